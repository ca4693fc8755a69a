/* The genome text format (docs/formats.md): a versioned, line-based text.
 *
 *   amorph-genome 1
 *   repr dct|cppn|gmx
 *   materials NAME...          (palette names, one per density field)
 *   evolved phase stiffness    (version 2: the evolved fields after the materials', one or both)
 *   workspace W H D            (cells)
 *   ...                        (the representation's lines: its shape line first)
 *   end
 *
 * '#' starts a comment; blank lines and extra spaces are ignored. Reals are written with enough
 * digits to read back bit for bit (%.9g for float, %.17g for double) and read with strtod. The
 * common header is parsed here, the rest line by line by the representation's parse_line, so a
 * new representation brings its own lines. Every problem is reported as "file:line: problem".
 */
#include "geno_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define GENOME_MAGIC "amorph-genome"
#define GENOME_VERSION 2 /* 2: the evolved fields' line; a genome without them is written as version 1 */
#define LINE_MAX_CHARS 1024
#define TOKENS_MAX 48

static int is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

int am_genome_sniff(const char* text)
{
    const size_t n = sizeof GENOME_MAGIC - 1;
    while (*text) { /* skip blank and comment lines */
        while (is_space(*text) || *text == '\n') text++;
        if (*text != '#') break;
        while (*text && *text != '\n') text++;
    }
    return strncmp(text, GENOME_MAGIC, n) == 0 && (is_space(text[n]) || text[n] == '\n' || text[n] == '\0');
}

am_status am_genome_write(const am_genome* g, am_text* out, char* err, int errsz)
{
    am_status st = am_genome_check(g, err, errsz);
    if (st != AM_OK) return st;
    am_text_put(out, "%s %d\n", GENOME_MAGIC, g->controls ? 2 : 1);
    am_text_put(out, "# amorph genome (am_real %s); format: docs/formats.md\n", AM_REAL_NAME);
    am_text_put(out, "repr %s\n", am_repr_name(g->repr));
    am_text_put(out, "materials");
    for (int m = 0; m < g->materials; m++) am_text_put(out, " %s", g->mat[m]);
    if (g->controls)
        am_text_put(out, "\nevolved%s%s", g->controls & AM_CTL_PHASE ? " phase" : "", g->controls & AM_CTL_STIFFNESS ? " stiffness" : "");
    am_text_put(out, "\nworkspace %d %d %d\n", g->nx, g->ny, g->nz);
    am_geno_ops_of(g->repr)->format(g, out);
    am_text_put(out, "end\n");
    if (out->full == 2) return am_fail(err, errsz, AM_ERR_IO, "genome text: the output failed");
    if (out->full) return am_fail(err, errsz, AM_ERR_CAPACITY, "genome text needs more than the %ld bytes given", out->cap);
    return AM_OK;
}

static am_status write_genome(const void* g, am_text* out, char* err, int errsz)
{
    return am_genome_write((const am_genome*)g, out, err, errsz);
}

am_status am_genome_format(const am_genome* g, char* buf, long cap, long* len, char* err, int errsz)
{
    return am_text_format(write_genome, g, "genome text", buf, cap, len, err, errsz);
}

static int valid_name(const char* s)
{
    size_t n = strlen(s);
    if (n == 0 || n >= AM_NAME_MAX) return 0;
    for (; *s; s++) {
        char c = *s;
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-')) return 0;
    }
    return 1;
}

enum { S_MAGIC, S_REPR, S_MATERIALS, S_WORKSPACE, S_BODY, S_DONE };
static const char* const expected[] = {"'amorph-genome 1' or 'amorph-genome 2'", "'repr dct|cppn|gmx'", "'materials NAME...'",
                                       "'workspace W H D'"};

/* a version 2 genome's 'evolved phase stiffness' line (before 'workspace') */
static am_status evolved_line(am_genome* g, int ntok, char** tok, char* msg, int msz)
{
    char qb[AM_QUOTE_BUF];
    if (g->controls) return am_fail(msg, msz, AM_ERR_PARSE, "'evolved' given twice");
    if (ntok < 2) return am_fail(msg, msz, AM_ERR_PARSE, "expected 'evolved phase', 'evolved stiffness' or 'evolved phase stiffness'");
    int prev = 0;
    for (int i = 1; i < ntok; i++) {
        int c = strcmp(tok[i], "phase") == 0 ? AM_CTL_PHASE : strcmp(tok[i], "stiffness") == 0 ? AM_CTL_STIFFNESS : 0;
        if (!c) return am_fail(msg, msz, AM_ERR_PARSE, "unknown evolved field '%s' (phase, stiffness)", am_quote(qb, sizeof qb, tok[i], -1));
        if (c <= prev) return am_fail(msg, msz, AM_ERR_PARSE, "evolved fields in the order phase, stiffness, each once");
        g->controls |= c;
        prev = c;
    }
    if (!AM_GENO_LAYERS)
        return am_fail(msg, msz, AM_ERR_CAPACITY, "an evolved %s: the %s profile keeps no phase or stiffness per voxel", tok[1], AM_PROFILE_NAME);
    return AM_OK;
}

