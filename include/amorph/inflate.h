/* amorph/inflate.h: a zlib inflater (RFC 1950 streams of RFC 1951 deflate data), hand-written,
 * in fixed memory.
 *
 * The one decompressor of amorph: the VXA reader decodes Compression="ZLIB" layers with it and
 * the tests read PNG files with it. It works on caller buffers with a small caller workspace
 * (am_inflate_work, under 2 KB, no allocation), decodes the three block kinds (stored, fixed and
 * dynamic Huffman) and is strict: a bad header, a preset dictionary, a bad block type, a stored
 * length that does not match its complement, an over-subscribed or incomplete Huffman code (but
 * the one-code distance tree RFC 1951 allows), an invalid symbol, a distance reaching before the
 * start of the output, an output longer than the caller's buffer, input that ends early, a wrong
 * Adler-32 and bytes after the stream are each an error with its own one-line message.
 */
#ifndef AMORPH_INFLATE_H
#define AMORPH_INFLATE_H

#include <stdint.h>
#include "amorph/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* a canonical Huffman code: count[len] codes of each length, the symbols in code order */
typedef struct am_huffman {
    int16_t count[16];
    int16_t symbol[288];
} am_huffman;

/* the inflater's workspace: the literal/length and distance codes of the block being decoded */
typedef struct am_inflate_work {
    am_huffman lit, dist;
    int kinds[3];            /* blocks met: stored, fixed Huffman, dynamic Huffman */
} am_inflate_work;

/* inflates raw deflate data in[0..n) into out (capacity cap); *len gets the bytes written and
 * *used the input bytes consumed (through the last block's last byte). AM_ERR_PARSE for malformed
 * or truncated data, AM_ERR_CAPACITY when the output needs more than cap bytes. The message names
 * the input byte where decoding stopped. */
am_status am_inflate_raw(const uint8_t* in, long n, uint8_t* out, long cap, long* len, long* used, am_inflate_work* w,
                         char* err, int errsz);

/* inflates one zlib stream (2-byte header, deflate data, big-endian Adler-32 of the output) that
 * fills in[0..n) exactly into out (capacity cap); *len gets the bytes written. AM_ERR_PARSE for a
 * bad header or checksum, malformed or truncated data, or bytes after the checksum;
 * AM_ERR_CAPACITY as am_inflate_raw. */
am_status am_zlib_inflate(const uint8_t* in, long n, uint8_t* out, long cap, long* len, am_inflate_work* w, char* err,
                          int errsz);

#ifdef __cplusplus
}
#endif
#endif
