/* amorph evolve: a run in a folder (config, log, best robot, summary, checkpoint), resumable;
 * amorph experiment: the seed's experiments as groups of runs; bench --evolve. */
#include "cmd.h"

#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(AM_PROFILE_BOARD)
#define EXP_ROWS 64             /* generations an experiment's table reads per run */
#define EXP_MAX_RUNS 4          /* runs per variant */
#define EXP_DIR_MAX 256         /* an experiment folder's name */
#define EXP_RUN_DIR_MAX 384     /* a run folder's name */
#else
#define EXP_ROWS 4096
#define EXP_MAX_RUNS 16
#define EXP_DIR_MAX 1024
#define EXP_RUN_DIR_MAX 2048
#endif

static const char evolve_help[] =
    "usage: amorph evolve [--config FILE] [--KEY VALUE]... [--out DIR] [options]\n"
    "       amorph evolve --resume DIR [--evaluations N] [--threads N] [--quiet]\n"
    "Evolves robots by deterministic crowding. With no options: the seed's two-material experiment\n"
    "(GMX, 20^3 workspace, population 20, CTE 0.01, amplitude 30, period 500 steps, friction\n"
    "0.3 / 1.0) for 200 evaluations. Settings come from the defaults, then --config FILE, then\n"
    "flags: every configuration key is a flag (--workspace 8, --representation dct ...;\n"
    "--help-config lists them).\n"
    "  --out DIR          the run folder (default: a new folder runs/run-NNN)\n"
    "  --resume DIR       continue the run in DIR from its checkpoint\n"
    "  --print-config     print the effective configuration and exit\n"
    "  --help-config      list the configuration keys\n"
    "  --quiet            no progress output\n"
    "  --no-pictures      no filmstrip, plot or viewer page at the end\n"
    "  --json             the final summary as one JSON line (summary.json holds the same)\n"
    "The run folder holds config.txt, log.csv, evals.csv (a row per evaluation), best.genome,\n"
    "best.lattice, checkpoint.txt, lock (one process at a time), and at the end summary.txt,\n"
    "summary.json, best.png (filmstrip), best.html (viewer) and fitness.svg.\n"
    "Ctrl-C stops after the current evaluations; --resume continues exactly.\n";

/* ---- options shared by evolve and experiment ---- */

typedef struct evo_opts {
    const char* config;       /* --config FILE */
    const char* out;          /* --out DIR */
    const char* resume;       /* --resume DIR */
    int print_config, quiet, pictures, json;
    int nflags;
    const char* key[64];      /* KEY VALUE flags in order */
    const char* val[64];
} evo_opts;

/* one option at argv[*i]; returns 1 when consumed, 0 when unknown, -1 after an error message */
static int parse_common(int argc, char** argv, int* i, evo_opts* o, const char* cmd)
{
    const char* a = argv[*i];
    const char* v = *i + 1 < argc ? argv[*i + 1] : NULL;
    if (strncmp(a, "--", 2) != 0) return 0;
    const char* name = a + 2;
    char keybuf[64];
    const char* eq = strchr(name, '=');
    if (eq) {
        size_t n = (size_t)(eq - name);
        if (n >= sizeof keybuf) return 0;
        memcpy(keybuf, name, n);
        keybuf[n] = 0;
        name = keybuf;
        v = eq + 1;
    }
    /* flags may spell keys with '-' for '_' */
    char norm[64];
    snprintf(norm, sizeof norm, "%s", name);
    for (char* c = norm; *c; c++)
        if (*c == '-') *c = '_';
    if (!strcmp(norm, "quiet")) o->quiet = 1;
    else if (!strcmp(norm, "no_pictures")) o->pictures = 0;
    else if (!strcmp(norm, "json")) o->json = 1;
    else if (!strcmp(norm, "print_config")) o->print_config = 1;
    else if (!strcmp(norm, "config") || !strcmp(norm, "out") || !strcmp(norm, "resume") || am_evo_is_key(norm)) {
        if (!v || (!eq && !strncmp(v, "--", 2))) {
            tool_usage_error("%s: --%s needs a value", cmd, name);
            return -1;
        }
        if (!eq) (*i)++;
        if (!strcmp(norm, "config")) o->config = v;
        else if (!strcmp(norm, "out")) o->out = v;
        else if (!strcmp(norm, "resume")) o->resume = v;
        else {
            if (o->nflags == 64) {
                tool_usage_error("%s: too many settings on the command line", cmd);
                return -1;
            }
            /* keep the key as spelt in the table */
            for (int k = 0; k < am_evo_key_count(); k++)
                if (!strcmp(am_evo_key_name(k), norm)) o->key[o->nflags] = am_evo_key_name(k);
            o->val[o->nflags++] = v;
        }
    } else return 0;
    return 1;
}

/* defaults, then the config file (o->config, else `config` when not NULL), then the flags, then
 * `extra` more (keys and values, NULL-terminated; may be NULL) */
