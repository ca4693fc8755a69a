/* One time step of the voxel beam lattice (docs/physics.md section 7).
 *
 * Order: actuation (per-material temperature -> voxel scales -> rest lengths, once per pair of
 * materials), contact forces (self-collision) and link forces, both from the state at the start of
 * the step (the floor is per voxel and done during integration because its friction state machine
 * needs the voxel's total force), then semi-implicit Euler per voxel: the totals (each voxel
 * gathers its links), the floor and friction, the links' damping correction, and one update of
 * rotation and translation.
 *
 * Links write their forces into per-link arrays; each voxel then gathers from its six slots in a
 * fixed order (+x, -x, +y, -y, +z, -z; a missing link points at the zero link nl). No voxel sum
 * depends on how links are ordered or how work is split, and the floating-point sums are the same
 * on every platform. The board profile (AM_COMPACT) has no room for per-link results: there each
 * chunk of links adds its results to its voxels' totals straight away, in an order that makes
 * every sum the desktop's gather, operation for operation (add_links). */
#include "sim_internal.h"
#include "amorph/base.h"

#include <stddef.h>

/* Arrays of the state and the model are handed to the hot loops as restrict-qualified function
 * parameters (rows of [3][AM_MAX_VOXELS] and [3][AM_MAX_LINKS + 1] arrays as pointers to rows):
 * only then does the compiler know that the loads (gathers through lneg/lpos and the slots)
 * cannot see the stores, and vectorise the loops. */
typedef am_real vox_row[AM_MAX_VOXELS];
typedef am_real link_row[AM_MAX_LINKS + 1];

/* the entry of a per-link (LCI) and per-voxel (VCI) constant inside the loops below, which have
 * lpair and mat at hand (amorph/sim.h: AM_LC, AM_VC) */
#if defined(AM_COMPACT)
#define LCI(l) lpair[l]
#define VCI(i) mat[i]
#else
#define LCI(l) (l)
#define VCI(i) (i)
#endif

/* the rounding remainders of the integrator (AM_ACC, error diffusion) are extra parameters of the
 * voxel passes in the fixed-point build only; in the others AM_ACC drops its remainder argument */
#if defined(AM_REAL_FIXED_POINT)
#define REM_PARAM(name) , vox_row* restrict name
#define REM_ARG(rem) , (rem)
#else
#define REM_PARAM(name)
#define REM_ARG(rem)
#endif

/* Links are evaluated LINK_CHUNK at a time. The large-angle frame costs about as much again as
 * the small-angle element, and large links come in clusters that last: a chunk none of whose
 * links was large at the last step runs the small-angle loop alone, and again with the
 * large-angle frame only if one of its links turns large now. Both loops compute a link the same
 * way, so the results do not depend on the chunking. */
#define LINK_CHUNK 32

/* The link passes read the velocities and spins of the voxels (rows v and w) and write their
 * results (rows fn, mn, mp and strain, at index l - o). On the desktop v and w are the state's and
 * the results go to the per-link arrays (o = 0); on a board v and w are the momenta p and h, scaled
 * where read by the voxel's 1/m and 1/I (the values the desktop keeps), and the results go to a
 * chunk's buffer (o = the chunk's first link). */
/* the rate of change of voxel i's linear scale (thermal expansion): a link's rest length changes at
 * half_L times the sum of its voxels' (kept per voxel on the desktop, per material on a board) */
#if defined(AM_COMPACT)
#define SRATE(i) srate[vmat[i]]
#define SRATE_ARG(m, s) (s)->mat_scale_rate
#else
#define SRATE(i) srate[i]
#define SRATE_ARG(m, s) (s)->s_rate
#endif

#if defined(AM_COMPACT)
typedef am_real out_row[LINK_CHUNK];
#define KIN_PARAM , const am_real* restrict vim, const am_real* restrict wim, const am_matid* restrict vmat
#define KIN_ARG(m) , (m)->inv_mass, (m)->inv_inertia, (m)->mat
#define VEL3(r, i) v3(AM_MUL(r[0][i], vim[vmat[i]]), AM_MUL(r[1][i], vim[vmat[i]]), AM_MUL(r[2][i], vim[vmat[i]]))
#define SPIN3(r, i) v3(AM_MUL(r[0][i], wim[vmat[i]]), AM_MUL(r[1][i], wim[vmat[i]]), AM_MUL(r[2][i], wim[vmat[i]]))
#else
typedef link_row out_row;
#define KIN_PARAM
#define KIN_ARG(m)
#define VEL3(r, i) v3(r[0][i], r[1][i], r[2][i])
#define SPIN3(r, i) v3(r[0][i], r[1][i], r[2][i])
#endif

static void voxel_scales(int nv, const am_matid* restrict mat, const am_real* restrict mat_scale, am_real* restrict scale)
{
    for (int i = 0; i < nv; i++) scale[i] = mat_scale[mat[i]];
}

/* the actuation's angular frequency 2 pi / (period_steps dt), 1/s */
static am_real actuation_omega(const am_state* s)
{
#if defined(AM_REAL_FIXED_POINT)
    return AM_RATIO((int64_t)AM_R(6.283185307179586477), (int64_t)s->dt * s->period_steps);
#else
    return AM_DIV(AM_MUL(AM_R(2), AM_PI), AM_MUL_INT(s->dt, s->period_steps));
#endif
}

/* a link's rest length is the mean of its voxels' edges: one per pair of materials, from the
 * materials' scales */
static void pair_rest_lengths(const am_model* m, am_state* s)
{
    const am_real half_L = AM_MUL(AM_R(0.5), m->L);
    for (int i = 0; i < m->palette.count; i++)
        for (int j = 0; j < m->palette.count; j++) {
            const am_real r = AM_MUL(half_L, s->mat_scale[i] + s->mat_scale[j]);
            s->pair_rest[i * AM_MAX_MATERIALS + j] = r;
            s->pair_inv_rest[i * AM_MAX_MATERIALS + j] = AM_DIV(AM_R(1), r);
        }
}

#if !defined(AM_COMPACT)
/* the actuation's argument at the state's step, radians (0 while it is off) */
static inline am_real actuation_arg0(const am_state* s)
{
    if (!s->actuate) return AM_R(0);
    long ph = (s->step - s->actuation_step0) % s->period_steps; /* exact phase in steps */
#if defined(AM_REAL_FIXED_POINT)
    return AM_RATIO((int64_t)AM_R(6.283185307179586477) * ph, (int64_t)s->period_steps * AM_FIX_ONE);
#else
    return AM_DIV(AM_MUL(AM_MUL(AM_R(2), AM_PI), AM_R(ph)), AM_R(s->period_steps));
#endif
}

/* the scale and its rate of a voxel of material k at the sinusoid's argument arg (angular
 * frequency wt) */
static inline void sinusoid_at(const am_model* m, int k, am_real arg, am_real wt, am_real* sc_out, am_real* rate_out)
{
    const am_env* e = &m->env;
    am_real T = m->temp_base + AM_MUL(m->temp_amplitude, am_sin(arg));
    am_real sc = m->mat_cte[k] == AM_R(0) ? AM_R(1) : am_sim_scale(e->cte_mode, m->mat_cte[k], T);
    *sc_out = sc;
    *rate_out = m->mat_cte[k] == AM_R(0) ? AM_R(0)
        : AM_MUL(am_sim_scale_rate(e->cte_mode, m->mat_cte[k], T, AM_MUL(m->temp_amplitude, am_cos(arg)), sc), wt);
}

/* voxel i's, with its own phase, at the actuation's argument arg0 */
static inline void phase_sinusoid(const am_model* m, int k, am_real phase, am_real arg0, am_real wt, am_real* sc_out, am_real* rate_out)
{
    sinusoid_at(m, k, (arg0 + m->mat_phase[k]) + phase, wt, sc_out, rate_out);
}
static inline void voxel_sinusoid(const am_model* m, int i, am_real arg0, am_real wt, am_real* sc_out, am_real* rate_out)
{
    phase_sinusoid(m, m->mat[i], m->vphase[i], arg0, wt, sc_out, rate_out);
}

/* a voxel's of material k and phase 0 */
static inline void material_sinusoid(const am_model* m, int k, am_real arg0, am_real wt, am_real* sc_out, am_real* rate_out)
{
    sinusoid_at(m, k, arg0 + m->mat_phase[k], wt, sc_out, rate_out);
}

