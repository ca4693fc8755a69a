/* A minimal strict JSON reader (tools/json.h): a cursor over one line, what amorph eval needs. */
#include "json.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void tool_json_begin(tool_json* j, const char* line)
{
    j->start = j->p = line;
    j->err[0] = 0;
}

int tool_json_fail(tool_json* j, const char* fmt, ...)
{
    int n = snprintf(j->err, sizeof j->err, "column %ld: ", (long)(j->p - j->start) + 1);
    va_list ap;
    va_start(ap, fmt);
    if (n > 0 && n < (int)sizeof j->err) vsnprintf(j->err + n, sizeof j->err - (size_t)n, fmt, ap);
    va_end(ap);
    return 0;
}

static void blanks(tool_json* j)
{
    while (*j->p == ' ' || *j->p == '\t' || *j->p == '\r') j->p++;
}

/* what stands at the cursor, for a message: the byte, or "the end of the line" */
static const char* here(const tool_json* j, char buf[16])
{
    const unsigned char c = (unsigned char)*j->p;
    if (!c) return "the end of the line";
    if (c >= 0x20 && c < 0x7f) snprintf(buf, 16, "'%c'", (char)c);
    else snprintf(buf, 16, "byte 0x%02x", c);
    return buf;
}

int tool_json_take(tool_json* j, char c)
{
    blanks(j);
    if (*j->p != c) return 0;
    j->p++;
    return 1;
}

int tool_json_expect(tool_json* j, char c, const char* what)
{
    if (tool_json_take(j, c)) return 1;
    char b[16];
    return tool_json_fail(j, "expected '%c' %s, found %s", c, what, here(j, b));
}

static int hex4(const char* s, unsigned* v)
{
    *v = 0;
    for (int i = 0; i < 4; i++) {
        const char c = s[i];
        int d = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
        if (d < 0) return 0;
        *v = *v * 16 + (unsigned)d;
    }
    return 1;
}

/* code point u as UTF-8 at out + *n (room checked by the caller: 4 bytes) */
static void utf8(char* out, long* n, unsigned u)
{
    if (u < 0x80) out[(*n)++] = (char)u;
    else if (u < 0x800) {
        out[(*n)++] = (char)(0xc0 | (u >> 6));
        out[(*n)++] = (char)(0x80 | (u & 0x3f));
    } else if (u < 0x10000) {
        out[(*n)++] = (char)(0xe0 | (u >> 12));
        out[(*n)++] = (char)(0x80 | ((u >> 6) & 0x3f));
        out[(*n)++] = (char)(0x80 | (u & 0x3f));
    } else {
        out[(*n)++] = (char)(0xf0 | (u >> 18));
        out[(*n)++] = (char)(0x80 | ((u >> 12) & 0x3f));
        out[(*n)++] = (char)(0x80 | ((u >> 6) & 0x3f));
        out[(*n)++] = (char)(0x80 | (u & 0x3f));
    }
}

int tool_json_string(tool_json* j, char* out, long cap, long* len)
{
    char b[16];
    blanks(j);
    if (*j->p != '"') return tool_json_fail(j, "expected a string, found %s", here(j, b));
    j->p++;
    long n = 0;
    for (;;) {
        const unsigned char c = (unsigned char)*j->p;
        if (c == '"') break;
        if (!c) return tool_json_fail(j, "a string not closed before the end of the line");
        if (c < 0x20) return tool_json_fail(j, "a control byte (0x%02x) in a string: write it as an escape", c);
        if (n + 5 > cap) return tool_json_fail(j, "a string longer than %ld bytes", cap - 5);
        if (c != '\\') {
            out[n++] = (char)c;
            j->p++;
            continue;
        }
        const char e = j->p[1];
        char d = 0;
        switch (e) {
        case '"': case '\\': case '/': d = e; break;
        case 'b': d = '\b'; break;
        case 'f': d = '\f'; break;
        case 'n': d = '\n'; break;
        case 'r': d = '\r'; break;
        case 't': d = '\t'; break;
        default: break;
        }
        if (d) {
            out[n++] = d;
            j->p += 2;
            continue;
        }
        if (e != 'u') return tool_json_fail(j, "an unknown escape '\\%c' in a string", e > 0x20 && e < 0x7f ? e : '?');
        unsigned u, lo;
        if (!hex4(j->p + 2, &u)) return tool_json_fail(j, "\\u needs four hex digits");
        j->p += 6;
        if (u >= 0xd800 && u < 0xdc00) {
            if (j->p[0] != '\\' || j->p[1] != 'u' || !hex4(j->p + 2, &lo) || lo < 0xdc00 || lo >= 0xe000)
                return tool_json_fail(j, "a high surrogate \\u%04x without its low surrogate", u);
            u = 0x10000 + ((u - 0xd800) << 10) + (lo - 0xdc00);
            j->p += 6;
        } else if (u >= 0xdc00 && u < 0xe000) return tool_json_fail(j, "a lone low surrogate \\u%04x", u);
        if (u == 0) return tool_json_fail(j, "a NUL character (\\u0000) in a string");
        utf8(out, &n, u);
    }
    j->p++;
    out[n] = 0;
    if (len) *len = n;
    return 1;
}

int tool_json_number(tool_json* j, char* out, long cap)
{
    char b[16];
    blanks(j);
    const char* s = j->p;
    const char* p = s;
    if (*p == '-') p++;
    if (*p == '0') p++;
    else if (*p >= '1' && *p <= '9')
        while (*p >= '0' && *p <= '9') p++;
    else return tool_json_fail(j, "expected a number, found %s", here(j, b));
    if (*p == '.') {
        p++;
        if (!(*p >= '0' && *p <= '9')) return tool_json_fail(j, "a number needs digits after its '.'");
        while (*p >= '0' && *p <= '9') p++;
    }
    if (*p == 'e' || *p == 'E') {
        p++;
        if (*p == '+' || *p == '-') p++;
        if (!(*p >= '0' && *p <= '9')) return tool_json_fail(j, "a number needs digits in its exponent");
        while (*p >= '0' && *p <= '9') p++;
    }
    if (p - s >= cap) return tool_json_fail(j, "a number longer than %ld characters", cap - 1);
    memcpy(out, s, (size_t)(p - s));
    out[p - s] = 0;
    j->p = p;
    return 1;
}

int tool_json_literal(tool_json* j, int* v)
{
    char b[16];
    blanks(j);
    static const char* const words[] = {"null", "false", "true"};
    for (int k = 0; k < 3; k++) {
        size_t n = strlen(words[k]);
        if (!strncmp(j->p, words[k], n)) {
            j->p += n;
            *v = k - 1;
            return 1;
        }
    }
    return tool_json_fail(j, "expected true, false or null, found %s", here(j, b));
}

int tool_json_end(tool_json* j)
{
    char b[16];
    blanks(j);
    if (*j->p) return tool_json_fail(j, "%s after the object (one object per line)", here(j, b));
    return 1;
}
