/* A run's tables: log.csv (one row per generation) and evals.csv (one row per evaluation), their
 * writers, and the reader of log.csv; an experiment's results.csv rows (amorph/evo.h, the run
 * folder: beside the evolver whose numbers they hold, apart from the codecs).
 *
 * The reader is the one parser of log.csv (amorph plot and amorph experiment read logs through
 * it). It takes a line at a time, like the lattice and genome readers, so a log streamed through a
 * small buffer needs no copy of the whole file. The header names the columns: the reader notes
 * where each one it knows stands and skips the others, so it reads a log written by a build that
 * added, dropped (beyond the required three) or reordered columns. A field is copied into a small
 * buffer before it is converted, so a number never runs past its comma, and accepted only when the
 * whole field is consumed and the value is finite; a field a message shows goes through am_quote.
 */
#include "amorph/evo.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char* am_evo_log_header(void)
{
    return "generation,evaluations,best,mean,median,diverged,empty,wall_s,unsettled";
}

int am_evo_log_row(const am_evo_stats* s, char* buf, int cap)
{
    int n = snprintf(buf, (size_t)cap, "%ld,%ld,%.9g,%.9g,%.9g,%d,%d,%.3f,%d", s->generation, s->evaluations, s->best, s->mean,
                     s->median, s->diverged, s->empty, s->wall_s, s->unsettled);
    return n < 0 ? 0 : n;
}

/* the characters snprintf put into a buffer of cap, or would have: clamped to what it holds */
static int held(int n, int cap)
{
    if (n < 0) return 0;
    return n < cap ? n : cap - 1;
}

int am_evo_evals_header(int materials, char* buf, int cap)
{
    if (cap <= 0) return 0;
    int n = held(snprintf(buf, (size_t)cap, "evaluation,generation,parent_a,parent_b,placed,representation,voxels"), cap);
    for (int k = 0; k < materials && k < AM_MAX_GENO_MATERIALS; k++)
        n += held(snprintf(buf + n, (size_t)(cap - n), ",voxels_m%d", k + 1), cap - n);
    n += held(snprintf(buf + n, (size_t)(cap - n), ",fitness,dx,dy,dz,settled,diverged,empty,relax_steps,steps,state_hash"), cap - n);
    return n;
}

/* a displacement: empty when it is not a finite number (a diverged body) */
static int put_len(char* buf, int cap, double v)
{
    return held(isfinite(v) ? snprintf(buf, (size_t)cap, ",%.9g", v) : snprintf(buf, (size_t)cap, ","), cap);
}

int am_evo_evals_row(const am_evo_def* d, const am_evo_ind* ind, const am_evo_eval* ev, char* buf, int cap)
{
    if (cap <= 0) return 0;
    int n = held(snprintf(buf, (size_t)cap, "%ld,%ld,%ld,%ld,%d,%s,%d", ind->id, ev->generation, ev->parent[0], ev->parent[1],
                          ev->placed, am_repr_name(d->geno.repr), ind->voxels),
                 cap);
    for (int k = 0; k < d->geno.materials && k < AM_MAX_GENO_MATERIALS; k++)
        n += held(snprintf(buf + n, (size_t)(cap - n), ",%d", ev->material_voxels[k]), cap - n);
    n += put_len(buf + n, cap - n, ind->diverged ? (double)NAN : ind->fitness);
    n += put_len(buf + n, cap - n, ind->diverged ? (double)NAN : ev->sim.dx);
    n += put_len(buf + n, cap - n, ind->diverged ? (double)NAN : ev->sim.dy);
    n += put_len(buf + n, cap - n, ind->diverged ? (double)NAN : ev->sim.dz);
    n += held(snprintf(buf + n, (size_t)(cap - n), ",%d,%d,%d,%ld,%ld,%016llx", ev->sim.settled, ind->diverged, ind->empty,
                       ev->sim.relax_steps, ind->steps, (unsigned long long)ind->state_hash),
              cap - n);
    return n;
}

const char* am_exp_results_header(void)
{
    return "variant,evaluations,mean_best,stderr_best,runs";
}

