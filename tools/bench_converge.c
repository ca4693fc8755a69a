/* amorph bench --convergence: does the default time step give the small-step answer?
 *
 * Each body is evaluated at its own step (the default 0.9 dt_rec) and at a fine step (0.1 dt_rec)
 * with the same physics in seconds: the actuation period held (period_s) and the relaxation
 * scaled (its step counts are steps of the default step, amorph/sim.h), settling at the fine
 * step itself (the default's settling pseudo-step, relax_dt_frac, is part of what is checked). The bodies: the two
 * calibration bars (halfbar:6, antibar:6), random genomes of every representation as evolution
 * meets them (the default experiment's settings), and the robots named on the command line (run
 * folders: their best robot in their own settings; robot files, a VXA file's layers with it). Then
 * the margins, at the default step: the
 * friction 10% lower and higher, the internal damping scale 0.5 and 1.0, and a step 1.2 times as
 * long. Prints a table and a summary (docs/physics.md, Time step). */
#include "evolve_cmd.h"
#include "robot.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if !defined(AM_PROFILE_BOARD)

#define CONV_MAX_BODIES 96
#define CONV_MAX_ROBOTS (CONV_MAX_BODIES - 64) /* the bars and up to 3 x 20 random genomes take the rest */
enum { V_DEFAULT, V_FINE, V_MU_LOW, V_MU_HIGH, V_ZETA_HALF, V_ZETA_ONE, V_STEP_LONG, V_COUNT };
static const char* const g_variant_name[V_COUNT] = {"default", "fine", "mu-10%", "mu+10%", "zeta0.5", "zeta1.0", "step1.2"};

typedef struct conv_body {
    char name[80];
    int kind;                 /* 0 bar, 1 random genome, 2 robot */
    am_lattice lat;
    const am_layers* layers;  /* a VXA robot's per-cell phases, stiffnesses and boundary conditions; NULL: none */
    am_env env;
    am_eval_def eval;
} conv_body;

typedef struct conv_out {
    double travel, fitness;
    int diverged, settled, period_steps;
    long relax_steps;
} conv_out;

typedef struct conv_job {
    tool_ctx* c;
    int nbody;
    double fine;              /* the fine step, dt_frac */
    conv_out out[CONV_MAX_BODIES * V_COUNT];
} conv_job;

static conv_body g_body[CONV_MAX_BODIES];
static am_layers g_layers[CONV_MAX_ROBOTS]; /* the robots' layers (read by every worker, written by none) */
static conv_job g_job;

/* the body's settings for one variant into env and ev, and its lattice into lat */
static void variant(const conv_body* b, int v, double fine, am_lattice* lat, am_env* env, am_eval_def* ev)
{
    *lat = b->lat;
    *env = b->env;
    *ev = b->eval;
    ev->record = NULL;
    ev->gait = NULL;
    const double own = AM_PARAM_TO_DOUBLE(b->env.dt_frac);
    if (v == V_FINE || v == V_STEP_LONG) {
        /* the same period in seconds at the other step; the relaxation scales itself */
        env->dt_frac = AM_PARAM_FROM_DOUBLE(v == V_FINE ? fine : 1.2 * own);
        ev->dt_search = 0;
    }
    /* the reference relaxes at its own fine step too: the default's settling pseudo-step
     * (relax_dt_frac) is part of what is checked */
    if (v == V_FINE) ev->relax_dt_frac = AM_P(0);
    if (v == V_MU_LOW || v == V_MU_HIGH)
        for (int k = 0; k < lat->palette.count; k++) {
            const double f = v == V_MU_LOW ? 0.9 : 1.1;
            lat->palette.mat[k].mu_static = AM_PARAM_FROM_DOUBLE(f * AM_PARAM_TO_DOUBLE(lat->palette.mat[k].mu_static));
            lat->palette.mat[k].mu_kinetic = AM_PARAM_FROM_DOUBLE(f * AM_PARAM_TO_DOUBLE(lat->palette.mat[k].mu_kinetic));
        }
    if (v == V_ZETA_HALF) env->zeta_internal_scale = AM_P(0.5);
    if (v == V_ZETA_ONE) env->zeta_internal_scale = AM_P(1);
}

