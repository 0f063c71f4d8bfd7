/*
 * order.c -- the insertion order of a construction and of the batch
 * calls (DESIGN 5).
 *
 * Owns: BRIO rounds and the 3D Hilbert curve.  Each kept point draws its
 * BRIO round from a hash of its input index with a fixed seed: rounds
 * grow by a factor of 8 (the last holds about 7/8 of the points, the one
 * before 7/64, ..., the first about 64 points or fewer).  Insertion goes
 * round by round, smallest first, each round along a 3D Hilbert curve
 * (Skilling's transform on 16 bits per axis) of the kept points' bounding
 * box, as CGAL's spatial_sort and geogram do.  Round and Hilbert index
 * form one 52-bit key, so one pass over the coordinates and one LSD radix
 * sort give the whole order, a deterministic function of the input.
 *
 * Threads: the keys are computed, and each radix pass counts and
 * scatters, in equal chunks of the array, one a thread; thread j's
 * elements of a digit go after those of threads before j, so the sort
 * stays stable and its result is the one-thread result.
 */
#include "mesh/mesh.h"
#include "dtdel/alloc.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Spreads the low 16 bits of v to bits 0, 3, 6, ..., 45. */
static uint64_t spread3(uint64_t v)
{
    v &= 0xFFFF;
    v = (v | v << 16) & 0x0000FF0000FFull;
    v = (v | v << 8) & 0x00F00F00F00Full;
    v = (v | v << 4) & 0x0C30C30C30C3ull;
    v = (v | v << 2) & 0x249249249249ull;
    return v;
}

/* Skilling's transform: axes -> Hilbert index, b <= 16 bits per axis, the
 * bits of x[0] most significant in each triple.  Branch-free on scalars
 * (the axes' bits are unpredictable, and an array would keep the chain of
 * updates of x0 in memory).                                               */
static uint64_t hilbert_key(const uint32_t x[3], int b)
{
    uint32_t x0 = x[0], x1 = x[1], x2 = x[2];
    for (uint32_t q = 1u << (b - 1); q > 1; q >>= 1) {
        /* axis i: bit q set -> invert the low bits of x0, else swap them
         * between x0 and xi                                              */
        uint32_t p = q - 1, hit, s;
        x0 ^= p & (0u - ((x0 & q) != 0));
        hit = 0u - ((x1 & q) != 0);
        s = (x0 ^ x1) & p & ~hit;
        x0 ^= (p & hit) | s;
        x1 ^= s;
        hit = 0u - ((x2 & q) != 0);
        s = (x0 ^ x2) & p & ~hit;
        x0 ^= (p & hit) | s;
        x2 ^= s;
    }
    /* Gray decode */
    x1 ^= x0;
    x2 ^= x1;
    uint32_t t = 0;
    for (uint32_t q = 1u << (b - 1); q > 1; q >>= 1)
        t ^= (q - 1) & (0u - ((x2 & q) != 0));
    x0 ^= t;
    x1 ^= t;
    x2 ^= t;
    return spread3(x0) << 2 | spread3(x1) << 1 | spread3(x2);
}

typedef struct keyed { uint64_t key; uint32_t id; } keyed;

/* Composite key: BRIO round in bits 48..51 (at most 10 rounds for 32-bit
 * n), Hilbert index in bits 0..47; radix-sorted 13 bits a pass.           */
#define KEY_BITS 52
#define DIGIT_BITS 13
#define NDIGIT (1u << DIGIT_BITS)
#define NPASS (KEY_BITS / DIGIT_BITS)
#define BRIO_SEED 0x243F6A8885A308D3ull

/* BRIO round of input i among rounds 0..depth: depth with probability 7/8,
 * depth - 1 with 7/64, ..., 0 with 8^-depth (a leading zero octal digit
 * of a hash of i moves the point one round earlier).                      */
static uint64_t brio_round(uint32_t i, uint32_t depth)
{
    uint64_t r = dd_mix64(BRIO_SEED + ((uint64_t)i + 1) * 0x9E3779B97F4A7C15ull);
    uint32_t level = 0;
    while (level < depth && ((r >> (61 - 3 * level)) & 7u) == 0) level++;
    return depth - level;
}

void dd_brio_rounds(const uint32_t *v2in, uint32_t m, uint32_t *starts, uint32_t *nround)
{
    uint32_t depth = 0, count[17] = {0};
    for (uint32_t hi = m; hi > 64; hi /= 8) depth++;
    for (uint32_t k = 0; k < m; k++) count[brio_round(v2in[k], depth)]++;
    starts[0] = 0;
    for (uint32_t r = 0; r <= depth; r++) starts[r + 1] = starts[r] + count[r];
    *nround = depth + 1;
}


