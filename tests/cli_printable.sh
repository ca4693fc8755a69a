# tests/cli_printable.sh: amorph export --stl (a file per material, or --merge: the body's), --amf,
# and --step's self-intersection warning. Every STL file is read back by test_io_mesh --stl-check,
# our own manifold check (one solid; every edge, by position, in exactly two facets once each way
# round; every vertex's facets one disc around it) with the solid's signed volume from its own
# numbers (voxels x 1000 mm^3 at rest, 10 mm voxels, a sliver less where a pinch is opened); with
# ADMesh installed, ADMesh must read each file and find nothing to fix. AMF volumes, materials,
# colours and triangles. Bad flags and unwritable paths: one line, a non-zero exit, no file left
# behind, an older file unchanged.
# Run from the repository root: sh tests/cli_printable.sh
. tests/shlib.sh
if ! "$AMORPH" render --help >/dev/null 2>&1; then
    # the board profile has no printable files: export says so in one line
    expect_fail 2 "export --stl: not in this build" "$AMORPH" export --scene cube:2 --stl "$TMPD/x.stl"
    echo "cli_printable.sh: SKIPPED (no printable files in this build)"
    summary "cli_printable.sh"
    exit $?
fi
W=tests/data/walker.lattice
MESH=${MESH_TOOL:-$BUILD/tests/test_io_mesh}

# stlcheck FILE: "solids S facets F volume V open_edges E bad_vertices B" (V in mm^3)
stlcheck() { "$MESH" --stl-check "$1"; }
# field NAME LINE: the value after NAME in a stlcheck line
field() { echo "$2" | sed -n "s/.*$1 \([^ ]*\).*/\1/p"; }
# manifold FILE VOLUME [REL]: one solid, no open edge, no bad vertex, volume within REL (default 1e-6)
manifold() {
    m=$(stlcheck "$1")
    if [ "$(field solids "$m")" = 1 ] && [ "$(field open_edges "$m")" = 0 ] && [ "$(field bad_vertices "$m")" = 0 ] &&
        awk -v v="$(field volume "$m")" -v w="$2" -v r="${3:-1e-6}" 'BEGIN { d = v - w; if (d < 0) d = -d; exit !(d <= r * w) }'
    then ok; else ko "$1: $m (want one manifold solid of $2 mm^3)"; fi
}
# admesh_clean FILE PARTS: ADMesh reads FILE, finds PARTS parts and nothing to fix (skipped without ADMesh)
admesh_clean() {
    command -v admesh >/dev/null 2>&1 || return 0
    a=$(admesh "$1" 2>&1)
    if echo "$a" | grep -q "Number of parts *: *$2 " && echo "$a" | grep -q "Total disconnected facets *: *0 *0" &&
        echo "$a" | grep -q "Backwards edges *: *0" && echo "$a" | grep -q "Facets reversed *: *0" &&
        echo "$a" | grep -q "Edges fixed *: *0" && echo "$a" | grep -q "Facets added *: *0" && ! echo "$a" | grep -qi "wrong"
    then ok; else ko "ADMesh on $1: $(echo "$a" | grep -iE 'parts|disconnected|backwards|reversed|fixed|added|wrong' | tr -s ' ' | tr '\n' ';')"; fi
}
command -v admesh >/dev/null 2>&1 || echo "cli_printable.sh: no admesh: its checks skipped"

# the walker at rest: three materials (24 passive, 24 active, 12 active90 voxels of 10 mm), a file each
expect_ok "$AMORPH" export "$W" --stl "$TMPD/w.stl" --amf "$TMPD/w.amf"
check "STL: a file per material: $(ls "$TMPD" | tr '\n' ' ')" [ "$(cd "$TMPD" && ls w*.stl | tr '\n' ' ')" = "w-active.stl w-active90.stl w-passive.stl " ]
manifold "$TMPD/w-passive.stl" 24000
manifold "$TMPD/w-active.stl" 24000
manifold "$TMPD/w-active90.stl" 12000
check "STL: solid names" [ "$(head -qn 1 "$TMPD/w-passive.stl" "$TMPD/w-active.stl" "$TMPD/w-active90.stl" | tr '\n' ';')" = "solid passive;solid active;solid active90;" ]
for f in passive active active90; do admesh_clean "$TMPD/w-$f.stl" 1; done
facets=$(cat "$TMPD"/w-*.stl | grep -c 'facet normal')
# merged: the body's outer surface, the walls between materials left out
expect_ok "$AMORPH" export "$W" --stl "$TMPD/wm.stl" --merge
manifold "$TMPD/wm.stl" 60000
check "merged STL: solid body" [ "$(head -n 1 "$TMPD/wm.stl")" = "solid body" ]
check "merged STL: fewer facets than the materials' ($(grep -c 'facet normal' "$TMPD/wm.stl") of $facets)" \
    [ "$(grep -c 'facet normal' "$TMPD/wm.stl")" -lt "$facets" ]
