/* amorph/api.h: the embedding API (src/api/): evaluate one robot, given as text, from any language
 * that can call C (Python's ctypes, Julia's ccall, Rust's FFI). It includes every layer's header
 * (amorph/base.h, sim.h, geno.h, evo.h, io.h) and adds a handful of functions over them whose
 * signatures use only pointers, long, int and char: a caller that cannot read the other headers
 * allocates am_api_work_size() bytes (aligned as malloc aligns) and mirrors am_result (sim.h; its
 * size is am_api_result_size()). docs/embedding.md is the manual.
 *
 * The caller owns the workspace: the library keeps no global and never allocates, so two threads
 * may evaluate at once on two workspaces. Every function returns an am_status (AM_OK = 0) and
 * writes a one-line message into err (capacity errsz; AM_ERR_MAX is enough) when it fails.
 */
#ifndef AMORPH_API_H
#define AMORPH_API_H

#include "amorph/base.h"
#include "amorph/sim.h"
#include "amorph/geno.h"
#include "amorph/evo.h"
#include "amorph/io.h"

#ifdef __cplusplus
extern "C" {
#endif

/* the version of this API: its functions and am_result's layout (a new field raises it) */
#define AM_API_VERSION 4 /* 2: ask/tell (am_api_seed ... am_api_crowd); 3: stepping (am_api_sim_*), VXA text; 4: am_api_set_config */

/* one evaluation's workspace and settings. Large (7.4 MB in the float desktop build): static, or on the
 * heap of a caller that may allocate; never on a stack. */
typedef struct am_api_work {
    long size;                /* sizeof(am_api_work) once am_api_init has run (a check of the caller's buffer) */
    am_evo_def def;           /* the settings: am_default_evo(), then each am_api_set in order */
    unsigned materials_set;   /* the AM_MATERIAL_* bits (evo.h) of the material keys that were set */
    am_palette palette;       /* the palette a genome is expressed with (am_evo_palette(&def)) */
    am_genome genome;         /* the genome being evaluated */
    am_evo_work work;         /* expression, lattice, model, state */
    am_rng rng;               /* the genome operators' stream (am_api_seed; seed 1 after am_api_init) */
    am_genome op[4];          /* the genome operators' genomes: parents, offspring */
    int sim;                  /* the robot being stepped (am_api_sim_*): 0 none, 1 open, 2 settled */
    am_xml_doc xml;           /* a VXA text's XML (am_api_eval_vxa, am_api_sim_open) */
    am_vxa_info vxa;          /* and what it holds */
} am_api_work;

/* ==== the caller's layout. Every struct of the headers is the caller's to allocate, and its layout
 * depends on the build's number type (REAL) and profile or capacities (PROFILE, AMORPH_CONFIG_H):
 * a program compiled with other defines than the library's would hand it structs of another size
 * and have them written past their end. A C program calls AM_LAYOUT_CHECK before anything else:
 *     if (AM_LAYOUT_CHECK(err, sizeof err) != AM_OK) { fprintf(stderr, "%s\n", err); exit(1); }
 * It passes the header version and the sizes of the caller-owned structs as the program sees them;
 * the library compares them with its own and refuses (AM_ERR_ARG, one line naming both
 * configurations) a program of another major version, of a newer minor version, or of another
 * layout. am_api_init checks its workspace's size the same way. */
#define AM_LAYOUT_VERSION (AM_VERSION_MAJOR * 10000L + AM_VERSION_MINOR * 100L + AM_VERSION_PATCH)
#define AM_LAYOUT_CONFIG AM_REAL_NAME " " AM_PROFILE_NAME
#define AM_LAYOUT_CHECK(err, errsz) am_layout_check(AM_LAYOUT_VERSION, AM_LAYOUT_CONFIG, (long)sizeof(am_lattice), (long)sizeof(am_model), \
    (long)sizeof(am_state), (long)sizeof(am_genome), (long)sizeof(am_evo), (long)sizeof(am_api_work), (err), (errsz))
/* the check behind AM_LAYOUT_CHECK: version and config as the caller's headers give them, then
 * the caller's sizeof of am_lattice, am_model, am_state, am_genome, am_evo and am_api_work */
AM_API am_status am_layout_check(long version, const char* config, long lattice, long model, long state, long genome, long evo,
                                 long api_work, char* err, int errsz);

