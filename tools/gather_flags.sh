#!/bin/sh
# tools/gather_flags.sh: the compiler flags that keep vector gathers out of an -march=native build
# on a CPU whose gathers are slow, or nothing (docs/benchmarks.md, Build flags). The Makefile calls
# it for GATHER=auto (the default) and GATHER=off:
#   sh tools/gather_flags.sh CC auto|off     prints the flags, or nothing
#   sh tools/gather_flags.sh CC why          says what it decided and why (make gather-why)
# The link and voxel loops read their voxels through index arrays; under -march=native, gcc's
# tuning for most Intel cores vectorises those reads as gathers (vgatherdps). Where the microcode's
# Gather Data Sampling (Downfall) mitigation is on, a gather costs several times more and the
# native build runs at about half the speed of a generic one; elsewhere the gathers are the
# fastest build. The kernel says which (Linux 6.5 and later, and the stable kernels it went back
# to): /sys/devices/system/cpu/vulnerabilities/gather_data_sampling reads "Not affected" or
# "Vulnerable..." where gathers run at full speed, "Mitigation: ..." where the microcode slows
# them, "Unknown: Dependent on hypervisor status" in a guest of an affected host (which runs the
# microcode, mitigated unless its owner turned it off). Without that file (an older kernel, another
# OS) an Intel CPU is taken as mitigated. On AMD they are left out whatever the kernel says. The choice changes speed only: every build computes the
# same results bit for bit (-ffp-contract=off, no fast-math; make test compares -O0 with -O3).
set -u
CC=${1:-gcc}
MODE=${2:-auto}
STATE_FILE=${GDS_STATE_FILE:-/sys/devices/system/cpu/vulnerabilities/gather_data_sampling}
CPUINFO=${GDS_CPUINFO:-/proc/cpuinfo}

# the compiler's switch: -mno-gather (gcc 14, clang 17 and later), else gcc's tuning control
# (gcc 8 to 13), else none (the compiler cannot be told; the build keeps its gathers)
flag=
for f in -mno-gather "-mtune-ctrl=^use_gather_2parts,^use_gather_4parts,^use_gather"; do
    if echo 'int x;' | $CC -march=native "$f" -Werror -x c -c -o /dev/null - >/dev/null 2>&1; then
        flag=$f
        break
    fi
done

# AMD's gathers are microcoded at every GDS state ("Not affected" says nothing of their speed):
# on a Zen 3 EPYC (family 25 model 1) the native build with gathers ran 1.45 times slower than
# without them (docs/benchmarks.md, Build flags); gcc 12 still emits them for znver3. Intel's run
# at full speed unless the microcode's mitigation is on; the kernel says which.
if [ -r "$STATE_FILE" ]; then
    state=$(head -n 1 "$STATE_FILE")
else
    state="no $STATE_FILE"
fi
if grep -q -m 1 -E 'AuthenticAMD|HygonGenuine' "$CPUINFO" 2>/dev/null; then
    slow=yes why="AMD: gathers are microcoded"
else
    case $state in
    "Not affected"* | Vulnerable*) slow=no why="the microcode does not slow them" ;;
    "Mitigation"* | "Unknown"*) slow=yes why="the microcode's GDS mitigation slows them" ;;
    *)
        if grep -q -m 1 GenuineIntel "$CPUINFO" 2>/dev/null; then
            slow=yes why="Intel without the kernel's word: taken as mitigated"
        else
            slow=no why="neither Intel nor AMD: the compiler's choice"
        fi
        ;;
    esac
fi

case $MODE in
auto) [ "$slow" = yes ] && [ -n "$flag" ] && echo "$flag" ;;
off) [ -n "$flag" ] && echo "$flag" ;;
why)
    echo "gather_flags: gather_data_sampling: $state"
    echo "gather_flags: gathers are slow here: $slow ($why)"
    echo "gather_flags: $CC's switch to leave them out: ${flag:-none}"
    if [ "$slow" = yes ] && [ -n "$flag" ]; then
        echo "gather_flags: the default build (ARCH=native GATHER=auto) leaves gathers out"
    else
        echo "gather_flags: the default build (ARCH=native GATHER=auto) keeps the compiler's choice"
    fi
    ;;
*)
    echo "gather_flags: mode must be auto, off or why, not '$MODE'" >&2
    exit 2
    ;;
esac
exit 0
