/* Loading robots for the commands: scenes, lattice files, genome files, VXA files; the workspaces
 * and the evolver the commands share. */
#include "cmd.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

am_evo_work tool_work[AM_MAX_WORKERS];
am_evo tool_evo;

int tool_usage_error(const char* fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("amorph: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    return 2;
}

int tool_not_in_build(const char* what, const char* feature)
{
    return tool_usage_error("%s: not in this build: %s belong to the desktop profile (make PROFILE=desktop)", what, feature);
}

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

static am_status lattice_line(void* ctx, int lineno, char* line, long n, char* err, int errsz)
{
    (void)lineno;
    return am_lattice_read_line((am_lattice_reader*)ctx, line, n, err, errsz);
}

am_status tool_load_robot(const char* name, int is_scene, am_lattice* lat, char* err, int errsz)
{
    tool_vxa_loaded = 0;
    if (is_scene) return am_scene_build(lat, name, err, errsz);
    tool_src src;
    am_status st = tool_src_open(&src, name, TOOL_FILE_MAX, 0, err, errsz);
    if (st != AM_OK) return src.binary ? tool_src_binary(&src, err, errsz) : st;
    int kind = tool_src_sniff(&src, err, errsz);
    if (kind < 0) {
        st = src.binary ? tool_src_binary(&src, err, errsz) : AM_ERR_PARSE;
    } else if (kind == TOOL_TEXT_VXA) {
#if TOOL_VXA
        st = tool_vxa_text_to_lattice(tool_src_text(&src), name, lat, err, errsz);
#else
        st = am_fail(err, errsz, AM_ERR_ARG, "%s: a VXA file: not in this build: VXA files belong to the desktop profile", name);
#endif
    } else if (kind == TOOL_TEXT_GENOME) {
        st = tool_genome_to_lattice(&src, lat, err, errsz);
    } else {
        am_lattice_reader r;
        am_lattice_read_begin(&r, lat, name);
        st = tool_src_each(&src, lattice_line, &r, err, errsz);
        if (st == AM_OK) st = am_lattice_read_end(&r, err, errsz);
    }
    tool_src_close(&src);
    return st;
}

am_status tool_resolve_env(const am_lattice* lat, double dt_s, double period_s, am_env* env, char* err, int errsz)
{
    if (dt_s <= 0 && period_s <= 0) return AM_OK;
    /* dt_rec depends on the materials and the voxel size only: a build with env as it is gives it */
    am_status st = am_model_build(&tool_work[0].model, lat, env, err, errsz);
    if (st != AM_OK) return st;
    const am_model* m = &tool_work[0].model;
    if (dt_s > 0) env->dt_frac = AM_PARAM_FROM_DOUBLE(dt_s / am_to_si(m, m->dt_rec, AM_DIM_TIME));
    if (period_s > 0) env->period_steps = am_vxa_period_steps(period_s, am_dt_si(m, env->dt_frac));
    return AM_OK;
}
