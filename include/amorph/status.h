/* amorph/status.h: status codes. Functions that can fail return am_status and write a one-line,
 * human-readable message (for files: "file:line: problem") into a caller's buffer. */
#ifndef AMORPH_STATUS_H
#define AMORPH_STATUS_H

#include <stdarg.h>

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

#endif
