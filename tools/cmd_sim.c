/* amorph sim and amorph bench. */
#include "robot.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char sim_help[] =
    "usage: amorph sim FILE | --scene NAME [options]\n"
    "Simulates one robot (relaxation, then actuation cycles) and prints its fitness and diagnostics.\n"
    "FILE is a lattice (.lattice), a genome, a VXA file" TOOL_DESKTOP_ONLY " (.vxa, with its environment) or a\n"
    "run folder of amorph evolve (its best robot, in the run's environment, evaluation and materials);\n"
    "NAME a built-in scene (cube:N, sphere:D, cantilever:N, chain:N), in the seed's environment.\n"
    TOOL_ROBOT_HELP
    "  --json             one JSON object instead of name = value lines\n"
    "A run that diverged or did not settle prints one warning line on stderr; the exit status is\n"
    "still 0 (it is a result). Besides the fitness: residual_speed (m/s, the largest RMS voxel speed\n"
    "through the release window, or the last one when the relaxation ran out first) and\n"
    "kinetic_resets (the relaxation's kinetic damping stops; docs/physics.md, Evaluation).\n";

/* the result and the gait of the movement segment (docs/results.md, Gaits), on the standard output */
static int print_result(const char* robot, const am_result* r, double wall, const am_gait* g, int fitness, double voxel_size, int json)
{
    am_gait_summary gs;
    am_gait_summarize(g, fitness, voxel_size, &gs);
    double travel[AM_GAIT_MAX_CYCLES];
    for (int k = 0; k < g->cycles; k++) travel[k] = am_gait_travel(g, fitness, k);
    tool_out out;
    if (tool_out_open(&out, NULL)) return 1;
    tool_rec rec, *q = &rec;
    tool_rec_begin(q, &out.text, json);
    tool_rec_str(q, "robot", robot);
    tool_rec_num(q, "fitness", r->fitness);
    tool_rec_num(q, "dx", r->dx);
    tool_rec_num(q, "dy", r->dy);
    tool_rec_num(q, "dz", r->dz);
    tool_rec_int(q, "voxels", r->voxels);
    tool_rec_int(q, "links", r->links);
    tool_rec_num(q, "dt", r->dt);
    tool_rec_int(q, "steps", r->steps);
    tool_rec_int(q, "relax_steps", r->relax_steps);
    tool_rec_int(q, "move_steps", r->move_steps);
    tool_rec_int(q, "diverged", r->diverged);
    tool_rec_int(q, "settled", r->settled);
    tool_rec_num(q, "residual_speed", r->residual_speed);
    tool_rec_int(q, "kinetic_resets", r->kinetic_resets);
    tool_rec_num(q, "sim_seconds", r->sim_seconds);
    tool_rec_num(q, "wall_seconds", wall);
    tool_rec_int(q, "collision_rebuilds", r->rebuilds);
    tool_rec_int(q, "max_pairs", r->max_pairs);
    tool_rec_hex(q, "hash", r->hash);
    tool_rec_nums(q, "cycle_travel", travel, g->cycles);
    tool_rec_num(q, "travel_first_half", gs.first_half);
    tool_rec_num(q, "travel_last_half", gs.last_half);
    tool_rec_num(q, "sustained", gs.sustained);
    tool_rec_num(q, "airborne", gs.airborne);
    tool_rec_num(q, "lift", gs.lift);
    tool_rec_str(q, "gait", r->diverged ? "diverged" : am_gait_mode_name(gs.mode));
    tool_rec_end(q);
    return tool_out_close(&out, 1);
}

