/*
 * bench.c -- `dtdel bench`, the paper's experiment (DESIGN 10), and
 * `dtdel seq-bench`, whole sequences of deletions.
 *
 * Per dataset and size (a bcase): DT(S) is built once by the engine and
 * once by CGAL; the vertices to delete are drawn from a seeded generator,
 * the same for every row, and sparse degree buckets are topped up
 * (--bucket-min).  For each vertex and row, cgal first (its result is the
 * reference), the deletion alone is timed with a monotonic clock: the
 * median of up to --reps R runs (default 5) while they take under
 * rep_budget_s together, after a warm-up run dropped when another follows
 * (the rows run one after another on the same vertex, and a row's first
 * run pays for the caches and branch predictors the row before trained;
 * --reps 1 times that single cold run).  Its result is compared with
 * CGAL's, and the vertex re-inserted untimed, so that the next deletion
 * starts from DT(S) again.
 *
 * The comparison: the canonical form of the cells incident to the deleted
 * vertex's neighbours (everything a deletion can change) must equal
 * CGAL's; on the first deletion of each case with n <= 20000 the whole
 * triangulation is compared too.  A mismatch is counted and written in the
 * match column (0); it is a bug.  The cgal row is the reference: its
 * match column is 1 by definition.
 *
 * The "insert" row: after the deletion rows of a vertex, our re-insertion
 * of it, the cost a deletion is measured against (target: deleting costs
 * at most 2x re-inserting, at every degree).  Each repetition deletes the
 * vertex with the default strategy and re-inserts it, both timed, up to
 * PAIR_REPS kept within pair_budget_s.  Its match column: the local hash
 * after the re-insertion equals the one taken on the intact DT(S).  Before
 * it comes "<default>-paired" (auto-paired): the median of those
 * deletions, each timed right before the re-insertion it is compared with
 * (the default's own row ran earlier, and the machine's speed drifts); its
 * match column compares the first deletion with CGAL's.  Neither row has
 * tets_created or phases; counting builds write neither.
 *
 * Phases: counting builds (build/count/dtdel) write only the engine rows,
 * with their phase split, to PHASEDIR/<dataset>.csv; the timing build then
 * copies those phase columns into its own rows (same seed, same sample).
 */
#include "bench/bench.h"
#include "bench/buckets.h"
#include "dtdel/alloc.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* Repetitions of a row go on while they took less than this together:
 * five runs for the slowest deletions compared within a few percent (the
 * moment curve at degree 1023, `build/dtdel bench --dataset moment`); a
 * run of CGAL's rows and of the slow variants takes longer, and is kept
 * alone.                                                               */
static const double rep_budget_s = 20e-3;

/* A case: `deletions` vertices drawn at random, then, per degree bucket
 * (buckets.h) with fewer than `bucket_min` of them, more drawn at random
 * among the vertices of that bucket until it has bucket_min or all of
 * them (bench_sample): a random sample leaves the tails of the degree
 * distribution a handful of deletions, whose medians move from run to
 * run.  The moment curve's vertices have one degree per case, and the
 * large helix cases cost seconds a deletion: no top-up there.          */
typedef struct bcase { const char *dataset; uint32_t n, deletions, bucket_min; } bcase;

static const bcase full_cases[] = {
    {"moment", 8, 6, 0}, {"moment", 16, 6, 0}, {"moment", 32, 6, 0}, {"moment", 64, 6, 0},
    {"moment", 128, 6, 0}, {"moment", 256, 6, 0}, {"moment", 512, 5, 0}, {"moment", 1024, 4, 0},
    {"helix", 1000, 12, 12}, {"helix", 4000, 12, 12}, {"helix", 16000, 12, 0}, {"helix", 64000, 10, 0},
    {"uniform", 100000, 150, 20}, {"sphere", 100000, 150, 20}, {"bunny", 0, 100, 20},
    {"grid", 8000, 60, 20}, {"cosphere", 4000, 60, 20}, {NULL, 0, 0, 0}};
static const bcase quick_cases[] = {
    {"moment", 16, 3, 0}, {"moment", 64, 3, 0}, {"moment", 256, 3, 0}, {"moment", 512, 2, 0},
    {"helix", 1000, 6, 6}, {"helix", 16000, 6, 0},
    {"uniform", 20000, 40, 8}, {"sphere", 20000, 40, 8}, {"bunny", 10000, 20, 8},
    {"grid", 1000, 20, 8}, {"cosphere", 1000, 20, 8}, {NULL, 0, 0, 0}};

typedef struct phase_row { uint32_t n, vertex; char variant[24]; double ph[4]; uint64_t tets; } phase_row;

static int cmp_phase(const void *a, const void *b)
{
    const phase_row *x = a, *y = b;
    if (x->n != y->n) return x->n < y->n ? -1 : 1;
    if (x->vertex != y->vertex) return x->vertex < y->vertex ? -1 : 1;
    return strcmp(x->variant, y->variant);
}

