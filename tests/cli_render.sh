# tests/cli_render.sh: amorph render, plot and view write valid files (PNGs decoded by the test
# program's own inflate, checked for size and the materials' colours; SVG and HTML checked for
# their parts), and bad input gives one line, a non-zero exit and no damaged output.
# Run from the repository root: sh tests/cli_render.sh
. tests/shlib.sh
PNG=${PNG_TOOL:-$BUILD/tests/test_io_png}
if ! "$AMORPH" render --help >/dev/null 2>&1; then
    # the board profile builds no pictures: the commands must say so in one line
    expect_fail 2 "render: not in this build" "$AMORPH" render --scene cube:2 --out "$TMPD/x.png"
    echo "cli_render.sh: SKIPPED (no pictures in this build)"
    summary "cli_render.sh"
    exit $?
fi
# colours of tests/data/walker.lattice: passive, active, active90
PASSIVE=285adc ACTIVE=f0c81e ACTIVE90=dc2828
W=tests/data/walker.lattice
QUICK="--cycles 2 --relax-max 400"

# render: a filmstrip of the default size with the three materials' shades in it
expect_ok "$AMORPH" render "$W" $QUICK --out "$TMPD/w.png"
info=$("$PNG" --png-info "$TMPD/w.png" $PASSIVE $ACTIVE $ACTIVE90 2>&1)
check "render: not a valid PNG: $info" [ $? -eq 0 ]
set -- $info
if [ "$1" = 1600 ] && [ "$2" = 400 ]; then ok; else ko "render: size $1 x $2, want 1600 x 400"; fi
if [ "${3:-0}" -gt 2000 ] && [ "${4:-0}" -gt 2000 ] && [ "${5:-0}" -gt 1000 ]; then ok; else ko "render: too few passive/active/active90 pixels: $info"; fi

# and by a decoder not ours (python3's zlib, when there is python3): every chunk's CRC, the zlib
# stream inflated whole to 400 rows of filter byte 0 and 1600 x 3 samples, the first block a
# dynamic Huffman one, and as many passive-blue pixels (each channel within 2) as the test program
# counts with the library's inflater
if command -v python3 >/dev/null 2>&1; then
    py=$(python3 - "$TMPD/w.png" <<'PY' 2>&1
import struct, sys, zlib
d = open(sys.argv[1], "rb").read()
assert d[:8] == b"\x89PNG\r\n\x1a\n", "signature"
i, idat = 8, b""
while i < len(d):
    n, t = struct.unpack(">I", d[i:i + 4])[0], d[i + 4:i + 8]
    assert zlib.crc32(d[i + 4:i + 8 + n]) == struct.unpack(">I", d[i + 8 + n:i + 12 + n])[0], "CRC of " + t.decode()
    if t == b"IDAT":
        idat += d[i + 8:i + 8 + n]
    i += 12 + n
raw = zlib.decompress(idat)
assert len(raw) == 400 * 4801, "inflated to %d bytes" % len(raw)
assert all(raw[k * 4801] == 0 for k in range(400)), "a filter byte not 0"
blue = 0
for k in range(400):
    row = raw[k * 4801 + 1:(k + 1) * 4801]
    for x in range(0, 4800, 3):
        blue += abs(row[x] - 0x28) <= 2 and abs(row[x + 1] - 0x5a) <= 2 and abs(row[x + 2] - 0xdc) <= 2
print((idat[2] >> 1) & 3, blue)
PY
)
    set -- $py
    ours=$("$PNG" --png-count "$TMPD/w.png" 0 0 1600 400 $PASSIVE)
    check "render: python3's zlib: '$py' (want block type 2 and $ours passive pixels)" [ "${1:-}.${2:-}" = "2.$ours" ]
