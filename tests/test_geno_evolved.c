/* tests of the evolved fields (docs/genotypes.md, Evolved actuation): a genome's phase and
 * stiffness fields beside its materials, in every representation: their operators, their text,
 * their expression into bytes and layers, the crowding distance over them, and a run that
 * evolves them (deterministic for any thread count, the same with and without the same-body
 * table). A build without AM_GENO_LAYERS (the board's) refuses them in one line. */
#include <math.h>
#include <string.h>

#include "amorph.h"
#include "harness.h"

static am_geno_work W;
static am_genome ga, gb;
static char text1[AM_GENOME_TEXT_MAX], text2[AM_GENOME_TEXT_MAX];

/* a def on an 8^3 workspace (fits every profile) */
static am_geno_def small_def(int repr, int controls)
{
    am_geno_def d = am_default_geno();
    d.repr = repr;
    d.nx = d.ny = d.nz = 8;
    d.gmx_max_points = 24;
    d.controls = controls;
    return d;
}

#if AM_GENO_LAYERS
static am_layers L;
static uint8_t body[AM_MAX_CELLS];

/* every representation: random genomes carry the fields, stay in range under mutation and
 * crossover, read back bit for bit, and a genome without them writes the version 1 text */
static void test_operators_and_text(void)
{
    char err[AM_ERR_MAX];
    for (int repr = 1; repr < AM_REPR_COUNT; repr++) {
        am_geno_def d0 = small_def(repr, 0), d = small_def(repr, AM_CTL_PHASE | AM_CTL_STIFFNESS);
        am_rng r0, r;
        am_rng_seed(&r0, 7);
        am_rng_seed(&r, 7);
        CHECK(am_genome_init(&ga, &d0, &r0, err, sizeof err) == AM_OK, "%s init: %s", am_repr_name(repr), err);
        CHECK(am_genome_init(&gb, &d, &r, err, sizeof err) == AM_OK, "%s init: %s", am_repr_name(repr), err);
        CHECK(am_genome_fields(&ga) == 2 && am_genome_fields(&gb) == 4, "%s fields %d, %d", am_repr_name(repr),
              am_genome_fields(&ga), am_genome_fields(&gb));
        CHECK(am_genome_field_of(&gb, AM_CTL_PHASE) == 2 && am_genome_field_of(&gb, AM_CTL_STIFFNESS) == 3 &&
                  am_genome_field_of(&ga, AM_CTL_PHASE) == -1,
              "%s field indices", am_repr_name(repr));
        CHECK(am_genome_values(&gb) > am_genome_values(&ga), "%s values %d vs %d", am_repr_name(repr), am_genome_values(&gb),
              am_genome_values(&ga));
        CHECK(am_genome_hash(&ga) != am_genome_hash(&gb), "%s: the fields are in the hash", am_repr_name(repr));
        long n1 = 0, n2 = 0;
        CHECK(am_genome_format(&ga, text1, sizeof text1, &n1, err, sizeof err) == AM_OK, "%s", err);
        CHECK(!strncmp(text1, "amorph-genome 1\n", 16) && !strstr(text1, "evolved"), "%s: a genome without them is version 1",
              am_repr_name(repr));
        /* mutate and cross many times: every value stays in its range */
        am_genome c1, c2;
        for (int i = 0; i < (test_quick() ? 50 : 200); i++) {
            am_genome_mutate(&gb, &d, &r);
            CHECK(am_genome_crossover(&gb, &gb, &c1, &c2, &d, &r, err, sizeof err) == AM_OK, "%s", err);
            if (am_genome_check(&gb, err, sizeof err) != AM_OK || am_genome_check(&c1, err, sizeof err) != AM_OK) {
                CHECK(0, "%s after %d mutations: %s", am_repr_name(repr), i, err);
                break;
            }
        }
        CHECK(am_genome_format(&gb, text1, sizeof text1, &n1, err, sizeof err) == AM_OK, "%s", err);
        CHECK(!strncmp(text1, "amorph-genome 2\n", 16) && strstr(text1, "\nevolved phase stiffness\n"), "%s text:\n%.200s",
              am_repr_name(repr), text1);
        CHECK(am_genome_parse(&ga, text1, "g", err, sizeof err) == AM_OK, "%s parse: %s", am_repr_name(repr), err);
        CHECK(am_genome_equal(&ga, &gb) && am_genome_hash(&ga) == am_genome_hash(&gb), "%s: read back differs", am_repr_name(repr));
        CHECK(am_genome_format(&ga, text2, sizeof text2, &n2, err, sizeof err) == AM_OK && n1 == n2 && !strcmp(text1, text2),
              "%s: written twice differently", am_repr_name(repr));
        /* one field alone */
        d = small_def(repr, AM_CTL_STIFFNESS);
        CHECK(am_genome_init(&gb, &d, &r, err, sizeof err) == AM_OK && am_genome_field_of(&gb, AM_CTL_STIFFNESS) == 2, "%s", err);
        CHECK(am_genome_format(&gb, text1, sizeof text1, &n1, err, sizeof err) == AM_OK && strstr(text1, "\nevolved stiffness\n") &&
                  am_genome_parse(&ga, text1, "g", err, sizeof err) == AM_OK && am_genome_equal(&ga, &gb),
              "%s stiffness alone: %s", am_repr_name(repr), err);
    }
}

