/* tests/test_io_mesh.c: the surface mesh (src/io/io_mesh.c), its self-intersection check (src/io/io_mesh_cross.c)
 * and its STL and AMF files (src/io/io_printable.c). A manifold check of our own, over a triangle soup:
 * every edge in exactly two triangles, once each way round (closed, consistently turned), and
 * every vertex's link (the far edges of its triangles) one cycle (a single disc of triangles
 * around it). It runs on the mesh's vertex numbers and, as a slicer sees an STL file, on vertices
 * welded by their printed positions (%.7g mm), after am_mesh_open_pinches. Shapes: voxels touching
 * along an edge, at a corner, checkerboards, multi-material bodies (per material) and the merged
 * body, at rest and deformed; outward normals (volume = voxels x L^3, a sliver less where pinches
 * open); surfaces of two materials that meet exactly; a placed rest pose equal to the rest shape;
 * no crossing at rest and crossings found where voxels are pushed into each other; the written
 * files read back.
 *
 * `test_io_mesh --stl-check FILE` checks an STL file the same way (what tests/cli_printable.sh uses)
 * and prints "solids S facets F volume V open_edges E bad_vertices B" (V in the file's units^3). */
#include "amorph.h"
#include "amorph/io.h"
#include "harness.h"

static am_mesh g_mesh;
static am_lattice g_lat;
static am_mesh_grid g_grid;
static double g_pos[3 * AM_MESH_MAX_VERTS], g_pos2[3 * AM_MESH_MAX_VERTS];
static float g_pose[7 * AM_MAX_VOXELS];
static int64_t g_edge[3 * AM_MESH_MAX_TRIS];
static char g_text[16L << 20];

/* the soup: three vertex numbers per triangle; for welding, the corners' positions */
static int32_t g_soup[AM_MESH_MAX_TRIS][3];
static double g_corner[3 * AM_MESH_MAX_TRIS][3];
static int32_t g_idx[3 * AM_MESH_MAX_TRIS];
typedef struct link_t {
    int64_t key; /* vertex << 32 | the next vertex of the triangle */
    int32_t far; /* the one after that */
} link_t;
static link_t g_link[3 * AM_MESH_MAX_TRIS];

static int cmp_i64(const void* a, const void* b)
{
    int64_t x = *(const int64_t*)a, y = *(const int64_t*)b;
    return x < y ? -1 : x > y;
}

static int cmp_link(const void* a, const void* b) { return cmp_i64(&((const link_t*)a)->key, &((const link_t*)b)->key); }

static int cmp_corner(const void* a, const void* b)
{
    const double *p = g_corner[*(const int32_t*)a], *q = g_corner[*(const int32_t*)b];
    for (int k = 0; k < 3; k++)
        if (p[k] != q[k]) return p[k] < q[k] ? -1 : 1;
    return 0;
}

/* the soup's vertex numbers from g_corner (3 n corners): equal positions, one vertex */
static void weld(long n)
{
    for (long i = 0; i < 3 * n; i++) g_idx[i] = (int32_t)i;
    qsort(g_idx, (size_t)(3 * n), sizeof g_idx[0], cmp_corner);
    int32_t id = -1;
    for (long i = 0; i < 3 * n; i++) {
        if (i == 0 || cmp_corner(&g_idx[i - 1], &g_idx[i])) id++;
        g_soup[g_idx[i] / 3][g_idx[i] % 3] = id;
    }
}

typedef struct manifold {
    long open_edges;   /* directed edges present twice or without their reverse */
    long bad_vertices; /* vertices whose link is not one cycle */
} manifold;

/* the manifold check of the first n triangles of the soup */
static manifold check_soup(long n)
{
    manifold r = {0, 0};
    long ne = 0;
    for (long t = 0; t < n; t++)
        for (int k = 0; k < 3; k++) {
            int32_t a = g_soup[t][k], b = g_soup[t][(k + 1) % 3], c = g_soup[t][(k + 2) % 3];
            g_edge[ne] = (int64_t)a << 32 | b;
            g_link[ne].key = g_edge[ne], g_link[ne].far = c;
            ne++;
        }
    qsort(g_edge, (size_t)ne, sizeof g_edge[0], cmp_i64);
    for (long i = 0; i < ne; i++) {
        if (i + 1 < ne && g_edge[i + 1] == g_edge[i]) r.open_edges++; /* a directed edge twice */
        int64_t rev = (g_edge[i] & 0xffffffff) << 32 | (g_edge[i] >> 32);
        if (!bsearch(&rev, g_edge, (size_t)ne, sizeof g_edge[0], cmp_i64)) r.open_edges++;
    }
    /* each vertex: follow its link from one triangle's far edge to the next; one cycle visits all */
    qsort(g_link, (size_t)ne, sizeof g_link[0], cmp_link);
    for (long i0 = 0, i1; i0 < ne; i0 = i1) {
        int64_t v = g_link[i0].key >> 32;
        for (i1 = i0; i1 < ne && g_link[i1].key >> 32 == v; i1++) {}
        long steps = 0, group = i1 - i0;
        int32_t first = (int32_t)(g_link[i0].key & 0xffffffff), cur = first;
        do {
            link_t want = {v << 32 | cur, 0};
            const link_t* l = bsearch(&want, g_link + i0, (size_t)group, sizeof want, cmp_link);
            if (!l) break;
            cur = l->far, steps++;
        } while (cur != first && steps <= group);
        if (steps != group || cur != first) r.bad_vertices++;
    }
    return r;
}

