/* A robot under a controller (amorph/sim.h, Control): what the state looks like to a caller that
 * steps it, and each voxel's actuation set by the caller in place of the sinusoid. The step reads
 * the control in its per-voxel actuation (sim_step.c); the sinusoid's own values for a step come
 * from the same function the step uses, so a controller that feeds them back moves the robot
 * exactly as the open-loop evaluation does. */
#include "sim_internal.h"

#include <math.h>
#include <string.h>

void am_observe(const am_model* m, const am_state* s, am_obs* out, double* pos, double* vel, double* strain, int* contact)
{
    memset(out, 0, sizeof *out);
    out->step = s->step;
    out->time = am_sim_time(m, s);
    out->nv = m->nv;
    out->diverged = s->diverged;
    out->hash = am_state_hash(m, s);
    const double ul = m->unit_len, uv = am_unit(m, AM_DIM_VELOCITY);
    double mt = 0;
    for (int i = 0; i < m->nv; i++) {
        const double mi = AM_TO_DOUBLE(m->mass[AM_VC(m, i)]);
        mt += mi;
        for (int c = 0; c < 3; c++) {
            const double p = am_sim_pos(m, s, c, i) * ul, v = AM_TO_DOUBLE(am_sim_vel(m, s, c, i)) * uv;
            out->com[c] += mi * p;
            out->com_vel[c] += mi * v;
            if (pos) pos[3 * i + c] = p;
            if (vel) vel[3 * i + c] = v;
        }
        if (contact) contact[i] = s->contact[i];
        out->contacts += s->contact[i] != 0;
    }
    for (int c = 0; c < 3; c++) {
        out->com[c] = mt > 0 ? out->com[c] / mt : 0;
        out->com_vel[c] = mt > 0 ? out->com_vel[c] / mt : 0;
    }
    if (!strain) return;
    /* each voxel's axial strain: the mean over its links of centre distance over rest length, less 1 */
    int links[AM_MAX_VOXELS];
    for (int i = 0; i < m->nv; i++) strain[i] = 0, links[i] = 0;
    const double half_L = 0.5 * AM_TO_DOUBLE(m->L);
    for (int l = 0; l < m->nl; l++) {
        if (!am_link_live(m, l)) continue;
        const int a = m->lneg[l], b = m->lpos[l];
        double d2 = 0;
        for (int c = 0; c < 3; c++) {
            const double d = am_sim_pos(m, s, c, b) - am_sim_pos(m, s, c, a);
            d2 += d * d;
        }
        const double rest = half_L * (AM_TO_DOUBLE(s->s[a]) + AM_TO_DOUBLE(s->s[b]));
        const double e = rest > 0 ? sqrt(d2) / rest - 1 : 0;
        strain[a] += e, strain[b] += e;
        links[a]++, links[b]++;
    }
    for (int i = 0; i < m->nv; i++)
        if (links[i]) strain[i] /= links[i];
}
