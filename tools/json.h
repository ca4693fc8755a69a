/* tools/json.h: a minimal strict JSON reader for the one-line objects amorph eval reads (RFC 8259
 * grammar for strings, numbers, true, false, null, objects; arrays are not read). A caller walks
 * an object with tool_json_* calls over a cursor; each returns 1 on success, 0 after writing a
 * message "column N: problem" into the cursor's err. No allocation: strings decode into the
 * caller's buffer. */
#ifndef AMORPH_TOOLS_JSON_H
#define AMORPH_TOOLS_JSON_H

#include "cmd.h"

typedef struct tool_json {
    const char* start;          /* the line (for columns in messages) */
    const char* p;              /* the next byte */
    char err[AM_ERR_MAX];       /* the message of the first failure */
} tool_json;

void tool_json_begin(tool_json* j, const char* line);
/* skips blanks; 1 when the next byte is c (and consumes it), else 0 (no message) */
int tool_json_take(tool_json* j, char c);
/* the byte c must come next (after blanks); what names the place for the message */
int tool_json_expect(tool_json* j, char c, const char* what);
/* a string into out (capacity cap, NUL-terminated, UTF-8; *len its bytes, len may be NULL): \uXXXX
 * escapes and surrogate pairs are decoded, a NUL character (\u0000) and control bytes refused */
int tool_json_string(tool_json* j, char* out, long cap, long* len);
/* a number's text as written (at most cap - 1 bytes) into out */
int tool_json_number(tool_json* j, char* out, long cap);
/* true, false or null: 1 (true), 0 (false), -1 (null) in *v */
int tool_json_literal(tool_json* j, int* v);
/* the end of the line: blanks only */
int tool_json_end(tool_json* j);
/* fails with "column N: " and the message */
int tool_json_fail(tool_json* j, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

#endif
