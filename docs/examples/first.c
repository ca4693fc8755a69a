/* docs/examples/first.c: a first program over amorph's library. It builds a robot cell by cell (a
 * 4 x 3 x 2 block of the built-in palette, its half x < 2 "active", the rest "passive"), simulates
 * it for four actuation cycles of the seed's evaluation and prints how far it travelled. From the
 * repository root, after make:
 *     cc -std=c11 -DAM_REAL_FLOAT -DAM_PROFILE_DESKTOP -Iinclude docs/examples/first.c build/libamorph.a -lm
 * tests/cli_first.sh builds it so and checks its travel against `amorph sim` of the same robot. */
#include <stdio.h>
#include "amorph.h"

/* the lattice, model and state are large (fixed capacities): static, never on the stack */
static am_lattice lattice;
static am_model model;
static am_state state;

int main(void)
{
    char err[AM_ERR_MAX];
    /* the caller was compiled with the library's number type and profile (one line otherwise) */
    if (AM_LAYOUT_CHECK(err, sizeof err) != AM_OK || am_lattice_init(&lattice, 4, 3, 2, 0.01, err, sizeof err) != AM_OK) {
        fprintf(stderr, "first: %s\n", err);
        return 1;
    }
    /* cell values are palette ids: material k of the palette is id k + 1, 0 is empty */
    int active = am_palette_find(&lattice.palette, "active") + 1, passive = am_palette_find(&lattice.palette, "passive") + 1;
    for (int z = 0; z < lattice.nz; z++)
        for (int y = 0; y < lattice.ny; y++)
            for (int x = 0; x < lattice.nx; x++) lattice.cell[am_lattice_index(&lattice, x, y, z)] = (uint8_t)(x < 2 ? active : passive);
    /* the model is built once from the lattice and the environment; the evaluation steps a state */
    am_env env = am_default_env();
    if (am_model_build(&model, &lattice, &env, err, sizeof err) != AM_OK) {
        fprintf(stderr, "first: %s\n", err);
        return 1;
    }
    am_eval_def def = am_default_eval();
    def.cycles = 4;
    am_result r;
    am_evaluate(&model, &state, &def, &r);
    printf("%d voxels, %ld steps: travel %.9g m (dx %.9g, dy %.9g)\n", r.voxels, r.steps, r.travel, r.dx, r.dy);
    return r.diverged ? 1 : 0;
}
