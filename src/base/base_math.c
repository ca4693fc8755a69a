/* Deterministic elementary functions.
 *
 * Each function works in double internally from + - * / and sqrt only, in a fixed order, then
 * rounds once to am_real. Range reduction uses Cody-Waite splits of pi/2 and ln 2, so results
 * are identical on every IEEE-754 platform and every optimisation level (the build forbids
 * contraction into fused multiply-adds). */
#include "amorph/base.h"

#if !defined(AM_REAL_FIXED_POINT)

/* pi/2 split so that k * PIO2_HI is exact for |k| < 2^20 */
#define PIO2_HI 1.57079632673412561417e+00
#define PIO2_LO 6.07710050650619224932e-11
#define LN2_HI 6.93147180369123816490e-01
#define LN2_LO 1.90821492927058770002e-10

static double round_half_even(double x)
{
    if (!(x > -4503599627370496.0 && x < 4503599627370496.0)) return x; /* |x| >= 2^52 is whole (or NaN) */
    double f = (double)(long long)x; /* truncation toward zero, exact for |x| < 2^52 */
    double r = x - f;
    if (r > 0.5 || (r == 0.5 && ((long long)f & 1))) f += 1.0;
    else if (r < -0.5 || (r == -0.5 && ((long long)f & 1))) f -= 1.0;
    return f;
}

/* sin and cos of |r| <= pi/4 by Taylor series (error below 2e-17) */
static double sin_kernel(double r)
{
    double r2 = r * r, term = r, sum = r;
    for (int n = 1; n <= 8; n++) {
        term = -term * r2 / (double)((2 * n) * (2 * n + 1));
        sum += term;
    }
    return sum;
}

static double cos_kernel(double r)
{
    double r2 = r * r, term = 1.0, sum = 1.0;
    for (int n = 1; n <= 8; n++) {
        term = -term * r2 / (double)((2 * n - 1) * (2 * n));
        sum += term;
    }
    return sum;
}

/* reduces x to r in [-pi/4, pi/4] and quadrant k mod 4 */
static double reduce(double x, int* quadrant)
{
    *quadrant = 0;
    if (x - x != 0.0) return x - x; /* NaN or infinity: NaN, never a cast of it */
    /* far out of any physical range: fold by whole turns first (each fold shrinks |x| by a
     * factor of at least 1e-10, so huge arguments take a few rounds; the result is
     * deterministic, not accurate, past about 1e7) */
    while (x > 1.0e6 || x < -1.0e6) {
        double turns = round_half_even(x / (4.0 * PIO2_HI));
        x = x - turns * (4.0 * PIO2_HI) - turns * (4.0 * PIO2_LO);
    }
    double k = round_half_even(x / (PIO2_HI + PIO2_LO));
    double r = (x - k * PIO2_HI) - k * PIO2_LO;
    long long ki = (long long)k;
    *quadrant = (int)(((ki % 4) + 4) % 4);
    return r;
}

static double sin_d(double x)
{
    int q;
    double r = reduce(x, &q);
    switch (q) {
    case 0: return sin_kernel(r);
    case 1: return cos_kernel(r);
    case 2: return -sin_kernel(r);
    default: return -cos_kernel(r);
    }
}

static double cos_d(double x)
{
    int q;
    double r = reduce(x, &q);
    switch (q) {
    case 0: return cos_kernel(r);
    case 1: return -sin_kernel(r);
    case 2: return -cos_kernel(r);
    default: return sin_kernel(r);
    }
}

static double pow2i(int k)
{
    double base = k < 0 ? 0.5 : 2.0, out = 1.0;
    int n = k < 0 ? -k : k;
    while (n) { /* exact: powers of two */
        if (n & 1) out *= base;
        base *= base;
        n >>= 1;
    }
    return out;
}

static double exp_d(double x)
{
    if (x > 700.0) x = 700.0;
    if (x < -700.0) x = -700.0;
    double k = round_half_even(x / (LN2_HI + LN2_LO));
    double r = (x - k * LN2_HI) - k * LN2_LO; /* |r| <= 0.35 */
    double term = 1.0, sum = 1.0;
    for (int n = 1; n <= 14; n++) {
        term = term * r / (double)n;
        sum += term;
    }
    return sum * pow2i((int)k);
}

