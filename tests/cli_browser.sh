# tests/cli_browser.sh: the page of amorph view in a real browser. Headless Chromium (Debian's
# chromium package) with a fresh profile and no network opens the page from file://, takes
# screenshots at two moments chosen by URL hash parameters, and the test checks that
#   (a) the robot is drawn: many pixels in shades of each of its materials' colours,
#   (b) it moved: those pixels differ between the two moments,
#   (c) the page reported no error: its DOM (--dump-dom) carries the "ok" marker the script sets
#       after drawing, and a page with damaged data carries the "error" marker instead;
# and that the page opens at the settled frame (the relaxation hidden) unless told otherwise, and
# its clock reads seconds from 1 s on.
# Without chromium (or with AM_NO_BROWSER=1) the test prints SKIPPED; CI installs it (.ci/run).
# Run from the repository root: sh tests/cli_browser.sh
. tests/shlib.sh
PNG=${PNG_TOOL:-$BUILD/tests/test_io_png}
if ! "$AMORPH" render --help >/dev/null 2>&1; then
    # the board profile builds no pictures: the commands must say so in one line
    expect_fail 2 "render: not in this build" "$AMORPH" render --scene cube:2 --out "$TMPD/x.png"
    echo "cli_browser.sh: SKIPPED (no pictures in this build)"
    summary "cli_browser.sh"
    exit $?
fi

CHROME=$(command -v chromium || command -v chromium-browser || true)
[ "${AM_NO_BROWSER:-0}" = 1 ] && CHROME=
if [ -z "$CHROME" ]; then
    echo "cli_browser.sh: SKIPPED (no chromium; apt-get install chromium)"
    summary "cli_browser.sh"
    exit 0
fi
TIMEOUT=$(command -v timeout || true)
[ -n "$TIMEOUT" ] && TIMEOUT="$TIMEOUT 90"

# chrome URL OUTFLAG...: one headless run with its own fresh profile, no network, no GPU
chrome() {
    url=$1; shift
    prof=$(mktemp -d "$TMPD/profile.XXXXXX")
    $TIMEOUT "$CHROME" --headless --no-sandbox --disable-gpu --user-data-dir="$prof" --no-first-run \
        --no-default-browser-check --disable-extensions --disable-sync --disable-background-networking \
        --disable-component-update --no-proxy-server --proxy-server="127.0.0.1:9" \
        --host-resolver-rules="MAP * ~NOTFOUND" --hide-scrollbars --force-device-scale-factor=1 \
        --window-size=900,600 --virtual-time-budget=5000 "$@" "$url" 2>"$TMPD/chrome.log"
}

# colours of tests/data/walker.lattice: passive, active, active90
COLS="285adc f0c81e dc2828"
expect_ok "$AMORPH" view tests/data/walker.lattice --cycles 2 --relax-max 400 --frames 60 --out "$TMPD/walker.html"
URL="file://$(cd "$TMPD" && pwd)/walker.html"

# two moments, paused: a quarter and three quarters of the way through the recording
for m in 1 2; do
    t=$([ $m = 1 ] && echo 0.25 || echo 0.75)
    chrome "$URL#t=$t&paused=1" --screenshot="$TMPD/shot$m.png" >/dev/null
    check "chromium took no screenshot at t=$t: $(tail -n 3 "$TMPD/chrome.log")" [ -s "$TMPD/shot$m.png" ]
    chrome "$URL#t=$t&paused=1" --dump-dom >"$TMPD/dom$m.html"
    check "page at t=$t did not report ok: $(grep -o '<title>[^<]*' "$TMPD/dom$m.html")" \
        grep -q '<title>amorph viewer: ok</title>' "$TMPD/dom$m.html"
    check "page at t=$t: no ok marker" grep -q 'id="status" data-status="ok"' "$TMPD/dom$m.html"
    # (a) the robot is drawn in its materials' colours
    info=$("$PNG" --png-info "$TMPD/shot$m.png" $COLS 2>&1)
    set -- $info
    if [ "$1" = 900 ] && [ "$2" = 600 ] && [ "${3:-0}" -ge 500 ] && [ "${4:-0}" -ge 500 ] && [ "${5:-0}" -ge 200 ]; then ok
    else ko "screenshot at t=$t: $info (want 900 x 600 and >= 500 pixels of each material)"; fi
