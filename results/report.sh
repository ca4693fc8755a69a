#!/bin/sh
# The per-robot figures of docs/results.md, from the run folders results/run.sh makes:
#   sh results/report.sh AMORPH DIR [--pictures]
# For each run folder DIR/EXPERIMENT/RUN (config.txt, log.csv, best.genome) it writes
# RUN/gait30.json, the best robot simulated in the run's settings over 30 actuation cycles instead
# of the evolved 10 (`amorph sim RUN --cycles 30 --json`: travel per cycle, sustained, airborne,
# the gait's name, the material mix), and with --pictures RUN/best.png, its filmstrip over the
# evolved cycles (`amorph render`, 1200 x 300 pixels). Then it prints one Markdown table, a row per run: evaluations
# done, best fitness, voxels and the material mix, and the 30-cycle gait. The files are
# deterministic (gait30.json leaves out the wall time): the same run folder gives the same files on
# every float build.
set -eu
AMORPH=$1 DIR=$2 PICTURES=${3:-}
[ -x "$AMORPH" ] || { echo "report.sh: $AMORPH: not an executable" >&2; exit 2; }
[ -d "$DIR" ] || { echo "report.sh: $DIR: no such folder" >&2; exit 2; }

# json FILE KEY: a number or string field of a one-line JSON object
json() { sed -n "s/.*\"$2\": *\"\{0,1\}\([^\",]*\)\"\{0,1\}[,}].*/\1/p" "$1"; }
# jarr FILE KEY: an array field, its items separated by spaces, strings unquoted
jarr() { sed -n "s/.*\"$2\": *\[\([^]]*\)\].*/\1/p" "$1" | tr -d '"' | sed 's/, */ /g'; }

echo "| run | evaluations | best fitness (m) | voxels | material mix | gait (30 cycles) | travel per cycle, first / last half (mm) | sustained | airborne |"
echo "|---|---:|---:|---:|---|---|---:|---:|---:|"
for cfg in "$DIR"/*/*/config.txt; do
    [ -f "$cfg" ] || continue
    run=${cfg%/config.txt}
    [ -f "$run/best.genome" ] || continue
    name=${run#"$DIR"/}
    evals=$(tail -n 1 "$run/log.csv" | cut -d, -f2)
    best=$(tail -n 1 "$run/log.csv" | cut -d, -f3)
    "$AMORPH" sim "$run" --cycles 30 --json 2>/dev/null | sed 's/"wall_seconds": [^,]*, //' >"$run/gait30.json"
    if [ "$PICTURES" = "--pictures" ]; then
        "$AMORPH" render "$run" --width 1200 --height 300 --out "$run/best.png" >/dev/null
    fi
    g=$run/gait30.json
    names=$(jarr "$g" materials)
    counts=$(jarr "$g" material_voxels)
    mix=$(echo "$names" "|" "$counts" | awk -F'|' '{ n = split($1, a, " "); split($2, b, " "); s = "";
        for (i = 1; i <= n; i++) s = s (i > 1 ? ", " : "") a[i] " " b[i]; print s }')
    first=$(json "$g" travel_first_half)
    last=$(json "$g" travel_last_half)
    printf '| %s | %s | %.4f | %s | %s | %s | %.2f / %.2f | %.2f | %.2f |\n' "$name" "$evals" "$best" "$(json "$g" voxels)" \
        "$mix" "$(json "$g" gait)" "$(echo "$first" | awk '{ print $1 * 1000 }')" "$(echo "$last" | awk '{ print $1 * 1000 }')" \
        "$(json "$g" sustained)" "$(json "$g" airborne)"
done
