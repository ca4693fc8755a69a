# tests/cli_lib.sh: the library as a program built against it sees it (docs/embedding.md). The
# first program (docs/examples/first.c) builds with the build's defines, runs, and travels as far
# as `amorph sim` moves the same robot; a program compiled with another number type than the
# library's stops at AM_LAYOUT_CHECK (and at am_api_init) with one line, against the static and
# the shared library, instead of writing past its structs; the shared library has its SONAME and
# its versioned file; a build with a project's own capacities (SMALL_BUILD, make test) keeps within
# them. Run from the repository root: BUILD=build sh tests/cli_lib.sh
. tests/shlib.sh
CC=${CC:-cc}
W=$TMPD
flags=$(cat "$BUILD/flags.txt" 2>/dev/null)
defs=$(printf '%s\n' "$flags" | tr ' ' '\n' | grep -E '^-DAM_(REAL|PROFILE)_' | tr '\n' ' ')
# a sanitizer build's library needs the sanitizer's runtime at the link (make asan)
san=$(printf '%s\n' "$flags" | tr ' ' '\n' | grep -E '^-fsanitize=' | tr '\n' ' ')
check "$BUILD/flags.txt names the number type and profile: $defs" test -n "$defs"
case $flags in *mingw*)
    echo "cli_lib: a Windows build: skipped"
    summary cli_lib
    exit $? ;;
esac

# the first program: built with the library's defines, its travel is amorph sim's of the same robot
# shellcheck disable=SC2086
$CC -std=c11 -Wall -Wextra -Werror $defs $san -Iinclude docs/examples/first.c "$BUILD/libamorph.a" -lm -o "$W/first" 2>"$W/ccerr"
check "docs/examples/first.c builds: $(head -c 300 "$W/ccerr")" test $? -eq 0
n=$(grep -c . docs/examples/first.c)
check "docs/examples/first.c is a first program: $n lines (at most 45)" test "$n" -le 45
"$W/first" >"$W/first.txt" 2>&1
check "first runs: $(head -c 300 "$W/first.txt")" test $? -eq 0
# the same robot as a lattice file: 4 x 3 x 2 cells of the built-in palette, x < 2 active (2), the rest passive (1)
printf 'amorph-lattice 1\nsize 4 3 2\nlayer 0\n2211\n2211\n2211\nlayer 1\n2211\n2211\n2211\n' >"$W/first.lattice"
want=$("$AMORPH" sim "$W/first.lattice" --cycles 4 --json 2>/dev/null | sed -n 's/.*"travel": \([^,]*\),.*/\1/p')
got=$(sed -n 's/.*: travel \([^ ]*\) m .*/\1/p' "$W/first.txt")
check "first's travel ($got) is amorph sim's of the same robot ($want)" test -n "$want" -a "$got" = "$want"
case $want in 0 | -* | "") ko "the robot does not move forward: travel '$want'" ;; *) ok ;; esac

# a program compiled with another number type than the library's: one line at the first call
case $defs in *AM_REAL_FLOAT*) other=fixed ;; *) other=float ;; esac
odefs=$(printf '%s\n' "$defs" | sed "s/-DAM_REAL_[A-Z]*/-DAM_REAL_$(echo $other | tr a-z A-Z)/")
# shellcheck disable=SC2086
$CC -std=c11 $odefs $san -Iinclude docs/examples/first.c "$BUILD/libamorph.a" -lm -o "$W/first_other" 2>"$W/ccerr"
check "first.c builds with $odefs: $(head -c 300 "$W/ccerr")" test $? -eq 0
expect_fail 1 "^first: the program was compiled for $other .*, the library for [a-z]+ [a-z]+ .*pkg-config" "$W/first_other"
check "nothing but the line was printed" test ! -s "$TMPD/out"