/* the header lines; msg gets the problem */
static am_status header_line(am_genome* g, int state, int version, int ntok, char** tok, char* msg, int msz)
{
    const char* keyword[] = {GENOME_MAGIC, "repr", "materials", "workspace"};
    char qb[AM_QUOTE_BUF];
    if (state == S_WORKSPACE && version >= 2 && strcmp(tok[0], "evolved") == 0) return evolved_line(g, ntok, tok, msg, msz);
    if (strcmp(tok[0], keyword[state]) != 0)
        return am_fail(msg, msz, AM_ERR_PARSE, state == S_MAGIC ? "not a genome: expected %s, found '%s'" : "expected %s, found '%s'",
                       expected[state], am_quote(qb, sizeof qb, tok[0], -1));
    switch (state) {
    case S_MAGIC: {
        int v = 0;
        if (ntok != 2 || !am_geno_tok_int(tok[1], 0, 1000000, &v))
            return am_fail(msg, msz, AM_ERR_PARSE, "expected %s", expected[state]);
        if (v < 1 || v > GENOME_VERSION)
            return am_fail(msg, msz, AM_ERR_PARSE, "genome format version %d: this build reads versions 1 to %d", v, GENOME_VERSION);
        return AM_OK;
    }
    case S_REPR:
        if (ntok != 2) return am_fail(msg, msz, AM_ERR_PARSE, "expected %s", expected[state]);
        g->repr = am_repr_from_name(tok[1]);
        if (g->repr == AM_REPR_NONE)
            return am_fail(msg, msz, AM_ERR_PARSE, "unknown representation '%s' (dct, cppn, gmx)",
                           am_quote(qb, sizeof qb, tok[1], -1));
        return AM_OK;
    case S_MATERIALS:
        if (ntok < 2) return am_fail(msg, msz, AM_ERR_PARSE, "expected %s", expected[state]);
        if (ntok - 1 > AM_MAX_GENO_MATERIALS)
            return am_fail(msg, msz, AM_ERR_CAPACITY, "%d materials: a genome holds at most %d", ntok - 1, AM_MAX_GENO_MATERIALS);
        g->materials = ntok - 1;
        for (int m = 0; m < g->materials; m++) {
            if (!valid_name(tok[1 + m]))
                return am_fail(msg, msz, AM_ERR_PARSE, "material name '%s': 1 to %d letters, digits, '_' or '-'",
                               am_quote(qb, sizeof qb, tok[1 + m], -1), AM_NAME_MAX - 1);
            for (int k = 0; k < m; k++)
                if (strcmp(g->mat[k], tok[1 + m]) == 0) return am_fail(msg, msz, AM_ERR_PARSE, "material '%s' given twice", tok[1 + m]);
            snprintf(g->mat[m], AM_NAME_MAX, "%s", tok[1 + m]);
        }
        return AM_OK;
    default: {
        int d[3];
        if (ntok != 4) return am_fail(msg, msz, AM_ERR_PARSE, "expected %s", expected[state]);
        for (int a = 0; a < 3; a++) {
            if (!am_geno_tok_int(tok[1 + a], 1, 1000000, &d[a]))
                return am_fail(msg, msz, AM_ERR_PARSE, "workspace side '%s' is not a positive integer",
                               am_quote(qb, sizeof qb, tok[1 + a], -1));
            if (d[a] > AM_MAX_DIM)
                return am_fail(msg, msz, AM_ERR_CAPACITY, "workspace side %d exceeds the %s profile's %d", d[a], AM_PROFILE_NAME, AM_MAX_DIM);
        }
        g->nx = d[0];
        g->ny = d[1];
        g->nz = d[2];
        return AM_OK;
    }
    }
}

