# tests/cli_browser.sh: the page of amorph view in a real browser. Headless Chromium (Debian's
# chromium package) with a fresh profile and no network opens the page from file://, takes
# screenshots at two moments chosen by URL hash parameters, and the test checks that
#   (a) the robot is drawn: many pixels in shades of each of its materials' colours,
#   (b) it moved: those pixels differ between the two moments,
#   (c) the page reported no error: its DOM (--dump-dom) carries the "ok" marker the script sets
#       after drawing, and a page with damaged data carries the "error" marker instead.
# Without chromium (or with AM_NO_BROWSER=1) the test prints SKIPPED; CI installs it (.ci/run).
# Run from the repository root: sh tests/cli_browser.sh
. tests/shlib.sh
PNG=${PNG_TOOL:-$BUILD/tests/test_image}
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
    check "screenshot at t=$t: $info (want 900 x 600 and >= 500 pixels of each material)" \
        [ "$1" = 900 ] && [ "$2" = 600 ] && [ "${3:-0}" -ge 500 ] && [ "${4:-0}" -ge 500 ] && [ "${5:-0}" -ge 200 ]
done
# (b) it moved: the frames differ and so do the robot's pixels
f1=$(sed -n 's/.*data-frame="\([0-9]*\)".*/\1/p' "$TMPD/dom1.html")
f2=$(sed -n 's/.*data-frame="\([0-9]*\)".*/\1/p' "$TMPD/dom2.html")
check "the two moments show frames '$f1' and '$f2'" [ -n "$f1" ] && [ -n "$f2" ] && [ "$f1" -lt "$f2" ]
diff=$("$PNG" --png-diff "$TMPD/shot1.png" "$TMPD/shot2.png" $COLS 2>&1)
check "robot pixels changed between t=0.25 and t=0.75: $diff (want >= 300)" [ "${diff:-0}" -ge 300 ] 2>/dev/null

# (d) the continuous surface (on by default) against the boxes at one moment: no light background
# pixel enclosed by the robot's with the surface on, and the two pictures differ on the robot
chrome "$URL#t=0.5&paused=1&surface=0" --screenshot="$TMPD/boxes.png" >/dev/null
chrome "$URL#t=0.5&paused=1" --screenshot="$TMPD/surface.png" >/dev/null
check "chromium took no screenshots of surface and boxes" [ -s "$TMPD/boxes.png" ] && [ -s "$TMPD/surface.png" ]
holes=$("$PNG" --png-holes "$TMPD/surface.png" $COLS 2>&1)
set -- $holes
check "surface: $1 background pixels inside the robot ($holes; want 0 of >= 20000 robot pixels)" [ "$1" = 0 ] && [ "${2:-0}" -ge 20000 ]
diff=$("$PNG" --png-diff "$TMPD/surface.png" "$TMPD/boxes.png" $COLS 2>&1)
check "surface and boxes differ in $diff robot pixels (want >= 2000)" [ "${diff:-0}" -ge 2000 ] 2>/dev/null
chrome "$URL#t=0.5&paused=1&surface=0" --dump-dom >"$TMPD/dom4.html"
check "boxes page: no ok marker" grep -q 'id="status" data-status="ok"' "$TMPD/dom4.html"
check "boxes page: not marked data-surface=0" grep -q 'data-surface="0"' "$TMPD/dom4.html"
check "default page: not marked data-surface=1" grep -q 'data-surface="1"' "$TMPD/dom1.html"

# (c) the error marker works: damaged pose data is reported, not silently drawn
sed 's/"pose": "/"pose": "!!/' "$TMPD/walker.html" >"$TMPD/broken.html"
chrome "file://$(cd "$TMPD" && pwd)/broken.html#paused=1" --dump-dom >"$TMPD/dom3.html"
check "damaged page did not report an error: $(grep -o '<title>[^<]*' "$TMPD/dom3.html")" \
    grep -q '<title>amorph viewer: error' "$TMPD/dom3.html"
check "damaged page: no error marker" grep -q 'data-status="error"' "$TMPD/dom3.html"

[ -n "$KEEP" ] && cp "$TMPD"/shot*.png "$TMPD"/surface.png "$TMPD"/boxes.png "$KEEP"
summary "cli_browser.sh"