fi
# --keep-same: a file that already holds the same picture stays (the same inode: the atomic write
# would have replaced it), whatever its compression; another picture, a damaged file or no file is
# written. Without it the file is always written again.
inode() { ls -i "$1" | awk '{ print $1 }'; }
cp "$TMPD/w.png" "$TMPD/k.png"
i0=$(inode "$TMPD/k.png")
expect_ok "$AMORPH" render "$W" $QUICK --keep-same --out "$TMPD/k.png"
check "--keep-same: the same picture should leave the file" [ "$(inode "$TMPD/k.png")" = "$i0" ]
expect_ok "$AMORPH" render "$W" $QUICK --out "$TMPD/k.png"
check "without --keep-same the file is written again" [ "$(inode "$TMPD/k.png")" != "$i0" ]
i0=$(inode "$TMPD/k.png")
expect_ok "$AMORPH" render "$W" $QUICK --frames 5 --keep-same --out "$TMPD/k.png"
check "--keep-same: another picture (5 frames) is written" sh -c "[ '$(inode "$TMPD/k.png")' != '$i0' ] && ! cmp -s '$TMPD/k.png' '$TMPD/w.png'"
# a damaged copy of the same picture (one byte of its image data changed: its CRC no longer holds)
cp "$TMPD/w.png" "$TMPD/k.png"
printf 'X' | dd of="$TMPD/k.png" bs=1 seek=200 conv=notrunc 2>/dev/null
expect_ok "$AMORPH" render "$W" $QUICK --keep-same --out "$TMPD/k.png"
check "--keep-same: a damaged file is written again" cmp -s "$TMPD/k.png" "$TMPD/w.png"
rm -f "$TMPD/k.png"
expect_ok "$AMORPH" render "$W" $QUICK --keep-same --out "$TMPD/k.png"
check "--keep-same: no file, written" cmp -s "$TMPD/k.png" "$TMPD/w.png"
# the same pixels in another compression (python3's zlib at level 1, one fixed or dynamic block of
# its own choosing): kept byte for byte
if command -v python3 >/dev/null 2>&1; then
    python3 - "$TMPD/w.png" "$TMPD/z.png" <<'PY'
import struct, sys, zlib
d = open(sys.argv[1], "rb").read()
i, idat, head = 8, b"", b""
while i < len(d):
    n, t = struct.unpack(">I", d[i:i + 4])[0], d[i + 4:i + 8]
    if t == b"IDAT":
        idat += d[i + 8:i + 8 + n]
    elif t == b"IHDR":
        head = d[i:i + 12 + n]
    i += 12 + n
z = zlib.compress(zlib.decompress(idat), 1)
chunk = struct.pack(">I", len(z)) + b"IDAT" + z + struct.pack(">I", zlib.crc32(b"IDAT" + z))
end = struct.pack(">I", 0) + b"IEND" + struct.pack(">I", zlib.crc32(b"IEND"))
open(sys.argv[2], "wb").write(d[:8] + head + chunk + end)
PY
    cp "$TMPD/z.png" "$TMPD/z0.png"
    expect_ok "$AMORPH" render "$W" $QUICK --keep-same --out "$TMPD/z.png"
    check "--keep-same: the same pixels compressed by zlib are kept" sh -c "cmp -s '$TMPD/z.png' '$TMPD/z0.png' && ! cmp -s '$TMPD/z.png' '$TMPD/w.png'"
fi
# the continuous surface (the default) against --boxes: no light background pixel enclosed by the
# robot's (the surface has no gap), and the two pictures differ on the robot
expect_ok "$AMORPH" render "$W" $QUICK --boxes --out "$TMPD/wb.png"
holes=$("$PNG" --png-holes "$TMPD/w.png" $PASSIVE $ACTIVE $ACTIVE90 2>&1)
set -- $holes
if [ "$1" = 0 ] && [ "${2:-0}" -gt 50000 ]; then ok; else ko "render: $1 background pixels inside the surface ($holes)"; fi
diff=$("$PNG" --png-diff "$TMPD/w.png" "$TMPD/wb.png" $PASSIVE $ACTIVE $ACTIVE90 2>&1)
check "render: surface and --boxes differ in $diff robot pixels (want >= 5000)" [ "${diff:-0}" -ge 5000 ] 2>/dev/null

# --colour: each scalar mode draws the body on its scale (none of the materials' shades left) with a
# legend from the scale's two ends (exact colours: 440154 to fde725, or 2166ac to b2182b for phase),
# and the modes differ from one another; material mode has no scale
for m in strain stress speed phase; do
    expect_ok "$AMORPH" render "$W" $QUICK --colour $m --width 1200 --out "$TMPD/c-$m.png"
done
expect_ok "$AMORPH" render "$W" $QUICK --width 1200 --out "$TMPD/c-material.png"
for m in material strain stress speed phase; do
    set -- $("$PNG" --png-count "$TMPD/c-$m.png" 0 360 1200 400 440154 fde725 2166ac b2182b)
    case $m in
    material) want="0 0 0 0" ;;
    phase) want="0 0 14 14" ;;
    *) want="14 14 0 0" ;;
    esac
    check "render --colour $m: the legend's ends should be '$want' pixels of 440154 fde725 2166ac b2182b: '$*'" [ "$*" = "$want" ]
    set -- $("$PNG" --png-info "$TMPD/c-$m.png" $PASSIVE $ACTIVE $ACTIVE90)
    if [ $m = material ]; then
        if [ "${3:-0}" -gt 2000 ] && [ "${4:-0}" -gt 2000 ]; then ok; else ko "render: material shades $*"; fi
    elif [ "${5:-x}" != x ] && [ $((${3:-0} + ${4:-0} + ${5:-0})) -lt 1000 ]; then ok
    else ko "render --colour $m: $3 passive, $4 active, $5 active90 shades left (want under 1000 in all)"; fi
