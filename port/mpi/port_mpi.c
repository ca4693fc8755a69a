/* MPI port (make PORT=mpi; run under mpirun): one program as N processes that act as one.
 *
 * Every rank runs the same program on the same inputs, and the port makes sure the inputs are the
 * same: rank 0 alone touches the outside world (clock, console, files, folder lock, environment,
 * terminal, interruptions) and every call made on the main thread outside a parallel map is
 * collective: rank 0 does the work (with the POSIX port's functions, port/posix/posix.h) and
 * broadcasts what the program sees (a status, a message, the bytes read, the time, a flag). The ranks therefore take
 * the same branches and reach the same calls in the same order, and the only thing a rank does on
 * its own is its share of each parallel map: each rank's main thread takes the next items (one per
 * thread) from a counter in rank 0's memory (MPI_Fetch_and_op, one-sided: rank 0 is not asked), runs
 * them on its own threads (the POSIX map: hybrid MPI + threads) and takes more until none is left,
 * so a rank busy with a large body takes fewer; then the items' result bytes (the map's out), each
 * with its index, are gathered to every rank with one MPI_Allgatherv. Without one-sided operations
 * (or with AMORPH_MPI_DEAL=static) the items are dealt in a fixed snake order instead (the largest
 * bodies, first in the caller's order, spread evenly). Which rank evaluates an item never changes
 * its result. Nothing else travels: every rank makes
 * the same offspring from the same random stream, so no genome is ever sent.
 *
 * Results (run hash, log.csv, checkpoints, best genome) equal those of one process with any number
 * of threads, for any number of ranks. Only rank 0 writes files and prints; the other ranks' standard
 * streams go to /dev/null (a rank's own MPI failure is still reported on its stderr).
 *
 * Interruptions are agreed: a signal sets a rank's own flag, and am_port_interrupted (on the main
 * thread, outside a map) returns the OR over the ranks, reduced there. Inside a map the agreed value
 * of the last reduction is used, so cancel callbacks decide alike everywhere; an interruption that
 * arrives during a map is therefore seen when the map has ended (under mpirun, a Ctrl-C or SIGTERM
 * reaches every rank; mpirun kills the job a few seconds later in any case, and the run resumes
 * from its last checkpoint). A rank that dies makes mpirun end the job (it notices the lost process);
 * an MPI call that fails ends the job with MPI_Abort after a one-line message.
 *
 * AMORPH_MPI_STATS=1 (each rank's own environment) makes rank 0 print, at the end, one line of what
 * the transport cost: maps, items, collectives, their seconds and bytes (docs/cluster.md).
 *
 * Test hooks: AMORPH_TEST_RANK=r (read by every rank from its own environment; default 0) names the
 * one rank on which am_port_raise acts, so a test's AMORPH_TEST_INTERRUPT stops or kills that rank;
 * AMORPH_TEST_END_PAUSE=s makes rank 0 wait s seconds after MPI_Finalize (am_port_end). */
#define _POSIX_C_SOURCE 200809L
#include "../posix/posix.h"

#include "amorph/base.h"

#include <mpi.h>
#include <pthread.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <time.h>
#include <unistd.h>

/* the bytes of one map's results a rank sends and receives (am_evo_result is under 400 bytes: an
 * experiment's 16 runs of 256 offspring fit) */
#define MPI_MAP_BYTES (4L << 20)
#define MPI_MAP_ITEMS 8192       /* items of one map */
#define MPI_ENV_NAMES 8          /* environment variables am_port_getenv keeps */
#define MPI_ENV_MAX 1024         /* the longest value kept */

static int on;                   /* 1 after MPI_Init: collectives apply */
static int rank, ranks;
static pthread_t main_thread;
static volatile int in_map;      /* the main thread runs map items: no collective */
static volatile int agreed;      /* the interruption flag agreed at the last reduction */
static int raise_rank;           /* AMORPH_TEST_RANK */
static int node_ranks = 1;       /* ranks on this rank's machine */
static volatile sig_atomic_t g_told; /* rank 0 has said mpirun is stopping the job (or falls silent: am_port_end) */
static int err_fd = 2;           /* this rank's own stderr (rank > 0: kept before /dev/null) */

