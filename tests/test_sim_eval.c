/* The evaluation protocol around the step (src/sim/sim_eval.c): recording, fitness modes, empty
 * bodies, the seed's time step search, the gait figures and the sustained score. The model build's
 * errors and link layout are tests/test_sim_model.c. */
#include "amorph.h"
#include "harness.h"

static am_lattice g_lat;
static am_model g_m;
static am_state g_s;
static float g_pose[64 * 64 * 7];
static long g_steps[64];

static void build(const char* scene)
{
    char err[AM_ERR_MAX];
    am_env env = am_default_env();
    CHECK(am_scene_build(&g_lat, scene, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_OK, "%s", err);
}

/* frames land every `every` steps, start with the initial pose, and stop with `truncated` set */
static void test_recording(void)
{
    build("sphere:4"); /* 32 voxels */
    am_record rec = {0};
    rec.every = 100;
    rec.max_frames = 64;
    rec.pose = g_pose;
    rec.step = g_steps;
    rec.pose_cap = (long)(sizeof g_pose / sizeof g_pose[0]);
    am_eval_def def = am_default_eval();
    def.cycles = 2;
    def.record = &rec;
    am_result r;
    am_evaluate(&g_m, &g_s, &def, &r);
    long expect = r.steps / 100 + 1;
    CHECK(rec.frames == expect, "frames %d, expected %ld for %ld steps", rec.frames, expect, r.steps);
    CHECK(!rec.truncated, "a recording with room to spare was truncated");
    CHECK(rec.nv == g_m.nv, "nv %d", rec.nv);
    CHECK(g_steps[0] == 0 && g_steps[1] == 100, "frame steps %ld %ld", g_steps[0], g_steps[1]);
    NEAR(g_pose[0], (float)am_to_si(&g_m, g_m.x0[0][0], AM_DIM_LENGTH), 0); /* frames hold floats (SI) in every build */
    NEAR(g_pose[2], (float)am_to_si(&g_m, g_m.x0[2][0], AM_DIM_LENGTH), 0);
    NEAR(g_pose[3], 1.0, 0); /* identity orientation at the start */
    /* the last frame is the final state (steps is a multiple of 100 only by chance, so compare the
     * frame with its step) */
    long last = g_steps[rec.frames - 1];
    CHECK(last <= r.steps && r.steps - last < 100, "last frame at step %ld of %ld", last, r.steps);

    rec.max_frames = 3;
    am_evaluate(&g_m, &g_s, &def, &r);
    CHECK(rec.frames == 3 && rec.truncated, "frames %d truncated %d with room for 3", rec.frames, rec.truncated);
}

/* a sink's steps: what it was handed, in order */
typedef struct sink_log {
    long step[256];
    int actuate[256];
    int n;
} sink_log;

static void sink_count(void* ctx, const am_model* m, const struct am_state* s)
{
    sink_log* lg = (sink_log*)ctx;
    (void)m;
    if (lg->n < 256) lg->step[lg->n] = s->step, lg->actuate[lg->n] = s->actuate;
    lg->n++;
}

/* a sink is handed every multiple of `every`, the relaxation's last step and the last step, each
 * once, stores nothing, and changes nothing of the result */
static void test_recording_sink(void)
{
    build("sphere:4");
    am_eval_def def = am_default_eval();
    def.cycles = 2;
    am_result plain, r;
    am_evaluate(&g_m, &g_s, &def, &plain);
    static sink_log lg;
    am_record rec = {0};
    rec.every = 70;
    rec.sink = sink_count;
    rec.sink_ctx = &lg;
    def.record = &rec;
    am_evaluate(&g_m, &g_s, &def, &r);
    CHECK(r.hash == plain.hash && r.fitness == plain.fitness, "the sink changed the run: hash %016llx against %016llx",
          (unsigned long long)r.hash, (unsigned long long)plain.hash);
    long expect = r.steps / 70 + 1 + (r.relax_steps % 70 != 0) + (r.steps % 70 != 0);
    CHECK(lg.n == expect && rec.frames == lg.n, "sink handed %d frames (frames %d), expected %ld (relax %ld, steps %ld)", lg.n,
          rec.frames, expect, r.relax_steps, r.steps);
    CHECK(r.relax_steps % 70 != 0 || r.steps % 70 != 0, "the test wants a segment end off the multiples of 70 (relax %ld, steps %ld)",
          r.relax_steps, r.steps);
    int seen_relax = 0;
    for (int i = 0; i < lg.n && i < 256; i++) {
        long st = lg.step[i];
        CHECK(st % 70 == 0 || st == r.relax_steps || st == r.steps, "sink handed step %ld", st);
        CHECK(i == 0 || st > lg.step[i - 1], "steps not rising: %ld after %ld", st, i ? lg.step[i - 1] : -1L);
        CHECK(lg.actuate[i] == (st > r.relax_steps), "step %ld actuate %d (relaxation to %ld)", st, lg.actuate[i], r.relax_steps);
        seen_relax |= st == r.relax_steps;
    }
    CHECK(lg.step[0] == 0 && seen_relax && lg.step[(lg.n < 256 ? lg.n : 256) - 1] == r.steps, "first %ld, relaxation's end %d, last %ld",
          lg.step[0], seen_relax, lg.step[(lg.n < 256 ? lg.n : 256) - 1]);
}

/* the three fitness measures are views of one displacement */
static void test_fitness_modes(void)
{
    build("sphere:6");
    am_eval_def def = am_default_eval();
    def.cycles = 3;
    am_result h, x, d3;
    am_evaluate(&g_m, &g_s, &def, &h);
    def.fitness = AM_FIT_PLUS_X;
    am_evaluate(&g_m, &g_s, &def, &x);
    def.fitness = AM_FIT_3D;
    am_evaluate(&g_m, &g_s, &def, &d3);
    CHECK(h.hash == x.hash && x.hash == d3.hash, "the fitness measure changed the motion");
    NEAR(h.fitness, sqrt(h.dx * h.dx + h.dy * h.dy), 0);
    NEAR(x.fitness, x.dx, 0);
    NEAR(d3.fitness, sqrt(h.dx * h.dx + h.dy * h.dy + h.dz * h.dz), 0);
    CHECK(h.fitness > 1e-4, "the actuated sphere should move (fitness %g m)", h.fitness);
    CHECK(h.move_steps == 3L * g_m.env.period_steps, "move steps %ld", h.move_steps);
    CHECK(h.settled, "relaxation did not settle");
    /* a passive body does not walk */
    build("cube:3");
    def.fitness = AM_FIT_HORIZONTAL;
    am_evaluate(&g_m, &g_s, &def, &h);
    CHECK(h.fitness < 1e-9, "a passive cube moved %g m", h.fitness);
}

/* a body that does not settle within the relaxation has no score (docs/evolve.md): fitness -1,
 * its travel measured all the same; the same body given room settles and scores its travel */
static void test_unsettled_no_score(void)
{
    build("sphere:6");
    am_eval_def def = am_default_eval();
    def.cycles = 2;
    def.relax_max_steps = 300; /* less than the release window: it cannot settle */
    am_result r;
    am_evaluate(&g_m, &g_s, &def, &r);
    CHECK(!r.settled && !r.diverged && r.relax_steps == 300, "settled %d diverged %d after %ld steps", r.settled, r.diverged,
          r.relax_steps);
    CHECK(r.fitness == -1.0, "an unsettled body scored %g", r.fitness);
    NEAR(r.travel, sqrt(r.dx * r.dx + r.dy * r.dy), 0);
    CHECK(r.travel > 1e-5, "its travel is still measured: %g m", r.travel);
    def.relax_max_steps = am_default_eval().relax_max_steps;
    am_evaluate(&g_m, &g_s, &def, &r);
    CHECK(r.settled && r.fitness == r.travel && r.fitness > 0, "given room: settled %d, fitness %g, travel %g", r.settled, r.fitness,
          r.travel);
}

/* the relaxation's step counts are steps of the default step: at a third of it they are three
 * times as many, the same time in seconds; the period in seconds is held the same way */
static void test_steps_in_seconds(void)
{
    char err[AM_ERR_MAX];
    CHECK(am_scene_build(&g_lat, "halfbar:6", err, sizeof err) == AM_OK, "%s", err);
    am_env env = am_default_env();
    am_eval_def def = am_default_eval();
    def.cycles = 1;
    def.relax_max_steps = 1000; /* too short to settle: the count is what it ran */
    def.release_steps = 2000;
    am_result a, b;
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_OK, "%s", err);
    am_evaluate(&g_m, &g_s, &def, &a);
    CHECK(am_steps_at(&g_m, &g_s, 1000) == 1000 && a.relax_steps == 1000, "at the default step: %ld relaxation steps", a.relax_steps);
    const double period = a.period_steps * a.dt;
    env.dt_frac = AM_P(0.3);
    env.period_s = (am_param)period;
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_OK, "%s", err);
    am_evaluate(&g_m, &g_s, &def, &b);
    CHECK(b.relax_steps == 3000, "at 0.3 dt_rec: %ld relaxation steps, want 3000", b.relax_steps);
    CHECK(b.period_steps == 1500 && b.move_steps == 1500, "at 0.3 dt_rec: period %d steps, movement %ld", b.period_steps, b.move_steps);
    NEAR(b.period_steps * b.dt, period, 1e-6 * period);
    /* a period in seconds too long for 10^7 steps is refused with the numbers */
    env.period_s = AM_P(1e4);
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_ERR_RANGE && strstr(err, "period_s = 10000 s is"), "%s", err);
}

