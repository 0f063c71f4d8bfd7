/*
 * wbench.c -- `dtdel wbench`: the per-degree deletion tables on
 * weighted points (issue 44, DESIGN 10 and 12), every strategy of the
 * registry against CGAL's Regular_triangulation_3::remove(), in one
 * hidden mode (the bench's: kept; --discard-hidden for the other).
 *
 * The protocol is dtdel bench's (bench.c): per case the regular
 * triangulation is built once by each engine; the vertices to delete are
 * drawn from a seeded generator, the same for every row, sparse degree
 * buckets topped up; for each vertex and row, cgal first, the deletion
 * alone is timed (the median of up to 5 runs after a warm-up, while they
 * take under 20 ms together), its result compared with CGAL's, and the
 * vertex put back untimed (dd_reinsert; CGAL's insert under the same
 * index), so the next deletion starts from the same triangulation.  The
 * CSV is the one dtdel bench writes (build/summarize reads both), with no
 * phase columns and no insert rows.
 *
 * The comparison: the canonical cells incident to the deleted vertex's
 * former neighbours and to the hidden points the deletion made vertices
 * again (CGAL's; together they hold every cell the deletion made), and
 * the whole hidden set; on the first vertex of a case of at most 20000
 * points, the whole triangulation too.  A difference is a mismatch,
 * counted and written in the match column (0).
 *
 * A strategy that answers DD_ERR_UNSUPPORTED has no rows: the command
 * says "n/a" for it once per case (summarize prints n/a for it).  There
 * is no cgal-rnd row: CGAL has no such removal for regular
 * triangulations (sew-full is the engine's own version of it).
 */
#include "bench/wbench.h"
#include "bench/buckets.h"
#include "dtdel/alloc.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* As dtdel bench: repetitions go on while they took less than this. */
static const double rep_budget_s = 20e-3;
#define MAX_REPS 5
#define MAX_ROWS 32
#define FULL_COMPARE_MAX 20000

typedef struct wcase { const char *dataset; uint32_t n, deletions, bucket_min; } wcase;

/* The curves at their high degrees, as dtdel bench (the moment curve's
 * vertices all have degree n - 1; the helix's about 2 sqrt(n)).        */
static const wcase full_cases[] = {
    {"wuniform", 100000, 150, 20}, {"wuniform-most", 100000, 60, 10}, {"molecule", 50000, 80, 10},
    {"wgrid", 8000, 60, 15},       {"wmoment", 64, 6, 0},             {"wmoment", 256, 6, 0},
    {"whelix", 1000, 12, 12},      {"whelix", 16000, 12, 0},          {NULL, 0, 0, 0}};
static const wcase quick_cases[] = {
    {"wuniform", 20000, 40, 8}, {"wuniform-most", 20000, 15, 4}, {"molecule", 10000, 20, 4},
    {"wgrid", 1000, 20, 6},     {"wmoment", 64, 3, 0},           {"wmoment", 256, 3, 0},
    {"whelix", 1000, 6, 4},     {"whelix", 16000, 4, 0},         {NULL, 0, 0, 0}};
/* For tests of the command and of scripts/bench.sh, never for figures. */
static const wcase tiny_cases[] = {
    {"wuniform", 2000, 6, 2}, {"wgrid", 343, 4, 0}, {"wmoment", 32, 2, 0}, {"whelix", 500, 3, 0}, {NULL, 0, 0, 0}};

typedef struct wopts {
    const wcase *cases;
    const char *outdir, *only;
    uint64_t seed;
    double scale;
    int discard;
} wopts;

/* A run: its rows (cgal first), the open CSV, the mismatches. */
typedef struct wrun {
    wopts o;
    const char *rows[MAX_ROWS];   /* engine strategies; NULL = cgal */
    size_t nr;
    FILE *csv;
    const char *open_ds;
    long mismatches;
} wrun;

/* The vertex under way: its degree, neighbours and, once the cgal row
 * ran, the vertices whose cells are compared and CGAL's hashes.        */
typedef struct wvertex {
    uint32_t v, deg, hull, nnb, ncmp, it;
    uint32_t *cmp;                /* neighbours then released: ncmp     */
    uint64_t cells_h, hidden_h;
} wvertex;

