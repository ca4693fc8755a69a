# tests/cli_trajectory.sh: amorph sim --trajectory (docs/formats.md, Trajectory): the rows and
# their steps, the centre of mass against what sim reports, voxel positions at rest, a free fall
# against 1/2 g t^2, CSV and JSON lines holding the same numbers, the voxels' scalars (--scalars:
# zero at rest, stress against strain, the phase against the actuation, a free fall's speed), bad
# flags and unwritable paths.
# Run from the repository root: sh tests/cli_trajectory.sh
. tests/shlib.sh

# field NAME FILE: a numeric field of the one-line JSON object in FILE
field() { sed -n "s/.*\"$1\": *\(-\{0,1\}[0-9][0-9.eE+-]*\).*/\1/p" "$2"; }
# awkt DESCRIPTION EXPR -v NAME=VALUE...: ok when the awk expression over the named values holds
# (a(v) is |v|)
awkt() { ad=$1; ae=$2; shift 2; if awk "$@" "function a(v) { return v < 0 ? -v : v } BEGIN { exit !($ae) }"; then ok; else ko "$ad"; fi; }
# col FILE NAME: the values of the CSV column NAME (found by the header), one per line
col() { awk -F, -v n="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == n) c = i; next } { print $c }' "$1"; }

# the walker (it travels), 2 cycles, a row every 70 steps: neither the relaxation's end nor the
# last step is a multiple of 70, so both are rows of their own
expect_ok "$AMORPH" sim tests/data/walker.lattice --cycles 2 --every 70 --trajectory "$TMPD/w.csv" --json
cp "$TMPD/out" "$TMPD/w.json"
steps=$(field steps "$TMPD/w.json"); relax=$(field relax_steps "$TMPD/w.json")
want=$((steps / 70 + 1))
[ $((relax % 70)) -ne 0 ] && want=$((want + 1))
[ $((steps % 70)) -ne 0 ] && want=$((want + 1))
rows=$(($(wc -l <"$TMPD/w.csv") - 1))
check "rows: $rows, want $want (steps $steps, relax $relax, every 70)" [ "$rows" -eq "$want" ]
check "the header: step,time,segment,com_x,com_y,com_z,v0_x...: $(head -c 120 "$TMPD/w.csv")" \
    grep -q '^step,time,segment,com_x,com_y,com_z,v0_x,v0_y,v0_z,v0_qw,v0_qx,v0_qy,v0_qz,v1_x,' "$TMPD/w.csv"
nv=$(field voxels "$TMPD/w.json")
check "6 + 7 x $nv columns in every line" \
    awk -F, -v n=$((6 + 7 * nv)) 'NF != n { exit 1 }' "$TMPD/w.csv"
col "$TMPD/w.csv" step >"$TMPD/steps"
check "the steps: 0, the multiples of 70, $relax and $steps, rising: $(tr '\n' ' ' <"$TMPD/steps" | head -c 300)" \
    awk -v r="$relax" -v s="$steps" 'NR == 1 && $1 != 0 { exit 1 } NR > 1 && $1 <= p { exit 1 }
        $1 % 70 && $1 != r && $1 != s { exit 1 } { p = $1 } END { exit !(p == s) }' "$TMPD/steps"
check "segment 0 up to step $relax, 1 after" \
    awk -F, -v r="$relax" 'NR > 1 && ($3 != ($1 > r)) { exit 1 }' "$TMPD/w.csv"
dt=$(field dt "$TMPD/w.json"); rdt=$(field relax_dt "$TMPD/w.json"); simt=$(field sim_seconds "$TMPD/w.json")
# time: rising; in the relaxation between step x dt and step x relax_dt (settling takes the pseudo-step,
# the release window the run's step); in the movement dt a step from the relaxation's end; the last
# row's is sim's simulated time
check "time: relaxation steps of dt ($dt s) to relax_dt ($rdt s), movement steps of dt, ending at $simt s" \
    awk -F, -v dt="$dt" -v rdt="$rdt" -v r="$relax" -v T="$simt" 'function a(x) { return x < 0 ? -x : x }
        NR == 1 { next } NR > 2 && $2 <= p { exit 1 } { p = $2 }
        $1 <= r && ($2 < $1 * dt * (1 - 1e-6) || $2 > $1 * rdt * (1 + 1e-6)) { exit 1 }
        $1 == r { tr = $2 } $1 > r && a($2 - tr - ($1 - r) * dt) > 1e-8 * $2 { exit 1 }
        END { if (a(p - T) > 1e-6 * T || rdt <= dt) exit 1 }' "$TMPD/w.csv"
# the centre of mass: the last row less the relaxation's last is sim's displacement
c0=$(awk -F, -v r="$relax" '$1 == r { print $4, $5, $6 }' "$TMPD/w.csv")
c1=$(tail -n 1 "$TMPD/w.csv" | awk -F, '{ print $4, $5, $6 }')
dx=$(field dx "$TMPD/w.json"); dy=$(field dy "$TMPD/w.json"); dz=$(field dz "$TMPD/w.json")
awkt "the walker should travel: dx $dx dy $dy" "dx * dx + dy * dy > 1e-8" -v dx="$dx" -v dy="$dy"
awkt "com displacement ($c0) -> ($c1) differs from sim's dx dy dz $dx $dy $dz" \
    "a(x1 - x0 - dx) < 1e-9 && a(y1 - y0 - dy) < 1e-9 && a(z1 - z0 - dz) < 1e-9" \
    -v x0="${c0%% *}" -v x1="${c1%% *}" -v dx="$dx" -v dy="$dy" -v dz="$dz" \
    -v y0="$(echo "$c0" | cut -d' ' -f2)" -v y1="$(echo "$c1" | cut -d' ' -f2)" \
    -v z0="$(echo "$c0" | cut -d' ' -f3)" -v z1="$(echo "$c1" | cut -d' ' -f3)"
# the centre of mass is the mean of the voxels (one density) in every row
check "com_x is the mean of the voxels' x in every row" \
    awk -F, -v n="$nv" 'NR > 1 { s = 0; for (i = 0; i < n; i++) s += $(7 + 7 * i); d = s / n - $4; if (d < 0) d = -d; if (d > 1e-8) exit 1 }' "$TMPD/w.csv"

# JSON lines: one object per row, the same numbers; --trajectory-format overrides the name
expect_ok "$AMORPH" sim tests/data/walker.lattice --cycles 2 --every 70 --trajectory "$TMPD/w.jsonl"
check "jsonl: as many lines as CSV rows" [ "$(wc -l <"$TMPD/w.jsonl")" -eq "$want" ]
check "jsonl: every line an object {\"step\": ..., \"quat\": [...]}" \
    awk '!/^\{"step": [0-9]+, "time": [-0-9.e]+, "segment": [01], "com": \[[^]]*\], "pos": \[\[.*\]\], "quat": \[\[.*\]\]\}$/ { exit 1 }' "$TMPD/w.jsonl"
check "jsonl: the last com equals the CSV's" \
    [ "$(tail -n 1 "$TMPD/w.jsonl" | sed 's/.*"com": \[\([^]]*\)\].*/\1/; s/, /,/g')" = "$(tail -n 1 "$TMPD/w.csv" | cut -d, -f4-6)" ]
check "jsonl: voxel 5's position at the last step equals the CSV's" \
    [ "$(tail -n 1 "$TMPD/w.jsonl" | sed 's/.*"pos": \[\(\[[^]]*\], \)\{5\}\[\([^]]*\)\].*/\2/; s/, /,/g')" = "$(tail -n 1 "$TMPD/w.csv" | cut -d, -f42-44)" ]
expect_ok "$AMORPH" sim tests/data/walker.lattice --cycles 2 --every 70 --trajectory "$TMPD/j.csv" --trajectory-format jsonl
check "--trajectory-format jsonl writes JSON lines whatever the name" cmp -s "$TMPD/j.csv" "$TMPD/w.jsonl"
expect_ok "$AMORPH" sim tests/data/walker.lattice --cycles 2 --every 70 --trajectory "$TMPD/c.jsonl" --trajectory-format csv
check "--trajectory-format csv writes CSV whatever the name" cmp -s "$TMPD/c.jsonl" "$TMPD/w.csv"

# the default interval: period_steps / 10 (a 300-step period: every 30 steps); the rows do not
# change the simulation (the same hash with and without)
expect_ok "$AMORPH" sim --scene cube:3 --cycles 1 --period_steps 300 --trajectory "$TMPD/c.csv" --json
cp "$TMPD/out" "$TMPD/c.json"
check "default every 30: the second row is step 30" [ "$(col "$TMPD/c.csv" step | sed -n 2p)" = 30 ]
expect_ok "$AMORPH" sim --scene cube:3 --cycles 1 --period_steps 300 --json
check "the trajectory changed the hash" [ "$(sed -n 's/.*"hash": "\([0-9a-f]*\)".*/\1/p' "$TMPD/out")" = "$(sed -n 's/.*"hash": "\([0-9a-f]*\)".*/\1/p' "$TMPD/c.json")" ]
# at step 0 every voxel is at its lattice position ((i + 1/2) L, L = 1 cm; 1e-8 m: L is a float) and unturned: voxel
# 5 of cube:3 is cell (2, 1, 0), voxel 13 cell (1, 1, 1), voxel 26 cell (2, 2, 2)
for vc in "5 2 1 0" "13 1 1 1" "26 2 2 2"; do
    set -- $vc
    row=$(sed -n 2p "$TMPD/c.csv" | cut -d, -f$((7 + 7 * $1))-$((13 + 7 * $1)))
    awkt "voxel $1 at step 0: $row, want cell ($2, $3, $4) x 1 cm + 5 mm, quaternion 1 0 0 0" \
        "a(x - ($2 + 0.5) * 0.01) < 1e-8 && a(y - ($3 + 0.5) * 0.01) < 1e-8 && a(z - ($4 + 0.5) * 0.01) < 1e-8 && w == 1 && qx == 0 && qy == 0 && qz == 0" \
        -v x="$(echo "$row" | cut -d, -f1)" -v y="$(echo "$row" | cut -d, -f2)" -v z="$(echo "$row" | cut -d, -f3)" \
        -v w="$(echo "$row" | cut -d, -f4)" -v qx="$(echo "$row" | cut -d, -f5)" -v qy="$(echo "$row" | cut -d, -f6)" \
        -v qz="$(echo "$row" | cut -d, -f7)"
done

# a free fall (no floor, so no contact): the centre of mass drops 1/2 g t^2. The semi-implicit
# Euler step drops 1/2 g t (t + dt) exactly: within 3e-4 of it (the fixed-point build's gravity,
# a Q24 number in model units, is 1.7e-4 low; the float build's drop is within 1e-5)
expect_ok "$AMORPH" sim --scene cube:2 --floor off --cycles 0 --relax_max_steps 2000 --every 100 --trajectory "$TMPD/f.csv" --json
cp "$TMPD/out" "$TMPD/f.json"
dt=$(field dt "$TMPD/f.json")
check "free fall: 21 rows (2000 steps, every 100)" [ "$(($(wc -l <"$TMPD/f.csv") - 1))" -eq 21 ]
check "free fall: the drop should be 1/2 g t^2 within g dt t, and 1/2 g t (t + dt) within 3e-4 of it (dt $dt): $(tail -n 1 "$TMPD/f.csv" | cut -d, -f1-6)" \
    awk -F, -v dt="$dt" 'NR == 2 { z0 = $6 } NR > 2 { g = 9.80665; t = $2; d = z0 - $6;
        e = d - 0.5 * g * t * t; if (e < 0) e = -e; if (e > g * dt * t) exit 1;
        e = d - 0.5 * g * t * (t + dt); if (e < 0) e = -e; if (e > 3e-4 * d) exit 1; n++ } END { exit !(n == 20 && d > 0.01) }' "$TMPD/f.csv"
