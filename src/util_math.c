/* Deterministic elementary functions.
 *
 * Each function works in double internally from + - * / and sqrt only, in a fixed order, then
 * rounds once to am_real. Range reduction uses Cody-Waite splits of pi/2 and ln 2, so results
 * are identical on every IEEE-754 platform and every optimisation level (the build forbids
 * contraction into fused multiply-adds). */
#include "amorph/mathx.h"

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
