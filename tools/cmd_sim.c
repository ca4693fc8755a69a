/* amorph sim: one robot's evaluation, its fitness and gait. */
#include "robot.h"
#include "trajectory.h"

#include <stdio.h>
#include <string.h>

static const char sim_help[] =
    "usage: amorph sim FILE | --scene NAME [options]\n"
    "Simulates one robot (relaxation, then actuation cycles) and prints its fitness and diagnostics.\n"
    "FILE is a lattice (.lattice), a genome, a VXA file" TOOL_DESKTOP_ONLY " (.vxa, with its environment and run length),\n"
    "a run folder of amorph evolve (its best robot, or --genome FILE's, in the run's environment,\n"
    "evaluation and materials) or a voxcraft folder (base.vxa and one .vxd; or name BASE.vxa ROBOT.vxd)" TOOL_DESKTOP_ONLY ";\n"
    "NAME a built-in scene (cube:N, sphere:D, cantilever:N, chain:N, halfbar:N, antibar:N), in the seed's environment.\n"
    TOOL_ROBOT_HELP
    "  --json             one JSON object instead of name = value lines\n"
    "  --trajectory FILE  writes the trajectory: a row every K steps and at the ends of the relaxation\n"
    "                     and of the evaluation (step, time, segment, centre of mass, each voxel's\n"
    "                     position and quaternion; docs/formats.md), as CSV, or as JSON lines when\n"
    "                     FILE ends in .jsonl\n"
    "  --every K          a trajectory row every K steps, 1..1000000000 (period_steps / 10: 10 a cycle)\n"
    "  --trajectory-format csv|jsonl   the trajectory's format, whatever FILE's name\n"
    "  --scalars          the trajectory also holds each voxel's strain, stress (Pa), speed (m/s) and\n"
    "                     phase (the actuation's expansion), as amorph render --colour shows them" TOOL_DESKTOP_ONLY "\n"
    "A run that diverged or did not settle has no score (fitness -1; travel is the displacement either\n"
    "way) and prints one warning line on stderr; the exit status is still 0 (it is a result).\n"
    "Besides the fitness: residual_speed (m/s, the largest RMS voxel speed through the release\n"
    "window, or the last one when the relaxation ran out first), kinetic_resets (the relaxation's\n"
    "kinetic damping stops; docs/physics.md, Evaluation), relax_dt (s, settling's pseudo-step:\n"
    "--relax_dt_frac, 1.8 dt_rec; 0 settles at the run's step) and relax_retried (1: the relaxation\n"
    "failed at the pseudo-step and was done again at the run's step), period_steps and period_s (the\n"
    "actuation period), sustained_travel (m per cycle after cycle sustained_from, 10: the sustained\n"
    "score, --score sustained; 0 without cycles after it), and the gait over the cycles (cycle_travel,\n"
    "sustained, airborne, lift, rotation, roll, gait: still, flop, scoot, bounce or roll; docs/results.md).\n"
    "A convergence study holds the physics in seconds: --dt_frac F --period_s P (the relaxation's\n"
    "step counts are steps of the default step and scale by themselves); --dt_frac alone keeps\n"
    "period_steps, and a note on stderr says the period in seconds changed.\n";

