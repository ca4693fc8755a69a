/* The Gaussian mixtures representation (GMX): an ordered list of Gaussian points.
 *
 * Point i (centre c_i in cells, signed weight w_i, radius r_i in cells, material m_i) adds
 * w_i e^(-|p - c_i|^2 / r_i^2) to the density of its material at cell centre p. Every field starts
 * at -AM_GMX_ISO / materials, so the level set "sum of the fields > 0" is "sum of all points >
 * AM_GMX_ISO (0.5)": one point of weight 1 gives a sphere of radius r sqrt(ln 2), as the seed
 * says ("if only one Gaussian point was used, the resulting solids would always be spheres").
 * The offset is the same for every material, so it never changes the argmax.
 *
 * Expression is separable: e^(-|d|^2/r^2) = e^(-dx^2/r^2) e^(-dy^2/r^2) e^(-dz^2/r^2), so each point
 * needs W + H + D table lookups and then one multiply-add per cell, skipping the rows and columns
 * where a factor is 0 (beyond 4 radii). Points are added in list order: deterministic.
 *
 * Mutation (the seed's rate 0.20): each of a point's centre coordinates, weight and radius moves,
 * with probability def->rate, by a uniform step of at most def->step (5%) of its range, reflected
 * into the range; its material changes with probability def->gmx_material_rate; then a random
 * point is appended with probability def->gmx_add (if below def->gmx_max_points) and a random
 * point removed with probability def->gmx_remove (if more than one is left).
 *
 * Crossover: a random plane through the workspace; the first child takes the first parent's
 * points on the positive side and the second parent's on the other side, the second child the
 * rest (each up to def->gmx_max_points, in order).
 */
#include "geno_internal.h"

#include <string.h>

/* largest radius of a workspace: half its longest side, at least the smallest radius */
static am_real radius_max(const am_genome* g)
{
    int n = g->nx > g->ny ? g->nx : g->ny;
    if (g->nz > n) n = g->nz;
    return am_max(AM_DIV(AM_INT(n), AM_R(2)), AM_GMX_RADIUS_MIN);
}

static int max_points(const am_geno_def* def)
{
    int m = def->gmx_max_points;
    return m < 1 ? 1 : (m > AM_MAX_GMX_POINTS ? AM_MAX_GMX_POINTS : m);
}

static am_gmx_point random_point(const am_genome* g, am_rng* r)
{
    am_gmx_point p;
    memset(&p, 0, sizeof p);
    p.x = am_rng_range(r, AM_R(0), AM_INT(g->nx - 1));
    p.y = am_rng_range(r, AM_R(0), AM_INT(g->ny - 1));
    p.z = am_rng_range(r, AM_R(0), AM_INT(g->nz - 1));
    p.weight = am_rng_range(r, -AM_GMX_WEIGHT_MAX, AM_GMX_WEIGHT_MAX);
    p.radius = am_rng_range(r, AM_GMX_RADIUS_MIN, radius_max(g));
    p.mat = (uint8_t)am_rng_below(r, (uint32_t)g->materials);
#if AM_GENO_LAYERS
    /* drawn only for the fields the genome carries: a genome of none draws as before them */
    if (g->controls & AM_CTL_PHASE) p.phase = am_rng_range(r, AM_R(0), AM_R(1));
    if (g->controls & AM_CTL_STIFFNESS) p.stiff = am_rng_range(r, AM_R(0), AM_R(1));
    if (p.phase >= AM_R(1)) p.phase = AM_R(0);
#endif
    return p;
}

#if AM_GENO_LAYERS
/* a phase moved by a uniform step in [-step, step], wrapped into [0, 1) periods */
static am_real wrap_phase(am_real v)
{
    am_real x = v - am_floor(v);
    return x >= AM_R(1) || x < AM_R(0) ? AM_R(0) : x;
}
#endif

