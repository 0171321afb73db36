/* alt_formulations.h: the two ray/cylinder formulations users would otherwise pick, written
 * out from their published math so that the benchmark and the viewer can put them side by side
 * with cylinder_isect.h on the same cases.
 *
 *   #include "cylinder_isect.h"      (for the ray, cylinder and hit types and the CYL_* codes)
 *   #include "bench/alt_formulations.h"
 *
 *   int altf_literal_intersect(const cylf_ray *, const cylf_cylinder *, unsigned opts, cylf_hit *);
 *   int altd_literal_intersect(const cyld_ray *, const cyld_cylinder *, unsigned opts, cyld_hit *);
 *   int altf_quilez_intersect (const cylf_ray *, const cylf_cylinder *, unsigned opts, cylf_hit *);
 *   int altd_quilez_intersect (const cyld_ray *, const cyld_cylinder *, unsigned opts, cyld_hit *);
 *
 * Same signature and geometry as cylf_intersect / cyld_intersect: nearest hit with t in
 * [tmin, tmax], fills t, n, v, part and flags (CYL_F_INSIDE when the crossing is an exit),
 * t_err = +INFINITY (neither formulation has an error bound), returns CYL_HIT or CYL_MISS and
 * leaves *hit untouched on a miss. Honoured options: CYL_CAPS (literal only, see below) and
 * CYL_OUTWARD; every other bit is ignored. There is no input validation: both are what a user
 * would write, and they are deliberately NOT made robust. Do not "fix" their numerics: they
 * exist to show what the textbook arithmetic gives.
 *
 * 1. The literal formulation ("ray vs cylinder with center c, axis a, radius r, height h",
 *    the classic exercise taken literally).
 *    With â = a/‖a‖ and w = o − c, a point x is on the infinite cylinder when the part of
 *    x − c orthogonal to the axis, obtained with the projection (I − â âᵀ)(x − c), has squared
 *    length r². Putting x = o + t d and writing the projections as d⊥ = d − â(âᵀd),
 *    w⊥ = w − â(âᵀw):
 *        A t² + B t + C = 0,  A = d⊥·d⊥,  B = 2 d⊥·w⊥,  C = w⊥·w⊥ − r²,
 *    solved with the textbook formula t = (−B ± √(B² − 4AC)) / (2A).
 *    Height test of a wall point: a wall point is at distance r from the axis, so its axial
 *    coordinate v satisfies v² = ‖x − c‖² − r²; the exercise's test |v| ≤ h/2 becomes the
 *    squared-distance test ‖x − c‖² ≤ r² + h²/4 (no square root, as the exercise does it).
 *    Caps (with CYL_CAPS): cap centres c_i = c ∓ â h/2; the plane âᵀ(x − c_i) = 0 gives
 *    t = âᵀ(c_i − o) / âᵀd and the point is on the disk when ‖x − c_i‖² ≤ r².
 *    Without CYL_CAPS it is the open tube; h = +INFINITY gives the infinite tube.
 *    A = 0 (ray parallel to the axis) gives no wall root; âᵀd = 0 gives no cap crossing.
 *
 * 2. The end-point formulation popularised by Inigo Quilez's "intersectors" article
 *    (capped cylinder given by its end points pa, pb and radius ra). Derivation:
 *    ba = pb − pa, oc = o − pa, and for a point p = oc + t d relative to pa, y = ba·p is the
 *    axial coordinate scaled by ‖ba‖ and the squared distance to the axis times ‖ba‖² is
 *    (ba·ba)(p·p) − y². Setting it to ra²(ba·ba) gives k2 t² + 2 k1 t + k0 = 0 with
 *        k2 = (ba·ba)(d·d) − (ba·d)²,
 *        k1 = (ba·ba)(oc·d) − (ba·oc)(ba·d),
 *        k0 = (ba·ba)(oc·oc) − (ba·oc)² − ra²(ba·ba)
 *    (the article assumes |d| = 1, so its k2 has no d·d; we keep d·d so that t stays in units
 *    of d). Only the near root t = (−k1 − √(k1² − k2 k0)) / k2 is used ("nearest hit from
 *    outside"). If its y is strictly between 0 and ba·ba it is the wall hit; otherwise the ray
 *    is tested against the cap plane on the side of y (y = 0 or y = ba·ba):
 *    t = (y_cap − ba·oc)/(ba·d), accepted when |k1 + k2 t| < √(k1² − k2 k0), i.e. when that t
 *    lies strictly between the two wall roots (inside the infinite cylinder).
 *    Mapping: pa = c − â h/2 (CYL_CAP_LOW side), pb = c + â h/2, ra = r.
 *    Limitations of the formulation, kept on purpose: it is capped-only (CYL_CAPS is implied,
 *    an open tube cannot be expressed), it cannot express h = +INFINITY (gives a miss), an
 *    origin inside the cylinder gets the near root behind it (so a miss, or a cap found by
 *    chance), and a ray exactly parallel to the axis divides by k2 = 0. The answer is the
 *    formulation's one hit: if its t is outside [tmin, tmax] the result is a miss (no search
 *    for a later hit).
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

static inline ALT__T ALT__PRIV(dot)(const ALT__T x[3], const ALT__T y[3])
{
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

/* Fills *hit with outward normal n_out; turns it to face the ray unless CYL_OUTWARD. */
static inline void ALT__PRIV(fill)(const ALT__RAY *ray, unsigned opts, ALT__T t,
                                   const ALT__T n_out[3], ALT__T v, int part, ALT__HIT *hit)
{
    ALT__T s = (ALT__T)1;
    unsigned flags = 0u;
    if (ALT__PRIV(dot)(n_out, ray->d) > (ALT__T)0) {
        flags |= CYL_F_INSIDE;
        if (!(opts & CYL_OUTWARD)) s = (ALT__T)-1;
    }
    hit->t = t;
    hit->t_err = (ALT__T)INFINITY;
    hit->n[0] = s * n_out[0];
    hit->n[1] = s * n_out[1];
    hit->n[2] = s * n_out[2];
    hit->v = v;
    hit->part = part;
    hit->flags = flags;
}

