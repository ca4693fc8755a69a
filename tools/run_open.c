/* Starting and resuming a run in its folder (amorph evolve, experiment and repro): the checks
 * before anything is written (a folder in use, a run already there, planted names, a resumed run's
 * settings and tables), then the folder made ready (tools/run_dir.c writes its files). */
#include "evolve_cmd.h"

#include <stdio.h>
#include <string.h>

/* the files a run replaces (a temporary renamed over each name): a folder, FIFO or device at one
 * of their names would fail that rename, at the end of the run for the summaries and pictures, so
 * it is refused before the first evaluation. The first `n` names: the run's own files (6), or
 * with its pictures (9). 0, or 2 after a message */
TOOL_NOINLINE int refuse_planted(const char* dir, int n)
{
    static const char* const names[] = {AM_RUN_CONFIG,      AM_RUN_CHECKPOINT,   AM_RUN_BEST_GENOME,
                                        AM_RUN_BEST_LATTICE, AM_RUN_SUMMARY_TXT, AM_RUN_SUMMARY_JSON,
                                        AM_RUN_BEST_PNG,     AM_RUN_BEST_HTML,    AM_RUN_FITNESS_SVG};
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    for (int k = 0; k < n && k < (int)(sizeof names / sizeof names[0]); k++) {
        path_join(path, sizeof path, dir, names[k]);
        am_port_stream st;
        if (!am_port_exists(path)) continue;
        if (am_port_open_read(path, &st, err, sizeof err) != AM_OK)
            return tool_usage_error("%s (the run replaces %s: move it away)", err, names[k]);
        am_port_close(st, 0, err, sizeof err);
    }
    return 0;
}

/* what a run folder without its checkpoint holds of a run: its tables' rows and a summary; 1 when
 * a table holds a row (the text then says so, for a message), else 0 */
static TOOL_NOINLINE int folder_holds(const char* dir, char* text, size_t cap)
{
    char path[TOOL_PATH_MAX];
    const long log_rows = table_rows(dir, AM_RUN_LOG), eval_rows = table_rows(dir, AM_RUN_EVALS);
    path_join(path, sizeof path, dir, AM_RUN_SUMMARY_TXT);
    snprintf(text, cap, "log.csv %ld rows (generations), evals.csv %ld rows (evaluations)%s", log_rows > 0 ? log_rows : 0,
             eval_rows > 0 ? eval_rows : 0, am_port_exists(path) ? ", and summary.txt (the run's end)" : "");
    return log_rows > 0 || eval_rows > 0;
}

/* dir holds a run already, or tables of one without their checkpoint, or a folder or device where
 * the run writes a file: --out is refused (nothing written) */
static int refuse_used(const char* dir)
{
    char path[TOOL_PATH_MAX], holds[192];
    path_join(path, sizeof path, dir, AM_RUN_CHECKPOINT);
    if (am_port_exists(path)) return tool_usage_error("%s holds a run already: continue it with --resume %s, or choose another --out", dir, dir);
    if (folder_holds(dir, holds, sizeof holds))
        return tool_usage_error("%s holds the tables of a run without its checkpoint (%s): a new run would overwrite them; keep them, "
                                "and choose another --out",
                                dir, holds);
    return refuse_planted(dir, 6);
}

/* A run folder is written only once the command is accepted: a folder in use by another process
 * is refused first (taking the lock of an existing lock file writes nothing), then the folder is
 * checked, and only then is the lock file made (when missing), stamped with this process's id and
 * the run's files written. */
