/* port/port.h: the porting layer, the program's OS layer: the whole contract between the program
 * (tools/) and a platform. The library (src/, include/amorph/) neither includes nor calls it: it
 * never calls the OS, and the evolver runs on the executor its caller gives (tools/executor.c wraps
 * this port's map and clock). Included as "port.h" by tools/, tests/ and port/ (-Iport, given to
 * their objects only, so that a source of src/ cannot include it).
 *
 * Everything platform-bound (time, console, files, threads, signals) goes through these
 * functions, implemented once per platform in
 * port/<name>/ (port/posix: Linux and other POSIX systems; port/win32: Windows;
 * port/baremetal: Cortex-M and RISC-V boards with semihosting). A port is selected at build
 * time with `make PORT=name`; docs/porting.md says how to add one.
 *
 * Rules every port keeps:
 * - no allocation (static storage only), no recursion;
 * - nothing here may change a result: the clock, the console and the number of workers only
 *   change how fast and how chatty a run is, never what it computes;
 * - every function is callable from the main thread; only am_port_now, am_port_interrupted,
 *   am_port_raise and the task given to am_port_parallel_map run on worker threads.
 */
#ifndef AMORPH_PORT_H
#define AMORPH_PORT_H

#include "amorph/base.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- the program ---- */

/* the first call of a program (main's), before any other function here: a port that runs the
 * program as several processes (port/mpi) joins them; the others do nothing */
void am_port_start(int* argc, char*** argv);
/* the last call of a program, with its exit status; returns the status main returns. A port of
 * several processes ends them together there (every process reaches it with the same status: they
 * run the same program on the same inputs, the port's). */
int am_port_end(int status);

/* ---- clock ---- */

/* monotonic wall clock, seconds since an arbitrary origin (only differences are meaningful) */
double am_port_now(void);

/* ---- console and progress ---- */

/* writes text to the console's output stream (stdout; semihosting on boards) */
void am_port_out(const char* text);
/* writes text to the console's diagnostic stream (stderr; semihosting on boards) */
void am_port_err(const char* text);
/* 1 when the diagnostic stream is an interactive terminal that can redraw a line in place */
int am_port_is_terminal(void);
/* the live progress line: on a terminal, redraws one line in place (line NULL ends it with a
 * newline); elsewhere it does nothing (callers print plain periodic lines instead) */
void am_port_progress(const char* line);

/* ---- files ---- */

/* Reading (whole files and streams) opens regular files only: a folder, FIFO or device is refused
 * with AM_ERR_IO at once, never waited on. */
/* reads the whole file path into buf (capacity cap) and NUL-terminates it; *len gets its length.
 * AM_ERR_IO if unreadable, AM_ERR_CAPACITY if larger than cap - 1. */
am_status am_port_read_file(const char* path, char* buf, long cap, long* len, char* err, int errsz);
/* writes n bytes to path atomically: a temporary file beside it, flushed, then renamed over
 * path (a link at path is replaced, never written through), so a reader (or a crash) sees either
 * the old file or the whole new one (one write of a
 * stream, below; port/common/port_file.c writes it once over the streams for every port) */
am_status am_port_write_file(const char* path, const void* data, long n, char* err, int errsz);
/* appends n bytes to path (created if missing); not atomic (logs). The file is opened without
 * following a link: a symbolic link, a file with several names (a hard link), a FIFO or a device
 * at path is refused with AM_ERR_IO, never written (port/baremetal: the host's semihosting cannot
 * tell, and writes where it points). */
am_status am_port_append_file(const char* path, const void* data, long n, char* err, int errsz);
/* flushes path (a regular file of one name, opened without following a link, as for appending;
 * never created) to the storage: once it returns AM_OK, what was appended to it survives a power
 * cut. A run's tables are synced so before the checkpoint that counts their rows is written.
 * AM_ERR_IO when path cannot be opened or flushed (port/baremetal: AM_OK, semihosting cannot) */
