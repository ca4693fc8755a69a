/* The viewer page of amorph view and of a run's end: one self-contained HTML file with a robot's
 * recorded motion and a hand-written canvas renderer (no network, no external script;
 * docs/pictures.md describes the data layout). */
#include "picture.h"
#if TOOL_PICTURES
#include "view_page.h"
#include "view_draw.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* the page: the poses in base64 (14 bytes a voxel a frame, 4/3 of it as text), the per-voxel and
 * per-frame numbers as text, and the fixed page around them */
#define VIEW_HTML_MAX ((TOOL_REC_FLOATS / 7) * 25L + AM_MAX_VOXELS * 96L + TOOL_REC_MAX_FRAMES * 96L + 262144L + VIEW_MESH_MAX)
/* the body's surface: at most one face per face position, half the mesh's capacities; a triangle
 * takes at most 3 x 8 + 3 characters, a vertex 4 x 8 + 4 */
#define VIEW_MESH_MAX ((AM_MESH_MAX_TRIS / 2) * 33L + (AM_MESH_MAX_VERTS / 2) * 36L)
static char view_html[VIEW_HTML_MAX];
static uint8_t view_raw[(TOOL_REC_FLOATS / 7) * 14L];

/* the bounded text buffer of amorph/base.h */
#define out_fmt am_text_put

static void out_str(am_text* o, const char* s)
{
    long n = (long)strlen(s);
    if (o->full || n >= o->cap - o->len) {
        o->full = 1;
        return;
    }
    memcpy(o->buf + o->len, s, (size_t)n + 1);
    o->len += n;
}

/* a JSON string safe inside a <script> element: <, >, & and controls as \u escapes */
static void out_json_string(am_text* o, const char* s)
{
    out_str(o, "\"");
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') out_fmt(o, "\\%c", c);
        else if (c < 0x20 || c == '<' || c == '>' || c == '&' || c == 0x7F) out_fmt(o, "\\u%04x", c);
        else out_fmt(o, "%c", c);
    }
    out_str(o, "\"");
}

