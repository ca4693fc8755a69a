#!/bin/sh
# tools/stack_peak.sh (make stack-peak): the stack each board command really takes, measured. The
# board builds (Cortex-M4 under qemu-system-arm -M mps2-an386, and rv32 under qemu-system-riscv32
# -M virt when riscv64-unknown-elf-gcc is installed) are made with -DAM_BAREMETAL_STACK_REPORT:
# the port paints the unused stack at reset and prints "baremetal: stack_used=N heap_used=N" on
# stderr at exit (port/baremetal/boot.c). Each command below runs in a scratch folder holding
# tests/data/board_small.cfg (tests/cli_board.sh's small run) as small.cfg and the folders the
# commands write into, made beforehand (semihosting cannot make folders). Prints a table: target, command, stack
# bytes, heap bytes, exit status; a command that prints no report fails the script. The figures
# include the C library's frames (newlib's printf), which make stack's static figure leaves out
# (docs/porting.md, Stack).
set -u
cd "$(dirname "$0")/.." || exit 2
ROOT=$(pwd)
MAKE=${MAKE:-make}
TIMEOUT=${STACK_PEAK_TIMEOUT:-600}
command -v qemu-system-arm >/dev/null || { echo "stack_peak: qemu-system-arm (Debian qemu-system-arm) is needed" >&2; exit 2; }
command -v arm-none-eabi-gcc >/dev/null || { echo "stack_peak: arm-none-eabi-gcc is needed" >&2; exit 2; }

targets=cortex-m4
command -v riscv64-unknown-elf-gcc >/dev/null && command -v qemu-system-riscv32 >/dev/null && targets="$targets rv32"

W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT INT TERM
cp tests/data/board_small.cfg "$W/small.cfg"

# board TARGET KERNEL ARGS...: runs one command on a board from the scratch folder, its output
# in $W/out and $W/err
board() {
    t=$1 k=$2
    shift 2
    m=mps2-an386
    [ "$t" = rv32 ] && m=riscv32-virt
    (cd "$W" && BOARD_TIMEOUT=$TIMEOUT sh "$ROOT/tools/board.sh" $m "$k" "$@" >"$W/out" 2>"$W/err")
}

bad=0
printf '%-10s %-78s %6s %6s %s\n' target command stack heap status
for t in $targets; do
    b=build/stackpeak/$t
    $MAKE --no-print-directory TARGET=$t PROFILE=board BUILD=$b CFLAGS=-DAM_BAREMETAL_STACK_REPORT "$b/amorph" >"$W/build.log" 2>&1 ||
        { cat "$W/build.log"; echo "stack_peak: the $t build failed" >&2; exit 1; }
    k=$(cd "$b" && pwd)/amorph
    rm -rf "$W/evo" "$W/exp"
    mkdir -p "$W/evo" "$W/exp/dct-1" "$W/exp/cppn-1" "$W/exp/gmx-1"
    while IFS='|' read -r label args; do
        [ -n "$label" ] || continue
        # shellcheck disable=SC2086 # the arguments are words without spaces
        board "$t" "$k" $args
        rc=$?
        used=$(sed -n 's/.*baremetal: stack_used=\([0-9]*\) heap_used=\([0-9]*\).*/\1 \2/p' "$W/err" | tail -n 1)
        if [ -z "$used" ]; then
            echo "stack_peak: $t $label: no stack report (status $rc): $(tail -n 2 "$W/err" | tr '\n' ' ')" >&2
            bad=1
            continue
        fi
        printf '%-10s %-78s %6s %6s %s\n' "$t" "$label" "${used% *}" "${used#* }" "$rc"
    done <<'CMDS'
evolve|evolve --config small.cfg --evaluations 24 --out evo --quiet
evolve --resume|evolve --resume evo --evaluations 48 --quiet
experiment|experiment representations --evals 12 --runs 1 --config small.cfg --out exp --quiet
experiment resuming its runs|experiment representations --evals 24 --runs 1 --config small.cfg --out exp --quiet
repro|repro
sim of a run folder|sim evo
sim of a genome file in a run folder|sim evo/best.genome
express|express evo/best.genome
sim --scene sphere:6|sim --scene sphere:6
bench|bench
CMDS
done
[ $bad -eq 0 ] || exit 1
