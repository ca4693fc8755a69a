/* One time step of the voxel beam lattice (docs/physics.md section 7).
 *
 * Order: actuation (per-material temperature -> voxel scales -> link rest lengths, once per
 * link), link forces from the state at the start of the step, contact forces (self-collision;
 * the floor is per voxel and done during integration because its friction state machine needs
 * the voxel's total force), then semi-implicit Euler per voxel.
 *
 * Links write their forces into per-link arrays; each voxel then gathers from its six slots in a
 * fixed order (+x, -x, +y, -y, +z, -z; a missing link points at the zero link nl). No voxel sum
 * depends on how links are ordered or how work is split, and the floating-point sums are the same
 * on every platform. */
#include "sim_internal.h"
#include "amorph/mathx.h"

/* per-material temperature and linear scale, voxel scales, link rest lengths */
static void actuation(const am_model* m, am_state* s)
{
    const am_env* e = &m->env;
    int changed = !s->scales_valid;
    for (int k = 0; k < m->palette.count; k++) {
        am_real T = m->temp_base;
        if (s->actuate) {
            long ph = (s->step - s->actuation_step0) % e->period_steps; /* exact phase in steps */
#if defined(AM_REAL_FIXED_POINT)
            am_real arg = AM_RATIO((int64_t)AM_R(6.283185307179586477) * ph, (int64_t)e->period_steps * AM_FIX_ONE) + m->mat_phase[k];
#else
            am_real arg = AM_DIV(AM_MUL(AM_MUL(AM_R(2), AM_PI), AM_R(ph)), AM_R(e->period_steps)) + m->mat_phase[k];
#endif
            T += AM_MUL(m->temp_amplitude, am_sin(arg));
        }
        am_real sc = m->mat_cte[k] == AM_R(0) ? AM_R(1) : am_sim_scale(e->cte_mode, m->mat_cte[k], T);
        changed |= sc != s->mat_scale[k];
        s->mat_scale[k] = sc;
    }
    /* voxel scales and rest lengths only when a material's scale moved (never, for a passive
     * body or during relaxation) */
    if (!changed) return;
    s->scales_valid = 1;
    const int nv = m->nv, nl = m->nl;
    for (int i = 0; i < nv; i++) s->s[i] = s->mat_scale[m->mat[i]];
    const am_real half_L = AM_MUL(AM_R(0.5), m->L);
#if defined(AM_REAL_FIXED_POINT)
    /* a rest length takes one value per pair of materials: one 64-bit division per change of value
     * along the link list instead of one per link */
    am_real last_r = 0, last_inv = 0;
    for (int l = 0; l < nl; l++) {
        am_real r = AM_MUL(half_L, s->s[m->lneg[l]] + s->s[m->lpos[l]]);
        if (r != last_r) {
            last_r = r;
            last_inv = AM_DIV(AM_R(1), r);
        }
        s->rest[l] = r;
        s->inv_rest[l] = last_inv;
    }
#else
    for (int l = 0; l < nl; l++) {
        am_real r = AM_MUL(half_L, s->s[m->lneg[l]] + s->s[m->lpos[l]]);
        s->rest[l] = r;
        s->inv_rest[l] = AM_DIV(AM_R(1), r);
    }
#endif
}

