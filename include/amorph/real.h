/* amorph/real.h: the number type of every simulation quantity.
 *
 * am_real is float by default (make REAL=float), double (make REAL=double) or a 32-bit fixed-point
 * integer (make REAL=fixed, docs/fixed.md). All simulation arithmetic goes through am_real and the
 * few macros below so that the fixed-point build is a switch rather than a fork: products and
 * quotients are written AM_MUL / AM_DIV, constants AM_R(1.5) (a constant expression only),
 * integers AM_INT(n), and conversions from and to double AM_FROM_DOUBLE / AM_TO_DOUBLE (never in
 * the per-step hot path).
 *
 * Parameters given by the user in SI units (material moduli, densities, the voxel size, gravity,
 * temperatures) are am_param: am_real in the float and double builds, double in the fixed build,
 * where the model converts them once into its own scaled units (voxel edge, voxel mass, a
 * reference time: include/amorph/sim.h), so that every quantity of a step is O(1).
 *
 * Determinism: only IEEE-exact operations are used (+ - * / sqrt, comparisons). The build uses
 * -ffp-contract=off and never -ffast-math, so every compiler, optimisation level and vector
 * width rounds each operation the same way. The fixed build uses integers only in a step.
 */
#ifndef AMORPH_REAL_H
#define AMORPH_REAL_H

#include <float.h>
#include <math.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Bit-identical results need floating-point arithmetic done in the types the code names: float in
 * float, double in double (FLT_EVAL_METHOD 0). A compiler that evaluates in wider registers (the
 * x87 unit of 32-bit x86: 2; s390x under -std=c11: 1) rounds differently and gives other results,
 * so such a build is refused; docs/porting.md gives the flags that make it 0. */
#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "amorph needs FLT_EVAL_METHOD 0: build x86-32 with -msse2 -mfpmath=sse, s390x with -fexcess-precision=fast (docs/porting.md)"
#endif

/* one number type per build: make REAL=... defines one of these; two would compile one silently */
#if defined(AM_REAL_FLOAT) + defined(AM_REAL_DOUBLE) + defined(AM_REAL_FIXED) > 1
#error "amorph: two number types defined: build with one of AM_REAL_FLOAT, AM_REAL_DOUBLE, AM_REAL_FIXED (make REAL=float|double|fixed)"
#endif

#if defined(AM_REAL_FIXED)
/* Q7.24: value = raw / 2^24, range [-128, 128), resolution 6.0e-8. Products and quotients go
 * through int64_t; AM_MUL rounds half up (adds half an ulp, then shifts arithmetically), AM_DIV
 * rounds half away from zero and saturates. Sums wrap (the build adds -fwrapv); the simulator
 * bounds its state every step so that a physical run never comes near the range. */
#define AM_REAL_FIXED_POINT 1
typedef int32_t am_real;
typedef double am_param;
#define AM_REAL_NAME "fixed"
#ifndef AM_FIX_FRAC
#define AM_FIX_FRAC 24
#endif
#define AM_FIX_ONE ((int32_t)1 << AM_FIX_FRAC)
#define AM_FIX_HALF ((int64_t)1 << (AM_FIX_FRAC - 1))
/* a constant (a constant expression: folded at compile time), rounded to nearest */
#define AM_R(c) ((am_real)((c) * (double)AM_FIX_ONE + ((c) < 0 ? -0.5 : 0.5)))
#define AM_P(c) ((am_param)(c))
#define AM_INT(n) ((am_real)((int32_t)(n) * AM_FIX_ONE)) /* |n| < 128 */
/* a / n and p / q for integers n, p, q (q > 0), rounded half away from zero */
#define AM_DIV_INT(a, n) ((am_real)am_fx_div_i64((int64_t)(a), (int64_t)(n)))
#define AM_RATIO(p, q) ((am_real)am_fx_div_i64((int64_t)(p) * AM_FIX_ONE, (int64_t)(q)))
/* a * n for an integer n, saturated */
#define AM_MUL_INT(a, n) am_fx_sat64((int64_t)(a) * (int64_t)(n))
#define AM_REAL_MAX ((am_real)INT32_MAX)
#define AM_REAL_EPS ((am_real)1)
static inline am_real am_fx_mul(am_real a, am_real b) { return (am_real)(((int64_t)a * b + AM_FIX_HALF) >> AM_FIX_FRAC); }
static inline am_real am_fx_sat64(int64_t v) { return v > INT32_MAX ? INT32_MAX : (v < -INT32_MAX ? -INT32_MAX : (am_real)v); }
static inline int64_t am_fx_div_i64(int64_t n, int64_t d) { return (n >= 0 ? n + d / 2 : n - d / 2) / d; }
static inline am_real am_fx_div(am_real a, am_real b)
{
    int64_t n = (int64_t)a * AM_FIX_ONE, d = b;
    if (d == 0) return a >= 0 ? INT32_MAX : -INT32_MAX;
    int64_t h = (d < 0 ? -d : d) / 2;
    int64_t q = (n >= 0 ? n + h : n - h) / d;
    return q > INT32_MAX ? INT32_MAX : (q < -INT32_MAX ? -INT32_MAX : (am_real)q);
}
am_real am_fx_sqrt(am_real x); /* util_math.c: the root rounded to nearest, 0 for x <= 0 */
/* a product kept whole (Q14.48 in int64_t), for squared norms of small vectors (friction forces
 * and speeds, whose squares would fall below the Q24 resolution) and exact sign tests */
