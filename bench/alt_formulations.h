/* alt_formulations.h: the two ray/cylinder formulations users would otherwise pick, written
 * out from their published math, each taking its inputs in its own form, so that the
 * benchmark times them as their users run them, side by side with cylinder_isect.h.
 *
 *   #include "cylinder_isect.h"      (for the ray, cylinder and hit types and the CYL_* codes)
 *   #include "bench/alt_formulations.h"
 *
 * Each formulation, per precision (altf_ float, altd_ double; T is float or double):
 *
 *   typedef struct { T t, n[3]; } altf_out;                         t and the OUTWARD normal
 *   typedef struct { T c[3], a[3], r, h; } altf_literal_cyl;        a of unit length
 *   typedef struct { T pa[3], pb[3], ra; } altf_endpoint_cyl;       the two end points
 *   int altf_literal_solve (const cylf_ray *, const altf_literal_cyl *, unsigned opts, altf_out *);
 *   int altf_endpoint_solve(const cylf_ray *ray_with_unit_d, const altf_endpoint_cyl *, altf_out *);
 *
 * Both return 0 for a miss, else 1 + the part hit (CYL_SIDE, CYL_CAP_LOW, CYL_CAP_HIGH), and on
 * a hit store t and the outward normal only: no error bound, no v, no flags, no flip of the
 * normal towards the ray, which their users do not compute. Preparing the inputs (once per
 * cylinder or ray, outside a render loop) is the caller's:
 *
 *   void altf_literal_from (const cylf_cylinder *, altf_literal_cyl *);   a / |a|
 *   void altf_endpoint_from(const cylf_cylinder *, altf_endpoint_cyl *);  pa = c - â h/2, ...
 *
 * (both computed in double and rounded once). For the end-point formulation the ray's d must
 * have unit length and tmin, tmax are in units of that d.
 *
 * For code written against the library's API (the viewer's split view) there is also
 *
 *   int altf_literal_intersect(const cylf_ray *, const cylf_cylinder *, unsigned opts, cylf_hit *);
 *
 * with cylf_intersect's signature: it prepares the cylinder on every call, calls
 * altf_literal_solve and fills the whole hit (t_err = +INFINITY, v, CYL_F_INSIDE, the normal
 * facing the ray unless CYL_OUTWARD). The benchmark does not time it.
 *
 * There is no input validation: both are what a user would write, and they are deliberately
 * NOT made robust. Do not "fix" their numerics: they exist to show what the textbook
 * arithmetic gives. Their vector operations are written component by component, as a C port
 * of vec3 code reads and as the library writes its own: gcc -O2 keeps a loop of three trips,
 * with its arrays in memory, and such loops made these routines look several times slower
 * than a port of the articles' code runs.
 *
 * 1. The literal formulation ("ray vs cylinder with center c, axis a, radius r, height h",
 *    the classic exercise taken literally, with the axis stored as a unit vector â).
 *    With w = o − c, a point x is on the infinite cylinder when the part of x − c orthogonal
 *    to the axis, obtained with the projection (I − â âᵀ)(x − c), has squared length r².
 *    Putting x = o + t d and writing the projections as d⊥ = d − â(âᵀd), w⊥ = w − â(âᵀw):
 *        A t² + B t + C = 0,  A = d⊥·d⊥,  B = 2 d⊥·w⊥,  C = w⊥·w⊥ − r²,
 *    solved with the textbook formula t = (−B ± √(B² − 4AC)) / (2A).
 *    Height test of a wall point: a wall point is at distance r from the axis, so its axial
 *    coordinate v satisfies v² = ‖x − c‖² − r²; the exercise's test |v| ≤ h/2 becomes the
 *    squared-distance test ‖x − c‖² ≤ r² + h²/4 (no square root, as the exercise does it).
 *    The wall normal is the projection of x − c, normalised.
 *    Caps (with CYL_CAPS): cap centres c_i = c ∓ â h/2; the plane âᵀ(x − c_i) = 0 gives
 *    t = âᵀ(c_i − o) / âᵀd and the point is on the disk when ‖x − c_i‖² ≤ r².
 *    Without CYL_CAPS it is the open tube; h = +INFINITY gives the infinite tube.
 *    A = 0 (ray parallel to the axis) gives no wall root; âᵀd = 0 gives no cap crossing.
 *    The nearest crossing with tmin <= t <= tmax is returned. Honoured option: CYL_CAPS.
 *
 * 2. The end-point formulation popularised by Inigo Quilez's "intersectors" article
 *    (capped cylinder given by its end points pa, pb and radius ra, ray of unit direction).
 *    Derivation: ba = pb − pa, oc = o − pa, and for a point p = oc + t d relative to pa,
 *    y = ba·p is the axial coordinate scaled by ‖ba‖ and the squared distance to the axis
 *    times ‖ba‖² is (ba·ba)(p·p) − y². Setting it to ra²(ba·ba) gives k2 t² + 2 k1 t + k0 = 0
 *    with, for |d| = 1,
 *        k2 = ba·ba − (ba·d)²,
 *        k1 = (ba·ba)(oc·d) − (ba·oc)(ba·d),
 *        k0 = (ba·ba)(oc·oc) − (ba·oc)² − ra²(ba·ba).
 *    Only the near root t = (−k1 − √(k1² − k2 k0)) / k2 is used ("nearest hit from
 *    outside"). If its y is strictly between 0 and ba·ba it is the wall hit, normal
 *    (oc + t d − ba y/(ba·ba)) / ra; otherwise the ray is tested against the cap plane on the
 *    side of y (y = 0 or y = ba·ba): t = (y_cap − ba·oc)/(ba·d), accepted when
 *    |k1 + k2 t| < √(k1² − k2 k0), i.e. when that t lies strictly between the two wall roots,
 *    normal ±ba/‖ba‖. The answer is accepted when tmin <= t <= tmax.
 *    Mapping from the library's cylinder: pa = c − â h/2 (the CYL_CAP_LOW side),
 *    pb = c + â h/2, ra = r.
 *    Limitations of the formulation, kept on purpose: it is capped-only (an open tube cannot
 *    be expressed), it cannot express h = +INFINITY, an origin inside the cylinder gets the
 *    near root behind it (so a miss, or a cap found by chance), a ray exactly parallel to the
 *    axis divides by k2 = 0, and a t outside [tmin, tmax] is a miss (no search for a later
 *    hit).
 *
 * No code was copied from anywhere: both are re-derived from the math above.
 */