/* Loads PHASEDIR/<dataset>.csv written by a counting build, if any. */
static phase_row *load_phases(const char *dir, const char *dataset, size_t *n)
{
    *n = 0;
    if (!dir) return NULL;
    char path[512], line[1024];
    snprintf(path, sizeof path, "%s/%s.csv", dir, dataset);
    FILE *f = fopen(path, "r");
    if (!f) return NULL;
    size_t cap = 256;
    phase_row *a = dd_malloc(cap * sizeof *a);
    if (!fgets(line, sizeof line, f)) { fclose(f); dd_mfree(a); return NULL; }   /* header */
    while (a && fgets(line, sizeof line, f)) {
        phase_row r;
        char ds[64];
        unsigned long long tets;
        if (sscanf(line, "%63[^,],%u,%u,%*u,%*d,%23[^,],%*f,%llu,%lf,%lf,%lf,%lf", ds, &r.n, &r.vertex,
                   r.variant, &tets, &r.ph[0], &r.ph[1], &r.ph[2], &r.ph[3]) != 9)
            continue;
        r.tets = tets;
        if (*n == cap) {
            phase_row *b = dd_realloc(a, 2 * cap * sizeof *a);
            if (!b) break;
            a = b;
            cap *= 2;
        }
        a[(*n)++] = r;
    }
    fclose(f);
    if (a) qsort(a, *n, sizeof *a, cmp_phase);
    return a;
}

static const phase_row *find_phase(const phase_row *a, size_t n, uint32_t np, uint32_t v, const char *var)
{
    phase_row key;
    key.n = np;
    key.vertex = v;
    snprintf(key.variant, sizeof key.variant, "%s", var);
    return a ? bsearch(&key, a, n, sizeof *a, cmp_phase) : NULL;
}

/* Local canonical hash of the row's result around the neighbours nb. */
static int local_hash(const row *r, dd_tri *t, dd_cgal *g, const uint32_t *nb, uint32_t k, uint64_t *h)
{
    int32_t *a = NULL;
    size_t n = 0;
    int bad = r->kind == ROW_ENGINE ? dd_local_canonical(t, nb, k, &a, &n) != DD_OK
                                    : dd_cgal_local_canonical(g, nb, k, &a, &n);
    if (!bad) *h = dd_canonical_hash(a, n);
    dd_mfree(a);
    return bad;
}

/* The insert row hashes the engine's triangulation like an engine row. */
static const row insert_row = {"insert", ROW_ENGINE};

/* The deletions of case c under --scale. */
static uint32_t deletions_of(const bcase *c, double scale)
{
    return (uint32_t)((double)c->deletions * scale + 0.5);
}

/* The vertices case c deletes, into *out (*nout of them; malloc'd): k
 * drawn at random (draw_vertex, in the order drawn; marked in used),
 * then the top-up of the buckets with fewer than bmin (see bcase), each
 * from its unused vertices at random, in increasing bucket order.  0, or
 * -1 when out of memory.                                              */
static int bench_sample(dd_tri *t, uint32_t np, uint32_t k, uint32_t bmin, uint64_t *x, unsigned char *used,
                        uint32_t **out, uint32_t *nout)
{
    enum { NB = 64 };                                /* buckets of 64-bit degrees */
    uint32_t have[NB] = {0}, *pool = NULL;
    uint8_t *bk = NULL;                              /* bucket of each candidate, else NB */
    uint32_t *v = dd_malloc((size_t)np * sizeof *v);
    if (!v) return -1;
    uint32_t n = 0;
    for (; n < k; n++) v[n] = draw_vertex(t, x, np, used);
    if (bmin > 0) {
        bk = dd_malloc((size_t)np * sizeof *bk);
        pool = dd_malloc((size_t)np * sizeof *pool);
        if (!bk || !pool) { dd_mfree(v); dd_mfree(bk); dd_mfree(pool); return -1; }
        for (uint32_t i = 0; i < n; i++) have[dd_degree_bucket(dd_degree(t, v[i]))]++;
        for (uint32_t i = 0; i < np; i++)                /* each degree once */
            bk[i] = dd_is_vertex(t, i) && !used[i] ? (uint8_t)dd_degree_bucket(dd_degree(t, i)) : NB;
        for (int b = 0; b < NB; b++) {
            if (have[b] >= bmin) continue;
            uint32_t m = 0;
            for (uint32_t i = 0; i < np; i++)
                if (bk[i] == b) pool[m++] = i;
            for (; have[b] < bmin && m > 0; have[b]++) {     /* a draw without replacement */
                uint32_t j = rand_below(x, m);
                v[n++] = pool[j];
                used[pool[j]] = 1;
                pool[j] = pool[--m];
            }
        }
    }
    dd_mfree(bk);
    dd_mfree(pool);
    *out = v;
    *nout = n;
    return 0;
}

