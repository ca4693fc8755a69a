#!/bin/sh
# tools/bench_arch.sh: the same code under several -march choices, side by side on the machine at
# hand (make bench-arch builds them; docs/benchmarks.md, Build flags). For each build:
#   - voxel-steps per second and simulated seconds per second of `amorph bench --scene sphere:20
#     --collisions off` (2,000 actuated steps), run in turns (every build once per turn, the turns
#     within the same minutes: a VM's speed moves), the median of the turns;
#   - instructions per voxel-step: (instructions of 300 steps - of 100 steps) / (220 x voxels), from
#     `perf stat` where the CPU's counters are readable, else from callgrind where valgrind can run
#     the build (it has no AVX-512), else n/a;
#   - the hash of `amorph sim --scene sphere:8`: every build must give the same one.
# The build the default `make` made (DEFAULT_DIR=, build) is marked in the table.
#   sh tools/bench_arch.sh [BUILD_DIR...]            (TURNS=5; make bench-arch)
set -u
TURNS=${TURNS:-5}
DEFAULT_DIR=${DEFAULT_DIR:-build}
[ $# -gt 0 ] || { echo "bench_arch: usage: sh tools/bench_arch.sh BUILD_DIR..." >&2; exit 2; }
for d in "$@"; do
    [ -x "$d/amorph" ] || { echo "bench_arch: $d/amorph not built (make bench-arch builds it)" >&2; exit 2; }
done
out=$(mktemp)
trap 'rm -f "$out" "$out.perf"' EXIT
echo "bench_arch: sphere:20 without self-collision, $TURNS turns, $(uname -m), $(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | cut -d: -f2 | sed 's/^ //')"
[ -r /sys/devices/system/cpu/vulnerabilities/gather_data_sampling ] &&
    echo "bench_arch: gather_data_sampling: $(cat /sys/devices/system/cpu/vulnerabilities/gather_data_sampling)"

# the value of key K in a line of key=value words
field() { tr ' ' '\n' | sed -n "s/^$1=//p" | head -n 1; }
# the median over the turns of key K of build directory D
median() {
    grep "^$2 " "$out" | field "$1" | sort -g | awk '{r[NR] = $1} END {print (NR % 2 ? r[(NR + 1) / 2] : (r[NR / 2] + r[NR / 2 + 1]) / 2)}'
}

for turn in $(seq 1 "$TURNS"); do
    for d in "$@"; do
        line=$("$d/amorph" bench --scene sphere:20 --collisions off | grep '^scene=')
        echo "$d $line" >>"$out"
    done
    echo "turn $turn of $TURNS done"
done

# the instructions callgrind counts in N steps of binary $1 (fails where valgrind cannot run it)
callgrind_ir() {
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "$1" bench --scene sphere:20 --collisions off --steps "$2" >/dev/null 2>"$out.perf" ||
        return 1
    sed -n 's/.*Collected : *\([0-9]*\).*/\1/p' "$out.perf" | grep .
}

# instructions per voxel-step of build $1, or n/a
instructions() {
    b=$1/amorph
    nv=$("$b" bench --scene sphere:20 --collisions off --steps 10 | grep '^scene=' | field voxels)
    if perf stat -x, -e instructions -o "$out.perf" "$b" bench --scene sphere:20 --collisions off --steps 100 >/dev/null 2>&1 &&
        i1=$(awk -F, '/instructions/ && $1 ~ /^[0-9]+$/ {print $1}' "$out.perf") && [ -n "$i1" ] &&
        perf stat -x, -e instructions -o "$out.perf" "$b" bench --scene sphere:20 --collisions off --steps 300 >/dev/null 2>&1 &&
        i3=$(awk -F, '/instructions/ && $1 ~ /^[0-9]+$/ {print $1}' "$out.perf") && [ -n "$i3" ]; then
        echo "$i1 $i3 $nv perf" | awk '{printf "%.0f (%s)", ($2 - $1) / (220 * $3), $4}'
        return
    fi
    if command -v valgrind >/dev/null 2>&1 && i1=$(callgrind_ir "$b" 100) && i3=$(callgrind_ir "$b" 300); then
        echo "$i1 $i3 $nv" | awk '{printf "%.0f (callgrind)", ($2 - $1) / (220 * $3)}'
        return
    fi
    echo "n/a"
}

echo
printf '%-28s %-28s %12s %8s %10s %11s  %-18s %s\n' build vector voxel_steps/s ns/step sim_s/s "(of best)" instructions/step hash
best=$(for d in "$@"; do median voxel_steps_per_s "$d"; done | sort -g | tail -n 1)
hashes=
for d in "$@"; do
    med=$(median voxel_steps_per_s "$d")
    sims=$(median sim_s_per_s "$d")
    build=$("$d/amorph" bench --scene cube:2 --steps 10 | grep '^build ' | sed 's/^build //')
    vec=$(echo "$build" | field vector)/$(echo "$build" | field gathers)
    hash=$("$d/amorph" sim --scene sphere:8 --json | tr ',' '\n' | sed -n 's/.*"hash": "\([0-9a-f]*\)".*/\1/p')
    hashes="$hashes $hash"
    name=$d
    [ "$d" = "$DEFAULT_DIR" ] && name="$d (default)"
    printf '%-28s %-28s %12.4g %8.2f %10.4f %10.0f%%  %-18s %s\n' "$name" "$vec" "$med" "$(echo "$med" | awk '{print 1e9 / $1}')" "$sims" \
        "$(echo "$med $best" | awk '{print 100 * $1 / $2}')" "$(instructions "$d")" "$hash"
done
n=$(echo "$hashes" | tr ' ' '\n' | sed '/^$/d' | sort -u | wc -l)
[ "$n" -eq 1 ] && echo "same_hash=yes" || { echo "same_hash=NO"; exit 1; }
