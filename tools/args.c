/* Messages, and command-line values: the library's strict number parsers (amorph/base.h) with a
 * range, shared by every subcommand. */
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

int tool_parse_long(const char* s, long lo, long hi, long* out)
{
    long v;
    if (!am_parse_long(s, &v) || v < lo || v > hi) return 0;
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
    double v;
    if (!am_parse_double(s, &v) || !(v >= lo && v <= hi)) return 0;
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
