/* tests/test_stats.c: the statistics of amorph stats (tools/stats.c) against values found another
 * way: closed forms of the incomplete beta function and of Student's t with 1 and 2 degrees of
 * freedom; tables (normal and t quantiles, Cohen's sample sizes); Welch's t-test on two textbook
 * samples, whose p was integrated numerically from the t density (Simpson's rule with 200,000
 * intervals in python3, which has no statistics library here); and the Mann-Whitney test's exact
 * p counted by hand on tiny samples and by brute force over every subset on larger ones; Holm's
 * correction worked by hand. */
#include "harness.h"
#include "stats.h"

static tool_stats_work work;

static void test_incbeta_closed_forms(void)
{
    /* I_x(1, b) = 1 - (1 - x)^b, I_x(a, 1) = x^a, I_x(a, b) = 1 - I_(1-x)(b, a), I_(1/2)(a, a) = 1/2 */
    const double xs[] = {0.001, 0.1, 0.37, 0.5, 0.8, 0.999};
    const double ps[] = {0.5, 1, 2.5, 7, 40};
    for (int i = 0; i < 6; i++)
        for (int j = 0; j < 5; j++) {
            double x = xs[i], p = ps[j];
            NEAR(tool_stats_incbeta(1, p, x), 1 - pow(1 - x, p), 1e-13);
            NEAR(tool_stats_incbeta(p, 1, x), pow(x, p), 1e-13);
            NEAR(tool_stats_incbeta(p, 3.5, x), 1 - tool_stats_incbeta(3.5, p, 1 - x), 1e-13);
            NEAR(tool_stats_incbeta(p, p, 0.5), 0.5, 1e-13);
        }
    /* I_x(1/2, 1/2) = (2 / pi) asin(sqrt(x)) */
    NEAR(tool_stats_incbeta(0.5, 0.5, 0.3), 2 / acos(-1.0) * asin(sqrt(0.3)), 1e-13);
    /* integrated numerically (python3, Simpson): general a, b on both sides of the switch */
    NEAR(tool_stats_incbeta(2.5, 3.5, 0.4), 0.486904191526, 1e-9);
    NEAR(tool_stats_incbeta(5, 2.5, 0.8), 0.77002488065, 1e-9);
    NEAR(tool_stats_incbeta(30, 40, 0.45), 0.644748008559, 1e-9);
    /* the ends, and arguments outside the domain */
    CHECK(tool_stats_incbeta(2, 3, 0) == 0 && tool_stats_incbeta(2, 3, 1) == 1, "I at 0 and 1");
    CHECK(isnan(tool_stats_incbeta(0, 3, 0.5)) && isnan(tool_stats_incbeta(2, 3, 1.5)) && isnan(tool_stats_incbeta(2, 3, -0.1)),
          "NAN outside the domain");
}

static void test_t_distribution(void)
{
    const double pi = acos(-1.0);
    const double ts[] = {-30, -4.2, -1, -0.3, 0, 0.5, 1, 2.7, 12.7, 300};
    for (int i = 0; i < 10; i++) {
        double t = ts[i];
        /* 1 degree of freedom: the Cauchy distribution */
        NEAR(tool_stats_t_cdf(t, 1), 0.5 + atan(t) / pi, 1e-13);
        /* 2: 1/2 + t / (2 sqrt(2 + t^2)) */
        NEAR(tool_stats_t_cdf(t, 2), 0.5 + t / (2 * sqrt(2 + t * t)), 1e-13);
        /* symmetry at a fractional df */
        NEAR(tool_stats_t_cdf(t, 3.7) + tool_stats_t_cdf(-t, 3.7), 1, 1e-13);
    }
    /* two-sided tails at fractional and larger df, integrated numerically (python3, Simpson) */
    NEAR(2 * tool_stats_t_cdf(-2.5, 7.3), 0.0396502346656, 1e-10);
    NEAR(2 * tool_stats_t_cdf(-0.7, 25), 0.490390536786, 1e-10);
    /* quantiles: tables (0.8 at 10 bisected on the integrated density), and the Cauchy's tan(pi (p - 1/2)) */
    NEAR(tool_stats_t_quantile(0.975, 10), 2.228138851986, 1e-9);
    NEAR(tool_stats_t_quantile(0.975, 30), 2.042272456301, 1e-9);
    NEAR(tool_stats_t_quantile(0.8, 10), 0.879057828551, 1e-9);
    NEAR(tool_stats_t_quantile(0.975, 1), tan(pi * 0.475), 1e-8);
    NEAR(tool_stats_t_quantile(0.025, 4), -2.776445105198, 1e-9);
    CHECK(tool_stats_t_quantile(0.5, 3) == 0, "the median is 0");
    NEAR(tool_stats_norm_quantile(0.975), 1.959963984540054, 1e-12);
    NEAR(tool_stats_norm_quantile(0.8), 0.8416212335729143, 1e-12);
    NEAR(tool_stats_norm_cdf(-1.959963984540054), 0.025, 1e-14);
}

