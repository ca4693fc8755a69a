/* Tests of the lattice text format (src/io/io_lattice.c): exact round trips, the built-in scenes,
 * the axis order, defaults, and one test per error with its status and "fname:LINE:" prefix. */
#include "amorph.h"
#include "harness.h"
#include "sink.h"

#include <stdint.h>

static am_lattice lat_a, lat_b;
static char text[AM_LATTICE_TEXT_MAX];
static char text2[AM_LATTICE_TEXT_MAX];
static char big[1L << 20];

/* field by field, reals by their bits, names up to their NUL (am_default_palette leaves bytes of
 * "passive" after the NUL of shorter names); cells over the whole array */
/* random draws as parameters (exact in the float and double builds) */
static am_param unit_p(am_rng* r) { return AM_PARAM_FROM_DOUBLE(AM_TO_DOUBLE(am_rng_unit(r))); }
static am_param normal_p(am_rng* r) { return AM_PARAM_FROM_DOUBLE(AM_TO_DOUBLE(am_rng_normal(r))); }

/* format a, parse it into b, check they agree and that formatting b gives the same text, also
 * through a 128-byte stream */
static void round_trip(const am_lattice* a, const char* what)
{
    char err[AM_ERR_MAX] = "";
    long len = -1, len2 = -1;
    am_status st = am_lattice_format(a, text, sizeof text, &len, err, sizeof err);
    CHECK(st == AM_OK, "%s: format: %s", what, err);
    CHECK(len == (long)strlen(text), "%s: len %ld vs strlen %ld", what, len, (long)strlen(text));
    st = am_lattice_parse(&lat_b, text, what, err, sizeof err);
    CHECK(st == AM_OK, "%s: parse: %s", what, err);
    CHECK(am_lattice_equal(a, &lat_b), "%s: round trip differs", what);
    st = am_lattice_format(&lat_b, text2, sizeof text2, &len2, err, sizeof err);
    CHECK(st == AM_OK && len2 == len && strcmp(text, text2) == 0, "%s: second format differs", what);
    char piece[128];
    t_sink sink = {text2, sizeof text2, 0};
    am_text out = {piece, sizeof piece, 0, 0, t_sink_flush, &sink, 0};
    st = am_lattice_write(&lat_b, &out, err, sizeof err);
    CHECK(st == AM_OK && am_text_flush(&out) == AM_OK && out.done == len && strcmp(text, text2) == 0, "%s: streamed text differs", what);
}

static int count_id(const am_lattice* l, int id)
{
    int n = 0, cells = l->nx * l->ny * l->nz;
    for (int i = 0; i < cells; i++) n += l->cell[i] == id;
    return n;
}

/* the calibration bars: N x 3 x 3, the x < N/2 half of the active material, the rest passive
 * (halfbar) or of the material actuated half a period later (antibar); a bar needs N >= 2 */
static void test_bars(void)
{
    char err[AM_ERR_MAX] = "";
    CHECK(am_scene_build(&lat_a, "halfbar:6", err, sizeof err) == AM_OK, "%s", err);
    CHECK(lat_a.nx == 6 && lat_a.ny == 3 && lat_a.nz == 3 && am_lattice_count(&lat_a) == 54, "halfbar:6 is %d x %d x %d, %d voxels",
          lat_a.nx, lat_a.ny, lat_a.nz, am_lattice_count(&lat_a));
    const int active = am_palette_find(&lat_a.palette, "active") + 1, passive = am_palette_find(&lat_a.palette, "passive") + 1;
    const int a180 = am_palette_find(&lat_a.palette, "active180") + 1;
    int bad = 0;
    for (int z = 0; z < 3; z++)
        for (int y = 0; y < 3; y++)
            for (int x = 0; x < 6; x++) bad += lat_a.cell[am_lattice_index(&lat_a, x, y, z)] != (x < 3 ? active : passive);
    CHECK(bad == 0, "halfbar:6: %d cells of the wrong material", bad);
    CHECK(am_scene_build(&lat_a, "antibar:6", err, sizeof err) == AM_OK, "%s", err);
    bad = 0;
    for (int z = 0; z < 3; z++)
        for (int y = 0; y < 3; y++)
            for (int x = 0; x < 6; x++) bad += lat_a.cell[am_lattice_index(&lat_a, x, y, z)] != (x < 3 ? active : a180);
    CHECK(bad == 0, "antibar:6: %d cells of the wrong material", bad);
    NEAR(lat_a.palette.mat[a180 - 1].phase, 3.14159265358979, 1e-6);
    CHECK(am_scene_build(&lat_a, "halfbar:1", err, sizeof err) == AM_ERR_ARG && strcmp(err, "scene 'halfbar:1': a bar needs N >= 2") == 0,
          "%s", err);
}

