# tests/cli_report.sh: results/report.sh, which writes the tables and pictures of docs/results.md,
# on small runs made here, with their log.csv replaced by rows whose answers are known: the Figure 6
# table's means and standard errors (over the runs that reached each 500 evaluations), each run's
# best so far every 1,000, the statistics of amorph stats (the representations' tests at every
# 1,000, the sustained score of the best robots with their gaits), the mean body size per 500 evaluations from evals.csv.gz, the compute
# with a paused generation counted at the median (per run, and per group and experiment in each window of 1,000 evaluations), a row per run with its 30-cycle gait, the other
# experiments against the range of the seed's settings, and the plots (gaits.svg's bars too).
# Float desktop builds (the report simulates the runs' best robots). Then results/ship.sh: a finished run and one gone on
# beyond its summaries copied as they stand at their checkpoints, and a best robot that is not
# its checkpoint's refused. results/tables.sh copying a report's tables into a page; results/yield.sh
# counting what runners did since a ship. And
# results/run.sh's rounds, and results/runners.sh starting two runners and stopping them at a
# checkpoint, with stand-ins for amorph. Run from the repository root.
. tests/shlib.sh

if ! "$AMORPH" --help 2>/dev/null | grep -q 'profile=desktop'; then
    echo "cli_report: not a desktop build: skipped"
    summary cli_report
    exit $?
fi
R=$TMPD/res
mkdir -p "$R/representations" "$R/friction"
SMALL="--workspace 6 --population 4 --evaluations 8 --cycles 1 --period_steps 100 --relax_max_steps 400 --relax_min_steps 50 --release_steps 100 --threads 1 --quiet --no-pictures"
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
# and their checkpoints at those counts (results/run.sh reads a run's count there)
for rc in dct-1:1000 dct-2:510 gmx-1:500; do
    sed -i "s/^evaluations 8\$/evaluations ${rc#*:}/" "$R/representations/${rc%:*}/checkpoint.txt"
done

expect_ok sh results/report.sh "$AMORPH" "$R" --pictures
cp "$TMPD/out" "$TMPD/report.md"
# row KEY: the last line of the report that starts with "| KEY |" (the compute table comes last)
row() { awk -v k="| $1 |" 'index($0, k) == 1' "$TMPD/report.md" | tail -n 1; }
# the Figure 6 table: at 500, dct-1 holds 0.012 and dct-2 0.016 (its row at 490: 510 is past 500),
# mean 0.014, standard error |0.016 - 0.012| / 2 = 0.002; at 1000 only dct-1 (0.020, the best
# so far); gmx-1 only at 500
check "Figure 6 row at 500: '$(row 500)'" [ "$(row 500)" = "| 500 | 0.0140 +- 0.0020 (2 runs) |  | 0.0050 (1 run) |" ]
# (the Figure 6 table's row: the first of the report at that count; the statistics' come after it)
fig6_1000=$(awk 'index($0, "| 1000 |") == 1' "$TMPD/report.md" | head -n 1)
check "Figure 6 row at 1000: '$fig6_1000'" [ "$fig6_1000" = "| 1000 | 0.0200 (1 run) |  |  |" ]
# the best so far, not the generation's best: dct-1 at 750 logged 0.011 under an earlier 0.012
check "Figure 6 row at 750 should not exist (marks every 500): '$(row 750)'" [ -z "$(row 750)" ]
# each run's best so far at every 1,000: dct-1 0.020 at 1000 (its best so far: 0.020 came at
# 1000); dct-2 and gmx-1 never got there, so their cells are empty
runs1000=$(awk '/^\| run \| 1000 \|$/ { t = 1 } t && !NF { exit } t' "$TMPD/report.md" | tr '\n' '/')
check "the per-run table: '$runs1000'" [ "$runs1000" = "| run | 1000 |/|---|---:|/| representations/dct-1 | 0.0200 |/| representations/dct-2 | |/| representations/gmx-1 | |/" ]
# body size: the mean of the voxels column of every evaluation of the representation's runs
want=$(for run in dct-1 dct-2; do gzip -dc "$R/representations/$run/evals.csv.gz"; done |
    awk -F, '$1 != "evaluation" { s += $7; n++ } END { printf "%.0f (%d bodies)", s / n, n }')
check "body size row: '$(row 1-500)', want DCT $want" sh -c "echo '$(row 1-500)' | grep -qF '| 1-500 | $want |'"
# compute: dct-2's 160 s generation is a pause, counted as the median 20 s: 60 s = 0.02 h
check "compute row of dct-2: '$(row representations/dct-2)'" [ "$(row representations/dct-2)" = "| representations/dct-2 | 510 | 0.02 | 1 |" ]
# the rounds left, each run to the largest count of the rounds up to it: fig6-1000 has 30 runs, dct-1
# at its count, 30,000 - (1000 + 510 + 500) left; at the compute table's pace, DCT (0.01 + 0.02) h
# over 1,510 evaluations for its 8,490 left, GMX 0.01 h over 500 for its 9,500, CPPN (not started)
# at GMX's for its 10,000: 0.6 h. fig6-2000: 57,990 left, 1.2 h. others-2000 adds 18 runs to 2,000
# (the friction run's 8 done; its 0.00 h too few to measure: GMX's pace): 93,982, 1.9 h
check "rounds: fig6-1000 '$(row fig6-1000)'" [ "$(row fig6-1000)" = "| fig6-1000 | 30 | 1 | 27990 | 0.6 |" ]
check "rounds: fig6-2000 '$(row fig6-2000)'" [ "$(row fig6-2000)" = "| fig6-2000 | 30 | 0 | 57990 | 1.2 |" ]
check "rounds: others-2000 '$(row others-2000)'" [ "$(row others-2000)" = "| others-2000 | 18 | 0 | 93982 | 1.9 |" ]
check "rounds: full-20000 last, 3 runs" [ "$(awk '/^\| round \|/ { t = 1; next } t && /^\| [a-z]/ { r = $2 " " $4 } END { print r }' "$TMPD/report.md")" = "full-20000 3" ]
check "rounds: planning made no folder" sh -c "[ ! -e '$R/dynamic' ] && [ ! -e '$R/three-materials' ]"
check "compute row of dct-1: '$(row representations/dct-1)'" [ "$(row representations/dct-1)" = "| representations/dct-1 | 1000 | 0.01 | 0 |" ]
# the compute of each round: the DCT runs' 40 s and 60 s (the pause at the median) and GMX's 30 s
check "round row of DCT: '$(row representations/dct)'" [ "$(row representations/dct)" = "| representations/dct | 1-1000 | 2 | 0.03 | 0.01 |" ]
check "round row of the experiment: '$(row "representations (all)")'" [ "$(row "representations (all)")" = "| representations (all) | 1-1000 | 3 | 0.04 | 0.01 |" ]
# windows of 1,000 evaluations by the count a generation ended at (1000 the first window's, 1001 the
# second's), runs counted in each window they have a generation in, experiments apart
W=$TMPD/rounds-w
mkdir -p "$W/exp/a-1" "$W/exp/a-2" "$W/exp/b-1" "$W/other/a-1"
printf '%s\n0,1000,0.01,0,0,0,0,3600\n1,1001,0.01,0,0,0,0,7200\n2,2000,0.01,0,0,0,0,3600\n' "$h" >"$W/exp/a-1/log.csv"
printf '%s\n0,1000,0.01,0,0,0,0,1800\n' "$h" >"$W/exp/a-2/log.csv"
printf '%s\n0,900,0.01,0,0,0,0,900\n' "$h" >"$W/exp/b-1/log.csv"
printf '%s\n0,2500,0.01,0,0,0,0,36\n' "$h" >"$W/other/a-1/log.csv"
expect_ok "$AMORPH" report compute --root "$W" "$W/exp/a-1" "$W/exp/a-2" "$W/exp/b-1" "$W/other/a-1"
rounds=$(awk '/^\| group \|/ { t = 1 } t' "$TMPD/out" | tr '\n' '/')
check "the rounds table: '$rounds'" [ "$rounds" = "| group | evaluations | runs | hours | hours a run |/|---|---:|---:|---:|---:|/\
| exp/a | 1-1000 | 2 | 1.50 | 0.75 |/| exp/b | 1-1000 | 1 | 0.25 | 0.25 |/| exp (all) | 1-1000 | 3 | 1.75 | 0.58 |/\
| exp/a | 1001-2000 | 1 | 3.00 | 3.00 |/| exp (all) | 1001-2000 | 1 | 3.00 | 3.00 |/| other/a | 2001-3000 | 1 | 0.01 | 0.01 |/\
| other (all) | 2001-3000 | 1 | 0.01 | 0.01 |/" ]
# a paused generation is judged against the median of its own window of 1,000: a window's hours do
# not move when the run goes on past it (three 1-hour generations to 1,000 stay 3 hours after five
# of 6 minutes to 2,000, though 1 hour is more than 5 times the median of all eight)
V=$TMPD/rounds-v
mkdir -p "$V/exp/a-1"
printf '%s\n0,250,0.01,0,0,0,0,3600\n1,500,0.01,0,0,0,0,3600\n2,1000,0.01,0,0,0,0,3600\n' "$h" >"$V/exp/a-1/log.csv"
expect_ok "$AMORPH" report compute --root "$V" "$V/exp/a-1"
first=$(grep -F '| exp/a | 1-1000 |' "$TMPD/out")
check "one window: '$first'" [ "$first" = "| exp/a | 1-1000 | 1 | 3.00 | 3.00 |" ]
for e in 1200 1400 1600 1800 2000; do printf '%d,%d,0.01,0,0,0,0,360\n' $((e / 200)) $e >>"$V/exp/a-1/log.csv"; done
expect_ok "$AMORPH" report compute --root "$V" "$V/exp/a-1"
check "the first window after the second: '$(grep -F '| exp/a | 1-1000 |' "$TMPD/out")'" [ "$(grep -F '| exp/a | 1-1000 |' "$TMPD/out")" = "$first" ]
check "the second window: 5 x 6 minutes" grep -qF '| exp/a | 1001-2000 | 1 | 0.50 | 0.50 |' "$TMPD/out"
check "the run: 3.5 hours, none paused" grep -qF '| exp/a-1 | 2000 | 3.50 | 0 |' "$TMPD/out"
# a row per run with its 30-cycle gait, and the gait file beside the run
for run in representations/dct-1 representations/dct-2 representations/gmx-1 friction/k0.1_s5.0-1; do
    line=$(grep -F "| $run | " "$TMPD/report.md" | head -n 1)
    check "$run: a table row with a gait: '$line'" sh -c "echo '$line' | grep -qE '\\| (still|flop|bounce|scoot) \\|'"
    check "$run: gait30.json" grep -q '"cycle_travel"' "$R/$run/gait30.json"
    check "$run: best.png" [ -s "$R/$run/best.png" ]