/* the dynamic deal's counter: the next item of the map under way, a long in rank 0's window that
 * every rank's main thread advances with MPI_Fetch_and_op (passive target: rank 0 does nothing) */
static long* g_win_mem;          /* the counter (rank 0's window memory, allocated by MPI) */
static MPI_Win g_win;
static int g_dynamic;            /* 1: the counter works (else the snake deal) */

/* what the transport cost (AMORPH_MPI_STATS=1: one line from rank 0 at the end) */
static struct {
    int on;
    long collectives, maps, items;
    double bytes, seconds, map_seconds;
} g_stats;

/* the time an MPI call took, counted */
static double stat_t0(void)
{
    return g_stats.on ? MPI_Wtime() : 0.0;
}

static void stat_add(double t0, long bytes)
{
    if (!g_stats.on) return;
    g_stats.collectives++;
    g_stats.bytes += (double)bytes;
    g_stats.seconds += MPI_Wtime() - t0;
}

/* ---- collectives ---- */

/* 1 when a call must be collective: MPI is on, on the main thread, outside a map */
static int collective(void)
{
    return on && !in_map && pthread_equal(pthread_self(), main_thread);
}

/* one line on this rank's own stderr, then the job ends (an MPI call failed: the ranks may no
 * longer agree, so nothing else is safe) */
static void fatal(const char* what, int code)
{
    char msg[MPI_MAX_ERROR_STRING], line[MPI_MAX_ERROR_STRING + 160];
    int len = 0;
    msg[0] = 0;
    MPI_Error_string(code, msg, &len);
    int n = snprintf(line, sizeof line, "amorph: rank %d of %d: %s failed: %s; the job ends (resume the run from its last checkpoint)\n",
                     rank, ranks, what, msg);
    if (n > 0) (void)!write(err_fd, line, (size_t)(n < (int)sizeof line ? n : (int)sizeof line - 1));
    MPI_Abort(MPI_COMM_WORLD, 1);
    _exit(1);
}

/* rank 0's n bytes at p on every rank */
static void bcast(void* p, long n)
{
    char* c = (char*)p;
    while (n > 0) {
        int k = n > (1L << 30) ? 1 << 30 : (int)n;
        double t0 = stat_t0();
        int rc = MPI_Bcast(c, k, MPI_BYTE, 0, MPI_COMM_WORLD);
        if (rc != MPI_SUCCESS) fatal("MPI_Bcast", rc);
        stat_add(t0, k);
        c += k;
        n -= k;
    }
}

/* rank 0's status (and its message when it failed) on every rank */
static am_status bcast_status(am_status st, char* err, int errsz)
{
    int v = (int)st;
    bcast(&v, sizeof v);
    if (v != AM_OK && err && errsz > 0) bcast(err, errsz);
    return (am_status)v;
}

/* ---- the program ---- */

