/* tools/board_sim/board_sim.c: the simulator alone on a board (make sim-only TARGET=cortex-m4).
 *
 * A board that wants the voxel simulator and nothing else (no evolver, no files, no command, no
 * port) links src/base, src/sim and src/geno with the C library and libm, and its own start-up
 * (cortex-m.c: vector table, .data and .bss, the console and the exit by semihosting). This program
 * is that board's whole firmware: it evaluates two robots with the seed's evaluation cut to one
 * actuation cycle, the built-in scene sphere:6 and the random DCT genome of seed 1 in a 6^3
 * workspace expressed into a body, and prints each result's hash, which must be the one the
 * desktop build prints for the same robot:
 *     amorph sim --scene sphere:6 --cycles 1
 *     amorph random --seed 1 --representation dct --workspace 6 --out g.genome && amorph sim g.genome --cycles 1
 * (tools/sim_only.sh compares them). Nothing here is read from outside: the program is a fixed
 * computation, and its only output is a line per robot and the exit status. */
#include "amorph/base.h"
#include "amorph/sim.h"
#include "amorph/geno.h"
#include "board.h"

#include <stdint.h>

/* the simulator's model and state and the genotype's workspace: large, static (never on the
 * stack), as every caller of the library keeps them */
static am_model g_model;
static am_state g_state;
static am_lattice g_lattice;
static am_genome g_genome;
static am_geno_work g_geno;

/* text + the 16 hex digits of v */
static void put_hex(const char* text, uint64_t v)
{
    char line[40];
    int n = 0;
    while (text[n] && n < 20) line[n] = text[n], n++;
    for (int k = 15; k >= 0; k--) line[n++] = "0123456789abcdef"[(v >> (4 * k)) & 15];
    line[n] = 0;
    board_out(line);
}

/* decimal of a small non-negative number */
static void put_int(const char* text, long v)
{
    char digits[24], line[48];
    int d = 0, n = 0;
    do digits[d++] = (char)('0' + v % 10), v /= 10;
    while (v > 0 && d < 20);
    while (text[n] && n < 24) line[n] = text[n], n++;
    while (d > 0) line[n++] = digits[--d];
    line[n] = 0;
    board_out(line);
}

/* the lattice in g_lattice evaluated as `amorph sim ROBOT --cycles 1` does; one line "name hash=H
 * voxels=N steps=N"; 1 after a message when the model cannot be built */
static int evaluate(const char* name)
{
    char err[AM_ERR_MAX];
    am_env env = am_default_env();
    if (am_model_build(&g_model, &g_lattice, &env, err, sizeof err) != AM_OK) {
        board_out("board_sim: ");
        board_out(name);
        board_out(": ");
        board_out(err);
        board_out("\n");
        return 1;
    }
    am_eval_def def = am_default_eval();
    def.cycles = 1;
    am_result r;
    am_evaluate(&g_model, &g_state, &def, &r);
    board_out(name);
    put_hex(" hash=", r.hash);
    put_int(" voxels=", r.voxels);
    put_int(" steps=", r.steps);
    board_out(r.diverged ? " diverged=1\n" : "\n");
    return 0;
}

int main(void)
{
    char err[AM_ERR_MAX];
    int bad = 0;
    if (am_scene_build(&g_lattice, "sphere:6", err, sizeof err) != AM_OK) {
        board_out("board_sim: sphere:6: ");
        board_out(err);
        board_out("\n");
        board_exit(1);
    }
    bad |= evaluate("scene=sphere:6");

    am_geno_def gd = am_default_geno();
    gd.repr = AM_REPR_DCT;
    gd.nx = gd.ny = gd.nz = 6;
    am_rng rng;
    am_rng_seed(&rng, 1);
    if (am_genome_init(&g_genome, &gd, &rng, err, sizeof err) != AM_OK ||
        am_genome_to_lattice(&g_genome, NULL, &g_geno, &g_lattice, err, sizeof err) != AM_OK) {
        board_out("board_sim: the genome of seed 1: ");
        board_out(err);
        board_out("\n");
        board_exit(1);
    }
    bad |= evaluate("genome=dct:6:seed1");
    put_int("stack_used=", (long)board_stack_used());
    board_out("\n");
    board_exit(bad);
}
