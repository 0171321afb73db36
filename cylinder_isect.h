/* cylinder_isect.h - v1.0.0 - ray/cylinder intersection in float and double, C99, one header.

   Ray against a finite cylinder given by center c, axis a, radius r and height h: the open
   tube by default, the capped solid and the infinite tube as options; nearest hit, both
   crossings, or a shadow-ray test. No allocation, no global state, no I/O; nothing to link but
   sqrt and fma (both overridable). Every hit carries a rigorous bound on its t.

   QUICK START
   ===========
       #include "cylinder_isect.h"

       cyld_ray ray = {{-5, 0.5, 0.25}, {1, 0, 0}, 0, 100};   // origin o, direction d, tmin, tmax
       cyld_cylinder cyl = {{0, 0, 0}, {0, 0, 1}, 1, 2};      // center c, axis a, radius r, height h
       cyld_hit hit;
       int rc = cyld_intersect(&ray, &cyl, CYL_CAPS, &hit);   // nearest hit of the capped solid
       if (rc == CYL_HIT)
           printf("t = %.17g +- %.2g\n", hit.t, hit.t_err);  // t = 4.1339745962155616 +- 1.6e-14
       else if (rc < 0)
           printf("error: %s\n", cyl_strerror(rc));

   No implementation macro: every function is `static inline` (CYL_DEF). cylf_* is the float
   API, cyld_* the double one, both from one body this file includes twice. Link with -lm unless
   sqrt and fma inline (-fno-math-errno and a target FMA: -march=x86-64-v3, Cortex-M4F, RV32F).

   CONTRACT
   ========
   Geometry. The surface is the set of points at distance r from the axis line through c whose
   axial coordinate v = â·(x − c) lies in [−h/2, h/2]; â = a/|a|. The cap at c − â·h/2 is
   CYL_CAP_LOW, the one at c + â·h/2 is CYL_CAP_HIGH.
     - a may have any nonzero length; only its direction counts.
     - h = +INFINITY is the infinite tube (CYL_CAPS then changes nothing).
     - default: the open tube (curved wall only); CYL_CAPS: the solid capped cylinder.
   Ray. x(t) = o + t·d, d of any nonzero length, t in units of d; accepted t in [tmin, tmax]
   (inclusive; ±INFINITY allowed). Hits whose t is not representable count as misses.

   int cylf_intersect(const cylf_ray*, const cylf_cylinder*, unsigned opts, cylf_hit *hit)
       The nearest hit with tmin <= t <= tmax: returns CYL_HIT and fills *hit, or CYL_MISS, or a
       negative CYL_E_* code. On a miss or an error *hit is not touched, so it can be a caller's
       closest-hit record.
   int cylf_intersect_all(ray, cyl, opts, cylf_hit hits[2])
       Every hit in range (at most 2), sorted by t; returns the count (0, 1, 2) or an error.
       Open tube: both wall crossings. Capped solid: entry and exit. hits[i] for i >= count
       are not touched.
   int cylf_occluded(ray, cyl, opts)
       1 if anything is hit in range, 0 if not, or an error: the shadow-ray test, the cheapest.
   cylf_cylinder cylf_from_segment(const float p0[3], const float p1[3], float r)
       The cylinder whose axis runs from p0 (low cap) to p1 (high cap): pipes, bonds, bones.
       p0 == p1 gives a = 0 (and h = 0), which intersect reports as CYL_E_ZERO_AXIS.
   const char *cyl_strerror(int code)
       A short English description of any return value.

   The hit. t; t_err: the exact intersection of the given (already rounded) inputs with the
   reported part lies in [t − t_err, t + t_err] (a bound derived from a residual evaluated in
   the same precision, N6 and N8); n: unit normal, facing the ray origin (n·d <= 0)
   by default, the geometric outward normal with CYL_OUTWARD; v: axial coordinate of the hit,
   within [−h/2, h/2] (exactly ±h/2 on a cap; on an infinite tube it saturates at the largest
   finite value where the true v is not representable); part: CYL_SIDE, CYL_CAP_LOW, CYL_CAP_HIGH;
   flags: a set of
     CYL_F_INSIDE    the ray meets the surface from inside (it leaves the solid, or crosses the
                     tube's wall outward: an origin inside gets this on its first hit);
     CYL_F_TANGENT   a grazing wall contact: e = 1 − ρ²/r² lies within ±CYL_TANGENT_TOL, where ρ
                     is the distance between the ray line and the axis line. Such a contact
                     counts as a hit (both crossings, at or near the same t) unless
                     CYL_NO_TANGENT is given; there t is only determined to about √u (N11)
                     and t_err says so.
     CYL_F_PARALLEL  sin(angle between d and a) <= CYL_PARALLEL_TOL: treated as parallel. The
                     wall is then never hit; with CYL_CAPS a cap is hit where the ray point lies
                     inside its disk. No inf, NaN or division by zero either way. A wall crossing
                     that such a ray's inputs do determine is dropped too (a ray leaving the
                     wall can cross it again tens of radii along): a limit of this rule (N10).
   A hit exactly on the rim (the circle where wall and cap meet) is reported as CYL_SIDE.

   Errors, checked in this order; *hit is never touched on an error:
     CYL_E_NULL (-1) a NULL pointer            CYL_E_RADIUS (-5) r <= 0, NaN or infinite
     CYL_E_NONFINITE (-2) NaN/inf in o, d, c, a CYL_E_HEIGHT (-6) h <= 0 or NaN
     CYL_E_ZERO_DIR (-3) d == 0                 CYL_E_TRANGE (-7) tmin > tmax, or a NaN
     CYL_E_ZERO_AXIS (-4) a == 0                CYL_E_OPTION (-8) unknown or compiled-out bit

   OPTIONS (bits of opts)
   =======
     CYL_CAPS          solid capped cylinder instead of the open tube
     CYL_OUTWARD       outward normal instead of the ray-facing one
     CYL_NO_TANGENT    grazing contacts within the tangent tolerance are misses
     CYL_PRECISE       precise tier: classification right wherever its margin exceeds the
                       tolerances, far origins included (N9)
     CYL_NO_NORMAL     skip the normal: hit.n = {0, 0, 0}
     CYL_NO_ERRBOUND   skip the bound: hit.t_err = +INFINITY
     CYL_TRUSTED       skip input validation (NULL and option checks remain): the caller
                       guarantees finite inputs, nonzero d and a, r > 0, h > 0, tmin <= tmax
   Pass options as constants where you can: the functions are inline, so unused paths fold
   away where the compiler inlines the call (measured: see `make sizes`). gcc -O2 inlines an
   entry point called from one place; called from several, it may keep one out-of-line copy in
   which the options are run-time values (gcc 12 did so in bench/eval.c and in the viewer
   experiment of docs/examples.md). Then route the calls through one function of yours per
   option set, or define CYL_DEF as a forced inline.

   CONFIGURATION (define before including)
   =============
     macro                 default                      effect
     CYL_NO_FLOAT          undefined                    leave out cylf_* (and its code)
     CYL_NO_DOUBLE         undefined                    leave out cyld_*: no double anywhere
     CYL_NO_PRECISE        undefined                    compile out the precise tier
                                                        (CYL_PRECISE gives CYL_E_OPTION)
     CYL_NO_FAST_PATH      undefined                    every call runs the compensated solver:
                                                        smaller code, slower calls
     CYL_DEF               static inline                qualifier of every public function
     CYL_INTERNAL          static inline, forced inline qualifier of the internal functions
                           except under -Os
     CYL_SQRTF, CYL_SQRT   __builtin_sqrt[f] (gcc,      square roots; <math.h> is included
                           clang), else sqrt[f]          only when a non-builtin default is used
     CYL_FMAF, CYL_FMA     __builtin_fma[f], else fma[f] fused multiply-add; must be correctly
                                                        rounded (a real FMA or libm's)
     CYL_FLOAT_WIDE        1 where double is hardware   the float API computes in double (its
                           (x86-64, AArch64, ARM with   solver is the double API's); 0: in
                           VFP-D, RV64D, s390x, ppc64)  float (always so with CYL_NO_DOUBLE)
     CYL_TANGENT_TOLF      2^-16 = 2^-(24-8)            tangent band on e = 1 − ρ²/r²
     CYL_TANGENT_TOL       2^-45 = 2^-(53-8)
     CYL_PARALLEL_TOLF     2^-24 = u (float)            parallel bound on sin(angle)
     CYL_PARALLEL_TOL      2^-53 = u (double)
     CYL_HEADER_FILENAME   "cylinder_isect.h"           how this file includes itself

   ACCURACY
   ========
   Measured against the exact MPFR reference of ref/ on eleven case families, 6000 cases each
   with and without caps (`make report`, seed 20261122, x86-64, -O2 -march=x86-64-v3;
   bench/REPORT.md has every family; `make test` asserts the targets on a fixed-seed sample):
   t_err contained the exact t in all 510,576 float and 523,679 double hits of every variant;
   default path: no misclassification beyond the band in any family in either API (the target
   is the benign ones), t within 0.5 ulps on the well-conditioned hits of the benign families;
   CYL_PRECISE: none beyond the band in any family, 0.5 ulps. Cost per capped call on the
   well-conditioned family (instructions by callgrind, time the median of 5 runs): float 355
   instructions, 39 ns (precise 355, 39 ns; without t_err and the normal 240, 27 ns), double
   652, 58 ns (precise 1105, 84 ns; without t_err and the normal 554, 47 ns), against 119 and
   118 instructions, 29 and 32 ns for the end-point (pa, pb, ra) formulation fed its own input
   form, which misclassifies 19,020 float and 14,704 double cases beyond the band. How each
   path gets there: N9; where the guarantees weaken (extreme ratios, flat disks): N11.

   WHAT IT DOES NOT DO
   ===================
   No ray packets or SIMD, no BVH, no oblique cylinders or cones, no texture coordinates beyond
   v, no nudging of spawned rays (use tmin or the previous hit's t_err). Needs IEEE-754 with
   FLT_EVAL_METHOD == 0 and no -ffast-math (both refused by #error). gcc's contraction outside
   the ISO modes is turned off for this file by a pragma; clang's -ffp-contract=fast ignores
   pragmas: do not build with it.

   LICENSE: MIT. Copyright (c) 2026 the cylinder_isect developers.
*/
#if !defined(CYL__BODY)
#ifndef CYLINDER_ISECT_H
#define CYLINDER_ISECT_H

#define CYL_VERSION_MAJOR 1
#define CYL_VERSION_MINOR 0
#define CYL_VERSION_PATCH 0

#if defined(__FAST_MATH__)
#error "cylinder_isect.h: -ffast-math reorders and drops the operations the error-free transformations and the error bounds rely on; build this translation unit without it"
#endif
#if defined(CYL_NO_FLOAT) && defined(CYL_NO_DOUBLE)
#error "cylinder_isect.h: CYL_NO_FLOAT and CYL_NO_DOUBLE together leave nothing"
#endif

#include <float.h>
#include <stdint.h>
/* 0: every type in its own precision. 16 and 32 (ISO/IEC TS 18661-3, e.g. gcc with
   AVX512-FP16 in GNU modes) only widen _Float16: float and double still round to themselves. */
#if !defined(FLT_EVAL_METHOD) || !(FLT_EVAL_METHOD == 0 || FLT_EVAL_METHOD == 16 || FLT_EVAL_METHOD == 32)
#error "cylinder_isect.h: needs FLT_EVAL_METHOD == 0 (no excess precision, e.g. x87, or GCC's ISO mode on s390x); use SSE2, or -fexcess-precision=fast / -std=gnu99 where float is native"
#endif

#ifndef CYL_DEF
#define CYL_DEF static inline
#endif
/* Internal functions are inlined into the public ones even when large, so that options passed
   as constants fold away inside them (the public functions stay CYL_DEF, the caller's choice).
   Size-optimised builds (-Os) keep the compiler's own choice: options still fold there, and
   forcing cost Cortex-M4F up to 3.7x the code (make sizes). CYL_INTERNAL overrides both. */
#if defined(CYL_INTERNAL)
#define CYL__INL CYL_INTERNAL
#elif (defined(__GNUC__) || defined(__clang__)) && !defined(__OPTIMIZE_SIZE__)
#define CYL__INL static inline __attribute__((always_inline))
#else
#define CYL__INL static inline
#endif
/* The compensated solver, which answers what the fast path hands over, out of line (also under
   -Os: the deepest stack is then the larger of the two paths, not their sum). */
#if defined(__GNUC__) || defined(__clang__)
#define CYL__SLOW static __attribute__((noinline, unused))
#else
#define CYL__SLOW static inline
#endif
/* The compensated solver and its output (solvet, finish): one out-of-line copy per precision,
   shared by every entry point and option set, for which options are run-time values (it
   answers only what the fast path hands over). Under -Os the compiler's choice, as above. */
#if (defined(__GNUC__) || defined(__clang__)) && !defined(__OPTIMIZE_SIZE__) && !defined(CYL_INTERNAL)
#define CYL__EXACT static __attribute__((noinline, unused))
#else
#define CYL__EXACT CYL__INL
#endif
/* The fast path out of line under -Os too: inlined into an entry point, its frame adds to the
   solver's (make sizes, Cortex-M4F's open tube: 776 B of stack, about 480 B without).
   Options still fold: gcc specialises it for constant ones (.constprop). */
#if (defined(__GNUC__) || defined(__clang__)) && defined(__OPTIMIZE_SIZE__) && !defined(CYL_INTERNAL)
#define CYL__FAST static __attribute__((noinline, unused))
#else
#define CYL__FAST CYL__INL
#endif
/* The parts of one long function, split for reading: each has one caller, into which it is
   inlined, also under -Os. */
#if defined(CYL_INTERNAL)
#define CYL__PART CYL_INTERNAL
#elif defined(__GNUC__) || defined(__clang__)
#define CYL__PART static inline __attribute__((always_inline))
#else
#define CYL__PART static inline
#endif
#ifndef CYL_HEADER_FILENAME
#define CYL_HEADER_FILENAME "cylinder_isect.h"
#endif

/* Return values. */
#define CYL_HIT          1
#define CYL_MISS         0
#define CYL_E_NULL      (-1)
#define CYL_E_NONFINITE (-2)
#define CYL_E_ZERO_DIR  (-3)
#define CYL_E_ZERO_AXIS (-4)
#define CYL_E_RADIUS    (-5)
#define CYL_E_HEIGHT    (-6)
#define CYL_E_TRANGE    (-7)
#define CYL_E_OPTION    (-8)

/* Option bits. */
#define CYL_CAPS         0x01u
#define CYL_OUTWARD      0x02u
#define CYL_NO_TANGENT   0x04u
#define CYL_PRECISE      0x08u
#define CYL_NO_NORMAL    0x10u
#define CYL_NO_ERRBOUND  0x20u
#define CYL_TRUSTED      0x40u
#define CYL_OPTIONS_ALL  0x7fu

/* hit.part */
#define CYL_SIDE     0
#define CYL_CAP_LOW  1
#define CYL_CAP_HIGH 2

/* hit.flags */
#define CYL_F_INSIDE   0x1u
#define CYL_F_TANGENT  0x2u
#define CYL_F_PARALLEL 0x4u

/* Tolerances (see "Why these tolerances" above). Written as quotients so that C++11, which has
   no hexadecimal float literals, reads them too. */
#ifndef CYL_TANGENT_TOLF
#define CYL_TANGENT_TOLF (1.0f / 65536.0f)                    /* 2^-16 */
#endif
#ifndef CYL_TANGENT_TOL
#define CYL_TANGENT_TOL (1.0 / 35184372088832.0)              /* 2^-45 */
#endif
#ifndef CYL_PARALLEL_TOLF
#define CYL_PARALLEL_TOLF (1.0f / 16777216.0f)                /* 2^-24 */
#endif
#ifndef CYL_PARALLEL_TOL
#define CYL_PARALLEL_TOL (1.0 / 9007199254740992.0)           /* 2^-53 */
#endif

/* CYL_PRECISE's fast path: at most this many exact-quadratic steps with the plain √ from one
   start (where the step with √ from its own residual does not certify itself: rare), then the
   solver; fast()'s closed-form test of it (x^6) assumes 6 */
#define CYL__STEPS 6
#ifdef CYL_NO_PRECISE
#define CYL__SUPPORTED (CYL_OPTIONS_ALL & ~CYL_PRECISE)
#else
#define CYL__SUPPORTED CYL_OPTIONS_ALL
#endif

/* Environment hooks: builtins where the compiler has them (no header, inlined with a target
   FMA and -fno-math-errno), <math.h> otherwise. */
#if defined(__GNUC__) || defined(__clang__)
#define CYL__MEMCPY(d, s, n) __builtin_memcpy(d, s, n)
#define CYL__FABSF(x) __builtin_fabsf(x)
#define CYL__FABS(x) __builtin_fabs(x)
#ifndef CYL_SQRTF
#define CYL_SQRTF(x) __builtin_sqrtf(x)
#endif
#ifndef CYL_SQRT
#define CYL_SQRT(x) __builtin_sqrt(x)
#endif
#ifndef CYL_FMAF
#define CYL_FMAF(a, b, c) __builtin_fmaf(a, b, c)
#endif
#ifndef CYL_FMA
#define CYL_FMA(a, b, c) __builtin_fma(a, b, c)
#endif
#else
#include <string.h>
#define CYL__MEMCPY(d, s, n) memcpy(d, s, n)
#define CYL__FABSF(x) ((x) < 0 ? -(x) : (x))
#define CYL__FABS(x) ((x) < 0 ? -(x) : (x))
#if !defined(CYL_SQRTF) || !defined(CYL_SQRT) || !defined(CYL_FMAF) || !defined(CYL_FMA)
#include <math.h>
#endif
#ifndef CYL_SQRTF
#define CYL_SQRTF(x) sqrtf(x)
#endif
#ifndef CYL_SQRT
#define CYL_SQRT(x) sqrt(x)
#endif
#ifndef CYL_FMAF
#define CYL_FMAF(a, b, c) fmaf(a, b, c)
#endif
#ifndef CYL_FMA
#define CYL_FMA(a, b, c) fma(a, b, c)
#endif
#endif

/* Fast path arithmetic. A hardware FMA (the compiler says so) lets the fast path form the
   cross products with Kahan's algorithm; without one it uses plain products and wider bounds. */
#if defined(__FP_FAST_FMA) || defined(__FMA__) || defined(__aarch64__) || defined(_M_ARM64)
#define CYL__DKAHAN 1
#else
#define CYL__DKAHAN 0
#endif
#if defined(__FP_FAST_FMAF) || defined(__FMA__) || defined(__aarch64__) || defined(_M_ARM64) || \
    (defined(__ARM_FEATURE_FMA) && defined(__ARM_FP) && (__ARM_FP & 4))
#define CYL__FKAHAN 1
#else
#define CYL__FKAHAN 0
#endif
#if CYL__DKAHAN
#define CYL__DMADD(a, b, c) CYL_FMA(a, b, c)
#else
#define CYL__DMADD(a, b, c) ((a) * (b) + (c))
#endif
#if CYL__FKAHAN
#define CYL__FMADD(a, b, c) CYL_FMAF(a, b, c)
#else
#define CYL__FMADD(a, b, c) ((a) * (b) + (c))
#endif
/* CYL_FLOAT_WIDE: the float API's fast path computes in double, where double is hardware. */
#ifndef CYL_FLOAT_WIDE
#if !defined(CYL_NO_DOUBLE) &&                                                                 \
    (defined(__x86_64__) || defined(_M_X64) || defined(__aarch64__) || defined(_M_ARM64) ||      \
     (defined(__ARM_FP) && (__ARM_FP & 8)) || (defined(__riscv_flen) && __riscv_flen >= 64) || \
     defined(__s390x__) || defined(__powerpc64__))
#define CYL_FLOAT_WIDE 1
#else
#define CYL_FLOAT_WIDE 0
#endif
#endif
#if CYL_FLOAT_WIDE && defined(CYL_NO_DOUBLE)
#error "cylinder_isect.h: CYL_FLOAT_WIDE computes in double, which CYL_NO_DOUBLE excludes"
#endif

CYL_DEF const char *cyl_strerror(int code)
{
    switch (code) {
    case CYL_HIT: return "hit";
    case CYL_MISS: return "miss";
    case CYL_E_NULL: return "a pointer argument is NULL";
    case CYL_E_NONFINITE: return "a coordinate of o, d, c or a is NaN or infinite";
    case CYL_E_ZERO_DIR: return "the ray direction d is the zero vector";
    case CYL_E_ZERO_AXIS: return "the cylinder axis a is the zero vector";
    case CYL_E_RADIUS: return "the radius is not a positive finite number";
    case CYL_E_HEIGHT: return "the height is not positive (NaN or <= 0)";
    case CYL_E_TRANGE: return "the t range is empty or NaN (tmin > tmax)";
    case CYL_E_OPTION: return "unknown or compiled-out option bit";
    default: return "unknown cylinder_isect return code";
    }
}

/* ---- double instance (first: the float API computed in double calls its exact C) ---- */
#ifndef CYL_NO_DOUBLE
#define CYL__BODY 1
#define CYL__R double
#define CYL__UINT uint64_t
#define CYL__N(x) cyld_##x
#define CYL__P(x) cyl__d_##x
#define CYL__C(x) x
#define CYL__SQRTR(x) CYL_SQRT(x)
#define CYL__FMAR(a, b, c) CYL_FMA(a, b, c)
#define CYL__FABSR(x) CYL__FABS(x)
#define CYL__U (DBL_EPSILON * 0.5)
#define CYL__MAXR DBL_MAX
#define CYL__MINR DBL_MIN
#define CYL__MANT 53
#define CYL__EBIAS 1023
#define CYL__EMASK 0x7ffu
#define CYL__TWO_MANT 9007199254740992.0
#define CYL__TANG CYL_TANGENT_TOL
#define CYL__TBAND 2.8421709430404007e-14 /* 2^-45 = 2^-(53-8) */
#define CYL__PARA CYL_PARALLEL_TOL
#define CYL__RDIR 18446744073709551616.0
#define CYL__RLEN 3.402823669209384634633746e38
#define CYL__RCOARSE 1.1270725851789228e-131 /* 2^-435 */
#define CYL__LD 1
#define CYL__WIDE 0
#include CYL_HEADER_FILENAME /* the body #undefs the parameters above */
#endif

/* ---- float instance ---- */
#ifndef CYL_NO_FLOAT
#define CYL__BODY 1
#define CYL__R float
#define CYL__UINT uint32_t
#define CYL__N(x) cylf_##x
#define CYL__P(x) cyl__f_##x
#define CYL__C(x) x##f
#define CYL__SQRTR(x) CYL_SQRTF(x)
#define CYL__FMAR(a, b, c) CYL_FMAF(a, b, c)
#define CYL__FABSR(x) CYL__FABSF(x)
#define CYL__U (FLT_EPSILON * 0.5f)
#define CYL__MAXR FLT_MAX
#define CYL__MINR FLT_MIN
#define CYL__MANT 24
#define CYL__EBIAS 127
#define CYL__EMASK 0xffu
#define CYL__TWO_MANT 16777216.0f
#define CYL__TANG CYL_TANGENT_TOLF
#define CYL__TBAND 1.52587890625e-05f /* 2^-16 = 2^-(24-8): CYL_PRECISE's t-range band */
#define CYL__PARA CYL_PARALLEL_TOLF
#define CYL__RDIR 16.0f
#define CYL__RLEN 65536.0f
#define CYL__RCOARSE 4.656612873077393e-10f /* 2^-31 */
#define CYL__LD CYL_FLOAT_WIDE /* the fast path's type: double (1) or float (0) */
#define CYL__WIDE CYL_FLOAT_WIDE
#include CYL_HEADER_FILENAME /* the body #undefs the parameters above */
#endif

