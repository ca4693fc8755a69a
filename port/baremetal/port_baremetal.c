/* Bare-metal port (Cortex-M and RISC-V boards, semihosting): the clock, the console and the
 * files are the host's, reached through semihosting; one core, so the parallel map runs every
 * item in order on worker 0; nothing can interrupt a run.
 *
 * Directories: semihosting has no mkdir. am_port_make_dir succeeds when the directory already
 * exists on the host (opening "path/." succeeds only for a directory) and otherwise fails with
 * a message asking to create it on the host. Built with -DAM_SEMIHOST_MKDIR it instead asks
 * the host shell to create it through SYS_SYSTEM ("mkdir 'path'"), which a debugger may refuse. */
#include "port.h"

#include "semihost.h"

#include <string.h>

/* ---- semihosting helpers ---- */

int32_t sh_open(const char* name, int mode)
{
    uintptr_t a[3] = {(uintptr_t)name, (uintptr_t)mode, (uintptr_t)strlen(name)};
    return sh_call(SH_SYS_OPEN, (uintptr_t)a);
}

int32_t sh_close(int32_t handle)
{
    uintptr_t a[1] = {(uintptr_t)handle};
    return sh_call(SH_SYS_CLOSE, (uintptr_t)a);
}

int32_t sh_write(int32_t handle, const void* data, uint32_t n)
{
    uintptr_t a[3] = {(uintptr_t)handle, (uintptr_t)data, (uintptr_t)n};
    int32_t left = sh_call(SH_SYS_WRITE, (uintptr_t)a);
    return left < 0 || (uint32_t)left > n ? 0 : (int32_t)(n - (uint32_t)left);
}

int32_t sh_read(int32_t handle, void* buf, uint32_t n)
{
    uintptr_t a[3] = {(uintptr_t)handle, (uintptr_t)buf, (uintptr_t)n};
    int32_t left = sh_call(SH_SYS_READ, (uintptr_t)a);
    return left < 0 || (uint32_t)left > n ? -1 : (int32_t)(n - (uint32_t)left);
}

int32_t sh_flen(int32_t handle)
{
    uintptr_t a[1] = {(uintptr_t)handle};
    return sh_call(SH_SYS_FLEN, (uintptr_t)a);
}

int32_t sh_seek(int32_t handle, uint32_t pos)
{
    uintptr_t a[2] = {(uintptr_t)handle, (uintptr_t)pos};
    return sh_call(SH_SYS_SEEK, (uintptr_t)a);
}

void sh_write0(const char* text)
{
    sh_call(SH_SYS_WRITE0, (uintptr_t)text);
}

static int features = -1;   /* SH_EXT_* bits, -1 until read */
static int32_t console[2] = {-2, -2}; /* stdout, stderr handles; -2 until opened, -1 if none */

int sh_features(void)
{
    if (features >= 0) return features;
    features = 0;
    int32_t h = sh_open(":semihosting-features", SH_MODE_RB);
    if (h < 0) return features;
    unsigned char b[5];
    if (sh_read(h, b, 5) == 5 && b[0] == 'S' && b[1] == 'H' && b[2] == 'F' && b[3] == 'B') features = b[4];
    sh_close(h);
    return features;
}

int32_t sh_console(int err)
{
    if (console[err] == -2) {
        /* ":tt" opened for writing is stdout, for appending stderr when the host has both */
        int both = (sh_features() & SH_EXT_STDOUT_STDERR) != 0;
        console[err] = sh_open(":tt", err && both ? 8 : 4);
    }
    return console[err];
}

void sh_write_console(int err, const char* data, uint32_t n)
{
    int32_t h = sh_console(err);
    if (h >= 0) {
        while (n > 0) {
            int32_t put = sh_write(h, data, n);
            if (put <= 0) return;
            data += put;
            n -= (uint32_t)put;
        }
        return;
    }
    /* no console handle: NUL-terminated pieces through SYS_WRITE0 */
    char piece[65];
    while (n > 0) {
        uint32_t k = n < 64 ? n : 64;
        memcpy(piece, data, k);
        piece[k] = 0;
        sh_write0(piece);
        data += k;
        n -= k;
    }
}