#ifndef ALT_FORMULATIONS_BODY
#ifndef ALT_FORMULATIONS_H
#define ALT_FORMULATIONS_H

#include <math.h>
#include "cylinder_isect.h"

#ifndef CYL_NO_FLOAT
#define ALT_FORMULATIONS_BODY
#define ALT__T float
#define ALT__F(name) altf_##name
#define ALT__PRIV(name) alt__f_##name
#define ALT__RAY cylf_ray
#define ALT__CYL cylf_cylinder
#define ALT__HIT cylf_hit
#define ALT__SQRT sqrtf
#include "alt_formulations.h"
#undef ALT__T
#undef ALT__F
#undef ALT__PRIV
#undef ALT__RAY
#undef ALT__CYL
#undef ALT__HIT
#undef ALT__SQRT
#undef ALT_FORMULATIONS_BODY
#endif

#ifndef CYL_NO_DOUBLE
#define ALT_FORMULATIONS_BODY
#define ALT__T double
#define ALT__F(name) altd_##name
#define ALT__PRIV(name) alt__d_##name
#define ALT__RAY cyld_ray
#define ALT__CYL cyld_cylinder
#define ALT__HIT cyld_hit
#define ALT__SQRT sqrt
#include "alt_formulations.h"
#undef ALT__T
#undef ALT__F
#undef ALT__PRIV
#undef ALT__RAY
#undef ALT__CYL
#undef ALT__HIT
#undef ALT__SQRT
#undef ALT_FORMULATIONS_BODY
#endif

#endif /* ALT_FORMULATIONS_H */
#else  /* ALT_FORMULATIONS_BODY: one precision, parameterised by the ALT__ macros */

typedef struct ALT__F(out) { ALT__T t, n[3]; } ALT__F(out);
typedef struct ALT__F(literal_cyl) { ALT__T c[3], a[3], r, h; } ALT__F(literal_cyl);
typedef struct ALT__F(endpoint_cyl) { ALT__T pa[3], pb[3], ra; } ALT__F(endpoint_cyl);

