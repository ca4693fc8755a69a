/* amorph evolve: options shared with experiment and repro, the run loop (progress, testing
 * interruptions), the command; starting and resuming a run in its folder is tools/run_open.c. */
#include "evolve_cmd.h"
#include "robot.h"

#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
    "  --no-reuse         simulate every body, also one the run has simulated before (the results\n"
    "                     are the same either way: docs/evolve.md, Same body, same result)\n"
    "The run folder holds config.txt, log.csv, evals.csv (a row per evaluation), best.genome,\n"
    "best.lattice, checkpoint.txt, lock (one process at a time), and at the end summary.txt,\n"
    "summary.json, best.png (filmstrip), best.html (viewer) and fitness.svg.\n"
    "Ctrl-C stops after the current evaluations; --resume continues exactly.\n";


/* ---- options shared by evolve and experiment ---- */

/* one option at argv[*i]; returns 1 when consumed, 0 when unknown, 2 after an error message */
int parse_common(int argc, char** argv, int* i, evo_opts* o, const char* cmd)
{
    const char* a = argv[*i];
    if (strncmp(a, "--", 2) != 0) return 0;
    /* the settings: the configuration keys, as every command spells them (tools/robot.h) */
    const char *key, *val;
    int r = tool_setting_arg(cmd, argc, argv, i, &key, &val);
    if (r == 2) return 2;
    if (r == 1) {
        if (o->nflags == 64) {
            tool_usage_error("%s: too many settings on the command line", cmd);
            return 2;
        }
        o->key[o->nflags] = key;
        o->val[o->nflags++] = val;
        return 1;
    }
    const char* name = a + 2;
    const char* v = *i + 1 < argc ? argv[*i + 1] : NULL;
    char norm[64];
    const char* eq = strchr(name, '=');
    size_t n = eq ? (size_t)(eq - name) : strlen(name);
    if (n >= sizeof norm) return 0;
    memcpy(norm, name, n);
    norm[n] = 0;
    for (char* p = norm; *p; p++)
        if (*p == '-') *p = '_';
    if (eq) v = eq + 1;
    if (!strcmp(norm, "quiet")) o->quiet = 1;
    else if (!strcmp(norm, "no_pictures")) o->pictures = 0;
    else if (!strcmp(norm, "json")) o->json = 1;
    else if (!strcmp(norm, "print_config")) o->print_config = 1;
    else if (!strcmp(norm, "config") || !strcmp(norm, "out") || !strcmp(norm, "resume")) {
        if (!v || (!eq && !strncmp(v, "--", 2))) {
            tool_usage_error("%s: --%s needs a value", cmd, norm);
            return 2;
        }
        if (!eq) (*i)++;
        if (!strcmp(norm, "config")) o->config = v;
        else if (!strcmp(norm, "out")) o->out = v;
        else o->resume = v;
    } else return 0;
    return 1;
}

/* key (a flag's) set after the config file: no line of the file holds its value any more */
static void flag_set(int* key_line, const char* key)
{
    char t[80];
    int n = snprintf(t, sizeof t, "%s =", key);
    const int k = n > 0 && n < (int)sizeof t ? am_evo_line_key(t, n) : -1;
    if (k >= 0 && k < AM_EVO_KEY_MAX) key_line[k] = 0;
}

/* defaults, then the config file (o->config, else `config` when not NULL), then the flags, then
 * `extra` more (keys and values, NULL-terminated; may be NULL) */