/* AM_API_VERSION of the library (a program loaded against another build can compare) */
AM_API int am_api_version(void);
/* bytes of the workspace, sizeof(am_api_work): what a ctypes caller allocates */
AM_API long am_api_work_size(void);
/* bytes of am_result, for a caller that mirrors it field by field (sim.h) */
AM_API long am_api_result_size(void);
/* prepares w (size bytes at w, exactly am_api_work_size(), aligned for a double) with the
 * default settings, am_default_evo(): AM_ERR_ARG when w is NULL, of another size or misaligned.
 * A C caller passes sizeof *w, so that a program compiled with another REAL or PROFILE than the
 * library's is refused here rather than written past its workspace's end */
AM_API am_status am_api_init(am_api_work* w, long size, char* err, int errsz);
/* sets one key of amorph evolve's configuration ("cycles", "4"; docs/evolve.md lists them) over
 * w's settings, as `amorph sim --KEY VALUE` does: period_steps holds the period in steps
 * (period_s 0), relax_max_steps below relax_min_steps lowers that too. AM_ERR_ARG for an unknown
 * key, AM_ERR_RANGE for a bad value (the settings unchanged) */
AM_API am_status am_api_set(am_api_work* w, const char* key, const char* value, char* err, int errsz);
/* replaces w's settings with a configuration text: a run folder's config.txt (amorph evolve
 * --print-config's format, `key = value` lines, '#' comments), read as `amorph sim DIR` reads it:
 * the keys the text does not name take the values a stored configuration had (am_stored_evo, so
 * that a run folder of any age evaluates as it evolved), a key set twice is refused. Then a genome
 * is evaluated as that run evaluates it (amorph sim DIR --genome FILE); a lattice keeps its own
 * materials. am_api_set goes on from there; the operators' stream is am_api_seed's. Messages
 * "NAME:LINE: problem" (name NULL: "config"); AM_ERR_PARSE or AM_ERR_RANGE, the settings unchanged */
AM_API am_status am_api_set_config(am_api_work* w, const char* text, const char* name, char* err, int errsz);
/* evaluates the genome in text (the genome text format, docs/formats.md) as a run with w's
 * settings evaluates it: expressed with the run's palette and voxel size, simulated in its
 * environment and evaluation. *out gets the result (am_result, sim.h); an empty body is AM_OK
 * with a zero result (fitness 0, voxels 0). AM_ERR_PARSE for a malformed genome ("genome:LINE: ...") */
AM_API am_status am_api_eval_genome(am_api_work* w, const char* text, am_result* out, char* err, int errsz);
/* evaluates the lattice in text (the lattice text format, docs/formats.md) in w's environment and
 * evaluation, its materials changed by the material keys that am_api_set set (cte: the actuated
 * ones; mu_static, mu_kinetic: all; voxel_size: the lattice's), as `amorph sim FILE --KEY VALUE`
 * does. Empty body and failures as am_api_eval_genome ("lattice:LINE: ...") */
AM_API am_status am_api_eval_lattice(am_api_work* w, const char* text, am_result* out, char* err, int errsz);
/* evaluates a VXA text (VoxCAD, evosoro, amorph export --vxa; docs/vxa.md) as `amorph sim FILE`
 * does: its body with its per-voxel layers, in the file's own environment and evaluation, which
 * replace w's (a file holds all of them). Messages "vxa:LINE: ..."; the board refuses VXA text */
AM_API am_status am_api_eval_vxa(am_api_work* w, const char* text, am_result* out, char* err, int errsz);
/* (the step of am_api_eval_vxa and am_api_sim_open that reads the text into w) */
AM_API am_status am_api_read_vxa(am_api_work* w, const char* text, char* err, int errsz);

/* ==== ask/tell: amorph's own operators for an outer loop (docs/embedding.md, Ask/tell). Genomes go
 * in and out as text (the genome text format); random draws come from w's stream, one stream per
 * workspace, consumed in call order, so the same calls give the same genomes. A population made
 * with am_api_genome_new after am_api_seed(w, S), paired with am_api_pairing, bred with
 * am_api_offspring, evaluated with am_api_eval_genome and crowded with am_api_crowd is the run
 * `amorph evolve --seed S` makes with w's settings, generation for generation. Text out goes to
 * out (capacity cap, NUL-terminated; AM_GENOME_TEXT_MAX always suffices; AM_ERR_CAPACITY when it
 * does not fit). Genomes in are parsed as "genome:LINE: ..." (AM_ERR_PARSE), and must be of w's
 * settings' shape where two meet (AM_ERR_ARG otherwise). */