done
# the filmstrips shown: of each group (a representation; another experiment whole) and gait, the
# furthest best, with its filmstrip linked from the report's folder. dct-2's best (0.030) is ahead
# of dct-1's (0.020): it stands for DCT when the two share a gait, and both do when they do not
gait_of() { grep -F "| $1 | " "$TMPD/report.md" | head -n 1 | awk -F'|' '{ gsub(/ /, "", $7); print $7 }'; }
gallery=$(awk '/^\| group \| gait \| furthest best \|/ { t = 1; next } t && !NF { exit } t && !/^\|---/' "$TMPD/report.md")
g1=$(gait_of representations/dct-1) g2=$(gait_of representations/dct-2)
check "filmstrips: dct-2 for its gait $g2: '$gallery'" sh -c "echo '$gallery' | grep -qF '| representations/dct | $g2 | representations/dct-2 | 510 | 0.0300 |'"
if [ "$g1" = "$g2" ]; then
    check "filmstrips: dct-1 left out (dct-2 ahead, both $g1)" sh -c "! echo '$gallery' | grep -qF 'representations/dct-1'"
    want_rows=3
else
    check "filmstrips: dct-1 for its gait $g1" sh -c "echo '$gallery' | grep -qF '| representations/dct | $g1 | representations/dct-1 | 1000 | 0.0200 |'"
    want_rows=4
fi
check "filmstrips: gmx-1 for GMX" sh -c "echo '$gallery' | grep -qF '| representations/gmx | $(gait_of representations/gmx-1) | representations/gmx-1 | 500 | 0.0050 |'"
check "filmstrips: the friction run for its experiment" sh -c "echo '$gallery' | grep -qF '| friction | $(gait_of friction/k0.1_s5.0-1) | friction/k0.1_s5.0-1 |'"
check "filmstrips: $want_rows rows: '$gallery'" [ "$(echo "$gallery" | grep -c '^| ')" -eq "$want_rows" ]
link=$(echo "$gallery" | sed -n 's/.*| representations\/dct | '"$g2"' | .*(\(\.\.\/[^)]*\)) |$/\1/p')
check "filmstrips: '$link' leads from the report's folder to dct-2's best.png" sh -c "[ -n '$link' ] && cmp -s '$R/$link' '$R/representations/dct-2/best.png'"
check "the Figure 6 plot" grep -q '<svg' "$R/representations/fitness.svg"
check "the Figure 6 plot of every run when none has 2,000 evaluations" grep -q 'dct, 2 runs' "$R/representations/fitness.svg"
FIG6_MIN_EVALS=750 sh results/report.sh "$AMORPH" "$R" --pictures >/dev/null 2>&1
check "FIG6_MIN_EVALS=750: only dct-1 in the Figure 6 plot" sh -c "grep -q 'dct, 1 run' '$R/representations/fitness.svg' && ! grep -q 'gmx' '$R/representations/fitness.svg'"
check "the plot of the other experiments: the GMX runs as one line, and the friction run" \
    sh -c "grep -q '>gmx, 1 run<' '$R/others.svg' && grep -q '>k0.1_s5.0, 1 run<' '$R/others.svg' && ! grep -q '>dct' '$R/others.svg'"
