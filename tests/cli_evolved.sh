# tests/cli_evolved.sh: bodies and their actuation evolved together (docs/genotypes.md, Evolved
# actuation): runs with actuation = phase and stiffness = evolved in every representation are the
# same for one and two threads, their config.txt names the keys (the seed's runs still do not),
# the run folder, its best genome and its exported VXA file replay the logged best (the phases and
# stiffnesses reach the simulator every way; a genome file alone in the range --stiffness_min and
# --stiffness_max give), --lattice says what it leaves out, a run resumes
# after kill -9 exactly like the uninterrupted run, bad settings are refused in one line, and the
# board refuses the setting in one line. Run from the repository root.
. tests/shlib.sh

small_cfg "$TMPD/small.cfg"
E="$AMORPH evolve --quiet --no-pictures"

# --- the default writes none of the keys ---
"$AMORPH" evolve --print-config >"$TMPD/def.txt"
if ! grep -q "^actuation\|^stiffness" "$TMPD/def.txt"; then ok; else ko "the default configuration names $(grep '^actuation\|^stiffness' "$TMPD/def.txt")"; fi

cp "$TMPD/small.cfg" "$TMPD/ev.cfg"
printf '%s\n' "actuation = phase" "stiffness = evolved" "stiffness_min = 2e5" "stiffness_max = 5e6" >>"$TMPD/ev.cfg"
for r in gmx cppn dct; do
    d1="$TMPD/$r-1"; d2="$TMPD/$r-2"
    expect_ok $E --config "$TMPD/ev.cfg" --representation $r --threads 1 --out "$d1"
    expect_ok $E --config "$TMPD/ev.cfg" --representation $r --threads 2 --out "$d2"
    if [ -n "$(sumval "$d1" run_hash)" ] && [ "$(sumval "$d1" run_hash)" = "$(sumval "$d2" run_hash)" ] && cmp -s "$d1/evals.csv" "$d2/evals.csv"; then ok
    else ko "$r: 1 and 2 threads differ: $(sumval "$d1" run_hash) $(sumval "$d2" run_hash)"; fi
    if grep -qx "actuation = phase" "$d1/config.txt" && grep -qx "stiffness = evolved" "$d1/config.txt" &&
       grep -qx "stiffness_max = 5e+06" "$d1/config.txt"; then ok; else ko "$r: config.txt lacks the keys: $(grep 'actuation\|stiffness' "$d1/config.txt")"; fi
    if head -1 "$d1/best.genome" | grep -qx "amorph-genome 2" && grep -qx "evolved phase stiffness" "$d1/best.genome"; then ok
    else ko "$r: best.genome carries no evolved fields: $(head -5 "$d1/best.genome")"; fi
    best=$(sumval "$d1" best_fitness)
    # the run folder replays its best with its phases and its stiffness range
    f=$("$AMORPH" sim "$d1" | sed -n 's/^fitness = //p')
    if [ -n "$f" ] && [ "$f" = "$best" ]; then ok; else ko "$r: amorph sim RUN gives '$f', the run logged $best"; fi
    # the best as a VoxCAD file: its PhaseOffset and Stiffness layers, and the same travel
    "$AMORPH" export "$d1" --vxa "$TMPD/$r.vxa" 2>"$TMPD/err" || ko "$r: export --vxa: $(cat "$TMPD/err")"
    if grep -q "<PhaseOffset>" "$TMPD/$r.vxa" && grep -q "<Stiffness>" "$TMPD/$r.vxa"; then ok; else ko "$r: the VXA file has no layers"; fi
    f=$("$AMORPH" sim "$TMPD/$r.vxa" 2>/dev/null | sed -n 's/^fitness = //p')
    if [ -n "$f" ] && [ "$f" = "$best" ]; then ok; else ko "$r: the exported VXA gives '$f', the run logged $best"; fi
    # without its layers the body moves otherwise: the lattice says it leaves them out
    "$AMORPH" export "$d1" --lattice "$TMPD/$r.lattice" 2>"$TMPD/err" >/dev/null
    if grep -q "holds no per-voxel phases or per-voxel stiffness" "$TMPD/err"; then ok; else ko "$r: --lattice says nothing: $(cat "$TMPD/err")"; fi
done
# the fields change the run: the same settings without them are another run
expect_ok $E --config "$TMPD/small.cfg" --representation gmx --threads 1 --out "$TMPD/plain"
if [ "$(sumval "$TMPD/plain" run_hash)" != "$(sumval "$TMPD/gmx-1" run_hash)" ]; then ok; else ko "evolved fields: the same run as without"; fi
# the genome file alone: the default stiffness range (1e5 to 1e7 Pa), so another travel than the run's 2e5 to 5e6
cp "$TMPD/small.cfg" "$TMPD/ph.cfg"; echo "actuation = phase" >>"$TMPD/ph.cfg"
expect_ok $E --config "$TMPD/ph.cfg" --threads 1 --out "$TMPD/ph"
f=$("$AMORPH" sim "$TMPD/ph/best.genome" --cycles 2 --period_steps 100 --relax_max_steps 400 --relax_min_steps 50 --release_steps 100 |
    sed -n 's/^fitness = //p')
if [ -n "$f" ] && [ "$f" = "$(sumval "$TMPD/ph" best_fitness)" ]; then ok; else ko "phase alone: the genome file gives '$f', the run $(sumval "$TMPD/ph" best_fitness)"; fi

