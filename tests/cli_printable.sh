# tests/cli_printable.sh: amorph export --stl and --amf. The files are read back here: STL solids,
# facets, each solid's signed volume from its own numbers (voxels x 1000 mm^3 at rest, 10 mm
# voxels) and its edges (every directed edge, by position, once, and its reverse once: closed and
# consistently turned); AMF volumes, materials, colours and triangles. Bad flags and unwritable
# paths: one line, a non-zero exit, no file left behind, an older file unchanged.
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

# stlcheck FILE: one line per solid "NAME FACETS VOLUME_MM3 BAD_EDGES"
stlcheck() {
    awk '
    /^solid / { s = $2; solids++; order[solids] = s }
    /facet normal/ { nv = 0; facets[s]++ }
    /vertex / { nv++; x[nv] = $2; y[nv] = $3; z[nv] = $4; k[nv] = $2 " " $3 " " $4
      if (nv == 3) {
        vol[s] += (x[1] * (y[2] * z[3] - z[2] * y[3]) + y[1] * (z[2] * x[3] - x[2] * z[3]) + z[1] * (x[2] * y[3] - y[2] * x[3])) / 6
        for (i = 1; i <= 3; i++) { j = i % 3 + 1; e[s, k[i] "|" k[j]]++ }
      }
    }
    END {
      for (key in e) { split(key, p, SUBSEP); split(p[2], ab, "|"); if (e[key] != 1 || e[p[1], ab[2] "|" ab[1]] != 1) bad[p[1]]++ }
      for (i = 1; i <= solids; i++) { s = order[i]; printf "%s %d %.3f %d\n", s, facets[s], vol[s], bad[s] + 0 }
    }' "$1"
}

# the walker at rest: three materials (24 passive, 24 active, 12 active90 voxels of 10 mm)
expect_ok "$AMORPH" export "$W" --stl "$TMPD/w.stl" --amf "$TMPD/w.amf"
stlcheck "$TMPD/w.stl" >"$TMPD/w.solids"
check "STL at rest: $(tr '\n' ';' <"$TMPD/w.solids")" [ "$(awk '{print $1, $3, $4}' "$TMPD/w.solids" | tr '\n' ';')" = \
    "passive 24000.000 0;active 24000.000 0;active90 12000.000 0;" ]
check "STL: endsolid per solid" [ "$(grep -c '^endsolid' "$TMPD/w.stl")" -eq 3 ]
facets=$(awk '{n += $2} END {print n}' "$TMPD/w.solids")
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

# a simulated moment: still closed, same facets, moved and deformed
expect_ok "$AMORPH" export "$W" --cycles 1 --relax-max 400 --step 500 --stl "$TMPD/w500.stl"
stlcheck "$TMPD/w500.stl" >"$TMPD/w500.solids"
if [ "$(awk '{b += $4} END {print b}' "$TMPD/w500.solids")" -eq 0 ] && \
    [ "$(awk '{n += $2} END {print n}' "$TMPD/w500.solids")" -eq "$facets" ]; then ok; else ko "STL at step 500: $(tr '\n' ';' <"$TMPD/w500.solids")"; fi
check "STL at step 500 equals the rest shape" sh -c "! cmp -s '$TMPD/w.stl' '$TMPD/w500.stl'"
check "STL at step 500: volumes not within 20% of rest: $(tr '\n' ';' <"$TMPD/w500.solids")" \
    awk '{r = $1 == "active90" ? 12000 : 24000; if ($3 < 0.8 * r || $3 > 1.2 * r) exit 1}' "$TMPD/w500.solids"
expect_ok "$AMORPH" export "$W" --cycles 1 --relax-max 400 --time 0 --amf "$TMPD/t0.amf"
check "AMF at time 0: 3 volumes" [ "$(grep -c '<volume materialid=' "$TMPD/t0.amf")" -eq 3 ]
# to standard output, a scene
"$AMORPH" export --scene cube:2 --stl - >"$TMPD/c.stl" 2>"$TMPD/err"
check "STL of cube:2 on stdout: $(stlcheck "$TMPD/c.stl")" [ "$(stlcheck "$TMPD/c.stl")" = "passive 96 8000.000 0" ]

# bad input: one line, exit 2 (flags) or 1 (cannot write), no file
expect_fail 2 "--step and --time" "$AMORPH" export "$W" --stl "$TMPD/x.stl" --step 5 --time 1
expect_fail 2 "are for --stl and --amf" "$AMORPH" export "$W" --lattice "$TMPD/x.lattice" --step 5
expect_fail 2 "--step needs a whole number" "$AMORPH" export "$W" --stl "$TMPD/x.stl" --step five
expect_fail 2 "--time needs seconds" "$AMORPH" export "$W" --stl "$TMPD/x.stl" --time -1
expect_fail 2 "--stl needs a file name" "$AMORPH" export "$W" --stl
expect_fail 2 "name the same file" "$AMORPH" export "$W" --stl "$TMPD/x.stl" --amf "$TMPD/x.stl"
expect_fail 2 "past the longest evaluation" "$AMORPH" export "$W" --cycles 1 --relax-max 400 --step 999999 --stl "$TMPD/x.stl"
printf 'amorph-lattice 1\nsize 2 1 1\nlayer 0\n..\n' >"$TMPD/empty.lattice"
expect_fail 2 "no voxel" "$AMORPH" export "$TMPD/empty.lattice" --stl "$TMPD/x.stl"
expect_fail 1 "nodir" "$AMORPH" export "$W" --stl "$TMPD/nodir/x.stl"
expect_fail 1 "nodir" "$AMORPH" export "$W" --amf "$TMPD/nodir/x.amf"
if [ ! -e "$TMPD/x.stl" ] && [ ! -e "$TMPD/x.amf" ] && [ ! -e "$TMPD/x.lattice" ]; then ok; else ko "failed commands left an output file"; fi
cp "$TMPD/w.stl" "$TMPD/keep.stl"
expect_fail 2 "past the longest" "$AMORPH" export "$W" --cycles 1 --relax-max 400 --step 999999 --stl "$TMPD/keep.stl"
check "a failed export changed the existing file" cmp -s "$TMPD/w.stl" "$TMPD/keep.stl"
check "no temporary files left behind: $(ls "$TMPD")" [ -z "$(ls "$TMPD" | grep -iE 'tmp|\.part')" ]
expect_ok "$AMORPH" export --help
check "export --help names --stl and --amf" sh -c "'$AMORPH' export --help | grep -q -- '--amf FILE'"

summary "cli_printable.sh"
