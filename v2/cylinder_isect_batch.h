/* cylinder_isect_batch.h - v2.0.0 (in development beside v1) - one ray against many cylinders.

   Staged beside v2/cylinder_isect.h, whose API it extends and which it includes; it joins that
   header when v2 replaces v1 (issue 31). No allocation: the caller gives the memory.

   QUICK START
       #include "cylinder_isect_batch.h"
       void *mem = malloc(cylf_batch_bytes(n));                  // any alignment
       cylf_batch b;
       if (cylf_batch_build(&b, mem, cyls, n) == 0) {            // checks and copies cyls
           size_t i; float t;
           if (cylf_batch_nearest(&b, &ray, CYL_CAPS, &i, &t) == CYL_HIT)
               cylf_intersect(&ray, &cyls[i], CYL_CAPS, &hit);   // the full hit, if wanted
           if (cylf_batch_any(&b, &shadow, CYL_CAPS) == 1) ...   // something in range is hit
       }

   CONTRACT (cyld_* alike, in double)
   int cylf_batch_nearest(const cylf_batch *b, const cylf_ray *ray, unsigned opts, size_t *i, float *t)
       What a loop of cylf_intersect(ray, &cyls[k], opts, &hit) over k = 0 .. n−1 keeping the
       smallest hit.t (the lowest k among equal ones) gives: CYL_HIT with *i = k and *t = hit.t,
       the same bits; CYL_MISS (n = 0 too) when every call misses; or the error the calls give
       (the ray's and the options', in the scalar order). *i and *t are written on a hit only.
   int cylf_batch_any(const cylf_batch *b, const cylf_ray *ray, unsigned opts)
       1 if cylf_occluded(ray, &cyls[k], opts) is 1 for some k, 0 if for none, or the error.
   Every option of the scalar API counts, CYL_PRECISE included: each answer is a scalar call's.
   CYL_TRUSTED's promises about the ray (o and d finite, d nonzero, tmin <= tmax) are the
   caller's here as there: where one is broken the answer is unspecified, as the call's is (the
   cylinders are checked when the batch is built, whatever the options).
   A vector filter first drops the cylinders that certainly give no hit at or before the best t
   found so far, t range included: the infinite tube, the t interval it leaves and the slab
   between the cap planes, each compared with a bound on its rounding and on the scalar call's
   (the standard model; N9 of cylinder_isect.h). The rest, a few per ray in a scene, take the
   scalar call, in index order. Not dropped, so asked: cylinders whose axis the ray follows
   within about √(18u) (their t interval is unbounded), and everything outside the range
   below; a scene of rays parallel to the axes of cylinders parallel to them (an axis-aligned
   lidar looking down on stems) pays a scalar call for every cylinder whose slab its range
   crosses.
   size_t cylf_batch_bytes(size_t n)
       The memory a batch of n cylinders takes (any alignment); 0 if n is too large for size_t.
   int cylf_batch_build(cylf_batch *b, void *mem, const cylf_cylinder *cyls, size_t n)
       0, or the first error a cylinder gives in the scalar order (CYL_E_NONFINITE, _ZERO_AXIS,
       _RADIUS, _HEIGHT); CYL_E_NULL for b NULL, or mem or cyls NULL with n > 0. On an error
       nothing is written. mem holds cylf_batch_bytes(n) bytes and lives as long as b is used;
       cyls is copied into it. A batch is read only by queries: threads may share it.

   The filter works in the API's own type (the float API's in float, whose bounds are wider
   than the scalar call's double: more cylinders asked, twice the lanes per instruction).
   Outside its range every cylinder is asked: a ray whose largest |o| component exceeds 2^100
   (float: 2^32); a cylinder likewise for c, or whose r lies outside 2^±100 (2^±32), or h/2
   outside 2^±400 (double; infinite is in range). a and d may have any length (the filter
   scales them by powers of two). Where the float API computes in float (CYL_FLOAT_WIDE 0):
   2^16, r from 2^-20, h/2 within 2^±58.

   LAYOUT (in mem, 64-byte aligned): blocks of 8 cylinders in double, 16 in float, structure of
   arrays, each field of a block one 64-byte line: the center c, the axis a scaled to a largest
   component in [1, 2), r² (+inf outside the range), |a|², (h/2)|a|, |a| rounded up; the last
   block padded; then the cylinders as given.

   CODE: the filter is written once over a vector: GCC vector extensions where the compiler has
   them (gcc, clang) for x86 at the width of the instruction set the build targets (SSE2,
   AVX2; with AVX-512, 256 bits and its 32 registers unless CYL_BATCH_VECTOR_BYTES is 64;
   square roots, fused multiply-adds and masks by the builtins its intrinsics call, so that
   <immintrin.h> is included only for 512 bits), else (NEON not measured
   yet), or with CYL_BATCH_PORTABLE, the same text over one lane. `make bench-batch` measures
   each form.
*/
#ifndef CYLINDER_ISECT_BATCH_H
#define CYLINDER_ISECT_BATCH_H
#include "cylinder_isect.h"

