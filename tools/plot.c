/* The plots of amorph plot, evolve and experiment: best fitness against evaluations as SVG, one
 * line per run folder; for an experiment folder, the mean of each variant's runs with a band of one
 * standard error (the seed's Figure 6); or one robot's travel against time. docs/pictures.md. */
#include "picture.h"
#if TOOL_PICTURES

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PLOT_MAX_SERIES 64
#define PLOT_MAX_POINTS (1L << 18)  /* rows of all runs together */
#define PLOT_PATH_MAX 1024
#define PLOT_SVG_MAX (PLOT_MAX_POINTS * 48L + (1L << 20))

typedef struct plot_run {
    char dir[PLOT_PATH_MAX];
    char name[96];       /* the folder's last component */
    long first, n;       /* rows in plot_x / plot_y */
    int series;          /* the series (line) it belongs to */
} plot_run;

typedef struct plot_series {
    char label[96];
    int runs[PLOT_MAX_RUNS]; /* indices into plot_runs */
    int nruns;
    int experiment;          /* 1: a variant of an experiment folder (mean and band) */
    long first, n;           /* mean points in plot_mx / plot_my / plot_se */
} plot_series;

static plot_run plot_runs[PLOT_MAX_RUNS];
static long plot_min_evals; /* --min-evals: a folder of runs leaves out the runs short of it */
static long plot_max_evals; /* --max-evals: rows beyond it are not drawn (0: all) */
static plot_series plot_ser[PLOT_MAX_SERIES];
static int plot_nruns, plot_nser;
static double plot_x[PLOT_MAX_POINTS], plot_y[PLOT_MAX_POINTS];
static long plot_used;
static double plot_mx[PLOT_MAX_POINTS], plot_my[PLOT_MAX_POINTS], plot_se[PLOT_MAX_POINTS];
static long plot_mused;
static char plot_svg[PLOT_SVG_MAX];
/* --travel: one robot's recorded motion (travel against time) instead of run folders */
static int plot_travel;
static double plot_period;   /* s: the actuation period, where the cycles' marks go */

/* ten colours; a series past the tenth repeats them, dashed (then dotted), so that no two of the
 * first 30 look alike */
#define PLOT_COLOURS 10
static const char* const plot_colours[PLOT_COLOURS] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                                       "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"};
static const char* const plot_dashes[3] = {"", " stroke-dasharray=\"7 4\"", " stroke-dasharray=\"2 3\""};

/* a path's last component: it starts at the returned offset and ends at *end (trailing '/' left
 * out) */
static size_t last_component(const char* path, size_t* end)
{
    size_t len = strlen(path);
    while (len > 1 && path[len - 1] == '/') len--;
    size_t s = len;
    while (s > 0 && path[s - 1] != '/') s--;
    *end = len;
    return s;
}

static const char* base_name(const char* path, char* buf, int n)
{
    size_t end, s = last_component(path, &end);
    snprintf(buf, (size_t)n, "%.*s", (int)(end - s), path + s);
    return buf;
}

/* one run being read from its log.csv: the library's reader, and the best fitness so far */
typedef struct plot_reading {
    plot_run* r;
    double best;
} plot_reading;

/* one line of a log.csv: a row becomes a point (evaluations, best so far) of the run */
static am_status plot_log_row(void* ctx, const char* fname, int lineno, const am_evo_stats* rowp, char* err, int errsz)
{
    plot_reading* pr = (plot_reading*)ctx;
    plot_run* r = pr->r;
    const am_evo_stats row = *rowp;
    if (plot_max_evals > 0 && row.evaluations > plot_max_evals) return AM_OK; /* read on: the rest is checked */
    double e = (double)row.evaluations;
    if (r->n > 0 && e < plot_x[plot_used - 1])
        return am_fail_at(err, errsz, AM_ERR_PARSE, fname, lineno, "evaluations go backwards (%ld after %.17g)", row.evaluations,
                          plot_x[plot_used - 1]);
    if (plot_used >= PLOT_MAX_POINTS) return am_fail(err, errsz, AM_ERR_CAPACITY, "more than %ld rows in all", PLOT_MAX_POINTS);
    /* the best so far: a generation's best may fall back under crowding */
    if (row.best > pr->best) pr->best = row.best;
    plot_x[plot_used] = e;
    plot_y[plot_used] = pr->best;
    plot_used++;
    r->n++;
    return AM_OK;
}

