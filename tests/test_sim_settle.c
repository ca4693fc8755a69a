/* tests/test_sim_settle.c: the evaluation on the bodies evolution meets (docs/physics.md, Evaluation
 * and Time step). 30 random genomes, 10 per representation (seeds 1..10, what `amorph random
 * --repr R --seed N` writes), expressed in the seed's 20^3 workspace with the built-in palette:
 * - relaxation settles every one (settled = 1), and with the actuation off each travels less than
 *   10 um (3-D) in the 10-cycle movement segment: what evolution scores is locomotion, not a body
 *   still sagging, tipping or creeping;
 * - with the seed's actuation each runs at the default step (0.9 dt_rec) without diverging;
 * - the seed's time step search gives a step under which the actuated sphere:20 and every body
 *   stay stable.
 * The float desktop build runs all 30; other builds (AddressSanitizer's, and AM_TEST_QUICK=1 as
 * under valgrind) only the bodies of at most QUICK_VOXELS voxels, with the actuation off, to keep
 * the suite's time. */
#include "amorph.h"
#include "harness.h"

static am_genome g_genome;
static am_geno_work g_work;
static am_lattice g_lat;
static am_model g_m;
static am_state g_s;
static char g_err[AM_ERR_MAX];

enum { BODIES = 10, QUICK_VOXELS = 200 };

/* the body of random genome (repr, seed) into g_lat; its voxel count, -1 on failure */
static int body(int repr, uint64_t seed)
{
    am_geno_def def = am_default_geno();
    def.repr = repr;
    if (def.dct_k > def.nx) def.dct_k = def.nx;
    am_rng rng;
    am_rng_seed(&rng, seed);
    am_status st = am_genome_init(&g_genome, &def, &rng, g_err, (int)sizeof g_err);
    CHECK(st == AM_OK, "genome %s %llu: %s", am_repr_name(repr), (unsigned long long)seed, g_err);
    if (st != AM_OK) return -1;
    am_default_palette_into(&g_lat.palette);
    char msg[AM_ERR_MAX];
    st = am_genome_to_lattice(&g_genome, NULL, &g_work, &g_lat, msg, (int)sizeof msg);
    CHECK(st == AM_OK, "express %s %llu: %s", am_repr_name(repr), (unsigned long long)seed, msg);
    return st == AM_OK ? am_lattice_count(&g_lat) : -1;
}

static int build(double amplitude)
{
    am_env env = am_default_env();
    env.temp_amplitude = (am_param)amplitude;
    am_status st = am_model_build(&g_m, &g_lat, &env, g_err, (int)sizeof g_err);
    CHECK(st == AM_OK, "am_model_build: %s", g_err);
    return st == AM_OK;
}

static int full_set(void)
{
#if defined(AM_REAL_FLOAT) && !defined(AM_PROFILE_BOARD) && !defined(__SANITIZE_ADDRESS__)
    return !test_quick();
#else
    (void)test_quick; /* the harness's, unused here */
    return 0;
#endif
}

/* fn on each of the 30 random genomes: seeds 1..BODIES of GMX, DCT and CPPN */
static void each_body(void (*fn)(int repr, uint64_t seed))
{
    const int reprs[3] = {AM_REPR_GMX, AM_REPR_DCT, AM_REPR_CPPN};
    for (int k = 0; k < 3; k++)
        for (uint64_t seed = 1; seed <= BODIES; seed++) fn(reprs[k], seed);
}

static int g_settled, g_bodies, g_stable, g_searched;
static double g_worst_travel, g_worst_speed;
static long g_worst_relax;