static int parse_args(int argc, char **argv, wopts *o)
{
    const char *mode = "full";
    *o = (wopts){NULL, "results/weighted", NULL, 1, 1.0, 0};
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--mode") && i + 1 < argc) mode = argv[++i];
        else if (!strcmp(argv[i], "--out") && i + 1 < argc) o->outdir = argv[++i];
        else if (!strcmp(argv[i], "--dataset") && i + 1 < argc) o->only = argv[++i];
        else if (!strcmp(argv[i], "--discard-hidden")) o->discard = 1;
        else if (!strcmp(argv[i], "--scale") && i + 1 < argc) {
            char *end;
            o->scale = strtod(argv[++i], &end);
            if (*end || !(o->scale > 0) || o->scale > 1000)
                return usage_error("wbench", "--scale wants a positive number, got '%s'", argv[i]);
        } else if (!strcmp(argv[i], "--seed") && i + 1 < argc) {
            if (parse_u64(argv[++i], &o->seed)) return usage_error("wbench", "--seed wants a non-negative integer%s", "");
        } else return usage_error("wbench", "unexpected argument '%s'", argv[i]);
    }
    o->cases = !strcmp(mode, "full") ? full_cases : !strcmp(mode, "quick") ? quick_cases
             : !strcmp(mode, "tiny") ? tiny_cases : NULL;
    if (!o->cases) return usage_error("wbench", "--mode is quick, full or tiny, got '%s'", mode);
    return 0;
}

static int cmp_u32(const void *a, const void *b)
{
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* The sample: k vertices at random, then the buckets with fewer than
 * bmin topped up from their unused vertices (as dtdel bench).  Malloc'd
 * into *out; -1 when out of memory.                                    */
static int sample(const dd_tri *t, uint32_t np, uint32_t k, uint32_t bmin, uint64_t *x, uint32_t **out, uint32_t *nout)
{
    enum { NB = 64 };
    unsigned char *used = dd_calloc(np, 1);
    uint32_t *v = dd_malloc(((size_t)k + (size_t)NB * bmin + 1) * sizeof *v), *pool = dd_malloc((size_t)np * sizeof *pool);
    uint32_t have[NB] = {0}, n = 0, nv = 0;
    if (!used || !v || !pool) { dd_mfree(used), dd_mfree(v), dd_mfree(pool); return -1; }
    for (uint32_t i = 0; i < np; i++) nv += (uint32_t)dd_is_vertex(t, i);
    if (k > nv) k = nv;
    for (; n < k; n++) {
        v[n] = draw_vertex(t, x, np, used);
        have[dd_degree_bucket(dd_degree(t, v[n]))]++;
    }
    for (int b = 0; b < NB && bmin; b++) {
        if (have[b] >= bmin) continue;
        uint32_t m = 0;
        for (uint32_t i = 0; i < np; i++)
            if (!used[i] && dd_is_vertex(t, i) && dd_degree_bucket(dd_degree(t, i)) == b) pool[m++] = i;
        for (; have[b] < bmin && m > 0; have[b]++) {
            uint32_t j = rand_below(x, m);
            v[n++] = pool[j];
            used[pool[j]] = 1;
            pool[j] = pool[--m];
        }
    }
    dd_mfree(used), dd_mfree(pool);
    *out = v;
    *nout = n;
    return 0;
}

static uint64_t hash_ints(const uint32_t *a, size_t n)
{
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < n; i++) h = (h ^ a[i]) * 1099511628211ull;
    return h ^ n;
}

/* Hashes of our cells around cmp and of our hidden set; -1 on failure. */
static int our_hashes(const dd_tri *t, const wvertex *wv, uint64_t *cells, uint64_t *hidden)
{
    int32_t *a = NULL;
    uint32_t *h = NULL;
    size_t na = 0, nh = 0;
    int bad = dd_local_canonical(t, wv->cmp, wv->ncmp, &a, &na) != DD_OK || dd_hidden(t, &h, &nh) != DD_OK;
    if (!bad) *cells = dd_canonical_hash(a, na), *hidden = hash_ints(h, nh);
    dd_mfree(a), dd_mfree(h);
    return bad ? -1 : 0;
}

