/* tests/test_api.c: the embedding API (amorph/api.h). A genome and a lattice evaluated through it
 * give what the library's own calls give (am_evo_evaluate; am_model_build and am_evaluate) bit for
 * bit, on either of two workspaces; settings reach the evaluation; bad workspaces, keys and texts
 * are refused with one-line messages. */
#include "harness.h"

#include "amorph.h"

static am_api_work g_w[2];
static am_evo_work g_ref;
static am_evo_ind g_ind;
static am_lattice g_lat;
static char g_text[1 << 20];

/* a short evaluation: 8^3 workspace, two cycles of 100 steps */
static const char* const g_keys[][2] = {{"workspace", "8"}, {"cycles", "2"}, {"period_steps", "100"},
                                        {"relax_max_steps", "400"}, {"relax_min_steps", "50"}, {"release_steps", "100"}};
enum { NKEYS = (int)(sizeof g_keys / sizeof g_keys[0]) };

static am_evo_def small_def(void)
{
    am_evo_def d = am_default_evo();
    char err[AM_ERR_MAX];
    for (int k = 0; k < NKEYS; k++) am_evo_set(&d, g_keys[k][0], g_keys[k][1], err, sizeof err);
    return d;
}

static void prepare(am_api_work* w)
{
    char err[AM_ERR_MAX];
    am_status st = am_api_init(w, am_api_work_size(), err, sizeof err);
    CHECK(st == AM_OK, "am_api_init: %s", err);
    for (int k = 0; k < NKEYS; k++) {
        st = am_api_set(w, g_keys[k][0], g_keys[k][1], err, sizeof err);
        CHECK(st == AM_OK, "am_api_set %s: %s", g_keys[k][0], err);
    }
}

static void test_sizes(void)
{
    CHECK(am_api_version() == AM_API_VERSION, "version %d", am_api_version());
    CHECK(am_api_work_size() == (long)sizeof(am_api_work), "work size %ld", am_api_work_size());
    CHECK(am_api_result_size() == (long)sizeof(am_result), "result size %ld", am_api_result_size());
}

static void test_genome_as_run(void)
{
    char err[AM_ERR_MAX];
    am_evo_def d = small_def();
    am_rng r;
    am_rng_seed(&r, 11);
    for (int trial = 0; trial < 3; trial++) {
        am_genome* g = &g_ind.genome;
        CHECK(am_genome_init(g, &d.geno, &r, err, sizeof err) == AM_OK, "genome: %s", err);
        long len = 0;
        CHECK(am_genome_format(g, g_text, (long)sizeof g_text, &len, err, sizeof err) == AM_OK, "format: %s", err);
        static am_palette pal;
        am_evo_palette_into(&d, &pal);
        am_evo_evaluate(&d, &pal, g, &g_ref, NULL, &g_ind, NULL);
        for (int k = 0; k < 2; k++) {
            prepare(&g_w[k]);
            am_result res;
            am_status st = am_api_eval_genome(&g_w[k], g_text, &res, err, sizeof err);
            CHECK(st == AM_OK, "eval genome: %s", err);
            CHECK(res.hash == g_ind.state_hash, "trial %d workspace %d: hash %016llx, the run's %016llx", trial, k,
                  (unsigned long long)res.hash, (unsigned long long)g_ind.state_hash);
            CHECK(memcmp(&res.fitness, &g_ind.fitness, sizeof res.fitness) == 0 || (res.diverged && g_ind.fitness == -1.0),
                  "trial %d: fitness %.17g, the run's %.17g", trial, res.fitness, g_ind.fitness);
            CHECK(res.voxels == g_ind.voxels && res.steps == g_ind.steps, "voxels %d/%d steps %ld/%ld", res.voxels, g_ind.voxels,
                  res.steps, g_ind.steps);
        }
    }
}

