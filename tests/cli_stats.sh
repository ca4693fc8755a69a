# tests/cli_stats.sh: amorph stats on run folders made here, whose log.csv and gait30.json hold
# values with known answers: the groups by folder name and by --group, the best so far at every
# 1,000 evaluations (rows at or below the count, a log's columns found by name), the tables of
# groups, pairs and ranking, the sustained score of cycles 11-30 with the gaits, the JSON; then bad
# input, each refused in one line. The expected rows were computed apart from the program (python3:
# p by Simpson's rule on the t density, the Mann-Whitney p by listing every subset, the runs needed
# by bisection on the integrated distribution; Holm's correction by hand: at 1000 the three tested
# pairs, Welch 0.0213 x 3 = 0.064 (no longer significant), 0.0824 x 2 = 0.165, 0.285; Mann-Whitney
# 0.1 x 3, 0.2 x 2, then 0.4 held at 0.4; at 2000 a family of one, unchanged). Desktop builds (the board build has no stats).
# Run from the repository root.
. tests/shlib.sh

if ! "$AMORPH" --help 2>/dev/null | grep -q 'profile=desktop'; then
    echo "cli_stats: not a desktop build: skipped"
    summary cli_stats
    exit $?
fi
R=$TMPD/runs
h="generation,evaluations,best,mean,median,diverged,empty,wall_s,unsettled"
# log NAME ROWS...: R/NAME/log.csv with a row per "evaluations:best"
log() {
    mkdir -p "$R/$1"
    d=$R/$1; shift
    { echo "$h"; g=0; for r in "$@"; do echo "$g,${r%:*},${r#*:},0,0,0,0,1,0"; g=$((g + 1)); done; } >"$d/log.csv"
}
# A-1's columns in another order: read by name. At 1000 it holds 0.010 (its row at 990; 1010's
# 0.030 is past the count); A-3's generation best falls to 0.011 at 1000 under its 0.014 at 500: the
# best so far counts. C-2 stops at 1500, so C has no 2000; D has one run: no test.
mkdir -p "$R/A-1"
printf 'best,generation,evaluations,mean,median,diverged,empty,wall_s,unsettled\n0.005,0,480,0,0,0,0,1,0\n0.010,1,990,0,0,0,0,1,0\n0.030,2,1010,0,0,0,0,1,0\n0.030,3,2000,0,0,0,0,1,0\n' >"$R/A-1/log.csv"
log A-2 500:0.012 1000:0.012 2000:0.020
log A-3 500:0.014 1000:0.011 2000:0.025
log B-1 1000:0.004 2000:0.010
log B-2 1000:0.006 2000:0.012
log B-3 1000:0.008 2000:0.014
log C-1 1000:0.009 2000:0.009
log C-2 1000:0.007 1500:0.007
log D-1 1000:0.020 2000:0.020

expect_ok "$AMORPH" stats "$R/A-1" "$R/A-2" "$R/A-3" "$R/B-1" "$R/B-2" "$R/B-3" "$R/C-1" "$R/C-2/" "$R/D-1"
cat >"$TMPD/want" <<'EOF'
| evaluations | group | runs | mean best fitness so far (mm) | standard deviation (mm) | standard error (mm) |
|---:|---|---:|---:|---:|---:|
| 1000 | A | 3 | 12.00 | 2.00 | 1.15 |
| 1000 | B | 3 | 6.00 | 2.00 | 1.15 |
| 1000 | C | 2 | 8.00 | 1.41 | 1.00 |
| 1000 | D | 1 | 20.00 | - | - |
| 2000 | A | 3 | 25.00 | 5.00 | 2.89 |
| 2000 | B | 3 | 12.00 | 2.00 | 1.15 |
| 2000 | D | 1 | 20.00 | - | - |

| evaluations | pair | difference (mm) | Welch's t | df | p (Welch) | p (Welch, Holm) | U | p (Mann-Whitney) | p (Mann-Whitney, Holm) | Cohen's d | Hedges' g | runs for 80% power |
|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|
| 1000 | D - A | 8.00 | no test: D has 1 run | | | | | | | | | |
| 1000 | D - C | 12.00 | no test: D has 1 run | | | | | | | | | |
| 1000 | D - B | 14.00 | no test: D has 1 run | | | | | | | | | |
| 1000 | A - C | 4.00 | 2.62 | 2.9 | 0.082 | 0.165 | 6 | 0.200 | 0.400 | 2.19 | 1.59 | 5 |
| 1000 | A - B | 6.00 | 3.67 | 4.0 | 0.021 | 0.064 | 9 | 0.100 | 0.300 | 3.00 | 2.39 | 4 |
| 1000 | C - B | 2.00 | 1.31 | 2.9 | 0.285 | 0.285 | 5 | 0.400 | 0.400 | 1.10 | 0.79 | 15 |
| 2000 | A - D | 5.00 | no test: D has 1 run | | | | | | | | | |
| 2000 | A - B | 13.00 | 4.18 | 2.6 | 0.032 | 0.032 | 9 | 0.100 | 0.100 | 3.41 | 2.72 | 3 |
| 2000 | D - B | 8.00 | no test: D has 1 run | | | | | | | | | |