static int cgal_hashes(const dd_cgal_rb *c, const wvertex *wv, uint64_t *cells, uint64_t *hidden)
{
    int32_t *a = NULL;
    uint32_t *h = NULL;
    size_t na = 0, nh = 0;
    int bad = dd_cgal_rb_local_canonical(c, wv->cmp, wv->ncmp, &a, &na) || dd_cgal_rb_hidden(c, &h, &nh);
    if (!bad) *cells = dd_canonical_hash(a, na), *hidden = hash_ints(h, nh);
    dd_mfree(a), dd_mfree(h);
    return bad ? -1 : 0;
}

static double kept_median(double *us, int reps)
{
    return reps > 1 ? median_of(us + 1, (size_t)(reps - 1)) : median_of(us, (size_t)reps);
}

/* The cgal row of the vertex: CGAL's remove() timed, the compared
 * vertices (its former neighbours and what it released) and CGAL's
 * hashes taken after the first run, the vertex put back each time.
 * 0; 1 when CGAL refuses (the vertex is skipped); -1 on a failure.    */
static int cgal_row(wpair *p, wvertex *wv, double *med)
{
    double us[MAX_REPS + 1], spent = 0;
    int reps = 0;
    while (reps < MAX_REPS + 1 && (reps == 0 || spent < rep_budget_s)) {
        double s;
        int rc = dd_cgal_rb_remove(p->c, wv->v, &s);
        if (rc) return rc == 3 && reps == 0 ? 1 : -1;
        us[reps++] = 1e6 * s;
        spent += s;
        if (reps == 1) {
            const uint32_t *r, *nb;
            size_t nr = dd_cgal_rb_released(p->c, &r), nn = dd_cgal_rb_last_neighbors(p->c, &nb);
            memcpy(wv->cmp, nb, nn * sizeof *nb);
            memcpy(wv->cmp + nn, r, nr * sizeof *r);
            wv->ncmp = (uint32_t)(nn + nr);
            qsort(wv->cmp, wv->ncmp, sizeof *wv->cmp, cmp_u32);
            if (cgal_hashes(p->c, wv, &wv->cells_h, &wv->hidden_h)) return -1;
        }
        const uint32_t *nb;
        dd_cgal_rb_last_neighbors(p->c, &nb);
        if (dd_cgal_rb_insert(p->c, wv->v, p->xyz + 3 * (size_t)wv->v, p->w[wv->v], nb[0], &s)) return -1;
    }
    *med = kept_median(us, reps);
    return 0;
}

/* Whether our whole triangulation equals CGAL's after CGAL removed v
 * (it is put back).                                                    */
static int whole_equal(wpair *p, uint32_t v)
{
    double s;
    if (dd_cgal_rb_remove(p->c, v, &s)) return 0;
    int same = wpair_compare(p->t, p->c) == 0;
    const uint32_t *nb;
    dd_cgal_rb_last_neighbors(p->c, &nb);
    if (dd_cgal_rb_insert(p->c, v, p->xyz + 3 * (size_t)v, p->w[v], nb[0], &s)) same = 0;
    return same;
}

/* An engine row of the vertex.  0 with *med and *match; 1 when the
 * strategy refused weighted points (DD_ERR_UNSUPPORTED); -1 on another
 * failure (a mismatch, said on stderr).                                */
static int engine_row(wpair *p, const wvertex *wv, const char *var, double *med, int *match,
                      uint64_t *tets)
{
    double us[MAX_REPS + 1], spent = 0;
    int reps = 0;
    *match = 0;
    while (reps < MAX_REPS + 1 && (reps == 0 || spent < rep_budget_s)) {
        double t0 = now_seconds();
        dd_status s = dd_delete_with(p->t, wv->v, var);
        double t1 = now_seconds();
        if (s == DD_ERR_UNSUPPORTED) return 1;
        if (s != DD_OK) {
            fprintf(stderr, "dtdel wbench: %s failed on vertex %u: %s\n", var, wv->v, dd_errmsg(p->t));
            return -1;
        }
        us[reps++] = 1e6 * (t1 - t0);
        spent += t1 - t0;
        if (reps == 1) {
            dd_delete_stats st;
            uint64_t ch, hh;
            dd_last_delete_stats(p->t, &st);
            *tets = st.tets_created;
            *match = !our_hashes(p->t, wv, &ch, &hh) && ch == wv->cells_h && hh == wv->hidden_h;
            if (*match && wv->it == 0 && p->np <= FULL_COMPARE_MAX) *match = whole_equal(p, wv->v);
        }
        if (dd_reinsert(p->t, wv->v) != DD_OK) {
            fprintf(stderr, "dtdel wbench: cannot put vertex %u back: %s\n", wv->v, dd_errmsg(p->t));
            return -1;
        }
    }
    *med = kept_median(us, reps);
    return 0;
}