/* reads dir/log.csv (the library's reader, am_evo_log_read_line) into a new run of series
 * `series`; 0 or 2 after a message */
static int load_run(const char* dir, int series)
{
    char path[PLOT_PATH_MAX + 16], err[AM_ERR_MAX];
    if (plot_nruns >= PLOT_MAX_RUNS) return tool_usage_error("plot: more than %d runs", PLOT_MAX_RUNS);
    if (strlen(dir) >= PLOT_PATH_MAX) return tool_usage_error("plot: folder name too long: %.60s...", dir);
    snprintf(path, sizeof path, "%s/" AM_RUN_LOG, dir);
    plot_run* r = &plot_runs[plot_nruns];
    snprintf(r->dir, sizeof r->dir, "%s", dir);
    base_name(dir, r->name, sizeof r->name);
    r->first = plot_used;
    r->n = 0;
    r->series = series;
    plot_reading pr;
    pr.r = r;
    pr.best = -HUGE_VAL;
    am_status st = tool_log_each(path, plot_log_row, &pr, err, sizeof err);
    if (st != AM_OK) {
        plot_used = r->first; /* the points of a run that failed are not kept */
        return tool_usage_error("plot: %s", err);
    }
    if (r->n == 0 && plot_max_evals > 0) return tool_usage_error("%s: no generation logged within %ld evaluations (--max-evals)", path, plot_max_evals);
    if (r->n == 0) return tool_usage_error("%s: no generations logged yet", path);
    plot_nruns++;
    return 0;
}

static int new_series(const char* label)
{
    if (plot_nser >= PLOT_MAX_SERIES) return -1;
    plot_series* s = &plot_ser[plot_nser];
    memset(s, 0, sizeof *s);
    snprintf(s->label, sizeof s->label, "%s", label);
    return plot_nser++;
}

static int cmp_names(const void* a, const void* b) { return strcmp((const char*)a, (const char*)b); }

/* an experiment folder: its run subfolders, grouped by variant (the name before the last '-');
 * only: the one variant to keep (named `asked` on the command line), or NULL for all */
static int load_experiment(const char* dir, const char* only, const char* asked)
{
    static char names[PLOT_MAX_RUNS][96];
    static char listing[PLOT_MAX_RUNS * 128];
    int n = 0, count = 0;
    char err[AM_ERR_MAX];
    if (am_port_list_dir(dir, listing, (long)sizeof listing, &count, err, sizeof err) != AM_OK) return tool_usage_error("plot: %s", err);
    for (const char* name = listing; count-- > 0; name += strlen(name) + 1) {
        char sub[PLOT_PATH_MAX + 128], csv[PLOT_PATH_MAX + 160];
        if (name[0] == '.' || strlen(name) >= sizeof names[0]) continue;
        snprintf(sub, sizeof sub, "%s/%.95s", dir, name); /* a name that long was skipped above */
        snprintf(csv, sizeof csv, "%s/" AM_RUN_LOG, sub);
        if (!am_port_exists(csv) || !strrchr(name, '-')) continue;
        if (only && (strlen(only) != (size_t)(strrchr(name, '-') - name) || strncmp(name, only, strlen(only)))) continue;
        if (n >= PLOT_MAX_RUNS) return tool_usage_error("plot: %s: more than %d runs", dir, PLOT_MAX_RUNS);
        memcpy(names[n++], name, strlen(name) + 1); /* shorter than names[0]: checked above */
    }
    if (n == 0 && only) return tool_usage_error("plot: %s: no such folder, nor runs %s-<k> in %s", asked, only, dir);
    if (n == 0) return tool_usage_error("plot: %s: neither a run folder (log.csv) nor a folder of run folders (<variant>-<k>/log.csv)", dir);
    qsort(names, (size_t)n, sizeof names[0], cmp_names);
    int s = -1, kept = 0;
    for (int i = 0; i < n; i++) {
        char label[96], sub[PLOT_PATH_MAX + 128];
        snprintf(label, sizeof label, "%.*s", (int)(strrchr(names[i], '-') - names[i]), names[i]);
        /* a variant's line begins with its first run kept */
        int fresh = s < 0 || strcmp(plot_ser[s].label, label);
        const int s_run = fresh ? plot_nser : s;
        snprintf(sub, sizeof sub, "%s/%.95s", dir, names[i]);
        int rc = load_run(sub, s_run);
        if (rc) return rc;
        const plot_run* r = &plot_runs[plot_nruns - 1];
        if (plot_x[r->first + r->n - 1] < (double)plot_min_evals) { /* short of --min-evals: left out */
            plot_used = r->first;
            plot_nruns--;
            continue;
        }
        if (fresh) {
            s = new_series(label);
            if (s < 0) return tool_usage_error("plot: more than %d lines", PLOT_MAX_SERIES);
            plot_ser[s].experiment = 1;
        }
        plot_ser[s].runs[plot_ser[s].nruns++] = plot_nruns - 1;
        kept++;
    }
    if (kept == 0) return tool_usage_error("plot: %s: no run has logged %ld evaluations (--min-evals)", dir, plot_min_evals);
    return 0;
}

