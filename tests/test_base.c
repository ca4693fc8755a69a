/* Tests of the numbers layer: the deterministic elementary functions (src/base/base_math.c) against
 * libm, and the seeded random stream and hashes (src/base/base_rng.c); and of the text buffer
 * (src/base/base_text.c) and the quoting of input in messages (am_quote, src/base/base_status.c).
 *
 * Tolerances, in units in the last place of am_real at the libm (double) reference value:
 *   float build:  1 ulp for every function (they compute in double and round once);
 *   double build: 8 ulp for sin, cos, exp, log, cbrt, atan2, acos (measured at most 6), and
 *                 8 + 3 |y ln x| ulp for pow = exp(y log x), whose relative error grows with
 *                 the size of the exponent (measured 27 ulp at |y ln x| = 10).
 * Golden values pin the random stream (and a hash of sampled function values): they must never
 * change; a deliberate change is explained in the commit that makes it. */
#include "amorph.h"
#include "harness.h"

#include <float.h>
#include <stdint.h>
#include <string.h>

#if defined(AM_REAL_FIXED_POINT)
/* the fixed-point build (docs/fixed.md) has its own tests of the functions below */
#elif defined(AM_REAL_DOUBLE)
#define TOL_ULP 8.0
#define REAL_MANT 53
#define REAL_MIN_NORMAL DBL_MIN
#else
#define TOL_ULP 1.0
#define REAL_MANT 24
#define REAL_MIN_NORMAL ((double)FLT_MIN)
#endif

#if defined(AM_REAL_FIXED_POINT)
/* Q7.24: errors in units of the last place (2^-24), over the range each function's result fits */
static double fx_err(am_real got, double ref) { return fabs(AM_TO_DOUBLE(got) - ref) * (double)AM_FIX_ONE; }
static am_real fx_sample(double lo, double hi, long i, long n) { return AM_FROM_DOUBLE(lo + (hi - lo) * (double)i / (double)n); }

/* measured worst errors (ulp): sin, cos, log, cbrt, sqrt, atan2 0.6; exp 1.7 (near e^4.8 = 128);
 * acos 2.4 (near +-1, where the root of 1 - x^2 magnifies the argument's rounding); tolerances
 * are those plus margin */
static void test_fixed_functions(void)
{
    double e[9] = {0};
    const long n = test_quick() ? 20000 : 200000;
    for (long i = 0; i <= n; i++) {
        am_real x = fx_sample(-100.0, 100.0, i, n);
        double xd = AM_TO_DOUBLE(x);
        e[0] = fmax(e[0], fx_err(am_sin(x), sin(xd)));
        e[1] = fmax(e[1], fx_err(am_cos(x), cos(xd)));
        am_real xe = fx_sample(-16.0, 4.8, i, n);
        e[2] = fmax(e[2], fx_err(am_exp(xe), exp(AM_TO_DOUBLE(xe))));
        am_real p = fx_sample(1e-6, 127.0, i, n);
        e[3] = fmax(e[3], fx_err(am_log(p), log(AM_TO_DOUBLE(p))));
        e[4] = fmax(e[4], fx_err(am_cbrt(x), cbrt(xd)));
        e[5] = fmax(e[5], fx_err(am_sqrt(p), sqrt(AM_TO_DOUBLE(p))));
        am_real y = fx_sample(-3.0, 3.0, i % 97, 96);
        e[6] = fmax(e[6], fx_err(am_atan2(y, x), atan2(AM_TO_DOUBLE(y), xd)));
        am_real u = fx_sample(-1.0, 1.0, i, n);
        e[7] = fmax(e[7], fx_err(am_acos(u), acos(AM_TO_DOUBLE(u))));
        am_real b = fx_sample(0.05, 4.0, i, n), ex = fx_sample(-2.0, 3.0, i % 101, 100);
        double ref = pow(AM_TO_DOUBLE(b), AM_TO_DOUBLE(ex));
        if (ref < 100.0) e[8] = fmax(e[8], fx_err(am_pow(b, ex), ref) / fmax(1.0, ref));
    }
    static const char* const name[9] = {"sin", "cos", "exp", "log", "cbrt", "sqrt", "atan2", "acos", "pow (relative)"};
    static const double tol[9] = {1.0, 1.0, 2.0, 1.0, 1.0, 0.5, 1.0, 3.0, 4.0};
    for (int k = 0; k < 9; k++) CHECK(e[k] <= tol[k], "am_%s: %.2f ulp (tolerance %.1f)", name[k], e[k], tol[k]);
}

