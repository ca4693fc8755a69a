/* The filmstrip of amorph render and of a run's end: a PNG of one robot's evaluation, as the
 * seed's Figures 5 and 7 (the initial shape, the settled shape, then snapshots of the motion),
 * drawn by the library's rasteriser from recorded poses (docs/pictures.md). */
#include "picture.h"
#if TOOL_PICTURES

#include <math.h>
#include <stdio.h>
#include <string.h>


static uint8_t film_rgb[FILM_MAX_PIXELS * 3];
static float film_depth[FILM_MAX_PIXELS];
/* room for am_png_max_size of the largest picture */
static uint8_t film_png[FILM_MAX_PIXELS * 3 + FILM_MAX_H * 4 + (FILM_MAX_PIXELS * 3) / 8 + 4096];


/* the colour of every voxel in the frame being drawn, and the scale of a scalar colouring */
static uint8_t film_vcol[AM_MAX_VOXELS][3];
static double film_lo, film_hi;

/* each voxel's colour in frame fr: a clamped voxel in the clamp's grey, the others by their material
 * or by the scalar on the scale film_lo .. film_hi */
static void voxel_colours(const tool_motion* mo, int mode, int fr)
{
    for (int i = 0; i < mo->nv; i++) {
        if (mo->fixed[i]) memcpy(film_vcol[i], tool_col_clamp, 3);
        else if (mode == TOOL_COL_MATERIAL) memcpy(film_vcol[i], mo->model->palette.mat[mo->model->mat[i]].color, 3);
        else tool_colour_ramp(mode, (tool_colour_value(mo, mode, fr, i) - film_lo) / (film_hi - film_lo), film_vcol[i]);
    }
}

static const uint8_t col_floor[3] = {236, 236, 230}, col_grid[3] = {206, 206, 198}, col_shadow[3] = {196, 196, 190},
                     col_text[3] = {30, 30, 30}, col_trail[3] = {190, 0, 190},
                     col_rule[3] = {160, 160, 160}, col_start[3] = {90, 90, 90};

/* the fixed oblique camera: looking along +x+y from the front left, 28 degrees down */
#define FILM_AZ (-0.6)
#define FILM_EL (0.49)

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* 1, 2 or 5 times a power of ten, the smallest at least x */
static double nice_step(double x)
{
    double p = pow(10.0, floor(log10(x)));
    return x <= p ? p : x <= 2 * p ? 2 * p : x <= 5 * p ? 5 * p : 10 * p;
}

/* a length in metres as text: mm below 10 cm, cm below 1 m, else m */
static void fmt_len(char* buf, int n, double m)
{
    double a = fabs(m);
    if (a < 0.1) snprintf(buf, (size_t)n, "%.3g mm", m * 1000);
    else if (a < 1) snprintf(buf, (size_t)n, "%.3g cm", m * 100);
    else snprintf(buf, (size_t)n, "%.3g m", m);
}

/* a time in seconds as text: ms below 1 s */
static void fmt_time(char* buf, int n, double t)
{
    if (fabs(t) < 1) snprintf(buf, (size_t)n, "%.3g ms", t * 1000);
    else snprintf(buf, (size_t)n, "%.4g s", t);
}

/* the arrow head at (x1, y1) of a 2-D segment from (x0, y0) */
static void arrow_head(am_canvas* c, const am_camera* cam, double x0, double y0, double x1, double y1, double size,
                       const uint8_t rgb[3])
{
    double dx = x1 - x0, dy = y1 - y0, len = sqrt(dx * dx + dy * dy);
    if (!(len > 1e-9)) return;
    dx /= len, dy /= len;
    double t[9] = {x1 + dx * size * 0.4, y1 + dy * size * 0.4, 0, x1 - dx * size * 0.8 - dy * size * 0.55,
                   y1 - dy * size * 0.8 + dx * size * 0.55, 0, x1 - dx * size * 0.8 + dy * size * 0.55,
                   y1 - dy * size * 0.8 - dx * size * 0.55, 0};
    am_raster_triangle(c, cam, t, rgb, 0);
}