| evaluations | ranking by mean | significant at 0.05 after Holm's correction, Welch's t | significant at 0.05 after Holm's correction, Mann-Whitney |
|---:|---|---|---|
| 1000 | D > A > C > B | none | none |
| 2000 | A > D > B | A > B | none |
EOF
if cmp -s "$TMPD/want" "$TMPD/out"; then ok; else ko "stats tables: $(diff "$TMPD/want" "$TMPD/out" | head -20)"; fi

# --pair: only the pairs named, either way round, are compared, and they alone are Holm's family:
# at 1000 A - B's 0.0213 x 2 = 0.043 is significant again, A - C's 0.082 x 1 held at 0.082
expect_ok "$AMORPH" stats "$R/A-1" "$R/A-2" "$R/A-3" "$R/B-1" "$R/B-2" "$R/B-3" "$R/C-1" "$R/C-2/" "$R/D-1" --pair A,B --pair C,A
cat >"$TMPD/want" <<'EOF2'
| evaluations | pair | difference (mm) | Welch's t | df | p (Welch) | p (Welch, Holm) | U | p (Mann-Whitney) | p (Mann-Whitney, Holm) | Cohen's d | Hedges' g | runs for 80% power |
|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|
| 1000 | A - C | 4.00 | 2.62 | 2.9 | 0.082 | 0.082 | 6 | 0.200 | 0.200 | 2.19 | 1.59 | 5 |
| 1000 | A - B | 6.00 | 3.67 | 4.0 | 0.021 | 0.043 | 9 | 0.100 | 0.200 | 3.00 | 2.39 | 4 |
| 2000 | A - B | 13.00 | 4.18 | 2.6 | 0.032 | 0.032 | 9 | 0.100 | 0.100 | 3.41 | 2.72 | 3 |

| evaluations | ranking by mean | significant at 0.05 after Holm's correction, Welch's t | significant at 0.05 after Holm's correction, Mann-Whitney |
|---:|---|---|---|
| 1000 | D > A > C > B | A > B | none |
| 2000 | A > D > B | A > B | none |
EOF2
if sed -n '/| pair |/,$p' "$TMPD/out" | cmp -s "$TMPD/want" -; then ok; else ko "--pair tables: $(sed -n '/| pair |/,$p' "$TMPD/out" | diff "$TMPD/want" - | head -20)"; fi
expect_ok "$AMORPH" stats --json "$R/A-1" "$R/A-2" "$R/A-3" "$R/B-1" "$R/B-2" "$R/B-3" --pair B,A
check "--pair, JSON: the one pair" [ "$(grep -o '"a": "[A-D]", "b": "[A-D]"' "$TMPD/out" | tr '\n' ' ')" = '"a": "A", "b": "B" "a": "A", "b": "B" ' ]
expect_fail 2 "stats: --pair A,X: no group X among the runs named" "$AMORPH" stats "$R/A-1" "$R/B-1" --pair A,X
expect_fail 2 "stats: --pair A,A: a group against itself" "$AMORPH" stats "$R/A-1" "$R/B-1" --pair A,A
expect_fail 2 "stats: --pair needs NAME,NAME \(two groups\)" "$AMORPH" stats "$R/A-1" --pair A
expect_fail 2 "stats: --pair needs NAME,NAME \(two groups\)" "$AMORPH" stats "$R/A-1" --pair A,B,C

