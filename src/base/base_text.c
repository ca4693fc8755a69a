/* The bounded text buffer of include/amorph/base.h, and the strict number parsers. */
#include "amorph/base.h"

#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* hands the buffer to flush and empties it; 0, or -1 (full 2) when flush failed */
static int drain(am_text* t)
{
    if (t->len > 0) {
        if (t->flush(t->ctx, t->buf, t->len) != AM_OK) {
            t->full = 2;
            t->buf[0] = 0;
            t->len = 0;
            return -1;
        }
        t->done += t->len;
        t->len = 0;
        t->buf[0] = 0;
    }
    return 0;
}

void am_text_vput(am_text* t, const char* fmt, va_list ap)
{
    if (t->full) return;
    long room = t->cap - t->len;
    if (room <= 0) {
        t->full = 1;
        return;
    }
    va_list again;
    va_copy(again, ap);
    int n = vsnprintf(t->buf + t->len, (size_t)room, fmt, ap);
    if (n >= 0 && (long)n < room) {
        t->len += n;
    } else {
        t->buf[t->len] = 0;
        /* streaming: empty the buffer into the stream and format the piece again at its start */
        if (n >= 0 && t->flush && (long)n < t->cap && drain(t) == 0) {
            vsnprintf(t->buf, (size_t)t->cap, fmt, again);
            t->len = n;
        } else if (!t->full) {
            t->full = 1;
        }
    }
    va_end(again);
}

void am_text_put(am_text* t, const char* fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    am_text_vput(t, fmt, ap);
    va_end(ap);
}

void am_text_write(am_text* t, const char* data, long n)
{
    while (!t->full && n > 0) {
        long room = t->cap - 1 - t->len;
        if (room <= 0) {
            if (!t->flush || t->cap < 2) {
                t->full = 1;
                return;
            }
            if (drain(t) != 0) return;
            continue;
        }
        if (!t->flush && n > room) {
            t->full = 1; /* a whole-text buffer takes a piece whole or not at all */
            return;
        }
        long k = n < room ? n : room;
        AM_ASSERT(t->len >= 0 && t->len + k < t->cap); /* the piece and its NUL fit */
        memcpy(t->buf + t->len, data, (size_t)k);
        t->len += k;
        t->buf[t->len] = 0;
        data += k;
        n -= k;
    }
}

am_status am_text_flush(am_text* t)
{
    if (!t->full && t->flush) drain(t);
    if (t->full == 2) return AM_ERR_IO;
    return t->full ? AM_ERR_CAPACITY : AM_OK;
}

am_status am_text_drop(void* ctx, const char* data, long n)
{
    (void)ctx, (void)data, (void)n;
    return AM_OK;
}

am_status am_text_format(am_text_writer write, const void* ctx, const char* what, char* buf, long cap, long* len,
                         char* err, int errsz)
{
    am_text t = {buf, cap, 0, 0, NULL, NULL, 0};
    if (len) *len = 0;
    if (!buf || cap < 1) return am_fail(err, errsz, AM_ERR_CAPACITY, "%s: no buffer", what);
    buf[0] = 0;
    am_status st = write(ctx, &t, err, errsz);
    if (len) *len = t.len;
    if (st == AM_ERR_CAPACITY && t.full) {
        /* the length it needs: the text again through a counting stream (a piece must fit) */
        char piece[320];
        am_text c = {piece, sizeof piece, 0, 0, am_text_drop, NULL, 0};
        write(ctx, &c, NULL, 0);
        if (len) *len = c.done + c.len;
        return am_fail(err, errsz, st, "%s needs %ld bytes, the buffer holds %ld", what, c.done + c.len + 1, cap);
    }
    return st;
}

/* ---- strict numbers ---- */

int am_parse_long(const char* s, long* out)
{
    int neg = 0;
    long v = 0;
    if (!s) return 0;
    if (*s == '-') {
        neg = 1;
        s++;
    }
    if (!*s) return 0;
    for (; *s; s++) {
        if (*s < '0' || *s > '9') return 0;
        if (v > (LONG_MAX - 9) / 10) return 0;
        v = v * 10 + (*s - '0');
    }
    *out = neg ? -v : v;
    return 1;
}

int am_parse_u64(const char* s, uint64_t* out)
{
    uint64_t v = 0;
    if (!s || !*s) return 0;
    for (; *s; s++) {
        if (*s < '0' || *s > '9') return 0;
        unsigned dgt = (unsigned)(*s - '0');
        if (v > (UINT64_MAX - dgt) / 10) return 0;
        v = v * 10 + dgt;
    }
    *out = v;
    return 1;
}

int am_parse_double(const char* s, double* out)
{
    char* end = NULL;
    if (!s || !*s || *s == ' ' || *s == '\t' || *s == '+') return 0;
    double v = strtod(s, &end);
    if (!end || *end || !(v == v) || v > 1e300 || v < -1e300) return 0;
    *out = v;
    return 1;
}

/* ---- the temporaries of atomic writes ---- */

long am_temp_name_pid(const char* name)
{
    const char* t = NULL;
    for (const char* p = strstr(name, ".tmp."); p; p = strstr(p + 1, ".tmp.")) t = p;
    if (!t || t == name) return -1;
    const char* p = t + 5;
    size_t digits = strspn(p, "0123456789");
    if (digits == 0) return -1;
    /* NAME.tmp.PID, or NAME.tmp.PID.NONCE (1 to 16 lowercase hex digits) */
    if (p[digits] == '.') {
        size_t hex = strspn(p + digits + 1, "0123456789abcdef");
        if (hex == 0 || hex > 16 || p[digits + 1 + hex] != 0) return -1;
    } else if (p[digits] != 0) {
        return -1;
    }
    long pid = 0;
    /* a number past 2 * 10^9 (past a 32-bit long) is no process's: a stranger's */
    for (size_t k = 0; k < digits; k++) pid = pid < 200000000L ? pid * 10 + (p[k] - '0') : 2000000000L;
    return pid;
}
