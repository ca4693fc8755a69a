# tests/cli_results.sh: the reference runs shipped in results/ (docs/results.md) still give what
# they recorded: each run folder's best robot, simulated by `amorph sim DIR` in the run's own
# settings, ends in the recorded state hash (and, for a finished run, at the recorded fitness).
# A change to the simulator that moves a published result fails here, and must re-run or re-pin
# the results deliberately. Float desktop builds only (the runs are float, at 20^3). Run from the
# repository root.
. tests/shlib.sh

if ! "$AMORPH" --help 2>/dev/null | grep -q 'am_real=float' || ! "$AMORPH" --help 2>/dev/null | grep -q 'profile=desktop'; then
    echo "cli_results: not a float desktop build: the shipped results are not checked"
    summary cli_results
    exit $?
fi
n=0
for ck in results/*/*/checkpoint.txt; do
    [ -f "$ck" ] || continue
    d=${ck%/checkpoint.txt}
    [ -f "$d/best.genome" ] || continue
    n=$((n + 1))
    # the best individual's state hash: the summary's when the run is finished, else the checkpoint's
    if [ -f "$d/summary.txt" ]; then want=$(sumval "$d" best_state_hash); fit=$(sumval "$d" best_fitness)
    else want=$(awk '$1 == "individual" && $2 == "best" { print $9 }' "$ck"); fit=""; fi
    expect_ok "$AMORPH" sim "$d" --json
    got=$(sed -n 's/.*"hash": "\([0-9a-f]*\)".*/\1/p' "$TMPD/out")
    if [ -n "$want" ] && [ "$got" = "$want" ]; then ok
    else ko "$d: best robot ends in state $got, the run recorded $want"; fi
    if [ -n "$fit" ]; then
        got=$(sed -n 's/.*"fitness": \([-0-9.e+]*\).*/\1/p' "$TMPD/out")
        if [ "$got" = "$fit" ]; then ok; else ko "$d: best robot's fitness $got, the run recorded $fit"; fi
    fi
done
if [ $n -gt 0 ]; then ok; else ko "results/: no run folder found"; fi
summary cli_results