/* seeds w's stream (seed >= 0): the stream a run of `seed = SEED` draws from */
AM_API am_status am_api_seed(am_api_work* w, long seed, char* err, int errsz);
/* a random genome of w's settings (representation, materials and palette, workspace, evolved
 * fields, sizes), as a run's initial population draws them */
AM_API am_status am_api_genome_new(am_api_work* w, char* out, long cap, char* err, int errsz);
/* the pairs of a generation: order[0..n-1] the members 0..n-1 shuffled (n 2..AM_MAX_POPULATION, even);
 * a run pairs order[2k] with order[2k + 1] */
AM_API am_status am_api_pairing(am_api_work* w, int n, int* order, char* err, int errsz);
/* the two offspring of parents a and b as a run breeds them: crossover, then each mutated */
AM_API am_status am_api_offspring(am_api_work* w, const char* a, const char* b, char* out1, char* out2, long cap, char* err,
                                  int errsz);
/* the genome in, mutated once (w's rates) */
AM_API am_status am_api_mutate(am_api_work* w, const char* in, char* out, long cap, char* err, int errsz);
/* the crowding distance of two genomes' bodies (am_genome_distance with their evolved fields):
 * in [0, 1] */
AM_API am_status am_api_distance(am_api_work* w, const char* a, const char* b, double* out, char* err, int errsz);
/* deterministic crowding's step for parents a, b and their offspring 1, 2, each with its fitness
 * (a NaN: diverged, always loses): meets[k] gets the parent (0: a, 1: b) offspring k + 1 competes
 * with, replaces[k] 1 when it is strictly better and takes that parent's place, as a run decides */
AM_API am_status am_api_crowd(am_api_work* w, const char* a, double fa, const char* b, double fb, const char* c1, double f1,
                              const char* c2, double f2, int* meets, int* replaces, char* err, int errsz);

/* ==== stepping: a robot under the caller's control (docs/embedding.md, Stepping). Open a robot
 * (genome, lattice or VXA text, built as am_api_eval_* builds it: a VXA text's environment and
 * evaluation replace w's), settle it as
 * the evaluation's relaxation settles it (out may be NULL: its relaxation fields), then step it N
 * steps at a time and observe it. The actuation starts at the settle (the movement's phase 0);
 * each voxel follows its sinusoid unless the step's scale[] sets it: scale[i] is voxel i's linear
 * scale, 1 + its expansion (0.5..2), rate[i] the scale's rate of change in 1/s (NULL: 0), held for
 * the N steps; a NaN scale leaves that voxel to its sinusoid; scale NULL leaves every voxel to it.
 * am_api_sim_sinusoid gives each voxel's own scale and rate for the next step: fed back step by
 * step, the robot moves exactly as am_api_eval_* moves it (the same hash, bit for bit). The desktop
 * profile only (a phase per voxel: the board refuses, AM_ERR_CAPACITY). Deterministic, no
 * allocation; a diverged robot takes no more steps (am_obs.diverged). */
AM_API am_status am_api_sim_open(am_api_work* w, const char* text, char* err, int errsz);
AM_API am_status am_api_sim_settle(am_api_work* w, am_result* out, char* err, int errsz);
/* the open robot's voxels (-1 when none is open) and, when not NULL, each voxel's material (its
 * index in the lattice's palette) and lattice cell: the order of every per-voxel array */
AM_API long am_api_sim_voxels(am_api_work* w, int* material, int* cell);
AM_API am_status am_api_sim_step(am_api_work* w, long n, const double* scale, const double* rate, char* err, int errsz);
AM_API am_status am_api_sim_sinusoid(am_api_work* w, double* scale, double* rate, char* err, int errsz);
/* am_observe (sim.h) of the open robot: *out, and each per-voxel array that is not NULL */
AM_API am_status am_api_sim_observe(am_api_work* w, am_obs* out, double* pos, double* vel, double* strain, int* contact, char* err,
                                    int errsz);

#ifdef __cplusplus
}
#endif
#endif