done
# (b) it moved: the frames differ and so do the robot's pixels
f1=$(sed -n 's/.*data-frame="\([0-9]*\)".*/\1/p' "$TMPD/dom1.html")
f2=$(sed -n 's/.*data-frame="\([0-9]*\)".*/\1/p' "$TMPD/dom2.html")
if [ -n "$f1" ] && [ -n "$f2" ] && [ "$f1" -lt "$f2" ]; then ok; else ko "the two moments show frames '$f1' and '$f2'"; fi
diff=$("$PNG" --png-diff "$TMPD/shot1.png" "$TMPD/shot2.png" $COLS 2>&1)
check "robot pixels changed between t=0.25 and t=0.75: $diff (want >= 300)" [ "${diff:-0}" -ge 300 ] 2>/dev/null

# the relaxation is skipped by default: the page opens at the settled frame (the relaxation's
# last, where the movement starts); #relax=1 opens at frame 0, and a frame of the relaxation
# (#frame=1) shows the relaxation too
sf=$(sed -n 's/.*"settled_frame": \([0-9]*\).*/\1/p' "$TMPD/walker.html")
# dom HASH NAME: the page at URL#HASH, its DOM in $TMPD/dom-NAME.html; attr NAME KEY: a status
# attribute of it; clock NAME: its clock text
dom() { chrome "$URL#$1" --dump-dom >"$TMPD/dom-$2.html"; }
attr() { sed -n "s/.*id=\"status\"[^>]* $2=\"\([^\"]*\)\".*/\1/p" "$TMPD/dom-$1.html"; }
clock() { sed -n 's/.*<span id="clock">\([^<]*\)<.*/\1/p' "$TMPD/dom-$1.html"; }
dom "paused=1" start
check "settled frame '$sf' should be past frame 0" [ "${sf:-0}" -gt 0 ]
check "the page should open at the settled frame $sf, opened at '$(attr start data-frame)'" [ "$(attr start data-frame)" = "$sf" ]
check "the relaxation should be hidden by default: data-relax '$(attr start data-relax)'" [ "$(attr start data-relax)" = 0 ]
check "the clock at the start should read cycle 0.00: '$(clock start)'" sh -c "echo '$(clock start)' | grep -qE '^t = [0-9]+\.[0-9]{2} ms, cycle 0\.00$'"
dom "relax=1&paused=1" relax
if [ "$(attr relax data-frame)" = 0 ] && [ "$(attr relax data-relax)" = 1 ]; then ok
else ko "#relax=1 should open at frame 0: '$(attr relax data-frame)', relax '$(attr relax data-relax)'"; fi
check "the clock at frame 0 should read relaxing: '$(clock relax)'" [ "$(clock relax)" = "t = 0.00 ms, relaxing" ]
dom "frame=1&paused=1" frame1
if [ "$(attr frame1 data-frame)" = 1 ] && [ "$(attr frame1 data-relax)" = 1 ]; then ok
else ko "#frame=1 should show frame 1 with the relaxation: '$(attr frame1 data-frame)', relax '$(attr frame1 data-relax)'"; fi
# cycles count from the relaxation's last step: the last frame is the end of the 2 cycles
dom "t=1&paused=1" end
check "the clock at the end should read cycle 2.00: '$(clock end)'" sh -c "echo '$(clock end)' | grep -qE '^t = [0-9.]+ ms, cycle 2\.00$'"
# time in seconds from 1 s on: 50 cycles of 500 steps are over 1 s. The cycles count from the
# relaxation's last step (423), which the recording holds as the settled frame (the simulator
# hands the recorder the relaxation's last step whatever the spacing of the frames)
expect_ok "$AMORPH" view tests/data/walker.lattice --cycles 50 --relax-max 423 --frames 60 --out "$TMPD/long.html"
URL0=$URL; URL="file://$(cd "$TMPD" && pwd)/long.html"
dom "t=1&paused=1" long
st=$(sed -n 's/.*"steps": \[\([0-9,]*\)\].*/\1/p' "$TMPD/long.html" | tr ',' '\n')
lsf=$(sed -n 's/.*"settled_frame": \([0-9]*\).*/\1/p' "$TMPD/long.html")
sstep=$(echo "$st" | sed -n "$((lsf + 1))p"); last=$(echo "$st" | tail -n 1)
want=$(awk -v l="$last" 'BEGIN { printf "%.2f", (l - 423) / 500 }')
check "long page: the settled frame's step '$sstep' should be the relaxation's last, 423" [ "$sstep" = 423 ]
check "the clock past 1 s should read seconds and cycle $want (last step $last): '$(clock long)'" \
    sh -c "echo '$(clock long)' | grep -qE '^t = 1\.[0-9]{3} s, cycle $want\$'"
# no relaxation recorded: nothing to skip, the check box stays on
expect_ok "$AMORPH" view tests/data/walker.lattice --cycles 2 --relax-max 0 --frames 60 --out "$TMPD/norelax.html"
URL="file://$(cd "$TMPD" && pwd)/norelax.html"
dom "paused=1" norelax
if [ "$(attr norelax data-frame)" = 0 ] && [ "$(attr norelax data-relax)" = 1 ]; then ok
else ko "no relaxation: frame 0 and relax 1, got '$(attr norelax data-frame)' and '$(attr norelax data-relax)'"; fi
URL=$URL0