done
for pair in "material strain" "strain speed" "strain phase" "speed phase"; do
    set -- $pair
    n=$("$PNG" --png-changed "$TMPD/c-$1.png" "$TMPD/c-$2.png")
    check "render --colour $1 and $2 differ in $n pixels (want >= 5000)" [ "${n:-0}" -ge 5000 ]
done
# strain and stress: one scale for one modulus (walker's materials all have E = 1 MPa), but the
# legend's units differ
n=$("$PNG" --png-changed "$TMPD/c-strain.png" "$TMPD/c-stress.png")
check "render --colour strain and stress: their legends should differ ($n pixels)" [ "${n:-0}" -gt 50 ]
expect_fail 2 "render: --colour needs material, strain, stress, speed or phase" "$AMORPH" render "$W" --colour heat --out "$TMPD/x.png"
# the labels fit their panels of 200 px (text pixels end before the panel's last 10 px: the
# settled label, too long for the big font, is drawn small with its unit); the scale bar (a 24 x 4
# px run of the text's colour at the caption's right end)
for k in 0 1 2 3 4 5; do
    n=$("$PNG" --png-count "$TMPD/c-material.png" $((k * 200 + 190)) 0 $((k * 200 + 196)) 26 1e1e1e)
    check "render: the label of picture $((k + 1)) runs into its panel's edge ($n pixels)" [ "$n" = 0 ]
done
n=$("$PNG" --png-count "$TMPD/c-material.png" 1160 376 1184 380 1e1e1e)
check "render: no scale bar at the caption's right end ($n of 96 pixels)" [ "$n" = 96 ]
# clamps and forces: the VXA cantilever's clamped voxel in the clamp's grey (shades of 46464e) and
# its tip's force as an arrow (009696); the walker has neither
expect_ok "$AMORPH" render tests/data/voxcad_cantilever.vxa --cycles 1 --colour strain --out "$TMPD/cant.png"
set -- $("$PNG" --png-count "$TMPD/cant.png" 0 0 1600 400 009696)
check "render: the cantilever's force arrow should be drawn (009696: $1 pixels)" [ "${1:-0}" -gt 300 ]
set -- $("$PNG" --png-info "$TMPD/cant.png" 46464e)
check "render: the cantilever's clamp should be drawn (shades of 46464e: $3 pixels)" [ "${3:-0}" -gt 1000 ]
set -- $("$PNG" --png-count "$TMPD/c-material.png" 0 0 1200 400 009696)
check "render: a force arrow on a robot without forces ($1 pixels)" [ "$1" = 0 ]

# options: size and frames; a scene
expect_ok "$AMORPH" render --scene sphere:6 --cycles 1 --relax-max 300 --frames 4 --width 800 --height 260 --out "$TMPD/s.png"
info=$("$PNG" --png-info "$TMPD/s.png" $PASSIVE $ACTIVE 2>&1)
set -- $info
if [ "$1" = 800 ] && [ "$2" = 260 ] && [ "${3:-0}" -gt 500 ] && [ "${4:-0}" -gt 500 ]; then ok; else ko "render --width 800 --height 260: got $info"; fi

# a run folder stands for its best robot (a small run of amorph evolve)
cat >"$TMPD/small.cfg" <<'CFG'
workspace = 6
population = 4
evaluations = 8
cycles = 1
period_steps = 100
relax_max_steps = 300
relax_min_steps = 50
release_steps = 100
seed = 3
CFG
expect_ok "$AMORPH" evolve --config "$TMPD/small.cfg" --quiet --no-pictures --out "$TMPD/run"
expect_ok "$AMORPH" render "$TMPD/run" --out "$TMPD/run.png"
check "render RUN: not a valid PNG: $("$PNG" --png-info "$TMPD/run.png" 2>&1)" "$PNG" --png-info "$TMPD/run.png" >/dev/null
expect_ok "$AMORPH" view "$TMPD/run" --out "$TMPD/run.html"
check "view RUN: no data in the page" grep -q '"format": "amorph-view 1"' "$TMPD/run.html"

# a VXA file in its own environment (warnings about VoxCAD tags go to stderr)
expect_ok "$AMORPH" render tests/data/voxcad_quadruped.vxa --cycles 1 --frames 3 --width 600 --height 200 --out "$TMPD/vxa.png"
info=$("$PNG" --png-info "$TMPD/vxa.png" 2>&1)
check "render VXA: $info" [ "$info" = "600 200" ]

