/* The evolver's executor (amorph/evo.h) on the program's port: the port's parallel map (threads, or
 * MPI ranks in the MPI build) and its clock. */
#include "cmd.h"

static am_status port_map(void* self, int n, int workers, am_task_fn task, void* ctx, void* out, long size, char* err, int errsz)
{
    (void)self;
    return am_port_parallel_map(n, workers, task, ctx, out, size, err, errsz);
}

static double port_now(void* self)
{
    (void)self;
    return am_port_now();
}

am_executor tool_executor(int workers)
{
    am_executor ex = {port_map, port_now, NULL, workers}; /* the evolver keeps workers within 1..AM_MAX_WORKERS */
    return ex;
}
