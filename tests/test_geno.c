/* tests of the genotypes: the hand-written DCT, the three representations' operators, the level
 * set, the text format. Statistical tests state their tolerance next to the expected value. */
#include "amorph.h"
#include "harness.h"
#include "sink.h"
#include "../src/geno/geno_internal.h" /* the operators' steps, checked one by one */

static am_geno_work W;
static am_dct_work D;
static am_dct_scratch DS;
static am_real field[AM_MAX_CELLS], field2[AM_MAX_CELLS], coef[AM_MAX_CELLS], coef2[AM_MAX_CELLS];
static am_genome ga, gb, gc, gd, ge;
static char text1[AM_GENOME_TEXT_MAX], text2[AM_GENOME_TEXT_MAX];
static am_real ratio[AM_MAX_GENO_MATERIALS * AM_MAX_CELLS];
static int comp[AM_MAX_CELLS], stack_[AM_MAX_CELLS];
static am_lattice lat;

/* a def on an 8^3 workspace (fits every profile), with a fixed GMX cap */
static am_geno_def small_def(int repr, int materials)
{
    am_geno_def d = am_default_geno();
    d.repr = repr;
    d.materials = materials;
    d.nx = d.ny = d.nz = 8;
    d.gmx_max_points = 24;
    return d;
}

static void init_or_fail(am_genome* g, const am_geno_def* d, am_rng* r)
{
    char err[AM_ERR_MAX] = "";
    am_status st = am_genome_init(g, d, r, err, sizeof err);
    CHECK(st == AM_OK, "init %s: %s", am_repr_name(d->repr), err);
}

/* ---- DCT ---- */

static double ref_basis(int u, int x, int n)
{
    double c = u == 0 ? sqrt(1.0 / n) : sqrt(2.0 / n);
    double ang = 3.14159265358979323846 * (double)((2 * x + 1) * u) / (double)(2 * n);
    return c * cos(ang); /* the reference in double (libm is fine in a test) */
}

static void test_dct_inverse_equals_direct_sum(void)
{
    const int shapes[3][6] = {{4, 4, 4, 20, 20, 20}, {4, 3, 5, 20, 13, 7}, {8, 8, 8, 8, 8, 8}};
    am_rng r;
    am_rng_seed(&r, 11);
    for (int s = 0; s < 3; s++) {
        const int* k = shapes[s];
        const int* n = shapes[s] + 3;
        if (n[0] > AM_MAX_DIM || n[1] > AM_MAX_DIM || n[2] > AM_MAX_DIM) continue;
        CHECK(am_dct_plan(&D, k, n, NULL, 0) == AM_OK, "plan %d", s);
        for (int i = 0; i < k[0] * k[1] * k[2]; i++) coef[i] = am_rng_range(&r, AM_R(-1), AM_R(1));
        am_dct_inverse(&D, &DS, coef, field);
        double worst = 0;
        for (int z = 0; z < n[2]; z++)
            for (int y = 0; y < n[1]; y++)
                for (int x = 0; x < n[0]; x++) {
                    double sum = 0;
                    for (int w = 0; w < k[2]; w++)
                        for (int v = 0; v < k[1]; v++)
                            for (int u = 0; u < k[0]; u++)
                                sum += AM_TO_DOUBLE(coef[u + k[0] * (v + k[1] * w)]) * ref_basis(u, x, n[0]) * ref_basis(v, y, n[1]) *
                                       ref_basis(w, z, n[2]);
                    double e = fabs(sum - AM_TO_DOUBLE(field[x + n[0] * (y + n[1] * z)]));
                    if (e > worst) worst = e;
                }
        CHECK(worst <= 1e-5, "shape %d: separable inverse differs from the triple sum by %.3g", s, worst);
    }
}

static void test_dct_forward_then_inverse_is_identity(void)
{
    const int shapes[2][3] = {{AM_MAX_DIM, AM_MAX_DIM, AM_MAX_DIM}, {7, 5, 3}};
    am_rng r;
    am_rng_seed(&r, 12);
    for (int s = 0; s < 2; s++) {
        const int* n = shapes[s];
        const int cells = n[0] * n[1] * n[2];
        CHECK(am_dct_plan(&D, n, n, NULL, 0) == AM_OK, "plan");
        for (int i = 0; i < cells; i++) field[i] = am_rng_range(&r, AM_R(-1), AM_R(1));
        am_dct_forward(&D, &DS, field, coef);
        am_dct_inverse(&D, &DS, coef, field2);
        double worst = 0;
        for (int i = 0; i < cells; i++) worst = fmax(worst, fabs(AM_TO_DOUBLE(field[i]) - AM_TO_DOUBLE(field2[i])));
        CHECK(worst <= 1e-5, "shape %d: forward then inverse differs from the identity by %.3g", s, worst);
        /* and inverse then forward, with only k < n coefficients: orthonormal projection */
        const int k[3] = {4 < n[0] ? 4 : n[0], 3, 2};
        CHECK(am_dct_plan(&D, k, n, NULL, 0) == AM_OK, "plan k");
        for (int i = 0; i < k[0] * k[1] * k[2]; i++) coef[i] = am_rng_range(&r, AM_R(-1), AM_R(1));
        am_dct_inverse(&D, &DS, coef, field);
        am_dct_forward(&D, &DS, field, coef2);
        worst = 0;
        for (int i = 0; i < k[0] * k[1] * k[2]; i++) worst = fmax(worst, fabs(AM_TO_DOUBLE(coef[i]) - AM_TO_DOUBLE(coef2[i])));
        CHECK(worst <= 1e-5, "shape %d: inverse then forward differs by %.3g", s, worst);
    }
}

static void test_dct_plan_limits(void)
{
    char err[AM_ERR_MAX] = "";
    const int k[3] = {3, 3, 3}, big[3] = {AM_MAX_DIM + 1, 4, 4}, small[3] = {2, 4, 4};
    CHECK(am_dct_plan(&D, k, big, err, sizeof err) != AM_OK, "n past AM_MAX_DIM accepted");
    CHECK(am_dct_plan(&D, k, small, err, sizeof err) == AM_ERR_RANGE, "k > n accepted");
}

/* ---- golden hashes: seeded init, mutation, crossover and expression are reproducible ---- */

static uint64_t cells_hash(const uint8_t* c, int n) { return am_hash_bytes(AM_HASH_INIT, c, (unsigned long)n); }

