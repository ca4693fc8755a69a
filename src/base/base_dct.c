/* The separable 3-D DCT (orthonormal DCT-II forward, DCT-III inverse).
 *
 * Each pass contracts one axis with its basis table while the x index stays innermost, so the
 * inner loops walk contiguous rows (the compiler vectorises them) and every output element adds
 * its terms in the same, ascending order whatever the vector width: the results are bit-identical
 * across builds. Angles are reduced on integers before am_cos, so the tables are accurate to the
 * last bit of am_real for any n <= AM_MAX_DIM.
 */
#include "amorph/base.h"


static void build_axis(am_real* b, int k, int n)
{
    am_real c0 = am_sqrt(AM_RATIO(1, n)), c1 = am_sqrt(AM_RATIO(2, n));
    for (int u = 0; u < k; u++)
        for (int x = 0; x < n; x++) {
            /* cos(pi m / (2n)) with m = (2x + 1) u reduced modulo one turn (4n) */
            int m = ((2 * x + 1) * u) % (4 * n);
#if defined(AM_REAL_FIXED_POINT)
            am_real ang = AM_RATIO((int64_t)AM_PI * m, (int64_t)(2 * n) * AM_FIX_ONE);
#else
            am_real ang = AM_DIV(AM_PI * (am_real)m, (am_real)(2 * n));
#endif
            b[u * n + x] = AM_MUL(u == 0 ? c0 : c1, am_cos(ang));
        }
}

am_status am_dct_plan(am_dct_work* w, const int k[3], const int n[3], char* err, int errsz)
{
    for (int a = 0; a < 3; a++) {
        if (n[a] < 1 || k[a] < 1 || k[a] > n[a])
            return am_fail(err, errsz, AM_ERR_RANGE, "DCT axis %d: need 1 <= k (%d) <= n (%d)", a, k[a], n[a]);
        if (n[a] > AM_MAX_DIM)
            return am_fail(err, errsz, AM_ERR_CAPACITY, "DCT axis %d: %d cells exceed the %s profile's %d",
                           a, n[a], AM_PROFILE_NAME, AM_MAX_DIM);
    }
    for (int a = 0; a < 3; a++) {
        if (w->k[a] == k[a] && w->n[a] == n[a]) continue;
        build_axis(w->basis[a], k[a], n[a]);
        w->k[a] = k[a];
        w->n[a] = n[a];
    }
    return AM_OK;
}

void am_dct_inverse(const am_dct_work* w, am_dct_scratch* sc, const am_real* coef, am_real* out)
{
    const int k0 = w->k[0], k1 = w->k[1], k2 = w->k[2];
    const int n0 = w->n[0], n1 = w->n[1], n2 = w->n[2];
    const am_real* b0 = w->basis[0];
    const am_real* b1 = w->basis[1];
    const am_real* b2 = w->basis[2];
    am_real* t1 = sc->t1;
    am_real* t2 = sc->t2;
    /* pass 1, along x: t1[x + n0 (v + k1 w)] = sum_u coef[u, v, w] B0[u][x] */
    for (int r = 0; r < k1 * k2; r++) {
        am_real* row = t1 + (long)r * n0;
        const am_real* c = coef + (long)r * k0;
        for (int x = 0; x < n0; x++) row[x] = AM_MUL(c[0], b0[x]);
        for (int u = 1; u < k0; u++) {
            const am_real cu = c[u];
            const am_real* bu = b0 + u * n0;
            for (int x = 0; x < n0; x++) row[x] += AM_MUL(cu, bu[x]);
        }
    }
    /* pass 2, along y: t2[x + n0 (y + n1 w)] = sum_v t1[x + n0 (v + k1 w)] B1[v][y] */
    for (int ww = 0; ww < k2; ww++)
        for (int y = 0; y < n1; y++) {
            am_real* row = t2 + (long)(y + n1 * ww) * n0;
            const am_real* src = t1 + (long)(k1 * ww) * n0;
            const am_real bv0 = b1[y];
            for (int x = 0; x < n0; x++) row[x] = AM_MUL(src[x], bv0);
            for (int v = 1; v < k1; v++) {
                const am_real bv = b1[v * n1 + y];
                const am_real* s = src + (long)v * n0;
                for (int x = 0; x < n0; x++) row[x] += AM_MUL(s[x], bv);
            }
        }
    /* pass 3, along z: out[x + n0 (y + n1 z)] = sum_w t2[x + n0 (y + n1 w)] B2[w][z] */
    const long plane = (long)n0 * n1;
    for (int z = 0; z < n2; z++) {
        am_real* dst = out + plane * z;
        const am_real bw0 = b2[z];
        for (long i = 0; i < plane; i++) dst[i] = AM_MUL(t2[i], bw0);
        for (int ww = 1; ww < k2; ww++) {
            const am_real bw = b2[ww * n2 + z];
            const am_real* s = t2 + plane * ww;
            for (long i = 0; i < plane; i++) dst[i] += AM_MUL(s[i], bw);
        }
    }
}

void am_dct_forward(const am_dct_work* w, am_dct_scratch* sc, const am_real* in, am_real* coef)
{
    const int k0 = w->k[0], k1 = w->k[1], k2 = w->k[2];
    const int n0 = w->n[0], n1 = w->n[1], n2 = w->n[2];
    const am_real* b0 = w->basis[0];
    const am_real* b1 = w->basis[1];
    const am_real* b2 = w->basis[2];
    am_real* f1 = sc->t2; /* n0 x n1 x k2 */
    am_real* f2 = sc->t1; /* n0 x k1 x k2 */
    const long plane = (long)n0 * n1;
    /* along z: f1[x + n0 (y + n1 w)] = sum_z in[x + n0 (y + n1 z)] B2[w][z] */
    for (int ww = 0; ww < k2; ww++) {
        am_real* dst = f1 + plane * ww;
        const am_real* bw = b2 + ww * n2;
        for (long i = 0; i < plane; i++) dst[i] = AM_MUL(in[i], bw[0]);
        for (int z = 1; z < n2; z++) {
            const am_real* s = in + plane * z;
            const am_real bz = bw[z];
            for (long i = 0; i < plane; i++) dst[i] += AM_MUL(s[i], bz);
        }
    }
    /* along y: f2[x + n0 (v + k1 w)] = sum_y f1[x + n0 (y + n1 w)] B1[v][y] */
    for (int ww = 0; ww < k2; ww++)
        for (int v = 0; v < k1; v++) {
            am_real* row = f2 + (long)(v + k1 * ww) * n0;
            const am_real* src = f1 + (long)(n1 * ww) * n0;
            const am_real* bv = b1 + v * n1;
            for (int x = 0; x < n0; x++) row[x] = AM_MUL(src[x], bv[0]);
            for (int y = 1; y < n1; y++) {
                const am_real* s = src + (long)y * n0;
                const am_real by = bv[y];
                for (int x = 0; x < n0; x++) row[x] += AM_MUL(s[x], by);
            }
        }
    /* along x: coef[u + k0 (v + k1 w)] = sum_x f2[x + n0 (v + k1 w)] B0[u][x] */
    for (int r = 0; r < k1 * k2; r++) {
        const am_real* row = f2 + (long)r * n0;
        for (int u = 0; u < k0; u++) {
            const am_real* bu = b0 + u * n0;
            am_real s = AM_R(0);
            for (int x = 0; x < n0; x++) s += AM_MUL(row[x], bu[x]);
            coef[r * k0 + u] = s;
        }
    }
}
