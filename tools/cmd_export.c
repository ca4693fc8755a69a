/* amorph export: a robot in another format (VXA for VoxCAD / Voxelyze, the lattice text format,
 * and printable surfaces: STL and AMF, at rest or at a simulated moment; a moment whose surface
 * crosses itself gets a warning). */
#include "evolve_cmd.h"
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
static am_mesh_grid g_grid; /* the self-intersection check's scratch */
#define EXPORT_PATH_MAX 4096
static char g_stl_path[AM_MAX_MATERIALS][EXPORT_PATH_MAX]; /* the per-material STL files */
#define EXPORT_MAX_VISITS 200000000L /* the self-intersection check's work: some seconds at most */

/* the pose at step `step` of the robot's evaluation into g_pose (its first frame when step is 0),
 * the step in *at; 0 or an exit status after a message */
static int simulate_to(tool_ctx* c, const am_lattice* lat, const am_robot* rob, const char* name, long step, double time_s,
                       long* at)
{
    char err[AM_ERR_MAX];
    am_model* m = &c->work[0].model;
    am_state* s = &c->work[0].state;
    /* with the robot's layers (a VXA file's phases, stiffnesses, clamps and forces), as sim runs it */
    if (am_model_build_layers(m, lat, &rob->env, rob->layers, err, sizeof err) != AM_OK) return tool_usage_error("%s: %s", name, err);
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
    *at = step;
    return 0;
}

/* the mesh of lat in mode (AM_MESH_BODY or AM_MESH_MATERIALS) into tool_mesh(), placed at rest
 * (pose NULL) or in pose, its pinches opened; 0 or an exit status after a message */
static int place_mesh(const am_lattice* lat, int mode, const float* pose, const char* name)
{
    char err[AM_ERR_MAX];
    if (am_mesh_build(tool_mesh(), lat, mode, err, sizeof err) != AM_OK) return tool_usage_error("%s: %s", name, err);
    if (pose) am_mesh_place(tool_mesh(), pose, tool_mesh_pos());
    else am_mesh_rest(tool_mesh(), tool_mesh_pos());
    am_mesh_open_pinches(tool_mesh(), pose, tool_mesh_pos());
    return 0;
}

/* the body's surface (tool_mesh(), AM_MESH_BODY, placed) at step `step`: a warning line on stderr
 * when it crosses itself, or when the check could not look at every pair */
static void warn_crossings(const char* name, long step)
{
    am_mesh_crossing x;
    am_mesh_crossings(tool_mesh(), tool_mesh_pos(), -1, &g_grid, EXPORT_MAX_VISITS, &x);
    if (x.pairs > 0)
        fprintf(stderr, "%s: warning: at step %ld the surface crosses itself (%ld pair%s of triangles%s, the first near "
                        "x %.1f y %.1f z %.1f mm): a printer fuses the parts that overlap\n",
                name, step, x.pairs, x.pairs == 1 ? "" : "s", x.complete ? "" : " at least", x.at[0] * 1000, x.at[1] * 1000,
                x.at[2] * 1000);
    else if (!x.complete)
        fprintf(stderr, "%s: warning: at step %ld the self-intersection check stopped after %ld pairs of triangles: the "
                        "surface may cross itself\n", name, step, x.visits);
}

/* the file of material `mat`'s surface: FILE.stl (or FILE) becomes FILE-NAME.stl; 0 or 2 after a message */
static int material_path(char* buf, const char* stl, const char* mat)
{
    size_t n = strlen(stl);
    if (n >= 4 && stl[n - 4] == '.' && (stl[n - 3] | 32) == 's' && (stl[n - 2] | 32) == 't' && (stl[n - 1] | 32) == 'l') n -= 4;
    if (n + strlen(mat) + 6 > EXPORT_PATH_MAX) return tool_usage_error("export: --stl %s: the file name is too long", stl);
    snprintf(buf, EXPORT_PATH_MAX, "%.*s-%s.stl", (int)n, stl, mat);
    return 0;
}

