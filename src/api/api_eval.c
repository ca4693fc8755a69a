/* The embedding API (amorph/api.h): one robot, given as text, evaluated on a workspace its caller
 * owns. A thin layer over the others: the genome and lattice readers, the run's expression
 * (am_evo_lattice), am_model_build and am_evaluate, with the settings applied as amorph sim applies
 * its flags, so that a result here is the command's, bit for bit. */
#include "api_internal.h"

#include <stdint.h>
#include <string.h>

am_status am_layout_check(long version, const char* config, long lattice, long model, long state, long genome, long evo,
                          long api_work, char* err, int errsz)
{
    const long mine[] = {(long)sizeof(am_lattice), (long)sizeof(am_model), (long)sizeof(am_state), (long)sizeof(am_genome),
                         (long)sizeof(am_evo), (long)sizeof(am_api_work)};
    const long theirs[] = {lattice, model, state, genome, evo, api_work};
    const char* names[] = {"am_lattice", "am_model", "am_state", "am_genome", "am_evo", "am_api_work"};
    if (!config) config = "?";
    if (version / 10000 != AM_LAYOUT_VERSION / 10000 || version / 100 > AM_LAYOUT_VERSION / 100)
        return am_fail(err, errsz, AM_ERR_ARG, "the program was compiled with amorph %ld.%ld.%ld headers, the library is %d.%d.%d: rebuild it against this library",
                       version / 10000, version / 100 % 100, version % 100, AM_VERSION_MAJOR, AM_VERSION_MINOR, AM_VERSION_PATCH);
    for (int k = 0; k < (int)(sizeof mine / sizeof mine[0]); k++)
        if (theirs[k] != mine[k])
            return am_fail(err, errsz, AM_ERR_ARG,
                           "the program was compiled for %.40s (%s %ld bytes), the library for " AM_LAYOUT_CONFIG " (%ld bytes): "
                           "build it with the library's defines (pkg-config --cflags amorph)",
                           config, names[k], theirs[k], mine[k]);
    return AM_OK;
}

int am_api_version(void)
{
    return AM_API_VERSION;
}

long am_api_work_size(void)
{
    return (long)sizeof(am_api_work);
}

long am_api_result_size(void)
{
    return (long)sizeof(am_result);
}

am_status am_api_init(am_api_work* w, long size, char* err, int errsz)
{
    if (!w) return am_fail(err, errsz, AM_ERR_ARG, "no workspace (NULL)");
    if (size != (long)sizeof *w)
        return am_fail(err, errsz, AM_ERR_ARG,
                       "the workspace has %ld bytes; the library's (" AM_LAYOUT_CONFIG ") has %ld (am_api_work_size): a program compiled "
                       "with the library's REAL and PROFILE passes sizeof *w",
                       size, (long)sizeof *w);
    if ((uintptr_t)w % _Alignof(am_api_work) != 0)
        return am_fail(err, errsz, AM_ERR_ARG, "the workspace is not aligned to %d bytes", (int)_Alignof(am_api_work));
    w->def = am_default_evo();
    am_rng_seed(&w->rng, w->def.seed); /* the stream of the genome operators (api_ask.c) */
    w->materials_set = 0;
    w->sim = 0;
    w->size = (long)sizeof *w;
    return AM_OK;
}

am_status am_api_set(am_api_work* w, const char* key, const char* value, char* err, int errsz)
{
    am_status st = am_api_ready(w, err, errsz);
    if (st != AM_OK) return st;
    if (!key || !value) return am_fail(err, errsz, AM_ERR_ARG, "a setting needs a key and a value (NULL)");
    am_evo_def d = w->def;
    unsigned material = 0;
    st = am_evo_set_over(&d, key, value, &material, err, errsz);
    if (st != AM_OK) return st;
    w->def = d;
    w->materials_set |= material;
    return AM_OK;
}

am_status am_api_set_config(am_api_work* w, const char* text, const char* name, char* err, int errsz)
{
    am_status st = am_api_ready(w, err, errsz);
    if (st != AM_OK) return st;
    if (!text) return am_fail(err, errsz, AM_ERR_ARG, "no configuration text (NULL)");
    if (!name) name = "config";
    /* a run folder's config.txt as amorph sim DIR reads it: the keys it does not name as the run had
     * them, and a key set twice refused at its second line (which value was meant is not a guess) */
    am_evo_def d = am_stored_evo();
    int line_of[AM_EVO_KEY_MAX] = {0};
    int lineno = 0;
    for (const char* p = text; *p;) {
        lineno++;
        const char* nl = strchr(p, '\n');
        const long n = nl ? (long)(nl - p) : (long)strlen(p);
        const int key = am_evo_line_key(p, n);
        if (key >= 0 && key < AM_EVO_KEY_MAX && line_of[key])
            return am_fail(err, errsz, AM_ERR_PARSE, "%.200s:%d: %s set again (first on line %d): say it once", name, lineno,
                           am_evo_key_name(key), line_of[key]);
        if ((st = am_evo_parse_line(&d, p, n, name, lineno, err, errsz)) != AM_OK) return st;
        if (key >= 0 && key < AM_EVO_KEY_MAX) line_of[key] = lineno;
        p = nl ? nl + 1 : p + n;
    }
    w->def = d;
    w->materials_set = 0; /* the run's materials are its palette's, which a genome is expressed with */
    return AM_OK;
}

