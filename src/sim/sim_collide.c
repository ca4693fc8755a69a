/* Self-collision (docs/physics.md section 6).
 *
 * Only surface voxels (fewer than 6 links) collide. Candidate pairs are surface voxels whose
 * centres are closer than 2.5 L and that are not within two links of each other in the lattice
 * (the seed's rule). The list is kept and rebuilt only when some voxel has moved, since the last
 * rebuild, more than half the slack between 2.5 L and the largest contact distance: until then no
 * pair off the list can touch. The rebuild hashes voxel centres into a spatial grid of 2.5 L
 * cells (fixed bucket array; the voxels counting-sorted by bucket into a fixed array, with a copy
 * of their centres on the desktop), so it costs O(n), not O(n^2).
 *
 * Contacts are spheres of radius 0.625 s L; overlapping pairs push apart along the line of
 * centres with the harmonic mean of the two contact stiffnesses plus collision damping on the
 * approach speed. The pair list is walked serially in its (deterministic) order. */
#include "sim_internal.h"

#include <string.h>

#define CAND_FACTOR AM_R(2.5)

/* 1 when voxels i and j are joined by one link or by two. Links join voxels one lattice step
 * apart along their direction, so a path of one or two links from i to j is a way of writing the
 * lattice offset of j from i as that many unit steps: only offsets of one or two steps can be, and
 * only the (at most two) orders of their steps need looking at; d is the offset of j from i */
static int within_two_links(const am_model* m, int i, int j, const int d[3])
{
    int step[2], n = 0;
    for (int a = 0; a < 3; a++)
        for (int k = d[a] < 0 ? -d[a] : d[a]; k > 0; k--) {
            if (n == 2) return 0; /* three or more steps */
            step[n++] = 2 * a + (d[a] < 0); /* the direction: +x, -x, +y, -y, +z, -z */
        }
    if (n == 1) return am_neighbour(m, step[0], i) == j;
    if (n != 2) return 0;
    for (int o = 0; o < (step[0] == step[1] ? 1 : 2); o++) {
        const int v = am_neighbour(m, step[o], i);
        if (v >= 0 && am_neighbour(m, step[1 - o], v) == j) return 1;
    }
    return 0;
}

/* the lattice offset along one axis of two voxels whose rest centres are e apart there, for
 * offsets of at most 2: rest centres sit on a lattice of pitch L, so e is within rounding of a
 * multiple of L (and no division into lattice indices is needed) */
static int lattice_offset(am_real e, am_real half_L, am_real three_half_L)
{
    return (e > half_L) + (e > three_half_L) - (e < -half_L) - (e < -three_half_L);
}

static uint32_t bucket_of(long cx, long cy, long cz)
{
    uint32_t h = (uint32_t)cx * 73856093u ^ (uint32_t)cy * 19349663u ^ (uint32_t)cz * 83492791u;
    return h & (AM_COLL_BUCKETS - 1);
}

#if defined(AM_REAL_FIXED_POINT)
static long cell_coord(am_real x, am_real inv_h) { return (long)AM_FLOOR_INT(AM_MUL(x, inv_h)); }
#else
static long cell_coord(am_real x, am_real inv_h) { return (long)am_floor(AM_MUL(x, inv_h)); }
#endif

/* the centre of voxel i along c: x holds displacements from the rest lattice x0. The desktop keeps
 * the centres of the step in s->pos (collision_positions), the board computes them where read: the
 * same values, so the same contacts */
#if defined(AM_COMPACT)
#define POS(c, i) (m->x0[c][i] + s->x[c][i])
#else
#define POS(c, i) (s->pos[c][i])
#endif

#if !defined(AM_COMPACT)
/* the width of a bin of the pairs' distances: AM_COLL_GAP_BINS over the 2 slack between the
 * contact range and h (not positive when there is no slack: every step rebuilds then, and every
 * pair goes in the first bin) */
static am_real gap_width(const am_model* m)
{
    return AM_MUL(AM_MUL(CAND_FACTOR, m->L) - m->coll_range, AM_R(1.0 / AM_COLL_GAP_BINS));
}

/* the bin of a pair d2 = d0^2 apart at the rebuild: floor((d0 - range) / width), in [0, bins) */
static int gap_bin(am_real d2, am_real range, am_real inv_w)
{
    const am_real u = AM_MUL(am_sqrt(d2) - range, inv_w);
    if (!(u > AM_R(0))) return 0;
    if (u >= AM_INT(AM_COLL_GAP_BINS - 1)) return AM_COLL_GAP_BINS - 1;
    return (int)AM_FLOOR_INT(u);
}

