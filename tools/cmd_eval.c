/* amorph eval: robots as JSON lines on stdin, one JSON result per line on stdout, a batch at a
 * time (ask/tell: a whole population per batch), evaluated on the port's parallel map through the
 * embedding API (amorph/api.h), so a result here is the library's and amorph sim's, bit for bit.
 * docs/embedding.md is the manual. */
#include "json.h"
#include "robot.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(AM_PROFILE_BOARD)
int cmd_eval(tool_ctx* c, int argc, char** argv)
{
    (void)c, (void)argc, (void)argv;
    return tool_not_in_build("eval", "JSON pipes of robots");
}
#else

static const char eval_help[] =
    "usage: amorph eval [--threads N] [--run DIR] [--KEY VALUE ...] < robots.jsonl\n"
    "Reads robots as JSON lines on stdin and writes one JSON result per robot on stdout.\n"
    "A line is one object: {\"id\": 3, \"genome\": \"amorph-genome 1\\n...\"} or {\"id\": 3, \"lattice\": \"...\"} or {\"vxa\": \"<VXA ...\"},\n"
    "with optional \"settings\": {\"cycles\": \"4\", ...} (configuration keys, values as strings or numbers).\n"
    "id (an integer) is optional: the line's number on stdin stands in. An empty line or the end of\n"
    "the input ends a batch: its robots are evaluated on the threads, their results printed in input\n"
    "order (the same for any --threads), then an empty line, and the output is flushed.\n"
    "A line may ask for one of amorph's genome operators instead (ask/tell, docs/embedding.md):\n"
    "{\"op\": \"seed\", \"seed\": 5}, {\"op\": \"new\"}, {\"op\": \"pairing\", \"n\": 20},\n"
    "{\"op\": \"offspring\", \"a\": G, \"b\": G}, {\"op\": \"mutate\", \"genome\": G}, {\"op\": \"distance\", \"a\": G, \"b\": G},\n"
    "{\"op\": \"crowd\", \"a\": G, \"fa\": F, \"b\": G, \"fb\": F, \"c1\": G, \"f1\": F, \"c2\": G, \"f2\": F} (null: diverged);\n"
    "they run in input order on one stream that goes on across batches, and answer with \"genome\",\n"
    "\"genomes\", \"order\", \"distance\" or \"meets\" and \"replaces\".\n"
    "A result: id, fitness, travel, dx, dy, dz, sustained_travel, voxels, links, empty, steps,\n"
    "diverged, settled, hash (as amorph sim --json). A genome is evaluated as amorph evolve's run\n"
    "evaluates it (its palette and voxel size from the settings), a lattice as amorph sim does.\n"
    "Bad input (bad JSON, an unknown key, a bad genome or lattice) ends the command: one line on\n"
    "stderr, 'amorph: eval: stdin:LINE: problem', exit status 2; no result of that batch is printed.\n"
    "  --threads N        workers, 1..%d (0, the default: every core)\n"
    "  --run DIR          the settings of a run folder (its config.txt, or a config file named\n"
    "                     itself) under the flags and each line's: a genome is evaluated as that run\n"
    "                     evaluated it (amorph sim DIR --genome FILE); the operators breed its genomes\n"
    "  --KEY VALUE        a setting for every robot, before each line's own (amorph evolve --help-config;\n"
    "                     not the run's keys population, evaluations, seed, threads, checkpoint_seconds)\n"
    "One process: the MPI build runs it without mpirun (on threads).\n";


#define EVAL_LINE_MAX (1L << 20)      /* bytes of one input line */
#define EVAL_ARENA (32L << 20)        /* decoded texts of one batch */
#define EVAL_MAX_BATCH 4096           /* robots of one batch */
#define EVAL_MAX_SETTINGS 32          /* settings of one line, and of the command line */
#define EVAL_VALUE_MAX 256            /* bytes of a setting's value */

