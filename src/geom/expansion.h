/*
 * expansion.h -- exact orient3d / insphere signs in floating-point
 * expansion arithmetic (Shewchuk 1997, "Adaptive precision floating-point
 * arithmetic and fast robust geometric predicates"), a faster exact stage
 * for pred.c than its GMP integers.
 *
 * Owns: dd_orient3d_exp and dd_insphere_exp.  Same signs as pred.c's
 * exact stage (and so as CGAL), no perturbation:
 *   dd_orient3d_exp(p,q,r,s)    = sign det[q-p; r-p; s-p].
 *   dd_insphere_exp(p,q,r,s,t)  = sign det of the rows p-t, r-t, q-t, s-t
 *                                 (note r, q swapped), each lifted with its
 *                                 squared norm: +1 when t is inside the
 *                                 sphere of the positively oriented pqrs.
 *
 * Invariant: a result in {-1, 0, +1} is the exact sign, for every input;
 * DD_EXP_UNSAFE means "not decided here, ask the GMP stage".  The
 * functions are pure: no allocation, no FP-environment changes, and no
 * global state but one cached CPU-feature flag (below).  They assume IEEE
 * binary64 with round-to-nearest-even (the default mode) and no x87
 * excess precision.  Hardware FMA is neither needed nor assumed: when the
 * compiler targets it, every TWO-PRODUCT uses it (which also makes the
 * code safe against FP contraction); on baseline x86 builds stage C uses
 * it when the CPU has it (checked once, at run time).  Either way the
 * results are bit-identical: every TWO-PRODUCT is exact.
 *
 * Safe range.  DD_EXP_UNSAFE is returned exactly when some coordinate of
 * the input points is NaN, infinite, or has a magnitude outside the
 * predicate's range (zero is always allowed):
 *   orient3d:  2^-260 <= |x| <= 2^260   (about 5.4e-79 .. 1.9e78)
 *   insphere:  2^-140 <= |x| <= 2^140   (about 7.2e-43 .. 1.4e42)
 * The derivation is at the top of expansion.c.  [1e-30, 1e30] is inside
 * both; 1e-200 and 1e200 are not.
 *
 * Cost: adaptive.  A: doubles with a dynamic error bound; B: exact
 * determinant of the rounded differences when they are exact (an O(1)
 * certificate when they are small integers times a power of two, else
 * expansions); C: double-double evaluation over the exact differences,
 * with a derived error bound of order 2^-99 times the permanent; D: exact
 * determinant of the raw coordinates when the differences are inexact and
 * C cannot decide (in practice: exact zeros, e.g. five coplanar points
 * with non-representable differences).  Stage D of insphere uses about
 * 120 KB of stack (a separate, non-inlined frame); everything else uses
 * under 30 KB.
 */
#ifndef DD_EXPANSION_H
#define DD_EXPANSION_H

#include "geom/fp.h"   /* first: no contraction from here on */

#define DD_EXP_UNSAFE 2

/* The safe ranges below as powers of two: 2^-LIM <= |x| <= 2^LIM. */
#define DD_EXP_O3_LIM 260
#define DD_EXP_INS_LIM 140

/* Stage that decided, reported by the _staged variants (tests, counting). */
enum {
    DD_EXP_STAGE_UNSAFE = 0,   /* out of the safe range                     */
    DD_EXP_STAGE_A = 1,        /* doubles with a dynamic error bound        */
    DD_EXP_STAGE_B = 2,        /* exact det of exact differences            */
    DD_EXP_STAGE_C = 3,        /* double-double with an error bound         */
    DD_EXP_STAGE_D = 4         /* exact det of the raw coordinates          */
};

int dd_orient3d_exp(const double *p, const double *q, const double *r,
                    const double *s);
int dd_insphere_exp(const double *p, const double *q, const double *r,
                    const double *s, const double *t);

/* The same, also storing the deciding stage in *stage (never NULL). */
int dd_orient3d_exp_staged(const double *p, const double *q, const double *r,
                           const double *s, int *stage);
int dd_insphere_exp_staged(const double *p, const double *q, const double *r,
                           const double *s, const double *t, int *stage);

#ifdef DD_TEST_BUILD
/* Test builds only (dd_test_control, DD_TEST_EXP_PLAIN): on != 0 makes
 * stage C use the plain TWO-PRODUCT (Dekker's) even on a CPU with FMA,
 * on == 0 restores the run-time choice.  Returns whether stage C now
 * uses hardware FMA (always 1 in builds targeting FMA, where plain is
 * FMA too).  Both paths give the same results.                         */
int dd_exp_force_plain(int on);
/* The value last given to dd_exp_force_plain (0 at start).             */
int dd_exp_plain_forced(void);
#endif

/* w = |x - q|^2 - 2 (x - q).c within 2u |w| (exact expansion, rounded);
 * |x - q| and |c| must stay below 2^160.  The compact conflict DT's
 * shifted lifts (qsmall.c).                                              */
double dd_exp_shifted_lift(const double *x, const double *q, const double *c);

#endif
