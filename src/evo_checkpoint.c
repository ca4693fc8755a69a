/* Checkpoints of a run: a text file holding the configuration, the random stream, the counters,
 * the population and the best individual, closed by a checksum line over everything before it.
 * Reals of the genomes are written so they read back bit for bit; fitness values (doubles) as
 * the hexadecimal digits of their bit patterns, so a checkpoint is exact on every platform.
 *
 *   amorph-checkpoint 1
 *   config-begin
 *   key = value ...            (am_evo_format, runtime keys included)
 *   config-end
 *   rng HEX HEX HEX HEX
 *   generation G
 *   evaluations N
 *   history HEX
 *   last G N BEST MEAN MEDIAN DIVERGED EMPTY WALL   (doubles as HEX bit patterns)
 *   individual pop|best INDEX FITNESS VOXELS DIVERGED EMPTY STEPS STATEHASH
 *   amorph-genome 1 ... end    (the individual's genome, am_genome_format)
 *   ...
 *   checksum HEX               (am_hash_bytes of every byte before this line)
 */
#include "amorph/evolve.h"

#include <limits.h>
#include <stdio.h>
#include <string.h>

#define CHECKPOINT_VERSION 1

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
 * the caller's output, so the checksum needs no copy of the whole text */
typedef struct ck_pass {
    am_text* out;
    uint64_t hash;            /* am_hash_bytes of every byte handed on */
} ck_pass;

static am_status ck_flush(void* ctx, const char* data, long n)
{
    ck_pass* c = (ck_pass*)ctx;
    c->hash = am_hash_bytes(c->hash, data, (unsigned long)n);
    am_text_write(c->out, data, n);
    return c->out->full ? AM_ERR_IO : AM_OK;
}

/* one individual line and its genome; a genome that fails its check is not written and its
 * message kept in err (the first one counts) */
static void put_ind(am_text* s, const char* kind, int index, const am_evo_ind* it, char* err, int errsz, am_status* st)
{
    am_text_put(s, "individual %s %d %016llx %d %d %d %ld %016llx\n", kind, index, dbits(it->fitness), it->voxels, it->diverged,
                it->empty, it->steps, (unsigned long long)it->state_hash);
    char msg[AM_ERR_MAX];
    am_status c = am_genome_check(&it->genome, msg, sizeof msg);
    if (c != AM_OK) {
        if (*st == AM_OK) *st = am_fail(err, errsz, c, "%s", msg);
        return;
    }
    am_genome_write(&it->genome, s, NULL, 0); /* only the output can fail now: seen at the end */
}

am_status am_evo_checkpoint_write(const am_evo* e, am_text* out, char* err, int errsz)
{
    char piece[320]; /* longer than any one piece the writers put */
    ck_pass pass = {out, AM_HASH_INIT};
    am_text s = {piece, sizeof piece, 0, 0, ck_flush, &pass, 0};
    am_status st = AM_OK;
    piece[0] = 0;
    am_text_put(&s, "amorph-checkpoint %d\nconfig-begin\n", CHECKPOINT_VERSION);
    am_evo_write(&e->def, 1, &s, NULL, 0);
    am_text_put(&s, "config-end\nrng %016llx %016llx %016llx %016llx\n", (unsigned long long)e->rng.s[0],
                (unsigned long long)e->rng.s[1], (unsigned long long)e->rng.s[2], (unsigned long long)e->rng.s[3]);
    am_text_put(&s, "generation %ld\nevaluations %ld\nhistory %016llx\n", e->generation, e->evaluations,
                (unsigned long long)e->history);
    am_text_put(&s, "last %ld %ld %016llx %016llx %016llx %d %d %016llx\n", e->last.generation, e->last.evaluations,
                dbits(e->last.best), dbits(e->last.mean), dbits(e->last.median), e->last.diverged, e->last.empty,
                dbits(e->last.wall_s));
    for (int i = 0; i < e->def.population; i++) put_ind(&s, "pop", i, &e->pop[i], err, errsz, &st);
    if (e->has_best) put_ind(&s, "best", 0, &e->best, err, errsz, &st);
    if (st != AM_OK) return st;
    if (am_text_flush(&s) == AM_OK) am_text_put(out, "checksum %016llx\n", (unsigned long long)pass.hash);
    if (out->full == 1) return am_fail(err, errsz, AM_ERR_CAPACITY, "checkpoint needs more than the %ld bytes given", out->cap);
    if (out->full || s.full) return am_fail(err, errsz, AM_ERR_IO, "checkpoint: the output failed");
    return AM_OK;
}

