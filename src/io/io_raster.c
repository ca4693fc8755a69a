/* A small software rasteriser for pictures of robots (docs/pictures.md).
 *
 * Orthographic camera, so a triangle's depth is linear in screen space and nothing needs near-plane
 * clipping. Triangles are filled by edge functions over their bounding box clipped to the camera's
 * viewport, sampling pixel centres with the top-left rule for centres on an edge. Depth
 * is the distance along the view direction (smaller is nearer), compared strictly, so of two
 * surfaces at one depth the first drawn stays. Lines are thin quads; text is a 5 x 7 bitmap font. */
#include "amorph/io.h"

#include <math.h>
#include <string.h>

void am_canvas_clear(am_canvas* c, const uint8_t rgb[3])
{
    long n = (long)c->w * c->h;
    for (long i = 0; i < n; i++) {
        c->rgb[3 * i] = rgb[0];
        c->rgb[3 * i + 1] = rgb[1];
        c->rgb[3 * i + 2] = rgb[2];
        c->depth[i] = 3.0e38f;
    }
}

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

void am_camera_look(am_camera* cam, const double target[3], double az, double el, double view_h, int vx, int vy,
                    int vw, int vh)
{
    double ca = cos(az), sa = sin(az), ce = cos(el), se = sin(el);
    for (int k = 0; k < 3; k++) cam->target[k] = target[k];
    cam->fwd[0] = -sa * ce, cam->fwd[1] = ca * ce, cam->fwd[2] = -se;
    cam->right[0] = ca, cam->right[1] = sa, cam->right[2] = 0;
    /* up = right x fwd */
    cam->up[0] = cam->right[1] * cam->fwd[2] - cam->right[2] * cam->fwd[1];
    cam->up[1] = cam->right[2] * cam->fwd[0] - cam->right[0] * cam->fwd[2];
    cam->up[2] = cam->right[0] * cam->fwd[1] - cam->right[1] * cam->fwd[0];
    cam->scale = view_h > 0 ? vh / view_h : 1.0;
    cam->vx = vx, cam->vy = vy, cam->vw = vw, cam->vh = vh;
}

void am_camera_project(const am_camera* cam, const double p[3], double out[3])
{
    double d[3] = {p[0] - cam->target[0], p[1] - cam->target[1], p[2] - cam->target[2]};
    out[0] = cam->vx + 0.5 * cam->vw + cam->scale * dot3(d, cam->right);
    out[1] = cam->vy + 0.5 * cam->vh - cam->scale * dot3(d, cam->up);
    out[2] = dot3(d, cam->fwd);
}

void am_raster_triangle(am_canvas* c, const am_camera* cam, const double v[9], const uint8_t rgb[3], int depth_test)
{
    const double s[3][3] = {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]}};
    double area = (s[1][0] - s[0][0]) * (s[2][1] - s[0][1]) - (s[2][0] - s[0][0]) * (s[1][1] - s[0][1]);
    if (!(fabs(area) > 1e-12)) return; /* degenerate (or NaN) */
    /* viewport clipped to the canvas */
    int x0 = cam->vx < 0 ? 0 : cam->vx, y0 = cam->vy < 0 ? 0 : cam->vy;
    int x1 = cam->vx + cam->vw > c->w ? c->w : cam->vx + cam->vw;
    int y1 = cam->vy + cam->vh > c->h ? c->h : cam->vy + cam->vh;
    double minx = fmin(s[0][0], fmin(s[1][0], s[2][0])), maxx = fmax(s[0][0], fmax(s[1][0], s[2][0]));
    double miny = fmin(s[0][1], fmin(s[1][1], s[2][1])), maxy = fmax(s[0][1], fmax(s[1][1], s[2][1]));
    if (maxx < x0 || minx > x1 || maxy < y0 || miny > y1) return;
    int ix0 = minx > x0 ? (int)floor(minx) : x0, ix1 = maxx < x1 - 1 ? (int)ceil(maxx) : x1 - 1;
    int iy0 = miny > y0 ? (int)floor(miny) : y0, iy1 = maxy < y1 - 1 ? (int)ceil(maxy) : y1 - 1;
    double sg = area > 0 ? 1.0 : -1.0, inv = 1.0 / area;
    /* the top-left rule: a pixel centre exactly on an edge belongs to the triangle only when the
     * edge is a left edge (inside to its right) or a top edge (horizontal, inside below), so
     * triangles sharing an edge never both draw it */
    int tl[3];
    for (int e = 0; e < 3; e++) {
        const double* a = s[(e + 1) % 3];
        const double* b = s[(e + 2) % 3];
        double gx = sg * (a[1] - b[1]), gy = sg * (b[0] - a[0]);
        tl[e] = gx > 0 || (gx == 0 && gy > 0);
    }
    for (int y = iy0; y <= iy1; y++) {
        double py = y + 0.5;
        for (int x = ix0; x <= ix1; x++) {
            double px = x + 0.5;
            /* edge values, positive inside; over the area they are the barycentric weights */
            double e0 = sg * ((s[1][0] - px) * (s[2][1] - py) - (s[2][0] - px) * (s[1][1] - py));
            double e1 = sg * ((s[2][0] - px) * (s[0][1] - py) - (s[0][0] - px) * (s[2][1] - py));
            double e2 = sg * ((s[0][0] - px) * (s[1][1] - py) - (s[1][0] - px) * (s[0][1] - py));
            if (e0 < 0 || e1 < 0 || e2 < 0 || (e0 == 0 && !tl[0]) || (e1 == 0 && !tl[1]) || (e2 == 0 && !tl[2])) continue;
            double w0 = e0 * sg * inv, w1 = e1 * sg * inv, w2 = 1.0 - w0 - w1;
            long i = (long)y * c->w + x;
            if (depth_test) {
                float z = (float)(w0 * s[0][2] + w1 * s[1][2] + w2 * s[2][2]);
                if (!(z < c->depth[i])) continue;
                c->depth[i] = z;
            }
            c->rgb[3 * i] = rgb[0];
            c->rgb[3 * i + 1] = rgb[1];
            c->rgb[3 * i + 2] = rgb[2];
        }
    }
}

