/* What the pictures share (amorph render and view, plot --travel, the filmstrip at a run's end):
 * one recorded evaluation of a robot, the size of each voxel in a recorded frame, centres of mass,
 * and the robot argument (scene, file or run). */
#include "picture.h"
#if TOOL_PICTURES

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static float pic_pose[TOOL_REC_FLOATS];
static long pic_step[TOOL_REC_MAX_FRAMES];
static float pic_scalar[(TOOL_REC_FLOATS / 7) * TOOL_REC_SCALARS];
static uint8_t pic_fixed[AM_MAX_VOXELS];
static float pic_force[3 * AM_MAX_VOXELS];
static am_mesh pic_mesh;
static double pic_mesh_pos[3 * AM_MESH_MAX_VERTS];

static int32_t pic_tri_voxel[AM_MESH_MAX_TRIS];

const int32_t* tool_mesh_tri_voxel(void)
{
    const am_mesh* m = &pic_mesh;
    long f = -1;
    int32_t ctr = -1;
    for (long t = 0; t < m->ntri; t++) {
        if (m->tri[t][0] != ctr) ctr = m->tri[t][0], f++;
        pic_tri_voxel[t] = f < m->nface ? m->cell_voxel[m->face_cell[f]] : 0;
    }
    return pic_tri_voxel;
}

am_mesh* tool_mesh(void) { return &pic_mesh; }
double* tool_mesh_pos(void) { return pic_mesh_pos; }

const uint8_t tool_col_clamp[3] = {70, 70, 78}, tool_col_force[3] = {0, 150, 150};

/* the recording: the simulator hands every frame to rec_frame (am_record.sink), which keeps its
 * poses and scalars while there is room; when there is none, the last frame kept is replaced, so
 * that the end of the evaluation is always the last frame */
typedef struct pic_rec {
    int cap;      /* frames that fit */
    int frames;   /* frames kept */
} pic_rec;

/* voxel i's links (its neighbours' slots): each one's strain |e| + |theta| / 2, e its axial strain
 * against its current rest length (the simulator's, state strain), theta the angle between its two
 * voxels' orientations (a bend or twist of theta over one voxel edge strains the beam's outer fibre
 * by theta / 2), and that times the link's modulus k_ax / L^2 as its stress; the means over the
 * voxel's links */
static void link_scalars(const am_model* m, const am_state* s, int i, double* strain, double* stress)
{
    double e = 0, sg = 0, L = am_to_si(m, m->L, AM_DIM_LENGTH);
    int n = 0;
    for (int d = 0; d < 6; d++) {
        const int j = am_neighbour(m, d, i);
        if (j < 0) continue;
        const int l = m->slot[d][i];
        /* the relative turn conj(qi) qj: its angle from its vector part and its w */
        double a[4], b[4];
        for (int k = 0; k < 4; k++) a[k] = AM_TO_DOUBLE(s->q[k][i]), b[k] = AM_TO_DOUBLE(s->q[k][j]);
        double w = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
        double vx = a[0] * b[1] - a[1] * b[0] - (a[2] * b[3] - a[3] * b[2]);
        double vy = a[0] * b[2] - a[2] * b[0] - (a[3] * b[1] - a[1] * b[3]);
        double vz = a[0] * b[3] - a[3] * b[0] - (a[1] * b[2] - a[2] * b[1]);
        double theta = 2 * atan2(sqrt(vx * vx + vy * vy + vz * vz), fabs(w));
        double eps = fabs(AM_TO_DOUBLE(s->strain[l])) + 0.5 * theta;
        e += eps;
        sg += eps * am_to_si(m, m->k_ax[AM_LC(m, l)], AM_DIM_FORCE) / (L * L);
        n++;
    }
    *strain = n ? e / n : 0;
    *stress = n ? sg / n : 0;
}

void tool_voxel_scalars(const am_model* m, const am_state* s, int i, double out[TOOL_REC_SCALARS])
{
    double v2 = 0;
    link_scalars(m, s, i, &out[0], &out[1]);
    const double mass = am_to_si(m, m->mass[AM_VC(m, i)], AM_DIM_MASS);
    for (int k = 0; k < 3; k++) {
        double v = am_to_si(m, s->p[k][i], AM_DIM_MOMENTUM) / mass;
        v2 += v * v;
    }
    out[2] = sqrt(v2);
    out[3] = AM_TO_DOUBLE(s->s[i]) - 1;
}

