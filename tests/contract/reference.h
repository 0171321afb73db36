/* reference.h: the long double model of the exact geometry the contract tests compare with.
 *
 * ref_solve gives every hit of the exact ray-cylinder geometry of the inputs as stored in T
 * (long double arithmetic, so up to TOL_REF); chk_against_ref checks one library hit against
 * one reference hit. Used by reference.c.
 */
#ifndef REFERENCE_H
#define REFERENCE_H

#include "contract.h"

/* One hit of the exact geometry. */
typedef struct RefHit {
    long double t, v, n_out[3]; /* n_out: geometric outward normal */
    int part;
    unsigned flags;
} RefHit;

static inline void ref_fill(const RefGeom *g, long double t, int part, unsigned flags, RefHit *out)
{
    int i;
    out->t = t;
    out->part = part;
    out->flags = flags;
    out->v = g->aw + t * g->ad;
    if (part == CYL_SIDE) {
        long double x[3], len;
        for (i = 0; i < 3; i++) x[i] = g->w[i] + t * g->d[i];
        for (i = 0; i < 3; i++) x[i] -= g->ah[i] * out->v;
        len = sqrtl(dotl3(x, x));
        for (i = 0; i < 3; i++) out->n_out[i] = x[i] / len;
    } else {
        long double s = part == CYL_CAP_HIGH ? 1.0L : -1.0L;
        for (i = 0; i < 3; i++) out->n_out[i] = s * g->ah[i];
    }
}

/* All hits of the exact geometry in [tmin, tmax], sorted; for scenes far from every boundary
 * (no tangency flag, no parallel flag expected). Returns the count. */
static inline int ref_solve(const Ray *ray, const Cyl *cyl, int capped, RefHit out[2])
{
    RefGeom g;
    long double u[3], q[3], A, B, C, disc, s, t1, t2, lo, hi, tmin, tmax;
    int n = 0, lo_part, hi_part;
    ref_geom(ray, cyl, &g);
    tmin = (long double)ray->tmin;
    tmax = (long double)ray->tmax;
    crossl3(g.ah, g.d, u);
    crossl3(g.ah, g.w, q);
    A = dotl3(u, u);
    B = dotl3(u, q);
    C = dotl3(q, q) - g.r * g.r;
    if (A <= 0) { /* exactly parallel: inside the tube iff C <= 0, only caps can be hit */
        if (C > 0 || !capped || isinf(g.H)) return 0;
        t1 = -(long double)INFINITY;
        t2 = (long double)INFINITY;
    } else {
        disc = B * B - A * C;
        if (disc < 0) return 0;
        s = sqrtl(disc);
        if (B > 0) {
            long double qq = -(B + s);
            t1 = qq / A;
            t2 = C / qq;
        } else {
            long double qq = -B + s;
            t2 = qq / A;
            t1 = C / qq;
        }
        if (t1 > t2) { long double tt = t1; t1 = t2; t2 = tt; }
    }
    if (!capped) {
        if (A <= 0) return 0;
        if (t1 >= tmin && t1 <= tmax && fabsl(g.aw + t1 * g.ad) <= g.H)
            ref_fill(&g, t1, CYL_SIDE, 0u, &out[n++]);
        if (t2 >= tmin && t2 <= tmax && fabsl(g.aw + t2 * g.ad) <= g.H)
            ref_fill(&g, t2, CYL_SIDE, CYL_F_INSIDE, &out[n++]);
        return n;
    }
    if (isinf(g.H)) {
        lo = -(long double)INFINITY; hi = (long double)INFINITY; lo_part = hi_part = CYL_SIDE;
    } else if (!(g.ad < 0 || g.ad > 0)) { /* ray in a cap plane's direction */
        if (fabsl(g.aw) > g.H) return 0;
        lo = -(long double)INFINITY; hi = (long double)INFINITY; lo_part = hi_part = CYL_SIDE;
    } else {
        long double tl = (-g.H - g.aw) / g.ad, th = (g.H - g.aw) / g.ad;
        if (g.ad > 0) { lo = tl; hi = th; lo_part = CYL_CAP_LOW; hi_part = CYL_CAP_HIGH; }
        else { lo = th; hi = tl; lo_part = CYL_CAP_HIGH; hi_part = CYL_CAP_LOW; }
    }
    {
        long double te = t1 >= lo ? t1 : lo, tx = t2 <= hi ? t2 : hi;
        int pe = t1 >= lo ? CYL_SIDE : lo_part, px = t2 <= hi ? CYL_SIDE : hi_part;
        if (te > tx) return 0;
        if (te >= tmin && te <= tmax) ref_fill(&g, te, pe, 0u, &out[n++]);
        if (tx >= tmin && tx <= tmax) ref_fill(&g, tx, px, CYL_F_INSIDE, &out[n++]);
    }
    return n;
}

