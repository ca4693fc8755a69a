/* CRC-32, Adler-32 and a PNG encoder (docs/pictures.md).
 *
 * The image data is one zlib stream (RFC 1950) of scanlines, each led by filter byte 0 (none).
 * The deflate stream (RFC 1951) is stored blocks, a single block with the fixed Huffman code, or
 * (AM_PNG_DYNAMIC) the smallest of those and a single block with codes made for the picture.
 * Matches are found greedily. The fixed mode looks at two distances only: one pixel back (runs of
 * a colour) and one scanline back (a row like the one above): 2 KiB of stack, the codes. The
 * dynamic mode also looks up the four latest positions of the same three bytes in a hash table on
 * the stack (16 KiB; 34 KiB of stack in all, make stack's frames), runs that matcher once to count
 * the symbols, builds Huffman codes of at most 15 bits from the counts and runs it again to write
 * them. Every
 * match of 3 or more bytes costs fewer bits under the fixed code than its literals would (at most
 * 25 bits for 3 bytes, 31 for 4 and more, against 9 per literal), and the dynamic mode writes a
 * fixed or stored block when that is smaller, so the output never exceeds 9 bits per input byte. */
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

static const uint16_t len_base[29] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27,
                                      31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
static const uint8_t len_extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const uint16_t dist_base[30] = {1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769,
                                       1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
static const uint8_t dist_extra[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

/* ---- Huffman codes: lengths from frequencies, canonical codes from lengths ---- */

/* literal/length symbols a block can use (the fixed code has 288, two never used), distance
 * symbols, code-length symbols */
enum { NLIT = 286, NFIXED = 288, NDIST = 30, NCL = 19 };

/* a code of up to NFIXED symbols: each one's length in bits (0: unused) and its canonical code */
typedef struct hcode {
    uint8_t len[NFIXED];
    uint16_t code[NFIXED];
} hcode;

/* the canonical codes of lengths len[0..n) (RFC 1951 3.2.2) */
static void canonical(hcode* c, int n)
{
    int count[16] = {0}, next[16];
    for (int i = 0; i < n; i++) count[c->len[i]]++;
    count[0] = 0;
    int code = 0;
    for (int b = 1; b < 16; b++) {
        code = (code + count[b - 1]) << 1;
        next[b] = code;
    }
    for (int i = 0; i < n; i++) c->code[i] = c->len[i] ? (uint16_t)next[c->len[i]]++ : 0;
}

/* Huffman code lengths of at most `limit` bits for the n symbols of frequencies f: the two least
 * weights joined first (ties to the lower index, so every platform builds the same code); when
 * the tree is deeper than `limit`, the leaves below it are lifted and shorter ones pushed down
 * until the code is complete again, and the lengths go to the symbols by frequency. At least two
 * symbols get a length (unused ones with weight 1 if need be), so the code is always complete. */
static void huff_lengths(const uint32_t* f, int n, int limit, uint8_t* len)
{
    uint32_t w[2 * NLIT];
    int16_t parent[2 * NLIT];
    uint8_t alive[2 * NLIT];
    int used = 0;
    for (int i = 0; i < n; i++) used += f[i] > 0;
    for (int i = 0; i < n; i++) {
        w[i] = f[i];
        if (!w[i] && used < 2) w[i] = 1, used++;
        alive[i] = w[i] > 0;
        parent[i] = -1;
        len[i] = 0;
    }
    int nodes = n;
    for (int left = used; left > 1; left--) {
        int a = -1, b = -1;
        for (int i = 0; i < nodes; i++) {
            if (!alive[i]) continue;
            if (a < 0 || w[i] < w[a]) b = a, a = i;
            else if (b < 0 || w[i] < w[b]) b = i;
        }
        w[nodes] = w[a] + w[b];
        alive[nodes] = 1, parent[nodes] = -1;
        alive[a] = alive[b] = 0;
        parent[a] = parent[b] = (int16_t)nodes;
        nodes++;
    }
    int count[32] = {0}, deepest = 0;
    for (int i = 0; i < n; i++) {
        if (!w[i]) continue;
        int d = 0;
        for (int p = parent[i]; p >= 0; p = parent[p]) d++;
        len[i] = (uint8_t)d;
        count[d < limit ? d : limit]++;
        if (d > deepest) deepest = d;
    }
    if (deepest <= limit) return;
    /* Kraft sum in units of 2^-limit: lifting leaves to `limit` made it exceed 1; each round takes
     * one leaf off the deepest level and splits a shallower leaf into two one level down */
    long total = 0;
    for (int d = 1; d <= limit; d++) total += (long)count[d] << (limit - d);
    while (total > (1L << limit)) {
        count[limit]--;
        for (int d = limit - 1; d > 0; d--)
            if (count[d]) {
                count[d]--;
                count[d + 1] += 2;
                break;
            }
        total--;
    }
    /* the shortest lengths to the most frequent symbols (ties to the lower index) */
    int order[NLIT], m = 0;
    for (int i = 0; i < n; i++)
        if (w[i]) {
            int j = m++;
            while (j > 0 && w[order[j - 1]] < w[i]) order[j] = order[j - 1], j--;
            order[j] = i;
        }
    int k = 0;
    for (int d = 1; d <= limit; d++)
        for (int c = 0; c < count[d]; c++) len[order[k++]] = (uint8_t)d;
}

/* ---- the matcher ---- */

/* recent positions of each 3-byte hash, newest first (positions modulo 65536: a candidate is always
 * checked byte by byte, so a stale one costs a comparison and never a wrong match) */
enum { HASH_BITS = 11, HASH_WAYS = 4 };
typedef struct png_hash {
    uint16_t pos[1 << HASH_BITS][HASH_WAYS];
} png_hash;

static unsigned hash_at(const stream* s, long p)
{
    uint32_t v = (uint32_t)stream_at(s, p) << 16 | (uint32_t)stream_at(s, p + 1) << 8 | stream_at(s, p + 2);
    return (unsigned)((v * 2654435761u) >> (32 - HASH_BITS));
}

static void hash_insert(png_hash* t, const stream* s, long p)
{
    if (p + 2 >= s->n) return;
    uint16_t* e = t->pos[hash_at(s, p)];
    for (int i = HASH_WAYS - 1; i > 0; i--) e[i] = e[i - 1];
    e[0] = (uint16_t)p;
}

/* length of the match at p against p - d, at most 258 */
static int match_len(const stream* s, long p, long d)
{
    int len = 0;
    while (len < 258 && p + len < s->n && stream_at(s, p + len) == stream_at(s, p + len - d)) len++;
    return len;
}

/* the longest match at p (0 when none of 3 bytes or more): one pixel back, one row back, then
 * (with a hash table) the recent positions of the same 3 bytes; ties to the first found */
static int best_match(const stream* s, long p, int ch, const png_hash* t, long* dist)
{
    long cand[2 + HASH_WAYS];
    int nc = 0;
    cand[nc++] = ch;
    cand[nc++] = s->rowbytes;
    if (t && p + 2 < s->n) {
        const uint16_t* e = t->pos[hash_at(s, p)];
        for (int i = 0; i < HASH_WAYS; i++) cand[nc++] = (long)(((unsigned long)p - e[i]) & 0xFFFFu);
    }
    int best = 0;
    for (int c = 0; c < nc; c++) {
        long d = cand[c];
        if (d < 1 || d > p || d > 32768) continue;
        int len = match_len(s, p, d);
        if (len > best) best = len, *dist = d;
    }
    return best >= 3 ? best : 0;
}

/* the symbols of the stream, matches found greedily: each literal's and match's symbols counted
 * (f_lit, f_dist, *extra the extra bits) when out is NULL, else written with the codes lit, dist */
static void deflate_symbols(const stream* s, int ch, png_hash* t, uint32_t* f_lit, uint32_t* f_dist, long* extra, sink* out,
                            const hcode* lit, const hcode* dist)
{
    if (t) memset(t, 0, sizeof *t);
    for (long p = 0; p < s->n && !(out && out->full);) {
        long d = 0;
        const int m = best_match(s, p, ch, t, &d);
        if (!m) {
            const int b = stream_at(s, p);
            if (out) put_code(out, lit->code[b], lit->len[b]);
            else f_lit[b]++;
            if (t) hash_insert(t, s, p);
            p++;
            continue;
        }
        int i = 28, j = 29;
        while (len_base[i] > m) i--;
        while (dist_base[j] > d) j--;
        if (out) {
            put_code(out, lit->code[257 + i], lit->len[257 + i]);
            if (len_extra[i]) put_bits(out, (uint32_t)(m - len_base[i]), len_extra[i]);
            put_code(out, dist->code[j], dist->len[j]);
            if (dist_extra[j]) put_bits(out, (uint32_t)(d - dist_base[j]), dist_extra[j]);
        } else {
            f_lit[257 + i]++;
            f_dist[j]++;
            *extra += len_extra[i] + dist_extra[j];
        }
        if (t)
            for (long q = p; q < p + m; q++) hash_insert(t, s, q);
        p += m;
    }
    if (out) put_code(out, lit->code[256], lit->len[256]);
    else f_lit[256]++;
}

/* the fixed codes (RFC 1951 3.2.6) */
static void fixed_codes(hcode* lit, hcode* dist)
{
    for (int i = 0; i < NFIXED; i++) lit->len[i] = (uint8_t)(i < 144 ? 8 : i < 256 ? 9 : i < 280 ? 7 : 8);
    for (int i = 0; i < NDIST; i++) dist->len[i] = 5;
    canonical(lit, NFIXED);
    canonical(dist, NDIST);
}

static void deflate_fixed(sink* k, const stream* s, int ch)
{
    static const hcode none;
    hcode lit = none, dist = none;
    fixed_codes(&lit, &dist);
    put_bits(k, 1, 1); /* BFINAL */
    put_bits(k, 1, 2); /* BTYPE 01: fixed Huffman */
    deflate_symbols(s, ch, NULL, NULL, NULL, NULL, k, &lit, &dist);
    flush_bits(k);
}

/* a dynamic block's header: the code lengths of lit (nlit) then dist (ndist), each run-length
 * coded on its own (16: the previous length 3-6 times, 17: 3-10 zeros, 18: 11-138 zeros) in the
 * code-length code. Written to out, or only its size in bits returned when out is NULL. */
static long dynamic_header(sink* out, const hcode* lit, int nlit, const hcode* dist, int ndist)
{
    static const uint8_t order[NCL] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
    uint8_t sym[NLIT + NDIST], ext[NLIT + NDIST];
    int nt = 0;
    for (int part = 0; part < 2; part++) {
        const uint8_t* l = part ? dist->len : lit->len;
        const int n = part ? ndist : nlit;
        for (int i = 0; i < n;) {
            int run = 1;
            while (i + run < n && l[i + run] == l[i]) run++;
            if (l[i] == 0 && run >= 3) {
                run = run > 138 ? 138 : run;
                sym[nt] = run >= 11 ? 18 : 17, ext[nt++] = (uint8_t)(run >= 11 ? run - 11 : run - 3);
            } else if (l[i] != 0 && run >= 4) {
                sym[nt] = l[i], ext[nt++] = 0; /* the length once, then repeats of it */
                run = run - 1 > 6 ? 6 : run - 1;
                sym[nt] = 16, ext[nt++] = (uint8_t)(run - 3);
                run++;
            } else {
                run = 1;
                sym[nt] = l[i], ext[nt++] = 0;
            }
            i += run;
        }
    }
    uint32_t f[NCL] = {0};
    for (int i = 0; i < nt; i++) f[sym[i]]++;
    hcode cl;
    huff_lengths(f, NCL, 7, cl.len);
    canonical(&cl, NCL);
    int ncl = NCL;
    while (ncl > 4 && cl.len[order[ncl - 1]] == 0) ncl--;
    static const uint8_t ext_bits[NCL] = {[16] = 2, [17] = 3, [18] = 7};
    long bits = 5 + 5 + 4 + 3L * ncl;
    for (int i = 0; i < nt; i++) bits += cl.len[sym[i]] + ext_bits[sym[i]];
    if (!out) return bits;
    put_bits(out, (uint32_t)(nlit - 257), 5);
    put_bits(out, (uint32_t)(ndist - 1), 5);
    put_bits(out, (uint32_t)(ncl - 4), 4);
    for (int i = 0; i < ncl; i++) put_bits(out, cl.len[order[i]], 3);
    for (int i = 0; i < nt; i++) {
        put_code(out, cl.code[sym[i]], cl.len[sym[i]]);
        if (ext_bits[sym[i]]) put_bits(out, ext[i], ext_bits[sym[i]]);
    }
    return bits;
}

/* bits of the symbols counted in f under code c */
static long coded_bits(const uint32_t* f, const hcode* c, int n)
{
    long bits = 0;
    for (int i = 0; i < n; i++) bits += (long)f[i] * c->len[i];
    return bits;
}

/* the smallest of three: a block of codes made for this picture (matches found at one pixel, one
 * row and, through a hash table of recent 3-byte strings, anywhere in the 32 KiB window), a fixed
 * block of the same symbols, or stored blocks. Two passes of the same matcher: one counts the
 * symbols, one writes them. Returns 0 when it wrote nothing because stored blocks are smaller. */
static int deflate_dynamic(sink* k, const stream* s, int ch)
{
    png_hash t;
    uint32_t f_lit[NLIT] = {0}, f_dist[NDIST] = {0};
    long extra = 0;
    deflate_symbols(s, ch, &t, f_lit, f_dist, &extra, NULL, NULL, NULL);
    static const hcode none;
    hcode lit = none, dist = none, flit = none, fdist = none;
    huff_lengths(f_lit, NLIT, 15, lit.len);
    huff_lengths(f_dist, NDIST, 15, dist.len);
    canonical(&lit, NLIT);
    canonical(&dist, NDIST);
    fixed_codes(&flit, &fdist);
    int nlit = NLIT, ndist = NDIST;
    while (nlit > 257 && lit.len[nlit - 1] == 0) nlit--;
    while (ndist > 1 && dist.len[ndist - 1] == 0) ndist--;
    const long dyn = 3 + dynamic_header(NULL, &lit, nlit, &dist, ndist) + coded_bits(f_lit, &lit, NLIT) +
                     coded_bits(f_dist, &dist, NDIST) + extra;
    const long fix = 3 + coded_bits(f_lit, &flit, NLIT) + coded_bits(f_dist, &fdist, NDIST) + extra;
    const long stored = 8 * (s->n + 5 * (s->n / 65535 + 1));
    if (stored < dyn && stored < fix) return 0;
    put_bits(k, 1, 1); /* BFINAL */
    if (fix <= dyn) {
        put_bits(k, 1, 2); /* BTYPE 01: fixed Huffman */
        deflate_symbols(s, ch, &t, NULL, NULL, NULL, k, &flit, &fdist);
    } else {
        put_bits(k, 2, 2); /* BTYPE 10: dynamic Huffman */
        dynamic_header(k, &lit, nlit, &dist, ndist);
        deflate_symbols(s, ch, &t, NULL, NULL, NULL, k, &lit, &dist);
    }
    flush_bits(k);
    return 1;
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
    if (mode != AM_PNG_STORED && mode != AM_PNG_FIXED && mode != AM_PNG_DYNAMIC)
        return am_fail(err, errsz, AM_ERR_ARG, "png: bad mode %d", mode);
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
    else if (mode == AM_PNG_STORED || !deflate_dynamic(&k, &s, channels)) deflate_stored(&k, &s);
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