/* the body's surface in frame fr: each triangle turned to the viewer flat-shaded as a box face */
static void draw_surface(am_canvas* c, const am_camera* cam, const tool_motion* mo, int fr, const double light[3])
{
    const am_mesh* mesh = tool_mesh();
    double* pos = tool_mesh_pos();
    am_mesh_place(mesh, mo->pose + (long)fr * mo->nv * 7, pos);
    const int32_t* tv = tool_mesh_tri_voxel();
    for (long t = 0; t < mesh->ntri; t++) {
        const double *a = pos + 3 * mesh->tri[t][0], *b = pos + 3 * mesh->tri[t][1], *d = pos + 3 * mesh->tri[t][2];
        double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
        double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        double len = sqrt(dot3(n, n));
        if (!(len > 0)) continue;
        for (int k = 0; k < 3; k++) n[k] /= len;
        if (dot3(n, cam->fwd) >= 0) continue; /* turned away from the viewer */
        double lit = dot3(n, light), shade = 0.35 + 0.65 * (lit > 0 ? lit : 0);
        const uint8_t* rgb = film_vcol[tv[t]];
        uint8_t col[3];
        for (int j = 0; j < 3; j++) {
            double x = rgb[j] * shade + 0.5;
            col[j] = (uint8_t)(x > 255 ? 255 : x);
        }
        double s[9];
        am_camera_project(cam, a, s);
        am_camera_project(cam, b, s + 3);
        am_camera_project(cam, d, s + 6);
        am_raster_triangle(c, cam, s, col, 1);
    }
}

/* the constant external forces: an arrow from each forced voxel's centre along its force, the
 * largest force 2.5 voxel edges long, drawn over the body */
static void draw_forces(am_canvas* c, const am_camera* cam, const tool_motion* mo, int fr)
{
    double big = 0, L = am_to_si(mo->model, mo->model->L, AM_DIM_LENGTH);
    for (int i = 0; i < mo->nv; i++) {
        double F[3] = {(double)mo->force[3 * i], (double)mo->force[3 * i + 1], (double)mo->force[3 * i + 2]};
        big = fmax(big, sqrt(dot3(F, F)));
    }
    if (!(big > 0)) return;
    const float* f = mo->pose + (long)fr * mo->nv * 7;
    for (int i = 0; i < mo->nv; i++) {
        double F[3] = {(double)mo->force[3 * i], (double)mo->force[3 * i + 1], (double)mo->force[3 * i + 2]};
        double a[3] = {(double)f[7 * i], (double)f[7 * i + 1], (double)f[7 * i + 2]}, b[3], sa[3], sb[3];
        if (!(dot3(F, F) > 0)) continue;
        for (int k = 0; k < 3; k++) b[k] = a[k] + 2.5 * L * F[k] / big;
        am_camera_project(cam, a, sa);
        am_camera_project(cam, b, sb);
        am_raster_line2(c, cam, sa[0], sa[1], sb[0], sb[1], 3, tool_col_force);
        arrow_head(c, cam, sa[0], sa[1], sb[0], sb[1], 12, tool_col_force);
    }
}

/* a filled rectangle in screen pixels */
static void fill_rect(am_canvas* c, const am_camera* cam, double x0, double y0, double x1, double y1, const uint8_t rgb[3])
{
    double a[9] = {x0, y0, 0, x1, y0, 0, x1, y1, 0}, b[9] = {x0, y0, 0, x1, y1, 0, x0, y1, 0};
    am_raster_triangle(c, cam, a, rgb, 0);
    am_raster_triangle(c, cam, b, rgb, 0);
}

