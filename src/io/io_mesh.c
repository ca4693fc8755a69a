/* The surface of a voxel body as a triangle mesh (include/amorph/io.h).
 *
 * Faces: every face of a voxel whose other side is outside the surface's inside set (BODY: empty
 * space; MATERIALS: anything but the voxel's own material), with its four corners counter-clockwise
 * seen from outside.
 *
 * Vertices: a face corner first stands alone; then, around every lattice edge, the faces of one
 * inside set that meet there are paired and their corners at both ends of the edge merged
 * (union-find over the 4 corners of every face). Around an edge with two boundary faces they are
 * simply the two. Around an edge where two voxels of the set touch only diagonally there are
 * four, and the two faces of the same voxel pair up: the surface pinches along that edge rather
 * than joining the diagonal voxels (the simulator does not link them either). Each merged class is
 * a vertex, so a corner where the surface pinches gets one vertex per fan of faces around it, and
 * every edge of the surface belongs to exactly two faces. The two sides of a pinched edge would
 * still join the same two vertices, so each side gets a midpoint vertex of its own.
 *
 * The split vertices and the midpoints of one pinch sit at one point; am_mesh_open_pinches moves
 * each a little towards the voxels of its own side (vpull), which makes the surface manifold by
 * position as well: what an STL file, which names vertices by their coordinates, needs.
 *
 * Positions: a corner vertex follows the voxels around its corner that are face-connected (inside
 * the 2 x 2 x 2 block of cells around the corner) to the voxel of one of its faces, whatever their
 * material, so that the surfaces of two materials meet exactly. Each face is drawn as four
 * triangles around its centre (the mean of its corners), so a face between two materials is the
 * same four triangles in both of their surfaces, and a bent face has no preferred diagonal. */
#include "amorph/io.h"

#include <math.h>
#include <string.h>

/* corner offsets (bit 0: +x, bit 1: +y, bit 2: +z) of the face of a cell in direction d, counter-
 * clockwise seen from outside */
static const uint8_t face_corner[6][4] = {
    {1, 3, 7, 5}, /* +x */
    {0, 4, 6, 2}, /* -x */
    {2, 6, 7, 3}, /* +y */
    {0, 1, 5, 4}, /* -y */
    {4, 5, 7, 6}, /* +z */
    {0, 2, 3, 1}, /* -z */
};

static int corner_index(const am_mesh* m, int x, int y, int z) { return x + (m->nx + 1) * (y + (m->ny + 1) * z); }

/* the lattice corner of corner k of face f */
static int face_corner_index(const am_mesh* m, long f, int k)
{
    int c = m->face_cell[f], o = face_corner[m->face_dir[f]][k];
    int x = c % m->nx, y = (c / m->nx) % m->ny, z = c / (m->nx * m->ny);
    return corner_index(m, x + (o & 1), y + (o >> 1 & 1), z + (o >> 2 & 1));
}

/* the cell at (x, y, z), -1 outside the lattice */
static int cell_at(const am_mesh* m, int x, int y, int z)
{
    if (x < 0 || y < 0 || z < 0 || x >= m->nx || y >= m->ny || z >= m->nz) return -1;
    return x + m->nx * (y + m->ny * z);
}

static int32_t find(int32_t* parent, int32_t s)
{
    while (parent[s] != s) {
        parent[s] = parent[parent[s]]; /* path halving */
        s = parent[s];
    }
    return s;
}

static void unite(int32_t* parent, int32_t a, int32_t b)
{
    a = find(parent, a), b = find(parent, b);
    if (a < b) parent[b] = a;
    else if (b < a) parent[a] = b;
}

/* the slot (4 f + k) of face f at lattice corner p */
static int32_t slot_at(const am_mesh* m, long f, int p)
{
    for (int k = 0; k < 4; k++)
        if (face_corner_index(m, f, k) == p) return (int32_t)(4 * f + k);
    return -1;
}

/* the edge slot (4 f + k: corner k to k+1) of face f joining lattice corners p and q */
static int32_t edge_at(const am_mesh* m, long f, int p, int q)
{
    for (int k = 0; k < 4; k++) {
        int a = face_corner_index(m, f, k), b = face_corner_index(m, f, (k + 1) & 3);
        if ((a == p && b == q) || (a == q && b == p)) return (int32_t)(4 * f + k);
    }
    return -1;
}

