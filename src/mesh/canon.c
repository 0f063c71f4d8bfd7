/*
 * canon.c -- canonical output (its one builder, dd_canonical_of_cells),
 * its hash, status names and the small accessors of the public header
 * (DESIGN 8).
 *
 * Canonical form: each live cell as its four input indices sorted
 * ascending, -1 for the infinite vertex, the list sorted.  It depends only
 * on the triangulation, never on cell storage order, so it is the key for
 * comparing with CGAL.
 */
#include "mesh/mesh.h"

#include <stdlib.h>
#include <string.h>

const char *dd_status_name(dd_status s)
{
    static const char *const names[DD_NUM_STATUS] = {
        "ok", "out of memory", "i/o error", "parse error", "NaN coordinate",
        "infinite coordinate", "too few points", "collinear points",
        "coplanar points", "unknown vertex", "unknown variant",
        "duplicate point", "dimension would drop", "internal error",
        "bad argument", "unsupported", "unknown cell", "unknown file format"};
    return (unsigned)s < DD_NUM_STATUS ? names[s] : "unknown status";
}

const char *dd_errmsg(const dd_tri *t) { return t->errmsg; }
uint32_t dd_num_input(const dd_tri *t) { return t->np; }
uint32_t dd_num_vertices(const dd_tri *t) { return t->nvert; }
uint32_t dd_num_duplicates(const dd_tri *t) { return t->ndup; }
size_t dd_num_tets(const dd_tri *t) { return t->nlive; }
size_t dd_num_finite_tets(const dd_tri *t) { return t->nfinite; }

uint32_t dd_alias(const dd_tri *t, uint32_t i)
{
    return i < t->np ? t->v2in[t->in2v[i]] : UINT32_MAX;
}

int dd_is_vertex(const dd_tri *t, uint32_t i)
{
    if (i >= t->np) return 0;
    uint32_t v = t->in2v[i];
    return t->v2in[v] == i && t->vcell[v] != DD_NONE;
}

size_t dd_memory_bytes(const dd_tri *t)
{
    /* cells: records (plus the alignment slack), stamp; vertices: xyz,
     * vcell, v2in; inputs: in2v; insertion scratch: the three vectors,
     * the edge hash and table; the location grid and the reusable ids   */
    return (size_t)t->cap_c * (DD_CELL_WORDS * sizeof(uint32_t) + sizeof(dd_mark)) + (t->cell_block ? 64 : 0)
         + (size_t)t->cap_v * (3 * sizeof(double) + 2 * sizeof(uint32_t))
         + (size_t)t->cap_in * sizeof(uint32_t)
         + (t->stack.cap + t->conflict.cap + t->boundary.cap + t->vfree.cap) * sizeof(uint32_t)
         + (t->flip[0].cap + t->flip[1].cap + t->flip[2].cap + t->flip[3].cap + t->flip[4].cap) * sizeof(uint32_t)
         + t->grid.cap * sizeof(uint32_t)
         + (size_t)t->ehash_cap * sizeof(dd_edge_slot)
         + (t->etab ? DD_STAR_MAXV * DD_STAR_MAXV * sizeof(uint32_t) : 0)
         + t->made.cap * sizeof(int64_t);
}

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
    int32_t *a = malloc((n ? n : 1) * 4 * sizeof *a);
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

dd_status dd_canonical(const dd_tri *t, int32_t **tets, size_t *ntets)
{
    uint32_t *live = malloc((t->nlive ? t->nlive : 1) * sizeof *live);
    if (!live) return DD_ERR_NOMEM;
    size_t n = 0;
    for (uint32_t c = 0; c < t->ncell; c++)
        if (dd_tv(t, c)[0] != DD_DEAD) live[n++] = c;
    dd_status s = dd_canonical_of_cells(t, live, n, tets, ntets);
    free(live);
    return s;
}

uint64_t dd_canonical_hash(const int32_t *tets, size_t ntets)
{
    uint64_t h = 0xcbf29ce484222325ull;
    for (size_t i = 0; i < 4 * ntets; i++) {
        uint32_t x = (uint32_t)tets[i];
        for (int b = 0; b < 4; b++) {
            h ^= (x >> (8 * b)) & 0xFF;
            h *= 0x100000001b3ull;
        }
    }
    return h;
}
