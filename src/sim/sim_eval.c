/* Evaluation (the seed's relaxation + movement protocol), the empirical time step search,
 * energies, momenta, state hashes and recording. None of this is in the per-step hot path. */
#include "sim_internal.h"
#include "amorph/base.h"

#include <string.h>

am_eval_def am_default_eval(void)
{
    am_eval_def d;
    memset(&d, 0, sizeof d);
    d.cycles = 10;
    d.fitness = AM_FIT_HORIZONTAL;
    d.dt_search = 0;
    d.relax_max_steps = 40000;
    d.relax_min_steps = 200;
    d.settle_speed = AM_P(1e-4);
    d.relax_dt_frac = AM_P(1.8);
    d.release_steps = 500;
    d.score = AM_SCORE_TRAVEL;
    d.sustained_from = 10;
    d.record = 0;
    d.gait = 0;
    return d;
}

/* the kinetic energy (model units) of the free voxels into *e and, with speeds, the sum of the
 * squares of every voxel's velocity components into *v2: one pass, so that the two sums' chains of
 * additions overlap (each in voxel order: the same values as two passes) */
static inline void motion_sums(const am_model* m, const am_state* s, int speeds, double* e_out, double* v2_out)
{
    double e = 0, v2 = 0;
    for (int i = 0; i < m->nv; i++) {
        if (speeds)
            for (int c = 0; c < 3; c++) {
                const double vc = AM_TO_DOUBLE(am_sim_vel(m, s, c, i));
                v2 += vc * vc;
            }
        if (m->fixed[i]) continue;
        double p2 = 0, h2 = 0;
        for (int c = 0; c < 3; c++) {
            p2 += AM_TO_DOUBLE(s->p[c][i]) * AM_TO_DOUBLE(s->p[c][i]);
            h2 += AM_TO_DOUBLE(s->h[c][i]) * AM_TO_DOUBLE(s->h[c][i]);
        }
        e += 0.5 * p2 * AM_TO_DOUBLE(m->inv_mass[AM_VC(m, i)]) + 0.5 * h2 * AM_TO_DOUBLE(m->inv_inertia[AM_VC(m, i)]);
    }
    *e_out = e;
    *v2_out = v2;
}

double am_kinetic_energy(const am_model* m, const am_state* s)
{
    double e, v2;
    motion_sums(m, s, 0, &e, &v2);
    return e * am_unit(m, AM_DIM_ENERGY);
}

/* the elastic energy of the frame element whose forces am_step uses */
double am_strain_energy(const am_model* m, const am_state* s)
{
    double e = 0;
    for (int l = 0; l < m->nl; l++) {
        if (!am_link_live(m, l)) continue;
        link_kin k;
        int axis = link_axis(m, l);
        link_kin_small(m, s, m->lneg[l], m->lpos[l], axis, &k);
        link_kin_large(&k, s->large[l]);
        double rest = AM_TO_DOUBLE(m->L) * 0.5 * (AM_TO_DOUBLE(s->s[m->lneg[l]]) + AM_TO_DOUBLE(s->s[m->lpos[l]]));
        double u = AM_TO_DOUBLE(k.p.x) - rest, y = AM_TO_DOUBLE(k.p.y), z = AM_TO_DOUBLE(k.p.z);
        double t1x = AM_TO_DOUBLE(k.t1.x), t1y = AM_TO_DOUBLE(k.t1.y), t1z = AM_TO_DOUBLE(k.t1.z);
        double t2x = AM_TO_DOUBLE(k.t2.x), t2y = AM_TO_DOUBLE(k.t2.y), t2z = AM_TO_DOUBLE(k.t2.z);
        double b1 = AM_TO_DOUBLE(m->b1[AM_LC(m, l)]), b2 = AM_TO_DOUBLE(m->b2[AM_LC(m, l)]), b3 = AM_TO_DOUBLE(m->b3[AM_LC(m, l)]);
        e += 0.5 * AM_TO_DOUBLE(m->k_ax[AM_LC(m, l)]) * u * u / rest;
        e += 0.5 * b1 * (y * y + z * z) - b2 * y * (t1z + t2z) + b2 * z * (t1y + t2y);
        e += b3 * (t1z * t1z + t1z * t2z + t2z * t2z) + b3 * (t1y * t1y + t1y * t2y + t2y * t2y);
        e += 0.5 * AM_TO_DOUBLE(m->a2[AM_LC(m, l)]) * (t2x - t1x) * (t2x - t1x);
    }
    return e * am_unit(m, AM_DIM_ENERGY);
}

