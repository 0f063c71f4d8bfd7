/*
 * alloc.h -- the engine's one allocation path.
 *
 * Every allocation in src/ and variants/ goes through these four calls, so
 * that a test build can make any one of them fail (issue 46); the release
 * build maps them straight onto the C library's.  They behave as malloc,
 * calloc, realloc and free.
 */
#ifndef DD_ALLOC_H
#define DD_ALLOC_H

#include <stdlib.h>

static inline void *dd_malloc(size_t size) { return malloc(size); }
static inline void *dd_calloc(size_t n, size_t size) { return calloc(n, size); }
static inline void *dd_realloc(void *p, size_t size) { return realloc(p, size); }
static inline void dd_mfree(void *p) { free(p); }

#endif
