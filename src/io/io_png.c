/* CRC-32, Adler-32 and a PNG encoder (docs/pictures.md).
 *
 * The image data is one zlib stream (RFC 1950) of scanlines, each led by filter byte 0 (none).
 * The deflate stream (RFC 1951) is either stored blocks or a single block with the fixed Huffman
 * code. Matches are searched greedily at two distances only: one pixel back (runs of a colour)
 * and one scanline back (a row like the one above). Synthetic pictures are mostly such runs, so
 * this gets most of what a hash-chain matcher would, without any working memory. Every match of
 * 3 or more bytes costs fewer bits than its literals would (at most 25 bits for 3 bytes, 31 for
 * 4 and more, against 9 per literal), so the output never exceeds 9 bits per input byte. */
#include "amorph/io.h"

#include <string.h>

/* CRC-32 four bits at a time: the table of the reflected polynomial 0xEDB88320 for each nibble */
static const uint32_t crc_nibble[16] = {
    0x00000000u, 0x1DB71064u, 0x3B6E20C8u, 0x26D930ACu, 0x76DC4190u, 0x6B6B51F4u, 0x4DB26158u, 0x5005713Cu,
    0xEDB88320u, 0xF00F9344u, 0xD6D6A3E8u, 0xCB61B38Cu, 0x9B64C2B0u, 0x86D3D2D4u, 0xA00AE278u, 0xBDBDF21Cu};

uint32_t am_crc32(uint32_t crc, const void* data, long n)
{
    const uint8_t* p = (const uint8_t*)data;
    crc = ~crc;
    for (long i = 0; i < n; i++) {
        crc ^= p[i];
        crc = (crc >> 4) ^ crc_nibble[crc & 15u];
        crc = (crc >> 4) ^ crc_nibble[crc & 15u];
    }
    return ~crc;
}

uint32_t am_adler32(uint32_t adler, const void* data, long n)
{
    const uint8_t* p = (const uint8_t*)data;
    uint32_t a = adler & 0xFFFFu, b = adler >> 16;
    while (n > 0) {
        /* 5552 bytes is the most that cannot overflow 32 bits before the modulo */
        long k = n < 5552 ? n : 5552;
        n -= k;
        while (k-- > 0) {
            a += *p++;
            b += a;
        }
        a %= 65521u;
        b %= 65521u;
    }
    return (b << 16) | a;
}

/* ---- the scanline stream: row r is filter byte 0 then the row's w * ch bytes ---- */

typedef struct stream {
    const uint8_t* px;
    long rowbytes; /* 1 + w * ch */
    long n;        /* h * rowbytes */
} stream;

static inline uint8_t stream_at(const stream* s, long p)
{
    long r = p / s->rowbytes, c = p - r * s->rowbytes;
    return c == 0 ? 0 : s->px[r * (s->rowbytes - 1) + c - 1];
}

/* ---- output: bytes and an LSB-first bit writer ---- */

typedef struct sink {
    uint8_t* out;
    long cap, pos;
    uint32_t bits;
    int nbits;
    int full; /* 1 once something did not fit */
} sink;

static void put_byte(sink* k, uint8_t b)
{
    if (k->pos < k->cap) k->out[k->pos++] = b;
    else k->full = 1;
}

static void put_be32(sink* k, uint32_t v)
{
    put_byte(k, (uint8_t)(v >> 24));
    put_byte(k, (uint8_t)(v >> 16));
    put_byte(k, (uint8_t)(v >> 8));
    put_byte(k, (uint8_t)v);
}

static void put_bits(sink* k, uint32_t v, int n)
{
    k->bits |= v << k->nbits;
    k->nbits += n;
    while (k->nbits >= 8) {
        put_byte(k, (uint8_t)k->bits);
        k->bits >>= 8;
        k->nbits -= 8;
    }
}

static void flush_bits(sink* k)
{
    if (k->nbits > 0) put_byte(k, (uint8_t)k->bits);
    k->bits = 0;
    k->nbits = 0;
}

/* a Huffman code is sent most significant bit first */
static void put_code(sink* k, uint32_t code, int len)
{
    uint32_t r = 0;
    for (int i = 0; i < len; i++) r |= ((code >> i) & 1u) << (len - 1 - i);
    put_bits(k, r, len);
}

/* the fixed literal/length code (RFC 1951 3.2.6) */
static void put_fixed(sink* k, int sym)
{
    if (sym < 144) put_code(k, (uint32_t)(0x30 + sym), 8);
    else if (sym < 256) put_code(k, (uint32_t)(0x190 + sym - 144), 9);
    else if (sym < 280) put_code(k, (uint32_t)(sym - 256), 7);
    else put_code(k, (uint32_t)(0xC0 + sym - 280), 8);
}

static const uint16_t len_base[29] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27,
                                      31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