typedef int64_t am_wide;
#define AM_MULW(a, b) ((int64_t)(a) * (b))
am_real am_fx_sqrt_wide(am_wide w); /* the root of a wide value, as am_real, rounded to nearest */
#define AM_WIDE_SQRT(w) am_fx_sqrt_wide(w)

#define AM_MUL(a, b) am_fx_mul((a), (b))
#define AM_DIV(a, b) am_fx_div((a), (b))
#define am_sqrt(x) am_fx_sqrt(x)
#define am_fabs(x) am_fx_abs(x)
#define am_floor(x) am_fx_floor(x)
static inline am_real am_fx_abs(am_real x) { return x < 0 ? -x : x; }
static inline am_real am_fx_floor(am_real x) { return (am_real)(x & ~(AM_FIX_ONE - 1)); }
/* the whole part of x (floor), as an integer */
#define AM_FLOOR_INT(x) ((int32_t)((x) >> AM_FIX_FRAC))
#define AM_TO_DOUBLE(x) ((double)(x) * (1.0 / (double)AM_FIX_ONE))
static inline am_real am_fx_from_double(double d)
{
    double r = d * (double)AM_FIX_ONE;
    if (!(r == r)) return 0;
    if (r >= 2147483647.0) return INT32_MAX;
    if (r <= -2147483647.0) return -INT32_MAX;
    return (am_real)(r < 0 ? r - 0.5 : r + 0.5);
}
#define AM_FROM_DOUBLE(d) am_fx_from_double(d)
#define AM_PARAM_TO_DOUBLE(p) ((double)(p))
#define AM_PARAM_FROM_DOUBLE(d) ((am_param)(d))
/* 1: every fixed-point value is finite */
static inline int am_finite(am_real x) { (void)x; return 1; }
#define AM_ISNAN(x) 0
static inline int am_param_finite(am_param x) { return (x - x) == (x - x) && (x - x) == 0.0; }
#else
#if defined(AM_REAL_DOUBLE)
typedef double am_real;
#define AM_REAL_NAME "double"
#define am_sqrt(x) sqrt(x)
#define am_fabs(x) fabs(x)
#define am_floor(x) floor(x)
#define AM_REAL_MAX 1.0e300
#define AM_REAL_EPS 2.220446049250313e-16
#else
typedef float am_real;
#define AM_REAL_NAME "float"
#define am_sqrt(x) sqrtf(x)
#define am_fabs(x) fabsf(x)
#define am_floor(x) floorf(x)
#define AM_REAL_MAX 1.0e30f
#define AM_REAL_EPS 1.1920929e-07f
#endif
typedef am_real am_param;
#define AM_R(c) ((am_real)(c))
#define AM_P(c) ((am_param)(c))
#define AM_INT(n) ((am_real)(n))
typedef am_real am_wide;
#define AM_MULW(a, b) AM_MUL((a), (b))
#define AM_WIDE_SQRT(w) am_sqrt(w)
#define AM_DIV_INT(a, n) AM_DIV((a), (am_real)(n))
#define AM_RATIO(p, q) AM_DIV((am_real)(p), (am_real)(q))
#define AM_MUL_INT(a, n) AM_MUL((am_real)(n), (a))
#define AM_MUL(a, b) ((a) * (b))
#define AM_DIV(a, b) ((a) / (b))
#define AM_FLOOR_INT(x) ((int32_t)am_floor(x))
#define AM_TO_DOUBLE(x) ((double)(x))
#define AM_FROM_DOUBLE(d) ((am_real)(d))
#define AM_PARAM_TO_DOUBLE(p) ((double)(p))
#define AM_PARAM_FROM_DOUBLE(d) ((am_param)(d))
/* 1 when x is neither NaN nor infinite (IEEE: x - x is 0 only for finite x) */
static inline int am_finite(am_real x) { return (x - x) == (x - x) && (x - x) == AM_R(0); }
static inline int am_param_finite(am_param x) { return am_finite(x); }
#define AM_ISNAN(x) ((x) != (x))
#endif

#define AM_PI AM_R(3.14159265358979323846)

static inline am_real am_min(am_real a, am_real b) { return a < b ? a : b; }
static inline am_real am_max(am_real a, am_real b) { return a > b ? a : b; }
static inline am_real am_clamp(am_real x, am_real lo, am_real hi) { return x < lo ? lo : (x > hi ? hi : x); }

#ifdef __cplusplus
}
#endif
#endif
