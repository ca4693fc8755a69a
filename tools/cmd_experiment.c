/* amorph experiment: the seed's experiments as groups of runs, their table (results.csv), summary
 * and ranking. */
#include "evolve_cmd.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- experiments ---- */

typedef struct variant {
    const char* name;
    const char* settings;     /* "key=value key=value" */
} variant;

typedef struct experiment {
    const char* name;
    const char* about;
    variant v[6];
} experiment;

static const experiment experiments[] = {
    {"representations", "DCT, CPPN and GMX on the two-material task (the seed's Figure 6)",
     {{"dct", "representation=dct"}, {"cppn", "representation=cppn"}, {"gmx", "representation=gmx"}, {NULL, NULL}}},
    {"three-materials", "two materials against three (a second actuator 90 degrees out of phase)",
     {{"two", "materials=2"}, {"three", "materials=3"}, {NULL, NULL}}},
    {"dynamic", "dynamic response: actuation period and internal damping",
     {{"base", "period_steps=500 damping_internal=1"},
      {"fast", "period_steps=250 damping_internal=1"},
      {"lowdamp", "period_steps=500 damping_internal=0.1"},
      {"fast_lowdamp", "period_steps=250 damping_internal=0.1"},
      {NULL, NULL}}},
    {"friction", "floor friction kinetic / static: 0.3 / 1.0 (seed), 0.1 / 5.0 and 0.4 / 0.5",
     {{"k0.3_s1.0", "mu_kinetic=0.3 mu_static=1.0"},
      {"k0.1_s5.0", "mu_kinetic=0.1 mu_static=5.0"},
      {"k0.4_s0.5", "mu_kinetic=0.4 mu_static=0.5"},
      {NULL, NULL}}},
};
#define EXPERIMENTS ((int)(sizeof experiments / sizeof experiments[0]))

static const char experiment_help[] =
    "usage: amorph experiment NAME [--evals N] [--runs R] [--out DIR] [--KEY VALUE]... [--quiet]\n"
    "Runs one of the seed's experiments: every variant R times (seeds seed, seed+1, ...), each a\n"
    "run folder DIR/<variant>-<k>, then writes DIR/results.csv (mean and standard error of the best\n"
    "fitness against evaluations, per variant), summary.txt and summary.json (the last row and the\n"
    "ranking), DIR/fitness.svg (the plot; not with --no-pictures, which the runs take too) beside\n"
    "DIR/experiment.txt (what was run), and prints the table. Running the same command again with\n"
    "the same --out DIR resumes unfinished runs and skips finished ones (without --out, a new\n"
    "runs/NAME-NNN). Other flags set configuration keys of every run (amorph evolve --help-config).\n"
    "  --evals N     evaluations per run: an alias of --evaluations N (the configuration's, 200)\n"
    "  --runs R      runs per variant (3)\n"
    "  --out DIR     experiment folder (default runs/NAME-NNN)\n"
    "  --json        the summary as one JSON line instead of the table (summary.json holds it too)\n"
    "experiments:\n";

/* applies "key=value ..." to d */
static int apply_settings(am_evo_def* d, const char* settings)
{
    char buf[256], err[AM_ERR_MAX];
    snprintf(buf, sizeof buf, "%s", settings);
    for (char* tok = strtok(buf, " "); tok; tok = strtok(NULL, " ")) {
        char* eq = strchr(tok, '=');
        if (!eq) return 1;
        *eq = 0;
        if (am_evo_set(d, tok, eq + 1, err, sizeof err) != AM_OK) return tool_usage_error("experiment: %s", err);
    }
    return 0;
}

/* the rows read_log keeps: evaluations (when evals is not NULL) and best of the first cap rows */
typedef struct log_rows {
    am_evo_log_reader rd;
    long* evals;
    double* best;
    int cap, n;
} log_rows;

