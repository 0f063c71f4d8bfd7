/*
 * soak.h -- what the two halves of `make soak` share: the unweighted
 * soak (tests/soak.c: its cases, the workers and main) and the weighted
 * one (tests/soak_weighted.c: regular triangulations in both hidden
 * modes).  One binary, one queue of cases, one set of counters.
 *
 * A case is numbered k in [0, soak_num_cases()): the unweighted ones
 * first, then the weighted ones (k - soak_num_unweighted() is the
 * weighted number).  Both kinds apply the same coordinate transforms.
 */
#ifndef DD_SOAK_H
#define DD_SOAK_H

#include "dtdel.h"

#include <stdint.h>
#include <stddef.h>

#define SOAK_MAX_VARIANTS 32

typedef enum {
    TF_NONE, TF_E16, TF_EM16, TF_E150, TF_EM150, TF_FAR, TF_E300, TF_EM300, TF_SUB, TF_MIXED, TF_SPAN, NUM_TF
} soak_tf;
extern const char *const soak_tf_names[NUM_TF];

typedef struct soak_case {
    int index;
    const char *dataset;
    soak_tf tf;
    int mode;                /* the kind's own mode number */
    const char *mode_name;   /* for messages: "seq", "wmove/discard", ... */
    int weighted;            /* a case of soak_weighted.c */
    int discard;             /* weighted: DD_DISCARD_HIDDEN */
    uint64_t seed;
    uint64_t quota;          /* operations to reach (unweighted: deletions) */
} soak_case;

/* The operations of the weighted soak, counted done and skipped. */
typedef enum {
    WOP_DELETE, WOP_SET, WOP_REINSERT, WOP_INSERT, WOP_MOVE, WOP_MOVE_WEIGHTED, NUM_WOPS
} soak_wop;
extern const char *const soak_wop_names[NUM_WOPS];

/* Every field a uint64_t: the parent sums the workers' records as arrays. */
typedef struct stats {
    uint64_t deletions, insertions, moves, mismatches, refusals, sets, checks;
    uint64_t per_variant[SOAK_MAX_VARIANTS];
    /* weighted: operations done (a set counts its vertices under
     * WOP_SET), refused by both sides alike, skipped because the engine
     * answered DD_ERR_UNSUPPORTED; per strategy the deletions done;
     * hidden points that came back; deletions and moves of kept
     * hidden points; whole comparisons; exact copies kept here that
     * CGAL's remove() dropped (soak_weighted.c: wp_copies_dropped).     */
    uint64_t wdone[NUM_WOPS], wrefused[NUM_WOPS], wskipped[NUM_WOPS];
    uint64_t wvariant[SOAK_MAX_VARIANTS];
    uint64_t wreleased, whidden_ops, wchecks, wcopies;
} stats;

typedef struct soak {
    const char *variants[SOAK_MAX_VARIANTS];
    size_t nvariants;
    uint64_t turn;           /* next strategy: variants[turn % nvariants] */
    stats st;
    int quiet, worker;
    double scale;            /* for the rerun hint */
    uint64_t seed;
    /* the real models, loaded once per worker */
    const char *model_name[32];
    double *model_xyz[32];
    uint32_t model_n[32];
    size_t nmodels;
    /* the current case, for messages */
    const soak_case *cs;
    uint64_t round, step;
} soak;

/* ---- a seeded generator: testlib.h's (splitmix64) ------------------------------ */

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"     /* testlib.h's runner: unused here */
#include "testlib.h"
#pragma GCC diagnostic pop

typedef tl_rng rng;
static inline uint64_t next_u64(rng *r) { return tl_next(r); }
static inline uint32_t below(rng *r, uint32_t m) { return (uint32_t)(next_u64(r) % m); }

/* ---- shared by both halves (soak.c) ----------------------------------------- */

/* Reports a mismatch of the current case with everything needed to find
 * it again (case, round, step, the rerun command); counts it.          */
__attribute__((format(printf, 2, 3))) void soak_mismatch(soak *s, const char *fmt, ...);
/* Applies transform tf to n points in place; with w not NULL, scales the
 * weights as squared lengths (times f^2 where the points are times f;
 * unchanged by a translation), saturating at +-DBL_MAX and rounding to
 * zero below the subnormals: still finite doubles CGAL is given too.    */
void soak_transform(soak_tf tf, double *xyz, double *w, uint32_t n);
/* Shuffles n points (and their weights, w not NULL) alike. */
void soak_shuffle(rng *r, double *xyz, double *w, uint32_t n);
/* About the mean spacing of n points (half the box's edge over n^(1/3)). */
double soak_mean_spacing(const double *xyz, uint32_t n);

/* ---- the weighted half (soak_weighted.c) ------------------------------------ */

size_t soak_num_weighted(void);
/* Weighted case j (0 <= j < soak_num_weighted()), numbered index. */
soak_case soak_weighted_case(size_t j, int index, double scale, uint64_t seed);
/* A rough cost of a weighted case at scale 1, in the unweighted soak's
 * units (one deletion checked locally).                                */
double soak_weighted_cost(const soak_case *c);
/* Runs a weighted case; 0, or -1 after a mismatch (reported). */
int soak_weighted_run(soak *s, const soak_case *c, rng *r);
/* Prints the weighted totals (lines starting "soak: weighted"). */
void soak_weighted_report(const soak *proto, const stats *tot);

#endif
