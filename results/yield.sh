#!/bin/sh
# What the runners did since a ship: for each run folder of NOW (results/run.sh's DIR/EXPERIMENT/RUN),
# the evaluations and the runner-hours of the generations its log.csv holds past where the same run
# stands in BEFORE (the shipped copy: results/ until the next ship; a run BEFORE lacks counts from
# 0). Evaluations: the last row's count less BEFORE's last; hours: the sum of wall_s (column 8) over
# the rows past it, as logged (a generation the runners were paused in counts whole: the compute
# table of report.sh judges pauses, this counts what the period's log holds).
#   sh results/yield.sh BEFORE NOW
# Prints a Markdown table, a row per run that moved and a last row of the totals; nothing moved, the
# header and the totals of 0. A log.csv whose evaluations or wall_s is not a number is refused with
# FILE:LINE.
set -eu
[ $# -eq 2 ] || { echo "usage: sh results/yield.sh BEFORE NOW" >&2; exit 2; }
BEFORE=$1 NOW=$2
for d in "$BEFORE" "$NOW"; do
    [ -d "$d" ] || { echo "yield.sh: $d: no such folder" >&2; exit 2; }
done
# last FILE: the evaluations of the last row of a log.csv (0 without one)
last() {
    [ -f "$1" ] || { echo 0; return 0; }
    awk -F, -v f="$1" 'NR > 1 && NF { if ($2 !~ /^[0-9]+$/) { printf "%s:%d: evaluations (column 2): not a whole number\n", f, NR > "/dev/stderr"; bad = 1; exit 1 } n = $2 }
        END { if (!bad) print n + 0 }' "$1"
}
echo "| run | evaluations before | evaluations now | evaluations | runner-hours |"
echo "|---|---:|---:|---:|---:|"
rows=$(for log in "$NOW"/*/*/log.csv; do
    [ -f "$log" ] || continue
    run=${log%/log.csv}
    name=${run#"$NOW"/}
    from=$(last "$BEFORE/$name/log.csv") || exit 1
    awk -F, -v f="$log" -v from="$from" -v name="$name" '
        NR == 1 || !NF { next }
        $2 !~ /^[0-9]+$/ { printf "%s:%d: evaluations (column 2): not a whole number\n", f, NR > "/dev/stderr"; bad = 1; exit 1 }
        $2 + 0 > from + 0 {
            if ($8 !~ /^[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?$/) { printf "%s:%d: wall_s (column 8): not a number\n", f, NR > "/dev/stderr"; bad = 1; exit 1 }
            h += $8 / 3600; to = $2 + 0
        }
        END { if (!bad && to > from + 0) printf "%s %d %d %.9g\n", name, from, to, h }' "$log" || exit 1
done) || exit 1
printf '%s\n' "$rows" | awk 'NF == 4 { printf "| %s | %d | %d | %d | %.2f |\n", $1, $2, $3, $3 - $2, $4; e += $3 - $2; h += $4 }
    END { printf "| all | | | %d | %.2f |\n", e, h }'
