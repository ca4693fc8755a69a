/* amorph/mesh.h: the surface of a voxel body as a triangle mesh whose vertices follow the voxels
 * around them, and the STL and AMF writers of printable robots (docs/pictures.md, Surface;
 * docs/formats.md, STL and AMF).
 *
 * The mesh is built once per lattice (its topology) and placed once per pose (its positions):
 *   - am_mesh_build makes the faces of the lattice's cells that lie on a surface, each a quad cut
 *     into four triangles around its centre, counter-clockwise seen from outside. A vertex sits on
 *     a lattice corner and follows the voxels that share the corner: placed, it is the mean of
 *     their corner points p + R (+-hx, +-hy, +-hz). Faces that meet at a corner share its vertex,
 *     so the surface has no gap or overlap however the voxels bend and turn.
 *   - AM_MESH_BODY: the outer surface of the whole body (faces between a voxel and empty space),
 *     each triangle in the colour of its voxel's material: what render and view draw.
 *     AM_MESH_MATERIALS: one closed surface per material (faces between a voxel of the material
 *     and anything else), what a multi-material printer needs: a face between two materials is in
 *     both surfaces, once each way round.
 *   - Every surface is closed and every edge is shared by exactly two of its triangles: where two
 *     voxels of one surface touch only along an edge or at a corner, the corner's vertex is split
 *     (one per fan of faces around it) and such an edge gets a midpoint per side, so no edge is
 *     ever shared by four triangles. Diagonal neighbours are not linked in the simulator either.
 *     The split vertices still sit at one point; am_mesh_open_pinches moves each a little towards
 *     its own voxels, so that a file that names vertices by their position (STL) is manifold too.
 *
 * Nothing allocates: the caller owns the am_mesh (a large struct, declare it static) and the
 * arrays of positions. Capacities follow AM_MAX_DIM (config.h); the build never runs out of room
 * for a lattice of this profile, and says so with AM_ERR_CAPACITY if it ever would. */
#ifndef AMORPH_MESH_H
#define AMORPH_MESH_H

#include <stdint.h>

#include "amorph/config.h"
#include "amorph/lattice.h"
#include "amorph/status.h"
#include "amorph/text.h"