/* the triangles of material mat (-1: all) into the soup by the mesh's vertex numbers */
static long soup_by_number(const am_mesh* m, int mat)
{
    long n = 0;
    for (long t = 0; t < m->ntri; t++)
        if (mat < 0 || m->tmat[t] == mat) memcpy(g_soup[n++], m->tri[t], sizeof g_soup[0]);
    return n;
}

/* the same welded by position as an STL file prints it (mm, %.7g) */
static long soup_by_position(const am_mesh* m, const double* pos, int mat)
{
    long n = 0;
    char buf[32];
    for (long t = 0; t < m->ntri; t++) {
        if (mat >= 0 && m->tmat[t] != mat) continue;
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 3; j++) {
                snprintf(buf, sizeof buf, "%.7g", pos[3 * m->tri[t][k] + j] * 1000.0);
                g_corner[3 * n + k][j] = strtod(buf, NULL);
            }
        n++;
    }
    weld(n);
    return n;
}

/* 0 when the triangles of material mat (-1: all) are closed and consistently turned by vertex
 * number; else the number of bad edges */
static long open_edges(const am_mesh* m, int mat) { return check_soup(soup_by_number(m, mat)).open_edges; }

static int count_mat(const am_lattice* lat, int id)
{
    int n = 0;
    for (int c = 0; c < lat->nx * lat->ny * lat->nz; c++) n += id ? lat->cell[c] == id : lat->cell[c] != 0;
    return n;
}

/* the checks of one surface (material mat, -1: all) of g_mesh with the rest shape in g_pos: a
 * manifold by vertex number; opened (g_pos2), a manifold by position, outward, its volume voxels x
 * L^3 less a sliver at most, and not crossing itself */
static void check_surface(const char* what, int mode, int mat, int voxels)
{
    double L = g_mesh.voxel_size, L3 = L * L * L;
    manifold r = check_soup(soup_by_number(&g_mesh, mat));
    CHECK(r.open_edges == 0 && r.bad_vertices == 0, "%s mode %d material %d: by number %ld open edges, %ld bad vertices",
          what, mode, mat, r.open_edges, r.bad_vertices);
    NEAR_REL(am_mesh_volume(&g_mesh, g_pos, mat), voxels * L3, 1e-9);
    r = check_soup(soup_by_position(&g_mesh, g_pos2, mat));
    CHECK(r.open_edges == 0 && r.bad_vertices == 0, "%s mode %d material %d: by position %ld open edges, %ld bad vertices",
          what, mode, mat, r.open_edges, r.bad_vertices);
    /* opened: a sliver more or less per vertex moved (at most 0.0094 L^3 seen) */
    long moved = 0;
    for (long v = 0; v < g_mesh.nvert; v++) moved += g_mesh.vpull[v] != 0;
    double vol = am_mesh_volume(&g_mesh, g_pos2, mat);
    CHECK(fabs(vol - voxels * L3) <= 0.015 * L3 * moved + 1e-9 * voxels * L3,
          "%s mode %d material %d: opened, volume %.6g of %d voxels (%ld vertices moved)", what, mode, mat, vol / L3, voxels, moved);
    am_mesh_crossing x;
    am_mesh_crossings(&g_mesh, g_pos2, mat, &g_grid, 1L << 40, &x);
    CHECK(x.pairs == 0 && x.complete, "%s mode %d material %d: at rest %ld crossings near (%g, %g, %g) L", what, mode, mat,
          x.pairs, x.at[0] / L, x.at[1] / L, x.at[2] / L);
}

/* every check of one lattice: both modes, the body (BODY) and each material (MATERIALS) */
static void check_lattice(const am_lattice* lat, const char* what)
{
    char err[AM_ERR_MAX];
    for (int mode = 0; mode < 2; mode++) {
        am_status st = am_mesh_build(&g_mesh, lat, mode, err, sizeof err);
        CHECK(st == AM_OK, "%s: %s", what, err);
        if (st != AM_OK) return;
        am_mesh_rest(&g_mesh, g_pos);
        memcpy(g_pos2, g_pos, sizeof(double) * 3 * (size_t)g_mesh.nvert);
        am_mesh_open_pinches(&g_mesh, NULL, g_pos2);
        if (mode == AM_MESH_BODY) check_surface(what, mode, -1, count_mat(lat, 0));
        else {
            long bad = open_edges(&g_mesh, -1);
            CHECK(bad == 0, "%s mode %d: %ld edges not shared by exactly two triangles", what, mode, bad);
            for (int k = 0; k < lat->palette.count; k++)
                if (count_mat(lat, k + 1)) check_surface(what, mode, k, count_mat(lat, k + 1));
        }
    }
}

