/* The zlib inflater (include/amorph/io.h): RFC 1950 around RFC 1951.
 *
 * Decoding follows the RFC's canonical codes directly: a code is held as the number of codes of
 * each length and its symbols in code order, and a symbol is decoded one bit at a time by
 * comparing the code read so far with the first code of each length (the method of zlib's
 * "puff"). That is slower than table lookup but needs 600 bytes per code and no table building
 * beyond a counting pass, which suits the small layers and test images it reads. Every read is
 * bounded: running out of input, output or a valid code stops the block with a message, and no
 * function recurses.
 */
#include "amorph/io.h"


#include <string.h>

typedef struct inf {
    const uint8_t* in;
    long n, pos;          /* input and the next byte to read */
    uint32_t bitbuf;      /* bits read, not yet used (low bits first) */
    int bitcnt;
    uint8_t* out;
    long cap, len;
    am_status st;         /* the first failure, AM_OK until then */
    char* err;
    int errsz;
} inf;

/* records the first failure (its message names the input byte reached) */
static void fail(inf* s, am_status code, const char* what)
{
    if (s->st != AM_OK) return;
    s->st = code;
    am_fail(s->err, s->errsz, code, "%s (deflate data, byte %ld)", what, s->pos);
}

/* need (0..16) bits, low bit first; 0 after a failure */
static int bits(inf* s, int need)
{
    uint32_t v = s->bitbuf;
    while (s->bitcnt < need) {
        if (s->pos >= s->n) {
            fail(s, AM_ERR_PARSE, "the compressed data ends early");
            return 0;
        }
        v |= (uint32_t)s->in[s->pos++] << s->bitcnt;
        s->bitcnt += 8;
    }
    s->bitbuf = need < 32 ? v >> need : 0;
    s->bitcnt -= need;
    return (int)(v & ((1u << need) - 1u));
}

/* the code of n symbols with these lengths (0: unused) into h; returns 0 for a complete code, > 0
 * for an incomplete one (the number of unused codes at the longest length), < 0 when
 * over-subscribed */
static int build(am_huffman* h, const int16_t* length, int n)
{
    int16_t offs[16];
    memset(h->count, 0, sizeof h->count);
    for (int i = 0; i < n; i++) h->count[length[i]]++;
    if (h->count[0] == n) return 0; /* no codes: complete, and any decode fails */
    int left = 1;
    for (int len = 1; len < 16; len++) {
        left <<= 1;
        left -= h->count[len];
        if (left < 0) return left;
    }
    offs[1] = 0;
    for (int len = 1; len < 15; len++) offs[len + 1] = (int16_t)(offs[len] + h->count[len]);
    for (int i = 0; i < n; i++)
        if (length[i] != 0) h->symbol[offs[length[i]]++] = (int16_t)i;
    return left;
}

/* one symbol of code h; -1 after a failure */
static int decode(inf* s, const am_huffman* h)
{
    int code = 0, first = 0, index = 0;
    for (int len = 1; len < 16; len++) {
        code |= bits(s, 1);
        if (s->st != AM_OK) return -1;
        const int count = h->count[len];
        if (code - count < first) return h->symbol[index + (code - first)];
        index += count;
        first += count;
        first <<= 1;
        code <<= 1;
    }
    fail(s, AM_ERR_PARSE, "a code that is not in the block's Huffman table");
    return -1;
}

static const int16_t len_base[29] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31,
                                     35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