static void test_golden_hashes(void)
{
    uint64_t got[3][4];
    char err[AM_ERR_MAX] = "";
    for (int repr = 1; repr <= 3; repr++) {
        am_geno_def d = small_def(repr, 3);
        am_rng r;
        am_rng_seed(&r, 20240614u + (uint64_t)repr);
        init_or_fail(&ga, &d, &r);
        init_or_fail(&gb, &d, &r);
        got[repr - 1][0] = am_genome_hash(&ga);
        for (int i = 0; i < 100; i++) am_genome_mutate(&ga, &d, &r);
        got[repr - 1][1] = am_genome_hash(&ga);
        CHECK(am_genome_crossover(&ga, &gb, &gc, &gd, &d, &r, err, sizeof err) == AM_OK, "crossover: %s", err);
        got[repr - 1][2] = am_hash_u64(am_genome_hash(&gc), am_genome_hash(&gd));
        CHECK(am_genome_express(&gc, NULL, &W, NULL, err, sizeof err) == AM_OK, "express: %s", err);
        got[repr - 1][3] = cells_hash(W.cell, 8 * 8 * 8);
        /* the same seed again gives the same genome */
        am_rng_seed(&r, 20240614u + (uint64_t)repr);
        init_or_fail(&ge, &d, &r);
        CHECK(am_genome_hash(&ge) == got[repr - 1][0], "%s: init not reproducible", am_repr_name(repr));
    }
    /* genome hashes (init, 100 mutations, crossover) pinned per am_real: am_rng_unit draws 24 bits
     * for float and fixed point (Q24 fractions) and 53 for double. The bodies agree for float, double
     * and fixed point, and for both
     * profiles here (their lookup tables differ, so other bodies could differ by a cell). */
#if defined(AM_REAL_FIXED_POINT)
    static const uint64_t want[3][3] = {
        {UINT64_C(0x8583e2069c1fa9dd), UINT64_C(0xba5de46c0eee7401), UINT64_C(0x497b8149567964da)},
        {UINT64_C(0x709c4e37e413a3ee), UINT64_C(0xa51cbb12a5d8646a), UINT64_C(0x2c878b43507c548f)},
        {UINT64_C(0xfd83b46b1f453096), UINT64_C(0x6bda639f669f3507), UINT64_C(0x51646a05476d83fa)},
    };
#elif defined(AM_REAL_DOUBLE)
    static const uint64_t want[3][3] = {
        {UINT64_C(0x685bc36db97cc1c6), UINT64_C(0x28d38066fda97874), UINT64_C(0x57ed60415a86323c)},
        {UINT64_C(0x47ecc9892c225731), UINT64_C(0xf07947f3abca52a1), UINT64_C(0xbba8de6727d42352)},
        {UINT64_C(0xcd6216e2b4e14010), UINT64_C(0xf37bba788c6d713f), UINT64_C(0xfebc97c6b73d2c08)},
    };
#else
    static const uint64_t want[3][3] = {
        {UINT64_C(0x55e9a13dbee23b39), UINT64_C(0xe3c1fc9a05e4fb1a), UINT64_C(0x9dbdd8f4b8520775)},
        {UINT64_C(0xf1d2e4f1aca04cfa), UINT64_C(0xbf20e072d3ca294a), UINT64_C(0xd08b543027f502ff)},
        {UINT64_C(0x401dc1a5b42fb5dc), UINT64_C(0x10ecf143c3ee77c5), UINT64_C(0x018532822c5d4ef0)},
    };
#endif
    static const uint64_t want_body[3] = {UINT64_C(0xf30c4ee6b2290a69), UINT64_C(0xf76e1e29214a331d),
                                          UINT64_C(0x6dc252f8359a7235)};
    for (int repr = 0; repr < 3; repr++)
        for (int k = 0; k < 4; k++)
            CHECK(got[repr][k] == (k < 3 ? want[repr][k] : want_body[repr]), "%s hash %d: got 0x%016llx",
                  am_repr_name(repr + 1), k, (unsigned long long)got[repr][k]);
}

static void test_dct_mutation_rate(void)
{
    am_geno_def d = small_def(AM_REPR_DCT, 2);
    am_rng r;
    am_rng_seed(&r, 31);
    init_or_fail(&ga, &d, &r);
    const int n = 2 * 4 * 4 * 4, trials = test_quick() ? 2000 : 10000;
    long changed = 0;
    double biggest = 0;
    for (int t = 0; t < trials; t++) {
        gb = ga;
        am_genome_mutate(&ga, &d, &r);
        for (int m = 0; m < 2; m++)
            for (int i = 0; i < 64; i++) {
                double delta = fabs(AM_TO_DOUBLE(ga.dct.amp[m][i]) - AM_TO_DOUBLE(gb.dct.amp[m][i]));
                changed += delta != 0;
                if (delta > biggest) biggest = delta;
            }
    }
    double frac = (double)changed / ((double)n * trials);
    /* expected 0.20; binomial standard error 3.5e-4 over 10,000 mutations: tolerance 0.01 */
    NEAR(frac, 0.20, 0.01);
    /* a change is at most 5% of the range [-1, 1] */
    CHECK(biggest <= 0.1 + 1e-6, "largest change %.9g > 0.1", biggest);
    CHECK(biggest > 0.09, "largest change %.9g: steps too small", biggest);
}

/* values that differ between two CPPN genomes of the same shape */
static int cppn_diff(const am_genome* a, const am_genome* b)
{
    const am_cppn_genome* x = &a->cppn;
    const am_cppn_genome* y = &b->cppn;
    int n = 0;
    for (int l = 0; l < x->layers; l++)
        for (int j = 0; j < x->nodes; j++) {
            n += x->node[l][j].fn != y->node[l][j].fn;
            n += x->node[l][j].offset != y->node[l][j].offset;
            n += x->node[l][j].xscale != y->node[l][j].xscale;
            n += x->node[l][j].yscale != y->node[l][j].yscale;
        }
    for (int j = 0; j < x->nodes; j++)
        for (int i = 0; i < 4; i++) n += (x->w_in[j][i] != y->w_in[j][i]) + (x->on_in[j][i] != y->on_in[j][i]);
    for (int l = 0; l + 1 < x->layers; l++)
        for (int j = 0; j < x->nodes; j++)
            for (int i = 0; i < x->nodes; i++) n += (x->w[l][j][i] != y->w[l][j][i]) + (x->on[l][j][i] != y->on[l][j][i]);
    for (int m = 0; m < a->materials; m++)
        for (int j = 0; j < x->nodes; j++) n += (x->w_out[m][j] != y->w_out[m][j]) + (x->on_out[m][j] != y->on_out[m][j]);
    return n;
}

static void test_cppn_mutation_changes_one_value_on_average(void)
{
    am_geno_def d = small_def(AM_REPR_CPPN, 2);
    am_rng r;
    am_rng_seed(&r, 32);
    init_or_fail(&ga, &d, &r);
    CHECK(am_genome_values(&ga) == 4 * 12 + 2 * (16 + 2 * 16 + 2 * 4), "values %d", am_genome_values(&ga));
    const int trials = test_quick() ? 2000 : 10000;
    long changed = 0, none = 0;
    for (int t = 0; t < trials; t++) {
        gb = ga;
        am_genome_mutate(&ga, &d, &r);
        int c = cppn_diff(&ga, &gb);
        changed += c;
        none += c == 0;
    }
    double mean = (double)changed / trials;
    /* expected 1 (binomial over 160 values, p = 1/160): standard error 0.01; tolerance 0.05 */
    NEAR(mean, 1.0, test_quick() ? 0.1 : 0.05);
    /* no change at all: (1 - 1/160)^160 = 0.367 */
    NEAR((double)none / trials, 0.367, test_quick() ? 0.05 : 0.025);
}