#endif /* CYLINDER_ISECT_H */

#else /* CYL__BODY: one precision, written once; included above with CYL__R = float, double */

/* No contraction of a product into a following sum inside this file: gcc outside the ISO
   modes (-std=gnu*, its default, and C++) fuses x*y + z across statements into an FMA where
   the target has one, and a TwoSum of a rounded product then loses its exact error term: the
   double words of the solver and of the corrections came out wrong by far more than their
   bounds. ISO C modes (-std=c99, c11, ...) do not contract; clang contracts
   only inside one expression, which every error-free transformation here keeps apart, except
   under -ffp-contract=fast, which ignores this and every other pragma: do not use it. Only
   where gcc would contract (a GNU mode or C++, and a hardware FMA): the pragma also changes
   how gcc -Os expands struct copies (a memcpy call on RV32 and Cortex-M0). */
#if defined(__GNUC__) && !defined(__clang__) &&                                                 \
    (!defined(__STRICT_ANSI__) || defined(__cplusplus)) &&                                       \
    (defined(__FP_FAST_FMA) || defined(__FP_FAST_FMAF))
#define CYL__NOCONTRACT 1
#pragma GCC push_options
#pragma GCC optimize("fp-contract=off")
#else
#define CYL__NOCONTRACT 0
#endif

/* The fast path's working type (see the fast path): double or float, chosen by the instance. */
#if CYL__LD
#define CYL__L double
#define CYL__LU (DBL_EPSILON * 0.5)
#define CYL__LMIN DBL_MIN
#define CYL__LMAX DBL_MAX
#define CYL__LSQRT(x) CYL_SQRT(x)
#define CYL__LABS(x) CYL__FABS(x)
#define CYL__LFMA(a, b, c) CYL_FMA(a, b, c)
#define CYL__LMADD(a, b, c) CYL__DMADD(a, b, c)
#define CYL__LKAHAN CYL__DKAHAN
#define CYL__LHI 2.037035976334486e90 /* 2^300 */
#define CYL__LDIR 1.329227995784916e36 /* 2^120 */
#ifndef CYL_NO_FAST_PATH
#define CYL__QUICK 1 /* the lean path (see there) */
#else
#define CYL__QUICK 0
#endif
#else
#define CYL__QUICK 0
#define CYL__L float
#define CYL__LU (FLT_EPSILON * 0.5f)
#define CYL__LMIN FLT_MIN
#define CYL__LMAX FLT_MAX
#define CYL__LSQRT(x) CYL_SQRTF(x)
#define CYL__LABS(x) CYL__FABSF(x)
#define CYL__LFMA(a, b, c) CYL_FMAF(a, b, c)
#define CYL__LMADD(a, b, c) CYL__FMADD(a, b, c)
#define CYL__LKAHAN CYL__FKAHAN
#define CYL__LHI 1099511627776.0f /* 2^40 */
#define CYL__LDIR 4096.0f /* 2^12 */
#endif

typedef struct CYL__N(ray) { CYL__R o[3], d[3], tmin, tmax; } CYL__N(ray);
typedef struct CYL__N(cylinder) { CYL__R c[3], a[3], r, h; } CYL__N(cylinder);
typedef struct CYL__N(hit) {
    CYL__R t, t_err, n[3], v;
    int part;
    unsigned flags;
} CYL__N(hit);

/* ------------------------------------------------------------------ small exact tools */

CYL__INL CYL__R CYL__P(abs)(CYL__R x) { return CYL__FABSR(x); }
CYL__INL CYL__R CYL__P(max)(CYL__R x, CYL__R y) { return x > y ? x : y; }
CYL__INL int CYL__P(finite)(CYL__R x) { return x >= -CYL__MAXR && x <= CYL__MAXR; }
CYL__INL int CYL__P(nonzero)(CYL__R x) { return x < 0 || x > 0; }
CYL__INL CYL__R CYL__P(amax3)(const CYL__R x[3])
{
    return CYL__P(max)(CYL__P(abs)(x[0]), CYL__P(max)(CYL__P(abs)(x[1]), CYL__P(abs)(x[2])));
}

/* floor(log2(x)) for finite x > 0, from the exponent bits: no libm, exact for subnormals. */
CYL__INL int CYL__P(ilogb)(CYL__R x)
{
    CYL__UINT b;
    int e, shift = 0;
    CYL__MEMCPY(&b, &x, sizeof b);
    e = (int)((b >> (CYL__MANT - 1)) & CYL__EMASK);
    if (e == 0) { /* subnormal: 2^MANT brings it into the normal range exactly */
        x *= CYL__TWO_MANT;
        CYL__MEMCPY(&b, &x, sizeof b);
        e = (int)((b >> (CYL__MANT - 1)) & CYL__EMASK);
        shift = CYL__MANT;
    }
    return e - CYL__EBIAS - shift;
}

/* 2^k for k in the normal exponent range [1 - EBIAS, EBIAS]. */
CYL__INL CYL__R CYL__P(exp2i)(int k)
{
    CYL__UINT b = (CYL__UINT)(k + CYL__EBIAS) << (CYL__MANT - 1);
    CYL__R x;
    CYL__MEMCPY(&x, &b, sizeof x);
    return x;
}

/* Two factors whose product is 2^k, each a normal number, for |k| up to twice the exponent
   range. Both move x the same way, so x * f1 * f2 rounds at most where the final value is
   subnormal. */
CYL__INL void CYL__P(pow2pair)(int k, CYL__R f[2])
{
    int lo = 1 - CYL__EBIAS, hi = CYL__EBIAS;
    int k1 = k < lo ? lo : (k > hi ? hi : k);
    int k2 = k - k1;
    k2 = k2 < lo ? lo : (k2 > hi ? hi : k2);
    f[0] = CYL__P(exp2i)(k1);
    f[1] = CYL__P(exp2i)(k2);
}

/* x·2^k for any k: steps of the largest normal powers, so that only the last step can round
   (into the subnormals). */
CYL__INL CYL__R CYL__P(scale)(CYL__R x, int k)
{
    const int lo = 1 - CYL__EBIAS, hi = CYL__EBIAS;
    while (k > hi) { x *= CYL__P(exp2i)(hi); k -= hi; }
    while (k < lo) { x *= CYL__P(exp2i)(lo); k -= lo; }
    return x * CYL__P(exp2i)(k);
}

/* ab − cd with Kahan's FMA algorithm: relative error <= 2u (Jeannerod, Louvet, Muller 2013). */
CYL__INL CYL__R CYL__P(dop)(CYL__R a, CYL__R b, CYL__R c, CYL__R d)
{
    CYL__R w = c * d;
    CYL__R e = CYL__FMAR(-c, d, w);
    CYL__R f = CYL__FMAR(a, b, -w);
    return f + e;
}

CYL__INL void CYL__P(cross)(const CYL__R x[3], const CYL__R y[3], CYL__R z[3])
{
    z[0] = CYL__P(dop)(x[1], y[2], x[2], y[1]);
    z[1] = CYL__P(dop)(x[2], y[0], x[0], y[2]);
    z[2] = CYL__P(dop)(x[0], y[1], x[1], y[0]);
}

CYL__INL CYL__R CYL__P(dot)(const CYL__R x[3], const CYL__R y[3])
{
    return CYL__FMAR(x[2], y[2], CYL__FMAR(x[1], y[1], x[0] * y[0]));
}

CYL__INL CYL__R CYL__P(asum3)(const CYL__R x[3])
{
    return CYL__P(abs)(x[0]) + CYL__P(abs)(x[1]) + CYL__P(abs)(x[2]);
}

/* |x|·|y| summed componentwise: the scale of a dot product's rounding error. */
CYL__INL CYL__R CYL__P(adot)(const CYL__R x[3], const CYL__R y[3])
{
    return CYL__P(abs)(x[0] * y[0]) + CYL__P(abs)(x[1] * y[1]) + CYL__P(abs)(x[2] * y[2]);
}

/* Error-free transformations (Knuth's TwoSum; TwoProd with FMA) and a compensated
   accumulator in the style of Ogita, Rump and Oishi's Sum2/Dot2: hi + lo carries the sum with
   error about u·|sum| + γ²·Σ|terms|. */
typedef struct CYL__P(acc) { CYL__R hi, lo; } CYL__P(acc);

CYL__INL void CYL__P(two_sum)(CYL__R a, CYL__R b, CYL__R *s, CYL__R *e)
{
    CYL__R x = a + b, bb = x - a;
    *s = x;
    *e = (a - (x - bb)) + (b - bb);
}

CYL__INL void CYL__P(acc_add)(CYL__P(acc) *s, CYL__R x)
{
    CYL__R e;
    CYL__P(two_sum)(s->hi, x, &s->hi, &e);
    s->lo += e;
}

CYL__INL void CYL__P(acc_prod)(CYL__P(acc) *s, CYL__R x, CYL__R y)
{
    CYL__R p = x * y;
    CYL__R e = CYL__FMAR(x, y, -p);
    CYL__P(acc_add)(s, p);
    s->lo += e;
}

/* z = x × (yh + yl) as a double word zh + zl (x exact): each component's two products are
   split exactly, so zh + zl is accurate to O(u²) relative. */
/* A fresh accumulator started with the exact product x·y. */
CYL__INL CYL__P(acc) CYL__P(acc_first)(CYL__R x, CYL__R y)
{
    CYL__P(acc) s;
    s.hi = x * y;
    s.lo = CYL__FMAR(x, y, -s.hi);
    return s;
}

/* x·y for exact x and y, into a fresh accumulator. */
CYL__INL CYL__P(acc) CYL__P(dot_acc)(const CYL__R x[3], const CYL__R y[3])
{
    CYL__P(acc) s = CYL__P(acc_first)(x[0], y[0]);
    CYL__P(acc_prod)(&s, x[1], y[1]);
    CYL__P(acc_prod)(&s, x[2], y[2]);
    return s;
}

/* x·y as if computed in twice the precision, then rounded (Ogita, Rump, Oishi's Dot2). */
CYL__INL CYL__R CYL__P(dot2)(const CYL__R x[3], const CYL__R y[3])
{
    CYL__P(acc) s = CYL__P(dot_acc)(x, y);
    return s.hi + s.lo;
}

/* s as a normalised double word: hi = s rounded, lo what is left (Fast2Sum). */
CYL__INL void CYL__P(acc_split)(CYL__P(acc) s, CYL__R *hi, CYL__R *lo)
{
    *hi = s.hi + s.lo;
    *lo = s.lo - (*hi - s.hi);
}

/* One component x_k (yh + yl)_l − x_l (yh + yl)_k as hi + lo. */
CYL__INL void CYL__P(dop_dw)(CYL__R xk, CYL__R xl, CYL__R yhl, CYL__R yhk, CYL__R yll,
                            CYL__R ylk, CYL__R *zh, CYL__R *zl)
{
    CYL__R p1 = xk * yhl, e1 = CYL__FMAR(xk, yhl, -p1);
    CYL__R p2 = xl * yhk, e2 = CYL__FMAR(xl, yhk, -p2);
    CYL__R h, e3, lo;
    CYL__P(two_sum)(p1, -p2, &h, &e3);
    lo = (e1 - e2) + e3 + (xk * yll - xl * ylk);
    *zh = h + lo;
    *zl = lo - (*zh - h);
}

CYL__INL void CYL__P(cross_dw)(const CYL__R x[3], const CYL__R yh[3], const CYL__R yl[3],
                              CYL__R zh[3], CYL__R zl[3])
{
    CYL__P(dop_dw)(x[1], x[2], yh[2], yh[1], yl[2], yl[1], &zh[0], &zl[0]);
    CYL__P(dop_dw)(x[2], x[0], yh[0], yh[2], yl[0], yl[2], &zh[1], &zl[1]);
    CYL__P(dop_dw)(x[0], x[1], yh[1], yh[0], yl[1], yl[0], &zh[2], &zl[2]);
}

/* (nh + nl) / (dh + dl) to about u: one correction of the quotient with the exact remainder
   of nh − q·dh (FMA). */
CYL__INL CYL__R CYL__P(div_dw)(CYL__R nh, CYL__R nl, CYL__R dh, CYL__R dl)
{
    CYL__R q = nh / dh, rem;
    if (!CYL__P(finite)(q)) return q; /* overflowed (a·d subnormal): the remainder is NaN */
    rem = CYL__FMAR(-q, dh, nh) + nl - q * dl;
    return q + rem / dh;
}

/* Σ (xh + xl)_i (yh + yl)_i into an accumulator. */
CYL__INL void CYL__P(acc_dot_dw)(CYL__P(acc) *s, const CYL__R xh[3], const CYL__R xl[3],
                                const CYL__R yh[3], const CYL__R yl[3])
{
    CYL__P(acc_prod)(s, xh[0], yh[0]);
    CYL__P(acc_prod)(s, xh[1], yh[1]);
    CYL__P(acc_prod)(s, xh[2], yh[2]);
    s->lo += (xh[0] * yl[0] + xl[0] * yh[0]) + (xh[1] * yl[1] + xl[1] * yh[1]) +
             (xh[2] * yl[2] + xl[2] * yh[2]);
}

/* D = r²|s|² − P² as one compensated sum, from s = sh + sl and P = Ph + Pl as double words:
   each (r·s_i)² split exactly up to O(u²) of itself, P² from P's double word. */
CYL__INL CYL__R CYL__P(disc_dw)(CYL__R r, const CYL__R sh[3], const CYL__R sl[3], CYL__R Ph,
                               CYL__R Pl)
{
    CYL__P(acc) sd;
    int i;
    sd.hi = sd.lo = 0;
    for (i = 0; i < 3; i++) {
        CYL__R rs = r * sh[i], rsl = CYL__FMAR(r, sh[i], -rs);
        CYL__P(acc_prod)(&sd, rs, rs);
        sd.lo += 2 * rs * (rsl + r * sl[i]);
    }
    CYL__P(acc_prod)(&sd, -Ph, Ph);
    sd.lo -= 2 * Ph * Pl;
    return sd.hi + sd.lo;
}

/* ------------------------------------------------------------------ validation */

CYL__INL int CYL__P(validate)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl)
{
    /* x·0 is 0 for finite x and NaN for NaN or ±inf: one branch for all twelve numbers. */
    CYL__R z = 0;
    int i;
    for (i = 0; i < 3; i++)
        z += (ray->o[i] * 0 + ray->d[i] * 0) + (cyl->c[i] * 0 + cyl->a[i] * 0);
    if (!(z < 1)) return CYL_E_NONFINITE;
    if (!(CYL__P(amax3)(ray->d) > 0)) return CYL_E_ZERO_DIR;
    if (!(CYL__P(amax3)(cyl->a) > 0)) return CYL_E_ZERO_AXIS;
    if (!(cyl->r > 0) || !(cyl->r <= CYL__MAXR)) return CYL_E_RADIUS;
    if (!(cyl->h > 0)) return CYL_E_HEIGHT;
    if (!(ray->tmin <= ray->tmax)) return CYL_E_TRANGE;
    return 0;
}

CYL__INL int CYL__P(check)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts)
{
    int rc;
    if (!ray || !cyl) return CYL_E_NULL;
    rc = (opts & CYL_TRUSTED) ? 0 : CYL__P(validate)(ray, cyl);
    if (!rc && (opts & ~(unsigned)CYL__SUPPORTED)) rc = CYL_E_OPTION;
    return rc;
}

/* Where the lean path runs (see quick), what it hands over the fast path would hand over too,
   except for CYL_PRECISE in the double API, which the fast path certifies decision by
   decision; so the fast path serves that, and every valid option set of the float API
   computed in float. In the float API computed in double the solver's entry points try the
   fast path first (see there). */
CYL__INL int CYL__P(fastok)(unsigned opts)
{
#if defined(CYL_NO_FAST_PATH) || (CYL__QUICK && (CYL__WIDE || defined(CYL_NO_PRECISE)))
    (void)opts;
    return 0;
#elif CYL__QUICK
    return !(opts & ~(unsigned)CYL__SUPPORTED) && (opts & CYL_PRECISE);
#else
    return !(opts & ~(unsigned)CYL__SUPPORTED);
#endif
}

/* ------------------------------------------------------------------ the solver */

/* Everything below works in a frame scaled by exact powers of two: the largest component of a
   and of d in [1, 2), the largest of |o − c|, r, h in [1, 2). A user t is the frame's t times
   2^e. The scaled w (= o − c) is exact up to its one rounding (default path) or exactly
   wh + wl (precise path). */
typedef struct CYL__P(frame) {
    CYL__R a[3], d[3], w[3], wl[3];
    CYL__R r, H;          /* radius, half height (+inf: infinite tube)                     */
    CYL__R aa, aal, na;   /* |a|² (+ its low part), |a|                                    */
    CYL__R s[3], sl[3];   /* s = a × d (+ low part on the precise path)                    */
    CYL__R m[3], ml[3];   /* m = a × w (+ low part)                                        */
    CYL__R A, R2, sq;     /* |s|², r²|a|², √(|a|²D) (the wall's half discriminant)       */
    CYL__R R2l;           /* precise path: low part of r²|a|²                              */
    CYL__R ad, aw;        /* a·d, a·w                                                      */
    CYL__R awl, nal, adl; /* precise path: low parts of a·w, |a| and a·d                    */
    CYL__R Hu;            /* h/2 in user units, rounded toward zero                        */
    int coarse;           /* r² underflows in the frame: linear wall test, t_err = +inf     */
    int capscale;         /* H is in units 2^capscale times the frame's (h/2 would overflow) */
    int e;                /* user t = frame t · 2^e                                        */
    int el;               /* user length = frame length · 2^el                             */
    int precise;
    CYL__R tang, para;    /* the tangent band and parallel tolerance (the float API's where
                             the double solver answers for it, see wsolve)                 */
} CYL__P(frame);

/* One crossing found by the solver, before the t range and the output. */
typedef struct CYL__P(cand) {
    CYL__R t;             /* frame t                                                       */
    CYL__R tu;            /* user t                                                        */
    int part;
    unsigned flags;
} CYL__P(cand);

/* The frame. Arithmetic is equivariant under exact power-of-two scaling as long as nothing
   overflows or underflows, so inputs of moderate size (the largest component of a and of d
   within 2^±RDIR, the lengths |o − c|, r, h within 2^±RLEN: every product the solver forms then
   stays far inside the exponent range) are used as they are, and anything else is first
   scaled exactly so that those maxima land in [1, 2). Both give the same bits, up to the
   scaling, wherever no intermediate underflows. */
CYL__INL void CYL__P(prepare)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                             unsigned opts, CYL__P(frame) *f)
{
    const CYL__R rdir = CYL__RDIR, rlen = CYL__RLEN;
    CYL__R ma = CYL__P(amax3)(cyl->a), md = CYL__P(amax3)(ray->d), L, rr = cyl->r, hh = cyl->h;
    int i, hfin = hh <= CYL__MAXR;
#ifndef CYL_NO_PRECISE
    f->precise = (opts & CYL_PRECISE) != 0;
#else
    (void)opts;
    f->precise = 0;
#endif
    /* w = o − c exactly, as w + wl (TwoSum): its rounding would otherwise be the largest
       error left for origins far from the axis */
    for (i = 0; i < 3; i++) CYL__P(two_sum)(ray->o[i], -cyl->c[i], &f->w[i], &f->wl[i]);
    /* the wall is quadratic in |o − c| and r, the caps only linear in h: the scale follows the
       first two, so that a very long tube does not crush r and o − c toward underflow */
    L = CYL__P(max)(CYL__P(amax3)(f->w), rr);
    if (ma >= 1 / rdir && ma <= rdir && md >= 1 / rdir && md <= rdir && L <= rlen &&
        rr >= 1 / rlen && (!hfin || (hh >= 1 / rlen && hh <= rlen))) {
        for (i = 0; i < 3; i++) {
            f->a[i] = cyl->a[i];
            f->d[i] = ray->d[i];
        }
        f->r = rr;
        f->H = hh * CYL__C(0.5);
        f->e = f->el = 0;
        f->coarse = f->capscale = 0;
    } else {
        CYL__R fa[2], fd[2], fl[2], fw[2];
        int kl, kd, half[3];
        /* o − c overflows only where both are near the top of the range: that component is
           formed from halves (exact there: no other number is touched, so a subnormal r or
           coordinate keeps every bit) and carries one more factor 2 into the frame. */
        kl = CYL__P(ilogb)(rr);
        for (i = 0; i < 3; i++) {
            half[i] = !CYL__P(finite)(f->w[i]);
            if (half[i])
                CYL__P(two_sum)(ray->o[i] * CYL__C(0.5), -cyl->c[i] * CYL__C(0.5), &f->w[i],
                                &f->wl[i]);
            if (CYL__P(nonzero)(f->w[i]) && CYL__P(ilogb)(CYL__P(abs)(f->w[i])) + half[i] > kl)
                kl = CYL__P(ilogb)(CYL__P(abs)(f->w[i])) + half[i];
        }
        kd = CYL__P(ilogb)(md);
        /* h/2 alone has a scale of its own when it is so much longer that it would overflow
           in this frame: the cap planes then use lengths 2^capscale times coarser */
        f->capscale = hfin && CYL__P(ilogb)(hh) - kl > CYL__EBIAS - 4
                          ? CYL__P(ilogb)(hh) - (CYL__EBIAS - 4) - kl : 0;
        CYL__P(pow2pair)(-CYL__P(ilogb)(ma), fa);
        CYL__P(pow2pair)(-kd, fd);
        CYL__P(pow2pair)(-kl, fl);
        for (i = 0; i < 3; i++) {
            f->a[i] = cyl->a[i] * fa[0] * fa[1];
            f->d[i] = ray->d[i] * fd[0] * fd[1];
            fw[0] = fl[0];
            fw[1] = half[i] ? fl[1] * 2 : fl[1];
            f->w[i] = f->w[i] * fw[0] * fw[1];
            f->wl[i] = f->wl[i] * fw[0] * fw[1];
        }
        f->r = rr * fl[0] * fl[1];
        f->H = (f->capscale ? CYL__P(scale)(hh, -(kl + f->capscale)) : hh * fl[0] * fl[1]) *
               CYL__C(0.5);
        f->e = kl - kd;
        f->el = kl;
        f->coarse = f->r < CYL__RCOARSE;
    }
    /* h/2 for the reported v, never above the true half height (h/2 of an odd subnormal h
       rounds up) */
    f->Hu = cyl->h * CYL__C(0.5);
    if (f->Hu + f->Hu > cyl->h) f->Hu = (cyl->h - CYL__MINR * 2 * CYL__U) * CYL__C(0.5);
    {
        /* |a|² as a double word aa + aal (the cap planes and r²|a|² use the low part) */
        CYL__P(acc) sa = CYL__P(dot_acc)(f->a, f->a);
        CYL__P(acc_split)(sa, &f->aa, &f->aal);
    }
    f->na = CYL__SQRTR(f->aa);
}

/* The wall. The distance of x(t) = w + t·d from the axis is |a × x(t)|/|a|, so the crossings
   solve f(t) = |m + t·s|² − r²|a|² = A t² + 2B t + C = 0 with s = a × d, m = a × w,
   A = |s|², B = m·s, C = |m|² − r²|a|². Its discriminant B² − AC = |a|²·D with
   D = r²A − P², P = w·s (Lagrange: |m × s| = |a|·|w·s|), and D = r²A·e with e = 1 − ρ²/r².
   Error analysis of e = D/(r²A) on the default path: w and s are exact to O(u²), P = w·s is
   a compensated dot (error u|P| + O(u²)|w||s|), r² is split exactly, A = |s|² carries 3u; so
   |ê − e| <= about 8u + O(u²)|w|²/r², which is what CYL_TANGENT_TOL is set against; the
   precise path also compensates A and P². Returns 0 (no crossing), or 1 with t[0] <= t[1]
   and *tangent set. */
