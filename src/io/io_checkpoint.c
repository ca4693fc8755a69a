/* Checkpoints of a run: a text file holding the configuration, the random stream, the counters,
 * the population and the best individual, closed by a checksum line over everything before it.
 * Reals of the genomes are written so they read back bit for bit; fitness values (doubles) as
 * the hexadecimal digits of their bit patterns, so a checkpoint is exact on every platform.
 *
 *   amorph-checkpoint 3
 *   config-begin
 *   key = value ...            (am_evo_format, runtime keys included)
 *   config-end
 *   rng HEX HEX HEX HEX
 *   generation G
 *   evaluations N
 *   history HEX
 *   last G N BEST MEAN MEDIAN DIVERGED EMPTY WALL UNSETTLED   (doubles as HEX bit patterns; a
 *                              checkpoint from before UNSETTLED was logged lacks it)
 *   individual pop|best INDEX FITNESS VOXELS DIVERGED EMPTY STEPS STATEHASH ID
 *   amorph-genome V ... end    (the individual's genome, am_genome_format)
 *   ...
 *   reused N VOXELSTEPS        (evaluations that took a remembered result; VOXELSTEPS as HEX bits)
 *   memo SLOT USED KEY BYTES   (a remembered body, am_evo.memo[SLOT]: BYTES bytes follow, its
 *   m BASE64 ...                result's 28 numbers (one more a material past the third) of 8 bytes
 *                               little-endian, then its packed cells,
 *                               in base64 lines of up to 48 bytes)
 *   checksum HEX               (am_hash_bytes of every byte before this line)
 */
#include "amorph/io.h"

#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#define CHECKPOINT_VERSION 3 /* 3: the remembered bodies (memo, reused); 2 (read): individuals carry
                                the id of their evaluation; 1 (read): without */

static unsigned long long dbits(double v)
{
    uint64_t b;
    memcpy(&b, &v, sizeof b);
    return (unsigned long long)b;
}

static double bits_d(uint64_t b)
{
    double v;
    memcpy(&v, &b, sizeof v);
    return v;
}

/* ---- writing ---- */

/* the text goes through a small buffer of its own whose flush hashes every byte on its way to
 * the caller's output, so the checksum needs no copy of the whole text. A streaming output gets
 * the pieces straight at its far end (its own buffer is emptied first), a whole-text output in
 * its buffer. */
typedef struct ck_pass {
    am_text* out;
    uint64_t hash;            /* am_hash_bytes of every byte handed on */
} ck_pass;

static am_status ck_flush(void* ctx, const char* data, long n)
{
    ck_pass* c = (ck_pass*)ctx;
    am_text* out = c->out;
    c->hash = am_hash_bytes(c->hash, data, (unsigned long)n);
    if (out->full) return AM_ERR_IO;
    if (out->flush) {
        if (out->flush(out->ctx, data, n) != AM_OK) {
            out->full = 2;
            return AM_ERR_IO;
        }
        out->done += n;
        return AM_OK;
    }
    if (n > out->cap - 1 - out->len) {
        out->full = 1; /* a whole-text buffer takes a piece whole or not at all */
        return AM_ERR_IO;
    }
    memcpy(out->buf + out->len, data, (size_t)n);
    out->len += n;
    out->buf[out->len] = 0;
    return AM_OK;
}

/* one individual line and its genome; a genome that fails its check is not written and its
 * message kept in err (the first one counts) */
static void put_ind(am_text* s, const char* kind, int index, const am_evo_ind* it, char* err, int errsz, am_status* st)
{
    am_text_put(s, "individual %s %d %016llx %d %d %d %ld %016llx %ld\n", kind, index, dbits(it->fitness), it->voxels, it->diverged,
                it->empty, it->steps, (unsigned long long)it->state_hash, it->id);
    char msg[AM_ERR_MAX];
    am_status c = am_genome_check(&it->genome, msg, sizeof msg);
    if (c != AM_OK) {
        if (*st == AM_OK) *st = am_fail(err, errsz, c, "%s", msg);
        return;
    }
    am_genome_write(&it->genome, s, NULL, 0); /* only the output can fail now: seen at the end */
}

/* ---- remembered bodies: a result as 28 numbers of 8 bytes, little-endian ---- */

/* a remembered result is 28 numbers of 8 bytes, and in a run of more than three materials one
 * more for each material past the third (its voxels) */
#define MEMO_NUMBERS (25 + AM_MAX_GENO_MATERIALS)
_Static_assert(AM_EVO_MEMO_RESULT_BYTES == 8 * MEMO_NUMBERS, "a remembered result's numbers");
static int memo_count(int materials) { return 28 + (materials > 3 ? materials - 3 : 0); }
static long memo_result_bytes(int materials) { return 8L * memo_count(materials); }
#define MEMO_LINE_BYTES 48 /* bytes of one base64 line: 64 characters */

