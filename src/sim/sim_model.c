/* Building the immutable model from a lattice, and resetting a state to rest.
 *
 * Voxels are numbered in lattice cell order (x fastest, then y, then z); links are grouped by
 * axis (all x-links, then y, then z), each group in cell order of its negative voxel, so the link
 * loop can use a fixed axis permutation per group. Every constant a step needs (masses, inverse
 * inertias, beam stiffnesses, damping coefficients, contact stiffness) is computed here once. */
#include "sim_internal.h"
#include "amorph/base.h"

#include <string.h>

_Static_assert(AM_MAX_MATERIALS * AM_MAX_MATERIALS <= 256, "am_model.lpair holds a pair of materials in a uint8_t on a board");

double am_unit(const am_model* m, int dim)
{
    const double L = m->unit_len, M = m->unit_mass, T = m->unit_time;
    switch (dim) {
    case AM_DIM_LENGTH: return L;
    case AM_DIM_TIME: return T;
    case AM_DIM_MASS: return M;
    case AM_DIM_VELOCITY: return L / T;
    case AM_DIM_ACCEL: return L / (T * T);
    case AM_DIM_MOMENTUM: return M * L / T;
    case AM_DIM_ANGMOM: return M * L * L / T;
    case AM_DIM_FORCE: return M * L / (T * T);
    case AM_DIM_MOMENT: case AM_DIM_ENERGY: return M * L * L / (T * T);
    case AM_DIM_ANGVEL: return 1.0 / T;
    case AM_DIM_INERTIA: return M * L * L;
    case AM_DIM_STIFFNESS: return M / (T * T);
    case AM_DIM_PRESSURE: return M / (L * T * T);
    case AM_DIM_DAMPING: return M / T;
    default: return 1.0;
    }
}

double am_to_si(const am_model* m, am_real v, int dim) { return AM_TO_DOUBLE(v) * am_unit(m, dim); }
am_real am_from_si(const am_model* m, double v, int dim) { return AM_FROM_DOUBLE(v / am_unit(m, dim)); }

double am_dt_si(const am_model* m, am_param dt_frac)
{
#if defined(AM_REAL_FIXED_POINT)
    return dt_frac * am_to_si(m, m->dt_rec, AM_DIM_TIME);
#else
    return (double)(dt_frac * m->dt_rec);
#endif
}

am_env am_default_env(void)
{
    am_env e;
    memset(&e, 0, sizeof e);
    e.gravity = AM_P(9.80665);
    e.floor = 1;
    e.collisions = 1;
    e.cte_mode = AM_CTE_VOLUMETRIC;
    e.temp_base = AM_P(0);
    e.temp_amplitude = AM_P(30);
    e.period_steps = 500;
    e.period_s = AM_P(0);
    e.dt_frac = AM_P(0.9);
    e.lift = AM_P(0);
    e.zeta_internal_scale = AM_P(1);
    e.zeta_global_scale = AM_P(1);
    return e;
}

static am_status check_material(const am_material* mt, int k, char* err, int errsz)
{
    if (!(mt->E > AM_P(0)) || !am_param_finite(mt->E))
        return am_fail(err, errsz, AM_ERR_RANGE, "material %d (%s): E must be a positive number of Pa", k + 1, mt->name);
    if (!(mt->density > AM_P(0)) || !am_param_finite(mt->density))
        return am_fail(err, errsz, AM_ERR_RANGE, "material %d (%s): density must be positive", k + 1, mt->name);
    if (!(mt->poisson >= AM_P(0) && mt->poisson < AM_P(0.5)))
        return am_fail(err, errsz, AM_ERR_RANGE, "material %d (%s): Poisson ratio must be in [0, 0.5)", k + 1, mt->name);
    if (!am_param_finite(mt->cte) || !am_param_finite(mt->phase))
        return am_fail(err, errsz, AM_ERR_RANGE, "material %d (%s): CTE and phase must be finite", k + 1, mt->name);
    if (!(mt->mu_static >= AM_P(0)) || !(mt->mu_kinetic >= AM_P(0)) || !am_param_finite(mt->mu_static) || !am_param_finite(mt->mu_kinetic))
        return am_fail(err, errsz, AM_ERR_RANGE, "material %d (%s): friction coefficients must be >= 0", k + 1, mt->name);
    if (!(mt->zeta_internal >= AM_P(0)) || !(mt->zeta_global >= AM_P(0)) || !(mt->zeta_collision >= AM_P(0)) ||
        !am_param_finite(mt->zeta_internal) || !am_param_finite(mt->zeta_global) || !am_param_finite(mt->zeta_collision))
        return am_fail(err, errsz, AM_ERR_RANGE, "material %d (%s): damping ratios must be >= 0", k + 1, mt->name);
    return AM_OK;
}

