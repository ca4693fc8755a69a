/* amorph stats's tables (tools/stats_cmd.h): the numbers at each count (a group's values, the
 * groups ranked, a pair compared by tools/stats.h's tests), as Markdown tables or one JSON object.
 * docs/results.md, Statistics. */
#include "stats_cmd.h"
#if !defined(AM_PROFILE_BOARD)

#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---- the numbers at one count ---- */

/* the values of group g at checkpoint k (sustained: its scores) into x; their number */
static int values(int g, int k, double* x)
{
    const stats_group* G = &stats_S.groups[g];
    for (int i = 0; i < G->n; i++) {
        const stats_run* R = &stats_S.runs[G->runs[i]];
        x[i] = stats_S.sustained ? R->sustained : R->val[k];
    }
    return G->n;
}

/* 1 when group g has a value at checkpoint k (every run reached it) */
static int has(int g, int k) { return stats_S.sustained ? k == 0 : k < stats_S.groups[g].counts; }

/* the groups that have checkpoint k, by mean from the highest (the first named first among equal
 * means) into order; their number */
static int ranked(int k, int* order, double* mean)
{
    int n = 0;
    for (int g = 0; g < stats_S.ngroups; g++) {
        if (!has(g, k)) continue;
        tool_stats_sample s;
        tool_stats_describe(stats_S.a, values(g, k, stats_S.a), &s);
        int at = n++;
        while (at > 0 && mean[at - 1] < s.mean) {
            order[at] = order[at - 1];
            mean[at] = mean[at - 1];
            at--;
        }
        order[at] = g;
        mean[at] = s.mean;
    }
    return n;
}

/* the comparison of groups ga and gb at checkpoint k */
static void compare(int ga, int gb, int k, tool_stats_compare* c)
{
    int na = values(ga, k, stats_S.a), nb = values(gb, k, stats_S.b);
    tool_stats_compare_samples(stats_S.a, na, stats_S.b, nb, &stats_S.work, c);
}

/* every pair at checkpoint k, one family: the groups ranked (ranked()), then pair (i, j), i < j,
 * at fam.c[...] in that order with its p values after Holm's correction over the tested pairs,
 * each test's its own family; the number of groups */
#define PAIRS_MAX (STATS_MAX_GROUPS * (STATS_MAX_GROUPS - 1) / 2)
typedef struct pair_family {
    tool_stats_compare c[PAIRS_MAX];
    double holm_welch[PAIRS_MAX], holm_mw[PAIRS_MAX];
    int chosen[PAIRS_MAX];            /* 1: compared (--pair, or every pair) */
    int scratch[PAIRS_MAX];
} pair_family;
static pair_family fam;

/* 1 when groups a and b are to be compared: every pair, or one --pair named (either way round) */
static int chosen(int a, int b)
{
    if (stats_S.npairs == 0) return 1;
    for (int p = 0; p < stats_S.npairs; p++)
        if ((stats_S.pair[p][0] == a && stats_S.pair[p][1] == b) || (stats_S.pair[p][0] == b && stats_S.pair[p][1] == a)) return 1;
    return 0;
}

static int family(int k, int* order, double* mean)
{
    const int n = ranked(k, order, mean);
    int m = 0;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++, m++) {
            fam.c[m].tested = 0;
            fam.holm_welch[m] = fam.holm_mw[m] = (double)NAN;
            fam.chosen[m] = chosen(order[i], order[j]);
            if (!fam.chosen[m]) continue; /* not compared: not one of the family */
            compare(order[i], order[j], k, &fam.c[m]);
            fam.holm_welch[m] = fam.c[m].p_welch; /* NAN when not tested */
            fam.holm_mw[m] = fam.c[m].p_mw;
        }
    tool_stats_holm(fam.holm_welch, m, fam.holm_welch, fam.scratch);
    tool_stats_holm(fam.holm_mw, m, fam.holm_mw, fam.scratch);
    return n;
}

/* ---- markdown ---- */

#define put am_text_put

/* a number of the tables: "-" when not a number, "inf" when infinite */
static void put_num(am_text* t, double v, int decimals)
{
    if (isnan(v)) put(t, " - |");
    else if (isinf(v)) put(t, " %sinf |", v < 0 ? "-" : "");
    else put(t, " %.*f |", decimals, v);
}

/* a p value: 3 decimals, or below 0.001 two digits and a power of ten ("2.3e-05"), written out
 * here because C libraries differ in the digits of an exponent */
static void put_p(am_text* t, double p, const char* note)
{
    if (isnan(p)) put(t, " - |");
    else if (p >= 0.001 || p == 0) put(t, " %.3f%s |", p, note);
    else {
        int e = (int)floor(log10(p));
        double m = floor(p / pow(10, e) * 10 + 0.5) / 10;
        if (m >= 10) m /= 10, e++;
        put(t, " %.1fe-%02d%s |", m, -e, note);
    }
}

