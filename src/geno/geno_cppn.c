/* The CPPN representation (Stanley 2007, as the seed lays it out): m layers of n nodes.
 *
 * Inputs are the cell centre x, y, z (scaled so the longest workspace side spans [-1, 1], the same
 * scale on every axis) and a bias of 1; they feed layer 0. Layer l + 1 is fed by layer l (up to
 * (m-1) n^2 connections); each material's density is a weighted sum of the last layer. Every
 * connection has a weight and an active flag; an inactive one contributes nothing. Node (l, j)
 * computes  out = yscale f(xscale (in - offset)),  in = sum of its active weighted inputs, with f
 * one of sigmoid, Gaussian, sine, absolute value, linear: the seed's "function type, offset and
 * scaling along the x axis, scaling along the y axis".
 *
 * Complexity measure: a bound R on how fast each node's argument t = xscale (in - offset) can
 * change across space (the 1-norm of its gradient, propagated through the layers with each
 * function's Lipschitz constant). Where R exceeds pi/2 per cell, the node's x scaling is reduced
 * at expression time to bring it to pi/2: t then changes by at most pi/2 between any two
 * neighbouring cells (face, edge or corner), a sine keeps a period of at least 4 cells (half the
 * voxel grid's Nyquist frequency) and no feature shrinks below a voxel. The genome itself keeps
 * the scalings it evolved (am_cppn_effective_xscale reports the limited ones).
 *
 * Mutation: every value (function type, offset, x and y scaling of each node; weight and active
 * flag of each connection) changes independently with probability def->cppn_changes / values,
 * so one value changes on average: a real by a uniform step of at most def->cppn_step (10%) of
 * its range, reflected into the range; a function type to another one; a flag is toggled.
 *
 * Crossover: a rectangle of nodes (a run of layers x a run of positions) comes from the second
 * parent, the rest from the first. Along each axis of size n the run has a length L uniform in
 * 1..n and a start uniform in -(L-1)..n-1, clipped to the axis: every index is then covered by
 * exactly L of the n + L - 1 starts, so every node is equally likely to be in the region
 * (uniform starts in 0..n-L would favour the centre). A node carries its function, parameters
 * and incoming connections; nodes of the last layer also carry their connections to the outputs.
 */
#include "geno_internal.h"

#include <string.h>

static const char* const fn_names[AM_FN_COUNT] = {"sigmoid", "gauss", "sine", "abs", "linear"};
/* Lipschitz constants of the functions: |f'| <= lip (gauss: 2 sqrt(2) e^(-1/2)) */
static const am_real fn_lip[AM_FN_COUNT] = {AM_R(0.5), AM_R(1.7155277699214135), AM_R(1), AM_R(1), AM_R(1)};

static int cppn_values(const am_genome* g)
{
    const int L = g->cppn.layers, n = g->cppn.nodes;
    return 4 * L * n + 2 * (4 * n + (L - 1) * n * n + am_genome_fields(g) * n);
}