static double log_d(double x)
{
    if (!(x > 0.0)) return -1.0e300;
    if (!(x <= 1.7976931348623157e308)) return x; /* infinity: would halve forever */
    /* x = m * 2^e with m in [sqrt(1/2), sqrt(2)) */
    int e = 0;
    while (x >= 1.4142135623730951) { x *= 0.5; e++; }
    while (x < 0.7071067811865476) { x *= 2.0; e--; }
    double z = (x - 1.0) / (x + 1.0), z2 = z * z, term = z, sum = z;
    for (int n = 3; n <= 31; n += 2) {
        term *= z2;
        sum += term / (double)n;
    }
    return 2.0 * sum + (double)e * LN2_HI + (double)e * LN2_LO;
}

static double atan_d(double x)
{
    int neg = x < 0.0;
    if (neg) x = -x;
    int inv = x > 1.0;
    if (inv) x = 1.0 / x;
    /* two halvings: atan(x) = 2 atan(x / (1 + sqrt(1 + x^2))), |x| <= tan(pi/16) after them */
    x = x / (1.0 + sqrt(1.0 + x * x));
    x = x / (1.0 + sqrt(1.0 + x * x));
    double x2 = x * x, term = x, sum = x;
    for (int n = 3; n <= 41; n += 2) {
        term = -term * x2;
        sum += term / (double)n;
    }
    sum *= 4.0;
    if (inv) sum = (PIO2_HI - sum) + PIO2_LO;
    return neg ? -sum : sum;
}

static double atan2_d(double y, double x)
{
    if (x > 0.0) return atan_d(y / x);
    if (x < 0.0) {
        double a = atan_d(y / x);
        return y >= 0.0 ? (a + 2.0 * PIO2_HI) + 2.0 * PIO2_LO : (a - 2.0 * PIO2_HI) - 2.0 * PIO2_LO;
    }
    if (y > 0.0) return PIO2_HI + PIO2_LO;
    if (y < 0.0) return -(PIO2_HI + PIO2_LO);
    return 0.0;
}

am_real am_sin(am_real x) { return (am_real)sin_d((double)x); }
am_real am_cos(am_real x) { return (am_real)cos_d((double)x); }
am_real am_exp(am_real x)
{
    double xd = (double)x; /* the documented range [-80, 80]: clamped outside (float stays finite) */
    if (xd > 80.0) xd = 80.0;
    if (xd < -80.0) xd = -80.0;
    return (am_real)exp_d(xd);
}
am_real am_log(am_real x) { return x > AM_R(0) ? (am_real)log_d((double)x) : -AM_REAL_MAX; }
am_real am_pow(am_real x, am_real y) { return (am_real)exp_d((double)y * log_d((double)x)); }
am_real am_atan2(am_real y, am_real x) { return (am_real)atan2_d((double)y, (double)x); }

am_real am_acos(am_real xr)
{
    double x = (double)xr;
    if (x > 1.0) x = 1.0;
    if (x < -1.0) x = -1.0;
    return (am_real)atan2_d(sqrt((1.0 - x) * (1.0 + x)), x);
}

am_real am_cbrt(am_real xr)
{
    double x = (double)xr;
    if (x == 0.0) return AM_R(0);
    int neg = x < 0.0;
    if (neg) x = -x;
    double y = exp_d(log_d(x) / 3.0);
    for (int i = 0; i < 2; i++) y = y - (y * y * y - x) / (3.0 * y * y); /* Newton polish */
    return (am_real)(neg ? -y : y);
}

#endif

#if defined(AM_REAL_FIXED_POINT)
/* The fixed-point build: the same functions on integers only. Inputs and outputs are Q7.24;
 * kernels work in Q30 on int64_t (a product of two Q30 values below 4 fits in 63 bits), range
 * reduction subtracts multiples of pi/2 or ln 2 held in Q40, and every rounding is to nearest
 * (half up), so the results are the same on every platform; the error is within an ulp or two of
 * Q24 (tests/test_base.c measures it). */
