/* tests of stepping a robot under control (amorph/api.h, docs/embedding.md, Stepping): the
 * sinusoid fed back step by step is the evaluation bit for bit (genome, lattice, evolved phases);
 * a held scale is the expansion it says (a free cube held at 1.1 grows to 1.1 edges); holding the
 * rest scale stops the gait; the same calls give the same bits; refusals are one line. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "amorph.h"
#include "harness.h"

static am_api_work W;
static char text[AM_GENOME_TEXT_MAX];
static double sc[AM_MAX_VOXELS], rt[AM_MAX_VOXELS], pos[3 * AM_MAX_VOXELS], strain[AM_MAX_VOXELS];
static int contact[AM_MAX_VOXELS];

static const char* const small[][2] = {{"workspace", "6"},        {"cycles", "2"},          {"period_steps", "100"},
                                       {"relax_max_steps", "400"}, {"relax_min_steps", "50"}, {"release_steps", "100"}};

static int prepare(const char* extra_key, const char* extra_val, char* err)
{
    if (am_api_init(&W, (long)sizeof W, err, AM_ERR_MAX) != AM_OK) return 0;
    for (int i = 0; i < 6; i++)
        if (am_api_set(&W, small[i][0], small[i][1], err, AM_ERR_MAX) != AM_OK) return 0;
    return !extra_key || am_api_set(&W, extra_key, extra_val, err, AM_ERR_MAX) == AM_OK;
}

#if AM_GENO_LAYERS && !defined(AM_COMPACT)
/* the robot in text: evaluated, then stepped with its own sinusoid fed back one step at a time */
static void fed_back_is_the_evaluation(const char* what, const char* robot, int genome)
{
    char err[AM_ERR_MAX];
    am_result r, settled;
    am_obs o0, o1;
    CHECK((genome ? am_api_eval_genome(&W, robot, &r, err, sizeof err) : am_api_eval_lattice(&W, robot, &r, err, sizeof err)) == AM_OK,
          "%s: %s", what, err);
    CHECK(r.voxels > 0, "%s: %d voxels", what, r.voxels);
    CHECK(am_api_sim_open(&W, robot, err, sizeof err) == AM_OK && am_api_sim_settle(&W, &settled, err, sizeof err) == AM_OK, "%s: %s",
          what, err);
    CHECK(settled.relax_steps == r.relax_steps && settled.settled == r.settled, "%s: settled after %ld steps, the evaluation %ld", what,
          settled.relax_steps, r.relax_steps);
    const long n = am_api_sim_voxels(&W, NULL, NULL);
    CHECK(n == r.voxels, "%s: %ld voxels open, %d evaluated", what, n, r.voxels);
    CHECK(am_api_sim_observe(&W, &o0, NULL, NULL, NULL, NULL, err, sizeof err) == AM_OK, "%s", err);
    const long steps = 2L * r.period_steps;
    for (long k = 0; k < steps; k++) {
        if (am_api_sim_sinusoid(&W, sc, rt, err, sizeof err) != AM_OK || am_api_sim_step(&W, 1, sc, rt, err, sizeof err) != AM_OK) {
            CHECK(0, "%s: step %ld: %s", what, k, err);
            return;
        }
    }
    CHECK(am_api_sim_observe(&W, &o1, NULL, NULL, NULL, NULL, err, sizeof err) == AM_OK, "%s", err);
    const uint64_t h = am_state_hash(&W.work.model, &W.work.state);
    CHECK(h == r.hash && o1.step == r.steps, "%s: state %016llx after %ld steps, the evaluation %016llx after %ld", what,
          (unsigned long long)h, o1.step, (unsigned long long)r.hash, r.steps);
    const double travel = hypot(o1.com[0] - o0.com[0], o1.com[1] - o0.com[1]);
    NEAR_REL(travel, r.travel, 1e-9);
    printf("    %s: %ld steps fed back, state %016llx as evaluated, travel %.6g m\n", what, steps, (unsigned long long)h, travel);
}

static void test_sinusoid_fed_back(void)
{
    char err[AM_ERR_MAX];
    am_rng rng;
    am_rng_seed(&rng, 3);
    CHECK(prepare("representation", "gmx", err), "%s", err);
    do CHECK(am_api_genome_new(&W, text, sizeof text, err, sizeof err) == AM_OK, "%s", err);
    while (strstr(text, "gmx 0\n"));
    fed_back_is_the_evaluation("gmx genome", text, 1);
    static const char lattice[] = "amorph-lattice 1\nsize 3 2 2\nvoxel_size 0.01\nmaterial passive E=1e6 density=1000 cte=0\n"
                                  "material active E=1e6 density=1000 cte=0.01\nlayer 0\n112\n221\nlayer 1\n111\n222\n";
    CHECK(prepare(NULL, NULL, err), "%s", err);
    fed_back_is_the_evaluation("lattice", lattice, 0);
    CHECK(prepare("actuation", "phase", err), "%s", err);
    CHECK(am_api_genome_new(&W, text, sizeof text, err, sizeof err) == AM_OK && strstr(text, "evolved phase"), "%s", err);
    fed_back_is_the_evaluation("evolved phases", text, 1);
}

