/* cyl_ref.c: exact MPFR reference for cylinder_isect.h. See cyl_ref.h for the contract and
 * the exactness argument. Written for clarity, not speed (tens of microseconds per case). */
#include "cyl_ref.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <gmp.h>
#include <mpfr.h>

#ifndef CYL_TANGENT_TOLF
#define CYL_TANGENT_TOLF 0x1p-16f
#endif
#ifndef CYL_TANGENT_TOL
#define CYL_TANGENT_TOL 0x1p-45
#endif
#ifndef CYL_PARALLEL_TOLF
#define CYL_PARALLEL_TOLF 0x1p-24f
#endif
#ifndef CYL_PARALLEL_TOL
#define CYL_PARALLEL_TOL 0x1p-53
#endif

#define RN MPFR_RNDN

/* ------------------------------------------------------------------ exact arithmetic
 * Every x* helper stores an exact result: products get prec(a)+prec(b) bits, sums enough bits
 * to cover both operands' bit ranges. The ternary value proves it (0 = exact). */

static void ref_die(const char *what)
{
    fprintf(stderr, "cyl_ref: internal error: %s was not exact\n", what);
    abort();
}

static void xinit(mpfr_t x) { mpfr_init2(x, MPFR_PREC_MIN); mpfr_set_zero(x, 1); }

static void xset_d(mpfr_t x, double v)
{
    mpfr_set_prec(x, 53);
    if (mpfr_set_d(x, v, RN) != 0) ref_die("set_d");
}

static void xcopy(mpfr_t r, const mpfr_t a)
{
    mpfr_t t;
    mpfr_init2(t, mpfr_get_prec(a));
    mpfr_set(t, a, RN);
    mpfr_swap(r, t);
    mpfr_clear(t);
}

static void xmul(mpfr_t r, const mpfr_t a, const mpfr_t b)
{
    mpfr_t t;
    mpfr_init2(t, mpfr_get_prec(a) + mpfr_get_prec(b));
    if (mpfr_mul(t, a, b, RN) != 0) ref_die("mul");
    mpfr_swap(r, t);
    mpfr_clear(t);
}

/* r = a + sgn*b exactly */
static void xaddsub(mpfr_t r, const mpfr_t a, const mpfr_t b, int sgn)
{
    mpfr_t t;
    if (mpfr_zero_p(b)) { xcopy(r, a); return; }
    if (mpfr_zero_p(a)) {
        xcopy(r, b);
        if (sgn < 0) mpfr_neg(r, r, RN);
        return;
    }
    {
        mpfr_exp_t ea = mpfr_get_exp(a), eb = mpfr_get_exp(b);
        mpfr_exp_t la = ea - (mpfr_exp_t)mpfr_get_prec(a), lb = eb - (mpfr_exp_t)mpfr_get_prec(b);
        mpfr_exp_t hi = (ea > eb ? ea : eb) + 1, lo = la < lb ? la : lb;
        mpfr_prec_t p = (mpfr_prec_t)(hi - lo + 1);
        if (p < MPFR_PREC_MIN) p = MPFR_PREC_MIN;
        mpfr_init2(t, p);
    }
    if ((sgn > 0 ? mpfr_add(t, a, b, RN) : mpfr_sub(t, a, b, RN)) != 0) ref_die("add");
    mpfr_swap(r, t);
    mpfr_clear(t);
}
static void xadd(mpfr_t r, const mpfr_t a, const mpfr_t b) { xaddsub(r, a, b, 1); }
static void xsub(mpfr_t r, const mpfr_t a, const mpfr_t b) { xaddsub(r, a, b, -1); }

/* r = a*b - c*d exactly */
static void xdop(mpfr_t r, const mpfr_t a, const mpfr_t b, const mpfr_t c, const mpfr_t d)
{
    mpfr_t u, v;
    xinit(u); xinit(v);
    xmul(u, a, b);
    xmul(v, c, d);
    xsub(r, u, v);
    mpfr_clear(u); mpfr_clear(v);
}