am_status am_port_sync_file(const char* path, char* err, int errsz);
/* streams: a file written or read piece by piece, so a text of any length needs only a small
 * buffer. A written stream is an atomic replace like am_port_write_file: its pieces go to a
 * temporary file beside path, which a committing am_port_close flushes and renames over path; a
 * reader (or a crash) sees the old file or the whole new one, never a part. Streams live in a
 * fixed table of the port (at least AM_PORT_STREAMS open at once; no allocation); the handle
 * names a slot. The path string must stay valid and unchanged until am_port_close. The temporary
 * is made anew, never opened through a file or link planted at its name: the POSIX and Windows
 * ports name it path.tmp.PID.NONCE (NONCE 16 hex digits, unpredictable) and create it exclusively,
 * trying another NONCE when the name is taken; port/baremetal's is path.tmp (semihosting has no
 * exclusive create). A failure to make it names path, not the temporary. */
#define AM_PORT_STREAMS 2
typedef int am_port_stream;
/* starts an atomic replace of path (nothing is visible at path until the commit) */
am_status am_port_open_write(const char* path, am_port_stream* s, char* err, int errsz);
/* appends n bytes; after a failure the stream only waits for am_port_close, which drops it */
am_status am_port_write(am_port_stream s, const void* data, long n, char* err, int errsz);
/* opens path for reading from its start */
am_status am_port_open_read(const char* path, am_port_stream* s, char* err, int errsz);
/* reads up to cap bytes into buf (no NUL added); *got gets the count, 0 at the end of the file */
am_status am_port_read(am_port_stream s, void* buf, long cap, long* got, char* err, int errsz);
/* ends a stream and frees its slot. A written stream with commit 1 (and no failed write) is
 * finished: flushed, closed and renamed over its path; with commit 0, or after a failed write,
 * it is dropped: the temporary is removed and path stays as it was. AM_OK, or AM_ERR_IO when
 * finishing fails (the temporary is removed then too); always AM_OK for a read stream. */
am_status am_port_close(am_port_stream s, int commit, char* err, int errsz);
/* creates the directory path (one level); AM_OK if it already exists as a directory */
am_status am_port_make_dir(const char* path, char* err, int errsz);
/* 1 when path exists (file or directory), 0 otherwise */
int am_port_exists(const char* path);
/* removes the temporaries of atomic replaces (above) that a process left in the folder dir when
 * it died before renaming them (a kill during a write), and sets *removed (may be NULL) to their
 * count. The POSIX and Windows ports' temporaries are path.tmp.PID.NONCE: they remove the regular
 * files directly in dir named NAME.tmp.DIGITS.HEX or NAME.tmp.DIGITS (an older build's; NAME not
 * empty, am_temp_name_pid), except this process's own, and touch nothing else. Call it only while no other process writes files in dir (the caller holds the folder's
 * lock, am_port_lock). AM_ERR_IO when dir cannot be listed or a temporary cannot be removed (the
 * others are removed all the same). A port that cannot list a folder returns AM_OK with 0
 * removed: port/baremetal, whose one temporary per file, path.tmp, is reused and renamed by the
 * next write of path. */
am_status am_port_remove_stale(const char* dir, int* removed, char* err, int errsz);
/* the names of the entries of the folder dir (files and folders, not . and ..), in no particular
 * order, each followed by a NUL, into names (capacity cap); *count gets how many. AM_ERR_IO when
 * dir cannot be listed (not a folder; a port without listing, as port/baremetal), AM_ERR_CAPACITY
 * when the names need more than cap bytes. */
am_status am_port_list_dir(const char* dir, char* names, long cap, int* count, char* err, int errsz);

/* ---- parallel map ---- */

/* one item of a parallel map: item in [0, n), worker in [0, workers) names the caller's
 * per-worker workspace (no two calls with the same worker run at the same time) */
