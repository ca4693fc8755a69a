/* amorph/lattice.h: materials and the lattice of material ids a robot is made of.
 *
 * A lattice is nx x ny x nz cells of edge voxel_size metres. Cell (x, y, z) is stored at
 * index x + nx * (y + ny * z); value 0 is empty, value k in 1..palette.count is material
 * palette.mat[k - 1]. z is up; the floor is the plane z = 0.
 */
#ifndef AMORPH_LATTICE_H
#define AMORPH_LATTICE_H

#include <stdint.h>
#include "amorph/config.h"
#include "amorph/real.h"
#include "amorph/status.h"
#include "amorph/text.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct am_material {
    char name[AM_NAME_MAX];  /* identifier: letters, digits, '_' and '-' */
    am_param E;               /* Young's modulus, Pa (> 0) */
    am_param density;         /* kg/m^3 (> 0) */
    am_param poisson;         /* Poisson ratio, [0, 0.5) */
    am_param cte;             /* thermal expansion per degree; volumetric or linear (see am_env) */
    am_param phase;           /* actuation phase, radians (added to the global temperature phase) */
    am_param mu_static;       /* static floor friction coefficient (>= 0) */
    am_param mu_kinetic;      /* kinetic floor friction coefficient (>= 0) */
    am_param zeta_internal;   /* internal (bond) damping ratio, fraction of critical */
    am_param zeta_global;     /* global (ground-referenced) damping ratio */
    am_param zeta_collision;  /* floor / self-collision damping ratio */
    uint8_t color[4];        /* display colour, RGBA */
    int fixed;               /* 1: voxels of this material are clamped in place */
} am_material;

typedef struct am_palette {
    int count;                              /* materials in use, 1..AM_MAX_MATERIALS */
    am_material mat[AM_MAX_MATERIALS];      /* mat[k - 1] is cell value k */
} am_palette;

/* the cell edges amorph simulates, m: one range wherever a size comes from (a lattice or VXA file,
 * the configuration's voxel_size, a model built from any of them); outside it the model's scales
 * lose their meaning (a subnormal edge makes masses and stiffnesses 0 or infinite) */
#define AM_VOXEL_SIZE_MIN 1e-5
#define AM_VOXEL_SIZE_MAX 10.0

typedef struct am_lattice {
    int nx, ny, nz;             /* cells along x, y, z; each 1..AM_MAX_DIM */
    am_param voxel_size;        /* cell edge, m */
    am_palette palette;
    uint8_t cell[AM_MAX_CELLS]; /* (nx*ny*nz) material ids, 0 = empty */
} am_lattice;

/* the default material (E 1 MPa, 1000 kg/m^3, passive, mu_s 1.0 / mu_k 0.3, zeta 1.0/0.01/0.8) */
am_material am_default_material(void);
/* the built-in palette of 9 materials: passive, active, active90 (90 degrees behind), stiff,
 * soft, heavy, light, active180, fixed. Active CTE is 0.01 (volumetric, as the seed). */
am_palette am_default_palette(void);
/* the same palette written into *out (no copy of the large struct on the stack) */
void am_default_palette_into(am_palette* out);
/* index (0-based) of the material named name in p, or -1 */
int am_palette_find(const am_palette* p, const char* name);

/* an empty lattice of the given size with the default palette; AM_ERR_CAPACITY past AM_MAX_DIM */
am_status am_lattice_init(am_lattice* lat, int nx, int ny, int nz, am_param voxel_size, char* err, int errsz);
static inline int am_lattice_index(const am_lattice* lat, int x, int y, int z) { return x + lat->nx * (y + lat->ny * z); }
int am_lattice_count(const am_lattice* lat);         /* filled cells */
/* 1 when a and b are the same robot: shape, voxel size and every material value bit for bit,
 * names up to their NUL, and the cells of the nx x ny x nz box */
int am_lattice_equal(const am_lattice* a, const am_lattice* b);

/* built-in scenes shared by tests, benchmarks and the command:
 *   cube:N        a solid N^3 cube of passive material
 *   sphere:D      cells whose centre is within D/2 of the centre of a D^3 lattice; the half with
 *                 x < D/2 is "active", the rest "passive" (sphere:20 has 4224 voxels)
 *   cantilever:N  an N x 1 x 1 beam of passive material whose x = 0 cell is "fixed", lifted
 *                 clear of the floor (the lattice is N x 1 x 3 with the beam in the top layer)
 *   chain:N       an N x 1 x 1 row of passive voxels */
am_status am_scene_build(am_lattice* lat, const char* name, char* err, int errsz);

/* the lattice text format (docs/formats.md). Parse from a NUL-terminated buffer; fname is used
 * only in messages ("fname:line: problem"). */
am_status am_lattice_parse(am_lattice* lat, const char* text, const char* fname, char* err, int errsz);
/* a lattice read line by line, for text that is not held whole (a file streamed through a small
 * buffer): begin, one call per line, end. am_lattice_parse is these calls over a whole text and
 * gives the same lattice and messages. */
typedef struct am_lattice_reader {
    am_lattice* lat;            /* the lattice being filled (partial after an error) */
    const char* fname;          /* for messages; must stay valid while reading */
    int line, last;             /* lines read; the last one */
    int have_header, have_size, have_voxel;
    int z, y;                   /* the layer being read (-1 before the first) and its rows so far */
    am_status st;               /* the first failure: every later call returns it */
} am_lattice_reader;
void am_lattice_read_begin(am_lattice_reader* r, am_lattice* lat, const char* fname);
/* one line of n characters without its newline (text[n] is '\n' or NUL) */
am_status am_lattice_read_line(am_lattice_reader* r, const char* text, long n, char* err, int errsz);
/* after the last line: AM_OK when the lattice is complete */
am_status am_lattice_read_end(am_lattice_reader* r, char* err, int errsz);
/* write lat in the lattice text format into buf (capacity cap, NUL-terminated); *len gets the
 * length. AM_ERR_CAPACITY if it does not fit. */
am_status am_lattice_format(const am_lattice* lat, char* buf, long cap, long* len, char* err, int errsz);
/* the same text written to out, a whole-text buffer or a stream (amorph/text.h); AM_ERR_CAPACITY
 * or AM_ERR_IO when out dropped text */
am_status am_lattice_write(const am_lattice* lat, am_text* out, char* err, int errsz);
/* the largest text am_lattice_format can produce for any lattice of this profile */
#define AM_LATTICE_TEXT_MAX (AM_MAX_MATERIALS * 400L + AM_MAX_CELLS * 3L + 8192L)

#ifdef __cplusplus
}
#endif
#endif