enum { ROBOT_GENOME = 1, ROBOT_LATTICE = 2, ROBOT_VXA = 3 };
/* the genome operators a line may ask for instead of an evaluation (ask/tell, amorph/api.h) */
enum { OP_NONE, OP_SEED, OP_NEW, OP_PAIRING, OP_OFFSPRING, OP_MUTATE, OP_DISTANCE, OP_CROWD, OP_COUNT };
static const char* const op_name[OP_COUNT] = {"", "seed", "new", "pairing", "offspring", "mutate", "distance", "crowd"};
/* the texts an operator takes ("genome" is a, "c1" c, "c2" d) and the fitnesses of crowd */
static const char* const op_text[4] = {"a", "b", "c1", "c2"};
static const char* const op_fit[4] = {"fa", "fb", "f1", "f2"};
static const int op_texts[OP_COUNT] = {0, 0, 0, 0, 2, 1, 2, 4};

typedef struct eval_item {
    long id;
    int line;                         /* its line on stdin */
    int kind;                         /* ROBOT_GENOME or ROBOT_LATTICE */
    const char* text;                 /* in the arena */
    int op;                           /* OP_NONE (an evaluation) or the operator asked for */
    const char* t[4];                 /* its texts, in the arena */
    double f[4];                      /* crowd's fitnesses (null: NaN, a diverged body) */
    long num;                         /* pairing's n, seed's seed */
    int has_num, nf;
    int nset;
    const char* key[EVAL_MAX_SETTINGS];
    const char* val[EVAL_MAX_SETTINGS];
} eval_item;

typedef struct eval_out {
    am_result r;
    int st;                           /* am_status */
    char err[AM_ERR_MAX];
    char* g[2];                       /* an operator's genomes out, in the operators' arena */
    double d;                         /* distance's */
    int v[AM_MAX_POPULATION];         /* pairing's order, crowd's meets and replaces */
} eval_out;

typedef struct eval_batch {
    int n;
    long used;                        /* arena bytes */
    const char* run_text;             /* --run: the run's config.txt text, or NULL */
    const char* run_name;             /* and the file's name, for messages */
    am_evo_def base;                  /* the settings under the flags: the run's, or the defaults */
    int nflag;                        /* the command line's settings */
    const char* flag_key[EVAL_MAX_SETTINGS];
    const char* flag_val[EVAL_MAX_SETTINGS];
    eval_item item[EVAL_MAX_BATCH];
    eval_out out[EVAL_MAX_BATCH];
} eval_batch;

/* one batch, the line buffer, the arena and a workspace per worker: static, used by this command only */
static eval_batch g_batch;
static char g_line[EVAL_LINE_MAX + 2];
static char g_arena[EVAL_ARENA];
static am_api_work g_work[AM_MAX_WORKERS];
static char g_run_text[1L << 16];   /* --run: the run's config.txt */
static char g_run_path[TOOL_PATH_MAX];
/* the genome operators' workspace: its stream goes on from line to line and batch to batch */
static am_api_work g_ops;
static int g_ops_ready;
static char g_ops_arena[EVAL_ARENA]; /* operators' genomes out, one batch's */

/* room for cap bytes in the arena, or NULL */
static char* arena(eval_batch* b, long cap)
{
    if (b->used + cap > EVAL_ARENA) return NULL;
    return g_arena + b->used;
}

/* a setting's key and value checked as amorph evolve checks them; NULL or a message */
static const char* check_setting(const char* key, const char* val, char* err, int errsz)
{
    int g = am_evo_key_group(key);
    if (g < 0) {
        char q[AM_QUOTE_BUF];
        snprintf(err, (size_t)errsz, "unknown setting '%s' (amorph evolve --help-config lists them)", am_quote(q, sizeof q, key, -1));
        return err;
    }
    if (g == AM_KEYS_RUN) {
        snprintf(err, (size_t)errsz, "'%s' is a setting of an evolution, not of one robot", key);
        return err;
    }
    am_evo_def d = am_default_evo();
    if (am_evo_set(&d, key, val, err, errsz) != AM_OK) return err;
    return NULL;
}