# JSON: the same numbers in m, a pair without a test, the ranking
expect_ok "$AMORPH" stats --json "$R/A-1" "$R/A-2" "$R/A-3" "$R/B-1" "$R/B-2" "$R/B-3" "$R/D-1"
cp "$TMPD/out" "$TMPD/j.json"
check "JSON: A's mean at 1000 is 0.012" grep -qF '{"group": "A", "n": 3, "mean": 0.012, "sd": 0.002,' "$TMPD/j.json"
check "JSON: A against B at 1000, exact p 0.1, 4 runs needed, Holm's p over the pairs of A, B (and D: no test)" \
    grep -q '"a": "A", "b": "B", "tested": true, "difference": 0.006,.*"p_welch": 0.0213116411, "p_welch_holm": 0.0213116411, "u": 9, "p_mann_whitney": 0.1, "p_mann_whitney_holm": 0.1, "mann_whitney_exact": true,[^}]*"runs_needed": 4}' "$TMPD/j.json"
check "JSON: D's pairs untested" grep -qF '"a": "D", "b": "A", "tested": false, "difference": 0.008, "t": null' "$TMPD/j.json"
check "JSON: the rankings" grep -q '"ranking": \["D", "A", "B"\]}, {"evaluations": 2000,.*"ranking": \["A", "D", "B"\]}\]}$' "$TMPD/j.json"
check "JSON: one line" [ "$(wc -l <"$TMPD/j.json")" -eq 1 ]

# --group: the runs of one group named explicitly, beside a group by folder name; --every 500:
# A-1's 480-row best holds at 500 for it, A-2 and A-3 have rows at 500
expect_ok "$AMORPH" stats --every 500 --group mixed="$R/A-1,$R/A-2,$R/B-1" "$R/B-2" "$R/B-3"
# mixed at 500: A-1 0.005 (its row at 480), A-2 0.012, B-1 0.004 (no row at or below 500: its
# first row's); at 1000: 0.010, 0.012, 0.004
row=$(grep '^| 500 | mixed |' "$TMPD/out")
check "--group, --every 500: mixed at 500: '$row'" [ "$row" = "| 500 | mixed | 3 | 7.00 | 4.36 | 2.52 |" ]
row=$(grep '^| 1000 | mixed |' "$TMPD/out")
check "--group: mixed at 1000: '$row'" [ "$row" = "| 1000 | mixed | 3 | 8.67 | 4.16 | 2.40 |" ]
row=$(grep '^| 1000 | B |' "$TMPD/out")
check "--group: B is B-2 and B-3 alone: '$row'" [ "$row" = "| 1000 | B | 2 | 7.00 | 1.41 | 1.00 |" ]
check "--every 500: rows at 500, 1000, 1500 and 2000" [ "$(grep -c '^| [0-9]* | mixed |' "$TMPD/out")" -eq 4 ]

# the sustained score: gait30.json's sustained_travel (cycles 11-30), and the gaits
# gait NAME GAIT V W: R/NAME/gait30.json, cycles 1-10 travel 0.009 m, cycles 11-30 alternate V and W
# (sustained_travel their mean: a body that goes straight on)
gait() {
    mkdir -p "$R/$1"
    awk -v g="$2" -v v="$3" -v w="$4" 'BEGIN { s = ""; for (i = 1; i <= 30; i++) s = s (i > 1 ? ", " : "") (i <= 10 ? 0.009 : i % 2 ? v : w)
        printf "{\"robot\": \"x\", \"fitness\": 0.01, \"sustained_travel\": %.9g, \"cycle_travel\": [%s], \"sustained\": 0.5, \"gait\": \"%s\"}\n", (v + w) / 2, s, g }' >"$R/$1/gait30.json"
}
gait X-1 bounce 0.001 0.001
gait X-2 flop 0.001 0.002
gait Y-1 scoot 0.0005 0.0005
gait Y-2 roll 0.0007 0.0007
expect_ok "$AMORPH" stats --score sustained "$R/X-1" "$R/X-2" "$R/Y-1" "$R/Y-2"
cat >"$TMPD/want" <<'EOF'
| score | group | runs | mean travel per cycle, cycles 11-30 (mm) | standard deviation (mm) | standard error (mm) | still | flop | scoot | bounce | roll |
|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|
| sustained | X | 2 | 1.250 | 0.354 | 0.250 | 0 | 1 | 0 | 1 | 0 |
| sustained | Y | 2 | 0.600 | 0.141 | 0.100 | 0 | 0 | 1 | 0 | 1 |

| score | pair | difference (mm) | Welch's t | df | p (Welch) | p (Welch, Holm) | U | p (Mann-Whitney) | p (Mann-Whitney, Holm) | Cohen's d | Hedges' g | runs for 80% power |
|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|
| sustained | X - Y | 0.650 | 2.41 | 1.3 | 0.200 | 0.200 | 4 | 0.333 | 0.333 | 2.41 | 1.36 | 4 |