#ifdef __cplusplus
extern "C" {
#endif

/* faces of one build: every cell face position of the workspace, once per side */
#define AM_MESH_MAX_FACES (2L * 3L * AM_MAX_DIM * AM_MAX_DIM * (AM_MAX_DIM + 1))
/* vertices: at most 4 corners, 2 midpoints and a centre per face */
#define AM_MESH_MAX_VERTS (7L * AM_MESH_MAX_FACES)
/* triangles: 4 per face and 2 per pair of midpoints */
#define AM_MESH_MAX_TRIS (8L * AM_MESH_MAX_FACES)
/* am_mesh_open_pinches: the share of the way from a pinch to the centre of its voxels a split
 * vertex moves (0.025: two voxels touching at a corner end 0.043 voxel sizes apart there) */
#define AM_MESH_PINCH_PULL 0.025

enum { AM_MESH_BODY = 0, AM_MESH_MATERIALS = 1 };

typedef struct am_mesh {
    int mode;                 /* AM_MESH_BODY or AM_MESH_MATERIALS */
    int nx, ny, nz;           /* the lattice's size; corner (x, y, z) has index x + (nx+1) (y + (ny+1) z) */
    int nv;                   /* voxels (filled cells; voxel k is the k-th in cell order, as am_model numbers them) */
    long nface, nvert, ntri;  /* faces, vertices, triangles */
    long ncorner;             /* vertices 0 .. ncorner-1 sit on corners, the rest are means of others */
    double voxel_size;        /* the lattice's cell edge, m */
    int32_t cell_voxel[AM_MAX_CELLS];      /* voxel of each cell, -1 if empty */
    int32_t voxel_cell[AM_MAX_VOXELS];     /* cell of each voxel */
    /* per vertex (nvert) */
    int32_t vcorner[AM_MESH_MAX_VERTS];    /* the lattice corner of a corner vertex, -1 for the others */
    uint8_t vmask[AM_MESH_MAX_VERTS];      /* the cells around its corner it follows: bit bx + 2 by + 4 bz
                                            * is the cell (x - 1 + bx, y - 1 + by, z - 1 + bz) */
    int32_t vfrom[AM_MESH_MAX_VERTS][4];   /* a vertex that is no corner: the mean of these four earlier
                                            * vertices (a midpoint lists its two ends twice) */
    uint8_t vpull[AM_MESH_MAX_VERTS];      /* a vertex where its surface pinches (one of two or more
                                            * vertices of one surface at a corner, a midpoint): the
                                            * cells around its corner (a midpoint: around the corner of
                                            * vfrom[0]; bits as vmask) whose voxels own its faces there,
                                            * which am_mesh_open_pinches moves it towards; else 0 */
    /* per triangle (ntri) */
    int32_t tri[AM_MESH_MAX_TRIS][3];      /* vertices, counter-clockwise seen from outside */
    uint8_t tmat[AM_MESH_MAX_TRIS];        /* palette index (0-based) of the material inside it */
    /* the build's scratch */
    int32_t face_cell[AM_MESH_MAX_FACES];  /* the cell inside the face */
    uint8_t face_dir[AM_MESH_MAX_FACES];   /* its outward direction 0..5: +x, -x, +y, -y, +z, -z */
    int32_t face_of[6 * AM_MAX_CELLS];     /* face of (cell, direction), -1 if none */
    int32_t slot[4 * AM_MESH_MAX_FACES];   /* per face corner: union-find parent, then its vertex */
    int32_t mid[4 * AM_MESH_MAX_FACES];    /* per face edge (corner k to k+1): its midpoint vertex or -1 */
    int32_t corner_head[(AM_MAX_DIM + 1) * (AM_MAX_DIM + 1) * (AM_MAX_DIM + 1)]; /* a corner's first vertex */
} am_mesh;

/* the surface of lat (mode AM_MESH_BODY or AM_MESH_MATERIALS) into *mesh. AM_ERR_EMPTY for a
 * lattice without voxels, AM_ERR_ARG for a bad mode, AM_ERR_CAPACITY if a capacity would be passed. */
am_status am_mesh_build(am_mesh* mesh, const am_lattice* lat, int mode, char* err, int errsz);

/* the rest shape: vertex positions (nvert x 3, m) with the corner (x, y, z) at (x L, y L, z L),
 * L the lattice's voxel size, so the body sits in the box [0, nx L] x [0, ny L] x [0, nz L] */
void am_mesh_rest(const am_mesh* mesh, double* pos);

/* half-extents of voxel i along its own axes in a pose (pose: nv x 7 floats, x, y, z in m then the
 * unit quaternion qw, qx, qy, qz, as am_record writes them): half the mean distance to its lattice
 * neighbours on each axis, so thermal expansion shows; an axis without neighbours takes the mean of
 * the others, a lone voxel half the voxel size; never more than the voxel size */
void am_mesh_half(const am_mesh* mesh, const float* pose, int i, double half[3]);

/* vertex positions (nvert x 3, m) for a pose of the body (as am_mesh_half): each corner vertex is
 * the mean of p + R (+-hx, +-hy, +-hz) over the voxels it follows, the others the means they are */
void am_mesh_place(const am_mesh* mesh, const float* pose, double* pos);

/* moves the vertices where a surface pinches (vpull) AM_MESH_PINCH_PULL of the way towards the
 * centre of the voxels they pull to (pose as am_mesh_half, or NULL for the rest shape), and places
 * the vertices that are means of others again. After am_mesh_rest or am_mesh_place: the two sides
 * of a pinch no longer meet, so the surface is manifold by position as well as by vertex number
 * (each surface stays closed; its volume shrinks by a sliver at each pinch). */
void am_mesh_open_pinches(const am_mesh* mesh, const float* pose, double* pos);

/* signed volume enclosed by the triangles of material mat (-1: all), m^3 (positive when every
 * triangle turns counter-clockwise seen from outside) */
double am_mesh_volume(const am_mesh* mesh, const double* pos, int mat);

/* 1 when the mesh holds a triangle of material mat (palette index) */
int am_mesh_holds(const am_mesh* mesh, int mat);

/* Self-intersection: pairs of triangles (of material mat, -1: all) that share no vertex and cross,
 * each pair once. A crossing is an overlap of positive length (coplanar triangles: of positive
 * area) beyond a tolerance of 1e-6 voxel sizes, so triangles that only touch are not counted.
 * Broad phase: a uniform grid of cells no smaller than the largest triangle, at most
 * AM_MESH_GRID_DIM a side, each triangle filed under the cell of its box's low corner; a triangle
 * is compared with those filed in the 3 x 3 x 3 cells that can hold an overlapping box. */
#define AM_MESH_GRID_DIM (3 * AM_MAX_DIM + 4)
typedef struct am_mesh_grid {
    int32_t start[AM_MESH_GRID_DIM * AM_MESH_GRID_DIM * AM_MESH_GRID_DIM + 1]; /* first entry of each cell in order */
    int32_t order[AM_MESH_MAX_TRIS];                                         /* triangles, cell by cell */
} am_mesh_grid;
typedef struct am_mesh_crossing {
    long pairs;     /* crossing pairs found */
    long visits;    /* candidate pairs looked at (the work done) */
    int complete;   /* 1 when every candidate pair was looked at; 0 when max_visits stopped the search
                     * or a position was not finite */
    double at[3];   /* the first crossing found: the mean of the two triangles' centres, m */
} am_mesh_crossing;
/* the crossings of the surface in pos, with grid (the caller's scratch, a large struct) and at
 * most max_visits candidate pairs looked at */
void am_mesh_crossings(const am_mesh* mesh, const double* pos, int mat, am_mesh_grid* grid, long max_visits,
                       am_mesh_crossing* out);

/* The printable files (docs/formats.md), in millimetres (positions in m times 1000):
 * ASCII STL: one `solid NAME ... endsolid NAME`: the triangles of material mat (NAME the
 * material's), or with mat -1 every triangle of the mesh (NAME `body`: the AM_MESH_BODY surface).
 * One solid a file, as slicers and ADMesh read them.
 * AMF (ISO/ASTM 52915): <amf unit="millimeter">, a <material id="K"> with its name and <color>
 * per material held (K = palette index + 1; 0 means no material in AMF), one <object> whose
 * <mesh> holds every vertex and one <volume materialid="K"> per material held, materials in
 * palette order.
 * title (may be NULL): the AMF's <metadata type="name">. AM_ERR_CAPACITY or AM_ERR_IO when out
 * dropped text. */
am_status am_mesh_write_stl(const am_mesh* mesh, const double* pos, const am_palette* pal, int mat, am_text* out,
                            char* err, int errsz);
am_status am_mesh_write_amf(const am_mesh* mesh, const double* pos, const am_palette* pal, const char* title,
                            am_text* out, char* err, int errsz);

#ifdef __cplusplus
}
#endif
#endif