static void test_lattice_as_sim(void)
{
    char err[AM_ERR_MAX];
    am_evo_def d = small_def();
    CHECK(am_scene_build(&g_lat, "sphere:6", err, sizeof err) == AM_OK, "scene: %s", err);
    long len = 0;
    CHECK(am_lattice_format(&g_lat, g_text, (long)sizeof g_text, &len, err, sizeof err) == AM_OK, "format: %s", err);
    /* mu_static changes every material, as amorph sim --mu_static does */
    for (int m = 0; m < g_lat.palette.count; m++) g_lat.palette.mat[m].mu_static = AM_PARAM_FROM_DOUBLE(0.5);
    am_result ref, res;
    CHECK(am_model_build(&g_ref.model, &g_lat, &d.env, err, sizeof err) == AM_OK, "build: %s", err);
    am_evaluate(&g_ref.model, &g_ref.state, &d.eval, &ref);
    prepare(&g_w[1]);
    CHECK(am_api_set(&g_w[1], "mu_static", "0.5", err, sizeof err) == AM_OK, "set: %s", err);
    CHECK(am_api_eval_lattice(&g_w[1], g_text, &res, err, sizeof err) == AM_OK, "eval lattice: %s", err);
    CHECK(res.hash == ref.hash && res.fitness == ref.fitness && res.steps == ref.steps, "hash %016llx/%016llx fitness %.9g/%.9g",
          (unsigned long long)res.hash, (unsigned long long)ref.hash, res.fitness, ref.fitness);
    /* without the setting the friction is the lattice's own: another motion */
    prepare(&g_w[0]);
    CHECK(am_api_eval_lattice(&g_w[0], g_text, &res, err, sizeof err) == AM_OK, "eval lattice: %s", err);
    CHECK(res.hash != ref.hash, "mu_static made no difference");
    CHECK(res.voxels == ref.voxels && res.voxels > 0, "voxels %d", res.voxels);
}

static void test_empty_body(void)
{
    char err[AM_ERR_MAX];
    prepare(&g_w[0]);
    am_result res;
    res.fitness = 5;
    am_status st = am_api_eval_lattice(&g_w[0], "lattice 2 2 2 0.01\nmaterial passive\n", &res, err, sizeof err);
    if (st != AM_OK) {
        /* the lattice format may want its cells: build the text of an empty lattice */
        CHECK(am_lattice_init(&g_lat, 2, 2, 2, AM_PARAM_FROM_DOUBLE(0.01), err, sizeof err) == AM_OK, "init: %s", err);
        long len = 0;
        CHECK(am_lattice_format(&g_lat, g_text, (long)sizeof g_text, &len, err, sizeof err) == AM_OK, "format: %s", err);
        st = am_api_eval_lattice(&g_w[0], g_text, &res, err, sizeof err);
    }
    CHECK(st == AM_OK, "empty lattice: %s", err);
    CHECK(res.fitness == 0 && res.voxels == 0 && res.steps == 0 && res.hash == 0, "fitness %g voxels %d", res.fitness, res.voxels);
}

/* a run folder's config.txt as amorph sim DIR reads it: every key as the run wrote it, the keys it
 * does not name as a stored configuration had them, a key set twice and a bad line refused with
 * the file's name and line, the settings unchanged then */
