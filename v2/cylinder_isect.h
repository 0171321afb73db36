/* cylinder_isect.h - v2.0.0 (in development beside v1) - ray/cylinder intersection, C99, one header.

   Ray against a finite cylinder given by center c, axis a, radius r and height h: open tube,
   capped solid or infinite tube; nearest hit, both crossings, or a shadow-ray test. No
   allocation, no global state, no I/O. Every hit carries a rigorous bound on its t.

   QUICK START
       #include "cylinder_isect.h"

       cyld_ray ray = {{-5, 0.5, 0.25}, {1, 0, 0}, 0, 100};   // origin o, direction d, tmin, tmax
       cyld_cylinder cyl = {{0, 0, 0}, {0, 0, 1}, 1, 2};      // center c, axis a, radius r, height h
       cyld_hit hit;
       int rc = cyld_intersect(&ray, &cyl, CYL_CAPS, &hit);   // nearest hit of the capped solid
       if (rc == CYL_HIT)
           printf("t = %.17g +- %.2g\n", hit.t, hit.t_err);
       else if (rc < 0)
           printf("error: %s\n", cyl_strerror(rc));

   No implementation macro: every function is `static inline` (CYL_DEF). cylf_* is the float
   API, cyld_* the double one, one body included twice. Link with -lm (or -fno-math-errno).

   CONTRACT
   Geometry. The surface is the set of points at distance r from the axis line through c whose
   axial coordinate v = â·(x − c) lies in [−h/2, h/2]; â = a/|a|. The cap at c − â·h/2 is
   CYL_CAP_LOW, the one at c + â·h/2 is CYL_CAP_HIGH. a may have any nonzero length; only its
   direction counts. h = +INFINITY is the infinite tube (CYL_CAPS then changes nothing).
   Default: the open tube (curved wall only); CYL_CAPS: the solid capped cylinder.
   Ray. x(t) = o + t·d, d of any nonzero length, t in units of d; accepted t in [tmin, tmax]
   (inclusive; ±INFINITY allowed). Hits whose t is not representable count as misses.

   int cylf_intersect(const cylf_ray*, const cylf_cylinder*, unsigned opts, cylf_hit *hit)
       The nearest hit with tmin <= t <= tmax: CYL_HIT and *hit filled, CYL_MISS, or a negative
       CYL_E_* code; on a miss or an error *hit is not touched. Outputs must not overlap inputs.
   int cylf_intersect_all(ray, cyl, opts, cylf_hit hits[2])
       Every hit in range, sorted by t (open tube: both wall crossings; capped solid: entry and
       exit): the count (0, 1, 2) or an error; hits[i >= count] untouched.
   int cylf_occluded(ray, cyl, opts)      1 if anything is hit in range, 0 if not, or an error.
   cylf_cylinder cylf_from_segment(const float p0[3], const float p1[3], float r)
       The cylinder from p0 (low cap) to p1 (high cap); p0 == p1 gives a = 0 and h = 0, which
       intersect reports as CYL_E_ZERO_AXIS.
   const char *cyl_strerror(int code)     a short English description of any return value.

   The hit. t; t_err: the exact intersection of the given (already rounded) inputs with the
   reported part lies in [t − t_err, t + t_err] (a rigorous bound, N5); n: unit normal, facing
   the ray origin (n·d <= 0) by default, the outward one with CYL_OUTWARD; v: axial coordinate,
   within [−h/2, h/2] (exactly ±h/2 on a cap; saturated at the largest finite value on an
   infinite tube); part: CYL_SIDE, CYL_CAP_LOW, CYL_CAP_HIGH; flags:
     CYL_F_INSIDE    the ray meets the surface from inside (it leaves the solid, or crosses the
                     wall outward: an origin inside gets this on its first hit);
     CYL_F_TANGENT   a grazing wall contact: e = 1 − ρ²/r² within ±CYL_TANGENT_TOL, ρ the
                     distance between the ray line and the axis line. It counts as a hit (both
                     crossings, at or near the same t) unless CYL_NO_TANGENT; t is then only
                     determined to about √u (N6), and t_err says so.
     CYL_F_PARALLEL  sin(angle between d and a) <= CYL_PARALLEL_TOL: the wall is never hit;
                     with CYL_CAPS a cap is hit where the ray point lies inside its disk. A wall
                     crossing such a ray's inputs do determine is dropped too (N7).
   A hit exactly on the rim (the circle where wall and cap meet) is reported as CYL_SIDE.
   Decisions (hit or miss, part, tangent, rim, t range) are taken with plain comparisons: each
   is right where its margin exceeds the working type's rounding of the quantities it compares
   (N6); nearer than that either answer may come, and t_err still holds for the part reported.
   CYL_PRECISE takes them certified (N9) or on the exact path's compensated values (N8): right
   wherever the margin exceeds a few ulps of the tangent band's e, of t or of the slab ends.

   Errors, checked in this order; *hit is never touched on an error:
     CYL_E_NULL (-1) a NULL pointer            CYL_E_RADIUS (-5) r <= 0, NaN or infinite
     CYL_E_NONFINITE (-2) NaN/inf in o, d, c, a CYL_E_HEIGHT (-6) h <= 0 or NaN
     CYL_E_ZERO_DIR (-3) d == 0                 CYL_E_TRANGE (-7) tmin > tmax, or a NaN
     CYL_E_ZERO_AXIS (-4) a == 0                CYL_E_OPTION (-8) unknown or compiled-out bit

   OPTIONS (bits of opts)
     CYL_CAPS          solid capped cylinder instead of the open tube
     CYL_OUTWARD       outward normal instead of the ray-facing one
     CYL_NO_TANGENT    grazing contacts within the tangent tolerance are misses
     CYL_PRECISE       decisions certified: each taken on the hot path only where its
                       margin exceeds an a-priori bound on its error (N9), else on the exact
                       path's compensated residuals (N8); the double API's t then takes
                       N8's compensated Newton step; `make cost` gives the price
     CYL_NO_NORMAL     skip the normal: hit.n = {0, 0, 0}
     CYL_NO_ERRBOUND   skip the bound: hit.t_err = +INFINITY
     CYL_TRUSTED       skip input validation (NULL and option checks remain): the caller
                       guarantees finite inputs, nonzero d and a, r > 0, h > 0, tmin <= tmax
   Pass options as constants: the entry points are forced inline (CYL_DEF), so the code of an
   option not given folds away at each call site.

   CONFIGURATION (define before including)
     macro                 default                      effect
     CYL_NO_FLOAT          undefined                    leave out cylf_* (and its code)
     CYL_NO_DOUBLE         undefined                    leave out cyld_*: no double anywhere
     CYL_NO_PRECISE        undefined; defined with      compile out CYL_PRECISE (the bit then
                           CYL_NO_DOUBLE                returns CYL_E_OPTION) and N8's steps
     CYL_DEF               static inline (forced, gcc   qualifier of every public function;
                           and clang but at -O0, -Os)   `static inline` lets calls share code
     CYL_SQRTF, CYL_SQRT   the instruction (x86-64,     square roots
                           AArch64), sqrt[f] otherwise
     CYL_FMAF, CYL_FMA     __builtin_fma[f] or fma[f]   the exact path's fused multiply-add
     CYL_FLOAT_WIDE        1 where double is hardware   the float API computes in double (the
                           (x86-64, AArch64, ARM with   same body, another working type); 0: in
                           VFP-D, RV64D, s390x, ppc64)  float (always so with CYL_NO_DOUBLE)
     CYL_FMA_DISPATCH      1 on x86-64 (gcc, clang)     CYL_PRECISE calls run a copy built for
                           built without -mfma          the FMA where the CPU has it; 0: never
     CYL_TANGENT_TOLF      2^-16 = 2^-(24-8)            tangent band on e = 1 − ρ²/r²
     CYL_TANGENT_TOL       2^-45 = 2^-(53-8)
     CYL_PARALLEL_TOLF     2^-24 = u (float)            parallel bound on sin(angle)
     CYL_PARALLEL_TOL      2^-53 = u (double)
     CYL_HEADER_FILENAME   "cylinder_isect.h"           how this file includes itself
   Gone in v2 (#error): CYL_NO_FAST_PATH and CYL_INTERNAL (one path, internals follow CYL_DEF).

   ACCURACY
   `make report V=2` (MPFR reference, 6000 cases per family, caps on and off, seed 20261122):
   t_err held the exact t on all 510,492 float and 521,305 double hits; nothing misclassified
   beyond the band, default or CYL_PRECISE. t on well-conditioned hits: CYL_PRECISE within
   0.5 ulps in every family, both APIs, at 341 and 603 instructions per capped call (float,
   double): 4.46 and 7.96 times the end-point routine's (REPORT, x86-64-v3; -O2: 2.98, 5.10).
   Default: float within 0.5 ulps; double within 0.5 on the tiny and huge families (2^∓400:
   the exact path's N8 steps), on the hot path within 7 ulps on the well family's walls, 14.4
   on its caps (z0 + Ha cancels, N6), 271 for origins far along the axis (thin). Per unit of
   the data's condition κ (o − c, d, a, r, h each moved by a relative u move t by κ·u·|t|;
   REPORT's ulps/κ) double errs by at most 1.7 on those families, 2.7 on all.

   NOT DONE: ray packets or batches, BVHs, oblique cylinders or cones, texture coordinates beyond
   v, nudging spawned rays (use tmin or the previous hit's t_err). Needs IEEE-754 with
   FLT_EVAL_METHOD == 0 and no -ffast-math (both refused by #error).

   LICENSE: MIT. Copyright (c) 2026 the cylinder_isect developers.
*/
#if !defined(CYL__P) /* the header; with CYL__P defined, one body (below) */
#ifndef CYLINDER_ISECT_H
#define CYLINDER_ISECT_H

#define CYL_VERSION_MAJOR 2
#define CYL_VERSION_MINOR 0
#define CYL_VERSION_PATCH 0

#if defined(__FAST_MATH__)
#error "cylinder_isect.h: -ffast-math reorders the operations its error bounds rely on; build this translation unit without it"
#endif
#if defined(CYL_NO_FLOAT) && defined(CYL_NO_DOUBLE)
#error "cylinder_isect.h: CYL_NO_FLOAT and CYL_NO_DOUBLE together leave nothing"
#endif
#if defined(CYL_NO_FAST_PATH) || defined(CYL_INTERNAL)
#error "cylinder_isect.h: CYL_NO_FAST_PATH and CYL_INTERNAL are gone in v2 (one path; internals follow CYL_DEF's call site): remove them"
#endif
#include <float.h>
#include <stddef.h>
#include <stdint.h>
#if !defined(FLT_EVAL_METHOD) || !(FLT_EVAL_METHOD == 0 || FLT_EVAL_METHOD == 16 || FLT_EVAL_METHOD == 32)
#error "cylinder_isect.h: needs FLT_EVAL_METHOD == 0 (no excess precision, e.g. x87); use SSE2, or -fexcess-precision=fast"
#endif

/* CYL__INL forced inline when optimizing for speed: constant options fold at every call site (gcc keeps
   an entry point called from several places out of line otherwise). CYL__ALWAYS at -Os too (stack). */
