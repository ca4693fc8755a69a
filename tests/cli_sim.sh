# tests/cli_sim.sh: the `amorph sim` command: JSON output, relaxation diagnostics, divergence and
# settling warnings, bad input; `amorph bench` figures; the evolver's release_steps key.
# Run from the repository root: sh tests/cli_sim.sh
. tests/shlib.sh

# field NAME FILE: the value of a numeric JSON field in the one-line object in FILE
field() { sed -n "s/.*\"$1\": *\(-\{0,1\}[0-9][0-9.eE+-]*\).*/\1/p" "$2"; }
# check DESCRIPTION CONDITION...: ok when the shell test succeeds
# tval NAME FILE: the value of a `name = value` line in FILE
tval() { sed -n "s/^$1 = //p" "$2"; }
# isnum V: V is one decimal number (sign, digits, point, exponent), as printf %g or %ld writes it
isnum() { echo "$1" | grep -qE '^-?[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?$'; }
# isint V: V is a whole number >= 0
isint() { echo "$1" | grep -qE '^[0-9]+$'; }
# awkt DESCRIPTION EXPR -v NAME=VALUE...: ok when the awk expression over the named values holds
awkt() { ad=$1; ae=$2; shift 2; if awk "$@" "BEGIN { exit !($ae) }"; then ok; else ko "$ad"; fi; }
# lines FILE: its line count
lines() { wc -l <"$1" | tr -d ' '; }

# a normal run: every key, a 16-hex-digit hash, sane numbers
expect_ok "$AMORPH" sim --scene cube:4 --cycles 2 --json
cp "$TMPD/out" "$TMPD/cube"
check "one line of JSON: $(head -c 300 "$TMPD/cube")" [ "$(wc -l <"$TMPD/cube")" -eq 1 ]
for k in fitness dx dy dz voxels links dt steps relax_steps move_steps diverged settled residual_speed kinetic_resets \
         sim_seconds wall_seconds; do
    v=$(field $k "$TMPD/cube")
    check "key $k missing or not a number in: $(head -c 300 "$TMPD/cube")" isnum "$v"
done
check "kinetic_resets not a whole number: $(head -c 300 "$TMPD/cube")" isint "$(field kinetic_resets "$TMPD/cube")"
# the gait (docs/results.md, Gaits): a travel per cycle, the halves, and one of the four names
for k in travel_first_half travel_last_half sustained airborne lift; do
    check "gait key $k missing or not a number in: $(head -c 600 "$TMPD/cube")" isnum "$(field $k "$TMPD/cube")"
done
check "cycle_travel of 2 cycles: $(head -c 600 "$TMPD/cube")" grep -qE '"cycle_travel": \[[-0-9.e]+, [-0-9.e]+\]' "$TMPD/cube"
check "gait name: $(head -c 600 "$TMPD/cube")" grep -qE '"gait": "(still|flop|scoot|bounce)"}$' "$TMPD/cube"
# the same fields as text
expect_ok "$AMORPH" sim --scene cube:4 --cycles 3
check "text cycle_travel of 3 cycles: $(grep cycle_travel "$TMPD/out")" grep -qE '^cycle_travel = [-0-9.e]+ [-0-9.e]+ [-0-9.e]+$' "$TMPD/out"
check "text gait: $(grep gait "$TMPD/out")" grep -qE '^gait = (still|flop|scoot|bounce)$' "$TMPD/out"
# a still body: no actuation, nothing travels
expect_ok "$AMORPH" sim --scene cube:4 --cycles 4 --amplitude 0 --json
check "unactuated cube should be still: $(head -c 600 "$TMPD/out")" grep -qE '"gait": "still"' "$TMPD/out"
check "hash is not 16 hex digits: $(head -c 300 "$TMPD/cube")" grep -qE '"hash": *"[0-9a-f]{16}"' "$TMPD/cube"
check "cube:4 has 64 voxels" [ "$(field voxels "$TMPD/cube")" = 64 ]
check "cube:4 has 144 links" [ "$(field links "$TMPD/cube")" = 144 ]
check "cube:4 diverged" [ "$(field diverged "$TMPD/cube")" = 0 ]
s=$(field steps "$TMPD/cube"); r=$(field relax_steps "$TMPD/cube"); m=$(field move_steps "$TMPD/cube")
check "steps $s != relax_steps $r + move_steps $m" [ "$s" -eq $((r + m)) ]
check "2 cycles of the default 500-step period should be 1000 move steps, got $m" [ "$m" -eq 1000 ]
check "passive cube: fitness should be >= 0, got $(field fitness "$TMPD/cube")" \
    awk -v f="$(field fitness "$TMPD/cube")" 'BEGIN { exit !(f >= 0) }'

