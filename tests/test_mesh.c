/* tests/test_mesh.c: the surface mesh (src/mesh.c) and its STL and AMF files (src/format_mesh.c):
 * closed surfaces (every edge shared by exactly two triangles, once each way round, per material),
 * outward normals (positive signed volume), volume = voxels x L^3 at rest, surfaces of two
 * materials that meet exactly, a placed rest pose equal to the rest shape, and the written files
 * read back. */
#include "amorph.h"
#include "amorph/mesh.h"
#include "harness.h"

static am_mesh g_mesh;
static am_lattice g_lat;
static double g_pos[3 * AM_MESH_MAX_VERTS], g_pos2[3 * AM_MESH_MAX_VERTS];
static float g_pose[7 * AM_MAX_VOXELS];
static int64_t g_edge[3 * AM_MESH_MAX_TRIS];
static char g_text[16L << 20];

static int cmp_i64(const void* a, const void* b)
{
    int64_t x = *(const int64_t*)a, y = *(const int64_t*)b;
    return x < y ? -1 : x > y;
}

/* 0 when every directed edge of the triangles of material mat (-1: all) appears exactly once and
 * its reverse exactly once; else the number of bad edges */
static long open_edges(const am_mesh* m, int mat)
{
    long n = 0, bad = 0;
    for (long t = 0; t < m->ntri; t++) {
        if (mat >= 0 && m->tmat[t] != mat) continue;
        for (int k = 0; k < 3; k++) g_edge[n++] = (int64_t)m->tri[t][k] << 32 | m->tri[t][(k + 1) % 3];
    }
    qsort(g_edge, (size_t)n, sizeof g_edge[0], cmp_i64);
    for (long i = 0; i < n; i++) {
        if (i + 1 < n && g_edge[i + 1] == g_edge[i]) bad++; /* a directed edge twice */
        int64_t rev = (g_edge[i] & 0xffffffff) << 32 | (g_edge[i] >> 32);
        if (!bsearch(&rev, g_edge, (size_t)n, sizeof g_edge[0], cmp_i64)) bad++;
    }
    return bad;
}

static int count_mat(const am_lattice* lat, int id)
{
    int n = 0;
    for (int c = 0; c < lat->nx * lat->ny * lat->nz; c++) n += id ? lat->cell[c] == id : lat->cell[c] != 0;
    return n;
}

/* every check of one lattice: both modes, closed per material, volumes at rest */
static void check_lattice(const am_lattice* lat, const char* what)
{
    char err[AM_ERR_MAX];
    double L = AM_PARAM_TO_DOUBLE(lat->voxel_size), L3 = L * L * L;
    for (int mode = 0; mode < 2; mode++) {
        am_status st = am_mesh_build(&g_mesh, lat, mode, err, sizeof err);
        CHECK(st == AM_OK, "%s: %s", what, err);
        if (st != AM_OK) return;
        am_mesh_rest(&g_mesh, g_pos);
        long bad = open_edges(&g_mesh, -1);
        CHECK(bad == 0, "%s mode %d: %ld edges not shared by exactly two triangles", what, mode, bad);
        NEAR_REL(am_mesh_volume(&g_mesh, g_pos, -1), count_mat(lat, 0) * L3, 1e-9);
        if (mode == AM_MESH_MATERIALS)
            for (int k = 0; k < lat->palette.count; k++) {
                int n = count_mat(lat, k + 1);
                if (!n) continue;
                bad = open_edges(&g_mesh, k);
                CHECK(bad == 0, "%s material %d: %ld edges not shared by exactly two triangles", what, k, bad);
                NEAR_REL(am_mesh_volume(&g_mesh, g_pos, k), n * L3, 1e-9);
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
    CHECK(am_mesh_write_stl(&g_mesh, g_pos, &g_lat.palette, &t, err, sizeof err) == AM_ERR_CAPACITY, "small STL buffer");
    am_text t2 = {small, sizeof small, 0, 0, NULL, NULL, 0};
    CHECK(am_mesh_write_amf(&g_mesh, g_pos, &g_lat.palette, "x", &t2, err, sizeof err) == AM_ERR_CAPACITY, "small AMF buffer");
}

/* the STL text read back: solids, facets, and the volume of each solid from its own numbers */
static void test_stl(void)
{
    char err[AM_ERR_MAX];
    set_cells(&g_lat, 3, 2, 2, "112.1.2221.2");
    am_mesh_build(&g_mesh, &g_lat, AM_MESH_MATERIALS, err, sizeof err);
    am_mesh_rest(&g_mesh, g_pos);
    am_text t = {g_text, sizeof g_text, 0, 0, NULL, NULL, 0};
    CHECK(am_mesh_write_stl(&g_mesh, g_pos, &g_lat.palette, &t, err, sizeof err) == AM_OK, "%s", err);
    int solids = 0, ends = 0;
    long facets = 0;
    double vol[2] = {0, 0}, v[3][3];
    char name[2][32];
    int cur = -1, nv = 0;
    for (char* line = strtok(g_text, "\n"); line; line = strtok(NULL, "\n")) {
        while (*line == ' ') line++;
        if (!strncmp(line, "solid ", 6)) {
            cur = solids++;
            if (cur < 2) snprintf(name[cur], sizeof name[cur], "%s", line + 6);
        } else if (!strncmp(line, "endsolid ", 9)) ends++;
        else if (!strncmp(line, "facet normal", 12)) facets++, nv = 0;
        else if (!strncmp(line, "vertex ", 7) && cur >= 0 && cur < 2 && nv < 3) {
            sscanf(line + 7, "%lf %lf %lf", &v[nv][0], &v[nv][1], &v[nv][2]);
            if (++nv == 3)
                vol[cur] += (v[0][0] * (v[1][1] * v[2][2] - v[1][2] * v[2][1]) + v[0][1] * (v[1][2] * v[2][0] - v[1][0] * v[2][2]) +
                             v[0][2] * (v[1][0] * v[2][1] - v[1][1] * v[2][0])) / 6;
        }
    }
    CHECK(solids == 2 && ends == 2, "%d solids, %d ends, want 2", solids, ends);
    CHECK(facets == g_mesh.ntri, "%ld facets, %ld triangles", facets, g_mesh.ntri);
    CHECK(!strcmp(name[0], "passive") && !strcmp(name[1], "active"), "solids '%s', '%s'", name[0], name[1]);
    NEAR_REL(vol[0], 4 * 1000.0, 1e-6); /* mm^3: four passive voxels of 10 mm */
    NEAR_REL(vol[1], 5 * 1000.0, 1e-6);
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

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    RUN(test_one_voxel);
    RUN(test_shapes);
    RUN(test_random);
    RUN(test_place);
    RUN(test_errors);
    RUN(test_stl);
    RUN(test_amf);
    return SUMMARY();
}