| score | ranking by mean | significant at 0.05 after Holm's correction, Welch's t | significant at 0.05 after Holm's correction, Mann-Whitney |
|---:|---|---|---|
| sustained | X > Y | none | none |
EOF
if cmp -s "$TMPD/want" "$TMPD/out"; then ok; else ko "sustained tables: $(diff "$TMPD/want" "$TMPD/out" | head -20)"; fi
expect_ok "$AMORPH" stats --score sustained --json "$R/X-1" "$R/X-2" "$R/Y-1" "$R/Y-2"
check "sustained JSON: X's gaits and mean" sh -c "grep -q '\"group\": \"X\", \"runs\": .*, \"still\": 0, \"flop\": 1, \"scoot\": 0, \"bounce\": 1, \"roll\": 0}' '$TMPD/out' && grep -q '\"group\": \"X\", \"n\": 2, \"mean\": 0.00125,' '$TMPD/out'"

# a p below 0.001: two digits and a power of ten, the same from every C library
for k in 1 2 3; do log "lo-$k" "1000:0.01$k"; log "hi-$k" "1000:0.02$k"; done
expect_ok "$AMORPH" stats "$R/lo-1" "$R/lo-2" "$R/lo-3" "$R/hi-1" "$R/hi-2" "$R/hi-3"
check "a small p: '$(grep '^| 1000 | hi - lo |' "$TMPD/out")'" grep -qxF "| 1000 | hi - lo | 10.00 | 12.25 | 4.0 | 2.6e-04 | 2.6e-04 | 9 | 0.100 | 0.100 | 10.00 | 7.98 | 2 |" "$TMPD/out"

# nothing reached: a note, exit 0, no table
log E-1 500:0.01
log E-2 900:0.01
"$AMORPH" stats "$R/E-1" "$R/E-2" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
check "no count reached: exit 0 ($rc), a note, no output" sh -c "[ $rc -eq 0 ] && [ ! -s '$TMPD/out' ] && grep -q 'nothing to compare' '$TMPD/err'"

# a run that has reached no count yet (one just started) is left out of its group's best fitness,
# with a note, rather than hiding the group at every count: B's three runs at 1000 beside B-4 at 40
# evaluations; E, whose one run has reached none, is no group of the tables
log B-4 20:0.001 40:0.002
log E-1 20:0.003
expect_ok "$AMORPH" stats "$R/B-1" "$R/B-2" "$R/B-3" "$R/B-4" "$R/C-1" "$R/C-2" "$R/E-1"
check "a run just started: B at 1000 over its three runs that reached it" grep -qF "| 1000 | B | 3 | 6.00 | 2.00 | 1.15 |" "$TMPD/out"
check "a run just started: a note names it" grep -qF "$R/B-4 has not reached 1000 evaluations: left out of B" "$TMPD/err"
check "a group none of whose runs reached a count: no row" sh -c "! grep -q '| E |' '$TMPD/out'"
check "a group none of whose runs reached a count: no note (nothing to leave out)" sh -c "! grep -q 'E-1' '$TMPD/err'"