/* the model of w's lattice in w's environment, evaluated into *out (a zero result for an empty body) */
static am_status simulate(am_api_work* w, am_result* out, char* err, int errsz)
{
    memset(out, 0, sizeof *out);
    am_status st = am_evo_simulate(&w->def, &w->work, NULL, out, err, errsz);
    return st == AM_ERR_EMPTY ? AM_OK : st; /* an empty body is a valid one that goes nowhere: fitness 0 */
}

am_status am_api_eval_genome(am_api_work* w, const char* text, am_result* out, char* err, int errsz)
{
    am_status st = am_api_ready(w, err, errsz);
    if (st != AM_OK) return st;
    if (!text || !out) return am_fail(err, errsz, AM_ERR_ARG, "no genome text or no result (NULL)");
    st = am_genome_parse(&w->genome, text, "genome", err, errsz);
    if (st != AM_OK) return st;
    am_evo_palette_into(&w->def, &w->palette);
    char msg[AM_ERR_MAX];
    st = am_evo_express(&w->def, &w->palette, &w->genome, &w->work, msg, sizeof msg); /* with its evolved fields */
    if (st != AM_OK) return am_fail(err, errsz, st, "genome: %s", msg);
    return simulate(w, out, err, errsz);
}

am_status am_api_eval_lattice(am_api_work* w, const char* text, am_result* out, char* err, int errsz)
{
    am_status st = am_api_ready(w, err, errsz);
    if (st != AM_OK) return st;
    if (!text || !out) return am_fail(err, errsz, AM_ERR_ARG, "no lattice text or no result (NULL)");
    am_lattice* lat = &w->work.lattice;
    w->work.has_layers = 0; /* a lattice carries no layers */
    st = am_lattice_parse(lat, text, "lattice", err, errsz);
    if (st != AM_OK) return st;
    /* the material keys that were set change the lattice's own materials (amorph sim's rule) */
    am_evo_apply_materials(&w->def, w->materials_set, lat);
    return simulate(w, out, err, errsz);
}

/* a VXA text's robot into w->work (lattice, layers) and w->def's environment and evaluation */
am_status am_api_read_vxa(am_api_work* w, const char* text, char* err, int errsz)
{
#if AM_GENO_LAYERS && !defined(AM_COMPACT)
    am_evo_work* k = &w->work;
    am_robot r;
    am_robot_init(&r, &k->lattice, &k->layers);
    am_status st = am_vxa_parse(&k->lattice, &w->vxa, &w->xml, text, "vxa", err, errsz);
    if (st == AM_OK) st = am_vxa_robot(&r, &w->vxa, err, errsz);
    if (st != AM_OK) return st;
    k->has_layers = k->layers.has_phase || k->layers.has_stiffness || k->layers.has_bc;
    w->def.env = r.env;
    w->def.eval = r.eval;
    w->def.eval.record = NULL;
    w->def.eval.gait = NULL;
    /* the file's run length (its StopCondition, InitCmTime) as the evaluation's cycles and least
     * relaxation, at the robot's own step, as amorph sim FILE takes it */
    if (!(w->vxa.stop_type >= 0 || w->vxa.init_cm_time > 0) || w->def.eval.dt_search) return AM_OK;
    st = am_model_build_layers(&k->model, &k->lattice, &w->def.env, k->has_layers ? &k->layers : NULL, err, errsz);
    if (st == AM_ERR_EMPTY) return AM_OK; /* no voxel: nothing to run */
    if (st != AM_OK) return st;
    char note[640];
    const double dt = am_dt_si(&k->model, w->def.env.dt_frac), dt_rec = am_to_si(&k->model, k->model.dt_rec, AM_DIM_TIME);
    return am_vxa_stop_settings(&w->vxa, dt, AM_REF_DT_FRAC * dt_rec, k->model.env.period_steps, 0, &w->def.eval, note, (int)sizeof note,
                                err, errsz);
#else
    (void)w, (void)text;
    return am_fail(err, errsz, AM_ERR_CAPACITY, "VXA text: the %s profile reads no VXA", AM_PROFILE_NAME);
#endif
}

am_status am_api_eval_vxa(am_api_work* w, const char* text, am_result* out, char* err, int errsz)
{
    am_status st = am_api_ready(w, err, errsz);
    if (st != AM_OK) return st;
    if (!text || !out) return am_fail(err, errsz, AM_ERR_ARG, "no VXA text or no result (NULL)");
    if ((st = am_api_read_vxa(w, text, err, errsz)) != AM_OK) return st;
    return simulate(w, out, err, errsz);
}