# the name = value form carries the same hash, and the same relaxation diagnostics
expect_ok "$AMORPH" sim --scene cube:4 --cycles 2
cp "$TMPD/out" "$TMPD/cube.txt"
check "text output hash differs from JSON" grep -q "^hash = $(sed -n 's/.*"hash": *"\([0-9a-f]*\)".*/\1/p' "$TMPD/cube")\$" "$TMPD/out"
for k in relax_steps settled residual_speed kinetic_resets; do
    v=$(tval $k "$TMPD/cube.txt")
    check "line '$k = NUMBER' missing: $(tr '\n' ' ' <"$TMPD/cube.txt" | head -c 400)" isnum "$v"
    check "$k: text '$v', JSON '$(field $k "$TMPD/cube")'" [ "$v" = "$(field $k "$TMPD/cube")" ]
done

# a passive cube resting on the floor settles: settled = 1, nothing on stderr; residual_speed is
# the largest RMS speed through the release window, so below settle_speed (1e-3 m/s), and the
# relaxation lasted at least that window (500 steps)
check "cube:4 did not settle: $(head -c 300 "$TMPD/cube")" [ "$(field settled "$TMPD/cube")" = 1 ]
check "settled run wrote on stderr: $(head -c 300 "$TMPD/err")" [ ! -s "$TMPD/err" ]
awkt "settled, yet residual_speed $(field residual_speed "$TMPD/cube") is not in [0, 1e-3)" 'r >= 0 && r < 1e-3' \
    -v r="$(field residual_speed "$TMPD/cube")"
awkt "settled after $(field relax_steps "$TMPD/cube") relaxation steps, fewer than the release window (500)" 'n >= 500' \
    -v n="$(field relax_steps "$TMPD/cube")"
expect_ok "$AMORPH" sim --scene cube:4 --cycles 1 --release-steps 1500 --json
if [ "$(field settled "$TMPD/out")" = 1 ]; then
    awkt "--release-steps 1500: settled after $(field relax_steps "$TMPD/out") relaxation steps" 'n >= 1500' -v n="$(field relax_steps "$TMPD/out")"
else
    check "--release-steps 1500: not settled, yet no warning: $(head -c 300 "$TMPD/err")" grep -q "did not settle" "$TMPD/err"
fi
# a release window longer than the relaxation can never end: not settled, whatever the physics
expect_ok "$AMORPH" sim --scene cube:3 --cycles 1 --relax-max 300 --release-steps 1000 --json
check "--relax-max 300 --release-steps 1000 settled: $(head -c 300 "$TMPD/out")" [ "$(field settled "$TMPD/out")" = 0 ]

# a run that cannot settle (--relax-max 10): a result, not an error: exit 0, settled = 0, the full
# output on stdout, exactly one warning line on stderr, in both forms
for form in --json ""; do
    "$AMORPH" sim --scene cube:4 --cycles 1 --relax-max 10 $form >"$TMPD/out" 2>"$TMPD/err"; rc=$?
    check "--relax-max 10 $form: exit $rc" [ $rc -eq 0 ]
    if [ -n "$form" ]; then sv=$(field settled "$TMPD/out"); rv=$(field relax_steps "$TMPD/out"); dv=$(field diverged "$TMPD/out")
    else sv=$(tval settled "$TMPD/out"); rv=$(tval relax_steps "$TMPD/out"); dv=$(tval diverged "$TMPD/out"); fi
    check "--relax-max 10 $form: settled '$sv', want 0" [ "$sv" = 0 ]
    check "--relax-max 10 $form: relax_steps '$rv', want 10" [ "$rv" = 10 ]
    check "--relax-max 10 $form: diverged '$dv', want 0" [ "$dv" = 0 ]
    check "--relax-max 10 $form: want one stderr line, got $(lines "$TMPD/err"): $(head -c 300 "$TMPD/err")" [ "$(lines "$TMPD/err")" -eq 1 ]
    check "--relax-max 10 $form: warning: $(head -c 300 "$TMPD/err")" \
        grep -qE '^amorph: sim: warning: cube:4 did not settle within 10 relaxation steps \(residual speed [-0-9.e+]+ m/s' "$TMPD/err"
