/* tools/evolve_cmd.h: what amorph evolve, experiment and repro share: the options, the run loop,
 * and the run folder (tools/run_open.c, tools/run_dir.c). Each function returns an exit status (0, 1 at run time, 2
 * for bad input, 130 interrupted) after a one-line message, unless its comment says otherwise. */
#ifndef AMORPH_TOOLS_EVOLVE_CMD_H
#define AMORPH_TOOLS_EVOLVE_CMD_H

#include "cmd.h"

#if defined(AM_PROFILE_BOARD)
#define EXP_ROWS 64             /* generations an experiment's table reads per run */
#define EXP_MAX_RUNS 4          /* runs per variant */
#define EXP_DIR_MAX 256         /* an experiment folder's name */
#define EXP_RUN_DIR_MAX 384     /* a run folder's name */
#define EXP_WAVE AM_EVO_WAVE_MAX /* runs evolved in lockstep (one am_evo each): 1 */
#else
#define EXP_ROWS 4096
#define EXP_MAX_RUNS 16
#define EXP_DIR_MAX 1024
#define EXP_RUN_DIR_MAX 2048
#define EXP_WAVE AM_EVO_WAVE_MAX /* 16 */
#endif

/* ---- options (tools/cmd_evolve.c) ---- */

typedef struct evo_opts {
    const char* config;       /* --config FILE */
    const char* out;          /* --out DIR */
    const char* resume;       /* --resume DIR */
    int print_config, quiet, pictures, json;
    int nflags;
    const char* key[64];      /* KEY VALUE flags in order */
    const char* val[64];
} evo_opts;

/* one option at argv[*i]; 1 when consumed, 0 when unknown, 2 after an error message */
int parse_common(int argc, char** argv, int* i, evo_opts* o, const char* cmd);
/* defaults (am_default_evo, or am_stored_evo when stored: `config` is a run folder's config.txt),
 * then the config file (o->config, else `config` when not NULL), then the flags, then `extra` more
 * (keys and values, NULL-terminated; may be NULL) */
int build_def(const evo_opts* o, const char* config, const char* const* extra, int stored, am_evo_def* d, const char* cmd);
/* the workers a run uses (threads, 0: all cores) */
int workers_of(const am_evo_def* d);
/* reads AMORPH_TEST_INTERRUPT (docs/evolve.md, Testing interruptions) */
int test_interrupt_setup(void);

/* ---- runs (tools/cmd_evolve.c) ---- */

/* evals.csv: one row per evaluation, appended as the library places each batch */
typedef struct evals_out {
    const char* dir;
    const am_evo_def* def;
    int failed;               /* 1 after a row could not be written (reported once) */
} evals_out;

/* one run of a wave: runs evolved in lockstep, the offspring of all of them evaluated in one
 * parallel map per generation (amorph experiment; amorph evolve is a wave of one) */
typedef struct run_slot {
    am_evo* e;                /* the run (opened by open_start or open_resume) */
    const char* dir;          /* its folder (valid while the wave runs) */
    const char* label;        /* prefix of its progress line, or NULL */
    evals_out eo;             /* the rest is run_wave's */
    double last_ckpt;
    int dirty;
} run_slot;
/* starting and resuming (tools/run_open.c): a new run in dir: the folder made and locked, its first files written, e initialised; 0, 1 or 2 */
int open_start(am_evo* e, const am_evo_def* d, const char* dir);
/* the run in dir locked and loaded into e, checked against the flags o and `extra` keys and
 * values, its tables cut back to its checkpoint; 0, 1 or 2 */
int open_resume(am_evo* e, const char* dir, const evo_opts* o, const char* const* extra);
/* the n (1..EXP_WAVE) runs of s to their ends together, then their summaries; 0, 1, or 130 when
 * interrupted (every run's checkpoint written). The locks stay held (am_port_unlock). */
int run_wave(tool_ctx* c, run_slot* s, int n, int quiet);

/* ---- the run folder (tools/run_dir.c) ---- */

/* dir/file into out; 1 when it fits (a path too long is cut, and then fails to open with its name) */
int path_join(char* out, size_t cap, const char* dir, const char* file);
/* dir/file written atomically with len bytes of text */
int write_text(const char* dir, const char* file, const char* text, long len);
int write_config(const char* dir, const am_evo_def* d);
int write_checkpoint(const char* dir, const am_evo* e);
/* best.genome and best.lattice of c->evo */
int write_best(am_evo_work* w, const am_evo* e, const char* dir);
/* dir/summary.txt (a comment line, then key = value lines) and dir/summary.json (one JSON object),
 * both of the fields put(q, ctx) writes */