static void xdot(mpfr_t r, mpfr_t x[3], mpfr_t y[3])
{
    mpfr_t u, s;
    int i;
    xinit(u); xinit(s);
    for (i = 0; i < 3; ++i) {
        xmul(u, x[i], y[i]);
        xadd(s, s, u);
    }
    mpfr_swap(r, s);
    mpfr_clear(u); mpfr_clear(s);
}

static void xcross(mpfr_t r[3], mpfr_t x[3], mpfr_t y[3])
{
    xdop(r[0], x[1], y[2], x[2], y[1]);
    xdop(r[1], x[2], y[0], x[0], y[2]);
    xdop(r[2], x[0], y[1], x[1], y[0]);
}

/* ------------------------------------------------------------------ helpers */

static int all_finite(const double *v, int n)
{
    int i;
    for (i = 0; i < n; ++i)
        if (!isfinite(v[i])) return 0;
    return 1;
}

static int all_zero(const double *v)
{
    return !(v[0] < 0 || v[0] > 0 || v[1] < 0 || v[1] > 0 || v[2] < 0 || v[2] > 0);
}

static void span_of(double v, int *emin, int *emax)
{
    int e;
    if (!isfinite(v) || !(v < 0 || v > 0)) return;
    (void)frexp(v, &e);
    if (e > *emax) *emax = e;
    if (e - 53 < *emin) *emin = e - 53;
}

static double hd(const mpfr_t x) { return mpfr_get_d(x, RN); }

/* t[0..2] = x split into three doubles */
static void split3(double out[3], const mpfr_t x)
{
    mpfr_t r;
    int i;
    mpfr_init2(r, mpfr_get_prec(x));
    mpfr_set(r, x, RN);
    for (i = 0; i < 3; ++i) {
        out[i] = mpfr_get_d(r, RN);
        mpfr_sub_d(r, r, out[i], RN);
    }
    mpfr_clear(r);
}

/* ------------------------------------------------------------------ the reference */