static const int16_t len_extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const int16_t dist_base[30] = {1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769,
                                      1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
static const int16_t dist_extra[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

/* the literals and matches of one Huffman block, up to its end-of-block symbol */
static void codes(inf* s, const am_huffman* lit, const am_huffman* dist)
{
    for (;;) {
        int sym = decode(s, lit);
        if (sym < 0) return;
        if (sym < 256) {
            if (s->len >= s->cap) {
                fail(s, AM_ERR_CAPACITY, "the data inflates to more bytes than the output holds");
                return;
            }
            s->out[s->len++] = (uint8_t)sym;
            continue;
        }
        if (sym == 256) return;
        sym -= 257;
        if (sym >= 29) {
            fail(s, AM_ERR_PARSE, "an invalid length symbol (286 or 287)");
            return;
        }
        const long n = len_base[sym] + bits(s, len_extra[sym]);
        const int ds = decode(s, dist);
        if (ds < 0) return;
        if (ds >= 30) {
            fail(s, AM_ERR_PARSE, "an invalid distance symbol (30 or 31)");
            return;
        }
        const long d = dist_base[ds] + bits(s, dist_extra[ds]);
        if (s->st != AM_OK) return;
        if (d > s->len) {
            fail(s, AM_ERR_PARSE, "a distance reaching before the start of the output");
            return;
        }
        if (n > s->cap - s->len) {
            fail(s, AM_ERR_CAPACITY, "the data inflates to more bytes than the output holds");
            return;
        }
        for (long i = 0; i < n; i++, s->len++) s->out[s->len] = s->out[s->len - d];
    }
}

static void stored(inf* s)
{
    s->bitbuf = 0; /* the rest of the current byte is padding */
    s->bitcnt = 0;
    if (s->n - s->pos < 4) {
        fail(s, AM_ERR_PARSE, "the compressed data ends early");
        return;
    }
    const long len = s->in[s->pos] | (long)s->in[s->pos + 1] << 8;
    const long nlen = s->in[s->pos + 2] | (long)s->in[s->pos + 3] << 8;
    if (len != (~nlen & 0xFFFF)) {
        fail(s, AM_ERR_PARSE, "a stored block whose length does not match its complement");
        return;
    }
    s->pos += 4;
    if (s->n - s->pos < len) {
        fail(s, AM_ERR_PARSE, "the compressed data ends early");
        return;
    }
    if (len > s->cap - s->len) {
        fail(s, AM_ERR_CAPACITY, "the data inflates to more bytes than the output holds");
        return;
    }
    memcpy(s->out + s->len, s->in + s->pos, (size_t)len);
    s->len += len;
    s->pos += len;
}

static void fixed(inf* s, am_inflate_work* w)
{
    int16_t l[288];
    for (int i = 0; i < 288; i++) l[i] = (int16_t)(i < 144 ? 8 : i < 256 ? 9 : i < 280 ? 7 : 8);
    build(&w->lit, l, 288);
    for (int i = 0; i < 30; i++) l[i] = 5;
    build(&w->dist, l, 30);
    codes(s, &w->lit, &w->dist);
}

static void dynamic(inf* s, am_inflate_work* w)
{
    static const uint8_t order[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
    int16_t lengths[286 + 30];
    const int nlen = bits(s, 5) + 257, ndist = bits(s, 5) + 1, ncode = bits(s, 4) + 4;
    if (s->st != AM_OK) return;
    if (nlen > 286 || ndist > 30) {
        fail(s, AM_ERR_PARSE, "a dynamic block with more than 286 length or 30 distance codes");
        return;
    }
    memset(lengths, 0, sizeof lengths);
    for (int i = 0; i < ncode; i++) lengths[order[i]] = (int16_t)bits(s, 3);
    if (s->st != AM_OK) return;
    if (build(&w->lit, lengths, 19) != 0) { /* the code-length code must be complete */
        fail(s, AM_ERR_PARSE, "bad code lengths: an incomplete or over-subscribed code-length code");
        return;
    }
    int idx = 0;
    while (idx < nlen + ndist) {
        int sym = decode(s, &w->lit);
        if (sym < 0) return;
        if (sym < 16) {
            lengths[idx++] = (int16_t)sym;
            continue;
        }
        int rep, val = 0;
        if (sym == 16) {
            if (idx == 0) {
                fail(s, AM_ERR_PARSE, "bad code lengths: a repeat with no length before it");
                return;
            }
            val = lengths[idx - 1];
            rep = 3 + bits(s, 2);
        } else if (sym == 17) rep = 3 + bits(s, 3);
        else rep = 11 + bits(s, 7);
        if (s->st != AM_OK) return;
        if (idx + rep > nlen + ndist) {
            fail(s, AM_ERR_PARSE, "bad code lengths: a repeat past the last code");
            return;
        }
        while (rep--) lengths[idx++] = (int16_t)val;
    }
    if (lengths[256] == 0) {
        fail(s, AM_ERR_PARSE, "bad code lengths: no end-of-block code");
        return;
    }
    int left = build(&w->lit, lengths, nlen);
    if (left != 0) { /* an incomplete literal/length code is refused, as zlib refuses it */
        fail(s, AM_ERR_PARSE, "bad code lengths: an incomplete or over-subscribed literal/length code");
        return;
    }
    left = build(&w->dist, lengths + nlen, ndist);
    /* an incomplete distance code only as RFC 1951 allows it: one code of one bit (or none) */
    if (left < 0 || (left > 0 && !(ndist - w->dist.count[0] == 1 && w->dist.count[1] == 1))) {
        fail(s, AM_ERR_PARSE, "bad code lengths: an incomplete or over-subscribed distance code");
        return;
    }
    codes(s, &w->lit, &w->dist);
}

am_status am_inflate_raw(const uint8_t* in, long n, uint8_t* out, long cap, long* len, long* used, am_inflate_work* w,
                         char* err, int errsz)
{
    if (len) *len = 0;
    if (used) *used = 0;
    if (!in || n < 0 || !out || cap < 0 || !w) return am_fail(err, errsz, AM_ERR_ARG, "inflate: no input, output or workspace");
    inf s = {in, n, 0, 0, 0, out, cap, 0, AM_OK, err, errsz};
    w->kinds[0] = w->kinds[1] = w->kinds[2] = 0;
    int last = 0;
    while (!last && s.st == AM_OK) {
        last = bits(&s, 1);
        const int type = bits(&s, 2);
        if (s.st != AM_OK) break;
        if (type == 0) stored(&s);
        else if (type == 1) fixed(&s, w);
        else if (type == 2) dynamic(&s, w);
        else fail(&s, AM_ERR_PARSE, "a block of the reserved type 3");
        if (s.st == AM_OK && type < 3) w->kinds[type]++;
    }
    if (len) *len = s.len;
    if (used) *used = s.pos;
    return s.st;
}

am_status am_zlib_inflate(const uint8_t* in, long n, uint8_t* out, long cap, long* len, am_inflate_work* w, char* err,
                          int errsz)
{
    if (len) *len = 0;
    if (!in || n < 0 || !out || cap < 0 || !w) return am_fail(err, errsz, AM_ERR_ARG, "inflate: no input, output or workspace");
    if (n < 2) return am_fail(err, errsz, AM_ERR_PARSE, "zlib stream of %ld bytes: shorter than its header", n);
    const unsigned cmf = in[0], flg = in[1];
    if ((cmf & 15u) != 8u || (cmf >> 4) > 7u)
        return am_fail(err, errsz, AM_ERR_PARSE, "bad zlib header: method %u, window %u (deflate, at most 7, expected)", cmf & 15u,
                       cmf >> 4);
    if ((cmf * 256u + flg) % 31u != 0)
        return am_fail(err, errsz, AM_ERR_PARSE, "bad zlib header: check bits 0x%02x%02x not a multiple of 31", cmf, flg);
    if (flg & 0x20u) return am_fail(err, errsz, AM_ERR_PARSE, "bad zlib header: a preset dictionary is not supported");
    long got = 0, used = 0;
    am_status st = am_inflate_raw(in + 2, n - 2, out, cap, &got, &used, w, err, errsz);
    if (st != AM_OK) return st;
    const long at = 2 + used;
    if (n - at < 4) return am_fail(err, errsz, AM_ERR_PARSE, "the zlib stream ends before its Adler-32 checksum");
    const uint32_t want = (uint32_t)in[at] << 24 | (uint32_t)in[at + 1] << 16 | (uint32_t)in[at + 2] << 8 | in[at + 3];
    const uint32_t have = am_adler32(1, out, got);
    if (want != have)
        return am_fail(err, errsz, AM_ERR_PARSE, "bad Adler-32: the stream says %08lx, the data gives %08lx", (unsigned long)want,
                       (unsigned long)have);
    if (n - at > 4) return am_fail(err, errsz, AM_ERR_PARSE, "%ld bytes after the end of the zlib stream", n - at - 4);
    if (len) *len = got;
    return AM_OK;
}

am_status am_gzip_inflate(const uint8_t* in, long n, uint8_t* out, long cap, long* len, am_inflate_work* w, char* err,
                          int errsz)
{
    if (len) *len = 0;
    if (!in || n < 0 || !out || cap < 0 || !w) return am_fail(err, errsz, AM_ERR_ARG, "inflate: no input, output or workspace");
    if (n < 18 || in[0] != 0x1f || in[1] != 0x8b) return am_fail(err, errsz, AM_ERR_PARSE, "not a gzip file (no gzip header)");
    if (in[2] != 8) return am_fail(err, errsz, AM_ERR_PARSE, "bad gzip header: method %u (deflate, 8, expected)", (unsigned)in[2]);
    const unsigned flg = in[3];
    if (flg & 0xe0u) return am_fail(err, errsz, AM_ERR_PARSE, "bad gzip header: reserved flags 0x%02x", flg);
    long at = 10;
    if (flg & 4u) { /* FEXTRA: a length, then that many bytes */
        if (n - at < 2) return am_fail(err, errsz, AM_ERR_PARSE, "the gzip header ends in its extra field");
        at += 2 + (long)(in[at] | in[at + 1] << 8);
    }
    for (unsigned f = 8u; f <= 16u; f <<= 1) /* FNAME, FCOMMENT: NUL-terminated */
        if (flg & f) {
            while (at < n && in[at]) at++;
            at++;
        }
    if (flg & 2u) at += 2; /* FHCRC */
    if (n - at < 8) return am_fail(err, errsz, AM_ERR_PARSE, "the gzip file ends in its header");
    long got = 0, used = 0;
    am_status st = am_inflate_raw(in + at, n - at - 8, out, cap, &got, &used, w, err, errsz);
    if (st != AM_OK) return st;
    at += used;
    if (n - at < 8) return am_fail(err, errsz, AM_ERR_PARSE, "the gzip file ends before its CRC-32 and size");
    const uint32_t crc = (uint32_t)in[at] | (uint32_t)in[at + 1] << 8 | (uint32_t)in[at + 2] << 16 | (uint32_t)in[at + 3] << 24;
    const uint32_t size = (uint32_t)in[at + 4] | (uint32_t)in[at + 5] << 8 | (uint32_t)in[at + 6] << 16 | (uint32_t)in[at + 7] << 24;
    if (crc != am_crc32(0, out, got))
        return am_fail(err, errsz, AM_ERR_PARSE, "bad CRC-32: the file says %08lx, the data gives %08lx", (unsigned long)crc,
                       (unsigned long)am_crc32(0, out, got));
    if (size != (uint32_t)got) return am_fail(err, errsz, AM_ERR_PARSE, "the file says %lu bytes, the data holds %ld", (unsigned long)size, got);
    if (n - at > 8) return am_fail(err, errsz, AM_ERR_PARSE, "%ld bytes after the gzip member", n - at - 8);
    if (len) *len = got;
    return AM_OK;
}