#define Q30 ((int64_t)1 << 30)
#define Q40_PIO2 INT64_C(1727108826179)  /* pi/2 * 2^40 */
#define Q40_LN2 INT64_C(762123384786)    /* ln 2 * 2^40 */
#define Q30_SQRT2 INT64_C(1518500250)    /* sqrt(2) * 2^30 */
#define Q30_SQRTH INT64_C(759250125)     /* sqrt(1/2) * 2^30 */

static int64_t mul30(int64_t a, int64_t b) { return (a * b + (Q30 >> 1)) >> 30; }
static int64_t div30(int64_t a, int64_t b) /* a / b in Q30, |a| < 2^32, b > 0 */
{
    int64_t n = a * Q30;
    return (n >= 0 ? n + b / 2 : n - b / 2) / b;
}
static int64_t round_shift(int64_t v, int sh) { return sh <= 0 ? v * ((int64_t)1 << -sh) : (v + ((int64_t)1 << (sh - 1))) >> sh; }
static am_real sat32(int64_t v) { return v > INT32_MAX ? INT32_MAX : (v < -INT32_MAX ? -INT32_MAX : (am_real)v); }

am_real am_fx_sqrt(am_real x) { return x <= 0 ? 0 : am_fx_sqrt_wide((am_wide)x << AM_FIX_FRAC); }

/* first guesses of sqrt(n) for n in [2^62, 2^64), by the top 8 bits of n (i = 64..255):
 * round(sqrt((i + 0.5) 2^56)) */
static const uint32_t sqrt_seed[192] = {
    2155855936u, 2172503719u, 2189024898u, 2205422317u, 2221698718u, 2237856739u,
    2253898928u, 2269827741u, 2285645547u, 2301354636u, 2316957219u, 2332455434u,
    2347851346u, 2363146956u, 2378344200u, 2393444949u, 2408451021u, 2423364173u,
    2438186110u, 2452918487u, 2467562906u, 2482120926u, 2496594057u, 2510983767u,
    2525291483u, 2539518589u, 2553666435u, 2567736329u, 2581729546u, 2595647326u,
    2609490877u, 2623261373u, 2636959959u, 2650587750u, 2664145832u, 2677635264u,
    2691057079u, 2704412283u, 2717701858u, 2730926763u, 2744087932u, 2757186278u,
    2770222692u, 2783198045u, 2796113187u, 2808968947u, 2821766139u, 2834505554u,
    2847187969u, 2859814141u, 2872384814u, 2884900711u, 2897362543u, 2909771005u,
    2922126776u, 2934430522u, 2946682895u, 2958884532u, 2971036060u, 2983138090u,
    2995191222u, 3007196045u, 3019153134u, 3031063054u, 3042926360u, 3054743594u,
    3066515290u, 3078241968u, 3089924143u, 3101562317u, 3113156983u, 3124708625u,
    3136217720u, 3147684733u, 3159110124u, 3170494341u, 3181837828u, 3193141017u,
    3204404336u, 3215628204u, 3226813031u, 3237959223u, 3249067178u, 3260137286u,
    3271169931u, 3282165491u, 3293124338u, 3304046836u, 3314933346u, 3325784221u,
    3336599808u, 3347380449u, 3358126482u, 3368838236u, 3379516039u, 3390160210u,
    3400771066u, 3411348918u, 3421894071u, 3432406827u, 3442887483u, 3453336331u,
    3463753659u, 3474139750u, 3484494884u, 3494819336u, 3505113377u, 3515377274u,
    3525611290u, 3535815686u, 3545990716u, 3556136633u, 3566253685u, 3576342118u,
    3586402172u, 3596434085u, 3606438094u, 3616414428u, 3626363318u, 3636284987u,
    3646179658u, 3656047551u, 3665888881u, 3675703862u, 3685492705u, 3695255616u,
    3704992802u, 3714704464u, 3724390803u, 3734052014u, 3743688294u, 3753299833u,
    3762886821u, 3772449446u, 3781987892u, 3791502342u, 3800992976u, 3810459972u,
    3819903506u, 3829323751u, 3838720878u, 3848095058u, 3857446457u, 3866775241u,
    3876081573u, 3885365614u, 3894627523u, 3903867459u, 3913085577u, 3922282031u,
    3931456972u, 3940610551u, 3949742917u, 3958854216u, 3967944594u, 3977014193u,
    3986063156u, 3995091623u, 4004099733u, 4013087623u, 4022055427u, 4031003282u,
    4039931317u, 4048839666u, 4057728458u, 4066597820u, 4075447880u, 4084278764u,
    4093090594u, 4101883495u, 4110657588u, 4119412992u, 4128149826u, 4136868210u,
    4145568258u, 4154250085u, 4162913807u, 4171559536u, 4180187383u, 4188797458u,
    4197389873u, 4205964733u, 4214522147u, 4223062221u, 4231585060u, 4240090767u,
    4248579446u, 4257051198u, 4265506124u, 4273944324u, 4282365898u, 4290770942u,
};