static const char b64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

/* a remembered result's numbers, in their order in the text: where each lives in am_evo_result,
 * its C type, and for an integer the range a checkpoint may hold (doubles: any bit pattern, since
 * a diverged body's last speed may be NaN) */
enum { NUM_INT, NUM_LONG, NUM_REAL, NUM_U64 };
typedef struct memo_field {
    size_t at;
    int type;
    long lo, hi;
} memo_field;
#define F_INT(m, lo, hi) {offsetof(am_evo_result, m), NUM_INT, lo, hi}
#define F_LONG(m) {offsetof(am_evo_result, m), NUM_LONG, 0, 2000000000L}
#define F_REAL(m) {offsetof(am_evo_result, m), NUM_REAL, 0, 0}
#define MEMO_FIXED 28 /* the numbers every run has; then the voxels of materials 4, 5, ... */
static const memo_field memo_fields[MEMO_FIXED] = {
    F_INT(voxels, 0, AM_MAX_CELLS), F_INT(empty, 0, 1), F_INT(detail.material_voxels[0], 0, AM_MAX_CELLS),
    F_INT(detail.material_voxels[1], 0, AM_MAX_CELLS), F_INT(detail.material_voxels[2], 0, AM_MAX_CELLS),
    F_REAL(detail.sim.fitness), F_REAL(detail.sim.travel), F_REAL(detail.sim.dx), F_REAL(detail.sim.dy), F_REAL(detail.sim.dz),
    F_REAL(detail.sim.sustained), F_INT(detail.sim.voxels, 0, AM_MAX_CELLS), F_INT(detail.sim.links, 0, AM_MAX_LINKS),
    F_REAL(detail.sim.dt), F_INT(detail.sim.period_steps, 0, 2000000000L), F_LONG(detail.sim.relax_steps),
    F_LONG(detail.sim.move_steps), F_LONG(detail.sim.steps), F_REAL(detail.sim.relax_dt), F_INT(detail.sim.relax_retried, 0, 1),
    F_INT(detail.sim.diverged, 0, 1), F_INT(detail.sim.settled, 0, 1), F_REAL(detail.sim.residual_speed),
    F_LONG(detail.sim.kinetic_resets), F_REAL(detail.sim.sim_seconds), F_LONG(detail.sim.rebuilds),
    F_INT(detail.sim.max_pairs, 0, 2000000000L), {offsetof(am_evo_result, detail.sim.hash), NUM_U64, 0, 0},
};
_Static_assert(AM_MAX_GENO_MATERIALS >= 3 && MEMO_NUMBERS == MEMO_FIXED + AM_MAX_GENO_MATERIALS - 3,
               "a remembered result holds every material's count");

/* number k's field: the table's, or past it material_voxels[k - 25] (materials 4, 5, ...) */
static memo_field memo_field_at(int k)
{
    if (k < MEMO_FIXED) return memo_fields[k];
    const memo_field f = {offsetof(am_evo_result, detail.material_voxels) + (size_t)(k - MEMO_FIXED + 3) * sizeof(int), NUM_INT, 0,
                          AM_MAX_CELLS};
    return f;
}

/* the result's numbers: integers as two's complement, doubles as bit patterns */
static void memo_numbers(const am_evo_result* r, int count, uint64_t v[MEMO_NUMBERS])
{
    const char* base = (const char*)r;
    for (int k = 0; k < count; k++) {
        const memo_field fk = memo_field_at(k), *f = &fk;
        int i;
        long l;
        double d;
        switch (f->type) {
        case NUM_INT: memcpy(&i, base + f->at, sizeof i); v[k] = (uint64_t)(int64_t)i; break;
        case NUM_LONG: memcpy(&l, base + f->at, sizeof l); v[k] = (uint64_t)(int64_t)l; break;
        case NUM_REAL: memcpy(&d, base + f->at, sizeof d); v[k] = dbits(d); break;
        default: memcpy(&v[k], base + f->at, sizeof v[k]); break;
        }
    }
}

/* the numbers back into *r (the rest of it cleared, parents unknown); 0 when an integer is out
 * of its range (a damaged checkpoint) */
static int memo_result(const uint64_t v[MEMO_NUMBERS], int count, am_evo_result* r)
{
    char* base = (char*)r;
    memset(r, 0, sizeof *r);
    r->detail.parent[0] = r->detail.parent[1] = -1;
    for (int k = 0; k < count; k++) {
        const memo_field fk = memo_field_at(k), *f = &fk;
        const int64_t x = (int64_t)v[k];
        if ((f->type == NUM_INT || f->type == NUM_LONG) && (x < f->lo || x > f->hi)) return 0;
        if (f->type == NUM_INT) {
            const int i = (int)x;
            memcpy(base + f->at, &i, sizeof i);
        } else if (f->type == NUM_LONG) {
            const long l = (long)x;
            memcpy(base + f->at, &l, sizeof l);
        } else if (f->type == NUM_REAL) {
            const double d = bits_d(v[k]);
            memcpy(base + f->at, &d, sizeof d);
        } else memcpy(base + f->at, &v[k], sizeof v[k]);
    }
    return 1;
}

