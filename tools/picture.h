/* tools/picture.h: what amorph render, view and plot share (tools/picture.c; docs/pictures.md). */
#ifndef AMORPH_TOOLS_PICTURE_H
#define AMORPH_TOOLS_PICTURE_H

#include "robot.h"

/* the recording budget: poses of up to 128 frames of the largest body (more frames of smaller ones) */
#define TOOL_REC_FLOATS (AM_MAX_VOXELS * 7L * 128L)
#define TOOL_REC_MAX_FRAMES 1024

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
} tool_motion;

/* evaluates the robot with recording, about `want` frames over the longest possible run (fewer
 * for a big body); returns 0, or an exit status after a one-line message naming `what` */
int tool_record_motion(tool_ctx* c, const am_lattice* lat, const am_env* env, const am_eval_def* eval, int want, tool_motion* mo,
                       const char* what);
/* mass-weighted centre of frame `frame`, m */
void tool_motion_com(const tool_motion* mo, int frame, double com[3]);

/* the surface mesh render, view and export share (amorph/mesh.h), static storage of tools/picture.c
 * (one at a time), and room for its vertex positions (3 per vertex, m) */
am_mesh* tool_mesh(void);
double* tool_mesh_pos(void);

/* the robot of render and view (tools/robot.h) into c->work[0].lattice, with its environment and
 * evaluation; 0 or an exit status after a message naming cmd */
int tool_load_subject(tool_ctx* c, const tool_robot_args* a, tool_robot* r, const char* cmd);
/* --out FILE present and not a folder name; 0 or 2 after a message */
int tool_check_output(const char* path, const char* cmd, const char* ext);

#endif