/* the body-level block around corner (x, y, z): which of its 8 cells hold a voxel */
static int block_filled(const am_mesh* m, int x, int y, int z)
{
    int filled = 0;
    for (int b = 0; b < 8; b++) {
        int c = cell_at(m, x - 1 + (b & 1), y - 1 + (b >> 1 & 1), z - 1 + (b >> 2 & 1));
        if (c >= 0 && m->cell_voxel[c] >= 0) filled |= 1 << b;
    }
    return filled;
}

/* the corner vertices where a surface pinches: a lattice corner with two vertices or more of one
 * inside set (one per fan of faces around it). Each such vertex gets, as vpull, the cells of its
 * fan's faces: their voxels lie on its own side of the pinch. Uses mid[] (free until the midpoints)
 * as the list of the vertices at each corner. */
static void split_corners(am_mesh* m, const am_lattice* lat)
{
    long ns = 4 * m->nface, nc = (long)(m->nx + 1) * (m->ny + 1) * (m->nz + 1);
    /* each vertex's fan: the cells of the faces that share it */
    for (long s = 0; s < ns; s++) {
        long f = s / 4;
        int p = m->vcorner[m->slot[s]];
        int px = p % (m->nx + 1), py = (p / (m->nx + 1)) % (m->ny + 1), pz = p / ((m->nx + 1) * (m->ny + 1));
        int c = m->face_cell[f], cx = c % m->nx, cy = (c / m->nx) % m->ny, cz = c / (m->nx * m->ny);
        m->vpull[m->slot[s]] |= (uint8_t)(1 << ((cx == px) | (cy == py) << 1 | (cz == pz) << 2));
    }
    /* the vertices of each corner, listed */
    for (long p = 0; p < nc; p++) m->corner_head[p] = -1;
    for (long v = m->ncorner - 1; v >= 0; v--) m->mid[v] = m->corner_head[m->vcorner[v]], m->corner_head[m->vcorner[v]] = (int32_t)v;
    /* a vertex alone of its set at its corner does not move; the set of a vertex is the material
     * of its fan's cells (AM_MESH_BODY: one set) */
    for (long p = 0; p < nc; p++) {
        int32_t v[24]; /* a fan has 3 faces or more, and 8 cells have 24 faces at a corner */
        int set[24], n = 0;
        int px = (int)(p % (m->nx + 1)), py = (int)((p / (m->nx + 1)) % (m->ny + 1)), pz = (int)(p / ((m->nx + 1) * (m->ny + 1)));
        for (int32_t w = m->corner_head[p]; w >= 0 && n < 24; w = m->mid[w]) {
            int b = 0;
            while (!(m->vpull[w] >> b & 1)) b++;
            v[n] = w;
            set[n++] = m->mode == AM_MESH_BODY ? 1 : lat->cell[cell_at(m, px - 1 + (b & 1), py - 1 + (b >> 1 & 1), pz - 1 + (b >> 2 & 1))];
        }
        for (int i = 0; i < n; i++) {
            int alone = 1;
            for (int j = 0; j < n; j++) alone &= j == i || set[j] != set[i];
            if (alone) m->vpull[v[i]] = 0;
        }
    }
    for (long v = 0; v < m->ncorner; v++) m->mid[v] = -1;
}

/* the cells of the block face-connected to cell bit b0 among the filled ones */
static uint8_t block_component(int filled, int b0)
{
    int mask = 1 << b0, grown = 1;
    while (grown) {
        grown = 0;
        for (int b = 0; b < 8; b++) {
            if (!(mask >> b & 1)) continue;
            for (int a = 0; a < 3; a++) {
                int nb = b ^ (1 << a);
                if ((filled >> nb & 1) && !(mask >> nb & 1)) mask |= 1 << nb, grown = 1;
            }
        }
    }
    return (uint8_t)mask;
}

/* one pass over every lattice edge: pairs the faces of each inside set that meet there. Pass 0
 * merges their corners at the edge's ends; pass 1 gives each side of a pinched edge a midpoint. */