/* voxel i's scale while the actuation is off: its material's at temp_base */
static inline am_real held_scale(const am_model* m, int k)
{
    return m->mat_cte[k] == AM_R(0) ? AM_R(1) : am_sim_scale(m->env.cte_mode, m->mat_cte[k], m->temp_base);
}

void am_actuation_values(const am_model* m, const am_state* s, double* scale, double* rate)
{
    /* as the step finds them: a voxel of phase 0 its material's, found once per material */
    const am_real arg0 = actuation_arg0(s), wt = actuation_omega(s);
    am_real msc[AM_MAX_MATERIALS], mrt[AM_MAX_MATERIALS];
    for (int k = 0; k < m->palette.count; k++) {
        msc[k] = held_scale(m, k), mrt[k] = AM_R(0);
        if (s->actuate) material_sinusoid(m, k, arg0, wt, &msc[k], &mrt[k]);
    }
    const double unit_time = am_unit(m, AM_DIM_TIME);
    for (int i = 0; i < m->nv; i++) {
        am_real sc = msc[m->mat[i]], r = mrt[m->mat[i]];
        if (s->actuate && m->vphase[i] != AM_R(0)) voxel_sinusoid(m, i, arg0, wt, &sc, &r);
        scale[i] = AM_TO_DOUBLE(sc);
        if (rate) rate[i] = AM_TO_DOUBLE(r) / unit_time;
    }
}

enum { OWN_NOW = 1, OWN_WAS = 2, OWN_MOVED = 4 }; /* am_state.rest_own */
/* 1: a voxel whose links' rest lengths are looked at: it moved, or took or left a scale of its own */
static inline int own_visit(int f) { return ((f >> 2) | ((f >> 1) ^ f)) & 1; }

/* link l's rest length: its pair's when both ends have their materials' scales, else its own
 * entry (the same operations on the same values) */
static inline void link_rest(const am_model* m, am_state* s, int l, am_real half_L)
{
    const int a = m->lneg[l], b = m->lpos[l], own0 = AM_MAX_MATERIALS * AM_MAX_MATERIALS;
    if (s->s[a] == s->mat_scale[m->mat[a]] && s->s[b] == s->mat_scale[m->mat[b]]) {
        s->rest_at[l] = m->lpair[l];
        return;
    }
    const am_real r = AM_MUL(half_L, s->s[a] + s->s[b]);
    s->rest_at[l] = (am_pair)(own0 + l);
    s->pair_rest[own0 + l] = r;
    s->pair_inv_rest[own0 + l] = AM_DIV(AM_R(1), r);
}

/* one voxel's scale and rate: its material's, its phase class's (actuate), or a controller's
 * (controlled) */
static inline void voxel_values(const am_model* m, const am_state* s, int i, int actuate, int controlled, const am_real* mrate,
                                am_real* sc, am_real* rate)
{
    *sc = s->mat_scale[m->mat[i]], *rate = mrate[m->mat[i]];
    if (actuate && m->vphase_class[i] >= 0) *sc = s->class_scale[m->vphase_class[i]], *rate = s->class_rate[m->vphase_class[i]];
    if (controlled && s->ctl_on[i]) *sc = s->ctl_scale[i], *rate = s->ctl_rate[i];
}

/* a robot with a phase per voxel (model voxel_phase): each voxel's scale and rate from its
 * material's argument plus its own phase (once per phase class), or a controller's (ctl_on), then
 * the rest lengths of the links that need their own. With every voxel phase 0 and no controller
 * these are the per-material path's values, operation for operation. */
static void voxel_actuation(const am_model* m, am_state* s)
{
    int changed = !s->scales_valid;
    const int fresh = !s->scales_valid; /* (am_state_reset cleared rest_own) */
    const int actuate = s->actuate, controlled = s->controlled;
    const am_real arg0 = actuation_arg0(s), wt = actuate ? actuation_omega(s) : AM_R(0);
    /* a voxel of phase 0 has its material's values: found once per material (the same
     * operations: the argument plus a zero phase is the argument); held at temp_base (relaxation)
     * every voxel of a material has its material's scale, and nothing changes from step to step */
    am_real mrate[AM_MAX_MATERIALS];
    for (int k = 0; k < m->palette.count; k++) {
        am_real sc = held_scale(m, k);
        mrate[k] = AM_R(0);
        if (s->actuate) {
            material_sinusoid(m, k, arg0, wt, &sc, &mrate[k]);
            changed |= mrate[k] != s->mat_scale_rate[k];
            s->mat_scale_rate[k] = mrate[k];
        }
        changed |= sc != s->mat_scale[k];
        s->mat_scale[k] = sc;
    }
    const am_real half_L = AM_MUL(AM_R(0.5), m->L);
    /* a phase class's values (voxel_sinusoid's operations on its material and phase), once for all
     * its voxels */
    for (int c = 0; actuate && c < m->nphase; c++)
        phase_sinusoid(m, m->class_mat[c], m->class_phase[c], arg0, wt, &s->class_scale[c], &s->class_rate[c]);
    if (m->vphase_any) {
        /* phases: most voxels move at every step, and every link is looked at once */
        for (int i = 0; i < m->nv; i++) {
            am_real sc, rate;
            voxel_values(m, s, i, actuate, controlled, mrate, &sc, &rate);
            changed |= (sc != s->s[i]) | (rate != s->s_rate[i]);
            s->s[i] = sc;
            s->s_rate[i] = rate;
        }
        if (!changed) return;
        s->scales_valid = 1;
        pair_rest_lengths(m, s);
        for (int l = 0; l < m->nl; l++) link_rest(m, s, l, half_L);
        return;
    }
    /* no phases and no controller's values, now or at the last step (stepping a robot under a
     * controller that leaves it to its sinusoid): every voxel has its material's values and every
     * link its pair's rest length, as on the per-material path */
    if (!fresh && s->vox_plain && !s->controlled) {
        if (!changed) return;
        voxel_scales(m->nv, m->mat, s->mat_scale, s->s);
        voxel_scales(m->nv, m->mat, mrate, s->s_rate);
        pair_rest_lengths(m, s);
        return;
    }
    /* a controller's values: each voxel's, and whether its scale is its material's, was at the
     * last step, and moved (rest_own: which links to look at) */
    int acc = 0;
    for (int i = 0; i < m->nv; i++) {
        am_real sc, rate;
        voxel_values(m, s, i, actuate, controlled, mrate, &sc, &rate);
        const int moved = fresh | (sc != s->s[i]);
        changed |= moved | (rate != s->s_rate[i]);
        s->s[i] = sc;
        s->s_rate[i] = rate;
        const int f = (sc != s->mat_scale[m->mat[i]]) * OWN_NOW | (s->rest_own[i] & OWN_NOW) * OWN_WAS | moved * OWN_MOVED;
        s->rest_own[i] = (uint8_t)f;
        acc |= f;
    }
    s->vox_plain = !s->controlled; /* with no controller every voxel has its material's values */
    if (!changed) return;
    s->scales_valid = 1;
    pair_rest_lengths(m, s);
    if (fresh) /* a state just reset: every link at its pair's entry until its voxels say otherwise */
        for (int l = 0; l < m->nl; l++) s->rest_at[l] = m->lpair[l];
    if (!(acc & (OWN_NOW | OWN_WAS))) return; /* and every link still is */
    /* a link is looked at when an end of it takes or leaves a scale of its own, or moves */
    int visits = 0;
    for (int i = 0; i < m->nv; i++) visits += own_visit(s->rest_own[i]);
    if (visits > m->nv / 4) { /* many: each link once */
        for (int l = 0; l < m->nl; l++) link_rest(m, s, l, half_L);
        return;
    }
    for (int i = 0; i < m->nv; i++) {
        if (!own_visit(s->rest_own[i])) continue; /* still, and as it was */
        /* its links: the x lanes i and i + 1 (lane l joins voxels l - 1 and l; the two edge lanes 0
         * and nv join voxel 0 to itself), and its y and z links by slot; a link both of whose ends
         * are looked at, once, from its - end */
        const int at[8] = {i, i + 1, 0, m->nv, m->slot[2][i], m->slot[3][i], m->slot[4][i], m->slot[5][i]};
        for (int k = 0; k < 8; k++) {
            const int l = at[k];
            if (l >= m->nl || (m->lneg[l] != i && m->lpos[l] != i)) continue;
            if (m->lneg[l] != i && own_visit(s->rest_own[m->lneg[l]])) continue;
            link_rest(m, s, l, half_L);
        }
    }
}
#endif