#if (defined(__GNUC__) || defined(__clang__)) && defined(__OPTIMIZE__)
#define CYL__ALWAYS static inline __attribute__((always_inline))
#else
#define CYL__ALWAYS static inline
#endif
#if (defined(__GNUC__) || defined(__clang__)) && defined(__OPTIMIZE__) && !defined(__OPTIMIZE_SIZE__)
#define CYL__INL CYL__ALWAYS
#define CYL__HANDBACK 0
#define CYL__UNROLL8 CYL__UNROLL
#else /* the frame in memory: the exact path fills it, its caller answers it (one frame, less stack) */
#define CYL__INL static inline
#define CYL__HANDBACK 1
#define CYL__UNROLL8 /* N8's loops rolled for size; the frame's unrolled (its pairs then leave the stack) */
#endif
#ifndef CYL_DEF
#define CYL_DEF CYL__INL
#endif
#if defined(__GNUC__) || defined(__clang__)
#define CYL__COLD static __attribute__((noinline, cold, unused))
#define CYL__OUT static __attribute__((noinline, unused))
#else
#define CYL__COLD static
#define CYL__OUT static
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

/* Tolerances (N7). Quotients, since C++11 has no hexadecimal float literals. */
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

/* Environment hooks: builtins where the compiler has them (no header; fma one instruction
   with a hardware FMA), <math.h> otherwise. Square roots as the instruction on x86 and AArch64
   (sqrt() adds an errno branch without -fno-math-errno). CYL__OPAQUE: a float taken as it is,
   CYL__LAUNDER: a pointer whose target's stores are not forwarded; gcc 12's SLP vectorizer
   drops (double)(float) round trips that a caller's conversions and ours pair up (NUMERICS). */
#if defined(__GNUC__) || defined(__clang__)
#define CYL__B(f) __builtin_##f
#define CYL__HUGE __builtin_huge_val()
#define CYL__LAUNDER(p) __asm__("" : "+r"(p))
#if defined(__x86_64__) || defined(__i386__)
#define CYL__OPAQUE(x) __asm__("" : "+x"(x))
#endif
#if defined(__x86_64__)
#define CYL__ROOT(x, f, g) __asm__(CYL__VEX("v") "sqrt" f " %0, " CYL__VEX("%0, ") "%0" : "+x"(x))
/* the two floats at p as a pair of doubles, one instruction (gcc 12 splits the generic form) */
#define CYL__CVT2(x, p) __asm__(CYL__VEX("v") "cvtps2pd %1, %0" : "=x"(x) : "m"(*(const cyl__float2 *)(p)))
typedef struct cyl__float2 { float v[2]; } cyl__float2;
#elif defined(__aarch64__)
#define CYL__OPAQUE(x) __asm__("" : "+w"(x))
#define CYL__ROOT(x, f, g) __asm__("fsqrt %" g "0, %" g "0" : "+w"(x))
#endif
#else
#include <math.h>
#include <string.h>
#define CYL__B(f) f
#define CYL__HUGE HUGE_VAL
#define CYL__LAUNDER(p) (void)0
#endif
#if defined(__clang__) || (defined(__GNUC__) && __GNUC__ >= 8) /* gcc -O2 keeps 3-trip loops */
#define CYL__UNROLL _Pragma("GCC unroll 3")
#else
#define CYL__UNROLL
#endif
#ifndef CYL__OPAQUE
#define CYL__OPAQUE(x) (void)0
#endif
/* A pair of L (N1): a vector on x86-64 and AArch64, else a struct run lane by lane (CYL__EACH). */
#if (defined(__GNUC__) || defined(__clang__)) && (defined(__SSE2__) || defined(__aarch64__)) && \
    !defined(CYL__PAIR_STRUCT)
#define CYL__PAIR(L, name) typedef L name __attribute__((vector_size(2 * sizeof(L))))
#define CYL__EACH(x) x
#define CYL__V(p) (p)
#define CYL__LANE(p, i) (p)[i]
#else
#define CYL__PAIR(L, name) typedef struct { L v[2]; } name
#undef CYL__CVT2 /* it writes a vector */
#define CYL__EACH(x) do { int k_ = 0; x; k_ = 1; x; } while (0)
#define CYL__V(p) (p).v[k_]
#define CYL__LANE(p, i) (p).v[i]
#endif
#if defined(__AVX__) /* the VEX form: no SSE/AVX transition */
#define CYL__VEX(x) x
#else
#define CYL__VEX(x)
#endif
#ifdef CYL__ROOT
static inline float cyl__sqrtf(float x) { CYL__ROOT(x, "ss", "s"); return x; }
static inline double cyl__sqrt(double x) { CYL__ROOT(x, "sd", "d"); return x; }
#else
#define cyl__sqrtf(x) CYL__B(sqrtf)(x)
#define cyl__sqrt(x) CYL__B(sqrt)(x)
#endif
#ifndef CYL_SQRTF
#define CYL_SQRTF(x) cyl__sqrtf(x)
#endif
#ifndef CYL_SQRT
#define CYL_SQRT(x) cyl__sqrt(x)
#endif
#ifndef CYL_FMAF
#define CYL_FMAF(a, b, c) CYL__B(fmaf)(a, b, c)
#endif
#ifndef CYL_FMA
#define CYL_FMA(a, b, c) CYL__B(fma)(a, b, c)
#endif

/* CYL_FLOAT_WIDE: the float API's working type is double, where double is hardware. */
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
/* CYL_PRECISE's certified layer and exact path work in double (N9). */
#if defined(CYL_NO_DOUBLE) && !defined(CYL_NO_PRECISE)
#define CYL_NO_PRECISE
#endif
#ifdef CYL_NO_PRECISE
#define CYL__SUPPORTED (CYL_OPTIONS_ALL & ~CYL_PRECISE)
#else
#define CYL__SUPPORTED CYL_OPTIONS_ALL
#endif
/* CYL_FMA_DISPATCH (CONFIGURATION): where CYL_PRECISE calls may use the FMA (N9). */
#if !defined(CYL_FMA_DISPATCH) && defined(__x86_64__) && !defined(__FMA__) && !defined(CYL_NO_PRECISE) && \
    defined(__GNUC__) && !defined(__INTEL_COMPILER) && (!defined(__clang__) || __clang_major__ >= 11)
#define CYL_FMA_DISPATCH 1
#elif !defined(CYL_FMA_DISPATCH)
#define CYL_FMA_DISPATCH 0
#endif

CYL_DEF const char *cyl_strerror(int code)
{
    static const char *const msg[] = {"unknown or compiled-out option bit", /* CYL_E_OPTION (-8) */
        "the t range is empty or NaN (tmin > tmax)", "the height is not positive (NaN or <= 0)",
        "the radius is not a positive finite number", "the cylinder axis a is the zero vector",
        "the ray direction d is the zero vector", "a coordinate of o, d, c or a is NaN or infinite",
        "a pointer argument is NULL", "miss", "hit"};
    return code < CYL_E_OPTION || code > CYL_HIT ? "unknown cylinder_isect return code" : msg[code - CYL_E_OPTION];
}

/* The body's types, names and constants, chosen where it uses them: CYL__IFL(x, y) is x in a
   body whose working type L is double, else y; CYL__IFR likewise for the API's type R. */
#define CYL__CAT(a, b) CYL__CAT_(a, b)
#define CYL__CAT_(a, b) a##b
#define CYL__SEL1(x, y) x
#define CYL__SEL0(x, y) y
#define CYL__IFL(x, y) CYL__CAT(CYL__SEL, CYL__LD)(x, y)
#define CYL__IFR(x, y) CYL__CAT(CYL__SEL, CYL__RD)(x, y)
#define CYL__R CYL__IFR(double, float)
#define CYL__N(x) CYL__IFR(cyld_##x, cylf_##x)
#define CYL__RMAX CYL__IFR(DBL_MAX, FLT_MAX)
#define CYL__RMIN CYL__IFR(DBL_MIN, FLT_MIN)
#define CYL__RSQRT(x) CYL__IFR(CYL_SQRT, CYL_SQRTF)(x)
#define CYL__UINT CYL__IFR(uint64_t, uint32_t)
#define CYL__MANT CYL__IFR(53, 24)
#define CYL__EBIAS CYL__IFR(1023, 127)
#define CYL__TANG CYL__IFR(CYL_TANGENT_TOL, CYL_TANGENT_TOLF)
#define CYL__PARA CYL__IFR(CYL_PARALLEL_TOL, CYL_PARALLEL_TOLF)
#define CYL__L CYL__IFL(double, float)
#define CYL__WIDE (CYL__LD && !CYL__RD) /* L wider than R: the float API computed in double */
#define CYL__LT(x) CYL__IFL(cyl__d_##x, cyl__f_##x)
#define CYL__K(x) CYL__IFL(x, x##f)
#define CYL__LMAX CYL__IFL(DBL_MAX, FLT_MAX)
#define CYL__LU (CYL__IFL(DBL_EPSILON, FLT_EPSILON) / 2)
#define CYL__LSQRT(x) CYL__IFL(CYL_SQRT, CYL_SQRTF)(x)
#define CYL__LABS(x) CYL__IFL(CYL__B(fabs), CYL__B(fabsf))(x)
#define CYL__LFMA(a, b, c) CYL__IFL(CYL_FMA, CYL_FMAF)(a, b, c)
#define CYL__LSPLIT CYL__IFL(134217729.0, 4097.0f) /* 2^27 + 1, 2^12 + 1 */
#define CYL__LTINY CYL__IFL(4.9406564584124654e-324, 1.40129846e-45f) /* 2^-1074, 2^-149 */
#define CYL__HOT_LO CYL__IFL(4.9090934652977266e-91, 8.67361738e-19f) /* range, N2: 2^-300, 2^-60 */
#define CYL__HOT_HI CYL__IFL(2.9073548971824276e135, 1.15292150e18f) /* 2^450, 2^60 */
#define CYL__COLD_LO CYL__IFL(2.4099198651028841e-181, 1.32348898e-23f) /* scaled r²|a|²: 2^-600, 2^-76 */
#define CYL__LINF ((CYL__L)CYL__HUGE) /* not LMAX * 2: gcc computes that at run time */
/* The certified layer runs (N9): CYL_PRECISE asked for and compiled in (it folds away
   without, opts constant or not); what answer returns when it is not sure. */
#define CYL__CERT(f, opts) (((opts) & CYL__SUPPORTED & CYL_PRECISE) && !(f)->cold)
#define CYL__DOUBT (-100)
/* Which cap plane slab end k lies on (a macro: gcc 12 folded the inline function less well). */
#define CYL__CAP_PART(f, k) (((k) == 0) == !((f)->zeta < 0) ? CYL_CAP_LOW : CYL_CAP_HIGH)

/* One body per API, parameters (#undef'd by it): CYL__P its private names, CYL__RD 1 if its type
   R is double, CYL__LD 1 if its working type L is. A helper body (CYL__HELPER, N9): an API's in
   another type or instruction set, taking CYL_PRECISE calls as CYL__HANDOFF_IF. */