# the run's genome file alone takes its range from the flags: the run's range gives the run's travel
# (and the file alone another), in sim and through an exported VXA; in its run folder a note names
# the run's range; a robot without an evolved stiffness and a range past 100x are refused
SHORT="--cycles 2 --period_steps 100 --relax_max_steps 400 --relax_min_steps 50 --release_steps 100"
cp "$TMPD/gmx-1/best.genome" "$TMPD/alone.genome"
best=$(sumval "$TMPD/gmx-1" best_fitness)
f=$("$AMORPH" sim "$TMPD/alone.genome" $SHORT --stiffness-min 2e5 --stiffness_max 5e6 | sed -n 's/^fitness = //p')
if [ -n "$f" ] && [ "$f" = "$best" ]; then ok; else ko "the genome file with the run's range gives '$f', the run logged $best"; fi
f0=$("$AMORPH" sim "$TMPD/alone.genome" $SHORT | sed -n 's/^fitness = //p')
if [ -n "$f0" ] && [ "$f0" != "$best" ]; then ok; else ko "the genome file in the default range gives '$f0', the run's $best"; fi
"$AMORPH" export "$TMPD/alone.genome" $SHORT --stiffness_min 2e5 --stiffness_max 5e6 --vxa "$TMPD/alone.vxa" 2>"$TMPD/err" ||
    ko "export of the genome file with a range: $(cat "$TMPD/err")"
f=$("$AMORPH" sim "$TMPD/alone.vxa" 2>/dev/null | sed -n 's/^fitness = //p')
if [ -n "$f" ] && [ "$f" = "$best" ]; then ok; else ko "its VXA file gives '$f', the run logged $best"; fi
"$AMORPH" sim "$TMPD/gmx-1/best.genome" $SHORT >/dev/null 2>"$TMPD/err"
if grep -q "the run had .*stiffness_min = 200000, stiffness_max = 5e+06" "$TMPD/err"; then ok
else ko "the genome in its run folder: no note of the range: $(cat "$TMPD/err")"; fi
"$AMORPH" sim "$TMPD/gmx-1/best.genome" $SHORT --stiffness_min 2e5 --stiffness_max 5e6 >/dev/null 2>"$TMPD/err"
if ! grep -q "stiffness" "$TMPD/err"; then ok; else ko "the genome in the run's range: a note all the same: $(cat "$TMPD/err")"; fi
expect_fail 2 "--stiffness_min: cube:3 has no evolved stiffness" "$AMORPH" sim --scene cube:3 --stiffness_min 2e5
expect_fail 2 "--stiffness_min: .*ph/best\.genome has no evolved stiffness" "$AMORPH" sim "$TMPD/ph/best.genome" --stiffness_min 2e5
expect_fail 2 "--stiffness_max = 5e\+07: from stiffness_min \(200000\) to 100 times it" "$AMORPH" sim "$TMPD/alone.genome" --stiffness_min 2e5 --stiffness_max 5e7

# --- kill -9 and resume: the uninterrupted run, remembered bodies with their fields included ---
ref="$TMPD/ref"; d="$TMPD/kill"
expect_ok $E --config "$TMPD/ev.cfg" --threads 1 --out "$ref" --evaluations 60
AMORPH_TEST_INTERRUPT=KILL:21 $E --config "$TMPD/ev.cfg" --threads 1 --out "$d" --evaluations 60 >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 137 ] && grep -qx "evaluations 18" "$d/checkpoint.txt"; then ok
else ko "kill -9 at 21: exit $rc, checkpoint at $(grep '^evaluations [0-9]' "$d/checkpoint.txt")"; fi
expect_ok "$AMORPH" evolve --resume "$d" --quiet --no-pictures
if cmp -s "$d/evals.csv" "$ref/evals.csv" && [ "$(sumval "$d" run_hash)" = "$(sumval "$ref" run_hash)" ]; then ok
else ko "the resumed run differs: $(diff "$d/evals.csv" "$ref/evals.csv" | head -4)"; fi

# --- refusals ---
printf '%s\n' "actuation = phase" "stiffness = evolved" "stiffness_max = 2e7" >"$TMPD/bad.cfg"
expect_fail 2 "bad\.cfg:3: stiffness_max = 2e\+07: from stiffness_min \(100000\) to 100 times it" $E --config "$TMPD/bad.cfg" --out "$TMPD/bad"
expect_fail 2 "--actuation = 'legs': expected global or phase" $E --actuation legs --out "$TMPD/bad"
expect_fail 2 "--stiffness = 'soft': expected material or evolved" $E --stiffness soft --out "$TMPD/bad"
if [ ! -e "$TMPD/bad" ]; then ok; else ko "a refused setting left a folder behind"; fi
# an evolved genome on the board, and the setting there: one line each
if [ -n "${BOARD_BUILD:-}" ] && [ -x "$BOARD_BUILD/amorph" ]; then
    expect_fail 2 "actuation = phase: the board profile keeps no phase or stiffness per voxel" "$BOARD_BUILD/amorph" evolve --actuation phase --out "$TMPD/bb"
    expect_fail 2 "best\.genome:5: an evolved phase: the board profile keeps no phase or stiffness per voxel" "$BOARD_BUILD/amorph" sim "$TMPD/ph/best.genome"
fi

summary cli_evolved