/* the result and the gait of the movement segment (docs/results.md, Gaits), on the standard output */
static int print_result(const char* robot, const am_lattice* lat, const am_result* r, double wall, const am_gait* g, int fitness, int json)
{
    /* the material mix: the voxels of each material the body holds, in palette order */
    const char* names[AM_MAX_MATERIALS];
    double count[AM_MAX_MATERIALS] = {0}, used[AM_MAX_MATERIALS];
    int nused = 0;
    for (long i = 0; i < (long)lat->nx * lat->ny * lat->nz; i++)
        if (lat->cell[i] > 0 && lat->cell[i] <= lat->palette.count) count[lat->cell[i] - 1] += 1;
    for (int m = 0; m < lat->palette.count; m++)
        if (count[m] > 0) names[nused] = lat->palette.mat[m].name, used[nused++] = count[m];
    const double voxel_size = AM_PARAM_TO_DOUBLE(lat->voxel_size);
    /* the body's length: the longer horizontal side of its bounding box as built (travel in body
     * lengths per cycle, the follow-up's measure, divides by it) */
    int lo[2] = {lat->nx, lat->ny}, hi[2] = {-1, -1};
    for (int z = 0, i = 0; z < lat->nz; z++)
        for (int y = 0; y < lat->ny; y++)
            for (int x = 0; x < lat->nx; x++, i++)
                if (lat->cell[i]) {
                    lo[0] = x < lo[0] ? x : lo[0], hi[0] = x > hi[0] ? x : hi[0];
                    lo[1] = y < lo[1] ? y : lo[1], hi[1] = y > hi[1] ? y : hi[1];
                }
    const int side = hi[0] < 0 ? 0 : (hi[0] - lo[0] > hi[1] - lo[1] ? hi[0] - lo[0] : hi[1] - lo[1]) + 1;
    am_gait_summary gs;
    am_gait_summarize(g, fitness, voxel_size, &gs);
    double travel[AM_GAIT_MAX_CYCLES];
    for (int k = 0; k < g->cycles; k++) travel[k] = am_gait_travel(g, fitness, k);
    tool_out out;
    if (tool_out_open(&out, NULL)) return 1;
    tool_rec rec, *q = &rec;
    tool_rec_begin(q, &out.text, json);
    tool_rec_str(q, "robot", robot);
    tool_rec_num(q, "fitness", r->fitness);
    tool_rec_num(q, "travel", r->travel);
    tool_rec_num(q, "dx", r->dx);
    tool_rec_num(q, "dy", r->dy);
    tool_rec_num(q, "dz", r->dz);
    tool_rec_num(q, "sustained_travel", r->sustained);
    tool_rec_int(q, "voxels", r->voxels);
    tool_rec_strs(q, "materials", names, nused);
    tool_rec_nums(q, "material_voxels", used, nused);
    tool_rec_num(q, "body_length", side * voxel_size);
    tool_rec_int(q, "links", r->links);
    tool_rec_num(q, "dt", r->dt);
    tool_rec_int(q, "period_steps", r->period_steps);
    tool_rec_num(q, "period_s", r->period_steps * r->dt);
    tool_rec_int(q, "steps", r->steps);
    tool_rec_int(q, "relax_steps", r->relax_steps);
    tool_rec_int(q, "move_steps", r->move_steps);
    tool_rec_int(q, "diverged", r->diverged);
    tool_rec_int(q, "settled", r->settled);
    tool_rec_num(q, "residual_speed", r->residual_speed);
    tool_rec_int(q, "kinetic_resets", r->kinetic_resets);
    tool_rec_num(q, "relax_dt", r->relax_dt);
    tool_rec_int(q, "relax_retried", r->relax_retried);
    tool_rec_num(q, "sim_seconds", r->sim_seconds);
    tool_rec_num(q, "wall_seconds", wall);
    tool_rec_int(q, "collision_rebuilds", r->rebuilds);
    tool_rec_int(q, "max_pairs", r->max_pairs);
    tool_rec_hex(q, "hash", r->hash);
    tool_rec_nums(q, "cycle_travel", travel, g->cycles);
    tool_rec_num(q, "travel_first_half", gs.first_half);
    tool_rec_num(q, "travel_last_half", gs.last_half);
    tool_rec_num(q, "sustained", gs.sustained);
    tool_rec_num(q, "airborne", gs.airborne);
    tool_rec_num(q, "lift", gs.lift);
    tool_rec_num(q, "rotation", gs.rotation);
    tool_rec_num(q, "roll", gs.roll);
    tool_rec_str(q, "gait", r->diverged ? "diverged" : am_gait_mode_name(gs.mode));
    tool_rec_end(q);
    return tool_out_close(&out, 1);
}