#ifndef CYL_NO_DOUBLE
#define CYL__RD 1
#define CYL__LD 1
#define CYL__P(x) cyl__d_##x
#if CYL_FMA_DISPATCH
#define CYL__HANDOFF(x) cyl__dx_##x
#define CYL__HANDOFF_IF(want) ((want) > 0 && __builtin_cpu_supports("fma")) /* polish: N8 */
#endif
#include CYL_HEADER_FILENAME
#endif

#ifndef CYL_NO_FLOAT
#define CYL__RD 0
#define CYL__P(x) cyl__f_##x
#define CYL__LD CYL_FLOAT_WIDE
#if !CYL_FLOAT_WIDE && !defined(CYL_NO_PRECISE)
#define CYL__HANDOFF(x) cyl__fw_##x
#define CYL__HANDOFF_IF(want) 1
#elif CYL_FMA_DISPATCH
#define CYL__HANDOFF(x) cyl__fx_##x
#define CYL__HANDOFF_IF(want) __builtin_cpu_supports("fma")
#endif
#include CYL_HEADER_FILENAME
#if !CYL_FLOAT_WIDE && !defined(CYL_NO_PRECISE)
#define CYL__HELPER 1 /* the float API's body in double, private: its CYL_PRECISE calls */
#define CYL__RD 0
#define CYL__P(x) cyl__fw_##x
#define CYL__LD 1
#include CYL_HEADER_FILENAME
#endif
#endif

#if CYL_FMA_DISPATCH /* the APIs' bodies built for the FMA, private: CYL_PRECISE calls (N9) */
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("fma"))), apply_to = function)
#pragma float_control(push)
#pragma clang fp contract(off)
#else
#pragma GCC push_options
#pragma GCC target("fma")
#pragma GCC optimize("fp-contract=off", "no-tree-slp-vectorize")
#endif
#define CYL__HELPER 1
#define CYL__RD 1
#define CYL__LD 1
#define CYL__P(x) cyl__dx_##x
#define CYL__LFASTFMA 1
#include CYL_HEADER_FILENAME
#if !defined(CYL_NO_FLOAT) && CYL_FLOAT_WIDE
#define CYL__HELPER 1
#define CYL__RD 0
#define CYL__LD 1
#define CYL__P(x) cyl__fx_##x
#define CYL__LFASTFMA 1
#include CYL_HEADER_FILENAME
#endif
#if defined(__clang__)
#pragma float_control(pop)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
#endif

#endif /* CYLINDER_ISECT_H */

#else /* CYL__P: one precision's body, written once */

/* CYL__X: the names of the exact path (N8), the frame type's and its functions', which depend on L
   alone: the float API computed in double shares the double API's (with the FMA: its helper's). */
#if CYL__WIDE && defined(CYL__LFASTFMA)
#define CYL__X(x) cyl__dx_##x
#elif CYL__WIDE
#define CYL__X(x) cyl__d_##x
#else
#define CYL__X(x) CYL__P(x)
#define CYL__XOWN
#endif

#ifndef CYL__HELPER /* the public types (a helper body has its API's already) */
typedef struct CYL__N(ray) { CYL__R o[3], d[3], tmin, tmax; } CYL__N(ray);
typedef struct CYL__N(cylinder) { CYL__R c[3], a[3], r, h; } CYL__N(cylinder);
typedef struct CYL__N(hit) { CYL__R t, t_err, n[3], v; int part; unsigned flags; } CYL__N(hit);
#endif
#ifdef CYL__HANDOFF
static int CYL__HANDOFF(out)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts, int want, CYL__N(hit) *hits);
#endif

/* The frame (N1): the inputs in L, scaled on the exact path (t, v there 2^et, 2^ev times the
   frame's), and everything derived from them once; set by the exact path alone: et, ev, exact,
   rmin, rmax (the caller's t range) and tc (the closest approach). */
#ifndef CYL__XOWN
typedef CYL__X(frame) CYL__P(frame);
#else
typedef struct CYL__P(frame) {
    CYL__L w[3], wl[3], d[3], a[3], r, H, tmin, tmax, rmin, rmax;
    CYL__L s[3], m[3], aa, ad, mm, aww, A, B, P, D, r2, r2aa, z0, zeta, sqaa, Ha, tc;
    int et, ev;
    unsigned char exact, cold, par; /* cold: the exact path's (FMA products, unscaled output) */
} CYL__P(frame);
static void CYL__P(refine)(const CYL__P(frame) *f, CYL__L v[4], CYL__L *l);
static CYL__L CYL__P(polish)(const CYL__P(frame) *f, CYL__L t, int part, CYL__L gap, CYL__L *lo);
#endif

/* One crossing of the ray with the surface; h: ∓√(|a|²D) at a wall (entry −, exit +). */
typedef struct CYL__P(cross) { CYL__L t, h; int part, ok, doubt; unsigned flags; } CYL__P(cross);

/* ------------------------------------------------------------------ small tools */
CYL__INL CYL__L CYL__P(abs)(CYL__L x) { return CYL__LABS(x); }
CYL__INL CYL__L CYL__P(max)(CYL__L x, CYL__L y) { return x > y ? x : y; }
CYL__INL CYL__L CYL__P(min)(CYL__L x, CYL__L y) { return x < y ? x : y; }
CYL__INL CYL__L CYL__P(dot)(const CYL__L x[3], const CYL__L y[3]) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }
CYL__INL void CYL__P(cross3)(const CYL__L x[3], const CYL__L y[3], CYL__L z[3])
{ z[0] = x[1] * y[2] - x[2] * y[1], z[1] = x[2] * y[0] - x[0] * y[2], z[2] = x[0] * y[1] - x[1] * y[0]; }
/* z = x·p + y·q, componentwise, written out (no loop: the frame stays in registers). */
CYL__ALWAYS void CYL__P(lin)(CYL__L p, const CYL__L x[3], CYL__L q, const CYL__L y[3], CYL__L z[3])
{ z[0] = x[0] * p + y[0] * q, z[1] = x[1] * p + y[1] * q, z[2] = x[2] * p + y[2] * q; }
/* A pair (N1) and the pair (x, y). */
CYL__PAIR(CYL__L, CYL__P(pair));
CYL__INL CYL__P(pair) CYL__P(pr)(CYL__L x, CYL__L y) { CYL__P(pair) p; CYL__LANE(p, 0) = x, CYL__LANE(p, 1) = y; return p; }
/* x + y − s for s = x + y rounded, exactly (Knuth's TwoSum). */
CYL__INL CYL__L CYL__P(sum_err)(CYL__L x, CYL__L y, CYL__L s) { CYL__L z = s - x; return (x - (s - z)) + (y - z); }
CYL__INL void CYL__P(mul3)(CYL__L p, const CYL__L x[3], CYL__L z[3]) { z[0] = x[0] * p, z[1] = x[1] * p, z[2] = x[2] * p; }
CYL__INL CYL__L CYL__P(amax)(const CYL__L x[3])
{ return CYL__P(max)(CYL__P(max)(CYL__P(abs)(x[0]), CYL__P(abs)(x[1])), CYL__P(abs)(x[2])); }
/* x·2^k for any k, in steps of normal powers of two: only the last step can round. */
static inline CYL__R CYL__P(scale)(CYL__R x, int k)
{
    CYL__UINT b; CYL__R p;
    for (; k > CYL__EBIAS; k -= CYL__EBIAS) x *= 2 / CYL__RMIN;         /* 2^EBIAS */
    for (; k < 1 - CYL__EBIAS; k += CYL__EBIAS - 1) x *= CYL__RMIN;     /* 2^(1 - EBIAS) */
    b = (CYL__UINT)(k + CYL__EBIAS) << (CYL__MANT - 1), CYL__B(memcpy)(&p, &b, sizeof p);
    return x * p;
}

/* floor(log2(x)) for finite x > 0 in R, from the exponent bits (subnormals included). */
static inline int CYL__P(expo)(CYL__R x)
{
    const CYL__UINT m = (CYL__UINT)(2 * CYL__EBIAS + 1) << (CYL__MANT - 1); /* the exponent bits */
    CYL__UINT b; int s = 0;
    if ((CYL__B(memcpy)(&b, &x, sizeof b), (b & m) == 0u) && x > 0) /* a subnormal */
        x *= CYL__P(scale)(1, CYL__MANT), s = CYL__MANT, CYL__B(memcpy)(&b, &x, sizeof b);
    return (int)((b & m) >> (CYL__MANT - 1)) - CYL__EBIAS - s;
}

/* The neighbour of x toward zero in R (x finite, nonzero). */
static inline CYL__R CYL__P(toward0)(CYL__R x)
{ CYL__UINT b; CYL__B(memcpy)(&b, &x, sizeof b), b -= 1u, CYL__B(memcpy)(&x, &b, sizeof x); return x; }

/* ab − cd within 2u of itself (Kahan's algorithm with FMA; Jeannerod, Louvet, Muller 2013). */
CYL__INL CYL__L CYL__P(dop)(CYL__L a, CYL__L b, CYL__L c, CYL__L d)
{ CYL__L w = c * d; return CYL__LFMA(a, b, -w) + CYL__LFMA(-c, d, w); }
/* x × y with each component within 2u of itself (the exact path's: N1). */
CYL__INL void CYL__P(cross_exact)(const CYL__L x[3], const CYL__L y[3], CYL__L z[3])
{ z[0] = CYL__P(dop)(x[1], y[2], x[2], y[1]), z[1] = CYL__P(dop)(x[2], y[0], x[0], y[2]);
  z[2] = CYL__P(dop)(x[0], y[1], x[1], y[0]); }

/* ------------------------------------------------------------------ frame */
/* The inputs in L: w = o − c, d, a, r, H = h/2 (written out: the frame stays in registers). */
CYL__INL void CYL__P(load)(CYL__P(frame) *f, const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl)
{
    f->w[0] = (CYL__L)ray->o[0] - (CYL__L)cyl->c[0], f->d[0] = (CYL__L)ray->d[0], f->r = (CYL__L)cyl->r;
    f->w[1] = (CYL__L)ray->o[1] - (CYL__L)cyl->c[1], f->d[1] = (CYL__L)ray->d[1], f->H = (CYL__L)cyl->h * CYL__K(0.5);
    f->w[2] = (CYL__L)ray->o[2] - (CYL__L)cyl->c[2], f->d[2] = (CYL__L)ray->d[2];
    f->a[0] = (CYL__L)cyl->a[0], f->a[1] = (CYL__L)cyl->a[1], f->a[2] = (CYL__L)cyl->a[2];
}

CYL__INL CYL__L CYL__P(parallel)(const CYL__P(frame) *f);
/* Everything the decisions use, from s = a × d and m = a × w (N1), and the range test (N2) on derived
   values: r, r²|a|², Ha and (hot path) r²A and the margin at least HOT_LO (exact path: COLD_LO; |a|²|d|²
   is by the margin, or by the exact path's scale at least 1); |a|²(|w|² + r²), |a|²|d|² and r²A (>= D)
   summed at most HOT_HI (Ha: no test, N2). Every NaN, infinity, zero or negative of o, d, c, a, r, h fails it. */