static void rec_frame(void* ctx, const am_model* m, const struct am_state* s)
{
    pic_rec* r = (pic_rec*)ctx;
    int f = r->frames < r->cap ? r->frames++ : r->cap - 1;
    const double unit = am_unit(m, AM_DIM_LENGTH);
    float* p = pic_pose + (long)f * m->nv * 7;
    float* sc = pic_scalar + (long)f * m->nv * TOOL_REC_SCALARS;
    for (int i = 0; i < m->nv; i++) {
        for (int k = 0; k < 3; k++) p[7 * i + k] = (float)((AM_TO_DOUBLE(m->x0[k][i]) + AM_TO_DOUBLE(s->x[k][i])) * unit);
        for (int k = 0; k < 4; k++) p[7 * i + 3 + k] = (float)AM_TO_DOUBLE(s->q[k][i]);
        double v[TOOL_REC_SCALARS];
        tool_voxel_scalars(m, s, i, v);
        for (int k = 0; k < TOOL_REC_SCALARS; k++) sc[TOOL_REC_SCALARS * i + k] = (float)v[k];
    }
    pic_step[f] = s->step;
}

int tool_record_motion(tool_ctx* c, const am_robot* r, int want, tool_motion* mo, const char* what)
{
    const am_env* env = &r->env;
    const am_eval_def* eval = &r->eval;
    char err[AM_ERR_MAX];
    memset(mo, 0, sizeof *mo);
    am_status st = am_robot_build(&c->work[0].model, r, err, sizeof err);
    if (st == AM_ERR_EMPTY) return tool_usage_error("%s: the robot has no voxel, nothing to draw", what);
    if (st != AM_OK) return tool_usage_error("%s: %s", what, err);
    /* frames that fit: the float budget caps big bodies, the step list caps the count. Record as
     * many as fit over the longest the evaluation can take, then keep `want` of them */
    const am_model* m = &c->work[0].model;
    long fit = TOOL_REC_FLOATS / ((long)m->nv * 7);
    if (fit > TOOL_REC_MAX_FRAMES) fit = TOOL_REC_MAX_FRAMES;
    if (want > fit) want = (int)fit;
    if (want < 2) want = 2;
    /* the regular frames, and the two the simulator adds (the ends of the relaxation and of the
     * evaluation) */
    long total = eval->relax_max_steps + (long)eval->cycles * env->period_steps;
    long every = (total + fit - 4) / (fit - 3);
    if (every < 1) every = 1;
    static am_record rec;
    static pic_rec pr;
    memset(&rec, 0, sizeof rec);
    pr.cap = (int)fit;
    pr.frames = 0;
    rec.every = (int)(every > 1000000000L ? 1000000000L : every);
    rec.sink = rec_frame;
    rec.sink_ctx = &pr;
    am_eval_def def = *eval;
    def.record = &rec;
    am_evaluate(m, &c->work[0].state, &def, &mo->res);
    rec.frames = pr.frames;
    rec.nv = m->nv;
    /* the boundary conditions: clamped voxels, constant forces (N) */
    mo->nfixed = mo->nforced = 0;
    for (int i = 0; i < m->nv; i++) {
        pic_fixed[i] = m->fixed[i] ? 1 : 0;
        mo->nfixed += pic_fixed[i];
        double f2 = 0;
        for (int k = 0; k < 3; k++) {
            /* (a clamped voxel's entry is its prescribed displacement, not a force) */
            double fk = m->any_force && !m->fixed[i] ? am_to_si(m, m->force[k][i], AM_DIM_FORCE) : 0;
            pic_force[3 * i + k] = (float)fk;
            f2 += fk * fk;
        }
        mo->nforced += f2 > 0;
    }
    mo->fixed = pic_fixed;
    mo->force = pic_force;
    mo->scalar = pic_scalar;
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
            memmove(pic_scalar + (long)k * rec.nv * TOOL_REC_SCALARS, pic_scalar + (long)sel[k] * rec.nv * TOOL_REC_SCALARS,
                    sizeof(float) * TOOL_REC_SCALARS * (size_t)rec.nv);
            pic_step[k] = pic_step[sel[k]];
            if (sel[k] <= settled) mo->settled_frame = k;
        }
        good = want;
    } else
        mo->settled_frame = settled;
    mo->frames = good;
    return 0;
}

static const char* const colour_names[TOOL_COL_COUNT] = {"material", "strain", "stress", "speed", "phase"};

const char* tool_colour_name(int mode) { return mode >= 0 && mode < TOOL_COL_COUNT ? colour_names[mode] : "?"; }

