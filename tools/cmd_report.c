/* amorph report: the tables of docs/results.md that come from the run folders' log.csv, computed
 * here from the library's reader of log.csv (am_evo_log_read_line) so that results/report.sh only
 * calls the program and assembles its output (docs/results.md):
 *   last RUN       "EVALUATIONS BEST": the last row of the run's log.csv
 *   fig6 RUN...    Figure 6: the runs <rep>-<k> of each representation (dct, cppn, gmx), the mean
 *                  +- standard error of their best fitness so far every 500 evaluations, over the
 *                  runs that reached it; then each run's best so far every 1,000
 *   compute RUN... a row per run: evaluations, hours of one thread (the sum of log.csv's wall_s, a
 *                  generation that took more than 5 times the median of its window of 1,000
 *                  evaluations counted as that median)
 *                  and the generations so counted (paused); then the compute of each round: per
 *                  group of runs and per experiment, the runs and hours of the generations that
 *                  ended in each window of 1,000 evaluations
 *   best-at N RUN  the run's best fitness so far at N evaluations (%.4f), nothing before it got there
 *   range N RUN... over the runs that reached N evaluations, their best so far there (each as
 *                  best-at prints it): "RUNS MEAN STDERR LOW HIGH", nothing when none did
 *   bodies RUN...  the mean voxels of the bodies each representation evaluated in each window of
 *                  500 evaluations (each run's evals.csv.gz, as results/ship.sh ships it) */
#include "cmd.h"
#if !defined(AM_PROFILE_BOARD)

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define REPORT_MAX_RUNS 256
#define REPORT_MAX_ROWS 8192          /* generations of one run */
#define REPORT_MAX_MARKS 400          /* multiples of 500 evaluations (200,000) */
#define REPORT_NAME_MAX 128

/* the command's state: large, so static (one command runs at a time) */
static struct {
    long evals[REPORT_MAX_ROWS];
    double best[REPORT_MAX_ROWS], wall[REPORT_MAX_ROWS];
    int rows;
    /* fig6: each run's name, representation and best so far at every multiple of 500 it reached */
    char name[REPORT_MAX_RUNS][REPORT_NAME_MAX];
    int rep[REPORT_MAX_RUNS];         /* index into reps, -1 for another */
    int marks[REPORT_MAX_RUNS];       /* multiples of 500 reached: at[r][0 .. marks - 1] */
    double at[REPORT_MAX_RUNS][REPORT_MAX_MARKS];
} R;

static const char* const reps[3] = {"dct", "cppn", "gmx"};

/* one row of a run's log.csv into R's rows */
static am_status report_row(void* ctx, const char* fname, int lineno, const am_evo_stats* row, char* err, int errsz)
{
    (void)ctx;
    if (R.rows >= REPORT_MAX_ROWS) return am_fail_at(err, errsz, AM_ERR_CAPACITY, fname, lineno, "more than %d generations", REPORT_MAX_ROWS);
    R.evals[R.rows] = row->evaluations;
    R.best[R.rows] = row->best;
    R.wall[R.rows++] = row->wall_s;
    return AM_OK;
}

/* RUN/log.csv into R's rows; 0 or 2 after a message */
static int read_rows(const char* run)
{
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    if (snprintf(path, sizeof path, "%s/" AM_RUN_LOG, run) >= (int)sizeof path) return tool_usage_error("report: %.60s...: path too long", run);
    R.rows = 0;
    am_status st = tool_log_each(path, report_row, NULL, err, sizeof err);
    if (st != AM_OK) return tool_usage_error("report: %s", err);
    return 0;
}

/* the last component of a folder name (trailing slashes left out) into out */
static void base_of(const char* dir, char* out, size_t cap)
{
    size_t end = strlen(dir);
    while (end > 1 && dir[end - 1] == '/') end--;
    size_t at = end;
    while (at > 0 && dir[at - 1] != '/') at--;
    snprintf(out, cap, "%.*s", (int)(end - at), dir + at);
}

