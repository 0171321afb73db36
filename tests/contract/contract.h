/* contract.h: what every contract test file shares (tests/contract/<topic>.c).
 *
 * The contract tests are written once for both precisions: a topic file compiled as it is tests
 * float (cylf_*), and with T_DOUBLE defined tests double (cyld_*). tests/test_float.c includes
 * every topic into one runner (CONTRACT_ALL); tests/test_double.c is the same with T_DOUBLE.
 * This header turns the choice into:
 *   T             the scalar type under test (float / double)
 *   CYL(x)        the public prefix: cylf_x / cyld_x
 *   TOL_TANGENT   CYL_TANGENT_TOLF / CYL_TANGENT_TOL   (band on e = 1 - rho^2/r^2)
 *   TOL_PARALLEL  CYL_PARALLEL_TOLF / CYL_PARALLEL_TOL (bound on sin(angle(d, axis)))
 *   T_EPS         FLT_EPSILON / DBL_EPSILON (ulp of 1.0, = 2u)
 *   T_SQRT T_FABS T_NEXT T_LDEXP   sqrt, fabs, nextafter, ldexp of that type
 *   T_BIG_EXP     scale-invariance exponent for lengths (50 float, 400 double)
 *   T_DIR_EXP     scale exponent for d and a alone (60 float, 500 double)
 *   T_MAX_EXP     FLT_MAX_EXP / DBL_MAX_EXP
 *   T_MAX         FLT_MAX / DBL_MAX
 *   T_TINY_EXP    the smallest subnormal's exponent (-149 float, -1074 double)
 * and provides the named tolerances, the assertion helpers (each reports the caller's line), the
 * scene builders, the fixed generic scenes and the option sets the generic checks run under.
 * The long double model of the exact geometry that reference.c compares with is reference.h.
 *
 * Conventions: a "scene" is a ray plus a cylinder; expected values are computed in long double
 * from the inputs as stored in T (so they are the exact answers of the given inputs up to the
 * reference's own rounding, TOL_REF). Floats are compared with == (EXACT) only where the exact
 * answer is representable and every sane formulation reaches it without rounding (small
 * integers, axis-aligned, power-of-two scalings): there exactness is the property under test.
 * Every function here is static inline: a test file that does not use one gets no warning.
 */
#ifndef CONTRACT_H
#define CONTRACT_H

#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "cylinder_isect.h"
#include "rt_calls.h"

#ifdef T_DOUBLE
#define T double
#define CYL(x) cyld_##x
#define TOL_TANGENT CYL_TANGENT_TOL
#define TOL_PARALLEL CYL_PARALLEL_TOL
#define T_EPS DBL_EPSILON
#define T_SQRT sqrt
#define T_FABS fabs
#define T_NEXT nextafter
#define T_LDEXP ldexp
#define T_BIG_EXP 400 /* lengths scaled by 2^+-400: squares stay finite only with prescaling */
#define T_DIR_EXP 500 /* d and a scaled by 2^+-500 */
#define T_EDGE_EXPS 221, 225, 263, 323 /* lengths and d by 2^k: v2's hot range edge, 2^450 */
#define T_MAX_EXP DBL_MAX_EXP
#define T_MAX DBL_MAX
#define T_TINY_EXP (DBL_MIN_EXP - DBL_MANT_DIG)
#else
#define T float
#define CYL(x) cylf_##x
#define TOL_TANGENT CYL_TANGENT_TOLF
#define TOL_PARALLEL CYL_PARALLEL_TOLF
#define T_EPS FLT_EPSILON
#define T_SQRT sqrtf
#define T_FABS fabsf
#define T_NEXT nextafterf
#define T_LDEXP ldexpf
#define T_BIG_EXP 50 /* lengths scaled by 2^+-50: squares stay finite only with prescaling */
#define T_DIR_EXP 60 /* d and a scaled by 2^+-60 */
#define T_EDGE_EXPS 26, 30, 44, 58 /* lengths and d by 2^k: v2's hot range edge in float, 2^60 */
#define T_MAX_EXP FLT_MAX_EXP
#define T_MAX FLT_MAX
#define T_TINY_EXP (FLT_MIN_EXP - FLT_MANT_DIG)
#endif