static void test_gmx_mutation_rates(void)
{
    am_geno_def d = small_def(AM_REPR_GMX, 3);
    d.gmx_add = d.gmx_remove = AM_R(0); /* fixed list for the per-value rates */
    am_rng r;
    am_rng_seed(&r, 33);
    init_or_fail(&ga, &d, &r);
    const int trials = test_quick() ? 2000 : 10000;
    long changed = 0, mats = 0, total = 0;
    for (int t = 0; t < trials; t++) {
        gb = ga;
        am_genome_mutate(&ga, &d, &r);
        for (int i = 0; i < ga.gmx.count; i++) {
            const am_gmx_point* p = &ga.gmx.pt[i];
            const am_gmx_point* q = &gb.gmx.pt[i];
            changed += (p->x != q->x) + (p->y != q->y) + (p->z != q->z) + (p->weight != q->weight) + (p->radius != q->radius);
            mats += p->mat != q->mat;
            total++;
        }
    }
    /* 0.20 per real value, 0.05 per material: standard errors 1.4e-3 and 1.7e-3 over 10,000 x 16 */
    NEAR((double)changed / (5.0 * total), 0.20, 0.01);
    NEAR((double)mats / total, 0.05, 0.01);
    /* adding and removing: each with probability 0.1 per mutation */
    d = small_def(AM_REPR_GMX, 2);
    am_rng_seed(&r, 34);
    init_or_fail(&ga, &d, &r);
    long grew = 0, shrank = 0;
    for (int t = 0; t < trials; t++) {
        int before = ga.gmx.count;
        am_genome_mutate(&ga, &d, &r);
        grew += ga.gmx.count > before;
        shrank += ga.gmx.count < before;
        CHECK(ga.gmx.count >= 1 && ga.gmx.count <= 24, "count %d outside 1..24", ga.gmx.count);
    }
    /* net change +1 with p 0.09, -1 with p 0.09 (when neither bound binds) */
    NEAR((double)grew / trials, 0.09, 0.02);
    NEAR((double)shrank / trials, 0.09, 0.02);
}

/* ---- crossover ---- */

static void test_dct_crossover_takes_each_component_from_a_parent(void)
{
    am_geno_def d = small_def(AM_REPR_DCT, 2);
    am_rng r;
    am_rng_seed(&r, 41);
    init_or_fail(&ga, &d, &r);
    init_or_fail(&gb, &d, &r);
    long from_b = 0, n = 0, bad = 0;
    for (int t = 0; t < 200; t++) {
        am_genome_crossover(&ga, &gb, &gc, &gd, &d, &r, NULL, 0);
        for (int m = 0; m < 2; m++)
            for (int i = 0; i < 64; i++) {
                int b1 = gc.dct.amp[m][i] == gb.dct.amp[m][i], a1 = gc.dct.amp[m][i] == ga.dct.amp[m][i];
                int b2 = gd.dct.amp[m][i] == gb.dct.amp[m][i], a2 = gd.dct.amp[m][i] == ga.dct.amp[m][i];
                bad += !((a1 && b2) || (b1 && a2));
                from_b += b1;
                n++;
            }
    }
    CHECK(bad == 0, "%ld components from neither parent or not complementary", bad);
    NEAR((double)from_b / n, 0.5, 0.02); /* 25,600 draws: standard error 0.003 */
}

static void test_gmx_plane_crossover_keeps_sides(void)
{
    am_geno_def d = small_def(AM_REPR_GMX, 2);
    am_rng r;
    am_rng_seed(&r, 42);
    for (int t = 0; t < 200; t++) {
        init_or_fail(&ga, &d, &r);
        init_or_fail(&gb, &d, &r);
        am_rng copy = r;
        am_real point[3], normal[3];
        am_gmx_random_plane(&ga, &copy, point, normal);
        CHECK(am_genome_crossover(&ga, &gb, &gc, &gd, &d, &r, NULL, 0) == AM_OK, "crossover");
        CHECK(copy.s[0] == r.s[0] && copy.s[3] == r.s[3], "the crossover draws exactly one plane");
        /* expected children, built here from the definition */
        int n1 = 0, n2 = 0;
        const am_genome* par[2] = {&ga, &gb};
        for (int pass = 0; pass < 2; pass++)
            for (int i = 0; i < par[pass]->gmx.count; i++) {
                const am_gmx_point* p = &par[pass]->gmx.pt[i];
                double s = (AM_TO_DOUBLE(p->x) - AM_TO_DOUBLE(point[0])) * AM_TO_DOUBLE(normal[0]) +
                           (AM_TO_DOUBLE(p->y) - AM_TO_DOUBLE(point[1])) * AM_TO_DOUBLE(normal[1]) + (AM_TO_DOUBLE(p->z) - AM_TO_DOUBLE(point[2])) * AM_TO_DOUBLE(normal[2]);
                if (fabs(s) < 1e-4) continue; /* too close to the plane to judge in double */
                int pos = s > 0;
                /* child 1: a's positive side, b's negative side; child 2: the rest */
                const am_genome* child = (pass == 0) == pos ? &gc : &gd;
                int found = 0;
                for (int k = 0; k < child->gmx.count; k++)
                    if (!memcmp(&child->gmx.pt[k].x, &p->x, sizeof p->x) && child->gmx.pt[k].weight == p->weight &&
                        child->gmx.pt[k].radius == p->radius)
                        found = 1;
                CHECK(found, "point %d of parent %d (side %d) not in the right child", i, pass, pos);
                if (child == &gc) n1++;
                else n2++;
            }
        CHECK(gc.gmx.count + gd.gmx.count == ga.gmx.count + gb.gmx.count, "points lost: %d + %d vs %d + %d",
              gc.gmx.count, gd.gmx.count, ga.gmx.count, gb.gmx.count);
        CHECK(AM_MUL(normal[0], normal[0]) + AM_MUL(normal[1], normal[1]) + AM_MUL(normal[2], normal[2]) > AM_R(0.999), "normal not unit");
        for (int a = 0; a < 3; a++) CHECK(point[a] >= 0 && point[a] <= AM_INT(7), "plane point outside the workspace");
    }
    /* a given plane x = 3.5: child 1 holds a's points with x >= 3.5 then b's with x < 3.5 */
    init_or_fail(&ga, &d, &r);
    init_or_fail(&gb, &d, &r);
    const am_real pt[3] = {AM_R(3.5), 0, 0}, nx[3] = {AM_R(1), 0, 0};
    am_gmx_plane_cross(&ga, &gb, pt, nx, 64, &gc, &gd);
    int k = 0;
    for (int i = 0; i < ga.gmx.count; i++)
        if (ga.gmx.pt[i].x >= AM_R(3.5)) CHECK(gc.gmx.pt[k++].x == ga.gmx.pt[i].x, "a's side, in order");
    for (int i = 0; i < gb.gmx.count; i++)
        if (gb.gmx.pt[i].x < AM_R(3.5)) CHECK(gc.gmx.pt[k++].x == gb.gmx.pt[i].x, "b's side, in order");
    CHECK(k == gc.gmx.count, "child 1 has %d points, expected %d", gc.gmx.count, k);
}

