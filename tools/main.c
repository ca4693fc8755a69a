/* amorph: the command. Subcommands in the style of git. */
#include "cmd.h"

#include <stdio.h>
#include <string.h>

static const struct {
    const char* name;
    int (*fn)(tool_ctx*, int, char**);
    const char* help;
} commands[] = {
    {"evolve", cmd_evolve, "evolve robots (the seed's experiment by default; resumable run folders)"},
    {"experiment", cmd_experiment, "run one of the seed's experiments (representations, three-materials, ...)"},
    {"repro", cmd_repro, "run the reference evolution of make repro and print its hash"},
    {"sim", cmd_sim, "simulate one robot (a lattice, genome or VXA file, a run or voxcraft folder, or --scene) and print its fitness"},
    {"eval", cmd_eval, "evaluate robots given as JSON lines on stdin, one JSON result per line (pipes, docs/embedding.md)" TOOL_DESKTOP_ONLY},
    {"bench", cmd_bench, "print simulator speed figures (name=value lines)"},
    {"random", cmd_random, "write a random genome (--representation dct|cppn|gmx, alias --repr)"},
    {"express", cmd_express, "express a genome into a lattice file"},
#if TOOL_VXA
    {"export", cmd_export, "write a robot (file, run folder or --scene) as a VXA file for VoxCAD (--vxa), a lattice file or STL/AMF surfaces"},
#else
    {"export", cmd_export, "write a robot (file, run folder or --scene) as a lattice file or STL/AMF surfaces (VXA files: not in this build)"},
#endif
    {"render", cmd_render, "draw a filmstrip PNG of a robot's motion (initial, settled, snapshots)" TOOL_DESKTOP_ONLY},
    {"plot", cmd_plot, "plot best fitness against evaluations of runs or experiments (SVG)" TOOL_DESKTOP_ONLY},
    {"view", cmd_view, "write a self-contained HTML viewer of a robot's recorded motion" TOOL_DESKTOP_ONLY},
    {"stats", cmd_stats, "compare groups of runs by tests: Welch's t, Mann-Whitney, effect size, runs needed" TOOL_DESKTOP_ONLY},
    {"report", cmd_report, "the tables of docs/results.md from run folders' log.csv (fig6, compute, last)" TOOL_DESKTOP_ONLY},
};

static void usage(FILE* f)
{
    fprintf(f, "usage: amorph COMMAND [options]   (amorph COMMAND --help for each)\n\ncommands:\n");
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        fprintf(f, "  %-9s %s\n", commands[i].name, commands[i].help);
    fprintf(f, "\nbuild: am_real=%s, profile=%s (workspace up to %d^3)\n", AM_REAL_NAME, AM_PROFILE_NAME, AM_MAX_DIM);
}

/* the commands' workspaces: large, so static storage rather than main's stack */
static tool_ctx ctx;

/* the command named by argv[1]; its exit status */
static int run_command(int argc, char** argv)
{
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        usage(stdout);
        return 0;
    }
    for (size_t i = 0; i < sizeof commands / sizeof commands[0]; i++)
        if (!strcmp(argv[1], commands[i].name)) return commands[i].fn(&ctx, argc - 1, argv + 1);
    char q[AM_QUOTE_BUF];
    return tool_usage_error("unknown command '%s' (amorph --help lists them)", am_quote(q, sizeof q, argv[1], -1));
}

int main(int argc, char** argv)
{
    am_port_start(&argc, &argv);
    int status = run_command(argc, argv);
    fflush(stdout);
    fflush(stderr);
    return am_port_end(status);
}
