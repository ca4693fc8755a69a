/* Tests of the POSIX port (port/posix): the parallel map hands every item out exactly once on
 * 1, 2, 3 and 8 workers, with worker ids in range and never two calls at once for one worker id;
 * files are replaced atomically, appended to, and directories made and found; the progress line
 * is silent when stderr is not a terminal; the stale temporaries of atomic writes are removed from
 * a folder, and nothing else; no file is written through a link planted where amorph writes (a
 * temporary's predictable name, an appended table, a lock). Scratch files go to
 * $BUILD/tests/port_scratch. */
#define _POSIX_C_SOURCE 200809L
#include "amorph.h"
#include "port.h"
#include "harness.h"

#include <fcntl.h>
#include <stdatomic.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define MAP_MAX_ITEMS 200
#define MAP_MAX_WORKERS 8

typedef struct map_probe {
    atomic_int calls[MAP_MAX_ITEMS];       /* calls per item */
    atomic_int busy[MAP_MAX_WORKERS];      /* calls running now per worker id */
    atomic_int overlaps;                   /* calls that found their worker id busy */
    atomic_int bad_worker;                 /* worker ids out of range */
    atomic_int ticket;                     /* calls so far, in start order */
    int order[MAP_MAX_ITEMS];              /* item of the k-th call (one worker only) */
    int workers;
} map_probe;

static map_probe probe;

static void probe_task(void* ctx, int item, int worker)
{
    map_probe* p = (map_probe*)ctx;
    if (worker < 0 || worker >= p->workers) {
        atomic_fetch_add(&p->bad_worker, 1);
        return;
    }
    if (atomic_fetch_add(&p->busy[worker], 1) != 0) atomic_fetch_add(&p->overlaps, 1);
    int k = atomic_fetch_add(&p->ticket, 1);
    if (k < MAP_MAX_ITEMS) p->order[k] = item;
    if (item >= 0 && item < MAP_MAX_ITEMS) atomic_fetch_add(&p->calls[item], 1);
    /* stay a little while so that other workers run at the same time */
    struct timespec ts = {0, 20000 + 1000 * (item % 7)};
    nanosleep(&ts, NULL);
    atomic_fetch_sub(&p->busy[worker], 1);
}

static void reset_probe(int workers)
{
    for (int i = 0; i < MAP_MAX_ITEMS; i++) atomic_store(&probe.calls[i], 0);
    for (int i = 0; i < MAP_MAX_WORKERS; i++) atomic_store(&probe.busy[i], 0);
    atomic_store(&probe.overlaps, 0);
    atomic_store(&probe.bad_worker, 0);
    atomic_store(&probe.ticket, 0);
    probe.workers = workers;
}

static void test_parallel_map_covers_each_item_once(void)
{
    static const int worker_counts[] = {1, 2, 3, 8};
    static const int item_counts[] = {0, 1, 2, 7, 64, MAP_MAX_ITEMS};
    char err[AM_ERR_MAX];
    size_t counts = sizeof item_counts / sizeof item_counts[0] - (test_quick() ? 1 : 0); /* valgrind: fewer */
    for (size_t w = 0; w < sizeof worker_counts / sizeof worker_counts[0]; w++)
        for (size_t c = 0; c < counts; c++) {
            int workers = worker_counts[w], n = item_counts[c];
            reset_probe(workers);
            am_status st = am_port_parallel_map(n, workers, probe_task, &probe, NULL, 0, err, sizeof err);
            CHECK(st == AM_OK, "%d items on %d workers: status %d (%s)", n, workers, (int)st, err);
            int once = 1;
            for (int i = 0; i < n; i++) once &= atomic_load(&probe.calls[i]) == 1;
            CHECK(once, "%d items on %d workers: an item was not called exactly once", n, workers);
            CHECK(atomic_load(&probe.ticket) == n, "%d items on %d workers: %d calls", n, workers, atomic_load(&probe.ticket));
            CHECK(atomic_load(&probe.bad_worker) == 0, "%d items on %d workers: worker id out of range", n, workers);
            CHECK(atomic_load(&probe.overlaps) == 0, "%d items on %d workers: two calls at once for one worker id", n, workers);
            if (workers == 1) {
                int in_order = 1;
                for (int i = 0; i < n; i++) in_order &= probe.order[i] == i;
                CHECK(in_order, "one worker: items not called in order");
            }
        }
}