static inline int ALT__F(literal_intersect)(const ALT__RAY *ray, const ALT__CYL *cyl,
                                            unsigned opts, ALT__HIT *hit)
{
    const ALT__T *o = ray->o, *d = ray->d, *c = cyl->c;
    const ALT__T r = cyl->r, h = cyl->h;
    ALT__T al = ALT__SQRT(ALT__PRIV(dot)(cyl->a, cyl->a));
    ALT__T ah[3], w[3], dp[3], wp[3], x[3], n[3];
    ALT__T ad, aw, A, B, C, disc, best_t = (ALT__T)0, best_n[3] = {0, 0, 0}, best_v = (ALT__T)0;
    int i, k, best_part = CYL_SIDE, found = 0;

    for (i = 0; i < 3; ++i) {
        ah[i] = cyl->a[i] / al;
        w[i] = o[i] - c[i];
    }
    ad = ALT__PRIV(dot)(ah, d);
    aw = ALT__PRIV(dot)(ah, w);
    for (i = 0; i < 3; ++i) {           /* projections (I - a a^T) d and (I - a a^T) w */
        dp[i] = d[i] - ah[i] * ad;
        wp[i] = w[i] - ah[i] * aw;
    }
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
                for (i = 0; i < 3; ++i) xc[i] = o[i] + t * d[i] - c[i];
                /* height test as a squared distance to the centre: |x-c|^2 <= r^2 + h^2/4 */
                if (!(ALT__PRIV(dot)(xc, xc) <= r * r + h * h / (ALT__T)4)) continue;
                v = ALT__PRIV(dot)(ah, xc);
                for (i = 0; i < 3; ++i) n[i] = xc[i] - ah[i] * v;   /* projection of x - c */
                {
                    ALT__T nl = ALT__SQRT(ALT__PRIV(dot)(n, n));
                    for (i = 0; i < 3; ++i) best_n[i] = n[i] / nl;
                }
                best_t = t;
                best_v = v;
                best_part = CYL_SIDE;
                found = 1;
            }
        }
    }

    if ((opts & CYL_CAPS) && isfinite(h) && (ad > (ALT__T)0 || ad < (ALT__T)0)) {
        for (k = 0; k < 2; ++k) {
            ALT__T sgn = k == 0 ? (ALT__T)-1 : (ALT__T)1;
            ALT__T ci[3], co[3], t, xr[3];
            for (i = 0; i < 3; ++i) {
                ci[i] = c[i] + sgn * ah[i] * h / (ALT__T)2;
                co[i] = ci[i] - o[i];
            }
            t = ALT__PRIV(dot)(ah, co) / ad;
            if (!(t >= ray->tmin && t <= ray->tmax)) continue;
            if (found && !(t < best_t)) continue;
            for (i = 0; i < 3; ++i) {
                x[i] = o[i] + t * d[i];
                xr[i] = x[i] - ci[i];
            }
            if (!(ALT__PRIV(dot)(xr, xr) <= r * r)) continue;
            for (i = 0; i < 3; ++i) best_n[i] = sgn * ah[i];
            best_t = t;
            best_v = sgn * h / (ALT__T)2;
            best_part = k == 0 ? CYL_CAP_LOW : CYL_CAP_HIGH;
            found = 1;
        }
    }

    if (!found) return CYL_MISS;
    ALT__PRIV(fill)(ray, opts, best_t, best_n, best_v, best_part, hit);
    return CYL_HIT;
}

