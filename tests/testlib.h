/*
 * testlib.h -- the tiny assertion layer shared by the C test programs.
 *
 * Each assertion prints one line, "ok NAME" or "FAIL NAME: why"; the runner
 * (tests/run.sh) counts those lines over all programs and prints the final
 * "N passed, N failed".  A program's exit status is non-zero on any
 * failure, so a crash or a silent early exit also fails the suite.
 */
#ifndef DD_TESTLIB_H
#define DD_TESTLIB_H

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dtdel_stats.h"

typedef struct tl_state { int passed, failed; } tl_state;

/* The test controls (dtdel_stats.h) a test sets before deleting input
 * vertex v, so that over many deletions every course of the gift wrap is
 * taken: scalar scans for odd v, single-precision passes only for v of
 * 0 mod 4 and spoiled for 4 mod 8, narrower guesses for 3 mod 4.  The
 * test chooses; the engine reads nothing from the input.  Release builds
 * have no controls and take the default course.                         */
static inline void tl_controls_for(dd_tri *t, uint32_t v)
{
#ifdef DD_TEST_BUILD
    dd_test_control(t, DD_TEST_SCALAR, v % 2);
    dd_test_control(t, DD_TEST_NO_SINGLE, v % 4 != 0);
    dd_test_control(t, DD_TEST_SPOIL_SINGLE, v % 8 == 4);
    dd_test_control(t, DD_TEST_NARROWER, v % 4 == 3);
#else
    (void)t;
    (void)v;
#endif
}

static void tl_check(tl_state *st, int ok, const char *name, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static void tl_check(tl_state *st, int ok, const char *name, const char *fmt, ...)
{
    if (ok) {
        st->passed++;
        printf("ok %s\n", name);
    } else {
        st->failed++;
        printf("FAIL %s: ", name);
        va_list ap;
        va_start(ap, fmt);
        vprintf(fmt, ap);
        va_end(ap);
        printf("\n");
    }
    fflush(stdout);
}

static int tl_finish(const tl_state *st)
{
    fprintf(stderr, "  (%d passed, %d failed in this program)\n", st->passed, st->failed);
    return st->failed ? 1 : 0;
}

/* A small deterministic generator for test data. */
typedef struct tl_rng { uint64_t s; } tl_rng;
static inline uint64_t tl_next(tl_rng *r)
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}
static inline double tl_unif(tl_rng *r) { return (double)(tl_next(r) >> 11) * 0x1.0p-53; }
static inline int64_t tl_int(tl_rng *r, int64_t lo, int64_t hi)
{
    return lo + (int64_t)(tl_next(r) % (uint64_t)(hi - lo + 1));
}

/* A pool of points to draw test tuples from. */
typedef struct pool { double *p; int n; } pool;

/* k (<= 8) distinct points of the pool, copied to out. */
static inline void tl_pick(tl_rng *r, const pool *pl, int k, double out[][3])
{
    int idx[8];
    for (int i = 0; i < k; i++) {
        int again;
        do {
            idx[i] = (int)tl_int(r, 0, pl->n - 1);
            again = 0;
            for (int j = 0; j < i; j++) again |= idx[j] == idx[i];
        } while (again);
        memcpy(out[i], pl->p + 3 * idx[i], sizeof out[i]);
    }
}

/* Integer points of the sphere x^2+y^2+z^2 = r2, written to pts (3 doubles
 * each, up to max points); returns how many.                              */
static inline int tl_sphere_points(int64_t r2, double *pts, int max)
{
    int n = 0;
    int64_t r = 0;
    while ((r + 1) * (r + 1) <= r2) r++;
    for (int64_t x = -r; x <= r; x++)
        for (int64_t y = -r; y <= r; y++) {
            int64_t z2 = r2 - x * x - y * y;
            if (z2 < 0) continue;
            int64_t z = 0;
            while ((z + 1) * (z + 1) <= z2) z++;
            if (z * z != z2) continue;
            for (int sgn = -1; sgn <= 1; sgn += 2) {
                if (z == 0 && sgn > 0) continue;
                if (n < max) {
                    pts[3 * n] = (double)x; pts[3 * n + 1] = (double)y;
                    pts[3 * n + 2] = (double)(sgn * z);
                }
                n++;
            }
        }
    return n < max ? n : max;
}

#endif
