#!/bin/sh
# tools/repro.sh (make repro): one reference computation, built and run on every target we claim
# bit-identical results on, must print the same 64-bit hash everywhere, equal to the pinned one.
#   x86-64: gcc -O0, gcc -O3 -march=native, clang -O2 (native)
#   aarch64, armhf, riscv64, s390x (big-endian) and i686 (32-bit x86, SSE2 arithmetic) Linux:
#   Debian cross compilers, static, under qemu-user
#   Cortex-M3 (soft float) and Cortex-M4F (hard float): bare metal under qemu-system-arm
#   (mps2-an385 / mps2-an386) with semihosting
#   RISC-V 32-bit (rv32imafc, single-precision FPU): bare metal under qemu-system-riscv32 (virt)
#   with semihosting
#   Windows x86-64: mingw-w64, static, port/win32, under wine (tools/wine.sh: prefix build/wine)
# and the simulator alone on the Cortex-M boards (make sim-only; tools/sim_only.sh)
# Every build uses PROFILE=board. Prints a table (target, hash, seconds) and fails unless every
# hash equals REPRO_EXPECT. Builds log to build/repro/<target>.log.
# REPRO_ARGS is the reference computation: the amorph command line (without "amorph"); its
# output must hold "repro_hash=<16 hex>" or a JSON "hash": "<16 hex>". Arguments must not
# contain spaces (semihosting passes one command-line string).
set -u
cd "$(dirname "$0")/.."

# the number type is the first argument: float (default) or fixed, each with its pinned hash
REAL=${1:-float}
case "$REAL" in
float) REPRO_EXPECT=${REPRO_EXPECT:-3d35b249bf334b1b} ;;
fixed) REPRO_EXPECT=${REPRO_EXPECT_FIXED:-5a1b76ab7b19a89a} ;;
*) echo "repro: the number type must be float or fixed, not '$REAL'" >&2; exit 2 ;;
esac
REPRO_ARGS=${REPRO_ARGS:-"repro"}
JOBS=${JOBS:-2}
MAKE=${MAKE:-make}
TIMEOUT=${REPRO_TIMEOUT:-600}

# name | make variables (besides PROFILE=board) | how to run (native, a qemu-user binary, or
# board:<machine>: under QEMU by tools/board.sh, mps2-an385, mps2-an386 or riscv32-virt)
# (a runner script is given the program's path: tools/wine.sh runs a Windows build's amorph.exe)
TARGETS="cortex-m3|TARGET=cortex-m3|board:mps2-an385
cortex-m4|TARGET=cortex-m4|board:mps2-an386
rv32|TARGET=rv32|board:riscv32-virt
x86_64-gcc-O0|BUILD=build/repro/gcc-O0-REAL CC=gcc OPT=-O0 ARCH=|native
x86_64-gcc-O3-native|BUILD=build/repro/gcc-O3-native-REAL CC=gcc OPT=-O3 ARCH=native|native
x86_64-clang-O2|BUILD=build/repro/clang-O2-REAL CC=clang OPT=-O2 ARCH=|native
win64|TARGET=win64|tools/wine.sh
aarch64-linux|TARGET=aarch64-linux|qemu-aarch64
armhf-linux|TARGET=armhf-linux|qemu-arm
riscv64-linux|TARGET=riscv64-linux|qemu-riscv64
s390x-linux|TARGET=s390x-linux|qemu-s390x
i686-linux|TARGET=i686-linux|qemu-i386"

TARGETS=$(echo "$TARGETS" | sed "s/-REAL /-$REAL /")
mkdir -p build/repro
out=build/repro/results-$REAL.txt
: >"$out"

