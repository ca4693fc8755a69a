# tests/cli_sim.sh: the `amorph sim` command: JSON output, divergence reporting, bad input.
# Run from the repository root: sh tests/cli_sim.sh
. tests/shlib.sh

# field NAME FILE: the value of a numeric JSON field in the one-line object in FILE
field() { sed -n "s/.*\"$1\": *\(-\{0,1\}[0-9][0-9.eE+-]*\).*/\1/p" "$2"; }
# check DESCRIPTION CONDITION...: ok when the shell test succeeds
check() { d=$1; shift; if "$@"; then ok; else ko "$d"; fi; }

# a normal run: every key, a 16-hex-digit hash, sane numbers
expect_ok "$AMORPH" sim --scene cube:4 --cycles 2 --json
cp "$TMPD/out" "$TMPD/cube"
check "one line of JSON: $(head -c 300 "$TMPD/cube")" [ "$(wc -l <"$TMPD/cube")" -eq 1 ]
for k in fitness dx dy dz voxels links dt steps relax_steps move_steps diverged settled sim_seconds wall_seconds; do
    v=$(field $k "$TMPD/cube")
    check "key $k missing or not a number in: $(head -c 300 "$TMPD/cube")" [ -n "$v" ]
done
check "hash is not 16 hex digits: $(head -c 300 "$TMPD/cube")" grep -qE '"hash": *"[0-9a-f]{16}"' "$TMPD/cube"
check "cube:4 has 64 voxels" [ "$(field voxels "$TMPD/cube")" = 64 ]
check "cube:4 has 144 links" [ "$(field links "$TMPD/cube")" = 144 ]
check "cube:4 diverged" [ "$(field diverged "$TMPD/cube")" = 0 ]
s=$(field steps "$TMPD/cube"); r=$(field relax_steps "$TMPD/cube"); m=$(field move_steps "$TMPD/cube")
check "steps $s != relax_steps $r + move_steps $m" [ "$s" -eq $((r + m)) ]
check "2 cycles of the default 500-step period should be 1000 move steps, got $m" [ "$m" -eq 1000 ]
check "passive cube: fitness should be >= 0, got $(field fitness "$TMPD/cube")" \
    awk -v f="$(field fitness "$TMPD/cube")" 'BEGIN { exit !(f >= 0) }'

# the name = value form carries the same hash
expect_ok "$AMORPH" sim --scene cube:4 --cycles 2
check "text output hash differs from JSON" grep -q "^hash = $(sed -n 's/.*"hash": *"\([0-9a-f]*\)".*/\1/p' "$TMPD/cube")\$" "$TMPD/out"

# options that change the run still succeed
expect_ok "$AMORPH" sim --scene cube:3 --cycles 1 --collisions off --json
expect_ok "$AMORPH" sim --scene cube:3 --cycles 1 --collisions on --json
expect_ok "$AMORPH" sim --scene sphere:6 --cycles 1 --dt-search --json
check "--dt-search run diverged: $(head -c 300 "$TMPD/out")" [ "$(field diverged "$TMPD/out")" = 0 ]
expect_ok "$AMORPH" sim --scene cube:3 --cycles 1 --dt 2e-5 --json
check "--dt 2e-5 not used: $(head -c 300 "$TMPD/out")" awk -v d="$(field dt "$TMPD/out")" 'BEGIN { exit !(d > 1.99e-5 && d < 2.01e-5) }'

# divergence is reported, not a crash: exit 0, diverged 1, fitness -1
expect_ok "$AMORPH" sim --scene cube:4 --dt 1 --json
check "--dt 1 should print \"diverged\": 1, got: $(head -c 300 "$TMPD/out")" grep -qE '"diverged": *1[,}]' "$TMPD/out"
check "--dt 1 should give fitness -1, got $(field fitness "$TMPD/out")" awk -v f="$(field fitness "$TMPD/out")" 'BEGIN { exit !(f == -1) }'