check "free fall: x and y stay" awk -F, 'NR == 2 { x = $4; y = $5 } NR > 2 && ($4 != x || $5 != y) { exit 1 }' "$TMPD/f.csv"

# --scalars: each voxel's strain, stress, speed and phase after its quaternion (11 columns a voxel)
expect_ok "$AMORPH" sim tests/data/walker.lattice --cycles 1 --every 25 --trajectory "$TMPD/s.csv" --scalars --json
cp "$TMPD/out" "$TMPD/s.json"
sr=$(field relax_steps "$TMPD/s.json"); sp=$(field period_steps "$TMPD/s.json")
check "--scalars: the header names v0_strain,v0_stress,v0_speed,v0_phase after v0_qz" \
    grep -q '^step,time,segment,com_x,com_y,com_z,v0_x,v0_y,v0_z,v0_qw,v0_qx,v0_qy,v0_qz,v0_strain,v0_stress,v0_speed,v0_phase,v1_x,' "$TMPD/s.csv"
check "--scalars: 6 + 11 x $nv columns in every line" awk -F, -v n=$((6 + 11 * nv)) 'NF != n { exit 1 }' "$TMPD/s.csv"
expect_ok "$AMORPH" sim tests/data/walker.lattice --cycles 1 --every 25 --trajectory "$TMPD/p.csv" --json
check "--scalars changed the result (all but wall_seconds)" \
    sh -c "sed 's/\"wall_seconds\": [0-9.e+-]*//' '$TMPD/out' >'$TMPD/r1'; sed 's/\"wall_seconds\": [0-9.e+-]*//' '$TMPD/s.json' | cmp -s - '$TMPD/r1'"
