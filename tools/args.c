/* Strict parsing of command-line values, shared by every subcommand: the whole token must be the
 * number (no blanks, no sign where none is allowed, no trailing text), and it must lie in range. */
#include "cmd.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int tool_usage_error(const char* fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("amorph: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    return 2;
}

int tool_unknown_option(const char* cmd, const char* arg)
{
    char q[AM_QUOTE_BUF];
    return tool_usage_error("%s: unknown option '%s' (amorph %s --help)", cmd, am_quote(q, sizeof q, arg, -1), cmd);
}

int tool_not_in_build(const char* what, const char* feature)
{
    return tool_usage_error("%s: not in this build: %s belong to the desktop profile (make PROFILE=desktop)", what, feature);
}

int tool_parse_u64(const char* s, uint64_t* out)
{
    uint64_t v = 0;
    if (!s || !*s) return 0;
    for (; *s; s++) {
        if (*s < '0' || *s > '9') return 0;
        uint64_t d = (uint64_t)(*s - '0');
        if (v > (UINT64_MAX - d) / 10) return 0;
        v = v * 10 + d;
    }
    *out = v;
    return 1;
}

int tool_parse_long(const char* s, long lo, long hi, long* out)
{
    uint64_t mag;
    int neg = s && *s == '-';
    if (!s || !tool_parse_u64(s + neg, &mag) || mag > (uint64_t)1 << 62) return 0;
    long v = neg ? -(long)mag : (long)mag;
    if (v < lo || v > hi) return 0;
    *out = v;
    return 1;
}

int tool_parse_int(const char* s, int lo, int hi, int* out)
{
    long v;
    if (!tool_parse_long(s, lo, hi, &v)) return 0;
    *out = (int)v;
    return 1;
}

int tool_parse_real(const char* s, double lo, double hi, double* out)
{
    char* end;
    if (!s || !*s || *s == ' ' || *s == '\t') return 0;
    double v = strtod(s, &end);
    if (*end || !(v >= lo && v <= hi)) return 0; /* NaN fails the range test */
    *out = v;
    return 1;
}

int tool_parse_onoff(const char* s, int* out)
{
    if (s && !strcmp(s, "on")) *out = 1;
    else if (s && !strcmp(s, "off")) *out = 0;
    else return 0;
    return 1;
}
