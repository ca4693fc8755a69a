/* A robot under the caller's control (amorph/api.h, Stepping): opened from its text, settled as an
 * evaluation settles it, then stepped N steps at a time with each voxel's actuation set by the
 * caller or left to the sinusoid, and observed into the caller's arrays. The model is built with a
 * phase per voxel (every phase 0 unless the genome evolved its own), the layout whose per-voxel
 * actuation the step can take over; fed back the sinusoid's own values (am_api_sim_sinusoid) it
 * moves exactly as the open-loop evaluation moves it. */
#include "api_internal.h"

#include <string.h>

/* stepping needs the per-voxel actuation of the desktop profile's model and a genome's layers */
#if AM_GENO_LAYERS && !defined(AM_COMPACT)
#define STEPPING 1
#else
#define STEPPING 0
#endif

/* AM_OK when a robot is open (settled: and settled) */
static am_status is_open(const am_api_work* w, int settled, char* err, int errsz)
{
    am_status st = am_api_ready(w, err, errsz);
    if (st != AM_OK) return st;
    if (w->sim < 1) return am_fail(err, errsz, AM_ERR_ARG, "no robot is open (am_api_sim_open)");
    if (settled && w->sim < 2) return am_fail(err, errsz, AM_ERR_ARG, "the robot is not settled yet (am_api_sim_settle)");
    return AM_OK;
}

am_status am_api_sim_open(am_api_work* w, const char* text, char* err, int errsz)
{
    am_status st = am_api_ready(w, err, errsz);
    if (st != AM_OK) return st;
    w->sim = 0;
    if (!text) return am_fail(err, errsz, AM_ERR_ARG, "no robot text (NULL)");
#if !STEPPING
    return am_fail(err, errsz, AM_ERR_CAPACITY, "stepping a robot under control: the %s profile keeps no actuation per voxel", AM_PROFILE_NAME);
#else
    char msg[AM_ERR_MAX];
    am_evo_work* k = &w->work;
    if (am_vxa_sniff(text)) {
        if ((st = am_api_read_vxa(w, text, err, errsz)) != AM_OK) return st;
    } else if (am_genome_sniff(text)) {
        if ((st = am_genome_parse(&w->genome, text, "genome", err, errsz)) != AM_OK) return st;
        am_evo_palette_into(&w->def, &w->palette);
        if ((st = am_evo_express(&w->def, &w->palette, &w->genome, k, msg, sizeof msg)) != AM_OK)
            return am_fail(err, errsz, st, "genome: %s", msg);
    } else {
        k->has_layers = 0;
        if ((st = am_lattice_parse(&k->lattice, text, "lattice", err, errsz)) != AM_OK) return st;
        am_evo_apply_materials(&w->def, w->materials_set, &k->lattice);
    }
    /* a phase per voxel: the genome's, else 0 everywhere */
    if (!k->has_layers) am_layers_clear(&k->layers);
    if (!k->layers.has_phase) {
        const long cells = (long)k->lattice.nx * k->lattice.ny * k->lattice.nz;
        for (long c = 0; c < cells; c++) k->layers.phase[c] = AM_P(0);
        k->layers.has_phase = 1;
    }
    k->has_layers = 1;
    if ((st = am_model_build_layers(&k->model, &k->lattice, &w->def.env, &k->layers, err, errsz)) != AM_OK) return st;
    int key;
    if ((st = am_evo_check_budget(&w->def, (double)k->model.env.period_steps, &key, err, errsz)) != AM_OK) return st;
    am_state_reset(&k->model, &k->state);
    w->sim = 1;
    return AM_OK;
#endif
}

am_status am_api_sim_settle(am_api_work* w, am_result* out, char* err, int errsz)
{
    am_status st = is_open(w, 0, err, errsz);
    if (st != AM_OK) return st;
    am_result r;
    am_eval_settle(&w->work.model, &w->work.state, &w->def.eval, &r);
    am_eval_actuate(&w->work.state);
    if (out) *out = r;
    w->sim = 2;
    return AM_OK;
}

long am_api_sim_voxels(am_api_work* w, int* material, int* cell)
{
    if (am_api_ready(w, NULL, 0) != AM_OK || w->sim < 1) return -1;
    const am_model* m = &w->work.model;
    for (int i = 0; i < m->nv; i++) {
        if (material) material[i] = m->mat[i];
        if (cell) cell[i] = m->cell[i];
    }
    return m->nv;
}

am_status am_api_sim_step(am_api_work* w, long n, const double* scale, const double* rate, char* err, int errsz)
{
    am_status st = is_open(w, 1, err, errsz);
    if (st != AM_OK) return st;
    if (n < 0 || n > AM_EVAL_MAX_STEPS) return am_fail(err, errsz, AM_ERR_RANGE, "%ld steps: 0 to %.0f a call", n, (double)AM_EVAL_MAX_STEPS);
    const am_model* m = &w->work.model;
    am_state* s = &w->work.state;
    if (!scale && rate) return am_fail(err, errsz, AM_ERR_ARG, "a rate without a scale");
    for (int i = 0; scale && i < m->nv; i++) {
        const double v = scale[i], r = rate ? rate[i] : 0.0;
        if (v != v) continue; /* NaN: the sinusoid's */
        if (!(v >= 0.5 && v <= 2.0) || !(r >= -1e6 && r <= 1e6))
            return am_fail(err, errsz, AM_ERR_RANGE, "voxel %d: scale %g (0.5 to 2) or rate %g 1/s (+-1e6) out of range", i, v, r);
    }
#if STEPPING
    /* the control, held for the n steps */
    s->controlled = 0;
    for (int i = 0; scale && i < m->nv; i++) {
        const int on = scale[i] == scale[i];
        s->controlled |= on;
        s->ctl_on[i] = (uint8_t)on;
        s->ctl_scale[i] = on ? AM_FROM_DOUBLE(scale[i]) : AM_R(1);
        s->ctl_rate[i] = on && rate ? AM_FROM_DOUBLE(rate[i] * am_unit(m, AM_DIM_TIME)) : AM_R(0);
    }
#endif
    for (long k = 0; k < n && !s->diverged; k++) am_step(m, s);
    return AM_OK;
}

am_status am_api_sim_sinusoid(am_api_work* w, double* scale, double* rate, char* err, int errsz)
{
    am_status st = is_open(w, 1, err, errsz);
    if (st != AM_OK) return st;
    if (!scale) return am_fail(err, errsz, AM_ERR_ARG, "no scale array (NULL)");
#if STEPPING
    am_actuation_values(&w->work.model, &w->work.state, scale, rate);
#else
    (void)rate;
#endif
    return AM_OK;
}

am_status am_api_sim_observe(am_api_work* w, am_obs* out, double* pos, double* vel, double* strain, int* contact, char* err, int errsz)
{
    am_status st = is_open(w, 0, err, errsz);
    if (st != AM_OK) return st;
    if (!out) return am_fail(err, errsz, AM_ERR_ARG, "no observation (NULL)");
    am_observe(&w->work.model, &w->work.state, out, pos, vel, strain, contact);
    return AM_OK;
}
