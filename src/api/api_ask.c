/* Ask/tell (amorph/api.h): amorph's own genetic operators for a caller's outer loop, genomes as
 * text. Each function is the evolver's step, called the evolver's way: am_genome_init as a run's
 * initial population draws, am_evo_pairing as a generation pairs, crossover then two mutations as
 * a batch breeds, the body distance and am_evo_crowd_straight as crowding decides, so a caller that
 * makes these calls in a run's order gets the run. */
#include "api_internal.h"

#include <string.h>

/* genome text into w->op[k], which must be of w's settings' representation, materials, evolved
 * fields and workspace; what names it in messages */
static am_status read_genome(am_api_work* w, int k, const char* text, const char* what, char* err, int errsz)
{
    if (!text) return am_fail(err, errsz, AM_ERR_ARG, "no %s (NULL)", what);
    am_genome* g = &w->op[k];
    am_status st = am_genome_parse(g, text, what, err, errsz);
    if (st != AM_OK) return st;
    const am_geno_def* d = &w->def.geno;
    if (g->repr != d->repr || g->materials != d->materials || g->controls != d->controls || g->nx != d->nx || g->ny != d->ny ||
        g->nz != d->nz)
        return am_fail(err, errsz, AM_ERR_ARG,
                       "%s: a %s genome of %d materials%s on %dx%dx%d; the settings make %s genomes of %d materials%s on %dx%dx%d", what,
                       am_repr_name(g->repr), g->materials, g->controls ? " and evolved fields" : "", g->nx, g->ny, g->nz,
                       am_repr_name(d->repr), d->materials, d->controls ? " and evolved fields" : "", d->nx, d->ny, d->nz);
    return AM_OK;
}

static am_status write_genome(const am_genome* g, char* out, long cap, char* err, int errsz)
{
    long len = 0;
    if (!out) return am_fail(err, errsz, AM_ERR_ARG, "no output buffer (NULL)");
    return am_genome_format(g, out, cap, &len, err, errsz);
}

/* w's settings as a run holds them: the genomes' evolved fields follow the two keys (am_evo_init's rule) */
static am_geno_def run_geno(const am_api_work* w)
{
    am_geno_def d = w->def.geno;
    d.controls = am_evo_controls(&w->def);
    return d;
}

am_status am_api_seed(am_api_work* w, long seed, char* err, int errsz)
{
    am_status st = am_api_ready(w, err, errsz);
    if (st != AM_OK) return st;
    if (seed < 0) return am_fail(err, errsz, AM_ERR_RANGE, "seed %ld: 0 or more", seed);
    am_rng_seed(&w->rng, (uint64_t)seed);
    return AM_OK;
}

am_status am_api_genome_new(am_api_work* w, char* out, long cap, char* err, int errsz)
{
    am_status st = am_api_ready(w, err, errsz);
    if (st != AM_OK) return st;
    const am_geno_def d = run_geno(w);
    am_rng saved = w->rng;
    if ((st = am_genome_init(&w->op[0], &d, &w->rng, err, errsz)) != AM_OK) return st;
    if ((st = write_genome(&w->op[0], out, cap, err, errsz)) != AM_OK) w->rng = saved; /* nothing drawn for a refusal */
    return st;
}

am_status am_api_pairing(am_api_work* w, int n, int* order, char* err, int errsz)
{
    am_status st = am_api_ready(w, err, errsz);
    if (st != AM_OK) return st;
    if (!order) return am_fail(err, errsz, AM_ERR_ARG, "no order array (NULL)");
    if (n < 2 || n > AM_MAX_POPULATION || n % 2)
        return am_fail(err, errsz, AM_ERR_RANGE, "pairing %d members: an even number from 2 to %d", n, AM_MAX_POPULATION);
    am_evo_pairing(&w->rng, n, order);
    return AM_OK;
}