/* one panel: floor, grid, shadows, the centre-of-mass trail and the voxels of frame fr */
static void draw_panel(am_canvas* c, const am_camera* cam, const tool_motion* mo, int fr, int trail_from,
                       double view_w, const film_opts* o)
{
    const int boxes = o->boxes;
    voxel_colours(mo, o->colour, fr);
    const double light[3] = {-0.26, -0.43, 0.865}; /* unit: up, towards the viewer's left */
    double R = 2.5 * view_w / sin(FILM_EL) + 0.1;
    double cx = cam->target[0], cy = cam->target[1];
    /* floor: a square well past the viewport */
    double corners[4][3] = {{cx - R, cy - R, 0}, {cx + R, cy - R, 0}, {cx + R, cy + R, 0}, {cx - R, cy + R, 0}}, s[4][3];
    for (int k = 0; k < 4; k++) am_camera_project(cam, corners[k], s[k]);
    double t1[9] = {s[0][0], s[0][1], s[0][2], s[1][0], s[1][1], s[1][2], s[2][0], s[2][1], s[2][2]};
    double t2[9] = {s[0][0], s[0][1], s[0][2], s[2][0], s[2][1], s[2][2], s[3][0], s[3][1], s[3][2]};
    am_raster_triangle(c, cam, t1, col_floor, 1);
    am_raster_triangle(c, cam, t2, col_floor, 1);
    /* grid lines at a round spacing, fixed in the world so motion shows against them */
    double g = nice_step(view_w / 6);
    double bias = 1e-4 * R;
    for (double x = floor((cx - R) / g) * g; x <= cx + R; x += g) {
        double a[3] = {x, cy - R, 0}, b[3] = {x, cy + R, 0};
        am_raster_line3(c, cam, a, b, 1.0, bias, col_grid);
    }
    for (double y = floor((cy - R) / g) * g; y <= cy + R; y += g) {
        double a[3] = {cx - R, y, 0}, b[3] = {cx + R, y, 0};
        am_raster_line3(c, cam, a, b, 1.0, bias, col_grid);
    }
    /* shadows: each voxel's footprint straight below it */
    const float* f = mo->pose + (long)fr * mo->nv * 7;
    for (int i = 0; i < mo->nv; i++) {
        double h[3];
        am_mesh_half(tool_mesh(), f, i, h);
        double r = (h[0] + h[1]) * 0.5, x = (double)f[7 * i], y = (double)f[7 * i + 1];
        double q[4][3] = {{x - r, y - r, 0}, {x + r, y - r, 0}, {x + r, y + r, 0}, {x - r, y + r, 0}};
        for (int k = 0; k < 4; k++) {
            am_camera_project(cam, q[k], s[k]);
            s[k][2] -= 2 * bias;
        }
        double u1[9] = {s[0][0], s[0][1], s[0][2], s[1][0], s[1][1], s[1][2], s[2][0], s[2][1], s[2][2]};
        double u2[9] = {s[0][0], s[0][1], s[0][2], s[2][0], s[2][1], s[2][2], s[3][0], s[3][1], s[3][2]};
        am_raster_triangle(c, cam, u1, col_shadow, 1);
        am_raster_triangle(c, cam, u2, col_shadow, 1);
    }
    /* the centre of mass: a cross where it started, its path on the floor up to this frame */
    if (trail_from >= 0) {
        double c0[3], a[3], b[3];
        tool_motion_com(mo, trail_from, c0);
        double arm = view_w * 0.03;
        double p1[3] = {c0[0] - arm, c0[1], 0}, p2[3] = {c0[0] + arm, c0[1], 0};
        double p3[3] = {c0[0], c0[1] - arm, 0}, p4[3] = {c0[0], c0[1] + arm, 0};
        am_raster_line3(c, cam, p1, p2, 2.0, 3 * bias, col_start);
        am_raster_line3(c, cam, p3, p4, 2.0, 3 * bias, col_start);
        a[0] = c0[0], a[1] = c0[1], a[2] = 0;
        for (int k = trail_from + 1; k <= fr; k++) {
            double ck[3];
            tool_motion_com(mo, k, ck);
            b[0] = ck[0], b[1] = ck[1], b[2] = 0;
            am_raster_line3(c, cam, a, b, 2.5, 3 * bias, col_trail);
            memcpy(a, b, sizeof a);
        }
    }
    /* the voxels: the surface over them, or each a box */
    if (!boxes) draw_surface(c, cam, mo, fr, light);
    else
        for (int i = 0; i < mo->nv; i++) {
        double h[3], p[3] = {(double)f[7 * i], (double)f[7 * i + 1], (double)f[7 * i + 2]},
               q[4] = {(double)f[7 * i + 3], (double)f[7 * i + 4], (double)f[7 * i + 5], (double)f[7 * i + 6]};
        double qn = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (!(qn > 0.5)) q[0] = 1, q[1] = q[2] = q[3] = 0, qn = 1;
        for (int k = 0; k < 4; k++) q[k] /= qn;
        am_mesh_half(tool_mesh(), f, i, h);
        am_raster_box(c, cam, p, q, h, film_vcol[i], light, 0.35);
    }
    draw_forces(c, cam, mo, fr);
}

