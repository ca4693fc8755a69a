/* amorph report: the tables of docs/results.md that come from the run folders' log.csv, computed
 * here from the library's reader of log.csv (am_evo_log_read_line) so that results/report.sh only
 * calls the program and assembles its output (docs/results.md):
 *   last RUN       "EVALUATIONS BEST": the last row of the run's log.csv
 *   fig6 RUN...    Figure 6: the runs <rep>-<k> of each representation (dct, cppn, gmx), the mean
 *                  +- standard error of their best fitness so far every 500 evaluations, over the
 *                  runs that reached it; then each run's best so far every 1,000
 *   compute RUN... a row per run: evaluations, hours of one thread (the sum of log.csv's wall_s, a
 *                  generation that took more than 5 times the run's median counted as the median)
 *                  and the generations so counted (paused) */
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

typedef struct report_reading {
    am_evo_log_reader rd;
} report_reading;

static am_status report_line(void* ctx, int lineno, char* line, long n, char* err, int errsz)
{
    report_reading* rr = (report_reading*)ctx;
    am_evo_stats row;
    int is_row = 0;
    am_status st = am_evo_log_read_line(&rr->rd, line, n, &row, &is_row, err, errsz);
    if (st != AM_OK || !is_row) return st;
    if (R.rows >= REPORT_MAX_ROWS)
        return am_fail_at(err, errsz, AM_ERR_CAPACITY, rr->rd.fname, lineno, "more than %d generations", REPORT_MAX_ROWS);
    R.evals[R.rows] = row.evaluations;
    R.best[R.rows] = row.best;
    R.wall[R.rows++] = row.wall_s;
    return AM_OK;
}

/* RUN/log.csv into R's rows; 0 or 2 after a message */
static int read_rows(const char* run)
{
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    if (snprintf(path, sizeof path, "%s/" AM_RUN_LOG, run) >= (int)sizeof path) return tool_usage_error("report: %.60s...: path too long", run);
    R.rows = 0;
    report_reading rr;
    am_evo_log_read_begin(&rr.rd, path);
    tool_src src;
    am_status st = tool_src_open(&src, path, TOOL_FILE_MAX, 0, err, sizeof err);
    if (st != AM_OK && src.binary) st = tool_src_binary(&src, err, sizeof err);
    if (st == AM_OK) {
        st = tool_src_each(&src, report_line, &rr, err, sizeof err);
        if (st == AM_OK) st = am_evo_log_read_end(&rr.rd, err, sizeof err);
        tool_src_close(&src);
    }
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

static int cmp_double(const void* a, const void* b)
{
    const double x = *(const double*)a, y = *(const double*)b;
    return x < y ? -1 : x > y;
}

static int report_compute(const char* root, int nruns, char** runs)
{
    static double sorted[REPORT_MAX_ROWS];
    printf("| run | evaluations | hours | paused generations |\n|---|---:|---:|---:|\n");
    const size_t rl = root ? strlen(root) : 0;
    for (int r = 0; r < nruns; r++) {
        int rc = read_rows(runs[r]);
        if (rc) return rc;
        for (int i = 0; i < R.rows; i++) {
            if (isnan(R.wall[i])) return tool_usage_error("report: %s/" AM_RUN_LOG ": no wall_s column", runs[r]);
            sorted[i] = R.wall[i];
        }
        qsort(sorted, (size_t)R.rows, sizeof sorted[0], cmp_double);
        /* the lower median: a generation more than 5 times it was paused, and counts as it */
        const double med = R.rows ? sorted[(R.rows + 1) / 2 - 1] : 0;
        double t = 0;
        int paused = 0;
        for (int i = 0; i < R.rows; i++) {
            double w = R.wall[i];
            if (w > 5 * med) {
                w = med;
                paused++;
            }
            t += w;
        }
        const char* name = runs[r];
        if (rl && !strncmp(name, root, rl) && name[rl] == '/') name += rl + 1;
        printf("| %s | %ld | %.2f | %d |\n", name, R.rows ? R.evals[R.rows - 1] : 0, t / 3600, paused);
    }
    return 0;
}

static const char report_help[] =
    "usage: amorph report TABLE [--root DIR] RUN...\n"
    "Prints a table of docs/results.md from run folders' log.csv (results/report.sh assembles them):\n"
    "  last RUN        'EVALUATIONS BEST': the run's last logged generation\n"
    "  fig6 RUN...     Figure 6: per representation (runs named dct-<k>, cppn-<k>, gmx-<k>) the mean\n"
    "                  +- standard error of the best fitness so far every 500 evaluations, over the\n"
    "                  runs that reached it; then each run's best so far every 1,000\n"
    "  compute RUN...  a row per run: evaluations, hours (the sum of wall_s; a generation over 5 times\n"
    "                  the run's median counts as the median) and those paused generations\n"
    "  --root DIR      compute: runs named relative to DIR\n";

int cmd_report(tool_ctx* c, int argc, char** argv)
{
    (void)c;
    if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
        fputs(report_help, argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    const char* table = argv[1];
    if (table[0] == '-') return tool_unknown_option("report", table);
    const char* root = NULL;
    int first = 2;
    if (first + 1 < argc && !strcmp(argv[first], "--root")) root = argv[first + 1], first += 2;
    const int n = argc - first;
    for (int i = first; i < argc; i++)
        if (argv[i][0] == '-') return tool_unknown_option("report", argv[i]);
    if (!strcmp(table, "last")) {
        if (n != 1) return tool_usage_error("report: last takes one run folder");
        return report_last(argv[first]);
    }
    if (n < 1) return tool_usage_error("report: %s needs run folders (amorph report --help)", table);
    if (!strcmp(table, "fig6")) return report_fig6(n, argv + first);
    if (!strcmp(table, "compute")) return report_compute(root, n, argv + first);
    char q[AM_QUOTE_BUF];
    return tool_usage_error("report: unknown table '%s' (last, fig6, compute)", am_quote(q, sizeof q, table, -1));
}

#else
/* the board profile: the report's tables belong to the desktop */
int cmd_report(tool_ctx* c, int argc, char** argv)
{
    (void)c, (void)argc, (void)argv;
    return tool_not_in_build("report", "the report's tables");
}
#endif