/* per-material temperature and linear scale, voxel scales, rest lengths per material pair */
static void actuation(const am_model* m, am_state* s)
{
#if !defined(AM_COMPACT)
    if (m->voxel_phase) {
        voxel_actuation(m, s);
        return;
    }
#endif
    const am_env* e = &m->env;
    int changed = !s->scales_valid;
    const am_real wt = actuation_omega(s); /* d(phase)/dt */
    for (int k = 0; k < m->palette.count; k++) {
        am_real T = m->temp_base, dT = AM_R(0);
        if (s->actuate) {
            long ph = (s->step - s->actuation_step0) % s->period_steps; /* exact phase in steps */
#if defined(AM_REAL_FIXED_POINT)
            am_real arg = AM_RATIO((int64_t)AM_R(6.283185307179586477) * ph, (int64_t)s->period_steps * AM_FIX_ONE) + m->mat_phase[k];
#else
            am_real arg = AM_DIV(AM_MUL(AM_MUL(AM_R(2), AM_PI), AM_R(ph)), AM_R(s->period_steps)) + m->mat_phase[k];
#endif
            T += AM_MUL(m->temp_amplitude, am_sin(arg));
            dT = AM_MUL(m->temp_amplitude, am_cos(arg)); /* dT / d(phase) */
        }
        am_real sc = m->mat_cte[k] == AM_R(0) ? AM_R(1) : am_sim_scale(e->cte_mode, m->mat_cte[k], T);
        changed |= sc != s->mat_scale[k];
        s->mat_scale[k] = sc;
        const am_real rate = m->mat_cte[k] == AM_R(0) ? AM_R(0) : AM_MUL(am_sim_scale_rate(e->cte_mode, m->mat_cte[k], T, dT, sc), wt);
        changed |= rate != s->mat_scale_rate[k];
        s->mat_scale_rate[k] = rate;
    }
    /* voxel scales and rest lengths only when a material's scale moved (never, for a passive
     * body or during relaxation) */
    if (!changed) return;
    s->scales_valid = 1;
    voxel_scales(m->nv, m->mat, s->mat_scale, s->s);
#if !defined(AM_COMPACT)
    voxel_scales(m->nv, m->mat, s->mat_scale_rate, s->s_rate);
#endif
    pair_rest_lengths(m, s);
}

/* the constants of one link and its current rest length */
typedef struct link_par { am_real k_ax, a2, b1, b2, b3, c_t, c_r, rest, inv_rest, rest_rate; } link_par;
/* what a link hands to its two voxels: force on the negative end (the positive end gets -F),
 * moments on both ends, and the axial strain */
typedef struct link_out { vec3 F, M, Mp; am_real strain; } link_out;

/* the large-angle switch with hysteresis (docs/physics.md section 2), from the small-angle frame */
static inline int large_switch(const link_kin* k, int was_large, am_real inv_rest)
{
    am_real lateral = am_fabs(k->p.y) + am_fabs(k->p.z);
    am_real axial = am_fabs(AM_R(1) - AM_MUL(k->p.x, inv_rest));
    /* no branch: the small-link loop must vectorise */
    am_real lat_lim = was_large ? AM_LA_OFF_LAT : AM_LA_ON_LAT, ax_lim = was_large ? AM_LA_OFF_AX : AM_LA_ON_AX;
    return (lateral > AM_MUL(lat_lim, k->p.x)) | (axial > ax_lim) | !(k->p.x > AM_R(0));
}

/* internal damping of a link of world offset d, acting at its midpoint against the rate of
 * deformation: the relative velocity of the two ends there less what a rigid rotation would give
 * (c_t), and the relative spin (c_r); va, vb, wa, wb are the velocities and spins of the negative
 * and positive voxels. Fd is the force on the negative end, Md its moment. The forces derive from
 * the dissipation function (c_t |rate|^2 + c_r |wb - wa|^2) / 2: their power is minus twice it, so
 * they only ever remove energy, and a rigid motion is not damped. */
static inline void link_damping(vec3 d, am_real c_t, am_real c_r, vec3 va, vec3 vb, vec3 wa, vec3 wb, vec3* Fd, vec3* Md)
{
    const vec3 half_d = v3_scale(d, AM_R(0.5));
    const vec3 rate = v3_sub(v3_sub(vb, va), v3_cross(v3_add(wa, wb), half_d));
    *Fd = v3_scale(rate, c_t);
    *Md = v3_add(v3_cross(half_d, *Fd), v3_scale(v3_sub(wb, wa), c_r));
}

/* the Euler-Bernoulli frame element in the local frame plus internal damping, turned to world
 * axes; va, vb, wa, wb are the velocities and spins of the negative and positive voxels */
static inline link_out link_element(const link_kin* k, int large, int axis, link_par c, vec3 va, vec3 vb, vec3 wa, vec3 wb)
{
    /* only the axial term goes through the material law (linear here); shear, bending and
     * torsion are linear */
    const am_real b1 = c.b1, b2 = c.b2, b3 = c.b3;
    link_out o;
    o.strain = AM_MUL(k->p.x - c.rest, c.inv_rest);
    /* the axial damping acts on the mechanical extension: the rate of the rest length (thermal
     * expansion) is taken out of the relative velocity's axial part, along the link's local axis */
    vec3 F = v3(AM_MUL(c.k_ax, o.strain) - AM_MUL(c.c_t, c.rest_rate),
                AM_MUL(b1, k->p.y) - AM_MUL(b2, k->t1.z + k->t2.z),
                AM_MUL(b1, k->p.z) + AM_MUL(b2, k->t1.y + k->t2.y));
    vec3 M = v3(AM_MUL(c.a2, k->t2.x - k->t1.x),
                -AM_MUL(b2, k->p.z) - AM_MUL(b3, AM_MUL(AM_R(2), k->t1.y) + k->t2.y),
                AM_MUL(b2, k->p.y) - AM_MUL(b3, AM_MUL(AM_R(2), k->t1.z) + k->t2.z));
#if defined(AM_REAL_FIXED_POINT)
    if (large) { /* nothing to vectorise in the fixed-point build: a branch, same values */
        F = q_rot_inv(k->rot, F);
        M = q_rot_inv(k->rot, M);
    }
#else
    F = v3_sel(large, q_rot_inv(k->rot, F), F);
    M = v3_sel(large, q_rot_inv(k->rot, M), M);
#endif
    F = q_rot(k->qn, from_local(F, axis));
    M = q_rot(k->qn, from_local(M, axis));

    vec3 Fd, Md;
    link_damping(k->d, c.c_t, c.c_r, va, vb, wa, wb, &Fd, &Md);
    o.F = v3_add(F, Fd);
    o.M = v3_add(M, Md);

    /* the positive end's moment from the balance of the element, so that the link exerts no
     * net torque (angular momentum is conserved exactly); at rest length this is the
     * textbook M_pos */
    o.Mp = v3_sub(v3_cross(k->d, o.F), o.M);
    return o;
}

/* bound on the axial strain of any link: no physical run stretches a link to six times its rest
 * length or through its neighbour */
#define AM_DIVERGE_STRAIN AM_R(5)

/* The two passes below are near-copies on purpose. They write their results out line by line:
 * with the stores in a helper function (restrict-qualified or not) gcc 12 no longer proves that
 * they cannot alias the gathers and leaves the loops scalar (five times the instructions). And one
 * function for both, told which by a constant argument, is neither inlined nor vectorised by gcc
 * 12 (it clones it per axis and keeps the branches); only forced inlining would, and under forced
 * inlining gcc 12 fuses multiplies and adds (see check-fma in the Makefile). */

/* the world offset x_pos - x_neg of the ends a, b: the rest lattice's L along the axis plus the
 * difference of the displacements (amorph/sim.h: x holds displacements) */
#define LINK_OFFSET(x, a, b)                                                                                  \
    v3(axis == 0 ? (x[0][b] - x[0][a]) + L : x[0][b] - x[0][a], axis == 1 ? (x[1][b] - x[1][a]) + L : x[1][b] - x[1][a], \
       axis == 2 ? (x[2][b] - x[2][a]) + L : x[2][b] - x[2][a])
/* the two ends of entry l, and whether it is a link: x lane l joins voxels l - 1 and l (read
 * contiguously: the axis is a constant in each of link_forces' copies), and is a link when voxel
 * l's -x slot holds it (amorph/sim.h) */