double am_potential_energy(const am_model* m, const am_state* s)
{
    double e = 0;
    for (int i = 0; i < m->nv; i++) {
        const double z = AM_TO_DOUBLE(m->x0[2][i]) + AM_TO_DOUBLE(s->x[2][i]);
        e += AM_TO_DOUBLE(m->mass[AM_VC(m, i)]) * AM_TO_DOUBLE(m->gravity) * z;
        if (m->env.floor) {
            double pen = 0.5 * AM_TO_DOUBLE(s->s[i]) * AM_TO_DOUBLE(m->L) - z;
            if (pen > 0) e += 0.5 * AM_TO_DOUBLE(m->k_floor[AM_VC(m, i)]) * pen * pen;
        }
    }
    return e * am_unit(m, AM_DIM_ENERGY);
}

void am_com(const am_model* m, const am_state* s, double out[3])
{
    double mt = 0, c[3] = {0, 0, 0};
    for (int i = 0; i < m->nv; i++) {
        mt += AM_TO_DOUBLE(m->mass[AM_VC(m, i)]);
        for (int k = 0; k < 3; k++) c[k] += AM_TO_DOUBLE(m->mass[AM_VC(m, i)]) * am_sim_pos(m, s, k, i);
    }
    for (int k = 0; k < 3; k++) out[k] = (mt > 0 ? c[k] / mt : 0) * m->unit_len;
}

void am_momentum(const am_model* m, const am_state* s, double lin[3], double ang[3])
{
    for (int k = 0; k < 3; k++) lin[k] = ang[k] = 0;
    for (int i = 0; i < m->nv; i++) {
        double x = am_sim_pos(m, s, 0, i), y = am_sim_pos(m, s, 1, i), z = am_sim_pos(m, s, 2, i);
        double px = AM_TO_DOUBLE(s->p[0][i]), py = AM_TO_DOUBLE(s->p[1][i]), pz = AM_TO_DOUBLE(s->p[2][i]);
        lin[0] += px; lin[1] += py; lin[2] += pz;
        ang[0] += y * pz - z * py + AM_TO_DOUBLE(s->h[0][i]);
        ang[1] += z * px - x * pz + AM_TO_DOUBLE(s->h[1][i]);
        ang[2] += x * py - y * px + AM_TO_DOUBLE(s->h[2][i]);
    }
    for (int k = 0; k < 3; k++) {
        lin[k] *= am_unit(m, AM_DIM_MOMENTUM);
        ang[k] *= am_unit(m, AM_DIM_ANGMOM);
    }
}

uint64_t am_state_hash(const am_model* m, const am_state* s)
{
    uint64_t h = AM_HASH_INIT;
    h = am_hash_u64(h, (uint64_t)m->nv);
    h = am_hash_u64(h, (uint64_t)s->step);
    h = am_hash_u64(h, (uint64_t)s->diverged);
    for (int i = 0; i < m->nv; i++) {
        for (int c = 0; c < 3; c++) h = am_hash_real(h, s->x[c][i]);
        for (int c = 0; c < 4; c++) h = am_hash_real(h, s->q[c][i]);
        for (int c = 0; c < 3; c++) h = am_hash_real(h, s->p[c][i]);
        for (int c = 0; c < 3; c++) h = am_hash_real(h, s->h[c][i]);
        h = am_hash_u64(h, s->contact[i]);
    }
    return h;
}

void am_record_frame(const am_model* m, const am_state* s, am_record* rec)
{
    if (!rec || rec->every < 1 || s->step % rec->every != 0) return;
    rec->nv = m->nv;
    if (rec->sink) {
        rec->sink(rec->sink_ctx, m, s);
        rec->frames++;
        return;
    }
    long need = (long)(rec->frames + 1) * m->nv * 7;
    if (rec->frames >= rec->max_frames || need > rec->pose_cap || !rec->pose) {
        rec->truncated = 1;
        return;
    }
    float* f = rec->pose + (long)rec->frames * m->nv * 7;
    for (int i = 0; i < m->nv; i++) {
        for (int c = 0; c < 3; c++) f[7 * i + c] = (float)(am_sim_pos(m, s, c, i) * am_unit(m, AM_DIM_LENGTH));
        for (int c = 0; c < 4; c++) f[7 * i + 3 + c] = (float)AM_TO_DOUBLE(s->q[c][i]);
    }
    if (rec->step) rec->step[rec->frames] = s->step;
    rec->frames++;
}

