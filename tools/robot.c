/* The robot a command names, loaded as one unit with its environment and evaluation, and the
 * settings that change them (tools/robot.h); the options naming it are tools/robot_args.c. */
#include "robot.h"

#include <stdio.h>
#include <string.h>

/* where the settings an evaluation's length depends on came from, for messages: a line of the
 * robot's file (a VXA file's element, a run folder's config.txt), or a flag; nothing for a default.
 * Those keys only (a board has a few hundred bytes of RAM to spare) */
static const char* const origin_keys[] = {"dt_frac", "dt_search", "period_s", "period_steps", "cycles", "relax_max_steps"};
#define ORIGIN_KEYS ((int)(sizeof origin_keys / sizeof origin_keys[0]))
typedef struct origins {
    int line[ORIGIN_KEYS];              /* the file's line that set the key (0: none) */
    unsigned char in_vxd[ORIGIN_KEYS];  /* 1: that line is the VXD file's */
    unsigned char flag[ORIGIN_KEYS];    /* 1: a flag set it last */
    const char* file;                   /* the VXA file of those lines, or the run folder */
    const char* vxd;                    /* the VXD file over it, or NULL */
    int run;                            /* 1: the lines are the run folder's config.txt's */
} origins;
static origins g_origin;
/* what the robot being loaded took from a genome (its palette, stiffness range, layers) */
static tool_genome_use g_use;

static int key_index(const char* key)
{
    for (int i = 0; i < am_evo_key_count() && i < AM_EVO_KEY_MAX; i++)
        if (!strcmp(am_evo_key_name(i), key)) return i;
    return -1;
}

/* the slot of configuration key i in g_origin, or -1 */
static int origin_slot(int i)
{
    const char* name = am_evo_key_name(i);
    for (int k = 0; name && k < ORIGIN_KEYS; k++)
        if (!strcmp(origin_keys[k], name)) return k;
    return -1;
}

/* the lines of the keys in lines (by key index, AM_EVO_KEY_MAX of them) into g_origin */
static void origin_lines(const int* lines, const unsigned char* in_vxd)
{
    for (int k = 0; k < ORIGIN_KEYS; k++) {
        const int i = key_index(origin_keys[k]);
        g_origin.line[k] = i >= 0 ? lines[i] : 0;
        g_origin.in_vxd[k] = (unsigned char)(i >= 0 && in_vxd ? in_vxd[i] : 0);
    }
}

/* "FILE:LINE" or "--KEY" for where key i's value came from, or "" */
static const char* origin_of(int i, char* buf, int cap)
{
    const int k = i >= 0 ? origin_slot(i) : -1;
    buf[0] = 0;
    if (k < 0) return buf;
    if (g_origin.flag[k]) snprintf(buf, (size_t)cap, "--%s", origin_keys[k]);
    else if (g_origin.line[k] > 0 && g_origin.run) snprintf(buf, (size_t)cap, "%s/" AM_RUN_CONFIG ":%d", g_origin.file, g_origin.line[k]);
    else if (g_origin.line[k] > 0)
        snprintf(buf, (size_t)cap, "%s:%d", g_origin.in_vxd[k] && g_origin.vxd ? g_origin.vxd : g_origin.file, g_origin.line[k]);
    return buf;
}

/* ---- loading ---- */

#if TOOL_VXA
/* VXA text (and a VXD file over it, vxd NULL when none) -> the robot r (its lattice, layers and
 * environment); the reader's warnings on stderr */
static am_status load_vxa(const char* text, const char* fname, const char* vxd, am_robot* r, const am_vxa_info** out, char* err, int errsz)
{
    static am_xml_doc doc, vxd_doc; /* the XML reader's workspaces, used during this call only */
    static am_vxa_info info;        /* the file's environment, layers and warnings, copied out below;
                                       its run length read by the caller (*out) until the next load */
    static char vxd_text[4L << 20]; /* the VXD file's text (a structure and its layers): 4 MiB, as a VXA file's */
    am_status st;
    if (vxd) {
        long len = 0;
        if ((st = am_port_read_file(vxd, vxd_text, sizeof vxd_text, &len, err, errsz)) != AM_OK) return st;
        if ((long)strlen(vxd_text) != len) return am_fail(err, errsz, AM_ERR_PARSE, "%s:1: binary data (a NUL byte) in a text file", vxd);
    }
    st = am_vxa_parse_vxd(r->lattice, &info, &doc, text, fname, &vxd_doc, vxd ? vxd_text : NULL, vxd, err, errsz);
    if (st != AM_OK) return st;
    int kept = 0;
    for (const char* p = info.warning; *p; p++) kept += *p == '\n';
    fputs(info.warning, stderr);
    if (info.warnings > kept) fprintf(stderr, "%s: warning: %d more warnings not shown\n", fname, info.warnings - kept);
    /* one line that says whether the warnings matter to the motion */
    if (info.differ[0])
        fprintf(stderr, "%s: warning: results will differ from the reference simulator: amorph does not simulate %s (warnings above)\n",
                vxd ? vxd : fname, info.differ);
    *out = &info;
    g_origin.file = fname;
    g_origin.vxd = vxd;
    origin_lines(info.key_line, info.key_vxd);
    return am_vxa_robot(r, &info, err, errsz);
}
#endif

