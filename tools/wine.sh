#!/bin/sh
# tools/wine.sh PROGRAM [ARGS...]: runs a Windows build of amorph (make TARGET=win64) under wine,
# quietly and without touching $HOME: the wine prefix is build/wine (AMORPH_WINEPREFIX overrides
# it), made on first use (wineboot, some seconds and about 0.7 GB), wine's own messages are off
# (WINEDEBUG=-all) and so is its menu builder (which writes into $HOME). PROGRAM may be named
# without its .exe (build/win64/amorph), as tools/repro.sh names every target's program. The
# program's exit status is this script's; it runs in the caller's folder, so relative paths work.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
WINEPREFIX=${AMORPH_WINEPREFIX:-$root/build/wine}
WINEDEBUG=-all
WINEDLLOVERRIDES="winemenubuilder.exe=d;mscoree=d;mshtml=d"
export WINEPREFIX WINEDEBUG WINEDLLOVERRIDES
if ! command -v wine >/dev/null 2>&1; then
    echo "wine.sh: wine not found (apt-get install wine wine64)" >&2
    exit 127
fi
if [ $# -lt 1 ]; then
    echo "usage: tools/wine.sh PROGRAM[.exe] [ARGS...]" >&2
    exit 2
fi
prog=$1
shift
case "$prog" in *.exe) ;; *) [ -f "$prog.exe" ] && prog=$prog.exe ;; esac
# the prefix, once: its messages ("created the configuration directory") would mix with amorph's
if [ ! -f "$WINEPREFIX/system.reg" ]; then
    mkdir -p "$WINEPREFIX"
    wineboot --init >/dev/null 2>&1 || { echo "wine.sh: wineboot --init failed for $WINEPREFIX" >&2; exit 127; }
fi
exec wine "$prog" "$@"
