/*
 * refine_bench.c -- `dtdel refine-bench`: a mesh generator's refinement
 * loop against CGAL's.  N uniform points in the unit cube; K times, the
 * largest queued cell (squared circumradius, among finite cells whose
 * circumcentre is in the cube: refine_rule.h) gets its circumcentre
 * inserted.  Our queue is fed by dd_created_cells alone (an entry is
 * live while its cell is alive and its stamp is the id's latest); CGAL's
 * by find_conflicts and insert_in_hole (cgal/cgal_refine.h).  Both use
 * the same rule function, so both insert the same points and must end in
 * the same triangulation: compared by canonical hash, a mismatch counted
 * and printed.  What make bench writes to results/refine.txt.
 */
#include "bench/bench.h"
#include "bench/refine_rule.h"
#include "cgal/cgal_refine.h"
#include "dtdel/alloc.h"

#include <stdlib.h>
#include <string.h>

static const double unit_lo[3] = {0, 0, 0}, unit_hi[3] = {1, 1, 1};

/* The rule as CGAL's loop calls it (refine_rule.h). */
static int rule_callback(const double *const q[4], const double lo[3], const double hi[3], double c[3], double *r2)
{
    return refine_rule(q, lo, hi, c, r2);
}

typedef struct entry {
    double r2, p[3];
    int32_t v[4];
    dd_cell_id c;
    uint32_t stamp;
} entry;

/* Our loop's state: the queue (a binary max-heap in refine_before's
 * order), a stamp per cell id, the points by input index.               */
typedef struct refiner {
    dd_tri *t;
    entry *heap;
    size_t nheap, capheap;
    uint32_t *stamp, gen;
    size_t capstamp;
    double *pts;
    size_t cappts;
    int32_t *verts;       /* the new cells' vertices, 4 a cell */
    size_t capverts;
    double core;          /* seconds in dd_insert_from + reading new cells */
} refiner;

static int grow(void *pp, size_t *cap, size_t need, size_t size)
{
    if (need <= *cap) return 0;
    size_t c = *cap ? *cap : 1024;
    while (c < need) c *= 2;
    void *p;
    memcpy(&p, pp, sizeof p);
    p = dd_realloc(p, c * size);
    if (!p) return -1;
    memcpy(pp, &p, sizeof p);
    *cap = c;
    return 0;
}

static int before(const entry *a, const entry *b)
{
    return refine_before(a->r2, a->v, b->r2, b->v);
}

static int heap_push(refiner *r, const entry *e)
{
    if (grow(&r->heap, &r->capheap, r->nheap + 1, sizeof *r->heap)) return -1;
    size_t i = r->nheap++;
    while (i > 0 && before(e, &r->heap[(i - 1) / 2])) {
        r->heap[i] = r->heap[(i - 1) / 2];
        i = (i - 1) / 2;
    }
    r->heap[i] = *e;
    return 0;
}

static entry heap_pop(refiner *r)
{
    entry top = r->heap[0], last = r->heap[--r->nheap];
    size_t i = 0;
    for (;;) {
        size_t k = 2 * i + 1;
        if (k >= r->nheap) break;
        if (k + 1 < r->nheap && before(&r->heap[k + 1], &r->heap[k])) k++;
        if (!before(&r->heap[k], &last)) break;
        r->heap[i] = r->heap[k];
        i = k;
    }
    if (r->nheap) r->heap[i] = last;
    return top;
}

/* Stamps and queues the cells the last edit made. */
static int queue_created(refiner *r, double t0)
{
    const dd_cell_id *cells;
    size_t n;
    if (dd_created_cells(r->t, &cells, &n) != DD_OK) return -1;
    if (grow(&r->verts, &r->capverts, 4 * n, sizeof *r->verts)) return -1;
    if (dd_cells_vertices(r->t, cells, n, r->verts) != DD_OK) return -1;
    r->core += now_seconds() - t0;
    if (grow(&r->stamp, &r->capstamp, (size_t)dd_cell_end(r->t), sizeof *r->stamp)) return -1;
    for (size_t k = 0; k < n; k++) {
        entry e;
        memcpy(e.v, r->verts + 4 * k, sizeof e.v);
        r->stamp[cells[k]] = ++r->gen;
        if (e.v[0] < 0 || e.v[1] < 0 || e.v[2] < 0 || e.v[3] < 0) continue;
        for (int i = 1; i < 4; i++)                                /* ascending indices */
            for (int j = i; j > 0 && e.v[j - 1] > e.v[j]; j--) {
                int32_t s = e.v[j];
                e.v[j] = e.v[j - 1];
                e.v[j - 1] = s;
            }
        const double *q[4];
        for (int i = 0; i < 4; i++) q[i] = r->pts + 3 * (size_t)e.v[i];
        if (!refine_rule(q, unit_lo, unit_hi, e.p, &e.r2)) continue;
        e.c = cells[k];
        e.stamp = r->gen;
        if (heap_push(r, &e)) return -1;
    }
    return 0;
}

