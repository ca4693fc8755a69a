# tests/cli_lattice.sh: `amorph sim FILE` on bad lattice files must exit 2 with one stderr line
# "FILE:LINE: problem" (format: docs/formats.md). Run by tests/run_all.sh; needs build/amorph.
. tests/shlib.sh

D=$TMPD/lat
mkdir -p "$D"

# a small good file: a 2-material palette, 3 x 2 x 2 cells
cat >"$D/good.lattice" <<'EOF'
amorph-lattice 1
material body E=1e6 density=1000
material muscle cte=0.01 color=#f0c81e
size 3 2 2
voxel_size 0.01
layer 0
122
111
layer 1
1..
...
EOF
expect_ok "$AMORPH" sim "$D/good.lattice" --cycles 1 --relax-max 10

# bad header (a version this build does not read): line 1
printf 'amorph-lattice 9\nsize 1 1 1\nlayer 0\n1\n' >"$D/header.lattice"
expect_fail 2 "$D/header.lattice:1: .*version" "$AMORPH" sim "$D/header.lattice"

# not a lattice at all: line 3 is the first meaningful one
printf '# comment\n\nhello world\n' >"$D/nothdr.lattice"
expect_fail 2 "$D/nothdr.lattice:3: " "$AMORPH" sim "$D/nothdr.lattice"

# wrong counts: a row of 4 cells in a 3-wide lattice, line 5
printf 'amorph-lattice 1\nsize 3 2 1\nlayer 0\n111\n1111\n' >"$D/row.lattice"
expect_fail 2 "$D/row.lattice:5: .*4 cells, expected 3" "$AMORPH" sim "$D/row.lattice"

# wrong counts: too few rows (the next layer starts early), line 5
printf 'amorph-lattice 1\nsize 3 2 2\nlayer 0\n111\nlayer 1\n111\n111\n' >"$D/rows.lattice"
expect_fail 2 "$D/rows.lattice:5: .*rows" "$AMORPH" sim "$D/rows.lattice"

# wrong counts: a missing layer at the end of the file, line 5
printf 'amorph-lattice 1\nsize 3 2 2\nlayer 0\n111\n111\n' >"$D/layer.lattice"
expect_fail 2 "$D/layer.lattice:5: .*missing layer 1" "$AMORPH" sim "$D/layer.lattice"

# unknown material: id 3 with a 2-material palette, line 7
printf 'amorph-lattice 1\nmaterial a\nmaterial b\nsize 2 2 1\nlayer 0\n12\n3.\n' >"$D/mat.lattice"
expect_fail 2 "$D/mat.lattice:7: .*unknown material id '3'" "$AMORPH" sim "$D/mat.lattice"

# over capacity: more cells per side than any profile holds, line 3
printf 'amorph-lattice 1\n# too big\nsize 999 1 1\nlayer 0\n' >"$D/cap.lattice"
expect_fail 2 "$D/cap.lattice:3: .*(desktop|board) profile" "$AMORPH" sim "$D/cap.lattice"

# junk numbers: E=1e6x, line 3; nan, line 2
printf 'amorph-lattice 1\nmaterial a\nmaterial b E=1e6x\nsize 1 1 1\nlayer 0\n1\n' >"$D/junk.lattice"
expect_fail 2 "$D/junk.lattice:3: .*1e6x" "$AMORPH" sim "$D/junk.lattice"
printf 'amorph-lattice 1\nvoxel_size nan\nsize 1 1 1\nlayer 0\n1\n' >"$D/nan.lattice"
expect_fail 2 "$D/nan.lattice:2: .*nan" "$AMORPH" sim "$D/nan.lattice"

# a missing file: exit 2, the message names it
expect_fail 2 "$D/no-such-file.lattice" "$AMORPH" sim "$D/no-such-file.lattice"

summary cli_lattice.sh
