/* Tests of the picture layer: CRC-32 and Adler-32 against known vectors and bitwise references,
 * the PNG encoder (decoded here by tests/png_read.h with the library inflater) (src/io/io_png.c),
 * and a whole filmstrip from the filmstrip writer (tools/film.c); the rasteriser is
 * tests/test_io_raster.c.
 *
 * The program doubles as the PNG inspector of the shell tests (tests/cli_render.sh,
 * tests/cli_browser.sh):
 *   test_io_png --png-info FILE [RRGGBB ...]    prints "W H N1 N2 ..." (pixels in shades of each colour)
 *   test_io_png --png-diff A B RRGGBB ...       prints the pixels shaded like one of the colours in
 *                                              A or B that differ between A and B
 *   test_io_png --png-holes FILE RRGGBB ...     prints "HOLES ROBOT": HOLES the light grey pixels
 *                                              (background, floor, grid, shadow) enclosed by pixels
 *                                              shaded like the colours (not reachable from the
 *                                              picture's border without crossing one), ROBOT the
 *                                              pixels shaded like them
 *   test_io_png --png-count FILE X0 Y0 X1 Y1 RRGGBB ...   prints the pixels of each colour (each
 *                                              channel within 2) in the box [X0, X1) x [Y0, Y1)
 *   test_io_png --png-changed A B               prints the pixels that differ between A and B
 * All exit 1 with a message when a file is not a valid PNG. */
#define _POSIX_C_SOURCE 200809L /* mkstemp, close */
#include "amorph.h"
#include "cmd.h"
#include "harness.h"
#include "png_read.h"
#if TOOL_PICTURES
#include "picture.h"
#endif

#include <stdint.h>
#include <stdlib.h>
#include <unistd.h>

static void test_crc32_vectors(void)
{
    CHECK(am_crc32(0, "123456789", 9) == 0xCBF43926u, "crc32(123456789) = %08x", am_crc32(0, "123456789", 9));
    CHECK(am_crc32(0, "", 0) == 0, "crc32('') = %08x", am_crc32(0, "", 0));
    const char* fox = "The quick brown fox jumps over the lazy dog";
    CHECK(am_crc32(0, fox, 43) == 0x414FA339u, "crc32(fox) = %08x", am_crc32(0, fox, 43));
    /* running value: in two parts gives the same as at once */
    uint32_t part = am_crc32(am_crc32(0, fox, 10), fox + 10, 33);
    CHECK(part == 0x414FA339u, "crc32 in parts = %08x", part);
    /* a PNG IEND chunk's CRC is a well-known constant */
    CHECK(am_crc32(0, "IEND", 4) == 0xAE426082u, "crc32(IEND) = %08x", am_crc32(0, "IEND", 4));
    /* against the bitwise reference on every byte value */
    static uint8_t buf[4096];
    for (int i = 0; i < 4096; i++) buf[i] = (uint8_t)(i * 7 + (i >> 3));
    CHECK(am_crc32(0, buf, 4096) == png_ref_crc(buf, 4096), "crc32 differs from the bitwise reference");
}

static void test_adler32_vectors(void)
{
    CHECK(am_adler32(1, "Wikipedia", 9) == 0x11E60398u, "adler32(Wikipedia) = %08x", am_adler32(1, "Wikipedia", 9));
    CHECK(am_adler32(1, "", 0) == 1, "adler32('') = %08x", am_adler32(1, "", 0));
    CHECK(am_adler32(1, "123456789", 9) == 0x091E01DEu, "adler32(123456789) = %08x", am_adler32(1, "123456789", 9));
    /* long runs of 0xFF cross the 5552-byte modulo boundary many times */
    static uint8_t ff[100000];
    memset(ff, 0xFF, sizeof ff);
    CHECK(am_adler32(1, ff, 100000) == png_ref_adler(ff, 100000), "adler32 of 100000 x 0xFF = %08x, reference %08x",
          am_adler32(1, ff, 100000), png_ref_adler(ff, 100000));
    uint32_t part = am_adler32(am_adler32(1, ff, 7777), ff + 7777, 100000 - 7777);
    CHECK(part == png_ref_adler(ff, 100000), "adler32 in parts = %08x", part);
}