#define LINK_ENDS(l)                                                                                          \
    const int a = axis == 0 ? (l) - 1 : lneg[l], b = axis == 0 ? (l) : lpos[l];                                \
    const int live = axis != 0 || slot_mx[l] == (l)
/* the results of entry l at j: zeros for an empty lane (what the zero link nl holds); the strain
 * check for links only */
#define STORE_FORCES(j_)                                                                                       \
    const int j = (j_);                                                                                        \
    fn[0][j] = live ? r.F.x : AM_R(0); fn[1][j] = live ? r.F.y : AM_R(0); fn[2][j] = live ? r.F.z : AM_R(0);      \
    mn[0][j] = live ? r.M.x : AM_R(0); mn[1][j] = live ? r.M.y : AM_R(0); mn[2][j] = live ? r.M.z : AM_R(0);      \
    mp[0][j] = live ? r.Mp.x : AM_R(0); mp[1][j] = live ? r.Mp.y : AM_R(0); mp[2][j] = live ? r.Mp.z : AM_R(0)
#define STORE_RESULTS(j_)                                                                                      \
    STORE_FORCES(j_);                                                                                          \
    strain[j] = live ? r.strain : AM_R(0);                                                                      \
    bad |= live & !(am_fabs(r.strain) <= AM_DIVERGE_STRAIN)

/* the links [l0, l1), all along one axis and none of them large at the last step, as small-angle
 * elements. No branch: the compiler vectorises it. Returns bit 0 when some link is strained
 * beyond AM_DIVERGE_STRAIN (or NaN), bit 1 when some link's switch turns on (then its results are
 * wrong and the caller runs full_pass on the range). */
static int small_pass(int l0, int l1, int axis, am_real L, const am_index* restrict lneg, const am_index* restrict lpos,
                      const vox_row* restrict x, const vox_row* restrict q, const vox_row* restrict v,
                      const vox_row* restrict w, const am_real* restrict k_ax, const am_real* restrict a2,
                      const am_real* restrict b1, const am_real* restrict b2, const am_real* restrict b3,
                      const am_real* restrict c_t, am_real kr, const am_pair* restrict lpair,
                      const am_real* restrict pair_rest, const am_real* restrict pair_inv_rest,
                      const am_real* restrict srate, am_real half_L KIN_PARAM,
                      const am_index* restrict slot_mx, out_row* restrict fn, out_row* restrict mn, out_row* restrict mp,
                      am_real* restrict strain, int o)
{
    int bad = 0, any_large = 0;
    for (int l = l0; l < l1; l++) {
        LINK_ENDS(l);
        link_kin k;
        link_kin_from(qt(q[0][a], q[1][a], q[2][a], q[3][a]), qt(q[0][b], q[1][b], q[2][b], q[3][b]),
                      LINK_OFFSET(x, a, b), axis, &k);
        const am_real rest = pair_rest[lpair[l]], inv_rest = pair_inv_rest[lpair[l]];
        any_large |= live & large_switch(&k, 0, inv_rest);
        link_par c = {k_ax[LCI(l)], a2[LCI(l)], b1[LCI(l)], b2[LCI(l)], b3[LCI(l)], c_t[LCI(l)], AM_MUL(c_t[LCI(l)], kr), rest, inv_rest,
                      AM_MUL(half_L, SRATE(a) + SRATE(b))};
        link_out r = link_element(&k, 0, axis, c, VEL3(v, a), VEL3(v, b), SPIN3(w, a), SPIN3(w, b));
        STORE_RESULTS(l - o);
    }
    return bad | any_large << 1;
}

/* the links [l0, l1), all along one axis: the large-angle switch with its hysteresis, and each
 * link with the frame its switch says (both frames are computed, one is kept: no branch, the
 * compiler vectorises it). Returns 1 when some link is strained beyond AM_DIVERGE_STRAIN (or NaN). */
static int full_pass(int l0, int l1, int axis, am_real L, const am_index* restrict lneg, const am_index* restrict lpos,
                     const vox_row* restrict x, const vox_row* restrict q, const vox_row* restrict v,
                     const vox_row* restrict w, const am_real* restrict k_ax, const am_real* restrict a2,
                     const am_real* restrict b1, const am_real* restrict b2, const am_real* restrict b3,
                     const am_real* restrict c_t, am_real kr, const am_pair* restrict lpair,
                     const am_real* restrict pair_rest, const am_real* restrict pair_inv_rest,
                     const am_real* restrict srate, am_real half_L KIN_PARAM,
                     const am_index* restrict slot_mx, am_flag* restrict large, out_row* restrict fn,
                     out_row* restrict mn, out_row* restrict mp, am_real* restrict strain, int o)
{
    int bad = 0;
    for (int l = l0; l < l1; l++) {
        LINK_ENDS(l);
        link_kin k;
        link_kin_from(qt(q[0][a], q[1][a], q[2][a], q[3][a]), qt(q[0][b], q[1][b], q[2][b], q[3][b]),
                      LINK_OFFSET(x, a, b), axis, &k);
        const am_real rest = pair_rest[lpair[l]], inv_rest = pair_inv_rest[lpair[l]];
        int lg = live & large_switch(&k, large[l], inv_rest);
#if defined(AM_REAL_FIXED_POINT)
        /* integer roots and 64-bit divisions do not vectorise: the large-angle frame only where it
         * is on (the same values as the select) */
        if (lg) link_kin_large(&k, 1);
#else
        link_kin_large(&k, lg);
#endif
        link_par c = {k_ax[LCI(l)], a2[LCI(l)], b1[LCI(l)], b2[LCI(l)], b3[LCI(l)], c_t[LCI(l)], AM_MUL(c_t[LCI(l)], kr), rest, inv_rest,
                      AM_MUL(half_L, SRATE(a) + SRATE(b))};
        link_out r = link_element(&k, lg, axis, c, VEL3(v, a), VEL3(v, b), SPIN3(w, a), SPIN3(w, b));
        large[l] = (am_flag)lg;
        STORE_RESULTS(l - o);
    }
    return bad;
}

/* The damping correction of the links [l0, l1), all along one axis (docs/physics.md, Damping): each
 * link's damping impulse for the velocity increments dv and spin increments dw of its ends (the
 * step's accelerations times alpha dt^2), with the link's offset at the start of the step; the
 * impulse on the negative end and its moment, and the positive end's moment from the balance, as
 * in link_element. On the desktop dv and dw are the rows v and w (voxel_totals puts them there);
 * on a board the totals fc and mc, scaled where read by the voxel's 1/m or 1/I and by sc. No
 * branch: the compiler vectorises it. */
#if defined(AM_COMPACT)
#define DAMP_PARAM , const am_real* restrict vim, const am_real* restrict wim, const am_matid* restrict vmat, am_real sc
#define DAMP_ARG(m, s) , (m)->inv_mass, (m)->inv_inertia, (m)->mat, (s)->damp_scale
#define DVEL3(r, i) v3(AM_MUL(AM_MUL(r[0][i], vim[vmat[i]]), sc), AM_MUL(AM_MUL(r[1][i], vim[vmat[i]]), sc), \
                       AM_MUL(AM_MUL(r[2][i], vim[vmat[i]]), sc))
#define DSPIN3(r, i) v3(AM_MUL(AM_MUL(r[0][i], wim[vmat[i]]), sc), AM_MUL(AM_MUL(r[1][i], wim[vmat[i]]), sc), \
                        AM_MUL(AM_MUL(r[2][i], wim[vmat[i]]), sc))
#else
#define DAMP_PARAM
#define DAMP_ARG(m, s)
#define DVEL3(r, i) VEL3(r, i)
#define DSPIN3(r, i) SPIN3(r, i)
#endif
static inline void damp_pass(int l0, int l1, int axis, am_real L, const am_index* restrict lneg, const am_index* restrict lpos,
                      const vox_row* restrict x, const vox_row* restrict dv, const vox_row* restrict dw,
                      const am_real* restrict c_t, am_real kr, const am_pair* restrict lpair DAMP_PARAM,
                      const am_index* restrict slot_mx, out_row* restrict fn, out_row* restrict mn, out_row* restrict mp, int o)
{
    (void)lpair; /* read through LCI in the board profile only */
    for (int l = l0; l < l1; l++) {
        LINK_ENDS(l);
        const vec3 d = LINK_OFFSET(x, a, b);
        link_out r;
        link_damping(d, c_t[LCI(l)], AM_MUL(c_t[LCI(l)], kr), DVEL3(dv, a), DVEL3(dv, b), DSPIN3(dw, a), DSPIN3(dw, b), &r.F, &r.M);
        r.Mp = v3_sub(v3_cross(d, r.F), r.M);
        STORE_FORCES(l - o);
    }
}