# with no other experiment's runs there is no plot of them (the GMX runs alone are Figure 6's)
mkdir -p "$TMPD/res2"
cp -R "$R/representations" "$TMPD/res2/"
expect_ok sh results/report.sh "$AMORPH" "$TMPD/res2" --pictures
if [ -s "$TMPD/res2/gaits.svg" ] && [ ! -e "$TMPD/res2/others.svg" ]; then ok
else ko "a report without other experiments should draw gaits.svg and no others.svg"; fi
# gaits.svg: a row of 30 bars per run (4 runs here), the rows named after the runs
check "gaits.svg: $(grep -c 'class="bar"' "$R/gaits.svg") bars, want 120" [ "$(grep -c 'class="bar"' "$R/gaits.svg")" -eq 120 ]
check "gaits.svg names the runs" sh -c "grep -q '>representations/dct-2<' '$R/gaits.svg' && grep -q '>friction/k0.1_s5.0-1<' '$R/gaits.svg'"
# the same folders give the same files (the report leaves out wall times)
cp "$R/representations/dct-1/gait30.json" "$TMPD/gait-a.json"
rm "$R/representations/gmx-1/best.png"
expect_ok sh results/report.sh "$AMORPH" "$R"
check "a second report gives the same gait30.json" cmp -s "$TMPD/gait-a.json" "$R/representations/dct-1/gait30.json"
check "filmstrips: gmx-1 without best.png (no --pictures) is not drawn" sh -c "grep -E '^\| representations/gmx \| [a-z]+ \| representations/gmx-1 \|' '$TMPD/out' | grep -qF '| (not drawn) |'"
# the sustained score of the best robots, over the runs at 1,000 evaluations (every run at 1,000 or
# more has reached it): dct-1 alone, its sustained_travel (cycles 11-30 of gait30.json) in mm with
# its gait; dct-2 (510) and gmx-1 (500), just started beside it, left out
sus() { sed -n 's/.*"sustained_travel": \([-0-9.e]*\),.*/\1/p' "$1/gait30.json"; }
want=$(sus "$R/representations/dct-1" | awk '{ printf "%.3f", $1 * 1000 }')
row=$(grep '^| sustained | dct |' "$TMPD/report.md")
check "sustained row of dct: '$row', want dct-1's $want mm" sh -c "echo '$row' | grep -qF '| sustained | dct | 1 | $want |'"
gaits=$(echo "$row" | awk -F'|' '{ print $8 + $9 + $10 + $11 + $12 }')
check "sustained: dct's gaits count its 1 run: '$row'" [ "$gaits" = 1 ]
check "sustained: gmx-1, short of 1,000, left out" sh -c "! grep -q '^| sustained | gmx' '$TMPD/report.md'"
# dct-2 at 1,000 too: dct's two runs (the mean of their scores), gmx-1 still left out; a run
# beyond the count (dct-1 at 2,000) is compared at its best as it stands
S=$TMPD/sus
mkdir -p "$S"
cp -R "$R/representations" "$S/"
printf '%s\n0,1000,0.010,0,0,0,0,10\n1,2000,0.020,0,0,0,0,10\n' "$h" >"$S/representations/dct-1/log.csv"
printf '%s\n0,500,0.015,0,0,0,0,20\n1,1000,0.016,0,0,0,0,20\n' "$h" >"$S/representations/dct-2/log.csv"
expect_ok sh results/report.sh "$AMORPH" "$S"
want=$(for run in dct-1 dct-2; do sus "$S/representations/$run"; done | awk '{ m[NR] = $1 } END { printf "%.3f", (m[1] + m[2]) / 2 * 1000 }')
row=$(grep '^| sustained | dct |' "$TMPD/out")
check "sustained row of dct's two runs: '$row', want the mean $want mm" sh -c "echo '$row' | grep -qF '| sustained | dct | 2 | $want |'"
check "sustained: gmx-1 at 500 still left out" sh -c "! grep -q '^| sustained | gmx' '$TMPD/out'"
# dct-1's best robot at 1,000 kept (run.sh's best-1000.genome; dct-2's robot here): dct-1 is
# compared at it, simulated in its settings into gait30-1000.json, so DCT's mean is dct-2's score
cp "$S/representations/dct-2/best.genome" "$S/representations/dct-1/best-1000.genome"
expect_ok sh results/report.sh "$AMORPH" "$S"
want=$(sus "$S/representations/dct-2" | awk '{ printf "%.3f", $1 * 1000 }')
row=$(grep '^| sustained | dct |' "$TMPD/out")
check "sustained: dct-1 at its best at 1,000: '$row', want $want mm" sh -c "echo '$row' | grep -qF '| sustained | dct | 2 | $want |'"
g1000=$S/representations/dct-1/gait30-1000.json
check "sustained: dct-1's gait30-1000.json names best-1000.genome" grep -qF "\"robot\": \"$S/representations/dct-1/best-1000.genome\"" "$g1000"
check "sustained: gait30-1000.json is the kept robot's gait" [ "$(sed -n 's/.*"sustained_travel": \([-0-9.e]*\),.*/\1/p' "$g1000")" = "$(sus "$S/representations/dct-2")" ]
check "sustained: gait30.json is still dct-1's best as it stands" [ "$(sus "$S/representations/dct-1")" = "$(sus "$R/representations/dct-1")" ]
# none at 1,000: every run is compared (gmx-1 alone: no test)
printf '%s\n0,500,0.010,0,0,0,0,10\n' "$h" >"$S/representations/dct-1/log.csv"
printf '%s\n0,500,0.015,0,0,0,0,20\n' "$h" >"$S/representations/dct-2/log.csv"
expect_ok sh results/report.sh "$AMORPH" "$S"
check "sustained, no run at 1,000: dct's two runs" grep -q '^| sustained | dct | 2 |' "$TMPD/out"
check "sustained, no run at 1,000: no gait30-1000.json left" [ ! -e "$S/representations/dct-1/gait30-1000.json" ]
check "sustained, no run at 1,000: gmx-1 alone is not tested" grep -qE '^\| sustained \| (dct - gmx|gmx - dct) \| [-0-9.]+ \| no test: gmx has 1 run \|' "$TMPD/out"
# the statistics at 1,000: dct-1 alone (dct-2 has not reached it: left out, not hiding DCT), gmx-1
# neither: no pair to test, so no table of pairs or ranking
check "stats at 1,000: DCT's one run that reached it" grep -qF "| 1000 | dct | 1 | 20.00 | - | - |" "$TMPD/report.md"
check "no table of tests on the best fitness while one representation alone has runs at 1,000" sh -c "! grep -q '^| evaluations | pair \|^| evaluations | ranking' '$TMPD/report.md'"
expect_fail 2 "no such folder" sh results/report.sh "$AMORPH" "$TMPD/none"
# the statistics, on folders of log.csv only: at 1000, GMX 0.020/0.022/0.021, CPPN 0.011/0.013, DCT
# 0.010/0.012; at 2000, GMX 0.030/0.031/0.032, CPPN 0.0160/0.01604, DCT 0.015/0.017; at 3000, which
# gmx-3 did not reach, CPPN and DCT alone. The expected rows were computed apart (python3: p by
# Simpson's rule on the t density, the Mann-Whitney p over every subset; Holm's correction by hand:
# at 1000 Welch's 0.0215 x 3 = 0.065 and 0.0256 x 2 = 0.051 held up to it, so neither GMX pair is
# significant after it; at 2000 0.00147 x 3 and 0.0110 x 2 still are); no sustained table (no
# gait30.json)
K=$TMPD/rank
for r in dct-1 dct-2 cppn-1 cppn-2 gmx-1 gmx-2 gmx-3; do mkdir -p "$K/representations/$r"; done
printf '%s\n0,1000,0.010,0,0,0,0,1\n1,2000,0.015,0,0,0,0,1\n2,3000,0.015,0,0,0,0,1\n' "$h" >"$K/representations/dct-1/log.csv"
printf '%s\n0,1000,0.012,0,0,0,0,1\n1,2000,0.017,0,0,0,0,1\n2,3000,0.017,0,0,0,0,1\n' "$h" >"$K/representations/dct-2/log.csv"
printf '%s\n0,1000,0.011,0,0,0,0,1\n1,2000,0.0160,0,0,0,0,1\n2,3000,0.02,0,0,0,0,1\n' "$h" >"$K/representations/cppn-1/log.csv"
printf '%s\n0,1000,0.013,0,0,0,0,1\n1,2000,0.01604,0,0,0,0,1\n2,3000,0.02,0,0,0,0,1\n' "$h" >"$K/representations/cppn-2/log.csv"
printf '%s\n0,1000,0.020,0,0,0,0,1\n1,2000,0.030,0,0,0,0,1\n2,3000,0.04,0,0,0,0,1\n' "$h" >"$K/representations/gmx-1/log.csv"
printf '%s\n0,1000,0.022,0,0,0,0,1\n1,2000,0.031,0,0,0,0,1\n2,3000,0.04,0,0,0,0,1\n' "$h" >"$K/representations/gmx-2/log.csv"
printf '%s\n0,1000,0.021,0,0,0,0,1\n1,2000,0.032,0,0,0,0,1\n' "$h" >"$K/representations/gmx-3/log.csv"
expect_ok sh results/report.sh "$AMORPH" "$K"
# table HEADER: the table of the report whose header line starts with HEADER, lines joined by '/'
table() { awk -v k="$1" 'index($0, k) == 1 { t = 1 } t && !NF { exit } t' "$TMPD/out" | tr '\n' '/'; }
pairs=$(table "| evaluations | pair |")
check "the pairs table: '$pairs'" [ "$pairs" = "| evaluations | pair | difference (mm) | Welch's t | df | p (Welch) | p (Welch, Holm) | U | p (Mann-Whitney) | p (Mann-Whitney, Holm) | Cohen's d | Hedges' g | runs for 80% power |/|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|/\
| 1000 | gmx - cppn | 9.00 | 7.79 | 1.7 | 0.026 | 0.065 | 6 | 0.200 | 0.600 | 7.79 | 5.64 | 2 |/| 1000 | gmx - dct | 10.00 | 8.66 | 1.7 | 0.022 | 0.065 | 6 | 0.200 | 0.600 | 8.66 | 6.27 | 2 |/\
| 1000 | cppn - dct | 1.00 | 0.71 | 2.0 | 0.553 | 0.553 | 3 | 0.667 | 0.667 | 0.71 | 0.40 | 33 |/| 2000 | gmx - cppn | 14.98 | 25.93 | 2.0 | 0.001 | 0.004 | 6 | 0.200 | 0.600 | 18.34 | 13.27 | 2 |/\
| 2000 | gmx - dct | 15.00 | 12.99 | 1.7 | 0.011 | 0.022 | 6 | 0.200 | 0.600 | 12.99 | 9.40 | 2 |/| 2000 | cppn - dct | 0.02 | 0.02 | 1.0 | 0.987 | 0.987 | 2 | 1.000 | 1.000 | 0.02 | 0.01 | 39262 |/\
| 3000 | cppn - dct | 4.00 | 4.00 | 1.0 | 0.156 | 0.156 | 4 | 0.333 | 0.333 | 4.00 | 2.26 | 3 |/" ]
ranking=$(table "| evaluations | ranking by mean |")
check "the ranking table: '$ranking'" [ "$ranking" = "| evaluations | ranking by mean | significant at 0.05 after Holm's correction, Welch's t | significant at 0.05 after Holm's correction, Mann-Whitney |/|---:|---|---|---|/\
| 1000 | gmx > cppn > dct | none | none |/| 2000 | gmx > cppn > dct | gmx > cppn, gmx > dct | none |/| 3000 | cppn > dct | none | none |/" ]
check "the groups table at 2000: '$(grep '^| 2000 | cppn |' "$TMPD/out")'" grep -qxF "| 2000 | cppn | 2 | 16.02 | 0.03 | 0.02 |" "$TMPD/out"
check "no bands table (not a test)" sh -c "! grep -q 'bands' '$TMPD/out'"
check "no sustained table without gait30.json" sh -c "! grep -q '^| sustained' '$TMPD/out'"
# a damaged log stops the report (exit 1) with the program's message (amorph report's, the first to read it)
printf '%s\n0,1000,abc,0,0,0,0,1\n' "$h" >"$K/representations/gmx-3/log.csv"
expect_fail 1 "gmx-3/log.csv:2: best \\(column 3\\): not a number" sh results/report.sh "$AMORPH" "$K"

