/* Run folders for the commands that show or export robots: a folder written by amorph evolve
 * (config.txt, best.genome, ...) stands for its best robot in the environment it evolved in. */
#include "cmd.h"

#include <stdio.h>
#include <string.h>

int tool_is_run_dir(const char* path)
{
    char p[4096];
    if (snprintf(p, sizeof p, "%s/config.txt", path) >= (int)sizeof p) return 0;
    if (!am_port_exists(p)) return 0;
    if (snprintf(p, sizeof p, "%s/best.genome", path) >= (int)sizeof p) return 0;
    return am_port_exists(p);
}


am_status tool_load_run(const char* dir, am_lattice* lat, am_env* env, am_eval_def* eval, char* err, int errsz)
{
    char path[4096], msg[AM_ERR_MAX];
    long len = 0;
    am_evo_def d = am_default_evo();
    snprintf(path, sizeof path, "%s/config.txt", dir);
    am_status st = am_port_read_file(path, tool_file_buf, TOOL_FILE_MAX, &len, err, errsz);
    if (st != AM_OK) return st;
    st = am_evo_parse(&d, tool_file_buf, path, err, errsz);
    if (st != AM_OK) return st;
    snprintf(path, sizeof path, "%s/best.genome", dir);
    st = am_port_read_file(path, tool_file_buf, TOOL_FILE_MAX, &len, err, errsz);
    if (st != AM_OK) return st;
    static am_genome g;
    st = am_genome_parse(&g, tool_file_buf, path, err, errsz);
    if (st != AM_OK) return st;
    am_palette pal = am_evo_palette(&d);
    st = am_evo_lattice(&d, &pal, &g, &tool_work[0].geno, lat, msg, sizeof msg);
    if (st != AM_OK) return am_fail(err, errsz, st, "%s: %s", path, msg);
    if (env) *env = d.env;
    if (eval) {
        *eval = d.eval;
        eval->record = NULL;
    }
    return AM_OK;
}
