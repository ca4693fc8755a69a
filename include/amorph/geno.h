/* amorph/geno.h: the genotype layer (src/geno/): level-set genomes (DCT, CPPN, Gaussian mixtures),
 * their operators, their expression into a lattice and their text format. It includes
 * amorph/base.h and amorph/sim.h.
 */
#ifndef AMORPH_GENO_H
#define AMORPH_GENO_H

#include <stdint.h>
#include "amorph/base.h"
#include "amorph/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ==== level-set genotypes (DCT, CPPN, GMX) and their expression into voxel bodies.
 *
 * A genome describes one density field per material on a W x H x D workspace (docs/genotypes.md).
 * Expression evaluates the fields, fills every cell whose density sum exceeds the threshold (0),
 * gives it the material of highest density (argmax, ties to the lower index), and keeps only the
 * largest face-connected piece. An empty body is a valid result (0 voxels, no error); the evolver
 * gives it zero fitness.
 *
 * am_genome is a fixed-size tagged union, copyable by assignment (the evolver keeps a population
 * of them). Every representation implements the same operations (am_geno_ops, in the library's
 * internal src/geno/geno_internal.h): a new one is one new source file, one member of the union and one
 * line in the dispatch table.
 *
 * The distance used by deterministic crowding compares the expressed bodies, not the genes: see
 * am_genome_distance. Randomness comes only from the caller's am_rng, consumed serially.
 */

/* ---- representations ---- */

typedef enum am_repr { AM_REPR_NONE = 0, AM_REPR_DCT = 1, AM_REPR_CPPN = 2, AM_REPR_GMX = 3 } am_repr;
#define AM_REPR_COUNT 4 /* one past the last am_repr */

/* CPPN node functions: f(t) with t = xscale (input - offset); node output yscale f(t) */
typedef enum am_cppn_fn {
    AM_FN_SIGMOID = 0, /* 2 / (1 + e^-t) - 1, in (-1, 1) */
    AM_FN_GAUSS = 1,   /* 2 e^(-t^2) - 1, in (-1, 1] */
    AM_FN_SINE = 2,    /* sin t */
    AM_FN_ABS = 3,     /* |t| */
    AM_FN_LINEAR = 4,  /* t */
    AM_FN_COUNT = 5
} am_cppn_fn;

/* value ranges (every init, mutation and parsed file stays inside them) */
#define AM_DCT_AMP_MAX AM_R(1)        /* DCT amplitudes in [-1, 1] */
#define AM_CPPN_OFFSET_MAX AM_R(1)    /* node offset in [-1, 1] (input units) */
#define AM_CPPN_XSCALE_MAX AM_R(4)    /* node x scaling in [-4, 4] */
#define AM_CPPN_YSCALE_MAX AM_R(2)    /* node y scaling in [-2, 2] */
#define AM_CPPN_WEIGHT_MAX AM_R(2)    /* connection weight in [-2, 2] */
#define AM_GMX_WEIGHT_MAX AM_R(1)     /* GMX point weight in [-1, 1] */
#define AM_GMX_RADIUS_MIN AM_R(1)     /* GMX radius in [1, max(W, H, D) / 2] cells */
#define AM_GMX_ISO AM_R(0.5)          /* GMX iso-level: fields are sum w g - AM_GMX_ISO / materials */

/* Evolved fields beyond the materials (docs/genotypes.md, Evolved actuation): a genome may also
 * describe each voxel's actuation phase and its stiffness. They follow the material fields in a
 * genome's field order (phase first): DCT one more amplitude matrix each, CPPN one more output
 * each, GMX a phase and a stiffness on every point. Expression quantises them to a byte a cell
 * (am_geno_work.ctl), the same bytes a run compares, remembers and simulates. */
enum { AM_CTL_PHASE = 1, AM_CTL_STIFFNESS = 2 };
#define AM_CTL_ALL (AM_CTL_PHASE | AM_CTL_STIFFNESS)

/* DCT: a k x k x k amplitude matrix per field */
typedef struct am_dct_genome {
    int k;                                   /* amplitudes per axis, 1..AM_MAX_DCT_K, <= each side */
    am_real amp[AM_MAX_GENO_FIELDS][AM_MAX_DCT_K * AM_MAX_DCT_K * AM_MAX_DCT_K];
                                             /* (fields x k^3) in [-1, 1] at u + k (v + k w) */
} am_dct_genome;

/* one CPPN node */
typedef struct am_cppn_node {
    am_real offset;                          /* shift of the input (x axis of the function) */
    am_real xscale;                          /* scaling of the input (x axis) */
    am_real yscale;                          /* scaling of the output (y axis) */
    uint8_t fn;                              /* am_cppn_fn */
} am_cppn_node;

