# tests/cli_palette.sh: a run's palette from the configuration (docs/evolve.md, Palettes): the
# seed's palette writes the configuration it always wrote, the follow-up's four materials and a
# six-material palette of materialK keys evolve in every representation with bodies of every
# material, their config.txt reads back to itself, a run of each resumes after kill -9 exactly
# like the uninterrupted run, a run's genome file alone replays it in the palette that --palette and
# --materialK give, and a bad palette is refused in one line naming its file and line.
# Run from the repository root.
. tests/shlib.sh

small_cfg "$TMPD/small.cfg"
E="$AMORPH evolve --quiet --no-pictures --threads 1"

# --- the seed's palette: no palette line, as before palettes (config.txt and checkpoints unchanged) ---
"$AMORPH" evolve --print-config >"$TMPD/def.txt"
if ! grep -q "^palette\|^material[0-9]" "$TMPD/def.txt" && grep -qx "materials = 2" "$TMPD/def.txt"; then ok
else ko "the default configuration names a palette: $(grep '^palette\|^material' "$TMPD/def.txt")"; fi
"$AMORPH" evolve --materials 3 --print-config >"$TMPD/def3.txt"
if ! grep -q "^palette\|^material[0-9]" "$TMPD/def3.txt" && grep -qx "materials = 3" "$TMPD/def3.txt"; then ok
else ko "materials = 3 names a palette"; fi
# palette = seed is the default: the same text
"$AMORPH" evolve --palette seed --print-config >"$TMPD/seed.txt"
if cmp -s "$TMPD/seed.txt" "$TMPD/def.txt"; then ok; else ko "palette = seed differs from the default: $(diff "$TMPD/seed.txt" "$TMPD/def.txt")"; fi

# --- the follow-up's four materials ---
cp "$TMPD/small.cfg" "$TMPD/four.cfg"
echo "palette = unshackled" >>"$TMPD/four.cfg"
# --- six materials: the four and two of materialK keys ---
cp "$TMPD/four.cfg" "$TMPD/six.cfg"
cat >>"$TMPD/six.cfg" <<'CFG'
material5 = gel modulus=2e5 density=1e6 cte=0 phase=0 poisson=0.35
material6 = muscle90 modulus=5e6 density=1e6 cte=0.01 phase=-90 mu_kinetic=0.5 color=ff8800
CFG
for p in four six; do
    n=4; [ $p = six ] && n=6
    for r in gmx cppn dct; do
        d="$TMPD/$p-$r"
        expect_ok $E --config "$TMPD/$p.cfg" --representation $r --out "$d"
        # the run's materials: config.txt, the best genome's names, an evals.csv column each
        if grep -qx "palette = unshackled" "$d/config.txt" && grep -qx "materials = $n" "$d/config.txt"; then ok
        else ko "$p-$r: config.txt lacks its palette: $(head -5 "$d/config.txt")"; fi
        want="materials passive_soft passive_hard active_plus active_minus"; [ $p = six ] && want="$want gel muscle90"
        if grep -qx "$want" "$d/best.genome"; then ok; else ko "$p-$r: best.genome: $(grep '^materials' "$d/best.genome")"; fi
        if [ "$(head -n 1 "$d/evals.csv" | tr , '\n' | grep -c '^voxels_m')" -eq $n ]; then ok
        else ko "$p-$r: evals.csv header: $(head -n 1 "$d/evals.csv")"; fi
        # the bodies use every material: each material's column holds voxels somewhere
        if tail -n +2 "$d/evals.csv" | awk -F, -v n=$n '{ for (i = 8; i < 8 + n; i++) s[i] += $i; if ($7 != 0) { t = 0; for (i = 8; i < 8 + n; i++) t += $i; if (t != $7) bad = 1 } }
                END { for (i = 8; i < 8 + n; i++) if (!s[i]) bad = 1; exit bad }'; then ok
        else ko "$p-$r: a material no body uses, or counts that do not add up: $(tail -n +2 "$d/evals.csv" | cut -d, -f7-$((7 + n)) | head -5)"; fi
        # config.txt reads back to itself
        "$AMORPH" evolve --config "$d/config.txt" --print-config >"$TMPD/rt.txt"
        if cmp -s "$TMPD/rt.txt" "$d/config.txt"; then ok; else ko "$p-$r: config.txt does not read back: $(diff "$TMPD/rt.txt" "$d/config.txt" | head -4)"; fi
    done
    # the run folder replays with its palette: amorph sim DIR gives the logged best
    f=$("$AMORPH" sim "$TMPD/$p-gmx" | sed -n 's/^fitness = //p')
    if [ -n "$f" ] && [ "$f" = "$(sumval "$TMPD/$p-gmx" best_fitness)" ]; then ok
    else ko "$p: amorph sim RUN gives fitness '$f', the run logged $(sumval "$TMPD/$p-gmx" best_fitness)"; fi
    # kill -9 inside the fourth generation (evaluation 21), then --resume: the uninterrupted run,
    # remembered bodies (the checkpoint's same-body table) included
    ref="$TMPD/$p-ref"; d="$TMPD/$p-kill"
    expect_ok $E --config "$TMPD/$p.cfg" --out "$ref" --evaluations 60
    AMORPH_TEST_INTERRUPT=KILL:21 $E --config "$TMPD/$p.cfg" --out "$d" --evaluations 60 >"$TMPD/out" 2>"$TMPD/err"; rc=$?
    if [ $rc -eq 137 ] && grep -qx "evaluations 18" "$d/checkpoint.txt"; then ok
    else ko "$p: kill -9 at 21: exit $rc, checkpoint at $(grep '^evaluations [0-9]' "$d/checkpoint.txt")"; fi
    if grep -q "^memo " "$d/checkpoint.txt"; then ok; else ko "$p: the checkpoint remembers no body"; fi
    expect_ok "$AMORPH" evolve --resume "$d" --quiet --no-pictures
    if [ "$(nowall "$d/log.csv")" = "$(nowall "$ref/log.csv")" ] && cmp -s "$d/evals.csv" "$ref/evals.csv" &&
       [ "$(sumval "$d" run_hash)" = "$(sumval "$ref" run_hash)" ] && cmp -s "$d/best.genome" "$ref/best.genome"; then ok
    else ko "$p: the resumed run differs: $(diff "$d/evals.csv" "$ref/evals.csv" | head -4)"; fi