/* The mean of each variant's runs, on the x axis of a single run. A run's best fitness so far is a
 * step function of evaluations: it holds from the evaluations of one logged generation up to the
 * next. The mean is one too: at every x where some run of the variant steps, from the largest first
 * x (where every run has a value) to the smallest last x (while every run has logged), the mean of
 * the runs' values there and its standard error. Runs that log at the same evaluations (one
 * population size) give the row-by-row mean. */
static void series_means(void)
{
    static long at[PLOT_MAX_RUNS]; /* per run of the series: its row holding at x */
    for (int s = 0; s < plot_nser; s++) {
        plot_series* S = &plot_ser[s];
        const int m = S->nruns;
        S->first = plot_mused;
        S->n = 0;
        if (m == 0) continue;
        double x = -HUGE_VAL, hi = HUGE_VAL;
        for (int k = 0; k < m; k++) {
            const plot_run* R = &plot_runs[S->runs[k]];
            x = fmax(x, plot_x[R->first]);
            hi = fmin(hi, plot_x[R->first + R->n - 1]);
            at[k] = 0;
        }
        while (x <= hi && plot_mused < PLOT_MAX_POINTS) {
            double sy = 0, s2 = 0, next = HUGE_VAL;
            for (int k = 0; k < m; k++) {
                const plot_run* R = &plot_runs[S->runs[k]];
                while (at[k] + 1 < R->n && plot_x[R->first + at[k] + 1] <= x) at[k]++;
                sy += plot_y[R->first + at[k]];
                if (at[k] + 1 < R->n) next = fmin(next, plot_x[R->first + at[k] + 1]);
            }
            const double my = sy / m;
            for (int k = 0; k < m; k++) {
                double d = plot_y[plot_runs[S->runs[k]].first + at[k]] - my;
                s2 += d * d;
            }
            plot_mx[plot_mused] = x;
            plot_my[plot_mused] = my;
            plot_se[plot_mused] = m > 1 ? sqrt(s2 / (m - 1)) / sqrt((double)m) : 0;
            plot_mused++;
            S->n++;
            x = next; /* HUGE_VAL past the last row: the loop ends */
        }
    }
}

/* the bounded text buffer of amorph/base.h */
#define put am_text_put

/* text with &, <, > and " escaped */
static void put_text(am_text* o, const char* s)
{
    for (; *s; s++) {
        if (*s == '&') put(o, "&amp;");
        else if (*s == '<') put(o, "&lt;");
        else if (*s == '>') put(o, "&gt;");
        else if (*s == '"') put(o, "&quot;");
        else if ((unsigned char)*s < 0x20) put(o, " ");
        else put(o, "%c", *s);
    }
}

/* ticks: a round step giving about `want` intervals over [lo, hi] */
static double tick_step(double lo, double hi, int want)
{
    double span = hi - lo, raw = span / want, p = pow(10.0, floor(log10(raw))), f = raw / p;
    return (f <= 1 ? 1 : f <= 2 ? 2 : f <= 2.5 ? 2.5 : f <= 5 ? 5 : 10) * p;
}