static void test_set_config(void)
{
    char err[AM_ERR_MAX];
    static char again[1 << 16];
    am_evo_def d = small_def();
    d.eval.cycles = 3; /* not the defaults, not prepare()'s */
    long len = 0, len2 = 0;
    CHECK(am_evo_format(&d, 1, g_text, (long)sizeof g_text, &len, err, sizeof err) == AM_OK, "format: %s", err);
    CHECK(am_api_init(&g_w[1], am_api_work_size(), err, sizeof err) == AM_OK, "init: %s", err);
    CHECK(am_api_set_config(&g_w[1], g_text, "run/config.txt", err, sizeof err) == AM_OK, "set_config: %s", err);
    CHECK(am_evo_format(&g_w[1].def, 1, again, (long)sizeof again, &len2, err, sizeof err) == AM_OK, "format: %s", err);
    CHECK(len == len2 && !memcmp(g_text, again, (size_t)len), "the settings read back differ:\n%s\n%s", g_text, again);
    /* a genome evaluated after it is the run's evaluation (am_evo_evaluate with the run's settings) */
    am_rng r;
    am_rng_seed(&r, 5);
    CHECK(am_genome_init(&g_ind.genome, &d.geno, &r, err, sizeof err) == AM_OK, "genome: %s", err);
    static char gtext[1 << 20];
    CHECK(am_genome_format(&g_ind.genome, gtext, (long)sizeof gtext, &len, err, sizeof err) == AM_OK, "format: %s", err);
    static am_palette pal;
    am_evo_palette_into(&d, &pal);
    am_evo_evaluate(&d, &pal, &g_ind.genome, &g_ref, NULL, &g_ind, NULL);
    am_result res;
    CHECK(am_api_eval_genome(&g_w[1], gtext, &res, err, sizeof err) == AM_OK, "eval: %s", err);
    CHECK(res.hash == g_ind.state_hash && res.steps == g_ind.steps, "hash %016llx, the run's %016llx",
          (unsigned long long)res.hash, (unsigned long long)g_ind.state_hash);
    /* a text naming one key: the others as a stored configuration had them (relax_dt_frac 0, where
     * today's default settles at 1.8 dt_rec), not the workspace's or today's defaults */
    CHECK(am_api_set_config(&g_w[1], "# an old run\ncycles = 4  # four\n", NULL, err, sizeof err) == AM_OK, "set_config: %s", err);
    CHECK(g_w[1].def.eval.cycles == 4 && g_w[1].def.eval.relax_dt_frac == am_stored_evo().eval.relax_dt_frac &&
              am_stored_evo().eval.relax_dt_frac != am_default_evo().eval.relax_dt_frac && g_w[1].def.geno.nx == am_default_evo().geno.nx,
          "cycles %d relax_dt_frac %g workspace %d", g_w[1].def.eval.cycles, (double)g_w[1].def.eval.relax_dt_frac, g_w[1].def.geno.nx);
    /* refusals: the name and line, one line, the settings as they were */
    static const char* const bad[][2] = {
        {"cycles = 2\nworkspace = 6\ncycles = 3\n", "run/config.txt:3: cycles set again (first on line 1): say it once"},
        {"cycles = 2\n\ncycles = many\n", "run/config.txt:3: "},
        {"cycles = 2\nno_such_key = 1\n", "run/config.txt:2: "},
        {"cycles = 2\njust words\n", "run/config.txt:2: expected 'key = value'"},
        {"cycles =\n", "run/config.txt:1: "},
    };
    for (int k = 0; k < (int)(sizeof bad / sizeof bad[0]); k++) {
        const am_status st = am_api_set_config(&g_w[1], bad[k][0], "run/config.txt", err, sizeof err);
        CHECK(st != AM_OK && !strncmp(err, bad[k][1], strlen(bad[k][1])) && printable_line(err), "text %d: status %d, '%s'", k, (int)st, err);
        CHECK(g_w[1].def.eval.cycles == 4 && g_w[1].def.geno.nx == am_default_evo().geno.nx, "text %d changed the settings", k);
    }
    CHECK(am_api_set_config(&g_w[1], NULL, "x", err, sizeof err) == AM_ERR_ARG, "NULL text accepted");
    CHECK(am_api_set_config(&g_w[1], "cycles = 7\n", NULL, err, sizeof err) == AM_OK && g_w[1].def.eval.cycles == 7, "after refusals: %s", err);
}

