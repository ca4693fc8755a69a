/* Where a placed surface mesh crosses itself (include/amorph/io.h, am_mesh_crossings): what a
 * deformed export warns about, since a printer fuses whatever overlaps.
 *
 * Broad phase: a uniform grid whose cell is no smaller than the largest triangle's box on any
 * axis (and no smaller than the body's box over AM_MESH_GRID_DIM), each triangle filed once, under
 * the cell of its box's low corner (a counting sort into one array). A triangle whose box overlaps
 * that of triangle t has its low corner within one cell size below t's box, so t looks at the
 * 3 x 3 x 3 cells from there up to its box's high corner, and counts a pair only with a triangle
 * numbered above its own.
 *
 * Narrow phase (pairs that share no vertex): a triangle that does not reach more than the
 * tolerance to both sides of the other's plane at most touches it. Otherwise each triangle
 * crosses the other's plane along a segment of the line where the two planes meet (between the
 * points where its edges cross the plane, never a corner merely near it, which would be far off
 * that line when the planes are nearly parallel); the triangles cross when the two segments
 * overlap by more than the tolerance. A triangle within the tolerance of the other's plane is
 * coplanar with it: they cross when an edge of one properly crosses an edge of the other or the
 * centre of one lies strictly inside the other. Touching is not crossing: the tolerance is on the
 * side of not counting. */
#include "amorph/io.h"

#include <math.h>
#include <string.h>

