/* amorph/status.h: status codes. Functions that can fail return am_status and write a one-line,
 * human-readable message (for files: "file:line: problem") into a caller's buffer; a piece of input
 * in a message goes through am_quote (below). */
#ifndef AMORPH_STATUS_H
#define AMORPH_STATUS_H

#include <stdarg.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum am_status {
    AM_OK = 0,
    AM_ERR_PARSE,      /* malformed input text */
    AM_ERR_RANGE,      /* a value outside its allowed range */
    AM_ERR_CAPACITY,   /* a compile-time capacity would be exceeded */
    AM_ERR_IO,         /* a file could not be read or written */
    AM_ERR_EMPTY,      /* nothing to simulate (no voxel) */
    AM_ERR_ARG,        /* a bad argument from the caller */
    AM_ERR_CANCELLED   /* the caller asked to stop (a cancel callback returned non-zero) */
} am_status;

/* the code's name ("ok", "parse", "range", "capacity", "io", "empty", "arg", "cancelled";
 * "unknown" for any other value) */
const char* am_status_name(am_status code);

/* writes "fmt" into err (size errsz, may be 0) like snprintf and returns code */
am_status am_fail(char* err, int errsz, am_status code, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* "fname:line: " followed by fmt into err, like am_fail: the one form of every file message.
 * The va_list form serves the parsers' own variadic wrappers. */
am_status am_vfail_at(char* err, int errsz, am_status code, const char* fname, int line, const char* fmt, va_list ap)
#if defined(__GNUC__)
    __attribute__((format(printf, 6, 0)))
#endif
    ;
am_status am_fail_at(char* err, int errsz, am_status code, const char* fname, int line, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 6, 7)))
#endif
    ;

/* ---- input quoted in messages ----
 * am_quote writes the input token s (its first n bytes; n < 0: up to its NUL; NULL: empty) into
 * out (capacity cap) the one way every reader quotes input in a message, "... '%s' ...":
 *   - at most AM_QUOTE_MAX (40) bytes of s are shown; when s is longer, "..." follows them;
 *   - printable ASCII (0x20..0x7e) stands for itself, except a backslash, written \\, and a single
 *     quote, written \';
 *   - newline, tab and carriage return are written \n, \t and \r; every other byte below 0x20,
 *     0x7f (DEL) and every byte from 0x80 up (so UTF-8 too) is written \xNN, two lowercase hex
 *     digits;
 * so the result is one line of printable ASCII whatever the input (the bytes ESC [ 3 1 m show as
 * \x1b[31m, the empty token as nothing). A cap of AM_QUOTE_BUF always holds the whole result; a
 * smaller cap holds whole escapes up to what fits, then "..." when that fits too. out is always
 * NUL-terminated (when cap >= 1). Returns out, or "" when out is NULL or cap < 1, for use as a
 * printf argument. */
#define AM_QUOTE_MAX 40
#define AM_QUOTE_BUF (4 * AM_QUOTE_MAX + 4) /* 40 escapes of 4 characters, "...", the NUL */
const char* am_quote(char* out, int cap, const char* s, long n);

#ifdef __cplusplus
}
#endif
#endif
