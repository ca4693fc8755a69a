/* amorph plot: the command (its options); the plots themselves are tools/plot.c. docs/pictures.md. */
#include "picture.h"
#if TOOL_PICTURES

#include <stdio.h>
#include <string.h>

static const char plot_help[] =
    "usage: amorph plot DIR... --out FILE.svg [--title TEXT] [--min-evals N] [--max-evals N]\n"
    "Plots the best fitness so far against evaluations (the log.csv of each folder) as SVG. A run\n"
    "folder (amorph evolve --out DIR) is one line; an experiment folder (amorph experiment --out\n"
    "DIR), or any folder of run folders named <variant>-<k>, gives one line per variant: the mean\n"
    "of its runs with a band of one standard error, and each run faintly, as the seed's Figure 6.\n"
    "DIR/VARIANT, where DIR is such a folder, gives the line of its VARIANT-<k> runs alone.\n"
    "  --out FILE.svg   the picture (written atomically); required\n"
    "  --title TEXT     the heading (\"best fitness against evaluations\")\n"
    "  --min-evals N    in a folder of runs, leave out the runs that have logged fewer than N\n"
    "                   evaluations (each mean runs as far as the shortest run it keeps)\n"
    "  --max-evals N    draw each run up to N evaluations (its rows beyond N are left out)\n"
    "\n"
    "usage: amorph plot --travel ROBOT | --scene NAME --out FILE.svg [--title TEXT] [--KEY VALUE]...\n"
    "Simulates the robot (as amorph render and view) and plots its centre of mass's horizontal\n"
    "travel from where the movement started against time, the actuation cycles marked. ROBOT and\n"
    "NAME as for amorph render.\n"
    TOOL_ROBOT_HELP;

int cmd_plot(tool_ctx* c, int argc, char** argv)
{
    const char* out = 0;
    const char* title = 0;
    long min_evals = 0, max_evals = 0;
    static char* dirs[PLOT_MAX_RUNS];
    int nd = 0, travel = 0;
    tool_robot_args ra;
    memset(&ra, 0, sizeof ra);
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        if (!strcmp(a, "--travel")) travel = 1;
    }
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        const char* v = i + 1 < argc ? argv[i + 1] : 0;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(plot_help, stdout);
            return 0;
        } else if (!strcmp(a, "--travel")) {
            continue;
        } else if (travel && strcmp(a, "--out") && strcmp(a, "--title")) {
            /* the robot and its settings, as render and view take them */
            int r = tool_robot_arg("plot", argc, argv, &i, &ra);
            if (r == 2) return 2;
            if (r == 0) return tool_unknown_option("plot", a, plot_help);
        } else if (!strcmp(a, "--out")) {
            if (!v) return tool_usage_error("plot: --out needs a file name");
            out = v, i++;
        } else if (!strcmp(a, "--title")) {
            if (!v) return tool_usage_error("plot: --title needs a text");
            title = v, i++;
        } else if (!strcmp(a, "--min-evals")) {
            if (!tool_parse_long(v, 0, 1000000000L, &min_evals)) return tool_usage_error("plot: --min-evals needs a whole number 0..1000000000");
            i++;
        } else if (!strcmp(a, "--max-evals")) {
            if (!tool_parse_long(v, 1, 1000000000L, &max_evals)) return tool_usage_error("plot: --max-evals needs a whole number 1..1000000000");
            i++;
        } else if (a[0] == '-' && a[1]) {
            return tool_unknown_option("plot", a, plot_help);
        } else {
            if (nd >= PLOT_MAX_RUNS) return tool_usage_error("plot: more than %d folders", PLOT_MAX_RUNS);
            dirs[nd++] = argv[i];
        }
    }
    if (travel) {
        if (!ra.name) return tool_usage_error("plot: --travel needs a robot file, a run folder or --scene NAME (amorph plot --help)");
        int rc = tool_check_output(out, "plot", ".svg");
        if (rc) return rc;
        return tool_plot_travel(c, &ra, title ? title : "travel against time", out);
    }
    if (nd == 0) return tool_usage_error("plot: name run or experiment folders (amorph plot --help)");
    if (!out) return tool_usage_error("plot: --out FILE.svg is required");
    size_t n = strlen(out);
    if (n == 0 || out[n - 1] == '/') return tool_usage_error("plot: --out needs a file name");
    return tool_plot_runs(nd, dirs, min_evals, max_evals, title ? title : "best fitness against evaluations", out);
}

#else
typedef int tool_plot_not_built; /* board profile: tools/picture.c has the stand-ins */
#endif