void am_port_start(int* argc, char*** argv)
{
    int provided = 0;
    int rc = MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    if (rc != MPI_SUCCESS) {
        fprintf(stderr, "amorph: MPI_Init_thread failed (error %d): run under mpirun, or use the POSIX build\n", rc);
        exit(1);
    }
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    main_thread = pthread_self();
    on = 1;
    /* ranks sharing this machine share its cores (am_port_cores) */
    MPI_Comm node;
    if (MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node) == MPI_SUCCESS) {
        MPI_Comm_size(node, &node_ranks);
        MPI_Comm_free(&node);
    }
    const char* r = getenv("AMORPH_TEST_RANK");
    raise_rank = r ? atoi(r) : 0;
    r = getenv("AMORPH_MPI_STATS");
    g_stats.on = r && !strcmp(r, "1");
    /* the deal: dynamic (a shared counter) unless rank 0's AMORPH_MPI_DEAL says static, or the MPI
     * library has no one-sided operations here; every rank must agree */
    int want = 1;
    if (rank == 0) {
        r = getenv("AMORPH_MPI_DEAL");
        want = !(r && !strcmp(r, "static"));
    }
    MPI_Bcast(&want, 1, MPI_INT, 0, MPI_COMM_WORLD);
    int made = 0;
    /* the window's memory is MPI's own (MPI_Win_allocate), so that on one machine the library can
     * place it in shared memory, where the counter is a hardware atomic that needs nothing of
     * rank 0 (a window over this program's memory is served by rank 0's MPI calls: a rank would
     * wait for rank 0 to finish an evaluation) */
    if (want && MPI_Win_allocate(rank == 0 ? (MPI_Aint)sizeof(long) : 0, (int)sizeof(long), MPI_INFO_NULL, MPI_COMM_WORLD, &g_win_mem,
                                 &g_win) == MPI_SUCCESS) {
        made = MPI_Win_lock_all(0, g_win) == MPI_SUCCESS;
    }
    MPI_Allreduce(&made, &g_dynamic, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (rank > 0) {
        /* the console is rank 0's: the others' output (the same as rank 0's) goes nowhere */
        fflush(stdout);
        fflush(stderr);
        err_fd = dup(2);
        int null = open("/dev/null", O_WRONLY);
        if (null >= 0) {
            dup2(null, 1);
            dup2(null, 2);
            close(null);
        }
    }
}

int am_port_end(int status)
{
    if (!on) return status;
    fflush(stdout);
    fflush(stderr);
    /* the job ends with the status every rank has: mpirun's SIGTERM, which follows a rank's
     * non-zero exit while rank 0 is still ending, says nothing new. Rank 0 falls silent first, and
     * the barrier keeps every other rank from ending before it has (MPI_Finalize need not wait). */
    if (rank == 0) g_told = 1;
    MPI_Barrier(MPI_COMM_WORLD);
    if (g_stats.on && rank == 0) {
        char line[400];
        int n = snprintf(line, sizeof line,
                         "amorph: mpi: ranks=%d maps=%ld items=%ld map_s=%.6f collectives=%ld collective_s=%.6f bytes=%.0f "
                         "us_per_collective=%.2f\n",
                         ranks, g_stats.maps, g_stats.items, g_stats.map_seconds, g_stats.collectives, g_stats.seconds, g_stats.bytes,
                         g_stats.collectives ? g_stats.seconds / (double)g_stats.collectives * 1e6 : 0.0);
        if (n > 0) (void)!write(err_fd, line, (size_t)(n < (int)sizeof line ? n : (int)sizeof line - 1));
    }
    if (g_dynamic) {
        MPI_Win_unlock_all(g_win);
        MPI_Win_free(&g_win);
    }
    /* every rank arrives here with the same status (same program, same inputs) */
    MPI_Finalize();
    on = 0;
    /* test hook: rank 0 is slow to end after MPI_Finalize, so that the other ranks end first */
    const char* p = rank == 0 ? getenv("AMORPH_TEST_END_PAUSE") : NULL;
    if (p) {
        struct timespec ts = {atoi(p), 0};
        while (nanosleep(&ts, &ts) != 0) {}
    }
    return status;
}

/* ---- clock ---- */

double am_port_now(void)
{
    double t = am_posix_now();
    if (collective()) bcast(&t, sizeof t);
    return t;
}

/* ---- console ---- */

void am_port_out(const char* text)
{
    if (rank == 0) am_posix_out(text);
}

void am_port_err(const char* text)
{
    if (rank == 0) am_posix_err(text);
}

int am_port_is_terminal(void)
{
    int v = rank == 0 ? am_posix_is_terminal() : 0;
    if (collective()) bcast(&v, sizeof v);
    return v;
}

void am_port_progress(const char* line)
{
    if (rank == 0) am_posix_progress(line);
}

