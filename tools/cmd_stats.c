/* amorph stats: groups of run folders compared by tests (tools/stats.h): at every N evaluations,
 * each group's best fitness so far (n, mean, standard deviation, standard error), and for each
 * pair of groups Welch's t-test, the Mann-Whitney test (each p also after Holm's correction over
 * the pairs of its count), Cohen's d and Hedges' g and the runs needed for 80% power; or the same on the sustained score of each run's best robot
 * (gait30.json). Markdown tables or one JSON object. docs/results.md, Statistics. */
#include "stats_cmd.h"
#if !defined(AM_PROFILE_BOARD)

#include <math.h>
#include <stdio.h>
#include <string.h>

const char* const stats_gait_names[GAITS] = {"still", "flop", "scoot", "bounce", "roll"};
stats_set stats_S;

/* ---- reading the runs ---- */

/* the group named name, made when new; -1 past capacity */
static int group_of(const char* name, long len)
{
    for (int g = 0; g < stats_S.ngroups; g++)
        if ((long)strlen(stats_S.groups[g].name) == len && !strncmp(stats_S.groups[g].name, name, (size_t)len)) return g;
    if (stats_S.ngroups >= STATS_MAX_GROUPS) return -1;
    stats_group* G = &stats_S.groups[stats_S.ngroups];
    memset(G, 0, sizeof *G);
    memcpy(G->name, name, (size_t)len);
    G->name[len] = 0;
    return stats_S.ngroups++;
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
    if (stats_S.nruns >= STATS_MAX_RUNS) return tool_usage_error("stats: more than %d runs", STATS_MAX_RUNS);
    for (int r = 0; r < stats_S.nruns; r++)
        if (path_len(stats_S.runs[r].dir) == path_len(dir) && !strncmp(stats_S.runs[r].dir, dir, path_len(dir)))
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
    stats_run* R = &stats_S.runs[stats_S.nruns];
    memset(R, 0, sizeof *R);
    R->dir = dir;
    R->group = g;
    stats_S.groups[g].runs[stats_S.groups[g].n++] = stats_S.nruns++;
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
    for (long m = (R->counts + 1) * stats_S.every; m < row.evaluations; m += stats_S.every) {
        if (R->counts >= STATS_MAX_COUNTS)
            return am_fail_at(err, errsz, AM_ERR_CAPACITY, fname, lineno, "more than %d counts of %ld evaluations (a larger --every)",
                              STATS_MAX_COUNTS, stats_S.every);
        R->val[R->counts++] = before;
    }
    if (lr->rows == 0 || row.best > lr->best) lr->best = row.best;
    R->last = row.evaluations;
    lr->rows++;
    /* a row at a checkpoint holds it itself */
    if (row.evaluations == (R->counts + 1) * stats_S.every) {
        if (R->counts >= STATS_MAX_COUNTS)
            return am_fail_at(err, errsz, AM_ERR_CAPACITY, fname, lineno, "more than %d counts of %ld evaluations (a larger --every)",
                              STATS_MAX_COUNTS, stats_S.every);
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
            size_t len = strlen(stats_gait_names[i]);
            if (v[0] == '"' && !strncmp(v + 1, stats_gait_names[i], len) && v[len + 1] == '"') k = i;
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

/* ---- the command ---- */

static const char stats_help[] =
    "usage: amorph stats [--score best|sustained] [--every N] [--group NAME=DIR[,DIR...]]... [--pair A,B]... [--json] [DIR...]\n"
    "Compares groups of run folders (amorph evolve --out DIR) by tests. A DIR named on its own joins\n"
    "the group of its folder name without the trailing -K (runs/dct-1 and runs/dct-2: dct); --group\n"
    "names a group's runs explicitly. At every N evaluations that all the runs of a group have\n"
    "reached, each run's best fitness so far (log.csv: the best of its rows at or below N; a run\n"
    "that has not reached N yet is left out, with a note, while another of its group has); for each\n"
    "group n, mean, standard deviation and standard error; for each pair of groups (the higher mean\n"
    "first) the difference, Welch's t with its Welch-Satterthwaite degrees of freedom and two-sided\n"
    "p, the Mann-Whitney U (the pairs of runs in which the first group's is the higher, ties one half)\n"
    "with its two-sided p (exact up to 20 runs a group, else the normal approximation), Cohen's d,\n"
    "Hedges' g and the runs per group a t-test needs to find a difference of that d with 80% power at\n"
    "0.05; each test's p values also after Holm's correction over the pairs tested at that count\n"
    "(one family per count and test); then the ranking by mean with the differences each test finds\n"
    "significant at 0.05 after that correction. A pair with a group of fewer than 2 runs is not\n"
    "tested. Markdown tables in mm (docs/results.md).\n"
    "  --score best       the best fitness so far from log.csv (the default)\n"
    "  --score sustained  each run's best robot's travel per cycle over cycles 11-30, its\n"
    "                     gait30.json's sustained_travel (amorph sim DIR --cycles 30 --json;\n"
    "                     results/report.sh writes it), and each group's gaits (still, flop,\n"
    "                     scoot, bounce, roll)\n"
    "  --every N          the counts compared: every N evaluations (1000)\n"
    "  --group NAME=DIRS  the runs DIRS (comma-separated) as group NAME\n"
    "  --pair A,B         compare groups A and B (repeatable): only the pairs named, which are then\n"
    "                     the family Holm's correction runs over (planned comparisons); every\n"
    "                     pair when none is named\n"
    "  --json             one JSON object instead of the tables (values in m)\n";

int cmd_stats(tool_ctx* c, int argc, char** argv)
{
    (void)c;
    int as_json = 0;
    stats_S.nruns = stats_S.ngroups = 0;
    stats_S.every = 1000;
    stats_S.sustained = 0;
    stats_S.npairs = 0;
    /* --pair A,B: the names, found among the groups once every folder is read */
    static const char* pair_arg[STATS_MAX_GROUPS * (STATS_MAX_GROUPS - 1) / 2];
    int npair_args = 0;
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
            stats_S.sustained = !strcmp(v, "sustained");
            i++;
        } else if (!strcmp(a, "--every")) {
            if (!tool_parse_long(v, 1, 1000000000L, &stats_S.every)) return tool_usage_error("stats: --every needs a whole number 1..1000000000");
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
        } else if (!strcmp(a, "--pair")) {
            const char* comma = v ? strchr(v, ',') : 0;
            if (!comma || comma == v || !comma[1] || strchr(comma + 1, ',')) return tool_usage_error("stats: --pair needs NAME,NAME (two groups)");
            if (npair_args == (int)(sizeof pair_arg / sizeof pair_arg[0])) return tool_usage_error("stats: more than %d --pair", npair_args);
            pair_arg[npair_args++] = v;
            i++;
        } else if (a[0] == '-' && a[1]) {
            return tool_unknown_option("stats", a, stats_help);
        } else {
            int rc = add_run(a, NULL, 0);
            if (rc) return rc;
        }
    }
    if (stats_S.nruns == 0) return tool_usage_error("stats: name run folders (amorph stats --help)");
    for (int p = 0; p < npair_args; p++) {
        const char* comma = strchr(pair_arg[p], ',');
        int g[2] = {-1, -1};
        for (int side = 0; side < 2; side++) {
            const char* name = side ? comma + 1 : pair_arg[p];
            const size_t len = side ? strlen(name) : (size_t)(comma - pair_arg[p]);
            for (int k = 0; k < stats_S.ngroups; k++)
                if (strlen(stats_S.groups[k].name) == len && !strncmp(stats_S.groups[k].name, name, len)) g[side] = k;
            if (g[side] < 0) {
                char q[AM_QUOTE_BUF];
                return tool_usage_error("stats: --pair %s: no group %s among the runs named", pair_arg[p], am_quote(q, sizeof q, name, (int)len));
            }
        }
        if (g[0] == g[1]) return tool_usage_error("stats: --pair %s: a group against itself", pair_arg[p]);
        stats_S.pair[stats_S.npairs][0] = g[0];
        stats_S.pair[stats_S.npairs++][1] = g[1];
    }
    for (int r = 0; r < stats_S.nruns; r++) {
        int rc = stats_S.sustained ? read_gait(&stats_S.runs[r]) : read_log(&stats_S.runs[r]);
        if (rc) return rc;
    }
    for (int g = 0; g < stats_S.ngroups; g++) {
        stats_group* G = &stats_S.groups[g];
        /* a run that has reached no count yet (one just started) is left out of its group's best
         * fitness while another run of the group has reached one: it would hide the group at every
         * count (its runs are compared at the counts all of them reached) */
        int kept = 0;
        for (int i = 0; i < G->n; i++) kept += stats_S.runs[G->runs[i]].counts > 0;
        if (!stats_S.sustained && kept > 0 && kept < G->n) {
            int n = 0;
            for (int i = 0; i < G->n; i++) {
                const stats_run* R = &stats_S.runs[G->runs[i]];
                if (R->counts > 0) G->runs[n++] = G->runs[i];
                else fprintf(stderr, "amorph: stats: note: %s has not reached %ld evaluations: left out of %s\n", R->dir, stats_S.every, G->name);
            }
            G->n = n;
        }
        G->counts = STATS_MAX_COUNTS;
        for (int i = 0; i < G->n; i++) {
            const stats_run* R = &stats_S.runs[G->runs[i]];
            if (R->counts < G->counts) G->counts = R->counts;
            if (stats_S.sustained) G->gaits[R->gait]++;
        }
    }
    if (!stats_S.sustained && stats_max_counts() == 0) {
        fprintf(stderr, "amorph: stats: no group's runs have all reached %ld evaluations: nothing to compare\n", stats_S.every);
        return 0;
    }
    tool_out o;
    if (tool_out_open(&o, NULL)) return 1;
    if (as_json) stats_json(&o.text);
    else stats_markdown(&o.text);
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