/* byte i of slot k's text: its result's numbers, then its packed cells */
static uint8_t memo_byte(const uint64_t v[MEMO_NUMBERS], long result_bytes, const am_evo_memo* m, long i)
{
    return i < result_bytes ? (uint8_t)(v[i / 8] >> 8 * (i % 8)) : m->cells[i - result_bytes];
}

/* the bytes of a remembered body of a run of n cells and `materials` materials */
static long memo_bytes(int n, int materials, int controls) { return memo_result_bytes(materials) + am_evo_body_bytes(n, materials, controls); }

static void put_memo(am_text* s, const am_evo* e, int k)
{
    const am_evo_memo* m = &e->memo[k];
    const long bytes = memo_bytes(e->def.geno.nx * e->def.geno.ny * e->def.geno.nz, e->def.geno.materials, e->def.geno.controls);
    const long rb = memo_result_bytes(e->def.geno.materials);
    uint64_t v[MEMO_NUMBERS];
    memo_numbers(&m->res, memo_count(e->def.geno.materials), v);
    am_text_put(s, "memo %d %ld %016llx %ld\n", k, m->used, (unsigned long long)m->key, bytes);
    for (long at = 0; at < bytes; at += MEMO_LINE_BYTES) {
        char line[2 + 4 * MEMO_LINE_BYTES / 3 + 2];
        int len = 0;
        const long end = at + MEMO_LINE_BYTES < bytes ? at + MEMO_LINE_BYTES : bytes;
        for (long i = at; i < end; i += 3) {
            const long left = end - i;
            const unsigned t = (unsigned)memo_byte(v, rb, m, i) << 16 | (left > 1 ? (unsigned)memo_byte(v, rb, m, i + 1) << 8 : 0u) |
                               (left > 2 ? (unsigned)memo_byte(v, rb, m, i + 2) : 0u);
            line[len++] = b64[t >> 18 & 63];
            line[len++] = b64[t >> 12 & 63];
            line[len++] = left > 1 ? b64[t >> 6 & 63] : '=';
            line[len++] = left > 2 ? b64[t & 63] : '=';
        }
        line[len] = 0;
        am_text_put(s, "m %s\n", line);
    }
}

am_status am_evo_checkpoint_write(const am_evo* e, am_text* out, char* err, int errsz)
{
    char piece[320]; /* longer than any one piece the writers put */
    ck_pass pass = {out, AM_HASH_INIT};
    am_text s = {piece, sizeof piece, 0, 0, ck_flush, &pass, 0};
    am_status st = AM_OK;
    piece[0] = 0;
    if (out->flush) am_text_flush(out); /* what out holds goes first */
    am_text_put(&s, "amorph-checkpoint %d\nconfig-begin\n", CHECKPOINT_VERSION);
    am_evo_write(&e->def, 1, &s, NULL, 0);
    am_text_put(&s, "config-end\nrng %016llx %016llx %016llx %016llx\n", (unsigned long long)e->rng.s[0],
                (unsigned long long)e->rng.s[1], (unsigned long long)e->rng.s[2], (unsigned long long)e->rng.s[3]);
    am_text_put(&s, "generation %ld\nevaluations %ld\nhistory %016llx\n", e->generation, e->evaluations,
                (unsigned long long)e->history);
    am_text_put(&s, "last %ld %ld %016llx %016llx %016llx %d %d %016llx %d\n", e->last.generation, e->last.evaluations,
                dbits(e->last.best), dbits(e->last.mean), dbits(e->last.median), e->last.diverged, e->last.empty,
                dbits(e->last.wall_s), e->last.unsettled);
    for (int i = 0; i < e->def.population; i++) put_ind(&s, "pop", i, &e->pop[i], err, errsz, &st);
    if (e->has_best) put_ind(&s, "best", 0, &e->best, err, errsz, &st);
    if (st != AM_OK) return st;
    am_text_put(&s, "reused %ld %016llx\n", e->reused, dbits(e->reused_voxel_steps));
    for (int k = 0; k < AM_EVO_MEMO; k++)
        if (e->memo[k].key) put_memo(&s, e, k);
    if (am_text_flush(&s) == AM_OK) am_text_put(out, "checksum %016llx\n", (unsigned long long)pass.hash);
    if (out->full == 1) return am_fail(err, errsz, AM_ERR_CAPACITY, "checkpoint needs more than the %ld bytes given", out->cap);
    if (out->full || s.full) return am_fail(err, errsz, AM_ERR_IO, "checkpoint: the output failed");
    return AM_OK;
}

