/* Text files for the commands: written through a small buffer into a port stream (an atomic
 * replace) or onto the standard output, and read line by line.
 *
 * Reading has two sources behind one interface. The desktop profile reads a file whole into
 * one buffer, as amorph always did (a file larger than the buffer is refused whole), and hands
 * out its lines in place. The board profile streams the file through one line buffer
 * (TOOL_LINE_MAX characters), so a file of any length needs no more RAM than its longest line.
 * Both cut lines at '\n' the same way, so the parsers above see the same lines either way. */
#include "cmd.h"

#include <stdio.h>
#include <string.h>

/* ---- writing ---- */

static char out_buf[TOOL_OUT_BUF];
static int out_busy; /* 1 while a tool_out uses out_buf */

/* the flush of a tool_out: the port stream, or the standard output */
static am_status out_flush(void* ctx, const char* data, long n)
{
    tool_out* o = (tool_out*)ctx;
    if (!o->path) {
        if (fwrite(data, 1, (size_t)n, stdout) != (size_t)n) {
            snprintf(o->err, sizeof o->err, "cannot write to the standard output");
            return AM_ERR_IO;
        }
        return AM_OK;
    }
    return am_port_write(o->stream, data, n, o->err, sizeof o->err);
}

int tool_out_open(tool_out* o, const char* path)
{
    memset(o, 0, sizeof *o);
    o->path = path;
    o->stream = -1;
    if (out_busy) {
        fprintf(stderr, "amorph: %s: another output is open\n", path ? path : "standard output");
        return 1;
    }
    if (path && am_port_open_write(path, &o->stream, o->err, sizeof o->err) != AM_OK) {
        fprintf(stderr, "amorph: %s\n", o->err);
        return 1;
    }
    out_busy = 1;
    am_text t = {out_buf, sizeof out_buf, 0, 0, out_flush, o, 0};
    o->text = t;
    out_buf[0] = 0;
    return 0;
}

int tool_out_close(tool_out* o, int commit)
{
    char err[AM_ERR_MAX];
    int bad = 0;
    out_busy = 0;
    if (commit) {
        am_status st = am_text_flush(&o->text);
        if (st == AM_ERR_CAPACITY) snprintf(o->err, sizeof o->err, "%s: a piece of text longer than the %d-byte buffer",
                                            o->path ? o->path : "standard output", TOOL_OUT_BUF);
        if (st != AM_OK) {
            fprintf(stderr, "amorph: %s\n", o->err);
            commit = 0, bad = 1;
        }
    }
    if (!o->path) {
        if (commit && fflush(stdout) != 0) {
            fprintf(stderr, "amorph: cannot write to the standard output\n");
            return 1;
        }
        return bad;
    }
    if (am_port_close(o->stream, commit, err, sizeof err) != AM_OK) {
        fprintf(stderr, "amorph: %s\n", err);
        return 1;
    }
    return bad;
}

int tool_write_output(const char* out, const char* text, long len)
{
    tool_out o;
    if (tool_out_open(&o, out)) return 1;
    am_text_write(&o.text, text, len);
    return tool_out_close(&o, 1);
}

/* ---- reading ---- */

#if TOOL_WHOLE_FILES
#define TOOL_FILE_BUF (TOOL_FILE_MAX > TOOL_CKPT_MAX ? TOOL_FILE_MAX : TOOL_CKPT_MAX)
static char tool_file_buf[TOOL_FILE_BUF];

am_status tool_src_open(tool_src* s, const char* path, long cap, int nul_ends, char* err, int errsz)
{
    memset(s, 0, sizeof *s);
    s->path = path;
    s->restore = -1;
    long len = 0;
    if (cap > TOOL_FILE_BUF) cap = TOOL_FILE_BUF;
    am_status st = am_port_read_file(path, tool_file_buf, cap, &len, err, errsz);
    if (st != AM_OK) return st;
    size_t n = strlen(tool_file_buf);
    if (n != (size_t)len && !nul_ends) {
        s->binary = 1;
        return AM_ERR_PARSE;
    }
    s->end = (long)n;
    return AM_OK;
}