# bad input: exit 2 and one line on stderr
expect_fail 2 "." "$AMORPH" sim
expect_fail 2 "collisions" "$AMORPH" sim --scene cube:3 --collisions maybe
expect_fail 2 "dt" "$AMORPH" sim --scene cube:3 --dt -1
expect_fail 2 "dt" "$AMORPH" sim --scene cube:3 --dt 0
expect_fail 2 "cycles" "$AMORPH" sim --scene cube:3 --cycles many
# whole-token numbers only: blanks, signs and trailing text are refused, not half-read
expect_fail 2 "cycles" "$AMORPH" sim --scene cube:3 --cycles " 5"
expect_fail 2 "cycles" "$AMORPH" sim --scene cube:3 --cycles 5x
expect_fail 2 "amplitude" "$AMORPH" sim --scene cube:3 --amplitude nan
expect_fail 2 "seed" "$AMORPH" random --repr gmx --seed -3
expect_fail 2 "scene" "$AMORPH" sim --scene nosuch:3
expect_fail 2 "no-such-robot" "$AMORPH" sim "$TMPD/no-such-robot.lattice"
expect_fail 2 "unknown option" "$AMORPH" sim --scene cube:3 --bogus
expect_ok "$AMORPH" sim --help

# an empty body is a valid robot: zero fitness, flagged, exit 0, no simulation
printf 'amorph-lattice 1\nsize 3 2 1\nlayer 0\n...\n...\n' >"$TMPD/empty.lattice"
expect_ok "$AMORPH" sim "$TMPD/empty.lattice" --json
check "empty body not flagged with zero fitness: $(head -c 300 "$TMPD/out")" grep -q '"fitness": 0, "voxels": 0, "links": 0, "empty": 1' "$TMPD/out"

# --- amorph bench: figures, not timings asserted ---
expect_ok "$AMORPH" bench --scene cube:3 --steps 40 --collisions off
check "bench line: $(head -c 300 "$TMPD/out")" grep -qE '^scene=cube:3 collisions=off voxels=27 links=54 steps=40 .*voxel_steps_per_s=[0-9.e+]+ .*diverged=0$' "$TMPD/out"
# the product kernels compute the same polynomial in float and in Q24: their sums agree to the
# fixed-point resolution (2048 values of magnitude below 2)
expect_ok "$AMORPH" bench --kernels
sf=$(sed -n 's/^kernel=horner8 real=float .*sum=\([-0-9.]*\)$/\1/p' "$TMPD/out")
sq=$(sed -n 's/^kernel=horner8 real=q24 .*sum=\([-0-9.]*\)$/\1/p' "$TMPD/out")
check "kernel sums missing or apart: float '$sf' q24 '$sq'" awk -v a="$sf" -v b="$sq" 'BEGIN { d = a - b; exit !(a != "" && b != "" && a > 1 && d < 1e-3 && d > -1e-3) }'
check "kernel ratio line: $(head -c 300 "$TMPD/out")" grep -qE '^kernel=horner8 q24_time_over_float=[0-9.]+$' "$TMPD/out"
# --repeat: every run's line, then best >= median >= worst of them
expect_ok "$AMORPH" bench --scene cube:3 --steps 40 --collisions on --repeat 3
check "three runs: $(head -c 300 "$TMPD/out")" [ "$(grep -c '^scene=cube:3 collisions=on voxels=27' "$TMPD/out")" -eq 3 ]
check "summary: $(tail -n 1 "$TMPD/out")" awk '/^scene=cube:3 collisions=on runs=3 / { for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] + 0 }
    ok = v["best_voxel_steps_per_s"] >= v["median_voxel_steps_per_s"] && v["median_voxel_steps_per_s"] >= v["worst_voxel_steps_per_s"] && v["worst_voxel_steps_per_s"] > 0; n++ }
    END { exit !(n == 1 && ok) }' "$TMPD/out"
expect_fail 2 "bench: --repeat needs a whole number from 1 to 64" "$AMORPH" bench --repeat 65
expect_fail 2 "bench: unknown option '--kernel'" "$AMORPH" bench --kernel
expect_fail 2 "bench: --steps needs a whole number" "$AMORPH" bench --steps 0

summary cli_sim
