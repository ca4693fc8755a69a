/* The evolver's configuration: defaults, one table of `key = value` settings shared by config
 * files and command-line flags, the text format, and the comparison used by --resume. */
#include "amorph/evo.h"

#include <stddef.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

am_evo_def am_default_evo(void)
{
    am_evo_def d;
    memset(&d, 0, sizeof d);
    d.geno = am_default_geno();
    d.geno.repr = AM_REPR_GMX;
    d.geno.materials = 2;
    d.env = am_default_env();
    d.eval = am_default_eval();
    d.eval.record = NULL;
    d.cte = AM_P(0.01);
    d.mu_static = AM_P(1.0);
    d.mu_kinetic = AM_P(0.3);
    d.voxel_size = AM_P(0.01);
    d.actuation = AM_ACTUATION_GLOBAL;
    d.stiffness = AM_STIFFNESS_MATERIAL;
    d.stiffness_min = AM_P(1e5);
    d.stiffness_max = AM_P(1e7);
    d.population = 20;
    d.evaluations = 200;
    d.seed = 1;
    d.threads = 0;
    d.checkpoint_seconds = 0;
    return d;
}

am_evo_def am_stored_evo(void)
{
    am_evo_def d = am_default_evo();
    d.eval.relax_dt_frac = AM_P(0); /* runs made before the settling pseudo-step */
    return d;
}

am_palette am_evo_palette(const am_evo_def* d)
{
    am_palette p;
    am_evo_palette_into(d, &p);
    return p;
}

/* ---- palettes ---- */

static const char* const palette_names[] = {"seed", "unshackled", NULL};
static const int preset_size[] = {3, 4};   /* materials of each preset */
static const int preset_fields[] = {2, 4}; /* the materials key each preset sets */
#define PI_D 3.14159265358979323846

/* entry i of a preset, with the run's cte over its actuated materials and its friction */
static am_material preset_material(const am_evo_def* d, int i)
{
    am_material m = am_default_material();
    memset(m.name, 0, sizeof m.name);
    if (d->palette == AM_PALETTE_SEED) {
        /* the built-in palette's first three (am_default_palette): passive, active, active90 */
        static const char* const name[3] = {"passive", "active", "active90"};
        static const uint8_t rgb[3][3] = {{40, 90, 220}, {240, 200, 30}, {220, 40, 40}};
        snprintf(m.name, sizeof m.name, "%s", name[i]);
        m.cte = i > 0 ? AM_P(0.01) : AM_P(0);
        m.phase = i == 2 ? -(AM_P(PI_D) / AM_P(2)) : AM_P(0);
        for (int c = 0; c < 3; c++) m.color[c] = rgb[i][c];
    } else {
        /* Cheney et al. 2013 as evosoro writes them (evosoro/tools/read_write_voxelyze.py, with
         * evosoro/base.py's Env defaults): 5 MPa soft tissue and muscle, 500 MPa hard tissue,
         * density 1e6, Poisson's ratio 0.35, muscles of CTE +-0.01; active_minus here has the CTE of
         * active_plus half a period later, the same expansion about temp_base 0 */
        static const char* const name[4] = {"passive_soft", "passive_hard", "active_plus", "active_minus"};
        static const uint8_t rgb[4][3] = {{0, 255, 255}, {0, 0, 255}, {255, 0, 0}, {0, 255, 0}};
        snprintf(m.name, sizeof m.name, "%s", name[i]);
        m.E = i == 1 ? AM_P(5e8) : AM_P(5e6);
        m.density = AM_P(1e6);
        m.poisson = AM_P(0.35);
        m.cte = i >= 2 ? AM_P(0.01) : AM_P(0);
        m.phase = i == 3 ? AM_P(PI_D) : AM_P(0);
        for (int c = 0; c < 3; c++) m.color[c] = rgb[i][c];
    }
    if (m.cte != AM_P(0)) m.cte = d->cte;
    m.mu_static = d->mu_static;
    m.mu_kinetic = d->mu_kinetic;
    return m;
}

/* a materialK key's material as the palette holds it */
static am_material given_material(const am_evo_def* d, int k)
{
    /* by index: the built-in palette's colours, then more */
    static const uint8_t rgb[8][3] = {{40, 90, 220}, {240, 200, 30}, {220, 40, 40},   {140, 140, 150},
                                      {60, 190, 90}, {110, 70, 40},  {200, 120, 230}, {240, 130, 20}};
    const am_evo_material* g = &d->material[k];
    am_material m = am_default_material();
    memset(m.name, 0, sizeof m.name);
    snprintf(m.name, sizeof m.name, "%s", g->name);
    m.E = g->E;
    m.density = g->density;
    m.cte = g->cte;
    m.phase = AM_PARAM_FROM_DOUBLE(AM_PARAM_TO_DOUBLE(g->phase) * (PI_D / 180.0));
    m.poisson = g->given & AM_EVO_MAT_POISSON ? g->poisson : AM_P(0);
    m.mu_static = g->given & AM_EVO_MAT_MU_STATIC ? g->mu_static : d->mu_static;
    m.mu_kinetic = g->given & AM_EVO_MAT_MU_KINETIC ? g->mu_kinetic : d->mu_kinetic;
    for (int c = 0; c < 3; c++) m.color[c] = g->given & AM_EVO_MAT_COLOR ? g->color[c] : rgb[k % 8][c];
    return m;
}

int am_evo_palette_size(const am_evo_def* d)
{
    int n = d->palette == AM_PALETTE_UNSHACKLED ? preset_size[1] : preset_size[0];
    for (int k = 0; k < AM_MAX_GENO_MATERIALS; k++)
        if (d->material[k].name[0] && k + 1 > n) n = k + 1;
    return n;
}

static int any_given(const am_evo_def* d)
{
    for (int k = 0; k < AM_MAX_GENO_MATERIALS; k++)
        if (d->material[k].name[0]) return 1;
    return 0;
}

