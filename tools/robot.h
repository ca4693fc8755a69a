/* tools/robot.h: the robot a command names (a built-in scene, a lattice, genome or VXA file, or a
 * run folder), loaded as one unit with the environment and evaluation it comes with, and the
 * settings (--KEY VALUE, the configuration keys of amorph evolve) that change them.
 *
 * The order is "file first, then flags in order": the robot's own environment and evaluation (a
 * VXA file's, a run folder's, else the seed's defaults), then each setting of the command line in
 * the order given. Settings in seconds (a VXA file's period, --dt) become steps of this robot
 * before anything builds its model, so no model is edited after am_model_build. */
#ifndef AMORPH_TOOLS_ROBOT_H
#define AMORPH_TOOLS_ROBOT_H

#include "cmd.h"

#define TOOL_MAX_SETTINGS 64

/* what sim, render, view and export were told about the robot */
typedef struct tool_robot_args {
    const char* name;          /* the file or run folder, or the scene's name; NULL until given */
    const char* vxd;           /* a voxcraft VXD file over the VXA file name (the other file named with
                                  it, one of them ending in .vxd); NULL when none */
    int is_scene;              /* 1: name is a scene (--scene NAME) */
    const char* genome;        /* --genome FILE: a run folder's robot from this genome instead of its
                                  best.genome (the run's settings, palette and expression); NULL */
    double dt_s;               /* --dt SECONDS (a fixed time step), 0 when not given */
    int nset;                  /* settings given, in order */
    const char* key[TOOL_MAX_SETTINGS];  /* each as the configuration table spells its key */
    const char* val[TOOL_MAX_SETTINGS];
} tool_robot_args;

/* The flag names every command shares (one vocabulary): "--KEY VALUE" or "--KEY=VALUE" for a key of
 * the configuration table (amorph evolve --help-config), '-' standing for '_' anywhere in KEY, and
 * these documented aliases of older spellings:
 *   --repr R -> --representation R     --size N -> --workspace N
 *   --relax-max N -> --relax_max_steps N     --dt-search (alone) -> --dt_search on
 *   --evals N -> --evaluations N
 * Sets *key to the table's spelling and *val to the value ("on" for a bare --dt-search) and returns
 * 1; 0 when argv[*i] is no setting. A setting that needs a value and has none, or an old spelling
 * that now means something else (--cte linear|volume: the CTE convention is --cte_mode), prints a
 * one-line message and returns 2 (cmd.h: an option parser's convention). *i is left on the last
 * token used. */
int tool_setting_arg(const char* cmd, int argc, char** argv, int* i, const char** key, const char** val);

/* one argument of sim, render, view or export at argv[*i]: the robot (a file or run folder, or
 * --scene NAME; a VXA file and a VXD file over it, voxcraft-sim's `base.vxa robot.vxd`; a folder
 * holding a base VXA and one .vxd, voxcraft-sim's layout), --genome FILE (a run folder's robot from
 * another genome), --dt SECONDS, or a setting of the robot's environment, evaluation or materials
 * (tool_setting_arg). Returns 1 when consumed, 0 when it is none of these (the command's own
 * option, or unknown), 2 after a one-line message (a second robot, a setting of the evolver such
 * as --population, a value missing). */
int tool_robot_arg(const char* cmd, int argc, char** argv, int* i, tool_robot_args* a);
/* 1 when s ends with tail */
int tool_ends_with(const char* s, const char* tail);

/* the robot of a as *r (amorph/sim.h, am_robot): its body in lat, its per-cell layers (a VXA
 * file's; in c's static room, desktop profile), its environment and evaluation ready to build the
 * model with (am_robot_build; eval.record NULL): the file's (a VXA file's
 * environment, a run folder's environment, evaluation and materials), else the seed's; then the
 * settings of a in order: environment and evaluation keys replace the values, materials keys
 * (cte, mu_static, mu_kinetic, voxel_size) change every material of the robot's palette that they
 * apply to (cte only the actuated ones, those of non-zero CTE) and the voxel size; relax_max_steps
 * below relax_min_steps lowers that too. Then seconds become steps: --dt sets env.dt_frac (in the key
 * dt_frac's range), a period in seconds (a VXA file's, unless the file or a setting gave
 * period_steps) becomes period_steps of the resulting step, 2 to 10^7, and a VXA file's run length
 * (VoxCAD's StopCondition, evosoro's InitCmTime) becomes cycles and relax_min_steps unless a setting
 * gave them (am_vxa_stop_settings; one note line on stderr says what it set). Last, the evaluation's
 * budget (am_evo_check_budget, 10^9 steps). A folder that is neither a run folder nor a voxcraft
 * folder is refused with what it lacks. Messages are "file:line: problem" or "KEY = 'VALUE':
 * problem"; those of the period and the budget name where the setting to blame was given
 * ("FILE:LINE: ..." for a VXA file's element or a run's config.txt line, "--KEY = ..." for a flag). */