# (e) the continuous surface (on by default) against the boxes at one moment: no light background
# pixel enclosed by the robot's with the surface on, and the two pictures differ on the robot
chrome "$URL#t=0.5&paused=1&surface=0" --screenshot="$TMPD/boxes.png" >/dev/null
chrome "$URL#t=0.5&paused=1" --screenshot="$TMPD/surface.png" >/dev/null
if [ -s "$TMPD/boxes.png" ] && [ -s "$TMPD/surface.png" ]; then ok; else ko "chromium took no screenshots of surface and boxes"; fi
holes=$("$PNG" --png-holes "$TMPD/surface.png" $COLS 2>&1)
set -- $holes
if [ "$1" = 0 ] && [ "${2:-0}" -ge 20000 ]; then ok; else ko "surface: $1 background pixels inside the robot ($holes; want 0 of >= 20000 robot pixels)"; fi
diff=$("$PNG" --png-diff "$TMPD/surface.png" "$TMPD/boxes.png" $COLS 2>&1)
check "surface and boxes differ in $diff robot pixels (want >= 2000)" [ "${diff:-0}" -ge 2000 ] 2>/dev/null
chrome "$URL#t=0.5&paused=1&surface=0" --dump-dom >"$TMPD/dom4.html"
check "boxes page: no ok marker" grep -q 'id="status" data-status="ok"' "$TMPD/dom4.html"
check "boxes page: not marked data-surface=0" grep -q 'data-surface="0"' "$TMPD/dom4.html"
check "default page: not marked data-surface=1" grep -q 'data-surface="1"' "$TMPD/dom1.html"

# (f) the colourings, one screenshot each at t=0.5 (#colour=NAME): the page marks the mode and
# writes its legend (the materials, or the scale's ends with units); a scalar's body keeps none
# of the materials' shades (under a quarter of the material colouring's), its legend's gradient runs between the scale's end colours (440154 to
# fde725, 2166ac to b2182b for phase), and the modes differ on the robot
legend() { sed -n 's/.*<div id="legend">\(.*\)<\/div><\/div>.*/\1/p' "$TMPD/dom-$1.html" | sed 's/<[^>]*>/ /g'; }
for m in material strain stress speed phase; do
    chrome "$URL#t=0.5&paused=1&colour=$m" --screenshot="$TMPD/col-$m.png" >/dev/null
    dom "t=0.5&paused=1&colour=$m" col-$m
    check "#colour=$m: the page should be marked data-colour=$m: '$(attr col-$m data-colour)'" [ "$(attr col-$m data-colour)" = $m ]
    case $m in
    material) want="passive active active90" ;;
    strain) want="strain 0 [0-9.]+ %" ;;
    stress) want="stress 0 [0-9.]+ kPa" ;;
    speed) want="speed 0 [0-9.]+ mm/s" ;;
    phase) want="phase -[0-9.]+ [0-9.]+ %" ;;
    esac
    check "#colour=$m: the legend '$(legend col-$m)' should read '$want'" sh -c "echo '$(legend col-$m)' | tr -s ' ' | grep -qE '$want'"
    set -- $("$PNG" --png-info "$TMPD/col-$m.png" $COLS)
    # (the top of the sequential scale is a yellow near active's: a quarter of material's count)
    if [ $m = material ]; then
        matpx=$((${3:-0} + ${4:-0} + ${5:-0}))
        if [ "${3:-0}" -ge 5000 ] && [ "${4:-0}" -ge 5000 ]; then ok; else ko "#colour=material: material shades $*"; fi
    elif [ "${5:-x}" != x ] && [ $((4 * (${3:-0} + ${4:-0} + ${5:-0}))) -lt "$matpx" ]; then ok
    else ko "#colour=$m: $3 passive, $4 active, $5 active90 pixels left (want under a quarter of material's $matpx)"; fi
    ends=$("$PNG" --png-count "$TMPD/col-$m.png" 0 0 450 90 440154 fde725 2166ac b2182b)
    set -- $ends
    case $m in
    material) check "#colour=material: scale colours in the legend: $ends" [ "$*" = "0 0 0 0" ] ;;
    phase) check "#colour=phase: the legend should end in 2166ac and b2182b: $ends" [ $(((${3:-0} >= 20) * (${4:-0} >= 20))) = 1 ] ;;
    *) check "#colour=$m: the legend should end in 440154 and fde725: $ends" [ $(((${1:-0} >= 20) * (${2:-0} >= 20))) = 1 ] ;;
    esac
