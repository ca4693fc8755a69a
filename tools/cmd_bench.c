/* amorph bench: speed figures as name=value lines: the simulator per step and per simulated
 * second, the product kernels of both number types, genotype expression, and whole evolutions
 * (--evolve). docs/benchmarks.md records them. */
#include "evolve_cmd.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* times `steps` actuated steps of one scene after a short warm-up, at dt_frac of dt_rec (the default when 0);
 * *vps_out gets the voxel steps per second, *k_out the simulated seconds per voxel step (dt / nv,
 * the same in every run of the scene), so that vps * k is the simulated seconds per second */
static int bench_one(tool_ctx* c, const char* scene, long steps, int collisions, double dt_frac, double* vps_out, double* k_out)
{
    char err[AM_ERR_MAX];
    am_env env = am_default_env();
    env.collisions = collisions;
    if (dt_frac > 0) env.dt_frac = AM_PARAM_FROM_DOUBLE(dt_frac);
    am_lattice* lat = &c->work[0].lattice;
    if (am_scene_build(lat, scene, err, sizeof err) != AM_OK) return tool_usage_error("bench: %s", err);
    if (am_model_build(&c->work[0].model, lat, &env, err, sizeof err) != AM_OK) return tool_usage_error("bench: %s", err);
    am_state_reset(&c->work[0].model, &c->work[0].state);
    c->work[0].state.actuate = 1;
    am_steps(&c->work[0].model, &c->work[0].state, steps / 10 + 1); /* warm-up: caches, first collision build */
    long r0 = c->work[0].state.rebuilds;
    double t0 = am_port_now();
    long done = am_steps(&c->work[0].model, &c->work[0].state, steps);
    double wall = am_port_now() - t0;
    const double vps = (double)done * c->work[0].model.nv / (wall > 0 ? wall : 1e-9);
    const double dt = am_to_si(&c->work[0].model, c->work[0].state.dt, AM_DIM_TIME);
    const double k = dt / c->work[0].model.nv, sps = vps * k;
    printf("scene=%s collisions=%s voxels=%d links=%d steps=%ld dt_frac=%g dt_s=%.4g wall_s=%.4f voxel_steps_per_s=%.4g "
           "sim_s_per_s=%.4g ns_per_voxel_step=%.2f rebuilds=%ld pairs=%d diverged=%d\n",
           scene, collisions ? "on" : "off", c->work[0].model.nv, c->work[0].model.links, done,
           AM_PARAM_TO_DOUBLE(c->work[0].model.env.dt_frac), dt, wall, vps, sps, 1e9 / vps, c->work[0].state.rebuilds - r0,
           c->work[0].state.npairs, c->work[0].state.diverged);
    fflush(stdout);
    *vps_out = vps;
    *k_out = k;
    return 0;
}

/* `repeat` runs of bench_one, then the best and the median figure: on a shared or virtual
 * machine whose speed moves from minute to minute, the best of several runs is the figure of
 * the code */
static int bench_scene(tool_ctx* c, const char* scene, long steps, int collisions, double dt_frac, int repeat)
{
    double v[64], sk = 0; /* voxel steps per second; simulated seconds per voxel step */
    for (int k = 0; k < repeat; k++) {
        if (bench_one(c, scene, steps, collisions, dt_frac, &v[k], &sk)) return 2;
        for (int j = k; j > 0 && v[j] < v[j - 1]; j--) { /* sorted as they come */
            double t = v[j];
            v[j] = v[j - 1];
            v[j - 1] = t;
        }
    }
    if (repeat > 1) {
        double med = repeat % 2 ? v[repeat / 2] : 0.5 * (v[repeat / 2 - 1] + v[repeat / 2]);
        printf("scene=%s collisions=%s runs=%d best_voxel_steps_per_s=%.4g median_voxel_steps_per_s=%.4g "
               "worst_voxel_steps_per_s=%.4g best_sim_s_per_s=%.4g median_sim_s_per_s=%.4g worst_sim_s_per_s=%.4g\n",
               scene, collisions ? "on" : "off", repeat, v[repeat - 1], med, v[0], v[repeat - 1] * sk, med * sk, v[0] * sk);
        fflush(stdout);
    }
    return 0;
}

/* The product at the heart of both number types, alone: a degree-8 polynomial by Horner's rule
 * (8 products and 8 sums per element, in registers, as in the link element where loads are few
 * against the arithmetic) over arrays that stay in the L1 cache, in float and with the
 * fixed-point build's Q24 product (64-bit multiply, half an ulp, arithmetic shift: am_fx_mul of
 * amorph/base.h). Both are in every build, so one binary shows what a product costs in each
 * (docs/benchmarks.md, Fixed point). */
