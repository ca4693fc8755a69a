/* sim_internal.h: kernels shared by the simulator's files (not public).
 *
 * Vectors are plain am_real triples and quaternions (w, x, y, z) passed by value, so that the
 * compiler keeps them in registers. The beam kinematics live here because both the step (forces)
 * and the energy diagnostics (strain energy) need exactly the same local frame. */
#ifndef AMORPH_SIM_INTERNAL_H
#define AMORPH_SIM_INTERNAL_H

#include "amorph/sim.h"

#if defined(AM_REAL_FIXED_POINT)
/* a parameter in SI converted to model units (u: the SI value of one unit of its dimension) */
#define AM_PV(v, u) AM_FROM_DOUBLE((double)(v) / (u))
#else
#define AM_PV(v, u) (v)
#endif

typedef struct { am_real x, y, z; } vec3;
typedef struct { am_real w, x, y, z; } quat;

static inline vec3 v3(am_real x, am_real y, am_real z) { vec3 r = {x, y, z}; return r; }
static inline vec3 v3_add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 v3_sub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 v3_scale(vec3 a, am_real k) { return v3(AM_MUL(a.x, k), AM_MUL(a.y, k), AM_MUL(a.z, k)); }
static inline am_real v3_dot(vec3 a, vec3 b) { return AM_MUL(a.x, b.x) + AM_MUL(a.y, b.y) + AM_MUL(a.z, b.z); }
static inline vec3 v3_cross(vec3 a, vec3 b)
{
    return v3(AM_MUL(a.y, b.z) - AM_MUL(a.z, b.y), AM_MUL(a.z, b.x) - AM_MUL(a.x, b.z), AM_MUL(a.x, b.y) - AM_MUL(a.y, b.x));
}

static inline quat qt(am_real w, am_real x, am_real y, am_real z) { quat r = {w, x, y, z}; return r; }
static inline quat q_conj(quat a) { return qt(a.w, -a.x, -a.y, -a.z); }
static inline quat q_mul(quat a, quat b)
{
    return qt(AM_MUL(a.w, b.w) - AM_MUL(a.x, b.x) - AM_MUL(a.y, b.y) - AM_MUL(a.z, b.z),
              AM_MUL(a.w, b.x) + AM_MUL(a.x, b.w) + AM_MUL(a.y, b.z) - AM_MUL(a.z, b.y),
              AM_MUL(a.w, b.y) - AM_MUL(a.x, b.z) + AM_MUL(a.y, b.w) + AM_MUL(a.z, b.x),
              AM_MUL(a.w, b.z) + AM_MUL(a.x, b.y) - AM_MUL(a.y, b.x) + AM_MUL(a.z, b.w));
}
/* rotates v by unit quaternion q: v + w t + u x t with u = (x, y, z), t = 2 u x v */
static inline vec3 q_rot(quat q, vec3 v)
{
    vec3 u = v3(q.x, q.y, q.z);
    vec3 t = v3_cross(u, v);
    t = v3_add(t, t);
    return v3_add(v3_add(v, v3_scale(t, q.w)), v3_cross(u, t));
}
/* rotates v by the inverse of unit quaternion q */
static inline vec3 q_rot_inv(quat q, vec3 v) { return q_rot(q_conj(q), v); }

/* rotation vector (axis * angle) of a unit quaternion without trigonometry: with s = |u| =
 * sin(angle/2), angle = 2 asin(s); asin(s)/s by its series in s^2 (error below 3e-4 at 90
 * degrees of relative rotation, the largest a link sees in practice). */
static inline vec3 q_rotvec(quat q)
{
    am_real sg = q.w < AM_R(0) ? AM_R(-2) : AM_R(2);
    am_real s2 = AM_MUL(q.x, q.x) + AM_MUL(q.y, q.y) + AM_MUL(q.z, q.z);
    am_real f = AM_R(0.017352764423076923); /* 231/13312 */
    f = AM_MUL(f, s2) + AM_R(0.022372159090909091); /* 63/2816 */
    f = AM_MUL(f, s2) + AM_R(0.030381944444444444); /* 35/1152 */
    f = AM_MUL(f, s2) + AM_R(0.044642857142857144); /* 5/112 */
    f = AM_MUL(f, s2) + AM_R(0.075);                /* 3/40 */
    f = AM_MUL(f, s2) + AM_R(0.16666666666666666);  /* 1/6 */
    f = AM_MUL(f, s2) + AM_R(1);
    f = AM_MUL(f, sg);
    return v3(AM_MUL(q.x, f), AM_MUL(q.y, f), AM_MUL(q.z, f));
}

/* unit quaternion of a small rotation vector r (|r| well below 1 rad): half angle a = |r|/2,
 * cos a and sin(a)/a by their series; the caller renormalises the product */
