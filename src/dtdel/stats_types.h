/*
 * dtdel/stats_types.h -- the constants and names of the diagnostics
 * (dtdel_stats.h) that the engine's layers use too: the sizes of the
 * deletion statistics' tables and the test controls.  Part of the
 * diagnostic interface: dtdel_stats.h includes it, and it is installed
 * beside it as dtdel/stats_types.h.  The engine includes this, not
 * dtdel_stats.h (docs/architecture.md).
 */
#ifndef DTDEL_STATS_TYPES_H
#define DTDEL_STATS_TYPES_H

#ifdef __cplusplus
extern "C" {
#endif

#define DD_LINKDEG_BUCKETS 16   /* dd_delete_stats.link_deletions         */
#define DD_STRATEGY_STATS 16    /* dd_delete_stats.strategy               */

/* Test controls (as SQLite's sqlite3_test_control): switches that force
 * one of the engine's equivalent courses, so that tests reach each of
 * them on the same inputs.  Compiled into test builds (-DDD_TEST_BUILD)
 * only; every control starts at 0, the release behaviour.  Nothing in
 * the input selects a course.                                           */
typedef enum dd_test_ctl {
    DD_TEST_SCALAR,       /* 1: the gift wrap takes its plain C scans, not
                             its AVX2 kernels                             */
    DD_TEST_NO_SINGLE,    /* 1: the wrap makes no single-precision pass    */
    DD_TEST_SPOIL_SINGLE, /* 1: the wrap's single-precision passes answer
                             a wrong point now and then (one guess in 16,
                             every hull step), so the checks that refute
                             them run                                     */
    DD_TEST_NARROWER,     /* 1: the wrap's narrow guesses take only the
                             shortest lists, no second step, so they are
                             refuted more often and the wide guess after
                             them runs                                    */
    DD_TEST_SET_FAIL_AT,  /* k + 1: dd_delete_set fails at its deletion
                             number k as out of memory would (0: never)   */
    DD_TEST_SET_COURSE,   /* dd_delete_set's course: 1 one at a time, 2 a
                             rebuild of the points left (0: the cheaper) */
    DD_TEST_EXP_PLAIN,    /* 1: the exact stages take their plain
                             TWO-PRODUCT, not FMA (process-wide)          */
    DD_TEST_ALLOC_FAIL,   /* k: the k-th allocation from now on fails, once
                             (dtdel/alloc.h; 0: none; process-wide).
                             Reads back how many are left before it (0
                             once it has failed)                         */
    DD_TEST_ALLOC_COUNT,  /* the allocations made so far (process-wide):
                             setting it returns the count and restarts it
                             from the value set                           */
    DD_TEST_NCTL
} dd_test_ctl;

#ifdef __cplusplus
}
#endif
#endif