static void test_fixed_special_values(void)
{
    CHECK(am_sin(AM_R(0)) == AM_R(0) && am_cos(AM_R(0)) == AM_R(1), "sin 0, cos 0");
    CHECK(am_exp(AM_R(0)) == AM_R(1) && am_log(AM_R(1)) == AM_R(0), "exp 0, log 1");
    CHECK(am_cbrt(AM_R(8)) == AM_R(2) && am_cbrt(AM_R(-27)) == AM_R(-3), "cbrt 8, cbrt -27");
    CHECK(am_sqrt(AM_R(4)) == AM_R(2) && am_sqrt(AM_R(0)) == 0 && am_sqrt(AM_R(-1)) == 0, "sqrt 4, 0, -1");
    CHECK(am_atan2(AM_R(0), AM_R(-1)) == AM_PI && am_atan2(AM_R(1), AM_R(0)) == AM_R(1.5707963267948966), "atan2 edges");
    CHECK(am_acos(AM_R(1)) == 0 && am_acos(AM_R(-1)) == AM_PI && am_acos(AM_R(2)) == 0, "acos edges and clamp");
    CHECK(am_log(0) == -AM_REAL_MAX && am_exp(AM_R(10)) == AM_REAL_MAX && am_exp(AM_R(-20)) == 0, "log 0, exp saturates");
    CHECK(am_sin(AM_R(-3)) == -am_sin(AM_R(3)) && am_cos(AM_R(-3)) == am_cos(AM_R(3)), "symmetry");
    /* the arithmetic: rounding half up, quotients half away from zero and saturated */
    CHECK(AM_MUL(AM_R(1.5), AM_R(-2)) == AM_R(-3) && AM_MUL(1, AM_FIX_ONE / 2) == 1 && AM_MUL(-1, AM_FIX_ONE / 2) == 0,
          "AM_MUL rounds half up");
    CHECK(AM_DIV(AM_R(1), AM_R(3)) == 5592405 && AM_DIV(AM_R(-1), AM_R(3)) == -5592405, "AM_DIV rounds to nearest");
    CHECK(AM_DIV(AM_R(100), AM_R(0.01)) == INT32_MAX && AM_DIV(AM_R(1), 0) == INT32_MAX, "AM_DIV saturates");
    CHECK(AM_FROM_DOUBLE(1e10) == INT32_MAX && AM_FROM_DOUBLE(-1e10) == -INT32_MAX && AM_FROM_DOUBLE(0.5) == AM_FIX_ONE / 2,
          "AM_FROM_DOUBLE saturates");
    CHECK(AM_WIDE_SQRT(AM_MULW(AM_R(3e-4), AM_R(3e-4)) + AM_MULW(AM_R(4e-4), AM_R(4e-4))) == AM_R(5e-4), "wide norm of small values");
    CHECK(am_floor(AM_R(-0.5)) == AM_R(-1) && AM_FLOOR_INT(AM_R(2.75)) == 2 && AM_FLOOR_INT(AM_R(-2.25)) == -3, "floor");
}

static void test_math_golden_hash(void)
{
    uint64_t h = AM_HASH_INIT;
    for (int i = 0; i <= 2000; i++) {
        am_real x = fx_sample(-50.0, 50.0, i, 2000), p = fx_sample(0.001, 30.0, i, 2000), u = fx_sample(-1.0, 1.0, i, 2000);
        h = am_hash_real(h, am_sin(x));
        h = am_hash_real(h, am_cos(x));
        h = am_hash_real(h, am_exp(AM_DIV_INT(x, 12)));
        h = am_hash_real(h, am_log(p));
        h = am_hash_real(h, am_cbrt(x));
        h = am_hash_real(h, am_pow(p, u));
        h = am_hash_real(h, am_atan2(x, u));
        h = am_hash_real(h, am_acos(u));
        h = am_hash_real(h, am_sqrt(p));
    }
    const uint64_t want = UINT64_C(0x0579d625aa839f9d);
    CHECK(h == want, "math golden hash %016llx, want %016llx", (unsigned long long)h, (unsigned long long)want);
}
#else
/* one ulp of am_real at the value ref (subnormal spacing below the smallest normal) */
static double ulp_at(double ref)
{
    int e;
    double a = fabs(ref);
    if (a < REAL_MIN_NORMAL) a = REAL_MIN_NORMAL;
    frexp(a, &e);
    return ldexp(1.0, e - REAL_MANT);
}

static double ulps(am_real got, double ref) { return fabs((double)got - ref) / ulp_at(ref); }

typedef struct worst {
    double err, at, at2;
} worst;

static void note(worst* w, double err, double at, double at2)
{
    if (err > w->err) {
        w->err = err;
        w->at = at;
        w->at2 = at2;
    }
}

/* n + 1 evenly spaced am_real points over [lo, hi] */
static am_real sample(double lo, double hi, long i, long n) { return (am_real)(lo + (hi - lo) * (double)i / (double)n); }

static long points(void) { return test_quick() ? 20000 : 400000; }

static void test_sin_cos(void)
{
    worst ws = {0, 0, 0}, wc = {0, 0, 0};
    long n = points();
    int odd = 0, even = 0;
    for (long i = 0; i <= n; i++) {
        am_real x = sample(-100.0, 100.0, i, n);
        note(&ws, ulps(am_sin(x), sin((double)x)), (double)x, 0);
        note(&wc, ulps(am_cos(x), cos((double)x)), (double)x, 0);
        odd += am_sin(-x) != -am_sin(x);
        even += am_cos(-x) != am_cos(x);
    }
    CHECK(ws.err <= TOL_ULP, "am_sin: %.2f ulp at x = %.17g", ws.err, ws.at);
    CHECK(wc.err <= TOL_ULP, "am_cos: %.2f ulp at x = %.17g", wc.err, wc.at);
    CHECK(odd == 0 && even == 0, "symmetry broken: %d odd, %d even", odd, even);
    /* near multiples of pi/2, where the reduction matters */
    worst wr = {0, 0, 0};
    for (int k = -60; k <= 60; k++) {
        am_real x = (am_real)(1.5707963267948966 * (double)k);
        double abs_err = fabs((double)am_sin(x) - sin((double)x)) + fabs((double)am_cos(x) - cos((double)x));
        note(&wr, abs_err, (double)x, 0);
    }
    CHECK(wr.err <= 4.0 * (double)AM_REAL_EPS, "near k pi/2: absolute error %.3g at %.17g", wr.err, wr.at);
}