/* the "settings" object of a line into it (keys and values in the arena) */
static int read_settings(tool_json* j, eval_batch* b, eval_item* it)
{
    if (!tool_json_expect(j, '{', "to open \"settings\"")) return 0;
    if (tool_json_take(j, '}')) return 1;
    do {
        char* k = arena(b, 64 + EVAL_VALUE_MAX);
        if (!k) return tool_json_fail(j, "the batch's texts pass %ld bytes: end the batch sooner (an empty line)", EVAL_ARENA);
        if (!tool_json_string(j, k, 64, NULL)) return 0;
        if (!tool_json_expect(j, ':', "after a setting's name")) return 0;
        char* v = k + 64;
        while (*j->p == ' ' || *j->p == '\t') j->p++;
        if (*j->p == '"') {
            if (!tool_json_string(j, v, EVAL_VALUE_MAX, NULL)) return 0;
        } else if (!tool_json_number(j, v, EVAL_VALUE_MAX)) return 0;
        char msg[AM_ERR_MAX];
        if (check_setting(k, v, msg, sizeof msg)) return tool_json_fail(j, "settings: %s", msg);
        if (it->nset == EVAL_MAX_SETTINGS) return tool_json_fail(j, "more than %d settings", EVAL_MAX_SETTINGS);
        it->key[it->nset] = k;
        it->val[it->nset++] = v;
        b->used += (long)strlen(v) + 65;
    } while (tool_json_take(j, ','));
    return tool_json_expect(j, '}', "to close \"settings\"");
}

/* the evaluation's budget for the item's settings (the command line's, then its own), before any
 * robot of the batch is evaluated; a period in seconds is taken at its fewest steps here, and at the
 * body's own in the evaluation (am_evo_simulate refuses it there, before its first step). NULL or a
 * message naming the setting's place: "settings: KEY = ..." or "--KEY = ..." */
static const char* check_budget(const eval_batch* b, const eval_item* it, char* err, int errsz)
{
    am_evo_def d = b->base;
    char why[AM_ERR_MAX];
    unsigned mat = 0;
    int key, in_line = 0;
    for (int s = 0; s < b->nflag; s++) am_evo_set_over(&d, b->flag_key[s], b->flag_val[s], &mat, why, sizeof why);
    for (int s = 0; s < it->nset; s++) am_evo_set_over(&d, it->key[s], it->val[s], &mat, why, sizeof why);
    if (am_evo_check_budget(&d, d.env.period_s > AM_P(0) ? 2.0 : (double)d.env.period_steps, &key, why, sizeof why) == AM_OK)
        return NULL;
    int in_flags = 0;
    for (int s = 0; s < it->nset; s++) in_line |= !strcmp(it->key[s], am_evo_key_name(key));
    for (int s = 0; s < b->nflag; s++) in_flags |= !strcmp(b->flag_key[s], am_evo_key_name(key));
    if (!in_line && !in_flags && b->run_name) { /* the run's config.txt set it */
        const int n = snprintf(err, (size_t)errsz, "%s: ", b->run_name);
        if (n >= 0 && n < errsz) snprintf(err + n, (size_t)(errsz - n), "%s", why);
    } else {
        snprintf(err, (size_t)errsz, "%s%.200s", in_line ? "settings: " : "--", why);
    }
    return err;
}

/* index of key in names[4], or -1 */
static int op_slot(const char* key, const char* const names[4])
{
    for (int k = 0; k < 4; k++)
        if (!strcmp(key, names[k])) return k;
    return -1;
}