/* The solver's C = |m|² − r²|a|² as one compensated sum of the double words m + ml and
   R2 + R2l = r²|a|², in both tiers (the default mode needs it for an origin on the surface
   within the roundings: see fc0). Inline: called out of line it made the
   precise tier's hand-overs about twice as slow in time (not in instructions). */
CYL__INL CYL__R CYL__P(wallc)(const CYL__P(frame) *f, CYL__R R2, CYL__R R2l)
{
    CYL__P(acc) sc;
    sc.hi = -R2;
    sc.lo = -R2l;
    CYL__P(acc_dot_dw)(&sc, f->m, f->ml, f->m, f->ml);
    return sc.hi + sc.lo;
}

CYL__INL int CYL__P(wall)(CYL__P(frame) *f, unsigned opts, CYL__R t[2],
                         int *tangent)
{
    CYL__R P, D, B, C, sq, q, band, r2 = f->r * f->r;
    int clamped = 0;
#ifndef CYL_NO_PRECISE
    if (f->precise) {
        CYL__P(acc) sp, sb, sc;
        CYL__R Pl;
        int i;
        CYL__P(cross_dw)(f->a, f->w, f->wl, f->m, f->ml);
        sp.hi = sp.lo = sb.hi = sb.lo = sc.hi = sc.lo = 0;
        CYL__P(acc_dot_dw)(&sp, f->w, f->wl, f->s, f->sl);
        CYL__P(acc_split)(sp, &P, &Pl);
        CYL__P(acc_dot_dw)(&sb, f->m, f->ml, f->s, f->sl);
        B = sb.hi + sb.lo;
        /* D = r²|s|² − P² as one compensated sum, C = |m|² − r²|a|² from r²|a|² as a double
           word (wallc), which the root refinement keeps. */
        for (i = 0; i < 3; i++) {
            CYL__R ra = f->r * f->a[i], ral = CYL__FMAR(f->r, f->a[i], -ra);
            CYL__P(acc_prod)(&sc, ra, ra);
            sc.lo += 2 * ra * ral;
        }
        CYL__P(acc_split)(sc, &f->R2, &f->R2l);
        C = CYL__P(wallc)(f, f->R2, f->R2l);
        D = CYL__P(disc_dw)(f->r, f->s, f->sl, P, Pl); /* e to O(u²) */
    } else
#endif
    {
        /* m as a double word from the exact w + wl, P compensated, r²|a|² as a double word:
           what the root correction in finish needs for a residual exact to O(u²); C from them
           compensated (wallc), so that an origin on the surface within the roundings gets its
           crossing near t = 0 right (the solver is the rare path, and one
           compensated sum is less code than a test for when it is needed) */
        CYL__R r2l = CYL__FMAR(f->r, f->r, -r2);
        /* the same m on every entry point, so that occluded and intersect classify alike */
        CYL__P(cross_dw)(f->a, f->w, f->wl, f->m, f->ml);
        {
            CYL__R p = r2 * f->aa;
            f->R2 = p;
            f->R2l = CYL__FMAR(r2, f->aa, -p) + r2 * f->aal + r2l * f->aa;
        }
        P = CYL__P(dot2)(f->w, f->s) + (CYL__P(dot)(f->w, f->sl) + CYL__P(dot)(f->wl, f->s));
        B = CYL__P(dot)(f->m, f->s);
        C = CYL__P(wallc)(f, f->R2, f->R2l);
        D = CYL__P(dop)(r2, f->A, P, P) + r2l * f->A;
    }
    if (f->coarse) {
        /* r is so small against |o − c| or h that r² underflows in the frame: compare ρ with r
           linearly (|P| = ρ|s|), and form the half chord r·√e·|a|/|s| from the ratio ρ/r. */
        CYL__R ns = CYL__SQRTR(f->A), rs = f->r * ns, x, e, hc, tc;
        if (CYL__P(abs)(P) > rs) return 0;
        x = rs > 0 ? CYL__P(abs)(P) / rs : 0;
        e = (1 - x) * (1 + x);
        *tangent = e <= f->tang;
        if (*tangent && (opts & CYL_NO_TANGENT)) return 0;
        hc = f->r * CYL__SQRTR(e) * f->na / ns;
        tc = -B / f->A;
        f->sq = hc * f->A;
        t[0] = tc - hc;
        t[1] = tc + hc;
        (void)C;
        (void)D;
        return 1;
    }
    band = f->tang * r2 * f->A;
    if (D < -band) return 0;
    *tangent = D <= band;
    if (*tangent && (opts & CYL_NO_TANGENT)) return 0;
    if (D < 0) { D = 0; clamped = 1; }
    sq = f->sq = CYL__SQRTR(f->aa * D);
    q = -(B + (B < 0 ? -sq : sq));
    if (clamped || !CYL__P(nonzero)(q)) {
        /* a contact (within the band) at the point of closest approach */
        t[0] = t[1] = -B / f->A;
        return 1;
    }
    t[0] = q / f->A;
    t[1] = C / q;
    if (t[0] > t[1]) { CYL__R x = t[0]; t[0] = t[1]; t[1] = x; }
    return 1;
}

/* The shift δ from t to the lower (upper = 0) or upper root of F + 2Gδ + Aδ², sq = √(G² − AF),
   in the form that does not cancel (refine below explains it; fref uses it too). */
CYL__INL CYL__R CYL__P(qstep)(CYL__R F, CYL__R G, CYL__R sq, CYL__R A, int upper)
{
    if (!upper) return G > 0 ? (-G - sq) / A : (sq - G > 0 ? F / (sq - G) : 0);
    return G < 0 ? (sq - G) / A : (G + sq > 0 ? -F / (G + sq) : 0);
}

/* The solver's exact-quadratic correction of a wall root (the fast and lean paths take the
   same step, qstep, on fres's residual: see fref). With F = f(t) evaluated in
   compensated arithmetic and G = s·(m + t s) (= f'(t)/2), the roots of
   f(t + δ) = F + 2Gδ + Aδ² are δ = (−G ∓ √(G² − AF))/A, and G² − AF = |a|²D is the
   discriminant the solver already has (it does not depend on the shift). Each root is taken in
   the form that does not cancel, so the step is accurate even when the two roots are a few ulps
   apart (a plain Newton step from near the midpoint would jump away). The start is within a
   few ulps, so hi + lo carries the root with about the residual's own rounding, u² relative
   to the terms, and hi is the root correctly rounded in nearly every case. */
CYL__INL void CYL__P(refine)(const CYL__R s[3], const CYL__R sl[3], const CYL__R m[3],
                             const CYL__R ml[3], CYL__R A, CYL__R R2, CYL__R R2l, CYL__R sq,
                             CYL__R t, int upper, CYL__R *hi, CYL__R *lo)
{
    CYL__P(acc) sf;
    CYL__R G = 0, F, dt;
    int i;
    sf.hi = sf.lo = 0;
    for (i = 0; i < 3; i++) {
        CYL__R p = t * s[i], pe = CYL__FMAR(t, s[i], -p), yh, ye, yl;
        CYL__P(two_sum)(m[i], p, &yh, &ye);
        yl = ye + pe + ml[i] + t * sl[i];
        /* y can be far smaller than m and t·s (origin far away): renormalise, so that the
           dropped yl² is O(u²)·y² */
        CYL__P(two_sum)(yh, yl, &yh, &yl);
        CYL__P(acc_prod)(&sf, yh, yh);
        sf.lo += 2 * yh * yl;
        G += (yh + yl) * s[i];
    }
    CYL__P(acc_add)(&sf, -R2);
    F = sf.hi + (sf.lo - R2l);
    dt = CYL__P(qstep)(F, G, sq, A, upper);
    *hi = t + dt; /* |dt| is a few ulps of t: Fast2Sum applies */
    *lo = dt - (*hi - t);
}

/* Which side of the cap planes the wall root t + tl lies on, from the sign of
   a·x ± H|a| = aw + (t + tl)·ad ± H·(na + nal) summed in compensated arithmetic. */
CYL__INL int CYL__P(side)(const CYL__P(frame) *f, CYL__R t, CYL__R tl)
{
    CYL__P(acc) b, lo, hi;
    if (!(f->H <= CYL__MAXR) || !CYL__P(nonzero)(f->ad)) return 0;
    b.hi = b.lo = 0;
    CYL__P(acc_prod)(&b, t, f->ad);
    b.lo += t * f->adl + tl * f->ad + f->awl;
    CYL__P(acc_add)(&b, f->aw);
    lo.hi = hi.hi = b.hi;
    lo.lo = hi.lo = b.lo;
    CYL__P(acc_prod)(&lo, f->H, f->na);   /* v + H, times |a| */
    lo.lo += f->H * f->nal;
    CYL__P(acc_prod)(&hi, -f->H, f->na);  /* v − H, times |a| */
    hi.lo -= f->H * f->nal;
    if (lo.hi + lo.lo < 0) return f->ad > 0 ? -1 : 1;
    if (hi.hi + hi.lo > 0) return f->ad > 0 ? 1 : -1;
    return 0;
}

/* The slab between the cap planes v = −H and v = +H along the ray: [sl[0], sl[1]] with the cap
   part of each end. Returns 0 when the ray runs beside the slab (a·d == 0 outside it). */
CYL__INL int CYL__P(slab)(const CYL__P(frame) *f, CYL__R sl[2], int part[2])
{
    CYL__R hna, tl, th, aw, awl;
    if (!(f->H <= CYL__MAXR)) { /* infinite tube */
        sl[0] = -CYL__MAXR * 2; /* -inf */
        sl[1] = CYL__MAXR * 2;
        part[0] = part[1] = CYL_SIDE;
        return 1;
    }
    hna = f->H * f->na;
    aw = f->capscale ? CYL__P(scale)(f->aw, -f->capscale) : f->aw;
    awl = f->capscale ? CYL__P(scale)(f->awl, -f->capscale) : f->awl;
    if (!CYL__P(nonzero)(f->ad)) {
        sl[0] = -CYL__MAXR * 2;
        sl[1] = CYL__MAXR * 2;
        part[0] = part[1] = CYL_SIDE;
        return CYL__P(abs)(aw) <= hna;
    }
    {
        /* ±H|a| − a·w from the double-word |a| and a·w: the only rounding left is the
           final division's. */
        CYL__P(acc) lo, hi;
        lo.hi = lo.lo = 0;
        CYL__P(acc_prod)(&lo, -f->H, f->na);
        lo.lo -= f->H * f->nal + awl;
        hi.hi = -lo.hi;
        hi.lo = -lo.lo - 2 * awl;
        CYL__P(acc_add)(&lo, -aw);
        CYL__P(acc_add)(&hi, -aw);
        tl = CYL__P(div_dw)(lo.hi, lo.lo, f->ad, f->adl);
        th = CYL__P(div_dw)(hi.hi, hi.lo, f->ad, f->adl);
        if (f->capscale) { /* back to the frame's units; far beyond any wall crossing */
            tl = CYL__P(scale)(tl, f->capscale);
            th = CYL__P(scale)(th, f->capscale);
        }
    }
    if (f->ad > 0) { /* by the direction, not by comparing: a thin disk can round tl == th */
        sl[0] = tl; part[0] = CYL_CAP_LOW;
        sl[1] = th; part[1] = CYL_CAP_HIGH;
    } else {
        sl[0] = th; part[0] = CYL_CAP_HIGH;
        sl[1] = tl; part[1] = CYL_CAP_LOW;
    }
    return 1;
}

#if !CYL__WIDE
CYL__INL void CYL__P(fr2)(const CYL__R a[3], CYL__R r, CYL__R *R2, CYL__R *R2l);
CYL__INL CYL__R CYL__P(fres)(const CYL__R a[3], const CYL__R d[3], const CYL__R s[3],
                            const CYL__R wh[3], const CYL__R wl[3], CYL__R R2, CYL__R R2l,
                            CYL__R t, CYL__R *G);
#endif

/* Is the point x(t) of a cap inside its disk? (Parallel rays, and the cap end of a grazing
   wall interval: otherwise the wall interval decides.) |a × x|² <= r²|a|², from the exact
   o − c and the crossing point in double words (fres): formed plainly, x = (o − c) + t·d
   rounds by about u·|o − c|, which for a far origin is far more than the disk's margin (the
   double API's search: a parallel ray from 2^40 radii got a cap 2.7e-6 outside
   its disk). */
CYL__INL int CYL__P(in_disk)(const CYL__P(frame) *f, CYL__R t)
{
#if !CYL__WIDE
    CYL__R R2, R2l, G;
    CYL__P(fr2)(f->a, f->r, &R2, &R2l);
    return CYL__P(fres)(f->a, f->d, f->s, f->w, f->wl, R2, R2l, t, &G) <= 0;
#else
    CYL__R x[3], y[3];
    int i;
    for (i = 0; i < 3; i++) x[i] = CYL__FMAR(t, f->d[i], f->w[i]);
    CYL__P(cross)(f->a, x, y);
    return CYL__P(dot)(y, y) <= f->R2;
#endif
}

/* All crossings of the chosen surface (at most 2), sorted, then those in [tmin, tmax]; with
   the tangent band tang and the parallel tolerance para (this instance's, or the float API's
   where this double solver answers for it: wsolve). */
CYL__EXACT int CYL__P(solvet)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts,
                           CYL__R tang, CYL__R para, CYL__P(frame) *f, CYL__P(cand) out[2])
{
    CYL__P(cand) c[2];
    CYL__R sl[2], tw[2];
    int sp[2], n = 0, k, kept = 0, tangent = 0;
    int caps = (opts & CYL_CAPS) != 0;
    CYL__P(prepare)(ray, cyl, opts, f);
    f->tang = tang;
    f->para = para;
    {
        /* s = a × d as a double word on every path: its low part makes P = w·s and the
           residual of the root correction exact to O(u²) */
        CYL__R zero[3] = {0, 0, 0};
        CYL__P(cross_dw)(f->a, f->d, zero, f->s, f->sl);
    }
    if (f->H <= CYL__MAXR) {
        /* The cap planes' t = (∓H|a| − a·w)/(a·d) cancels twice: a·d for rays across the
           axis, and the numerator for origins near a cap plane. a·d, a·w and |a| are
           therefore carried as double words (Dot2; |a| with one correction of the square
           root), on every path: caps are the part of the default path they make accurate. */
        CYL__P(acc) s1 = CYL__P(dot_acc)(f->a, f->d), s2 = CYL__P(dot_acc)(f->a, f->w);
        CYL__P(acc_split)(s1, &f->ad, &f->adl);
        s2.lo += CYL__P(dot)(f->a, f->wl);
        CYL__P(acc_split)(s2, &f->aw, &f->awl);
        f->nal = (CYL__FMAR(-f->na, f->na, f->aa) + f->aal) / (2 * f->na);
    } else {
        f->ad = CYL__P(dot)(f->a, f->d);
        f->aw = CYL__P(dot)(f->a, f->w);
        f->awl = f->nal = f->adl = 0;
    }
    f->A = CYL__P(dot)(f->s, f->s);
    f->R2 = f->r * f->r * f->aa;
    f->R2l = f->sq = 0;
    for (k = 0; k < 3; k++) f->m[k] = f->ml[k] = 0; /* set by the wall; zero for -O3's sake */
    if (!CYL__P(slab)(f, sl, sp)) return 0;
    /* sin²(angle) = A / (|a|²|d|²) */
    if (f->A <= f->para * f->para * f->aa * CYL__P(dot)(f->d, f->d)) {
        if (caps && f->H <= CYL__MAXR) {
            for (k = 0; k < 2; k++)
                if (CYL__P(in_disk)(f, sl[k])) {
                    c[n].t = sl[k];
                    c[n].part = sp[k];
                    c[n].flags = CYL_F_PARALLEL | (k ? CYL_F_INSIDE : 0u);
                    n++;
                }
        }
    } else if (CYL__P(wall)(f, opts, tw, &tangent)) {
        unsigned tf = tangent ? CYL_F_TANGENT : 0u;
        int pos[2]; /* each wall root: -1 before the slab, 0 in it (inclusive), +1 after */
#ifndef CYL_NO_PRECISE
        if (f->precise && !tangent) {
            /* the roots to about u², and their side of the cap planes from the axial
               coordinate itself: comparing rounded t's would decide the rim by t's rounding */
            CYL__R tl[2];
            for (k = 0; k < 2; k++) {
                CYL__P(refine)(f->s, f->sl, f->m, f->ml, f->A, f->R2, f->R2l, f->sq, tw[k], k,
                               &tw[k], &tl[k]);
                pos[k] = f->capscale ? (tw[k] < sl[0] ? -1 : (tw[k] > sl[1] ? 1 : 0))
                                     : CYL__P(side)(f, tw[k], tl[k]);
            }
        } else
#endif
        {
            for (k = 0; k < 2; k++) pos[k] = tw[k] < sl[0] ? -1 : (tw[k] > sl[1] ? 1 : 0);
        }
        if (caps && f->H <= CYL__MAXR) {
            if (pos[0] <= 0 && pos[1] >= 0) {
                for (k = 0; k < 2; k++) {
                    /* a grazing wall interval is only known to the tangent band: a cap end
                       it produces must still lie on its disk, else it is no crossing */
                    if (pos[k] && tangent && !CYL__P(in_disk)(f, sl[k])) continue;
                    c[n].t = pos[k] ? sl[k] : tw[k];
                    c[n].part = pos[k] ? sp[k] : CYL_SIDE;
                    c[n].flags = (k ? CYL_F_INSIDE : 0u) | (pos[k] ? 0u : tf);
                    n++;
                }
            }
        } else {
            for (k = 0; k < 2; k++)
                if (!pos[k]) {
                    c[n].t = tw[k];
                    c[n].part = CYL_SIDE;
                    c[n].flags = tf | (k ? CYL_F_INSIDE : 0u);
                    n++;
                }
        }
    }
    for (k = 0; k < n; k++) {
        CYL__R tu = f->e ? CYL__P(scale)(c[k].t, f->e) : c[k].t;
        if (tu >= ray->tmin && tu <= ray->tmax && CYL__P(finite)(tu)) {
            /* field by field: a struct copy becomes a memcpy call at -Os on some targets */
            out[kept].t = c[k].t;
            out[kept].tu = tu;
            out[kept].part = c[k].part;
            out[kept].flags = c[k].flags;
            kept++;
        }
    }
    return kept;
}

CYL__INL int CYL__P(solve)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts,
                          CYL__P(frame) *f, CYL__P(cand) out[2])
{
    return CYL__P(solvet)(ray, cyl, opts, CYL__TANG, CYL__PARA, f, out);
}

/* ------------------------------------------------------------------ the output */

/* Rigorous bound on |t − exact crossing| in the frame (N6).
   Wall: ŷ = m̂ + t ŝ (fma), with |ŷ_j − y_j| <= Ey_j from the 2u of each cross-product
   component, the error of w propagated through a×, and the fma's own rounding; then
   F >= |f(t)| and a lower bound of |f'(t)| = 2|s·y| give the nearest root of the exact
   quadratic f(t + δ) = f(t) + f'δ + Aδ²: |δ| <= min(2F/|f'|, √(F/A)).
   Cap: the plane's residual g(t) = a·x(t) ∓ H|a| is linear with slope a·d.
   First-order terms are multiplied by (1 + 2^-8), which covers the second-order ones and the
   rounding of this evaluation; CYL__MINR terms cover products that underflowed. */
CYL__INL CYL__R CYL__P(bound)(const CYL__P(frame) *f, const CYL__P(cand) *c,
                             const CYL__R y[3], CYL__R ys)
{
    const CYL__R u = CYL__U, safe = CYL__C(1.0) + CYL__C(1.0) / CYL__C(256.0);
    CYL__R t = c->t, d, werr;
    /* |exact w − w| componentwise: u|w| for the one rounding of o − c, or |wl| when w + wl
       is exact; the absolute term covers a component that the scaling made subnormal.
       Norms (∞ and 1) instead of componentwise terms: at most 3 times looser, much cheaper. */
    werr = CYL__P(amax3)(f->wl) + CYL__MINR;
    if (c->part == CYL_SIDE) {
        CYL__R ym = CYL__P(amax3)(y), y1 = CYL__P(asum3)(y), s1 = CYL__P(asum3)(f->s);
        CYL__R ey, g, E, F, Eb, bb, Alo;
        ey = 2 * u * (CYL__P(amax3)(f->m) + CYL__P(abs)(t) * CYL__P(amax3)(f->s)) + u * ym +
             2 * CYL__P(amax3)(f->a) * werr + CYL__MINR;
        g = CYL__P(dot)(y, y);
        E = 3 * u * g + 5 * u * f->R2 + (2 * y1 + 3 * ey) * ey;
        Eb = s1 * (ey + 5 * u * ym);
        g -= f->R2;
        E = (E + u * CYL__P(abs)(g) + CYL__MINR) * safe;
        F = CYL__P(abs)(g) + E;
        bb = 2 * (CYL__P(abs)(ys) - Eb * safe);     /* |f'| >= bb */
        Alo = f->A * (1 - 8 * u);                   /* A >= Alo   */
        if (bb > 0 && bb * bb >= 4 * F * Alo)
            d = 2 * F / bb;
        else
            d = CYL__SQRTR(F / Alo);
    } else if (f->capscale) {
        d = CYL__MAXR * 2; /* a cap 2^123 (float) lengths away: no bound offered */
    } else {
        CYL__R x[3], g, Eg, slope, a1 = CYL__P(asum3)(f->a);
        int i;
        for (i = 0; i < 3; i++) x[i] = CYL__FMAR(t, f->d[i], f->w[i]);
        g = CYL__P(dot)(f->a, x);
        Eg = a1 * (werr + 4 * u * CYL__P(amax3)(x) + CYL__MINR) + 4 * u * f->H * f->na;
        g += c->part == CYL_CAP_LOW ? f->H * f->na : -f->H * f->na;
        Eg = (Eg + u * CYL__P(abs)(g) + CYL__MINR) * safe;
        slope = CYL__P(abs)(f->ad) - 3 * u * CYL__P(adot)(f->a, f->d) * safe;
        d = slope > 0 ? (CYL__P(abs)(g) + Eg) / slope : CYL__MAXR * 2;
    }
    return d * safe;
}

/* Some unit vector orthogonal to the axis: the normal of last resort, when the computed one
   vanished (r underflowed in the frame). */
CYL__INL void CYL__P(radial)(const CYL__P(frame) *f, CYL__R no[3])
{
    CYL__R z[3] = {0, 0, 0}, len;
    int i;
    z[CYL__P(abs)(f->a[0]) <= CYL__P(abs)(f->a[1]) ? 0 : 1] = 1;
    CYL__P(cross)(z, f->a, no);
    len = CYL__SQRTR(CYL__P(dot)(no, no));
    for (i = 0; i < 3; i++) no[i] /= len;
}

