/* The lattice text format ("amorph-lattice 1"; grammar and errors in docs/formats.md).
 *
 * The parser takes one line at a time (am_lattice_read_line; am_lattice_parse splits a whole
 * NUL-terminated text at '\n' and feeds its lines) and walks it in place with pointers: a token
 * is a run of non-blank bytes in the line, so a line of any length needs no buffer and nothing is
 * copied. Numbers go through strtod/strtof/strtol, which
 * stop at the blank, '#', newline or NUL after the token; a number is accepted only when the
 * whole token was consumed and the value is finite. The lattice is filled as the text is read,
 * so on an error *lat holds a partial result and only the status and message count.
 *
 * The writer prints every real in the shortest "%g" form that reads back to the same bits (at
 * most "%.9g" for float, "%.17g" for double) and always writes the whole palette, so format-then-parse gives the same lattice bit
 * for bit. It checks the lattice first with the same rules the parser applies, so whatever it
 * writes reads back. It writes to an am_text, a whole-text buffer or a stream.
 */
#include "amorph/io.h"

#include "amorph/base.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define LAT_MAGIC "amorph-lattice"
#define LAT_VERSION 1

static const char cell_chars[] = ".123456789abcdefg"; /* cell value v is cell_chars[v] */

/* ---- scanning ---------------------------------------------------------------------------- */

typedef struct pctx {
    const char* fname;
    int line;
    char* err;
    int errsz;
} pctx;