static am_status gmx_check(const am_genome* g, char* err, int errsz)
{
    const am_gmx_genome* x = &g->gmx;
    if (x->count > AM_MAX_GMX_POINTS)
        return am_fail(err, errsz, AM_ERR_CAPACITY, "%d GMX points exceed the %s profile's %d", x->count, AM_PROFILE_NAME, AM_MAX_GMX_POINTS);
    if (x->count < 0) return am_fail(err, errsz, AM_ERR_RANGE, "negative GMX point count");
    const am_real rmax = radius_max(g);
    for (int i = 0; i < x->count; i++) {
        const am_gmx_point* p = &x->pt[i];
        if (!(p->x >= AM_R(0) && p->x <= AM_INT(g->nx - 1)) || !(p->y >= AM_R(0) && p->y <= AM_INT(g->ny - 1)) ||
            !(p->z >= AM_R(0) && p->z <= AM_INT(g->nz - 1)))
            return am_fail(err, errsz, AM_ERR_RANGE, "GMX point %d lies outside the workspace", i);
        if (!(am_fabs(p->weight) <= AM_GMX_WEIGHT_MAX) || !(p->radius >= AM_GMX_RADIUS_MIN && p->radius <= rmax) ||
            p->mat >= g->materials)
            return am_fail(err, errsz, AM_ERR_RANGE, "GMX point %d has a weight, radius or material out of range", i);
#if AM_GENO_LAYERS
        if (!(p->phase >= AM_R(0) && p->phase < AM_R(1)) || !(p->stiff >= AM_R(0) && p->stiff <= AM_R(1)))
            return am_fail(err, errsz, AM_ERR_RANGE, "GMX point %d has a phase outside [0, 1) or a stiffness outside [0, 1]", i);
#endif
    }
    return AM_OK;
}

static am_status gmx_init(am_genome* g, const am_geno_def* def, am_rng* r, char* err, int errsz)
{
    if (def->gmx_points > AM_MAX_GMX_POINTS || def->gmx_points > max_points(def))
        return am_fail(err, errsz, AM_ERR_CAPACITY, "%d GMX points exceed the limit of %d (%s profile: %d)", def->gmx_points,
                       max_points(def), AM_PROFILE_NAME, AM_MAX_GMX_POINTS);
    if (def->gmx_points < 0) return am_fail(err, errsz, AM_ERR_RANGE, "negative GMX point count");
    g->gmx.count = def->gmx_points;
    for (int i = 0; i < g->gmx.count; i++) g->gmx.pt[i] = random_point(g, r);
    return AM_OK;
}

static void gmx_mutate(am_genome* g, const am_geno_def* def, am_rng* r)
{
    am_gmx_genome* x = &g->gmx;
    const am_real rmax = radius_max(g), s = def->step;
    const am_real hi[3] = {AM_INT(g->nx - 1), AM_INT(g->ny - 1), AM_INT(g->nz - 1)};
    for (int i = 0; i < x->count; i++) {
        am_gmx_point* p = &x->pt[i];
        am_real* c[3] = {&p->x, &p->y, &p->z};
        for (int a = 0; a < 3; a++)
            if (am_rng_chance(r, def->rate)) *c[a] = am_geno_perturb(r, *c[a], AM_MUL(s, hi[a]), AM_R(0), hi[a]);
        if (am_rng_chance(r, def->rate))
            p->weight = am_geno_perturb(r, p->weight, AM_MUL(s, AM_MUL(AM_R(2), AM_GMX_WEIGHT_MAX)), -AM_GMX_WEIGHT_MAX, AM_GMX_WEIGHT_MAX);
        if (am_rng_chance(r, def->rate))
            p->radius = am_geno_perturb(r, p->radius, AM_MUL(s, rmax - AM_GMX_RADIUS_MIN), AM_GMX_RADIUS_MIN, rmax);
        if (g->materials > 1 && am_rng_chance(r, def->gmx_material_rate))
            p->mat = (uint8_t)((p->mat + 1 + am_rng_below(r, (uint32_t)(g->materials - 1))) % (uint32_t)g->materials);
#if AM_GENO_LAYERS
        if ((g->controls & AM_CTL_PHASE) && am_rng_chance(r, def->rate))
            p->phase = wrap_phase(p->phase + am_rng_range(r, -s, s)); /* a step of def->step of a period */
        if ((g->controls & AM_CTL_STIFFNESS) && am_rng_chance(r, def->rate))
            p->stiff = am_geno_perturb(r, p->stiff, s, AM_R(0), AM_R(1));
#endif
    }
    if (am_rng_chance(r, def->gmx_add) && x->count < max_points(def)) x->pt[x->count++] = random_point(g, r);
    if (am_rng_chance(r, def->gmx_remove) && x->count > 1) {
        int k = (int)am_rng_below(r, (uint32_t)x->count);
        for (int i = k; i + 1 < x->count; i++) x->pt[i] = x->pt[i + 1];
        x->count--;
    }
}