#if !defined(AM_PROFILE_BOARD) /* its 32 KB of arrays are not worth a board's RAM */
#define KERNEL_N 2048
#define KERNEL_DEG 8
static float g_kf[2][KERNEL_N];
static int32_t g_ki[2][KERNEL_N];
static const double g_kc[KERNEL_DEG + 1] = {0.5, -0.25, 0.125, 0.75, -0.5, 0.3, -0.2, 0.1, 1.0};

static void kernel_f32(const float* restrict x, float* restrict y, const float* restrict k)
{
    for (int i = 0; i < KERNEL_N; i++) {
        float p = k[0];
        for (int d = 1; d <= KERNEL_DEG; d++) p = p * x[i] + k[d];
        y[i] = p;
    }
}
static inline int32_t q24_mul(int32_t a, int32_t b) { return (int32_t)(((int64_t)a * b + ((int64_t)1 << 23)) >> 24); }
static void kernel_q24(const int32_t* restrict x, int32_t* restrict y, const int32_t* restrict k)
{
    for (int i = 0; i < KERNEL_N; i++) {
        int32_t p = k[0];
        for (int d = 1; d <= KERNEL_DEG; d++) p = q24_mul(p, x[i]) + k[d];
        y[i] = p;
    }
}

static void bench_kernels(void)
{
    float kf[KERNEL_DEG + 1];
    int32_t ki[KERNEL_DEG + 1];
    for (int d = 0; d <= KERNEL_DEG; d++) {
        kf[d] = (float)g_kc[d];
        ki[d] = (int32_t)(g_kc[d] * 16777216.0);
    }
    for (int i = 0; i < KERNEL_N; i++) {
        g_kf[0][i] = (float)(i % 97) / 97.0f - 0.5f;
        g_ki[0][i] = (int32_t)((double)g_kf[0][i] * 16777216.0);
    }
    /* called through volatile pointers: the compiler can neither inline the kernels nor drop the
     * repetitions */
    void (*volatile run_f)(const float*, float*, const float*) = kernel_f32;
    void (*volatile run_q)(const int32_t*, int32_t*, const int32_t*) = kernel_q24;
    const long reps = 4000;
    double best_f = 1e30, best_q = 1e30, sf = 0, sq = 0;
    for (int round = 0; round < 5; round++) { /* best of five, the two kernels in turns */
        double t0 = am_port_now();
        for (long r = 0; r < reps; r++) run_f(g_kf[0], g_kf[1], kf);
        double tf = am_port_now() - t0;
        t0 = am_port_now();
        for (long r = 0; r < reps; r++) run_q(g_ki[0], g_ki[1], ki);
        double tq = am_port_now() - t0;
        best_f = tf < best_f ? tf : best_f;
        best_q = tq < best_q ? tq : best_q;
    }
    for (int i = 0; i < KERNEL_N; i++) { /* the two agree to Q24's resolution: both computed */
        sf += (double)g_kf[1][i];
        sq += (double)g_ki[1][i] / 16777216.0;
    }
    const double n = (double)reps * KERNEL_N * KERNEL_DEG;
    printf("kernel=horner8 real=float ns_per_product=%.4f sum=%.6f\n", 1e9 * best_f / n, sf);
    printf("kernel=horner8 real=q24 ns_per_product=%.4f sum=%.6f\n", 1e9 * best_q / n, sq);
    printf("kernel=horner8 q24_time_over_float=%.2f\n", best_q / (best_f > 0 ? best_f : 1e-9));
    fflush(stdout);
}
#endif

/* ---- expression and evolution ---- */