static int report_last(const char* run)
{
    int rc = read_rows(run);
    if (rc) return rc;
    if (R.rows == 0) return tool_usage_error("report: %s/" AM_RUN_LOG ": no generations logged yet", run);
    printf("%ld %.9g\n", R.evals[R.rows - 1], R.best[R.rows - 1]);
    return 0;
}

/* over the runs of representation p that reached mark k (500 (k + 1) evaluations), in the order
 * given: their number, mean and its standard error */
static int mark_stats(int nruns, int p, int k, double* mean, double* se)
{
    int n = 0;
    double s = 0, s2 = 0;
    for (int r = 0; r < nruns; r++)
        if (R.rep[r] == p && k < R.marks[r]) {
            const double v = R.at[r][k];
            n++;
            s += v;
            s2 += v * v;
        }
    *mean = n ? s / n : 0;
    const double var = n > 1 ? (s2 - n * *mean * *mean) / (n - 1) : 0;
    *se = sqrt(var > 0 ? var / n : 0);
    return n;
}

static int report_fig6(int nruns, char** runs)
{
    if (nruns > REPORT_MAX_RUNS) return tool_usage_error("report: more than %d runs", REPORT_MAX_RUNS);
    long top = 0;
    for (int r = 0; r < nruns; r++) {
        int rc = read_rows(runs[r]);
        if (rc) return rc;
        base_of(runs[r], R.name[r], sizeof R.name[r]);
        /* the representation: the name without its -<k> */
        char rep[REPORT_NAME_MAX];
        snprintf(rep, sizeof rep, "%s", R.name[r]);
        char* dash = strrchr(rep, '-');
        if (dash && dash[1] && strspn(dash + 1, "0123456789") == strlen(dash + 1)) *dash = 0;
        R.rep[r] = -1;
        for (int p = 0; p < 3; p++)
            if (!strcmp(rep, reps[p])) R.rep[r] = p;
        /* every multiple m of 500 in (previous row, this row]: the best of the rows at or below m */
        double best = -1;
        long prev = 0;
        R.marks[r] = 0;
        for (int i = 0; i < R.rows; i++) {
            const long e = R.evals[i];
            const double before = best;
            if (R.best[i] > best) best = R.best[i];
            for (long m = 500 * (prev / 500 + 1); m <= e; m += 500) {
                const long k = m / 500 - 1;
                if (k >= REPORT_MAX_MARKS) return tool_usage_error("report: %s: more than %d times 500 evaluations", runs[r], REPORT_MAX_MARKS);
                R.at[r][k] = m == e ? best : before;
                if (k + 1 > R.marks[r]) R.marks[r] = (int)(k + 1);
            }
            prev = e;
            if (e > top) top = e;
        }
    }
    printf("| evaluations | DCT | CPPN | GMX |\n|---:|---|---|---|\n");
    for (long m = 500; m <= top; m += 500) {
        printf("| %ld |", m);
        for (int p = 0; p < 3; p++) {
            double mean, se;
            const int n = mark_stats(nruns, p, (int)(m / 500 - 1), &mean, &se);
            if (n == 0) printf("  |");
            else if (n == 1) printf(" %.4f (1 run) |", mean);
            else printf(" %.4f +- %.4f (%d runs) |", mean, se, n);
        }
        printf("\n");
    }
    printf("\n| run |");
    for (long m = 1000; m <= top; m += 1000) printf(" %ld |", m);
    printf("\n|---|");
    for (long m = 1000; m <= top; m += 1000) printf("---:|");
    printf("\n");
    for (int r = 0; r < nruns; r++) {
        printf("| representations/%s |", R.name[r]);
        for (long m = 1000; m <= top; m += 1000) {
            const int k = (int)(m / 500 - 1);
            if (k < R.marks[r]) printf(" %.4f |", R.at[r][k]);
            else printf(" |");
        }
        printf("\n");
    }
    return 0;
}

/* the best so far at n evaluations of the rows read, as best-at prints it (4 decimals) in out; 0
 * when the run has not got there */