static double dot3(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void cross3(const double* a, const double* b, double* o)
{
    o[0] = a[1] * b[2] - a[2] * b[1];
    o[1] = a[2] * b[0] - a[0] * b[2];
    o[2] = a[0] * b[1] - a[1] * b[0];
}

/* the unit normal of triangle t into n; 0 for a degenerate triangle */
static int unit_normal(const double* const t[3], double n[3])
{
    double u[3], v[3];
    for (int k = 0; k < 3; k++) u[k] = t[1][k] - t[0][k], v[k] = t[2][k] - t[0][k];
    cross3(u, v, n);
    double len = sqrt(dot3(n, n));
    if (!(len > 0)) return 0;
    for (int k = 0; k < 3; k++) n[k] /= len;
    return 1;
}

/* signed distances s of t's corners to the plane (n, through p); 1 when t lies within tol of the
 * plane, 2 when it reaches more than tol to both sides of it, else 0 (it stays on one side, or
 * only touches it) */
static int side_of(const double* const t[3], const double n[3], const double* p, double tol, double s[3])
{
    int above = 0, below = 0;
    for (int i = 0; i < 3; i++) {
        double d[3] = {t[i][0] - p[0], t[i][1] - p[1], t[i][2] - p[2]};
        s[i] = dot3(n, d);
        above |= s[i] > tol, below |= s[i] < -tol;
    }
    return above && below ? 2 : !above && !below;
}

/* the segment of the line (unit direction d) where t, reaching to both sides of the other plane
 * (distances s), crosses it, as parameters d . x of the points where its edges cross */
static void segment(const double* const t[3], const double s[3], const double d[3], double* lo, double* hi)
{
    *lo = HUGE_VAL, *hi = -HUGE_VAL;
    for (int i = 0; i < 3; i++) {
        int j = (i + 1) % 3;
        double pi = dot3(d, t[i]), pj = dot3(d, t[j]), q;
        if (s[i] == 0) q = pi;
        else if ((s[i] < 0 && s[j] > 0) || (s[i] > 0 && s[j] < 0)) q = pi + (pj - pi) * (s[i] / (s[i] - s[j]));
        else continue;
        if (q < *lo) *lo = q;
        if (q > *hi) *hi = q;
    }
}

/* twice the signed area of (p, q, r) in the plane of axes (a, b) */
static double orient(const double* p, const double* q, const double* r, int a, int b)
{
    return (q[a] - p[a]) * (r[b] - p[b]) - (q[b] - p[b]) * (r[a] - p[a]);
}

static double dist2d(const double* p, const double* q, int a, int b) { return hypot(q[a] - p[a], q[b] - p[b]); }

/* 1 when point p lies inside triangle t by more than tol from every edge (axes a, b) */
static int inside2d(const double* const t[3], const double* p, int a, int b, double tol)
{
    double area = orient(t[0], t[1], t[2], a, b), sg = area > 0 ? 1 : -1;
    if (area == 0) return 0;
    for (int i = 0; i < 3; i++) {
        const double *e0 = t[i], *e1 = t[(i + 1) % 3];
        if (!(sg * orient(e0, e1, p, a, b) > tol * dist2d(e0, e1, a, b))) return 0;
    }
    return 1;
}

/* coplanar triangles (normal n): 1 when they overlap with positive area */
static int cross_coplanar(const double* const ta[3], const double* const tb[3], const double n[3], double tol)
{
    /* drop the axis the normal is largest on */
    int drop = fabs(n[0]) >= fabs(n[1]) ? (fabs(n[0]) >= fabs(n[2]) ? 0 : 2) : (fabs(n[1]) >= fabs(n[2]) ? 1 : 2);
    int a = (drop + 1) % 3, b = (drop + 2) % 3;
    for (int i = 0; i < 3; i++) {
        const double *p0 = ta[i], *p1 = ta[(i + 1) % 3];
        double lp = tol * dist2d(p0, p1, a, b);
        for (int j = 0; j < 3; j++) {
            const double *q0 = tb[j], *q1 = tb[(j + 1) % 3];
            double lq = tol * dist2d(q0, q1, a, b);
            double o1 = orient(p0, p1, q0, a, b), o2 = orient(p0, p1, q1, a, b);
            double o3 = orient(q0, q1, p0, a, b), o4 = orient(q0, q1, p1, a, b);
            if (((o1 > lp && o2 < -lp) || (o1 < -lp && o2 > lp)) && ((o3 > lq && o4 < -lq) || (o3 < -lq && o4 > lq)))
                return 1;
        }
    }
    double ca[3], cb[3];
    for (int k = 0; k < 3; k++) ca[k] = (ta[0][k] + ta[1][k] + ta[2][k]) / 3, cb[k] = (tb[0][k] + tb[1][k] + tb[2][k]) / 3;
    return inside2d(tb, ca, a, b, tol) || inside2d(ta, cb, a, b, tol);
}

/* 1 when triangles ta and tb cross (see the top of the file) */
static int tri_cross(const double* const ta[3], const double* const tb[3], double tol)
{
    double na[3], nb[3], sa[3], sb[3];
    if (!unit_normal(ta, na) || !unit_normal(tb, nb)) return 0;
    int b_on_a = side_of(tb, na, ta[0], tol, sb), a_on_b = side_of(ta, nb, tb[0], tol, sa);
    if (b_on_a == 1 || a_on_b == 1) return cross_coplanar(ta, tb, na, tol);
    if (b_on_a != 2 || a_on_b != 2) return 0; /* apart, or touching */
    /* each reaches through the other's plane: compare where, along the planes' common line */
    double d[3];
    cross3(na, nb, d);
    double len = sqrt(dot3(d, d));
    if (!(len > 0)) return 0;
    for (int k = 0; k < 3; k++) d[k] /= len;
    double alo, ahi, blo, bhi;
    segment(ta, sa, d, &alo, &ahi);
    segment(tb, sb, d, &blo, &bhi);
    return fmin(ahi, bhi) - fmax(alo, blo) > tol;
}

/* the box of triangle t */
static void tri_box(const am_mesh* m, const double* pos, long t, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        double a = pos[3 * m->tri[t][0] + k], b = pos[3 * m->tri[t][1] + k], c = pos[3 * m->tri[t][2] + k];
        lo[k] = fmin(a, fmin(b, c)), hi[k] = fmax(a, fmax(b, c));
    }
}

/* the grid cell index of coordinate x on one axis */
static int grid_at(double x, double lo, double h, int dim)
{
    double i = floor((x - lo) / h);
    return i < 0 ? 0 : i >= dim ? dim - 1 : (int)i;
}