int cyl_ref_intersect(const cyl_ref_case *in, cyl_ref_result *res)
{
    const int capped = (in->opts & CYL_CAPS) != 0;
    const double tol_t = in->prec == 24 ? (double)CYL_TANGENT_TOLF : (double)CYL_TANGENT_TOL;
    const double tol_p = in->prec == 24 ? (double)CYL_PARALLEL_TOLF : (double)CYL_PARALLEL_TOL;
    const int finite_h = isfinite(in->h);
    mpfr_t o[3], d[3], c[3], a[3], w[3], p[3], q[3];
    mpfr_t aa, ad, aw, dd, pp, pq, qq, wp, r, r2, r2aa, C, D, enum_, eden, tmp, tmp2, tolx;
    mpfr_t sa, H, sD, qv, t1, t2, s1, s2, lo, hi, x, y, z, u, n3[3], tmin, tmax, dlen;
    int i, parallel, wall_ok, grazing, emin = 1 << 20, emax = -(1 << 20);
    mpfr_prec_t P;
    double vals[20];
    cyl_ref_hit hits[2];
    int nh = 0, k;

    res->status = CYL_MISS;
    res->count = 0;
    res->e = res->sin2 = (double)NAN;
    res->m_tangent = res->m_parallel = res->m_rim = res->m_trange = res->margin = (double)INFINITY;
    res->prec_bits = 0;

    /* ---- validation, in the library's order. Also under CYL_TRUSTED: there the library's
       answer for invalid input is unspecified, and the exact arithmetic needs finite input. */
    {
        if (!all_finite(in->o, 3) || !all_finite(in->d, 3) || !all_finite(in->c, 3) ||
            !all_finite(in->a, 3)) return res->status = CYL_E_NONFINITE;
        if (all_zero(in->d)) return res->status = CYL_E_ZERO_DIR;
        if (all_zero(in->a)) return res->status = CYL_E_ZERO_AXIS;
        if (!(in->r > 0) || !isfinite(in->r)) return res->status = CYL_E_RADIUS;
        if (!(in->h > 0)) return res->status = CYL_E_HEIGHT;
        if (!(in->tmin <= in->tmax)) return res->status = CYL_E_TRANGE;
        if (in->opts & ~(unsigned)CYL_OPTIONS_ALL) return res->status = CYL_E_OPTION;
    }

    for (i = 0; i < 3; ++i) {
        vals[i] = in->o[i]; vals[3 + i] = in->d[i]; vals[6 + i] = in->c[i]; vals[9 + i] = in->a[i];
    }
    vals[12] = in->r; vals[13] = in->h; vals[14] = in->tmin; vals[15] = in->tmax;
    for (i = 0; i < 16; ++i) span_of(vals[i], &emin, &emax);
    P = 2 * (mpfr_prec_t)(emax - emin) + 64;
    if (P < 320) P = 320;
    res->prec_bits = (int)P;

    for (i = 0; i < 3; ++i) {
        xinit(o[i]); xinit(d[i]); xinit(c[i]); xinit(a[i]); xinit(w[i]); xinit(p[i]); xinit(q[i]);
        mpfr_init2(n3[i], P);
        xset_d(o[i], in->o[i]); xset_d(d[i], in->d[i]);
        xset_d(c[i], in->c[i]); xset_d(a[i], in->a[i]);
    }
    xinit(aa); xinit(ad); xinit(aw); xinit(dd); xinit(pp); xinit(pq); xinit(qq); xinit(wp);
    xinit(r); xinit(r2); xinit(r2aa); xinit(C); xinit(D); xinit(enum_); xinit(eden);
    xinit(tmp); xinit(tmp2); xinit(tolx);
    mpfr_inits2(P, sa, H, sD, qv, t1, t2, s1, s2, lo, hi, x, y, z, u, tmin, tmax, dlen, (mpfr_ptr)0);

    /* ---- exact polynomial quantities */
    for (i = 0; i < 3; ++i) xsub(w[i], o[i], c[i]);
    xcross(p, a, d);                /* p = a × d, |p| = |a||d| sin θ */
    xcross(q, a, w);                /* q = a × w, |q| = |a| × distance of o to the axis */
    xdot(aa, a, a); xdot(ad, a, d); xdot(aw, a, w); xdot(dd, d, d);
    xdot(pp, p, p); xdot(pq, p, q); xdot(qq, q, q); xdot(wp, w, p);
    xset_d(r, in->r);
    xmul(r2, r, r);
    xmul(r2aa, r2, aa);
    xsub(C, qq, r2aa);              /* wall: pp t² + 2 pq t + C = 0 */
    xmul(tmp, pq, pq);
    xmul(tmp2, pp, C);
    xsub(D, tmp, tmp2);             /* quarter discriminant = aa·(pp r² − (w·p)²) */

    /* e = 1 − ρ²/r² = enum_/eden; exactly parallel: ρ = |q|/|a| */
    if (mpfr_zero_p(pp)) {
        xcopy(enum_, C);
        mpfr_neg(enum_, enum_, RN);
        xcopy(eden, r2aa);
    } else {
        xmul(tmp, pp, r2);
        xmul(tmp2, wp, wp);
        xsub(enum_, tmp, tmp2);
        xmul(eden, pp, r2);
    }
    mpfr_div(x, enum_, eden, RN);
    res->e = hd(x);
    /* sin² θ = pp / (aa dd) */
    xmul(tmp, aa, dd);
    mpfr_div(x, pp, tmp, RN);
    res->sin2 = hd(x);

    /* parallel: sin θ ≤ tol_p  ⇔  pp ≤ tol_p² aa dd (tol_p is a power of two: exact) */
    xset_d(tolx, tol_p * tol_p);
    xmul(tmp2, tmp, tolx);
    parallel = mpfr_cmp(pp, tmp2) <= 0;
    if (mpfr_zero_p(pp)) res->m_parallel = 1.0;
    else {
        mpfr_sqrt(x, x, RN);
        mpfr_div_d(x, x, tol_p, RN);
        mpfr_sub_ui(x, x, 1, RN);
        res->m_parallel = fabs(hd(x));
    }
    /* grazing: |e| ≤ tol_t  ⇔  |enum_| ≤ tol_t eden */
    xset_d(tolx, tol_t);
    xmul(tmp, eden, tolx);
    grazing = mpfr_cmpabs(enum_, tmp) <= 0;
    res->m_tangent = fabs(res->e);
    if (in->opts & CYL_NO_TANGENT) {
        double m2 = fabs(res->e - tol_t);
        if (m2 < res->m_tangent) res->m_tangent = m2;
    }

    /* the wall gives crossings when not parallel, D ≥ 0, and not dropped as grazing */
    wall_ok = !parallel && mpfr_sgn(D) >= 0 && !((in->opts & CYL_NO_TANGENT) && grazing);

    mpfr_sqrt(sa, aa, RN);          /* |a| */
    mpfr_set_d(H, in->h, RN);
    mpfr_div_2ui(H, H, 1, RN);
    mpfr_set_d(tmin, in->tmin, RN);
    mpfr_set_d(tmax, in->tmax, RN);
    mpfr_sqrt(dlen, dd, RN);

    if (wall_ok) {                  /* stable pairing of the roots: qv/pp and C/qv */
        mpfr_sqrt(sD, D, RN);
        if (mpfr_sgn(pq) >= 0) { mpfr_add(qv, pq, sD, RN); mpfr_neg(qv, qv, RN); }
        else mpfr_sub(qv, sD, pq, RN);
        if (mpfr_zero_p(qv)) { mpfr_set_zero(t1, 1); mpfr_set_zero(t2, 1); }
        else {
            mpfr_div(t1, qv, pp, RN);
            mpfr_div(t2, C, qv, RN);
            if (mpfr_cmp(t1, t2) > 0) mpfr_swap(t1, t2);
        }
    }

    /* rim margins of the wall roots: v = (aw + t ad)/|a| */
    if (wall_ok && finite_h) {
        mpfr_t *tt[2];
        tt[0] = &t1; tt[1] = &t2;
        for (k = 0; k < 2; ++k) {
            mpfr_mul(x, *tt[k], ad, RN);
            mpfr_add(x, x, aw, RN);
            mpfr_div(x, x, sa, RN);
            mpfr_abs(x, x, RN);
            mpfr_sub(x, x, H, RN);
            mpfr_div(x, x, H, RN);
            if (fabs(hd(x)) < res->m_rim) res->m_rim = fabs(hd(x));
        }
    }

    /* the slab between the cap planes: s1 ≤ s2; ad = 0 → all t or none */
    {
        int slab_all = 0, slab_none = 0, cap_in[2] = {0, 0};
        if (capped && finite_h) {
            if (mpfr_zero_p(ad)) {
                mpfr_mul(x, H, sa, RN);
                mpfr_abs(y, aw, RN);
                if (mpfr_cmp(y, x) <= 0) slab_all = 1; else slab_none = 1;
            } else {
                mpfr_mul(x, H, sa, RN);
                mpfr_neg(y, x, RN);
                mpfr_sub(s1, y, aw, RN);
                mpfr_div(s1, s1, ad, RN);                         /* plane v = −H */
                mpfr_sub(s2, x, aw, RN);
                mpfr_div(s2, s2, ad, RN);                         /* plane v = +H */
                /* rim margins of the cap-plane crossings: ρ_x² = |q + s p|²/aa */
                for (k = 0; k < 2; ++k) {
                    mpfr_ptr s = k == 0 ? s1 : s2;
                    mpfr_set_zero(z, 1);
                    for (i = 0; i < 3; ++i) {
                        mpfr_mul(y, s, p[i], RN);
                        mpfr_add(y, y, q[i], RN);
                        mpfr_sqr(y, y, RN);
                        mpfr_add(z, z, y, RN);
                    }
                    mpfr_div(z, z, aa, RN);
                    mpfr_sqrt(z, z, RN);
                    cap_in[k] = mpfr_cmp(z, r) <= 0;
                    mpfr_sub(z, z, r, RN);
                    mpfr_div(z, z, r, RN);
                    if (fabs(hd(z)) < res->m_rim) res->m_rim = fabs(hd(z));
                }
            }
        }

        if (!capped) {
            /* open tube: both wall roots with |v| ≤ H */
            if (wall_ok) {
                mpfr_ptr tt[2];
                tt[0] = t1; tt[1] = t2;
                for (k = 0; k < 2; ++k) {
                    int on = 1;
                    if (finite_h) {
                        mpfr_mul(x, tt[k], ad, RN);
                        mpfr_add(x, x, aw, RN);
                        mpfr_div(x, x, sa, RN);
                        mpfr_abs(x, x, RN);
                        on = mpfr_cmp(x, H) <= 0;
                    }
                    if (!on) continue;
                    hits[nh].part = CYL_SIDE;
                    split3(hits[nh].t, tt[k]);
                    nh++;
                }
            }
        } else if (!slab_none) {
            /* solid: wall interval ∩ slab */
            int lo_inf = 0, hi_inf = 0, lo_part = CYL_SIDE, hi_part = CYL_SIDE;
            if (parallel) {
                /* no wall: each cap plane crossing is a hit where the ray point lies inside
                   its disk (the library's contract for CYL_F_PARALLEL) */
                mpfr_ptr sv[2];
                int pv[2], in2[2];
                if (!finite_h || slab_all) goto done_solid;
                sv[0] = s1; sv[1] = s2; pv[0] = CYL_CAP_LOW; pv[1] = CYL_CAP_HIGH;
                in2[0] = cap_in[0]; in2[1] = cap_in[1];
                if (mpfr_cmp(s1, s2) > 0) {
                    sv[0] = s2; sv[1] = s1; pv[0] = CYL_CAP_HIGH; pv[1] = CYL_CAP_LOW;
                    in2[0] = cap_in[1]; in2[1] = cap_in[0];
                }
                for (k = 0; k < 2; ++k)
                    if (in2[k]) { hits[nh].part = pv[k]; split3(hits[nh].t, sv[k]); nh++; }
                goto done_solid;
            } else if (!wall_ok) goto done_solid;
            mpfr_set(lo, t1, RN);
            mpfr_set(hi, t2, RN);
            if (finite_h && !slab_all) {
                int s1_part = mpfr_sgn(ad) > 0 ? CYL_CAP_LOW : CYL_CAP_HIGH;
                int s2_part = mpfr_sgn(ad) > 0 ? CYL_CAP_HIGH : CYL_CAP_LOW;
                if (mpfr_cmp(s1, s2) > 0) { mpfr_swap(s1, s2); }
                if (lo_inf || mpfr_cmp(s1, lo) > 0) { mpfr_set(lo, s1, RN); lo_inf = 0; lo_part = s1_part; }
                if (hi_inf || mpfr_cmp(s2, hi) < 0) { mpfr_set(hi, s2, RN); hi_inf = 0; hi_part = s2_part; }
            }
            if (lo_inf || hi_inf) goto done_solid;        /* infinite tube seen along its axis */
            if (mpfr_cmp(lo, hi) > 0) goto done_solid;
            hits[0].part = lo_part; split3(hits[0].t, lo);
            hits[1].part = hi_part; split3(hits[1].t, hi);
            nh = 2;
        done_solid:;
        }
    }

    /* t-range margins of the surface crossings, then keep those in [tmin, tmax] */
    {
        cyl_ref_hit kept[2];
        int nk = 0;
        for (k = 0; k < nh; ++k) {
            double t = hits[k].t[0];
            double scale = fabs(t);
            double rd = in->r / hd(dlen);
            if (rd > scale) scale = rd;
            if (isfinite(in->tmin)) {
                double m;
                mpfr_set_d(x, hits[k].t[0], RN); mpfr_add_d(x, x, hits[k].t[1], RN);
                mpfr_add_d(x, x, hits[k].t[2], RN); mpfr_sub(x, x, tmin, RN);
                m = fabs(hd(x)) / scale;
                if (m < res->m_trange) res->m_trange = m;
            }
            if (isfinite(in->tmax)) {
                double m;
                mpfr_set_d(x, hits[k].t[0], RN); mpfr_add_d(x, x, hits[k].t[1], RN);
                mpfr_add_d(x, x, hits[k].t[2], RN); mpfr_sub(x, x, tmax, RN);
                m = fabs(hd(x)) / scale;
                if (m < res->m_trange) res->m_trange = m;
            }
            mpfr_set_d(x, hits[k].t[0], RN); mpfr_add_d(x, x, hits[k].t[1], RN);
            mpfr_add_d(x, x, hits[k].t[2], RN);
            if (mpfr_cmp(x, tmin) >= 0 && mpfr_cmp(x, tmax) <= 0) kept[nk++] = hits[k];
        }
        for (k = 0; k < nk; ++k) hits[k] = kept[k];
        nh = nk;
    }

    /* normals, v and flags of the kept hits */
    for (k = 0; k < nh; ++k) {
        cyl_ref_hit *hh = &hits[k];
        mpfr_t tt;
        double sgn = 1.0;
        mpfr_init2(tt, P);
        mpfr_set_d(tt, hh->t[0], RN); mpfr_add_d(tt, tt, hh->t[1], RN);
        mpfr_add_d(tt, tt, hh->t[2], RN);
        /* v = (aw + t ad)/|a| */
        mpfr_mul(x, tt, ad, RN); mpfr_add(x, x, aw, RN); mpfr_div(x, x, sa, RN);
        hh->v = hd(x);
        if (hh->part == CYL_SIDE) {
            /* outward normal ∝ (w + t d) − a (v/|a|) */
            mpfr_div(y, x, sa, RN);                   /* v/|a| */
            mpfr_set_zero(z, 1);
            for (i = 0; i < 3; ++i) {
                mpfr_mul(n3[i], tt, d[i], RN);
                mpfr_add(n3[i], n3[i], w[i], RN);
                mpfr_mul(u, y, a[i], RN);
                mpfr_sub(n3[i], n3[i], u, RN);
                mpfr_sqr(u, n3[i], RN);
                mpfr_add(z, z, u, RN);
            }
            mpfr_sqrt(z, z, RN);
            for (i = 0; i < 3; ++i) mpfr_div(n3[i], n3[i], z, RN);
        } else {
            double s = hh->part == CYL_CAP_HIGH ? 1.0 : -1.0;
            for (i = 0; i < 3; ++i) { mpfr_div(n3[i], a[i], sa, RN); mpfr_mul_d(n3[i], n3[i], s, RN); }
            hh->v = s * in->h / 2;
        }
        /* n_out · d > 0 → exit crossing */
        mpfr_set_zero(z, 1);
        for (i = 0; i < 3; ++i) { mpfr_mul(u, n3[i], d[i], RN); mpfr_add(z, z, u, RN); }
        hh->flags = 0u;
        if (mpfr_sgn(z) > 0) {
            hh->flags |= CYL_F_INSIDE;
            if (!(in->opts & CYL_OUTWARD)) sgn = -1.0;
        }
        if (hh->part == CYL_SIDE && grazing) hh->flags |= CYL_F_TANGENT;
        if (parallel) hh->flags |= CYL_F_PARALLEL;
        for (i = 0; i < 3; ++i) hh->n[i] = sgn * hd(n3[i]);
        mpfr_clear(tt);
    }

    res->count = nh;
    for (k = 0; k < nh; ++k) res->hit[k] = hits[k];
    res->status = nh > 0 ? CYL_HIT : CYL_MISS;

    res->margin = res->m_tangent;
    if (res->m_parallel < res->margin) res->margin = res->m_parallel;
    if (res->m_rim < res->margin) res->margin = res->m_rim;
    if (res->m_trange < res->margin) res->margin = res->m_trange;

    for (i = 0; i < 3; ++i) {
        mpfr_clear(o[i]); mpfr_clear(d[i]); mpfr_clear(c[i]); mpfr_clear(a[i]);
        mpfr_clear(w[i]); mpfr_clear(p[i]); mpfr_clear(q[i]); mpfr_clear(n3[i]);
    }
    mpfr_clears(aa, ad, aw, dd, pp, pq, qq, wp, r, r2, r2aa, C, D, enum_, eden, tmp, tmp2, tolx,
                (mpfr_ptr)0);
    mpfr_clears(sa, H, sD, qv, t1, t2, s1, s2, lo, hi, x, y, z, u, tmin, tmax, dlen, (mpfr_ptr)0);
    return res->status;
}