static int best_at(long n, char* out, size_t cap)
{
    double best = -1;
    int got = 0;
    for (int i = 0; i < R.rows; i++) {
        if (R.evals[i] <= n && R.best[i] > best) best = R.best[i];
        if (R.evals[i] >= n) got = 1;
    }
    if (got) snprintf(out, cap, "%.4f", best);
    return got;
}

static int report_best_at(long n, const char* run)
{
    char v[64];
    int rc = read_rows(run);
    if (rc) return rc;
    if (best_at(n, v, sizeof v)) printf("%s\n", v);
    return 0;
}

static int report_range(long n, int nruns, char** runs)
{
    int k = 0;
    double s = 0, s2 = 0, lo = 0, hi = 0;
    for (int r = 0; r < nruns; r++) {
        char v[64];
        int rc = read_rows(runs[r]);
        if (rc) return rc;
        if (!best_at(n, v, sizeof v)) continue;
        const double x = strtod(v, NULL); /* the value as printed: the table compares the printed ones */
        k++;
        s += x;
        s2 += x * x;
        if (k == 1 || x < lo) lo = x;
        if (k == 1 || x > hi) hi = x;
    }
    if (!k) return 0;
    const double m = s / k;
    const double var = k > 1 ? (s2 - k * m * m) / (k - 1) : 0;
    printf("%d %.4f %.4f %.4f %.4f\n", k, m, sqrt(var > 0 ? var / k : 0), lo, hi);
    return 0;
}

#define REPORT_GZ_MAX (4L << 20)      /* a shipped evals.csv.gz */
#define REPORT_CSV_MAX (64L << 20)    /* and its text */
#define REPORT_WINDOWS 4096           /* windows of 500 evaluations */

static int report_bodies(int nruns, char** runs)
{
    static char gz[REPORT_GZ_MAX];
    static uint8_t csv[REPORT_CSV_MAX + 1];
    static double sum[3][REPORT_WINDOWS];
    static long count[3][REPORT_WINDOWS];
    static am_inflate_work w;
    memset(sum, 0, sizeof sum);
    memset(count, 0, sizeof count);
    long top = -1;
    for (int r = 0; r < nruns; r++) {
        char path[TOOL_PATH_MAX], err[AM_ERR_MAX], msg[AM_ERR_MAX], name[REPORT_NAME_MAX];
        if (snprintf(path, sizeof path, "%s/" AM_RUN_EVALS ".gz", runs[r]) >= (int)sizeof path)
            return tool_usage_error("report: %.60s...: path too long", runs[r]);
        long n = 0, len = 0;
        if (am_port_read_file(path, gz, REPORT_GZ_MAX, &n, err, sizeof err) != AM_OK) return tool_usage_error("report: %s", err);
        if (am_gzip_inflate((const uint8_t*)gz, n, csv, REPORT_CSV_MAX, &len, &w, msg, sizeof msg) != AM_OK)
            return tool_usage_error("report: %s: %s", path, msg);
        csv[len] = 0;
        /* the representation: the folder's name up to its last '-' */
        base_of(runs[r], name, sizeof name);
        char* dash = strrchr(name, '-');
        if (dash) *dash = 0;
        int p = -1;
        for (int k = 0; k < 3; k++)
            if (!strcmp(name, reps[k])) p = k;
        /* the header names the columns */
        char* const stop = (char*)csv + len;
        char* line = (char*)csv;
        int c_eval = -1, c_vox = -1, lineno = 1;
        char* nl = memchr(line, '\n', (size_t)(stop - line));
        if (!nl) return tool_usage_error("report: %s:1: no header line", path);
        *nl = 0;
        int col = 0;
        for (char* f = line; f; col++) {
            char* comma = strchr(f, ',');
            size_t fl = comma ? (size_t)(comma - f) : strlen(f);
            if (fl == 10 && !strncmp(f, "evaluation", 10)) c_eval = col;
            if (fl == 6 && !strncmp(f, "voxels", 6)) c_vox = col;
            f = comma ? comma + 1 : NULL;
        }
        if (c_eval < 0 || c_vox < 0) return tool_usage_error("report: %s:1: no evaluation or voxels column", path);
        for (line = nl + 1; line < stop; line = nl + 1) {
            lineno++;
            nl = memchr(line, '\n', (size_t)(stop - line));
            if (!nl) nl = stop; /* the last line without its newline (csv[len] is its NUL) */
            *nl = 0;
            if (!*line) continue;
            long v[2] = {-1, -1};
            col = 0;
            for (char* f = line; f; col++) {
                char* comma = strchr(f, ',');
                if (col == c_eval || col == c_vox) {
                    char* e2;
                    long x = strtol(f, &e2, 10);
                    if (e2 == f || (*e2 && *e2 != ',') || x < 0)
                        return tool_usage_error("report: %s:%d: column %d: not a whole number from 0", path, lineno, col + 1);
                    v[col == c_vox] = x;
                }
                f = comma ? comma + 1 : NULL;
            }
            if (v[0] < 0 || v[1] < 0) return tool_usage_error("report: %s:%d: fewer fields than the header", path, lineno);
            const long win = v[0] / 500;
            if (win >= REPORT_WINDOWS) return tool_usage_error("report: %s:%d: evaluation %ld past %d windows of 500", path, lineno, v[0], REPORT_WINDOWS);
            if (win > top) top = win;
            if (p >= 0) {
                sum[p][win] += (double)v[1];
                count[p][win]++;
            }
        }
    }
    printf("| evaluations | DCT voxels | CPPN voxels | GMX voxels |\n|---:|---:|---:|---:|\n");
    for (long k = 0; k <= top; k++) {
        printf("| %ld-%ld |", k * 500 + 1, (k + 1) * 500);
        for (int p = 0; p < 3; p++)
            if (count[p][k]) printf(" %.0f (%ld bodies) |", sum[p][k] / (double)count[p][k], count[p][k]);
            else printf(" |");
        printf("\n");
    }
    return 0;
}