static am_status write_checkpoint(const void* e, am_text* out, char* err, int errsz)
{
    return am_evo_checkpoint_write((const am_evo*)e, out, err, errsz);
}

am_status am_evo_checkpoint_format(const am_evo* e, char* buf, long cap, long* len, char* err, int errsz)
{
    return am_text_format(write_checkpoint, e, "checkpoint", buf, cap, len, err, errsz);
}

/* ---- reading, in two passes ----
 *
 * Pass 1 (the scan) takes the bytes in pieces of any size: it finds the last line, checks that it
 * is "checksum HEX" over every byte before it, and notes the line of the first "config-end" and of
 * the last "end", so that pass 2 knows where the configuration and the genomes end without looking
 * ahead. Pass 2 (the reader) takes the lines before the checksum line one at a time. A text held
 * whole (am_evo_checkpoint_parse) and one streamed from a file take the same path. */

static int hex64(const char* s, uint64_t* out)
{
    uint64_t v = 0;
    int n = 0;
    for (; *s; s++, n++) {
        int d;
        if (*s >= '0' && *s <= '9') d = *s - '0';
        else if (*s >= 'a' && *s <= 'f') d = *s - 'a' + 10;
        else return 0;
        v = v << 4 | (uint64_t)d;
    }
    if (n != 16) return 0;
    *out = v;
    return 1;
}

/* splits s at spaces into at most max tokens; returns the count */
static int split(char* s, char** tok, int max)
{
    int n = 0;
    while (*s) {
        while (*s == ' ') *s++ = 0;
        if (!*s) break;
        if (n == max) return max + 1;
        tok[n++] = s;
        while (*s && *s != ' ') s++;
    }
    return n;
}

static int to_long(const char* s, long lo, long hi, long* out)
{
    long v = 0;
    int neg = 0;
    if (*s == '-') {
        neg = 1;
        s++;
    }
    if (!*s) return 0;
    for (; *s; s++) {
        if (*s < '0' || *s > '9' || v > (LONG_MAX - 9) / 10) return 0;
        v = v * 10 + (*s - '0');
    }
    if (neg) v = -v;
    if (v < lo || v > hi) return 0;
    *out = v;
    return 1;
}

void am_evo_checkpoint_scan_begin(am_evo_ckpt_scan* sc)
{
    memset(sc, 0, sizeof *sc);
    sc->hash = sc->line_hash = sc->prev_hash = AM_HASH_INIT;
}

static void scan_byte(am_evo_ckpt_scan* sc, unsigned char c)
{
    sc->hash = am_hash_bytes(sc->hash, &c, 1);
    sc->bytes++;
    if (c != '\n') {
        if (sc->cur_len < (long)sizeof sc->cur) sc->cur[sc->cur_len] = (char)c;
        sc->cur_len++;
        return;
    }
    /* a whole line: number lines + 1, its first bytes in cur */
    int line = ++sc->lines;
    if (sc->cur_len == 10 && !memcmp(sc->cur, "config-end", 10) && line >= 4 && !sc->config_end) sc->config_end = line;
    if (sc->cur_len == 3 && !memcmp(sc->cur, "end", 3)) sc->last_end = line;
    memcpy(sc->prev, sc->cur, sizeof sc->cur);
    sc->prev_len = sc->cur_len;
    sc->prev_hash = sc->line_hash;
    sc->line_hash = sc->hash;
    sc->cur_len = 0;
}

/* CRLF line ends (a checkpoint that went through a Windows editor or transfer) read as LF: a CR
 * just before a LF is left out, of the checksum too, so the text is the one that was written */
void am_evo_checkpoint_scan(am_evo_ckpt_scan* sc, const char* data, long n)
{
    const unsigned char* p = (const unsigned char*)data;
    for (long i = 0; i < n; i++) {
        unsigned char c = p[i];
        if (sc->cr && c != '\n') scan_byte(sc, '\r'); /* a CR not before a LF is a byte like any other */
        sc->cr = c == '\r';
        if (!sc->cr) scan_byte(sc, c);
    }
}

