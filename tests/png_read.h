/* tests/png_read.h: a small PNG reader for the tests (test code only; the library only writes).
 *
 * png_decode checks the signature, every chunk's CRC-32 (computed here bit by bit, independently
 * of the library's table), the zlib header and the Adler-32 of the inflated data, inflates the
 * IDAT stream (stored, fixed and dynamic Huffman blocks: screenshots from browsers use all
 * three), undoes the five scanline filters and returns 8-bit RGB pixels (RGBA is composited on
 * white, grey and palette images are expanded). Bit depth 8 only, no interlace. */
#ifndef AMORPH_TEST_PNG_READ_H
#define AMORPH_TEST_PNG_READ_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct png_image {
    int w, h;
    int color_type;      /* as in the file */
    int stored_blocks, fixed_blocks, dynamic_blocks; /* deflate block kinds met */
    int chunks;          /* chunks read, all with a good CRC */
    uint8_t* rgb;        /* w * h * 3, malloc'd; png_free releases it */
} png_image;

static uint32_t png_ref_crc(const uint8_t* p, long n)
{
    uint32_t c = 0xFFFFFFFFu;
    for (long i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++) c = c & 1 ? (c >> 1) ^ 0xEDB88320u : c >> 1;
    }
    return ~c;
}

static uint32_t png_ref_adler(const uint8_t* p, long n)
{
    uint32_t a = 1, b = 0;
    for (long i = 0; i < n; i++) {
        a = (a + p[i]) % 65521u;
        b = (b + a) % 65521u;
    }
    return b << 16 | a;
}

/* ---- inflate (RFC 1951) ---- */

typedef struct inf_state {
    const uint8_t* in;
    long n, pos;
    uint32_t bitbuf;
    int bitcnt;
    uint8_t* out;
    long cap, len;
    int bad;
} inf_state;

static int inf_bits(inf_state* s, int need)
{
    uint32_t v = s->bitbuf;
    while (s->bitcnt < need) {
        if (s->pos >= s->n) {
            s->bad = 1;
            return 0;
        }
        v |= (uint32_t)s->in[s->pos++] << s->bitcnt;
        s->bitcnt += 8;
    }
    s->bitbuf = v >> need;
    s->bitcnt -= need;
    return (int)(v & ((1u << need) - 1));
}

typedef struct inf_huff {
    short count[16];
    short symbol[320];
} inf_huff;

/* canonical code from lengths; returns 0 when complete or incomplete-but-usable */
static void inf_build(inf_huff* h, const short* length, int n)
{
    short offs[16];
    memset(h->count, 0, sizeof h->count);
    for (int s = 0; s < n; s++) h->count[length[s]]++;
    offs[1] = 0;
    for (int l = 1; l < 15; l++) offs[l + 1] = (short)(offs[l] + h->count[l]);
    for (int s = 0; s < n; s++)
        if (length[s]) h->symbol[offs[length[s]]++] = (short)s;
}

static int inf_decode(inf_state* s, const inf_huff* h)
{
    int code = 0, first = 0, index = 0;
    for (int len = 1; len < 16; len++) {
        code |= inf_bits(s, 1);
        int count = h->count[len];
        if (code - count < first) return h->symbol[index + (code - first)];
        index += count;
        first += count;
        first <<= 1;
        code <<= 1;
        if (s->bad) return -1;
    }
    s->bad = 1;
    return -1;
}

static void inf_put(inf_state* s, uint8_t b)
{
    if (s->len < s->cap) s->out[s->len++] = b;
    else s->bad = 1;
}

static const short inf_lbase[29] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31,
                                    35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