/* Repetitions to run under the rule above: max_reps, and a warm-up
 * before them when there is more than one. */
static int runs_for(int max_reps)
{
    return max_reps > 1 ? max_reps + 1 : max_reps;
}

/* The median of the repetitions kept: all but the warm-up, if another
 * followed it. */
static double kept_median(double *us, int reps, int max_reps)
{
    return max_reps > 1 && reps > 1 ? median_of(us + 1, (size_t)(reps - 1)) : median_of(us, (size_t)reps);
}

/* Repetitions kept by the insert row and its paired deletion row (when
 * the other rows keep more than one): their quotient is read against the
 * target "deleting costs at most twice re-inserting" within a few
 * percent, where the other rows' ratios to CGAL are read within tens of
 * percent, and five repetitions leave it a spread of tens of percent
 * from one bench run to the next (`make bench`, the bunny's vertices of
 * degree 64 and more).  The runs stop once the deletions and
 * re-insertions took pair_budget_s together.                           */
#define PAIR_REPS 15
static const double pair_budget_s = 40e-3;

/* The options of a bench run (dtdel bench --help). */
typedef struct bench_opts {
    const bcase *cases;           /* the mode's                           */
    const char *outdir, *phasedir, *only;
    uint64_t seed;
    double scale;
    int max_reps, bucket_min;     /* bucket_min -1: each case's own       */
    int counting;                 /* a counting build: engine rows only,
                                     with their phases                    */
} bench_opts;

/* A run: its options, its rows in order (cgal first), the open CSV with
 * its dataset and that dataset's phases, the mismatches and the
 * progress (deletions done of the total, in cases' parts).             */
typedef struct bench_run {
    bench_opts o;
    row rows[32];
    size_t nr;
    const char *open_ds;
    FILE *csv;
    phase_row *ph;
    size_t nph;
    long mismatches;
    double total_work, done_work, t_start, last_print;
} bench_run;

/* A case under way: its points, DT(S) in the engine and in CGAL (g for
 * the CGAL rows, ref for the whole-triangulation comparison; none in a
 * counting build), the sample, and scratch for a vertex's neighbours.  */
typedef struct bench_case {
    const bcase *c;
    double *pts;
    uint32_t np, k;               /* k: the random part of the sample     */
    dd_tri *t;
    dd_cgal *g, *ref;
    unsigned char *used;
    uint32_t *nb, *sample, ns;
} bench_case;

/* The vertex whose rows are being timed: its neighbours (in the case's
 * nb), the engine's local hash of the intact DT(S) for the insert row
 * (pre, if pre_ok), and CGAL's local hash of its deletion (refh, once
 * the cgal row ran: have_ref).                                         */
typedef struct bench_vertex {
    uint32_t it, v, deg, hull, nnb;
    uint64_t pre, refh;
    int pre_ok, have_ref;
} bench_vertex;

/* The "insert" row of vertex bv and its paired deletion row (see the
 * top): 0, or -1 when a deletion or re-insertion failed (dd_errmsg(t)
 * says why).  Each repetition deletes the vertex with the default
 * strategy and re-inserts it, each timed.  *med, *del_med: the medians
 * of the re-insertions and of the deletions; *match: the local hash
 * after the first re-insertion equals bv->pre; *del_match: the one
 * after the first deletion equals CGAL's, bv->refh.                    */
static int time_insert(dd_tri *t, const bench_vertex *bv, const uint32_t *nb, int max_reps, double *med,
                       double *del_med, int *match, int *del_match)
{
    const int keep = max_reps > 1 ? PAIR_REPS : max_reps;
    double us[PAIR_REPS + 1], ds[PAIR_REPS + 1], spent = 0;
    int reps = 0;
    *match = *del_match = 0;
    while (reps < runs_for(keep) && (reps == 0 || spent < pair_budget_s)) {
        double t0 = now_seconds();
        if (dd_delete(t, bv->v) != DD_OK) return -1;
        double t1 = now_seconds();
        uint64_t h = 0;
        if (reps == 0)
            *del_match = bv->have_ref && !local_hash(&insert_row, t, NULL, nb, bv->nnb, &h) && h == bv->refh;
        double t2 = now_seconds();
        if (dd_reinsert(t, bv->v) != DD_OK) return -1;
        double t3 = now_seconds();
        ds[reps] = 1e6 * (t1 - t0);
        us[reps++] = 1e6 * (t3 - t2);
        spent += (t1 - t0) + (t3 - t2);
        if (reps == 1) *match = bv->pre_ok && !local_hash(&insert_row, t, NULL, nb, bv->nnb, &h) && h == bv->pre;
    }
    *med = kept_median(us, reps, keep);
    *del_med = kept_median(ds, reps, keep);
    return 0;
}

