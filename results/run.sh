#!/bin/sh
# The reference runs of docs/results.md, in the order they are run: each step starts its run
# folder or resumes it (a run killed at any moment continues exactly), so the script can be
# stopped and started again at will.
#   sh results/run.sh AMORPH DIR STAGE
# AMORPH: the amorph binary; DIR: where the run folders go (DIR/representations/dct-1 ...);
# STAGE: fig6-N (the Figure 6 runs, seeds 1..FIG6_SEEDS (10) of each representation, to N
# evaluations, interleaved so every representation has runs early), others-N (the other
# experiments' variants that differ from the seed's settings, seeds 1..3, to N evaluations),
# full-N (seed 1 of each representation extended to N evaluations: the seed's budget was
# 20,000), actuation-N (bodies and actuation evolved together, issue 44: GMX and CPPN on a 10^3
# workspace, the seed's palette or the follow-up's four materials, global or evolved phase, and
# two of the follow-up's materials with global phase, seeds 1..5, to N evaluations). Taken in rounds (fig6-1000, fig6-2000, others-2000, fig6-3000, fig6-4000,
# fig6-5000, full-20000), all runs of a stage reach a count before any goes beyond it; a run
# already beyond a round's count is left as it is.
# Every run uses one thread (results do not depend on it).
# RUN_PLAN=1 runs nothing and writes nothing: a line "FOLDER DONE EVALS" per run of the stage, DONE
# the evaluations its checkpoint holds (0 for a run not started), EVALS the stage's count
# (results/report.sh counts what the rounds have left from them).
# Two runners may work through one stage at once (say others-2000 then fig6-2000 beside
# fig6-2000): a run folder that the other runner is working in is skipped, and that runner
# finishes it.
set -u
AMORPH=$1 DIR=$2 STAGE=$3
err=$DIR/.run.$$.err
# stopped (results/runners.sh stop: SIGTERM to the runner's process group): the trap runs once the
# amorph going has written its checkpoint and ended, passes on its words and starts no other run
trap 'cat "$err" >&2 2>/dev/null; rm -f "$err"; exit 143' TERM

# run FOLDER EVALS KEY=VALUE...: FOLDER started with the settings or resumed to EVALS evaluations
run() {
    folder=$1 evals=$2
    shift 2
    done_evals=$(sed -n 's/^evaluations \([0-9][0-9]*\)$/\1/p' "$folder/checkpoint.txt" 2>/dev/null)
    if [ "${RUN_PLAN:-0}" = 1 ]; then
        echo "$folder ${done_evals:-0} $evals"
        return 0
    fi
    if [ -n "$done_evals" ] && [ "$done_evals" -gt "$evals" ]; then
        # a later round's run: it is past this round, so nothing to do
        echo "$(date -u +%FT%TZ) $folder already at $done_evals evaluations"
        return 0
    fi
    if [ -f "$folder/checkpoint.txt" ]; then
        "$AMORPH" evolve --resume "$folder" --evaluations "$evals" --threads 1 --quiet 2>"$err"
    else
        # KEY=VALUE into --KEY VALUE, a value with spaces kept whole (a materialK key's)
        n=$#
        while [ "$n" -gt 0 ]; do
            kv=$1
            shift
            set -- "$@" "--${kv%%=*}" "${kv#*=}"
            n=$((n - 1))
        done
        "$AMORPH" evolve "$@" --evaluations "$evals" --threads 1 --quiet --no-pictures --out "$folder" 2>"$err"
    fi
    rc=$?
    if [ $rc -ne 0 ] && grep -q 'another amorph is working' "$err"; then
        rm -f "$err"
        echo "$(date -u +%FT%TZ) $folder skipped: another runner is working in it"
        return 0
    fi
    cat "$err" >&2
    rm -f "$err"
    [ $rc -eq 0 ] || exit 1
    # the best robot at the round's count, kept as best-EVALS.genome: the run goes on beyond it in
    # the next round, and report.sh compares the best robots of all runs at one count
    at=$(sed -n 's/^evaluations \([0-9][0-9]*\)$/\1/p' "$folder/checkpoint.txt" 2>/dev/null)
    if [ "$at" = "$evals" ] && [ -f "$folder/best.genome" ] && ! cmp -s "$folder/best.genome" "$folder/best-$evals.genome"; then
        cp "$folder/best.genome" "$folder/best-$evals.genome.new" && mv "$folder/best-$evals.genome.new" "$folder/best-$evals.genome"
    fi
    echo "$(date -u +%FT%TZ) $folder $(sed -n 's/^evaluations = //p' "$folder/summary.txt" 2>/dev/null) evaluations"
}