/* pair_by_gap: the pairs' indices counting-sorted by the bins that pair_touch holds */
static void sort_by_gap(am_state* s)
{
    int32_t* end = s->gap_end;
    for (int b = 0; b < AM_COLL_GAP_BINS; b++) end[b] = 0;
    for (int k = 0; k < s->npairs; k++) end[s->pair_touch[k]]++;
    int32_t sum = 0;
    for (int b = 0; b < AM_COLL_GAP_BINS; b++) {
        const int32_t n = end[b];
        end[b] = sum;
        sum += n;
    }
    for (int k = 0; k < s->npairs; k++) s->pair_by_gap[end[s->pair_touch[k]]++] = (am_index)k;
}
#endif

/* the bucket of voxel i's centre */
static uint32_t voxel_bucket(const am_model* m, const am_state* s, int i, am_real inv_h)
{
    (void)m; /* read by the board's POS */
    return bucket_of(cell_coord(POS(0, i), inv_h), cell_coord(POS(1, i), inv_h), cell_coord(POS(2, i), inv_h));
}

/* the centre of entry k of the sorted buckets: a copy on the desktop, read where it is on the board */
#if defined(AM_COMPACT)
#define ITEM_POS(c, k) POS(c, s->bucket_item[k])
#else
#define ITEM_POS(c, k) (s->bucket_pos[c][k])
#endif

static void rebuild(const am_model* m, am_state* s)
{
    const int nv = m->nv;
    const am_real h = AM_MUL(CAND_FACTOR, m->L), h2 = AM_MUL(h, h), inv_h = AM_DIV(AM_R(1), h);
    /* two voxels within two links are at most two lattice steps apart (Manhattan), so a pair whose
     * rest centres are further apart than 2.5 edges needs no look at the links */
    const am_real lattice_far = AM_MUL(AM_R(2.5), m->L), half_L = AM_MUL(AM_R(0.5), m->L), three_half_L = AM_MUL(AM_R(1.5), m->L);
    am_index* end = s->bucket_end;
#if !defined(AM_COMPACT)
    const am_real w = gap_width(m), inv_w = w > AM_R(0) ? AM_DIV(AM_R(1), w) : AM_R(0);
#endif
    /* the surface voxels sorted by bucket (a counting sort), ascending within each bucket */
    for (int b = 0; b < AM_COLL_BUCKETS; b++) end[b] = 0;
    for (int i = 0; i < nv; i++)
        if (m->surface[i]) end[voxel_bucket(m, s, i, inv_h)]++;
    int sum = 0;
    for (int b = 0; b < AM_COLL_BUCKETS; b++) {
        int n = end[b];
        end[b] = (am_index)sum; /* the bucket's first entry; the placing below moves it to its end */
        sum += n;
    }
    for (int i = 0; i < nv; i++) {
        if (!m->surface[i]) continue;
        const int k = end[voxel_bucket(m, s, i, inv_h)]++;
        s->bucket_item[k] = (am_index)i;
#if !defined(AM_COMPACT)
        for (int c = 0; c < 3; c++) s->bucket_pos[c][k] = POS(c, i);
#endif
    }
#if !defined(AM_COMPACT)
    for (int b = 0; b < AM_COLL_BUCKETS; b++) {
        s->bucket_seen[b] = 0;
        s->bucket_cursor[b] = b ? end[b - 1] : 0;
    }
#endif
    int np = 0;
    for (int i = 0; i < nv; i++) {
        if (!m->surface[i]) continue;
        const am_real pix = POS(0, i), piy = POS(1, i), piz = POS(2, i);
        long cx = cell_coord(pix, inv_h), cy = cell_coord(piy, inv_h), cz = cell_coord(piz, inv_h);
#if defined(AM_COMPACT)
        uint32_t seen[27];
        int nseen = 0;
#endif
        for (int dz = -1; dz <= 1; dz++)
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) {
                    uint32_t b = bucket_of(cx + dx, cy + dy, cz + dz);
                    AM_ASSERT(b < AM_COLL_BUCKETS);
                    /* two cells that hash alike: the bucket is visited once, at the first; then
                     * its entries after i, the pairs (i, j > i) */
#if defined(AM_COMPACT)
                    int dup = 0;
                    for (int k = 0; k < nseen; k++) dup |= seen[k] == b;
                    if (dup) continue;
                    AM_ASSERT(nseen < 27);
                    seen[nseen++] = b;
                    int k = b ? end[b - 1] : 0;
                    const int k1 = end[b];
                    while (k < k1 && s->bucket_item[k] <= i) k++;
#else
                    if (s->bucket_seen[b] == i + 1) continue;
                    s->bucket_seen[b] = i + 1;
                    /* i only grows, so the entries the cursor passed stay behind */
                    int k = s->bucket_cursor[b];
                    const int k1 = end[b];
                    while (k < k1 && s->bucket_item[k] <= i) k++;
                    s->bucket_cursor[b] = (am_index)k;
#endif
                    for (; k < k1; k++) {
                        const int j = s->bucket_item[k];
                        AM_ASSERT(j > i && j < m->nv); /* a bucket's entries after i are voxels after it */
                        am_real ex = ITEM_POS(0, k) - pix, ey = ITEM_POS(1, k) - piy, ez = ITEM_POS(2, k) - piz;
#if defined(AM_REAL_FIXED_POINT)
                        /* a far pair is out on one axis already (and its square might leave the
                         * fixed-point range) */
                        if (am_fabs(ex) >= h || am_fabs(ey) >= h || am_fabs(ez) >= h) continue;
#endif
                        /* in floating point |e| >= h on one axis gives d2 >= h2 too (rounding
                         * keeps the order of squares and of sums of non-negatives), so the one
                         * test, without a branch per axis, takes the same pairs */
                        const am_real d2 = AM_MUL(ex, ex) + AM_MUL(ey, ey) + AM_MUL(ez, ez);
                        if (d2 >= h2) continue;
                        const am_real rx = m->x0[0][j] - m->x0[0][i], ry = m->x0[1][j] - m->x0[1][i], rz = m->x0[2][j] - m->x0[2][i];
                        if (am_fabs(rx) + am_fabs(ry) + am_fabs(rz) < lattice_far) {
                            /* at most two steps on each axis */
                            const int d[3] = {lattice_offset(rx, half_L, three_half_L), lattice_offset(ry, half_L, three_half_L),
                                              lattice_offset(rz, half_L, three_half_L)};
                            if (within_two_links(m, i, j, d)) continue;
                        }
                        if (np >= AM_MAX_PAIRS) {
                            s->pairs_overflow = 1;
                            continue;
                        }
                        s->pa[np] = (am_index)i;
                        s->pb[np] = (am_index)j;
#if !defined(AM_COMPACT)
                        s->pair_touch[np] = (uint8_t)gap_bin(d2, m->coll_range, inv_w);
#endif
                        np++;
                    }
                }
    }
    /* pairs come out grouped by bucket visit order, ascending within a bucket; that order is fixed
     * by the positions, so the list is deterministic */
    s->npairs = np;
    if (np > s->max_npairs) s->max_npairs = np;