static am_status cppn_check(const am_genome* g, char* err, int errsz)
{
    const am_cppn_genome* c = &g->cppn;
    if (c->layers > AM_MAX_CPPN_LAYERS || c->nodes > AM_MAX_CPPN_NODES)
        return am_fail(err, errsz, AM_ERR_CAPACITY, "CPPN of %d x %d nodes exceeds the %s profile's %d x %d",
                       c->layers, c->nodes, AM_PROFILE_NAME, AM_MAX_CPPN_LAYERS, AM_MAX_CPPN_NODES);
    if (c->layers < 1 || c->nodes < 1)
        return am_fail(err, errsz, AM_ERR_RANGE, "CPPN of %d x %d nodes: needs at least 1 x 1", c->layers, c->nodes);
    for (int l = 0; l < c->layers; l++)
        for (int j = 0; j < c->nodes; j++) {
            const am_cppn_node* nd = &c->node[l][j];
            if (nd->fn >= AM_FN_COUNT || !(am_fabs(nd->offset) <= AM_CPPN_OFFSET_MAX) ||
                !(am_fabs(nd->xscale) <= AM_CPPN_XSCALE_MAX) || !(am_fabs(nd->yscale) <= AM_CPPN_YSCALE_MAX))
                return am_fail(err, errsz, AM_ERR_RANGE, "CPPN node %d %d has a value out of range", l, j);
        }
    for (int j = 0; j < c->nodes; j++)
        for (int i = 0; i < 4; i++)
            if (!(am_fabs(c->w_in[j][i]) <= AM_CPPN_WEIGHT_MAX) || c->on_in[j][i] > 1)
                return am_fail(err, errsz, AM_ERR_RANGE, "CPPN input connection %d %d out of range", j, i);
    for (int l = 0; l + 1 < c->layers; l++)
        for (int j = 0; j < c->nodes; j++)
            for (int i = 0; i < c->nodes; i++)
                if (!(am_fabs(c->w[l][j][i]) <= AM_CPPN_WEIGHT_MAX) || c->on[l][j][i] > 1)
                    return am_fail(err, errsz, AM_ERR_RANGE, "CPPN connection %d %d %d out of range", l + 1, j, i);
    for (int m = 0; m < am_genome_fields(g); m++)
        for (int j = 0; j < c->nodes; j++)
            if (!(am_fabs(c->w_out[m][j]) <= AM_CPPN_WEIGHT_MAX) || c->on_out[m][j] > 1)
                return am_fail(err, errsz, AM_ERR_RANGE, "CPPN output connection %d %d out of range", m, j);
    return AM_OK;
}

/* ---- init and mutation walk every value in the same fixed order ---- */

typedef struct walk {
    am_rng* r;
    int init;          /* 1: draw fresh values; 0: mutate */
    am_real p;         /* mutation: per-value probability */
    am_real step;      /* mutation: fraction of the range */
    am_real active;    /* init: probability of an active connection */
} walk;

static am_real walk_real(walk* k, am_real v, am_real max)
{
    if (k->init) return am_rng_range(k->r, -max, max);
    if (!am_rng_chance(k->r, k->p)) return v;
    return am_geno_perturb(k->r, v, AM_MUL(k->step, AM_MUL(AM_R(2), max)), -max, max);
}

static void walk_node(walk* k, am_cppn_node* nd)
{
    if (k->init) nd->fn = (uint8_t)am_rng_below(k->r, AM_FN_COUNT);
    else if (am_rng_chance(k->r, k->p)) nd->fn = (uint8_t)((nd->fn + 1 + am_rng_below(k->r, AM_FN_COUNT - 1)) % AM_FN_COUNT);
    nd->offset = walk_real(k, nd->offset, AM_CPPN_OFFSET_MAX);
    nd->xscale = walk_real(k, nd->xscale, AM_CPPN_XSCALE_MAX);
    nd->yscale = walk_real(k, nd->yscale, AM_CPPN_YSCALE_MAX);
}

static void walk_conn(walk* k, am_real* w, uint8_t* on)
{
    *w = walk_real(k, *w, AM_CPPN_WEIGHT_MAX);
    if (k->init) *on = (uint8_t)am_rng_chance(k->r, k->active);
    else if (am_rng_chance(k->r, k->p)) *on = (uint8_t)!*on;
}

static void walk_all(am_genome* g, walk* k)
{
    am_cppn_genome* c = &g->cppn;
    const int L = c->layers, n = c->nodes;
    for (int l = 0; l < L; l++)
        for (int j = 0; j < n; j++) walk_node(k, &c->node[l][j]);
    for (int j = 0; j < n; j++)
        for (int i = 0; i < 4; i++) walk_conn(k, &c->w_in[j][i], &c->on_in[j][i]);
    for (int l = 0; l + 1 < L; l++)
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) walk_conn(k, &c->w[l][j][i], &c->on[l][j][i]);
    for (int m = 0; m < am_genome_fields(g); m++)
        for (int j = 0; j < n; j++) walk_conn(k, &c->w_out[m][j], &c->on_out[m][j]);
}