/* K insertions (fewer if the queue runs dry): *done of them; 0, or -1
 * on a failure (a message on stderr).                                   */
static int refine_ours(refiner *r, uint32_t k, uint32_t *done)
{
    *done = 0;
    if (queue_created(r, now_seconds())) return -1;
    r->core = 0;
    while (*done < k && r->nheap > 0) {
        const entry e = heap_pop(r);
        if (!dd_cell_alive(r->t, e.c) || r->stamp[e.c] != e.stamp) continue;
        uint32_t index;
        const double t0 = now_seconds();
        const dd_status s = dd_insert_from(r->t, e.p, e.c, &index);
        if (s == DD_ERR_DUPLICATE) continue;
        if (s != DD_OK) {
            fprintf(stderr, "dtdel refine-bench: %s\n", dd_errmsg(r->t));
            return -1;
        }
        if (grow(&r->pts, &r->cappts, 3 * ((size_t)index + 1), sizeof *r->pts)) return -1;
        memcpy(r->pts + 3 * (size_t)index, e.p, sizeof e.p);
        ++*done;
        if (queue_created(r, t0)) return -1;
    }
    return 0;
}

int cmd_refine_bench(int argc, char **argv)
{
    uint64_t n = 100000, k = 100000, seed = 1;
    const num_opt opts[] = {{NULL, &n}, {"--inserts", &k}, {"--seed", &seed}};
    int rc = parse_num_opts("refine-bench", argc, argv, opts, (int)(sizeof opts / sizeof *opts));
    if (rc) return rc;
    if (n < 8) return usage_error("refine-bench", "N must be at least %s", "8");
    double *xyz = NULL;
    uint32_t np;
    if ((rc = gen_points("refine-bench", "uniform", n, seed, &xyz, &np))) return rc;
    refiner r = {0};
    char msg[256];
    dd_cgalr *g = dd_cgalr_build(xyz, np);
    if (!g || dd_create(&r.t, xyz, np, msg, sizeof msg) != DD_OK ||
        grow(&r.pts, &r.cappts, 3 * (size_t)np, sizeof *r.pts)) {
        fprintf(stderr, "dtdel refine-bench: cannot build the triangulations\n");
        dd_cgalr_free(g), dd_free(r.t), dd_mfree(xyz);
        return EXIT_INPUT;
    }
    memcpy(r.pts, xyz, 3 * (size_t)np * sizeof *xyz);
    uint32_t ours_done = 0, cgal_done = 0;
    const double t0 = now_seconds();
    rc = refine_ours(&r, (uint32_t)k, &ours_done);
    const double t1 = now_seconds();
    rc |= dd_cgalr_refine(g, (uint32_t)k, unit_lo, unit_hi, rule_callback, &cgal_done);
    const double t2 = now_seconds();
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    int same = !rc && dd_canonical(r.t, &a, &na) == DD_OK && !dd_cgalr_canonical(g, &b, &nb) &&
               ours_done == cgal_done && same_canonical(a, na, b, nb);
    const int mismatches = !same;
    const double core_c = dd_cgalr_core_seconds(g);
    printf("refine: %u uniform points, %u circumcentres of the largest cell inserted (CGAL %u); "
           "dtdel %.2f us an insertion (dd_insert_from the queued cell, queue fed by dd_created_cells), "
           "CGAL find_conflicts + insert_in_hole %.2f us (%.2fx); triangulation part "
           "(dd_insert_from + dd_cells_vertices vs find_conflicts + insert_in_hole) %.2f us vs %.2f us (%.2fx); "
           "hashes %016llx / %016llx; %d mismatches\n",
           np, ours_done, cgal_done, 1e6 * (t1 - t0) / (ours_done ? ours_done : 1),
           1e6 * (t2 - t1) / (cgal_done ? cgal_done : 1), (t2 - t1) / (t1 - t0),
           1e6 * r.core / (ours_done ? ours_done : 1), 1e6 * core_c / (cgal_done ? cgal_done : 1),
           core_c / (r.core > 0 ? r.core : 1e-9),
           (unsigned long long)dd_canonical_hash(a, na), (unsigned long long)dd_canonical_hash(b, nb), mismatches);
    dd_mfree(a), dd_mfree(b);
    dd_cgalr_free(g);
    dd_free(r.t);
    dd_mfree(r.heap), dd_mfree(r.stamp), dd_mfree(r.pts), dd_mfree(r.verts), dd_mfree(xyz);
    return rc ? EXIT_INPUT : mismatches ? EXIT_INPUT : 0;
}