/* the first cell of a row: the count, or the score's name */
static void put_key(am_text* t, int k)
{
    if (stats_S.sustained) put(t, "| sustained |");
    else put(t, "| %ld |", (k + 1) * stats_S.every);
}

int stats_max_counts(void)
{
    int top = 0;
    for (int g = 0; g < stats_S.ngroups; g++) top = stats_S.groups[g].counts > top ? stats_S.groups[g].counts : top;
    return stats_S.sustained ? 1 : top;
}

void stats_markdown(am_text* t)
{
    const int top = stats_max_counts(), dec = stats_S.sustained ? 3 : 2;
    const char* key = stats_S.sustained ? "score" : "evaluations";
    const char* what = stats_S.sustained ? "travel per cycle, cycles 11-30" : "best fitness so far";
    static int order[STATS_MAX_GROUPS];
    static double mean[STATS_MAX_GROUPS];
    /* each group: its runs, mean, sd, se (and, sustained, its gaits) */
    put(t, "| %s | group | runs | mean %s (mm) | standard deviation (mm) | standard error (mm) |", key, what);
    if (stats_S.sustained) put(t, " still | flop | scoot | bounce | roll |");
    put(t, "\n|---:|---|---:|---:|---:|---:|%s\n", stats_S.sustained ? "---:|---:|---:|---:|---:|" : "");
    for (int k = 0; k < top; k++)
        for (int g = 0; g < stats_S.ngroups; g++) {
            if (!has(g, k)) continue;
            tool_stats_sample s;
            tool_stats_describe(stats_S.a, values(g, k, stats_S.a), &s);
            put_key(t, k);
            put(t, " %s | %d |", stats_S.groups[g].name, s.n);
            put_num(t, s.mean * 1000, dec);
            put_num(t, s.sd * 1000, dec);
            put_num(t, s.se * 1000, dec);
            if (stats_S.sustained)
                for (int i = 0; i < GAITS; i++) put(t, " %d |", stats_S.groups[g].gaits[i]);
            put(t, "\n");
        }
    /* no pairs at any count (one group there at the most): no tables of them */
    int pairs = 0;
    for (int k = 0; k < top && !pairs; k++) pairs = ranked(k, order, mean) >= 2;
    if (!pairs) return;
    /* each pair, the higher mean first, with its p values after Holm's correction over the pairs
     * of its count */
    put(t, "\n| %s | pair | difference (mm) | Welch's t | df | p (Welch) | p (Welch, Holm) | U | p (Mann-Whitney) | p (Mann-Whitney, Holm) "
           "| Cohen's d | Hedges' g | runs for 80%% power |\n", key);
    put(t, "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int k = 0; k < top; k++) {
        int n = family(k, order, mean), m = 0;
        for (int i = 0; i < n; i++)
            for (int j = i + 1; j < n; j++, m++) {
                const tool_stats_compare* c = &fam.c[m];
                if (!fam.chosen[m]) continue;
                put_key(t, k);
                put(t, " %s - %s |", stats_S.groups[order[i]].name, stats_S.groups[order[j]].name);
                put_num(t, c->difference * 1000, dec);
                if (!c->tested) {
                    const stats_group* few = stats_S.groups[order[i]].n < 2 ? &stats_S.groups[order[i]] : &stats_S.groups[order[j]];
                    put(t, " no test: %s has %d run%s | | | | | | | | | |\n", few->name, few->n, few->n == 1 ? "" : "s");
                    continue;
                }
                put_num(t, c->t, 2);
                put_num(t, c->df, 1);
                put_p(t, c->p_welch, "");
                put_p(t, fam.holm_welch[m], "");
                put(t, " %.*f |", c->u == floor(c->u) ? 0 : 1, c->u);
                put_p(t, c->p_mw, c->mw_exact ? "" : " (normal)");
                put_p(t, fam.holm_mw[m], "");
                put_num(t, c->d, 2);
                put_num(t, c->g, 2);
                if (c->runs_needed > 0) put(t, " %ld |\n", c->runs_needed);
                else put(t, " - |\n");
            }
    }
    /* the ranking, and which of its differences each test finds at 0.05 after Holm's correction */
    put(t, "\n| %s | ranking by mean | significant at 0.05 after Holm's correction, Welch's t | significant at 0.05 after Holm's correction, "
           "Mann-Whitney |\n|---:|---|---|---|\n", key);
    for (int k = 0; k < top; k++) {
        int n = family(k, order, mean);
        if (n < 2) continue;
        put_key(t, k);
        put(t, " %s", stats_S.groups[order[0]].name);
        for (int i = 1; i < n; i++) {
            /* equal when the table's means are */
            char m1[64], m2[64];
            snprintf(m1, sizeof m1, "%.*f", dec, mean[i - 1] * 1000);
            snprintf(m2, sizeof m2, "%.*f", dec, mean[i] * 1000);
            int same = !strcmp(m1, m2);
            put(t, " %s %s", same ? "=" : ">", stats_S.groups[order[i]].name);
        }
        put(t, " |");
        for (int test = 0; test < 2; test++) {
            int found = 0;
            for (int i = 0, m = 0; i < n; i++)
                for (int j = i + 1; j < n; j++, m++) {
                    const double p = test == 0 ? fam.holm_welch[m] : fam.holm_mw[m];
                    if (!fam.chosen[m] || !fam.c[m].tested || !(p < 0.05)) continue;
                    put(t, "%s %s > %s", found ? "," : "", stats_S.groups[order[i]].name, stats_S.groups[order[j]].name);
                    found++;
                }
            put(t, "%s |", found ? "" : " none");
        }
        put(t, "\n");
    }
}