static void test_exp_log(void)
{
    worst we = {0, 0, 0}, wl = {0, 0, 0}, ws = {0, 0, 0};
    long n = points();
    for (long i = 0; i <= n; i++) {
        am_real x = sample(-20.0, 20.0, i, n);
        note(&we, ulps(am_exp(x), exp((double)x)), (double)x, 0);
        /* log over many decades: x = 10^t for t in [-30, 30] */
        am_real y = (am_real)pow(10.0, -30.0 + 60.0 * (double)i / (double)n);
        note(&wl, ulps(am_log(y), log((double)y)), (double)y, 0);
        /* and densely around 1, where log is small */
        am_real z = sample(0.5, 2.0, i, n);
        if (z != AM_R(1)) note(&ws, ulps(am_log(z), log((double)z)), (double)z, 0);
    }
    CHECK(we.err <= TOL_ULP, "am_exp: %.2f ulp at x = %.17g", we.err, we.at);
    CHECK(wl.err <= TOL_ULP, "am_log: %.2f ulp at x = %.17g", wl.err, wl.at);
    CHECK(ws.err <= TOL_ULP, "am_log near 1: %.2f ulp at x = %.17g", ws.err, ws.at);
}

static void test_cbrt_pow(void)
{
    worst wc = {0, 0, 0}, wp = {0, 0, 0};
    long n = points();
    for (long i = 0; i <= n; i++) {
        am_real x = sample(-1000.0, 1000.0, i, n);
        note(&wc, ulps(am_cbrt(x), cbrt((double)x)), (double)x, 0);
        am_real tiny = (am_real)pow(10.0, -30.0 + 60.0 * (double)i / (double)n);
        note(&wc, ulps(am_cbrt(tiny), cbrt((double)tiny)), (double)tiny, 0);
    }
    CHECK(wc.err <= TOL_ULP, "am_cbrt: %.2f ulp at x = %.17g", wc.err, wc.at);
    /* pow on a grid of bases and exponents; the tolerance grows with |y ln x| in double */
    static const double ys[] = {-3.0, -1.0, -0.5, 1.0 / 3.0, 0.5, 1.0, 2.0, 2.5, 7.0};
    long m = n / 10;
    double worst_ratio = 0;
    for (size_t j = 0; j < sizeof ys / sizeof ys[0]; j++)
        for (long i = 0; i <= m; i++) {
            am_real x = sample(0.01, 10.0, i, m), y = (am_real)ys[j];
            double ref = pow((double)x, (double)y);
            double tol = TOL_ULP;
#if defined(AM_REAL_DOUBLE)
            tol += 3.0 * fabs((double)y * log((double)x));
#endif
            double e = ulps(am_pow(x, y), ref);
            if (e / tol > worst_ratio) {
                worst_ratio = e / tol;
                wp.err = e;
                wp.at = (double)x;
                wp.at2 = (double)y;
            }
        }
    CHECK(worst_ratio <= 1.0, "am_pow: %.2f ulp at x = %.17g, y = %.17g", wp.err, wp.at, wp.at2);
}

static void test_atan2_acos(void)
{
    worst wa = {0, 0, 0}, wc = {0, 0, 0};
    long n = points() / 4;
    static const double xs[] = {-10.0, -0.7, -1e-3, 1e-3, 0.7, 10.0};
    for (size_t j = 0; j < sizeof xs / sizeof xs[0]; j++)
        for (long i = 0; i <= n; i++) {
            am_real y = sample(-10.0, 10.0, i, n), x = (am_real)xs[j];
            note(&wa, ulps(am_atan2(y, x), atan2((double)y, (double)x)), (double)y, (double)x);
            note(&wa, ulps(am_atan2(x, y), atan2((double)x, (double)y)), (double)x, (double)y);
        }
    for (long i = 0; i <= 4 * n; i++) {
        am_real x = sample(-1.0, 1.0, i, 4 * n);
        note(&wc, ulps(am_acos(x), acos((double)x)), (double)x, 0);
    }
    CHECK(wa.err <= TOL_ULP, "am_atan2: %.2f ulp at y = %.17g, x = %.17g", wa.err, wa.at, wa.at2);
    CHECK(wc.err <= TOL_ULP, "am_acos: %.2f ulp at x = %.17g", wc.err, wc.at);
}