/* an operator line has what its operator takes, and nothing else */
static int check_op(tool_json* j, eval_item* it)
{
    const int op = it->op, nt = op_texts[op];
    if (op == OP_MUTATE && it->kind == ROBOT_GENOME && !it->t[0]) /* "genome" read before "op" */
        it->t[0] = it->text, it->text = NULL, it->kind = 0;
    if (it->kind) return tool_json_fail(j, "op \"%s\" evaluates nothing: no \"genome\" or \"lattice\" robot with it", op_name[op]);
    for (int k = 0; k < 4; k++) {
        const char* name = op == OP_MUTATE && k == 0 ? "genome" : op_text[k];
        if (k < nt && !it->t[k]) return tool_json_fail(j, "op \"%s\" needs \"%s\"", op_name[op], name);
        if (k >= nt && it->t[k]) return tool_json_fail(j, "op \"%s\" takes no \"%s\"", op_name[op], op_text[k]);
    }
    if (op == OP_CROWD && it->nf != 15) return tool_json_fail(j, "op \"crowd\" needs \"fa\", \"fb\", \"f1\" and \"f2\"");
    if (op != OP_CROWD && it->nf) return tool_json_fail(j, "op \"%s\" takes no fitness", op_name[op]);
    if ((op == OP_SEED || op == OP_PAIRING) != (it->has_num != 0))
        return tool_json_fail(j, op == OP_SEED ? "op \"seed\" needs \"seed\"" : op == OP_PAIRING ? "op \"pairing\" needs \"n\"" :
                                                                                             "op \"%s\" takes no \"n\" or \"seed\"", op_name[op]);
    return 1;
}

/* one robot line into the batch's next item */
static int read_robot(tool_json* j, eval_batch* b, eval_item* it, int lineno)
{
    int has_id = 0;
    memset(it, 0, sizeof *it);
    it->id = lineno; /* unless the line gives one */
    if (!tool_json_expect(j, '{', "to open the robot's object")) return 0;
    if (!tool_json_take(j, '}')) do {
            char key[32];
            if (!tool_json_string(j, key, sizeof key, NULL)) return 0;
            if (!tool_json_expect(j, ':', "after a key")) return 0;
            if (!strcmp(key, "id")) {
                char num[32];
                if (has_id++) return tool_json_fail(j, "\"id\" given twice");
                if (!tool_json_number(j, num, sizeof num)) return 0;
                if (!tool_parse_long(num, LONG_MIN, LONG_MAX, &it->id)) return tool_json_fail(j, "\"id\" must be an integer, not %s", num);
            } else if (!strcmp(key, "op")) {
                char name[16];
                if (it->op) return tool_json_fail(j, "\"op\" given twice");
                if (!tool_json_string(j, name, sizeof name, NULL)) return 0;
                for (int k = 1; k < OP_COUNT && !it->op; k++)
                    if (!strcmp(name, op_name[k])) it->op = k;
                if (!it->op) return tool_json_fail(j, "unknown op \"%s\" (seed, new, pairing, offspring, mutate, distance, crowd)", name);
            } else if (!strcmp(key, "n") || !strcmp(key, "seed")) {
                char num[32];
                if (it->has_num++) return tool_json_fail(j, "\"n\" or \"seed\" given twice");
                if (!tool_json_number(j, num, sizeof num)) return 0;
                if (!tool_parse_long(num, 0, LONG_MAX, &it->num)) return tool_json_fail(j, "\"%s\" must be an integer of 0 or more, not %s", key, num);
            } else if (op_slot(key, op_fit) >= 0) {
                const int k = op_slot(key, op_fit);
                int lit = 0;
                char num[64];
                while (*j->p == ' ' || *j->p == '\t') j->p++;
                if (*j->p == 'n') {
                    if (!tool_json_literal(j, &lit) || lit != -1) return tool_json_fail(j, "\"%s\": a number, or null for a diverged body", key);
                    it->f[k] = (double)NAN;
                } else {
                    if (!tool_json_number(j, num, sizeof num)) return 0;
                    it->f[k] = strtod(num, NULL);
                }
                it->nf |= 1 << k;
            } else if (op_slot(key, op_text) >= 0 || (!strcmp(key, "genome") && it->op)) {
                const int k = op_slot(key, op_text) >= 0 ? op_slot(key, op_text) : 0;
                if (it->t[k]) return tool_json_fail(j, "\"%s\" given twice", key);
                char* t = arena(b, EVAL_LINE_MAX);
                if (!t) return tool_json_fail(j, "the batch's texts pass %ld bytes: end the batch sooner (an empty line)", EVAL_ARENA);
                long len = 0;
                if (!tool_json_string(j, t, EVAL_LINE_MAX, &len)) return 0;
                it->t[k] = t;
                b->used += len + 1;
            } else if (!strcmp(key, "genome") || !strcmp(key, "lattice") || !strcmp(key, "vxa")) {
                if (it->kind) return tool_json_fail(j, "one robot per line (\"genome\", \"lattice\" or \"vxa\", once)");
                it->kind = key[0] == 'g' ? ROBOT_GENOME : key[0] == 'l' ? ROBOT_LATTICE : ROBOT_VXA;
                char* t = arena(b, EVAL_LINE_MAX);
                if (!t) return tool_json_fail(j, "the batch's texts pass %ld bytes: end the batch sooner (an empty line)", EVAL_ARENA);
                long len = 0;
                if (!tool_json_string(j, t, EVAL_LINE_MAX, &len)) return 0;
                it->text = t;
                b->used += len + 1;
            } else if (!strcmp(key, "settings")) {
                if (it->nset) return tool_json_fail(j, "\"settings\" given twice");
                if (!read_settings(j, b, it)) return 0;
            } else {
                char q[AM_QUOTE_BUF];
                return tool_json_fail(j, "unknown key \"%s\" (a line holds id, genome, lattice or vxa, settings; or op and its inputs)",
                                      am_quote(q, sizeof q, key, -1));
            }
        } while (tool_json_take(j, ','));
    if (!tool_json_expect(j, '}', "to close the robot's object")) return 0;
    if (!tool_json_end(j)) return 0;
    if (it->op) return check_op(j, it);
    if (it->t[0] || it->t[1] || it->t[2] || it->t[3] || it->nf || it->has_num)
        return tool_json_fail(j, "an operator's inputs without \"op\"");
    if (!it->kind) return tool_json_fail(j, "no robot: the line needs \"genome\", \"lattice\" or \"vxa\" (or an \"op\")");
    return 1;
}