static am_status cppn_init(am_genome* g, const am_geno_def* def, am_rng* r, char* err, int errsz)
{
    g->cppn.layers = def->cppn_layers;
    g->cppn.nodes = def->cppn_nodes;
    if (def->cppn_layers > AM_MAX_CPPN_LAYERS || def->cppn_nodes > AM_MAX_CPPN_NODES)
        return am_fail(err, errsz, AM_ERR_CAPACITY, "CPPN of %d x %d nodes exceeds the %s profile's %d x %d",
                       def->cppn_layers, def->cppn_nodes, AM_PROFILE_NAME, AM_MAX_CPPN_LAYERS, AM_MAX_CPPN_NODES);
    if (def->cppn_layers < 1 || def->cppn_nodes < 1)
        return am_fail(err, errsz, AM_ERR_RANGE, "CPPN of %d x %d nodes: needs at least 1 x 1", def->cppn_layers, def->cppn_nodes);
    walk k = {r, 1, AM_R(0), AM_R(0), def->cppn_active};
    walk_all(g, &k);
    return AM_OK;
}

static void cppn_mutate(am_genome* g, const am_geno_def* def, am_rng* r)
{
    walk k = {r, 0, AM_DIV_INT(def->cppn_changes, cppn_values(g)), def->cppn_step, AM_R(0)};
    walk_all(g, &k);
}

/* ---- crossover ---- */

/* a run of an axis of n: length uniform in 1..n, start uniform in -(len-1)..n-1, clipped */
static void random_run(am_rng* r, int n, int* lo, int* hi)
{
    int len = 1 + (int)am_rng_below(r, (uint32_t)n);
    int s = (int)am_rng_below(r, (uint32_t)(n + len - 1)) - (len - 1);
    *lo = s < 0 ? 0 : s;
    *hi = s + len > n ? n : s + len;
}

void am_cppn_random_region(const am_genome* g, am_rng* r, int* l0, int* l1, int* j0, int* j1)
{
    random_run(r, g->cppn.layers, l0, l1);
    random_run(r, g->cppn.nodes, j0, j1);
}

/* node (l, j) of dst, with its incoming (and, in the last layer, outgoing) connections, from src */
static void take_node(am_genome* dst, const am_genome* src, int l, int j)
{
    am_cppn_genome* d = &dst->cppn;
    const am_cppn_genome* s = &src->cppn;
    d->node[l][j] = s->node[l][j];
    if (l == 0) {
        for (int i = 0; i < 4; i++) {
            d->w_in[j][i] = s->w_in[j][i];
            d->on_in[j][i] = s->on_in[j][i];
        }
    } else {
        for (int i = 0; i < s->nodes; i++) {
            d->w[l - 1][j][i] = s->w[l - 1][j][i];
            d->on[l - 1][j][i] = s->on[l - 1][j][i];
        }
    }
    if (l == s->layers - 1)
        for (int m = 0; m < am_genome_fields(src); m++) {
            d->w_out[m][j] = s->w_out[m][j];
            d->on_out[m][j] = s->on_out[m][j];
        }
}

static void cppn_crossover(const am_genome* a, const am_genome* b, am_genome* c1, am_genome* c2,
                           const am_geno_def* def, am_rng* r)
{
    (void)def;
    int l0, l1, j0, j1;
    am_cppn_random_region(a, r, &l0, &l1, &j0, &j1);
    *c1 = *a;
    if (c2) *c2 = *b;
    for (int l = l0; l < l1; l++)
        for (int j = j0; j < j1; j++) {
            take_node(c1, b, l, j);
            if (c2) take_node(c2, a, l, j);
        }
}

static int cppn_same_shape(const am_genome* a, const am_genome* b)
{
    return a->cppn.layers == b->cppn.layers && a->cppn.nodes == b->cppn.nodes;
}

/* ---- hash and equality, in the order of the text format ---- */