static int film_draw(const tool_motion* mo, const film_opts* o, am_canvas* c)
{
    int np = o->panels;
    /* frames: the first, the end of relaxation, then even steps over the movement segment */
    int frame[FILM_MAX_PANELS];
    frame[0] = 0;
    frame[1] = mo->settled_frame;
    int last = mo->frames - 1;
    for (int k = 2; k < np; k++) {
        int m = np - 2;
        frame[k] = mo->settled_frame + (int)((double)(last - mo->settled_frame) * (k - 1) / m + 0.5);
        if (frame[k] > last) frame[k] = last;
    }
    am_camera cam;
    double zero[3] = {0, 0, 0};
    am_camera_look(&cam, zero, FILM_AZ, FILM_EL, 1, 0, 0, 1, 1); /* for the view axes only */
    /* extents of each frame about its centre of mass in the view plane, and of all about the mean */
    double umin = 1e30, umax = -1e30, vmin = 1e30, vmax = -1e30;
    double gu0 = 1e30, gu1 = -1e30, gv0 = 1e30, gv1 = -1e30, mean[3] = {0, 0, 0}, com[FILM_MAX_PANELS][3];
    double pad = 0.9 * am_to_si(mo->model, mo->model->L, AM_DIM_LENGTH);
    for (int k = 0; k < np; k++) {
        tool_motion_com(mo, frame[k], com[k]);
        for (int j = 0; j < 3; j++) mean[j] += com[k][j] / np;
    }
    for (int k = 0; k < np; k++) {
        const float* f = mo->pose + (long)frame[k] * mo->nv * 7;
        for (int i = 0; i < mo->nv; i++) {
            double p[3] = {(double)f[7 * i], (double)f[7 * i + 1], (double)f[7 * i + 2]};
            double d[3] = {p[0] - com[k][0], p[1] - com[k][1], p[2] - com[k][2]};
            double e[3] = {p[0] - mean[0], p[1] - mean[1], p[2] - mean[2]};
            double u = dot3(d, cam.right), v = dot3(d, cam.up), gu = dot3(e, cam.right), gv = dot3(e, cam.up);
            umin = fmin(umin, u - pad), umax = fmax(umax, u + pad), vmin = fmin(vmin, v - pad), vmax = fmax(vmax, v + pad);
            gu0 = fmin(gu0, gu - pad), gu1 = fmax(gu1, gu + pad), gv0 = fmin(gv0, gv - pad), gv1 = fmax(gv1, gv + pad);
        }
    }
    /* one fixed centre when the whole motion fits in not much more room than the body, so the
     * panels show the real displacement; else each panel follows its centre of mass */
    int fixed = (gu1 - gu0) <= 1.6 * (umax - umin) && (gv1 - gv0) <= 1.6 * (vmax - vmin);
    if (fixed) umin = gu0, umax = gu1, vmin = gv0, vmax = gv1;
    int cap_h = 44, label_h = 26;
    int pw = o->width / np, ph = o->height - cap_h - label_h;
    double scale = fmin((pw - 16) / (umax - umin), (ph - 12) / (vmax - vmin));
    double view_w = (pw) / scale;

    static const uint8_t white[3] = {255, 255, 255};
    am_canvas_clear(c, white);
    am_camera whole;
    am_camera_look(&whole, zero, 0, 0, 1, 0, 0, c->w, c->h);
    char text[160], len[64];
    for (int k = 0; k < np; k++) {
        double target[3];
        const double* base = fixed ? mean : com[k];
        double um = 0.5 * (umin + umax), vm = 0.5 * (vmin + vmax);
        for (int j = 0; j < 3; j++) target[j] = base[j] + um * cam.right[j] + vm * cam.up[j];
        am_camera panel;
        am_camera_look(&panel, target, FILM_AZ, FILM_EL, ph / scale, k * pw, label_h, pw, ph);
        draw_panel(c, &panel, mo, frame[k], k >= 2 ? frame[1] : -1, view_w, o);
        double t = (double)mo->step[frame[k]] * mo->dt;
        char tt[48];
        fmt_time(tt, sizeof tt, t);
        /* the label fits its panel whole, units included: the big font, else the small one, else
         * without the word "settled" */
        if (k == 0) snprintf(text, sizeof text, "1 initial");
        else if (k == 1) snprintf(text, sizeof text, "2 settled t=%s", tt);
        else snprintf(text, sizeof text, "%d t=%s", k + 1, tt);
        int fs = 2, room = pw - 16;
        if ((int)strlen(text) * 12 > room) fs = 1;
        if (fs == 1 && (int)strlen(text) * 6 > room && k == 1) snprintf(text, sizeof text, "2 t=%s", tt);
        am_camera label;
        am_camera_look(&label, zero, 0, 0, 1, k * pw, 0, pw - 4, label_h);
        am_raster_text(c, &label, k * pw + 8, fs == 2 ? 6 : 9, fs, text, col_text);
        if (k > 0) am_raster_line2(c, &whole, k * pw, 0, k * pw, o->height - cap_h, 2, col_rule);
    }
    /* caption: direction of travel, distance, materials */
    int y0 = o->height - cap_h;
    am_raster_line2(c, &whole, 0, y0, np * pw, y0, 2, col_rule);
    double cs[3], ce[3];
    tool_motion_com(mo, frame[1], cs);
    tool_motion_com(mo, frame[np - 1], ce);
    double d[3] = {ce[0] - cs[0], ce[1] - cs[1], 0};
    double dist = sqrt(d[0] * d[0] + d[1] * d[1]);
    int ym = y0 + cap_h / 2;
    double su = dot3(d, cam.right), sv = -dot3(d, cam.up), sl = sqrt(su * su + sv * sv);
    if (dist > 1e-9 && sl > 1e-12) {
        double ax = 34 + 26 * su / sl, ay = ym + 14 * sv / sl, bx = 34 - 26 * su / sl, by = ym - 14 * sv / sl;
        am_raster_line2(c, &whole, bx, by, ax, ay, 4, col_trail);
        arrow_head(c, &whole, bx, by, ax, ay, 16, col_trail);
    }
    int x = 72;
    fmt_len(len, sizeof len, dist);
    char tt[48];
    fmt_time(tt, sizeof tt, (double)(mo->step[frame[np - 1]] - mo->step[frame[1]]) * mo->dt);
    snprintf(text, sizeof text, "direction of travel: %s in %s%s", len, tt, mo->res.diverged ? "  (diverged)" : "");
    x += am_raster_text(c, &whole, x, ym - 7, 2, text, col_text) + 24;
    /* legend: the materials the robot uses, or the scalar's scale from its minimum to its maximum */
    const am_model* m = mo->model;
    if (o->colour == TOOL_COL_MATERIAL)
        for (int k = 0; k < m->palette.count; k++) {
            int used = 0;
            for (int i = 0; i < m->nv && !used; i++) used = m->mat[i] == k && !mo->fixed[i];
            if (!used) continue;
            fill_rect(c, &whole, x, ym - 7, x + 14, ym + 7, m->palette.mat[k].color);
            x += 20;
            x += am_raster_text(c, &whole, x, ym - 7, 2, m->palette.mat[k].name, col_text) + 16;
        }
    else {
        double per;
        const char* unit = tool_colour_unit(o->colour, &per);
        snprintf(text, sizeof text, "%s %.3g", tool_colour_name(o->colour), film_lo * per);
        x += am_raster_text(c, &whole, x, ym - 7, 2, text, col_text) + 8;
        for (int k = 0; k < 120; k++) {
            uint8_t rgb[3];
            tool_colour_ramp(o->colour, k / 119.0, rgb);
            fill_rect(c, &whole, x + k, ym - 7, x + k + 1, ym + 7, rgb);
        }
        x += 128;
        snprintf(text, sizeof text, "%.3g %s", film_hi * per, unit);
        x += am_raster_text(c, &whole, x, ym - 7, 2, text, col_text) + 16;
    }
    /* the boundary conditions: clamped voxels, forces */
    if (mo->nfixed > 0) {
        fill_rect(c, &whole, x, ym - 7, x + 14, ym + 7, tool_col_clamp);
        x += 20;
        x += am_raster_text(c, &whole, x, ym - 7, 2, "clamped", col_text) + 16;
    }
    if (mo->nforced > 0) {
        am_raster_line2(c, &whole, x, ym, x + 16, ym, 3, tool_col_force);
        arrow_head(c, &whole, x, ym, x + 20, ym, 12, tool_col_force);
        x += 28;
        x += am_raster_text(c, &whole, x, ym - 7, 2, "force", col_text) + 16;
    }
    /* a scale bar at the right end: the round length of 80 to 200 pixels, true along the screen's
     * horizontal (every picture has this one scale) */
    double bar = nice_step(80 / scale), bpx = bar * scale;
    char blen[64];
    fmt_len(blen, sizeof blen, bar);
    int bx1 = np * pw - 16, bx0 = (int)(bx1 - bpx + 0.5);
    int tw = (int)strlen(blen) * 12;
    if (bx0 - tw - 8 > x) {
        am_raster_text(c, &whole, bx0 - tw - 8, ym - 7, 2, blen, col_text);
        fill_rect(c, &whole, bx0, ym - 2, bx1, ym + 2, col_text);
        fill_rect(c, &whole, bx0, ym - 7, bx0 + 2, ym + 7, col_text);
        fill_rect(c, &whole, bx1 - 2, ym - 7, bx1, ym + 7, col_text);
    }
    return 0;
}

