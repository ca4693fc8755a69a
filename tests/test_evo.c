/* tests/test_evo.c: the evolver. Configuration parsing and printing, the deterministic
 * crowding rule, bit-identical runs for 1, 2 and 3 workers, checkpoints (round trip, resume
 * equals an uninterrupted run, damage detected), cancellation, and a pinned golden run hash. */
#include "harness.h"
#include "sink.h"

#include "amorph.h"
#include "port.h"

static am_evo g_a, g_b, g_c;
static am_evo_work g_work[3];
static char g_text[AM_EVO_CHECKPOINT_MAX(AM_MAX_POPULATION)];
static char g_text2[AM_EVO_CHECKPOINT_MAX(AM_MAX_POPULATION)];

/* Golden hash of the small reference run of small_def() after 4 generations (float desktop build).
 * Re-pin it deliberately when the simulator, the genotypes or the evolver change results. */
#define GOLDEN_SMALL_RUN UINT64_C(0xe88816345e62357e)
/* the same run in the fixed-point build (make REAL=fixed, docs/fixed.md) */
#define GOLDEN_SMALL_RUN_FIXED UINT64_C(0x02ac445dc8acf6aa)

/* a run small enough for a unit test: 8^3 workspace, population 6, short simulations */
static am_evo_def small_def(int repr)
{
    am_evo_def d = am_default_evo();
    char err[AM_ERR_MAX];
    am_evo_set(&d, "workspace", "8", err, sizeof err);
    d.geno.repr = repr;
    d.geno.gmx_points = 24;
    d.population = 6;
    d.evaluations = 24;
    d.eval.cycles = 2;
    d.env.period_steps = 100;
    d.eval.relax_max_steps = 400;
    d.eval.relax_min_steps = 50;
    d.eval.release_steps = 100; /* room to settle (am_evo_check_run) */
    d.seed = 7;
    return d;
}

/* the executor of `workers` workers on the port's parallel map (0: none, NULL, items in order on
 * this thread), with a clock that counts its calls */
static double g_clock;
static am_status port_map(void* self, int n, int workers, am_task_fn task, void* ctx, void* out, long size, char* err, int errsz)
{
    (void)self;
    return am_port_parallel_map(n, workers, task, ctx, out, size, err, errsz);
}
static double count_now(void* self)
{
    (void)self;
    return g_clock += 1.0;
}
static am_executor g_ex[AM_MAX_WORKERS + 1];
static const am_executor* on(int workers)
{
    if (workers == 0) return NULL;
    am_executor* x = &g_ex[workers];
    x->map = port_map;
    x->now = count_now;
    x->self = NULL;
    x->workers = workers;
    return x;
}

static int run_to_end(am_evo* e, int workers)
{
    char err[AM_ERR_MAX];
    while (!am_evo_done(e))
        if (am_evo_generation(e, g_work, on(workers), NULL, err, sizeof err) != AM_OK) {
            fprintf(stderr, "generation: %s\n", err);
            return 0;
        }
    return 1;
}

static void test_config_defaults_are_the_seed(void)
{
    am_evo_def d = am_default_evo();
    CHECK(d.geno.repr == AM_REPR_GMX, "representation %d", d.geno.repr);
    CHECK(d.geno.materials == 2, "materials %d", d.geno.materials);
    CHECK(d.geno.nx == AM_MAX_DIM && d.geno.ny == AM_MAX_DIM && d.geno.nz == AM_MAX_DIM, "workspace");
    CHECK(d.population == 20, "population %d", d.population);
    NEAR(d.cte, 0.01, 1e-9);
    NEAR(d.env.temp_amplitude, 30, 0);
    CHECK(d.env.period_steps == 500, "period %d", d.env.period_steps);
    NEAR(d.mu_kinetic, 0.3, 1e-7);
    NEAR(d.mu_static, 1.0, 0);
    CHECK(d.env.cte_mode == AM_CTE_VOLUMETRIC, "cte mode");
    am_palette p = am_evo_palette(&d);
    int act = am_palette_find(&p, "active"), pas = am_palette_find(&p, "passive");
    CHECK(act >= 0 && pas >= 0, "palette names");
    NEAR(p.mat[act].cte, 0.01, 1e-9);
    NEAR(p.mat[pas].cte, 0, 0);
    NEAR(p.mat[pas].mu_kinetic, 0.3, 1e-7);
    char err[AM_ERR_MAX];
    CHECK(am_evo_check(&d, err, sizeof err) == AM_OK, "%s", err);
}

static void test_config_set_and_errors(void)
{
    am_evo_def d = am_default_evo();
    char err[AM_ERR_MAX];
    CHECK(am_evo_set(&d, "workspace", "4x5x6", err, sizeof err) == AM_OK, "%s", err);
    CHECK(d.geno.nx == 4 && d.geno.ny == 5 && d.geno.nz == 6, "workspace %d %d %d", d.geno.nx, d.geno.ny, d.geno.nz);
    CHECK(am_evo_set(&d, "representation", "cppn", err, sizeof err) == AM_OK && d.geno.repr == AM_REPR_CPPN, "repr");
    CHECK(am_evo_set(&d, "mu_static", "5.0", err, sizeof err) == AM_OK, "%s", err);
    NEAR(d.mu_static, 5, 0);
    CHECK(am_evo_set(&d, "seed", "18446744073709551615", err, sizeof err) == AM_OK && d.seed == UINT64_MAX, "seed max");
    CHECK(am_evo_set(&d, "collisions", "off", err, sizeof err) == AM_OK && d.env.collisions == 0, "collisions");
    /* errors name the key and the problem */
    CHECK(am_evo_set(&d, "populaton", "20", err, sizeof err) == AM_ERR_ARG && strstr(err, "unknown key 'populaton'"), "%s", err);
    CHECK(am_evo_set(&d, "population", "20x", err, sizeof err) == AM_ERR_RANGE && strstr(err, "population"), "%s", err);
    CHECK(am_evo_set(&d, "population", "1", err, sizeof err) == AM_ERR_RANGE, "population 1: %s", err);
    CHECK(am_evo_set(&d, "workspace", "0", err, sizeof err) == AM_ERR_RANGE, "workspace 0: %s", err);
    CHECK(am_evo_set(&d, "workspace", "4x5", err, sizeof err) == AM_ERR_RANGE, "workspace 4x5: %s", err);
    CHECK(am_evo_set(&d, "workspace", "99", err, sizeof err) == AM_ERR_RANGE && strstr(err, "profile"), "%s", err);
    CHECK(am_evo_set(&d, "representation", "dna", err, sizeof err) == AM_ERR_RANGE && strstr(err, "dct, cppn or gmx"), "%s", err);
    CHECK(am_evo_set(&d, "cte", "nan", err, sizeof err) == AM_ERR_RANGE, "cte nan: %s", err);
    CHECK(am_evo_set(&d, "cte", " 0.1", err, sizeof err) == AM_ERR_RANGE, "leading space: %s", err);
    CHECK(am_evo_set(&d, "seed", "-1", err, sizeof err) == AM_ERR_RANGE, "seed -1: %s", err);
    CHECK(am_evo_set(&d, "collisions", "yes", err, sizeof err) == AM_ERR_RANGE, "collisions yes: %s", err);
    am_evo_def odd = am_default_evo();
    odd.population = 7;
    CHECK(am_evo_check(&odd, err, sizeof err) == AM_ERR_RANGE && strstr(err, "even"), "%s", err);
    am_evo_def few = am_default_evo();
    few.evaluations = 10;
    CHECK(am_evo_check(&few, err, sizeof err) == AM_ERR_RANGE && strstr(err, "evaluations"), "%s", err);
}