CYL__INL int CYL__P(derive)(CYL__P(frame) *f)
{
    CYL__L ml[3], lo; int i;
    CYL__P(pair) dw[3], sm[3], q[3], z, ab, pm; /* lanes: (d, w) give (s, m) */
    dw[0] = CYL__P(pr)(f->d[0], f->w[0]), dw[1] = CYL__P(pr)(f->d[1], f->w[1]), dw[2] = CYL__P(pr)(f->d[2], f->w[2]);
    if (f->cold) { /* s, m to 2u each; w = w + wl exactly there */
        CYL__P(cross_exact)(f->a, f->d, f->s), CYL__P(cross_exact)(f->a, f->w, f->m);
        CYL__P(cross3)(f->a, f->wl, ml), CYL__P(lin)(1, f->m, 1, ml, f->m);
        CYL__UNROLL for (i = 0; i < 3; i++) sm[i] = CYL__P(pr)(f->s[i], f->m[i]);
    } else { /* both cross products at once */
        CYL__EACH(CYL__V(sm[0]) = f->a[1] * CYL__V(dw[2]) - f->a[2] * CYL__V(dw[1]));
        CYL__EACH(CYL__V(sm[1]) = f->a[2] * CYL__V(dw[0]) - f->a[0] * CYL__V(dw[2]));
        CYL__EACH(CYL__V(sm[2]) = f->a[0] * CYL__V(dw[1]) - f->a[1] * CYL__V(dw[0]));
    }
    CYL__UNROLL for (i = 0; i < 3; i++)
        f->s[i] = CYL__LANE(sm[i], 0), f->m[i] = CYL__LANE(sm[i], 1), q[i] = CYL__P(pr)(f->w[i], f->m[i]);
    CYL__EACH(CYL__V(z) = f->a[0] * CYL__V(dw[0]) + f->a[1] * CYL__V(dw[1]) + f->a[2] * CYL__V(dw[2]));
    CYL__EACH(CYL__V(ab) = f->s[0] * CYL__V(sm[0]) + f->s[1] * CYL__V(sm[1]) + f->s[2] * CYL__V(sm[2]));
    CYL__EACH(CYL__V(pm) = CYL__V(q[0]) * CYL__V(sm[0]) + CYL__V(q[1]) * CYL__V(sm[1]) + CYL__V(q[2]) * CYL__V(sm[2]));
    f->zeta = CYL__LANE(z, 0), f->z0 = CYL__LANE(z, 1), f->A = CYL__LANE(ab, 0), f->B = CYL__LANE(ab, 1);
    f->P = CYL__LANE(pm, 0), f->mm = CYL__LANE(pm, 1);
    f->ad = f->A + f->zeta * f->zeta, f->aww = f->mm + f->z0 * f->z0; /* |a|²|d|², |a|²|w|² */
    f->aa = CYL__P(dot)(f->a, f->a), f->r2 = f->r * f->r, f->r2aa = f->r2 * f->aa;
    /* P = w·s = −m·d: with its accurate s and m the exact path takes the one of smaller error */
    if (f->cold && f->aww * f->A > f->mm * f->ad) f->P = -CYL__P(dot)(f->m, f->d);
    f->D = f->r2 * f->A - f->P * f->P; /* B² − AC = |a|²D (N3) */
    f->sqaa = CYL__LSQRT(f->aa), f->Ha = f->H * f->sqaa;
    /* min passes a NaN on only as its second operand (h's is Ha's); the sum passes every one */
    lo = CYL__P(min)(CYL__P(min)(f->r, f->r2aa), f->Ha);
    /* the hot path's margin for the exact path: parallel rays and, unless L makes the inputs'
       products exact, those whose s or m loses 8 bits (N6): d or o − c within 2^-8 of the axis */
    if (!f->cold) lo = CYL__P(min)(CYL__P(min)(CYL__WIDE ? CYL__P(parallel)(f) :
        CYL__P(min)(65536 * f->A - f->ad, 65536 * f->mm - f->aww), f->r2 * f->A), lo);
    return lo >= (f->cold ? CYL__COLD_LO : CYL__HOT_LO) && f->aww + f->r2aa + f->ad + f->r2 * f->A <= CYL__HOT_HI;
}

/* ------------------------------------------------------------------ decisions */
/* Parallel (N7): sin²(d, a) = A/(|a|²|d|²) at most the tolerance's square; as a margin: where <= 0. */
CYL__INL CYL__L CYL__P(parallel)(const CYL__P(frame) *f) { return f->A / ((CYL__L)CYL__PARA * (CYL__L)CYL__PARA) - f->ad; }

/* The wall (N3, N6): 0 the line misses the infinite tube, 1 a tangent contact (e = D/(r²A) in the band), 2 two. */
CYL__INL int CYL__P(classify_wall)(const CYL__P(frame) *f)
{ CYL__L band = (CYL__L)CYL__TANG * (f->r2 * f->A); return f->D > band ? 2 : f->D >= -band; }

/* The wall roots in t order from the stable pair (N4); a contact in the band without a real
   root (D <= 0) is the point of closest approach, twice. Returns √(|a|²D). */
CYL__INL CYL__L CYL__P(wall_roots)(const CYL__P(frame) *f, CYL__L t[2])
{
    CYL__L sq = 0, q, C = f->mm - f->r2aa;
    if (!(f->D > 0)) return t[0] = t[1] = -f->B / f->A, sq;
    sq = CYL__LSQRT(f->aa * f->D);
    if (f->B < 0) q = sq - f->B, t[0] = C / q, t[1] = q / f->A; /* q² >= AC: in order */
    else q = -(f->B + sq), t[0] = q / f->A, t[1] = C / q;
    q = t[0], t[0] = CYL__P(min)(q, t[1]), t[1] = CYL__P(max)(q, t[1]); /* but for rounding */
    return sq;
}

/* The slab between the cap planes, as the t interval [s[0], s[1]] the ray spends in it (N4):
   |z0 + tζ| <= Ha. ζ = ±0 gives (−∞, ∞) or an empty interval; a ray lying in a cap plane gives
   NaN ends, which in_slab reads as inclusive (the rim belongs to the surface). */
CYL__INL void CYL__P(slab)(const CYL__P(frame) *f, CYL__L s[2])
{
    CYL__L p0 = (f->Ha + f->z0) / -f->zeta, p1 = (f->Ha - f->z0) / f->zeta;
    s[0] = CYL__P(min)(p0, p1), s[1] = CYL__P(max)(p0, p1);
}

/* v[i] < v[j], v = (t0, t1, s0, s1) the wall roots and slab ends; pairs v + l on the exact path (N8). */
CYL__INL int CYL__P(before)(const CYL__P(frame) *f, const CYL__L v[4], const CYL__L l[4], int i, int j)
{ return (CYL__SUPPORTED & CYL_PRECISE) && f->cold ? v[i] - v[j] < l[j] - l[i] : v[i] < v[j]; }
/* The rim: is wall root k inside the slab, ends included? */
CYL__INL int CYL__P(in_slab)(const CYL__P(frame) *f, const CYL__L v[4], const CYL__L l[4], int k)
{ return !CYL__P(before)(f, v, l, k, 2) && !CYL__P(before)(f, v, l, 3, k); }

/* N9: x and y not certainly farther apart than their bounds' sum (a NaN bound certifies none). */
CYL__INL int CYL__P(near)(CYL__L x, CYL__L ex, CYL__L y, CYL__L ey)
{ return !(CYL__P(abs)(x - y) > ex + ey); }
/* The t range, ends included (a NaN end: none); run and load_scaled keep it within R's (beyond: no hit). */
CYL__INL int CYL__P(in_range)(const CYL__P(frame) *f, CYL__L t) { return t >= f->tmin && t <= f->tmax; }

/* Crossing k (0 entry, 1 exit) of the wall roots and the slab v (N4): the open tube keeps a
   wall crossing inside the slab; the capped solid clips the wall interval with the slab (entry
   and exit the wall or a cap; a rim point is the wall). ok: it exists, in the t range. e: the
   certified layer's bounds on v (N9); doubt: a comparison within them. */
CYL__ALWAYS CYL__P(cross) CYL__P(crossing)(const CYL__P(frame) *f, unsigned opts, int k, const CYL__L v[4],
                                        const CYL__L *e, const CYL__L l[4], CYL__L sq, unsigned tan)
{
    CYL__P(cross) x;
    CYL__L ex = e ? e[k] : 0;
    x.t = v[k], x.h = k ? sq : -sq, x.part = CYL_SIDE, x.flags = (k ? CYL_F_INSIDE : 0u) | tan;
    x.ok = CYL__P(in_slab)(f, v, l, k);
    x.doubt = e && (CYL__P(near)(v[k], ex, v[2], e[2]) || CYL__P(near)(v[k], ex, v[3], e[3]));
    if (!x.ok && (opts & CYL_CAPS) && (k ? CYL__P(before)(f, v, l, 3, 1) && !CYL__P(before)(f, v, l, 3, 0)
                                         : CYL__P(before)(f, v, l, 0, 2) && !CYL__P(before)(f, v, l, 1, 2))) {
        x.t = v[2 + k], x.ok = 1, x.flags &= ~CYL_F_TANGENT, x.part = CYL__CAP_PART(f, k);
        if (e) ex = e[2 + k], x.doubt |= CYL__P(near)(v[2 + k], ex, v[1 - k], e[1 - k]);
    }
    if (e && x.ok) x.doubt |= CYL__P(near)(x.t, ex, f->tmin, 0) || CYL__P(near)(x.t, ex, f->tmax, 0);
    if (f->par) { /* a parallel ray's cap crossing counts where its point is inside the disk */
        CYL__L y[3];
        CYL__P(lin)(1, f->m, x.t, f->s, y);
        x.ok = x.ok && x.part != CYL_SIDE && CYL__P(dot)(y, y) <= f->r2aa, x.flags |= CYL_F_PARALLEL;
    }
    x.ok = x.ok && CYL__P(in_range)(f, x.t);
    return x;
}

/* ------------------------------------------------------------------ output and bound */
/* The plain layer's error (N9): its quadratic's at t is at most noise·(S + t²|a|²|d|²), S =
   |a|²(|w|² + r²); a wall root t's, h = √(|a|²D), root_bound (k = noise) where that is below h/A. */
CYL__INL CYL__L CYL__P(noise)(const CYL__P(frame) *f)
{ return 128 * CYL__LU * (1 + CYL__LSQRT(f->ad / f->A)); }
CYL__INL CYL__L CYL__P(root_bound)(const CYL__P(frame) *f, CYL__L k, CYL__L t, CYL__L h)
{ return k * (f->aww + f->r2aa + t * t * f->ad) / h + 4 * CYL__LU * CYL__P(abs)(t); }
CYL__INL int CYL__P(first_order)(const CYL__P(frame) *f, CYL__L e, CYL__L h) { return e * f->A <= h; }

/* t_err of a wall crossing (N5): root_bound on a wider L's hot path where far below R's ulp (e: the
   certified layer's, entry then exit), else from the residual F = |y|² − r²|a|², G = y·s at t (y = m + t·s)
   and bounds EF, EG on their rounding: (|F| + EF)/(|G| − EG) near, else the product-of-roots one. */