static am_status edge_pass(am_mesh* m, const am_lattice* lat, int pass, char* err, int errsz)
{
    const int n[3] = {m->nx, m->ny, m->nz};
    for (int e = 0; e < 3; e++) {
        int u = (e + 1) % 3, v = (e + 2) % 3; /* u x v = e */
        int p[3];
        for (p[2] = 0; p[2] <= n[2] - (e == 2); p[2]++)
            for (p[1] = 0; p[1] <= n[1] - (e == 1); p[1]++)
                for (p[0] = 0; p[0] <= n[0] - (e == 0); p[0]++) {
                    /* the four cells around the edge, counter-clockwise about +e: (u, v) offsets
                     * (-1, -1), (0, -1), (0, 0), (-1, 0) */
                    static const int du[4] = {-1, 0, 0, -1}, dv[4] = {-1, -1, 0, 0};
                    int cell[4], mat[4];
                    for (int i = 0; i < 4; i++) {
                        int q[3] = {p[0], p[1], p[2]};
                        q[u] += du[i], q[v] += dv[i];
                        cell[i] = cell_at(m, q[0], q[1], q[2]);
                        mat[i] = cell[i] >= 0 ? lat->cell[cell[i]] : 0;
                    }
                    if (!mat[0] && !mat[1] && !mat[2] && !mat[3]) continue;
                    int p1[3] = {p[0], p[1], p[2]};
                    p1[e]++;
                    int c0 = corner_index(m, p[0], p[1], p[2]), c1 = corner_index(m, p1[0], p1[1], p1[2]);
                    /* each inside set present: the body, or each material once */
                    for (int s = 0; s < 4; s++) {
                        int set = m->mode == AM_MESH_BODY ? 1 : mat[s];
                        if (!set) continue;
                        if (m->mode == AM_MESH_BODY && s > 0) break;
                        int dup = 0;
                        for (int t = 0; t < s && m->mode != AM_MESH_BODY; t++) dup |= mat[t] == set;
                        if (dup) continue;
                        int in[4], nb = 0;
                        for (int i = 0; i < 4; i++) in[i] = m->mode == AM_MESH_BODY ? mat[i] != 0 : mat[i] == set;
                        /* boundary j lies between cells j and j+1; its face belongs to the inside
                         * one: j = 0 and 2 are faces across u, 1 and 3 across v */
                        long face[4];
                        for (int j = 0; j < 4; j++) {
                            int k = (j + 1) & 3;
                            face[j] = -1;
                            if (in[j] == in[k]) continue;
                            int own = in[j] ? j : k;
                            /* the outward direction of the owner's face towards the other cell */
                            static const int axis_of[4] = {0, 1, 0, 1}; /* 0: u, 1: v */
                            int ax = axis_of[j] ? v : u;
                            int other = own == j ? k : j;
                            int step = (axis_of[j] ? dv[other] - dv[own] : du[other] - du[own]);
                            int dir = 2 * ax + (step > 0 ? 0 : 1);
                            face[j] = m->face_of[6 * cell[own] + dir];
                            if (face[j] < 0) return am_fail(err, errsz, AM_ERR_ARG, "mesh: a boundary without its face");
                            nb++;
                        }
                        /* the pairs: the two faces, or around a pinch the two of each inside cell */
                        long pa[2] = {-1, -1}, pb[2] = {-1, -1};
                        int side[2] = {0, 0}; /* around a pinch: each pair's cell, its bit in c0's block */
                        if (nb == 2) {
                            int j0 = -1, j1 = -1;
                            for (int j = 0; j < 4; j++)
                                if (face[j] >= 0) {
                                    if (j0 < 0) j0 = j;
                                    else j1 = j;
                                }
                            pa[0] = face[j0], pb[0] = face[j1];
                        } else if (nb == 4) {
                            int w = 0;
                            for (int i = 0; i < 4; i++)
                                if (in[i]) {
                                    side[w] = (du[i] + 1) << u | (dv[i] + 1) << v | 1 << e;
                                    pa[w] = face[(i + 3) & 3], pb[w] = face[i], w++;
                                }
                        } else
                            continue;
                        for (int w = 0; w < 2 && pa[w] >= 0; w++) {
                            if (pass == 0) {
                                unite(m->slot, slot_at(m, pa[w], c0), slot_at(m, pb[w], c0));
                                unite(m->slot, slot_at(m, pa[w], c1), slot_at(m, pb[w], c1));
                            } else if (nb == 4) {
                                if (m->nvert >= AM_MESH_MAX_VERTS)
                                    return am_fail(err, errsz, AM_ERR_CAPACITY, "mesh: more than %ld vertices", AM_MESH_MAX_VERTS);
                                int32_t va = m->slot[slot_at(m, pa[w], c0)], vb = m->slot[slot_at(m, pa[w], c1)];
                                long id = m->nvert++;
                                m->vcorner[id] = -1;
                                m->vmask[id] = 0;
                                m->vpull[id] = (uint8_t)(1 << side[w]);
                                m->vfrom[id][0] = va, m->vfrom[id][1] = vb, m->vfrom[id][2] = va, m->vfrom[id][3] = vb;
                                m->mid[edge_at(m, pa[w], c0, c1)] = (int32_t)id;
                                m->mid[edge_at(m, pb[w], c0, c1)] = (int32_t)id;
                            }
                        }
                    }
                }
    }
    return AM_OK;
}