/* ---- files: rank 0's, its results broadcast ---- */

am_status am_port_read_file(const char* path, char* buf, long cap, long* len, char* err, int errsz)
{
    if (!collective()) return am_posix_read_file(path, buf, cap, len, err, errsz);
    am_status st = AM_OK;
    long n = 0;
    if (rank == 0) st = am_posix_read_file(path, buf, cap, &n, err, errsz);
    st = bcast_status(st, err, errsz);
    if (st != AM_OK) return st;
    bcast(&n, sizeof n);
    bcast(buf, n + 1); /* with its NUL */
    *len = n;
    return AM_OK;
}

am_status am_port_append_file(const char* path, const void* data, long n, char* err, int errsz)
{
    if (!collective()) return am_posix_append_file(path, data, n, err, errsz);
    am_status st = rank == 0 ? am_posix_append_file(path, data, n, err, errsz) : AM_OK;
    return bcast_status(st, err, errsz);
}

am_status am_port_sync_file(const char* path, char* err, int errsz)
{
    if (!collective()) return am_posix_sync_file(path, err, errsz);
    am_status st = rank == 0 ? am_posix_sync_file(path, err, errsz) : AM_OK;
    return bcast_status(st, err, errsz);
}

am_status am_port_open_write(const char* path, am_port_stream* s, char* err, int errsz)
{
    if (!collective()) return am_posix_open_write(path, s, err, errsz);
    am_status st = rank == 0 ? am_posix_open_write(path, s, err, errsz) : AM_OK;
    st = bcast_status(st, err, errsz);
    if (st == AM_OK) bcast(s, sizeof *s);
    return st;
}

am_status am_port_write(am_port_stream s, const void* data, long n, char* err, int errsz)
{
    if (!collective()) return am_posix_write(s, data, n, err, errsz);
    am_status st = rank == 0 ? am_posix_write(s, data, n, err, errsz) : AM_OK;
    return bcast_status(st, err, errsz);
}

am_status am_port_open_read(const char* path, am_port_stream* s, char* err, int errsz)
{
    if (!collective()) return am_posix_open_read(path, s, err, errsz);
    am_status st = rank == 0 ? am_posix_open_read(path, s, err, errsz) : AM_OK;
    st = bcast_status(st, err, errsz);
    if (st == AM_OK) bcast(s, sizeof *s);
    return st;
}

am_status am_port_read(am_port_stream s, void* buf, long cap, long* got, char* err, int errsz)
{
    if (!collective()) return am_posix_read(s, buf, cap, got, err, errsz);
    long n = 0;
    am_status st = rank == 0 ? am_posix_read(s, buf, cap, &n, err, errsz) : AM_OK;
    st = bcast_status(st, err, errsz);
    if (st != AM_OK) return st;
    bcast(&n, sizeof n);
    bcast(buf, n);
    *got = n;
    return AM_OK;
}

am_status am_port_close(am_port_stream s, int commit, char* err, int errsz)
{
    if (!collective()) return am_posix_close(s, commit, err, errsz);
    am_status st = rank == 0 ? am_posix_close(s, commit, err, errsz) : AM_OK;
    return bcast_status(st, err, errsz);
}

am_status am_port_make_dir(const char* path, char* err, int errsz)
{
    if (!collective()) return am_posix_make_dir(path, err, errsz);
    am_status st = rank == 0 ? am_posix_make_dir(path, err, errsz) : AM_OK;
    return bcast_status(st, err, errsz);
}

int am_port_exists(const char* path)
{
    int v = rank == 0 || !collective() ? am_posix_exists(path) : 0;
    if (collective()) bcast(&v, sizeof v);
    return v;
}

am_status am_port_remove_stale(const char* dir, int* removed, char* err, int errsz)
{
    if (!collective()) return am_posix_remove_stale(dir, removed, err, errsz);
    int n = 0;
    am_status st = rank == 0 ? am_posix_remove_stale(dir, &n, err, errsz) : AM_OK;
    st = bcast_status(st, err, errsz);
    bcast(&n, sizeof n);
    if (removed) *removed = n;
    return st;
}

