/* amorph/mathx.h: deterministic elementary functions (am_ prefix: pure utilities).
 *
 * libm's sin, cos, exp, pow and cbrt differ between C libraries and versions in the last bit,
 * which would break bit-identical results across platforms. These are written from + - * / and
 * sqrt in a fixed order, so every platform computes the same bits. Accuracy: a few ulp of am_real
 * over the documented range; they are not for the hot loop (the simulator calls them once per
 * material per step at most).
 */
#ifndef AMORPH_MATHX_H
#define AMORPH_MATHX_H

#include "amorph/real.h"

#ifdef __cplusplus
extern "C" {
#endif

am_real am_sin(am_real x);            /* any finite x (radians) */
am_real am_cos(am_real x);            /* any finite x (radians) */
am_real am_exp(am_real x);            /* x in [-80, 80]; clamps outside */
am_real am_log(am_real x);            /* x > 0; returns -AM_REAL_MAX for x <= 0 */
am_real am_cbrt(am_real x);           /* any finite x */
am_real am_pow(am_real x, am_real y); /* x > 0 */
am_real am_atan2(am_real y, am_real x); /* radians in (-pi, pi] */
am_real am_acos(am_real x);           /* x clamped to [-1, 1] */

#ifdef __cplusplus
}
#endif
#endif