/* CYL__BVEC: the bytes of the filter's vector, 0 for the portable form. With AVX-512, 32 unless
   CYL_BATCH_VECTOR_BYTES is 64: 256-bit vectors with AVX-512's 32 registers measured faster here
   (make bench-batch's avx512 rows; gcc's own default width for x86-64-v4 too). */
#if (defined(__GNUC__) || defined(__clang__)) && !defined(CYL_BATCH_PORTABLE) && defined(__SSE2__)
#if defined(__AVX512F__) && defined(CYL_BATCH_VECTOR_BYTES) && CYL_BATCH_VECTOR_BYTES == 64
#define CYL__BVEC 64
#elif defined(__AVX__)
#define CYL__BVEC 32
#else
#define CYL__BVEC 16
#endif
#if CYL__BVEC == 64 /* the others call the builtins behind the intrinsics: no <immintrin.h> to parse */
#include <immintrin.h>
#else
typedef double cyl__bvd __attribute__((vector_size(CYL__BVEC)));
typedef float cyl__bvs __attribute__((vector_size(CYL__BVEC)));
#endif
#else
#define CYL__BVEC 0
#endif

/* One API's batch: B its names, BR its type, BK the filter's (the API's working type), BW the
   lanes of a block (64 bytes of BK), BI an integer as wide as BK. */
#ifndef CYL_NO_DOUBLE
#define CYL__BN(x) cyld_##x
#define CYL__BP(x) cyl__db_##x
#define CYL__BS(x) cyl__d_##x
#define CYL__BR double
#define CYL__BK double
#define CYL__BI int64_t
#define CYL__BW 8
#define CYL__BTANG CYL_TANGENT_TOL
#include "cylinder_isect_batch.h"
#endif
#ifndef CYL_NO_FLOAT
#define CYL__BN(x) cylf_##x
#define CYL__BP(x) cyl__fb_##x
#define CYL__BS(x) cyl__f_##x
#define CYL__BR float
#define CYL__BTANG CYL_TANGENT_TOLF
#define CYL__BK float
#define CYL__BI int32_t
#define CYL__BW 16
#include "cylinder_isect_batch.h"
#endif
#endif /* CYLINDER_ISECT_BATCH_H */

#if defined(CYL__BP) && !defined(CYL__BBODY) /* one API's batch, written once */
#define CYL__BBODY
#define CYL__BU ((CYL__BK)(sizeof(CYL__BK) == 8 ? 1.1102230246251565e-16 : 5.9604644775390625e-08)) /* u */
/* The range the filter holds in: its bounds neither overflow nor underflow (a and d scaled by
   powers of two to a largest component in [1, 2): exact; t does not change with a's scale and
   scales with d's), and the scalar call answers within them (its exact path raises r or h/2
   only for r below 2^-300 |o − c| or h/2 below 2^-600 |o − c| in double, 2^-38 and 2^-76 in
   float; clamps h/2 only above 2^1021 times those): |c| and |o| at most P, r within [1/P, P],
   h/2 within [1/H, H] or infinite. Double: P = 2^100, H = 2^400; the float API computed in
   double: 2^32 (its bounds) and any h; computed in float: 2^16, r from 2^-20, h/2 2^±58. */
