/* A robot from a genome (tools/robot.h): the genome file's text expressed in a palette, the palette
 * and the stiffness range its settings give, and its evolved phases and stiffnesses as the robot's
 * layers. tools/robot.c loads robots through these. */
#include "robot.h"

#include <stdio.h>
#include <string.h>

/* a genome's lines to the reader, noting the line of "materials" (for messages) */
typedef struct genome_read {
    am_genome_reader r;
    int materials_line;       /* the first line that starts with "materials", 0 until seen */
} genome_read;

static am_status genome_line(void* ctx, int lineno, char* line, long n, char* err, int errsz)
{
    genome_read* g = (genome_read*)ctx;
    const char* p = line;
    while (*p == ' ' || *p == '\t') p++;
    if (!g->materials_line && !strncmp(p, "materials", 9)) g->materials_line = lineno;
    return am_genome_read_line(&g->r, line, n, err, errsz);
}

am_status tool_genome_to_lattice(tool_ctx* c, tool_src* src, am_lattice* lat, const am_palette* pal, char* err, int errsz)
{
    const char* fname = src->path;
    am_genome* g = tool_genome(c);
    genome_read gr;
    gr.materials_line = 0;
    am_genome_read_begin(&gr.r, g, fname);
    am_status st = tool_src_each(src, genome_line, &gr, err, errsz);
    if (st == AM_OK) st = am_genome_read_end(&gr.r, err, errsz);
    if (st != AM_OK) return st;
    /* the palette, in the lattice about to be filled (none is built on the stack) */
    if (pal) lat->palette = *pal;
    else am_default_palette_into(&lat->palette);
    for (int m = 0; m < g->materials; m++)
        if (am_palette_find(&lat->palette, g->mat[m]) < 0)
            return am_fail(err, errsz, AM_ERR_RANGE,
                           pal ? "%s:%d: material '%s' is not in the palette the settings give (--palette, --materialK)"
                               : "%s:%d: material '%s' is not in the built-in palette (a run's genome: give the run's palette, --palette "
                                 "and --materialK as its config.txt has them, or, to sim, render, view and export, its run folder)",
                           fname, gr.materials_line ? gr.materials_line : 1, g->mat[m]);
    char msg[AM_ERR_MAX];
    am_express_def ex = am_default_express();
    ex.palette = pal; /* NULL: the built-in one */
    st = am_genome_to_lattice(g, &ex, &c->work[0].geno, lat, msg, sizeof msg);
    if (st != AM_OK) return am_fail(err, errsz, st, "%s:1: %s", fname, msg);
    return AM_OK;
}

int tool_robot_palette_key(const char* key)
{
    return !strcmp(key, "palette") || (!strncmp(key, "material", 8) && key[8] >= '1' && key[8] <= '9');
}

int tool_robot_palette(const tool_robot_args* a, am_evo_def* d, char* err, int errsz)
{
    int given = 0;
    for (int k = 0; k < a->nset; k++) {
        if (!tool_robot_palette_key(a->key[k])) continue;
        if (am_evo_set(d, a->key[k], a->val[k], err, errsz) != AM_OK) return -1;
        given = 1;
    }
    if (!given) return 0;
    char why[AM_ERR_MAX];
    if (am_evo_check(d, why, sizeof why) != AM_OK) {
        am_fail(err, errsz, AM_ERR_RANGE, "--%s", why);
        return -1;
    }
    return 1;
}

am_status tool_robot_stiffness_range(const tool_robot_args* a, am_express_def* ex, char* err, int errsz)
{
    am_evo_def d = am_default_evo();
    d.stiffness = AM_STIFFNESS_EVOLVED;
    d.stiffness_min = ex->stiffness_min;
    d.stiffness_max = ex->stiffness_max;
    int given = 0;
    for (int k = 0; k < a->nset; k++) {
        if (strcmp(a->key[k], "stiffness_min") && strcmp(a->key[k], "stiffness_max")) continue;
        am_status st = am_evo_set(&d, a->key[k], a->val[k], err, errsz);
        if (st != AM_OK) return st;
        given = 1;
    }
    if (!given) return AM_OK;
    /* the range's relation (at most 100 x), as amorph evolve checks it */
    char why[AM_ERR_MAX];
    if (am_evo_check(&d, why, sizeof why) != AM_OK) return am_fail(err, errsz, AM_ERR_RANGE, "--%s", why);
    ex->stiffness_min = d.stiffness_min;
    ex->stiffness_max = d.stiffness_max;
    return AM_OK;
}

am_status tool_robot_genome_layers(tool_ctx* c, const am_express_def* ex, am_robot* r, const char* fname, tool_genome_use* use, char* err,
                                   int errsz)
{
    const am_genome* g = tool_genome(c);
    char msg[AM_ERR_MAX];
    use->range = *ex;
    use->genome = 1;
    use->evolved_stiffness = (g->controls & AM_CTL_STIFFNESS) != 0;
    if (!g->controls) return AM_OK;
    am_status st = r->layers ? am_genome_layers(g, ex, &c->work[0].geno, r->layers, msg, sizeof msg)
                             : am_fail(msg, sizeof msg, AM_ERR_CAPACITY, "an evolved phase or stiffness: this build keeps no layers per voxel");
    return st == AM_OK ? AM_OK : am_fail(err, errsz, st, "%s: %s", fname, msg);
}