/* the evolved fields never change the body: the same genome without them expresses the same cells */
static void test_fields_leave_the_body_alone(void)
{
    char err[AM_ERR_MAX];
    for (int repr = 1; repr < AM_REPR_COUNT; repr++) {
        am_geno_def d = small_def(repr, AM_CTL_PHASE | AM_CTL_STIFFNESS);
        am_rng r;
        am_rng_seed(&r, 11);
        int bodies = 0;
        for (int t = 0; t < 8; t++) {
            CHECK(am_genome_init(&ga, &d, &r, err, sizeof err) == AM_OK, "%s", err);
            gb = ga;
            gb.controls = 0;
            CHECK(am_genome_express(&ga, NULL, &W, NULL, err, sizeof err) == AM_OK, "%s", err);
            memcpy(body, W.cell, 512);
            const int voxels = W.voxels;
            bodies += voxels > 0;
            /* the bytes: phases and stiffnesses in filled cells only */
            int bad = 0;
            for (int c = 0; c < 512; c++) bad += !W.cell[c] && (W.ctl[0][c] || W.ctl[1][c]);
            CHECK(bad == 0, "%s: %d empty cells with fields", am_repr_name(repr), bad);
            CHECK(am_genome_layers(&ga, NULL, &W, &L, err, sizeof err) == AM_OK && L.has_phase && L.has_stiffness && !L.has_bc,
                  "%s layers: %s", am_repr_name(repr), err);
            for (int c = 0; c < 512; c++)
                if (W.cell[c]) {
                    if (!(L.phase[c] >= 0 && L.phase[c] < 1 && L.phase[c] * 256 == W.ctl[0][c])) bad++;
                    if (!(L.stiffness[c] >= AM_P(1e5) && L.stiffness[c] <= AM_P(1e7))) bad++;
                }
            CHECK(bad == 0, "%s: %d layer values off their bytes or range", am_repr_name(repr), bad);
            CHECK(am_genome_express(&gb, NULL, &W, NULL, err, sizeof err) == AM_OK, "%s", err);
            CHECK(W.voxels == voxels && !memcmp(W.cell, body, 512), "%s genome %d: the body changed without the fields",
                  am_repr_name(repr), t);
            /* layers of a genome the workspace does not hold: refused */
            CHECK(am_genome_layers(&ga, NULL, &W, &L, err, sizeof err) == AM_ERR_ARG, "%s: stale expression taken",
                  am_repr_name(repr));
        }
        CHECK(bodies >= 2, "%s: %d of 8 random genomes have a body", am_repr_name(repr), bodies);
    }
}