static const short inf_lext[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const short inf_dbase[30] = {1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769,
                                    1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
static const short inf_dext[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

static void inf_codes(inf_state* s, const inf_huff* lit, const inf_huff* dist)
{
    for (;;) {
        int sym = inf_decode(s, lit);
        if (s->bad || sym < 0) return;
        if (sym < 256) inf_put(s, (uint8_t)sym);
        else if (sym == 256) return;
        else {
            sym -= 257;
            if (sym >= 29) {
                s->bad = 1;
                return;
            }
            int len = inf_lbase[sym] + inf_bits(s, inf_lext[sym]);
            int ds = inf_decode(s, dist);
            if (ds < 0 || ds >= 30) {
                s->bad = 1;
                return;
            }
            long d = inf_dbase[ds] + inf_bits(s, inf_dext[ds]);
            if (d > s->len) {
                s->bad = 1;
                return;
            }
            for (int i = 0; i < len && !s->bad; i++) inf_put(s, s->out[s->len - d]);
        }
        if (s->bad) return;
    }
}

/* inflates a raw deflate stream; returns the length written or -1; counts block kinds */
static long inflate_raw(const uint8_t* in, long n, uint8_t* out, long cap, long* used, int kinds[3])
{
    inf_state s;
    memset(&s, 0, sizeof s);
    s.in = in, s.n = n, s.out = out, s.cap = cap;
    int last = 0;
    while (!last && !s.bad) {
        last = inf_bits(&s, 1);
        int type = inf_bits(&s, 2);
        if (type == 0) {
            s.bitbuf = 0, s.bitcnt = 0;
            if (s.pos + 4 > s.n) return -1;
            unsigned len = s.in[s.pos] | (unsigned)s.in[s.pos + 1] << 8;
            unsigned nlen = s.in[s.pos + 2] | (unsigned)s.in[s.pos + 3] << 8;
            s.pos += 4;
            if (len != (~nlen & 0xFFFFu) || s.pos + (long)len > s.n) return -1;
            for (unsigned i = 0; i < len; i++) inf_put(&s, s.in[s.pos + i]);
            s.pos += len;
            kinds[0]++;
        } else if (type == 1) {
            static inf_huff lit, dist;
            short l[288];
            for (int i = 0; i < 288; i++) l[i] = (short)(i < 144 ? 8 : i < 256 ? 9 : i < 280 ? 7 : 8);
            inf_build(&lit, l, 288);
            for (int i = 0; i < 30; i++) l[i] = 5;
            inf_build(&dist, l, 30);
            inf_codes(&s, &lit, &dist);
            kinds[1]++;
        } else if (type == 2) {
            static const short order[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
            int nlen = inf_bits(&s, 5) + 257, ndist = inf_bits(&s, 5) + 1, ncode = inf_bits(&s, 4) + 4;
            if (nlen > 286 || ndist > 30) return -1;
            short lengths[320];
            memset(lengths, 0, sizeof lengths);
            for (int i = 0; i < ncode; i++) lengths[order[i]] = (short)inf_bits(&s, 3);
            static inf_huff lencode, lit, dist;
            inf_build(&lencode, lengths, 19);
            int idx = 0;
            while (idx < nlen + ndist && !s.bad) {
                int sym = inf_decode(&s, &lencode);
                if (sym < 0) return -1;
                if (sym < 16) lengths[idx++] = (short)sym;
                else {
                    int rep, val = 0;
                    if (sym == 16) {
                        if (idx == 0) return -1;
                        val = lengths[idx - 1];
                        rep = 3 + inf_bits(&s, 2);
                    } else if (sym == 17) rep = 3 + inf_bits(&s, 3);
                    else rep = 11 + inf_bits(&s, 7);
                    if (idx + rep > nlen + ndist) return -1;
                    while (rep--) lengths[idx++] = (short)val;
                }
            }
            inf_build(&lit, lengths, nlen);
            inf_build(&dist, lengths + nlen, ndist);
            inf_codes(&s, &lit, &dist);
            kinds[2]++;
        } else return -1;
    }
    if (s.bad) return -1;
    *used = s.pos;
    return s.len;
}

static uint32_t png_be32(const uint8_t* p) { return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3]; }

static int png_paeth(int a, int b, int c)
{
    int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/* decodes a PNG file held in memory; 0 on success, else -1 with a reason in why */
static int png_decode(const uint8_t* f, long n, png_image* img, char* why, int whysz)
{
    static const uint8_t sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    memset(img, 0, sizeof *img);
    if (n < 8 || memcmp(f, sig, 8)) return snprintf(why, (size_t)whysz, "no PNG signature"), -1;
    uint8_t* z = 0;
    long zn = 0, pos = 8;
    int depth = 0, interlace = 0, ended = 0;
    uint8_t pal[256][3];
    memset(pal, 0, sizeof pal);
    while (pos + 12 <= n && !ended) {
        uint32_t len = png_be32(f + pos);
        if (len > (uint32_t)(n - pos - 12)) return free(z), snprintf(why, (size_t)whysz, "chunk past the end"), -1;
        const uint8_t* type = f + pos + 4;
        const uint8_t* data = f + pos + 8;
        if (png_ref_crc(type, (long)len + 4) != png_be32(data + len))
            return free(z), snprintf(why, (size_t)whysz, "bad CRC in chunk %.4s", (const char*)type), -1;
        img->chunks++;
        if (!memcmp(type, "IHDR", 4)) {
            img->w = (int)png_be32(data), img->h = (int)png_be32(data + 4);
            depth = data[8], img->color_type = data[9], interlace = data[12];
        } else if (!memcmp(type, "PLTE", 4)) {
            for (uint32_t i = 0; i < len / 3 && i < 256; i++) memcpy(pal[i], data + 3 * i, 3);
        } else if (!memcmp(type, "IDAT", 4)) {
            uint8_t* nz = (uint8_t*)realloc(z, (size_t)(zn + (long)len + 1));
            if (!nz) return free(z), snprintf(why, (size_t)whysz, "out of memory"), -1;
            z = nz;
            memcpy(z + zn, data, len);
            zn += len;
        } else if (!memcmp(type, "IEND", 4)) ended = 1;
        pos += 12 + (long)len;
    }
    if (!ended) return free(z), snprintf(why, (size_t)whysz, "no IEND"), -1;
    int ch = img->color_type == 2 ? 3 : img->color_type == 6 ? 4 : img->color_type == 0 ? 1 : img->color_type == 4 ? 2 : img->color_type == 3 ? 1 : 0;
    if (depth != 8 || interlace || !ch || img->w < 1 || img->h < 1)
        return free(z), snprintf(why, (size_t)whysz, "unsupported PNG (depth %d, type %d, interlace %d)", depth, img->color_type, interlace), -1;
    if (zn < 6 || ((z[0] << 8) | z[1]) % 31 || (z[0] & 15) != 8)
        return free(z), snprintf(why, (size_t)whysz, "bad zlib header"), -1;
    long stride = (long)img->w * ch, rawn = (stride + 1) * img->h, used = 0;
    uint8_t* raw = (uint8_t*)malloc((size_t)rawn + 1);
    int kinds[3] = {0, 0, 0};
    long got = raw ? inflate_raw(z + 2, zn - 2, raw, rawn, &used, kinds) : -1;
    if (got != rawn) return free(z), free(raw), snprintf(why, (size_t)whysz, "inflate failed (%ld of %ld bytes)", got, rawn), -1;
    if (2 + used + 4 > zn || png_ref_adler(raw, rawn) != png_be32(z + 2 + used))
        return free(z), free(raw), snprintf(why, (size_t)whysz, "bad Adler-32"), -1;
    img->stored_blocks = kinds[0], img->fixed_blocks = kinds[1], img->dynamic_blocks = kinds[2];
    free(z);
    /* unfilter in place */
    for (int y = 0; y < img->h; y++) {
        uint8_t* row = raw + y * (stride + 1);
        uint8_t* cur = row + 1;
        const uint8_t* prev = y ? raw + (y - 1) * (stride + 1) + 1 : 0;
        int ft = row[0];
        if (ft > 4) return free(raw), snprintf(why, (size_t)whysz, "bad filter %d on row %d", ft, y), -1;
        for (long x = 0; x < stride; x++) {
            int a = x >= ch ? cur[x - ch] : 0, b = prev ? prev[x] : 0, c = prev && x >= ch ? prev[x - ch] : 0;
            int add = ft == 1 ? a : ft == 2 ? b : ft == 3 ? (a + b) / 2 : ft == 4 ? png_paeth(a, b, c) : 0;
            cur[x] = (uint8_t)(cur[x] + add);
        }
    }
    img->rgb = (uint8_t*)malloc((size_t)img->w * img->h * 3);
    if (!img->rgb) return free(raw), snprintf(why, (size_t)whysz, "out of memory"), -1;
    for (int y = 0; y < img->h; y++)
        for (int x = 0; x < img->w; x++) {
            const uint8_t* p = raw + y * (stride + 1) + 1 + (long)x * ch;
            uint8_t* o = img->rgb + ((long)y * img->w + x) * 3;
            if (img->color_type == 3) memcpy(o, pal[p[0]], 3);
            else if (ch <= 2) o[0] = o[1] = o[2] = p[0];
            else memcpy(o, p, 3);
            int alpha = ch == 4 ? p[3] : ch == 2 ? p[1] : 255;
            for (int k = 0; k < 3; k++) o[k] = (uint8_t)((o[k] * alpha + 255 * (255 - alpha) + 127) / 255);
        }
    free(raw);
    return 0;
}

static void png_free(png_image* img)
{
    free(img->rgb);
    img->rgb = 0;
}

/* reads and decodes a PNG file */
static int png_read_file(const char* path, png_image* img, char* why, int whysz)
{
    FILE* fp = fopen(path, "rb");
    if (!fp) return snprintf(why, (size_t)whysz, "%s: cannot open", path), -1;
    fseek(fp, 0, SEEK_END);
    long n = ftell(fp);
    fseek(fp, 0, SEEK_SET);
    uint8_t* buf = (uint8_t*)malloc((size_t)n + 1);
    if (!buf || fread(buf, 1, (size_t)n, fp) != (size_t)n) {
        fclose(fp);
        free(buf);
        return snprintf(why, (size_t)whysz, "%s: cannot read", path), -1;
    }
    fclose(fp);
    int r = png_decode(buf, n, img, why, whysz);
    free(buf);
    return r;
}

/* 1 when pixel p looks like colour c under flat shading: p = k c for some k in [0.3, 1.05],
 * within tol per channel (chromaticity and a plausible brightness) */
static int png_shade_of(const uint8_t* p, const uint8_t* c, double tol)
{
    double cc = (double)c[0] * c[0] + (double)c[1] * c[1] + (double)c[2] * c[2];
    if (cc < 1) return 0;
    double k = ((double)p[0] * c[0] + (double)p[1] * c[1] + (double)p[2] * c[2]) / cc;
    if (k < 0.3 || k > 1.05) return 0;
    for (int j = 0; j < 3; j++)
        if (fabs(p[j] - k * c[j]) > tol) return 0;
    return 1;
}

#endif