static void set_cells(am_lattice* lat, int nx, int ny, int nz, const char* cells)
{
    char err[AM_ERR_MAX];
    am_lattice_init(lat, nx, ny, nz, AM_PARAM_FROM_DOUBLE(0.01), err, sizeof err);
    for (int c = 0; c < nx * ny * nz; c++) lat->cell[c] = (uint8_t)(cells[c] == '.' ? 0 : cells[c] - '0');
}

static void test_one_voxel(void)
{
    char err[AM_ERR_MAX];
    set_cells(&g_lat, 1, 1, 1, "1");
    CHECK(am_mesh_build(&g_mesh, &g_lat, AM_MESH_BODY, err, sizeof err) == AM_OK, "%s", err);
    CHECK(g_mesh.nface == 6 && g_mesh.ncorner == 8 && g_mesh.nvert == 14 && g_mesh.ntri == 24,
          "faces %ld corners %ld vertices %ld triangles %ld", g_mesh.nface, g_mesh.ncorner, g_mesh.nvert, g_mesh.ntri);
    am_mesh_rest(&g_mesh, g_pos);
    double L = AM_PARAM_TO_DOUBLE(g_lat.voxel_size);
    NEAR_REL(am_mesh_volume(&g_mesh, g_pos, -1), L * L * L, 1e-12);
    CHECK(open_edges(&g_mesh, -1) == 0, "a cube is not closed");
    /* every corner vertex follows the one voxel */
    int masks = 1;
    for (long v = 0; v < g_mesh.ncorner; v++) masks &= g_mesh.vmask[v] != 0 && (g_mesh.vmask[v] & (g_mesh.vmask[v] - 1)) == 0;
    CHECK(masks, "a lone voxel's corners should each follow exactly one voxel");
}

static void test_shapes(void)
{
    char err[AM_ERR_MAX];
    /* two voxels of two materials side by side: one body, two closed surfaces sharing a face */
    set_cells(&g_lat, 2, 1, 1, "12");
    check_lattice(&g_lat, "two materials");
    am_mesh_build(&g_mesh, &g_lat, AM_MESH_MATERIALS, err, sizeof err);
    CHECK(g_mesh.nface == 12, "two voxels of two materials: %ld faces, want 12 (the shared face once each way)", g_mesh.nface);
    am_mesh_build(&g_mesh, &g_lat, AM_MESH_BODY, err, sizeof err);
    CHECK(g_mesh.nface == 10 && g_mesh.ncorner == 12, "two voxels: %ld faces %ld corners, want 10 and 12", g_mesh.nface,
          g_mesh.ncorner);
    /* touching along an edge only: the corners at the edge split, the edge gets two midpoints */
    set_cells(&g_lat, 2, 2, 1, "1..1");
    check_lattice(&g_lat, "edge contact");
    am_mesh_build(&g_mesh, &g_lat, AM_MESH_BODY, err, sizeof err);
    CHECK(g_mesh.ncorner == 16 && g_mesh.nvert == 16 + 2 + 12, "edge contact: %ld corner vertices, %ld vertices (want 16, 30)",
          g_mesh.ncorner, g_mesh.nvert);
    /* touching at a corner only */
    set_cells(&g_lat, 2, 2, 2, "1......1");
    check_lattice(&g_lat, "corner contact");
    am_mesh_build(&g_mesh, &g_lat, AM_MESH_BODY, err, sizeof err);
    CHECK(g_mesh.ncorner == 16, "corner contact: %ld corner vertices, want 16", g_mesh.ncorner);
    /* a pinched edge whose ends are each a single vertex (layers joined above and below): without
     * midpoints its two sides would be the same edge four times */
    set_cells(&g_lat, 2, 2, 3, "11111..11111");
    check_lattice(&g_lat, "tunnel");
    /* a ring of six around a corner (two opposite cells empty) and its complement */
    set_cells(&g_lat, 2, 2, 2, ".111111.");
    check_lattice(&g_lat, "ring of six");
    set_cells(&g_lat, 2, 2, 2, "1.2..2.1");
    check_lattice(&g_lat, "checker");
    /* an edge and a corner contact in one body; a material pinched where another fills the gap */
    set_cells(&g_lat, 3, 2, 2, "1..1.......1");
    check_lattice(&g_lat, "edge and corner");
    set_cells(&g_lat, 2, 2, 1, "12.1");
    check_lattice(&g_lat, "pinch filled by another material");
    /* a checkerboard of one material: every voxel touches its neighbours along edges only; and of
     * two materials with every other cell empty in one layer */
    char cells[5 * 5 * 5 + 1];
    for (int c = 0; c < 125; c++) cells[c] = (c % 5 + c / 5 % 5 + c / 25) % 2 ? '.' : '1';
    cells[125] = 0;
    set_cells(&g_lat, 5, 5, 5, cells);
    check_lattice(&g_lat, "checkerboard");
    for (int c = 0; c < 125; c++) cells[c] = c / 25 == 2 && (c % 5 + c / 5 % 5) % 2 ? '.' : (c % 5 + c / 5 % 5 + c / 25) % 2 ? '2' : '1';
    set_cells(&g_lat, 5, 5, 5, cells);
    check_lattice(&g_lat, "two-material checkerboard with a sparse layer");
    /* the check sees the pinch by position: not opened, the STL of an edge contact is no manifold */
    set_cells(&g_lat, 2, 2, 1, "1..1");
    am_mesh_build(&g_mesh, &g_lat, AM_MESH_BODY, err, sizeof err);
    am_mesh_rest(&g_mesh, g_pos);
    manifold r = check_soup(soup_by_position(&g_mesh, g_pos, -1));
    CHECK(r.bad_vertices > 0 || r.open_edges > 0, "an edge contact that is not opened passes the check by position");
    /* scenes */
    static const char* scenes[] = {"cube:3", "sphere:8", "chain:5", "cantilever:6"};
    for (int i = 0; i < 4; i++) {
        CHECK(am_scene_build(&g_lat, scenes[i], err, sizeof err) == AM_OK, "%s", err);
        check_lattice(&g_lat, scenes[i]);
    }
}