#if !defined(AM_COMPACT)
    sort_by_gap(s);
#endif
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < nv; i++) s->xref[c][i] = s->x[c][i];
    s->rebuilds++;
}

typedef am_real vox_row[AM_MAX_VOXELS];

/* 1 when some voxel is farther than sqrt(lim) = slack from where it was at the last rebuild
 * (restrict parameters and no early exit, so that the compiler vectorises it); *most the
 * largest square of a voxel's move (trusted when 0 is returned) */
/* the largest move is kept as a key that compares as the square does: the square itself in fixed
 * point; else its bits, which compare as unsigned integers in the order of the (never negative)
 * value, so that the maximum is an integer one, which the compiler vectorises (a floating one it
 * may not reorder) */
#if defined(AM_REAL_FIXED_POINT)
typedef am_real move_key;
static inline move_key key_of(am_real d2) { return d2; }
static inline am_real real_of(move_key k) { return k; }
#else
#if defined(AM_REAL_DOUBLE)
typedef uint64_t move_key;
#else
typedef uint32_t move_key;
#endif
static inline move_key key_of(am_real d2)
{
    move_key k;
    memcpy(&k, &d2, sizeof k);
    return k;
}
static inline am_real real_of(move_key k)
{
    am_real d2;
    memcpy(&d2, &k, sizeof d2);
    return d2;
}
#endif

static int moved_far(int nv, am_real slack, am_real lim, const vox_row* restrict x, const vox_row* restrict xref, am_real* most)
{
    int far = 0;
    move_key top = key_of(AM_R(0));
    (void)slack; /* read by the fixed-point build only */
    for (int i = 0; i < nv; i++) {
        am_real ex = x[0][i] - xref[0][i], ey = x[1][i] - xref[1][i], ez = x[2][i] - xref[2][i];
#if defined(AM_REAL_FIXED_POINT)
        /* out on one axis already: then the square below may have left the range and is not
         * trusted (an or over all voxels, as the early return of the scalar test was) */
        far |= (am_fabs(ex) > slack) + (am_fabs(ey) > slack) + (am_fabs(ez) > slack) > 0;
#endif
        const am_real d2 = AM_MUL(ex, ex) + AM_MUL(ey, ey) + AM_MUL(ez, ez);
        const move_key k = key_of(d2);
        far |= d2 > lim;
        top = k > top ? k : top;
    }
    *most = real_of(top);
    return far;
}

