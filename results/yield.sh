#!/bin/sh
# What the runners did since a ship: for each run folder of NOW (results/run.sh's DIR/EXPERIMENT/RUN),
# the evaluations and the runner-hours of the generations its log.csv holds past where the same run
# stands in BEFORE (the shipped copy: results/ until the next ship; a run BEFORE lacks counts from
# 0). Evaluations: the last logged count less BEFORE's (`amorph report last`, which reads and checks
# the whole log.csv); hours: the sum of wall_s (column 8) over the rows past it, as logged (a
# generation the runners were paused in counts whole: the compute table of report.sh judges
# pauses, this counts what the period's log holds).
#   sh results/yield.sh AMORPH BEFORE NOW
# Prints a Markdown table, a row per run that moved and a last row of the totals; nothing moved, the
# header and the totals of 0. A damaged log.csv is refused with amorph's FILE:LINE message.
set -eu
[ $# -eq 3 ] || { echo "usage: sh results/yield.sh AMORPH BEFORE NOW" >&2; exit 2; }
AMORPH=$1 BEFORE=$2 NOW=$3
[ -x "$AMORPH" ] || { echo "yield.sh: $AMORPH: not an executable" >&2; exit 2; }
for d in "$BEFORE" "$NOW"; do
    [ -d "$d" ] || { echo "yield.sh: $d: no such folder" >&2; exit 2; }
done
# count RUN: the evaluations of RUN's last logged generation (0 before its first)
count() {
    if [ -f "$1/log.csv" ] && tail -n +2 "$1/log.csv" | grep -q .; then
        last=$("$AMORPH" report last "$1") || return 1
        echo "${last% *}"
    else
        echo 0
    fi
}
echo "| run | evaluations before | evaluations now | evaluations | runner-hours |"
echo "|---|---:|---:|---:|---:|"
rows=$(for log in "$NOW"/*/*/log.csv; do
    [ -f "$log" ] || continue
    run=${log%/log.csv}
    name=${run#"$NOW"/}
    from=$(count "$BEFORE/$name") || exit 1
    to=$(count "$run") || exit 1
    [ "$to" -gt "$from" ] || continue
    awk -F, -v from="$from" -v to="$to" -v name="$name" 'NR > 1 && $2 + 0 > from + 0 { h += $8 / 3600 }
        END { printf "%s %d %d %.9g\n", name, from, to, h }' "$log"
done) || exit 1
printf '%s\n' "$rows" | awk 'NF == 4 { printf "| %s | %d | %d | %d | %.2f |\n", $1, $2, $3, $3 - $2, $4; e += $3 - $2; h += $4 }
    END { printf "| all | | | %d | %.2f |\n", e, h }'
