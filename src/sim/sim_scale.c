/* sim_scale.c: the actuation's law, a voxel's linear scale at a temperature and its rate of
 * change. The step owns it (sim_step.c applies it once per material every step); the model build
 * only asks it for the largest scale the actuation can reach (am_model.max_scale). A file of its
 * own, so the step depends on no model-building code. */
#include "sim_internal.h"
#include "amorph/base.h"

am_real am_sim_scale(int cte_mode, am_real cte, am_real T)
{
    am_real arg = AM_R(1) + AM_MUL(cte, T);
    if (arg < AM_R(0.01)) arg = AM_R(0.01); /* a voxel never shrinks to nothing */
    return cte_mode == AM_CTE_LINEAR ? arg : am_cbrt(arg);
}

am_real am_sim_scale_rate(int cte_mode, am_real cte, am_real T, am_real dT, am_real s)
{
    if (AM_R(1) + AM_MUL(cte, T) < AM_R(0.01)) return AM_R(0); /* clamped: the scale holds */
    const am_real a = AM_MUL(cte, dT); /* the change of 1 + cte T */
    return cte_mode == AM_CTE_LINEAR ? a : AM_DIV(a, AM_MUL(AM_R(3), AM_MUL(s, s)));
}