/* 1 when the list must be rebuilt; else *most is the largest square of a voxel's move since */
static int needs_rebuild(const am_model* m, const am_state* s, am_real* most)
{
    *most = AM_R(0);
    if (s->npairs < 0) return 1;
    am_real slack = AM_MUL(AM_R(0.5), AM_MUL(CAND_FACTOR, m->L) - m->coll_range);
    if (!(slack > AM_R(0))) return 1;
    return moved_far(m->nv, slack, AM_MUL(slack, slack), (const vox_row*)s->x, (const vox_row*)s->xref, most);
}

/* the centres of the voxels for the contact tests: x0 + x where read on the board, the step's
 * copy in pos on the desktop */
#define PAIR_CHUNK 64
#if defined(AM_COMPACT)
#define CENTRES_PARAM const vox_row *restrict x0, const vox_row *restrict x
#define CENTRES_ARG(m, s) (const vox_row*)(m)->x0, (const vox_row*)(s)->x
#define CENTRE(c, i) (x0[c][i] + x[c][i])
#else
#define CENTRES_PARAM const vox_row* restrict pos
#define CENTRES_ARG(m, s) (const vox_row*)(s)->pos
#define CENTRE(c, i) pos[c][i]
/* the centres of the step, once, for the candidate pairs to gather */
static void collision_positions(int nv, const vox_row* restrict x0, const vox_row* restrict x, vox_row* restrict pos)
{
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < nv; i++) pos[c][i] = x0[c][i] + x[c][i];
}
#endif

#if defined(AM_COMPACT)
/* touch[j] = 1 when the candidate pair k0 + j (j < n) overlaps: the test of am_sim_collide, for
 * a chunk of the list at once (no branch: the compiler vectorises it) */
static void overlaps(int n, am_real rad, const am_index* restrict pa, const am_index* restrict pb, CENTRES_PARAM,
                     const am_real* restrict scale, int32_t* restrict touch)
{
    for (int j = 0; j < n; j++) {
        const int a = pa[j], b = pb[j];
        am_real ex = CENTRE(0, b) - CENTRE(0, a), ey = CENTRE(1, b) - CENTRE(1, a), ez = CENTRE(2, b) - CENTRE(2, a);
        am_real reach = AM_MUL(rad, scale[a] + scale[b]);
        am_real d2 = AM_MUL(ex, ex) + AM_MUL(ey, ey) + AM_MUL(ez, ez);
        touch[j] = !(d2 >= AM_MUL(reach, reach)) & (d2 > AM_R(0));
    }
}
#else
/* hit[q] = 1 when the candidate pair idx[q] (q < n) overlaps: the test of am_sim_collide for the
 * pairs a step tests, a chunk at once (no branch: the compiler vectorises it) */
static void overlaps_of(int n, am_real rad, const am_index* restrict idx, const am_index* restrict pa, const am_index* restrict pb,
                        CENTRES_PARAM, const am_real* restrict scale, int32_t* restrict hit)
{
    for (int q = 0; q < n; q++) {
        const int k = idx[q], a = pa[k], b = pb[k];
        am_real ex = CENTRE(0, b) - CENTRE(0, a), ey = CENTRE(1, b) - CENTRE(1, a), ez = CENTRE(2, b) - CENTRE(2, a);
        am_real reach = AM_MUL(rad, scale[a] + scale[b]);
        am_real d2 = AM_MUL(ex, ex) + AM_MUL(ey, ey) + AM_MUL(ez, ez);
        hit[q] = !(d2 >= AM_MUL(reach, reach)) & (d2 > AM_R(0));
    }
}
#endif

void am_sim_collide(const am_model* m, am_state* s)
{
    if (!m->env.collisions) return; /* without self-collision fc is not read */
    const int nv = m->nv;
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < nv; i++) s->fc[c][i] = AM_R(0);
#if !defined(AM_COMPACT)
    collision_positions(nv, (const vox_row*)m->x0, (const vox_row*)s->x, s->pos);
