/* The DCT representation (Hiller and Lipson 2009): a k x k x k matrix of frequency amplitudes per
 * material, in [-1, 1], zero-padded to the workspace and turned into a density field by the
 * inverse 3-D DCT (src/base/base_dct.c, orthonormal DCT-III). Amplitude (u, v, w) scales the harmonic with
 * u, v, w half-waves along x, y, z, so a small k gives smooth bodies whatever the workspace size.
 *
 * Mutation (the seed's): each amplitude, with probability def->rate (0.20), moves by a uniform
 * step of at most def->step (5%) of its range [-1, 1] and is reflected back into the range.
 * Crossover: each amplitude comes from either parent with probability 1/2 (the second child takes
 * the other parent's).
 */
#include "geno_internal.h"

#include <string.h>

static int cube(int k) { return k * k * k; }

static am_status dct_check(const am_genome* g, char* err, int errsz)
{
    const am_dct_genome* d = &g->dct;
    if (d->k > AM_MAX_DCT_K)
        return am_fail(err, errsz, AM_ERR_CAPACITY, "DCT k %d exceeds the %s profile's %d", d->k, AM_PROFILE_NAME, AM_MAX_DCT_K);
    if (d->k < 1 || d->k > g->nx || d->k > g->ny || d->k > g->nz)
        return am_fail(err, errsz, AM_ERR_RANGE, "DCT k %d: must be 1 to the smallest workspace side", d->k);
    for (int m = 0; m < am_genome_fields(g); m++)
        for (int i = 0; i < cube(d->k); i++)
            if (!(d->amp[m][i] >= -AM_DCT_AMP_MAX && d->amp[m][i] <= AM_DCT_AMP_MAX))
                return am_fail(err, errsz, AM_ERR_RANGE, "DCT amplitude %d of %s %d outside [-1, 1]", i, am_geno_field_word(g), m);
    return AM_OK;
}

static am_status dct_init(am_genome* g, const am_geno_def* def, am_rng* r, char* err, int errsz)
{
    g->dct.k = def->dct_k;
    if (def->dct_k > AM_MAX_DCT_K)
        return am_fail(err, errsz, AM_ERR_CAPACITY, "DCT k %d exceeds the %s profile's %d", def->dct_k, AM_PROFILE_NAME, AM_MAX_DCT_K);
    if (def->dct_k < 1 || def->dct_k > g->nx || def->dct_k > g->ny || def->dct_k > g->nz)
        return am_fail(err, errsz, AM_ERR_RANGE, "DCT k %d: must be 1 to the smallest workspace side", def->dct_k);
    for (int m = 0; m < am_genome_fields(g); m++)
        for (int i = 0; i < cube(g->dct.k); i++) g->dct.amp[m][i] = am_rng_range(r, -AM_DCT_AMP_MAX, AM_DCT_AMP_MAX);
    return AM_OK;
}

static void dct_mutate(am_genome* g, const am_geno_def* def, am_rng* r)
{
    const am_real step = AM_MUL(def->step, AM_MUL(AM_R(2), AM_DCT_AMP_MAX));
    for (int m = 0; m < am_genome_fields(g); m++)
        for (int i = 0; i < cube(g->dct.k); i++)
            if (am_rng_chance(r, def->rate))
                g->dct.amp[m][i] = am_geno_perturb(r, g->dct.amp[m][i], step, -AM_DCT_AMP_MAX, AM_DCT_AMP_MAX);
}

static void dct_crossover(const am_genome* a, const am_genome* b, am_genome* c1, am_genome* c2,
                          const am_geno_def* def, am_rng* r)
{
    (void)def;
    *c1 = *a;
    if (c2) *c2 = *b;
    for (int m = 0; m < am_genome_fields(a); m++)
        for (int i = 0; i < cube(a->dct.k); i++)
            if (am_rng_below(r, 2)) {
                c1->dct.amp[m][i] = b->dct.amp[m][i];
                if (c2) c2->dct.amp[m][i] = a->dct.amp[m][i];
            }
}

static int dct_same_shape(const am_genome* a, const am_genome* b) { return a->dct.k == b->dct.k; }

static int dct_values(const am_genome* g) { return am_genome_fields(g) * cube(g->dct.k); }

static uint64_t dct_hash(uint64_t h, const am_genome* g)
{
    h = am_hash_u64(h, (uint64_t)g->dct.k);
    for (int m = 0; m < am_genome_fields(g); m++)
        for (int i = 0; i < cube(g->dct.k); i++) h = am_hash_real(h, g->dct.amp[m][i]);
    return h;
}

static int dct_equal(const am_genome* a, const am_genome* b)
{
    if (a->dct.k != b->dct.k) return 0;
    for (int m = 0; m < am_genome_fields(a); m++)
        if (memcmp(a->dct.amp[m], b->dct.amp[m], sizeof(am_real) * (size_t)cube(a->dct.k)) != 0) return 0;
    return 1;
}