/* a test picture: flat areas, a gradient, a noisy block and repeated rows */
static void make_picture(uint8_t* px, int w, int h, int ch)
{
    uint32_t r = 12345;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            uint8_t* p = px + ((long)y * w + x) * ch;
            r = r * 1103515245u + 12345u;
            if (y < h / 3) p[0] = 200, p[1] = 30, p[2] = 40;
            else if (x < w / 2) p[0] = (uint8_t)x, p[1] = (uint8_t)(y * 3), p[2] = (uint8_t)(x + y);
            else p[0] = (uint8_t)(r >> 24), p[1] = (uint8_t)(r >> 16), p[2] = (uint8_t)(r >> 8);
            if (ch == 4) p[3] = 255;
        }
}

static void roundtrip(int w, int h, int ch, int mode)
{
    static uint8_t px[300 * 200 * 4], out[400000];
    make_picture(px, w, h, ch);
    long len = 0;
    char err[AM_ERR_MAX], why[200];
    long max = am_png_max_size(w, h, ch);
    CHECK(max > 0 && max <= (long)sizeof out, "max size %ld", max);
    am_status st = am_png_encode(px, w, h, ch, mode, out, (long)sizeof out, &len, err, sizeof err);
    CHECK(st == AM_OK, "encode %d x %d x %d mode %d: %s", w, h, ch, mode, err);
    CHECK(len > 0 && len <= max, "length %ld of at most %ld", len, max);
    png_image img;
    int r = png_decode(out, len, &img, why, sizeof why);
    CHECK(r == 0, "decode %d x %d x %d mode %d: %s", w, h, ch, mode, why);
    if (r) return;
    CHECK(img.w == w && img.h == h, "size %d x %d, want %d x %d", img.w, img.h, w, h);
    CHECK(img.color_type == (ch == 4 ? 6 : 2), "colour type %d", img.color_type);
    CHECK(img.chunks == 3, "chunks %d (IHDR, IDAT, IEND)", img.chunks);
    if (mode == AM_PNG_FIXED)
        CHECK(img.fixed_blocks == 1 && img.stored_blocks == 0 && img.dynamic_blocks == 0, "blocks: %d fixed, %d stored, %d dynamic",
              img.fixed_blocks, img.stored_blocks, img.dynamic_blocks);
    else if (mode == AM_PNG_STORED)
        CHECK(img.stored_blocks >= 1 && img.fixed_blocks == 0 && img.dynamic_blocks == 0, "blocks: %d fixed, %d stored, %d dynamic",
              img.fixed_blocks, img.stored_blocks, img.dynamic_blocks);
    else /* the smallest: one Huffman block, or stored blocks alone */
        CHECK(img.fixed_blocks + img.dynamic_blocks == 1 ? img.stored_blocks == 0 : img.fixed_blocks + img.dynamic_blocks == 0,
              "blocks: %d fixed, %d stored, %d dynamic", img.fixed_blocks, img.stored_blocks, img.dynamic_blocks);
    if (mode == AM_PNG_DYNAMIC && w * h > 1000)
        CHECK(img.dynamic_blocks == 1, "the test picture should take a dynamic block: %d fixed, %d stored", img.fixed_blocks,
              img.stored_blocks);
    long bad = 0;
    for (long i = 0; i < (long)w * h; i++)
        for (int k = 0; k < 3; k++) bad += img.rgb[3 * i + k] != px[i * ch + k];
    CHECK(bad == 0, "%ld samples differ after the round trip", bad);
    png_free(&img);
}

static void test_png_roundtrip(void)
{
    roundtrip(300, 200, 3, AM_PNG_FIXED);
    roundtrip(300, 200, 3, AM_PNG_STORED); /* 180200 bytes: three stored blocks */
    roundtrip(97, 61, 4, AM_PNG_FIXED);
    roundtrip(97, 61, 4, AM_PNG_STORED);
    roundtrip(1, 1, 3, AM_PNG_FIXED);
    roundtrip(1, 1, 3, AM_PNG_STORED);
    roundtrip(300, 200, 3, AM_PNG_DYNAMIC);
    roundtrip(97, 61, 4, AM_PNG_DYNAMIC);
    roundtrip(1, 1, 3, AM_PNG_DYNAMIC);
    roundtrip(2, 1, 4, AM_PNG_DYNAMIC);
}