static void test_scenes_round_trip(void)
{
    static const char* const scenes[] = {"cube:1", "cube:2", "cube:5", "cube:20", "sphere:1", "sphere:7", "sphere:20",
                                         "cantilever:2", "cantilever:10", "cantilever:20", "chain:1", "chain:3", "chain:20",
                                         "halfbar:2", "halfbar:6", "antibar:6", "antibar:20"};
    char err[AM_ERR_MAX] = "";
    for (size_t i = 0; i < sizeof scenes / sizeof scenes[0]; i++) {
        if (atoi(strchr(scenes[i], ':') + 1) > AM_MAX_DIM) continue; /* the board profile */
        am_status st = am_scene_build(&lat_a, scenes[i], err, sizeof err);
        CHECK(st == AM_OK, "%s: %s", scenes[i], err);
        if (st == AM_OK) round_trip(&lat_a, scenes[i]);
    }
}

/* the comparison the round trips rely on sees one changed cell, bit of a material or name */
static void test_lattice_equal_sees_differences(void)
{
    static am_lattice a, b;
    char err[AM_ERR_MAX];
    CHECK(am_scene_build(&a, "sphere:6", err, sizeof err) == AM_OK, "%s", err);
    b = a;
    CHECK(am_lattice_equal(&a, &b), "a copy differs");
    b.cell[7] = (uint8_t)(b.cell[7] ? 0 : 1);
    CHECK(!am_lattice_equal(&a, &b), "a changed cell went unseen");
    b = a;
    b.palette.mat[1].E = AM_PARAM_FROM_DOUBLE(AM_PARAM_TO_DOUBLE(b.palette.mat[1].E) * 1.0000001);
    CHECK(!am_lattice_equal(&a, &b), "a changed modulus went unseen");
    b = a;
    b.palette.mat[0].name[0] = 'X';
    CHECK(!am_lattice_equal(&a, &b), "a changed name went unseen");
    b = a;
    b.nz = a.nz - 1;
    CHECK(!am_lattice_equal(&a, &b), "a changed shape went unseen");
}