/* CPPN: m layers of n nodes; inputs x, y, z (the longest side spans [-1, 1]) and a bias of 1 */
typedef struct am_cppn_genome {
    int layers;                              /* m, 1..AM_MAX_CPPN_LAYERS */
    int nodes;                               /* n, 1..AM_MAX_CPPN_NODES */
    am_cppn_node node[AM_MAX_CPPN_LAYERS][AM_MAX_CPPN_NODES]; /* (m x n) */
    am_real w_in[AM_MAX_CPPN_NODES][4];      /* (n x 4) input x, y, z, bias -> node (0, j) */
    uint8_t on_in[AM_MAX_CPPN_NODES][4];     /* 1: that connection is active */
    am_real w[AM_MAX_CPPN_LAYERS - 1][AM_MAX_CPPN_NODES][AM_MAX_CPPN_NODES];
                                             /* ((m-1) x n x n) w[l][j][i]: node (l, i) -> (l + 1, j) */
    uint8_t on[AM_MAX_CPPN_LAYERS - 1][AM_MAX_CPPN_NODES][AM_MAX_CPPN_NODES]; /* active flags */
    am_real w_out[AM_MAX_GENO_FIELDS][AM_MAX_CPPN_NODES]; /* (fields x n) node (m-1, j) -> output */
    uint8_t on_out[AM_MAX_GENO_FIELDS][AM_MAX_CPPN_NODES]; /* active flags */
} am_cppn_genome;

/* one Gaussian point: adds weight e^(-(d / radius)^2) to its material's field at distance d */
typedef struct am_gmx_point {
    am_real x, y, z;                         /* centre, cells: [0, W-1] x [0, H-1] x [0, D-1] */
    am_real weight;                          /* signed weight, [-1, 1] */
    am_real radius;                          /* cells, [1, max(W, H, D) / 2] */
    uint8_t mat;                             /* material index, < materials */
#if AM_GENO_LAYERS
    am_real phase;                           /* periods, [0, 1): its actuation phase (AM_CTL_PHASE) */
    am_real stiff;                           /* [0, 1] of the run's stiffness range (AM_CTL_STIFFNESS) */
#endif
} am_gmx_point;

/* GMX: an ordered list of Gaussian points */
typedef struct am_gmx_genome {
    int count;                               /* points in use, 0..AM_MAX_GMX_POINTS */
    am_gmx_point pt[AM_MAX_GMX_POINTS];
} am_gmx_genome;

/* a genome of any representation; fixed size, copy by assignment */
typedef struct am_genome {
    int repr;                                /* am_repr */
    int materials;                           /* density fields, 1..AM_MAX_GENO_MATERIALS */
    int controls;                            /* AM_CTL_* bits: the evolved fields it carries besides (0: none) */
    int nx, ny, nz;                          /* workspace, cells, 1..AM_MAX_DIM each */
    char mat[AM_MAX_GENO_MATERIALS][AM_NAME_MAX]; /* palette name of each material */
    union {
        am_dct_genome dct;                   /* repr == AM_REPR_DCT */
        am_cppn_genome cppn;                 /* repr == AM_REPR_CPPN */
        am_gmx_genome gmx;                   /* repr == AM_REPR_GMX */
    };
} am_genome;

/* ---- parameters ---- */

/* how random genomes are made and varied; am_default_geno() gives the seed's settings */
typedef struct am_geno_def {
    int repr;                 /* am_repr (AM_REPR_DCT) */
    int materials;            /* density fields, 1..AM_MAX_GENO_MATERIALS (2: passive, active) */
    int controls;             /* AM_CTL_* bits: evolved phase and stiffness fields (0: none, the seed's) */
    char mat[AM_MAX_GENO_MATERIALS][AM_NAME_MAX]; /* palette name of each field; "" (the default):
                                                   * the seed's passive, active, active90 */
    int nx, ny, nz;           /* workspace, cells (AM_MAX_DIM: 20 desktop, 8 board) */
    int dct_k;                /* DCT amplitudes per axis (4) */
    int cppn_layers;          /* CPPN layers m (3) */
    int cppn_nodes;           /* CPPN nodes per layer n (4) */
    am_real cppn_active;      /* CPPN: probability that a connection of a random genome is active (0.75) */
    am_real cppn_changes;     /* CPPN: values a mutation changes on average (1) */
    am_real cppn_step;        /* CPPN: largest change of a real value, fraction of its range (0.10) */
    int gmx_points;           /* GMX points of a random genome (16) */
    int gmx_max_points;       /* GMX points a genome may grow to, <= AM_MAX_GMX_POINTS (AM_MAX_GMX_POINTS) */
    am_real rate;             /* DCT and GMX: per-value mutation probability (0.20) */
    am_real step;             /* DCT and GMX: largest change, fraction of the value's range (0.05) */
    am_real gmx_material_rate; /* GMX: per-point probability that a mutation changes its material (0.05) */
    am_real gmx_add;          /* GMX: probability that a mutation adds a random point (0.10) */
    am_real gmx_remove;       /* GMX: probability that a mutation removes a point (0.10) */
} am_geno_def;