/* encodes w x h RGB pixels in mode, decodes them into *img and checks every sample; the length */
static long encode_decode(const uint8_t* px, int w, int h, int mode, png_image* img)
{
    static uint8_t out[700000];
    long len = 0;
    char err[AM_ERR_MAX], why[200];
    CHECK(am_png_encode(px, w, h, 3, mode, out, (long)sizeof out, &len, err, sizeof err) == AM_OK, "encode: %s", err);
    CHECK(len <= am_png_max_size(w, h, 3), "%ld bytes, more than the bound %ld", len, am_png_max_size(w, h, 3));
    const int r = png_decode(out, len, img, why, sizeof why);
    CHECK(r == 0, "decode %d x %d mode %d: %s", w, h, mode, why);
    if (r) return memset(img, 0, sizeof *img), len;
    long bad = 0;
    for (long i = 0; i < 3L * w * h; i++) bad += img->rgb[i] != px[i];
    CHECK(bad == 0, "%ld samples differ after the round trip", bad);
    return len;
}

/* AM_PNG_DYNAMIC takes the smallest block: codes made for a picture with a skewed mix of byte
 * values (rare values deeper than 15 bits in an unlimited Huffman tree: the code must be cut to
 * 15 bits and stay complete, which the inflater checks), stored blocks for noise, the fixed code
 * for a picture too small to pay for a code table; and it beats the fixed code where there is
 * something to learn */