am_status am_evo_checkpoint_scan_end(am_evo_ckpt_scan* sc, const char* fname, char* err, int errsz)
{
    if (sc->cr) scan_byte(sc, '\r');
    sc->cr = 0;
    if (sc->bytes == 0) return am_fail(err, errsz, AM_ERR_PARSE, "%s:1: empty checkpoint", fname);
    /* the last line: the unfinished one, or the last whole one when the text ends with a newline */
    int ends_nl = sc->cur_len == 0;
    const char* last = ends_nl ? sc->prev : sc->cur;
    long last_len = ends_nl ? sc->prev_len : sc->cur_len;
    uint64_t before = ends_nl ? sc->prev_hash : sc->line_hash;
    int line = ends_nl ? sc->lines : sc->lines + 1;
    uint64_t want;
    if (last_len != 25 || strncmp(last, "checksum ", 9) != 0)
        return am_fail(err, errsz, AM_ERR_PARSE, "%s:%d: missing checksum line (truncated checkpoint?)", fname, line);
    char hex[17];
    memcpy(hex, last + 9, 16);
    hex[16] = 0;
    if (!hex64(hex, &want)) return am_fail(err, errsz, AM_ERR_PARSE, "%s:%d: malformed checksum", fname, line);
    if (before != want) return am_fail(err, errsz, AM_ERR_PARSE, "%s:%d: checksum mismatch: the checkpoint is damaged", fname, line);
    sc->checksum_line = line;
    return AM_OK;
}

#define BAD(...) return r->st = am_fail(err, errsz, AM_ERR_PARSE, __VA_ARGS__)

void am_evo_checkpoint_read_begin(am_evo_ckpt_reader* r, am_evo* e, const am_evo_ckpt_scan* sc, const char* fname)
{
    memset(r, 0, sizeof *r);
    r->e = e;
    r->fname = fname;
    r->until = sc->checksum_line;
    r->config_end = sc->config_end;
    r->last_end = sc->last_end;
    memset(e, 0, sizeof *e);
    e->def = am_stored_evo(); /* a key the checkpoint does not name: as runs made before it had it */
    r->memo_slot = -1;
}

/* an "individual" line (tokens tok): its numbers, then its genome from the next line */
static am_status read_ind(am_evo_ckpt_reader* r, char** tok, int ntok, char* err, int errsz)
{
    am_evo* e = r->e;
    long idx, vox, div, emp, steps, id = -1;
    uint64_t fit, hash;
    const int want = r->version >= 2 ? 10 : 9;
    if (ntok != want || (strcmp(tok[1], "pop") && strcmp(tok[1], "best")) || !to_long(tok[2], 0, AM_MAX_POPULATION - 1, &idx) ||
        !hex64(tok[3], &fit) || !to_long(tok[4], 0, AM_MAX_CELLS, &vox) || !to_long(tok[5], 0, 1, &div) ||
        !to_long(tok[6], 0, 1, &emp) || !to_long(tok[7], 0, 2000000000L, &steps) || !hex64(tok[8], &hash) ||
        (want == 10 && !to_long(tok[9], -1, LONG_MAX, &id)))
        BAD("%s:%d: malformed individual line", r->fname, r->line);
    int is_best = strcmp(tok[1], "best") == 0;
    if (!is_best && idx >= e->def.population)
        BAD("%s:%d: individual %ld beyond the population of %d", r->fname, r->line, idx, e->def.population);
    if (is_best ? r->best_seen : r->pop_have[idx])
        BAD("%s:%d: individual %s %ld given twice", r->fname, r->line, tok[1], is_best ? 0L : idx);
    double f = bits_d(fit);
    if (!isfinite(f)) BAD("%s:%d: fitness of individual %s %ld is not a finite number", r->fname, r->line, tok[1], idx);
    if (is_best) r->best_seen = 1;
    else r->pop_have[idx] = 1;
    am_evo_ind* it = is_best ? &e->best : &e->pop[idx];
    it->id = id;
    it->fitness = f;
    it->voxels = (int)vox;
    it->diverged = (int)div;
    it->empty = (int)emp;
    it->steps = steps;
    it->state_hash = hash;
    if (is_best) e->has_best = 1;
    /* the genome: the lines up to the next "end" line */
    if (r->last_end <= r->line) BAD("%s:%d: genome of individual %ld not closed by 'end'", r->fname, r->until - 1, idx);
    r->ind = it;
    r->ind_pop = !is_best;
    r->idx = idx;
    r->first = r->line + 1;
    snprintf(r->where, sizeof r->where, "%s (genome from line %d)", r->fname, r->first);
    am_genome_read_begin(&r->gr, &it->genome, r->where);
    r->in_genome = 1;
    return AM_OK;
}

