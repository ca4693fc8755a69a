/* The level set shared by every representation: density fields -> a body of material cells.
 *
 * A cell is filled where the sum of the material densities exceeds the threshold (0 by default);
 * its material is the one of highest density there (ties go to the lower material index). Of the
 * filled cells only the largest face-connected piece is kept: a robot is one body. The pieces are
 * found by breadth-first fills on a fixed queue (each cell enters the queue at most once, so
 * AM_MAX_CELLS entries always suffice), never by recursion. An empty body is a valid outcome.
 *
 * The seed's alternative, materials blended in proportion to their densities, is offered as an
 * optional output (per-cell ratios of the positive parts of the densities) for formats that can
 * carry mixtures; the lattice itself holds one material per cell.
 */
#include "geno_internal.h"

#include <string.h>

/* mark[] bits: the six face neighbours that exist (+x -x +y -y +z -z), then "seen" and "kept" */
enum { NB_ALL = 63, SEEN = 64, KEPT = 128 };

/* breadth-first fill of the piece holding seed, appended to queue from *tail; returns its size */
static int fill(const uint8_t* cell, int nx, int ny, int seed, uint8_t* mark, int32_t* queue, int* tail)
{
    const int step[6] = {1, -1, nx, -nx, nx * ny, -nx * ny};
    int head = *tail, end = *tail;
    mark[seed] |= SEEN;
    queue[end++] = seed;
    while (head < end) {
        const int c = queue[head++];
        const int nb = mark[c] & NB_ALL;
        for (int k = 0; k < 6; k++) {
            if (!(nb & (1 << k))) continue;
            const int d = c + step[k];
            if (cell[d] && !(mark[d] & SEEN)) {
                mark[d] |= SEEN;
                queue[end++] = d;
            }
        }
    }
    int size = end - *tail;
    *tail = end;
    return size;
}

int am_keep_largest_piece(uint8_t* cell, int nx, int ny, int nz, uint8_t* mark, int32_t* queue)
{
    const int cells = nx * ny * nz;
    /* which neighbours exist, once per cell (no division in the fill) */
    for (int z = 0, c = 0; z < nz; z++)
        for (int y = 0; y < ny; y++)
            for (int x = 0; x < nx; x++, c++)
                mark[c] = (uint8_t)((x < nx - 1) | (x > 0) << 1 | (y < ny - 1) << 2 | (y > 0) << 3 | (z < nz - 1) << 4 |
                                    (z > 0) << 5);
    /* every piece, found from its lowest cell index, goes to the queue after the previous ones
     * (each cell enters once); the first of the largest wins */
    int tail = 0, best_start = 0, best_size = 0;
    for (int c = 0; c < cells; c++) {
        if (!cell[c] || (mark[c] & SEEN)) continue;
        int start = tail;
        int size = fill(cell, nx, ny, c, mark, queue, &tail);
        if (size > best_size) {
            best_size = size;
            best_start = start;
        }
    }
    for (int i = best_start; i < best_start + best_size; i++) mark[queue[i]] |= KEPT;
    for (int c = 0; c < cells; c++)
        if (!(mark[c] & KEPT)) cell[c] = 0;
    return best_size;
}

int am_levelset(am_geno_work* w, int materials, int nx, int ny, int nz, am_real threshold, am_real* ratio)
{
    if (materials < 1 || materials > AM_MAX_GENO_MATERIALS || nx < 1 || ny < 1 || nz < 1 || (long)nx * ny * nz > AM_MAX_CELLS) {
        w->voxels = 0;
        return 0;
    }
    const int cells = nx * ny * nz;
    w->nx = nx;
    w->ny = ny;
    w->nz = nz;
    const am_real* d0 = w->dens[0];
    if (materials == 2) { /* the common cases, in loops the compiler vectorises; same results */
        const am_real* d1 = w->dens[1];
        for (int c = 0; c < cells; c++) w->cell[c] = (uint8_t)(d0[c] + d1[c] > threshold ? (d1[c] > d0[c] ? 2 : 1) : 0);
    } else if (materials == 3) {
        const am_real* d1 = w->dens[1];
        const am_real* d2 = w->dens[2];
        for (int c = 0; c < cells; c++) {
            int b = d1[c] > d0[c] ? 1 : 0;
            am_real bv = d1[c] > d0[c] ? d1[c] : d0[c];
            b = d2[c] > bv ? 2 : b;
            w->cell[c] = (uint8_t)((d0[c] + d1[c]) + d2[c] > threshold ? b + 1 : 0);
        }
    } else {
        for (int c = 0; c < cells; c++) {
            am_real sum = d0[c], bv = d0[c];
            int best = 0;
            for (int m = 1; m < materials; m++) {
                am_real d = w->dens[m][c];
                sum += d;
                if (d > bv) {
                    bv = d;
                    best = m;
                }
            }
            w->cell[c] = (uint8_t)(sum > threshold ? best + 1 : 0);
        }
    }
    w->voxels = am_keep_largest_piece(w->cell, nx, ny, nz, w->scratch.piece.mark, w->scratch.piece.queue);
    if (ratio) {
        for (int c = 0; c < cells; c++) {
            am_real pos = AM_R(0);
            for (int m = 0; m < materials; m++) pos += am_max(w->dens[m][c], AM_R(0));
            for (int m = 0; m < materials; m++)
                ratio[(long)m * cells + c] = w->cell[c] && pos > AM_R(0) ? AM_DIV(am_max(w->dens[m][c], AM_R(0)), pos) : AM_R(0);
        }
    }
    return w->voxels;
}

