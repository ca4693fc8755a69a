/* Tests of the zlib inflater (src/io/io_inflate.c, amorph/io.h): streams of the three block kinds
 * (made with Python's zlib for these tests, the plain text rebuilt here), one check per kind of
 * malformed stream with its status and message, every truncation, a short output, and a fuzz
 * pass of byte mutations that must each end in AM_OK or one clean message, never a crash (the
 * asan and valgrind targets run it under their checkers). */
#include "amorph.h"
#include "amorph/io.h"
#include "harness.h"

#include <stdint.h>

static const uint8_t z_dynamic[160] = {
    0x78, 0xda, 0x95, 0xd1, 0x31, 0x0e, 0xc2, 0x30, 0x0c, 0x85, 0xe1, 0xab, 0xf8, 0x00, 0x0c, 0x79,
    0x49, 0x9b, 0x34, 0x70, 0x9a, 0x82, 0x82, 0x3a, 0x04, 0x05, 0xa5, 0x15, 0x82, 0xdb, 0x23, 0x50,
    0x8d, 0x3c, 0x78, 0x30, 0xfb, 0x27, 0x3f, 0xc9, 0xff, 0x7c, 0x6b, 0xfd, 0xbe, 0xd0, 0xa3, 0x3d,
    0x4b, 0x5d, 0x8f, 0x54, 0xe7, 0x57, 0xe9, 0xe4, 0xa8, 0x5d, 0x69, 0x5b, 0x0a, 0xf5, 0x76, 0x6e,
    0xdb, 0x81, 0x2e, 0xa5, 0xd6, 0x95, 0x1c, 0x7c, 0x18, 0xc6, 0x98, 0xa6, 0xec, 0x70, 0xda, 0x25,
    0x54, 0xf9, 0x25, 0x3b, 0x66, 0xe9, 0x55, 0xc9, 0xf7, 0x3e, 0x98, 0x65, 0x50, 0xa5, 0x18, 0xf7,
    0x2c, 0x07, 0x55, 0x8a, 0xf1, 0xcc, 0x72, 0x54, 0xa5, 0x18, 0x8f, 0x2c, 0xa3, 0x2a, 0xc5, 0x78,
    0x60, 0x99, 0x54, 0x29, 0xc6, 0x1d, 0xcb, 0x49, 0x95, 0x62, 0x3c, 0xb1, 0xcc, 0xaa, 0x14, 0xe3,
    0xc3, 0xef, 0xf3, 0x7f, 0x44, 0xb2, 0x57, 0x82, 0x3d, 0x13, 0xec, 0x9d, 0x60, 0x0f, 0x05, 0x7b,
    0x29, 0xd8, 0x53, 0xc1, 0xde, 0x0a, 0xf6, 0x58, 0xb0, 0xd4, 0x7a, 0x03, 0x25, 0x46, 0xfe, 0xdb};
static const uint8_t z_fixed[17] = {
    0x78, 0xda, 0x4b, 0x4c, 0x4a, 0x4e, 0x44, 0x45, 0x06, 0x86, 0x46, 0xc6, 0x00, 0x5e, 0xfa, 0x07,
    0xab};
static const uint8_t z_stored[39] = {
    0x78, 0x01, 0x01, 0x1c, 0x00, 0xe3, 0xff, 0x73, 0x74, 0x6f, 0x72, 0x65, 0x64, 0x20, 0x62, 0x79,
    0x74, 0x65, 0x73, 0x2c, 0x20, 0x6e, 0x6f, 0x20, 0x63, 0x6f, 0x6d, 0x70, 0x72, 0x65, 0x73, 0x73,
    0x69, 0x6f, 0x6e, 0x9b, 0x20, 0x0a, 0xd4};
static const uint8_t z_far[5] = {
    0x78, 0x01, 0x03, 0x02, 0x00};
static const uint8_t z_over[10] = {
    0x78, 0x01, 0x05, 0x00, 0x92, 0x04, 0x00, 0x00, 0x00, 0x00};

static am_inflate_work work;
static uint8_t out[4096];
static char text[4096];