/* GMX: the phase is the weighted circular mean of the points that reach a cell */
static void test_gmx_circular_mean(void)
{
    char err[AM_ERR_MAX];
    am_geno_def d = small_def(AM_REPR_GMX, AM_CTL_PHASE | AM_CTL_STIFFNESS);
    d.gmx_points = 0;
    am_rng r;
    am_rng_seed(&r, 1);
    CHECK(am_genome_init(&ga, &d, &r, err, sizeof err) == AM_OK, "%s", err);
    /* two equal points at one place: phases 0.2 and 0.4 give 0.3 (byte 76.8), stiffnesses 0.2 and 0.6 give 0.4 */
    const am_gmx_point p = {.x = AM_R(4), .y = AM_R(4), .z = AM_R(4), .weight = AM_R(1), .radius = AM_R(3), .mat = 1,
                            .phase = AM_R(0.2), .stiff = AM_R(0.2)};
    ga.gmx.pt[0] = p;
    ga.gmx.pt[1] = p;
    ga.gmx.pt[1].phase = AM_R(0.4);
    ga.gmx.pt[1].stiff = AM_R(0.6);
    ga.gmx.count = 2;
    CHECK(am_genome_express(&ga, NULL, &W, NULL, err, sizeof err) == AM_OK && W.voxels > 0, "%s", err);
    const int centre = 4 + 8 * (4 + 8 * 4);
    CHECK(W.ctl[0][centre] == 76 || W.ctl[0][centre] == 77, "phase byte %d, want 76.8", W.ctl[0][centre]);
    CHECK(W.ctl[1][centre] == 102, "stiffness byte %d, want 0.4 x 255 = 102", W.ctl[1][centre]);
    /* across the wrap: 0.9 and 0.1 average to 0 (byte 0, or 255 a rounding below), not 0.5 */
    ga.gmx.pt[0].phase = AM_R(0.9);
    ga.gmx.pt[1].phase = AM_R(0.1);
    CHECK(am_genome_express(&ga, NULL, &W, NULL, err, sizeof err) == AM_OK, "%s", err);
    CHECK(W.ctl[0][centre] <= 1 || W.ctl[0][centre] == 255, "phase byte %d across the wrap, want 0", W.ctl[0][centre]);
    /* a hole's point pulls as strongly as a solid's: a weight -1 point of phase 0.5 beside */
    ga.gmx.pt[2] = p;
    ga.gmx.pt[2].weight = AM_R(-0.01);
    ga.gmx.pt[2].phase = AM_R(0.5);
    ga.gmx.count = 3;
    ga.gmx.pt[0].phase = ga.gmx.pt[1].phase = AM_R(0.5);
    CHECK(am_genome_express(&ga, NULL, &W, NULL, err, sizeof err) == AM_OK, "%s", err);
    CHECK(W.ctl[0][centre] == 128, "phase byte %d, want 128", W.ctl[0][centre]);
}

/* the stiffness of a byte: geometric between the range's ends */
static void test_stiffness_bytes(void)
{
    am_express_def ex = am_default_express();
    CHECK(am_stiffness_of_byte(&ex, 0) == AM_P(1e5) && am_stiffness_of_byte(&ex, 255) == AM_P(1e7), "ends %g %g",
          (double)am_stiffness_of_byte(&ex, 0), (double)am_stiffness_of_byte(&ex, 255));
    for (int s = 1; s < 255; s += 23) {
        const double want = 1e5 * pow(100.0, s / 255.0);
        NEAR_REL((double)am_stiffness_of_byte(&ex, s), want, 1e-5);
    }
    double prev = 0;
    int rising = 1;
    for (int s = 0; s < 256; s++) {
        const double v = (double)am_stiffness_of_byte(&ex, s);
        rising &= v > prev;
        prev = v;
    }
    CHECK(rising, "the stiffness of a byte rises with it");
    /* a range of more than a factor of 100 is refused, before any layer is written */
    char err[AM_ERR_MAX];
    am_geno_def d = small_def(AM_REPR_DCT, AM_CTL_STIFFNESS);
    am_rng r;
    am_rng_seed(&r, 3);
    CHECK(am_genome_init(&ga, &d, &r, err, sizeof err) == AM_OK && am_genome_express(&ga, NULL, &W, NULL, err, sizeof err) == AM_OK,
          "%s", err);
    ex.stiffness_max = AM_P(2e7);
    CHECK(am_genome_layers(&ga, &ex, &W, &L, err, sizeof err) == AM_ERR_RANGE && strstr(err, "100"), "range 200 taken: %s", err);
}