/* a line of the genome being read; at its "end" line the genome is checked against the run */
static am_status read_genome_line(am_evo_ckpt_reader* r, const char* text, long n, char* err, int errsz)
{
    char msg[AM_ERR_MAX], cerr[AM_ERR_MAX];
    am_evo* e = r->e;
    if (am_genome_read_line(&r->gr, text, n, msg, sizeof msg) != AM_OK) return r->st = am_fail(err, errsz, AM_ERR_PARSE, "%s", msg);
    if (n != 3 || memcmp(text, "end", 3) != 0) return AM_OK;
    r->in_genome = 0;
    if (am_genome_read_end(&r->gr, msg, sizeof msg) != AM_OK) return r->st = am_fail(err, errsz, AM_ERR_PARSE, "%s", msg);
    const am_genome* g = &r->ind->genome;
    if (g->repr != e->def.geno.repr || g->nx != e->def.geno.nx || g->ny != e->def.geno.ny || g->nz != e->def.geno.nz ||
        g->materials != e->def.geno.materials || g->controls != e->def.geno.controls)
        BAD("%s:%d: genome of individual %ld does not match the run's representation, workspace, materials or evolved fields", r->fname, r->first,
            r->idx);
    if (am_genome_check(g, cerr, sizeof cerr) != AM_OK) BAD("%s:%d: %s", r->fname, r->first, cerr);
    if (r->ind_pop) r->pop_seen++;
    return AM_OK;
}

static int b64_value(char c)
{
    const char* p = c ? strchr(b64, c) : NULL;
    return p ? (int)(p - b64) : -1;
}

/* a remembered body's numbers and cells, read: checked against the run */
static am_status memo_done(am_evo_ckpt_reader* r, char* err, int errsz)
{
    am_evo* e = r->e;
    am_evo_memo* m = &e->memo[r->memo_slot];
    const int n = e->def.geno.nx * e->def.geno.ny * e->def.geno.nz;
    const int count = memo_count(e->def.geno.materials);
    uint64_t v[MEMO_NUMBERS];
    for (int i = 0; i < count; i++) {
        v[i] = 0;
        for (int b = 7; b >= 0; b--) v[i] = v[i] << 8 | r->memo_res[8 * i + b];
    }
    if (!memo_result(v, count, &m->res)) BAD("%s:%d: remembered body %d: a number of its result out of range", r->fname, r->memo_line, r->memo_slot);
    const int mats = e->def.geno.materials;
    for (int c = 0; c < n; c++)
        if (am_evo_packed_cell(m->cells, c, mats) > mats)
            BAD("%s:%d: remembered body %d: a cell beyond the run's %d materials", r->fname, r->memo_line, r->memo_slot, mats);
    for (int c = n; c < 8 / am_evo_cell_bits(mats) * am_evo_packed_bytes(n, mats); c++)
        if (am_evo_packed_cell(m->cells, c, mats)) BAD("%s:%d: remembered body %d: bits past its last cell", r->fname, r->memo_line, r->memo_slot);
    if (am_evo_body_key(m->cells, n, mats, e->def.geno.controls) != m->key) BAD("%s:%d: remembered body %d: its key is not its cells'", r->fname, r->memo_line, r->memo_slot);
    r->memo_slot = -1;
    return AM_OK;
}

/* the "reused", "memo" and "m" lines (tokens tok) */
static am_status read_memo(am_evo_ckpt_reader* r, char** tok, int ntok, char* err, int errsz)
{
    am_evo* e = r->e;
    const char* fname = r->fname;
    if (strcmp(tok[0], "reused") == 0) {
        uint64_t vs;
        if (ntok != 3 || !to_long(tok[1], 0, LONG_MAX, &e->reused) || !hex64(tok[2], &vs) || !isfinite(bits_d(vs)) || bits_d(vs) < 0)
            BAD("%s:%d: malformed 'reused' line", fname, r->line);
        e->reused_voxel_steps = bits_d(vs);
        return AM_OK;
    }
    if (strcmp(tok[0], "memo") == 0) {
        long slot, used, bytes;
        uint64_t key;
        const long want = memo_bytes(e->def.geno.nx * e->def.geno.ny * e->def.geno.nz, e->def.geno.materials, e->def.geno.controls);
        if (r->memo_slot >= 0) BAD("%s:%d: remembered body %d ends early", fname, r->line, r->memo_slot);
        if (ntok != 5 || !to_long(tok[1], 0, AM_EVO_MEMO - 1, &slot) || !to_long(tok[2], -1, LONG_MAX, &used) || !hex64(tok[3], &key) ||
            key == 0 || !to_long(tok[4], 0, LONG_MAX, &bytes))
            BAD("%s:%d: malformed 'memo' line (slots 0 to %d)", fname, r->line, AM_EVO_MEMO - 1);
        if (bytes != want) BAD("%s:%d: remembered body of %ld bytes: the run's take %ld", fname, r->line, bytes, want);
        if (e->memo[slot].key) BAD("%s:%d: remembered body %ld given twice", fname, r->line, slot);
        e->memo[slot].key = key;
        e->memo[slot].used = used;
        r->memo_slot = (int)slot;
        r->memo_line = r->line;
        r->memo_have = 0;
        r->memo_need = bytes;
        return AM_OK;
    }
    /* "m": the next bytes of the remembered body */
    if (r->memo_slot < 0 || ntok != 2) BAD("%s:%d: an 'm' line outside a remembered body", fname, r->line);
    const char* t = tok[1];
    const long len = (long)strlen(t);
    if (len % 4 || len > 4 * MEMO_LINE_BYTES / 3) BAD("%s:%d: malformed base64", fname, r->line);
    am_evo_memo* m = &e->memo[r->memo_slot];
    for (long i = 0; i < len; i += 4) {
        int d[4], pad = 0;
        for (int q = 0; q < 4; q++) {
            d[q] = b64_value(t[i + q]);
            if (t[i + q] == '=' && q >= 2 && i + 4 == len) d[q] = 0, pad++;
            else if (d[q] < 0 || pad) BAD("%s:%d: malformed base64", fname, r->line);
        }
        const unsigned v = (unsigned)d[0] << 18 | (unsigned)d[1] << 12 | (unsigned)d[2] << 6 | (unsigned)d[3];
        for (int q = 0; q < 3 - pad; q++) {
            if (r->memo_have >= r->memo_need) BAD("%s:%d: remembered body %d longer than its %ld bytes", fname, r->line, r->memo_slot, r->memo_need);
            const uint8_t byte = (uint8_t)(v >> (16 - 8 * q));
            const long rb = memo_result_bytes(e->def.geno.materials);
            if (r->memo_have < rb) r->memo_res[r->memo_have] = byte;
            else m->cells[r->memo_have - rb] = byte;
            r->memo_have++;
        }
    }
    return r->memo_have == r->memo_need ? memo_done(r, err, errsz) : AM_OK;
}