static am_status log_rows_line(void* ctx, int lineno, char* line, long n, char* err, int errsz)
{
    log_rows* lr = (log_rows*)ctx;
    am_evo_stats row;
    int is_row = 0;
    (void)lineno;
    am_status st = am_evo_log_read_line(&lr->rd, line, n, &row, &is_row, err, errsz);
    if (st == AM_OK && is_row && lr->n < lr->cap) {
        if (lr->evals) lr->evals[lr->n] = row.evaluations;
        lr->best[lr->n++] = row.best;
    }
    return st;
}

/* reads the best-fitness column of dir/log.csv (the library's reader, am_evo_log_read_line):
 * evals[i] (when evals is not NULL), best[i] for up to cap rows after the header; the rows read,
 * or -1 after a one-line message (a file that cannot be read, a damaged log) */
static TOOL_NOINLINE int read_log(const char* dir, long* evals, double* best, int cap)
{
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    path_join(path, sizeof path, dir, AM_RUN_LOG);
    log_rows lr;
    memset(&lr, 0, sizeof lr);
    lr.evals = evals;
    lr.best = best;
    lr.cap = cap;
    am_evo_log_read_begin(&lr.rd, path);
    tool_src src;
    am_status st = tool_src_open(&src, path, TOOL_FILE_MAX, 1, err, sizeof err);
    if (st == AM_OK) {
        st = tool_src_each(&src, log_rows_line, &lr, err, sizeof err);
        if (st == AM_OK) st = am_evo_log_read_end(&lr.rd, err, sizeof err);
        tool_src_close(&src);
    }
    if (st != AM_OK) {
        tool_usage_error("%s", err);
        return -1;
    }
    return lr.n;
}

/* the table: evaluations of each row (from the last run read), one run's best fitness, and per
 * row the sum over the runs of a variant, then the sum of squared deviations from the mean */
static long g_exp_evals[EXP_ROWS];
static double g_exp_tmp[EXP_ROWS], g_exp_sum[EXP_ROWS], g_exp_dev[EXP_ROWS];

/* dir/experiment.txt */
static TOOL_NOINLINE int write_about(const experiment* x, long runs, long evaluations, const char* dir)
{
    char about[512];
    int n = snprintf(about, sizeof about, "experiment = %s\nabout = %s\nruns = %ld\nevaluations = %ld\n", x->name, x->about, runs,
                     evaluations);
    return write_text(dir, AM_EXP_ABOUT, about, n);
}

/* 1 when the run folder holds a checkpoint */
static TOOL_NOINLINE int run_has_checkpoint(const char* rdir)
{
    char ck[TOOL_PATH_MAX];
    path_join(ck, sizeof ck, rdir, AM_RUN_CHECKPOINT);
    return am_port_exists(ck);
}

/* run k of variant v in dir/<variant>-<k> (its name into rdir, its progress label into label)
 * opened into e: started, or resumed with this experiment's evaluations and threads (a finished
 * run only writes its summary again); 0, 1 or 2 */
static TOOL_NOINLINE int experiment_open(am_evo* e, const am_evo_def* base, const variant* v, long k, const char* dir, char* rdir,
                                         char* label)
{
    char err[AM_ERR_MAX];
    am_evo_def d = *base;
    if (apply_settings(&d, v->settings)) return 2;
    d.seed = base->seed + (uint64_t)(k - 1);
    if (am_evo_check_run(&d, err, sizeof err) != AM_OK) return tool_usage_error("experiment %s: %s", v->name, err);
    if (snprintf(rdir, EXP_RUN_DIR_MAX, "%s/%s-%ld", dir, v->name, k) >= EXP_RUN_DIR_MAX)
        return tool_usage_error("experiment: folder name too long");
    snprintf(label, 96, "%s-%ld", v->name, k);
    if (!run_has_checkpoint(rdir)) return open_start(e, &d, rdir);
    static const evo_opts none;
    char evs[32], ths[32];
    snprintf(evs, sizeof evs, "%ld", d.evaluations);
    snprintf(ths, sizeof ths, "%d", d.threads);
    const char* const extra[] = {"evaluations", evs, "threads", ths, NULL};
    return open_resume(e, rdir, &none, extra);
}