/* Whether the row's whole triangulation equals ref's. */
static int full_equal(const row *r, dd_tri *t, dd_cgal *g, dd_cgal *ref)
{
    int32_t *a = NULL, *b = NULL;
    size_t na = 0, nb = 0;
    int ok = !row_canonical(r, t, g, &a, &na) && !dd_cgal_canonical(ref, &b, &nb) && same_canonical(a, na, b, nb);
    dd_mfree(a);
    dd_mfree(b);
    return ok;
}

/* Parses the bench's arguments into *o: 0, or the exit status of a usage
 * error (already reported).                                            */
static int parse_bench_args(int argc, char **argv, bench_opts *o)
{
    const char *mode = "full";
    *o = (bench_opts){NULL, "results", NULL, NULL, 1, 1.0, 5, -1, 0};
#ifdef DD_COUNTERS
    o->counting = 1;
#endif
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--mode") && i + 1 < argc) mode = argv[++i];
        else if (!strcmp(argv[i], "--out") && i + 1 < argc) o->outdir = argv[++i];
        else if (!strcmp(argv[i], "--phases") && i + 1 < argc) o->phasedir = argv[++i];
        else if (!strcmp(argv[i], "--dataset") && i + 1 < argc) o->only = argv[++i];
        else if (!strcmp(argv[i], "--reps") && i + 1 < argc) {
            char *end;
            long r = strtol(argv[++i], &end, 10);
            if (*end || r < 1 || r > 5) return usage_error("bench", "--reps wants 1 to 5, got '%s'", argv[i]);
            o->max_reps = (int)r;
        }
        else if (!strcmp(argv[i], "--bucket-min") && i + 1 < argc) {
            char *end;
            long b = strtol(argv[++i], &end, 10);
            if (*end || end == argv[i] || b < 0 || b > 1000)
                return usage_error("bench", "--bucket-min wants 0 to 1000, got '%s'", argv[i]);
            o->bucket_min = (int)b;
        }
        else if (!strcmp(argv[i], "--scale") && i + 1 < argc) {
            char *end;
            o->scale = strtod(argv[++i], &end);
            if (*end || !(o->scale > 0) || o->scale > 1000)
                return usage_error("bench", "--scale wants a positive number, got '%s'", argv[i]);
        } else if (!strcmp(argv[i], "--seed") && i + 1 < argc) {
            if (parse_u64(argv[++i], &o->seed)) return usage_error("bench", "--seed wants a non-negative integer%s", "");
        } else return usage_error("bench", "unexpected argument '%s'", argv[i]);
    }
    o->cases = !strcmp(mode, "full") ? full_cases : !strcmp(mode, "quick") ? quick_cases : NULL;
    if (!o->cases) return usage_error("bench", "--mode is quick or full, got '%s'", mode);
    return 0;
}

/* The rows, cgal first (its result is the reference of every other
 * row), and the progress's total: the deletions of the cases run.      */
static void start_run(bench_run *b)
{
    row all[32];
    size_t na = all_rows(all, 32);
    for (size_t i = 0; i < na; i++)
        if (all[i].kind == ROW_CGAL) b->rows[b->nr++] = all[i];
    for (size_t i = 0; i < na; i++)
        if (all[i].kind != ROW_CGAL) b->rows[b->nr++] = all[i];
    b->t_start = now_seconds();
    b->last_print = -10;
    for (const bcase *c = b->o.cases; c->dataset; c++)
        if (!b->o.only || !strcmp(b->o.only, c->dataset)) b->total_work += deletions_of(c, b->o.scale);
}

/* Makes OUTDIR/<dataset>.csv the open CSV (a new file with its header,
 * the dataset's phases loaded) unless it already is.  0, or EXIT_INPUT
 * after a message.                                                     */
static int open_dataset(bench_run *b, const char *dataset)
{
    if (b->open_ds && !strcmp(b->open_ds, dataset)) return 0;
    if (b->csv) fclose(b->csv);
    dd_mfree(b->ph);
    b->ph = NULL;
    char path[512];
    snprintf(path, sizeof path, "%s/%s.csv", b->o.outdir, dataset);
    b->csv = fopen(path, "w");
    if (!b->csv) { fprintf(stderr, "dtdel bench: cannot write %s\n", path); return EXIT_INPUT; }
    fprintf(b->csv, "dataset,n,vertex,degree,on_hull,variant,us,tets_created,link_us,locate_us,conflict_us,sew_us,match\n");
    b->open_ds = dataset;
    b->ph = load_phases(b->o.phasedir, dataset, &b->nph);
    return 0;
}

/* Builds case c (points, both triangulations, the sample) into *bc,
 * which free_case frees whatever happened.  0, or EXIT_INPUT after a
 * message.                                                             */