int tool_src_next(tool_src* s, char** line, long* n, char* err, int errsz)
{
    (void)err, (void)errsz;
    if (s->restore >= 0) tool_file_buf[s->restore] = '\n';
    s->restore = -1;
    if (s->pos >= s->end) return 0;
    char* p = tool_file_buf + s->pos;
    char* nl = memchr(p, '\n', (size_t)(s->end - s->pos));
    long k = nl ? (long)(nl - p) : s->end - s->pos;
    if (nl) {
        *nl = 0;
        s->restore = s->pos + k;
    }
    s->newline = nl != NULL;
    s->pos += k + (nl ? 1 : 0);
    s->line++;
    *line = p;
    *n = k;
    return 1;
}

am_status tool_src_rewind(tool_src* s, char* err, int errsz)
{
    (void)err, (void)errsz;
    if (s->restore >= 0) tool_file_buf[s->restore] = '\n';
    s->restore = -1;
    s->pos = 0;
    s->line = 0;
    return AM_OK;
}

void tool_src_close(tool_src* s)
{
    if (s->restore >= 0) tool_file_buf[s->restore] = '\n';
    s->restore = -1;
}

const char* tool_src_text(const tool_src* s)
{
    (void)s;
    return tool_file_buf;
}
#else
static char line_buf[TOOL_LINE_MAX + 2]; /* a line, its newline, and a NUL */

am_status tool_src_open(tool_src* s, const char* path, long cap, int nul_ends, char* err, int errsz)
{
    (void)cap;
    memset(s, 0, sizeof *s);
    s->path = path;
    s->nul_ends = nul_ends;
    s->stream = -1;
    am_status st = am_port_open_read(path, &s->stream, err, errsz);
    if (st != AM_OK) s->stream = -1;
    return st;
}

/* fills line_buf after its first `end` bytes; 0, or -1 after a read error (message in err) */
static int fill(tool_src* s, char* err, int errsz)
{
    while (!s->eof && s->end < TOOL_LINE_MAX + 1) {
        long got = 0;
        if (am_port_read(s->stream, line_buf + s->end, TOOL_LINE_MAX + 1 - s->end, &got, err, errsz) != AM_OK) {
            s->st = AM_ERR_IO;
            return -1;
        }
        if (got == 0) {
            s->eof = 1;
            break;
        }
        char* z = memchr(line_buf + s->end, 0, (size_t)got);
        if (z) {
            long keep = (long)(z - line_buf);
            if (!s->nul_ends) {
                s->binary = 1;
                s->st = AM_ERR_PARSE;
                return -1;
            }
            s->end = keep; /* a NUL ends the text */
            s->eof = 1;
            break;
        }
        s->end += got;
        if (memchr(line_buf + s->end - got, '\n', (size_t)got)) break;
    }
    return 0;
}

int tool_src_next(tool_src* s, char** line, long* n, char* err, int errsz)
{
    if (s->st != AM_OK) return -1;
    /* drop the line handed out last */
    if (s->pos > 0) {
        memmove(line_buf, line_buf + s->pos, (size_t)(s->end - s->pos));
        s->end -= s->pos;
        s->pos = 0;
    }
    char* nl = memchr(line_buf, '\n', (size_t)s->end);
    if (!nl) {
        if (fill(s, err, errsz) != 0) return -1;
        nl = memchr(line_buf, '\n', (size_t)s->end);
    }
    if (!nl && s->end == 0) return 0;
    long k = nl ? (long)(nl - line_buf) : s->end;
    s->line++;
    if (k > TOOL_LINE_MAX || (!nl && !s->eof)) {
        s->st = AM_ERR_PARSE;
        am_fail(err, errsz, AM_ERR_PARSE, "%s:%d: line longer than %d characters", s->path, s->line, TOOL_LINE_MAX);
        return -1;
    }
    line_buf[k] = 0;
    s->newline = nl != NULL;
    s->pos = k + (nl ? 1 : 0);
    *line = line_buf;
    *n = k;
    return 1;
}