CYL__INL CYL__L CYL__P(bound_wall)(const CYL__P(frame) *f, const CYL__P(cross) *x, const CYL__L *e)
{
    const CYL__L u = CYL__LU;
    CYL__L y[3], yy, F, G, ny, Ey, Fb, EG, EA, Gb, nd;
    if (CYL__WIDE && !f->cold) {
        const CYL__L h = CYL__P(abs)(x->h);
        Gb = e ? e[x->flags & CYL_F_INSIDE ? 1 : 0] : CYL__P(root_bound)(f, CYL__P(noise)(f), x->t, h); /* first order, 2^-7 of R's ulp */
        if ((e || CYL__P(first_order)(f, Gb, h)) && Gb <= CYL__P(abs)(x->t) * ((CYL__L)CYL__IFR(DBL_EPSILON, FLT_EPSILON) / 128))
            return Gb;
    }
    nd = CYL__LSQRT(f->ad); /* >= |s|: ad is A plus a square */
    CYL__P(lin)(1, f->m, x->t, f->s, y);
    yy = CYL__P(dot)(y, y), ny = CYL__LSQRT(yy), F = yy - f->r2aa, G = CYL__P(dot)(y, f->s);
    /* y's error, widened to cover |y|²'s, r²|a|²'s and y·s's roundings too; s's is u|a||d|'s
       (steep rays: |s| itself scales the rest); |F|'s own rounding: in EA and the factor (N5) */
    Ey = 8 * u * (CYL__LSQRT(f->aww) + ny) + CYL__P(abs)(x->t) * (10 * u * nd), EA = 32 * u * f->ad;
    Fb = CYL__P(abs)(F) + Ey * (2 * ny + Ey), EG = Ey * CYL__LSQRT(f->A) + (ny + Ey) * (5 * u) * nd;
    /* G with the crossing's sign (entry negative), any sign for a tangent contact */
    Gb = (x->flags & CYL_F_TANGENT ? CYL__P(abs)(G) : x->flags & CYL_F_INSIDE ? G : -G) - EG;
    if (Gb > 0 && Gb * Gb >= (f->A + EA) * Fb) return Fb / Gb * (1 + 48 * u);
    if (!(f->A > EA)) return CYL__LINF;
    return (2 * (CYL__P(abs)(G) + EG) + CYL__LSQRT((f->A + EA) * Fb)) / (f->A - EA) * (1 + 48 * u);
}

/* t_err of a cap crossing (N5): the plane's residual z0 + tζ ∓ Ha over |ζ|, both bounded. */
CYL__INL CYL__L CYL__P(bound_cap)(const CYL__P(frame) *f, const CYL__P(cross) *x)
{
    const CYL__L u = CYL__LU, nd = CYL__LSQRT(f->ad);
    CYL__L g = f->z0 + x->t * f->zeta - (x->part == CYL_CAP_HIGH ? f->Ha : -f->Ha);
    CYL__L Eg = 5 * u * (CYL__LSQRT(f->aww) + CYL__P(abs)(x->t) * nd + f->Ha); /* |g|'s: the factor */
    CYL__L den = CYL__P(abs)(f->zeta) - 4 * u * nd;
    return den > 0 ? (CYL__P(abs)(g) + Eg) / den * (1 + 36 * u) : CYL__LINF;
}

/* The unit normal (N5). The wall's outward one is y × a at the crossing, which from the roots
   is P|a|²·s ∓ √(|a|²D)·(a × s) (entry −, exit +): no cancellation for far origins; its length
   follows from P and h alone. A cap's is ±a. The ray-facing one turns at an exit (CYL_F_INSIDE). */
CYL__INL void CYL__P(normal)(const CYL__P(frame) *f, const CYL__N(cylinder) *cyl, const CYL__P(cross) *x,
                             unsigned opts, int side, CYL__L n[3])
{
    CYL__L as[3], a[3], g = (!(opts & CYL_OUTWARD) && (x->flags & CYL_F_INSIDE)) ? -1 : 1, h = x->h, P = f->P, q;
    /* a: the hot path in R's type reads it again from the caller, as operands (the frame's spills) */
    if (f->cold || CYL__WIDE) CYL__P(mul3)(1, f->a, a);
    else { CYL__LAUNDER(cyl); a[0] = (CYL__L)cyl->a[0], a[1] = (CYL__L)cyl->a[1], a[2] = (CYL__L)cyl->a[2]; }
    if (!side) { CYL__P(mul3)(x->part == CYL_CAP_HIGH ? g / f->sqaa : -g / f->sqaa, a, n); return; }
    if (f->cold && (q = CYL__P(max)(CYL__P(abs)(P), CYL__P(abs)(h) / f->sqaa)) > 0)
        P /= q, h /= q; /* the exact path's P² can leave the range (the hot path's cannot, N2) */
    else if (f->cold) h = x->flags & CYL_F_INSIDE ? f->aa : -f->aa; /* P = D = 0 (hot: q >= r²A) */
    q = P * P + h * h / f->aa; /* |P|a|²s ∓ h(a × s)| = |a|²√(Aq) (N5) */
    CYL__P(cross3)(a, f->s, as), q = 1 / CYL__LSQRT(f->A * q);
    CYL__P(lin)(P * q, f->s, -h / f->aa * q, as, n);
    CYL__P(mul3)(g, n, n); /* turned last: the two normals negate bit for bit */
}

/* v of a wall point (N5), kept within the tube's half height. */
CYL__INL CYL__L CYL__P(axial_v)(const CYL__P(frame) *f, CYL__L t)
{ CYL__L v = (f->z0 + t * f->zeta) / f->sqaa; return CYL__P(max)(-f->H, CYL__P(min)(v, f->H)); }

/* The hit in the caller's units and type: t, t_err, v unscaled (exact path), t kept in range,
   t_err widened by t's rounding into R and rounded up, v within h/2 after its rounding. e: N9's bounds. */
CYL__INL void CYL__P(emit)(const CYL__P(frame) *f, const CYL__N(cylinder) *cyl, const CYL__P(cross) *x, const CYL__L *e, unsigned opts,
                          CYL__N(hit) *hit)
{
    CYL__L n[3] = {0, 0, 0}, t = x->t, err = CYL__LINF, v, vlim = 0;
    CYL__R tr, vr, er;
    const int side = !(opts & CYL_CAPS) || x->part == CYL_SIDE; /* the open tube emits walls alone */
    if (!(opts & CYL_NO_ERRBOUND)) err = side ? CYL__P(bound_wall)(f, x, e) : CYL__P(bound_cap)(f, x);
    if (!(opts & CYL_NO_NORMAL)) CYL__P(normal)(f, cyl, x, opts, side, n);
    v = side ? CYL__P(axial_v)(f, t) : (x->part == CYL_CAP_HIGH ? f->H : -f->H);
    if (f->cold || CYL__WIDE) { /* h/2 within R's range; in R itself rounded toward 0 (R's subnormals) */
        vlim = CYL__P(min)(f->cold ? (CYL__L)cyl->h * CYL__K(0.5) : f->H, (CYL__L)CYL__RMAX);
        if (!CYL__WIDE && vlim * 2 > (CYL__L)cyl->h) vlim = (CYL__L)CYL__P(toward0)((CYL__R)vlim);
    }
    if (f->cold) {
        CYL__L t0 = CYL__LT(scale)(t, f->et);
        t = CYL__P(max)(f->rmin, CYL__P(min)(t0, f->rmax));
        err = f->exact && !(opts & CYL_NO_ERRBOUND) ? CYL__LT(scale)(err, f->et) + CYL__LTINY + CYL__P(abs)(t - t0) : CYL__LINF;
        v = CYL__P(max)(-vlim, CYL__P(min)(CYL__LT(scale)(v, f->ev), vlim));
    }
    tr = (CYL__R)t, vr = (CYL__R)v, er = (CYL__R)err;
    if (CYL__WIDE) {
        CYL__OPAQUE(tr);
        if (!(opts & CYL_NO_ERRBOUND)) /* t's rounding to R joins the bound, rounded up in R */
            er = (CYL__R)(err + CYL__P(abs)((CYL__L)tr - t)), /* (beyond R's range: inf) */
            er = er * (1 + 2 * (CYL__R)CYL__IFR(DBL_EPSILON, FLT_EPSILON)) + (CYL__R)1.40129846432481707e-45;
        if (CYL__P(abs)((CYL__L)vr) > vlim) vr = CYL__P(toward0)(vr);
    }
    hit->t = tr, hit->t_err = er, hit->v = vr; /* cppcheck-suppress ctunullpointer ; occluded's NULL: no emit */
    hit->n[0] = (CYL__R)n[0], hit->n[1] = (CYL__R)n[1], hit->n[2] = (CYL__R)n[2];
    hit->part = x->part, hit->flags = x->flags;
}

/* ------------------------------------------------------------------ certificates */
/* The tangent band: 1 unless D lies beyond the band's edges by more than its bound (a contact
   inside the band is the exact path's: its roots move by u/√e). */
CYL__INL int CYL__P(band_doubt)(const CYL__P(frame) *f, CYL__L k)
{
    CYL__L band = (CYL__L)CYL__TANG * (f->r2 * f->A), eD = k * (f->aww + f->r2aa) * (f->A / f->aa);
    return !(f->D - band > eD) && !(f->D + band < -eD);
}

/* Bounds e on the wall roots and the slab ends v (N9); 1 where one is not first order. */
CYL__INL int CYL__P(bounds)(const CYL__P(frame) *f, CYL__L k, const CYL__L v[4], CYL__L sq, CYL__L e[4])
{
    const CYL__L u = CYL__LU, z = CYL__P(abs)(f->zeta);
    const CYL__L es = 64 * u * (CYL__LSQRT(f->aww) + f->Ha) / z, ed = 64 * u * CYL__LSQRT(f->ad) / z;
    e[0] = CYL__P(root_bound)(f, k, v[0], sq), e[1] = CYL__P(root_bound)(f, k, v[1], sq);
    e[2] = CYL__P(abs)(v[2]) <= CYL__LMAX ? es + CYL__P(abs)(v[2]) * (ed + 2 * u) : 0;
    e[3] = CYL__P(abs)(v[3]) <= CYL__LMAX ? es + CYL__P(abs)(v[3]) * (ed + 2 * u) : 0;
    return !(CYL__P(first_order)(f, CYL__P(max)(e[0], e[1]), sq) && ed <= CYL__K(0.5)); /* and ζ */
}

/* polish of a hot path's t from the caller's inputs, so that its frame stays in registers (N9). */
CYL__OUT CYL__L CYL__P(polish_hot)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, CYL__L t, int part, CYL__L gap)
{
    CYL__P(frame) f; int i;
    CYL__UNROLL8 for (CYL__P(load)(&f, ray, cyl), i = 0; i < 3; i++) /* w exact as w + wl */
        f.wl[i] = CYL__P(sum_err)((CYL__L)ray->o[i], -(CYL__L)cyl->c[i], f.w[i]);
    return CYL__P(cross3)(f.a, f.d, f.s), CYL__X(polish)(&f, t, part, gap, NULL);
}

/* The crossings in t order; occluded and intersect stop at the first, and nothing is emitted
   before every decision it depends on is certain (CYL_PRECISE: else CYL__DOUBT, N9). compact
   (a literal: the exact path's 1): one emit site for every hit, its code once, for size. */
