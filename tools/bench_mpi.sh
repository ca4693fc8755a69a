#!/bin/sh
# tools/bench_mpi.sh: evaluations per hour of the default experiment on 1 and 2 threads of the
# POSIX build against 1 and 2 ranks (one thread each) of the MPI build, the 2 ranks with the
# dynamic deal and with the fixed snake deal (AMORPH_MPI_DEAL=static), in turns (the five runs of
# a turn follow each other within the same minutes: this VM's speed moves), and the parallel map's
# own cost per item (map_us_per_item: the transport of a result between ranks, or the hand-over
# to a thread). Every run prints its run hash: all must be equal.
#   sh tools/bench_mpi.sh [EVALS] [TURNS]      (make bench-mpi; EVALS 60, TURNS 2)
# Needs build/amorph and build/mpi/amorph (make; make PORT=mpi) and mpirun.
set -u
EVALS=${1:-60}
TURNS=${2:-2}
POSIX=${POSIX:-build/amorph}
MPI=${MPI:-build/mpi/amorph}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
for b in "$POSIX" "$MPI"; do
    [ -x "$b" ] || { echo "bench_mpi: $b not built (make; make PORT=mpi)" >&2; exit 2; }
done
command -v mpirun >/dev/null 2>&1 || { echo "bench_mpi: mpirun not found (apt-get install openmpi-bin)" >&2; exit 2; }
out=$(mktemp)
trap 'rm -f "$out"' EXIT
echo "bench_mpi: default experiment, $EVALS evaluations a run, $TURNS turns, $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'))"
for turn in $(seq 1 "$TURNS"); do
    for cfg in "threads 1" "threads 2" "ranks 1" "ranks 2" "ranks 2 static"; do
        set -- $cfg
        if [ "$1" = threads ]; then
            line=$("$POSIX" bench --evolve --evals "$EVALS" --threads "$2" | grep '^processes=.* threads=')
        else
            deal=${3:-dynamic}
            line=$(mpirun -q --oversubscribe -np "$2" -x AMORPH_MPI_DEAL=$deal "$MPI" bench --evolve --evals "$EVALS" --threads 1 |
                grep '^processes=.* threads=')
        fi
        echo "$cfg $line" >>"$out"
        echo "turn $turn: $cfg: $line"
    done
done
echo
printf '%-15s %14s %14s %16s  %s\n' config evals_per_hour "(per turn)" map_us_per_item run_hash
for cfg in "threads 1" "threads 2" "ranks 1" "ranks 2" "ranks 2 static"; do
    grep "^$cfg processes" "$out" | awk -v c="$cfg" '
        { for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] }
          r[NR] = v["evals_per_hour"]; m[NR] = v["map_us_per_item"]; h = v["run_hash"]; list = list (NR > 1 ? "," : "") v["evals_per_hour"] }
        END { n = NR; for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (r[j] < r[i]) { t = r[i]; r[i] = r[j]; r[j] = t }
              med = n % 2 ? r[(n + 1) / 2] : (r[n / 2] + r[n / 2 + 1]) / 2
              printf "%-15s %14.0f %14s %16s  %s\n", c, med, list, m[n], h }'
done
hashes=$(sed 's/.*run_hash=//' "$out" | sort -u | wc -l)
[ "$hashes" -eq 1 ] && echo "same_hash=yes" || { echo "same_hash=NO"; exit 1; }