/* a sink's frame at a step that is not a multiple of rec->every (the ends of the segments) */
static void record_extra(const am_model* m, const am_state* s, am_record* rec)
{
    if (!rec || !rec->sink || rec->every < 1 || s->step % rec->every == 0) return;
    rec->sink(rec->sink_ctx, m, s);
    rec->frames++;
}

/* s at the step dt, with the period at that step (am_period_steps, the period's one owner) */
static void run_at(const am_model* m, am_state* s, am_real dt)
{
    s->dt = dt;
    s->period_steps = am_period_steps(m, &m->env, dt);
}

/* 100 steps after every voxel is displaced by up to 2% of L and turned by up to 0.02 rad in a
 * fixed pseudo-random pattern, so that every mode, symmetric or not, starts with a finite
 * amplitude, and with the actuation switched on at its peak; gravity and floor as configured. In a
 * stable damped run the strain energy settles to the level of the thermal and gravity loads; an
 * unstable mode grows by orders of magnitude. */
static int stable_at(const am_model* m, am_state* s, am_real dt)
{
    am_state_reset(m, s);
    run_at(m, s, dt);
    /* the actuation from its peak: a thermal step load on every actuated voxel (large deformations
     * are where a step first fails: the actuated sphere:20 runs stable at rest at 2 dt_rec, and
     * diverges actuated at 1.6) */
    s->actuate = m->any_cte;
    s->actuation_step0 = -(long)(s->period_steps / 4);
    am_rng r;
    am_rng_seed(&r, UINT64_C(0x5eed0f57ab1e));
    const am_real amp = AM_MUL(AM_R(0.02), m->L);
    for (int i = 0; i < m->nv; i++) {
        if (m->fixed[i]) continue;
        for (int k = 0; k < 3; k++) s->x[k][i] += am_rng_range(&r, -amp, amp);
        vec3 rv = v3(am_rng_range(&r, AM_R(-0.02), AM_R(0.02)), am_rng_range(&r, AM_R(-0.02), AM_R(0.02)),
                     am_rng_range(&r, AM_R(-0.02), AM_R(0.02)));
        quat q = q_from_rotvec(rv);
        am_real n = am_sqrt(AM_MUL(q.w, q.w) + v3_dot(v3(q.x, q.y, q.z), v3(q.x, q.y, q.z)));
        s->q[0][i] = AM_DIV(q.w, n);
        s->q[1][i] = AM_DIV(q.x, n);
        s->q[2][i] = AM_DIV(q.y, n);
        s->q[3][i] = AM_DIV(q.z, n);
    }
    double e0 = am_strain_energy(m, s), mid = 0, late = 0;
    for (int n = 0; n < 100 && !s->diverged; n++) {
        am_step(m, s);
        double e = am_strain_energy(m, s);
        if (!(e == e) || e > 1e30) return 0;
        if (n >= 75) late = e > late ? e : late;
        else if (n >= 50) mid = e > mid ? e : mid;
    }
    /* a significant increase: the last quarter more than twice the third and above 1% of the
     * initial perturbation (gravity alone loads the body slowly and stays far below that) */
    return !s->diverged && !(late > 2.0 * mid && late > 0.01 * e0);
}

am_real am_dt_search(const am_model* m, am_state* scratch)
{
    /* coarse pass: from 10 dt_rec down, one order of magnitude apart */
    am_real unstable = AM_R(0), stable = AM_R(0);
    am_real dt = AM_MUL(AM_R(10), m->dt_rec);
    for (int k = 0; k < 6 && stable == AM_R(0); k++) {
        if (stable_at(m, scratch, dt)) stable = dt;
        else {
            unstable = dt;
            dt = AM_DIV(dt, AM_R(10));
        }
    }
    if (stable == AM_R(0)) return AM_MUL(AM_R(0.95), unstable); /* nothing stable: the smallest tried */
    if (unstable != AM_R(0)) {
        /* fine pass: nine values between the last unstable and the first stable one, largest first */
        am_real inc = AM_DIV(unstable - stable, AM_R(10));
        for (int j = 1; j < 10; j++) {
            am_real cand = unstable - AM_MUL(AM_INT(j), inc);
            if (stable_at(m, scratch, cand)) {
                stable = cand;
                break;
            }
        }
    }
    return AM_MUL(AM_R(0.95), stable);
}