static void test_special_values(void)
{
    CHECK(am_sin(AM_R(0)) == AM_R(0), "sin 0");
    CHECK(am_cos(AM_R(0)) == AM_R(1), "cos 0");
    CHECK(am_exp(AM_R(0)) == AM_R(1), "exp 0");
    CHECK(am_log(AM_R(1)) == AM_R(0), "log 1");
    CHECK(am_cbrt(AM_R(0)) == AM_R(0), "cbrt 0");
    CHECK(ulps(am_cbrt(AM_R(8)), 2.0) <= 1.0, "cbrt 8 = %.17g", (double)am_cbrt(AM_R(8)));
    CHECK(ulps(am_cbrt(AM_R(-27)), -3.0) <= 1.0, "cbrt -27 = %.17g", (double)am_cbrt(AM_R(-27)));
    CHECK(ulps(am_cbrt(AM_R(1e-6)), 0.01) <= 1.0, "cbrt 1e-6 = %.17g", (double)am_cbrt(AM_R(1e-6)));
    CHECK(ulps(am_pow(AM_R(2), AM_R(10)), 1024.0) <= TOL_ULP, "pow 2^10 = %.17g", (double)am_pow(AM_R(2), AM_R(10)));
    CHECK(am_pow(AM_R(5), AM_R(0)) == AM_R(1), "pow x^0");
    CHECK(ulps(am_exp(AM_R(1)), 2.718281828459045) <= TOL_ULP, "e");
    CHECK(ulps(am_sin(AM_PI / AM_R(6)), sin((double)(AM_PI / AM_R(6)))) <= TOL_ULP, "sin pi/6");
    /* atan2 and acos at their edges: pi and pi/2 to the am_real nearest */
    CHECK(am_atan2(AM_R(0), AM_R(-1)) == AM_PI, "atan2(0, -1) = %.17g", (double)am_atan2(AM_R(0), AM_R(-1)));
    CHECK(am_atan2(AM_R(1), AM_R(0)) == AM_PI / AM_R(2), "atan2(1, 0)");
    CHECK(am_atan2(AM_R(-1), AM_R(0)) == -AM_PI / AM_R(2), "atan2(-1, 0)");
    CHECK(am_atan2(AM_R(0), AM_R(0)) == AM_R(0), "atan2(0, 0)");
    CHECK(am_atan2(AM_R(0), AM_R(1)) == AM_R(0), "atan2(0, 1)");
    CHECK(am_acos(AM_R(1)) == AM_R(0), "acos 1");
    CHECK(am_acos(AM_R(-1)) == AM_PI, "acos -1");
    CHECK(am_acos(AM_R(0)) == AM_PI / AM_R(2), "acos 0");
    CHECK(am_acos(AM_R(2)) == AM_R(0) && am_acos(AM_R(-2)) == AM_PI, "acos clamps");
    /* documented edges: log of x <= 0, exp clamped outside [-80, 80] */
    CHECK(am_log(AM_R(0)) == -AM_REAL_MAX && am_log(AM_R(-3)) == -AM_REAL_MAX, "log of x <= 0");
    CHECK(am_exp(AM_R(100)) == am_exp(AM_R(80)) && am_finite(am_exp(AM_R(100))), "exp clamps above 80");
    CHECK(am_exp(AM_R(-100)) == am_exp(AM_R(-80)) && am_exp(AM_R(-80)) > AM_R(0), "exp clamps below -80");
    /* far arguments stay finite and bounded (deterministic, not accurate) */
    static const double far[] = {1e7, -3e9, 1e19, -1e30, 3e38};
    for (size_t i = 0; i < sizeof far / sizeof far[0]; i++) {
        am_real s = am_sin((am_real)far[i]), c = am_cos((am_real)far[i]);
        CHECK(am_finite(s) && am_finite(c) && am_fabs(s) <= AM_R(1) && am_fabs(c) <= AM_R(1), "sin/cos(%g) = %g, %g", far[i],
              (double)s, (double)c);
    }
    /* infinity must not hang log or cbrt */
    am_real inf = (am_real)HUGE_VAL;
    CHECK(!(am_log(inf) < AM_R(0)), "log inf");
    CHECK(!am_finite(am_sin(inf)), "sin inf is NaN");
}

/* a hash of sampled values of every function: the bits must not drift between builds or
 * platforms of one am_real type */
static void test_math_golden_hash(void)
{
    uint64_t h = AM_HASH_INIT;
    for (int i = 0; i <= 2000; i++) {
        am_real x = sample(-50.0, 50.0, i, 2000), p = sample(0.001, 30.0, i, 2000), u = sample(-1.0, 1.0, i, 2000);
        h = am_hash_real(h, am_sin(x));
        h = am_hash_real(h, am_cos(x));
        h = am_hash_real(h, am_exp(x));
        h = am_hash_real(h, am_log(p));
        h = am_hash_real(h, am_cbrt(x));
        h = am_hash_real(h, am_pow(p, u));
        h = am_hash_real(h, am_atan2(x, u));
        h = am_hash_real(h, am_acos(u));
    }
#if defined(AM_REAL_DOUBLE)
    const uint64_t want = UINT64_C(0x0be0b5eb61be79ec);
#else
    const uint64_t want = UINT64_C(0x94c44732ff8dcea0);
#endif
    CHECK(h == want, "math golden hash %016llx, want %016llx", (unsigned long long)h, (unsigned long long)want);
}

#endif

/* ---- the random stream ----------------------------------------------------------------- */

/* xoshiro256** and splitmix64 written again from the published reference code */
static uint64_t ref_rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

