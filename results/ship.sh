#!/bin/sh
# Copies the reference runs as they stand into results/ (the repository's copy), small enough for
# git: every run folder of SRC (made by results/run.sh) with its config.txt, log.csv, checkpoint.txt
# (without the same-body table, amorph export --checkpoint),
# best.genome, best.lattice, the best robots kept at the rounds' counts (best-N.genome) and
# summaries as they are, and evals.csv compressed (gzip -9n: no name
# or time in the header, so the same table gives the same bytes); then results/report.sh writes
# each best robot's gait30.json and best.png and results/report.md, the table of docs/results.md.
#   sh results/ship.sh AMORPH SRC
# A run still going on is copied at its last checkpoint: its log.csv and evals.csv are cut back to
# the checkpoint's generation and evaluation, as a resume would cut them, its best robot must be
# the checkpoint's (copied again, up to SHIP_TRIES times SHIP_WAIT seconds apart, while a
# generation ending meanwhile has moved one of them on), and its summaries, of an earlier
# command, are left out.
set -eu
AMORPH=$1 SRC=$2
TRIES=${SHIP_TRIES:-10} WAIT=${SHIP_WAIT:-5}
DST=$(dirname "$0")
[ -x "$AMORPH" ] || { echo "ship.sh: $AMORPH: not an executable" >&2; exit 2; }
for ck in "$SRC"/*/*/checkpoint.txt; do
    [ -f "$ck" ] || continue
    run=${ck%/checkpoint.txt}
    name=${run#"$SRC"/}
    out=$DST/$name
    mkdir -p "$out"
    # the checkpoint and the best robot of one moment, gathered in $new first: a generation that
    # ends between the copies may have moved either on, so the best robot is simulated and must
    # end in the checkpoint's best state; else all are copied again. Nothing of the run in results/
    # changes until they agree.
    new=$out/.ship
    try=0
    while :; do
        try=$((try + 1))
        rm -rf "$new"
        mkdir -p "$new"
        # without the table of bodies already simulated (a cache: a resume from the copy simulates
        # them again, to the same rows)
        "$AMORPH" export "$run" --checkpoint "$new/checkpoint.txt" || exit 1
        for f in config.txt best.genome best.lattice; do
            [ -f "$run/$f" ] && cp "$run/$f" "$new/"
        done
        want=$(awk '$1 == "individual" && $2 == "best" { print $9; exit }' "$new/checkpoint.txt")
        [ -n "$want" ] || break
        got=$("$AMORPH" sim "$new" --json 2>/dev/null | sed -n 's/.*"hash": "\([0-9a-f]*\)".*/\1/p')
        [ "$got" = "$want" ] && break
        if [ "$try" -ge "$TRIES" ]; then
            rm -rf "$new"
            echo "ship.sh: $run: best.genome ends in state $got, checkpoint.txt's best in $want" >&2
            exit 1
        fi
        sleep "$WAIT"
    done
    # ("last G E ...": generations 0..G logged, E evaluations)
    gens=$(awk '$1 == "last" { print $2; exit }' "$new/checkpoint.txt")
    evals=$(awk '$1 == "evaluations" && NF == 2 { print $2; exit }' "$new/checkpoint.txt")
    # the summaries are of the run's last finished command: kept when they are of this checkpoint,
    # dropped while the run goes on beyond them; they name the folder the run was made in, the
    # copy names itself
    if [ -f "$run/summary.txt" ] && [ "$(sed -n 's/^evaluations = //p' "$run/summary.txt")" = "$evals" ]; then
        cp "$run/summary.txt" "$run/summary.json" "$new/"
        sed -i "s|^run = .*|run = results/$name|" "$new/summary.txt"
        sed -i "s|\"run\": \"[^\"]*\"|\"run\": \"results/$name\"|" "$new/summary.json"
        # a resume with nothing left to do rewrites them with its own wall time only: the copy
        # already shipped stays (no change in git for a finished run)
        if [ -f "$out/summary.txt" ] && [ -f "$out/summary.json" ] &&
            [ "$(grep -v '^wall_s = ' "$out/summary.txt")" = "$(grep -v '^wall_s = ' "$new/summary.txt")" ]; then
            cp "$out/summary.txt" "$out/summary.json" "$new/"
        fi
    fi
    # the best robots kept at the rounds' counts (run.sh: best-N.genome), each checked to be the
    # run's best at N, evals.csv's fittest of its first N evaluations (the first of equals), by its
    # state at the end; one shipped before unchanged needs no second look
    for g in "$run"/best-[0-9]*.genome; do
        [ -f "$g" ] || continue
        f=${g##*/}
        n=${f#best-}
        n=${n%.genome}
        if ! cmp -s "$g" "$out/$f"; then
            want=$(awk -F, -v n="$n" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
                $1 < n && (h == "" || $c["fitness"] + 0 > b) { b = $c["fitness"] + 0; h = $c["state_hash"] } END { print h }' "$run/evals.csv")
            got=$("$AMORPH" sim "$new" --genome "$g" --json 2>/dev/null | sed -n 's/.*"hash": "\([0-9a-f]*\)".*/\1/p')
            if [ -z "$want" ] || [ "$got" != "$want" ]; then
                rm -rf "$new"
                echo "ship.sh: $run: $f ends in state $got, the best of evals.csv's first $n evaluations in ${want:-no state}" >&2
                exit 1
            fi
        fi
        cp "$g" "$new/"
    done
    head -n $((gens + 2)) "$run/log.csv" >"$new/log.csv"
    head -n $((evals + 1)) "$run/evals.csv" | gzip -9n >"$new/evals.csv.gz"
    rm -f "$out/summary.txt" "$out/summary.json" "$out/evals.csv"
    mv "$new"/* "$out/"
    rmdir "$new"
done
sh "$DST/report.sh" "$AMORPH" "$DST" --pictures >"$DST/report.md"
du -sh "$DST"