static inline quat q_from_rotvec(vec3 r)
{
    am_real a2 = AM_MUL(AM_R(0.25), v3_dot(r, r)); /* (|r|/2)^2 */
    am_real c = AM_R(1) - AM_MUL(a2, AM_R(0.5) - AM_MUL(a2, AM_R(1.0 / 24.0) - AM_MUL(a2, AM_R(1.0 / 720.0))));
    am_real sa = AM_R(1) - AM_MUL(a2, AM_R(1.0 / 6.0) - AM_MUL(a2, AM_R(1.0 / 120.0) - AM_MUL(a2, AM_R(1.0 / 5040.0))));
    am_real k = AM_MUL(AM_R(0.5), sa);
    return qt(c, AM_MUL(r.x, k), AM_MUL(r.y, k), AM_MUL(r.z, k));
}

/* world <-> link-local axis permutation: the link's axis becomes +x (cyclic, a proper rotation).
 * Written component by component so that a loop over links with a run-time axis still
 * vectorises (the choice is then a blend). */
static inline vec3 to_local(vec3 v, int axis)
{
    return v3(axis == 0 ? v.x : (axis == 1 ? v.y : v.z), axis == 0 ? v.y : (axis == 1 ? v.z : v.x),
              axis == 0 ? v.z : (axis == 1 ? v.x : v.y));
}
static inline vec3 from_local(vec3 v, int axis)
{
    return v3(axis == 0 ? v.x : (axis == 1 ? v.z : v.y), axis == 0 ? v.y : (axis == 1 ? v.x : v.z),
              axis == 0 ? v.z : (axis == 1 ? v.y : v.x));
}

/* the kinematics of one link in its local frame: the positive voxel at (x, y, z) from the
 * negative one, end rotation vectors t1 (negative) and t2 (positive); rot is the extra frame
 * rotation of the large-angle treatment (identity when small) */
typedef struct link_kin {
    vec3 d;        /* world offset x_pos - x_neg */
    vec3 p;        /* local offset */
    vec3 t1, t2;   /* local end rotations */
    quat qn;       /* orientation of the negative voxel */
    quat qr;       /* rotation of the positive voxel relative to the negative one (local axes) */
    quat rot;      /* large-angle frame rotation (local) */
} link_kin;

static inline int link_axis(const am_model* m, int l) { return l < m->axis_end[0] ? 0 : (l < m->axis_end[1] ? 1 : 2); }

/* large-angle thresholds (Voxelyze's hysteresis): on above, off below */
#define AM_LA_ON_LAT AM_R(0.06)
#define AM_LA_OFF_LAT AM_R(0.05)
#define AM_LA_ON_AX AM_R(0.6)
#define AM_LA_OFF_AX AM_R(0.5)

/* the small-angle local frame of a link from its ends' orientations (qn negative, qp positive)
 * and the world offset d = x_pos - x_neg */
static inline void link_kin_from(quat qn, quat qp, vec3 d, int axis, link_kin* k)
{
    k->d = d;
    k->qn = qn;
    k->p = to_local(q_rot_inv(qn, d), axis);
    quat qr = q_mul(q_conj(qn), qp);
    vec3 rv = to_local(v3(qr.x, qr.y, qr.z), axis);
    k->qr = qt(qr.w, rv.x, rv.y, rv.z);
    k->t2 = q_rotvec(k->qr);
    k->t1 = v3(0, 0, 0);
    k->rot = qt(1, 0, 0, 0);
}

/* the same from the state, for the link from voxel a to voxel b: the offset is the rest lattice's
 * L along the axis plus the difference of the displacements, as in the step */
static inline void link_kin_small(const am_model* m, const am_state* s, int a, int b, int axis, link_kin* k)
{
    am_real dx = s->x[0][b] - s->x[0][a], dy = s->x[1][b] - s->x[1][a], dz = s->x[2][b] - s->x[2][a];
    link_kin_from(qt(s->q[0][a], s->q[1][a], s->q[2][a], s->q[3][a]), qt(s->q[0][b], s->q[1][b], s->q[2][b], s->q[3][b]),
                  v3(axis == 0 ? dx + m->L : dx, axis == 1 ? dy + m->L : dy, axis == 2 ? dz + m->L : dz), axis, k);
}

/* per-component choices (on ? a : b), written so that loops over links stay vectorisable */
static inline vec3 v3_sel(int on, vec3 a, vec3 b) { return v3(on ? a.x : b.x, on ? a.y : b.y, on ? a.z : b.z); }
static inline quat q_sel(int on, quat a, quat b) { return qt(on ? a.w : b.w, on ? a.x : b.x, on ? a.y : b.y, on ? a.z : b.z); }

/* when on, turns a small-angle frame into the large-angle one: rotate so the positive voxel lies
 * on +x (a link of zero or NaN length keeps its small frame). Computed whether on or not and then
 * chosen, without a branch, so that the link loop vectorises. */