/* the seed's settings: DCT, 2 materials (names ""), AM_MAX_DIM^3, rates as documented field by field */
AM_API am_geno_def am_default_geno(void);

/* how a genome becomes a body; am_default_express() gives the seed's */
typedef struct am_express_def {
    const am_palette* palette; /* materials are looked up by the genome's names; NULL: am_default_palette() */
    am_param voxel_size;       /* lattice cell edge, m (0.01) */
    am_real threshold;         /* a cell is filled where the density sum exceeds this (0) */
    am_param stiffness_min;    /* Pa: an evolved stiffness's range, byte 0 .. (1e5) */
    am_param stiffness_max;    /* Pa: .. byte 255, geometric between (1e7; at most 100 x stiffness_min) */
} am_express_def;

/* default palette, 0.01 m voxels, threshold 0, evolved stiffnesses 1e5 to 1e7 Pa */
AM_API am_express_def am_default_express(void);

/* ---- workspace ---- */

/* scratch and results of expression; large: declare it static (zeroed), one per thread */
typedef struct am_geno_work {
    /* (materials x cells) density fields, lattice order; then the evolved fields' rows (two each:
     * a representation may need both before it reduces them to one) */
    am_real dens[AM_MAX_GENO_MATERIALS + 2 * AM_GENO_CONTROLS][AM_MAX_CELLS];
    uint8_t cell[AM_MAX_CELLS];      /* (cells) the body: 0 empty, 1 + material index */
    int voxels;                      /* filled cells of cell[] */
    int nx, ny, nz;                  /* shape of dens and cell */
    uint8_t other[AM_MAX_CELLS];     /* (cells) a second body: am_genome_distance's, the evolver's crowding's */
#if AM_GENO_LAYERS
    int controls;                    /* the AM_CTL_* fields of the last expression (0: ctl[] not set) */
    uint8_t ctl[AM_GENO_CONTROLS][AM_MAX_CELLS];   /* [0] phase in 1/256 periods, [1] stiffness byte, of
                                                    * every filled cell of cell[] (0 in empty cells) */
    uint8_t other_ctl[AM_GENO_CONTROLS][AM_MAX_CELLS]; /* the same of other[] */
#endif
    am_dct_work dct;                 /* DCT basis tables (cached) */
    /* lookup tables of the CPPN and GMX functions (filled and read by src/geno/geno_internal.h's helpers) */
    int tables;                      /* 1 once the lookup tables below are filled */
    am_real tab_sin[AM_GENO_TABLE + 1];   /* sin(2 pi i / T), T = AM_GENO_TABLE */
    am_real tab_gauss[AM_GENO_TABLE + 1]; /* e^(-q) at q = 16 i / T (AM_GENO_GAUSS_RANGE = 16) */
    am_real tab_sig[AM_GENO_TABLE + 1];   /* 2 / (1 + e^-t) - 1 at t = 16 (2 i / T - 1) (AM_GENO_SIG_RANGE = 16) */
    /* scratch of one step of an expression: the representation's fields, then the level set. No
     * member outlives the step that uses it, so they share memory */
    union {
        am_dct_scratch dct;                   /* DCT: the passes of the inverse transform */
        struct {
            am_real coord[3][AM_CPPN_CHUNK];  /* CPPN inputs of one chunk of cells */
            am_real act[2][AM_MAX_CPPN_NODES][AM_CPPN_CHUNK]; /* CPPN node values of one chunk (two layers) */
        } cppn;
        struct {
            am_real fx[AM_MAX_DIM], fy[AM_MAX_DIM], fz[AM_MAX_DIM]; /* GMX separable falloff factors */
        } gmx;
        struct {
            uint8_t mark[AM_MAX_CELLS];       /* (cells) flood-fill marks */
            int32_t queue[AM_MAX_CELLS];      /* (cells) flood-fill queue */
        } piece;                              /* the level set's largest piece */
    } scratch;
} am_geno_work;

