#!/bin/sh
# tests/cli_mpi.sh: the MPI build (port/mpi, make PORT=mpi) under Open MPI's mpirun on this machine
# (loopback, --oversubscribe), against the POSIX build $BUILD/amorph on one thread. `make test`
# builds it into $BUILD/mpi and sets MPI_BUILD when mpicc and mpirun are installed; skipped
# otherwise. Checked: an evolution at 1, 2 and 3 ranks (and 2 ranks of 2 threads, and 3 ranks with
# the fixed deal, AMORPH_MPI_DEAL=static) gives the
# one-thread run hash, log.csv (wall time aside), evals.csv, best genome and checkpoint; an
# experiment (its runs in lockstep) at 1, 2 and 3 ranks gives the same results.csv and run tables;
# a rank killed mid-run (rank 0, and rank 1) ends the job with amorph's one line, no hang, and the
# run resumes under MPI or on one machine to the uninterrupted result; mpirun killed with SIGKILL
# while the job is held leaves no process and no lock behind, and the run resumes; an interruption
# (SIGINT on rank 1) is agreed by every rank: exit 130 after the generation, one message; bad input
# gives one line once, not once per rank, also when rank 0 is the last to end. Every run is bounded by `timeout`, so a hang fails.
# Run from the repository root.
. tests/shlib.sh

if [ -z "${MPI_BUILD:-}" ] || ! [ -f "$MPI_BUILD/amorph" ]; then
    echo "cli_mpi: MPI_BUILD not set or not built: MPI tests skipped"
    summary cli_mpi
    exit $?
fi
if ! command -v mpirun >/dev/null 2>&1; then
    echo "cli_mpi: mpirun not found: MPI tests skipped"
    summary cli_mpi
    exit $?
fi
MPX="$MPI_BUILD/amorph"
# Open MPI refuses root without these (CI runs as root); copy-in/out shared memory, so that a
# container without ptrace's cross-memory attach works
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
# M NP ARGS...: the MPI build on NP ranks (mpirun quiet: amorph's own lines only), at most 300 s
M() {
    np=$1; shift
    timeout 300 mpirun -q --oversubscribe -np "$np" "$@"
}
RUN="--workspace 8 --population 8 --evaluations 48 --quiet --no-pictures"
# same DIR REF: DIR's results equal REF's: log.csv without wall time, evals.csv, best genome, and
# the checkpoint but for its last line (the last generation's wall time), checksum and threads (which never change results)
same() {
    [ "$(nowall "$1/log.csv")" = "$(nowall "$2/log.csv")" ] && cmp -s "$1/evals.csv" "$2/evals.csv" &&
        cmp -s "$1/best.genome" "$2/best.genome" &&
        [ "$(grep -v '^last \|^checksum \|^threads = ' "$1/checkpoint.txt")" = "$(grep -v '^last \|^checksum \|^threads = ' "$2/checkpoint.txt")" ]
}

# --- the reference: one process, one thread ---
expect_ok "$AMORPH" evolve $RUN --threads 1 --out "$TMPD/ref"
ref=$(sumval "$TMPD/ref" run_hash)
check "reference run hash" [ -n "$ref" ]

# --- evolve at 1, 2 and 3 ranks of one thread, 2 ranks of 2 threads, and 3 ranks dealt the
# items in a fixed snake order instead of taking them from the shared counter ---
for np in 1 2 3 2x2 3static; do
    n=${np%x*} n=${n%static} th=1 deal=dynamic
    [ "$np" = 2x2 ] && th=2
    [ "$np" = 3static ] && deal=static
    M "$n" -x AMORPH_MPI_DEAL=$deal "$MPX" evolve $RUN --threads $th --out "$TMPD/r$np" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
    h=$(sumval "$TMPD/r$np" run_hash)
    if [ $rc -eq 0 ] && [ "$h" = "$ref" ]; then ok
    else ko "evolve on $np ranks: exit $rc, run hash '$h' (one thread: $ref), stderr: $(head -c 200 "$TMPD/err")"; fi
    check "evolve on $np ranks: log, evals.csv, best genome or checkpoint differ from one thread's" same "$TMPD/r$np" "$TMPD/ref"
    check "evolve on $np ranks: the summary printed $(grep -c run_hash "$TMPD/out") times (want once, by rank 0)" \
        [ "$(grep -c '^run_hash' "$TMPD/out")" -eq 1 ]