static inline void link_kin_large(link_kin* k, int on)
{
    am_real len = am_sqrt(v3_dot(k->p, k->p));
    on = on && len > AM_R(0);
    vec3 u = v3_scale(k->p, AM_DIV(AM_R(1), len));
    /* shortest rotation taking u onto +x: (1 + ux, u x e_x) normalised */
    am_real wq = AM_R(1) + u.x;
    wq = wq < AM_R(1e-6) ? AM_R(1e-6) : wq; /* a link turned inside out: any axis will do */
    am_real n = am_sqrt(AM_MUL(wq, wq) + AM_MUL(u.y, u.y) + AM_MUL(u.z, u.z));
    am_real inv = AM_DIV(AM_R(1), n);
    quat r = qt(AM_MUL(wq, inv), AM_R(0), AM_MUL(u.z, inv), AM_MUL(-u.y, inv));
    /* in the new frame the negative end is turned by r and the positive one by r * qr */
    k->t1 = v3_sel(on, q_rotvec(r), k->t1);
    k->t2 = q_rotvec(q_sel(on, q_mul(r, k->qr), k->qr)); /* = k->t2 when off, one series fewer */
    k->p = v3_sel(on, v3(len, 0, 0), k->p);
    k->rot = q_sel(on, r, k->rot);
}

/* v + a b: in the fixed-point build exactly, with the rounding remainder carried in *rem to the
 * next step (so increments below the resolution, such as the gravity impulse of a stiff body,
 * accumulate instead of rounding away); v + a b otherwise */
#if defined(AM_REAL_FIXED_POINT)
static inline am_real am_acc(am_real v, am_real* rem, am_real a, am_real b)
{
    int64_t w = (int64_t)v * AM_FIX_ONE + *rem + (int64_t)a * b;
    am_real r = (am_real)((w + AM_FIX_HALF) >> AM_FIX_FRAC);
    *rem = (am_real)(w - (int64_t)r * AM_FIX_ONE);
    return r;
}
#define AM_ACC(v, rem, a, b) am_acc((v), &(rem), (a), (b))
#define AM_ACC_X(v, rem, a, b) am_acc((v), &(rem), (a), (b))
#define AM_REM_CLEAR(rem) ((rem) = 0)
#else
#define AM_ACC(v, rem, a, b) ((v) + AM_MUL((a), (b)))
/* v + a b for a position: the increment plus the remainder carried from the last step is added,
 * and what the addition lost is the next remainder (Fast2Sum: exact when |v| >= |increment|, the
 * case that matters; a displacement near 0 loses nothing worth carrying) */
static inline am_real am_acc_x(am_real v, am_real* rem, am_real a, am_real b)
{
    const am_real y = AM_MUL(a, b) + *rem, t = v + y;
    *rem = y - (t - v);
    return t;
}
#define AM_ACC_X(v, rem, a, b) am_acc_x((v), &(rem), (a), (b))
#define AM_REM_CLEAR(rem) ((void)0)
#endif

/* a voxel's rotational inertia m L^2 / 6, and the reduced mass of a link's two voxels: what the
 * internal damping's ratios refer to (sim_model.c) and what its cap per step bounds (sim_step.c) */
static inline am_real am_sim_inertia(am_real mass, am_real L) { return AM_DIV(AM_MUL(mass, AM_MUL(L, L)), AM_R(6)); }
static inline am_real am_sim_reduced_mass(am_real ma, am_real mb) { return AM_DIV(AM_MUL(ma, mb), ma + mb); }

/* linear scale of a voxel of thermal coefficient cte at temperature T (sim_scale.c: the step's, which
 * the model build asks for the largest scale) */
am_real am_sim_scale(int cte_mode, am_real cte, am_real T);
/* its change for a small change dT of T (its derivative times dT), s being am_sim_scale's value (0
 * where it clamps); with dT = dT/dt, the scale's rate of change */
am_real am_sim_scale_rate(int cte_mode, am_real cte, am_real T, am_real dT, am_real s);
/* velocity component c of voxel i outside the step's loops: kept in the state on the desktop,
 * derived from the momentum where read on a board (the same value: the step computes it so; the
 * step's own loops do the same for the spins, see sim_step.c) */
#if defined(AM_COMPACT)
static inline am_real am_sim_vel(const am_model* m, const am_state* s, int c, int i)
{
    return AM_MUL(s->p[c][i], m->inv_mass[AM_VC(m, i)]);
}
#else
static inline am_real am_sim_vel(const am_model* m, const am_state* s, int c, int i) { (void)m; return s->v[c][i]; }
#endif

/* the centre of voxel i along c in model units, in double: the rest lattice plus the displacement
 * (diagnostics only; the step works on displacements) */
static inline double am_sim_pos(const am_model* m, const am_state* s, int c, int i)
{
    return AM_TO_DOUBLE(m->x0[c][i]) + AM_TO_DOUBLE(s->x[c][i]);
}

/* self-collision forces into s->fc, rebuilding the candidate list when needed (sim_collide.c) */
void am_sim_collide(const am_model* m, am_state* s);

/* the AM_CHECKS build's hooks (sim_check.c): the invariants after each model build and step; a
 * failure calls AM_CHECK_HANDLER(file, line, message) (default: stderr and abort) */
#if defined(AM_CHECKS)
void am_check_model(const am_model* m);
void am_check_state(const am_model* m, const am_state* s);
#endif

#endif