/* the batch's operators, in input order on the operators' workspace (its stream goes on), each with
 * the command line's settings, then its own */
static void run_ops(eval_batch* b)
{
    long used = 0;
    for (int i = 0; i < b->n; i++) {
        const eval_item* it = &b->item[i];
        eval_out* o = &b->out[i];
        if (!it->op) continue;
        am_api_work* k = &g_ops;
        am_rng stream = k->rng;
        am_status st = am_api_init(k, (long)sizeof *k, o->err, sizeof o->err);
        if (g_ops_ready) k->rng = stream; /* am_api_init seeded it: the stream goes on */
        g_ops_ready = 1;
        if (st == AM_OK && b->run_text) st = am_api_set_config(k, b->run_text, b->run_name, o->err, sizeof o->err);
        for (int s = 0; st == AM_OK && s < b->nflag; s++) st = am_api_set(k, b->flag_key[s], b->flag_val[s], o->err, sizeof o->err);
        for (int s = 0; st == AM_OK && s < it->nset; s++) st = am_api_set(k, it->key[s], it->val[s], o->err, sizeof o->err);
        const long cap = AM_GENOME_TEXT_MAX;
        o->g[0] = o->g[1] = NULL;
        if (st == AM_OK && (it->op == OP_NEW || it->op == OP_MUTATE || it->op == OP_OFFSPRING)) {
            if (used + 2 * cap > EVAL_ARENA) {
                o->st = am_fail(o->err, sizeof o->err, AM_ERR_CAPACITY, "the batch's genomes out pass %ld bytes: end the batch sooner",
                                EVAL_ARENA);
                continue;
            }
            o->g[0] = g_ops_arena + used;
            o->g[1] = g_ops_arena + used + cap;
        }
        if (st == AM_OK) switch (it->op) {
            case OP_SEED: st = am_api_seed(k, it->num, o->err, sizeof o->err); break;
            case OP_NEW: st = am_api_genome_new(k, o->g[0], cap, o->err, sizeof o->err); break;
            case OP_MUTATE: st = am_api_mutate(k, it->t[0], o->g[0], cap, o->err, sizeof o->err); break;
            case OP_OFFSPRING: st = am_api_offspring(k, it->t[0], it->t[1], o->g[0], o->g[1], cap, o->err, sizeof o->err); break;
            case OP_DISTANCE: st = am_api_distance(k, it->t[0], it->t[1], &o->d, o->err, sizeof o->err); break;
            case OP_PAIRING:
                st = it->num > AM_MAX_POPULATION ? am_fail(o->err, sizeof o->err, AM_ERR_RANGE, "pairing %ld members: at most %d", it->num, AM_MAX_POPULATION)
                                                 : am_api_pairing(k, (int)it->num, o->v, o->err, sizeof o->err);
                break;
            default:
                st = am_api_crowd(k, it->t[0], it->f[0], it->t[1], it->f[1], it->t[2], it->f[2], it->t[3], it->f[3], o->v, o->v + 2,
                                  o->err, sizeof o->err);
            }
        if (o->g[0]) used += (long)strlen(o->g[0]) + 1;
        if (o->g[1] && it->op == OP_OFFSPRING) {
            memmove(g_ops_arena + used, o->g[1], strlen(o->g[1]) + 1);
            o->g[1] = g_ops_arena + used;
            used += (long)strlen(o->g[1]) + 1;
        }
        o->st = (int)st;
    }
}