void am_evo_palette_into(const am_evo_def* d, am_palette* p)
{
    if (d->palette == AM_PALETTE_SEED && !any_given(d)) {
        /* the seed's runs: the built-in palette, as every run before palettes had it */
        am_default_palette_into(p);
        for (int i = 0; i < p->count; i++) {
            /* the actuated materials (non-zero CTE in the default palette) share the run's CTE */
            if (p->mat[i].cte != AM_P(0)) p->mat[i].cte = d->cte;
            p->mat[i].mu_static = d->mu_static;
            p->mat[i].mu_kinetic = d->mu_kinetic;
        }
        return;
    }
    memset(p, 0, sizeof *p);
    const int preset = d->palette == AM_PALETTE_UNSHACKLED ? preset_size[1] : preset_size[0];
    const int n = am_evo_palette_size(d);
    p->count = n;
    for (int k = 0; k < n; k++)
        p->mat[k] = d->material[k].name[0] ? given_material(d, k) : k < preset ? preset_material(d, k) : am_default_material();
}

/* the genotype's names: the palette's (am_genome_init names the genomes' fields with them) */
static void palette_names_sync(am_evo_def* d)
{
    const int preset = d->palette == AM_PALETTE_UNSHACKLED ? preset_size[1] : preset_size[0];
    memset(d->geno.mat, 0, sizeof d->geno.mat);
    for (int k = 0; k < AM_MAX_GENO_MATERIALS; k++) {
        const am_material pm = k < preset ? preset_material(d, k) : am_default_material();
        if (d->material[k].name[0]) snprintf(d->geno.mat[k], AM_NAME_MAX, "%s", d->material[k].name);
        else if (k < preset) snprintf(d->geno.mat[k], AM_NAME_MAX, "%s", pm.name);
    }
}

/* a name as the genome format takes it: letters, digits, '_' and '-' */
static int material_name_ok(const char* s, size_t n)
{
    if (n == 0 || n >= AM_NAME_MAX) return 0;
    for (size_t i = 0; i < n; i++) {
        char c = s[i];
        if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-')) return 0;
    }
    return 1;
}

/* a materialK value: NAME field=value ...; the message without the key */
static am_status parse_material(const char* value, am_evo_material* out, char* err, int errsz)
{
    static const struct {
        const char* name;
        double lo, hi;
        int open_lo; /* 1: lo itself is out of range */
        int need;    /* 1: required */
        uint8_t bit; /* AM_EVO_MAT_* of an optional field */
    } field[] = {
        {"modulus", 0, 1e12, 1, 1, 0},   {"density", 0, 1e9, 1, 1, 0},       {"cte", -1, 1, 0, 1, 0},
        {"phase", -360, 360, 0, 1, 0},   {"poisson", 0, 0.4999, 0, 0, AM_EVO_MAT_POISSON},
        {"mu_static", 0, 100, 0, 0, AM_EVO_MAT_MU_STATIC}, {"mu_kinetic", 0, 100, 0, 0, AM_EVO_MAT_MU_KINETIC},
        {"color", 0, 0, 0, 0, AM_EVO_MAT_COLOR},
    };
    enum { NF = (int)(sizeof field / sizeof field[0]) };
    char qb[AM_QUOTE_BUF];
    am_evo_material m;
    memset(&m, 0, sizeof m);
    int have[NF] = {0};
    const char* s = value;
    while (*s == ' ' || *s == '\t') s++;
    size_t n = strcspn(s, " \t");
    if (!material_name_ok(s, n))
        return am_fail(err, errsz, AM_ERR_RANGE, "expected a material name first (1 to %d letters, digits, '_' or '-'), "
                       "then modulus= density= cte= phase=", AM_NAME_MAX - 1);
    memcpy(m.name, s, n);
    s += n;
    for (;;) {
        while (*s == ' ' || *s == '\t') s++;
        if (!*s) break;
        n = strcspn(s, " \t");
        const char* eq = memchr(s, '=', n);
        char word[64];
        if (!eq || n >= sizeof word)
            return am_fail(err, errsz, AM_ERR_RANGE, "'%s': expected field=value", am_quote(qb, sizeof qb, s, (long)n));
        int f = -1;
        for (int i = 0; i < NF; i++)
            if (strlen(field[i].name) == (size_t)(eq - s) && !strncmp(field[i].name, s, (size_t)(eq - s))) f = i;
        if (f < 0)
            return am_fail(err, errsz, AM_ERR_RANGE, "unknown field '%s' (modulus, density, cte, phase, poisson, mu_static, "
                           "mu_kinetic, color)", am_quote(qb, sizeof qb, s, eq - s));
        if (have[f]) return am_fail(err, errsz, AM_ERR_RANGE, "%s given twice", field[f].name);
        have[f] = 1;
        memcpy(word, eq + 1, n - (size_t)(eq - s) - 1);
        word[n - (size_t)(eq - s) - 1] = 0;
        s += n;
        if (field[f].bit == AM_EVO_MAT_COLOR) {
            char* end = NULL;
            unsigned long c = strlen(word) == 6 ? strtoul(word, &end, 16) : 0;
            if (!end || *end) return am_fail(err, errsz, AM_ERR_RANGE, "color=%s: expected RRGGBB (hexadecimal)", am_quote(qb, sizeof qb, word, -1));
            for (int i = 0; i < 3; i++) m.color[i] = (uint8_t)(c >> (16 - 8 * i));
        } else {
            double v;
            if (!am_parse_double(word, &v) || v < field[f].lo || v > field[f].hi || (field[f].open_lo && v <= field[f].lo))
                return am_fail(err, errsz, AM_ERR_RANGE, "%s=%s: expected a number in %s%g, %g]", field[f].name,
                               am_quote(qb, sizeof qb, word, -1), field[f].open_lo ? "(" : "[", field[f].lo, field[f].hi);
            am_param* dst[] = {&m.E, &m.density, &m.cte, &m.phase, &m.poisson, &m.mu_static, &m.mu_kinetic};
            *dst[f] = AM_PARAM_FROM_DOUBLE(v);
        }
        m.given |= field[f].bit;
    }
    for (int i = 0; i < NF; i++)
        if (field[i].need && !have[i])
            return am_fail(err, errsz, AM_ERR_RANGE, "missing %s= (a material needs modulus, density, cte and phase)", field[i].name);
    *out = m;
    return AM_OK;
}

/* the shortest text of v that reads back to the same am_param */
static void param_text(am_param v, char* out, int cap)
{
    for (int prec = 6; prec <= 17; prec++) {
        snprintf(out, (size_t)cap, "%.*g", prec, AM_PARAM_TO_DOUBLE(v));
        if (AM_PARAM_FROM_DOUBLE(strtod(out, NULL)) == v) break;
    }
}