void am_mesh_crossings(const am_mesh* m, const double* pos, int mat, am_mesh_grid* g, long max_visits, am_mesh_crossing* out)
{
    memset(out, 0, sizeof *out);
    out->complete = 1;
    /* the body's box and the largest triangle */
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}, h = 0;
    long n = 0;
    for (long t = 0; t < m->ntri; t++) {
        if (mat >= 0 && m->tmat[t] != mat) continue;
        double bl[3], bh[3];
        tri_box(m, pos, t, bl, bh);
        for (int k = 0; k < 3; k++) {
            if (!isfinite(bl[k]) || !isfinite(bh[k])) {
                out->complete = 0;
                return;
            }
            lo[k] = fmin(lo[k], bl[k]), hi[k] = fmax(hi[k], bh[k]), h = fmax(h, bh[k] - bl[k]);
        }
        n++;
    }
    if (n < 2) return;
    double ext = fmax(hi[0] - lo[0], fmax(hi[1] - lo[1], hi[2] - lo[2]));
    if (h < ext / AM_MESH_GRID_DIM) h = ext / AM_MESH_GRID_DIM;
    if (!(h > 0)) h = 1;
    int dim[3];
    for (int k = 0; k < 3; k++) {
        double c = floor((hi[k] - lo[k]) / h) + 1;
        dim[k] = c > AM_MESH_GRID_DIM ? AM_MESH_GRID_DIM : (int)c;
    }
    long ncell = (long)dim[0] * dim[1] * dim[2];

    /* file each triangle under the cell of its box's low corner */
    for (long c = 0; c <= ncell; c++) g->start[c] = 0;
    for (long t = 0; t < m->ntri; t++) {
        if (mat >= 0 && m->tmat[t] != mat) continue;
        double bl[3], bh[3];
        tri_box(m, pos, t, bl, bh);
        g->start[grid_at(bl[0], lo[0], h, dim[0]) + dim[0] * (grid_at(bl[1], lo[1], h, dim[1]) + dim[1] * grid_at(bl[2], lo[2], h, dim[2]))]++;
    }
    for (long c = 1; c < ncell; c++) g->start[c] += g->start[c - 1]; /* the end of each cell */
    g->start[ncell] = (int32_t)n;
    for (long t = m->ntri - 1; t >= 0; t--) {
        if (mat >= 0 && m->tmat[t] != mat) continue;
        double bl[3], bh[3];
        tri_box(m, pos, t, bl, bh);
        long c = grid_at(bl[0], lo[0], h, dim[0]) + dim[0] * (grid_at(bl[1], lo[1], h, dim[1]) + dim[1] * grid_at(bl[2], lo[2], h, dim[2]));
        g->order[--g->start[c]] = (int32_t)t;
    }

    /* each triangle against those filed where an overlapping box can be */
    double tol = 1e-6 * m->voxel_size;
    for (long t = 0; t < m->ntri; t++) {
        if (mat >= 0 && m->tmat[t] != mat) continue;
        double tl[3], th[3];
        tri_box(m, pos, t, tl, th);
        int c0[3], c1[3];
        for (int k = 0; k < 3; k++) c0[k] = grid_at(tl[k] - h, lo[k], h, dim[k]), c1[k] = grid_at(th[k], lo[k], h, dim[k]);
        const double* ta[3] = {pos + 3 * m->tri[t][0], pos + 3 * m->tri[t][1], pos + 3 * m->tri[t][2]};
        for (int z = c0[2]; z <= c1[2]; z++)
            for (int y = c0[1]; y <= c1[1]; y++)
                for (int x = c0[0]; x <= c1[0]; x++) {
                    long c = x + (long)dim[0] * (y + (long)dim[1] * z);
                    for (int32_t e = g->start[c]; e < g->start[c + 1]; e++) {
                        long u = g->order[e];
                        if (u <= t) continue;
                        if (out->visits >= max_visits) {
                            out->complete = 0;
                            return;
                        }
                        out->visits++;
                        double ul[3], uh[3];
                        tri_box(m, pos, u, ul, uh);
                        if (ul[0] > th[0] || ul[1] > th[1] || ul[2] > th[2] || uh[0] < tl[0] || uh[1] < tl[1] || uh[2] < tl[2])
                            continue;
                        int shared = 0;
                        for (int i = 0; i < 3; i++)
                            for (int j = 0; j < 3; j++) shared |= m->tri[t][i] == m->tri[u][j];
                        if (shared) continue;
                        const double* tb[3] = {pos + 3 * m->tri[u][0], pos + 3 * m->tri[u][1], pos + 3 * m->tri[u][2]};
                        if (!tri_cross(ta, tb, tol)) continue;
                        if (!out->pairs++)
                            for (int k = 0; k < 3; k++) out->at[k] = (ta[0][k] + ta[1][k] + ta[2][k] + tb[0][k] + tb[1][k] + tb[2][k]) / 6;
                    }
                }
    }
}