static int setup_case(const bench_run *b, const bcase *c, bench_case *bc)
{
    const bench_opts *o = &b->o;
    char msg[512];
    *bc = (bench_case){.c = c};
    if (dd_gen(c->dataset, c->n, o->seed, &bc->pts, &bc->np, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "dtdel bench: %s\n", msg);
        return EXIT_INPUT;
    }
    if (dd_create(&bc->t, bc->pts, bc->np, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "dtdel bench: %s %u: %s\n", c->dataset, bc->np, msg);
        return EXIT_INPUT;
    }
    /* counting runs time no CGAL row: no CGAL triangulation needed */
    bc->g = o->counting ? NULL : dd_cgal_build(bc->pts, bc->np);
    bc->ref = !o->counting && bc->np <= 20000 ? dd_cgal_build(bc->pts, bc->np) : NULL;
    uint32_t k = deletions_of(c, o->scale);
    if (k < 1) k = 1;
    if (k > dd_num_vertices(bc->t)) k = dd_num_vertices(bc->t);
    bc->k = k;
    uint64_t x = (o->seed + c->n) * 0x9E3779B97F4A7C15ull | 1;
    bc->used = dd_calloc(bc->np, 1);
    bc->nb = dd_malloc((bc->np + 1) * sizeof *bc->nb);
    uint32_t bmin = o->bucket_min >= 0 ? (uint32_t)o->bucket_min : (uint32_t)((double)c->bucket_min * o->scale + 0.5);
    if (!bc->used || !bc->nb || bench_sample(bc->t, bc->np, k, bmin, &x, bc->used, &bc->sample, &bc->ns)) {
        fprintf(stderr, "dtdel bench: out of memory\n");
        return EXIT_INPUT;
    }
    return 0;
}

static void free_case(bench_case *bc)
{
    dd_mfree(bc->used);
    dd_mfree(bc->nb);
    dd_mfree(bc->sample);
    dd_mfree(bc->pts);
    dd_free(bc->t);
    dd_cgal_free(bc->g);
    dd_cgal_free(bc->ref);
}

/* Times row r's deletion of the vertex (see the top), re-inserting it
 * after each run: *med the median kept, *h the local hash of the first
 * result (changed when, on the case's first vertex, the whole
 * triangulation differs from CGAL's), *st the engine's statistics of the
 * last run.  0, or 1 when a deletion or re-insertion failed.          */
static int time_row(const bench_run *b, bench_case *bc, const bench_vertex *bv, const row *r, double *med,
                    uint64_t *h, dd_delete_stats *st)
{
    const int max_reps = b->o.max_reps;
    double us[6], spent = 0;
    int reps = 0, bad = 0, hashed = 0;
    *h = 0;
    memset(st, 0, sizeof *st);
    while (reps < runs_for(max_reps) && (reps == 0 || spent < rep_budget_s) && !bad) {
        double t0 = now_seconds();
        bad = row_delete(r, bc->t, bc->g, bv->v, b->o.seed + bv->it + (uint64_t)reps);
        double t1 = now_seconds();
        if (bad) break;
        us[reps++] = 1e6 * (t1 - t0);
        spent += t1 - t0;
        if (r->kind == ROW_ENGINE) dd_last_delete_stats(bc->t, st);
        if (!hashed) { bad = local_hash(r, bc->t, bc->g, bc->nb, bv->nnb, h); hashed = 1; }
        if (!bad && bv->it == 0 && reps == 1 && bc->ref && dd_cgal_remove(bc->ref, bv->v) == 0) {
            if (!full_equal(r, bc->t, bc->g, bc->ref)) *h ^= 1;    /* force a mismatch */
            dd_cgal_reinsert(bc->ref, bv->v);
        }
        if (row_reinsert(r, bc->t, bc->g, bv->v)) { bad = 1; break; }
    }
    if (!bad) *med = kept_median(us, reps, max_reps);
    return bad;
}

/* The CSV columns every row of the vertex starts with, up to variant. */
static void write_row_start(const bench_run *b, const bench_case *bc, const bench_vertex *bv)
{
    fprintf(b->csv, "%s,%u,%u,%u,%u,", bc->c->dataset, bc->np, bv->v, bv->deg, bv->hull);
}

/* The CSV row of row r: its median, tets created and phases (its own in
 * a counting build, else the counting build's if loaded), its match.  */
static void write_row(const bench_run *b, const bench_case *bc, const bench_vertex *bv, const row *r, double med,
                      const dd_delete_stats *st, int match)
{
    FILE *csv = b->csv;
    write_row_start(b, bc, bv);
    fprintf(csv, "%s,%.3f,", r->name, med);
    if (r->kind == ROW_ENGINE) fprintf(csv, "%llu", (unsigned long long)st->tets_created);
    const phase_row *pr = b->o.counting ? NULL : find_phase(b->ph, b->nph, bc->np, bv->v, r->name);
    if (b->o.counting && r->kind == ROW_ENGINE)
        fprintf(csv, ",%.3f,%.3f,%.3f,%.3f", st->link_us, st->locate_us, st->conflict_us, st->sew_us);
    else if (pr)
        fprintf(csv, ",%.3f,%.3f,%.3f,%.3f", pr->ph[0], pr->ph[1], pr->ph[2], pr->ph[3]);
    else
        fprintf(csv, ",,,,");
    fprintf(csv, ",%d\n", match);
}