/* where the plot's data lands on the picture */
typedef struct plot_frame {
    double x0, x1, y0, y1; /* the axes' ranges (y in the shown unit) */
    double unit;           /* shown unit per metre (1000 for mm, 1 for m) */
    int ml, mt, pw, ph;    /* the plot area: left, top, width, height (px) */
} plot_frame;

static double frame_x(const plot_frame* f, double x) { return f->ml + (x - f->x0) / (f->x1 - f->x0) * f->pw; }
static double frame_y(const plot_frame* f, double y) { return f->mt + f->ph - (y * f->unit - f->y0) / (f->y1 - f->y0) * f->ph; }

/* a best-so-far curve as steps: each value holds until the next point's x, then the curve rises
 * (or falls) there: "Mx0,y0 Hx1 Vy1 Hx2 Vy2 ...". The y values are y[i] + sign * e[i] (e may be
 * NULL); reverse 1 walks from the last point back to the first ("Vy(n-2) Hx(n-2) ..."), for the
 * lower edge of a band, continuing a path with its first command a line to the last point */
static void put_steps(am_text* o, const plot_frame* f, const double* x, const double* y, const double* e, double sign, long n,
                      int reverse)
{
#define VAL(i) (y[i] + (e ? sign * e[i] : 0))
    if (n <= 0) return;
    if (!reverse) {
        put(o, "M%.2f,%.2f", frame_x(f, x[0]), frame_y(f, VAL(0)));
        for (long i = 1; i < n; i++) put(o, " H%.2f V%.2f", frame_x(f, x[i]), frame_y(f, VAL(i)));
    } else {
        put(o, " L%.2f,%.2f", frame_x(f, x[n - 1]), frame_y(f, VAL(n - 1)));
        for (long i = n - 2; i >= 0; i--) put(o, " V%.2f H%.2f", frame_y(f, VAL(i)), frame_x(f, x[i]));
    }
#undef VAL
}

static void fmt_num(char* buf, int n, double v)
{
    if (fabs(v) < 1e-12) v = 0;
    snprintf(buf, (size_t)n, "%.6g", v);
}