#if defined(AM_COMPACT)
/* The links [c0, c1) of one axis into their voxels' totals f and mt, last link first. Along an
 * axis links are numbered by their negative voxel, and voxels by cell, so voxel i's + link
 * (i, i + axis) comes after its - link (i - axis, i): taken from the last, each voxel receives its
 * + link before its - link, and the axes come in order x, y, z. That is the order of the desktop's
 * gathers (voxel_totals, and voxel_update for the damping correction), so every total is the same sum; the zeros the gather adds for
 * missing links are added there too. */
static void add_links(int c0, int c1, const am_index* restrict lneg, const am_index* restrict lpos,
                      const out_row* restrict fn, const out_row* restrict mn, const out_row* restrict mp,
                      vox_row* restrict f, vox_row* restrict mt)
{
    for (int l = c1 - 1; l >= c0; l--) {
        const int a = lneg[l], b = lpos[l], j = l - c0;
        for (int c = 0; c < 3; c++) {
            f[c][a] += fn[c][j];
            mt[c][a] += mn[c][j];
            f[c][b] -= fn[c][j];
            mt[c][b] += mp[c][j];
        }
    }
}
#endif

/* forces and moments of the links [l0, l1), all along one axis, chunk by chunk: the small-angle
 * loop for a chunk none of whose links was large at the last step and none turns large now, else
 * the full one. On the desktop into the per-link arrays; on a board into a chunk's buffer, added
 * to the voxels' totals (s->fc, s->mc) straight away, the last chunk first (add_links). Returns 1
 * when some link is strained beyond AM_DIVERGE_STRAIN (or NaN). */
static int link_forces(const am_model* m, am_state* s, int l0, int l1, int axis)
{
    const vox_row *x = (const vox_row*)s->x, *q = (const vox_row*)s->q;
#if defined(AM_COMPACT)
    const vox_row *v = (const vox_row*)s->p, *w = (const vox_row*)s->h;
    out_row fn[3], mn[3], mp[3];
    am_real strain[LINK_CHUNK];
    const int backward = 1;
#else
    const vox_row *v = (const vox_row*)s->v, *w = (const vox_row*)s->w;
    link_row *fn = s->fn, *mn = s->mn, *mp = s->mp;
    am_real* strain = s->strain;
    const int backward = 0;
#endif
    /* where each link finds its rest length: its pair of materials', or its own (voxel_phase) */
#if defined(AM_COMPACT)
    const am_pair* rest_at = m->lpair;
#else
    const am_pair* rest_at = m->voxel_phase ? s->rest_at : m->lpair;
#endif
    const int chunks = (l1 - l0 + LINK_CHUNK - 1) / LINK_CHUNK;
    int bad = 0;
    for (int k = 0; k < chunks; k++) {
        const int c0 = l0 + LINK_CHUNK * (backward ? chunks - 1 - k : k);
        const int c1 = l1 - c0 < LINK_CHUNK ? l1 : c0 + LINK_CHUNK;
        const int o = backward ? c0 : 0; /* results of link l at l - o */
        int was_large = 0, r = 2;
        for (int l = c0; l < c1; l++) was_large |= s->large[l];
        if (!was_large)
            r = small_pass(c0, c1, axis, m->L, m->lneg, m->lpos, x, q, v, w, m->k_ax, m->a2, m->b1, m->b2, m->b3,
                           s->damp_t, s->damp_kr, rest_at, s->pair_rest, s->pair_inv_rest, SRATE_ARG(m, s), AM_MUL(AM_R(0.5), m->L) KIN_ARG(m), m->slot[1], fn, mn, mp, strain, o);
        if (r & 2)
            r = full_pass(c0, c1, axis, m->L, m->lneg, m->lpos, x, q, v, w, m->k_ax, m->a2, m->b1, m->b2, m->b3,
                          s->damp_t, s->damp_kr, rest_at, s->pair_rest, s->pair_inv_rest, SRATE_ARG(m, s), AM_MUL(AM_R(0.5), m->L) KIN_ARG(m), m->slot[1], s->large, fn, mn, mp,
                          strain, o);
        bad |= r & 1;
#if defined(AM_COMPACT)
        add_links(c0, c1, m->lneg, m->lpos, (const out_row*)fn, (const out_row*)mn, (const out_row*)mp, s->fc, s->mc);
#endif
    }
    return bad;
}

/* the damping correction of the links [l0, l1), all along one axis: on the desktop into the
 * per-link arrays (voxel_update gathers them into the momenta); on a board chunk by chunk, the
 * last chunk first, added to the momenta p and h straight away (add_links: the same sums) */
static void damp_forces(const am_model* m, am_state* s, int l0, int l1, int axis)
{
#if defined(AM_COMPACT)
    const vox_row *dv = (const vox_row*)s->fc, *dw = (const vox_row*)s->mc;
    out_row fn[3], mn[3], mp[3];
    const int chunks = (l1 - l0 + LINK_CHUNK - 1) / LINK_CHUNK;
    for (int k = chunks - 1; k >= 0; k--) {
        const int c0 = l0 + LINK_CHUNK * k, c1 = l1 - c0 < LINK_CHUNK ? l1 : c0 + LINK_CHUNK;
        damp_pass(c0, c1, axis, m->L, m->lneg, m->lpos, (const vox_row*)s->x, dv, dw, s->damp_t, s->damp_kr, m->lpair DAMP_ARG(m, s),
                  m->slot[1], fn, mn, mp, c0);
        add_links(c0, c1, m->lneg, m->lpos, (const out_row*)fn, (const out_row*)mn, (const out_row*)mp, s->p, s->h);
    }
#else
    /* per axis, so that each call's axis is a constant (gcc then vectorises the copies) */
    if (axis == 0)
        damp_pass(l0, l1, 0, m->L, m->lneg, m->lpos, (const vox_row*)s->x, (const vox_row*)s->v, (const vox_row*)s->w, s->damp_t,
                  s->damp_kr, m->lpair DAMP_ARG(m, s), m->slot[1], s->fn, s->mn, s->mp, 0);
    else if (axis == 1)
        damp_pass(l0, l1, 1, m->L, m->lneg, m->lpos, (const vox_row*)s->x, (const vox_row*)s->v, (const vox_row*)s->w, s->damp_t,
                  s->damp_kr, m->lpair DAMP_ARG(m, s), m->slot[1], s->fn, s->mn, s->mp, 0);
    else
        damp_pass(l0, l1, 2, m->L, m->lneg, m->lpos, (const vox_row*)s->x, (const vox_row*)s->v, (const vox_row*)s->w, s->damp_t,
                  s->damp_kr, m->lpair DAMP_ARG(m, s), m->slot[1], s->fn, s->mn, s->mp, 0);
#endif
}

/* the floor's penetration of voxel i: half its current edge less its height (z = x0 + displacement) */
#define FLOOR_PEN(scale, L, z0, z) (AM_MUL(AM_MUL(AM_R(0.5), (scale)), (L)) - (z0) - (z))

/* floor contact of voxel i (docs/physics.md, Gravity, floor, friction). F is the voxel's total force
 * without the floor. Adds the normal force (spring plus collision damping, never pulling) and
 * friction, the seed's static/kinetic model, which only ever resists: every decision is taken on
 * friction's own impulse, never on the elastic forces, and in one step the floor's horizontal
 * impulse never exceeds mu_s N dt (mu_k N dt when that is larger), N the contact's spring force.
 * Returns 1 when the voxel ends the step at rest in the plane (stuck, or sliding to a stop): then the
 * caller zeroes its horizontal force and momentum, an impulse of -(p_h + F_h dt), which the tests below
 * have bounded. */