# --- bad input: one line, exit 2 ---
mkdir -p "$R/nolog-1" "$R/empty-1" "$R/bad-1" "$R/short-1" "$R/back-1" "$R/g10-1" "$R/gname-1" "$R/gnum-1"
expect_fail 2 "stats: .*/nolog-1/log.csv: no such file \(not a run folder" "$AMORPH" stats "$R/A-1" "$R/nolog-1"
echo "$h" >"$R/empty-1/log.csv"
expect_fail 2 "empty-1/log.csv: no generations logged yet" "$AMORPH" stats "$R/empty-1"
printf '%s\n0,500,0.01,0,0,0,0,1,0\n1,1000,zero,0,0,0,0,1,0\n' "$h" >"$R/bad-1/log.csv"
expect_fail 2 "bad-1/log.csv:3: best \(column 3\): not a number: 'zero'" "$AMORPH" stats "$R/bad-1"
printf '%s\n0,500,0.01,0,0\n' "$h" >"$R/short-1/log.csv"
expect_fail 2 "short-1/log.csv:2: 5 fields, the header has 9 columns" "$AMORPH" stats "$R/short-1"
printf '%s\n0,500,0.01,0,0,0,0,1,0\n1,400,0.01,0,0,0,0,1,0\n' "$h" >"$R/back-1/log.csv"
expect_fail 2 "back-1/log.csv:3: evaluations go backwards \(400 after 500\)" "$AMORPH" stats "$R/back-1"
printf 'no,header,here\n' >"$R/nolog-1/log.csv"
expect_fail 2 "nolog-1/log.csv:1: not a log.csv header" "$AMORPH" stats "$R/nolog-1"
expect_fail 2 "A-1/gait30.json: no such file \(results/report.sh writes it" "$AMORPH" stats --score sustained "$R/A-1"
printf '{"cycle_travel": [0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001, 0.001], "gait": "scoot"}\n' >"$R/g10-1/gait30.json"
expect_fail 2 "g10-1/gait30.json: cycle_travel holds 20 cycles; the sustained score needs 30" "$AMORPH" stats --score sustained "$R/g10-1"
gait gname-1 hop 0.001 0.001
expect_fail 2 "gname-1/gait30.json:1: gait: not still, flop, scoot, bounce or roll: '\"hop\"'" "$AMORPH" stats --score sustained "$R/gname-1"
mkdir -p "$R/nosus-1" && sed 's/"sustained_travel": [^,]*, //' "$R/X-1/gait30.json" >"$R/nosus-1/gait30.json"
expect_fail 2 "nosus-1/gait30.json: no \"sustained_travel\" \(amorph sim RUN --cycles 30 --json writes it\)" "$AMORPH" stats --score sustained "$R/nosus-1"
gait gnum-1 scoot 0.001 null
expect_fail 2 "gnum-1/gait30.json:1: cycle_travel\[11\]: not a number: 'null'" "$AMORPH" stats --score sustained "$R/gnum-1"
expect_fail 2 "stats: --score needs best or sustained" "$AMORPH" stats --score worst "$R/A-1"
expect_fail 2 "stats: --every needs a whole number" "$AMORPH" stats --every 0 "$R/A-1"
expect_fail 2 "stats: --group needs NAME=DIR" "$AMORPH" stats --group "$R/A-1"
expect_fail 2 "stats: --group x: an empty folder name" "$AMORPH" stats --group "x=$R/A-1,,$R/A-2"
expect_fail 2 "stats: unknown option '--bands'" "$AMORPH" stats --bands "$R/A-1"
expect_fail 2 "stats: name run folders" "$AMORPH" stats
expect_fail 2 "A-1/: the same run named twice" "$AMORPH" stats "$R/A-1" "$R/A-2" "$R/A-1/"
expect_fail 2 "a group name of 1 to 63 printable characters" "$AMORPH" stats --group "a|b=$R/A-1"
expect_ok "$AMORPH" stats --help
check "--help names the tests" grep -q "Welch's t" "$TMPD/out"
check "amorph --help lists stats" sh -c "'$AMORPH' --help | grep -q '^  stats '"

# amorph report: the tables results/report.sh takes from the program (docs/results.md). fig6 over
# runs whose answers are worked out by hand: dct at 500 has 0.010 and 0.012 (mean 0.011, standard
# error 0.001), at 1000 0.020 and 0.016; gmx-1 holds at 500 its row at 480 (the 990 row is past
# it), at 1000 its 990 row's 0.010 (1010's 0.030 is past it); cppn has no run
P=$TMPD/rep
mkdir -p "$P/dct-1" "$P/dct-2" "$P/gmx-1" "$P/x-1"
{ echo "$h"; echo "0,500,0.010,0,0,0,0,1,0"; echo "1,1000,0.020,0,0,0,0,1,0"; } >"$P/dct-1/log.csv"
{ echo "$h"; echo "0,500,0.012,0,0,0,0,1,0"; echo "1,1000,0.016,0,0,0,0,1,0"; } >"$P/dct-2/log.csv"
{ echo "$h"; echo "0,480,0.005,0,0,0,0,1,0"; echo "1,990,0.010,0,0,0,0,1,0"; echo "2,1010,0.030,0,0,0,0,1,0"; } >"$P/gmx-1/log.csv"
expect_ok "$AMORPH" report fig6 "$P/dct-1" "$P/dct-2/" "$P/gmx-1"
cat >"$TMPD/want" <<'EOF'
| evaluations | DCT | CPPN | GMX |
|---:|---|---|---|
| 500 | 0.0110 +- 0.0010 (2 runs) |  | 0.0050 (1 run) |
| 1000 | 0.0180 +- 0.0020 (2 runs) |  | 0.0100 (1 run) |