CYL__INL int CYL__P(answer)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, const CYL__P(frame) *f,
                            unsigned opts, int want, CYL__N(hit) *hits, int compact)
{
    CYL__L v[4], sq = 0, eb[4], *e = CYL__CERT(f, opts) ? eb : NULL, nz = 0, l[4] = {0, 0, 0, 0};
    CYL__P(cross) x, y;
    int kind = f->par ? 2 : CYL__P(classify_wall)(f), n = 0, pol, alone;
    unsigned tan = kind == 1 ? CYL_F_TANGENT : 0u;
    if (e) { nz = CYL__P(noise)(f); if (CYL__P(band_doubt)(f, nz)) return CYL__DOUBT; } /* N9's factor, once */
    if (kind == 0 || (tan && (opts & CYL_NO_TANGENT))) return 0;
    if (!f->par) sq = CYL__P(wall_roots)(f, v);
    else v[0] = -CYL__LINF, v[1] = CYL__LINF; /* no wall (N7): the slab alone bounds */
    CYL__P(slab)(f, &v[2]);
    if ((CYL__SUPPORTED & CYL_PRECISE) && f->cold && f->exact) CYL__X(refine)(f, v, opts & CYL_PRECISE ? l : NULL); /* N8 */
    pol = e && !CYL__WIDE && want; /* the double API's t to an ulp */
    if (e && CYL__P(bounds)(f, nz, v, sq, e)) return CYL__DOUBT;
    x = CYL__P(crossing)(f, opts, 0, v, e, l, sq, tan), alone = x.ok && want < 2; /* entry, then exit: no loop, so */
    if (e) { /* both certain, whatever the entry point: */ /* that k and the arrays fold away */
        y = CYL__P(crossing)(f, opts, 1, v, e, l, sq, tan); /* each answers on one path */
        if (x.doubt || y.doubt) return CYL__DOUBT;
        if (pol) { /* each crossing emitted moved onto its residual's root */
            if (x.ok) x.t = CYL__P(polish_hot)(ray, cyl, x.t, x.part, sq / f->A);
            if (y.ok && !alone) y.t = CYL__P(polish_hot)(ray, cyl, y.t, y.part, sq / f->A);
        }
    }
    if (alone && !compact) {
        if (want) CYL__P(emit)(f, cyl, &x, e, opts, hits);
        return 1;
    }
    if (alone) y.t = x.t, y.h = x.h, y.part = x.part, y.ok = x.ok, y.flags = x.flags; /* not y = x (RV32: memcpy) */
    else if (!e) y = CYL__P(crossing)(f, opts, 1, v, e, l, sq, tan);
    if (x.ok && want == 2) CYL__P(emit)(f, cyl, &x, e, opts, &hits[n++]);
    if (y.ok && want) CYL__P(emit)(f, cyl, &y, e, opts, &hits[n]);
    return n + y.ok;
}

/* ------------------------------------------------------------------ the exact path */
#ifdef CYL__XOWN
/* x·y − p for p = x·y rounded, exactly: by FMA where it is one instruction, else by Dekker's
   split (a call to fma() would spill every register around it). */
CYL__INL CYL__L CYL__P(prod_err)(CYL__L x, CYL__L y, CYL__L p)
{
#if defined(CYL__LFASTFMA) || defined(__FMA__) || (CYL__LD ? defined(__FP_FAST_FMA) || defined(__aarch64__) \
                                                : defined(__FP_FAST_FMAF) || defined(__ARM_FEATURE_FMA))
    return CYL__LFMA(x, y, -p);
#else
    CYL__L cx = x * CYL__LSPLIT, cy = y * CYL__LSPLIT, xh = cx - (cx - x), yh = cy - (cy - y);
    CYL__L xl = x - xh, yl = y - yh;
    return ((xh * yh - p) + xh * yl + xl * yh) + xl * yl;
#endif
}
/* A compensated sum (N8): s rounded, c the sum of its errors; x·y's error exact. */
typedef struct CYL__P(acc) { CYL__L s, c; } CYL__P(acc);
CYL__INL void CYL__P(acc_add)(CYL__P(acc) *q, CYL__L x)
{
    CYL__L s = q->s + x;
    q->c += CYL__P(sum_err)(q->s, x, s), q->s = s;
}
CYL__INL void CYL__P(acc_mul)(CYL__P(acc) *q, CYL__L x, CYL__L y)
{
    CYL__L p = x * y;
    CYL__P(acc_add)(q, p), q->c += CYL__P(prod_err)(x, y, p);
}
CYL__INL CYL__P(acc) CYL__P(acc_prod)(CYL__L x, CYL__L y) /* a sum's first term (0 + p is not p) */
{ CYL__P(acc) q; q.s = x * y, q.c = CYL__P(prod_err)(x, y, q.s); return q; }
/* The sum as a pair hi + lo, hi = rounded sum. */
CYL__INL CYL__L CYL__P(acc_pair)(const CYL__P(acc) *q, CYL__L *lo)
{ CYL__L h = q->s + q->c; *lo = q->c - (h - q->s); return h; }

/* |a| as a pair sa (√ of |a|²'s compensated sum, one Newton step) and −r²|a|² as ra: its
   rounded product, that product's error, the error of r²|a|² (N8). */
CYL__INL void CYL__P(norm_a)(const CYL__P(frame) *f, CYL__L sa[2], CYL__L ra[3])
{
    CYL__L aah, aal, p, r2 = f->r * f->r;
    CYL__P(acc) aa = CYL__P(acc_prod)(f->a[0], f->a[0]);
    CYL__P(acc_mul)(&aa, f->a[1], f->a[1]), CYL__P(acc_mul)(&aa, f->a[2], f->a[2]);
    aah = CYL__P(acc_pair)(&aa, &aal), sa[0] = CYL__LSQRT(aah), p = sa[0] * sa[0];
    sa[1] = ((aah - p) - CYL__P(prod_err)(sa[0], sa[0], p) + aal) / (2 * sa[0]);
    ra[0] = -r2 * aah, ra[1] = CYL__P(prod_err)(-r2, aah, ra[0]);
    ra[2] = CYL__P(prod_err)(f->r, f->r, r2) * aah + r2 * aal;
}

/* The wall's residual F = |a × x|² − r²|a|² at t as its compensated sum (N8), and g = (a × x)·s
   (F' = 2g). Out of line: exact_frame and polish's steps share one copy. */
CYL__OUT CYL__L CYL__P(resid)(const CYL__P(frame) *f, const CYL__L ra[3], CYL__L t, CYL__L *gp)
{
    CYL__L xh[3], xl[3], yh, yl, g = 0;
    CYL__P(acc) q, F; int i;
    F.s = ra[0], F.c = ra[1] - ra[2];
    CYL__UNROLL8 for (i = 0; i < 3; i++) { /* x = w + t·d as pairs xh + xl (w exact as w + wl) */
        q.s = f->w[i], q.c = f->wl[i], CYL__P(acc_mul)(&q, t, f->d[i]);
        xh[i] = q.s, xl[i] = q.c; /* as summed: a × xl is formed apart */
    }
    CYL__UNROLL8 for (i = 0; i < 3; i++) { /* y = a × x, componentwise as a pair, into |y|² */
        const int i1 = i == 2 ? 0 : i + 1, i2 = i == 0 ? 2 : i - 1;
        q = CYL__P(acc_prod)(f->a[i1], xh[i2]), CYL__P(acc_mul)(&q, -f->a[i2], xh[i1]);
        q.c += f->a[i1] * xl[i2] - f->a[i2] * xl[i1];
        yh = CYL__P(acc_pair)(&q, &yl);
        CYL__P(acc_mul)(&F, yh, yh), F.c += 2 * yh * yl, g += yh * f->s[i];
    }
    return *gp = g, F.s + F.c;
}

/* z0 = a·w (w exact as w + wl) and ζ = a·d as compensated sums (N8). */
CYL__INL void CYL__P(axial)(const CYL__P(frame) *f, CYL__P(acc) *z, CYL__P(acc) *ze)
{
    *z = CYL__P(acc_prod)(f->a[0], f->w[0]), *ze = CYL__P(acc_prod)(f->a[0], f->d[0]);
    CYL__P(acc_mul)(z, f->a[1], f->w[1]), CYL__P(acc_mul)(z, f->a[2], f->w[2]);
    CYL__P(acc_mul)(ze, f->a[1], f->d[1]), CYL__P(acc_mul)(ze, f->a[2], f->d[2]);
    z->c += CYL__P(dot)(f->a, f->wl);
}

/* The exact path's z0 and ζ (compensated sums) and, off the parallel rule, D = (g² − AF)/|a|²
   from the residual F and g at t_c = −B/A (exact for the quadratic whatever t_c's rounding,
   N8), where the plain D errs by u·r²A and more; t_c then takes one step on g (linear). */
CYL__COLD void CYL__P(exact_frame)(CYL__P(frame) *f)
{
    CYL__L sa[2], ra[3], F, g;
    CYL__P(acc) z, ze;
    CYL__P(axial)(f, &z, &ze), f->z0 = z.s + z.c, f->zeta = ze.s + ze.c;
    if (f->par) return;
    CYL__P(norm_a)(f, sa, ra);
    F = CYL__P(resid)(f, ra, f->tc = -f->B / f->A, &g);
    f->D = (g * g - F * f->A) / f->aa, f->tc -= g / f->A;
}

/* t onto its residual's root by Newton steps on compensated sums (N8): a cap plane's a·x ± H|a|
   (one), the wall's |a × x|² − r²|a|² (up to three, each leaving dt²/(2·gap); kept if it moved
   less than gap, half the roots' distance). *lo (if lo): the low part (the wall: one more, as held). */
CYL__OUT CYL__L CYL__P(polish)(const CYL__P(frame) *f, CYL__L t, int part, CYL__L gap, CYL__L *lo)
{
    CYL__L v = t, dt, g, sa[2], ra[3], H, Hh, zh, zl;
    CYL__P(acc) F, Z;
    int it;
    if (part != CYL_SIDE) { /* a·w + H|a| + tζ on the low plane, ζ = a·d summed first */
        CYL__P(norm_a)(f, sa, ra);
        H = part == CYL_CAP_LOW ? f->H : -f->H, Hh = H * sa[0];
        CYL__P(axial)(f, &F, &Z), zh = CYL__P(acc_pair)(&Z, &zl);
        CYL__P(acc_add)(&F, Hh), F.c += CYL__P(prod_err)(H, sa[0], Hh) + H * sa[1];
        CYL__P(acc_mul)(&F, t, zh), F.c += t * zl;
        v = t + (dt = -(F.s + F.c) / (zh + zl));
        if (lo && CYL__P(abs)(v) <= CYL__LMAX) *lo = CYL__P(sum_err)(t, dt, v);
        return CYL__P(abs)(v) <= CYL__LMAX ? v : t; /* ζ = 0 (no ends): t stays */
    }
    for (CYL__P(norm_a)(f, sa, ra), it = 0; it < 3; it++) { /* the wall: ra alone */
        v -= dt = CYL__P(resid)(f, ra, v, &g) / (2 * g);
        if (!(dt * dt > gap * CYL__LU * CYL__P(abs)(v))) break;
    }
    if (!(CYL__P(abs)(v - t) < gap)) return t;
    if (lo && (dt = -CYL__P(resid)(f, ra, v, &g) / (2 * g), CYL__P(abs)(v + dt - t) < gap))
        t = v + dt, *lo = CYL__P(sum_err)(v, dt, t), v = t; /* v: the pair rounded, as decided */
    return v;
}