/* the kinetic energy (J, as am_kinetic_energy) into *ke and the RMS voxel speed (m/s) into *speed */
static void ke_and_speed(const am_model* m, const am_state* s, double* ke, double* speed)
{
    double e, v2;
    motion_sums(m, s, 1, &e, &v2);
    *ke = e * am_unit(m, AM_DIM_ENERGY);
    *speed = sqrt(v2 / (double)(m->nv)) * am_unit(m, AM_DIM_VELOCITY);
}

/* the calm steps (of the default step) that end settling: the RMS speed below settle_speed */
#define CALM_STEPS 50L

/* every voxel's linear and angular momentum to zero (kinetic damping's stop) */
static void stop_all(const am_model* m, am_state* s)
{
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < m->nv; i++) {
            s->p[c][i] = s->h[c][i] = AM_R(0);
#if !defined(AM_COMPACT)
            s->v[c][i] = s->w[c][i] = AM_R(0);
#endif
#if defined(AM_REAL_FIXED_POINT)
            s->p_rem[c][i] = s->h_rem[c][i] = 0;
#endif
        }
}

/* ---- gait diagnostics ---- */

/* the body's mean orientation: the sum of its voxels' unit quaternions, each taken with the sign
 * that agrees with the first voxel's (q and -q are one orientation), normalised */
static void body_orientation(const am_model* m, const am_state* s, double out[4])
{
    double sum[4] = {0, 0, 0, 0}, first[4] = {1, 0, 0, 0};
    for (int i = 0; i < m->nv; i++) {
        double q[4];
        for (int c = 0; c < 4; c++) q[c] = AM_TO_DOUBLE(s->q[c][i]);
        if (i == 0)
            for (int c = 0; c < 4; c++) first[c] = q[c];
        const double sign = q[0] * first[0] + q[1] * first[1] + q[2] * first[2] + q[3] * first[3] < 0 ? -1.0 : 1.0;
        for (int c = 0; c < 4; c++) sum[c] += sign * q[c];
    }
    const double n = sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2] + sum[3] * sum[3]);
    for (int c = 0; c < 4; c++) out[c] = n > 0 ? sum[c] / n : (c == 0);
}

/* the rotation from orientation a to orientation b (unit quaternions w, x, y, z) as a rotation
 * vector in world axes, axis times angle (rad, 0..pi): d = b conj(a), the shorter way round */
static void turn_vector(const double a[4], const double b[4], double out[3])
{
    double d[4] = {b[0] * a[0] + b[1] * a[1] + b[2] * a[2] + b[3] * a[3],
                   -b[0] * a[1] + b[1] * a[0] - b[2] * a[3] + b[3] * a[2],
                   -b[0] * a[2] + b[1] * a[3] + b[2] * a[0] - b[3] * a[1],
                   -b[0] * a[3] - b[1] * a[2] + b[2] * a[1] + b[3] * a[0]};
    if (d[0] < 0)
        for (int c = 0; c < 4; c++) d[c] = -d[c];
    const double sn = sqrt(d[1] * d[1] + d[2] * d[2] + d[3] * d[3]);
    const double k = sn > 0 ? 2.0 * atan2(sn, d[0]) / sn : 2.0;
    for (int c = 0; c < 3; c++) out[c] = k * d[c + 1];
}

static void gait_begin(const am_model* m, const am_state* s, am_gait* g, const double c0[3])
{
    memset(g, 0, sizeof *g);
    for (int d = 0; d < 3; d++) g->com[0][d] = c0[d];
    body_orientation(m, s, g->quat);
}

/* after step k (0-based) of the movement: the cycle's airborne steps and height range so far, and
 * at the step that ends a cycle, its figures and centre of mass */
