/* Status messages into caller buffers. */
#include "amorph/status.h"

#include <stdarg.h>
#include <stdio.h>

const char* am_status_name(am_status code)
{
    static const char* const names[] = {"ok", "parse", "range", "capacity", "io", "empty", "arg", "cancelled"};
    unsigned k = (unsigned)code;
    return k < sizeof names / sizeof names[0] ? names[k] : "unknown";
}

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

am_status am_vfail_at(char* err, int errsz, am_status code, const char* fname, int line, const char* fmt, va_list ap)
{
    if (err && errsz > 0) {
        int n = snprintf(err, (size_t)errsz, "%s:%d: ", fname, line);
        if (n >= 0 && n < errsz) vsnprintf(err + n, (size_t)(errsz - n), fmt, ap);
    }
    return code;
}

am_status am_fail_at(char* err, int errsz, am_status code, const char* fname, int line, const char* fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    am_vfail_at(err, errsz, code, fname, line, fmt, ap);
    va_end(ap);
    return code;
}