/* forces and moments of the links [l0, l1), all along one axis */
static am_real link_forces(const am_model* m, am_state* s, int l0, int l1, int axis)
{
    am_real max_strain = AM_R(0);
    for (int l = l0; l < l1; l++) {
        const int a = m->lneg[l], b = m->lpos[l];
        link_kin k;
        link_kin_small(s, a, b, axis, &k);

        /* large-angle switch with hysteresis (docs/physics.md section 2) */
        am_real lateral = am_fabs(k.p.y) + am_fabs(k.p.z);
        am_real axial = am_fabs(AM_R(1) - AM_MUL(k.p.x, s->inv_rest[l]));
        int large = s->large[l] ? (lateral > AM_MUL(AM_LA_OFF_LAT, k.p.x) || axial > AM_LA_OFF_AX)
                                : (lateral > AM_MUL(AM_LA_ON_LAT, k.p.x) || axial > AM_LA_ON_AX);
        large |= !(k.p.x > AM_R(0));
        s->large[l] = (uint8_t)large;
        if (large) link_kin_large(&k);

        /* the Euler-Bernoulli frame element in the local frame; only the axial term goes through
         * the material law (linear here), shear, bending and torsion are linear */
        const am_real b1 = m->b1[l], b2 = m->b2[l], b3 = m->b3[l];
        am_real strain = AM_MUL(k.p.x - s->rest[l], s->inv_rest[l]);
        vec3 F = v3(AM_MUL(m->k_ax[l], strain),
                    AM_MUL(b1, k.p.y) - AM_MUL(b2, k.t1.z + k.t2.z),
                    AM_MUL(b1, k.p.z) + AM_MUL(b2, k.t1.y + k.t2.y));
        vec3 M = v3(AM_MUL(m->a2[l], k.t2.x - k.t1.x),
                    -AM_MUL(b2, k.p.z) - AM_MUL(b3, AM_MUL(AM_R(2), k.t1.y) + k.t2.y),
                    AM_MUL(b2, k.p.y) - AM_MUL(b3, AM_MUL(AM_R(2), k.t1.z) + k.t2.z));
        if (large) {
            F = q_rot_inv(k.rot, F);
            M = q_rot_inv(k.rot, M);
        }
        F = q_rot(k.qn, from_local(F, axis));
        M = q_rot(k.qn, from_local(M, axis));

        /* internal damping, acting at the link's midpoint against the rate of deformation: the
         * relative velocity of the two ends there less what a rigid rotation would give, and the
         * relative spin. Its power is -c |rate|^2, so it only ever removes energy. */
        const am_real ct = m->c_t[l], cr = m->c_r[l];
        vec3 wa = v3(s->w[0][a], s->w[1][a], s->w[2][a]), wb = v3(s->w[0][b], s->w[1][b], s->w[2][b]);
        vec3 half_d = v3_scale(k.d, AM_R(0.5));
        vec3 rate = v3_sub(v3(s->v[0][b] - s->v[0][a], s->v[1][b] - s->v[1][a], s->v[2][b] - s->v[2][a]),
                           v3_cross(v3_add(wa, wb), half_d));
        vec3 Fd = v3_scale(rate, ct);
        F = v3_add(F, Fd);
        M = v3_add(M, v3_add(v3_cross(half_d, Fd), v3_scale(v3_sub(wb, wa), cr)));

        /* the positive end's moment from the balance of the element, so that the link exerts no
         * net torque (angular momentum is conserved exactly); at rest length this is the
         * textbook M_pos */
        vec3 Mp = v3_sub(v3_cross(k.d, F), M);

        s->fn[0][l] = F.x; s->fn[1][l] = F.y; s->fn[2][l] = F.z;
        s->mn[0][l] = M.x; s->mn[1][l] = M.y; s->mn[2][l] = M.z;
        s->mp[0][l] = Mp.x; s->mp[1][l] = Mp.y; s->mp[2][l] = Mp.z;
        s->strain[l] = strain;
        am_real as = am_fabs(strain);
        max_strain = as > max_strain ? as : max_strain;
        if (AM_ISNAN(as)) max_strain = AM_REAL_MAX; /* NaN */
    }
    return max_strain;
}

/* floor contact of voxel i: normal force and the static/kinetic friction state machine. F is the
 * voxel's total force without the floor; returns 1 when the horizontal motion is stuck. */