check "--scalars: the other columns are the trajectory without it, byte for byte" \
    sh -c "awk -F, -v OFS=, -v n=$nv '{ o = \$1; for (i = 2; i <= 6; i++) o = o OFS \$i; for (v = 0; v < n; v++) for (k = 0; k < 7; k++) o = o OFS \$(7 + 11 * v + k); print o }' '$TMPD/s.csv' | cmp -s - '$TMPD/p.csv'"
# at step 0 every link is at its rest length and unturned, and nothing moves: all scalars 0
check "--scalars: strain, stress, speed and phase 0 at step 0" \
    awk -F, -v n="$nv" 'NR == 2 { for (v = 0; v < n; v++) for (k = 0; k < 4; k++) if ($(14 + 11 * v + k) != 0) exit 1; ok = 1 } END { exit !ok }' "$TMPD/s.csv"
# the walker's materials all have E = 1 MPa: a link's stress is its strain times E, so the voxel's
# mean stress is its mean strain times 1e6 Pa; under gravity some voxel is strained
check "--scalars: stress = 1e6 Pa x strain in every row, and some strain above 1e-6" \
    awk -F, -v n="$nv" 'function a(x) { return x < 0 ? -x : x } NR > 1 { for (v = 0; v < n; v++) { e = $(14 + 11 * v); s = $(15 + 11 * v);
        if (e < 0 || a(s - 1e6 * e) > 1e-6 * s + 1e-9) exit 1; if (e > 1e-6) big = 1 } } END { exit !big }' "$TMPD/s.csv"
