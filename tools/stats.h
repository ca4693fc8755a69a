/* tools/stats.h: the statistics of amorph stats (docs/results.md, Statistics): two samples of runs
 * compared by Welch's t-test and the Mann-Whitney U test, their effect size, and the runs a
 * comparison needs. Pure functions of their arguments (no I/O, no state between calls); the one
 * large scratch space, the Mann-Whitney test's, is the caller's tool_stats_work.
 *
 * The distributions are computed here from their mathematics: the regularized incomplete beta
 * function by its continued fraction (evaluated by the modified Lentz method), Student's t from
 * it, the normal distribution from the C library's erfc, the exact null distribution of the
 * Mann-Whitney statistic by counting subsets. */
#ifndef AMORPH_TOOLS_STATS_H
#define AMORPH_TOOLS_STATS_H

/* the largest sample (runs of one group) the tests take */
#define TOOL_STATS_MAX_N 256
/* the Mann-Whitney p is exact (the null distribution counted) when both samples have at most this
 * many values, else from the normal approximation with the tie correction */
#define TOOL_STATS_MW_EXACT 20
/* the counting table: subsets of up to TOOL_STATS_MW_EXACT values of 2 * TOOL_STATS_MW_EXACT, by
 * their sum of doubled ranks (each at most 2 * 2 * TOOL_STATS_MW_EXACT) */
#define TOOL_STATS_MW_SUM (4 * TOOL_STATS_MW_EXACT * TOOL_STATS_MW_EXACT + 1)

/* the Mann-Whitney test's scratch space (about 200 KB: declare it static) */
typedef struct tool_stats_work {
    double v[2 * TOOL_STATS_MAX_N];   /* the pooled values, sorted */
    int from_a[2 * TOOL_STATS_MAX_N]; /* 1 where the sorted value came from the first sample */
    int rank2[2 * TOOL_STATS_MAX_N];  /* twice its mid-rank (an integer) */
    double ways[TOOL_STATS_MW_EXACT + 1][TOOL_STATS_MW_SUM]; /* ways[k][s]: subsets of k values whose doubled ranks sum to s */
} tool_stats_work;

/* ---- one sample ---- */

typedef struct tool_stats_sample {
    int n;
    double mean;
    double sd;   /* the sample standard deviation (n - 1 in the denominator); NAN when n < 2 */
    double se;   /* its standard error, sd / sqrt(n); NAN when n < 2 */
} tool_stats_sample;
void tool_stats_describe(const double* x, int n, tool_stats_sample* s);

/* ---- distributions ---- */

/* the regularized incomplete beta function I_x(a, b), a > 0, b > 0, 0 <= x <= 1 (NAN outside) */
double tool_stats_incbeta(double a, double b, double x);
/* Student's t distribution with df > 0 degrees of freedom (not necessarily whole): P(T <= t) */
double tool_stats_t_cdf(double t, double df);
/* its quantile: the t with P(T <= t) = p, 0 < p < 1 */
double tool_stats_t_quantile(double p, double df);
/* the standard normal distribution, P(Z <= z), and its quantile */
double tool_stats_norm_cdf(double z);
double tool_stats_norm_quantile(double p);

/* ---- two samples: a against b ---- */

typedef struct tool_stats_compare {
    int tested;        /* 0 when a sample has fewer than 2 values: no test, the rest NAN */
    double difference; /* mean of a - mean of b */
    /* Welch's t-test: t = difference / sqrt(var_a / n_a + var_b / n_b), df by Welch-Satterthwaite,
     * p two-sided from Student's t */
    double t, df, p_welch;
    /* Mann-Whitney: u counts the pairs (value of a, value of b) in which a's is the larger, a tie
     * counting one half (0 to n_a n_b); p two-sided, exact when mw_exact */
    double u, p_mw;
    int mw_exact;
    /* effect sizes: Cohen's d (the difference over the pooled standard deviation) and Hedges' g
     * (d times the exact small-sample correction J(n_a + n_b - 2)) */
    double d, g;
    /* runs per group for 80% power at alpha 0.05 two-sided at |d| (tool_stats_runs_needed) */
    long runs_needed;
} tool_stats_compare;
/* both tests and the effect sizes; n_a, n_b at most TOOL_STATS_MAX_N */
void tool_stats_compare_samples(const double* a, int na, const double* b, int nb, tool_stats_work* w, tool_stats_compare* c);

/* Welch's t-test alone: t, df and the two-sided p (t 0 and p 1 when both samples are constant and
 * equal; t +-inf and p 0 when they are constant and differ) */
void tool_stats_welch(const tool_stats_sample* a, const tool_stats_sample* b, double* t, double* df, double* p);

/* the Mann-Whitney test alone: *u as above, the two-sided p, and 1 when it is exact (both samples
 * at most TOOL_STATS_MW_EXACT: the null distribution of the rank sum counted over every way of
 * choosing the first sample's places among the pooled values, ties at their mid-ranks, and
 * p = min(1, 2 min(P(W <= w), P(W >= w)))), 0 when it is the normal approximation (the variance
 * with the tie correction, a continuity correction of 1/2) */
int tool_stats_mann_whitney(const double* a, int na, const double* b, int nb, tool_stats_work* w, double* u, double* p);

/* Cohen's d of the two samples (pooled standard deviation), and Hedges' g = d J(df) with
 * J(df) = Gamma(df / 2) / (sqrt(df / 2) Gamma((df - 1) / 2)), df = n_a + n_b - 2 */
double tool_stats_cohen_d(const tool_stats_sample* a, const tool_stats_sample* b);
double tool_stats_hedges_g(double d, int na, int nb);

/* The runs per group for a two-sided two-sample t-test at level alpha to find an effect of size d
 * with probability power: the smallest n >= 2 with n >= 2 (t(1 - alpha/2, 2n - 2) + t(power, 2n - 2))^2
 * / d^2, the normal approximation n = 2 (z(1 - alpha/2) + z(power))^2 / d^2 with its quantiles
 * replaced by Student's t at the n being tried (it gives Cohen's tables: 64 runs for d = 0.5,
 * 26 for 0.8). -1 when d is 0 or not a number, or more than TOOL_STATS_RUNS_MAX runs are needed. */
#define TOOL_STATS_RUNS_MAX 10000000L
long tool_stats_runs_needed(double d, double alpha, double power);

/* ---- many comparisons ---- */

/* Holm's step-down correction of the p values of one family of m tests (Holm 1979): with the
 * tested p values in ascending order p_(1) <= ... <= p_(k) (a NAN, no test, is not one of the
 * family and stays NAN), the i-th becomes max over j <= i of min(1, (k - j + 1) p_(j)), so that the
 * family's chance of one false finding at level alpha is at most alpha. adj may be p; order is
 * the caller's scratch of m ints. */
void tool_stats_holm(const double* p, int m, double* adj, int* order);

#endif