/* random lattices of three materials: every kind of contact occurs */
static void test_random(void)
{
    am_rng r;
    am_rng_seed(&r, 17);
    char err[AM_ERR_MAX], what[64];
    int runs = test_quick() ? 20 : 200;
    for (int k = 0; k < runs; k++) {
        int n = 2 + (int)am_rng_below(&r, 5);
        am_lattice_init(&g_lat, n, n, n, AM_PARAM_FROM_DOUBLE(0.002), err, sizeof err);
        for (int c = 0; c < n * n * n; c++) g_lat.cell[c] = (uint8_t)(am_rng_below(&r, 2) ? 1 + am_rng_below(&r, 3) : 0);
        if (!count_mat(&g_lat, 0)) g_lat.cell[0] = 1;
        snprintf(what, sizeof what, "random %d (%d^3)", k, n);
        check_lattice(&g_lat, what);
    }
    /* a full 20^3 workspace of alternating materials: the largest mesh the capacities are for */
    am_lattice_init(&g_lat, AM_MAX_DIM, AM_MAX_DIM, AM_MAX_DIM, AM_PARAM_FROM_DOUBLE(0.01), err, sizeof err);
    for (int c = 0; c < AM_MAX_CELLS; c++) {
        int x = c % AM_MAX_DIM, y = c / AM_MAX_DIM % AM_MAX_DIM, z = c / (AM_MAX_DIM * AM_MAX_DIM);
        g_lat.cell[c] = (uint8_t)(1 + (x + y + z) % 2);
    }
    CHECK(am_mesh_build(&g_mesh, &g_lat, AM_MESH_MATERIALS, err, sizeof err) == AM_OK, "checkerboard: %s", err);
    CHECK(g_mesh.nface == 6L * AM_MAX_CELLS, "checkerboard: %ld faces", g_mesh.nface);
}

/* pose of the rest lattice: centres at (x + 1/2) L, no turn */
static void rest_pose(const am_mesh* m, float* pose, double L)
{
    for (int i = 0; i < m->nv; i++) {
        int c = m->voxel_cell[i];
        pose[7 * i] = (float)((c % m->nx + 0.5) * L);
        pose[7 * i + 1] = (float)((c / m->nx % m->ny + 0.5) * L);
        pose[7 * i + 2] = (float)((c / (m->nx * m->ny) + 0.5) * L);
        pose[7 * i + 3] = 1, pose[7 * i + 4] = pose[7 * i + 5] = pose[7 * i + 6] = 0;
    }
}