void am_gmx_random_plane(const am_genome* g, am_rng* r, am_real point[3], am_real normal[3])
{
    point[0] = am_rng_range(r, AM_R(0), AM_INT(g->nx - 1));
    point[1] = am_rng_range(r, AM_R(0), AM_INT(g->ny - 1));
    point[2] = am_rng_range(r, AM_R(0), AM_INT(g->nz - 1));
    for (int a = 0; a < 3; a++) normal[a] = am_rng_normal(r);
    am_real len = am_sqrt(AM_MUL(normal[0], normal[0]) + AM_MUL(normal[1], normal[1]) + AM_MUL(normal[2], normal[2]));
    if (!(len > AM_R(0))) {
        normal[0] = AM_R(1);
        normal[1] = normal[2] = AM_R(0);
        return;
    }
    for (int a = 0; a < 3; a++) normal[a] = AM_DIV(normal[a], len);
}

static int positive_side(const am_gmx_point* p, const am_real point[3], const am_real normal[3])
{
    am_real s = AM_MUL(p->x - point[0], normal[0]) + AM_MUL(p->y - point[1], normal[1]) + AM_MUL(p->z - point[2], normal[2]);
    return s >= AM_R(0);
}

/* appends to dst the points of src on the given side */
static void take_side(am_gmx_genome* dst, const am_gmx_genome* src, int side, const am_real point[3],
                      const am_real normal[3], int maxp)
{
    for (int i = 0; i < src->count && dst->count < maxp; i++)
        if (positive_side(&src->pt[i], point, normal) == side) dst->pt[dst->count++] = src->pt[i];
}

void am_gmx_plane_cross(const am_genome* a, const am_genome* b, const am_real point[3], const am_real normal[3],
                        int max_points_, am_genome* c1, am_genome* c2)
{
    int maxp = max_points_ < 1 ? 1 : (max_points_ > AM_MAX_GMX_POINTS ? AM_MAX_GMX_POINTS : max_points_);
    *c1 = *a;
    c1->gmx.count = 0;
    take_side(&c1->gmx, &a->gmx, 1, point, normal, maxp);
    take_side(&c1->gmx, &b->gmx, 0, point, normal, maxp);
    if (c2) {
        *c2 = *b;
        c2->gmx.count = 0;
        take_side(&c2->gmx, &b->gmx, 1, point, normal, maxp);
        take_side(&c2->gmx, &a->gmx, 0, point, normal, maxp);
    }
}

static void gmx_crossover(const am_genome* a, const am_genome* b, am_genome* c1, am_genome* c2,
                          const am_geno_def* def, am_rng* r)
{
    am_real point[3], normal[3];
    am_gmx_random_plane(a, r, point, normal);
    am_gmx_plane_cross(a, b, point, normal, max_points(def), c1, c2);
}

static int gmx_same_shape(const am_genome* a, const am_genome* b)
{
    (void)a;
    (void)b;
    return 1;
}

static int gmx_values(const am_genome* g) { return (6 + am_genome_fields(g) - g->materials) * g->gmx.count; }

static uint64_t gmx_hash(uint64_t h, const am_genome* g)
{
    h = am_hash_u64(h, (uint64_t)g->gmx.count);
    for (int i = 0; i < g->gmx.count; i++) {
        const am_gmx_point* p = &g->gmx.pt[i];
        h = am_hash_real(h, p->x);
        h = am_hash_real(h, p->y);
        h = am_hash_real(h, p->z);
        h = am_hash_real(h, p->weight);
        h = am_hash_real(h, p->radius);
        h = am_hash_u64(h, p->mat);
#if AM_GENO_LAYERS
        if (g->controls & AM_CTL_PHASE) h = am_hash_real(h, p->phase);
        if (g->controls & AM_CTL_STIFFNESS) h = am_hash_real(h, p->stiff);
#endif
    }
    return h;
}

static int gmx_equal(const am_genome* a, const am_genome* b)
{
    if (a->gmx.count != b->gmx.count) return 0;
    for (int i = 0; i < a->gmx.count; i++) {
        const am_gmx_point* p = &a->gmx.pt[i];
        const am_gmx_point* q = &b->gmx.pt[i];
        const am_real pv[5] = {p->x, p->y, p->z, p->weight, p->radius};
        const am_real qv[5] = {q->x, q->y, q->z, q->weight, q->radius};
        if (p->mat != q->mat || memcmp(pv, qv, sizeof pv) != 0) return 0;
#if AM_GENO_LAYERS
        if ((a->controls & AM_CTL_PHASE) && memcmp(&p->phase, &q->phase, sizeof p->phase) != 0) return 0;
        if ((a->controls & AM_CTL_STIFFNESS) && memcmp(&p->stiff, &q->stiff, sizeof p->stiff) != 0) return 0;
#endif
    }
    return 1;
}