#define CYL__BDERR (sizeof(CYL__BK) == 8 || !CYL_FLOAT_WIDE ? 36 : 20) /* 2 x 18 (16 and the bound's own), 18 + 2 */
#define CYL__BLIM(d_, w_, f_) ((CYL__BK)(sizeof(CYL__BK) == 8 ? (d_) : CYL_FLOAT_WIDE ? (w_) : (f_)))
#define CYL__BLIM_P CYL__BLIM(1.2676506002282294e+30, 4294967296.0, 65536.0)
#define CYL__BLIM_R CYL__BLIM(7.8886090522101181e-31, 2.3283064365386963e-10, 9.5367431640625e-07)
#define CYL__BLIM_H CYL__BLIM(2.5822498780869086e+120, 3.4028234663852886e+38, 2.8823037615171174e+17)
#define CYL__BSQRT1(x) (sizeof(CYL__BK) == 8 ? (CYL__BK)CYL_SQRT((double)(x)) : (CYL__BK)CYL_SQRTF((float)(x)))
#define CYL__BF 10 /* fields: c (3), a (3), r² (+inf: always asked), |a|², H|a|, |a| */

typedef struct CYL__BN(batch) {
    const CYL__BK *blocks;          /* nb blocks of CYL__BF fields of CYL__BW lanes */
    const CYL__BN(cylinder) *cyls;  /* the n cylinders as given */
    size_t n, nb;
} CYL__BN(batch);

/* A block's vectors written out (at most 4; measured: 13 % faster in float, AVX2). */
#if CYL__BVEC && (defined(__clang__) || (defined(__GNUC__) && __GNUC__ >= 8))
#define CYL__BUNROLL _Pragma("GCC unroll 4")
#else
#define CYL__BUNROLL
#endif
/* CYL__BL lanes at once: a vector of the instruction set's (GCC's extension), or one lane (the
   portable form); a block is BW / BL of them. */
#if CYL__BVEC
typedef CYL__BK CYL__BP(v) __attribute__((vector_size(CYL__BVEC)));
typedef CYL__BI CYL__BP(m) __attribute__((vector_size(CYL__BVEC)));
#define CYL__BL (CYL__BVEC / (int)sizeof(CYL__BK))
#define CYL__BLOAD(p) (*(const CYL__BP(v) *)(const void *)(p))
#define CYL__BSEL(k_, x_, y_) ((CYL__BP(v))(((k_) & (CYL__BP(m))(x_)) | (~(k_) & (CYL__BP(m))(y_))))
#define CYL__BNOT(k_) (~(k_))
#else
typedef CYL__BK CYL__BP(v);
typedef int CYL__BP(m);
#define CYL__BL 1
#define CYL__BLOAD(p) (*(p))
#define CYL__BSEL(k_, x_, y_) ((k_) ? (x_) : (y_))
#define CYL__BNOT(k_) (!(k_))
#endif
/* The intrinsics of the vector's width, CYL__BMM(op, b) one of them: _mm512_op for 512 bits, else
   b, the builtin that gcc's and clang's intrinsics of 128 bits call (gcc's manual, x86 Built-in
   Functions), with 256 appended for 256 bits. CYL__BMD and CYL__BMS: its double and float
   vectors, the same as the filter's (copies between them cost no instruction). */
