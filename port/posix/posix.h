/* port/posix/posix.h: the POSIX port's functions (posix.c), one per function of the contract
 * (port.h), named am_posix_* instead of am_port_*. port_posix.c is the contract over them (each
 * am_port_X calls am_posix_X); port/mpi is the POSIX port seen from rank 0: port_mpi.c takes
 * port_posix.c's place in the MPI build, and each of its functions calls the one here, on rank 0
 * or on every process, and adds what several processes need. */
#ifndef AMORPH_PORT_POSIX_H
#define AMORPH_PORT_POSIX_H

#include "port.h"

void am_posix_start(int* argc, char*** argv);
int am_posix_end(int status);
double am_posix_now(void);
void am_posix_out(const char* text);
void am_posix_err(const char* text);
int am_posix_is_terminal(void);
void am_posix_progress(const char* line);
am_status am_posix_read_file(const char* path, char* buf, long cap, long* len, char* err, int errsz);
am_status am_posix_append_file(const char* path, const void* data, long n, char* err, int errsz);
am_status am_posix_sync_file(const char* path, char* err, int errsz);
am_status am_posix_open_write(const char* path, am_port_stream* s, char* err, int errsz);
am_status am_posix_write(am_port_stream s, const void* data, long n, char* err, int errsz);
am_status am_posix_open_read(const char* path, am_port_stream* s, char* err, int errsz);
am_status am_posix_read(am_port_stream s, void* buf, long cap, long* got, char* err, int errsz);
am_status am_posix_close(am_port_stream s, int commit, char* err, int errsz);
am_status am_posix_make_dir(const char* path, char* err, int errsz);
int am_posix_exists(const char* path);
am_status am_posix_remove_stale(const char* dir, int* removed, char* err, int errsz);
am_status am_posix_list_dir(const char* dir, char* names, long cap, int* count, char* err, int errsz);
int am_posix_cores(void);
int am_posix_processes(void);
am_status am_posix_parallel_map(int n, int workers, am_port_task task, void* ctx, void* out, long size, char* err, int errsz);
void am_posix_catch_interrupt(void);
int am_posix_interrupted(void);
am_status am_posix_lock(const char* path, char* err, int errsz);
void am_posix_unlock(void);
void am_posix_lock_stamp(void);
const char* am_posix_getenv(const char* name);
void am_posix_raise(am_port_signal sig);

#endif