/* ---- operations ---- */

/* a random genome: every value uniform in its range (docs/genotypes.md). AM_ERR_RANGE or
 * AM_ERR_CAPACITY (with a message) for a def outside the limits */
AM_API am_status am_genome_init(am_genome* g, const am_geno_def* def, am_rng* r, char* err, int errsz);
/* mutates g in place (rates in def, which must not be NULL; its shape fields are not used) */
AM_API void am_genome_mutate(am_genome* g, const am_geno_def* def, am_rng* r);
/* two children of parents a and b (same representation and shape); c1 takes a's part where c2
 * takes b's (complementary). c2 may be NULL; the children must not alias the parents. AM_ERR_ARG
 * (c1 = a, c2 = b) when the shapes differ */
AM_API am_status am_genome_crossover(const am_genome* a, const am_genome* b, am_genome* c1, am_genome* c2,
                              const am_geno_def* def, am_rng* r, char* err, int errsz);
/* checks every field against its range and capacity; AM_ERR_RANGE / AM_ERR_CAPACITY with a message */
AM_API am_status am_genome_check(const am_genome* g, char* err, int errsz);
/* evolvable values of g (DCT: amplitudes; CPPN: 4 per node, 2 per connection; GMX: 6 per point
 * and one more per evolved field) */
AM_API int am_genome_values(const am_genome* g);
/* 64-bit hash of every value of g (golden hashes in tests) */
AM_API uint64_t am_genome_hash(const am_genome* g);
/* 1 when a and b hold the same values, bit for bit */
AM_API int am_genome_equal(const am_genome* a, const am_genome* b);
/* name of a representation ("dct", "cppn", "gmx"), or "?" */
AM_API const char* am_repr_name(int repr);
/* representation of a name, or AM_REPR_NONE */
AM_API int am_repr_from_name(const char* name);

/* densities into w->dens, then the level set into w->cell and w->voxels (def NULL: defaults).
 * ratio (NULL or materials x cells) receives the blend ratios of am_levelset. */
AM_API am_status am_genome_express(const am_genome* g, const am_express_def* def, am_geno_work* w, am_real* ratio,
                            char* err, int errsz);
/* expresses g into lat: nx x ny x nz cells, palette = the genome's materials (found by name in
 * def->palette) in genome order, cell value 1 + material index. AM_ERR_RANGE for an unknown name */
AM_API am_status am_genome_to_lattice(const am_genome* g, const am_express_def* def, am_geno_work* w, am_lattice* lat,
                               char* err, int errsz);
/* the crowding distance: fraction of workspace cells (in [0, 1]) whose material differs between the
 * two expressed bodies; expresses both (w->cell ends as b's body). AM_ERR_ARG for different workspaces */
AM_API am_status am_genome_distance(const am_genome* a, const am_genome* b, am_geno_work* w, am_real* out,
                             char* err, int errsz);
/* the same distance between two bodies already expressed: fraction of the n cells that differ */
AM_API am_real am_body_distance(const uint8_t* a, const uint8_t* b, int n);

/* fields of g: its materials, then its evolved fields (AM_CTL_*) */
static inline int am_genome_fields(const am_genome* g)
{
    return g->materials + (g->controls & AM_CTL_PHASE ? 1 : 0) + (g->controls & AM_CTL_STIFFNESS ? 1 : 0);
}
/* the field index of evolved field ctl (AM_CTL_PHASE or AM_CTL_STIFFNESS) of g, or -1 */
static inline int am_genome_field_of(const am_genome* g, int ctl)
{
    if (!(g->controls & ctl)) return -1;
    return g->materials + (ctl == AM_CTL_STIFFNESS && (g->controls & AM_CTL_PHASE) ? 1 : 0);
}
/* the body's layers from the last expression of g on w (am_genome_express): phase[] from its phase
 * field (byte / 256 periods), stiffness[] from its stiffness field (def's range, geometric); the
 * flags of the fields g does not carry 0, no boundary conditions. AM_ERR_CAPACITY in a build
 * without AM_GENO_LAYERS, AM_ERR_ARG when w does not hold g's expression */
AM_API am_status am_genome_layers(const am_genome* g, const am_express_def* def, const am_geno_work* w, am_layers* out,
                                  char* err, int errsz);
/* the stiffness of byte s (0..255) in def's range: stiffness_min (stiffness_max / stiffness_min)^(s / 255), Pa */
AM_API am_param am_stiffness_of_byte(const am_express_def* def, int s);
/* the crowding distance of bodies that carry evolved fields: per cell 1 where the materials differ,
 * else the mean over the fields in `controls` of the phase's circular difference (half a period: 1)
 * and the stiffness byte's difference (/ 255); averaged over the n cells. controls 0 is
 * am_body_distance. actl / bctl: the bodies' rows as am_geno_work.ctl holds them */