#if CYL__BVEC == 64
#define CYL__BMM(op, b) _mm512_##op
#define CYL__BMD __m512d
#define CYL__BMS __m512
#elif CYL__BVEC
#if CYL__BVEC == 32
#define CYL__BMM(op, b) __builtin_ia32_##b##256
#else
#define CYL__BMM(op, b) __builtin_ia32_##b
#endif
#define CYL__BMD cyl__bvd
#define CYL__BMS cyl__bvs
#endif
/* x·y + z: one fused instruction where the build has the FMA (the bounds hold either way). */
#if CYL__BVEC && defined(__FMA__)
CYL__ALWAYS CYL__BP(v) CYL__BP(fma)(CYL__BP(v) x, CYL__BP(v) y, CYL__BP(v) z)
{
#define CYL__BFM(t, f) { t a_, b_, c_; __builtin_memcpy(&a_, &x, sizeof a_), __builtin_memcpy(&b_, &y, sizeof b_), __builtin_memcpy(&c_, &z, sizeof c_); \
                         a_ = f(a_, b_, c_); __builtin_memcpy(&x, &a_, sizeof x); return x; }
    if (sizeof(CYL__BK) == 8) CYL__BFM(CYL__BMD, CYL__BMM(fmadd_pd, vfmaddpd)) else CYL__BFM(CYL__BMS, CYL__BMM(fmadd_ps, vfmaddps))
#undef CYL__BFM
}
#define CYL__BFMA(x_, y_, z_) CYL__BP(fma)(x_, y_, z_)
#else
#define CYL__BFMA(x_, y_, z_) ((x_) * (y_) + (z_))
#endif
#define CYL__BABS(x_) CYL__BSEL((x_) < 0, -(x_), (x_))
#define CYL__BMAX(x_, y_) CYL__BSEL((x_) > (y_), (x_), (y_))
#define CYL__BMIN(x_, y_) CYL__BSEL((x_) < (y_), (x_), (y_))
CYL__ALWAYS void CYL__BP(sqrt)(CYL__BP(v) *xp)
{
    const CYL__BP(v) x = *xp;
#if CYL__BVEC /* the intrinsic's type is the same vector: a copy, no instruction */
#define CYL__BSQ(t, f) { t y; __builtin_memcpy(&y, &x, sizeof y); y = f(y); __builtin_memcpy(xp, &y, sizeof y); }
    if (sizeof(CYL__BK) == 8) CYL__BSQ(CYL__BMD, CYL__BMM(sqrt_pd, sqrtpd)) else CYL__BSQ(CYL__BMS, CYL__BMM(sqrt_ps, sqrtps))
#undef CYL__BSQ
#else
    *xp = CYL__BSQRT1(x);
#endif
}

/* Bit j set where lane j of m is (the candidates, in index order). */
CYL__ALWAYS unsigned CYL__BP(bits)(const CYL__BP(m) *mp)
{
    const CYL__BP(m) m = *mp;
#if CYL__BVEC
#define CYL__BMV(t, f) { t y; __builtin_memcpy(&y, &m, sizeof y); return (unsigned)f; }
#if CYL__BVEC == 64
    if (sizeof(CYL__BK) == 8) CYL__BMV(__m512i, _mm512_test_epi64_mask(y, y)) else CYL__BMV(__m512i, _mm512_test_epi32_mask(y, y))
#else
    if (sizeof(CYL__BK) == 8) CYL__BMV(CYL__BMD, CYL__BMM(movemask_pd, movmskpd)(y)) else CYL__BMV(CYL__BMS, CYL__BMM(movemask_ps, movmskps)(y))
#endif
#undef CYL__BMV
#else
    return m != 0;
#endif
}

/* The ray in the filter's type, once per query. */
typedef struct CYL__BP(q) { CYL__BK o[3], d[3], nd, dd, tmin, tmax; int kd; } CYL__BP(q);

