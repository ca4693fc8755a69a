/* tools/cmd.h: the subcommands of the amorph program and what they share. Every command returns
 * the process exit status: 0 success, 1 failure at run time, 2 bad input (flags, files). */
#ifndef AMORPH_TOOLS_CMD_H
#define AMORPH_TOOLS_CMD_H

#include "amorph.h"

int cmd_sim(int argc, char** argv);
int cmd_bench(int argc, char** argv);
int cmd_random(int argc, char** argv);
int cmd_express(int argc, char** argv);
int cmd_render(int argc, char** argv);
int cmd_plot(int argc, char** argv);
int cmd_view(int argc, char** argv);
int cmd_evolve(int argc, char** argv);
int cmd_experiment(int argc, char** argv);
int cmd_repro(int argc, char** argv);
int cmd_export(int argc, char** argv);

/* 1 when path is a run folder of amorph evolve (config.txt and best.genome) */
int tool_is_run_dir(const char* path);
/* a run folder's best robot, and the environment and evaluation it evolved in (tools/run.c);
 * env and eval may be NULL */
am_status tool_load_run(const char* dir, am_lattice* lat, am_env* env, am_eval_def* eval, char* err, int errsz);

/* prints name=value lines of the default experiment's evaluations per hour on 1 and 2 threads
 * (cmd_evolve.c); 0, or 1 when the two runs differ */
int tool_bench_evolve(long evaluations);

/* prints "amorph: <message>" on stderr as one line and returns 2 */
int tool_usage_error(const char* fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/* loads a robot: "scene:NAME" style names (cube:N ...) when is_scene, else a file in any format
 * amorph reads (lattice text; genome text, expressed; VXA). Messages are "file:line: problem". */
am_status tool_load_robot(const char* name, int is_scene, am_lattice* lat, char* err, int errsz);

/* genome text (any representation) -> lattice; implemented with the genotypes (cmd_genome.c).
 * Returns AM_ERR_ARG without a message when text is not a genome, so the caller tries others. */
am_status tool_genome_text_to_lattice(const char* text, const char* fname, am_lattice* lat, char* err, int errsz);

/* VXA text -> lattice (cmd_export.c); prints the reader's warnings on stderr. Returns AM_ERR_ARG
 * without a message when text is not XML. On success tool_vxa_loaded is 1 and tool_vxa_info holds
 * the file's environment (tool_load_robot sets tool_vxa_loaded to 0 before each load). */
am_status tool_vxa_text_to_lattice(const char* text, const char* fname, am_lattice* lat, char* err, int errsz);
extern int tool_vxa_loaded;
extern am_vxa_info tool_vxa_info;

/* strict value parsers (tools/args.c): 1 when the whole token is a number in [lo, hi] */
int tool_parse_u64(const char* s, uint64_t* out);
int tool_parse_long(const char* s, long lo, long hi, long* out);
int tool_parse_int(const char* s, int lo, int hi, int* out);
int tool_parse_real(const char* s, double lo, double hi, double* out);
int tool_parse_onoff(const char* s, int* out); /* "on" or "off" */

/* writes text (len bytes) to the file out atomically, or to the standard output when out is NULL;
 * returns 0, or 1 after a one-line message on stderr */
int tool_write_output(const char* out, const char* text, long len);

/* prints name=value lines of the genotype expression times (cmd_genome.c) */
void tool_bench_express(void);

/* 1 when the picture commands are built in. Not in the board profile: a microcontroller shows no
 * pictures, and their buffers would be many times its RAM; there render, plot and view say so and
 * exit 2, and the three functions below print that and return 1. */
#if defined(AM_PROFILE_BOARD)
#define TOOL_PICTURES 0
#else
#define TOOL_PICTURES 1
#endif
/* pictures (docs/pictures.md), for the end of a run; each simulates the robot with recording in
 * env with eval (its record field is ignored) and writes path atomically. Silent on success;
 * 0, or 1 after a one-line message on stderr. */
int tool_write_filmstrip(const am_lattice* lat, const am_env* env, const am_eval_def* eval, const char* path);
int tool_write_viewer(const am_lattice* lat, const am_env* env, const am_eval_def* eval, const char* title,
                      const char* path);
/* the best fitness against evaluations of run folders or experiment folders (a mean line and a
 * standard-error band per variant) as SVG */
int tool_write_plot(int ndirs, char** dirs, const char* path);

/* one shared file buffer for the commands (they run one at a time): 4 MiB on the desktop; in the
 * board profile the largest text amorph writes itself (a genome or a lattice), plus its NUL */
#if defined(AM_PROFILE_BOARD)
#define TOOL_FILE_MAX ((AM_GENOME_TEXT_MAX > AM_LATTICE_TEXT_MAX ? AM_GENOME_TEXT_MAX : AM_LATTICE_TEXT_MAX) + 1L)
#else
#define TOOL_FILE_MAX (4L << 20)
#endif
extern char tool_file_buf[TOOL_FILE_MAX];

/* the workspaces every command shares (they run one at a time): the evolver's evaluation
 * workers; [0] also serves sim, bench, export, random, express and the pictures, each job on its
 * own members (geno to express, model and state to simulate) */
extern am_evo_work tool_work[AM_MAX_WORKERS];

#endif
