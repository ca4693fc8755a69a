/* Status messages into caller buffers. */
#include "amorph/status.h"

#include <stdarg.h>
#include <stdio.h>

am_status am_fail(char* err, int errsz, am_status code, const char* fmt, ...)
{
    if (err && errsz > 0) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, (size_t)errsz, fmt, ap);
        va_end(ap);
    }
    return code;
}