/* What the filter forms first, from the block's lanes at p and the ray. */
typedef struct CYL__BP(tube) { CYL__BP(v) a[3], w[3], s[3], r2, A, P, S, ad, D; } CYL__BP(tube);
CYL__ALWAYS void CYL__BP(tube_of)(const CYL__BK *p, const CYL__BP(q) *q, CYL__BP(tube) *f)
{
    const CYL__BP(v) zero = {0};
    int i;
    f->r2 = CYL__BLOAD(p + 6 * CYL__BW);
    for (i = 0; i < 3; i++) f->a[i] = CYL__BLOAD(p + (3 + i) * CYL__BW), f->w[i] = q->o[i] - CYL__BLOAD(p + i * CYL__BW);
    f->s[0] = CYL__BFMA(f->a[1], zero + q->d[2], -(f->a[2] * q->d[1])), f->s[1] = CYL__BFMA(f->a[2], zero + q->d[0], -(f->a[0] * q->d[2]));
    f->s[2] = CYL__BFMA(f->a[0], zero + q->d[1], -(f->a[1] * q->d[0]));
    f->A = CYL__BFMA(f->s[0], f->s[0], CYL__BFMA(f->s[1], f->s[1], f->s[2] * f->s[2]));
    f->P = CYL__BFMA(f->w[0], f->s[0], CYL__BFMA(f->w[1], f->s[1], f->w[2] * f->s[2]));
    f->S = CYL__BFMA(f->w[0], f->w[0], CYL__BFMA(f->w[1], f->w[1], f->w[2] * f->w[2])) + f->r2; /* |w|² + r² */
    f->ad = CYL__BLOAD(p + 7 * CYL__BW) * q->dd, f->D = CYL__BFMA(f->r2, f->A, -(f->P * f->P));
}

/* The filter (the contract's "how"): of lanes p[j], those a scalar call might hit at a t in
   [tmin, min(tmax, best)]. Every test rejects only where certain, from bounds on its own
   rounding and the scalar call's (the standard model, each input exact); a NaN or an infinity
   rejects nothing. The tube: D = r²A − P² below the tangent band by more than those. Its t
   interval: tc ± √(|a|²D)/A with D, A and tc = −B/A each moved by their bounds against the
   interval. The slab: the axial coordinate z0 + tζ at both ends of that interval on one side of
   the cap planes by more than twice N9's bound at the farther end. */