static am_status check_env(const am_env* e, char* err, int errsz)
{
    if (!(e->gravity >= AM_P(0)) || !am_param_finite(e->gravity))
        return am_fail(err, errsz, AM_ERR_RANGE, "gravity must be >= 0 m/s^2");
    if (e->period_steps < 2) return am_fail(err, errsz, AM_ERR_RANGE, "period_steps must be >= 2");
    if (!(e->period_s >= AM_P(0)) || !am_param_finite(e->period_s)) return am_fail(err, errsz, AM_ERR_RANGE, "period_s must be >= 0 s");
    if (!(e->dt_frac > AM_P(0)) || !am_param_finite(e->dt_frac))
        return am_fail(err, errsz, AM_ERR_RANGE, "dt_frac must be positive");
    if (!am_param_finite(e->temp_base) || !am_param_finite(e->temp_amplitude) || !am_param_finite(e->lift) || e->lift < AM_P(0))
        return am_fail(err, errsz, AM_ERR_RANGE, "temperatures and lift must be finite (lift >= 0)");
    if (!(e->zeta_internal_scale >= AM_P(0)) || !(e->zeta_global_scale >= AM_P(0)))
        return am_fail(err, errsz, AM_ERR_RANGE, "damping scales must be >= 0");
    if (e->cte_mode != AM_CTE_VOLUMETRIC && e->cte_mode != AM_CTE_LINEAR)
        return am_fail(err, errsz, AM_ERR_RANGE, "unknown CTE convention %d", e->cte_mode);
    return AM_OK;
}

void am_layers_clear(am_layers* l)
{
    l->has_phase = 0;
    l->has_bc = 0;
    l->has_stiffness = 0;
}

am_status am_model_build(am_model* m, const am_lattice* lat, const am_env* env, char* err, int errsz)
{
    return am_model_build_layers(m, lat, env, NULL, err, errsz);
}

/* the elastic modulus of filled cell c, Pa: the layers' stiffness when they have one, else its
 * material's (the same value, so a robot without the layer builds bit for bit as before) */
static am_param cell_E(const am_lattice* lat, const am_layers* ly, int c)
{
    return ly && ly->has_stiffness ? ly->stiffness[c] : lat->palette.mat[lat->cell[c] - 1].E;
}

/* the layers' values of the filled cells: finite phases and forces, positive stiffnesses; the board
 * takes none of them */
static am_status check_layers(const am_lattice* lat, const am_layers* ly, int* any_force, char* err, int errsz)
{
    const int ncell = lat->nx * lat->ny * lat->nz;
    *any_force = 0;
    for (int c = 0; c < ncell; c++) {
        if (!lat->cell[c]) continue;
        if (ly->has_phase && !am_param_finite(ly->phase[c]))
            return am_fail(err, errsz, AM_ERR_RANGE, "cell %d: its phase must be a finite number of periods", c);
        if (ly->has_stiffness && !(ly->stiffness[c] > AM_P(0) && am_param_finite(ly->stiffness[c])))
            return am_fail(err, errsz, AM_ERR_RANGE, "cell %d: its stiffness must be a positive number of Pa", c);
        if (!ly->has_bc) continue;
        for (int k = 0; k < 3; k++) {
            if (!am_param_finite(ly->force[k][c]))
                return am_fail(err, errsz, AM_ERR_RANGE, "cell %d: its external force must be finite", c);
            const double d = (double)ly->force[k][c], most = AM_MAX_DISPLACE * (double)lat->voxel_size;
            if (ly->fixed[c] && !(d <= most && d >= -most))
                return am_fail(err, errsz, AM_ERR_RANGE, "cell %d: its prescribed displacement %g m is more than %d voxel edges", c,
                               (double)ly->force[k][c], AM_MAX_DISPLACE);
            *any_force |= ly->force[k][c] != AM_P(0);
        }
    }
#if defined(AM_COMPACT)
    if (ly->has_phase || ly->has_stiffness || *any_force)
        return am_fail(err, errsz, AM_ERR_CAPACITY, "%s: the board profile has no room for them (desktop profile only)",
                       ly->has_phase ? "a phase per voxel" : ly->has_stiffness ? "a stiffness per voxel" : "external forces or displacements per voxel");
#endif
    return AM_OK;
}