static void test_config_text_round_trip(void)
{
    am_evo_def d = small_def(AM_REPR_CPPN), e = am_default_evo();
    char err[AM_ERR_MAX], a[8192], b[8192];
    long la = 0, lb = 0;
    d.mu_kinetic = AM_P(0.1);
    d.env.cte_mode = AM_CTE_LINEAR;
    CHECK(am_evo_format(&d, 1, a, sizeof a, &la, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_evo_parse(&e, a, "cfg", err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_evo_format(&e, 1, b, sizeof b, &lb, err, sizeof err) == AM_OK, "%s", err);
    CHECK(la == lb && strcmp(a, b) == 0, "text differs after a round trip");
    char key[160];
    CHECK(am_evo_same_run(&d, &e, key, sizeof key), "same run: %s", key);
    e.evaluations = 999;
    e.threads = 3;
    CHECK(am_evo_same_run(&d, &e, key, sizeof key), "evaluations and threads never make another run: %s", key);
    e.population = 8;
    CHECK(!am_evo_same_run(&d, &e, key, sizeof key) && strstr(key, "population"), "%s", key);
    /* parse errors carry file:line */
    am_evo_def f = am_default_evo();
    CHECK(am_evo_parse(&f, "# c\npopulation = 10\nbogus = 1\n", "x.cfg", err, sizeof err) == AM_ERR_PARSE &&
              strstr(err, "x.cfg:3: unknown key 'bogus'"), "%s", err);
    CHECK(f.population == 10, "population read before the error");
    CHECK(am_evo_parse(&f, "population 10\n", "x.cfg", err, sizeof err) == AM_ERR_PARSE && strstr(err, "x.cfg:1: expected 'key = value'"),
          "%s", err);
    CHECK(am_evo_parse(&f, "\n\ncte =\n", "x.cfg", err, sizeof err) == AM_ERR_PARSE && strstr(err, "x.cfg:3: cte: missing value"), "%s", err);
    CHECK(am_evo_parse(&f, "amplitude = 1e9\n", "x.cfg", err, sizeof err) == AM_ERR_RANGE && strstr(err, "x.cfg:1: amplitude"), "%s", err);
}

/* the configuration's message for text (file "x.cfg"): exactly want, one line of printable ASCII */
static void expect_config_message(const char* text, const char* want)
{
    am_evo_def d = am_default_evo();
    char err[AM_ERR_MAX] = "";
    CHECK(am_evo_parse(&d, text, "x.cfg", err, sizeof err) != AM_OK && !strcmp(err, want), "message '%s', want '%s'", err, want);
    CHECK(printable_line(err), "'%s' is not one line of printable ASCII", err);
}

/* a bad key, value or line shows cut and escaped (am_quote) */
/* palettes (docs/evolve.md, Palettes): the seed's is the built-in one as before, the follow-up's
 * holds evosoro's values, materialK keys extend and replace, and the text reads back exactly */
static void test_config_palettes(void)
{
    char err[AM_ERR_MAX] = "";
    static am_palette p, q;
    /* the seed's palette: the built-in one with the run's cte and friction, whatever materials says */
    am_evo_def d = am_default_evo();
    d.cte = AM_P(0.02);
    am_evo_palette_into(&d, &p);
    am_default_palette_into(&q);
    CHECK(p.count == q.count && p.count == 9, "seed palette of %d materials", p.count);
    for (int i = 0; i < q.count; i++)
        CHECK(p.mat[i].E == q.mat[i].E && (q.mat[i].cte == AM_P(0) ? p.mat[i].cte == AM_P(0) : p.mat[i].cte == AM_P(0.02)) &&
                  !strcmp(p.mat[i].name, q.mat[i].name) && p.mat[i].mu_kinetic == AM_P(0.3),
              "seed palette: %s", q.mat[i].name);
    CHECK(am_evo_palette_size(&d) == 3, "seed palette size %d", am_evo_palette_size(&d));
    /* the follow-up's four: materials 4, evosoro's moduli and density, active_minus half a period behind */
    CHECK(am_evo_set(&d, "palette", "unshackled", err, sizeof err) == AM_OK, "%s", err);
    CHECK(d.geno.materials == 4 && !strcmp(d.geno.mat[3], "active_minus"), "unshackled: %d materials, '%s'", d.geno.materials,
          d.geno.mat[3]);
    am_evo_palette_into(&d, &p);
    CHECK(p.count == 4 && p.mat[0].E == AM_P(5e6) && p.mat[1].E == AM_P(5e8) && p.mat[2].E == AM_P(5e6) &&
              p.mat[0].density == AM_P(1e6) && p.mat[1].poisson == AM_P(0.35) && p.mat[0].cte == AM_P(0) &&
              p.mat[2].cte == AM_P(0.02) && p.mat[3].cte == AM_P(0.02) && p.mat[2].phase == AM_P(0) &&
              p.mat[3].phase == AM_P(3.14159265358979323846),
          "unshackled palette values");
    /* materialK: in place of a preset's entry and past its end, raising materials */
    CHECK(am_evo_set(&d, "material6", "muscle90 modulus=5e6 density=1e6 cte=0.01 phase=-90 mu_kinetic=0.5 color=ff8800", err,
                     sizeof err) == AM_OK, "%s", err);
    CHECK(am_evo_check(&d, err, sizeof err) == AM_ERR_RANGE && strstr(err, "material6: the palette has no material5"), "gap: %s", err);
    CHECK(am_evo_set(&d, "material5", "gel modulus=2e5 density=1e6 cte=0 phase=0 poisson=0.35", err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_evo_set(&d, "material1", "soft modulus=1e5 density=1000 cte=0 phase=0", err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_evo_check(&d, err, sizeof err) == AM_OK, "six materials: %s", err);
    CHECK(d.geno.materials == 6 && am_evo_palette_size(&d) == 6, "materials %d", d.geno.materials);
    am_evo_palette_into(&d, &p);
    CHECK(p.count == 6 && !strcmp(p.mat[0].name, "soft") && p.mat[0].E == AM_P(1e5) && !strcmp(p.mat[1].name, "passive_hard") &&
              p.mat[4].poisson == AM_P(0.35) && p.mat[4].mu_kinetic == AM_P(0.3) && p.mat[5].mu_kinetic == AM_P(0.5) &&
              p.mat[5].cte == AM_P(0.01) && p.mat[5].color[0] == 0xff && p.mat[5].color[1] == 0x88 &&
              p.mat[5].phase == AM_PARAM_FROM_DOUBLE(-90.0 * (3.14159265358979323846 / 180.0)),
          "six-material palette values");
    /* the text reads back to the same run and the same text */
    static char t1[8192], t2[8192];
    long n1 = 0, n2 = 0;
    CHECK(am_evo_format(&d, 1, t1, sizeof t1, &n1, err, sizeof err) == AM_OK, "%s", err);
    am_evo_def e = am_default_evo();
    CHECK(am_evo_parse(&e, t1, "c.txt", err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_evo_format(&e, 1, t2, sizeof t2, &n2, err, sizeof err) == AM_OK && !strcmp(t1, t2), "text differs:\n%s\n%s", t1, t2);
    char key[128] = "";
    CHECK(am_evo_same_run(&d, &e, key, sizeof key), "not the same run: %s", key);
    am_evo_palette_into(&e, &q);
    CHECK(p.count == q.count && !memcmp(&p.mat[5], &q.mat[5], sizeof p.mat[5]), "palette read back differs");
    /* a changed material is another run */
    CHECK(am_evo_set(&e, "material5", "gel modulus=3e5 density=1e6 cte=0 phase=0 poisson=0.35", err, sizeof err) == AM_OK, "%s", err);
    CHECK(!am_evo_same_run(&d, &e, key, sizeof key) && !strncmp(key, "material5", 9), "changed material5: '%s'", key);
    /* the seed's palette set explicitly writes no palette line: the default text */
    d = am_default_evo();
    e = am_default_evo();
    CHECK(am_evo_set(&e, "palette", "seed", err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_evo_format(&d, 1, t1, sizeof t1, &n1, err, sizeof err) == AM_OK && am_evo_format(&e, 1, t2, sizeof t2, &n2, err, sizeof err) == AM_OK &&
              !strcmp(t1, t2) && !strstr(t1, "palette") && !strstr(t1, "material1"),
          "palette = seed changed the text");
    /* refusals: the message names the problem */
    CHECK(am_evo_set(&d, "material1", "x modulus=0 density=1 cte=0 phase=0", err, sizeof err) == AM_ERR_RANGE && strstr(err, "modulus=0"),
          "modulus 0: %s", err);
    CHECK(am_evo_set(&d, "material1", "x modulus=1e6 density=1 cte=0 phase=0 poisson=0.5", err, sizeof err) == AM_ERR_RANGE,
          "poisson 0.5: %s", err);
    CHECK(am_evo_set(&d, "material1", "x modulus=1e6 density=1 cte=0", err, sizeof err) == AM_ERR_RANGE && strstr(err, "missing phase="),
          "missing phase: %s", err);
    CHECK(am_evo_set(&d, "material1", "x modulus=1e6 density=1 cte=0 phase=0 color=12345", err, sizeof err) == AM_ERR_RANGE,
          "short colour: %s", err);
    CHECK(am_evo_set(&d, "material1", "x modulus=1e6 modulus=2e6 density=1 cte=0 phase=0", err, sizeof err) == AM_ERR_RANGE &&
              strstr(err, "modulus given twice"), "twice: %s", err);
    char over[32];
    snprintf(over, sizeof over, "material%d", AM_MAX_GENO_MATERIALS + 1);
    CHECK(am_evo_set(&d, over, "x modulus=1e6 density=1 cte=0 phase=0", err, sizeof err) == AM_ERR_RANGE && strstr(err, "at most"),
          "over capacity: %s", err);
    CHECK(am_evo_set(&d, "material0", "x", err, sizeof err) == AM_ERR_ARG, "material0: %s", err);
}

static void test_config_bad_tokens_quoted(void)
{
    char t[512], want[AM_ERR_MAX], tok[301], err[AM_ERR_MAX];
    expect_config_message("\x1b[31mpopulation = 4\n",
                          "x.cfg:1: unknown key '\\x1b[31mpopulation' (amorph evolve --help-config lists them)");
    expect_config_message("seed = \x01x\n", "x.cfg:1: seed = '\\x01x': expected an integer in [0, 18446744073709551615]");
    expect_config_message("representation = d\x7fna\n", "x.cfg:1: representation = 'd\\x7fna': expected dct, cppn or gmx");
    expect_config_message("\x07" "bell's\n", "x.cfg:1: expected 'key = value', got '\\x07bell\\'s'");
    expect_config_message("\x1b =\n", "x.cfg:1: \\x1b: missing value after '='");
    /* the key-value call itself (command-line flags go through it) */
    am_evo_def d = am_default_evo();
    CHECK(am_evo_set(&d, "collisions", "\x1b[31m", err, sizeof err) == AM_ERR_RANGE &&
              !strcmp(err, "collisions = '\\x1b[31m': expected on or off"), "%s", err);
    /* 300-character tokens: their first 40 characters and "..." */
    memset(tok, 'k', 300);
    tok[300] = 0;
    snprintf(t, sizeof t, "%s = 1\n", tok);
    snprintf(want, sizeof want, "x.cfg:1: unknown key '%.40s...' (amorph evolve --help-config lists them)", tok);
    expect_config_message(t, want);
    snprintf(t, sizeof t, "# a comment\n%s\n", tok);
    snprintf(want, sizeof want, "x.cfg:2: expected 'key = value', got '%.40s...'", tok);
    expect_config_message(t, want);
    memset(tok, '7', 300);
    tok[1] = '\t';
    snprintf(t, sizeof t, "seed = %s\n", tok);
    snprintf(want, sizeof want, "x.cfg:1: seed = '7\\t%.38s...': expected an integer in [0, 18446744073709551615]", tok + 2);
    expect_config_message(t, want);
}

/* every slot after a generation holds its old member or one of the two offspring of its pair,
 * and an offspring only ever replaces a worse member */
static void test_crowding_rule(void)
{
    am_evo_def d = small_def(AM_REPR_GMX);
    char err[AM_ERR_MAX];
    CHECK(am_evo_init(&g_a, &d, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_evo_generation(&g_a, g_work, on(1), NULL, err, sizeof err) == AM_OK, "%s", err);
    CHECK(g_a.evaluations == 6 && g_a.generation == 1, "after generation 0: %ld evaluations", g_a.evaluations);
    int replaced_total = 0;
    for (int gen = 0; gen < 3; gen++) {
        am_evo_ind before[AM_MAX_POPULATION];
        for (int i = 0; i < d.population; i++) before[i] = g_a.pop[i];
        double best_before = g_a.last.best;
        CHECK(am_evo_generation(&g_a, g_work, on(2), NULL, err, sizeof err) == AM_OK, "%s", err);
        /* the offspring of the generation are all in child[] when one batch holds them (the
         * desktop); a board keeps the last pair only, so there a replaced member is checked
         * against what it became */
        const int whole = AM_EVO_BATCH >= d.population;
        for (int i = 0; i < d.population; i++) {
            int same = am_genome_equal(&g_a.pop[i].genome, &before[i].genome);
            int from_child = -1;
            for (int c = 0; c < (whole ? d.population : 0); c++)
                if (am_genome_equal(&g_a.pop[i].genome, &g_a.child[c].genome)) from_child = c;
            CHECK(same || from_child >= 0 || !whole, "slot %d holds neither its member nor an offspring", i);
            if (!same) {
                replaced_total++;
                const am_evo_ind* c = from_child >= 0 ? &g_a.child[from_child] : &g_a.pop[i];
                CHECK(!c->diverged, "a diverged offspring replaced a member");
                CHECK(before[i].diverged || c->fitness > before[i].fitness, "offspring %.9g replaced a member of %.9g", c->fitness,
                      before[i].fitness);
            }
        }
        CHECK(g_a.last.best >= best_before, "the best fitness fell from %.9g to %.9g", best_before, g_a.last.best);
    }
    CHECK(replaced_total > 0, "no offspring ever replaced a member in 3 generations");
    CHECK(g_a.has_best && g_a.best.fitness == g_a.last.best, "best ever %.9g vs population best %.9g", g_a.best.fitness, g_a.last.best);
}

/* a generation counts its unsettled evaluations (log.csv's unsettled), scores them -1 and leaves
 * them out of the population's mean and median, as diverged ones (docs/evolve.md) */
static void test_unsettled_generation(void)
{
    am_evo_def d = small_def(AM_REPR_GMX); /* 400 relaxation steps: room for the release window of 100, not for every body */
    char err[AM_ERR_MAX];
    CHECK(am_evo_init(&g_a, &d, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_evo_generation(&g_a, g_work, on(1), NULL, err, sizeof err) == AM_OK, "%s", err);
    int unsettled = 0, scored = 0;
    double sum = 0;
    for (int i = 0; i < d.population; i++) {
        const am_evo_ind* p = &g_a.pop[i];
        const int u = !p->diverged && !p->empty && !g_a.eval[i].sim.settled;
        unsettled += u;
        if (u) CHECK(p->fitness == -1.0, "member %d did not settle yet scored %g", i, p->fitness);
        if (!p->diverged && p->fitness >= 0) sum += p->fitness, scored++;
    }
    CHECK(unsettled > 0 && scored > 0, "generation 0 should hold both kinds: %d unsettled, %d scored", unsettled, scored);
    CHECK(g_a.last.unsettled == unsettled, "the generation counted %d unsettled, its members show %d", g_a.last.unsettled, unsettled);
    if (scored) NEAR(g_a.last.mean, sum / scored, 1e-12);
    /* a relaxation too short for the release window is refused before anything runs */
    d.eval.relax_max_steps = 120;
    CHECK(am_evo_init(&g_a, &d, err, sizeof err) == AM_ERR_RANGE && strstr(err, "relax_max_steps = 120 leaves no room to settle"), "%s",
          err);
}

static void test_workers_give_identical_runs(void)
{
    am_evo_def d = small_def(AM_REPR_GMX);
    char err[AM_ERR_MAX];
    uint64_t h[3];
    am_evo* runs[3] = {&g_a, &g_b, &g_c};
    for (int w = 1; w <= 3; w++) {
        CHECK(am_evo_init(runs[w - 1], &d, err, sizeof err) == AM_OK, "%s", err);
        CHECK(run_to_end(runs[w - 1], w), "run with %d workers", w);
        h[w - 1] = am_evo_hash(runs[w - 1]);
    }
    CHECK(h[0] == h[1] && h[1] == h[2], "run hashes for 1, 2, 3 workers: %016llx %016llx %016llx", (unsigned long long)h[0],
          (unsigned long long)h[1], (unsigned long long)h[2]);
    /* no executor: every evaluation in order on this thread, no clock (wall_s 0); the executor's
     * clock: one call at the generation's start and one at its end */
    CHECK(g_c.last.wall_s == 1.0, "wall_s from the executor's clock: %g", g_c.last.wall_s);
    CHECK(am_evo_init(&g_b, &d, err, sizeof err) == AM_OK && run_to_end(&g_b, 0), "run without an executor");
    CHECK(am_evo_hash(&g_b) == h[0], "no executor: %016llx, 1 worker: %016llx", (unsigned long long)am_evo_hash(&g_b),
          (unsigned long long)h[0]);
    CHECK(g_b.last.wall_s == 0.0, "wall_s without a clock: %g", g_b.last.wall_s);
    CHECK(g_a.evaluations == 24 && g_a.generation == 4, "%ld evaluations in %ld generations", g_a.evaluations, g_a.generation);
#if defined(AM_REAL_FIXED_POINT)
    if (AM_MAX_DIM == 20)
        CHECK(h[0] == GOLDEN_SMALL_RUN_FIXED, "golden fixed-point run hash: got %016llx, pinned %016llx", (unsigned long long)h[0],
              (unsigned long long)GOLDEN_SMALL_RUN_FIXED);
#else
    if (GOLDEN_SMALL_RUN != 0 && sizeof(am_real) == sizeof(float) && AM_MAX_DIM == 20)
        CHECK(h[0] == GOLDEN_SMALL_RUN, "golden run hash: got %016llx, pinned %016llx", (unsigned long long)h[0],
              (unsigned long long)GOLDEN_SMALL_RUN);
#endif
    else printf("  (golden run hash %016llx)\n", (unsigned long long)h[0]);
    /* a different seed gives a different run */
    d.seed = 8;
    CHECK(am_evo_init(&g_c, &d, err, sizeof err) == AM_OK && run_to_end(&g_c, 1), "seed 8");
    CHECK(am_evo_hash(&g_c) != h[0], "seeds 7 and 8 gave the same run");
}

static void test_checkpoint_resume_equals_uninterrupted(void)
{
    const int reprs[3] = {AM_REPR_DCT, AM_REPR_CPPN, AM_REPR_GMX};
    for (int r = test_quick() ? 2 : 0; r < 3; r++) {
        am_evo_def d = small_def(reprs[r]);
        char err[AM_ERR_MAX];
        long la = 0, lb = 0;
        CHECK(am_evo_init(&g_a, &d, err, sizeof err) == AM_OK && run_to_end(&g_a, 2), "uninterrupted %s", am_repr_name(reprs[r]));
        CHECK(am_evo_init(&g_b, &d, err, sizeof err) == AM_OK, "%s", err);
        CHECK(am_evo_generation(&g_b, g_work, on(1), NULL, err, sizeof err) == AM_OK, "%s", err);
        CHECK(am_evo_generation(&g_b, g_work, on(1), NULL, err, sizeof err) == AM_OK, "%s", err);
        CHECK(am_evo_checkpoint_format(&g_b, g_text, sizeof g_text, &la, err, sizeof err) == AM_OK, "%s", err);
        /* through a 64-byte stream: the same text, checksum included */
        char piece[64];
        t_sink sink = {g_text2, sizeof g_text2, 0};
        am_text out = {piece, sizeof piece, 0, 0, t_sink_flush, &sink, 0};
        CHECK(am_evo_checkpoint_write(&g_b, &out, err, sizeof err) == AM_OK && am_text_flush(&out) == AM_OK && sink.n == la &&
                  memcmp(g_text, g_text2, (size_t)la) == 0, "%s: the streamed checkpoint differs", am_repr_name(reprs[r]));
        memcpy(g_text2, g_text, (size_t)la + 1);
        CHECK(am_evo_checkpoint_parse(&g_c, g_text2, "ck", err, sizeof err) == AM_OK, "%s: %s", am_repr_name(reprs[r]), err);
        CHECK(am_evo_checkpoint_format(&g_c, g_text2, sizeof g_text2, &lb, err, sizeof err) == AM_OK, "%s", err);
        CHECK(la == lb && memcmp(g_text, g_text2, (size_t)la) == 0, "%s: checkpoint text changes after a round trip",
              am_repr_name(reprs[r]));
        CHECK(am_evo_hash(&g_c) == am_evo_hash(&g_b), "hash of the restored run");
        CHECK(run_to_end(&g_c, 3), "resumed run");
        CHECK(am_evo_hash(&g_c) == am_evo_hash(&g_a), "%s: resumed %016llx vs uninterrupted %016llx", am_repr_name(reprs[r]),
              (unsigned long long)am_evo_hash(&g_c), (unsigned long long)am_evo_hash(&g_a));
        CHECK(am_genome_equal(&g_c.best.genome, &g_a.best.genome) && g_c.best.fitness == g_a.best.fitness, "same best genome");
    }
}

static void test_checkpoint_damage_is_refused(void)
{
    am_evo_def d = small_def(AM_REPR_GMX);
    char err[AM_ERR_MAX];
    long len = 0;
    CHECK(am_evo_init(&g_a, &d, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_evo_generation(&g_a, g_work, on(1), NULL, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_evo_checkpoint_format(&g_a, g_text, sizeof g_text, &len, err, sizeof err) == AM_OK, "%s", err);
    /* one changed digit anywhere */
    memcpy(g_text2, g_text, (size_t)len + 1);
    char* p = strstr(g_text2, "generation 1");
    CHECK(p != NULL, "generation line");
    if (p) p[11] = '2';
    CHECK(am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_ERR_PARSE && strstr(err, "ck.txt:") &&
              strstr(err, "checksum mismatch"), "%s", err);
    /* truncated */
    memcpy(g_text2, g_text, (size_t)len + 1);
    g_text2[len / 2] = 0;
    CHECK(am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_ERR_PARSE && strstr(err, "missing checksum"), "%s", err);
    /* empty, and not a checkpoint */
    g_text2[0] = 0;
    CHECK(am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_ERR_PARSE && strstr(err, "ck.txt:1: empty"), "%s", err);
    /* too small a buffer is a capacity error, not an overflow */
    CHECK(am_evo_checkpoint_format(&g_a, g_text2, 100, &len, err, sizeof err) == AM_ERR_CAPACITY, "capacity: %s", err);
}

/* text with its last line (the checksum) replaced by one that matches the new text */
static void reseal(char* text)
{
    size_t n = strlen(text);
    if (n < 2) return;
    size_t k = n - 1;
    while (k > 0 && text[k - 1] != '\n') k--;
    text[k] = 0;
    uint64_t h = am_hash_bytes(AM_HASH_INIT, text, (unsigned long)k);
    snprintf(text + k, 64, "checksum %016llx\n", (unsigned long long)h);
}

/* in g_text2 (a copy of src), the first occurrence of `from` replaced by `to`, sealed again */
static int edit_checkpoint(const char* src, const char* from, const char* to)
{
    char* p = strstr(src, from);
    if (!p) return 0;
    size_t head = (size_t)(p - src), nf = strlen(from), nt = strlen(to);
    memcpy(g_text2, src, head);
    memcpy(g_text2 + head, to, nt);
    strcpy(g_text2 + head + nt, p + nf);
    reseal(g_text2);
    return 1;
}

static void test_checkpoint_members_checked(void)
{
    am_evo_def d = small_def(AM_REPR_GMX);
    char err[AM_ERR_MAX], line[160];
    long len = 0;
    CHECK(am_evo_init(&g_a, &d, err, sizeof err) == AM_OK, "%s", err);
    CHECK(run_to_end(&g_a, 1), "run");
    CHECK(am_evo_checkpoint_format(&g_a, g_text, sizeof g_text, &len, err, sizeof err) == AM_OK, "%s", err);
    /* resealed unchanged: read back */
    CHECK(edit_checkpoint(g_text, "history", "history") && am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_OK,
          "%s", err);
    CHECK(am_evo_hash(&g_b) == am_evo_hash(&g_a) && g_b.pop[3].id == g_a.pop[3].id && g_b.best.id == g_a.best.id && g_a.best.id >= 0,
          "ids did not read back");
    /* member 1 given twice (in place of member 0): refused with its line */
    CHECK(edit_checkpoint(g_text, "individual pop 0 ", "individual pop 1 ") &&
              am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_ERR_PARSE && strstr(err, "ck.txt:") &&
              strstr(err, "individual pop 1 given twice"),
          "%s", err);
    /* a member beyond the population: a malformed index */
    CHECK(edit_checkpoint(g_text, "individual pop 2 ", "individual pop 9 ") &&
              am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_ERR_PARSE && strstr(err, "beyond the population"),
          "%s", err);
    /* a non-finite fitness (the bit pattern of +inf, then of a NaN) */
    snprintf(line, sizeof line, "individual pop 4 %016llx ", 0x7ff0000000000000ULL);
    {
        char from[40];
        char* p = strstr(g_text, "individual pop 4 ");
        CHECK(p != NULL, "member 4");
        if (p) {
            memcpy(from, p, 33);
            from[33] = 0;
            CHECK(edit_checkpoint(g_text, from, line) && am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_ERR_PARSE &&
                      strstr(err, "not a finite number"),
                  "%s", err);
            snprintf(line, sizeof line, "individual pop 4 %016llx ", 0x7ff8000000000001ULL);
            CHECK(edit_checkpoint(g_text, from, line) && am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_ERR_PARSE &&
                      strstr(err, "not a finite number"),
                  "%s", err);
        }
    }
    /* CRLF line ends read as the same checkpoint (the checksum is over the LF text) */
    for (int pass = 0; pass < 2; pass++) {
        size_t o = 0;
        for (const char* p = g_text; *p; p++) {
            if (*p == '\n') g_text2[o++] = '\r';
            g_text2[o++] = *p;
        }
        g_text2[o] = 0;
        if (pass == 0) {
            CHECK(am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_OK && am_evo_hash(&g_b) == am_evo_hash(&g_a),
                  "CRLF: %s", err);
            continue; /* the parse used the text as scratch: made again */
        }
        /* and streamed in pieces that split a CR from its LF */
        am_evo_ckpt_scan sc;
        am_evo_checkpoint_scan_begin(&sc);
        for (size_t k = 0; k < o; k += 7) am_evo_checkpoint_scan(&sc, g_text2 + k, (long)(o - k < 7 ? o - k : 7));
        CHECK(am_evo_checkpoint_scan_end(&sc, "ck.txt", err, sizeof err) == AM_OK, "CRLF in pieces: %s", err);
    }
    /* version 1 (individuals without ids, no remembered bodies) still reads, the ids unknown and
     * the table empty; version 4 does not */
    {
        static char v1[AM_EVO_CHECKPOINT_MAX(AM_MAX_POPULATION)];
        size_t o = 0;
        for (const char* p = g_text; *p;) {
            const char* nl = strchr(p, '\n');
            size_t n = nl ? (size_t)(nl - p) : strlen(p);
            size_t keep = n;
            if (!strncmp(p, "individual ", 11))
                while (keep > 0 && p[keep - 1] != ' ') keep--; /* drop the last token (the id) and its space */
            if (keep < n && keep > 0) keep--;
            if (!strncmp(p, "reused ", 7) || !strncmp(p, "memo ", 5) || !strncmp(p, "m ", 2)) { /* not in version 1 */
                p = nl ? nl + 1 : p + n;
                if (!nl) break;
                continue;
            }
            memcpy(v1 + o, p, keep);
            o += keep;
            if (!nl) break;
            v1[o++] = '\n';
            p = nl + 1;
        }
        v1[o] = 0;
        memcpy(g_text, v1, o + 1);
    }
    CHECK(edit_checkpoint(g_text, "amorph-checkpoint 3", "amorph-checkpoint 1") &&
              am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_OK,
          "version 1: %s", err);
    CHECK(am_evo_hash(&g_b) == am_evo_hash(&g_a) && g_b.pop[0].id == -1 && g_b.best.id == -1, "version 1 read differently");
    int kept = 0;
    for (int k = 0; k < AM_EVO_MEMO; k++) kept += g_b.memo[k].key != 0;
    CHECK(kept == 0 && g_b.reused == 0 && g_b.reused_voxel_steps == 0, "version 1: %d remembered bodies, %ld reused", kept, g_b.reused);
    CHECK(edit_checkpoint(g_text, "amorph-checkpoint 3", "amorph-checkpoint 4") &&
              am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_ERR_PARSE && strstr(err, "ck.txt:1:") &&
              strstr(err, "versions 1 to 3"),
          "version 4: %s", err);
}

/* the checkpoint's message for text (sealed with a matching checksum first): exactly want, one
 * line of printable ASCII */
static void expect_checkpoint_message(const char* text, const char* want)
{
    char err[AM_ERR_MAX] = "";
    snprintf(g_text2, sizeof g_text2, "%schecksum 0\n", text);
    reseal(g_text2);
    CHECK(am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_ERR_PARSE && !strcmp(err, want),
          "message '%s', want '%s'", err, want);
    CHECK(printable_line(err), "'%s' is not one line of printable ASCII", err);
}

/* a bad token in a checkpoint shows cut and escaped (am_quote) */
static void test_checkpoint_bad_tokens_quoted(void)
{
    static char t[1024];
    char want[AM_ERR_MAX], tok[301];
    const char* head = "amorph-checkpoint 2\nconfig-begin\nseed = 1\nconfig-end\n";
    expect_checkpoint_message("amorph-checkpoint \x1b[31m\n",
                              "ck.txt:1: checkpoint version '\\x1b[31m': this build reads versions 1 to 3");
    snprintf(t, sizeof t, "%s\x01rng\t1 2\n", head);
    expect_checkpoint_message(t, "ck.txt:5: unexpected line '\\x01rng\\t1'");
    /* the configuration inside goes through the configuration's reader */
    expect_checkpoint_message("amorph-checkpoint 2\nconfig-begin\nseed = \x7f\nconfig-end\n",
                              "ck.txt:3: seed = '\\x7f': expected an integer in [0, 18446744073709551615]");
    /* the generator's all-zero state (it would only ever give 0) is damage, not a state (issue 31) */
    expect_checkpoint_message("amorph-checkpoint 2\nconfig-begin\nseed = 1\nconfig-end\nrng 0000000000000000 0000000000000000 0000000000000000 0000000000000000\n",
                              "ck.txt:5: rng state all zero (a generator that would only ever give 0: damaged)");
    /* a relation between keys names the file and the line of the key (issue 31: neither) */
    {
        char msg[AM_ERR_MAX] = "", w[AM_ERR_MAX];
        snprintf(g_text2, sizeof g_text2, "amorph-checkpoint 2\nconfig-begin\nseed = 1\npopulation = 3\nconfig-end\nchecksum 0\n");
        reseal(g_text2);
        snprintf(w, sizeof w, "ck.txt:4: population = 3: must be even, in [2, %d]", AM_MAX_POPULATION);
        CHECK(am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", msg, sizeof msg) == AM_ERR_RANGE && !strcmp(msg, w), "message '%s', want '%s'",
              msg, w);
    }
    /* 300-character tokens: their first 40 characters and "..." */
    memset(tok, 'v', 300);
    tok[300] = 0;
    snprintf(t, sizeof t, "amorph-checkpoint %s\n", tok);
    snprintf(want, sizeof want, "ck.txt:1: checkpoint version '%.40s...': this build reads versions 1 to 3", tok);
    expect_checkpoint_message(t, want);
    snprintf(t, sizeof t, "%s%s 1\n", head, tok);
    snprintf(want, sizeof want, "ck.txt:5: unexpected line '%.40s...'", tok);
    expect_checkpoint_message(t, want);
}

/* evals.csv's view of a run: every evaluation once, in index order */
typedef struct seen_evals {
    long next;                /* the index expected next */
    int bad;                  /* 1 after a row out of order or with impossible parents */
    int placed;               /* placed rows */
    const am_evo* e;
} seen_evals;

static void on_eval(void* ctx, const am_evo_ind* ind, const am_evo_eval* ev)
{
    seen_evals* s = (seen_evals*)ctx;
    int mats = 0;
    for (int k = 0; k < s->e->def.geno.materials; k++) mats += ev->material_voxels[k];
    if (ind->id != s->next || ev->generation != s->e->generation || mats != ind->voxels ||
        (ev->generation == 0 && (ev->parent[0] != -1 || ev->parent[1] != -1 || !ev->placed)) ||
        (ev->generation > 0 && (ev->parent[0] < 0 || ev->parent[0] >= s->e->evaluations || ev->parent[1] < 0 ||
                                ev->parent[1] >= s->e->evaluations)))
        s->bad = 1;
    s->placed += ev->placed;
    s->next++;
}

static void test_evaluations_are_reported(void)
{
    am_evo_def d = small_def(AM_REPR_CPPN);
    char err[AM_ERR_MAX];
    CHECK(am_evo_init(&g_a, &d, err, sizeof err) == AM_OK, "%s", err);
    seen_evals s = {0, 0, 0, &g_a};
    const am_evo_hooks hooks = {NULL, on_eval, &s};
    while (!am_evo_done(&g_a)) {
        long ids[AM_MAX_POPULATION];
        for (int i = 0; i < d.population; i++) ids[i] = g_a.pop[i].id;
        const long placed_before = s.placed, evals_before = g_a.evaluations;
        CHECK(am_evo_generation(&g_a, g_work, on(2), &hooks, err, sizeof err) == AM_OK, "%s", err);
        /* the rows marked placed are exactly the members that are new: each pair of offspring meets
         * its own two parents, so a placed offspring stays in the population to the generation's end */
        int fresh = 0;
        for (int i = 0; i < d.population; i++) {
            CHECK(g_a.pop[i].id >= 0 && g_a.pop[i].id < g_a.evaluations, "member %d id %ld", i, g_a.pop[i].id);
            if (g_a.pop[i].id != ids[i]) {
                fresh++;
                CHECK(g_a.pop[i].id >= evals_before, "member %d changed to an old id %ld", i, g_a.pop[i].id);
            }
        }
        CHECK(s.placed - placed_before == fresh, "%ld rows placed, %d members new", s.placed - placed_before, fresh);
    }
    CHECK(!s.bad && s.next == g_a.evaluations, "rows out of order or impossible: bad %d, %ld of %ld", s.bad, s.next, g_a.evaluations);
    /* the hooks never change a run */
    CHECK(am_evo_init(&g_b, &d, err, sizeof err) == AM_OK && run_to_end(&g_b, 1), "reference");
    CHECK(am_evo_hash(&g_a) == am_evo_hash(&g_b), "a run with hooks differs");
    /* the rows' text: a header with a column per material, and a row per evaluation */
    char hdr[AM_EVO_EVALS_ROW_MAX], row[AM_EVO_EVALS_ROW_MAX];
    int n = am_evo_evals_header(d.geno.materials, hdr, (int)sizeof hdr);
    CHECK(n == (int)strlen(hdr) && strstr(hdr, ",voxels_m1,voxels_m2,fitness,") && !strstr(hdr, "voxels_m3"), "%s", hdr);
    am_evo_eval ev;
    memset(&ev, 0, sizeof ev);
    ev.parent[0] = ev.parent[1] = -1;
    am_evo_ind div = g_a.pop[0];
    div.diverged = 1;
    div.fitness = -1;
    n = am_evo_evals_row(&d, &div, &ev, row, (int)sizeof row);
    CHECK(n == (int)strlen(row) && strstr(row, ",,,,") && !strstr(row, "nan"), "diverged row: %s", row);
    CHECK(am_evo_evals_row(&d, &g_a.pop[0], &ev, row, 12) == 11 && strlen(row) == 11, "a short buffer: %s", row);
}

static int cancel_now(void* ctx)
{
    (void)ctx;
    return 1;
}

static void test_cancel_leaves_the_run_unchanged(void)
{
    am_evo_def d = small_def(AM_REPR_GMX);
    char err[AM_ERR_MAX];
    CHECK(am_evo_init(&g_a, &d, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_evo_generation(&g_a, g_work, on(1), NULL, err, sizeof err) == AM_OK, "%s", err);
    uint64_t h = am_evo_hash(&g_a);
    am_rng r = g_a.rng;
    long gen = g_a.generation;
    const am_evo_hooks hooks = {cancel_now, NULL, NULL};
    CHECK(am_evo_generation(&g_a, g_work, on(2), &hooks, err, sizeof err) == AM_ERR_CANCELLED && strstr(err, "interrupted"), "%s", err);
    CHECK(am_evo_hash(&g_a) == h && g_a.generation == gen && memcmp(&r, &g_a.rng, sizeof r) == 0, "cancelled generation changed the run");
    /* and the run goes on as if nothing happened */
    CHECK(run_to_end(&g_a, 1), "after a cancel");
    CHECK(am_evo_init(&g_b, &d, err, sizeof err) == AM_OK && run_to_end(&g_b, 1), "reference");
    CHECK(am_evo_hash(&g_a) == am_evo_hash(&g_b), "a cancelled generation changed the rest of the run");
}

/* the step API: two runs stepped together, their items evaluated interleaved and last first (as a
 * wave's map hands them out, or another process evaluates them), equal the runs made one
 * generation at a time; a skipped result cancels the generation and leaves the run as it was */
static am_evo_result g_res[2][AM_EVO_BATCH];

static void test_steps_equal_generations(void)
{
    am_evo_def d1 = small_def(AM_REPR_GMX), d2 = small_def(AM_REPR_DCT);
    char err[AM_ERR_MAX];
    d2.seed = 11;
    CHECK(am_evo_init(&g_a, &d1, err, sizeof err) == AM_OK && run_to_end(&g_a, 1), "reference 1: %s", err);
    CHECK(am_evo_init(&g_b, &d2, err, sizeof err) == AM_OK && run_to_end(&g_b, 1), "reference 2: %s", err);
    const uint64_t h1 = am_evo_hash(&g_a), h2 = am_evo_hash(&g_b);
    am_evo* e[2] = {&g_a, &g_b};
    CHECK(am_evo_init(e[0], &d1, err, sizeof err) == AM_OK && am_evo_init(e[1], &d2, err, sizeof err) == AM_OK, "%s", err);
    int gens = 0, cancelled = 0;
    while (!am_evo_done(e[0]) || !am_evo_done(e[1])) {
        int live[2], m[2];
        for (int k = 0; k < 2; k++) {
            live[k] = !am_evo_done(e[k]);
            if (live[k]) am_evo_gen_begin(e[k], 0.0);
        }
        for (;;) {
            int total = 0;
            for (int k = 0; k < 2; k++) {
                m[k] = 0;
                if (live[k]) CHECK(am_evo_batch_begin(e[k], &g_work[0].geno, &m[k], err, sizeof err) == AM_OK, "batch: %s", err);
                total += m[k];
            }
            if (total == 0) break;
            /* largest first within a run; here the last item first, the runs interleaved, on three workspaces */
            for (int i = AM_EVO_BATCH - 1, w = 0; i >= 0; i--)
                for (int k = 0; k < 2; k++)
                    if (i < m[k]) am_evo_batch_eval(e[k], i, &g_work[w++ % 3], &g_res[k][i]);
            if (gens == 1 && !cancelled && m[0] > 0) {
                /* one item skipped in run 0's first batch: its generation is abandoned, run 1's is not */
                am_rng before = e[0]->gen_saved;
                uint64_t hb = am_evo_hash(e[0]);
                g_res[0][m[0] - 1].skipped = 1;
                CHECK(am_evo_batch_cancellable(e[0]), "the first batch is cancellable");
                CHECK(am_evo_batch_end(e[0], g_res[0], &g_work[0].geno, NULL, err, sizeof err) == AM_ERR_CANCELLED, "skipped: %s", err);
                CHECK(memcmp(&before, &e[0]->rng, sizeof before) == 0 && am_evo_hash(e[0]) == hb, "a cancel changed the run");
                live[0] = 0;
                m[0] = 0;
                cancelled = 1;
            }
            for (int k = 0; k < 2; k++)
                if (m[k] > 0) CHECK(am_evo_batch_end(e[k], g_res[k], &g_work[0].geno, NULL, err, sizeof err) == AM_OK, "%s", err);
        }
        for (int k = 0; k < 2; k++)
            if (live[k]) am_evo_gen_end(e[k], 0.0);
        CHECK(++gens < 20, "runaway");
        if (gens >= 20) return;
    }
    CHECK(cancelled == 1, "the cancel case did not run");
    CHECK(am_evo_hash(e[0]) == h1 && am_evo_hash(e[1]) == h2, "stepped runs %016llx %016llx, whole generations %016llx %016llx",
          (unsigned long long)am_evo_hash(e[0]), (unsigned long long)am_evo_hash(e[1]), (unsigned long long)h1, (unsigned long long)h2);
}

/* am_evo_generations: runs of different lengths in lockstep, their offspring in one map, each ends
 * as it does alone; a finished run is left alone while the other goes on */
static am_evo_wave g_wave;

static void test_generations_in_lockstep(void)
{
    am_evo_def d1 = small_def(AM_REPR_CPPN), d2 = small_def(AM_REPR_GMX);
    char err[AM_ERR_MAX];
    d2.evaluations = 36;
    CHECK(am_evo_init(&g_a, &d1, err, sizeof err) == AM_OK && run_to_end(&g_a, 1), "alone 1: %s", err);
    CHECK(am_evo_init(&g_b, &d2, err, sizeof err) == AM_OK && run_to_end(&g_b, 1), "alone 2: %s", err);
    const uint64_t h1 = am_evo_hash(&g_a), h2 = am_evo_hash(&g_b);
    am_evo* runs[2] = {&g_a, &g_b};
    CHECK(am_evo_init(&g_a, &d1, err, sizeof err) == AM_OK && am_evo_init(&g_b, &d2, err, sizeof err) == AM_OK, "%s", err);
    int gens = 0;
    while ((!am_evo_done(&g_a) || !am_evo_done(&g_b)) && gens < 20) {
        CHECK(am_evo_generations(runs, 2, &g_wave, g_work, on(3), NULL, err, sizeof err) == AM_OK, "%s", err);
        gens++;
    }
    CHECK(gens == 6 && g_a.generation == 4 && g_b.generation == 6, "%d calls, generations %ld and %ld (want 6, 4, 6)", gens,
          g_a.generation, g_b.generation);
    CHECK(am_evo_hash(&g_a) == h1 && am_evo_hash(&g_b) == h2, "in lockstep %016llx %016llx, alone %016llx %016llx",
          (unsigned long long)am_evo_hash(&g_a), (unsigned long long)am_evo_hash(&g_b), (unsigned long long)h1, (unsigned long long)h2);
    CHECK(am_evo_generations(runs, 2, NULL, g_work, on(1), NULL, err, sizeof err) == AM_ERR_ARG, "two runs without a wave accepted");
}

static void test_log_row(void)
{
    am_evo_stats s = {3, 80, 0.125, 0.0625, 0.05, 1, 2, 1.5, 4};
    char row[256];
    int n = am_evo_log_row(&s, row, sizeof row);
    CHECK(n > 0 && strcmp(row, "3,80,0.125,0.0625,0.05,1,2,1.500,4") == 0, "row '%s'", row);
    CHECK(strcmp(am_evo_log_header(), "generation,evaluations,best,mean,median,diverged,empty,wall_s,unsettled") == 0, "header");
}

/* ---- same body, same result (am_evo.memo) ---- */

/* a run whose bodies repeat often: CPPN in a 5^3 workspace */
static am_evo_def repeat_def(void)
{
    am_evo_def d = small_def(AM_REPR_CPPN);
    char err[AM_ERR_MAX];
    am_evo_set(&d, "workspace", "5", err, sizeof err);
    d.population = 20;
    d.evaluations = 200;
    d.seed = 3;
    return d;
}

/* what the rows of a run said, and the test's own count of bodies seen before: each body expressed
 * again here, set down to its lowest layer, and compared cell for cell with every earlier one */
#define SEEN_MAX 256
typedef struct reuse_watch {
    const am_evo* e;
    uint64_t rows;                      /* a hash of every row's measurements */
    double simulated;                   /* voxel-steps simulated (the generations' last_voxel_steps) */
    long bodies, repeats;
    uint8_t body[SEEN_MAX][5 * 5 * 5];
} reuse_watch;
static reuse_watch g_watch[2];
static am_geno_work g_geno;
static am_lattice g_lat;

static void on_reuse_eval(void* ctx, const am_evo_ind* ind, const am_evo_eval* ev)
{
    reuse_watch* w = (reuse_watch*)ctx;
    const am_result* r = &ev->sim;
    uint64_t h = am_hash_u64(w->rows, (uint64_t)ind->id);
    const double v[10] = {r->fitness, r->travel, r->dx, r->dy, r->dz, r->sustained, r->dt, r->relax_dt, r->residual_speed, r->sim_seconds};
    h = am_hash_bytes(h, v, sizeof v);
    const long n[12] = {r->voxels, r->links, r->period_steps, r->relax_steps, r->move_steps, r->steps, r->relax_retried, r->diverged,
                        r->settled, r->kinetic_resets, r->rebuilds, r->max_pairs};
    h = am_hash_bytes(h, n, sizeof n);
    h = am_hash_u64(h, r->hash);
    for (int m = 0; m < AM_MAX_GENO_MATERIALS; m++) h = am_hash_u64(h, (uint64_t)ev->material_voxels[m]);
    w->rows = h;
    char err[AM_ERR_MAX];
    if (ind->empty || am_evo_lattice(&w->e->def, &w->e->palette, &ind->genome, &g_geno, &g_lat, err, sizeof err) != AM_OK) return;
    const int cells = 125, layer = 25;
    uint8_t low[125];
    int from = 0;
    while (from < cells && !g_lat.cell[from]) from++;
    from -= from % layer;
    memset(low, 0, sizeof low);
    memcpy(low, g_lat.cell + from, (size_t)(cells - from));
    int seen = 0;
    for (long k = 0; k < w->bodies && !seen; k++) seen = !memcmp(w->body[k], low, sizeof low);
    if (seen) w->repeats++;
    else if (w->bodies < SEEN_MAX) memcpy(w->body[w->bodies++], low, sizeof low);
}

static int watched_run(am_evo* e, reuse_watch* w, int workers, int limit)
{
    char err[AM_ERR_MAX];
    am_evo_def d = repeat_def();
    if (am_evo_init(e, &d, err, sizeof err) != AM_OK) return 0;
    e->memo_limit = limit;
    memset(w, 0, sizeof *w);
    w->e = e;
    const am_evo_hooks hooks = {NULL, on_reuse_eval, w};
    while (!am_evo_done(e)) {
        if (am_evo_generation(e, g_work, on(workers), &hooks, err, sizeof err) != AM_OK) return 0;
        w->simulated += (double)e->last_voxel_steps;
    }
    return 1;
}

static void test_reuse_gives_the_same_run(void)
{
    /* with the table and without: the same rows and run, and every repeated body taken from it */
    CHECK(watched_run(&g_a, &g_watch[0], 2, 0), "run with reuse");
    CHECK(watched_run(&g_b, &g_watch[1], 2, -1), "run without");
    CHECK(am_evo_hash(&g_a) == am_evo_hash(&g_b) && g_watch[0].rows == g_watch[1].rows, "reuse changed the run");
    CHECK(g_b.reused == 0 && g_b.reused_voxel_steps == 0, "no reuse: %ld reused", g_b.reused);
    CHECK(g_watch[0].repeats >= 10 && g_a.reused == g_watch[0].repeats, "%ld reused, the rows repeat %ld bodies", g_a.reused,
          g_watch[0].repeats);
    /* the voxel-steps simulated with the table and those it saved add up to the run without it */
    CHECK(g_a.reused_voxel_steps > 0 && g_watch[0].simulated + g_a.reused_voxel_steps == g_watch[1].simulated,
          "simulated %.0f + reused %.0f voxel-steps, without the table %.0f", g_watch[0].simulated, g_a.reused_voxel_steps,
          g_watch[1].simulated);
    /* any number of workers: the same reuse */
    CHECK(watched_run(&g_c, &g_watch[1], 3, 0), "3 workers");
    CHECK(am_evo_hash(&g_c) == am_evo_hash(&g_a) && g_c.reused == g_a.reused && g_watch[1].rows == g_watch[0].rows,
          "3 workers: %ld reused against %ld", g_c.reused, g_a.reused);
    CHECK(watched_run(&g_c, &g_watch[1], 0, 0), "no executor");
    CHECK(am_evo_hash(&g_c) == am_evo_hash(&g_a) && g_c.reused == g_a.reused, "no executor: %ld reused against %ld", g_c.reused, g_a.reused);
    /* a table of 2 slots: bodies pushed out are simulated again, with the same results */
    CHECK(watched_run(&g_c, &g_watch[1], 2, 2), "2 slots");
    CHECK(am_evo_hash(&g_c) == am_evo_hash(&g_a) && g_watch[1].rows == g_watch[0].rows && g_c.reused < g_a.reused,
          "2 slots: %ld reused against %ld", g_c.reused, g_a.reused);
    int used = 0;
    for (int k = 0; k < AM_EVO_MEMO; k++) used += g_c.memo[k].key != 0;
    CHECK(used == 2, "2 slots: %d filled", used);
}

static void test_reuse_survives_a_checkpoint(void)
{
    char err[AM_ERR_MAX];
    long la = 0, lb = 0;
    am_evo_def d = repeat_def();
    CHECK(am_evo_init(&g_a, &d, err, sizeof err) == AM_OK && run_to_end(&g_a, 0), "uninterrupted");
    CHECK(am_evo_init(&g_b, &d, err, sizeof err) == AM_OK, "%s", err);
    for (int k = 0; k < 5; k++) CHECK(am_evo_generation(&g_b, g_work, NULL, NULL, err, sizeof err) == AM_OK, "%s", err);
    CHECK(g_b.reused > 0, "no reuse in the first half");
    CHECK(am_evo_checkpoint_format(&g_b, g_text, sizeof g_text, &la, err, sizeof err) == AM_OK, "%s", err);
    memcpy(g_text2, g_text, (size_t)la + 1);
    CHECK(am_evo_checkpoint_parse(&g_c, g_text2, "ck", err, sizeof err) == AM_OK, "%s", err);
    CHECK(g_c.reused == g_b.reused && g_c.reused_voxel_steps == g_b.reused_voxel_steps, "reused %ld, was %ld", g_c.reused, g_b.reused);
    int same = 1;
    for (int k = 0; k < AM_EVO_MEMO; k++) {
        const am_evo_memo *x = &g_b.memo[k], *y = &g_c.memo[k];
        same = same && x->key == y->key && (!x->key || (x->used == y->used && !memcmp(x->cells, y->cells, sizeof x->cells) &&
                                                        x->res.voxels == y->res.voxels && x->res.detail.sim.hash == y->res.detail.sim.hash &&
                                                        !memcmp(&x->res.detail.sim.fitness, &y->res.detail.sim.fitness, sizeof(double)) &&
                                                        x->res.detail.sim.relax_steps == y->res.detail.sim.relax_steps));
    }
    CHECK(same, "the table read back differs");
    /* a diverged body's result may hold NaN (its last speed): read back bit for bit */
    {
        int k = 0;
        while (k < AM_EVO_MEMO - 1 && !g_c.memo[k].key) k++;
        const double inf = HUGE_VAL;
        g_c.memo[k].res.detail.sim.residual_speed = inf - inf;
        g_c.memo[k].res.detail.sim.dx = -inf;
        CHECK(am_evo_checkpoint_format(&g_c, g_text2, sizeof g_text2, &lb, err, sizeof err) == AM_OK &&
                  am_evo_checkpoint_parse(&g_b, g_text2, "ck", err, sizeof err) == AM_OK && isnan(g_b.memo[k].res.detail.sim.residual_speed) &&
                  g_b.memo[k].res.detail.sim.dx == -inf,
              "NaN and infinity in a remembered result: %s", err);
        CHECK(am_evo_checkpoint_parse(&g_c, g_text, "ck", err, sizeof err) == AM_OK, "the checkpoint read again: %s", err);
    }
    CHECK(run_to_end(&g_c, 0), "resumed");
    CHECK(am_evo_hash(&g_c) == am_evo_hash(&g_a) && g_c.reused == g_a.reused, "resumed: %ld reused, uninterrupted %ld", g_c.reused,
          g_a.reused);
    CHECK(am_evo_checkpoint_format(&g_a, g_text, sizeof g_text, &la, err, sizeof err) == AM_OK &&
              am_evo_checkpoint_format(&g_c, g_text2, sizeof g_text2, &lb, err, sizeof err) == AM_OK && la == lb &&
              !memcmp(g_text, g_text2, (size_t)la),
          "the resumed run's last checkpoint differs from the uninterrupted run's");
    /* damage in a remembered body: refused in one line that names it */
    static char src[AM_EVO_CHECKPOINT_MAX(AM_MAX_POPULATION)];
    memcpy(src, g_text, (size_t)la + 1);
    char* memo = strstr(src, "\nmemo 0 ");
    CHECK(memo != NULL, "no remembered body 0 in the checkpoint");
    if (!memo) return;
    char line[128];
    const char* eol = strchr(memo + 1, '\n');
    snprintf(line, sizeof line, "%.*s", (int)(eol - memo - 1), memo + 1);
    char* last = strrchr(line, ' ');
    char bad[128];
    snprintf(bad, sizeof bad, "%.*s 999", (int)(last - line), line);
    CHECK(edit_checkpoint(src, line, bad) && am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_ERR_PARSE &&
              strstr(err, "ck.txt:") && strstr(err, "remembered body of 999 bytes"),
          "bytes: %s", err);
    snprintf(bad, sizeof bad, "memo %d%.100s", AM_EVO_MEMO, line + 6);
    CHECK(edit_checkpoint(src, line, bad) && am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_ERR_PARSE &&
              strstr(err, "malformed 'memo' line"),
          "slot: %s", err);
    /* its last base64 line (the cells) changed: the key no longer matches */
    const char* next = strstr(eol, "\nmemo ");
    const char* end = next ? next : strstr(eol, "\nchecksum");
    const char* lastm = end;
    while (lastm > eol && strncmp(lastm, "\nm ", 3)) lastm--;
    char mline[80], mbad[80];
    const char* mend = strchr(lastm + 1, '\n');
    snprintf(mline, sizeof mline, "%.*s", (int)(mend - lastm), lastm);
    snprintf(mbad, sizeof mbad, "%s", mline);
    mbad[3] = mbad[3] == 'A' ? 'B' : 'A';
    CHECK(edit_checkpoint(src, mline, mbad) && am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_ERR_PARSE &&
              strstr(err, "remembered body 0"),
          "cells: %s", err);
    /* a base64 line dropped: the entry ends early */
    CHECK(edit_checkpoint(src, mline, "") && am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_ERR_PARSE &&
              strstr(err, "remembered body 0 ends early"),
          "dropped: %s", err);
    /* a base64 line with no entry before it */
    CHECK(edit_checkpoint(src, "\nreused ", "\nm QUJD\nreused ") &&
              am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_ERR_PARSE && strstr(err, "outside a remembered body"),
          "stray m line: %s", err);
    CHECK(edit_checkpoint(src, "\nreused ", "\nreused -1 0 ") &&
              am_evo_checkpoint_parse(&g_b, g_text2, "ck.txt", err, sizeof err) == AM_ERR_PARSE && strstr(err, "malformed 'reused' line"),
          "reused: %s", err);
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    RUN(test_config_defaults_are_the_seed);
    RUN(test_config_set_and_errors);
    RUN(test_config_text_round_trip);
    RUN(test_config_palettes);
    RUN(test_config_bad_tokens_quoted);
    RUN(test_log_row);
    RUN(test_unsettled_generation);
    RUN(test_crowding_rule);
    RUN(test_workers_give_identical_runs);
    RUN(test_checkpoint_resume_equals_uninterrupted);
    RUN(test_checkpoint_damage_is_refused);
    RUN(test_cancel_leaves_the_run_unchanged);
    RUN(test_steps_equal_generations);
    RUN(test_generations_in_lockstep);
    RUN(test_checkpoint_members_checked);
    RUN(test_checkpoint_bad_tokens_quoted);
    RUN(test_evaluations_are_reported);
    RUN(test_reuse_gives_the_same_run);
    RUN(test_reuse_survives_a_checkpoint);
    return SUMMARY();
}
