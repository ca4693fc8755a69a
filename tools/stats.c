/* The statistics of amorph stats (tools/stats.h). Written from the mathematics: the continued
 * fraction of the incomplete beta function is the classical one,
 *   I_x(a, b) = x^a (1 - x)^b / (a B(a, b)) * 1 / (1 + d1 / (1 + d2 / (1 + ...))),
 *   d(2m + 1) = -(a + m)(a + b + m) x / ((a + 2m)(a + 2m + 1)),
 *   d(2m)     = m (b - m) x / ((a + 2m - 1)(a + 2m)),
 * which converges quickly for x < (a + 1) / (a + b + 2); beyond, I_x(a, b) = 1 - I_(1-x)(b, a).
 * Student's t: P(|T| > t) = I_(df / (df + t^2))(df / 2, 1 / 2). */
#include "stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

void tool_stats_describe(const double* x, int n, tool_stats_sample* s)
{
    double sum = 0, ss = 0;
    for (int i = 0; i < n; i++) sum += x[i];
    s->n = n;
    s->mean = n > 0 ? sum / n : (double)NAN;
    /* the squares about the mean (not sum x^2 - n mean^2, which cancels) */
    for (int i = 0; i < n; i++) ss += (x[i] - s->mean) * (x[i] - s->mean);
    s->sd = n > 1 ? sqrt(ss / (n - 1)) : (double)NAN;
    s->se = n > 1 ? s->sd / sqrt((double)n) : (double)NAN;
}

/* ---- distributions ---- */

/* the continued fraction 1 / (1 + d1 / (1 + d2 / ...)) of I_x(a, b), by the modified Lentz method:
 * the convergents' ratios C = b_j + a_j / C and D = 1 / (b_j + a_j D) multiply into f */
static double beta_cf(double a, double b, double x)
{
    const double tiny = 1e-300, eps = 1e-15;
    double f = tiny, C = tiny, D = 0;
    for (int j = 1; j <= 10000; j++) {
        double aj;
        if (j == 1) aj = 1;
        else {
            int k = j - 1; /* the coefficient d_k */
            double m = (double)(k / 2);
            if (k % 2) aj = -(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1));
            else aj = m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m));
        }
        D = 1 + aj * D;
        if (fabs(D) < tiny) D = tiny;
        D = 1 / D;
        C = 1 + aj / C;
        if (fabs(C) < tiny) C = tiny;
        double delta = C * D;
        f *= delta;
        if (fabs(delta - 1) < eps) break;
    }
    return f;
}

double tool_stats_incbeta(double a, double b, double x)
{
    if (!(a > 0) || !(b > 0) || !(x >= 0) || !(x <= 1)) return (double)NAN;
    if (x == 0) return 0;
    if (x == 1) return 1;
    /* x^a (1 - x)^b / B(a, b), in logarithms */
    double front = exp(a * log(x) + b * log1p(-x) - (lgamma(a) + lgamma(b) - lgamma(a + b)));
    if (x < (a + 1) / (a + b + 2)) return front * beta_cf(a, b, x) / a;
    return 1 - front * beta_cf(b, a, 1 - x) / b;
}

double tool_stats_t_cdf(double t, double df)
{
    if (isnan(t) || !(df > 0)) return (double)NAN;
    if (isinf(t)) return t > 0 ? 1 : 0;
    /* the two tails together: I_(df / (df + t^2))(df / 2, 1 / 2) */
    double tails = tool_stats_incbeta(df / 2, 0.5, df / (df + t * t));
    return t > 0 ? 1 - tails / 2 : tails / 2;
}

/* x in [lo, hi] with f(x) = p for an increasing f, by bisection to the last bit */
static double invert(double (*f)(double, double), double arg, double p, double lo, double hi)
{
    for (int i = 0; i < 2000; i++) {
        double mid = lo + (hi - lo) / 2;
        if (mid <= lo || mid >= hi) break;
        if (f(mid, arg) < p) lo = mid;
        else hi = mid;
    }
    return lo + (hi - lo) / 2;
}

double tool_stats_t_quantile(double p, double df)
{
    if (!(p > 0) || !(p < 1) || !(df > 0)) return (double)NAN;
    if (p == 0.5) return 0;
    /* by symmetry, the upper half: a bracket [0, hi] doubled until it holds p */
    double q = p > 0.5 ? p : 1 - p, hi = 1;
    while (tool_stats_t_cdf(hi, df) < q && hi < 1e300) hi *= 2;
    double t = invert(tool_stats_t_cdf, df, q, 0, hi);
    return p > 0.5 ? t : -t;
}