static inline ALT__T ALT__PRIV(dot)(const ALT__T x[3], const ALT__T y[3])
{
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

/* â = a / |a| in double, rounded once */
static inline void ALT__PRIV(unit_axis)(const ALT__CYL *cyl, double ah[3])
{
    double a0 = (double)cyl->a[0], a1 = (double)cyl->a[1], a2 = (double)cyl->a[2];
    double al = sqrt(a0 * a0 + a1 * a1 + a2 * a2);
    ah[0] = a0 / al;
    ah[1] = a1 / al;
    ah[2] = a2 / al;
}

static inline void ALT__F(literal_from)(const ALT__CYL *cyl, ALT__F(literal_cyl) *out)
{
    double ah[3];
    int i;
    ALT__PRIV(unit_axis)(cyl, ah);
    for (i = 0; i < 3; ++i) {
        out->c[i] = cyl->c[i];
        out->a[i] = (ALT__T)ah[i];
    }
    out->r = cyl->r;
    out->h = cyl->h;
}

static inline void ALT__F(endpoint_from)(const ALT__CYL *cyl, ALT__F(endpoint_cyl) *out)
{
    double ah[3], hh = (double)cyl->h / 2.0;
    int i;
    ALT__PRIV(unit_axis)(cyl, ah);
    for (i = 0; i < 3; ++i) {
        out->pa[i] = (ALT__T)((double)cyl->c[i] - ah[i] * hh);
        out->pb[i] = (ALT__T)((double)cyl->c[i] + ah[i] * hh);
    }
    out->ra = cyl->r;
}

static inline int ALT__F(literal_solve)(const ALT__RAY *ray, const ALT__F(literal_cyl) *cyl,
                                        unsigned opts, ALT__F(out) *out)
{
    const ALT__T *o = ray->o, *d = ray->d, *c = cyl->c, *ah = cyl->a;
    const ALT__T r = cyl->r, h = cyl->h;
    ALT__T w[3], dp[3], wp[3], x[3], n[3];
    ALT__T ad, aw, A, B, C, disc, best_t = (ALT__T)0, best_n[3] = {0, 0, 0};
    int k, best_part = CYL_SIDE, found = 0;

    /* vector operations component by component (see the top of this file) */
    w[0] = o[0] - c[0], w[1] = o[1] - c[1], w[2] = o[2] - c[2];
    ad = ALT__PRIV(dot)(ah, d);
    aw = ALT__PRIV(dot)(ah, w);
    /* projections (I - a a^T) d and (I - a a^T) w */
    dp[0] = d[0] - ah[0] * ad, dp[1] = d[1] - ah[1] * ad, dp[2] = d[2] - ah[2] * ad;
    wp[0] = w[0] - ah[0] * aw, wp[1] = w[1] - ah[1] * aw, wp[2] = w[2] - ah[2] * aw;
    A = ALT__PRIV(dot)(dp, dp);
    B = (ALT__T)2 * ALT__PRIV(dot)(dp, wp);
    C = ALT__PRIV(dot)(wp, wp) - r * r;

    if (A > (ALT__T)0) {
        disc = B * B - (ALT__T)4 * A * C;
        if (disc >= (ALT__T)0) {
            ALT__T sq = ALT__SQRT(disc);
            ALT__T roots[2];
            roots[0] = (-B - sq) / ((ALT__T)2 * A);
            roots[1] = (-B + sq) / ((ALT__T)2 * A);
            for (k = 0; k < 2; ++k) {
                ALT__T t = roots[k], xc[3], v;
                if (!(t >= ray->tmin && t <= ray->tmax)) continue;
                if (found && !(t < best_t)) continue;
                xc[0] = o[0] + t * d[0] - c[0];
                xc[1] = o[1] + t * d[1] - c[1];
                xc[2] = o[2] + t * d[2] - c[2];
                /* height test as a squared distance to the centre: |x-c|^2 <= r^2 + h^2/4 */
                if (!(ALT__PRIV(dot)(xc, xc) <= r * r + h * h / (ALT__T)4)) continue;
                v = ALT__PRIV(dot)(ah, xc);
                n[0] = xc[0] - ah[0] * v, n[1] = xc[1] - ah[1] * v, n[2] = xc[2] - ah[2] * v;
                {                                                  /* projection of x - c */
                    ALT__T nl = ALT__SQRT(ALT__PRIV(dot)(n, n));
                    best_n[0] = n[0] / nl, best_n[1] = n[1] / nl, best_n[2] = n[2] / nl;
                }
                best_t = t;
                best_part = CYL_SIDE;
                found = 1;
            }
        }
    }

    if ((opts & CYL_CAPS) && isfinite(h) && (ad > (ALT__T)0 || ad < (ALT__T)0)) {
        for (k = 0; k < 2; ++k) {
            ALT__T sgn = k == 0 ? (ALT__T)-1 : (ALT__T)1;
            ALT__T ci[3], co[3], t, xr[3];
            ci[0] = c[0] + sgn * ah[0] * h / (ALT__T)2;
            ci[1] = c[1] + sgn * ah[1] * h / (ALT__T)2;
            ci[2] = c[2] + sgn * ah[2] * h / (ALT__T)2;
            co[0] = ci[0] - o[0], co[1] = ci[1] - o[1], co[2] = ci[2] - o[2];
            t = ALT__PRIV(dot)(ah, co) / ad;
            if (!(t >= ray->tmin && t <= ray->tmax)) continue;
            if (found && !(t < best_t)) continue;
            x[0] = o[0] + t * d[0], x[1] = o[1] + t * d[1], x[2] = o[2] + t * d[2];
            xr[0] = x[0] - ci[0], xr[1] = x[1] - ci[1], xr[2] = x[2] - ci[2];
            if (!(ALT__PRIV(dot)(xr, xr) <= r * r)) continue;
            best_n[0] = sgn * ah[0], best_n[1] = sgn * ah[1], best_n[2] = sgn * ah[2];
            best_t = t;
            best_part = k == 0 ? CYL_CAP_LOW : CYL_CAP_HIGH;
            found = 1;
        }
    }

    if (!found) return 0;
    out->t = best_t;
    out->n[0] = best_n[0], out->n[1] = best_n[1], out->n[2] = best_n[2];
    return 1 + best_part;
}

/* ray->d of unit length; tmin, tmax in units of it */
static inline int ALT__F(endpoint_solve)(const ALT__RAY *ray, const ALT__F(endpoint_cyl) *cyl,
                                         ALT__F(out) *out)
{
    const ALT__T *o = ray->o, *d = ray->d, *pa = cyl->pa, *pb = cyl->pb, ra = cyl->ra;
    /* the article's vec3 code, component by component (see the top of this file) */
    const ALT__T ba[3] = {pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]};
    const ALT__T oc[3] = {o[0] - pa[0], o[1] - pa[1], o[2] - pa[2]};
    ALT__T baba, bard, baoc, k2, k1, k0, disc, sq, t, y, m;

    baba = ALT__PRIV(dot)(ba, ba);
    bard = ALT__PRIV(dot)(ba, d);
    baoc = ALT__PRIV(dot)(ba, oc);
    k2 = baba - bard * bard;                               /* |d| = 1 */
    k1 = baba * ALT__PRIV(dot)(oc, d) - baoc * bard;
    k0 = baba * ALT__PRIV(dot)(oc, oc) - baoc * baoc - ra * ra * baba;
    disc = k1 * k1 - k2 * k0;
    if (!(disc >= (ALT__T)0)) return 0;
    sq = ALT__SQRT(disc);
    t = (-k1 - sq) / k2;
    y = baoc + t * bard;
    if (y > (ALT__T)0 && y < baba) {                       /* wall */
        ALT__T yb = y / baba;
        if (!(t >= ray->tmin && t <= ray->tmax)) return 0;
        out->t = t;
        out->n[0] = (oc[0] + t * d[0] - ba[0] * yb) / ra;
        out->n[1] = (oc[1] + t * d[1] - ba[1] * yb) / ra;
        out->n[2] = (oc[2] + t * d[2] - ba[2] * yb) / ra;
        return 1 + CYL_SIDE;
    }
    t = ((y < (ALT__T)0 ? (ALT__T)0 : baba) - baoc) / bard;  /* cap on the side of y */
    m = k1 + k2 * t;
    if (!((m < (ALT__T)0 ? -m : m) < sq)) return 0;
    if (!(t >= ray->tmin && t <= ray->tmax)) return 0;
    {
        ALT__T s = (y < (ALT__T)0 ? (ALT__T)-1 : (ALT__T)1) / ALT__SQRT(baba);
        out->t = t;
        out->n[0] = ba[0] * s, out->n[1] = ba[1] * s, out->n[2] = ba[2] * s;
    }
    return 1 + (y < (ALT__T)0 ? CYL_CAP_LOW : CYL_CAP_HIGH);
}