static am_status perr(const pctx* c, am_status code, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* "fname:line: message" into the caller's buffer */
static am_status perr(const pctx* c, am_status code, const char* fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    am_vfail_at(c->err, c->errsz, code, c->fname, c->line, fmt, ap);
    va_end(ap);
    return code;
}

static int is_blank(char ch) { return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\v' || ch == '\f'; }

/* next token in [*p, end): sets [*ts, *te) and advances *p; 0 when the line has no more */
static int next_token(const char** p, const char* end, const char** ts, const char** te)
{
    const char* s = *p;
    while (s < end && is_blank(*s)) s++;
    if (s >= end) {
        *p = end;
        return 0;
    }
    const char* e = s;
    while (e < end && !is_blank(*e)) e++;
    *ts = s;
    *te = e;
    *p = e;
    return 1;
}

static int tok_is(const char* ts, const char* te, const char* word)
{
    size_t n = strlen(word);
    return (size_t)(te - ts) == n && memcmp(ts, word, n) == 0;
}

/* the token [ts, te) quoted for a message (am_quote: cut and escaped, one line) */
static const char* shown(char qb[AM_QUOTE_BUF], const char* ts, const char* te)
{
    return am_quote(qb, AM_QUOTE_BUF, ts, (long)(te - ts));
}

/* a real: the whole token must be a finite number */
static int parse_real(const char* ts, const char* te, am_param* out)
{
    char* end = NULL;
    if (ts >= te) return 0;
#if defined(AM_REAL_DOUBLE) || defined(AM_REAL_FIXED_POINT)
    am_param v = strtod(ts, &end);
#else
    am_param v = strtof(ts, &end);
#endif
    if (end != te || !am_param_finite(v)) return 0;
    *out = v;
    return 1;
}

/* a decimal integer: the whole token; values past +-1e9 are clamped to +-1e9 */
static int parse_int(const char* ts, const char* te, long* out)
{
    char* end = NULL;
    if (ts >= te) return 0;
    long v = strtol(ts, &end, 10);
    if (end != te) return 0;
    if (v > 1000000000L) v = 1000000000L;
    if (v < -1000000000L) v = -1000000000L;
    *out = v;
    return 1;
}

static int hex_digit(char ch)
{
    if (ch >= '0' && ch <= '9') return ch - '0';
    if (ch >= 'a' && ch <= 'f') return ch - 'a' + 10;
    if (ch >= 'A' && ch <= 'F') return ch - 'A' + 10;
    return -1;
}

/* #rrggbb or #rrggbbaa */
static int parse_color(const char* ts, const char* te, uint8_t rgba[4])
{
    long n = (long)(te - ts);
    if ((n != 7 && n != 9) || ts[0] != '#') return 0;
    rgba[3] = 255;
    for (int i = 0; 1 + 2 * i < n; i++) {
        int hi = hex_digit(ts[1 + 2 * i]), lo = hex_digit(ts[2 + 2 * i]);
        if (hi < 0 || lo < 0) return 0;
        rgba[i] = (uint8_t)(hi * 16 + lo);
    }
    return 1;
}

static int name_ok(const char* s, size_t n)
{
    if (n < 1 || n >= AM_NAME_MAX) return 0;
    for (size_t i = 0; i < n; i++) {
        char ch = s[i];
        if (!((ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '_' || ch == '-'))
            return 0;
    }
    return 1;
}

/* ---- materials --------------------------------------------------------------------------- */

enum { K_E, K_DENSITY, K_POISSON, K_CTE, K_PHASE, K_MU_S, K_MU_K, K_ZETA_INT, K_ZETA_GLOB, K_ZETA_COL, K_COLOR, K_FIXED, K_COUNT };
static const char* const key_names[K_COUNT] = {"E", "density", "poisson", "cte", "phase", "mu_s", "mu_k",
                                               "zeta_int", "zeta_glob", "zeta_col", "color", "fixed"};
#define KEY_LIST "E, density, poisson, cte, phase, mu_s, mu_k, zeta_int, zeta_glob, zeta_col, color, fixed"

static am_param get_real(const am_material* m, int k)
{
    switch (k) {
    case K_E: return m->E;
    case K_DENSITY: return m->density;
    case K_POISSON: return m->poisson;
    case K_CTE: return m->cte;
    case K_PHASE: return m->phase;
    case K_MU_S: return m->mu_static;
    case K_MU_K: return m->mu_kinetic;
    case K_ZETA_INT: return m->zeta_internal;
    case K_ZETA_GLOB: return m->zeta_global;
    default: return m->zeta_collision;
    }
}

static void set_real(am_material* m, int k, am_param v)
{
    switch (k) {
    case K_E: m->E = v; break;
    case K_DENSITY: m->density = v; break;
    case K_POISSON: m->poisson = v; break;
    case K_CTE: m->cte = v; break;
    case K_PHASE: m->phase = v; break;
    case K_MU_S: m->mu_static = v; break;
    case K_MU_K: m->mu_kinetic = v; break;
    case K_ZETA_INT: m->zeta_internal = v; break;
    case K_ZETA_GLOB: m->zeta_global = v; break;
    default: m->zeta_collision = v; break;
    }
}

/* the allowed range of each real key; NULL when v is allowed */
static const char* range_problem(int k, am_param v)
{
    if (!am_param_finite(v)) return "must be a finite number";
    switch (k) {
    case K_E: case K_DENSITY: return v > AM_P(0) ? NULL : "must be greater than 0";
    case K_POISSON: return v >= AM_P(0) && v < AM_P(0.5) ? NULL : "must be in [0, 0.5)";
    case K_MU_S: case K_MU_K: case K_ZETA_INT: case K_ZETA_GLOB: case K_ZETA_COL:
        return v >= AM_P(0) ? NULL : "must be 0 or more";
    default: return NULL;
    }
}

/* "material NAME key=value ...": the rest of the line after the keyword */
static am_status parse_material(const pctx* c, am_palette* pal, const char* p, const char* end)
{
    const char *ts = NULL, *te = NULL;
    char qb[AM_QUOTE_BUF];
    if (!next_token(&p, end, &ts, &te)) return perr(c, AM_ERR_PARSE, "material: expected a name after 'material'");
    if (!name_ok(ts, (size_t)(te - ts)))
        return perr(c, AM_ERR_PARSE, "material name '%s': use 1 to %d letters, digits, '_' or '-'", shown(qb, ts, te),
                    AM_NAME_MAX - 1);
    for (int i = 0; i < pal->count; i++)
        if (tok_is(ts, te, pal->mat[i].name))
            return perr(c, AM_ERR_PARSE, "material '%s' defined twice (first as id %d)", pal->mat[i].name, i + 1);
    if (pal->count >= AM_MAX_MATERIALS)
        return perr(c, AM_ERR_CAPACITY, "material '%s': more than %d materials (the palette's capacity)", shown(qb, ts, te),
                    AM_MAX_MATERIALS);
    am_material* m = &pal->mat[pal->count];
    *m = am_default_material();
    memset(m->name, 0, sizeof m->name);
    memcpy(m->name, ts, (size_t)(te - ts));
    int seen[K_COUNT] = {0};
    while (next_token(&p, end, &ts, &te)) {
        const char* eq = memchr(ts, '=', (size_t)(te - ts));
        if (!eq) return perr(c, AM_ERR_PARSE, "material '%s': expected key=value, found '%s'", m->name, shown(qb, ts, te));
        int k = 0;
        while (k < K_COUNT && !tok_is(ts, eq, key_names[k])) k++;
        if (k == K_COUNT)
            return perr(c, AM_ERR_PARSE, "material '%s': unknown key '%s' (keys: " KEY_LIST ")", m->name, shown(qb, ts, eq));
        if (seen[k]) return perr(c, AM_ERR_PARSE, "material '%s': key '%s' given twice", m->name, key_names[k]);
        seen[k] = 1;
        const char* vs = eq + 1;
        if (k == K_COLOR) {
            if (!parse_color(vs, te, m->color))
                return perr(c, AM_ERR_PARSE, "material '%s': bad color '%s' (expected #rrggbb or #rrggbbaa)", m->name,
                            shown(qb, vs, te));
        } else if (k == K_FIXED) {
            if (!tok_is(vs, te, "0") && !tok_is(vs, te, "1"))
                return perr(c, AM_ERR_PARSE, "material '%s': fixed must be 0 or 1, not '%s'", m->name, shown(qb, vs, te));
            m->fixed = *vs == '1';
        } else {
            am_param v;
            if (!parse_real(vs, te, &v))
                return perr(c, AM_ERR_PARSE, "material '%s': %s: '%s' is not a finite number", m->name, key_names[k],
                            shown(qb, vs, te));
            const char* why = range_problem(k, v);
            if (why) return perr(c, AM_ERR_RANGE, "material '%s': %s = %s %s", m->name, key_names[k], shown(qb, vs, te), why);
            set_real(m, k, v);
        }
    }
    pal->count++;
    return AM_OK;
}

/* ---- the parser -------------------------------------------------------------------------- */

static int is_keyword(const char* ts, const char* te)
{
    return tok_is(ts, te, "size") || tok_is(ts, te, "voxel_size") || tok_is(ts, te, "material") || tok_is(ts, te, "layer") ||
           tok_is(ts, te, LAT_MAGIC);
}

/* cell value of a row character, or -1 */
static int cell_value(char ch)
{
    for (int v = 0; v <= AM_MAX_MATERIALS; v++)
        if (cell_chars[v] == ch) return v;
    return -1;
}

/* a token made only of cell characters */
static int is_row(const char* ts, const char* te)
{
    for (; ts < te; ts++)
        if (cell_value(*ts) < 0) return 0;
    return 1;
}

/* one row of the current layer: a single token of exactly nx cell characters */
static am_status parse_row(const pctx* c, am_lattice* lat, int z, int y, const char* p, const char* end)
{
    const char *ts = p, *te = p, *xs = p, *xe = p;
    char qb[AM_QUOTE_BUF];
    next_token(&p, end, &ts, &te);
    if (next_token(&p, end, &xs, &xe))
        return perr(c, AM_ERR_PARSE, "layer %d row %d: unexpected '%s' after the row (a row is %d characters, no blanks)", z, y,
                    shown(qb, xs, xe), lat->nx);
    if (te - ts != lat->nx)
        return perr(c, AM_ERR_PARSE, "layer %d row %d has %ld cells, expected %d (size %d %d %d)", z, y, (long)(te - ts), lat->nx,
                    lat->nx, lat->ny, lat->nz);
    for (int x = 0; x < lat->nx; x++) {
        int v = cell_value(ts[x]);
        if (v < 0) {
            unsigned char ch = (unsigned char)ts[x];
            if (ch >= 0x20 && ch < 0x7f)
                return perr(c, AM_ERR_PARSE, "layer %d row %d: bad cell character '%c' at x = %d (expected '.', 1-9 or a-g)", z, y,
                            ts[x], x);
            return perr(c, AM_ERR_PARSE, "layer %d row %d: bad cell byte 0x%02x at x = %d (expected '.', 1-9 or a-g)", z, y, ch, x);
        }
        if (v > lat->palette.count)
            return perr(c, AM_ERR_RANGE, "layer %d row %d: unknown material id '%c' at x = %d (the palette has %d materials)", z, y,
                        ts[x], x, lat->palette.count);
        lat->cell[am_lattice_index(lat, x, y, z)] = (uint8_t)v;
    }
    return AM_OK;
}

/* the rest of a line after its first token must be empty */
static am_status no_more(const pctx* c, const char* what, const char* p, const char* end)
{
    const char *ts = NULL, *te = NULL;
    char qb[AM_QUOTE_BUF];
    if (next_token(&p, end, &ts, &te))
        return perr(c, AM_ERR_PARSE, "%s: unexpected '%s' at the end of the line", what, shown(qb, ts, te));
    return AM_OK;
}

static am_status parse_size_line(const pctx* c, am_lattice* lat, const char* p, const char* end)
{
    long v[3];
    char qb[AM_QUOTE_BUF];
    const char *ts = NULL, *te = NULL, *first = NULL;
    for (int i = 0; i < 3; i++) {
        if (!next_token(&p, end, &ts, &te)) return perr(c, AM_ERR_PARSE, "size: expected three whole numbers NX NY NZ");
        if (!parse_int(ts, te, &v[i]))
            return perr(c, AM_ERR_PARSE, "size: '%s' is not a whole number", shown(qb, ts, te));
        if (i == 0) first = ts;
    }
    am_status st = no_more(c, "size", p, end);
    if (st != AM_OK) return st;
    /* the sizes as written (parse_int clamps a number past 10^9) */
    if (v[0] < 1 || v[1] < 1 || v[2] < 1)
        return perr(c, AM_ERR_RANGE, "size %s: every side must be at least 1", shown(qb, first, te));
    if (v[0] > AM_MAX_DIM || v[1] > AM_MAX_DIM || v[2] > AM_MAX_DIM)
        return perr(c, AM_ERR_CAPACITY, "size %s exceeds the %s profile's %d cells per side", shown(qb, first, te), AM_PROFILE_NAME,
                    AM_MAX_DIM);
    lat->nx = (int)v[0];
    lat->ny = (int)v[1];
    lat->nz = (int)v[2];
    return AM_OK;
}

void am_lattice_read_begin(am_lattice_reader* r, am_lattice* lat, const char* fname)
{
    memset(r, 0, sizeof *r);
    r->lat = lat;
    r->fname = fname ? fname : "(text)";
    r->z = -1;
    r->last = 1;
    if (lat) {
        memset(lat, 0, sizeof *lat);
        lat->voxel_size = AM_P(0.01);
    }
}

/* one line [ls, le); c->line is its number */
static am_status lattice_line(am_lattice_reader* r, const pctx* c, const char* ls, const char* le)
{
    am_lattice* lat = r->lat;
    char qb[AM_QUOTE_BUF];
    am_status st;
    /* a '#' at the start of the line or after a blank starts a comment */
    const char* end = ls;
    while (end < le && !(*end == '#' && (end == ls || is_blank(end[-1])))) end++;
    const char* q = ls;
    const char *ts = NULL, *te = NULL;
    if (!next_token(&q, end, &ts, &te)) return AM_OK;

    if (!r->have_header) {
        const char *vs = NULL, *ve = NULL;
        long version = 0;
        if (!tok_is(ts, te, LAT_MAGIC))
            return perr(c, AM_ERR_PARSE, "not a lattice file: expected the header '" LAT_MAGIC " %d', found '%s'", LAT_VERSION,
                        shown(qb, ts, te));
        if (!next_token(&q, end, &vs, &ve) || !parse_int(vs, ve, &version))
            return perr(c, AM_ERR_PARSE, "header: expected '" LAT_MAGIC " %d' (a version number after the name)", LAT_VERSION);
        if (version != LAT_VERSION)
            return perr(c, AM_ERR_PARSE, "unsupported lattice format version %ld (this build reads version %d)", version,
                        LAT_VERSION);
        if ((st = no_more(c, "header", q, end)) != AM_OK) return st;
        r->have_header = 1;
        return AM_OK;
    }

    /* inside a layer: the next ny meaningful lines are its rows */
    if (r->z >= 0 && r->y < lat->ny) {
        if (is_keyword(ts, te))
            return perr(c, AM_ERR_PARSE, "layer %d has %d rows, expected %d (size %d %d %d)", r->z, r->y, lat->ny, lat->nx, lat->ny,
                        lat->nz);
        if ((st = parse_row(c, lat, r->z, r->y, ts, end)) != AM_OK) return st;
        r->y++;
        return AM_OK;
    }

    if (tok_is(ts, te, "size")) {
        if (r->have_size) return perr(c, AM_ERR_PARSE, "size given twice");
        if ((st = parse_size_line(c, lat, q, end)) != AM_OK) return st;
        r->have_size = 1;
    } else if (tok_is(ts, te, "voxel_size")) {
        am_param v;
        if (r->have_voxel) return perr(c, AM_ERR_PARSE, "voxel_size given twice");
        if (r->z >= 0) return perr(c, AM_ERR_PARSE, "voxel_size must come before the first layer");
        if (!next_token(&q, end, &ts, &te)) return perr(c, AM_ERR_PARSE, "voxel_size: expected a length in metres");
        if (!parse_real(ts, te, &v))
            return perr(c, AM_ERR_PARSE, "voxel_size: '%s' is not a finite number", shown(qb, ts, te));
        if (!(v > AM_P(0))) return perr(c, AM_ERR_RANGE, "voxel_size %s must be greater than 0", shown(qb, ts, te));
        if (!(v >= AM_P(AM_VOXEL_SIZE_MIN) && v <= AM_P(AM_VOXEL_SIZE_MAX)))
            return perr(c, AM_ERR_RANGE, "voxel_size %s m is outside %g..%g", shown(qb, ts, te), AM_VOXEL_SIZE_MIN, AM_VOXEL_SIZE_MAX);
        if ((st = no_more(c, "voxel_size", q, end)) != AM_OK) return st;
        lat->voxel_size = v;
        r->have_voxel = 1;
    } else if (tok_is(ts, te, "material")) {
        if (r->z >= 0) return perr(c, AM_ERR_PARSE, "materials must come before the first layer");
        if ((st = parse_material(c, &lat->palette, q, end)) != AM_OK) return st;
    } else if (tok_is(ts, te, "layer")) {
        long k = 0;
        if (!r->have_size) return perr(c, AM_ERR_PARSE, "layer before size: a 'size NX NY NZ' line must come first");
        if (!next_token(&q, end, &ts, &te) || !parse_int(ts, te, &k))
            return perr(c, AM_ERR_PARSE, "layer: expected a layer number 0..%d", lat->nz - 1);
        if ((st = no_more(c, "layer", q, end)) != AM_OK) return st;
        if (r->z == lat->nz - 1 && r->y == lat->ny)
            return perr(c, AM_ERR_PARSE, "layer %ld: too many layers (size says %d)", k, lat->nz);
        if (k != r->z + 1)
            return perr(c, AM_ERR_PARSE, "expected layer %d, found layer %ld (layers go 0..%d in order)", r->z + 1, k, lat->nz - 1);
        if (r->z < 0 && lat->palette.count == 0) am_default_palette_into(&lat->palette);
        r->z = (int)k;
        r->y = 0;
    } else if (tok_is(ts, te, LAT_MAGIC)) {
        return perr(c, AM_ERR_PARSE, "header given twice");
    } else if (is_row(ts, te)) {
        if (r->z < 0) return perr(c, AM_ERR_PARSE, "row before any 'layer' line");
        return perr(c, AM_ERR_PARSE, "layer %d has more than %d rows (size %d %d %d)", r->z, lat->ny, lat->nx, lat->ny, lat->nz);
    } else {
        return perr(c, AM_ERR_PARSE, "unknown keyword '%s' (expected size, voxel_size, material or layer)", shown(qb, ts, te));
    }
    return AM_OK;
}

am_status am_lattice_read_line(am_lattice_reader* r, const char* text, long n, char* err, int errsz)
{
    if (r->st != AM_OK) return r->st;
    r->line++;
    r->last = r->line;
    pctx c = {r->fname, r->line, err, errsz};
    if (!r->lat || !text) return r->st = perr(&c, AM_ERR_ARG, "no lattice or no text given");
    r->st = lattice_line(r, &c, text, text + n);
    return r->st;
}

am_status am_lattice_read_end(am_lattice_reader* r, char* err, int errsz)
{
    if (r->st != AM_OK) return r->st;
    /* the end: everything the size promised must be there */
    pctx c = {r->fname, r->last, err, errsz};
    const am_lattice* lat = r->lat;
    if (!lat) return r->st = perr(&c, AM_ERR_ARG, "no lattice or no text given");
    if (!r->have_header)
        return r->st = perr(&c, AM_ERR_PARSE, "not a lattice file: no header '" LAT_MAGIC " %d' (the file is empty or only comments)",
                            LAT_VERSION);
    if (!r->have_size) return r->st = perr(&c, AM_ERR_PARSE, "missing size: no 'size NX NY NZ' line");
    if (r->z >= 0 && r->y < lat->ny)
        return r->st = perr(&c, AM_ERR_PARSE, "layer %d has %d rows, expected %d (the file ends)", r->z, r->y, lat->ny);
    if (r->z < lat->nz - 1)
        return r->st = perr(&c, AM_ERR_PARSE, "missing layer %d: the file ends, size says %d layers", r->z + 1, lat->nz);
    return AM_OK;
}

am_status am_lattice_parse(am_lattice* lat, const char* text, const char* fname, char* err, int errsz)
{
    am_lattice_reader r;
    if (!lat || !text) {
        pctx c = {fname ? fname : "(text)", 1, err, errsz};
        return perr(&c, AM_ERR_ARG, "no lattice or no text given");
    }
    am_lattice_read_begin(&r, lat, fname);
    const char* p = text;
    while (*p) {
        const char* le = p;
        while (*le && *le != '\n') le++;
        am_status st = am_lattice_read_line(&r, p, (long)(le - p), err, errsz);
        if (st != AM_OK) return st;
        p = *le ? le + 1 : le;
    }
    return am_lattice_read_end(&r, err, errsz);
}

/* ---- the writer -------------------------------------------------------------------------- */

/* the bounded text buffer of amorph/base.h */
#define put am_text_put

#if defined(AM_REAL_DOUBLE) || defined(AM_REAL_FIXED_POINT)
#define REAL_DIGITS 17
#else
#define REAL_DIGITS 9
#endif

/* the shortest "%.Ng" that reads back to the same bits (N <= 9 for float, 17 for double, which
 * always round-trips), preferring a form without an exponent: 0.01 rather than 0.00999999978,
 * 1000 rather than 1e+03, but 1e-30 as is */
static void fmt_real(char out[40], am_param v)
{
    int first = 0;
    for (int digits = 1; digits <= REAL_DIGITS; digits++) {
        snprintf(out, 40, "%.*g", digits, (double)v);
#if defined(AM_REAL_DOUBLE) || defined(AM_REAL_FIXED_POINT)
        am_param back = strtod(out, NULL);
#else
        am_param back = strtof(out, NULL);
#endif
        if (memcmp(&back, &v, sizeof v) != 0) continue;
        if (!strchr(out, 'e')) return;
        if (!first) first = digits;
    }
    int digits = first >= 1 && first <= REAL_DIGITS ? first : REAL_DIGITS;
    snprintf(out, 40, "%.*g", digits, (double)v);
}

am_status am_lattice_write(const am_lattice* lat, am_text* out, char* err, int errsz)
{
    if (!lat || !out) return am_fail(err, errsz, AM_ERR_ARG, "lattice format: no lattice or no output");
    /* the same rules as the parser, so what is written reads back */
    if (lat->nx < 1 || lat->ny < 1 || lat->nz < 1 || lat->nx > AM_MAX_DIM || lat->ny > AM_MAX_DIM || lat->nz > AM_MAX_DIM)
        return am_fail(err, errsz, AM_ERR_ARG, "lattice format: size %d %d %d outside 1..%d", lat->nx, lat->ny, lat->nz, AM_MAX_DIM);
    if (!am_param_finite(lat->voxel_size) || !(lat->voxel_size > AM_P(0)))
        return am_fail(err, errsz, AM_ERR_ARG, "lattice format: voxel size must be a positive finite number");
    const am_palette* pal = &lat->palette;
    if (pal->count < 1 || pal->count > AM_MAX_MATERIALS)
        return am_fail(err, errsz, AM_ERR_ARG, "lattice format: palette count %d outside 1..%d", pal->count, AM_MAX_MATERIALS);
    for (int i = 0; i < pal->count; i++) {
        const am_material* m = &pal->mat[i];
        const char* nul = memchr(m->name, 0, sizeof m->name);
        if (!nul || !name_ok(m->name, (size_t)(nul - m->name)))
            return am_fail(err, errsz, AM_ERR_ARG, "lattice format: material %d has a bad name", i + 1);
        for (int j = 0; j < i; j++)
            if (strcmp(pal->mat[j].name, m->name) == 0)
                return am_fail(err, errsz, AM_ERR_ARG, "lattice format: material '%s' appears twice", m->name);
        for (int k = 0; k < K_COLOR; k++) {
            const char* why = range_problem(k, get_real(m, k));
            if (why) return am_fail(err, errsz, AM_ERR_ARG, "lattice format: material '%s': %s %s", m->name, key_names[k], why);
        }
        if (m->fixed != 0 && m->fixed != 1)
            return am_fail(err, errsz, AM_ERR_ARG, "lattice format: material '%s': fixed must be 0 or 1", m->name);
    }
    int cells = lat->nx * lat->ny * lat->nz;
    for (int i = 0; i < cells; i++)
        if (lat->cell[i] > pal->count)
            return am_fail(err, errsz, AM_ERR_ARG, "lattice format: cell %d holds material id %d, the palette has %d", i, lat->cell[i],
                           pal->count);

    am_text* w = out;
    put(w, LAT_MAGIC " %d\n", LAT_VERSION);
    put(w, "# rows: y = 0..%d top to bottom; characters: x = 0..%d left to right; layers: z = 0 (floor) up\n", lat->ny - 1,
        lat->nx - 1);
    put(w, "# cells: '.' empty, 1-9 and a-g material ids (order of the material lines, from 1)\n");
    put(w, "size %d %d %d\n", lat->nx, lat->ny, lat->nz);
    char num[40];
    fmt_real(num, lat->voxel_size);
    put(w, "voxel_size %s\n", num);
    for (int i = 0; i < pal->count; i++) {
        const am_material* m = &pal->mat[i];
        put(w, "material %s", m->name);
        for (int k = 0; k < K_COLOR; k++) {
            fmt_real(num, get_real(m, k));
            put(w, " %s=%s", key_names[k], num);
        }
        put(w, " color=#%02x%02x%02x", m->color[0], m->color[1], m->color[2]);
        if (m->color[3] != 255) put(w, "%02x", m->color[3]);
        put(w, " fixed=%d\n", m->fixed);
    }
    char row[AM_MAX_DIM + 1];
    for (int z = 0; z < lat->nz && !w->full; z++) {
        put(w, "layer %d\n", z);
        for (int y = 0; y < lat->ny && !w->full; y++) {
            for (int x = 0; x < lat->nx; x++) row[x] = cell_chars[lat->cell[am_lattice_index(lat, x, y, z)]];
            row[lat->nx] = '\n';
            am_text_write(w, row, lat->nx + 1);
        }
    }
    if (w->full == 2) return am_fail(err, errsz, AM_ERR_IO, "lattice format: the output failed");
    if (w->full) return am_fail(err, errsz, AM_ERR_CAPACITY, "lattice format: the text needs more than the %ld bytes given", w->cap);
    return AM_OK;
}

am_status am_lattice_format(const am_lattice* lat, char* buf, long cap, long* len, char* err, int errsz)
{
    if (len) *len = 0;
    if (!lat || !buf || cap < 1) return am_fail(err, errsz, AM_ERR_ARG, "lattice format: no lattice or no buffer");
    buf[0] = 0;
    am_text w = {buf, cap, 0, 0, NULL, NULL, 0};
    am_status st = am_lattice_write(lat, &w, err, errsz);
    if (st != AM_OK) {
        buf[0] = 0;
        return st;
    }
    if (len) *len = w.len;
    return AM_OK;
}
