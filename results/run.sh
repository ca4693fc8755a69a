#!/bin/sh
# The reference runs of docs/results.md, in the order they are run: each step starts its run
# folder or resumes it (a run killed at any moment continues exactly), so the script can be
# stopped and started again at will.
#   sh results/run.sh AMORPH DIR STAGE
# AMORPH: the amorph binary; DIR: where the run folders go (DIR/representations/dct-1 ...);
# STAGE: fig6-N (the nine Figure 6 runs to N evaluations, interleaved so every representation
# has runs early; the seed's were 20,000), others-2000 (one run of each other experiment's
# variants that differ from the seed's settings). Taken in rounds (fig6-500, fig6-1000,
# fig6-2000, then others-2000 and fig6-3000, fig6-4000, ...), all nine reach a count before any
# goes beyond it; a run already beyond a round's count is left as it is.
# Every run uses one thread (results do not depend on it).
# Two runners may work through one stage at once (say others-2000 then fig6-2000 beside
# fig6-2000): a run folder that the other runner is working in is skipped, and that runner
# finishes it.
set -u
AMORPH=$1 DIR=$2 STAGE=$3

# run FOLDER EVALS KEY=VALUE...: FOLDER started with the settings or resumed to EVALS evaluations
run() {
    folder=$1 evals=$2
    shift 2
    err=$DIR/.run.$$.err
    done_evals=$(sed -n 's/^evaluations \([0-9][0-9]*\)$/\1/p' "$folder/checkpoint.txt" 2>/dev/null)
    if [ -n "$done_evals" ] && [ "$done_evals" -gt "$evals" ]; then
        # a later round's run: it is past this round, so nothing to do
        echo "$(date -u +%FT%TZ) $folder already at $done_evals evaluations"
        return 0
    fi
    if [ -f "$folder/checkpoint.txt" ]; then
        "$AMORPH" evolve --resume "$folder" --evaluations "$evals" --threads 1 --quiet 2>"$err"
    else
        set -- $(for kv in "$@"; do printf -- '--%s %s ' "${kv%%=*}" "${kv#*=}"; done)
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
    echo "$(date -u +%FT%TZ) $folder $(sed -n 's/^evaluations = //p' "$folder/summary.txt" 2>/dev/null) evaluations"
}

fig6() {
    mkdir -p "$DIR/representations"
    for k in 1 2 3; do
        for r in dct cppn gmx; do
            run "$DIR/representations/$r-$k" "$1" representation=$r seed=$k
        done
    done
}

case $STAGE in
fig6-*[!0-9]* | fig6-) echo "run.sh: '$STAGE': fig6-N takes a number of evaluations" >&2; exit 2 ;;
fig6-*) fig6 "${STAGE#fig6-}" ;;
others-2000)
    # the variants of the other experiments (amorph experiment --help) that differ from the seed's
    # settings; the seed's settings themselves are representations/gmx-1
    mkdir -p "$DIR/three-materials" "$DIR/dynamic" "$DIR/friction"
    run "$DIR/three-materials/three-1" 2000 materials=3 seed=1
    run "$DIR/dynamic/fast-1" 2000 period_steps=250 damping_internal=1 seed=1
    run "$DIR/dynamic/lowdamp-1" 2000 period_steps=500 damping_internal=0.1 seed=1
    run "$DIR/dynamic/fast_lowdamp-1" 2000 period_steps=250 damping_internal=0.1 seed=1
    run "$DIR/friction/k0.1_s5.0-1" 2000 mu_kinetic=0.1 mu_static=5.0 seed=1
    run "$DIR/friction/k0.4_s0.5-1" 2000 mu_kinetic=0.4 mu_static=0.5 seed=1
    ;;
*) echo "run.sh: unknown stage '$STAGE' (fig6-2000, others-2000, fig6-N)" >&2; exit 2 ;;
esac