# view: one self-contained page (no URL to load anything from), the data and the renderer
expect_ok "$AMORPH" view "$W" $QUICK --frames 50 --title "walker <test>" --out "$TMPD/w.html"
check "view: no doctype" grep -q '^<!DOCTYPE html>' "$TMPD/w.html"
check "view: no data block" grep -q '<script type="application/json" id="amorph-data">' "$TMPD/w.html"
check "view: the title is not escaped" grep -q '"title": "walker \\u003ctest\\u003e"' "$TMPD/w.html"
check "view: loads something from outside" sh -c "! grep -qiE '(src|href)=|https?://|@import|fetch\\(' '$TMPD/w.html'"
check "view: not 50 frames" grep -q '"frames": 50,' "$TMPD/w.html"
check "view: no closing tag" grep -q '</html>' "$TMPD/w.html"

# plot: a single run and an experiment folder (a band per variant)
expect_ok "$AMORPH" plot tests/data/plot-run --out "$TMPD/one.svg"
check "plot: not an SVG" grep -q '<svg xmlns="http://www.w3.org/2000/svg"' "$TMPD/one.svg"
if [ "$(grep -c 'class="run"' "$TMPD/one.svg")" -eq 1 ] && [ "$(grep -c 'class="band"' "$TMPD/one.svg")" -eq 0 ]; then ok; else ko "plot: one run should be one line and no band"; fi
check "plot: axis labels" grep -q '>evaluations</text>' "$TMPD/one.svg"
expect_ok "$AMORPH" plot tests/data/plot-exp "$TMPD/run" --out "$TMPD/exp.svg" --title "representations"
if [ "$(grep -c 'class="band"' "$TMPD/exp.svg")" -eq 2 ] && [ "$(grep -c 'class="mean"' "$TMPD/exp.svg")" -eq 2 ]; then ok; else ko "plot: two variants should give two bands and two mean lines"; fi
check "plot: 6 experiment runs and 1 run" [ "$(grep -c 'class="run"' "$TMPD/exp.svg")" -eq 7 ]
check "plot: legend" grep -q '>dct, 3 runs<' "$TMPD/exp.svg"
check "plot: legend" grep -q '>gmx, 3 runs<' "$TMPD/exp.svg"
check "plot: title" grep -q '>representations</text>' "$TMPD/exp.svg"
if [ "$(grep -c '<svg' "$TMPD/exp.svg")" -eq 1 ] && tail -n 1 "$TMPD/exp.svg" | grep -q '^</svg>$'; then ok; else ko "plot: unbalanced tags"; fi
# steps per generation: the best so far holds its value until the next logged generation, so a
# curve is "Mx,y" then one "Hx Vy" (across, then up or down) per further row, x rising
# dpath FILE CLASS N: the d of the N-th path of that class
dpath() { grep "class=\"$2\"" "$1" | sed -n "$3{s/.* d=\"\([^\"]*\)\".*/\1/p;}"; }
# steps D ROWS: D is a step curve through ROWS points, its x rising
steps() { echo "$1" | awk -v n="$2" '{ if ($1 !~ /^M[0-9.]+,[0-9.]+$/ || NF != 2 * n - 1) exit 1; split(substr($1, 2), a, ","); x = a[1]
    for (i = 2; i < NF; i += 2) { if ($i !~ /^H[0-9.]+$/ || $(i + 1) !~ /^V[0-9.]+$/ || substr($i, 2) + 0 <= x + 0) exit 1; x = substr($i, 2) } }'; }
pth=$(dpath "$TMPD/one.svg" run 1)
check "plot: a run should be steps through its 8 rows: '$pth'" steps "$pth" 8
check "plot: an experiment's mean should be steps through its 10 rows: '$(dpath "$TMPD/exp.svg" mean 1)'" steps "$(dpath "$TMPD/exp.svg" mean 1)" 10
check "plot: an experiment's run should be steps through its 10 rows: '$(dpath "$TMPD/exp.svg" run 1)'" steps "$(dpath "$TMPD/exp.svg" run 1)" 10
# the band: the upper edge as steps, then back along the lower edge ("Vy Hx" pairs), closed
check "plot: the band should be steps out and back: '$(dpath "$TMPD/exp.svg" band 1)'" \
    sh -c "echo '$(dpath "$TMPD/exp.svg" band 1)' | grep -qE '^M[0-9.]+,[0-9.]+( H[0-9.]+ V[0-9.]+){9} L[0-9.]+,[0-9.]+( V[0-9.]+ H[0-9.]+){9} Z$'"