/* Below this many points a comparison sort of the keys beats the radix
 * sort's 128 KiB of counters.                                            */
#define RADIX_MIN 2048
/* Points a thread of the sort at least; threads of the sort at most
 * (each has NPASS * NDIGIT counters).                                   */
#define SORT_SHARE 65536u
#define SORT_THREADS 64u

static int cmp_keyed(const void *a, const void *b)
{
    const keyed *x = a, *y = b;
    return x->key < y->key ? -1 : x->key > y->key ? 1 : (x->id > y->id) - (x->id < y->id);
}

/* One sort: the grid of the bounding box, the arrays, the counters. */
typedef struct sorter {
    const double *pts;
    const uint32_t *ids;
    keyed *a, *b;
    uint32_t *count;          /* thread j's: count + j * NPASS * NDIGIT */
    uint32_t n, depth, shift;
    unsigned nth;
    double lo[3], scale, top;
    int plain, eh, bits;
} sorter;

/* Thread j's chunk of the array. */
static void chunk_of(const sorter *r, unsigned j, uint32_t *k0, uint32_t *k1)
{
    *k0 = (uint32_t)((uint64_t)r->n * j / r->nth);
    *k1 = (uint32_t)((uint64_t)r->n * (j + 1) / r->nth);
}

static uint64_t key_of(const sorter *r, uint32_t id)
{
    const double *p = r->pts + 3 * (size_t)id;
    uint32_t x[3];
    for (int c = 0; c < 3; c++) {
        double q = r->plain ? (p[c] - r->lo[c]) * r->scale : ldexp(0.5 * p[c] - 0.5 * r->lo[c], -r->eh) * r->scale;
        x[c] = !(q > 0) ? 0 : q >= r->top ? (uint32_t)r->top : (uint32_t)q;
    }
    return brio_round(id, r->depth) << 48 | hilbert_key(x, r->bits);
}

/* Thread j: the keys of its chunk, and the digits of every pass counted. */
static void keys_job(void *arg, unsigned j)
{
    sorter *r = arg;
    uint32_t k0, k1, *cnt = r->count ? r->count + (size_t)j * NPASS * NDIGIT : NULL;
    chunk_of(r, j, &k0, &k1);
    for (uint32_t k = k0; k < k1; k++) {
        uint64_t key = key_of(r, r->ids[k]);
        r->a[k].key = key;
        r->a[k].id = r->ids[k];
        for (uint32_t d = 0; cnt && d < NPASS; d++) cnt[d * NDIGIT + ((key >> (d * DIGIT_BITS)) & (NDIGIT - 1))]++;
    }
}

/* Thread j: this pass's digits of its chunk counted again (the passes
 * before moved the elements between chunks).                          */
static void count_job(void *arg, unsigned j)
{
    sorter *r = arg;
    uint32_t k0, k1, *cnt = r->count + (size_t)j * NPASS * NDIGIT;
    chunk_of(r, j, &k0, &k1);
    memset(cnt, 0, NDIGIT * sizeof *cnt);
    for (uint32_t k = k0; k < k1; k++) cnt[(r->a[k].key >> r->shift) & (NDIGIT - 1)]++;
}

/* Thread j: its chunk to the places its offsets give. */
static void scatter_job(void *arg, unsigned j)
{
    sorter *r = arg;
    uint32_t k0, k1, *off = r->count + (size_t)j * NPASS * NDIGIT;
    chunk_of(r, j, &k0, &k1);
    for (uint32_t k = k0; k < k1; k++) r->b[off[(r->a[k].key >> r->shift) & (NDIGIT - 1)]++] = r->a[k];
}

/* The grid: bounding box, bits per axis, scale.  The grid coordinates
 * are (x - lo) * scale in doubles, unless the extent overflows
 * (coordinates of both signs beyond DBL_MAX / 2) or its reciprocal does
 * (subnormal extents): then in halves and scaled by powers of two, which
 * nothing can overflow.                                                */