int tool_colour_parse(const char* name)
{
    for (int k = 0; k < TOOL_COL_COUNT; k++)
        if (name && !strcmp(name, colour_names[k])) return k;
    return -1;
}

double tool_colour_value(const tool_motion* mo, int mode, int f, int i)
{
    if (mode <= TOOL_COL_MATERIAL || mode >= TOOL_COL_COUNT) return 0;
    return (double)mo->scalar[((long)f * mo->nv + i) * TOOL_REC_SCALARS + (mode - TOOL_COL_STRAIN)];
}

const char* tool_colour_unit(int mode, double* per_si)
{
    switch (mode) {
    case TOOL_COL_STRAIN: *per_si = 100; return "%";
    case TOOL_COL_STRESS: *per_si = 0.001; return "kPa";
    case TOOL_COL_SPEED: *per_si = 1000; return "mm/s";
    case TOOL_COL_PHASE: *per_si = 100; return "%";
    default: *per_si = 1; return "";
    }
}

/* 1, 2 or 5 times a power of ten, the smallest at least x (x > 0) */
static double round_up(double x)
{
    double p = pow(10.0, floor(log10(x)));
    return x <= p ? p : x <= 2 * p ? 2 * p : x <= 5 * p ? 5 * p : 10 * p;
}

void tool_colour_range(const tool_motion* mo, int mode, double* lo, double* hi)
{
    /* over the movement (the frames from the settled one on), or the whole recording when the
     * movement has no frame of its own: the fall of the relaxation does not set the scale; the
     * voxels that are not clamped; and the 99th percentile of the |values| (a histogram of 1000
     * bins up to the largest), so that a moment's spike does not darken every other */
    int f0 = mo->settled_frame < mo->frames - 1 ? mo->settled_frame : 0;
    static long hist[1001];
    double big = 0, per;
    long n = 0;
    for (int f = f0; f < mo->frames; f++)
        for (int i = 0; i < mo->nv; i++) {
            double v = mo->fixed[i] ? 0 : fabs(tool_colour_value(mo, mode, f, i));
            if (v == v && v > big) big = v;
        }
    memset(hist, 0, sizeof hist);
    for (int f = f0; f < mo->frames && big > 0; f++)
        for (int i = 0; i < mo->nv; i++) {
            double v = fabs(tool_colour_value(mo, mode, f, i));
            if (v == v && !mo->fixed[i]) hist[(int)(fmin(v, big) / big * 1000)]++, n++;
        }
    double top = 0;
    long seen = 0;
    for (int b = 0; b <= 1000 && big > 0; b++) {
        seen += hist[b];
        top = (b + 1) * big / 1000;
        if (seen >= n - n / 100) break;
    }
    tool_colour_unit(mode, &per);
    double shown = top * per;
    shown = shown > 1e-9 ? round_up(shown * (1 - 1e-9)) : 1;
    *hi = shown / per;
    *lo = mode == TOOL_COL_PHASE ? -*hi : 0;
}

void tool_colour_ramp(int mode, double u, uint8_t rgb[3])
{
    static const uint8_t seq[5][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
    static const uint8_t div[3][3] = {{33, 102, 172}, {247, 247, 247}, {178, 24, 43}};
    if (!(u > 0)) u = 0;
    if (u > 1) u = 1;
    const uint8_t(*stop)[3] = mode == TOOL_COL_PHASE ? div : seq;
    int n = mode == TOOL_COL_PHASE ? 3 : 5;
    double x = u * (n - 1);
    int k = (int)x;
    if (k > n - 2) k = n - 2;
    double t = x - k;
    for (int j = 0; j < 3; j++) rgb[j] = (uint8_t)(stop[k][j] + (stop[k + 1][j] - stop[k][j]) * t + 0.5);
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

int tool_load_subject(tool_ctx* c, const tool_robot_args* a, am_robot* r, const char* cmd)
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
int tool_write_filmstrip(tool_ctx* c, const am_robot* r, const char* path)
{
    (void)c, (void)r;
    return not_built(path) ? 1 : 0;
}
int tool_write_viewer(tool_ctx* c, const am_robot* r, const char* title, const char* path)
{
    (void)c, (void)r, (void)title;
    return not_built(path) ? 1 : 0;
}
int tool_write_plot(int ndirs, char** dirs, const char* path)
{
    (void)ndirs, (void)dirs;
    return not_built(path ? path : "plot") ? 1 : 0;
}
#endif