static int plot_svg_write(const char* title, const char* path)
{
    /* data range; fitness shown in mm below 10 cm, else in m */
    double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
    for (long i = 0; i < plot_used; i++) {
        x0 = fmin(x0, plot_x[i]), x1 = fmax(x1, plot_x[i]);
        y0 = fmin(y0, plot_y[i]), y1 = fmax(y1, plot_y[i]);
    }
    for (long i = 0; i < plot_mused; i++) y0 = fmin(y0, plot_my[i] - plot_se[i]), y1 = fmax(y1, plot_my[i] + plot_se[i]);
    double unit = fmax(fabs(y0), fabs(y1)) < 0.1 ? 1000 : 1;
    const char* uname = unit == 1000 ? "mm" : "m";
    y0 *= unit, y1 *= unit;
    if (y0 > 0) y0 = 0; /* fitness from zero, as the seed's figure */
    if (x0 > 0) x0 = 0; /* and evaluations from zero, for runs and experiments alike */
    if (!(y1 > y0)) y1 = y0 + 1;
    if (!(x1 > x0)) x1 = x0 + 1;
    double xs = tick_step(x0, x1, 6), ys = tick_step(y0, y1, 6);
    const double xdata = x1, ydata = y1;
    x0 = floor(x0 / xs) * xs, x1 = ceil(x1 / xs) * xs;
    y0 = floor(y0 / ys) * ys, y1 = ceil(y1 / ys) * ys;
    /* room past the data: a curve reaching the last tick would lie on the frame (the highest best
     * on the top border, the last generation's step on the right one), so the axis goes one tick
     * further when the data come within 3 % of its end */
    if (x1 - xdata < 0.03 * (x1 - x0)) x1 += xs;
    if (y1 - ydata < 0.03 * (y1 - y0)) y1 += ys;
    /* the legend's column as wide as its longest entry needs (about 7.5 px a character at 13 px,
     * after the 46 px of the line sample), the plot itself always 592 px wide */
    size_t longest = 0;
    for (int s = 0; s < plot_nser; s++) {
        size_t n = strlen(plot_ser[s].label) + (plot_ser[s].experiment ? strlen(", 99 runs") : 0);
        longest = n > longest ? n : longest;
    }
    const int legend = 46 + (int)(7.5 * (double)longest) + 12, mr = legend > 190 ? legend : 190;
    const int ml = 78, mt = 46, mb = 58, W = 670 + mr, H = 520;
    const int pw = W - ml - mr, ph = H - mt - mb;
    const plot_frame fr = {x0, x1, y0, y1, unit, ml, mt, pw, ph};
#define PX(x) frame_x(&fr, (x))
#define PY(y) frame_y(&fr, (y))
    am_text o = {plot_svg, PLOT_SVG_MAX, 0, 0, NULL, NULL, 0};
    put(&o, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    put(&o, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\" "
            "font-family=\"sans-serif\" font-size=\"13\">\n", W, H, W, H);
    put(&o, "<rect width=\"%d\" height=\"%d\" fill=\"#ffffff\"/>\n", W, H);
    put(&o, "<text x=\"%d\" y=\"26\" font-size=\"16\" font-weight=\"bold\">", ml);
    put_text(&o, title);
    put(&o, "</text>\n");
    /* grid, ticks and tick labels */
    char num[48];
    put(&o, "<g stroke=\"#e4e4e4\" stroke-width=\"1\">\n");
    for (double x = x0; x <= x1 + xs * 1e-9; x += xs) put(&o, "<line x1=\"%.2f\" y1=\"%d\" x2=\"%.2f\" y2=\"%d\"/>\n", PX(x), mt, PX(x), mt + ph);
    for (double y = y0; y <= y1 + ys * 1e-9; y += ys)
        put(&o, "<line x1=\"%d\" y1=\"%.2f\" x2=\"%d\" y2=\"%.2f\"/>\n", ml, PY(y / unit), ml + pw, PY(y / unit));
    put(&o, "</g>\n<g class=\"ticks\" fill=\"#333333\">\n");
    for (double x = x0; x <= x1 + xs * 1e-9; x += xs) {
        fmt_num(num, sizeof num, x);
        put(&o, "<line x1=\"%.2f\" y1=\"%d\" x2=\"%.2f\" y2=\"%d\" stroke=\"#333333\"/>", PX(x), mt + ph, PX(x), mt + ph + 5);
        put(&o, "<text x=\"%.2f\" y=\"%d\" text-anchor=\"middle\">%s</text>\n", PX(x), mt + ph + 19, num);
    }
    for (double y = y0; y <= y1 + ys * 1e-9; y += ys) {
        fmt_num(num, sizeof num, y);
        put(&o, "<line x1=\"%d\" y1=\"%.2f\" x2=\"%d\" y2=\"%.2f\" stroke=\"#333333\"/>", ml - 5, PY(y / unit), ml, PY(y / unit));
        put(&o, "<text x=\"%d\" y=\"%.2f\" text-anchor=\"end\">%s</text>\n", ml - 8, PY(y / unit) + 4, num);
    }
    put(&o, "</g>\n<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"none\" stroke=\"#333333\"/>\n", ml, mt, pw, ph);
    /* one x axis for runs and experiments: evaluations done (log.csv's evaluations column) */
    put(&o, "<text class=\"xlabel\" x=\"%d\" y=\"%d\" text-anchor=\"middle\">%s</text>\n", ml + pw / 2, H - 14,
        plot_travel ? "time since the movement started (s)" : "evaluations");
    put(&o, "<text class=\"ylabel\" transform=\"translate(20 %d) rotate(-90)\" text-anchor=\"middle\">%s (%s)</text>\n",
        mt + ph / 2, plot_travel ? "horizontal travel of the centre of mass" : "best fitness so far", uname);
    /* a travel plot: a faint line at the end of every actuation cycle */
    if (plot_travel && plot_period > 0 && (x1 - x0) / plot_period <= 100)
        for (double x = plot_period; x <= x1 + 1e-12; x += plot_period)
            put(&o, "<line class=\"cycle\" x1=\"%.2f\" y1=\"%d\" x2=\"%.2f\" y2=\"%d\" stroke=\"#c8c8f0\" stroke-dasharray=\"3 3\"/>\n",
                PX(x), mt, PX(x), mt + ph);
    /* the curves, as steps: each run alone, or each variant's mean with its standard-error band */
    int ly = mt + 8, any_band = 0;
    for (int s = 0; s < plot_nser; s++) {
        const plot_series* S = &plot_ser[s];
        const char* col = plot_colours[s % PLOT_COLOURS];
        const char* dash = plot_dashes[s / PLOT_COLOURS % 3];
        int grouped = S->experiment;
        if (plot_travel) {
            const plot_run* R = &plot_runs[S->runs[0]];
            put(&o, "<path class=\"travel\" data-end=\"%.9g\" fill=\"none\" stroke=\"%s\"%s stroke-width=\"2\" d=\"",
                R->n ? plot_y[R->first + R->n - 1] : 0.0, col, dash);
            for (long i = 0; i < R->n; i++)
                put(&o, i ? " L%.2f,%.2f" : "M%.2f,%.2f", PX(plot_x[R->first + i]), PY(plot_y[R->first + i]));
            put(&o, "\"/>\n");
        } else if (grouped && S->n > 0) {
            const long k = S->first;
            put(&o, "<path class=\"band\" fill=\"%s\" fill-opacity=\"0.18\" stroke=\"none\" d=\"", col);
            put_steps(&o, &fr, plot_mx + k, plot_my + k, plot_se + k, 1, S->n, 0);
            put_steps(&o, &fr, plot_mx + k, plot_my + k, plot_se + k, -1, S->n, 1);
            put(&o, " Z\"/>\n");
            for (int r = 0; r < S->nruns; r++) {
                const plot_run* R = &plot_runs[S->runs[r]];
                put(&o, "<path class=\"run\" fill=\"none\" stroke=\"%s\"%s stroke-opacity=\"0.35\" stroke-width=\"1\" d=\"", col, dash);
                put_steps(&o, &fr, plot_x + R->first, plot_y + R->first, NULL, 0, R->n, 0);
                put(&o, "\"/>\n");
            }
            put(&o, "<path class=\"mean\" fill=\"none\" stroke=\"%s\"%s stroke-width=\"2.5\" d=\"", col, dash);
            put_steps(&o, &fr, plot_mx + k, plot_my + k, NULL, 0, S->n, 0);
            put(&o, "\"/>\n");
        } else {
            const plot_run* R = &plot_runs[S->runs[0]];
            put(&o, "<path class=\"run\" fill=\"none\" stroke=\"%s\"%s stroke-width=\"2\" d=\"", col, dash);
            put_steps(&o, &fr, plot_x + R->first, plot_y + R->first, NULL, 0, R->n, 0);
            put(&o, "\"/>\n");
        }
        /* legend entry */
        put(&o, "<g class=\"legend\"><line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"%s\"%s stroke-width=\"3\"/>", ml + pw + 16,
            ly, ml + pw + 40, ly, col, dash);
        put(&o, "<text x=\"%d\" y=\"%d\">", ml + pw + 46, ly + 4);
        put_text(&o, S->label);
        if (grouped) put(&o, ", %d run%s", S->nruns, S->nruns == 1 ? "" : "s");
        put(&o, "</text></g>\n");
        ly += 20;
        any_band |= grouped;
    }
    if (any_band)
        put(&o, "<text x=\"%d\" y=\"%d\" font-size=\"11\" fill=\"#555555\">thick: mean of the runs;</text>\n"
                "<text x=\"%d\" y=\"%d\" font-size=\"11\" fill=\"#555555\">band: &#177; one standard error</text>\n",
            ml + pw + 16, ly + 6, ml + pw + 16, ly + 20);
    put(&o, "</svg>\n");
#undef PX
#undef PY
    if (o.full) {
        fprintf(stderr, "amorph: %s: the plot does not fit in %ld bytes\n", path ? path : "plot", (long)PLOT_SVG_MAX);
        return 1;
    }
    return tool_write_output(path, plot_svg, o.len);
}

/* loads every folder: a run folder (log.csv) is one line, an experiment folder (or any folder of
 * run folders) one per variant */
static int plot_load(int ndirs, char** dirs)
{
    plot_nruns = plot_nser = 0;
    plot_used = plot_mused = 0;
    for (int i = 0; i < ndirs; i++) {
        char csv[PLOT_PATH_MAX + 16];
        if (strlen(dirs[i]) >= PLOT_PATH_MAX) return tool_usage_error("plot: folder name too long: %.60s...", dirs[i]);
        snprintf(csv, sizeof csv, "%s/" AM_RUN_LOG, dirs[i]);
        if (!am_port_exists(dirs[i])) {
            /* DIR/VARIANT: the runs VARIANT-<k> of the folder of runs DIR, as one line */
            char parent[PLOT_PATH_MAX], variant[96];
            size_t end, at = last_component(dirs[i], &end);
            if (at == 0) snprintf(parent, sizeof parent, ".");
            else snprintf(parent, sizeof parent, "%.*s", (int)(at > 1 ? at - 1 : 1), dirs[i]); /* no '/' but the root's */
            base_name(dirs[i], variant, sizeof variant);
            if (end - at >= sizeof variant || !variant[0] || !strcmp(variant, ".") || !strcmp(variant, "..") || !am_port_exists(parent))
                return tool_usage_error("plot: %s: no such folder", dirs[i]);
            int rc = load_experiment(parent, variant, dirs[i]);
            if (rc) return rc;
        } else if (am_port_exists(csv)) {
            char name[96];
            int s = new_series(base_name(dirs[i], name, sizeof name));
            if (s < 0) return tool_usage_error("plot: more than %d lines", PLOT_MAX_SERIES);
            int rc = load_run(dirs[i], s);
            if (rc) return rc;
            plot_ser[s].runs[plot_ser[s].nruns++] = plot_nruns - 1;
        } else {
            /* an experiment folder, or any folder of <variant>-<k> run folders (results/run.sh's) */
            int rc = load_experiment(dirs[i], 0, 0);
            if (rc) return rc;
        }
    }
    series_means();
    return 0;
}

/* --travel: the robot simulated with recording (as render and view), its centre of mass's
 * horizontal distance from the settled frame's against the time since then, one point a frame */
static int travel_load(tool_ctx* c, const tool_robot_args* ra, const char* label)
{
    am_robot rob;
    int rc = tool_load_subject(c, ra, &rob, "plot");
    if (rc) return rc;
    static tool_motion mo;
    rc = tool_record_motion(c, &rob, TOOL_REC_MAX_FRAMES, &mo, ra->name);
    if (rc) return rc;
    plot_nruns = plot_nser = 0;
    plot_used = plot_mused = 0;
    int s = new_series(label);
    plot_run* r = &plot_runs[0];
    memset(r, 0, sizeof *r);
    snprintf(r->name, sizeof r->name, "%s", label);
    r->series = s;
    double c0[3], ck[3];
    tool_motion_com(&mo, mo.settled_frame, c0);
    for (int f = mo.settled_frame; f < mo.frames; f++) {
        tool_motion_com(&mo, f, ck);
        plot_x[plot_used] = (double)(mo.step[f] - mo.step[mo.settled_frame]) * mo.dt;
        plot_y[plot_used] = sqrt((ck[0] - c0[0]) * (ck[0] - c0[0]) + (ck[1] - c0[1]) * (ck[1] - c0[1]));
        plot_used++;
        r->n++;
    }
    plot_nruns = 1;
    plot_ser[s].runs[plot_ser[s].nruns++] = 0;
    plot_period = (double)mo.res.period_steps * mo.dt;
    return 0;
}

int tool_write_plot(int ndirs, char** dirs, const char* path)
{
    plot_travel = 0;
    if (plot_load(ndirs, dirs)) return 1;
    return plot_svg_write("best fitness against evaluations", path) ? 1 : 0;
}

int tool_plot_runs(int ndirs, char** dirs, long min_evals, long max_evals, const char* title, const char* path)
{
    plot_travel = 0;
    plot_min_evals = min_evals;
    plot_max_evals = max_evals;
    int rc = plot_load(ndirs, dirs);
    if (rc) return rc;
    return plot_svg_write(title, path);
}

int tool_plot_travel(tool_ctx* c, const tool_robot_args* ra, const char* title, const char* path)
{
    char label[96];
    if (ra->is_scene) snprintf(label, sizeof label, "%s", ra->name);
    else base_name(ra->name, label, sizeof label);
    plot_travel = 1;
    int rc = travel_load(c, ra, label);
    if (rc) return rc;
    return plot_svg_write(title, path);
}

#else
typedef int tool_plot_engine_not_built; /* board profile: tools/picture.c has the stand-ins */
#endif