am_status am_mesh_build(am_mesh* m, const am_lattice* lat, int mode, char* err, int errsz)
{
    if (mode != AM_MESH_BODY && mode != AM_MESH_MATERIALS) return am_fail(err, errsz, AM_ERR_ARG, "mesh: unknown mode %d", mode);
    if (lat->nx < 1 || lat->ny < 1 || lat->nz < 1 || lat->nx > AM_MAX_DIM || lat->ny > AM_MAX_DIM || lat->nz > AM_MAX_DIM)
        return am_fail(err, errsz, AM_ERR_ARG, "mesh: lattice size %d x %d x %d", lat->nx, lat->ny, lat->nz);
    m->mode = mode;
    m->nx = lat->nx, m->ny = lat->ny, m->nz = lat->nz;
    m->voxel_size = AM_PARAM_TO_DOUBLE(lat->voxel_size);
    m->nv = 0;
    m->nface = m->nvert = m->ntri = m->ncorner = 0;
    int ncell = m->nx * m->ny * m->nz;
    for (int c = 0; c < ncell; c++) {
        m->cell_voxel[c] = -1;
        if (!lat->cell[c]) continue;
        m->voxel_cell[m->nv] = c;
        m->cell_voxel[c] = m->nv++;
    }
    if (m->nv == 0) return am_fail(err, errsz, AM_ERR_EMPTY, "the lattice has no voxel");

    /* faces, in cell order then direction */
    for (int c = 0; c < ncell; c++) {
        for (int d = 0; d < 6; d++) m->face_of[6 * c + d] = -1;
        if (!lat->cell[c]) continue;
        int x = c % m->nx, y = (c / m->nx) % m->ny, z = c / (m->nx * m->ny);
        for (int d = 0; d < 6; d++) {
            int s = d & 1 ? -1 : 1, a = d >> 1;
            int o = cell_at(m, x + (a == 0) * s, y + (a == 1) * s, z + (a == 2) * s);
            int other = o >= 0 ? lat->cell[o] : 0;
            if (mode == AM_MESH_BODY ? other != 0 : other == lat->cell[c]) continue;
            if (m->nface >= AM_MESH_MAX_FACES) return am_fail(err, errsz, AM_ERR_CAPACITY, "mesh: more than %ld faces", AM_MESH_MAX_FACES);
            m->face_cell[m->nface] = c;
            m->face_dir[m->nface] = (uint8_t)d;
            m->face_of[6 * c + d] = (int32_t)m->nface++;
        }
    }

    /* corners: each face corner its own class, merged across the paired faces of every edge */
    long ns = 4 * m->nface;
    for (long s = 0; s < ns; s++) m->slot[s] = (int32_t)s, m->mid[s] = -1;
    am_status st = edge_pass(m, lat, 0, err, errsz);
    if (st != AM_OK) return st;
    /* a vertex per class, numbered in order of first appearance; mid[] holds each slot's root */
    for (long s = 0; s < ns; s++) m->mid[s] = find(m->slot, (int32_t)s);
    for (long s = 0; s < ns; s++) {
        int32_t r = m->mid[s];
        if (m->slot[r] != r) continue; /* numbered already (its code is negative) */
        if (m->nvert >= AM_MESH_MAX_VERTS) return am_fail(err, errsz, AM_ERR_CAPACITY, "mesh: more than %ld vertices", AM_MESH_MAX_VERTS);
        long f = s / 4;
        int p = face_corner_index(m, f, (int)(s % 4));
        int px = p % (m->nx + 1), py = (p / (m->nx + 1)) % (m->ny + 1), pz = p / ((m->nx + 1) * (m->ny + 1));
        int c = m->face_cell[f], cx = c % m->nx, cy = (c / m->nx) % m->ny, cz = c / (m->nx * m->ny);
        int b = (cx == px) | (cy == py) << 1 | (cz == pz) << 2;
        long id = m->nvert++;
        m->vcorner[id] = p;
        m->vmask[id] = block_component(block_filled(m, px, py, pz), b);
        m->vpull[id] = 0;
        m->slot[r] = (int32_t)(-2 - id);
    }
    for (long s = 0; s < ns; s++) m->mid[s] = -2 - m->slot[m->mid[s]];
    for (long s = 0; s < ns; s++) m->slot[s] = m->mid[s], m->mid[s] = -1;
    m->ncorner = m->nvert;
    split_corners(m, lat);
    st = edge_pass(m, lat, 1, err, errsz);
    if (st != AM_OK) return st;

    /* triangles: four around each face's centre, and two where an edge has a midpoint */
    for (long f = 0; f < m->nface; f++) {
        if (m->nvert >= AM_MESH_MAX_VERTS) return am_fail(err, errsz, AM_ERR_CAPACITY, "mesh: more than %ld vertices", AM_MESH_MAX_VERTS);
        long ctr = m->nvert++;
        m->vcorner[ctr] = -1;
        m->vmask[ctr] = 0;
        m->vpull[ctr] = 0;
        for (int k = 0; k < 4; k++) m->vfrom[ctr][k] = m->slot[4 * f + k];
        uint8_t mat = (uint8_t)(lat->cell[m->face_cell[f]] - 1);
        for (int k = 0; k < 4; k++) {
            int32_t a = m->slot[4 * f + k], b = m->slot[4 * f + ((k + 1) & 3)], md = m->mid[4 * f + k];
            int32_t t[2][3] = {{(int32_t)ctr, a, md < 0 ? b : md}, {(int32_t)ctr, md, b}};
            for (int h = 0; h < (md < 0 ? 1 : 2); h++) {
                if (m->ntri >= AM_MESH_MAX_TRIS) return am_fail(err, errsz, AM_ERR_CAPACITY, "mesh: more than %ld triangles", AM_MESH_MAX_TRIS);
                memcpy(m->tri[m->ntri], t[h], sizeof t[h]);
                m->tmat[m->ntri++] = mat;
            }
        }
    }
    return AM_OK;
}

