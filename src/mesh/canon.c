/*
 * canon.c -- canonical output: its one builder, dd_canonical_of_cells
 * (DESIGN 8), behind dd_canonical and dd_local_canonical (src/access.c,
 * src/api.c).
 *
 * Canonical form: each live cell as its four input indices sorted
 * ascending, -1 for the infinite vertex, the list sorted.  It depends only
 * on the triangulation, never on cell storage order, so it is the key for
 * comparing with CGAL.
 */
#include "mesh/mesh.h"
#include "dtdel/alloc.h"

#include <stdlib.h>
#include <string.h>

static void sort4(int32_t *a)
{
    for (int i = 1; i < 4; i++) {
        int32_t x = a[i];
        int j = i - 1;
        while (j >= 0 && a[j] > x) { a[j + 1] = a[j]; j--; }
        a[j + 1] = x;
    }
}

static int cmp_tet(const void *a, const void *b)
{
    const int32_t *p = a, *q = b;
    for (int i = 0; i < 4; i++)
        if (p[i] != q[i]) return p[i] < q[i] ? -1 : 1;
    return 0;
}

dd_status dd_canonical_of_cells(const dd_tri *t, const uint32_t *cells, size_t n, int32_t **tets, size_t *ntets)
{
    int32_t *a = dd_malloc((n ? n : 1) * 4 * sizeof *a);
    if (!a) return DD_ERR_NOMEM;
    for (size_t k = 0; k < n; k++) {
        const uint32_t *v = dd_tv(t, cells[k]);
        for (int i = 0; i < 4; i++) a[4 * k + (size_t)i] = dd_input_index(t, v[i]);
        sort4(a + 4 * k);
    }
    qsort(a, n, 4 * sizeof *a, cmp_tet);
    size_t u = 0;
    for (size_t k = 0; k < n; k++)
        if (u == 0 || cmp_tet(a + 4 * (u - 1), a + 4 * k)) memmove(a + 4 * u++, a + 4 * k, 4 * sizeof *a);
    *tets = a;
    *ntets = u;
    return DD_OK;
}