static inline int ALT__F(quilez_intersect)(const ALT__RAY *ray, const ALT__CYL *cyl,
                                           unsigned opts, ALT__HIT *hit)
{
    const ALT__T *o = ray->o, *d = ray->d;
    const ALT__T ra = cyl->r, hh = cyl->h / (ALT__T)2;
    ALT__T al = ALT__SQRT(ALT__PRIV(dot)(cyl->a, cyl->a));
    ALT__T ah[3], pa[3], pb[3], ba[3], oc[3], n[3];
    ALT__T baba, bard, baoc, k2, k1, k0, disc, sq, t, y;
    int i;

    for (i = 0; i < 3; ++i) {
        ah[i] = cyl->a[i] / al;
        pa[i] = cyl->c[i] - ah[i] * hh;
        pb[i] = cyl->c[i] + ah[i] * hh;
    }
    for (i = 0; i < 3; ++i) {
        ba[i] = pb[i] - pa[i];
        oc[i] = o[i] - pa[i];
    }
    baba = ALT__PRIV(dot)(ba, ba);
    bard = ALT__PRIV(dot)(ba, d);
    baoc = ALT__PRIV(dot)(ba, oc);
    k2 = baba * ALT__PRIV(dot)(d, d) - bard * bard;
    k1 = baba * ALT__PRIV(dot)(oc, d) - baoc * bard;
    k0 = baba * ALT__PRIV(dot)(oc, oc) - baoc * baoc - ra * ra * baba;
    disc = k1 * k1 - k2 * k0;
    if (!(disc >= (ALT__T)0)) return CYL_MISS;
    sq = ALT__SQRT(disc);
    t = (-k1 - sq) / k2;
    y = baoc + t * bard;
    if (y > (ALT__T)0 && y < baba) {                       /* wall */
        if (!(t >= ray->tmin && t <= ray->tmax)) return CYL_MISS;
        for (i = 0; i < 3; ++i) n[i] = (oc[i] + t * d[i] - ba[i] * y / baba) / ra;
        ALT__PRIV(fill)(ray, opts, t, n, y / baba * cyl->h - hh, CYL_SIDE, hit);
        return CYL_HIT;
    }
    t = ((y < (ALT__T)0 ? (ALT__T)0 : baba) - baoc) / bard;  /* cap on the side of y */
    {
        ALT__T m = k1 + k2 * t;
        if (!((m < (ALT__T)0 ? -m : m) < sq)) return CYL_MISS;
    }
    if (!(t >= ray->tmin && t <= ray->tmax)) return CYL_MISS;
    {
        ALT__T sgn = y < (ALT__T)0 ? (ALT__T)-1 : (ALT__T)1;
        for (i = 0; i < 3; ++i) n[i] = sgn * ah[i];
        ALT__PRIV(fill)(ray, opts, t, n, sgn * hh, y < (ALT__T)0 ? CYL_CAP_LOW : CYL_CAP_HIGH,
                        hit);
    }
    return CYL_HIT;
}

#endif /* ALT_FORMULATIONS_BODY */
