/* The run folder of amorph evolve: its files, their writers, the tables (log.csv, evals.csv) and
 * how a resume cuts them back, the checkpoint reader, the first files of a new run, and the lock
 * that keeps a second process out. */
#include "evolve_cmd.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- run folder ---- */

/* dir/file into out; a path too long for out is cut (and then fails to open, with its name) */
int path_join(char* out, size_t cap, const char* dir, const char* file)
{
    int n = snprintf(out, cap, "%s/%s", dir, file);
    return n >= 0 && (size_t)n < cap;
}

TOOL_NOINLINE int write_text(const char* dir, const char* file, const char* text, long len)
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
static TOOL_NOINLINE int write_stream(const char* dir, const char* file, am_text_writer fn, const void* obj, const char* what)
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

int write_config(const char* dir, const am_evo_def* d)
{
    return write_stream(dir, AM_RUN_CONFIG, config_writer, d, NULL);
}

/* log.csv and evals.csv (those there) flushed to the storage, so that the checkpoint written next
 * never counts a row that a power cut could take back: 0, or 1 after a message */
TOOL_NOINLINE int sync_tables(const char* dir)
{
    static const char* const tables[] = {AM_RUN_LOG, AM_RUN_EVALS};
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    for (int k = 0; k < 2; k++) {
        path_join(path, sizeof path, dir, tables[k]);
        if (am_port_exists(path) && am_port_sync_file(path, err, sizeof err) != AM_OK) {
            fprintf(stderr, "amorph: %s\n", err);
            return 1;
        }
    }
    return 0;
}

int write_checkpoint(const char* dir, const am_evo* e)
{
    return write_stream(dir, AM_RUN_CHECKPOINT, checkpoint_writer, e, "checkpoint");
}

TOOL_NOINLINE int write_best(am_evo_work* w, const am_evo* e, const char* dir)
{
    char err[AM_ERR_MAX];
    if (write_stream(dir, AM_RUN_BEST_GENOME, genome_writer, &e->best.genome, "best genome")) return 1;
    if (am_evo_lattice(&e->def, &e->palette, &e->best.genome, &w->geno, &w->lattice, err, sizeof err) != AM_OK) {
        fprintf(stderr, "amorph: best lattice: %s\n", err);
        return 1;
    }
    return write_stream(dir, AM_RUN_BEST_LATTICE, lattice_writer, &w->lattice, "best lattice");
}

/* a run's summary as a record: the same fields in summary.txt, summary.json and the final output */
void put_summary(tool_rec* q, const am_evo* e, const char* dir, double wall, const step_account* acct)
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
    if (acct) account_put(q, acct);
    account_put_reuse(q, acct, e);
    tool_rec_num(q, "wall_s", wall);
    char build[64];
    snprintf(build, sizeof build, "%s %s", AM_REAL_NAME, AM_PROFILE_NAME);
    tool_rec_str(q, "build", build);
}

/* dir/summary.txt (a comment line, then key = value lines) and dir/summary.json (one JSON
 * object), both of the fields put(q, ctx) writes; 0, or 1 after a message */
TOOL_NOINLINE int write_summaries(const char* dir, const char* comment, void (*put)(tool_rec* q, const void* ctx), const void* ctx)
{
    for (int json = 0; json < 2; json++) {
        char path[TOOL_PATH_MAX];
        path_join(path, sizeof path, dir, json ? AM_RUN_SUMMARY_JSON : AM_RUN_SUMMARY_TXT);
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
    const step_account* acct;
} run_summary;

static void put_run_summary(tool_rec* q, const void* ctx)
{
    const run_summary* r = (const run_summary*)ctx;
    put_summary(q, r->e, r->dir, r->wall, r->acct);
}

int write_summary(const char* dir, const am_evo* e, double wall, const step_account* acct)
{
    const run_summary r = {e, dir, wall, acct};
    return write_summaries(dir, "amorph evolve summary", put_run_summary, &r);
}

TOOL_NOINLINE int append_log(const char* dir, const am_evo_stats* s)
{
    char row[256], path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    int n = am_evo_log_row(s, row, (int)sizeof row - 1);
    row[n++] = '\n';
    path_join(path, sizeof path, dir, AM_RUN_LOG);
    if (am_port_append_file(path, row, n, err, sizeof err) != AM_OK) {
        fprintf(stderr, "amorph: %s\n", err);
        return 1;
    }
    return 0;
}

/* dir/file (a table: log.csv or evals.csv with header hdr) cut back to the header and the first
 * `rows` rows (rows the checkpoint has seen, `unit` its count's name in messages): the file is
 * read line by line, then, when it holds more and cut is 1, copied that far into its replacement
 * (cut 0 only checks it, writing nothing). A table one row short of the checkpoint (a crash took
 * back a row the checkpoint counts, or left half of it) is whole again with `last` (the row the
 * checkpoint can give, without its newline; NULL when it cannot). 0, 2 for a damaged table, 1
 * when the replacement cannot be written */
TOOL_NOINLINE int trim_table(const char* dir, const char* file, const char* hdr, long rows, const char* unit, int cut, const char* last)
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
    const int mend = have == rows - 1 && last != NULL;
    if (have < rows && !mend) {
        tool_src_close(&src);
        return tool_usage_error("%s: %ld whole rows, but the checkpoint counts %ld %ss: the rows a crash took back cannot be rebuilt, "
                                "so the run cannot go on (its files are left as they are)",
                                path, have, rows, unit);
    }
    if ((!more && !mend) || !cut) {
        tool_src_close(&src);
        return 0;
    }
    tool_out o;
    if (tool_src_rewind(&src, err, sizeof err) != AM_OK) {
        tool_src_close(&src);
        return tool_usage_error("%s", err);
    }
    if (tool_out_open(&o, path)) {
        tool_src_close(&src);
        return 1;
    }
    for (long k = 0; k <= have && tool_src_next(&src, &line, &n, err, sizeof err) == 1; k++) {
        am_text_write(&o.text, line, n);
        am_text_write(&o.text, "\n", 1);
    }
    tool_src_close(&src);
    if (mend) {
        am_text_write(&o.text, last, (long)strlen(last));
        am_text_write(&o.text, "\n", 1);
    }
    return tool_out_close(&o, 1);
}