now() { date +%s.%N; }
# the build folder a line's make variables select
build_of() {
    case "$1" in
    *BUILD=*) echo "$1" | sed 's/.*BUILD=\([^ ]*\).*/\1/' ;;
    *TARGET=*) echo "build/$(echo "$1" | sed 's/.*TARGET=\([^ ]*\).*/\1/')$([ "$REAL" = float ] || echo "-$REAL")" ;;
    esac
}
# runs a built amorph the way a target's line says, output and exit status its own, bounded by
# TIMEOUT: run_as HOW BIN ARGS... (HOW: native, board:<machine>, or a program given BIN first)
run_as() {
    how=$1
    shift
    case "$how" in
    native) timeout "$TIMEOUT" "$@" ;;
    board:*) BOARD_TIMEOUT=$TIMEOUT sh tools/board.sh "${how#board:}" "$@" ;;
    *) timeout "$TIMEOUT" "$how" "$@" ;;
    esac
}
# whether this machine has what run_as HOW needs
can_run() {
    case "$1" in
    native) true ;;
    board:riscv32-virt) command -v qemu-system-riscv32 >/dev/null 2>&1 ;;
    board:*) command -v qemu-system-arm >/dev/null 2>&1 ;;
    *) command -v "$1" >/dev/null 2>&1 ;;
    esac
}
# builds and runs one target; appends "name hash seconds" to $out
one() {
    name=$1 vars=$2 how=$3
    build=$(build_of "$vars")
    log=build/repro/$name-$REAL.log
    # shellcheck disable=SC2086
    if ! $MAKE --no-print-directory -j"$JOBS" PROFILE=board REAL=$REAL $vars "$build/amorph" >"$log" 2>&1; then
        echo "$name (build-failed) -" >>"$out"
        return
    fi
    t0=$(now)
    # shellcheck disable=SC2086
    res=$(run_as "$how" "$build/amorph" $REPRO_ARGS 2>>"$log")
    rc=$?
    t1=$(now)
    echo "$res" >>"$log"
    hash=$(echo "$res" | sed -n 's/.*repro_hash=\([0-9a-f]\{16\}\).*/\1/p; s/.*"hash": "\([0-9a-f]\{16\}\)".*/\1/p' | head -n 1)
    [ $rc -eq 0 ] || hash="(exit-status-$rc)"
    [ -n "$hash" ] || hash="(no-hash)"
    echo "$name $hash $(echo "$t1 $t0" | awk '{printf "%.2f", $1 - $2}')" >>"$out"
}

start=$(now)
echo "repro ($REAL): amorph $REPRO_ARGS (expected hash $REPRO_EXPECT)"
# the slow Cortex-M3 run goes on in the background while the others build
echo "$TARGETS" | {
    first=1
    while IFS='|' read -r name vars how; do
        if [ $first = 1 ]; then
            first=0
            one "$name" "$vars" "$how" &
        else
            one "$name" "$vars" "$how"
        fi
    done
    wait
}
printf '%-22s %-18s %8s\n' target hash seconds
bad=0
for name in $(echo "$TARGETS" | cut -d'|' -f1); do
    line=$(grep "^$name " "$out")
    hash=$(echo "$line" | cut -d' ' -f2)
    secs=$(echo "$line" | cut -d' ' -f3)
    mark=""
    [ "$hash" = "$REPRO_EXPECT" ] || { mark="  MISMATCH (build/repro/$name-$REAL.log)"; bad=$((bad + 1)); }
    printf '%-22s %-18s %8s%s\n' "$name" "${hash:-(missing)}" "${secs:--}" "$mark"