am_status tool_src_rewind(tool_src* s, char* err, int errsz)
{
    const char* path = s->path;
    int nul_ends = s->nul_ends;
    tool_src_close(s);
    return tool_src_open(s, path, 0, nul_ends, err, errsz);
}

void tool_src_close(tool_src* s)
{
    if (s->stream >= 0) am_port_close(s->stream, 0, NULL, 0);
    s->stream = -1;
}
#endif

am_status tool_src_binary(const tool_src* s, char* err, int errsz)
{
    return am_fail(err, errsz, AM_ERR_PARSE, "%s:1: binary data (a NUL byte) in a text file", s->path);
}

/* ---- what a text holds, and its lines one by one ---- */

/* what a text is, from its first meaningful lines, as am_vxa_sniff and am_genome_sniff judge a
 * whole text: XML when the first non-blank character (after a byte order mark) is '<'; a genome
 * when the first line that is neither blank nor a comment starts with "amorph-genome"; else a
 * lattice. The source is left at its start. */
static int is_vxa_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
static int is_geno_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

int tool_src_sniff(tool_src* s, char* err, int errsz)
{
    char* line;
    long n;
    int r, vxa_open = 1, kind = TOOL_TEXT_LATTICE;
    while ((r = tool_src_next(s, &line, &n, err, errsz)) == 1) {
        if (vxa_open) {
            const char* q = line;
            if (s->line == 1 && (unsigned char)q[0] == 0xEF && (unsigned char)q[1] == 0xBB && (unsigned char)q[2] == 0xBF) q += 3;
            while (is_vxa_blank(*q)) q++;
            if (*q) {
                vxa_open = 0;
                if (*q == '<') {
                    kind = TOOL_TEXT_VXA;
                    break;
                }
            }
        }
        const char* q = line;
        while (is_geno_blank(*q)) q++;
        if (!*q || *q == '#') continue;
        kind = am_genome_sniff(line) ? TOOL_TEXT_GENOME : TOOL_TEXT_LATTICE;
        break;
    }
    if (r < 0) return -1;
    if (tool_src_rewind(s, err, errsz) != AM_OK) return -1;
    return kind;
}

am_status tool_src_each(tool_src* s, tool_line_fn fn, void* ctx, char* err, int errsz)
{
    char* line;
    long n;
    int r;
    while ((r = tool_src_next(s, &line, &n, err, errsz)) == 1) {
        am_status st = fn(ctx, s->line, line, n, err, errsz);
        if (st != AM_OK) return st;
    }
    if (r < 0) return s->binary ? tool_src_binary(s, err, errsz) : s->st;
    return AM_OK;
}

/* ---- a run's log.csv, row by row ---- */

typedef struct log_each {
    am_evo_log_reader rd;
    tool_log_row_fn fn;
    void* ctx;
} log_each;

static am_status log_each_line(void* ctx, int lineno, char* line, long n, char* err, int errsz)
{
    log_each* le = (log_each*)ctx;
    am_evo_stats row;
    int is_row = 0;
    am_status st = am_evo_log_read_line(&le->rd, line, n, &row, &is_row, err, errsz);
    if (st != AM_OK || !is_row) return st;
    return le->fn(le->ctx, le->rd.fname, lineno, &row, err, errsz);
}

am_status tool_log_each(const char* path, tool_log_row_fn fn, void* ctx, char* err, int errsz)
{
    log_each le;
    am_evo_log_read_begin(&le.rd, path);
    le.fn = fn;
    le.ctx = ctx;
    tool_src src;
    am_status st = tool_src_open(&src, path, TOOL_FILE_MAX, 0, err, errsz);
    if (st != AM_OK && src.binary) st = tool_src_binary(&src, err, errsz);
    if (st != AM_OK) return st;
    st = tool_src_each(&src, log_each_line, &le, err, errsz);
    if (st == AM_OK) st = am_evo_log_read_end(&le.rd, err, errsz);
    tool_src_close(&src);
    return st;
}
