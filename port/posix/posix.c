/* port/posix/posix.c: the POSIX port's work: clock, console and progress line, files with atomic
 * replace (and the removal of the temporaries a killed process left), a parallel map on POSIX
 * threads, Ctrl-C / SIGTERM caught into a flag, and the environment and a signal to itself for
 * tests of interruptions. Each function of the contract (port.h) is here as am_posix_* (posix.h):
 * port_posix.c defines the contract by calling them, and port/mpi/port_mpi.c, in the MPI build,
 * calls them from rank 0 or from every rank. */
#define _POSIX_C_SOURCE 200809L
/* 64-bit file offsets on 32-bit systems (glibc): readdir would otherwise fail with EOVERFLOW on a
 * file system whose directory offsets or inode numbers do not fit 32 bits (ext4, btrfs, a 64-bit
 * host under qemu-user) */
#define _FILE_OFFSET_BITS 64
#include "posix.h"
#include "amorph/base.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#define PORT_MAX_THREADS 64 /* workers a parallel map can start */

/* ---- the program: one process ---- */

void am_posix_start(int* argc, char*** argv)
{
    (void)argc, (void)argv;
}

int am_posix_end(int status)
{
    return status;
}

double am_posix_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* fd, opened non-blocking at path, kept when it is a regular file with at most max_names names
 * (then made blocking again and returned), else closed and refused (-1 after the message): a FIFO,
 * device or folder is never waited on nor written; a file with other names (a hard link) is not
 * written either */
static int keep_regular(int fd, const char* path, nlink_t max_names, char* err, int errsz)
{
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        am_fail(err, errsz, AM_ERR_IO, "%s: not a regular file (a folder, FIFO or device): refused", path);
        return -1;
    }
    if (st.st_nlink > max_names) {
        close(fd);
        am_fail(err, errsz, AM_ERR_IO, "%s: a file with %ld names (a hard link): refused (amorph writes no file through a link)", path,
                (long)st.st_nlink);
        return -1;
    }
    int fl = fcntl(fd, F_GETFL);
    if (fl >= 0) fcntl(fd, F_SETFL, fl & ~O_NONBLOCK);
    return fd;
}

/* path opened for reading when it is a regular file: a FIFO, device or folder is refused without
 * waiting for a writer (opened non-blocking, checked, then made blocking again); fd, or -1 after
 * the message */
static int open_regular(const char* path, char* err, int errsz)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK);
    if (fd < 0) {
        am_fail(err, errsz, AM_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
        return -1;
    }
    return keep_regular(fd, path, (nlink_t)-1, err, errsz);
}

am_status am_posix_read_file(const char* path, char* buf, long cap, long* len, char* err, int errsz)
{
    int fd = open_regular(path, err, errsz);
    if (fd < 0) return AM_ERR_IO;
    long n = 0;
    for (;;) {
        if (n >= cap - 1) {
            char extra;
            ssize_t more = read(fd, &extra, 1);
            close(fd);
            if (more > 0)
                return am_fail(err, errsz, AM_ERR_CAPACITY, "%s: file larger than the %ld bytes this build can read", path, cap - 1);
            break;
        }
        ssize_t got = read(fd, buf + n, (size_t)(cap - 1 - n));
        if (got < 0) {
            if (errno == EINTR) continue;
            int e = errno;
            close(fd);
            return am_fail(err, errsz, AM_ERR_IO, "%s: read error: %s", path, strerror(e));
        }
        if (got == 0) {
            close(fd);
            break;
        }
        n += got;
    }
    buf[n] = 0;
    if (len) *len = n;
    return AM_OK;
}