static void test_scene_facts(void)
{
    char err[AM_ERR_MAX] = "";
    for (int n = 1; n <= AM_MAX_DIM; n++) {
        char name[32];
        snprintf(name, sizeof name, "cube:%d", n);
        CHECK(am_scene_build(&lat_a, name, err, sizeof err) == AM_OK, "%s", err);
        CHECK(am_lattice_count(&lat_a) == n * n * n, "%s has %d voxels", name, am_lattice_count(&lat_a));
        if (n >= 2) {
            snprintf(name, sizeof name, "cantilever:%d", n);
            CHECK(am_scene_build(&lat_a, name, err, sizeof err) == AM_OK, "%s", err);
            int fixed = am_palette_find(&lat_a.palette, "fixed") + 1;
            CHECK(fixed > 0 && lat_a.palette.mat[fixed - 1].fixed == 1, "fixed material");
            CHECK(am_lattice_count(&lat_a) == n, "%s has %d voxels", name, am_lattice_count(&lat_a));
            CHECK(count_id(&lat_a, fixed) == 1, "%s has %d fixed voxels", name, count_id(&lat_a, fixed));
            CHECK(lat_a.cell[am_lattice_index(&lat_a, 0, 0, 2)] == fixed, "%s: x = 0 of the top layer is fixed", name);
        }
    }
    if (AM_MAX_DIM < 20) return;
    CHECK(am_scene_build(&lat_a, "sphere:20", err, sizeof err) == AM_OK, "%s", err);
    /* the facts must hold after a trip through the text as well */
    long len = 0;
    CHECK(am_lattice_format(&lat_a, text, sizeof text, &len, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_lattice_parse(&lat_b, text, "sphere.lattice", err, sizeof err) == AM_OK, "%s", err);
    const am_lattice* l = &lat_b;
    int active = am_palette_find(&l->palette, "active") + 1, passive = am_palette_find(&l->palette, "passive") + 1;
    CHECK(active > 0 && passive > 0, "palette has active and passive");
    CHECK(am_lattice_count(l) == 4224, "sphere:20 has %d voxels", am_lattice_count(l));
    int bad = 0, na = 0, np = 0;
    for (int z = 0; z < 20; z++)
        for (int y = 0; y < 20; y++)
            for (int x = 0; x < 20; x++) {
                int v = l->cell[am_lattice_index(l, x, y, z)];
                if (!v) continue;
                if (v != (x < 10 ? active : passive)) bad++;
                na += v == active;
                np += v == passive;
            }
    CHECK(bad == 0, "%d sphere voxels on the wrong side", bad);
    CHECK(na == 2112 && np == 2112, "active %d passive %d", na, np);
}

/* 16 materials with long names and awkward values, every id used, a non-cubic size */
static void make_custom(am_lattice* l)
{
    char err[AM_ERR_MAX];
    int nx = AM_MAX_DIM, ny = AM_MAX_DIM > 7 ? 7 : AM_MAX_DIM, nz = AM_MAX_DIM > 13 ? 13 : AM_MAX_DIM - 1;
    CHECK(am_lattice_init(l, nx, ny, nz, AM_P(0.0123456789), err, sizeof err) == AM_OK, "%s", err);
    memset(&l->palette, 0, sizeof l->palette);
    l->palette.count = AM_MAX_MATERIALS;
    am_rng r;
    am_rng_seed(&r, 42);
    for (int i = 0; i < AM_MAX_MATERIALS; i++) {
        am_material* m = &l->palette.mat[i];
        *m = am_default_material();
        memset(m->name, 0, sizeof m->name);
        if (i == 0) memcpy(m->name, "a_very-long_name_23_chr", 23);
        else snprintf(m->name, sizeof m->name, "M-%d_x", i);
        m->E = AM_P(1e6) * (AM_P(0.1) + unit_p(&r));
        m->density = AM_P(1) / AM_P(3) + (am_param)i;
        m->poisson = AM_P(0.49999);
        m->cte = i == 1 ? AM_P(-0.0) : AM_P(1e-30) * normal_p(&r);
        m->phase = -AM_P(3.14159265358979323846) / AM_P(3) * (am_param)i;
        m->mu_static = i == 2 ? AM_P(1e-40) : unit_p(&r); /* a subnormal float */
        m->mu_kinetic = AM_P(0.0);
        m->zeta_internal = AM_P(3.0e30);
        m->zeta_global = AM_P(0.1) * (am_param)i;
        m->zeta_collision = AM_P(2) / AM_P(7);
        m->color[0] = (uint8_t)(i * 16);
        m->color[1] = (uint8_t)(255 - i);
        m->color[2] = (uint8_t)(i * 7);
        m->color[3] = (uint8_t)(i % 2 ? 255 : i * 3);
        m->fixed = i % 5 == 4;
    }
    int cells = nx * ny * nz;
    for (int i = 0; i < cells; i++) l->cell[i] = (uint8_t)am_rng_below(&r, AM_MAX_MATERIALS + 1);
    for (int v = 0; v <= AM_MAX_MATERIALS; v++) l->cell[v] = (uint8_t)v;
}

static void test_custom_round_trip(void)
{
    make_custom(&lat_a);
    round_trip(&lat_a, "custom");
    /* a full lattice with every cell of material 16 fits AM_LATTICE_TEXT_MAX */
    int nx = AM_MAX_DIM;
    lat_a.nx = lat_a.ny = lat_a.nz = nx;
    memset(lat_a.cell, AM_MAX_MATERIALS, sizeof lat_a.cell);
    round_trip(&lat_a, "full custom");
}

static void test_axis_order(void)
{
    char err[AM_ERR_MAX] = "";
    const char* t = "amorph-lattice 1\n"
                    "size 3 2 2\n"
                    "layer 0\n"
                    "1..\n"  /* y = 0 */
                    "..2\n"  /* y = 1 */
                    "layer 1\n"
                    ".3.\n"
                    "9..\n";
    CHECK(am_lattice_parse(&lat_a, t, "axes", err, sizeof err) == AM_OK, "%s", err);
    CHECK(lat_a.nx == 3 && lat_a.ny == 2 && lat_a.nz == 2, "size");
    CHECK(lat_a.palette.count == 9, "default palette has 9, got %d", lat_a.palette.count);
    CHECK(lat_a.cell[am_lattice_index(&lat_a, 0, 0, 0)] == 1, "x0 y0 z0");
    CHECK(lat_a.cell[am_lattice_index(&lat_a, 2, 1, 0)] == 2, "x2 y1 z0");
    CHECK(lat_a.cell[am_lattice_index(&lat_a, 1, 0, 1)] == 3, "x1 y0 z1");
    CHECK(lat_a.cell[am_lattice_index(&lat_a, 0, 1, 1)] == 9, "x0 y1 z1");
    CHECK(am_lattice_count(&lat_a) == 4, "count %d", am_lattice_count(&lat_a));
}

static void test_defaults_and_layout(void)
{
    char err[AM_ERR_MAX] = "";
    /* comments anywhere, CRLF, trailing blanks, no final newline, keys omitted, voxel_size omitted */
    const char* t = "# a comment before the header\r\n"
                    "\n"
                    "  amorph-lattice   1   # the header\r\n"
                    "material soft_one E=5e4\t# only E\r\n"
                    "material plain\n"
                    "size 2 1 1 # nx ny nz\n"
                    "# between\n"
                    "layer 0\n"
                    "\n"
                    "  # a comment line among the rows\n"
                    "12   # a trailing comment\r\n"
                    "# the end";
    CHECK(am_lattice_parse(&lat_a, t, "defaults", err, sizeof err) == AM_OK, "%s", err);
    am_material d = am_default_material();
    CHECK(lat_a.palette.count == 2, "count %d", lat_a.palette.count);
    CHECK(strcmp(lat_a.palette.mat[0].name, "soft_one") == 0, "name 0");
    CHECK(strcmp(lat_a.palette.mat[1].name, "plain") == 0, "name 1");
    CHECK(lat_a.palette.mat[0].E == AM_P(5e4), "E");
    CHECK(lat_a.palette.mat[1].E == d.E && lat_a.palette.mat[1].density == d.density && lat_a.palette.mat[1].mu_kinetic == d.mu_kinetic &&
              lat_a.palette.mat[1].zeta_global == d.zeta_global && memcmp(lat_a.palette.mat[1].color, d.color, 4) == 0 &&
              lat_a.palette.mat[1].fixed == d.fixed,
          "defaults of am_default_material");
    CHECK(lat_a.voxel_size == AM_P(0.01), "default voxel size");
    CHECK(lat_a.cell[0] == 1 && lat_a.cell[1] == 2, "cells");
    /* colors: #rrggbb gives alpha 255, #rrggbbaa sets it; hex digits in either case */
    const char* c = "amorph-lattice 1\nmaterial a color=#0A0b0C\nmaterial b color=#ffeeDD80 fixed=1\nsize 1 1 1\nlayer 0\n2\n";
    CHECK(am_lattice_parse(&lat_a, c, "colors", err, sizeof err) == AM_OK, "%s", err);
    CHECK(lat_a.palette.mat[0].color[0] == 10 && lat_a.palette.mat[0].color[1] == 11 && lat_a.palette.mat[0].color[2] == 12 &&
              lat_a.palette.mat[0].color[3] == 255,
          "color a");
    CHECK(lat_a.palette.mat[1].color[0] == 255 && lat_a.palette.mat[1].color[2] == 0xdd && lat_a.palette.mat[1].color[3] == 0x80 &&
              lat_a.palette.mat[1].fixed == 1,
          "color b");
}

/* ---- errors ---------------------------------------------------------------------------- */

typedef struct bad_case {
    const char* text;
    am_status status;
    int line;
    const char* contains; /* a piece of the message, or NULL */
} bad_case;

#define HDR "amorph-lattice 1\n"
#define OK1 "size 3 2 2\nlayer 0\n1..\n.2.\nlayer 1\n...\n..1\n" /* lines 2..8 after HDR */

static void expect_bad(const char* t, am_status want, int line, const char* contains, const char* label)
{
    char err[AM_ERR_MAX];
    char prefix[64];
    memset(err, 'Z', sizeof err);
    am_status st = am_lattice_parse(&lat_a, t, "t.lattice", err, sizeof err);
    snprintf(prefix, sizeof prefix, "t.lattice:%d: ", line);
    CHECK(st == want, "%s: status %d, want %d (%s)", label, (int)st, (int)want, st == AM_OK ? "ok" : err);
    if (st == AM_OK) return;
    CHECK(memchr(err, 0, sizeof err) != NULL, "%s: message not terminated", label);
    CHECK(strncmp(err, prefix, strlen(prefix)) == 0, "%s: message '%s' does not start with '%s'", label, err, prefix);
    CHECK(strchr(err, '\n') == NULL && strchr(err, '\r') == NULL, "%s: newline in message", label);
    CHECK(strlen(err) > strlen(prefix) + 5, "%s: message too short: '%s'", label, err);
    if (contains) CHECK(strstr(err, contains) != NULL, "%s: '%s' lacks '%s'", label, err, contains);
}

static void test_bad_cases(void)
{
    static char over[256], over_mat[4096];
    snprintf(over, sizeof over, HDR "# comment\nsize %d 1 1\nlayer 0\n", AM_MAX_DIM + 1);
    int n = snprintf(over_mat, sizeof over_mat, HDR);
    for (int i = 0; i <= AM_MAX_MATERIALS; i++) n += snprintf(over_mat + n, sizeof over_mat - (size_t)n, "material m%d\n", i);
    static const bad_case cases[] = {
        /* header */
        {"", AM_ERR_PARSE, 1, "header"},
        {"# only a comment\n\n", AM_ERR_PARSE, 2, "header"},
        {"amorph-lattice 2\n" OK1, AM_ERR_PARSE, 1, "version 2"},
        {"amorph-lattice 0x1\n" OK1, AM_ERR_PARSE, 1, "version"},
        {"amorph-lattice\n" OK1, AM_ERR_PARSE, 1, "version"},
        {"amorph-lattic 1\n" OK1, AM_ERR_PARSE, 1, "header"},
        {"size 3 2 2\n" HDR, AM_ERR_PARSE, 1, "header"},
        {"\n# c\namorph-lattice 1 extra\n" OK1, AM_ERR_PARSE, 3, "extra"},
        {HDR HDR OK1, AM_ERR_PARSE, 2, "header"},
        /* keywords and order */
        {HDR "colour red\n" OK1, AM_ERR_PARSE, 2, "unknown keyword 'colour'"},
        {HDR "layer 0\n", AM_ERR_PARSE, 2, "size"},
        {HDR "# no size\n", AM_ERR_PARSE, 2, "missing size"},
        {HDR "material x\n", AM_ERR_PARSE, 2, "missing size"},
        {HDR "size 3 2 2\n1..\n", AM_ERR_PARSE, 3, "row before"},
        {HDR "size 3 2 2\nsize 3 2 2\n", AM_ERR_PARSE, 3, "twice"},
        {HDR "size 3 2 2\nlayer 0\n1..\n.2.\nmaterial late\n", AM_ERR_PARSE, 6, "before the first layer"},
        {HDR "size 3 2 2\nlayer 0\n1..\n.2.\nvoxel_size 1\n", AM_ERR_PARSE, 6, "before the first layer"},
        /* counts */
        {HDR "size 3 2 2\nlayer 0\n1..\n.2..\n", AM_ERR_PARSE, 5, "has 4 cells, expected 3"},
        {HDR "size 3 2 2\nlayer 0\n1.\n", AM_ERR_PARSE, 4, "has 2 cells, expected 3"},
        {HDR "size 3 2 2\nlayer 0\n1 . .\n", AM_ERR_PARSE, 4, "row"},
        {HDR "size 3 2 2\nlayer 0\n1..\nlayer 1\n", AM_ERR_PARSE, 5, "layer 0 has 1 rows, expected 2"},
        {HDR "size 3 2 2\nlayer 0\n1..\n.2.\n...\nlayer 1\n", AM_ERR_PARSE, 6, "more than 2 rows"},
        {HDR OK1 "...\n", AM_ERR_PARSE, 9, "more than 2 rows"},
        {HDR OK1 "\n# more\nlayer 2\n...\n...\n", AM_ERR_PARSE, 11, "too many layers"},
        {HDR OK1 "layer 1\n", AM_ERR_PARSE, 9, "too many layers"},
        {HDR OK1 "1x.\n", AM_ERR_PARSE, 9, "unknown keyword '1x.'"},
        {HDR "size 3 2 2\nlayer 0\n1..\n.2.\n", AM_ERR_PARSE, 5, "missing layer 1"},
        {HDR "size 3 2 2\nlayer 0\n1..\n.2.\n# the end\n\n", AM_ERR_PARSE, 7, "missing layer 1"},
        {HDR "size 3 2 2\n", AM_ERR_PARSE, 2, "missing layer 0"},
        {HDR "size 3 2 2\nlayer 1\n...\n...\n", AM_ERR_PARSE, 3, "expected layer 0"},
        {HDR "size 3 2 2\nlayer 0\n...\n...\nlayer 0\n", AM_ERR_PARSE, 6, "expected layer 1"},
        {HDR "size 3 2 2\nlayer -1\n", AM_ERR_PARSE, 3, "expected layer 0"},
        {HDR "size 3 2 2\nlayer 0\n1..\n.2.\nlayer 1\n...", AM_ERR_PARSE, 7, "layer 1 has 1 rows"},
        {HDR "size 3 2 2\nlayer\n", AM_ERR_PARSE, 3, "layer number"},
        {HDR "size 3 2 2\nlayer zero\n", AM_ERR_PARSE, 3, "layer number"},
        {HDR "size 3 2 2\nlayer 0 0\n", AM_ERR_PARSE, 3, "unexpected"},
        /* cells */
        {HDR "size 3 2 2\nlayer 0\n1..\n.a.\n", AM_ERR_RANGE, 5, "unknown material id 'a'"},
        {HDR "material one\nmaterial two\nsize 3 2 2\nlayer 0\n1..\n.3.\n", AM_ERR_RANGE, 7, "unknown material id '3'"},
        {HDR "size 3 2 2\nlayer 0\n1..\n.h.\n", AM_ERR_PARSE, 5, "bad cell character 'h'"},
        {HDR "size 3 2 2\nlayer 0\n1..\n.0.\n", AM_ERR_PARSE, 5, "bad cell character '0'"},
        {HDR "size 3 2 2\nlayer 0\n1..\n.\001.\n", AM_ERR_PARSE, 5, "0x01"},
        {HDR "size 3 2 2\nlayer 0\n1..\n.\377.\n", AM_ERR_PARSE, 5, "0xff"},
        /* sizes */
        {HDR "size 0 2 2\n", AM_ERR_RANGE, 2, "at least 1"},
        {HDR "size 3 -2 2\n", AM_ERR_RANGE, 2, "at least 1"},
        {HDR "size 3 2\n", AM_ERR_PARSE, 2, "three"},
        {HDR "size 3 2 2 2\n", AM_ERR_PARSE, 2, "unexpected"},
        {HDR "size 3 2.5 2\n", AM_ERR_PARSE, 2, "2.5"},
        {HDR "size 3 2 2x\n", AM_ERR_PARSE, 2, "2x"},
        {HDR "size 3 2 99999999999999999999999\n", AM_ERR_CAPACITY, 2, AM_PROFILE_NAME},
        /* a number past 10^9 shown as written, not clamped (issue 31) */
        {HDR "size 3 2 99999999999999999999999\n", AM_ERR_CAPACITY, 2, "size 3 2 99999999999999999999999 exceeds"},
        {over, AM_ERR_CAPACITY, 3, AM_PROFILE_NAME " profile"},
        {over_mat, AM_ERR_CAPACITY, 2 + AM_MAX_MATERIALS, "materials"},
        /* voxel size */
        {HDR "voxel_size 0\n", AM_ERR_RANGE, 2, "greater than 0"},
        {HDR "voxel_size -0.01\n", AM_ERR_RANGE, 2, "greater than 0"},
        /* the configuration's range (issue 31: a subnormal size made the model's scales NaN) */
        {HDR "voxel_size 1e-45\n", AM_ERR_RANGE, 2, "voxel_size 1e-45 m is outside 1e-05..10"},
        {HDR "voxel_size 11\n", AM_ERR_RANGE, 2, "outside 1e-05..10"},
        {HDR "voxel_size 1cm\n", AM_ERR_PARSE, 2, "'1cm'"},
        {HDR "voxel_size nan\n", AM_ERR_PARSE, 2, "finite"},
        {HDR "voxel_size\n", AM_ERR_PARSE, 2, "metres"},
        {HDR "voxel_size 0.01 0.02\n", AM_ERR_PARSE, 2, "unexpected"},
        {HDR "voxel_size 0.01\nvoxel_size 0.01\n", AM_ERR_PARSE, 3, "twice"},
        /* materials */
        {HDR "material\n", AM_ERR_PARSE, 2, "name"},
        {HDR "material bad!name\n", AM_ERR_PARSE, 2, "bad!name"},
        {HDR "material abcdefghijklmnopqrstuvwxyz\n", AM_ERR_PARSE, 2, "name"},
        {HDR "material m\nmaterial n\n\nmaterial m E=2\n", AM_ERR_PARSE, 5, "defined twice"},
        {HDR "material m Ee=5\n", AM_ERR_PARSE, 2, "unknown key 'Ee'"},
        {HDR "material m =5\n", AM_ERR_PARSE, 2, "unknown key"},
        {HDR "material m E\n", AM_ERR_PARSE, 2, "key=value"},
        {HDR "material m E=1 E=2\n", AM_ERR_PARSE, 2, "twice"},
        {HDR "material m E=1e6x\n", AM_ERR_PARSE, 2, "'1e6x'"},
        {HDR "material m E=\n", AM_ERR_PARSE, 2, "E"},
        {HDR "material m E=nan\n", AM_ERR_PARSE, 2, "'nan'"},
        {HDR "material m E=inf\n", AM_ERR_PARSE, 2, "'inf'"},
        {HDR "material m cte=-infinity\n", AM_ERR_PARSE, 2, "'-infinity'"},
        {HDR "material m E=1e400\n", AM_ERR_PARSE, 2, "'1e400'"},
        {HDR "material m phase=1,5\n", AM_ERR_PARSE, 2, "'1,5'"},
        {HDR "material m E=0\n", AM_ERR_RANGE, 2, "greater than 0"},
        {HDR "material m E=-1e6\n", AM_ERR_RANGE, 2, "greater than 0"},
        {HDR "material m density=-1000\n", AM_ERR_RANGE, 2, "density"},
        {HDR "material m density=0\n", AM_ERR_RANGE, 2, "density"},
        {HDR "material m poisson=0.5\n", AM_ERR_RANGE, 2, "[0, 0.5)"},
        {HDR "material m poisson=-0.1\n", AM_ERR_RANGE, 2, "[0, 0.5)"},
        {HDR "material m mu_k=-0.3\n", AM_ERR_RANGE, 2, "mu_k"},
        {HDR "material m zeta_col=-1\n", AM_ERR_RANGE, 2, "zeta_col"},
        {HDR "material m fixed=2\n", AM_ERR_PARSE, 2, "fixed"},
        {HDR "material m fixed=yes\n", AM_ERR_PARSE, 2, "fixed"},
        {HDR "material m color=#12345\n", AM_ERR_PARSE, 2, "bad color"},
        {HDR "material m color=#12345g\n", AM_ERR_PARSE, 2, "bad color"},
        {HDR "material m color=123456\n", AM_ERR_PARSE, 2, "bad color"},
        {HDR "material m color=#1234567\n", AM_ERR_PARSE, 2, "bad color"},
        {HDR "material m color= #123456\n", AM_ERR_PARSE, 2, "bad color"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char label[32];
        snprintf(label, sizeof label, "case %d", (int)i);
        expect_bad(cases[i].text, cases[i].status, cases[i].line, cases[i].contains, label);
    }
}

/* lines of any length: no fixed line buffer */
static void test_long_lines(void)
{
    char err[AM_ERR_MAX] = "";
    long n = 0;
    n += snprintf(big + n, sizeof big - (size_t)n, "amorph-lattice 1\n#");
    memset(big + n, 'c', 500000);
    n += 500000;
    n += snprintf(big + n, sizeof big - (size_t)n, "\nsize 2 1 1\nlayer 0\n");
    long row = n;
    memset(big + n, '1', 300000);
    n += 300000;
    big[n++] = '\n';
    big[n] = 0;
    expect_bad(big, AM_ERR_PARSE, 5, "has 300000 cells, expected 2", "long row");
    big[row + 2] = '\n';
    big[row + 3] = 0;
    CHECK(am_lattice_parse(&lat_a, big, "long", err, sizeof err) == AM_OK, "%s", err);
    /* a long unknown keyword is quoted shortened */
    memset(big, 'k', 200000);
    big[200000] = 0;
    expect_bad(big, AM_ERR_PARSE, 1, "header", "long header");
    /* a tiny message buffer truncates, never overflows */
    char tiny[8];
    CHECK(am_lattice_parse(&lat_a, "junk", "some/long/file/name.lattice", tiny, sizeof tiny) == AM_ERR_PARSE, "tiny");
    CHECK(strlen(tiny) == 7, "tiny message length %d", (int)strlen(tiny));
    CHECK(am_lattice_parse(&lat_a, "junk", "f", NULL, 0) == AM_ERR_PARSE, "no message buffer");
}

/* every prefix of a valid text, and texts with random bytes changed, parse or fail cleanly */
static void test_truncation_and_noise(void)
{
    char err[AM_ERR_MAX];
    make_custom(&lat_a);
    lat_a.nx = 5;
    lat_a.ny = 3;
    lat_a.nz = 2;
    memset(lat_a.cell, 0, sizeof lat_a.cell);
    for (int i = 0; i < 30; i++) lat_a.cell[i] = (uint8_t)(i % 17);
    long len = 0;
    CHECK(am_lattice_format(&lat_a, text, sizeof text, &len, err, sizeof err) == AM_OK, "%s", err);
    int ok_count = 0, bad_prefix = 0;
    for (long cut = 0; cut <= len; cut++) {
        /* at the very end of the array, so a read past the NUL hits a sanitizer's red zone */
        char* t = big + sizeof big - 1 - cut;
        memcpy(t, text, (size_t)cut);
        t[cut] = 0;
        am_status st = am_lattice_parse(&lat_b, t, "cut", err, sizeof err);
        if (st == AM_OK) ok_count++;
        else if (strncmp(err, "cut:", 4) != 0 || strchr(err, '\n')) bad_prefix++;
    }
    /* only the whole text (and the whole text less its last newline) is complete */
    CHECK(ok_count == 2, "%d prefixes parsed", ok_count);
    CHECK(bad_prefix == 0, "%d messages without the prefix", bad_prefix);
    am_rng r;
    am_rng_seed(&r, 7);
    int rounds = test_quick() ? 300 : 3000;
    bad_prefix = 0;
    for (int k = 0; k < rounds; k++) {
        char* t = big + sizeof big - 1 - len;
        memcpy(t, text, (size_t)len + 1);
        int flips = 1 + (int)am_rng_below(&r, 4);
        for (int f = 0; f < flips; f++) {
            static const char pool[] = " \t\n\r#=.-+e0123456789abcdefgxyz!\377\001";
            t[am_rng_below(&r, (uint32_t)len)] = pool[am_rng_below(&r, sizeof pool - 1)];
        }
        if (am_lattice_parse(&lat_b, t, "noise", err, sizeof err) != AM_OK && (strncmp(err, "noise:", 6) != 0 || strchr(err, '\n')))
            bad_prefix++;
    }
    CHECK(bad_prefix == 0, "%d noisy inputs gave messages without the prefix", bad_prefix);
}

static void test_format_errors(void)
{
    char err[AM_ERR_MAX] = "";
    long len = 123;
    CHECK(am_scene_build(&lat_a, "cube:3", err, sizeof err) == AM_OK, "%s", err);
    /* too small a buffer: capacity, still NUL-terminated */
    char small[100];
    memset(small, 'x', sizeof small);
    CHECK(am_lattice_format(&lat_a, small, sizeof small, &len, err, sizeof err) == AM_ERR_CAPACITY, "small buffer");
    CHECK(small[0] == 0 && len == 0, "small buffer emptied");
    CHECK(am_lattice_format(&lat_a, text, sizeof text, &len, err, sizeof err) == AM_OK, "%s", err);
    /* exactly enough room (len + 1) works, one byte less does not */
    CHECK(am_lattice_format(&lat_a, text2, len + 1, &len, err, sizeof err) == AM_OK, "%s", err);
    CHECK(am_lattice_format(&lat_a, text2, len, &len, err, sizeof err) == AM_ERR_CAPACITY, "len bytes");
    /* lattices that would not read back are refused */
    lat_a.cell[5] = (uint8_t)(lat_a.palette.count + 1);
    CHECK(am_lattice_format(&lat_a, text, sizeof text, &len, err, sizeof err) == AM_ERR_ARG, "bad cell id");
    lat_a.cell[5] = 1;
    lat_a.palette.mat[2].poisson = AM_P(0.5);
    CHECK(am_lattice_format(&lat_a, text, sizeof text, &len, err, sizeof err) == AM_ERR_ARG, "bad poisson");
    lat_a.palette.mat[2].poisson = AM_P(0);
    strcpy(lat_a.palette.mat[3].name, "passive");
    CHECK(am_lattice_format(&lat_a, text, sizeof text, &len, err, sizeof err) == AM_ERR_ARG, "duplicate name");
    strcpy(lat_a.palette.mat[3].name, "with space");
    CHECK(am_lattice_format(&lat_a, text, sizeof text, &len, err, sizeof err) == AM_ERR_ARG, "bad name");
    strcpy(lat_a.palette.mat[3].name, "stiff");
    lat_a.nz = AM_MAX_DIM + 1;
    CHECK(am_lattice_format(&lat_a, text, sizeof text, &len, err, sizeof err) == AM_ERR_ARG, "bad size");
    lat_a.nz = 3;
    CHECK(am_lattice_format(&lat_a, text, sizeof text, &len, err, sizeof err) == AM_OK, "%s", err);
}

/* parse t; the message must be exactly want, one line of printable ASCII */
static void expect_message(const char* t, const char* want)
{
    char err[AM_ERR_MAX] = "";
    am_status st = am_lattice_parse(&lat_a, t, "t.lattice", err, sizeof err);
    CHECK(st != AM_OK && !strcmp(err, want), "message '%s', want '%s'", err, want);
    CHECK(printable_line(err), "'%s' is not one line of printable ASCII", err);
}

/* a bad token shows cut and escaped (am_quote): control bytes never reach the message */
static void test_bad_tokens_quoted(void)
{
    static char t[1024], want[AM_ERR_MAX];
    char tok[301];
    expect_message(HDR "\x1b[31mred 1\n",
                   "t.lattice:2: unknown keyword '\\x1b[31mred' (expected size, voxel_size, material or layer)");
    expect_message("\x01" "amorph-lattice 1\n",
                   "t.lattice:1: not a lattice file: expected the header 'amorph-lattice 1', found '\\x01amorph-lattice'");
    expect_message(HDR "material m E=\x01\x7f\n", "t.lattice:2: material 'm': E: '\\x01\\x7f' is not a finite number");
    expect_message(HDR "voxel_size 1'\\\n", "t.lattice:2: voxel_size: '1\\'\\\\' is not a finite number");
    expect_message(HDR "size 3 2 2\nlayer 0\n1.. \x1b\n",
                   "t.lattice:4: layer 0 row 0: unexpected '\\x1b' after the row (a row is 3 characters, no blanks)");
    /* a 300-character token: its first 40 characters and "..." */
    memset(tok, 'k', 300);
    tok[300] = 0;
    snprintf(t, sizeof t, HDR "%s 1\n", tok);
    snprintf(want, sizeof want, "t.lattice:2: unknown keyword '%.40s...' (expected size, voxel_size, material or layer)", tok);
    expect_message(t, want);
    tok[0] = '\x01';
    snprintf(t, sizeof t, HDR "material m color=%s\n", tok);
    snprintf(want, sizeof want, "t.lattice:2: material 'm': bad color '\\x01%.39s...' (expected #rrggbb or #rrggbbaa)", tok + 1);
    expect_message(t, want);
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    RUN(test_bars);
    RUN(test_scenes_round_trip);
    RUN(test_lattice_equal_sees_differences);
    RUN(test_scene_facts);
    RUN(test_custom_round_trip);
    RUN(test_axis_order);
    RUN(test_defaults_and_layout);
    RUN(test_bad_cases);
    RUN(test_long_lines);
    RUN(test_truncation_and_noise);
    RUN(test_format_errors);
    RUN(test_bad_tokens_quoted);
    return SUMMARY();
}