CYL__EXACT void CYL__P(finish)(const CYL__P(frame) *f, const CYL__P(cand) *cin, unsigned opts,
                            const CYL__N(ray) *ray, CYL__N(hit) *hit)
{
    CYL__R no[3] = {0, 0, 0}, y[3] = {0, 0, 0}, ys = 0, v, face = 1;
    CYL__P(cand) cc, *c = &cc;
    int i;
    cc.t = cin->t; /* field by field: no memcpy call at -Os */
    cc.tu = cin->tu;
    cc.part = cin->part;
    cc.flags = cin->flags;
    if (!f->precise && !f->coarse && c->part == CYL_SIDE && !(c->flags & CYL_F_TANGENT)) {
        /* default path: one correction of the returned root with the compensated residual
           (the precise path corrected both in the solver, to decide the rim); the step is a
           few ulps, so keep it inside the accepted range */
        CYL__R lo;
        CYL__P(refine)(f->s, f->sl, f->m, f->ml, f->A, f->R2, f->R2l, f->sq, c->t,
                       (c->flags & CYL_F_INSIDE) != 0, &c->t, &lo);
        c->tu = f->e ? CYL__P(scale)(c->t, f->e) : c->t;
        if (c->tu < ray->tmin || c->tu > ray->tmax) {
            c->tu = c->tu < ray->tmin ? ray->tmin : ray->tmax;
            c->t = f->e ? CYL__P(scale)(c->tu, -f->e) : c->tu;
        }
    }
    hit->t = c->tu;
    hit->part = c->part;
    hit->flags = c->flags;
    if (c->part == CYL_SIDE) {
        CYL__R len2;
        /* y = a × x(t) = m + t·s, from the accurate m and s: no term as large as the axial
           coordinate enters, so long tubes keep accurate normals. The outward normal is
           y × a normalised. */
        for (i = 0; i < 3; i++) y[i] = CYL__FMAR(c->t, f->s[i], f->m[i]) + (f->ml[i] + c->t * f->sl[i]);
        ys = CYL__P(dot)(y, f->s);
        v = CYL__FMAR(c->t, f->ad, f->aw) / f->na;
        if (!(opts & CYL_NO_NORMAL)) {
            /* y ⊥ a, so |y × a| = |y||a| has no cancellation: one FMA per component is enough
               for a normal accurate to a few u. */
            no[0] = CYL__FMAR(y[1], f->a[2], -(y[2] * f->a[1]));
            no[1] = CYL__FMAR(y[2], f->a[0], -(y[0] * f->a[2]));
            no[2] = CYL__FMAR(y[0], f->a[1], -(y[1] * f->a[0]));
            len2 = CYL__P(dot)(no, no);
            if (!(len2 >= CYL__RDIR * CYL__MINR) || !(len2 <= CYL__MAXR / CYL__RDIR)) {
                /* y is tiny or huge (far origins, r far below |o − c|): bring the largest
                   component near 1 exactly, so that |no|² neither underflows nor overflows */
                CYL__R mx = CYL__P(amax3)(no), sc[2];
                if (mx > 0) {
                    CYL__P(pow2pair)(-CYL__P(ilogb)(mx), sc);
                    for (i = 0; i < 3; i++) no[i] = no[i] * sc[0] * sc[1];
                }
                len2 = CYL__P(dot)(no, no);
            }
            if (len2 > 0) {
                CYL__R inv = 1 / CYL__SQRTR(len2);
                for (i = 0; i < 3; i++) no[i] *= inv;
            } else { /* only when r underflowed in the frame: any radial direction */
                CYL__P(radial)(f, no);
            }
            if (f->coarse) { /* y is mostly rounding there: at least keep n ⊥ a */
                CYL__R k = CYL__P(dot)(no, f->a) / f->aa, len;
                for (i = 0; i < 3; i++) no[i] -= k * f->a[i];
                len = CYL__SQRTR(CYL__P(dot)(no, no));
                if (len > 0) {
                    for (i = 0; i < 3; i++) no[i] /= len;
                } else {
                    CYL__P(radial)(f, no);
                }
            }
            face = CYL__P(dot)(no, f->d) > 0 ? -1 : 1;
        }
    } else {
        CYL__R sgn = c->part == CYL_CAP_HIGH ? 1 : -1;
        v = 0; /* exactly ±h/2, set below */
        if (!(opts & CYL_NO_NORMAL)) {
            for (i = 0; i < 3; i++) no[i] = sgn * f->a[i] / f->na;
            face = sgn * f->ad > 0 ? -1 : 1;
        }
    }
    if (opts & CYL_OUTWARD) face = 1;
    for (i = 0; i < 3; i++) hit->n[i] = face * no[i];
    v = f->el ? CYL__P(scale)(v, f->el) : v;
    /* an infinite tube's v can exceed the format even where t does not: saturate */
    v = v > CYL__MAXR ? CYL__MAXR : (v < -CYL__MAXR ? -CYL__MAXR : v);
    /* a wall hit inside the slab has |v| <= h/2 up to rounding: report it within */
    hit->v = c->part == CYL_SIDE ? (v > f->Hu ? f->Hu : (v < -f->Hu ? -f->Hu : v))
                                 : (c->part == CYL_CAP_HIGH ? f->Hu : -f->Hu);
    if (opts & CYL_NO_ERRBOUND) {
        hit->t_err = CYL__MAXR * 2;
    } else {
        CYL__R te = CYL__P(bound)(f, c, y, ys);
        if (f->e) te = CYL__P(scale)(te, f->e);
        const CYL__R tiny = CYL__MINR * 2 * CYL__U; /* the smallest subnormal */
        /* the scaling back, or a user t among the subnormals, rounded once more */
        if (te < CYL__MINR) te += tiny;
        if (CYL__P(abs)(hit->t) < CYL__MINR) te += tiny;
        hit->t_err = f->coarse ? CYL__MAXR * 2 : te;
    }
}

/* ------------------------------------------------------------------ the fast path */

/* The float API computed in float runs this first, and CYL_PRECISE in the double API (where
   the lean path below, its common case, runs first otherwise): the plain formulas of the
   solver above (the geometric discriminant, the stable root pair, the cap planes), once, in
   type CYL__L (double for the float API where double is hardware, see CYL_FLOAT_WIDE; else
   the API's own type).
   What it does not do is compensate: o − c, a·w and the coefficients carry their roundings,
   so a decision within a few ulps of its threshold (tangency, rim, tmin/tmax) can go either
   way, and t is good to a few ulps where the case is well-conditioned. t_err stays rigorous:
   an a-priori bound on every rounding that enters the returned root or cap crossing (standard
   model, Higham ch. 3). Inputs outside the range where nothing can overflow or underflow are
   first scaled by exact powers of two; the rest (invalid input, extreme ratios) go to the
   solver above, which then answers alone.

   Error model: each operation rounds with relative error <= u; an FMA once, a product and add
   at most twice, so each bound holds with or without contraction. Bounds are first order; the
   factor sf = 1 + 2^-6 covers the second-order terms and the rounding of the bound's own
   arithmetic, LMIN terms cover underflow below the range check's floor. */
typedef struct CYL__P(fx) { /* one crossing of the fast path */
    CYL__L t;               /* frame t */
    CYL__L et;              /* CYL_PRECISE: a bound on |t − exact t| (else 0) */
    int sg;                 /* wall 0, low cap −1, high cap +1 */
    int ok;                 /* the crossing exists */
    int steps;              /* corrections in the output: a wall crossing's exact-quadratic
                               steps (1 to CYL__STEPS, or 0: t is already frefr's); a cap
                               crossing's fcapt (1, or 0: t is already fcapt's) */
    int resid;              /* CYL_PRECISE: first try one step certified after the fact (frefr) */
} CYL__P(fx);

CYL__INL CYL__L CYL__P(labs)(CYL__L x) { return CYL__LABS(x); }
CYL__INL CYL__L CYL__P(lmax3)(const CYL__L x[3])
{
    CYL__L p = CYL__P(labs)(x[0]), q = CYL__P(labs)(x[1]), z = CYL__P(labs)(x[2]);
    p = p > q ? p : q;
    return p > z ? p : z;
}
CYL__INL CYL__L CYL__P(l1)(const CYL__L x[3])
{
    return CYL__P(labs)(x[0]) + CYL__P(labs)(x[1]) + CYL__P(labs)(x[2]);
}
CYL__INL CYL__L CYL__P(ldot)(const CYL__L x[3], const CYL__L y[3])
{
    return CYL__LMADD(x[2], y[2], CYL__LMADD(x[1], y[1], x[0] * y[0]));
}
/* pq − rs. With a hardware FMA, Kahan's algorithm: relative error <= 2u (Jeannerod, Louvet,
   Muller, Math. Comp. 82, 2013); without, the error is at most 2u(|pq| + |rs|)(1 + u). */
CYL__INL CYL__L CYL__P(ldop)(CYL__L p, CYL__L q, CYL__L r, CYL__L s)
{
#if CYL__LKAHAN
    CYL__L w = r * s;
    return CYL__LFMA(p, q, -w) + CYL__LFMA(-r, s, w);
#else
    return p * q - r * s;
#endif
}

/* Is the ray point at t on the disk |a × x| <= r|a|? y = m + t·s = a × x(t). */
CYL__INL int CYL__P(fdisk)(const CYL__L m[3], const CYL__L s[3], CYL__L R2, CYL__L t)
{
    /* component by component: a loop here keeps the caller's frame in memory (gcc's scalar
       replacement runs before loops are unrolled) */
    CYL__L y[3];
    y[0] = CYL__LMADD(t, s[0], m[0]);
    y[1] = CYL__LMADD(t, s[1], m[1]);
    y[2] = CYL__LMADD(t, s[2], m[2]);
    return CYL__P(ldot)(y, y) <= R2;
}

#if !CYL__WIDE
/* o − c exactly, as wh + wl (TwoSum), times the frame's length scale lf (two factors that move
   it the same way, so only a subnormal result rounds). */
CYL__INL void CYL__P(fwexact)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                             const CYL__R lf[2], CYL__R wh[3], CYL__R wl[3])
{
    int i;
    for (i = 0; i < 3; i++) {
        CYL__P(two_sum)(ray->o[i], -cyl->c[i], &wh[i], &wl[i]);
        wh[i] = wh[i] * lf[0] * lf[1];
        wl[i] = wl[i] * lf[0] * lf[1];
    }
}

/* The cap crossing (sg·H|a| − a·w)/(a·d) to about an ulp (CYL__L is the API's type here): from
   the exact o − c (TwoSum, times the frame's length scale lf), with a·w, a·d and |a| as double
   words (Dot2; one correction of the square root), as the solver's slab forms it. The plain
   quotient loses several ulps where H|a| and a·w nearly cancel. */
CYL__INL CYL__R CYL__P(fcapt)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                             const CYL__R a[3], const CYL__R d[3], CYL__R H, const CYL__R lf[2],
                             int sg, CYL__R tp)
{
    CYL__R wh[3], wl[3], aa, aal, na, nal, ad, adl, sH = (CYL__R)sg * H, t;
    CYL__P(acc) sw, num;
    CYL__P(fwexact)(ray, cyl, lf, wh, wl);
    CYL__P(acc_split)(CYL__P(dot_acc)(a, a), &aa, &aal);
    na = CYL__SQRTR(aa);
    nal = (CYL__FMAR(-na, na, aa) + aal) / (2 * na);
    sw = CYL__P(dot_acc)(a, wh);
    sw.lo += CYL__P(dot)(a, wl);
    CYL__P(acc_split)(CYL__P(dot_acc)(a, d), &ad, &adl);
    num = CYL__P(acc_first)(sH, na);
    num.lo += sH * nal - sw.lo;
    CYL__P(acc_add)(&num, -sw.hi);
    t = CYL__P(div_dw)(num.hi, num.lo, ad, adl);
    /* a·d far below its plain rounding (a ray parallel to the cap planes within 2^-p of |a||d|)
       can come out 0 here and leave no quotient: keep the plain crossing tp then, which the
       caller decided with, and whose bound (cbound) says how little is known of it */
    return CYL__P(abs)(t) <= CYL__MAXR ? t : tp;
}

/* r²|a|² as a double word R2 + R2l (a exact). */
CYL__INL void CYL__P(fr2)(const CYL__R a[3], CYL__R r, CYL__R *R2, CYL__R *R2l)
{
    CYL__R r2 = r * r, r2l = CYL__FMAR(r, r, -r2), aa, aal;
    CYL__P(acc_split)(CYL__P(dot_acc)(a, a), &aa, &aal);
    *R2 = r2 * aa;
    *R2l = CYL__FMAR(r2, aa, -*R2) + r2 * aal + r2l * aa;
}

/* The wall residual f(t) = |y|² − r²|a|², y = a × x, x = (o − c) + t·d, from the crossing point:
   o − c = wh + wl exact (fwexact), x as a double word (TwoSum, TwoProd), y from exact products
   (cross_dw), so f carries about u of itself plus u² of its terms (|y|², r²|a|² and
   |a|·|o − c| squared); also G = y·s (s as the caller computed it, plainly: it only scales a
   correction of a few ulps). */
CYL__INL CYL__R CYL__P(fres)(const CYL__R a[3], const CYL__R d[3], const CYL__R s[3],
                            const CYL__R wh[3], const CYL__R wl[3], CYL__R R2, CYL__R R2l,
                            CYL__R t, CYL__R *G)
{
    /* component by component (see fdisk) */
    CYL__R xh[3], xl[3], yh[3], yl[3], p0 = t * d[0], p1 = t * d[1], p2 = t * d[2], e0, e1, e2;
    CYL__P(acc) sf;
    CYL__P(two_sum)(wh[0], p0, &xh[0], &e0);
    CYL__P(two_sum)(wh[1], p1, &xh[1], &e1);
    CYL__P(two_sum)(wh[2], p2, &xh[2], &e2);
    xl[0] = e0 + (wl[0] + CYL__FMAR(t, d[0], -p0));
    xl[1] = e1 + (wl[1] + CYL__FMAR(t, d[1], -p1));
    xl[2] = e2 + (wl[2] + CYL__FMAR(t, d[2], -p2));
    CYL__P(cross_dw)(a, xh, xl, yh, yl);
    sf = CYL__P(acc_first)(yh[0], yh[0]);
    CYL__P(acc_prod)(&sf, yh[1], yh[1]);
    CYL__P(acc_prod)(&sf, yh[2], yh[2]);
    CYL__P(acc_add)(&sf, -R2);
    sf.lo += 2 * yh[0] * yl[0];
    sf.lo += 2 * yh[1] * yl[1];
    sf.lo += 2 * yh[2] * yl[2];
    *G = yh[0] * s[0] + yh[1] * s[1] + yh[2] * s[2];
    return sf.hi + (sf.lo - R2l);
}

/* C = f(0) = |a × (o − c)|² − r²|a|² from the exact o − c (fres at t = 0): about u of itself
   plus u² of its terms. The plain C rounds by about u·|m|², which for an origin on the surface
   (a secondary ray) is all of it; the crossing near t = 0 then moves by about u·r²|a|²/|q|,
   and along a ray nearly parallel to the axis that is far past a rim. */
CYL__INL CYL__R CYL__P(fc0)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                           const CYL__R a[3], const CYL__R d[3], const CYL__R s[3], CYL__R r,
                           const CYL__R lf[2])
{
    CYL__R wh[3], wl[3], R2, R2l, G0;
    CYL__P(fwexact)(ray, cyl, lf, wh, wl);
    CYL__P(fr2)(a, r, &R2, &R2l);
    return CYL__P(fres)(a, d, s, wh, wl, R2, R2l, 0, &G0);
}

/* CYL_PRECISE near the tangent band (CYL__L is the API's type here): D = r²A − P² (A = |s|²,
   P = w·s, s = a × d) from the exact w = o − c (fwexact) and s as a double word (cross_dw),
   summed as Dot2 does, with a bound on its error. The plain D errs by about u·|o − c||s|·|P|,
   for an origin a few radii away the width of the tangent band itself; this one by 2u of
   itself and u² of its terms. Where D then decides (clearly beside the band, or certainly
   inside it with its sign certain: two roots, or none and a contact at the point of closest
   approach), A and B = m·s (m = a × w) follow the same way and it returns 1 (out: A, B, D;
   err: their bounds); else 0, and the solver answers. The bounds, with ma, md, mw the
   largest components of a, d and the rounded w (|w_i| <= mw(1 + u)): a component of s's
   double word leaves at most 12u²·ma·md (dop_dw: its lo sums errors of at most u of the two
   products with two roundings, and a Fast2Sum), one of m's 22u²·ma·mw (the wl terms add a
   product and a rounding); Dot2's sums add γ6² of their terms' magnitudes (below
   40u²·Σ|terms|) and the dropped lo·lo products u² of them; each (r·s_i)² is split exactly up
   to 8u² of itself, and P² comes from P's double word. Every constant below covers its sum by
   a factor of two or more. Out of line: only a contact near the band calls it. */
CYL__SLOW int CYL__P(fcomp)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                            const CYL__R a[3], const CYL__R d[3], CYL__R r, const CYL__R lf[2],
                            CYL__R mw, CYL__R ma, CYL__R md, CYL__R band, CYL__R out[3],
                            CYL__R err[3])
{
    const CYL__R u = CYL__U, tiny = CYL__MINR, zero[3] = {0, 0, 0};
    const CYL__R sf = (CYL__R)1 + (CYL__R)1 / 64;
    CYL__R wh[3], wl[3], sh[3], sl[3], mh[3], ml[3], Ph, Pl, S2 = ma * ma * md * md, eP, A, D, eD;
    CYL__P(acc) sa, sp, sb;
    CYL__P(fwexact)(ray, cyl, lf, wh, wl);
    CYL__P(cross_dw)(a, d, zero, sh, sl);
    sa.hi = sa.lo = sp.hi = sp.lo = sb.hi = sb.lo = 0;
    CYL__P(acc_dot_dw)(&sa, sh, sl, sh, sl);
    A = sa.hi + sa.lo;
    CYL__P(acc_dot_dw)(&sp, wh, wl, sh, sl);
    CYL__P(acc_split)(sp, &Ph, &Pl);
    D = CYL__P(disc_dw)(r, sh, sl, Ph, Pl);
    eP = 256 * u * u * mw * ma * md + tiny;
    eD = (2 * u * CYL__P(abs)(D) + 256 * u * u * (r * r * (A + 16 * S2) + Ph * Ph) +
          2 * CYL__P(abs)(Ph) * eP + eP * eP) * sf + tiny;
    if (!(D < -band - eD) && !(D > band + eD) && !(D - eD > 0 && D + eD < band) &&
        !(D + eD < 0 && D - eD > -band))
        return 0;
    CYL__P(cross_dw)(a, wh, wl, mh, ml);
    CYL__P(acc_dot_dw)(&sb, mh, ml, sh, sl);
    out[0] = A;
    out[1] = sb.hi + sb.lo;
    out[2] = D;
    err[0] = (2 * u * A + 256 * u * u * S2) * sf + tiny;
    err[1] = (2 * u * CYL__P(abs)(out[1]) + 1024 * u * u * ma * ma * mw * md) * sf + tiny;
    err[2] = eD;
    return 1;
}

/* A wall root to about an ulp: refine's exact-quadratic step on the residual of fres, which
   forms y from the crossing point with one double-word cross product (refine's from m and s
   takes two). The plain root loses ulps where |o − c| is far above r or where the
   coefficients cancel. steps = 2 repeats the step from its own result: a start too far for
   one step (CYL_PRECISE's check in the fast path) costs one more residual, not the solver. */
CYL__INL CYL__R CYL__P(fref)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                            const CYL__R a[3], const CYL__R d[3], const CYL__R s[3], CYL__R r,
                            const CYL__R lf[2], CYL__R A, CYL__R sq, CYL__R t, int upper,
                            int steps)
{
    CYL__R wh[3], wl[3], R2, R2l, G, F;
    CYL__P(fwexact)(ray, cyl, lf, wh, wl);
    CYL__P(fr2)(a, r, &R2, &R2l);
    do {
        F = CYL__P(fres)(a, d, s, wh, wl, R2, R2l, t, &G);
        t += CYL__P(qstep)(F, G, sq, A, upper);
    } while (--steps > 0);
    return t;
}

/* CYL_PRECISE: one exact-quadratic step from t0 with √(G² − A·F) from its own residual in
   place of the given √(|a|²D) (the same quantity in exact arithmetic: the discriminant does
   not depend on the start). Near a root G² dominates it, so it errs by about the error of G
   (a few u of |y||s|), not by D's, which the plain D leaves large near tangency (where the
   given √ needs several steps). Certified after the fact: returns 1 with *tout = t0 + δ
   where the bound below puts t0 + δ, before its rounding, within 0.25u(|t0| + rd) of the
   root (the steps' target in fast), else 0 (*tout untouched). cb = {rn >= r|a|, max |s_i|,
   the error of each s_i, max |a_i|, max |w_i|, max |d_i|, the error of A, rd = r/max|d_i|}.
   The bounds (standard model; y* etc. from the exact data at t0):
     fres's y (x = w + t0·d as a double word, y = a × x from exact products) is within
     49u²·ma·X of y* in each component, X = mw + |t0|·md >= max |x_i|, and
     |y*| <= Ym = (rn + |F|/(2rn))(1 + 8u) (|y*|² = r²|a|² + f*);
     G = Σ yh_i s_i: |G − G*| <= eG = 2Ym(es + 5u·ms) + 160u²·ma·X·ms (|y|_1 <= √3|y|, yh
     within u of y, the sum's γ3);
     F compensated: |F − F*| <= eF = 2u|F| + 192u²·Ym·ma·X + 16u²(Ym² + R2) (2|y|·|δy|, the
     dropped yl², the sum's u² terms, r²|a|²'s double word);
     g2 = G² − A·F with a product and an FMA: within E2 = 2|G|eG + eG² + (A + eA)eF + |F|eA
     + 3u(G² + A|F|) of G*² − A*F* = sq*², so √g2 is within esqn = E2/√g2 + u√g2 of sq*;
     qstep's form N/A (the start beyond the midpoint; |N| = |G| + √g2): |δ − δ*| <= α + β|δ*|,
     α = (eG + esqn + u|N|)/A + u|δ|, β = 2eA/A + u; its form F/den (den = √g2 + |G|):
     α = eF/den + 2u|δ|, β = (esqn + eG)/den;
   so |δ − δ*| <= (α + β|δ|)/(1 − β) <= (16/15)(α + β|δ|) for β <= 1/16. */
CYL__INL int CYL__P(frefr)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                          const CYL__R a[3], const CYL__R d[3], const CYL__R s[3], CYL__R r,
                          const CYL__R lf[2], CYL__R A, CYL__R t0, int upper,
                          const CYL__R cb[8], CYL__R *tout)
{
    const CYL__R u = CYL__U, sf = (CYL__R)1 + (CYL__R)1 / 32, tiny = CYL__MINR;
    const CYL__R rn = cb[0], ms = cb[1], es = cb[2], ma = cb[3], eA = cb[6];
    CYL__R wh[3], wl[3], R2, R2l, G, F, g2, sq, aF, aG, X, Ym, eG, eF, E2, esqn, dl, al, be;
    CYL__P(fwexact)(ray, cyl, lf, wh, wl);
    CYL__P(fr2)(a, r, &R2, &R2l);
    F = CYL__P(fres)(a, d, s, wh, wl, R2, R2l, t0, &G);
    g2 = CYL__FMAR(G, G, -(A * F));
    if (!(g2 > 0) || !(rn > 0)) return 0;
    sq = CYL__SQRTR(g2);
    dl = CYL__P(qstep)(F, G, sq, A, upper);
    aF = CYL__P(abs)(F);
    aG = CYL__P(abs)(G);
    X = cb[4] + CYL__P(abs)(t0) * cb[5];
    Ym = (rn + (CYL__R)0.5 * aF / rn) * (1 + 8 * u);
    eG = 2 * Ym * (es + 5 * u * ms) + 160 * u * u * ma * X * ms + tiny;
    eF = 2 * u * aF + 192 * u * u * Ym * ma * X + 16 * u * u * (Ym * Ym + R2) + tiny;
    E2 = (eG * (2 * aG + eG) + (A + eA) * eF + aF * eA + 3 * u * (G * G + A * aF)) * sf + tiny;
    esqn = (E2 / sq + u * sq) * (1 + 2 * u) * sf;
    if (upper ? G < 0 : G > 0) {
        al = ((eG + esqn + u * (aG + sq)) / A * (1 + 2 * u) + u * CYL__P(abs)(dl)) * sf;
        be = (2 * eA / A + u) * sf;
    } else {
        CYL__R den = sq + aG;
        al = (eF / den * (1 + 2 * u) + 2 * u * CYL__P(abs)(dl)) * sf;
        be = (esqn + eG) / den * (1 + 2 * u) * sf;
    }
    if (!(be <= (CYL__R)0.0625) ||
        !((al + be * CYL__P(abs)(dl)) * (CYL__R)16 / 15 <=
          (CYL__R)0.25 * u * (CYL__P(abs)(t0) + cb[7])))
        return 0;
    *tout = t0 + dl;
    return 1;
}

