/*
 * canon.h -- canonical forms under a renumbering, for the checks that
 * compare two triangulations whose input indices differ (the fuzz
 * interpreter's build from scratch, the weighted soak's CGAL side, whose
 * indices only grow).  Header-only, all static.
 */
#ifndef DD_CANON_H
#define DD_CANON_H

#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

static inline int canon_cmp4(const void *a, const void *b)
{
    const int32_t *x = a, *y = b;
    for (int i = 0; i < 4; i++)
        if (x[i] != y[i]) return x[i] < y[i] ? -1 : 1;
    return 0;
}

static inline int canon_cmp_u32(const void *a, const void *b)
{
    const uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* Renames the indices of a canonical cell list c[0 .. 4 nc) through map
 * (-1, the infinite vertex, stays), then sorts each cell and the list
 * again: the canonical form of the same cells under the new names.     */
static inline void canon_remap(int32_t *c, size_t nc, const uint32_t *map)
{
    for (size_t i = 0; i < 4 * nc; i++)
        if (c[i] >= 0) c[i] = (int32_t)map[c[i]];
    for (size_t i = 0; i < nc; i++) {
        int32_t *o = c + 4 * i;
        for (int x = 1; x < 4; x++)
            for (int y = x; y > 0 && o[y - 1] > o[y]; y--) {
                const int32_t tmp = o[y];
                o[y] = o[y - 1];
                o[y - 1] = tmp;
            }
    }
    if (nc > 1) qsort(c, nc, 4 * sizeof *c, canon_cmp4);
}

/* Renames a list of indices through map and sorts it. */
static inline void canon_remap_list(uint32_t *a, size_t n, const uint32_t *map)
{
    for (size_t i = 0; i < n; i++) a[i] = map[a[i]];
    if (n > 1) qsort(a, n, sizeof *a, canon_cmp_u32);
}

#endif