static void test_png_dynamic(void)
{
    static uint8_t px[400 * 300 * 3];
    png_image img;
    uint32_t r = 2024;
    /* byte values 0, 1, 2, ... with chances 1/2, 1/4, 1/8, ...: 360,000 bytes reach values of chance
     * 2^-18 and less */
    for (long i = 0; i < 400L * 300 * 3; i++) {
        r = r * 1664525u + 1013904223u;
        int v = 0;
        for (uint32_t b = r; v < 31 && !(b & 0x80000000u); b <<= 1) v++;
        px[i] = (uint8_t)v;
    }
    long dyn = encode_decode(px, 400, 300, AM_PNG_DYNAMIC, &img);
    CHECK(img.dynamic_blocks == 1 && img.lit_bits == 15, "skewed bytes: %d dynamic blocks, longest code %d bits (want 1, 15)",
          img.dynamic_blocks, img.lit_bits);
    png_free(&img);
    long fix = encode_decode(px, 400, 300, AM_PNG_FIXED, &img);
    png_free(&img);
    CHECK(dyn < fix * 3 / 4, "skewed bytes: dynamic %ld bytes, fixed %ld", dyn, fix);
    /* noise: stored blocks, no bigger than the stored encoding */
    for (long i = 0; i < 400L * 300 * 3; i++) r = r * 1664525u + 1013904223u, px[i] = (uint8_t)(r >> 24);
    dyn = encode_decode(px, 400, 300, AM_PNG_DYNAMIC, &img);
    CHECK(img.stored_blocks >= 1 && img.fixed_blocks + img.dynamic_blocks == 0, "noise: %d stored, %d fixed, %d dynamic blocks",
          img.stored_blocks, img.fixed_blocks, img.dynamic_blocks);
    png_free(&img);
    long stored = encode_decode(px, 400, 300, AM_PNG_STORED, &img);
    png_free(&img);
    CHECK(dyn == stored, "noise: %ld bytes, stored %ld", dyn, stored);
    /* one pixel: the fixed code */
    encode_decode(px, 1, 1, AM_PNG_DYNAMIC, &img);
    CHECK(img.fixed_blocks == 1 && img.stored_blocks + img.dynamic_blocks == 0, "one pixel: %d fixed, %d stored, %d dynamic",
          img.fixed_blocks, img.stored_blocks, img.dynamic_blocks);
    png_free(&img);
    /* the same picture twice: the same bytes (no state kept between calls) */
    static uint8_t a[700000], b[700000];
    long na = 0, nb = 0;
    char err[AM_ERR_MAX];
    make_picture(px, 300, 200, 3);
    CHECK(am_png_encode(px, 300, 200, 3, AM_PNG_DYNAMIC, a, (long)sizeof a, &na, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_png_encode(px, 300, 200, 3, AM_PNG_DYNAMIC, b, (long)sizeof b, &nb, err, sizeof err) == AM_OK, "%s", err);
    CHECK(na == nb && !memcmp(a, b, (size_t)na), "two encodings of one picture differ");
}

static void test_png_compresses_flat(void)
{
    static uint8_t px[400 * 300 * 3], out[500000];
    for (long i = 0; i < 400L * 300; i++) px[3 * i] = 240, px[3 * i + 1] = 240, px[3 * i + 2] = 230;
    for (int y = 100; y < 200; y++)
        for (int x = 150; x < 250; x++) px[3 * (y * 400 + x)] = 40, px[3 * (y * 400 + x) + 1] = 90, px[3 * (y * 400 + x) + 2] = 220;
    long len = 0;
    char err[AM_ERR_MAX];
    CHECK(am_png_encode(px, 400, 300, 3, AM_PNG_FIXED, out, (long)sizeof out, &len, err, sizeof err) == AM_OK, "%s", err);
    CHECK(len < 400L * 300 * 3 / 50, "a flat picture should shrink at least 50 times: %ld bytes", len);
}

static void test_png_errors(void)
{
    static uint8_t px[64 * 64 * 3], out[100];
    long len = 7;
    char err[AM_ERR_MAX] = "";
    CHECK(am_png_encode(px, 64, 64, 3, AM_PNG_FIXED, out, (long)sizeof out, &len, err, sizeof err) == AM_ERR_CAPACITY,
          "a 100-byte buffer should be too small");
    CHECK(len == 0 && strstr(err, "does not fit"), "len %ld, message '%s'", len, err);
    CHECK(am_png_encode(px, 0, 64, 3, AM_PNG_FIXED, out, (long)sizeof out, &len, err, sizeof err) == AM_ERR_ARG, "width 0");
    CHECK(am_png_encode(px, 64, 64, 2, AM_PNG_FIXED, out, (long)sizeof out, &len, err, sizeof err) == AM_ERR_ARG, "2 channels");
    CHECK(am_png_encode(px, 64, 64, 3, 7, out, (long)sizeof out, &len, err, sizeof err) == AM_ERR_ARG, "mode 7");
    CHECK(am_png_max_size(AM_PNG_MAX_SIDE + 1, 1, 3) == 0, "too wide");
}

/* ---- the filmstrip writer of amorph render ---- */

static void test_filmstrip_png(void)
{
#if !TOOL_PICTURES
    CHECK(tool_write_filmstrip(0, 0, "x.png") == 1, "the board profile's stand-in returns 1");
    return;
#endif
    static am_lattice lat;
    char err[AM_ERR_MAX], why[200];
    CHECK(am_scene_build(&lat, "sphere:6", err, sizeof err) == AM_OK, "%s", err);
    am_env env = am_default_env();
    am_eval_def eval = am_default_eval();
    eval.cycles = test_quick() ? 1 : 2;
    eval.relax_max_steps = 300;
    eval.relax_min_steps = 100;
    char path[] = "/tmp/amorph-test-film-XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0, "mkstemp");
    if (fd < 0) return;
    close(fd);
    static tool_ctx ctx;
    am_robot robot;
    am_robot_init(&robot, &lat, NULL);
    robot.env = env;
    robot.eval = eval;
    CHECK(tool_write_filmstrip(&ctx, &robot, path) == 0, "filmstrip written");
    png_image img;
    int r = png_read_file(path, &img, why, sizeof why);
    CHECK(r == 0, "decode the filmstrip: %s", why);
    FILE* f = fopen(path, "rb");
    long size = f && !fseek(f, 0, SEEK_END) ? ftell(f) : -1;
    if (f) fclose(f);
    remove(path);
    if (r) return;
    CHECK(img.w == 1600 && img.h == 400, "size %d x %d", img.w, img.h);
    CHECK(img.dynamic_blocks == 1, "a dynamic Huffman block: %d fixed, %d stored", img.fixed_blocks, img.stored_blocks);
    /* the file is the smallest encoding, well under the fixed code's of the same pixels */
    static uint8_t again[1600 * 400 * 3 + 100000];
    long dyn = 0, fix = 0;
    CHECK(am_png_encode(img.rgb, 1600, 400, 3, AM_PNG_DYNAMIC, again, (long)sizeof again, &dyn, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_png_encode(img.rgb, 1600, 400, 3, AM_PNG_FIXED, again, (long)sizeof again, &fix, err, sizeof err) == AM_OK, "%s", err);
    CHECK(size == dyn && dyn < fix * 4 / 5, "the filmstrip: %ld bytes, dynamic %ld, fixed %ld", size, dyn, fix);
    /* the body in shades of both materials, in every one of the six panels */
    const uint8_t* passive = lat.palette.mat[0].color;
    const uint8_t* active = lat.palette.mat[1].color;
    for (int panel = 0; panel < 6; panel++) {
        long np = 0, na = 0;
        for (int y = 30; y < 350; y++)
            for (int x = panel * 266 + 2; x < panel * 266 + 264; x++) {
                const uint8_t* p = img.rgb + 3 * ((long)y * img.w + x);
                np += png_shade_of(p, passive, 6);
                na += png_shade_of(p, active, 6);
            }
        CHECK(np > 500 && na > 500, "panel %d: %ld passive and %ld active pixels", panel, np, na);
    }
    png_free(&img);
}

/* the colourings' scalars (tools/picture.c) on the cantilever scene, clamped at x = 0 and bent by
 * gravity: the clamp is reported, the bend strains the voxels near the clamp more than the tip,
 * stress is strain times the modulus (1 MPa for every material of the scene), a passive body has
 * no actuation phase, the scale ends on round numbers, the ramps end in their stops */
static void test_colour_scalars(void)
{
#if TOOL_PICTURES
    static am_lattice lat;
    static tool_ctx ctx;
    static tool_motion mo;
    char err[AM_ERR_MAX];
    CHECK(am_scene_build(&lat, "cantilever:6", err, sizeof err) == AM_OK, "%s", err);
    am_env env = am_default_env();
    am_eval_def eval = am_default_eval();
    eval.cycles = 1;
    eval.relax_max_steps = 2000;
    am_robot robot;
    am_robot_init(&robot, &lat, NULL);
    robot.env = env;
    robot.eval = eval;
    CHECK(tool_record_motion(&ctx, &robot, 40, &mo, "cantilever") == 0, "recorded");
    CHECK(mo.nv == 6 && mo.nfixed == 1 && mo.fixed[0] == 1 && mo.nforced == 0, "%d voxels, %d clamped, %d forced", mo.nv, mo.nfixed,
          mo.nforced);
    const int f = mo.frames - 1;
    double root = tool_colour_value(&mo, TOOL_COL_STRAIN, f, 1), tip = tool_colour_value(&mo, TOOL_COL_STRAIN, f, 5);
    CHECK(root > 2 * tip && root > 1e-6, "strain at the root %g, at the tip %g", root, tip);
    for (int i = 0; i < mo.nv; i++) {
        double e = tool_colour_value(&mo, TOOL_COL_STRAIN, f, i), sg = tool_colour_value(&mo, TOOL_COL_STRESS, f, i);
        CHECK(fabs(sg - 1e6 * e) <= 1e-3 * sg + 1e-9, "voxel %d: stress %g is not 1 MPa x strain %g", i, sg, e);
        CHECK(tool_colour_value(&mo, TOOL_COL_PHASE, f, i) == 0, "voxel %d: a passive voxel's phase", i);
        CHECK(tool_colour_value(&mo, TOOL_COL_SPEED, f, i) >= 0, "voxel %d: speed", i);
    }
    CHECK(tool_colour_value(&mo, TOOL_COL_SPEED, 0, 3) == 0, "at rest in the first frame");
    double lo, hi, per;
    tool_colour_range(&mo, TOOL_COL_STRAIN, &lo, &hi);
    tool_colour_unit(TOOL_COL_STRAIN, &per);
    double shown = hi * per, p10 = pow(10, floor(log10(shown) + 1e-9)), m = shown / p10;
    CHECK(lo == 0 && (fabs(m - 1) < 1e-9 || fabs(m - 2) < 1e-9 || fabs(m - 5) < 1e-9), "strain scale %g .. %g %%", lo * per, shown);
    CHECK(hi >= root * 0.99, "the scale %g should hold the root's %g", hi, root);
    tool_colour_range(&mo, TOOL_COL_PHASE, &lo, &hi);
    CHECK(lo == -hi && hi > 0, "phase scale %g .. %g", lo, hi);
    uint8_t c0[3], c1[3];
    tool_colour_ramp(TOOL_COL_SPEED, -1, c0);
    tool_colour_ramp(TOOL_COL_SPEED, 2, c1);
    CHECK(c0[0] == 68 && c0[1] == 1 && c0[2] == 84 && c1[0] == 253 && c1[1] == 231 && c1[2] == 37, "sequential ends");
    tool_colour_ramp(TOOL_COL_PHASE, 0.5, c0);
    CHECK(c0[0] == 247 && c0[1] == 247 && c0[2] == 247, "diverging middle");
    CHECK(tool_colour_parse("stress") == TOOL_COL_STRESS && tool_colour_parse("heat") < 0, "names");
#endif
}

/* ---- the PNG inspector of the shell tests ---- */

static int parse_colours(int n, char** hex, uint8_t (*col)[3])
{
    for (int i = 0; i < n; i++) {
        unsigned v;
        if (strlen(hex[i]) != 6 || sscanf(hex[i], "%6x", &v) != 1) return fprintf(stderr, "bad colour '%s'\n", hex[i]), -1;
        col[i][0] = (uint8_t)(v >> 16), col[i][1] = (uint8_t)(v >> 8), col[i][2] = (uint8_t)v;
    }
    return 0;
}

static int inspector(int argc, char** argv)
{
    char why[300];
    uint8_t col[16][3];
    if (!strcmp(argv[1], "--png-info") && argc >= 3 && argc - 3 <= 16) {
        png_image img;
        if (parse_colours(argc - 3, argv + 3, col)) return 2;
        if (png_read_file(argv[2], &img, why, sizeof why)) return fprintf(stderr, "%s: %s\n", argv[2], why), 1;
        printf("%d %d", img.w, img.h);
        for (int k = 0; k < argc - 3; k++) {
            long n = 0;
            for (long i = 0; i < (long)img.w * img.h; i++) n += png_shade_of(img.rgb + 3 * i, col[k], 8);
            printf(" %ld", n);
        }
        printf("\n");
        png_free(&img);
        return 0;
    }
    if (!strcmp(argv[1], "--png-diff") && argc >= 5 && argc - 4 <= 16) {
        png_image a, b;
        if (parse_colours(argc - 4, argv + 4, col)) return 2;
        if (png_read_file(argv[2], &a, why, sizeof why)) return fprintf(stderr, "%s: %s\n", argv[2], why), 1;
        if (png_read_file(argv[3], &b, why, sizeof why)) return png_free(&a), fprintf(stderr, "%s: %s\n", argv[3], why), 1;
        if (a.w != b.w || a.h != b.h) return png_free(&a), png_free(&b), fprintf(stderr, "sizes differ\n"), 1;
        long n = 0;
        for (long i = 0; i < (long)a.w * a.h; i++) {
            const uint8_t *p = a.rgb + 3 * i, *q = b.rgb + 3 * i;
            if (!memcmp(p, q, 3)) continue;
            for (int k = 0; k < argc - 4; k++)
                if (png_shade_of(p, col[k], 8) || png_shade_of(q, col[k], 8)) {
                    n++;
                    break;
                }
        }
        printf("%ld\n", n);
        png_free(&a);
        png_free(&b);
        return 0;
    }
    if (!strcmp(argv[1], "--png-holes") && argc >= 4 && argc - 3 <= 16) {
        png_image img;
        if (parse_colours(argc - 3, argv + 3, col)) return 2;
        if (png_read_file(argv[2], &img, why, sizeof why)) return fprintf(stderr, "%s: %s\n", argv[2], why), 1;
        long n = (long)img.w * img.h, robot = 0, holes = 0, top = 0;
        uint8_t* mark = calloc((size_t)n, 1); /* 1 robot, 2 reached from the border */
        long* stack = malloc(sizeof(long) * (size_t)n);
        if (!mark || !stack) return fprintf(stderr, "out of memory\n"), 1;
        for (long i = 0; i < n; i++)
            for (int k = 0; k < argc - 3; k++)
                if (png_shade_of(img.rgb + 3 * i, col[k], 8)) mark[i] = 1;
        /* flood from every border pixel through pixels that are not the robot's */
        for (long i = 0; i < n; i++) {
            long x = i % img.w, y = i / img.w;
            if ((x == 0 || y == 0 || x == img.w - 1 || y == img.h - 1) && !mark[i]) mark[i] = 2, stack[top++] = i;
        }
        while (top > 0) {
            long i = stack[--top], x = i % img.w, y = i / img.w;
            long nb[4] = {x > 0 ? i - 1 : -1, x < img.w - 1 ? i + 1 : -1, y > 0 ? i - img.w : -1, y < img.h - 1 ? i + img.w : -1};
            for (int k = 0; k < 4; k++)
                if (nb[k] >= 0 && !mark[nb[k]]) mark[nb[k]] = 2, stack[top++] = nb[k];
        }
        for (long i = 0; i < n; i++) {
            const uint8_t* p = img.rgb + 3 * i;
            int lo = p[0] < p[1] ? p[0] : p[1], hi = p[0] > p[1] ? p[0] : p[1];
            lo = p[2] < lo ? p[2] : lo, hi = p[2] > hi ? p[2] : hi;
            robot += mark[i] == 1;
            holes += mark[i] == 0 && lo >= 180 && hi - lo <= 12;
        }
        printf("%ld %ld\n", holes, robot);
        free(mark);
        free(stack);
        png_free(&img);
        return 0;
    }
    if (!strcmp(argv[1], "--png-count") && argc >= 8 && argc - 7 <= 16) {
        png_image img;
        int box[4];
        for (int k = 0; k < 4; k++) box[k] = atoi(argv[3 + k]);
        if (parse_colours(argc - 7, argv + 7, col)) return 2;
        if (png_read_file(argv[2], &img, why, sizeof why)) return fprintf(stderr, "%s: %s\n", argv[2], why), 1;
        for (int k = 0; k < argc - 7; k++) {
            long n = 0;
            for (int y = box[1] < 0 ? 0 : box[1]; y < box[3] && y < img.h; y++)
                for (int x = box[0] < 0 ? 0 : box[0]; x < box[2] && x < img.w; x++) {
                    const uint8_t* p = img.rgb + 3 * ((long)y * img.w + x);
                    n += abs(p[0] - col[k][0]) <= 2 && abs(p[1] - col[k][1]) <= 2 && abs(p[2] - col[k][2]) <= 2;
                }
            printf(k ? " %ld" : "%ld", n);
        }
        printf("\n");
        png_free(&img);
        return 0;
    }
    if (!strcmp(argv[1], "--png-changed") && argc == 4) {
        png_image a, b;
        if (png_read_file(argv[2], &a, why, sizeof why)) return fprintf(stderr, "%s: %s\n", argv[2], why), 1;
        if (png_read_file(argv[3], &b, why, sizeof why)) return png_free(&a), fprintf(stderr, "%s: %s\n", argv[3], why), 1;
        if (a.w != b.w || a.h != b.h) return png_free(&a), png_free(&b), fprintf(stderr, "sizes differ\n"), 1;
        long n = 0;
        for (long i = 0; i < (long)a.w * a.h; i++) n += memcmp(a.rgb + 3 * i, b.rgb + 3 * i, 3) != 0;
        printf("%ld\n", n);
        png_free(&a);
        png_free(&b);
        return 0;
    }
    fprintf(stderr, "usage: test_io_png --png-info FILE [RRGGBB...] | --png-diff A B RRGGBB... | --png-holes FILE RRGGBB... |\n"
                    "       --png-count FILE X0 Y0 X1 Y1 RRGGBB... | --png-changed A B\n");
    return 2;
}

int main(int argc, char** argv)
{
    if (argc >= 2 && !strncmp(argv[1], "--png-", 6)) return inspector(argc, argv);
    TEST_INIT(argc, argv);
    RUN(test_crc32_vectors);
    RUN(test_adler32_vectors);
    RUN(test_png_roundtrip);
    RUN(test_png_compresses_flat);
    RUN(test_png_dynamic);
    RUN(test_png_errors);
    RUN(test_filmstrip_png);
    RUN(test_colour_scalars);
    return SUMMARY();
}