/* A corrected crossing t (frame) kept in [tmin, tmax], in the caller's units (tmin/tsc can be
   subnormal in the frame): sets t and tu = t·tsc, returns what the frame's t
   differs from tu (|t·tsc − tu|, added to the bound). */
CYL__INL CYL__R CYL__P(fclamp)(const CYL__N(ray) *ray, CYL__R tsc, CYL__R *t, CYL__R *tu)
{
    *tu = *t * tsc;
    if (!(*tu < ray->tmin || *tu > ray->tmax)) return 0;
    *tu = *tu < ray->tmin ? ray->tmin : ray->tmax;
    *t = *tu / tsc;
    return CYL__P(abs)(*t * tsc - *tu);
}
#else
/* The float API computed in double hands the double instance the float inputs (exact). */
CYL__INL void CYL__P(todbl)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, cyld_ray *dr,
                           cyld_cylinder *dc)
{
    int i;
    for (i = 0; i < 3; i++) {
        dr->o[i] = (double)ray->o[i];
        dr->d[i] = (double)ray->d[i];
        dc->c[i] = (double)cyl->c[i];
        dc->a[i] = (double)cyl->a[i];
    }
    dr->tmin = (double)ray->tmin;
    dr->tmax = (double)ray->tmax;
    dc->r = (double)cyl->r;
    dc->h = (double)cyl->h;
}

/* C from the exact o − c by the double instance's fc0. The frame's a, d and s are doubles
   already, and r converts exactly; lengths are not scaled in double (fscale), so lf is 1. */
CYL__SLOW CYL__L CYL__P(fc0)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                           const CYL__L a[3], const CYL__L d[3], const CYL__L s[3], CYL__L r,
                           const CYL__R lf[2])
{
    const double one[2] = {1, 1};
    cyld_ray dr;
    cyld_cylinder dc;
    (void)lf;
    CYL__P(todbl)(ray, cyl, &dr, &dc);
    return cyl__d_fc0(&dr, &dc, a, d, s, r, one);
}
#endif

/* Could the rounding of C (|δC| <= eC) move the root t = C/q (frame) across a rim (v|a| =
   a·w + t·a·d, computed: v, against ±H|a|), or with ends = 1 across tmin or tmax (t·tsc)? It
   moves it by up to eC/|q|, which for an origin near the wall grows like 1/sin of the angle to the axis: a
   ray nearly parallel to it. At a rim that error is also multiplied by
   r/h, so even C's rounding in double can decide a float rim there. Compared without a
   division against e = 4·|δC| (the 4 for the roundings of the test); infinite ends never
   qualify. */
CYL__INL int CYL__P(cnear)(CYL__L t, CYL__L v, CYL__L q, CYL__L e, CYL__L ad, CYL__L Hn,
                          int ends, CYL__L tsc, CYL__L tmin, CYL__L tmax)
{
    CYL__L aq = CYL__P(labs)(q), tu = t * tsc;
    return CYL__P(labs)(CYL__P(labs)(v) - Hn) * aq <= e * CYL__P(labs)(ad) ||
           (ends && (CYL__P(labs)(tu - tmin) * aq <= e * tsc ||
                     CYL__P(labs)(tu - tmax) * aq <= e * tsc));
}

/* The root pair's q = −(B + sgn(B)·sq), sq = √(|a|²D) = √(B² − AC) (N4). */
CYL__INL CYL__L CYL__P(qpair)(CYL__L B, CYL__L sq) { return -(B + (B < 0 ? -sq : sq)); }

/* sq for an origin on the surface (|C| <= 128u·r²|a|², C from the exact o − c): √(B² − AC)
   errs there by about u|B||a||w||s|, √(|a|²D) by u·r²|a|²A, more by r|a||s|/|B| = 1/√e near
   tangency (N3). */
CYL__INL int CYL__P(onsurf)(CYL__L C, CYL__L R2) { return CYL__P(labs)(C) <= 128 * CYL__LU * R2; }
CYL__INL CYL__L CYL__P(sqbc)(CYL__L B, CYL__L A, CYL__L C)
{
    CYL__L x = CYL__LMADD(B, B, -(A * C));
    return CYL__LSQRT(x > 0 ? x : 0);
}

/* Componentwise bounds on the errors of s = a × d (es) and m = a × w (em, with the rounding
   of o − c), from the largest components of a, d, s (returned too) and w. */
CYL__INL void CYL__P(ferr)(const CYL__L a[3], const CYL__L d[3], const CYL__L s[3], CYL__L mw,
                          CYL__L *ma, CYL__L *md, CYL__L *ms, CYL__L *es, CYL__L *em)
{
    const CYL__L u = CYL__LU;
    *ma = CYL__P(lmax3)(a);
    *md = CYL__P(lmax3)(d);
    *ms = CYL__P(lmax3)(s);
#if CYL__LKAHAN
    *es = 2 * u * *ms * (1 + 4 * u);
#else
    *es = 4 * u * *ma * *md * (1 + 4 * u);
#endif
    *em = 6 * u * *ma * mw * (1 + 4 * u);
}

/* A wall crossing's bound (N8), in the frame: y = m + t·s as computed, Y = y·y,
   Gs = y·s, at = |t|; es and em bound the errors of s and m componentwise, ms = max |s_i|.
   Bounds on the rounding of y give F >= |f(t)| and G <= |f'(t)|/2; the nearest root of the
   exact quadratic is within F/G where G² > A·F, else within √(F/A). */
CYL__INL CYL__L CYL__P(wbound)(const CYL__L y[3], CYL__L Y, CYL__L Gs, CYL__L at, CYL__L A,
                              CYL__L R2, CYL__L ms, CYL__L es, CYL__L em)
{
    const CYL__L u = CYL__LU, sf = (CYL__L)1 + (CYL__L)1 / 64, tiny = CYL__LMIN;
    CYL__L y1, Ey, F, EF, G, EG, Alo;
    y1 = CYL__P(l1)(y);
    Ey = em + at * (es + u * ms) + u * y1;
    F = Y - R2;
    EF = (3 * u * Y + Ey * (2 * y1 + 3 * Ey) + 6 * u * R2 + u * CYL__P(labs)(F)) * sf + tiny;
    F = CYL__P(labs)(F) + EF;
    G = CYL__P(labs)(Gs);
    EG = (y1 * (3 * u * ms + es) + 3 * Ey * (ms + es)) * sf + tiny;
    G -= EG;
    Alo = A - (3 * u * A + es * (6 * ms + 3 * es)) * sf - tiny;
    if (G > 0 && G * G > (2 * A - Alo) * F) return F / G;
    return Alo > 0 ? CYL__LSQRT(F / Alo) : (CYL__L)CYL__MAXR * 2;
}

/* A cap crossing's bound, in the frame: the plane's residual a·x(t) − sHn (sHn = ±H|a|) over
   a·d, with the roundings of a·w (and of o − c), a·d and H|a|; Sw >= Σ|a_i w_i| and
   Sd >= Σ|a_i d_i| (three times the product of the largest components, or |a||w| and |a||d|). */
CYL__INL CYL__L CYL__P(cbound)(CYL__L t, CYL__L ad, CYL__L aw, CYL__L sHn, CYL__L Sw, CYL__L Sd)
{
    const CYL__L u = CYL__LU, sf = (CYL__L)1 + (CYL__L)1 / 64, tiny = CYL__LMIN;
    CYL__L at = CYL__P(labs)(t), ead = 3 * u * Sd + tiny, g, aad;
    g = CYL__LMADD(t, ad, aw) - sHn;
    aad = CYL__P(labs)(ad) - ead;
    g = CYL__P(labs)(g) + (4 * u * Sw + at * (ead + 2 * u * Sd) + 6 * u * CYL__P(labs)(sHn) +
                           u * (CYL__P(labs)(aw) + at * CYL__P(labs)(ad))) * sf + tiny;
    return aad > 0 ? g / aad : (CYL__L)CYL__MAXR * 2;
}

/* The bound et (in the caller's units, about t's value tu in the wider type) of the returned
   tr: plus the rounding of tu to the API's type, then in the API's type rounded up: where the
   conversion rounded down (the wider type's bound, or a subnormal one), one ulp more. */
CYL__INL CYL__R CYL__P(errup)(CYL__L et, CYL__L tu, CYL__R tr)
{
    CYL__R te;
    et += CYL__P(labs)(tu - (CYL__L)tr);
#if CYL__WIDE
    /* widened in the wider type before the conversion, which then cannot land below et (an
       ulp is at most 2u|x|, or the subnormal step): no branch, and no subnormal operand,
       which costs a microcode assist on x86 */
    te = (CYL__R)(et * (1 + 4 * (CYL__L)CYL__U) + (CYL__L)CYL__MINR * 2 * (CYL__L)CYL__U);
#else
    if (CYL__P(labs)(tu) < CYL__LMIN) et += CYL__LMIN * 2 * CYL__LU;
    te = (CYL__R)et;
    if ((CYL__L)te < et) te += CYL__P(abs)(te) * (2 * CYL__U) + CYL__MINR * 2 * CYL__U;
#endif
    if (CYL__P(abs)(tr) < CYL__MINR) te += CYL__MINR * 2 * CYL__U;
    return te;
}

/* Two crossings whose corrections crossed over are kept ordered, the bound widened to match,
   rounded up: the difference and the sum round once each. */
CYL__INL void CYL__P(order2)(CYL__N(hit) hits[2])
{
    if (hits[1].t < hits[0].t) {
        CYL__R e = hits[1].t_err + (hits[0].t - hits[1].t);
        hits[1].t_err = e + e * (4 * CYL__U) + CYL__MINR * 2 * CYL__U;
        hits[1].t = hits[0].t;
    }
}

/* Exact power-of-two scaling into the fast path's range (valid input only): max(|w|, r) (the
   double API) and the largest components of a and d into [1, 2); scaling d changes the unit of
   t. r, h (whole or half) and w are scaled alike, lf holds the length factor (two halves, each
   representable), tsc and vsc convert the frame's t and lengths to the caller's. Returns -1
   where a factor is out of range: the solver answers. */
CYL__INL int CYL__P(fscale)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, CYL__L a[3],
                           CYL__L d[3], CYL__L w[3], CYL__L *r, CYL__L *h, CYL__R lf[2],
                           CYL__L *tsc, CYL__L *vsc)
{
    CYL__R f[2];
    int i, ev = 0, et, kdx = CYL__P(ilogb)(CYL__P(amax3)(ray->d));
    CYL__L mw = CYL__P(lmax3)(w);
    if (!(mw <= CYL__LMAX)) return -1;
    if (!CYL__WIDE) { /* every float length is in range in double */
        ev = CYL__P(ilogb)((CYL__R)(mw > *r ? mw : *r));
        CYL__P(pow2pair)(-ev, f);
        lf[0] = f[0];
        lf[1] = f[1];
        for (i = 0; i < 3; i++) w[i] = w[i] * (CYL__L)f[0] * (CYL__L)f[1];
        *r = *r * (CYL__L)f[0] * (CYL__L)f[1];
        *h = *h * (CYL__L)f[0] * (CYL__L)f[1];
    }
    CYL__P(pow2pair)(-CYL__P(ilogb)(CYL__P(amax3)(cyl->a)), f);
    for (i = 0; i < 3; i++) a[i] = a[i] * (CYL__L)f[0] * (CYL__L)f[1];
    CYL__P(pow2pair)(-kdx, f);
    for (i = 0; i < 3; i++) d[i] = d[i] * (CYL__L)f[0] * (CYL__L)f[1];
    et = ev - kdx;
    if (et < 1 - CYL__EBIAS || et > CYL__EBIAS || ev < 1 - CYL__EBIAS || ev > CYL__EBIAS)
        return -1;
    *tsc = (CYL__L)CYL__P(exp2i)(et);
    *vsc = (CYL__L)CYL__P(exp2i)(ev);
    return 0;
}

/* The frame's a, d and w = o − c from the caller's data, component by component (a loop
   would keep them in memory: see fdisk). */
CYL__INL void CYL__P(frame_in)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                              CYL__L a[3], CYL__L d[3], CYL__L w[3])
{
    a[0] = (CYL__L)cyl->a[0];
    a[1] = (CYL__L)cyl->a[1];
    a[2] = (CYL__L)cyl->a[2];
    d[0] = (CYL__L)ray->d[0];
    d[1] = (CYL__L)ray->d[1];
    d[2] = (CYL__L)ray->d[2];
    w[0] = (CYL__L)ray->o[0] - (CYL__L)cyl->c[0];
    w[1] = (CYL__L)ray->o[1] - (CYL__L)cyl->c[1];
    w[2] = (CYL__L)ray->o[2] - (CYL__L)cyl->c[2];
}

/* The rare scaling step, out of line: were the frame's a, d, w, r and h passed by address
   from the hot path, gcc would keep them in memory there for the whole call (loads and stores
   on every call: `make insn` counts them). It starts again from the caller's data (the frame
   holds nothing else before it scales), validates, and hands the scaled frame back through x.
   Returns -1 where the solver must answer. */
typedef struct CYL__P(sc) {
    CYL__L a[3], d[3], w[3], r, h, tsc, vsc;
    CYL__R lf[2];
} CYL__P(sc);
CYL__SLOW int CYL__P(scale_out)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                                CYL__P(sc) *x)
{
    int i;
    if (CYL__P(validate)(ray, cyl)) return -1;
    /* frame_in's loads as a loop: x is in memory anyway, and frame_in here changed gcc's code
       for the hot path around the call (make insn) */
    for (i = 0; i < 3; i++) {
        x->a[i] = (CYL__L)cyl->a[i];
        x->d[i] = (CYL__L)ray->d[i];
        x->w[i] = (CYL__L)ray->o[i] - (CYL__L)cyl->c[i];
    }
    x->r = (CYL__L)cyl->r;
    x->h = (CYL__L)cyl->h;
    x->lf[0] = x->lf[1] = 1;
    return CYL__P(fscale)(ray, cyl, x->a, x->d, x->w, &x->r, &x->h, x->lf, &x->tsc, &x->vsc);
}
CYL__INL int CYL__P(rescale)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, CYL__L a[3],
                            CYL__L d[3], CYL__L w[3], CYL__L *r, CYL__L *h, CYL__R lf[2],
                            CYL__L *tsc, CYL__L *vsc)
{
#if defined(__OPTIMIZE_SIZE__)
    /* -Os: in place, where the copy would only add code (make sizes) */
    return CYL__P(validate)(ray, cyl) || CYL__P(fscale)(ray, cyl, a, d, w, r, h, lf, tsc, vsc)
               ? -1
               : 0;
#else
    CYL__P(sc) x;
    if (CYL__P(scale_out)(ray, cyl, &x)) return -1;
    a[0] = x.a[0];
    a[1] = x.a[1];
    a[2] = x.a[2];
    d[0] = x.d[0];
    d[1] = x.d[1];
    d[2] = x.d[2];
    w[0] = x.w[0];
    w[1] = x.w[1];
    w[2] = x.w[2];
    *r = x.r;
    *h = x.h;
    *tsc = x.tsc;
    *vsc = x.vsc;
    lf[0] = x.lf[0];
    lf[1] = x.lf[1];
    return 0;
#endif
}

/* CYL_PRECISE: how many exact-quadratic steps with sq = √(|a|²D) (within esq of exact) take
   a start within e of a wall root (at = |start|) to within 0.25u·(at + r/md) of it, or
   most + 1 where more than most would be needed. The correction solves the exact quadratic
   around its start with this √: its error is the start's times that of √, which must stay
   under an ulp of max(|t|, r/|d|) (rays near the axis direction without an FMA start far off,
   origins far along a thin tube). Where one step is not enough, each leaves at most twice its
   first-order error e·esq/sq plus its roundings, and the step from there starts with that e
   (two roots a few √ errors apart converge slowly: grazing rays just inside the tube). */
CYL__INL int CYL__P(fsteps)(CYL__L e, CYL__L at, CYL__L sq, CYL__L esq, CYL__L md, CYL__L r,
                           int most)
{
    const CYL__L u = CYL__LU, lim = (CYL__L)0.25 * u * sq * (at * md + r);
    int n = 1;
    while (n <= most && !(e * esq * md <= lim)) {
        n++;
        e = 2 * e * esq / sq + 2 * u * (at + r / md);
    }
    return n;
}

/* The fast path's frame (fast and its parts): its scalars and decisions. a, d, s, m and lf
   stay arrays of fast itself: an out-of-line call takes some of them, which would keep a
   whole struct in memory. */
typedef struct CYL__P(fs) {
    CYL__L r, H, aa, dd, A, MM, R2, r2, sq, aw, ad, na, Hn, tsc, vsc, P, D, band;
    CYL__L eD, esq; /* CYL_PRECISE: the bounds on D's and √(|a|²D)'s errors */
    CYL__L mw, ma, md, ms, es, em, eA, eaw, ead, eHn;
    int caps, hfin, ce, parallel, tangent;
    int comp;    /* CYL_PRECISE near the tangent band: A, B, C, D from double words */
    int noroots; /* ... and a contact without roots there (D < 0): both ends at −B/A */
} CYL__P(fs);

/* The fast path's frame from the caller's data, rescaled where out of range; the hand-over of
   far origins; the parallel test; a miss beside the tube. Returns -1 (the solver answers),
   0 (a miss) or 1. */
CYL__PART int CYL__P(fframe)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts,
                            CYL__P(fs) *F, CYL__L a[3], CYL__L d[3], CYL__L s[3], CYL__L m[3],
                            CYL__R lf[2])
{
    const CYL__L u = CYL__LU, sf = (CYL__L)1 + (CYL__L)1 / 64, tiny = CYL__LMIN;
    const CYL__L hi = CYL__LHI, lo = 1 / CYL__LHI;
    CYL__L w[3], r, H, tsc = 1, vsc = 1, thr;
    int scaled = 0, ce = (opts & CYL_PRECISE) != 0;

    F->caps = (opts & CYL_CAPS) != 0;
    F->hfin = cyl->h <= CYL__MAXR;
    F->ce = ce;
    F->parallel = F->tangent = F->comp = F->noroots = 0;
    /* every field set before any use (the compiler cannot always tell) */
    F->r = F->H = F->aa = F->dd = F->A = F->MM = F->R2 = F->r2 = F->sq = F->aw = F->ad = 0;
    F->na = F->Hn = F->P = F->D = F->band = F->eD = F->esq = F->mw = 0;
    F->ma = F->md = F->ms = F->es = F->em = F->eA = F->eaw = F->ead = F->eHn = 0;
    F->tsc = F->vsc = 1;
    /* the scaling on a copy (rescale): an address here keeps a, d and w in memory on the
       whole path */
    CYL__P(frame_in)(ray, cyl, a, d, w);
    r = (CYL__L)cyl->r;
    H = (CYL__L)cyl->h; /* h until the frame is set, then h/2 */
    for (;;) {
        /* s = a × d with Kahan's products where the FMA is hardware (relative error 2u: rays
           near the axis direction keep an accurate s), m = a × w plainly (its error is of the
           order of the rounding of o − c anyway) */
        s[0] = CYL__P(ldop)(a[1], d[2], a[2], d[1]);
        s[1] = CYL__P(ldop)(a[2], d[0], a[0], d[2]);
        s[2] = CYL__P(ldop)(a[0], d[1], a[1], d[0]);
        m[0] = CYL__P(ldop)(a[1], w[2], a[2], w[1]);
        m[1] = CYL__P(ldop)(a[2], w[0], a[0], w[2]);
        m[2] = CYL__P(ldop)(a[0], w[1], a[1], w[0]);
        F->aa = CYL__P(ldot)(a, a);
        F->dd = CYL__P(ldot)(d, d);
        F->MM = CYL__P(ldot)(m, m);
        F->R2 = r * r * F->aa;
        /* The range check is the validation too: NaN, infinities, zero vectors and r, h <= 0
           fail it. Inside it no quantity below overflows, and none that decides or bounds
           anything underflows: they are products of |a|², |d|² and |m|² + r²|a|² (r²|s|² <=
           r²|a|²·|d|², so |a|² and |d|² are bounded each, not only their product) */
        if (F->aa >= 1 / CYL__LDIR && F->aa <= CYL__LDIR && F->dd >= 1 / CYL__LDIR &&
            F->dd <= CYL__LDIR && F->MM + F->R2 <= hi && F->R2 >= lo && r > 0 && cyl->h > 0 &&
            ray->tmin <= ray->tmax)
            break;
        if (scaled++ || CYL__P(rescale)(ray, cyl, a, d, w, &r, &H, lf, &tsc, &vsc)) return -1;
    }
    F->r = r;
    F->tsc = tsc;
    F->vsc = vsc;
    {
        /* Hand over what the plain roundings cannot resolve: o − c beyond 2^30 (double) or
           2^12 (float) radii or half heights, where its rounding alone is 2^-23 (2^-12) of e or
           of the rim margin; and an h/2 that rounds (h subnormal in the frame). The float API
           computed in double certifies (CYL_PRECISE, and every hand-over of the lean path)
           up to 2^40, where the first-order error bounds still hold with room (2^-10 of the
           quantities they bound). */
        const CYL__L far = CYL__LD ? (CYL__WIDE && ce ? (CYL__L)1099511627776.0 /* 2^40 */
                                                      : (CYL__L)1073741824.0)  /* 2^30 */
                                   : (CYL__L)4096.0;
        F->mw = CYL__P(lmax3)(w);
        F->H = H * (CYL__L)0.5;
        if (!(F->mw <= far * r) || (F->hfin && !(F->mw <= far * F->H))) return -1;
        if (F->hfin && (F->H + F->H < H || F->H + F->H > H)) return -1;
    }
    F->A = CYL__P(ldot)(s, s);
    /* sin²(angle) = A / (|a|²|d|²) against the parallel tolerance */
    thr = (CYL__L)CYL__PARA * (CYL__L)CYL__PARA * F->aa * F->dd;
    F->parallel = F->A <= thr;
    if (ce) {
        /* CYL_PRECISE in the API's own type: every decision below is taken only where the
           computed value is farther from its threshold than an a-priori bound on its error
           (standard model; first order, sf covers the rest), else the solver answers. The
           bounds: componentwise on s, m (with the rounding of o − c), then A, P, D, B, C, the
           roots, a·w, a·d, H|a|. */
        CYL__P(ferr)(a, d, s, F->mw, &F->ma, &F->md, &F->ms, &F->es, &F->em);
        F->eA = 3 * u * F->A + F->es * (6 * F->ms + 3 * F->es) + tiny;
        /* parallel rays go to the solver (|sin| <= u: rare in double) */
        if (!(F->A - F->eA > thr * (1 + 8 * u)) || !(F->eA < F->A * (CYL__L)0.25)) return -1;
    }
    F->r2 = r * r;
    if (!F->parallel) {
        /* D = r²A − P² = A(r² − ρ²), P = w·s: the wall is crossed iff D >= 0; a ray beside
           the infinite tube (certainly so, for CYL_PRECISE) misses before anything else is
           formed */
        F->P = CYL__P(ldot)(w, s);
        F->D = CYL__LMADD(F->r2, F->A, -(F->P * F->P));
        F->band = (CYL__L)CYL__TANG * F->r2 * F->A;
        if (ce) {
            CYL__L aP = CYL__P(labs)(F->P), eP = 3 * F->mw * (4 * u * F->ms + (1 + u) * F->es) + tiny;
            F->eD = (F->r2 * (3 * u * F->A + F->eA) + (3 * u * aP + 2 * eP) * (aP + eP) +
                     u * CYL__P(labs)(F->D)) * sf + tiny;
        }
        /* the plain test first (it resolves as soon as D does), then its certification (in
           CYL_PRECISE; nearly always true, so well predicted) */
        if (F->D < -F->band && F->D < -F->band - F->eD) return 0;
    }
    F->aw = CYL__P(ldot)(a, w);
    F->ad = CYL__P(ldot)(a, d);
    F->na = CYL__LSQRT(F->aa);
    F->Hn = F->hfin ? F->H * F->na : 0;
    if (ce) {
        F->eaw = 12 * u * F->ma * F->mw + tiny;
        F->ead = 9 * u * F->ma * F->md + tiny;
        F->eHn = 4 * u * F->Hn + tiny;
    }
    return 1;
}

