/* Status messages into caller buffers, and the AM_CHECKS build's default check handler. */
#include "amorph/base.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

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

const char* am_quote(char* out, int cap, const char* s, long n)
{
    static const char hex[] = "0123456789abcdef";
    if (!out || cap < 1) return "";
    if (!s) n = 0;
    int len = 0, keep = 0, cut = 0; /* keep: the length after the last escape that leaves room for "..." */
    for (long i = 0; n < 0 ? s[i] != 0 : i < n; i++) {
        if (i == AM_QUOTE_MAX) {
            cut = 1;
            break;
        }
        /* the byte's escape: itself, \c or \xNN */
        unsigned char u = (unsigned char)s[i];
        char e[4];
        int k = 2;
        e[0] = '\\';
        if (u == '\\' || u == '\'') e[1] = (char)u;
        else if (u == '\n') e[1] = 'n';
        else if (u == '\t') e[1] = 't';
        else if (u == '\r') e[1] = 'r';
        else if (u < 0x20 || u >= 0x7f) {
            e[1] = 'x';
            e[2] = hex[u >> 4];
            e[3] = hex[u & 15];
            k = 4;
        } else {
            e[0] = (char)u;
            k = 1;
        }
        if (len + k + 1 > cap) {
            cut = 1;
            break;
        }
        memcpy(out + len, e, (size_t)k);
        len += k;
        if (len + 4 <= cap) keep = len;
    }
    if (cut) {
        len = keep;
        if (len + 4 <= cap) {
            memcpy(out + len, "...", 3);
            len += 3;
        }
    }
    out[len] = 0;
    return out;
}

#if defined(AM_CHECKS)
#include <stdlib.h>
void am_check_failed(const char* file, int line, const char* msg)
{
    fprintf(stderr, "%s:%d: invariant broken: %s\n", file, line, msg);
    abort();
}
#endif