static void gait_step(const am_model* m, const am_state* s, am_gait* g, long k)
{
    const long period = s->period_steps;
    const long cyc = k / period, in = k % period;
    if (cyc >= AM_GAIT_MAX_CYCLES) return;
    int touching = 0;
    for (int i = 0; i < m->nv && !touching; i++) touching = s->contact[i] != 0;
    double c[3];
    am_com(m, s, c);
    if (in == 0) {
        g->low = g->high = c[2];
        g->air_steps = 0;
    }
    g->low = c[2] < g->low ? c[2] : g->low;
    g->high = c[2] > g->high ? c[2] : g->high;
    g->air_steps += !touching;
    if (in == period - 1) {
        g->lift[cyc] = g->high - g->low;
        g->airborne[cyc] = (double)g->air_steps / (double)period;
        for (int d = 0; d < 3; d++) g->com[cyc + 1][d] = c[d];
        double q[4];
        body_orientation(m, s, q);
        turn_vector(g->quat, q, g->turn[cyc]);
        for (int d = 0; d < 4; d++) g->quat[d] = q[d];
        g->cycles = (int)cyc + 1;
    }
}

/* the travel from centre of mass a to b, measured as the fitness is */
static double measured_travel(int fitness, const double a[3], const double b[3])
{
    double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
    if (fitness == AM_FIT_PLUS_X) return dx;
    if (fitness == AM_FIT_3D) return sqrt(dx * dx + dy * dy + dz * dz);
    return sqrt(dx * dx + dy * dy);
}

double am_gait_travel(const am_gait* g, int fitness, int k)
{
    return measured_travel(fitness, g->com[k], g->com[k + 1]);
}

void am_gait_summarize(const am_gait* g, int fitness, double voxel_size, am_gait_summary* out)
{
    memset(out, 0, sizeof *out);
    const int n = g->cycles, h = n / 2;
    double net[3] = {0, 0, 0}; /* rad: the sum of the cycles' rotation vectors */
    out->cycles = n;
    for (int k = 0; k < n; k++) {
        double t = am_gait_travel(g, fitness, k);
        out->travel_total += t;
        if (k < h) out->first_half += t;
        if (k >= n - h) out->last_half += t;
        out->airborne += g->airborne[k];
        out->lift += g->lift[k];
        for (int d = 0; d < 3; d++) net[d] += g->turn[k][d];
    }
    if (h > 0) {
        out->first_half /= h;
        out->last_half /= h;
    }
    if (n > 0) {
        out->airborne /= n;
        out->lift /= n;
        out->rotation = sqrt(net[0] * net[0] + net[1] * net[1] + net[2] * net[2]) / n * (180.0 / 3.14159265358979323846);
        /* rolling without slipping about a point on the floor carries the centre of mass its height
         * times the turn about the horizontal axis across the travel (z x the travel's direction);
         * taken over the last half of the cycles, so that a body that only tipped into its pose at
         * the start (and a flop) is not counted as rolling */
        const int k0 = n - h;
        double r[3] = {0, 0, 0};
        for (int k = k0; k < n; k++)
            for (int d = 0; d < 3; d++) r[d] += g->turn[k][d];
        const double hx = g->com[n][0] - g->com[k0][0], hy = g->com[n][1] - g->com[k0][1];
        const double travel = sqrt(hx * hx + hy * hy);
        /* (z x d) . r with d = (hx, hy, 0) / travel: (-hy r_x + hx r_y) / travel */
        out->roll = h > 0 && travel > 0 ? (hx * r[1] - hy * r[0]) / travel * g->com[k0][2] / travel : 0.0;
        out->roll_turn = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]) * (180.0 / 3.14159265358979323846);
    }
    out->sustained = out->first_half > 0 ? out->last_half / out->first_half : 0.0;
    if (n == 0 || out->travel_total / n < AM_GAIT_STILL_FRAC * voxel_size) out->mode = AM_GAIT_STILL;
    else if (h == 0 || out->sustained < AM_GAIT_FLOP_RATIO) out->mode = AM_GAIT_FLOP;
    else if (out->roll >= AM_GAIT_ROLL_SHARE && out->roll_turn >= AM_GAIT_ROLL_MIN_DEG) out->mode = AM_GAIT_ROLL;
    else if (out->airborne >= AM_GAIT_BOUNCE_AIR) out->mode = AM_GAIT_BOUNCE;
    else out->mode = AM_GAIT_SCOOT;
}