static void dct_express(const am_genome* g, am_geno_work* w)
{
    const int k[3] = {g->dct.k, g->dct.k, g->dct.k};
    const int n[3] = {g->nx, g->ny, g->nz};
    am_dct_plan(&w->dct, k, n, NULL, 0); /* k and n were checked with the genome */
    for (int m = 0; m < am_genome_fields(g); m++) am_dct_inverse(&w->dct, &w->scratch.dct, g->dct.amp[m], w->dens[m]);
    am_geno_controls_of_fields(g, w);
}

static void dct_format(const am_genome* g, am_text* s)
{
    const int k = g->dct.k;
    am_text_put(s, "dct %d\n", k);
    am_text_put(s, "# amp MATERIAL V W, then the amplitudes of u = 0..%d\n", k - 1);
    for (int m = 0; m < am_genome_fields(g); m++)
        for (int w = 0; w < k; w++)
            for (int v = 0; v < k; v++) {
                am_text_put(s, "amp %d %d %d", m, v, w);
                for (int u = 0; u < k; u++) am_geno_put_real(s, g->dct.amp[m][u + k * (v + k * w)]);
                am_text_put(s, "\n");
            }
}

static am_status dct_parse_line(am_genome* g, am_geno_parse* ps, int ntok, char** tok, char* err, int errsz)
{
    char q1[AM_QUOTE_BUF], q2[AM_QUOTE_BUF];
    if (!ps->shape) {
        int k = 0;
        if (strcmp(tok[0], "dct") != 0 || ntok != 2)
            return am_fail(err, errsz, AM_ERR_PARSE, "expected 'dct K' (amplitudes per axis)");
        if (!am_geno_tok_int(tok[1], 1, 1000000, &k))
            return am_fail(err, errsz, AM_ERR_PARSE, "DCT k '%s' is not a positive integer", am_quote(q1, sizeof q1, tok[1], -1));
        if (k > AM_MAX_DCT_K)
            return am_fail(err, errsz, AM_ERR_CAPACITY, "DCT k %d exceeds the %s profile's %d", k, AM_PROFILE_NAME, AM_MAX_DCT_K);
        if (k > g->nx || k > g->ny || k > g->nz)
            return am_fail(err, errsz, AM_ERR_RANGE, "DCT k %d exceeds the smallest workspace side", k);
        g->dct.k = k;
        ps->shape = 1;
        return AM_OK;
    }
    const int k = g->dct.k;
    int m, v, w;
    if (strcmp(tok[0], "amp") != 0)
        return am_fail(err, errsz, AM_ERR_PARSE, "unknown line '%s' in a dct genome (expected 'amp' or 'end')",
                       am_quote(q1, sizeof q1, tok[0], -1));
    if (ntok != 4 + k)
        return am_fail(err, errsz, AM_ERR_PARSE, "'amp MATERIAL V W' needs %d amplitudes, found %d", k, ntok - 4 > 0 ? ntok - 4 : 0);
    if (!am_geno_tok_int(tok[1], 0, am_genome_fields(g) - 1, &m))
        return am_fail(err, errsz, AM_ERR_RANGE, "%s '%s' is not 0..%d", am_geno_field_word(g),
                       am_quote(q1, sizeof q1, tok[1], -1), am_genome_fields(g) - 1);
    if (!am_geno_tok_int(tok[2], 0, k - 1, &v) || !am_geno_tok_int(tok[3], 0, k - 1, &w))
        return am_fail(err, errsz, AM_ERR_RANGE, "amplitude row '%s %s' is not 0..%d",
                       am_quote(q1, sizeof q1, tok[2], -1), am_quote(q2, sizeof q2, tok[3], -1), k - 1);
    int id = m * k * k + v + k * w;
    if (ps->seen[id]) return am_fail(err, errsz, AM_ERR_PARSE, "'amp %d %d %d' given twice", m, v, w);
    for (int u = 0; u < k; u++)
        if (!am_geno_tok_real(tok[4 + u], -AM_DCT_AMP_MAX, AM_DCT_AMP_MAX, &g->dct.amp[m][u + k * (v + k * w)]))
            return am_fail(err, errsz, AM_ERR_RANGE, "amplitude '%s' is not a number in [-1, 1]",
                           am_quote(q1, sizeof q1, tok[4 + u], -1));
    ps->seen[id] = 1;
    ps->lines++;
    return AM_OK;
}

static am_status dct_parse_end(am_genome* g, am_geno_parse* ps, char* err, int errsz)
{
    if (!ps->shape) return am_fail(err, errsz, AM_ERR_PARSE, "missing 'dct K' line");
    const int k = g->dct.k;
    for (int m = 0; m < am_genome_fields(g); m++)
        for (int w = 0; w < k; w++)
            for (int v = 0; v < k; v++)
                if (!ps->seen[m * k * k + v + k * w])
                    return am_fail(err, errsz, AM_ERR_PARSE, "missing line 'amp %d %d %d'", m, v, w);
    return AM_OK;
}

const am_geno_ops am_geno_dct_ops = {
    "dct", dct_init, dct_mutate, dct_crossover, dct_same_shape, dct_check, dct_values,
    dct_hash, dct_equal, dct_express, dct_format, dct_parse_line, dct_parse_end,
};