static void material_text(const am_evo_material* m, char* out, int cap)
{
    if (!m->name[0]) {
        if (cap > 0) out[0] = 0;
        return;
    }
    const am_param v[] = {m->E, m->density, m->cte, m->phase, m->poisson, m->mu_static, m->mu_kinetic};
    static const char* const name[] = {"modulus", "density", "cte", "phase", "poisson", "mu_static", "mu_kinetic"};
    static const uint8_t bit[] = {0, 0, 0, 0, AM_EVO_MAT_POISSON, AM_EVO_MAT_MU_STATIC, AM_EVO_MAT_MU_KINETIC};
    int n = snprintf(out, (size_t)cap, "%s", m->name);
    for (int i = 0; i < 7 && n >= 0 && n < cap; i++) {
        if (bit[i] && !(m->given & bit[i])) continue;
        char num[32];
        param_text(v[i], num, sizeof num);
        n += snprintf(out + n, (size_t)(cap - n), " %s=%s", name[i], num);
    }
    if ((m->given & AM_EVO_MAT_COLOR) && n >= 0 && n < cap)
        snprintf(out + n, (size_t)(cap - n), " color=%02x%02x%02x", m->color[0], m->color[1], m->color[2]);
}

/* ---- the key table ---- */

typedef enum key_kind { K_INT, K_LONG, K_REAL, K_PARAM, K_U64, K_ENUM, K_ONOFF, K_WORKSPACE, K_PALETTE, K_MATERIAL } key_kind;

typedef struct key_def {
    const char* name;
    key_kind kind;
    size_t off;            /* field offset in am_evo_def */
    double lo, hi;         /* allowed range (numbers) */
    const char* const* names; /* K_ENUM: value names, index = stored value, NULL-terminated */
    int runtime;           /* 1: never changes results (left out of run comparisons) */
    const char* help;
} key_def;

static const char* const repr_names[] = {"none", "dct", "cppn", "gmx", NULL};
static const char* const fit_names[] = {"horizontal", "x", "3d", NULL};
static const char* const cte_names[] = {"volumetric", "linear", NULL};
static const char* const score_names[] = {"travel", "sustained", NULL};
static const char* const actuation_names[] = {"global", "phase", NULL};
static const char* const stiffness_names[] = {"material", "evolved", NULL};