# one x axis: a run folder and an experiment folder are labelled alike
expect_ok "$AMORPH" plot tests/data/plot-exp --out "$TMPD/exp-only.svg"
for l in xlabel ylabel; do
    a=$(sed -n "s/.*class=\"$l\"[^>]*>\([^<]*\)<.*/\1/p" "$TMPD/one.svg"); b=$(sed -n "s/.*class=\"$l\"[^>]*>\([^<]*\)<.*/\1/p" "$TMPD/exp-only.svg")
    if [ -n "$a" ] && [ "$a" = "$b" ]; then ok; else ko "plot: the $l of a run ('$a') and of an experiment ('$b') should be equal"; fi
done
check "plot: the x axis should be evaluations" grep -q 'class="xlabel"[^>]*>evaluations<' "$TMPD/exp-only.svg"
# a folder of run folders without experiment.txt (results/run.sh's layout) plots as the experiment
mkdir -p "$TMPD/runsonly"
cp -R tests/data/plot-exp/dct-1 tests/data/plot-exp/dct-2 tests/data/plot-exp/dct-3 tests/data/plot-exp/gmx-1 \
    tests/data/plot-exp/gmx-2 tests/data/plot-exp/gmx-3 "$TMPD/runsonly/"
expect_ok "$AMORPH" plot "$TMPD/runsonly" --out "$TMPD/runsonly.svg"
check "plot: a folder of run folders should draw what its experiment folder draws" cmp -s "$TMPD/exp-only.svg" "$TMPD/runsonly.svg"
# DIR/VARIANT: one variant's runs of a folder of runs, drawn as a folder holding only them draws it
mkdir -p "$TMPD/gmxonly"
cp -R tests/data/plot-exp/gmx-1 tests/data/plot-exp/gmx-2 tests/data/plot-exp/gmx-3 "$TMPD/gmxonly/"
expect_ok "$AMORPH" plot "$TMPD/gmxonly" --out "$TMPD/gmxonly.svg"
expect_ok "$AMORPH" plot tests/data/plot-exp/gmx/ --out "$TMPD/gmxvariant.svg"
check "plot DIR/VARIANT: should draw what a folder of that variant's runs draws" cmp -s "$TMPD/gmxonly.svg" "$TMPD/gmxvariant.svg"
if [ "$(grep -c 'class="band"' "$TMPD/gmxvariant.svg")" -eq 1 ] && [ "$(grep -c 'class="run"' "$TMPD/gmxvariant.svg")" -eq 3 ]; then ok; else ko "plot DIR/VARIANT: one band, three runs"; fi
expect_ok "$AMORPH" plot tests/data/plot-exp/gmx tests/data/plot-exp/dct-1 --out "$TMPD/gmxdct.svg"
if grep -q '>dct-1<' "$TMPD/gmxdct.svg" && grep -q '>gmx, 3 runs<' "$TMPD/gmxdct.svg"; then ok; else ko "plot DIR/VARIANT beside a run: two lines"; fi
expect_fail 2 "tests/data/plot-exp/cppn: no such folder, nor runs cppn-<k> in tests/data/plot-exp" "$AMORPH" plot tests/data/plot-exp/cppn --out "$TMPD/x.svg"
expect_fail 2 "$TMPD/none/gmx: no such folder" "$AMORPH" plot "$TMPD/none/gmx" --out "$TMPD/x.svg"
check "plot: a refused plot should write no file" [ ! -e "$TMPD/x.svg" ]
# --min-evals: a run short of N is left out of its variant's mean (a third run of 20 evaluations
# would otherwise end the mean at 20)
mkdir -p "$TMPD/short/a-1" "$TMPD/short/a-2" "$TMPD/short/a-3"
printf 'generation,evaluations,best\n0,20,0.001\n1,40,0.002\n2,60,0.004\n' >"$TMPD/short/a-1/log.csv"
printf 'generation,evaluations,best\n0,20,0.003\n1,40,0.003\n2,60,0.005\n' >"$TMPD/short/a-2/log.csv"
printf 'generation,evaluations,best\n0,20,0.009\n' >"$TMPD/short/a-3/log.csv"
expect_ok "$AMORPH" plot "$TMPD/short" --out "$TMPD/short-all.svg"
expect_ok "$AMORPH" plot "$TMPD/short" --min-evals 60 --out "$TMPD/short-60.svg"
check "plot --min-evals: the legend should count 2 runs" grep -q 'a, 2 runs' "$TMPD/short-60.svg"
check "plot without --min-evals: the legend should count 3 runs" grep -q 'a, 3 runs' "$TMPD/short-all.svg"
check "plot --min-evals: the mean should step 3 times (20, 40, 60): '$(dpath "$TMPD/short-60.svg" mean 1)'" steps "$(dpath "$TMPD/short-60.svg" mean 1)" 3
expect_fail 2 "no run has logged 100 evaluations" "$AMORPH" plot "$TMPD/short" --min-evals 100 --out "$TMPD/x.svg"
expect_fail 2 "--min-evals needs a whole number" "$AMORPH" plot "$TMPD/short" --min-evals -1 --out "$TMPD/x.svg"
# eleven variants with long names (the actuation experiment's): the first ten in ten colours, the
# eleventh in the first colour dashed; the legend's column as wide as its longest entry needs
mkdir -p "$TMPD/many"
for v in 01 02 03 04 05 06 07 08 09 10 11; do
    mkdir -p "$TMPD/many/variant-with-a-long-name-$v-1"
    printf 'generation,evaluations,best\n0,20,0.00%s\n' "${v#0}" >"$TMPD/many/variant-with-a-long-name-$v-1/log.csv"
