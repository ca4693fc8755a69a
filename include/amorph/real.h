/* amorph/real.h: the number type of every simulation quantity.
 *
 * am_real is float by default (make REAL=float) or double (make REAL=double). All simulation
 * arithmetic goes through am_real and the few macros below so that a fixed-point build can be
 * a switch rather than a fork: products and quotients are written AM_MUL / AM_DIV where a
 * fixed-point type would need rescaling, constants are AM_R(1.5).
 *
 * Determinism: only IEEE-exact operations are used (+ - * / sqrt, comparisons). The build uses
 * -ffp-contract=off and never -ffast-math, so every compiler, optimisation level and vector
 * width rounds each operation the same way.
 */
#ifndef AMORPH_REAL_H
#define AMORPH_REAL_H

#include <math.h>
#include <stdint.h>

#if defined(AM_REAL_DOUBLE)
typedef double am_real;
#define AM_REAL_NAME "double"
#define AM_R(c) ((am_real)(c))
#define am_sqrt(x) sqrt(x)
#define am_fabs(x) fabs(x)
#define am_floor(x) floor(x)
#define AM_REAL_MAX 1.0e300
#define AM_REAL_EPS 2.220446049250313e-16
#else
typedef float am_real;
#define AM_REAL_NAME "float"
#define AM_R(c) ((am_real)(c))
#define am_sqrt(x) sqrtf(x)
#define am_fabs(x) fabsf(x)
#define am_floor(x) floorf(x)
#define AM_REAL_MAX 1.0e30f
#define AM_REAL_EPS 1.1920929e-07f
#endif

#define AM_MUL(a, b) ((a) * (b))
#define AM_DIV(a, b) ((a) / (b))
#define AM_PI AM_R(3.14159265358979323846)

/* 1 when x is neither NaN nor infinite (IEEE: x - x is 0 only for finite x) */
static inline int am_finite(am_real x) { return (x - x) == (x - x) && (x - x) == AM_R(0); }
static inline am_real am_min(am_real a, am_real b) { return a < b ? a : b; }
static inline am_real am_max(am_real a, am_real b) { return a > b ? a : b; }
static inline am_real am_clamp(am_real x, am_real lo, am_real hi) { return x < lo ? lo : (x > hi ? hi : x); }

#endif
