/* geno_internal.h: what the genotype files share (not public).
 *
 * The library's genotype sources (src/geno/geno_*.c, src/geno/geno_format.c) include this header; the
 * public interface is include/amorph/geno.h. Here: the operations table every representation
 * implements and its dispatch, the helpers of the representations' text lines, the lookup tables
 * of the CPPN and GMX functions (read with linear interpolation, see src/geno/geno_common.c), the value
 * perturbation of mutations, and the steps of the GMX and CPPN operators that tests/test_geno.c
 * checks one by one.
 */
#ifndef AMORPH_GENO_INTERNAL_H
#define AMORPH_GENO_INTERNAL_H

#include <stdint.h>
#include "amorph/geno.h"

/* ---- representations ---- */

/* the operations one representation implements (genome header fields are set by the caller); the
 * struct am_geno_ops that amorph/geno.h's am_genome_reader points to */
typedef struct am_geno_ops {
    const char* name;                                  /* keyword of the text format */
    /* random genes from def (the header is set and checked) */
    am_status (*init)(am_genome* g, const am_geno_def* def, am_rng* r, char* err, int errsz);
    /* mutation in place */
    void (*mutate)(am_genome* g, const am_geno_def* def, am_rng* r);
    /* two children of same-shaped parents; c2 may be NULL */
    void (*crossover)(const am_genome* a, const am_genome* b, am_genome* c1, am_genome* c2,
                      const am_geno_def* def, am_rng* r);
    /* 1 when the representation's sizes match (headers already equal) */
    int (*same_shape)(const am_genome* a, const am_genome* b);
    /* every value in range and capacity */
    am_status (*check)(const am_genome* g, char* err, int errsz);
    /* evolvable values */
    int (*values)(const am_genome* g);
    /* h extended with every value */
    uint64_t (*hash)(uint64_t h, const am_genome* g);
    /* 1 when every value is the same, bit for bit */
    int (*equal)(const am_genome* a, const am_genome* b);
    void (*express)(const am_genome* g, am_geno_work* w); /* fills w->dens (materials x cells) */
    void (*format)(const am_genome* g, am_text* s);  /* the body lines, shape line first (am_text_put) */
    /* one line after the header, split into ntok fields; the message without "file:line: " */
    am_status (*parse_line)(am_genome* g, am_geno_parse* ps, int ntok, char** tok, char* err, int errsz);
    am_status (*parse_end)(am_genome* g, am_geno_parse* ps, char* err, int errsz); /* at "end" */
} am_geno_ops;

extern const am_geno_ops am_geno_dct_ops;   /* src/geno/geno_dct.c */
extern const am_geno_ops am_geno_cppn_ops;  /* src/geno/geno_cppn.c */
extern const am_geno_ops am_geno_gmx_ops;   /* src/geno/geno_gmx.c */
/* the operations of repr, or NULL */
const am_geno_ops* am_geno_ops_of(int repr);

/* what a field index names in messages: "material", or "field" in a genome with evolved fields */
static inline const char* am_geno_field_word(const am_genome* g) { return g->controls ? "field" : "material"; }

/* ---- text lines ---- */

/* appends " " and a real that reads back bit for bit (%.9g for float, %.17g for double) */
void am_geno_put_real(am_text* s, am_real v);
/* token helpers for line parsers: 1 on success */
int am_geno_tok_int(const char* s, int lo, int hi, int* out);   /* decimal integer in [lo, hi] */
int am_geno_tok_real(const char* s, am_real lo, am_real hi, am_real* out); /* finite real in [lo, hi] */

/* ---- lookup tables and mutation ---- */

#define AM_GENO_GAUSS_RANGE AM_R(16)  /* e^(-q) is taken as 0 for q > 16 (e^-16 = 1.1e-7) */
#define AM_GENO_SIG_RANGE AM_R(16)    /* the sigmoid is taken as +-1 (to 2.3e-7) beyond |t| > 16 */

/* fills the lookup tables of w once (with am_sin and am_exp); expressions call it themselves */
void am_geno_tables(am_geno_work* w);
#if defined(AM_REAL_FIXED_POINT)
/* fixed point: the table position u is held as a table index and a Q24 fraction (the index range,
 * up to AM_GENO_TABLE, is beyond the Q7.24 range of am_real) */