#if !defined(AM_COMPACT)
/* voxel i's phase class (am_model.vphase_class): -1 for a voxel of phase 0 or of a material that
 * does not actuate (cte 0: its scale is 1 at any phase, its material's); else the class of its
 * material and phase, added when new (open addressing in class_hash, at most half full) */
static int phase_class(am_model* m, int i)
{
    const int k = m->mat[i], cap = 2 * AM_MAX_VOXELS;
    if (m->vphase[i] == AM_R(0) || m->mat_cte[k] == AM_R(0)) return -1;
    uint64_t bits = 0;
    memcpy(&bits, &m->vphase[i], sizeof m->vphase[i]);
    const uint64_t key = (bits ^ (uint64_t)k << 56) * UINT64_C(0x9E3779B97F4A7C15);
    int h = (int)((key >> 32) % (uint64_t)cap);
    for (; m->class_hash[h] >= 0; h = h + 1 == cap ? 0 : h + 1) {
        const int c = m->class_hash[h];
        if (m->class_mat[c] == k && m->class_phase[c] == m->vphase[i]) return c;
    }
    const int c = m->nphase++;
    m->class_hash[h] = (am_index)c;
    m->class_mat[c] = (am_index)k;
    m->class_phase[c] = m->vphase[i];
    return c;
}
#endif