int cyl_ref_t_within(const cyl_ref_hit *h, double t, double t_err)
{
    mpfr_t x;
    int ok;
    if (isnan(t) || isnan(t_err)) return 0;
    if (isinf(t_err)) return t_err > 0;
    mpfr_init2(x, 4000);    /* enough for the exact sum of four doubles of any exponents */
    mpfr_set_d(x, t, RN);
    mpfr_sub_d(x, x, h->t[0], RN);
    mpfr_sub_d(x, x, h->t[1], RN);
    mpfr_sub_d(x, x, h->t[2], RN);
    mpfr_abs(x, x, RN);
    ok = mpfr_cmp_d(x, t_err) <= 0;
    mpfr_clear(x);
    return ok;
}

double cyl_ref_ulp(const cyl_ref_hit *h, int prec)
{
    double T = h->t[0];
    int p = prec == 24 ? 24 : 53, emin = prec == 24 ? -149 : -1074, e = emin + p;
    if (T < 0 || T > 0) (void)frexp(T, &e);
    return ldexp(1.0, e - p > emin ? e - p : emin);
}

double cyl_ref_ulps(const cyl_ref_hit *h, double t, int prec)
{
    return (((t - h->t[0]) - h->t[1]) - h->t[2]) / cyl_ref_ulp(h, prec);
}