# the other experiments' table, on folders of config.txt and log.csv only: the seed's settings are
# gmx-1 (0.014 at 500) and gmx-2 (0.018 at 500; its 0.030 at 750 is past the count): mean 0.016,
# standard error 0.002, range 0.014 to 0.018; friction/a (0.020) is above it, dynamic/b (0.015,
# another seed) within, dynamic/c (0.010) below; three/d has not reached 500 evaluations
O=$TMPD/others
mkdir -p "$O/representations/gmx-1" "$O/representations/gmx-2" "$O/friction/a" "$O/dynamic/b" "$O/dynamic/c" "$O/three/d"
cfg=$R/representations/gmx-1/config.txt
cp "$cfg" "$O/representations/gmx-1/config.txt"
sed 's/^seed = .*/seed = 2/' "$cfg" >"$O/representations/gmx-2/config.txt"
sed 's/^mu_kinetic = .*/mu_kinetic = 0.1/; s/^mu_static = .*/mu_static = 5/' "$cfg" >"$O/friction/a/config.txt"
sed 's/^seed = .*/seed = 7/; s/^evaluations = .*/evaluations = 900/; s/^damping_internal = .*/damping_internal = 0.1/' "$cfg" >"$O/dynamic/b/config.txt"
sed 's/^period_steps = .*/period_steps = 50/' "$cfg" >"$O/dynamic/c/config.txt"
sed 's/^materials = .*/materials = 3/' "$cfg" >"$O/three/d/config.txt"
printf '%s\n0,250,0.010,0,0,0,0,1\n1,500,0.014,0,0,0,0,1\n' "$h" >"$O/representations/gmx-1/log.csv"
printf '%s\n0,500,0.018,0,0,0,0,1\n1,750,0.030,0,0,0,0,1\n' "$h" >"$O/representations/gmx-2/log.csv"
printf '%s\n0,250,0.020,0,0,0,0,1\n1,500,0.019,0,0,0,0,1\n' "$h" >"$O/friction/a/log.csv"
printf '%s\n0,500,0.015,0,0,0,0,1\n' "$h" >"$O/dynamic/b/log.csv"
printf '%s\n0,500,0.010,0,0,0,0,1\n' "$h" >"$O/dynamic/c/log.csv"
printf '%s\n0,250,0.040,0,0,0,0,1\n' "$h" >"$O/three/d/log.csv"
OTHERS_EVALS=500 expect_ok sh results/report.sh "$AMORPH" "$O"
# orow KEY: the row of the others' table that starts with "| KEY |"
orow() { awk -v k="| $1 |" '/^\| run \| settings \|/ { t = 1 } t && !NF { t = 0 } t && index($0, k) == 1' "$TMPD/out"; }
check "others: the header names the count: '$(grep -F '| run | settings |' "$TMPD/out")'" grep -qxF "| run | settings | best fitness at 500 evaluations (m) | against the seed's settings | gait (30 cycles) |" "$TMPD/out"
check "others: the seed's settings: '$(orow 'representations/gmx-\*')'" [ "$(orow 'representations/gmx-*')" = "| representations/gmx-* | the seed's (GMX, 2 runs) | 0.0160 +- 0.0020 (0.0140 to 0.0180) | | |" ]
check "others: friction/a above: '$(orow friction/a)'" [ "$(orow friction/a)" = "| friction/a | mu_static=5, mu_kinetic=0.1 | 0.0200 | above the range |  |" ]
check "others: dynamic/b within (its seed and evaluations are not settings): '$(orow dynamic/b)'" [ "$(orow dynamic/b)" = "| dynamic/b | damping_internal=0.1 | 0.0150 | within the range |  |" ]
check "others: dynamic/c below: '$(orow dynamic/c)'" [ "$(orow dynamic/c)" = "| dynamic/c | period_steps=50 | 0.0100 | below the range |  |" ]
check "others: no row for a run short of the count: '$(orow three/d)'" [ -z "$(orow three/d)" ]

# the actuation experiment's table: real small runs (6^3, 24 evaluations), two of the seed's
# palette with global actuation and two with evolved phase; not in the others' table; a variant's
# mean +- standard error is its runs' best at ACT_EVALS, its body lengths per cycle the mean of
# each best robot's 30-cycle travel per cycle over its body length (gait30.json); the variants
# compared by amorph stats in the family of their question, the tables' first cell saying
# "actuation" and the family
A=$TMPD/act
mkdir -p "$A/actuation"
for v in seed-global seed-phase; do
    for k in 1 2; do
        f=; [ $v = seed-phase ] && f="--actuation phase"
        # shellcheck disable=SC2086
        expect_ok "$AMORPH" evolve --workspace 6 --population 8 --evaluations 24 --cycles 2 --period_steps 100 --relax_max_steps 400 \
            --relax_min_steps 50 --release_steps 100 --seed $k $f --threads 1 --quiet --no-pictures --out "$A/actuation/gmx-$v-$k"
    done
done
# a variant none of whose runs has reached ACT_EVALS yet is no group of the tests (its pairs left out)
expect_ok "$AMORPH" evolve --workspace 6 --population 8 --evaluations 8 --cycles 2 --period_steps 100 --relax_max_steps 400 \
    --relax_min_steps 50 --release_steps 100 --seed 1 --actuation phase --palette unshackled --threads 1 --quiet --no-pictures --out "$A/actuation/gmx-four-phase-1"