int cmd_sim(tool_ctx* c, int argc, char** argv)
{
    int json = 0;
    tool_robot_args ra;
    memset(&ra, 0, sizeof ra);
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(sim_help, stdout);
            return 0;
        }
        if (!strcmp(a, "--json")) {
            json = 1;
            continue;
        }
        int r = tool_robot_arg("sim", argc, argv, &i, &ra);
        if (r == 2) return 2;
        if (r == 0) return tool_usage_error("sim: unknown option '%s' (amorph sim --help)", a);
    }
    if (!ra.name) return tool_usage_error("sim: name a robot file or --scene NAME (amorph sim --help)");

    char err[AM_ERR_MAX];
    am_lattice* lat = &c->work[0].lattice; /* the robot */
    tool_robot rob;
    const char* file = ra.name;
    if (tool_robot_load(c, &ra, lat, &rob, err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
    if (rob.eval.dt_search && ra.dt_s > 0) return tool_usage_error("sim: --dt and dt_search exclude each other");
    am_status st = am_model_build(&c->work[0].model, lat, &rob.env, err, sizeof err);
    if (st == AM_ERR_EMPTY) {
        /* an empty body is a valid robot that goes nowhere: flagged zero fitness, no simulation */
        tool_out out;
        if (tool_out_open(&out, NULL)) return 1;
        tool_rec q;
        tool_rec_begin(&q, &out.text, json);
        tool_rec_str(&q, "robot", file);
        tool_rec_num(&q, "fitness", 0);
        tool_rec_int(&q, "voxels", 0);
        tool_rec_int(&q, "links", 0);
        tool_rec_int(&q, "empty", 1);
        tool_rec_int(&q, "diverged", 0);
        tool_rec_int(&q, "steps", 0);
        tool_rec_end(&q);
        return tool_out_close(&out, 1);
    }
    if (st != AM_OK) return tool_usage_error("%s: %s", file, err);
    am_eval_def def = rob.eval;

    am_result res;
    am_gait gait;
    def.gait = &gait;
    double t0 = am_port_now();
    am_evaluate(&c->work[0].model, &c->work[0].state, &def, &res);
    double wall = am_port_now() - t0;
    if (print_result(file, &res, wall, &gait, def.fitness, AM_PARAM_TO_DOUBLE(lat->voxel_size), json)) return 1;
    fflush(stdout);
    /* a run that diverged or did not settle is a result (exit status 0), with one line of warning */
    if (res.diverged) {
        const long at = c->work[0].state.diverge_step;
        fprintf(stderr, "amorph: sim: warning: %s diverged at step %ld, in the %s (fitness %g)\n", file, at,
                at <= res.relax_steps ? "relaxation" : "actuation", res.fitness);
    } else if (!res.settled) {
        fprintf(stderr, "amorph: sim: warning: %s did not settle within %ld relaxation steps (residual speed %.2e m/s, "
                "release window %ld steps)\n", file, res.relax_steps, res.residual_speed, def.release_steps);
    }
    return 0;
}

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
 * amorph/real.h). Both are in every build, so one binary shows what a product costs in each
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

static const char bench_help[] =
    "usage: amorph bench [--scene NAME] [--steps N] [--collisions on|off] [--dt-frac F] [--repeat N]\n"
    "       amorph bench --evolve [--evals N]\n"
    "       amorph bench --kernels\n"
    "Prints name=value figures of the simulator on one thread. With no options: sphere:20 and\n"
    "cube:10, self-collision off and on, then the genotype expression times.\n"
    "Each scene's line: the time step (dt_frac of the analytic limit, dt_s), voxel steps per second\n"
    "and simulated seconds per wall second (sim_s_per_s), both over --steps actuated steps (2000).\n"
    "--dt-frac F: another step than the default (to compare builds or steps at the same step).\n"
    "--repeat N: each scene N times (1 to 64), then the best, median and worst figure.\n"
    "--evolve: evaluations per hour of the default experiment (amorph evolve) on 1 and 2 threads,\n"
    "each a run of N evaluations (60), and the speedup of the second core.\n"
    "--kernels: the cost of a product alone, float against the fixed-point build's Q24, in\n"
    "vectorisable loops" TOOL_DESKTOP_ONLY ".\n";

int cmd_bench(tool_ctx* c, int argc, char** argv)
{
    const char* scene = 0;
    long steps = 2000, n;
    int coll = -1;
    long evolve_evals = 0;
    int kernels = 0, repeat = 1;
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
            if (!tool_parse_real(v, 1e-6, 100, &dt_frac)) return tool_usage_error("bench: --dt-frac needs a number in [1e-6, 100]");
            i++;
        } else if (!strcmp(a, "--kernels")) {
            kernels = 1;
        } else if (!strcmp(a, "--evolve")) {
            evolve_evals = 60;
        } else if (!strcmp(a, "--evals")) {
            if (!tool_parse_long(v, 2, 1000000, &n)) return tool_usage_error("bench: --evals needs a whole number >= 2");
            evolve_evals = n, i++;
        } else return tool_usage_error("bench: unknown option '%s' (amorph bench --help)", a);
    }
    if (kernels) {
#if defined(AM_PROFILE_BOARD)
        return tool_not_in_build("bench --kernels", "the product kernels");
#else
        printf("build real=%s profile=%s\n", AM_REAL_NAME, AM_PROFILE_NAME);
        bench_kernels();
        return 0;
#endif
    }
    if (evolve_evals) {
        printf("build real=%s profile=%s\n", AM_REAL_NAME, AM_PROFILE_NAME);
        return tool_bench_evolve(c, evolve_evals);
    }
    printf("build real=%s profile=%s\n", AM_REAL_NAME, AM_PROFILE_NAME);
    if (scene) {
        if (coll != 0 && bench_scene(c, scene, steps, 1, dt_frac, repeat)) return 2;
        if (coll != 1 && bench_scene(c, scene, steps, 0, dt_frac, repeat)) return 2;
        return 0;
    }
    const char* scenes[2] = {AM_MAX_DIM >= 20 ? "sphere:20" : "sphere:8", AM_MAX_DIM >= 10 ? "cube:10" : "cube:8"};
    for (int k = 0; k < 2; k++)
        for (int on = 0; on <= 1; on++)
            if ((coll < 0 || coll == on) && bench_scene(c, scenes[k], steps, on, dt_frac, repeat)) return 2;
    tool_bench_express(c);
    return 0;
}