static uint64_t cppn_hash(uint64_t h, const am_genome* g)
{
    const am_cppn_genome* c = &g->cppn;
    h = am_hash_u64(h, (uint64_t)c->layers);
    h = am_hash_u64(h, (uint64_t)c->nodes);
    for (int l = 0; l < c->layers; l++)
        for (int j = 0; j < c->nodes; j++) {
            h = am_hash_u64(h, c->node[l][j].fn);
            h = am_hash_real(h, c->node[l][j].offset);
            h = am_hash_real(h, c->node[l][j].xscale);
            h = am_hash_real(h, c->node[l][j].yscale);
        }
    for (int j = 0; j < c->nodes; j++)
        for (int i = 0; i < 4; i++) h = am_hash_real(am_hash_u64(h, c->on_in[j][i]), c->w_in[j][i]);
    for (int l = 0; l + 1 < c->layers; l++)
        for (int j = 0; j < c->nodes; j++)
            for (int i = 0; i < c->nodes; i++) h = am_hash_real(am_hash_u64(h, c->on[l][j][i]), c->w[l][j][i]);
    for (int m = 0; m < am_genome_fields(g); m++)
        for (int j = 0; j < c->nodes; j++) h = am_hash_real(am_hash_u64(h, c->on_out[m][j]), c->w_out[m][j]);
    return h;
}

static int same_real(am_real a, am_real b) { return memcmp(&a, &b, sizeof a) == 0; }

static int cppn_equal(const am_genome* a, const am_genome* b)
{
    const am_cppn_genome* x = &a->cppn;
    const am_cppn_genome* y = &b->cppn;
    if (!cppn_same_shape(a, b)) return 0;
    for (int l = 0; l < x->layers; l++)
        for (int j = 0; j < x->nodes; j++) {
            const am_cppn_node* p = &x->node[l][j];
            const am_cppn_node* q = &y->node[l][j];
            if (p->fn != q->fn || !same_real(p->offset, q->offset) || !same_real(p->xscale, q->xscale) ||
                !same_real(p->yscale, q->yscale))
                return 0;
        }
    for (int j = 0; j < x->nodes; j++)
        for (int i = 0; i < 4; i++)
            if (x->on_in[j][i] != y->on_in[j][i] || !same_real(x->w_in[j][i], y->w_in[j][i])) return 0;
    for (int l = 0; l + 1 < x->layers; l++)
        for (int j = 0; j < x->nodes; j++)
            for (int i = 0; i < x->nodes; i++)
                if (x->on[l][j][i] != y->on[l][j][i] || !same_real(x->w[l][j][i], y->w[l][j][i])) return 0;
    for (int m = 0; m < am_genome_fields(a); m++)
        for (int j = 0; j < x->nodes; j++)
            if (x->on_out[m][j] != y->on_out[m][j] || !same_real(x->w_out[m][j], y->w_out[m][j])) return 0;
    return 1;
}

/* ---- expression ---- */

int am_cppn_effective_xscale(const am_genome* g, am_real eff[AM_MAX_CPPN_LAYERS][AM_MAX_CPPN_NODES])
{
    const am_cppn_genome* c = &g->cppn;
    int nmax = g->nx > g->ny ? g->nx : g->ny;
    if (g->nz > nmax) nmax = g->nz;
    /* the cell spacing is h = 2 / (nmax - 1); the limit is R h <= pi/2 */
    const am_real rmax = nmax > 1 ? AM_DIV(AM_MUL(AM_PI, AM_INT(nmax - 1)), AM_R(4)) : AM_REAL_MAX;
    am_real grad[2][AM_MAX_CPPN_NODES]; /* bound on the 1-norm of each node output's gradient */
    int limited = 0;
    for (int l = 0; l < c->layers; l++) {
        am_real* out = grad[l & 1];
        const am_real* prev = grad[(l + 1) & 1];
        for (int j = 0; j < c->nodes; j++) {
            const am_cppn_node* nd = &c->node[l][j];
            am_real s = AM_R(0);
            if (l == 0) {
                for (int i = 0; i < 3; i++) /* x, y, z each have gradient 1-norm 1; the bias 0 */
                    if (c->on_in[j][i]) s += am_fabs(c->w_in[j][i]);
            } else {
                for (int i = 0; i < c->nodes; i++)
                    if (c->on[l - 1][j][i]) s += AM_MUL(am_fabs(c->w[l - 1][j][i]), prev[i]);
            }
            am_real rate = AM_MUL(am_fabs(nd->xscale), s);
            eff[l][j] = nd->xscale;
            if (rate > rmax) {
                eff[l][j] = AM_MUL(nd->xscale, AM_DIV(rmax, rate));
                rate = rmax;
                limited++;
            }
            out[j] = AM_MUL(AM_MUL(am_fabs(nd->yscale), fn_lip[nd->fn < AM_FN_COUNT ? nd->fn : 0]), rate);
        }
    }
    return limited;
}

