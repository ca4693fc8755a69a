/* Genotypes: what every representation shares.
 *
 * The public operations (am_genome_init, _mutate, _crossover, ...) check and fill the header of a
 * genome (representation, materials, workspace) and hand the rest to the representation's
 * am_geno_ops, found in one table by tag. The helpers below (value perturbation, lookup tables of
 * the activation and falloff functions, token parsing, the text sink) are shared by the
 * representation files so that each of them stays about its own genes.
 *
 * Lookup tables: the CPPN and GMX expressions need e^x and sin x at every cell (tens of thousands
 * of calls per body). am_exp and am_sin (a few ulp, the same bits everywhere) are too slow for that, so both
 * are tabulated once per workspace (AM_GENO_TABLE intervals, filled with am_sin / am_exp) and read
 * with linear interpolation: only + - * / and floor, so the result is the same on every platform.
 * Interpolation error (h^2/8 of the largest second derivative) is at most 1.9e-6 on the desktop
 * profile (4096 intervals: e^-q 1.9e-6, the sigmoid 1.5e-6, sin 2.9e-7) and 4.7e-4 on the board
 * (256: 4.7e-4, 3.8e-4, 7.5e-5): the genotype-to-body map is a fixed, deterministic function
 * either way.
 */
#include "geno_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "amorph/base.h"

/* the names of a def that names no material: the seed's three (a def of more names them all) */
static const char* const seed_names[3] = {"passive", "active", "active90"};

am_geno_def am_default_geno(void)
{
    am_geno_def d;
    memset(&d, 0, sizeof d);
    d.repr = AM_REPR_DCT;
    d.materials = 2;
    d.nx = d.ny = d.nz = AM_MAX_DIM;
    d.dct_k = 4;
    d.cppn_layers = 3;
    d.cppn_nodes = 4;
    d.cppn_active = AM_R(0.75);
    d.cppn_changes = AM_R(1);
    d.cppn_step = AM_R(0.10);
    d.gmx_points = 16;
    d.gmx_max_points = AM_MAX_GMX_POINTS;
    d.rate = AM_R(0.20);
    d.step = AM_R(0.05);
    d.gmx_material_rate = AM_R(0.05);
    d.gmx_add = AM_R(0.10);
    d.gmx_remove = AM_R(0.10);
    return d;
}

am_express_def am_default_express(void)
{
    am_express_def d;
    d.palette = NULL;
    d.voxel_size = AM_P(0.01);
    d.threshold = AM_R(0);
    d.stiffness_min = AM_P(1e5);
    d.stiffness_max = AM_P(1e7);
    return d;
}

/* ---- dispatch ---- */

const am_geno_ops* am_geno_ops_of(int repr)
{
    switch (repr) {
    case AM_REPR_DCT: return &am_geno_dct_ops;
    case AM_REPR_CPPN: return &am_geno_cppn_ops;
    case AM_REPR_GMX: return &am_geno_gmx_ops;
    default: return NULL;
    }
}

const char* am_repr_name(int repr)
{
    const am_geno_ops* ops = am_geno_ops_of(repr);
    return ops ? ops->name : "?";
}

int am_repr_from_name(const char* name)
{
    for (int r = 1; r < AM_REPR_COUNT; r++)
        if (strcmp(am_geno_ops_of(r)->name, name) == 0) return r;
    return AM_REPR_NONE;
}

/* length of a name held in a field of AM_NAME_MAX characters (AM_NAME_MAX when unterminated) */
static size_t name_len(const char* s)
{
    size_t n = 0;
    while (n < AM_NAME_MAX && s[n]) n++;
    return n;
}