check "merged STL: no per-material files" [ ! -e "$TMPD/wm-passive.stl" ]
admesh_clean "$TMPD/wm.stl" 1
check "AMF: unit" grep -q '<amf unit="millimeter"' "$TMPD/w.amf"
check "AMF: 3 volumes" [ "$(grep -c '<volume materialid="[123]">' "$TMPD/w.amf")" -eq 3 ]
if [ "$(grep -c '<material id=' "$TMPD/w.amf")" -eq 3 ] && \
    [ "$(grep -c '<color><r>' "$TMPD/w.amf")" -eq 3 ]; then ok; else ko "AMF: 3 materials with colours"; fi
check "AMF: $(grep -c '<triangle>' "$TMPD/w.amf") triangles, STL $facets facets" [ "$(grep -c '<triangle>' "$TMPD/w.amf")" -eq "$facets" ]
if [ "$(grep -c '<object id=' "$TMPD/w.amf")" -eq 1 ] && tail -n 1 "$TMPD/w.amf" | grep -q '^</amf>$'; then ok; else ko "AMF: one object, closed"; fi
# every triangle names a vertex that exists
nvert=$(grep -c '<vertex>' "$TMPD/w.amf")
maxv=$(sed -n 's/.*<v1>\([0-9]*\)<\/v1><v2>\([0-9]*\)<\/v2><v3>\([0-9]*\)<\/v3>.*/\1\n\2\n\3/p' "$TMPD/w.amf" | sort -n | tail -n 1)
check "AMF: vertex $maxv of $nvert" [ "$maxv" -lt "$nvert" ]

# voxels that touch only along an edge or at a corner: the passive voxels at (0,0,0) and (1,1,0)
# along an edge (the active one beside them), (1,1,0) and (2,1,1) along another; opened, every
# file is manifold by position, a sliver less than 3 and 1 voxels (the merged body: 4)
printf 'amorph-lattice 1\nsize 3 2 2\nvoxel_size 0.01\nmaterial passive E=1e6 density=1000\nmaterial active E=1e6 density=1000 cte=0.01\nlayer 0\n12.\n.1.\nlayer 1\n...\n..1\n' >"$TMPD/pinch.lattice"
expect_ok "$AMORPH" export "$TMPD/pinch.lattice" --stl "$TMPD/p.stl"
manifold "$TMPD/p-passive.stl" 3000 0.05
manifold "$TMPD/p-active.stl" 1000
expect_ok "$AMORPH" export "$TMPD/pinch.lattice" --stl "$TMPD/pm.stl" --merge
manifold "$TMPD/pm.stl" 4000 0.05
admesh_clean "$TMPD/p-passive.stl" 3
admesh_clean "$TMPD/pm.stl" 2
# a checkerboard of one material: every voxel touches the others along edges only
printf 'amorph-lattice 1\nsize 3 3 2\nlayer 0\n1.1\n.1.\n1.1\nlayer 1\n.1.\n1.1\n.1.\n' >"$TMPD/checker.lattice"
expect_ok "$AMORPH" export "$TMPD/checker.lattice" --stl "$TMPD/ch.stl"
manifold "$TMPD/ch-passive.stl" 9000 0.1
admesh_clean "$TMPD/ch-passive.stl" 9

# a simulated moment: still closed and manifold, same facets, moved and deformed, no warning
expect_ok "$AMORPH" export "$W" --cycles 1 --relax-max 400 --step 500 --stl "$TMPD/w500.stl"
check "STL at step 500: a warning: $(cat "$TMPD/err")" [ ! -s "$TMPD/err" ]
check "STL at step 500: $(cat "$TMPD"/w500-*.stl | grep -c 'facet normal') facets, want $facets" [ "$(cat "$TMPD"/w500-*.stl | grep -c 'facet normal')" -eq "$facets" ]
manifold "$TMPD/w500-passive.stl" 24000 0.2
manifold "$TMPD/w500-active.stl" 24000 0.2
manifold "$TMPD/w500-active90.stl" 12000 0.2
check "STL at step 500 equals the rest shape" sh -c "! cmp -s '$TMPD/w-active.stl' '$TMPD/w500-active.stl'"
# a VXA robot's moment takes its layers (per-voxel phases), as sim does: at the evaluation's last step
# the surface's middle in x and y is that of the voxels' centres in sim's trajectory, within 1 mm (the
# robot travels 11 mm; without its phases 1 mm, and the surface then sits 11 mm away)
V=tests/data/evosoro_phase.vxa
"$AMORPH" sim "$V" --trajectory "$TMPD/vp.csv" --every 1000000 >"$TMPD/vp.txt" 2>/dev/null
vsteps=$(sed -n 's/^steps = //p' "$TMPD/vp.txt")
expect_ok "$AMORPH" export "$V" --step "$vsteps" --stl "$TMPD/vp.stl" --merge
for axis in 1 2; do
    smid=$(awk -v k=$((axis + 1)) '$1 == "vertex" { if (!n || $k < lo) lo = $k; if (!n || $k > hi) hi = $k; n++ } END { print (lo + hi) / 2 }' "$TMPD/vp.stl")
    tmid=$(tail -n 1 "$TMPD/vp.csv" | awk -F, -v a="$axis" '{ n = (NF - 6) / 7; for (i = 0; i < n; i++) { x = 1000 * $(6 + a + 7 * i); if (!i || x < lo) lo = x; if (!i || x > hi) hi = x } print (lo + hi) / 2 }')
    check "$V at step $vsteps: the STL's middle along axis $axis ($smid mm) should be the trajectory's ($tmid mm)" \
        awk -v s="$smid" -v t="$tmid" 'BEGIN { exit !(s != "" && t != "" && s - t < 1 && t - s < 1) }'
