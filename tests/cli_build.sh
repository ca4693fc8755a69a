# tests/cli_build.sh: the build's own rules (the Makefile and include/amorph). One number type and
# one profile per build, refused at compile time otherwise; the public headers usable from C++
# (extern "C": a C++ program links against the library); each object rebuilt when a header it
# includes changes and only then (-MMD -MP), and every object when the compiler's flags change
# ($BUILD/flags.txt). Run from the repository root: sh tests/cli_build.sh
. tests/shlib.sh
CC=${CC:-cc}
flags=$(cat "$BUILD/flags.txt" 2>/dev/null)
check "$BUILD/flags.txt holds the build's compiler and flags" test -n "$flags"
defs=$(printf '%s\n' "$flags" | tr ' ' '\n' | grep -E '^-DAM_(REAL|PROFILE)_' | tr '\n' ' ')
case $defs in *AM_REAL_*AM_PROFILE_*) ok ;; *) ko "flags.txt names no number type and profile: $defs" ;; esac
# a sanitizer build's library needs the sanitizer's runtime at the link (make asan)
san=$(printf '%s\n' "$flags" | tr ' ' '\n' | grep -E '^-fsanitize=' | tr '\n' ' ')

# compile C source $1 with the flags $2: the compiler's first error line, or "ok"
compile() {
    printf '%s\n' "$1" >"$TMPD/c.c"
    # shellcheck disable=SC2086
    if $CC -std=c11 -pedantic-errors $2 -Iinclude -c "$TMPD/c.c" -o "$TMPD/c.o" 2>"$TMPD/cerr"; then echo ok; else grep -m 1 'error' "$TMPD/cerr"; fi
}
src='#include "amorph.h"
int amorph_probe(void) { return (int)sizeof(am_real); }'
case $(compile "$src" "-DAM_REAL_DOUBLE -DAM_REAL_FIXED -DAM_PROFILE_DESKTOP") in
*"two number types defined"*) ok ;; *) ko "double and fixed together: $(cat "$TMPD/cerr" | head -n 2)" ;; esac
case $(compile "$src" "-DAM_REAL_FLOAT -DAM_REAL_DOUBLE -DAM_PROFILE_DESKTOP") in
*"two number types defined"*) ok ;; *) ko "float and double together: $(cat "$TMPD/cerr" | head -n 2)" ;; esac
case $(compile "$src" "-DAM_REAL_FLOAT -DAM_PROFILE_DESKTOP -DAM_PROFILE_BOARD") in
*"two profiles defined"*) ok ;; *) ko "two profiles: $(cat "$TMPD/cerr" | head -n 2)" ;; esac
case $(compile "$src" "-DAM_REAL_FIXED -DAM_PROFILE_BOARD") in ok) ok ;; *) ko "fixed + board: $(cat "$TMPD/cerr")" ;; esac

# C++: the headers compile as C++ and their functions link with C names (extern "C")
if command -v g++ >/dev/null 2>&1; then
    cat >"$TMPD/api.cpp" <<'EOF'
#include "amorph.h"
#include <cstdio>
int main()
{
    am_eval_def d = am_default_eval();
    am_rng r;
    am_rng_seed(&r, 7);
    std::printf("cycles=%d rng=%llu\n", d.cycles, (unsigned long long)(am_rng_u64(&r) != 0));
    return 0;
}
EOF
    # shellcheck disable=SC2086
    if g++ -std=c++11 -Wall -Werror $defs $san -Iinclude "$TMPD/api.cpp" "$BUILD/libamorph.a" -lm -o "$TMPD/api" 2>"$TMPD/cxx"; then
        out=$("$TMPD/api")
        check "a C++ program calls the library: $out" test "$out" = "cycles=10 rng=1"
    else
        ko "a C++ program against $BUILD/libamorph.a: $(head -c 400 "$TMPD/cxx")"
    fi
else
    echo "cli_build: no g++: the C++ check skipped"
fi

# dependencies, by make's dry run (it writes nothing): the build as make test made it, with the
# same number type and profile
real=float profile=desktop
case $defs in *AM_REAL_FIXED*) real=fixed ;; *AM_REAL_DOUBLE*) real=double ;; esac
case $defs in *AM_PROFILE_BOARD*) profile=board ;; esac
dry() { env -u MAKEFLAGS -u MAKELEVEL -u MFLAGS make --no-print-directory -n BUILD="$BUILD" REAL=$real PROFILE=$profile "$@" all 2>&1; }
compiled() { grep -oE -- '-c (src|tools|port)/[a-z_/0-9]+\.c' | sed 's/^-c //' | sort | tr '\n' ' '; }
now=$(dry | compiled)
check "$BUILD is up to date (nothing to compile: $now)" test -z "$now"
geno=$(dry -W include/amorph/geno.h | compiled)
case " $geno " in *" src/evo/evo_evolve.c "*" src/geno/geno_dct.c "*) ok ;; *) ko "geno.h changed: geno_dct.c and evo_evolve.c not rebuilt: $geno" ;; esac
case " $geno " in *" src/base/"* | *" src/sim/"*) ko "geno.h changed: objects of the layers below it rebuilt: $geno" ;; *) ok ;; esac
step=$(dry -W src/sim/sim_internal.h | compiled)
case " $step " in *" src/sim/sim_step.c "*) ok ;; *) ko "sim_internal.h changed: sim_step.c not rebuilt: $step" ;; esac
case " $step " in *" tools/"*) ko "sim_internal.h changed: tools rebuilt: $step" ;; *) ok ;; esac
all=$(dry CFLAGS=-DAM_FLAGS_PROBE | compiled)
n_all=$(echo "$all" | wc -w) n_src=$(ls src/*/*.c tools/*.c | wc -l)
check "new flags rebuild every object ($n_all of at least $n_src)" test "$n_all" -ge "$n_src"
check "a dry run wrote no flags: $(head -c 200 "$BUILD/flags.txt")" test "$(cat "$BUILD/flags.txt")" = "$flags"

summary cli_build