#ifndef CYL_NO_FLOAT
void cyl_ref_from_f(cyl_ref_case *in, const cylf_ray *ray, const cylf_cylinder *cyl,
                    unsigned opts)
{
    int i;
    for (i = 0; i < 3; ++i) {
        in->o[i] = (double)ray->o[i]; in->d[i] = (double)ray->d[i];
        in->c[i] = (double)cyl->c[i]; in->a[i] = (double)cyl->a[i];
    }
    in->tmin = (double)ray->tmin; in->tmax = (double)ray->tmax;
    in->r = (double)cyl->r; in->h = (double)cyl->h;
    in->opts = opts;
    in->prec = 24;
}
#endif

#ifndef CYL_NO_DOUBLE
void cyl_ref_from_d(cyl_ref_case *in, const cyld_ray *ray, const cyld_cylinder *cyl,
                    unsigned opts)
{
    int i;
    for (i = 0; i < 3; ++i) {
        in->o[i] = ray->o[i]; in->d[i] = ray->d[i];
        in->c[i] = cyl->c[i]; in->a[i] = cyl->a[i];
    }
    in->tmin = ray->tmin; in->tmax = ray->tmax;
    in->r = cyl->r; in->h = cyl->h;
    in->opts = opts;
    in->prec = 53;
}
#endif