static void test_place(void)
{
    char err[AM_ERR_MAX];
    CHECK(am_scene_build(&g_lat, "sphere:6", err, sizeof err) == AM_OK, "%s", err);
    for (int c = 0; c < g_lat.nx * g_lat.ny * g_lat.nz; c++)
        if (g_lat.cell[c] && c % g_lat.nx < 3) g_lat.cell[c] = 2; /* a second material: half the body */
    double L = AM_PARAM_TO_DOUBLE(g_lat.voxel_size);
    for (int mode = 0; mode < 2; mode++) {
        am_mesh_build(&g_mesh, &g_lat, mode, err, sizeof err);
        am_mesh_rest(&g_mesh, g_pos);
        rest_pose(&g_mesh, g_pose, L);
        am_mesh_place(&g_mesh, g_pose, g_pos2);
        double worst = 0;
        for (long i = 0; i < 3 * g_mesh.nvert; i++) worst = fmax(worst, fabs(g_pos[i] - g_pos2[i]));
        CHECK(worst < 1e-6 * L, "mode %d: the placed rest pose is %.3g m off the rest shape", mode, worst);
    }
    /* turned as one rigid body (30 degrees about an oblique axis) and moved: same volume */
    am_mesh_build(&g_mesh, &g_lat, AM_MESH_BODY, err, sizeof err);
    rest_pose(&g_mesh, g_pose, L);
    double ang = 0.5236, ax[3] = {0.48, 0.6, 0.64}, s = sin(ang / 2);
    double q[4] = {cos(ang / 2), s * ax[0], s * ax[1], s * ax[2]};
    for (int i = 0; i < g_mesh.nv; i++) {
        double p[3] = {g_pose[7 * i], g_pose[7 * i + 1], g_pose[7 * i + 2]}, u[3] = {q[1], q[2], q[3]};
        double t[3] = {2 * (u[1] * p[2] - u[2] * p[1]), 2 * (u[2] * p[0] - u[0] * p[2]), 2 * (u[0] * p[1] - u[1] * p[0])};
        double w[3] = {p[0] + q[0] * t[0] + (u[1] * t[2] - u[2] * t[1]), p[1] + q[0] * t[1] + (u[2] * t[0] - u[0] * t[2]),
                       p[2] + q[0] * t[2] + (u[0] * t[1] - u[1] * t[0])};
        for (int k = 0; k < 3; k++) g_pose[7 * i + k] = (float)(w[k] + 0.3);
        for (int k = 0; k < 4; k++) g_pose[7 * i + 3 + k] = (float)q[k];
    }
    am_mesh_place(&g_mesh, g_pose, g_pos);
    NEAR_REL(am_mesh_volume(&g_mesh, g_pos, -1), g_mesh.nv * L * L * L, 1e-5);
    /* deformed (each voxel moved and turned a little at random): the two materials' surfaces still
     * meet exactly, so their volumes add up to the body's */
    am_rng r;
    am_rng_seed(&r, 5);
    rest_pose(&g_mesh, g_pose, L);
    for (int i = 0; i < g_mesh.nv; i++) {
        for (int k = 0; k < 3; k++) g_pose[7 * i + k] += (float)(0.2 * L * (AM_TO_DOUBLE(am_rng_unit(&r)) - 0.5));
        double a = 0.2 * (AM_TO_DOUBLE(am_rng_unit(&r)) - 0.5);
        g_pose[7 * i + 3] = (float)cos(a), g_pose[7 * i + 6] = (float)sin(a);
    }
    am_mesh_place(&g_mesh, g_pose, g_pos);
    double body = am_mesh_volume(&g_mesh, g_pos, -1);
    CHECK(body > 0.5 * g_mesh.nv * L * L * L, "deformed body volume %.6g", body);
    am_mesh_build(&g_mesh, &g_lat, AM_MESH_MATERIALS, err, sizeof err);
    am_mesh_place(&g_mesh, g_pose, g_pos);
    double sum = am_mesh_volume(&g_mesh, g_pos, 0) + am_mesh_volume(&g_mesh, g_pos, 1);
    NEAR_REL(sum, body, 1e-9);
    CHECK(open_edges(&g_mesh, 0) == 0 && open_edges(&g_mesh, 1) == 0, "deformed: not closed");
    /* deformed and opened, a body with pinches of every kind: manifold by position, per material
     * and as one body */
    set_cells(&g_lat, 3, 3, 2, "12..21.1.2..1.2.12");
    for (int mode = 0; mode < 2; mode++) {
        am_mesh_build(&g_mesh, &g_lat, mode, err, sizeof err);
        rest_pose(&g_mesh, g_pose, L);
        am_rng_seed(&r, 9);
        for (int i = 0; i < g_mesh.nv; i++) {
            for (int k = 0; k < 3; k++) g_pose[7 * i + k] += (float)(0.05 * L * (AM_TO_DOUBLE(am_rng_unit(&r)) - 0.5));
            double a = 0.1 * (AM_TO_DOUBLE(am_rng_unit(&r)) - 0.5);
            g_pose[7 * i + 3] = (float)cos(a), g_pose[7 * i + 4] = (float)sin(a);
        }
        am_mesh_place(&g_mesh, g_pose, g_pos);
        am_mesh_open_pinches(&g_mesh, g_pose, g_pos);
        for (int mat = mode == AM_MESH_BODY ? -1 : 0; mat < (mode == AM_MESH_BODY ? 0 : 2); mat++) {
            manifold mf = check_soup(soup_by_position(&g_mesh, g_pos, mat));
            CHECK(mf.open_edges == 0 && mf.bad_vertices == 0, "deformed mode %d material %d: %ld open edges, %ld bad vertices", mode,
                  mat, mf.open_edges, mf.bad_vertices);
            CHECK(am_mesh_volume(&g_mesh, g_pos, mat) > 0, "deformed mode %d material %d: volume not positive", mode, mat);
        }
    }
}

/* voxel i of the mesh moved by (dx, dy, dz) voxel sizes */
static void move_voxel(const am_mesh* m, float* pose, int i, double dx, double dy, double dz)
{
    pose[7 * i] += (float)(dx * m->voxel_size), pose[7 * i + 1] += (float)(dy * m->voxel_size);
    pose[7 * i + 2] += (float)(dz * m->voxel_size);
}

