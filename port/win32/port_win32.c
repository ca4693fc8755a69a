/* Windows port (port/win32, built with mingw-w64; runs on Windows and under wine): the clock
 * (QueryPerformanceCounter), console and progress line, files with atomic replace (a temporary
 * beside the file, FlushFileBuffers, MoveFileEx over the old one) and the removal of the
 * temporaries a killed process left (FindFirstFile), the folder lock (LockFileEx), a parallel map
 * on Windows threads, Ctrl-C (SetConsoleCtrlHandler) caught into a flag, and the environment and
 * a request to itself for tests of interruptions.
 *
 * Why not port/posix under mingw: mingw-w64 is a C runtime over the Windows API, not a POSIX
 * system. It has no fork, no sigaction and no signals from outside (raise only calls a handler in
 * the same thread; SIGTERM and SIGKILL never arrive), no fcntl record locks (the lock), no
 * O_NONBLOCK opens nor S_ISFIFO (the regular-files rule), and its rename() refuses to replace an
 * existing file, so the atomic replace itself needs MoveFileEx. What it does share with POSIX is
 * ISO C: stdio for the console, getenv.
 *
 * Paths are passed to the ANSI ("A") functions as the program received them, in the process's
 * code page like argv; '/' and '\' both separate folders. */
#define WIN32_LEAN_AND_MEAN
#include "port.h"
#include "amorph/base.h"

#include <windows.h>
#include <process.h>
#include <tlhelp32.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PORT_MAX_THREADS 64  /* workers a parallel map can start (the calling thread and 63 more) */
#define PORT_PATH 4096       /* the longest path with its temporary's suffix */

/* the system's message for error code e, one line without the final full stop, into buf */
static const char* win_error(DWORD e, char* buf, int cap)
{
    DWORD n = FormatMessageA(FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS | FORMAT_MESSAGE_MAX_WIDTH_MASK, NULL, e, 0,
                             buf, (DWORD)cap, NULL);
    while (n > 0 && (buf[n - 1] == ' ' || buf[n - 1] == '.' || buf[n - 1] == '\r' || buf[n - 1] == '\n')) n--;
    if (n == 0) snprintf(buf, (size_t)cap, "Windows error %lu", (unsigned long)e);
    else buf[n] = 0;
    return buf;
}

