/* fuzz_check.h: how a fuzz input becomes a call of cylinder_isect.h, and every invariant the
 * result must satisfy. Shared by the libFuzzer harness (fuzz_isect.c, aborts on a violation) and
 * the plain replay driver (replay.c, a Unity runner: a violation fails the test).
 *
 * Input layout (docs/fuzzing.md has the details):
 *   byte 0  bit 0     precision: 0 float (cylf_), 1 double (cyld_)
 *           bits 1-2  function: 0 intersect, 1 intersect_all, 2 occluded,
 *                     3 cyl*_from_segment(p0 = c, p1 = a, r) then intersect_all
 *           bits 3-5  NULL pointer: 5 ray, 6 cylinder, 7 hit; anything else none
 *                     (function 3: 5 and 6 make from_segment's p0 / p1 NULL instead)
 *           bit 6     always run the exact-reference check (otherwise a hash samples 1 in 16)
 *   byte 1            option bits 0..7 (bit 7 is unknown to the library)
 *   byte 2            if bit 7 is set, option bit (byte2 & 31) is also set (unknown bits)
 *   byte 3            an arbitrary code for cyl_strerror (as a signed char)
 *   then 16 numbers, raw bits, native byte order, 4 bytes (float) or 8 (double) each:
 *     o[3] d[3] tmin tmax c[3] a[3] r h      (missing bytes read as 0)
 * Raw bits mean NaN payloads, infinities, subnormals and -0 all reach the library.
 */
#ifndef FUZZ_CHECK_H
#define FUZZ_CHECK_H

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cylinder_isect.h"

/* What a violation does: abort in the fuzzer (libFuzzer saves the input), fail the Unity test in
 * the replay driver. FZ_FAIL must not return. */
#ifndef FZ_FAIL
#define FZ_FAIL(msg) (fputs((msg), stderr), fputc('\n', stderr), abort())
#endif

/* Helpers that one of the including programs may not use. */
#if defined(__GNUC__) || defined(__clang__)
#define FZ_UNUSED __attribute__((unused))
#else
#define FZ_UNUSED
#endif

#define FZ_HEADER_BYTES 4
#define FZ_NUMS 16

/* Checks are evaluated in long double: 64-bit significand on x86-64, so float inputs give exact
 * products and double inputs keep 11 guard bits. FZ_U_EVAL is its unit roundoff; every slack
 * below that uses it covers our own evaluation error, never the library's. */
typedef long double fz_real;
#define FZ_U_EVAL ((fz_real)LDBL_EPSILON * 0.5L)

/* Unit roundoff of the library's two precisions. */
#define FZ_U_F ((fz_real)FLT_EPSILON * 0.5L)
#define FZ_U_D ((fz_real)DBL_EPSILON * 0.5L)

/* |n| must be 1 within this many units of roundoff of the precision ("a few ulps"): normalising
 * costs a square root, a division and three products, each within one rounding. */
#define FZ_NORM_ULPS 8.0L
/* A dot product of the returned n with d, recomputed here, may exceed the library's computed
 * value by gamma_3 |n||d| (Higham, ch. 3): n.d <= 0 is checked with this many roundoffs. */
#define FZ_DOT_ULPS 4.0L
/* Direction of a wall normal: the library forms it from the hit point relative to the axis,
 * whose components carry a rounding error of order u (|w| + |t d|) against a length r. */
#define FZ_NDIR_ULPS 16.0L
/* Our own evaluation of a hit point's distance to the axis and axial coordinate: a handful of
 * long double roundings relative to the magnitudes involved (|o|+|c|+|t d|+r). */
#define FZ_EVAL_ULPS 32.0L
/* A hit-or-miss decision (rim of a cap) made on rounded data may err by a few roundings of the
 * magnitudes it is made from: "a decision farther than a few ulps from its boundary must be
 * right" (NUMERICS.md). */
#define FZ_DECIDE_ULPS 16.0L

typedef struct fz_input {
  int dbl;            /* 1: cyld_, 0: cylf_ */
  int func;           /* 0 intersect, 1 intersect_all, 2 occluded, 3 from_segment + all */
  int nullsel;        /* 0 none, 1 ray, 2 cylinder, 3 hit */
  int force_ref;      /* 1: always run the exact-reference check */
  unsigned opts;      /* option bits as given, unknown bits included */
  int errcode;        /* argument for cyl_strerror */
  float f[FZ_NUMS];   /* native values (bits copied) */
  double d[FZ_NUMS];
} fz_input;

/* Index of each number in f[] / d[]. */
enum { FZ_O = 0, FZ_D = 3, FZ_TMIN = 6, FZ_TMAX = 7, FZ_C = 8, FZ_A = 11, FZ_R = 14, FZ_H = 15 };

/* A result in a precision-free form: every float and double converts exactly to long double. */
typedef struct fz_hit {
  fz_real t, t_err, n[3], v;
  int part;
  unsigned flags;
} fz_hit;

typedef struct fz_res {
  int rc;
  fz_hit h[2];
} fz_res;

/* The problem actually handed to the library, exactly, in long double. */
typedef struct fz_prob {
  int dbl;
  fz_real o[3], d[3], tmin, tmax, c[3], a[3], r, h;
} fz_prob;

/* ---------------------------------------------------------------- failure reporting */
static char fz_ctx[1024];

static void fz_failf(const char *fmt, ...)
{
  static char msg[2048];
  va_list ap;
  int k;
  va_start(ap, fmt);
  k = vsnprintf(msg, sizeof msg, fmt, ap);
  va_end(ap);
  if (k >= 0 && (size_t)k < sizeof msg)
    snprintf(msg + k, sizeof msg - (size_t)k, " | %s", fz_ctx);
  FZ_FAIL(msg);
}

static void fz_describe(const fz_input *in)
{
  static const char *const fn[4] = {"intersect", "intersect_all", "occluded", "from_segment"};
  int k = snprintf(fz_ctx, sizeof fz_ctx, "%s %s opts=0x%x null=%d nums:", in->dbl ? "double" : "float",
                   fn[in->func], in->opts, in->nullsel);
  int i;
  for (i = 0; i < FZ_NUMS && k >= 0 && (size_t)k < sizeof fz_ctx; i++)
    k += snprintf(fz_ctx + k, sizeof fz_ctx - (size_t)k, " %a", in->dbl ? in->d[i] : (double)in->f[i]);
}

/* ---------------------------------------------------------------- decoding */
static void fz_decode(const unsigned char *data, size_t size, fz_input *in)
{
  unsigned char hdr[FZ_HEADER_BYTES] = {0, 0, 0, 0};
  unsigned char nums[FZ_NUMS * 8];
  size_t i, nb;
  for (i = 0; i < FZ_HEADER_BYTES && i < size; i++) hdr[i] = data[i];
  memset(in, 0, sizeof *in);
  in->dbl = hdr[0] & 1;
  in->func = (hdr[0] >> 1) & 3;
  switch ((hdr[0] >> 3) & 7) {
  case 5: in->nullsel = 1; break;
  case 6: in->nullsel = 2; break;
  case 7: in->nullsel = 3; break;
  default: in->nullsel = 0; break;
  }
  in->force_ref = (hdr[0] >> 6) & 1;
  in->opts = hdr[1];
  if (hdr[2] & 0x80) in->opts |= 1u << (hdr[2] & 31);
  in->errcode = (int)(signed char)hdr[3];
  nb = (size_t)FZ_NUMS * (in->dbl ? 8u : 4u);
  memset(nums, 0, sizeof nums);
  if (size > FZ_HEADER_BYTES) {
    size_t avail = size - FZ_HEADER_BYTES;
    memcpy(nums, data + FZ_HEADER_BYTES, avail < nb ? avail : nb);
  }
  if (in->dbl) memcpy(in->d, nums, sizeof in->d);
  else memcpy(in->f, nums, sizeof in->f);
}

