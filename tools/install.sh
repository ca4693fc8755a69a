#!/bin/sh
# tools/install.sh BUILD DEST PREFIX DEFS: what make install does, from a build folder already made
# (make all shared): the headers into DEST/include, libamorph.a and the shared library into DEST/lib
# (the file libamorph.so.MAJOR.MINOR.PATCH and the links libamorph.so.MAJOR and libamorph.so), the
# program into DEST/bin and DEST/lib/pkgconfig/amorph.pc, whose prefix is PREFIX (DEST is
# $(DESTDIR)$(PREFIX)) and whose Cflags carry DEFS, the build's number type and profile, which the
# headers need to be read as the library was compiled.
set -e
build=$1 dest=$2 prefix=$3 defs=$4
[ -n "$build" ] && [ -n "$dest" ] && [ -n "$prefix" ] || { echo "usage: tools/install.sh BUILD DEST PREFIX DEFS" >&2; exit 2; }
prog=$build/amorph
[ -f "$prog" ] || prog=$build/amorph.exe
# the version the Makefile named the shared library with (AM_VERSION_* of include/amorph/base.h)
ver() { awk -v k="AM_VERSION_$1" 'index($1, "define") && $2 == k {print $3}' include/amorph/base.h; }
major=$(ver MAJOR) version=$(ver MAJOR).$(ver MINOR).$(ver PATCH)
so=libamorph.so.$version
for f in "$build/libamorph.a" "$build/$so" "$prog"; do
    [ -f "$f" ] || { echo "install: $f is missing (make all shared)" >&2; exit 1; }
done
mkdir -p "$dest/include/amorph" "$dest/lib/pkgconfig" "$dest/bin"
cp include/amorph.h "$dest/include/"
cp include/amorph/*.h "$dest/include/amorph/"
cp "$build/libamorph.a" "$build/$so" "$dest/lib/"
ln -sf "$so" "$dest/lib/libamorph.so.$major"
ln -sf "libamorph.so.$major" "$dest/lib/libamorph.so"
cp "$prog" "$dest/bin/"
chmod 644 "$dest/include/amorph.h" "$dest"/include/amorph/*.h "$dest/lib/libamorph.a"
chmod 755 "$dest/lib/$so" "$dest/bin/$(basename "$prog")"
cat >"$dest/lib/pkgconfig/amorph.pc" <<PC
prefix=$prefix
includedir=\${prefix}/include
libdir=\${prefix}/lib

Name: amorph
Description: evolving amorphous soft robots: a voxel soft-body simulator and a genetic algorithm
Version: $version
Cflags: -I\${includedir} $defs
Libs: -L\${libdir} -lamorph -lm
PC