CYL__ALWAYS void CYL__BP(filter)(const CYL__BK *p, const CYL__BP(q) *q, CYL__BK best, CYL__BP(m) *out)
{
    const CYL__BK u = CYL__BU;
    const CYL__BP(v) zero = {0};
    CYL__BP(tube) f;
    CYL__BP(v) B, z0, ze, tc, h, T, er, lo, hi, e, zl, zh, aa, Ha, na, nw, eD, eA, Am;
    CYL__BP(m) keep;
    CYL__BP(tube_of)(p, q, &f);
    /* the tube: kept unless D is below the band by more than its rounding and the scalar call's
       (each at most 16u|a|²|d|²(|w|² + r²), the standard model through s, w, A, P and r², less
       where the call works in double: CYL__BDERR) */
    eD = f.D + (CYL__BK)CYL__BTANG * f.r2 * f.A + (CYL__BK)CYL__BDERR * u * f.ad * f.S; /* D's most */
    keep = CYL__BNOT(eD < 0);
    *out = keep; /* r² = +inf (a cylinder out of range) keeps its lane: D, S and the bounds infinite or NaN */
    if (!CYL__BP(bits)(out)) return; /* the usual block: no more */
    aa = CYL__BLOAD(p + 7 * CYL__BW), Ha = CYL__BLOAD(p + 8 * CYL__BW), na = CYL__BLOAD(p + 9 * CYL__BW);
    B = CYL__BFMA(f.a[1] * f.w[2] - f.a[2] * f.w[1], f.s[0], CYL__BFMA(f.a[2] * f.w[0] - f.a[0] * f.w[2], f.s[1],
                  (f.a[0] * f.w[1] - f.a[1] * f.w[0]) * f.s[2])); /* m·s, m = a × w */
    z0 = f.a[0] * f.w[0] + f.a[1] * f.w[1] + f.a[2] * f.w[2], ze = f.a[0] * q->d[0] + f.a[1] * q->d[1] + f.a[2] * q->d[2];
    /* its t interval: every root or contact the scalar call can report is tc ± √(|a|²D)/A with its
       D at most eD above, its A at least A − eA, its tc = −B/A within er, B and A erring by at
       most 8u|a|²|w||d| and 8.2u|a|²|d|² each (the standard model, as D's); A <= eA: unbounded */
    nw = CYL__BABS(f.w[0]) + CYL__BABS(f.w[1]) + CYL__BABS(f.w[2]); /* >= |w| */
    eA = (CYL__BK)(CYL__BDERR / 2) * u * f.ad, Am = f.A - eA;
    e = 1 / f.A, tc = -B * e, h = CYL__BSEL(eD < zero, zero, eD) * aa; /* a NaN stays one (not BMAX) */
    CYL__BP(sqrt)(&h), h = h * (1 + 4 * u) / Am;
    er = ((CYL__BK)(CYL__BDERR / 2) * u * aa * nw * q->nd + CYL__BABS(tc) * eA) / Am + 4 * u * (CYL__BABS(tc) + h);
    er = CYL__BSEL(Am > 0, er + h, zero + (CYL__BK)CYL__HUGE); /* the half width */
    lo = CYL__BMAX(tc - er, zero + q->tmin);
    hi = CYL__BMIN(tc + er, zero + (best < q->tmax ? best : q->tmax));
    keep &= CYL__BNOT(lo > hi);
    /* the slab: z0 + tζ at lo and hi, beyond one cap plane by more than twice N9's bound */
    T = CYL__BMAX(CYL__BABS(lo), CYL__BABS(hi));
    e = 2 * (64 * u * (na * nw + Ha + T * na * q->nd) + 2 * u * T * CYL__BABS(ze)) + Ha;
    zl = z0 + lo * ze, zh = z0 + hi * ze;
    keep &= CYL__BNOT(((zl > e) & (zh > e)) | ((zl < -e) & (zh < -e)));
    *out = keep;
}

/* t·2^k (t in the units of the scaled d) where that is exact, else the side's infinity. */
CYL__ALWAYS CYL__BK CYL__BP(tscale)(CYL__BK t, int k, CYL__BK inf)
{
    CYL__BK y = CYL__BS(scale)(t, k), z = CYL__BS(scale)(y, -k);
    return !(z < t) && !(z > t) ? y : inf;
}

/* The ray in the filter's type; 0 where the filter's bounds could overflow (then every cylinder is asked). */
CYL__ALWAYS int CYL__BP(query)(CYL__BP(q) *q, const CYL__BN(ray) *ray)
{
    CYL__BK om = 0, dm = 0, x;
    int i;
    for (i = 0; i < 3; i++) {
        q->o[i] = ray->o[i];
        x = q->o[i] < 0 ? -q->o[i] : q->o[i], om = x > om ? x : om;
        x = ray->d[i] < 0 ? -ray->d[i] : ray->d[i], dm = x > dm ? x : dm;
    }
    q->kd = CYL__BS(expo)(dm); /* d nonzero (validated, or CYL_TRUSTED's promise) */
    for (i = 0; i < 3; i++) q->d[i] = CYL__BS(scale)(ray->d[i], -q->kd);
    x = q->d[0] * q->d[0] + q->d[1] * q->d[1] + q->d[2] * q->d[2];
    q->nd = CYL__BSQRT1(x) * (1 + 4 * CYL__BU), q->dd = x;
    q->tmin = CYL__BP(tscale)(ray->tmin, q->kd, -(CYL__BK)CYL__HUGE), q->tmax = CYL__BP(tscale)(ray->tmax, q->kd, (CYL__BK)CYL__HUGE);
    return om <= CYL__BLIM_P;
}

