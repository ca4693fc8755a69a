/* amorph repro: the reference evolution of `make repro`, in memory, without a run folder. */
#include "evolve_cmd.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- repro: the reference evolution of `make repro` ---- */

static const char repro_help[] =
    "usage: amorph repro [--KEY VALUE]...\n"
    "Runs the reference evolution of `make repro` in memory (no files) and prints a line of its\n"
    "figures (evaluations, generations, best fitness, voxel steps, wall time), then the line\n"
    "repro_hash=<16 hex digits>: the run hash over every genome, fitness and final simulation\n"
    "state of the run. Every build on every platform must print the same value. The reference\n"
    "run: GMX, 6^3 workspace, population 8, 24 evaluations, 1 cycle of 100 steps after a\n"
    "relaxation of 50 to 400 steps (the last 100 its release window); flags (configuration keys)\n"
    "change it.\n";

int cmd_repro(tool_ctx* c, int argc, char** argv)
{
    evo_opts o;
    memset(&o, 0, sizeof o);
    static const char* const ref[][2] = {
        {"representation", "gmx"}, {"workspace", "6"}, {"population", "8"}, {"evaluations", "24"}, {"cycles", "1"},
        {"period_steps", "100"}, {"relax_min_steps", "50"}, {"relax_max_steps", "400"}, {"release_steps", "100"}, {"gmx_points", "12"},
        {"seed", "2024"}, {"threads", "1"},
    };
    for (size_t k = 0; k < sizeof ref / sizeof ref[0]; k++) {
        o.key[o.nflags] = ref[k][0];
        o.val[o.nflags++] = ref[k][1];
    }
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            fputs(repro_help, stdout);
            return 0;
        }
        const char* a = argv[i];
        int r = parse_common(argc, argv, &i, &o, "repro");
        if (r == 2) return 2;
        if (r == 0 || o.config || o.out || o.resume || o.print_config)
            return tool_unknown_option("repro", a, repro_help);
    }
    am_evo_def d;
    if (build_def(&o, NULL, NULL, 0, &d, "repro")) return 2;
    char err[AM_ERR_MAX];
    if (am_evo_init(&c->evo, &d, err, sizeof err) != AM_OK) return tool_usage_error("repro: %s", err);
    const double t0 = am_port_now();
    const am_executor ex = tool_executor(workers_of(&d));
    while (!am_evo_done(&c->evo))
        if (am_evo_generation(&c->evo, c->work, &ex, NULL, err, sizeof err) != AM_OK) {
            fprintf(stderr, "amorph: repro: %s\n", err);
            return 1;
        }
    long voxel_steps = 0;
    for (int i = 0; i < d.population; i++) voxel_steps += (long)c->evo.pop[i].voxels * c->evo.pop[i].steps;
    printf("evaluations=%ld generations=%ld best_fitness=%.9g final_population_voxel_steps=%ld wall_s=%.2f\n", c->evo.evaluations,
           c->evo.generation, c->evo.best.fitness, voxel_steps, am_port_now() - t0);
    printf("repro_hash=%016llx\n", (unsigned long long)am_evo_hash(&c->evo));
    return 0;
}

