/* The evolver: deterministic crowding (Mahfoud 1996) over any genotype, evaluations on the
 * port's parallel map, statistics. Randomness comes from one stream, consumed serially on the
 * calling thread; workers only evaluate, each on its own workspace, and results are applied in a
 * fixed order, so a run is the same for any number of workers. */
#include "amorph/evo.h"

#include <stdio.h>
#include <string.h>


am_express_def am_evo_express_def(const am_evo_def* d, const am_palette* pal)
{
    am_express_def ex = am_default_express();
    ex.palette = pal;
    ex.voxel_size = d->voxel_size;
    ex.stiffness_min = d->stiffness_min;
    ex.stiffness_max = d->stiffness_max;
    return ex;
}
#define express_def am_evo_express_def

am_status am_evo_lattice(const am_evo_def* d, const am_palette* pal, const am_genome* g, am_geno_work* w,
                         am_lattice* lat, char* err, int errsz)
{
    am_express_def ex = express_def(d, pal);
    return am_genome_to_lattice(g, &ex, w, lat, err, errsz);
}

am_status am_evo_express(const am_evo_def* d, const am_palette* pal, const am_genome* g, am_evo_work* w, char* err,
                         int errsz)
{
    w->has_layers = 0;
    am_status st = am_evo_lattice(d, pal, g, &w->geno, &w->lattice, err, errsz);
    if (st != AM_OK || !g->controls) return st;
#if AM_GENO_LAYERS
    am_express_def ex = express_def(d, pal);
    st = am_genome_layers(g, &ex, &w->geno, &w->layers, err, errsz);
    w->has_layers = st == AM_OK;
    return st;
#else
    return am_genome_layers(g, NULL, &w->geno, NULL, err, errsz); /* refuses: no room for layers */
#endif
}

am_status am_evo_simulate(const am_evo_def* d, am_evo_work* w, am_record* rec, am_result* out, char* err, int errsz)
{
#if AM_GENO_LAYERS
    const am_layers* layers = w->has_layers ? &w->layers : NULL;
#else
    const am_layers* layers = NULL;
#endif
    am_status st = am_model_build_layers(&w->model, &w->lattice, &d->env, layers, err, errsz);
    if (st != AM_OK) return st;
    /* the budget at this body's period (am_evo_check_key took a period in seconds at its most) */
    int key;
    if ((st = am_evo_check_budget(d, (double)w->model.env.period_steps, &key, err, errsz)) != AM_OK) return st;
    am_eval_def ev = d->eval;
    ev.record = rec;
    am_evaluate(&w->model, &w->state, &ev, out);
    return AM_OK;
}

/* one evaluation of g on the workspace w into *r and *detail (rec may be NULL) */
static void evaluate(const am_evo_def* d, const am_palette* pal, const am_genome* g, am_evo_work* w, am_record* rec,
                     am_evo_result* r)
{
    char err[AM_ERR_MAX];
    am_evo_eval* detail = &r->detail;
    memset(r, 0, sizeof *r);
    detail->parent[0] = detail->parent[1] = -1;
    if (am_evo_express(d, pal, g, w, err, sizeof err) != AM_OK) {
        detail->sim.diverged = 1; /* cannot happen for a checked genome; never wins if it does */
        detail->sim.fitness = AM_NO_SCORE;
        return;
    }
    r->voxels = w->geno.voxels;
    /* the expressed body holds 1 + the genome's material index in each filled cell */
    const int cells = g->nx * g->ny * g->nz;
    for (int c = 0; c < cells; c++)
        if (w->geno.cell[c] > 0 && w->geno.cell[c] <= AM_MAX_GENO_MATERIALS) detail->material_voxels[w->geno.cell[c] - 1]++;
    am_status st = am_evo_simulate(d, w, rec, &detail->sim, err, sizeof err);
    if (st == AM_ERR_EMPTY) r->empty = 1; /* a valid body that goes nowhere */
    else if (st != AM_OK) {
        detail->sim.diverged = 1;
        detail->sim.fitness = AM_NO_SCORE;
    }
}

