/*
 * alloc.h -- the engine's one allocation path.
 *
 * Every allocation in src/ and variants/ goes through these four calls,
 * so that a test build can make any one of them fail (issue 46); the
 * release build maps them straight onto the C library's.  They behave as
 * malloc, calloc, realloc and free (memory from one may be freed by the
 * other, in both builds).
 *
 * Test builds (-DDD_TEST_BUILD) count every dd_malloc, dd_calloc and
 * dd_realloc, process-wide, and refuse the one whose number is set by
 * dd_test_control's DD_TEST_ALLOC_FAIL (dtdel/stats_types.h): it returns
 * NULL, as the C library's would out of memory, and allocates nothing
 * (a refused dd_realloc leaves its block as it was).  The count and the
 * number live in src/geom/alloc.c, the lowest layer with objects; they
 * are atomics, so threads may allocate at once (tests/test_threads.c).
 */
#ifndef DD_ALLOC_H
#define DD_ALLOC_H

#include <stdlib.h>

/* 1 in test builds, whose allocations can be made to fail; 0 else.     */
extern const int dd_alloc_faults;

#ifdef DD_TEST_BUILD
extern unsigned long dd_alloc_calls;     /* allocations so far            */
extern unsigned long dd_alloc_fail_at;   /* the one refused: its number in
                                            dd_alloc_calls (0: none)      */

/* Counts one allocation; 1 when it is the one to refuse. */
static inline int dd_alloc_refused(void)
{
    unsigned long n = __atomic_add_fetch(&dd_alloc_calls, 1, __ATOMIC_RELAXED);
    return n == __atomic_load_n(&dd_alloc_fail_at, __ATOMIC_RELAXED);
}

/* dd_test_control's DD_TEST_ALLOC_FAIL (fail = 1) and DD_TEST_ALLOC_COUNT
 * (fail = 0): sets the control to value, returns what it was.          */
long dd_alloc_control(int fail, long value);

static inline void *dd_malloc(size_t size) { return dd_alloc_refused() ? NULL : malloc(size); }
static inline void *dd_calloc(size_t n, size_t size) { return dd_alloc_refused() ? NULL : calloc(n, size); }
static inline void *dd_realloc(void *p, size_t size) { return dd_alloc_refused() ? NULL : realloc(p, size); }
#else
static inline void *dd_malloc(size_t size) { return malloc(size); }
static inline void *dd_calloc(size_t n, size_t size) { return calloc(n, size); }
static inline void *dd_realloc(void *p, size_t size) { return realloc(p, size); }
#endif
static inline void dd_mfree(void *p) { free(p); }

#endif
