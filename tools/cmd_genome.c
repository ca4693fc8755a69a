/* amorph random, amorph express, genome files for amorph sim, and the expression benchmark. */
#include "cmd.h"

#include <stdio.h>
#include <string.h>

static const char random_help[] =
    "usage: amorph random --repr dct|cppn|gmx [--materials 2|3] [--seed S] [--size N] [--out FILE]\n"
    "Writes a random genome (docs/formats.md) to FILE, or to the standard output.\n"
    "  --repr R         representation: dct, cppn or gmx\n"
    "  --materials M    2 (passive, active) or 3 (passive, active, active90) (2)\n"
    "  --seed S         seed of the random stream, 0..2^64-1 (1)\n"
    "  --size N         workspace N x N x N cells (the profile's largest, 20 on desktops)\n"
    "  --out FILE       the genome file (written atomically)\n";

int cmd_random(int argc, char** argv)
{
    am_geno_def def = am_default_geno();
    uint64_t seed = 1;
    const char* out = NULL;
    int have_repr = 0, n = 0;
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        const char* v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(random_help, stdout);
            return 0;
        } else if (!strcmp(a, "--repr")) {
            def.repr = v ? am_repr_from_name(v) : AM_REPR_NONE;
            if (def.repr == AM_REPR_NONE) return tool_usage_error("random: --repr takes dct, cppn or gmx");
            have_repr = 1, i++;
        } else if (!strcmp(a, "--materials")) {
            if (!tool_parse_int(v, 2, 3, &n)) return tool_usage_error("random: --materials takes 2 or 3");
            def.materials = n, i++;
        } else if (!strcmp(a, "--seed")) {
            if (!tool_parse_u64(v, &seed)) return tool_usage_error("random: --seed needs a whole number 0..18446744073709551615");
            i++;
        } else if (!strcmp(a, "--size")) {
            if (!tool_parse_int(v, 1, AM_MAX_DIM, &n))
                return tool_usage_error("random: --size needs a whole number 1..%d (%s profile)", AM_MAX_DIM, AM_PROFILE_NAME);
            def.nx = def.ny = def.nz = n, i++;
        } else if (!strcmp(a, "--out")) {
            if (!v) return tool_usage_error("random: --out needs a file name");
            out = v, i++;
        } else return tool_usage_error("random: unknown option '%s' (amorph random --help)", a);
    }
    if (!have_repr) return tool_usage_error("random: --repr dct|cppn|gmx is required (amorph random --help)");
    if (def.dct_k > def.nx) def.dct_k = def.nx;
    char err[AM_ERR_MAX];
    am_rng rng;
    am_rng_seed(&rng, seed);
    if (am_genome_init(&tool_genome, &def, &rng, err, sizeof err) != AM_OK) return tool_usage_error("random: %s", err);
    tool_out o;
    if (tool_out_open(&o, out)) return 1;
    am_status st = am_genome_write(&tool_genome, &o.text, err, sizeof err);
    if (st != AM_OK && st != AM_ERR_IO) {
        fprintf(stderr, "amorph: random: %s\n", err);
        tool_out_close(&o, 0);
        return 1;
    }
    return tool_out_close(&o, 1);
}

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

am_status tool_genome_to_lattice(tool_src* src, am_lattice* lat, char* err, int errsz)
{
    const char* fname = src->path;
    genome_read g;
    g.materials_line = 0;
    am_genome_read_begin(&g.r, &tool_genome, fname);
    am_status st = tool_src_each(src, genome_line, &g, err, errsz);
    if (st == AM_OK) st = am_genome_read_end(&g.r, err, errsz);
    if (st != AM_OK) return st;
    /* the built-in palette, in the lattice about to be filled (none is built on the stack) */
    am_default_palette_into(&lat->palette);
    for (int m = 0; m < tool_genome.materials; m++)
        if (am_palette_find(&lat->palette, tool_genome.mat[m]) < 0)
            return am_fail(err, errsz, AM_ERR_RANGE, "%s:%d: material '%s' is not in the built-in palette", fname,
                           g.materials_line ? g.materials_line : 1, tool_genome.mat[m]);
    char msg[AM_ERR_MAX];
    st = am_genome_to_lattice(&tool_genome, NULL, &tool_work[0].geno, lat, msg, sizeof msg);
    if (st != AM_OK) return am_fail(err, errsz, st, "%s:1: %s", fname, msg);
    return AM_OK;
}

static const char express_help[] =
    "usage: amorph express GENOME [--out FILE.lattice]\n"
    "Expresses a genome into a body (level set, argmax material, largest face-connected piece)\n"
    "and writes it in the lattice format to FILE (atomically; then prints voxels=N), or to the\n"
    "standard output. An empty body is not an error: it has 0 voxels.\n";