/* the crowding distance over the fields, against hand-worked cells */
static void test_distance_over_fields(void)
{
    const uint8_t a[4] = {1, 1, 0, 2}, b[4] = {1, 1, 0, 1};
    const uint8_t pa[4] = {0, 128, 0, 250}, pb[4] = {0, 0, 0, 5};
    const uint8_t sa[4] = {255, 0, 0, 0}, sb[4] = {0, 0, 0, 0};
    /* materials alone: one cell of four */
    NEAR(AM_TO_DOUBLE(am_body_distance_ctl(a, pa, sa, b, pb, sb, 0, 4)), 0.25, 1e-6);
    /* phase: cell 3's material differs (1), cell 1 half a period (1): 2 / 4 */
    NEAR(AM_TO_DOUBLE(am_body_distance_ctl(a, pa, sa, b, pb, sb, AM_CTL_PHASE, 4)), 0.5, 1e-6);
    /* stiffness: cell 0 the whole range (1), cell 3 (1): 2 / 4 */
    NEAR(AM_TO_DOUBLE(am_body_distance_ctl(a, pa, sa, b, pb, sb, AM_CTL_STIFFNESS, 4)), 0.5, 1e-6);
    /* both, each field half of a same-material cell: (0.5 + 0.5 + 1) / 4 */
    NEAR(AM_TO_DOUBLE(am_body_distance_ctl(a, pa, sa, b, pb, sb, AM_CTL_PHASE | AM_CTL_STIFFNESS, 4)), 0.5, 1e-6);
    /* across the wrap: 250 and 5 are 11 / 256 apart, 22 / 256 of a half period */
    const uint8_t c[1] = {1}, p1[1] = {250}, p2[1] = {5}, z[1] = {0};
    NEAR(AM_TO_DOUBLE(am_body_distance_ctl(c, p1, z, c, p2, z, AM_CTL_PHASE, 1)), 11.0 / 128.0, 1e-6);
    /* bodies that differ only in phase: 0 by their materials, not by their fields (two genomes) */
    char err[AM_ERR_MAX];
    am_geno_def d = small_def(AM_REPR_GMX, AM_CTL_PHASE);
    am_rng r;
    am_rng_seed(&r, 5);
    do CHECK(am_genome_init(&ga, &d, &r, err, sizeof err) == AM_OK, "%s", err);
    while (am_genome_express(&ga, NULL, &W, NULL, err, sizeof err) == AM_OK && W.voxels == 0);
    gb = ga;
    for (int i = 0; i < gb.gmx.count; i++) gb.gmx.pt[i].phase = AM_R(0.5) * (gb.gmx.pt[i].phase < AM_R(0.5)) + AM_R(0.25);
    am_real dist = AM_R(0);
    CHECK(am_genome_distance(&ga, &gb, &W, &dist, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_body_distance(W.other, W.cell, 512) == AM_R(0) && dist > AM_R(0.01), "phase-only difference: distance %g",
          AM_TO_DOUBLE(dist));
    CHECK(memcmp(W.ctl[0], W.other_ctl[0], 512) != 0, "the two bodies' phases are the same");
}

/* the text format's refusals */
static void test_parse_errors(void)
{
    static const struct {
        const char* text;
        const char* want;
    } cases[] = {
        {"amorph-genome 1\nrepr dct\nmaterials a b\nevolved phase\nworkspace 8 8 8\n", "g:4: expected 'workspace W H D', found 'evolved'"},
        {"amorph-genome 2\nrepr dct\nmaterials a b\nevolved speed\nworkspace 8 8 8\n", "g:4: unknown evolved field 'speed' (phase, stiffness)"},
        {"amorph-genome 2\nrepr dct\nmaterials a b\nevolved stiffness phase\n", "g:4: evolved fields in the order phase, stiffness, each once"},
        {"amorph-genome 2\nrepr dct\nmaterials a b\nevolved phase\nevolved phase\n", "g:5: 'evolved' given twice"},
        {"amorph-genome 3\n", "g:1: genome format version 3: this build reads versions 1 to 2"},
        {"amorph-genome 2\nrepr gmx\nmaterials a b\nevolved phase\nworkspace 8 8 8\ngmx 1\npoint 1 1 1 0.5 2 1\n",
         "g:7: 'point' needs X Y Z WEIGHT RADIUS MATERIAL PHASE"},
        {"amorph-genome 2\nrepr gmx\nmaterials a b\nevolved phase\nworkspace 8 8 8\ngmx 1\npoint 1 1 1 0.5 2 1 1\n",
         "g:7: phase '1' is not a number in [0, 1)"},
        {"amorph-genome 2\nrepr gmx\nmaterials a b\nevolved stiffness\nworkspace 8 8 8\ngmx 1\npoint 1 1 1 0.5 2 1 1.5\n",
         "g:7: stiffness '1.5' is not a number in [0, 1]"},
        {"amorph-genome 2\nrepr dct\nmaterials a b\nevolved phase\nworkspace 8 8 8\ndct 1\namp 0 0 0 0.1\namp 1 0 0 0.1\nend\n",
         "g:9: missing line 'amp 2 0 0'"},
        {"amorph-genome 2\nrepr dct\nmaterials a b\nevolved phase\nworkspace 8 8 8\ndct 1\namp 3 0 0 0.1\n", "g:7: field '3' is not 0..2"},
        {"amorph-genome 2\nrepr cppn\nmaterials a b\nevolved phase\nworkspace 8 8 8\ncppn 1 1\nout 3 1 0.5\n", "g:7: field '3' is not 0..2"},
    };
    char err[AM_ERR_MAX];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        am_status st = am_genome_parse(&ga, cases[i].text, "g", err, sizeof err);
        CHECK(st != AM_OK && !strcmp(err, cases[i].want), "case %d: got '%s', want '%s'", (int)i, st == AM_OK ? "ok" : err, cases[i].want);
    }
}
#endif

