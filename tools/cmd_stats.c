/* amorph stats: groups of run folders compared by tests (tools/stats.h): at every N evaluations,
 * each group's best fitness so far (n, mean, standard deviation, standard error), and for each
 * pair of groups Welch's t-test, the Mann-Whitney test, Cohen's d and Hedges' g and the runs
 * needed for 80% power; or the same on the sustained score of each run's best robot
 * (gait30.json). Markdown tables or one JSON object. docs/results.md, Statistics. */
#include "cmd.h"
#if !defined(AM_PROFILE_BOARD)

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "stats.h"

#define STATS_MAX_RUNS TOOL_STATS_MAX_N /* run folders in all */
#define STATS_MAX_GROUPS 16
#define STATS_MAX_COUNTS 500            /* checkpoints (every N evaluations) of one run */
#define STATS_NAME_MAX 64
#define STATS_GAIT_FILE "gait30.json"
/* the sustained score: gait30.json's sustained_travel, the travel per cycle over cycles 11-30 (the
 * centre of mass's displacement from the end of cycle 10 to the end of cycle 30, over 20: docs/evolve.md,
 * score); its cycle_travel must hold the 30 cycles */
#define STATS_SUSTAINED_TO 30

#define GAITS 5
static const char* const gait_names[GAITS] = {"still", "flop", "scoot", "bounce", "roll"};

typedef struct stats_run {
    const char* dir;
    int group;
    long last;                       /* evaluations of its last log.csv row */
    int counts;                      /* checkpoints reached: val[0 .. counts-1] */
    double val[STATS_MAX_COUNTS];    /* best fitness so far at (k + 1) * every evaluations, m */
    double sustained;                /* --score sustained: its best robot's, m per cycle */
    int gait;                        /* index into gait_names */
} stats_run;

typedef struct stats_group {
    char name[STATS_NAME_MAX];
    int runs[STATS_MAX_RUNS];
    int n;
    int counts;                      /* checkpoints every run of the group reached */
    int gaits[GAITS];
} stats_group;

/* the command's state: large, so static (one command runs at a time) */
static struct {
    stats_run runs[STATS_MAX_RUNS];
    int nruns;
    stats_group groups[STATS_MAX_GROUPS];
    int ngroups;
    long every;
    int sustained;                   /* --score sustained */
    tool_stats_work work;
    double a[STATS_MAX_RUNS], b[STATS_MAX_RUNS];
} S;

/* ---- reading the runs ---- */

/* the group named name, made when new; -1 past capacity */
static int group_of(const char* name, long len)
{
    for (int g = 0; g < S.ngroups; g++)
        if ((long)strlen(S.groups[g].name) == len && !strncmp(S.groups[g].name, name, (size_t)len)) return g;
    if (S.ngroups >= STATS_MAX_GROUPS) return -1;
    stats_group* G = &S.groups[S.ngroups];
    memset(G, 0, sizeof *G);
    memcpy(G->name, name, (size_t)len);
    G->name[len] = 0;
    return S.ngroups++;
}

/* 1 when the name can head a table cell and a JSON string as it is */
static int plain_name(const char* s, long len)
{
    if (len <= 0 || len >= STATS_NAME_MAX) return 0;
    for (long i = 0; i < len; i++)
        if (s[i] == '|' || s[i] == '"' || s[i] == '\\' || (unsigned char)s[i] < 0x21 || (unsigned char)s[i] > 0x7e) return 0;
    return 1;
}

/* the length of a path without its trailing '/'s */
static size_t path_len(const char* p)
{
    size_t n = strlen(p);
    while (n > 1 && p[n - 1] == '/') n--;
    return n;
}

/* adds run folder dir to group `name` (len bytes), or, name NULL, to the group of its folder name
 * without the trailing -K (dct-2: dct); 0 or 2 after a message */