_Noreturn void sh_exit(int status)
{
    if (sh_features() & SH_EXT_EXIT_EXTENDED) {
        uintptr_t a[2] = {SH_ADP_APPLICATION_EXIT, (uintptr_t)(uint32_t)status};
        sh_call(SH_SYS_EXIT_EXTENDED, (uintptr_t)a);
    }
    /* the AArch32 SYS_EXIT carries no status: success or a run-time error */
    sh_call(SH_SYS_EXIT, status == 0 ? SH_ADP_APPLICATION_EXIT : SH_ADP_RUNTIME_ERROR);
    for (;;) {
    }
}

/* ---- clock ---- */

#if !defined(AM_BAREMETAL_ICOUNT) /* else the instruction set folder's clock (cortex-m/icount.c) */
double am_port_now(void)
{
    static int32_t freq; /* SYS_TICKFREQ, 0 until asked, -1 when the host has no SYS_ELAPSED */
    if (freq == 0) freq = sh_call(SH_SYS_TICKFREQ, 0);
    if (freq > 0) {
        uint32_t t[2] = {0, 0};
        if (sh_call(SH_SYS_ELAPSED, (uintptr_t)t) == 0)
            return ((double)t[1] * 4294967296.0 + (double)t[0]) / (double)freq;
    }
    int32_t cs = sh_call(SH_SYS_CLOCK, 0);
    return cs < 0 ? 0.0 : 0.01 * (double)cs;
}
#endif

/* ---- console and progress ---- */

/* the C library's streams are unbuffered (cortex-m/startup.c, riscv/picolibc.c), so these keep the
 * order of printf output */
void am_port_out(const char* text)
{
    sh_write_console(0, text, (uint32_t)strlen(text));
}

void am_port_err(const char* text)
{
    sh_write_console(1, text, (uint32_t)strlen(text));
}

int am_port_is_terminal(void)
{
    return 0;
}

void am_port_progress(const char* line)
{
    (void)line;
}

/* ---- files ---- */

am_status am_port_read_file(const char* path, char* buf, long cap, long* len, char* err, int errsz)
{
    int32_t h = sh_open(path, SH_MODE_RB);
    if (h < 0) return am_fail(err, errsz, AM_ERR_IO, "%s: cannot open (host errno %d)", path, (int)sh_call(SH_SYS_ERRNO, 0));
    int32_t size = sh_flen(h);
    if (size < 0) {
        sh_close(h);
        return am_fail(err, errsz, AM_ERR_IO, "%s: cannot tell the file's length", path);
    }
    if ((long)size > cap - 1) {
        sh_close(h);
        return am_fail(err, errsz, AM_ERR_CAPACITY, "%s: file larger than the %ld bytes this build can read", path, cap - 1);
    }
    long n = 0;
    while (n < (long)size) {
        int32_t got = sh_read(h, buf + n, (uint32_t)((long)size - n));
        if (got < 0) {
            sh_close(h);
            return am_fail(err, errsz, AM_ERR_IO, "%s: read error", path);
        }
        if (got == 0) break;
        n += got;
    }
    sh_close(h);
    buf[n] = 0;
    if (len) *len = n;
    return AM_OK;
}

/* writes all n bytes to an open handle; 0 on success */
static int write_all(int32_t h, const void* data, long n)
{
    const char* p = (const char*)data;
    while (n > 0) {
        int32_t put = sh_write(h, p, (uint32_t)n);
        if (put <= 0) return -1;
        p += put;
        n -= put;
    }
    return 0;
}

static int32_t sh_rename(const char* from, const char* to)
{
    uintptr_t a[4] = {(uintptr_t)from, (uintptr_t)strlen(from), (uintptr_t)to, (uintptr_t)strlen(to)};
    return sh_call(SH_SYS_RENAME, (uintptr_t)a);
}

static int32_t sh_remove(const char* name)
{
    uintptr_t a[2] = {(uintptr_t)name, (uintptr_t)strlen(name)};
    return sh_call(SH_SYS_REMOVE, (uintptr_t)a);
}

#define PORT_PATH_MAX 512 /* longest path the port handles, with its suffix */