/* acc[i] <- yscale f(xs (acc[i] - offset)) for one node over a chunk */
static void apply(const am_geno_work* w, const am_cppn_node* nd, am_real xs, am_real* acc, int cnt)
{
    const am_real off = nd->offset, ys = nd->yscale;
    switch (nd->fn) {
    case AM_FN_SIGMOID:
        for (int i = 0; i < cnt; i++) acc[i] = AM_MUL(ys, am_geno_sigmoid(w, AM_MUL(xs, acc[i] - off)));
        break;
    case AM_FN_GAUSS:
        for (int i = 0; i < cnt; i++) {
            am_real t = AM_MUL(xs, acc[i] - off);
            acc[i] = AM_MUL(ys, AM_MUL(AM_R(2), AM_GENO_GAUSS_SQ(w, t)) - AM_R(1));
        }
        break;
    case AM_FN_SINE:
        for (int i = 0; i < cnt; i++) acc[i] = AM_MUL(ys, am_geno_sin(w, AM_MUL(xs, acc[i] - off)));
        break;
    case AM_FN_ABS:
        for (int i = 0; i < cnt; i++) acc[i] = AM_MUL(ys, am_fabs(AM_MUL(xs, acc[i] - off)));
        break;
    default:
        for (int i = 0; i < cnt; i++) acc[i] = AM_MUL(ys, AM_MUL(xs, acc[i] - off));
        break;
    }
}

static void cppn_express(const am_genome* g, am_geno_work* w)
{
    const am_cppn_genome* c = &g->cppn;
    const int nx = g->nx, ny = g->ny, nz = g->nz, cells = nx * ny * nz, L = c->layers, n = c->nodes;
    am_real eff[AM_MAX_CPPN_LAYERS][AM_MAX_CPPN_NODES];
    am_real axis[3][AM_MAX_DIM];
    const int dims[3] = {nx, ny, nz};
    int nmax = nx > ny ? nx : ny;
    if (nz > nmax) nmax = nz;
    am_cppn_effective_xscale(g, eff);
    /* cell centres: the longest side spans [-1, 1], every axis centred */
    for (int a = 0; a < 3; a++)
        for (int i = 0; i < dims[a]; i++)
            axis[a][i] = nmax > 1 ? AM_DIV(AM_INT(2 * i - (dims[a] - 1)), AM_INT(nmax - 1)) : AM_R(0);
    int x = 0, y = 0, z = 0;
    for (int c0 = 0; c0 < cells; c0 += AM_CPPN_CHUNK) {
        const int cnt = cells - c0 < AM_CPPN_CHUNK ? cells - c0 : AM_CPPN_CHUNK;
        for (int i = 0; i < cnt; i++) {
            w->scratch.cppn.coord[0][i] = axis[0][x];
            w->scratch.cppn.coord[1][i] = axis[1][y];
            w->scratch.cppn.coord[2][i] = axis[2][z];
            if (++x == nx) {
                x = 0;
                if (++y == ny) {
                    y = 0;
                    z++;
                }
            }
        }
        for (int l = 0; l < L; l++) {
            am_real(*in)[AM_CPPN_CHUNK] = w->scratch.cppn.act[(l + 1) & 1];
            am_real(*out)[AM_CPPN_CHUNK] = w->scratch.cppn.act[l & 1];
            for (int j = 0; j < n; j++) {
                am_real* acc = out[j];
                for (int i = 0; i < cnt; i++) acc[i] = AM_R(0);
                if (l == 0) {
                    for (int s = 0; s < 3; s++)
                        if (c->on_in[j][s]) {
                            const am_real wv = c->w_in[j][s];
                            const am_real* src = w->scratch.cppn.coord[s];
                            for (int i = 0; i < cnt; i++) acc[i] += AM_MUL(wv, src[i]);
                        }
                    if (c->on_in[j][3]) {
                        const am_real wv = c->w_in[j][3];
                        for (int i = 0; i < cnt; i++) acc[i] += wv;
                    }
                } else {
                    for (int s = 0; s < n; s++)
                        if (c->on[l - 1][j][s]) {
                            const am_real wv = c->w[l - 1][j][s];
                            const am_real* src = in[s];
                            for (int i = 0; i < cnt; i++) acc[i] += AM_MUL(wv, src[i]);
                        }
                }
                apply(w, &c->node[l][j], eff[l][j], acc, cnt);
            }
        }
        am_real(*last)[AM_CPPN_CHUNK] = w->scratch.cppn.act[(L - 1) & 1];
        for (int m = 0; m < am_genome_fields(g); m++) {
            am_real* d = w->dens[m] + c0;
            for (int i = 0; i < cnt; i++) d[i] = AM_R(0);
            for (int j = 0; j < n; j++)
                if (c->on_out[m][j]) {
                    const am_real wv = c->w_out[m][j];
                    for (int i = 0; i < cnt; i++) d[i] += AM_MUL(wv, last[j][i]);
                }
        }
    }
    am_geno_controls_of_fields(g, w);
}