done
expect_ok "$AMORPH" plot "$TMPD/many" --out "$TMPD/many.svg"
cols=$(grep -o 'class="mean" fill="none" stroke="#[0-9a-f]*"' "$TMPD/many.svg" | head -n 10 | sort -u | wc -l)
check "plot: ten variants should have ten colours, not $cols" [ "$cols" -eq 10 ]
check "plot: the eleventh variant's mean and legend should be dashed in the first colour" sh -c \
    "grep 'class=\"mean\"' '$TMPD/many.svg' | sed -n 11p | grep -q 'stroke=\"#1f77b4\" stroke-dasharray' &&
     grep 'class=\"legend\"' '$TMPD/many.svg' | sed -n 11p | grep -q 'stroke-dasharray'"
check "plot: none of the first ten dashed" sh -c "! grep 'class=\"mean\"' '$TMPD/many.svg' | head -n 10 | grep -q dasharray"
# the legend's text starts at x and takes about 7.5 px a character: the picture must be wider
lx=$(grep -o '<text x="[0-9]*" y="[0-9]*">variant-with-a-long-name-01' "$TMPD/many.svg" | sed 's/<text x="\([0-9]*\)".*/\1/')
w=$(sed -n 's/.*<svg [^>]*width="\([0-9]*\)".*/\1/p' "$TMPD/many.svg")
lx_label="variant-with-a-long-name-01, 1 run"
check "plot: the legend ('$lx_label' at x=$lx) should fit in the width $w" [ "$((${lx:-99999} + 75 * ${#lx_label} / 10))" -le "${w:-0}" ]
# --max-evals: rows beyond N are not drawn; it draws what logs cut at N draw
expect_ok "$AMORPH" plot "$TMPD/short" --max-evals 40 --out "$TMPD/short-max40.svg"
mkdir -p "$TMPD/cut/a-1" "$TMPD/cut/a-2" "$TMPD/cut/a-3"
for k in 1 2 3; do head -n 3 "$TMPD/short/a-$k/log.csv" >"$TMPD/cut/a-$k/log.csv"; done
expect_ok "$AMORPH" plot "$TMPD/cut" --out "$TMPD/cut.svg"
check "plot --max-evals 40: should draw what logs ending at 40 draw" cmp -s "$TMPD/short-max40.svg" "$TMPD/cut.svg"
expect_ok "$AMORPH" plot "$TMPD/short" --min-evals 40 --max-evals 40 --out "$TMPD/short-40.svg"
check "plot --min-evals 40 --max-evals 40: 2 runs, the mean stepping twice (20, 40): '$(dpath "$TMPD/short-40.svg" mean 1)'" \
    sh -c "grep -q 'a, 2 runs' '$TMPD/short-40.svg' && echo '$(dpath "$TMPD/short-40.svg" mean 1)' | grep -qE '^M[0-9.]+,[0-9.]+ H[0-9.]+ V[0-9.]+$'"