done

# options that change the run still succeed
expect_ok "$AMORPH" sim --scene cube:3 --cycles 1 --collisions off --json
expect_ok "$AMORPH" sim --scene cube:3 --cycles 1 --collisions on --json
expect_ok "$AMORPH" sim --scene sphere:6 --cycles 1 --dt-search --json
check "--dt-search run diverged: $(head -c 300 "$TMPD/out")" [ "$(field diverged "$TMPD/out")" = 0 ]
expect_ok "$AMORPH" sim --scene cube:3 --cycles 1 --dt 2e-5 --json
check "--dt 2e-5 not used: $(head -c 300 "$TMPD/out")" awk -v d="$(field dt "$TMPD/out")" 'BEGIN { exit !(d > 1.99e-5 && d < 2.01e-5) }'

# divergence is reported, not a crash: exit 0, diverged 1, fitness -1
expect_ok "$AMORPH" sim --scene cube:4 --dt 5e-4 --json
check "--dt 5e-4 should print \"diverged\": 1, got: $(head -c 300 "$TMPD/out")" grep -qE '"diverged": *1[,}]' "$TMPD/out"
check "--dt 5e-4 should give fitness -1, got $(field fitness "$TMPD/out")" awk -v f="$(field fitness "$TMPD/out")" 'BEGIN { exit !(f == -1) }'
check "--dt 5e-4 diverged: settled should be 0: $(head -c 300 "$TMPD/out")" [ "$(field settled "$TMPD/out")" = 0 ]
check "--dt 5e-4: JSON with nan or inf: $(head -c 600 "$TMPD/out")" sh -c "! grep -qiE 'nan|inf' '$TMPD/out'"
check "--dt 5e-4: gait should be diverged: $(head -c 600 "$TMPD/out")" grep -qE '"gait": "diverged"' "$TMPD/out"
# and said once on stderr (diverged, not also "did not settle"), beside the note that a step this
# long (9.9 dt_rec, near the top of dt_frac's range) makes the 500-step period 0.25 s
check "--dt 5e-4: want one warning, got $(grep -c warning "$TMPD/err"): $(head -c 300 "$TMPD/err")" [ "$(grep -c warning "$TMPD/err")" -eq 1 ]
check "--dt 5e-4: warning: $(head -c 300 "$TMPD/err")" grep -qE '^amorph: sim: warning: cube:4 diverged at step [0-9]+, in the relaxation \(fitness -1\)$' "$TMPD/err"
check "--dt 5e-4: note: $(head -c 300 "$TMPD/err")" grep -qE '^amorph: note: at this step the actuation period is 500 steps = 0.25 s, ' "$TMPD/err"

# the period in seconds (docs/evolve.md): --dt_frac alone keeps 500 steps and says that the period
# changed; --period_s holds it, and the relaxation's step counts scale with the step by themselves
"$AMORPH" sim --scene halfbar:6 --cycles 1 --dt_frac 0.3 --json >"$TMPD/out" 2>"$TMPD/err"
check "--dt_frac 0.3: period_steps $(field period_steps "$TMPD/out"), want 500" [ "$(field period_steps "$TMPD/out")" = 500 ]
check "--dt_frac 0.3: note: $(head -c 300 "$TMPD/err")" \
    grep -qxE 'amorph: note: at this step the actuation period is 500 steps = 0.007549 s, not the robot.s own 0.02265 s \(--period_s 0.02265 holds it in seconds\)' "$TMPD/err"
"$AMORPH" sim --scene halfbar:6 --cycles 1 --json >"$TMPD/own.json" 2>"$TMPD/err"
check "default step: no note: $(head -c 300 "$TMPD/err")" [ "$(lines "$TMPD/err")" -eq 0 ]
"$AMORPH" sim --scene halfbar:6 --cycles 1 --dt_frac 0.3 --period_s 0.02265 --json >"$TMPD/out" 2>"$TMPD/err"
check "--period_s held: no note: $(head -c 300 "$TMPD/err")" [ "$(lines "$TMPD/err")" -eq 0 ]
check "--period_s 0.02265 at 0.3: period_steps $(field period_steps "$TMPD/out"), want 1500" [ "$(field period_steps "$TMPD/out")" = 1500 ]
check "--period_s: the period in seconds" awk -v a="$(field period_s "$TMPD/out")" -v b="$(field period_s "$TMPD/own.json")" \
    'BEGIN { exit !(a / b > 0.9999 && a / b < 1.0001) }'