/* the crossings of g_mesh in pose */
static am_mesh_crossing crossings_in(const float* pose, int mat, long max_visits)
{
    am_mesh_crossing x;
    am_mesh_place(&g_mesh, pose, g_pos);
    am_mesh_open_pinches(&g_mesh, pose, g_pos);
    am_mesh_crossings(&g_mesh, g_pos, mat, &g_grid, max_visits, &x);
    return x;
}

static void test_crossings(void)
{
    char err[AM_ERR_MAX];
    /* two cubes a voxel apart: pushed half into each other they cross, a tenth apart they do not */
    set_cells(&g_lat, 3, 1, 1, "1.1");
    am_mesh_build(&g_mesh, &g_lat, AM_MESH_BODY, err, sizeof err);
    double L = g_mesh.voxel_size;
    rest_pose(&g_mesh, g_pose, L);
    am_mesh_crossing x = crossings_in(g_pose, -1, 1L << 40);
    CHECK(x.pairs == 0 && x.complete, "two cubes at rest: %ld crossings", x.pairs);
    move_voxel(&g_mesh, g_pose, 1, -0.9, 0, 0);
    x = crossings_in(g_pose, -1, 1L << 40);
    CHECK(x.pairs == 0 && x.complete, "two cubes 0.1 L apart: %ld crossings", x.pairs);
    move_voxel(&g_mesh, g_pose, 1, -0.6, 0.2, 0.1);
    x = crossings_in(g_pose, -1, 1L << 40);
    CHECK(x.pairs > 0 && x.complete, "two cubes pushed half into each other: %ld crossings", x.pairs);
    CHECK(fabs(x.at[0] / L - 1) < 0.6, "the crossing is at x = %.3g L, want near L", x.at[0] / L);
    /* a U (x-z) folded: its right arm pushed over into its left one */
    set_cells(&g_lat, 3, 1, 2, "1111.1");
    for (int mode = 0; mode < 2; mode++) {
        am_mesh_build(&g_mesh, &g_lat, mode, err, sizeof err);
        rest_pose(&g_mesh, g_pose, L);
        x = crossings_in(g_pose, mode == AM_MESH_BODY ? -1 : 0, 1L << 40);
        CHECK(x.pairs == 0, "mode %d: the U at rest: %ld crossings", mode, x.pairs);
        move_voxel(&g_mesh, g_pose, 4, -1.6, 0, 0); /* the right arm's top, voxel 4 */
        x = crossings_in(g_pose, mode == AM_MESH_BODY ? -1 : 0, 1L << 40);
        CHECK(x.pairs > 0, "mode %d: the folded U: no crossing found", mode);
        /* the work is bounded: a budget too small says the search is not complete */
        x = crossings_in(g_pose, -1, 3);
        CHECK(!x.complete && x.visits == 3, "a budget of 3 visits: complete %d after %ld", x.complete, x.visits);
    }
    /* a full workspace at rest (the largest body): no crossing, and the broad phase keeps the
     * work near linear */
    am_lattice_init(&g_lat, AM_MAX_DIM, AM_MAX_DIM, AM_MAX_DIM, AM_PARAM_FROM_DOUBLE(0.01), err, sizeof err);
    for (int c = 0; c < AM_MAX_CELLS; c++) g_lat.cell[c] = (uint8_t)(1 + (c % AM_MAX_DIM < AM_MAX_DIM / 2));
    am_mesh_build(&g_mesh, &g_lat, AM_MESH_BODY, err, sizeof err);
    rest_pose(&g_mesh, g_pose, L);
    x = crossings_in(g_pose, -1, 1L << 40);
    CHECK(x.pairs == 0 && x.complete, "a full workspace: %ld crossings", x.pairs);
    CHECK(x.visits < 100 * g_mesh.ntri, "a full workspace: %ld candidate pairs for %ld triangles", x.visits, g_mesh.ntri);
    /* a non-finite position: no answer rather than a wrong one */
    g_pose[0] = NAN;
    x = crossings_in(g_pose, -1, 1L << 40);
    CHECK(!x.complete, "a NaN position gave a complete answer");
}

static void test_errors(void)
{
    char err[AM_ERR_MAX];
    set_cells(&g_lat, 2, 1, 1, "..");
    CHECK(am_mesh_build(&g_mesh, &g_lat, AM_MESH_BODY, err, sizeof err) == AM_ERR_EMPTY, "empty lattice");
    set_cells(&g_lat, 2, 1, 1, "1.");
    CHECK(am_mesh_build(&g_mesh, &g_lat, 7, err, sizeof err) == AM_ERR_ARG, "bad mode");
    CHECK(strstr(err, "mode") != NULL, "message: %s", err);
    /* a writer into a buffer too small */
    am_mesh_build(&g_mesh, &g_lat, AM_MESH_MATERIALS, err, sizeof err);
    am_mesh_rest(&g_mesh, g_pos);
    char small[200];
    am_text t = {small, sizeof small, 0, 0, NULL, NULL, 0};
    CHECK(am_mesh_write_stl(&g_mesh, g_pos, &g_lat.palette, 0, &t, err, sizeof err) == AM_ERR_CAPACITY, "small STL buffer");
    am_text t2 = {small, sizeof small, 0, 0, NULL, NULL, 0};
    CHECK(am_mesh_write_amf(&g_mesh, g_pos, &g_lat.palette, "x", &t2, err, sizeof err) == AM_ERR_CAPACITY, "small AMF buffer");
}