/* one printable file: the mesh in pos written as STL of material mat (-1: every triangle; amf 0)
 * or AMF (amf 1); 0 or 1 after a message */
static int write_printable(const char* path, const am_palette* pal, const char* title, int amf, int mat)
{
    char err[AM_ERR_MAX];
    tool_out o;
    if (tool_out_open(&o, strcmp(path, "-") ? path : NULL)) return 1;
    am_status st = amf ? am_mesh_write_amf(tool_mesh(), tool_mesh_pos(), pal, title, &o.text, err, sizeof err)
                       : am_mesh_write_stl(tool_mesh(), tool_mesh_pos(), pal, mat, &o.text, err, sizeof err);
    if (st != AM_OK) {
        fprintf(stderr, "amorph: %s\n", o.err[0] ? o.err : err);
        tool_out_close(&o, 0);
        return 1;
    }
    return tool_out_close(&o, 1);
}
#endif

/* --checkpoint: the run folder dir's checkpoint again, without its same-body table (am_evo.memo, a
 * cache of results: a run resumed from the copy simulates those bodies again, to the same results,
 * rows and best robot; only its count of reused evaluations is lower). 0, 1 or 2 */
static TOOL_NOINLINE int export_checkpoint(tool_ctx* c, const char* dir, const char* out)
{
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX];
    if (!tool_is_run_dir(dir)) return tool_usage_error("export: --checkpoint takes a run folder of amorph evolve; %s is not one", dir);
    if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, AM_RUN_CHECKPOINT) >= sizeof path)
        return tool_usage_error("export: %s: the path is too long", dir);
    am_evo* e = &c->evo;
    int rc = read_checkpoint(path, e);
    if (rc) return rc;
    memset(e->memo, 0, sizeof e->memo);
    tool_out o;
    if (tool_out_open(&o, strcmp(out, "-") ? out : NULL)) return 1;
    am_status st = am_evo_checkpoint_write(e, &o.text, err, sizeof err);
    if (st != AM_OK && st != AM_ERR_IO) {
        tool_out_close(&o, 0);
        return tool_usage_error("%s", err);
    }
    return tool_out_close(&o, 1);
}

static const char export_help[] =
    "usage: amorph export ROBOT | --scene NAME  --vxa FILE.vxa | --lattice FILE.lattice |\n"
    "                     --stl FILE.stl [--merge] | --amf FILE.amf  [--step N | --time S]\n"
    "Writes a robot (a lattice, genome or VXA file, a run folder, or a built-in scene) in another format:\n"
    "  --vxa FILE       a VXA 1.1 file that VoxCAD and Voxelyze load (docs/vxa.md); '-' for stdout" TOOL_DESKTOP_ONLY "\n"
    "                   (with the robot's layers, environment and evaluation: amorph sim FILE.vxa\n"
    "                   evaluates it as the run or the command's settings did)\n"
    "  --lattice FILE   the amorph lattice text format (docs/formats.md); '-' for stdout\n"
    "  --stl FILE       the surface for printing, ASCII STL in mm: one file per material the robot uses,\n"
    "                   FILE-NAME.stl (NAME the material's; robot.stl gives robot-passive.stl,\n"
    "                   robot-active.stl, ...), each one closed solid (docs/formats.md); '-' for stdout\n"
    "                   with --merge or when the robot has one material" TOOL_DESKTOP_ONLY "\n"
    "  --merge          --stl writes FILE itself: one closed solid, the body's outer surface (the walls\n"
    "                   between materials left out)\n"
    "  --amf FILE       the surfaces as AMF (ISO/ASTM 52915): one volume per material, with its colour;\n"
    "                   '-' for stdout" TOOL_DESKTOP_ONLY "\n"
    "  --step N         STL and AMF: the shape at step N of the robot's evaluation (as amorph sim runs\n"
    "                   it) instead of the rest shape; a warning on stderr when that surface crosses\n"
    "                   itself (a printer would fuse the parts that overlap)\n"
    "  --time S         the same at simulated time S seconds (the nearest step)\n"
    "  --checkpoint FILE  ROBOT a run folder: its checkpoint.txt without the table of bodies already\n"
    "                   simulated (a cache, most of the file's size): a run resumed from it goes on to\n"
    "                   the same rows and best robot, simulating those bodies again; '-' for stdout\n"
    "Where voxels of one surface touch only along an edge or at a corner, its vertex there is split and\n"
    "each part moved 2.5% of the way to its own voxels' centre, so every file is manifold.\n"
    "The environment in a VXA file is the robot's own (a VXA file's or a run folder's), else the\n"
    "seed's, with the settings below on top. Files are replaced atomically.\n"
    TOOL_ROBOT_HELP;