done
# the six-material run is not the four-material one
if [ "$(sumval "$TMPD/six-gmx" run_hash)" != "$(sumval "$TMPD/four-gmx" run_hash)" ]; then ok; else ko "six and four materials: one run"; fi
# a run's genome file alone: its materials from the palette keys given as settings (sim, render,
# view, export), so it replays its run's best; without them the built-in palette has none of its
# names; a robot that carries its materials refuses the keys; over a run folder they change it
SHORT="--cycles 2 --period_steps 100 --relax_max_steps 400 --relax_min_steps 50 --release_steps 100"
for p in four six; do
    cp "$TMPD/$p-gmx/best.genome" "$TMPD/$p-alone.genome"
    set -- --palette unshackled
    [ $p = six ] && set -- "$@" --material5 "gel modulus=2e5 density=1e6 cte=0 phase=0 poisson=0.35" \
        --material6 "muscle90 modulus=5e6 density=1e6 cte=0.01 phase=-90 mu_kinetic=0.5 color=ff8800"
    # shellcheck disable=SC2086
    f=$("$AMORPH" sim "$TMPD/$p-alone.genome" $SHORT "$@" | sed -n 's/^fitness = //p')
    if [ -n "$f" ] && [ "$f" = "$(sumval "$TMPD/$p-gmx" best_fitness)" ]; then ok
    else ko "$p: the genome file in its run's palette gives '$f', the run logged $(sumval "$TMPD/$p-gmx" best_fitness)"; fi