am_status am_model_build_layers(am_model* m, const am_lattice* lat, const am_env* env, const am_layers* layers, char* err,
                                int errsz)
{
    am_status st;
    if (lat->nx < 1 || lat->ny < 1 || lat->nz < 1 || lat->nx > AM_MAX_DIM || lat->ny > AM_MAX_DIM || lat->nz > AM_MAX_DIM)
        return am_fail(err, errsz, AM_ERR_CAPACITY, "lattice %d x %d x %d is outside 1..%d per side", lat->nx, lat->ny, lat->nz, AM_MAX_DIM);
    if (lat->palette.count < 1 || lat->palette.count > AM_MAX_MATERIALS)
        return am_fail(err, errsz, AM_ERR_CAPACITY, "palette of %d materials (1..%d)", lat->palette.count, AM_MAX_MATERIALS);
    if (!(lat->voxel_size >= AM_P(AM_VOXEL_SIZE_MIN) && lat->voxel_size <= AM_P(AM_VOXEL_SIZE_MAX)))
        return am_fail(err, errsz, AM_ERR_RANGE, "voxel size %g m is outside %g..%g", (double)lat->voxel_size, AM_VOXEL_SIZE_MIN, AM_VOXEL_SIZE_MAX);
    if ((st = check_env(env, err, errsz)) != AM_OK) return st;
    for (int k = 0; k < lat->palette.count; k++)
        if ((st = check_material(&lat->palette.mat[k], k, err, errsz)) != AM_OK) return st;

    int any_force = 0;
    if (layers && (st = check_layers(lat, layers, &any_force, err, errsz)) != AM_OK) return st;
    const int nx = lat->nx, ny = lat->ny, nz = lat->nz, ncell = nx * ny * nz;
    /* units (docs/fixed.md): SI in the float and double builds; in the fixed-point build the voxel
     * edge, the mass of the densest voxel of the palette and the time in which the stiffest
     * material's (or voxel's, with a stiffness layer) link moves that mass by one edge, so stiffnesses,
     * masses and sound speeds are O(1) */
    m->unit_len = m->unit_mass = m->unit_time = 1.0;
#if defined(AM_REAL_FIXED_POINT)
    {
        double rho = 0, E = 0, L = lat->voxel_size;
        uint8_t used[AM_MAX_MATERIALS + 1] = {0};
        for (int c = 0; c < ncell; c++) used[lat->cell[c] <= AM_MAX_MATERIALS ? lat->cell[c] : 0] = 1;
        for (int k = 0; k < lat->palette.count; k++) {
            if (!used[k + 1]) continue;
            if (lat->palette.mat[k].density > rho) rho = lat->palette.mat[k].density;
            if (lat->palette.mat[k].E > E) E = lat->palette.mat[k].E;
        }
        if (layers && layers->has_stiffness) /* the stiffest voxel instead (check_layers: all positive) */
            for (int c = 0, first = 1; c < ncell; c++)
                if (lat->cell[c] && lat->cell[c] <= lat->palette.count && (first || layers->stiffness[c] > E))
                    E = layers->stiffness[c], first = 0;
        if (!(rho > 0)) rho = lat->palette.mat[0].density, E = lat->palette.mat[0].E; /* no voxel: reported below */
        m->unit_len = L;
        m->unit_mass = rho * L * L * L;
        m->unit_time = sqrt(m->unit_mass / (E * L));
        double tmax = fabs(env->temp_base) + fabs(env->temp_amplitude);
        if (!(tmax < 100.0) || !(env->gravity * m->unit_time * m->unit_time / L < 1.0) || !(env->lift / L < 50.0))
            return am_fail(err, errsz, AM_ERR_RANGE, "temperatures (|base| + amplitude < 100 degrees), gravity or lift outside the fixed-point range");
        for (int k = 0; k < lat->palette.count; k++)
            if (used[k + 1] && (!(fabs(lat->palette.mat[k].cte) * tmax < 8.0) ||
                                (!(layers && layers->has_stiffness) && !(lat->palette.mat[k].E / E > 1e-5)) ||
                                !(lat->palette.mat[k].density / rho > 1e-3)))
                return am_fail(err, errsz, AM_ERR_RANGE, "material %d (%s): CTE, modulus or density ratio outside the fixed-point range",
                               k + 1, lat->palette.mat[k].name);
        for (int c = 0; layers && layers->has_stiffness && c < ncell; c++)
            if (lat->cell[c] && !(layers->stiffness[c] / E > 1e-5))
                return am_fail(err, errsz, AM_ERR_RANGE, "cell %d: its stiffness %g Pa is below 1e-5 of the stiffest voxel's (the fixed-point range)",
                               c, (double)layers->stiffness[c]);
    }
#endif
    const double uP = am_unit(m, AM_DIM_PRESSURE), uRho = m->unit_mass / (m->unit_len * m->unit_len * m->unit_len);
    (void)uP;
    (void)uRho;
    const am_real L = AM_PV(lat->voxel_size, m->unit_len);
    m->gravity = AM_PV(env->gravity, am_unit(m, AM_DIM_ACCEL));
    m->temp_base = AM_PV(env->temp_base, 1.0);
    m->temp_amplitude = AM_PV(env->temp_amplitude, 1.0);
    m->env = *env;
    m->palette = lat->palette;
    m->nx = nx;
    m->ny = ny;
    m->nz = nz;
    m->L = L;

    /* voxels, in cell order; vid maps cell -> voxel */
    am_index* vid = m->cell_voxel;
    int nv = 0, kmin = nz;
    for (int c = 0; c < ncell; c++) {
        int id = lat->cell[c];
        vid[c] = -1;
        if (!id) continue;
        if (id > lat->palette.count)
            return am_fail(err, errsz, AM_ERR_RANGE, "cell %d holds material %d, the palette has %d", c, id, lat->palette.count);
        AM_ASSERT(nv < AM_MAX_VOXELS); /* nv <= the cells of an AM_MAX_DIM lattice */
        vid[c] = (am_index)nv;
        m->cell[nv] = (am_index)c;
        m->mat[nv] = (am_matid)(id - 1);
        nv++;
        int z = c / (nx * ny);
        if (z < kmin) kmin = z;
    }
    if (nv == 0) return am_fail(err, errsz, AM_ERR_EMPTY, "the lattice has no voxel");
    m->nv = nv;

    for (int i = 0; i < nv; i++) {
        const am_material* mt = &lat->palette.mat[m->mat[i]];
        int c = m->cell[i], x = c % nx, y = (c / nx) % ny, z = c / (nx * ny);
        m->x0[0][i] = AM_MUL(AM_INT(x) + AM_R(0.5), L);
        m->x0[1][i] = AM_MUL(AM_INT(y) + AM_R(0.5), L);
        m->x0[2][i] = AM_MUL(AM_INT(z - kmin) + AM_R(0.5), L) + AM_PV(env->lift, m->unit_len);
        const int vc = AM_VC(m, i); /* the voxel's constants (once per material in the board profile) */
        am_real mass = AM_MUL(AM_PV(mt->density, uRho), AM_MUL(L, AM_MUL(L, L)));
        am_real inertia = am_sim_inertia(mass, L);
        m->mass[vc] = mass;
        m->fixed[i] = (uint8_t)(mt->fixed != 0 || (layers && layers->has_bc && layers->fixed[c]));
        m->inv_mass[vc] = m->fixed[i] ? AM_R(0) : AM_DIV(AM_R(1), mass);
        m->inv_inertia[vc] = m->fixed[i] ? AM_R(0) : AM_DIV(AM_R(1), inertia);
        am_real EL = AM_MUL(AM_PV(cell_E(lat, layers, c), uP), L), EL3 = AM_MUL(EL, AM_MUL(L, L));
        am_real zg = AM_MUL(AM_PV(mt->zeta_global, 1.0), AM_PV(env->zeta_global_scale, 1.0));
        m->c_glob_t[vc] = AM_MUL(AM_MUL(AM_R(2), zg), am_sqrt(AM_MUL(mass, EL)));
        m->c_glob_r[vc] = AM_MUL(AM_MUL(AM_R(2), zg), am_sqrt(AM_MUL(inertia, EL3)));
        m->k_floor[vc] = AM_MUL(AM_R(2), EL);
        m->c_col[vc] = AM_MUL(AM_MUL(AM_R(2), AM_PV(mt->zeta_collision, 1.0)), am_sqrt(AM_MUL(mass, EL)));
        m->mu_s[vc] = AM_PV(mt->mu_static, 1.0);
        m->mu_k[vc] = AM_PV(mt->mu_kinetic, 1.0);
    }

    /* links grouped by axis; along x the lanes (amorph/sim.h): lane i + 1 from voxel i to i + 1,
     * empty when that is not its +x neighbour (the constants of a link all the same, never a force),
     * lanes 0 and nv from voxel 0 to itself and always empty. The slots are filled on the way. */
    int nl = 0, nlinks = 0;
    /* slots: +x,-x,+y,-y,+z,-z, the voxel is the negative end of its + links; -1 (then the zero
     * link nl) where it has no link */
    for (int d = 0; d < 6; d++)
        for (int i = 0; i < nv; i++) m->slot[d][i] = -1;
    for (int axis = 0; axis < 3; axis++) {
        for (int i = axis == 0 ? -1 : 0; i < nv; i++) {
            int j = -1;
            if (i >= 0) {
                int c = m->cell[i], x = c % nx, y = (c / nx) % ny, z = c / (nx * ny);
                int nc;
                if (axis == 0) nc = x + 1 < nx ? c + 1 : -1;
                else if (axis == 1) nc = y + 1 < ny ? c + nx : -1;
                else nc = z + 1 < nz ? c + nx * ny : -1;
                AM_ASSERT(nc < ncell);
                if (nc >= 0) j = vid[nc];
            }
            const int live = j >= 0;
            if (axis != 0 && !live) continue;
            if (nl >= AM_MAX_LINKS) return am_fail(err, errsz, AM_ERR_CAPACITY, "more than %d links", AM_MAX_LINKS);
            const int edge = axis == 0 && (i < 0 || i + 1 >= nv); /* lane 0 or nv */
            const int a = edge ? 0 : i; /* the negative end */
            if (axis == 0) j = edge ? 0 : i + 1;
            AM_ASSERT(a >= 0 && a < nv && j >= 0 && j < nv && (axis == 0 || a < j)); /* a link's ends are voxels, + after - */
            if (live) {
                m->slot[2 * axis][a] = (am_index)nl;
                m->slot[2 * axis + 1][j] = (am_index)nl;
                nlinks++;
            }
            const am_material* ma = &lat->palette.mat[m->mat[a]];
            const am_material* mb = &lat->palette.mat[m->mat[j]];
            const am_real Ea = AM_PV(cell_E(lat, layers, m->cell[a]), uP), Eb = AM_PV(cell_E(lat, layers, m->cell[j]), uP);
            am_real E = AM_DIV(AM_MUL(AM_R(2), AM_MUL(Ea, Eb)), Ea + Eb); /* halves in series */
            am_real nu = AM_MUL(AM_R(0.5), AM_PV(ma->poisson, 1.0) + AM_PV(mb->poisson, 1.0));
            am_real L2 = AM_MUL(L, L), L3 = AM_MUL(L2, L);
            m->lneg[nl] = (am_index)a;
            m->lpos[nl] = (am_index)j;
            m->lpair[nl] = (am_pair)(m->mat[a] * AM_MAX_MATERIALS + m->mat[j]);
            const int lc = AM_LC(m, nl); /* the link's constants (once per pair of materials on a board) */
            AM_ASSERT(lc >= 0 && lc < AM_LC_CAP);
            m->k_ax[lc] = AM_MUL(E, L2);
            m->a2[lc] = AM_DIV(AM_MUL(E, L3), AM_MUL(AM_R(12), AM_R(1) + nu));
            m->b1[lc] = AM_MUL(E, L);
            m->b2[lc] = AM_MUL(AM_R(0.5), AM_MUL(E, L2));
            m->b3[lc] = AM_DIV(AM_MUL(E, L3), AM_R(6));
            /* internal damping: the element's stiffness applied to its rates of deformation, times
             * the retardation time beta = zeta sqrt(2 mu / (E L)) (Kelvin-Voigt; 2 mu is the voxel
             * mass for two equal voxels: the reference simulator's convention). For the small-angle
             * element that is a dashpot c_t = beta E L on the relative velocity of the link's
             * midpoint and c_r = beta E L^3 / 12 = c_t L^2 / 12 on the relative spin, which the step
             * derives from c_t (docs/physics.md, Damping) */
            am_real mu = am_sim_reduced_mass(m->mass[AM_VC(m, a)], m->mass[AM_VC(m, j)]);
            am_real zi = AM_MUL(AM_MUL(AM_R(0.5), AM_PV(ma->zeta_internal, 1.0) + AM_PV(mb->zeta_internal, 1.0)),
                                AM_PV(env->zeta_internal_scale, 1.0));
            m->c_t[lc] = AM_MUL(zi, am_sqrt(AM_MUL(AM_MUL(AM_R(2), mu), AM_MUL(E, L))));
            nl++;
        }
        m->axis_end[axis] = nl;
    }
    m->nl = nl;
    m->links = nlinks;

    for (int d = 0; d < 6; d++) /* a missing link: the zero link */
        for (int i = 0; i < nv; i++)
            if (m->slot[d][i] < 0) m->slot[d][i] = (am_index)nl;
    for (int i = 0; i < nv; i++) {
        int links = 0;
        for (int d = 0; d < 6; d++) links += m->slot[d][i] != nl;
        m->surface[i] = (uint8_t)(links < 6);
    }

    /* actuation per material, and the largest scale it can reach */
    am_real tmax = am_fabs(m->temp_base) + am_fabs(m->temp_amplitude);
    m->max_scale = AM_R(1);
    m->any_cte = 0;
    for (int k = 0; k < lat->palette.count; k++) {
        m->mat_cte[k] = AM_PV(lat->palette.mat[k].cte, 1.0);
        m->mat_phase[k] = AM_PV(lat->palette.mat[k].phase, 1.0);
        if (m->mat_cte[k] != AM_R(0)) m->any_cte = 1;
        m->max_scale = am_max(m->max_scale, am_sim_scale(env->cte_mode, m->mat_cte[k], tmax));
        m->max_scale = am_max(m->max_scale, am_sim_scale(env->cte_mode, m->mat_cte[k], -tmax));
    }
    m->coll_range = AM_MUL(AM_MUL(AM_R(1.25), m->max_scale), L);

    /* the layers: a phase per voxel (and then a rest length per link), forces per voxel */
    m->voxel_phase = layers != NULL && layers->has_phase;
    m->any_force = any_force;
#if !defined(AM_COMPACT)
    m->vphase_any = 0;
    m->nphase = 0;
    for (int h = 0; m->voxel_phase && h < 2 * AM_MAX_VOXELS; h++) m->class_hash[h] = -1;
    for (int i = 0; i < nv; i++) {
        m->vphase[i] = AM_R(0);
        if (m->voxel_phase) m->vphase[i] = AM_PV(2.0 * 3.14159265358979323846 * (double)layers->phase[m->cell[i]], 1.0);
        m->vphase_any |= m->vphase[i] != AM_R(0);
        m->vphase_class[i] = (am_index)phase_class(m, i);
        /* a clamped voxel takes no force: its slot holds the displacement a region prescribes (a
         * voxel clamped by its material alone: none) */
        const int bc_fixed = any_force && layers->fixed[m->cell[i]];
        for (int k = 0; k < 3; k++) {
            m->force[k][i] = AM_R(0);
            if (any_force && !m->fixed[i]) m->force[k][i] = AM_PV(layers->force[k][m->cell[i]], am_unit(m, AM_DIM_FORCE));
            if (bc_fixed) m->force[k][i] = AM_PV(layers->force[k][m->cell[i]], m->unit_len);
        }
    }
#endif

    /* divergence bound: ten times the fastest sound speed of the palette */
    am_real c2 = AM_R(0);
#if defined(AM_REAL_FIXED_POINT)
    /* the materials of the body only, and at most 10 model units (ten sound speeds of the stiffest
     * material), so that the bound's square stays in the range */
    for (int i = 0; i < nv; i++) {
        const am_material* mt = &lat->palette.mat[m->mat[i]];
        c2 = am_max(c2, AM_DIV(AM_PV(cell_E(lat, layers, m->cell[i]), uP), AM_PV(mt->density, uRho)));
    }
    m->max_speed = am_min(AM_MUL(AM_R(10), am_sqrt(c2)), AM_R(10));
#else
    for (int k = 0; k < lat->palette.count; k++)
        c2 = am_max(c2, AM_DIV(AM_PV(lat->palette.mat[k].E, uP), AM_PV(lat->palette.mat[k].density, uRho)));
    for (int i = 0; layers && layers->has_stiffness && i < nv; i++) /* and the voxels' own moduli */
        c2 = am_max(c2, AM_DIV(AM_PV(layers->stiffness[m->cell[i]], uP), AM_PV(lat->palette.mat[m->mat[i]].density, uRho)));
    m->max_speed = AM_MUL(AM_R(10), am_sqrt(c2));
#endif
    m->dt_rec = am_dt_analytic(m);
    if (env->period_s > AM_P(0)) {
        /* the period in seconds as steps of the model's step: refused where am_period_steps would
         * clamp it, else its value kept in the model's env for every state at the model's step */
        const double dt = am_dt_si(m, env->dt_frac), k = (double)env->period_s / dt;
        if (!(k >= 1.5 && k <= 1e7)) /* rounded: period_steps' range, 2 to 10^7 */
            return am_fail(err, errsz, AM_ERR_RANGE, "period_s = %g s is %.3g steps of %.4g s (a period takes 2 to 10^7 steps)",
                           (double)env->period_s, k, dt);
        m->env.period_steps = am_period_steps(m, env, AM_MUL(AM_PV(env->dt_frac, 1.0), m->dt_rec));
    }
#if defined(AM_CHECKS)
    am_check_model(m);
#endif
    return AM_OK;
}