int cmd_express(int argc, char** argv)
{
    const char* in = NULL;
    const char* out = NULL;
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        const char* v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(express_help, stdout);
            return 0;
        } else if (!strcmp(a, "--out")) {
            if (!v) return tool_usage_error("express: --out needs a file name");
            out = v, i++;
        } else if (a[0] == '-' && a[1]) {
            return tool_usage_error("express: unknown option '%s' (amorph express --help)", a);
        } else {
            if (in) return tool_usage_error("express: one genome at a time ('%s' and '%s')", in, a);
            in = a;
        }
    }
    if (!in) return tool_usage_error("express: name a genome file (amorph express --help)");
    char err[AM_ERR_MAX];
    tool_src src;
    am_lattice* lat = &tool_work[0].lattice;
    am_status st = tool_src_open(&src, in, TOOL_FILE_MAX, 0, err, sizeof err);
    if (st != AM_OK) {
        if (src.binary) tool_src_binary(&src, err, sizeof err);
        return tool_usage_error("%s", err);
    }
    int kind = tool_src_sniff(&src, err, sizeof err);
    if (kind == TOOL_TEXT_GENOME) st = tool_genome_to_lattice(&src, lat, err, sizeof err);
    else if (kind < 0 && src.binary) st = tool_src_binary(&src, err, sizeof err);
    else if (kind < 0) st = AM_ERR_IO;
    tool_src_close(&src);
    if (kind > 0 && kind != TOOL_TEXT_GENOME) return tool_usage_error("%s:1: not a genome (expected 'amorph-genome 1')", in);
    if (st != AM_OK) return tool_usage_error("%s", err);
    tool_out o;
    if (tool_out_open(&o, out)) return 1;
    st = am_lattice_write(lat, &o.text, err, sizeof err);
    if (st != AM_OK && st != AM_ERR_IO) {
        fprintf(stderr, "amorph: express: %s\n", err);
        tool_out_close(&o, 0);
        return 1;
    }
    if (tool_out_close(&o, 1) != 0) return 1;
    if (!out) return 0;
    printf("voxels=%d\n", tool_work[0].geno.voxels);
    return 0;
}

void tool_bench_express(void)
{
    enum { GENOMES = 8 };
    /* the pool: the genomes of the evolver's population, idle while bench runs */
    _Static_assert(GENOMES <= AM_MAX_POPULATION, "the expression pool borrows the evolver's population");
    am_genome* pool[GENOMES];
    for (int i = 0; i < GENOMES; i++) pool[i] = &tool_evo.pop[i].genome;
    char err[AM_ERR_MAX];
    am_geno_def def = am_default_geno();
    printf("express_workspace=%dx%dx%d\n", def.nx, def.ny, def.nz);
    printf("genome_bytes=%d\n", (int)sizeof(am_genome));
    for (int repr = 1; repr < AM_REPR_COUNT; repr++) {
        def.repr = repr;
        am_rng rng;
        am_rng_seed(&rng, 2024);
        for (int i = 0; i < GENOMES; i++)
            if (am_genome_init(pool[i], &def, &rng, err, sizeof err) != AM_OK) {
                printf("express_%s_error=%s\n", am_repr_name(repr), err);
                return;
            }
        am_genome_express(pool[0], NULL, &tool_work[0].geno, NULL, err, sizeof err); /* warm-up: tables */
        long reps = 0, voxels = 0;
        double t0 = am_port_now(), t = 0;
        do {
            for (int i = 0; i < GENOMES; i++) {
                am_genome_express(pool[i], NULL, &tool_work[0].geno, NULL, err, sizeof err);
                voxels += tool_work[0].geno.voxels;
            }
            reps += GENOMES;
            t = am_port_now() - t0;
        } while (t < 0.25);
        /* the level set alone, on the last fields */
        long lreps = 0;
        double l0 = am_port_now(), lt = 0;
        do {
            for (int i = 0; i < GENOMES; i++)
                am_levelset(&tool_work[0].geno, def.materials, def.nx, def.ny, def.nz, AM_R(0), NULL);
            lreps += GENOMES;
            lt = am_port_now() - l0;
        } while (lt < 0.1);
        printf("express_%s_us=%.1f\n", am_repr_name(repr), 1e6 * t / (double)reps);
        printf("express_%s_levelset_us=%.1f\n", am_repr_name(repr), 1e6 * lt / (double)lreps);
        printf("express_%s_mean_voxels=%ld\n", am_repr_name(repr), voxels / reps);
    }
    fflush(stdout);
}
