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

/* the edit distance (insertions, deletions, substitutions) between a[0..n) and b[0..m), '-' and
 * '_' alike, both at most 63 bytes */
static int edit_distance(const char* a, int n, const char* b, int m)
{
    int row[64];
    for (int j = 0; j <= m; j++) row[j] = j;
    for (int i = 1; i <= n; i++) {
        int diag = row[0];
        row[0] = i;
        for (int j = 1; j <= m; j++) {
            const char x = a[i - 1] == '-' ? '_' : a[i - 1], y = b[j - 1] == '-' ? '_' : b[j - 1];
            const int best = diag + (x != y), up = row[j] + 1, left = row[j - 1] + 1;
            diag = row[j];
            row[j] = best < up ? (best < left ? best : left) : (up < left ? up : left);
        }
    }
    return row[m];
}

/* the flag of help (each "--name" it writes, and the configuration's keys when help sends the
 * reader to --help-config) nearest to arg's name, within a third of its length (at least 1): its
 * name's start in *at and its length, 0 when none is that near */
static int nearest_flag(const char* arg, const char* help, const char** at)
{
    const char* name = arg;
    while (*name == '-') name++;
    int n = 0;
    while (name[n] && name[n] != '=' && n < 63) n++;
    if (n == 0 || n >= 63 || !help) return 0;
    const int most = n / 3 > 1 ? n / 3 : 1;
    int best = most + 1, len = 0;
    for (const char* p = help; (p = strstr(p, "--")) != NULL;) {
        p += 2;
        int k = 0;
        while ((p[k] >= 'a' && p[k] <= 'z') || (p[k] >= '0' && p[k] <= '9') || ((p[k] == '-' || p[k] == '_') && k > 0)) k++;
        if (k > 0 && k < 64) {
            const int d = edit_distance(name, n, p, k);
            if (d < best && d > 0) best = d, *at = p, len = k;
        }
    }
    for (int i = 0; strstr(help, "help-config") && i < am_evo_key_count(); i++) {
        const char* key = am_evo_key_name(i);
        const int k = (int)strlen(key);
        const int d = k < 64 ? edit_distance(name, n, key, k) : best;
        if (d < best && d > 0) best = d, *at = key, len = k;
    }
    return best <= most ? len : 0;
}

int tool_unknown_option(const char* cmd, const char* arg, const char* help)
{
    char q[AM_QUOTE_BUF];
    const char* at = NULL;
    const int len = arg[0] == '-' ? nearest_flag(arg, help, &at) : 0;
    if (len > 0)
        return tool_usage_error("%s: unknown option '%s': did you mean --%.*s? (amorph %s --help)", cmd, am_quote(q, sizeof q, arg, -1), len, at,
                                cmd);
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