done
# shellcheck disable=SC2086
"$AMORPH" export "$TMPD/six-alone.genome" $SHORT "$@" --vxa "$TMPD/six-alone.vxa" 2>"$TMPD/err" || ko "export of the genome file in a palette: $(cat "$TMPD/err")"
f=$("$AMORPH" sim "$TMPD/six-alone.vxa" 2>/dev/null | sed -n 's/^fitness = //p')
if [ -n "$f" ] && [ "$f" = "$(sumval "$TMPD/six-gmx" best_fitness)" ]; then ok; else ko "its VXA file gives '$f', the run logged $(sumval "$TMPD/six-gmx" best_fitness)"; fi
expect_fail 2 "four-alone\.genome:[0-9]*: material 'passive_soft' is not in the built-in palette .*--palette and --materialK" "$AMORPH" sim "$TMPD/four-alone.genome"
expect_fail 2 "six-alone\.genome:[0-9]*: material 'gel' is not in the palette the settings give" "$AMORPH" sim "$TMPD/six-alone.genome" --palette unshackled
expect_fail 2 "--palette: cube:3 carries its own materials" "$AMORPH" sim --scene cube:3 --palette unshackled
expect_fail 2 "--material5 = 'gel modulus=2e5': missing density=" "$AMORPH" sim "$TMPD/six-alone.genome" --material5 "gel modulus=2e5"
# over a run folder: the run's own palette with its every material 10 times stiffer is another robot
f0=$("$AMORPH" sim "$TMPD/six-gmx" | sed -n 's/^fitness = //p')
f=$("$AMORPH" sim "$TMPD/six-gmx" --material1 "passive_soft modulus=5e7 density=1e6 cte=0 phase=0 poisson=0.35" \
    --material2 "passive_hard modulus=5e9 density=1e6 cte=0 phase=0 poisson=0.35" --material3 "active_plus modulus=5e7 density=1e6 cte=0.01 phase=0 poisson=0.35" \
    --material4 "active_minus modulus=5e7 density=1e6 cte=0.01 phase=180 poisson=0.35" --material5 "gel modulus=2e6 density=1e6 cte=0 phase=0 poisson=0.35" \
    --material6 "muscle90 modulus=5e7 density=1e6 cte=0.01 phase=-90 mu_kinetic=0.5" | sed -n 's/^fitness = //p')
if [ -n "$f" ] && [ "$f" != "$f0" ] && [ "$f0" = "$(sumval "$TMPD/six-gmx" best_fitness)" ]; then ok
else ko "a run folder with stiffer materials: '$f', as it is '$f0'"; fi
# a run of the seed's three materials writes no palette: its config.txt is as before palettes
expect_ok $E --config "$TMPD/small.cfg" --materials 3 --out "$TMPD/m3"
if grep -q "^palette\|^material[0-9]" "$TMPD/m3/config.txt"; then ko "materials = 3 wrote a palette"; else ok; fi

# --- bad palettes: one line naming the file and line, exit 2, nothing written ---
bad() {
    pat=$1; shift
    printf 'population = 6\n' >"$TMPD/bad.cfg"
    printf '%s\n' "$@" >>"$TMPD/bad.cfg"
    expect_fail 2 "$pat" $E --config "$TMPD/bad.cfg" --out "$TMPD/bad"
}
bad "bad.cfg:2: palette = 'rainbow': expected seed or unshackled" "palette = rainbow"
bad "bad.cfg:2: material7: a palette holds at most 6 materials \(the desktop profile\)" "material7 = x modulus=1e6 density=1000 cte=0 phase=0"
bad "bad.cfg:3: material2 = .*modulus=-5: expected a number in \(0, 1e\+12\]" "palette = unshackled" "material2 = x modulus=-5 density=1000 cte=0 phase=0"
bad "bad.cfg:2: material4 = .*missing phase=" "material4 = x modulus=1e6 density=1000 cte=0"
bad "bad.cfg:2: material1 = .*unknown field 'stiffness'" "material1 = x stiffness=1e6 density=1000 cte=0 phase=0"
bad "bad.cfg:2: material1 = .*expected a material name first" "material1 = modulus=1e6 density=1000 cte=0 phase=0"
bad "bad.cfg:2: material5: the palette has no material4 \(seed has 3 materials\)" "material5 = x modulus=1e6 density=1000 cte=0 phase=0"
bad "bad.cfg:3: material1 and material2 are both named 'active'" "palette = seed" "material1 = active modulus=1e6 density=1000 cte=0 phase=0"
bad "bad.cfg:3: materials = 5: the palette has 4 \(unshackled\)" "palette = unshackled" "materials = 5"
expect_fail 2 "--palette = 'x': expected seed or unshackled" $E --palette x --out "$TMPD/bad"
if [ ! -e "$TMPD/bad" ]; then ok; else ko "a refused palette left a folder behind"; fi

summary cli_palette
