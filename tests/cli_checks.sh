# tests/cli_checks.sh: the CHECKS=1 build ($CHECKS_BUILD, exported by `make checks`: the model's and
# the state's invariants after every build and step, and every AM_ASSERT) runs a VXA file with
# per-voxel layers and the shipped runs' best robots without calling the check handler, to the
# same results as the release build; and the handler does fire on a false AM_ASSERT, with the
# file, the line and the condition. Run from the repository root: make checks.
. tests/shlib.sh

if [ -z "${CHECKS_BUILD:-}" ]; then
    echo "cli_checks: CHECKS_BUILD not set (make checks sets it): skipped"
    summary cli_checks
    exit $?
fi
C=$CHECKS_BUILD/amorph
# the JSON line without its wall-clock field
strip_wall() { sed 's/"wall_seconds": *[0-9.eE+-]*,* *//' "$1"; }

# a false AM_ASSERT calls the handler: "FILE:LINE: invariant broken: CONDITION" on stderr, abort()
"$CHECKS_BUILD/tests/test_base" assert_fires >"$TMPD/out" 2>"$TMPD/err"
rc=$?
check "a false AM_ASSERT aborts (exit 134), not $rc" [ $rc -eq 134 ]
check "a false AM_ASSERT names its file, line and condition: $(head -c 300 "$TMPD/err")" \
    grep -qE '^tests/test_base\.c:[0-9]+: invariant broken: assert_cond\(0\)$' "$TMPD/err"

# a VXA file's scene with a phase per voxel (evosoro's), checked at every step: no handler call,
# and the release build's result to the last digit
for f in tests/data/evosoro_phase.vxa tests/data/evosoro_stiffness.vxa; do
    expect_ok "$C" sim "$f" --json
    check "$f: the handler stays silent in the checked build: $(head -c 300 "$TMPD/err")" sh -c '! grep -q "invariant broken" "$1"' _ "$TMPD/err"
    strip_wall "$TMPD/out" >"$TMPD/checked"
    if [ -x "$AMORPH" ]; then
        "$AMORPH" sim "$f" --json >"$TMPD/rel" 2>/dev/null
        strip_wall "$TMPD/rel" >"$TMPD/release"
        check "$f: the checked build's result is the release build's: $(head -c 300 "$TMPD/checked")" cmp -s "$TMPD/checked" "$TMPD/release"
    fi
done

# a shipped run's best robot (results/, tests/cli_results.sh): the checked build ends in the state
# hash the run recorded
n=0
for run in results/representations/gmx-1 results/representations/dct-1; do
    [ -f "$run/summary.txt" ] || continue
    n=$((n + 1))
    expect_ok "$C" sim "$run" --json
    check "$run: the handler stays silent in the checked build: $(head -c 300 "$TMPD/err")" sh -c '! grep -q "invariant broken" "$1"' _ "$TMPD/err"
    got=$(sed -n 's/.*"hash": "\([0-9a-f]*\)".*/\1/p' "$TMPD/out")
    want=$(sumval "$run" best_state_hash)
    check "$run: the checked build's best robot ends in state $got, the run recorded $want" [ -n "$want" -a "$got" = "$want" ]
done
check "results/: a shipped run's best robot found" [ $n -gt 0 ]
summary cli_checks