/* writes all n bytes to fd (retrying on EINTR); 0, or the errno of the failure */
static int write_all(int fd, const void* data, long n)
{
    const char* p = (const char*)data;
    long done = 0;
    while (done < n) {
        ssize_t put = write(fd, p + done, (size_t)(n - done));
        if (put < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        done += put;
    }
    return 0;
}

/* ---- streams: port/common/stream_table.h over file descriptors ---- */

#define PORT_STREAMS 8
#define PORT_TMP_CAP 4096
typedef int port_handle;

/* the temporary beside path: path.tmp.<pid>.<nonce, 16 hex digits>; 0 when the name does not fit */
static int sys_tmp_name(char* out, size_t cap, const char* path, uint64_t nonce)
{
    int n = snprintf(out, cap, "%s.tmp.%ld.%016" PRIx64, path, (long)getpid(), nonce);
    return n >= 0 && (size_t)n < cap;
}

/* a temporary's nonce, unpredictable to another user: the library's generator (amorph/base.h),
 * seeded once from /dev/urandom when it can be read, the clock, this process's address space
 * (randomised by the system) and its id; each draw also takes the clock. Names only: never a
 * result. */
static uint64_t tmp_nonce(void)
{
    static am_rng rng;
    static int seeded;
    struct timespec ts;
    clock_gettime(CLOCK_REALTIME, &ts);
    if (!seeded) {
        uint64_t seed = (uint64_t)ts.tv_nsec ^ ((uint64_t)ts.tv_sec << 32) ^ (uint64_t)(uintptr_t)&rng ^ ((uint64_t)getpid() << 20);
        int fd = open("/dev/urandom", O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
        if (fd >= 0) {
            uint64_t r = 0;
            if (read(fd, &r, sizeof r) == (ssize_t)sizeof r) seed ^= r;
            close(fd);
        }
        am_rng_seed(&rng, seed);
        seeded = 1;
    }
    return am_rng_u64(&rng) ^ (uint64_t)ts.tv_nsec;
}

/* a new temporary for path: created exclusively (a file or link planted at the name is never
 * opened: the create fails and a new name is tried), never through a link */
static am_status sys_create(const char* path, char* tmp, size_t cap, uint64_t* nonce, port_handle* h, char* err, int errsz)
{
    int e = EEXIST;
    *h = -1;
    for (int k = 0; k < 64 && e == EEXIST; k++) {
        *nonce = tmp_nonce();
        sys_tmp_name(tmp, cap, path, *nonce);
        *h = open(tmp, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
        if (*h >= 0) return AM_OK;
        e = errno;
    }
    return am_fail(err, errsz, AM_ERR_IO, "%s: cannot create: %s", path, strerror(e));
}

static am_status sys_open_read(const char* path, port_handle* h, char* err, int errsz)
{
    *h = open_regular(path, err, errsz);
    return *h < 0 ? AM_ERR_IO : AM_OK;
}

static am_status sys_write(port_handle h, const void* data, long n, const char* path, char* err, int errsz)
{
    int e = write_all(h, data, n);
    if (e != 0) return am_fail(err, errsz, AM_ERR_IO, "%s: write error: %s", path, strerror(e));
    return AM_OK;
}

static am_status sys_read(port_handle h, void* buf, long cap, long* got, const char* path, char* err, int errsz)
{
    for (;;) {
        ssize_t n = read(h, buf, (size_t)cap);
        if (n >= 0) {
            *got = (long)n;
            return AM_OK;
        }
        if (errno != EINTR) return am_fail(err, errsz, AM_ERR_IO, "%s: read error: %s", path, strerror(errno));
    }
}

static void sys_close(port_handle h)
{
    close(h);
}

static void sys_drop(port_handle h, const char* tmp)
{
    close(h);
    unlink(tmp);
}

static am_status sys_commit(port_handle h, const char* tmp, const char* path, char* err, int errsz)
{
    int bad = fsync(h) != 0, e = errno;
    if (close(h) != 0 && !bad) bad = 1, e = errno;
    if (bad) {
        unlink(tmp);
        return am_fail(err, errsz, AM_ERR_IO, "%s: cannot finish writing: %s", path, strerror(e));
    }
    if (rename(tmp, path) != 0) {
        e = errno;
        unlink(tmp);
        return am_fail(err, errsz, AM_ERR_IO, "%s: cannot replace: %s", path, strerror(e));
    }
    return AM_OK;
}

/* the streams as am_posix_open_write ... */
#define PORT_FN(name) am_posix_##name
#include "../common/stream_table.h"

int am_posix_processes(void)
{
    return 1;
}

int am_posix_cores(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : (int)n;
}

/* ---- console ---- */

static int progress_open; /* 1 while a progress line is on the terminal */

static void put_all(int fd, const char* text)
{
    size_t n = strlen(text);
    while (n > 0) {
        ssize_t put = write(fd, text, n);
        if (put < 0 && errno == EINTR) continue;
        if (put <= 0) return;
        text += put;
        n -= (size_t)put;
    }
}

static void progress_close(void)
{
    if (progress_open) {
        put_all(2, "\n");
        progress_open = 0;
    }
}

void am_posix_out(const char* text)
{
    progress_close();
    fflush(stdout);
    fputs(text, stdout);
    fflush(stdout);
}

void am_posix_err(const char* text)
{
    progress_close();
    fflush(stderr);
    fputs(text, stderr);
    fflush(stderr);
}

int am_posix_is_terminal(void)
{
    return isatty(2) ? 1 : 0;
}

void am_posix_progress(const char* line)
{
    if (!am_posix_is_terminal()) return;
    if (!line) {
        progress_close();
        return;
    }
    fflush(stderr);
    put_all(2, "\r\033[K"); /* back to the start of the line, clear it */
    put_all(2, line);
    progress_open = 1;
}

/* ---- more files ---- */

/* path opened for appending or locking (flags: O_WRONLY | O_APPEND or O_RDWR, with O_CREAT when
 * it may be made) when it is a regular file with one name: a symbolic link at path is not
 * followed, and a link, a file with other names (a hard link: writing it would write them), a
 * FIFO or a device is refused, never written nor waited on. fd, or -1 after the message (what:
 * "cannot open for appending", "cannot open") */
static int open_own(const char* path, int flags, const char* what, char* err, int errsz)
{
    int fd = open(path, flags | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0644);
    if (fd < 0) {
        int e = errno;
        struct stat sb;
        if (e == ELOOP || (lstat(path, &sb) == 0 && S_ISLNK(sb.st_mode)))
            am_fail(err, errsz, AM_ERR_IO, "%s: a symbolic link: refused (amorph writes no file through a link)", path);
        else if (e == ENXIO || e == EISDIR)
            am_fail(err, errsz, AM_ERR_IO, "%s: not a regular file (a folder, FIFO or device): refused", path);
        else
            am_fail(err, errsz, AM_ERR_IO, "%s: %s: %s", path, what, strerror(e));
        return -1;
    }
    return keep_regular(fd, path, 1, err, errsz);
}

am_status am_posix_append_file(const char* path, const void* data, long n, char* err, int errsz)
{
    int fd = open_own(path, O_WRONLY | O_CREAT | O_APPEND, "cannot open for appending", err, errsz);
    if (fd < 0) return AM_ERR_IO;
    int e = write_all(fd, data, n);
    if (e != 0) {
        close(fd);
        return am_fail(err, errsz, AM_ERR_IO, "%s: write error: %s", path, strerror(e));
    }
    if (close(fd) != 0) return am_fail(err, errsz, AM_ERR_IO, "%s: cannot finish writing: %s", path, strerror(errno));
    return AM_OK;
}

am_status am_posix_sync_file(const char* path, char* err, int errsz)
{
    int fd = open_own(path, O_WRONLY | O_APPEND, "cannot open to sync", err, errsz);
    if (fd < 0) return AM_ERR_IO;
    int bad = fsync(fd) != 0, e = errno;
    if (close(fd) != 0 && !bad) bad = 1, e = errno;
    if (bad) return am_fail(err, errsz, AM_ERR_IO, "%s: cannot sync: %s", path, strerror(e));
    return AM_OK;
}

/* ---- owning a folder: an fcntl lock, released by the kernel when the process ends ---- */

static int lock_fd[AM_PORT_LOCKS];
static int locks;

am_status am_posix_lock(const char* path, char* err, int errsz)
{
    if (locks >= AM_PORT_LOCKS) return am_fail(err, errsz, AM_ERR_CAPACITY, "%s: more than %d folder locks at once", path, AM_PORT_LOCKS);
    /* an existing lock file is opened as it is (no truncation): taking the lock writes nothing */
    int fd = open_own(path, O_RDWR | O_CREAT, "cannot open", err, errsz);
    if (fd < 0) return AM_ERR_ARG;
    struct flock fl;
    memset(&fl, 0, sizeof fl);
    fl.l_type = F_WRLCK;
    fl.l_whence = SEEK_SET;
    if (fcntl(fd, F_SETLK, &fl) != 0) {
        int e = errno;
        long pid = 0;
        if ((e == EACCES || e == EAGAIN) && fcntl(fd, F_GETLK, &fl) == 0 && fl.l_type != F_UNLCK) pid = (long)fl.l_pid;
        close(fd);
        if (e == EACCES || e == EAGAIN) return am_fail(err, errsz, AM_ERR_IO, "%s: in use by process %ld", path, pid);
        return am_fail(err, errsz, AM_ERR_ARG, "%s: cannot lock: %s", path, strerror(e));
    }
    lock_fd[locks++] = fd;
    return AM_OK;
}

void am_posix_lock_stamp(void)
{
    if (locks == 0) return;
    char text[32];
    int n = snprintf(text, sizeof text, "%ld\n", (long)getpid());
    int fd = lock_fd[locks - 1];
    /* the owner, for people: the lock is what counts */
    if (ftruncate(fd, 0) == 0 && lseek(fd, 0, SEEK_SET) == 0) (void)write_all(fd, text, n);
}

void am_posix_unlock(void)
{
    while (locks > 0) close(lock_fd[--locks]); /* closing releases the lock */
}

am_status am_posix_make_dir(const char* path, char* err, int errsz)
{
    if (mkdir(path, 0755) == 0) return AM_OK;
    int e = errno;
    struct stat st;
    if (e == EEXIST && stat(path, &st) == 0 && S_ISDIR(st.st_mode)) return AM_OK;
    if (e == EEXIST) return am_fail(err, errsz, AM_ERR_IO, "%s: exists and is not a directory", path);
    return am_fail(err, errsz, AM_ERR_IO, "%s: cannot create the directory: %s", path, strerror(e));
}

int am_posix_exists(const char* path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

am_status am_posix_remove_stale(const char* dir, int* removed, char* err, int errsz)
{
    if (removed) *removed = 0;
    DIR* d = opendir(dir);
    if (!d) return am_fail(err, errsz, AM_ERR_IO, "%s: cannot list the folder: %s", dir, strerror(errno));
    const long own = (long)getpid();
    am_status st = AM_OK;
    int n = 0;
    for (;;) {
        errno = 0;
        struct dirent* e = readdir(d);
        if (!e) {
            if (errno != 0 && st == AM_OK) st = am_fail(err, errsz, AM_ERR_IO, "%s: cannot list the folder: %s", dir, strerror(errno));
            break;
        }
        const long pid = am_temp_name_pid(e->d_name);
        if (pid < 0 || pid == own) continue; /* not a temporary, or one of this process's writes */
        char path[4096];
        int k = snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (k < 0 || (size_t)k >= sizeof path) {
            if (st == AM_OK) st = am_fail(err, errsz, AM_ERR_IO, "%s/%s: path too long", dir, e->d_name);
            continue;
        }
        /* regular files only: a folder or a link of that name is not ours */
        struct stat sb;
        if (lstat(path, &sb) != 0 || !S_ISREG(sb.st_mode)) continue;
        if (unlink(path) != 0) {
            if (st == AM_OK) st = am_fail(err, errsz, AM_ERR_IO, "%s: cannot remove a stale temporary: %s", path, strerror(errno));
            continue;
        }
        n++;
    }
    closedir(d);
    if (removed) *removed = n;
    return st;
}

am_status am_posix_list_dir(const char* dir, char* names, long cap, int* count, char* err, int errsz)
{
    *count = 0;
    DIR* d = opendir(dir);
    if (!d) return am_fail(err, errsz, AM_ERR_IO, "%s: cannot list the folder: %s", dir, strerror(errno));
    long at = 0;
    am_status st = AM_OK;
    for (;;) {
        errno = 0;
        struct dirent* e = readdir(d);
        if (!e) {
            if (errno != 0) st = am_fail(err, errsz, AM_ERR_IO, "%s: cannot list the folder: %s", dir, strerror(errno));
            break;
        }
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
        long n = (long)strlen(e->d_name) + 1;
        if (at + n > cap) {
            st = am_fail(err, errsz, AM_ERR_CAPACITY, "%s: the folder's names need more than %ld bytes", dir, cap);
            break;
        }
        memcpy(names + at, e->d_name, (size_t)n);
        at += n;
        (*count)++;
    }
    closedir(d);
    return st;
}

/* ---- parallel map: port/common/parallel_map.h on POSIX threads ---- */

typedef pthread_mutex_t port_mutex;
typedef pthread_t port_thread;

#include "../common/parallel_map.h"

static int sys_mutex_init(port_mutex* mu)
{
    return pthread_mutex_init(mu, NULL) == 0;
}

static void sys_mutex_lock(port_mutex* mu)
{
    pthread_mutex_lock(mu);
}

static void sys_mutex_unlock(port_mutex* mu)
{
    pthread_mutex_unlock(mu);
}

static void sys_mutex_destroy(port_mutex* mu)
{
    pthread_mutex_destroy(mu);
}

static void* map_thread(void* arg)
{
    map_worker* w = (map_worker*)arg;
    map_loop(w->job, w->id);
    return NULL;
}

static am_status sys_thread_start(port_thread* t, map_worker* w, char* err, int errsz)
{
    int e = pthread_create(t, NULL, map_thread, w);
    if (e != 0) return am_fail(err, errsz, AM_ERR_IO, "parallel map: cannot start a thread: %s", strerror(e));
    return AM_OK;
}

static void sys_thread_join(port_thread t)
{
    pthread_join(t, NULL);
}

/* ---- interruption ---- */

static volatile sig_atomic_t interrupt_flag;

static void on_interrupt(int sig)
{
    if (interrupt_flag) {
        signal(sig, SIG_DFL);
        raise(sig); /* a second request ends the process at once */
        return;
    }
    interrupt_flag = 1;
}

void am_posix_catch_interrupt(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_interrupt;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}

int am_posix_interrupted(void)
{
    return interrupt_flag ? 1 : 0;
}

/* ---- testing interruptions ---- */

const char* am_posix_getenv(const char* name)
{
    return getenv(name);
}

void am_posix_raise(am_port_signal sig)
{
    switch (sig) {
    case AM_PORT_SIGINT: raise(SIGINT); break; /* raise: the calling thread, handler run on return */
    case AM_PORT_SIGTERM: raise(SIGTERM); break;
    case AM_PORT_SIGKILL:
        raise(SIGKILL);
        _exit(128 + SIGKILL); /* not reached: SIGKILL cannot be caught */
    case AM_PORT_SIGSTOP: kill(getpid(), SIGSTOP); break; /* the whole process, not one thread */
    }
}
