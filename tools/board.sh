#!/bin/sh
# tools/board.sh MACHINE PROGRAM [ARGS...]: runs a bare-metal board build (PROFILE=board,
# port/baremetal) under QEMU with semihosting, the way a native amorph runs: ARGS are its arguments
# (its argv[0] is "amorph"), its output the program's, the exit status the program's (124 when
# BOARD_TIMEOUT seconds pass first, 600 by default). The program reads and writes files relative
# to the caller's folder (semihosting opens them on the host).
# MACHINE is a qemu-system-arm machine (mps2-an385 for the Cortex-M3 build, mps2-an386 for the
# Cortex-M4F build) or riscv32-virt (the rv32 build, qemu-system-riscv32 -M virt without a BIOS).
# BOARD_ICOUNT=1 adds -icount shift=0: the board's clock then advances 1 ns an instruction, so a
# time the program prints is its instruction count (tools/bench_board.sh).
# Semihosting hands the program one command line split at spaces: an argument holding a space or
# a tab is refused (status 2); a comma is doubled for QEMU's option syntax.
# Used by tools/repro.sh, tools/sim_only.sh, tools/bench_board.sh, tools/stack_peak.sh and
# tests/cli_board.sh.
set -u
usage() { echo "usage: tools/board.sh mps2-an385|mps2-an386|riscv32-virt PROGRAM [ARGS...]" >&2; exit 2; }
[ $# -ge 2 ] || usage
machine=$1 program=$2
shift 2
TIMEOUT=${BOARD_TIMEOUT:-600}
case $TIMEOUT in '' | *[!0-9]* | 0) echo "board.sh: BOARD_TIMEOUT='$TIMEOUT': a whole number of seconds from 1" >&2; exit 2 ;; esac
bios=""
case $machine in
riscv32-virt) qemu=qemu-system-riscv32 m=virt bios="-bios none" ;;
mps2-an385 | mps2-an386) qemu=qemu-system-arm m=$machine ;;
*) echo "board.sh: '$machine': not a board machine (mps2-an385, mps2-an386 or riscv32-virt)" >&2; exit 2 ;;
esac
[ -f "$program" ] || { echo "board.sh: $program: no such file" >&2; exit 2; }
cmdline="arg=amorph"
for a in "$@"; do
    case $a in *' '* | *'	'*) echo "board.sh: argument '$a': semihosting splits the command line at spaces" >&2; exit 2 ;; esac
    cmdline="$cmdline,arg=$(printf '%s' "$a" | sed 's/,/,,/g')"
done
command -v "$qemu" >/dev/null 2>&1 || { echo "board.sh: $qemu not found (Debian qemu-system-arm, qemu-system-misc)" >&2; exit 127; }
icount=""
[ "${BOARD_ICOUNT:-0}" = 1 ] && icount="-icount shift=0"
# shellcheck disable=SC2086 # $bios and $icount are words without spaces, or nothing
exec timeout "$TIMEOUT" "$qemu" -M "$m" $bios -nographic -monitor none -serial none $icount \
    -semihosting-config "enable=on,target=native,$cmdline" -kernel "$program" </dev/null