void setUp(void) {}
void tearDown(void) {}

typedef CYL(ray) Ray;
typedef CYL(cylinder) Cyl;
typedef CYL(hit) Hit;

/* rt_intersect, rt_intersect_all, rt_occluded: for options known only at run time (rt_calls.h). */
#ifdef T_DOUBLE
RT_CALLS(rt_, d)
#else
RT_CALLS(rt_, f)
#endif

/* A literal in the precision under test (explicit cast: no -Wconversion noise, no promotion). */
#define L(x) ((T)(x))
#define T_INF ((T)INFINITY)
#define T_NAN ((T)NAN)

/* ------------------------------------------------------------------ the precise tier */
/* No CYL_PRECISE under CYL_NO_PRECISE (v2 defines it with CYL_NO_DOUBLE): option sets with it
   are left out, and the precise tier's test asserts that the bit is refused. */
#ifdef CYL_NO_PRECISE
#define HAVE_PRECISE 0
#else
#define HAVE_PRECISE 1
#endif
#define NO_PRECISE_SET(opts) (!HAVE_PRECISE && ((opts) & CYL_PRECISE) != 0u)

/* ------------------------------------------------------------------ named tolerances
 * Relative ones are used as TOL_x * scale, scale being the magnitude they are relative to (|t|,
 * max(|t|, r/|d|) or the scene size); a literal factor is that magnitude. T_EPS = ulp(1) = 2u. */
/* t: 4 ulp of max(|t|, r/|d|), the default path's target on well-conditioned hits. */
#define TOL_T_ULP4 (4.0L * (long double)T_EPS)
/* n, per component, on a well-conditioned hit: roundings of the hit point, a sqrt, a division. */
#define TOL_NORMAL (8.0L * (long double)T_EPS)
/* | |n| - 1 | of a vector the library normalised: a few ulp of 1.0. */
#define TOL_UNIT (4.0L * (long double)T_EPS)
/* v, per unit of scene size max(|o-c|, |t d|, r, h/2): a rounded point dot a rounded axis. */
#define TOL_V (8.0L * (long double)T_EPS)
/* Largest useful t_err per unit of max(|t|, r/|d|): a huge bound is rigorous but useless. */
#define TOL_ERR_USEFUL (1024.0L * (long double)T_EPS)
/* The reference's own rounding per unit of scale: 2^-58 on x86-64, 64 ulp of double on armhf. */
#define TOL_REF (64.0L * (long double)LDBL_EPSILON)
/* Both hits of a tangent contact (|e| <= tol) lie this near t_c: t_c +- sqrt(e) r/|d_perp|. */
#define TOL_TANGENT_SPREAD(r_over_dperp) (2.0L * sqrtl((long double)TOL_TANGENT) * (r_over_dperp))
/* Random scenes nearer (relative) to a decision boundary are skipped: 10^4 u away in float. */
#define TOL_MARGIN 1e-3L

/* ------------------------------------------------------------------ assertion helpers */
/* == without -Wfloat-equal; false for NaN (a NaN is never "exactly" anything). */
static inline int same_T(T a, T b) { return a <= b && a >= b; }

static inline void chk_exact_at(T expect, T got, const char *what, int line)
{
    if (!same_T(expect, got)) {
        char m[512];
        snprintf(m, sizeof m, "%.300s: expected exactly %.17g, got %.17g", what, (double)expect,
                 (double)got);
        UNITY_TEST_FAIL(line, m);
    }
}

static inline void chk_near_at(long double expect, long double got, long double tol,
                               const char *what, int line)
{
    long double diff = fabsl(expect - got);
    if (!(diff <= tol)) {
        char m[512];
        snprintf(m, sizeof m, "%.300s: expected %.21Lg, got %.21Lg (|diff| %.4Lg > tol %.4Lg)",
                 what, expect, got, diff, tol);
        UNITY_TEST_FAIL(line, m);
    }
}