/* a genome text as a JSON string */
static void put_genome(am_text* t, const char* s)
{
    am_text_put(t, "\"");
    for (; *s; s++) {
        const unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') am_text_put(t, "\\%c", c);
        else if (c == '\n') am_text_put(t, "\\n");
        else if (c < 0x20) am_text_put(t, "\\u%04x", c);
        else am_text_put(t, "%c", c);
    }
    am_text_put(t, "\"");
}

/* an operator's result line */
static void put_op(am_text* t, const eval_item* it, const eval_out* o)
{
    am_text_put(t, "{\"id\": %ld, \"op\": \"%s\"", it->id, op_name[it->op]);
    switch (it->op) {
    case OP_SEED: am_text_put(t, ", \"seed\": %ld", it->num); break;
    case OP_NEW:
    case OP_MUTATE: am_text_put(t, ", \"genome\": "), put_genome(t, o->g[0]); break;
    case OP_OFFSPRING:
        am_text_put(t, ", \"genomes\": [");
        put_genome(t, o->g[0]);
        am_text_put(t, ", ");
        put_genome(t, o->g[1]);
        am_text_put(t, "]");
        break;
    case OP_DISTANCE: am_text_put(t, ", \"distance\": %.9g", o->d); break;
    case OP_PAIRING:
        am_text_put(t, ", \"order\": [");
        for (long k = 0; k < it->num; k++) am_text_put(t, "%s%d", k ? ", " : "", o->v[k]);
        am_text_put(t, "]");
        break;
    default: am_text_put(t, ", \"meets\": [%d, %d], \"replaces\": [%d, %d]", o->v[0], o->v[1], o->v[2], o->v[3]);
    }
    am_text_put(t, "}\n");
}

/* item i on worker w's workspace: the settings (command line, then the line's), then the robot */
static void eval_task(void* ctx, int i, int w)
{
    eval_batch* b = (eval_batch*)ctx;
    const eval_item* it = &b->item[i];
    eval_out* o = &b->out[i];
    if (it->op) return; /* done by run_ops */
    am_api_work* k = &g_work[w];
    am_status st = am_api_init(k, (long)sizeof *k, o->err, sizeof o->err);
    if (st == AM_OK && b->run_text) st = am_api_set_config(k, b->run_text, b->run_name, o->err, sizeof o->err);
    for (int s = 0; st == AM_OK && s < b->nflag; s++) st = am_api_set(k, b->flag_key[s], b->flag_val[s], o->err, sizeof o->err);
    for (int s = 0; st == AM_OK && s < it->nset; s++) st = am_api_set(k, it->key[s], it->val[s], o->err, sizeof o->err);
    if (st == AM_OK)
        st = it->kind == ROBOT_GENOME  ? am_api_eval_genome(k, it->text, &o->r, o->err, sizeof o->err)
             : it->kind == ROBOT_VXA ? am_api_eval_vxa(k, it->text, &o->r, o->err, sizeof o->err)
                                     : am_api_eval_lattice(k, it->text, &o->r, o->err, sizeof o->err);
    o->st = (int)st;
}