/* The exact path's slab ends and wall roots v on their residuals' roots, the roots from its
   t_c and D (N8); a contact without roots is at the closest approach. l (CYL_PRECISE): their
   low parts, for the rim to compare the pairs. */
CYL__COLD void CYL__P(refine)(const CYL__P(frame) *f, CYL__L v[4], CYL__L *l)
{
    CYL__L lo = CYL__P(polish)(f, v[2], CYL__CAP_PART(f, 0), 0, l ? &l[2] : NULL);
    CYL__L hi = CYL__P(polish)(f, v[3], CYL__CAP_PART(f, 1), 0, l ? &l[3] : NULL);
    CYL__L gap = f->D > 0 ? CYL__LSQRT(f->aa * f->D) / f->A : 0; /* half the roots' distance */
    if (lo <= hi) v[2] = lo, v[3] = hi;
    else if (l) l[2] = l[3] = 0;
    if (f->par) return;
    v[0] = v[1] = f->tc; /* a contact without roots stays there */
    if (gap > 0) v[0] = CYL__P(polish)(f, v[0] - gap, CYL_SIDE, gap, l ? &l[0] : NULL),
                 v[1] = CYL__P(polish)(f, v[1] + gap, CYL_SIDE, gap, l ? &l[1] : NULL);
}
#endif /* CYL__XOWN */

/* Validation in the documented order of what the hot path refused; CYL_TRUSTED: the options alone. */
static inline int CYL__P(validate)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts)
{
    const CYL__R *v[4] = {ray->o, ray->d, cyl->c, cyl->a};
    unsigned i, k, nonzero = 0; /* bit k: v[k] has a nonzero component (an int[4]'s initializer calls memcpy on RV32) */
    if (opts & CYL_TRUSTED) return (opts & ~CYL__SUPPORTED) != 0u ? CYL_E_OPTION : 0;
    for (k = 0; k < 4; k++)
        for (i = 0; i < 3; i++) {
            if (!(v[k][i] >= -CYL__RMAX && v[k][i] <= CYL__RMAX)) return CYL_E_NONFINITE;
            if (v[k][i] < 0 || v[k][i] > 0) nonzero |= 1u << k;
        }
    if ((nonzero & (2u | 8u)) != (2u | 8u)) return nonzero & 2u ? CYL_E_ZERO_AXIS : CYL_E_ZERO_DIR; /* d, a */
    if (!(cyl->r > 0) || !(cyl->r <= CYL__RMAX)) return CYL_E_RADIUS;
    if (!(cyl->h > 0)) return CYL_E_HEIGHT;
    if (!(ray->tmin <= ray->tmax)) return CYL_E_TRANGE;
    return (opts & ~CYL__SUPPORTED) != 0u ? CYL_E_OPTION : 0;
}

/* The frame of valid input scaled into the range (N2): lengths by 2^-kl (a finite h/2 below 2^(emax − 2),
   else clamped, raised; Ha finite, |a| < 4), d by 2^-kd, a by 2^-ka; o − c exactly, halved where it overflows. */
static inline void CYL__P(load_scaled)(CYL__P(frame) *f, const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl)
{
    CYL__L wr[3], m;
    int j = 0, kl, kd, ka, kh, kr, i;
    for (i = 0; i < 3; i++) /* halved (exact) only where o − c overflows: small parts stay */
        if (!(CYL__P(abs)((CYL__L)ray->o[i] - (CYL__L)cyl->c[i]) <= CYL__LMAX)) j = 1;
    for (i = 0; i < 3; i++) { /* o − c = wr + f->wl exactly */
        CYL__L x = CYL__LT(scale)((CYL__L)ray->o[i], -j), y = -CYL__LT(scale)((CYL__L)cyl->c[i], -j);
        f->wl[i] = CYL__P(sum_err)(x, y, wr[i] = x + y);
    }
    for (i = 0; i < 3; i++) f->d[i] = (CYL__L)ray->d[i], f->a[i] = (CYL__L)cyl->a[i];
    m = CYL__P(max)(CYL__P(amax)(wr), CYL__LT(scale)((CYL__L)cyl->r, -j));
    kl = (m > 0 ? CYL__LT(expo)(m) : 0) + j, kh = CYL__LT(expo)((CYL__L)cyl->h) - CYL__IFL(1021, 125);
    kr = CYL__LT(expo)((CYL__L)cyl->r) + CYL__IFL(200, 30); /* a finite h/2 below 2^(emax − 2), if r allows */
    if ((CYL__L)cyl->h <= CYL__LMAX && kh > kl) kl = kr > kl ? kr : kl, kl = kl < kh ? kl : kh; /* min(kh, max(kr, kl)) */
    kd = CYL__LT(expo)(CYL__P(amax)(f->d)), ka = CYL__LT(expo)(CYL__P(amax)(f->a));
    for (i = 0; i < 3; i++) {
        f->w[i] = CYL__LT(scale)(wr[i], j - kl), f->wl[i] = CYL__LT(scale)(f->wl[i], j - kl);
        f->d[i] = CYL__LT(scale)(f->d[i], -kd), f->a[i] = CYL__LT(scale)(f->a[i], -ka);
    }
    f->r = CYL__LT(scale)((CYL__L)cyl->r, -kl), f->H = CYL__LT(scale)((CYL__L)cyl->h, -kl - 1);
    f->et = kl - kd, f->ev = kl;
    m = CYL__LT(scale)((CYL__L)CYL__RMAX, -f->et); /* R's largest t */
    f->tmin = CYL__P(max)(CYL__LT(scale)((CYL__L)ray->tmin, -f->et), -m), f->rmin = (CYL__L)ray->tmin;
    f->tmax = CYL__P(min)(CYL__LT(scale)((CYL__L)ray->tmax, -f->et), m), f->rmax = (CYL__L)ray->tmax;
    f->cold = 1, f->exact = !(f->H > CYL__LMAX / 4 && (CYL__L)cyl->h <= CYL__LMAX), f->H = f->exact ? f->H : CYL__LMAX / 4;
}

/* The exact path: validates, scales, answers on the same decisions; ratios out of range even scaled
   (double: r below 2^-300, h/2 below 2^-600 |o − c| or above 2^1220 r) are answered raised (h/2 clamped),
   t_err = inf. fs: the caller's frame to fill, which the caller answers (CYL__HANDBACK; CYL__DOUBT), else NULL. */
CYL__COLD int CYL__P(cold)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts,
                           int want, CYL__N(hit) *hits, CYL__P(frame) *fs)
{
    CYL__P(frame) own, *f = fs ? fs : &own; /* cppcheck-suppress uninitvar ; load_scaled fills it */
    int rc = CYL__P(validate)(ray, cyl, opts);
    if (rc) return rc;
    CYL__P(load_scaled)(f, ray, cyl);
    while (!CYL__P(derive)(f)) { /* one call: it is inlined once; rc (0 here) counts the raise */
        if (rc++) return CYL_MISS;
        f->r = CYL__P(max)(f->r, CYL__LSQRT(CYL__COLD_LO) * 2), f->H = CYL__P(max)(f->H, CYL__COLD_LO * 2), f->exact = 0;
    }
    f->par = CYL__P(parallel)(f) <= 0;
    if (CYL__SUPPORTED & CYL_PRECISE) CYL__X(exact_frame)(f); /* N8 (a raised frame too: its D decides the wall) */
    return CYL__HANDBACK ? CYL__DOUBT : CYL__P(answer)(ray, cyl, f, opts, want, hits, 1);
}

/* ------------------------------------------------------------------ entry points */
/* The hot path: the frame, one range test, the answer; what the test refuses (invalid, out of
   range, near the axis direction, an unknown option) goes to the exact path. want: 0 occluded,
   1 nearest, 2 all. */
CYL__INL int CYL__P(run)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts,
                         int want, CYL__N(hit) *hits)
{
    CYL__P(frame) f; int ok, tfirst = CYL__WIDE || CYL__HANDBACK; /* tfirst: tmin <= tmax up front, else on a miss (N2) */
#ifdef CYL__HANDOFF
    if ((opts & CYL_PRECISE) && CYL__HANDOFF_IF(want)) return CYL__HANDOFF(out)(ray, cyl, opts, want, hits);
#endif
#if defined(CYL__CVT2) && CYL__WIDE /* float inputs in pairs, as they lie in memory: */
    { /* ray (o0, o1), (o2, d0), (d1, d2), (tmin, tmax), cylinder (c0, c1), (c2, a0), (a1, a2), (r, h) */
        const unsigned char *p = (const unsigned char *)ray, *q = (const unsigned char *)cyl;
        CYL__P(pair) o, od, dd, c, ca, aa, rh;
        (void)sizeof(char[sizeof *ray == 32 && sizeof *cyl == 32 ? 1 : -1]); /* 8 floats each, packed */
        CYL__CVT2(o, p); CYL__CVT2(od, p + 8); CYL__CVT2(dd, p + 16); CYL__CVT2(c, q);
        CYL__CVT2(ca, q + 8); CYL__CVT2(aa, q + 16); CYL__CVT2(rh, q + 24); o -= c, c = od - ca;
        f.w[0] = o[0], f.w[1] = o[1], f.w[2] = c[0], f.d[0] = od[1], f.d[1] = dd[0], f.d[2] = dd[1];
        f.a[0] = ca[1], f.a[1] = aa[0], f.a[2] = aa[1], f.r = rh[0], f.H = rh[1] * CYL__K(0.5);
    }
#else
    if (CYL__WIDE) { CYL__LAUNDER(ray); CYL__LAUNDER(cyl); } /* here: the t range reads too */
    CYL__P(load)(&f, ray, cyl);
#endif
    f.cold = f.par = 0; /* the exact path's fields: load_scaled's */
    ok = CYL__P(derive)(&f); /* the t range read after it: fewer values live (and spilled) */
#if defined(CYL__CVT2) && CYL__WIDE
    { CYL__P(pair) t; CYL__CVT2(t, (const unsigned char *)ray + 24); f.tmin = t[0], f.tmax = t[1]; }
#else
    f.tmin = (CYL__L)ray->tmin, f.tmax = (CYL__L)ray->tmax;
#endif
    if (!ok || (tfirst && !(f.tmin <= f.tmax)) || (opts & ~CYL__SUPPORTED) != 0u)
        ok = CYL__P(cold)(ray, cyl, opts, want, hits, CYL__HANDBACK ? &f : NULL);
    else {
        if (CYL__WIDE) /* t representable in R: in the range (in_range) */
            f.tmin = CYL__P(max)(f.tmin, -(CYL__L)CYL__RMAX), f.tmax = CYL__P(min)(f.tmax, (CYL__L)CYL__RMAX);
        ok = CYL__P(answer)(ray, cyl, &f, opts, want, hits, 0);
        if (ok == CYL__DOUBT || (!tfirst && !ok && !(f.tmin <= f.tmax)))
            ok = CYL__P(cold)(ray, cyl, opts, want, hits, CYL__HANDBACK ? &f : NULL);
    }
    return CYL__HANDBACK && ok == CYL__DOUBT ? CYL__P(answer)(ray, cyl, &f, opts, want, hits, 1) : ok;
}