#define OFF(f) offsetof(am_evo_def, f)
#define MATERIAL_KEY(k, help) {"material" #k, K_MATERIAL, OFF(material[k - 1]), k, k, NULL, 0, help}
_Static_assert(AM_MAX_GENO_MATERIALS >= 3 && AM_MAX_GENO_MATERIALS <= 8, "one materialK key per palette entry: the table below");
static const key_def keys[] = {
    {"representation", K_ENUM, OFF(geno.repr), 1, 3, repr_names, 0, "genotype: dct, cppn or gmx"},
    {"palette", K_PALETTE, OFF(palette), 0, 1, palette_names, 0,
     "materials to build with: seed (passive, active, active90) or unshackled (passive_soft, passive_hard, active_plus, "
     "active_minus); sets materials (seed 2, unshackled 4)"},
    MATERIAL_KEY(1, "palette material 1 in place of the preset's: NAME modulus=Pa density=kg/m^3 cte=1/degree phase=degrees "
                    "[poisson= mu_static= mu_kinetic= color=RRGGBB]; raises materials to 1"),
    MATERIAL_KEY(2, "palette material 2 (as material1)"),
    MATERIAL_KEY(3, "palette material 3 (as material1)"),
#if AM_MAX_GENO_MATERIALS >= 4
    MATERIAL_KEY(4, "palette material 4 (as material1)"),
#endif
#if AM_MAX_GENO_MATERIALS >= 5
    MATERIAL_KEY(5, "palette material 5 (as material1)"),
#endif
#if AM_MAX_GENO_MATERIALS >= 6
    MATERIAL_KEY(6, "palette material 6 (as material1)"),
#endif
#if AM_MAX_GENO_MATERIALS >= 7
    MATERIAL_KEY(7, "palette material 7 (as material1)"),
#endif
#if AM_MAX_GENO_MATERIALS >= 8
    MATERIAL_KEY(8, "palette material 8 (as material1)"),
#endif
    {"materials", K_INT, OFF(geno.materials), 1, AM_MAX_GENO_MATERIALS, NULL, 0,
     "materials of the genomes: the palette's first N (seed: 1 passive, 2 + active, 3 + active90)"},
    {"actuation", K_ENUM, OFF(actuation), 0, 1, actuation_names, 0,
     "global (each material's sinusoid) or phase (the genomes also evolve each voxel's phase)"},
    {"stiffness", K_ENUM, OFF(stiffness), 0, 1, stiffness_names, 0,
     "material (each material's modulus) or evolved (the genomes evolve each voxel's, in stiffness_min..stiffness_max)"},
    {"stiffness_min", K_PARAM, OFF(stiffness_min), 1, 1e12, NULL, 0, "Pa: the lowest evolved modulus (stiffness = evolved)"},
    {"stiffness_max", K_PARAM, OFF(stiffness_max), 1, 1e12, NULL, 0, "Pa: the highest, at most 100 x stiffness_min"},
    {"workspace", K_WORKSPACE, OFF(geno.nx), 1, AM_MAX_DIM, NULL, 0, "workspace cells: N or NxMxK"},
    {"population", K_INT, OFF(population), 2, AM_MAX_POPULATION, NULL, 0, "individuals (even)"},
    {"evaluations", K_LONG, OFF(evaluations), 2, 1e9, NULL, 0, "the run stops after this many evaluations"},
    {"seed", K_U64, OFF(seed), 0, 0, NULL, 0, "seed of the random stream"},
    {"threads", K_INT, OFF(threads), 0, AM_MAX_WORKERS, NULL, 1, "evaluation workers; 0: every core"},
    {"cycles", K_INT, OFF(eval.cycles), 0, 100000, NULL, 0, "actuation cycles of the movement segment (0: relaxation only)"},
    {"period_steps", K_INT, OFF(env.period_steps), 2, 1e7, NULL, 0, "actuation period, time steps"},
    {"period_s", K_PARAM, OFF(env.period_s), 0, 1e4, NULL, 0,
     "actuation period in seconds, held when the step changes (0: period_steps; > 0 overrides it)"},
    {"amplitude", K_PARAM, OFF(env.temp_amplitude), 0, 1e4, NULL, 0, "temperature amplitude, degrees"},
    {"temp_base", K_PARAM, OFF(env.temp_base), -1e4, 1e4, NULL, 0, "temperature offset, degrees"},
    {"cte", K_PARAM, OFF(cte), -1, 1, NULL, 0, "thermal expansion of the actuated materials, per degree"},
    {"cte_mode", K_ENUM, OFF(env.cte_mode), 0, 1, cte_names, 0, "volumetric (seed) or linear (VXA)"},
    {"mu_static", K_PARAM, OFF(mu_static), 0, 100, NULL, 0, "static floor friction"},
    {"mu_kinetic", K_PARAM, OFF(mu_kinetic), 0, 100, NULL, 0, "kinetic floor friction"},
    {"fitness", K_ENUM, OFF(eval.fitness), 0, 2, fit_names, 0, "centre of mass displacement: horizontal, x or 3d"},
    {"score", K_ENUM, OFF(eval.score), 0, 1, score_names, 0,
     "travel (the seed's: the whole movement's) or sustained (travel per cycle after sustained_from cycles)"},
    {"sustained_from", K_INT, OFF(eval.sustained_from), 0, 100000, NULL, 0,
     "cycles before the sustained score's window (10: cycles 11 on)"},
    {"collisions", K_ONOFF, OFF(env.collisions), 0, 1, NULL, 0, "self-collision: on or off"},
    {"floor", K_ONOFF, OFF(env.floor), 0, 1, NULL, 0, "the floor: on or off"},
    {"gravity", K_PARAM, OFF(env.gravity), 0, 1000, NULL, 0, "m/s^2"},
    {"dt_frac", K_PARAM, OFF(env.dt_frac), 1e-6, 10, NULL, 0, "time step, fraction of the analytic limit"},
    {"dt_search", K_ONOFF, OFF(eval.dt_search), 0, 1, NULL, 0, "the seed's empirical time step search"},
    {"damping_internal", K_PARAM, OFF(env.zeta_internal_scale), 0, 1000, NULL, 0, "scale of the internal damping"},
    {"damping_global", K_PARAM, OFF(env.zeta_global_scale), 0, 1000, NULL, 0, "scale of the global damping"},
    {"relax_min_steps", K_LONG, OFF(eval.relax_min_steps), 0, 1e8, NULL, 0,
     "relaxation lasts at least this (steps of the default step, 0.9 dt_rec: scaled to the step)"},
    {"relax_max_steps", K_LONG, OFF(eval.relax_max_steps), 0, 1e8, NULL, 0, "and at most this (likewise); no score if not settled"},
    {"settle_speed", K_PARAM, OFF(eval.settle_speed), 0, 100, NULL, 0, "m/s: relaxed below this RMS speed"},
    {"relax_dt_frac", K_PARAM, OFF(eval.relax_dt_frac), 0, 10, NULL, 0,
     "settling's pseudo-step, fraction of dt_rec (0: the run's step); redone at the run's step if it fails"},
    {"release_steps", K_LONG, OFF(eval.release_steps), 0, 1e8, NULL, 0,
     "settled: calm through this many last relaxation steps (likewise), model damping alone"},
    {"voxel_size", K_PARAM, OFF(voxel_size), AM_VOXEL_SIZE_MIN, AM_VOXEL_SIZE_MAX, NULL, 0, "cell edge, m"},
    {"dct_k", K_INT, OFF(geno.dct_k), 1, AM_MAX_DCT_K, NULL, 0, "DCT amplitudes per axis"},
    {"cppn_layers", K_INT, OFF(geno.cppn_layers), 1, AM_MAX_CPPN_LAYERS, NULL, 0, "CPPN layers"},
    {"cppn_nodes", K_INT, OFF(geno.cppn_nodes), 1, AM_MAX_CPPN_NODES, NULL, 0, "CPPN nodes per layer"},
    {"cppn_active", K_REAL, OFF(geno.cppn_active), 0, 1, NULL, 0, "CPPN: active connections of a random genome"},
    {"cppn_changes", K_REAL, OFF(geno.cppn_changes), 0, 1000, NULL, 0, "CPPN: values a mutation changes on average"},
    {"cppn_step", K_REAL, OFF(geno.cppn_step), 0, 1, NULL, 0, "CPPN: largest change, fraction of the range"},
    {"gmx_points", K_INT, OFF(geno.gmx_points), 0, AM_MAX_GMX_POINTS, NULL, 0, "GMX points of a random genome"},
    {"gmx_max_points", K_INT, OFF(geno.gmx_max_points), 1, AM_MAX_GMX_POINTS, NULL, 0, "GMX points a genome may grow to"},
    {"mutation_rate", K_REAL, OFF(geno.rate), 0, 1, NULL, 0, "DCT and GMX: per-value mutation probability"},
    {"mutation_step", K_REAL, OFF(geno.step), 0, 1, NULL, 0, "DCT and GMX: largest change, fraction of the range"},
    {"gmx_material_rate", K_REAL, OFF(geno.gmx_material_rate), 0, 1, NULL, 0, "GMX: per-point material change"},
    {"gmx_add", K_REAL, OFF(geno.gmx_add), 0, 1, NULL, 0, "GMX: probability a mutation adds a point"},
    {"gmx_remove", K_REAL, OFF(geno.gmx_remove), 0, 1, NULL, 0, "GMX: probability a mutation removes a point"},
    {"checkpoint_seconds", K_LONG, OFF(checkpoint_seconds), 0, 1e7, NULL, 1, "0: a checkpoint every generation"},
};

#define KEY_COUNT ((int)(sizeof keys / sizeof keys[0]))
#define AM_EVO_VALUE_MAX 256 /* a value's text: a materialK's is the longest */
_Static_assert(sizeof keys / sizeof keys[0] <= AM_EVO_KEY_MAX, "AM_EVO_KEY_MAX: fewer entries than keys");

static const key_def* find_key(const char* name)
{
    for (int i = 0; i < KEY_COUNT; i++)
        if (strcmp(keys[i].name, name) == 0) return &keys[i];
    return NULL;
}

int am_evo_is_key(const char* key)
{
    return find_key(key) != NULL;
}