check "--dt_frac 0.3: the relaxation in seconds ($(field relax_steps "$TMPD/out") steps against $(field relax_steps "$TMPD/own.json"))" \
    awk -v a="$(field relax_steps "$TMPD/out")" -v b="$(field relax_steps "$TMPD/own.json")" 'BEGIN { exit !(a > 2.5 * b && a < 3.5 * b) }'
# the same physics at both steps: the half bar's travel within 5% (docs/physics.md, Time step)
check "--period_s: travel $(field travel "$TMPD/out") at 0.3, $(field travel "$TMPD/own.json") at 0.9" \
    awk -v a="$(field travel "$TMPD/out")" -v b="$(field travel "$TMPD/own.json")" 'BEGIN { d = a / b - 1; exit !(d > -0.05 && d < 0.05) }'
# a later --period_steps wins over a period in seconds
"$AMORPH" sim --scene halfbar:6 --cycles 1 --period_s 0.02265 --period_steps 300 --json >"$TMPD/out" 2>/dev/null
check "--period_steps after --period_s: $(field period_steps "$TMPD/out")" [ "$(field period_steps "$TMPD/out")" = 300 ]
expect_fail 2 "^amorph: sim: --period_s = '-1': expected a number in \[0, 10000\]$" "$AMORPH" sim --scene cube:3 --period_s -1
expect_fail 2 "^amorph: --period_s = 10000 s is .* steps of .* s \(a period takes 2 to 10\^7 steps\)$" "$AMORPH" sim --scene cube:3 --period_s 10000
# issue 46: a period of 2 to 10^7 steps however it is given, and one bound on every evaluation
# (10^9 steps, docs/physics.md), refused before any step in one line that names the flag (timeout:
# the builds before ran these for ever)
expect_fail 2 "^amorph: --period_s = 1e-09 s is .* steps of .* s \(a period takes 2 to 10\^7 steps\)$" \
    timeout -k 5 60 "$AMORPH" sim --scene cube:3 --period_s 1e-9
expect_fail 2 "^amorph: --period_steps = 10000000: up to 1e\+12 steps an evaluation \(2 relaxations of 4e\+04: relax_max_steps 40000 at 0.9 dt_rec; 100000 cycles of 1e\+07\), over the budget of 1e\+09 \(docs/physics.md\)$" \
    timeout -k 5 60 "$AMORPH" sim --scene cube:2 --cycles 100000 --period_steps 10000000
expect_fail 2 "^amorph: --dt_frac = 1e-06: up to 1.8e\+14 steps an evaluation .*relax_max_steps 100000000 at 1e-06 dt_rec" \
    timeout -k 5 60 "$AMORPH" sim --scene cube:2 --dt_frac 1e-6 --relax_max_steps 100000000 --settle_speed 0
expect_fail 2 "^amorph: --dt 1e-12: is .* of this robot's dt_rec \(.* s\), outside dt_frac's range \[1e-06, 10\]$" \
    timeout -k 5 60 "$AMORPH" sim --scene cube:2 --dt 1e-12
expect_fail 2 "^amorph: --dt_search = on: up to .* steps an evaluation \(the search, 2 relaxations .* a searched step down to 9.5e-05 dt_rec" \
    timeout -k 5 60 "$AMORPH" sim --scene cube:2 --dt-search --relax_max_steps 1000000
expect_fail 2 "^amorph: render: --period_steps = 10000000: up to 1e\+12 steps an evaluation" \
    timeout -k 5 60 "$AMORPH" render --scene cube:2 --cycles 100000 --period_steps 10000000 --out "$TMPD/long.png"
check "a refused render writes no picture" [ ! -e "$TMPD/long.png" ]
expect_fail 2 "bench: --dt-frac needs a number in \[1e-6, 10\] \(the key dt_frac's range\)" "$AMORPH" bench --dt-frac 50
# a run folder's config.txt over the budget: its line named
if [ -d results/representations/gmx-1 ]; then
    cp -r results/representations/gmx-1 "$TMPD/longrun"
    sed -i 's/^cycles = 10$/cycles = 100000/; s/^period_steps = 500$/period_steps = 10000000/' "$TMPD/longrun/config.txt"
    expect_fail 2 "^amorph: $TMPD/longrun/config.txt:10: period_steps = 10000000: up to 1e\+12 steps an evaluation \([12] relaxations? of" \
        timeout -k 5 60 "$AMORPH" sim "$TMPD/longrun"