/* the plain text of z_dynamic */
static long dynamic_text(void)
{
    long n = snprintf(text, sizeof text, "amorph voxels: ");
    for (int i = 0; i < 20; i++) {
        n += snprintf(text + n, sizeof text - (size_t)n, "layer %d of the robot, cells ", i);
        for (int j = 0; j < 12; j++) text[n++] = (char)('0' + (i * 7 + j) % 10);
        n += snprintf(text + n, sizeof text - (size_t)n, "; ");
    }
    return n;
}

static void expect(const uint8_t* in, long n, long cap, am_status code, const char* want)
{
    char err[AM_ERR_MAX] = "";
    long len = -1;
    am_status st = am_zlib_inflate(in, n, out, cap, &len, &work, err, sizeof err);
    CHECK(st == code && strstr(err, want) != NULL && (st == AM_OK || len == 0), "status %d (want %d), message '%s' (want '%s')", st,
          code, err, want);
}

static void test_inflate_block_kinds(void)
{
    char err[AM_ERR_MAX] = "";
    long len = 0, n = dynamic_text();
    CHECK(am_zlib_inflate(z_dynamic, sizeof z_dynamic, out, sizeof out, &len, &work, err, sizeof err) == AM_OK, "%s", err);
    CHECK(len == n && !memcmp(out, text, (size_t)n), "dynamic: %ld bytes, want %ld", len, n);
    CHECK(work.kinds[2] == 1 && work.kinds[0] == 0 && work.kinds[1] == 0, "dynamic block counted");
    CHECK(am_zlib_inflate(z_fixed, sizeof z_fixed, out, sizeof out, &len, &work, err, sizeof err) == AM_OK, "%s", err);
    CHECK(len == 22 && !memcmp(out, "abcabcabcabcabcabc0123", 22) && work.kinds[1] == 1, "fixed: '%.*s'", (int)len, (char*)out);
    CHECK(am_zlib_inflate(z_stored, sizeof z_stored, out, sizeof out, &len, &work, err, sizeof err) == AM_OK, "%s", err);
    CHECK(len == 28 && !memcmp(out, "stored bytes, no compression", 28) && work.kinds[0] == 1, "stored");
    /* the exact output size is enough */
    CHECK(am_zlib_inflate(z_dynamic, sizeof z_dynamic, out, n, &len, &work, err, sizeof err) == AM_OK && len == n, "exact cap");
}

static void test_inflate_errors(void)
{
    static uint8_t b[512];
    expect(z_fixed, 1, 100, AM_ERR_PARSE, "shorter than its header");
    const uint8_t bad_check[] = {0x78, 0x9d, 0x03, 0x00};
    expect(bad_check, 4, 100, AM_ERR_PARSE, "bad zlib header: check bits 0x789d");
    const uint8_t bad_method[] = {0x79, 0xd9, 0x03, 0x00};
    expect(bad_method, 4, 100, AM_ERR_PARSE, "bad zlib header: method 9");
    const uint8_t dict[] = {0x78, 0xbb, 0, 0, 0, 0, 0x03, 0x00};
    expect(dict, sizeof dict, 100, AM_ERR_PARSE, "preset dictionary");
    const uint8_t reserved[] = {0x78, 0x01, 0x07, 0, 0, 0, 0};
    expect(reserved, sizeof reserved, 100, AM_ERR_PARSE, "reserved type 3");
    const uint8_t nlen[] = {0x78, 0x01, 0x01, 0x05, 0x00, 0x00, 0x00, 1, 2, 3, 4, 5};
    expect(nlen, sizeof nlen, 100, AM_ERR_PARSE, "length does not match its complement");
    expect(z_far, sizeof z_far, 100, AM_ERR_PARSE, "a distance reaching before the start of the output");
    expect(z_over, sizeof z_over, 100, AM_ERR_PARSE, "bad code lengths: an incomplete or over-subscribed code-length code");
    /* a wrong checksum, a missing one, a byte after it */
    memcpy(b, z_fixed, sizeof z_fixed);
    b[sizeof z_fixed - 1] ^= 1;
    expect(b, sizeof z_fixed, 100, AM_ERR_PARSE, "bad Adler-32: the stream says 5efa07aa, the data gives 5efa07ab");
    expect(z_fixed, sizeof z_fixed - 2, 100, AM_ERR_PARSE, "ends before its Adler-32");
    memcpy(b, z_fixed, sizeof z_fixed);
    b[sizeof z_fixed] = 0;
    expect(b, sizeof z_fixed + 1, 100, AM_ERR_PARSE, "1 bytes after the end of the zlib stream");
    /* too small an output: each block kind */
    expect(z_dynamic, sizeof z_dynamic, 100, AM_ERR_CAPACITY, "inflates to more bytes than the output holds");
    expect(z_fixed, sizeof z_fixed, 21, AM_ERR_CAPACITY, "inflates to more bytes than the output holds");
    expect(z_stored, sizeof z_stored, 27, AM_ERR_CAPACITY, "inflates to more bytes than the output holds");
    char err[AM_ERR_MAX];
    long len;
    CHECK(am_zlib_inflate(NULL, 3, out, 10, &len, &work, err, sizeof err) == AM_ERR_ARG, "no input");
}