am_status am_evo_checkpoint_format(const am_evo* e, char* buf, long cap, long* len, char* err, int errsz)
{
    am_text t = {buf, cap, 0, 0, NULL, NULL, 0};
    if (len) *len = 0;
    if (!buf || cap < 1) return am_fail(err, errsz, AM_ERR_CAPACITY, "checkpoint: no buffer");
    buf[0] = 0;
    am_status st = am_evo_checkpoint_write(e, &t, err, errsz);
    if (len) *len = t.len;
    if (st == AM_ERR_CAPACITY && t.full) {
        /* the length it needs: the text again through a counting stream */
        char piece[64];
        am_text c = {piece, sizeof piece, 0, 0, am_text_drop, NULL, 0};
        am_evo_checkpoint_write(e, &c, NULL, 0);
        if (len) *len = c.done + c.len;
        return am_fail(err, errsz, st, "checkpoint needs %ld bytes, the buffer holds %ld", c.done + c.len + 1, cap);
    }
    return st;
}

/* ---- reading ---- */

typedef struct reader {
    char* p;            /* next line */
    int line;           /* line number of the last line returned */
    const char* fname;
} reader;

/* the next line, NUL-terminated in place (the newline is overwritten); NULL at the end */
static char* next_line(reader* r, char** restore)
{
    if (!*r->p) return NULL;
    char* s = r->p;
    char* nl = strchr(s, '\n');
    r->line++;
    if (nl) {
        *nl = 0;
        *restore = nl;
        r->p = nl + 1;
    } else {
        *restore = NULL;
        r->p = s + strlen(s);
    }
    return s;
}

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

#define BAD(...) return am_fail(err, errsz, AM_ERR_PARSE, __VA_ARGS__)

static am_status read_ind(reader* r, am_evo* e, char** tok, int ntok, char* err, int errsz)
{
    long idx, vox, div, emp, steps;
    uint64_t fit, hash;
    if (ntok != 9 || (strcmp(tok[1], "pop") && strcmp(tok[1], "best")) || !to_long(tok[2], 0, AM_MAX_POPULATION - 1, &idx) ||
        !hex64(tok[3], &fit) || !to_long(tok[4], 0, AM_MAX_CELLS, &vox) || !to_long(tok[5], 0, 1, &div) ||
        !to_long(tok[6], 0, 1, &emp) || !to_long(tok[7], 0, 2000000000L, &steps) || !hex64(tok[8], &hash))
        BAD("%s:%d: malformed individual line", r->fname, r->line);
    int is_best = strcmp(tok[1], "best") == 0;
    if (!is_best && idx >= e->def.population) BAD("%s:%d: individual %ld beyond the population of %d", r->fname, r->line, idx, e->def.population);
    am_evo_ind* it = is_best ? &e->best : &e->pop[idx];
    it->fitness = bits_d(fit);
    it->voxels = (int)vox;
    it->diverged = (int)div;
    it->empty = (int)emp;
    it->steps = steps;
    it->state_hash = hash;
    if (is_best) e->has_best = 1;
    /* the genome: lines up to "end", parsed in place */
    char* start = r->p;
    int first = r->line + 1;
    char* end = NULL;
    for (;;) {
        char* restore = NULL;
        char* s = next_line(r, &restore);
        if (!s) BAD("%s:%d: genome of individual %ld not closed by 'end'", r->fname, r->line, idx);
        int is_end = strcmp(s, "end") == 0;
        if (restore) *restore = '\n';
        if (is_end) {
            end = r->p;
            break;
        }
    }
    char saved = *end;
    *end = 0;
    char msg[AM_ERR_MAX], where[96];
    snprintf(where, sizeof where, "%s (genome from line %d)", r->fname, first);
    am_status st = am_genome_parse(&it->genome, start, where, msg, sizeof msg);
    *end = saved;
    if (st != AM_OK) return am_fail(err, errsz, AM_ERR_PARSE, "%s", msg);
    char cerr[AM_ERR_MAX];
    if (it->genome.repr != e->def.geno.repr || it->genome.nx != e->def.geno.nx || it->genome.ny != e->def.geno.ny ||
        it->genome.nz != e->def.geno.nz || it->genome.materials != e->def.geno.materials)
        BAD("%s:%d: genome of individual %ld does not match the run's representation, workspace or materials", r->fname, first, idx);
    if (am_genome_check(&it->genome, cerr, sizeof cerr) != AM_OK) BAD("%s:%d: %s", r->fname, first, cerr);
    return AM_OK;
}

