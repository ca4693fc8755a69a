/* A run's tables: log.csv (one row per generation) and evals.csv (one row per evaluation). */
#include "amorph/evolve.h"

#include <math.h>
#include <stdio.h>

const char* am_evo_log_header(void)
{
    return "generation,evaluations,best,mean,median,diverged,empty,wall_s";
}

int am_evo_log_row(const am_evo_stats* s, char* buf, int cap)
{
    int n = snprintf(buf, (size_t)cap, "%ld,%ld,%.9g,%.9g,%.9g,%d,%d,%.3f", s->generation, s->evaluations, s->best, s->mean,
                     s->median, s->diverged, s->empty, s->wall_s);
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
    n += put_len(buf + n, cap - n, ind->diverged ? (double)NAN : ev->dx);
    n += put_len(buf + n, cap - n, ind->diverged ? (double)NAN : ev->dy);
    n += put_len(buf + n, cap - n, ind->diverged ? (double)NAN : ev->dz);
    n += held(snprintf(buf + n, (size_t)(cap - n), ",%d,%d,%d,%ld,%ld,%016llx", ev->settled, ind->diverged, ind->empty,
                       ev->relax_steps, ind->steps, (unsigned long long)ind->state_hash),
              cap - n);
    return n;
}