/* CYL_PRECISE near the tangent band (either side of it), where the plain D errs by about the
   band's width: A, B and D again from double words (fcomp; C from the exact o − c, fc0, in
   froots), and a contact certainly inside the band is answered here too (N9); what fcomp
   cannot decide goes to the solver (-1). B and its bound in Bc[2]. */
CYL__PART int CYL__P(fnear)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, CYL__P(fs) *F,
                           const CYL__L a[3], const CYL__L d[3], const CYL__R lf[2], CYL__L Bc[2])
{
#if !CYL__WIDE
    /* fcomp is out of line: its inputs as copies, so that a and d themselves need no address
       (see rescale) */
    CYL__L cv[3], cerr[3], ac[3], dc[3];
    CYL__R lc[2];
    ac[0] = a[0];
    ac[1] = a[1];
    ac[2] = a[2];
    dc[0] = d[0];
    dc[1] = d[1];
    dc[2] = d[2];
    lc[0] = lf[0];
    lc[1] = lf[1];
    if (!CYL__P(fcomp)(ray, cyl, ac, dc, F->r, lc, F->mw, F->ma, F->md, F->band, cv, cerr))
        return -1;
    F->A = cv[0];
    F->eA = cerr[0];
    Bc[0] = cv[1];
    Bc[1] = cerr[1];
    F->D = cv[2];
    F->eD = cerr[2];
    F->comp = 1;
    return 0;
#else
    (void)ray;
    (void)cyl;
    (void)F;
    (void)a;
    (void)d;
    (void)lf;
    Bc[0] = Bc[1] = 0;
    return -1;
#endif
}

/* The wall's two roots of A t² + 2B t + C (B = m·s, C = |m|² − r²|a|², B² − AC = |a|²D) into
   tw[0] <= tw[1], with their bounds in c (CYL_PRECISE); Bc: B from double words and its
   bound (comp). Returns -1 where the solver must answer, else 0. */
CYL__PART int CYL__P(froots)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, CYL__P(fs) *F,
                            const CYL__L a[3], const CYL__L d[3], const CYL__L s[3],
                            const CYL__L m[3], const CYL__R lf[2], const CYL__L Bc[2],
                            CYL__P(fx) c[2], CYL__L tw[2])
{
    const CYL__L u = CYL__LU, sf = (CYL__L)1 + (CYL__L)1 / 64, tiny = CYL__LMIN;
    CYL__L ta, tb, B, C, Dp, q, sq, sb;
    int swap, cx = 0, comp = F->comp, ce = F->ce; /* cx: C from the exact o − c */
    B = comp ? Bc[0] : CYL__P(ldot)(m, s);
    C = F->MM - F->R2;
    Dp = F->D > 0 ? F->D : 0;
    sq = CYL__LSQRT(F->aa * Dp);
    F->noroots = comp && !(sq > 0);
    q = CYL__P(qpair)(B, sq);
    if (!(CYL__P(labs)(q) >= tiny)) return -1; /* a contact where B = D = 0 */
    ta = q / F->A;
    tb = C / q;
    if (comp ? !F->noroots
             : (CYL__P(labs)(C) <= 64 * u * (F->MM + F->R2) ||
                CYL__P(cnear)(tb, CYL__LMADD(tb, F->ad, F->aw), q,
                              64 * u * (3 * F->aa * F->mw * F->mw + F->R2), F->ad,
                              F->hfin ? F->Hn : (CYL__L)CYL__LMAX * 2, 1, F->tsc,
                              (CYL__L)ray->tmin, (CYL__L)ray->tmax))) {
        /* an origin on the surface within the roundings (a secondary ray), or a root C/q that
           C's rounding could move across a rim or an end of the t range: C from the exact
           o − c (fc0), so that the crossing near t = 0 is known to about u of itself for the
           rim and, in CYL_PRECISE, against tmin = 0 without the solver; near the tangent band
           in CYL_PRECISE (comp) always, unless there are no roots */
        C = CYL__P(fc0)(ray, cyl, a, d, s, F->r, lf);
        cx = 1;
        sb = CYL__P(sqbc)(B, F->A, C); /* √(B² − AC), kept where on the surface */
        if (!ce && CYL__P(onsurf)(C, F->R2) && CYL__P(labs)(CYL__P(qpair)(B, sb)) >= tiny) {
            sq = sb;
            q = CYL__P(qpair)(B, sq);
            ta = q / F->A;
        }
        tb = C / q;
    }
    F->sq = sq;
    /* a contact without roots (CYL_PRECISE near the band, D < 0): both ends at the point of
       closest approach −B/A, as the solver gives it */
    if (F->noroots) tb = ta;
    swap = ta > tb;
    tw[0] = swap ? tb : ta;
    tw[1] = swap ? ta : tb;
    if (ce) {
        /* the roots' bounds: q' = −(B + sgn(B̂)√(|a|²D)) exact, |q − q'| <= eq, t = q/A or C/q
           (1/(x(1 − ε)) <= (1 + 2ε)/x for ε <= 1/4) */
        const CYL__L ma = F->ma, mw = F->mw;
        CYL__L eB, eC, aq = CYL__P(labs)(q), rq, rA = F->eA / F->A, g, e0, e1, iq;
        eB = comp ? Bc[1] : 6 * ma * mw * (6 * u * F->ms + 2 * F->es) + tiny;
        /* C from fres carries u of itself and u² of |m|², r²|a|² and |a|²|o − c|² (<= 9 ma²
           mw²), over-covered here */
        eC = cx ? 2 * u * CYL__P(labs)(C) + 64 * u * u * (F->MM + F->R2 + 9 * ma * ma * mw * mw) +
                      tiny
                : 3 * u * F->MM + F->em * (12 * ma * mw + 3 * F->em) + 7 * u * F->R2 +
                      u * CYL__P(labs)(C) + tiny;
        F->esq = F->noroots ? 0 : F->aa * (F->eD + 4 * u * Dp) / sq + u * sq;
        /* one reciprocal for both quotients by |q|, raised by 4u so that each product bounds
           its quotient */
        iq = (1 + 4 * u) / aq;
        rq = (eB + F->esq + u * (sq + aq)) * iq;
        if (!(rq < (CYL__L)0.25)) return -1;
        g = rq * (1 + 2 * rq) + rA * (1 + 2 * rA) + u;
        e0 = CYL__P(labs)(ta) * g * (1 + 2 * rA) * (1 + 2 * g) * sf;
        e1 = ((eC * iq + CYL__P(labs)(tb) * rq) * (1 + 2 * rq) + u * CYL__P(labs)(tb)) * sf;
        if (F->noroots) e1 = e0; /* the contact: t = q/A at both ends */
        c[0].et = swap ? e1 : e0;
        c[1].et = swap ? e0 : e1;
    }
    return 0;
}

/* Each wall root tw[k] into c[k]: its side of the cap planes, and in CYL_PRECISE the
   certification of its correction and of its rim. Returns -1 where the solver must answer,
   else 0. */
CYL__PART int CYL__P(fcert)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                           const CYL__P(fs) *F, const CYL__L a[3], const CYL__L d[3],
                           const CYL__L s[3], const CYL__R lf[2], const CYL__L tw[2],
                           CYL__P(fx) c[2])
{
    const CYL__L u = CYL__LU, sf = (CYL__L)1 + (CYL__L)1 / 64;
    int k;
    for (k = 0; k < 2; k++) {
        /* the root against the cap planes: v|a| = a·w + t·a·d against ±H|a| */
        CYL__L vn = CYL__LMADD(tw[k], F->ad, F->aw);
        c[k].sg = !F->hfin || CYL__P(labs)(vn) <= F->Hn ? 0 : (vn < 0 ? -1 : 1);
        c[k].t = tw[k];
        /* the wall root's correction in the output (a root that gives way to a cap plane is
           not corrected at all): steps with this √(|a|²D) as fsteps counts them; where one is
           not enough, first one step with √ from its own residual, which certifies itself
           (frefr), then those steps; where more than CYL__STEPS would be needed, that step
           here, else the solver */
        if (F->ce && !c[k].sg && !F->noroots) {
            const CYL__L r = F->r, md = F->md, sq = F->sq, esq = F->esq;
#if !CYL__WIDE
            CYL__L at = CYL__P(labs)(tw[k]), x, x2;
            /* a flag, not a branch: the bound comes at the end of a long chain */
            c[k].resid = CYL__P(fsteps)(c[k].et, at, sq, esq, md, r, 1) > 1;
            if (c[k].resid) {
                /* fsteps' e_n <= x^(n-1)·e_1 + 8L/(1 − x), x = 2·esq/sq, L its target:
                   x <= 1/32 and x^6·e_1 <= L give n <= 6 = CYL__STEPS. Else the residual step
                   here, then the counted steps, then the solver, so that every entry point
                   hands the call over alike (whichever root it reports); a t from here is
                   final (steps 0) */
                x = 2 * esq / sq;
                x2 = x * x;
                if (!(x <= (CYL__L)0.03125 &&
                      x2 * x2 * x2 * c[k].et <= (CYL__L)0.25 * u * (at + r / md))) {
                    const CYL__L cb[8] = {r * F->na * (1 + 4 * u), F->ms, F->es, F->ma, F->mw,
                                          md, F->eA, r / md};
                    CYL__L tc = tw[k];
                    c[k].resid = 0;
                    if (CYL__P(frefr)(ray, cyl, a, d, s, r, lf, F->A, tw[k], k, cb, &tc)) {
                        c[k].t = tc;
                        c[k].et += (CYL__L)0.25 * u * (at + r / md) + 2 * u * CYL__P(labs)(tc);
                        c[k].steps = 0;
                    } else if ((c[k].steps = CYL__P(fsteps)(c[k].et, at, sq, esq, md, r,
                                                            CYL__STEPS)) > CYL__STEPS) {
                        return -1;
                    }
                }
            }
#else
            (void)ray;
            (void)cyl;
            (void)a;
            (void)d;
            (void)s;
            (void)lf;
            if (CYL__P(fsteps)(c[k].et, CYL__P(labs)(tw[k]), sq, esq, md, r, CYL__STEPS) >
                CYL__STEPS)
                return -1;
#endif
        }
        if (F->ce && F->hfin) {
            CYL__L av = CYL__P(labs)(vn), ev;
            ev = (F->eaw + F->eHn + CYL__P(labs)(tw[k]) * (F->ead + 6 * u * F->ma * F->md) +
                  (3 * F->ma * F->md + F->ead) * c[k].et + u * av) * sf;
            if (!(av > F->Hn + ev) && !(av < F->Hn - ev)) return -1;
        }
    }
    return 0;
}

/* The wall roots in c against the solid's caps: the roots are ordered, so the ray runs from
   one side to the other: the solid is entered through the cap of side 0 (or the wall), left
   through that of side 1. Returns -1 where the solver must answer, else 0. */
CYL__PART int CYL__P(fclip)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                           const CYL__P(fs) *F, const CYL__L a[3], const CYL__L d[3],
                           const CYL__L s[3], const CYL__L m[3], const CYL__R lf[2],
                           CYL__P(fx) c[2])
{
    const CYL__L u = CYL__LU, sf = (CYL__L)1 + (CYL__L)1 / 64;
    int k;
    for (k = 0; k < 2; k++) {
        if (!c[k].sg) {
            c[k].ok = 1;
        } else if (F->caps && c[0].sg != c[1].sg) {
            CYL__L num = (CYL__L)c[k].sg * F->Hn - F->aw, aad = CYL__P(labs)(F->ad);
            c[k].t = num / F->ad;
            if (F->ce) {
                const CYL__L eHn = F->eHn, eaw = F->eaw;
                if (!(aad > 2 * F->ead)) return -1;
                c[k].et = ((eHn + eaw + u * CYL__P(labs)(num) + CYL__P(labs)(c[k].t) * F->ead) *
                               2 / aad +
                           u * CYL__P(labs)(c[k].t)) * sf;
#if !CYL__WIDE
                if (CYL__P(labs)(num) <= 4 * (eHn + eaw)) {
                    /* an origin on the cap plane within the roundings (a secondary ray from a
                       cap): the crossing from double words (fcapt: its numerator and a·d
                       carry u² of their terms, its quotient rounds twice), decided against
                       tmin = 0 without the solver */
                    CYL__L at;
                    c[k].t = CYL__P(fcapt)(ray, cyl, a, d, F->H, lf, c[k].sg, c[k].t);
                    c[k].steps = 0;
                    at = CYL__P(labs)(c[k].t);
                    c[k].et = (2 * u * at + 16 * u * u *
                               (F->Hn + 3 * F->ma * F->mw + at * 3 * F->ma * F->md) * 2 / aad) *
                                  sf +
                              CYL__LMIN;
                }
#endif
            }
            /* a grazing interval's cap end must still lie on its disk */
            c[k].ok = !F->tangent || CYL__P(fdisk)(m, s, F->R2, c[k].t);
        }
    }
#if CYL__WIDE
    (void)ray;
    (void)cyl;
    (void)a;
    (void)d;
    (void)lf;
#endif
    return 0;
}

/* The crossings c of a ray that is not parallel: -1 where the solver must answer, 0 a miss,
   1 with c set. */
CYL__PART int CYL__P(fwall)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts,
                           CYL__P(fs) *F, const CYL__L a[3], const CYL__L d[3],
                           const CYL__L s[3], const CYL__L m[3], const CYL__R lf[2],
                           CYL__P(fx) c[2])
{
    CYL__L Bc[2] = {0, 0}, tw[2]; /* B from double words (comp) and its bound */
    /* certified: beside (above), or clearly crossed, else fnear */
    if (F->ce && !(F->D > F->band + F->eD) && CYL__P(fnear)(ray, cyl, F, a, d, lf, Bc)) return -1;
    if (!(F->D >= -F->band)) return 0;
    F->tangent = F->D <= F->band;
    if (F->tangent && (opts & CYL_NO_TANGENT)) return 0;
    if (CYL__P(froots)(ray, cyl, F, a, d, s, m, lf, Bc, c, tw) ||
        CYL__P(fcert)(ray, cyl, F, a, d, s, lf, tw, c) ||
        CYL__P(fclip)(ray, cyl, F, a, d, s, m, lf, c))
        return -1;
    return 1;
}

/* The crossings c kept in [tmin, tmax], as indices into sel (the first only, for want < 2):
   their number, or -1 where CYL_PRECISE hands one over. */
CYL__PART int CYL__P(fpick)(const CYL__N(ray) *ray, const CYL__P(fs) *F, const CYL__P(fx) c[2],
                           int want, int sel[2])
{
    CYL__L tmin = (CYL__L)ray->tmin, tmax = (CYL__L)ray->tmax, tsc = F->tsc;
    int k, kept = 0;
    for (k = 0; F->ce && k < 2; k++) {
        /* CYL_PRECISE: a crossing too close to tmin or tmax to tell goes to the solver, for
           every entry point alike, unless it is inside the t-range band, where either answer
           is right (N9): [tu − eu, tu + eu] holds an end and the exact t, so they are within
           2·eu, and max(|tu| − eu, r/|d|) is at most the band's scale max(|t|, r/|d|)
           (1 + 1/64 covers the roundings of r/|d| and of this test). Secondary rays (an
           origin on the surface, tmin = 0) are decided here. */
        CYL__L tu = c[k].t * tsc, eu = c[k].et * tsc, sc;
        if (c[k].ok && !(tu + eu < tmin || tu - eu > tmax) &&
            !(tu - eu > tmin && tu + eu < tmax)) {
            sc = F->r / CYL__LSQRT(F->dd) * tsc;
            if (CYL__P(labs)(tu) - eu > sc) sc = CYL__P(labs)(tu) - eu;
            if (!(2 * eu * (1 + (CYL__L)1 / 64) <= (CYL__L)CYL__TBAND * sc)) return -1;
        }
    }
    for (k = 0; k < 2; k++) {
        CYL__L tu = c[k].t * tsc;
        if (c[k].ok && tu >= tmin && tu <= tmax && CYL__P(labs)(tu) <= (CYL__L)CYL__MAXR) {
            sel[kept] = k;
            kept++;
            if (want < 2) break;
        }
    }
    return kept;
}

/* The unit outward wall normal y × a at y = m + t·s (no cancellation: y ⊥ a) into nl, y into
   y; returns the face that turns it toward the ray. */
CYL__PART CYL__L CYL__P(fnormal)(const CYL__L a[3], const CYL__L d[3], const CYL__L s[3],
                                const CYL__L m[3], CYL__L t, CYL__L nl[3], CYL__L y[3])
{
    CYL__L len2;
    int k;
    /* y stays a loop: written out, gcc -Os spills more of fast() on Cortex-M4F (its stack in
       make sizes) */
    for (k = 0; k < 3; k++) y[k] = CYL__LMADD(t, s[k], m[k]);
    nl[0] = CYL__LMADD(y[1], a[2], -(y[2] * a[1]));
    nl[1] = CYL__LMADD(y[2], a[0], -(y[0] * a[2]));
    nl[2] = CYL__LMADD(y[0], a[1], -(y[1] * a[0]));
    len2 = CYL__P(ldot)(nl, nl);
    if (!(len2 >= CYL__LMIN)) {
        /* y lost to cancellation (r far below the rounding of o − c): any unit vector
           orthogonal to the axis */
        int z0 = CYL__P(labs)(a[0]) <= CYL__P(labs)(a[1]); /* zero nl[0] */
        nl[0] = z0 ? 0 : a[2];
        nl[1] = z0 ? a[2] : 0;
        nl[2] = z0 ? -a[1] : -a[0];
        len2 = CYL__P(ldot)(nl, nl);
    } else if (!(len2 <= CYL__LMAX)) {
        /* a crossing so far out that |y × a|² overflows: scaled by its largest component */
        CYL__L sk = 1 / CYL__P(lmax3)(nl);
        nl[0] *= sk;
        nl[1] *= sk;
        nl[2] *= sk;
        len2 = CYL__P(ldot)(nl, nl);
    }
    len2 = 1 / CYL__LSQRT(len2);
    nl[0] *= len2;
    nl[1] *= len2;
    nl[2] *= len2;
    return CYL__P(ldot)(nl, d) > 0 ? -1 : 1;
}

/* One hit of the fast path from crossing x (index k: 1 for the second root) into *o: t
   corrected (double words, N4/N5), part, flags, v, the normal and t_err (N8). Nothing hands
   over from here on: the caller's record is written directly; Hu is h/2 rounded toward 0. */
CYL__PART void CYL__P(femit)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts,
                            const CYL__P(fs) *F, const CYL__L a[3], const CYL__L d[3],
                            const CYL__L s[3], const CYL__L m[3], const CYL__R lf[2],
                            const CYL__P(fx) *x, int k, CYL__R Hu, CYL__N(hit) *o)
{
    const CYL__L sf = (CYL__L)1 + (CYL__L)1 / 64, tsc = F->tsc;
    CYL__L t = x->t, tu, nl[3] = {0, 0, 0}, y[3], face = 1, et;
    CYL__L tdev = 0; /* |t·tsc − tu| where the frame's t is not exactly tu */
    CYL__R tr;
    tu = t * tsc;
#if !CYL__WIDE
    if (x->steps && (x->sg || !F->tangent || (F->comp && !F->noroots))) {
        /* the crossing to an ulp, kept in the accepted range; CYL_PRECISE first tries one
           step with √ from its own residual where one plain step is not enough (ce first:
           without it all of this folds away), and where that step does not certify itself
           takes the plain steps fsteps counts (the certification made sure there are at most
           CYL__STEPS) */
        if (x->sg) {
            t = CYL__P(fcapt)(ray, cyl, a, d, F->H, lf, x->sg, t);
        } else {
            const CYL__L u = CYL__LU, r = F->r, md = F->md;
            const CYL__L cb[8] = {r * F->na * (1 + 4 * u), F->ms, F->es, F->ma, F->mw, md, F->eA,
                                  r / md};
            int rs = F->ce && x->resid;
            if (!rs || !CYL__P(frefr)(ray, cyl, a, d, s, r, lf, F->A, x->t, k, cb, &t))
                t = CYL__P(fref)(ray, cyl, a, d, s, r, lf, F->A, F->sq, x->t, k,
                                 rs ? CYL__P(fsteps)(x->et, CYL__P(labs)(x->t), F->sq, F->esq,
                                                     md, r, CYL__STEPS)
                                    : x->steps);
        }
        tdev = CYL__P(fclamp)(ray, tsc, &t, &tu);
    }
#else
    (void)ray;
    (void)cyl;
    (void)lf;
#endif
    tr = (CYL__R)tu;
    o->t = tr;
    o->part = x->sg ? (x->sg > 0 ? CYL_CAP_HIGH : CYL_CAP_LOW) : CYL_SIDE;
    o->flags = (k ? CYL_F_INSIDE : 0u) | (F->parallel ? CYL_F_PARALLEL : 0u) |
               (F->tangent && !x->sg ? CYL_F_TANGENT : 0u);
    if (!x->sg) {
        /* wall: v within ±h/2 up to rounding is reported within; an infinite tube's
           saturates */
        CYL__L v = CYL__LMADD(t, F->ad, F->aw) / F->na * F->vsc;
        if (!(opts & CYL_NO_NORMAL)) face = CYL__P(fnormal)(a, d, s, m, t, nl, y);
        v = v > (CYL__L)Hu ? (CYL__L)Hu : (v < -(CYL__L)Hu ? -(CYL__L)Hu : v);
        if (!F->hfin && CYL__P(labs)(v) > (CYL__L)CYL__MAXR)
            v = v > 0 ? (CYL__L)CYL__MAXR : -(CYL__L)CYL__MAXR;
        o->v = (CYL__R)v;
    } else {
        if (!(opts & CYL_NO_NORMAL)) {
            CYL__L sg = (CYL__L)x->sg / F->na;
            nl[0] = sg * a[0];
            nl[1] = sg * a[1];
            nl[2] = sg * a[2];
            face = sg * F->ad > 0 ? -1 : 1;
        }
        o->v = x->sg > 0 ? Hu : -Hu;
    }
    if (opts & CYL_OUTWARD) face = 1;
    {
        /* named before the conversion (MISRA 10.8); component by component, so that a, s, m
           and the normal need no memory (see rescale) */
        CYL__L n0 = face * nl[0], n1 = face * nl[1], n2 = face * nl[2];
        o->n[0] = (CYL__R)n0;
        o->n[1] = (CYL__R)n1;
        o->n[2] = (CYL__R)n2;
    }
    if (opts & CYL_NO_ERRBOUND) {
        o->t_err = CYL__MAXR * 2;
        return;
    }
    {
        /* t's bound, from the residual at t (N8): bounds on the errors of s and m (with the
           rounding of o − c) give one on y = m + t·s, hence on f(t) = |y|² − r²|a|² and on
           f'(t)/2 = y·s; the nearest root of the exact quadratic is within min(F/G, √(F/A)).
           A cap: the plane's residual a·x(t) ∓ H|a| over a·d. */
        CYL__L at = CYL__P(labs)(t), ma = F->ma, md = F->md, ms = F->ms, es = F->es, em = F->em;
        if (!F->ce) CYL__P(ferr)(a, d, s, F->mw, &ma, &md, &ms, &es, &em);
        if (!x->sg) {
            int j;
            if (opts & CYL_NO_NORMAL)
                for (j = 0; j < 3; j++) y[j] = CYL__LMADD(t, s[j], m[j]);
            et = CYL__P(wbound)(y, CYL__P(ldot)(y, y), CYL__P(ldot)(y, s), at, F->A, F->R2, ms, es,
                                em);
        } else {
            et = CYL__P(cbound)(t, F->ad, F->aw, (CYL__L)x->sg * F->Hn, 3 * ma * F->mw,
                                3 * ma * md);
        }
        /* in the caller's units */
        o->t_err = CYL__P(errup)(et * sf * tsc + tdev, tu, tr);
    }
}