static int add_run(const char* dir, const char* name, long len)
{
    char q[AM_QUOTE_BUF];
    if (S.nruns >= STATS_MAX_RUNS) return tool_usage_error("stats: more than %d runs", STATS_MAX_RUNS);
    for (int r = 0; r < S.nruns; r++)
        if (path_len(S.runs[r].dir) == path_len(dir) && !strncmp(S.runs[r].dir, dir, path_len(dir)))
            return tool_usage_error("stats: %s: the same run named twice", am_quote(q, sizeof q, dir, -1));
    if (!name) {
        long end = (long)strlen(dir);
        while (end > 1 && dir[end - 1] == '/') end--;
        long start = end;
        while (start > 0 && dir[start - 1] != '/') start--;
        long cut = end;
        while (cut > start && dir[cut - 1] >= '0' && dir[cut - 1] <= '9') cut--;
        name = dir + start;
        len = cut < end && cut - 1 > start && dir[cut - 1] == '-' ? cut - 1 - start : end - start;
    }
    if (!plain_name(name, len))
        return tool_usage_error("stats: %s: a group name of 1 to %d printable characters without '|', '\"', '\\' or blanks",
                                am_quote(q, sizeof q, name, len), STATS_NAME_MAX - 1);
    int g = group_of(name, len);
    if (g < 0) return tool_usage_error("stats: more than %d groups", STATS_MAX_GROUPS);
    stats_run* R = &S.runs[S.nruns];
    memset(R, 0, sizeof *R);
    R->dir = dir;
    R->group = g;
    S.groups[g].runs[S.groups[g].n++] = S.nruns++;
    return 0;
}

/* one run's log.csv being read: the best so far, and the checkpoints passed */
typedef struct log_reading {
    stats_run* R;
    double best;
    int rows;
} log_reading;

/* one line of log.csv: every checkpoint m from the last row's evaluations up to (not including)
 * this row's takes the best so far of the rows at or below it (the first row's, for a checkpoint
 * before the first row) */
static am_status log_row(void* ctx, const char* fname, int lineno, const am_evo_stats* rowp, char* err, int errsz)
{
    log_reading* lr = (log_reading*)ctx;
    stats_run* R = lr->R;
    const am_evo_stats row = *rowp;
    if (lr->rows > 0 && row.evaluations < R->last)
        return am_fail_at(err, errsz, AM_ERR_PARSE, fname, lineno, "evaluations go backwards (%ld after %ld)", row.evaluations, R->last);
    const double before = lr->rows > 0 ? lr->best : row.best;
    for (long m = (R->counts + 1) * S.every; m < row.evaluations; m += S.every) {
        if (R->counts >= STATS_MAX_COUNTS)
            return am_fail_at(err, errsz, AM_ERR_CAPACITY, fname, lineno, "more than %d counts of %ld evaluations (a larger --every)",
                              STATS_MAX_COUNTS, S.every);
        R->val[R->counts++] = before;
    }
    if (lr->rows == 0 || row.best > lr->best) lr->best = row.best;
    R->last = row.evaluations;
    lr->rows++;
    /* a row at a checkpoint holds it itself */
    if (row.evaluations == (R->counts + 1) * S.every) {
        if (R->counts >= STATS_MAX_COUNTS)
            return am_fail_at(err, errsz, AM_ERR_CAPACITY, fname, lineno, "more than %d counts of %ld evaluations (a larger --every)",
                              STATS_MAX_COUNTS, S.every);
        R->val[R->counts++] = lr->best;
    }
    return AM_OK;
}

/* reads the run's log.csv into its checkpoints; 0 or 2 after a message */
static int read_log(stats_run* R)
{
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    if (snprintf(path, sizeof path, "%s/" AM_RUN_LOG, R->dir) >= (int)sizeof path) return tool_usage_error("stats: %.60s...: path too long", R->dir);
    if (!am_port_exists(path)) return tool_usage_error("stats: %s: no such file (not a run folder of amorph evolve)", path);
    log_reading lr;
    lr.R = R;
    lr.best = 0;
    lr.rows = 0;
    am_status st = tool_log_each(path, log_row, &lr, err, sizeof err);
    if (st != AM_OK) return tool_usage_error("stats: %s", err);
    if (lr.rows == 0) return tool_usage_error("stats: %s: no generations logged yet", path);
    return 0;
}