/* The candidates of block k of b (bit j: its j-th cylinder), all of them where the ray is out of range. */
CYL__ALWAYS unsigned CYL__BP(block_of)(const CYL__BN(batch) *b, size_t k, const CYL__BP(q) *q, int inrange, CYL__BK best)
{
    const CYL__BK *p = b->blocks + k * (CYL__BF * CYL__BW);
    const size_t left = b->n - k * CYL__BW;
    unsigned m = (2u << (CYL__BW - 1)) - 1u, j;
    CYL__BP(m) keep;
    if (inrange) CYL__BUNROLL for (m = 0u, j = 0; j < CYL__BW; j += CYL__BL) CYL__BP(filter)(p + j, q, best, &keep), m |= CYL__BP(bits)(&keep) << j;
    return left < CYL__BW ? m & ((1u << left) - 1u) : m; /* the padding lanes are no cylinders */
}

/* The lowest set bit's index (m nonzero). */
CYL__ALWAYS int CYL__BP(ctz)(unsigned m)
{
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_ctz(m);
#else
    int j = 0;
    while (!(m & 1u)) m >>= 1, j++;
    return j;
#endif
}

CYL_DEF size_t CYL__BN(batch_bytes)(size_t n)
{
    const size_t blk = CYL__BF * CYL__BW * sizeof(CYL__BK), per = CYL__BF * sizeof(CYL__BK) + sizeof(CYL__BN(cylinder));
    if (n > (SIZE_MAX - 63 - blk) / per) return 0;
    return 63 + (n / CYL__BW + (n % CYL__BW != 0)) * blk + n * sizeof(CYL__BN(cylinder));
}

CYL_DEF int CYL__BN(batch_build)(CYL__BN(batch) *b, void *mem, const CYL__BN(cylinder) *cyls, size_t n)
{
    static const CYL__BN(ray) probe = {{0, 0, 0}, {1, 0, 0}, 0, 1};
    const size_t nb = n / CYL__BW + (n % CYL__BW != 0);
    CYL__BK *blocks, v[CYL__BF], m;
    CYL__BN(cylinder) *copy;
    size_t i, k;
    int rc, f;
    if (!b || (n && (!mem || !cyls))) return CYL_E_NULL;
    for (i = 0; i < n; i++)
        if ((rc = CYL__BS(validate)(&probe, &cyls[i], 0u)) != 0) return rc;
    if (!n) return b->blocks = NULL, b->cyls = NULL, b->n = b->nb = 0, 0;
    blocks = (CYL__BK *)(void *)((unsigned char *)mem + ((64u - (unsigned)((uintptr_t)mem & 63u)) & 63u));
    copy = (CYL__BN(cylinder) *)(void *)(blocks + nb * (CYL__BF * CYL__BW));
    for (i = 0; i < nb * CYL__BW; i++) { /* the padding lanes repeat the last cylinder */
        const CYL__BN(cylinder) *cy = &cyls[i < n ? i : n - 1];
        CYL__BK H = (CYL__BK)cy->h * (CYL__BK)0.5, r = (CYL__BK)cy->r, sa;
        int in = r >= CYL__BLIM_R && r <= CYL__BLIM_P && ((H >= 1 / CYL__BLIM_H && H <= CYL__BLIM_H) || !(H < (CYL__BK)CYL__HUGE)), ka;
        for (m = 0, k = 0; k < 3; k++) {
            v[k] = cy->c[k], v[3 + k] = cy->a[k];
            in &= v[k] <= CYL__BLIM_P && v[k] >= -CYL__BLIM_P;
            m = v[3 + k] > m ? v[3 + k] : -v[3 + k] > m ? -v[3 + k] : m;
        }
        for (ka = CYL__BS(expo)(m), k = 0; k < 3; k++) v[3 + k] = CYL__BS(scale)(v[3 + k], -ka); /* largest in [1, 2) */
        v[6] = r * r, v[7] = v[3] * v[3] + v[4] * v[4] + v[5] * v[5];
        sa = CYL__BSQRT1(v[7]);
        v[8] = H * sa, v[9] = sa * (1 + 4 * CYL__BU);
        if (!in) v[6] = v[8] = (CYL__BK)CYL__HUGE; /* r² and H|a| infinite: always asked */
        for (f = 0; f < CYL__BF; f++) blocks[(i / CYL__BW) * (CYL__BF * CYL__BW) + (size_t)f * CYL__BW + i % CYL__BW] = v[f];
    }
    for (i = 0; i < n; i++) copy[i] = cyls[i];
    b->blocks = blocks, b->cyls = copy, b->n = n, b->nb = nb;
    return 0;
}