int am_evo_key_group(const char* key)
{
    const key_def* k = find_key(key);
    if (!k) return -1;
    const size_t off = k->off;
    if (k->kind == K_PALETTE || k->kind == K_MATERIAL) return AM_KEYS_GENOTYPE; /* what genomes are made of */
    if (off == OFF(actuation) || off == OFF(stiffness) || off == OFF(stiffness_min) || off == OFF(stiffness_max))
        return AM_KEYS_GENOTYPE;
    /* unsigned: an offset below the member wraps past its end */
    if (off - OFF(env) < sizeof(am_env)) return AM_KEYS_ENV;
    if (off - OFF(eval) < sizeof(am_eval_def)) return AM_KEYS_EVAL;
    if (off - OFF(geno) < sizeof(am_geno_def)) return AM_KEYS_GENOTYPE;
    if (off == OFF(cte) || off == OFF(mu_static) || off == OFF(mu_kinetic) || off == OFF(voxel_size)) return AM_KEYS_MATERIALS;
    return AM_KEYS_RUN;
}

int am_evo_key_count(void)
{
    return KEY_COUNT;
}

const char* am_evo_key_name(int i)
{
    return i >= 0 && i < KEY_COUNT ? keys[i].name : NULL;
}

const char* am_evo_key_help(int i)
{
    return i >= 0 && i < KEY_COUNT ? keys[i].help : NULL;
}

static am_status set_key(am_evo_def* d, const char* key, const char* value, char* err, int errsz);

am_status am_evo_set(am_evo_def* d, const char* key, const char* value, char* err, int errsz)
{
    am_status st = set_key(d, key, value, err, errsz);
    /* the genomes' evolved fields follow the two keys */
    d->geno.controls = am_evo_controls(d);
    return st;
}

static am_status set_key(am_evo_def* d, const char* key, const char* value, char* err, int errsz)
{
    const key_def* k = find_key(key);
    char qv[AM_QUOTE_BUF]; /* the key, then the value, as messages show them */
    if (!k) {
        long n;
        if (!strncmp(key, "material", 8) && key[8] != '-' && key[8] != '+' && am_parse_long(key + 8, &n) && n > AM_MAX_GENO_MATERIALS)
            return am_fail(err, errsz, AM_ERR_RANGE, "%s: a palette holds at most %d materials (the %s profile)",
                           am_quote(qv, sizeof qv, key, -1), AM_MAX_GENO_MATERIALS, AM_PROFILE_NAME);
        return am_fail(err, errsz, AM_ERR_ARG, "unknown key '%s' (amorph evolve --help-config lists them)",
                       am_quote(qv, sizeof qv, key, -1));
    }
    am_quote(qv, sizeof qv, value, -1);
    char* base = (char*)d + k->off;
    switch (k->kind) {
    case K_INT:
    case K_LONG: {
        long v;
        if (!am_parse_long(value, &v) || (double)v < k->lo || (double)v > k->hi)
            return am_fail(err, errsz, AM_ERR_RANGE, "%s = '%s': expected an integer in [%.0f, %.0f]", key, qv, k->lo, k->hi);
        if (k->kind == K_INT) *(int*)base = (int)v;
        else *(long*)base = v;
        return AM_OK;
    }
    case K_U64: {
        uint64_t v;
        if (!am_parse_u64(value, &v))
            return am_fail(err, errsz, AM_ERR_RANGE, "%s = '%s': expected an integer in [0, 18446744073709551615]", key, qv);
        *(uint64_t*)base = v;
        return AM_OK;
    }
    case K_REAL:
    case K_PARAM: {
        double v;
        if (!am_parse_double(value, &v) || v < k->lo || v > k->hi)
            return am_fail(err, errsz, AM_ERR_RANGE, "%s = '%s': expected a number in [%g, %g]", key, qv, k->lo, k->hi);
        if (k->kind == K_PARAM) *(am_param*)base = AM_PARAM_FROM_DOUBLE(v);
        else *(am_real*)base = AM_FROM_DOUBLE(v);
        return AM_OK;
    }
    case K_ENUM:
        for (int i = (int)k->lo; i <= (int)k->hi; i++)
            if (strcmp(value, k->names[i]) == 0) {
                *(int*)base = i;
                return AM_OK;
            }
        {
            char list[128] = "";
            for (int i = (int)k->lo; i <= (int)k->hi; i++) {
                strncat(list, k->names[i], sizeof list - strlen(list) - 1);
                if (i < (int)k->hi) strncat(list, i + 1 < (int)k->hi ? ", " : " or ", sizeof list - strlen(list) - 1);
            }
            return am_fail(err, errsz, AM_ERR_RANGE, "%s = '%s': expected %s", key, qv, list);
        }
    case K_ONOFF:
        if (strcmp(value, "on") == 0) *(int*)base = 1;
        else if (strcmp(value, "off") == 0) *(int*)base = 0;
        else return am_fail(err, errsz, AM_ERR_RANGE, "%s = '%s': expected on or off", key, qv);
        return AM_OK;
    case K_WORKSPACE: {
        long v[3];
        int n = 0;
        const char* s = value;
        char part[32];
        while (n < 3) {
            const char* x = strchr(s, 'x');
            size_t len = x ? (size_t)(x - s) : strlen(s);
            if (len == 0 || len >= sizeof part) break;
            memcpy(part, s, len);
            part[len] = 0;
            if (!am_parse_long(part, &v[n])) break;
            n++;
            if (!x) {
                s = NULL;
                break;
            }
            s = x + 1;
        }
        if (s != NULL || (n != 1 && n != 3))
            return am_fail(err, errsz, AM_ERR_RANGE, "%s = '%s': expected N or NxMxK cells", key, qv);
        if (n == 1) v[1] = v[2] = v[0];
        for (int a = 0; a < 3; a++)
            if (v[a] < 1 || v[a] > AM_MAX_DIM)
                return am_fail(err, errsz, AM_ERR_RANGE, "%s = '%s': each side must be in [1, %d] (the %s profile)", key, qv,
                               AM_MAX_DIM, AM_PROFILE_NAME);
        d->geno.nx = (int)v[0];
        d->geno.ny = (int)v[1];
        d->geno.nz = (int)v[2];
        return AM_OK;
    }
    case K_PALETTE:
        for (int i = 0; k->names[i]; i++)
            if (strcmp(value, k->names[i]) == 0) {
                if (preset_size[i] > AM_MAX_GENO_MATERIALS)
                    return am_fail(err, errsz, AM_ERR_RANGE, "%s = %s: %d materials; the %s profile's palette holds at most %d", key,
                                   qv, preset_size[i], AM_PROFILE_NAME, AM_MAX_GENO_MATERIALS);
                d->palette = i;
                d->geno.materials = preset_fields[i];
                palette_names_sync(d);
                return AM_OK;
            }
        return am_fail(err, errsz, AM_ERR_RANGE, "%s = '%s': expected seed or unshackled (or materialK keys over one)", key, qv);
    case K_MATERIAL: {
        char msg[AM_ERR_MAX];
        const int idx = (int)k->lo - 1;
        if (parse_material(value, &d->material[idx], msg, sizeof msg) != AM_OK)
            return am_fail(err, errsz, AM_ERR_RANGE, "%s = '%s': %s", key, qv, msg);
        if (d->geno.materials < idx + 1) d->geno.materials = idx + 1;
        palette_names_sync(d);
        return AM_OK;
    }
    }
    return am_fail(err, errsz, AM_ERR_ARG, "key '%s': internal error", key);
}

