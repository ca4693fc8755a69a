/* port/mpi/posix_base.c: the POSIX port (port/posix/port_posix.c, unchanged) compiled with its
 * contract functions named am_posix_* (posix_base.h), for port_mpi.c to call. */
#define _POSIX_C_SOURCE 200809L
#define _FILE_OFFSET_BITS 64
#include "posix_base.h"

#define am_port_start am_posix_start
#define am_port_end am_posix_end
#define am_port_now am_posix_now
#define am_port_out am_posix_out
#define am_port_err am_posix_err
#define am_port_is_terminal am_posix_is_terminal
#define am_port_progress am_posix_progress
#define am_port_read_file am_posix_read_file
#define am_port_append_file am_posix_append_file
#define am_port_open_write am_posix_open_write
#define am_port_write am_posix_write
#define am_port_open_read am_posix_open_read
#define am_port_read am_posix_read
#define am_port_close am_posix_close
#define am_port_make_dir am_posix_make_dir
#define am_port_exists am_posix_exists
#define am_port_remove_stale am_posix_remove_stale
#define am_port_list_dir am_posix_list_dir
#define am_port_cores am_posix_cores
#define am_port_processes am_posix_processes
#define am_port_parallel_map am_posix_parallel_map
#define am_port_catch_interrupt am_posix_catch_interrupt
#define am_port_interrupted am_posix_interrupted
#define am_port_lock am_posix_lock
#define am_port_unlock am_posix_unlock
#define am_port_lock_stamp am_posix_lock_stamp
#define am_port_getenv am_posix_getenv
#define am_port_raise am_posix_raise

#include "../posix/port_posix.c"