static void test_rng_golden(void)
{
    static const uint64_t golden[8] = {
        UINT64_C(0xb3f2af6d0fc710c5), UINT64_C(0x853b559647364cea), UINT64_C(0x92f89756082a4514), UINT64_C(0x642e1c7bc266a3a7),
        UINT64_C(0xb27a48e29a233673), UINT64_C(0x24c123126ffda722), UINT64_C(0x123004ef8df510e6), UINT64_C(0x61954dcc47b1e89d),
    };
    am_rng r;
    am_rng_seed(&r, 1);
    for (int i = 0; i < 8; i++) {
        uint64_t v = am_rng_u64(&r);
        CHECK(v == golden[i], "output %d of seed 1: %016llx, want %016llx", i, (unsigned long long)v, (unsigned long long)golden[i]);
    }
    /* splitmix64's published first output for seed 0 is the first state word */
    am_rng_seed(&r, 0);
    CHECK(r.s[0] == UINT64_C(0xe220a8397b1dcdaf), "splitmix64(0) = %016llx", (unsigned long long)r.s[0]);
    CHECK((r.s[0] | r.s[1] | r.s[2] | r.s[3]) != 0, "state never all zero");
    /* the reference algorithm over many outputs */
    uint64_t s[4];
    am_rng_seed(&r, 12345);
    memcpy(s, r.s, sizeof s);
    int diff = 0;
    for (int i = 0; i < 100000; i++) {
        uint64_t want = ref_rotl(s[1] * 5, 7) * 9, t = s[1] << 17;
        s[2] ^= s[0];
        s[3] ^= s[1];
        s[1] ^= s[2];
        s[0] ^= s[3];
        s[2] ^= t;
        s[3] = ref_rotl(s[3], 45);
        diff += am_rng_u64(&r) != want;
    }
    CHECK(diff == 0, "%d outputs differ from the reference xoshiro256**", diff);
    /* derived draws of seed 1 */
    static const uint32_t below10[5] = {7, 2, 0, 3, 1};
    am_rng_seed(&r, 1);
    for (int i = 0; i < 5; i++) {
        uint32_t v = am_rng_below(&r, 10);
        CHECK(v == below10[i], "below(10) draw %d = %u, want %u", i, v, below10[i]);
    }
    am_rng_seed(&r, 1);
    for (int i = 0; i < 8; i++) {
        am_real u = am_rng_unit(&r);
#if defined(AM_REAL_FIXED_POINT)
        double want = (double)(golden[i] >> 40) * 0x1p-24;
        CHECK(AM_TO_DOUBLE(u) == want, "unit draw %d = %a, want %a", i, AM_TO_DOUBLE(u), want);
        continue;
#elif defined(AM_REAL_DOUBLE)
        double want = (double)(golden[i] >> 11) * 0x1p-53;
#else
        double want = (double)(golden[i] >> 40) * 0x1p-24;
#endif
        CHECK((double)u == want, "unit draw %d = %a, want %a", i, (double)u, want);
    }
#if defined(AM_REAL_FIXED_POINT)
    static const am_real normal[3] = {-25924537, -17006182, 16077557}; /* Q24 raw values */
#elif defined(AM_REAL_DOUBLE)
    static const am_real normal[3] = {-0x1.8b93b94e8cc62p+0, -0x1.037e69664d113p+0, 0x1.eaa5ec6ca9a27p-1};
#else
    static const am_real normal[3] = {-0x1.8b93bap+0f, -0x1.037e68p+0f, 0x1.eaa5eap-1f};
#endif
    am_rng_seed(&r, 1);
    for (int i = 0; i < 3; i++) {
        am_real v = am_rng_normal(&r);
        CHECK(v == normal[i], "normal draw %d = %a, want %a", i, AM_TO_DOUBLE(v), AM_TO_DOUBLE(normal[i]));
    }
    /* different seeds, different streams */
    am_rng a, b;
    am_rng_seed(&a, 1);
    am_rng_seed(&b, 2);
    CHECK(am_rng_u64(&a) != am_rng_u64(&b), "seeds 1 and 2 agree");
}

static void test_rng_below_unbiased(void)
{
    am_rng r;
    am_rng_seed(&r, 2024);
    long counts[10] = {0};
    const long draws = 100000;
    for (long i = 0; i < draws; i++) {
        uint32_t v = am_rng_below(&r, 10);
        if (v < 10) counts[v]++;
    }
    double expect = (double)draws / 10.0, chi2 = 0;
    long total = 0;
    for (int k = 0; k < 10; k++) {
        double d = (double)counts[k] - expect;
        chi2 += d * d / expect;
        total += counts[k];
    }
    CHECK(total == draws, "draws out of range: %ld of %ld in [0, 10)", total, draws);
    /* 9 degrees of freedom: 27.88 is the 99.9th percentile */
    CHECK(chi2 < 27.88, "chi-square %.2f over 10 bins (bound 27.88)", chi2);
    CHECK(am_rng_below(&r, 1) == 0 && am_rng_below(&r, 0) == 0, "n <= 1 gives 0");
    /* a large n (most of 2^32): draws stay below n and cover both halves */
    uint32_t big = 3000000000u, lo = 0, hi = 0, over = 0;
    for (int i = 0; i < 10000; i++) {
        uint32_t v = am_rng_below(&r, big);
        over += v >= big;
        if (v < big / 2) lo++;
        else hi++;
    }
    CHECK(over == 0, "%u draws not below %u", over, big);
    CHECK(lo > 4700 && hi > 4700, "halves %u / %u", lo, hi);
}

