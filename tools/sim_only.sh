#!/bin/sh
# tools/sim_only.sh [float|fixed] (make repro): the simulator alone on the Cortex-M boards
# (tools/board_sim/, make sim-only TARGET=...). For cortex-m3 and cortex-m4 it builds board_sim
# (PROFILE=board, REAL as given) beside the whole program's build, and checks
#   - with nm, that the image holds no global symbol defined by an object of src/evo, src/io,
#     tools/ or port/ (of the same build of the whole program), and none named am_evo_*, am_port_*,
#     tool_* or cmd_*;
#   - under qemu-system-arm (mps2-an385 / mps2-an386, semihosting), that each robot's hash equals
#     the one the desktop build DESKTOP (an amorph of the same REAL: build/amorph for float,
#     build/fixed/amorph for fixed unless given) prints for the same robot;
# and prints the image's RAM (data + bss, its stack included) and flash (text + data) from
# arm-none-eabi-size as a row "memory NAME-sim-only ...", the format of make repro's rows.
# Skipped (status 0) without arm-none-eabi-gcc or qemu-system-arm. Exit status 1 on a failure.
set -u
cd "$(dirname "$0")/.."
REAL=${1:-float}
case "$REAL" in
float) DESKTOP=${DESKTOP:-build/amorph} ;;
fixed) DESKTOP=${DESKTOP:-build/fixed/amorph} ;;
*) echo "sim_only: the number type must be float or fixed, not '$REAL'" >&2; exit 2 ;;
esac
MAKE=${MAKE:-make}
JOBS=${JOBS:-2}
RAM_MAX=196608
FLASH_MAX=262144
if ! command -v arm-none-eabi-gcc >/dev/null 2>&1 || ! command -v qemu-system-arm >/dev/null 2>&1; then
    echo "sim_only: no arm-none-eabi-gcc or qemu-system-arm: skipped"
    exit 0
fi
mkdir -p build/repro
bad=0
fail() { echo "sim_only: $*"; bad=$((bad + 1)); }

# the desktop's hash of a robot: sim_hash ROBOT-ARGS...
sim_hash() { "$DESKTOP" sim "$@" --cycles 1 2>/dev/null | sed -n 's/^hash = \([0-9a-f]\{16\}\)$/\1/p'; }
want_scene= want_genome=
if [ -x "$DESKTOP" ]; then
    want_scene=$(sim_hash --scene sphere:6)
    g=build/repro/sim-only-seed1.genome
    "$DESKTOP" random --seed 1 --representation dct --workspace 6 --out "$g" && want_genome=$(sim_hash "$g")
fi
[ -n "$want_scene" ] && [ -n "$want_genome" ] || fail "$DESKTOP gave no hash for sphere:6 or the genome of seed 1 (build it: make$([ "$REAL" = fixed ] && echo " BUILD=build/fixed REAL=fixed"))"

for name in cortex-m3 cortex-m4; do
    build=build/$name$([ "$REAL" = float ] || echo "-$REAL")
    log=build/repro/$name-sim-only-$REAL.log
    if ! $MAKE --no-print-directory -j"$JOBS" TARGET=$name PROFILE=board REAL=$REAL "$build/amorph" sim-only >"$log" 2>&1; then
        fail "$name: the build failed ($log)"
        continue
    fi
    bin=$build/board_sim
    # no global symbol of the evolver, the codecs, the program or the port (but main and the C
    # library's system calls, _sbrk ..., which board_sim has of its own)
    others=$(for o in $build/src/evo/*.o $build/src/io/*.o $build/tools/*.o $build/port/*/*.o $build/port/*/*/*.o; do
        [ -f "$o" ] && arm-none-eabi-nm -g --defined-only "$o" | awk 'NF == 3 { print $3 }'; done | grep -v -E '^(main$|_)' | LC_ALL=C sort -u)
    arm-none-eabi-nm --defined-only "$bin" | awk 'NF == 3 { print $3 }' | LC_ALL=C sort -u >"$build/board_sim.syms"
    n_others=$(echo "$others" | grep -c .)
    [ "$n_others" -gt 100 ] || fail "$name: only $n_others symbols of src/evo, src/io, tools and port/ found to look for"
    leak=$({ echo "$others" | LC_ALL=C comm -12 - "$build/board_sim.syms"; grep -E '^(am_evo_|am_port_|tool_|cmd_)' "$build/board_sim.syms"; } |
        sort -u | tr '\n' ' ')
    [ -z "$leak" ] || fail "$name: board_sim holds symbols of src/evo, src/io, tools or port: $leak"
    machine=mps2-an386
    [ "$name" = cortex-m3 ] && machine=mps2-an385
    # (QEMU writes the semihosting console, SYS_WRITE0, to its standard error)
    out=$(BOARD_TIMEOUT=900 sh tools/board.sh $machine "$bin" 2>&1)
    rc=$?
    echo "$out" >>"$log"
    got_scene=$(echo "$out" | sed -n 's/^scene=sphere:6 hash=\([0-9a-f]*\).*/\1/p')
    got_genome=$(echo "$out" | sed -n 's/^genome=dct:6:seed1 hash=\([0-9a-f]*\).*/\1/p')
    [ $rc -eq 0 ] || fail "$name: board_sim exited with status $rc ($log)"
    [ -n "$got_scene" ] && [ "$got_scene" = "$want_scene" ] || fail "$name: sphere:6 hash ${got_scene:-(none)}, the desktop's $want_scene"
    [ -n "$got_genome" ] && [ "$got_genome" = "$want_genome" ] || fail "$name: genome of seed 1 hash ${got_genome:-(none)}, the desktop's $want_genome"
    sizes=$(arm-none-eabi-size "$bin" | awk 'NR == 2 { print $1 + $2, $2 + $3 }')
    flash=${sizes% *} ram=${sizes#* }
    printf 'memory %-15s RAM %7d of %d bytes, flash %7d of %d (sphere:6 %s, genome %s, %s, %d global symbols of evo/io/tools/port absent)\n' \
        "$name-sim-only" "$ram" $RAM_MAX "$flash" $FLASH_MAX "${got_scene:-?}" "${got_genome:-?}" \
        "$(echo "$out" | sed -n 's/^\(stack_used=[0-9]*\).*/\1/p')" "$n_others"
done
if [ $bad -ne 0 ]; then echo "sim_only: 0 passed, $bad failed"; exit 1; fi
echo "sim_only ($REAL): board_sim on cortex-m3 and cortex-m4 gives the desktop's hashes ($want_scene, $want_genome), no symbol of evo, io, tools or port"
