/* Where a run's time steps go: relaxation against movement, and the evaluations whose steps buy
 * no score (diverged, unsettled) or buy a result the run had already (a body evaluated before).
 * amorph bench --evolve adds its evaluations as they are placed; a run's summary reads them back
 * from evals.csv, so a resumed run is counted whole. */
#include "evolve_cmd.h"

#include <stdlib.h>
#include <string.h>

void account_begin(step_account* a)
{
    memset(a, 0, sizeof *a);
}

/* 1 when hash was seen before (and remembers it); -1 when the table is full (not counted) */
static int seen_before(step_account* a, uint64_t hash)
{
#if ACCOUNT_SET > 1
    if (a->distinct >= ACCOUNT_SET / 4 * 3) return -1;
    unsigned long i = (unsigned long)(hash ^ hash >> 29) & (ACCOUNT_SET - 1);
    for (;;) {
        if (a->set[i] == hash) return 1;
        if (a->set[i] == 0) {
            a->set[i] = hash;
            a->distinct++;
            return 0;
        }
        i = (i + 1) & (ACCOUNT_SET - 1);
    }
#else
    (void)a;
    (void)hash;
    return -1;
#endif
}

void account_add(step_account* a, long voxels, int empty, int diverged, int settled, long relax_steps, long steps, uint64_t hash)
{
    a->evaluations++;
    if (empty) {
        a->empty++; /* not simulated: no steps */
        return;
    }
    const double vs = (double)steps * (double)voxels;
    const long relax = relax_steps < steps ? relax_steps : steps;
    a->relax_steps += relax;
    a->move_steps += steps - relax;
    a->relax_voxel_steps += (double)relax * (double)voxels;
    a->voxel_steps += vs;
    if (diverged) {
        a->diverged++;
        a->diverged_voxel_steps += vs;
    } else if (!settled) {
        a->unsettled++;
        a->unsettled_voxel_steps += vs;
    }
    /* the same body gives the same final state (deterministic), and two bodies share one only by
     * a 64-bit coincidence; 0 is an empty body's */
    int r = hash ? seen_before(a, hash) : -1;
    if (r < 0) return;
    a->tracked++;
    if (r == 1) {
        a->repeats++;
        a->repeat_voxel_steps += vs;
    }
}

/* the column of name in a CSV header, or -1 */
static int column(const char* header, const char* name)
{
    const size_t n = strlen(name);
    int k = 0;
    for (const char* p = header;; k++) {
        const char* q = strchr(p, ',');
        size_t len = q ? (size_t)(q - p) : strlen(p);
        if (len == n && !strncmp(p, name, n)) return k;
        if (!q) return -1;
        p = q + 1;
    }
}

/* field k of a CSV row (no quoting in evals.csv) as a number */
static const char* field(const char* row, int k)
{
    const char* p = row;
    for (int i = 0; i < k && p; i++) {
        p = strchr(p, ',');
        if (p) p++;
    }
    return p ? p : "";
}

enum { COL_VOXELS, COL_EMPTY, COL_DIVERGED, COL_SETTLED, COL_RELAX, COL_STEPS, COL_HASH, COLS };

int account_read_evals(step_account* a, const char* dir)
{
    static const char* const names[COLS] = {"voxels", "empty", "diverged", "settled", "relax_steps", "steps", "state_hash"};
    char path[TOOL_PATH_MAX], err[AM_ERR_MAX], *line;
    long n;
    int col[COLS];
    account_begin(a);
    path_join(path, sizeof path, dir, AM_RUN_EVALS);
    tool_src src;
    if (tool_src_open(&src, path, TOOL_FILE_MAX, 1, err, sizeof err) != AM_OK) return -1;
    int r = tool_src_next(&src, &line, &n, err, sizeof err);
    for (int k = 0; k < COLS && r == 1; k++)
        if ((col[k] = column(line, names[k])) < 0) r = -1;
    while (r == 1 && (r = tool_src_next(&src, &line, &n, err, sizeof err)) == 1) {
        char* end;
        const char* h = field(line, col[COL_HASH]);
        uint64_t hash = (uint64_t)strtoull(h, &end, 16);
        if (end == h) continue; /* a row cut by a kill (a resume cuts it off) */
        account_add(a, atol(field(line, col[COL_VOXELS])), atoi(field(line, col[COL_EMPTY])), atoi(field(line, col[COL_DIVERGED])),
                    atoi(field(line, col[COL_SETTLED])), atol(field(line, col[COL_RELAX])), atol(field(line, col[COL_STEPS])), hash);
    }
    tool_src_close(&src);
    return r < 0 ? -1 : 0;
}

static double share(double part, double whole)
{
    return whole > 0 ? part / whole : 0.0;
}

void account_put(tool_rec* q, const step_account* a)
{
    const long simulated = a->evaluations - a->empty;
    tool_rec_int(q, "steps_relax", a->relax_steps);
    tool_rec_int(q, "steps_move", a->move_steps);
    tool_rec_num(q, "steps_per_eval", simulated ? (double)(a->relax_steps + a->move_steps) / (double)simulated : 0.0);
    tool_rec_num(q, "relax_share", share(a->relax_voxel_steps, a->voxel_steps));
    tool_rec_int(q, "evals_empty", a->empty);
    tool_rec_int(q, "evals_diverged", a->diverged);
    tool_rec_num(q, "diverged_share", share(a->diverged_voxel_steps, a->voxel_steps));
    tool_rec_int(q, "evals_unsettled", a->unsettled);
    tool_rec_num(q, "unsettled_share", share(a->unsettled_voxel_steps, a->voxel_steps));
#if ACCOUNT_SET > 1
    tool_rec_int(q, "evals_repeat", a->repeats);
    tool_rec_num(q, "repeat_share", share(a->repeat_voxel_steps, a->voxel_steps));
    if (a->tracked < simulated) tool_rec_int(q, "evals_repeat_tracked", a->tracked);
#endif
}

void account_put_reuse(tool_rec* q, const step_account* a, const am_evo* e)
{
    tool_rec_int(q, "evals_reused", e->reused);
    if (a) tool_rec_num(q, "reused_share", share(e->reused_voxel_steps, a->voxel_steps));
}