void am_genome_read_begin(am_genome_reader* r, am_genome* g, const char* fname)
{
    memset(r, 0, sizeof *r);
    memset(g, 0, sizeof *g);
    r->g = g;
    r->fname = fname ? fname : "genome";
    r->state = S_MAGIC;
}

/* the reader's failure as "fname:line: problem" */
static am_status read_fail(am_genome_reader* r, am_status st, const char* msg, char* err, int errsz)
{
    r->st = st;
    return am_fail(err, errsz, st, "%s:%d: %s", r->fname, r->lineno, msg);
}

am_status am_genome_read_line(am_genome_reader* r, const char* text, long n, char* err, int errsz)
{
    char line[LINE_MAX_CHARS];
    char* tok[TOKENS_MAX];
    char msg[AM_ERR_MAX];
    am_genome* g = r->g;
    am_status st = AM_OK;
    if (r->st != AM_OK) return r->st;
    msg[0] = '\0';
    r->lineno++;
    if (n >= (long)sizeof line) {
        am_fail(msg, sizeof msg, AM_ERR_PARSE, "line longer than %d characters", LINE_MAX_CHARS - 1);
        return read_fail(r, AM_ERR_PARSE, msg, err, errsz);
    }
    memcpy(line, text, (size_t)n);
    line[n] = '\0';
    char* hash = strchr(line, '#');
    if (hash) *hash = '\0';
    int ntok = 0;
    for (char* q = line; *q;) {
        while (is_space(*q)) *q++ = '\0';
        if (!*q) break;
        if (ntok == TOKENS_MAX) {
            am_fail(msg, sizeof msg, AM_ERR_PARSE, "more than %d fields on a line", TOKENS_MAX);
            return read_fail(r, AM_ERR_PARSE, msg, err, errsz);
        }
        tok[ntok++] = q;
        while (*q && !is_space(*q)) q++;
    }
    if (ntok == 0) return AM_OK;
    if (r->state == S_DONE) {
        am_fail(msg, sizeof msg, AM_ERR_PARSE, "text after 'end'");
        return read_fail(r, AM_ERR_PARSE, msg, err, errsz);
    }
    if (r->state < S_BODY) {
        const int evolved = r->state == S_WORKSPACE && strcmp(tok[0], "evolved") == 0;
        st = header_line(g, r->state, r->version, ntok, tok, msg, sizeof msg);
        if (st != AM_OK) return read_fail(r, st, msg, err, errsz);
        if (r->state == S_MAGIC) r->version = atoi(tok[1]);
        if (evolved) return AM_OK; /* the workspace line still to come */
        r->state++;
        if (r->state == S_BODY) r->ops = am_geno_ops_of(g->repr);
        return AM_OK;
    }
    if (strcmp(tok[0], "end") == 0 && ntok == 1) {
        st = r->ops->parse_end(g, &r->ps, msg, sizeof msg);
        if (st == AM_OK) st = am_genome_check(g, msg, sizeof msg);
        if (st != AM_OK) return read_fail(r, st, msg, err, errsz);
        r->state = S_DONE;
        return AM_OK;
    }
    st = r->ops->parse_line(g, &r->ps, ntok, tok, msg, sizeof msg);
    if (st != AM_OK) return read_fail(r, st, msg, err, errsz);
    return AM_OK;
}

am_status am_genome_read_end(am_genome_reader* r, char* err, int errsz)
{
    char msg[AM_ERR_MAX];
    if (r->st != AM_OK) return r->st;
    if (r->state == S_DONE) return AM_OK;
    if (r->lineno == 0) r->lineno = 1;
    if (r->state < S_BODY) am_fail(msg, sizeof msg, AM_ERR_PARSE, "unexpected end of text: expected %s", expected[r->state]);
    else am_fail(msg, sizeof msg, AM_ERR_PARSE, "unexpected end of text: missing 'end' line");
    return read_fail(r, AM_ERR_PARSE, msg, err, errsz);
}

am_status am_genome_parse(am_genome* g, const char* text, const char* fname, char* err, int errsz)
{
    am_genome_reader r;
    am_genome_read_begin(&r, g, fname);
    const char* p = text;
    while (*p) {
        const char* eol = strchr(p, '\n');
        long n = eol ? (long)(eol - p) : (long)strlen(p);
        am_status st = am_genome_read_line(&r, p, n, err, errsz);
        if (st != AM_OK) return st;
        p = eol ? eol + 1 : p + n;
    }
    return am_genome_read_end(&r, err, errsz);
}