static void test_cppn_region_covers_nodes_uniformly(void)
{
    am_geno_def d = small_def(AM_REPR_CPPN, 2);
    am_rng r;
    am_rng_seed(&r, 43);
    init_or_fail(&ga, &d, &r);
    gb = ga;
    for (int l = 0; l < 3; l++)
        for (int j = 0; j < 4; j++) {
            ga.cppn.node[l][j].offset = AM_R(0.5);
            gb.cppn.node[l][j].offset = AM_R(-0.5);
        }
    const int trials = test_quick() ? 5000 : 40000;
    static long hits[AM_MAX_CPPN_LAYERS][AM_MAX_CPPN_NODES];
    memset(hits, 0, sizeof hits);
    long bad = 0;
    for (int t = 0; t < trials; t++) {
        am_genome_crossover(&ga, &gb, &gc, &gd, &d, &r, NULL, 0);
        for (int l = 0; l < 3; l++)
            for (int j = 0; j < 4; j++) {
                int in1 = gc.cppn.node[l][j].offset < 0, in2 = gd.cppn.node[l][j].offset > 0;
                bad += in1 != in2;
                hits[l][j] += in1;
            }
    }
    CHECK(bad == 0, "children not complementary at %ld nodes", bad);
    /* P(in region) = E[len/(n+len-1)] per axis: layers (3) 0.47778, positions (4) 0.43036 */
    const double p = ((1.0 / 3 + 2.0 / 4 + 3.0 / 5) / 3) * ((1.0 / 4 + 2.0 / 5 + 3.0 / 6 + 4.0 / 7) / 4);
    /* standard error sqrt(p (1-p) / 40,000) = 0.002: tolerance 0.01 for every node */
    for (int l = 0; l < 3; l++)
        for (int j = 0; j < 4; j++) NEAR((double)hits[l][j] / trials, p, test_quick() ? 0.03 : 0.01);
    /* a node's incoming connections travel with it */
    am_rng_seed(&r, 44);
    init_or_fail(&ga, &d, &r);
    init_or_fail(&gb, &d, &r);
    for (int t = 0; t < 50; t++) {
        am_genome_crossover(&ga, &gb, &gc, NULL, &d, &r, NULL, 0);
        for (int j = 0; j < 4; j++) {
            const am_genome* src = !memcmp(&gc.cppn.node[1][j], &gb.cppn.node[1][j], sizeof(am_cppn_node)) ? &gb : &ga;
            for (int i = 0; i < 4; i++) CHECK(gc.cppn.w[0][j][i] == src->cppn.w[0][j][i], "link %d %d from the other parent", j, i);
        }
    }
}

/* ---- expressed bodies ---- */

/* checks a body against its fields: inside the workspace, argmax material, one face-connected
 * piece, and the largest piece of the thresholded cells */
static void check_body(const am_genome* g, am_real threshold)
{
    const int nx = g->nx, ny = g->ny, nz = g->nz, cells = nx * ny * nz;
    int filled = 0, wrong_material = 0, below = 0, second_piece = 0, dropped = 0;
    CHECK(W.voxels <= cells && W.nx == nx && W.ny == ny && W.nz == nz, "body of %d voxels, workspace %d", W.voxels, cells);
    for (int c = 0; c < cells; c++) {
        int best = 0;
        for (int m = 1; m < g->materials; m++)
            if (W.dens[m][c] > W.dens[best][c]) best = m;
        if (W.cell[c]) {
            filled++;
            wrong_material += W.cell[c] != best + 1;
        }
    }
    CHECK(filled == W.voxels, "voxels %d, counted %d", W.voxels, filled);
    CHECK(wrong_material == 0, "%d cells without the argmax material", wrong_material);
    /* components of the thresholded set, by an explicit stack */
    for (int c = 0; c < cells; c++) comp[c] = -1;
    int ncomp = 0, biggest = 0, body_comp = -1;
    for (int c = 0; c < cells; c++) {
        am_real s = W.dens[0][c];
        for (int m = 1; m < g->materials; m++) s += W.dens[m][c];
        if (!(s > threshold) || comp[c] >= 0) {
            below += W.cell[c] && !(s > threshold);
            continue;
        }
        int top = 0, size = 0;
        stack_[top++] = c;
        comp[c] = ncomp;
        while (top) {
            int e = stack_[--top];
            size++;
            int x = e % nx, y = (e / nx) % ny, z = e / (nx * ny);
            int nb[6] = {x > 0 ? e - 1 : -1, x < nx - 1 ? e + 1 : -1, y > 0 ? e - nx : -1, y < ny - 1 ? e + nx : -1,
                         z > 0 ? e - nx * ny : -1, z < nz - 1 ? e + nx * ny : -1};
            for (int k = 0; k < 6; k++) {
                int f = nb[k];
                if (f < 0 || comp[f] >= 0) continue;
                am_real t = W.dens[0][f];
                for (int m = 1; m < g->materials; m++) t += W.dens[m][f];
                if (t > threshold) {
                    comp[f] = ncomp;
                    stack_[top++] = f;
                }
            }
        }
        if (size > biggest) biggest = size;
        ncomp++;
    }
    CHECK(below == 0, "%d cells filled at or below the threshold", below);
    CHECK(W.voxels == biggest, "body %d voxels, largest piece %d", W.voxels, biggest);
    for (int c = 0; c < cells; c++)
        if (W.cell[c]) {
            if (body_comp < 0) body_comp = comp[c];
            second_piece += comp[c] != body_comp;
        }
    if (body_comp >= 0)
        for (int c = 0; c < cells; c++) dropped += comp[c] == body_comp && !W.cell[c];
    CHECK(second_piece == 0, "%d body cells outside the first piece: not face-connected", second_piece);
    CHECK(dropped == 0, "%d cells of the kept piece dropped", dropped);
}

static void test_bodies_connected_argmax_in_workspace(void)
{
    char err[AM_ERR_MAX] = "";
    const int count = test_quick() ? 10 : 60;
    int nonempty[4] = {0, 0, 0, 0};
    for (int repr = 1; repr <= 3; repr++)
        for (int mats = 2; mats <= 3; mats++) {
            am_geno_def d = am_default_geno();
            d.repr = repr;
            d.materials = mats;
            if (repr == AM_REPR_DCT) d.nx = AM_MAX_DIM > 12 ? 12 : AM_MAX_DIM; /* and a non-cubic workspace */
            am_rng r;
            am_rng_seed(&r, (uint64_t)(50 + 10 * repr + mats));
            for (int i = 0; i < count; i++) {
                init_or_fail(&ga, &d, &r);
                for (int k = 0; k < i % 5; k++) am_genome_mutate(&ga, &d, &r);
                CHECK(am_genome_express(&ga, NULL, &W, NULL, err, sizeof err) == AM_OK, "express: %s", err);
                check_body(&ga, AM_R(0));
                nonempty[repr] += W.voxels > 0;
            }
        }
    for (int repr = 1; repr <= 3; repr++) CHECK(nonempty[repr] > count, "%s: too many empty bodies", am_repr_name(repr));
}

static void test_empty_body_is_valid(void)
{
    char err[AM_ERR_MAX] = "";
    am_geno_def d = small_def(AM_REPR_GMX, 2);
    d.gmx_points = 0;
    am_rng r;
    am_rng_seed(&r, 60);
    init_or_fail(&ga, &d, &r);
    CHECK(am_genome_express(&ga, NULL, &W, NULL, err, sizeof err) == AM_OK && W.voxels == 0, "empty gmx: %s", err);
    d = small_def(AM_REPR_DCT, 2);
    init_or_fail(&ga, &d, &r);
    memset(ga.dct.amp, 0, sizeof ga.dct.amp);
    ga.dct.amp[0][0] = ga.dct.amp[1][0] = AM_R(-1); /* a uniform negative field */
    CHECK(am_genome_express(&ga, NULL, &W, NULL, err, sizeof err) == AM_OK && W.voxels == 0, "empty dct: %s", err);
    CHECK(am_genome_to_lattice(&ga, NULL, &W, &lat, err, sizeof err) == AM_OK && am_lattice_count(&lat) == 0, "lattice: %s", err);
    ga.dct.amp[0][0] = AM_R(1); /* uniform positive sum: the whole workspace, passive (1 > -0.5) */
    ga.dct.amp[1][0] = AM_R(-0.5);
    CHECK(am_genome_express(&ga, NULL, &W, NULL, err, sizeof err) == AM_OK && W.voxels == 512, "full: %d", W.voxels);
    CHECK(W.cell[0] == 1 && W.cell[511] == 1, "argmax material");
}