/* ---- text ---- */

static void put_conn(am_text* s, uint8_t on, am_real w)
{
    am_text_put(s, " %d", on);
    am_geno_put_real(s, w);
}

static void cppn_format(const am_genome* g, am_text* s)
{
    const am_cppn_genome* c = &g->cppn;
    am_text_put(s, "cppn %d %d\n", c->layers, c->nodes);
    am_text_put(s, "# node LAYER J FUNCTION OFFSET XSCALE YSCALE\n");
    for (int l = 0; l < c->layers; l++)
        for (int j = 0; j < c->nodes; j++) {
            const am_cppn_node* nd = &c->node[l][j];
            am_text_put(s, "node %d %d %s", l, j, fn_names[nd->fn < AM_FN_COUNT ? nd->fn : 0]);
            am_geno_put_real(s, nd->offset);
            am_geno_put_real(s, nd->xscale);
            am_geno_put_real(s, nd->yscale);
            am_text_put(s, "\n");
        }
    am_text_put(s, "# in J: ACTIVE WEIGHT pairs from x, y, z, bias into node 0 J\n"
                   "# link LAYER J: ACTIVE WEIGHT pairs from each node of LAYER-1 into node LAYER J\n"
                   "# out MATERIAL: ACTIVE WEIGHT pairs from each node of the last layer\n");
    for (int j = 0; j < c->nodes; j++) {
        am_text_put(s, "in %d", j);
        for (int i = 0; i < 4; i++) put_conn(s, c->on_in[j][i], c->w_in[j][i]);
        am_text_put(s, "\n");
    }
    for (int l = 0; l + 1 < c->layers; l++)
        for (int j = 0; j < c->nodes; j++) {
            am_text_put(s, "link %d %d", l + 1, j);
            for (int i = 0; i < c->nodes; i++) put_conn(s, c->on[l][j][i], c->w[l][j][i]);
            am_text_put(s, "\n");
        }
    for (int m = 0; m < am_genome_fields(g); m++) {
        am_text_put(s, "out %d", m);
        for (int j = 0; j < c->nodes; j++) put_conn(s, c->on_out[m][j], c->w_out[m][j]);
        am_text_put(s, "\n");
    }
}

/* reads count (flag, weight) pairs from tok */
static am_status parse_conns(char** tok, int count, am_real* w, int wstride, uint8_t* on, int onstride, char* err, int errsz)
{
    char q1[AM_QUOTE_BUF];
    for (int i = 0; i < count; i++) {
        int f = 0;
        if (!am_geno_tok_int(tok[2 * i], 0, 1, &f))
            return am_fail(err, errsz, AM_ERR_PARSE, "active flag '%s' is not 0 or 1", am_quote(q1, sizeof q1, tok[2 * i], -1));
        if (!am_geno_tok_real(tok[2 * i + 1], -AM_CPPN_WEIGHT_MAX, AM_CPPN_WEIGHT_MAX, &w[i * wstride]))
            return am_fail(err, errsz, AM_ERR_RANGE, "weight '%s' is not a number in [-2, 2]",
                           am_quote(q1, sizeof q1, tok[2 * i + 1], -1));
        on[i * onstride] = (uint8_t)f;
    }
    return AM_OK;
}