/* f[i] = e^(-((i - c) / r)^2) along one axis; returns the first and one-past-last non-zero index.
 * inv is 1 / r^2 (1 / r in the fixed-point build) */
static void factors(const am_geno_work* w, am_real* f, int n, am_real c, am_real inv, int* lo, int* hi)
{
    *lo = n;
    *hi = 0;
    for (int i = 0; i < n; i++) {
        am_real d = AM_INT(i) - c;
#if defined(AM_REAL_FIXED_POINT)
        am_real dr = AM_MUL(d, inv);
        f[i] = am_fabs(dr) < AM_R(4) ? am_geno_gauss(w, AM_MUL(dr, dr)) : AM_R(0); /* (d/r)^2 would leave the range */
#else
        f[i] = am_geno_gauss(w, AM_MUL(AM_MUL(d, d), inv));
#endif
        if (f[i] != AM_R(0)) {
            if (*lo == n) *lo = i;
            *hi = i + 1;
        }
    }
}

#if AM_GENO_LAYERS
/* Evolved fields: every point pulls the cells it reaches towards its own phase and stiffness in
 * proportion to its strength there, |weight| e^(-d^2/r^2) (a hole's point as much as a solid's).
 * The phase is the weighted circular mean (the angle of the summed unit vectors of the points'
 * phases: a point at 0.95 and one at 0.05 average to 0, not 0.5), the stiffness the weighted mean.
 * Rows of w->dens after the materials' (M): the phase's sums of cos and sin at M and M + 1, the
 * stiffness's sums of weight x stiffness and of weight at M + 2k and M + 2k + 1 (k = 1 with a
 * phase), reduced by control_means to the phase at M and the stiffness at M + k. */
static void control_point(const am_genome* g, am_geno_work* w, const am_gmx_point* p, int x0, int x1, int y0, int y1,
                          int z0, int z1)
{
    const int nx = g->nx, M = g->materials, k = g->controls & AM_CTL_PHASE ? 1 : 0;
    am_real val[4];
    am_real* row[4];
    int n = 0;
    if (g->controls & AM_CTL_PHASE) {
        const am_real turn = AM_MUL(AM_R(6.283185307179586477), p->phase);
        val[n] = am_cos(turn), row[n++] = w->dens[M];
        val[n] = am_sin(turn), row[n++] = w->dens[M + 1];
    }
    if (g->controls & AM_CTL_STIFFNESS) {
        val[n] = p->stiff, row[n++] = w->dens[M + 2 * k];
        val[n] = AM_R(1), row[n++] = w->dens[M + 2 * k + 1];
    }
    const am_real strength = am_fabs(p->weight);
    for (int z = z0; z < z1; z++) {
        const am_real wz = AM_MUL(strength, w->scratch.gmx.fz[z]);
        for (int y = y0; y < y1; y++) {
            const am_real wyz = AM_MUL(wz, w->scratch.gmx.fy[y]);
            const long at = (long)nx * (y + (long)g->ny * z);
            for (int x = x0; x < x1; x++) {
                const am_real s = AM_MUL(wyz, w->scratch.gmx.fx[x]);
                for (int i = 0; i < n; i++) row[i][at + x] += AM_MUL(s, val[i]);
            }
        }
    }
}

/* the sums of control_point reduced to a phase in periods and a stiffness in [0, 1] a cell (a cell
 * no point reaches: phase 0, stiffness 1/2) */
static void control_means(const am_genome* g, am_geno_work* w)
{
    const int cells = g->nx * g->ny * g->nz, M = g->materials, k = g->controls & AM_CTL_PHASE ? 1 : 0;
    for (int c = 0; c < cells; c++) {
        if (g->controls & AM_CTL_PHASE) {
            const am_real cs = w->dens[M][c], sn = w->dens[M + 1][c];
            const am_real turns = cs == AM_R(0) && sn == AM_R(0) ? AM_R(0)
                                                                 : AM_MUL(am_atan2(sn, cs), AM_R(0.15915494309189533577));
            w->dens[M][c] = turns < AM_R(0) ? turns + AM_R(1) : turns;
        }
        if (g->controls & AM_CTL_STIFFNESS) {
            const am_real sum = w->dens[M + 2 * k][c], wt = w->dens[M + 2 * k + 1][c];
            w->dens[M + k][c] = wt > AM_R(0) ? am_clamp(AM_DIV(sum, wt), AM_R(0), AM_R(1)) : AM_R(0.5);
        }
    }
}
#endif