/* want: 0 occluded (returns 1 or 0), 1 the nearest hit into hits[0], 2 every hit.
   Returns -1 (nothing written) when the solver must answer. */
#if CYL__QUICK && CYL__WIDE
#define CYL__FASTQ CYL__SLOW /* only behind the lean path's hand-over: out of line */
#else
#define CYL__FASTQ CYL__FAST
#endif
CYL__FASTQ int CYL__P(fast)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts,
                          int want, CYL__N(hit) *hits)
{
    CYL__L a[3], d[3], s[3], m[3];
    CYL__R lf[2] = {1, 1}; /* the frame's length scale, as two factors */
    CYL__P(fs) F;
    CYL__P(fx) c[2];
    int i, k, n, sel[2] = {0, 0};
    n = CYL__P(fframe)(ray, cyl, opts, &F, a, d, s, m, lf);
    if (n <= 0) return n;
    for (k = 0; k < 2; k++) {
        c[k].ok = c[k].sg = c[k].resid = 0;
        c[k].steps = 1;
        c[k].t = c[k].et = 0;
    }
    if (!F.parallel) {
        n = CYL__P(fwall)(ray, cyl, opts, &F, a, d, s, m, lf, c);
        if (n <= 0) return n;
    } else if (F.caps && F.hfin) {
        /* the wall is never hit; a cap is, where the ray point is on its disk */
        for (k = 0; k < 2; k++) {
            c[k].sg = (k == 0) == (F.ad > 0) ? -1 : 1;
            c[k].t = ((CYL__L)c[k].sg * F.Hn - F.aw) / F.ad;
            c[k].ok = CYL__P(fdisk)(m, s, F.R2, c[k].t);
        }
    }
    n = CYL__P(fpick)(ray, &F, c, want, sel);
    if (want == 0 || n <= 0) return n < 0 ? -1 : n > 0;
    {
        CYL__R Hu = cyl->h * CYL__C(0.5);
        if (Hu + Hu > cyl->h) Hu = (cyl->h - CYL__MINR * 2 * CYL__U) * CYL__C(0.5);
        for (i = 0; i < n; i++)
            CYL__P(femit)(ray, cyl, opts, &F, a, d, s, m, lf, &c[sel[i]], sel[i], Hu, &hits[i]);
    }
    if (n == 2) CYL__P(order2)(hits);
    return n;
}

/* ------------------------------------------------------------------ the lean path */

#if CYL__QUICK
/* Cross product components for the lean path. The float API's inputs are floats: their
   products are exact in double, so pq − rs rounds once with or without an FMA; the double
   API uses Kahan's products (ldop). */
#if CYL__WIDE
#define CYL__QX(p, q, r, s) CYL__LMADD(p, q, -((r) * (s)))
#else
#define CYL__QX(p, q, r, s) CYL__P(ldop)(p, q, r, s)
#endif

/* The lean path's wall bound: N8's residual bound with norm-wise error terms, from what
   the lean path has at hand (no componentwise maxima, no square root: 1-norms bound the
   2-norms): em >= |δm| (with the rounding of o − c), es >= |δs|, s1 >= |s|; y at t with
   Y = ŷ·ŷ and Gs = ŷ·ŝ, at = |t|. E bounds |ŷ − y| (the roundings of m, s and of
   ŷ = m + t·s), hence F >= |f(t)| (with the roundings of Y, r²|a|² and Y − r²|a|²) and
   G <= |f'(t)|/2 (with the rounding of ŷ·ŝ); the nearest root of the exact quadratic is
   within F/G where G² > A·F, else within √(F/A). */
CYL__INL CYL__L CYL__P(qbound)(const CYL__L y[3], CYL__L Y, CYL__L Gs, CYL__L at, CYL__L A,
                              CYL__L R2, CYL__L s1, CYL__L es, CYL__L em)
{
    const CYL__L u = CYL__LU, sf = (CYL__L)1 + (CYL__L)1 / 64, tiny = CYL__LMIN;
    CYL__L y1 = CYL__P(l1)(y), E, F, G, Alo;
    E = em + at * (es + u * s1) + u * y1;
    F = Y - R2;
    F = CYL__P(labs)(F) +
        (3 * u * Y + E * (2 * y1 + E) + 6 * u * R2 + u * CYL__P(labs)(F)) * sf + tiny;
    G = CYL__P(labs)(Gs) - (E * (s1 + es) + y1 * (es + 3 * u * s1)) * sf - tiny;
    Alo = A - (3 * u * A + es * (2 * s1 + es)) * sf - tiny;
    if (G > 0 && G * G > (2 * A - Alo) * F) return F / G;
    return Alo > 0 ? CYL__LSQRT(F / Alo) : (CYL__L)CYL__MAXR * 2;
}

/* The lean path's frame: what its hits need besides the crossing. */
typedef struct CYL__P(qf) {
    CYL__L a[3], d[3], w[3], s[3], m[3];
    CYL__L aa, na, A, R2, ad, aw, H, Hn, r, sq;
    CYL__L w1, d1;   /* |w|_1 and |d|_1 for the bounds, formed early: w and d then die there */
    CYL__L tsc, vsc; /* the frame's t and lengths times these are the caller's */
    CYL__R lf[2];    /* the frame's length scale, as two factors */
} CYL__P(qf);

/* One hit of the lean path: crossing t (frame) on the wall (sg = 0) or a cap (sg = ∓1). */
CYL__INL void CYL__P(qhit)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                          const CYL__P(qf) *f, CYL__L t, int sg, unsigned flags, unsigned opts,
                          CYL__N(hit) *o)
{
    CYL__R Hu = cyl->h * CYL__C(0.5); /* h/2 in the caller's units, rounded toward zero */
    const CYL__L u = CYL__LU;
    CYL__L et = 0, nl[3] = {0, 0, 0}, face = 1, s1 = 0, es = 0, em = 0, Sw = 0, Sd = 0;
    CYL__L tu = t * f->tsc, tdev = 0;
    CYL__R tr;
#if CYL__WIDE
    (void)ray;
#endif
    if (Hu + Hu > cyl->h) Hu = (cyl->h - CYL__MINR * 2 * CYL__U) * CYL__C(0.5);
    if (!(opts & CYL_NO_ERRBOUND)) {
        /* norm-wise error bounds (1-norms bound the 2-norms): Sw = |a|·|w|_1 >= Σ|a_i w_i|,
           Sd = |a|·|d|_1; |δm| <= 4u|a||w| (o − c, the products and the subtraction, with or
           without an FMA); |δs| <= u|s| for float inputs (exact products, one rounding), 2u|s|
           for Kahan's, else 3u|a||d| */
        Sw = f->na * f->w1;
        Sd = f->na * f->d1;
        s1 = CYL__P(l1)(f->s);
        em = 4 * u * Sw;
        es = CYL__WIDE ? u * s1 : (CYL__LKAHAN ? 2 * u * s1 : 3 * u * Sd);
    }
    if (!sg) {
        CYL__L y[3], Y, G, v;
#if !CYL__WIDE
        if (!(flags & CYL_F_TANGENT)) {
            /* the exact-quadratic correction from double words (fref), kept in range */
            t = CYL__P(fref)(ray, cyl, f->a, f->d, f->s, f->r, f->lf, f->A, f->sq, t,
                             (flags & CYL_F_INSIDE) != 0, 1);
            tdev = CYL__P(fclamp)(ray, f->tsc, &t, &tu);
        }
#endif
        y[0] = CYL__LMADD(t, f->s[0], f->m[0]);
        y[1] = CYL__LMADD(t, f->s[1], f->m[1]);
        y[2] = CYL__LMADD(t, f->s[2], f->m[2]);
        Y = CYL__P(ldot)(y, y);
        G = CYL__P(ldot)(y, f->s);
        o->part = CYL_SIDE;
        if (!(opts & CYL_NO_NORMAL)) {
            /* the outward normal y × a, |y × a| = |y||a| (y ⊥ a); it faces the ray where
               (y × a)·d = y·s = G < 0 */
            CYL__L Ya = Y * f->aa, sc, yn[3];
            yn[0] = y[0];
            yn[1] = y[1];
            yn[2] = y[2];
            if (!(Ya <= CYL__LMAX)) {
                /* a crossing so far out that |y|²|a|² overflows (the far root of a contact in
                   the tangent band): y scaled by its largest component */
                CYL__L k = 1 / CYL__P(lmax3)(y);
                yn[0] = y[0] * k;
                yn[1] = y[1] * k;
                yn[2] = y[2] * k;
                if (CYL__WIDE) Ya = CYL__P(ldot)(yn, yn) * f->aa; /* the double API: |y × a| */
            }
            nl[0] = CYL__LMADD(yn[1], f->a[2], -(yn[2] * f->a[1]));
            nl[1] = CYL__LMADD(yn[2], f->a[0], -(yn[0] * f->a[2]));
            nl[2] = CYL__LMADD(yn[0], f->a[1], -(yn[1] * f->a[0]));
            /* the double API divides by |y × a| itself: y = m + t·s cancels by up to |o − c|/r
               (2^30), which tilts it off ⊥ a by as much times u, and |y||a| then exceeds
               |y × a| by that squared (64 ulps); in the float API it stays below 2^-47 */
            sc = 1 / CYL__LSQRT(CYL__WIDE ? Ya : CYL__P(ldot)(nl, nl));
            nl[0] *= sc;
            nl[1] *= sc;
            nl[2] *= sc;
            face = G > 0 ? -1 : 1;
        }
        /* v within ±h/2 up to rounding: reported within; an infinite tube's saturates */
        v = CYL__LMADD(t, f->ad, f->aw) / f->na * f->vsc;
        v = v > (CYL__L)Hu ? (CYL__L)Hu : (v < -(CYL__L)Hu ? -(CYL__L)Hu : v);
        if (CYL__P(labs)(v) > (CYL__L)CYL__MAXR) v = v > 0 ? (CYL__L)CYL__MAXR : -(CYL__L)CYL__MAXR;
        o->v = (CYL__R)v;
        if (!(opts & CYL_NO_ERRBOUND))
            et = CYL__P(qbound)(y, Y, G, CYL__P(labs)(t), f->A, f->R2, s1, es, em);
    } else {
        CYL__L sgn = (CYL__L)sg;
#if !CYL__WIDE
        /* the plane crossing to about an ulp from double words (the plain quotient loses
           several where H|a| and a·w nearly cancel), kept in [tmin, tmax] */
        t = CYL__P(fcapt)(ray, cyl, f->a, f->d, f->H, f->lf, sg, t);
        tdev = CYL__P(fclamp)(ray, f->tsc, &t, &tu);
#endif
        o->part = sg > 0 ? CYL_CAP_HIGH : CYL_CAP_LOW;
        if (!(opts & CYL_NO_NORMAL)) {
            CYL__L k = sgn / f->na;
            nl[0] = k * f->a[0];
            nl[1] = k * f->a[1];
            nl[2] = k * f->a[2];
            face = sgn * f->ad > 0 ? -1 : 1;
        }
        o->v = sg > 0 ? Hu : -Hu;
        if (!(opts & CYL_NO_ERRBOUND))
            et = CYL__P(cbound)(t, f->ad, f->aw, sgn * f->Hn, Sw, Sd);
    }
    tr = (CYL__R)tu;
    o->t = tr;
    o->flags = flags;
    if (opts & CYL_OUTWARD) face = 1;
    /* component by component, not in a loop: gcc then keeps y and the normal in registers */
    {
        /* named before the conversion: MISRA 10.8 (no cast of a composite expression) */
        CYL__L n0 = face * nl[0], n1 = face * nl[1], n2 = face * nl[2];
        o->n[0] = (CYL__R)n0;
        o->n[1] = (CYL__R)n1;
        o->n[2] = (CYL__R)n2;
    }
    o->t_err = (opts & CYL_NO_ERRBOUND)
                   ? CYL__MAXR * 2
                   : CYL__P(errup)(et * ((CYL__L)1 + (CYL__L)1 / 64) * f->tsc + tdev, tu, tr);
}

/* Where the fast path computes in double (the double API, and the float API where double is
   hardware), every option set starts here (CYL_PRECISE only for floats with an FMA): the fast
   path's formulas and exact scaling with as few operations, branches and live values as the
   method allows. It answers origins within 2^30 radii and half heights (2^28 for
   CYL_PRECISE); far origins, an h/2 that rounds, a degenerate root pair and scaling out of
   range return -1 (nothing written), and the solver answers (the fast path, for CYL_PRECISE
   in the double API). The double API's crossings are corrected from double words as in the
   fast path (fref, fcapt); t_err is the residual bound at the returned t. */
/* qhit out of line, for the rescaled frame's copy of the lean path (one copy, not two). */
CYL__SLOW void CYL__P(qhitc)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                             const CYL__P(qf) *f, CYL__L t, int sg, unsigned flags, unsigned opts,
                             CYL__N(hit) *o)
{
    CYL__P(qhit)(ray, cyl, f, t, sg, flags, opts, o);
}

/* One hit of the lean path: inline, or out of line in the float API's rescaled copy. */
CYL__INL void CYL__P(qemit)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                           const CYL__P(qf) *f, CYL__L t, int sg, unsigned flags, unsigned opts,
                           int scaled, CYL__N(hit) *o)
{
    if (CYL__WIDE && scaled)
        CYL__P(qhitc)(ray, cyl, f, t, sg, flags, opts, o);
    else
        CYL__P(qhit)(ray, cyl, f, t, sg, flags, opts, o);
}

/* The lean path's frame from a, d, w (in f) and r: s, m and what needs w and d, formed before
   the range check so that w and d die there. Returns the fast path's range check, which
   validates too. */
CYL__INL int CYL__P(qframe)(CYL__P(qf) *f, CYL__L r, CYL__L h, CYL__L tmin, CYL__L tmax,
                           CYL__L *dd, CYL__L *MM, CYL__L *r2, CYL__L *ww, CYL__L *P)
{
    const CYL__L hi = CYL__LHI;
    f->s[0] = CYL__QX(f->a[1], f->d[2], f->a[2], f->d[1]);
    f->s[1] = CYL__QX(f->a[2], f->d[0], f->a[0], f->d[2]);
    f->s[2] = CYL__QX(f->a[0], f->d[1], f->a[1], f->d[0]);
    f->m[0] = CYL__QX(f->a[1], f->w[2], f->a[2], f->w[1]);
    f->m[1] = CYL__QX(f->a[2], f->w[0], f->a[0], f->w[2]);
    f->m[2] = CYL__QX(f->a[0], f->w[1], f->a[1], f->w[0]);
    f->aa = CYL__P(ldot)(f->a, f->a);
    *dd = CYL__P(ldot)(f->d, f->d);
    f->A = CYL__P(ldot)(f->s, f->s);
    *MM = CYL__P(ldot)(f->m, f->m);
    *r2 = r * r;
    f->R2 = *r2 * f->aa;
    *ww = CYL__P(ldot)(f->w, f->w);
    f->aw = CYL__P(ldot)(f->a, f->w);
    f->ad = CYL__P(ldot)(f->a, f->d);
    *P = CYL__P(ldot)(f->w, f->s);
    f->w1 = CYL__P(l1)(f->w);
    f->d1 = CYL__P(l1)(f->d);
    return f->aa >= 1 / CYL__LDIR && f->aa <= CYL__LDIR && *dd >= 1 / CYL__LDIR &&
           *dd <= CYL__LDIR && *MM + f->R2 <= hi && f->R2 >= 1 / hi && r > 0 && h > 0 &&
           tmin <= tmax;
}

/* The lean path's wall roots t[0] <= t[1] (frame) where D >= −band, and their sides of the cap
   planes in sg (0 between them, ∓1 beyond the low or high one). Returns -1 where the roots
   are left to the fast path, else 0. */
CYL__PART int CYL__P(qroots)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                            CYL__P(qf) *f, CYL__L r, CYL__L D, CYL__L MM, CYL__L ww,
                            CYL__L tmin, CYL__L tmax, CYL__L t[2], int sg[2])
{
    CYL__L B = CYL__P(ldot)(f->m, f->s), C = MM - f->R2, sq, q, t0, t1, v0, v1;
    f->sq = sq = CYL__LSQRT(f->aa * (D > 0 ? D : 0));
    q = CYL__P(qpair)(B, sq);
    if (!(CYL__P(labs)(q) >= CYL__LMIN)) return -1;
    t0 = q / f->A;
    t1 = C / q;
    /* the roots against the slab between the cap planes, v|a| = a·w + t·a·d against
       ±H|a| (+inf for the infinite tube) */
    v0 = CYL__LMADD(t0, f->ad, f->aw);
    v1 = CYL__LMADD(t1, f->ad, f->aw);
#if CYL__WIDE
    /* a root C/q that C's rounding could move across a rim (cnear): the fast path forms C
       from the exact o − c (out of line: a call here would cost every call its spills).
       Against tmin and tmax C/q errs by at most about 8u/sin of r/|d| (u of double), far
       inside float's t-range band, so surface origins need nothing. */
    if (CYL__P(cnear)(t1, v1, q, 64 * (CYL__L)CYL__LU * (f->aa * ww + f->R2), f->ad, f->Hn, 0,
                      f->tsc, tmin, tmax))
        return -1;
#else
    /* an origin on the surface within the roundings, or a root C/q that C's rounding could
       move across a rim or an end of the t range (cnear): C from the exact o − c */
    if (CYL__P(labs)(C) <= 64 * (CYL__L)CYL__LU * (MM + f->R2) ||
        CYL__P(cnear)(t1, v1, q, 64 * (CYL__L)CYL__LU * (f->aa * ww + f->R2), f->ad, f->Hn, 1,
                      f->tsc, tmin, tmax)) {
        CYL__L sb;
        C = CYL__P(fc0)(ray, cyl, f->a, f->d, f->s, r, f->lf);
        sb = CYL__P(sqbc)(B, f->A, C); /* √(B² − AC), kept where on the surface */
        if (CYL__P(onsurf)(C, f->R2) && CYL__P(labs)(CYL__P(qpair)(B, sb)) >= CYL__LMIN) {
            f->sq = sq = sb;
            q = CYL__P(qpair)(B, sq);
            t0 = q / f->A;
            v0 = CYL__LMADD(t0, f->ad, f->aw);
        }
        t1 = C / q;
        v1 = CYL__LMADD(t1, f->ad, f->aw);
    }
#endif
    if (t0 > t1) {
        CYL__L x = t0;
        t0 = t1;
        t1 = x;
        x = v0;
        v0 = v1;
        v1 = x;
    }
    t[0] = t0;
    t[1] = t1;
    sg[0] = (v0 > f->Hn) - (v0 < -f->Hn);
    sg[1] = (v1 > f->Hn) - (v1 < -f->Hn);
#if CYL__WIDE
    (void)ray;
    (void)cyl;
    (void)r;
#endif
    return 0;
}

/* The lean path after its range check, on the frame f and what qframe formed (dd, MM, r2, ww,
   P) with r, h, tmin and tmax in the frame's type; scaled = 1 for the rescaled frame. */
CYL__INL int CYL__P(qbody)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts,
                          int want, CYL__N(hit) *hits, CYL__P(qf) *f, CYL__L r, CYL__L h,
                          CYL__L tmin, CYL__L tmax, CYL__L dd, CYL__L MM, CYL__L r2, CYL__L ww,
                          CYL__L P, int scaled)
{
    /* |o − c| <= 2^30 r and 2^30 h/2, as the fast path; CYL_PRECISE (here only for the float
       API computed in double with an FMA) keeps a headroom of 2^28 (N9) */
    const CYL__L far2 = (opts & CYL_PRECISE) ? (CYL__L)72057594037927936.0 /* 2^56 */
                                             : (CYL__L)1152921504606846976.0; /* 2^60 */
    const CYL__L hi = CYL__LHI;
    CYL__L HH, band, D, t0, t1, v0, v1;
    int caps = (opts & CYL_CAPS) != 0, sg0, sg1, in0, in1;
    unsigned tf;

    /* the fast path's hand-over of far origins and of an h/2 that rounds; cap planes within
       range (float data in double: H²|a|² <= 2^374 unless rescaled) */
    f->H = h * (CYL__L)0.5;
    HH = f->H * f->H; /* +inf for the infinite tube */
    if (!(ww <= far2 * (HH < r2 ? HH : r2) &&
          (CYL__WIDE || !(f->H + f->H < h || f->H + f->H > h)) &&
          ((CYL__WIDE && !scaled) || !(h <= (CYL__L)CYL__MAXR) || HH * f->aa <= hi * hi)))
        return -1;
    f->na = CYL__LSQRT(f->aa);
    f->Hn = f->H * f->na;
    f->r = r;
    f->sq = 0;
    if (!(f->A > (CYL__L)CYL__PARA * (CYL__L)CYL__PARA * f->aa * dd)) {
        /* parallel (sin² = A/(|a|²|d|²) within the tolerance): the wall is never hit; a cap
           is, where the ray point lies on its disk */
        if (!caps || !(h <= (CYL__L)CYL__MAXR)) return 0;
        tf = CYL_F_PARALLEL;
        sg0 = f->ad > 0 ? -1 : 1;
        sg1 = -sg0;
        t0 = ((CYL__L)sg0 * f->Hn - f->aw) / f->ad;
        t1 = ((CYL__L)sg1 * f->Hn - f->aw) / f->ad;
        in0 = CYL__P(fdisk)(f->m, f->s, f->R2, t0);
        in1 = CYL__P(fdisk)(f->m, f->s, f->R2, t1);
    } else {
        /* D = r²A − P² = A(r² − ρ²): beside the infinite tube below −band, a miss */
        D = CYL__LMADD(r2, f->A, -(P * P));
        band = (CYL__L)CYL__TANG * r2 * f->A;
        if (D < -band) return 0;
        tf = D <= band ? CYL_F_TANGENT : 0u;
        if (tf && (opts & CYL_NO_TANGENT)) return 0;
        {
            CYL__L t[2];
            int sg[2];
            if (CYL__P(qroots)(ray, cyl, f, r, D, MM, ww, tmin, tmax, t, sg)) return -1;
            t0 = t[0];
            t1 = t[1];
            sg0 = sg[0];
            sg1 = sg[1];
        }
        in0 = caps || !sg0;
        in1 = caps || !sg1;
        if (caps) {
            /* the solid: a root beyond a cap plane gives way to that plane's crossing (which
               must still lie on its disk for a grazing contact); both beyond the same plane,
               the tube is met beside the solid */
            if (sg0 * sg1 > 0) return 0;
            if (sg0) {
                t0 = ((CYL__L)sg0 * f->Hn - f->aw) / f->ad;
                in0 = !tf || CYL__P(fdisk)(f->m, f->s, f->R2, t0);
            }
            if (sg1) {
                t1 = ((CYL__L)sg1 * f->Hn - f->aw) / f->ad;
                in1 = !tf || CYL__P(fdisk)(f->m, f->s, f->R2, t1);
            }
        }
    }
    /* in the caller's units (v0, v1 now); a t beyond the API type's range is a miss */
    v0 = t0 * f->tsc;
    v1 = t1 * f->tsc;
    in0 = in0 && v0 >= tmin && v0 <= tmax && CYL__P(labs)(v0) <= (CYL__L)CYL__MAXR;
    /* the second only where it is wanted */
    in1 = in1 && !(in0 && want < 2) && v1 >= tmin && v1 <= tmax &&
          CYL__P(labs)(v1) <= (CYL__L)CYL__MAXR;
    if (want == 0) return in0 || in1;
    {
        int n = 0;
        if (in0) {
            CYL__P(qemit)(ray, cyl, f, t0, sg0, tf & (sg0 ? CYL_F_PARALLEL : ~0u), opts, scaled,
                          &hits[0]);
            n = 1;
        }
        if (in1) {
            CYL__P(qemit)(ray, cyl, f, t1, sg1, CYL_F_INSIDE | (tf & (sg1 ? CYL_F_PARALLEL : ~0u)),
                          opts, scaled, &hits[n]);
            n++;
        }
        if (n == 2) CYL__P(order2)(hits);
        return n;
    }
}