const char* am_gait_mode_name(am_gait_mode mode)
{
    static const char* const names[] = {"still", "flop", "scoot", "bounce", "roll"};
    return (unsigned)mode < sizeof names / sizeof names[0] ? names[mode] : "unknown";
}

/* the relaxation's limits, in steps of the run's step (amorph/sim.h: the counts are steps of the
 * default step) */
typedef struct relax_limits {
    long max, min, release, calm;
    am_real dt, dt_settle;   /* the run's step; settling's pseudo-step (>= dt) */
    int period_steps;        /* the run's actuation period (am_evaluate's, from am_period_steps) */
} relax_limits;

/* s back to the start of the evaluation, at the run's step and period */
static void restart(const am_model* m, am_state* s, const relax_limits* lim)
{
    am_state_reset(m, s);
    s->dt = lim->dt;
    s->period_steps = lim->period_steps;
}

/* the relaxation from s's reset state (docs/physics.md, Evaluation): no actuation. Settling:
 * kinetic damping in place of the global damping, at the pseudo-step lim->dt_settle. Every time the
 * kinetic energy passes a peak, all momenta are set to zero, so the body stops near the bottom of
 * each swing and comes to rest in equilibrium in a few swings, while a body that must topple falls
 * at its own pace (the seed's global damping, a drag on every voxel, would make it creep for
 * seconds). The internal damping stays. Once the RMS speed has stayed below settle_speed for
 * lim->calm steps, the release: the model's damping alone, at the run's step, for lim->release
 * steps; the body has settled when the RMS speed stays below settle_speed through it, else settling
 * goes on. Fills out's relaxation fields; s ends at the run's step. */
static void relax(const am_model* m, am_state* s, const am_eval_def* def, const relax_limits* lim, am_record* rec, am_result* out)
{
    const double calm_speed = (double)def->settle_speed;
    long calm = 0, release = -1; /* release: steps into the release window, -1 while settling */
    double ke_prev = 0, worst = 0, speed = 0;
    out->kinetic_resets = 0;
    out->settled = 0;
    s->glob_scale = AM_R(0);
    s->dt = lim->dt_settle;
    s->settle_dt = lim->dt_settle;
    while (s->step < lim->max && !s->diverged) {
        s->settle_steps += release < 0;
        am_step(m, s);
        am_record_frame(m, s, rec);
        double ke;
        ke_and_speed(m, s, &ke, &speed);
        if (release < 0) {
            if (ke < ke_prev) { /* past a peak: stop */
                stop_all(m, s);
                out->kinetic_resets++;
                ke = 0;
            }
            ke_prev = ke;
            calm = speed < calm_speed ? calm + 1 : 0;
            if (calm >= lim->calm && s->step >= lim->min) {
                release = 0;
                worst = 0;
                s->glob_scale = AM_R(1);
                s->dt = lim->dt;
            }
        } else {
            worst = speed > worst ? speed : worst;
            if (!(speed < calm_speed)) { /* moving again: back to settling */
                release = -1;
                calm = 0;
                ke_prev = ke;
                s->glob_scale = AM_R(0);
                s->dt = lim->dt_settle;
            } else if (++release >= lim->release) {
                out->settled = 1;
                break;
            }
        }
    }
    s->dt = lim->dt;
    out->residual_speed = out->settled ? worst : speed;
}

double am_sim_time(const am_model* m, const am_state* s)
{
    return (double)(s->step - s->settle_steps) * am_to_si(m, s->dt, AM_DIM_TIME) + (double)s->settle_steps * am_to_si(m, s->settle_dt, AM_DIM_TIME);
}

/* settling's pseudo-step: relax_dt_frac dt_rec, or the run's step dt when that is larger (or
 * relax_dt_frac is 0) */
static am_real settle_step(const am_model* m, const am_eval_def* def, am_real dt)
{
    if (!(def->relax_dt_frac > AM_P(0))) return dt;
    const am_real d = AM_MUL(AM_PV(def->relax_dt_frac, 1.0), m->dt_rec); /* as am_state_reset's dt */
    return d > dt ? d : dt;
}

