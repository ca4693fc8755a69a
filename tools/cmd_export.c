/* amorph export: a robot in another format (VXA for VoxCAD / Voxelyze, the lattice text format). */
#include "robot.h"

#include <stdio.h>
#include <string.h>

#if TOOL_VXA
static char g_out[AM_VXA_TEXT_MAX]; /* the VXA text, during one call */
#endif

static const char export_help[] =
    "usage: amorph export ROBOT | --scene NAME  --vxa FILE.vxa | --lattice FILE.lattice\n"
    "Writes a robot (a lattice, genome or VXA file, or a built-in scene) in another format:\n"
    "  --vxa FILE       a VXA 1.1 file that VoxCAD and Voxelyze load (docs/vxa.md); '-' for stdout" TOOL_DESKTOP_ONLY "\n"
    "  --lattice FILE   the amorph lattice text format (docs/formats.md); '-' for stdout\n"
    "The environment in a VXA file is the robot's own (a VXA file's or a run folder's), else the\n"
    "seed's, with the settings below on top. Files are replaced atomically.\n"
    TOOL_ROBOT_HELP;

int cmd_export(tool_ctx* c, int argc, char** argv)
{
    const char *vxa = 0, *lattice = 0;
    tool_robot_args ra;
    memset(&ra, 0, sizeof ra);
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        const char* v = i + 1 < argc ? argv[i + 1] : 0;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(export_help, stdout);
            return 0;
        } else if (!strcmp(a, "--vxa")) {
            if (!v) return tool_usage_error("export: --vxa needs a file name");
            vxa = v, i++;
        } else if (!strcmp(a, "--lattice")) {
            if (!v) return tool_usage_error("export: --lattice needs a file name");
            lattice = v, i++;
        } else {
            int r = tool_robot_arg("export", argc, argv, &i, &ra);
            if (r == 2) return 2;
            if (r == 0) return tool_unknown_option("export", a);
        }
    }
    if (!ra.name) return tool_usage_error("export: name a robot file or --scene NAME (amorph export --help)");
    if (!vxa && !lattice) return tool_usage_error("export: say what to write: --vxa FILE or --lattice FILE");
    if (vxa && lattice && !strcmp(vxa, lattice)) return tool_usage_error("export: --vxa and --lattice name the same file");
    if (vxa && !TOOL_VXA) return tool_not_in_build("export --vxa", "VXA files");

    char err[AM_ERR_MAX];
    am_lattice* lat = &c->work[0].lattice; /* the robot */
    tool_robot rob;
    am_status st = tool_robot_load(c, &ra, lat, &rob, err, sizeof err);
    if (st != AM_OK) return tool_usage_error("%s", err);
    if (lattice) {
#if TOOL_VXA
        /* the lattice format has no place for per-cell layers: said, then the lattice alone */
        if (c->layers.has_phase || c->layers.has_bc)
            fprintf(stderr, "%s: warning: the lattice format holds no %s: --lattice %s has the voxels and materials only "
                            "(--vxa keeps them)\n", ra.name,
                    c->layers.has_phase && c->layers.has_bc ? "per-voxel phases or boundary conditions"
                    : c->layers.has_phase                   ? "per-voxel phases"
                                                            : "boundary conditions",
                    lattice);
#endif
        tool_out o;
        if (tool_out_open(&o, strcmp(lattice, "-") ? lattice : NULL)) return 1;
        st = am_lattice_write(lat, &o.text, err, sizeof err);
        if (st != AM_OK && st != AM_ERR_IO) {
            tool_out_close(&o, 0);
            return tool_usage_error("%s", err);
        }
        if (tool_out_close(&o, 1)) return 1;
    }
#if TOOL_VXA
    if (vxa) {
        /* the time step turns the period in steps into seconds */
        double dt;
        long len = 0;
        st = tool_robot_dt(c, lat, &rob.env, &dt, err, sizeof err);
        if (st != AM_OK) return tool_usage_error("%s: %s", ra.name, err);
        if (am_vxa_format_layers(lat, &c->layers, &rob.env, dt, g_out, sizeof g_out, &len, err, sizeof err) != AM_OK)
            return tool_usage_error("%s", err);
        if (tool_write_output(strcmp(vxa, "-") ? vxa : NULL, g_out, len)) return 1;
    }
#endif
    return 0;
}