static void out_base64(am_text* o, const uint8_t* p, long n)
{
    static const char tab[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    long need = (n + 2) / 3 * 4;
    if (o->full || need >= o->cap - o->len) {
        o->full = 1;
        return;
    }
    char* d = o->buf + o->len;
    long i = 0;
    for (; i + 2 < n; i += 3) {
        uint32_t v = (uint32_t)p[i] << 16 | (uint32_t)p[i + 1] << 8 | p[i + 2];
        *d++ = tab[v >> 18], *d++ = tab[(v >> 12) & 63], *d++ = tab[(v >> 6) & 63], *d++ = tab[v & 63];
    }
    if (i < n) {
        uint32_t v = (uint32_t)p[i] << 16 | (i + 1 < n ? (uint32_t)p[i + 1] << 8 : 0);
        *d++ = tab[v >> 18], *d++ = tab[(v >> 12) & 63];
        *d++ = i + 1 < n ? tab[(v >> 6) & 63] : '=';
        *d++ = '=';
    }
    *d = 0;
    o->len += need;
}

/* 1, 2 or 5 times a power of ten, the smallest at least x */
static double nice_step(double x)
{
    double p = pow(10.0, floor(log10(x)));
    return x <= p ? p : x <= 2 * p ? 2 * p : x <= 5 * p ? 5 * p : 10 * p;
}

/* the data of the page as one JSON object */
static void view_data(am_text* o, const tool_motion* mo, const am_mesh* mesh, const am_eval_def* eval, const char* title)
{
    const am_model* m = mo->model;
    int nv = mo->nv, nf = mo->frames;
    long i;
    /* quantised poses: positions as 16-bit steps over the recorded box, quaternions as x 32767 */
    double lo[3] = {1e30, 1e30, 1e30}, hi[3] = {-1e30, -1e30, -1e30}, q[3];
    for (i = 0; i < (long)nf * nv; i++)
        for (int k = 0; k < 3; k++) {
            double v = (double)mo->pose[7 * i + k];
            lo[k] = fmin(lo[k], v), hi[k] = fmax(hi[k], v);
        }
    for (int k = 0; k < 3; k++) q[k] = hi[k] > lo[k] ? (hi[k] - lo[k]) / 65535.0 : 1e-9;
    for (i = 0; i < (long)nf * nv; i++) {
        uint8_t* r = view_raw + 14 * i;
        for (int k = 0; k < 3; k++) {
            long u = lround(((double)mo->pose[7 * i + k] - lo[k]) / q[k]);
            u = u < 0 ? 0 : u > 65535 ? 65535 : u;
            r[2 * k] = (uint8_t)u, r[2 * k + 1] = (uint8_t)(u >> 8);
        }
        for (int k = 0; k < 4; k++) {
            long s = lround((double)mo->pose[7 * i + 3 + k] * 32767.0);
            s = s < -32767 ? -32767 : s > 32767 ? 32767 : s;
            uint16_t u = (uint16_t)(s < 0 ? s + 65536 : s);
            r[6 + 2 * k] = (uint8_t)u, r[7 + 2 * k] = (uint8_t)(u >> 8);
        }
    }
    /* framing, over the movement (the frames from the settled one on; all of them when the
     * movement has none of its own): the body's size, and the whole path's */
    const int f0 = mo->settled_frame < nf - 1 ? mo->settled_frame : 0;
    double mean[3] = {0, 0, 0}, body = 0, all = 0, c[3];
    for (int f = f0; f < nf; f++) {
        tool_motion_com(mo, f, c);
        for (int k = 0; k < 3; k++) mean[k] += c[k] / (nf - f0);
    }
    for (int f = f0; f < nf; f++) {
        tool_motion_com(mo, f, c);
        const float* p = mo->pose + (long)f * nv * 7;
        for (int v = 0; v < nv; v++) {
            double d2 = 0, e2 = 0;
            for (int k = 0; k < 3; k++) {
                double d = (double)p[7 * v + k] - c[k], e = (double)p[7 * v + k] - mean[k];
                d2 += d * d, e2 += e * e;
            }
            body = fmax(body, sqrt(d2)), all = fmax(all, sqrt(e2));
        }
    }
    double L = am_to_si(m, m->L, AM_DIM_LENGTH);
    int follow = all > 3 * body;
    double extent = 2 * (follow ? body : all) + 2 * L;
    /* the box the page fills with the body: the voxels' centres seen by the default camera
     * (azimuth -0.6, elevation 0.49 rad), about the centre of mass of each frame when the view
     * follows the robot, else about the mean, padded by 0.7 voxel edges (a voxel's half diagonal seen from there) */
    double box[4] = {1e30, -1e30, 1e30, -1e30};
    {
        const double az = -0.6, el = 0.49;
        const double right[3] = {cos(az), sin(az), 0}, fwd[3] = {-sin(az) * cos(el), cos(az) * cos(el), -sin(el)};
        const double up[3] = {right[1] * fwd[2] - right[2] * fwd[1], right[2] * fwd[0] - right[0] * fwd[2],
                              right[0] * fwd[1] - right[1] * fwd[0]};
        for (int f = f0; f < nf; f++) {
            tool_motion_com(mo, f, c);
            const double* ctr = follow ? c : mean;
            const float* p = mo->pose + (long)f * nv * 7;
            for (int v = 0; v < nv; v++) {
                double d[3] = {(double)p[7 * v] - ctr[0], (double)p[7 * v + 1] - ctr[1], (double)p[7 * v + 2] - ctr[2]};
                double u = d[0] * right[0] + d[1] * right[1] + d[2] * right[2], w = d[0] * up[0] + d[1] * up[1] + d[2] * up[2];
                box[0] = fmin(box[0], u - 0.7 * L), box[1] = fmax(box[1], u + 0.7 * L), box[2] = fmin(box[2], w - 0.7 * L), box[3] = fmax(box[3], w + 0.7 * L);
            }
        }
    }

    out_str(o, "{\"format\": \"amorph-view 1\",\n\"title\": ");
    out_json_string(o, title);
    out_fmt(o, ",\n\"nv\": %d, \"frames\": %d, \"dt\": %.9g, \"period_steps\": %d, \"cycles\": %d,\n", nv, nf, mo->dt,
            m->env.period_steps, eval->cycles);
    out_fmt(o, "\"settled_frame\": %d, \"fitness\": %.9g, \"diverged\": %d, \"voxel_size\": %.9g,\n", mo->settled_frame,
            mo->res.fitness, mo->res.diverged, L);
    out_fmt(o, "\"relax_steps\": %ld,\n", mo->res.relax_steps);
    out_fmt(o, "\"size\": [%d, %d, %d], \"center\": [%.7g, %.7g, %.7g], \"extent\": %.7g, \"grid\": %.7g, \"follow\": %d,\n",
            m->nx, m->ny, m->nz, mean[0], mean[1], mean[2], extent, nice_step(extent / 8), follow);
    out_fmt(o, "\"view_box\": [%.7g, %.7g, %.7g, %.7g],\n", box[0], box[1], box[2], box[3]);
    out_fmt(o, "\"origin\": [%.9g, %.9g, %.9g], \"quantum\": [%.9g, %.9g, %.9g],\n", lo[0], lo[1], lo[2], q[0], q[1], q[2]);
    out_str(o, "\"materials\": [");
    for (int k = 0; k < m->palette.count; k++) {
        const uint8_t* col = m->palette.mat[k].color;
        out_str(o, k ? ", {\"name\": " : "{\"name\": ");
        out_json_string(o, m->palette.mat[k].name);
        out_fmt(o, ", \"color\": \"#%02x%02x%02x\"}", col[0], col[1], col[2]);
    }
    out_str(o, "],\n\"steps\": [");
    for (int f = 0; f < nf; f++) out_fmt(o, f ? ",%ld" : "%ld", mo->step[f]);
    out_str(o, "],\n\"com\": [");
    for (int f = 0; f < nf; f++) {
        tool_motion_com(mo, f, c);
        out_fmt(o, f ? ",%.7g,%.7g,%.7g" : "%.7g,%.7g,%.7g", c[0], c[1], c[2]);
    }
    out_str(o, "],\n\"mat\": [");
    for (int v = 0; v < nv; v++) out_fmt(o, v ? ",%d" : "%d", m->mat[v]);
    out_str(o, "],\n\"cell\": [");
    for (int v = 0; v < nv; v++) {
        int idx = m->cell[v], x = idx % m->nx, y = (idx / m->nx) % m->ny, z = idx / (m->nx * m->ny);
        out_fmt(o, v ? ",%d,%d,%d" : "%d,%d,%d", x, y, z);
    }
    if (mesh) {
        /* the surface (amorph/io.h): corner vertices, the means, the triangles */
        out_str(o, "],\n\"mesh_corner\": [");
        for (long v = 0; v < mesh->ncorner; v++) out_fmt(o, v ? ",%ld" : "%ld", (long)mesh->vcorner[v]);
        out_str(o, "],\n\"mesh_mask\": [");
        for (long v = 0; v < mesh->ncorner; v++) out_fmt(o, v ? ",%d" : "%d", mesh->vmask[v]);
        out_str(o, "],\n\"mesh_from\": [");
        for (long v = mesh->ncorner; v < mesh->nvert; v++)
            out_fmt(o, v > mesh->ncorner ? ",%ld,%ld,%ld,%ld" : "%ld,%ld,%ld,%ld", (long)mesh->vfrom[v][0], (long)mesh->vfrom[v][1],
                    (long)mesh->vfrom[v][2], (long)mesh->vfrom[v][3]);
        out_str(o, "],\n\"mesh_tri\": [");
        for (long t = 0; t < mesh->ntri; t++)
            out_fmt(o, t ? ",%ld,%ld,%ld" : "%ld,%ld,%ld", (long)mesh->tri[t][0], (long)mesh->tri[t][1], (long)mesh->tri[t][2]);
        out_str(o, "],\n\"mesh_mat\": [");
        for (long t = 0; t < mesh->ntri; t++) out_fmt(o, t ? ",%d" : "%d", mesh->tmat[t]);
        out_str(o, "],\n\"mesh_vox\": [");
        const int32_t* tv = tool_mesh_tri_voxel();
        for (long t = 0; t < mesh->ntri; t++) out_fmt(o, t ? ",%ld" : "%ld", (long)tv[t]);
    }
    /* the boundary conditions: the clamped voxels, and each forced voxel with its force (N) */
    out_str(o, "],\n\"fixed\": [");
    int any = 0;
    for (int v = 0; v < nv; v++)
        if (mo->fixed[v]) out_fmt(o, any++ ? ",%d" : "%d", v);
    out_str(o, "],\n\"force\": [");
    any = 0;
    for (int v = 0; v < nv; v++) {
        const float* F = mo->force + 3 * v;
        if (F[0] != 0 || F[1] != 0 || F[2] != 0)
            out_fmt(o, any++ ? ",%d,%.6g,%.6g,%.6g" : "%d,%.6g,%.6g,%.6g", v, (double)F[0], (double)F[1], (double)F[2]);
    }
    out_str(o, "],\n\"pose\": \"");
    out_base64(o, view_raw, 14L * nf * nv);
    /* the colourings: each scalar as a byte per voxel and frame, 0 .. 255 over its scale lo .. hi */
    out_str(o, "\",\n\"scalars\": [");
    for (int mode = TOOL_COL_STRAIN; mode < TOOL_COL_COUNT; mode++) {
        double slo, shi, per;
        tool_colour_range(mo, mode, &slo, &shi);
        const char* unit = tool_colour_unit(mode, &per);
        for (i = 0; i < (long)nf * nv; i++) {
            double u = (tool_colour_value(mo, mode, (int)(i / nv), (int)(i % nv)) - slo) / (shi - slo);
            view_raw[i] = (uint8_t)(u > 1 ? 255 : u > 0 ? lround(u * 255) : 0);
        }
        out_fmt(o, "%s{\"name\": \"%s\", \"unit\": \"%s\", \"per_si\": %g, \"lo\": %.6g, \"hi\": %.6g, \"data\": \"",
                mode > TOOL_COL_STRAIN ? ",\n" : "", tool_colour_name(mode), unit, per, slo, shi);
        out_base64(o, view_raw, (long)nf * nv);
        out_str(o, "\"}");
    }
    out_str(o, "]}\n");
}

int view_write(tool_ctx* c, const am_robot* r, int frames, const char* title, const char* what, const char* path)
{
    static tool_motion mo;
    const am_lattice* lat = r->lattice;
    const am_eval_def* eval = &r->eval;
    int rc = tool_record_motion(c, r, frames, &mo, what);
    if (rc) return rc;
    am_text o = {view_html, VIEW_HTML_MAX, 0, 0, NULL, NULL, 0};
    view_html[0] = 0;
    for (size_t k = 0; k < sizeof view_page_pre / sizeof view_page_pre[0]; k++) out_str(&o, view_page_pre[k]);
    char err[AM_ERR_MAX];
    if (am_mesh_build(tool_mesh(), lat, AM_MESH_BODY, err, sizeof err) != AM_OK) return tool_usage_error("%s: %s", what, err);
    view_data(&o, &mo, tool_mesh(), eval, title);
    for (size_t k = 0; k < sizeof view_page_post / sizeof view_page_post[0]; k++) out_str(&o, view_page_post[k]);
    for (size_t k = 0; k < sizeof view_page_draw / sizeof view_page_draw[0]; k++) out_str(&o, view_page_draw[k]);
    if (o.full) {
        fprintf(stderr, "amorph: %s: the page does not fit in %ld bytes\n", path, (long)VIEW_HTML_MAX);
        return 1;
    }
    return tool_write_output(path, view_html, o.len);
}

int tool_write_viewer(tool_ctx* c, const am_robot* r, const char* title, const char* path)
{
    return view_write(c, r, 200, title ? title : path, path, path) ? 1 : 0;
}

#else
typedef int tool_viewer_not_built; /* board profile: tools/picture.c has the stand-ins */
#endif