static void test_parallel_map_rejects_bad_arguments(void)
{
    char err[AM_ERR_MAX];
    reset_probe(1);
    CHECK(am_port_parallel_map(3, 0, probe_task, &probe, NULL, 0, err, sizeof err) == AM_ERR_ARG, "0 workers accepted");
    CHECK(am_port_parallel_map(-1, 2, probe_task, &probe, NULL, 0, err, sizeof err) == AM_ERR_ARG, "-1 items accepted");
    CHECK(atomic_load(&probe.ticket) == 0, "a rejected map called the task");
    /* more workers than the port starts, or than items: still every item once */
    reset_probe(MAP_MAX_WORKERS);
    CHECK(am_port_parallel_map(5, 1000, probe_task, &probe, NULL, 0, err, sizeof err) == AM_OK, "1000 workers: %s", err);
    CHECK(atomic_load(&probe.ticket) == 5, "1000 workers on 5 items: %d calls", atomic_load(&probe.ticket));
    CHECK(am_port_cores() >= 1, "cores = %d", am_port_cores());
}

static char scratch[512];

/* scratch/name into out */
static const char* path_of(char* out, size_t cap, const char* name)
{
    snprintf(out, cap, "%s/%s", scratch, name);
    return out;
}

static void test_files(void)
{
    const char* build = getenv("BUILD");
    snprintf(scratch, sizeof scratch, "%s/tests/port_scratch", build && *build ? build : "build");
    char err[AM_ERR_MAX], p[600], q[700], buf[64];
    long len = -1;

    /* directories: made once, found again, a file in the way is an error */
    CHECK(am_port_make_dir(scratch, err, sizeof err) == AM_OK, "make_dir %s: %s", scratch, err);
    CHECK(am_port_make_dir(scratch, err, sizeof err) == AM_OK, "make_dir of an existing directory: %s", err);
    CHECK(am_port_exists(scratch) == 1, "the directory is not found");
    path_of(p, sizeof p, "missing");
    unlink(p);
    CHECK(am_port_exists(p) == 0, "a missing file exists");
    CHECK(am_port_read_file(p, buf, sizeof buf, &len, err, sizeof err) == AM_ERR_IO, "reading a missing file");

    /* atomic replace: the new content, and no temporary left beside it */
    path_of(p, sizeof p, "replaced.txt");
    CHECK(am_port_write_file(p, "first version\n", 14, err, sizeof err) == AM_OK, "write: %s", err);
    CHECK(am_port_write_file(p, "two\n", 4, err, sizeof err) == AM_OK, "rewrite: %s", err);
    CHECK(am_port_read_file(p, buf, sizeof buf, &len, err, sizeof err) == AM_OK && len == 4 && !strcmp(buf, "two\n"),
          "replaced file reads '%s' (%ld bytes)", buf, len);
    snprintf(q, sizeof q, "%s.tmp.%ld", p, (long)getpid());
    CHECK(am_port_exists(q) == 0, "temporary %s left behind", q);
    CHECK(am_port_make_dir(p, err, sizeof err) == AM_ERR_IO, "make_dir over a file accepted");

    /* a file larger than the buffer is a capacity error, not a truncation */
    CHECK(am_port_read_file(p, buf, 4, &len, err, sizeof err) == AM_ERR_CAPACITY, "4-byte file in a 4-byte buffer");
    CHECK(am_port_read_file(p, buf, 5, &len, err, sizeof err) == AM_OK && len == 4, "4-byte file in a 5-byte buffer");

    /* append: created when missing, then extended */
    path_of(q, sizeof q, "log.txt");
    unlink(q);
    CHECK(am_port_append_file(q, "a,1\n", 4, err, sizeof err) == AM_OK, "append to a new file: %s", err);
    CHECK(am_port_append_file(q, "b,2\n", 4, err, sizeof err) == AM_OK, "append: %s", err);
    CHECK(am_port_read_file(q, buf, sizeof buf, &len, err, sizeof err) == AM_OK && !strcmp(buf, "a,1\nb,2\n"),
          "appended file reads '%s'", buf);
    /* sync: the appended rows flushed to the storage, the file unchanged; a missing file is an
     * error (never created), and so is a folder */
    CHECK(am_port_sync_file(q, err, sizeof err) == AM_OK, "sync: %s", err);
    CHECK(am_port_read_file(q, buf, sizeof buf, &len, err, sizeof err) == AM_OK && !strcmp(buf, "a,1\nb,2\n"), "synced file reads '%s'", buf);
    path_of(q, sizeof q, "no-such-log.txt");
    err[0] = 0;
    CHECK(am_port_sync_file(q, err, sizeof err) == AM_ERR_IO && strstr(err, "no-such-log.txt") && !am_port_exists(q),
          "sync of a missing file: '%s'", err);
    path_of(q, sizeof q, "");
    err[0] = 0;
    CHECK(am_port_sync_file(q, err, sizeof err) == AM_ERR_IO && err[0], "sync of a folder accepted");

    /* writing into a missing directory fails with a message */
    path_of(q, sizeof q, "no/such/dir/file");
    err[0] = 0;
    CHECK(am_port_write_file(q, "x", 1, err, sizeof err) == AM_ERR_IO && err[0], "write into a missing directory");
}

