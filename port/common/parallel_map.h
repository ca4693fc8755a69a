/* port/common/parallel_map.h: am_port_parallel_map of port.h on threads that share the
 * memory, for the ports that have threads (posix, win32). What the map promises is decided here
 * once: the calling thread is worker 0 and the others are threads of their own (at most
 * PORT_MAX_THREADS in all, never more than there are items); the items are handed out in order
 * under a lock, each exactly once; every item is done even when a thread fails to start (then the
 * map reports that failure); the results are in place (`out` is not read).
 *
 * A port's source includes this file once (the function is am_port_parallel_map unless the source
 * defines PORT_FN(name) to name it otherwise, as port/posix does: am_posix_parallel_map), after
 * defining PORT_MAX_THREADS and the types
 * port_mutex and port_thread, and then defines these static functions:
 *   int  sys_mutex_init(port_mutex* mu)             1, or 0 when it cannot be made
 *   void sys_mutex_lock(port_mutex* mu), sys_mutex_unlock(port_mutex* mu), sys_mutex_destroy(port_mutex* mu)
 *   am_status sys_thread_start(port_thread* t, map_worker* w, char* err, int errsz)
 *       a thread that calls map_loop(w->job, w->id) and ends
 *   void sys_thread_join(port_thread t)             waits for it, and frees it */
#ifndef AMORPH_PORT_PARALLEL_MAP_H
#define AMORPH_PORT_PARALLEL_MAP_H

#ifndef PORT_FN
#define PORT_FN(name) am_port_##name
#endif

typedef struct map_job {
    port_mutex lock;
    int next; /* next item to hand out */
    int n;
    am_port_task task;
    void* ctx;
} map_job;

typedef struct map_worker {
    map_job* job;
    int id;
} map_worker;

static int sys_mutex_init(port_mutex* mu);
static void sys_mutex_lock(port_mutex* mu);
static void sys_mutex_unlock(port_mutex* mu);
static void sys_mutex_destroy(port_mutex* mu);
static am_status sys_thread_start(port_thread* t, map_worker* w, char* err, int errsz);
static void sys_thread_join(port_thread t);

/* worker `worker`'s work: the next item until none is left */
static void map_loop(map_job* job, int worker)
{
    for (;;) {
        sys_mutex_lock(&job->lock);
        int item = job->next < job->n ? job->next++ : -1;
        sys_mutex_unlock(&job->lock);
        if (item < 0) return;
        job->task(job->ctx, item, worker);
    }
}

am_status PORT_FN(parallel_map)(int n, int workers, am_port_task task, void* ctx, void* out, long size, char* err, int errsz)
{
    (void)out; /* the workers share this memory: each result is in place */
    if (workers < 1 || n < 0 || size < 0 || !task) return am_fail(err, errsz, AM_ERR_ARG, "parallel map: %d items on %d workers", n, workers);
    if (workers > PORT_MAX_THREADS) workers = PORT_MAX_THREADS;
    if (workers > n) workers = n > 0 ? n : 1;
    map_job job;
    job.next = 0;
    job.n = n;
    job.task = task;
    job.ctx = ctx;
    if (!sys_mutex_init(&job.lock)) return am_fail(err, errsz, AM_ERR_IO, "parallel map: cannot create a mutex");
    port_thread th[PORT_MAX_THREADS];
    map_worker w[PORT_MAX_THREADS];
    int started = 0;
    am_status st = AM_OK;
    for (int i = 1; i < workers; i++) {
        w[i].job = &job;
        w[i].id = i;
        st = sys_thread_start(&th[i], &w[i], err, errsz);
        if (st != AM_OK) break;
        started = i;
    }
    map_loop(&job, 0); /* finishes every item even when a thread failed to start */
    for (int i = 1; i <= started; i++) sys_thread_join(th[i]);
    sys_mutex_destroy(&job.lock);
    return st;
}

#endif