am_status am_api_offspring(am_api_work* w, const char* a, const char* b, char* out1, char* out2, long cap, char* err,
                           int errsz)
{
    am_status st = am_api_ready(w, err, errsz);
    if (st != AM_OK) return st;
    if ((st = read_genome(w, 0, a, "parent a", err, errsz)) != AM_OK || (st = read_genome(w, 1, b, "parent b", err, errsz)) != AM_OK)
        return st;
    const am_geno_def d = run_geno(w);
    am_rng saved = w->rng;
    if ((st = am_genome_crossover(&w->op[0], &w->op[1], &w->op[2], &w->op[3], &d, &w->rng, err, errsz)) != AM_OK) return st;
    am_genome_mutate(&w->op[2], &d, &w->rng);
    am_genome_mutate(&w->op[3], &d, &w->rng);
    if ((st = write_genome(&w->op[2], out1, cap, err, errsz)) != AM_OK || (st = write_genome(&w->op[3], out2, cap, err, errsz)) != AM_OK)
        w->rng = saved;
    return st;
}

am_status am_api_mutate(am_api_work* w, const char* in, char* out, long cap, char* err, int errsz)
{
    am_status st = am_api_ready(w, err, errsz);
    if (st != AM_OK) return st;
    if ((st = read_genome(w, 0, in, "genome", err, errsz)) != AM_OK) return st;
    const am_geno_def d = run_geno(w);
    am_rng saved = w->rng;
    am_genome_mutate(&w->op[0], &d, &w->rng);
    if ((st = write_genome(&w->op[0], out, cap, err, errsz)) != AM_OK) w->rng = saved;
    return st;
}

/* the crowding distance of w->op[i] and w->op[j] (their bodies do not depend on the palette) */
static am_status op_distance(am_api_work* w, int i, int j, am_real* out, char* err, int errsz)
{
    return am_genome_distance(&w->op[i], &w->op[j], &w->work.geno, out, err, errsz);
}

am_status am_api_distance(am_api_work* w, const char* a, const char* b, double* out, char* err, int errsz)
{
    am_status st = am_api_ready(w, err, errsz);
    if (st != AM_OK) return st;
    if (!out) return am_fail(err, errsz, AM_ERR_ARG, "no output (NULL)");
    if ((st = read_genome(w, 0, a, "genome a", err, errsz)) != AM_OK || (st = read_genome(w, 1, b, "genome b", err, errsz)) != AM_OK)
        return st;
    am_real d = AM_R(0);
    if ((st = op_distance(w, 0, 1, &d, err, errsz)) != AM_OK) return st;
    *out = AM_TO_DOUBLE(d);
    return AM_OK;
}

/* the evolver's rule: a valid body strictly further, or any body against a diverged one (NaN) */
static int better(double child, double parent)
{
    if (child != child) return 0;
    if (parent != parent) return 1;
    return child > parent;
}

am_status am_api_crowd(am_api_work* w, const char* a, double fa, const char* b, double fb, const char* c1, double f1,
                       const char* c2, double f2, int* meets, int* replaces, char* err, int errsz)
{
    am_status st = am_api_ready(w, err, errsz);
    if (st != AM_OK) return st;
    if (!meets || !replaces) return am_fail(err, errsz, AM_ERR_ARG, "no meets or replaces array (NULL)");
    if ((st = read_genome(w, 0, a, "parent a", err, errsz)) != AM_OK || (st = read_genome(w, 1, b, "parent b", err, errsz)) != AM_OK ||
        (st = read_genome(w, 2, c1, "offspring 1", err, errsz)) != AM_OK || (st = read_genome(w, 3, c2, "offspring 2", err, errsz)) != AM_OK)
        return st;
    /* the four distances, each offspring's body against each parent's, as crowding measures them */
    am_real d1a, d1b, d2a, d2b;
    if ((st = op_distance(w, 0, 2, &d1a, err, errsz)) != AM_OK || (st = op_distance(w, 1, 2, &d1b, err, errsz)) != AM_OK ||
        (st = op_distance(w, 0, 3, &d2a, err, errsz)) != AM_OK || (st = op_distance(w, 1, 3, &d2b, err, errsz)) != AM_OK)
        return st;
    const int straight = am_evo_crowd_straight(d1a, d1b, d2a, d2b);
    meets[0] = straight ? 0 : 1;
    meets[1] = straight ? 1 : 0;
    const double parent[2] = {fa, fb};
    replaces[0] = better(f1, parent[meets[0]]);
    replaces[1] = better(f2, parent[meets[1]]);
    return AM_OK;
}