fi
# an evolution whose relaxation cannot hold the release window would score nothing: refused
expect_fail 2 "^amorph: evolve: relax_max_steps = 300 leaves no room to settle: the release window \(release_steps = 500\) and 50 calm steps need 550" \
    "$AMORPH" evolve --workspace 4 --population 2 --evaluations 2 --relax-max-steps 300 --out "$TMPD/nosettle" --quiet
check "a refused run makes no folder" [ ! -e "$TMPD/nosettle" ]

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
# a misspelt flag: the nearest of the command's flags (its help's, and the configuration's keys)
expect_fail 2 "^amorph: sim: unknown option '--trajectry': did you mean --trajectory\? \(amorph sim --help\)$" "$AMORPH" sim --scene cube:3 --trajectry x
expect_fail 2 "^amorph: sim: unknown option '--cycels': did you mean --cycles\? \(amorph sim --help\)$" "$AMORPH" sim --scene cube:3 --cycels 2
expect_fail 2 "^amorph: evolve: unknown option '--populaton': did you mean --population\? " "$AMORPH" evolve --populaton 4
expect_fail 2 "^amorph: render: unknown option '--colur': did you mean --colour\? " "$AMORPH" render --scene cube:2 --colur strain
expect_fail 2 "^amorph: export: unknown option '--latice': did you mean --lattice\? " "$AMORPH" export --scene cube:2 --latice x
expect_fail 2 "^amorph: sim: unknown option '--bogus' \(amorph sim --help\)$" "$AMORPH" sim --scene cube:3 --bogus
# a folder that is no robot: what it is and what a robot is, not "not a regular file"
mkdir -p "$TMPD/plain" "$TMPD/half"; : >"$TMPD/plain/notes.txt"; : >"$TMPD/half/config.txt"
expect_fail 2 "^amorph: $TMPD/plain: a folder, neither a run folder \(config.txt, best.genome: neither\) nor a voxcraft folder .*; a robot is a lattice, genome or VXA file, a run or voxcraft folder, or --scene NAME$" "$AMORPH" sim "$TMPD/plain"
expect_fail 2 "^amorph: render: $TMPD/half: a folder, neither a run folder \(config.txt, best.genome: no best.genome yet\)" "$AMORPH" render "$TMPD/half" --out "$TMPD/x.png"
# the command list says what each command takes
"$AMORPH" --help >"$TMPD/help" 2>&1
check "amorph --help's sim, random and export lines: $(grep -E '^  (sim|random|export) ' "$TMPD/help")" sh -c \
    "grep -q '^  sim .*VXA file, a run or voxcraft folder, or --scene' '$TMPD/help' && grep -q '^  random .*--representation dct|cppn|gmx' '$TMPD/help' && grep -q '^  export .*run folder or --scene.*STL/AMF' '$TMPD/help'"
# --release-steps: a whole number 0..1e8, checked by the configuration table as evolve checks it
for bad in x -1 100000001 " 5" 5x 1e3 ""; do
    expect_fail 2 "^amorph: sim: --release_steps = '.*': expected an integer in \[0, 100000000\]$" "$AMORPH" sim --scene cube:3 --release-steps "$bad"
done
expect_fail 2 "^amorph: sim: --release-steps needs a value$" "$AMORPH" sim --scene cube:3 --release-steps
expect_fail 2 "^amorph: sim: --relax_max_steps = '-1': expected an integer" "$AMORPH" sim --scene cube:3 --relax-max -1
expect_ok "$AMORPH" sim --scene cube:3 --cycles 1 --release-steps 0 --json
check "--release-steps 0: $(head -c 300 "$TMPD/out")" isnum "$(field residual_speed "$TMPD/out")"
expect_ok "$AMORPH" sim --help

# an empty body is a valid robot: zero fitness, flagged, exit 0, no simulation
printf 'amorph-lattice 1\nsize 3 2 1\nlayer 0\n...\n...\n' >"$TMPD/empty.lattice"
expect_ok "$AMORPH" sim "$TMPD/empty.lattice" --json
check "empty body not flagged with zero fitness: $(head -c 300 "$TMPD/out")" grep -q '"fitness": 0, "voxels": 0, "links": 0, "empty": 1' "$TMPD/out"