static void one_body(int repr, uint64_t seed)
{
    int nv = body(repr, seed);
    if (nv <= 0) return;
    if (!full_set() && nv > QUICK_VOXELS) return;
    const char* name = am_repr_name(repr);
    am_eval_def def = am_default_eval();
    am_result r;

    /* actuation off: settled, and no travel */
    if (!build(0)) return;
    am_evaluate(&g_m, &g_s, &def, &r);
    double travel = sqrt(r.dx * r.dx + r.dy * r.dy + r.dz * r.dz);
    printf("    %s %llu: %d voxels, settled %d after %ld steps (%ld kinetic stops, residual %.2e m/s), "
           "travel with the actuation off %.2e m\n",
           name, (unsigned long long)seed, nv, r.settled, r.relax_steps, r.kinetic_resets, r.residual_speed, travel);
    g_bodies++;
    g_settled += r.settled;
    CHECK(r.settled == 1 && !r.diverged, "%s %llu did not settle (%ld steps, residual %.3g m/s, diverged %d)", name,
          (unsigned long long)seed, r.relax_steps, r.residual_speed, r.diverged);
    CHECK(travel < 10e-6, "%s %llu travelled %.3g m with the actuation off", name, (unsigned long long)seed, travel);
    if (travel > g_worst_travel) g_worst_travel = travel;
    if (r.residual_speed > g_worst_speed) g_worst_speed = r.residual_speed;
    if (r.relax_steps > g_worst_relax) g_worst_relax = r.relax_steps;
    if (!full_set()) return;

    /* the seed's actuation at the default step */
    if (!build(30)) return;
    am_evaluate(&g_m, &g_s, &def, &r);
    printf("    %s %llu actuated at %.2f dt_rec: fitness %.4e m, diverged %d, settled %d\n", name, (unsigned long long)seed,
           (double)g_m.env.dt_frac, r.fitness, r.diverged, r.settled);
    CHECK(!r.diverged && r.settled, "%s %llu actuated: diverged %d at step %ld, settled %d", name,
          (unsigned long long)seed, r.diverged, g_s.diverge_step, r.settled);
    g_stable += !r.diverged;

    /* and at the step the seed's search finds */
    def.dt_search = 1;
    am_evaluate(&g_m, &g_s, &def, &r);
    printf("    %s %llu actuated at the searched step %.3f dt_rec: fitness %.4e m, diverged %d\n", name,
           (unsigned long long)seed, r.dt / am_to_si(&g_m, g_m.dt_rec, AM_DIM_TIME), r.fitness, r.diverged);
    CHECK(!r.diverged, "%s %llu diverged at the searched step %.3g s (step %ld)", name, (unsigned long long)seed, r.dt,
          g_s.diverge_step);
    g_searched += !r.diverged;
}

/* settling at the pseudo-step (relax_dt_frac, 1.8 dt_rec) against settling at the run's step
 * (relax_dt_frac 0), evaluated with the actuation off and no movement (cycles 0), so that the end
 * state is the rest state. The equilibrium does not depend on the step, the path to it does: a
 * body that tips or rolls may land turned a little and slid. Wanted: every rest pose within
 * REST_SHAPE (RMS about the centre of mass: shape and orientation) and REST_HEIGHT (the centre of
 * mass's height), the median pose within REST_MEDIAN (the settle speed's tolerance), and fewer
 * steps over the bodies. */
#define REST_SHAPE 2e-3   /* m: a fifth of the 1 cm voxel */
#define REST_HEIGHT 1e-4  /* m */
#define REST_MEDIAN 1e-5  /* m */
static double g_rest_d[3 * BODIES];
static long g_rest_steps[2];
static double g_rest_worst, g_rest_slide;
static int g_rest_bodies;
static am_state g_s2;

/* the RMS over the voxels of the difference of their positions relative to the centre of mass
 * (m): how far two rest poses differ in shape and orientation, a horizontal slide left out */
static double pose_diff(const am_model* m, const am_state* a, const double ca[3], const am_state* b, const double cb[3])
{
    double sum = 0;
    for (int i = 0; i < m->nv; i++)
        for (int k = 0; k < 3; k++) {
            const double d = ((AM_TO_DOUBLE(m->x0[k][i]) + AM_TO_DOUBLE(a->x[k][i])) * m->unit_len - ca[k]) - ((AM_TO_DOUBLE(m->x0[k][i]) + AM_TO_DOUBLE(b->x[k][i])) * m->unit_len - cb[k]);
            sum += d * d;
        }
    return m->nv ? sqrt(sum / m->nv) : 0;
}