static int cmp_double(const void* a, const void* b)
{
    const double x = *(const double*)a, y = *(const double*)b;
    return x < y ? -1 : x > y;
}

/* the compute of each round: per group of runs (a run's folder name without its trailing -K, with
 * its experiment's folder: representations/dct) and per experiment (its folder: representations),
 * the hours of the generations that ended in each window of 1,000 evaluations */
#define ROUND_EVALS 1000
#define ROUND_MAX 200                 /* windows (200,000 evaluations) */
static struct {
    char name[REPORT_MAX_RUNS][REPORT_NAME_MAX]; /* a group's, or an experiment's name */
    int experiment[REPORT_MAX_RUNS];  /* 1: the whole experiment's folder */
    int n;
    double hours[REPORT_MAX_RUNS][ROUND_MAX];
    int runs[REPORT_MAX_RUNS][ROUND_MAX];
    int top;                          /* windows in use */
} Q;

/* the slot of a group (or experiment) name, made on first use; -1 when full */
static int round_slot(const char* name, int experiment)
{
    for (int i = 0; i < Q.n; i++)
        if (Q.experiment[i] == experiment && !strcmp(Q.name[i], name)) return i;
    if (Q.n == REPORT_MAX_RUNS) return -1;
    snprintf(Q.name[Q.n], REPORT_NAME_MAX, "%s", name);
    Q.experiment[Q.n] = experiment;
    return Q.n++;
}

/* the name of a run's group and experiment: "representations/dct" and "representations" for
 * .../representations/dct-3 (a name without a -K suffix is its own group) */
static void round_names(const char* run, char* group, char* experiment, size_t cap)
{
    char base[REPORT_NAME_MAX], parent[TOOL_PATH_MAX];
    base_of(run, base, sizeof base);
    size_t end = strlen(run);
    while (end > 1 && run[end - 1] == '/') end--;
    while (end > 0 && run[end - 1] != '/') end--;
    snprintf(parent, sizeof parent, "%.*s", (int)(end ? end - 1 : 0), run);
    base_of(parent[0] ? parent : ".", experiment, cap);
    size_t k = strlen(base);
    while (k > 0 && base[k - 1] >= '0' && base[k - 1] <= '9') k--;
    if (k > 0 && k < strlen(base) && base[k - 1] == '-') base[k - 1] = 0;
    snprintf(group, cap, "%s/%s", experiment, base);
}