/* gait30.json being read: the cycle travels and the gait's name, from whichever line holds them */
typedef struct gait_reading {
    const char* path;
    int cycles;                      /* values of cycle_travel (-1 before it is found) */
    int gait;                        /* -1 before it is found */
    int has_sustained;               /* 1 once sustained_travel is read */
    double sustained;                /* sustained_travel: m per cycle, cycles 11-30 */
} gait_reading;

/* where "key": starts its value in line (after the colon and blanks), or NULL */
static char* json_value(char* line, const char* key)
{
    char pat[64];
    snprintf(pat, sizeof pat, "\"%s\"", key);
    for (char* at = strstr(line, pat); at; at = strstr(at + 1, pat)) {
        char* v = at + strlen(pat);
        while (*v == ' ' || *v == '\t') v++;
        if (*v != ':') continue;
        v++;
        while (*v == ' ' || *v == '\t') v++;
        return v;
    }
    return NULL;
}

static am_status gait_line(void* ctx, int lineno, char* line, long n, char* err, int errsz)
{
    gait_reading* gr = (gait_reading*)ctx;
    char q[AM_QUOTE_BUF];
    (void)n;
    char* v = json_value(line, "cycle_travel");
    if (v) {
        if (*v != '[') return am_fail_at(err, errsz, AM_ERR_PARSE, gr->path, lineno, "cycle_travel is not an array");
        v++;
        gr->cycles = 0;
        for (;;) {
            while (*v == ' ' || *v == '\t') v++;
            if (*v == ']' && gr->cycles == 0) break;
            char* end = v;
            while (*end && *end != ',' && *end != ']') end++;
            if (!*end) return am_fail_at(err, errsz, AM_ERR_PARSE, gr->path, lineno, "cycle_travel: no closing ']' on its line");
            char tok[64];
            long len = (long)(end - v);
            while (len > 0 && (v[len - 1] == ' ' || v[len - 1] == '\t')) len--;
            double x;
            if (len <= 0 || len >= (long)sizeof tok) x = (double)NAN;
            else {
                memcpy(tok, v, (size_t)len);
                tok[len] = 0;
                if (!am_parse_double(tok, &x)) x = (double)NAN;
            }
            if (isnan(x))
                return am_fail_at(err, errsz, AM_ERR_PARSE, gr->path, lineno, "cycle_travel[%d]: not a number: '%s'", gr->cycles,
                                  am_quote(q, sizeof q, v, len));
            gr->cycles++;
            v = end + 1;
            if (*end == ']') break;
        }
    }
    v = json_value(line, "gait");
    if (v) {
        int k = -1;
        for (int i = 0; i < GAITS; i++) {
            size_t len = strlen(gait_names[i]);
            if (v[0] == '"' && !strncmp(v + 1, gait_names[i], len) && v[len + 1] == '"') k = i;
        }
        if (k < 0) {
            long len = 0;
            while (v[len] && v[len] != ',' && v[len] != '}') len++;
            return am_fail_at(err, errsz, AM_ERR_PARSE, gr->path, lineno, "gait: not still, flop, scoot, bounce or roll: '%s'", am_quote(q, sizeof q, v, len));
        }
        gr->gait = k;
    }
    v = json_value(line, "sustained_travel");
    if (v) {
        long len = 0;
        while (v[len] && v[len] != ',' && v[len] != '}' && v[len] != ' ') len++;
        char tok[64];
        double x = (double)NAN;
        if (len > 0 && len < (long)sizeof tok) {
            memcpy(tok, v, (size_t)len);
            tok[len] = 0;
            if (!am_parse_double(tok, &x)) x = (double)NAN;
        }
        if (isnan(x)) return am_fail_at(err, errsz, AM_ERR_PARSE, gr->path, lineno, "sustained_travel: not a number: '%s'", am_quote(q, sizeof q, v, len));
        gr->sustained = x;
        gr->has_sustained = 1;
    }
    return AM_OK;
}