static void rest_pose(int repr, uint64_t seed)
{
    int nv = body(repr, seed);
    if (nv <= 0 || (!full_set() && nv > QUICK_VOXELS) || !build(0)) return;
    double com[2][3];
    am_result r[2];
    for (int k = 0; k < 2; k++) {
        am_eval_def def = am_default_eval();
        def.cycles = 0;
        if (k == 1) def.relax_dt_frac = AM_P(0);
        am_evaluate(&g_m, k ? &g_s2 : &g_s, &def, &r[k]);
        am_com(&g_m, k ? &g_s2 : &g_s, com[k]);
        g_rest_steps[k] += r[k].relax_steps;
    }
    const double d = pose_diff(&g_m, &g_s, com[0], &g_s2, com[1]), dz = fabs(com[0][2] - com[1][2]);
    const double slide = sqrt((com[0][0] - com[1][0]) * (com[0][0] - com[1][0]) + (com[0][1] - com[1][1]) * (com[0][1] - com[1][1]));
    printf("    %s %llu: %d voxels, rest at the pseudo-step %.3g s after %ld steps%s, at the run's step after %ld; "
           "poses %.2e m apart (RMS about the centre of mass), centre of mass %.2e m higher or lower, slid %.2e m\n",
           am_repr_name(repr), (unsigned long long)seed, nv, r[0].relax_dt, r[0].relax_steps, r[0].relax_retried ? " (retried)" : "",
           r[1].relax_steps, d, dz, slide);
    CHECK(r[0].settled && r[1].settled && !r[0].diverged, "%s %llu: settled %d / %d", am_repr_name(repr), (unsigned long long)seed,
          r[0].settled, r[1].settled);
    CHECK(d <= REST_SHAPE && dz <= REST_HEIGHT, "%s %llu: the rest poses are %.3g m apart (at most %g), their centres of mass %.3g m in height "
          "(at most %g)", am_repr_name(repr), (unsigned long long)seed, d, REST_SHAPE, dz, REST_HEIGHT);
    g_rest_d[g_rest_bodies] = d;
    g_rest_worst = d > g_rest_worst ? d : g_rest_worst;
    g_rest_slide = slide > g_rest_slide ? slide : g_rest_slide;
    g_rest_bodies++;
}

static int cmp_double(const void* a, const void* b)
{
    const double x = *(const double*)a, y = *(const double*)b;
    return (x > y) - (x < y);
}

static void test_rest_pose(void)
{
    each_body(rest_pose);
    printf("    %d bodies: %ld relaxation steps at the pseudo-step, %ld at the run's step (%.2fx); rest poses up to %.2e m apart, "
           "slid up to %.2e m\n",
           g_rest_bodies, g_rest_steps[0], g_rest_steps[1], (double)g_rest_steps[1] / (double)(g_rest_steps[0] ? g_rest_steps[0] : 1),
           g_rest_worst, g_rest_slide);
    CHECK(g_rest_bodies >= (full_set() ? 3 * BODIES : 1), "only %d bodies tried", g_rest_bodies);
    qsort(g_rest_d, (size_t)g_rest_bodies, sizeof g_rest_d[0], cmp_double);
    const double median = g_rest_bodies ? g_rest_d[g_rest_bodies / 2] : 0;
    printf("    median pose difference %.2e m\n", median);
    CHECK(median <= REST_MEDIAN, "the median rest pose differs by %.3g m (at most %g)", median, REST_MEDIAN);
    /* the point of the pseudo-step: over the bodies that take long to settle, fewer steps */
    if (full_set())
        CHECK(g_rest_steps[1] >= 1.3 * g_rest_steps[0], "the pseudo-step saved too little: %ld steps against %ld", g_rest_steps[0],
              g_rest_steps[1]);
}

/* a pseudo-step the body cannot take (6 dt_rec diverges): the relaxation is done again at the
 * run's step, and the evaluation is the one with the pseudo-step off, bit for bit, recorded or not */