static void round_row(int i, int w, const char* tail)
{
    printf("| %s%s | %d-%d | %d | %.2f | %.2f |\n", Q.name[i], tail, w * ROUND_EVALS + 1, (w + 1) * ROUND_EVALS, Q.runs[i][w], Q.hours[i][w],
           Q.hours[i][w] / Q.runs[i][w]);
}

static void round_table(void)
{
    printf("\n| group | evaluations | runs | hours | hours a run |\n|---|---:|---:|---:|---:|\n");
    /* each experiment (in the order first met), each window: its groups, then the whole */
    for (int e = 0; e < Q.n; e++) {
        if (!Q.experiment[e]) continue;
        const size_t el = strlen(Q.name[e]);
        for (int w = 0; w < Q.top; w++) {
            if (!Q.runs[e][w]) continue;
            for (int i = 0; i < Q.n; i++)
                if (!Q.experiment[i] && !strncmp(Q.name[i], Q.name[e], el) && Q.name[i][el] == '/' && Q.runs[i][w]) round_row(i, w, "");
            round_row(e, w, " (all)");
        }
    }
}

/* the window of ROUND_EVALS evaluations a generation that ended at `evals` is in (1..1000: the first) */
static long window_of(long evals) { return evals > 0 ? (evals - 1) / ROUND_EVALS : 0; }

/* the lower median of wall_s over the rows of R from row `first` on that end in its window of
 * ROUND_EVALS evaluations: a window's hours never move once the run has gone past it */
static double window_median(int first)
{
    static double sorted[REPORT_MAX_ROWS];
    const long win = window_of(R.evals[first]);
    int n = 0;
    for (int i = first; i < R.rows && window_of(R.evals[i]) == win; i++) sorted[n++] = R.wall[i];
    qsort(sorted, (size_t)n, sizeof sorted[0], cmp_double);
    return sorted[(n + 1) / 2 - 1];
}

static int report_compute(const char* root, int nruns, char** runs)
{
    printf("| run | evaluations | hours | paused generations |\n|---|---:|---:|---:|\n");
    const size_t rl = root ? strlen(root) : 0;
    memset(&Q, 0, sizeof Q);
    for (int r = 0; r < nruns; r++) {
        int rc = read_rows(runs[r]);
        if (rc) return rc;
        for (int i = 0; i < R.rows; i++)
            if (isnan(R.wall[i])) return tool_usage_error("report: %s/" AM_RUN_LOG ": no wall_s column", runs[r]);
        char group[REPORT_NAME_MAX], experiment[REPORT_NAME_MAX];
        round_names(runs[r], group, experiment, sizeof group);
        const int slot[2] = {round_slot(group, 0), round_slot(experiment, 1)};
        if (slot[0] < 0 || slot[1] < 0) return tool_usage_error("report: more than %d groups of runs", REPORT_MAX_RUNS);
        double t = 0, med = 0;
        int paused = 0, last_w = -1;
        for (int i = 0; i < R.rows; i++) {
            const long win = window_of(R.evals[i]);
            if (win >= ROUND_MAX) return tool_usage_error("report: %s: evaluation %ld past %d windows of %d", runs[r], R.evals[i], ROUND_MAX, ROUND_EVALS);
            if (win != last_w) med = window_median(i);
            double w = R.wall[i];
            /* over 5 times its window's median: paused, and counted as it */
            if (w > 5 * med) {
                w = med;
                paused++;
            }
            t += w;
            for (int k = 0; k < 2; k++) {
                Q.hours[slot[k]][win] += w / 3600;
                if (win != last_w) Q.runs[slot[k]][win]++;
            }
            last_w = (int)win;
            if (win + 1 > Q.top) Q.top = (int)win + 1;
        }
        const char* name = runs[r];
        if (rl && !strncmp(name, root, rl) && name[rl] == '/') name += rl + 1;
        printf("| %s | %ld | %.2f | %d |\n", name, R.rows ? R.evals[R.rows - 1] : 0, t / 3600, paused);
    }
    round_table();
    return 0;
}