double tool_stats_norm_cdf(double z) { return 0.5 * erfc(-z / sqrt(2.0)); }

static double norm_cdf2(double z, double unused)
{
    (void)unused;
    return tool_stats_norm_cdf(z);
}

double tool_stats_norm_quantile(double p)
{
    if (!(p > 0) || !(p < 1)) return (double)NAN;
    return invert(norm_cdf2, 0, p, -40, 40);
}

/* ---- two samples ---- */

void tool_stats_welch(const tool_stats_sample* a, const tool_stats_sample* b, double* t, double* df, double* p)
{
    double va = a->sd * a->sd / a->n, vb = b->sd * b->sd / b->n, diff = a->mean - b->mean;
    double se2 = va + vb;
    if (!(se2 > 0)) {
        /* both samples constant: their means are equal or they differ beyond any doubt */
        *df = a->n + b->n - 2;
        *t = diff == 0 ? 0 : diff > 0 ? (double)INFINITY : -(double)INFINITY;
        *p = diff == 0 ? 1 : 0;
        return;
    }
    *t = diff / sqrt(se2);
    *df = se2 * se2 / (va * va / (a->n - 1) + vb * vb / (b->n - 1));
    *p = tool_stats_incbeta(*df / 2, 0.5, *df / (*df + *t * *t));
}

/* sorts the pooled values of the workspace (with their sample marks) by value: insertion sort,
 * stable, on at most 2 * TOOL_STATS_MAX_N values */
static void sort_pooled(tool_stats_work* w, int n)
{
    for (int i = 1; i < n; i++) {
        double v = w->v[i];
        int fa = w->from_a[i], j = i;
        while (j > 0 && w->v[j - 1] > v) {
            w->v[j] = w->v[j - 1];
            w->from_a[j] = w->from_a[j - 1];
            j--;
        }
        w->v[j] = v;
        w->from_a[j] = fa;
    }
}

int tool_stats_mann_whitney(const double* a, int na, const double* b, int nb, tool_stats_work* w, double* u, double* p)
{
    const int n = na + nb;
    for (int i = 0; i < na; i++) w->v[i] = a[i], w->from_a[i] = 1;
    for (int i = 0; i < nb; i++) w->v[na + i] = b[i], w->from_a[na + i] = 0;
    sort_pooled(w, n);
    /* mid-ranks, doubled so that they are whole: a run of equal values at places i..j-1 (from 0)
     * has mid-rank (i + 1 + j) / 2; ties: the sum of t^3 - t over the runs */
    long w2 = 0;       /* twice the rank sum of a */
    double ties = 0;
    for (int i = 0; i < n;) {
        int j = i + 1;
        while (j < n && w->v[j] == w->v[i]) j++;
        for (int k = i; k < j; k++) {
            w->rank2[k] = i + 1 + j;
            if (w->from_a[k]) w2 += w->rank2[k];
        }
        double t = j - i;
        ties += t * t * t - t;
        i = j;
    }
    /* U of a: its rank sum less the least it can be, na (na + 1) / 2 */
    *u = w2 / 2.0 - na * (na + 1) / 2.0;
    if (na <= TOOL_STATS_MW_EXACT && nb <= TOOL_STATS_MW_EXACT) {
        /* the exact null distribution: every choice of na of the n places is as likely; ways[k][s]
         * counts the choices of k among the places seen so far whose doubled ranks sum to s
         * (whole numbers below 2^53: C(40, 20) is about 1.4e11, so the counts are exact) */
        const int smax = 2 * n * na; /* at least the largest sum */
        for (int k = 0; k <= na; k++) memset(w->ways[k], 0, sizeof(double) * (size_t)(smax + 1));
        w->ways[0][0] = 1;
        for (int i = 0; i < n; i++) {
            const int r = w->rank2[i];
            for (int k = (i + 1 < na ? i + 1 : na); k >= 1; k--)
                for (int s = smax; s >= r; s--) w->ways[k][s] += w->ways[k - 1][s - r];
        }
        double total = 0, low = 0, high = 0;
        for (int s = 0; s <= smax; s++) {
            total += w->ways[na][s];
            if (s <= w2) low += w->ways[na][s];
            if (s >= w2) high += w->ways[na][s];
        }
        double pp = 2 * fmin(low, high) / total;
        *p = pp < 1 ? pp : 1;
        return 1;
    }
    /* the normal approximation: U has mean na nb / 2 and, with ties, variance
     * na nb / 12 ((n + 1) - sum(t^3 - t) / (n (n - 1))) */
    double mu = na * (double)nb / 2;
    double var = na * (double)nb / 12 * ((n + 1) - ties / ((double)n * (n - 1)));
    if (!(var > 0)) {
        *p = 1;
        return 0;
    }
    double z = (fabs(*u - mu) - 0.5) / sqrt(var);
    if (z < 0) z = 0;
    *p = erfc(z / sqrt(2.0));
    return 0;
}