/* an ASCII STL text read into the soup (corners welded by their numbers) */
typedef struct stl_info {
    int solids, ends;   /* `solid` and `endsolid` lines */
    long facets, tris;  /* `facet normal` lines, and triangles of three vertices */
    double volume;      /* signed, from the file's numbers */
    char name[64];      /* the first solid's name */
} stl_info;

static stl_info stl_read(char* text)
{
    stl_info in;
    memset(&in, 0, sizeof in);
    int nv = 0;
    for (char* line = strtok(text, "\n"); line; line = strtok(NULL, "\n")) {
        while (*line == ' ') line++;
        if (!strncmp(line, "solid ", 6)) {
            if (!in.solids++) snprintf(in.name, sizeof in.name, "%s", line + 6);
        } else if (!strncmp(line, "endsolid", 8)) in.ends++;
        else if (!strncmp(line, "facet normal", 12)) in.facets++, nv = 0;
        else if (!strncmp(line, "vertex ", 7) && nv < 3 && in.tris < AM_MESH_MAX_TRIS) {
            double* v = g_corner[3 * in.tris + nv];
            sscanf(line + 7, "%lf %lf %lf", &v[0], &v[1], &v[2]);
            if (++nv == 3) {
                const double *a = g_corner[3 * in.tris], *b = a + 3, *c = a + 6;
                in.volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
                in.tris++;
            }
        }
    }
    weld(in.tris);
    return in;
}

/* the STL texts read back: one solid each, its name, its facets, its volume from its own numbers,
 * a manifold by position */
static void test_stl(void)
{
    char err[AM_ERR_MAX];
    set_cells(&g_lat, 3, 2, 2, "112.1.2221.2");
    static const char* const names[2] = {"passive", "active"};
    static const int voxels[2] = {4, 5};
    am_mesh_build(&g_mesh, &g_lat, AM_MESH_MATERIALS, err, sizeof err);
    am_mesh_rest(&g_mesh, g_pos);
    am_mesh_open_pinches(&g_mesh, NULL, g_pos);
    long total = 0;
    for (int k = 0; k < 3; k++) {
        int mat = k < 2 ? k : -1;
        if (k == 2) { /* the merged body */
            am_mesh_build(&g_mesh, &g_lat, AM_MESH_BODY, err, sizeof err);
            am_mesh_rest(&g_mesh, g_pos);
            am_mesh_open_pinches(&g_mesh, NULL, g_pos);
        }
        am_text t = {g_text, sizeof g_text, 0, 0, NULL, NULL, 0};
        CHECK(am_mesh_write_stl(&g_mesh, g_pos, &g_lat.palette, mat, &t, err, sizeof err) == AM_OK, "%s", err);
        stl_info in = stl_read(g_text);
        CHECK(in.solids == 1 && in.ends == 1, "material %d: %d solids, %d ends, want 1", mat, in.solids, in.ends);
        CHECK(!strcmp(in.name, k < 2 ? names[k] : "body"), "material %d: solid '%s'", mat, in.name);
        CHECK(in.facets == in.tris, "material %d: %ld facets, %ld triangles", mat, in.facets, in.tris);
        if (k < 2) total += in.facets;
        else CHECK(in.facets == g_mesh.ntri, "body: %ld facets, %ld triangles", in.facets, g_mesh.ntri);
        manifold r = check_soup(in.tris);
        CHECK(r.open_edges == 0 && r.bad_vertices == 0, "material %d: %ld open edges, %ld bad vertices", mat, r.open_edges,
              r.bad_vertices);
        /* mm^3: voxels of 10 mm, a sliver less where the passive voxels touch along edges */
        double want = (k < 2 ? voxels[k] : 9) * 1000.0;
        CHECK(in.volume <= want * (1 + 1e-6) && in.volume > 0.95 * want, "material %d: volume %.3f of %.0f mm^3", mat,
              in.volume, want);
    }
    am_mesh_build(&g_mesh, &g_lat, AM_MESH_MATERIALS, err, sizeof err);
    CHECK(total == g_mesh.ntri, "%ld facets in the two files, %ld triangles", total, g_mesh.ntri);
    am_text t = {g_text, sizeof g_text, 0, 0, NULL, NULL, 0};
    CHECK(am_mesh_write_stl(&g_mesh, g_pos, &g_lat.palette, g_lat.palette.count, &t, err, sizeof err) == AM_ERR_ARG,
          "a material past the palette");
}