am_status am_port_list_dir(const char* dir, char* names, long cap, int* count, char* err, int errsz)
{
    if (!collective()) return am_posix_list_dir(dir, names, cap, count, err, errsz);
    int n = 0;
    am_status st = rank == 0 ? am_posix_list_dir(dir, names, cap, &n, err, errsz) : AM_OK;
    st = bcast_status(st, err, errsz);
    bcast(&n, sizeof n);
    *count = n;
    if (st != AM_OK) return st;
    long len = 0;
    if (rank == 0)
        for (int k = 0; k < n; k++) len += (long)strlen(names + len) + 1;
    bcast(&len, sizeof len);
    bcast(names, len);
    return AM_OK;
}

/* ---- owning a folder: rank 0 holds the locks ---- */

am_status am_port_lock(const char* path, char* err, int errsz)
{
    if (!collective()) return am_posix_lock(path, err, errsz);
    am_status st = rank == 0 ? am_posix_lock(path, err, errsz) : AM_OK;
    return bcast_status(st, err, errsz);
}

void am_port_lock_stamp(void)
{
    if (rank == 0) am_posix_lock_stamp();
}

void am_port_unlock(void)
{
    if (rank == 0) am_posix_unlock();
}

/* ---- parallel map: items dealt over the ranks, results gathered to all ---- */

/* the rank that runs item i of n: snake order (0 1 2 2 1 0 0 1 2 ...), so each rank's share of the
 * caller's order (the largest bodies first) is as even as a fixed deal can make it */
static int owner(int i)
{
    int round = i / ranks, k = i % ranks;
    return round % 2 ? ranks - 1 - k : k;
}

typedef struct local_job {
    am_port_task task;
    void* ctx;
    const int* items;            /* this rank's items, in the caller's order */
} local_job;

static void local_task(void* ctx, int k, int worker)
{
    local_job* j = (local_job*)ctx;
    j->task(j->ctx, j->items[k], worker);
}

static int g_items[MPI_MAP_ITEMS];   /* this rank's items of the map under way, in their order */
static char g_send[MPI_MAP_BYTES], g_recv[MPI_MAP_BYTES];
static int g_counts[1024], g_displs[1024];

/* waits for req without spinning: a rank done with its share may wait for seconds on one with a
 * large body, and MPI's busy polling would take a core (or a hyperthread's sibling) from it */
static void wait_asleep(MPI_Request* req, const char* what)
{
    for (;;) {
        int done = 0;
        int rc = MPI_Test(req, &done, MPI_STATUS_IGNORE);
        if (rc != MPI_SUCCESS) fatal(what, rc);
        if (done) return;
        struct timespec ts = {0, 200000}; /* 0.2 ms: nothing against an evaluation's 0.1 to 10 s */
        nanosleep(&ts, NULL);
    }
}

/* the next `count` items for this rank: the first index (n or more when none is left) */
static long fetch_items(long count)
{
    long first = 0;
    double t0 = stat_t0();
    int rc = MPI_Fetch_and_op(&count, &first, MPI_LONG, 0, 0, MPI_SUM, g_win);
    if (rc == MPI_SUCCESS) rc = MPI_Win_flush(0, g_win);
    if (rc != MPI_SUCCESS) fatal("MPI_Fetch_and_op", rc);
    stat_add(t0, sizeof count);
    return first;
}