expect_fail 2 "a-1/log.csv: no generation logged within 10 evaluations" "$AMORPH" plot "$TMPD/short" --max-evals 10 --out "$TMPD/x.svg"
expect_fail 2 "no run has logged 60 evaluations" "$AMORPH" plot "$TMPD/short" --min-evals 60 --max-evals 40 --out "$TMPD/x.svg"
expect_fail 2 "--max-evals needs a whole number" "$AMORPH" plot "$TMPD/short" --max-evals 0 --out "$TMPD/x.svg"
# runs logging at different evaluations (populations of 20 and 30): the mean steps wherever one
# of them does, from 30 (both have a value) to 60 (both still logged): at 30, 40 and 60
mkdir -p "$TMPD/mixed/a-1" "$TMPD/mixed/a-2"
echo "experiment = mixed" >"$TMPD/mixed/experiment.txt"
printf 'generation,evaluations,best\n0,20,0.001\n1,40,0.002\n2,60,0.003\n3,80,0.004\n' >"$TMPD/mixed/a-1/log.csv"
printf 'generation,evaluations,best\n0,30,0.002\n1,60,0.004\n' >"$TMPD/mixed/a-2/log.csv"
expect_ok "$AMORPH" plot "$TMPD/mixed" --out "$TMPD/mixed.svg"
pth=$(dpath "$TMPD/mixed.svg" mean 1)
check "plot: the mean of runs with different populations should step at 30, 40 and 60: '$pth'" steps "$pth" 3
xs=$(echo "$pth" | tr ' ' '\n' | sed -n 's/^M\([0-9.]*\),.*/\1/p; s/^H//p' | tr '\n' ' ')
# the x axis runs from 0 to 100 (80, the last row, plus a tick of room) over the 592 px from
# x = 78: 30, 40, 60 are at 255.6, 314.8, 433.2
check "plot: the mean's steps should be at evaluations 30, 40, 60 (px 255.6, 314.8, 433.2): '$xs' in '$pth'" [ "$xs" = "255.60 314.80 433.20 " ]
check "plot: the x axis should start at 0 evaluations" grep -q '<text x="78.00" y="[0-9]*" text-anchor="middle">0</text>' "$TMPD/mixed.svg"
# room past the data: a run of two generations whose best ends on a round number (2 mm at 20
# evaluations) keeps its last step and its highest value off the frame (x = 78..670, y = 46..462):
# no curve point on the right or the top border
mkdir -p "$TMPD/two/r-1"
printf 'generation,evaluations,best\n0,10,0.001\n1,20,0.002\n' >"$TMPD/two/r-1/log.csv"
for d in "$TMPD/two/r-1" "$TMPD/two"; do
    expect_ok "$AMORPH" plot "$d" --out "$TMPD/two.svg"
    edge=$(grep -E 'class="(run|mean|band)"' "$TMPD/two.svg" | sed 's/.* d="\([^"]*\)".*/\1/' | tr ' ' '\n' |
        awk '/^[ML]/ { split(substr($0, 2), a, ","); x = a[1]; y = a[2] } /^H/ { x = substr($0, 2); y = 100 } /^V/ { y = substr($0, 2); x = 100 }
            /^[MLHV]/ && (x + 0 >= 668 || y + 0 <= 48) { print }')
    check "plot $d: curve points on the right or top border of the frame: '$edge'" [ -z "$edge" ]
done

# plot --travel: a robot's recorded motion, its centre of mass's horizontal travel from the settled
# frame against time: one path of a point per frame, time rising from 0, a mark per actuation
# cycle, ending at the travel amorph sim measures (data-end, m)
expect_ok "$AMORPH" plot --travel "$W" $QUICK --cycles 4 --out "$TMPD/travel.svg"
check "plot --travel: one travel path" [ "$(grep -c 'class="travel"' "$TMPD/travel.svg")" = 1 ]
check "plot --travel: 4 cycle marks" [ "$(grep -c 'class="cycle"' "$TMPD/travel.svg")" = 4 ]
check "plot --travel: the x axis" grep -q 'class="xlabel"[^>]*>time since the movement started (s)<' "$TMPD/travel.svg"
pth=$(dpath "$TMPD/travel.svg" travel 1)
check "plot --travel: a line from x = 78 (time 0) with x rising through at least 20 points: '$(echo "$pth" | cut -c1-80)...'" \
    sh -c "echo '$pth' | tr ' ' '\n' | awk -F, 'NR == 1 { if (\$1 != \"M78.00\") exit 1; x = 78; next } { v = substr(\$1, 2) + 0; if (\$1 !~ /^L/ || v < x) exit 1; x = v } END { exit NR < 20 }'"
end=$(sed -n 's/.*class="travel" data-end="\([^"]*\)".*/\1/p' "$TMPD/travel.svg")
simt=$("$AMORPH" sim "$W" $QUICK --cycles 4 2>/dev/null | sed -n 's/^travel = //p')
check "plot --travel: the end '$end' should be sim's travel '$simt'" awk -v a="$end" -v b="$simt" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(b > 0 && d <= 1e-6 * b + 1e-9) }'
expect_fail 2 "plot: --travel needs a robot file" "$AMORPH" plot --travel --out "$TMPD/x.svg"
expect_fail 2 "unknown option" "$AMORPH" plot --travel "$W" --bogus --out "$TMPD/x.svg"
expect_fail 2 "no-such-robot" "$AMORPH" plot --travel "$TMPD/no-such-robot.lattice" --out "$TMPD/x.svg"