static const char report_help[] =
    "usage: amorph report TABLE [--root DIR] [N] RUN...\n"
    "Prints a table of docs/results.md from run folders' log.csv (results/report.sh assembles them):\n"
    "  last RUN        'EVALUATIONS BEST': the run's last logged generation\n"
    "  fig6 RUN...     Figure 6: per representation (runs named dct-<k>, cppn-<k>, gmx-<k>) the mean\n"
    "                  +- standard error of the best fitness so far every 500 evaluations, over the\n"
    "                  runs that reached it; then each run's best so far every 1,000\n"
    "  compute RUN...  a row per run: evaluations, hours (the sum of wall_s; a generation over 5 times\n"
    "                  the median of its window of 1,000 evaluations counts as that median) and those\n"
    "                  paused generations; then the rounds: per group of runs (the folder name\n"
    "                  without -K, in its experiment's folder) and per experiment, the runs and hours\n"
    "                  of the generations that ended in each window of 1,000 evaluations\n"
    "  best-at N RUN   the run's best fitness so far at N evaluations, nothing before it got there\n"
    "  range N RUN...  over the runs that reached N evaluations: 'RUNS MEAN STDERR LOW HIGH' of their\n"
    "                  best so far there (each to 4 decimals, as best-at prints it)\n"
    "  bodies RUN...   the mean voxels of the bodies each representation evaluated per 500\n"
    "                  evaluations, from each run's evals.csv.gz\n"
    "  --root DIR      compute: runs named relative to DIR\n";

int cmd_report(tool_ctx* c, int argc, char** argv)
{
    (void)c;
    if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
        fputs(report_help, argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    const char* table = argv[1];
    if (table[0] == '-') return tool_unknown_option("report", table, report_help);
    const char* root = NULL;
    int first = 2;
    if (first + 1 < argc && !strcmp(argv[first], "--root")) root = argv[first + 1], first += 2;
    const int n = argc - first;
    for (int i = first; i < argc; i++)
        if (argv[i][0] == '-') return tool_unknown_option("report", argv[i], report_help);
    if (!strcmp(table, "last")) {
        if (n != 1) return tool_usage_error("report: last takes one run folder");
        return report_last(argv[first]);
    }
    if (!strcmp(table, "best-at") || !strcmp(table, "range")) {
        long at;
        if (n < 1 || !tool_parse_long(argv[first], 1, 1000000000L, &at))
            return tool_usage_error("report: %s needs a number of evaluations, 1..1000000000, then run folders", table);
        if (n < 2 || (table[0] == 'b' && n != 2)) return tool_usage_error("report: %s N takes %s", table, table[0] == 'b' ? "one run folder" : "run folders");
        return table[0] == 'b' ? report_best_at(at, argv[first + 1]) : report_range(at, n - 1, argv + first + 1);
    }
    if (n < 1) return tool_usage_error("report: %s needs run folders (amorph report --help)", table);
    if (!strcmp(table, "fig6")) return report_fig6(n, argv + first);
    if (!strcmp(table, "compute")) return report_compute(root, n, argv + first);
    if (!strcmp(table, "bodies")) return report_bodies(n, argv + first);
    char q[AM_QUOTE_BUF];
    return tool_usage_error("report: unknown table '%s' (last, fig6, compute, best-at, range, bodies)", am_quote(q, sizeof q, table, -1));
}

#else
/* the board profile: the report's tables belong to the desktop */
int cmd_report(tool_ctx* c, int argc, char** argv)
{
    (void)c, (void)argc, (void)argv;
    return tool_not_in_build("report", "the report's tables");
}
#endif