/* the runs of an experiment evolve in waves of up to EXP_WAVE runs in lockstep: each generation,
 * the offspring of every run of the wave go to one parallel map, so the workers (threads, or MPI
 * ranks) have runs x population evaluations to share rather than one population. Run 0 of a wave
 * is the tool_ctx's; the others are these. */
#if EXP_WAVE > 1
static am_evo g_exp_evo[EXP_WAVE - 1];
#endif

/* the runs [from, to) of the experiment's list (variant-major) as one wave; 0, 1, 2 or 130 */
static TOOL_NOINLINE int experiment_wave(tool_ctx* c, const am_evo_def* base, const experiment* x, long runs, long from, long to,
                                         const char* dir, int quiet)
{
    run_slot s[EXP_WAVE];
    char rdir[EXP_WAVE][EXP_RUN_DIR_MAX], label[EXP_WAVE][96];
    int n = 0, rc = 0;
    memset(s, 0, sizeof s);
    for (long r = from; r < to && rc == 0; r++, n++) {
#if EXP_WAVE > 1
        s[n].e = n == 0 ? &c->evo : &g_exp_evo[n - 1];
#else
        s[n].e = &c->evo;
#endif
        rc = experiment_open(s[n].e, base, &x->v[r / runs], r % runs + 1, dir, rdir[n], label[n]);
        s[n].dir = rdir[n];
        s[n].label = label[n];
    }
    if (rc == 0) rc = run_wave(c, s, n, quiet);
    am_port_unlock();
    return rc;
}

static int experiment_results(const experiment* x, int nv, long runs, const char* dir, int pictures, int json_out);