/* a run folder's best robot (or a->genome's, --genome FILE), with the environment, evaluation,
 * materials and expression it evolved in */
static am_status load_run(tool_ctx* c, const tool_robot_args* a, const char* dir, am_robot* r, char* err, int errsz)
{
    char path[TOOL_PATH_MAX], msg[AM_ERR_MAX];
    am_evo_def d = am_stored_evo(); /* a key config.txt does not name: as the run had it */
    /* a NUL byte ends these texts, as it ended them when they were parsed whole */
    int lines[AM_EVO_KEY_MAX] = {0};
    snprintf(path, sizeof path, "%s/" AM_RUN_CONFIG, dir);
    am_status st = tool_read_config_lines(path, &d, 1, lines, err, errsz);
    if (st != AM_OK) return st;
    origin_lines(lines, NULL);
    g_origin.file = dir;
    g_origin.run = 1;
    if (a->genome) snprintf(path, sizeof path, "%s", a->genome);
    else snprintf(path, sizeof path, "%s/" AM_RUN_BEST_GENOME, dir);
    tool_src src;
    st = tool_src_open(&src, path, TOOL_FILE_MAX, 1, err, errsz);
    if (st == AM_OK) st = tool_read_genome(&src, tool_genome(c), err, errsz);
    tool_src_close(&src);
    if (st != AM_OK) return st;
    /* the run's palette (the settings' palette keys over it), in the evolver's slot (idle: no run
     * is going on) */
    if (tool_robot_palette(a, &d, err, errsz) < 0) return AM_ERR_RANGE;
    am_evo_palette_into(&d, &c->evo.palette);
    st = am_evo_lattice(&d, &c->evo.palette, tool_genome(c), &c->work[0].geno, r->lattice, msg, sizeof msg);
    if (st != AM_OK) return am_fail(err, errsz, st, "%s: %s", path, msg);
    am_express_def ex = am_evo_express_def(&d, &c->evo.palette);
    if ((st = tool_robot_stiffness_range(a, &ex, err, errsz)) != AM_OK) return st;
    if ((st = tool_robot_genome_layers(c, &ex, r, path, &g_use, err, errsz)) != AM_OK) return st;
    r->env = d.env;
    r->eval = d.eval;
    return AM_OK;
}

static am_status lattice_line(void* ctx, int lineno, char* line, long n, char* err, int errsz)
{
    (void)lineno;
    return am_lattice_read_line((am_lattice_reader*)ctx, line, n, err, errsz);
}