/* streams: an atomic replace written piece by piece, a drop that leaves the old file, reading
 * piece by piece, AM_PORT_STREAMS open at once, and bad handles refused */
static void test_streams(void)
{
    char err[AM_ERR_MAX], p[600], q[700], buf[64];
    long len = -1, got = -1;
    if (!scratch[0]) return;
    path_of(p, sizeof p, "streamed.txt");
    CHECK(am_port_write_file(p, "old\n", 4, err, sizeof err) == AM_OK, "write: %s", err);
    am_port_stream w = -1, r = -1;
    CHECK(am_port_open_write(p, &w, err, sizeof err) == AM_OK && w >= 0, "open_write: %s", err);
    CHECK(am_port_write(w, "new ", 4, err, sizeof err) == AM_OK && am_port_write(w, "text\n", 5, err, sizeof err) == AM_OK,
          "write pieces: %s", err);
    /* nothing is visible at the path before the commit; reading and writing at once */
    CHECK(am_port_open_read(p, &r, err, sizeof err) == AM_OK && r >= 0 && r != w, "open_read beside a write: %s", err);
    CHECK(am_port_read(r, buf, sizeof buf, &got, err, sizeof err) == AM_OK && got == 4 && !memcmp(buf, "old\n", 4),
          "the old file during the write: %ld bytes", got);
    CHECK(am_port_close(r, 0, err, sizeof err) == AM_OK, "close read: %s", err);
    CHECK(am_port_close(w, 1, err, sizeof err) == AM_OK, "commit: %s", err);
    CHECK(am_port_read_file(p, buf, sizeof buf, &len, err, sizeof err) == AM_OK && !strcmp(buf, "new text\n"), "committed '%s'", buf);
    snprintf(q, sizeof q, "%s.tmp.%ld", p, (long)getpid());
    CHECK(am_port_exists(q) == 0, "temporary %s left after a commit", q);
    /* a dropped stream leaves the old file and no temporary */
    CHECK(am_port_open_write(p, &w, err, sizeof err) == AM_OK && am_port_write(w, "lost", 4, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_port_close(w, 0, err, sizeof err) == AM_OK, "drop: %s", err);
    CHECK(am_port_read_file(p, buf, sizeof buf, &len, err, sizeof err) == AM_OK && !strcmp(buf, "new text\n"), "after a drop '%s'", buf);
    CHECK(am_port_exists(q) == 0, "temporary %s left after a drop", q);
    /* reading in pieces of 3 bytes gives the file back, then 0 at the end */
    char all[32];
    long n = 0;
    CHECK(am_port_open_read(p, &r, err, sizeof err) == AM_OK, "%s", err);
    for (int k = 0; k < 10; k++) {
        CHECK(am_port_read(r, all + n, 3, &got, err, sizeof err) == AM_OK, "%s", err);
        if (got <= 0) break;
        n += got;
    }
    CHECK(n == 9 && !memcmp(all, "new text\n", 9) && got == 0, "read in pieces: %ld bytes", n);
    CHECK(am_port_close(r, 1, err, sizeof err) == AM_OK, "close: %s", err);
    /* the table: AM_PORT_STREAMS at once, and a closed handle is refused */
    am_port_stream many[AM_PORT_STREAMS];
    for (int k = 0; k < AM_PORT_STREAMS; k++)
        CHECK(am_port_open_read(p, &many[k], err, sizeof err) == AM_OK, "stream %d of %d: %s", k + 1, AM_PORT_STREAMS, err);
    for (int k = 0; k < AM_PORT_STREAMS; k++) am_port_close(many[k], 0, NULL, 0);
    /* a full table: the next open, for reading or writing, is refused with the file's name and
     * a handle of -1; a close frees a slot */
    am_port_stream full[64];
    int nfull = 0;
    while (nfull < 64 && am_port_open_read(p, &full[nfull], err, sizeof err) == AM_OK) nfull++;
    CHECK(nfull >= AM_PORT_STREAMS && nfull < 64 && full[nfull] == -1 && strstr(err, "files open at once") && strstr(err, "streamed.txt"),
          "the table full after %d streams: '%s'", nfull, err);
    err[0] = 0;
    CHECK(am_port_open_write(p, &w, err, sizeof err) == AM_ERR_IO && w == -1 && strstr(err, "files open at once"), "open_write into a full table: '%s'", err);
    if (nfull > 0) CHECK(am_port_close(full[--nfull], 0, err, sizeof err) == AM_OK, "close: %s", err);
    CHECK(am_port_open_read(p, &full[nfull], err, sizeof err) == AM_OK, "open after a close freed a slot: %s", err);
    nfull++;
    while (nfull > 0) am_port_close(full[--nfull], 0, NULL, 0);
    CHECK(am_port_read(many[0], buf, sizeof buf, &got, err, sizeof err) == AM_ERR_ARG, "read on a closed stream");
    CHECK(am_port_close(many[0], 0, err, sizeof err) == AM_ERR_ARG, "close of a closed stream");
    /* failures: a missing file, a missing directory */
    path_of(q, sizeof q, "missing.txt");
    unlink(q);
    err[0] = 0;
    CHECK(am_port_open_read(q, &r, err, sizeof err) == AM_ERR_IO && strstr(err, "missing.txt"), "open a missing file: %s", err);
    path_of(q, sizeof q, "no/such/dir/file");
    err[0] = 0;
    CHECK(am_port_open_write(q, &w, err, sizeof err) == AM_ERR_IO && err[0], "open_write into a missing directory");
}

/* the temporaries a killed writer left (NAME.tmp.DIGITS) are removed from a folder; nothing else
 * is: other names, this process's own temporary, a folder or a link of that form, a subfolder's */
static void test_remove_stale(void)
{
    char err[AM_ERR_MAX], dir[600], p[700], own[64];
    if (!scratch[0]) return;
    snprintf(dir, sizeof dir, "%s/stale-%ld", scratch, (long)getpid());
    snprintf(own, sizeof own, "mine.txt.tmp.%ld", (long)getpid());
    static const char* const stale[] = {"checkpoint.txt.tmp.12345", "log.csv.tmp.7", "a.tmp.1.tmp.2"};
    const char* kept[] = {"notes.tmp.txt", "x.tmp.", ".tmp.5", "a.tmp.12x", "b.tmp", "tmp.3", "log.csv", "c.tmp.-1", own};
    const int nstale = 3, nkept = (int)(sizeof kept / sizeof kept[0]);
    /* a folder of this process's own: no file of an earlier run of the test is in it */
    CHECK(am_port_make_dir(dir, err, sizeof err) == AM_OK, "make_dir %s: %s", dir, err);
    for (int i = 0; i < nstale; i++) {
        snprintf(p, sizeof p, "%s/%s", dir, stale[i]);
        CHECK(am_port_append_file(p, "partial", 7, err, sizeof err) == AM_OK, "%s", err);
    }
    for (int i = 0; i < nkept; i++) {
        snprintf(p, sizeof p, "%s/%s", dir, kept[i]);
        CHECK(am_port_append_file(p, "kept", 4, err, sizeof err) == AM_OK, "%s", err);
    }
    snprintf(p, sizeof p, "%s/folder.tmp.9", dir);
    CHECK(am_port_make_dir(p, err, sizeof err) == AM_OK, "%s", err);
    snprintf(p, sizeof p, "%s/sub", dir);
    CHECK(am_port_make_dir(p, err, sizeof err) == AM_OK, "%s", err);
    snprintf(p, sizeof p, "%s/sub/d.tmp.3", dir);
    CHECK(am_port_append_file(p, "kept", 4, err, sizeof err) == AM_OK, "%s", err);
    snprintf(p, sizeof p, "%s/link.tmp.5", dir); /* a link to log.csv beside it */
    CHECK(symlink("log.csv", p) == 0, "symlink %s", p);

    int removed = -1;
    CHECK(am_port_remove_stale(dir, &removed, err, sizeof err) == AM_OK, "remove_stale: %s", err);
    CHECK(removed == nstale, "removed %d, want %d", removed, nstale);
    for (int i = 0; i < nstale; i++) {
        snprintf(p, sizeof p, "%s/%s", dir, stale[i]);
        CHECK(am_port_exists(p) == 0, "stale temporary %s left", stale[i]);
    }
    for (int i = 0; i < nkept; i++) {
        snprintf(p, sizeof p, "%s/%s", dir, kept[i]);
        CHECK(am_port_exists(p) == 1, "%s removed", kept[i]);
    }
    struct stat sb;
    snprintf(p, sizeof p, "%s/link.tmp.5", dir);
    CHECK(lstat(p, &sb) == 0 && S_ISLNK(sb.st_mode), "a link named like a temporary was removed");
    snprintf(p, sizeof p, "%s/folder.tmp.9", dir);
    CHECK(am_port_exists(p) == 1, "a folder named like a temporary was removed");
    snprintf(p, sizeof p, "%s/sub/d.tmp.3", dir);
    CHECK(am_port_exists(p) == 1, "a subfolder's file was removed");
    /* again: nothing left to remove; removed may be NULL */
    removed = -1;
    CHECK(am_port_remove_stale(dir, &removed, err, sizeof err) == AM_OK && removed == 0, "second pass removed %d", removed);
    CHECK(am_port_remove_stale(dir, NULL, err, sizeof err) == AM_OK, "removed NULL: %s", err);
    /* a folder that is not there: an error naming it, 0 removed */
    snprintf(p, sizeof p, "%s/no-such-folder", dir);
    removed = -1;
    err[0] = 0;
    CHECK(am_port_remove_stale(p, &removed, err, sizeof err) == AM_ERR_IO && strstr(err, "no-such-folder") && removed == 0,
          "a missing folder: %s, %d removed", err, removed);
    /* the folder goes */
    static const char* const extra[] = {"link.tmp.5", "sub/d.tmp.3", "folder.tmp.9", "sub"};
    for (int i = 0; i < nkept + 4; i++) {
        snprintf(p, sizeof p, "%s/%s", dir, i < nkept ? kept[i] : extra[i - nkept]);
        if (i < nkept + 2) unlink(p);
        else rmdir(p);
    }
    CHECK(rmdir(dir) == 0, "%s: not empty after the test", dir);
}

static void test_progress_is_silent_off_a_terminal(void)
{
    char err[AM_ERR_MAX], p[600];
    if (!scratch[0]) return;
    path_of(p, sizeof p, "stderr.txt");
    fflush(stderr);
    int saved = dup(2);
    int fd = open(p, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    CHECK(saved >= 0 && fd >= 0, "cannot redirect stderr");
    if (saved < 0 || fd < 0) return;
    dup2(fd, 2);
    close(fd);
    int term = am_port_is_terminal();
    am_port_progress("generation 1 of 10");
    am_port_progress("generation 2 of 10");
    am_port_progress(NULL);
    fflush(stderr);
    dup2(saved, 2);
    close(saved);
    CHECK(term == 0, "a file is taken for a terminal");
    char buf[64];
    long len = -1;
    CHECK(am_port_read_file(p, buf, sizeof buf, &len, err, sizeof err) == AM_OK && len == 0,
          "progress wrote %ld bytes to a non-terminal stderr", len);
    CHECK(am_port_interrupted() == 0, "interrupted without a request");
}

/* a folder's entries: every file and folder once, not . and ..; too small a buffer and a missing
 * folder are errors with the folder's name */
static void test_list_dir(void)
{
    char err[AM_ERR_MAX], d[600], p[700], names[256];
    path_of(d, sizeof d, "listing");
    CHECK(am_port_make_dir(d, err, sizeof err) == AM_OK, "%s", err);
    static const char* const want[3] = {"a.vxa", "robot.vxd", "sub"};
    for (int k = 0; k < 2; k++) {
        snprintf(p, sizeof p, "%s/%s", d, want[k]);
        CHECK(am_port_write_file(p, "x", 1, err, sizeof err) == AM_OK, "%s", err);
    }
    snprintf(p, sizeof p, "%s/%s", d, want[2]);
    CHECK(am_port_make_dir(p, err, sizeof err) == AM_OK, "%s", err);
    int count = -1, seen[3] = {0, 0, 0};
    CHECK(am_port_list_dir(d, names, sizeof names, &count, err, sizeof err) == AM_OK && count == 3, "%d entries: %s", count, err);
    const char* q = names;
    for (int i = 0; i < count && i < 3; i++, q += strlen(q) + 1)
        for (int k = 0; k < 3; k++) seen[k] += !strcmp(q, want[k]);
    CHECK(seen[0] == 1 && seen[1] == 1 && seen[2] == 1, "entries seen %d %d %d", seen[0], seen[1], seen[2]);
    CHECK(am_port_list_dir(d, names, 8, &count, err, sizeof err) == AM_ERR_CAPACITY && strstr(err, "listing"), "8 bytes: %s", err);
    snprintf(p, sizeof p, "%s/none", d);
    CHECK(am_port_list_dir(p, names, sizeof names, &count, err, sizeof err) == AM_ERR_IO && strstr(err, "none"), "missing: %s", err);
}

/* the whole text of path into buf (capacity cap), "" when unreadable */
static const char* text_of(const char* path, char* buf, long cap)
{
    char err[AM_ERR_MAX];
    long len = 0;
    if (am_port_read_file(path, buf, cap, &len, err, sizeof err) != AM_OK) buf[0] = 0;
    return buf;
}

/* a file planted by someone else where amorph writes is never written through (issue 31): a
 * symbolic or hard link at the name a temporary had (path.tmp.PID), at an appended table, at a
 * lock; the temporary's name is path.tmp.PID.NONCE, new for every write, and a failure names the
 * user's path, not the temporary */
static void test_no_write_through_links(void)
{
    char err[AM_ERR_MAX], d[600], p[700], q[800], victim[700], buf[256], names[4096];
    if (!scratch[0]) return;
    snprintf(d, sizeof d, "%s/links-%ld", scratch, (long)getpid());
    CHECK(am_port_make_dir(d, err, sizeof err) == AM_OK, "%s", err);
    snprintf(victim, sizeof victim, "%s/victim", d);
    CHECK(am_port_write_file(victim, "secret\n", 7, err, sizeof err) == AM_OK, "%s", err);

    /* the old predictable temporary names, planted as a symbolic and a hard link to the victim */
    snprintf(p, sizeof p, "%s/out.lattice", d);
    snprintf(q, sizeof q, "%s.tmp.%ld", p, (long)getpid());
    CHECK(symlink(victim, q) == 0, "symlink %s", q);
    CHECK(am_port_write_file(p, "lattice\n", 8, err, sizeof err) == AM_OK, "write beside a planted link: %s", err);
    struct stat sb;
    CHECK(!strcmp(text_of(victim, buf, sizeof buf), "secret\n"), "the victim was written through a planted symlink: '%s'", buf);
    CHECK(lstat(p, &sb) == 0 && S_ISREG(sb.st_mode) && sb.st_nlink == 1, "out.lattice is not a file of its own after the write");
    unlink(q);
    CHECK(link(victim, q) == 0, "link %s", q);
    CHECK(am_port_write_file(p, "lattice2\n", 9, err, sizeof err) == AM_OK, "write beside a planted hard link: %s", err);
    CHECK(!strcmp(text_of(victim, buf, sizeof buf), "secret\n"), "the victim was written through a planted hard link: '%s'", buf);
    CHECK(!strcmp(text_of(p, buf, sizeof buf), "lattice2\n"), "out.lattice reads '%s'", buf);
    unlink(q);
    /* the file itself a link: replaced by the new file, the link's target untouched */
    CHECK(unlink(p) == 0 && symlink(victim, p) == 0, "symlink %s", p);
    CHECK(am_port_write_file(p, "new\n", 4, err, sizeof err) == AM_OK, "replace a link: %s", err);
    CHECK(!strcmp(text_of(victim, buf, sizeof buf), "secret\n") && lstat(p, &sb) == 0 && S_ISREG(sb.st_mode),
          "a replace wrote through the link at the path: victim '%s'", buf);

    /* a temporary's name: path.tmp.PID.NONCE (16 hex digits), another one for the next write */
    am_port_stream w1 = -1, w2 = -1;
    snprintf(p, sizeof p, "%s/a.txt", d);
    snprintf(q, sizeof q, "%s/b.txt", d);
    CHECK(am_port_open_write(p, &w1, err, sizeof err) == AM_OK && am_port_open_write(q, &w2, err, sizeof err) == AM_OK, "%s", err);
    int count = 0, temps = 0;
    char first[300] = "";
    CHECK(am_port_list_dir(d, names, sizeof names, &count, err, sizeof err) == AM_OK, "%s", err);
    const char* nm = names;
    for (int k = 0; k < count; k++, nm += strlen(nm) + 1) {
        const long pid = am_temp_name_pid(nm);
        if (pid < 0) continue;
        const char* dot = strrchr(nm, '.');
        CHECK(pid == (long)getpid() && dot && strlen(dot + 1) == 16, "temporary %s", nm);
        if (!temps++) snprintf(first, sizeof first, "%s", dot);
        else CHECK(strcmp(first, dot) != 0, "two temporaries with one nonce %s", dot);
    }
    CHECK(temps == 2, "%d temporaries for two open writes", temps);
    /* this process's own temporaries are not stale */
    int removed = -1;
    CHECK(am_port_remove_stale(d, &removed, err, sizeof err) == AM_OK && removed == 0, "removed %d of its own", removed);
    CHECK(am_port_close(w1, 1, err, sizeof err) == AM_OK && am_port_close(w2, 1, err, sizeof err) == AM_OK, "%s", err);

    /* appends: a symbolic link, a dangling one and a hard link at the table are refused */
    snprintf(p, sizeof p, "%s/log.csv", d);
    CHECK(symlink(victim, p) == 0, "symlink %s", p);
    err[0] = 0;
    CHECK(am_port_append_file(p, "row\n", 4, err, sizeof err) == AM_ERR_IO && strstr(err, "log.csv: a symbolic link: refused"),
          "append through a symlink: '%s'", err);
    CHECK(!strcmp(text_of(victim, buf, sizeof buf), "secret\n"), "a row was appended to the victim: '%s'", buf);
    err[0] = 0;
    CHECK(am_port_sync_file(p, err, sizeof err) == AM_ERR_IO && strstr(err, "log.csv: a symbolic link: refused"), "sync through a symlink: '%s'",
          err);
    snprintf(q, sizeof q, "%s/nowhere", d);
    CHECK(unlink(p) == 0 && symlink(q, p) == 0, "symlink %s", p);
    CHECK(am_port_append_file(p, "row\n", 4, err, sizeof err) == AM_ERR_IO && !am_port_exists(q), "append through a dangling link made %s", q);
    CHECK(unlink(p) == 0 && link(victim, p) == 0, "link %s", p);
    err[0] = 0;
    CHECK(am_port_append_file(p, "row\n", 4, err, sizeof err) == AM_ERR_IO && strstr(err, "hard link"), "append to a hard link: '%s'", err);
    CHECK(!strcmp(text_of(victim, buf, sizeof buf), "secret\n"), "a row was appended to the victim: '%s'", buf);
    unlink(p);
    /* a FIFO is refused at once, never waited on */
    CHECK(mkfifo(p, 0644) == 0, "mkfifo %s", p);
    err[0] = 0;
    CHECK(am_port_append_file(p, "row\n", 4, err, sizeof err) == AM_ERR_IO && strstr(err, "not a regular file"), "append to a FIFO: '%s'", err);
    unlink(p);

    /* the lock: a link is refused and its target left alone; an existing lock file is taken as
     * it is, its text changed only by am_port_lock_stamp (a refused command writes nothing) */
    snprintf(p, sizeof p, "%s/lock", d);
    CHECK(symlink(victim, p) == 0, "symlink %s", p);
    err[0] = 0;
    CHECK(am_port_lock(p, err, sizeof err) == AM_ERR_ARG && strstr(err, "symbolic link"), "lock through a symlink: '%s'", err);
    CHECK(!strcmp(text_of(victim, buf, sizeof buf), "secret\n"), "the lock wrote through a link: '%s'", buf);
    CHECK(unlink(p) == 0 && link(victim, p) == 0, "link %s", p);
    CHECK(am_port_lock(p, err, sizeof err) == AM_ERR_ARG && strstr(err, "hard link"), "lock on a hard link: '%s'", err);
    CHECK(!strcmp(text_of(victim, buf, sizeof buf), "secret\n"), "the lock wrote through a hard link: '%s'", buf);
    unlink(p);
    CHECK(am_port_write_file(p, "12345\n", 6, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_port_lock(p, err, sizeof err) == AM_OK, "lock: %s", err);
    CHECK(!strcmp(text_of(p, buf, sizeof buf), "12345\n"), "taking the lock wrote '%s'", buf);
    am_port_lock_stamp();
    char own[32];
    snprintf(own, sizeof own, "%ld\n", (long)getpid());
    CHECK(!strcmp(text_of(p, buf, sizeof buf), own), "the stamped lock reads '%s', want the pid", buf);
    am_port_unlock();

    /* a write into a missing folder names the file, not its temporary */
    snprintf(p, sizeof p, "%s/no/such/out.lattice", d);
    err[0] = 0;
    CHECK(am_port_write_file(p, "x", 1, err, sizeof err) == AM_ERR_IO && strstr(err, "out.lattice: cannot create") && !strstr(err, ".tmp."),
          "message '%s'", err);

    /* the folder goes */
    static const char* const files[] = {"victim", "out.lattice", "a.txt", "b.txt", "lock"};
    for (size_t k = 0; k < sizeof files / sizeof files[0]; k++) {
        snprintf(p, sizeof p, "%s/%s", d, files[k]);
        unlink(p);
    }
    CHECK(rmdir(d) == 0, "%s: not empty after the test", d);
}

/* 1 when a child process can take the lock of path (it exits at once, releasing it) */
static int other_process_can_lock(const char* path)
{
    pid_t pid = fork();
    if (pid == 0) {
        char err[AM_ERR_MAX];
        _exit(am_port_lock(path, err, sizeof err) == AM_OK ? 0 : 1);
    }
    int status = 0;
    if (pid < 0 || waitpid(pid, &status, 0) != pid) return -1;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

/* several folders held at once (an experiment's run folders), each refused to another process,
 * AM_PORT_LOCKS at most, all released by one am_port_unlock */
static void test_locks(void)
{
    char err[AM_ERR_MAX], a[600], b[600], p[600];
    path_of(a, sizeof a, "lock_a");
    path_of(b, sizeof b, "lock_b");
    CHECK(am_port_lock(a, err, sizeof err) == AM_OK, "lock a: %s", err);
    CHECK(am_port_lock(b, err, sizeof err) == AM_OK, "a second lock while holding one: %s", err);
    CHECK(other_process_can_lock(a) == 0 && other_process_can_lock(b) == 0, "another process took a held lock");
    int n = 2;
    for (; n < AM_PORT_LOCKS; n++) {
        char name[32];
        snprintf(name, sizeof name, "lock_%d", n);
        path_of(p, sizeof p, name);
        if (am_port_lock(p, err, sizeof err) != AM_OK) break;
    }
    CHECK(n == AM_PORT_LOCKS, "only %d of %d locks: %s", n, AM_PORT_LOCKS, err);
    path_of(p, sizeof p, "lock_over");
    CHECK(am_port_lock(p, err, sizeof err) == AM_ERR_CAPACITY && strstr(err, "lock_over"), "lock %d: %s", AM_PORT_LOCKS + 1, err);
    am_port_unlock();
    CHECK(other_process_can_lock(a) == 1 && other_process_can_lock(b) == 1, "am_port_unlock left a lock held");
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    RUN(test_parallel_map_covers_each_item_once);
    RUN(test_parallel_map_rejects_bad_arguments);
    RUN(test_files);
    RUN(test_streams);
    RUN(test_remove_stale);
    RUN(test_locks);
    RUN(test_no_write_through_links);
    RUN(test_list_dir);
    RUN(test_progress_is_silent_off_a_terminal);
    return SUMMARY();
}