static void test_level_set_keeps_the_largest_piece(void)
{
    /* hand-made fields on 6 x 3 x 1: 'a' is material 0, 'b' material 1, '.' empty */
    const int nx = 6, ny = 3, nz = 1;
    const char* pattern = "aa.bbb"
                          "...b.."
                          "b..b.a";
    memset(W.dens, 0, sizeof W.dens);
    for (int c = 0; c < nx * ny; c++) {
        W.dens[0][c] = pattern[c] == 'a' ? AM_R(2) : AM_R(-1);
        W.dens[1][c] = pattern[c] == 'b' ? AM_R(2) : AM_R(-1);
    }
    int v = am_levelset(&W, 2, nx, ny, nz, AM_R(0), ratio);
    /* pieces: {0, 1}, {3, 4, 5, 9, 15}, {12}, {17} */
    CHECK(v == 5, "kept %d voxels, want 5", v);
    const int keep[5] = {3, 4, 5, 9, 15};
    for (int i = 0; i < 5; i++) CHECK(W.cell[keep[i]] == 2, "cell %d not kept", keep[i]);
    CHECK(W.cell[0] == 0 && W.cell[1] == 0 && W.cell[12] == 0 && W.cell[17] == 0, "other pieces not dropped");
    /* blend ratios: the positive parts, normalised, in kept cells; 0 elsewhere */
    for (int c = 0; c < nx * ny; c++) {
        double s = AM_TO_DOUBLE(ratio[c]) + AM_TO_DOUBLE(ratio[nx * ny + c]);
        CHECK(W.cell[c] ? fabs(s - 1) < 1e-6 : s == 0, "ratio sum %.9g at cell %d", s, c);
    }
    CHECK(ratio[nx * ny + 3] == AM_R(1), "b cell is all material 1");
    /* ties: two pieces of equal size, the one holding the lowest cell wins */
    for (int c = 0; c < 6; c++) {
        W.dens[0][c] = c == 2 || c == 5 ? AM_R(-1) : AM_R(1);
        W.dens[1][c] = AM_R(0);
    }
    v = am_levelset(&W, 2, 6, 1, 1, AM_R(0), NULL);
    CHECK(v == 2 && W.cell[0] == 1 && W.cell[1] == 1 && W.cell[3] == 0 && W.cell[4] == 0, "tie kept %d", v);
}

static void test_cppn_complexity_limit(void)
{
    char err[AM_ERR_MAX] = "";
    am_geno_def d = am_default_geno();
    d.repr = AM_REPR_CPPN;
    d.materials = 1;
    d.cppn_layers = 2;
    d.cppn_nodes = 1;
    am_rng r;
    am_rng_seed(&r, 70);
    init_or_fail(&ga, &d, &r);
    /* x -> linear (x scaling 4, y scaling 2: gradient 8) -> sine with weight 2 and x scaling 4:
     * 4 x 2 x 8 = 64 rad per unit, past the limit pi (n - 1) / 4 (14.9 at n = 20: pi/2 per cell) */
    memset(&ga.cppn, 0, sizeof ga.cppn);
    ga.cppn.layers = 2;
    ga.cppn.nodes = 1;
    ga.cppn.node[0][0] = (am_cppn_node){AM_R(0), AM_R(4), AM_R(2), AM_FN_LINEAR};
    ga.cppn.node[1][0] = (am_cppn_node){AM_R(0.01), AM_R(4), AM_R(1), AM_FN_SINE};
    ga.cppn.w_in[0][0] = AM_R(1);
    ga.cppn.on_in[0][0] = 1;
    ga.cppn.w[0][0][0] = AM_R(2);
    ga.cppn.on[0][0][0] = 1;
    ga.cppn.w_out[0][0] = AM_R(1);
    ga.cppn.on_out[0][0] = 1;
    am_real eff[AM_MAX_CPPN_LAYERS][AM_MAX_CPPN_NODES];
    CHECK(am_cppn_effective_xscale(&ga, eff) == 1, "one node limited");
    const int n = ga.nx;
    const double rmax = 3.14159265358979 * (n - 1) / 4.0, rate = fabs(AM_TO_DOUBLE(eff[1][0])) * 2 * 8;
    CHECK(rate <= rmax * (1 + 1e-5) && rate >= rmax * (1 - 1e-5), "limited rate %.6g, limit %.6g", rate, rmax);
    CHECK(am_genome_express(&ga, NULL, &W, NULL, err, sizeof err) == AM_OK, "express: %s", err);
    /* along x the density is sin(pi/2 per cell): runs of one sign are at least 2 cells */
    int shortest = n, run = 1, runs = 0;
    for (int x = 1; x < n; x++) {
        if ((W.dens[0][x] > 0) == (W.dens[0][x - 1] > 0)) run++;
        else {
            if (runs > 0 && run < shortest) shortest = run; /* interior runs only */
            runs++;
            run = 1;
        }
    }
    CHECK(runs >= n / 2 - 1, "only %d sign changes: the limit is too strict", runs);
    CHECK(shortest >= 2, "a feature of %d cell(s) along x", shortest);
    /* random genomes: after limiting, every node's rate is within the bound */
    d = am_default_geno();
    d.repr = AM_REPR_CPPN;
    d.cppn_layers = AM_MAX_CPPN_LAYERS;
    d.cppn_nodes = AM_MAX_CPPN_NODES;
    int limited = 0;
    for (int i = 0; i < 50; i++) {
        init_or_fail(&ga, &d, &r);
        limited += am_cppn_effective_xscale(&ga, eff);
        for (int l = 0; l < ga.cppn.layers; l++)
            for (int j = 0; j < ga.cppn.nodes; j++)
                CHECK(fabs(AM_TO_DOUBLE(eff[l][j])) <= fabs(AM_TO_DOUBLE(ga.cppn.node[l][j].xscale)), "limit raised a scaling");
    }
    CHECK(limited > 0, "deep random networks never hit the limit");
}

static void test_distance_compares_bodies(void)
{
    char err[AM_ERR_MAX] = "";
    am_geno_def d = small_def(AM_REPR_GMX, 2);
    am_rng r;
    am_rng_seed(&r, 80);
    init_or_fail(&ga, &d, &r);
    init_or_fail(&gb, &d, &r);
    am_real dist = -1, back = -1, self = -1;
    CHECK(am_genome_distance(&ga, &ga, &W, &self, err, sizeof err) == AM_OK && self == 0, "d(a, a) = %g", AM_TO_DOUBLE(self));
    CHECK(am_genome_distance(&ga, &gb, &W, &dist, err, sizeof err) == AM_OK, "distance: %s", err);
    CHECK(am_genome_distance(&gb, &ga, &W, &back, err, sizeof err) == AM_OK && back == dist, "not symmetric");
    static uint8_t body_a[AM_MAX_CELLS];
    am_genome_express(&ga, NULL, &W, NULL, err, sizeof err);
    memcpy(body_a, W.cell, 512);
    am_genome_express(&gb, NULL, &W, NULL, err, sizeof err);
    CHECK(am_body_distance(body_a, W.cell, 512) == dist, "body distance differs");
    CHECK(dist >= 0 && dist <= AM_R(1), "distance %g", AM_TO_DOUBLE(dist));
    /* two genomes with the same body are at distance 0 even when their genes differ (a point of
     * weight 0) */
    gc = ga;
    gc.gmx.pt[gc.gmx.count++] = (am_gmx_point){.x = AM_R(1), .y = AM_R(1), .z = AM_R(1), .weight = AM_R(0), .radius = AM_R(1), .mat = 0};
    CHECK(am_genome_distance(&ga, &gc, &W, &dist, err, sizeof err) == AM_OK && dist == 0, "a weightless point changes the body");
    gd = ga;
    gd.nx = 7;
    CHECK(am_genome_distance(&ga, &gd, &W, &dist, err, sizeof err) == AM_ERR_ARG, "different workspaces");
}