/* a quad of two triangles from four screen points (in order around it) */
static void quad(am_canvas* c, const am_camera* cam, double p[4][3], const uint8_t rgb[3], int depth_test)
{
    double t1[9], t2[9];
    for (int k = 0; k < 3; k++) {
        t1[k] = p[0][k], t1[3 + k] = p[1][k], t1[6 + k] = p[2][k];
        t2[k] = p[0][k], t2[3 + k] = p[2][k], t2[6 + k] = p[3][k];
    }
    am_raster_triangle(c, cam, t1, rgb, depth_test);
    am_raster_triangle(c, cam, t2, rgb, depth_test);
}

/* a screen-space segment as a quad of the given width; depths za, zb at the ends */
static void thick(am_canvas* c, const am_camera* cam, double x0, double y0, double za, double x1, double y1,
                  double zb, double width, const uint8_t rgb[3], int depth_test)
{
    double dx = x1 - x0, dy = y1 - y0, len = sqrt(dx * dx + dy * dy);
    if (!(len > 1e-9)) return;
    double nx = -dy / len * 0.5 * width, ny = dx / len * 0.5 * width;
    double ex = dx / len * 0.5 * width * 0.5, ey = dy / len * 0.5 * width * 0.5; /* small end caps */
    double p[4][3] = {{x0 + nx - ex, y0 + ny - ey, za}, {x1 + nx + ex, y1 + ny + ey, zb},
                      {x1 - nx + ex, y1 - ny + ey, zb}, {x0 - nx - ex, y0 - ny - ey, za}};
    quad(c, cam, p, rgb, depth_test);
}

void am_raster_line3(am_canvas* c, const am_camera* cam, const double a[3], const double b[3], double width,
                     double bias, const uint8_t rgb[3])
{
    double pa[3], pb[3];
    am_camera_project(cam, a, pa);
    am_camera_project(cam, b, pb);
    thick(c, cam, pa[0], pa[1], pa[2] - bias, pb[0], pb[1], pb[2] - bias, width, rgb, 1);
}

void am_raster_line2(am_canvas* c, const am_camera* cam, double x0, double y0, double x1, double y1, double width,
                     const uint8_t rgb[3])
{
    thick(c, cam, x0, y0, 0, x1, y1, 0, width, rgb, 0);
}

/* v rotated by the unit quaternion q = (w, x, y, z): v + 2w (u x v) + 2 u x (u x v) */
void am_quat_rotate(const double q[4], const double v[3], double out[3])
{
    double u[3] = {q[1], q[2], q[3]};
    double t[3] = {2 * (u[1] * v[2] - u[2] * v[1]), 2 * (u[2] * v[0] - u[0] * v[2]), 2 * (u[0] * v[1] - u[1] * v[0])};
    out[0] = v[0] + q[0] * t[0] + (u[1] * t[2] - u[2] * t[1]);
    out[1] = v[1] + q[0] * t[1] + (u[2] * t[0] - u[0] * t[2]);
    out[2] = v[2] + q[0] * t[2] + (u[0] * t[1] - u[1] * t[0]);
}