static int key_index(const char* name)
{
    for (int i = 0; i < KEY_COUNT; i++)
        if (strcmp(keys[i].name, name) == 0) return i;
    return -1;
}

am_status am_evo_check_key(const am_evo_def* d, int* key, char* err, int errsz)
{
    *key = -1;
    if (d->population < 2 || d->population > AM_MAX_POPULATION || d->population % 2 != 0)
        return *key = key_index("population"),
               am_fail(err, errsz, AM_ERR_RANGE, "population = %d: must be even, in [2, %d]", d->population, AM_MAX_POPULATION);
    if (d->evaluations < d->population)
        return *key = key_index("evaluations"),
               am_fail(err, errsz, AM_ERR_RANGE, "evaluations = %ld: at least the population (%d)", d->evaluations, d->population);
    if (d->eval.relax_min_steps > d->eval.relax_max_steps)
        return *key = key_index("relax_min_steps"), am_fail(err, errsz, AM_ERR_RANGE, "relax_min_steps = %ld exceeds relax_max_steps = %ld",
                                                            d->eval.relax_min_steps, d->eval.relax_max_steps);
    if (d->geno.gmx_points > d->geno.gmx_max_points)
        return *key = key_index("gmx_points"), am_fail(err, errsz, AM_ERR_RANGE, "gmx_points = %d exceeds gmx_max_points = %d",
                                                       d->geno.gmx_points, d->geno.gmx_max_points);
    if (d->geno.repr == AM_REPR_DCT && (d->geno.dct_k > d->geno.nx || d->geno.dct_k > d->geno.ny || d->geno.dct_k > d->geno.nz))
        return *key = key_index("dct_k"), am_fail(err, errsz, AM_ERR_RANGE, "dct_k = %d exceeds a workspace side (%dx%dx%d)",
                                                  d->geno.dct_k, d->geno.nx, d->geno.ny, d->geno.nz);
    if ((d->actuation != AM_ACTUATION_GLOBAL || d->stiffness != AM_STIFFNESS_MATERIAL) && !AM_GENO_LAYERS)
        return *key = key_index(d->actuation != AM_ACTUATION_GLOBAL ? "actuation" : "stiffness"),
               am_fail(err, errsz, AM_ERR_RANGE, "%s: the %s profile keeps no phase or stiffness per voxel (AM_GENO_LAYERS 0)",
                       d->actuation != AM_ACTUATION_GLOBAL ? "actuation = phase" : "stiffness = evolved", AM_PROFILE_NAME);
    if (d->stiffness == AM_STIFFNESS_EVOLVED &&
        !(AM_PARAM_TO_DOUBLE(d->stiffness_min) <= AM_PARAM_TO_DOUBLE(d->stiffness_max) &&
          AM_PARAM_TO_DOUBLE(d->stiffness_max) <= 100.0 * AM_PARAM_TO_DOUBLE(d->stiffness_min)))
        return *key = key_index("stiffness_max"),
               am_fail(err, errsz, AM_ERR_RANGE, "stiffness_max = %g: from stiffness_min (%g) to 100 times it", AM_PARAM_TO_DOUBLE(d->stiffness_max),
                       AM_PARAM_TO_DOUBLE(d->stiffness_min));
    if (d->eval.score == AM_SCORE_SUSTAINED && d->eval.cycles <= d->eval.sustained_from)
        return *key = key_index("score"),
               am_fail(err, errsz, AM_ERR_RANGE, "score = sustained needs cycles above sustained_from (cycles = %d, sustained_from = %d): say cycles = 30",
                       d->eval.cycles, d->eval.sustained_from);
    /* the palette: materialK keys without a gap after the preset, names once each, enough materials */
    {
        const int preset = preset_size[d->palette == AM_PALETTE_UNSHACKLED];
        if (preset > AM_MAX_GENO_MATERIALS)
            return *key = key_index("palette"), am_fail(err, errsz, AM_ERR_RANGE, "palette = %s: %d materials; the %s profile's palette holds at most %d",
                                                        palette_names[1], preset, AM_PROFILE_NAME, AM_MAX_GENO_MATERIALS);
        int size = preset;
        for (int k = preset; k < AM_MAX_GENO_MATERIALS; k++) {
            if (!d->material[k].name[0]) continue;
            if (k > size) {
                char name[32];
                snprintf(name, sizeof name, "material%d", k + 1);
                return *key = key_index(name),
                       am_fail(err, errsz, AM_ERR_RANGE, "material%d: the palette has no material%d (%s has %d materials): give "
                               "them in order", k + 1, size + 1, palette_names[d->palette == AM_PALETTE_UNSHACKLED], preset);
            }
            size = k + 1;
        }
        char name_of[AM_MAX_GENO_MATERIALS][AM_NAME_MAX];
        for (int k = 0; k < size; k++)
            snprintf(name_of[k], AM_NAME_MAX, "%s", d->material[k].name[0] ? d->material[k].name : preset_material(d, k).name);
        for (int k = 1; k < size; k++)
            for (int j = 0; j < k; j++)
                if (!strcmp(name_of[j], name_of[k])) {
                    char name[32];
                    snprintf(name, sizeof name, "material%d", d->material[k].name[0] ? k + 1 : j + 1);
                    return *key = key_index(name), am_fail(err, errsz, AM_ERR_RANGE, "material%d and material%d are both named '%s'",
                                                              j + 1, k + 1, name_of[k]);
                }
        if (d->geno.materials > size)
            return *key = key_index("materials"),
                   am_fail(err, errsz, AM_ERR_RANGE, "materials = %d: the palette has %d (%s%s)", d->geno.materials, size,
                           palette_names[d->palette == AM_PALETTE_UNSHACKLED], size > preset ? " and materialK keys" : "");
    }
    if (d->threads < 0 || d->threads > AM_MAX_WORKERS)
        return *key = key_index("threads"), am_fail(err, errsz, AM_ERR_RANGE, "threads = %d: must be in [0, %d]", d->threads, AM_MAX_WORKERS);
    /* the evaluation's budget, with the period in seconds at its most steps (no body is built) */
    return am_evo_check_budget(d, d->env.period_s > AM_P(0) ? 1e7 : (double)d->env.period_steps, key, err, errsz);
}