int open_start(am_evo* e, const am_evo_def* d, const char* dir)
{
    char err[AM_ERR_MAX];
    const int locked = run_has_lock(dir);
    if (locked && lock_run(dir)) return 2;
    if (refuse_used(dir)) return 2;
    if (am_port_make_dir(dir, err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
    if (!locked && (lock_run(dir) || refuse_used(dir))) return 2;
    am_port_lock_stamp();
    /* what a process killed before the first checkpoint left: its files are started over, its
     * temporaries go */
    remove_stale(dir);
    return start_prepare(e, d, dir);
}

/* dir/log.csv checked (cut 0) or cut back (cut 1) to run e's checkpoint; one row short, it is
 * mended with the log row of the checkpoint's last generation (the checkpoint holds its figures).
 * trim_table's status */
static TOOL_NOINLINE int trim_log(const am_evo* e, const char* dir, int cut)
{
    char last[256];
    const int has_last = e->generation >= 1 && e->last.generation + 1 == e->generation && e->last.evaluations == e->evaluations;
    if (has_last) last[am_evo_log_row(&e->last, last, (int)sizeof last - 1)] = 0;
    return trim_table(dir, AM_RUN_LOG, am_evo_log_header(), e->generation, "generation", cut, has_last ? last : NULL);
}

/* --resume of a folder without its checkpoint whose tables hold rows: what it holds, in one line
 * (2); 0 when they hold none */
static TOOL_NOINLINE int refuse_no_checkpoint(const char* dir)
{
    char holds[192];
    if (!folder_holds(dir, holds, sizeof holds)) return 0;
    return tool_usage_error("--resume %s: no checkpoint.txt (missing, or a link to nothing), so the run cannot go on; the folder "
                            "holds what it did: %s: keep them (--out %s refuses to overwrite them), and start again in another folder",
                            dir, holds, dir);
}

/* 1 when the configuration file at path holds no setting (nothing, blank lines or comments) */
static TOOL_NOINLINE int config_empty(const char* path)
{
    char err[AM_ERR_MAX], *line;
    long n;
    int r, empty = 1;
    tool_src src;
    if (tool_src_open(&src, path, TOOL_FILE_MAX, 1, err, sizeof err) != AM_OK) return 0;
    while (empty && (r = tool_src_next(&src, &line, &n, err, sizeof err)) == 1) {
        const char* p = line;
        while (*p == ' ' || *p == '\t' || *p == '\r') p++;
        if (*p && *p != '#') empty = 0;
    }
    tool_src_close(&src);
    return empty;
}

/* loads the run in dir into e and checks it against the settings the user gives now (flags o,
 * then `extra` keys and values), its tables included; writes nothing. 0, 1 or 2 */
static TOOL_NOINLINE int resume_check(am_evo* e, const char* dir, const evo_opts* o, const char* const* extra)
{
    char path[TOOL_PATH_MAX], what[160];
    path_join(path, sizeof path, dir, AM_RUN_CONFIG);
    int started = am_port_exists(path) || run_has_lock(dir);
    path_join(path, sizeof path, dir, AM_RUN_LOG);
    started = started || am_port_exists(path);
    path_join(path, sizeof path, dir, AM_RUN_CHECKPOINT);
    if (!am_port_exists(path) && refuse_no_checkpoint(dir)) return 2;
    if (started && !am_port_exists(path))
        return tool_usage_error("--resume %s: no checkpoint.txt: the run stopped before its first checkpoint, so no evaluation was "
                                "done; start it again with --out %s",
                                dir, dir);
    int rc = read_checkpoint(path, e);
    if (rc) return rc;
    if (refuse_planted(dir, 6)) return 2;
    /* what the run folder's config.txt and today's flags say (an empty one says nothing: it is
     * not a change of settings, but a file that lost them) */
    path_join(path, sizeof path, dir, AM_RUN_CONFIG);
    if (config_empty(path))
        return tool_usage_error("--resume %s: %s is empty: the run's settings are not there (a run continues only with its own "
                                "settings: put the file back from a copy)",
                                dir, path);
    am_evo_def d;
    if (build_def(o, path, extra, 1, &d, "resume")) return 2;
    if (!am_evo_same_run(&e->def, &d, what, sizeof what))
        return tool_usage_error("--resume %s: the configuration changed: %s; a run continues only with its own settings", dir, what);
    e->def.evaluations = d.evaluations;
    e->def.threads = d.threads;
    e->def.checkpoint_seconds = d.checkpoint_seconds;
    if (e->def.evaluations < e->evaluations)
        return tool_usage_error("--resume %s: evaluations = %ld is below the %ld already done", dir, e->def.evaluations, e->evaluations);
    if ((rc = trim_log(e, dir, 0)) != 0) return rc;
    char hdr[AM_EVO_EVALS_ROW_MAX + 2];
    int n = evals_header(&e->def, hdr, (int)sizeof hdr);
    path_join(path, sizeof path, dir, AM_RUN_EVALS);
    hdr[n - 1] = 0;
    const int has_evals = am_port_exists(path);
    if (has_evals && (rc = trim_table(dir, AM_RUN_EVALS, hdr, e->evaluations, "evaluation", 0, NULL)) != 0) return rc;
    /* the tables are appended to: a link (or a file of several names) in their place is refused
     * now, before anything is written, not at the first row (appending nothing writes nothing) */
    char err[AM_ERR_MAX];
    path_join(path, sizeof path, dir, AM_RUN_LOG);
    if (am_port_append_file(path, "", 0, err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
    path_join(path, sizeof path, dir, AM_RUN_EVALS);
    if (has_evals && am_port_append_file(path, "", 0, err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
    return 0;
}

/* the accepted run e in dir made ready to go on: its tables cut back to its checkpoint, its
 * configuration written; 0, 1 or 2 */
static TOOL_NOINLINE int resume_prepare(const am_evo* e, const char* dir)
{
    char path[TOOL_PATH_MAX];
    int rc = trim_log(e, dir, 1);
    if (rc) return rc;
    char hdr[AM_EVO_EVALS_ROW_MAX + 2];
    int n = evals_header(&e->def, hdr, (int)sizeof hdr);
    path_join(path, sizeof path, dir, AM_RUN_EVALS);
    if (!am_port_exists(path)) {
        /* a run begun by a build without evals.csv: the table starts at the checkpoint's evaluation */
        if (write_text(dir, AM_RUN_EVALS, hdr, n)) return 1;
    } else {
        hdr[n - 1] = 0;
        if ((rc = trim_table(dir, AM_RUN_EVALS, hdr, e->evaluations, "evaluation", 1, NULL)) != 0) return rc;
    }
    if (write_config(dir, &e->def)) return 1;
    return 0;
}

/* as open_start: a folder in use is refused first (without writing), the run is checked, and
 * only an accepted run has its lock stamped and its files written */
int open_resume(am_evo* e, const char* dir, const evo_opts* o, const char* const* extra)
{
    const int locked = run_has_lock(dir);
    if (locked && lock_run(dir)) return 2;
    int rc = resume_check(e, dir, o, extra);
    if (rc) return rc;
    if (!locked && (lock_run(dir) || (rc = resume_check(e, dir, o, extra)) != 0)) return rc ? rc : 2;
    am_port_lock_stamp();
    rc = resume_prepare(e, dir);
    /* what a kill during a write left: the run's files are whole, their temporaries go */
    if (rc == 0) remove_stale(dir);
    return rc;
}