static void test_lattice_palette(void)
{
    char err[AM_ERR_MAX] = "";
    am_geno_def d = small_def(AM_REPR_DCT, 3);
    am_rng r;
    am_rng_seed(&r, 90);
    init_or_fail(&ga, &d, &r);
    CHECK(am_genome_to_lattice(&ga, NULL, &W, &lat, err, sizeof err) == AM_OK, "to lattice: %s", err);
    CHECK(lat.nx == 8 && lat.palette.count == 3, "size %d, palette %d", lat.nx, lat.palette.count);
    CHECK(!strcmp(lat.palette.mat[0].name, "passive") && !strcmp(lat.palette.mat[1].name, "active") &&
              !strcmp(lat.palette.mat[2].name, "active90"),
          "palette names");
    CHECK(lat.palette.mat[0].cte == 0 && lat.palette.mat[1].cte == AM_P(0.01) && lat.palette.mat[2].phase < 0, "materials");
    CHECK(am_lattice_count(&lat) == W.voxels, "lattice count");
    CHECK(!memcmp(lat.cell, W.cell, 512), "lattice cells");
    snprintf(ga.mat[1], AM_NAME_MAX, "unobtainium");
    CHECK(am_genome_to_lattice(&ga, NULL, &W, &lat, err, sizeof err) == AM_ERR_RANGE, "unknown material accepted");
    /* a palette passed in */
    am_palette pal = am_default_palette();
    snprintf(pal.mat[4].name, AM_NAME_MAX, "unobtainium");
    am_express_def ed = am_default_express();
    ed.palette = &pal;
    CHECK(am_genome_to_lattice(&ga, &ed, &W, &lat, err, sizeof err) == AM_OK, "own palette: %s", err);
    CHECK(lat.palette.mat[1].E == pal.mat[4].E && !strcmp(lat.palette.mat[1].name, "unobtainium"), "own palette entry");
}

/* ---- text format ---- */

static void test_text_round_trip_is_exact(void)
{
    char err[AM_ERR_MAX] = "";
    for (int repr = 1; repr <= 3; repr++)
        for (int mats = 1; mats <= AM_MAX_GENO_MATERIALS; mats++) {
            am_geno_def d = am_default_geno();
            d.repr = repr;
            d.materials = mats;
            /* past the seed's three the names are the palette's (here made up) */
            for (int m = 3; m < mats; m++) snprintf(d.mat[m], AM_NAME_MAX, "extra_%d", m + 1);
            am_rng r;
            am_rng_seed(&r, (uint64_t)(100 + repr * 10 + mats));
            init_or_fail(&ga, &d, &r);
            for (int i = 0; i < 30; i++) am_genome_mutate(&ga, &d, &r);
            if (repr == AM_REPR_DCT) ga.dct.amp[0][1] = -AM_R(0.0); /* signed zero survives */
            long len1 = 0, len2 = 0;
            CHECK(am_genome_format(&ga, text1, sizeof text1, &len1, err, sizeof err) == AM_OK, "format: %s", err);
            CHECK(len1 == (long)strlen(text1), "length");
            CHECK(am_genome_sniff(text1), "sniff");
            CHECK(am_genome_parse(&gb, text1, "t.genome", err, sizeof err) == AM_OK, "parse: %s", err);
            CHECK(am_genome_equal(&ga, &gb), "%s: read differs from written", am_repr_name(repr));
            CHECK(am_genome_hash(&ga) == am_genome_hash(&gb), "hash");
            CHECK(am_genome_format(&gb, text2, sizeof text2, &len2, err, sizeof err) == AM_OK && !strcmp(text1, text2),
                  "second text differs");
            /* written through a 256-byte stream: the same text */
            char piece[256];
            t_sink sink = {text2, sizeof text2, 0};
            am_text st = {piece, sizeof piece, 0, 0, t_sink_flush, &sink, 0};
            CHECK(am_genome_write(&gb, &st, err, sizeof err) == AM_OK && am_text_flush(&st) == AM_OK && !strcmp(text1, text2) &&
                      st.done == len1, "%s: the streamed text differs", am_repr_name(repr));
#if !defined(AM_REAL_FIXED_POINT) /* a fixed-point zero has no sign */
            if (repr == AM_REPR_DCT) CHECK(signbit(gb.dct.amp[0][1]), "-0 lost");
#endif
        }
}

static void expect_parse_error(const char* text, am_status want, const char* where)
{
    char err[AM_ERR_MAX] = "";
    am_status st = am_genome_parse(&gb, text, "f.genome", err, sizeof err);
    CHECK(st == want, "status %d, want %d (%s)", st, want, err);
    CHECK(!strncmp(err, where, strlen(where)), "message '%s' does not start with '%s'", err, where);
    CHECK(!strchr(err, '\n'), "message on more than one line");
}

/* parse text; the message must be exactly want, one line of printable ASCII */
static void expect_parse_message(const char* text, const char* want)
{
    char err[AM_ERR_MAX] = "";
    am_status st = am_genome_parse(&gb, text, "f.genome", err, sizeof err);
    CHECK(st != AM_OK && !strcmp(err, want), "message '%s', want '%s'", err, want);
    CHECK(printable_line(err), "'%s' is not one line of printable ASCII", err);
}

/* a bad token shows cut and escaped (am_quote), in the header and in each representation's lines */
static void test_parse_bad_tokens_quoted(void)
{
    static char t[2048], want[AM_ERR_MAX];
    char tok[301];
    expect_parse_message("\x01" "amorph-genome 1\n",
                         "f.genome:1: not a genome: expected 'amorph-genome 1' or 'amorph-genome 2', found '\\x01amorph-genome'");
    expect_parse_message("amorph-genome 1\nrepr \x1b[31mdct\n",
                         "f.genome:2: unknown representation '\\x1b[31mdct' (dct, cppn, gmx)");
    expect_parse_message("amorph-genome 1\nrepr dct\nmaterials a b\nworkspace 8 \x7f 8\n",
                         "f.genome:4: workspace side '\\x7f' is not a positive integer");
    expect_parse_message("amorph-genome 1\nrepr dct\nmaterials a b\nworkspace 8 8 8\ndct 2\namp 0 0 0 0.5 \x7f\x01\n",
                         "f.genome:6: amplitude '\\x7f\\x01' is not a number in [-1, 1]");
    expect_parse_message("amorph-genome 1\nrepr gmx\nmaterials a b\nworkspace 8 8 8\ngmx 1\npoint 1 1 1 0.5 2 \x1b\n",
                         "f.genome:6: material '\\x1b' is not 0..1");
    expect_parse_message("amorph-genome 1\nrepr cppn\nmaterials a b\nworkspace 8 8 8\ncppn 1 2\nnode 0 0 it's\\ 0 1 1\n",
                         "f.genome:6: unknown function 'it\\'s\\\\' (sigmoid, gauss, sine, abs, linear)");
    /* a 300-character token: its first 40 characters and "..." */
    memset(tok, 'r', 300);
    tok[300] = 0;
    snprintf(t, sizeof t, "amorph-genome 1\nrepr %s\n", tok);
    snprintf(want, sizeof want, "f.genome:2: unknown representation '%.40s...' (dct, cppn, gmx)", tok);
    expect_parse_message(t, want);
    tok[0] = '\x01';
    snprintf(t, sizeof t, "amorph-genome 1\nrepr dct\nmaterials %s b\n", tok);
    snprintf(want, sizeof want, "f.genome:3: material name '\\x01%.39s...': 1 to %d letters, digits, '_' or '-'", tok + 1,
             AM_NAME_MAX - 1);
    expect_parse_message(t, want);
    snprintf(t, sizeof t, "amorph-genome 1\nrepr dct\nmaterials a b\nworkspace 8 8 8\ndct 2\n%s\n", tok);
    snprintf(want, sizeof want, "f.genome:6: unknown line '\\x01%.39s...' in a dct genome (expected 'amp' or 'end')", tok + 1);
    expect_parse_message(t, want);
}

