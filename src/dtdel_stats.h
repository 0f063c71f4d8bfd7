/*
 * dtdel_stats.h -- diagnostics of libdtdel for benchmarks and tests: what
 * the last deletion did, the predicates' counters, and (in test builds
 * only) the test controls.  Not needed to use the library (dtdel.h is);
 * these may change between versions.
 */
#ifndef DTDEL_STATS_H
#define DTDEL_STATS_H

#include "dtdel.h"

#ifdef __cplusplus
extern "C" {
#endif
DD_API_BEGIN

#define DD_LINKDEG_BUCKETS 16
#define DD_STRATEGY_STATS 16

/* What the last dd_delete did.  Phase times only in counting builds
 * (-DDD_COUNTERS).                                                       */
typedef struct dd_delete_stats {
    uint32_t degree;          /* neighbours, the infinite vertex included  */
    int on_hull;
    int forced_fill;          /* hull vertex with coplanar finite
                                 neighbours: the framework's forced fill
                                 ran instead of the strategy             */
    uint64_t tets_created;    /* cells built for the cavity (dummies too)  */
    uint64_t fallbacks;       /* sampling fallbacks of guided strategies   */
    uint64_t locate_steps;    /* cells tested by point location in the
                                 conflict DT (guided variants, dtq-only)  */
    uint32_t link_deletions[DD_LINKDEG_BUCKETS];   /* LINKDTDELETE calls by
                                 the degree of the deleted link vertex:
                                 index k = degree k for k < 15, last = 15+ */
    double link_us, locate_us, conflict_us, sew_us;
    /* The strategy's own statistics: strategy[i] counts what
     * strategy_name[i] says, i < nstrategy (none for most strategies;
     * gift wrapping's are listed in src/wrap/wrap.h).                   */
    uint32_t nstrategy;
    const char *strategy_name[DD_STRATEGY_STATS];
    uint32_t strategy[DD_STRATEGY_STATS];
} dd_delete_stats;
void dd_last_delete_stats(const dd_tri *t, dd_delete_stats *s);

/* Statistics: the predicate counts are kept by counting builds
 * (-DDD_COUNTERS), zero otherwise; tets_created and walk_steps (cells
 * crossed by point location) always.                                    */
typedef struct dd_counters {
    uint64_t orient_calls, orient_exact;
    uint64_t insphere_calls, insphere_exact;
    uint64_t perturbed;            /* exact zeros resolved by perturbation */
    uint64_t tets_created;
    uint64_t walk_steps;
    uint64_t moves_kept;           /* dd_move: the filter kept the cells     */
    uint64_t moves_flipped;        /* dd_move: repaired by flips             */
    uint64_t moves_redone;         /* dd_move: inserted again, then deleted  */
} dd_counters;
void dd_get_counters(const dd_tri *t, dd_counters *c);
void dd_reset_counters(dd_tri *t);

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
    DD_TEST_NCTL
} dd_test_ctl;
#ifdef DD_TEST_BUILD
/* Sets control ctl of t to value (t may be NULL for process-wide
 * controls); returns the value it had.                                   */
long dd_test_control(dd_tri *t, dd_test_ctl ctl, long value);
#endif

DD_API_END
#ifdef __cplusplus
}
#endif
#endif