mkdir -p "$A/representations/gmx-1" && cp "$O/representations/gmx-1/config.txt" "$O/representations/gmx-1/log.csv" "$A/representations/gmx-1/"
ACT_EVALS=24 OTHERS_EVALS=24 expect_ok sh results/report.sh "$AMORPH" "$A"
arow() { awk -v k="| actuation/$1 |" '/^\| variant \|/ { t = 1 } t && !NF { t = 0 } t && index($0, k) == 1' "$TMPD/out"; }
want=$(for k in 1 2; do
    g=$A/actuation/gmx-seed-phase-$k/gait30.json
    echo "$("$AMORPH" report best-at 24 "$A/actuation/gmx-seed-phase-$k") $(sed -n 's/.*"body_length": \([^,]*\),.*/\1/p' "$g") $(sed -n 's/.*"cycle_travel": \[\([^]]*\)\].*/\1/p' "$g" | tr -d ',')"
done | awk '{ s += $1; q += $1 * $1; t = 0; for (c = 3; c <= NF; c++) t += $c; bl += t / (NF - 2) / $2 }
            END { m = s / 2; printf "%.4f +- %.4f | %.4f", m, sqrt((q - 2 * m * m) / 1) / sqrt(2), bl / 2 }')
check "actuation: the evolved-phase row: '$(arow gmx-seed-phase)', want '$want'" sh -c "echo '$(arow gmx-seed-phase)' | grep -qF '| 2 | $want |'"
check "actuation: a row per variant" [ -n "$(arow gmx-seed-global)" ]
check "actuation: not in the others' table" [ -z "$(orow actuation/gmx-seed-phase-1)" ]
check "actuation: the variants compared by amorph stats" grep -qF "| 24 | gmx-seed-phase - gmx-seed-global |" "$TMPD/out"
check "actuation: the variants' table once, its header saying so" [ "$(grep -c '^| evaluations (actuation) | group |' "$TMPD/out")" -eq 1 ]
check "actuation: the pairs' table names its family (evolved against global phase)" grep -qF "| evaluations (actuation: phase) | pair |" "$TMPD/out"
check "actuation: no ranking table (the families' are in the pairs' tables)" sh -c "! grep -q '^| evaluations (actuation[^|]*) | ranking' '$TMPD/out'"
check "actuation: the sustained score's tables too" grep -qF "| score (actuation: phase) | pair |" "$TMPD/out"
# --pictures: actuation/fitness.svg, the variants of the runs that reached ACT_EVALS (the four-phase
# run at 8 evaluations left out), every run when none has
ACT_EVALS=24 OTHERS_EVALS=24 sh results/report.sh "$AMORPH" "$A" --pictures >/dev/null 2>&1
check "actuation plot: the two variants that reached 24 evaluations, two runs each, and not the one short of it" sh -c \
    "grep -q '>gmx-seed-global, 2 runs<' '$A/actuation/fitness.svg' && grep -q '>gmx-seed-phase, 2 runs<' '$A/actuation/fitness.svg' &&
     ! grep -q 'gmx-four-phase' '$A/actuation/fitness.svg'"
ACT_EVALS=1000 OTHERS_EVALS=24 sh results/report.sh "$AMORPH" "$A" --pictures >/dev/null 2>&1
check "actuation plot: every run when none reached ACT_EVALS" grep -q '>gmx-four-phase, 1 run<' "$A/actuation/fitness.svg"

# --- results/tables.sh: the report's tables copied over a page's older ones, the prose around
# them kept (the page here: each table of the first report with one stale row, and the per-run
# table without its 1000 column, as before the runs reached 1,000); a table the page lacks refused
awk '/^\|/ { if (!t) { n++; print; t = 1; h = $0 } else if (t == 1) { print (h == "| run | 1000 |" ? "|---|" : $0); print "| stale | row |"; t = 2 } next }
     { if (t) { print ""; print "prose " n } t = 0 } END { if (t) { print ""; print "prose " n } }' "$TMPD/report.md" | sed 's/^| run | 1000 |$/| run |/' >"$TMPD/page.md"
check "tables.sh: the stale page has the per-run table without its column" grep -qxF "| run |" "$TMPD/page.md"
expect_ok sh results/tables.sh "$TMPD/report.md" "$TMPD/page.md"
# the page's tables, one per line, must be the report's
tabs() { awk '/^\|/ { printf "%s/", $0; next } { print "" }' "$1" | grep -v '^$'; }
check "tables.sh: the page's tables are the report's now" [ "$(tabs "$TMPD/page.md")" = "$(tabs "$TMPD/report.md")" ]
check "tables.sh: the prose kept: $(grep -c '^prose' "$TMPD/page.md") paragraphs" [ "$(grep -c '^prose [1-5]$' "$TMPD/page.md")" -eq 5 ]
check "tables.sh: no stale row left" sh -c "! grep -q 'stale' '$TMPD/page.md'"
cp "$TMPD/page.md" "$TMPD/page0.md"
cp "$TMPD/report.md" "$TMPD/report2.md"
printf '\n| a new | table |\n|---|---|\n| 1 | 2 |\n' >>"$TMPD/report2.md"
expect_fail 1 "page.md: no table headed \"\| a new \| table \|\"" sh results/tables.sh "$TMPD/report2.md" "$TMPD/page.md"
check "tables.sh: the page unchanged after a refusal" cmp -s "$TMPD/page0.md" "$TMPD/page.md"
check "tables.sh: no temporary file left" [ -z "$(ls "$TMPD" | grep 'page.md.tables')" ]
cp "$TMPD/report.md" "$TMPD/report3.md"
printf '\n| run | 2000 |\n|---|---:|\n| x | 1 |\n' >>"$TMPD/report3.md"
expect_fail 1 "report3.md: two tables headed like \"\| run \| 2000 \|\"" sh results/tables.sh "$TMPD/report3.md" "$TMPD/page.md"
check "tables.sh: the page unchanged after two tables of one header" cmp -s "$TMPD/page0.md" "$TMPD/page.md"
expect_fail 2 "none.md: no such file" sh results/tables.sh "$TMPD/none.md" "$TMPD/page.md"


# --- results/yield.sh: what the runners did since a ship, from the log.csv of both copies ---
YB=$TMPD/yield-before YN=$TMPD/yield-now
mkdir -p "$YB/exp/a-1" "$YB/exp/b-1" "$YN/exp/a-1" "$YN/exp/b-1" "$YN/other/c-1"
# a-1 went from 500 to 1000 (two generations, 360 + 720 s); b-1 did not move; c-1 is new (0 to 250, 36 s)
printf '%s\n0,250,0.01,0,0,0,0,10\n1,500,0.01,0,0,0,0,20\n' "$h" >"$YB/exp/a-1/log.csv"
cat "$YB/exp/a-1/log.csv" >"$YN/exp/a-1/log.csv"
printf '2,750,0.01,0,0,0,0,360\n3,1000,0.01,0,0,0,0,720\n' >>"$YN/exp/a-1/log.csv"
printf '%s\n0,250,0.01,0,0,0,0,10\n' "$h" | tee "$YB/exp/b-1/log.csv" >"$YN/exp/b-1/log.csv"
printf '%s\n0,250,0.01,0,0,0,0,36\n' "$h" >"$YN/other/c-1/log.csv"
# c-2 just started: its log.csv has no generation yet (no row, no refusal)
mkdir -p "$YN/other/c-2"
echo "$h" >"$YN/other/c-2/log.csv"
expect_ok sh results/yield.sh "$AMORPH" "$YB" "$YN"
check "yield: a-1 500 to 1000 in 0.30 h: $(tr '\n' '/' <"$TMPD/out")" grep -qxF '| exp/a-1 | 500 | 1000 | 500 | 0.30 |' "$TMPD/out"
check "yield: c-1 from 0" grep -qxF '| other/c-1 | 0 | 250 | 250 | 0.01 |' "$TMPD/out"
check "yield: b-1 did not move and c-2 has no generation: no rows" sh -c "! grep -qE 'exp/b-1|other/c-2' '$TMPD/out'"
check "yield: the totals" grep -qxF '| all | | | 750 | 0.31 |' "$TMPD/out"
expect_ok sh results/yield.sh "$AMORPH" "$YN" "$YN"
check "yield: nothing moved: header and totals of 0" [ "$(tr '\n' '/' <"$TMPD/out")" = "| run | evaluations before | evaluations now | evaluations | runner-hours |/|---|---:|---:|---:|---:|/| all | | | 0 | 0.00 |/" ]
printf '4,1250,0.01,0,0,0,0,slow\n' >>"$YN/exp/a-1/log.csv"
expect_fail 1 "yield-now/exp/a-1/log.csv:6: wall_s \\(column 8\\): not a number" sh results/yield.sh "$AMORPH" "$YB" "$YN"
expect_fail 2 "no such folder" sh results/yield.sh "$AMORPH" "$YB" "$TMPD/none"

# --- results/ship.sh (copied with report.sh into a folder of its own, which it fills) ---
S=$TMPD/ship-src D=$TMPD/ship-dst
mkdir -p "$S/representations" "$D"
cp results/ship.sh results/report.sh "$D/"
# dct-1 finished at 8 evaluations, then resumed towards 16 and killed after 12 (a generation's end:
# its checkpoint is of 12, its summaries still of the command that ended at 8); gmx-1 finished
# shellcheck disable=SC2086
expect_ok "$AMORPH" evolve $SMALL --representation dct --seed 1 --out "$S/representations/dct-1"
cp "$S/representations/dct-1/best.genome" "$S/representations/dct-1/best-8.genome" # as run.sh keeps it
AMORPH_TEST_INTERRUPT=KILL:12 "$AMORPH" evolve --resume "$S/representations/dct-1" --evaluations 16 --quiet >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 137 ] && grep -qx 'evaluations 12' "$S/representations/dct-1/checkpoint.txt"; then ok; else ko "the resumed run was killed (exit $rc) at 12 evaluations"; fi
# shellcheck disable=SC2086
expect_ok "$AMORPH" evolve $SMALL --representation gmx --seed 1 --out "$S/representations/gmx-1"
cp "$S/representations/gmx-1/best.genome" "$S/representations/gmx-1/best-8.genome"
expect_ok sh "$D/ship.sh" "$AMORPH" "$S"
check "ship: the best robots kept at a round's count" sh -c "cmp -s '$S/representations/dct-1/best-8.genome' '$D/representations/dct-1/best-8.genome' && cmp -s '$S/representations/gmx-1/best-8.genome' '$D/representations/gmx-1/best-8.genome'"
check "ship: the finished run's summary names its copy" grep -qx 'run = results/representations/gmx-1' "$D/representations/gmx-1/summary.txt"
check "ship: summary.json too" grep -q '"run": "results/representations/gmx-1"' "$D/representations/gmx-1/summary.json"
if [ ! -f "$D/representations/dct-1/summary.txt" ] && [ ! -f "$D/representations/dct-1/summary.json" ]; then ok; else ko "ship: no summary for the run gone on beyond it"; fi
check "ship: evals.csv.gz cut to the checkpoint's 12 rows" [ "$(gzip -dc "$D/representations/dct-1/evals.csv.gz" | wc -l)" -eq 13 ]
check "ship: log.csv cut to the checkpoint's 3 generations" [ "$(wc -l <"$D/representations/dct-1/log.csv")" -eq 4 ]
want=$(awk '$1 == "individual" && $2 == "best" { print $9 }' "$D/representations/dct-1/checkpoint.txt")
expect_ok "$AMORPH" sim "$D/representations/dct-1" --json
check "ship: the copied best robot ends in the checkpoint's best state $want" grep -q "\"hash\": \"$want\"" "$TMPD/out"
check "ship: the report" grep -q '| representations/dct-1 | 12 |' "$D/report.md"
check "ship: no folder of its own left behind" [ ! -d "$D/representations/dct-1/.ship" ]
# the checkpoint is shipped without its table of simulated bodies (a cache, most of its size):
# resumed from the copy, the run goes on to the rows and best robot of the run never stopped
if grep -q '^memo ' "$S/representations/dct-1/checkpoint.txt" && ! grep -q '^memo \|^m ' "$D/representations/dct-1/checkpoint.txt"; then ok
else ko "ship: the run's checkpoint has remembered bodies and the shipped one none"; fi
cp -r "$D/representations/dct-1" "$TMPD/lean-resumed"
gzip -dc "$TMPD/lean-resumed/evals.csv.gz" >"$TMPD/lean-resumed/evals.csv" && rm "$TMPD/lean-resumed/evals.csv.gz"
expect_ok "$AMORPH" evolve --resume "$TMPD/lean-resumed" --evaluations 16 --quiet
# shellcheck disable=SC2086
expect_ok "$AMORPH" evolve $SMALL --representation dct --seed 1 --evaluations 16 --out "$TMPD/never-stopped"
check "ship: resumed from the shipped checkpoint, evals.csv is the uninterrupted run's" cmp -s "$TMPD/lean-resumed/evals.csv" "$TMPD/never-stopped/evals.csv"
check "ship: log.csv too (but the wall times)" sh -c "cut -d, -f1-7,9- '$TMPD/lean-resumed/log.csv' >'$TMPD/l1'; cut -d, -f1-7,9- '$TMPD/never-stopped/log.csv' >'$TMPD/l2'; cmp -s '$TMPD/l1' '$TMPD/l2'"
check "ship: and the best robot" cmp -s "$TMPD/lean-resumed/best.genome" "$TMPD/never-stopped/best.genome"
# export --checkpoint alone: a run folder, nothing else
expect_fail 2 "takes a run folder of amorph evolve; $TMPD is not one" "$AMORPH" export "$TMPD" --checkpoint "$TMPD/x.txt"
expect_fail 2 "--checkpoint takes a run folder and no other output or setting" "$AMORPH" export "$S/representations/gmx-1" --checkpoint "$TMPD/x.txt" --cycles 3
expect_fail 2 "--checkpoint needs a file name" "$AMORPH" export "$S/representations/gmx-1" --checkpoint
check "export --checkpoint: no file left by a refusal" [ ! -e "$TMPD/x.txt" ]
# a resume with nothing left to do rewrites the summaries with its own wall time: the shipped ones stay
cp "$D/representations/gmx-1/summary.txt" "$TMPD/shipped-summary.txt"
cp "$S/representations/gmx-1/summary.txt" "$TMPD/run-summary.txt"
expect_ok "$AMORPH" evolve --resume "$S/representations/gmx-1" --quiet
check "the no-op resume rewrote the run's wall time" sh -c "! cmp -s '$S/representations/gmx-1/summary.txt' '$TMPD/run-summary.txt'"
expect_ok sh "$D/ship.sh" "$AMORPH" "$S"
check "ship: the shipped summary of a finished run stays as it was" cmp -s "$TMPD/shipped-summary.txt" "$D/representations/gmx-1/summary.txt"
# a kept best robot that is not the run's best at its count (another run's): refused, the copy unchanged
cp "$S/representations/dct-1/best-8.genome" "$S/representations/gmx-1/best-8.genome"
SHIP_TRIES=2 SHIP_WAIT=0 expect_fail 1 "gmx-1: best-8.genome ends in state .*, the best of evals.csv's first 8 evaluations in [0-9a-f]" sh "$D/ship.sh" "$AMORPH" "$S"
check "ship: the refused robot's shipped copy unchanged" cmp -s "$S/representations/dct-1/best-8.genome" "$D/representations/dct-1/best-8.genome"
check "ship: the refused robot not copied" sh -c "! cmp -s '$S/representations/dct-1/best-8.genome' '$D/representations/gmx-1/best-8.genome'"
cp "$D/representations/gmx-1/best-8.genome" "$S/representations/gmx-1/best-8.genome"
# a best robot that is not the checkpoint's (another run's genome): refused, the copy unchanged
cp "$S/representations/gmx-1/best.genome" "$S/representations/dct-1/best.genome"
cp "$D/representations/dct-1/best.genome" "$TMPD/shipped.genome"
SHIP_TRIES=2 SHIP_WAIT=0 expect_fail 1 "best.genome ends in state .*, checkpoint.txt's best in $want" sh "$D/ship.sh" "$AMORPH" "$S"
check "ship: the refused run's copy unchanged" cmp -s "$TMPD/shipped.genome" "$D/representations/dct-1/best.genome"
check "ship: no folder of its own left behind after a refusal" [ ! -d "$D/representations/dct-1/.ship" ]
# --- results/run.sh, with a stand-in for amorph that records its calls (the real runs take hours):
# a round starts the missing runs and resumes the others, leaves a run already beyond the round's
# count alone, skips a folder another runner works in, stops at a failing run, refuses a bad stage
F=$TMPD/fake-amorph RD=$TMPD/rounds
cat >"$F" <<'FAKE'
#!/bin/sh
echo "$*" >>"$RD/calls"
while [ $# -gt 0 ]; do
    case $1 in --resume | --out) dir=$2 ;; --evaluations) n=$2 ;; --material2) printf '%s\n' "$2" >>"$RD/material2" ;; esac
    shift