/* the vertices that are means of others, in order (each only of earlier ones) */
static void place_means(const am_mesh* m, double* pos)
{
    for (long v = m->ncorner; v < m->nvert; v++)
        for (int k = 0; k < 3; k++) {
            const int32_t* f = m->vfrom[v];
            pos[3 * v + k] = ((pos[3 * f[0] + k] + pos[3 * f[1] + k]) + (pos[3 * f[2] + k] + pos[3 * f[3] + k])) * 0.25;
        }
}

void am_mesh_rest(const am_mesh* m, double* pos)
{
    double L = m->voxel_size;
    for (long v = 0; v < m->ncorner; v++) {
        int p = m->vcorner[v];
        pos[3 * v] = (p % (m->nx + 1)) * L;
        pos[3 * v + 1] = ((p / (m->nx + 1)) % (m->ny + 1)) * L;
        pos[3 * v + 2] = (p / ((m->nx + 1) * (m->ny + 1))) * L;
    }
    place_means(m, pos);
}

void am_mesh_half(const am_mesh* m, const float* pose, int i, double half[3])
{
    double L = m->voxel_size, sum = 0;
    int have = 0, c = m->voxel_cell[i];
    int x = c % m->nx, y = (c / m->nx) % m->ny, z = c / (m->nx * m->ny);
    const float* pi = pose + 7 * i;
    for (int a = 0; a < 3; a++) {
        double s = 0;
        int n = 0;
        for (int sg = -1; sg <= 1; sg += 2) {
            int o = cell_at(m, x + (a == 0) * sg, y + (a == 1) * sg, z + (a == 2) * sg);
            int j = o >= 0 ? m->cell_voxel[o] : -1;
            if (j < 0) continue;
            const float* pj = pose + 7 * j;
            double dx = (double)pj[0] - (double)pi[0], dy = (double)pj[1] - (double)pi[1], dz = (double)pj[2] - (double)pi[2];
            s += sqrt(dx * dx + dy * dy + dz * dz);
            n++;
        }
        half[a] = n ? 0.5 * s / n : -1;
        if (n) sum += half[a], have++;
    }
    for (int a = 0; a < 3; a++)
        if (half[a] < 0) half[a] = have ? sum / have : 0.5 * L;
    for (int a = 0; a < 3; a++)
        if (half[a] > L) half[a] = L; /* a torn-apart link must not make a giant voxel */
}