done
# the board budget: with the board profile's population of 20, at most 192 KiB of RAM (data + bss,
# stack and heap arena included) and 256 KiB of flash (text + data), from arm-none-eabi-size
# (riscv64-unknown-elf-size for rv32)
RAM_MAX=196608
FLASH_MAX=262144
for name in cortex-m3 cortex-m4 rv32; do
    bin=$(build_of "TARGET=$name")/amorph
    size=arm-none-eabi-size
    [ "$name" = rv32 ] && size=riscv64-unknown-elf-size
    [ -f "$bin" ] && command -v $size >/dev/null 2>&1 || continue
    sizes=$($size "$bin" | awk 'NR == 2 { print $1 + $2, $2 + $3 }')
    flash=${sizes% *} ram=${sizes#* }
    mark=""
    if [ "$ram" -gt $RAM_MAX ] || [ "$flash" -gt $FLASH_MAX ]; then mark="  OVER BUDGET"; bad=$((bad + 1)); fi
    printf 'memory %-15s RAM %7d of %d bytes, flash %7d of %d%s\n' "$name" "$ram" $RAM_MAX "$flash" $FLASH_MAX "$mark"
done
# the simulator alone (make sim-only, tools/board_sim/): its RAM and flash as rows beside the whole
# program's, no symbol of src/evo, src/io, tools or the port in it (nm), and each of its robots'
# hashes equal to the x86-64 build's for the same robot (tools/sim_only.sh)
DESKTOP=$(build_of "BUILD=build/repro/gcc-O3-native-$REAL")/amorph JOBS=$JOBS MAKE=$MAKE sh tools/sim_only.sh "$REAL" || bad=$((bad + 1))
# byte order: a run checkpointed by the x86-64 build resumes on the big-endian s390x build (and on
# 32-bit i686) to the run the x86-64 build makes uninterrupted: same run hash, same best genome
SMALL="--workspace 6 --population 8 --cycles 1 --period_steps 100 --relax_max_steps 400 --relax_min_steps 50 --release_steps 100 --quiet --no-pictures --threads 1"
native=$(build_of "BUILD=build/repro/gcc-O3-native-$REAL")/amorph
# two genome files hold the same genome: the same tokens, numbers compared by value (each C library
# prints a double its own way: glibc's %.17g gives 3.2262551784515381 where picolibc gives the
# shortest form 3.226255178451538, the same double)
same_genome() {
    awk 'NR == FNR { line[FNR] = $0; n = FNR; next }
         { if (FNR > n) bad = 1; k = split(line[FNR], a); if (k != NF) bad = 1
           for (i = 1; i <= NF; i++) if (a[i] != $i && (a[i] !~ /^[-+0-9.eE]+$/ || a[i] + 0 != $i + 0)) bad = 1 }
         END { exit bad || FNR != n }' "$1" "$2"
}
cross_resume() {
    name=$1 how=$2
    bin=$(build_of "TARGET=$name")/amorph
    [ -x "$bin" ] || [ ! -f "$bin.exe" ] || bin=$bin.exe
    [ -x "$native" ] && [ -x "$bin" ] && can_run "$how" || return 0
    d=build/repro/resume-$name-$REAL
    rm -rf "$d" && mkdir -p "$d"
    # shellcheck disable=SC2086
    "$native" evolve $SMALL --evaluations 32 --out "$d/whole" >/dev/null 2>&1 &&
        "$native" evolve $SMALL --evaluations 16 --out "$d/half" >/dev/null 2>&1 &&
        run_as "$how" "$bin" evolve --resume "$d/half" --evaluations 32 --quiet --no-pictures >/dev/null 2>>"$d/err"
    a=$(sed -n 's/^run_hash = //p' "$d/whole/summary.txt" 2>/dev/null)
    b=$(sed -n 's/^run_hash = //p' "$d/half/summary.txt" 2>/dev/null)
    mark=""
    if [ -z "$a" ] || [ "$a" != "$b" ] || ! same_genome "$d/whole/best.genome" "$d/half/best.genome"; then
        mark="  DIFFERS ($d)"
        bad=$((bad + 1))
    fi
    printf 'resume on %-13s x86-64 checkpoint: run %s, uninterrupted %s%s\n' "$name" "${b:-(none)}" "${a:-(none)}" "$mark"
}
cross_resume s390x-linux qemu-s390x
cross_resume i686-linux qemu-i386
# and on the rv32 board, whose C library (picolibc) reads the checkpoint's numbers
cross_resume rv32 board:riscv32-virt
cross_resume win64 tools/wine.sh
n=$(wc -l <"$out")
total=$(echo "$(now) $start" | awk '{printf "%.0f", $1 - $2}')
if [ "$bad" -ne 0 ]; then
    echo "repro ($REAL): $bad of $n targets differ from $REPRO_EXPECT or exceed the board budget (${total}s)"
    exit 1
fi
echo "repro ($REAL): all $n targets print $REPRO_EXPECT (${total}s)"