/* a file in any format amorph reads: lattice text, genome text (expressed), VXA (desktop) */
static am_status load_file(tool_ctx* c, const tool_robot_args* a, const char* name, const char* vxd, am_robot* r, const am_vxa_info** vxa,
                           char* err, int errsz)
{
    tool_src src;
    am_status st = tool_src_open(&src, name, TOOL_FILE_MAX, 0, err, errsz);
    if (st != AM_OK) return src.binary ? tool_src_binary(&src, err, errsz) : st;
    int kind = tool_src_sniff(&src, err, errsz);
    if (kind < 0) {
        st = src.binary ? tool_src_binary(&src, err, errsz) : AM_ERR_PARSE;
    } else if (kind == TOOL_TEXT_VXA) {
#if TOOL_VXA
        st = load_vxa(tool_src_text(&src), name, vxd, r, vxa, err, errsz);
#else
        (void)vxa;
        st = am_fail(err, errsz, AM_ERR_ARG, "%s: a VXA file: not in this build: VXA files belong to the desktop profile", name);
#endif
    } else if (vxd) {
        st = am_fail(err, errsz, AM_ERR_PARSE, "%s: not a VXA file: a VXD file (%s) goes over a base VXA file", name, vxd);
    } else if (kind == TOOL_TEXT_GENOME) {
        /* its materials from the built-in palette, or the one the settings' palette keys give (in
         * the evolver's slot, idle) */
        am_evo_def d = am_default_evo();
        const int own = tool_robot_palette(a, &d, err, errsz);
        if (own > 0) am_evo_palette_into(&d, &c->evo.palette);
        st = own < 0 ? AM_ERR_RANGE : tool_genome_to_lattice(c, &src, r->lattice, own ? &c->evo.palette : NULL, err, errsz);
        am_express_def ex = am_default_express();
        if (st == AM_OK) st = tool_robot_stiffness_range(a, &ex, err, errsz);
        if (st == AM_OK) st = tool_robot_genome_layers(c, &ex, r, name, &g_use, err, errsz);
    } else {
        am_lattice_reader lr;
        am_lattice_read_begin(&lr, r->lattice, name);
        st = tool_src_each(&src, lattice_line, &lr, err, errsz);
        if (st == AM_OK) st = am_lattice_read_end(&lr, err, errsz);
    }
    tool_src_close(&src);
    return st;
}

/* the settings of a over r, in order; *period_set becomes 1 when one gave period_steps */
static am_status apply_settings(const tool_robot_args* a, am_robot* r, int* period_set, unsigned* keep, char* err, int errsz)
{
    am_lattice* lat = r->lattice;
    am_evo_def d = am_default_evo();
    d.env = r->env;
    d.eval = r->eval;
    for (int k = 0; k < a->nset; k++) {
        unsigned material = 0;
        am_status st = am_evo_set_over(&d, a->key[k], a->val[k], &material, err, errsz);
        if (st != AM_OK) return st;
        if (!strcmp(a->key[k], "period_steps")) *period_set = 1;
        if (!strcmp(a->key[k], "cycles")) *keep |= AM_VXA_KEEP_CYCLES;
        if (!strncmp(a->key[k], "relax_m", 7)) *keep |= AM_VXA_KEEP_RELAX;
        const int slot = origin_slot(key_index(a->key[k]));
        if (slot >= 0) g_origin.flag[slot] = 1;
        /* a period in steps replaces one in seconds */
        const int other = origin_slot(key_index("period_s"));
        if (!strcmp(a->key[k], "period_steps") && other >= 0) g_origin.flag[other] = 0, g_origin.line[other] = 0;
        am_evo_apply_materials(&d, material, lat); /* in order: a later --cte sees the earlier one's materials */
    }
    r->env = d.env;
    r->eval = d.eval;
    return AM_OK;
}

am_status tool_robot_dt(tool_ctx* c, const am_robot* r, double* dt, char* err, int errsz)
{
    am_lattice* lat = r->lattice;
    const am_env* env = &r->env;
    /* dt_rec depends on the materials and the voxel size only: an empty robot is timed as one
     * voxel of its first material, set for the build and cleared again */
    const int empty = am_lattice_count(lat) == 0 && lat->palette.count > 0;
    if (empty) lat->cell[0] = 1;
    /* with the robot's layers: a stiffness per voxel sets dt_rec (none for the stand-in voxel) */
    am_status st = empty ? am_model_build(&c->work[0].model, lat, env, err, errsz) : am_robot_build(&c->work[0].model, r, err, errsz);
    if (empty) lat->cell[0] = 0;
    if (st != AM_OK) return st;
    *dt = am_dt_si(&c->work[0].model, env->dt_frac);
    return AM_OK;
}

#if TOOL_VXA
/* a voxcraft folder (voxcraft-sim's layout: a base VXA and the robots' VXD files): 1 with its VXA
 * (base.vxa, else the folder's one .vxa) in base and its one .vxd in robot; 0 when dir is no folder
 * or holds no .vxa; -1 after a message in err (which VXA or which VXD is not clear) */