/* name=value lines of the genotype expression times */
static void bench_express(tool_ctx* c)
{
    enum { GENOMES = 8 };
    /* the pool: the genomes of the evolver's population, idle while bench runs */
    _Static_assert(GENOMES <= AM_MAX_POPULATION, "the expression pool borrows the evolver's population");
    am_genome* pool[GENOMES];
    for (int i = 0; i < GENOMES; i++) pool[i] = &c->evo.pop[i].genome;
    char err[AM_ERR_MAX];
    am_geno_def def = am_default_geno();
    printf("express_workspace=%dx%dx%d\n", def.nx, def.ny, def.nz);
    printf("genome_bytes=%d\n", (int)sizeof(am_genome));
    for (int repr = 1; repr < AM_REPR_COUNT; repr++) {
        def.repr = repr;
        am_rng rng;
        am_rng_seed(&rng, 2024);
        for (int i = 0; i < GENOMES; i++)
            if (am_genome_init(pool[i], &def, &rng, err, sizeof err) != AM_OK) {
                printf("express_%s_error=%s\n", am_repr_name(repr), err);
                return;
            }
        am_genome_express(pool[0], NULL, &c->work[0].geno, NULL, err, sizeof err); /* warm-up: tables */
        long reps = 0, voxels = 0;
        double t0 = am_port_now(), t = 0;
        do {
            for (int i = 0; i < GENOMES; i++) {
                am_genome_express(pool[i], NULL, &c->work[0].geno, NULL, err, sizeof err);
                voxels += c->work[0].geno.voxels;
            }
            reps += GENOMES;
            t = am_port_now() - t0;
        } while (t < 0.25);
        /* the level set alone, on the last fields */
        long lreps = 0;
        double l0 = am_port_now(), lt = 0;
        do {
            for (int i = 0; i < GENOMES; i++)
                am_levelset(&c->work[0].geno, def.materials, def.nx, def.ny, def.nz, AM_R(0), NULL);
            lreps += GENOMES;
            lt = am_port_now() - l0;
        } while (lt < 0.1);
        printf("express_%s_us=%.1f\n", am_repr_name(repr), 1e6 * t / (double)reps);
        printf("express_%s_levelset_us=%.1f\n", am_repr_name(repr), 1e6 * lt / (double)lreps);
        printf("express_%s_mean_voxels=%ld\n", am_repr_name(repr), voxels / reps);
    }
    fflush(stdout);
}

/* the parallel map's own cost: maps of `n` items that only write their result bytes (an
 * am_evo_result each, what an evaluation hands back), timed over `reps` maps; microseconds per item.
 * Under port/mpi this is the transport of an evaluation's result to every rank (and the collectives
 * around a map); on threads, the cost of handing an item to a worker. */
typedef struct null_job {
    am_evo_result* res;
} null_job;

static void null_task(void* ctx, int item, int worker)
{
    null_job* j = (null_job*)ctx;
    (void)worker;
    memset(&j->res[item], 0, sizeof j->res[item]);
    j->res[item].detail.sim.fitness = (double)item;
    j->res[item].detail.sim.steps = item;
}

static double map_us_per_item(am_evo* e, int n, int workers, int reps)
{
    char err[AM_ERR_MAX];
    null_job j = {e->res};
    double t0 = am_port_now();
    for (int r = 0; r < reps; r++) {
        if (am_port_parallel_map(n, workers, null_task, &j, e->res, (long)sizeof e->res[0], err, sizeof err) != AM_OK) return -1.0;
        for (int i = 0; i < n; i++)
            if (e->res[i].detail.sim.steps != i) return -1.0; /* a result that did not arrive */
    }
    return (am_port_now() - t0) / ((double)reps * n) * 1e6;
}

/* the am_evo_hooks.evaluated callback of bench --evolve: each evaluation into the account */
static void account_evaluated(void* ctx, const am_evo_ind* ind, const am_evo_eval* ev)
{
    account_add((step_account*)ctx, ind->voxels, ind->empty, ind->diverged, ev->sim.settled, ev->sim.relax_steps, ind->steps, ind->state_hash);
}

/* name=value lines of the default experiment's evaluations per hour on `threads` (0: 1 and 2)
 * threads of each of am_port_processes() processes; 0, or 1 when the runs differ */