/* The period's one owner: a run's actuation period in steps is decided here and nowhere else.
 * am_model_build keeps it for the model's step in m->env.period_steps, am_state_reset copies that
 * into the state, a run at another step (am_dt_search's trials, am_evaluate's searched step) asks
 * again with its step; everything else reads s->period_steps or m->env.period_steps. A VXA file's
 * period in seconds (am_vxa_period_steps) and the programs take the same rounding from
 * am_period_steps_si. */
int am_period_steps(const am_model* m, const am_env* env, am_real dt)
{
    if (!(env->period_s > AM_P(0))) return env->period_steps;
    return am_period_steps_si((double)env->period_s, am_to_si(m, dt, AM_DIM_TIME));
}

int am_period_steps_si(double period_s, double dt_s)
{
    const double k = period_s / dt_s;
    return !(k >= 1.5) ? 2 : k >= 1e7 ? 10000000 : (int)floor(k + 0.5);
}

long am_steps_at(const am_model* m, const am_state* s, long n)
{
    const am_real ref = AM_MUL(AM_PV(AM_P(AM_REF_DT_FRAC), 1.0), m->dt_rec);
    if (n <= 0 || s->dt == ref) return n;
    const double k = (double)n * AM_TO_DOUBLE(ref) / AM_TO_DOUBLE(s->dt);
    return k < 1 ? 1 : k >= 4e18 ? (long)4e18 : (long)floor(k + 0.5);
}

