#!/bin/sh
# tools/cost_model.sh: the speedup of evaluations spread over P workers (MPI ranks x threads),
# predicted from real runs' evals.csv: every evaluation's cost taken as its voxel-steps (steps x
# voxels, which the simulator's time follows), every generation a barrier. With P workers a
# generation's items, largest body first, are dealt as port/mpi deals them (snake order over the
# workers: 0 1 .. P-1 P-1 .. 0 0 1 ..), and the generation lasts as long as its busiest worker's
# share. Runs given together are one experiment's wave: their generations g are one map.
#   sh tools/cost_model.sh [-P "1 2 3 4 8 16 20 32 64 128 256 512 1024"] EVALS.csv[.gz]...
# Prints per P: the predicted speedup over one worker for both deals, the dynamic deal's
# efficiency, and the bound (the whole work over the generations' largest items: what no P can beat).
set -u
PS="1 2 3 4 8 16 20 32 64 128 256 512 1024"
if [ "${1:-}" = "-P" ]; then PS=$2; shift 2; fi
[ $# -ge 1 ] || { echo "usage: sh tools/cost_model.sh [-P \"P...\"] EVALS.csv[.gz]..." >&2; exit 2; }
for f in "$@"; do
    [ -f "$f" ] || { echo "cost_model: $f: no such file" >&2; exit 2; }
done
runs=$#
for f in "$@"; do

    case $f in *.gz) gzip -dc "$f" ;; *) cat "$f" ;; esac | awk -F, -v run="$f" '
        NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
        { print run, $col["generation"], $col["voxels"], $col["steps"] }'
done | sort -k2,2n -k3,3nr | awk -v ps="$PS" -v runs=$runs '
    # one line per evaluation: run generation voxels steps, a generation'"'"'s items largest first
    function flush(   i, p, w, q, r, k, slot, mx) {
        if (n == 0) return
        gens++
        for (i = 1; i <= n; i++) { total += c[i]; if (c[i] > big) big = c[i] }
        bound += big
        for (q = 1; q <= np; q++) {
            p = P[q]
            for (w = 0; w < p; w++) load[w] = 0
            for (i = 1; i <= n; i++) {
                r = int((i - 1) / p); k = (i - 1) % p
                slot = (r % 2) ? p - 1 - k : k
                load[slot] += c[i]
            }
            mx = 0
            for (w = 0; w < p; w++) if (load[w] > mx) mx = load[w]
            span[q] += mx
            # dynamic: each item, in order, to the worker with the least load so far
            for (w = 0; w < p && w < n; w++) load[w] = 0
            for (i = 1; i <= n; i++) {
                if (i <= p) { load[i - 1] = c[i]; continue }
                k = 0
                for (w = 1; w < p && w < n; w++) if (load[w] < load[k]) k = w
                load[k] += c[i]
            }
            mx = 0
            for (w = 0; w < p && w < n; w++) if (load[w] > mx) mx = load[w]
            dspan[q] += mx
        }
        n = 0; big = 0
    }
    BEGIN { np = split(ps, P, " ") }
    $2 != g { flush(); g = $2 }
    { c[++n] = $3 * $4 }
    END {
        flush()
        printf "cost_model: %d run(s) in lockstep, %d generations, %.3g voxel-steps; bound on speedup (work / largest items) %.1f\n", runs, gens, total, total / bound
        printf "%6s %9s %9s %11s\n", "P", "dynamic", "snake", "efficiency"
        for (q = 1; q <= np; q++) printf "%6d %9.2f %9.2f %10.0f%%\n", P[q], total / dspan[q], total / span[q], 100 * total / dspan[q] / P[q]
    }'