static int voxcraft_dir(const char* dir, char base[TOOL_PATH_MAX], char robot[TOOL_PATH_MAX], char* err, int errsz)
{
    static char names[16384];
    int count = 0;
    char e2[AM_ERR_MAX];
    if (am_port_list_dir(dir, names, (long)sizeof names, &count, e2, sizeof e2) != AM_OK) return 0;
    size_t n = strlen(dir);
    const char* sep = n && dir[n - 1] == '/' ? "" : "/";
    const char *vxa = NULL, *vxd = NULL, *vxd2 = NULL;
    int nvxa = 0, nvxd = 0, has_base = 0;
    for (const char* p = names; count-- > 0; p += strlen(p) + 1) {
        if (strlen(p) > 4 && tool_ends_with(p, ".vxa")) {
            nvxa++;
            vxa = p;
            if (!strcmp(p, "base.vxa")) has_base = 1;
        } else if (strlen(p) > 4 && tool_ends_with(p, ".vxd")) {
            nvxd++;
            if (!vxd || strcmp(p, vxd) < 0) vxd2 = vxd, vxd = p;
            else if (!vxd2 || strcmp(p, vxd2) < 0) vxd2 = p;
        }
    }
    if (nvxa == 0) return 0;
    if (nvxa > 1 && !has_base) {
        am_fail(err, errsz, AM_ERR_ARG, "%s: a voxcraft folder holds base.vxa and VXD files; this one has %d VXA files and no base.vxa: "
                                        "name the files (amorph sim BASE.vxa ROBOT.vxd)", dir, nvxa);
        return -1;
    }
    if (nvxd != 1) {
        if (nvxd == 0)
            am_fail(err, errsz, AM_ERR_ARG, "%s: a voxcraft folder holds a base VXA and a robot's VXD; no .vxd in it (a VXA alone: amorph "
                                            "sim %s%s%s)", dir, dir, sep, has_base ? "base.vxa" : vxa);
        else
            am_fail(err, errsz, AM_ERR_ARG, "%s: %d VXD files (%s, %s%s): name one (amorph sim %s%s%s %s%s%s)", dir, nvxd, vxd, vxd2,
                    nvxd > 2 ? ", ..." : "", dir, sep, has_base ? "base.vxa" : vxa, dir, sep, vxd);
        return -1;
    }
    if (snprintf(base, TOOL_PATH_MAX, "%s%s%s", dir, sep, has_base ? "base.vxa" : vxa) >= TOOL_PATH_MAX) return 0;
    if (snprintf(robot, TOOL_PATH_MAX, "%s%s%s", dir, sep, vxd) >= TOOL_PATH_MAX) return 0;
    return 1;
}
#endif

const char* tool_robot_name(const tool_robot_args* a, char* buf, int cap)
{
    if (a->vxd) return a->vxd;
    if (a->genome) return a->genome;
#if TOOL_VXA
    char base[TOOL_PATH_MAX], err[AM_ERR_MAX];
    if (!a->is_scene && !tool_is_run_dir(a->name) && voxcraft_dir(a->name, base, buf, err, (int)sizeof err) == 1 && cap >= TOOL_PATH_MAX)
        return buf;
#endif
    (void)buf, (void)cap;
    return a->name;
}

int tool_settings_apart(const am_evo_def* from, const am_evo_def* to, unsigned materials, char* out, int cap)
{
    static const char* const mat_key[4] = {"cte", "mu_static", "mu_kinetic", "voxel_size"}; /* AM_MATERIAL_* bits 0..3 */
    int n = 0;
    size_t len = 0;
    out[0] = 0;
    for (int i = 0; i < am_evo_key_count(); i++) {
        const char* key = am_evo_key_name(i);
        const int g = am_evo_key_group(key);
        char v[64], v0[64];
        am_evo_key_value(to, i, v, sizeof v);
        if (g == AM_KEYS_ENV || g == AM_KEYS_EVAL) {
            am_evo_key_value(from, i, v0, sizeof v0);
            if (!strcmp(v, v0)) continue;
        } else {
            int named = 0;
            for (int b = 0; b < 4; b++) named |= (materials >> b & 1u) && !strcmp(key, mat_key[b]);
            named |= (materials & TOOL_APART_STIFFNESS) && (!strcmp(key, "stiffness_min") || !strcmp(key, "stiffness_max"));
            if (!named) continue;
        }
        int w = snprintf(out + len, (size_t)cap - len, "%s%s = %s", n ? ", " : "", key, v);
        if (w < 0 || len + (size_t)w + 6 >= (size_t)cap) {
            if (len + 6 < (size_t)cap) strcpy(out + len, ", ...");
            return n + 1;
        }
        len += (size_t)w;
        n++;
    }
    return n;
}