# the phase: 0 through the relaxation (held at temp_base); in the movement, the expansion the step
# ending at the row used, cbrt(1 + cte A sin(2 pi (step - 1 - relax_steps) / period + phase)) - 1 with
# cte 0.01 and A 30: voxel 0 (passive) 0, voxel 40 (active) in phase, voxel 10 (active90) -90 degrees
check "--scalars: the phase 0 in the relaxation and the materials' expansion in the movement (relax $sr, period $sp)" \
    awk -F, -v r="$sr" -v P="$sp" 'function a(x) { return x < 0 ? -x : x }
        function ex(st, ph) { return exp(log(1 + 0.3 * sin(2 * 3.14159265358979 * (st - 1 - r) / P + ph)) / 3) - 1 }
        NR == 1 { next } $3 == 0 && ($17 != 0 || $(17 + 11 * 40) != 0 || $(17 + 11 * 10) != 0) { exit 1 }
        $3 == 1 { if ($17 != 0 || a($(17 + 11 * 40) - ex($1, 0)) > 1e-5 || a($(17 + 11 * 10) - ex($1, -1.5707963)) > 1e-5) exit 1;
            m = a($(17 + 11 * 40)) > m ? a($(17 + 11 * 40)) : m; n++ } END { exit !(n >= 20 && m > 0.09) }' "$TMPD/s.csv"