static void gmx_express(const am_genome* g, am_geno_work* w)
{
    const int nx = g->nx, ny = g->ny, nz = g->nz, cells = nx * ny * nz;
    const am_real base = -AM_DIV(AM_GMX_ISO, AM_INT(g->materials));
    for (int m = 0; m < g->materials; m++)
        for (int c = 0; c < cells; c++) w->dens[m][c] = base;
#if AM_GENO_LAYERS
    for (int m = g->materials; m < g->materials + 2 * (am_genome_fields(g) - g->materials); m++)
        for (int c = 0; c < cells; c++) w->dens[m][c] = AM_R(0);
#endif
    for (int k = 0; k < g->gmx.count; k++) {
        const am_gmx_point* p = &g->gmx.pt[k];
        #if defined(AM_REAL_FIXED_POINT)
        const am_real inv_r2 = AM_DIV(AM_R(1), p->radius);
#else
        const am_real inv_r2 = AM_DIV(AM_R(1), AM_MUL(p->radius, p->radius));
#endif
        int x0, x1, y0, y1, z0, z1;
        factors(w, w->scratch.gmx.fx, nx, p->x, inv_r2, &x0, &x1);
        factors(w, w->scratch.gmx.fy, ny, p->y, inv_r2, &y0, &y1);
        factors(w, w->scratch.gmx.fz, nz, p->z, inv_r2, &z0, &z1);
        am_real* d = w->dens[p->mat];
        for (int z = z0; z < z1; z++) {
            const am_real wz = AM_MUL(p->weight, w->scratch.gmx.fz[z]);
            for (int y = y0; y < y1; y++) {
                const am_real wyz = AM_MUL(wz, w->scratch.gmx.fy[y]);
                am_real* row = d + (long)nx * (y + (long)ny * z);
                for (int x = x0; x < x1; x++) row[x] += AM_MUL(wyz, w->scratch.gmx.fx[x]);
            }
        }
#if AM_GENO_LAYERS
        if (g->controls) control_point(g, w, p, x0, x1, y0, y1, z0, z1);
#endif
    }
#if AM_GENO_LAYERS
    if (g->controls) control_means(g, w);
#endif
}

static void gmx_format(const am_genome* g, am_text* s)
{
    am_text_put(s, "gmx %d\n", g->gmx.count);
    if (g->controls)
        am_text_put(s, "# point X Y Z WEIGHT RADIUS MATERIAL%s%s (centre and radius in cells)\n",
                    g->controls & AM_CTL_PHASE ? " PHASE" : "", g->controls & AM_CTL_STIFFNESS ? " STIFFNESS" : "");
    else
        am_text_put(s, "# point X Y Z WEIGHT RADIUS MATERIAL (centre and radius in cells)\n");
    for (int i = 0; i < g->gmx.count; i++) {
        const am_gmx_point* p = &g->gmx.pt[i];
        am_text_put(s, "point");
        am_geno_put_real(s, p->x);
        am_geno_put_real(s, p->y);
        am_geno_put_real(s, p->z);
        am_geno_put_real(s, p->weight);
        am_geno_put_real(s, p->radius);
        am_text_put(s, " %d", p->mat);
#if AM_GENO_LAYERS
        if (g->controls & AM_CTL_PHASE) am_geno_put_real(s, p->phase);
        if (g->controls & AM_CTL_STIFFNESS) am_geno_put_real(s, p->stiff);
#endif
        am_text_put(s, "\n");
    }
}

