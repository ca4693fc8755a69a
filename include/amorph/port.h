/* amorph/port.h: the porting layer, the whole contract between amorph and a platform.
 *
 * The library in src/ never calls the OS: everything platform-bound (time, console, files,
 * threads, signals) goes through these functions, implemented once per platform in
 * port/<name>/ (port/posix: Linux and other POSIX systems; port/baremetal: Cortex-M boards
 * with semihosting). A port is selected at build time with `make PORT=name`; docs/porting.md
 * says how to add one.
 *
 * Rules every port keeps:
 * - no allocation (static storage only), no recursion;
 * - nothing here may change a result: the clock, the console and the number of workers only
 *   change how fast and how chatty a run is, never what it computes;
 * - every function is callable from the main thread; only am_port_now and the task given to
 *   am_port_parallel_map run on worker threads.
 */
#ifndef AMORPH_PORT_H
#define AMORPH_PORT_H

#include "amorph/status.h"

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

/* reads the whole file path into buf (capacity cap) and NUL-terminates it; *len gets its length.
 * AM_ERR_IO if unreadable, AM_ERR_CAPACITY if larger than cap - 1. */
am_status am_port_read_file(const char* path, char* buf, long cap, long* len, char* err, int errsz);
/* writes n bytes to path atomically: a temporary file beside it, flushed, then renamed over
 * path, so a reader (or a crash) sees either the old file or the whole new one */
am_status am_port_write_file(const char* path, const void* data, long n, char* err, int errsz);
/* appends n bytes to path (created if missing); not atomic (logs) */
am_status am_port_append_file(const char* path, const void* data, long n, char* err, int errsz);
/* creates the directory path (one level); AM_OK if it already exists as a directory */
am_status am_port_make_dir(const char* path, char* err, int errsz);
/* 1 when path exists (file or directory), 0 otherwise */
int am_port_exists(const char* path);

/* ---- parallel map ---- */

/* one item of a parallel map: item in [0, n), worker in [0, workers) names the caller's
 * per-worker workspace (no two calls with the same worker run at the same time) */
typedef void (*am_port_task)(void* ctx, int item, int worker);
/* processor cores available (1 on a single-core board) */
int am_port_cores(void);
/* calls task(ctx, item, worker) exactly once for every item in [0, n), in items' order of
 * hand-out (item 0 first) on up to `workers` workers, and returns when all are done. A port may
 * use fewer workers than asked (port/baremetal uses one); results must not depend on how many.
 * AM_ERR_ARG for workers < 1 or n < 0, AM_ERR_IO if the platform cannot start a worker. */
am_status am_port_parallel_map(int n, int workers, am_port_task task, void* ctx, char* err, int errsz);

/* ---- interruption ---- */

/* from now on, an interruption request (Ctrl-C, SIGTERM) sets a flag instead of ending the
 * process; a second request ends it at once */
void am_port_catch_interrupt(void);
/* 1 once an interruption was requested since am_port_catch_interrupt */
int am_port_interrupted(void);

#endif