/* the AMF text read back by the library's XML reader */
static void test_amf(void)
{
    static am_xml_doc doc;
    char err[AM_ERR_MAX], buf[64];
    set_cells(&g_lat, 3, 1, 1, "122");
    am_mesh_build(&g_mesh, &g_lat, AM_MESH_MATERIALS, err, sizeof err);
    am_mesh_rest(&g_mesh, g_pos);
    am_text t = {g_text, sizeof g_text, 0, 0, NULL, NULL, 0};
    CHECK(am_mesh_write_amf(&g_mesh, g_pos, &g_lat.palette, "a <b> & c", &t, err, sizeof err) == AM_OK, "%s", err);
    am_status st = am_xml_parse(&doc, g_text, t.len, "mesh.amf", err, sizeof err);
    CHECK(st == AM_OK, "%s", err);
    if (st != AM_OK) return;
    CHECK(am_xml_is(&doc, 0, "amf"), "root is not <amf>");
    int a = am_xml_attr_find(&doc, 0, "unit");
    CHECK(a >= 0 && am_xml_attr_text(&doc, a, buf, sizeof buf, NULL) == AM_OK && !strcmp(buf, "millimeter"), "unit '%s'", buf);
    int objects = 0, volumes = 0, materials = 0, colours = 0, vertices = 0;
    long tris[3] = {0, 0, 0};
    static double xyz[AM_XML_MAX_NODES][3];
    for (int n = 0; n < doc.nnodes; n++) {
        objects += am_xml_is(&doc, n, "object");
        if (am_xml_is(&doc, n, "material")) {
            materials++;
            int c = doc.node[n].child;
            for (; c >= 0; c = doc.node[c].next) colours += am_xml_is(&doc, c, "color");
        }
        if (am_xml_is(&doc, n, "vertex")) {
            int co = doc.node[n].child; /* <coordinates> */
            int k = 0;
            for (int c = doc.node[co].child; c >= 0 && k < 3; c = doc.node[c].next, k++) {
                am_xml_text(&doc, c, buf, sizeof buf, NULL);
                xyz[vertices][k] = atof(buf);
            }
            vertices++;
        }
        if (am_xml_is(&doc, n, "volume")) {
            volumes++;
            int id = am_xml_attr_find(&doc, n, "materialid");
            CHECK(id >= 0, "a volume without materialid");
            am_xml_attr_text(&doc, id, buf, sizeof buf, NULL);
            int mat = atoi(buf);
            CHECK(mat == 1 || mat == 2, "materialid %d", mat);
            double vol = 0;
            for (int c = doc.node[n].child; c >= 0; c = doc.node[c].next) {
                if (!am_xml_is(&doc, c, "triangle")) continue;
                tris[mat]++;
                int vi[3], k = 0;
                for (int e = doc.node[c].child; e >= 0 && k < 3; e = doc.node[e].next, k++) {
                    am_xml_text(&doc, e, buf, sizeof buf, NULL);
                    vi[k] = atoi(buf);
                }
                const double *p = xyz[vi[0]], *q = xyz[vi[1]], *r = xyz[vi[2]];
                vol += (p[0] * (q[1] * r[2] - q[2] * r[1]) + p[1] * (q[2] * r[0] - q[0] * r[2]) + p[2] * (q[0] * r[1] - q[1] * r[0])) / 6;
            }
            NEAR_REL(vol, (mat == 1 ? 1 : 2) * 1000.0, 1e-6);
        }
    }
    CHECK(objects == 1 && volumes == 2 && materials == 2 && colours == 2, "objects %d volumes %d materials %d colours %d",
          objects, volumes, materials, colours);
    CHECK(vertices == g_mesh.nvert, "%d vertices, the mesh has %ld", vertices, g_mesh.nvert);
    CHECK(tris[1] + tris[2] == g_mesh.ntri && tris[1] == 24, "triangles %ld + %ld", tris[1], tris[2]);
    CHECK(strstr(g_text, "<metadata type=\"name\">a &lt;b&gt; &amp; c</metadata>") != NULL, "the title is not escaped");
}

/* test_io_mesh --stl-check FILE: the file's solids, facets, volume and manifold check on one line */
static int stl_check(const char* path)
{
    FILE* f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "test_io_mesh: cannot open %s\n", path);
        return 2;
    }
    size_t n = fread(g_text, 1, sizeof g_text - 1, f);
    int big = !feof(f);
    fclose(f);
    if (big) {
        fprintf(stderr, "test_io_mesh: %s is larger than %ld bytes\n", path, (long)sizeof g_text - 1);
        return 2;
    }
    g_text[n] = 0;
    stl_info in = stl_read(g_text);
    manifold r = check_soup(in.tris);
    printf("solids %d facets %ld volume %.3f open_edges %ld bad_vertices %ld\n", in.solids, in.facets, in.volume, r.open_edges,
           r.bad_vertices);
    return 0;
}

int main(int argc, char** argv)
{
    if (argc == 3 && !strcmp(argv[1], "--stl-check")) return stl_check(argv[2]);
    TEST_INIT(argc, argv);
    RUN(test_one_voxel);
    RUN(test_shapes);
    RUN(test_random);
    RUN(test_place);
    RUN(test_crossings);
    RUN(test_errors);
    RUN(test_stl);
    RUN(test_amf);
    return SUMMARY();
}