static void test_describe(void)
{
    const double x[] = {2, 4, 4, 4, 5, 5, 7, 9};
    tool_stats_sample s;
    tool_stats_describe(x, 8, &s);
    /* mean 5; squares about it 32; sd sqrt(32 / 7) */
    NEAR(s.mean, 5, 1e-15);
    NEAR(s.sd, sqrt(32.0 / 7), 1e-15);
    NEAR(s.se, sqrt(32.0 / 7) / sqrt(8.0), 1e-15);
    tool_stats_describe(x, 1, &s);
    CHECK(s.n == 1 && s.mean == 2 && isnan(s.sd) && isnan(s.se), "one value: no spread");
}

/* Welch's t-test and the effect sizes on two samples of 15 (Wikipedia's first example of Welch's
 * test) and on samples of 10 and 20; the references from python3 (Simpson on the t density) */
static void test_welch(void)
{
    const double a[] = {27.5, 21.0, 19.0, 23.6, 17.0, 17.9, 16.9, 20.1, 21.9, 22.6, 23.1, 19.6, 19.0, 21.7, 21.4};
    const double b[] = {27.1, 22.0, 20.8, 23.4, 23.4, 23.5, 25.8, 22.0, 24.8, 20.2, 21.9, 22.1, 22.9, 20.5, 24.4};
    tool_stats_compare c;
    tool_stats_compare_samples(a, 15, b, 15, &work, &c);
    CHECK(c.tested, "tested");
    NEAR(c.t, -2.45535639829, 1e-10);
    NEAR(c.df, 24.9885292902, 1e-9);
    NEAR(c.p_welch, 0.0213780014629, 1e-10);
    NEAR(c.d, -0.896569390704, 1e-10);
    /* Hedges' g = d J(28), J(df) = Gamma(df/2) / (sqrt(df/2) Gamma((df-1)/2)) */
    NEAR(c.g, c.d * exp(lgamma(14) - lgamma(13.5)) / sqrt(14.0), 1e-12);
    NEAR(c.difference, (312.3 - 344.8) / 15, 1e-12); /* the sums 312.3 and 344.8 */
    const double x[] = {17.2, 20.9, 22.6, 18.1, 21.7, 21.4, 23.5, 24.2, 14.7, 21.8};
    const double y[] = {21.5, 22.8, 21.0, 23.0, 21.6, 23.6, 22.5, 20.7, 23.4, 21.8,
                        20.7, 21.7, 21.5, 22.5, 23.6, 21.5, 22.5, 23.5, 21.5, 21.8};
    tool_stats_compare_samples(x, 10, y, 20, &work, &c);
    NEAR(c.t, -1.5654335236, 1e-9);
    NEAR(c.df, 9.90474124865, 1e-9);
    NEAR(c.p_welch, 0.148841696605, 1e-10);
    NEAR(c.d, -0.813345727267, 1e-10);
    /* the order of the samples turns the sign, not p */
    tool_stats_compare r;
    tool_stats_compare_samples(y, 20, x, 10, &work, &r);
    NEAR(r.t, -c.t, 1e-12);
    NEAR(r.p_welch, c.p_welch, 1e-14);
    /* Hedges' J(4) = 2 / sqrt(2 pi) */
    NEAR(tool_stats_hedges_g(1, 3, 3), 2 / sqrt(2 * acos(-1.0)), 1e-13);
}

static void test_degenerate(void)
{
    const double a[] = {1, 1, 1}, b[] = {2, 2}, one[] = {5};
    tool_stats_compare c;
    /* constant samples that differ: beyond doubt; equal ones: nothing */
    tool_stats_compare_samples(b, 2, a, 3, &work, &c);
    CHECK(c.tested && isinf(c.t) && c.t > 0 && c.p_welch == 0, "t %g p %g", c.t, c.p_welch);
    CHECK(isinf(c.d) && c.runs_needed == 2, "d %g runs %ld", c.d, c.runs_needed);
    tool_stats_compare_samples(a, 3, a, 2, &work, &c);
    CHECK(c.t == 0 && c.p_welch == 1 && c.runs_needed == -1, "equal constants: t %g p %g runs %ld", c.t, c.p_welch, c.runs_needed);
    /* fewer than 2 values: no test */
    tool_stats_compare_samples(one, 1, a, 3, &work, &c);
    CHECK(!c.tested && isnan(c.p_welch) && isnan(c.p_mw) && c.runs_needed == -1, "one value: no test");
    NEAR(c.difference, 4, 1e-15);
}

