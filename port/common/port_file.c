/* The parts of the porting layer's contract (port/port.h) that every port would write
 * the same way, written once here over the port's own functions. */
#include <stddef.h>
#include "port.h"

/* one write of a stream: the stream's atomic replace makes the whole file appear at once */
am_status am_port_write_file(const char* path, const void* data, long n, char* err, int errsz)
{
    am_port_stream s;
    am_status st = am_port_open_write(path, &s, err, errsz);
    if (st != AM_OK) return st;
    st = am_port_write(s, data, n, err, errsz);
    if (st != AM_OK) {
        am_port_close(s, 0, NULL, 0);
        return st;
    }
    return am_port_close(s, 1, err, errsz);
}