# --- amorph bench: figures, not timings asserted ---
expect_ok "$AMORPH" bench --scene cube:3 --steps 40 --collisions off
check "bench line: $(head -c 300 "$TMPD/out")" grep -qE '^scene=cube:3 collisions=off voxels=27 links=54 steps=40 .*voxel_steps_per_s=[0-9.e+]+ .*diverged=0$' "$TMPD/out"
# simulated seconds per wall second beside it, at the default step (dt_frac): steps * dt / wall
# time = voxel_steps_per_s * dt_s / voxels
check "bench: sim_s_per_s and dt_frac: $(head -c 300 "$TMPD/out")" awk '/^scene=cube:3 / { for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
    n++; s = v["sim_s_per_s"] + 0; e = v["voxel_steps_per_s"] * v["dt_s"] / v["voxels"]
    ok = v["sim_s_per_s"] ~ /^[0-9.e+-]+$/ && s > 0 && v["dt_frac"] > 0 && v["dt_s"] > 0 && s > 0.999 * e && s < 1.001 * e }
    END { exit !(n == 1 && ok) }' "$TMPD/out"
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
check "summary, sim_s_per_s: $(tail -n 1 "$TMPD/out")" awk '/^scene=cube:3 collisions=on runs=3 / { for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] + 0 }
    ok = v["best_sim_s_per_s"] >= v["median_sim_s_per_s"] && v["median_sim_s_per_s"] >= v["worst_sim_s_per_s"] && v["worst_sim_s_per_s"] > 0; n++ }
    END { exit !(n == 1 && ok) }' "$TMPD/out"
expect_fail 2 "bench: --repeat needs a whole number from 1 to 64" "$AMORPH" bench --repeat 65
# bench --evals N stands on either side of --evolve: a count below the population is refused before
# any evaluation, naming the count the runs would take (--evolve's 60 would run for minutes)
for order in "--evals 2 --evolve" "--evolve --evals 2"; do
    # shellcheck disable=SC2086
    expect_fail 2 "^amorph: bench: evaluations = 2: at least the population \\(20\\)$" timeout -k 5 60 "$AMORPH" bench $order --threads 1
done
expect_fail 2 "bench: unknown option '--kernel'" "$AMORPH" bench --kernel
expect_fail 2 "bench: --steps needs a whole number" "$AMORPH" bench --steps 0
# bench --convergence takes a VXA robot with its layers (per-voxel phases, stiffnesses): at its own
# step each robot travels what amorph sim says it does (the two files share their lattice and
# differ only in their layers)
"$AMORPH" bench --convergence --random 0 --threads 2 tests/data/evosoro_phase.vxa tests/data/evosoro_stiffness.vxa >"$TMPD/conv" 2>/dev/null
for f in evosoro_phase evosoro_stiffness; do
    t=$("$AMORPH" sim "tests/data/$f.vxa" 2>/dev/null | sed -n 's/^travel = //p')
    check "bench --convergence: $f.vxa's default_mm is sim's travel $t m: $(grep "$f" "$TMPD/conv")" \
        awk -v t="$t" -v f="tests/data/$f.vxa" '$1 == f { d = $3 - 1000 * t; n++; ok = t > 0.001 && (d < 0 ? -d : d) < 1e-4 } END { exit !(n == 1 && ok) }' "$TMPD/conv"
done

# --- the evolver's release_steps key (docs/evolve.md): a config key and a flag, 0..1e8 ---
expect_ok "$AMORPH" evolve --help-config
check "--help-config lists release_steps 500: $(grep release "$TMPD/out")" grep -qE '^ +release_steps +500 ' "$TMPD/out"
expect_ok "$AMORPH" evolve --print-config --release-steps 7
check "--release-steps 7 not in the configuration: $(grep release "$TMPD/out")" grep -qx 'release_steps = 7' "$TMPD/out"
expect_fail 2 "release_steps = '-1': expected an integer in \[0, 100000000\]" "$AMORPH" evolve --print-config --release-steps -1
expect_fail 2 "release_steps = '100000001'" "$AMORPH" evolve --print-config --release-steps 100000001
expect_fail 2 "relax_min_steps = 500 exceeds relax_max_steps = 100" "$AMORPH" evolve --print-config --relax-min-steps 500 --relax-max-steps 100
# a run folder's release_steps reaches amorph sim, and --release-steps overrides it: a window
# longer than the relaxation never ends; the flag back at the default gives the default run
mkdir -p "$TMPD/run"
expect_ok "$AMORPH" random --repr gmx --size 4 --seed 7 --out "$TMPD/run/best.genome"
"$AMORPH" evolve --print-config --workspace 4 --relax-max-steps 2000 >"$TMPD/run/config.txt"
"$AMORPH" sim "$TMPD/run" --cycles 1 --json >"$TMPD/def.json" 2>/dev/null
"$AMORPH" evolve --print-config --workspace 4 --relax-max-steps 2000 --release-steps 100000000 >"$TMPD/run/config.txt"
expect_ok "$AMORPH" sim "$TMPD/run" --cycles 1 --json
check "run's release_steps 1e8: settled, or not 2000 steps: $(head -c 300 "$TMPD/out")" \
    [ "$(field settled "$TMPD/out")/$(field relax_steps "$TMPD/out")" = 0/2000 ]