int write_summaries(const char* dir, const char* comment, void (*put)(tool_rec* q, const void* ctx), const void* ctx);
/* where a run's steps go (tools/account.c): relaxation and movement, and the evaluations that buy no
 * score (diverged, unsettled) or a result the run had (a body evaluated before, recognised by its
 * final state hash in a table of ACCOUNT_SET entries; not on the board). Shares are of voxel-steps,
 * which is the share of the simulator's time (its cost per voxel-step does not depend on the body:
 * docs/benchmarks.md). Large on the desktop: inside tool_ctx or static. */
#if defined(AM_PROFILE_BOARD)
#define ACCOUNT_SET 1
#else
#define ACCOUNT_SET (1L << 18)
#endif
typedef struct step_account {
    long evaluations, empty, diverged, unsettled, repeats;
    long relax_steps, move_steps;                /* summed over the simulated evaluations */
    double voxel_steps, relax_voxel_steps;       /* each step times the body's voxels */
    double diverged_voxel_steps, unsettled_voxel_steps, repeat_voxel_steps;
    long tracked, distinct;                      /* evaluations the repeat table saw; hashes in it */
    uint64_t set[ACCOUNT_SET];                   /* final state hashes seen (0: a free slot) */
} step_account;
void account_begin(step_account* a);
/* one evaluation (an evals.csv row's fields) */
void account_add(step_account* a, long voxels, int empty, int diverged, int settled, long relax_steps, long steps, uint64_t hash);
/* every row of dir/evals.csv (after account_begin): 0, or -1 when it cannot be read (no message) */
int account_read_evals(step_account* a, const char* dir);
/* the account's summary fields */
void account_put(tool_rec* q, const step_account* a);
/* the evaluations that took a remembered result instead of a simulation (am_evo.reused) and their
 * share of the account's voxel-steps (a may be NULL: the count alone) */
void account_put_reuse(tool_rec* q, const step_account* a, const am_evo* e);
/* a run's summary fields (summary.txt, summary.json and the final output); acct may be NULL */
void put_summary(tool_rec* q, const am_evo* e, const char* dir, double wall, const step_account* acct);
/* a run's summary.txt and summary.json */
int write_summary(const char* dir, const am_evo* e, double wall, const step_account* acct);
/* one row of log.csv */
int append_log(const char* dir, const am_evo_stats* s);
/* dir/file (a table with header hdr) checked to hold its first `rows` rows, and cut back to them
 * when cut is 1 (cut 0 writes nothing); one row short, it is mended with `last` when not NULL.
 * 0, 2 for a damaged table, 1 when it cannot be written */
int trim_table(const char* dir, const char* file, const char* hdr, long rows, const char* unit, int cut, const char* last);
/* the rows after the header of dir/file (a half row counted), or -1 when it cannot be read */
long table_rows(const char* dir, const char* file);
/* dir's log.csv and evals.csv (those there) flushed to the storage (am_port_sync_file) */
int sync_tables(const char* dir);
/* a folder, FIFO or device where the run in dir replaces a file is refused: the first n of its
 * files (6: config, checkpoint, best genome and lattice, summaries; 9: its pictures too;
 * tools/run_open.c) */
int refuse_planted(const char* dir, int n);
/* the am_evo_hooks.evaluated callback: one row of evals.csv (ctx: an evals_out) */
void evals_append(void* ctx, const am_evo_ind* ind, const am_evo_eval* ev);
/* the header of a run's evals.csv, with its newline; its length */
int evals_header(const am_evo_def* d, char* buf, int cap);
/* a fresh folder name runs/run-NNN */
int default_out(char* out, size_t cap);
/* a new run's files in dir (made and locked): configuration, log headers, first checkpoint */
int start_prepare(am_evo* e, const am_evo_def* d, const char* dir);
/* the folder's lock (one process at a time), taken without writing (am_port_lock_stamp does) */
int lock_run(const char* dir);
/* 1 when dir holds a lock file already */
int run_has_lock(const char* dir);
/* the stale temporaries of atomic writes in dir removed (a warning when one cannot be); no status */
void remove_stale(const char* dir);
/* the checkpoint at path read into e */
int read_checkpoint(const char* path, am_evo* e);

#endif
