/* The embedding API (amorph/api.h): one robot, given as text, evaluated on a workspace its caller
 * owns. A thin layer over the others: the genome and lattice readers, the run's expression
 * (am_evo_lattice), am_model_build and am_evaluate, with the settings applied as amorph sim applies
 * its flags, so that a result here is the command's, bit for bit. */
#include "amorph/api.h"

#include <stdint.h>
#include <string.h>

/* the material keys of the configuration, in the order of am_api_work.materials_set's bits */
static const char* const material_keys[] = {"cte", "mu_static", "mu_kinetic", "voxel_size"};
enum { MATERIAL_KEYS = (int)(sizeof material_keys / sizeof material_keys[0]) };

int am_api_version(void)
{
    return AM_API_VERSION;
}

long am_api_work_size(void)
{
    return (long)sizeof(am_api_work);
}

long am_api_result_size(void)
{
    return (long)sizeof(am_result);
}

/* AM_OK when w is a workspace am_api_init prepared */
static am_status ready(const am_api_work* w, char* err, int errsz)
{
    if (!w || w->size != (long)sizeof *w) return am_fail(err, errsz, AM_ERR_ARG, "the workspace is not prepared (am_api_init)");
    return AM_OK;
}

am_status am_api_init(am_api_work* w, long size, char* err, int errsz)
{
    if (!w) return am_fail(err, errsz, AM_ERR_ARG, "no workspace (NULL)");
    if (size < (long)sizeof *w)
        return am_fail(err, errsz, AM_ERR_ARG, "the workspace has %ld bytes; it needs %ld (am_api_work_size)", size, (long)sizeof *w);
    if ((uintptr_t)w % _Alignof(am_api_work) != 0)
        return am_fail(err, errsz, AM_ERR_ARG, "the workspace is not aligned to %d bytes", (int)_Alignof(am_api_work));
    w->def = am_default_evo();
    w->materials_set = 0;
    w->size = (long)sizeof *w;
    return AM_OK;
}

am_status am_api_set(am_api_work* w, const char* key, const char* value, char* err, int errsz)
{
    am_status st = ready(w, err, errsz);
    if (st != AM_OK) return st;
    if (!key || !value) return am_fail(err, errsz, AM_ERR_ARG, "a setting needs a key and a value (NULL)");
    am_evo_def d = w->def;
    st = am_evo_set(&d, key, value, err, errsz);
    if (st != AM_OK) return st;
    /* as amorph sim's flags: the period in steps, and a relaxation no shorter than its minimum */
    if (!strcmp(key, "period_steps")) d.env.period_s = AM_P(0);
    if (!strcmp(key, "relax_max_steps") && d.eval.relax_min_steps > d.eval.relax_max_steps) d.eval.relax_min_steps = d.eval.relax_max_steps;
    for (int k = 0; k < MATERIAL_KEYS; k++)
        if (!strcmp(key, material_keys[k])) w->materials_set |= 1u << k;
    w->def = d;
    return AM_OK;
}

/* the model of w's lattice in w's environment, evaluated into *out (a zero result for an empty body) */
static am_status simulate(am_api_work* w, am_result* out, char* err, int errsz)
{
    am_evo_work* k = &w->work;
    memset(out, 0, sizeof *out);
    am_status st = am_model_build(&k->model, &k->lattice, &w->def.env, err, errsz);
    if (st == AM_ERR_EMPTY) return AM_OK; /* a valid body that goes nowhere: fitness 0 */
    if (st != AM_OK) return st;
    am_eval_def ev = w->def.eval;
    ev.record = NULL;
    ev.gait = NULL;
    am_evaluate(&k->model, &k->state, &ev, out);
    return AM_OK;
}

am_status am_api_eval_genome(am_api_work* w, const char* text, am_result* out, char* err, int errsz)
{
    am_status st = ready(w, err, errsz);
    if (st != AM_OK) return st;
    if (!text || !out) return am_fail(err, errsz, AM_ERR_ARG, "no genome text or no result (NULL)");
    st = am_genome_parse(&w->genome, text, "genome", err, errsz);
    if (st != AM_OK) return st;
    am_evo_palette_into(&w->def, &w->palette);
    char msg[AM_ERR_MAX];
    st = am_evo_lattice(&w->def, &w->palette, &w->genome, &w->work.geno, &w->work.lattice, msg, sizeof msg);
    if (st != AM_OK) return am_fail(err, errsz, st, "genome: %s", msg);
    return simulate(w, out, err, errsz);
}

am_status am_api_eval_lattice(am_api_work* w, const char* text, am_result* out, char* err, int errsz)
{
    am_status st = ready(w, err, errsz);
    if (st != AM_OK) return st;
    if (!text || !out) return am_fail(err, errsz, AM_ERR_ARG, "no lattice text or no result (NULL)");
    am_lattice* lat = &w->work.lattice;
    st = am_lattice_parse(lat, text, "lattice", err, errsz);
    if (st != AM_OK) return st;
    /* the material keys that were set change the lattice's own materials (amorph sim's rule) */
    const am_evo_def* d = &w->def;
    if (w->materials_set & 8u) lat->voxel_size = d->voxel_size;
    for (int m = 0; m < lat->palette.count; m++) {
        am_material* mt = &lat->palette.mat[m];
        if ((w->materials_set & 1u) && mt->cte != AM_P(0)) mt->cte = d->cte;
        if (w->materials_set & 2u) mt->mu_static = d->mu_static;
        if (w->materials_set & 4u) mt->mu_kinetic = d->mu_kinetic;
    }
    return simulate(w, out, err, errsz);
}