/* the exact two-sided p of the samples by brute force: every choice of na places among the
 * pooled values, each as likely */
static double brute_mw(const double* a, int na, const double* b, int nb)
{
    double v[40];
    int n = na + nb;
    for (int i = 0; i < na; i++) v[i] = a[i];
    for (int i = 0; i < nb; i++) v[na + i] = b[i];
    /* U of a subset: pairs (chosen, not chosen) with the chosen larger, ties one half */
    double u0 = 0;
    for (int i = 0; i < na; i++)
        for (int j = 0; j < nb; j++) u0 += a[i] > b[j] ? 1 : a[i] == b[j] ? 0.5 : 0;
    long total = 0, low = 0, high = 0;
    for (long mask = 0; mask < (1L << n); mask++) {
        int k = 0;
        for (int i = 0; i < n; i++) k += (int)((mask >> i) & 1);
        if (k != na) continue;
        double u = 0;
        for (int i = 0; i < n; i++)
            for (int j = 0; j < n; j++)
                if (((mask >> i) & 1) && !((mask >> j) & 1)) u += v[i] > v[j] ? 1 : v[i] == v[j] ? 0.5 : 0;
        total++;
        low += u <= u0 + 1e-9;
        high += u >= u0 - 1e-9;
    }
    double p = 2.0 * (low < high ? low : high) / (double)total;
    return p < 1 ? p : 1;
}

static void test_mann_whitney(void)
{
    double u, p;
    /* 3 against 3, apart: U = 0, P(U <= 0) = 1 / C(6, 3) = 1/20, two-sided 0.1 */
    const double lo3[] = {1, 2, 3}, hi3[] = {4, 5, 6};
    CHECK(tool_stats_mann_whitney(lo3, 3, hi3, 3, &work, &u, &p) == 1, "exact");
    CHECK(u == 0, "U %g", u);
    NEAR(p, 0.1, 1e-15);
    tool_stats_mann_whitney(hi3, 3, lo3, 3, &work, &u, &p);
    CHECK(u == 9, "U %g", u);
    NEAR(p, 0.1, 1e-15);
    /* 2 against 2, apart: 2 / C(4, 2) = 1/3 */
    tool_stats_mann_whitney(lo3, 2, hi3, 2, &work, &u, &p);
    NEAR(p, 1.0 / 3, 1e-15);
    /* a tie: {1, 2} against {2, 3}, mid-ranks 1, 2.5, 2.5, 4; U = 1/2; the six choices of two
     * places give doubled rank sums 7, 7, 10, 10, 13, 13: P(W <= 7) = 2/6, two-sided 2/3 */
    const double ta[] = {1, 2}, tb[] = {2, 3};
    tool_stats_mann_whitney(ta, 2, tb, 2, &work, &u, &p);
    CHECK(u == 0.5, "U %g", u);
    NEAR(p, 2.0 / 3, 1e-15);
    /* interleaved {1, 3, 5} against {2, 4, 6}: U = 3, P(U <= 3) = 7/20 (U = 0, 1, 2, 2, 3, 3, 3
     * among the 20), two-sided 0.7 */
    const double odd[] = {1, 3, 5}, even[] = {2, 4, 6};
    tool_stats_mann_whitney(odd, 3, even, 3, &work, &u, &p);
    CHECK(u == 3, "U %g", u);
    NEAR(p, 0.7, 1e-15);
    /* larger samples with ties against brute force over every subset */
    const double a[] = {3, 1, 4, 1, 5, 9, 2, 6}, b[] = {5, 3, 5, 8, 9, 7, 9, 3};
    if (!test_quick()) { /* 2^16 subsets: long under valgrind */
        tool_stats_mann_whitney(a, 8, b, 8, &work, &u, &p);
        NEAR(p, brute_mw(a, 8, b, 8), 1e-14);
    }
    tool_stats_mann_whitney(a, 5, b, 8, &work, &u, &p);
    NEAR(p, brute_mw(a, 5, b, 8), 1e-14);
    const double c[] = {0.0111, 0.0111, 0.0095}, d[] = {0.0110, 0.0175, 0.0115, 0.0111};
    tool_stats_mann_whitney(c, 3, d, 4, &work, &u, &p);
    NEAR(p, brute_mw(c, 3, d, 4), 1e-14);
    /* 25 against 25, apart: the normal approximation, z = (312.5 - 0.5) / sqrt(25 25 51 / 12) */
    double x[25], y[25];
    for (int i = 0; i < 25; i++) x[i] = i, y[i] = 100 + i;
    CHECK(tool_stats_mann_whitney(x, 25, y, 25, &work, &u, &p) == 0, "beyond 20: the normal approximation");
    CHECK(u == 0, "U %g", u);
    NEAR_REL(p, 1.41565622485e-09, 1e-8);
    /* with ties (python3: midranks, the tie-corrected variance): 30 values 0,0,1,1,...,14,14
     * against 22 values 3,3,4,4,...,13,13 */
    double t1[30], t2[22];
    for (int i = 0; i < 30; i++) t1[i] = i / 2;
    for (int i = 0; i < 22; i++) t2[i] = i / 2 + 3;
    tool_stats_mann_whitney(t1, 30, t2, 22, &work, &u, &p);
    CHECK(u == 286, "U %g", u);
    NEAR(p, 0.419285581309, 1e-11);
    /* 20 against 20 is still exact, and agrees with the approximation roughly */
    double e[20], f[20];
    for (int i = 0; i < 20; i++) e[i] = i * 2, f[i] = i * 2 + 5;
    CHECK(tool_stats_mann_whitney(e, 20, f, 20, &work, &u, &p) == 1, "20 against 20: exact");
    CHECK(p > 0.2 && p < 0.6, "p %g", p);
}