/* A query's start: the ray's and the options' errors as the scalar call gives them (on a valid
   cylinder), else 0 and the ray in the filter's type, *inrange 0 where every cylinder is asked. */
CYL__ALWAYS int CYL__BP(start)(const CYL__BN(ray) *ray, unsigned opts, CYL__BP(q) *q, int *inrange)
{
    static const CYL__BN(cylinder) unit = {{0, 0, 0}, {0, 0, 1}, 1, 1};
    int rc = CYL__BS(validate)(ray, &unit, opts);
    if (!rc) *inrange = CYL__BP(query)(q, ray);
    return rc;
}

CYL_DEF int CYL__BN(batch_nearest)(const CYL__BN(batch) *b, const CYL__BN(ray) *ray, unsigned opts, size_t *index, CYL__BR *t)
{
    CYL__BP(q) q;
    CYL__BN(hit) hit;
    CYL__BR bt = 0;
    size_t k, i, found = 0;
    int rc, got = 0, inrange = 0;
    CYL__BK bk;
    unsigned m;
    if (!b || !ray || !index || !t) return CYL_E_NULL;
    if ((rc = CYL__BP(start)(ray, opts, &q, &inrange)) != 0) return rc;
    for (bk = q.tmax, k = 0; k < b->nb; k++)
        for (m = CYL__BP(block_of)(b, k, &q, inrange, bk); m; m &= m - 1u) {
            i = k * CYL__BW + (size_t)CYL__BP(ctz)(m);
            if (CYL__BN(intersect)(ray, &b->cyls[i], opts, &hit) == CYL_HIT && (!got || hit.t < bt))
                bt = hit.t, found = i, got = 1, bk = CYL__BP(tscale)(bt, q.kd, (CYL__BK)CYL__HUGE);
        }
    if (got) *index = found, *t = bt;
    return got;
}

CYL_DEF int CYL__BN(batch_any)(const CYL__BN(batch) *b, const CYL__BN(ray) *ray, unsigned opts)
{
    CYL__BP(q) q;
    size_t k;
    int rc, inrange = 0;
    unsigned m;
    if (!b || !ray) return CYL_E_NULL;
    if ((rc = CYL__BP(start)(ray, opts, &q, &inrange)) != 0) return rc;
    for (k = 0; k < b->nb; k++)
        for (m = CYL__BP(block_of)(b, k, &q, inrange, q.tmax); m; m &= m - 1u)
            if (CYL__BN(occluded)(ray, &b->cyls[k * CYL__BW + (size_t)CYL__BP(ctz)(m)], opts) == 1) return 1;
    return 0;
}

#undef CYL__BN
#undef CYL__BP
#undef CYL__BS
#undef CYL__BR
#undef CYL__BK
#undef CYL__BI
#undef CYL__BW
#undef CYL__BU
#undef CYL__BLIM
#undef CYL__BLIM_P
#undef CYL__BLIM_R
#undef CYL__BLIM_H
#undef CYL__BDERR
#undef CYL__BF
#undef CYL__BSQRT1
#undef CYL__BL
#undef CYL__BLOAD
#undef CYL__BSEL
#undef CYL__BNOT
#undef CYL__BUNROLL
#undef CYL__BMM
#undef CYL__BMD
#undef CYL__BMS
#undef CYL__BABS
#undef CYL__BFMA
#undef CYL__BMAX
#undef CYL__BMIN
#undef CYL__BTANG
#undef CYL__BBODY
#endif /* one API's batch */