static inline am_real am_geno_lerp_fx(const am_real* tab, int64_t pos)
{
    if (!(pos > 0)) return tab[0];
    if (!(pos < ((int64_t)AM_GENO_TABLE << AM_FIX_FRAC))) return tab[AM_GENO_TABLE];
    int i = (int)(pos >> AM_FIX_FRAC);
    am_real f = (am_real)(pos & (AM_FIX_ONE - 1));
    return tab[i] + AM_MUL(f, tab[i + 1] - tab[i]);
}
static inline am_real am_geno_sin(const am_geno_work* w, am_real t)
{
    const am_real turns = AM_MUL(t, AM_R(0.15915494309189533577)); /* t / (2 pi) */
    return am_geno_lerp_fx(w->tab_sin, (int64_t)(turns - am_floor(turns)) * AM_GENO_TABLE);
}
static inline am_real am_geno_gauss(const am_geno_work* w, am_real q)
{
    if (!(q < AM_GENO_GAUSS_RANGE)) return AM_R(0);
    return am_geno_lerp_fx(w->tab_gauss, (int64_t)q * (AM_GENO_TABLE / 16)); /* AM_GENO_GAUSS_RANGE is 16 */
}
static inline am_real am_geno_sigmoid(const am_geno_work* w, am_real t)
{
    return am_geno_lerp_fx(w->tab_sig, ((int64_t)t + AM_GENO_SIG_RANGE) * (AM_GENO_TABLE / 32)); /* 2 AM_GENO_SIG_RANGE is 32 */
}
#else
/* linear interpolation in a table of AM_GENO_TABLE intervals, u in [0, AM_GENO_TABLE] (clamped) */
static inline am_real am_geno_lerp(const am_real* tab, am_real u)
{
    if (!(u > AM_R(0))) return tab[0];
    if (!(u < (am_real)AM_GENO_TABLE)) return tab[AM_GENO_TABLE];
    int i = (int)u;
    am_real f = u - (am_real)i;
    return tab[i] + AM_MUL(f, tab[i + 1] - tab[i]);
}
/* sin t from the table (0 for a non-finite t) */
static inline am_real am_geno_sin(const am_geno_work* w, am_real t)
{
    const am_real turns = AM_MUL(t, AM_R(0.15915494309189533577)); /* t / (2 pi) */
    if (!am_finite(turns)) return AM_R(0);
    return am_geno_lerp(w->tab_sin, AM_MUL(turns - am_floor(turns), (am_real)AM_GENO_TABLE));
}
/* e^(-q) from the table, q >= 0 (0 beyond AM_GENO_GAUSS_RANGE) */
static inline am_real am_geno_gauss(const am_geno_work* w, am_real q)
{
    if (!(q < AM_GENO_GAUSS_RANGE)) return AM_R(0);
    return am_geno_lerp(w->tab_gauss, AM_MUL(q, AM_DIV((am_real)AM_GENO_TABLE, AM_GENO_GAUSS_RANGE)));
}
/* 2 / (1 + e^-t) - 1 from the table (0 for NaN) */
static inline am_real am_geno_sigmoid(const am_geno_work* w, am_real t)
{
    if (t != t) return AM_R(0);
    return am_geno_lerp(w->tab_sig, AM_MUL(t + AM_GENO_SIG_RANGE, AM_DIV((am_real)AM_GENO_TABLE, AM_R(2) * AM_GENO_SIG_RANGE)));
}
#endif
#if defined(AM_REAL_FIXED_POINT)
/* e^(-t^2) from the table (t^2 would leave the fixed-point range where the table is 0 anyway) */
#define AM_GENO_GAUSS_SQ(w, t) (am_fabs(t) < AM_R(4) ? am_geno_gauss((w), AM_MUL((t), (t))) : AM_R(0))
#else
#define AM_GENO_GAUSS_SQ(w, t) am_geno_gauss((w), AM_MUL((t), (t)))
#endif
/* the evolved fields of a representation whose fields are plain sums (DCT, CPPN), rows
 * materials.. of w->dens, turned into what expression quantises: field f gives a phase of f / 2
 * periods (wrapped: a field spanning [-1, 1] spans one period) and a stiffness of (f + 1) / 2 in
 * [0, 1] (clamped). Nothing for a genome without them */
void am_geno_controls_of_fields(const am_genome* g, am_geno_work* w);
/* a value moved by a uniform step in [-step, step] and reflected into [lo, hi] */
am_real am_geno_perturb(am_rng* r, am_real v, am_real step, am_real lo, am_real hi);

/* ---- for tests: the crossovers' steps and the CPPN complexity limit ---- */

/* GMX crossover, step 1 (exposed for tests): a random plane through g's workspace, a point
 * uniform in the box (cells) and a unit normal uniform on the sphere */
void am_gmx_random_plane(const am_genome* g, am_rng* r, am_real point[3], am_real normal[3]);
/* GMX crossover, step 2: c1 gets a's points with (p - point) . normal >= 0, then b's points on the
 * other side; c2 gets b's positive side, then a's negative side; in order, up to max_points each */
void am_gmx_plane_cross(const am_genome* a, const am_genome* b, const am_real point[3], const am_real normal[3],
                        int max_points, am_genome* c1, am_genome* c2);
/* CPPN region crossover, exposed for tests: the region (layers [l0, l1), positions [j0, j1)) a
 * crossover draws; every node is inside it with the same probability */
void am_cppn_random_region(const am_genome* g, am_rng* r, int* l0, int* l1, int* j0, int* j1);
/* CPPN complexity limit on g's workspace: writes each node's effective x scaling into eff and
 * returns how many nodes were limited (docs/genotypes.md, complexity measure) */
int am_cppn_effective_xscale(const am_genome* g, am_real eff[AM_MAX_CPPN_LAYERS][AM_MAX_CPPN_NODES]);

#endif