am_status tool_robot_load(tool_ctx* c, const tool_robot_args* a, am_lattice* lat, am_robot* r, char* err, int errsz);

/* the name of the robot's own file, for reports: a's file, the VXD of a VXA file with a VXD over it
 * (voxcraft-sim's robot; a voxcraft folder's .vxd, written into buf, which holds TOOL_PATH_MAX
 * bytes), or a's name (a scene, a run folder) */
const char* tool_robot_name(const tool_robot_args* a, char* buf, int cap);

/* the environment and evaluation keys whose values in `to` differ from those in `from`, and the
 * material keys named by the AM_MATERIAL_* bits of `materials` (TOOL_APART_STIFFNESS: stiffness_min
 * and stiffness_max), as "key = value" items (to's values) separated by ", " into out (cut short
 * with ", ..." when out is full); their count */
#define TOOL_APART_STIFFNESS 16u
int tool_settings_apart(const am_evo_def* from, const am_evo_def* to, unsigned materials, char* out, int cap);

/* the time step in seconds the simulator takes for the robot r (an empty robot is timed as one
 * voxel of its first material); builds the model into c->work[0].model */
am_status tool_robot_dt(tool_ctx* c, const am_robot* r, double* dt, char* err, int errsz);

/* ---- a robot from a genome (tools/robot_genome.c) ---- */

/* what the robot being loaded took from a genome, for the checks and the note after loading */
typedef struct tool_genome_use {
    int genome;              /* 1: a genome's robot (a genome file or a run folder's best) */
    int evolved_stiffness;   /* 1: it has an evolved stiffness field */
    am_express_def range;    /* the stiffness range it was expressed in */
} tool_genome_use;
/* 1 when key is one of the palette's (palette, materialK): what a genome's material names are
 * looked up in */
int tool_robot_palette_key(const char* key);
/* the settings' palette keys over d, in order; 1 when there were any, 0 when none, or -1 after a
 * message (a materialK after a gap, a name given twice: am_evo_check's) */
int tool_robot_palette(const tool_robot_args* a, am_evo_def* d, char* err, int errsz);
/* the stiffness range an evolved stiffness field maps to: ex's (the run's, or the default for a
 * genome file) under the settings' stiffness_min and stiffness_max, checked as amorph evolve
 * checks them */
am_status tool_robot_stiffness_range(const tool_robot_args* a, am_express_def* ex, char* err, int errsz);
/* the evolved phases and stiffnesses of the genome just expressed into c->work[0].geno, into the
 * robot's layers (nothing for a genome without them), its stiffnesses in ex's range; *use says so */
am_status tool_robot_genome_layers(tool_ctx* c, const am_express_def* ex, am_robot* r, const char* fname, tool_genome_use* use, char* err,
                                   int errsz);

/* the help lines of the robot commands' shared options */
#define TOOL_ROBOT_HELP                                                                                 \
    "Settings (file first, then the flags in order): every key of the robot's environment, evaluation\n" \
    "and materials in amorph evolve's configuration (amorph evolve --help-config; '-' may stand for\n"   \
    "'_'): --cycles N, --period_steps N, --amplitude DEG, --gravity G, --collisions on|off,\n"           \
    "--floor on|off, --cte_mode volumetric|linear, --fitness horizontal|x|3d, --dt_frac F,\n"            \
    "--dt_search on|off (--dt-search alone: on), --relax_max_steps N (alias --relax-max N),\n"           \
    "--release_steps N, --mu_static M, --mu_kinetic M, --cte C, --voxel_size M, ...\n"                   \
    "  --genome FILE      ROBOT a run folder: FILE's robot instead of its best, in the run's settings,\n"  \
    "                     materials and expression (a robot kept at a round, another run's best, ...)\n"    \
    "  --dt SECONDS       a fixed time step (becomes dt_frac of this robot, in dt_frac's [1e-6, 10])\n"  \
    "  --stiffness_min PA, --stiffness_max PA   the range a genome's evolved stiffness maps to (a\n"   \
    "                     genome file's: 1e5..1e7 unless given; a run folder's: the run's)\n"          \
    "  --palette P, --materialK SPEC   the palette a genome's material names are looked up in (a\n"   \
    "                     genome file's: the built-in one unless given; a run folder's: the run's)\n"  \
    "A voxcraft-sim robot: BASE.vxa ROBOT.vxd (the VXD replaces parts of the base), or a folder\n"     \
    "holding base.vxa and one .vxd" TOOL_DESKTOP_ONLY " (docs/vxa.md).\n"

#endif