/* reads the run's gait30.json: its sustained score and gait; 0 or 2 after a message */
static int read_gait(stats_run* R)
{
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    if (snprintf(path, sizeof path, "%s/" STATS_GAIT_FILE, R->dir) >= (int)sizeof path) return tool_usage_error("stats: %.60s...: path too long", R->dir);
    if (!am_port_exists(path))
        return tool_usage_error("stats: %s: no such file (results/report.sh writes it: amorph sim %s --cycles 30 --json)", path, R->dir);
    gait_reading gr;
    gr.path = path;
    gr.cycles = -1;
    gr.gait = -1;
    gr.has_sustained = 0;
    gr.sustained = 0;
    tool_src src;
    am_status st = tool_src_open(&src, path, TOOL_FILE_MAX, 0, err, sizeof err);
    if (st != AM_OK && src.binary) st = tool_src_binary(&src, err, sizeof err);
    if (st == AM_OK) {
        st = tool_src_each(&src, gait_line, &gr, err, sizeof err);
        tool_src_close(&src);
    }
    if (st != AM_OK) return tool_usage_error("stats: %s", err);
    if (gr.cycles < 0) return tool_usage_error("stats: %s: no \"cycle_travel\" array (amorph sim RUN --cycles 30 --json writes one)", path);
    if (gr.cycles < STATS_SUSTAINED_TO)
        return tool_usage_error("stats: %s: cycle_travel holds %d cycles; the sustained score needs %d (amorph sim RUN --cycles 30 --json)", path,
                                gr.cycles, STATS_SUSTAINED_TO);
    if (gr.gait < 0) return tool_usage_error("stats: %s: no \"gait\" field", path);
    if (!gr.has_sustained)
        return tool_usage_error("stats: %s: no \"sustained_travel\" (amorph sim RUN --cycles 30 --json writes it)", path);
    R->sustained = gr.sustained;
    R->gait = gr.gait;
    return 0;
}

/* ---- the numbers at one count ---- */

/* the values of group g at checkpoint k (sustained: its scores) into x; their number */
static int values(int g, int k, double* x)
{
    const stats_group* G = &S.groups[g];
    for (int i = 0; i < G->n; i++) {
        const stats_run* R = &S.runs[G->runs[i]];
        x[i] = S.sustained ? R->sustained : R->val[k];
    }
    return G->n;
}

/* 1 when group g has a value at checkpoint k (every run reached it) */
static int has(int g, int k) { return S.sustained ? k == 0 : k < S.groups[g].counts; }

/* the groups that have checkpoint k, by mean from the highest (the first named first among equal
 * means) into order; their number */