/* Inverse of fz_decode, for the seed generator and the regression tests. */
FZ_UNUSED static size_t fz_encode(const fz_input *in, unsigned char *out, size_t cap)
{
  size_t nb = (size_t)FZ_NUMS * (in->dbl ? 8u : 4u);
  unsigned hb = 0, extra = 0;
  if (cap < FZ_HEADER_BYTES + nb) return 0;
  switch (in->nullsel) {
  case 1: hb = 5; break;
  case 2: hb = 6; break;
  case 3: hb = 7; break;
  default: hb = 0; break;
  }
  if (in->opts & ~0xffu) {
    unsigned b;
    for (b = 8; b < 32; b++)
      if (in->opts & (1u << b)) { extra = 0x80u | b; break; }
  }
  out[0] = (unsigned char)((unsigned)in->dbl | ((unsigned)in->func << 1) | (hb << 3) |
                           ((unsigned)in->force_ref << 6));
  out[1] = (unsigned char)(in->opts & 0xffu);
  out[2] = (unsigned char)extra;
  out[3] = (unsigned char)(signed char)in->errcode;
  if (in->dbl) memcpy(out + FZ_HEADER_BYTES, in->d, nb);
  else memcpy(out + FZ_HEADER_BYTES, in->f, nb);
  return FZ_HEADER_BYTES + nb;
}

/* ---------------------------------------------------------------- small helpers */
/* Bitwise identity of two long doubles that came from the same precision (x87 padding bytes are
 * never compared: both sides go through the same conversion). */
static int fz_same(fz_real x, fz_real y)
{
  if (isnan(x) || isnan(y)) return isnan(x) && isnan(y);
  return !(x < y) && !(x > y) && signbit(x) == signbit(y);
}
static int fz_eq(fz_real x, fz_real y) { return !(x < y) && !(x > y); }

static fz_real fz_dot(const fz_real *x, const fz_real *y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }
static void fz_cross(const fz_real *x, const fz_real *y, fz_real *z)
{
  z[0] = x[1] * y[2] - x[2] * y[1];
  z[1] = x[2] * y[0] - x[0] * y[2];
  z[2] = x[0] * y[1] - x[1] * y[0];
}
/* y = x over its largest component (x itself where that is 0 or not finite), and that scale:
 * norms from y neither overflow nor underflow where long double is double (armhf), whose range
 * the squares of extreme double inputs leave, and keep their bits for subnormal x. */
static fz_real fz_prescale(const fz_real *x, fz_real *y)
{
  fz_real m = fmaxl(fmaxl(fabsl(x[0]), fabsl(x[1])), fabsl(x[2]));
  int i;
  if (!(m > 0) || !isfinite(m)) m = 1;
  for (i = 0; i < 3; i++) y[i] = x[i] / m;
  return m;
}
/* |x| */
static fz_real fz_norm(const fz_real *x)
{
  fz_real y[3], m = fz_prescale(x, y);
  return m * sqrtl(fz_dot(y, y));
}
/* x/|x|, from the prescaled components: a subnormal |x| would keep only a subnormal's bits
 * (2^-39 of them for an axis of 2^-1036), which the unit axis would carry into every distance
 * from it. */
static void fz_unit(const fz_real *x, fz_real *u)
{
  fz_real y[3], n;
  int i;
  fz_prescale(x, y);
  n = sqrtl(fz_dot(y, y));
  for (i = 0; i < 3; i++) u[i] = y[i] / n;
}
static fz_real fz_abssum(const fz_real *x) { return fabsl(x[0]) + fabsl(x[1]) + fabsl(x[2]); }

static int fz_isfinite_all(const fz_real *x, int n)
{
  int i;
  for (i = 0; i < n; i++)
    if (!isfinite(x[i])) return 0;
  return 1;
}

/* ---------------------------------------------------------------- what the library must say */
#define FZ_KNOWN_OPTS                                                                          \
  ((unsigned)(CYL_CAPS | CYL_OUTWARD | CYL_NO_TANGENT | CYL_PRECISE | CYL_NO_NORMAL |          \
              CYL_NO_ERRBOUND | CYL_TRUSTED))

/* Expected status, straight from the contract's list, checked in the documented order. */
static int fz_expected_error(const fz_input *in, unsigned opts, int no_hit_arg)
{
  fz_real v[FZ_NUMS];
  int i;
  for (i = 0; i < FZ_NUMS; i++) v[i] = in->dbl ? (fz_real)in->d[i] : (fz_real)in->f[i];
  if (in->nullsel == 1 || in->nullsel == 2 || (in->nullsel == 3 && !no_hit_arg)) return CYL_E_NULL;
  for (i = 0; i < 6; i++)
    if (!isfinite(v[FZ_O + i])) return CYL_E_NONFINITE;
  for (i = 0; i < 6; i++)
    if (!isfinite(v[FZ_C + i])) return CYL_E_NONFINITE;
  if (fz_eq(v[FZ_D], 0) && fz_eq(v[FZ_D + 1], 0) && fz_eq(v[FZ_D + 2], 0)) return CYL_E_ZERO_DIR;
  if (fz_eq(v[FZ_A], 0) && fz_eq(v[FZ_A + 1], 0) && fz_eq(v[FZ_A + 2], 0)) return CYL_E_ZERO_AXIS;
  if (!(v[FZ_R] > 0) || isinf(v[FZ_R])) return CYL_E_RADIUS;
  if (!(v[FZ_H] > 0)) return CYL_E_HEIGHT;
  if (isnan(v[FZ_TMIN]) || isnan(v[FZ_TMAX]) || v[FZ_TMIN] > v[FZ_TMAX]) return CYL_E_TRANGE;
  if (opts & ~FZ_KNOWN_OPTS) return CYL_E_OPTION;
#ifdef CYL_NO_PRECISE
  if (opts & CYL_PRECISE) return CYL_E_OPTION;
#endif
  return 0;
}

static int fz_precise_available(void)
{
#ifdef CYL_NO_PRECISE
  return 0;
#else
  return 1;
#endif
}

/* ---------------------------------------------------------------- calling the library */
/* Sentinel written into the output structs before each call: on a miss or an error they must
 * come back byte-for-byte identical. */
#define FZ_SENTINEL 0x5b