film_opts film_defaults(void)
{
    film_opts o = {6, 1600, 400, 0, TOOL_COL_MATERIAL, 0};
    return o;
}

static uint32_t film_be32(const uint8_t* p) { return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3]; }

/* whether the file at path is a sound PNG of exactly film_rgb's w x h pixels (8-bit RGB, every
 * chunk's CRC right, the zlib stream whole, every row unfiltered), whatever its deflate blocks:
 * render --keep-same leaves such a file as it is. Read into film_png and inflated into the depth
 * buffer, both free once the picture is drawn. Anything else (no file, another size, a filter,
 * a bad CRC) is not the same. */
static int film_same_pixels(const char* path, int w, int h)
{
    static am_inflate_work iw;
    char err[AM_ERR_MAX];
    long n = 0, pos = 8, z = 0, got = 0;
    uint8_t* f = film_png;
    static const uint8_t sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    if (am_port_read_file(path, (char*)f, (long)sizeof film_png, &n, err, sizeof err) != AM_OK || n < 8 || memcmp(f, sig, 8)) return 0;
    int header = 0, end = 0;
    while (!end && pos + 12 <= n) {
        const uint32_t len = film_be32(f + pos);
        if (len > (uint32_t)(n - pos - 12)) return 0;
        const uint8_t* type = f + pos + 4;
        if (am_crc32(0, type, (long)len + 4) != film_be32(type + 4 + len)) return 0;
        if (!memcmp(type, "IHDR", 4))
            header = len == 13 && film_be32(type + 4) == (uint32_t)w && film_be32(type + 8) == (uint32_t)h &&
                     !memcmp(type + 12, "\x08\x02\x00\x00\x00", 5);
        else if (!memcmp(type, "IDAT", 4)) {
            memmove(f + z, type + 4, len); /* the stream gathered at the front (z <= pos) */
            z += len;
        } else if (!memcmp(type, "IEND", 4)) end = 1;
        pos += 12 + (long)len;
    }
    if (!header || !end) return 0;
    uint8_t* raw = (uint8_t*)film_depth;
    const long row = 1 + 3L * w;
    if (am_zlib_inflate(f, z, raw, (long)sizeof film_depth, &got, &iw, err, sizeof err) != AM_OK || got != row * h) return 0;
    for (long y = 0; y < h; y++)
        if (raw[y * row] != 0 || memcmp(raw + y * row + 1, film_rgb + y * (row - 1), (size_t)(row - 1))) return 0;
    return 1;
}

