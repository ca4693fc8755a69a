/* port/posix/port_posix.c: the POSIX port's contract (port.h): each am_port_* function is the
 * POSIX port's am_posix_* (posix.c, posix.h). The MPI build (make PORT=mpi) compiles posix.c and
 * port/mpi/port_mpi.c in place of this file. */
#include "posix.h"

void am_port_start(int* argc, char*** argv) { am_posix_start(argc, argv); }
int am_port_end(int status) { return am_posix_end(status); }
double am_port_now(void) { return am_posix_now(); }
void am_port_out(const char* text) { am_posix_out(text); }
void am_port_err(const char* text) { am_posix_err(text); }
int am_port_is_terminal(void) { return am_posix_is_terminal(); }
void am_port_progress(const char* line) { am_posix_progress(line); }

am_status am_port_read_file(const char* path, char* buf, long cap, long* len, char* err, int errsz)
{
    return am_posix_read_file(path, buf, cap, len, err, errsz);
}
am_status am_port_append_file(const char* path, const void* data, long n, char* err, int errsz)
{
    return am_posix_append_file(path, data, n, err, errsz);
}
am_status am_port_sync_file(const char* path, char* err, int errsz) { return am_posix_sync_file(path, err, errsz); }
am_status am_port_open_write(const char* path, am_port_stream* s, char* err, int errsz)
{
    return am_posix_open_write(path, s, err, errsz);
}
am_status am_port_write(am_port_stream s, const void* data, long n, char* err, int errsz)
{
    return am_posix_write(s, data, n, err, errsz);
}
am_status am_port_open_read(const char* path, am_port_stream* s, char* err, int errsz)
{
    return am_posix_open_read(path, s, err, errsz);
}
am_status am_port_read(am_port_stream s, void* buf, long cap, long* got, char* err, int errsz)
{
    return am_posix_read(s, buf, cap, got, err, errsz);
}
am_status am_port_close(am_port_stream s, int commit, char* err, int errsz) { return am_posix_close(s, commit, err, errsz); }
am_status am_port_make_dir(const char* path, char* err, int errsz) { return am_posix_make_dir(path, err, errsz); }
int am_port_exists(const char* path) { return am_posix_exists(path); }
am_status am_port_remove_stale(const char* dir, int* removed, char* err, int errsz)
{
    return am_posix_remove_stale(dir, removed, err, errsz);
}
am_status am_port_list_dir(const char* dir, char* names, long cap, int* count, char* err, int errsz)
{
    return am_posix_list_dir(dir, names, cap, count, err, errsz);
}

int am_port_cores(void) { return am_posix_cores(); }
int am_port_processes(void) { return am_posix_processes(); }
am_status am_port_parallel_map(int n, int workers, am_port_task task, void* ctx, void* out, long size, char* err, int errsz)
{
    return am_posix_parallel_map(n, workers, task, ctx, out, size, err, errsz);
}

void am_port_catch_interrupt(void) { am_posix_catch_interrupt(); }
int am_port_interrupted(void) { return am_posix_interrupted(); }

am_status am_port_lock(const char* path, char* err, int errsz) { return am_posix_lock(path, err, errsz); }
void am_port_lock_stamp(void) { am_posix_lock_stamp(); }
void am_port_unlock(void) { am_posix_unlock(); }

const char* am_port_getenv(const char* name) { return am_posix_getenv(name); }
void am_port_raise(am_port_signal sig) { am_posix_raise(sig); }