/* ---- JSON ---- */

static void put_jnum(am_text* t, const char* key, double v, int comma)
{
    if (isfinite(v)) put(t, "%s\"%s\": %.9g", comma ? ", " : "", key, v);
    else put(t, "%s\"%s\": null", comma ? ", " : "", key);
}

void stats_json(am_text* t)
{
    const int top = stats_max_counts();
    static int order[STATS_MAX_GROUPS];
    static double mean[STATS_MAX_GROUPS];
    put(t, "{\"score\": \"%s\", ", stats_S.sustained ? "sustained" : "best");
    if (!stats_S.sustained) put(t, "\"every\": %ld, ", stats_S.every);
    put(t, "\"groups\": [");
    for (int g = 0; g < stats_S.ngroups; g++) {
        const stats_group* G = &stats_S.groups[g];
        put(t, "%s{\"group\": \"%s\", \"runs\": [", g ? ", " : "", G->name);
        for (int i = 0; i < G->n; i++) {
            char esc[TOOL_PATH_MAX * 2];
            tool_json_escape(esc, sizeof esc, stats_S.runs[G->runs[i]].dir);
            put(t, "%s\"", i ? ", " : "");
            am_text_write(t, esc, (long)strlen(esc));
            put(t, "\"");
        }
        put(t, "]");
        if (stats_S.sustained)
            for (int i = 0; i < GAITS; i++) put(t, ", \"%s\": %d", stats_gait_names[i], G->gaits[i]);
        else put(t, ", \"counts\": %d", G->counts);
        put(t, "}");
    }
    put(t, "], \"rows\": [");
    int rows = 0;
    for (int k = 0; k < top; k++) {
        const int n = family(k, order, mean);
        if (n == 0) continue;
        put(t, "%s{", rows++ ? ", " : "");
        if (!stats_S.sustained) put(t, "\"evaluations\": %ld, ", (k + 1) * stats_S.every);
        put(t, "\"groups\": [");
        for (int g = 0, first = 1; g < stats_S.ngroups; g++) {
            if (!has(g, k)) continue;
            tool_stats_sample s;
            tool_stats_describe(stats_S.a, values(g, k, stats_S.a), &s);
            put(t, "%s{\"group\": \"%s\", \"n\": %d", first ? "" : ", ", stats_S.groups[g].name, s.n);
            put_jnum(t, "mean", s.mean, 1);
            put_jnum(t, "sd", s.sd, 1);
            put_jnum(t, "se", s.se, 1);
            put(t, "}");
            first = 0;
        }
        put(t, "], \"pairs\": [");
        for (int i = 0, m = 0, first = 1; i < n; i++)
            for (int j = i + 1; j < n; j++, m++) {
                const tool_stats_compare* c = &fam.c[m];
                if (!fam.chosen[m]) continue;
                put(t, "%s{\"a\": \"%s\", \"b\": \"%s\", \"tested\": %s", first ? "" : ", ", stats_S.groups[order[i]].name,
                    stats_S.groups[order[j]].name, c->tested ? "true" : "false");
                first = 0;
                put_jnum(t, "difference", c->difference, 1);
                put_jnum(t, "t", c->t, 1);
                put_jnum(t, "df", c->df, 1);
                put_jnum(t, "p_welch", c->p_welch, 1);
                put_jnum(t, "p_welch_holm", fam.holm_welch[m], 1);
                put_jnum(t, "u", c->u, 1);
                put_jnum(t, "p_mann_whitney", c->p_mw, 1);
                put_jnum(t, "p_mann_whitney_holm", fam.holm_mw[m], 1);
                put(t, ", \"mann_whitney_exact\": %s", c->tested && c->mw_exact ? "true" : "false");
                put_jnum(t, "cohen_d", c->d, 1);
                put_jnum(t, "hedges_g", c->g, 1);
                if (c->runs_needed > 0) put(t, ", \"runs_needed\": %ld}", c->runs_needed);
                else put(t, ", \"runs_needed\": null}");
            }
        put(t, "], \"ranking\": [");
        for (int i = 0; i < n; i++) put(t, "%s\"%s\"", i ? ", " : "", stats_S.groups[order[i]].name);
        put(t, "]}");
    }
    put(t, "]}\n");
}

#else
typedef int tool_stats_table_not_built; /* board profile: amorph stats is not built */
#endif