static const uint8_t len_extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const uint16_t dist_base[30] = {1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769,
                                       1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
static const uint8_t dist_extra[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

static void put_match(sink* k, int len, int dist)
{
    int i = 28;
    while (len_base[i] > len) i--;
    put_fixed(k, 257 + i);
    if (len_extra[i]) put_bits(k, (uint32_t)(len - len_base[i]), len_extra[i]);
    int j = 29;
    while (dist_base[j] > dist) j--;
    put_code(k, (uint32_t)j, 5);
    if (dist_extra[j]) put_bits(k, (uint32_t)(dist - dist_base[j]), dist_extra[j]);
}

/* length of the match at p against p - d, at most 258 */
static int match_len(const stream* s, long p, long d)
{
    int len = 0;
    while (len < 258 && p + len < s->n && stream_at(s, p + len) == stream_at(s, p + len - d)) len++;
    return len;
}

static void deflate_fixed(sink* k, const stream* s, int ch)
{
    put_bits(k, 1, 1); /* BFINAL */
    put_bits(k, 1, 2); /* BTYPE 01: fixed Huffman */
    long cand[2] = {ch, s->rowbytes};
    for (long p = 0; p < s->n && !k->full;) {
        int best = 0;
        long bestd = 0;
        for (int c = 0; c < 2; c++) {
            long d = cand[c];
            if (d > p || d > 32768) continue;
            int len = match_len(s, p, d);
            if (len > best) best = len, bestd = d;
        }
        if (best >= 3) {
            put_match(k, best, (int)bestd);
            p += best;
        } else {
            put_fixed(k, stream_at(s, p));
            p++;
        }
    }
    put_fixed(k, 256);
    flush_bits(k);
}

static void deflate_stored(sink* k, const stream* s)
{
    long p = 0;
    do {
        long n = s->n - p < 65535 ? s->n - p : 65535;
        put_byte(k, p + n == s->n ? 1 : 0); /* BFINAL, BTYPE 00, padding */
        put_byte(k, (uint8_t)n);
        put_byte(k, (uint8_t)(n >> 8));
        put_byte(k, (uint8_t)~n);
        put_byte(k, (uint8_t)(~n >> 8));
        for (long i = 0; i < n && !k->full; i++) put_byte(k, stream_at(s, p + i));
        p += n;
    } while (p < s->n && !k->full);
}

static void chunk_start(sink* k, long* at, uint32_t n, const char type[4])
{
    put_be32(k, n);
    *at = k->pos;
    for (int i = 0; i < 4; i++) put_byte(k, (uint8_t)type[i]);
}

static void chunk_end(sink* k, long at)
{
    if (k->full) return;
    put_be32(k, am_crc32(0, k->out + at, k->pos - at));
}

long am_png_max_size(int w, int h, int channels)
{
    if (w < 1 || h < 1 || w > AM_PNG_MAX_SIDE || h > AM_PNG_MAX_SIDE || (channels != 3 && channels != 4)) return 0;
    long raw = (long)h * (1 + (long)w * channels);
    long stored = raw + 5 * (raw / 65535 + 1);
    long fixed = raw + raw / 8 + 4;
    return (stored > fixed ? stored : fixed) + 8 + 25 + 12 + 6 + 12 + 16;
}

am_status am_png_encode(const uint8_t* pixels, int w, int h, int channels, int mode, uint8_t* out, long cap,
                        long* len, char* err, int errsz)
{
    *len = 0;
    if (!am_png_max_size(w, h, channels))
        return am_fail(err, errsz, AM_ERR_ARG, "png: bad image %d x %d x %d (sides 1..%d, 3 or 4 channels)", w, h,
                       channels, AM_PNG_MAX_SIDE);
    if (mode != AM_PNG_STORED && mode != AM_PNG_FIXED) return am_fail(err, errsz, AM_ERR_ARG, "png: bad mode %d", mode);
    sink k = {out, cap, 0, 0, 0, 0};
    static const uint8_t sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    for (int i = 0; i < 8; i++) put_byte(&k, sig[i]);

    long at;
    chunk_start(&k, &at, 13, "IHDR");
    put_be32(&k, (uint32_t)w);
    put_be32(&k, (uint32_t)h);
    put_byte(&k, 8);                          /* bit depth */
    put_byte(&k, channels == 4 ? 6 : 2);      /* colour type: RGBA or RGB */
    put_byte(&k, 0);                          /* deflate */
    put_byte(&k, 0);                          /* adaptive filtering (we use filter 0 only) */
    put_byte(&k, 0);                          /* no interlace */
    chunk_end(&k, at);

    stream s = {pixels, 1 + (long)w * channels, 0};
    s.n = (long)h * s.rowbytes;
    long len_at = k.pos;
    chunk_start(&k, &at, 0, "IDAT");
    put_byte(&k, 0x78); /* zlib: deflate, 32 KiB window */
    put_byte(&k, 0x01); /* no dictionary, fastest; (0x78 * 256 + 0x01) % 31 == 0 */
    if (mode == AM_PNG_FIXED) deflate_fixed(&k, &s, channels);
    else deflate_stored(&k, &s);
    uint32_t adler = 1;
    static const uint8_t zero = 0;
    for (int r = 0; r < h; r++) {
        adler = am_adler32(adler, &zero, 1);
        adler = am_adler32(adler, pixels + (long)r * (s.rowbytes - 1), s.rowbytes - 1);
    }
    put_be32(&k, adler);
    if (!k.full) {
        long n = k.pos - at - 4;
        out[len_at] = (uint8_t)(n >> 24);
        out[len_at + 1] = (uint8_t)(n >> 16);
        out[len_at + 2] = (uint8_t)(n >> 8);
        out[len_at + 3] = (uint8_t)n;
    }
    chunk_end(&k, at);

    chunk_start(&k, &at, 0, "IEND");
    chunk_end(&k, at);
    if (k.full)
        return am_fail(err, errsz, AM_ERR_CAPACITY, "png: %d x %d image does not fit in %ld bytes (needs up to %ld)", w,
                       h, cap, am_png_max_size(w, h, channels));
    *len = k.pos;
    return AM_OK;
}
