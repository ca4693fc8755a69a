/* amorph export: a robot in another format (VXA for VoxCAD / Voxelyze, the lattice text format,
 * and printable surfaces: STL and AMF, at rest or at a simulated moment). */
#include "picture.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#if TOOL_VXA
static char g_out[AM_VXA_TEXT_MAX]; /* the VXA text, during one call */
#endif

#if TOOL_PICTURES
/* the printable surfaces (desktop profile: the mesh is many times a board's RAM) */
static float g_pose[2 * 7 * AM_MAX_VOXELS];
static long g_pose_step[2];

/* the pose at step `step` of the robot's evaluation into g_pose (its first frame when step is 0);
 * 0 or an exit status after a message */
static int simulate_to(tool_ctx* c, const am_lattice* lat, const tool_robot* rob, const char* name, long step, double time_s)
{
    char err[AM_ERR_MAX];
    am_model* m = &c->work[0].model;
    am_state* s = &c->work[0].state;
    if (am_model_build(m, lat, &rob->env, err, sizeof err) != AM_OK) return tool_usage_error("%s: %s", name, err);
    if (time_s >= 0) {
        /* seconds become steps of the time step the evaluation will take */
        double dt = rob->eval.dt_search ? am_to_si(m, am_dt_search(m, s), AM_DIM_TIME) : am_dt_si(m, rob->env.dt_frac);
        double n = floor(time_s / dt + 0.5);
        if (!(n < 2e9)) return tool_usage_error("export: --time %g s is more than 2e9 steps of %g s", time_s, dt);
        step = (long)n;
    }
    long total = rob->eval.relax_max_steps + (long)rob->eval.cycles * rob->env.period_steps;
    if (step > total)
        return tool_usage_error("export: step %ld is past the longest evaluation of this robot (%ld steps: relaxation at "
                                "most %ld, then %d cycles of %d)", step, total, (long)rob->eval.relax_max_steps,
                                rob->eval.cycles, rob->env.period_steps);
    static am_record rec;
    memset(&rec, 0, sizeof rec);
    rec.every = step > 0 ? (int)step : 1;
    rec.max_frames = step > 0 ? 2 : 1;
    rec.pose = g_pose;
    rec.step = g_pose_step;
    rec.pose_cap = 2L * 7 * AM_MAX_VOXELS;
    am_eval_def def = rob->eval;
    def.record = &rec;
    am_result res;
    am_evaluate(m, s, &def, &res);
    if (rec.frames < rec.max_frames)
        return tool_usage_error("export: the evaluation of %s ended at step %ld (%s), before step %ld", name, res.steps,
                                res.diverged ? "it diverged" : "it settled early", step);
    if (step > 0) memmove(g_pose, g_pose + 7L * m->nv, sizeof(float) * 7 * (size_t)m->nv);
    for (long k = 0; k < 7L * m->nv; k++)
        if (!(fabsf(g_pose[k]) < 1e6f)) return tool_usage_error("export: %s has diverged by step %ld", name, step);
    return 0;
}

/* one printable file: the mesh in pos written as STL (amf 0) or AMF (amf 1); 0 or 1 after a message */
static int write_printable(const char* path, const am_palette* pal, const char* title, int amf)
{
    char err[AM_ERR_MAX];
    tool_out o;
    if (tool_out_open(&o, strcmp(path, "-") ? path : NULL)) return 1;
    am_status st = amf ? am_mesh_write_amf(tool_mesh(), tool_mesh_pos(), pal, title, &o.text, err, sizeof err)
                       : am_mesh_write_stl(tool_mesh(), tool_mesh_pos(), pal, &o.text, err, sizeof err);
    if (st != AM_OK) {
        fprintf(stderr, "amorph: %s\n", o.err[0] ? o.err : err);
        tool_out_close(&o, 0);
        return 1;
    }
    return tool_out_close(&o, 1);
}
#endif

