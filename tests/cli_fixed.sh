# tests/cli_fixed.sh: the fixed-point build (make REAL=fixed, docs/fixed.md) against this float
# build: the fitness of the reference robots (sphere:8, cube:4 and random genomes of every
# representation) within 5% (or both below 1e-5 m: a body that does not locomote; a settled body
# may drift up to that much with the actuation off, docs/physics.md, Evaluation). Needs
# $FIXED_BUILD/amorph (exported by `make test`); skipped otherwise. Run from the repository root.
. tests/shlib.sh

# the "fitness" value of the JSON line in file $1
fitness_of() { sed -n 's/.*"fitness": *\([-0-9.eE+]*\).*/\1/p' "$1"; }

if [ -z "${FIXED_BUILD:-}" ] || ! [ -x "$FIXED_BUILD/amorph" ]; then
    echo "cli_fixed: FIXED_BUILD not set or not built: float / fixed comparison skipped"
    summary cli_fixed
    exit $?
fi
if ! "$FIXED_BUILD/amorph" --help 2>/dev/null | grep -q 'am_real=fixed'; then
    ko "$FIXED_BUILD/amorph is not a fixed-point build"
    summary cli_fixed
    exit $?
fi

# compare NAME ARGS...: both builds simulate the robot; fitness within 5%
compare() {
    name=$1; shift
    "$AMORPH" sim "$@" --json >"$TMPD/f" 2>"$TMPD/err" || { ko "$name: float sim failed: $(head -c 200 "$TMPD/err")"; return; }
    "$FIXED_BUILD/amorph" sim "$@" --json >"$TMPD/x" 2>"$TMPD/err" || { ko "$name: fixed sim failed: $(head -c 200 "$TMPD/err")"; return; }
    a=$(fitness_of "$TMPD/f"); b=$(fitness_of "$TMPD/x")
    if awk -v a="$a" -v b="$b" 'BEGIN { d = a - b; if (d < 0) d = -d; m = a < 0 ? -a : a; exit !(a >= 0 && b >= 0 && (d <= 0.05 * m || (m < 1e-5 && b < 1e-5))) }'; then
        ok; echo "  $name: float $a m, fixed $b m"
    else ko "$name: fitness float $a m, fixed $b m: more than 5% apart"; fi
}

compare sphere:8 --scene sphere:8
compare cube:4 --scene cube:4
for repr in dct cppn gmx; do
    for seed in 1 2; do
        "$AMORPH" random --repr "$repr" --seed "$seed" --size 8 --out "$TMPD/$repr$seed.genome" || { ko "random $repr"; continue; }
        compare "$repr seed $seed" "$TMPD/$repr$seed.genome"
    done
done
summary cli_fixed