static void csv_row(const wrun *b, const wcase *c, const wpair *p, const wvertex *wv, const char *name, double med,
                    const uint64_t *tets, int match)
{
    fprintf(b->csv, "%s,%u,%u,%u,%u,%s,%.3f,", c->dataset, p->np, wv->v, wv->deg, wv->hull, name, med);
    if (tets) fprintf(b->csv, "%llu", (unsigned long long)*tets);
    fprintf(b->csv, ",,,,,%d\n", match);
}

/* Every row of one vertex; refused[r] marks the strategies found to
 * refuse weighted points in this case (said once, then skipped).       */
static void vertex_rows(wrun *b, const wcase *c, wpair *p, wvertex *wv, unsigned char *refused)
{
    wv->deg = dd_degree(p->t, wv->v);
    wv->hull = (uint32_t)dd_on_hull(p->t, wv->v);
    double med;
    int rc = cgal_row(p, wv, &med);
    if (rc < 0) {
        fprintf(stderr, "dtdel wbench: %s %u: the CGAL reference failed on vertex %u\n", c->dataset, p->np, wv->v);
        b->mismatches++;
    }
    if (rc) return;                                     /* CGAL refuses: skip the vertex */
    csv_row(b, c, p, wv, "cgal", med, NULL, 1);
    for (size_t r = 0; r < b->nr; r++) {
        if (refused[r]) continue;
        int match;
        uint64_t tets = 0;
        rc = engine_row(p, wv, b->rows[r], &med, &match, &tets);
        if (rc == 1) {
            refused[r] = 1;
            continue;
        }
        if (rc < 0 || !match) b->mismatches++;
        if (rc == 0) csv_row(b, c, p, wv, b->rows[r], med, &tets, match);
    }
}

static int open_csv(wrun *b, const char *dataset)
{
    if (b->open_ds && !strcmp(b->open_ds, dataset)) return 0;
    if (b->csv) fclose(b->csv);
    char path[512];
    snprintf(path, sizeof path, "%s/%s.csv", b->o.outdir, dataset);
    b->csv = fopen(path, "w");
    if (!b->csv) { fprintf(stderr, "dtdel wbench: cannot write %s\n", path); return EXIT_INPUT; }
    fprintf(b->csv, "dataset,n,vertex,degree,on_hull,variant,us,tets_created,link_us,locate_us,conflict_us,sew_us,match\n");
    b->open_ds = dataset;
    return 0;
}

static int run_case(wrun *b, const wcase *c)
{
    wpair p;
    int rc = wpair_build("wbench", c->dataset, c->n, b->o.seed, b->o.discard, &p);
    if (rc) return rc;
    uint32_t k = (uint32_t)((double)c->deletions * b->o.scale + 0.5), ns = 0;
    uint32_t bmin = (uint32_t)((double)c->bucket_min * b->o.scale + 0.5), *vs = NULL;
    uint64_t x = (b->o.seed + c->n) * 0x9E3779B97F4A7C15ull | 1;
    unsigned char refused[MAX_ROWS] = {0};
    wvertex wv = {0};
    wv.cmp = dd_malloc(((size_t)p.np + 1) * sizeof *wv.cmp);
    if (!wv.cmp || sample(p.t, p.np, k ? k : 1, bmin, &x, &vs, &ns)) {
        fprintf(stderr, "dtdel wbench: out of memory\n");
        rc = EXIT_INPUT;
    }
    const double t0 = now_seconds();
    for (uint32_t i = 0; !rc && i < ns; i++) {
        wv.v = vs[i];
        wv.it = i;
        vertex_rows(b, c, &p, &wv, refused);
    }
    fprintf(stderr, "  %-13s n=%-7u %u deletions, %.0f s\n", c->dataset, p.np, ns, now_seconds() - t0);
    int any = 0;
    for (size_t r = 0; r < b->nr; r++) {
        if (!refused[r]) continue;
        if (!any++) printf("%s n=%u: n/a (%s):", c->dataset, p.np, dd_status_name(DD_ERR_UNSUPPORTED));
        printf(" %s", b->rows[r]);
    }
    if (any) printf("\n");
    fflush(b->csv);
    dd_mfree(vs), dd_mfree(wv.cmp);
    wpair_free(&p);
    return rc;
}

