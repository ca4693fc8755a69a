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
    return AM_OK;
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
    st = am_genome_express(b, NULL, w, NULL, err, errsz);
    if (st != AM_OK) return st;
    *out = am_body_distance(w->other, w->cell, cells);
    return AM_OK;
}