/* The library's signature, for code written against it (the viewer); not timed. */
static inline int ALT__F(literal_intersect)(const ALT__RAY *ray, const ALT__CYL *cyl,
                                            unsigned opts, ALT__HIT *hit)
{
    ALT__F(literal_cyl) lc;
    ALT__F(out) out;
    ALT__T s = (ALT__T)1, x[3];
    unsigned flags = 0u;
    int rc, i;
    ALT__F(literal_from)(cyl, &lc);
    rc = ALT__F(literal_solve)(ray, &lc, opts, &out);
    if (rc == 0) return CYL_MISS;
    if (ALT__PRIV(dot)(out.n, ray->d) > (ALT__T)0) {
        flags |= CYL_F_INSIDE;
        if (!(opts & CYL_OUTWARD)) s = (ALT__T)-1;
    }
    for (i = 0; i < 3; ++i) {
        x[i] = ray->o[i] + out.t * ray->d[i] - lc.c[i];
        hit->n[i] = s * out.n[i];
    }
    hit->t = out.t;
    hit->t_err = (ALT__T)INFINITY;
    hit->part = rc - 1;
    hit->v = rc - 1 == CYL_SIDE ? ALT__PRIV(dot)(lc.a, x)
             : (rc - 1 == CYL_CAP_LOW ? -lc.h : lc.h) / (ALT__T)2;
    hit->flags = flags;
    return CYL_HIT;
}

#endif /* ALT_FORMULATIONS_BODY */
