/* tests/test_io_raster.c: the rasteriser (src/io/io_raster.c) on single triangles (exact coverage
 * of a square split in two, depth order, viewport clipping), cubes (the top face seen from straight
 * above, a turned cube, the shading of a side face) and text. */
#include "amorph.h"
#include "harness.h"

#include <stdint.h>

#define RW 120
#define RH 100
static uint8_t r_rgb[RW * RH * 3];
static float r_depth[RW * RH];

static int px_is(const am_canvas* c, int x, int y, const uint8_t rgb[3])
{
    const uint8_t* p = c->rgb + 3 * ((long)y * c->w + x);
    return p[0] == rgb[0] && p[1] == rgb[1] && p[2] == rgb[2];
}

static long count_colour(const am_canvas* c, const uint8_t rgb[3])
{
    long n = 0;
    for (int y = 0; y < c->h; y++)
        for (int x = 0; x < c->w; x++) n += px_is(c, x, y, rgb);
    return n;
}

static void test_raster_triangles(void)
{
    am_canvas c = {RW, RH, r_rgb, r_depth};
    const uint8_t bg[3] = {255, 255, 255}, red[3] = {255, 0, 0}, blue[3] = {0, 0, 255};
    am_canvas_clear(&c, bg);
    am_camera cam;
    double o[3] = {0, 0, 0};
    am_camera_look(&cam, o, 0, 0, 1, 0, 0, RW, RH);
    /* two triangles sharing a diagonal cover the 40 x 30 square exactly: no gap, nothing outside */
    double t1[9] = {10, 10, 1, 50, 10, 1, 50, 40, 1}, t2[9] = {10, 10, 1, 50, 40, 1, 10, 40, 1};
    am_raster_triangle(&c, &cam, t1, red, 1);
    am_raster_triangle(&c, &cam, t2, red, 1);
    CHECK(count_colour(&c, red) == 40 * 30, "square covers %ld pixels, want 1200", count_colour(&c, red));
    CHECK(px_is(&c, 10, 10, red) && px_is(&c, 49, 39, red) && px_is(&c, 9, 10, bg) && px_is(&c, 50, 39, bg),
          "square edges");
    /* a nearer triangle wins, a farther one does not */
    double near[9] = {20, 20, 0.5, 60, 20, 0.5, 20, 60, 0.5}, far[9] = {0, 0, 2, 119, 0, 2, 0, 99, 2};
    am_raster_triangle(&c, &cam, near, blue, 1);
    am_raster_triangle(&c, &cam, far, bg, 1);
    CHECK(px_is(&c, 25, 25, blue), "nearer triangle drawn over the square");
    CHECK(px_is(&c, 45, 12, red), "square kept where the farther triangle overlaps it");
    /* the viewport clips */
    am_camera half;
    am_camera_look(&half, o, 0, 0, 1, 0, 0, 60, RH);
    am_canvas_clear(&c, bg);
    double wide[9] = {0, 0, 0, 119, 0, 0, 0, 99, 0};
    am_raster_triangle(&c, &half, wide, red, 0);
    CHECK(px_is(&c, 5, 5, red) && px_is(&c, 70, 5, bg), "drawing stays in the viewport");
}