check "run's release_steps 1e8: want one warning, got: $(head -c 300 "$TMPD/err")" [ "$(lines "$TMPD/err")" -eq 1 ]
expect_ok "$AMORPH" sim "$TMPD/run" --cycles 1 --json --release-steps 500
h1=$(sed -n 's/.*"hash": *"\([0-9a-f]*\)".*/\1/p' "$TMPD/def.json"); h2=$(sed -n 's/.*"hash": *"\([0-9a-f]*\)".*/\1/p' "$TMPD/out")
check "--release-steps 500 over the run's 1e8 is not the default run: '$h1' vs '$h2'" [ "${h1:-none}" = "$h2" ]

# --- one vocabulary: sim, render, view, export take the configuration keys (tools/robot.h) ---
hash_of() { sed -n 's/.*"hash": *"\([0-9a-f]*\)".*/\1/p' "$1"; }
"$AMORPH" sim --scene cube:3 --cycles 1 --relax-max 200 --period_steps 300 --json >"$TMPD/a.json" 2>/dev/null
for spelling in "--period-steps 300" "--period_steps=300" "--period-steps=300"; do
    expect_ok "$AMORPH" sim --scene cube:3 --cycles 1 --relax_max_steps 200 $spelling --json
    check "$spelling is --period_steps 300: $(hash_of "$TMPD/out") vs $(hash_of "$TMPD/a.json")" [ "$(hash_of "$TMPD/out")" = "$(hash_of "$TMPD/a.json")" ]