int am_exp_results_row(const char* variant, long evaluations, double mean, double stderr_best, long runs, char* buf, int cap)
{
    if (cap <= 0) return 0;
    return held(snprintf(buf, (size_t)cap, "%s,%ld,%.9g,%.9g,%ld", variant, evaluations, mean, stderr_best, runs), cap);
}

/* ---- reading log.csv ---- */

/* the names of am_evo_log_header, in its order; the first LOG_REQUIRED must be in a header */
static const char* const log_names[AM_EVO_LOG_COLUMNS] = {"generation", "evaluations", "best",   "mean",     "median",
                                                          "diverged",   "empty",       "wall_s", "unsettled"};
enum { LOG_GENERATION, LOG_EVALUATIONS, LOG_BEST, LOG_MEAN, LOG_MEDIAN, LOG_DIVERGED, LOG_EMPTY, LOG_WALL_S, LOG_UNSETTLED };
#define LOG_REQUIRED 3
#define LOG_FIELD_MAX 64  /* a longer field is not a number this reader takes */

/* "fname:line: problem" for the line being read; it is the reader's status from now on */
static am_status log_fail(am_evo_log_reader* r, char* err, int errsz, const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
static am_status log_fail(am_evo_log_reader* r, char* err, int errsz, const char* fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    r->st = am_vfail_at(err, errsz, AM_ERR_PARSE, r->fname, r->line, fmt, ap);
    va_end(ap);
    return r->st;
}

void am_evo_log_read_begin(am_evo_log_reader* r, const char* fname)
{
    memset(r, 0, sizeof *r);
    r->fname = fname ? fname : "(text)";
    for (int k = 0; k < AM_EVO_LOG_COLUMNS; k++) r->col[k] = -1;
}

/* the known column named [s, e), or -1 */
static int log_column(const char* s, const char* e)
{
    size_t n = (size_t)(e - s);
    for (int k = 0; k < AM_EVO_LOG_COLUMNS; k++)
        if (strlen(log_names[k]) == n && memcmp(log_names[k], s, n) == 0) return k;
    return -1;
}

/* the header [s, end): where each known column stands */
static am_status log_header(am_evo_log_reader* r, const char* s, const char* end, char* err, int errsz)
{
    int c = 0;
    for (const char* p = s;; c++) {
        const char* q = p;
        while (q < end && *q != ',') q++;
        int k = log_column(p, q);
        if (k >= 0) {
            if (r->col[k] >= 0)
                return log_fail(r, err, errsz, "not a log.csv header: column '%s' named twice (columns %d and %d)", log_names[k],
                                r->col[k] + 1, c + 1);
            r->col[k] = c;
        }
        if (q == end) break;
        p = q + 1;
    }
    r->columns = c + 1;
    for (int k = 0; k < LOG_REQUIRED; k++)
        if (r->col[k] < 0)
            return log_fail(r, err, errsz, "not a log.csv header: no '%s' column (expected %s)", log_names[k], am_evo_log_header());
    r->header = 1;
    return AM_OK;
}

/* "NAME (column C): WHAT: 'FIELD'" for field [s, s + n) of the header's name k in column c */
static am_status log_bad(am_evo_log_reader* r, int k, int c, const char* what, const char* s, size_t n, char* err, int errsz)
{
    char q[AM_QUOTE_BUF];
    return log_fail(r, err, errsz, "%s (column %d): %s: '%s'", log_names[k], c + 1, what, am_quote(q, (int)sizeof q, s, (long)n));
}

/* field [s, e) in column c, the header's column of name k: a count into *w (generation,
 * evaluations, diverged, empty, unsettled) or a finite number into *v */
static am_status log_field(am_evo_log_reader* r, int k, int c, const char* s, const char* e, double* v, long* w, char* err,
                           int errsz)
{
    char buf[LOG_FIELD_MAX], what[64];
    size_t n = (size_t)(e - s);
    if (n == 0) return log_fail(r, err, errsz, "%s (column %d): empty, expected a number", log_names[k], c + 1);
    if (k == LOG_GENERATION || k == LOG_EVALUATIONS || k == LOG_DIVERGED || k == LOG_EMPTY || k == LOG_UNSETTLED) {
        long hi = k == LOG_DIVERGED || k == LOG_EMPTY || k == LOG_UNSETTLED ? INT_MAX : LONG_MAX;
        long x = 0;
        int ok = n < sizeof buf;
        if (ok) {
            memcpy(buf, s, n);
            buf[n] = 0;
            ok = strspn(buf, "0123456789") == n;
        }
        if (ok) {
            char* end = NULL;
            errno = 0;
            x = strtol(buf, &end, 10);
            ok = end == buf + n && errno != ERANGE && x <= hi;
        }
        if (!ok) {
            snprintf(what, sizeof what, "not a whole number from 0 to %ld", hi);
            return log_bad(r, k, c, what, s, n, err, errsz);
        }
        *w = x;
        return AM_OK;
    }
    if (n >= sizeof buf) return log_bad(r, k, c, "not a number", s, n, err, errsz);
    memcpy(buf, s, n);
    buf[n] = 0;
    char* end = NULL;
    double x = strtod(buf, &end);
    if (end != buf + n) return log_bad(r, k, c, "not a number", s, n, err, errsz);
    if (!isfinite(x)) return log_bad(r, k, c, "not a finite number", s, n, err, errsz);
    /* decimal only: strtod would take hexadecimal too, which no writer of a log makes */
    if (strspn(buf, "0123456789+-.eE") != n)
        return log_bad(r, k, c, "not a number", s, n, err, errsz);
    *v = x;
    return AM_OK;
}

/* the row [s, end) into *row */
static am_status log_row(am_evo_log_reader* r, const char* s, const char* end, am_evo_stats* row, char* err, int errsz)
{
    /* as many fields as the header has columns: a short row is named as such, not by a field */
    int fields = 1;
    for (const char* p = s; p < end; p++) fields += *p == ',';
    if (fields != r->columns)
        return log_fail(r, err, errsz, "%d field%s, the header has %d columns", fields, fields == 1 ? "" : "s", r->columns);
    am_evo_stats out = {0, 0, 0.0, (double)NAN, (double)NAN, -1, -1, (double)NAN, -1};
    const char* p = s;
    for (int c = 0; c < fields; c++) {
        const char* q = p;
        while (q < end && *q != ',') q++;
        for (int k = 0; k < AM_EVO_LOG_COLUMNS; k++) {
            if (r->col[k] != c) continue;
            double v = 0.0;
            long w = 0;
            am_status st = log_field(r, k, c, p, q, &v, &w, err, errsz);
            if (st != AM_OK) return st;
            switch (k) {
            case LOG_GENERATION: out.generation = w; break;
            case LOG_EVALUATIONS: out.evaluations = w; break;
            case LOG_BEST: out.best = v; break;
            case LOG_MEAN: out.mean = v; break;
            case LOG_MEDIAN: out.median = v; break;
            case LOG_DIVERGED: out.diverged = (int)w; break;
            case LOG_EMPTY: out.empty = (int)w; break;
            case LOG_UNSETTLED: out.unsettled = (int)w; break;
            default: out.wall_s = v; break;
            }
        }
        p = q + 1;
    }
    *row = out;
    return AM_OK;
}

am_status am_evo_log_read_line(am_evo_log_reader* r, const char* text, long n, am_evo_stats* row, int* is_row, char* err,
                               int errsz)
{
    if (is_row) *is_row = 0;
    if (r->st != AM_OK) return r->st;
    r->line++;
    if (!text || n < 0 || !row) return r->st = am_fail_at(err, errsz, AM_ERR_ARG, r->fname, r->line, "no text or no row given");
    const char* end = text + n;
    if (end > text && end[-1] == '\r') end--;
    if (end == text) return AM_OK; /* a blank line */
    if (!r->header) return log_header(r, text, end, err, errsz);
    am_status st = log_row(r, text, end, row, err, errsz);
    if (st != AM_OK) return st;
    r->rows++;
    if (is_row) *is_row = 1;
    return AM_OK;
}

am_status am_evo_log_read_end(am_evo_log_reader* r, char* err, int errsz)
{
    if (r->st != AM_OK) return r->st;
    if (!r->header)
        return r->st = am_fail_at(err, errsz, AM_ERR_PARSE, r->fname, r->line > 0 ? r->line : 1,
                                  "not a log.csv: no header line (the file is empty)");
    return AM_OK;
}
