#!/bin/sh
# tools/check_exports.sh CC "CFLAGS" LIB: the shared library exports the public API and nothing
# else (docs/embedding.md, The library's symbols). The API is every function the public headers
# declare (include/amorph.h and what it includes), listed by the compiler itself (-aux-info; the
# static inline helpers are not symbols); the exports are what `nm -D --defined-only` shows of
# LIB. A function a header declares without AM_API is hidden and shows up here as missing; a
# function of src/ that no header declares, exported, shows up as extra. Exit 1 on either.
cc=$1 flags=$2 lib=$3
[ -n "$cc" ] && [ -n "$lib" ] || { echo "usage: tools/check_exports.sh CC CFLAGS LIB" >&2; exit 2; }
NM=${NM:-nm}
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
printf '#include "amorph.h"\n' >"$tmp/api.c"
# shellcheck disable=SC2086
$cc $flags -Iinclude -aux-info "$tmp/api.aux" -c "$tmp/api.c" -o "$tmp/api.o" || exit 1
grep '^/\* [^ ]*include/amorph[/.]' "$tmp/api.aux" | grep ' \*/ extern ' |
    sed 's/ *(.*//; s/.*[ *]//' | sort -u >"$tmp/api.txt"
$NM -D --defined-only "$lib" | awk 'NF >= 3 {print $3}' | sort -u >"$tmp/exports.txt"
n_api=$(grep -c . "$tmp/api.txt") n_exp=$(grep -c . "$tmp/exports.txt")
extra=$(comm -13 "$tmp/api.txt" "$tmp/exports.txt" | tr '\n' ' ')
missing=$(comm -23 "$tmp/api.txt" "$tmp/exports.txt" | tr '\n' ' ')
bad=0
if [ "$n_api" -lt 100 ]; then echo "check-exports: only $n_api functions found in the headers"; bad=1; fi
if [ -n "$extra" ]; then echo "check-exports: $lib exports symbols no public header declares: $extra"; bad=1; fi
if [ -n "$missing" ]; then echo "check-exports: $lib does not export these API functions (AM_API missing?): $missing"; bad=1; fi
if [ $bad -ne 0 ]; then echo "check-exports: 0 passed, 1 failed"; exit 1; fi
echo "check-exports: $lib exports the $n_api functions of the public headers and nothing else"