done
echo "${dir#"$RD"/representations/}" >>"$RD/order"
case "$dir" in *"$FAKE_BUSY") echo "amorph: $dir: another amorph is working in this folder" >&2; exit 1 ;; esac
case "$dir" in *"$FAKE_FAIL") echo "amorph: $dir: no space left" >&2; exit 1 ;; esac
mkdir -p "$dir" && printf 'evaluations = %s\n' "$n" >"$dir/summary.txt"
printf 'evaluations %s\n' "$n" >"$dir/checkpoint.txt"
echo "the best at $n" >"$dir/best.genome"
FAKE
chmod +x "$F"
mkdir -p "$RD/representations/dct-1" "$RD/representations/gmx-2"
printf 'evaluations = 4000\nevaluations 3640\n' >"$RD/representations/dct-1/checkpoint.txt"
printf 'evaluations = 5000\nevaluations 5000\n' >"$RD/representations/gmx-2/checkpoint.txt"
export RD FAKE_BUSY=cppn-3 FAKE_FAIL=none
FIG6_SEEDS=3 sh results/run.sh "$F" "$RD" fig6-4000 >"$TMPD/out" 2>"$TMPD/err"; rc=$?
check "run.sh: a round with a busy folder succeeds (exit $rc: $(cat "$TMPD/err"))" [ $rc -eq 0 ]
if [ "$(wc -l <"$RD/calls")" -eq 8 ] && ! grep -q gmx-2 "$RD/calls"; then ok; else ko "run.sh: eight calls, gmx-2 (at 5000) left alone: $(wc -l <"$RD/calls")"; fi
check "run.sh: gmx-2 reported as beyond the round" grep -q "representations/gmx-2 already at 5000 evaluations\$" "$TMPD/out"
check "run.sh: dct-1 (at 3640) resumed to 4000" grep -qx -- "evolve --resume $RD/representations/dct-1 --evaluations 4000 --threads 1 --quiet" "$RD/calls"
check "run.sh: cppn-2 started with its representation and seed" grep -qx -- "evolve --representation cppn --seed 2 --evaluations 4000 --threads 1 --quiet --no-pictures --out $RD/representations/cppn-2" "$RD/calls"
check "run.sh: the runs in the interleaved order: $(tr '\n' ' ' <"$RD/order")" [ "$(tr '\n' ' ' <"$RD/order")" = "dct-1 cppn-1 gmx-1 dct-2 cppn-2 dct-3 cppn-3 gmx-3 " ]
check "run.sh: the busy folder skipped" grep -q "representations/cppn-3 skipped: another runner is working in it\$" "$TMPD/out"
check "run.sh: a started run reported at its count" grep -q "representations/gmx-3 4000 evaluations\$" "$TMPD/out"
check "run.sh: the best robot at the round's count kept" sh -c "grep -qx 'the best at 4000' '$RD/representations/dct-1/best-4000.genome' && [ -f '$RD/representations/gmx-3/best-4000.genome' ]"
check "run.sh: none kept for a run beyond the round or one the other runner has" sh -c "[ ! -e '$RD/representations/gmx-2/best-4000.genome' ] && [ ! -e '$RD/representations/cppn-3/best-4000.genome' ]"
# RUN_PLAN=1: "FOLDER DONE EVALS" a run, nothing run and no folder made
rm -f "$RD/calls"
FIG6_SEEDS=3 RUN_PLAN=1 sh results/run.sh "$F" "$RD" fig6-4500 >"$TMPD/plan" 2>&1
check "run.sh RUN_PLAN: nothing run" [ ! -e "$RD/calls" ]
check "run.sh RUN_PLAN: a line a run: $(tr '\n' '/' <"$TMPD/plan")" sh -c "[ \$(wc -l <'$TMPD/plan') -eq 9 ] &&
    grep -qx '$RD/representations/dct-1 4000 4500' '$TMPD/plan' && grep -qx '$RD/representations/gmx-2 5000 4500' '$TMPD/plan' &&
    grep -qx '$RD/representations/cppn-3 0 4500' '$TMPD/plan'"
