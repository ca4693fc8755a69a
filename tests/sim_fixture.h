/* tests/sim_fixture.h: the scene helpers the simulator's physics tests share (test_sim_step.c,
 * test_sim_collide.c): one lattice, model and state, a box filled cell by cell, a free
 * environment, the model built with a check, velocities set in SI and positions read in SI.
 * Units: SI; VOX_L is the voxel edge of every scene. Include after harness.h. */
#ifndef AMORPH_TESTS_SIM_FIXTURE_H
#define AMORPH_TESTS_SIM_FIXTURE_H

#include <math.h>
#include <stdint.h>
#include "amorph.h"
#include "harness.h"

#define VOX_L 0.01 /* m, the voxel edge of every test scene */

static am_lattice g_lat;
/* model values in SI and back (exact casts in the float and double builds; docs/fixed.md) */
#define SI(v, dim) am_to_si(&g_m, (v), AM_DIM_##dim)
#define MU(v, dim) am_from_si(&g_m, (v), AM_DIM_##dim)
static am_model g_m;
static am_state g_s;
static char g_err[AM_ERR_MAX];

static inline int lattice_box(int nx, int ny, int nz)
{
    am_status st = am_lattice_init(&g_lat, nx, ny, nz, (am_param)VOX_L, g_err, (int)sizeof g_err);
    CHECK(st == AM_OK, "am_lattice_init: %s", g_err);
    return st == AM_OK;
}

/* fills the box [x0, x1] x [y0, y1] x [z0, z1] (inclusive) with cell value v */
static inline void fill(int x0, int x1, int y0, int y1, int z0, int z1, uint8_t v)
{
    for (int z = z0; z <= z1; z++)
        for (int y = y0; y <= y1; y++)
            for (int x = x0; x <= x1; x++) g_lat.cell[am_lattice_index(&g_lat, x, y, z)] = v;
}

/* an environment with no gravity, no floor, no collisions and the body at rest height */
static inline am_env env_free(void)
{
    am_env e = am_default_env();
    e.gravity = AM_P(0);
    e.floor = 0;
    e.collisions = 0;
    e.lift = AM_P(0);
    e.temp_base = AM_P(0);
    return e;
}

static inline int build(const am_env* e)
{
    am_status st = am_model_build(&g_m, &g_lat, e, g_err, (int)sizeof g_err);
    CHECK(st == AM_OK, "am_model_build: %s", g_err);
    return st == AM_OK;
}

/* sets voxel i's linear velocity (m/s), consistently in p and v */
static inline void set_vel(am_state* s, int i, double vx, double vy, double vz)
{
    double m = SI(g_m.mass[AM_VC(&g_m, i)], MASS);
    double v[3] = {vx, vy, vz};
    for (int a = 0; a < 3; a++) {
        s->p[a][i] = MU(m * v[a], MOMENTUM);
        s->v[a][i] = MU(v[a], VELOCITY);
    }
}

/* the centre of voxel i along k, m: the rest lattice plus the state's displacement */
static inline double pos(const am_state* s, int k, int i) { return SI(g_m.x0[k][i], LENGTH) + SI(s->x[k][i], LENGTH); }

static inline double dist(const am_state* s, int a, int b)
{
    double d2 = 0;
    for (int k = 0; k < 3; k++) {
        double d = pos(s, k, a) - pos(s, k, b);
        d2 += d * d;
    }
    return sqrt(d2);
}

/* n steps, or `quick` under AMORPH_TEST_QUICK */
static inline long qsteps(long n, long quick) { return test_quick() ? quick : n; }

#endif