#if AM_GENO_LAYERS
/* floor(256 t) of a phase t in periods wrapped into [0, 1): 0..255 */
static int phase_byte(am_real v)
{
    am_real t = v - am_floor(v);
#if defined(AM_REAL_FIXED_POINT)
    int b = (int)(t >> (AM_FIX_FRAC - 8));
#else
    int b = (int)(t * AM_R(256));
#endif
    return b < 0 ? 0 : b > 255 ? 255 : b;
}

/* round(255 v) of v in [0, 1]: 0..255 */
static int unit_byte(am_real v)
{
#if defined(AM_REAL_FIXED_POINT)
    int b = (int)(((int64_t)v * 255 + AM_FIX_HALF) >> AM_FIX_FRAC);
#else
    int b = (int)(v * AM_R(255) + AM_R(0.5));
#endif
    return b < 0 ? 0 : b > 255 ? 255 : b;
}

/* the evolved fields of the body just expressed, a byte a filled cell (0 in empty cells) */
static void quantise_controls(const am_genome* g, am_geno_work* w)
{
    const int cells = g->nx * g->ny * g->nz;
    const int ph = am_genome_field_of(g, AM_CTL_PHASE), st = am_genome_field_of(g, AM_CTL_STIFFNESS);
    w->controls = g->controls;
    for (int c = 0; c < cells; c++) {
        const int on = w->cell[c] != 0;
        w->ctl[0][c] = (uint8_t)(on && ph >= 0 ? phase_byte(w->dens[ph][c]) : 0);
        w->ctl[1][c] = (uint8_t)(on && st >= 0 ? unit_byte(w->dens[st][c]) : 0);
    }
}
#endif

am_status am_genome_express(const am_genome* g, const am_express_def* def, am_geno_work* w, am_real* ratio,
                            char* err, int errsz)
{
    am_express_def d = def ? *def : am_default_express();
    am_status st = am_genome_check(g, err, errsz);
    if (st != AM_OK) {
        w->voxels = 0;
        return st;
    }
    am_geno_tables(w);
    am_geno_ops_of(g->repr)->express(g, w);
    am_levelset(w, g->materials, g->nx, g->ny, g->nz, d.threshold, ratio);
#if AM_GENO_LAYERS
    if (g->controls) quantise_controls(g, w);
    else w->controls = 0;
#endif
    return AM_OK;
}

am_param am_stiffness_of_byte(const am_express_def* def, int s)
{
    const am_express_def d = def ? *def : am_default_express();
    if (s <= 0) return d.stiffness_min;
    if (s >= 255) return d.stiffness_max;
    /* the ratio (at most 100) and the power in am_real: the same bits on every platform */
    const am_real ratio = AM_FROM_DOUBLE(AM_PARAM_TO_DOUBLE(d.stiffness_max) / AM_PARAM_TO_DOUBLE(d.stiffness_min));
    const am_real f = am_pow(ratio, AM_RATIO(s, 255));
    return AM_PARAM_FROM_DOUBLE(AM_PARAM_TO_DOUBLE(d.stiffness_min) * AM_TO_DOUBLE(f));
}

am_status am_genome_layers(const am_genome* g, const am_express_def* def, const am_geno_work* w, am_layers* out,
                           char* err, int errsz)
{
    if (out) am_layers_clear(out);
#if AM_GENO_LAYERS
    const am_express_def d = def ? *def : am_default_express();
    if (w->controls != g->controls || w->nx != g->nx || w->ny != g->ny || w->nz != g->nz)
        return am_fail(err, errsz, AM_ERR_ARG, "the workspace does not hold this genome's expression");
    if (!g->controls) return AM_OK;
    if (!(d.stiffness_min > AM_P(0)) || !(d.stiffness_max >= d.stiffness_min) ||
        !(AM_PARAM_TO_DOUBLE(d.stiffness_max) <= 100.0 * AM_PARAM_TO_DOUBLE(d.stiffness_min)))
        return am_fail(err, errsz, AM_ERR_RANGE, "stiffness range %g to %g Pa: needs 0 < min <= max <= 100 min",
                       AM_PARAM_TO_DOUBLE(d.stiffness_min), AM_PARAM_TO_DOUBLE(d.stiffness_max));
    const int cells = g->nx * g->ny * g->nz;
    out->has_phase = (g->controls & AM_CTL_PHASE) != 0;
    out->has_stiffness = (g->controls & AM_CTL_STIFFNESS) != 0;
    am_param E[256];
    if (out->has_stiffness)
        for (int s = 0; s < 256; s++) E[s] = am_stiffness_of_byte(&d, s);
    for (int c = 0; c < cells; c++) {
        if (out->has_phase) out->phase[c] = AM_P(w->ctl[0][c]) / AM_P(256);
        if (out->has_stiffness) out->stiffness[c] = E[w->ctl[1][c]];
    }
    return AM_OK;
#else
    (void)def;
    (void)w;
    if (!g->controls) return AM_OK;
    return am_fail(err, errsz, AM_ERR_CAPACITY, "an evolved phase or stiffness: the %s profile keeps none (AM_GENO_LAYERS 0)",
                   AM_PROFILE_NAME);
#endif
}