/* ---- streams: port/common/stream_table.h over semihosting handles ---- */

#define PORT_STREAMS AM_PORT_STREAMS
#define PORT_TMP_CAP PORT_PATH_MAX
typedef int32_t port_handle;

/* the temporary beside path: path.tmp (one program per board; semihosting opens files with fopen's
 * modes, none of which creates exclusively, so a name nobody could guess buys nothing); 0 when it
 * does not fit */
static int sys_tmp_name(char* out, size_t cap, const char* path, uint64_t nonce)
{
    (void)nonce;
    size_t pl = strlen(path);
    if (pl + 5 > cap) return 0;
    memcpy(out, path, pl);
    memcpy(out + pl, ".tmp", 5);
    return 1;
}

static am_status sys_create(const char* path, char* tmp, size_t cap, uint64_t* nonce, port_handle* h, char* err, int errsz)
{
    *nonce = 0;
    sys_tmp_name(tmp, cap, path, 0);
    *h = sh_open(tmp, SH_MODE_WB);
    if (*h < 0) return am_fail(err, errsz, AM_ERR_IO, "%s: cannot create (host errno %d)", path, (int)sh_call(SH_SYS_ERRNO, 0));
    return AM_OK;
}

static am_status sys_open_read(const char* path, port_handle* h, char* err, int errsz)
{
    *h = sh_open(path, SH_MODE_RB);
    if (*h < 0) return am_fail(err, errsz, AM_ERR_IO, "%s: cannot open (host errno %d)", path, (int)sh_call(SH_SYS_ERRNO, 0));
    return AM_OK;
}

static am_status sys_write(port_handle h, const void* data, long n, const char* path, char* err, int errsz)
{
    if (write_all(h, data, n) != 0) return am_fail(err, errsz, AM_ERR_IO, "%s: write error", path);
    return AM_OK;
}

static am_status sys_read(port_handle h, void* buf, long cap, long* got, const char* path, char* err, int errsz)
{
    int32_t n = sh_read(h, buf, (uint32_t)cap);
    if (n < 0) return am_fail(err, errsz, AM_ERR_IO, "%s: read error", path);
    *got = n;
    return AM_OK;
}

static void sys_close(port_handle h)
{
    sh_close(h);
}

static void sys_drop(port_handle h, const char* tmp)
{
    sh_close(h);
    sh_remove(tmp);
}

static am_status sys_commit(port_handle h, const char* tmp, const char* path, char* err, int errsz)
{
    if (sh_close(h) != 0) {
        sh_remove(tmp);
        return am_fail(err, errsz, AM_ERR_IO, "%s: cannot finish writing", path);
    }
    /* a POSIX host's rename replaces path atomically; a host whose rename refuses to replace
     * (Windows) gets the old file removed first, which is not atomic */
    if (sh_rename(tmp, path) != 0 && (sh_remove(path) != 0 || sh_rename(tmp, path) != 0)) {
        sh_remove(tmp);
        return am_fail(err, errsz, AM_ERR_IO, "%s: cannot replace", path);
    }
    return AM_OK;
}

#include "../common/stream_table.h"

am_status am_port_append_file(const char* path, const void* data, long n, char* err, int errsz)
{
    int32_t h = sh_open(path, SH_MODE_AB);
    if (h < 0) return am_fail(err, errsz, AM_ERR_IO, "%s: cannot open for appending (host errno %d)", path, (int)sh_call(SH_SYS_ERRNO, 0));
    /* QEMU 7.2 opens "ab" without O_APPEND (its semihosting drops the flag) and would write at
     * the start: go to the end first, harmless where the host appends anyway */
    int32_t end = sh_flen(h);
    int bad = end < 0 || sh_seek(h, (uint32_t)end) != 0 || write_all(h, data, n);
    if (sh_close(h) != 0) bad = 1;
    if (bad) return am_fail(err, errsz, AM_ERR_IO, "%s: write error", path);
    return AM_OK;
}

/* semihosting has no sync: the host's file system keeps what was written */
am_status am_port_sync_file(const char* path, char* err, int errsz)
{
    (void)path, (void)err, (void)errsz;
    return AM_OK;
}