/* The lean path's frame from the caller's data, unscaled (rescale starts from it). */
CYL__INL void CYL__P(qstart)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                            CYL__P(qf) *f, CYL__L *r, CYL__L *h)
{
    *r = (CYL__L)cyl->r;
    *h = (CYL__L)cyl->h;
    f->tsc = f->vsc = 1;
    f->lf[0] = f->lf[1] = 1;
    CYL__P(frame_in)(ray, cyl, f->a, f->d, f->w);
}

#if CYL__WIDE
/* The rescaled frame, out of line: only data beyond the range check come here. */
CYL__SLOW int CYL__P(qscaled)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                              unsigned opts, int want, CYL__N(hit) *hits)
{
    CYL__P(qf) f;
    CYL__L r, h, dd, MM, r2, ww, P, tmin = (CYL__L)ray->tmin, tmax = (CYL__L)ray->tmax;
    CYL__P(qstart)(ray, cyl, &f, &r, &h);
    if (CYL__P(rescale)(ray, cyl, f.a, f.d, f.w, &r, &h, f.lf, &f.tsc, &f.vsc)) return -1;
    if (!CYL__P(qframe)(&f, r, h, tmin, tmax, &dd, &MM, &r2, &ww, &P)) return -1;
    return CYL__P(qbody)(ray, cyl, opts, want, hits, &f, r, h, tmin, tmax, dd, MM, r2, ww, P, 1);
}
#endif

/* The float API computed in double runs the lean path inline for the caller's data and out of
   line for a rescaled frame (qscaled), so that the hot path merges no scaled value into its
   own; the double API rescales in place (an out-of-line copy there is half its code). */
CYL__INL int CYL__P(quick)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts,
                          int want, CYL__N(hit) *hits)
{
    CYL__P(qf) f;
    CYL__L r, h, dd, MM, r2, ww, P, tmin = (CYL__L)ray->tmin, tmax = (CYL__L)ray->tmax;
    int scaled = 0;
    CYL__P(qstart)(ray, cyl, &f, &r, &h);
#if CYL__WIDE
    if (!CYL__P(qframe)(&f, r, h, tmin, tmax, &dd, &MM, &r2, &ww, &P))
        return CYL__P(qscaled)(ray, cyl, opts, want, hits);
#else
    while (!CYL__P(qframe)(&f, r, h, tmin, tmax, &dd, &MM, &r2, &ww, &P))
        if (scaled++ || CYL__P(rescale)(ray, cyl, f.a, f.d, f.w, &r, &h, f.lf, &f.tsc, &f.vsc))
            return -1;
#endif
    return CYL__P(qbody)(ray, cyl, opts, want, hits, &f, r, h, tmin, tmax, dd, MM, r2, ww, P,
                         scaled);
}
#undef CYL__QX
#endif

/* ------------------------------------------------------------------ public functions */

/* The lean path serves every valid option set where the fast path computes in double;
   CYL_PRECISE only where the fast path serves it in double (the float API with an FMA). */
#if CYL__QUICK
CYL__INL int CYL__P(quickok)(unsigned opts)
{
    return !(opts & ~(unsigned)CYL__SUPPORTED) &&
           (!(opts & CYL_PRECISE) || (CYL__WIDE && CYL__LKAHAN));
}
#endif

#if CYL__QUICK && CYL__WIDE
/* The float API computed in double: what the lean path hands over goes to the fast path in
   double first, with CYL_PRECISE's certification whatever the options (a hand-over is rare,
   and an uncertain decision goes on), up to 2^40 radii and half heights; C there comes from
   the exact o − c in double where its rounding could decide a rim. What it cannot certify,
   the double instance's solver answers, with the float API's tangent band and parallel
   tolerance, on the float inputs (exact in double), and its hits are rounded to float (t_err
   rounded up; a t beyond float's range is a miss, a v beyond it saturates). Float's own
   solver would decide with double words of float (about 2^-48), which a ray nearly parallel
   to the axis of a flat disk amplifies by r/(h·sin) past any rim margin. */
CYL__SLOW int CYL__P(wsolve)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                             unsigned opts, int want, CYL__N(hit) *hits)
{
    cyld_ray dr;
    cyld_cylinder dc;
    cyl__d_frame f;
    cyl__d_cand c[2];
    cyld_hit dh[2];
    CYL__R Hu = cyl->h * CYL__C(0.5);
    int i, k, n, kept = 0, sel[2] = {0, 0};
    n = CYL__P(fast)(ray, cyl, opts | CYL_PRECISE, want, hits);
    if (n >= 0) return n;
    CYL__P(todbl)(ray, cyl, &dr, &dc);
    n = cyl__d_solvet(&dr, &dc, opts, (double)CYL__TANG, (double)CYL__PARA, &f, c);
    for (k = 0; k < n && kept < (want < 2 ? 1 : 2); k++)
        if (CYL__P(labs)(c[k].tu) <= (CYL__L)CYL__MAXR) sel[kept++] = k;
    if (want == 0 || !kept) return kept > 0;
    for (k = 0; k < kept; k++) cyl__d_finish(&f, &c[sel[k]], opts, &dr, &dh[k]);
    if (kept == 2) cyl__d_order2(dh);
    if (Hu + Hu > cyl->h) Hu = (cyl->h - CYL__MINR * 2 * CYL__U) * CYL__C(0.5);
    for (k = 0; k < kept; k++) {
        CYL__N(hit) *o = &hits[k];
        double v = dh[k].v;
        o->t = (CYL__R)dh[k].t;
        o->t_err = CYL__P(errup)(dh[k].t_err, dh[k].t, o->t);
        for (i = 0; i < 3; i++) o->n[i] = (CYL__R)dh[k].n[i];
        v = v > (double)Hu ? (double)Hu : (v < -(double)Hu ? -(double)Hu : v);
        if (CYL__P(labs)(v) > (CYL__L)CYL__MAXR) v = v > 0 ? (double)CYL__MAXR : -(double)CYL__MAXR;
        o->v = (CYL__R)v;
        o->part = dh[k].part;
        o->flags = dh[k].flags;
    }
    return kept;
}
#endif

/* The solver's entry points stay out of line: the fast path answers nearly every call, and
   a small public function inlines into the caller's loop, where the options fold. */
#if CYL__QUICK && CYL__WIDE
CYL__SLOW int CYL__P(slow_intersect)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                                     unsigned opts, CYL__N(hit) *hit)
{
    int rc = CYL__P(check)(ray, cyl, opts);
    return rc ? rc : CYL__P(wsolve)(ray, cyl, opts, 1, hit);
}

CYL__SLOW int CYL__P(slow_all)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                               unsigned opts, CYL__N(hit) hits[2])
{
    int rc = CYL__P(check)(ray, cyl, opts);
    return rc ? rc : CYL__P(wsolve)(ray, cyl, opts, 2, hits);
}

CYL__SLOW int CYL__P(slow_occluded)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                                    unsigned opts)
{
    CYL__N(hit) unused; /* want = 0: nothing is written */
    int rc = CYL__P(check)(ray, cyl, opts);
    return rc ? rc : CYL__P(wsolve)(ray, cyl, opts, 0, &unused);
}
#else
CYL__SLOW int CYL__P(slow_intersect)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                                     unsigned opts, CYL__N(hit) *hit)
{
    CYL__P(frame) f;
    CYL__P(cand) c[2];
    int rc = CYL__P(check)(ray, cyl, opts);
    if (rc) return rc;
    if (!CYL__P(solve)(ray, cyl, opts, &f, c)) return CYL_MISS;
    CYL__P(finish)(&f, &c[0], opts, ray, hit);
    return CYL_HIT;
}

CYL__SLOW int CYL__P(slow_all)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                               unsigned opts, CYL__N(hit) hits[2])
{
    CYL__P(frame) f;
    CYL__P(cand) c[2];
    int k, n, rc = CYL__P(check)(ray, cyl, opts);
    if (rc) return rc;
    n = CYL__P(solve)(ray, cyl, opts, &f, c);
    for (k = 0; k < n; k++) CYL__P(finish)(&f, &c[k], opts, ray, &hits[k]);
    if (n == 2) CYL__P(order2)(hits);
    return n;
}

CYL__SLOW int CYL__P(slow_occluded)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                                    unsigned opts)
{
    CYL__P(frame) f;
    CYL__P(cand) c[2];
    int rc = CYL__P(check)(ray, cyl, opts);
    if (rc) return rc;
    return CYL__P(solve)(ray, cyl, opts, &f, c) > 0;
}
#endif

CYL_DEF int CYL__N(intersect)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                              unsigned opts, CYL__N(hit) *hit)
{
    int rc;
    if (!ray || !cyl || !hit) return CYL_E_NULL;
#if CYL__QUICK
    if (CYL__P(quickok)(opts) && (rc = CYL__P(quick)(ray, cyl, opts, 1, hit)) >= 0) return rc;
#endif
    if (CYL__P(fastok)(opts) && (rc = CYL__P(fast)(ray, cyl, opts, 1, hit)) >= 0) return rc;
    return CYL__P(slow_intersect)(ray, cyl, opts, hit);
}

CYL_DEF int CYL__N(intersect_all)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                                  unsigned opts, CYL__N(hit) hits[2])
{
    int n;
    if (!ray || !cyl || !hits) return CYL_E_NULL;
#if CYL__QUICK
    if (CYL__P(quickok)(opts) && (n = CYL__P(quick)(ray, cyl, opts, 2, hits)) >= 0) return n;
#endif
    if (CYL__P(fastok)(opts) && (n = CYL__P(fast)(ray, cyl, opts, 2, hits)) >= 0) return n;
    return CYL__P(slow_all)(ray, cyl, opts, hits);
}

CYL_DEF int CYL__N(occluded)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts)
{
    CYL__N(hit) unused; /* want = 0: the fast path writes no hit */
    int rc;
    if (!ray || !cyl) return CYL_E_NULL;
#if CYL__QUICK
    if (CYL__P(quickok)(opts) && (rc = CYL__P(quick)(ray, cyl, opts, 0, &unused)) >= 0)
        return rc;
#endif
    if (CYL__P(fastok)(opts) && (rc = CYL__P(fast)(ray, cyl, opts, 0, &unused)) >= 0)
        return rc;
    return CYL__P(slow_occluded)(ray, cyl, opts);
}

/* The cylinder from p0 (its low cap center) to p1 (high cap center). c, a and h are rounded
   once each; |p1 − p0| is computed with an exact power-of-two prescale, so it neither
   overflows nor underflows. NULL ends give the zero axis (CYL_E_ZERO_AXIS at use). */
CYL_DEF CYL__N(cylinder) CYL__N(from_segment)(const CYL__R p0[3], const CYL__R p1[3], CYL__R r)
{
    CYL__N(cylinder) cy;
    CYL__R m, x[3];
    int i, k;
    for (i = 0; i < 3; i++) {
        cy.c[i] = p0 && p1 ? p0[i] * CYL__C(0.5) + p1[i] * CYL__C(0.5) : 0;
        cy.a[i] = p0 && p1 ? p1[i] - p0[i] : 0;
    }
    cy.r = r;
    m = CYL__P(amax3)(cy.a);
    if (m > 0 && m <= CYL__MAXR) {
        k = CYL__P(ilogb)(m);
        for (i = 0; i < 3; i++) x[i] = CYL__P(scale)(cy.a[i], -k);
        cy.h = CYL__P(scale)(CYL__SQRTR(CYL__P(dot)(x, x)), k);
    } else {
        cy.h = m; /* 0, or the non-finite value that intersect will report */
    }
    return cy;
}

/* This instance's parameters, so that the next one can define its own. */
#undef CYL__BODY
#undef CYL__R
#undef CYL__UINT
#undef CYL__N
#undef CYL__P
#undef CYL__C
#undef CYL__SQRTR
#undef CYL__FMAR
#undef CYL__FABSR
#undef CYL__U
#undef CYL__MAXR
#undef CYL__MINR
#undef CYL__MANT
#undef CYL__EBIAS
#undef CYL__EMASK
#undef CYL__TWO_MANT
#undef CYL__TANG
#undef CYL__TBAND
#undef CYL__PARA
#undef CYL__RDIR
#undef CYL__RLEN
#undef CYL__RCOARSE
#undef CYL__L
#undef CYL__LU
#undef CYL__LMIN
#undef CYL__LMAX
#undef CYL__LSQRT
#undef CYL__LABS
#undef CYL__LFMA
#undef CYL__LMADD
#undef CYL__LKAHAN
#undef CYL__LHI
#undef CYL__LDIR
#undef CYL__QUICK
#undef CYL__WIDE
#undef CYL__LD
#undef CYL__FASTQ

#if CYL__NOCONTRACT
#pragma GCC pop_options
#endif
#undef CYL__NOCONTRACT
#endif /* CYL__BODY */

/* NOTES (cited from the code as N1 .. N11)
   ==========================================
   u = 2^-24 (float), 2^-53 (double). The method, with a source for each step:
   N1. Exact power-of-two prescaling (from the exponent bits, no libm) of a, d and the lengths
        o − c, r when they are outside a safe range, so nothing overflows or underflows for
        finite inputs whose answer is representable; arithmetic is equivariant under it, so a
        scene scaled by 2^k gives the same bits (tests check 2^±50 float, 2^±400 double).
   N2. o − c exactly as a double word (Knuth's TwoSum); cross products s = a × d and
        m = a × (o − c) as double words from FMA TwoProducts (never projections: no
        cancellation for rays near the axis direction or origins far along it).
   N3. Geometric discriminant B² − AC = |a|²·D, D = r²|s|² − P², P = (o − c)·s (Ray Tracing
        Gems, ch. 7; pbrt-v4 cylinders), with P compensated (Ogita, Rump, Oishi, "Accurate sum
        and dot product", SIAM J. Sci. Comput. 26, 2005): no difference of large squares when
        the origin is far. For an origin on the surface (C ≈ 0) the other form is the better
        one: B² − AC errs by about u|a||w||s|·|B| and |a|²D by u·r²|a|²A, which near tangency
        (|B| ≈ √e·r|a||s| there) is 1/√e times more.
   N4. Stable root pairing q = −(B + sgn(B)√Δ), t = q/A and C/q (Numerical Recipes §5.6),
        then one exact-quadratic correction of the returned root, δ from f(t + δ) = 0 with
        the residual f(t) = |m + t s|² − r²|a|² summed in compensated arithmetic.
   N5. Caps by clipping the wall interval with the slab between the cap planes (Cychosz and
        Waggenspack, Graphics Gems IV): watertight at the rim. The plane crossings
        (∓H|a| − a·w)/(a·d) use double-word a·d, a·w and |a|, since both cancel.
   N6. t_err: the residual f is evaluated at the returned t with a bound on its rounding
        error (standard model, Higham, "Accuracy and Stability of Numerical Algorithms",
        ch. 3), and the root nearest t of the exact quadratic f(t + δ) = f + f'δ + Aδ² is
        bounded by min(2F/|f'|, √(F/A)), F = |f| + its error bound. Near tangency this is the
        inherent √ term. Caps: the same with the plane's linear residual.
   N7. CYL_PRECISE: B, C and D compensated too; both roots corrected before the rim is
        decided from the sign of a compensated a·x(t) ± H|a|.
   N8. The fast path's t_err: componentwise bounds on the errors of s = a × d and m = a × w
        (the latter including the rounding of o − c) give one on y = m + t·s, hence F >= |f(t)|
        and G <= |f'(t)|/2 (standard model: each operation errs by at most u, an FMA once, so
        the bounds hold with or without contraction); the nearest root of the exact quadratic
        is within F/G where G² > A·F (f' keeps its sign there: the same crossing), else
        √(F/A). A cap: the plane's residual a·x(t) ∓ H|a| over a·d. For the float API computed
        in double, the rounding of t to float is added and the sum rounded up. The lean path
        uses the same argument with norm-wise terms (1-norms for the 2-norms, no square root):
        |δm| <= 4u|a||w|, |δs| <= u|s| for float inputs (exact products), 2u|s| with Kahan's,
        else 3u|a||d|.
   N9. The default path and the precise tier.
   Every call without CYL_PRECISE runs a fast path first: the plain formulas of N3-N5 once, in double for the float API where double is hardware (CYL_FLOAT_WIDE),
   else in the API's own type. Where it computes in double (the double API; the float API on
   x86-64, AArch64 and the like) it is the lean path: one range check that also validates,
   cross products from plain FMA products for float inputs (exact in double) and from Kahan's
   for double ones, no live value it does not need, a normal from (a × x) × a, and the
   residual bound of N8, also in double. For the double API (and the float API computed in
   float) the crossing is then corrected from double words: a wall root by the exact-quadratic
   step of N4, a cap crossing as in N5; so t is about an ulp in both APIs. There, for
   an origin on the surface within the roundings (a secondary ray), C = f(0) is formed from the
   exact o − c first, so the crossing near t = 0 is decided from an accurate value, and the
   roots take √(B² − AC) with it (N3: there it errs by about u/√e, √(|a|²D) by u/e); and in
   every API it is wherever the rounding of C could move the root C/q across a rim (or, in the
   double API, an end of the t range): that root moves by about u·r/sin of the angle to the
   axis, and a flat disk (h far below r) multiplies that by r/h in units of its rim margin. Its
   decisions (tangency, rim, tmin/tmax) carry the plain roundings: within a few ulps of a
   threshold they can go either way, and farther for origins far from the axis (the rounding
   of o − c is about u·|o − c|/r of e). t_err is rigorous on every path (N8). Inputs
   outside the range where nothing overflows or underflows are first scaled by powers of two.
   The compensated solver of N1-N7 answers alone for invalid input, degenerate cases, an
   h/2 that rounds, and origins farther than 2^30 radii or half heights (2^12 when the fast
   path computes in float), where the rounding of o − c alone would be 2^-23 (2^-12) of e or
   of the rim margin. In the float API computed in double, whatever the lean path hands over
   first goes to the fast path in double with CYL_PRECISE's certification (below), up to 2^40
   radii and half heights, and what that cannot certify to the double API's solver, run on the
   float inputs with the float tolerances: no decision of the float API is then taken in float
   arithmetic (float's double words, about 2^-48, are what a flat disk defeats, see Extreme
   ratios).
   CYL_PRECISE starts on the fast path too, but certifies every decision: each is taken only
   where the computed value is farther from its threshold than an a-priori bound on its error
   (the parallel test, D against the tangent band, each root against the rims, each crossing
   against tmin and tmax, and a start close enough for the final correction). Where one
   correction step is not enough (the plain √(|a|²D) errs by about D's error, large near
   tangency), one step takes √(G² − A·F) from its own residual instead, which errs by about the
   error of f', and certifies itself by a bound computed after the fact; failing that, up to
   six steps with the plain √, then the solver. Near the tangent band the plain D errs by
   about the band's width, so A, B, C and D are formed again from double words: a crossing
   that then shows clearly, or a contact certainly inside the band, is answered there (two
   roots, corrected like any other; or none, D < 0, and both ends at the point of closest
   approach −B/A, as the solver gives them). Anything closer, and every parallel contact, go
   to the compensated solver, with every wall coefficient compensated and the rim decided
   from the corrected roots (N7). A crossing whose bound shows it within the t-range
   band of tmin or tmax, 2^-(p−8)·max(|t|, r/|d|) (p = 24, 53), is kept or dropped as the plain
   comparison says: either answer is right there, as for the tangent band. That decides the
   t ≈ 0 crossing of a secondary ray (an origin on the surface, tmin = 0) without the solver
   wherever its bound is that small. For the float API computed in double with a hardware FMA the
   bound is global (and the lean path serves it): |o − c| below 2^28 r and 2^28 h/2 keeps
   double's roundings under 2^-20 of every margin, inside float's band of 2^-16, except for
   the rim of the root C/q, which the lean path tests (see above) and hands over where C's
   rounding could decide it; farther origins go to the fast path's certification.

   N10. Why these tolerances. Tangent: the default path computes e with an absolute error of a
   few u times (1 + |o − c|/r) (see the error analysis at the wall solver), so 256u =
   2^-(p−8) classifies every contact whose |e| exceeds it correctly for origins within tens
   of radii (everywhere on CYL_PRECISE), and it is the band inside which the tests accept
   either answer. Parallel: below sin = u a half-ulp change of one
   component of d makes it exactly parallel. That is not true of every such ray: a ray from
   the wall can cross it again a few dozen radii along, a crossing the inputs determine (a × d
   is exact for an axis-aligned a), which the float API then drops: a limit of this rule,
   pinned by test_parallel_rule_drops_secondary_ray_from_wall in tests/contract/tangent.c.

   N11. Extreme ratios: when r is below 2^-31 (float computed in float) or 2^-435 (double, and so
   out of reach of float inputs computed in double) of |o − c|, r² underflows in the frame:
   the wall test then compares distances linearly, may misjudge rays within the rounding of
   o − c of the axis, and reports t_err = +inf; when h/2 exceeds |o − c| and r by
   more than 2^123 (float) or 2^1019 (double), the cap planes are computed at a coarser scale
   of their own and cap hits carry t_err = +inf. Flat disks: for an origin on the wall and a
   ray nearly parallel to the axis, the crossing near t = 0 is decided against the rim with
   an error of about X = r/(h·sin) times the solver's double words, 2^-106·X in the double
   API and the float API computed in double, 2^-46·X in float-only builds (CYL_FLOAT_WIDE =
   0), relative to the rim margin, times up to about 2^10: past X of about 2^50 (double),
   2^80 (float computed in double) or 2^20 (float only) the rim can go either way on every
   path, CYL_PRECISE included. The bench's flat family (X up to 2^83 in double, 2^54 in
   float) finds them only in a float-only build.
   Conditioning: near tangency a relative input change ε moves t by about √ε·r/(|d|·sin);
   on the default path the rounding of D (about u·|o − c|/r relative to e) decides hit or
   miss for origins beyond about 1/(256u) radii; CYL_PRECISE removes that term.

*/