/* a robot file (a lattice or a genome) that sits in a run folder carries none of the run's
 * environment and evaluation, and a genome none of its materials: when the run's differ from the
 * robot's, one note on stderr names them and the command that evaluates the run's best robot in the
 * run's settings */
static void run_note(tool_ctx* c, const char* name, const am_robot* r)
{
    /* one path buffer (the board's stack is small): the folder, then its config.txt */
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX], apart[256];
    const char* slash = strrchr(name, '/');
    const int dlen = slash ? (int)(slash - name) : 1;
    const size_t cl = strlen("/" AM_RUN_CONFIG);
    if (dlen < 1 || (size_t)dlen + cl >= sizeof path) return;
    memcpy(path, slash ? name : ".", (size_t)dlen);
    path[dlen] = 0;
    if (!tool_is_run_dir(path)) return;
    memcpy(path + dlen, "/" AM_RUN_CONFIG, cl + 1);
    am_evo_def d = am_stored_evo(), h = am_default_evo();
    if (tool_read_config(path, &d, 1, err, sizeof err) != AM_OK) return;
    path[dlen] = 0; /* the folder again, for the note */
    h.env = r->env;
    h.eval = r->eval;
    /* the run's materials against the robot's, by name: the keys that set them (the run's palette
     * in the evolver's slot, idle: no run is going on) */
    am_palette* pal = &c->evo.palette;
    am_evo_palette_into(&d, pal);
    const am_palette* own = &r->lattice->palette;
    unsigned mat = r->lattice->voxel_size != d.voxel_size ? AM_MATERIAL_VOXEL_SIZE : 0u;
    for (int k = 0; k < own->count; k++) {
        const int j = am_palette_find(pal, own->mat[k].name);
        if (j < 0) continue;
        if (pal->mat[j].mu_static != own->mat[k].mu_static) mat |= AM_MATERIAL_MU_STATIC;
        if (pal->mat[j].mu_kinetic != own->mat[k].mu_kinetic) mat |= AM_MATERIAL_MU_KINETIC;
        if (pal->mat[j].cte != own->mat[k].cte) mat |= AM_MATERIAL_CTE;
    }
    /* a genome's evolved stiffness field in the run's range, as the run expressed it */
    if (g_use.evolved_stiffness && d.stiffness == AM_STIFFNESS_EVOLVED &&
        (d.stiffness_min != g_use.range.stiffness_min || d.stiffness_max != g_use.range.stiffness_max))
        mat |= TOOL_APART_STIFFNESS;
    const int n = tool_settings_apart(&h, &d, mat, apart, (int)sizeof apart);
    if (n > 0 && g_use.genome)
        fprintf(stderr, "amorph: note: %s is in the run folder %s, whose settings differ from these: the run had %s "
                        "(amorph sim %s --genome %s evaluates this genome as the run did)\n", name, path, apart, path, name);
    else if (n > 0)
        fprintf(stderr, "amorph: note: %s is in the run folder %s, whose settings differ from these: the run had %s "
                        "(amorph sim %s evaluates the run's best robot as the run did)\n", name, path, apart, path);
}

/* 1 when path is a folder (one the port can list: a listing longer than the few bytes given is a
 * folder too, so no room for a whole listing is kept; the board's RAM has none to spare) */
static int is_folder(const char* path)
{
    char names[64];
    int count = 0;
    char e2[AM_ERR_MAX];
    const am_status st = am_port_list_dir(path, names, (long)sizeof names, &count, e2, sizeof e2);
    return st == AM_OK || st == AM_ERR_CAPACITY;
}

/* 1 when dir holds a run's config.txt (a run folder, with or without its best.genome yet) */
static int run_config(const char* dir)
{
    char p[TOOL_PATH_MAX];
    return snprintf(p, sizeof p, "%s/" AM_RUN_CONFIG, dir) < (int)sizeof p && am_port_exists(p);
}

/* a folder named as the robot that is neither a run folder nor a voxcraft folder: what it is
 * (which of a run folder's files it lacks) and what the commands take */
static am_status not_a_robot_folder(const char* dir, char* err, int errsz)
{
    const int config = run_config(dir);
    return am_fail(err, errsz, AM_ERR_ARG, "%s: a folder, neither a run folder (config.txt, best.genome: %s) nor a voxcraft folder "
                                           "(a .vxa, a .vxd: %s); a robot is a lattice, genome or VXA file, a run or voxcraft folder, or "
                                           "--scene NAME", dir, config ? "no best.genome yet" : "neither", TOOL_VXA ? "no .vxa" : "not in this build");
}