AM_API am_real am_body_distance_ctl(const uint8_t* a, const uint8_t* actl0, const uint8_t* actl1, const uint8_t* b,
                                    const uint8_t* bctl0, const uint8_t* bctl1, int controls, int n);

/* ---- level set ---- */

/* the level set of w->dens (materials fields of nx x ny x nz): cells whose density sum exceeds
 * threshold are filled with 1 + argmax material, then only the largest face-connected piece is kept
 * (ties: the piece holding the lowest cell index). Writes w->cell, w->voxels and returns the
 * voxel count. ratio (NULL or materials x cells, index m * cells + c) receives the blend ratios of
 * the seed's alternative: max(d_m, 0) / sum_i max(d_i, 0) in kept cells, 0 elsewhere.
 * materials 1..AM_MAX_GENO_MATERIALS and nx ny nz <= AM_MAX_CELLS, else nothing is done and 0 returned. */
AM_API int am_levelset(am_geno_work* w, int materials, int nx, int ny, int nz, am_real threshold, am_real* ratio);
/* keeps only the largest face-connected piece of non-zero cells (fixed queue, no recursion);
 * mark and queue have nx ny nz entries (each >= 1). Returns the cells kept. */
AM_API int am_keep_largest_piece(uint8_t* cell, int nx, int ny, int nz, uint8_t* mark, int32_t* queue);

/* ---- text format (docs/formats.md) ---- */

/* 1 when text is a genome (its first word is "amorph-genome") */
AM_API int am_genome_sniff(const char* text);
/* writes g as text to out, a whole-text buffer or a stream (amorph/base.h); AM_ERR_CAPACITY or
 * AM_ERR_IO (with a message) when out dropped text */
AM_API am_status am_genome_write(const am_genome* g, am_text* out, char* err, int errsz);
/* writes g as text into buf (capacity cap, NUL-terminated); *len gets the length. AM_ERR_CAPACITY
 * if it does not fit (AM_GENOME_TEXT_MAX always does) */
AM_API am_status am_genome_format(const am_genome* g, char* buf, long cap, long* len, char* err, int errsz);
/* parses a NUL-terminated genome text; messages are "fname:line: problem" */
AM_API am_status am_genome_parse(am_genome* g, const char* text, const char* fname, char* err, int errsz);

/* ---- reading a genome line by line ---- */

/* lines a representation may require to appear once each (the largest over all of them) */
#define AM_GENO_SEEN_MAX (AM_MAX_GENO_FIELDS * AM_MAX_DCT_K * AM_MAX_DCT_K \
                          + 2 * AM_MAX_CPPN_LAYERS * AM_MAX_CPPN_NODES + AM_MAX_GENO_FIELDS + 8)
/* state a representation's line parser keeps (part of am_genome_reader; not for callers) */
typedef struct am_geno_parse {
    int shape;                          /* 1 once the representation's shape line was read */
    int lines;                          /* data lines accepted */
    uint8_t seen[AM_GENO_SEEN_MAX];     /* 1 for each required line already read */
} am_geno_parse;

/* the operations of one representation: defined in src/geno/geno_internal.h, opaque here */
struct am_geno_ops;

/* a genome read line by line, for text that is not held whole (a file streamed through a small
 * buffer): begin, one call per line, end. am_genome_parse is these calls over a whole text and
 * gives the same genome and messages. The members are the reader's own state. */
typedef struct am_genome_reader {
    am_genome* g;                  /* the genome being read */
    const char* fname;             /* for messages; must stay valid while reading */
    int state;                     /* the header line expected next, or the body */
    int version;                   /* the format version its first line gave */
    int lineno;                    /* lines read */
    am_status st;                  /* the first failure: every later call returns it */
    am_geno_parse ps;
    const struct am_geno_ops* ops; /* the representation's, once its line was read */
} am_genome_reader;
AM_API void am_genome_read_begin(am_genome_reader* r, am_genome* g, const char* fname);
/* one line of n characters without its newline (text[n] is '\n' or NUL); messages "fname:line: problem" */
AM_API am_status am_genome_read_line(am_genome_reader* r, const char* text, long n, char* err, int errsz);
/* after the last line: AM_OK when the genome ended with its 'end' line */
AM_API am_status am_genome_read_end(am_genome_reader* r, char* err, int errsz);

#ifdef __cplusplus
}
#endif
#endif
