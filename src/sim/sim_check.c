/* sim_check.c: the invariants of a model and a state (am_model_validate, am_state_validate), and
 * the AM_CHECKS build's hook that runs them after am_model_build and after every am_step. Without
 * AM_CHECKS nothing here is called by the library: the step is compiled exactly as before. */
#include "sim_internal.h"
#include "amorph/base.h"
#include <math.h>

#define FIN(v) isfinite((double)(v))

am_status am_model_validate(const am_model* m, char* err, int errsz)
{
    if (m->nv < 1 || m->nv > AM_MAX_VOXELS) return am_fail(err, errsz, AM_ERR_RANGE, "model: nv %d outside 1..%d", m->nv, AM_MAX_VOXELS);
    if (m->nl < m->nv + 1 || m->nl >= AM_MAX_LINKS)
        return am_fail(err, errsz, AM_ERR_RANGE, "model: nl %d outside %d..%d", m->nl, m->nv + 1, AM_MAX_LINKS - 1);
    if (m->axis_end[0] != m->nv + 1 || m->axis_end[1] < m->axis_end[0] || m->axis_end[1] > m->nl)
        return am_fail(err, errsz, AM_ERR_RANGE, "model: link layout axis_end %d %d for nv %d, nl %d", m->axis_end[0], m->axis_end[1],
                       m->nv, m->nl);
    for (int i = 0; i < m->nv; i++) {
        if (m->mat[i] >= m->palette.count) return am_fail(err, errsz, AM_ERR_RANGE, "model: voxel %d material %d out of range", i, (int)m->mat[i]);
        for (int d = 0; d < 6; d++) {
            const int l = m->slot[d][i];
            if (l < 0 || l > m->nl) return am_fail(err, errsz, AM_ERR_RANGE, "model: voxel %d slot %d link %d out of range", i, d, l);
            if (l < m->nl && (d & 1 ? m->lpos[l] : m->lneg[l]) != i)
                return am_fail(err, errsz, AM_ERR_RANGE, "model: voxel %d slot %d link %d does not end at it", i, d, l);
        }
        for (int k = 0; k < 3; k++)
            if (!FIN(m->x0[k][i])) return am_fail(err, errsz, AM_ERR_RANGE, "model: voxel %d position x0 not finite", i);
        const am_real mass = m->mass[AM_VC(m, i)];
        if (!FIN(mass) || !(mass > 0)) return am_fail(err, errsz, AM_ERR_RANGE, "model: voxel %d mass %g not positive", i, (double)mass);
        if (!FIN(m->inv_mass[AM_VC(m, i)]) || !FIN(m->inv_inertia[AM_VC(m, i)]))
            return am_fail(err, errsz, AM_ERR_RANGE, "model: voxel %d inverse mass or inertia not finite", i);
    }
    for (int l = 0; l < m->axis_end[0]; l++) /* x lanes: am_link_live reads slot[1][lpos[l]] */
        if (m->lpos[l] < 0 || m->lpos[l] > m->nv || m->lneg[l] < 0 || m->lneg[l] > m->nv)
            return am_fail(err, errsz, AM_ERR_RANGE, "model: x lane %d ends %d %d out of range 0..%d", l, (int)m->lneg[l], (int)m->lpos[l], m->nv);
    for (int l = m->axis_end[0]; l < m->nl; l++)
        if (m->lneg[l] < 0 || m->lneg[l] >= m->nv || m->lpos[l] < 0 || m->lpos[l] >= m->nv)
            return am_fail(err, errsz, AM_ERR_RANGE, "model: link %d ends %d %d out of range 0..%d", l, (int)m->lneg[l], (int)m->lpos[l],
                           m->nv - 1);
    for (int l = 0; l <= m->nl; l++) {
        const int c = AM_LC(m, l);
        if (c < 0 || c >= AM_LC_CAP) return am_fail(err, errsz, AM_ERR_RANGE, "model: link %d constant entry %d out of range", l, c);
        if (!FIN(m->k_ax[c]) || !FIN(m->a2[c]) || !FIN(m->b1[c]) || !FIN(m->b2[c]) || !FIN(m->b3[c]) || !FIN(m->c_t[c]))
            return am_fail(err, errsz, AM_ERR_RANGE, "model: link %d stiffness not finite", l);
    }
    if (!FIN(m->dt_rec) || !(m->dt_rec > 0)) return am_fail(err, errsz, AM_ERR_RANGE, "model: time step %g not positive", (double)m->dt_rec);
#if !defined(AM_COMPACT)
    /* a voxel of an actuated material and a phase other than 0 is in the class of both */
    if (m->nphase < 0 || m->nphase > m->nv) return am_fail(err, errsz, AM_ERR_RANGE, "model: %d phase classes for %d voxels", m->nphase, m->nv);
    for (int i = 0; i < m->nv; i++) {
        const int c = m->vphase_class[i], k = m->mat[i];
        const int want = m->vphase[i] != AM_R(0) && m->mat_cte[k] != AM_R(0);
        if (c < -1 || c >= m->nphase || want != (c >= 0) || (c >= 0 && (m->class_mat[c] != k || m->class_phase[c] != m->vphase[i])))
            return am_fail(err, errsz, AM_ERR_RANGE, "model: voxel %d phase class %d is not its material's and phase's", i, c);
    }
#endif
    return AM_OK;
}