#ifdef CYL__HELPER /* the handoff's target: one out-of-line copy for every call site */
CYL__OUT int CYL__P(out)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts,
                         int want, CYL__N(hit) *hits)
{ return CYL__P(run)(ray, cyl, opts, want, hits); }
#else
CYL_DEF int CYL__N(intersect)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                              unsigned opts, CYL__N(hit) *hit)
{ return !ray || !cyl || !hit ? CYL_E_NULL : CYL__P(run)(ray, cyl, opts, 1, hit); }
CYL_DEF int CYL__N(intersect_all)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl,
                                  unsigned opts, CYL__N(hit) hits[2])
{ return !ray || !cyl || !hits ? CYL_E_NULL : CYL__P(run)(ray, cyl, opts, 2, hits); }
CYL_DEF int CYL__N(occluded)(const CYL__N(ray) *ray, const CYL__N(cylinder) *cyl, unsigned opts)
{ return !ray || !cyl ? CYL_E_NULL : CYL__P(run)(ray, cyl, opts, 0, NULL); }
#endif

#ifndef CYL__HELPER
/* The cylinder from p0 (its low cap center) to p1 (high cap center); |p1 − p0| with a
   power-of-two prescale, so it neither overflows nor underflows. NULL ends give a = 0. */
CYL_DEF CYL__N(cylinder) CYL__N(from_segment)(const CYL__R p0[3], const CYL__R p1[3], CYL__R r)
{
    CYL__N(cylinder) cy;
    CYL__R m, x[3];
    CYL__L al[3];
    int i, k;
    for (i = 0; i < 3; i++) {
        cy.c[i] = p0 && p1 ? p0[i] * (CYL__R)0.5 + p1[i] * (CYL__R)0.5 : 0;
        al[i] = (CYL__L)(cy.a[i] = p0 && p1 ? p1[i] - p0[i] : 0);
    }
    cy.r = r, cy.h = m = (CYL__R)CYL__P(amax)(al); /* exact; 0 or non-finite: intersect reports it */
    if (m > 0 && m <= CYL__RMAX) {
        for (k = CYL__P(expo)(m), i = 0; i < 3; i++) x[i] = CYL__P(scale)(cy.a[i], -k);
        cy.h = CYL__P(scale)(CYL__RSQRT(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), k);
    }
    return cy;
}
#endif

#undef CYL__HELPER
#undef CYL__X
#undef CYL__XOWN
#undef CYL__HANDOFF
#undef CYL__HANDOFF_IF
#undef CYL__LD
#undef CYL__RD
#undef CYL__P
#undef CYL__LFASTFMA
#endif /* CYL__P */

/* NOTES (cited from the code as N1 .. N9); u is the working type's unit roundoff
   N1. One formulation (DESIGN.md of the project): w = o − c, s = a × d, m = a × w (cross products, never
       projections: no cancellation for rays near the axis direction or origins far along it), A = s·s, B =
       m·s, C = m·m − r²|a|², z0 = a·w, ζ = a·d, Ha = (h/2)|a|, formed in pairs (s, m), (ζ, z0), (A, B), (P,
       |m|²): vectors where the compiler has them, one instruction for two, the same bits. The exact path forms
       s and m with Kahan's FMA difference of products (Jeannerod, Louvet, Muller, Math. Comp. 82, 2013), 2u each.
   N2. Range: instead of validating 16 inputs the hot path tests r²|a|², r²A (else D can be subnormal), Ha,
       |a|²(|w|² + r²) and (through the steep or parallel margin) |a|²|d|² against one range, [2^-300, 2^450]
       in double: the largest products the bounds form, such as |a|²D <= r²|a|²·|a|²|d|², stay below 2^900.
       Every NaN, infinity, zero or out-of-range input fails it and goes to the exact path, which validates in
       the documented order (unless CYL_TRUSTED) and scales lengths, d and a by powers of two (exact: its
       answers to a scene scaled by 2^k are the same bits scaled; the hot path's, without N8's step, agree
       within t_err). tmin <= tmax is tested there too where L is wider or the frame is handed back, else after
       a miss only (a hit proves it): measured the cheaper. Ha = ∞ for a finite h changes no answer of the hot
       path: |a||w|, r|a| <= √HOT_HI and sin(d, a) >= 2^-8 keep |a| times a wall point's axial coordinate
       below 2^10·√HOT_HI, inside the slab (−∞, ∞) it gives as inside the true one; the exact path scales h/2
       below 2^(emax − 2) with |a| < 4 (a wider L: Ha < 2^256 anyway).
   N3. Geometric discriminant B² − AC = |a|²·D, D = r²A − P², P = w·s (Ray Tracing Gems, ch. 7; pbrt-v4
       cylinders): no difference of large squares for far origins.
   N4. Stable root pair q = −(B + sgn(B)√(|a|²D)), t = q/A and C/q (Numerical Recipes §5.6); caps by clipping
       the wall interval with the slab |z0 + tζ| <= Ha (Cychosz and Waggenspack, Graphics Gems IV): watertight
       at the rim, no separate disk test.
   N5. Output: v = (z0 + tζ)/|a|; the wall normal y × a (= |a|²x⊥, y = m + t·s = a × x) written from the roots
       as P|a|²s − h(a × s), h = ∓√(|a|²D), of length |a|²|s|√(P² + h²/|a|²) (s ⊥ a × s): made unit by its two
       scalars, none of its terms can overflow. t_err: F = |y|² − r²|a|² and G = y·s at t, with bounds EF, EG
       on their rounding (standard model, Higham, "Accuracy and Stability of Numerical Algorithms", ch. 3;
       componentwise sums bounded by 2-norms, e.g. |δ(a × w)|₁ <= 3u·√6|a||w|): y errs by at most Ey =
       8u(|a||w| + |y|) + 10u|t||a||d| (|s| <= |a||d|), which leaves room for the roundings of |y|², r²|a|² and
       y·s: EF = Ey(2|y| + Ey), EG = |s|Ey + 5u|a||d|(|y| + Ey), s erring by 5u|a||d|; A's error and F's own
       rounding (up to 12u|F|, with the bound's) take A⁺ = A + 32u|a|²|d|² and a last factor 1 + 48u. f(t +
       δ) = f + 2gδ + Aδ² exactly: where g has the crossing's sign and (|G| − EG)² >= A⁺(|F| + EF), the root
       is within (|F| + EF)/(|G| − EG); else, the roots' product being f/A, within (2|g| + √(A|f|))/A. A cap:
       the plane's residual over |ζ| less its bound (|g|'s own rounding in its last factor). The float API
       computed in double adds t's rounding; its wall root's bound is N9's where first order and below 2^-7
       of float's ulp.
   N6. The plain tier's limits, from rounding what each decision compares: e = D/(r²A) carries a few u·(1 + |o
       − c|/r)(1 + 2ρ/r) (ρ: the line's distance from the axis): the tangent band's edges blur by that for far
       origins; a rim, u·(|o − c| + |t d| + h)/h of the half height (a flat disk seen along its axis from an
       origin on its wall: about u·r/(h·sin)); a t range end, u·|t|; a cap crossing, u times the cancellation
       of z0 ∓ Ha. A ray within 2^-8 of the axis' direction would add u/sin to e (far origins: u·|w|/(r·sin));
       the double API sends those to the exact path, whose s and m are accurate.
   N7. Parallel: A <= τ²|a|²|d|² (sin <= τ = CYL_PARALLEL_TOL). Below sin = u a half-ulp change of one
       component of d makes the ray exactly parallel; yet a ray from the wall can cross it again a few dozen
       radii along, a crossing its inputs determine (a × d is exact for an axis-aligned a), which the rule
       drops (test_parallel_rule_drops_secondary_ray_from_wall).
   N8. The exact path's t: before any decision, each slab end takes one Newton step t − F/F' on its cap
       plane's residual F = a·x ± H|a| (F' = ζ), each wall root up to three on F = |a × x|² − r²|a|² (F' = 2(a
       × x)·s; a step leaves about dt²/(2·gap)), x = w + t·d, w exact as a pair, each product's error kept
       exactly (FMA, or Dekker's split) in a compensated sum (Ogita, Rump, Oishi, SIAM J. Sci. Comput. 26,
       2005): F errs by about u|F| + u²(r²|a|² + |a|²|x|²); z0 and ζ are such sums too. With CYL_PRECISE the
       next step is kept as each t's low part and the rim compares the pairs: a steep ray moves |ζ|/|a| along
       the axis per unit of t, so an ulp of t can exceed a flat disk's rim margin. The tangent band decides on
       D from the residual near the closest approach t_c = −B/A: F(t) = g²/A − |a|²D/A for the quadratic, g =
       (a × x)·s = F'/2, so D = (g² − AF)/|a|² whatever t's rounding (the plain D errs by u·r²A·|w|/r and
       more). t_c takes one step on g (g' = A); the roots start at t_c ± √(|a|²D)/A (the plain C cancels for
       an origin on the wall), each refined while its steps stay within that half gap; without roots, a
       contact is at t_c. CYL_NO_PRECISE (so every float-only build) compiles none of this: the exact path
       then answers from its s and m (N1) and the scaled inputs with the hot path's arithmetic alone.
   N9. The certified layer (CYL_PRECISE on the hot path) takes each comparison an answer depends on (tangent
       band, rims, t range, entry and exit, both crossings whatever the entry point) only where its operands
       lie farther apart than their bounds' sum; else the exact path answers. The bounds are a priori, from
       magnitudes the hot path has: s and m carry about u|a||d| and u|a||w|, so A, B, C, D and the quadratic
       each root solves (from √(|a|²D), not B² − AC) err at t by at most k(S + t²|a|²|d|²), S = |a|²(|w|² +
       r²), k = 128u(1 + |a||d|/|s|) (the last term: P's error through s). A root moves by that over √(|a|²D),
       plus 4u|t|, while this is below √(|a|²D)/A (first order); D by k·S·A/|a|²; a slab end by 64u(|a||w| +
       Ha + |t||a||d|)/|ζ| + 2u|t|, while |ζ| > 128u|a||d|. A NaN or infinite bound, or a contact inside the
       band (its roots move by u/√e), certifies nothing. Each crossing the double API emits then takes N8's
       step (polish, out of line from the caller's inputs, so that the hot frame stays in registers): 36 ulps
       on the hot path, the tier promises 2; the float API's, computed in double, is within 2^-29 already.
       Helper bodies take CYL_PRECISE calls out of line: the float API's in double where it computes in float;
       on x86-64 built without the FMA, both APIs' built with it where the CPU has it (CYL_FMA_DISPATCH; not the
       double API's occluded): one instruction per exact product, nothing contracted or vectorized, same bits.
*/
