/* A simulation's trajectory as CSV or JSON lines, written row by row from the simulator's
 * recording sink (am_record.sink) through a small buffer into an atomic replace. */
#include "trajectory.h"

#include "picture.h"

#include <math.h>
#include <string.h>

int tool_traj_format_of(const char* path)
{
    size_t n = strlen(path);
    return n >= 6 && !strcmp(path + n - 6, ".jsonl") ? TOOL_TRAJ_JSONL : TOOL_TRAJ_CSV;
}

/* a number: %.9g (positions, quaternions), or null in JSON when it is not finite */
static void num(am_text* o, int json, const char* sep, double v, int digits)
{
    if (json && !isfinite(v)) am_text_put(o, "%snull", sep);
    else am_text_put(o, "%s%.*g", sep, digits, v);
}

/* one row's scalars, every voxel's found once (tool_voxel_scalars) for either format; the board
 * profile has none (its sim refuses --scalars) */
typedef double voxel_scalars[TOOL_REC_SCALARS];
#if TOOL_PICTURES
static voxel_scalars g_row[AM_MAX_VOXELS];
static voxel_scalars* row_scalars(const am_model* m, const am_state* s)
{
    for (int i = 0; i < m->nv; i++) tool_voxel_scalars(m, s, i, g_row[i]);
    return g_row;
}
#else
static voxel_scalars* row_scalars(const am_model* m, const am_state* s)
{
    (void)m, (void)s;
    return NULL;
}
#endif

/* the scalars' names, in tool_voxel_scalars' order */
static const char* const scalar_name[TOOL_REC_SCALARS] = {"strain", "stress", "speed", "phase"};

/* the CSV header: step, time, segment, the centre of mass, then 7 columns per voxel (11 with the
 * scalars) */
static void csv_header(am_text* o, int nv, int scalars)
{
    am_text_put(o, "step,time,segment,com_x,com_y,com_z");
    for (int i = 0; i < nv; i++) {
        am_text_put(o, ",v%d_x,v%d_y,v%d_z,v%d_qw,v%d_qx,v%d_qy,v%d_qz", i, i, i, i, i, i, i);
        for (int k = 0; scalars && k < TOOL_REC_SCALARS; k++) am_text_put(o, ",v%d_%s", i, scalar_name[k]);
    }
    am_text_put(o, "\n");
}

/* one row: the state s of model m (the simulator's sink) */
static void traj_row(void* ctx, const am_model* m, const struct am_state* s)
{
    tool_traj* t = (tool_traj*)ctx;
    am_text* o = &t->out.text;
    const int json = t->format == TOOL_TRAJ_JSONL;
    voxel_scalars* sc = t->scalars ? row_scalars(m, s) : NULL;
    if (t->rows == 0 && !json) csv_header(o, m->nv, sc != NULL);
    double com[3];
    am_com(m, s, com);
    const double time = am_sim_time(m, s), unit = am_unit(m, AM_DIM_LENGTH);
    if (json) am_text_put(o, "{\"step\": %ld, \"time\": ", s->step);
    else am_text_put(o, "%ld,", s->step);
    num(o, json, "", time, 9);
    am_text_put(o, json ? ", \"segment\": %d, \"com\": [" : ",%d", s->actuate ? 1 : 0);
    for (int k = 0; k < 3; k++) num(o, json, json && !k ? "" : json ? ", " : ",", com[k], 17);
    if (json) am_text_put(o, "], \"pos\": [");
    for (int i = 0; i < m->nv; i++) {
        if (json) am_text_put(o, i ? ", [" : "[");
        for (int k = 0; k < 3; k++)
            num(o, json, json && !k ? "" : json ? ", " : ",", (AM_TO_DOUBLE(m->x0[k][i]) + AM_TO_DOUBLE(s->x[k][i])) * unit, 9);
        if (json) {
            am_text_put(o, "]");
            continue;
        }
        for (int k = 0; k < 4; k++) num(o, 0, ",", AM_TO_DOUBLE(s->q[k][i]), 9);
        for (int k = 0; sc && k < TOOL_REC_SCALARS; k++) num(o, 0, ",", sc[i][k], 9);
    }
    if (json) {
        am_text_put(o, "], \"quat\": [");
        for (int i = 0; i < m->nv; i++) {
            am_text_put(o, i ? ", [" : "[");
            for (int k = 0; k < 4; k++) num(o, 1, k ? ", " : "", AM_TO_DOUBLE(s->q[k][i]), 9);
            am_text_put(o, "]");
        }
        am_text_put(o, "]");
        /* the scalars, one array each: "strain": [e0, e1, ...], ... */
        for (int k = 0; sc && k < TOOL_REC_SCALARS; k++) {
            am_text_put(o, ", \"%s\": [", scalar_name[k]);
            for (int i = 0; i < m->nv; i++) num(o, 1, i ? ", " : "", sc[i][k], 9);
            am_text_put(o, "]");
        }
        am_text_put(o, "}");
    }
    am_text_put(o, "\n");
    t->rows++;
}

int tool_traj_open(tool_traj* t, const char* path, int format, int every, int scalars, am_eval_def* eval)
{
    memset(t, 0, sizeof *t);
    t->format = format;
    t->scalars = scalars;
    if (tool_out_open(&t->out, path)) return 1;
    t->rec.every = every;
    t->rec.sink = traj_row;
    t->rec.sink_ctx = t;
    eval->record = &t->rec;
    return 0;
}

int tool_traj_close(tool_traj* t, int commit)
{
    return tool_out_close(&t->out, commit);
}