/* The paired and insert rows of the vertex (time_insert), written. */
static void insert_rows(bench_run *b, bench_case *bc, const bench_vertex *bv)
{
    double med, del_med;
    int match, del_match;
    if (time_insert(bc->t, bv, bc->nb, b->o.max_reps, &med, &del_med, &match, &del_match)) {
        fprintf(stderr, "dtdel bench: %s %u: insert row failed on vertex %u: %s\n", bc->c->dataset, bc->np, bv->v,
                dd_errmsg(bc->t));
        b->mismatches++;
        return;
    }
    b->mismatches += !match + !del_match;
    write_row_start(b, bc, bv);
    fprintf(b->csv, "%s-paired,%.3f,,,,,,%d\n", dd_variant_name(0), del_med, del_match);
    write_row_start(b, bc, bv);
    fprintf(b->csv, "insert,%.3f,,,,,,%d\n", med, match);
}

/* Every row of sample vertex number it: the deletion rows, timed and
 * compared with CGAL's (cgal first), then the paired and insert rows.
 * A vertex CGAL refuses to delete is skipped.                          */
static void bench_vertex_rows(bench_run *b, bench_case *bc, uint32_t it)
{
    bench_vertex bv = {.it = it, .v = bc->sample[it]};
    dd_tri *t = bc->t;
    bv.deg = dd_degree(t, bv.v);
    bv.hull = (uint32_t)dd_on_hull(t, bv.v);
    bv.nnb = dd_neighbors(t, bv.v, bc->nb, bc->np);
    /* the engine's local hash on the intact DT(S), for the insert row */
    bv.pre_ok = !b->o.counting && !local_hash(&insert_row, t, NULL, bc->nb, bv.nnb, &bv.pre);
    for (size_t ri = 0; ri < b->nr; ri++) {
        const row *r = &b->rows[ri];
        if (b->o.counting && r->kind != ROW_ENGINE) continue;
        double med = 0;
        uint64_t h;
        dd_delete_stats st;
        if (time_row(b, bc, &bv, r, &med, &h, &st)) {
            if (r->kind == ROW_CGAL) return;                  /* CGAL refuses: skip the vertex */
            fprintf(stderr, "dtdel bench: %s %u: %s failed on vertex %u: %s\n", bc->c->dataset, bc->np, r->name,
                    bv.v, r->kind == ROW_ENGINE ? dd_errmsg(t) : "");
            b->mismatches++;
            continue;
        }
        if (r->kind == ROW_CGAL) { bv.refh = h; bv.have_ref = 1; }
        int match = b->o.counting ? 1 : bv.have_ref && h == bv.refh;
        if (!match) b->mismatches++;
        write_row(b, bc, &bv, r, med, &st, match);
    }
    if (!b->o.counting) insert_rows(b, bc, &bv);
}

/* Counts sample vertex it done (the top-up shares its case's part) and
 * says how far the run is, at most every 2 s and at a case's end.      */
static void report_progress(bench_run *b, const bench_case *bc, uint32_t it)
{
    b->done_work += (double)bc->k / bc->ns;
    double el = now_seconds() - b->t_start;
    if (el - b->last_print >= 2.0 || it + 1 == bc->ns) {
        b->last_print = el;
        fprintf(stderr, "  %-9s n=%-7u %3.0f%% of the deletions done, %4.0f s elapsed\n", bc->c->dataset, bc->np,
                100.0 * b->done_work / b->total_work, el);
    }
}

/* Case c: built, every sample vertex's rows written, freed.  0, or
 * EXIT_INPUT after a message.                                          */
static int run_case(bench_run *b, const bcase *c)
{
    bench_case bc;
    int rc = setup_case(b, c, &bc);
    for (uint32_t it = 0; !rc && it < bc.ns; it++) {
        bench_vertex_rows(b, &bc, it);
        report_progress(b, &bc, it);
    }
    if (!rc) fflush(b->csv);
    free_case(&bc);
    return rc;
}

int cmd_bench(int argc, char **argv)
{
    bench_run b = {0};
    int rc = parse_bench_args(argc, argv, &b.o);
    if (rc) return rc;
    mkdir(b.o.outdir, 0777);
    start_run(&b);
    for (const bcase *c = b.o.cases; !rc && c->dataset; c++) {
        if (b.o.only && strcmp(b.o.only, c->dataset)) continue;
        rc = open_dataset(&b, c->dataset);
        if (!rc) rc = run_case(&b, c);
    }
    if (b.csv) fclose(b.csv);
    dd_mfree(b.ph);
    if (rc) return rc;
    fprintf(stderr, "  bench: %ld mismatches%s\n", b.mismatches, b.mismatches ? " -- A BUG" : "");
    return b.mismatches ? EXIT_INPUT : 0;
}