static int floor_contact(const am_model* m, am_state* s, int i, vec3* F)
{
    am_real pen = AM_MUL(AM_MUL(AM_R(0.5), s->s[i]), m->L) - s->x[2][i];
    if (!(pen > AM_R(0))) {
        s->contact[i] = 0;
        return 0;
    }
    am_real N = AM_MUL(m->k_floor[i], pen) - AM_MUL(m->c_col[i], s->v[2][i]);
    if (N < AM_R(0)) N = AM_R(0); /* the floor pushes, never pulls */
    F->z += N;

    /* squared norms as wide products: in the fixed-point build these forces and speeds are small
     * (gravity is 1e-4 of a unit) and their squares would fall below the resolution */
    const am_real vx = s->v[0][i], vy = s->v[1][i];
    am_wide v2 = AM_MULW(vx, vx) + AM_MULW(vy, vy);
    if (s->contact[i] == 0) s->contact[i] = v2 > AM_R(0) ? 2 : 1; /* landing: slides if it moves */
    am_wide fh2 = AM_MULW(F->x, F->x) + AM_MULW(F->y, F->y);
    if (s->contact[i] == 1) {
        am_real lim = AM_MUL(m->mu_s[i], N);
        if (fh2 <= AM_MULW(lim, lim)) {
            F->x = F->y = AM_R(0);
            return 1;
        }
        s->contact[i] = 2; /* breaks loose: kinetic friction from this step */
    }
    /* sliding: kinetic friction against the velocity (against the force when not yet moving) */
    am_real fk = AM_MUL(m->mu_k[i], N);
    am_real dx, dy;
#if defined(AM_REAL_FIXED_POINT)
    /* the direction as quotients (1 / |v| may be beyond the range) */
    if (v2 > 0) {
        am_real n = AM_WIDE_SQRT(v2);
        dx = AM_DIV(vx, n);
        dy = AM_DIV(vy, n);
    } else if (fh2 > 0) {
        am_real n = AM_WIDE_SQRT(fh2);
        dx = AM_DIV(F->x, n);
        dy = AM_DIV(F->y, n);
    } else {
#else
    if (v2 > AM_R(0)) {
        am_real inv = AM_DIV(AM_R(1), am_sqrt(v2));
        dx = AM_MUL(vx, inv);
        dy = AM_MUL(vy, inv);
    } else if (fh2 > AM_R(0)) {
        am_real inv = AM_DIV(AM_R(1), am_sqrt(fh2));
        dx = AM_MUL(F->x, inv);
        dy = AM_MUL(F->y, inv);
    } else {
#endif
        s->contact[i] = 1;
        return 1;
    }
    am_real fx = F->x - AM_MUL(fk, dx), fy = F->y - AM_MUL(fk, dy);
    /* friction may stop the voxel within the step but never reverse it: then it sticks */
    am_real px = s->p[0][i], py = s->p[1][i];
    am_real nx = px + AM_MUL(fx, s->dt), ny = py + AM_MUL(fy, s->dt);
    if (v2 > AM_R(0) && AM_MULW(nx, px) + AM_MULW(ny, py) <= AM_R(0)) {
        s->contact[i] = 1;
        F->x = F->y = AM_R(0);
        return 1;
    }
    F->x = fx;
    F->y = fy;
    return 0;
}

/* semi-implicit Euler for every voxel; returns the largest squared speed (NaN-safe) */
static am_real integrate(const am_model* m, am_state* s)
{
    const int nv = m->nv;
    const am_real dt = s->dt;
    const am_real g = m->gravity;
    const int floor_on = m->env.floor;
    am_real max_v2 = AM_R(0);
    for (int i = 0; i < nv; i++) {
        /* gather the six links in a fixed order: + slots (this voxel is the negative end) add the
         * link's force, - slots subtract it and take the positive end's moment */
        vec3 F = v3(s->fext[0][i] + s->fc[0][i], s->fext[1][i] + s->fc[1][i], s->fext[2][i] + s->fc[2][i]);
        vec3 M = v3(s->mext[0][i], s->mext[1][i], s->mext[2][i]);
        for (int d = 0; d < 3; d++) {
            int lp = m->slot[2 * d][i], ln = m->slot[2 * d + 1][i];
            F = v3_add(F, v3(s->fn[0][lp], s->fn[1][lp], s->fn[2][lp]));
            M = v3_add(M, v3(s->mn[0][lp], s->mn[1][lp], s->mn[2][lp]));
            F = v3_sub(F, v3(s->fn[0][ln], s->fn[1][ln], s->fn[2][ln]));
            M = v3_add(M, v3(s->mp[0][ln], s->mp[1][ln], s->mp[2][ln]));
        }
        const am_real mass = m->mass[i];
        F.z -= AM_MUL(mass, g);
        const am_real cg = m->c_glob_t[i], cgr = m->c_glob_r[i];
        F = v3_sub(F, v3(AM_MUL(cg, s->v[0][i]), AM_MUL(cg, s->v[1][i]), AM_MUL(cg, s->v[2][i])));
        M = v3_sub(M, v3(AM_MUL(cgr, s->w[0][i]), AM_MUL(cgr, s->w[1][i]), AM_MUL(cgr, s->w[2][i])));

        int stuck = 0;
        if (floor_on) stuck = floor_contact(m, s, i, &F);

        /* p += F dt; x += p dt / m (a stuck voxel keeps no horizontal momentum) */
        const am_real im = m->inv_mass[i];
        am_real px = AM_ACC(s->p[0][i], s->p_rem[0][i], F.x, dt), py = AM_ACC(s->p[1][i], s->p_rem[1][i], F.y, dt),
                pz = AM_ACC(s->p[2][i], s->p_rem[2][i], F.z, dt);
        if (stuck) {
            px = py = AM_R(0);
            AM_REM_CLEAR(s->p_rem[0][i]);
            AM_REM_CLEAR(s->p_rem[1][i]);
        }
        if (m->fixed[i]) px = py = pz = AM_R(0);
        am_real vx = AM_MUL(px, im), vy = AM_MUL(py, im), vz = AM_MUL(pz, im);
        s->p[0][i] = px; s->p[1][i] = py; s->p[2][i] = pz;
        s->v[0][i] = vx; s->v[1][i] = vy; s->v[2][i] = vz;
        s->x[0][i] = AM_ACC(s->x[0][i], s->x_rem[0][i], vx, dt);
        s->x[1][i] = AM_ACC(s->x[1][i], s->x_rem[1][i], vy, dt);
        s->x[2][i] = AM_ACC(s->x[2][i], s->x_rem[2][i], vz, dt);

        /* h += M dt; q = quat(w dt) q, renormalised */
        const am_real ii = m->inv_inertia[i];
        am_real hx = AM_ACC(s->h[0][i], s->h_rem[0][i], M.x, dt), hy = AM_ACC(s->h[1][i], s->h_rem[1][i], M.y, dt),
                hz = AM_ACC(s->h[2][i], s->h_rem[2][i], M.z, dt);
        if (m->fixed[i]) hx = hy = hz = AM_R(0);
        vec3 w = v3(AM_MUL(hx, ii), AM_MUL(hy, ii), AM_MUL(hz, ii));
        s->h[0][i] = hx; s->h[1][i] = hy; s->h[2][i] = hz;
        s->w[0][i] = w.x; s->w[1][i] = w.y; s->w[2][i] = w.z;
        quat dq = q_from_rotvec(v3_scale(w, dt));
        quat q = q_mul(dq, qt(s->q[0][i], s->q[1][i], s->q[2][i], s->q[3][i]));
        am_real n2 = AM_MUL(q.w, q.w) + AM_MUL(q.x, q.x) + AM_MUL(q.y, q.y) + AM_MUL(q.z, q.z);
#if defined(AM_REAL_FIXED_POINT)
        /* |q| is 1 to within a few ulp: one Newton step from 1, 1/sqrt(n2) = (3 - n2) / 2, is exact
         * to O((n2 - 1)^2); the root and a division only when q is far from unit */
        am_real dn = n2 - AM_R(1);
        am_real inv = am_fabs(dn) < AM_R(0.0009765625) ? AM_R(1) - (dn >> 1) : AM_DIV(AM_R(1), am_sqrt(n2));
#else
        am_real inv = AM_DIV(AM_R(1), am_sqrt(n2));
#endif
        s->q[0][i] = AM_MUL(q.w, inv); s->q[1][i] = AM_MUL(q.x, inv);
        s->q[2][i] = AM_MUL(q.y, inv); s->q[3][i] = AM_MUL(q.z, inv);

        am_real v2 = AM_MUL(vx, vx) + AM_MUL(vy, vy) + AM_MUL(vz, vz);
        if (!(v2 <= max_v2)) max_v2 = !AM_ISNAN(v2) ? v2 : AM_REAL_MAX; /* NaN counts as too fast */
    }
    return max_v2;
}

/* bound on the axial strain of any link: no physical run stretches a link to six times its rest
 * length or through its neighbour */
#define AM_DIVERGE_STRAIN AM_R(5)

void am_step(const am_model* m, am_state* s)
{
    if (s->diverged) return;
    actuation(m, s);
    am_real strain = AM_R(0);
    strain = am_max(strain, link_forces(m, s, 0, m->axis_end[0], 0));
    strain = am_max(strain, link_forces(m, s, m->axis_end[0], m->axis_end[1], 1));
    strain = am_max(strain, link_forces(m, s, m->axis_end[1], m->nl, 2));
    am_sim_collide(m, s);
    am_real v2 = integrate(m, s);
    s->step++;
    s->t = AM_MUL_INT(s->dt, s->step);
    if (!(strain <= AM_DIVERGE_STRAIN) || !(v2 <= AM_MUL(m->max_speed, m->max_speed))) {
        s->diverged = 1;
        s->diverge_step = s->step;
    }
}

long am_steps(const am_model* m, am_state* s, long n)
{
    long i = 0;
    for (; i < n && !s->diverged; i++) am_step(m, s);
    return i;
}