int cmd_experiment(tool_ctx* c, int argc, char** argv)
{
    evo_opts o;
    memset(&o, 0, sizeof o);
    o.pictures = 1;
    const char* name = NULL;
    long runs = 3;
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        const char* v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(experiment_help, stdout);
            for (int k = 0; k < EXPERIMENTS; k++) printf("  %-16s %s\n", experiments[k].name, experiments[k].about);
            return 0;
        } else if (!strcmp(a, "--runs")) {
            if (!tool_parse_long(v, 1, EXP_MAX_RUNS, &runs))
                return tool_usage_error("experiment: --runs needs a whole number in [1, %d]", EXP_MAX_RUNS);
            i++;
        } else if (a[0] != '-' && !name) {
            name = a;
        } else {
            int r = parse_common(argc, argv, &i, &o, "experiment");
            if (r == 2) return 2;
            if (r == 0) return tool_unknown_option("experiment", a, experiment_help);
        }
    }
    if (o.resume) return tool_usage_error("experiment: run the same command with the same --out again to resume");
    if (o.print_config) return tool_usage_error("experiment: --print-config applies to amorph evolve");
    if (!name) return tool_usage_error("experiment: which one? (amorph experiment --help lists them)");
    const experiment* x = NULL;
    for (int k = 0; k < EXPERIMENTS; k++)
        if (!strcmp(experiments[k].name, name)) x = &experiments[k];
    if (!x) {
        char q[AM_QUOTE_BUF];
        return tool_usage_error("experiment: unknown experiment '%s' (representations, three-materials, dynamic, friction)",
                                am_quote(q, sizeof q, name, -1));
    }
    am_evo_def base;
    if (build_def(&o, NULL, NULL, 0, &base, "experiment")) return 2;
    if (test_interrupt_setup()) return 2;
    char dir[EXP_DIR_MAX], err[AM_ERR_MAX];
    if (o.out && strlen(o.out) >= sizeof dir) return tool_usage_error("experiment: folder name too long");
    if (o.out) snprintf(dir, sizeof dir, "%s", o.out);
    else {
        if (am_port_make_dir("runs", err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
        for (int k = 1;; k++) {
            snprintf(dir, sizeof dir, "runs/%s-%03d", name, k);
            if (!am_port_exists(dir)) break;
        }
    }
    if (am_port_make_dir(dir, err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
    if (write_about(x, runs, base.evaluations, dir)) return 1;
    am_port_catch_interrupt();
    int nv = 0;
    while (nv < 6 && x->v[nv].name) nv++;
    const long all = (long)nv * runs;
    for (long from = 0; from < all; from += EXP_WAVE) {
        int rc = experiment_wave(c, &base, x, runs, from, from + EXP_WAVE < all ? from + EXP_WAVE : all, dir, o.quiet);
        if (rc == 130) {
            fprintf(stderr, "amorph: resume the experiment with the same command and --out %s\n", dir);
            return rc;
        }
        if (rc) return rc;
    }
    return experiment_results(x, nv, runs, dir, o.pictures, o.json);
}

/* an experiment's summary: per variant the mean and standard error of the runs' best fitness at
 * the last evaluation count every run holds, and the variants ranked by that mean */
typedef struct exp_summary {
    const char* name;
    const char* dir;
    long runs, evaluations;
    int nv;
    const char* names[6];
    const char* ranked[6];
    double mean[6], se[6];
} exp_summary;

static void put_experiment(tool_rec* q, const void* ctx)
{
    const exp_summary* x = (const exp_summary*)ctx;
    tool_rec_str(q, "experiment", x->name);
    tool_rec_str(q, "folder", x->dir);
    tool_rec_int(q, "runs", x->runs);
    tool_rec_int(q, "evaluations", x->evaluations);
    tool_rec_strs(q, "variants", x->names, x->nv);
    tool_rec_nums(q, "mean_best", x->mean, x->nv);
    tool_rec_nums(q, "stderr_best", x->se, x->nv);
    tool_rec_strs(q, "ranking", x->ranked, x->nv);
}

/* the experiment's table: results.csv, and the printed summary; 0, 1 or 2 */
static TOOL_NOINLINE int experiment_results(const experiment* x, int nv, long runs, const char* dir, int pictures, int json_out)
{
    /* results: mean and standard error of the runs' best fitness at each logged evaluation count.
     * First the rows every run holds; then variant by variant, the logs read again for the sums
     * (in the order of the runs, the sums of one table held whole) */
    int rows = EXP_ROWS;
    for (int v = 0; v < nv; v++)
        for (long k = 1; k <= runs; k++) {
            char rdir[EXP_RUN_DIR_MAX];
            if (snprintf(rdir, sizeof rdir, "%s/%s-%ld", dir, x->v[v].name, k) >= (int)sizeof rdir)
                return tool_usage_error("experiment: folder name too long");
            int n = read_log(rdir, g_exp_evals, g_exp_tmp, EXP_ROWS);
            if (n < 0) return 2;
            if (n == 0) return tool_usage_error("%s/" AM_RUN_LOG ": no rows", rdir);
            if (n < rows) rows = n;
        }
    double mean_at[6][8], se_at[6][8];
    int marks[8], nm = 0;
    for (int q = 1; q <= 5; q++) {
        int r = (int)((long)rows * q / 5) - 1;
        if (r < 0) r = 0;
        if (nm == 0 || marks[nm - 1] != r) marks[nm++] = r;
    }
    {
        char path[TOOL_PATH_MAX];
        path_join(path, sizeof path, dir, AM_EXP_RESULTS);
        tool_out out;
        if (tool_out_open(&out, path)) return 1;
        char row[AM_EXP_RESULTS_ROW_MAX];
        am_text_put(&out.text, "%s\n", am_exp_results_header());
        for (int v = 0; v < nv; v++) {
            for (int pass = 0; pass < 2; pass++) {
                for (int r = 0; r < rows; r++) (pass ? g_exp_dev : g_exp_sum)[r] = 0;
                for (long k = 1; k <= runs; k++) {
                    char rdir[EXP_RUN_DIR_MAX];
                    snprintf(rdir, sizeof rdir, "%s/%s-%ld", dir, x->v[v].name, k);
                    int got = read_log(rdir, NULL, g_exp_tmp, rows);
                    if (got < rows) {
                        tool_out_close(&out, 0);
                        return got < 0 ? 2 : tool_usage_error("%s/" AM_RUN_LOG ": changed while the table was made", rdir);
                    }
                    for (int r = 0; r < rows; r++) {
                        if (!pass) g_exp_sum[r] += g_exp_tmp[r];
                        else g_exp_dev[r] += (g_exp_tmp[r] - g_exp_sum[r]) * (g_exp_tmp[r] - g_exp_sum[r]);
                    }
                }
                if (!pass)
                    for (int r = 0; r < rows; r++) g_exp_sum[r] = g_exp_sum[r] / (double)runs; /* the mean */
            }
            for (int r = 0; r < rows; r++) {
                double m = g_exp_sum[r];
                double se = runs > 1 ? sqrt(g_exp_dev[r] / (double)(runs - 1)) / sqrt((double)runs) : 0.0;
                am_exp_results_row(x->v[v].name, g_exp_evals[r], m, se, runs, row, (int)sizeof row);
                am_text_put(&out.text, "%s\n", row);
                for (int q = 0; q < nm; q++)
                    if (marks[q] == r) {
                        mean_at[v][q] = m;
                        se_at[v][q] = se;
                    }
            }
        }
        if (tool_out_close(&out, 1)) return 1;
    }
    if (TOOL_PICTURES && pictures) {
        char svg[2048];
        char* dirs[1] = {(char*)(uintptr_t)dir};
        if (snprintf(svg, sizeof svg, "%s/" AM_RUN_FITNESS_SVG, dir) < (int)sizeof svg && tool_write_plot(1, dirs, svg)) return 1;
    }
    /* the summary: the final row per variant, and the variants ranked by it */
    exp_summary sum;
    memset(&sum, 0, sizeof sum);
    sum.name = x->name;
    sum.dir = dir;
    sum.runs = runs;
    sum.evaluations = g_exp_evals[rows - 1];
    sum.nv = nv;
    int order[6];
    for (int v = 0; v < nv; v++) {
        sum.names[v] = x->v[v].name;
        sum.mean[v] = mean_at[v][nm - 1];
        sum.se[v] = se_at[v][nm - 1];
        int j = v; /* insertion: the highest mean first, ties in the experiment's order */
        while (j > 0 && sum.mean[order[j - 1]] < sum.mean[v]) {
            order[j] = order[j - 1];
            j--;
        }
        order[j] = v;
    }
    for (int v = 0; v < nv; v++) sum.ranked[v] = sum.names[order[v]];
    if (write_summaries(dir, "amorph experiment summary: the best fitness (m) at the last evaluation every run holds", put_experiment, &sum))
        return 1;
    tool_out o;
    if (tool_out_open(&o, NULL)) return 1;
    if (json_out) {
        tool_rec q;
        tool_rec_begin(&q, &o.text, 1);
        put_experiment(&q, &sum);
        tool_rec_end(&q);
        return tool_out_close(&o, 1);
    }
    am_text* t = &o.text;
    am_text_put(t, "experiment %s: best fitness (m), mean +- standard error of %ld runs\n%-12s", x->name, runs, "evaluations");
    for (int v = 0; v < nv; v++) am_text_put(t, " %22s", x->v[v].name);
    am_text_put(t, "\n");
    for (int q = 0; q < nm; q++) {
        am_text_put(t, "%-12ld", g_exp_evals[marks[q]]);
        for (int v = 0; v < nv; v++) am_text_put(t, "   %9.4f +- %7.4f", mean_at[v][q], se_at[v][q]);
        am_text_put(t, "\n");
    }
    am_text_put(t, "ranking =");
    for (int v = 0; v < nv; v++) am_text_put(t, " %s", sum.ranked[v]);
    am_text_put(t, "\nfolder = %s\nresults = %s/" AM_EXP_RESULTS "\nsummary = %s/" AM_RUN_SUMMARY_JSON "\n", dir, dir, dir);
    return tool_out_close(&o, 1);
}