/* ---- seq-bench ------------------------------------------------------------- */

/* `dtdel seq-bench`: the whole-workload companion of the per-vertex bench.
 * A fraction of the vertices is deleted one after another, with no
 * re-insertion and no repetition, so caches and branch predictors see a
 * real workload rather than the same deletion again.  Each run starts
 * from its own DT(S), built untimed (build-bench times construction), and
 * times its deletions whole; every run's final triangulation must equal
 * CGAL's.  The runs: the same seeded random order for both engines; the
 * same points in a spatial order (Morton order of the points, computed
 * here, so neither engine's internals) for both; and our dd_delete_set,
 * which takes its own order (CGAL's range remove() keeps the order it is
 * given, so its spatial-order run is the fair comparison there).        */

/* Morton key of p in the box lo..hi: 21 bits an axis, interleaved. */
static uint64_t morton_key(const double *p, const double lo[3], const double hi[3])
{
    uint64_t key = 0, c[3];
    for (int a = 0; a < 3; a++) {
        double f = hi[a] > lo[a] ? (p[a] - lo[a]) / (hi[a] - lo[a]) : 0;
        c[a] = (uint64_t)(f * 2097151.0);
    }
    for (int b = 20; b >= 0; b--)
        for (int a = 0; a < 3; a++) key = key << 1 | (c[a] >> b & 1);
    return key;
}

typedef struct keyed { uint64_t key; uint32_t v; } keyed;

static int cmp_keyed(const void *a, const void *b)
{
    const keyed *x = a, *y = b;
    return x->key < y->key ? -1 : x->key > y->key ? 1 : (x->v > y->v) - (x->v < y->v);
}

/* One run: deletes order[0..k) from DT(S) (t, or a fresh one; freed),
 * with strategy var one at a time, or as one set, or by CGAL (var NULL).
 * Seconds, or -1 with a message; *canon: the final canonical form.      */
static double seq_run(const double *xyz, uint32_t np, dd_tri *t, const uint32_t *order, uint32_t k,
                      const char *var, int set, int32_t **canon, size_t *nc)
{
    char msg[512];
    double secs = -1;
    *canon = NULL;
    if (!var) {
        dd_cgal *g = dd_cgal_build(xyz, np);
        if (!g) { fprintf(stderr, "dtdel seq-bench: CGAL could not build DT(S)\n"); return -1; }
        double t0 = now_seconds();
        uint32_t i = 0;
        while (i < k && !dd_cgal_remove(g, order[i])) i++;
        secs = now_seconds() - t0;
        if (i < k) { fprintf(stderr, "dtdel seq-bench: CGAL cannot delete vertex %u\n", order[i]); secs = -1; }
        if (secs >= 0 && dd_cgal_canonical(g, canon, nc)) secs = -1;
        dd_cgal_free(g);
        return secs;
    }
    if (!t && dd_create(&t, xyz, np, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "dtdel seq-bench: %s\n", msg);
        return -1;
    }
    double t0 = now_seconds();
    dd_status s = DD_OK;
    uint32_t i = 0;
    if (set) s = dd_delete_set_with(t, order, k, var);
    else
        while (i < k && (s = dd_delete_with(t, order[i], var)) == DD_OK) i++;
    secs = now_seconds() - t0;
    if (s != DD_OK) {
        fprintf(stderr, "dtdel seq-bench: %s cannot delete %s%u: %s\n", var, set ? "the set, " : "vertex ",
                set ? k : order[i], dd_errmsg(t));
        secs = -1;
    }
    if (secs >= 0 && dd_canonical(t, canon, nc) != DD_OK) secs = -1;
    dd_free(t);
    return secs;
}