static int floor_contact(const am_model* m, am_state* s, int i, vec3* F)
{
    const am_real pen = FLOOR_PEN(s->s[i], m->L, m->x0[2][i], s->x[2][i]);
    if (!(pen > AM_R(0))) {
        s->contact[i] = 0;
        return 0;
    }
    const am_real N = AM_MUL(m->k_floor[AM_VC(m, i)], pen); /* the spring force: friction's N */
    /* the normal velocity from the momentum (the velocity row is scratch in the step) */
    am_real Fn = N - AM_MUL(m->c_col[AM_VC(m, i)], AM_MUL(s->p[2][i], m->inv_mass[AM_VC(m, i)]));
    F->z += Fn < AM_R(0) ? AM_R(0) : Fn; /* the floor pushes, never pulls */

    /* squared norms as wide products: in the fixed-point build these impulses are small and their
     * squares would fall below the resolution */
    const am_real dt = s->dt, px = s->p[0][i], py = s->p[1][i];
    const am_real jk = AM_MUL(AM_MUL(m->mu_k[AM_VC(m, i)], N), dt); /* kinetic friction's impulse in a step */
    const am_real js = AM_MUL(AM_MUL(m->mu_s[AM_VC(m, i)], N), dt); /* static friction's bound */
    const am_wide p2 = AM_MULW(px, px) + AM_MULW(py, py);
    if (s->contact[i] == 0) s->contact[i] = p2 > AM_R(0) ? 2 : 1; /* landing: slides if it moves */
    /* q = p_h + F_h dt: the horizontal momentum at the end of the step without friction */
    const am_real fx = AM_MUL(F->x, dt), fy = AM_MUL(F->y, dt), qx = px + fx, qy = py + fy;
    const am_wide q2 = AM_MULW(qx, qx) + AM_MULW(qy, qy), jk2 = AM_MULW(jk, jk);
    /* sliding, and kinetic friction cannot bring it to rest within the step: it cannot cancel q
     * (in the floor's plane a sliding voxel stops only if friction can take all its motion; one
     * whose velocity swings past zero sideways keeps sliding). Otherwise at rest, or it comes to
     * rest within the step: static friction holds it if it can at rest (|F_h| <= mu_s N) and the
     * impulse that stops it, j = -q, is within the bound */
    if (!(s->contact[i] == 2 && p2 > AM_R(0) && q2 > jk2)) {
        const am_wide f2 = AM_MULW(fx, fx) + AM_MULW(fy, fy);
        const am_wide js2 = AM_MULW(js, js), lim2 = js2 > jk2 ? js2 : jk2;
        if (q2 <= lim2 && f2 <= lim2) {
            s->contact[i] = 1;
            return 1;
        }
        /* it breaks loose (or keeps sliding). A motion that kinetic friction can take whole within
         * the step (|q| <= mu_k N dt) it takes whole and no more: friction stops a voxel, never
         * throws it back. The voxel then ends the step with no horizontal momentum, still sliding,
         * and the caller zeroes it as a stuck one */
        s->contact[i] = 2;
        if (q2 <= jk2) return 1;
    }
    /* kinetic friction against the motion at the end of the step, q: implicit in the direction, so
     * the momentum keeps q's direction and loses mu_k N dt of its length (against the motion at the
     * start, p, an impulse larger than the momentum would flip a sideways motion every step) */
#if defined(AM_REAL_FIXED_POINT)
    const am_real qn = AM_WIDE_SQRT(q2), ux = -AM_DIV(qx, qn), uy = -AM_DIV(qy, qn);
#else
    const am_real inv = AM_DIV(AM_R(1), am_sqrt(q2)), ux = -AM_MUL(qx, inv), uy = -AM_MUL(qy, inv);
#endif
    const am_real fk = AM_MUL(m->mu_k[AM_VC(m, i)], N);
    F->x += AM_MUL(fk, ux);
    F->y += AM_MUL(fk, uy);
    return 0;
}

/* Pass A, per voxel: the total force without the floor into f and the total moment into mt, from
 * the state at the start of the step. On the desktop f holds the collision force on entry and each
 * voxel gathers its six links in a fixed order: + slots (this voxel is the negative end) add the
 * link's force, - slots subtract it and take the positive end's moment; then the velocity and spin
 * rows v and w, read here for the global damping, are overwritten by what the damping correction
 * reads: the increments the totals would give in alpha dt^2 (sc), F sc / m and M sc / I. On a board
 * f and mt hold the totals already (add_links) but for the zeros of missing links; the correction
 * scales them where it reads them. No branch: the compiler vectorises it. */
#if defined(AM_COMPACT)
#define TOTAL_PARAM const uint8_t* restrict surface, const am_index* restrict slot_px, const am_index* restrict slot_py, \
                    const am_index* restrict slot_pz, int nl
#define TOTAL_ARG(m, s) (m)->surface, (m)->slot[0], (m)->slot[2], (m)->slot[4], (m)->nl
#define VEL_PARAM , const am_real* restrict inv_mass
#define VEL_ARG(m) , (m)->inv_mass
#define VGET(r, c, i) AM_MUL(r[c][i], inv_mass[VCI(i)])
#else
#define TOTAL_PARAM const am_index (*restrict slot)[AM_MAX_VOXELS], const link_row* restrict fn, \
                    const link_row* restrict mn, const link_row* restrict mp, const vox_row* restrict fext, \
                    const vox_row* restrict mext
#define TOTAL_ARG(m, s) (const am_index(*)[AM_MAX_VOXELS])(m)->slot, (const link_row*)(s)->fn, (const link_row*)(s)->mn, \
                        (const link_row*)(s)->mp, (const vox_row*)(s)->fext, (const vox_row*)(s)->mext
#define VEL_PARAM , const am_real* restrict inv_mass
#define VEL_ARG(m) , (m)->inv_mass
#define VGET(r, c, i) r[c][i]
#endif
/* the desktop's gather of a voxel's six link results, in slot order (+x, -x, +y, -y, +z, -z): the +x
 * and -x results at lanes i + 1 and i (contiguous; zeros where empty), the others through the slots.
 * F and M are updated in place. */
#define GATHER_LINKS(F, M, i)                                                                                   \
    for (int d = 0; d < 3; d++) {                                                                               \
        const int lp = d == 0 ? (i) + 1 : slot[2 * d][i], ln = d == 0 ? (i) : slot[2 * d + 1][i];              \
        F = v3_add(F, v3(fn[0][lp], fn[1][lp], fn[2][lp]));                                                     \
        M = v3_add(M, v3(mn[0][lp], mn[1][lp], mn[2][lp]));                                                     \
        F = v3_sub(F, v3(fn[0][ln], fn[1][ln], fn[2][ln]));                                                     \
        M = v3_add(M, v3(mp[0][ln], mp[1][ln], mp[2][ln]));                                                     \
    }
static void voxel_totals(int nv, am_real g, am_real sc, int collisions, TOTAL_PARAM, const am_real* restrict mass,
                         const am_real* restrict c_glob_t, const am_real* restrict c_glob_r, const am_real* restrict inv_inertia,
                         const am_matid* restrict mat, vox_row* restrict v, vox_row* restrict w VEL_PARAM,
                         vox_row* restrict f, vox_row* restrict mt)
{
    (void)mat; /* read through VCI in the board profile only */
    for (int i = 0; i < nv; i++) {
#if defined(AM_COMPACT)
        (void)collisions;
        (void)sc;
        vec3 F = v3(f[0][i], f[1][i], f[2][i]), M = v3(mt[0][i], mt[1][i], mt[2][i]);
        /* a missing + link adds a zero force, any missing link a zero moment: x + 0 is x but for
         * x = -0, and where in the sum it comes does not matter */
        const vec3 zero = v3(AM_R(0), AM_R(0), AM_R(0));
        if ((slot_px[i] == nl) | (slot_py[i] == nl) | (slot_pz[i] == nl)) F = v3_add(F, zero);
        if (surface[i]) M = v3_add(M, zero);
        const vec3 wi = v3(AM_MUL(w[0][i], inv_inertia[VCI(i)]), AM_MUL(w[1][i], inv_inertia[VCI(i)]),
                           AM_MUL(w[2][i], inv_inertia[VCI(i)]));
#else
        (void)inv_mass;
        /* fc is zero without self-collision, and then holds the last step's total: not read */
        vec3 F = v3(fext[0][i] + (collisions ? f[0][i] : AM_R(0)), fext[1][i] + (collisions ? f[1][i] : AM_R(0)),
                    fext[2][i] + (collisions ? f[2][i] : AM_R(0)));
        vec3 M = v3(mext[0][i], mext[1][i], mext[2][i]);
        GATHER_LINKS(F, M, i)
        const vec3 wi = v3(w[0][i], w[1][i], w[2][i]);
#endif
        F.z -= AM_MUL(mass[VCI(i)], g);
        const am_real cg = c_glob_t[VCI(i)], cgr = c_glob_r[VCI(i)];
        F = v3_sub(F, v3(AM_MUL(cg, VGET(v, 0, i)), AM_MUL(cg, VGET(v, 1, i)), AM_MUL(cg, VGET(v, 2, i))));
        M = v3_sub(M, v3(AM_MUL(cgr, wi.x), AM_MUL(cgr, wi.y), AM_MUL(cgr, wi.z)));
        f[0][i] = F.x; f[1][i] = F.y; f[2][i] = F.z;
        mt[0][i] = M.x; mt[1][i] = M.y; mt[2][i] = M.z;
#if !defined(AM_COMPACT)
        /* what the damping correction reads (the board scales the totals where it reads them) */
        const am_real im = inv_mass[i], ii = inv_inertia[i];
        v[0][i] = AM_MUL(AM_MUL(F.x, im), sc); v[1][i] = AM_MUL(AM_MUL(F.y, im), sc); v[2][i] = AM_MUL(AM_MUL(F.z, im), sc);
        w[0][i] = AM_MUL(AM_MUL(M.x, ii), sc); w[1][i] = AM_MUL(AM_MUL(M.y, ii), sc); w[2][i] = AM_MUL(AM_MUL(M.z, ii), sc);
#endif
    }
}

