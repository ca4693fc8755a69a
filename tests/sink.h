/* tests/sink.h: the far end of an am_text stream for the tests: appends what is flushed to a
 * caller's buffer, NUL-terminated, and fails (AM_ERR_IO) rather than overrun it.
 *   t_sink k = {buf, sizeof buf, 0};
 *   am_text out = {piece, sizeof piece, 0, 0, t_sink_flush, &k, 0};
 * After am_text_flush, k.n bytes of buf hold the text. */
#ifndef AMORPH_TEST_SINK_H
#define AMORPH_TEST_SINK_H

#include <string.h>
#include "amorph/base.h"

typedef struct t_sink {
    char* buf;
    long cap; /* bytes of buf, including the NUL */
    long n;   /* bytes received */
} t_sink;

static am_status t_sink_flush(void* ctx, const char* data, long n)
{
    t_sink* k = (t_sink*)ctx;
    if (k->n + n >= k->cap) return AM_ERR_IO;
    memcpy(k->buf + k->n, data, (size_t)n);
    k->n += n;
    k->buf[k->n] = 0;
    return AM_OK;
}

#endif
