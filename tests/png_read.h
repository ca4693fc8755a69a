/* tests/png_read.h: a small PNG reader for the tests (test code only; the library writes PNGs).
 *
 * png_decode checks the signature and every chunk's CRC-32 (computed here bit by bit, independently
 * of the library's table), inflates the IDAT stream with the library's inflater, amorph/io.h
 * (which checks the zlib header and the Adler-32; stored, fixed and dynamic Huffman blocks:
 * screenshots from browsers use all three), undoes the five scanline filters and returns 8-bit
 * RGB pixels (RGBA is composited on white, grey and palette images are expanded). Bit depth 8
 * only, no interlace. */
#ifndef AMORPH_TEST_PNG_READ_H
#define AMORPH_TEST_PNG_READ_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "amorph/io.h"

typedef struct png_image {
    int w, h;
    int color_type;      /* as in the file */
    int stored_blocks, fixed_blocks, dynamic_blocks; /* deflate block kinds met */
    int lit_bits;        /* the longest literal/length code of the last Huffman block */
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

/* Adler-32 computed the plain way, a reference for the library's am_adler32 */
static uint32_t png_ref_adler(const uint8_t* p, long n)
{
    uint32_t a = 1, b = 0;
    for (long i = 0; i < n; i++) {
        a = (a + p[i]) % 65521u;
        b = (b + a) % 65521u;
    }
    return b << 16 | a;
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
    long stride = (long)img->w * ch, rawn = (stride + 1) * img->h, got = 0;
    uint8_t* raw = (uint8_t*)malloc((size_t)rawn + 1);
    static am_inflate_work iw; /* the library's inflater (amorph/io.h): header, data, Adler-32 */
    char ierr[256];
    if (!raw) return free(z), snprintf(why, (size_t)whysz, "out of memory"), -1;
    if (am_zlib_inflate(z, zn, raw, rawn, &got, &iw, ierr, sizeof ierr) != AM_OK)
        return free(z), free(raw), snprintf(why, (size_t)whysz, "inflate failed: %s", ierr), -1;
    if (got != rawn) return free(z), free(raw), snprintf(why, (size_t)whysz, "inflate gave %ld of %ld bytes", got, rawn), -1;
    int kinds[3] = {iw.kinds[0], iw.kinds[1], iw.kinds[2]};
    img->stored_blocks = kinds[0], img->fixed_blocks = kinds[1], img->dynamic_blocks = kinds[2];
    for (int b = 1; b < 16; b++)
        if (iw.lit.count[b]) img->lit_bits = b;
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
