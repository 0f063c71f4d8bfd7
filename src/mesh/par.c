/*
 * par.c -- the engine's threads (issue 59): how many a call may use, and
 * the one way they are started.
 *
 * POSIX threads, not OpenMP: the engine is a library that Python and C
 * programs load, and its parallel steps are a handful of coarse jobs a
 * call (one per thread, joined before the call returns), which need no
 * runtime of their own, no thread pool that outlives the call, nothing
 * that a fork of the caller's process could find half-held.
 *
 * The count.  Per triangulation (t->nthreads), set by dd_create_ex's
 * DD_THREADS(n) or DD_THREADS_ALL and by dd_set_threads; without either,
 * 1, or the value of the environment variable DTDEL_THREADS when it is
 * set ("all" or 0: every core).  No global state: the variable is read
 * when a triangulation is made.
 */
#include "mesh/mesh.h"

#include <pthread.h>
#include <stdlib.h>
#include <unistd.h>

unsigned dd_cores(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1u : n > DD_THREADS_MAX ? DD_THREADS_MAX : (unsigned)n;
}

unsigned dd_threads_default(void)
{
    const char *e = getenv("DTDEL_THREADS");
    if (!e || !*e) return 1;
    if (e[0] == 'a' && e[1] == 'l' && e[2] == 'l' && !e[3]) return dd_cores();
    char *end;
    unsigned long n = strtoul(e, &end, 10);
    if (*end || e[0] == '-') return 1;          /* not a count: as if unset */
    if (n == 0) return dd_cores();
    return n > DD_THREADS_MAX ? DD_THREADS_MAX : (unsigned)n;
}

typedef struct job {
    void (*fn)(void *arg, unsigned j);
    void *arg;
    unsigned j;
} job;

static void *run_job(void *p)
{
    const job *b = p;
    b->fn(b->arg, b->j);
    return NULL;
}

void dd_run_threads(unsigned n, void (*fn)(void *arg, unsigned j), void *arg)
{
    enum { MAXJ = DD_THREADS_MAX };
    pthread_t th[MAXJ];
    job jobs[MAXJ];
    int started[MAXJ];
    if (n > MAXJ) n = MAXJ;
    for (unsigned j = 1; j < n; j++) {
        jobs[j] = (job){fn, arg, j};
        started[j] = pthread_create(&th[j], NULL, run_job, &jobs[j]) == 0;
    }
    fn(arg, 0);
    for (unsigned j = 1; j < n; j++) {
        if (started[j]) pthread_join(th[j], NULL);
        else fn(arg, j);              /* no thread to be had: the caller's */
    }
}