int cmd_export(tool_ctx* c, int argc, char** argv)
{
    const char *vxa = 0, *lattice = 0, *stl = 0, *amf = 0, *ckpt = 0;
    int merge = 0;
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
        } else if (!strcmp(a, "--checkpoint")) {
            if (!v || !v[0]) return tool_usage_error("export: --checkpoint needs a file name");
            ckpt = v, i++;
        } else if (!strcmp(a, "--merge")) {
            merge = 1;
        } else if (!strcmp(a, "--step")) {
            if (!tool_parse_long(v, 0, 2000000000L, &step)) return tool_usage_error("export: --step needs a whole number 0..2000000000");
            i++;
        } else if (!strcmp(a, "--time")) {
            if (!tool_parse_real(v, 0, 1e9, &time_s)) return tool_usage_error("export: --time needs seconds in [0, 1e9]");
            i++;
        } else {
            int r = tool_robot_arg("export", argc, argv, &i, &ra);
            if (r == 2) return 2;
            if (r == 0) return tool_unknown_option("export", a, export_help);
        }
    }
    if (!ra.name) return tool_usage_error("export: name a robot file or --scene NAME (amorph export --help)");
    if (ckpt) {
        if (ra.is_scene || ra.vxd || ra.genome || ra.nset || ra.dt_s > 0 || vxa || lattice || stl || amf || step >= 0 || time_s >= 0 || merge)
            return tool_usage_error("export: --checkpoint takes a run folder and no other output or setting");
        return export_checkpoint(c, ra.name, ckpt);
    }
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
    if (merge && !stl) return tool_usage_error("export: --merge is for --stl");
    if (vxa && !TOOL_VXA) return tool_not_in_build("export --vxa", "VXA files");
    if ((stl || amf) && !TOOL_PICTURES) return tool_not_in_build(stl ? "export --stl" : "export --amf", "printable files");

    char err[AM_ERR_MAX];
    am_lattice* lat = &c->work[0].lattice; /* the robot */
    am_robot rob;
    am_status st = tool_robot_load(c, &ra, lat, &rob, err, sizeof err);
    if (st != AM_OK) return tool_usage_error("%s", err);
    if (lattice) {
#if TOOL_VXA
        /* the lattice format has no place for per-cell layers: said, then the lattice alone */
        const am_layers* ly = rob.layers;
        if (ly->has_phase || ly->has_stiffness || ly->has_bc) {
            char what[96] = "";
            const char* item[3] = {ly->has_phase ? "per-voxel phases" : NULL,
                                   ly->has_stiffness ? "per-voxel stiffness" : NULL,
                                   ly->has_bc ? "boundary conditions" : NULL};
            for (int k = 0; k < 3; k++)
                if (item[k]) {
                    if (what[0]) strcat(what, " or ");
                    strcat(what, item[k]);
                }
            fprintf(stderr, "%s: warning: the lattice format holds no %s: --lattice %s has the voxels and materials only "
                            "(--vxa keeps them)\n", ra.name, what, lattice);
        }
#endif
        /* nor for where the body starts (a VXA file's, VoxCAD's placement): a lattice is lowered onto the floor */
        if (rob.env.lift > AM_P(0))
            fprintf(stderr, "%s: warning: the lattice format holds no starting height: --lattice %s lowers the body onto the floor, "
                            "not %.4g m above it%s\n", ra.name, lattice, (double)rob.env.lift, TOOL_VXA ? " (--vxa keeps it)" : "");
        /* nor for the environment and the evaluation: the settings away from the defaults, said */
        char apart[512];
        am_evo_def dr = am_default_evo();
        const am_evo_def d0 = dr;
        dr.env = rob.env;
        dr.eval = rob.eval;
        const int napart = tool_settings_apart(&d0, &dr, 0, apart, (int)sizeof apart);
        if (napart > 0)
            fprintf(stderr, "%s: warning: the lattice format holds no environment or evaluation: --lattice %s leaves out %s "
                            "(give %s to amorph sim%s)\n", ra.name, lattice, apart, napart > 1 ? "them" : "it",
                    TOOL_VXA ? ", or export --vxa, which keeps them" : "");
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
        st = tool_robot_dt(c, &rob, &dt, err, sizeof err);
        if (st != AM_OK) return tool_usage_error("%s: %s", ra.name, err);
        if (am_vxa_format_robot(&rob, dt, g_out, sizeof g_out, &len, err, sizeof err) != AM_OK)
            return tool_usage_error("%s", err);
        if (tool_write_output(strcmp(vxa, "-") ? vxa : NULL, g_out, len)) return 1;
    }
