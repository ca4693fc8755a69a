/* Materials, palettes, lattices and the built-in scenes shared by tests, benchmarks and the
 * command. */
#include "amorph/sim.h"

#include <stdio.h>
#include <string.h>

am_material am_default_material(void)
{
    am_material m;
    memset(&m, 0, sizeof m);
    strcpy(m.name, "passive");
    m.E = AM_P(1.0e6);
    m.density = AM_P(1000.0);
    m.poisson = AM_P(0.0);
    m.cte = AM_P(0.0);
    m.phase = AM_P(0.0);
    m.mu_static = AM_P(1.0);
    m.mu_kinetic = AM_P(0.3);
    m.zeta_internal = AM_P(1.0);
    m.zeta_global = AM_P(0.01);
    m.zeta_collision = AM_P(0.8);
    m.color[0] = 40; m.color[1] = 90; m.color[2] = 220; m.color[3] = 255;
    m.fixed = 0;
    return m;
}

static am_material variant(const char* name, am_param E, am_param rho, am_param cte, am_param phase,
                           uint8_t r, uint8_t g, uint8_t b, int fixed)
{
    am_material m = am_default_material();
    memset(m.name, 0, sizeof m.name); /* no stale bytes after the NUL: materials hash and compare whole */
    snprintf(m.name, sizeof m.name, "%s", name);
    m.E = E;
    m.density = rho;
    m.cte = cte;
    m.phase = phase;
    m.color[0] = r; m.color[1] = g; m.color[2] = b;
    m.fixed = fixed;
    return m;
}

am_palette am_default_palette(void)
{
    am_palette p;
    am_default_palette_into(&p);
    return p;
}

void am_default_palette_into(am_palette* out)
{
    am_palette* p = out;
    memset(p, 0, sizeof *p);
    const am_param half_pi = AM_P(3.14159265358979323846) / AM_P(2);
    p->mat[0] = variant("passive", AM_P(1e6), AM_P(1000), AM_P(0), AM_P(0), 40, 90, 220, 0);
    p->mat[1] = variant("active", AM_P(1e6), AM_P(1000), AM_P(0.01), AM_P(0), 240, 200, 30, 0);
    p->mat[2] = variant("active90", AM_P(1e6), AM_P(1000), AM_P(0.01), -half_pi, 220, 40, 40, 0);
    p->mat[3] = variant("stiff", AM_P(1e7), AM_P(1000), AM_P(0), AM_P(0), 140, 140, 150, 0);
    p->mat[4] = variant("soft", AM_P(1e5), AM_P(1000), AM_P(0), AM_P(0), 60, 190, 90, 0);
    p->mat[5] = variant("heavy", AM_P(1e6), AM_P(3000), AM_P(0), AM_P(0), 110, 70, 40, 0);
    p->mat[6] = variant("light", AM_P(1e6), AM_P(300), AM_P(0), AM_P(0), 200, 230, 250, 0);
    p->mat[7] = variant("active180", AM_P(1e6), AM_P(1000), AM_P(0.01), AM_P(3.14159265358979323846), 240, 130, 20, 0);
    p->mat[8] = variant("fixed", AM_P(1e6), AM_P(1000), AM_P(0), AM_P(0), 30, 30, 30, 1);
    p->count = 9;
}

int am_palette_find(const am_palette* p, const char* name)
{
    for (int i = 0; i < p->count; i++)
        if (strcmp(p->mat[i].name, name) == 0) return i;
    return -1;
}

am_status am_lattice_init(am_lattice* lat, int nx, int ny, int nz, am_param voxel_size, char* err, int errsz)
{
    if (nx < 1 || ny < 1 || nz < 1)
        return am_fail(err, errsz, AM_ERR_RANGE, "lattice size %d x %d x %d: every side must be at least 1", nx, ny, nz);
    if (nx > AM_MAX_DIM || ny > AM_MAX_DIM || nz > AM_MAX_DIM)
        return am_fail(err, errsz, AM_ERR_CAPACITY, "lattice size %d x %d x %d exceeds the %s profile's %d per side",
                       nx, ny, nz, AM_PROFILE_NAME, AM_MAX_DIM);
    if (!(voxel_size > AM_P(0)) || !am_param_finite(voxel_size))
        return am_fail(err, errsz, AM_ERR_RANGE, "voxel size must be a positive number of metres");
    lat->nx = nx;
    lat->ny = ny;
    lat->nz = nz;
    lat->voxel_size = voxel_size;
    am_default_palette_into(&lat->palette);
    memset(lat->cell, 0, sizeof lat->cell);
    return AM_OK;
}

int am_lattice_count(const am_lattice* lat)
{
    int n = 0, cells = lat->nx * lat->ny * lat->nz;
    for (int i = 0; i < cells; i++) n += lat->cell[i] != 0;
    return n;
}