/* one (body, variant) item on a worker's workspace */
static void conv_task(void* ctx, int item, int worker)
{
    conv_job* j = ctx;
    const int b = item / V_COUNT, v = item % V_COUNT;
    am_evo_work* w = &j->c->work[worker];
    am_env env;
    am_eval_def ev;
    variant(&g_body[b], v, j->fine, &w->lattice, &env, &ev);
    conv_out* o = &j->out[item];
    memset(o, 0, sizeof *o);
    char err[AM_ERR_MAX];
    if (v == V_FINE || v == V_STEP_LONG) {
        /* hold the period of the body's own step in seconds */
        am_env own = g_body[b].env;
        if (am_model_build_layers(&w->model, &w->lattice, &own, g_body[b].layers, err, sizeof err) != AM_OK) {
            o->diverged = 1;
            return;
        }
        env.period_s = AM_PARAM_FROM_DOUBLE(w->model.env.period_steps * am_dt_si(&w->model, own.dt_frac));
    }
    if (am_model_build_layers(&w->model, &w->lattice, &env, g_body[b].layers, err, sizeof err) != AM_OK) {
        o->diverged = 1;
        return;
    }
    am_result r;
    am_evaluate(&w->model, &w->state, &ev, &r);
    o->travel = r.travel;
    o->fitness = r.fitness;
    o->diverged = r.diverged;
    o->settled = r.settled;
    o->period_steps = r.period_steps;
    o->relax_steps = r.relax_steps;
}

/* the random genome (repr, seed) of the default experiment, expressed, into b */
static int random_body(tool_ctx* c, int repr, int seed, conv_body* b)
{
    char err[AM_ERR_MAX];
    am_evo_def d = am_default_evo();
    d.geno.repr = repr;
    am_rng rng;
    am_rng_seed(&rng, (uint64_t)seed);
    am_genome* g = tool_genome(c);
    if (am_genome_init(g, &d.geno, &rng, err, sizeof err) != AM_OK) return tool_usage_error("bench: %s", err);
    am_palette pal;
    am_evo_palette_into(&d, &pal);
    if (am_evo_lattice(&d, &pal, g, &c->work[0].geno, &b->lat, err, sizeof err) != AM_OK) return tool_usage_error("bench: %s", err);
    b->env = d.env;
    b->eval = d.eval;
    b->layers = NULL;
    b->kind = 1;
    snprintf(b->name, sizeof b->name, "random %s %d", am_repr_name(repr), seed);
    return 0;
}

/* |a - b| relative to |b|, or to 1 mm when b travels less (a still body's travel is noise) */
static double rel_diff(double a, double b) { return fabs(a - b) / fmax(fabs(b), 1e-3); }