/* the root of a wide value, rounded to nearest: normalise to [2^62, 2^64), seed from the table
 * (relative error below 2e-3), two Newton steps (below 1e-11, so within one of the floor), correct
 * to the exact floor, scale back, round */
am_real am_fx_sqrt_wide(am_wide w)
{
    if (w <= 0) return 0;
    uint64_t n = (uint64_t)w;
    int s = 0;
    if (!(n >> 32)) { n <<= 32; s += 32; }
    if (!(n >> 48)) { n <<= 16; s += 16; }
    if (!(n >> 56)) { n <<= 8; s += 8; }
    if (!(n >> 60)) { n <<= 4; s += 4; }
    if (!(n >> 62)) { n <<= 2; s += 2; }
    uint64_t y = sqrt_seed[(n >> 56) - 64];
    y = (y + n / y) >> 1;
    y = (y + n / y) >> 1;
    if (y > UINT32_MAX) y = UINT32_MAX;
    while (y * y > n) y--;
    while (y < UINT32_MAX && (y + 1) * (y + 1) <= n) y++;
    uint64_t r = y >> (s / 2), v = (uint64_t)w; /* floor(sqrt(w)) */
    if (v > r * r + r) r++;                     /* to nearest: w > (r + 1/2)^2 - 1/4 */
    return (am_real)r;
}

/* sin and cos of |r| <= pi/4 (Q30) by Horner on their Taylor series */
static int64_t sin30(int64_t r)
{
    int64_t r2 = mul30(r, r), t = Q30;
    static const int div[5] = {156, 110, 72, 42, 20};
    for (int i = 0; i < 5; i++) t = Q30 - mul30(r2, t) / div[i];
    t = Q30 - mul30(r2, t) / 6;
    return mul30(r, t);
}
static int64_t cos30(int64_t r)
{
    int64_t r2 = mul30(r, r), t = Q30;
    static const int div[6] = {132, 90, 56, 30, 12, 2};
    for (int i = 0; i < 6; i++) t = Q30 - mul30(r2, t) / div[i];
    return t;
}
/* x (Q24) = k pi/2 + r: r in Q30, quadrant k mod 4 */
static int64_t reduce_fx(am_real x, int* quadrant)
{
    int64_t x40 = (int64_t)x * ((int64_t)1 << (40 - AM_FIX_FRAC));
    int64_t k = (x40 >= 0 ? x40 + Q40_PIO2 / 2 : x40 - Q40_PIO2 / 2) / Q40_PIO2;
    int64_t r40 = x40 - k * Q40_PIO2;
    *quadrant = (int)(((k % 4) + 4) % 4);
    return round_shift(r40, 10);
}
static am_real to24(int64_t v30) { return sat32(round_shift(v30, 30 - AM_FIX_FRAC)); }

am_real am_sin(am_real x)
{
    int q;
    int64_t r = reduce_fx(x, &q);
    switch (q) {
    case 0: return to24(sin30(r));
    case 1: return to24(cos30(r));
    case 2: return to24(-sin30(r));
    default: return to24(-cos30(r));
    }
}
am_real am_cos(am_real x)
{
    int q;
    int64_t r = reduce_fx(x, &q);
    switch (q) {
    case 0: return to24(cos30(r));
    case 1: return to24(-sin30(r));
    case 2: return to24(-cos30(r));
    default: return to24(sin30(r));
    }
}