am_status am_port_parallel_map(int n, int workers, am_port_task task, void* ctx, void* out, long size, char* err, int errsz)
{
    if (!collective() || ranks == 1) return am_posix_parallel_map(n, workers, task, ctx, out, size, err, errsz);
    if (workers < 1 || n < 0 || size < 0 || !task) return am_fail(err, errsz, AM_ERR_ARG, "parallel map: %d items on %d workers", n, workers);
    if (ranks > (int)(sizeof g_counts / sizeof g_counts[0]))
        return am_fail(err, errsz, AM_ERR_CAPACITY, "parallel map: %d ranks, at most %d", ranks, (int)(sizeof g_counts / sizeof g_counts[0]));
    const long rec = (long)sizeof(int) + size; /* a result on the way: its item, then its bytes */
    if (n > MPI_MAP_ITEMS || (long)n * rec > MPI_MAP_BYTES || !out)
        return am_fail(err, errsz, AM_ERR_CAPACITY, "parallel map: %d items of %ld bytes: at most %d items and %ld bytes across ranks",
                       n, size, MPI_MAP_ITEMS, MPI_MAP_BYTES);
    const double map_t0 = stat_t0();
    int mine = 0, rc;
    am_status st = AM_OK;
    local_job job = {task, ctx, g_items};
    if (g_dynamic) {
        /* dynamic deal: rank 0 resets the counter, then every rank takes `workers` items at a time
         * (one per thread) until none is left: a rank with a large body takes fewer */
        if (rank == 0) {
            long zero = 0, old = 0;
            rc = MPI_Fetch_and_op(&zero, &old, MPI_LONG, 0, 0, MPI_REPLACE, g_win);
            if (rc == MPI_SUCCESS) rc = MPI_Win_flush(0, g_win);
            if (rc != MPI_SUCCESS) fatal("MPI_Fetch_and_op", rc);
        }
        rc = MPI_Barrier(MPI_COMM_WORLD);
        if (rc != MPI_SUCCESS) fatal("MPI_Barrier", rc);
        for (;;) {
            long first = fetch_items(workers);
            if (first >= n) break;
            int got = (int)(n - first < workers ? n - first : workers);
            for (int k = 0; k < got; k++) g_items[mine + k] = (int)first + k;
            job.items = g_items + mine;
            in_map = 1;
            am_status s1 = am_posix_parallel_map(got, workers, local_task, &job, NULL, 0, err, errsz);
            in_map = 0;
            if (s1 != AM_OK) st = s1;
            mine += got;
        }
    } else {
        /* snake deal: a fixed share */
        for (int i = 0; i < n; i++)
            if (owner(i) == rank) g_items[mine++] = i;
        in_map = 1;
        st = am_posix_parallel_map(mine, workers, local_task, &job, NULL, 0, err, errsz);
        in_map = 0;
    }
    /* each rank's count and status (a rank that could not start its threads still ran its items
     * on this thread: a warning every rank gives alike) */
    int me[2] = {mine, st != AM_OK}, all[2 * 1024];
    double t0 = stat_t0();
    MPI_Request req;
    rc = MPI_Iallgather(me, 2, MPI_INT, all, 2, MPI_INT, MPI_COMM_WORLD, &req);
    if (rc != MPI_SUCCESS) fatal("MPI_Iallgather", rc);
    wait_asleep(&req, "MPI_Iallgather");
    stat_add(t0, sizeof me);
    /* the results: each rank's records (item, bytes) gathered to all, put in place */
    char* o = (char*)out;
    for (int k = 0; k < mine; k++) {
        memcpy(g_send + k * rec, &g_items[k], sizeof(int));
        memcpy(g_send + k * rec + sizeof(int), o + (long)g_items[k] * size, (size_t)size);
    }
    int at = 0, any_bad = 0, total = 0;
    for (int r = 0; r < ranks; r++) {
        g_counts[r] = all[2 * r] * (int)rec;
        g_displs[r] = at;
        at += g_counts[r];
        total += all[2 * r];
        any_bad |= all[2 * r + 1];
    }
    if (total != n) fatal("the parallel map (items lost)", MPI_ERR_OTHER);
    t0 = stat_t0();
    rc = MPI_Allgatherv(g_send, mine * (int)rec, MPI_BYTE, g_recv, g_counts, g_displs, MPI_BYTE, MPI_COMM_WORLD);
    if (rc != MPI_SUCCESS) fatal("MPI_Allgatherv", rc);
    stat_add(t0, (long)n * rec);
    for (int k = 0; k < n; k++) {
        int i;
        memcpy(&i, g_recv + k * rec, sizeof i);
        if (i < 0 || i >= n) fatal("the parallel map (an item out of range)", MPI_ERR_OTHER);
        memcpy(o + (long)i * size, g_recv + k * rec + sizeof(int), (size_t)size);
    }
    if (g_stats.on) {
        g_stats.maps++;
        g_stats.items += n;
        g_stats.map_seconds += MPI_Wtime() - map_t0;
    }
    if (any_bad && st == AM_OK) return am_fail(err, errsz, AM_ERR_IO, "parallel map: a rank could not start its threads");
    return st;
}

