/* amorph render: the command (its options); the filmstrip itself is tools/film.c. docs/pictures.md. */
#include "picture.h"
#if TOOL_PICTURES

#include <stdio.h>
#include <string.h>

static const char render_help[] =
    "usage: amorph render ROBOT | --scene NAME --out FILE.png [options]\n"
    "Simulates the robot (relaxation, then actuation cycles, as amorph sim) and draws a filmstrip:\n"
    "the initial shape, the settled shape, then snapshots of the motion, with the centre of mass\n"
    "path and the direction of travel. ROBOT is a lattice, genome or VXA file or a run folder (its\n"
    "best robot in the run's environment); NAME a built-in scene (cube:N, sphere:D, cantilever:N,\n"
    "chain:N, halfbar:N, antibar:N).\n"
    "  --out FILE.png     the picture (written atomically); required\n"
    "  --keep-same        leave FILE.png as it is when it already holds this very picture (the\n"
    "                     same pixels, whatever its compression; results/report.sh)\n"
    "  --frames N         pictures side by side, 3..16 (6: initial, settled, 4 of the motion)\n"
    "  --width W          pixels, 200..4096 (1600)\n"
    "  --height H         pixels, 120..4096 (400); width x height at most 4194304\n"
    "  --boxes            each voxel as a box (turned and sized as simulated) instead of the\n"
    "                     continuous surface over the voxels (--surface, the default)\n"
    "  --colour MODE      what the colours show: material (the default), strain, stress, speed\n"
    "                     or phase (docs/pictures.md, Colours), with a legend of the scale (alias --color)\n"
    TOOL_ROBOT_HELP;

int cmd_render(tool_ctx* c, int argc, char** argv)
{
    const char* out = 0;
    tool_robot_args ra;
    memset(&ra, 0, sizeof ra);
    film_opts o = film_defaults();
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        const char* v = i + 1 < argc ? argv[i + 1] : 0;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(render_help, stdout);
            return 0;
        } else if (!strcmp(a, "--out")) {
            if (!v) return tool_usage_error("render: --out needs a file name");
            out = v, i++;
        } else if (!strcmp(a, "--keep-same")) {
            o.keep_same = 1;
        } else if (!strcmp(a, "--boxes") || !strcmp(a, "--surface")) {
            o.boxes = a[2] == 'b';
        } else if (!strcmp(a, "--colour") || !strcmp(a, "--color")) {
            o.colour = tool_colour_parse(v);
            if (o.colour < 0) return tool_usage_error("render: %s needs material, strain, stress, speed or phase", a);
            i++;
        } else if (!strcmp(a, "--frames")) {
            if (!tool_parse_int(v, 3, FILM_MAX_PANELS, &o.panels)) return tool_usage_error("render: --frames needs a whole number 3..%d", FILM_MAX_PANELS);
            i++;
        } else if (!strcmp(a, "--width")) {
            if (!tool_parse_int(v, 200, FILM_MAX_W, &o.width)) return tool_usage_error("render: --width needs a whole number 200..%d", FILM_MAX_W);
            i++;
        } else if (!strcmp(a, "--height")) {
            if (!tool_parse_int(v, 120, FILM_MAX_H, &o.height)) return tool_usage_error("render: --height needs a whole number 120..%d", FILM_MAX_H);
            i++;
        } else {
            int r = tool_robot_arg("render", argc, argv, &i, &ra);
            if (r == 2) return 2;
            if (r == 0) return tool_unknown_option("render", a, render_help);
        }
    }
    if (!ra.name) return tool_usage_error("render: name a robot file, a run folder or --scene NAME (amorph render --help)");
    int rc = tool_check_output(out, "render", ".png");
    if (rc) return rc;
    if ((long)o.width * o.height > FILM_MAX_PIXELS)
        return tool_usage_error("render: %d x %d is more than %ld pixels", o.width, o.height, FILM_MAX_PIXELS);
    if (o.width / o.panels < 60) return tool_usage_error("render: %d frames need a width of at least %d", o.panels, 60 * o.panels);
    am_robot rob;
    rc = tool_load_subject(c, &ra, &rob, "render");
    if (rc) return rc;
    return film_write(c, &rob, &o, ra.name, out);
}

#else
typedef int tool_render_not_built; /* board profile: tools/picture.c has the stand-ins */
#endif