done

# --- an experiment: its 6 runs in lockstep, at 1, 2 and 3 ranks ---
EXP="representations --workspace 8 --population 6 --evals 18 --runs 2 --quiet --no-pictures --threads 1"
expect_ok "$AMORPH" experiment $EXP --out "$TMPD/eref"
for np in 1 2 3; do
    M $np "$MPX" experiment $EXP --out "$TMPD/e$np" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
    check "experiment on $np ranks: exit $rc, stderr: $(head -c 200 "$TMPD/err")" [ $rc -eq 0 ]
    check "experiment on $np ranks: results.csv differs from one thread's" cmp -s "$TMPD/e$np/results.csv" "$TMPD/eref/results.csv"
    for r in dct-1 cppn-2 gmx-1; do
        check "experiment on $np ranks: $r differs from one thread's" same "$TMPD/e$np/$r" "$TMPD/eref/$r"
    done
done

# --- a rank killed mid-run: the job ends with one line of amorph's, then resumes ---
# rank 0 (the one that writes) killed as it is about to start its 20th evaluation of the run,
# counted over its own share (AMORPH_TEST_RANK names the rank, docs/cluster.md)
M 3 -x AMORPH_TEST_INTERRUPT=KILL:20 "$MPX" evolve $RUN --threads 1 --out "$TMPD/k0" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -ne 0 ] && [ $rc -ne 124 ]; then ok; else ko "rank 0 killed: exit $rc (want non-zero, not 124: a hang)"; fi
if [ "$(wc -l <"$TMPD/k0/log.csv")" -ge 2 ] && [ "$(wc -l <"$TMPD/k0/log.csv")" -lt 7 ]; then ok
else ko "rank 0 killed: the run's log has $(nowall "$TMPD/k0/log.csv" | wc -l) lines, want 2 to 6 (stopped mid-run)"; fi
M 2 "$MPX" evolve --resume "$TMPD/k0" --threads 1 --quiet --no-pictures >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 0 ] && [ "$(sumval "$TMPD/k0" run_hash)" = "$ref" ]; then ok
else ko "rank 0 killed, resumed on 2 ranks: exit $rc, hash '$(sumval "$TMPD/k0" run_hash)' (want $ref)"; fi
check "rank 0 killed, resumed: results differ from the uninterrupted run's" same "$TMPD/k0" "$TMPD/ref"
# rank 1 killed: rank 0, waiting for it, is stopped by mpirun and says so in one line
M 3 -x AMORPH_TEST_RANK=1 -x AMORPH_TEST_INTERRUPT=KILL:10 "$MPX" evolve $RUN --threads 1 --out "$TMPD/k1" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -ne 0 ] && [ $rc -ne 124 ]; then ok; else ko "rank 1 killed: exit $rc (want non-zero, not 124: a hang)"; fi
if sh -c "[ \$(wc -l <'$TMPD/err') -eq 1 ] && grep -q 'mpirun is stopping the job' '$TMPD/err'"; then ok
else ko "rank 1 killed: stderr should be amorph's one line: $(head -c 300 "$TMPD/err")"; fi
expect_ok "$AMORPH" evolve --resume "$TMPD/k1" --threads 2 --quiet --no-pictures
check "rank 1 killed, resumed on one machine: hash '$(sumval "$TMPD/k1" run_hash)' (want $ref)" [ "$(sumval "$TMPD/k1" run_hash)" = "$ref" ]
check "rank 1 killed, resumed: results differ from the uninterrupted run's" same "$TMPD/k1" "$TMPD/ref"

# --- mpirun killed with SIGKILL: the job held (rank 0 stops itself at its 14th evaluation), then
# kill -9 of mpirun; no rank may survive it, the folder's lock must be free, and the run resumes ---
timeout 300 mpirun -q --oversubscribe -np 3 -x AMORPH_TEST_INTERRUPT=STOP:14 "$MPX" evolve $RUN --threads 1 --out "$TMPD/sk" \
    >"$TMPD/sk.out" 2>"$TMPD/sk.err" &