static const char export_help[] =
    "usage: amorph export ROBOT | --scene NAME  --vxa FILE.vxa | --lattice FILE.lattice | --stl FILE.stl |\n"
    "                     --amf FILE.amf  [--step N | --time S]\n"
    "Writes a robot (a lattice, genome or VXA file, a run folder, or a built-in scene) in another format:\n"
    "  --vxa FILE       a VXA 1.1 file that VoxCAD and Voxelyze load (docs/vxa.md); '-' for stdout" TOOL_DESKTOP_ONLY "\n"
    "  --lattice FILE   the amorph lattice text format (docs/formats.md); '-' for stdout\n"
    "  --stl FILE       the surface for printing: ASCII STL in mm, one closed solid per material\n"
    "                   (docs/formats.md); '-' for stdout" TOOL_DESKTOP_ONLY "\n"
    "  --amf FILE       the same as AMF (ISO/ASTM 52915): one volume per material, with its colour;\n"
    "                   '-' for stdout" TOOL_DESKTOP_ONLY "\n"
    "  --step N         STL and AMF: the shape at step N of the robot's evaluation (as amorph sim runs\n"
    "                   it) instead of the rest shape\n"
    "  --time S         the same at simulated time S seconds (the nearest step)\n"
    "The environment in a VXA file is the robot's own (a VXA file's or a run folder's), else the\n"
    "seed's, with the settings below on top. Files are replaced atomically.\n"
    TOOL_ROBOT_HELP;

int cmd_export(tool_ctx* c, int argc, char** argv)
{
    const char *vxa = 0, *lattice = 0, *stl = 0, *amf = 0;
    long step = -1;
    double time_s = -1;
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
        } else if (!strcmp(a, "--stl") || !strcmp(a, "--amf")) {
            if (!v || !v[0]) return tool_usage_error("export: %s needs a file name", a);
            *(a[2] == 's' ? &stl : &amf) = v, i++;
        } else if (!strcmp(a, "--step")) {
            if (!tool_parse_long(v, 0, 2000000000L, &step)) return tool_usage_error("export: --step needs a whole number 0..2000000000");
            i++;
        } else if (!strcmp(a, "--time")) {
            if (!tool_parse_real(v, 0, 1e9, &time_s)) return tool_usage_error("export: --time needs seconds in [0, 1e9]");
            i++;
        } else {
            int r = tool_robot_arg("export", argc, argv, &i, &ra);
            if (r == 2) return 2;
            if (r == 0) return tool_unknown_option("export", a);
        }
    }
    if (!ra.name) return tool_usage_error("export: name a robot file or --scene NAME (amorph export --help)");
    if (!vxa && !lattice && !stl && !amf)
        return tool_usage_error("export: say what to write: --vxa FILE, --lattice FILE, --stl FILE or --amf FILE");
    {
        const char* outs[4] = {vxa, lattice, stl, amf};
        static const char* const flag[4] = {"--vxa", "--lattice", "--stl", "--amf"};
        for (int x = 0; x < 4; x++)
            for (int y = x + 1; y < 4; y++)
                if (outs[x] && outs[y] && !strcmp(outs[x], outs[y]))
                    return tool_usage_error("export: %s and %s name the same %s", flag[x], flag[y],
                                            strcmp(outs[x], "-") ? "file" : "output (one at a time on stdout)");
    }
    if (step >= 0 && time_s >= 0) return tool_usage_error("export: --step and --time both pick the moment: give one");
    if ((step >= 0 || time_s >= 0) && !stl && !amf) return tool_usage_error("export: --step and --time are for --stl and --amf");
    if (vxa && !TOOL_VXA) return tool_not_in_build("export --vxa", "VXA files");
    if ((stl || amf) && !TOOL_PICTURES) return tool_not_in_build(stl ? "export --stl" : "export --amf", "printable files");

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
#if TOOL_PICTURES
    if (stl || amf) {
        st = am_mesh_build(tool_mesh(), lat, AM_MESH_MATERIALS, err, sizeof err);
        if (st != AM_OK) return tool_usage_error("%s: %s", ra.name, err);
        if (step < 0 && time_s < 0) am_mesh_rest(tool_mesh(), tool_mesh_pos());
        else {
            int rc = simulate_to(c, lat, &rob, ra.name, step, time_s);
            if (rc) return rc;
            am_mesh_place(tool_mesh(), g_pose, tool_mesh_pos());
        }
        if (stl && write_printable(stl, &lat->palette, ra.name, 0)) return 1;
        if (amf && write_printable(amf, &lat->palette, ra.name, 1)) return 1;
    }
#endif
    return 0;
}
