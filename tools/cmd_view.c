/* amorph view: the command (its options); the page itself is tools/viewer.c. docs/pictures.md. */
#include "picture.h"
#if TOOL_PICTURES

#include <stdio.h>
#include <string.h>

static const char view_help[] =
    "usage: amorph view ROBOT | --scene NAME --out FILE.html [options]\n"
    "Simulates the robot (relaxation, then actuation cycles, as amorph sim) and writes one\n"
    "self-contained HTML file that plays the recorded motion in a browser: drag to orbit, wheel to\n"
    "zoom, play/pause, speed, a time slider, the centre-of-mass trail, a scale bar and a plot of the\n"
    "travel against time; a menu colours the voxels by material, strain, stress, speed or phase\n"
    "(#colour=NAME), clamped voxels and forces drawn. It opens where the movement\n"
    "starts, the relaxation skipped (its check box, or #relax=1, shows it). URL hash parameters pick\n"
    "a moment: FILE.html#t=0.5&paused=1 (docs/pictures.md lists them all). ROBOT is a lattice or\n"
    "genome or VXA file or a run folder; NAME a built-in scene (cube:N, sphere:D, cantilever:N,\n"
    "chain:N, halfbar:N, antibar:N).\n"
    "  --out FILE.html    the page (written atomically); required\n"
    "  --frames N         frames recorded, 2..1000 (200; fewer for big bodies)\n"
    "  --title TEXT       the page's heading (the robot's name)\n"
    TOOL_ROBOT_HELP;

int cmd_view(tool_ctx* c, int argc, char** argv)
{
    const char* out = 0;
    const char* title = 0;
    int frames = 200;
    tool_robot_args ra;
    memset(&ra, 0, sizeof ra);
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        const char* v = i + 1 < argc ? argv[i + 1] : 0;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(view_help, stdout);
            return 0;
        } else if (!strcmp(a, "--out")) {
            if (!v) return tool_usage_error("view: --out needs a file name");
            out = v, i++;
        } else if (!strcmp(a, "--title")) {
            if (!v) return tool_usage_error("view: --title needs a text");
            title = v, i++;
        } else if (!strcmp(a, "--frames")) {
            if (!tool_parse_int(v, 2, 1000, &frames)) return tool_usage_error("view: --frames needs a whole number 2..1000");
            i++;
        } else {
            int r = tool_robot_arg("view", argc, argv, &i, &ra);
            if (r == 2) return 2;
            if (r == 0) return tool_unknown_option("view", a, view_help);
        }
    }
    if (!ra.name) return tool_usage_error("view: name a robot file, a run folder or --scene NAME (amorph view --help)");
    int rc = tool_check_output(out, "view", ".html");
    if (rc) return rc;
    am_robot rob;
    rc = tool_load_subject(c, &ra, &rob, "view");
    if (rc) return rc;
    return view_write(c, &rob, frames, title ? title : ra.name, ra.name, out);
}

#else
typedef int tool_view_not_built; /* board profile: tools/picture.c has the stand-ins */
#endif
