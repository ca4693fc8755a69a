/* amorph/port.h: the porting layer. The library in src/ never calls the OS; programs and the
 * evolver reach the platform only through these functions, implemented once per platform in
 * port/<name>/ (port/posix today). */
#ifndef AMORPH_PORT_H
#define AMORPH_PORT_H

#include "amorph/status.h"

/* monotonic wall clock, seconds */
double am_port_now(void);
/* reads the whole file path into buf (capacity cap) and NUL-terminates it; *len gets its length.
 * AM_ERR_IO if unreadable, AM_ERR_CAPACITY if larger than cap - 1. */
am_status am_port_read_file(const char* path, char* buf, long cap, long* len, char* err, int errsz);
/* writes n bytes to path atomically (a temporary file beside it, then rename) */
am_status am_port_write_file(const char* path, const void* data, long n, char* err, int errsz);
/* number of processor cores available */
int am_port_cores(void);

#endif