/* Pass B, per voxel: the damping correction's impulses into the momenta p and h (on the desktop
 * gathered here from the per-link arrays, in the order of pass A; a board has added them already,
 * add_links, and adds here the zeros of missing links the gather adds), then the update:
 * h += M dt, q = quat(w dt) q, renormalised; p += F dt, x += p dt / m (a fixed voxel keeps no
 * momentum). Returns 1 when some voxel's squared speed is beyond v2_max (or NaN). No branch: the
 * compiler vectorises it. */
#if defined(AM_COMPACT)
#define ROT_PARAM const uint8_t* restrict surface, const am_index* restrict slot_px, const am_index* restrict slot_py, \
                  const am_index* restrict slot_pz, int nl
#define ROT_ARG(m, s) (m)->surface, (m)->slot[0], (m)->slot[2], (m)->slot[4], (m)->nl
#else
#define ROT_PARAM const am_index (*restrict slot)[AM_MAX_VOXELS], const link_row* restrict fn, \
                  const link_row* restrict mn, const link_row* restrict mp
#define ROT_ARG(m, s) (const am_index(*)[AM_MAX_VOXELS])(m)->slot, (const link_row*)(s)->fn, (const link_row*)(s)->mn, \
                      (const link_row*)(s)->mp
#endif
static int voxel_update(int nv, am_real dt, am_real v2_max, ROT_PARAM, const vox_row* restrict f, const vox_row* restrict mt,
                        const am_real* restrict inv_mass, const am_real* restrict inv_inertia, const uint8_t* restrict fixed,
                        const am_matid* restrict mat, vox_row* restrict p, vox_row* restrict h, vox_row* restrict v,
                        vox_row* restrict w, vox_row* restrict q, vox_row* restrict x, vox_row* restrict x_rem
                        REM_PARAM(p_rem) REM_PARAM(h_rem))
{
    (void)mat; /* read through VCI in the board profile only */
    int bad = 0;
    for (int i = 0; i < nv; i++) {
        vec3 P = v3(p[0][i], p[1][i], p[2][i]), H = v3(h[0][i], h[1][i], h[2][i]);
#if defined(AM_COMPACT)
        const vec3 zero = v3(AM_R(0), AM_R(0), AM_R(0));
        if ((slot_px[i] == nl) | (slot_py[i] == nl) | (slot_pz[i] == nl)) P = v3_add(P, zero);
        if (surface[i]) H = v3_add(H, zero);
#else
        GATHER_LINKS(P, H, i)
#endif
        /* rotation */
        const am_real ii = inv_inertia[VCI(i)];
        am_real hx = AM_ACC(H.x, h_rem[0][i], mt[0][i], dt), hy = AM_ACC(H.y, h_rem[1][i], mt[1][i], dt),
                hz = AM_ACC(H.z, h_rem[2][i], mt[2][i], dt);
        if (fixed[i]) hx = hy = hz = AM_R(0);
        vec3 wn = v3(AM_MUL(hx, ii), AM_MUL(hy, ii), AM_MUL(hz, ii));
        h[0][i] = hx; h[1][i] = hy; h[2][i] = hz;
#if defined(AM_COMPACT)
        (void)w;
        (void)v;
#else
        w[0][i] = wn.x; w[1][i] = wn.y; w[2][i] = wn.z;
#endif
        quat dq = q_from_rotvec(v3_scale(wn, dt));
        quat qn = q_mul(dq, qt(q[0][i], q[1][i], q[2][i], q[3][i]));
        am_real n2 = AM_MUL(qn.w, qn.w) + AM_MUL(qn.x, qn.x) + AM_MUL(qn.y, qn.y) + AM_MUL(qn.z, qn.z);
#if defined(AM_REAL_FIXED_POINT)
        /* |q| is 1 to within a few ulp: one Newton step from 1, 1/sqrt(n2) = (3 - n2) / 2, is exact
         * to O((n2 - 1)^2); the root and a division only when q is far from unit */
        am_real dn = n2 - AM_R(1);
        am_real inv = am_fabs(dn) < AM_R(0.0009765625) ? AM_R(1) - (dn >> 1) : AM_DIV(AM_R(1), am_sqrt(n2));
#else
        am_real inv = AM_DIV(AM_R(1), am_sqrt(n2));
#endif
        q[0][i] = AM_MUL(qn.w, inv); q[1][i] = AM_MUL(qn.x, inv);
        q[2][i] = AM_MUL(qn.y, inv); q[3][i] = AM_MUL(qn.z, inv);
        /* translation */
        const am_real im = inv_mass[VCI(i)];
        am_real px = AM_ACC(P.x, p_rem[0][i], f[0][i], dt), py = AM_ACC(P.y, p_rem[1][i], f[1][i], dt),
                pz = AM_ACC(P.z, p_rem[2][i], f[2][i], dt);
        if (fixed[i]) px = py = pz = AM_R(0);
        am_real vx = AM_MUL(px, im), vy = AM_MUL(py, im), vz = AM_MUL(pz, im);
        p[0][i] = px; p[1][i] = py; p[2][i] = pz;
#if !defined(AM_COMPACT)
        v[0][i] = vx; v[1][i] = vy; v[2][i] = vz;
#endif
        x[0][i] = AM_ACC_X(x[0][i], x_rem[0][i], vx, dt);
        x[1][i] = AM_ACC_X(x[1][i], x_rem[1][i], vy, dt);
        x[2][i] = AM_ACC_X(x[2][i], x_rem[2][i], vz, dt);
        am_real v2 = AM_MUL(vx, vx) + AM_MUL(vy, vy) + AM_MUL(vz, vz);
        bad |= !(v2 <= v2_max);
    }
    return bad;
}

/* touch[j] = 1 when voxel i0 + j (j < n) reaches below the floor: the test of floor_contact for a
 * chunk of voxels at once (no branch: the compiler vectorises it); returns 1 when one does */
#define FLOOR_CHUNK 64
static int floor_touch(int n, am_real L, const am_real* restrict scale, const am_real* restrict z0, const am_real* restrict z,
                       int32_t* restrict touch)
{
    int any = 0;
    for (int j = 0; j < n; j++) {
        touch[j] = FLOOR_PEN(scale[j], L, z0[j], z[j]) > AM_R(0);
        any |= touch[j];
    }
    return any;
}

/* the floor under every voxel that touches it: normal force and friction into its total force;
 * a stuck voxel loses its horizontal momentum (and force, so the update below keeps it zero).
 * Most voxels do not touch: a vectorised test picks the ones that do. */
