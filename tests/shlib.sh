# tests/shlib.sh: helpers for the shell tests (sourced, not run).
# expect_fail CODE PATTERN CMD...: CMD must exit with CODE and print one stderr line matching PATTERN
BUILD=${BUILD:-build}
AMORPH=${AMORPH:-$BUILD/amorph}
T_PASS=0; T_FAIL=0
TMPD=$(mktemp -d)
trap 'rm -rf "$TMPD"' EXIT
ok() { T_PASS=$((T_PASS + 1)); }
ko() { T_FAIL=$((T_FAIL + 1)); echo "FAILED: $*" >&2; }
expect_fail() {
    code=$1; pat=$2; shift 2
    "$@" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
    lines=$(wc -l <"$TMPD/err")
    if [ $rc -eq "$code" ] && grep -qE -- "$pat" "$TMPD/err" && [ "$lines" -eq 1 ]; then ok
    else ko "$* -> exit $rc (want $code), stderr: $(head -c 300 "$TMPD/err") (want /$pat/, one line)"; fi
}
expect_ok() {
    "$@" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
    if [ $rc -eq 0 ]; then ok; else ko "$* -> exit $rc: $(head -c 300 "$TMPD/err")"; fi
}
# check DESCRIPTION COMMAND...: passes when COMMAND succeeds
check() { d=$1; shift; if "$@"; then ok; else ko "$d"; fi; }
summary() { echo "$1: $T_PASS passed, $T_FAIL failed"; [ "$T_FAIL" -eq 0 ]; }
# nowall LOG: an evolution's log.csv without its wall-clock column (the one that differs between runs)
nowall() { cut -d, -f1-7 "$1"; }
# sumval DIR KEY: the value of KEY in run folder DIR's summary.txt
sumval() { sed -n "s/^$2 = //p" "$1/summary.txt"; }
# small_cfg FILE: a small evolution's configuration (a run of 36 evaluations at 8^3 takes a second or two)
small_cfg() {
    printf '%s\n' "workspace = 8" "population = 6" "evaluations = 36" "cycles = 2" "period_steps = 100" "relax_max_steps = 400" \
        "relax_min_steps = 50" "release_steps = 100" "gmx_points = 24" "seed = 11" >"$1"
}