static inline void chk_int_at(long expect, long got, const char *what, int line)
{
    if (expect != got) {
        char m[512];
        snprintf(m, sizeof m, "%.300s: expected %ld, got %ld", what, expect, got);
        UNITY_TEST_FAIL(line, m);
    }
}

#define EXACT(e, g, what) chk_exact_at((T)(e), (g), (what), __LINE__)
#define NEAR(e, g, tol, what) \
    chk_near_at((long double)(e), (long double)(g), (long double)(tol), (what), __LINE__)
#define EQ_INT(e, g, what) chk_int_at((long)(e), (long)(g), (what), __LINE__)
#define CHECK(cond, what) UNITY_TEST_ASSERT((cond), __LINE__, (what))

/* ------------------------------------------------------------------ builders */
static inline Ray mk_ray(T ox, T oy, T oz, T dx, T dy, T dz)
{
    Ray r;
    memset(&r, 0, sizeof r);
    r.o[0] = ox; r.o[1] = oy; r.o[2] = oz;
    r.d[0] = dx; r.d[1] = dy; r.d[2] = dz;
    r.tmin = 0;
    r.tmax = T_INF;
    return r;
}

static inline Cyl mk_cyl(T cx, T cy, T cz, T ax, T ay, T az, T radius, T height)
{
    Cyl c;
    memset(&c, 0, sizeof c);
    c.c[0] = cx; c.c[1] = cy; c.c[2] = cz;
    c.a[0] = ax; c.a[1] = ay; c.a[2] = az;
    c.r = radius;
    c.h = height;
    return c;
}

/* Unit-radius cylinder on the z axis centred at the origin: v = z, caps at z = +-h/2. */
static inline Cyl z_cyl(T height) { return mk_cyl(0, 0, 0, 0, 0, 1, 1, height); }

static inline void sentinel(Hit *h, size_t n) { memset(h, 0xA5, n * sizeof *h); }

/* A generic scene in dyadic numbers (exact in float and double, and after the translations and
 * power-of-two scalings below), chosen far from every decision boundary (tangency, rim, cap
 * plane, tmin): the reference's classification is then the only right one. */
typedef struct Scene {
    double o[3], d[3], c[3], a[3], r, h;
    const char *name;
} Scene;

static const Scene scenes[] = {
    {{-3.25, 0.5, 0.125}, {1, 0.125, -0.0625}, {0.25, -0.125, 0.5}, {0.125, 0.25, 1}, 1.25, 3.5,
     "oblique through, two wall hits"},
    {{2.5, -4, 1.75}, {-0.5, 1, -0.25}, {0, 0.5, 0.25}, {1, -0.5, 0.75}, 0.75, 2.5,
     "tilted axis, non-unit d and a"},
    {{0.125, 0.25, -0.5}, {0.3125, -0.75, 0.5}, {0, 0, 0}, {0.5, 0.5, 1}, 1.5, 4,
     "origin inside"},
    {{0.25, 0.125, -6}, {0.0625, 0.03125, 1}, {0, 0, 0}, {0, 0, 1}, 1, 4,
     "steep ray through low cap"},
    {{0.5, -0.25, 6}, {-0.03125, 0.0625, -2}, {0, 0, 0}, {0, 0, 1}, 1, 4,
     "steep ray down through high cap, both caps"},
    {{-5, 0.75, 1.5}, {4, 0.5, 0.25}, {0.5, 0.25, 0}, {0, 0, 1}, 1, 4,
     "wall entry then cap exit"},
    {{-3, 3, 0}, {1, 0, 0}, {0, 0, 0}, {0, 0, 1}, 1, 2, "miss: passes beside"},
    {{-3, 0, 5}, {1, 0, 0}, {0, 0, 0}, {0, 0, 1}, 1, 2, "miss: passes above"},
    {{-3, 0.25, 0}, {-1, 0.5, 0.125}, {0, 0, 0}, {0, 0, 1}, 1, 2, "miss: points away"},
    {{7, -1.5, 2.25}, {-1.5, 0.375, -0.5}, {1.25, -0.5, 0.75}, {0.25, 1, -0.5}, 0.625, 1.75,
     "far oblique, negative axis component"},
    {{0.5, 0.5, 0.5}, {1, 1, 1}, {0, 0, 0}, {1, 1, 1}, 1, 8,
     "exactly parallel to a diagonal axis, inside"},
    {{0.25, -0.125, 0.5}, {0.5, 0.25, -1}, {0, 0, 0}, {0, 0, 1}, 2, 1.5,
     "origin inside, exits through low cap"},
};
#define N_SCENES (sizeof scenes / sizeof scenes[0])