am_status am_evo_checkpoint_parse(am_evo* e, char* text, const char* fname, char* err, int errsz)
{
    /* the checksum first: the last line must be "checksum HEX" over every byte before it */
    size_t n = strlen(text);
    if (n == 0) BAD("%s:1: empty checkpoint", fname);
    size_t body = n;
    if (text[body - 1] == '\n') body--;
    size_t ls = body;
    while (ls > 0 && text[ls - 1] != '\n') ls--;
    int lines = 1;
    for (size_t i = 0; i < ls; i++) lines += text[i] == '\n';
    uint64_t want;
    if (body - ls != 25 || strncmp(text + ls, "checksum ", 9) != 0) BAD("%s:%d: missing checksum line (truncated checkpoint?)", fname, lines);
    char hex[17];
    memcpy(hex, text + ls + 9, 16);
    hex[16] = 0;
    if (!hex64(hex, &want)) BAD("%s:%d: malformed checksum", fname, lines);
    if (am_hash_bytes(AM_HASH_INIT, text, (unsigned long)ls) != want)
        BAD("%s:%d: checksum mismatch: the checkpoint is damaged", fname, lines);
    char saved_end = text[ls];
    text[ls] = 0;

    am_status st = AM_OK;
    reader r = {text, 0, fname};
    char* restore = NULL;
    char* tok[12];
    memset(e, 0, sizeof *e);
    e->def = am_default_evo();
    char* s = next_line(&r, &restore);
    int ntok = s ? split(s, tok, 12) : 0;
    long v;
    if (ntok != 2 || strcmp(tok[0], "amorph-checkpoint") != 0) {
        st = am_fail(err, errsz, AM_ERR_PARSE, "%s:1: not an amorph checkpoint", fname);
        goto done;
    }
    if (!to_long(tok[1], 0, 1000, &v) || v != CHECKPOINT_VERSION) {
        st = am_fail(err, errsz, AM_ERR_PARSE, "%s:1: checkpoint version '%s': this build reads version %d", fname, tok[1], CHECKPOINT_VERSION);
        goto done;
    }
    s = next_line(&r, &restore);
    if (!s || strcmp(s, "config-begin") != 0) {
        st = am_fail(err, errsz, AM_ERR_PARSE, "%s:%d: expected config-begin", fname, r.line);
        goto done;
    }
    {
        char* cfg = r.p;
        int cfg_line = r.line;
        char* cfg_end = strstr(cfg, "\nconfig-end\n");
        if (!cfg_end) {
            st = am_fail(err, errsz, AM_ERR_PARSE, "%s:%d: configuration not closed by config-end", fname, r.line);
            goto done;
        }
        cfg_end[1] = 0;
        char msg[AM_ERR_MAX];
        st = am_evo_parse(&e->def, cfg, fname, msg, sizeof msg);
        cfg_end[1] = 'c';
        if (st != AM_OK) {
            (void)cfg_line;
            st = am_fail(err, errsz, AM_ERR_PARSE, "%s (checkpoint configuration, after line %d)", msg, cfg_line);
            goto done;
        }
        for (char* q = cfg; q <= cfg_end; q++) r.line += *q == '\n';
        r.p = cfg_end + 1;
        s = next_line(&r, &restore); /* config-end */
        st = am_evo_check(&e->def, err, errsz);
        if (st != AM_OK) goto done;
        e->palette = am_evo_palette(&e->def);
    }
    int seen_last = 0, seen_rng = 0, seen_gen = 0, seen_evals = 0, seen_hist = 0, pop_seen = 0;
    while ((s = next_line(&r, &restore)) != NULL) {
        ntok = split(s, tok, 12);
        if (ntok == 0) continue;
        if (strcmp(tok[0], "rng") == 0 && ntok == 5) {
            for (int i = 0; i < 4; i++)
                if (!hex64(tok[1 + i], &e->rng.s[i])) {
                    st = am_fail(err, errsz, AM_ERR_PARSE, "%s:%d: malformed rng state", fname, r.line);
                    goto done;
                }
            seen_rng = 1;
        } else if (strcmp(tok[0], "generation") == 0 && ntok == 2 && to_long(tok[1], 0, 2000000000L, &e->generation)) {
            seen_gen = 1;
        } else if (strcmp(tok[0], "evaluations") == 0 && ntok == 2 && to_long(tok[1], 0, 2000000000L, &e->evaluations)) {
            seen_evals = 1;
        } else if (strcmp(tok[0], "history") == 0 && ntok == 2 && hex64(tok[1], &e->history)) {
            seen_hist = 1;
        } else if (strcmp(tok[0], "last") == 0 && ntok == 9) {
            uint64_t b[4];
            long dv, em;
            if (!to_long(tok[1], 0, 2000000000L, &e->last.generation) || !to_long(tok[2], 0, 2000000000L, &e->last.evaluations) ||
                !hex64(tok[3], &b[0]) || !hex64(tok[4], &b[1]) || !hex64(tok[5], &b[2]) || !to_long(tok[6], 0, AM_MAX_POPULATION, &dv) ||
                !to_long(tok[7], 0, AM_MAX_POPULATION, &em) || !hex64(tok[8], &b[3])) {
                st = am_fail(err, errsz, AM_ERR_PARSE, "%s:%d: malformed 'last' line", fname, r.line);
                goto done;
            }
            e->last.best = bits_d(b[0]);
            e->last.mean = bits_d(b[1]);
            e->last.median = bits_d(b[2]);
            e->last.diverged = (int)dv;
            e->last.empty = (int)em;
            e->last.wall_s = bits_d(b[3]);
            seen_last = 1;
        } else if (strcmp(tok[0], "individual") == 0) {
            st = read_ind(&r, e, tok, ntok, err, errsz);
            if (st != AM_OK) goto done;
            if (strcmp(tok[1], "pop") == 0) pop_seen++;
            continue;
        } else {
            st = am_fail(err, errsz, AM_ERR_PARSE, "%s:%d: unexpected line '%s'", fname, r.line, tok[0]);
            goto done;
        }
        if (restore) *restore = '\n';
    }
    if (!seen_rng || !seen_gen || !seen_evals || !seen_hist || !seen_last)
        st = am_fail(err, errsz, AM_ERR_PARSE, "%s: checkpoint misses its rng, generation, evaluations, history or last line", fname);
    else if (pop_seen != e->def.population)
        st = am_fail(err, errsz, AM_ERR_PARSE, "%s: checkpoint holds %d individuals, the population is %d", fname, pop_seen, e->def.population);
done:
    text[ls] = saved_end;
    return st;
}