/* evaluates the batch and prints its results and an empty line; 0, or the exit status after a message */
static int run_batch(eval_batch* b, int threads)
{
    char err[AM_ERR_MAX];
    if (b->n > 0) {
        run_ops(b);
        int workers = threads < b->n ? threads : b->n;
        am_status st = am_port_parallel_map(b->n, workers, eval_task, b, b->out, (long)sizeof b->out[0], err, sizeof err);
        if (st != AM_OK) return tool_usage_error("eval: %s", err), 1;
        for (int i = 0; i < b->n; i++)
            if (b->out[i].st != AM_OK) return tool_usage_error("eval: stdin:%d: %s", b->item[i].line, b->out[i].err);
    }
    tool_out out;
    if (tool_out_open(&out, NULL)) return 1;
    for (int i = 0; i < b->n; i++) {
        const am_result* r = &b->out[i].r;
        if (b->item[i].op) {
            put_op(&out.text, &b->item[i], &b->out[i]);
            continue;
        }
        tool_rec q;
        tool_rec_begin(&q, &out.text, 1);
        tool_rec_int(&q, "id", b->item[i].id);
        tool_rec_num(&q, "fitness", r->fitness);
        tool_rec_num(&q, "travel", r->travel);
        tool_rec_num(&q, "dx", r->dx);
        tool_rec_num(&q, "dy", r->dy);
        tool_rec_num(&q, "dz", r->dz);
        tool_rec_num(&q, "sustained_travel", r->sustained);
        tool_rec_int(&q, "voxels", r->voxels);
        tool_rec_int(&q, "links", r->links);
        tool_rec_int(&q, "empty", r->voxels == 0);
        tool_rec_int(&q, "steps", r->steps);
        tool_rec_int(&q, "diverged", r->diverged);
        tool_rec_int(&q, "settled", r->settled);
        tool_rec_hex(&q, "hash", r->hash);
        tool_rec_end(&q);
    }
    am_text_put(&out.text, "\n");
    if (tool_out_close(&out, 1)) return 1;
    fflush(stdout);
    b->n = 0;
    b->used = 0;
    return 0;
}