static void test_rng_unit_normal(void)
{
    am_rng r;
    am_rng_seed(&r, 99);
    const long draws = 100000;
    double sum = 0;
    long outside = 0;
    for (long i = 0; i < draws; i++) {
        am_real u = am_rng_unit(&r);
        if (!(u >= AM_R(0) && u < AM_R(1))) outside++;
        sum += AM_TO_DOUBLE(u);
    }
    CHECK(outside == 0, "%ld unit draws outside [0, 1)", outside);
    NEAR(sum / (double)draws, 0.5, 0.01);
    /* normal: mean 0 and sd 1 within 0.02 (standard errors are about 0.003 and 0.002) */
    double s1 = 0, s2 = 0;
    long nonfinite = 0;
    for (long i = 0; i < draws; i++) {
        am_real v = am_rng_normal(&r);
        if (!am_finite(v)) nonfinite++;
        s1 += AM_TO_DOUBLE(v);
        s2 += AM_TO_DOUBLE(v) * AM_TO_DOUBLE(v);
    }
    double mean = s1 / (double)draws, sd = sqrt(s2 / (double)draws - mean * mean);
    CHECK(nonfinite == 0, "%ld normal draws not finite", nonfinite);
    NEAR(mean, 0.0, 0.02);
    NEAR(sd, 1.0, 0.02);
    /* range and chance */
    long bad = 0, hits = 0;
    for (int i = 0; i < 10000; i++) {
        am_real v = am_rng_range(&r, AM_R(-2), AM_R(3));
        bad += !(v >= AM_R(-2) && v < AM_R(3));
        bad += am_rng_chance(&r, AM_R(0)) != 0;
        bad += am_rng_chance(&r, AM_R(1)) != 1;
        hits += am_rng_chance(&r, AM_R(0.25));
    }
    CHECK(bad == 0, "%ld range/chance failures", bad);
    CHECK(hits > 2300 && hits < 2700, "chance(0.25) hit %ld of 10000", hits);
}

/* a stream's far end for the am_text tests: collects what is flushed, fails when told */
typedef struct collected {
    char text[256];
    long len;
    int flushes;
    int fail;          /* 1: the next flush fails */
} collected;

static am_status collect(void* ctx, const char* data, long n)
{
    collected* c = (collected*)ctx;
    if (c->fail || c->len + n >= (long)sizeof c->text) return AM_ERR_IO;
    memcpy(c->text + c->len, data, (size_t)n);
    c->len += n;
    c->text[c->len] = 0;
    c->flushes++;
    return AM_OK;
}

static void test_text_buffer_and_stream(void)
{
    /* a whole-text buffer: a piece fits whole or sets full, never a byte past cap */
    char b[16];
    memset(b, '#', sizeof b);
    am_text t = {b, 12, 0, 0, NULL, NULL, 0};
    am_text_put(&t, "%s", "hello ");
    am_text_write(&t, "world", 5);
    CHECK(!t.full && t.len == 11 && !strcmp(b, "hello world"), "'%s' %ld", b, t.len);
    am_text_write(&t, "!", 1);
    CHECK(t.full == 1 && !strcmp(b, "hello world") && b[12] == '#', "full: '%s'", b);
    CHECK(am_text_flush(&t) == AM_ERR_CAPACITY, "a full buffer is a capacity status");
    /* a stream through 8 bytes: any length, the same text at the far end */
    collected c;
    memset(&c, 0, sizeof c);
    am_text s = {b, 8, 0, 0, collect, &c, 0};
    for (int i = 0; i < 10; i++) am_text_put(&s, "%d,", i * 7);
    am_text_write(&s, "0123456789abcdef", 16);
    CHECK(am_text_flush(&s) == AM_OK && !s.full, "stream: full %d", s.full);
    CHECK(!strcmp(c.text, "0,7,14,21,28,35,42,49,56,63,0123456789abcdef") && s.done == c.len && s.len == 0, "streamed '%s'", c.text);
    CHECK(c.flushes > 3, "%d flushes", c.flushes);
    /* a printf piece longer than the buffer cannot stream: full 1 */
    memset(&c, 0, sizeof c);
    am_text s2 = {b, 8, 0, 0, collect, &c, 0};
    am_text_put(&s2, "%s", "much too long");
    CHECK(s2.full == 1 && am_text_flush(&s2) == AM_ERR_CAPACITY, "long piece: full %d", s2.full);
    /* a failing flush: full 2, an I/O status, nothing more appended */
    memset(&c, 0, sizeof c);
    am_text s3 = {b, 8, 0, 0, collect, &c, 0};
    c.fail = 1;
    am_text_put(&s3, "%s", "abcde");
    am_text_put(&s3, "%s", "fghij");
    CHECK(s3.full == 2 && am_text_flush(&s3) == AM_ERR_IO, "failed flush: full %d", s3.full);
    /* the counting stream */
    am_text n = {b, 4, 0, 0, am_text_drop, NULL, 0};
    am_text_put(&n, "%s", "abc");
    am_text_put(&n, "%s", "def");
    am_text_write(&n, "ghijklm", 7);
    CHECK(n.done + n.len == 13 && !n.full, "counted %ld", n.done + n.len);
}