# the speed: in a free fall (no floor, kinetic damping stops nothing while the energy rises) every
# voxel moves at g t, t the row's time (the semi-implicit step: v = g x the sum of the steps; the
# fixed-point build's gravity is 1.7e-4 low)
expect_ok "$AMORPH" sim --scene cube:2 --floor off --cycles 0 --relax_max_steps 2000 --every 100 --trajectory "$TMPD/fs.csv" --scalars
check "--scalars: a free fall's speed is g t for every voxel, within 3e-4 (0.8 m/s at the end)" \
    awk -F, 'NR > 1 { g = 9.80665; for (v = 0; v < 8; v++) { s = $(16 + 11 * v); e = s - g * $2; if (e < 0) e = -e; if (e > 3e-4 * g * $2 + 1e-9) exit 1 } m = s }
        END { exit !(m > 0.8) }' "$TMPD/fs.csv"
# JSON lines: the four arrays after "quat", the CSV's numbers
expect_ok "$AMORPH" sim tests/data/walker.lattice --cycles 1 --every 25 --trajectory "$TMPD/s.jsonl" --scalars
check "--scalars jsonl: every line ends with the strain, stress, speed and phase arrays" \
    awk '!/"quat": \[\[.*\]\], "strain": \[[^]]*\], "stress": \[[^]]*\], "speed": \[[^]]*\], "phase": \[[^]]*\]\}$/ { exit 1 }' "$TMPD/s.jsonl"
check "--scalars jsonl: the last row's speeds are the CSV's" \
    [ "$(tail -n 1 "$TMPD/s.jsonl" | sed 's/.*"speed": \[\([^]]*\)\].*/\1/; s/, /,/g')" = "$(tail -n 1 "$TMPD/s.csv" | awk -F, -v n="$nv" -v OFS=, '{ o = $16; for (v = 1; v < n; v++) o = o OFS $(16 + 11 * v); print o }')" ]
expect_fail 2 "^amorph: sim: --scalars needs --trajectory FILE$" "$AMORPH" sim --scene cube:2 --scalars

# bad flags: one line, exit 2, no file
for args in "--every 0" "--every x" "--every 1000000001" "--every" "--trajectory-format xml" "--trajectory-format" "--trajectory" \
            "--trajectory $TMPD/" ; do
    # shellcheck disable=SC2086
    expect_fail 2 "sim: --(every|trajectory|trajectory-format)" "$AMORPH" sim --scene cube:2 $args
done
expect_fail 2 "^amorph: sim: --every needs --trajectory FILE$" "$AMORPH" sim --scene cube:2 --every 10
expect_fail 2 "^amorph: sim: --trajectory-format needs --trajectory FILE$" "$AMORPH" sim --scene cube:2 --trajectory-format csv
expect_fail 2 "^amorph: sim: --every needs a whole number of steps, 1..1000000000$" "$AMORPH" sim --scene cube:2 --every 0 --trajectory "$TMPD/b.csv"
check "a bad flag left a file" [ ! -e "$TMPD/b.csv" ]
# an empty robot: no trajectory, an older file unchanged
printf 'amorph-lattice 1\nsize 2 2 1\nvoxel_size 0.01\nmaterial passive E=1e6 density=1000\nlayer 0\n..\n..\n' >"$TMPD/empty.lattice"
echo old >"$TMPD/old.csv"
expect_fail 2 "empty.lattice: the robot has no voxel" "$AMORPH" sim "$TMPD/empty.lattice" --trajectory "$TMPD/old.csv"
check "an empty robot changed the older file" [ "$(cat "$TMPD/old.csv")" = old ]
# an unwritable path: one line, exit 1, no file, no result printed
expect_fail 1 "nodir/t.csv" "$AMORPH" sim --scene cube:2 --trajectory "$TMPD/nodir/t.csv"
check "unwritable path: a result was printed" [ ! -s "$TMPD/out" ]
check "unwritable path: a file or folder was made" [ ! -e "$TMPD/nodir" ]
check "no temporary left beside the files" [ -z "$(ls "$TMPD" | grep '\.tmp')" ]
expect_ok "$AMORPH" sim --help
check "sim --help names --trajectory, --every, --trajectory-format and --scalars" \
    sh -c "grep -q -- '--trajectory FILE' '$TMPD/out' && grep -q -- '--every K' '$TMPD/out' && grep -q -- '--trajectory-format' '$TMPD/out' && grep -q -- '--scalars' '$TMPD/out'"

summary cli_trajectory.sh
