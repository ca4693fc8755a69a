/* amorph random and amorph express: genomes. */
#include "robot.h"

#include <stdio.h>
#include <string.h>

static const char random_help[] =
    "usage: amorph random [--representation dct|cppn|gmx] [--KEY VALUE]... [--out FILE]\n"
    "Writes a random genome (docs/formats.md) to FILE, or to the standard output. The settings are\n"
    "the genotype's keys of amorph evolve's configuration (amorph evolve --help-config; '-' may\n"
    "stand for '_'), with the same defaults:\n"
    "  --representation R  dct, cppn or gmx (gmx; alias --repr R)\n"
    "  --palette P         seed (passive, active, active90) or unshackled (4 materials); --material1 ...\n"
    "                      as in a configuration (docs/evolve.md, Palettes) (seed)\n"
    "  --materials M       the palette's first M (2: passive, active; 3: + active90) (2)\n"
    "  --workspace N       N x N x N cells, or NxMxK (20; alias --size N)\n"
    "  --seed S            seed of the random stream, 0..2^64-1 (1)\n"
    "  --dct_k, --cppn_layers, --cppn_nodes, --cppn_active, --gmx_points ...  as in a configuration\n"
    "  --out FILE          the genome file (written atomically)\n";

int cmd_random(tool_ctx* c, int argc, char** argv)
{
    am_evo_def d = am_default_evo();
    const char* out = NULL;
    char err[AM_ERR_MAX];
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        const char *key, *val;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(random_help, stdout);
            return 0;
        } else if (!strcmp(a, "--out")) {
            if (i + 1 >= argc) return tool_usage_error("random: --out needs a file name");
            out = argv[++i];
            continue;
        }
        int r = tool_setting_arg("random", argc, argv, &i, &key, &val);
        if (r == 2) return 2;
        if (r == 0) return tool_unknown_option("random", a, random_help);
        if (am_evo_key_group(key) != AM_KEYS_GENOTYPE && strcmp(key, "seed") != 0)
            return tool_usage_error("random: --%s is not a setting of a genome (amorph random --help)", key);
        if (am_evo_set(&d, key, val, err, sizeof err) != AM_OK) return tool_usage_error("random: --%s", err);
    }
    /* the palette's relations (materials within it, names once each) */
    int bad_key;
    if (am_evo_check_key(&d, &bad_key, err, sizeof err) != AM_OK) return tool_usage_error("random: %s", err);
    am_geno_def def = d.geno;
    if (def.dct_k > def.nx) def.dct_k = def.nx;
    am_rng rng;
    am_rng_seed(&rng, d.seed);
    if (am_genome_init(tool_genome(c), &def, &rng, err, sizeof err) != AM_OK) return tool_usage_error("random: %s", err);
    tool_out o;
    if (tool_out_open(&o, out)) return 1;
    am_status st = am_genome_write(tool_genome(c), &o.text, err, sizeof err);
    if (st != AM_OK && st != AM_ERR_IO) {
        fprintf(stderr, "amorph: random: %s\n", err);
        tool_out_close(&o, 0);
        return 1;
    }
    return tool_out_close(&o, 1);
}

static const char express_help[] =
    "usage: amorph express GENOME [--palette P] [--materialK SPEC]... [--out FILE.lattice]\n"
    "Expresses a genome into a body (level set, argmax material, largest face-connected piece)\n"
    "and writes it in the lattice format to FILE (atomically; then prints voxels=N), or to the\n"
    "standard output. An empty body is not an error: it has 0 voxels. The genome's material names\n"
    "are looked up in the built-in palette, or in the one --palette and --materialK give (as in a\n"
    "configuration: docs/evolve.md, Palettes), which the lattice then carries.\n";

int cmd_express(tool_ctx* c, int argc, char** argv)
{
    const char* in = NULL;
    const char* out = NULL;
    char err[AM_ERR_MAX];
    tool_robot_args ra; /* the palette keys given, in order */
    memset(&ra, 0, sizeof ra);
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
            const char *key, *val;
            const int r = tool_setting_arg("express", argc, argv, &i, &key, &val);
            if (r == 2) return 2;
            if (r == 0) return tool_unknown_option("express", a, express_help);
            if (!tool_robot_palette_key(key)) return tool_usage_error("express: --%s is not a setting express takes (--palette, --materialK)", key);
            if (ra.nset == TOOL_MAX_SETTINGS) return tool_usage_error("express: more than %d settings", TOOL_MAX_SETTINGS);
            am_evo_def d = am_default_evo(); /* the value checked now, before the genome is read */
            if (am_evo_set(&d, key, val, err, sizeof err) != AM_OK) return tool_usage_error("express: --%s", err);
            ra.key[ra.nset] = key;
            ra.val[ra.nset++] = val;
        } else {
            if (in) {
                char q1[AM_QUOTE_BUF], q2[AM_QUOTE_BUF];
                return tool_usage_error("express: one genome at a time ('%s' and '%s')", am_quote(q1, sizeof q1, in, -1),
                                        am_quote(q2, sizeof q2, a, -1));
            }
            in = a;
        }
    }
    if (!in) return tool_usage_error("express: name a genome file (amorph express --help)");
    /* the palette the keys give, in the evolver's slot (idle), or the built-in one */
    am_evo_def d = am_default_evo();
    const int own = tool_robot_palette(&ra, &d, err, sizeof err);
    if (own < 0) return tool_usage_error("express: %s", err);
    if (own) am_evo_palette_into(&d, &c->evo.palette);
    tool_src src;
    am_lattice* lat = &c->work[0].lattice;
    am_status st = tool_src_open(&src, in, TOOL_FILE_MAX, 0, err, sizeof err);
    if (st != AM_OK) {
        if (src.binary) tool_src_binary(&src, err, sizeof err);
        return tool_usage_error("%s", err);
    }
    int kind = tool_src_sniff(&src, err, sizeof err);
    if (kind == TOOL_TEXT_GENOME) st = tool_genome_to_lattice(c, &src, lat, own ? &c->evo.palette : NULL, err, sizeof err);
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
    printf("voxels=%d\n", c->work[0].geno.voxels);
    return 0;
}