/* every prefix of a stream fails cleanly: AM_ERR_PARSE with one line, nothing written past cap */
static void test_inflate_truncated(void)
{
    static const struct { const uint8_t* z; long n; } s[] = {{z_dynamic, sizeof z_dynamic}, {z_fixed, sizeof z_fixed}, {z_stored, sizeof z_stored}};
    int bad = 0;
    for (size_t k = 0; k < sizeof s / sizeof s[0]; k++)
        for (long n = 0; n < s[k].n; n++) {
            char err[AM_ERR_MAX] = "";
            long len = -1;
            am_status st = am_zlib_inflate(s[k].z, n, out, sizeof out, &len, &work, err, sizeof err);
            if (st != AM_ERR_PARSE || !err[0] || strchr(err, '\n') || len != 0) {
                if (!bad++) fprintf(stderr, "stream %d cut at %ld: status %d, '%s'\n", (int)k, n, st, err);
            }
        }
    CHECK(bad == 0, "%d truncated streams not refused cleanly", bad);
}

/* byte mutations of each stream: AM_OK within the output, or an error with one line of message
 * (never a crash, a read past the input or a write past the output: asan) */
static void test_inflate_fuzz(void)
{
    static uint8_t b[512], small[64];
    uint64_t r = 0x9E3779B97F4A7C15ull;
    int ok = 0, refused = 0, bad = 0;
    const int rounds = test_quick() ? 2000 : 30000;
    for (int i = 0; i < rounds; i++) {
        const uint8_t* z = i % 3 == 0 ? z_dynamic : i % 3 == 1 ? z_fixed : z_stored;
        long n = i % 3 == 0 ? (long)sizeof z_dynamic : i % 3 == 1 ? (long)sizeof z_fixed : (long)sizeof z_stored;
        memcpy(b, z, (size_t)n);
        int flips = 1 + (int)(i % 4);
        for (int f = 0; f < flips; f++) {
            r ^= r << 13, r ^= r >> 7, r ^= r << 17;
            b[2 + (long)(r % (uint64_t)(n - 2))] ^= (uint8_t)(1u << (r >> 40) % 8);
        }
        /* the checksum would refuse nearly every change: half the rounds skip it through the raw call */
        char err[AM_ERR_MAX] = "";
        long len = -1, used = -1;
        am_status st = i & 1 ? am_inflate_raw(b + 2, n - 2, small, sizeof small, &len, &used, &work, err, sizeof err)
                             : am_zlib_inflate(b, n, small, sizeof small, &len, &work, err, sizeof err);
        if (st == AM_OK) ok++;
        else refused++;
        if (st != AM_OK && (!err[0] || strchr(err, '\n'))) bad++;
        if (len < 0 || len > (long)sizeof small || (i & 1 && (used < 0 || used > n - 2))) bad++;
    }
    CHECK(bad == 0 && refused > 0 && ok > 0, "%d bad outcomes (%d inflated, %d refused)", bad, ok, refused);
}

int main(int argc, char** argv)
{
    TEST_INIT(argc, argv);
    RUN(test_inflate_block_kinds);
    RUN(test_inflate_errors);
    RUN(test_inflate_truncated);
    RUN(test_inflate_fuzz);
    return SUMMARY();
}