double am_eval_max_steps(const am_env* env, const am_eval_def* def, double period_steps, am_eval_cost* cost)
{
    am_eval_cost c;
    /* am_dt_search: at most 6 coarse and 9 fine candidates of 100 steps each */
    c.search = def->dt_search ? 1500.0 : 0.0;
    c.step = def->dt_search ? AM_DT_SEARCH_MIN : AM_PARAM_TO_DOUBLE(env->dt_frac);
    if (!(c.step > 0)) c.step = 1e-300; /* check_env refuses it; the bound stays defined */
    /* settle_step: a pseudo-step above the run's step may fail and the relaxation be done again
     * (a recorded evaluation's first, unrecorded try is the recorded one: it fails or not alike) */
    const double settle = AM_PARAM_TO_DOUBLE(def->relax_dt_frac);
    c.relaxations = settle > 0 && (def->dt_search || settle >= c.step) ? 2 : 1;
    /* am_steps_at: counts of the default step scaled to the step, rounded (up here) */
    const double n = (double)def->relax_max_steps;
    const int at_ref = !def->dt_search && env->dt_frac == AM_P(AM_REF_DT_FRAC); /* the counts as given */
    c.relax = n > 0 ? at_ref ? n : fmax(1.0, ceil(n * AM_REF_DT_FRAC / c.step)) : 0.0;
    /* a period in seconds is period_steps of env's step, more of a smaller searched step: a bound
     * of what am_period_steps gives at the smallest step the search may take (no model here) */
    c.period = period_steps;
    if (def->dt_search && env->period_s > AM_P(0))
        c.period = fmin(1e7, ceil(period_steps * AM_PARAM_TO_DOUBLE(env->dt_frac) / c.step));
    c.move = (double)(def->cycles > 0 ? def->cycles : 0) * c.period;
    c.total = c.search + c.relaxations * c.relax + c.move;
    if (cost) *cost = c;
    return c.total;
}

am_status am_eval_check(const am_env* env, const am_eval_def* def, double period_steps, char* err, int errsz)
{
    am_eval_cost c;
    if (am_eval_max_steps(env, def, period_steps, &c) <= (double)AM_EVAL_MAX_STEPS) return AM_OK;
    return am_fail(err, errsz, AM_ERR_RANGE,
                   "up to %.3g steps an evaluation (%s%d relaxation%s of %.3g: relax_max_steps %ld at %s%.3g dt_rec; %d cycles of "
                   "%.3g), over the budget of %.0e (docs/physics.md)",
                   c.total, c.search > 0 ? "the search, " : "", c.relaxations, c.relaxations > 1 ? "s" : "", c.relax,
                   def->relax_max_steps, def->dt_search ? "a searched step down to " : "", c.step, def->cycles, c.period,
                   (double)AM_EVAL_MAX_STEPS);
}

/* the evaluation up to its movement: the reset, the relaxation (again at the run's step when
 * settling at the pseudo-step failed), the model's damping back; rec as am_evaluate records */
static void settle(const am_model* m, am_state* s, const am_eval_def* def, am_record* rec, am_result* out)
{
    am_real dt = def->dt_search ? am_dt_search(m, s) : AM_R(0);
    am_state_reset(m, s);
    if (def->dt_search) run_at(m, s, dt); /* a period in seconds at the searched step */
    out->dt = am_to_si(m, s->dt, AM_DIM_TIME);
    out->period_steps = s->period_steps;
    /* the relaxation's step counts are steps of the default step (amorph/sim.h) */
    relax_limits lim;
    lim.max = am_steps_at(m, s, def->relax_max_steps);
    lim.min = am_steps_at(m, s, def->relax_min_steps);
    lim.release = am_steps_at(m, s, def->release_steps);
    lim.calm = am_steps_at(m, s, CALM_STEPS);
    lim.dt = s->dt;
    lim.dt_settle = settle_step(m, def, s->dt);
    lim.period_steps = s->period_steps;
    if (rec && lim.dt_settle != lim.dt) {
        /* a recording cannot take frames back: the relaxation is tried without it first, so that
         * a recorded evaluation is the unrecorded one frame for frame */
        relax(m, s, def, &lim, NULL, out);
        if (s->diverged || !out->settled) lim.dt_settle = lim.dt, out->relax_retried = 1;
        restart(m, s, &lim);
    }
    if (rec) {
        rec->frames = 0;
        rec->truncated = 0;
        rec->nv = m->nv;
    }
    am_record_frame(m, s, rec);
    relax(m, s, def, &lim, rec, out);
    if ((s->diverged || !out->settled) && lim.dt_settle != lim.dt) {
        /* the pseudo-step failed this body (it diverged, or never came to rest): the relaxation is
         * done again from the start at the run's step, as if the pseudo-step were off */
        out->relax_retried = 1;
        lim.dt_settle = lim.dt;
        restart(m, s, &lim);
        relax(m, s, def, &lim, rec, out);
    }
    out->relax_dt = am_to_si(m, lim.dt_settle, AM_DIM_TIME);
    s->glob_scale = AM_R(1); /* the movement segment: the model's damping */
    out->relax_steps = s->step;
}