| run | 1000 |
|---|---:|
| representations/dct-1 | 0.0200 |
| representations/dct-2 | 0.0160 |
| representations/gmx-1 | 0.0100 |
EOF
check "report fig6: $(diff "$TMPD/want" "$TMPD/out" | head -5)" cmp -s "$TMPD/want" "$TMPD/out"
# compute: wall_s 3600, 3600, 3600 and 36000: the lower median is 3600, the last generation more
# than 5 times it is a pause, counted as 3600: 4 hours, 1 paused; names relative to --root
{ echo "$h"; for g in 0 1 2 3; do w=3600; [ $g = 3 ] && w=36000; echo "$g,$((g * 10 + 10)),0.01,0,0,0,0,$w,0"; done; } >"$P/x-1/log.csv"
expect_ok "$AMORPH" report compute --root "$P" "$P/x-1" "$P/dct-1"
check "report compute: $(cat "$TMPD/out")" [ "$(sed -n 3,4p "$TMPD/out")" = "$(printf '| x-1 | 40 | 4.00 | 1 |\n| dct-1 | 1000 | 0.00 | 0 |')" ]
expect_ok "$AMORPH" report last "$P/gmx-1"
check "report last: the last row's evaluations and best: $(cat "$TMPD/out")" [ "$(cat "$TMPD/out")" = "1010 0.03" ]
# best-at and range: the best so far at 1000 (gmx-1: its 990 row's 0.010; dct-1 and dct-2 their
# 1000 rows), nothing for a run that has not got there; range over the three: 0.0100, 0.0160 and
# 0.0200, mean 0.0153, standard error 0.0029 (sqrt(0.000025333 / 3))
expect_ok "$AMORPH" report best-at 1000 "$P/gmx-1"
check "report best-at: $(cat "$TMPD/out")" [ "$(cat "$TMPD/out")" = "0.0100" ]
expect_ok "$AMORPH" report best-at 1020 "$P/gmx-1"
check "report best-at: nothing before the run got there: '$(cat "$TMPD/out")'" [ ! -s "$TMPD/out" ]
expect_ok "$AMORPH" report range 1000 "$P/dct-1" "$P/dct-2" "$P/gmx-1"
check "report range: $(cat "$TMPD/out")" [ "$(cat "$TMPD/out")" = "3 0.0153 0.0029 0.0100 0.0200" ]
expect_fail 2 "report: best-at needs a number of evaluations" "$AMORPH" report best-at x "$P/gmx-1"
# bodies: the mean voxels per 500 evaluations from each run's evals.csv.gz, columns by name: dct-1
# evaluated 10 and 20 voxels in 1-500 and 7 in 501-1000, gmx-1 5 in 1-500; cppn nothing
printf 'evaluation,generation,voxels\n0,0,10\n499,1,20\n500,2,7\n' | gzip -9n >"$P/dct-1/evals.csv.gz"
printf 'voxels,evaluation\n5,1\n' | gzip -9n >"$P/gmx-1/evals.csv.gz"
expect_ok "$AMORPH" report bodies "$P/dct-1" "$P/gmx-1"
cat >"$TMPD/want" <<'EOF'
| evaluations | DCT voxels | CPPN voxels | GMX voxels |
|---:|---:|---:|---:|
| 1-500 | 15 (2 bodies) | | 5 (1 bodies) |
| 501-1000 | 7 (1 bodies) | | |
EOF
check "report bodies: $(diff "$TMPD/want" "$TMPD/out" | head -5)" cmp -s "$TMPD/want" "$TMPD/out"
head -c 30 "$P/dct-1/evals.csv.gz" >"$P/gmx-1/evals.csv.gz"
expect_fail 2 "report: $P/gmx-1/evals.csv.gz: " "$AMORPH" report bodies "$P/dct-1" "$P/gmx-1"
expect_fail 2 "report: unknown table 'nope'" "$AMORPH" report nope "$P/x-1"
expect_fail 2 "$P/none/log.csv" "$AMORPH" report fig6 "$P/dct-1" "$P/none"
printf '%s\n0,10\n' "$h" >"$P/x-1/log.csv"
expect_fail 2 "$P/x-1/log.csv:2: " "$AMORPH" report compute "$P/x-1"

# the board build leaves statistics out
if [ -n "${BOARD_BUILD:-}" ] && [ -x "$BOARD_BUILD/amorph" ]; then
    expect_fail 2 "stats: not in this build" "$BOARD_BUILD/amorph" stats "$R/A-1"
    expect_fail 2 "report: not in this build" "$BOARD_BUILD/amorph" report fig6 "$R/A-1"
fi
summary cli_stats