static am_status cppn_parse_line(am_genome* g, am_geno_parse* ps, int ntok, char** tok, char* err, int errsz)
{
    am_cppn_genome* c = &g->cppn;
    char q1[AM_QUOTE_BUF], q2[AM_QUOTE_BUF];
    if (!ps->shape) {
        int L = 0, n = 0;
        if (strcmp(tok[0], "cppn") != 0 || ntok != 3)
            return am_fail(err, errsz, AM_ERR_PARSE, "expected 'cppn LAYERS NODES'");
        if (!am_geno_tok_int(tok[1], 1, 1000000, &L) || !am_geno_tok_int(tok[2], 1, 1000000, &n))
            return am_fail(err, errsz, AM_ERR_PARSE, "CPPN size '%s %s' is not two positive integers",
                           am_quote(q1, sizeof q1, tok[1], -1), am_quote(q2, sizeof q2, tok[2], -1));
        if (L > AM_MAX_CPPN_LAYERS || n > AM_MAX_CPPN_NODES)
            return am_fail(err, errsz, AM_ERR_CAPACITY, "CPPN of %d x %d nodes exceeds the %s profile's %d x %d", L, n,
                           AM_PROFILE_NAME, AM_MAX_CPPN_LAYERS, AM_MAX_CPPN_NODES);
        c->layers = L;
        c->nodes = n;
        ps->shape = 1;
        return AM_OK;
    }
    const int L = c->layers, n = c->nodes;
    int l = 0, j = 0, id;
    am_status st;
    if (strcmp(tok[0], "node") == 0) {
        if (ntok != 7) return am_fail(err, errsz, AM_ERR_PARSE, "'node' needs LAYER J FUNCTION OFFSET XSCALE YSCALE");
        if (!am_geno_tok_int(tok[1], 0, L - 1, &l) || !am_geno_tok_int(tok[2], 0, n - 1, &j))
            return am_fail(err, errsz, AM_ERR_RANGE, "node '%s %s' is not in the %d x %d network",
                           am_quote(q1, sizeof q1, tok[1], -1), am_quote(q2, sizeof q2, tok[2], -1), L, n);
        int f = 0;
        while (f < AM_FN_COUNT && strcmp(tok[3], fn_names[f]) != 0) f++;
        if (f == AM_FN_COUNT)
            return am_fail(err, errsz, AM_ERR_PARSE, "unknown function '%s' (sigmoid, gauss, sine, abs, linear)",
                           am_quote(q1, sizeof q1, tok[3], -1));
        am_cppn_node* nd = &c->node[l][j];
        nd->fn = (uint8_t)f;
        if (!am_geno_tok_real(tok[4], -AM_CPPN_OFFSET_MAX, AM_CPPN_OFFSET_MAX, &nd->offset))
            return am_fail(err, errsz, AM_ERR_RANGE, "offset '%s' is not a number in [-1, 1]",
                           am_quote(q1, sizeof q1, tok[4], -1));
        if (!am_geno_tok_real(tok[5], -AM_CPPN_XSCALE_MAX, AM_CPPN_XSCALE_MAX, &nd->xscale))
            return am_fail(err, errsz, AM_ERR_RANGE, "x scaling '%s' is not a number in [-4, 4]",
                           am_quote(q1, sizeof q1, tok[5], -1));
        if (!am_geno_tok_real(tok[6], -AM_CPPN_YSCALE_MAX, AM_CPPN_YSCALE_MAX, &nd->yscale))
            return am_fail(err, errsz, AM_ERR_RANGE, "y scaling '%s' is not a number in [-2, 2]",
                           am_quote(q1, sizeof q1, tok[6], -1));
        id = l * n + j;
    } else if (strcmp(tok[0], "in") == 0) {
        if (ntok != 10) return am_fail(err, errsz, AM_ERR_PARSE, "'in J' needs 4 pairs ACTIVE WEIGHT (x, y, z, bias)");
        if (!am_geno_tok_int(tok[1], 0, n - 1, &j))
            return am_fail(err, errsz, AM_ERR_RANGE, "node '%s' is not 0..%d", am_quote(q1, sizeof q1, tok[1], -1), n - 1);
        if ((st = parse_conns(tok + 2, 4, c->w_in[j], 1, c->on_in[j], 1, err, errsz)) != AM_OK) return st;
        id = L * n + j;
    } else if (strcmp(tok[0], "link") == 0) {
        if (L < 2) return am_fail(err, errsz, AM_ERR_PARSE, "'link' in a one-layer network");
        if (ntok != 3 + 2 * n) return am_fail(err, errsz, AM_ERR_PARSE, "'link LAYER J' needs %d pairs ACTIVE WEIGHT", n);
        if (!am_geno_tok_int(tok[1], 1, L - 1, &l) || !am_geno_tok_int(tok[2], 0, n - 1, &j))
            return am_fail(err, errsz, AM_ERR_RANGE, "link target '%s %s' is not a node of layers 1..%d",
                           am_quote(q1, sizeof q1, tok[1], -1), am_quote(q2, sizeof q2, tok[2], -1), L - 1);
        if ((st = parse_conns(tok + 3, n, c->w[l - 1][j], 1, c->on[l - 1][j], 1, err, errsz)) != AM_OK) return st;
        id = L * n + n + (l - 1) * n + j;
    } else if (strcmp(tok[0], "out") == 0) {
        if (ntok != 2 + 2 * n) return am_fail(err, errsz, AM_ERR_PARSE, "'out MATERIAL' needs %d pairs ACTIVE WEIGHT", n);
        if (!am_geno_tok_int(tok[1], 0, am_genome_fields(g) - 1, &l))
            return am_fail(err, errsz, AM_ERR_RANGE, "%s '%s' is not 0..%d", am_geno_field_word(g),
                           am_quote(q1, sizeof q1, tok[1], -1), am_genome_fields(g) - 1);
        if ((st = parse_conns(tok + 2, n, c->w_out[l], 1, c->on_out[l], 1, err, errsz)) != AM_OK) return st;
        id = 2 * L * n + l;
    } else {
        return am_fail(err, errsz, AM_ERR_PARSE, "unknown line '%s' in a cppn genome (node, in, link, out or end)",
                       am_quote(q1, sizeof q1, tok[0], -1));
    }
    if (ps->seen[id])
        return am_fail(err, errsz, AM_ERR_PARSE, "'%s %s' given twice", am_quote(q1, sizeof q1, tok[0], -1),
                       am_quote(q2, sizeof q2, tok[1], -1));
    ps->seen[id] = 1;
    ps->lines++;
    return AM_OK;
}