/* the evaluation's budget (am_evo_check_budget) with the robot's settings as they stand, the period
 * in steps of its step; the message names where the setting it blames was given */
static am_status check_budget(const am_robot* r, char* err, int errsz)
{
    am_evo_def d = am_default_evo();
    d.env = r->env;
    d.eval = r->eval;
    char why[AM_ERR_MAX], at[TOOL_PATH_MAX + 32];
    int key;
    if (am_evo_check_budget(&d, (double)r->env.period_steps, &key, why, sizeof why) == AM_OK) return AM_OK;
    origin_of(key, at, (int)sizeof at);
    if (at[0] == '-') return am_fail(err, errsz, AM_ERR_RANGE, "--%s", why); /* "--KEY = VALUE: ..." */
    return am_fail(err, errsz, AM_ERR_RANGE, "%s%s%s", at, at[0] ? ": " : "", why);
}

am_status tool_robot_load(tool_ctx* c, const tool_robot_args* a, am_lattice* lat, am_robot* r, char* err, int errsz)
{
    /* no layers unless a VXA file brings them (the board reads no VXA file and keeps no room) */
#if TOOL_VXA
    am_robot_init(r, lat, &c->robot_layers);
#else
    am_robot_init(r, lat, NULL);
#endif
    am_status st;
    int one_file = 0; /* a robot file named alone (not a scene, a run folder or a VXD over a VXA) */
    const am_vxa_info* vxa = NULL; /* a VXA file's run length (its StopCondition), while this call runs */
#if TOOL_VXA
    static char base[TOOL_PATH_MAX], robot[TOOL_PATH_MAX]; /* a voxcraft folder's files, during this call */
#endif
    memset(&g_origin, 0, sizeof g_origin);
    memset(&g_use, 0, sizeof g_use);
    if (a->genome && (a->is_scene || a->vxd || !run_config(a->name)))
        return am_fail(err, errsz, AM_ERR_ARG, "--genome %s: a genome is evaluated in a run folder's settings (its config.txt); %s is %s",
                       a->genome, a->name, a->is_scene ? "a scene" : a->vxd ? "a VXA file" : "not a run folder");
    if (a->is_scene) st = am_scene_build(lat, a->name, err, errsz);
    else if (a->genome || tool_is_run_dir(a->name)) st = load_run(c, a, a->name, r, err, errsz);
#if TOOL_VXA
    else if (!a->vxd && (st = (am_status)voxcraft_dir(a->name, base, robot, err, errsz)) != 0) {
        if ((int)st < 0) return AM_ERR_ARG;
        st = load_file(c, a, base, robot, r, &vxa, err, errsz);
    }
#endif
    else if (!a->vxd && is_folder(a->name)) return not_a_robot_folder(a->name, err, errsz);
    else {
        st = load_file(c, a, a->name, a->vxd, r, &vxa, err, errsz);
        one_file = !a->vxd;
    }
    if (st != AM_OK) return st;
    /* a palette is what a genome's material names are looked up in: a lattice, a VXA file and a
     * scene carry their materials */
    for (int k = 0; k < a->nset && !g_use.genome; k++)
        if (tool_robot_palette_key(a->key[k]))
            return am_fail(err, errsz, AM_ERR_ARG, "--%s: %s carries its own materials (the palette keys apply to a genome's names: a "
                                                   "genome file or a run folder)", a->key[k], a->name);
    /* a stiffness range is what an evolved stiffness field maps to: a robot without one has none */
    for (int k = 0; k < a->nset && !g_use.evolved_stiffness; k++)
        if (!strcmp(a->key[k], "stiffness_min") || !strcmp(a->key[k], "stiffness_max"))
            return am_fail(err, errsz, AM_ERR_ARG, "--%s: %s has no evolved stiffness (the range applies to a genome's or a run's with "
                                                   "stiffness = evolved)", a->key[k], a->name);
    const am_env own = r->env; /* the robot's own, before the settings */
    int period_set = 0;
    unsigned keep = 0;
    st = apply_settings(a, r, &period_set, &keep, err, errsz);
    if (st != AM_OK) return st;
    r->eval.record = NULL;
    if (one_file) run_note(c, a->name, r);
    const int dt_changed = a->dt_s > 0 || r->env.dt_frac != own.dt_frac;
    const int run_length = vxa && (vxa->stop_type >= 0 || vxa->init_cm_time > 0);
    if (!dt_changed && !(r->env.period_s > AM_P(0)) && !run_length) return check_budget(r, err, errsz);
    double dt;
    /* the step alone (a period in seconds is checked below, where it can be named) */
    am_robot stepped = *r;
    stepped.env.period_s = AM_P(0);
    st = tool_robot_dt(c, &stepped, &dt, err, errsz);
    if (st != AM_OK) return st;
    /* dt_rec, of the model just built, does not depend on dt_frac */
    const am_model* m = &c->work[0].model;
    const double dt_rec = am_to_si(m, m->dt_rec, AM_DIM_TIME);
    if (a->dt_s > 0) {
        /* dt_frac's range, however the step is given */
        const double f = a->dt_s / dt_rec;
        if (!(f >= 1e-6 && f <= 10))
            return am_fail(err, errsz, AM_ERR_RANGE, "--dt %g: is %.3g of this robot's dt_rec (%.4g s), outside dt_frac's range [1e-06, 10]",
                           a->dt_s, f, dt_rec);
        r->env.dt_frac = AM_PARAM_FROM_DOUBLE(f);
        dt = am_dt_si(m, r->env.dt_frac);
    }
    /* a period in seconds becomes steps of this step (as am_model_build makes it), so that what the
     * commands count in steps (frames, trajectory rows) follows it */
    if (r->env.period_s > AM_P(0)) {
        const double k = (double)r->env.period_s / dt;
        if (!(k >= 1.5 && k <= 1e7)) {
            /* named where the period was given, or the step where the period is in range at the
             * default step (the step made it too many or too few steps) */
            char at[TOOL_PATH_MAX + 32];
            const double k_ref = (double)r->env.period_s / (dt_rec * AM_REF_DT_FRAC);
            if (k_ref >= 1.5 && k_ref <= 1e7) {
                if (a->dt_s > 0) snprintf(at, sizeof at, "--dt");
                else origin_of(key_index("dt_frac"), at, (int)sizeof at);
            } else {
                origin_of(key_index("period_s"), at, (int)sizeof at);
            }
            /* "--period_s = ...", "--dt: period_s = ...", "FILE:LINE: period_s = ..." */
            const int flag = !strcmp(at, "--period_s");
            return am_fail(err, errsz, AM_ERR_RANGE, "%s%speriod_s = %g s is %.3g steps of %.4g s (a period takes 2 to 10^7 steps)",
                           flag ? "--" : at, flag ? "" : at[0] ? ": " : "", (double)r->env.period_s, k, dt);
        }
        r->env.period_steps = am_period_steps(m, &r->env, am_from_si(m, dt, AM_DIM_TIME));
    }
#if TOOL_VXA
    char note[640] = "";
    if (run_length && !r->eval.dt_search) {
        /* the file's run length (VoxCAD's StopCondition, evosoro's InitCmTime) as the evaluation's
         * cycles and least relaxation, unless a flag set them; one note line says so */
        st = am_vxa_stop_settings(vxa, dt, AM_REF_DT_FRAC * dt_rec, r->env.period_steps, keep, &r->eval, note, (int)sizeof note, err, errsz);
        if (st != AM_OK) return st;
    }
#endif
    /* the budget with the run length as it now is, before any note: a refusal is one line */
    if ((st = check_budget(r, err, errsz)) != AM_OK) return st;
#if TOOL_VXA
    if (note[0]) fprintf(stderr, "%s: note: the file's run length as amorph's evaluation: %s\n", vxa->stop_file, note);
#endif
    /* a step of another length with the period held in steps changes the experiment: say so */
    const double own_s = own.period_s > AM_P(0) ? (double)own.period_s : own.period_steps * (double)own.dt_frac * dt_rec;
    const double now_s = r->env.period_steps * dt;
    if (dt_changed && !(fabs(now_s - own_s) <= 0.01 * own_s))
        fprintf(stderr, "amorph: note: at this step the actuation period is %d steps = %.4g s, not the robot's own %.4g s "
                        "(--period_s %.4g holds it in seconds)\n", r->env.period_steps, now_s, own_s, own_s);
    return AM_OK;
}
