/* The options that name a robot and change its settings, as render, view, sim, eval and the other
 * robot commands take them (tools/robot.h); loading the robot is tools/robot.c. */
#include "robot.h"

#include <string.h>

/* older spellings kept as aliases of the table's keys (after '-' became '_') */
static const struct {
    const char* old;
    const char* key;
} aliases[] = {{"repr", "representation"}, {"size", "workspace"}, {"relax_max", "relax_max_steps"}, {"evals", "evaluations"}};

int tool_setting_arg(const char* cmd, int argc, char** argv, int* i, const char** key, const char** val)
{
    const char* a = argv[*i];
    if (strncmp(a, "--", 2) != 0) return 0;
    const char* name = a + 2;
    const char* eq = strchr(name, '=');
    char norm[64];
    size_t n = eq ? (size_t)(eq - name) : strlen(name);
    if (n == 0 || n >= sizeof norm) return 0;
    memcpy(norm, name, n);
    norm[n] = 0;
    for (char* p = norm; *p; p++)
        if (*p == '-') *p = '_';
    const char* k = NULL;
    for (size_t j = 0; j < sizeof aliases / sizeof aliases[0]; j++)
        if (!strcmp(norm, aliases[j].old)) k = aliases[j].key;
    for (int j = 0; !k && j < am_evo_key_count(); j++)
        if (!strcmp(am_evo_key_name(j), norm)) k = am_evo_key_name(j);
    if (!k) return 0;
    const char* v = eq ? eq + 1 : *i + 1 < argc ? argv[*i + 1] : NULL;
    if (!eq && !strcmp(k, "dt_search") && !(v && (!strcmp(v, "on") || !strcmp(v, "off")))) {
        /* --dt-search alone, as amorph sim always took it */
        *key = k, *val = "on";
        return 1;
    }
    if (!v || (!eq && !strncmp(v, "--", 2))) {
        tool_usage_error("%s: --%.*s needs a value", cmd, (int)n, name);
        return 2;
    }
    if (!strcmp(k, "cte") && (!strcmp(v, "linear") || !strcmp(v, "volume") || !strcmp(v, "volumetric"))) {
        tool_usage_error("%s: --cte %s: the CTE convention is --cte_mode volumetric|linear (--cte is the expansion "
                         "coefficient, a number)", cmd, v);
        return 2;
    }
    if (!eq) (*i)++;
    *key = k, *val = v;
    return 1;
}

int tool_ends_with(const char* s, const char* tail)
{
    size_t n = strlen(s), t = strlen(tail);
    return n >= t && !strcmp(s + n - t, tail);
}

static int two_robots(const char* cmd, const char* one, const char* two)
{
    char q1[AM_QUOTE_BUF], q2[AM_QUOTE_BUF];
    return tool_usage_error("%s: one robot at a time ('%s' and '%s')", cmd, am_quote(q1, sizeof q1, one, -1),
                            am_quote(q2, sizeof q2, two, -1));
}

int tool_robot_arg(const char* cmd, int argc, char** argv, int* i, tool_robot_args* a)
{
    const char* arg = argv[*i];
    const char* v = *i + 1 < argc ? argv[*i + 1] : NULL;
    if (!strcmp(arg, "--scene")) {
        if (!v) return tool_usage_error("%s: --scene needs a name (cube:N, sphere:D, cantilever:N, chain:N, halfbar:N, antibar:N)", cmd);
        if (a->name) return two_robots(cmd, a->name, v);
        a->name = v, a->is_scene = 1, (*i)++;
        return 1;
    }
    if (!strcmp(arg, "--genome")) {
        if (!v) return tool_usage_error("%s: --genome needs a genome file (evaluated in the run folder's settings)", cmd);
        if (a->genome) {
            char q1[AM_QUOTE_BUF], q2[AM_QUOTE_BUF];
            return tool_usage_error("%s: --genome given twice ('%s' and '%s')", cmd, am_quote(q1, sizeof q1, a->genome, -1),
                                    am_quote(q2, sizeof q2, v, -1));
        }
        a->genome = v, (*i)++;
        return 1;
    }
    if (!strcmp(arg, "--dt")) {
        if (!tool_parse_real(v, 1e-12, 1e3, &a->dt_s)) return tool_usage_error("%s: --dt needs seconds in [1e-12, 1e3]", cmd);
        (*i)++;
        return 1;
    }
    if (arg[0] != '-' || !arg[1]) {
        /* a VXD over a VXA file: the one of the two ending in .vxd */
        if (a->name && !a->vxd && !a->is_scene && (tool_ends_with(arg, ".vxd") || tool_ends_with(a->name, ".vxd"))) {
            if (tool_ends_with(a->name, ".vxd")) a->vxd = a->name, a->name = arg;
            else a->vxd = arg;
            return 1;
        }
        if (a->name) return two_robots(cmd, a->name, a->vxd ? a->vxd : arg);
        a->name = arg;
        return 1;
    }
    const char *key, *val;
    int r = tool_setting_arg(cmd, argc, argv, i, &key, &val);
    if (r != 1) return r;
    int g = am_evo_key_group(key);
    /* the stiffness range and the palette too: what a genome's evolved stiffness field maps to, and
     * what its material names are looked up in */
    const int range = !strcmp(key, "stiffness_min") || !strcmp(key, "stiffness_max") || tool_robot_palette_key(key);
    if (g != AM_KEYS_ENV && g != AM_KEYS_EVAL && g != AM_KEYS_MATERIALS && !range)
        return tool_usage_error("%s: --%s is a setting of an evolution, not of one robot (the robot's settings: amorph %s "
                                "--help)", cmd, key, cmd);
    if (a->nset == TOOL_MAX_SETTINGS) return tool_usage_error("%s: more than %d settings", cmd, TOOL_MAX_SETTINGS);
    /* the value is checked now, as amorph evolve checks it, so a bad one is told before any file is read */
    am_evo_def d = am_default_evo();
    char err[AM_ERR_MAX];
    if (am_evo_set(&d, key, val, err, sizeof err) != AM_OK) return tool_usage_error("%s: --%s", cmd, err);
    a->key[a->nset] = key;
    a->val[a->nset++] = val;
    return 1;
}