void am_raster_box(am_canvas* c, const am_camera* cam, const double centre[3], const double q[4],
                   const double half[3], const uint8_t rgb[3], const double light[3], double ambient)
{
    /* corner k has sign bits x = k & 1, y = k & 2, z = k & 4 */
    double sc[8][3];
    for (int k = 0; k < 8; k++) {
        double v[3] = {(k & 1 ? 1 : -1) * half[0], (k & 2 ? 1 : -1) * half[1], (k & 4 ? 1 : -1) * half[2]}, w[3];
        am_quat_rotate(q, v, w);
        double p[3] = {centre[0] + w[0], centre[1] + w[1], centre[2] + w[2]};
        am_camera_project(cam, p, sc[k]);
    }
    /* faces -x, +x, -y, +y, -z, +z as corner loops */
    static const int face[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (int f = 0; f < 6; f++) {
        double axis[3] = {0, 0, 0}, n[3];
        axis[f / 2] = f & 1 ? 1 : -1;
        am_quat_rotate(q, axis, n);
        if (dot3(n, cam->fwd) >= 0) continue; /* faces away from the viewer */
        double lit = dot3(n, light);
        double k = ambient + (1 - ambient) * (lit > 0 ? lit : 0);
        uint8_t col[3];
        for (int j = 0; j < 3; j++) {
            double v = rgb[j] * k + 0.5;
            col[j] = (uint8_t)(v > 255 ? 255 : v);
        }
        double p[4][3];
        for (int j = 0; j < 4; j++) memcpy(p[j], sc[face[f][j]], sizeof p[j]);
        quad(c, cam, p, col, 1);
    }
}

/* the 5 x 7 font, ASCII 32..126: five columns per glyph, bit 0 the top row */
static const uint8_t font5x7[95][5] = {
    {0x00, 0x00, 0x00, 0x00, 0x00}, {0x00, 0x00, 0x5F, 0x00, 0x00}, {0x00, 0x07, 0x00, 0x07, 0x00},
    {0x14, 0x7F, 0x14, 0x7F, 0x14}, {0x24, 0x2A, 0x7F, 0x2A, 0x12}, {0x23, 0x13, 0x08, 0x64, 0x62},
    {0x36, 0x49, 0x55, 0x22, 0x50}, {0x00, 0x05, 0x03, 0x00, 0x00}, {0x00, 0x1C, 0x22, 0x41, 0x00},
    {0x00, 0x41, 0x22, 0x1C, 0x00}, {0x14, 0x08, 0x3E, 0x08, 0x14}, {0x08, 0x08, 0x3E, 0x08, 0x08},
    {0x00, 0x50, 0x30, 0x00, 0x00}, {0x08, 0x08, 0x08, 0x08, 0x08}, {0x00, 0x60, 0x60, 0x00, 0x00},
    {0x20, 0x10, 0x08, 0x04, 0x02}, {0x3E, 0x51, 0x49, 0x45, 0x3E}, {0x00, 0x42, 0x7F, 0x40, 0x00},
    {0x42, 0x61, 0x51, 0x49, 0x46}, {0x21, 0x41, 0x45, 0x4B, 0x31}, {0x18, 0x14, 0x12, 0x7F, 0x10},
    {0x27, 0x45, 0x45, 0x45, 0x39}, {0x3C, 0x4A, 0x49, 0x49, 0x30}, {0x01, 0x71, 0x09, 0x05, 0x03},
    {0x36, 0x49, 0x49, 0x49, 0x36}, {0x06, 0x49, 0x49, 0x29, 0x1E}, {0x00, 0x36, 0x36, 0x00, 0x00},
    {0x00, 0x56, 0x36, 0x00, 0x00}, {0x08, 0x14, 0x22, 0x41, 0x00}, {0x14, 0x14, 0x14, 0x14, 0x14},
    {0x00, 0x41, 0x22, 0x14, 0x08}, {0x02, 0x01, 0x51, 0x09, 0x06}, {0x32, 0x49, 0x79, 0x41, 0x3E},
    {0x7E, 0x11, 0x11, 0x11, 0x7E}, {0x7F, 0x49, 0x49, 0x49, 0x36}, {0x3E, 0x41, 0x41, 0x41, 0x22},
    {0x7F, 0x41, 0x41, 0x22, 0x1C}, {0x7F, 0x49, 0x49, 0x49, 0x41}, {0x7F, 0x09, 0x09, 0x09, 0x01},
    {0x3E, 0x41, 0x49, 0x49, 0x7A}, {0x7F, 0x08, 0x08, 0x08, 0x7F}, {0x00, 0x41, 0x7F, 0x41, 0x00},
    {0x20, 0x40, 0x41, 0x3F, 0x01}, {0x7F, 0x08, 0x14, 0x22, 0x41}, {0x7F, 0x40, 0x40, 0x40, 0x40},
    {0x7F, 0x02, 0x0C, 0x02, 0x7F}, {0x7F, 0x04, 0x08, 0x10, 0x7F}, {0x3E, 0x41, 0x41, 0x41, 0x3E},
    {0x7F, 0x09, 0x09, 0x09, 0x06}, {0x3E, 0x41, 0x51, 0x21, 0x5E}, {0x7F, 0x09, 0x19, 0x29, 0x46},
    {0x46, 0x49, 0x49, 0x49, 0x31}, {0x01, 0x01, 0x7F, 0x01, 0x01}, {0x3F, 0x40, 0x40, 0x40, 0x3F},
    {0x1F, 0x20, 0x40, 0x20, 0x1F}, {0x3F, 0x40, 0x38, 0x40, 0x3F}, {0x63, 0x14, 0x08, 0x14, 0x63},
    {0x07, 0x08, 0x70, 0x08, 0x07}, {0x61, 0x51, 0x49, 0x45, 0x43}, {0x00, 0x7F, 0x41, 0x41, 0x00},
    {0x02, 0x04, 0x08, 0x10, 0x20}, {0x00, 0x41, 0x41, 0x7F, 0x00}, {0x04, 0x02, 0x01, 0x02, 0x04},
    {0x40, 0x40, 0x40, 0x40, 0x40}, {0x00, 0x01, 0x02, 0x04, 0x00}, {0x20, 0x54, 0x54, 0x54, 0x78},
    {0x7F, 0x48, 0x44, 0x44, 0x38}, {0x38, 0x44, 0x44, 0x44, 0x20}, {0x38, 0x44, 0x44, 0x48, 0x7F},
    {0x38, 0x54, 0x54, 0x54, 0x18}, {0x08, 0x7E, 0x09, 0x01, 0x02}, {0x0C, 0x52, 0x52, 0x52, 0x3E},
    {0x7F, 0x08, 0x04, 0x04, 0x78}, {0x00, 0x44, 0x7D, 0x40, 0x00}, {0x20, 0x40, 0x44, 0x3D, 0x00},
    {0x7F, 0x10, 0x28, 0x44, 0x00}, {0x00, 0x41, 0x7F, 0x40, 0x00}, {0x7C, 0x04, 0x18, 0x04, 0x78},
    {0x7C, 0x08, 0x04, 0x04, 0x78}, {0x38, 0x44, 0x44, 0x44, 0x38}, {0x7C, 0x14, 0x14, 0x14, 0x08},
    {0x08, 0x14, 0x14, 0x18, 0x7C}, {0x7C, 0x08, 0x04, 0x04, 0x08}, {0x48, 0x54, 0x54, 0x54, 0x20},
    {0x04, 0x3F, 0x44, 0x40, 0x20}, {0x3C, 0x40, 0x40, 0x20, 0x7C}, {0x1C, 0x20, 0x40, 0x20, 0x1C},
    {0x3C, 0x40, 0x30, 0x40, 0x3C}, {0x44, 0x28, 0x10, 0x28, 0x44}, {0x0C, 0x50, 0x50, 0x50, 0x3C},
    {0x44, 0x64, 0x54, 0x4C, 0x44}, {0x00, 0x08, 0x36, 0x41, 0x00}, {0x00, 0x00, 0x7F, 0x00, 0x00},
    {0x00, 0x41, 0x36, 0x08, 0x00}, {0x08, 0x04, 0x08, 0x10, 0x08}};

int am_raster_text(am_canvas* c, const am_camera* cam, int x, int y, int scale, const char* text, const uint8_t rgb[3])
{
    int x0 = cam->vx < 0 ? 0 : cam->vx, y0 = cam->vy < 0 ? 0 : cam->vy;
    int x1 = cam->vx + cam->vw > c->w ? c->w : cam->vx + cam->vw;
    int y1 = cam->vy + cam->vh > c->h ? c->h : cam->vy + cam->vh;
    if (scale < 1) scale = 1;
    int cx = x;
    for (const char* t = text; *t; t++, cx += 6 * scale) {
        int ch = (unsigned char)*t;
        if (ch < 32 || ch > 126) ch = '?';
        for (int col = 0; col < 5; col++)
            for (int row = 0; row < 7; row++) {
                if (!(font5x7[ch - 32][col] >> row & 1)) continue;
                for (int dy = 0; dy < scale; dy++)
                    for (int dx = 0; dx < scale; dx++) {
                        int px = cx + col * scale + dx, py = y + row * scale + dy;
                        if (px < x0 || px >= x1 || py < y0 || py >= y1) continue;
                        long i = (long)py * c->w + px;
                        c->rgb[3 * i] = rgb[0];
                        c->rgb[3 * i + 1] = rgb[1];
                        c->rgb[3 * i + 2] = rgb[2];
                    }
            }
    }
    return cx - x;
}