int film_write(tool_ctx* c, const am_robot* r, const film_opts* o, const char* what, const char* path)
{
    static tool_motion mo;
    const am_lattice* lat = r->lattice;
    int rc = tool_record_motion(c, r, 400, &mo, what);
    if (rc) return rc;
    char err[AM_ERR_MAX];
    /* the body's mesh: its surface, and each voxel's half size for the boxes and the shadows */
    if (am_mesh_build(tool_mesh(), lat, AM_MESH_BODY, err, sizeof err) != AM_OK)
        return tool_usage_error("%s: %s", what, err);
    film_lo = 0, film_hi = 1;
    if (o->colour != TOOL_COL_MATERIAL) tool_colour_range(&mo, o->colour, &film_lo, &film_hi);
    am_canvas cv = {o->width, o->height, film_rgb, film_depth};
    film_draw(&mo, o, &cv);
    if (o->keep_same && film_same_pixels(path, o->width, o->height)) return 0;
    long n = 0;
    if (am_png_encode(film_rgb, o->width, o->height, 3, AM_PNG_DYNAMIC, film_png, (long)sizeof film_png, &n, err,
                      sizeof err) != AM_OK) {
        fprintf(stderr, "amorph: %s: %s\n", path, err);
        return 1;
    }
    if (am_port_write_file(path, film_png, n, err, sizeof err) != AM_OK) {
        fprintf(stderr, "amorph: %s\n", err);
        return 1;
    }
    return 0;
}

int tool_write_filmstrip(tool_ctx* c, const am_robot* r, const char* path)
{
    film_opts o = film_defaults();
    return film_write(c, r, &o, path, path) ? 1 : 0;
}

#else
typedef int tool_film_not_built; /* board profile: tools/picture.c has the stand-ins */
#endif