static void set_grid(sorter *r, int brio)
{
    double hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (int c = 0; c < 3; c++) r->lo[c] = HUGE_VAL;
    for (uint32_t k = 0; k < r->n; k++) {
        const double *p = r->pts + 3 * (size_t)r->ids[k];
        for (int c = 0; c < 3; c++) {
            if (p[c] < r->lo[c]) r->lo[c] = p[c];
            if (p[c] > hi[c]) hi[c] = p[c];
        }
    }
    double ext = 0;
    for (int c = 0; c < 3; c++) if (hi[c] - r->lo[c] > ext) ext = hi[c] - r->lo[c];
    /* bits per axis: 16 in a construction's rounds; else about 4 boxes a
     * point along each axis, as fine an order with fewer steps of the key
     * and fewer radix passes                                             */
    r->bits = 16;
    while (!brio && r->bits > 4 && (1ull << (3 * (r->bits - 3))) > r->n) r->bits--;
    r->top = (double)((1u << r->bits) - 1);
    r->plain = ext > 0 && ext <= DBL_MAX && r->top / ext <= DBL_MAX;
    r->scale = r->plain ? r->top / ext : 0.0;
    r->eh = 0;
    if (!r->plain) {
        double half = 0;
        for (int c = 0; c < 3; c++) half = fmax(half, 0.5 * hi[c] - 0.5 * r->lo[c]);
        r->eh = half > 0 ? ilogb(half) : 0;
        r->scale = half > 0 ? r->top / ldexp(half, -r->eh) : 0.0;
    }
}

/* The radix passes; the sorted array ends in r->a. */
static void radix_passes(sorter *r)
{
    const size_t stride = (size_t)NPASS * NDIGIT;
    for (uint32_t d = 0; d < NPASS; d++) {
        r->shift = d * DIGIT_BITS;
        if (d > 0 && r->nth > 1) dd_run_threads(r->nth, count_job, r);
        uint32_t at = d > 0 && r->nth > 1 ? 0 : d * NDIGIT;   /* this pass's counters */
        uint32_t *c0 = r->count + at, total0 = 0;
        for (unsigned j = 0; j < r->nth; j++) total0 += c0[j * stride + ((r->a[0].key >> r->shift) & (NDIGIT - 1))];
        if (total0 == r->n) continue;                          /* one digit */
        uint32_t sum = 0;
        for (uint32_t v = 0; v < NDIGIT; v++)
            for (unsigned j = 0; j < r->nth; j++) {
                uint32_t *c = r->count + j * stride + at + v, x = *c;
                *c = sum;
                sum += x;
            }
        if (at != 0)   /* scatter_job reads the offsets at the front */
            for (unsigned j = 0; j < r->nth; j++) memcpy(r->count + j * stride, r->count + j * stride + at, NDIGIT * sizeof *r->count);
        if (r->nth > 1) dd_run_threads(r->nth, scatter_job, r);
        else scatter_job(r, 0);
        keyed *tmp = r->a; r->a = r->b; r->b = tmp;
    }
}

dd_status dd_spatial_order_threads(const double *pts, uint32_t *ids, uint32_t n, int brio, unsigned nthreads)
{
    if (n < 2) return DD_OK;
    sorter r = {.pts = pts, .ids = ids, .n = n, .depth = 0, .nth = 1};
    /* as many factor-8 rounds as take n down to 64 points or fewer */
    for (uint32_t hi = n; brio && hi > 64; hi /= 8) r.depth++;
    set_grid(&r, brio);
    const int radix = n >= RADIX_MIN;
    if (radix) {
        uint32_t most = n / SORT_SHARE;
        r.nth = nthreads < most ? nthreads : most;
        if (r.nth > SORT_THREADS) r.nth = SORT_THREADS;
        if (r.nth < 1) r.nth = 1;
    }
    keyed *buf = dd_malloc(2 * (size_t)n * sizeof *buf);
    r.count = radix ? dd_calloc((size_t)r.nth * NPASS * NDIGIT, sizeof *r.count) : NULL;
    if (!buf || (radix && !r.count)) { dd_mfree(buf); dd_mfree(r.count); return DD_ERR_NOMEM; }
    r.a = buf;
    r.b = buf + n;
    if (r.nth > 1) dd_run_threads(r.nth, keys_job, &r);
    else keys_job(&r, 0);
    if (radix) radix_passes(&r);
    else qsort(r.a, n, sizeof *r.a, cmp_keyed);
    for (uint32_t k = 0; k < n; k++) ids[k] = r.a[k].id;
    dd_mfree(buf);
    dd_mfree(r.count);
    return DD_OK;
}

dd_status dd_spatial_order(const double *pts, uint32_t *ids, uint32_t n, int brio)
{
    return dd_spatial_order_threads(pts, ids, n, brio, 1);
}
