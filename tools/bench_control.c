/* amorph bench --control: the cost of stepping a robot under control through the embedding API
 * (amorph/api.h, Stepping) against amorph sim's open-loop step, on the same motion. For each scene
 * (cube:10, sphere:20) after the evaluation's relaxation: sim's actuated steps (am_steps on the
 * plain model); the same steps in one am_api_sim_step call (the model with a phase per voxel, the
 * layout stepping needs); and in calls of 1, 10 and 100 steps, each passing an action for every
 * voxel (all NaN: each voxel keeps its sinusoid, so the motion is sim's and only the calls cost).
 * Prints ns per voxel step of each and the overhead over sim, best of --repeat runs in turns. Then
 * calls of 1, 10 and 100 steps with a target for every voxel (its sinusoid's value at the call,
 * held for the call): every voxel under control; in calls of one step that is sim's motion bit for
 * bit, in longer calls a staircase of it, where a voxel's held scale parts from its material's and
 * its links take rest lengths of their own. */
#include "evolve_cmd.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#if defined(AM_PROFILE_BOARD) || !AM_GENO_LAYERS
int tool_bench_control(tool_ctx* c, long steps, int repeat)
{
    (void)c, (void)steps, (void)repeat;
    return tool_not_in_build("bench --control", "stepping under control");
}
#else

static am_api_work g_bench_api;
static char g_bench_text[1L << 22];
static double g_bench_scale[AM_MAX_VOXELS], g_bench_target[AM_MAX_VOXELS];

/* seconds of `steps` open-loop actuated steps of lat after the relaxation, as amorph sim steps */
static double time_sim(tool_ctx* c, const am_lattice* lat, long steps, char* err, int errsz)
{
    am_evo_work* w = &c->work[0];
    if (am_model_build(&w->model, lat, &g_bench_api.def.env, err, errsz) != AM_OK) return -1;
    am_result r;
    am_eval_settle(&w->model, &w->state, &g_bench_api.def.eval, &r);
    am_eval_actuate(&w->state);
    double t0 = am_port_now();
    am_steps(&w->model, &w->state, steps);
    return am_port_now() - t0;
}

/* seconds of the same steps through the API: one call (every 0), or calls of `every` steps each
 * passing an action for every voxel: NaN (each keeps its sinusoid), or with targets set each voxel's
 * sinusoid's value at the call, held for the call's steps (every voxel under control) */
static double time_control(long steps, long every, int targets, char* err, int errsz)
{
    am_api_work* w = &g_bench_api;
    if (am_api_sim_open(w, g_bench_text, err, errsz) != AM_OK || am_api_sim_settle(w, NULL, err, errsz) != AM_OK) return -1;
    double t0 = am_port_now();
    if (every == 0) {
        if (am_api_sim_step(w, steps, NULL, NULL, err, errsz) != AM_OK) return -1;
    } else
        for (long k = 0; k < steps; k += every)
            if ((targets && am_api_sim_sinusoid(w, g_bench_target, NULL, err, errsz) != AM_OK) ||
                am_api_sim_step(w, every, targets ? g_bench_target : g_bench_scale, NULL, err, errsz) != AM_OK)
                return -1;
    return am_port_now() - t0;
}

int tool_bench_control(tool_ctx* c, long steps, int repeat)
{
    char err[AM_ERR_MAX];
    static const char* const scenes[2] = {"cube:10", "sphere:20"};
    /* one call; calls of 1, 10 and 100 steps leaving every voxel to its sinusoid; the same with a
     * target for every voxel */
    enum { MODES = 7 };
    static const long every[MODES] = {0, 1, 10, 100, 1, 10, 100};
    for (int sc = 0; sc < 2; sc++) {
        am_lattice* lat = &c->work[1].lattice;
        long len = 0;
        if (am_scene_build(lat, scenes[sc], err, sizeof err) != AM_OK ||
            am_lattice_format(lat, g_bench_text, (long)sizeof g_bench_text, &len, err, sizeof err) != AM_OK ||
            am_api_init(&g_bench_api, (long)sizeof g_bench_api, err, sizeof err) != AM_OK)
            return tool_usage_error("bench: %s", err);
        const long nv = am_lattice_count(lat);
        for (long i = 0; i < nv; i++) g_bench_scale[i] = (double)NAN;
        double base = 1e30, best[MODES];
        for (int k = 0; k < MODES; k++) best[k] = 1e30;
        for (int r = 0; r < repeat; r++) {
            /* in turns, so that a slower minute of a shared machine falls on all of them */
            double t = time_sim(c, lat, steps, err, sizeof err);
            if (t < 0) return tool_usage_error("bench: %s", err);
            if (t < base) base = t;
            for (int k = 0; k < MODES; k++) {
                t = time_control(steps, every[k], k >= 4, err, sizeof err);
                if (t < 0) return tool_usage_error("bench: %s", err);
                if (t < best[k]) best[k] = t;
            }
        }
        const double vs = (double)steps * (double)nv;
        printf("control scene=%s voxels=%ld steps=%ld sim_ns_per_voxel_step=%.2f", scenes[sc], nv, steps, base / vs * 1e9);
        printf(" api_ns_per_voxel_step=%.2f api_overhead=%.1f%%", best[0] / vs * 1e9, 100.0 * (best[0] / base - 1.0));
        for (int k = 1; k < MODES; k++) {
            const char* what = k < 4 ? "every" : "targets";
            printf(" %s%ld_ns_per_voxel_step=%.2f %s%ld_overhead=%.1f%%", what, every[k], best[k] / vs * 1e9, what, every[k],
                   100.0 * (best[k] / base - 1.0));
        }
        printf(" runs=%d\n", repeat);
        fflush(stdout);
    }
    return 0;
}
#endif