/* a free cube (no gravity, no floor) held at scale 1.1: its voxels' centres end 1.1 edges apart */
static void test_held_scale_is_the_expansion(void)
{
    char err[AM_ERR_MAX];
    static const char cube[] = "amorph-lattice 1\nsize 2 2 2\nvoxel_size 0.01\nmaterial active E=1e6 density=1000 cte=0.01\n"
                               "layer 0\n11\n11\nlayer 1\n11\n11\n";
    CHECK(prepare("gravity", "0", err) && am_api_set(&W, "floor", "off", err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_api_sim_open(&W, cube, err, sizeof err) == AM_OK && am_api_sim_settle(&W, NULL, err, sizeof err) == AM_OK, "%s", err);
    const long n = am_api_sim_voxels(&W, NULL, NULL);
    for (long i = 0; i < n; i++) sc[i] = 1.1;
    CHECK(am_api_sim_step(&W, 4000, sc, NULL, err, sizeof err) == AM_OK, "%s", err);
    am_obs o;
    CHECK(am_api_sim_observe(&W, &o, pos, NULL, strain, contact, err, sizeof err) == AM_OK && !o.diverged, "%s", err);
    double worst = 0;
    for (long i = 0; i < n; i++)
        for (long j = i + 1; j < n; j++) {
            const double d = sqrt(pow(pos[3 * i] - pos[3 * j], 2) + pow(pos[3 * i + 1] - pos[3 * j + 1], 2) + pow(pos[3 * i + 2] - pos[3 * j + 2], 2));
            if (d < 0.0125) worst = fmax(worst, fabs(d - 0.011) / 0.011); /* face neighbours */
        }
    CHECK(worst < 1e-3, "face neighbours at 1.1 edges within %.2g (want 1e-3)", worst);
    double e = 0;
    for (long i = 0; i < n; i++) e = fmax(e, fabs(strain[i]));
    CHECK(e < 1e-3, "strain against the held rest length %.2g (want 0)", e);
    CHECK(o.contacts == 0, "no floor: %d contacts", o.contacts);
}

/* half the voxels held at the rest scale: another motion than the open loop's; the same calls twice give the same bits */
static void test_control_changes_the_motion(void)
{
    char err[AM_ERR_MAX];
    am_result r;
    CHECK(prepare("representation", "gmx", err), "%s", err);
    am_api_seed(&W, 11, err, sizeof err);
    do CHECK(am_api_genome_new(&W, text, sizeof text, err, sizeof err) == AM_OK && am_api_eval_genome(&W, text, &r, err, sizeof err) == AM_OK,
             "%s", err);
    while (!(r.travel > 1e-3));
    uint64_t h[2];
    am_obs o;
    for (int t = 0; t < 2; t++) {
        CHECK(am_api_sim_open(&W, text, err, sizeof err) == AM_OK && am_api_sim_settle(&W, NULL, err, sizeof err) == AM_OK, "%s", err);
        const long n = am_api_sim_voxels(&W, NULL, NULL);
        for (long i = 0; i < n; i++) sc[i] = i % 2 ? 1.0 : (double)NAN; /* half held at the rest scale, half their own */
        CHECK(am_api_sim_step(&W, 2L * r.period_steps, sc, NULL, err, sizeof err) == AM_OK, "%s", err);
        CHECK(am_api_sim_observe(&W, &o, NULL, NULL, NULL, NULL, err, sizeof err) == AM_OK, "%s", err);
        h[t] = o.hash;
    }
    CHECK(h[0] == h[1], "the same calls: %016llx, %016llx", (unsigned long long)h[0], (unsigned long long)h[1]);
    CHECK(h[0] != r.hash, "half the voxels held: the open-loop state");
}

/* the robot stepped with no action (NULL) all the way: the evaluation bit for bit */
static void test_no_action_is_the_evaluation(void)
{
    char err[AM_ERR_MAX];
    am_result r;
    am_obs o;
    CHECK(prepare("representation", "gmx", err), "%s", err);
    am_api_seed(&W, 5, err, sizeof err);
    do CHECK(am_api_genome_new(&W, text, sizeof text, err, sizeof err) == AM_OK && am_api_eval_genome(&W, text, &r, err, sizeof err) == AM_OK,
             "%s", err);
    while (r.voxels < 2);
    CHECK(am_api_sim_open(&W, text, err, sizeof err) == AM_OK && am_api_sim_settle(&W, NULL, err, sizeof err) == AM_OK, "%s", err);
    while (W.work.state.step < r.steps) {
        const long left = r.steps - W.work.state.step;
        if (am_api_sim_step(&W, left < 7 ? left : 7, NULL, NULL, err, sizeof err) != AM_OK) break;
    }
    CHECK(am_api_sim_observe(&W, &o, NULL, NULL, NULL, NULL, err, sizeof err) == AM_OK, "%s", err);
    CHECK(o.hash == r.hash && o.step == r.steps, "no action: state %016llx after %ld steps, the evaluation %016llx after %ld",
          (unsigned long long)o.hash, o.step, (unsigned long long)r.hash, r.steps);
}

/* control that comes and goes (a voxel held, left to its sinusoid, given its sinusoid's own value,
 * no action at all, every voxel held): after every call each link's rest length is the mean of
 * its two voxels' edges at their current scales (am_state_validate), with phases and without */
static void test_rest_lengths_follow_the_control(void)
{
    char err[AM_ERR_MAX];
    am_rng rng;
    am_rng_seed(&rng, 17);
    for (int phases = 0; phases < 2; phases++) {
        CHECK(prepare("representation", "gmx", err) && (!phases || am_api_set(&W, "actuation", "phase", err, sizeof err) == AM_OK), "%s", err);
        do CHECK(am_api_genome_new(&W, text, sizeof text, err, sizeof err) == AM_OK, "%s", err);
        while (strstr(text, "gmx 0\n"));
        CHECK(am_api_sim_open(&W, text, err, sizeof err) == AM_OK && am_api_sim_settle(&W, NULL, err, sizeof err) == AM_OK, "%s", err);
        const long n = am_api_sim_voxels(&W, NULL, NULL);
        int bad = 0, calls = 0;
        for (int c = 0; c < 60 && !bad; c++, calls++) {
            const int kind = (int)am_rng_below(&rng, 5);
            CHECK(am_api_sim_sinusoid(&W, sc, NULL, err, sizeof err) == AM_OK, "%s", err);
            for (long i = 0; i < n; i++) {
                const int pick = (int)am_rng_below(&rng, 4);
                if (kind == 1) sc[i] = 1.02; /* every voxel held */
                else if (pick == 0) sc[i] = 0.97 + 0.01 * (double)am_rng_below(&rng, 6); /* held */
                else if (pick == 1) sc[i] = (double)NAN; /* its sinusoid */
                /* else its sinusoid's own value at this step, held */
            }
            const long steps = 1 + (long)am_rng_below(&rng, 9);
            CHECK(am_api_sim_step(&W, steps, kind == 0 ? NULL : sc, NULL, err, sizeof err) == AM_OK, "%s", err);
            if (am_state_validate(&W.work.model, &W.work.state, err, sizeof err) != AM_OK) bad = 1;
        }
        CHECK(!bad, "%s, after call %d: %s", phases ? "evolved phases" : "global actuation", calls, err);
        CHECK(!W.work.state.diverged, "diverged");
    }
}
#endif

static void test_refusals(void)
{
    char err[AM_ERR_MAX];
    static const char cube[] = "amorph-lattice 1\nsize 1 1 1\nvoxel_size 0.01\nmaterial active E=1e6 density=1000 cte=0.01\nlayer 0\n1\n";
    CHECK(prepare(NULL, NULL, err), "%s", err);
    CHECK(am_api_sim_step(&W, 1, NULL, NULL, err, sizeof err) == AM_ERR_ARG && strstr(err, "no robot is open"), "%s", err);
#if AM_GENO_LAYERS && !defined(AM_COMPACT)
    CHECK(am_api_sim_open(&W, cube, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_api_sim_step(&W, 1, NULL, NULL, err, sizeof err) == AM_ERR_ARG && strstr(err, "not settled"), "%s", err);
    CHECK(am_api_sim_settle(&W, NULL, err, sizeof err) == AM_OK, "%s", err);
    sc[0] = 3.0;
    CHECK(am_api_sim_step(&W, 1, sc, NULL, err, sizeof err) == AM_ERR_RANGE && strstr(err, "voxel 0: scale 3") && printable_line(err), "%s",
          err);
    CHECK(am_api_sim_step(&W, -1, NULL, NULL, err, sizeof err) == AM_ERR_RANGE, "%s", err);
    CHECK(am_api_sim_open(&W, "amorph-lattice 1\nsize 1\n", err, sizeof err) == AM_ERR_PARSE && !strncmp(err, "lattice:", 8), "%s", err);
    CHECK(am_api_sim_observe(&W, NULL, NULL, NULL, NULL, NULL, err, sizeof err) == AM_ERR_ARG, "a failed open closes the robot: %s", err);
#else
    CHECK(am_api_sim_open(&W, cube, err, sizeof err) == AM_ERR_CAPACITY && strstr(err, "keeps no actuation per voxel"), "%s", err);
#endif
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    (void)test_quick;
#if AM_GENO_LAYERS && !defined(AM_COMPACT)
    RUN(test_sinusoid_fed_back);
    RUN(test_held_scale_is_the_expansion);
    RUN(test_control_changes_the_motion);
    RUN(test_no_action_is_the_evaluation);
    RUN(test_rest_lengths_follow_the_control);
#endif
    RUN(test_refusals);
    return SUMMARY();
}