int cmd_eval(tool_ctx* c, int argc, char** argv)
{
    (void)c;
    eval_batch* b = &g_batch;
    int threads = 0;
    const char* run = NULL;
    b->nflag = 0;
    b->run_text = b->run_name = NULL;
    b->base = am_default_evo();
    for (int i = 1; i < argc; i++) {
        const char* a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            printf(eval_help, AM_MAX_WORKERS);
            return 0;
        }
        if (!strcmp(a, "--threads")) {
            if (!tool_parse_int(i + 1 < argc ? argv[i + 1] : NULL, 0, AM_MAX_WORKERS, &threads))
                return tool_usage_error("eval: --threads needs a number of workers, 0..%d", AM_MAX_WORKERS);
            i++;
            continue;
        }
        if (!strcmp(a, "--run")) {
            if (i + 1 >= argc) return tool_usage_error("eval: --run needs a run folder (or its config.txt)");
            if (run) return tool_usage_error("eval: --run given twice");
            run = argv[++i];
            continue;
        }
        const char *key, *val;
        int r = tool_setting_arg("eval", argc, argv, &i, &key, &val);
        if (r == 2) return 2;
        if (r == 0) return tool_unknown_option("eval", a, eval_help);
        char msg[AM_ERR_MAX];
        if (check_setting(key, val, msg, sizeof msg)) return tool_usage_error("eval: %s", msg);
        if (b->nflag == EVAL_MAX_SETTINGS) return tool_usage_error("eval: more than %d settings", EVAL_MAX_SETTINGS);
        b->flag_key[b->nflag] = key;
        b->flag_val[b->nflag++] = val;
    }
    if (run) {
        /* the run's settings read once, and checked here on the operators' workspace (not started
         * yet: its stream begins at the first operator line) */
        char err[AM_ERR_MAX];
        long len = 0;
        /* a run folder's config.txt, else the file named */
        if (snprintf(g_run_path, sizeof g_run_path, "%s/" AM_RUN_CONFIG, run) >= (int)sizeof g_run_path)
            return tool_usage_error("eval: --run %s: the path is too long", run);
        if (!am_port_exists(g_run_path)) snprintf(g_run_path, sizeof g_run_path, "%s", run);
        am_status st = am_port_read_file(g_run_path, g_run_text, (long)sizeof g_run_text, &len, err, sizeof err);
        if (st == AM_ERR_CAPACITY) return tool_usage_error("eval: --run %s: larger than a configuration (%ld bytes)", g_run_path, (long)sizeof g_run_text - 1);
        if (st != AM_OK) return tool_usage_error("eval: --run: %s", err);
        if ((long)strlen(g_run_text) != len) return tool_usage_error("eval: --run %s: binary data (a NUL byte)", g_run_path);
        if (am_api_init(&g_ops, (long)sizeof g_ops, err, sizeof err) != AM_OK ||
            am_api_set_config(&g_ops, g_run_text, g_run_path, err, sizeof err) != AM_OK)
            return tool_usage_error("eval: --run: %s", err);
        b->run_text = g_run_text;
        b->run_name = g_run_path;
        b->base = g_ops.def;
    }
    /* stdin reaches one process only: the items of a map over several (MPI ranks) would be missing */
    if (am_port_processes() > 1)
        return tool_usage_error("eval: reads its robots from stdin, which one process alone gets: run it as one process (not under "
                                "mpirun with %d), on threads", am_port_processes());
    if (threads == 0) threads = am_port_cores();
    if (threads < 1) threads = 1;
    if (threads > AM_MAX_WORKERS) threads = AM_MAX_WORKERS;
    b->n = 0;
    b->used = 0;
    int lineno = 0;
    for (;;) {
        if (!fgets(g_line, (int)sizeof g_line, stdin)) break;
        lineno++;
        size_t n = strlen(g_line);
        if (n > 0 && g_line[n - 1] == '\n') g_line[--n] = 0;
        else if (n > (size_t)EVAL_LINE_MAX) return tool_usage_error("eval: stdin:%d: a line longer than %ld bytes", lineno, EVAL_LINE_MAX);
        if (n > 0 && g_line[n - 1] == '\r') g_line[--n] = 0;
        if (strlen(g_line) != n) return tool_usage_error("eval: stdin:%d: binary data (a NUL byte)", lineno);
        size_t lead = strspn(g_line, " \t");
        if (g_line[lead] == 0) {
            int rc = run_batch(b, threads);
            if (rc) return rc;
            continue;
        }
        if (b->n == EVAL_MAX_BATCH)
            return tool_usage_error("eval: stdin:%d: more than %d robots in a batch (end it with an empty line)", lineno, EVAL_MAX_BATCH);
        eval_item* it = &b->item[b->n];
        tool_json j;
        tool_json_begin(&j, g_line);
        if (!read_robot(&j, b, it, lineno)) return tool_usage_error("eval: stdin:%d: %s", lineno, j.err);
        char msg[AM_ERR_MAX];
        if (check_budget(b, it, msg, sizeof msg)) return tool_usage_error("eval: stdin:%d: %s", lineno, msg);
        it->line = lineno;
        b->n++;
    }
    if (ferror(stdin)) return tool_usage_error("eval: stdin: a read failed"), 1;
    return b->n > 0 ? run_batch(b, threads) : 0;
}
#endif