TOOL_NOINLINE int build_def(const evo_opts* o, const char* config, const char* const* extra, int stored, am_evo_def* d, const char* cmd)
{
    char err[AM_ERR_MAX];
    int key_line[AM_EVO_KEY_MAX] = {0}; /* the config file's line that set each key; 0: a default or a flag */
    *d = stored ? am_stored_evo() : am_default_evo();
    if (o->config) config = o->config;
    if (config && tool_read_config_lines(config, d, 0, key_line, err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
    for (int k = 0; k < o->nflags; k++) {
        if (am_evo_set(d, o->key[k], o->val[k], err, sizeof err) != AM_OK) return tool_usage_error("%s: --%s", cmd, err);
        flag_set(key_line, o->key[k]);
    }
    for (int k = 0; extra && extra[k]; k += 2) {
        if (am_evo_set(d, extra[k], extra[k + 1], err, sizeof err) != AM_OK) return tool_usage_error("%s: --%s", cmd, err);
        flag_set(key_line, extra[k]);
    }
    /* a relation between keys: named with the file and line of the key's value when a file set it */
    int key;
    if (am_evo_check_key(d, &key, err, sizeof err) != AM_OK) {
        if (key >= 0 && key < AM_EVO_KEY_MAX && key_line[key] > 0) return tool_usage_error("%s:%d: %s", config, key_line[key], err);
        return tool_usage_error("%s: %s", cmd, err);
    }
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


/* ---- the loop ---- */

/* the progress line of a wave: one run's (labelled in an experiment), or the sums of several */
static TOOL_NOINLINE void progress(const run_slot* s, int n, double t_start, long evals_start, int final, double* last_line, int quiet)
{
    if (quiet) return;
    double now = am_port_now(), el = now - t_start;
    long done = 0, total = 0;
    double best = -1.0, mean = 0.0;
    for (int k = 0; k < n; k++) {
        const am_evo* e = s[k].e;
        done += e->evaluations;
        total += e->def.evaluations;
        if (e->last.best > best) best = e->last.best;
        mean += e->last.mean / (double)n;
    }
    double rate = el > 0 ? (double)(done - evals_start) / el : 0.0;
    double left = rate > 0 ? (double)(total - done) / rate : 0.0;
    if (left < 0) left = 0;
    char line[256], label[96];
    if (n == 1) snprintf(label, sizeof label, "%s%s", s[0].label ? s[0].label : "", s[0].label ? ": " : "");
    else snprintf(label, sizeof label, "%d runs: ", n);
    snprintf(line, sizeof line, "%sevaluations %ld/%ld  best %.4f m  mean %.4f m  %.2f eval/s  %.0f s left", label, done, total, best, mean,
             rate, left);
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
    int at_checkpoint;        /* 1: SIG:checkpoint:N, before the checkpoint at N evaluations */
    long after;               /* N */
    long base;                /* the run's evaluations before the generation under way */
    atomic_long started;      /* cancel polls (evaluations about to start) of that generation */
    atomic_int fired;
} g_test_int;

/* reads AMORPH_TEST_INTERRUPT (unset or empty: none); 0, or 2 after a one-line message */
TOOL_NOINLINE int test_interrupt_setup(void)
{
    static const struct {
        const char* name;
        am_port_signal sig;
    } sigs[] = {{"INT", AM_PORT_SIGINT}, {"TERM", AM_PORT_SIGTERM}, {"KILL", AM_PORT_SIGKILL}, {"STOP", AM_PORT_SIGSTOP}};
    const char* v = am_port_getenv("AMORPH_TEST_INTERRUPT");
    g_test_int.sig = (am_port_signal)0;
    if (!v || !*v) return 0;
    const char* colon = strchr(v, ':');
    const char* num = colon ? colon + 1 : NULL;
    const int at_checkpoint = num && !strncmp(num, "checkpoint:", 11);
    if (at_checkpoint) num += 11;
    for (size_t k = 0; colon && k < sizeof sigs / sizeof sigs[0]; k++)
        if (strlen(sigs[k].name) == (size_t)(colon - v) && !strncmp(v, sigs[k].name, (size_t)(colon - v)) &&
            tool_parse_long(num, 0, 1000000000L, &g_test_int.after)) {
            g_test_int.sig = sigs[k].sig;
            g_test_int.at_checkpoint = at_checkpoint;
            atomic_store(&g_test_int.fired, 0);
            return 0;
        }
    char shown[48];
    snprintf(shown, sizeof shown, "%s", v);
    for (char* c = shown; *c; c++)
        if ((unsigned char)*c < 32 || *c == 127) *c = '?'; /* the message stays one line */
    return tool_usage_error("AMORPH_TEST_INTERRUPT = '%s%s': expected SIG:N or SIG:checkpoint:N, SIG one of INT, TERM, KILL, STOP "
                            "and N a whole number of evaluations >= 0 (a test setting, docs/evolve.md)",
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
    if (g_test_int.sig && !g_test_int.at_checkpoint && !atomic_load(&g_test_int.fired) &&
        g_test_int.base + atomic_fetch_add(&g_test_int.started, 1) == g_test_int.after)
        test_interrupt_fire();
    return am_port_interrupted();
}

int workers_of(const am_evo_def* d)
{
    int w = d->threads > 0 ? d->threads : am_port_cores();
    if (w > AM_MAX_WORKERS) w = AM_MAX_WORKERS;
    return w < 1 ? 1 : w;
}

/* where the steps of the run in dir went, from its evals.csv (NULL when it cannot be read) */
static const step_account* run_account(const char* dir)
{
    static step_account acct; /* its table of hashes is large */
    return account_read_evals(&acct, dir) == 0 ? &acct : NULL;
}

/* ---- a wave: runs evolved in lockstep, their offspring evaluated in one parallel map ---- */

/* the merged map's scratch of a wave of several runs (am_evo_generations) */
#if EXP_WAVE > 1
static am_evo_wave g_wave;
#define WAVE_SCRATCH(n) ((n) > 1 ? &g_wave : NULL)
#else
#define WAVE_SCRATCH(n) NULL
#endif

/* run e's checkpoint in dir, after its tables: their rows flushed to the storage first, so that
 * a power cut never leaves a checkpoint that counts rows the tables lost (a test's point
 * SIG:checkpoint:N is taken between the two); 0 or 1 */
static int save_checkpoint(const char* dir, const am_evo* e)
{
    if (sync_tables(dir)) return 1;
    if (g_test_int.sig && g_test_int.at_checkpoint && e->evaluations == g_test_int.after) test_interrupt_fire();
    return write_checkpoint(dir, e);
}

/* after run k's generation: its log row, best robot and (when due) checkpoint; 0 or 1 */
static int after_generation(tool_ctx* c, run_slot* r, double best_before, int had_best)
{
    am_evo* e = r->e;
    if (r->eo.failed) return 1; /* the checkpoint stays behind: a resume cuts evals.csv back to it */
    if (append_log(r->dir, &e->last)) return 1;
    if ((!had_best || e->best.fitness != best_before) && write_best(&c->work[0], e, r->dir)) return 1;
    r->dirty = 1;
    double now = am_port_now();
    if (e->def.checkpoint_seconds == 0 || now - r->last_ckpt >= (double)e->def.checkpoint_seconds || am_evo_done(e)) {
        if (save_checkpoint(r->dir, e)) return 1;
        r->last_ckpt = now;
        r->dirty = 0;
    }
    return 0;
}

/* one generation of every unfinished run of the wave (am_evo_generations: their offspring in one
 * parallel map), then each run's files. 0, 1 after a message, or 130 when the generation was
 * cancelled (the runs it stopped are as before it) */
static int wave_generation(tool_ctx* c, run_slot* s, int n, int workers)
{
    char err[AM_ERR_MAX];
    double best_before[EXP_WAVE];
    int had_best[EXP_WAVE];
    long gen_before[EXP_WAVE], base = 0, after = 0;
    am_evo* runs[EXP_WAVE];
    am_evo_hooks hooks[EXP_WAVE];
    for (int k = 0; k < n; k++) {
        runs[k] = s[k].e;
        base += s[k].e->evaluations;
        best_before[k] = s[k].e->has_best ? s[k].e->best.fitness : 0.0;
        had_best[k] = s[k].e->has_best;
        gen_before[k] = s[k].e->generation;
        hooks[k] = (am_evo_hooks){run_cancel, evals_append, &s[k].eo};
    }
    g_test_int.base = base;
    atomic_store(&g_test_int.started, 0);
    const am_executor ex = tool_executor(workers);
    am_status st = am_evo_generations(runs, n, WAVE_SCRATCH(n), c->work, &ex, hooks, err, sizeof err);
    if (st != AM_OK && st != AM_ERR_CANCELLED) {
        fprintf(stderr, "amorph: %s\n", err);
        return 1;
    }
    for (int k = 0; k < n; k++) after += s[k].e->evaluations;
    /* a test's point inside this generation that no cancel poll saw (several batches) */
    if (st == AM_OK && g_test_int.sig && !g_test_int.at_checkpoint && !atomic_load(&g_test_int.fired) && base <= g_test_int.after &&
        g_test_int.after < after)
        test_interrupt_fire();
    for (int k = 0; k < n; k++)
        if (s[k].e->generation != gen_before[k] && after_generation(c, &s[k], best_before[k], had_best[k])) return 1;
    return st == AM_ERR_CANCELLED ? 130 : 0;
}

int run_wave(tool_ctx* c, run_slot* s, int n, int quiet)
{
    if (n < 1 || n > EXP_WAVE) return tool_usage_error("internal: a wave of %d runs (1 to %d)", n, EXP_WAVE);
    int workers = 1;
    const double t0 = am_port_now();
    long evals0 = 0;
    double last_line = t0;
    for (int k = 0; k < n; k++) {
        int w = workers_of(&s[k].e->def);
        if (w > workers) workers = w;
        evals0 += s[k].e->evaluations;
        s[k].last_ckpt = t0;
        s[k].dirty = 0;
        s[k].eo.dir = s[k].dir;
        s[k].eo.def = &s[k].e->def;
        s[k].eo.failed = 0;
    }
    int rc = 0;
    for (;;) {
        int done = 1;
        for (int k = 0; k < n; k++) done &= am_evo_done(s[k].e);
        if (done) break;
        rc = wave_generation(c, s, n, workers);
        if (rc) break;
        done = 1;
        for (int k = 0; k < n; k++) done &= am_evo_done(s[k].e);
        progress(s, n, t0, evals0, done, &last_line, quiet);
        if (am_port_interrupted()) break;
    }
    if (rc == 1) return 1;
    int unfinished = 0;
    for (int k = 0; k < n; k++) unfinished += !am_evo_done(s[k].e);
    if ((rc == 130 || am_port_interrupted()) && unfinished) {
        for (int k = 0; k < n; k++)
            if (s[k].dirty && save_checkpoint(s[k].dir, s[k].e)) return 1;
        am_port_progress(NULL);
        if (n == 1)
            fprintf(stderr, "amorph: interrupted after %ld evaluations (generation %ld); the checkpoint in %s stands.\n"
                            "amorph: resume with: amorph evolve --resume %s\n",
                    s[0].e->evaluations, s[0].e->generation, s[0].dir, s[0].dir);
        else
            fprintf(stderr, "amorph: interrupted with %d of %d runs unfinished; the checkpoint in each run folder stands.\n", unfinished, n);
        return 130;
    }
    for (int k = 0; k < n; k++)
        if (write_summary(s[k].dir, s[k].e, am_port_now() - t0, run_account(s[k].dir))) return 1;
    return 0;
}

/* the run's pictures: the best robot's filmstrip (best.png) and viewer page (best.html), and the
 * fitness plot (fitness.svg); builds without pictures (the board profile) skip them */
static int finish_pictures(tool_ctx* c, const char* dir)
{
#if !TOOL_PICTURES
    (void)c, (void)dir;
    return 0;
#else
    const am_evo* e = &c->evo;
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX], title[256];
    if (am_evo_express(&e->def, &e->palette, &e->best.genome, &c->work[0], err, sizeof err) != AM_OK) {
        fprintf(stderr, "amorph: best robot: %s\n", err);
        return 1;
    }
    /* the best robot: its body, its evolved phases and stiffnesses if it has them, the run's
     * environment and evaluation */
    am_robot best;
    am_robot_init(&best, &c->work[0].lattice, NULL);
#if AM_GENO_LAYERS
    if (c->work[0].has_layers) best.layers = &c->work[0].layers;
#endif
    best.env = e->def.env;
    best.eval = e->def.eval;
    best.eval.record = NULL;
    if (am_lattice_count(best.lattice) > 0) {
        path_join(path, sizeof path, dir, AM_RUN_BEST_PNG);
        if (tool_write_filmstrip(c, &best, path)) return 1;
        path_join(path, sizeof path, dir, AM_RUN_BEST_HTML);
        snprintf(title, sizeof title, "amorph: best of %.200s (%.4f m)", dir, e->best.fitness);
        if (tool_write_viewer(c, &best, title, path)) return 1;
    }
    path_join(path, sizeof path, dir, AM_RUN_FITNESS_SVG);
    char* dirs[1] = {(char*)(uintptr_t)dir};
    return tool_write_plot(1, dirs, path);
#endif
}


/* the run opened in c->evo (status rc of its opening) run to its end in dir, then its pictures;
 * its lock released; reuse 0: every body simulated (am_evo.memo_limit). 0, 1, 2 or 130 */
static int run_opened(tool_ctx* c, int rc, const char* dir, int quiet, int pictures, int reuse)
{
    if (rc == 0) {
        if (!reuse) c->evo.memo_limit = -1;
        run_slot s;
        memset(&s, 0, sizeof s);
        s.e = &c->evo;
        s.dir = dir;
        rc = run_wave(c, &s, 1, quiet);
        if (rc == 0 && pictures) rc = finish_pictures(c, dir);
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
    put_summary(&q, e, dir, wall, run_account(dir));
    tool_rec_end(&q);
    return tool_out_close(&o, 1);
}

int cmd_evolve(tool_ctx* c, int argc, char** argv)
{
    evo_opts o;
    int reuse = 1;
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
        if (!strcmp(argv[i], "--no-reuse")) {
            reuse = 0;
            continue;
        }
        int r = parse_common(argc, argv, &i, &o, "evolve");
        if (r == 2) return 2;
        if (r == 0) return tool_unknown_option("evolve", argv[i], evolve_help);
    }
    if (o.resume && o.out) return tool_usage_error("evolve: --resume DIR continues in DIR; --out does not apply");
    if (o.resume && o.config) return tool_usage_error("evolve: --resume reads the run's own config.txt; --config does not apply");
    am_evo_def d;
    if (!o.resume) {
        if (build_def(&o, NULL, NULL, 0, &d, "evolve")) return 2;
        if (o.print_config) {
            char err[AM_ERR_MAX];
            tool_out out;
            if (tool_out_open(&out, NULL)) return 1;
            am_evo_write(&d, 1, &out.text, err, sizeof err);
            return tool_out_close(&out, 1);
        }
        char err[AM_ERR_MAX];
        if (am_evo_check_run(&d, err, sizeof err) != AM_OK) return tool_usage_error("evolve: %s", err);
    } else if (o.print_config) return tool_usage_error("evolve: --print-config and --resume: print a run's settings with cat DIR/config.txt");
    char dir[EXP_DIR_MAX];
    if (strlen(o.resume ? o.resume : o.out ? o.out : "") >= sizeof dir) return tool_usage_error("evolve: folder name too long");
    if (test_interrupt_setup()) return 2;
    if (o.resume) snprintf(dir, sizeof dir, "%s", o.resume);
    else if (o.out) snprintf(dir, sizeof dir, "%s", o.out);
    else if (default_out(dir, sizeof dir)) return 2;
    /* a folder where a picture goes is found now, not after the evaluations */
    if (TOOL_PICTURES && o.pictures && refuse_planted(dir, 9)) return 2;
    am_port_catch_interrupt();
    const double t0 = am_port_now();
    int rc = run_opened(c, o.resume ? open_resume(&c->evo, dir, &o, NULL) : open_start(&c->evo, &d, dir), dir, o.quiet, o.pictures, reuse);
    if (rc == 0) rc = print_result(&c->evo, dir, am_port_now() - t0, o.json);
    return rc;
}

