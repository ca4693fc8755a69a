/* amorph/text.h: the bounded text buffer every writer formats into (genome, lattice, configuration,
 * checkpoint, VXA, SVG, HTML).
 *
 * Appending never writes past cap. Without a flush function the buffer holds the whole text: text
 * that does not fit sets `full`, keeps what was written NUL-terminated, and every later append is
 * dropped, so a writer checks once at the end. With a flush function the buffer is a window of a
 * stream: when a piece does not fit, the buffered bytes are handed to flush (which writes them to
 * a file, say) and the buffer starts again, so a text of any length goes through a small buffer;
 * `full` is then set only when flush fails or one piece is longer than the buffer. */
#ifndef AMORPH_TEXT_H
#define AMORPH_TEXT_H

#include <stdint.h>

#include "amorph/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct am_text {
    char* buf;   /* output (cap bytes) */
    long cap;    /* capacity, including the NUL */
    long len;    /* characters in buf */
    int full;    /* 0; 1 once something did not fit; 2 once a flush failed */
    /* streaming (optional, NULL for a whole-text buffer): receives the n buffered bytes at data;
     * AM_OK, or a failure that sets full (the flush function keeps its own message) */
    am_status (*flush)(void* ctx, const char* data, long n);
    void* ctx;   /* the flush function's context */
    long done;   /* bytes handed to flush so far (the text's length is done + len) */
} am_text;

/* appends printf-style text */
void am_text_put(am_text* t, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* the va_list form, for the writers' own variadic helpers */
void am_text_vput(am_text* t, const char* fmt, va_list ap)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 0)))
#endif
    ;
/* appends n bytes of data (no NUL inside) */
void am_text_write(am_text* t, const char* data, long n);
/* a flush function that drops the text: a stream through it only counts (done + len is the length) */
am_status am_text_drop(void* ctx, const char* data, long n);
/* a writer of a whole text: formats ctx into out (the genome, configuration and checkpoint
 * writers behind one of these) */
typedef am_status (*am_text_writer)(const void* ctx, am_text* out, char* err, int errsz);
/* writes ctx into buf (capacity cap, NUL-terminated) as one whole text; *len (may be NULL) gets
 * its length. When it does not fit, writes it again through a counting stream and fails with
 * "WHAT needs N bytes, the buffer holds CAP" (AM_ERR_CAPACITY), *len then the length needed. */
am_status am_text_format(am_text_writer write, const void* ctx, const char* what, char* buf, long cap, long* len,
                         char* err, int errsz);
/* hands the buffered bytes to flush (a whole-text buffer keeps them). AM_OK while nothing was
 * dropped, else AM_ERR_CAPACITY (full 1) or AM_ERR_IO (full 2: the flush function's message) */
am_status am_text_flush(am_text* t);

/* Strict numbers, as every reader and command-line flag takes them: the whole token is the number
 * (no blank, no '+', nothing after it); 1 with *out set, else 0 (NULL counts as no number).
 * am_parse_long: decimal digits after an optional '-', within long. am_parse_u64: decimal digits
 * only, within 64 bits. am_parse_double: strtod's syntax, finite, and within +-1e300. */
int am_parse_long(const char* s, long* out);
int am_parse_u64(const char* s, uint64_t* out);
int am_parse_double(const char* s, double* out);

/* the process id in an atomic write's temporary file name, NAME.tmp.PID.NONCE as the POSIX and
 * Windows ports name them (NAME not empty, PID decimal digits, NONCE 1 to 16 lowercase hex digits)
 * or NAME.tmp.PID as builds before them did; -1 for any other name. A PID of 2 * 10^9 or more
 * reads as 2 * 10^9. The ports' am_port_remove_stale removes the files so named. */
long am_temp_name_pid(const char* name);

#ifdef __cplusplus
}
#endif
#endif