double tool_stats_cohen_d(const tool_stats_sample* a, const tool_stats_sample* b)
{
    double pooled = sqrt(((a->n - 1) * a->sd * a->sd + (b->n - 1) * b->sd * b->sd) / (a->n + b->n - 2));
    double diff = a->mean - b->mean;
    if (!(pooled > 0)) return diff == 0 ? (double)NAN : diff > 0 ? (double)INFINITY : -(double)INFINITY;
    return diff / pooled;
}

double tool_stats_hedges_g(double d, int na, int nb)
{
    double df = na + nb - 2;
    if (!(df > 1)) return (double)NAN;
    double j = exp(lgamma(df / 2) - lgamma((df - 1) / 2)) / sqrt(df / 2);
    return d * j;
}

long tool_stats_runs_needed(double d, double alpha, double power)
{
    double ad = fabs(d);
    if (!(ad > 0)) return -1;
    if (isinf(ad)) return 2;
    /* the normal approximation is a lower bound (t quantiles exceed z ones): start there */
    double zsum = tool_stats_norm_quantile(1 - alpha / 2) + tool_stats_norm_quantile(power);
    double n0 = ceil(2 * zsum * zsum / (ad * ad));
    if (n0 > TOOL_STATS_RUNS_MAX) return -1;
    for (long n = n0 < 2 ? 2 : (long)n0; n <= TOOL_STATS_RUNS_MAX; n++) {
        double df = 2.0 * n - 2;
        double tsum = tool_stats_t_quantile(1 - alpha / 2, df) + tool_stats_t_quantile(power, df);
        if ((double)n >= 2 * tsum * tsum / (ad * ad)) return n;
    }
    return -1;
}

void tool_stats_compare_samples(const double* a, int na, const double* b, int nb, tool_stats_work* w, tool_stats_compare* c)
{
    tool_stats_sample sa, sb;
    tool_stats_describe(a, na, &sa);
    tool_stats_describe(b, nb, &sb);
    c->difference = sa.mean - sb.mean;
    c->tested = na >= 2 && nb >= 2;
    c->t = c->df = c->p_welch = c->u = c->p_mw = c->d = c->g = (double)NAN;
    c->mw_exact = 0;
    c->runs_needed = -1;
    if (!c->tested) return;
    tool_stats_welch(&sa, &sb, &c->t, &c->df, &c->p_welch);
    c->mw_exact = tool_stats_mann_whitney(a, na, b, nb, w, &c->u, &c->p_mw);
    c->d = tool_stats_cohen_d(&sa, &sb);
    c->g = tool_stats_hedges_g(c->d, na, nb);
    c->runs_needed = tool_stats_runs_needed(c->d, 0.05, 0.8);
}

void tool_stats_holm(const double* p, int m, double* adj, int* order)
{
    /* the tested ones by ascending p (insertion sort: a family is a few hundred pairs at most; ties
     * keep their order, and get the same adjusted value below) */
    int k = 0;
    for (int i = 0; i < m; i++) {
        if (isnan(p[i])) continue;
        int at = k++;
        while (at > 0 && p[order[at - 1]] > p[i]) {
            order[at] = order[at - 1];
            at--;
        }
        order[at] = i;
    }
    for (int j = 0; j < m; j++)
        if (isnan(p[j])) adj[j] = p[j];
    /* the running maximum; each p is read before adj (which may be p) is written over it */
    double top = 0;
    for (int j = 0; j < k; j++) {
        double q = (double)(k - j) * p[order[j]];
        q = q < 1 ? q : 1;
        top = q > top ? q : top;
        adj[order[j]] = top;
    }
}