/* am_quote: the one way a token of input shows in a message */
static void test_quote(void)
{
    char q[AM_QUOTE_BUF], in[400], want[AM_QUOTE_BUF];
    /* printable ASCII as itself, blanks and double quotes too */
    CHECK(!strcmp(am_quote(q, sizeof q, "size 3\"x\"", -1), "size 3\"x\""), "'%s'", q);
    /* control bytes, DEL and bytes from 0x80 up escaped; backslash and single quote too */
    CHECK(!strcmp(am_quote(q, sizeof q, "\x1b[31m", -1), "\\x1b[31m"), "'%s'", q);
    CHECK(!strcmp(am_quote(q, sizeof q, "a\nb\tc\rd", -1), "a\\nb\\tc\\rd"), "'%s'", q);
    CHECK(!strcmp(am_quote(q, sizeof q, "\x01\x1f\x7f\x80\xff", -1), "\\x01\\x1f\\x7f\\x80\\xff"), "'%s'", q);
    CHECK(!strcmp(am_quote(q, sizeof q, "\xc3\xa9", -1), "\\xc3\\xa9"), "UTF-8: '%s'", q);
    CHECK(!strcmp(am_quote(q, sizeof q, "it's a\\b", -1), "it\\'s a\\\\b"), "'%s'", q);
    CHECK(printable_line(am_quote(q, sizeof q, "\x01\x02\n\x7f", -1)), "'%s' is not printable", q);
    /* n bytes: a NUL inside is a byte like any other; a shorter n stops early */
    CHECK(!strcmp(am_quote(q, sizeof q, "ab\0c", 4), "ab\\x00c"), "'%s'", q);
    CHECK(!strcmp(am_quote(q, sizeof q, "abcdef", 3), "abc"), "'%s'", q);
    /* the empty token, and none, show as nothing */
    CHECK(am_quote(q, sizeof q, "", -1) == q && q[0] == 0, "empty: '%s'", q);
    CHECK(!strcmp(am_quote(q, sizeof q, "abc", 0), ""), "n = 0: '%s'", q);
    CHECK(!strcmp(am_quote(q, sizeof q, NULL, 5), ""), "NULL: '%s'", q);
    /* cut after exactly AM_QUOTE_MAX (40) bytes, marked by "..." only when something was cut */
    CHECK(AM_QUOTE_MAX == 40, "AM_QUOTE_MAX %d", AM_QUOTE_MAX);
    memset(in, 'x', sizeof in);
    in[40] = 0;
    CHECK(!strcmp(am_quote(q, sizeof q, in, -1), in) && strlen(q) == 40, "40 bytes: '%s'", q);
    in[40] = 'y';
    in[41] = 0;
    memset(want, 'x', 40);
    strcpy(want + 40, "...");
    CHECK(!strcmp(am_quote(q, sizeof q, in, -1), want), "41 bytes: '%s'", q);
    CHECK(!strcmp(am_quote(q, sizeof q, in, 300), want), "300 bytes: '%s'", q);
    in[41] = 'x';
    in[300] = 0;
    CHECK(!strcmp(am_quote(q, sizeof q, in, -1), want), "300 bytes to a NUL: '%s'", q);
    /* the longest result, 40 escapes and the marker, fits AM_QUOTE_BUF exactly */
    memset(in, 0x01, 41);
    in[41] = 0;
    am_quote(q, sizeof q, in, -1);
    CHECK(strlen(q) == AM_QUOTE_BUF - 1 && !strncmp(q, "\\x01\\x01", 8) && !strcmp(q + 160, "..."), "%d bytes: '%s'",
          (int)strlen(q), q);
    /* a smaller buffer: whole escapes, then "..." when it fits; never a byte past cap */
    char s8[12];
    memset(s8, '#', sizeof s8);
    CHECK(!strcmp(am_quote(s8, 10, "abcdefghijklmnop", -1), "abcdef...") && s8[10] == '#', "cap 10: '%s'", s8);
    CHECK(!strcmp(am_quote(s8, 10, "abcdefghi", -1), "abcdefghi"), "cap 10, 9 bytes: '%s'", s8);
    CHECK(!strcmp(am_quote(s8, 10, "ab\x01\x02", -1), "ab\\x01..."), "cap 10, escapes: '%s'", s8);
    CHECK(!strcmp(am_quote(s8, 1, "abc", -1), "") && !strcmp(am_quote(NULL, 5, "abc", -1), "") &&
              !strcmp(am_quote(s8, 0, "abc", -1), ""), "no room");
}

static void test_hash(void)
{
    /* FNV-1a 64 of "a" (the published test vector) */
    CHECK(am_hash_bytes(AM_HASH_INIT, "a", 1) == UINT64_C(0xaf63dc4c8601ec8c), "fnv1a('a')");
    CHECK(am_hash_bytes(AM_HASH_INIT, "", 0) == AM_HASH_INIT, "empty");
    /* hash_u64 is little-endian bytes whatever the machine */
    unsigned char le[8] = {0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01};
    CHECK(am_hash_u64(AM_HASH_INIT, UINT64_C(0x0102030405060708)) == am_hash_bytes(AM_HASH_INIT, le, 8), "u64 byte order");
    /* -0 and +0 hash alike; other values apart */
    am_real pz = AM_R(0.0), nz = -pz;
#if !defined(AM_REAL_FIXED_POINT)
    CHECK(signbit(nz) && !signbit(pz), "-0 is -0");
#endif
    CHECK(am_hash_real(AM_HASH_INIT, nz) == am_hash_real(AM_HASH_INIT, pz), "-0 and +0 fold");
    CHECK(am_hash_real(AM_HASH_INIT, AM_R(1)) != am_hash_real(AM_HASH_INIT, AM_R(-1)), "1 and -1 differ");
    CHECK(am_hash_real(AM_HASH_INIT, AM_R(1)) != am_hash_real(AM_HASH_INIT, AM_R(1) + AM_REAL_EPS), "one ulp apart differ");
#if defined(AM_REAL_FIXED_POINT)
    CHECK(am_hash_real(AM_HASH_INIT, AM_R(1.5)) == am_hash_u64(AM_HASH_INIT, UINT64_C(0x01800000)), "hash of 1.5: its Q24 bits");
#elif defined(AM_REAL_DOUBLE)
    CHECK(am_hash_real(AM_HASH_INIT, AM_R(1.5)) == UINT64_C(0xaa95e93229a27c80), "golden hash of 1.5");
#else
    CHECK(am_hash_real(AM_HASH_INIT, AM_R(1.5)) == UINT64_C(0xe3e11d32b13106d8), "golden hash of 1.5");
#endif
}