done
expect_ok "$AMORPH" export "$W" --cycles 1 --relax-max 400 --time 0 --amf "$TMPD/t0.amf"
check "AMF at time 0: 3 volumes" [ "$(grep -c '<volume materialid=' "$TMPD/t0.amf")" -eq 3 ]
# a robot that folds into itself as it settles: one warning line, the file still written
"$AMORPH" export tests/data/folding.lattice --relax-max 9300 --cycles 1 --step 9300 --stl "$TMPD/fold.stl" --merge \
    >"$TMPD/out" 2>"$TMPD/err"
rc=$?
check "folding robot: exit $rc, stderr: $(cat "$TMPD/err")" [ $rc -eq 0 ]
check "folding robot: want one warning line, got: $(cat "$TMPD/err")" \
    sh -c "[ \$(wc -l <'$TMPD/err') -eq 1 ] && grep -q 'warning: at step 9300 the surface crosses itself ([0-9]* pairs of triangles' '$TMPD/err'"
check "folding robot: no file" [ -s "$TMPD/fold.stl" ]
# to standard output: a scene of one material, or the merged body
"$AMORPH" export --scene cube:2 --stl - >"$TMPD/c.stl" 2>"$TMPD/err"
manifold "$TMPD/c.stl" 8000
check "STL of cube:2 on stdout: $(stlcheck "$TMPD/c.stl")" [ "$(field facets "$(stlcheck "$TMPD/c.stl")")" = 96 ]
"$AMORPH" export "$W" --stl - --merge >"$TMPD/m.stl" 2>"$TMPD/err"
check "merged STL on stdout equals the file" cmp -s "$TMPD/m.stl" "$TMPD/wm.stl"
expect_fail 2 "add --merge" "$AMORPH" export "$W" --stl -

# bad input: one line, exit 2 (flags) or 1 (cannot write), no file
expect_fail 2 "--step and --time" "$AMORPH" export "$W" --stl "$TMPD/x.stl" --step 5 --time 1
expect_fail 2 "are for --stl and --amf" "$AMORPH" export "$W" --lattice "$TMPD/x.lattice" --step 5
expect_fail 2 "--step needs a whole number" "$AMORPH" export "$W" --stl "$TMPD/x.stl" --step five
expect_fail 2 "--time needs seconds" "$AMORPH" export "$W" --stl "$TMPD/x.stl" --time -1
expect_fail 2 "--stl needs a file name" "$AMORPH" export "$W" --stl
expect_fail 2 "--merge is for --stl" "$AMORPH" export "$W" --amf "$TMPD/x.amf" --merge
expect_fail 2 "another output names too" "$AMORPH" export "$W" --stl "$TMPD/x.stl" --amf "$TMPD/x-active.stl"
expect_fail 2 "name the same file" "$AMORPH" export "$W" --stl "$TMPD/x.stl" --amf "$TMPD/x.stl"
expect_fail 2 "past the longest evaluation" "$AMORPH" export "$W" --cycles 1 --relax-max 400 --step 999999 --stl "$TMPD/x.stl"
printf 'amorph-lattice 1\nsize 2 1 1\nlayer 0\n..\n' >"$TMPD/empty.lattice"
expect_fail 2 "no voxel" "$AMORPH" export "$TMPD/empty.lattice" --stl "$TMPD/x.stl"
expect_fail 1 "nodir" "$AMORPH" export "$W" --stl "$TMPD/nodir/x.stl"
expect_fail 1 "nodir" "$AMORPH" export "$W" --amf "$TMPD/nodir/x.amf"
if [ -z "$(ls "$TMPD" | grep -E '^x')" ]; then ok; else ko "failed commands left an output file: $(ls "$TMPD" | grep -E '^x')"; fi
cp "$TMPD/w-active.stl" "$TMPD/keep-active.stl"
expect_fail 2 "past the longest" "$AMORPH" export "$W" --cycles 1 --relax-max 400 --step 999999 --stl "$TMPD/keep.stl"
check "a failed export changed the existing file" cmp -s "$TMPD/w-active.stl" "$TMPD/keep-active.stl"
check "no temporary files left behind: $(ls "$TMPD")" [ -z "$(ls "$TMPD" | grep -iE 'tmp|\.part')" ]
expect_ok "$AMORPH" export --help
check "export --help names --stl and --amf" sh -c "'$AMORPH' export --help | grep -q -- '--amf FILE'"
check "export --help names --merge and the files' names" sh -c "'$AMORPH' export --help | grep -q -- 'robot-passive.stl' && '$AMORPH' export --help | grep -q -- '--merge'"

summary "cli_printable.sh"