am_real am_dt_analytic(const am_model* m)
{
    am_real wmax = AM_R(0);
    for (int l = 0; l < m->nl; l++) {
        if (!am_link_live(m, l)) continue;
        am_real a1 = AM_DIV(m->k_ax[AM_LC(m, l)], m->L); /* E L */
        am_real mm = am_min(m->mass[AM_VC(m, m->lneg[l])], m->mass[AM_VC(m, m->lpos[l])]);
        wmax = am_max(wmax, AM_DIV(a1, mm));
    }
    for (int i = 0; i < m->nv; i++) /* a lone voxel on the floor: its contact spring */
        wmax = am_max(wmax, AM_DIV(AM_MUL(AM_R(0.5), m->k_floor[AM_VC(m, i)]), m->mass[AM_VC(m, i)]));
    return AM_DIV(AM_R(1), AM_MUL(AM_MUL(AM_R(2), AM_PI), am_sqrt(wmax)));
}

void am_state_reset(const am_model* m, am_state* s)
{
    const int nv = m->nv, nl = m->nl;
    s->step = 0;
    s->dt = AM_MUL(AM_PV(m->env.dt_frac, 1.0), m->dt_rec);
    s->settle_steps = 0;
    s->settle_dt = s->dt;
    s->period_steps = m->env.period_steps; /* am_period_steps at the model's step (am_model_build) */
    s->actuate = 0;
    s->actuation_step0 = 0;
#if !defined(AM_COMPACT)
    s->controlled = 0;
    s->vox_plain = 0;
    memset(s->rest_own, 0, sizeof s->rest_own[0] * (size_t)nv);
#endif
    s->diverged = 0;
    s->diverge_step = -1;
    s->pairs_overflow = 0;
    s->rebuilds = 0;
    s->npairs = -1; /* the first step builds the collision list */
    s->max_npairs = 0;
    s->scales_valid = 0; /* the first step sets scales and rest lengths */
    s->damp_dt = AM_R(0);   /* and the damping for dt */
    s->glob_scale = AM_R(1);
    memset(s->x_rem, 0, sizeof s->x_rem);
#if defined(AM_REAL_FIXED_POINT)
    memset(s->p_rem, 0, sizeof s->p_rem);
    memset(s->h_rem, 0, sizeof s->h_rem);
#endif
    for (int k = 0; k < AM_MAX_MATERIALS; k++) s->mat_scale[k] = AM_R(1);
    for (int k = 0; k < AM_MAX_MATERIALS; k++) s->mat_scale_rate[k] = AM_R(0);
    for (int k = 0; k < AM_MAX_MATERIALS * AM_MAX_MATERIALS; k++) {
        s->pair_rest[k] = m->L;
        s->pair_inv_rest[k] = AM_DIV(AM_R(1), m->L);
    }
    for (int i = 0; i < nv; i++) {
        for (int c = 0; c < 3; c++) {
            s->x[c][i] = AM_R(0); /* displacements from x0 */
            s->p[c][i] = s->h[c][i] = AM_R(0);
#if defined(AM_COMPACT)
            s->mc[c][i] = AM_R(0);
#else
            s->v[c][i] = s->w[c][i] = AM_R(0);
#endif
            s->fext[c][i] = s->mext[c][i] = s->fc[c][i] = AM_R(0);
#if !defined(AM_COMPACT)
            /* the boundary conditions: a free voxel's force, a clamped one's prescribed displacement */
            if (m->any_force && !m->fixed[i]) s->fext[c][i] = m->force[c][i];
            if (m->any_force && m->fixed[i]) s->x[c][i] = m->force[c][i];
#endif
            s->xref[c][i] = AM_R(0);
        }
        s->q[0][i] = AM_R(1);
        s->q[1][i] = s->q[2][i] = s->q[3][i] = AM_R(0);
        s->s[i] = AM_R(1);
#if !defined(AM_COMPACT)
        s->s_rate[i] = AM_R(0);
#endif
        /* voxels start stuck where they touch the floor */
        s->contact[i] = (uint8_t)(m->env.floor && m->x0[2][i] <= AM_MUL(AM_R(0.5), m->L) ? 1 : 0);
    }
    for (int l = 0; l <= nl; l++) {
        s->large[l] = 0;
#if !defined(AM_COMPACT)
        s->strain[l] = AM_R(0);
        for (int c = 0; c < 3; c++) s->fn[c][l] = s->mn[c][l] = s->mp[c][l] = AM_R(0);
#endif
    }
}