/* the seed's search: deterministic, between the tried extremes, and stable for 2000 steps */
static void test_dt_search(void)
{
    build("cube:4");
    am_real a = am_dt_search(&g_m, &g_s);
    am_real b = am_dt_search(&g_m, &g_s);
    CHECK(a == b, "search not deterministic: %g vs %g", (double)a, (double)b);
    CHECK(a > AM_MUL(AM_R(0.0001), g_m.dt_rec) && a <= AM_MUL(AM_R(9.5), g_m.dt_rec), "dt %g, dt_rec %g", AM_TO_DOUBLE(a), AM_TO_DOUBLE(g_m.dt_rec));
    printf("    dt search: %.4g s = %.3f dt_rec\n", am_to_si(&g_m, a, AM_DIM_TIME), AM_TO_DOUBLE(a) / AM_TO_DOUBLE(g_m.dt_rec));
    am_state_reset(&g_m, &g_s);
    g_s.dt = a;
    am_steps(&g_m, &g_s, test_quick() ? 500 : 2000);
    CHECK(!g_s.diverged, "the searched dt diverged at rest");
    /* ten times past it is unstable */
    am_state_reset(&g_m, &g_s);
    g_s.dt = AM_MUL(AM_R(10), a);
    am_steps(&g_m, &g_s, 2000);
    CHECK(g_s.diverged, "10x the searched dt did not diverge");
}