am_status am_evo_check_budget(const am_evo_def* d, double period_steps, int* key, char* err, int errsz)
{
    am_eval_cost c;
    char why[AM_ERR_MAX], v[64];
    *key = -1;
    if (am_eval_check(&d->env, &d->eval, period_steps, why, sizeof why) == AM_OK) return AM_OK;
    am_eval_max_steps(&d->env, &d->eval, period_steps, &c);
    /* the setting that multiplies the seed's evaluation most in the larger part: the relaxation
     * (its count, its step) or the movement (cycles, the period) */
    const am_eval_def e0 = am_default_eval();
    const double r_count = (double)d->eval.relax_max_steps / (double)e0.relax_max_steps, r_step = AM_REF_DT_FRAC / c.step;
    const double m_cycles = (double)d->eval.cycles / (double)e0.cycles, m_period = c.period / 500.0;
    const char* name;
    if (c.relaxations * c.relax >= c.move)
        name = r_count >= r_step ? "relax_max_steps" : d->eval.dt_search ? "dt_search" : "dt_frac";
    else if (d->env.period_s > AM_P(0) && period_steps >= 1e7) /* a period in seconds at its most: the cycles are what was asked */
        name = d->eval.cycles > e0.cycles ? "cycles" : "period_s";
    else
        name = m_cycles >= m_period ? "cycles" : d->env.period_s > AM_P(0) ? "period_s" : "period_steps";
    *key = key_index(name);
    am_evo_key_value(d, *key, v, sizeof v);
    return am_fail(err, errsz, AM_ERR_RANGE, "%s = %s: %s", name, v, why);
}

am_status am_evo_check(const am_evo_def* d, char* err, int errsz)
{
    int key;
    return am_evo_check_key(d, &key, err, errsz);
}

/* ---- text ---- */


/* one key's value as text */
static void value_text(const am_evo_def* d, const key_def* k, char* out, int cap)
{
    const char* base = (const char*)d + k->off;
    switch (k->kind) {
    case K_INT: snprintf(out, (size_t)cap, "%d", *(const int*)base); break;
    case K_LONG: snprintf(out, (size_t)cap, "%ld", *(const long*)base); break;
    case K_U64: snprintf(out, (size_t)cap, "%llu", (unsigned long long)*(const uint64_t*)base); break;
    case K_REAL: {
        /* the shortest text that reads back to the same am_real */
        const am_real v = *(const am_real*)base;
        for (int prec = 6; prec <= 17; prec++) {
            snprintf(out, (size_t)cap, "%.*g", prec, AM_TO_DOUBLE(v));
            if (AM_FROM_DOUBLE(strtod(out, NULL)) == v) break;
        }
        break;
    }
    case K_PARAM: {
        /* the shortest text that reads back to the same am_param */
        const am_param v = *(const am_param*)base;
        for (int prec = 6; prec <= 17; prec++) {
            snprintf(out, (size_t)cap, "%.*g", prec, AM_PARAM_TO_DOUBLE(v));
            if (AM_PARAM_FROM_DOUBLE(strtod(out, NULL)) == v) break;
        }
        break;
    }
    case K_ENUM: {
        int v = *(const int*)base;
        snprintf(out, (size_t)cap, "%s", v >= (int)k->lo && v <= (int)k->hi ? k->names[v] : "?");
        break;
    }
    case K_ONOFF: snprintf(out, (size_t)cap, "%s", *(const int*)base ? "on" : "off"); break;
    case K_WORKSPACE:
        if (d->geno.nx == d->geno.ny && d->geno.ny == d->geno.nz) snprintf(out, (size_t)cap, "%d", d->geno.nx);
        else snprintf(out, (size_t)cap, "%dx%dx%d", d->geno.nx, d->geno.ny, d->geno.nz);
        break;
    case K_PALETTE: snprintf(out, (size_t)cap, "%s", d->palette == AM_PALETTE_UNSHACKLED ? k->names[1] : k->names[0]); break;
    case K_MATERIAL: material_text(&d->material[(int)k->lo - 1], out, cap); break;
    }
}

/* 1 when the key is written: a palette key only when it says something (the seed's palette, a
 * materialK not set), so that a run of the seed's palette writes the text it always wrote */
static int written(const am_evo_def* d, const key_def* k)
{
    if (k->kind == K_PALETTE) return d->palette != AM_PALETTE_SEED;
    if (k->kind == K_MATERIAL) return d->material[(int)k->lo - 1].name[0] != 0;
    /* the evolved fields' keys likewise: only in a run that evolves them */
    if (k->off == OFF(actuation)) return d->actuation != AM_ACTUATION_GLOBAL;
    if (k->off == OFF(stiffness) || k->off == OFF(stiffness_min) || k->off == OFF(stiffness_max))
        return d->stiffness != AM_STIFFNESS_MATERIAL;
    return 1;
}