static void test_parse_errors(void)
{
    const char* head = "amorph-genome 1\nrepr dct\nmaterials passive active\nworkspace 8 8 8\n";
    static char t[4096];
    expect_parse_error("lattice 1\n", AM_ERR_PARSE, "f.genome:1: not a genome");
    expect_parse_error("amorph-genome 3\n", AM_ERR_PARSE, "f.genome:1: genome format version 3: this build reads versions 1 to 2");
    expect_parse_error("amorph-genome 1\n# c\n\nrepr blob\n", AM_ERR_PARSE, "f.genome:4: unknown representation");
    /* one material past the profile's capacity */
    {
        char many[256] = "amorph-genome 1\nrepr dct\nmaterials";
        for (int m = 0; m <= AM_MAX_GENO_MATERIALS; m++) snprintf(many + strlen(many), sizeof many - strlen(many), " m%d", m);
        strcat(many, "\n");
        expect_parse_error(many, AM_ERR_CAPACITY, "f.genome:3:");
    }
    expect_parse_error("amorph-genome 1\nrepr dct\nmaterials a a\n", AM_ERR_PARSE, "f.genome:3: material 'a' given twice");
    expect_parse_error("amorph-genome 1\nrepr dct\nmaterials a b\nworkspace 8 99 8\n", AM_ERR_CAPACITY, "f.genome:4:");
    expect_parse_error("amorph-genome 1\nrepr dct\nmaterials a b\nworkspace 8 0 8\n", AM_ERR_PARSE, "f.genome:4:");
    snprintf(t, sizeof t, "%sdct 99\n", head);
    expect_parse_error(t, AM_ERR_CAPACITY, "f.genome:5: DCT k 99 exceeds");
    snprintf(t, sizeof t, "%sdct 2\namp 0 0 0 0.5 0.25\namp 0 0 0 0.5 0.25\n", head);
    expect_parse_error(t, AM_ERR_PARSE, "f.genome:7: 'amp 0 0 0' given twice");
    snprintf(t, sizeof t, "%sdct 2\namp 0 0 0 0.5 nan\n", head);
    expect_parse_error(t, AM_ERR_RANGE, "f.genome:6: amplitude 'nan'");
    snprintf(t, sizeof t, "%sdct 2\namp 0 0 0 0.5 1.5\n", head);
    expect_parse_error(t, AM_ERR_RANGE, "f.genome:6:");
    snprintf(t, sizeof t, "%sdct 2\namp 0 0 0 0.5\n", head);
    expect_parse_error(t, AM_ERR_PARSE, "f.genome:6: 'amp MATERIAL V W' needs 2");
    snprintf(t, sizeof t, "%sdct 1\namp 0 0 0 0.5\nend\n", head);
    expect_parse_error(t, AM_ERR_PARSE, "f.genome:7: missing line 'amp 1 0 0'");
    snprintf(t, sizeof t, "%sdct 1\namp 0 0 0 0.5\namp 1 0 0 0.5\n", head);
    expect_parse_error(t, AM_ERR_PARSE, "f.genome:7: unexpected end of text");
    snprintf(t, sizeof t, "%sdct 1\namp 0 0 0 0.5\namp 1 0 0 0.5\nend\nmore\n", head);
    expect_parse_error(t, AM_ERR_PARSE, "f.genome:9: text after 'end'");
    snprintf(t, sizeof t, "%sdct 1\namp 0 0 0 0.5\namp 1 0 0 0.5 # comment\nend # done\n", head);
    char err[AM_ERR_MAX] = "";
    CHECK(am_genome_parse(&gb, t, "f.genome", err, sizeof err) == AM_OK, "minimal dct: %s", err);
    expect_parse_error("amorph-genome 1\nrepr gmx\nmaterials a b\nworkspace 8 8 8\ngmx 1000\n", AM_ERR_CAPACITY,
                       "f.genome:5: 1000 GMX points exceed");
    expect_parse_error("amorph-genome 1\nrepr gmx\nmaterials a b\nworkspace 8 8 8\ngmx 1\npoint 1 2 9 0.5 2 0\n", AM_ERR_RANGE,
                       "f.genome:6: coordinate '9'");
    expect_parse_error("amorph-genome 1\nrepr gmx\nmaterials a b\nworkspace 8 8 8\ngmx 1\npoint 1 2 3 0.5 2 2\n", AM_ERR_RANGE,
                       "f.genome:6: material '2'");
    expect_parse_error("amorph-genome 1\nrepr gmx\nmaterials a b\nworkspace 8 8 8\ngmx 2\npoint 1 2 3 0.5 2 1\nend\n",
                       AM_ERR_PARSE, "f.genome:7: 1 'point' lines");
    expect_parse_error("amorph-genome 1\nrepr cppn\nmaterials a b\nworkspace 8 8 8\ncppn 2 9999\n", AM_ERR_CAPACITY, "f.genome:5:");
    expect_parse_error("amorph-genome 1\nrepr cppn\nmaterials a b\nworkspace 8 8 8\ncppn 1 1\nnode 0 0 cosh 0 1 1\n",
                       AM_ERR_PARSE, "f.genome:6: unknown function 'cosh'");
    expect_parse_error("amorph-genome 1\nrepr cppn\nmaterials a b\nworkspace 8 8 8\ncppn 1 1\nin 0 1 0.5 2 0 0 0 0 0\n",
                       AM_ERR_PARSE, "f.genome:6: active flag '2'");
    /* a line that would overflow the line buffer */
    memset(t, 'x', sizeof t - 1);
    t[sizeof t - 1] = '\0';
    memcpy(t, "amorph-genome 1\n", 16);
    expect_parse_error(t, AM_ERR_PARSE, "f.genome:2: line longer than");
}

