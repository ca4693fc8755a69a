/* amorph/image.h: pictures without a library: checksums, a PNG encoder and a small software
 * rasteriser (docs/pictures.md).
 *
 * Everything works on caller buffers and allocates nothing. The PNG encoder writes 8-bit RGB or
 * RGBA images with one zlib stream in either stored blocks or one fixed-Huffman deflate block
 * (greedy matches at the pixel and row distances, which is what flat synthetic pictures need).
 * The rasteriser draws z-buffered, flat-shaded triangles, lines and a 5 x 7 pixel font into an
 * RGB canvas through an orthographic camera whose viewport is a rectangle of the canvas, so one
 * canvas can hold several panels.
 */
#ifndef AMORPH_IMAGE_H
#define AMORPH_IMAGE_H

#include <stdint.h>
#include "amorph/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- checksums ---- */

/* CRC-32 (ISO 3309, as PNG and zlib): crc is the running value, 0 to start;
 * am_crc32(0, "123456789", 9) == 0xCBF43926 */
uint32_t am_crc32(uint32_t crc, const void* data, long n);
/* Adler-32 (RFC 1950): adler is the running value, 1 to start;
 * am_adler32(1, "Wikipedia", 9) == 0x11E60398 */
uint32_t am_adler32(uint32_t adler, const void* data, long n);

/* ---- PNG ---- */

enum { AM_PNG_STORED = 0, AM_PNG_FIXED = 1 }; /* deflate without compression / fixed Huffman */
#define AM_PNG_MAX_SIDE 8192                   /* pixels along either side of an image */

/* the largest PNG file am_png_encode can write for this image, bytes (0 for a bad size) */
long am_png_max_size(int w, int h, int channels);
/* encodes w x h pixels (channels 3: RGB, 4: RGBA; rows top to bottom, 8 bits per sample) as a
 * PNG file in out (capacity cap); *len gets its length. AM_ERR_ARG for a bad size or mode,
 * AM_ERR_CAPACITY when cap is too small (am_png_max_size always suffices). */
am_status am_png_encode(const uint8_t* pixels, int w, int h, int channels, int mode, uint8_t* out, long cap,
                        long* len, char* err, int errsz);

/* ---- rasteriser ---- */

/* an RGB picture with a depth buffer, both the caller's */
typedef struct am_canvas {
    int w, h;        /* pixels */
    uint8_t* rgb;    /* (h x w x 3) bytes, rows top to bottom */
    float* depth;    /* (h x w) distance along the view direction of what was drawn (smaller is nearer) */
} am_canvas;

/* fills the picture with one colour and resets the depth buffer to far */
void am_canvas_clear(am_canvas* c, const uint8_t rgb[3]);

/* an orthographic camera looking at `target` from azimuth/elevation, shown in a rectangle of the
 * canvas; set with am_camera_look */
typedef struct am_camera {
    double target[3];     /* world point at the centre of the viewport, m */
    double right[3], up[3], fwd[3]; /* unit view axes in world coordinates (fwd points into the picture) */
    double scale;         /* pixels per metre */
    int vx, vy, vw, vh;   /* viewport rectangle in canvas pixels (left, top, width, height) */
} am_camera;

/* camera at azimuth az (radians, 0 looks along +y, pi/2 along -x) and elevation el (radians above
 * the horizon, looking down), showing view_h metres over the viewport's height; z is up */
void am_camera_look(am_camera* cam, const double target[3], double az, double el, double view_h, int vx, int vy,
                    int vw, int vh);
/* world point -> canvas pixel (out[0], out[1]) and depth out[2] */
void am_camera_project(const am_camera* cam, const double p[3], double out[3]);
/* v rotated by the unit quaternion q = (w, x, y, z) (the pictures' and the mesh's placement) */
void am_quat_rotate(const double q[4], const double v[3], double out[3]);

/* a triangle given in canvas pixels with depths (v = x0, y0, depth0, x1, y1, depth1, x2, y2,
 * depth2), clipped to the viewport, depth-tested and written in one colour; depth_test 0 draws
 * over everything and leaves the depth buffer alone (overlays) */
void am_raster_triangle(am_canvas* c, const am_camera* cam, const double v[9], const uint8_t rgb[3], int depth_test);
/* a world-space line of the given width in pixels, depth-tested against what is drawn
 * (bias metres towards the viewer so lines on a surface stay visible) */
void am_raster_line3(am_canvas* c, const am_camera* cam, const double a[3], const double b[3], double width,
                     double bias, const uint8_t rgb[3]);
/* a canvas-space line (x0, y0)-(x1, y1) of the given width, over everything, clipped to the viewport */
void am_raster_line2(am_canvas* c, const am_camera* cam, double x0, double y0, double x1, double y1, double width,
                     const uint8_t rgb[3]);
/* a box centred at centre with half-extents half[3] along its own axes, turned by the unit
 * quaternion q = (w, x, y, z), flat-shaded: each visible face gets
 * rgb * (ambient + (1 - ambient) * max(0, n . light)), light a unit vector towards the light */
void am_raster_box(am_canvas* c, const am_camera* cam, const double centre[3], const double q[4],
                   const double half[3], const uint8_t rgb[3], const double light[3], double ambient);
/* text in a 5 x 7 pixel font (ASCII 32..126), each font pixel drawn as scale x scale canvas
 * pixels, top-left corner at (x, y), over everything and clipped to the viewport; returns the
 * width drawn in pixels */
int am_raster_text(am_canvas* c, const am_camera* cam, int x, int y, int scale, const char* text,
                   const uint8_t rgb[3]);

#ifdef __cplusplus
}
#endif
#endif