static void floor_pass(const am_model* m, am_state* s)
{
    const int nv = m->nv;
    int32_t touch[FLOOR_CHUNK];
    for (int i0 = 0; i0 < nv; i0 += FLOOR_CHUNK) {
        const int n = nv - i0 < FLOOR_CHUNK ? nv - i0 : FLOOR_CHUNK;
        if (!floor_touch(n, m->L, s->s + i0, m->x0[2] + i0, s->x[2] + i0, touch)) { /* voxels go by layer: most chunks are above */
            for (int j = 0; j < n; j++) s->contact[i0 + j] = 0;
            continue;
        }
        for (int j = 0; j < n; j++) {
            const int i = i0 + j;
            if (!touch[j]) {
                s->contact[i] = 0;
                continue;
            }
            vec3 F = v3(s->fc[0][i], s->fc[1][i], s->fc[2][i]);
            if (floor_contact(m, s, i, &F)) {
                F.x = F.y = AM_R(0);
                s->p[0][i] = s->p[1][i] = AM_R(0);
                AM_REM_CLEAR(s->p_rem[0][i]);
                AM_REM_CLEAR(s->p_rem[1][i]);
            }
            s->fc[0][i] = F.x; s->fc[1][i] = F.y; s->fc[2][i] = F.z;
#if !defined(AM_COMPACT)
            /* the damping correction's increment from the total with the floor (as a board reads it) */
            s->v[0][i] = AM_MUL(AM_MUL(F.x, m->inv_mass[i]), s->damp_scale);
            s->v[1][i] = AM_MUL(AM_MUL(F.y, m->inv_mass[i]), s->damp_scale);
            s->v[2][i] = AM_MUL(AM_MUL(F.z, m->inv_mass[i]), s->damp_scale);
#endif
        }
    }
}

#if defined(AM_COMPACT)
/* a board's totals before the links add to them: the external loads and the collision forces
 * (zero without self-collision), as the desktop's gather starts */
static void totals_start(int nv, int collisions, const vox_row* restrict fext, const vox_row* restrict mext,
                         vox_row* restrict f, vox_row* restrict mt)
{
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < nv; i++) {
            f[c][i] = fext[c][i] + (collisions ? f[c][i] : AM_R(0));
            mt[c][i] = mext[c][i];
        }
}
#endif

/* The internal damping's correction (docs/physics.md, Damping). The step's damping acts on the
 * velocities at its start (explicit) plus a correction: the damping of the velocity increments the
 * step's total forces give in alpha dt^2, added as an impulse. Per mode of damping rate lambda
 * (x = lambda dt) that multiplies the velocity by 1 - x + alpha x^2 instead of the explicit 1 - x:
 * alpha = 1/4 is two half steps of the damping, stable while x < 4. x is at most AM_DAMP_MODES
 * times the largest c_t dt / mu of the body's links (the checkerboard modes of a lattice of equal
 * links, where translation and rotation combine). Up to AM_DAMP_X_EQUAL alpha is 1/4; beyond it
 * alpha falls so that the fastest mode keeps a factor 0.8, down to AM_DAMP_X_MAX, past which the
 * damping coefficients are scaled down (the only place the model's damping changes: docs). */
#define AM_DAMP_MODES AM_R(7)
#define AM_DAMP_X_EQUAL AM_R(3.6)
#define AM_DAMP_X_MAX AM_R(6.5)
/* the largest fraction of a voxel's velocity the global damping may remove in one step (explicit;
 * never reached at the seed's 0.01 of critical: docs/physics.md, Damping) */
#define AM_GLOB_CAP AM_R(0.15)

/* the damping for this dt: the link coefficients the step applies (the model's, or scaled down
 * past AM_DAMP_X_MAX) and the correction's alpha dt^2; the global damping times glob_scale, capped
 * by AM_GLOB_CAP. Once per dt and scale, not per step. */
static void damping_for_dt(const am_model* m, am_state* s)
{
    s->damp_dt = s->dt;
    s->glob_for_scale = s->glob_scale;
    const am_real L = m->L, dt = s->dt, k = s->glob_scale;
#if defined(AM_COMPACT)
    const int n = AM_LC_CAP; /* per pair of materials */
#else
    const int n = m->nl;
#endif
    /* the fastest damped mode: AM_DAMP_MODES times the largest c_t dt / mu over the body's links */
    am_real r = AM_R(0);
    for (int l = 0; l < m->nl; l++) {
        if (!am_link_live(m, l)) continue;
        const am_real mass_a = m->mass[AM_VC(m, m->lneg[l])], mass_b = m->mass[AM_VC(m, m->lpos[l])];
        r = am_max(r, AM_DIV(AM_MUL(m->c_t[AM_LC(m, l)], dt), am_sim_reduced_mass(mass_a, mass_b)));
    }
    am_real x = AM_MUL(AM_DAMP_MODES, r), scale = AM_R(1);
    if (x > AM_DAMP_X_MAX) {
        scale = AM_DIV(AM_DAMP_X_MAX, x);
        x = AM_DAMP_X_MAX;
    }
    am_real alpha = AM_R(0.25);
    if (x > AM_DAMP_X_EQUAL) alpha = am_min(alpha, AM_DIV(x - AM_R(0.2), AM_MUL(x, x)));
    s->damp_scale = AM_MUL(alpha, AM_MUL(dt, dt));
    s->damp_on = x > AM_R(0);
    s->damp_limited = scale < AM_R(1);
    for (int c = 0; c < n; c++) s->damp_t[c] = scale < AM_R(1) ? AM_MUL(m->c_t[c], scale) : m->c_t[c];
    s->damp_kr = AM_DIV(AM_MUL(L, L), AM_R(12)); /* c_r = c_t L^2 / 12 (sim_model.c) */
    /* global damping: explicit, capped by the voxel's own mass and inertia */
#if defined(AM_COMPACT)
    const int nvc = m->palette.count;
#else
    const int nvc = m->nv;
#endif
    for (int c = 0; c < nvc; c++) {
        const am_real mass = m->mass[c], inertia = am_sim_inertia(mass, L);
        const am_real cap_t = dt > AM_R(0) ? AM_DIV(AM_MUL(AM_GLOB_CAP, mass), dt) : m->c_glob_t[c];
        const am_real cap_r = dt > AM_R(0) ? AM_DIV(AM_MUL(AM_GLOB_CAP, inertia), dt) : m->c_glob_r[c];
        s->glob_t[c] = am_min(AM_MUL(k, m->c_glob_t[c]), cap_t);
        s->glob_r[c] = am_min(AM_MUL(k, m->c_glob_r[c]), cap_r);
    }
}

void am_step(const am_model* m, am_state* s)
{
    if (s->diverged) return;
    if (s->damp_dt != s->dt || s->glob_for_scale != s->glob_scale) damping_for_dt(m, s);
    actuation(m, s);
    /* contacts and links both read the state at the start of the step */
    am_sim_collide(m, s);
#if defined(AM_COMPACT)
    totals_start(m->nv, m->env.collisions, (const vox_row*)s->fext, (const vox_row*)s->mext, s->fc, s->mc);
    /* a board keeps no velocities: the voxel passes read the momenta for them and store none */
    vox_row *v = s->p, *w = s->h, *w_out = NULL, *v_out = NULL;
#else
    vox_row *v = s->v, *w = s->w, *w_out = s->w, *v_out = s->v;
#endif
    int bad = link_forces(m, s, 1, m->axis_end[0] - 1, 0); /* lanes 0 and nv are always empty */
    bad |= link_forces(m, s, m->axis_end[0], m->axis_end[1], 1);
    bad |= link_forces(m, s, m->axis_end[1], m->nl, 2);
    /* semi-implicit Euler: the totals, the damping correction, rotation, floor and friction,
     * translation */
    voxel_totals(m->nv, m->gravity, s->damp_scale, m->env.collisions, TOTAL_ARG(m, s), m->mass, s->glob_t, s->glob_r,
                 m->inv_inertia, m->mat, v, w VEL_ARG(m), s->fc, s->mc);
    if (m->env.floor) floor_pass(m, s);
    damp_forces(m, s, 1, m->axis_end[0] - 1, 0);
    damp_forces(m, s, m->axis_end[0], m->axis_end[1], 1);
    damp_forces(m, s, m->axis_end[1], m->nl, 2);
    bad |= voxel_update(m->nv, s->dt, AM_MUL(m->max_speed, m->max_speed), ROT_ARG(m, s), (const vox_row*)s->fc,
                        (const vox_row*)s->mc, m->inv_mass, m->inv_inertia, m->fixed, m->mat, s->p, s->h, v_out, w_out, s->q, s->x,
                        s->x_rem REM_ARG(s->p_rem) REM_ARG(s->h_rem));
    s->step++;
    if (bad) {
        s->diverged = 1;
        s->diverge_step = s->step;
    }
#if defined(AM_CHECKS)
    am_check_state(m, s);
#endif
}

long am_steps(const am_model* m, am_state* s, long n)
{
    long i = 0;
    for (; i < n && !s->diverged; i++) am_step(m, s);
    return i;
}