static am_status gmx_parse_line(am_genome* g, am_geno_parse* ps, int ntok, char** tok, char* err, int errsz)
{
    am_gmx_genome* x = &g->gmx;
    char q1[AM_QUOTE_BUF];
    if (!ps->shape) {
        int n = 0;
        if (strcmp(tok[0], "gmx") != 0 || ntok != 2) return am_fail(err, errsz, AM_ERR_PARSE, "expected 'gmx COUNT'");
        if (!am_geno_tok_int(tok[1], 0, 1000000000, &n))
            return am_fail(err, errsz, AM_ERR_PARSE, "GMX point count '%s' is not a non-negative integer",
                           am_quote(q1, sizeof q1, tok[1], -1));
        if (n > AM_MAX_GMX_POINTS)
            return am_fail(err, errsz, AM_ERR_CAPACITY, "%d GMX points exceed the %s profile's %d", n, AM_PROFILE_NAME, AM_MAX_GMX_POINTS);
        x->count = n;
        ps->shape = 1;
        return AM_OK;
    }
    if (strcmp(tok[0], "point") != 0)
        return am_fail(err, errsz, AM_ERR_PARSE, "unknown line '%s' in a gmx genome (expected 'point' or 'end')",
                       am_quote(q1, sizeof q1, tok[0], -1));
    const int extra = am_genome_fields(g) - g->materials;
    if (ntok != 7 + extra)
        return am_fail(err, errsz, AM_ERR_PARSE, "'point' needs X Y Z WEIGHT RADIUS MATERIAL%s%s",
                       g->controls & AM_CTL_PHASE ? " PHASE" : "", g->controls & AM_CTL_STIFFNESS ? " STIFFNESS" : "");
    if (ps->lines >= x->count) return am_fail(err, errsz, AM_ERR_PARSE, "more 'point' lines than the %d announced", x->count);
    am_gmx_point* p = &x->pt[ps->lines];
    const am_real hi[3] = {AM_INT(g->nx - 1), AM_INT(g->ny - 1), AM_INT(g->nz - 1)};
    am_real* c[3] = {&p->x, &p->y, &p->z};
    for (int a = 0; a < 3; a++)
        if (!am_geno_tok_real(tok[1 + a], AM_R(0), hi[a], c[a]))
            return am_fail(err, errsz, AM_ERR_RANGE, "coordinate '%s' is not a number in [0, %d]",
                           am_quote(q1, sizeof q1, tok[1 + a], -1), (int)hi[a]);
    if (!am_geno_tok_real(tok[4], -AM_GMX_WEIGHT_MAX, AM_GMX_WEIGHT_MAX, &p->weight))
        return am_fail(err, errsz, AM_ERR_RANGE, "weight '%s' is not a number in [-1, 1]", am_quote(q1, sizeof q1, tok[4], -1));
    if (!am_geno_tok_real(tok[5], AM_GMX_RADIUS_MIN, radius_max(g), &p->radius))
        return am_fail(err, errsz, AM_ERR_RANGE, "radius '%s' is not a number in [1, %g]",
                       am_quote(q1, sizeof q1, tok[5], -1), (double)radius_max(g));
    int m = 0;
    if (!am_geno_tok_int(tok[6], 0, g->materials - 1, &m))
        return am_fail(err, errsz, AM_ERR_RANGE, "material '%s' is not 0..%d",
                       am_quote(q1, sizeof q1, tok[6], -1), g->materials - 1);
    p->mat = (uint8_t)m;
#if AM_GENO_LAYERS
    int t = 7;
    if ((g->controls & AM_CTL_PHASE) && !(am_geno_tok_real(tok[t++], AM_R(0), AM_R(1), &p->phase) && p->phase < AM_R(1)))
        return am_fail(err, errsz, AM_ERR_RANGE, "phase '%s' is not a number in [0, 1)", am_quote(q1, sizeof q1, tok[t - 1], -1));
    if ((g->controls & AM_CTL_STIFFNESS) && !am_geno_tok_real(tok[t++], AM_R(0), AM_R(1), &p->stiff))
        return am_fail(err, errsz, AM_ERR_RANGE, "stiffness '%s' is not a number in [0, 1]", am_quote(q1, sizeof q1, tok[t - 1], -1));
#endif
    ps->lines++;
    return AM_OK;
}

static am_status gmx_parse_end(am_genome* g, am_geno_parse* ps, char* err, int errsz)
{
    if (!ps->shape) return am_fail(err, errsz, AM_ERR_PARSE, "missing 'gmx COUNT' line");
    if (ps->lines != g->gmx.count)
        return am_fail(err, errsz, AM_ERR_PARSE, "%d 'point' lines where 'gmx %d' announced %d", ps->lines, g->gmx.count, g->gmx.count);
    return AM_OK;
}

const am_geno_ops am_geno_gmx_ops = {
    "gmx", gmx_init, gmx_mutate, gmx_crossover, gmx_same_shape, gmx_check, gmx_values,
    gmx_hash, gmx_equal, gmx_express, gmx_format, gmx_parse_line, gmx_parse_end,
};
