/* tools/cmd.h: the subcommands of the amorph program and what they share.
 *
 * One return convention. A command (cmd_*) and every helper that returns `int` return the exit
 * status of the process: 0 success; 1 a failure at run time (a file that cannot be written, a
 * capacity reached while running); 2 bad input (flags, files, settings); 130 a run interrupted by
 * a signal (evolve, experiment). Any non-zero status has been told on stderr in one line before it
 * is returned, so callers pass it up unchanged (`if (rc) return rc;`). Helpers that cannot tell
 * the user (they hold no command name or are shared with the library) return an am_status with the
 * message in err instead, and the command prints it. Two kinds of function answer otherwise, each
 * the same way: tool_parse_* and tool_is_* answer a question (1 yes, 0 no); an option parser
 * (tool_*_arg, parse_common) returns 1 when it consumed argv[*i], 0 when that is not its option,
 * and the exit status 2 after its message; a line source (tool_src_next) returns 1 for a line, 0
 * at the end, -1 on a failure.
 *
 * State. The workspaces the commands share are one tool_ctx that main owns and passes down; no
 * tools/ file holds another global. A file's own scratch arrays (the pixels of a filmstrip, the
 * reading buffer of tools/files.c) are static in that file and used only while one call runs:
 * nothing in them carries from one call to the next. */
#ifndef AMORPH_TOOLS_CMD_H
#define AMORPH_TOOLS_CMD_H

#include <stddef.h>
#include <stdint.h>

#include "amorph.h"
#include "port.h"

/* the workspaces of the commands (they run one at a time), owned by main */
typedef struct tool_ctx {
    /* the evolver's evaluation workers; [0] also serves sim, bench, export, random, express and the
     * pictures, each job on its own members (geno to express, lattice for the robot a command
     * loads, model and state to simulate) */
    am_evo_work work[AM_MAX_WORKERS];
    /* the evolver's run (evolve, experiment, repro, bench --evolve); bench's expression timing
     * borrows the genomes of its population as its pool */
    am_evo evo;
#if !defined(AM_PROFILE_BOARD)
    /* the room for the per-cell layers (phases, stiffnesses, boundary conditions) of the robot a
     * command loads: tool_robot_load points its am_robot at it (tools/robot.h) */
    am_layers robot_layers;
#endif
} tool_ctx;

/* the genome a command reads (random, express, sim of a genome file or a run folder): the
 * evolver's best slot, idle in those commands (the board's RAM holds no second genome) */
static inline am_genome* tool_genome(tool_ctx* c) { return &c->evo.best.genome; }

int cmd_sim(tool_ctx* c, int argc, char** argv);
int cmd_bench(tool_ctx* c, int argc, char** argv);
/* the "build ..." line every benchmark starts with: number type, profile, vector extension, gathers */
void bench_print_build(void);
/* amorph bench --convergence [options] [ROBOT...], the options from argv[first] (tools/bench_converge.c) */
int bench_convergence(tool_ctx* c, int argc, char** argv, int first);
/* amorph bench --control (tools/bench_control.c): the cost of stepping under control against sim */
int tool_bench_control(tool_ctx* c, long steps, int repeat);
int cmd_random(tool_ctx* c, int argc, char** argv);
int cmd_express(tool_ctx* c, int argc, char** argv);
int cmd_render(tool_ctx* c, int argc, char** argv);
int cmd_plot(tool_ctx* c, int argc, char** argv);
int cmd_view(tool_ctx* c, int argc, char** argv);
int cmd_evolve(tool_ctx* c, int argc, char** argv);
int cmd_experiment(tool_ctx* c, int argc, char** argv);
int cmd_repro(tool_ctx* c, int argc, char** argv);
int cmd_export(tool_ctx* c, int argc, char** argv);
/* amorph stats: groups of run folders compared by Welch's t and Mann-Whitney (tools/cmd_stats.c, tools/stats_table.c, tools/stats.h) */
int cmd_stats(tool_ctx* c, int argc, char** argv);
/* amorph eval: robots as JSON lines on stdin, results as JSON lines (tools/cmd_eval.c, docs/embedding.md) */
int cmd_eval(tool_ctx* c, int argc, char** argv);
/* amorph report: the tables of docs/results.md from run folders' log.csv (tools/cmd_report.c) */
int cmd_report(tool_ctx* c, int argc, char** argv);

