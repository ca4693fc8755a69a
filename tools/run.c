/* Run folders for the commands that show or export robots: a folder written by amorph evolve
 * (config.txt, best.genome, ...) stands for its best robot in the environment it evolved in. */
#include "cmd.h"

#include <stdio.h>
#include <string.h>

int tool_is_run_dir(const char* path)
{
    char p[TOOL_PATH_MAX];
    if (snprintf(p, sizeof p, "%s/config.txt", path) >= (int)sizeof p) return 0;
    if (!am_port_exists(p)) return 0;
    if (snprintf(p, sizeof p, "%s/best.genome", path) >= (int)sizeof p) return 0;
    return am_port_exists(p);
}

typedef struct config_ctx {
    am_evo_def* d;
    const char* fname;
} config_ctx;

static am_status config_line(void* ctx, int lineno, char* line, long n, char* err, int errsz)
{
    config_ctx* c = (config_ctx*)ctx;
    return am_evo_parse_line(c->d, line, n, c->fname, lineno, err, errsz);
}

am_status tool_read_config(const char* path, am_evo_def* d, int nul_ends, char* err, int errsz)
{
    tool_src src;
    am_status st = tool_src_open(&src, path, TOOL_FILE_MAX, nul_ends, err, errsz);
    if (st == AM_OK) {
        config_ctx c = {d, path};
        st = tool_src_each(&src, config_line, &c, err, errsz);
    } else if (src.binary) {
        st = tool_src_binary(&src, err, errsz);
    }
    tool_src_close(&src);
    return st;
}

static am_status genome_line(void* ctx, int lineno, char* line, long n, char* err, int errsz)
{
    (void)lineno;
    return am_genome_read_line((am_genome_reader*)ctx, line, n, err, errsz);
}

am_status tool_read_genome(tool_src* src, am_genome* g, char* err, int errsz)
{
    am_genome_reader r;
    am_genome_read_begin(&r, g, src->path);
    am_status st = tool_src_each(src, genome_line, &r, err, errsz);
    return st != AM_OK ? st : am_genome_read_end(&r, err, errsz);
}
