/*
 * alloc.c -- the state of the test builds' allocation faults
 * (dtdel/alloc.h): how many allocations the process made, and the number
 * of the one to refuse.  Here because src/dtdel, where alloc.h sits, has
 * no objects, and geom is the lowest layer that has: every layer may use
 * it.  Release builds keep nothing but dd_alloc_faults.
 */
#include "dtdel/alloc.h"

#ifdef DD_TEST_BUILD
unsigned long dd_alloc_calls;
unsigned long dd_alloc_fail_at;
const int dd_alloc_faults = 1;

/* How many allocations are left before the one to refuse (0: none). */
static unsigned long left(unsigned long calls, unsigned long at)
{
    return at > calls ? at - calls : 0;
}

long dd_alloc_control(int fail, long value)
{
    unsigned long calls = __atomic_load_n(&dd_alloc_calls, __ATOMIC_RELAXED);
    unsigned long at = __atomic_load_n(&dd_alloc_fail_at, __ATOMIC_RELAXED);
    unsigned long rest = left(calls, at), v = value > 0 ? (unsigned long)value : 0;
    if (fail) {
        __atomic_store_n(&dd_alloc_fail_at, v ? calls + v : 0, __ATOMIC_RELAXED);
        return (long)rest;
    }
    __atomic_store_n(&dd_alloc_calls, v, __ATOMIC_RELAXED);      /* the count restarts at v; */
    __atomic_store_n(&dd_alloc_fail_at, rest ? v + rest : 0, __ATOMIC_RELAXED);   /* a pending fault keeps its distance */
    return (long)calls;
}
#else
const int dd_alloc_faults = 0;
#endif