/* the rows after the header of dir/file (a half row counted), or -1 when it cannot be read */
TOOL_NOINLINE long table_rows(const char* dir, const char* file)
{
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX], *line;
    long n, rows = -1;
    int r;
    path_join(path, sizeof path, dir, file);
    if (!am_port_exists(path)) return -1;
    tool_src src;
    if (tool_src_open(&src, path, TOOL_FILE_MAX, 1, err, sizeof err) != AM_OK) return -1;
    while ((r = tool_src_next(&src, &line, &n, err, sizeof err)) == 1) rows++;
    tool_src_close(&src);
    return r < 0 ? -1 : rows < 0 ? 0 : rows;
}

void evals_append(void* ctx, const am_evo_ind* ind, const am_evo_eval* ev)
{
    evals_out* o = (evals_out*)ctx;
    char row[AM_EVO_EVALS_ROW_MAX + 1], path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    if (o->failed) return;
    int n = am_evo_evals_row(o->def, ind, ev, row, (int)sizeof row - 1);
    row[n++] = '\n';
    path_join(path, sizeof path, o->dir, AM_RUN_EVALS);
    if (am_port_append_file(path, row, n, err, sizeof err) != AM_OK) {
        fprintf(stderr, "amorph: %s\n", err);
        o->failed = 1;
    }
}

/* the header of a run's evals.csv, with its newline; returns its length */
int evals_header(const am_evo_def* d, char* buf, int cap)
{
    int n = am_evo_evals_header(d->geno.materials, buf, cap - 1);
    buf[n++] = '\n';
    buf[n] = 0;
    return n;
}

/* a fresh folder name under runs/, the folder made: a name that exists (a link to nothing too,
 * which am_port_exists does not see, but the making of the folder does) is someone else's, and
 * the next one is tried; after 100 names in a row that cannot be made, the first failure is
 * reported (a folder that cannot be made at all: the board's host without the folder) */