static int bench_evolve(tool_ctx* c, long evaluations, int threads)
{
    char err[AM_ERR_MAX];
    am_evo_def d = am_default_evo();
    d.evaluations = evaluations;
    uint64_t hash[2] = {0, 0};
    double rate[2] = {0, 0};
    int cores = am_port_cores(), procs = am_port_processes();
    int t_from = threads ? threads : 1, t_to = threads ? threads : 2;
    printf("evolve_config=default (gmx, %dx%dx%d, population %d)\nevolve_evaluations=%ld\ncores=%d\nprocesses=%d\n", d.geno.nx, d.geno.ny,
           d.geno.nz, d.population, evaluations, cores, procs);
    for (int t = t_from; t <= t_to; t++) {
        if (am_evo_init(&c->evo, &d, err, sizeof err) != AM_OK) return tool_usage_error("bench: %s", err);
        static step_account acct; /* its table of hashes is large */
        account_begin(&acct);
        const am_evo_hooks hooks = {NULL, account_evaluated, &acct};
        double t0 = am_port_now();
        long steps = 0, voxel_steps = 0;
        while (!am_evo_done(&c->evo)) {
            const am_executor ex = tool_executor(t);
            if (am_evo_generation(&c->evo, c->work, &ex, &hooks, err, sizeof err) != AM_OK) return tool_usage_error("bench: %s", err);
            steps += c->evo.last_steps;
            voxel_steps += c->evo.last_voxel_steps;
        }
        double el = am_port_now() - t0;
        int k = t - t_from;
        rate[k] = (double)c->evo.evaluations / el * 3600.0;
        hash[k] = am_evo_hash(&c->evo);
        double map_us = map_us_per_item(&c->evo, d.population, t, 2000);
        printf("processes=%d threads=%d evaluations=%ld wall_s=%.2f evals_per_hour=%.0f mean_steps_per_eval=%.0f mean_voxels=%.0f "
               "voxel_steps_per_s=%.0f map_us_per_item=%.2f run_hash=%016llx\n",
               procs, t, c->evo.evaluations, el, rate[k], (double)steps / (double)c->evo.evaluations,
               steps ? (double)voxel_steps / (double)steps : 0.0, (double)voxel_steps / el, map_us, (unsigned long long)hash[k]);
        if (t == t_from) {
            /* where the steps went (the same for any thread count) */
            tool_out o;
            if (tool_out_open(&o, NULL)) return 1;
            tool_rec q;
            tool_rec_begin_tight(&q, &o.text);
            account_put(&q, &acct);
            account_put_reuse(&q, &acct, &c->evo);
            tool_rec_end(&q);
            if (tool_out_close(&o, 1)) return 1;
        }
    }
    if (t_to > t_from)
        printf("speedup_2_threads=%.2f\nhours_for_20000_evals_2_threads=%.2f\nsame_hash=%s\n", rate[1] / rate[0], 20000.0 / rate[1],
               hash[0] == hash[1] ? "yes" : "NO");
    return hash[0] == hash[1] || t_to == t_from ? 0 : 1;
}

static const char bench_help[] =
    "usage: amorph bench [--scene NAME] [--steps N] [--collisions on|off] [--dt-frac F] [--repeat N]\n"
    "       amorph bench --evolve [--evals N] [--threads T]\n"
    "       amorph bench --kernels\n"
    "       amorph bench --control [--steps N] [--repeat R]\n"
    "       amorph bench --convergence [--fine F] [--random N] [--threads T] [ROBOT...]\n"
    "Prints name=value figures of the simulator on one thread. With no options: sphere:20 and\n"
    "cube:10, self-collision off and on, then the genotype expression times.\n"
    "Each scene's line: the time step (dt_frac of the analytic limit, dt_s), voxel steps per second\n"
    "and simulated seconds per wall second (sim_s_per_s), both over --steps actuated steps (2000).\n"
    "--dt-frac F: another step than the default (to compare builds or steps at the same step).\n"
    "--repeat N: each scene N times (1 to 64), then the best, median and worst figure.\n"
    "--evolve: evaluations per hour of the default experiment (amorph evolve) on 1 and 2 threads\n"
    "(or T only), each a run of N evaluations (--evals N, at least the population: 60; --evals alone implies\n"
    "--evolve), the speedup of the second core, and the parallel map's own cost per item\n"
    "(map_us_per_item: maps of 20 items that only hand back a result). Under\n"
    "mpirun (the MPI build), every rank runs T threads: tools/bench_mpi.sh sets ranks against threads.\n"
    "--control: the cost of stepping under control (amorph/api.h, Stepping) on cube:10 and sphere:20,\n"
    "on sim's motion: sim's open-loop steps against one API call and calls of 1, 10 and 100 steps\n"
    "each passing an action for every voxel; ns per voxel step and the overhead over sim" TOOL_DESKTOP_ONLY ".\n"
    "--kernels: the cost of a product alone, float against the fixed-point build's Q24, in\n"
    "vectorisable loops" TOOL_DESKTOP_ONLY ".\n"
    "--convergence: does the default step give the small-step answer? The calibration bars\n"
    "(halfbar:6, antibar:6), N random bodies of each representation (10) and every ROBOT (a run\n"
    "folder: its best robot in its own settings; a lattice, genome or VXA file, with its layers) at\n"
    "their own step and at F dt_rec (0.1), the period held in seconds and the relaxation scaled;\n"
    "then the margins at the default step (friction -10% and +10%, internal damping 0.5 and 1.0,\n"
    "1.2 times the step). A table, a summary line and pass or FAIL (docs/physics.md, Time step;\n"
    "make convergence)" TOOL_DESKTOP_ONLY ".\n";

/* the build's number type and profile, and what the compiler was allowed to vectorise with: the
 * widest vector extension it was given and whether gathers were left out (Makefile GATHER=,
 * docs/benchmarks.md, Build flags); speed only, never the results */