fig6() {
    [ "${RUN_PLAN:-0}" = 1 ] || mkdir -p "$DIR/representations"
    k=1
    while [ "$k" -le "${FIG6_SEEDS:-10}" ]; do
        for r in dct cppn gmx; do
            run "$DIR/representations/$r-$k" "$1" representation=$r seed=$k
        done
        k=$((k + 1))
    done
}

# the variants of the other experiments (amorph experiment --help) that differ from the seed's
# settings (the seed's settings themselves are representations/gmx-K), seeds 1..3
others() {
    [ "${RUN_PLAN:-0}" = 1 ] || mkdir -p "$DIR/three-materials" "$DIR/dynamic" "$DIR/friction"
    for k in 1 2 3; do
        run "$DIR/three-materials/three-$k" "$1" materials=3 seed=$k
        run "$DIR/dynamic/fast-$k" "$1" period_steps=250 damping_internal=1 seed=$k
        run "$DIR/dynamic/lowdamp-$k" "$1" period_steps=500 damping_internal=0.1 seed=$k
        run "$DIR/dynamic/fast_lowdamp-$k" "$1" period_steps=250 damping_internal=0.1 seed=$k
        run "$DIR/friction/k0.1_s5.0-$k" "$1" mu_kinetic=0.1 mu_static=5.0 seed=$k
        run "$DIR/friction/k0.4_s0.5-$k" "$1" mu_kinetic=0.4 mu_static=0.5 seed=$k
    done
}

# the four variants of the actuation experiment (docs/results.md): the seed's palette (passive,
# active) or the follow-up's four materials (palette = unshackled), each voxel actuated with its
# material's phase (actuation = global) or with its own evolved phase too (actuation = phase);
# and a control for the count of materials: two of the follow-up's four, its soft tissue and one
# muscle (the same modulus, density and Poisson's ratio as its active_plus, renamed as a material
# of a palette may not be named twice), global actuation. GMX and CPPN on a 10^3 workspace, seeds
# 1..5, interleaved so every variant has runs early
ACT_TWO="muscle modulus=5e6 density=1e6 cte=0.01 phase=0 poisson=0.35 color=ff0000"
actuation() {
    [ "${RUN_PLAN:-0}" = 1 ] || mkdir -p "$DIR/actuation"
    for k in 1 2 3 4 5; do
        for r in gmx cppn; do
            run "$DIR/actuation/$r-seed-global-$k" "$1" representation=$r workspace=10 seed=$k
            run "$DIR/actuation/$r-four-global-$k" "$1" representation=$r workspace=10 palette=unshackled seed=$k
            run "$DIR/actuation/$r-seed-phase-$k" "$1" representation=$r workspace=10 actuation=phase seed=$k
            run "$DIR/actuation/$r-four-phase-$k" "$1" representation=$r workspace=10 palette=unshackled actuation=phase seed=$k
            run "$DIR/actuation/$r-two-global-$k" "$1" representation=$r workspace=10 palette=unshackled materials=2 \
                "material2=$ACT_TWO" seed=$k
        done
    done
}
case $STAGE in
fig6-*[!0-9]* | fig6- | others-*[!0-9]* | others- | full-*[!0-9]* | full- | actuation-*[!0-9]* | actuation-)
    echo "run.sh: '$STAGE': the stage takes a number of evaluations (fig6-N, others-N, full-N, actuation-N)" >&2
    exit 2
    ;;
fig6-*) fig6 "${STAGE#fig6-}" ;;
others-*) others "${STAGE#others-}" ;;
actuation-*) actuation "${STAGE#actuation-}" ;;
full-*)
    for r in dct cppn gmx; do
        run "$DIR/representations/$r-1" "${STAGE#full-}" representation=$r seed=1
    done
    ;;
*) echo "run.sh: unknown stage '$STAGE' (fig6-N, others-N, full-N, actuation-N)" >&2; exit 2 ;;
esac