int am_port_processes(void)
{
    return on ? ranks : 1;
}

int am_port_cores(void)
{
    int c = am_posix_cores();
    if (!on) return c;
    c /= node_ranks; /* the ranks on this machine share its cores */
    return c < 1 ? 1 : c;
}

/* ---- interruption: each rank's flag, agreed by a reduction ---- */

static struct sigaction g_old_int, g_old_term;

/* rank 0's handler of SIGINT and SIGTERM under MPI: the POSIX port's (a flag; the second request
 * ends the process), after one line the first time. Under mpirun these signals are mpirun's: it
 * sends SIGTERM to every rank when a rank has died or mpirun itself was interrupted, and SIGKILL a
 * few seconds later; a rank waiting for a dead one would end silently. */
static void on_stop(int sig)
{
    static const char line[] = "amorph: mpirun is stopping the job (a rank ended, or the job was interrupted); the run folder's last "
                               "checkpoint stands: resume with --resume, under mpirun or on one machine\n";
    if (!g_told) {
        g_told = 1;
        (void)!write(err_fd, line, sizeof line - 1);
    }
    const struct sigaction* old = sig == SIGINT ? &g_old_int : &g_old_term;
    if (old->sa_handler != SIG_DFL && old->sa_handler != SIG_IGN) old->sa_handler(sig);
}

void am_port_catch_interrupt(void)
{
    am_posix_catch_interrupt();
    if (!on || rank != 0) return;
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    sigaction(SIGINT, &sa, &g_old_int);
    sigaction(SIGTERM, &sa, &g_old_term);
}

int am_port_interrupted(void)
{
    if (!on) return am_posix_interrupted();
    if (collective()) {
        int mine = am_posix_interrupted(), all = 0;
        double t0 = stat_t0();
        int rc = MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
        if (rc != MPI_SUCCESS) fatal("MPI_Allreduce", rc);
        stat_add(t0, sizeof mine);
        agreed = all;
    }
    return agreed;
}

/* ---- testing interruptions ---- */

const char* am_port_getenv(const char* name)
{
    if (!collective()) return am_posix_getenv(name);
    /* rank 0's value, kept per name (at most MPI_ENV_NAMES names; a value is cut to MPI_ENV_MAX - 1) */
    static char names[MPI_ENV_NAMES][64], values[MPI_ENV_NAMES][MPI_ENV_MAX];
    static int used;
    int k = 0;
    while (k < used && strcmp(names[k], name) != 0) k++;
    if (k == used) k = used < MPI_ENV_NAMES ? used++ : MPI_ENV_NAMES - 1;
    snprintf(names[k], sizeof names[k], "%s", name);
    int set = 0;
    if (rank == 0) {
        const char* v = am_posix_getenv(name);
        set = v != NULL;
        snprintf(values[k], sizeof values[k], "%s", v ? v : "");
    }
    bcast(&set, sizeof set);
    bcast(values[k], sizeof values[k]);
    return set ? values[k] : NULL;
}

void am_port_raise(am_port_signal sig)
{
    if (!on || rank == raise_rank) am_posix_raise(sig);
}