static void test_runs_needed(void)
{
    /* Cohen's (1988) table for a two-sided t-test at 0.05 and power 0.8: d 0.5 64 runs, 0.8 26,
     * 1.0 17; d 2: 6 (5 give power 0.79) */
    CHECK(tool_stats_runs_needed(0.5, 0.05, 0.8) == 64, "d 0.5: %ld", tool_stats_runs_needed(0.5, 0.05, 0.8));
    CHECK(tool_stats_runs_needed(-0.8, 0.05, 0.8) == 26, "d 0.8: %ld", tool_stats_runs_needed(-0.8, 0.05, 0.8));
    CHECK(tool_stats_runs_needed(1.0, 0.05, 0.8) == 17, "d 1: %ld", tool_stats_runs_needed(1.0, 0.05, 0.8));
    CHECK(tool_stats_runs_needed(2.0, 0.05, 0.8) == 6, "d 2: %ld", tool_stats_runs_needed(2.0, 0.05, 0.8));
    CHECK(tool_stats_runs_needed(50, 0.05, 0.8) == 2, "a huge d: the least, 2");
    CHECK(tool_stats_runs_needed(0, 0.05, 0.8) == -1, "d 0: never");
    CHECK(tool_stats_runs_needed(1e-5, 0.05, 0.8) == -1, "beyond TOOL_STATS_RUNS_MAX");
    CHECK(tool_stats_runs_needed((double)NAN, 0.05, 0.8) == -1, "not a number");
}

static void test_holm(void)
{
    /* worked by hand: ascending 0.005, 0.01, 0.03, 0.04 (k = 4) times 4, 3, 2, 1 give 0.02, 0.03,
     * 0.06, 0.04, and the running maximum makes the last 0.06; the untested pair (NAN) is not one
     * of the family and stays NAN */
    const double p[5] = {0.01, 0.04, (double)NAN, 0.03, 0.005};
    double adj[5];
    int order[5];
    tool_stats_holm(p, 5, adj, order);
    NEAR(adj[0], 0.03, 1e-15);
    NEAR(adj[1], 0.06, 1e-15);
    CHECK(isnan(adj[2]), "the untested pair: %g", adj[2]);
    NEAR(adj[3], 0.06, 1e-15);
    NEAR(adj[4], 0.02, 1e-15);
    /* capped at 1; ties get one value (the first of two equal p's, times the larger factor, sets
     * it); a family of one is left as it is; in place */
    double q[3] = {0.01, 0.2, 0.01}, c[3] = {0.6, 0.7, 0.45};
    tool_stats_holm(q, 3, q, order);
    NEAR(q[0], 0.03, 1e-15);
    NEAR(q[2], 0.03, 1e-15);
    NEAR(q[1], 0.2, 1e-15);
    tool_stats_holm(c, 3, c, order);
    CHECK(c[0] == 1 && c[1] == 1 && c[2] == 1, "capped at 1: %g %g %g", c[0], c[1], c[2]);
    double r[3] = {0.02, 0.04, 0.011};
    tool_stats_holm(r, 3, r, order);
    NEAR(r[2], 0.033, 1e-15);
    NEAR(r[0], 0.04, 1e-15);
    NEAR(r[1], 0.04, 1e-15);
    double one[1] = {0.0123};
    tool_stats_holm(one, 1, one, order);
    CHECK(one[0] == 0.0123, "a family of one: %g", one[0]);
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    RUN(test_incbeta_closed_forms);
    RUN(test_t_distribution);
    RUN(test_describe);
    RUN(test_welch);
    RUN(test_degenerate);
    RUN(test_mann_whitney);
    RUN(test_runs_needed);
    RUN(test_holm);
    return SUMMARY();
}