mkdir -p "$TMPD/plan-dir"
RUN_PLAN=1 expect_ok sh results/run.sh "$F" "$TMPD/plan-dir" others-2000
check "run.sh RUN_PLAN: 18 lines, no folder made: $(ls "$TMPD/plan-dir")" sh -c "[ \$(grep -c ' 0 2000\$' '$TMPD/out') -eq 18 ] && [ -z \"\$(ls -A '$TMPD/plan-dir')\" ]"
rm -f "$RD/calls" "$RD/order"
FAKE_BUSY=none FAKE_FAIL=cppn-1 expect_fail 1 "cppn-1: no space left" sh results/run.sh "$F" "$RD" fig6-4000
check "run.sh: no run after the failing one: $(tr '\n' ' ' <"$RD/order")" [ "$(tr '\n' ' ' <"$RD/order")" = "dct-1 cppn-1 " ]
# by default Figure 6 is seeds 1..10 of each representation (gmx-2, at 5000, left alone again)
rm -f "$RD/calls" "$RD/order"
FAKE_BUSY=none FAKE_FAIL=none expect_ok sh results/run.sh "$F" "$RD" fig6-4500
check "run.sh: seeds 1..10, 29 calls: $(wc -l <"$RD/calls")" [ "$(wc -l <"$RD/calls")" -eq 29 ]
check "run.sh: the last run of the round is gmx-10: $(tail -n 1 "$RD/order")" [ "$(tail -n 1 "$RD/order")" = gmx-10 ]
check "run.sh: cppn-10 started with its seed" grep -qx -- "evolve --representation cppn --seed 10 --evaluations 4500 --threads 1 --quiet --no-pictures --out $RD/representations/cppn-10" "$RD/calls"
# the other experiments, seeds 1..3 (18 runs), and seed 1 of each representation to the full budget
rm -f "$RD/calls" "$RD/order"
FAKE_BUSY=none FAKE_FAIL=none expect_ok sh results/run.sh "$F" "$RD" others-2000
check "run.sh: others-2000 makes 18 runs: $(wc -l <"$RD/calls")" [ "$(wc -l <"$RD/calls")" -eq 18 ]
check "run.sh: the friction variant of seed 3" grep -qx -- "evolve --mu_kinetic 0.4 --mu_static 0.5 --seed 3 --evaluations 2000 --threads 1 --quiet --no-pictures --out $RD/friction/k0.4_s0.5-3" "$RD/calls"
rm -f "$RD/calls" "$RD/order"
FAKE_BUSY=none FAKE_FAIL=none expect_ok sh results/run.sh "$F" "$RD" full-20000
check "run.sh: full-20000 resumes seed 1 of each: $(tr '\n' ' ' <"$RD/order")" [ "$(tr '\n' ' ' <"$RD/order")" = "dct-1 cppn-1 gmx-1 " ]
check "run.sh: to 20,000 evaluations" [ "$(grep -c -- '--evaluations 20000' "$RD/calls")" -eq 3 ]
# the actuation experiment: GMX and CPPN, five variants, seeds 1..5 (50 runs) on a 10^3 workspace;
# the two-material control's material a single argument, its spaces kept
rm -f "$RD/calls" "$RD/order"
FAKE_BUSY=none FAKE_FAIL=none expect_ok sh results/run.sh "$F" "$RD" actuation-2000
check "run.sh: actuation-2000 makes 50 runs: $(wc -l <"$RD/calls")" [ "$(wc -l <"$RD/calls")" -eq 50 ]
check "run.sh: the two-material control of seed 2" grep -qx -- "evolve --representation gmx --workspace 10 --palette unshackled --materials 2 --material2 muscle modulus=5e6 density=1e6 cte=0.01 phase=0 poisson=0.35 color=ff0000 --seed 2 --evaluations 2000 --threads 1 --quiet --no-pictures --out $RD/actuation/gmx-two-global-2" "$RD/calls"
m2="$(grep -c . "$RD/material2") $(sort -u "$RD/material2")"
check "run.sh: its material one argument, ten runs: $m2" [ "$m2" = "10 muscle modulus=5e6 density=1e6 cte=0.01 phase=0 poisson=0.35 color=ff0000" ]
check "run.sh: the four-material evolved-phase CPPN of seed 5" grep -qx -- "evolve --representation cppn --workspace 10 --palette unshackled --actuation phase --seed 5 --evaluations 2000 --threads 1 --quiet --no-pictures --out $RD/actuation/cppn-four-phase-5" "$RD/calls"
check "run.sh: the seed's palette with global actuation first" grep -qx -- "evolve --representation gmx --workspace 10 --seed 1 --evaluations 2000 --threads 1 --quiet --no-pictures --out $RD/actuation/gmx-seed-global-1" "$RD/calls"
expect_fail 2 "the stage takes a number of evaluations" sh results/run.sh "$F" "$RD" actuation-
expect_fail 2 "the stage takes a number of evaluations" sh results/run.sh "$F" "$RD" fig6-4k
expect_fail 2 "the stage takes a number of evaluations" sh results/run.sh "$F" "$RD" others-
expect_fail 2 "unknown stage 'fig7-2000'" sh results/run.sh "$F" "$RD" fig7-2000
# --- results/runners.sh, with a stand-in for amorph that holds its folder (mkdir of a lock, as the
# real one refuses a folder another is working in) and, unless FAKE_QUICK, works until SIGTERM,
# then writes its checkpoint as the real one does on Ctrl-C and SIGTERM (or gives up after 120 s, so
# that a failing test leaves nothing going)
G=$TMPD/fake-runner RR=$TMPD/runners
cat >"$G" <<'FAKE'
#!/bin/sh
while [ $# -gt 0 ]; do
    case $1 in --resume | --out) dir=$2 ;; --evaluations) n=$2 ;; esac
    shift
