/* amorph export: a robot in another format (VXA for VoxCAD / Voxelyze, the lattice text format),
 * and the VXA loader behind tool_load_robot. */
#include "cmd.h"

#include <stdio.h>
#include <string.h>

int tool_vxa_loaded;
#if TOOL_VXA
am_vxa_info tool_vxa_info;

static am_xml_doc g_xml;       /* the VXA reader's workspace */
static am_lattice g_one;       /* a one-voxel stand-in to time an empty robot */
static char g_out[AM_VXA_TEXT_MAX]; /* the VXA text */

am_status tool_vxa_text_to_lattice(const char* text, const char* fname, am_lattice* lat, char* err, int errsz)
{
    if (!am_vxa_sniff(text)) return AM_ERR_ARG;
    am_status st = am_vxa_parse(lat, &tool_vxa_info, &g_xml, text, fname, err, errsz);
    if (st != AM_OK) return st;
    tool_vxa_loaded = 1;
    int kept = 0;
    for (const char* p = tool_vxa_info.warning; *p; p++) kept += *p == '\n';
    fputs(tool_vxa_info.warning, stderr);
    if (tool_vxa_info.warnings > kept)
        fprintf(stderr, "%s: warning: %d more warnings not shown\n", fname, tool_vxa_info.warnings - kept);
    return AM_OK;
}
#endif

static const char export_help[] =
    "usage: amorph export ROBOT | --scene NAME  --vxa FILE.vxa | --lattice FILE.lattice\n"
    "Writes a robot (a lattice, genome or VXA file, or a built-in scene) in another format:\n"
    "  --vxa FILE       a VXA 1.1 file that VoxCAD and Voxelyze load (docs/vxa.md); '-' for stdout" TOOL_DESKTOP_ONLY "\n"
    "  --lattice FILE   the amorph lattice text format (docs/formats.md); '-' for stdout\n"
    "The environment in a VXA file is the robot's own when it was read from a VXA file, else the\n"
    "seed's (the defaults of amorph sim). Files are replaced atomically.\n";

int cmd_export(int argc, char** argv)
{
    const char *robot = 0, *vxa = 0, *lattice = 0;
    int is_scene = 0;
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        const char* v = i + 1 < argc ? argv[i + 1] : 0;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(export_help, stdout);
            return 0;
        } else if (!strcmp(a, "--scene")) {
            if (!v) return tool_usage_error("export: --scene needs a name (cube:N, sphere:D, cantilever:N, chain:N)");
            if (robot) return tool_usage_error("export: one robot at a time ('%s' and '%s')", robot, v);
            robot = v, is_scene = 1, i++;
        } else if (!strcmp(a, "--vxa")) {
            if (!v) return tool_usage_error("export: --vxa needs a file name");
            vxa = v, i++;
        } else if (!strcmp(a, "--lattice")) {
            if (!v) return tool_usage_error("export: --lattice needs a file name");
            lattice = v, i++;
        } else if (a[0] == '-' && a[1]) {
            return tool_usage_error("export: unknown option '%s' (amorph export --help)", a);
        } else {
            if (robot) return tool_usage_error("export: one robot at a time ('%s' and '%s')", robot, a);
            robot = a;
        }
    }
    if (!robot) return tool_usage_error("export: name a robot file or --scene NAME (amorph export --help)");
    if (!vxa && !lattice) return tool_usage_error("export: say what to write: --vxa FILE or --lattice FILE");
    if (vxa && lattice && !strcmp(vxa, lattice)) return tool_usage_error("export: --vxa and --lattice name the same file");
    if (vxa && !TOOL_VXA) return tool_not_in_build("export --vxa", "VXA files");

    char err[AM_ERR_MAX];
    am_lattice* lat = &tool_work[0].lattice; /* the robot */
    am_status st = tool_load_robot(robot, is_scene, lat, err, sizeof err);
    if (st != AM_OK) return tool_usage_error("%s", err);
    if (lattice) {
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
    long len = 0;
    if (vxa) {
        am_env env = tool_vxa_loaded ? tool_vxa_info.env : am_default_env();
        /* the time step turns the period in steps into seconds; an empty robot is timed as one
         * voxel of material 1 */
        const am_lattice* timed = lat;
        if (am_lattice_count(lat) == 0) {
            g_one = *lat;
            g_one.cell[0] = 1;
            timed = &g_one;
        }
        const double period_s = tool_vxa_loaded && !tool_vxa_info.period_steps_given ? tool_vxa_info.temp_period : 0;
        st = period_s > 0 ? tool_resolve_env(timed, 0, period_s, &env, err, sizeof err) : am_model_build(&tool_work[0].model, timed, &env, err, sizeof err);
        if (st != AM_OK) return tool_usage_error("%s: %s", robot, err);
        double dt = am_dt_si(&tool_work[0].model, env.dt_frac);
        if (am_vxa_format(lat, &env, dt, g_out, sizeof g_out, &len, err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
        if (tool_write_output(strcmp(vxa, "-") ? vxa : NULL, g_out, len)) return 1;
    }
#endif
    return 0;
}