/* the individual's fields from a result (its genome is set by the caller) */
static void take_result(am_evo_ind* out, const am_evo_result* r)
{
    const am_result* sim = &r->detail.sim;
    out->fitness = sim->fitness;
    out->voxels = r->voxels;
    out->diverged = sim->diverged;
    out->empty = r->empty;
    out->steps = sim->steps;
    out->state_hash = sim->hash;
}

void am_evo_evaluate(const am_evo_def* d, const am_palette* pal, const am_genome* g, am_evo_work* w,
                     am_record* rec, am_evo_ind* out, am_evo_eval* detail)
{
    am_evo_result r;
    evaluate(d, pal, g, w, rec, &r);
    if (&out->genome != g) out->genome = *g;
    take_result(out, &r);
    if (detail) *detail = r.detail;
}

am_status am_evo_check_run(const am_evo_def* d, char* err, int errsz)
{
    am_status st = am_evo_check(d, err, errsz);
    if (st != AM_OK) return st;
    /* a body settles after at least 50 calm steps and the release window (sim_eval.c): a run whose
     * relaxation cannot hold them would score no evaluation (docs/evolve.md) */
    if (d->eval.relax_max_steps < d->eval.release_steps + 50)
        return am_fail(err, errsz, AM_ERR_RANGE,
                       "relax_max_steps = %ld leaves no room to settle: the release window (release_steps = %ld) and 50 calm steps "
                       "need %ld, and a body that does not settle gets no score",
                       d->eval.relax_max_steps, d->eval.release_steps, d->eval.release_steps + 50);
    return AM_OK;
}

am_status am_evo_init(am_evo* e, const am_evo_def* d, char* err, int errsz)
{
    am_status st = am_evo_check_run(d, err, errsz);
    if (st != AM_OK) return st;
    memset(e, 0, sizeof *e);
    e->def = *d;
    /* the genomes' evolved fields as the run's keys say (a caller may have set the keys' members alone) */
    e->def.geno.controls = am_evo_controls(d);
    am_evo_palette_into(d, &e->palette);
    am_rng_seed(&e->rng, d->seed);
    for (int i = 0; i < d->population; i++) {
        st = am_genome_init(&e->pop[i].genome, &e->def.geno, &e->rng, err, errsz);
        if (st != AM_OK) return st;
        e->pop[i].id = -1; /* not evaluated yet */
    }
    e->best.id = -1;
    e->history = AM_HASH_INIT;
    return AM_OK;
}

int am_evo_done(const am_evo* e)
{
    return e->evaluations >= e->def.evaluations;
}

/* a beats b: a valid body that is strictly further, or any valid body against a diverged one */
static int better(const am_evo_ind* a, const am_evo_ind* b)
{
    if (a->diverged) return 0;
    if (b->diverged) return 1;
    return a->fitness > b->fitness;
}

_Static_assert(AM_EVO_BATCH >= 2 && AM_EVO_BATCH % 2 == 0, "offspring come in pairs");

/* ---- crowding ---- */

/* the body of g into w->cell and its evolved fields into w->ctl (all empty when it cannot be expressed) */
static void express_body(const am_evo* e, const am_genome* g, am_geno_work* w)
{
    am_express_def ex = express_def(&e->def, &e->palette);
    char msg[AM_ERR_MAX];
    int cells = g->nx * g->ny * g->nz;
    if (am_genome_express(g, &ex, w, NULL, msg, sizeof msg) != AM_OK) {
        memset(w->cell, 0, (size_t)cells);
#if AM_GENO_LAYERS
        memset(w->ctl, 0, sizeof w->ctl);
#endif
    }
}

/* the crowding distance of body a (its fields actl) to the body just expressed in w */
static am_real distance_to(const am_evo* e, const uint8_t* a, const uint8_t* a0, const uint8_t* a1, const am_geno_work* w,
                           int cells)
{
#if AM_GENO_LAYERS
    if (e->def.geno.controls) return am_body_distance_ctl(a, a0, a1, w->cell, w->ctl[0], w->ctl[1], e->def.geno.controls, cells);
#else
    (void)e;
    (void)a0;
    (void)a1;
#endif
    return am_body_distance(a, w->cell, cells);
}

