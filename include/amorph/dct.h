/* amorph/dct.h: the hand-written, separable 3-D discrete cosine transform.
 *
 * Orthonormal pair: the forward transform is the DCT-II and the inverse the DCT-III, each scaled so
 * that the basis is orthonormal. Along one axis of n cells, coefficient u and cell x:
 *     B[u][x] = c_u cos(pi (2x + 1) u / (2n)),   c_0 = sqrt(1/n), c_u = sqrt(2/n) for u > 0
 *     inverse:  f[x] = sum_u a[u] B[u][x]          forward:  a[u] = sum_x f[x] B[u][x]
 * In 3-D the basis is the product of the three axes'. Only the k lowest coefficients per axis are
 * held (k <= n): the inverse zero-pads them to the n-cell workspace, the forward keeps the k lowest
 * (with k = n the two are exact inverses). The tables are computed once per (k, n) with am_cos and
 * cached in the caller's am_dct_work; the passes run axis by axis (through the caller's
 * am_dct_scratch), so the inverse costs
 * nx k^3 + nx ny k^2 + nx ny nz k multiply-adds instead of nx ny nz k^3.
 *
 * Layouts: coefficients (k0 x k1 x k2) at u + k0 (v + k1 w); cells (n0 x n1 x n2) at
 * x + n0 (y + n1 z), the lattice order. Every sum runs in a fixed order (deterministic).
 */
#ifndef AMORPH_DCT_H
#define AMORPH_DCT_H

#include "amorph/config.h"
#include "amorph/real.h"
#include "amorph/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* cached basis tables of the transforms; declare it static, zeroed */
typedef struct am_dct_work {
    int k[3];                                   /* coefficients kept per axis (table key) */
    int n[3];                                   /* cells per axis (table key) */
    am_real basis[3][AM_MAX_DIM * AM_MAX_DIM];  /* basis[a][u * n[a] + x] = B[u][x] of axis a */
} am_dct_work;

/* scratch of one transform (the passes' intermediate fields); nothing in it outlives a call, so
 * it may share memory with other scratch (am_geno_work does) */
typedef struct am_dct_scratch {
    am_real t1[AM_MAX_CELLS];                   /* the first pass */
    am_real t2[AM_MAX_CELLS];                   /* the second pass */
} am_dct_scratch;

/* prepares w for k[a] coefficients on n[a] cells per axis (1 <= k[a] <= n[a] <= AM_MAX_DIM);
 * recomputes the tables only when (k, n) changed. AM_ERR_CAPACITY / AM_ERR_RANGE otherwise. */
am_status am_dct_plan(am_dct_work* w, const int k[3], const int n[3], char* err, int errsz);
/* inverse (DCT-III): coef (k0 x k1 x k2, zero-padded) -> out (n0 x n1 x n2); needs am_dct_plan */
void am_dct_inverse(const am_dct_work* w, am_dct_scratch* s, const am_real* coef, am_real* out);
/* forward (DCT-II): in (n0 x n1 x n2) -> the k0 x k1 x k2 lowest coefficients; needs am_dct_plan */
void am_dct_forward(const am_dct_work* w, am_dct_scratch* s, const am_real* in, am_real* coef);

#ifdef __cplusplus
}
#endif
#endif
