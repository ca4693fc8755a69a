#!/bin/sh
# tools/bench_board.sh (make bench-board): what a board really costs. The same work on three
# Cortex-M builds under QEMU, counted in instructions: the Cortex-M3 in fixed point, the
# Cortex-M3 in float (soft float: every operation a library call), the Cortex-M4F in float
# (FPv4-SP hardware). Each is built with -DAM_BAREMETAL_ICOUNT, whose clock is the MPS2 FPGA
# counter, and run with -icount shift=0, under which the board's time advances 1 ns per
# instruction: every figure amorph prints in seconds is then instructions / 1e9, independent of
# the host's speed and load.
#   1. `amorph bench` on sphere:8 (the board profile's largest sphere) with and without
#      self-collision: instructions per voxel-step of the simulator's step.
#   2. `amorph sim` of one robot in the seed's evaluation (relaxation, then 10 cycles of 500
#      steps): a random GMX genome of the board's 8^3 workspace (seed 1, expressed with the
#      built-in palette), the same file for the three builds: instructions per evaluation, and
#      the evaluations per hour they give at 100 MHz and 168 MHz, assuming one instruction per
#      cycle (a Cortex-M3/M4 runs most instructions in one cycle; loads, divisions, branches
#      and flash wait states take more, so real boards are slower by their CPI).
# Prints name=value lines and a table. Needs arm-none-eabi-gcc and qemu-system-arm.
set -u
cd "$(dirname "$0")/.."
MAKE=${MAKE:-make}
OUT=build/bench-board
STEPS=${BENCH_BOARD_STEPS:-300}
mkdir -p "$OUT"
for tool in arm-none-eabi-gcc qemu-system-arm; do
    command -v $tool >/dev/null 2>&1 || { echo "bench-board: $tool not found" >&2; exit 2; }
done
# the robot: written by the host build (a genome file is the same text for every build)
[ -x build/amorph ] || $MAKE --no-print-directory build/amorph >/dev/null || exit 1
build/amorph random --representation gmx --workspace 8 --seed 1 --out "$OUT/robot.genome" || exit 1

# name | make variables | qemu machine
BUILDS="m3-fixed|TARGET=cortex-m3 REAL=fixed|mps2-an385
m3-float|TARGET=cortex-m3 REAL=float|mps2-an385
m4-float|TARGET=cortex-m4 REAL=float|mps2-an386"

# run BIN MACHINE ARGS...: amorph ARGS on the board, instruction-counted
run() {
    bin=$1 machine=$2
    shift 2
    BOARD_TIMEOUT=1800 BOARD_ICOUNT=1 sh tools/board.sh "$machine" "$bin" "$@"
}
field() { echo "$1" | tr ' ' '\n' | sed -n "s/^$2=//p" | head -n 1; }

echo "$BUILDS" | while IFS='|' read -r name vars machine; do
    b=$OUT/$name
    # shellcheck disable=SC2086
    $MAKE --no-print-directory -j"${JOBS:-2}" PROFILE=board $vars BUILD="$b" CFLAGS=-DAM_BAREMETAL_ICOUNT "$b/amorph" \
        >"$b.log" 2>&1 || { echo "bench-board: $name: build failed ($b.log)" >&2; exit 1; }
    for coll in on off; do
        line=$(run "$b/amorph" "$machine" bench --scene sphere:8 --steps "$STEPS" --repeat 1 --collisions $coll | grep '^scene=')
        echo "${name}_step_collisions_${coll}_instructions_per_voxel_step=$(field "$line" ns_per_voxel_step)"
    done
    res=$(run "$b/amorph" "$machine" sim "$OUT/robot.genome")
    secs=$(echo "$res" | sed -n 's/^wall_seconds = //p')
    vox=$(echo "$res" | sed -n 's/^voxels = //p')
    steps=$(echo "$res" | sed -n 's/^steps = //p')
    hash=$(echo "$res" | sed -n 's/^hash = //p')
    echo "$secs $vox $steps" | awk -v n="$name" -v h="$hash" '{ ins = $1 * 1e9; vs = $2 * $3;
        printf "%s_evaluation voxels=%d steps=%d instructions=%.4g instructions_per_voxel_step=%.0f evals_per_hour_100MHz=%.0f evals_per_hour_168MHz=%.0f hash=%s\n",
            n, $2, $3, ins, ins / vs, 3600 * 100e6 / ins, 3600 * 168e6 / ins, h }'
done | tee "$OUT/results.txt"
awk '/^m3-fixed_evaluation/ { for (i = 1; i <= NF; i++) if ($i ~ /^instructions=/) { split($i, a, "="); fx = a[2] } }
     /^m3-float_evaluation/ { for (i = 1; i <= NF; i++) if ($i ~ /^instructions=/) { split($i, a, "="); fl = a[2] } }
     END { if (fx > 0 && fl > 0) printf "m3_soft_float_over_fixed=%.2f\n", fl / fx }' "$OUT/results.txt"