am_status am_evo_checkpoint_read_line(am_evo_ckpt_reader* r, char* text, long n, char* err, int errsz)
{
    am_evo* e = r->e;
    char* tok[12];
    if (r->st != AM_OK) return r->st;
    if (n > 0 && text[n - 1] == '\r') text[--n] = 0; /* a CRLF line end, left out by the scan too */
    r->line++;
    if (r->line >= r->until) return AM_OK; /* the checksum line */
    if (r->in_genome) return read_genome_line(r, text, n, err, errsz);
    const char* fname = r->fname;
    char qb[AM_QUOTE_BUF];
    if (r->line == 1) {
        long v;
        int ntok = split(text, tok, 12);
        if (ntok != 2 || strcmp(tok[0], "amorph-checkpoint") != 0) BAD("%s:1: not an amorph checkpoint", fname);
        if (!to_long(tok[1], 0, 1000, &v) || v < 1 || v > CHECKPOINT_VERSION)
            BAD("%s:1: checkpoint version '%s': this build reads versions 1 to %d", fname, am_quote(qb, sizeof qb, tok[1], -1),
                CHECKPOINT_VERSION);
        r->version = (int)v;
        return AM_OK;
    }
    if (r->line == 2) {
        if (strcmp(text, "config-begin") != 0) BAD("%s:%d: expected config-begin", fname, r->line);
        if (!r->config_end) BAD("%s:%d: configuration not closed by config-end", fname, r->line);
        return AM_OK;
    }
    if (r->line < r->config_end) {
        /* the configuration: its own line numbers, counted from the line after config-begin */
        if (am_evo_parse_line(&e->def, text, n, fname, r->line, err, errsz) != AM_OK) return r->st = AM_ERR_PARSE;
        const int key = am_evo_line_key(text, n);
        if (key >= 0 && key < AM_EVO_KEY_MAX) r->key_line[key] = r->line;
        return AM_OK;
    }
    if (r->line == r->config_end) {
        /* a relation between keys: the line of the key it names, else config-end's */
        int key;
        char msg[AM_ERR_MAX];
        if (am_evo_check_key(&e->def, &key, msg, sizeof msg) != AM_OK)
            return r->st = am_fail(err, errsz, AM_ERR_RANGE, "%s:%d: %s", fname,
                                   key >= 0 && key < AM_EVO_KEY_MAX && r->key_line[key] > 0 ? r->key_line[key] : r->line, msg);
        am_evo_palette_into(&e->def, &e->palette);
        return AM_OK;
    }
    int ntok = split(text, tok, 12);
    if (ntok == 0) return AM_OK;
    if (strcmp(tok[0], "rng") == 0 && ntok == 5) {
        for (int i = 0; i < 4; i++)
            if (!hex64(tok[1 + i], &e->rng.s[i])) BAD("%s:%d: malformed rng state", fname, r->line);
        /* xoshiro's one state that never leaves itself: every number after it would be 0 */
        if ((e->rng.s[0] | e->rng.s[1] | e->rng.s[2] | e->rng.s[3]) == 0)
            BAD("%s:%d: rng state all zero (a generator that would only ever give 0: damaged)", fname, r->line);
        r->seen_rng = 1;
    } else if (strcmp(tok[0], "generation") == 0 && ntok == 2 && to_long(tok[1], 0, 2000000000L, &e->generation)) {
        r->seen_gen = 1;
    } else if (strcmp(tok[0], "evaluations") == 0 && ntok == 2 && to_long(tok[1], 0, 2000000000L, &e->evaluations)) {
        r->seen_evals = 1;
    } else if (strcmp(tok[0], "history") == 0 && ntok == 2 && hex64(tok[1], &e->history)) {
        r->seen_hist = 1;
    } else if (strcmp(tok[0], "last") == 0 && (ntok == 9 || ntok == 10)) {
        /* the tenth token, the unsettled evaluations, is absent from checkpoints older than it (0) */
        uint64_t b[4];
        long dv, em, un = 0;
        if (!to_long(tok[1], 0, 2000000000L, &e->last.generation) || !to_long(tok[2], 0, 2000000000L, &e->last.evaluations) ||
            !hex64(tok[3], &b[0]) || !hex64(tok[4], &b[1]) || !hex64(tok[5], &b[2]) || !to_long(tok[6], 0, AM_MAX_POPULATION, &dv) ||
            !to_long(tok[7], 0, AM_MAX_POPULATION, &em) || !hex64(tok[8], &b[3]) ||
            (ntok == 10 && !to_long(tok[9], 0, AM_MAX_POPULATION, &un)))
            BAD("%s:%d: malformed 'last' line", fname, r->line);
        e->last.unsettled = (int)un;
        e->last.best = bits_d(b[0]);
        e->last.mean = bits_d(b[1]);
        e->last.median = bits_d(b[2]);
        e->last.diverged = (int)dv;
        e->last.empty = (int)em;
        e->last.wall_s = bits_d(b[3]);
        if (!isfinite(e->last.best) || !isfinite(e->last.mean) || !isfinite(e->last.median) || !isfinite(e->last.wall_s))
            BAD("%s:%d: 'last' line holds a number that is not finite", fname, r->line);
        r->seen_last = 1;
    } else if (strcmp(tok[0], "individual") == 0) {
        return read_ind(r, tok, ntok, err, errsz);
    } else if (strcmp(tok[0], "reused") == 0 || strcmp(tok[0], "memo") == 0 || strcmp(tok[0], "m") == 0) {
        return read_memo(r, tok, ntok, err, errsz);
    } else {
        BAD("%s:%d: unexpected line '%s'", fname, r->line, am_quote(qb, sizeof qb, tok[0], -1));
    }
    return AM_OK;
}