mp=$!
# wait (at most 120 s) until a rank of this job is stopped: the hold, at a counted evaluation
held=0
for i in $(seq 1 1200); do
    if ps -o stat= -p "$(pgrep -d, -f "$TMPD/sk" || echo 1)" 2>/dev/null | grep -q '^T'; then held=1; break; fi
    sleep 0.1
done
check "mpirun kill: the job was not held at its counted evaluation" [ $held -eq 1 ]
mpid=$(pgrep -x mpirun -P $mp 2>/dev/null || pgrep -f "mpirun -q --oversubscribe -np 3 -x AMORPH_TEST_INTERRUPT=STOP:14" | head -n 1)
kill -9 "$mpid" 2>/dev/null
wait $mp 2>/dev/null
gone=0
for i in $(seq 1 300); do
    if ! pgrep -f "$TMPD/sk" >/dev/null; then gone=1; break; fi
    sleep 0.1
done
check "mpirun kill: ranks survived mpirun's SIGKILL: $(pgrep -af "$TMPD/sk" | head -c 200)" [ $gone -eq 1 ]
[ $gone -eq 1 ] || pkill -9 -f "$TMPD/sk"
expect_ok "$AMORPH" evolve --resume "$TMPD/sk" --threads 1 --quiet --no-pictures
check "mpirun kill, resumed: hash '$(sumval "$TMPD/sk" run_hash)' (want $ref)" [ "$(sumval "$TMPD/sk" run_hash)" = "$ref" ]

# --- an interruption on one rank is agreed by all: the generation ends, every rank stops ---
M 3 -x AMORPH_TEST_RANK=1 -x AMORPH_TEST_INTERRUPT=INT:5 "$MPX" evolve $RUN --threads 1 --out "$TMPD/int" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 130 ] && [ "$(grep -c 'interrupted after' "$TMPD/err")" -eq 1 ]; then ok
else ko "SIGINT on rank 1: exit $rc (want 130), stderr: $(head -c 300 "$TMPD/err")"; fi
M 2 "$MPX" evolve --resume "$TMPD/int" --threads 1 --quiet --no-pictures >"$TMPD/out" 2>&1
check "SIGINT on rank 1, resumed on 2 ranks: hash '$(sumval "$TMPD/int" run_hash)' (want $ref)" [ "$(sumval "$TMPD/int" run_hash)" = "$ref" ]

# --- bad input: one line, once ---
M 3 "$MPX" evolve --population 7 --out "$TMPD/bad" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 2 ] && [ "$(wc -l <"$TMPD/err")" -eq 1 ] && grep -q population "$TMPD/err"; then ok
else ko "bad population under MPI: exit $rc (want 2), stderr (want one line): $(head -c 300 "$TMPD/err")"; fi
M 2 "$MPX" evolve --resume "$TMPD/nothing-here" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 2 ] && [ "$(wc -l <"$TMPD/err")" -eq 1 ]; then ok
else ko "resume of a missing folder under MPI: exit $rc (want 2), stderr (want one line): $(head -c 300 "$TMPD/err")"; fi
# the same with rank 0 slow to end after MPI_Finalize (AMORPH_TEST_END_PAUSE): rank 1 ends first with
# status 2 and mpirun sends rank 0 SIGTERM, which must not add a line (the job ends as it was ending)
AMORPH_TEST_END_PAUSE=2 M 2 "$MPX" evolve --resume "$TMPD/nothing-here" >"$TMPD/out" 2>"$TMPD/err"; rc=$?
if [ $rc -eq 2 ] && [ "$(wc -l <"$TMPD/err")" -eq 1 ] && grep -q "cannot open" "$TMPD/err"; then ok
else ko "resume of a missing folder under MPI, rank 0 slow to end: exit $rc (want 2), stderr (want one line): $(head -c 300 "$TMPD/err")"; fi

summary cli_mpi