static void test_capacity_is_a_status(void)
{
    char err[AM_ERR_MAX] = "";
    am_rng r;
    am_rng_seed(&r, 110);
    am_geno_def d = am_default_geno();
    d.dct_k = AM_MAX_DCT_K + 1;
    CHECK(am_genome_init(&ga, &d, &r, err, sizeof err) == AM_ERR_CAPACITY, "DCT k past capacity: %s", err);
    d = am_default_geno();
    d.repr = AM_REPR_CPPN;
    d.cppn_nodes = AM_MAX_CPPN_NODES + 1;
    CHECK(am_genome_init(&ga, &d, &r, err, sizeof err) == AM_ERR_CAPACITY, "CPPN past capacity: %s", err);
    d = am_default_geno();
    d.repr = AM_REPR_GMX;
    d.gmx_points = AM_MAX_GMX_POINTS + 1;
    CHECK(am_genome_init(&ga, &d, &r, err, sizeof err) == AM_ERR_CAPACITY, "GMX past capacity: %s", err);
    d = am_default_geno();
    d.nx = AM_MAX_DIM + 1;
    CHECK(am_genome_init(&ga, &d, &r, err, sizeof err) == AM_ERR_CAPACITY, "workspace past capacity: %s", err);
    d = am_default_geno();
    d.materials = AM_MAX_GENO_MATERIALS + 1;
    CHECK(am_genome_init(&ga, &d, &r, err, sizeof err) == AM_ERR_CAPACITY, "materials past capacity: %s", err);
    /* a GMX genome never grows past its limit */
    d = small_def(AM_REPR_GMX, 2);
    d.gmx_max_points = 17;
    d.gmx_add = AM_R(1);
    d.gmx_remove = AM_R(0);
    init_or_fail(&ga, &d, &r);
    for (int i = 0; i < 20; i++) am_genome_mutate(&ga, &d, &r);
    CHECK(ga.gmx.count == 17, "grew to %d", ga.gmx.count);
    /* formatting into a short buffer: a status, and not one byte past it */
    static char small[128];
    memset(small, '#', sizeof small);
    long len = 0;
    CHECK(am_genome_format(&ga, small, 100, &len, err, sizeof err) == AM_ERR_CAPACITY, "short buffer");
    CHECK(small[100] == '#' && small[127] == '#', "wrote past the buffer");
    CHECK(len > 100, "needed length %ld", len);
    /* the largest genome of the profile fits AM_GENOME_TEXT_MAX */
    const int reprs[3] = {AM_REPR_DCT, AM_REPR_CPPN, AM_REPR_GMX};
    for (int i = 0; i < 3; i++) {
        d = am_default_geno();
        d.repr = reprs[i];
        d.materials = AM_MAX_GENO_MATERIALS;
        for (int m = 0; m < AM_MAX_GENO_MATERIALS; m++) snprintf(d.mat[m], AM_NAME_MAX, "material_%d", m + 1);
        d.dct_k = AM_MAX_DCT_K;
        d.cppn_layers = AM_MAX_CPPN_LAYERS;
        d.cppn_nodes = AM_MAX_CPPN_NODES;
        d.gmx_points = AM_MAX_GMX_POINTS;
        init_or_fail(&ga, &d, &r);
        for (int k = 0; k < ga.cppn.nodes && reprs[i] == AM_REPR_CPPN; k++) ga.cppn.node[0][k].offset = AM_R(-1.1754944e-38);
        CHECK(am_genome_format(&ga, text1, AM_GENOME_TEXT_MAX, &len, err, sizeof err) == AM_OK, "largest %s: %s",
              am_repr_name(reprs[i]), err);
    }
    /* crossover of different shapes */
    am_geno_def d1 = small_def(AM_REPR_DCT, 2), d2 = small_def(AM_REPR_DCT, 2);
    d2.dct_k = 3;
    init_or_fail(&ga, &d1, &r);
    init_or_fail(&gb, &d2, &r);
    CHECK(am_genome_crossover(&ga, &gb, &gc, &gd, &d1, &r, err, sizeof err) == AM_ERR_ARG, "shapes differ");
    CHECK(am_genome_equal(&gc, &ga) && am_genome_equal(&gd, &gb), "children are the parents");
}

/* every representation expresses a palette of the profile's capacity: fields named as the def
 * names them, and each material in some body (one density field each, argmax) */
static void test_every_material_expressed(void)
{
    char err[AM_ERR_MAX] = "";
    static am_geno_work w;
    for (int repr = 1; repr <= 3; repr++) {
        am_geno_def d = small_def(repr, AM_MAX_GENO_MATERIALS);
        for (int m = 0; m < AM_MAX_GENO_MATERIALS; m++) snprintf(d.mat[m], AM_NAME_MAX, "mat_%d", m + 1);
        am_rng r;
        am_rng_seed(&r, (uint64_t)(700 + repr));
        long count[AM_MAX_GENO_MATERIALS + 1] = {0};
        int beyond = 0;
        for (int k = 0; k < 20; k++) {
            init_or_fail(&ga, &d, &r);
            CHECK(ga.materials == AM_MAX_GENO_MATERIALS && !strcmp(ga.mat[AM_MAX_GENO_MATERIALS - 1], d.mat[AM_MAX_GENO_MATERIALS - 1]),
                  "%s: genome of %d materials, last '%s'", am_repr_name(repr), ga.materials, ga.mat[AM_MAX_GENO_MATERIALS - 1]);
            CHECK(am_genome_express(&ga, NULL, &w, NULL, err, sizeof err) == AM_OK, "%s: %s", am_repr_name(repr), err);
            for (int c = 0; c < 8 * 8 * 8; c++) {
                if (w.cell[c] > AM_MAX_GENO_MATERIALS) beyond = 1;
                else count[w.cell[c]]++;
            }
        }
        CHECK(!beyond, "%s: a cell past the palette", am_repr_name(repr));
        for (int m = 1; m <= AM_MAX_GENO_MATERIALS; m++)
            CHECK(count[m] > 0, "%s: no body of 20 holds material %d of %d", am_repr_name(repr), m, AM_MAX_GENO_MATERIALS);
    }
    /* a def naming no material past the seed's three cannot make a genome of more */
    if (AM_MAX_GENO_MATERIALS > 3) {
        am_geno_def d = small_def(AM_REPR_GMX, 4);
        am_rng r;
        am_rng_seed(&r, 9);
        CHECK(am_genome_init(&ga, &d, &r, err, sizeof err) == AM_ERR_RANGE && strstr(err, "material 3 has no valid name"),
              "four unnamed materials: %s", err);
    }
}

static void test_memory_budget(void)
{
    printf("    sizeof(am_genome) = %d bytes, sizeof(am_geno_work) = %d bytes\n", (int)sizeof(am_genome),
           (int)sizeof(am_geno_work));
#if defined(AM_PROFILE_BOARD)
    CHECK(sizeof(am_genome) <= 2048, "board genome %d bytes > 2 KiB", (int)sizeof(am_genome));
#endif
    /* the largest member, DCT's amplitudes: (materials + evolved fields) x k^3 reals, 8 x 512 x 4
     * bytes on the desktop, and a header */
    CHECK(sizeof(am_genome) <= 16384 + 512, "genome %d bytes", (int)sizeof(am_genome));
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    RUN(test_dct_inverse_equals_direct_sum);
    RUN(test_dct_forward_then_inverse_is_identity);
    RUN(test_dct_plan_limits);
    RUN(test_golden_hashes);
    RUN(test_dct_mutation_rate);
    RUN(test_cppn_mutation_changes_one_value_on_average);
    RUN(test_gmx_mutation_rates);
    RUN(test_dct_crossover_takes_each_component_from_a_parent);
    RUN(test_gmx_plane_crossover_keeps_sides);
    RUN(test_cppn_region_covers_nodes_uniformly);
    RUN(test_bodies_connected_argmax_in_workspace);
    RUN(test_empty_body_is_valid);
    RUN(test_level_set_keeps_the_largest_piece);
    RUN(test_cppn_complexity_limit);
    RUN(test_distance_compares_bodies);
    RUN(test_lattice_palette);
    RUN(test_text_round_trip_is_exact);
    RUN(test_parse_errors);
    RUN(test_parse_bad_tokens_quoted);
    RUN(test_capacity_is_a_status);
    RUN(test_every_material_expressed);
    RUN(test_memory_budget);
    return SUMMARY();
}