static am_status check_header(const am_genome* g, char* err, int errsz)
{
    if (!am_geno_ops_of(g->repr)) return am_fail(err, errsz, AM_ERR_RANGE, "unknown representation %d", g->repr);
    if (g->materials < 1 || g->materials > AM_MAX_GENO_MATERIALS)
        return am_fail(err, errsz, g->materials < 1 ? AM_ERR_RANGE : AM_ERR_CAPACITY,
                       "%d materials: a genome holds 1 to %d", g->materials, AM_MAX_GENO_MATERIALS);
    if (g->nx < 1 || g->ny < 1 || g->nz < 1)
        return am_fail(err, errsz, AM_ERR_RANGE, "workspace %d x %d x %d: every side must be at least 1", g->nx, g->ny, g->nz);
    if (g->nx > AM_MAX_DIM || g->ny > AM_MAX_DIM || g->nz > AM_MAX_DIM)
        return am_fail(err, errsz, AM_ERR_CAPACITY, "workspace %d x %d x %d exceeds the %s profile's %d per side",
                       g->nx, g->ny, g->nz, AM_PROFILE_NAME, AM_MAX_DIM);
    if (g->controls & ~AM_CTL_ALL) return am_fail(err, errsz, AM_ERR_RANGE, "evolved fields %d: not a set of phase (1) and stiffness (2)", g->controls);
    if (g->controls && !AM_GENO_LAYERS)
        return am_fail(err, errsz, AM_ERR_CAPACITY, "an evolved %s: the %s profile keeps no phase or stiffness per voxel (AM_GENO_LAYERS 0)",
                       g->controls & AM_CTL_PHASE ? "phase" : "stiffness", AM_PROFILE_NAME);
    for (int m = 0; m < g->materials; m++) {
        size_t n = name_len(g->mat[m]);
        if (n == 0 || n >= AM_NAME_MAX) return am_fail(err, errsz, AM_ERR_RANGE, "material %d has no valid name", m);
        for (int k = 0; k < m; k++)
            if (strncmp(g->mat[k], g->mat[m], AM_NAME_MAX) == 0)
                return am_fail(err, errsz, AM_ERR_RANGE, "material '%.*s' given twice", (int)n, g->mat[m]);
    }
    return AM_OK;
}

am_status am_genome_check(const am_genome* g, char* err, int errsz)
{
    am_status st = check_header(g, err, errsz);
    if (st != AM_OK) return st;
    return am_geno_ops_of(g->repr)->check(g, err, errsz);
}

am_status am_genome_init(am_genome* g, const am_geno_def* def, am_rng* r, char* err, int errsz)
{
    memset(g, 0, sizeof *g);
    g->repr = def->repr;
    g->materials = def->materials;
    g->controls = def->controls;
    g->nx = def->nx;
    g->ny = def->ny;
    g->nz = def->nz;
    for (int m = 0; m < def->materials && m < AM_MAX_GENO_MATERIALS; m++)
        snprintf(g->mat[m], AM_NAME_MAX, "%s", def->mat[m][0] ? def->mat[m] : m < 3 ? seed_names[m] : "");
    am_status st = check_header(g, err, errsz);
    if (st != AM_OK) return st;
    return am_geno_ops_of(g->repr)->init(g, def, r, err, errsz);
}

void am_genome_mutate(am_genome* g, const am_geno_def* def, am_rng* r)
{
    const am_geno_ops* ops = am_geno_ops_of(g->repr);
    if (ops) ops->mutate(g, def, r);
}

static int same_header(const am_genome* a, const am_genome* b)
{
    if (a->repr != b->repr || a->materials != b->materials || a->controls != b->controls || a->nx != b->nx ||
        a->ny != b->ny || a->nz != b->nz)
        return 0;
    for (int m = 0; m < a->materials; m++)
        if (strcmp(a->mat[m], b->mat[m]) != 0) return 0;
    return 1;
}

am_status am_genome_crossover(const am_genome* a, const am_genome* b, am_genome* c1, am_genome* c2,
                              const am_geno_def* def, am_rng* r, char* err, int errsz)
{
    const am_geno_ops* ops = am_geno_ops_of(a->repr);
    if (!ops || !same_header(a, b) || !ops->same_shape(a, b)) {
        *c1 = *a;
        if (c2) *c2 = *b;
        return am_fail(err, errsz, AM_ERR_ARG, "crossover of genomes of different representation or shape");
    }
    ops->crossover(a, b, c1, c2, def, r);
    return AM_OK;
}

int am_genome_values(const am_genome* g)
{
    const am_geno_ops* ops = am_geno_ops_of(g->repr);
    return ops ? ops->values(g) : 0;
}

uint64_t am_genome_hash(const am_genome* g)
{
    uint64_t h = AM_HASH_INIT;
    h = am_hash_u64(h, (uint64_t)g->repr);
    h = am_hash_u64(h, (uint64_t)g->materials);
    h = am_hash_u64(h, (uint64_t)g->nx);
    h = am_hash_u64(h, (uint64_t)g->ny);
    h = am_hash_u64(h, (uint64_t)g->nz);
    for (int m = 0; m < g->materials && m < AM_MAX_GENO_MATERIALS; m++)
        h = am_hash_bytes(h, g->mat[m], (unsigned long)name_len(g->mat[m]));
    if (g->controls) h = am_hash_u64(h, 0x100u | (uint64_t)g->controls); /* none: the hash of a genome before them */
    const am_geno_ops* ops = am_geno_ops_of(g->repr);
    return ops ? ops->hash(h, g) : h;
}

int am_genome_equal(const am_genome* a, const am_genome* b)
{
    if (!same_header(a, b)) return 0;
    const am_geno_ops* ops = am_geno_ops_of(a->repr);
    return ops ? ops->equal(a, b) : 1;
}