static inline long double ref_parallel_flag_needed(const Ray *ray, const Cyl *cyl)
{
    RefGeom g;
    long double u[3];
    ref_geom(ray, cyl, &g);
    crossl3(g.ah, g.d, u);
    return sqrtl(dotl3(u, u)) / g.dnorm; /* sin(theta) */
}

/* Checks one library hit against a reference hit: classification exactly, t within t_err (plus
 * the reference's own rounding), t_err useful, v and the normal (for the options used). */
static inline void chk_against_ref_at(const Ray *ray, const Cyl *cyl, unsigned opts, const Hit *h,
                                      const RefHit *rh, int strict, const char *what, int line)
{
    RefGeom g;
    long double scale, nd, nexp[3], size;
    unsigned extra = 0u;
    int i;
    char m[200];
    ref_geom(ray, cyl, &g);
    if (ref_parallel_flag_needed(ray, cyl) <= (long double)TOL_PARALLEL) extra = CYL_F_PARALLEL;
    scale = fabsl(rh->t) > g.tscale ? fabsl(rh->t) : g.tscale;
    snprintf(m, sizeof m, "%.120s: part", what);
    chk_int_at(rh->part, h->part, m, line);
    snprintf(m, sizeof m, "%.120s: flags", what);
    chk_int_at((long)(rh->flags | extra), (long)h->flags, m, line);
    snprintf(m, sizeof m, "%.120s: |t - t_exact| <= t_err", what);
    chk_near_at(rh->t, (long double)h->t, (long double)h->t_err + TOL_REF * scale, m, line);
    snprintf(m, sizeof m, "%.120s: t_err useful (<= 1024 ulp of max(|t|, r/|d|))", what);
    if (!((long double)h->t_err <= TOL_ERR_USEFUL * scale) || !(h->t_err >= 0)) {
        snprintf(m, sizeof m, "%.120s: t_err %.4Lg not in [0, %.4Lg]", what, (long double)h->t_err,
                 TOL_ERR_USEFUL * scale);
        UNITY_TEST_FAIL(line, m);
    }
    size = sqrtl(dotl3(g.w, g.w)) + fabsl(rh->t) * g.dnorm + g.r + (isinf(g.H) ? 0 : g.H);
    if (strict) {
        snprintf(m, sizeof m, "%.120s: t within 4 ulp of max(|t|, r/|d|)", what);
        chk_near_at(rh->t, (long double)h->t, (TOL_T_ULP4 + TOL_REF) * scale, m, line);
        snprintf(m, sizeof m, "%.120s: v", what);
        chk_near_at(rh->v, (long double)h->v, (TOL_V + TOL_REF) * size, m, line);
    } else {
        /* conditioning varies: v and n may move with t's error, which t_err bounds */
        long double dt = (long double)h->t_err + TOL_REF * scale;
        snprintf(m, sizeof m, "%.120s: v (within t_err's effect)", what);
        chk_near_at(rh->v, (long double)h->v, dt * fabsl(g.ad) + (TOL_V + TOL_REF) * size, m,
                    line);
    }
    snprintf(m, sizeof m, "%.120s: |v| <= h/2 (documented: a hit's v lies within the height)", what);
    UNITY_TEST_ASSERT(!((long double)T_FABS(h->v) > g.H), line, m);
    nd = dotl3(rh->n_out, g.d);
    for (i = 0; i < 3; i++)
        nexp[i] = (opts & CYL_OUTWARD) || nd <= 0 ? rh->n_out[i] : -rh->n_out[i];
    for (i = 0; i < 3; i++) {
        snprintf(m, sizeof m, "%.120s: n[%d]", what, i);
        chk_near_at(nexp[i], (long double)h->n[i],
                    TOL_NORMAL + TOL_REF +
                        (strict ? 0 : ((long double)h->t_err + TOL_REF * scale) * g.dnorm / g.r),
                    m, line);
    }
}
#define CHK_AGAINST_REF(ray, cyl, opts, h, rh, what) \
    chk_against_ref_at((ray), (cyl), (opts), (h), (rh), 1, (what), __LINE__)
#define CHK_AGAINST_REF_LOOSE(ray, cyl, opts, h, rh, what) \
    chk_against_ref_at((ray), (cyl), (opts), (h), (rh), 0, (what), __LINE__)

#endif /* REFERENCE_H */