int cmd_seq_bench(int argc, char **argv)
{
    const char *dataset = "uniform", *var = "auto";
    uint64_t n = 1000000, seed = 1;
    double frac = 0.1;
    for (int i = 1, rc; i < argc; i++) {
        if (take_dataset_option("seq-bench", argc, argv, &i, &dataset, &seed, &rc)) {
            if (rc) return rc;
        } else if (!strcmp(argv[i], "--variant")) {
            if (++i >= argc) return usage_error("seq-bench", "--variant needs a name%s", "");
            var = argv[i];
        } else if (!strcmp(argv[i], "--fraction")) {
            char *end = NULL;
            if (++i >= argc) return usage_error("seq-bench", "--fraction needs a number%s", "");
            frac = strtod(argv[i], &end);
            if (*end || !(frac > 0) || frac > 0.9)
                return usage_error("seq-bench", "--fraction wants a number in (0, 0.9], got '%s'", argv[i]);
        } else if (parse_u64(argv[i], &n) || n > UINT32_MAX / 8) {
            return usage_error("seq-bench", "N must be a non-negative integer, got '%s'", argv[i]);
        }
    }
    row r;
    if (!find_row(var, &r) || r.kind != ROW_ENGINE) {
        fprintf(stderr, "dtdel seq-bench: unknown engine strategy '%s' (see dtdel variants)\n", var);
        return EXIT_INPUT;
    }
    double *xyz;
    uint32_t np;
    char msg[512];
    int rc = gen_points("seq-bench", dataset, n, seed, &xyz, &np);
    if (rc) return rc;
    dd_tri *t = NULL;
    if (dd_create(&t, xyz, np, msg, sizeof msg) != DD_OK) {
        fprintf(stderr, "dtdel seq-bench: %s\n", msg);
        dd_mfree(xyz);
        return EXIT_INPUT;
    }
    uint32_t *rnd = dd_malloc((size_t)np * sizeof *rnd), *spa = dd_malloc((size_t)np * sizeof *spa);
    keyed *kv = dd_malloc((size_t)np * sizeof *kv);
    if (!rnd || !spa || !kv) {
        fprintf(stderr, "dtdel seq-bench: out of memory\n");
        dd_mfree(rnd); dd_mfree(spa); dd_mfree(kv); dd_mfree(xyz); dd_free(t);
        return EXIT_INPUT;
    }
    /* The vertices (duplicates merged away are not), shuffled by a seeded
     * xorshift; the first k are deleted, leaving at least 5 vertices.    */
    uint32_t nv = 0;
    for (uint32_t i = 0; i < np; i++)
        if (dd_is_vertex(t, i)) rnd[nv++] = i;
    uint64_t x = seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull;
    for (uint32_t i = nv; i > 1; i--) {
        uint32_t j = rand_below(&x, i), s = rnd[i - 1];
        rnd[i - 1] = rnd[j];
        rnd[j] = s;
    }
    uint32_t k = (uint32_t)(frac * nv);
    if (nv < 5 || k > nv - 5) k = nv < 5 ? 0 : nv - 5;
    /* the same points in Morton order */
    double lo[3] = {xyz[0], xyz[1], xyz[2]}, hi[3] = {xyz[0], xyz[1], xyz[2]};
    for (uint32_t i = 0; i < np; i++)
        for (int a = 0; a < 3; a++) {
            double c = xyz[3 * (size_t)i + a];
            lo[a] = c < lo[a] ? c : lo[a];
            hi[a] = c > hi[a] ? c : hi[a];
        }
    for (uint32_t i = 0; i < k; i++) kv[i] = (keyed){morton_key(xyz + 3 * (size_t)rnd[i], lo, hi), rnd[i]};
    qsort(kv, k, sizeof *kv, cmp_keyed);
    for (uint32_t i = 0; i < k; i++) spa[i] = kv[i].v;
    dd_mfree(kv);
    /* the runs: ours and CGAL's in random order, in Morton order, ours as a set */
    const struct { const char *name; const uint32_t *order; int engine, set; } runs[] = {
        {"random order", rnd, 1, 0}, {"random order", rnd, 0, 0}, {"Morton order", spa, 1, 0},
        {"Morton order", spa, 0, 0}, {"one set (dd_delete_set, its own order)", rnd, 1, 1}};
    enum { NRUN = 5 };
    double secs[NRUN];
    int32_t *canon[NRUN] = {NULL};
    size_t nc[NRUN] = {0};
    rc = 0;
    for (int i = 0; i < NRUN && !rc; i++) {
        secs[i] = seq_run(xyz, np, i == 0 ? t : NULL, runs[i].order, k, runs[i].engine ? var : NULL, runs[i].set,
                          &canon[i], &nc[i]);
        if (i == 0) t = NULL;                   /* seq_run freed it */
        if (secs[i] < 0) rc = EXIT_INPUT;
    }
    dd_free(t);
    int same = !rc;
    for (int i = 0; i < NRUN && same; i++)
        same = same_canonical(canon[i], nc[i], canon[1], nc[1]);
    if (!rc) {
        double per = k ? 1e6 / k : 0;
        printf("dataset %s, n = %u, %u of %u vertices deleted one after another (seed %llu), %zu cells left\n",
               dataset, np, k, nv, (unsigned long long)seed, nc[1]);
        for (int i = 0; i < NRUN; i++)
            printf("%-40s %-6s %8.3f s, %7.2f us a deletion\n", runs[i].name, runs[i].engine ? "dtdel" : "cgal",
                   secs[i], secs[i] * per);
        printf("speed ratio dtdel/cgal: %.2f (random order), %.2f (Morton order), %.2f (set against Morton order)\n",
               secs[1] / secs[0], secs[3] / secs[2], secs[3] / secs[4]);
        printf("identical to CGAL: %s\n", same ? "yes" : "NO");
        if (!same) rc = EXIT_INPUT;
    }
    for (int i = 0; i < NRUN; i++) dd_mfree(canon[i]);
    dd_mfree(rnd);
    dd_mfree(spa);
    dd_mfree(xyz);
    return rc;
}
