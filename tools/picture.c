/* What amorph render and amorph view share: one recorded evaluation of a robot, the size of each
 * voxel in a recorded frame, centres of mass, and the robot argument (scene, file or run). */
#include "picture.h"
#if TOOL_PICTURES

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static float pic_pose[TOOL_REC_FLOATS];
static long pic_step[TOOL_REC_MAX_FRAMES];
static am_mesh pic_mesh;
static double pic_mesh_pos[3 * AM_MESH_MAX_VERTS];

am_mesh* tool_mesh(void) { return &pic_mesh; }
double* tool_mesh_pos(void) { return pic_mesh_pos; }

int tool_record_motion(tool_ctx* c, const am_lattice* lat, const am_env* env, const am_eval_def* eval, int want, tool_motion* mo,
                       const char* what)
{
    char err[AM_ERR_MAX];
    memset(mo, 0, sizeof *mo);
    am_status st = tool_model_build(c, &c->work[0].model, lat, env, err, sizeof err);
    if (st == AM_ERR_EMPTY) return tool_usage_error("%s: the robot has no voxel, nothing to draw", what);
    if (st != AM_OK) return tool_usage_error("%s: %s", what, err);
    /* frames that fit: the float budget caps big bodies, the step list caps the count. Record as
     * many as fit over the longest the evaluation can take, then keep `want` of them */
    long fit = TOOL_REC_FLOATS / ((long)c->work[0].model.nv * 7);
    if (fit > TOOL_REC_MAX_FRAMES) fit = TOOL_REC_MAX_FRAMES;
    if (want > fit) want = (int)fit;
    if (want < 2) want = 2;
    long total = eval->relax_max_steps + (long)eval->cycles * env->period_steps;
    long every = (total + fit - 2) / (fit - 1);
    if (every < 1) every = 1;
    static am_record rec;
    memset(&rec, 0, sizeof rec);
    rec.every = (int)(every > 1000000000L ? 1000000000L : every);
    rec.max_frames = (int)fit;
    rec.pose = pic_pose;
    rec.step = pic_step;
    rec.pose_cap = TOOL_REC_FLOATS;
    am_eval_def def = *eval;
    def.record = &rec;
    am_evaluate(&c->work[0].model, &c->work[0].state, &def, &mo->res);
    /* keep the frames before the first non-finite value (a diverged run) */
    int good = 0;
    for (; good < rec.frames; good++) {
        const float* f = pic_pose + (long)good * rec.nv * 7;
        int ok = 1;
        for (long k = 0; k < (long)rec.nv * 7 && ok; k++) ok = f[k] == f[k] && fabsf(f[k]) < 1e6f;
        if (!ok) break;
    }
    if (good < 1) return tool_usage_error("%s: the simulation diverged at once, nothing to draw", what);
    mo->model = &c->work[0].model;
    mo->nv = rec.nv;
    mo->frames = good;
    mo->pose = pic_pose;
    mo->step = pic_step;
    mo->dt = mo->res.dt;
    int settled = 0;
    for (int f = 0; f < good; f++)
        if (pic_step[f] <= mo->res.relax_steps) settled = f;
    /* keep `want` frames evenly spread; the one nearest the end of relaxation becomes that frame
     * (never the first or the last) */
    if (good > want) {
        static int sel[TOOL_REC_MAX_FRAMES];
        int near = 0;
        for (int k = 0; k < want; k++) {
            sel[k] = (int)((long)k * (good - 1) / (want - 1));
            if (abs(sel[k] - settled) < abs(sel[near] - settled)) near = k;
        }
        if (near == 0 && settled > 0) near = 1;
        if (near == want - 1 && settled < good - 1) near = want - 2;
        if (near > 0 && near < want - 1 && sel[near - 1] < settled && settled < sel[near + 1]) sel[near] = settled;
        mo->settled_frame = 0;
        for (int k = 0; k < want; k++) {
            memmove(pic_pose + (long)k * rec.nv * 7, pic_pose + (long)sel[k] * rec.nv * 7, sizeof(float) * 7 * (size_t)rec.nv);
            pic_step[k] = pic_step[sel[k]];
            if (sel[k] <= settled) mo->settled_frame = k;
        }
        good = want;
    } else
        mo->settled_frame = settled;
    mo->frames = good;
    return 0;
}

void tool_motion_com(const tool_motion* mo, int frame, double com[3])
{
    const float* f = mo->pose + (long)frame * mo->nv * 7;
    double m = 0;
    com[0] = com[1] = com[2] = 0;
    for (int i = 0; i < mo->nv; i++) {
        double w = am_to_si(mo->model, mo->model->mass[AM_VC(mo->model, i)], AM_DIM_MASS);
        for (int k = 0; k < 3; k++) com[k] += w * (double)f[7 * i + k];
        m += w;
    }
    for (int k = 0; k < 3; k++) com[k] = m > 0 ? com[k] / m : 0;
}

int tool_load_subject(tool_ctx* c, const tool_robot_args* a, tool_robot* r, const char* cmd)
{
    char err[AM_ERR_MAX];
    if (tool_robot_load(c, a, &c->work[0].lattice, r, err, sizeof err) != AM_OK) return tool_usage_error("%s: %s", cmd, err);
    return 0;
}

int tool_check_output(const char* path, const char* cmd, const char* ext)
{
    if (!path) return tool_usage_error("%s: --out FILE%s is required", cmd, ext);
    size_t n = strlen(path);
    if (n == 0) return tool_usage_error("%s: --out needs a file name", cmd);
    if (path[n - 1] == '/') return tool_usage_error("%s: --out %s is a folder, not a file", cmd, path);
    return 0;
}

#else
/* the board profile: the commands and functions exist and say they are not built in */
static int not_built(const char* what)
{
    return tool_not_in_build(what, "pictures");
}
int cmd_render(tool_ctx* c, int argc, char** argv)
{
    (void)c, (void)argc, (void)argv;
    return not_built("render");
}
int cmd_plot(tool_ctx* c, int argc, char** argv)
{
    (void)c, (void)argc, (void)argv;
    return not_built("plot");
}
int cmd_view(tool_ctx* c, int argc, char** argv)
{
    (void)c, (void)argc, (void)argv;
    return not_built("view");
}
int tool_write_filmstrip(tool_ctx* c, const am_lattice* lat, const am_env* env, const am_eval_def* eval, const char* path)
{
    (void)c, (void)lat, (void)env, (void)eval;
    return not_built(path) ? 1 : 0;
}
int tool_write_viewer(tool_ctx* c, const am_lattice* lat, const am_env* env, const am_eval_def* eval, const char* title,
                      const char* path)
{
    (void)c, (void)lat, (void)env, (void)eval, (void)title;
    return not_built(path) ? 1 : 0;
}
int tool_write_plot(int ndirs, char** dirs, const char* path)
{
    (void)ndirs, (void)dirs;
    return not_built(path ? path : "plot") ? 1 : 0;
}
#endif