int am_port_exists(const char* path)
{
    int32_t h = sh_open(path, 0);
    if (h < 0) return 0;
    sh_close(h);
    return 1;
}

/* 1 when path names a directory on the host: "path/." opens only then */
static int is_dir(const char* path)
{
    char dot[PORT_PATH_MAX];
    size_t pl = strlen(path);
    if (pl + 3 > sizeof dot) return 0;
    memcpy(dot, path, pl);
    memcpy(dot + pl, "/.", 3);
    return am_port_exists(dot);
}

am_status am_port_make_dir(const char* path, char* err, int errsz)
{
    if (is_dir(path)) return AM_OK;
    if (am_port_exists(path)) return am_fail(err, errsz, AM_ERR_IO, "%s: exists and is not a directory", path);
#if defined(AM_SEMIHOST_MKDIR)
    char cmd[2 * PORT_PATH_MAX];
    size_t k = 0;
    const char* pre = "mkdir '";
    for (const char* s = pre; *s; s++) cmd[k++] = *s;
    for (const char* s = path; *s; s++) {
        if (k + 6 >= sizeof cmd) return am_fail(err, errsz, AM_ERR_IO, "%s: path too long", path);
        if (*s == '\'') {
            memcpy(cmd + k, "'\\''", 4); /* a quote inside single quotes */
            k += 4;
        } else cmd[k++] = *s;
    }
    cmd[k++] = '\'';
    cmd[k] = 0;
    uintptr_t a[2] = {(uintptr_t)cmd, (uintptr_t)k};
    if (sh_call(SH_SYS_SYSTEM, (uintptr_t)a) == 0 && is_dir(path)) return AM_OK;
    return am_fail(err, errsz, AM_ERR_IO, "%s: the host could not create the directory", path);
#else
    return am_fail(err, errsz, AM_ERR_IO, "%s: no such directory, and semihosting cannot create one: create it on the host", path);
#endif
}

/* ---- stale temporaries: semihosting cannot list a folder ---- */

/* nothing to find and nothing to remove: a temporary here is path.tmp, one per file, which the
 * next atomic write of path truncates, fills and renames, so none outlives a file that is written
 * again (a run's checkpoint, rewritten every generation) */
am_status am_port_remove_stale(const char* dir, int* removed, char* err, int errsz)
{
    (void)dir, (void)err, (void)errsz;
    if (removed) *removed = 0;
    return AM_OK;
}

/* ---- folders: semihosting cannot list one ---- */

am_status am_port_list_dir(const char* dir, char* names, long cap, int* count, char* err, int errsz)
{
    (void)names, (void)cap;
    *count = 0;
    return am_fail(err, errsz, AM_ERR_IO, "%s: cannot list a folder on this board (name the files)", dir);
}

/* ---- the program: one process ---- */

void am_port_start(int* argc, char*** argv)
{
    (void)argc, (void)argv;
}

int am_port_end(int status)
{
    return status;
}

/* ---- parallel map: one core, one worker ---- */

int am_port_processes(void)
{
    return 1;
}

int am_port_cores(void)
{
    return 1;
}

am_status am_port_parallel_map(int n, int workers, am_port_task task, void* ctx, void* out, long size, char* err, int errsz)
{
    (void)out;
    if (workers < 1 || n < 0 || size < 0 || !task) return am_fail(err, errsz, AM_ERR_ARG, "parallel map: %d items on %d workers", n, workers);
    for (int i = 0; i < n; i++) task(ctx, i, 0);
    return AM_OK;
}

/* ---- interruption: a board has no Ctrl-C ---- */

void am_port_catch_interrupt(void)
{
}

int am_port_interrupted(void)
{
    return 0;
}

/* ---- owning a folder: one process, nothing to lock ---- */

am_status am_port_lock(const char* path, char* err, int errsz)
{
    (void)path, (void)err, (void)errsz;
    return AM_OK;
}

void am_port_lock_stamp(void)
{
}

void am_port_unlock(void)
{
}

/* ---- testing interruptions: no environment, no signals ---- */

const char* am_port_getenv(const char* name)
{
    (void)name;
    return NULL;
}

void am_port_raise(am_port_signal sig)
{
    (void)sig;
}