am_status am_evo_checkpoint_read_end(am_evo_ckpt_reader* r, char* err, int errsz)
{
    if (r->st != AM_OK) return r->st;
    const char* fname = r->fname;
    int read = r->line < r->until ? r->line : r->until - 1; /* lines before the checksum line */
    if (read < 1) BAD("%s:1: not an amorph checkpoint", fname);
    if (read < 2) BAD("%s:%d: expected config-begin", fname, read);
    if (r->in_genome) BAD("%s:%d: genome of individual %ld not closed by 'end'", fname, read, r->idx);
    if (r->memo_slot >= 0) BAD("%s:%d: remembered body %d ends early", fname, read, r->memo_slot);
    if (!r->seen_rng || !r->seen_gen || !r->seen_evals || !r->seen_hist || !r->seen_last)
        BAD("%s:%d: checkpoint misses its rng, generation, evaluations, history or last line", fname, read);
    for (int i = 0; i < r->e->def.population; i++)
        if (!r->pop_have[i]) BAD("%s:%d: individual pop %d missing (the population is %d)", fname, read, i, r->e->def.population);
    return AM_OK;
}

am_status am_evo_checkpoint_parse(am_evo* e, char* text, const char* fname, char* err, int errsz)
{
    am_evo_ckpt_scan sc;
    am_evo_checkpoint_scan_begin(&sc);
    am_evo_checkpoint_scan(&sc, text, (long)strlen(text));
    am_status st = am_evo_checkpoint_scan_end(&sc, fname, err, errsz);
    if (st != AM_OK) return st;
    am_evo_ckpt_reader r;
    am_evo_checkpoint_read_begin(&r, e, &sc, fname);
    for (char* p = text; *p && r.line + 1 < r.until;) {
        char* nl = strchr(p, '\n');
        long n = nl ? (long)(nl - p) : (long)strlen(p);
        if (nl) *nl = 0;
        st = am_evo_checkpoint_read_line(&r, p, n, err, errsz);
        if (nl) *nl = '\n';
        if (st != AM_OK) return st;
        p = nl ? nl + 1 : p + n;
    }
    return am_evo_checkpoint_read_end(&r, err, errsz);
}