done
# flags in order: the last of two settings of a key wins
expect_ok "$AMORPH" sim --scene cube:3 --cycles 1 --relax-max 200 --period_steps 999 --period_steps 300 --json
check "the later --period_steps wins" [ "$(hash_of "$TMPD/out")" = "$(hash_of "$TMPD/a.json")" ]
# the same ranges and messages as evolve's configuration
"$AMORPH" evolve --print-config --gravity 5000 2>"$TMPD/evolve.err"
expect_fail 2 "^amorph: sim: --gravity = '5000': expected a number in \[0, 1000\]$" "$AMORPH" sim --scene cube:3 --gravity 5000
check "sim and evolve word a bad gravity alike" [ "$(sed 's/^amorph: evolve: //' "$TMPD/evolve.err")" = "$(sed 's/^amorph: sim: //' "$TMPD/err")" ]
expect_fail 2 "^amorph: sim: --period_steps = '1': expected an integer in \[2, " "$AMORPH" sim --scene cube:3 --period-steps 1
expect_fail 2 "^amorph: sim: --amplitude = '-5': expected a number in \[0, " "$AMORPH" sim --scene cube:3 --amplitude -5
expect_fail 2 "^amorph: sim: --cte linear: the CTE convention is --cte_mode volumetric\|linear" "$AMORPH" sim --scene cube:3 --cte linear
expect_fail 2 "^amorph: sim: --cte volume: the CTE convention is --cte_mode" "$AMORPH" sim --scene cube:3 --cte volume
expect_fail 2 "^amorph: render: --population is a setting of an evolution, not of one robot" "$AMORPH" render --scene cube:3 --population 4 --out "$TMPD/x.png"
expect_fail 2 "^amorph: export: --seed is a setting of an evolution" "$AMORPH" export --scene cube:3 --seed 4 --lattice -
# --cte_mode, --floor, --dt_search on: what the old flags did
expect_ok "$AMORPH" sim --scene cube:3 --cycles 1 --relax-max 200 --cte_mode linear --floor off --json
check "--floor off: the cube falls (dz $(field dz "$TMPD/out"))" awk -v z="$(field dz "$TMPD/out")" 'BEGIN { exit !(z < -0.001) }'
"$AMORPH" sim --scene cube:3 --cycles 1 --relax-max 200 --dt-search --json >"$TMPD/b.json" 2>/dev/null
expect_ok "$AMORPH" sim --scene cube:3 --cycles 1 --relax-max 200 --dt_search on --json
check "--dt-search alone is --dt_search on" [ "$(hash_of "$TMPD/out")" = "$(hash_of "$TMPD/b.json")" ]
# file first, then flags: a run folder's friction, changed by --mu_static, changes the result;
# set back to the run's own value it gives the run's result again
expect_ok "$AMORPH" sim "$TMPD/run" --cycles 1 --json --mu_static 0.05 --mu_kinetic 0.01
check "--mu_static/--mu_kinetic over a run folder change its result" [ "$(hash_of "$TMPD/out")" != "$(hash_of "$TMPD/def.json")" ]
"$AMORPH" evolve --print-config --workspace 4 --relax-max-steps 2000 >"$TMPD/run/config.txt"
expect_ok "$AMORPH" sim "$TMPD/run" --cycles 1 --json --mu_static 1 --mu_kinetic 0.3
check "the run's own friction as flags: the run's result" [ "$(hash_of "$TMPD/out")" = "$(hash_of "$TMPD/def.json")" ]
# evolve takes the same aliases
expect_ok "$AMORPH" evolve --print-config --repr dct --size 4 --relax-max 3000 --dt-search --evals 30
check "evolve: --repr/--size/--relax-max/--dt-search/--evals are aliases: $(grep -E '^(representation|workspace|relax_max_steps|dt_search|evaluations) ' "$TMPD/out" | tr '\n' ' ')" \
    [ "$(grep -cxE 'representation = dct|workspace = 4|relax_max_steps = 3000|dt_search = on|evaluations = 30' "$TMPD/out")" = 5 ]

# tokens in the commands' messages are quoted as the readers quote them (am_quote): control bytes
# escaped, cut at 40 characters with "..."
long=$(printf 'x%.0s' $(seq 1 300))
for cmd in sim render view export random express evolve experiment plot bench repro report; do
    "$AMORPH" $cmd "--bo$(printf '\033')[31mgus" >/dev/null 2>"$TMPD/err"
    check "$cmd: an escape byte in an unknown option is escaped: $(od -c "$TMPD/err" | head -3)" grep -q "unknown option '--bo\\\\x1b\[31mgus'" "$TMPD/err"
    check "$cmd: no raw control byte in the message" sh -c "! LC_ALL=C grep -q '[[:cntrl:]]' \"\$1\"" _ "$(tr -d '\n' <"$TMPD/err" >"$TMPD/err1"; echo "$TMPD/err1")"
done
expect_fail 2 "^amorph: sim: unknown option '--x{38}\.\.\.' \(amorph sim --help\)$" "$AMORPH" sim "--$long"
expect_fail 2 "^amorph: sim: one robot at a time \('a' and 'b\\\\tc'\)$" "$AMORPH" sim a "$(printf 'b\tc')"
expect_fail 2 "^amorph: unknown command 'x{40}\.\.\.' " "$AMORPH" "$long"

# the material mix: the materials the body holds and their voxels, adding up to the body
expect_ok "$AMORPH" sim --scene sphere:6 --cycles 1 --relax-max 100
check "sphere:6 is half passive, half active: $(grep material "$TMPD/out" | tr '\n' ' ')" \
    [ "$(sed -n 's/^materials = //p' "$TMPD/out")/$(sed -n 's/^material_voxels = //p' "$TMPD/out")" = "passive active/68 68" ]
expect_ok "$AMORPH" sim "$TMPD/run" --cycles 1 --json
check "a run's best robot: material voxels add up to its voxels: $(head -c 400 "$TMPD/out")" awk -v v="$(field voxels "$TMPD/out")" \
    -v m="$(sed -n 's/.*"material_voxels": \[\([^]]*\)\].*/\1/p' "$TMPD/out")" 'BEGIN { n = split(m, a, ", "); s = 0; for (i = 1; i <= n; i++) s += a[i]; exit !(n >= 1 && s == v && v > 0) }'

summary cli_sim