done
for pair in "material strain" "strain speed" "strain phase" "speed phase"; do
    set -- $pair
    n=$("$PNG" --png-changed "$TMPD/col-$1.png" "$TMPD/col-$2.png")
    check "#colour=$1 and $2 differ in $n pixels (want >= 3000)" [ "${n:-0}" -ge 3000 ]
done
# (g) the scale bar, bottom left (a 4 px high run of 1e1e1e from x = 16), its length in the DOM;
# the body fills the window (walker's 60 voxels: at least 60000 pixels of its materials)
bar=$(attr col-material data-scalebar)
check "the scale bar's length should be a round number of metres: '$bar'" sh -c "echo '$bar' | grep -qE '^(1|2|5)(e-?[0-9]+)?\$|^0\.0*[125]\$'"
n=$("$PNG" --png-count "$TMPD/col-material.png" 16 536 60 540 1e1e1e)
check "no scale bar at the bottom left ($n of 176 pixels)" [ "${n:-0}" -ge 170 ]
set -- $("$PNG" --png-info "$TMPD/col-material.png" $COLS)
check "the walker should fill the window: $(($3 + $4 + $5)) pixels of its materials (want >= 60000)" [ $((${3:-0} + ${4:-0} + ${5:-0})) -ge 60000 ]
# (h) the travel plot beside the robot (top right, its curve in be00be): the travel shown is 0 at
# the settled frame and the fitness's distance at the end
n=$("$PNG" --png-count "$TMPD/col-material.png" 620 8 890 158 be00be)
check "no travel curve at the top right ($n pixels of be00be)" [ "${n:-0}" -ge 100 ]
tv0=$(attr start data-travel); tv1=$(attr end data-travel)
check "the travel at the settled frame should be 0: '$tv0'" [ "$tv0" = 0 ]
check "the travel at the end should be over 1 mm: '$tv1'" awk -v t="$tv1" 'BEGIN { exit !(t > 0.001) }'
# (i) clamps and forces: the VXA cantilever's clamped voxel in the clamp's grey (46464e shades),
# its tip's force as an arrow (009696), both in the legend
expect_ok "$AMORPH" view tests/data/voxcad_cantilever.vxa --cycles 1 --frames 30 --out "$TMPD/cant.html"
URLC="file://$(cd "$TMPD" && pwd)/cant.html"
chrome "$URLC#paused=1&colour=stress" --screenshot="$TMPD/cant.png" >/dev/null
chrome "$URLC#paused=1&colour=stress" --dump-dom >"$TMPD/dom-cant.html"
set -- $("$PNG" --png-count "$TMPD/cant.png" 0 90 900 540 009696)
check "cantilever: the force arrow should be drawn (009696: $1 pixels)" [ "${1:-0}" -ge 200 ]
sed 's|<DofFixed>63</DofFixed>|<DofFixed>0</DofFixed>|' tests/data/voxcad_cantilever.vxa >"$TMPD/unclamped.vxa"
expect_ok "$AMORPH" view "$TMPD/unclamped.vxa" --cycles 1 --frames 30 --out "$TMPD/unclamped.html"
chrome "file://$(cd "$TMPD" && pwd)/unclamped.html#paused=1&colour=stress" --screenshot="$TMPD/unclamped.png" >/dev/null
set -- $("$PNG" --png-info "$TMPD/cant.png" 46464e) $("$PNG" --png-info "$TMPD/unclamped.png" 46464e)
check "cantilever: the clamp should be drawn (shades of 46464e: $3 pixels, $6 without the clamp)" [ $(((${3:-0} >= 2000) * (4 * ${6:-0} < ${3:-0}))) = 1 ]
check "cantilever: the legend '$(legend cant)' should name the clamp and the force" sh -c "echo '$(legend cant)' | grep -q 'clamped.*force'"

# (c) the error marker works: damaged pose data is reported, not silently drawn
sed 's/"pose": "/"pose": "!!/' "$TMPD/walker.html" >"$TMPD/broken.html"
chrome "file://$(cd "$TMPD" && pwd)/broken.html#paused=1" --dump-dom >"$TMPD/dom3.html"
check "damaged page did not report an error: $(grep -o '<title>[^<]*' "$TMPD/dom3.html")" \
    grep -q '<title>amorph viewer: error' "$TMPD/dom3.html"
check "damaged page: no error marker" grep -q 'data-status="error"' "$TMPD/dom3.html"

[ -n "$KEEP" ] && cp "$TMPD"/shot*.png "$TMPD"/surface.png "$TMPD"/boxes.png "$TMPD"/col-*.png "$TMPD"/cant.png "$KEEP"
summary "cli_browser.sh"