# am_api_init refuses the workspace of such a program (sizeof *w is not the library's)
cat >"$W/api.c" <<'C'
#include <stdio.h>
#include "amorph.h"
static am_api_work work;
int main(void)
{
    char err[AM_ERR_MAX];
    if (am_api_init(&work, sizeof work, err, sizeof err) != AM_OK) {
        fprintf(stderr, "api: %s\n", err);
        return 1;
    }
    return 0;
}
C
# shellcheck disable=SC2086
$CC -std=c11 $odefs $san -Iinclude "$W/api.c" "$BUILD/libamorph.a" -lm -o "$W/api_other" 2>"$W/ccerr"
check "a program of the API builds with $odefs: $(head -c 300 "$W/ccerr")" test $? -eq 0
expect_fail 1 "^api: the workspace has [0-9]+ bytes; the library's \([a-z]+ [a-z]+\) has [0-9]+" "$W/api_other"
# shellcheck disable=SC2086
$CC -std=c11 $defs $san -Iinclude "$W/api.c" "$BUILD/libamorph.a" -lm -o "$W/api_same" 2>"$W/ccerr"
expect_ok "$W/api_same"

# the shared library: libamorph.so -> libamorph.so.MAJOR -> libamorph.so.MAJOR.MINOR.PATCH, whose
# SONAME is libamorph.so.MAJOR; the program of another number type fails against it the same way
if [ -f "$BUILD/libamorph.so" ] && [ -z "$san" ]; then
    ver() { awk -v k="AM_VERSION_$1" 'index($1, "define") && $2 == k {print $3}' include/amorph/base.h; }
    major=$(ver MAJOR) full=$(ver MAJOR).$(ver MINOR).$(ver PATCH)
    check "libamorph.so links to libamorph.so.$major: $(readlink "$BUILD/libamorph.so")" test "$(readlink "$BUILD/libamorph.so")" = "libamorph.so.$major"
    check "libamorph.so.$major links to libamorph.so.$full" test "$(readlink "$BUILD/libamorph.so.$major")" = "libamorph.so.$full"
    if command -v readelf >/dev/null 2>&1; then
        soname=$(readelf -d "$BUILD/libamorph.so.$full" | sed -n 's/.*SONAME.*\[\(.*\)\].*/\1/p')
        check "the SONAME is libamorph.so.$major: $soname" test "$soname" = "libamorph.so.$major"
    fi
    # shellcheck disable=SC2086
    $CC -std=c11 $odefs -Iinclude docs/examples/first.c -L"$BUILD" -lamorph -lm -o "$W/first_so" 2>"$W/ccerr"
    check "first.c links the shared library: $(head -c 300 "$W/ccerr")" test $? -eq 0
    expect_fail 1 "^first: the program was compiled for $other .*, the library for " env LD_LIBRARY_PATH="$BUILD" "$W/first_so"
else
    echo "cli_lib: no $BUILD/libamorph.so (or a sanitizer build): the shared library's checks skipped"
fi
# a project's own capacities (docs/examples/config_small.h, AMORPH_CONFIG_H): $SMALL_BUILD, built by
# make test with CONFIG=, runs a scene within them and refuses a body over them in one line
if [ -n "${SMALL_BUILD:-}" ] && [ -x "$SMALL_BUILD/amorph" ]; then
    "$SMALL_BUILD/amorph" --help >"$W/small_help.txt" 2>&1
    check "the small build names its capacities: $(grep -m 1 'build:' "$W/small_help.txt")" grep -q 'profile=small (workspace up to 6^3)' "$W/small_help.txt"
    expect_ok "$SMALL_BUILD/amorph" sim --scene sphere:6 --cycles 2 --json
    small=$(sed -n 's/.*"hash": "\([0-9a-f]*\)".*/\1/p' "$TMPD/out")
    default=$("$AMORPH" sim --scene sphere:6 --cycles 2 --json 2>/dev/null | sed -n 's/.*"hash": "\([0-9a-f]*\)".*/\1/p')
    check "sphere:6 in the small build ($small) is the default build's ($default)" test -n "$small" -a "$small" = "$default"
    expect_fail 2 "lattice size 7 x 7 x 7 exceeds the small profile's 6 per side" "$SMALL_BUILD/amorph" sim --scene cube:7
    printf 'amorph-lattice 1\nsize 7 1 1\nlayer 0\n1111111\n' >"$W/big.lattice"
    expect_fail 2 "big.lattice:2: size 7 1 1 exceeds the small profile's 6 cells per side" "$SMALL_BUILD/amorph" sim "$W/big.lattice"
else
    echo "cli_lib: no SMALL_BUILD (make test builds one with CONFIG=docs/examples/config_small.h): the small configuration's checks skipped"
fi
summary cli_lib
