#!/bin/sh
# Runs every test program given as arguments, then every tests/cli_*.sh (or the shell tests that
# CLI_TESTS lists: make check), and prints one closing line "N passed, N failed" summed over all of
# them. VALGRIND=1 runs the programs under memcheck. Each test's wall time is printed after it, and
# the slowest ten before the closing line (where a suite's time goes; a figure, never a check).
BUILD=${BUILD:-build}
export BUILD
pass=0; fail=0; bad=""
log=$(mktemp)
times=$(mktemp)
run() {
    name=$1; shift
    echo "== $name"
    t0=$(date +%s)
    "$@" >"$log" 2>&1
    rc=$?
    t1=$(date +%s)
    cat "$log"
    echo "-- $name: $((t1 - t0)) s"
    echo "$((t1 - t0)) $name" >>"$times"
    line=$(grep -E '[0-9]+ passed, [0-9]+ failed' "$log" | tail -n 1)
    p=$(echo "$line" | sed -n 's/.*\b\([0-9][0-9]*\) passed.*/\1/p')
    f=$(echo "$line" | sed -n 's/.* \([0-9][0-9]*\) failed.*/\1/p')
    [ -n "$p" ] || p=0
    [ -n "$f" ] || f=0
    if [ $rc -ne 0 ] && [ "$f" -eq 0 ]; then f=1; fi
    pass=$((pass + p)); fail=$((fail + f))
    [ $rc -ne 0 ] && bad="$bad $name"
}
for t in "$@"; do
    if [ "${VALGRIND:-0}" = 1 ]; then
        AM_TEST_QUICK=1 run "$(basename "$t") (valgrind)" valgrind -q --error-exitcode=99 --leak-check=full "$t"
    else
        run "$(basename "$t")" "$t"
    fi
done
if [ "${VALGRIND:-0}" != 1 ]; then
    for s in ${CLI_TESTS:-tests/cli_*.sh}; do
        [ -f "$s" ] && run "$(basename "$s")" sh "$s"
    done
fi
echo "slowest (wall seconds):"
sort -rn "$times" | head -n 10 | awk '{printf "  %5d  %s\n", $1, substr($0, index($0, " ") + 1)}'
rm -f "$log" "$times"
[ -n "$bad" ] && echo "failing:$bad"
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