int am_evo_crowd_straight(am_real d1a, am_real d1b, am_real d2a, am_real d2b)
{
    am_real straight = d1a + d2b;
    am_real crossed = d2a + d1b;
    return straight <= crossed;
}

void am_evo_pairing(am_rng* r, int n, int* order)
{
    for (int i = 0; i < n; i++) order[i] = i;
    /* random pairs: a Fisher-Yates shuffle of the population */
    for (int i = n - 1; i > 0; i--) {
        int j = (int)am_rng_below(r, (uint32_t)(i + 1));
        int t = order[i];
        order[i] = order[j];
        order[j] = t;
    }
}

/* offspring c and c + 1 against parents a and b; e->eval[].placed says which entered */
static void crowd_pair(am_evo* e, int a, int b, int c, am_geno_work* w)
{
    am_evo_ind* p1 = &e->pop[a];
    am_evo_ind* p2 = &e->pop[b];
    am_evo_ind* c1 = &e->child[c];
    am_evo_ind* c2 = &e->child[c + 1];
    const int cells = p1->genome.nx * p1->genome.ny * p1->genome.nz;
    /* the parents' bodies kept (the first in e->body, the second in the workspace's spare body),
     * each offspring's compared with both in w->cell */
#if AM_GENO_LAYERS
    const uint8_t *p1a = e->body_ctl[0], *p1b = e->body_ctl[1], *p2a = w->other_ctl[0], *p2b = w->other_ctl[1];
#else
    const uint8_t *p1a = NULL, *p1b = NULL, *p2a = NULL, *p2b = NULL;
#endif
    express_body(e, &p1->genome, w);
    memcpy(e->body, w->cell, (size_t)cells);
#if AM_GENO_LAYERS
    if (e->def.geno.controls) memcpy(e->body_ctl, w->ctl, sizeof e->body_ctl);
#endif
    express_body(e, &p2->genome, w);
    memcpy(w->other, w->cell, (size_t)cells);
#if AM_GENO_LAYERS
    if (e->def.geno.controls) memcpy(w->other_ctl, w->ctl, sizeof w->other_ctl);
#endif
    express_body(e, &c1->genome, w);
    am_real d1a = distance_to(e, e->body, p1a, p1b, w, cells), d1b = distance_to(e, w->other, p2a, p2b, w, cells);
    express_body(e, &c2->genome, w);
    am_real d2a = distance_to(e, e->body, p1a, p1b, w, cells), d2b = distance_to(e, w->other, p2a, p2b, w, cells);
    int k1 = c, k2 = c + 1;
    if (!am_evo_crowd_straight(d1a, d1b, d2a, d2b)) {
        am_evo_ind* t = c1;
        c1 = c2;
        c2 = t;
        k1 = c + 1;
        k2 = c;
    }
    /* each offspring meets its more similar parent and replaces it when strictly better */
    e->eval[k1].placed = better(c1, p1);
    e->eval[k2].placed = better(c2, p2);
    if (e->eval[k1].placed) *p1 = *c1;
    if (e->eval[k2].placed) *p2 = *c2;
}

/* ---- statistics ---- */