# the log is read by column name (the library's reader): reordered columns, one it does not know,
# and CRLF line ends give the same line
mkdir -p "$TMPD/reordered/plot-run"
awk -F, 'BEGIN { OFS = "," } { printf "%s,%s,%s,%s,%s\r\n", $8, (NR == 1 ? "note" : "n" NR), $3, $2, $1 }' \
    tests/data/plot-run/log.csv >"$TMPD/reordered/plot-run/log.csv"
expect_ok "$AMORPH" plot "$TMPD/reordered/plot-run" --out "$TMPD/reordered.svg"
check "plot: a log with reordered columns and CRLF line ends plots differently" cmp -s "$TMPD/one.svg" "$TMPD/reordered.svg"

# bad input: exit 2 (bad files and flags) or 1 (cannot write), one line, no output left behind
expect_fail 2 "no-such-robot" "$AMORPH" render "$TMPD/no-such-robot.lattice" --out "$TMPD/x.png"
expect_fail 2 "unknown option" "$AMORPH" render "$W" --out "$TMPD/x.png" --bogus
expect_fail 2 "frames" "$AMORPH" render "$W" --out "$TMPD/x.png" --frames 99
expect_fail 2 "width" "$AMORPH" render "$W" --out "$TMPD/x.png" --width 10x
expect_fail 2 "--out" "$AMORPH" render "$W"
expect_fail 2 "scene" "$AMORPH" render --scene nosuch:3 --out "$TMPD/x.png"
printf 'amorph-lattice 1\nsize 2 1 1\nlayer 0\n..\n' >"$TMPD/empty.lattice"
expect_fail 2 "no voxel" "$AMORPH" render "$TMPD/empty.lattice" --out "$TMPD/x.png"
expect_fail 2 "no-such-robot" "$AMORPH" view "$TMPD/no-such-robot.lattice" --out "$TMPD/x.html"
expect_fail 2 "frames" "$AMORPH" view "$W" --out "$TMPD/x.html" --frames 1
expect_fail 2 "unknown option" "$AMORPH" view "$W" --out "$TMPD/x.html" --bogus
expect_fail 2 "no-such-run" "$AMORPH" plot "$TMPD/no-such-run" --out "$TMPD/x.svg"
expect_fail 2 "--out" "$AMORPH" plot tests/data/plot-run
mkdir -p "$TMPD/notrun"
expect_fail 2 "neither a run folder" "$AMORPH" plot "$TMPD/notrun" --out "$TMPD/x.svg"
mkdir -p "$TMPD/badrun"
printf 'generation,evaluations,best\n0,20,0.001\n1,40,zero\n' >"$TMPD/badrun/log.csv"
expect_fail 2 "badrun/log.csv:3: best \\(column 3\\): not a number: 'zero'" "$AMORPH" plot "$TMPD/badrun" --out "$TMPD/x.svg"
printf 'generation,evaluations,best\n0,20,0.001\n1,40\n' >"$TMPD/badrun/log.csv"
expect_fail 2 "badrun/log.csv:3: 2 fields, the header has 3 columns" "$AMORPH" plot "$TMPD/badrun" --out "$TMPD/x.svg"
printf 'generation,evals,fitness\n0,20,0.001\n' >"$TMPD/badrun/log.csv"
expect_fail 2 "log.csv:1: not a log.csv header: no 'evaluations' column" "$AMORPH" plot "$TMPD/badrun" --out "$TMPD/x.svg"
if [ ! -e "$TMPD/x.png" ] && [ ! -e "$TMPD/x.html" ] && [ ! -e "$TMPD/x.svg" ]; then ok; else ko "failed commands left an output file"; fi
# unwritable outputs: a folder that does not exist, a file in place of a folder; an older file stays whole
expect_fail 1 "nodir" "$AMORPH" render "$W" $QUICK --out "$TMPD/nodir/x.png"
touch "$TMPD/afile"
expect_fail 1 "afile" "$AMORPH" view "$W" $QUICK --out "$TMPD/afile/x.html"
expect_fail 1 "nodir" "$AMORPH" plot tests/data/plot-run --out "$TMPD/nodir/x.svg"
cp "$TMPD/w.png" "$TMPD/keep.png"
expect_fail 2 "frames" "$AMORPH" render "$W" --out "$TMPD/keep.png" --frames 2
check "a failed render changed the existing file" cmp -s "$TMPD/w.png" "$TMPD/keep.png"
check "no temporary files left behind: $(ls "$TMPD")" [ -z "$(ls "$TMPD" | grep -iE 'tmp|\.part')" ]
expect_ok "$AMORPH" render --help
expect_ok "$AMORPH" plot --help
expect_ok "$AMORPH" view --help

summary "cli_render.sh"
