/* tools/stats_cmd.h: what amorph stats's command (tools/cmd_stats.c: its options, reading the run
 * folders) and its tables (tools/stats_table.c: the numbers at each count, Markdown, JSON) share:
 * the runs and groups read. Not on the board. */
#ifndef AMORPH_TOOLS_STATS_CMD_H
#define AMORPH_TOOLS_STATS_CMD_H

#include "cmd.h"
#include "stats.h"

#define STATS_MAX_RUNS TOOL_STATS_MAX_N /* run folders in all */
#define STATS_MAX_GROUPS 16
#define STATS_MAX_COUNTS 500            /* checkpoints (every N evaluations) of one run */
#define STATS_NAME_MAX 64
#define STATS_GAIT_FILE "gait30.json"
/* the sustained score: gait30.json's sustained_travel, the travel per cycle over cycles 11-30 (the
 * centre of mass's displacement from the end of cycle 10 to the end of cycle 30, over 20: docs/evolve.md,
 * score); its cycle_travel must hold the 30 cycles */
#define STATS_SUSTAINED_TO 30

#define GAITS 5
extern const char* const stats_gait_names[GAITS]; /* "still", "flop", "scoot", "bounce", "roll" */

typedef struct stats_run {
    const char* dir;
    int group;
    long last;                       /* evaluations of its last log.csv row */
    int counts;                      /* checkpoints reached: val[0 .. counts-1] */
    double val[STATS_MAX_COUNTS];    /* best fitness so far at (k + 1) * every evaluations, m */
    double sustained;                /* --score sustained: its best robot's, m per cycle */
    int gait;                        /* index into gait_names */
} stats_run;

typedef struct stats_group {
    char name[STATS_NAME_MAX];
    int runs[STATS_MAX_RUNS];
    int n;
    int counts;                      /* checkpoints every run of the group reached */
    int gaits[GAITS];
} stats_group;

/* the command's state: large, so static (one command runs at a time; tools/cmd_stats.c) */
typedef struct stats_set {
    stats_run runs[STATS_MAX_RUNS];
    int nruns;
    stats_group groups[STATS_MAX_GROUPS];
    int ngroups;
    long every;
    int sustained;                   /* --score sustained */
    /* --pair A,B: the pairs compared, as group indices (none given: every pair) */
    int npairs;
    int pair[STATS_MAX_GROUPS * (STATS_MAX_GROUPS - 1) / 2][2];
    tool_stats_work work;
    double a[STATS_MAX_RUNS], b[STATS_MAX_RUNS];
} stats_set;
extern stats_set stats_S;

/* the most counts (checkpoints) a group reached */
int stats_max_counts(void);
/* the tables of stats_S: Markdown, or one JSON object */
void stats_markdown(am_text* t);
void stats_json(am_text* t);

#endif
