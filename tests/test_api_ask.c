/* tests of ask/tell (amorph/api.h, docs/embedding.md): amorph's own operators called from outside
 * make amorph's own run. A population drawn with am_api_genome_new, paired, bred with
 * am_api_offspring, evaluated with am_api_eval_genome and crowded with am_api_crowd, generation by
 * generation, ends in the population of the run am_evo makes with the same settings and seed, genome
 * for genome and fitness for fitness, for each representation and with evolved phases; the
 * operators' refusals are one line each. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "amorph.h"
#include "harness.h"

#define POP 8
#define GENS 3

static am_api_work W;
static am_evo E;
static am_evo_work WK[1];
static char pop[POP][AM_GENOME_TEXT_MAX], kid[POP][AM_GENOME_TEXT_MAX], text[AM_GENOME_TEXT_MAX];
static double fit[POP], kfit[POP];

/* a result's fitness as crowding compares it: NaN for a diverged body */
static double score(const am_result* r) { return r->diverged ? (double)NAN : r->fitness; }

static int set_all(const char* const (*kv)[2], int n, char* err)
{
    for (int i = 0; i < n; i++)
        if (am_api_set(&W, kv[i][0], kv[i][1], err, AM_ERR_MAX) != AM_OK) return 0;
    return 1;
}

/* the run by am_evo and by the API's calls, compared */
static void replay(const char* repr, const char* actuation)
{
    char err[AM_ERR_MAX];
    const char* const kv[][2] = {{"representation", repr}, {"workspace", "6"}, {"cycles", "2"},   {"period_steps", "100"},
                                 {"relax_max_steps", "400"}, {"relax_min_steps", "50"}, {"release_steps", "100"},
                                 {"gmx_points", "6"},        {"dct_k", "2"},           {"actuation", actuation}};
    CHECK(am_api_init(&W, (long)sizeof W, err, sizeof err) == AM_OK && set_all(kv, 10, err), "%s: settings: %s", repr, err);
    /* the run */
    am_evo_def d = W.def;
    d.population = POP;
    d.evaluations = POP * GENS;
    d.seed = 5;
    CHECK(am_evo_init(&E, &d, err, sizeof err) == AM_OK, "%s: %s", repr, err);
    while (!am_evo_done(&E))
        if (am_evo_generation(&E, WK, NULL, NULL, err, sizeof err) != AM_OK) {
            CHECK(0, "%s: %s", repr, err);
            return;
        }
    /* the same by ask/tell */
    am_result r;
    CHECK(am_api_seed(&W, 5, err, sizeof err) == AM_OK, "%s", err);
    for (int i = 0; i < POP; i++) {
        CHECK(am_api_genome_new(&W, pop[i], sizeof pop[i], err, sizeof err) == AM_OK, "%s", err);
        CHECK(am_api_eval_genome(&W, pop[i], &r, err, sizeof err) == AM_OK, "%s", err);
        fit[i] = score(&r);
    }
    int placed = 0;
    for (int g = 1; g < GENS; g++) {
        int order[POP];
        CHECK(am_api_pairing(&W, POP, order, err, sizeof err) == AM_OK, "%s", err);
        for (int k = 0; k < POP; k += 2)
            CHECK(am_api_offspring(&W, pop[order[k]], pop[order[k + 1]], kid[k], kid[k + 1], sizeof kid[k], err, sizeof err) == AM_OK, "%s",
                  err);
        for (int k = 0; k < POP; k++) {
            CHECK(am_api_eval_genome(&W, kid[k], &r, err, sizeof err) == AM_OK, "%s", err);
            kfit[k] = score(&r);
        }
        for (int k = 0; k < POP; k += 2) {
            int meets[2], repl[2];
            const int pa = order[k], pb = order[k + 1];
            CHECK(am_api_crowd(&W, pop[pa], fit[pa], pop[pb], fit[pb], kid[k], kfit[k], kid[k + 1], kfit[k + 1], meets, repl, err,
                               sizeof err) == AM_OK,
                  "%s", err);
            for (int c = 0; c < 2; c++)
                if (repl[c]) {
                    const int p = meets[c] ? pb : pa;
                    memcpy(pop[p], kid[k + c], sizeof pop[p]);
                    fit[p] = kfit[k + c];
                    placed++;
                }
        }
    }
    int same = 0;
    for (int i = 0; i < POP; i++) {
        long len = 0;
        CHECK(am_genome_format(&E.pop[i].genome, text, sizeof text, &len, err, sizeof err) == AM_OK, "%s", err);
        const double f = E.pop[i].diverged ? (double)NAN : E.pop[i].fitness;
        same += !strcmp(text, pop[i]) && (f == fit[i] || (f != f && fit[i] != fit[i]));
    }
    CHECK(same == POP, "%s, actuation %s: %d of %d members as the run has them", repr, actuation, same, POP);
    CHECK(placed > 0, "%s: no offspring placed in %d generations: the comparison shows nothing", repr, GENS - 1);
    printf("    %s, actuation %s: %d offspring placed, the population the run's\n", repr, actuation, placed);
}

static void test_ask_tell_is_the_run(void)
{
    replay("gmx", "global");
    replay("dct", "global");
    replay("cppn", "global");
#if AM_GENO_LAYERS
    replay("gmx", "phase");
#endif
}

