/* The bounded text buffer of include/amorph/text.h. */
#include "amorph/text.h"

#include <stdarg.h>
#include <stdio.h>

void am_text_put(am_text* t, const char* fmt, ...)
{
    if (t->full) return;
    long room = t->cap - t->len;
    if (room <= 0) {
        t->full = 1;
        return;
    }
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(t->buf + t->len, (size_t)room, fmt, ap);
    va_end(ap);
    if (n < 0 || (long)n >= room) {
        t->full = 1;
        t->buf[t->len] = 0;
        return;
    }
    t->len += n;
}