int default_out(char* out, size_t cap)
{
    char err[AM_ERR_MAX], first[AM_ERR_MAX];
    if (am_port_make_dir("runs", err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
    int failed = 0;
    for (int k = 1; k < 100000 && failed < 100; k++) {
        snprintf(out, cap, "runs/run-%03d", k);
        if (am_port_exists(out)) continue;
        if (am_port_make_dir(out, err, sizeof err) == AM_OK) return 0;
        if (!failed++) snprintf(first, sizeof first, "%s", err);
    }
    if (failed) return tool_usage_error("%s", first);
    return tool_usage_error("runs/: no free run-NNN name left");
}


/* a new run in dir (made and locked by the caller): its configuration, log headers and first
 * checkpoint; 0, 1 or 2. A run exists once its first checkpoint does (written before any
 * evaluation): a folder with the other files but no checkpoint was left by a run stopped before
 * it, and is started over. */
TOOL_NOINLINE int start_prepare(am_evo* e, const am_evo_def* d, const char* dir)
{
    char err[AM_ERR_MAX], path[TOOL_PATH_MAX];
    path_join(path, sizeof path, dir, AM_RUN_CHECKPOINT);
    if (am_port_exists(path)) return tool_usage_error("%s holds a run already: continue it with --resume %s, or choose another --out", dir, dir);
    if (am_evo_init(e, d, err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
    if (write_config(dir, d)) return 1;
    char hdr[AM_EVO_EVALS_ROW_MAX + 2];
    int n = snprintf(hdr, sizeof hdr, "%s\n", am_evo_log_header());
    if (write_text(dir, AM_RUN_LOG, hdr, n)) return 1;
    n = evals_header(d, hdr, (int)sizeof hdr);
    if (write_text(dir, AM_RUN_EVALS, hdr, n)) return 1;
    /* a checkpoint before the first evaluation: a run stopped at any moment can be resumed */
    if (write_checkpoint(dir, e)) return 1;
    return 0;
}


/* owns the run folder dir (its `lock` file) while this process works in it: a second process on
 * the same folder is refused. Taking it writes nothing into an existing lock file (the caller
 * stamps it with am_port_lock_stamp once it has accepted the work); a `lock` that is a link, or
 * not a regular file, is refused. 0, or 2 after a message */
TOOL_NOINLINE int lock_run(const char* dir)
{
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    path_join(path, sizeof path, dir, AM_RUN_LOCK);
    am_status st = am_port_lock(path, err, sizeof err);
    if (st == AM_ERR_IO) return tool_usage_error("%s (another amorph is working in %s: wait for it to end, or stop it)", err, dir);
    if (st != AM_OK) return tool_usage_error("%s", err);
    return 0;
}

/* 1 when dir holds a lock file already (a run's, or a run's start) */
int run_has_lock(const char* dir)
{
    char path[TOOL_PATH_MAX];
    path_join(path, sizeof path, dir, AM_RUN_LOCK);
    return am_port_exists(path);
}


/* removes the temporaries that a process killed during an atomic write left in dir (the port's
 * am_port_remove_stale; the caller holds the folder's lock). One that cannot be removed is only a
 * warning: it is never read, and the run goes on. */
TOOL_NOINLINE void remove_stale(const char* dir)
{
    char err[AM_ERR_MAX];
    if (am_port_remove_stale(dir, NULL, err, sizeof err) != AM_OK) fprintf(stderr, "amorph: warning: %s\n", err);
}


/* reads the checkpoint at path into e, in the two passes of the library (the checksum over the
 * bytes, then the lines): 0, or 2 after a message */
TOOL_NOINLINE int read_checkpoint(const char* path, am_evo* e)
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

/* ---- reading a run folder (amorph sim, render, view, export of its best robot; --resume) ---- */

int tool_is_run_dir(const char* path)
{
    char p[TOOL_PATH_MAX];
    if (snprintf(p, sizeof p, "%s/" AM_RUN_CONFIG, path) >= (int)sizeof p) return 0;
    if (!am_port_exists(p)) return 0;
    if (snprintf(p, sizeof p, "%s/" AM_RUN_BEST_GENOME, path) >= (int)sizeof p) return 0;
    return am_port_exists(p);
}

typedef struct config_ctx {
    am_evo_def* d;
    const char* fname;
    int* key_line;
    uint8_t seen[AM_EVO_KEY_MAX]; /* 1: key k set by a line already */
} config_ctx;

/* one line of a configuration file; a key set twice is an error at its second line (which of two
 * values was meant is not the program's guess) */
static am_status config_line(void* ctx, int lineno, char* line, long n, char* err, int errsz)
{
    config_ctx* c = (config_ctx*)ctx;
    const int key = am_evo_line_key(line, n);
    const int known = key >= 0 && key < AM_EVO_KEY_MAX;
    if (known && c->seen[key]) {
        if (c->key_line)
            return am_fail(err, errsz, AM_ERR_PARSE, "%s:%d: %s set again (first on line %d): say it once", c->fname, lineno,
                           am_evo_key_name(key), c->key_line[key]);
        return am_fail(err, errsz, AM_ERR_PARSE, "%s:%d: %s set again: say it once", c->fname, lineno, am_evo_key_name(key));
    }
    am_status st = am_evo_parse_line(c->d, line, n, c->fname, lineno, err, errsz);
    if (st == AM_OK && known) {
        c->seen[key] = 1;
        if (c->key_line) c->key_line[key] = lineno;
    }
    return st;
}

am_status tool_read_config(const char* path, am_evo_def* d, int nul_ends, char* err, int errsz)
{
    return tool_read_config_lines(path, d, nul_ends, NULL, err, errsz);
}

am_status tool_read_config_lines(const char* path, am_evo_def* d, int nul_ends, int* key_line, char* err, int errsz)
{
    tool_src src;
    am_status st = tool_src_open(&src, path, TOOL_FILE_MAX, nul_ends, err, errsz);
    if (st == AM_OK) {
        config_ctx c = {d, path, key_line, {0}};
        st = tool_src_each(&src, config_line, &c, err, errsz);
    } else if (src.binary) {
        st = tool_src_binary(&src, err, errsz);
    }
    tool_src_close(&src);
    return st;
}

static am_status genome_line(void* ctx, int lineno, char* line, long n, char* err, int errsz)
{
    (void)lineno;
    return am_genome_read_line((am_genome_reader*)ctx, line, n, err, errsz);
}

am_status tool_read_genome(tool_src* src, am_genome* g, char* err, int errsz)
{
    am_genome_reader r;
    am_genome_read_begin(&r, g, src->path);
    am_status st = tool_src_each(src, genome_line, &r, err, errsz);
    return st != AM_OK ? st : am_genome_read_end(&r, err, errsz);
}
