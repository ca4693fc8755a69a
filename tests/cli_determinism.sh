# tests/cli_determinism.sh: `amorph sim` gives bit-identical results run to run, between this build
# and an -O0 build ($OTHER_BUILD, exported by `make test`), and matches a pinned golden hash on the
# default build (am_real=float, profile=desktop). Run from the repository root: sh tests/cli_determinism.sh
. tests/shlib.sh

# Golden hash of `amorph sim --scene sphere:8 --json` ("hash" field) for the default float desktop
# build. Re-pin it deliberately when the model changes, and say why in the commit message.
GOLDEN_SPHERE8_HASH=eee955b01f48f301
# and for the fixed-point desktop build (make REAL=fixed, docs/fixed.md)
GOLDEN_SPHERE8_HASH_FIXED=582b7a180a5185c6

# the "hash" value of the JSON line in file $1
hash_of() { sed -n 's/.*"hash": *"\([0-9a-fA-F]*\)".*/\1/p' "$1"; }
# the JSON line without its wall-clock field (everything else must be identical)
strip_wall() { sed 's/"wall_seconds": *[0-9.eE+-]*,* *//' "$1"; }

# sim BIN OUT ARGS...: runs BIN sim ARGS --json into OUT; ok/ko on exit status and one JSON line
sim() {
    bin=$1; out=$2; shift 2
    "$bin" sim "$@" --json >"$out" 2>"$TMPD/err"; rc=$?
    if [ $rc -ne 0 ]; then ko "$bin sim $* -> exit $rc: $(head -c 300 "$TMPD/err")"; return 1; fi
    if [ "$(wc -l <"$out")" -ne 1 ] || ! grep -qE '"hash": *"[0-9a-f]{16}"' "$out"; then
        ko "$bin sim $*: want one JSON line with a 16-hex-digit hash, got: $(head -c 300 "$out")"; return 1
    fi
    ok
}

# same binary, twice
sim "$AMORPH" "$TMPD/a1" --scene sphere:8
sim "$AMORPH" "$TMPD/a2" --scene sphere:8
if [ "$(strip_wall "$TMPD/a1")" = "$(strip_wall "$TMPD/a2")" ]; then ok
else ko "two runs differ: $(cat "$TMPD/a1") vs $(cat "$TMPD/a2")"; fi
if grep -q '"diverged": *0' "$TMPD/a1"; then ok; else ko "sphere:8 diverged: $(cat "$TMPD/a1")"; fi

# this build against the -O0 build (and a second scene with collisions and the dt search)
if [ -n "${OTHER_BUILD:-}" ]; then
    if [ -x "$OTHER_BUILD/amorph" ]; then
        ok
        sim "$OTHER_BUILD/amorph" "$TMPD/b1" --scene sphere:8
        if [ "$(strip_wall "$TMPD/a1")" = "$(strip_wall "$TMPD/b1")" ]; then ok
        else ko "$AMORPH and $OTHER_BUILD/amorph differ: $(cat "$TMPD/a1") vs $(cat "$TMPD/b1")"; fi
        sim "$AMORPH" "$TMPD/a3" --scene cube:5 --collisions on --dt-search --cycles 2
        sim "$OTHER_BUILD/amorph" "$TMPD/b3" --scene cube:5 --collisions on --dt-search --cycles 2
        if [ "$(strip_wall "$TMPD/a3")" = "$(strip_wall "$TMPD/b3")" ]; then ok
        else ko "cube:5 --dt-search: builds differ: $(cat "$TMPD/a3") vs $(cat "$TMPD/b3")"; fi
    else
        ko "OTHER_BUILD=$OTHER_BUILD is set but $OTHER_BUILD/amorph is missing"
    fi
else
    echo "cli_determinism: OTHER_BUILD not set: cross-build comparison skipped"
fi

# the golden hash, only on the default float desktop build
if "$AMORPH" --help 2>/dev/null | grep -q 'am_real=float, profile=desktop'; then
    h=$(hash_of "$TMPD/a1")
    if [ "$h" = "$GOLDEN_SPHERE8_HASH" ]; then ok
    else ko "sphere:8 hash $h, golden $GOLDEN_SPHERE8_HASH (re-pin GOLDEN_SPHERE8_HASH in tests/cli_determinism.sh only for a deliberate model change)"; fi
elif "$AMORPH" --help 2>/dev/null | grep -q 'am_real=fixed, profile=desktop'; then
    h=$(hash_of "$TMPD/a1")
    if [ "$h" = "$GOLDEN_SPHERE8_HASH_FIXED" ]; then ok
    else ko "fixed-point sphere:8 hash $h, golden $GOLDEN_SPHERE8_HASH_FIXED (re-pin GOLDEN_SPHERE8_HASH_FIXED only for a deliberate change)"; fi
else
    echo "cli_determinism: not a float or fixed-point desktop build: golden hash skipped"
fi

summary cli_determinism