/* a run folder's and an experiment folder's file names and table rows: amorph/evo.h (AM_RUN_*,
 * AM_EXP_*); tools/run_dir.c writes and reads the files */

/* 1 when path is a run folder of amorph evolve (config.txt and best.genome) */
int tool_is_run_dir(const char* path);

/* keeps a helper's locals out of its caller's frame, so they take stack only while it runs, not
 * all through the long calls of the caller (the board's stack is small) */
#if defined(__GNUC__)
#define TOOL_NOINLINE __attribute__((noinline))
#else
#define TOOL_NOINLINE
#endif

/* the evolver's executor on this port: its parallel map on `workers` workers and its clock
 * (tools/executor.c) */
am_executor tool_executor(int workers);

/* prints "amorph: <message>" on stderr as one line and returns 2 */
int tool_usage_error(const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/* "amorph: CMD: unknown option 'ARG' (amorph CMD --help)", ARG quoted as every reader quotes
 * input (am_quote); with ": did you mean --FLAG?" before the parenthesis when a flag of the
 * command's help text (each --name it writes, and the configuration's keys when it points to
 * --help-config; NULL: none) is within a third of ARG's name in edit distance ('-' and '_' alike);
 * returns 2 */
int tool_unknown_option(const char* cmd, const char* arg, const char* help);

/* ---- results as key = value lines or one JSON object (tools/record.c) ---- */

/* in as the contents of a JSON string: quotes, backslashes and control bytes escaped, cut to cap */
void tool_json_escape(char* out, size_t cap, const char* in);
/* one record: tool_rec_begin, its fields in order, tool_rec_end. In text, "key = value" lines;
 * in JSON, one object on one line, numbers that are not finite written null */
typedef struct tool_rec {
    am_text* t;
    int json;
    int n;                      /* fields so far */
    const char* eq;             /* text: " = ", or "=" (tool_rec_begin_tight) */
} tool_rec;
void tool_rec_begin(tool_rec* r, am_text* t, int json);
/* text as a benchmark's name=value lines */
void tool_rec_begin_tight(tool_rec* r, am_text* t);
void tool_rec_num(tool_rec* r, const char* key, double v);   /* %.9g */
void tool_rec_int(tool_rec* r, const char* key, long v);
void tool_rec_str(tool_rec* r, const char* key, const char* v);
void tool_rec_hex(tool_rec* r, const char* key, uint64_t v);  /* 16 hex digits (a string in JSON) */
void tool_rec_nums(tool_rec* r, const char* key, const double* v, int n); /* space-separated; a JSON array */
void tool_rec_strs(tool_rec* r, const char* key, const char* const* v, int n); /* space-separated; a JSON array */
void tool_rec_end(tool_rec* r);

/* ---- text files (tools/files.c) ---- */

/* an output: text formatted into `text` goes through a small buffer into the file path (an
 * atomic replace: nothing changes at path before tool_out_close commits) or onto the standard
 * output (path NULL). One output is open at a time. */
#define TOOL_OUT_BUF 512        /* longer than any one piece the writers put */
typedef struct tool_out {
    am_text text;               /* format into this (am_text_put, am_genome_write, ...) */
    const char* path;           /* the file, or NULL for the standard output */
    am_port_stream stream;
    char err[AM_ERR_MAX];       /* the message of a failed write */
} tool_out;
/* 0, or 1 after a one-line message on stderr */
int tool_out_open(tool_out* o, const char* path);
/* commit 1: the rest of the text goes out and the file replaces path; commit 0 drops the file
 * (path stays as it was). 0, or 1 after a one-line message on stderr (the file is dropped then) */
int tool_out_close(tool_out* o, int commit);
/* writes text (len bytes) to the file out atomically, or to the standard output when out is NULL;
 * returns 0, or 1 after a one-line message on stderr */
int tool_write_output(const char* out, const char* text, long len);

/* a text file read line by line. The desktop profile reads the file whole into one buffer (at
 * most cap - 1 bytes, else AM_ERR_CAPACITY) and hands out its lines in place; the board profile
 * streams it through one buffer, so a line may hold at most TOOL_LINE_MAX characters (a longer
 * one is an error "file:line: line longer than ..."). Either way lines are cut at '\n' and a
 * last line without one counts. */
#if defined(AM_PROFILE_BOARD)
#define TOOL_WHOLE_FILES 0
#define TOOL_LINE_MAX 1023
#else
#define TOOL_WHOLE_FILES 1
#endif
typedef struct tool_src {
    const char* path;           /* the file (for messages); valid until closed */
    int line;                   /* lines handed out */
    int newline;                /* 1 when the last line handed out ended with '\n' */
    int binary;                 /* 1 when the file holds a NUL byte (status AM_ERR_PARSE, no message) */
    int nul_ends;               /* 1: a NUL byte ends the text instead (what a whole-text parser saw) */
    am_status st;               /* board: the failure that ended reading */
    long pos, end;              /* the next line and the end of the text (desktop) or of the buffer (board) */
    long restore;               /* desktop: where the last line's newline was cut, or -1 */
    int eof;                    /* board: the stream is at its end */
    am_port_stream stream;      /* board: the open file */
} tool_src;
/* opens path: AM_OK; the port's AM_ERR_IO or AM_ERR_CAPACITY with a message; AM_ERR_PARSE with
 * binary set (no message: tool_src_binary gives the usual one) for a NUL byte */
am_status tool_src_open(tool_src* s, const char* path, long cap, int nul_ends, char* err, int errsz);
/* the next line, NUL-terminated without its newline (*line, *n, valid until the next call; the
 * caller may change its bytes): 1; 0 at the end; -1 on a failure (message in err, or binary set) */
int tool_src_next(tool_src* s, char** line, long* n, char* err, int errsz);
/* back to the first line */
am_status tool_src_rewind(tool_src* s, char* err, int errsz);
void tool_src_close(tool_src* s);
/* "path:1: binary data (a NUL byte) in a text file" */
am_status tool_src_binary(const tool_src* s, char* err, int errsz);

/* "amorph: WHAT: not in this build: FEATURE belong to the desktop profile ..." on stderr; returns 2.
 * The board profile leaves out what a microcontroller has no use for (pictures, VXA files). */
int tool_not_in_build(const char* what, const char* feature);

/* what a text file holds, judged from its first meaningful lines as am_vxa_sniff and
 * am_genome_sniff judge a whole text: TOOL_TEXT_VXA, _GENOME or _LATTICE (anything else), or -1
 * when reading failed (message in err, or s->binary). The source is left at its start. */
enum { TOOL_TEXT_VXA = 1, TOOL_TEXT_GENOME = 2, TOOL_TEXT_LATTICE = 3 };
int tool_src_sniff(tool_src* s, char* err, int errsz);
/* calls fn for every remaining line of s (lineno counts from 1); the first failure: fn's status,
 * or the source's with its message */
typedef am_status (*tool_line_fn)(void* ctx, int lineno, char* line, long n, char* err, int errsz);
am_status tool_src_each(tool_src* s, tool_line_fn fn, void* ctx, char* err, int errsz);
/* a run's log.csv read row by row (am_evo_log_read_*): fn(ctx, fname, lineno, &row, ...) for each
 * row in order, the header and blank lines skipped; AM_OK, or the first failure (fn's, or the
 * file's or reader's with its "path:line: problem" message) (files.c) */
typedef am_status (*tool_log_row_fn)(void* ctx, const char* fname, int lineno, const am_evo_stats* row, char* err, int errsz);
am_status tool_log_each(const char* path, tool_log_row_fn fn, void* ctx, char* err, int errsz);
/* a configuration file over d (am_evo_parse_line per line); nul_ends as tool_src_open (run_dir.c) */
am_status tool_read_config(const char* path, am_evo_def* d, int nul_ends, char* err, int errsz);
/* the same, with the line that set each key (key_line[i] for am_evo_key_name(i), left as it is for
 * a key no line sets; capacity AM_EVO_KEY_MAX) */
am_status tool_read_config_lines(const char* path, am_evo_def* d, int nul_ends, int* key_line, char* err, int errsz);
/* a genome from the lines of src (its start) */
am_status tool_read_genome(tool_src* src, am_genome* g, char* err, int errsz);
/* the genome of src (at its start) into tool_genome(c), expressed into lat with the palette pal
 * (NULL: the built-in one; tools/robot.c); "file:line: problem" messages */
am_status tool_genome_to_lattice(tool_ctx* c, tool_src* src, am_lattice* lat, const am_palette* pal, char* err, int errsz);

/* VXA files (docs/vxa.md) are read and written in the desktop profile only; TOOL_DESKTOP_ONLY
 * marks what a help text names that the board build answers with "not in this build" */
#if defined(AM_PROFILE_BOARD)
#define TOOL_VXA 0
#define TOOL_DESKTOP_ONLY " (not in this build: desktop profile)"
#else
#define TOOL_VXA 1
#define TOOL_DESKTOP_ONLY ""
#endif

/* strict value parsers (tools/args.c): 1 when the whole token is a number (am_parse_long,
 * am_parse_double) in [lo, hi] */
int tool_parse_long(const char* s, long lo, long hi, long* out);
int tool_parse_int(const char* s, int lo, int hi, int* out);
int tool_parse_real(const char* s, double lo, double hi, double* out);
int tool_parse_onoff(const char* s, int* out); /* "on" or "off" */


/* 1 when the picture commands are built in. Not in the board profile: a microcontroller shows no
 * pictures, and their buffers would be many times its RAM; there render, plot and view say so and
 * exit 2, and the three functions below print that and return 1. */
#if defined(AM_PROFILE_BOARD)
#define TOOL_PICTURES 0
#else
#define TOOL_PICTURES 1
#endif
/* pictures (docs/pictures.md; tools/film.c, tools/viewer.c, tools/plot.c), for the end of a run; each simulates the robot with recording (its
 * eval.record is ignored) and writes path atomically. Silent on success;
 * 0, or 1 after a one-line message on stderr. */
int tool_write_filmstrip(tool_ctx* c, const am_robot* r, const char* path);
int tool_write_viewer(tool_ctx* c, const am_robot* r, const char* title, const char* path);
/* the best fitness against evaluations of run folders or experiment folders (a mean line and a
 * standard-error band per variant) as SVG */
int tool_write_plot(int ndirs, char** dirs, const char* path);

/* the desktop profile reads whole files up to TOOL_FILE_MAX - 1 bytes, checkpoints up to
 * TOOL_CKPT_MAX - 1 (a population of AM_MAX_POPULATION of the largest genomes), into one buffer of
 * tools/files.c. The board profile has none: its files stream. */
#define TOOL_FILE_MAX (4L << 20)
#define TOOL_CKPT_MAX AM_EVO_CHECKPOINT_MAX(AM_MAX_POPULATION)
#if TOOL_WHOLE_FILES
/* the whole text of an open source */
const char* tool_src_text(const tool_src* s);
#endif

/* longest path the commands build (a run folder's files); the board's port takes 512 bytes */
#if defined(AM_PROFILE_BOARD)
#define TOOL_PATH_MAX 512
#else
#define TOOL_PATH_MAX 4096
#endif

#endif
