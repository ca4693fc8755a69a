#!/bin/sh
# Copies the reference runs as they stand into results/ (the repository's copy), small enough for
# git: every run folder of SRC (made by results/run.sh) with its config.txt, log.csv, checkpoint.txt,
# best.genome, best.lattice and summaries as they are, and evals.csv compressed (gzip -9n: no name
# or time in the header, so the same table gives the same bytes); then results/report.sh writes
# each best robot's gait30.json and best.png and results/report.md, the table of docs/results.md.
#   sh results/ship.sh AMORPH SRC
# A run still going on is copied at its last checkpoint: its log.csv and evals.csv are cut back to
# the checkpoint's generation and evaluation, as a resume would cut them.
set -eu
AMORPH=$1 SRC=$2
DST=$(dirname "$0")
[ -x "$AMORPH" ] || { echo "ship.sh: $AMORPH: not an executable" >&2; exit 2; }
for ck in "$SRC"/*/*/checkpoint.txt; do
    [ -f "$ck" ] || continue
    run=${ck%/checkpoint.txt}
    name=${run#"$SRC"/}
    out=$DST/$name
    mkdir -p "$out"
    # the checkpoint first: the tables are cut back to it, so they agree even while the run goes on
    # ("last G E ...": generations 0..G logged, E evaluations)
    cp "$run/checkpoint.txt" "$out/checkpoint.txt.new"
    gens=$(awk '$1 == "last" { print $2; exit }' "$out/checkpoint.txt.new")
    evals=$(awk '$1 == "evaluations" && NF == 2 { print $2; exit }' "$out/checkpoint.txt.new")
    for f in config.txt best.genome best.lattice summary.txt summary.json; do
        [ -f "$run/$f" ] && cp "$run/$f" "$out/$f"
    done
    # the summaries name the folder the run was made in; the copy names itself
    [ -f "$out/summary.txt" ] && sed -i "s|^run = .*|run = results/$name|" "$out/summary.txt"
    [ -f "$out/summary.json" ] && sed -i "s|\"run\": \"[^\"]*\"|\"run\": \"results/$name\"|" "$out/summary.json"
    head -n $((gens + 2)) "$run/log.csv" >"$out/log.csv"
    head -n $((evals + 1)) "$run/evals.csv" | gzip -9n >"$out/evals.csv.gz"
    rm -f "$out/evals.csv"
    mv "$out/checkpoint.txt.new" "$out/checkpoint.txt"
done
sh "$DST/report.sh" "$AMORPH" "$DST" --pictures >"$DST/report.md"
du -sh "$DST"