static void test_refusals(void)
{
    char err[AM_ERR_MAX];
    am_result res;
    static am_api_work fresh;
    CHECK(am_api_init(NULL, am_api_work_size(), err, sizeof err) == AM_ERR_ARG, "NULL accepted");
    CHECK(am_api_init(&fresh, am_api_work_size() - 1, err, sizeof err) == AM_ERR_ARG, "a short buffer accepted");
    CHECK(strstr(err, "sizeof *w") && printable_line(err), "message '%s'", err);
    /* a longer buffer is refused too: a C caller passes sizeof *w, which differs from the library's
     * only when it was compiled with another REAL or PROFILE */
    CHECK(am_api_init(&fresh, am_api_work_size() + 8, err, sizeof err) == AM_ERR_ARG, "a workspace of another layout accepted");
    CHECK(am_api_init((am_api_work*)((char*)&fresh + 1), am_api_work_size(), err, sizeof err) == AM_ERR_ARG, "misaligned accepted");
    CHECK(am_api_eval_genome(&fresh, "x", &res, err, sizeof err) == AM_ERR_ARG, "an unprepared workspace accepted");
    prepare(&g_w[0]);
    CHECK(am_api_set(&g_w[0], "no_such_key", "1", err, sizeof err) == AM_ERR_ARG, "unknown key accepted");
    CHECK(printable_line(err) && strstr(err, "no_such_key"), "message '%s'", err);
    CHECK(am_api_set(&g_w[0], "cycles", "many", err, sizeof err) == AM_ERR_RANGE, "bad value accepted");
    CHECK(g_w[0].def.eval.cycles == 2, "a refused value changed the settings (%d)", g_w[0].def.eval.cycles);
    CHECK(am_api_eval_genome(&g_w[0], "amorph-genome 1\nrepresentation nonsense\n", &res, err, sizeof err) != AM_OK, "bad genome accepted");
    CHECK(printable_line(err) && !strncmp(err, "genome:", 7), "message '%s'", err);
    CHECK(am_api_eval_lattice(&g_w[0], "lattice x\n", &res, err, sizeof err) != AM_OK, "bad lattice accepted");
    CHECK(printable_line(err) && !strncmp(err, "lattice:", 8), "message '%s'", err);
}

/* AM_LAYOUT_CHECK passes in a program compiled as the library was; another version or size is one line */
static void test_layout(void)
{
    char err[AM_ERR_MAX];
    CHECK(AM_LAYOUT_CHECK(err, sizeof err) == AM_OK, "the library refuses its own layout: %s", err);
    long v = AM_LAYOUT_VERSION, m = (long)sizeof(am_model);
    CHECK(am_layout_check(v, "x", (long)sizeof(am_lattice), m + 4, (long)sizeof(am_state), (long)sizeof(am_genome), (long)sizeof(am_evo),
                          (long)sizeof(am_api_work), err, sizeof err) == AM_ERR_ARG, "another am_model size accepted");
    CHECK(printable_line(err) && strstr(err, "am_model") && strstr(err, "compiled for x"), "message '%s'", err);
    CHECK(am_layout_check(v + 10000, AM_LAYOUT_CONFIG, (long)sizeof(am_lattice), m, (long)sizeof(am_state), (long)sizeof(am_genome),
                          (long)sizeof(am_evo), (long)sizeof(am_api_work), err, sizeof err) == AM_ERR_ARG, "another major version accepted");
    CHECK(printable_line(err) && strstr(err, "headers"), "message '%s'", err);
    CHECK(am_layout_check(v + 100, AM_LAYOUT_CONFIG, (long)sizeof(am_lattice), m, (long)sizeof(am_state), (long)sizeof(am_genome),
                          (long)sizeof(am_evo), (long)sizeof(am_api_work), err, sizeof err) == AM_ERR_ARG, "a newer minor version accepted");
    CHECK(AM_VERSION_MINOR == 0 || am_layout_check(v - 100, AM_LAYOUT_CONFIG, (long)sizeof(am_lattice), m, (long)sizeof(am_state),
                                                   (long)sizeof(am_genome), (long)sizeof(am_evo), (long)sizeof(am_api_work), err, sizeof err) == AM_OK,
          "an older minor version refused: %s", err);
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    (void)test_quick; /* nothing here has a quick form */
    RUN(test_sizes);
    RUN(test_genome_as_run);
    RUN(test_lattice_as_sim);
    RUN(test_empty_body);
    RUN(test_set_config);
    RUN(test_refusals);
    RUN(test_layout);
    return SUMMARY();
}