am_status am_evo_write(const am_evo_def* d, int with_runtime, am_text* out, char* err, int errsz)
{
    char v[AM_EVO_VALUE_MAX];
    am_text_put(out, "# amorph evolve configuration (key = value; docs/evolve.md)\n");
    for (int i = 0; i < KEY_COUNT; i++) {
        if ((keys[i].runtime && !with_runtime) || !written(d, &keys[i])) continue;
        value_text(d, &keys[i], v, sizeof v);
        am_text_put(out, "%s = %s\n", keys[i].name, v);
    }
    if (out->full == 2) return am_fail(err, errsz, AM_ERR_IO, "configuration text: the output failed");
    if (out->full) return am_fail(err, errsz, AM_ERR_CAPACITY, "configuration text needs more than the %ld bytes given", out->cap);
    return AM_OK;
}

static am_status write_config(const void* d, am_text* out, char* err, int errsz)
{
    return am_evo_write((const am_evo_def*)d, 0, out, err, errsz);
}
static am_status write_config_runtime(const void* d, am_text* out, char* err, int errsz)
{
    return am_evo_write((const am_evo_def*)d, 1, out, err, errsz);
}

am_status am_evo_format(const am_evo_def* d, int with_runtime, char* buf, long cap, long* len, char* err, int errsz)
{
    return am_text_format(with_runtime ? write_config_runtime : write_config, d, "configuration text", buf, cap, len,
                          err, errsz);
}

void am_evo_key_value(const am_evo_def* d, int i, char* out, int cap)
{
    if (i < 0 || i >= KEY_COUNT) {
        if (cap > 0) out[0] = 0;
        return;
    }
    value_text(d, &keys[i], out, cap);
}

int am_evo_same_run(const am_evo_def* a, const am_evo_def* b, char* key, int keysz)
{
    char va[AM_EVO_VALUE_MAX], vb[AM_EVO_VALUE_MAX];
    for (int i = 0; i < KEY_COUNT; i++) {
        if (keys[i].runtime || strcmp(keys[i].name, "evaluations") == 0) continue;
        value_text(a, &keys[i], va, sizeof va);
        value_text(b, &keys[i], vb, sizeof vb);
        if (strcmp(va, vb) != 0) {
            if (key && keysz > 0) snprintf(key, (size_t)keysz, "%s (%s, now %s)", keys[i].name, va, vb);
            return 0;
        }
    }
    return 1;
}

static char* trim(char* s)
{
    while (*s == ' ' || *s == '\t') s++;
    char* e = s + strlen(s);
    while (e > s && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\r')) *--e = 0;
    return s;
}

am_status am_evo_parse_line(am_evo_def* d, const char* text, long n, const char* fname, int lineno, char* err, int errsz)
{
    char line[512];
    char msg[AM_ERR_MAX];
    if (n >= (long)sizeof line)
        return am_fail(err, errsz, AM_ERR_PARSE, "%s:%d: line longer than %d characters", fname, lineno, (int)sizeof line - 1);
    memcpy(line, text, (size_t)n);
    line[n] = 0;
    char* hash = strchr(line, '#');
    if (hash) *hash = 0;
    char* s = trim(line);
    if (!*s) return AM_OK;
    char* eq = strchr(s, '=');
    char qb[AM_QUOTE_BUF];
    if (!eq)
        return am_fail(err, errsz, AM_ERR_PARSE, "%s:%d: expected 'key = value', got '%s'", fname, lineno,
                       am_quote(qb, sizeof qb, s, -1));
    *eq = 0;
    char* key = trim(s);
    char* value = trim(eq + 1);
    if (!*key) return am_fail(err, errsz, AM_ERR_PARSE, "%s:%d: missing key before '='", fname, lineno);
    if (!*value)
        return am_fail(err, errsz, AM_ERR_PARSE, "%s:%d: %s: missing value after '='", fname, lineno,
                       am_quote(qb, sizeof qb, key, -1));
    am_status st = am_evo_set(d, key, value, msg, sizeof msg);
    if (st != AM_OK) return am_fail(err, errsz, st == AM_ERR_ARG ? AM_ERR_PARSE : st, "%s:%d: %s", fname, lineno, msg);
    return AM_OK;
}

int am_evo_line_key(const char* text, long n)
{
    char line[512];
    if (n < 0 || n >= (long)sizeof line) return -1;
    memcpy(line, text, (size_t)n);
    line[n] = 0;
    char* hash = strchr(line, '#');
    if (hash) *hash = 0;
    char* eq = strchr(line, '=');
    if (!eq) return -1;
    *eq = 0;
    return key_index(trim(line));
}

am_status am_evo_parse(am_evo_def* d, const char* text, const char* fname, char* err, int errsz)
{
    int lineno = 0;
    const char* p = text;
    while (*p) {
        lineno++;
        const char* nl = strchr(p, '\n');
        long len = nl ? (long)(nl - p) : (long)strlen(p);
        am_status st = am_evo_parse_line(d, p, len, fname, lineno, err, errsz);
        if (st != AM_OK) return st;
        p = nl ? nl + 1 : p + len;
    }
    return AM_OK;
}

am_status am_evo_set_over(am_evo_def* d, const char* key, const char* value, unsigned* material, char* err, int errsz)
{
    static const char* const material_keys[] = {"cte", "mu_static", "mu_kinetic", "voxel_size"}; /* AM_MATERIAL_* bits in order */
    am_status st = am_evo_set(d, key, value, err, errsz);
    if (st != AM_OK) return st;
    if (!strcmp(key, "period_steps")) d->env.period_s = AM_P(0); /* the period in steps, as this setting says */
    if (!strcmp(key, "relax_max_steps") && d->eval.relax_min_steps > d->eval.relax_max_steps)
        d->eval.relax_min_steps = d->eval.relax_max_steps;
    *material = 0;
    for (int k = 0; k < (int)(sizeof material_keys / sizeof material_keys[0]); k++)
        if (!strcmp(key, material_keys[k])) *material = 1u << k;
    return AM_OK;
}

void am_evo_apply_materials(const am_evo_def* d, unsigned mask, am_lattice* lat)
{
    if (mask & AM_MATERIAL_VOXEL_SIZE) lat->voxel_size = d->voxel_size;
    for (int m = 0; m < lat->palette.count; m++) {
        am_material* mt = &lat->palette.mat[m];
        if ((mask & AM_MATERIAL_CTE) && mt->cte != AM_P(0)) mt->cte = d->cte;
        if (mask & AM_MATERIAL_MU_STATIC) mt->mu_static = d->mu_static;
        if (mask & AM_MATERIAL_MU_KINETIC) mt->mu_kinetic = d->mu_kinetic;
    }
}