void am_mesh_place(const am_mesh* m, const float* pose, double* pos)
{
    for (long v = 0; v < m->ncorner; v++) {
        int p = m->vcorner[v];
        int px = p % (m->nx + 1), py = (p / (m->nx + 1)) % (m->ny + 1), pz = p / ((m->nx + 1) * (m->ny + 1));
        double sum[3] = {0, 0, 0};
        int n = 0;
        for (int b = 0; b < 8; b++) {
            if (!(m->vmask[v] >> b & 1)) continue;
            int bx = b & 1, by = b >> 1 & 1, bz = b >> 2 & 1;
            int j = m->cell_voxel[cell_at(m, px - 1 + bx, py - 1 + by, pz - 1 + bz)];
            const float* f = pose + 7 * j;
            double q[4] = {(double)f[3], (double)f[4], (double)f[5], (double)f[6]}, h[3], w[3];
            double qn = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            if (!(qn > 0.5)) q[0] = 1, q[1] = q[2] = q[3] = 0, qn = 1;
            for (int k = 0; k < 4; k++) q[k] /= qn;
            am_mesh_half(m, pose, j, h);
            /* the corner is on the voxel's -axis side when the voxel lies on the corner's + side */
            double o[3] = {bx ? -h[0] : h[0], by ? -h[1] : h[1], bz ? -h[2] : h[2]};
            am_quat_rotate(q, o, w);
            for (int k = 0; k < 3; k++) sum[k] += (double)f[k] + w[k];
            n++;
        }
        for (int k = 0; k < 3; k++) pos[3 * v + k] = n ? sum[k] / n : 0;
    }
    place_means(m, pos);
}

void am_mesh_open_pinches(const am_mesh* m, const float* pose, double* pos)
{
    double L = m->voxel_size;
    for (long v = 0; v < m->nvert; v++) {
        if (v >= m->ncorner)
            for (int k = 0; k < 3; k++) {
                const int32_t* f = m->vfrom[v];
                pos[3 * v + k] = ((pos[3 * f[0] + k] + pos[3 * f[1] + k]) + (pos[3 * f[2] + k] + pos[3 * f[3] + k])) * 0.25;
            }
        if (!m->vpull[v]) continue;
        /* the centre of the voxels it pulls to, around its corner (a midpoint's: its first end's) */
        int p = m->vcorner[v < m->ncorner ? v : m->vfrom[v][0]];
        int px = p % (m->nx + 1), py = (p / (m->nx + 1)) % (m->ny + 1), pz = p / ((m->nx + 1) * (m->ny + 1));
        double c[3] = {0, 0, 0};
        int n = 0;
        for (int b = 0; b < 8; b++) {
            if (!(m->vpull[v] >> b & 1)) continue;
            int q[3] = {px - 1 + (b & 1), py - 1 + (b >> 1 & 1), pz - 1 + (b >> 2 & 1)};
            int j = m->cell_voxel[cell_at(m, q[0], q[1], q[2])];
            for (int k = 0; k < 3; k++) c[k] += pose ? (double)pose[7 * j + k] : (q[k] + 0.5) * L;
            n++;
        }
        for (int k = 0; k < 3; k++) pos[3 * v + k] += AM_MESH_PINCH_PULL * (c[k] / n - pos[3 * v + k]);
    }
}

int am_mesh_holds(const am_mesh* m, int mat)
{
    for (long t = 0; t < m->ntri; t++)
        if (m->tmat[t] == mat) return 1;
    return 0;
}

double am_mesh_volume(const am_mesh* m, const double* pos, int mat)
{
    double vol = 0;
    for (long t = 0; t < m->ntri; t++) {
        if (mat >= 0 && m->tmat[t] != mat) continue;
        const double *a = pos + 3 * m->tri[t][0], *b = pos + 3 * m->tri[t][1], *c = pos + 3 * m->tri[t][2];
        vol += a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    return vol / 6;
}
