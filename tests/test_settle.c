/* tests/test_settle.c: the evaluation on the bodies evolution meets (docs/physics.md, Evaluation
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

static void test_random_bodies(void)
{
    const int reprs[3] = {AM_REPR_GMX, AM_REPR_DCT, AM_REPR_CPPN};
    for (int k = 0; k < 3; k++)
        for (uint64_t seed = 1; seed <= BODIES; seed++) one_body(reprs[k], seed);
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
    return SUMMARY();
}