am_status am_state_validate(const am_model* m, const am_state* s, char* err, int errsz)
{
    if (!FIN(s->dt) || !(s->dt > 0)) return am_fail(err, errsz, AM_ERR_RANGE, "state: time step %g not positive", (double)s->dt);
    if (s->step < 0) return am_fail(err, errsz, AM_ERR_RANGE, "state: step %ld negative", s->step);
    if (s->diverged) return AM_OK; /* a diverged state is flagged, and left as it stopped */
    for (int i = 0; i < m->nv; i++) {
        for (int k = 0; k < 3; k++) {
            if (!FIN(s->x[k][i])) return am_fail(err, errsz, AM_ERR_RANGE, "state: step %ld voxel %d position not finite", s->step, i);
            if (!FIN(s->p[k][i]) || !FIN(s->h[k][i]))
                return am_fail(err, errsz, AM_ERR_RANGE, "state: step %ld voxel %d momentum not finite", s->step, i);
        }
        for (int k = 0; k < 4; k++)
            if (!FIN(s->q[k][i])) return am_fail(err, errsz, AM_ERR_RANGE, "state: step %ld voxel %d orientation not finite", s->step, i);
        if (!FIN(s->s[i]) || !(s->s[i] > 0)) return am_fail(err, errsz, AM_ERR_RANGE, "state: step %ld voxel %d scale not positive", s->step, i);
    }
    /* each link's rest length, where the link loop reads it (its pair of materials' or its own),
     * is the mean of its two voxels' edges at their current scales, bit for bit */
    const am_real half_L = AM_MUL(AM_R(0.5), m->L);
    for (int l = 0; s->scales_valid && l < m->nl; l++) {
#if defined(AM_COMPACT)
        const int e = m->lpair[l];
#else
        const int e = m->voxel_phase ? s->rest_at[l] : m->lpair[l];
#endif
        if (e < 0 || e >= AM_REST_CAP) return am_fail(err, errsz, AM_ERR_RANGE, "state: step %ld link %d rest length entry %d out of range", s->step, l, e);
        const am_real r = AM_MUL(half_L, s->s[m->lneg[l]] + s->s[m->lpos[l]]);
        if (s->pair_rest[e] != r || s->pair_inv_rest[e] != AM_DIV(AM_R(1), r))
            return am_fail(err, errsz, AM_ERR_RANGE, "state: step %ld link %d rest length %g, its voxels' scales give %g", s->step, l,
                           (double)s->pair_rest[e], (double)r);
    }
    return AM_OK;
}

#if defined(AM_CHECKS)
/* a broken invariant goes to the handler of amorph/base.h (AM_CHECK_HANDLER, as AM_ASSERT) */
void am_check_model(const am_model* m)
{
    char err[AM_ERR_MAX];
    if (am_model_validate(m, err, sizeof err) != AM_OK) AM_CHECK_HANDLER(__FILE__, __LINE__, err);
}

void am_check_state(const am_model* m, const am_state* s)
{
    char err[AM_ERR_MAX];
    if (am_state_validate(m, s, err, sizeof err) != AM_OK) AM_CHECK_HANDLER(__FILE__, __LINE__, err);
}
#endif