/* ---- helpers for the representations ---- */

void am_geno_controls_of_fields(const am_genome* g, am_geno_work* w)
{
#if AM_GENO_LAYERS
    const int cells = g->nx * g->ny * g->nz;
    const int ph = am_genome_field_of(g, AM_CTL_PHASE), st = am_genome_field_of(g, AM_CTL_STIFFNESS);
    if (ph >= 0)
        for (int c = 0; c < cells; c++) w->dens[ph][c] = AM_MUL(w->dens[ph][c], AM_R(0.5));
    if (st >= 0)
        for (int c = 0; c < cells; c++) w->dens[st][c] = am_clamp(AM_MUL(w->dens[st][c] + AM_R(1), AM_R(0.5)), AM_R(0), AM_R(1));
#else
    (void)g;
    (void)w;
#endif
}

am_real am_geno_perturb(am_rng* r, am_real v, am_real step, am_real lo, am_real hi)
{
    am_real x = v + am_rng_range(r, -step, step);
    if (x > hi) x = hi - (x - hi);
    if (x < lo) x = lo + (lo - x);
    return am_clamp(x, lo, hi);
}

void am_geno_tables(am_geno_work* w)
{
    if (w->tables) return;
#if defined(AM_REAL_FIXED_POINT)
    /* the same tables from integer arguments (the table index range is beyond Q7.24); the sigmoid
     * as (1 - e^-|t|) / (1 + e^-|t|) with the sign of t, since e^16 is beyond the range */
    for (int i = 0; i <= AM_GENO_TABLE; i++) {
        int q = i % AM_GENO_TABLE;
        w->tab_sin[i] = am_sin(AM_RATIO((int64_t)AM_R(6.283185307179586477) * q, (int64_t)AM_GENO_TABLE * AM_FIX_ONE));
        w->tab_gauss[i] = am_exp(-AM_RATIO(16 * i, AM_GENO_TABLE));
        am_real t = AM_RATIO(16 * (2 * i - AM_GENO_TABLE), AM_GENO_TABLE), e = am_exp(-am_fabs(t));
        am_real v = AM_DIV(AM_R(1) - e, AM_R(1) + e);
        w->tab_sig[i] = t < 0 ? -v : v;
    }
#else
    const am_real T = (am_real)AM_GENO_TABLE;
    for (int i = 0; i <= AM_GENO_TABLE; i++) {
        am_real fi = (am_real)i;
        int q = i % AM_GENO_TABLE; /* exact quarter turns for sin(0), sin(pi/2), ... */
        w->tab_sin[i] = am_sin(AM_DIV(AM_MUL(AM_MUL(AM_R(2), AM_PI), (am_real)q), T));
        w->tab_gauss[i] = am_exp(-AM_DIV(AM_MUL(AM_GENO_GAUSS_RANGE, fi), T));
        am_real t = AM_MUL(AM_GENO_SIG_RANGE, AM_DIV(AM_R(2) * fi, T) - AM_R(1));
        w->tab_sig[i] = AM_DIV(AM_R(2), AM_R(1) + am_exp(-t)) - AM_R(1);
    }
#endif
    w->tables = 1;
}

void am_geno_put_real(am_text* s, am_real v)
{
#if defined(AM_REAL_DOUBLE)
    am_text_put(s, " %.17g", v);
#elif defined(AM_REAL_FIXED_POINT)
    am_text_put(s, " %.17g", AM_TO_DOUBLE(v)); /* exact: a Q24 value is a short binary fraction */
#else
    am_text_put(s, " %.9g", (double)v);
#endif
}

int am_geno_tok_int(const char* s, int lo, int hi, int* out)
{
    long v = 0;
    int neg = 0;
    if (*s == '-' || *s == '+') neg = *s++ == '-';
    if (!*s) return 0;
    for (; *s; s++) {
        if (*s < '0' || *s > '9') return 0;
        v = v * 10 + (*s - '0');
        if (v > 1000000000L) return 0;
    }
    if (neg) v = -v;
    if (v < lo || v > hi) return 0;
    *out = (int)v;
    return 1;
}

int am_geno_tok_real(const char* s, am_real lo, am_real hi, am_real* out)
{
    char* end = NULL;
    if (!*s) return 0;
    double d = strtod(s, &end);
    if (!end || *end) return 0;
#if defined(AM_REAL_FIXED_POINT)
    if (!(d >= AM_TO_DOUBLE(lo) && d <= AM_TO_DOUBLE(hi))) return 0;
#endif
    am_real v = AM_FROM_DOUBLE(d);
    if (!am_finite(v) || !(v >= lo && v <= hi)) return 0;
    *out = v;
    return 1;
}