static void test_pseudo_step_fallback(void)
{
    am_status st = am_scene_build(&g_lat, "sphere:8", g_err, (int)sizeof g_err);
    CHECK(st == AM_OK, "scene: %s", g_err);
    if (!build(30)) return;
    am_eval_def def = am_default_eval();
    def.cycles = 1;
    def.relax_dt_frac = AM_P(0);
    am_result off, bad, rec_off, rec_bad;
    am_evaluate(&g_m, &g_s, &def, &off);
    def.relax_dt_frac = AM_P(6);
    am_evaluate(&g_m, &g_s, &def, &bad);
    /* recorded: the frames of the failed pseudo-step are never handed out */
    enum { FRAMES = 64, CAP = FRAMES * 400 * 7 };
    static float pose[2][CAP];
    static long steps[2][FRAMES];
    am_record rec[2];
    am_result* rr[2] = {&rec_off, &rec_bad};
    for (int k = 0; k < 2; k++) {
        memset(&rec[k], 0, sizeof rec[k]);
        rec[k].every = 100;
        rec[k].pose = pose[k];
        rec[k].step = steps[k];
        rec[k].pose_cap = CAP;
        rec[k].max_frames = FRAMES;
        def.record = &rec[k];
        def.relax_dt_frac = k == 0 ? AM_P(0) : AM_P(6);
        am_evaluate(&g_m, &g_s, &def, rr[k]);
    }
    printf("    sphere:8, pseudo-step 6 dt_rec: retried %d, hash %016llx (off: %016llx); recorded: %d and %d frames\n", bad.relax_retried,
           (unsigned long long)bad.hash, (unsigned long long)off.hash, rec[0].frames, rec[1].frames);
    CHECK(!off.diverged && off.settled, "sphere:8 with the pseudo-step off: diverged %d, settled %d", off.diverged, off.settled);
    CHECK(bad.relax_retried == 1 && rec_bad.relax_retried == 1, "the failed pseudo-step was not retried");
    CHECK(bad.hash == off.hash && rec_bad.hash == off.hash && rec_off.hash == off.hash && bad.fitness == off.fitness,
          "the retried evaluation differs from the one at the run's step");
    CHECK(rec[0].frames > 2 && !rec[0].truncated && rec[1].frames == rec[0].frames &&
              !memcmp(pose[0], pose[1], sizeof(float) * (size_t)rec[0].frames * (size_t)rec[0].nv * 7) &&
              !memcmp(steps[0], steps[1], sizeof(long) * (size_t)rec[0].frames),
          "the recording of the retried evaluation differs: %d frames against %d", rec[1].frames, rec[0].frames);
    CHECK(fabs(bad.sim_seconds - off.sim_seconds) < 1e-12, "simulated time %.9g s against %.9g s", bad.sim_seconds, off.sim_seconds);
}

static void test_random_bodies(void)
{
    each_body(one_body);
    printf("    %d bodies: %d settled (slowest %ld steps, residual speed up to %.2e m/s), travel with the actuation "
           "off up to %.2e m; actuated: %d stable at the default step, %d at the searched step\n",
           g_bodies, g_settled, g_worst_relax, g_worst_speed, g_worst_travel, g_stable, g_searched);
    CHECK(g_bodies >= (full_set() ? 3 * BODIES : 1), "only %d bodies tried", g_bodies);
}

/* the seed's sphere, half actuated: stable at 0.9 dt_rec and at the searched step */
static void test_sphere(void)
{
    if (!full_set()) return;
    am_status st = am_scene_build(&g_lat, "sphere:20", g_err, (int)sizeof g_err);
    CHECK(st == AM_OK, "scene: %s", g_err);
    if (!build(30)) return;
    am_eval_def def = am_default_eval();
    am_result r;
    am_evaluate(&g_m, &g_s, &def, &r);
    printf("    sphere:20 at %.2f dt_rec: fitness %.4e m, diverged %d, settled %d after %ld steps\n", (double)g_m.env.dt_frac,
           r.fitness, r.diverged, r.settled, r.relax_steps);
    CHECK((double)g_m.env.dt_frac >= 0.9 - 1e-6, "the default step is %.2f dt_rec", (double)g_m.env.dt_frac);
    CHECK(!r.diverged && r.settled, "sphere:20 at the default step: diverged %d, settled %d", r.diverged, r.settled);
    def.dt_search = 1;
    am_evaluate(&g_m, &g_s, &def, &r);
    printf("    sphere:20 at the searched step %.3f dt_rec: fitness %.4e m, diverged %d\n",
           r.dt / am_to_si(&g_m, g_m.dt_rec, AM_DIM_TIME), r.fitness, r.diverged);
    CHECK(!r.diverged, "sphere:20 diverged at the searched step");
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    RUN(test_sphere);
    RUN(test_random_bodies);
    RUN(test_rest_pose);
    RUN(test_pseudo_step_fallback);
    return SUMMARY();
}
