/*
 * fp.h -- no fused multiply-adds in the code that computes signs.
 *
 * Every error bound of src/geom/ (CGAL's filters in pred.c, the lifted
 * filters of lift.h and lift_pass.h) and every error-free transformation
 * of expansion.c counts one rounding per product and one per sum.  A
 * compiler that contracts a * b + c into one fused multiply-add changes
 * those roundings: a bound no longer holds and Two_Product no longer
 * returns the product's error.  The Makefile passes -ffp-contract=off,
 * but the sources must not depend on it (gcc in its GNU modes, the
 * default, contracts across statements; clang contracts within one by
 * default).  So every geom header includes this one first, and the
 * pragmas below hold from there to the end of each file that includes
 * it -- the engine's files include a geom header before any function.
 *
 *  - gcc ignores `#pragma STDC FP_CONTRACT` (it warns under -Wall), but
 *    honours `#pragma GCC optimize("fp-contract=off")` for every function
 *    defined after it, even under an explicit -ffp-contract=fast (gcc
 *    12: no vfmadd in the objects, which are those of -ffp-contract=off).
 *    Not pushed and popped: a function whose options differ from its
 *    caller's is not inlined into it, so the pragma must cover both.
 *  - clang honours `#pragma STDC FP_CONTRACT OFF` in its default mode
 *    (-ffp-contract=on) and with -ffp-contract=off, but clang 14 ignores
 *    every pragma under an explicit -ffp-contract=fast.  That mode alone
 *    is not supported; dd_fp_fused() (lift.c) tells, at run time, whether
 *    the library was built so, and the tests fail when it was.
 * The AVX2 single-precision passes (lift_f32.c) use fused multiply-adds
 * on purpose, as intrinsics: they only rank, and no bound covers them.
 */
#ifndef DD_GEOM_FP_H
#define DD_GEOM_FP_H

#if defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

#endif