done
mkdir -p "$dir"
mkdir "$dir/lock.d" 2>/dev/null || { echo "amorph: $dir: another amorph is working in this folder" >&2; exit 1; }
echo "$dir" >>"$RR/calls"
stopped=0
trap 'stopped=1' TERM
touch "$dir/started"
t=0
while [ -z "${FAKE_QUICK:-}" ] && [ $stopped = 0 ] && [ $t -lt 1200 ]; do sleep 0.1; t=$((t + 1)); done
rmdir "$dir/lock.d"
if [ $stopped = 1 ]; then echo "checkpoint" >"$dir/checkpoint.txt"; echo "amorph: $dir: stopped" >&2; exit 143; fi
printf 'evaluations = %s\n' "$n" >"$dir/summary.txt"
printf 'evaluations %s\n' "$n" >"$dir/checkpoint.txt"
FAKE
chmod +x "$G"
mkdir -p "$RR"
export RR
# wait_for WHAT CMD...: polls CMD until it succeeds, 60 s at the most (the runners start in the background)
wait_for() {
    what=$1
    shift
    t=0
    while ! "$@" 2>/dev/null; do
        t=$((t + 1))
        [ $t -lt 600 ] || { ko "runners.sh: no $what after 60 s"; return 1; }
        sleep 0.1
    done
    ok
}
RUNNER_STAGES=fig6-1000 FIG6_SEEDS=2 expect_ok sh results/runners.sh start "$G" "$RR"
check "runners.sh: two runners started: $(cat "$TMPD/out")" [ "$(grep -c '^runner [12]: process group [0-9]* ' "$TMPD/out")" -eq 2 ]
check "runners.sh: the program and run.sh copied for the runners" sh -c "cmp -s '$G' '$RR/.runners/amorph' && cmp -s results/run.sh '$RR/.runners/run.sh'"
# the two take one round: dct-1 and, dct-1 being held, cppn-1
wait_for "two runs going" sh -c "[ -f '$RR/representations/dct-1/started' ] && [ -f '$RR/representations/cppn-1/started' ]"
expect_ok sh results/runners.sh status "$RR"
check "runners.sh status: both going: $(cat "$TMPD/out")" [ "$(grep -c '^runner [12]: going' "$TMPD/out")" -eq 2 ]
expect_fail 1 "runner 1 is going already" sh results/runners.sh start "$G" "$RR"
expect_ok sh results/runners.sh stop "$RR"
check "runners.sh stop: said" grep -qx "runners stopped" "$TMPD/out"
check "runners.sh stop: both runs ended at a checkpoint" sh -c "grep -qx checkpoint '$RR/representations/dct-1/checkpoint.txt' && grep -qx checkpoint '$RR/representations/cppn-1/checkpoint.txt'"
check "runners.sh stop: no run started after: $(tr '\n' ' ' <"$RR/calls")" [ "$(wc -l <"$RR/calls")" -eq 2 ]
check "runners.sh stop: the runs' words in the logs" sh -c "cat '$RR'/.runners/runner-*.log | grep -q 'cppn-1: stopped'"
check "runners.sh stop: run.sh's files of words removed" sh -c "! ls '$RR'/.run.*.err 2>/dev/null"
expect_ok sh results/runners.sh status "$RR"
check "runners.sh status: neither going: $(cat "$TMPD/out")" [ "$(grep -c '^runner [12]: not going' "$TMPD/out")" -eq 2 ]
# started again, the runs resumed and the round finished: every run at its count, each log ends
FAKE_QUICK=1 RUNNER_STAGES=fig6-1000 FIG6_SEEDS=2 expect_ok sh results/runners.sh start "$G" "$RR"
wait_for "end of the round" sh -c "tail -n 1 '$RR/.runners/runner-1.log' | grep -q 'all rounds done' && tail -n 1 '$RR/.runners/runner-2.log' | grep -q 'all rounds done'"
n=0
for r in dct-1 cppn-1 gmx-1 dct-2 cppn-2 gmx-2; do grep -qx 'evaluations = 1000' "$RR/representations/$r/summary.txt" 2>/dev/null && n=$((n + 1)); done
check "runners.sh: the six runs of the round at 1000 evaluations: $n" [ $n -eq 6 ]
expect_ok sh results/runners.sh stop "$RR"
expect_fail 2 "not an executable" sh results/runners.sh start "$TMPD/none" "$RR"
expect_fail 2 "no such folder" sh results/runners.sh start "$G" "$TMPD/none"
expect_fail 2 "usage: sh results/runners.sh" sh results/runners.sh restart "$RR"
RUNNERS=x expect_fail 2 "RUNNERS='x': a whole number" sh results/runners.sh status "$RR"
STOP_WAIT=1m expect_fail 2 "STOP_WAIT='1m': a whole number of seconds" sh results/runners.sh stop "$RR"
# whatever failed above, nothing of the runners is left going
for f in "$RR"/.runners/runner-*.pid; do [ -f "$f" ] && kill -KILL "-$(cat "$f")" 2>/dev/null; done
summary cli_report