/* the strict number parsers every reader and flag uses: the whole token, nothing else */
static void test_parse_numbers(void)
{
    long l = 7;
    uint64_t u = 7;
    double d = 7;
    CHECK(am_parse_long("12", &l) && l == 12, "12");
    CHECK(am_parse_long("-3", &l) && l == -3, "-3");
    CHECK(am_parse_long("0", &l) && l == 0, "0");
    const char* bad_long[] = {"+3", " 3", "3 ", "3x", "", "-", "1e3", "0x10", "99999999999999999999"};
    for (size_t k = 0; k < sizeof bad_long / sizeof bad_long[0]; k++) {
        l = 7;
        CHECK(!am_parse_long(bad_long[k], &l) && l == 7, "'%s' is no long, *out untouched", bad_long[k]);
    }
    CHECK(!am_parse_long(NULL, &l), "NULL");
    CHECK(am_parse_u64("18446744073709551615", &u) && u == UINT64_MAX, "2^64 - 1");
    const char* bad_u64[] = {"18446744073709551616", "-1", "+1", "", " 1", "1.0"};
    for (size_t k = 0; k < sizeof bad_u64 / sizeof bad_u64[0]; k++) CHECK(!am_parse_u64(bad_u64[k], &u), "'%s' is no u64", bad_u64[k]);
    CHECK(am_parse_double("1e3", &d) && d == 1000, "1e3");
    CHECK(am_parse_double("-0.25", &d) && d == -0.25, "-0.25");
    CHECK(am_parse_double(".5", &d) && d == 0.5, ".5");
    const char* bad_double[] = {"nan", "inf", "-inf", "1e301", "+1", " 1", "1 ", "1x", "", "--1"};
    for (size_t k = 0; k < sizeof bad_double / sizeof bad_double[0]; k++) {
        d = 7;
        CHECK(!am_parse_double(bad_double[k], &d) && d == 7, "'%s' is no number, *out untouched", bad_double[k]);
    }
    CHECK(!am_parse_double(NULL, &d), "NULL");
}

/* the temporaries' names the ports remove on resume */
static void test_temp_name_pid(void)
{
    CHECK(am_temp_name_pid("log.csv.tmp.123") == 123, "log.csv.tmp.123 (an older build's)");
    CHECK(am_temp_name_pid("a.tmp.b.tmp.7") == 7, "the last .tmp. counts");
    CHECK(am_temp_name_pid("log.csv.tmp.123.00ab34cd56ef7890") == 123, "NAME.tmp.PID.NONCE");
    CHECK(am_temp_name_pid("x.tmp.99999999999999999999") == 2000000000L, "a pid past any process's");
    const char* no[] = {".tmp.5", "x.tmp.", "a.tmp.12x", "c.tmp.-1", "notes.tmp.txt", "plain", "a.tmp.5.", "a.tmp.5.12345678901234567",
                        "a.tmp.5.ABC", "a.tmp.5.1.2", "a.tmp..1f"};
    for (size_t k = 0; k < sizeof no / sizeof no[0]; k++) CHECK(am_temp_name_pid(no[k]) == -1, "'%s' is no temporary", no[k]);
}

/* the condition of an AM_ASSERT, counting its evaluations */
static int g_assert_evals;
static int assert_cond(int v)
{
    g_assert_evals++;
    return v;
}

/* AM_ASSERT: compiled out without AM_CHECKS (the condition not even evaluated), checked with it;
 * `test_base assert_fires` (tests/cli_checks.sh, in the CHECKS=1 build) makes one fail, which
 * calls the handler: "tests/test_base.c:LINE: invariant broken: assert_cond(0)" and abort() */
static void test_assert_fires(void)
{
    g_assert_evals = 0;
    AM_ASSERT(assert_cond(1));
#if defined(AM_CHECKS)
    CHECK(g_assert_evals == 1, "AM_CHECKS: the condition evaluated %d times", g_assert_evals);
    if (t_argc_ == 2 && !strcmp(t_argv_[1], "assert_fires")) AM_ASSERT(assert_cond(0));
#else
    CHECK(g_assert_evals == 0, "without AM_CHECKS the condition was evaluated %d times", g_assert_evals);
#endif
    const int before = g_assert_evals;
    CHECK(assert_cond(1) && g_assert_evals == before + 1, "the counter counts");
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    RUN(test_parse_numbers);
    RUN(test_temp_name_pid);
#if defined(AM_REAL_FIXED_POINT)
    RUN(test_fixed_functions);
    RUN(test_fixed_special_values);
#else
    RUN(test_sin_cos);
    RUN(test_exp_log);
    RUN(test_cbrt_pow);
    RUN(test_atan2_acos);
    RUN(test_special_values);
#endif
    RUN(test_math_golden_hash);
    RUN(test_rng_golden);
    RUN(test_rng_below_unbiased);
    RUN(test_rng_unit_normal);
    RUN(test_hash);
    RUN(test_text_buffer_and_stream);
    RUN(test_quote);
    RUN(test_assert_fires);
    return SUMMARY();
}