int cmd_sim(tool_ctx* c, int argc, char** argv)
{
    int json = 0, every = 0, format = -1, scalars = 0;
    const char* traj = NULL;
    tool_robot_args ra;
    memset(&ra, 0, sizeof ra);
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        const char* v = i + 1 < argc ? argv[i + 1] : NULL;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            fputs(sim_help, stdout);
            return 0;
        }
        if (!strcmp(a, "--json")) {
            json = 1;
            continue;
        }
        if (!strcmp(a, "--trajectory")) {
            size_t n = v ? strlen(v) : 0;
            if (!n) return tool_usage_error("sim: --trajectory needs a file name");
            if (v[n - 1] == '/') return tool_usage_error("sim: --trajectory %s is a folder, not a file", v);
            traj = v, i++;
            continue;
        }
        if (!strcmp(a, "--every")) {
            if (!tool_parse_int(v, 1, 1000000000, &every))
                return tool_usage_error("sim: --every needs a whole number of steps, 1..1000000000");
            i++;
            continue;
        }
        if (!strcmp(a, "--scalars")) {
            if (!TOOL_PICTURES) return tool_not_in_build("sim --scalars", "the voxels' scalars (strain, stress, speed, phase)");
            scalars = 1;
            continue;
        }
        if (!strcmp(a, "--trajectory-format")) {
            if (v && !strcmp(v, "csv")) format = TOOL_TRAJ_CSV;
            else if (v && !strcmp(v, "jsonl")) format = TOOL_TRAJ_JSONL;
            else return tool_usage_error("sim: --trajectory-format needs csv or jsonl");
            i++;
            continue;
        }
        int r = tool_robot_arg("sim", argc, argv, &i, &ra);
        if (r == 2) return 2;
        if (r == 0) return tool_unknown_option("sim", a, sim_help);
    }
    if (!ra.name) return tool_usage_error("sim: name a robot file or --scene NAME (amorph sim --help)");
    if (!traj && (every || format >= 0 || scalars))
        return tool_usage_error("sim: %s needs --trajectory FILE", every ? "--every" : scalars ? "--scalars" : "--trajectory-format");

    char err[AM_ERR_MAX];
    am_lattice* lat = &c->work[0].lattice; /* the robot */
    am_robot rob;
#if TOOL_VXA
    static char own[TOOL_PATH_MAX]; /* a voxcraft folder's VXD name (the board reads no VXA: no room for one) */
#else
    char own[1];
#endif
    if (tool_robot_load(c, &ra, lat, &rob, err, sizeof err) != AM_OK) return tool_usage_error("%s", err);
    const char* file = tool_robot_name(&ra, own, (int)sizeof own); /* a voxcraft robot: its VXD */
    if (rob.eval.dt_search && ra.dt_s > 0) return tool_usage_error("sim: --dt and dt_search exclude each other");
    am_status st = am_robot_build(&c->work[0].model, &rob, err, sizeof err);
    if (st == AM_ERR_EMPTY && traj) return tool_usage_error("sim: %s: the robot has no voxel, no trajectory to write", file);
    if (st == AM_ERR_EMPTY) {
        /* an empty body is a valid robot that goes nowhere: flagged zero fitness, no simulation */
        tool_out out;
        if (tool_out_open(&out, NULL)) return 1;
        tool_rec q;
        tool_rec_begin(&q, &out.text, json);
        tool_rec_str(&q, "robot", file);
        tool_rec_num(&q, "fitness", 0);
        tool_rec_int(&q, "voxels", 0);
        tool_rec_int(&q, "links", 0);
        tool_rec_int(&q, "empty", 1);
        tool_rec_int(&q, "diverged", 0);
        tool_rec_int(&q, "steps", 0);
        tool_rec_end(&q);
        return tool_out_close(&out, 1);
    }
    if (st != AM_OK) return tool_usage_error("%s: %s", file, err);
    am_eval_def def = rob.eval;

    am_result res;
    am_gait gait;
    def.gait = &gait;
    static tool_traj tr;
    if (traj) {
        if (!every) every = rob.env.period_steps >= 10 ? rob.env.period_steps / 10 : 1;
        if (tool_traj_open(&tr, traj, format >= 0 ? format : tool_traj_format_of(traj), every, scalars, &def)) return 1;
    }
    double t0 = am_port_now();
    am_evaluate(&c->work[0].model, &c->work[0].state, &def, &res);
    double wall = am_port_now() - t0;
    if (traj && tool_traj_close(&tr, 1)) return 1;
    if (print_result(file, lat, &res, wall, &gait, def.fitness, json)) return 1;
    fflush(stdout);
    /* a run that diverged or did not settle is a result (exit status 0), with one line of warning */
    if (res.diverged) {
        const long at = c->work[0].state.diverge_step;
        fprintf(stderr, "amorph: sim: warning: %s diverged at step %ld, in the %s (fitness %g)\n", file, at,
                at <= res.relax_steps ? "relaxation" : "actuation", res.fitness);
    } else if (!res.settled) {
        fprintf(stderr, "amorph: sim: warning: %s did not settle within %ld relaxation steps (residual speed %.2e m/s, "
                "release window %ld steps): no score (fitness -1; it travelled %.4g m)\n", file, res.relax_steps, res.residual_speed,
                am_steps_at(&c->work[0].model, &c->work[0].state, def.release_steps), res.travel);
    }
    return 0;
}
