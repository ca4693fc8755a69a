/* amorph/text.h: a bounded text buffer for the writers of every format (lattice, VXA, SVG, HTML).
 * Appending never writes past cap: text that does not fit sets `full`, keeps what was written
 * NUL-terminated, and every later append is dropped, so a writer checks once at the end. */
#ifndef AMORPH_TEXT_H
#define AMORPH_TEXT_H

typedef struct am_text {
    char* buf;   /* output (cap bytes) */
    long cap;    /* capacity, including the NUL */
    long len;    /* characters written */
    int full;    /* 1 once something did not fit */
} am_text;

/* appends printf-style text */
void am_text_put(am_text* t, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

#endif
