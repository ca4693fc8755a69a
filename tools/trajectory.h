/* tools/trajectory.h: a simulation's trajectory streamed to a file (amorph sim --trajectory;
 * docs/formats.md, Trajectory). Every `every` steps, and at the last step of the relaxation and of
 * the evaluation, one row: the step, the time, the segment, the centre of mass and every voxel's
 * position and orientation (and with `scalars` its strain, stress, speed and phase), as CSV or as
 * JSON lines. The rows go through the small buffer of a
 * tool_out into the port's atomic replace, so a run of any length needs no more memory. */
#ifndef AMORPH_TOOLS_TRAJECTORY_H
#define AMORPH_TOOLS_TRAJECTORY_H

#include "cmd.h"

enum { TOOL_TRAJ_CSV = 0, TOOL_TRAJ_JSONL = 1 };

typedef struct tool_traj {
    tool_out out;              /* the file (one tool_out is open at a time: close before printing) */
    int format;                /* TOOL_TRAJ_CSV or TOOL_TRAJ_JSONL */
    int scalars;               /* 1: each voxel's strain, stress, speed and phase too (--scalars) */
    long rows;                 /* rows written */
    am_record rec;             /* what am_evaluate calls: every, and the sink writing the rows */
} tool_traj;

/* the format a file name asks for: JSON lines for a name ending in .jsonl, else CSV */
int tool_traj_format_of(const char* path);
/* starts the file path (nothing is visible there before tool_traj_close commits) and points
 * eval->record at t->rec; 0, or 1 after a one-line message */
int tool_traj_open(tool_traj* t, const char* path, int format, int every, int scalars, am_eval_def* eval);
/* commit 1: the file replaces path; 0: dropped. 0, or 1 after a one-line message (dropped then) */
int tool_traj_close(tool_traj* t, int commit);

#endif