typedef void (*am_port_task)(void* ctx, int item, int worker);
/* processor cores available to this process (1 on a single-core board; port/mpi: this machine's
 * cores shared among the ranks on it) */
int am_port_cores(void);
/* the processes a parallel map spreads its items over: 1, but for a port of several (port/mpi: the
 * ranks). Like the workers, it never changes a result. */
int am_port_processes(void);
/* calls task(ctx, item, worker) exactly once for every item in [0, n), in items' order of
 * hand-out (item 0 first) on up to `workers` workers, and returns when all are done. A port may
 * use fewer workers than asked (port/baremetal uses one); results must not depend on how many.
 * Item i's result is the `size` bytes at (char*)out + i * size: the task writes nothing else that
 * the caller reads after the map. A port whose workers share the caller's memory (posix, win32,
 * baremetal) ignores out and size; one whose workers are other processes (port/mpi) runs each item
 * in one of them and copies its result bytes to every process, so all hold the same results.
 * AM_ERR_ARG for workers < 1, n < 0 or size < 0, AM_ERR_IO if the platform cannot start a worker or
 * lost one. */
am_status am_port_parallel_map(int n, int workers, am_port_task task, void* ctx, void* out, long size, char* err, int errsz);

/* ---- interruption ---- */

/* from now on, an interruption request (Ctrl-C, SIGTERM) sets a flag instead of ending the
 * process; a second request ends it at once */
void am_port_catch_interrupt(void);
/* 1 once an interruption was requested since am_port_catch_interrupt */
int am_port_interrupted(void);

/* ---- owning a folder ---- */

/* takes the exclusive lock of the file path (created empty if missing), held until am_port_unlock
 * or the end of the process, however it ends (kill -9 included: no stale lock is left). Taking it
 * writes nothing into an existing file (am_port_lock_stamp does, once the caller has accepted its
 * work), and the file is opened without following a link: a symbolic link, a file with several
 * names (a hard link), a FIFO or a device at path is refused. Up to AM_PORT_LOCKS locks at a time
 * (an experiment holds one per run folder it runs). AM_ERR_IO when another process holds it (the
 * message names it); AM_ERR_ARG when the file cannot be opened, made or locked (the message says
 * why); AM_ERR_CAPACITY past AM_PORT_LOCKS. A port with one process does nothing. */
#define AM_PORT_LOCKS 64
am_status am_port_lock(const char* path, char* err, int errsz);
/* writes this process's id into the file of the lock taken last (the POSIX and Windows ports: the
 * owner, for people and for the message of a refused second process; the lock is what counts) */
void am_port_lock_stamp(void);
/* releases every lock this process holds */
void am_port_unlock(void);

/* ---- testing interruptions ---- */

/* the value of the environment variable name, or NULL when it is not set (always NULL on a port
 * without an environment, as port/baremetal). The command reads AMORPH_TEST_INTERRUPT with it
 * (docs/evolve.md, Testing interruptions); the library never does. */
const char* am_port_getenv(const char* name);
/* the interruptions a process can be sent from outside */
typedef enum am_port_signal { AM_PORT_SIGINT = 1, AM_PORT_SIGTERM, AM_PORT_SIGKILL, AM_PORT_SIGSTOP } am_port_signal;
/* sends sig to this process itself, as `kill -SIG` from outside would, for deterministic tests
 * of the interruption paths: SIGINT and SIGTERM go to the calling thread, so the handler of
 * am_port_catch_interrupt has run when this returns (am_port_interrupted() is then 1); SIGKILL
 * ends the process at once, wherever it is (a shell sees status 137); SIGSTOP stops it until a
 * SIGCONT (or a SIGKILL) from outside, to hold it at a chosen point. Callable from a worker of
 * am_port_parallel_map. A port without signals does nothing. */
void am_port_raise(am_port_signal sig);

#ifdef __cplusplus
}
#endif
#endif
