/* tests/test_sim_model.c: the model built from a lattice (src/sim/sim_model.c): bad models are
 * statuses with messages (capacity and range errors), and the link entries of random bodies. */
#include "amorph.h"
#include "harness.h"
#include <math.h>
#include <string.h>

static am_lattice g_lat;
static am_model g_m;
static am_state g_s;

/* bad models are statuses with messages, never crashes */
static void test_model_errors(void)
{
    char err[AM_ERR_MAX];
    am_env env = am_default_env();
    CHECK(am_lattice_init(&g_lat, 3, 3, 3, AM_P(0.01), err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_ERR_EMPTY, "empty lattice accepted");
    g_lat.cell[0] = 1;
    g_lat.palette.mat[0].E = AM_P(-1);
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_ERR_RANGE && strstr(err, "E must"), "negative E: %s", err);
    g_lat.palette = am_default_palette();
    g_lat.cell[1] = (uint8_t)(g_lat.palette.count + 1);
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_ERR_RANGE, "unknown material accepted");
    g_lat.cell[1] = 1;
    env.period_steps = 0;
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_ERR_RANGE, "period 0 accepted");
    env.period_steps = 500;
    /* a cell edge outside the configuration's voxel_size range, however the lattice got it (issue
     * 31: a subnormal one gave NaN scales, a NaN cast to long in the collision grid) */
    g_lat.voxel_size = AM_PARAM_FROM_DOUBLE(1e-45);
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_ERR_RANGE && strstr(err, "voxel size"), "voxel size 1e-45: %s", err);
    g_lat.voxel_size = AM_P(100);
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_ERR_RANGE && strstr(err, "outside 1e-05..10"), "voxel size 100: %s", err);
    g_lat.voxel_size = AM_P(0.01);
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_OK, "voxel size 0.01: %s", err);
    CHECK(am_lattice_init(&g_lat, AM_MAX_DIM + 1, 1, 1, AM_P(0.01), err, sizeof err) == AM_ERR_CAPACITY, "over capacity");
}

/* the link entries of random bodies: the live ones are exactly the face pairs of the lattice,
 * each in the slots of its two voxels; x lane e joins voxels e - 1 and e, lanes 0 and nv are
 * empty, and the x lanes are nv + 1 */
static void test_link_layout(void)
{
    char err[AM_ERR_MAX];
    am_env env = am_default_env();
    am_rng r;
    am_rng_seed(&r, 7);
    for (int t = 0; t < 20; t++) {
        const int nx = 1 + (int)am_rng_below(&r, 6), ny = 1 + (int)am_rng_below(&r, 6), nz = 1 + (int)am_rng_below(&r, 6);
        CHECK(am_lattice_init(&g_lat, nx, ny, nz, AM_P(0.01), err, sizeof err) == AM_OK, "%s", err);
        for (int c = 0; c < nx * ny * nz; c++) g_lat.cell[c] = (uint8_t)(am_rng_below(&r, 3) == 0 ? 0 : 1 + am_rng_below(&r, 2));
        g_lat.cell[0] = 1;
        CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_OK, "%s", err);
        int pairs = 0;
        for (int z = 0; z < nz; z++)
            for (int y = 0; y < ny; y++)
                for (int x = 0; x < nx; x++) {
                    if (!g_lat.cell[am_lattice_index(&g_lat, x, y, z)]) continue;
                    pairs += x + 1 < nx && g_lat.cell[am_lattice_index(&g_lat, x + 1, y, z)];
                    pairs += y + 1 < ny && g_lat.cell[am_lattice_index(&g_lat, x, y + 1, z)];
                    pairs += z + 1 < nz && g_lat.cell[am_lattice_index(&g_lat, x, y, z + 1)];
                }
        int live = 0, wrong = 0;
        for (int l = 0; l < g_m.nl; l++) {
            if (!am_link_live(&g_m, l)) continue;
            live++;
            const int a = g_m.lneg[l], b = g_m.lpos[l], axis = l < g_m.axis_end[0] ? 0 : (l < g_m.axis_end[1] ? 1 : 2);
            const int step = axis == 0 ? 1 : (axis == 1 ? nx : nx * ny);
            wrong += g_m.cell[b] - g_m.cell[a] != step || g_m.slot[2 * axis][a] != l || g_m.slot[2 * axis + 1][b] != l;
            wrong += axis == 0 && (a != l - 1 || b != l);
        }
        CHECK(live == pairs && g_m.links == pairs, "body %d (%dx%dx%d): %d live entries, %d links, %d face pairs", t, nx, ny, nz, live,
              g_m.links, pairs);
        CHECK(wrong == 0, "body %d: %d entries join the wrong voxels or miss their slots", t, wrong);
        CHECK(g_m.axis_end[0] == g_m.nv + 1 && !am_link_live(&g_m, 0) && !am_link_live(&g_m, g_m.nv),
              "body %d: %d x lanes for %d voxels", t, g_m.axis_end[0], g_m.nv);
    }
}

/* am_model_validate / am_state_validate: a built model and its steps pass; a corrupted one names
 * the broken invariant */
static void test_validate(void)
{
    char err[AM_ERR_MAX];
    am_env env = am_default_env();
    CHECK(am_lattice_init(&g_lat, 3, 3, 3, AM_P(0.01), err, sizeof err) == AM_OK, "%s", err);
    for (int c = 0; c < 27; c++) g_lat.cell[c] = (uint8_t)(1 + c % 2);
    CHECK(am_model_build(&g_m, &g_lat, &env, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_model_validate(&g_m, err, sizeof err) == AM_OK, "built model fails: %s", err);
    am_state_reset(&g_m, &g_s);
    g_s.actuate = 1;
    for (int k = 0; k < 200; k++) am_step(&g_m, &g_s);
    CHECK(!g_s.diverged, "diverged");
    CHECK(am_state_validate(&g_m, &g_s, err, sizeof err) == AM_OK, "stepped state fails: %s", err);
    const am_index keep = g_m.lpos[g_m.axis_end[1]];
    g_m.lpos[g_m.axis_end[1]] = (am_index)g_m.nv;
    CHECK(am_model_validate(&g_m, err, sizeof err) == AM_ERR_RANGE && strstr(err, "link"), "link index: %s", err);
    g_m.lpos[g_m.axis_end[1]] = keep;
    const am_real mass = g_m.mass[AM_VC(&g_m, 5)];
    g_m.mass[AM_VC(&g_m, 5)] = AM_R(0);
    CHECK(am_model_validate(&g_m, err, sizeof err) == AM_ERR_RANGE && strstr(err, "mass"), "zero mass: %s", err);
    g_m.mass[AM_VC(&g_m, 5)] = mass;
    CHECK(am_model_validate(&g_m, err, sizeof err) == AM_OK, "restored model fails: %s", err);
#if !defined(AM_REAL_FIXED_POINT)
    g_s.x[1][4] = (am_real)NAN;
    CHECK(am_state_validate(&g_m, &g_s, err, sizeof err) == AM_ERR_RANGE && strstr(err, "voxel 4 position"), "NaN position: %s", err);
#endif
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    (void)test_quick; /* the harness's, unused here */
    RUN(test_model_errors);
    RUN(test_link_layout);
    RUN(test_validate);
    return SUMMARY();
}
