/* amorph/evo.h: the evolver layer (src/evo/): a run's settings, deterministic crowding one
 * generation at a time, the run's hash, and the run folder's file names and tables (log.csv,
 * evals.csv, an experiment's results.csv). It includes amorph/base.h, amorph/sim.h and
 * amorph/geno.h.
 */
#ifndef AMORPH_EVO_H
#define AMORPH_EVO_H

#include <stdint.h>
#include "amorph/base.h"
#include "amorph/sim.h"
#include "amorph/geno.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ==== the evolver (deterministic crowding), its configuration and checkpoints.
 *
 * A run is a population of genomes evolved by deterministic crowding (Mahfoud 1996), as in the
 * seed paper: each generation pairs the parents at random, every pair makes two offspring by
 * crossover and mutation, every offspring competes with the more similar of its two parents
 * (Mahfoud's pairing rule on the body distance of am_genome_distance) and replaces it when it
 * is strictly better. Offspring are made serially from one seeded stream; their evaluations go
 * to the port's parallel map, each on a workspace of its own, and crowding is applied in a fixed
 * order afterwards, so a run is bit-identical for any number of workers.
 *
 * The configuration (am_evo_def) is a set of `key = value` settings (docs/evolve.md lists every
 * key); am_evo_set applies one, so config files and command-line flags share one parser.
 * Everything a run needs to continue is in its checkpoint, a text file closed by a checksum.
 */

/* ---- configuration ---- */

/* a run's palette (docs/evolve.md, Palettes): a preset, the seed's (passive, active, active90: the
 * default, with materials 2) or the follow-up's (Cheney et al. 2013, as evosoro's examples have it:
 * passive_soft, passive_hard, active_plus, active_minus), and over it the materialK keys, each the
 * palette's entry K in place of the preset's or past its end. The genomes' fields are the palette's
 * first geno.materials entries, in order. */
enum { AM_PALETTE_SEED = 0, AM_PALETTE_UNSHACKLED = 1 };
/* one materialK key as given: NAME modulus= density= cte= phase= [poisson= mu_static= mu_kinetic= color=] */
typedef struct am_evo_material {
    char name[AM_NAME_MAX];   /* "": the key is not set (the preset's entry K, if it has one) */
    am_param E;                /* Pa, > 0 */
    am_param density;          /* kg/m^3, > 0 */
    am_param cte;              /* per degree (the cte key does not apply to it) */
    am_param phase;            /* degrees, added to the temperature's phase (-90: the seed's active90) */
    am_param poisson;          /* [0, 0.5) (0 unless given) */
    am_param mu_static;        /* floor friction (the run's mu_static unless given) */
    am_param mu_kinetic;       /* (the run's mu_kinetic unless given) */
    uint8_t color[3];          /* display colour, RGB (a colour of the material's index unless given) */
    uint8_t given;             /* AM_EVO_MAT_* bits of the optional fields given */
} am_evo_material;
enum { AM_EVO_MAT_POISSON = 1, AM_EVO_MAT_MU_STATIC = 2, AM_EVO_MAT_MU_KINETIC = 4, AM_EVO_MAT_COLOR = 8 };

enum { AM_ACTUATION_GLOBAL = 0, AM_ACTUATION_PHASE = 1 };
enum { AM_STIFFNESS_MATERIAL = 0, AM_STIFFNESS_EVOLVED = 1 };
/* everything that defines a run; am_default_evo() is the seed's two-material experiment */
typedef struct am_evo_def {
    am_geno_def geno;         /* representation, materials, workspace, variation rates (GMX, 2, 20^3);
                               * geno.mat: the palette's names (am_evo_set keeps them) */
    int palette;              /* AM_PALETTE_SEED (default) or AM_PALETTE_UNSHACKLED */
    am_evo_material material[AM_MAX_GENO_MATERIALS]; /* the materialK keys: material[K - 1] */
    am_env env;               /* environment: gravity, floor, actuation, time step (am_default_env) */
    am_eval_def eval;         /* evaluation: cycles, fitness measure, relaxation (record is ignored) */
    am_param cte;              /* CTE of the actuated materials, per degree (0.01, volumetric) */
    am_param mu_static;        /* static floor friction of every material (1.0) */
    am_param mu_kinetic;       /* kinetic floor friction of every material (0.3) */
    am_param voxel_size;       /* m (0.01) */
    int actuation;            /* AM_ACTUATION_GLOBAL (the seed's: each material's sinusoid) or AM_ACTUATION_PHASE
                               * (the genomes evolve each voxel's phase besides, AM_CTL_PHASE) */
    int stiffness;            /* AM_STIFFNESS_MATERIAL (each material's modulus) or AM_STIFFNESS_EVOLVED (the
                               * genomes evolve each voxel's modulus, AM_CTL_STIFFNESS, in the range below) */
    am_param stiffness_min;    /* Pa: an evolved modulus's range (1e5) */
    am_param stiffness_max;    /* Pa (1e7; at most 100 x stiffness_min) */
    int population;           /* individuals, even, 2..AM_MAX_POPULATION (20) */
    long evaluations;         /* the run stops after this many evaluations, >= population */
    uint64_t seed;            /* the random stream (1) */
    int threads;              /* workers for evaluations; 0: all cores. Never changes results */
    long checkpoint_seconds;  /* 0: a checkpoint every generation; else at most one per this many s */
} am_evo_def;

/* the genomes' evolved fields (AM_CTL_* bits) that d's actuation and stiffness keys ask for: the one
 * place geno.controls is derived from them */
static inline int am_evo_controls(const am_evo_def* d)
{
    return (d->actuation == AM_ACTUATION_PHASE ? AM_CTL_PHASE : 0) | (d->stiffness == AM_STIFFNESS_EVOLVED ? AM_CTL_STIFFNESS : 0);
}

/* the seed's two-material GMX experiment on the profile's workspace (20^3 desktop), 200 evaluations */
AM_API am_evo_def am_default_evo(void);
/* the defaults under a stored configuration (a run folder's config.txt, a checkpoint): those of
 * am_default_evo, except that a key added after run folders were first written takes the value
 * that reproduces the runs made before it, so that such a folder resumes and replays exactly:
 * relax_dt_frac 0 (settling at the run's step). A new run writes every key, these included. */
AM_API am_evo_def am_stored_evo(void);

/* sets one key from its text value ("population", "20"); the message names the problem only
 * (the caller adds "file:line: " or "--flag: "). AM_ERR_ARG for an unknown key, AM_ERR_RANGE for
 * a value out of range or malformed */
AM_API am_status am_evo_set(am_evo_def* d, const char* key, const char* value, char* err, int errsz);
/* A setting over one robot's own values, as `amorph sim ROBOT --KEY VALUE` and the embedding API
 * apply it: am_evo_set, then period_steps holds the period in steps (period_s 0) and a
 * relax_max_steps below relax_min_steps lowers that too. *material gets the key's AM_MATERIAL_* bit
 * (0 for a key that is not a material's): what am_evo_apply_materials writes into a lattice. */
enum { AM_MATERIAL_CTE = 1, AM_MATERIAL_MU_STATIC = 2, AM_MATERIAL_MU_KINETIC = 4, AM_MATERIAL_VOXEL_SIZE = 8 };
AM_API am_status am_evo_set_over(am_evo_def* d, const char* key, const char* value, unsigned* material, char* err, int errsz);
/* d's values of the material keys in mask (AM_MATERIAL_* bits) written over lat: cte over the
 * actuated materials (cte not 0), mu_static and mu_kinetic over every material, voxel_size over the
 * lattice's */
AM_API void am_evo_apply_materials(const am_evo_def* d, unsigned mask, am_lattice* lat);
/* checks the whole definition (relations between keys, the evaluation's budget: am_evo_check_budget);
 * messages name the key */
AM_API am_status am_evo_check(const am_evo_def* d, char* err, int errsz);
/* am_evo_check, with the index (am_evo_key_name) of the key its message names in *key (-1 when
 * the definition is whole), so that a caller can say where that key was set ("file:line: ") */
AM_API am_status am_evo_check_key(const am_evo_def* d, int* key, char* err, int errsz);
/* the evaluation's budget (am_eval_check, amorph/sim.h) for d's environment and evaluation with a
 * period of period_steps steps of d's step: AM_OK, or AM_ERR_RANGE with the message "KEY = VALUE:
 * up to ... steps an evaluation ..." and in *key the index of the setting that multiplies the seed's
 * evaluation most in the larger of its parts (relax_max_steps, dt_frac or dt_search for the
 * relaxation; cycles, period_steps or period_s for the movement). am_evo_check_key checks it with
 * the period in seconds at its most steps, 10^7 (no body is built yet) */
AM_API am_status am_evo_check_budget(const am_evo_def* d, double period_steps, int* key, char* err, int errsz);
/* the index of the key a configuration line sets (n characters), or -1 (a comment, a blank or a
 * malformed line, an unknown key) */
AM_API int am_evo_line_key(const char* text, long n);
/* more than the configuration keys there are: a table of one entry per key */
#define AM_EVO_KEY_MAX 80
/* am_evo_check, and that the definition can evolve: a relaxation long enough for a body to settle
 * (relax_max_steps at least release_steps + 50), as a run needs and a configuration to print does
 * not (am_evo_init checks it) */
AM_API am_status am_evo_check_run(const am_evo_def* d, char* err, int errsz);
/* 1 when key is a configuration key */
AM_API int am_evo_is_key(const char* key);
/* what a key sets: the robot's environment (gravity, period_steps, ...), its evaluation (cycles,
 * relax_max_steps, ...), the materials of the run's palette (cte, mu_static, mu_kinetic,
 * voxel_size), the genotype (representation, workspace, ...), or the run itself (population,
 * evaluations, seed, threads, checkpoint_seconds); -1 for an unknown key */
typedef enum am_key_group { AM_KEYS_RUN, AM_KEYS_GENOTYPE, AM_KEYS_MATERIALS, AM_KEYS_ENV, AM_KEYS_EVAL } am_key_group;
AM_API int am_evo_key_group(const char* key);
/* the keys in their documented order: count, name and one-line help of key i (NULL past the end) */
AM_API int am_evo_key_count(void);
AM_API const char* am_evo_key_name(int i);
AM_API const char* am_evo_key_help(int i);
/* the value of key i in d as the configuration text writes it ("" past the end) */
AM_API void am_evo_key_value(const am_evo_def* d, int i, char* out, int cap);
/* the effective configuration as `key = value` lines that am_evo_parse reads back exactly;
 * with_runtime 0 leaves out the keys that never change results (threads, checkpoint_seconds) */
AM_API am_status am_evo_format(const am_evo_def* d, int with_runtime, char* buf, long cap, long* len, char* err, int errsz);
/* the same text written to out, a whole-text buffer or a stream (amorph/base.h) */
AM_API am_status am_evo_write(const am_evo_def* d, int with_runtime, am_text* out, char* err, int errsz);
/* reads `key = value` lines (# comments, blank lines) over d; messages "fname:line: problem" */
AM_API am_status am_evo_parse(am_evo_def* d, const char* text, const char* fname, char* err, int errsz);
/* one line of that text (n characters without the newline; line number lineno for messages), for
 * text that is not held whole; am_evo_parse is this over every line */
AM_API am_status am_evo_parse_line(am_evo_def* d, const char* text, long n, const char* fname, int lineno, char* err, int errsz);
/* 1 when a and b give the same run (every key but threads, checkpoint_seconds and evaluations);
 * else 0 and the first differing key's name in key (capacity keysz) */
AM_API int am_evo_same_run(const am_evo_def* a, const am_evo_def* b, char* key, int keysz);
/* materials in d's palette: its preset's and the materialK keys' (at most AM_MAX_GENO_MATERIALS;
 * am_evo_check rejects a materialK past the end without the keys before it) */
AM_API int am_evo_palette_size(const am_evo_def* d);
/* the palette and expression settings a run's genomes are expressed and simulated with: the seed's
 * palette is the built-in one (am_default_palette) with the run's cte, mu_static and mu_kinetic;
 * any other holds am_evo_palette_size(d) materials, the preset's with those keys' values and the
 * materialK keys' as given */
AM_API am_palette am_evo_palette(const am_evo_def* d);
/* the same palette written into *out */
AM_API void am_evo_palette_into(const am_evo_def* d, am_palette* out);

/* ---- state ---- */

/* one evaluated individual */
typedef struct am_evo_ind {
    am_genome genome;
    double fitness;           /* m: am_result.fitness (AM_NO_SCORE when diverged or unsettled); 0 for an
                               * empty body (not simulated) */
    int voxels;               /* voxels of the expressed body */
    int diverged;             /* 1: the simulation diverged (always loses) */
    int empty;                /* 1: the body was empty (fitness 0, not simulated) */
    long steps;               /* time steps simulated */
    uint64_t state_hash;      /* am_state_hash at the end of the evaluation (0 when empty) */
    long id;                  /* the evaluation that made it: its index in the run, from 0 (-1: unknown,
                               * a checkpoint of version 1) */
} am_evo_ind;

/* what an evaluation measured besides its am_evo_ind (whose id is the evaluation's index), and
 * where it stands in the run: with the individual, one row of a run's evals.csv (am_evo_evals_row) */
typedef struct am_evo_eval {
    long generation;          /* 0: the initial population */
    long parent[2];           /* ids of the two parents (-1 in generation 0 or when unknown) */
    int placed;               /* 1: it entered the population (generation 0, or beat its parent) */
    am_result sim;            /* the simulator's result as am_evaluate gave it (all zeros for an empty
                               * body, which is not simulated; diverged 1 and fitness AM_NO_SCORE for a
                               * body whose model could not be built) */
    int material_voxels[AM_MAX_GENO_MATERIALS]; /* voxels of each material (the genome's order) */
} am_evo_eval;

/* what one evaluation gives back: the simulator's result and the body's counts (the individual's
 * fields come from them: fitness, steps, state_hash and diverged are detail.sim's). A port whose
 * workers do not share memory (port/mpi) copies these bytes, and nothing else, between processes
 * (am_port_parallel_map's out). */
typedef struct am_evo_result {
    int voxels, empty;        /* as am_evo_ind */
    int skipped;              /* 1: not evaluated (the caller cancelled it; am_evo_batch_end then cancels) */
    am_evo_eval detail;       /* the measurements (generation, parents and placed are am_evo_batch_end's) */
} am_evo_result;

/* One body a run has simulated, and what it gave (am_evo.memo). The result of an evaluation is a
 * function of the expressed body alone (the run's settings and palette are the run's), so an
 * offspring whose body equals a remembered one, cell for cell, takes the remembered result instead
 * of a simulation: the same bytes a simulation would give, so nothing of the run changes but its
 * speed (docs/evolve.md, Same body, same result). */
/* a body packed: 2 bits a cell (4 cells a byte) in a run of up to three materials, 4 bits a cell
 * (2 a byte) in a run of more; the first cell in the low bits */
static inline int am_evo_cell_bits(int materials) { return materials <= 3 ? 2 : 4; }
/* bytes of a body of n cells so packed */
static inline int am_evo_packed_bytes(int n, int materials) { return materials <= 3 ? (n + 3) / 4 : (n + 1) / 2; }
/* cell c of a packed body */
static inline int am_evo_packed_cell(const uint8_t* packed, int c, int materials)
{
    return materials <= 3 ? packed[c >> 2] >> 2 * (c & 3) & 3 : packed[c >> 1] >> 4 * (c & 1) & 15;
}
/* bytes of a body of n cells with its evolved fields (AM_CTL_* bits in controls): the packed cells,
 * then a byte a cell of each field (phase, then stiffness; am_geno_work.ctl), lowered as the cells */
static inline int am_evo_body_bytes(int n, int materials, int controls)
{
    return am_evo_packed_bytes(n, materials) + n * ((controls & 1) + (controls >> 1 & 1));
}
#define AM_EVO_MEMO_BYTES ((AM_MAX_GENO_MATERIALS <= 3 ? (AM_MAX_CELLS + 3) / 4 : (AM_MAX_CELLS + 1) / 2) + AM_GENO_CONTROLS * AM_MAX_CELLS)
typedef struct am_evo_memo {
    long used;                /* the id of the last evaluation that stored or took it (a full table
                               * gives the slot used longest ago to the next new body) */
    uint64_t key;             /* am_evo_body_key of the body; 0: a free slot */
    uint8_t cells[AM_EVO_MEMO_BYTES]; /* the body, packed (am_evo_cell_bits), and its evolved fields (am_evo_body_bytes) */
    am_evo_result res;        /* its result as the evaluation gave it */
} am_evo_memo;

/* the key of a body of n cells of a run of `materials` materials and evolved fields `controls`
 * packed as am_evo_memo.cells: a hash of its am_evo_body_bytes, never 0 */
AM_API uint64_t am_evo_body_key(const uint8_t* packed, int n, int materials, int controls);

/* what a caller of am_evo_generation may watch; every member may be NULL */
typedef struct am_evo_hooks {
    /* on the workers, before each evaluation of the generation's first batch: non-zero stops the
     * generation (AM_ERR_CANCELLED) */
    int (*cancel)(void* ctx);
    /* on the calling thread, every evaluation in index order, as its batch is placed */
    void (*evaluated)(void* ctx, const am_evo_ind* ind, const am_evo_eval* ev);
    void* ctx;
} am_evo_hooks;

/* statistics of one generation, after replacement (one row of log.csv) */
typedef struct am_evo_stats {
    long generation;          /* 0: the initial population */
    long evaluations;         /* evaluations done so far */
    double best, mean, median; /* of the population's fitness (diverged and unsettled members left out) */
    int diverged;             /* diverged evaluations in this generation */
    int empty;                /* empty bodies in this generation */
    double wall_s;            /* wall time of this generation, s */
    int unsettled;            /* evaluations whose body did not settle (no score: docs/evolve.md) */
} am_evo_stats;

/* a run: population, offspring, the random stream and counters. Large: declare it static.
 * Offspring are made, evaluated and placed AM_EVO_BATCH at a time: a whole generation on the
 * desktop (one parallel map), one pair at a time on a one-worker board. The pairs of a generation
 * are disjoint and nothing but making offspring draws from the stream, so the run is the same
 * for any batch size. */
typedef struct am_evo {
    am_evo_def def;
    am_palette palette;                       /* am_evo_palette(&def) */
    am_rng rng;                               /* the one random stream */
    long generation;                          /* generations completed (0 before the first) */
    long evaluations;                         /* evaluations completed */
    am_evo_ind pop[AM_MAX_POPULATION];        /* the population (def.population members) */
    am_evo_ind child[AM_EVO_BATCH];           /* offspring of the current batch */
    am_evo_ind best;                          /* best individual ever evaluated */
    int has_best;                             /* 1 once best is set */
    uint64_t history;                         /* hash over every genome and fitness evaluated */
    am_evo_stats last;                        /* statistics of the last generation */
    long last_steps;                          /* time steps simulated by the last generation (benchmarks) */
    long last_voxel_steps;                    /* the same, each step times the body's voxels */
    am_evo_eval eval[AM_EVO_BATCH];           /* what the evaluations of the current batch measured */
    am_evo_result res[AM_EVO_BATCH];          /* am_evo_generation's results of the batch's map items */
    int order[AM_EVO_BATCH];                  /* the current batch's evaluation order: item i of its
                                                 map evaluates child[order[i]] (largest body first) */
    int order_voxels[AM_EVO_BATCH];           /* voxels of item i's body (the order's key) */
    uint8_t body[AM_MAX_CELLS];               /* scratch: the first parent's body of a crowding pair
                                                 (the second's is in w[0].geno.other); before
                                                 crowding, bodies packed as memo's (without layers) */
#if AM_GENO_LAYERS
    uint8_t body_ctl[AM_GENO_CONTROLS][AM_MAX_CELLS]; /* the first parent's evolved fields (am_geno_work.ctl) */
    uint8_t packed[2][AM_EVO_MEMO_BYTES];     /* bodies packed as memo's */
#endif
    /* same body, same result: the bodies simulated last and their results (in the checkpoint) */
    am_evo_memo memo[AM_EVO_MEMO];
    long reused;                              /* evaluations that took a remembered result (in the checkpoint) */
    double reused_voxel_steps;                /* their voxel-steps, not simulated (in the checkpoint) */
    int memo_limit;                           /* slots the table may fill: 0 all AM_EVO_MEMO, < 0 none (no
                                                 reuse); a speed setting, not in the checkpoint */
    /* the generation under way (am_evo_gen_begin .. am_evo_gen_end; never in a checkpoint) */
    int gen_parent[AM_MAX_POPULATION];        /* offspring 2k, 2k + 1 come from these two members */
    int gen_b, gen_m;                         /* the current batch: individuals [gen_b, gen_b + gen_m) */
    am_rng gen_saved;                         /* the stream before the generation (a cancel restores it) */
    double gen_t0;                            /* the caller's clock at its start (the now it passes) */
    long gen_steps, gen_voxel_steps;          /* its time steps so far */
    int gen_diverged, gen_empty, gen_unsettled; /* its diverged, empty and unsettled evaluations so far */
    int reuse[AM_EVO_BATCH];                  /* the current batch's offspring j: -1 simulated, k >= 0 takes
                                                 memo[k]'s result, -2 - i takes offspring i's */
    uint64_t child_key[AM_EVO_BATCH];         /* its body's key (0: empty or not expressed) */
} am_evo;

/* one worker's workspace for evaluations. Large: declare them static, one per worker. */
typedef struct am_evo_work {
    am_geno_work geno;
    am_lattice lattice;
    am_model model;
    am_state state;
#if AM_GENO_LAYERS
    am_layers layers;         /* the evolved phases and stiffnesses of the body in lattice (am_evo_express) */
#endif
    int has_layers;           /* 1: layers go with lattice (am_evo_simulate builds its model with them) */
} am_evo_work;

/* ---- running ---- */

/* How the evolver runs a batch of evaluations and reads a clock, given by its caller (as Box2D's
 * world takes task callbacks): the library itself starts no thread and calls no OS.
 *   map(self, n, workers, task, ctx, out, size, err, errsz): calls task(ctx, i, worker) once for
 *       each item i in [0, n), on up to `workers` workers (worker in [0, workers)), in any order, and
 *       returns when every call has returned. Item i's result is the `size` bytes at
 *       out + i * size: an executor whose workers do not share memory (MPI ranks) copies them back;
 *       a threaded one leaves them where the task wrote them. A failure returns its status with a
 *       message in err.
 *   now(self): seconds on any monotonic clock (only differences are used: log.csv's wall_s).
 * Either member may be NULL, and so may the executor: then items run in order on the calling
 * thread as worker 0, and wall_s is 0. Results never depend on the executor. */
typedef void (*am_task_fn)(void* ctx, int item, int worker);
typedef struct am_executor {
    am_status (*map)(void* self, int n, int workers, am_task_fn task, void* ctx, void* out, long size, char* err, int errsz);
    double (*now)(void* self);
    void* self;     /* the executor's own state, passed back to map and now */
    int workers;    /* workspaces w[0..workers-1] the caller provides (1..AM_MAX_WORKERS; < 1 means 1) */
} am_executor;

/* a new run from d: checks it, seeds the stream and draws the random initial population (not yet
 * evaluated: the first am_evo_generation evaluates it) */
AM_API am_status am_evo_init(am_evo* e, const am_evo_def* d, char* err, int errsz);
/* 1 when the run has done its evaluations */
AM_API int am_evo_done(const am_evo* e);
/* one generation: generation 0 evaluates the initial population; later ones make offspring,
 * evaluate them on ex's workers (workspaces w[0..ex->workers-1]; ex may be NULL: one at a time) and
 * apply crowding. hooks may be NULL. When hooks->cancel returns non-zero during the evaluations of
 * the first batch (every evaluation of the generation when AM_EVO_BATCH >= population, as on the
 * desktop), no further evaluation starts, the generation is abandoned and e is left as it was
 * before the call (AM_ERR_CANCELLED, "interrupted"); once a batch has been placed the generation
 * runs to its end. hooks->evaluated sees each evaluation as its batch is placed. Fills e->last. */
AM_API am_status am_evo_generation(am_evo* e, am_evo_work* w, const am_executor* ex, const am_evo_hooks* hooks, char* err, int errsz);
/* A generation in steps, for a caller that evaluates the offspring of several runs in one parallel
 * map (amorph experiment): am_evo_generation is these steps over one run.
 *   am_evo_gen_begin(e, now);
 *   while (am_evo_batch_begin(e, &w[0].geno, &m, ...) == AM_OK && m > 0) {
 *       item i in [0, m), on any worker, in any order, in any process: am_evo_batch_eval(e, i, &w[k], &res[i]);
 *       am_evo_batch_end(e, res, &w[0].geno, hooks, ...);
 *   }
 *   am_evo_gen_end(e, now);
 * Evaluating is the only step that may run on workers; the others run on the calling thread. An
 * item's whole result is its am_evo_result. */
/* starts a generation (the random pairing of parents, generation > 0); now: the caller's clock
 * in seconds (any origin; 0 without one) */
AM_API void am_evo_gen_begin(am_evo* e, double now);
/* makes the next batch's offspring (e->child) and their evaluation order (e->order, the largest
 * body first) with the workspace w; *m gets its size, 0 when every batch of the generation is
 * placed. On a failure e is as before am_evo_gen_begin. */
AM_API am_status am_evo_batch_begin(am_evo* e, am_geno_work* w, int* m, char* err, int errsz);
/* evaluates item i of the batch (child[order[i]]) on the workspace w into *r (skipped = 0) */
AM_API void am_evo_batch_eval(const am_evo* e, int i, am_evo_work* w, am_evo_result* r);
/* 1 while the batch under way may be cancelled: the generation's first, before it is placed */
AM_API int am_evo_batch_cancellable(const am_evo* e);
/* places the batch (res[i]: item i's result): history, best, crowding, hooks->evaluated (hooks may be
 * NULL). When a result is skipped, nothing is placed and e is left as before am_evo_gen_begin:
 * AM_ERR_CANCELLED ("interrupted") in the first batch, AM_ERR_ARG in a later one */
AM_API am_status am_evo_batch_end(am_evo* e, const am_evo_result* res, am_geno_work* w, const am_evo_hooks* hooks, char* err, int errsz);
/* ends the generation: e->last (wall_s: now minus am_evo_gen_begin's now), e->last_steps,
 * e->last_voxel_steps, e->generation + 1 */
AM_API void am_evo_gen_end(am_evo* e, double now);

/* Several runs in lockstep (amorph experiment): one generation of each unfinished run of
 * runs[0..n), n <= AM_EVO_WAVE_MAX, the offspring of all of them evaluated in one parallel map,
 * the largest bodies first, so the workers share n x population evaluations. hooks[k] (hooks may
 * be NULL) are run k's. wave is the merged map's scratch (large: declare it static); NULL is
 * allowed for n = 1. AM_OK when every unfinished run did its generation; AM_ERR_CANCELLED
 * ("interrupted") when a cancel callback stopped a first batch: the runs so stopped are as before
 * the call (their generation unchanged) and the others did theirs. Each run's result is what
 * am_evo_generation gives it alone; am_evo_generation is this over one run. */
typedef struct am_evo_wave {
    int run[AM_EVO_WAVE_MAX * AM_EVO_BATCH], idx[AM_EVO_WAVE_MAX * AM_EVO_BATCH]; /* map item j: item idx[j] of run run[j] */
    am_evo_result res[AM_EVO_WAVE_MAX * AM_EVO_BATCH];                            /* map item j's result */
} am_evo_wave;
AM_API am_status am_evo_generations(am_evo* const* runs, int n, am_evo_wave* wave, am_evo_work* w, const am_executor* ex,
                             const am_evo_hooks* hooks, char* err, int errsz);

/* evaluates one genome as the run does (expression, lattice, model, am_evaluate); rec and detail
 * may be NULL (detail gets the measurements: displacement, settling, voxels per material) */
AM_API void am_evo_evaluate(const am_evo_def* d, const am_palette* pal, const am_genome* g, am_evo_work* w,
                     am_record* rec, am_evo_ind* out, am_evo_eval* detail);
/* the model of w->lattice (with w->layers when w->has_layers) in d's environment evaluated by d's
 * evaluation into *out (rec may be NULL): what am_evo_evaluate does after the expression. AM_ERR_EMPTY (out untouched) for a body
 * with no voxel, a failure of am_model_build with its message, AM_ERR_RANGE (no step taken) for an
 * evaluation over the budget at this body's period (am_evo_check_budget) */
AM_API am_status am_evo_simulate(const am_evo_def* d, am_evo_work* w, am_record* rec, am_result* out, char* err, int errsz);
/* expresses g into lat with the run's palette and voxel size (the body alone: am_evo_express
 * gives its evolved fields too) */
AM_API am_status am_evo_lattice(const am_evo_def* d, const am_palette* pal, const am_genome* g, am_geno_work* w,
                         am_lattice* lat, char* err, int errsz);
/* expresses g into w->lattice as am_evo_lattice does, and a genome's evolved phases and
 * stiffnesses into w->layers (w->has_layers 1; 0 for a genome without them) */
AM_API am_status am_evo_express(const am_evo_def* d, const am_palette* pal, const am_genome* g, am_evo_work* w, char* err,
                                int errsz);
/* how the run's genomes become bodies: its palette, voxel size and evolved stiffness range */
AM_API am_express_def am_evo_express_def(const am_evo_def* d, const am_palette* pal);
/* a generation's parents in pairs: order[0..n-1] the members 0..n-1 shuffled from r (Fisher-Yates),
 * offspring 2k and 2k + 1 coming from members order[2k] and order[2k + 1] (am_evo_gen_begin's draw) */
AM_API void am_evo_pairing(am_rng* r, int n, int* order);
/* deterministic crowding's rule (Mahfoud 1996): 1 when offspring 1 meets parent a and offspring
 * 2 parent b (d1a + d2b <= d2a + d1b, the body distances of each offspring to each parent), 0
 * when they meet the other way round */
AM_API int am_evo_crowd_straight(am_real d1a, am_real d1b, am_real d2a, am_real d2b);
/* the 64-bit hash of the run so far: every genome and fitness evaluated, in order, and the
 * final population (what `make repro` compares across platforms) */
AM_API uint64_t am_evo_hash(const am_evo* e);


/* ==== the run folder of amorph evolve and the experiment folder of amorph experiment
 * (docs/evolve.md; src/evo/evo_run.c): the names of their files, and below the rows of log.csv,
 * evals.csv and results.csv and the reader of log.csv (config.txt is am_evo_write's, the
 * checkpoint amorph/io.h's). The program reads and writes the files through the port; every place
 * that names one uses these. */
#define AM_RUN_CONFIG "config.txt"         /* the settings, key = value */
#define AM_RUN_LOG "log.csv"               /* a row per generation (am_evo_log_row) */
#define AM_RUN_EVALS "evals.csv"           /* a row per evaluation (am_evo_evals_row) */
#define AM_RUN_CHECKPOINT "checkpoint.txt" /* the whole state, to resume from */
#define AM_RUN_BEST_GENOME "best.genome"
#define AM_RUN_BEST_LATTICE "best.lattice"
#define AM_RUN_SUMMARY_TXT "summary.txt"   /* at the end: key = value lines */
#define AM_RUN_SUMMARY_JSON "summary.json" /* the same as one JSON object */
#define AM_RUN_LOCK "lock"                 /* held while a process runs the folder */
#define AM_RUN_BEST_PNG "best.png"         /* at the end, with pictures: the best robot's filmstrip */
#define AM_RUN_BEST_HTML "best.html"       /* its viewer page */
#define AM_RUN_FITNESS_SVG "fitness.svg"   /* the best fitness against evaluations */
/* an experiment folder: its run folders <variant>-<k>, and */
#define AM_EXP_ABOUT "experiment.txt"      /* what the experiment is */
#define AM_EXP_RESULTS "results.csv"       /* mean and standard error per variant (am_exp_results_row) */


/* ---- statistics ---- */

/* the log.csv header line (no newline) and one row for s; returns the characters written */
AM_API const char* am_evo_log_header(void);
AM_API int am_evo_log_row(const am_evo_stats* s, char* buf, int cap);

/* log.csv read back line by line (a file streamed through a small buffer, or held whole): begin,
 * one call per line, end. The header is the first line that is not blank; the reader finds its
 * columns there by name, so a log with its columns in another order, or with columns it does not
 * know, still reads. generation, evaluations and best are required; mean, median, diverged,
 * empty, wall_s and unsettled fill their fields when the header has them, else they are left NAN
 * (mean, median, wall_s) or -1 (diverged, empty, unsettled). Blank lines are skipped and a CR before
 * the newline is dropped. Messages are "fname:line: problem": a header without a required column
 * (or naming one twice), a row without as many fields as the header, a field that is not a finite
 * number (or, for generation, evaluations, diverged, empty and unsettled, not a whole number from
 * 0). */
#define AM_EVO_LOG_COLUMNS 9          /* the columns of am_evo_log_header */
typedef struct am_evo_log_reader {
    const char* fname;                /* for messages; must stay valid while reading */
    int line;                         /* lines read */
    int header;                       /* 1 once the header was read */
    int columns;                      /* columns the header names */
    int col[AM_EVO_LOG_COLUMNS];      /* the column (from 0) of each name of am_evo_log_header, in
                                       * its order; -1 when the header has none */
    long rows;                        /* rows read */
    am_status st;                     /* the first failure: every later call returns it */
} am_evo_log_reader;
AM_API void am_evo_log_read_begin(am_evo_log_reader* r, const char* fname);
/* one line of n characters without its newline (nothing past them is read): a row is parsed into
 * *row and *is_row set to 1; the header and blank lines set *is_row to 0 and leave *row alone
 * (is_row may be NULL: r->rows counts the rows) */
AM_API am_status am_evo_log_read_line(am_evo_log_reader* r, const char* text, long n, am_evo_stats* row, int* is_row, char* err,
                               int errsz);
/* after the last line: AM_OK when the header was read (a log may have no rows yet) */
AM_API am_status am_evo_log_read_end(am_evo_log_reader* r, char* err, int errsz);
/* the evals.csv header line of a run with `materials` materials (no newline), and one row for an
 * evaluation; both return the characters written (cut to cap - 1). docs/evolve.md gives the
 * columns. AM_EVO_EVALS_ROW_MAX: a capacity every header and row fits. */
#define AM_EVO_EVALS_ROW_MAX (320 + 12 * AM_MAX_GENO_MATERIALS)
AM_API int am_evo_evals_header(int materials, char* buf, int cap);
AM_API int am_evo_evals_row(const am_evo_def* d, const am_evo_ind* ind, const am_evo_eval* ev, char* buf, int cap);
/* an experiment's results.csv: its header line (no newline), and one row (no newline) for a variant
 * at an evaluation count: the mean and the standard error of its runs' best fitness there; returns
 * the characters written (cut to cap - 1). AM_EXP_RESULTS_ROW_MAX: a capacity every row fits with
 * a variant name of up to 160 characters. */
#define AM_EXP_RESULTS_ROW_MAX 256
AM_API const char* am_exp_results_header(void);
AM_API int am_exp_results_row(const char* variant, long evaluations, double mean, double stderr_best, long runs, char* buf, int cap);

#ifdef __cplusplus
}
#endif
#endif