void am_eval_settle(const am_model* m, am_state* s, const am_eval_def* def, am_result* out)
{
    memset(out, 0, sizeof *out);
    out->voxels = m->nv;
    out->links = m->links;
    settle(m, s, def, NULL, out);
    out->steps = s->step;
    out->sim_seconds = am_sim_time(m, s);
}

void am_eval_actuate(am_state* s)
{
    s->actuate = 1;
    s->actuation_step0 = s->step;
}

void am_evaluate(const am_model* m, am_state* s, const am_eval_def* def, am_result* out)
{
    memset(out, 0, sizeof *out);
    out->voxels = m->nv;
    out->links = m->links;
    if (am_eval_max_steps(&m->env, def, (double)m->env.period_steps, NULL) > (double)AM_EVAL_MAX_STEPS) {
        /* over the budget: not run (am_eval_check says why) */
        out->diverged = 1;
        out->fitness = AM_NO_SCORE;
        out->period_steps = m->env.period_steps;
        return;
    }
    am_record* rec = def->record;
    settle(m, s, def, rec, out);
    record_extra(m, s, rec);
    double c0[3], c1[3];
    am_com(m, s, c0);

    /* movement: `cycles` whole actuation periods */
    am_eval_actuate(s);
    long n = (long)def->cycles * s->period_steps;
    am_gait* gait = def->gait;
    if (gait) gait_begin(m, s, gait, c0);
    /* the sustained score's window: from the end of cycle sustained_from */
    const long window = def->sustained_from > 0 ? (long)def->sustained_from * s->period_steps : 0;
    double cs[3] = {c0[0], c0[1], c0[2]};
    for (long k = 0; k < n && !s->diverged; k++) {
        am_step(m, s);
        am_record_frame(m, s, rec);
        if (gait) gait_step(m, s, gait, k);
        if (k + 1 == window) am_com(m, s, cs);
    }
    if (s->step != out->relax_steps) record_extra(m, s, rec);
    out->move_steps = s->step - out->relax_steps;
    out->steps = s->step;
    out->sim_seconds = am_sim_time(m, s);
    out->rebuilds = s->rebuilds;
    out->max_pairs = s->max_npairs;
    am_com(m, s, c1);
    out->dx = c1[0] - c0[0];
    out->dy = c1[1] - c0[1];
    out->dz = c1[2] - c0[2];
    out->diverged = s->diverged;
    if (s->diverged) out->travel = 0.0;
    else if (def->fitness == AM_FIT_PLUS_X) out->travel = out->dx;
    else if (def->fitness == AM_FIT_3D) out->travel = sqrt(out->dx * out->dx + out->dy * out->dy + out->dz * out->dz);
    else out->travel = sqrt(out->dx * out->dx + out->dy * out->dy);
    const long after = (long)def->cycles - (def->sustained_from > 0 ? def->sustained_from : 0);
    out->sustained = !s->diverged && after > 0 ? measured_travel(def->fitness, cs, c1) / (double)after : 0.0;
    /* a body that diverged, or did not come to rest before the actuation started (its travel
     * counts motion the actuation did not make: docs/evolve.md), has no score */
    out->fitness = s->diverged || !out->settled ? AM_NO_SCORE : def->score == AM_SCORE_SUSTAINED ? out->sustained : out->travel;
    out->hash = am_state_hash(m, s);
}