#endif
    am_real most;
    if (needs_rebuild(m, s, &most)) {
        rebuild(m, s);
        most = AM_R(0);
    }
    const am_real rad = AM_MUL(AM_R(0.625), m->L);
#if !defined(AM_COMPACT)
    /* A pair d0 apart at the rebuild is now at least d0 - 2 D apart, D the largest move of a voxel
     * since, and touches only closer than the contact range: only the bins below 2 D (and a
     * margin for rounding) above the range are tested, the others cannot touch. The overlapping
     * pairs are then walked in the list's order, so the forces add up as when every pair is tested */
    uint8_t* touch = s->pair_touch;
    const int np = s->npairs;
    memset(touch, 0, (size_t)(np > 0 ? np : 0));
    int nb = AM_COLL_GAP_BINS;
    const am_real w = gap_width(m);
    if (w > AM_R(0)) {
        const am_real u = AM_DIV(AM_MUL(AM_R(2), am_sqrt(most)) + AM_MUL(AM_R(1.0 / 1024), m->L), w);
        if (u < AM_INT(AM_COLL_GAP_BINS - 1)) nb = (int)AM_FLOOR_INT(u) + 1;
    }
    const int ntest = np > 0 ? s->gap_end[nb - 1] : 0;
    int32_t hit[PAIR_CHUNK];
    for (int k = 0; k < ntest; k += PAIR_CHUNK) {
        const int n = ntest - k < PAIR_CHUNK ? ntest - k : PAIR_CHUNK;
        overlaps_of(n, rad, s->pair_by_gap + k, s->pa, s->pb, CENTRES_ARG(m, s), s->s, hit);
        for (int q = 0; q < n; q++) touch[s->pair_by_gap[k + q]] = (uint8_t)hit[q];
    }
    for (int k = 0; k < np; k++) {
        /* few pairs touch: eight flags at a time while they are all clear */
        if ((k & 7) == 0 && np - k >= 8) {
            uint64_t eight;
            memcpy(&eight, touch + k, sizeof eight);
            if (!eight) {
                k += 7;
                continue;
            }
        }
        if (!touch[k]) continue;
#else
    int32_t touch[PAIR_CHUNK];
    for (int k = 0; k < s->npairs; k++) {
        if (k % PAIR_CHUNK == 0) {
            int n = s->npairs - k < PAIR_CHUNK ? s->npairs - k : PAIR_CHUNK;
            overlaps(n, rad, s->pa + k, s->pb + k, CENTRES_ARG(m, s), s->s, touch);
        }
        if (!touch[k % PAIR_CHUNK]) continue;
#endif
        const int a = s->pa[k], b = s->pb[k];
        am_real ex = POS(0, b) - POS(0, a), ey = POS(1, b) - POS(1, a), ez = POS(2, b) - POS(2, a);
        am_real reach = AM_MUL(rad, s->s[a] + s->s[b]);
        am_real d2 = AM_MUL(ex, ex) + AM_MUL(ey, ey) + AM_MUL(ez, ez);
        if (d2 >= AM_MUL(reach, reach) || !(d2 > AM_R(0))) continue;
        am_real d = am_sqrt(d2), inv = AM_DIV(AM_R(1), d);
        am_real nx = AM_MUL(ex, inv), ny = AM_MUL(ey, inv), nz = AM_MUL(ez, inv);
        am_real ka = m->k_floor[AM_VC(m, a)], kb = m->k_floor[AM_VC(m, b)];
        am_real k_h = AM_DIV(AM_MUL(AM_R(2), AM_MUL(ka, kb)), ka + kb); /* harmonic mean */
        am_real c = AM_MUL(AM_R(0.5), m->c_col[AM_VC(m, a)] + m->c_col[AM_VC(m, b)]);
        am_real approach = AM_MUL(am_sim_vel(m, s, 0, a) - am_sim_vel(m, s, 0, b), nx) +
                           AM_MUL(am_sim_vel(m, s, 1, a) - am_sim_vel(m, s, 1, b), ny) +
                           AM_MUL(am_sim_vel(m, s, 2, a) - am_sim_vel(m, s, 2, b), nz);
        am_real f = AM_MUL(k_h, reach - d) + AM_MUL(c, approach);
        if (f <= AM_R(0)) continue; /* contacts push, never pull */
        s->fc[0][a] -= AM_MUL(f, nx); s->fc[1][a] -= AM_MUL(f, ny); s->fc[2][a] -= AM_MUL(f, nz);
        s->fc[0][b] += AM_MUL(f, nx); s->fc[1][b] += AM_MUL(f, ny); s->fc[2][b] += AM_MUL(f, nz);
    }
}