#define FZ_DEFINE_CALL(P, T, SUFFIX)                                                            \
  static void fz_conv_##SUFFIX(const P##_hit *h, fz_hit *o)                                     \
  {                                                                                             \
    o->t = (fz_real)h->t;                                                                       \
    o->t_err = (fz_real)h->t_err;                                                               \
    o->n[0] = (fz_real)h->n[0];                                                                 \
    o->n[1] = (fz_real)h->n[1];                                                                 \
    o->n[2] = (fz_real)h->n[2];                                                                 \
    o->v = (fz_real)h->v;                                                                       \
    o->part = h->part;                                                                          \
    o->flags = h->flags;                                                                        \
  }                                                                                             \
  /* func: 0 intersect, 1 intersect_all, 2 occluded. raw (may be NULL) receives the native      \
   * output bytes, so that two calls can be compared byte for byte. */                          \
  static fz_res fz_call_##SUFFIX(int func, const P##_ray *ray, const P##_cylinder *cyl,         \
                                 unsigned opts, int null_hit, P##_hit raw[2])                   \
  {                                                                                             \
    P##_hit hits[2], ref[2];                                                                    \
    fz_res res;                                                                                 \
    memset(&res, 0, sizeof res);                                                                \
    memset(hits, FZ_SENTINEL, sizeof hits);                                                     \
    memset(ref, FZ_SENTINEL, sizeof ref);                                                       \
    if (func == 0) res.rc = P##_intersect(ray, cyl, opts, null_hit ? NULL : &hits[0]);          \
    else if (func == 1) res.rc = P##_intersect_all(ray, cyl, opts, null_hit ? NULL : hits);     \
    else res.rc = P##_occluded(ray, cyl, opts);                                                 \
    if (func != 2 && res.rc <= 0 && memcmp(hits, ref, sizeof hits) != 0)                        \
      fz_failf("%s returned %d but wrote into its output",                                      \
               func == 0 ? #P "_intersect" : #P "_intersect_all", res.rc);                      \
    if (func == 0 && memcmp(&hits[1], &ref[1], sizeof hits[1]) != 0)                            \
      fz_failf(#P "_intersect wrote past its single hit");                                      \
    if (func == 1 && res.rc == 1 && memcmp(&hits[1], &ref[1], sizeof hits[1]) != 0)             \
      fz_failf(#P "_intersect_all returned 1 but wrote hits[1]");                               \
    if (res.rc > 0 && func != 2) {                                                              \
      fz_conv_##SUFFIX(&hits[0], &res.h[0]);                                                    \
      if (res.rc > 1) fz_conv_##SUFFIX(&hits[1], &res.h[1]);                                    \
    }                                                                                           \
    if (raw) memcpy(raw, hits, sizeof hits);                                                    \
    return res;                                                                                 \
  }                                                                                             \
  static void fz_build_##SUFFIX(const T *x, P##_ray *ray, P##_cylinder *cyl)                   \
  {                                                                                             \
    int i;                                                                                      \
    for (i = 0; i < 3; i++) {                                                                   \
      ray->o[i] = x[FZ_O + i];                                                                  \
      ray->d[i] = x[FZ_D + i];                                                                  \
      cyl->c[i] = x[FZ_C + i];                                                                  \
      cyl->a[i] = x[FZ_A + i];                                                                  \
    }                                                                                           \
    ray->tmin = x[FZ_TMIN];                                                                     \
    ray->tmax = x[FZ_TMAX];                                                                     \
    cyl->r = x[FZ_R];                                                                           \
    cyl->h = x[FZ_H];                                                                           \
  }                                                                                             \
  static void fz_prob_##SUFFIX(const P##_ray *ray, const P##_cylinder *cyl, fz_prob *p)        \
  {                                                                                             \
    int i;                                                                                      \
    p->dbl = (int)(sizeof(T) == sizeof(double));                                                \
    for (i = 0; i < 3; i++) {                                                                   \
      p->o[i] = (fz_real)ray->o[i];                                                             \
      p->d[i] = (fz_real)ray->d[i];                                                             \
      p->c[i] = (fz_real)cyl->c[i];                                                             \
      p->a[i] = (fz_real)cyl->a[i];                                                             \
    }                                                                                           \
    p->tmin = (fz_real)ray->tmin;                                                               \
    p->tmax = (fz_real)ray->tmax;                                                               \
    p->r = (fz_real)cyl->r;                                                                     \
    p->h = (fz_real)cyl->h;                                                                     \
  }

#ifndef CYL_NO_FLOAT
FZ_DEFINE_CALL(cylf, float, f)
#endif
#ifndef CYL_NO_DOUBLE
FZ_DEFINE_CALL(cyld, double, d)
#endif

/* ---------------------------------------------------------------- geometry of one problem */
typedef struct fz_geo {
  fz_real ah[3];   /* unit axis */
  fz_real w[3];    /* o - c */
  fz_real axd[3];  /* ah x d */
  fz_real axw[3];  /* ah x w */
  fz_real nd;      /* |d| */
  fz_real sd;      /* |ah x d| = |d| sin(theta) */
  fz_real sin_th;  /* sin of the angle between d and the axis */
  fz_real H;       /* h/2 */
  fz_real mag;     /* |o| + |c| + r: magnitudes that enter a hit point's evaluation */
  int ok;          /* everything above finite */
} fz_geo;

static void fz_geometry(const fz_prob *p, fz_geo *g)
{
  int i;
  fz_unit(p->a, g->ah);
  for (i = 0; i < 3; i++) g->w[i] = p->o[i] - p->c[i];
  fz_cross(g->ah, p->d, g->axd);
  fz_cross(g->ah, g->w, g->axw);
  g->nd = fz_norm(p->d);
  g->sd = fz_norm(g->axd);
  g->sin_th = g->sd / g->nd;
  g->H = p->h * 0.5L;
  g->mag = fz_abssum(p->o) + fz_abssum(p->c) + p->r;
  g->ok = fz_isfinite_all(g->ah, 3) && fz_isfinite_all(g->w, 3) && fz_isfinite_all(g->axd, 3) &&
          fz_isfinite_all(g->axw, 3) && isfinite(g->nd) && g->nd > 0 && isfinite(g->mag);
}

/* Point of the ray at t relative to c, its axial coordinate and its distance to the axis, plus
 * an upper bound of our own evaluation error on both. Returns 0 if not representable. */
static int fz_point(const fz_prob *p, const fz_geo *g, fz_real t, fz_real *v, fz_real *rho, fz_real *slack)
{
  fz_real x[3], q[3];
  int i;
  for (i = 0; i < 3; i++) x[i] = (p->o[i] + t * p->d[i]) - p->c[i];
  *v = fz_dot(g->ah, x);
  fz_cross(g->ah, x, q);
  *rho = fz_norm(q);
  *slack = FZ_EVAL_ULPS * FZ_U_EVAL * (g->mag + fabsl(t) * fz_abssum(p->d));
  return isfinite(*v) && isfinite(*rho) && isfinite(*slack);
}

/* e = 1 - rho^2/r^2 of the ray line, rho its distance to the axis line; and an evaluation
 * error bound. For a parallel ray rho is |ah x w|. */
static fz_real fz_max3abs(const fz_real x[3])
{
  fz_real m = fabsl(x[0]);
  if (fabsl(x[1]) > m) m = fabsl(x[1]);
  if (fabsl(x[2]) > m) m = fabsl(x[2]);
  return m;
}

static fz_real fz_tangent_e(const fz_prob *p, const fz_geo *g, fz_real *err)
{
  fz_real rho;
  if (g->sd > 0) {
    fz_real nn[3];
    int i;
    for (i = 0; i < 3; i++) nn[i] = g->axd[i] / g->sd;
    rho = fabsl(fz_dot(g->w, nn));
  } else {
    rho = fz_norm(g->axw);
  }
  /* rho = |w . (ah x d)|/|ah x d|: the long double cross product of nearly parallel ah and d
     has a relative error of about u/sin(theta), which the w term carries into rho */
  *err = FZ_EVAL_ULPS * FZ_U_EVAL *
         (fz_abssum(g->w) / (g->sin_th > 0 ? g->sin_th : 1) + p->r) / p->r * (1 + rho / p->r) * 4;
  return (1 - rho / p->r) * (1 + rho / p->r);
}

/* ---------------------------------------------------------------- one hit */
static void fz_check_hit(const char *what, const fz_prob *p, const fz_geo *g, unsigned opts, const fz_hit *h)
{
  fz_real u = p->dbl ? FZ_U_D : FZ_U_F;
  fz_real tan_tol = p->dbl ? (fz_real)CYL_TANGENT_TOL : (fz_real)CYL_TANGENT_TOLF;
  fz_real par_tol = p->dbl ? (fz_real)CYL_PARALLEL_TOL : (fz_real)CYL_PARALLEL_TOLF;
  fz_real v, rho, slack, te;

  if (h->part != CYL_SIDE && h->part != CYL_CAP_LOW && h->part != CYL_CAP_HIGH)
    fz_failf("%s: part %d is not a documented part", what, h->part);
  if (!(opts & CYL_CAPS) && h->part != CYL_SIDE)
    fz_failf("%s: cap hit (part %d) without CYL_CAPS", what, h->part);
  if (h->flags & ~(unsigned)(CYL_F_INSIDE | CYL_F_TANGENT | CYL_F_PARALLEL))
    fz_failf("%s: undocumented flag bits 0x%x", what, h->flags);
  if ((opts & CYL_NO_TANGENT) && (h->flags & CYL_F_TANGENT))
    fz_failf("%s: tangent hit reported under CYL_NO_TANGENT", what);
  if ((h->flags & CYL_F_PARALLEL) && h->part == CYL_SIDE)
    fz_failf("%s: wall hit on a ray flagged parallel", what);

  /* t within the accepted range, inclusive. */
  if (!(h->t >= p->tmin && h->t <= p->tmax))
    fz_failf("%s: t=%La outside [tmin, tmax]=[%La, %La]", what, h->t, p->tmin, p->tmax);
  if (opts & CYL_NO_ERRBOUND) {
    if (!(isinf(h->t_err) && h->t_err > 0)) fz_failf("%s: t_err=%La under CYL_NO_ERRBOUND, not +inf", what, h->t_err);
  } else if (!(h->t_err >= 0)) {
    fz_failf("%s: t_err=%La is negative or NaN", what, h->t_err);
  }

  /* v within [-h/2, h/2], and equal to +-h/2 on a cap. */
  if (!(h->v >= -g->H && h->v <= g->H)) fz_failf("%s: v=%La outside [-h/2, h/2], h/2=%La", what, h->v, g->H);

  /* Flags against the exact geometry, where our evaluation decides clearly, and outside the
     header's documented needle regime: r below 2^-31 (float) / 2^-435 (double) of |o - c|,
     where r^2 underflows in the library's frame, the wall test compares distances linearly
     and every hit carries t_err = +inf (classification not guaranteed there). */
  if (g->ok && !(p->r < ldexpl(fz_max3abs(g->w), p->dbl ? -434 : -30))) {
    fz_real eerr, e = fz_tangent_e(p, g, &eerr);
    if (isfinite(e) && isfinite(eerr) && h->part == CYL_SIDE) {
      fz_real band = tan_tol + 64 * u * (fz_abssum(g->w) + p->r) / p->r + eerr;
      /* v2's default tier computes e from the plain o - c, whose rounding u|o - c| moves the
         line's distance rho from the axis: 2 rho/r times that in e (v2's N6) */
      if (CYL_VERSION_MAJOR >= 2 && !(opts & CYL_PRECISE))
        band += 128 * u * (fz_abssum(g->w) + p->r) / p->r * sqrtl(fabsl(1 - e));
      if ((h->flags & CYL_F_TANGENT) && fabsl(e) > 2 * band)
        fz_failf("%s: flagged tangent but e=1-rho^2/r^2=%Lg is far outside the band %Lg", what, e, tan_tol);
      if (!(h->flags & CYL_F_TANGENT) && e < -2 * band)
        fz_failf("%s: wall hit on a ray that misses the cylinder (e=%Lg)", what, e);
    }
    if ((h->flags & CYL_F_PARALLEL) && g->sin_th > 2 * par_tol + 16 * u)
      fz_failf("%s: flagged parallel but sin(theta)=%Lg", what, g->sin_th);
    if (!(h->flags & CYL_F_PARALLEL) && fz_eq(g->sd, 0))
      fz_failf("%s: exactly axis-parallel ray not flagged parallel", what);
  }

  /* Normal: zero on request, else unit length. */
  if (opts & CYL_NO_NORMAL) {
    if (!fz_eq(h->n[0], 0) || !fz_eq(h->n[1], 0) || !fz_eq(h->n[2], 0))
      fz_failf("%s: n=(%La,%La,%La) under CYL_NO_NORMAL", what, h->n[0], h->n[1], h->n[2]);
  } else {
    fz_real nn = fz_norm(h->n);
    if (!(fabsl(nn - 1) <= FZ_NORM_ULPS * u))
      fz_failf("%s: |n|=%.21Lg is not 1 within %Lg ulps", what, nn, FZ_NORM_ULPS);
    if (g->ok) {
      fz_real nd = fz_dot(h->n, p->d);
      fz_real tol = FZ_DOT_ULPS * u * nn * g->nd;
      if (!(opts & CYL_OUTWARD) && !(nd <= tol))
        fz_failf("%s: ray-facing normal has n.d=%Lg > 0 (|d|=%Lg)", what, nd, g->nd);
      if (h->part == CYL_SIDE) {
        fz_real na = fz_dot(h->n, g->ah);
        fz_real dir_tol = FZ_NDIR_ULPS * u * (1 + (fz_abssum(g->w) + fabsl(h->t) * fz_abssum(p->d)) / p->r);
        if (!(fabsl(na) <= dir_tol)) fz_failf("%s: wall normal not orthogonal to the axis: n.a=%Lg", what, na);
      } else {
        fz_real na = fz_dot(h->n, g->ah);
        fz_real want = (h->part == CYL_CAP_HIGH) ? 1 : -1;
        if ((opts & CYL_OUTWARD) && !(na * want >= 1 - FZ_NDIR_ULPS * u))
          fz_failf("%s: outward cap normal n.a=%Lg, want %Lg", what, na, want);
        if (!(opts & CYL_OUTWARD) && !(fabsl(na) >= 1 - FZ_NDIR_ULPS * u))
          fz_failf("%s: cap normal not along the axis: n.a=%Lg", what, na);
      }
    }
  }

  /* The hit point lies on the reported part, as far as t_err allows. */
  te = (opts & CYL_NO_ERRBOUND) ? (fz_real)INFINITY : h->t_err;
  if (g->ok && isfinite(te) && fz_point(p, g, h->t, &v, &rho, &slack)) {
    fz_real da = fabsl(fz_dot(g->ah, p->d)); /* axial speed */
    fz_real dr = g->sd;                      /* radial speed bound */
    fz_real vtol = da * te + slack;
    fz_real rtol = dr * te + slack;
    if (h->flags & CYL_F_TANGENT) rtol += p->r * tan_tol; /* a graze may count as a contact */
    /* v itself is computed in the library's precision from w, t and d (even a.d alone carries
     * an error u |d|): a few roundings of |w| + |t||d|, and in the subnormal range an absolute
     * half ulp */
    /* an axial coordinate beyond the precision's range can only be reported saturated */
    fz_real vmax = p->dbl ? (fz_real)DBL_MAX : (fz_real)FLT_MAX;
    int vsat = fabsl(v) - vtol > vmax && fabsl(h->v) >= vmax && (h->v > 0) == (v > 0);
    if (!vsat && !(fabsl(v - h->v) <= vtol + FZ_DECIDE_ULPS * u * (fz_abssum(g->w) + fabsl(h->t) * fz_abssum(p->d) + fabsl(v)) +
                                 (p->dbl ? 0x1p-1074L : 0x1p-149L)))
      fz_failf("%s: reported v=%La but the point at t has v=%La (tol %Lg)", what, h->v, v, vtol);
    if (h->part == CYL_SIDE) {
      if (!(fabsl(rho - p->r) <= rtol))
        fz_failf("%s: wall hit at distance %La from the axis, r=%La, allowed %Lg (t_err=%Lg)", what, rho, p->r,
                 rtol, te);
      if (!(opts & CYL_NO_NORMAL) && (opts & CYL_OUTWARD) && rtol + slack < 0.25L * p->r) {
        fz_real x[3], q[3];
        int i;
        for (i = 0; i < 3; i++) x[i] = (p->o[i] + h->t * p->d[i]) - p->c[i] - g->ah[i] * v;
        for (i = 0; i < 3; i++) q[i] = x[i] / rho;
        if (!(fz_dot(q, h->n) > 0.5L))
          fz_failf("%s: outward wall normal points inward (n.radial=%Lg)", what, fz_dot(q, h->n));
        /* the crossing direction is clear when d is not too close to the tangent plane */
        if (fabsl(fz_dot(q, p->d)) > (8 * (rtol + slack) / p->r + FZ_NDIR_ULPS * u) * g->nd &&
            ((fz_dot(q, p->d) > 0) != ((h->flags & CYL_F_INSIDE) != 0)))
          fz_failf("%s: CYL_F_INSIDE=%d but the ray %s the wall (radial.d=%Lg)", what, (h->flags & CYL_F_INSIDE) != 0,
                   fz_dot(q, p->d) > 0 ? "leaves" : "enters", fz_dot(q, p->d));
      }
    } else {
      fz_real want = (h->part == CYL_CAP_HIGH) ? g->H : -g->H;
      if (!(fabsl(v - want) <= vtol))
        fz_failf("%s: cap hit at axial %La, cap plane at %La (tol %Lg)", what, v, want, vtol);
      /* inside the disk, up to t_err and to the rounding of the rim decision itself */
      if (!(rho <= p->r + rtol + FZ_DECIDE_ULPS * u * (fz_abssum(g->w) + fabsl(h->t) * fz_abssum(p->d) + p->r)))
        fz_failf("%s: cap hit outside the disk: radius %La > r=%La (tol %Lg)", what, rho, p->r, rtol);
      {
        fz_real ad = fz_dot(g->ah, p->d) * (h->part == CYL_CAP_HIGH ? 1 : -1); /* outward n . d */
        if (fabsl(ad) > FZ_NDIR_ULPS * u * g->nd && ((ad > 0) != ((h->flags & CYL_F_INSIDE) != 0)))
          fz_failf("%s: CYL_F_INSIDE=%d but the ray %s through the cap", what, (h->flags & CYL_F_INSIDE) != 0,
                   ad > 0 ? "leaves" : "enters");
      }
    }
  }
}

static int fz_hit_same(const fz_hit *x, const fz_hit *y)
{
  return fz_same(x->t, y->t) && fz_same(x->t_err, y->t_err) && fz_same(x->n[0], y->n[0]) &&
         fz_same(x->n[1], y->n[1]) && fz_same(x->n[2], y->n[2]) && fz_same(x->v, y->v) && x->part == y->part &&
         x->flags == y->flags;
}

/* Same hit apart from what the option bits NO_NORMAL, NO_ERRBOUND and OUTWARD may change. */
static int fz_hit_core_same(const fz_hit *x, const fz_hit *y)
{
  return fz_same(x->t, y->t) && fz_same(x->v, y->v) && x->part == y->part && x->flags == y->flags;
}

/* Two rigorous enclosures of the same exact root must overlap. A root is identified by its part
 * and its crossing direction; tangent contacts (a double root) are left out. */
static void fz_check_overlap(const char *what, const fz_hit *x, const fz_hit *y)
{
  fz_real gap;
  if (x->part != y->part || ((x->flags ^ y->flags) & CYL_F_INSIDE)) return;
  if ((x->flags | y->flags) & CYL_F_TANGENT) return;
  if (!isfinite(x->t_err) || !isfinite(y->t_err)) return;
  gap = fabsl(x->t - y->t);
  if (!(gap <= (x->t_err + y->t_err) * (1 + 4 * FZ_U_EVAL)))
    fz_failf("%s: error bounds do not overlap: t=%La +- %La vs t=%La +- %La (part %d)", what, x->t, x->t_err, y->t,
             y->t_err, x->part);
}


/* ---------------------------------------------------------------- float against double */
/* Margin within which a float decision may legitimately differ from the exact one: float's own
 * rounding of the problem (relative u_f of the magnitudes involved) times a safety factor. */
#define FZ_COND_ULPS 256.0L
/* Tangent and parallel bands are avoided by this factor so that both precisions agree on them. */
#define FZ_BAND_FACTOR 16.0L
/* Magnitudes outside [2^-60, 2^60] are left to the invariants: there, float's range limits
 * (overflow of squared terms, subnormal rounding) decide, not conditioning. */
#define FZ_RANGE 0x1p60L
/* from_segment is checked on segments whose coordinates stay below this (no overflow in |p1-p0|) */
#define FZ_RANGE_SEG 0x1p60L

/* Returns 1 if every decision of a computation with unit roundoff uf (hit or miss, part, inside,
 * range limits) is far enough from its boundary that it must come out as the exact one. */
static int fz_well_conditioned(const fz_prob *p, const fz_geo *g, unsigned opts, fz_real uf)
{
  fz_real eerr, e, scale, cand[4];
  int nc = 0, i;
  if (!g->ok) return 0;
  scale = fz_abssum(g->w) + p->r;
  if (!(scale < FZ_RANGE && p->r > 1 / FZ_RANGE && g->nd < FZ_RANGE && g->nd > 1 / FZ_RANGE)) return 0;
  if ((opts & CYL_CAPS) && !(g->H < FZ_RANGE && g->H > 1 / FZ_RANGE)) return 0;
  if (!(g->H < FZ_RANGE)) {
    if (!isinf(g->H)) return 0;
  }
  /* Parallel: either exactly parallel or clearly not. */
  if (!fz_eq(g->sd, 0) &&
      !(g->sin_th > FZ_BAND_FACTOR * (uf > FZ_U_D ? (fz_real)CYL_PARALLEL_TOLF : (fz_real)CYL_PARALLEL_TOL)))
    return 0;
  /* Tangent band and hit/miss of the infinite tube. */
  e = fz_tangent_e(p, g, &eerr);
  /* a perturbation of the problem moves rho (|1 - e| = (rho/r)^2 - 1 for a miss) by uf*scale,
     and e by 2 rho/r times that */
  if (!(fabsl(e) > FZ_BAND_FACTOR * (uf > FZ_U_D ? (fz_real)CYL_TANGENT_TOLF : (fz_real)CYL_TANGENT_TOL) +
                       FZ_COND_ULPS * uf * scale / p->r * (1 + 2 * sqrtl(fabsl(1 - e)))))
    return 0;
  /* Candidate points: the two wall crossings and the two cap planes. */
  if (g->sd > 0 && e > 0) {
    fz_real tc = -fz_dot(g->axd, g->axw) / (g->sd * g->sd);
    fz_real half = sqrtl(e) * p->r / g->sd;
    cand[nc++] = tc - half;
    cand[nc++] = tc + half;
  }
  if (isfinite(g->H) && (opts & CYL_CAPS)) { /* the open tube's rim is checked on the wall crossings */
    fz_real ad = fz_dot(g->ah, p->d), aw = fz_dot(g->ah, g->w);
    if (!fz_eq(ad, 0)) {
      cand[nc++] = (-g->H - aw) / ad;
      cand[nc++] = (g->H - aw) / ad;
    } else if (!(fabsl(fabsl(aw) - g->H) > FZ_COND_ULPS * uf * (fabsl(aw) + g->H))) {
      return 0; /* parallel ray running in a cap plane */
    }
  }
  for (i = 0; i < nc; i++) {
    int wall = i < 2 && g->sd > 0 && e > 0;
    fz_real t = cand[i], v, rho, slack, dt;
    /* how far a float rounding of the problem (u_f times its size) moves this crossing: a wall
     * crossing moves with the radial speed |d x a| and the angle sqrt(e) at which the ray
     * meets the wall, a cap crossing with the axial speed |a.d| */
    if (wall) dt = FZ_COND_ULPS * uf * (fabsl(t) + scale / (g->sd * sqrtl(e)));
    else dt = FZ_COND_ULPS * uf * (fabsl(t) + (scale + g->H) / fabsl(fz_dot(g->ah, p->d)));
    if (!isfinite(t) || !(fabsl(t) < FZ_RANGE) || !isfinite(dt)) return 0;
    if (!(fabsl(t - p->tmin) > dt) || !(fabsl(p->tmax - t) > dt)) return 0;
    if (!fz_point(p, g, t, &v, &rho, &slack)) return 0;
    if (wall) {
      /* wall crossing: away from the rim */
      if (isfinite(g->H) && !(fabsl(fabsl(v) - g->H) > FZ_COND_ULPS * uf * (scale + fabsl(t) * g->nd + g->H)))
        return 0;
    } else {
      /* cap plane crossing: away from the rim circle */
      if (!(fabsl(rho - p->r) > FZ_COND_ULPS * uf * (scale + fabsl(t) * g->nd + g->H))) return 0;
    }
  }
  return 1;
}

/* ---------------------------------------------------------------- one input */
/* The exact reference (MPFR) costs tens of microseconds: the fuzzer samples 1 input in 16 (and
 * those with the force bit); the replay driver sets FZ_REF_ALWAYS to 1. */
#ifndef FZ_REF_ALWAYS
#define FZ_REF_ALWAYS 0
#endif

typedef struct fz_stats {
  unsigned long inputs, valid, hits, cond_checked, ref_checked;
} fz_stats;
static fz_stats fz_stat;

static unsigned fz_hash(const unsigned char *data, size_t size)
{
  unsigned hsh = 2166136261u;
  size_t i;
  for (i = 0; i < size; i++) hsh = (hsh ^ data[i]) * 16777619u;
  return hsh;
}

/* All checks on the results of one precision. f: intersect, a: intersect_all, oc: occluded. */
static void fz_check_family(const char *prec, const fz_prob *p, unsigned opts, const fz_res *ri,
                            const fz_res *ra, const fz_res *ro)
{
  fz_geo g;
  char what[64];
  int k;
  fz_geometry(p, &g);
  if (!(ri->rc == CYL_HIT || ri->rc == CYL_MISS)) fz_failf("%s_intersect returned %d on valid input", prec, ri->rc);
  if (!(ra->rc >= 0 && ra->rc <= 2)) fz_failf("%s_intersect_all returned %d on valid input", prec, ra->rc);
  if (!(ro->rc == 0 || ro->rc == 1)) fz_failf("%s_occluded returned %d on valid input", prec, ro->rc);
  if ((ri->rc == CYL_HIT) != (ra->rc >= 1))
    fz_failf("%s: intersect returned %d but intersect_all found %d hits", prec, ri->rc, ra->rc);
  if (ro->rc != ri->rc) fz_failf("%s: occluded returned %d, intersect %d", prec, ro->rc, ri->rc);
  if (ri->rc == CYL_HIT) {
    snprintf(what, sizeof what, "%s_intersect", prec);
    fz_check_hit(what, p, &g, opts, &ri->h[0]);
    if (!fz_hit_same(&ri->h[0], &ra->h[0]))
      fz_failf("%s: intersect_all's first hit (t=%La part %d) differs from intersect's (t=%La part %d)", prec,
               ra->h[0].t, ra->h[0].part, ri->h[0].t, ri->h[0].part);
  }
  for (k = 0; k < ra->rc; k++) {
    snprintf(what, sizeof what, "%s_intersect_all hit %d/%d", prec, k + 1, ra->rc);
    fz_check_hit(what, p, &g, opts, &ra->h[k]);
  }
  if (ra->rc == 2) {
    const fz_hit *h0 = &ra->h[0], *h1 = &ra->h[1];
    if (!(h0->t <= h1->t)) fz_failf("%s_intersect_all: hits not sorted: %La then %La", prec, h0->t, h1->t);
    if (!((h0->flags | h1->flags) & CYL_F_TANGENT) &&
        (((h0->flags & CYL_F_INSIDE) != 0) || ((h1->flags & CYL_F_INSIDE) == 0)))
      fz_failf("%s_intersect_all: two crossings must be entry then exit (flags 0x%x, 0x%x)", prec, h0->flags,
               h1->flags);
    if (h0->part == h1->part && h0->part != CYL_SIDE)
      fz_failf("%s_intersect_all: two hits on the same cap", prec);
  }
}

#define FZ_DEFINE_RUN(P, T, SUFFIX, PREC)                                                       \
  /* Every call and check of one precision on valid input; returns intersect_all's result. */  \
  static fz_res fz_run_valid_##SUFFIX(const P##_ray *ray, const P##_cylinder *cyl, unsigned opts) \
  {                                                                                             \
    fz_prob p;                                                                                  \
    fz_res ri, ra, ro, x, y;                                                                    \
    P##_hit raw0[2], raw1[2];                                                                   \
    unsigned base = opts & ~(unsigned)CYL_TRUSTED;                                              \
    int k;                                                                                      \
    fz_prob_##SUFFIX(ray, cyl, &p);                                                             \
    ri = fz_call_##SUFFIX(0, ray, cyl, base, 0, raw0);                                          \
    ra = fz_call_##SUFFIX(1, ray, cyl, base, 0, NULL);                                          \
    ro = fz_call_##SUFFIX(2, ray, cyl, base, 0, NULL);                                          \
    fz_check_family(PREC, &p, base, &ri, &ra, &ro);                                             \
    /* determinism, and CYL_TRUSTED changes nothing on valid input */                          \
    x = fz_call_##SUFFIX(0, ray, cyl, (opts & CYL_TRUSTED) ? opts : base, 0, raw1);             \
    if (x.rc != ri.rc || memcmp(raw0, raw1, sizeof raw0) != 0)                                  \
      fz_failf(PREC ": repeated call%s gives a different result",                              \
               (opts & CYL_TRUSTED) ? " with CYL_TRUSTED" : "");                               \
    /* NO_NORMAL / NO_ERRBOUND / OUTWARD change only n and t_err */                             \
    {                                                                                           \
      static const unsigned flips[3] = {CYL_NO_NORMAL, CYL_NO_ERRBOUND, CYL_OUTWARD};           \
      for (k = 0; k < 3; k++) {                                                                 \
        unsigned o2 = base ^ flips[k];                                                          \
        fz_res z = fz_call_##SUFFIX(1, ray, cyl, o2, 0, NULL);                                  \
        int j;                                                                                  \
        if (z.rc != ra.rc) fz_failf(PREC ": toggling option 0x%x changes the hit count %d -> %d", flips[k], ra.rc, z.rc); \
        for (j = 0; j < z.rc; j++) {                                                            \
          if (!fz_hit_core_same(&z.h[j], &ra.h[j]))                                             \
            fz_failf(PREC ": toggling option 0x%x changes hit %d (t %La -> %La, part %d -> %d, flags 0x%x -> 0x%x)", \
                     flips[k], j, ra.h[j].t, z.h[j].t, ra.h[j].part, z.h[j].part, ra.h[j].flags, z.h[j].flags); \
          if (flips[k] != CYL_NO_ERRBOUND && !(o2 & CYL_NO_ERRBOUND) && !(base & CYL_NO_ERRBOUND) && \
              !fz_same(z.h[j].t_err, ra.h[j].t_err))                                            \
            fz_failf(PREC ": toggling option 0x%x changes t_err", flips[k]);                    \
          if (flips[k] == CYL_OUTWARD && !(base & CYL_NO_NORMAL)) {                              \
            /* ray-facing and outward normal lie on one line: equal or negated, bit for bit      \
             * (which sign is checked against d and the geometry in fz_check_hit) */            \
            int c, eq = 1, neg = 1;                                                             \
            for (c = 0; c < 3; c++) {                                                           \
              eq = eq && fz_same(z.h[j].n[c], ra.h[j].n[c]);                                    \
              neg = neg && fz_same(z.h[j].n[c], -ra.h[j].n[c]);                                 \
            }                                                                                   \
            if (!eq && !neg)                                                                    \
              fz_failf(PREC ": ray-facing normal is neither the outward normal nor its negation (hit %d)", j); \
          }                                                                                     \
        }                                                                                       \
      }                                                                                         \
    }                                                                                           \
    /* NO_TANGENT removes exactly the tangent contacts */                                       \
    {                                                                                           \
      fz_res with = (base & CYL_NO_TANGENT) ? fz_call_##SUFFIX(1, ray, cyl, base ^ CYL_NO_TANGENT, 0, NULL) : ra; \
      fz_res without = (base & CYL_NO_TANGENT) ? ra : fz_call_##SUFFIX(1, ray, cyl, base ^ CYL_NO_TANGENT, 0, NULL); \
      fz_hit keep[2];                                                                           \
      int nk = 0, j, m;                                                                         \
      for (j = 0; j < with.rc; j++)                                                             \
        if (!(with.h[j].flags & CYL_F_TANGENT)) keep[nk++] = with.h[j];                         \
      if (!(base & CYL_CAPS)) {                                                                 \
        /* no graze, or the open tube: exactly the grazing crossings go */                      \
        if (nk != without.rc)                                                                   \
          fz_failf(PREC ": CYL_NO_TANGENT leaves %d hits, expected the %d non-tangent ones", without.rc, nk); \
        for (j = 0; j < nk; j++)                                                                \
          if (!fz_hit_same(&keep[j], &without.h[j]))                                            \
            fz_failf(PREC ": CYL_NO_TANGENT changes non-tangent hit %d (t %La -> %La)", j, keep[j].t, without.h[j].t); \
      } else {                                                                                  \
        /* solid: a grazed wall interval goes, and with it the cap crossings that clipped it \
         * (those need not be flagged tangent); what remains is among the non-tangent hits */ \
        for (j = 0; j < without.rc; j++) {                                                      \
          int found = 0;                                                                        \
          for (m = 0; m < nk; m++) found = found || fz_hit_same(&keep[m], &without.h[j]);       \
          if (!found) fz_failf(PREC ": CYL_NO_TANGENT creates hit %d (t %La)", j, without.h[j].t); \
        }                                                                                       \
      }                                                                                         \
    }                                                                                           \
    /* precise and fast tiers enclose the same roots */                                         \
    if (fz_precise_available()) {                                                               \
      unsigned yo = (base ^ CYL_PRECISE) & ~(unsigned)CYL_NO_ERRBOUND;                          \
      y = fz_call_##SUFFIX(1, ray, cyl, yo, 0, NULL);                                           \
      if (y.rc < 0) fz_failf(PREC ": toggling CYL_PRECISE gives error %d", y.rc);              \
      { /* the other tier's hits pass the same per-hit checks */                               \
        fz_geo gy;                                                                              \
        fz_geometry(&p, &gy);                                                                   \
        for (k = 0; k < y.rc; k++)                                                              \
          fz_check_hit((yo & CYL_PRECISE) ? PREC "_intersect_all, precise tier" : PREC "_intersect_all, default tier", \
                       &p, &gy, yo, &y.h[k]);                                                   \
      }                                                                                         \
      {                                                                                         \
        fz_res z = (base & CYL_NO_ERRBOUND) ? fz_call_##SUFFIX(1, ray, cyl, base & ~(unsigned)CYL_NO_ERRBOUND, 0, NULL) : ra; \
        int j, m;                                                                               \
        for (j = 0; j < z.rc; j++)                                                              \
          for (m = 0; m < y.rc; m++) fz_check_overlap(PREC " precise vs fast tier", &z.h[j], &y.h[m]); \
      }                                                                                         \
    }                                                                                           \
    if (ri.rc == CYL_HIT) fz_stat.hits++;                                                       \
    return ra;                                                                                  \
  }

#ifndef CYL_NO_FLOAT
FZ_DEFINE_RUN(cylf, float, f, "cylf")
#endif
#ifndef CYL_NO_DOUBLE
FZ_DEFINE_RUN(cyld, double, d, "cyld")
#endif

#ifdef FUZZ_HAVE_REF
#include "fuzz_ref.h" /* the sampled exact-reference check: fz_ref_check_f / _d */
#endif

#if !defined(CYL_NO_FLOAT) && !defined(CYL_NO_DOUBLE)
/* The float problem, converted exactly to double: both results enclose the same exact roots, and
 * where every decision is well conditioned they must make the same decisions. */
static void fz_float_vs_double(const cylf_ray *rf, const cylf_cylinder *cf, unsigned opts, const fz_res *raf)
{
  cyld_ray rd;
  cyld_cylinder cd;
  fz_res rad, rff = *raf;
  fz_prob p;
  fz_geo g;
  unsigned base = opts & ~(unsigned)(CYL_TRUSTED | CYL_NO_ERRBOUND);
  int i, j, m;
  for (i = 0; i < 3; i++) {
    rd.o[i] = (double)rf->o[i];
    rd.d[i] = (double)rf->d[i];
    cd.c[i] = (double)cf->c[i];
    cd.a[i] = (double)cf->a[i];
  }
  rd.tmin = (double)rf->tmin;
  rd.tmax = (double)rf->tmax;
  cd.r = (double)cf->r;
  cd.h = (double)cf->h;
  rad = fz_call_d(1, &rd, &cd, base, 0, NULL);
  if (rad.rc < 0) fz_failf("cyld on the float problem returned error %d", rad.rc);
  if (opts & CYL_NO_ERRBOUND) rff = fz_call_f(1, rf, cf, base, 0, NULL);
  for (j = 0; j < rff.rc; j++)
    for (m = 0; m < rad.rc; m++) fz_check_overlap("float vs double", &rff.h[j], &rad.h[m]);
  fz_prob_d(&rd, &cd, &p);
  fz_geometry(&p, &g);
  if (!fz_well_conditioned(&p, &g, base, FZ_U_F)) return;
  fz_stat.cond_checked++;
  if (rff.rc != rad.rc)
    fz_failf("float vs double, well conditioned: float finds %d hits, double %d", rff.rc, rad.rc);
  for (j = 0; j < rff.rc; j++) {
    const unsigned mask = CYL_F_INSIDE | CYL_F_TANGENT | CYL_F_PARALLEL;
    if (rff.h[j].part != rad.h[j].part || ((rff.h[j].flags ^ rad.h[j].flags) & mask))
      fz_failf("float vs double, well conditioned: hit %d is part %d flags 0x%x in float, part %d flags 0x%x in double",
               j, rff.h[j].part, rff.h[j].flags, rad.h[j].part, rad.h[j].flags);
  }
}
#endif

/* from_segment(p0, p1, r): center at the midpoint, axis along p1 - p0, h = |p1 - p0|, r as given.
 * Checked where the segment is finite, within [2^-60, 2^60] and not lost to cancellation. */
static void fz_check_segment(const fz_real *p0, const fz_real *p1, fz_real r, const fz_real *c, const fz_real *a,
                             fz_real rr, fz_real h, fz_real u)
{
  fz_real dv[3], cx[3], mag = fz_abssum(p0) + fz_abssum(p1), len, na;
  int i;
  if (!fz_same(rr, r)) fz_failf("from_segment: r=%La became %La", r, rr);
  for (i = 0; i < 3; i++) dv[i] = p1[i] - p0[i];
  len = fz_norm(dv);
  if (!fz_isfinite_all(p0, 3) || !fz_isfinite_all(p1, 3) || !(mag < FZ_RANGE_SEG) ||
      !(len > 1 / FZ_RANGE_SEG) || !(len > 64 * u * mag))
    return;
  for (i = 0; i < 3; i++)
    if (!(fabsl(c[i] - (p0[i] + p1[i]) * 0.5L) <= 2 * u * mag))
      fz_failf("from_segment: c[%d]=%La is not the midpoint %La", i, c[i], (p0[i] + p1[i]) * 0.5L);
  if (!(fabsl(h - len) <= 8 * u * mag)) fz_failf("from_segment: h=%La but |p1-p0|=%La", h, len);
  na = fz_norm(a);
  fz_cross(a, dv, cx);
  if (!(fz_dot(a, dv) > 0) || !(fz_norm(cx) <= 8 * u * mag * na))
    fz_failf("from_segment: axis (%La,%La,%La) not along p1-p0", a[0], a[1], a[2]);
}

/* Entry point shared by the harness and the replay driver. */
FZ_UNUSED static void fz_one(const unsigned char *data, size_t size)
{
  static const char *const fz_fname[3] = {"intersect", "intersect_all", "occluded"};
  fz_input in;
  int f, i;
  unsigned base;
  const char *s;
  fz_decode(data, size, &in);
  fz_describe(&in);
  fz_stat.inputs++;

  s = cyl_strerror(in.errcode);
  if (s == NULL || s[0] == '\0') fz_failf("cyl_strerror(%d) returned an empty message", in.errcode);

#ifdef CYL_NO_DOUBLE
  if (in.dbl) return;
#endif
#ifdef CYL_NO_FLOAT
  if (!in.dbl) return;
#endif
  base = in.opts & ~(unsigned)CYL_TRUSTED;
  if (in.func == 3) {
    /* from_segment: p0 = numbers c, p1 = numbers a. A finite, non-degenerate segment gives a
     * cylinder whose axis runs from p0 to p1. */
    if (in.dbl) {
#ifndef CYL_NO_DOUBLE
      /* NULL selection 1 / 2 goes to from_segment's p0 / p1: a NULL end gives the zero axis */
      cyld_cylinder cy = cyld_from_segment(in.nullsel == 1 ? NULL : &in.d[FZ_C], in.nullsel == 2 ? NULL : &in.d[FZ_A],
                                           in.d[FZ_R]);
      fz_real p0[3], p1[3], c[3], a[3];
      for (i = 0; i < 3; i++) {
        p0[i] = (fz_real)in.d[FZ_C + i], p1[i] = (fz_real)in.d[FZ_A + i];
        c[i] = (fz_real)cy.c[i], a[i] = (fz_real)cy.a[i];
      }
      if (in.nullsel != 1 && in.nullsel != 2)
        fz_check_segment(p0, p1, (fz_real)in.d[FZ_R], c, a, (fz_real)cy.r, (fz_real)cy.h, FZ_U_D);
      for (i = 0; i < 3; i++) in.d[FZ_C + i] = cy.c[i], in.d[FZ_A + i] = cy.a[i];
      in.d[FZ_R] = cy.r;
      in.d[FZ_H] = cy.h;
#endif
    } else {
#ifndef CYL_NO_FLOAT
      cylf_cylinder cy = cylf_from_segment(in.nullsel == 1 ? NULL : &in.f[FZ_C], in.nullsel == 2 ? NULL : &in.f[FZ_A],
                                           in.f[FZ_R]);
      fz_real p0[3], p1[3], c[3], a[3];
      for (i = 0; i < 3; i++) {
        p0[i] = (fz_real)in.f[FZ_C + i], p1[i] = (fz_real)in.f[FZ_A + i];
        c[i] = (fz_real)cy.c[i], a[i] = (fz_real)cy.a[i];
      }
      if (in.nullsel != 1 && in.nullsel != 2)
        fz_check_segment(p0, p1, (fz_real)in.f[FZ_R], c, a, (fz_real)cy.r, (fz_real)cy.h, FZ_U_F);
      for (i = 0; i < 3; i++) in.f[FZ_C + i] = cy.c[i], in.f[FZ_A + i] = cy.a[i];
      in.f[FZ_R] = cy.r;
      in.f[FZ_H] = cy.h;
#endif
    }
    if (in.nullsel == 1 || in.nullsel == 2) {
      for (i = 0; i < 3; i++)
        if (!fz_eq(in.dbl ? (fz_real)in.d[FZ_A + i] : (fz_real)in.f[FZ_A + i], 0))
          fz_failf("from_segment with a NULL end gave a nonzero axis");
      in.nullsel = 0;
    }
    in.func = 1;
  }
  for (f = 0; f < 3; f++) {
    /* occluded takes no hit pointer: a NULL hit does not concern it */
    int want = fz_expected_error(&in, base, f == 2), rc = 0, nh = in.nullsel == 3;
    if (in.dbl) {
#ifndef CYL_NO_DOUBLE
      cyld_ray ray;
      cyld_cylinder cyl;
      fz_build_d(in.d, &ray, &cyl);
      rc = fz_call_d(f, in.nullsel == 1 ? NULL : &ray, in.nullsel == 2 ? NULL : &cyl, base, nh, NULL).rc;
#endif
    } else {
#ifndef CYL_NO_FLOAT
      cylf_ray ray;
      cylf_cylinder cyl;
      fz_build_f(in.f, &ray, &cyl);
      rc = fz_call_f(f, in.nullsel == 1 ? NULL : &ray, in.nullsel == 2 ? NULL : &cyl, base, nh, NULL).rc;
#endif
    }
    if (want < 0 && rc != want)
      fz_failf("%s returned %d, expected error %d (%s)", fz_fname[f], rc, want, cyl_strerror(want));
    if (want == 0 && rc < 0) fz_failf("%s returned error %d on valid input", fz_fname[f], rc);
    s = cyl_strerror(rc);
    if (s == NULL || s[0] == '\0') fz_failf("cyl_strerror(%d) returned an empty message", rc);
  }
  if (fz_expected_error(&in, base, 0) < 0) return;
  fz_stat.valid++;

  if (in.dbl) {
#ifndef CYL_NO_DOUBLE
    cyld_ray ray;
    cyld_cylinder cyl;
    fz_res ra;
    fz_build_d(in.d, &ray, &cyl);
    ra = fz_run_valid_d(&ray, &cyl, in.opts);
#ifdef FUZZ_HAVE_REF
    if (in.force_ref || FZ_REF_ALWAYS || (fz_hash(data, size) & 15u) == 0) {
      fz_stat.ref_checked++;
      fz_ref_check_d(&ray, &cyl, base);
    }
#endif
    (void)ra;
#endif
  } else {
#ifndef CYL_NO_FLOAT
    cylf_ray ray;
    cylf_cylinder cyl;
    fz_res ra;
    fz_build_f(in.f, &ray, &cyl);
    ra = fz_run_valid_f(&ray, &cyl, in.opts);
#ifndef CYL_NO_DOUBLE
    fz_float_vs_double(&ray, &cyl, base, &ra);
#endif
#ifdef FUZZ_HAVE_REF
    if (in.force_ref || FZ_REF_ALWAYS || (fz_hash(data, size) & 15u) == 0) {
      fz_stat.ref_checked++;
      fz_ref_check_f(&ray, &cyl, base);
    }
#endif
    (void)ra;
#endif
  }
  (void)fz_hash;
}

#endif /* FUZZ_CHECK_H */