static void population_stats(const am_evo* e, am_evo_stats* s)
{
    double v[AM_MAX_POPULATION];
    int n = 0;
    double sum = 0.0;
    for (int i = 0; i < e->def.population; i++) {
        if (e->pop[i].diverged || e->pop[i].fitness < 0.0) continue; /* no score: diverged, or not settled */
        double f = e->pop[i].fitness;
        int j = n++;
        while (j > 0 && v[j - 1] > f) {
            v[j] = v[j - 1];
            j--;
        }
        v[j] = f;
        sum += f;
    }
    if (n == 0) {
        s->best = s->mean = s->median = -1.0;
        return;
    }
    s->best = v[n - 1];
    s->mean = sum / (double)n;
    s->median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static uint64_t ind_hash(uint64_t h, const am_evo_ind* it)
{
    uint64_t bits;
    memcpy(&bits, &it->fitness, sizeof bits);
    h = am_hash_u64(h, am_genome_hash(&it->genome));
    h = am_hash_u64(h, bits);
    h = am_hash_u64(h, (uint64_t)it->voxels);
    h = am_hash_u64(h, (uint64_t)(it->diverged | it->empty << 1));
    h = am_hash_u64(h, (uint64_t)it->steps);
    return am_hash_u64(h, it->state_hash);
}

uint64_t am_evo_hash(const am_evo* e)
{
    uint64_t h = am_hash_u64(e->history, (uint64_t)e->evaluations);
    for (int i = 0; i < e->def.population; i++) h = ind_hash(h, &e->pop[i]);
    return h;
}

/* ---- one generation, in steps ---- */

void am_evo_gen_begin(am_evo* e, double now)
{
    const int n = e->def.population;
    e->gen_t0 = now;
    e->gen_saved = e->rng;
    e->gen_b = 0;
    e->gen_m = 0;
    e->gen_steps = e->gen_voxel_steps = 0;
    e->gen_diverged = e->gen_empty = e->gen_unsettled = 0;
    if (e->generation > 0) am_evo_pairing(&e->rng, n, e->gen_parent);
    else
        for (int i = 0; i < n; i++) e->gen_parent[i] = i;
}

/* ---- same body, same result ---- */

#if AM_GENO_LAYERS
/* scratch for packed bodies: the body looked up and one it is compared with */
#define PACKED(e) ((e)->packed[0])
#define PACKED_OTHER(e) ((e)->packed[1])
#else
_Static_assert(AM_MAX_CELLS >= 2 * AM_EVO_MEMO_BYTES, "e->body holds two packed bodies");
/* scratch for packed bodies: e->body, free outside crowding, holds the body looked up (its first
 * AM_EVO_MEMO_BYTES) and one it is compared with (the next) */
#define PACKED(e) ((e)->body)
#define PACKED_OTHER(e) ((e)->body + AM_EVO_MEMO_BYTES)
#endif
/* the bytes of a packed body of the run */
#define BODY_BYTES(e, n) am_evo_body_bytes((n), (e)->def.geno.materials, (e)->def.geno.controls)

uint64_t am_evo_body_key(const uint8_t* packed, int n, int materials, int controls)
{
    uint64_t h = am_hash_bytes(am_hash_u64(AM_HASH_INIT, (uint64_t)n), packed, (unsigned long)am_evo_body_bytes(n, materials, controls));
    return h ? h : 1;
}

/* the body of n cells in layers of `layer` cells of a run of `materials` materials, packed into out
 * (am_evo_cell_bits), lowered to the first layer: the simulator sets a body down on the floor from
 * its lowest voxel (sim_model.c), so two bodies that differ only in their height in the workspace
 * are one body to it */
static void pack_body(const am_geno_work* w, int layer, int n, int materials, int controls, uint8_t* out)
{
    const uint8_t* cell = w->cell;
    if (n < 1) return;
    int from = 0;
    while (from < n && !cell[from]) from++;
    from -= from % layer;
    memset(out, 0, (size_t)am_evo_body_bytes(n, materials, controls));
    if (materials <= 3)
        for (int c = from; c < n; c++) out[(c - from) >> 2] |= (uint8_t)((cell[c] & 3) << 2 * ((c - from) & 3));
    else
        for (int c = from; c < n; c++) out[(c - from) >> 1] |= (uint8_t)((cell[c] & 15) << 4 * ((c - from) & 1));
#if AM_GENO_LAYERS
    /* the evolved fields, a byte a cell each, lowered with the cells */
    uint8_t* at = out + am_evo_packed_bytes(n, materials);
    for (int k = 0; k < AM_GENO_CONTROLS; k++) {
        if (!(controls & (1 << k))) continue;
        memcpy(at, w->ctl[k] + from, (size_t)(n - from));
        at += n;
    }
#else
    (void)controls;
#endif
}

/* the slots the table may use now */
static int memo_slots(const am_evo* e)
{
    return e->memo_limit < 0 ? 0 : e->memo_limit > 0 && e->memo_limit < AM_EVO_MEMO ? e->memo_limit : AM_EVO_MEMO;
}

/* the slot holding the body packed in PACKED(e) (key, n cells), or -1 */
static int memo_find(const am_evo* e, uint64_t key, int n)
{
    for (int k = 0; k < AM_EVO_MEMO; k++)
        if (e->memo[k].key == key && !memcmp(e->memo[k].cells, PACKED(e), (size_t)BODY_BYTES(e, n))) return k;
    return -1;
}

/* the body packed in PACKED(e) and its result into the table: a free slot, else the one used
 * longest ago (the lowest index on a tie) among the slots it may use */
static void memo_store(am_evo* e, uint64_t key, int n, long id, const am_evo_result* r)
{
    const int slots = memo_slots(e);
    int k = -1;
    for (int i = 0; i < slots && k < 0; i++)
        if (e->memo[i].key == 0) k = i;
    if (k < 0) {
        k = 0;
        for (int i = 1; i < slots; i++)
            if (e->memo[i].used < e->memo[k].used) k = i;
    }
    am_evo_memo* m = &e->memo[k];
    m->key = key;
    m->used = id;
    const int bytes = BODY_BYTES(e, n);
    memcpy(m->cells, PACKED(e), (size_t)bytes);
    memset(m->cells + bytes, 0, sizeof m->cells - (size_t)bytes);
    m->res = *r;
    m->res.skipped = 0;
}

/* whether offspring j of the batch takes a result instead of a simulation (e->reuse[j], and its
 * body's key in e->child_key[j]): a body the table holds, or one an earlier offspring of the batch
 * has. w->cell holds its body when `expressed` (am_genome_express succeeded). Nothing of the table
 * changes here, so a cancelled batch leaves the run as it was. */
static void mark_reuse(am_evo* e, int j, int expressed, am_geno_work* w, const am_express_def* ex)
{
    const am_genome* g = &e->child[j].genome;
    const int n = g->nx * g->ny * g->nz;
    char msg[AM_ERR_MAX];
    e->reuse[j] = -1;
    e->child_key[j] = 0;
    if (!expressed || w->voxels == 0 || memo_slots(e) == 0) return;
    pack_body(w, g->nx * g->ny, n, e->def.geno.materials, e->def.geno.controls, PACKED(e));
    const uint64_t key = am_evo_body_key(PACKED(e), n, e->def.geno.materials, e->def.geno.controls);
    e->child_key[j] = key;
    int k = memo_find(e, key, n);
    if (k >= 0) {
        e->reuse[j] = k;
        return;
    }
    for (int i = 0; i < j; i++) {
        if (e->child_key[i] != key || e->reuse[i] != -1) continue;
        /* a key in common: the bodies compared cell for cell */
        if (am_genome_express(&e->child[i].genome, ex, w, NULL, msg, sizeof msg) != AM_OK) continue;
        pack_body(w, g->nx * g->ny, n, e->def.geno.materials, e->def.geno.controls, PACKED_OTHER(e));
        if (!memcmp(PACKED_OTHER(e), PACKED(e), (size_t)BODY_BYTES(e, n))) {
            e->reuse[j] = -2 - i;
            return;
        }
    }
}

am_status am_evo_batch_begin(am_evo* e, am_geno_work* w, int* m_out, char* err, int errsz)
{
    const int n = e->def.population;
    const int b = e->gen_b + e->gen_m; /* after the batch placed last */
    const int* parent = e->gen_parent;
    *m_out = 0;
    if (b >= n) return AM_OK;
    const int m = n - b < AM_EVO_BATCH ? n - b : AM_EVO_BATCH;
    if (e->generation == 0) {
        /* the initial population: evaluated as it is */
        for (int j = 0; j < m; j++) e->child[j] = e->pop[b + j];
    } else {
        for (int k = 0; k + 1 < m; k += 2) {
            am_evo_ind* c1 = &e->child[k];
            am_evo_ind* c2 = &e->child[k + 1];
            am_status st = am_genome_crossover(&e->pop[parent[b + k]].genome, &e->pop[parent[b + k + 1]].genome, &c1->genome,
                                               &c2->genome, &e->def.geno, &e->rng, err, errsz);
            if (st != AM_OK) {
                e->rng = e->gen_saved; /* the shapes of a run's genomes never differ: not after a placed batch */
                return st;
            }
            am_genome_mutate(&c1->genome, &e->def.geno, &e->rng);
            am_genome_mutate(&c2->genome, &e->def.geno, &e->rng);
        }
    }
    /* the evaluation order: most voxels first (they take longest), ties by index; the order
     * changes speed, never results */
    int voxels[AM_EVO_BATCH];
    am_express_def ex = express_def(&e->def, &e->palette);
    char msg[AM_ERR_MAX];
    for (int i = 0; i < m; i++) {
        e->order[i] = i;
        const int expressed = am_genome_express(&e->child[i].genome, &ex, w, NULL, msg, sizeof msg) == AM_OK;
        voxels[i] = expressed ? w->voxels : 0;
        mark_reuse(e, i, expressed, w, &ex);
        if (e->reuse[i] != -1) voxels[i] = 0; /* not simulated: last in the order */
    }
    for (int i = 1; i < m; i++) {
        int k = e->order[i], j = i;
        while (j > 0 && voxels[e->order[j - 1]] < voxels[k]) {
            e->order[j] = e->order[j - 1];
            j--;
        }
        e->order[j] = k;
    }
    for (int i = 0; i < m; i++) e->order_voxels[i] = voxels[e->order[i]];
    e->gen_b = b;
    e->gen_m = m;
    *m_out = m;
    return AM_OK;
}

void am_evo_batch_eval(const am_evo* e, int i, am_evo_work* w, am_evo_result* r)
{
    const int j = e->order[i];
    if (e->reuse[j] != -1) {
        memset(r, 0, sizeof *r); /* its result is taken in am_evo_batch_end */
        return;
    }
    evaluate(&e->def, &e->palette, &e->child[j].genome, w, NULL, r);
}

int am_evo_batch_cancellable(const am_evo* e)
{
    return e->gen_b == 0;
}

am_status am_evo_batch_end(am_evo* e, const am_evo_result* res, am_geno_work* w, const am_evo_hooks* hooks, char* err, int errsz)
{
    const int b = e->gen_b, m = e->gen_m;
    const int* parent = e->gen_parent;
    for (int i = 0; i < m; i++)
        if (res[i].skipped) {
            if (b != 0) return am_fail(err, errsz, AM_ERR_ARG, "evaluation skipped after a placed batch");
            e->rng = e->gen_saved; /* nothing of the run has changed: the generation is abandoned */
            e->gen_m = 0;
            return am_fail(err, errsz, AM_ERR_CANCELLED, "interrupted");
        }
    int item[AM_EVO_BATCH]; /* offspring j is map item item[j] */
    for (int i = 0; i < m; i++) item[e->order[i]] = i;
    for (int j = 0; j < m; j++) {
        /* a remembered body's result, an earlier offspring's of the same body, or its own */
        const int k = e->reuse[j];
        const am_evo_result* r = k >= 0 ? &e->memo[k].res : k <= -2 ? &res[item[-2 - k]] : &res[item[j]];
        take_result(&e->child[j], r);
        e->eval[j] = r->detail;
    }
    for (int j = 0; j < m; j++) {
        am_evo_ind* c = &e->child[j];
        c->id = e->evaluations + b + j;
        if (e->reuse[j] != -1) {
            e->reused++;
            e->reused_voxel_steps += (double)c->steps * (double)c->voxels;
        }
        e->history = ind_hash(e->history, c);
        e->gen_diverged += c->diverged;
        e->gen_empty += c->empty;
        e->gen_unsettled += !c->diverged && !c->empty && !e->eval[j].sim.settled;
        if (e->reuse[j] == -1) { /* simulated */
            e->gen_steps += c->steps;
            e->gen_voxel_steps += c->steps * c->voxels;
        }
        if (!e->has_best || better(c, &e->best)) {
            e->best = *c;
            e->has_best = 1;
        }
    }
    for (int j = 0; j < m; j++) {
        am_evo_eval* ev = &e->eval[j];
        ev->generation = e->generation;
        ev->parent[0] = e->generation == 0 ? -1 : e->pop[parent[b + (j & ~1)]].id;
        ev->parent[1] = e->generation == 0 ? -1 : e->pop[parent[b + (j | 1)]].id;
        ev->placed = 1; /* generation 0; crowding decides for the others */
    }
    /* the table: the remembered bodies taken now count as used now, then the simulated bodies go in */
    for (int j = 0; j < m; j++)
        if (e->reuse[j] >= 0) e->memo[e->reuse[j]].used = e->child[j].id;
    am_express_def ex = express_def(&e->def, &e->palette);
    char msg[AM_ERR_MAX];
    for (int j = 0; j < m; j++) {
        const am_genome* g = &e->child[j].genome;
        const int n = g->nx * g->ny * g->nz;
        if (e->reuse[j] != -1 || e->child_key[j] == 0 || am_genome_express(g, &ex, w, NULL, msg, sizeof msg) != AM_OK) continue;
        pack_body(w, g->nx * g->ny, n, e->def.geno.materials, e->def.geno.controls, PACKED(e));
        memo_store(e, e->child_key[j], n, e->child[j].id, &res[item[j]]);
    }
    if (e->generation == 0) {
        for (int j = 0; j < m; j++) e->pop[b + j] = e->child[j];
    } else {
        for (int k = 0; k + 1 < m; k += 2) crowd_pair(e, parent[b + k], parent[b + k + 1], k, w);
    }
    if (hooks && hooks->evaluated)
        for (int j = 0; j < m; j++) hooks->evaluated(hooks->ctx, &e->child[j], &e->eval[j]);
    return AM_OK;
}

void am_evo_gen_end(am_evo* e, double now)
{
    am_evo_stats s;
    memset(&s, 0, sizeof s);
    e->evaluations += e->def.population;
    s.generation = e->generation;
    s.evaluations = e->evaluations;
    s.diverged = e->gen_diverged;
    s.empty = e->gen_empty;
    s.unsettled = e->gen_unsettled;
    population_stats(e, &s);
    s.wall_s = now - e->gen_t0;
    e->last = s;
    e->last_steps = e->gen_steps;
    e->last_voxel_steps = e->gen_voxel_steps;
    e->generation++;
    e->gen_b = e->gen_m = 0;
}

/* ---- generations: one run, or several in lockstep ---- */

typedef struct eval_job {
    am_evo* const* runs;
    am_evo_wave* wave;                         /* NULL: one run, map item i its item i, results in its res */
    am_evo_work* work;
    const am_evo_hooks* cancel[AM_EVO_WAVE_MAX]; /* run k's hooks when its batch may be cancelled, else NULL */
} eval_job;

static void eval_task(void* ctx, int item, int worker)
{
    eval_job* job = (eval_job*)ctx;
    const int k = job->wave ? job->wave->run[item] : 0, i = job->wave ? job->wave->idx[item] : item;
    am_evo_result* r = job->wave ? &job->wave->res[item] : &job->runs[0]->res[item];
    const am_evo_hooks* h = job->cancel[k];
    if (h && h->cancel(h->ctx)) {
        memset(r, 0, sizeof *r);
        r->skipped = 1;
        return;
    }
    am_evo_batch_eval(job->runs[k], i, &job->work[worker], r);
}

/* the executor's clock, or 0 */
static double clock_of(const am_executor* ex) { return ex && ex->now ? ex->now(ex->self) : 0.0; }

/* the executor's map, or every item in order on this thread */
static am_status map_items(const am_executor* ex, int n, int workers, am_task_fn task, void* ctx, void* out, long size, char* err,
                           int errsz)
{
    if (ex && ex->map) return ex->map(ex->self, n, workers, task, ctx, out, size, err, errsz);
    for (int i = 0; i < n; i++) task(ctx, i, 0);
    return AM_OK;
}

/* the generations of runs[0..n) (all of them, or the unfinished ones when skip_done) */
static am_status generations(am_evo* const* runs, int n, am_evo_wave* wave, am_evo_work* w, const am_executor* ex,
                             const am_evo_hooks* hooks, int skip_done, char* err, int errsz)
{
    int workers = ex && ex->map ? ex->workers : 1;
    if (n < 1 || n > AM_EVO_WAVE_MAX || (n > 1 && !wave))
        return am_fail(err, errsz, AM_ERR_ARG, "%d runs in lockstep (1 to %d, several need a wave)", n, AM_EVO_WAVE_MAX);
    if (workers < 1) workers = 1;
    if (workers > AM_MAX_WORKERS) workers = AM_MAX_WORKERS;
    int live[AM_EVO_WAVE_MAX], m[AM_EVO_WAVE_MAX], cancelled = 0;
    for (int k = 0; k < n; k++) {
        live[k] = !(skip_done && am_evo_done(runs[k]));
        if (live[k]) am_evo_gen_begin(runs[k], clock_of(ex));
    }
    eval_job job = {runs, wave, w, {NULL}};
    for (;;) {
        /* every live run's next batch, merged into one map: most voxels first, ties in run order */
        int total = 0;
        for (int k = 0; k < n; k++) {
            m[k] = 0;
            if (!live[k]) continue;
            am_status st = am_evo_batch_begin(runs[k], &w[0].geno, &m[k], err, errsz);
            if (st != AM_OK) return st;
            job.cancel[k] = hooks && hooks[k].cancel && am_evo_batch_cancellable(runs[k]) ? &hooks[k] : NULL;
            for (int i = 0; wave && i < m[k]; i++) {
                int j = total + i, v = runs[k]->order_voxels[i];
                while (j > 0 && runs[wave->run[j - 1]]->order_voxels[wave->idx[j - 1]] < v) {
                    wave->run[j] = wave->run[j - 1];
                    wave->idx[j] = wave->idx[j - 1];
                    j--;
                }
                wave->run[j] = k;
                wave->idx[j] = i;
            }
            total += m[k];
        }
        if (total == 0) break;
        void* out = wave ? (void*)wave->res : (void*)runs[0]->res;
        am_status st = map_items(ex, total, workers, eval_task, &job, out, (long)sizeof(am_evo_result), err, errsz);
        if (st != AM_OK) {
            for (int k = 0; k < n; k++)
                if (live[k]) runs[k]->rng = runs[k]->gen_saved;
            return st;
        }
        for (int j = 0; wave && j < total; j++) runs[wave->run[j]]->res[wave->idx[j]] = wave->res[j];
        for (int k = 0; k < n; k++) {
            if (m[k] == 0) continue;
            st = am_evo_batch_end(runs[k], runs[k]->res, &w[0].geno, hooks ? &hooks[k] : NULL, err, errsz);
            if (st == AM_ERR_CANCELLED) {
                live[k] = 0; /* abandoned: the run is as before the generation */
                cancelled = 1;
            } else if (st != AM_OK) return st;
        }
    }
    for (int k = 0; k < n; k++)
        if (live[k]) am_evo_gen_end(runs[k], clock_of(ex));
    return cancelled ? am_fail(err, errsz, AM_ERR_CANCELLED, "interrupted") : AM_OK;
}

am_status am_evo_generations(am_evo* const* runs, int n, am_evo_wave* wave, am_evo_work* w, const am_executor* ex,
                             const am_evo_hooks* hooks, char* err, int errsz)
{
    return generations(runs, n, wave, w, ex, hooks, 1, err, errsz);
}

am_status am_evo_generation(am_evo* e, am_evo_work* w, const am_executor* ex, const am_evo_hooks* hooks, char* err, int errsz)
{
    am_evo* const runs[1] = {e};
    return generations(runs, 1, NULL, w, ex, hooks, 0, err, errsz);
}