/* e^x for x in Q30 (any int64 below 2^40): Q30, saturated at 2^61 */
static int64_t exp30(int64_t x30)
{
    if (x30 > 40 * Q30) return INT64_C(1) << 61;
    if (x30 < -40 * Q30) return 0;
    int64_t x40 = x30 * 1024;
    int64_t k = (x40 >= 0 ? x40 + Q40_LN2 / 2 : x40 - Q40_LN2 / 2) / Q40_LN2;
    int64_t r = round_shift(x40 - k * Q40_LN2, 10); /* |r| <= ln2 / 2 */
    int64_t t = Q30;
    for (int n = 10; n >= 1; n--) t = Q30 + mul30(r, t) / n;
    return k >= 0 ? (k > 30 ? INT64_C(1) << 61 : t << k) : round_shift(t, (int)-k);
}
/* ln x for x > 0 in Q24: Q30 */
static int64_t log30(am_real x)
{
    int64_t m = (int64_t)x * ((int64_t)1 << (30 - AM_FIX_FRAC)); /* Q30 */
    int e = 0;
    while (m >= Q30_SQRT2) { m = (m + 1) >> 1; e++; }
    while (m < Q30_SQRTH) { m <<= 1; e--; }
    int64_t z = div30(m - Q30, m + Q30), z2 = mul30(z, z), sum = 0;
    for (int n = 13; n >= 3; n -= 2) sum = mul30(z2, sum + Q30 / n);
    sum = mul30(z, Q30 + sum);
    return 2 * sum + round_shift((int64_t)e * Q40_LN2, 10);
}

am_real am_exp(am_real x) { return to24(exp30((int64_t)x * ((int64_t)1 << (30 - AM_FIX_FRAC)))); }
am_real am_log(am_real x) { return x > 0 ? to24(log30(x)) : -AM_REAL_MAX; }
am_real am_pow(am_real x, am_real y)
{
    if (x <= 0) return 0;
    return to24(exp30(round_shift(log30(x) * y, AM_FIX_FRAC)));
}
am_real am_cbrt(am_real x)
{
    if (x == 0) return 0;
    int64_t r = exp30(log30(x < 0 ? -x : x) / 3);
    return to24(x < 0 ? -r : r);
}
/* atan of a Q30 value in [0, 1]: Q30 */
static int64_t atan30(int64_t a)
{
    static const int64_t T8 = INT64_C(444758426);  /* tan(pi/8) * 2^30 */
    static const int64_t T16 = INT64_C(213580528); /* tan(pi/16) * 2^30 */
    int64_t base = 0;
    if (a > T8) { /* atan a = pi/4 + atan((a - 1) / (a + 1)) */
        a = div30(a - Q30, a + Q30);
        base = round_shift(Q40_PIO2, 11);
    }
    int neg = a < 0;
    if (neg) a = -a;
    int64_t off = 0;
    if (a > T16) { /* atan a = pi/8 + atan((a - t8) / (1 + a t8)) */
        a = div30(a - T8, Q30 + mul30(a, T8));
        off = round_shift(Q40_PIO2, 12);
    }
    int64_t a2 = mul30(a, a), sum = 0;
    for (int n = 15; n >= 3; n -= 2) sum = mul30(a2, Q30 / n - sum);
    int64_t v = off + mul30(a, Q30 - sum);
    return base + (neg ? -v : v);
}
am_real am_atan2(am_real y, am_real x)
{
    int64_t pio2 = round_shift(Q40_PIO2, 10);
    if (x == 0) return y > 0 ? to24(pio2) : (y < 0 ? to24(-pio2) : 0);
    int64_t ay = y < 0 ? -(int64_t)y : y, ax = x < 0 ? -(int64_t)x : x;
    int64_t a = ay <= ax ? atan30(div30(ay, ax)) : pio2 - atan30(div30(ax, ay));
    if (x < 0) a = 2 * pio2 - a;
    return to24(y < 0 ? -a : a);
}
am_real am_acos(am_real x)
{
    if (x > AM_FIX_ONE) x = AM_FIX_ONE;
    if (x < -AM_FIX_ONE) x = -AM_FIX_ONE;
    return am_atan2(am_fx_sqrt_wide(AM_MULW(AM_FIX_ONE - x, AM_FIX_ONE + x)), x); /* the product kept whole */
}
#endif