void bench_print_build(void)
{
#if defined(__AVX512F__)
    const char* vec = "avx512";
#elif defined(__AVX2__)
    const char* vec = "avx2";
#elif defined(__AVX__)
    const char* vec = "avx";
#elif defined(__SSE4_2__)
    const char* vec = "sse4.2";
#elif defined(__SSE2__)
    const char* vec = "sse2";
#elif defined(__ARM_FEATURE_SVE)
    const char* vec = "sve";
#elif defined(__ARM_NEON)
    const char* vec = "neon";
#else
    const char* vec = "none";
#endif
#if defined(AM_NO_GATHER)
    const char* gathers = "off";
#else
    const char* gathers = "compiler";
#endif
    printf("build real=%s profile=%s vector=%s gathers=%s\n", AM_REAL_NAME, AM_PROFILE_NAME, vec, gathers);
}

int cmd_bench(tool_ctx* c, int argc, char** argv)
{
    const char* scene = 0;
    long steps = 2000, n;
    int coll = -1;
    long evolve_evals = 0;
    int kernels = 0, repeat = 1, threads = 0, control = 0;
    double dt_frac = 0; /* the default step */
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        const char* v = i + 1 < argc ? argv[i + 1] : 0;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(bench_help, stdout);
            return 0;
        } else if (!strcmp(a, "--scene") && v) scene = v, i++;
        else if (!strcmp(a, "--steps")) {
            if (!tool_parse_long(v, 1, 100000000, &n)) return tool_usage_error("bench: --steps needs a whole number >= 1");
            steps = n, i++;
        } else if (!strcmp(a, "--collisions")) {
            if (!tool_parse_onoff(v, &coll)) return tool_usage_error("bench: --collisions takes on or off");
            i++;
        } else if (!strcmp(a, "--repeat")) {
            if (!tool_parse_long(v, 1, 64, &n)) return tool_usage_error("bench: --repeat needs a whole number from 1 to 64");
            repeat = (int)n, i++;
        } else if (!strcmp(a, "--dt-frac")) {
            if (!tool_parse_real(v, 1e-6, 10, &dt_frac)) return tool_usage_error("bench: --dt-frac needs a number in [1e-6, 10] (the key dt_frac's range)");
            i++;
        } else if (!strcmp(a, "--convergence")) {
            return bench_convergence(c, argc, argv, i + 1);
        } else if (!strcmp(a, "--kernels")) {
            kernels = 1;
        } else if (!strcmp(a, "--control")) {
            control = 1;
        } else if (!strcmp(a, "--evolve")) {
            if (!evolve_evals) evolve_evals = 60; /* an --evals N before it stands */
        } else if (!strcmp(a, "--evals")) {
            if (!tool_parse_long(v, 2, 1000000, &n)) return tool_usage_error("bench: --evals needs a whole number >= 2");
            evolve_evals = n, i++;
        } else if (!strcmp(a, "--threads")) {
            if (!tool_parse_long(v, 1, AM_MAX_WORKERS, &n)) return tool_usage_error("bench: --threads needs a whole number from 1 to %d", AM_MAX_WORKERS);
            threads = (int)n, i++;
        } else return tool_unknown_option("bench", a, bench_help);
    }
    if (kernels) {
#if defined(AM_PROFILE_BOARD)
        return tool_not_in_build("bench --kernels", "the product kernels");
#else
        bench_print_build();
        bench_kernels();
        return 0;
#endif
    }
    if (control) {
        bench_print_build();
        return tool_bench_control(c, steps, repeat);
    }
    if (threads && !evolve_evals) return tool_usage_error("bench: --threads applies to --evolve");
    if (evolve_evals) {
        bench_print_build();
        return bench_evolve(c, evolve_evals, threads);
    }
    bench_print_build();
    if (scene) {
        if (coll != 0 && bench_scene(c, scene, steps, 1, dt_frac, repeat)) return 2;
        if (coll != 1 && bench_scene(c, scene, steps, 0, dt_frac, repeat)) return 2;
        return 0;
    }
    const char* scenes[2] = {AM_MAX_DIM >= 20 ? "sphere:20" : "sphere:8", AM_MAX_DIM >= 10 ? "cube:10" : "cube:8"};
    for (int k = 0; k < 2; k++)
        for (int on = 0; on <= 1; on++)
            if ((coll < 0 || coll == on) && bench_scene(c, scenes[k], steps, on, dt_frac, repeat)) return 2;
    bench_express(c);
    return 0;
}