static int cmp_double(const void* a, const void* b)
{
    const double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

int bench_convergence(tool_ctx* c, int argc, char** argv, int first)
{
    double fine = 0.1;
    long nrandom = 10, n;
    int threads = 0;
    const char* robots[CONV_MAX_BODIES];
    int nrobots = 0;
    for (int i = first; i < argc; i++) {
        const char* a = argv[i];
        const char* v = i + 1 < argc ? argv[i + 1] : 0;
        if (!strcmp(a, "--fine")) {
            if (!tool_parse_real(v, 1e-3, 1, &fine)) return tool_usage_error("bench: --fine needs a step in [0.001, 1] (of dt_rec)");
            i++;
        } else if (!strcmp(a, "--random")) {
            if (!tool_parse_long(v, 0, 20, &n)) return tool_usage_error("bench: --random needs a whole number from 0 to 20");
            nrandom = n, i++;
        } else if (!strcmp(a, "--threads")) {
            if (!tool_parse_long(v, 1, AM_MAX_WORKERS, &n)) return tool_usage_error("bench: --threads needs a whole number from 1 to %d", AM_MAX_WORKERS);
            threads = (int)n, i++;
        } else if (a[0] == '-') return tool_unknown_option("bench --convergence", a, NULL);
        else if (nrobots >= CONV_MAX_ROBOTS) return tool_usage_error("bench: at most %d robots", CONV_MAX_ROBOTS);
        else robots[nrobots++] = a;
    }
    /* the bodies */
    int nb = 0;
    char err[AM_ERR_MAX];
    /* the bars at the seed's period (500 steps of 0.9 dt_rec, 22.6 ms) and at 7.5 ms (500 steps of
     * the old default 0.3 dt_rec); the pass line asks for three of them: the anti-phase bar at
     * 22.6 ms is a hopper (airborne 89%) whose travel is a small sum of large hops and takes another
     * branch at any step above 0.2 dt_rec (docs/physics.md, Time step) */
    static const char* const bars[4] = {"halfbar:6", "antibar:6", "halfbar:6", "antibar:6"};
    for (int k = 0; k < 4; k++, nb++) {
        conv_body* b = &g_body[nb];
        if (am_scene_build(&b->lat, bars[k], err, sizeof err) != AM_OK) return tool_usage_error("bench: %s", err);
        b->env = am_default_env();
        if (k >= 2) b->env.period_s = AM_P(0.0075493820);
        b->eval = am_default_eval();
        b->eval.fitness = AM_FIT_PLUS_X;
        b->layers = NULL;
        b->kind = 0;
        snprintf(b->name, sizeof b->name, "%s at %s ms", bars[k], k < 2 ? "22.6" : "7.5");
    }
    static const int reprs[3] = {AM_REPR_DCT, AM_REPR_CPPN, AM_REPR_GMX};
    for (int r = 0; r < 3; r++)
        for (int s = 1; s <= nrandom; s++)
            if (random_body(c, reprs[r], s, &g_body[nb++])) return 2;
    for (int k = 0; k < nrobots; k++) {
        tool_robot_args ra;
        memset(&ra, 0, sizeof ra);
        ra.name = robots[k];
        am_robot rob;
        conv_body* b = &g_body[nb++];
        if (tool_robot_load(c, &ra, &b->lat, &rob, err, sizeof err) != AM_OK) return tool_usage_error("bench: %s", err);
        b->env = rob.env;
        b->eval = rob.eval;
        /* the file's layers go with its lattice (tool_robot_load's room is the next robot's) */
        b->layers = rob.layers ? (g_layers[k] = *rob.layers, &g_layers[k]) : NULL;
        b->kind = 2;
        snprintf(b->name, sizeof b->name, "%s", robots[k]);
    }
    g_job.c = c;
    g_job.nbody = nb;
    g_job.fine = fine;
    const int workers = threads ? threads : am_port_cores();
    bench_print_build();
    printf("convergence: %d bodies at the default step and at %g dt_rec (period held in seconds, relaxation scaled), "
           "%d workers\n", nb, fine, workers);
    fflush(stdout);
    double t0 = am_port_now();
    if (am_port_parallel_map(nb * V_COUNT, workers, conv_task, &g_job, g_job.out, (long)sizeof g_job.out[0], err, sizeof err) != AM_OK) {
        fprintf(stderr, "amorph: bench: %s\n", err);
        return 1;
    }
    /* the table */
    printf("%-44s %7s %11s %11s %8s %9s  %s\n", "body", "voxels", "default_mm", "fine_mm", "diff", "settled", "margins");
    double diffs[CONV_MAX_BODIES];
    int nd = 0, unsettled = 0, unstable = 0, worst = -1;
    double bar_diff[4] = {0, 0, 0, 0}, worst_diff = 0;
    for (int b = 0; b < nb; b++) {
        const conv_out* o = &g_job.out[b * V_COUNT];
        char margins[128] = "";
        int bad = 0;
        for (int v = V_MU_LOW; v < V_COUNT; v++)
            if (o[v].diverged) {
                bad++;
                strncat(margins, g_variant_name[v], sizeof margins - strlen(margins) - 2);
                strcat(margins, " ");
            }
        unstable += bad > 0;
        const int ok = !o[V_DEFAULT].diverged && !o[V_FINE].diverged;
        const double d = ok ? rel_diff(o[V_DEFAULT].travel, o[V_FINE].travel) : (double)NAN;
        unsettled += !o[V_DEFAULT].settled || !o[V_FINE].settled;
        if (g_body[b].kind == 0) bar_diff[b] = ok ? d : (double)INFINITY;
        else {
            diffs[nd++] = ok ? d : (double)INFINITY;
            if (worst < 0 || !(d <= worst_diff)) worst = b, worst_diff = ok ? d : (double)INFINITY;
        }
        printf("%-44.44s %7d %11.4f %11.4f %7.1f%% %4d %4d  %s\n", g_body[b].name, am_lattice_count(&g_body[b].lat),
               o[V_DEFAULT].travel * 1e3, o[V_FINE].travel * 1e3, 100 * d, o[V_DEFAULT].settled, o[V_FINE].settled,
               bad ? margins : "stable");
    }
    qsort(diffs, (size_t)nd, sizeof diffs[0], cmp_double);
    const double median = nd ? (nd % 2 ? diffs[nd / 2] : 0.5 * (diffs[nd / 2 - 1] + diffs[nd / 2])) : 0;
    const double half_x = g_job.out[0].travel;
    printf("halfbar_diff=%.4f halfbar_fast_diff=%.4f antibar_fast_diff=%.4f (antibar_diff=%.4f) halfbar_default_dx_mm=%.4f bodies=%d "
           "median_diff=%.4f worst_diff=%.4f worst=%s unsettled=%d unstable_margins=%d wall_s=%.1f\n",
           bar_diff[0], bar_diff[2], bar_diff[3], bar_diff[1], half_x * 1e3, nd, median, worst_diff, worst >= 0 ? g_body[worst].name : "-",
           unsettled, unstable, am_port_now() - t0);
    const int pass = bar_diff[0] <= 0.05 && bar_diff[2] <= 0.05 && bar_diff[3] <= 0.05 && median <= 0.05 && worst_diff <= 0.15 && half_x > 0 &&
                     !unsettled && !unstable;
    printf("convergence: %s (the half bar at 22.6 and 7.5 ms, the anti-phase bar at 7.5 ms and the median body within 5%%, the "
           "worst within 15%%, the half bar in +x, all settled and stable)\n", pass ? "pass" : "FAIL");
    return 0;
}

#else
int bench_convergence(tool_ctx* c, int argc, char** argv, int first)
{
    (void)c;
    (void)argc;
    (void)argv;
    (void)first;
    return tool_not_in_build("bench --convergence", "20^3 bodies");
}
#endif