int am_lattice_equal(const am_lattice* a, const am_lattice* b)
{
    if (a->nx != b->nx || a->ny != b->ny || a->nz != b->nz) return 0;
    if (memcmp(&a->voxel_size, &b->voxel_size, sizeof a->voxel_size)) return 0;
    if (a->palette.count != b->palette.count) return 0;
    for (int i = 0; i < a->palette.count; i++) {
        const am_material *x = &a->palette.mat[i], *y = &b->palette.mat[i];
        if (strncmp(x->name, y->name, sizeof x->name) || memcmp(x->color, y->color, sizeof x->color) || x->fixed != y->fixed) return 0;
        const am_param* rx[10] = {&x->E, &x->density, &x->poisson, &x->cte, &x->phase, &x->mu_static, &x->mu_kinetic,
                                  &x->zeta_internal, &x->zeta_global, &x->zeta_collision};
        const am_param* ry[10] = {&y->E, &y->density, &y->poisson, &y->cte, &y->phase, &y->mu_static, &y->mu_kinetic,
                                  &y->zeta_internal, &y->zeta_global, &y->zeta_collision};
        for (int k = 0; k < 10; k++)
            if (memcmp(rx[k], ry[k], sizeof(am_param))) return 0;
    }
    return memcmp(a->cell, b->cell, (size_t)(a->nx * a->ny * a->nz)) == 0;
}

static int parse_size(const char* s, int* out)
{
    long v = 0;
    if (!*s) return 0;
    for (; *s; s++) {
        if (*s < '0' || *s > '9') return 0;
        v = v * 10 + (*s - '0');
        if (v > 100000) return 0;
    }
    *out = (int)v;
    return 1;
}

am_status am_scene_build(am_lattice* lat, const char* name, char* err, int errsz)
{
    const char* colon = strchr(name, ':');
    int n = 0;
    size_t kind_len = colon ? (size_t)(colon - name) : strlen(name);
    char qb[AM_QUOTE_BUF];
    if (!colon || !parse_size(colon + 1, &n) || n < 1)
        return am_fail(err, errsz, AM_ERR_ARG, "scene '%s': expected NAME:N with N >= 1 (cube:N, sphere:D, cantilever:N, chain:N, halfbar:N, antibar:N)",
                       am_quote(qb, sizeof qb, name, -1));
    const am_param L = AM_P(0.01);
    am_status st;
    if (kind_len == 4 && strncmp(name, "cube", 4) == 0) {
        if ((st = am_lattice_init(lat, n, n, n, L, err, errsz)) != AM_OK) return st;
        memset(lat->cell, 1, (size_t)(n * n * n));
        return AM_OK;
    }
    if (kind_len == 6 && strncmp(name, "sphere", 6) == 0) {
        if ((st = am_lattice_init(lat, n, n, n, L, err, errsz)) != AM_OK) return st;
        int active = am_palette_find(&lat->palette, "active") + 1;
        /* compare squared distances in doubled integer coordinates: exact */
        for (int z = 0; z < n; z++)
            for (int y = 0; y < n; y++)
                for (int x = 0; x < n; x++) {
                    long dx = 2 * x + 1 - n, dy = 2 * y + 1 - n, dz = 2 * z + 1 - n;
                    if (dx * dx + dy * dy + dz * dz <= (long)n * n)
                        lat->cell[am_lattice_index(lat, x, y, z)] = (uint8_t)(2 * x + 1 < n ? active : 1);
                }
        return AM_OK;
    }
    if (kind_len == 10 && strncmp(name, "cantilever", 10) == 0) {
        if (n < 2) return am_fail(err, errsz, AM_ERR_ARG, "scene '%s': a cantilever needs N >= 2", name);
        if ((st = am_lattice_init(lat, n, 1, 3, L, err, errsz)) != AM_OK) return st;
        int fixed = am_palette_find(&lat->palette, "fixed") + 1;
        for (int x = 0; x < n; x++) lat->cell[am_lattice_index(lat, x, 0, 2)] = (uint8_t)(x == 0 ? fixed : 1);
        return AM_OK;
    }
    /* the calibration bars (docs/validation.md): N x 3 x 3 on the floor, x < N/2 actuated; the rest
     * passive (halfbar) or actuated half a period later (antibar) */
    if (kind_len == 7 && (strncmp(name, "halfbar", 7) == 0 || strncmp(name, "antibar", 7) == 0)) {
        if (n < 2) return am_fail(err, errsz, AM_ERR_ARG, "scene '%s': a bar needs N >= 2", am_quote(qb, sizeof qb, name, -1));
        if ((st = am_lattice_init(lat, n, 3, 3, L, err, errsz)) != AM_OK) return st;
        const int active = am_palette_find(&lat->palette, "active") + 1;
        const int rest = name[0] == 'h' ? am_palette_find(&lat->palette, "passive") + 1 : am_palette_find(&lat->palette, "active180") + 1;
        for (int z = 0; z < 3; z++)
            for (int y = 0; y < 3; y++)
                for (int x = 0; x < n; x++) lat->cell[am_lattice_index(lat, x, y, z)] = (uint8_t)(2 * x < n ? active : rest);
        return AM_OK;
    }
    if (kind_len == 5 && strncmp(name, "chain", 5) == 0) {
        if ((st = am_lattice_init(lat, n, 1, 1, L, err, errsz)) != AM_OK) return st;
        memset(lat->cell, 1, (size_t)n);
        return AM_OK;
    }
    return am_fail(err, errsz, AM_ERR_ARG, "unknown scene '%s' (cube:N, sphere:D, cantilever:N, chain:N, halfbar:N, antibar:N)",
                   am_quote(qb, sizeof qb, name, (long)kind_len));
}
