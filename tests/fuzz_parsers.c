/* tests/fuzz_parsers.c: one libFuzzer target over every reader of outside input. The first byte of
 * an input picks the reader, the rest is its text:
 *   0 lattice file          1 genome file           2 configuration (key = value)
 *   3 checkpoint            4 VXA (XML; ZLIB layers, PhaseOffset, regions)
 *   5 VXA + VXD (the text split at its first byte 0x01: base, then the VXD over it)
 *   6 zlib stream (the inflater of VXA's compressed layers)
 *   7 log.csv (the log reader, line by line)
 * Besides the sanitizers' checks (built with ASan and UBSan), every reader must fail cleanly: a
 * status that is AM_OK or an error, and then a message of one line that fits its buffer. A
 * reader that accepts its input must accept what it writes back (lattice, genome, config).
 *   make fuzz [FUZZ_SECONDS=60]  (clang's libFuzzer; the seed corpus is tests/data)
 * `make test` runs it for a fixed count of inputs from a fixed seed when clang has libFuzzer. */
#include "amorph.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FUZZ_MAX (1 << 20)

static char g_text[FUZZ_MAX + 1], g_text2[FUZZ_MAX + 1];
static char g_out[AM_LATTICE_TEXT_MAX + AM_EVO_CHECKPOINT_MAX(AM_MAX_POPULATION)];
static am_lattice g_lat;
static am_genome g_genome;
static am_evo g_evo;
static am_xml_doc g_doc, g_doc2;
static uint8_t g_raw[1 << 20];
static am_inflate_work g_iw;

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

/* a reader's message after a failure: non-empty, one line, NUL-terminated in its buffer */
static void check_message(am_status st, const char* err, size_t cap)
{
    if (st == AM_OK) return;
    const char* nul = memchr(err, 0, cap);
    size_t n = nul ? (size_t)(nul - err) : cap;
    if (n == 0 || n >= cap || memchr(err, '\n', n) != NULL) {
        fprintf(stderr, "fuzz: status %d with a bad message: '%.*s'\n", (int)st, (int)(n < cap ? n : cap), err);
        abort();
    }
}

static void must(int ok, const char* what)
{
    if (!ok) {
        fprintf(stderr, "fuzz: %s\n", what);
        abort();
    }
}

int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    char err[AM_ERR_MAX];
    if (size < 1 || size > FUZZ_MAX) return 0;
    const int kind = data[0] % 8;
    const size_t n = size - 1;
    memcpy(g_text, data + 1, n);
    g_text[n] = 0;
    err[0] = 0;
    am_status st;
    long len = 0;
    switch (kind) {
    case 0:
        st = am_lattice_parse(&g_lat, g_text, "fuzz.lattice", err, sizeof err);
        check_message(st, err, sizeof err);
        if (st == AM_OK) {
            must(am_lattice_format(&g_lat, g_out, sizeof g_out, &len, err, sizeof err) == AM_OK, "an accepted lattice does not format");
            must(am_lattice_parse(&g_lat, g_out, "again", err, sizeof err) == AM_OK, "a formatted lattice is refused");
        }
        break;
    case 1:
        st = am_genome_parse(&g_genome, g_text, "fuzz.genome", err, sizeof err);
        check_message(st, err, sizeof err);
        if (st == AM_OK) {
            must(am_genome_format(&g_genome, g_out, sizeof g_out, &len, err, sizeof err) == AM_OK, "an accepted genome does not format");
            must(am_genome_parse(&g_genome, g_out, "again", err, sizeof err) == AM_OK, "a formatted genome is refused");
        }
        break;
    case 2: {
        am_evo_def d = am_default_evo();
        st = am_evo_parse(&d, g_text, "fuzz.cfg", err, sizeof err);
        check_message(st, err, sizeof err);
        if (st == AM_OK && am_evo_check(&d, err, sizeof err) == AM_OK) {
            must(am_evo_format(&d, 1, g_out, sizeof g_out, &len, err, sizeof err) == AM_OK, "an accepted config does not format");
            am_evo_def e = am_default_evo();
            must(am_evo_parse(&e, g_out, "again", err, sizeof err) == AM_OK, "a formatted config is refused");
        }
        break;
    }
    case 3:
        st = am_evo_checkpoint_parse(&g_evo, g_text, "fuzz.ckpt", err, sizeof err);
        check_message(st, err, sizeof err);
        break;
    case 4: {
        am_vxa_info info;
        st = am_vxa_parse(&g_lat, &info, &g_doc, g_text, "fuzz.vxa", err, sizeof err);
        check_message(st, err, sizeof err);
        break;
    }
    case 5: {
        am_vxa_info info;
        char* cut = memchr(g_text, 1, n);
        const char* vxd = "";
        if (cut) {
            *cut = 0;
            vxd = cut + 1;
        }
        memcpy(g_text2, vxd, strlen(vxd) + 1);
        st = am_vxa_parse_vxd(&g_lat, &info, &g_doc, g_text, "fuzz.vxa", &g_doc2, g_text2, "fuzz.vxd", err, sizeof err);
        check_message(st, err, sizeof err);
        break;
    }
    case 6:
        st = am_zlib_inflate(data + 1, (long)n, g_raw, (long)sizeof g_raw, &len, &g_iw, err, sizeof err);
        check_message(st, err, sizeof err);
        must(st != AM_OK || (len >= 0 && len <= (long)sizeof g_raw), "inflate: a length out of range");
        break;
    default: {
        am_evo_log_reader r;
        am_evo_stats row;
        am_evo_log_read_begin(&r, "fuzz.log");
        st = AM_OK;
        char* line = g_text;
        while (st == AM_OK && *line) {
            char* end = strchr(line, '\n');
            long k = end ? (long)(end - line) : (long)strlen(line);
            int is_row = 0;
            st = am_evo_log_read_line(&r, line, k, &row, &is_row, err, sizeof err);
            line += k + (end ? 1 : 0);
        }
        if (st == AM_OK) st = am_evo_log_read_end(&r, err, sizeof err);
        check_message(st, err, sizeof err);
        break;
    }
    }
    return 0;
}