/* am_fail with the message of the last error after fmt's text: "TEXT: MESSAGE" */
static am_status fail_last(char* err, int errsz, am_status code, const char* what, const char* path)
{
    char msg[256];
    win_error(GetLastError(), msg, sizeof msg);
    return am_fail(err, errsz, code, "%s: %s: %s", path, what, msg);
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

double am_port_now(void)
{
    LARGE_INTEGER freq, t; /* counts per second (fixed at boot), counts since boot */
    QueryPerformanceFrequency(&freq);
    QueryPerformanceCounter(&t);
    return (double)t.QuadPart / (double)freq.QuadPart;
}

/* path opened for reading when it is a regular file: a folder, pipe or device (CON, NUL, COM1) is
 * refused without reading from it; the handle, or INVALID_HANDLE_VALUE after the message */
static HANDLE open_regular(const char* path, char* err, int errsz)
{
    DWORD attr = GetFileAttributesA(path);
    if (attr != INVALID_FILE_ATTRIBUTES && (attr & FILE_ATTRIBUTE_DIRECTORY)) {
        am_fail(err, errsz, AM_ERR_IO, "%s: not a regular file (a folder, pipe or device): refused", path);
        return INVALID_HANDLE_VALUE;
    }
    /* others may read, write, rename and delete it meanwhile: a reader never blocks a writer's
     * atomic replace */
    HANDLE h = CreateFileA(path, GENERIC_READ, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, NULL, OPEN_EXISTING,
                           FILE_ATTRIBUTE_NORMAL | FILE_FLAG_SEQUENTIAL_SCAN, NULL);
    if (h == INVALID_HANDLE_VALUE) {
        fail_last(err, errsz, AM_ERR_IO, "cannot open", path);
        return INVALID_HANDLE_VALUE;
    }
    if (GetFileType(h) != FILE_TYPE_DISK) {
        CloseHandle(h);
        am_fail(err, errsz, AM_ERR_IO, "%s: not a regular file (a folder, pipe or device): refused", path);
        return INVALID_HANDLE_VALUE;
    }
    return h;
}

/* reads up to cap bytes; the count (0 at the end), or -1 with the error in GetLastError() */
static long read_some(HANDLE h, void* buf, long cap)
{
    DWORD got = 0;
    DWORD want = cap > 0x40000000L ? 0x40000000UL : (DWORD)cap;
    if (!ReadFile(h, buf, want, &got, NULL)) return -1;
    return (long)got;
}

am_status am_port_read_file(const char* path, char* buf, long cap, long* len, char* err, int errsz)
{
    HANDLE h = open_regular(path, err, errsz);
    if (h == INVALID_HANDLE_VALUE) return AM_ERR_IO;
    long n = 0;
    for (;;) {
        if (n >= cap - 1) {
            char extra;
            long more = read_some(h, &extra, 1);
            CloseHandle(h);
            if (more > 0)
                return am_fail(err, errsz, AM_ERR_CAPACITY, "%s: file larger than the %ld bytes this build can read", path, cap - 1);
            break;
        }
        long got = read_some(h, buf + n, cap - 1 - n);
        if (got < 0) {
            am_status st = fail_last(err, errsz, AM_ERR_IO, "read error", path);
            CloseHandle(h);
            return st;
        }
        if (got == 0) {
            CloseHandle(h);
            break;
        }
        n += got;
    }
    buf[n] = 0;
    if (len) *len = n;
    return AM_OK;
}

/* writes all n bytes to h; 1, or 0 with the error in GetLastError() */
static int write_all(HANDLE h, const void* data, long n)
{
    const char* p = (const char*)data;
    while (n > 0) {
        DWORD put = 0, want = n > 0x40000000L ? 0x40000000UL : (DWORD)n;
        if (!WriteFile(h, p, want, &put, NULL)) return 0;
        if (put == 0) {
            SetLastError(ERROR_WRITE_FAULT);
            return 0;
        }
        p += put;
        n -= (long)put;
    }
    return 1;
}

/* ---- streams: port/common/stream_table.h over file handles ---- */

#define PORT_STREAMS 8
#define PORT_TMP_CAP PORT_PATH
typedef HANDLE port_handle;

/* the temporary beside path: path.tmp.<process id>.<nonce, 16 hex digits>, the POSIX port's form,
 * so that am_port_remove_stale knows them; 0 when the name does not fit */
static int sys_tmp_name(char* out, size_t cap, const char* path, uint64_t nonce)
{
    int n = snprintf(out, cap, "%s.tmp.%lu.%08lx%08lx", path, (unsigned long)GetCurrentProcessId(), (unsigned long)(nonce >> 32),
                     (unsigned long)(nonce & 0xffffffffu));
    return n >= 0 && (size_t)n < cap;
}

/* a temporary's nonce, unpredictable to another user: the library's generator (amorph/base.h),
 * seeded once from the system time, this process's address space (randomised by the system), its
 * id and the tick count; each draw also takes the performance counter. Names only: never a
 * result. */
static uint64_t tmp_nonce(void)
{
    static am_rng rng;
    static int seeded;
    LARGE_INTEGER t;
    QueryPerformanceCounter(&t);
    if (!seeded) {
        FILETIME ft;
        GetSystemTimeAsFileTime(&ft);
        am_rng_seed(&rng, ((uint64_t)ft.dwHighDateTime << 32 | ft.dwLowDateTime) ^ (uint64_t)(uintptr_t)&rng ^
                              ((uint64_t)GetCurrentProcessId() << 20) ^ ((uint64_t)GetTickCount() << 40) ^ (uint64_t)t.QuadPart);
        seeded = 1;
    }
    return am_rng_u64(&rng) ^ (uint64_t)t.QuadPart;
}

/* a new temporary for path: CREATE_NEW fails on any file or link already at the name (a new name
 * is tried then), and a reparse point is opened as itself, never followed */
static am_status sys_create(const char* path, char* tmp, size_t cap, uint64_t* nonce, port_handle* h, char* err, int errsz)
{
    DWORD e = ERROR_FILE_EXISTS;
    *h = INVALID_HANDLE_VALUE;
    for (int k = 0; k < 64 && (e == ERROR_FILE_EXISTS || e == ERROR_ALREADY_EXISTS); k++) {
        *nonce = tmp_nonce();
        sys_tmp_name(tmp, cap, path, *nonce);
        /* nobody else opens a temporary while it is written */
        *h = CreateFileA(tmp, GENERIC_WRITE, 0, NULL, CREATE_NEW, FILE_ATTRIBUTE_NORMAL | FILE_FLAG_OPEN_REPARSE_POINT, NULL);
        if (*h != INVALID_HANDLE_VALUE) return AM_OK;
        e = GetLastError();
    }
    SetLastError(e);
    return fail_last(err, errsz, AM_ERR_IO, "cannot create", path);
}

static am_status sys_open_read(const char* path, port_handle* h, char* err, int errsz)
{
    *h = open_regular(path, err, errsz);
    return *h == INVALID_HANDLE_VALUE ? AM_ERR_IO : AM_OK;
}

static am_status sys_write(port_handle h, const void* data, long n, const char* path, char* err, int errsz)
{
    if (!write_all(h, data, n)) return fail_last(err, errsz, AM_ERR_IO, "write error", path);
    return AM_OK;
}

static am_status sys_read(port_handle h, void* buf, long cap, long* got, const char* path, char* err, int errsz)
{
    long n = read_some(h, buf, cap);
    if (n < 0) return fail_last(err, errsz, AM_ERR_IO, "read error", path);
    *got = n;
    return AM_OK;
}

static void sys_close(port_handle h)
{
    CloseHandle(h);
}

static void sys_drop(port_handle h, const char* tmp)
{
    CloseHandle(h);
    DeleteFileA(tmp);
}


/* MoveFileEx over path; another program (a virus scanner, an indexer, an editor) that holds the
 * old file open without FILE_SHARE_DELETE makes it fail for a moment, so it is tried again, up to
 * ten times over about half a second (waits of 1, 2, 4 ... 256 ms). 1, or 0 with the error in
 * GetLastError() */
static int replace(const char* tmp, const char* path)
{
    for (int k = 0;; k++) {
        if (MoveFileExA(tmp, path, MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) return 1;
        DWORD e = GetLastError();
        if (k >= 9 || (e != ERROR_ACCESS_DENIED && e != ERROR_SHARING_VIOLATION && e != ERROR_LOCK_VIOLATION)) return 0;
        Sleep(1u << k);
    }
}

static am_status sys_commit(port_handle h, const char* tmp, const char* path, char* err, int errsz)
{
    /* the bytes on the disk before the name points at them */
    int ok = FlushFileBuffers(h) != 0;
    DWORD e = ok ? 0 : GetLastError();
    if (!CloseHandle(h) && ok) ok = 0, e = GetLastError();
    if (!ok) {
        DeleteFileA(tmp);
        SetLastError(e);
        return fail_last(err, errsz, AM_ERR_IO, "cannot finish writing", path);
    }
    if (!replace(tmp, path)) {
        e = GetLastError();
        DeleteFileA(tmp);
        SetLastError(e);
        return fail_last(err, errsz, AM_ERR_IO, "cannot replace", path);
    }
    return AM_OK;
}

#include "../common/stream_table.h"

int am_port_processes(void)
{
    return 1;
}

int am_port_cores(void)
{
    SYSTEM_INFO si;
    GetSystemInfo(&si); /* the processors of this process's group, where its threads run */
    return si.dwNumberOfProcessors < 1 ? 1 : (int)si.dwNumberOfProcessors;
}

/* ---- console: the C runtime's streams (text mode: a newline is CR LF on the console and in a
 * redirection, as every Windows program writes it; files are written byte for byte above) ---- */

static int progress_open; /* 1 while a progress line is on the console */
static size_t progress_len; /* its length, to blank a longer line's rest */

static void progress_close(void)
{
    if (progress_open) {
        fputs("\n", stderr);
        fflush(stderr);
        progress_open = 0;
        progress_len = 0;
    }
}

void am_port_out(const char* text)
{
    progress_close();
    fflush(stdout);
    fputs(text, stdout);
    fflush(stdout);
}

void am_port_err(const char* text)
{
    progress_close();
    fflush(stderr);
    fputs(text, stderr);
    fflush(stderr);
}

int am_port_is_terminal(void)
{
    DWORD mode;
    return GetConsoleMode(GetStdHandle(STD_ERROR_HANDLE), &mode) ? 1 : 0; /* a console, not a file or a pipe */
}

void am_port_progress(const char* line)
{
    if (!am_port_is_terminal()) return;
    if (!line) {
        progress_close();
        return;
    }
    /* back to the start of the line, the new text, blanks over the rest of a longer old one (no
     * escape sequences: a console without virtual terminal processing prints them) */
    size_t n = strlen(line);
    fflush(stderr);
    fputs("\r", stderr);
    fputs(line, stderr);
    for (size_t k = n; k < progress_len; k++) fputc(' ', stderr);
    fflush(stderr);
    progress_len = n;
    progress_open = 1;
}

/* ---- more files ---- */

/* path opened with access acc (created when missing) when it is a regular file with one name: a
 * reparse point (a symbolic link or junction) is opened as itself and refused, as is a file with
 * other names (a hard link: writing it would write them) or a device. The handle, or
 * INVALID_HANDLE_VALUE after the message (what: "cannot open for appending", "cannot open") */
static HANDLE open_own(const char* path, DWORD acc, const char* what, char* err, int errsz)
{
    HANDLE h = CreateFileA(path, acc, FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE, NULL, OPEN_ALWAYS,
                           FILE_ATTRIBUTE_NORMAL | FILE_FLAG_OPEN_REPARSE_POINT, NULL);
    if (h == INVALID_HANDLE_VALUE) {
        fail_last(err, errsz, AM_ERR_IO, what, path);
        return INVALID_HANDLE_VALUE;
    }
    BY_HANDLE_FILE_INFORMATION fi;
    const char* why = NULL;
    if (GetFileType(h) != FILE_TYPE_DISK || !GetFileInformationByHandle(h, &fi) || (fi.dwFileAttributes & FILE_ATTRIBUTE_DIRECTORY))
        why = "not a regular file (a folder, pipe or device): refused";
    else if (fi.dwFileAttributes & FILE_ATTRIBUTE_REPARSE_POINT)
        why = "a symbolic link or junction: refused (amorph writes no file through a link)";
    else if (fi.nNumberOfLinks > 1)
        why = "a file with several names (a hard link): refused (amorph writes no file through a link)";
    if (why) {
        CloseHandle(h);
        am_fail(err, errsz, AM_ERR_IO, "%s: %s", path, why);
        return INVALID_HANDLE_VALUE;
    }
    return h;
}

am_status am_port_append_file(const char* path, const void* data, long n, char* err, int errsz)
{
    /* FILE_APPEND_DATA alone: every write goes to the end of the file */
    HANDLE h = open_own(path, FILE_APPEND_DATA | FILE_READ_ATTRIBUTES, "cannot open for appending", err, errsz);
    if (h == INVALID_HANDLE_VALUE) return AM_ERR_IO;
    if (!write_all(h, data, n)) {
        am_status st = fail_last(err, errsz, AM_ERR_IO, "write error", path);
        CloseHandle(h);
        return st;
    }
    if (!CloseHandle(h)) return fail_last(err, errsz, AM_ERR_IO, "cannot finish writing", path);
    return AM_OK;
}

am_status am_port_sync_file(const char* path, char* err, int errsz)
{
    /* opened as for appending (never created: OPEN_ALWAYS would make it, so it must exist) */
    if (GetFileAttributesA(path) == INVALID_FILE_ATTRIBUTES) return fail_last(err, errsz, AM_ERR_IO, "cannot open to sync", path);
    HANDLE h = open_own(path, FILE_APPEND_DATA | FILE_READ_ATTRIBUTES, "cannot open to sync", err, errsz);
    if (h == INVALID_HANDLE_VALUE) return AM_ERR_IO;
    if (!FlushFileBuffers(h)) {
        am_status st = fail_last(err, errsz, AM_ERR_IO, "cannot sync", path);
        CloseHandle(h);
        return st;
    }
    if (!CloseHandle(h)) return fail_last(err, errsz, AM_ERR_IO, "cannot sync", path);
    return AM_OK;
}

/* ---- owning a folder: LockFileEx on the lock file, released by the system when the process
 * ends, however it ends. The locked byte lies far beyond the file's text (the owner's process id),
 * so that a refused process can still read who owns it. ---- */

#define LOCK_OFFSET_HIGH 0x40000000UL /* the locked byte: offset 2^62 */

static HANDLE lock_h[AM_PORT_LOCKS];
static int locks;

/* the process id written in the lock file open as h, or 0 when it holds none yet */
static unsigned long lock_owner(HANDLE h)
{
    char text[32];
    OVERLAPPED ov;
    DWORD got = 0;
    memset(&ov, 0, sizeof ov);
    if (!ReadFile(h, text, sizeof text - 1, &got, &ov)) return 0;
    text[got] = 0;
    return strtoul(text, NULL, 10);
}

am_status am_port_lock(const char* path, char* err, int errsz)
{
    if (locks >= AM_PORT_LOCKS) return am_fail(err, errsz, AM_ERR_CAPACITY, "%s: more than %d folder locks at once", path, AM_PORT_LOCKS);
    /* an existing lock file is opened as it is: taking the lock writes nothing */
    HANDLE h = open_own(path, GENERIC_READ | GENERIC_WRITE, "cannot open", err, errsz);
    if (h == INVALID_HANDLE_VALUE) return AM_ERR_ARG;
    OVERLAPPED ov;
    memset(&ov, 0, sizeof ov);
    ov.OffsetHigh = LOCK_OFFSET_HIGH;
    if (!LockFileEx(h, LOCKFILE_EXCLUSIVE_LOCK | LOCKFILE_FAIL_IMMEDIATELY, 0, 1, 0, &ov)) {
        DWORD e = GetLastError();
        if (e == ERROR_LOCK_VIOLATION || e == ERROR_IO_PENDING) {
            unsigned long pid = lock_owner(h);
            CloseHandle(h);
            if (pid) return am_fail(err, errsz, AM_ERR_IO, "%s: in use by process %lu", path, pid);
            return am_fail(err, errsz, AM_ERR_IO, "%s: in use by another process", path);
        }
        CloseHandle(h);
        SetLastError(e);
        fail_last(err, errsz, AM_ERR_IO, "cannot lock", path);
        return AM_ERR_ARG;
    }
    lock_h[locks++] = h;
    return AM_OK;
}

void am_port_lock_stamp(void)
{
    if (locks == 0) return;
    HANDLE h = lock_h[locks - 1];
    /* the owner, for people and for the message above: the lock is what counts */
    char text[32];
    int n = snprintf(text, sizeof text, "%lu\n", (unsigned long)GetCurrentProcessId());
    LARGE_INTEGER zero;
    zero.QuadPart = 0;
    if (SetFilePointerEx(h, zero, NULL, FILE_BEGIN) && SetEndOfFile(h)) (void)write_all(h, text, n);
}

void am_port_unlock(void)
{
    while (locks > 0) {
        HANDLE h = lock_h[--locks];
        OVERLAPPED ov;
        memset(&ov, 0, sizeof ov);
        ov.OffsetHigh = LOCK_OFFSET_HIGH;
        UnlockFileEx(h, 0, 1, 0, &ov); /* at once: a lock left to the closing goes when the system gets to it */
        CloseHandle(h);
    }
}

am_status am_port_make_dir(const char* path, char* err, int errsz)
{
    if (CreateDirectoryA(path, NULL)) return AM_OK;
    DWORD e = GetLastError();
    DWORD attr = GetFileAttributesA(path);
    if (e == ERROR_ALREADY_EXISTS && attr != INVALID_FILE_ATTRIBUTES && (attr & FILE_ATTRIBUTE_DIRECTORY)) return AM_OK;
    if (e == ERROR_ALREADY_EXISTS || e == ERROR_FILE_EXISTS) return am_fail(err, errsz, AM_ERR_IO, "%s: exists and is not a directory", path);
    SetLastError(e);
    return fail_last(err, errsz, AM_ERR_IO, "cannot create the directory", path);
}

int am_port_exists(const char* path)
{
    return GetFileAttributesA(path) != INVALID_FILE_ATTRIBUTES;
}

am_status am_port_list_dir(const char* dir, char* names, long cap, int* count, char* err, int errsz)
{
    *count = 0;
    char pattern[PORT_PATH];
    size_t dl = strlen(dir);
    const char* sep = dl > 0 && (dir[dl - 1] == '/' || dir[dl - 1] == '\\' || dir[dl - 1] == ':') ? "" : "/";
    int k = snprintf(pattern, sizeof pattern, "%s%s*", dir, sep);
    if (k < 0 || (size_t)k >= sizeof pattern) return am_fail(err, errsz, AM_ERR_IO, "%s: path too long", dir);
    DWORD attr = GetFileAttributesA(dir);
    if (attr == INVALID_FILE_ATTRIBUTES || !(attr & FILE_ATTRIBUTE_DIRECTORY)) return am_fail(err, errsz, AM_ERR_IO, "%s: cannot list the folder: not a folder", dir);
    WIN32_FIND_DATAA fd;
    HANDLE f = FindFirstFileA(pattern, &fd);
    if (f == INVALID_HANDLE_VALUE) {
        if (GetLastError() == ERROR_FILE_NOT_FOUND) return AM_OK; /* an empty root folder */
        return fail_last(err, errsz, AM_ERR_IO, "cannot list the folder", dir);
    }
    long at = 0;
    am_status st = AM_OK;
    do {
        if (!strcmp(fd.cFileName, ".") || !strcmp(fd.cFileName, "..")) continue;
        long n = (long)strlen(fd.cFileName) + 1;
        if (at + n > cap) {
            st = am_fail(err, errsz, AM_ERR_CAPACITY, "%s: the folder's names need more than %ld bytes", dir, cap);
            break;
        }
        memcpy(names + at, fd.cFileName, (size_t)n);
        at += n;
        (*count)++;
    } while (FindNextFileA(f, &fd));
    FindClose(f);
    return st;
}

am_status am_port_remove_stale(const char* dir, int* removed, char* err, int errsz)
{
    if (removed) *removed = 0;
    char pattern[PORT_PATH];
    size_t dl = strlen(dir);
    const char* sep = dl > 0 && (dir[dl - 1] == '/' || dir[dl - 1] == '\\' || dir[dl - 1] == ':') ? "" : "/";
    int k = snprintf(pattern, sizeof pattern, "%s%s*", dir, sep);
    if (k < 0 || (size_t)k >= sizeof pattern) return am_fail(err, errsz, AM_ERR_IO, "%s: path too long", dir);
    WIN32_FIND_DATAA fd;
    HANDLE f = FindFirstFileA(pattern, &fd);
    if (f == INVALID_HANDLE_VALUE) {
        if (GetLastError() == ERROR_FILE_NOT_FOUND) return AM_OK; /* an empty root folder */
        return fail_last(err, errsz, AM_ERR_IO, "cannot list the folder", dir);
    }
    const long own = (long)GetCurrentProcessId();
    am_status st = AM_OK;
    int n = 0;
    do {
        const long pid = am_temp_name_pid(fd.cFileName);
        if (pid < 0 || pid == own) continue; /* not a temporary, or one of this process's writes */
        /* regular files only: a folder, a link (reparse point) or a device of that name is not ours */
        if (fd.dwFileAttributes & (FILE_ATTRIBUTE_DIRECTORY | FILE_ATTRIBUTE_REPARSE_POINT | FILE_ATTRIBUTE_DEVICE)) continue;
        char path[PORT_PATH];
        k = snprintf(path, sizeof path, "%s%s%s", dir, sep, fd.cFileName);
        if (k < 0 || (size_t)k >= sizeof path) {
            if (st == AM_OK) st = am_fail(err, errsz, AM_ERR_IO, "%s%s%s: path too long", dir, sep, fd.cFileName);
            continue;
        }
        if (!DeleteFileA(path)) {
            if (st == AM_OK) st = fail_last(err, errsz, AM_ERR_IO, "cannot remove a stale temporary", path);
            continue;
        }
        n++;
    } while (FindNextFileA(f, &fd));
    DWORD e = GetLastError();
    FindClose(f);
    if (e != ERROR_NO_MORE_FILES && st == AM_OK) {
        SetLastError(e);
        st = fail_last(err, errsz, AM_ERR_IO, "cannot list the folder", dir);
    }
    if (removed) *removed = n;
    return st;
}

/* ---- parallel map: port/common/parallel_map.h on Windows threads (a critical section hands
 * out the items) ---- */

typedef CRITICAL_SECTION port_mutex;
typedef HANDLE port_thread;

#include "../common/parallel_map.h"

static int sys_mutex_init(port_mutex* mu)
{
    InitializeCriticalSection(mu);
    return 1;
}

static void sys_mutex_lock(port_mutex* mu)
{
    EnterCriticalSection(mu);
}

static void sys_mutex_unlock(port_mutex* mu)
{
    LeaveCriticalSection(mu);
}

static void sys_mutex_destroy(port_mutex* mu)
{
    DeleteCriticalSection(mu);
}

/* _beginthreadex rather than CreateThread: the task uses the C runtime (its per-thread state is
 * set up and freed with the thread) */
static unsigned __stdcall map_thread(void* arg)
{
    map_worker* w = (map_worker*)arg;
    map_loop(w->job, w->id);
    return 0;
}

static am_status sys_thread_start(port_thread* t, map_worker* w, char* err, int errsz)
{
    uintptr_t h = _beginthreadex(NULL, 0, map_thread, w, 0, NULL);
    if (h == 0) return am_fail(err, errsz, AM_ERR_IO, "parallel map: cannot start a thread");
    *t = (HANDLE)h;
    return AM_OK;
}

static void sys_thread_join(port_thread t)
{
    WaitForSingleObject(t, INFINITE);
    CloseHandle(t);
}

/* ---- interruption: Ctrl-C and Ctrl-Break of the console ----
 * The system calls the handler on a thread of its own. The first request sets the flag; the next
 * one is left to the system's default handler, which ends the process at once (exit status
 * STATUS_CONTROL_C_EXIT). Closing the console window, logging off and shutting down are left to
 * the default too: the process ends there like a kill, and the last checkpoint stands. Windows has
 * no SIGTERM: a program is ended from outside with TerminateProcess (taskkill /F), a kill. */

static volatile LONG interrupt_flag;
static volatile LONG catching; /* 1 after am_port_catch_interrupt */

static BOOL WINAPI on_console(DWORD event)
{
    if (event != CTRL_C_EVENT && event != CTRL_BREAK_EVENT) return FALSE;
    return InterlockedExchange(&interrupt_flag, 1) ? FALSE : TRUE;
}

void am_port_catch_interrupt(void)
{
    if (InterlockedExchange(&catching, 1)) return;
    SetConsoleCtrlHandler(on_console, TRUE);
}

int am_port_interrupted(void)
{
    return interrupt_flag ? 1 : 0;
}

/* ---- testing interruptions ---- */

const char* am_port_getenv(const char* name)
{
    return getenv(name);
}

/* stops every thread of this process, the calling one last: the process stays there until a tool
 * resumes it (Process Explorer's or Resource Monitor's "Resume", which resume every thread) or
 * ends it (taskkill /F; under wine, kill -9 of its Unix process) */
static void suspend_self(void)
{
    DWORD me = GetCurrentProcessId(), self = GetCurrentThreadId();
    HANDLE snap = CreateToolhelp32Snapshot(TH32CS_SNAPTHREAD, 0);
    if (snap != INVALID_HANDLE_VALUE) {
        THREADENTRY32 te;
        te.dwSize = sizeof te;
        for (BOOL more = Thread32First(snap, &te); more; te.dwSize = sizeof te, more = Thread32Next(snap, &te)) {
            if (te.th32OwnerProcessID != me || te.th32ThreadID == self) continue;
            HANDLE t = OpenThread(THREAD_SUSPEND_RESUME, FALSE, te.th32ThreadID);
            if (t) {
                SuspendThread(t);
                CloseHandle(t);
            }
        }
        CloseHandle(snap);
    }
    SuspendThread(GetCurrentThread());
}

/* the exit status a POSIX shell shows for a process ended by signal number signo */
#define SIGNAL_STATUS(signo) (128u + (signo))

/* SIGINT and SIGTERM: what the console handler does on Ctrl-C, called on the calling thread so
 * the flag is set when am_port_raise returns; without am_port_catch_interrupt, or for a second
 * request, the process ends at once with the status a shell shows for the signal (130, 143).
 * SIGKILL: TerminateProcess, as taskkill /F (status 137, as after kill -9). SIGSTOP: every thread
 * suspended (suspend_self). */
void am_port_raise(am_port_signal sig)
{
    switch (sig) {
    case AM_PORT_SIGINT:
    case AM_PORT_SIGTERM: {
        unsigned status = SIGNAL_STATUS(sig == AM_PORT_SIGINT ? 2u : 15u);
        if (!catching || InterlockedExchange(&interrupt_flag, 1)) TerminateProcess(GetCurrentProcess(), status);
        break;
    }
    case AM_PORT_SIGKILL:
        TerminateProcess(GetCurrentProcess(), SIGNAL_STATUS(9u));
        ExitProcess(SIGNAL_STATUS(9u)); /* not reached: TerminateProcess of itself does not return */
    case AM_PORT_SIGSTOP: suspend_self(); break;
    }
}