static inline void scene_get(const Scene *s, Ray *ray, Cyl *cyl)
{
    *ray = mk_ray((T)s->o[0], (T)s->o[1], (T)s->o[2], (T)s->d[0], (T)s->d[1], (T)s->d[2]);
    *cyl = mk_cyl((T)s->c[0], (T)s->c[1], (T)s->c[2], (T)s->a[0], (T)s->a[1], (T)s->a[2],
                  (T)s->r, (T)s->h);
}

/* Option sets every generic check runs under (the result-shaping ones). */
static const unsigned opt_sets[] = {0u, CYL_CAPS, CYL_OUTWARD, CYL_CAPS | CYL_OUTWARD,
                                    CYL_CAPS | CYL_NO_TANGENT};
#define N_OPT_SETS (sizeof opt_sets / sizeof opt_sets[0])

/* ------------------------------------------------------------------ the scene in long double
 * The frame every check measures in: unit axis, w = o - c, |d|, and the projections on the axis
 * (the reference solver of reference.h builds on it). */
static inline long double dotl3(const long double a[3], const long double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static inline void crossl3(const long double a[3], const long double b[3], long double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

typedef struct RefGeom {
    long double ah[3], w[3], d[3], dnorm, ad, aw, H, r, tscale;
} RefGeom;

static inline void ref_geom(const Ray *ray, const Cyl *cyl, RefGeom *g)
{
    long double a[3], an;
    int i;
    for (i = 0; i < 3; i++) {
        a[i] = (long double)cyl->a[i];
        g->w[i] = (long double)ray->o[i] - (long double)cyl->c[i];
        g->d[i] = (long double)ray->d[i];
    }
    an = sqrtl(dotl3(a, a));
    for (i = 0; i < 3; i++) g->ah[i] = a[i] / an;
    g->dnorm = sqrtl(dotl3(g->d, g->d));
    g->ad = dotl3(g->ah, g->d);
    g->aw = dotl3(g->ah, g->w);
    g->H = (long double)cyl->h / 2;
    g->r = (long double)cyl->r;
    g->tscale = g->r / g->dnorm; /* time to cross one radius */
}

/* ------------------------------------------------------------------ hit checks */
/* Fields of two hits identical (bitwise for the floats: same computation expected). */
static inline void chk_same_hit_at(const Hit *a, const Hit *b, int with_err, const char *what,
                                   int line)
{
    char m[200];
    int i;
    snprintf(m, sizeof m, "%.120s: t", what);
    chk_exact_at(a->t, b->t, m, line);
    if (with_err) {
        snprintf(m, sizeof m, "%.120s: t_err", what);
        chk_exact_at(a->t_err, b->t_err, m, line);
    }
    for (i = 0; i < 3; i++) {
        snprintf(m, sizeof m, "%.120s: n[%d]", what, i);
        chk_exact_at(a->n[i], b->n[i], m, line);
    }
    snprintf(m, sizeof m, "%.120s: v", what);
    chk_exact_at(a->v, b->v, m, line);
    snprintf(m, sizeof m, "%.120s: part", what);
    chk_int_at(a->part, b->part, m, line);
    snprintf(m, sizeof m, "%.120s: flags", what);
    chk_int_at((long)a->flags, (long)b->flags, m, line);
}
#define SAME_HIT(a, b, with_err, what) chk_same_hit_at((a), (b), (with_err), (what), __LINE__)

/* Unit normal, facing rule or outward rule, for any hit. */
static inline void chk_normal_rule_at(const Ray *ray, const Cyl *cyl, unsigned opts, const Hit *h,
                                      const char *what, int line)
{
    RefGeom g;
    long double n[3], len, nd, x[3], out_dot;
    char m[200];
    int i;
    ref_geom(ray, cyl, &g);
    for (i = 0; i < 3; i++) n[i] = (long double)h->n[i];
    len = sqrtl(dotl3(n, n));
    snprintf(m, sizeof m, "%.120s: |n| = 1", what);
    chk_near_at(1.0L, len, TOL_UNIT + TOL_REF, m, line);
    nd = dotl3(n, g.d);
    if (!(opts & CYL_OUTWARD)) {
        snprintf(m, sizeof m, "%.120s: facing rule n.d <= 0 violated (n.d = %.4Lg)", what, nd);
        UNITY_TEST_ASSERT(nd <= 0, line, m);
        return;
    }
    /* outward: side -> along (x - c)_perp, caps -> -+ axis */
    if (h->part == CYL_SIDE) {
        for (i = 0; i < 3; i++) x[i] = g.w[i] + (long double)h->t * g.d[i];
        {
            long double ax = dotl3(g.ah, x);
            for (i = 0; i < 3; i++) x[i] -= g.ah[i] * ax;
        }
        out_dot = dotl3(n, x) / sqrtl(dotl3(x, x));
    } else {
        out_dot = dotl3(n, g.ah) * (h->part == CYL_CAP_HIGH ? 1.0L : -1.0L);
    }
    snprintf(m, sizeof m, "%.120s: outward normal (n . outward = %.6Lg)", what, out_dot);
    UNITY_TEST_ASSERT(out_dot >= 1.0L - TOL_NORMAL - TOL_REF, line, m);
}
#define NORMAL_RULE(ray, cyl, opts, h, what) \
    chk_normal_rule_at((ray), (cyl), (opts), (h), (what), __LINE__)

/* One hit's t, part and flags. */
static inline void chk_hit_at(const Hit *h, T t, int part, unsigned flags, int exact,
                              const char *what, int line)
{
    char m[200];
    snprintf(m, sizeof m, "%.120s: t", what);
    if (exact) chk_exact_at(t, h->t, m, line);
    else chk_near_at((long double)t, (long double)h->t,
                     TOL_T_ULP4 * (fabsl((long double)t) > 1 ? fabsl((long double)t) : 1.0L), m,
                     line);
    snprintf(m, sizeof m, "%.120s: part", what);
    chk_int_at(part, h->part, m, line);
    snprintf(m, sizeof m, "%.120s: flags", what);
    chk_int_at((long)flags, (long)h->flags, m, line);
}
#define HIT_EXACT(h, t, part, flags, what) chk_hit_at((h), L(t), (part), (flags), 1, (what), __LINE__)
#define HIT_NEAR(h, t, part, flags, what) chk_hit_at((h), L(t), (part), (flags), 0, (what), __LINE__)

static inline void chk_vec_exact_at(const T v[3], T x, T y, T z, const char *what, int line)
{
    char m[200];
    snprintf(m, sizeof m, "%.120s[0]", what);
    chk_exact_at(x, v[0], m, line);
    snprintf(m, sizeof m, "%.120s[1]", what);
    chk_exact_at(y, v[1], m, line);
    snprintf(m, sizeof m, "%.120s[2]", what);
    chk_exact_at(z, v[2], m, line);
}
#define VEC_EXACT(v, x, y, z, what) chk_vec_exact_at((v), L(x), L(y), L(z), (what), __LINE__)

static inline void chk_vec_near_at(const T v[3], long double x, long double y, long double z,
                                   long double tol, const char *what, int line)
{
    char m[200];
    snprintf(m, sizeof m, "%.120s[0]", what);
    chk_near_at(x, (long double)v[0], tol, m, line);
    snprintf(m, sizeof m, "%.120s[1]", what);
    chk_near_at(y, (long double)v[1], tol, m, line);
    snprintf(m, sizeof m, "%.120s[2]", what);
    chk_near_at(z, (long double)v[2], tol, m, line);
}
#define VEC_NEAR(v, x, y, z, tol, what) \
    chk_vec_near_at((v), (long double)(x), (long double)(y), (long double)(z), (tol), (what), \
                    __LINE__)

#endif /* CONTRACT_H */