#endif
#if TOOL_PICTURES
    if (stl || amf) {
        /* the files: FILE itself (--merge), or one per material the robot uses */
        int nmat = 0, one = -1;
        for (int k = 0; k < lat->palette.count && k < AM_MAX_MATERIALS; k++) {
            int used = 0;
            for (long cc = 0; cc < (long)lat->nx * lat->ny * lat->nz && !used; cc++) used = lat->cell[cc] == k + 1;
            if (used) nmat++, one = k;
            g_stl_path[k][0] = 0;
            if (used && stl && !merge && strcmp(stl, "-")) {
                if (material_path(g_stl_path[k], stl, lat->palette.mat[k].name)) return 2;
                const char* others[3] = {vxa, lattice, amf};
                for (int x = 0; x < 3; x++)
                    if (others[x] && !strcmp(others[x], g_stl_path[k]))
                        return tool_usage_error("export: --stl %s writes %s, which another output names too", stl, g_stl_path[k]);
            }
        }
        if (stl && !merge && !strcmp(stl, "-") && nmat > 1)
            return tool_usage_error("export: --stl - writes one solid, and %s has %d materials: add --merge, or name a file "
                                    "(one per material)", ra.name, nmat);
        if (stl && !merge && !strcmp(stl, "-") && one >= 0) strcpy(g_stl_path[one], "-");
        const float* pose = NULL;
        long at = 0;
        if (step >= 0 || time_s >= 0) {
            int rc = simulate_to(c, lat, &rob, ra.name, step, time_s, &at);
            if (rc) return rc;
            pose = g_pose;
        }
        /* the body's surface: checked when deformed, written with --merge */
        if (pose || merge) {
            int rc = place_mesh(lat, AM_MESH_BODY, pose, ra.name);
            if (rc) return rc;
            if (pose) warn_crossings(ra.name, at);
            if (merge && write_printable(stl, &lat->palette, ra.name, 0, -1)) return 1;
        }
        /* the materials' surfaces */
        if (amf || !merge) {
            int rc = place_mesh(lat, AM_MESH_MATERIALS, pose, ra.name);
            if (rc) return rc;
            for (int k = 0; k < lat->palette.count && k < AM_MAX_MATERIALS && stl && !merge; k++)
                if (g_stl_path[k][0] && write_printable(g_stl_path[k], &lat->palette, ra.name, 0, k)) return 1;
            if (amf && write_printable(amf, &lat->palette, ra.name, 1, -1)) return 1;
        }
    }
#endif
    return 0;
}