/* the distance: 0 for a genome and itself, in [0, 1], symmetric; mutation moves something */
static void test_operators(void)
{
    char err[AM_ERR_MAX];
    double d = -1, e = -1;
    CHECK(am_api_init(&W, (long)sizeof W, err, sizeof err) == AM_OK && am_api_set(&W, "workspace", "8", err, sizeof err) == AM_OK,
          "%s", err);
    CHECK(am_api_genome_new(&W, pop[0], sizeof pop[0], err, sizeof err) == AM_OK &&
              am_api_genome_new(&W, pop[1], sizeof pop[1], err, sizeof err) == AM_OK,
          "%s", err);
    CHECK(am_api_distance(&W, pop[0], pop[0], &d, err, sizeof err) == AM_OK && d == 0, "self distance %g: %s", d, err);
    CHECK(am_api_distance(&W, pop[0], pop[1], &d, err, sizeof err) == AM_OK && am_api_distance(&W, pop[1], pop[0], &e, err, sizeof err) == AM_OK &&
              d > 0 && d <= 1 && d == e,
          "distance %g / %g", d, e);
    int changed = 0;
    for (int i = 0; i < 20 && !changed; i++) {
        CHECK(am_api_mutate(&W, pop[0], pop[2], sizeof pop[2], err, sizeof err) == AM_OK, "%s", err);
        changed = strcmp(pop[0], pop[2]) != 0;
    }
    CHECK(changed, "20 mutations changed nothing");
    /* the same seed, the same genomes */
    CHECK(am_api_seed(&W, 9, err, sizeof err) == AM_OK && am_api_genome_new(&W, pop[3], sizeof pop[3], err, sizeof err) == AM_OK &&
              am_api_seed(&W, 9, err, sizeof err) == AM_OK && am_api_genome_new(&W, pop[4], sizeof pop[4], err, sizeof err) == AM_OK &&
              !strcmp(pop[3], pop[4]),
          "seed 9 twice: other genomes");
}

/* refusals: one line each, nothing drawn */
static void test_refusals(void)
{
    char err[AM_ERR_MAX];
    int order[4], meets[2], repl[2];
    double d;
    CHECK(am_api_init(&W, (long)sizeof W, err, sizeof err) == AM_OK && am_api_set(&W, "workspace", "8", err, sizeof err) == AM_OK,
          "%s", err);
    CHECK(am_api_genome_new(&W, pop[0], sizeof pop[0], err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_api_genome_new(&W, text, 100, err, sizeof err) == AM_ERR_CAPACITY && printable_line(err), "short buffer: %s", err);
    CHECK(am_api_pairing(&W, 3, order, err, sizeof err) == AM_ERR_RANGE && strstr(err, "even"), "odd pairing: %s", err);
    CHECK(am_api_seed(&W, -1, err, sizeof err) == AM_ERR_RANGE, "negative seed: %s", err);
    CHECK(am_api_mutate(&W, "amorph-genome 1\nrepr gmx\n", text, sizeof text, err, sizeof err) == AM_ERR_PARSE &&
              !strncmp(err, "genome:", 7) && printable_line(err),
          "bad genome: %s", err);
    /* a genome of other settings: a DCT genome where the settings make GMX ones */
    CHECK(am_api_set(&W, "representation", "dct", err, sizeof err) == AM_OK &&
              am_api_genome_new(&W, pop[1], sizeof pop[1], err, sizeof err) == AM_OK && am_api_set(&W, "representation", "gmx", err, sizeof err) == AM_OK,
          "%s", err);
    CHECK(am_api_distance(&W, pop[0], pop[1], &d, err, sizeof err) == AM_ERR_ARG && strstr(err, "genome b: a dct genome"),
          "mixed genomes: %s", err);
    CHECK(am_api_crowd(&W, pop[0], 1, pop[0], 1, pop[0], 1, NULL, 1, meets, repl, err, sizeof err) == AM_ERR_ARG &&
              strstr(err, "no offspring 2"),
          "missing offspring: %s", err);
    am_api_work* none = NULL;
    CHECK(am_api_genome_new(none, text, sizeof text, err, sizeof err) == AM_ERR_ARG, "NULL workspace: %s", err);
}

/* a crowding decision worked by hand: the offspring identical to parent b meets b */
static void test_crowd_rule(void)
{
    char err[AM_ERR_MAX];
    int meets[2], repl[2];
    CHECK(am_api_init(&W, (long)sizeof W, err, sizeof err) == AM_OK && am_api_set(&W, "workspace", "8", err, sizeof err) == AM_OK,
          "%s", err);
    double d = 0;
    do {
        CHECK(am_api_genome_new(&W, pop[0], sizeof pop[0], err, sizeof err) == AM_OK &&
                  am_api_genome_new(&W, pop[1], sizeof pop[1], err, sizeof err) == AM_OK &&
                  am_api_distance(&W, pop[0], pop[1], &d, err, sizeof err) == AM_OK,
              "%s", err);
    } while (d == 0);
    /* offspring 1 is b, offspring 2 is a: they meet the other way round; 1 beats b, 2 ties a */
    CHECK(am_api_crowd(&W, pop[0], 0.010, pop[1], 0.020, pop[1], 0.030, pop[0], 0.010, meets, repl, err, sizeof err) == AM_OK, "%s", err);
    CHECK(meets[0] == 1 && meets[1] == 0 && repl[0] == 1 && repl[1] == 0, "meets %d %d, replaces %d %d", meets[0], meets[1], repl[0],
          repl[1]);
    /* a diverged parent loses to anything but a diverged offspring */
    CHECK(am_api_crowd(&W, pop[0], (double)NAN, pop[1], 0.020, pop[0], -1, pop[1], (double)NAN, meets, repl, err, sizeof err) == AM_OK && meets[0] == 0 &&
              repl[0] == 1 && repl[1] == 0,
          "diverged: meets %d, replaces %d %d", meets[0], repl[0], repl[1]);
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    (void)test_quick;
    RUN(test_ask_tell_is_the_run);
    RUN(test_operators);
    RUN(test_refusals);
    RUN(test_crowd_rule);
    return SUMMARY();
}
