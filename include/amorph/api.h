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
#define AM_API_VERSION 1

/* one evaluation's workspace and settings. Large (tens of MB on the desktop): static, or on the
 * heap of a caller that may allocate; never on a stack. */
typedef struct am_api_work {
    long size;                /* sizeof(am_api_work) once am_api_init has run (a check of the caller's buffer) */
    am_evo_def def;           /* the settings: am_default_evo(), then each am_api_set in order */
    unsigned materials_set;   /* the AM_MATERIAL_* bits (evo.h) of the material keys that were set */
    am_palette palette;       /* the palette a genome is expressed with (am_evo_palette(&def)) */
    am_genome genome;         /* the genome being evaluated */
    am_evo_work work;         /* expression, lattice, model, state */
} am_api_work;

/* AM_API_VERSION of the library (a program loaded against another build can compare) */
int am_api_version(void);
/* bytes of the workspace, sizeof(am_api_work): what a ctypes caller allocates */
long am_api_work_size(void);
/* bytes of am_result, for a caller that mirrors it field by field (sim.h) */
long am_api_result_size(void);
/* prepares w (size bytes at w, at least am_api_work_size(), aligned for a double) with the
 * default settings, am_default_evo(): AM_ERR_ARG when w is NULL, too small or misaligned */
am_status am_api_init(am_api_work* w, long size, char* err, int errsz);
/* sets one key of amorph evolve's configuration ("cycles", "4"; docs/evolve.md lists them) over
 * w's settings, as `amorph sim --KEY VALUE` does: period_steps holds the period in steps
 * (period_s 0), relax_max_steps below relax_min_steps lowers that too. AM_ERR_ARG for an unknown
 * key, AM_ERR_RANGE for a bad value (the settings unchanged) */
am_status am_api_set(am_api_work* w, const char* key, const char* value, char* err, int errsz);
/* evaluates the genome in text (the genome text format, docs/formats.md) as a run with w's
 * settings evaluates it: expressed with the run's palette and voxel size, simulated in its
 * environment and evaluation. *out gets the result (am_result, sim.h); an empty body is AM_OK
 * with a zero result (fitness 0, voxels 0). AM_ERR_PARSE for a malformed genome ("genome:LINE: ...") */
am_status am_api_eval_genome(am_api_work* w, const char* text, am_result* out, char* err, int errsz);
/* evaluates the lattice in text (the lattice text format, docs/formats.md) in w's environment and
 * evaluation, its materials changed by the material keys that am_api_set set (cte: the actuated
 * ones; mu_static, mu_kinetic: all; voxel_size: the lattice's), as `amorph sim FILE --KEY VALUE`
 * does. Empty body and failures as am_api_eval_genome ("lattice:LINE: ...") */
am_status am_api_eval_lattice(am_api_work* w, const char* text, am_result* out, char* err, int errsz);

#ifdef __cplusplus
}
#endif
#endif