/* the gait figures of a body in free fall (no floor, no global damping): airborne throughout,
 * and each cycle's rise and fall is the fall of g t^2 / 2 over the cycle's sampled steps */
static void test_gait_free_fall(void)
{
    char err[AM_ERR_MAX];
    static am_gait gait;
    am_env env = am_default_env();
    env.floor = 0;
    env.zeta_global_scale = AM_P(0);
    env.temp_amplitude = AM_P(0);
    CHECK(am_scene_build(&g_lat, "cube:3", err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_OK, "%s", err);
    am_eval_def def = am_default_eval();
    def.cycles = 3;
    def.relax_max_steps = 300;
    def.gait = &gait;
    am_result r;
    am_evaluate(&g_m, &g_s, &def, &r);
    CHECK(!r.settled && r.relax_steps == 300 && gait.cycles == 3, "relax %ld, cycles %d", r.relax_steps, gait.cycles);
    const double g = am_to_si(&g_m, g_m.gravity, AM_DIM_ACCEL), dt = r.dt;
    const long P = g_m.env.period_steps;
    for (int c = 0; c < 3; c++) {
        /* sampled after movement steps c P + 1 .. (c + 1) P, falling since step 0 */
        double t0 = (double)(r.relax_steps + c * P + 1) * dt, t1 = (double)(r.relax_steps + (c + 1) * P) * dt;
        double want = 0.5 * g * (t1 * t1 - t0 * t0);
        CHECK(gait.airborne[c] == 1.0, "cycle %d airborne %g", c, gait.airborne[c]);
        NEAR(gait.lift[c], want, 2e-3 * want);
        NEAR(am_gait_travel(&gait, AM_FIT_HORIZONTAL, c), 0, 1e-9);
        NEAR(am_gait_travel(&gait, AM_FIT_3D, c), gait.com[c][2] - gait.com[c + 1][2], 1e-12);
    }
    /* the centres of mass bracket the movement: the first is where it began, the last where it ended */
    NEAR(gait.com[3][2] - gait.com[0][2], r.dz, 1e-12);
    am_gait_summary gs;
    am_gait_summarize(&gait, AM_FIT_HORIZONTAL, 0.01, &gs);
    CHECK(gs.mode == AM_GAIT_STILL && gs.airborne == 1.0, "falling straight down: %s, airborne %g", am_gait_mode_name(gs.mode), gs.airborne);
}

/* a gait with the given per-cycle travel along x (m) and airborne fraction */
static void synth_gait(am_gait* g, const double* travel, int n, double air)
{
    memset(g, 0, sizeof *g);
    g->cycles = n;
    for (int k = 0; k < n; k++) {
        g->com[k + 1][0] = g->com[k][0] + travel[k];
        g->com[k + 1][1] = 0.5; /* constant y: no part of the travel */
        g->com[k][1] = 0.5;
        g->airborne[k] = air;
    }
}

/* the numbers that tell a flop from a scoot from a bounce, on gaits made to be each */
static void test_gait_modes(void)
{
    static am_gait g;
    am_gait_summary s;
    const double flop[10] = {0.02, 0.01, 0.004, 0.001, 0.0005, 0.0002, 0.0001, 0.0001, 0.0001, 0.0001};
    const double scoot[10] = {0.002, 0.003, 0.002, 0.003, 0.002, 0.003, 0.002, 0.003, 0.002, 0.003};
    const double still[10] = {1e-5, 2e-5, 1e-5, 2e-5, 1e-5, 2e-5, 1e-5, 2e-5, 1e-5, 2e-5};
    synth_gait(&g, flop, 10, 0.0);
    am_gait_summarize(&g, AM_FIT_HORIZONTAL, 0.01, &s);
    NEAR(s.first_half, (0.02 + 0.01 + 0.004 + 0.001 + 0.0005) / 5, 1e-15);
    NEAR(s.last_half, (0.0002 + 4 * 0.0001) / 5, 1e-15);
    CHECK(s.mode == AM_GAIT_FLOP && s.sustained < AM_GAIT_FLOP_RATIO, "flop: %s, sustained %g", am_gait_mode_name(s.mode), s.sustained);
    synth_gait(&g, scoot, 10, 0.05);
    am_gait_summarize(&g, AM_FIT_HORIZONTAL, 0.01, &s);
    NEAR(s.sustained, 0.0026 / 0.0024, 1e-12);
    NEAR(s.travel_total, 0.025, 1e-15);
    CHECK(s.mode == AM_GAIT_SCOOT, "scoot: %s", am_gait_mode_name(s.mode));
    synth_gait(&g, scoot, 10, 0.5);
    am_gait_summarize(&g, AM_FIT_HORIZONTAL, 0.01, &s);
    CHECK(s.mode == AM_GAIT_BOUNCE && s.airborne == 0.5, "bounce: %s", am_gait_mode_name(s.mode));
    synth_gait(&g, still, 10, 0.0);
    am_gait_summarize(&g, AM_FIT_HORIZONTAL, 0.01, &s);
    CHECK(s.mode == AM_GAIT_STILL, "still: %s", am_gait_mode_name(s.mode));
    /* odd cycle counts leave the middle cycle out of both halves; +x counts backward travel negative */
    synth_gait(&g, scoot, 9, 0.0);
    am_gait_summarize(&g, AM_FIT_HORIZONTAL, 0.01, &s);
    NEAR(s.first_half, 0.01 / 4, 1e-15);
    NEAR(s.last_half, 0.01 / 4, 1e-15);
    const double back[2] = {-0.003, -0.003};
    synth_gait(&g, back, 2, 0.0);
    NEAR(am_gait_travel(&g, AM_FIT_PLUS_X, 0), -0.003, 1e-15);
    NEAR(am_gait_travel(&g, AM_FIT_HORIZONTAL, 0), 0.003, 1e-15);

    /* rolling: a wheel of centre height 0.04 m going +x turns about +y by its travel / 0.04 a cycle;
     * a scooter that turns so, on the floor, is a roller */
    const double wheel[10] = {0.01, 0.01, 0.01, 0.01, 0.01, 0.01, 0.01, 0.01, 0.01, 0.01};
    synth_gait(&g, wheel, 10, 0.0);
    for (int k = 0; k <= 10; k++) g.com[k][2] = 0.04;
    for (int k = 0; k < 10; k++) g.turn[k][1] = 0.01 / 0.04;
    am_gait_summarize(&g, AM_FIT_HORIZONTAL, 0.01, &s);
    NEAR(s.roll, 1.0, 1e-12);
    NEAR(s.rotation, 0.25 * 180.0 / 3.14159265358979323846, 1e-9);
    NEAR(s.roll_turn, 5 * 0.25 * 180.0 / 3.14159265358979323846, 1e-9);
    CHECK(s.mode == AM_GAIT_ROLL, "wheel: %s, roll %g", am_gait_mode_name(s.mode), s.roll);
    /* turning the other way (about -y) while going +x is no rolling */
    for (int k = 0; k < 10; k++) g.turn[k][1] = -0.01 / 0.04;
    am_gait_summarize(&g, AM_FIT_HORIZONTAL, 0.01, &s);
    CHECK(s.roll < -0.99 && s.mode == AM_GAIT_SCOOT, "backwards turn: %s, roll %g", am_gait_mode_name(s.mode), s.roll);
    /* rocking (+ and - in turn) nets nothing; turning about the vertical (spinning) carries nothing */
    for (int k = 0; k < 10; k++) g.turn[k][1] = k % 2 ? 0.25 : -0.25;
    am_gait_summarize(&g, AM_FIT_HORIZONTAL, 0.01, &s);
    CHECK(fabs(s.roll) < 0.21 && s.mode == AM_GAIT_SCOOT, "rocking: %s, roll %g", am_gait_mode_name(s.mode), s.roll);
    for (int k = 0; k < 10; k++) g.turn[k][1] = 0, g.turn[k][2] = 0.25;
    am_gait_summarize(&g, AM_FIT_HORIZONTAL, 0.01, &s);
    CHECK(s.roll == 0 && s.rotation > 14 && s.mode == AM_GAIT_SCOOT, "spinning: %s, roll %g", am_gait_mode_name(s.mode), s.roll);
    /* a tip into a pose in the first cycles, then walking: the last half does not turn */
    for (int k = 0; k < 10; k++) g.turn[k][2] = 0, g.turn[k][1] = k < 5 ? 0.25 : 0;
    am_gait_summarize(&g, AM_FIT_HORIZONTAL, 0.01, &s);
    CHECK(s.roll == 0 && s.mode == AM_GAIT_SCOOT, "a tip, then walking: %s, roll %g", am_gait_mode_name(s.mode), s.roll);
    /* a slow walker that tilts as much as its short travel: too little turn to be a roller */
    const double slow[10] = {1e-4, 1e-4, 1e-4, 1e-4, 1e-4, 1e-4, 1e-4, 1e-4, 1e-4, 1e-4};
    synth_gait(&g, slow, 10, 0.0);
    for (int k = 0; k <= 10; k++) g.com[k][2] = 0.04;
    for (int k = 0; k < 10; k++) g.turn[k][1] = 1e-4 / 0.04;
    am_gait_summarize(&g, AM_FIT_HORIZONTAL, 0.001, &s);
    CHECK(s.roll > 0.99 && s.roll_turn < AM_GAIT_ROLL_MIN_DEG && s.mode == AM_GAIT_SCOOT, "slow tilt: %s, roll %g, turn %g",
          am_gait_mode_name(s.mode), s.roll, s.roll_turn);
}

/* a body on the floor: the gait's ends are the result's displacement, and the per-cycle travels
 * add up to at least the fitness (a path is never shorter than its chord) */
static void test_gait_on_the_floor(void)
{
    static am_gait gait;
    build("sphere:6");
    am_eval_def def = am_default_eval();
    def.cycles = 4;
    def.gait = &gait;
    am_result r, r2;
    am_evaluate(&g_m, &g_s, &def, &r);
    CHECK(gait.cycles == 4, "cycles %d", gait.cycles);
    NEAR(gait.com[4][0] - gait.com[0][0], r.dx, 1e-12);
    NEAR(gait.com[4][1] - gait.com[0][1], r.dy, 1e-12);
    am_gait_summary s;
    am_gait_summarize(&gait, def.fitness, 0.01, &s);
    CHECK(s.travel_total >= r.fitness - 1e-12, "travel %g < fitness %g", s.travel_total, r.fitness);
    CHECK(s.airborne >= 0 && s.airborne <= 1 && s.lift > 0, "airborne %g lift %g", s.airborne, s.lift);
    /* watching changes nothing */
    def.gait = NULL;
    am_evaluate(&g_m, &g_s, &def, &r2);
    CHECK(r2.hash == r.hash && r2.fitness == r.fitness, "the gait changed the evaluation");
}

/* the sustained score: the travel from the end of cycle sustained_from to the end, per cycle after
 * it, measured as the fitness is; the fitness with score = sustained, the same run either way */
static void test_sustained_score(void)
{
    static am_gait gait;
    build("sphere:6");
    am_eval_def def = am_default_eval();
    def.cycles = 13;
    def.sustained_from = 10;
    def.gait = &gait;
    am_result r, r2;
    am_evaluate(&g_m, &g_s, &def, &r);
    CHECK(r.settled && !r.diverged && r.fitness == r.travel, "travel score: fitness %g travel %g", r.fitness, r.travel);
    const double dx = gait.com[13][0] - gait.com[10][0], dy = gait.com[13][1] - gait.com[10][1];
    NEAR(r.sustained, sqrt(dx * dx + dy * dy) / 3, 1e-15);
    CHECK(r.sustained > 0 && r.sustained != r.travel / 13, "sustained %g", r.sustained);
    def.score = AM_SCORE_SUSTAINED;
    am_evaluate(&g_m, &g_s, &def, &r2);
    CHECK(r2.fitness == r.sustained && r2.hash == r.hash && r2.travel == r.travel, "sustained score: fitness %g, want %g",
          r2.fitness, r.sustained);
    /* from cycle 0: the whole movement's travel per cycle; with no cycle after the window, 0 */
    def.sustained_from = 0;
    am_evaluate(&g_m, &g_s, &def, &r2);
    NEAR(r2.sustained, r.travel / 13, 1e-15);
    def.sustained_from = 13;
    am_evaluate(&g_m, &g_s, &def, &r2);
    CHECK(r2.sustained == 0 && r2.fitness == 0, "no window: sustained %g fitness %g", r2.sustained, r2.fitness);
    /* x fitness: signed */
    def.sustained_from = 10;
    def.fitness = AM_FIT_PLUS_X;
    am_evaluate(&g_m, &g_s, &def, &r2);
    NEAR(r2.sustained, dx / 3, 1e-15);
}

/* the budget of one evaluation (issue 46): the seed's and a convergence study's evaluations are
 * well inside it; a request over it takes no step, whatever makes it long */
static void test_budget(void)
{
    am_env env = am_default_env();
    am_eval_def def = am_default_eval();
    am_eval_cost c;
    char err[AM_ERR_MAX];
    /* the seed's: two relaxations of 40,000 and 10 cycles of 500 */
    NEAR(am_eval_max_steps(&env, &def, 500, &c), 85000, 0.5);
    CHECK(c.relaxations == 2 && c.move == 5000, "relaxations %d move %g", c.relaxations, c.move);
    CHECK(am_eval_check(&env, &def, 500, err, sizeof err) == AM_OK, "%s", err);
    /* 30 cycles at 0.05 dt_rec with the period held (9,000 steps), settling at the run's step */
    env.dt_frac = AM_P(0.05);
    def.cycles = 30;
    def.relax_dt_frac = AM_P(0);
    const double fine = am_eval_max_steps(&env, &def, 9000, &c);
    CHECK(c.relaxations == 1 && fine < 1e6 && am_eval_check(&env, &def, 9000, err, sizeof err) == AM_OK, "%g: %s", fine, err);
    /* the search at its smallest step with the seed's relaxation: inside */
    env = am_default_env();
    def = am_default_eval();
    def.dt_search = 1;
    const double searched = am_eval_max_steps(&env, &def, 500, &c);
    CHECK(searched > 7e8 && searched < (double)AM_EVAL_MAX_STEPS, "the search's worst case %g", searched);
    /* over it: the cases */
    def = am_default_eval();
    def.cycles = 100000;
    CHECK(am_eval_check(&env, &def, 1e7, err, sizeof err) == AM_ERR_RANGE && strstr(err, "over the budget of 1e+09"), "%s", err);
    def = am_default_eval();
    env.dt_frac = AM_P(1e-6);
    def.relax_max_steps = 100000000;
    def.settle_speed = AM_P(0);
    CHECK(am_eval_check(&env, &def, 500, err, sizeof err) == AM_ERR_RANGE, "dt_frac 1e-6 and relax_max_steps 1e8 accepted");
    /* am_evaluate takes no step over it (this would run for ever) */
    build("cube:2");
    g_m.env.period_steps = 10000000;
    def = am_default_eval();
    def.cycles = 100000;
    am_result r;
    am_evaluate(&g_m, &g_s, &def, &r);
    CHECK(r.steps == 0 && r.diverged && r.fitness == AM_NO_SCORE, "steps %ld diverged %d fitness %g", r.steps, r.diverged, r.fitness);
}

/* a period in seconds is 2 to 10^7 steps, as the key period_steps (issue 46: 1e-9 s gave 1) */
static void test_period_range(void)
{
    char err[AM_ERR_MAX];
    am_env env = am_default_env();
    CHECK(am_scene_build(&g_lat, "cube:2", err, sizeof err) == AM_OK, "%s", err);
    env.period_s = AM_P(1e-9);
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_ERR_RANGE && strstr(err, "2 to 10^7 steps"), "%s", err);
    env.period_s = AM_P(0);
    env.period_steps = 1;
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_ERR_RANGE, "period_steps 1 accepted");
    env.period_steps = 500;
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_OK, "%s", err);
    env.period_s = AM_P(1e-9);
    CHECK(am_period_steps(&g_m, &env, g_m.dt_rec) == 2, "a searched step's period %d", am_period_steps(&g_m, &env, g_m.dt_rec));
    /* the period's one owner: the model keeps am_period_steps at its step, a state copies it, and
     * the rounding is am_period_steps_si's, a VXA file's period in seconds included */
    env.period_s = AM_P(0.05);
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_OK, "%s", err);
    am_state_reset(&g_m, &g_s);
    const int own = am_period_steps(&g_m, &env, g_s.dt);
    CHECK(g_m.env.period_steps == own && g_s.period_steps == own && own > 2, "model %d, state %d, owner %d", g_m.env.period_steps,
          g_s.period_steps, own);
    CHECK(own == am_period_steps_si(0.05, am_to_si(&g_m, g_s.dt, AM_DIM_TIME)), "owner %d", own);
    CHECK(am_period_steps_si(1.0, 0.4) == 3 && am_period_steps_si(1.0, 0.8) == 2 && am_period_steps_si(1.0, 1e-9) == 10000000 &&
              am_period_steps_si(NAN, 1.0) == 2 && am_period_steps_si(1.0, 0.0) == 10000000,
          "am_period_steps_si rounds to the nearest, 2 to 10^7");
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    RUN(test_recording);
    RUN(test_recording_sink);
    RUN(test_fitness_modes);
    RUN(test_unsettled_no_score);
    RUN(test_steps_in_seconds);
    RUN(test_dt_search);
    RUN(test_gait_free_fall);
    RUN(test_gait_modes);
    RUN(test_gait_on_the_floor);
    RUN(test_sustained_score);
    RUN(test_budget);
    RUN(test_period_range);
    return SUMMARY();
}
