# tests/cli_report.sh: results/report.sh, which writes the tables and pictures of docs/results.md,
# on small runs made here, with their log.csv replaced by rows whose answers are known: the Figure 6
# table's means and standard errors (over the runs that reached each 500 evaluations), the mean
# body size per 500 evaluations from evals.csv.gz, the compute with a paused generation counted
# at the median, a row per run with its 30-cycle gait, and the plots (gaits.svg's bars too). Float desktop builds (the
# report simulates the runs' best robots). Run from the repository root.
. tests/shlib.sh

if ! "$AMORPH" --help 2>/dev/null | grep -q 'profile=desktop'; then
    echo "cli_report: not a desktop build: skipped"
    summary cli_report
    exit $?
fi
R=$TMPD/res
mkdir -p "$R/representations" "$R/friction"
SMALL="--workspace 6 --population 4 --evaluations 8 --cycles 1 --period_steps 100 --relax_max_steps 150 --relax_min_steps 50 --threads 1 --quiet --no-pictures"
for run in dct-1 dct-2 gmx-1; do
    # shellcheck disable=SC2086
    expect_ok "$AMORPH" evolve $SMALL --representation "${run%-*}" --seed "${run#*-}" --out "$R/representations/$run"
    gzip -9n "$R/representations/$run/evals.csv"
done
expect_ok "$AMORPH" evolve $SMALL --mu_kinetic 0.1 --mu_static 5.0 --out "$R/friction/k0.1_s5.0-1"

# log.csv rows with known answers: dct-1 reaches 1000 evaluations, dct-2 and gmx-1 500; dct-2's
# last generation took 8 times its median (a pause: more than 5 times)
h="generation,evaluations,best,mean,median,diverged,empty,wall_s"
printf '%s\n0,250,0.010,0,0,0,0,10\n1,500,0.012,0,0,0,0,10\n2,750,0.011,0,0,0,0,10\n3,1000,0.020,0,0,0,0,10\n' "$h" \
    >"$R/representations/dct-1/log.csv"
printf '%s\n0,250,0.015,0,0,0,0,20\n1,490,0.016,0,0,0,0,20\n2,510,0.030,0,0,0,0,160\n' "$h" >"$R/representations/dct-2/log.csv"
printf '%s\n0,500,0.005,0,0,0,0,30\n' "$h" >"$R/representations/gmx-1/log.csv"

expect_ok sh results/report.sh "$AMORPH" "$R" --pictures
cp "$TMPD/out" "$TMPD/report.md"
# row KEY: the last line of the report that starts with "| KEY |" (the compute table comes last)
row() { awk -v k="| $1 |" 'index($0, k) == 1' "$TMPD/report.md" | tail -n 1; }
# the Figure 6 table: at 500, dct-1 holds 0.012 and dct-2 0.016 (its row at 490: 510 is past 500),
# mean 0.014, standard error |0.016 - 0.012| / 2 = 0.002; at 1000 only dct-1 (0.020, the best
# so far); gmx-1 only at 500
check "Figure 6 row at 500: '$(row 500)'" [ "$(row 500)" = "| 500 | 0.0140 +- 0.0020 (2 runs) |  | 0.0050 (1 run) |" ]
check "Figure 6 row at 1000: '$(row 1000)'" [ "$(row 1000)" = "| 1000 | 0.0200 (1 run) |  |  |" ]
# the best so far, not the generation's best: dct-1 at 750 logged 0.011 under an earlier 0.012
check "Figure 6 row at 750 should not exist (marks every 500): '$(row 750)'" [ -z "$(row 750)" ]
# body size: the mean of the voxels column of every evaluation of the representation's runs
want=$(for run in dct-1 dct-2; do gzip -dc "$R/representations/$run/evals.csv.gz"; done |
    awk -F, '$1 != "evaluation" { s += $7; n++ } END { printf "%.0f (%d bodies)", s / n, n }')
check "body size row: '$(row 1-500)', want DCT $want" sh -c "echo '$(row 1-500)' | grep -qF '| 1-500 | $want |'"
# compute: dct-2's 160 s generation is a pause, counted as the median 20 s: 60 s = 0.02 h
check "compute row of dct-2: '$(row representations/dct-2)'" [ "$(row representations/dct-2)" = "| representations/dct-2 | 510 | 0.02 | 1 |" ]
check "compute row of dct-1: '$(row representations/dct-1)'" [ "$(row representations/dct-1)" = "| representations/dct-1 | 1000 | 0.01 | 0 |" ]
# a row per run with its 30-cycle gait, and the gait file beside the run
for run in representations/dct-1 representations/dct-2 representations/gmx-1 friction/k0.1_s5.0-1; do
    line=$(grep -F "| $run | " "$TMPD/report.md" | head -n 1)
    check "$run: a table row with a gait: '$line'" sh -c "echo '$line' | grep -qE '\\| (still|flop|bounce|scoot) \\|'"
    check "$run: gait30.json" grep -q '"cycle_travel"' "$R/$run/gait30.json"
    check "$run: best.png" [ -s "$R/$run/best.png" ]
done
check "the Figure 6 plot" grep -q '<svg' "$R/representations/fitness.svg"
check "the Figure 6 plot of every run when none has 2,000 evaluations" grep -q 'dct, 2 runs' "$R/representations/fitness.svg"
FIG6_MIN_EVALS=750 sh results/report.sh "$AMORPH" "$R" --pictures >/dev/null 2>&1
check "FIG6_MIN_EVALS=750: only dct-1 in the Figure 6 plot" sh -c "grep -q 'dct, 1 run' '$R/representations/fitness.svg' && ! grep -q 'gmx' '$R/representations/fitness.svg'"
check "the plot of the other experiments" grep -q '<svg' "$R/others.svg"
# gaits.svg: a row of 30 bars per run (4 runs here), the rows named after the runs
check "gaits.svg: $(grep -c 'class="bar"' "$R/gaits.svg") bars, want 120" [ "$(grep -c 'class="bar"' "$R/gaits.svg")" -eq 120 ]
check "gaits.svg names the runs" sh -c "grep -q '>representations/dct-2<' '$R/gaits.svg' && grep -q '>friction/k0.1_s5.0-1<' '$R/gaits.svg'"
# the same folders give the same files (the report leaves out wall times)
cp "$R/representations/dct-1/gait30.json" "$TMPD/gait-a.json"
expect_ok sh results/report.sh "$AMORPH" "$R"
check "a second report gives the same gait30.json" cmp -s "$TMPD/gait-a.json" "$R/representations/dct-1/gait30.json"
expect_fail 2 "no such folder" sh results/report.sh "$AMORPH" "$TMPD/none"
summary cli_report