/* a run that evolves phases and stiffnesses: the same with the same-body table on and off (a body
 * taken for another that differs in its fields would change it; threads: tests/cli_evolved.sh); its genomes carry the fields; a build without layers refuses the setting in one line */
static am_evo E1, E2;
/* the run's hash, pinned: float desktop, fixed-point desktop (the run is a fixed function of its settings) */
#define GOLDEN_EVOLVED_RUN UINT64_C(0x5b063caba25634b2)
#define GOLDEN_EVOLVED_RUN_FIXED UINT64_C(0xf43c64c5ec29b202)
static am_evo_work WK[1];

static uint64_t run(am_evo* e, int memo, char* err, int errsz)
{
    am_evo_def d = am_default_evo();
    const char* set[][2] = {{"representation", "gmx"}, {"actuation", "phase"}, {"stiffness", "evolved"}, {"workspace", "6"},
                            {"population", "8"},        {"evaluations", "40"},  {"cycles", "3"},          {"stiffness_min", "3e5"},
                            {"stiffness_max", "3e6"},   {"gmx_points", "3"},     {"mutation_rate", "0.02"},
                            {"gmx_add", "0"},           {"gmx_remove", "0"}}; /* offspring often a parent again */
    for (size_t i = 0; i < sizeof set / sizeof set[0]; i++)
        if (am_evo_set(&d, set[i][0], set[i][1], err, errsz) != AM_OK) return 0;
    am_status st = am_evo_init(e, &d, err, errsz);
    if (st != AM_OK) return 0;
    e->memo_limit = memo ? 0 : -1;
    while (!am_evo_done(e))
        if (am_evo_generation(e, WK, NULL, NULL, err, errsz) != AM_OK) return 0;
    return am_evo_hash(e);
}

static void test_evolved_run(void)
{
    char err[AM_ERR_MAX] = "";
#if AM_GENO_LAYERS
    const uint64_t h1 = run(&E1, 1, err, sizeof err);
    CHECK(h1 != 0, "run: %s", err);
    const uint64_t h2 = run(&E2, 0, err, sizeof err);
    CHECK(h2 == h1, "without the table: %016llx, with it: %016llx", (unsigned long long)h2, (unsigned long long)h1);
    CHECK(E1.reused > 0 && E2.reused == 0, "bodies taken from the table: %ld and %ld", E1.reused, E2.reused);
    CHECK(E1.pop[0].genome.controls == (AM_CTL_PHASE | AM_CTL_STIFFNESS) && E1.has_best && E1.best.voxels > 0, "the run's genomes");
    printf("    evolved phase and stiffness run: %016llx, best %.6g m\n", (unsigned long long)h1, E1.best.fitness);
    if (AM_MAX_DIM == 20) {
#if defined(AM_REAL_FIXED_POINT)
        const uint64_t pinned = GOLDEN_EVOLVED_RUN_FIXED;
#else
        const uint64_t pinned = GOLDEN_EVOLVED_RUN;
#endif
        CHECK(h1 == pinned, "golden evolved run hash: got %016llx, pinned %016llx", (unsigned long long)h1, (unsigned long long)pinned);
    }
#else
    CHECK(run(&E1, 1, err, sizeof err) == 0 && strstr(err, "actuation = phase: the") && strstr(err, "AM_GENO_LAYERS 0"),
          "refusal: '%s'", err);
#endif
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
#if AM_GENO_LAYERS
    RUN(test_operators_and_text);
    RUN(test_fields_leave_the_body_alone);
    RUN(test_gmx_circular_mean);
    RUN(test_stiffness_bytes);
    RUN(test_distance_over_fields);
    RUN(test_parse_errors);
#endif
    RUN(test_evolved_run);
    return SUMMARY();
}
