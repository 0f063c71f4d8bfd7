/*
 * dtdel_stats.h -- diagnostics of libdtdel for benchmarks and tests: what
 * the last deletion did, the predicates' counters, and (in test builds
 * only) the test controls.  Not needed to use the library (dtdel.h is);
 * these may change between versions.
 */
#ifndef DTDEL_STATS_H
#define DTDEL_STATS_H

#include "dtdel.h"
#include "dtdel/stats_types.h"   /* installed beside dtdel.h too */

#ifdef __cplusplus
extern "C" {
#endif
DD_API_BEGIN

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

/* Statistics of the edits (read-only calls count nothing: they write
 * nothing to t, dtdel.h's Threads): the predicate counts are kept by
 * counting builds (-DDD_COUNTERS), zero otherwise; tets_created and
 * walk_steps (cells crossed by point location) always.                  */
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

/* dd_test_ctl, the test controls, is in dtdel/stats_types.h. */
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