static TOOL_NOINLINE int build_def(const evo_opts* o, const char* config, const char* const* extra, am_evo_def* d, const char* cmd)
{
    char err[AM_ERR_MAX];
    *d = am_default_evo();
    if (o->config) config = o->config;
    if (config && tool_read_config(config, d, 0, err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
    for (int k = 0; k < o->nflags; k++)
        if (am_evo_set(d, o->key[k], o->val[k], err, sizeof err) != AM_OK) return tool_usage_error("%s: --%s", cmd, err);
    for (int k = 0; extra && extra[k]; k += 2)
        if (am_evo_set(d, extra[k], extra[k + 1], err, sizeof err) != AM_OK) return tool_usage_error("%s: --%s", cmd, err);
    if (am_evo_check(d, err, sizeof err) != AM_OK) return tool_usage_error("%s: %s", cmd, err);
    return 0;
}

static void help_config(void)
{
    am_evo_def d = am_default_evo();
    char value[64];
    printf("configuration keys (config file 'key = value', or flag --key VALUE), with defaults:\n");
    for (int k = 0; k < am_evo_key_count(); k++) {
        am_evo_key_value(&d, k, value, sizeof value);
        printf("  %-20s %-12s %s\n", am_evo_key_name(k), value, am_evo_key_help(k));
    }
}

/* ---- run folder ---- */

/* dir/file into out; a path too long for out is cut (and then fails to open, with its name) */
static int path_join(char* out, size_t cap, const char* dir, const char* file)
{
    int n = snprintf(out, cap, "%s/%s", dir, file);
    return n >= 0 && (size_t)n < cap;
}

static TOOL_NOINLINE int write_text(const char* dir, const char* file, const char* text, long len)
{
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    path_join(path, sizeof path, dir, file);
    if (am_port_write_file(path, text, len, err, sizeof err) != AM_OK) {
        fprintf(stderr, "amorph: %s\n", err);
        return 1;
    }
    return 0;
}

/* dir/file written through a stream by a writer of the library: 0, or 1 after a message
 * ("amorph: what: problem" for the writer's own failures) */
typedef am_status (*text_writer)(const void* obj, am_text* out, char* err, int errsz);

static TOOL_NOINLINE int write_stream(const char* dir, const char* file, text_writer fn, const void* obj, const char* what)
{
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    path_join(path, sizeof path, dir, file);
    tool_out o;
    if (tool_out_open(&o, path)) return 1;
    am_status st = fn(obj, &o.text, err, sizeof err);
    if (st != AM_OK && st != AM_ERR_IO) {
        if (what) fprintf(stderr, "amorph: %s: %s\n", what, err);
        else fprintf(stderr, "amorph: %s\n", err);
        tool_out_close(&o, 0);
        return 1;
    }
    return tool_out_close(&o, 1);
}

static am_status config_writer(const void* obj, am_text* out, char* err, int errsz)
{
    return am_evo_write((const am_evo_def*)obj, 1, out, err, errsz);
}

static am_status checkpoint_writer(const void* obj, am_text* out, char* err, int errsz)
{
    return am_evo_checkpoint_write((const am_evo*)obj, out, err, errsz);
}

static am_status genome_writer(const void* obj, am_text* out, char* err, int errsz)
{
    return am_genome_write((const am_genome*)obj, out, err, errsz);
}

static am_status lattice_writer(const void* obj, am_text* out, char* err, int errsz)
{
    return am_lattice_write((const am_lattice*)obj, out, err, errsz);
}

static int write_config(const char* dir, const am_evo_def* d)
{
    return write_stream(dir, "config.txt", config_writer, d, NULL);
}

static int write_checkpoint(const char* dir, const am_evo* e)
{
    return write_stream(dir, "checkpoint.txt", checkpoint_writer, e, "checkpoint");
}

static TOOL_NOINLINE int write_best(const char* dir, const am_evo* e)
{
    char err[AM_ERR_MAX];
    if (write_stream(dir, "best.genome", genome_writer, &e->best.genome, "best genome")) return 1;
    if (am_evo_lattice(&e->def, &e->palette, &e->best.genome, &tool_work[0].geno, &tool_work[0].lattice, err, sizeof err) != AM_OK) {
        fprintf(stderr, "amorph: best lattice: %s\n", err);
        return 1;
    }
    return write_stream(dir, "best.lattice", lattice_writer, &tool_work[0].lattice, "best lattice");
}

/* a run's summary as a record: the same fields in summary.txt, summary.json and the final output */
static void put_summary(tool_rec* q, const am_evo* e, const char* dir, double wall)
{
    tool_rec_str(q, "run", dir);
    tool_rec_str(q, "representation", am_repr_name(e->def.geno.repr));
    tool_rec_int(q, "evaluations", e->evaluations);
    tool_rec_int(q, "generations", e->generation);
    tool_rec_num(q, "best_fitness", e->best.fitness);
    tool_rec_int(q, "best_voxels", e->best.voxels);
    tool_rec_int(q, "best_steps", e->best.steps);
    tool_rec_hex(q, "best_state_hash", e->best.state_hash);
    tool_rec_int(q, "best_evaluation", e->best.id);
    tool_rec_num(q, "final_best", e->last.best);
    tool_rec_num(q, "final_mean", e->last.mean);
    tool_rec_num(q, "final_median", e->last.median);
    tool_rec_hex(q, "run_hash", am_evo_hash(e));
    tool_rec_num(q, "wall_s", wall);
    char build[64];
    snprintf(build, sizeof build, "%s %s", AM_REAL_NAME, AM_PROFILE_NAME);
    tool_rec_str(q, "build", build);
}

/* dir/summary.txt (a comment line, then key = value lines) and dir/summary.json (one JSON
 * object), both of the fields put(q, ctx) writes; 0, or 1 after a message */
static TOOL_NOINLINE int write_summaries(const char* dir, const char* comment, void (*put)(tool_rec* q, const void* ctx), const void* ctx)
{
    for (int json = 0; json < 2; json++) {
        char path[TOOL_PATH_MAX];
        path_join(path, sizeof path, dir, json ? "summary.json" : "summary.txt");
        tool_out o;
        if (tool_out_open(&o, path)) return 1;
        if (!json) am_text_put(&o.text, "# %s\n", comment);
        tool_rec q;
        tool_rec_begin(&q, &o.text, json);
        put(&q, ctx);
        tool_rec_end(&q);
        if (tool_out_close(&o, 1)) return 1;
    }
    return 0;
}

typedef struct run_summary {
    const am_evo* e;
    const char* dir;
    double wall;
} run_summary;

static void put_run_summary(tool_rec* q, const void* ctx)
{
    const run_summary* r = (const run_summary*)ctx;
    put_summary(q, r->e, r->dir, r->wall);
}

static int write_summary(const char* dir, const am_evo* e, double wall)
{
    const run_summary r = {e, dir, wall};
    return write_summaries(dir, "amorph evolve summary", put_run_summary, &r);
}

static TOOL_NOINLINE int append_log(const char* dir, const am_evo_stats* s)
{
    char row[256], path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    int n = am_evo_log_row(s, row, (int)sizeof row - 1);
    row[n++] = '\n';
    path_join(path, sizeof path, dir, "log.csv");
    if (am_port_append_file(path, row, n, err, sizeof err) != AM_OK) {
        fprintf(stderr, "amorph: %s\n", err);
        return 1;
    }
    return 0;
}

/* dir/file (a table: log.csv or evals.csv with header hdr) cut back to the header and the first
 * `rows` rows (rows the checkpoint has seen, `unit` its count's name in messages): the file is
 * read line by line, then, when it holds more, copied that far into its replacement */
static TOOL_NOINLINE int trim_table(const char* dir, const char* file, const char* hdr, long rows, const char* unit)
{
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX], *line;
    long n, have = 0;
    int r;
    path_join(path, sizeof path, dir, file);
    tool_src src;
    if (tool_src_open(&src, path, TOOL_FILE_MAX, 1, err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
    r = tool_src_next(&src, &line, &n, err, sizeof err);
    if (r == 1 && (strcmp(line, hdr) != 0 || !src.newline)) r = 2;
    if (r != 1) {
        tool_src_close(&src);
        if (r < 0) return tool_usage_error("%s", err);
        return tool_usage_error("%s:1: not an amorph log (expected the header '%s')", path, hdr);
    }
    /* rows the log holds (whole lines), and whether anything follows the last one kept */
    int more = 0;
    while ((r = tool_src_next(&src, &line, &n, err, sizeof err)) == 1) {
        if (have == rows || !src.newline) {
            more = 1;
            break;
        }
        have++;
    }
    if (r < 0) {
        tool_src_close(&src);
        return tool_usage_error("%s", err);
    }
    if (have < rows) {
        tool_src_close(&src);
        return tool_usage_error("%s: %ld rows, but the checkpoint is at %s %ld (the table is damaged)", path, have, unit, rows);
    }
    if (!more) {
        tool_src_close(&src);
        return 0;
    }
    tool_out o;
    if (tool_src_rewind(&src, err, sizeof err) != AM_OK || tool_out_open(&o, path)) {
        tool_src_close(&src);
        return tool_usage_error("%s", err);
    }
    for (long k = 0; k <= rows && tool_src_next(&src, &line, &n, err, sizeof err) == 1; k++) {
        am_text_write(&o.text, line, n);
        am_text_write(&o.text, "\n", 1);
    }
    tool_src_close(&src);
    return tool_out_close(&o, 1) ? 2 : 0;
}

/* evals.csv: one row per evaluation, appended as the library places each batch */
typedef struct evals_out {
    const char* dir;
    const am_evo_def* def;
    int failed;               /* 1 after a row could not be written (reported once) */
} evals_out;

static void evals_append(void* ctx, const am_evo_ind* ind, const am_evo_eval* ev)
{
    evals_out* o = (evals_out*)ctx;
    char row[AM_EVO_EVALS_ROW_MAX + 1], path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    if (o->failed) return;
    int n = am_evo_evals_row(o->def, ind, ev, row, (int)sizeof row - 1);
    row[n++] = '\n';
    path_join(path, sizeof path, o->dir, "evals.csv");
    if (am_port_append_file(path, row, n, err, sizeof err) != AM_OK) {
        fprintf(stderr, "amorph: %s\n", err);
        o->failed = 1;
    }
}

/* the header of a run's evals.csv, with its newline; returns its length */
static int evals_header(const am_evo_def* d, char* buf, int cap)
{
    int n = am_evo_evals_header(d->geno.materials, buf, cap - 1);
    buf[n++] = '\n';
    buf[n] = 0;
    return n;
}

/* a fresh folder name under runs/ */
static int default_out(char* out, size_t cap)
{
    char err[AM_ERR_MAX];
    if (am_port_make_dir("runs", err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
    for (int k = 1; k < 100000; k++) {
        snprintf(out, cap, "runs/run-%03d", k);
        if (!am_port_exists(out)) return 0;
    }
    return tool_usage_error("runs/: no free run-NNN name left");
}

/* ---- the loop ---- */

typedef struct run_io {
    const char* dir;
    int quiet;
    int pictures;
    const char* label;        /* prefix of progress lines (experiments), or NULL */
} run_io;

static TOOL_NOINLINE void progress(const am_evo* e, double t_start, long evals_start, int final, double* last_line, int quiet, const char* label)
{
    if (quiet) return;
    double now = am_port_now(), el = now - t_start;
    double rate = el > 0 ? (double)(e->evaluations - evals_start) / el : 0.0;
    double left = rate > 0 ? (double)(e->def.evaluations - e->evaluations) / rate : 0.0;
    if (left < 0) left = 0;
    char line[256];
    snprintf(line, sizeof line, "%s%sevaluations %ld/%ld  best %.4f m  mean %.4f m  %.2f eval/s  %.0f s left",
             label ? label : "", label ? ": " : "", e->evaluations, e->def.evaluations, e->last.best, e->last.mean, rate, left);
    if (am_port_is_terminal()) {
        am_port_progress(line);
        if (final) am_port_progress(NULL);
    } else if (final || now - *last_line >= 5.0) {
        fprintf(stderr, "%s\n", line);
        *last_line = now;
    }
}

/* ---- testing interruptions: AMORPH_TEST_INTERRUPT=SIG:N (docs/evolve.md) ----
 * The process sends itself SIG (INT, TERM or KILL) when its run is about to start evaluation
 * N + 1, counted over the whole run (a resumed run counts from its checkpoint): with one worker,
 * exactly N evaluations are done; with more, N have started and the unfinished generation is
 * dropped all the same. INT and TERM take the Ctrl-C path (stop, checkpoint, exit 130), KILL is
 * kill -9 (exit 137). Evaluations are polled through the cancel callback of am_evo_generation,
 * which sees every evaluation of a generation when the generation is one batch (the desktop);
 * a point past the first batch of a generation of several batches (the board profile) is taken
 * when that generation returns, before it is logged, as a Ctrl-C is there. Fired at most once. */
static struct {
    am_port_signal sig;       /* 0: no interruption asked for */
    long after;               /* N */
    long base;                /* the run's evaluations before the generation under way */
    atomic_long started;      /* cancel polls (evaluations about to start) of that generation */
    atomic_int fired;
} g_test_int;

/* reads AMORPH_TEST_INTERRUPT (unset or empty: none); 0, or 2 after a one-line message */
static TOOL_NOINLINE int test_interrupt_setup(void)
{
    static const struct {
        const char* name;
        am_port_signal sig;
    } sigs[] = {{"INT", AM_PORT_SIGINT}, {"TERM", AM_PORT_SIGTERM}, {"KILL", AM_PORT_SIGKILL}, {"STOP", AM_PORT_SIGSTOP}};
    const char* v = am_port_getenv("AMORPH_TEST_INTERRUPT");
    g_test_int.sig = (am_port_signal)0;
    if (!v || !*v) return 0;
    const char* colon = strchr(v, ':');
    for (size_t k = 0; colon && k < sizeof sigs / sizeof sigs[0]; k++)
        if (strlen(sigs[k].name) == (size_t)(colon - v) && !strncmp(v, sigs[k].name, (size_t)(colon - v)) &&
            tool_parse_long(colon + 1, 0, 1000000000L, &g_test_int.after)) {
            g_test_int.sig = sigs[k].sig;
            atomic_store(&g_test_int.fired, 0);
            return 0;
        }
    char shown[48];
    snprintf(shown, sizeof shown, "%s", v);
    for (char* c = shown; *c; c++)
        if ((unsigned char)*c < 32 || *c == 127) *c = '?'; /* the message stays one line */
    return tool_usage_error("AMORPH_TEST_INTERRUPT = '%s%s': expected SIG:N, SIG one of INT, TERM, KILL, STOP and N a whole number "
                            "of evaluations >= 0 (a test setting, docs/evolve.md)",
                            shown, strlen(v) >= sizeof shown ? "..." : "");
}

static void test_interrupt_fire(void)
{
    if (!atomic_exchange(&g_test_int.fired, 1)) am_port_raise(g_test_int.sig);
}

/* the cancel callback of a run's generations (on the workers, before each evaluation) */
static int run_cancel(void* ctx)
{
    (void)ctx;
    if (g_test_int.sig && !atomic_load(&g_test_int.fired) && g_test_int.base + atomic_fetch_add(&g_test_int.started, 1) == g_test_int.after)
        test_interrupt_fire();
    return am_port_interrupted();
}

static int workers_of(const am_evo_def* d)
{
    int w = d->threads > 0 ? d->threads : am_port_cores();
    if (w > AM_MAX_WORKERS) w = AM_MAX_WORKERS;
    return w < 1 ? 1 : w;
}

/* runs e to its end in io->dir; 0 done, 130 interrupted, 1 error */
static int run_loop(am_evo* e, const run_io* io)
{
    char err[AM_ERR_MAX];
    const int workers = workers_of(&e->def);
    const double t0 = am_port_now();
    const long evals0 = e->evaluations;
    double last_ckpt = t0, last_line = t0;
    int dirty = 0;
    evals_out eo = {io->dir, &e->def, 0};
    const am_evo_hooks hooks = {run_cancel, evals_append, &eo};
    while (!am_evo_done(e)) {
        double best_before = e->has_best ? e->best.fitness : 0.0;
        int had_best = e->has_best;
        g_test_int.base = e->evaluations;
        atomic_store(&g_test_int.started, 0);
        am_status st = am_evo_generation(e, tool_work, workers, &hooks, err, sizeof err);
        if (st == AM_ERR_CANCELLED) break;
        if (st != AM_OK) {
            fprintf(stderr, "amorph: %s\n", err);
            return 1;
        }
        if (eo.failed) return 1; /* the checkpoint stays behind: a resume cuts evals.csv back to it */
        /* a test's point inside this generation that no cancel poll saw (several batches) */
        if (g_test_int.sig && !atomic_load(&g_test_int.fired) && g_test_int.base <= g_test_int.after && g_test_int.after < e->evaluations)
            test_interrupt_fire();
        if (append_log(io->dir, &e->last)) return 1;
        if ((!had_best || e->best.fitness != best_before) && write_best(io->dir, e)) return 1;
        dirty = 1;
        double now = am_port_now();
        if (e->def.checkpoint_seconds == 0 || now - last_ckpt >= (double)e->def.checkpoint_seconds || am_evo_done(e)) {
            if (write_checkpoint(io->dir, e)) return 1;
            last_ckpt = now;
            dirty = 0;
        }
        progress(e, t0, evals0, am_evo_done(e), &last_line, io->quiet, io->label);
        if (am_port_interrupted()) break;
    }
    if (am_port_interrupted() && !am_evo_done(e)) {
        if (dirty && write_checkpoint(io->dir, e)) return 1;
        am_port_progress(NULL);
        fprintf(stderr, "amorph: interrupted after %ld evaluations (generation %ld); the checkpoint in %s stands.\n"
                        "amorph: resume with: amorph evolve --resume %s\n",
                e->evaluations, e->generation, io->dir, io->dir);
        return 130;
    }
    if (write_summary(io->dir, e, am_port_now() - t0)) return 1;
    return 0;
}

/* the run's pictures: the best robot's filmstrip (best.png) and viewer page (best.html), and the
 * fitness plot (fitness.svg); builds without pictures (the board profile) skip them */
static int finish_pictures(const am_evo* e, const char* dir)
{
#if !TOOL_PICTURES
    (void)e, (void)dir;
    return 0;
#else
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX], title[256];
    if (am_evo_lattice(&e->def, &e->palette, &e->best.genome, &tool_work[0].geno, &tool_work[0].lattice, err, sizeof err) != AM_OK) {
        fprintf(stderr, "amorph: best robot: %s\n", err);
        return 1;
    }
    am_eval_def ev = e->def.eval;
    ev.record = NULL;
    if (am_lattice_count(&tool_work[0].lattice) > 0) {
        path_join(path, sizeof path, dir, "best.png");
        if (tool_write_filmstrip(&tool_work[0].lattice, &e->def.env, &ev, path)) return 1;
        path_join(path, sizeof path, dir, "best.html");
        snprintf(title, sizeof title, "amorph: best of %s (%.4f m)", dir, e->best.fitness);
        if (tool_write_viewer(&tool_work[0].lattice, &e->def.env, &ev, title, path)) return 1;
    }
    path_join(path, sizeof path, dir, "fitness.svg");
    char* dirs[1] = {(char*)(uintptr_t)dir};
    return tool_write_plot(1, dirs, path);
#endif
}

/* a new run in dir (made and locked by the caller): its configuration, log headers and first
 * checkpoint; 0, 1 or 2. A run exists once its first checkpoint does (written before any
 * evaluation): a folder with the other files but no checkpoint was left by a run stopped before
 * it, and is started over. */
static TOOL_NOINLINE int start_prepare(const am_evo_def* d, const char* dir)
{
    char err[AM_ERR_MAX], path[TOOL_PATH_MAX];
    path_join(path, sizeof path, dir, "checkpoint.txt");
    if (am_port_exists(path)) return tool_usage_error("%s holds a run already: continue it with --resume %s, or choose another --out", dir, dir);
    if (am_evo_init(&tool_evo, d, err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
    if (write_config(dir, d)) return 1;
    char hdr[AM_EVO_EVALS_ROW_MAX + 2];
    int n = snprintf(hdr, sizeof hdr, "%s\n", am_evo_log_header());
    if (write_text(dir, "log.csv", hdr, n)) return 1;
    n = evals_header(d, hdr, (int)sizeof hdr);
    if (write_text(dir, "evals.csv", hdr, n)) return 1;
    /* a checkpoint before the first evaluation: a run stopped at any moment can be resumed */
    if (write_checkpoint(dir, &tool_evo)) return 1;
    return 0;
}

/* owns the run folder dir (its `lock` file) while this process works in it: a second process on
 * the same folder is refused. 0, or 2 after a message */
static TOOL_NOINLINE int lock_run(const char* dir)
{
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    path_join(path, sizeof path, dir, "lock");
    if (am_port_lock(path, err, sizeof err) != AM_OK)
        return tool_usage_error("%s (another amorph is working in %s: wait for it to end, or stop it)", err, dir);
    return 0;
}

/* a new run in dir, to its end; 0, 1, 2 or 130 */
static int start_run(const am_evo_def* d, const char* dir, int quiet, int pictures, const char* label)
{
    char err[AM_ERR_MAX];
    if (am_port_make_dir(dir, err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
    if (lock_run(dir)) return 2;
    int rc = start_prepare(d, dir);
    if (rc == 0) {
        run_io io = {dir, quiet, pictures, label};
        rc = run_loop(&tool_evo, &io);
        if (rc == 0 && pictures) rc = finish_pictures(&tool_evo, dir);
    }
    am_port_unlock();
    return rc;
}

/* reads the checkpoint at path into e, in the two passes of the library (the checksum over the
 * bytes, then the lines): 0, or 2 after a message */
static TOOL_NOINLINE int read_checkpoint(const char* path, am_evo* e)
{
    char err[AM_ERR_MAX], *line;
    long n;
    int r;
    tool_src src;
    am_status st = tool_src_open(&src, path, TOOL_CKPT_MAX, 0, err, sizeof err);
    if (st != AM_OK && !src.binary) return tool_usage_error("--resume: %s", err);
    am_evo_ckpt_scan sc;
    am_evo_checkpoint_scan_begin(&sc);
    if (st == AM_OK) {
        while ((r = tool_src_next(&src, &line, &n, err, sizeof err)) == 1) {
            am_evo_checkpoint_scan(&sc, line, n);
            if (src.newline) am_evo_checkpoint_scan(&sc, "\n", 1);
        }
        if (r < 0) st = src.binary ? AM_ERR_PARSE : src.st;
    }
    if (st != AM_OK) {
        tool_src_close(&src);
        if (src.binary) return tool_usage_error("%s:1: binary data in a checkpoint (damaged)", path);
        return tool_usage_error("%s", err);
    }
    st = am_evo_checkpoint_scan_end(&sc, path, err, sizeof err);
    if (st == AM_OK) st = tool_src_rewind(&src, err, sizeof err);
    if (st == AM_OK) {
        am_evo_ckpt_reader rd;
        am_evo_checkpoint_read_begin(&rd, e, &sc, path);
        r = 1;
        while (st == AM_OK && src.line + 1 < sc.checksum_line && (r = tool_src_next(&src, &line, &n, err, sizeof err)) == 1)
            st = am_evo_checkpoint_read_line(&rd, line, n, err, sizeof err);
        if (st == AM_OK && r < 0) st = src.st;
        if (st == AM_OK) st = am_evo_checkpoint_read_end(&rd, err, sizeof err);
    }
    tool_src_close(&src);
    return st == AM_OK ? 0 : tool_usage_error("%s", err);
}

/* loads the run in dir and checks it against the settings the user gives now (flags o, then
 * `extra` keys and values); 0, 1 or 2 */
static TOOL_NOINLINE int resume_load(const char* dir, const evo_opts* o, const char* const* extra)
{
    char path[TOOL_PATH_MAX], what[160];
    path_join(path, sizeof path, dir, "config.txt");
    const int has_config = am_port_exists(path);
    path_join(path, sizeof path, dir, "checkpoint.txt");
    if (has_config && !am_port_exists(path))
        return tool_usage_error("--resume %s: no checkpoint.txt: the run stopped before its first checkpoint, so no evaluation was "
                                "done; start it again with --out %s",
                                dir, dir);
    int rc = read_checkpoint(path, &tool_evo);
    if (rc) return rc;
    /* what the run folder's config.txt and today's flags say */
    path_join(path, sizeof path, dir, "config.txt");
    am_evo_def d;
    if (build_def(o, path, extra, &d, "resume")) return 2;
    if (!am_evo_same_run(&tool_evo.def, &d, what, sizeof what))
        return tool_usage_error("--resume %s: the configuration changed: %s; a run continues only with its own settings", dir, what);
    tool_evo.def.evaluations = d.evaluations;
    tool_evo.def.threads = d.threads;
    tool_evo.def.checkpoint_seconds = d.checkpoint_seconds;
    if (tool_evo.def.evaluations < tool_evo.evaluations)
        return tool_usage_error("--resume %s: evaluations = %ld is below the %ld already done", dir, tool_evo.def.evaluations, tool_evo.evaluations);
    if (trim_table(dir, "log.csv", am_evo_log_header(), tool_evo.generation, "generation")) return 2;
    char hdr[AM_EVO_EVALS_ROW_MAX + 2];
    int n = evals_header(&tool_evo.def, hdr, (int)sizeof hdr);
    path_join(path, sizeof path, dir, "evals.csv");
    if (!am_port_exists(path)) {
        /* a run begun by a build without evals.csv: the table starts at the checkpoint's evaluation */
        if (write_text(dir, "evals.csv", hdr, n)) return 1;
    } else {
        hdr[n - 1] = 0;
        if (trim_table(dir, "evals.csv", hdr, tool_evo.evaluations, "evaluation")) return 2;
    }
    if (write_config(dir, &tool_evo.def)) return 1;
    return 0;
}

static int resume_run(const char* dir, const evo_opts* o, const char* const* extra, int quiet, int pictures, const char* label)
{
    if (am_port_exists(dir) && lock_run(dir)) return 2;
    int rc = resume_load(dir, o, extra);
    if (rc == 0) {
        run_io io = {dir, quiet, pictures, label};
        rc = run_loop(&tool_evo, &io);
        if (rc == 0 && pictures) rc = finish_pictures(&tool_evo, dir);
    }
    am_port_unlock();
    return rc;
}

/* the run's summary on the standard output: key = value lines, or one JSON line (--json) */
static int print_result(const am_evo* e, const char* dir, double wall, int json)
{
    tool_out o;
    if (tool_out_open(&o, NULL)) return 1;
    tool_rec q;
    tool_rec_begin(&q, &o.text, json);
    put_summary(&q, e, dir, wall);
    tool_rec_end(&q);
    return tool_out_close(&o, 1);
}

int cmd_evolve(int argc, char** argv)
{
    evo_opts o;
    memset(&o, 0, sizeof o);
    o.pictures = 1;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            fputs(evolve_help, stdout);
            return 0;
        }
        if (!strcmp(argv[i], "--help-config")) {
            help_config();
            return 0;
        }
        int r = parse_common(argc, argv, &i, &o, "evolve");
        if (r < 0) return 2;
        if (r == 0) return tool_usage_error("evolve: unknown option '%s' (amorph evolve --help)", argv[i]);
    }
    if (o.resume && o.out) return tool_usage_error("evolve: --resume DIR continues in DIR; --out does not apply");
    if (o.resume && o.config) return tool_usage_error("evolve: --resume reads the run's own config.txt; --config does not apply");
    am_evo_def d;
    if (!o.resume) {
        if (build_def(&o, NULL, NULL, &d, "evolve")) return 2;
        if (o.print_config) {
            char err[AM_ERR_MAX];
            tool_out out;
            if (tool_out_open(&out, NULL)) return 1;
            am_evo_write(&d, 1, &out.text, err, sizeof err);
            return tool_out_close(&out, 1);
        }
    } else if (o.print_config) return tool_usage_error("evolve: --print-config and --resume: print a run's settings with cat DIR/config.txt");
    char dir[EXP_DIR_MAX];
    if (strlen(o.resume ? o.resume : o.out ? o.out : "") >= sizeof dir) return tool_usage_error("evolve: folder name too long");
    if (test_interrupt_setup()) return 2;
    if (o.resume) snprintf(dir, sizeof dir, "%s", o.resume);
    else if (o.out) snprintf(dir, sizeof dir, "%s", o.out);
    else if (default_out(dir, sizeof dir)) return 2;
    am_port_catch_interrupt();
    const double t0 = am_port_now();
    int rc = o.resume ? resume_run(dir, &o, NULL, o.quiet, o.pictures, NULL) : start_run(&d, dir, o.quiet, o.pictures, NULL);
    if (rc == 0) rc = print_result(&tool_evo, dir, am_port_now() - t0, o.json);
    return rc;
}

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
    "ranking), and prints the table. Running the same command again\n"
    "resumes unfinished runs and skips finished ones. Other flags set configuration keys of every\n"
    "run (amorph evolve --help-config).\n"
    "  --evals N     evaluations per run (the configuration's, 200)\n"
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

/* reads the best-fitness column of dir/log.csv: evals[i] (when evals is not NULL), best[i] for up
 * to cap rows after the header; the rows read, -1 when the file cannot be read */
static TOOL_NOINLINE int read_log(const char* dir, long* evals, double* best, int cap)
{
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX], *line;
    long len;
    path_join(path, sizeof path, dir, "log.csv");
    tool_src src;
    if (tool_src_open(&src, path, TOOL_FILE_MAX, 1, err, sizeof err) != AM_OK) return -1;
    int n = 0;
    /* the header must end with a newline; every row after it until one does not read */
    if (tool_src_next(&src, &line, &len, err, sizeof err) == 1 && src.newline)
        while (n < cap && tool_src_next(&src, &line, &len, err, sizeof err) == 1) {
            long g, e;
            double b;
            if (sscanf(line, "%ld,%ld,%lf", &g, &e, &b) != 3) break;
            if (evals) evals[n] = e;
            best[n] = b;
            n++;
        }
    tool_src_close(&src);
    return n;
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
    return write_text(dir, "experiment.txt", about, n);
}

/* 1 when the run folder holds a checkpoint */
static TOOL_NOINLINE int run_has_checkpoint(const char* rdir)
{
    char ck[TOOL_PATH_MAX];
    path_join(ck, sizeof ck, rdir, "checkpoint.txt");
    return am_port_exists(ck);
}

/* run k of variant v in dir/<variant>-<k>: started, resumed, or (finished) left as it is;
 * 0, 1, 2 or 130 */
static TOOL_NOINLINE int experiment_run(const am_evo_def* base, const variant* v, long k, const char* dir, int quiet)
{
    char err[AM_ERR_MAX], rdir[EXP_RUN_DIR_MAX], label[96];
    am_evo_def d = *base;
    if (apply_settings(&d, v->settings)) return 2;
    d.seed = base->seed + (uint64_t)(k - 1);
    if (am_evo_check(&d, err, sizeof err) != AM_OK) return tool_usage_error("experiment %s: %s", v->name, err);
    if (snprintf(rdir, sizeof rdir, "%s/%s-%ld", dir, v->name, k) >= (int)sizeof rdir)
        return tool_usage_error("experiment: folder name too long");
    snprintf(label, sizeof label, "%s-%ld", v->name, k);
    if (!run_has_checkpoint(rdir)) return start_run(&d, rdir, quiet, 0, label);
    /* a run begun before: resumed with this experiment's evaluations and threads */
    static const evo_opts none;
    char evs[32], ths[32];
    snprintf(evs, sizeof evs, "%ld", d.evaluations);
    snprintf(ths, sizeof ths, "%d", d.threads);
    const char* const extra[] = {"evaluations", evs, "threads", ths, NULL};
    return resume_run(rdir, &none, extra, quiet, 0, label);
}

static int experiment_results(const experiment* x, int nv, long runs, const char* dir, int pictures, int json_out);

int cmd_experiment(int argc, char** argv)
{
    evo_opts o;
    memset(&o, 0, sizeof o);
    o.pictures = 1;
    const char* name = NULL;
    long evals = 0, runs = 3;
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        const char* v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(experiment_help, stdout);
            for (int k = 0; k < EXPERIMENTS; k++) printf("  %-16s %s\n", experiments[k].name, experiments[k].about);
            return 0;
        } else if (!strcmp(a, "--evals")) {
            if (!tool_parse_long(v, 2, 1000000000L, &evals)) return tool_usage_error("experiment: --evals needs a whole number >= 2");
            i++;
        } else if (!strcmp(a, "--runs")) {
            if (!tool_parse_long(v, 1, EXP_MAX_RUNS, &runs))
                return tool_usage_error("experiment: --runs needs a whole number in [1, %d]", EXP_MAX_RUNS);
            i++;
        } else if (a[0] != '-' && !name) {
            name = a;
        } else {
            int r = parse_common(argc, argv, &i, &o, "experiment");
            if (r < 0) return 2;
            if (r == 0) return tool_usage_error("experiment: unknown option '%s' (amorph experiment --help)", a);
        }
    }
    if (o.resume) return tool_usage_error("experiment: run the same command with the same --out again to resume");
    if (o.print_config) return tool_usage_error("experiment: --print-config applies to amorph evolve");
    if (!name) return tool_usage_error("experiment: which one? (amorph experiment --help lists them)");
    const experiment* x = NULL;
    for (int k = 0; k < EXPERIMENTS; k++)
        if (!strcmp(experiments[k].name, name)) x = &experiments[k];
    if (!x) return tool_usage_error("experiment: unknown experiment '%s' (representations, three-materials, dynamic, friction)", name);
    am_evo_def base;
    if (build_def(&o, NULL, NULL, &base, "experiment")) return 2;
    if (evals) base.evaluations = evals;
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
    for (int v = 0; v < nv; v++)
        for (long k = 1; k <= runs; k++) {
            int rc = experiment_run(&base, &x->v[v], k, dir, o.quiet);
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
            if (n <= 0) return tool_usage_error("%s/log.csv: no rows", rdir);
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
        path_join(path, sizeof path, dir, "results.csv");
        tool_out out;
        if (tool_out_open(&out, path)) return 1;
        am_text_put(&out.text, "variant,evaluations,mean_best,stderr_best,runs\n");
        for (int v = 0; v < nv; v++) {
            for (int pass = 0; pass < 2; pass++) {
                for (int r = 0; r < rows; r++) (pass ? g_exp_dev : g_exp_sum)[r] = 0;
                for (long k = 1; k <= runs; k++) {
                    char rdir[EXP_RUN_DIR_MAX];
                    snprintf(rdir, sizeof rdir, "%s/%s-%ld", dir, x->v[v].name, k);
                    if (read_log(rdir, NULL, g_exp_tmp, rows) < rows) {
                        tool_out_close(&out, 0);
                        return tool_usage_error("%s/log.csv: changed while the table was made", rdir);
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
                am_text_put(&out.text, "%s,%ld,%.9g,%.9g,%ld\n", x->v[v].name, g_exp_evals[r], m, se, runs);
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
        if (snprintf(svg, sizeof svg, "%s/fitness.svg", dir) < (int)sizeof svg && tool_write_plot(1, dirs, svg)) return 1;
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
    am_text_put(t, "\nfolder = %s\nresults = %s/results.csv\nsummary = %s/summary.json\n", dir, dir, dir);
    return tool_out_close(&o, 1);
}

/* ---- bench --evolve ---- */

int tool_bench_evolve(long evaluations)
{
    char err[AM_ERR_MAX];
    am_evo_def d = am_default_evo();
    d.evaluations = evaluations;
    uint64_t hash[2] = {0, 0};
    double rate[2] = {0, 0};
    int cores = am_port_cores();
    printf("evolve_config=default (gmx, %dx%dx%d, population %d)\nevolve_evaluations=%ld\ncores=%d\n", d.geno.nx, d.geno.ny, d.geno.nz,
           d.population, evaluations, cores);
    for (int t = 1; t <= 2; t++) {
        if (am_evo_init(&tool_evo, &d, err, sizeof err) != AM_OK) return tool_usage_error("bench: %s", err);
        double t0 = am_port_now();
        long steps = 0, voxel_steps = 0;
        while (!am_evo_done(&tool_evo)) {
            if (am_evo_generation(&tool_evo, tool_work, t, NULL, err, sizeof err) != AM_OK) return tool_usage_error("bench: %s", err);
            steps += tool_evo.last_steps;
            voxel_steps += tool_evo.last_voxel_steps;
        }
        double el = am_port_now() - t0;
        rate[t - 1] = (double)tool_evo.evaluations / el * 3600.0;
        hash[t - 1] = am_evo_hash(&tool_evo);
        printf("threads=%d evaluations=%ld wall_s=%.2f evals_per_hour=%.0f mean_steps_per_eval=%.0f mean_voxels=%.0f "
               "voxel_steps_per_s=%.0f run_hash=%016llx\n",
               t, tool_evo.evaluations, el, rate[t - 1], (double)steps / (double)tool_evo.evaluations,
               steps ? (double)voxel_steps / (double)steps : 0.0, (double)voxel_steps / el, (unsigned long long)hash[t - 1]);
    }
    printf("speedup_2_threads=%.2f\nhours_for_20000_evals_2_threads=%.2f\nsame_hash=%s\n", rate[1] / rate[0], 20000.0 / rate[1],
           hash[0] == hash[1] ? "yes" : "NO");
    return hash[0] == hash[1] ? 0 : 1;
}

/* ---- repro: the reference evolution of `make repro` ---- */

static const char repro_help[] =
    "usage: amorph repro [--KEY VALUE]...\n"
    "Runs the reference evolution of `make repro` in memory (no files) and prints one line\n"
    "repro_hash=<16 hex digits>: the run hash over every genome, fitness and final simulation\n"
    "state of the run. Every build on every platform must print the same value. The reference\n"
    "run: GMX, 6^3 workspace, population 8, 24 evaluations, 1 cycle of 100 steps after at most\n"
    "150 steps of relaxation; flags (configuration keys) change it.\n";

int cmd_repro(int argc, char** argv)
{
    evo_opts o;
    memset(&o, 0, sizeof o);
    static const char* const ref[][2] = {
        {"representation", "gmx"}, {"workspace", "6"}, {"population", "8"}, {"evaluations", "24"}, {"cycles", "1"},
        {"period_steps", "100"}, {"relax_min_steps", "50"}, {"relax_max_steps", "150"}, {"gmx_points", "12"},
        {"seed", "2024"}, {"threads", "1"},
    };
    for (size_t k = 0; k < sizeof ref / sizeof ref[0]; k++) {
        o.key[o.nflags] = ref[k][0];
        o.val[o.nflags++] = ref[k][1];
    }
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            fputs(repro_help, stdout);
            return 0;
        }
        const char* a = argv[i];
        int r = parse_common(argc, argv, &i, &o, "repro");
        if (r < 0) return 2;
        if (r == 0 || o.config || o.out || o.resume || o.print_config)
            return tool_usage_error("repro: unknown option '%s' (amorph repro --help)", a);
    }
    am_evo_def d;
    if (build_def(&o, NULL, NULL, &d, "repro")) return 2;
    char err[AM_ERR_MAX];
    if (am_evo_init(&tool_evo, &d, err, sizeof err) != AM_OK) return tool_usage_error("repro: %s", err);
    const double t0 = am_port_now();
    while (!am_evo_done(&tool_evo))
        if (am_evo_generation(&tool_evo, tool_work, workers_of(&d), NULL, err, sizeof err) != AM_OK) {
            fprintf(stderr, "amorph: repro: %s\n", err);
            return 1;
        }
    long voxel_steps = 0;
    for (int i = 0; i < d.population; i++) voxel_steps += (long)tool_evo.pop[i].voxels * tool_evo.pop[i].steps;
    printf("evaluations=%ld generations=%ld best_fitness=%.9g final_population_voxel_steps=%ld wall_s=%.2f\n", tool_evo.evaluations,
           tool_evo.generation, tool_evo.best.fitness, voxel_steps, am_port_now() - t0);
    printf("repro_hash=%016llx\n", (unsigned long long)am_evo_hash(&tool_evo));
    return 0;
}