static int ranked(int k, int* order, double* mean)
{
    int n = 0;
    for (int g = 0; g < S.ngroups; g++) {
        if (!has(g, k)) continue;
        tool_stats_sample s;
        tool_stats_describe(S.a, values(g, k, S.a), &s);
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
    int na = values(ga, k, S.a), nb = values(gb, k, S.b);
    tool_stats_compare_samples(S.a, na, S.b, nb, &S.work, c);
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
    if (S.sustained) put(t, "| sustained |");
    else put(t, "| %ld |", (k + 1) * S.every);
}

static int max_counts(void)
{
    int top = 0;
    for (int g = 0; g < S.ngroups; g++) top = S.groups[g].counts > top ? S.groups[g].counts : top;
    return S.sustained ? 1 : top;
}

static void markdown(am_text* t)
{
    const int top = max_counts(), dec = S.sustained ? 3 : 2;
    const char* key = S.sustained ? "score" : "evaluations";
    const char* what = S.sustained ? "travel per cycle, cycles 11-30" : "best fitness so far";
    static int order[STATS_MAX_GROUPS];
    static double mean[STATS_MAX_GROUPS];
    /* each group: its runs, mean, sd, se (and, sustained, its gaits) */
    put(t, "| %s | group | runs | mean %s (mm) | standard deviation (mm) | standard error (mm) |", key, what);
    if (S.sustained) put(t, " still | flop | scoot | bounce | roll |");
    put(t, "\n|---:|---|---:|---:|---:|---:|%s\n", S.sustained ? "---:|---:|---:|---:|---:|" : "");
    for (int k = 0; k < top; k++)
        for (int g = 0; g < S.ngroups; g++) {
            if (!has(g, k)) continue;
            tool_stats_sample s;
            tool_stats_describe(S.a, values(g, k, S.a), &s);
            put_key(t, k);
            put(t, " %s | %d |", S.groups[g].name, s.n);
            put_num(t, s.mean * 1000, dec);
            put_num(t, s.sd * 1000, dec);
            put_num(t, s.se * 1000, dec);
            if (S.sustained)
                for (int i = 0; i < GAITS; i++) put(t, " %d |", S.groups[g].gaits[i]);
            put(t, "\n");
        }
    /* each pair, the higher mean first */
    put(t, "\n| %s | pair | difference (mm) | Welch's t | df | p (Welch) | U | p (Mann-Whitney) | Cohen's d | Hedges' g | runs for 80%% power |\n", key);
    put(t, "|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (int k = 0; k < top; k++) {
        int n = ranked(k, order, mean);
        for (int i = 0; i < n; i++)
            for (int j = i + 1; j < n; j++) {
                tool_stats_compare c;
                compare(order[i], order[j], k, &c);
                put_key(t, k);
                put(t, " %s - %s |", S.groups[order[i]].name, S.groups[order[j]].name);
                put_num(t, c.difference * 1000, dec);
                if (!c.tested) {
                    const stats_group* few = S.groups[order[i]].n < 2 ? &S.groups[order[i]] : &S.groups[order[j]];
                    put(t, " no test: %s has %d run%s | | | | | | | |\n", few->name, few->n, few->n == 1 ? "" : "s");
                    continue;
                }
                put_num(t, c.t, 2);
                put_num(t, c.df, 1);
                put_p(t, c.p_welch, "");
                put(t, " %.*f |", c.u == floor(c.u) ? 0 : 1, c.u);
                put_p(t, c.p_mw, c.mw_exact ? "" : " (normal)");
                put_num(t, c.d, 2);
                put_num(t, c.g, 2);
                if (c.runs_needed > 0) put(t, " %ld |\n", c.runs_needed);
                else put(t, " - |\n");
            }
    }
    /* the ranking, and which of its differences each test finds at 0.05 */
    put(t, "\n| %s | ranking by mean | significant at 0.05, Welch's t | significant at 0.05, Mann-Whitney |\n|---:|---|---|---|\n", key);
    for (int k = 0; k < top; k++) {
        int n = ranked(k, order, mean);
        if (n < 2) continue;
        put_key(t, k);
        put(t, " %s", S.groups[order[0]].name);
        for (int i = 1; i < n; i++) {
            /* equal when the table's means are */
            char m1[64], m2[64];
            snprintf(m1, sizeof m1, "%.*f", dec, mean[i - 1] * 1000);
            snprintf(m2, sizeof m2, "%.*f", dec, mean[i] * 1000);
            int same = !strcmp(m1, m2);
            put(t, " %s %s", same ? "=" : ">", S.groups[order[i]].name);
        }
        put(t, " |");
        for (int test = 0; test < 2; test++) {
            int found = 0;
            for (int i = 0; i < n; i++)
                for (int j = i + 1; j < n; j++) {
                    tool_stats_compare c;
                    compare(order[i], order[j], k, &c);
                    double p = test == 0 ? c.p_welch : c.p_mw;
                    if (!c.tested || !(p < 0.05)) continue;
                    put(t, "%s %s > %s", found ? "," : "", S.groups[order[i]].name, S.groups[order[j]].name);
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

static void json(am_text* t)
{
    const int top = max_counts();
    static int order[STATS_MAX_GROUPS];
    static double mean[STATS_MAX_GROUPS];
    put(t, "{\"score\": \"%s\", ", S.sustained ? "sustained" : "best");
    if (!S.sustained) put(t, "\"every\": %ld, ", S.every);
    put(t, "\"groups\": [");
    for (int g = 0; g < S.ngroups; g++) {
        const stats_group* G = &S.groups[g];
        put(t, "%s{\"group\": \"%s\", \"runs\": [", g ? ", " : "", G->name);
        for (int i = 0; i < G->n; i++) {
            char esc[TOOL_PATH_MAX * 2];
            tool_json_escape(esc, sizeof esc, S.runs[G->runs[i]].dir);
            put(t, "%s\"", i ? ", " : "");
            am_text_write(t, esc, (long)strlen(esc));
            put(t, "\"");
        }
        put(t, "]");
        if (S.sustained)
            for (int i = 0; i < GAITS; i++) put(t, ", \"%s\": %d", gait_names[i], G->gaits[i]);
        else put(t, ", \"counts\": %d", G->counts);
        put(t, "}");
    }
    put(t, "], \"rows\": [");
    int rows = 0;
    for (int k = 0; k < top; k++) {
        int n = ranked(k, order, mean);
        if (n == 0) continue;
        put(t, "%s{", rows++ ? ", " : "");
        if (!S.sustained) put(t, "\"evaluations\": %ld, ", (k + 1) * S.every);
        put(t, "\"groups\": [");
        for (int g = 0, first = 1; g < S.ngroups; g++) {
            if (!has(g, k)) continue;
            tool_stats_sample s;
            tool_stats_describe(S.a, values(g, k, S.a), &s);
            put(t, "%s{\"group\": \"%s\", \"n\": %d", first ? "" : ", ", S.groups[g].name, s.n);
            put_jnum(t, "mean", s.mean, 1);
            put_jnum(t, "sd", s.sd, 1);
            put_jnum(t, "se", s.se, 1);
            put(t, "}");
            first = 0;
        }
        put(t, "], \"pairs\": [");
        for (int i = 0, first = 1; i < n; i++)
            for (int j = i + 1; j < n; j++) {
                tool_stats_compare c;
                compare(order[i], order[j], k, &c);
                put(t, "%s{\"a\": \"%s\", \"b\": \"%s\", \"tested\": %s", first ? "" : ", ", S.groups[order[i]].name, S.groups[order[j]].name,
                    c.tested ? "true" : "false");
                put_jnum(t, "difference", c.difference, 1);
                put_jnum(t, "t", c.t, 1);
                put_jnum(t, "df", c.df, 1);
                put_jnum(t, "p_welch", c.p_welch, 1);
                put_jnum(t, "u", c.u, 1);
                put_jnum(t, "p_mann_whitney", c.p_mw, 1);
                put(t, ", \"mann_whitney_exact\": %s", c.tested && c.mw_exact ? "true" : "false");
                put_jnum(t, "cohen_d", c.d, 1);
                put_jnum(t, "hedges_g", c.g, 1);
                if (c.runs_needed > 0) put(t, ", \"runs_needed\": %ld}", c.runs_needed);
                else put(t, ", \"runs_needed\": null}");
                first = 0;
            }
        put(t, "], \"ranking\": [");
        for (int i = 0; i < n; i++) put(t, "%s\"%s\"", i ? ", " : "", S.groups[order[i]].name);
        put(t, "]}");
    }
    put(t, "]}\n");
}

/* ---- the command ---- */

static const char stats_help[] =
    "usage: amorph stats [--score best|sustained] [--every N] [--group NAME=DIR[,DIR...]]... [--json] [DIR...]\n"
    "Compares groups of run folders (amorph evolve --out DIR) by tests. A DIR named on its own joins\n"
    "the group of its folder name without the trailing -K (runs/dct-1 and runs/dct-2: dct); --group\n"
    "names a group's runs explicitly. At every N evaluations that all the runs of a group have\n"
    "reached, each run's best fitness so far (log.csv: the best of its rows at or below N); for each\n"
    "group n, mean, standard deviation and standard error; for each pair of groups (the higher mean\n"
    "first) the difference, Welch's t with its Welch-Satterthwaite degrees of freedom and two-sided\n"
    "p, the Mann-Whitney U (the pairs of runs in which the first group's is the higher, ties one half)\n"
    "with its two-sided p (exact up to 20 runs a group, else the normal approximation), Cohen's d,\n"
    "Hedges' g and the runs per group a t-test needs to find a difference of that d with 80% power at\n"
    "0.05; then the ranking by mean with the differences each test finds significant at 0.05. A pair\n"
    "with a group of fewer than 2 runs is not tested. Markdown tables in mm (docs/results.md).\n"
    "  --score best       the best fitness so far from log.csv (the default)\n"
    "  --score sustained  each run's best robot's travel per cycle over cycles 11-30, its\n"
    "                     gait30.json's sustained_travel (amorph sim DIR --cycles 30 --json;\n"
    "                     results/report.sh writes it), and each group's gaits (still, flop,\n"
    "                     scoot, bounce, roll)\n"
    "  --every N          the counts compared: every N evaluations (1000)\n"
    "  --group NAME=DIRS  the runs DIRS (comma-separated) as group NAME\n"
    "  --json             one JSON object instead of the tables (values in m)\n";

int cmd_stats(tool_ctx* c, int argc, char** argv)
{
    (void)c;
    int as_json = 0;
    S.nruns = S.ngroups = 0;
    S.every = 1000;
    S.sustained = 0;
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        const char* v = i + 1 < argc ? argv[i + 1] : 0;
        char q[AM_QUOTE_BUF];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(stats_help, stdout);
            return 0;
        } else if (!strcmp(a, "--json")) {
            as_json = 1;
        } else if (!strcmp(a, "--score")) {
            if (!v || (strcmp(v, "best") && strcmp(v, "sustained"))) return tool_usage_error("stats: --score needs best or sustained");
            S.sustained = !strcmp(v, "sustained");
            i++;
        } else if (!strcmp(a, "--every")) {
            if (!tool_parse_long(v, 1, 1000000000L, &S.every)) return tool_usage_error("stats: --every needs a whole number 1..1000000000");
            i++;
        } else if (!strcmp(a, "--group")) {
            const char* eq = v ? strchr(v, '=') : 0;
            if (!eq || eq == v || !eq[1]) return tool_usage_error("stats: --group needs NAME=DIR[,DIR...]");
            i++;
            /* the folders, cut in place at their commas (argv's strings are the program's) */
            for (char* d = argv[i] + (eq - v) + 1; d;) {
                char* comma = strchr(d, ',');
                if (comma) *comma = 0;
                if (!*d) return tool_usage_error("stats: --group %s: an empty folder name", am_quote(q, sizeof q, v, eq - v));
                int rc = add_run(d, v, eq - v);
                if (rc) return rc;
                d = comma ? comma + 1 : 0;
            }
        } else if (a[0] == '-' && a[1]) {
            return tool_unknown_option("stats", a, stats_help);
        } else {
            int rc = add_run(a, NULL, 0);
            if (rc) return rc;
        }
    }
    if (S.nruns == 0) return tool_usage_error("stats: name run folders (amorph stats --help)");
    for (int r = 0; r < S.nruns; r++) {
        int rc = S.sustained ? read_gait(&S.runs[r]) : read_log(&S.runs[r]);
        if (rc) return rc;
    }
    for (int g = 0; g < S.ngroups; g++) {
        stats_group* G = &S.groups[g];
        G->counts = STATS_MAX_COUNTS;
        for (int i = 0; i < G->n; i++) {
            const stats_run* R = &S.runs[G->runs[i]];
            if (R->counts < G->counts) G->counts = R->counts;
            if (S.sustained) G->gaits[R->gait]++;
        }
    }
    if (!S.sustained && max_counts() == 0) {
        fprintf(stderr, "amorph: stats: no group's runs have all reached %ld evaluations: nothing to compare\n", S.every);
        return 0;
    }
    tool_out o;
    if (tool_out_open(&o, NULL)) return 1;
    if (as_json) json(&o.text);
    else markdown(&o.text);
    return tool_out_close(&o, 1);
}

#else
/* the board profile: statistics belong to the desktop (their tables take 1.3 MB) */
int cmd_stats(tool_ctx* c, int argc, char** argv)
{
    (void)c, (void)argc, (void)argv;
    return tool_not_in_build("stats", "statistics");
}
#endif