static am_status cppn_parse_end(am_genome* g, am_geno_parse* ps, char* err, int errsz)
{
    if (!ps->shape) return am_fail(err, errsz, AM_ERR_PARSE, "missing 'cppn LAYERS NODES' line");
    const int L = g->cppn.layers, n = g->cppn.nodes;
    for (int l = 0; l < L; l++)
        for (int j = 0; j < n; j++)
            if (!ps->seen[l * n + j]) return am_fail(err, errsz, AM_ERR_PARSE, "missing line 'node %d %d'", l, j);
    for (int j = 0; j < n; j++)
        if (!ps->seen[L * n + j]) return am_fail(err, errsz, AM_ERR_PARSE, "missing line 'in %d'", j);
    for (int l = 1; l < L; l++)
        for (int j = 0; j < n; j++)
            if (!ps->seen[L * n + n + (l - 1) * n + j]) return am_fail(err, errsz, AM_ERR_PARSE, "missing line 'link %d %d'", l, j);
    for (int m = 0; m < am_genome_fields(g); m++)
        if (!ps->seen[2 * L * n + m]) return am_fail(err, errsz, AM_ERR_PARSE, "missing line 'out %d'", m);
    return AM_OK;
}

const am_geno_ops am_geno_cppn_ops = {
    "cppn", cppn_init, cppn_mutate, cppn_crossover, cppn_same_shape, cppn_check, cppn_values,
    cppn_hash, cppn_equal, cppn_express, cppn_format, cppn_parse_line, cppn_parse_end,
};