am_status am_genome_to_lattice(const am_genome* g, const am_express_def* def, am_geno_work* w, am_lattice* lat,
                               char* err, int errsz)
{
    am_express_def d = def ? *def : am_default_express();
    am_status st = am_genome_express(g, &d, w, NULL, err, errsz);
    if (st != AM_OK) return st;
    /* without a palette the genome's names are looked up in the built-in one, which
     * am_lattice_init puts into lat (none is built on the stack) */
    if (d.palette) {
        for (int m = 0; m < g->materials; m++)
            if (am_palette_find(d.palette, g->mat[m]) < 0)
                return am_fail(err, errsz, AM_ERR_RANGE, "material '%s' of the genome is not in the palette", g->mat[m]);
    }
    st = am_lattice_init(lat, g->nx, g->ny, g->nz, d.voxel_size, err, errsz);
    if (st != AM_OK) return st;
    const am_palette* pal = d.palette ? d.palette : &lat->palette;
    am_material mat[AM_MAX_GENO_MATERIALS];
    for (int m = 0; m < g->materials; m++) {
        int idx = am_palette_find(pal, g->mat[m]);
        if (idx < 0) return am_fail(err, errsz, AM_ERR_RANGE, "material '%s' of the genome is not in the palette", g->mat[m]);
        mat[m] = pal->mat[idx];
    }
    lat->palette.count = g->materials;
    for (int m = 0; m < g->materials; m++) lat->palette.mat[m] = mat[m];
    memcpy(lat->cell, w->cell, (size_t)(g->nx * g->ny * g->nz));
    return AM_OK;
}

am_real am_body_distance(const uint8_t* a, const uint8_t* b, int n)
{
    if (n <= 0) return AM_R(0);
    int diff = 0;
    for (int i = 0; i < n; i++) diff += a[i] != b[i];
    return AM_RATIO(diff, n);
}

am_real am_body_distance_ctl(const uint8_t* a, const uint8_t* actl0, const uint8_t* actl1, const uint8_t* b,
                             const uint8_t* bctl0, const uint8_t* bctl1, int controls, int n)
{
    const int k = (controls & AM_CTL_PHASE ? 1 : 0) + (controls & AM_CTL_STIFFNESS ? 1 : 0);
    if (k == 0) return am_body_distance(a, b, n);
    if (n <= 0) return AM_R(0);
    /* in units of 1 / (128 x 255) of a cell: a phase difference of d / 256 periods (d <= 128 after
     * wrapping) is 255 d of them, a stiffness difference of d bytes 128 d; a material difference
     * is k whole cells (the mean over the k fields is taken at the end) */
    int64_t sum = 0;
    for (int c = 0; c < n; c++) {
        if (a[c] != b[c]) sum += (int64_t)k * 32640;
        else if (a[c]) {
            if (controls & AM_CTL_PHASE) {
                int d = actl0[c] > bctl0[c] ? actl0[c] - bctl0[c] : bctl0[c] - actl0[c];
                sum += 255 * (d > 128 ? 256 - d : d);
            }
            if (controls & AM_CTL_STIFFNESS) sum += 128 * (actl1[c] > bctl1[c] ? actl1[c] - bctl1[c] : bctl1[c] - actl1[c]);
        }
    }
    return AM_RATIO(sum, (int64_t)n * k * 32640);
}

am_status am_genome_distance(const am_genome* a, const am_genome* b, am_geno_work* w, am_real* out,
                             char* err, int errsz)
{
    *out = AM_R(1);
    if (a->nx != b->nx || a->ny != b->ny || a->nz != b->nz)
        return am_fail(err, errsz, AM_ERR_ARG, "distance between genomes of different workspaces");
    am_status st = am_genome_express(a, NULL, w, NULL, err, errsz);
    if (st != AM_OK) return st;
    const int cells = a->nx * a->ny * a->nz;
    memcpy(w->other, w->cell, (size_t)cells);
#if AM_GENO_LAYERS
    if (a->controls != b->controls)
        return am_fail(err, errsz, AM_ERR_ARG, "distance between genomes of different evolved fields");
    memcpy(w->other_ctl, w->ctl, sizeof w->ctl);
    st = am_genome_express(b, NULL, w, NULL, err, errsz);
    if (st != AM_OK) return st;
    *out = am_body_distance_ctl(w->other, w->other_ctl[0], w->other_ctl[1], w->cell, w->ctl[0], w->ctl[1], a->controls, cells);
#else
    st = am_genome_express(b, NULL, w, NULL, err, errsz);
    if (st != AM_OK) return st;
    *out = am_body_distance(w->other, w->cell, cells);
#endif
    return AM_OK;
}
