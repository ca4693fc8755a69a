/* Results as "key = value" lines or as one JSON object: one list of fields, two spellings. */
#include "cmd.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void tool_json_escape(char* out, size_t cap, const char* in)
{
    size_t n = 0;
    if (cap == 0) return;
    for (; *in && n + 7 < cap; in++) {
        unsigned char c = (unsigned char)*in;
        if (c == '"' || c == '\\') {
            out[n++] = '\\';
            out[n++] = (char)c;
        } else if (c < 32 || c == 127) n += (size_t)snprintf(out + n, cap - n, "\\u%04x", c);
        else out[n++] = (char)c;
    }
    out[n] = 0;
}

void tool_rec_begin(tool_rec* r, am_text* t, int json)
{
    r->t = t;
    r->json = json;
    r->n = 0;
    r->eq = " = ";
    if (json) am_text_put(t, "{");
}

void tool_rec_begin_tight(tool_rec* r, am_text* t)
{
    tool_rec_begin(r, t, 0);
    r->eq = "=";
}

/* the key: "key = " or ", \"key\": " */
static void key(tool_rec* r, const char* k)
{
    if (r->json) am_text_put(r->t, "%s\"%s\": ", r->n ? ", " : "", k);
    else am_text_put(r->t, "%s%s", k, r->eq);
    r->n++;
}

static void end_field(tool_rec* r)
{
    if (!r->json) am_text_write(r->t, "\n", 1);
}

/* a number: %.9g, or null in JSON when it is not finite */
static void num(tool_rec* r, double v)
{
    if (r->json && !isfinite(v)) am_text_put(r->t, "null");
    else am_text_put(r->t, "%.9g", v);
}

void tool_rec_num(tool_rec* r, const char* k, double v)
{
    key(r, k);
    num(r, v);
    end_field(r);
}

void tool_rec_int(tool_rec* r, const char* k, long v)
{
    key(r, k);
    am_text_put(r->t, "%ld", v);
    end_field(r);
}

void tool_rec_str(tool_rec* r, const char* k, const char* v)
{
    key(r, k);
    if (r->json) {
        char esc[TOOL_PATH_MAX * 2];
        tool_json_escape(esc, sizeof esc, v);
        am_text_put(r->t, "\"%s\"", esc);
    } else am_text_put(r->t, "%s", v);
    end_field(r);
}

void tool_rec_hex(tool_rec* r, const char* k, uint64_t v)
{
    char h[24];
    snprintf(h, sizeof h, "%016llx", (unsigned long long)v);
    tool_rec_str(r, k, h);
}

void tool_rec_nums(tool_rec* r, const char* k, const double* v, int n)
{
    key(r, k);
    if (r->json) am_text_put(r->t, "[");
    for (int i = 0; i < n; i++) {
        if (i) am_text_put(r->t, r->json ? ", " : " ");
        num(r, v[i]);
    }
    if (r->json) am_text_put(r->t, "]");
    end_field(r);
}

void tool_rec_strs(tool_rec* r, const char* k, const char* const* v, int n)
{
    key(r, k);
    if (r->json) am_text_put(r->t, "[");
    for (int i = 0; i < n; i++) {
        if (r->json) {
            char esc[256];
            tool_json_escape(esc, sizeof esc, v[i]);
            am_text_put(r->t, "%s\"%s\"", i ? ", " : "", esc);
        } else am_text_put(r->t, "%s%s", i ? " " : "", v[i]);
    }
    if (r->json) am_text_put(r->t, "]");
    end_field(r);
}

void tool_rec_end(tool_rec* r)
{
    if (r->json) am_text_put(r->t, "}\n");
}