int cmd_wbench(int argc, char **argv)
{
    wrun b = {0};
    int rc = parse_args(argc, argv, &b.o);
    if (rc) return rc;
    mkdir(b.o.outdir, 0777);
    for (size_t i = 0; dd_variant_name(i) && b.nr < MAX_ROWS; i++) b.rows[b.nr++] = dd_variant_name(i);
    printf("wbench: weighted deletions against CGAL's Regular_triangulation_3::remove(), %s\n",
           wmode_name(b.o.discard));
    for (const wcase *c = b.o.cases; !rc && c->dataset; c++) {
        if (b.o.only && strcmp(b.o.only, c->dataset)) continue;
        rc = open_csv(&b, c->dataset);
        if (!rc) rc = run_case(&b, c);
        fflush(stdout);
    }
    if (b.csv) fclose(b.csv);
    if (rc) return rc;
    printf("wbench: %ld mismatches%s\n", b.mismatches, b.mismatches ? " -- A BUG" : "");
    return b.mismatches ? EXIT_INPUT : 0;
}

/* ---- shared with wbench_edits.c -------------------------------------------- */

const char *wmode_name(int discard)
{
    return discard ? "hidden points discarded" : "hidden points kept";
}

int wpair_build(const char *cmd, const char *dataset, uint32_t n, uint64_t seed, int discard, wpair *p)
{
    char msg[512];
    *p = (wpair){.discard = discard};
    if (dd_gen_weighted(dataset, n, seed, &p->xyz, &p->w, &p->np, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "dtdel %s: %s\n", cmd, msg);
        return EXIT_INPUT;
    }
    if (!p->w) {
        fprintf(stderr, "dtdel %s: %s is not a weighted dataset\n", cmd, dataset);
        wpair_free(p);
        return EXIT_INPUT;
    }
    if (dd_create_ex(&p->t, p->xyz, p->w, p->np, discard ? DD_DISCARD_HIDDEN : 0, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "dtdel %s: %s %u: %s\n", cmd, dataset, p->np, msg);
        p->t = NULL;
        wpair_free(p);
        return EXIT_INPUT;
    }
    if (!(p->c = dd_cgal_rb_build(p->xyz, p->w, p->np, discard))) {
        fprintf(stderr, "dtdel %s: %s %u: CGAL cannot build the regular triangulation\n", cmd, dataset, p->np);
        wpair_free(p);
        return EXIT_INPUT;
    }
    return 0;
}

void wpair_free(wpair *p)
{
    dd_free(p->t);
    dd_cgal_rb_free(p->c);
    dd_mfree(p->xyz), dd_mfree(p->w);
    *p = (wpair){0};
}

long wpair_compare(const dd_tri *t, const dd_cgal_rb *c)
{
    int32_t *a = NULL, *b = NULL;
    uint32_t *ha = NULL, *hb = NULL;
    size_t na = 0, nb = 0, nha = 0, nhb = 0;
    long bad = 0;
    if (dd_canonical(t, &a, &na) != DD_OK || dd_cgal_rb_canonical(c, &b, &nb) || !same_canonical(a, na, b, nb))
        bad++;
    if (dd_hidden(t, &ha, &nha) != DD_OK || dd_cgal_rb_hidden(c, &hb, &nhb) || nha != nhb ||
        (nha && memcmp(ha, hb, nha * sizeof *ha)))
        bad++;
    dd_mfree(a), dd_mfree(b), dd_mfree(ha), dd_mfree(hb);
    return bad;
}
