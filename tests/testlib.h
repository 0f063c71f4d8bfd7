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

/* The courses of the gift wrap a test case runs (dtdel_stats.h, test
 * controls).  Each is one equivalent way to the same result; a test case
 * names the courses it runs and deletes under each in turn, so every
 * course it names runs by construction, whatever the vertices.  The test
 * chooses; the engine reads nothing from the input.  Release builds have
 * no controls: every course is the default one there.                  */
typedef enum tl_course {
    TL_COURSE_DEFAULT,       /* the release course: AVX2 scans where the
                                CPU has them, single-precision passes    */
    TL_COURSE_SCALAR,        /* the plain C scans (DD_TEST_SCALAR)       */
    TL_COURSE_NO_SINGLE,     /* no single-precision pass                 */
    TL_COURSE_SPOIL_SINGLE,  /* spoiled single-precision passes, refuted */
    TL_COURSE_NARROWER,      /* narrower guesses, refuted more often     */
    TL_NCOURSES
} tl_course;

static const char *const tl_course_name[TL_NCOURSES] = {"default", "scalar", "no-single", "spoil-single",
                                                        "narrower"};

/* Every course, for the test cases that run them all. */
static const tl_course tl_all_courses[TL_NCOURSES] = {TL_COURSE_DEFAULT, TL_COURSE_SCALAR, TL_COURSE_NO_SINGLE,
                                                      TL_COURSE_SPOIL_SINGLE, TL_COURSE_NARROWER};

/* Sets t's controls to course c (every other control of the wrap off). */
static inline void tl_set_course(dd_tri *t, tl_course c)
{
#ifdef DD_TEST_BUILD
    dd_test_control(t, DD_TEST_SCALAR, c == TL_COURSE_SCALAR);
    dd_test_control(t, DD_TEST_NO_SINGLE, c == TL_COURSE_NO_SINGLE);
    dd_test_control(t, DD_TEST_SPOIL_SINGLE, c == TL_COURSE_SPOIL_SINGLE);
    dd_test_control(t, DD_TEST_NARROWER, c == TL_COURSE_NARROWER);
#else
    (void)t;
    (void)c;
#endif
}

/* A test case's courses: the list it names, taken in turn by
 * tl_course_next, and how many deletions each course had.             */
typedef struct tl_courses {
    const tl_course *list;
    unsigned n, next;
    tl_course last;               /* the course of the last deletion     */
    unsigned ran[TL_NCOURSES];
} tl_courses;

static inline tl_courses tl_courses_of(const tl_course *list, unsigned n)
{
    tl_courses cs;
    memset(&cs, 0, sizeof cs);
    cs.list = list;
    cs.n = n;
    return cs;
}

/* Every course, in turn. */
static inline tl_courses tl_courses_all(void)
{
    return tl_courses_of(tl_all_courses, TL_NCOURSES);
}

/* The courses named, in turn: TL_COURSES(TL_COURSE_DEFAULT, ...).       */
#define TL_COURSES(...)                                                                          \
    tl_courses_of((const tl_course[]){__VA_ARGS__},                                              \
                  (unsigned)(sizeof((const tl_course[]){__VA_ARGS__}) / sizeof(tl_course)))

/* Sets t to the next course of cs (the first after the last, cyclically)
 * before one deletion, and counts it; returns the course.              */
static inline tl_course tl_course_next(tl_courses *cs, dd_tri *t)
{
    tl_course c = cs->list[cs->next];
    cs->next = (cs->next + 1) % cs->n;
    cs->ran[c]++;
    cs->last = c;
    tl_set_course(t, c);
    return c;
}

/* 1 when every course cs names ran; else 0 and the first that did not
 * in why.  (A case of at least cs->n deletions covers them all.)       */
static inline int tl_courses_covered(const tl_courses *cs, char *why, size_t nwhy)
{
    for (unsigned i = 0; i < cs->n; i++)
        if (!cs->ran[cs->list[i]]) {
            snprintf(why, nwhy, "course %s never ran", tl_course_name[cs->list[i]]);
            return 0;
        }
    return 1;
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

/* Checks NAME/courses: every course cs names ran.  For the test cases
 * whose own check does not include tl_courses_covered.                 */
static inline void tl_courses_check(tl_state *st, const tl_courses *cs, const char *name)
{
    char tn[160], why[96] = "";
    snprintf(tn, sizeof tn, "%s/courses", name);
    tl_check(st, tl_courses_covered(cs, why, sizeof why), tn, "%s", why);
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
