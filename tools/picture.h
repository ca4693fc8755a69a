/* tools/picture.h: what amorph render, view and plot share (tools/picture.c; docs/pictures.md). */
#ifndef AMORPH_TOOLS_PICTURE_H
#define AMORPH_TOOLS_PICTURE_H

#include "robot.h"

/* the recording budget: poses of up to 128 frames of the largest body (more frames of smaller ones) */
#define TOOL_REC_FLOATS (AM_MAX_VOXELS * 7L * 128L)
#define TOOL_REC_MAX_FRAMES 1024

/* what a voxel is coloured by (render --colour, the viewer's menu; docs/pictures.md, Colours):
 * its material, or a scalar recorded per voxel and frame */
enum { TOOL_COL_MATERIAL = 0, TOOL_COL_STRAIN, TOOL_COL_STRESS, TOOL_COL_SPEED, TOOL_COL_PHASE, TOOL_COL_COUNT };
/* scalars per voxel and frame: strain, stress, speed, phase (TOOL_COL_STRAIN + k) */
#define TOOL_REC_SCALARS 4

/* one recorded evaluation; the arrays are static storage of tools/picture.c (one at a time) */
typedef struct tool_motion {
    const am_model* model;   /* the model simulated (palette, voxel materials, cells, neighbours) */
    am_result res;           /* the evaluation's result */
    int nv;                  /* voxels */
    int frames;              /* usable frames (a diverged run keeps those before the first bad one) */
    int settled_frame;       /* last frame of the relaxation */
    double dt;               /* s per step */
    const float* pose;       /* (frames x nv x 7) x, y, z (m), qw, qx, qy, qz */
    const long* step;        /* (frames) step of each frame */
    const float* scalar;     /* (frames x nv x 4) per voxel: strain (1), stress (Pa), speed (m/s), phase
                              * (the actuation's expansion s - 1, 1): tool_colour_value */
    const uint8_t* fixed;    /* (nv) 1: the voxel is clamped */
    const float* force;      /* (nv x 3) the constant external force on the voxel, N */
    int nfixed, nforced;     /* clamped voxels, voxels with a non-zero force */
} tool_motion;

/* voxel i's scalars in state s, in SI, as render and view colour them and sim --trajectory --scalars
 * writes them: out[0] strain (1; the mean over its links of |e| + |theta| / 2), out[1] stress (Pa;
 * each link's strain times its modulus, the mean), out[2] speed (m/s), out[3] phase (the actuation's
 * expansion s - 1) */
void tool_voxel_scalars(const am_model* m, const am_state* s, int i, double out[TOOL_REC_SCALARS]);

/* the colouring's name ("material", "strain", "stress", "speed", "phase"), and the mode of a name
 * (-1 when none) */
const char* tool_colour_name(int mode);
int tool_colour_parse(const char* name);
/* the scalar of a mode for voxel i in frame f, in SI (strain and phase as fractions) */
double tool_colour_value(const tool_motion* mo, int mode, int f, int i);
/* the legend's range of a mode over the recording, in SI, ends on round numbers of the shown unit:
 * 0 .. the largest value for strain, stress and speed, -m .. m (m the largest |value|) for phase */
void tool_colour_range(const tool_motion* mo, int mode, double* lo, double* hi);
/* the shown unit of a mode: its name and how many of it make one SI unit ("%" and 100 for strain
 * and phase, "kPa" and 0.001 for stress, "mm/s" and 1000 for speed) */
const char* tool_colour_unit(int mode, double* per_si);
/* the colour of a value at u = (v - lo) / (hi - lo) clamped to 0..1: a sequential scale (dark blue,
 * blue, green, yellow) for strain, stress and speed, a diverging one (blue, white, red) for phase */
void tool_colour_ramp(int mode, double u, uint8_t rgb[3]);
/* the colour clamped voxels are drawn in, and force arrows */
extern const uint8_t tool_col_clamp[3], tool_col_force[3];

/* evaluates the robot with recording, about `want` frames over the longest possible run (fewer
 * for a big body); returns 0, or an exit status after a one-line message naming `what` */
int tool_record_motion(tool_ctx* c, const am_robot* r, int want, tool_motion* mo, const char* what);
/* mass-weighted centre of frame `frame`, m */
void tool_motion_com(const tool_motion* mo, int frame, double com[3]);

/* the surface mesh render, view and export share (amorph/io.h), static storage of tools/picture.c
 * (one at a time), and room for its vertex positions (3 per vertex, m) */
am_mesh* tool_mesh(void);
double* tool_mesh_pos(void);
/* the voxel under each triangle of tool_mesh() (ntri), found again after each am_mesh_build: a
 * face's triangles share its centre, their first vertex, and the face's cell is its voxel's */
const int32_t* tool_mesh_tri_voxel(void);

/* the robot of render and view (tools/robot.h) into c->work[0].lattice, with its environment and
 * evaluation; 0 or an exit status after a message naming cmd */
int tool_load_subject(tool_ctx* c, const tool_robot_args* a, am_robot* r, const char* cmd);
/* --out FILE present and not a folder name; 0 or 2 after a message */
int tool_check_output(const char* path, const char* cmd, const char* ext);

/* the plots (tools/plot.c; amorph plot, and the end of evolve and experiment by tool_write_plot):
 * the best fitness against evaluations of up to PLOT_MAX_RUNS folders (the runs of a folder of runs
 * that have logged fewer than min_evals evaluations left out; each run's rows beyond max_evals left
 * out, 0: none), or one robot's travel against time; title its heading, written atomically at path.
 * 0 or an exit status after a message */
#define PLOT_MAX_RUNS 128
int tool_plot_runs(int ndirs, char** dirs, long min_evals, long max_evals, const char* title, const char* path);
int tool_plot_travel(tool_ctx* c, const tool_robot_args* ra, const char* title, const char* path);

/* the filmstrip (tools/film.c; amorph render, and a run's end by tool_write_filmstrip) */
#define FILM_MAX_W 4096
#define FILM_MAX_H 4096
#define FILM_MAX_PIXELS (4096L * 1024L)
#define FILM_MAX_PANELS 16
typedef struct film_opts {
    int panels;         /* pictures side by side, >= 3 */
    int width, height;  /* pixels of the whole strip */
    int boxes;          /* 1: each voxel a box; 0: the continuous surface (tool_mesh, built for the body either way) */
    int colour;         /* TOOL_COL_*: what a voxel's colour shows */
    int keep_same;      /* 1: a PNG already at the path with these very pixels is left as it is */
} film_opts;
/* 6 panels, 1600 x 400, the continuous surface, coloured by material */
film_opts film_defaults(void);
/* records r, draws and writes the filmstrip at path (what names the robot in messages); 0, or an
 * exit status after one line on stderr */
int film_write(tool_ctx* c, const am_robot* r, const film_opts* o, const char* what, const char* path);

/* the viewer page (tools/viewer.c; amorph view, and a run's end by tool_write_viewer): r recorded
 * over `frames` frames, the page titled title written at path (what names the robot in messages);
 * 0, or an exit status after one line on stderr */
int view_write(tool_ctx* c, const am_robot* r, int frames, const char* title, const char* what, const char* path);

#endif