static void test_raster_cube(void)
{
    am_canvas c = {RW, RH, r_rgb, r_depth};
    const uint8_t bg[3] = {255, 255, 255}, col[3] = {40, 90, 220};
    const double light_top[3] = {0, 0, 1}, q[4] = {1, 0, 0, 0}, half[3] = {0.5, 0.5, 0.5};
    am_camera cam;
    double o[3] = {0, 0, 0};
    /* straight down (elevation 90 degrees), 4 m over the 100-pixel height: 25 px per metre, so
     * the unit cube's top face is the 25 x 25 square centred on (60, 50), lit fully */
    am_canvas_clear(&c, bg);
    am_camera_look(&cam, o, 0, 1.5707963267948966, 4.0, 0, 0, RW, RH);
    am_raster_box(&c, &cam, o, q, half, col, light_top, 0.3);
    long n = count_colour(&c, col);
    CHECK(n == 25 * 25, "top face covers %ld pixels, want 625", n);
    /* x from 47.5 to 72.5, y from 37.5 to 62.5: the top-left rule takes the centres on the left
     * and top edges, so pixels 47..71 x 37..61 */
    CHECK(px_is(&c, 60, 50, col) && px_is(&c, 47, 37, col) && px_is(&c, 71, 61, col), "inside the top face");
    CHECK(px_is(&c, 46, 50, bg) && px_is(&c, 72, 50, bg) && px_is(&c, 60, 36, bg) && px_is(&c, 60, 62, bg),
          "outside the top face");
    NEAR(c.depth[50 * RW + 60], -0.5, 1e-5); /* the top face is 0.5 m nearer than the target */
    /* turned 45 degrees about z: a diamond, its corners at 25/sqrt(2) = 17.7 px along the axes */
    am_canvas_clear(&c, bg);
    double q45[4] = {cos(0.39269908169872414), 0, 0, sin(0.39269908169872414)};
    am_raster_box(&c, &cam, o, q45, half, col, light_top, 0.3);
    CHECK(px_is(&c, 60 + 16, 50, col) && px_is(&c, 60, 50 - 16, col), "diamond tips inside");
    CHECK(px_is(&c, 60 + 11, 50 - 11, bg) && px_is(&c, 60 - 11, 50 + 11, bg), "diamond sides outside: a turned cube");
    /* oblique view, light from the top: three faces, the top one brightest, the others darker shades */
    am_canvas_clear(&c, bg);
    am_camera_look(&cam, o, -0.6, 0.5, 3.0, 0, 0, RW, RH);
    am_raster_box(&c, &cam, o, q, half, col, light_top, 0.3);
    double top[3] = {0, 0, 0.5}, side[3] = {0, -0.5, 0}, s[3];
    am_camera_project(&cam, top, s);
    CHECK(px_is(&c, (int)s[0], (int)s[1], col), "top face centre in the full colour");
    am_camera_project(&cam, side, s);
    const uint8_t* p = c.rgb + 3 * ((long)(int)s[1] * RW + (int)s[0]);
    CHECK(p[0] == 12 && p[1] == 27 && p[2] == 66, "side face at the ambient 0.3: %d %d %d", p[0], p[1], p[2]);
    CHECK(px_is(&c, 2, 2, bg) && px_is(&c, RW - 3, RH - 3, bg), "corners stay background");
}

static void test_raster_text(void)
{
    am_canvas c = {RW, RH, r_rgb, r_depth};
    const uint8_t bg[3] = {255, 255, 255}, ink[3] = {0, 0, 0};
    am_canvas_clear(&c, bg);
    am_camera cam;
    double o[3] = {0, 0, 0};
    am_camera_look(&cam, o, 0, 0, 1, 0, 0, RW, RH);
    int w = am_raster_text(&c, &cam, 10, 10, 1, "I", ink);
    CHECK(w == 6, "advance %d", w);
    /* the I of the font: a full column of 7 pixels at x = 12 and bars at the top and bottom */
    CHECK(count_colour(&c, ink) == 7 + 4, "I has %ld pixels", count_colour(&c, ink));
    CHECK(px_is(&c, 12, 10, ink) && px_is(&c, 12, 16, ink) && px_is(&c, 11, 10, ink) && px_is(&c, 11, 13, bg), "I shape");
    am_canvas_clear(&c, bg);
    am_raster_text(&c, &cam, RW - 8, 10, 3, "WW", ink); /* mostly outside: clipped, no crash */
    CHECK(count_colour(&c, ink) > 0 && count_colour(&c, ink) < 35 * 9, "clipped text %ld", count_colour(&c, ink));
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    (void)test_quick; /* the harness's, unused here */
    RUN(test_raster_triangles);
    RUN(test_raster_cube);
    RUN(test_raster_text);
    return SUMMARY();
}
