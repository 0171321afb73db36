/* eval.c: see eval.h. */
#define _POSIX_C_SOURCE 199309L
#include "eval.h"
#include "alt_formulations.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

volatile double ev_sink;

static double ev_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* One call and one timing loop per (variant, caps), each with constant options. gcc inlines
 * a static function called from one place (a user's render loop), but this file calls each
 * entry point from 20 places, and there gcc keeps it out of line with the options as run-time
 * values: nothing folded, and every variant ran the same code (gcc 12 -O2, up to 85d4d6d).
 * `flatten` inlines into each timing loop what the loop calls, as at a user's single
 * call site; what the header keeps out of line (noinline) stays out of line. The accuracy
 * calls need no inlining. Only the benchmark (EV_TIMING) times: the accuracy test's builds of
 * this file skip the inlining, which more than doubles the file's compile time.
 * Every timing loop has the same shape: its variant's own inputs, prepared by ev_set_inputs,
 * one call per case, the t of each hit summed. */
#if (defined(__GNUC__) || defined(__clang__)) && defined(EV_TIMING)
#define EV_FLATTEN __attribute__((flatten))
#else
#define EV_FLATTEN
#endif
#define EV_TIME_LOOP(NAME, RAY_T, RAYS, CYL_T, CYLS, HIT_T, CALL)                             \
    EV_FLATTEN static double NAME(const ev_inputs *in, int reps)                             \
    {                                                                                        \
        const RAY_T *R = (const RAY_T *)in->RAYS;                                             \
        const CYL_T *C = (const CYL_T *)in->CYLS;                                             \
        HIT_T h;                                                                             \
        double acc = 0, t0, t1;                                                              \
        int k, i, n = in->n;                                                                 \
        memset(&h, 0, sizeof h);                                                             \
        t0 = ev_now();                                                                       \
        for (k = 0; k < reps; ++k)                                                           \
            for (i = 0; i < n; ++i)                                                          \
                if (CALL > 0) acc += (double)h.t;                                            \
        t1 = ev_now();                                                                       \
        ev_sink += acc;                                                                      \
        return t1 - t0;                                                                      \
    }

/* the library: its own ray and cylinder */
#define EV_LIB1(P, TAG, OPTS, CAPS)                                                          \
    static int ev_call_##P##_##TAG##_##CAPS(const ev_inputs *in, int i, ev_out *o)          \
    {                                                                                        \
        cyl##P##_hit h;                                                                      \
        memset(&h, 0, sizeof h);                                                             \
        o->rc = cyl##P##_intersect((const cyl##P##_ray *)in->rays + i,                       \
                                   (const cyl##P##_cylinder *)in->cyls + i,                  \
                                   (OPTS) | ((CAPS) ? CYL_CAPS : 0u), &h);                   \
        o->t = (double)h.t; o->t_err = (double)h.t_err; o->part = h.part;                    \
        o->flags = h.flags;                                                                  \
        o->n[0] = (double)h.n[0]; o->n[1] = (double)h.n[1]; o->n[2] = (double)h.n[2];        \
        return o->rc;                                                                        \
    }                                                                                        \
    EV_TIME_LOOP(ev_time_##P##_##TAG##_##CAPS, cyl##P##_ray, rays, cyl##P##_cylinder, cyls,   \
                 cyl##P##_hit, cyl##P##_intersect(&R[i], &C[i],                              \
                                                  (OPTS) | ((CAPS) ? CYL_CAPS : 0u), &h))
#define EV_LIB(P, TAG, OPTS) EV_LIB1(P, TAG, OPTS, 0) EV_LIB1(P, TAG, OPTS, 1)

/* an alternative's answer (0 or 1 + part, t in units of its ray's d, outward n) in the case's
   units; d: the case's direction (any positive multiple) */
static void ev_alt_out(int rc, double t, double scale, const double n[3], const double d[3],
                       ev_out *o)
{
    o->rc = rc > 0 ? CYL_HIT : CYL_MISS;
    o->t = rc > 0 ? t / scale : 0.0;
    o->t_err = (double)INFINITY;
    o->part = rc > 0 ? rc - 1 : CYL_SIDE;
    o->n[0] = n[0]; o->n[1] = n[1]; o->n[2] = n[2];
    o->flags = rc > 0 && n[0] * d[0] + n[1] * d[1] + n[2] * d[2] > 0 ? CYL_F_INSIDE : 0u;
}
#define EV_ALT_OUT(RC, H, SCALE, RAY)                                                        \
    do {                                                                                     \
        double n_[3], d_[3];                                                                 \
        int j_;                                                                              \
        for (j_ = 0; j_ < 3; ++j_) { n_[j_] = (double)(H).n[j_]; d_[j_] = (double)(RAY)->d[j_]; } \
        ev_alt_out(RC, (double)(H).t, SCALE, n_, d_, o);                                     \
    } while (0)

/* the literal formulation: the library's ray, its own cylinder (unit axis) */
#define EV_LIT1(P, CAPS)                                                                     \
    static int ev_call_##P##_literal_##CAPS(const ev_inputs *in, int i, ev_out *o)          \
    {                                                                                        \
        alt##P##_out h;                                                                      \
        const cyl##P##_ray *ray = (const cyl##P##_ray *)in->rays + i;                        \
        int rc;                                                                              \
        memset(&h, 0, sizeof h);                                                             \
        rc = alt##P##_literal_solve(ray, (const alt##P##_literal_cyl *)in->lit + i,          \
                                    (CAPS) ? CYL_CAPS : 0u, &h);                             \
        EV_ALT_OUT(rc, h, 1.0, ray);                                                      \
        return o->rc;                                                                        \
    }                                                                                        \
    EV_TIME_LOOP(ev_time_##P##_literal_##CAPS, cyl##P##_ray, rays, alt##P##_literal_cyl, lit, \
                 alt##P##_out, alt##P##_literal_solve(&R[i], &C[i], (CAPS) ? CYL_CAPS : 0u, &h))

/* the end-point formulation: unit-direction ray, end points (capped only: one loop) */
#define EV_EP(P)                                                                             \
    static int ev_call_##P##_endpoint(const ev_inputs *in, int i, ev_out *o)                \
    {                                                                                        \
        alt##P##_out h;                                                                      \
        int rc;                                                                              \
        memset(&h, 0, sizeof h);                                                             \
        rc = alt##P##_endpoint_solve((const cyl##P##_ray *)in->ep_rays + i,                  \
                                     (const alt##P##_endpoint_cyl *)in->ep + i, &h);         \
        EV_ALT_OUT(rc, h, in->ep_scale[i], (const cyl##P##_ray *)in->rays + i);           \
        return o->rc;                                                                        \
    }                                                                                        \
    EV_TIME_LOOP(ev_time_##P##_endpoint, cyl##P##_ray, ep_rays, alt##P##_endpoint_cyl, ep,     \
                 alt##P##_out, alt##P##_endpoint_solve(&R[i], &C[i], &h))

#define EV_LIST(P)                                                                           \
    EV_LIB(P, lib, 0u)                                                                       \
    EV_LIB(P, precise, CYL_PRECISE)                                                          \
    EV_LIB(P, noerr, CYL_NO_ERRBOUND)                                                        \
    EV_LIB(P, nonrm, CYL_NO_NORMAL)                                                          \
    EV_LIB(P, lean, CYL_NO_ERRBOUND | CYL_NO_NORMAL)                                         \
    EV_LIB(P, trusted, CYL_TRUSTED)                                                          \
    EV_LIB(P, outward, CYL_OUTWARD)                                                          \
    EV_LIB(P, notan, CYL_NO_TANGENT)                                                         \
    EV_LIT1(P, 0) EV_LIT1(P, 1)                                                              \
    EV_EP(P)

EV_LIST(f)
EV_LIST(d)

#define EV_ROW(P, PREC, NAME, KIND, OPTS, TAG)                                               \
    {NAME, PREC, KIND, OPTS, {ev_call_##P##_##TAG##_0, ev_call_##P##_##TAG##_1},              \
     {ev_time_##P##_##TAG##_0, ev_time_##P##_##TAG##_1}}
#define EV_ROWS(P, PREC)                                                                     \
    EV_ROW(P, PREC, "lib", EV_LIB, 0u, lib),                                                 \
    EV_ROW(P, PREC, "lib+PRECISE", EV_LIB, CYL_PRECISE, precise),                            \
    EV_ROW(P, PREC, "lib+NO_ERRBOUND", EV_LIB, CYL_NO_ERRBOUND, noerr),                      \
    EV_ROW(P, PREC, "lib+NO_NORMAL", EV_LIB, CYL_NO_NORMAL, nonrm),                          \
    EV_ROW(P, PREC, "lib+NO_ERRBOUND+NO_NORMAL", EV_LIB, CYL_NO_ERRBOUND | CYL_NO_NORMAL,     \
           lean),                                                                            \
    EV_ROW(P, PREC, "lib+TRUSTED", EV_LIB, CYL_TRUSTED, trusted),                            \
    EV_ROW(P, PREC, "lib+OUTWARD", EV_LIB, CYL_OUTWARD, outward),                            \
    EV_ROW(P, PREC, "lib+NO_TANGENT", EV_LIB, CYL_NO_TANGENT, notan),                        \
    EV_ROW(P, PREC, "literal", EV_LITERAL, 0u, literal),                                     \
    {"endpoint", PREC, EV_ENDPOINT, 0u, {ev_call_##P##_endpoint, ev_call_##P##_endpoint},      \
     {ev_time_##P##_endpoint, ev_time_##P##_endpoint}}

const ev_variant ev_variants[] = {EV_ROWS(f, 24), EV_ROWS(d, 53)};
const int ev_variant_count = (int)(sizeof ev_variants / sizeof ev_variants[0]);

/* ------------------------------------------------------------------ case sets */

/* case k into slot i of every input form */
static void to_inputs(const bench_case *k, int prec, ev_inputs *in, int i)
{
    double dl = sqrt(k->d[0] * k->d[0] + k->d[1] * k->d[1] + k->d[2] * k->d[2]);
    int j;
    in->ep_scale[i] = dl;
    if (prec == 24) {
        cylf_ray *r = (cylf_ray *)in->rays + i, *u = (cylf_ray *)in->ep_rays + i;
        cylf_cylinder *c = (cylf_cylinder *)in->cyls + i;
        for (j = 0; j < 3; ++j) {
            r->o[j] = (float)k->o[j]; r->d[j] = (float)k->d[j];
            c->c[j] = (float)k->c[j]; c->a[j] = (float)k->a[j];
            u->o[j] = r->o[j]; u->d[j] = (float)(k->d[j] / dl);
        }
        r->tmin = (float)k->tmin; r->tmax = (float)k->tmax;
        u->tmin = (float)(k->tmin * dl); u->tmax = (float)(k->tmax * dl);
        c->r = (float)k->r; c->h = (float)k->h;
        altf_literal_from(c, (altf_literal_cyl *)in->lit + i);
        altf_endpoint_from(c, (altf_endpoint_cyl *)in->ep + i);
    } else {
        cyld_ray *r = (cyld_ray *)in->rays + i, *u = (cyld_ray *)in->ep_rays + i;
        cyld_cylinder *c = (cyld_cylinder *)in->cyls + i;
        for (j = 0; j < 3; ++j) {
            r->o[j] = k->o[j]; r->d[j] = k->d[j];
            c->c[j] = k->c[j]; c->a[j] = k->a[j];
            u->o[j] = r->o[j]; u->d[j] = k->d[j] / dl;
        }
        r->tmin = k->tmin; r->tmax = k->tmax;
        u->tmin = k->tmin * dl; u->tmax = k->tmax * dl;
        c->r = k->r; c->h = k->h;
        altd_literal_from(c, (altd_literal_cyl *)in->lit + i);
        altd_endpoint_from(c, (altd_endpoint_cyl *)in->ep + i);
    }
}

static void inputs_alloc(ev_inputs *in, int prec, int n)
{
    size_t m = (size_t)(n > 0 ? n : 1);
    in->n = n;
    in->rays = calloc(m, prec == 24 ? sizeof(cylf_ray) : sizeof(cyld_ray));
    in->cyls = calloc(m, prec == 24 ? sizeof(cylf_cylinder) : sizeof(cyld_cylinder));
    in->lit = calloc(m, prec == 24 ? sizeof(altf_literal_cyl) : sizeof(altd_literal_cyl));
    in->ep_rays = calloc(m, prec == 24 ? sizeof(cylf_ray) : sizeof(cyld_ray));
    in->ep = calloc(m, prec == 24 ? sizeof(altf_endpoint_cyl) : sizeof(altd_endpoint_cyl));
    in->ep_scale = (double *)calloc(m, sizeof(double));
    if (!in->rays || !in->cyls || !in->lit || !in->ep_rays || !in->ep || !in->ep_scale) abort();
}

static void inputs_free(ev_inputs *in)
{
    free(in->rays); free(in->cyls); free(in->lit); free(in->ep_rays); free(in->ep);
    free(in->ep_scale);
}

static void ref_case(const bench_case *k, int prec, unsigned opts, cyl_ref_case *in)
{
    int j;
    for (j = 0; j < 3; ++j) {
        in->o[j] = k->o[j]; in->d[j] = k->d[j]; in->c[j] = k->c[j]; in->a[j] = k->a[j];
    }
    in->tmin = k->tmin; in->tmax = k->tmax; in->r = k->r; in->h = k->h;
    in->opts = opts;
    in->prec = prec;
}

void ev_set_inputs(ev_set *s, int prec, int family, int caps, uint64_t seed, int n)
{
    int i, nt = 0;
    s->prec = prec; s->family = family; s->caps = caps; s->n = n;
    s->cases = (bench_case *)calloc((size_t)(n > 0 ? n : 1), sizeof *s->cases);
    s->ref = NULL;
    if (!s->cases) abort();
    for (i = 0; i < n; ++i) {
        bench_case_gen(family, prec, seed, (uint64_t)i, &s->cases[i]);
        if (!caps || isfinite(s->cases[i].h)) nt++;
    }
    inputs_alloc(&s->all, prec, n);
    inputs_alloc(&s->timed, prec, nt);
    for (i = 0, nt = 0; i < n; ++i) {
        to_inputs(&s->cases[i], prec, &s->all, i);
        if (!caps || isfinite(s->cases[i].h)) to_inputs(&s->cases[i], prec, &s->timed, nt++);
    }
}

void ev_set_make(ev_set *s, int prec, int family, int caps, uint64_t seed, int n)
{
    int i;
    ev_set_inputs(s, prec, family, caps, seed, n);
    s->ref = (cyl_ref_result *)calloc((size_t)(n > 0 ? n : 1), sizeof *s->ref);
    if (!s->ref) abort();
    for (i = 0; i < n; ++i) {
        cyl_ref_case in;
        ref_case(&s->cases[i], prec, caps ? CYL_CAPS : 0u, &in);
        cyl_ref_intersect(&in, &s->ref[i]);
    }
}

void ev_set_free(ev_set *s)
{
    free(s->cases); free(s->ref);
    inputs_free(&s->all);
    inputs_free(&s->timed);
    memset(s, 0, sizeof *s);
}

void ev_run(const ev_variant *v, const ev_set *s, int i, ev_out *o)
{
    memset(o, 0, sizeof *o);
    v->call[s->caps ? 1 : 0](&s->all, i, o);
}

int ev_expressible(const ev_variant *v, const ev_set *s, int i)
{
    return v->kind != EV_ENDPOINT || (s->caps && isfinite(s->cases[i].h));
}

int ev_variant_available(const ev_variant *v)
{
    /* one case the library answers in every build: CYL_PRECISE compiled out returns an
       error code */
    static const bench_case k = {{0, -5, 0}, {0, 1, 0}, 0.0, 100.0, {0, 0, 0}, {0, 0, 1}, 1.0,
                                 2.0, 0};
    ev_inputs in;
    ev_out o;
    int rc;
    inputs_alloc(&in, v->prec, 1);
    to_inputs(&k, v->prec, &in, 0);
    rc = v->call[1](&in, 0, &o);
    inputs_free(&in);
    return rc >= 0;
}

/* ------------------------------------------------------------------ metrics */

double ev_band(int prec) { return ldexp(1.0, -(prec - 8)); }

static double dlen(const bench_case *k)
{
    return sqrt(k->d[0] * k->d[0] + k->d[1] * k->d[1] + k->d[2] * k->d[2]);
}

double ev_kappa(const ev_set *s, int i)
{
    const cyl_ref_result *ref = &s->ref[i];
    const bench_case *k = &s->cases[i];
    double rd = k->r / dlen(k), T, scale, sn, e, kap = 1.0;
    if (ref->status != CYL_HIT) return 1.0;
    T = fabs(ref->hit[0].t[0]);
    if (!(T > 0)) return (double)INFINITY;
    scale = T > rd ? T : rd;
    if (ref->hit[0].part == CYL_SIDE) {
        /* half chord r·sqrt(e)/(|d| sin): a relative change u of the data moves it by about
           u·r/(|d| sin sqrt(e)) */
        sn = sqrt(ref->sin2);
        e = fabs(ref->e);
        if (!(sn > 0) || !(e > 0)) return (double)INFINITY;
        kap = rd / (sn * sqrt(e)) / scale;
        if (kap < 1.0) kap = 1.0;
    }
    /* errors of the order u·max(|t|, r/|d|) are inherent to rounding the data's geometry
       (o - c, r); counted in ulps of t they grow by scale/|t| when the origin is close */
    return kap * scale / T;
}

/* The full first-order condition of the reference t: each component of w = o - c, d and a,
   and r and h, moved by a relative u (componentwise), moves t by at most kappa_full·u·|t|.
   From the surface's equation at the hit x = w + t·d, with â = a/|a|, v = â·x and g = x − v·â
   (|g| = r on the wall):
     wall  |g|² − (stuff of r) = 0:  δt ≤ u·(Σ|g_j|(|w_j| + |t·d_j| + |v·â_j|) + r²) / |g·d|
     cap   â·x ∓ h/2 = 0:           δt ≤ u·(Σ|â_j|(|w_j| + |t·d_j|) + Σ|g_j·â_j| + h/2) / |â·d|
   (∂/∂a of â·x is g/|a|; of |g|², −2v·g/|a|.) ev_kappa counts r alone on the wall and nothing
   on a cap; this counts every datum, so it is at least 2 on most hits. ulps/kappa_full is how
   far an answer's error exceeds what the data's own rounding could cause: about 1 for a
   backward-stable method, whatever the hit's conditioning. */
double ev_kappa_full(const ev_set *s, int i)
{
    const bench_case *k = &s->cases[i];
    const cyl_ref_hit *hh = &s->ref[i].hit[0];
    long double w[3], d[3], ah[3], x[3], g[3], aa = 0, v = 0, t = (long double)hh->t[0];
    long double num = 0, den = 0;
    int j;
    if (s->ref[i].status != CYL_HIT || !(t < 0 || t > 0)) return (double)INFINITY;
    for (j = 0; j < 3; j++) aa += (long double)k->a[j] * (long double)k->a[j];
    for (j = 0; j < 3; j++) {
        w[j] = (long double)k->o[j] - (long double)k->c[j], d[j] = (long double)k->d[j];
        ah[j] = (long double)k->a[j] / sqrtl(aa);
        x[j] = w[j] + t * d[j], v += ah[j] * x[j];
    }
    for (j = 0; j < 3; j++) g[j] = x[j] - v * ah[j];
    for (j = 0; j < 3; j++) {
        if (hh->part == CYL_SIDE) {
            num += fabsl(g[j]) * (fabsl(w[j]) + fabsl(t * d[j]) + fabsl(v * ah[j]));
            den += g[j] * d[j];
        } else {
            num += fabsl(ah[j]) * (fabsl(w[j]) + fabsl(t * d[j])) + fabsl(g[j] * ah[j]);
            den += ah[j] * d[j];
        }
    }
    num += hh->part == CYL_SIDE ? (long double)k->r * (long double)k->r : (long double)k->h / 2;
    return (double)(num / fabsl(den) / fabsl(t));
}

int ev_well_conditioned(const ev_set *s, int i)
{
    return ev_kappa(s, i) <= EV_KAPPA_MAX && s->ref[i].margin > ev_band(s->prec);
}

static int cmp_dbl(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y ? 1 : 0;
}

/* A hit farther than this from the reference t (relative to max(|t|, r/|d|)) is a different
   crossing, not an inaccurate one: even tangent contacts are within about sqrt(u) < 2^-8.
   A wall hit whose CYL_F_INSIDE differs from the reference's is the other crossing too (the
   part and that flag tell the crossings apart even when they round to the same t). */
#define EV_WRONG_CROSSING_REL 0x1p-8

/* intersect_all (count, parts, crossings) and occluded against the reference, same options */
static void check_all(const ev_variant *v, const ev_set *s, int i, const cyl_ref_result *ref,
                      double band, ev_stats *st)
{
    const bench_case *k = &s->cases[i];
    unsigned opts = v->opts | (s->caps ? CYL_CAPS : 0u);
    double t[2] = {0, 0}, rd = k->r / dlen(k);
    int part[2] = {0, 0}, cnt, occ, j, bad = 0;
    unsigned fl[2] = {0u, 0u};
    if (s->prec == 24) {
        cylf_hit h[2];
        const cylf_ray *ray = (const cylf_ray *)s->all.rays + i;
        const cylf_cylinder *cyl = (const cylf_cylinder *)s->all.cyls + i;
        memset(h, 0, sizeof h);
        cnt = cylf_intersect_all(ray, cyl, opts, h);
        occ = cylf_occluded(ray, cyl, opts);
        for (j = 0; j < 2; ++j) { t[j] = (double)h[j].t; part[j] = h[j].part; fl[j] = h[j].flags; }
    } else {
        cyld_hit h[2];
        const cyld_ray *ray = (const cyld_ray *)s->all.rays + i;
        const cyld_cylinder *cyl = (const cyld_cylinder *)s->all.cyls + i;
        memset(h, 0, sizeof h);
        cnt = cyld_intersect_all(ray, cyl, opts, h);
        occ = cyld_occluded(ray, cyl, opts);
        for (j = 0; j < 2; ++j) { t[j] = h[j].t; part[j] = h[j].part; fl[j] = h[j].flags; }
    }
    if (cnt != ref->count) bad = 1;
    for (j = 0; !bad && j < cnt && j < 2; ++j) {
        double T = ref->hit[j].t[0], scale = fabs(T) > rd ? fabs(T) : rd;
        if (part[j] != ref->hit[j].part) bad = 1;
        else if (part[j] == CYL_SIDE && ((fl[j] ^ ref->hit[j].flags) & CYL_F_INSIDE) != 0u) bad = 1;
        else if (!(fabs(t[j] - T) / scale <= EV_WRONG_CROSSING_REL)) bad = 1;
    }
    if (bad) {
        st->all_miscls++;
        if (ref->margin > band) st->all_miscls_out++;
    }
    if (occ != (ref->count > 0 ? 1 : 0)) {
        st->occ_miscls++;
        if (ref->margin > band) st->occ_miscls_out++;
    }
}

void ev_eval(const ev_variant *v, const ev_set *s, ev_stats *st)
{
    const double band = ev_band(s->prec);
    const double tol_t = s->prec == 24 ? (double)CYL_TANGENT_TOLF : (double)CYL_TANGENT_TOL;
    double *ulps = (double *)malloc(sizeof(double) * (size_t)(s->n > 0 ? s->n : 1));
    int i, nu = 0;
    memset(st, 0, sizeof *st);
    st->miscls_worst_index = st->cond_worst_index = st->stab_worst_index = st->terr_fail_index = -1;
    if (!ulps) abort();

    for (i = 0; i < s->n; ++i) {
        const bench_case *k = &s->cases[i];
        const cyl_ref_result *ref = &s->ref[i];
        cyl_ref_result ref_nt;
        ev_out o;
        int lib_hit, ref_hit, wrong = 0;

        if (!ev_expressible(v, s, i)) continue;   /* the end-point form cannot express it */
        if ((v->opts & CYL_NO_TANGENT) && fabs(ref->e) <= 4 * tol_t) {
            cyl_ref_case in;
            ref_case(k, s->prec, (s->caps ? CYL_CAPS : 0u) | CYL_NO_TANGENT, &in);
            cyl_ref_intersect(&in, &ref_nt);
            ref = &ref_nt;
        }
        st->n++;
        ev_run(v, s, i, &o);
        if (o.rc < 0) st->n_error++;
        lib_hit = o.rc == CYL_HIT;
        ref_hit = ref->status == CYL_HIT;
        st->ref_hits += ref_hit;
        st->lib_hits += lib_hit;

        if (lib_hit != ref_hit) wrong = 1;
        else if (lib_hit) {
            double rd = k->r / dlen(k), T = ref->hit[0].t[0];
            double scale = fabs(T) > rd ? fabs(T) : rd;
            double err = fabs(o.t - T);
            if (o.part != ref->hit[0].part) wrong = 1;
            /* entry vs exit of the wall: a different crossing, however close in t */
            else if (o.part == CYL_SIDE &&
                     ((o.flags ^ ref->hit[0].flags) & CYL_F_INSIDE) != 0u) wrong = 1;
            else if (!(err / scale <= EV_WRONG_CROSSING_REL)) wrong = 1;
        }
        if (v->kind == EV_LIB) check_all(v, s, i, ref, band, st);
        if (wrong) {
            st->miscls++;
            if (ref->margin > band) st->miscls_out++;
            if (st->miscls_worst_index < 0 || ref->margin > st->miscls_worst_margin) {
                st->miscls_worst_margin = ref->margin;
                st->miscls_worst_index = i;
            }
            continue;
        }
        if (!lib_hit) continue;

        /* same crossing: accuracy of t, n and t_err */
        {
            const cyl_ref_hit *rh = &ref->hit[0];
            double rd = k->r / dlen(k), T = rh->t[0];
            double scale = fabs(T) > rd ? fabs(T) : rd;
            double u = fabs(cyl_ref_ulps(rh, o.t, s->prec));
            double rel = fabs(((o.t - rh->t[0]) - rh->t[1])) / scale;
            st->compared++;
            ulps[nu++] = u;
            if (rel > st->rel_max) st->rel_max = rel;
            if (ref == &s->ref[i] && ref->margin > band) {
                double q = u / ev_kappa_full(s, i);
                if (st->stab_worst_index < 0 || q > st->stab_max)
                    st->stab_max = q, st->stab_worst_index = i;
            }
            if (ref == &s->ref[i] && ev_well_conditioned(s, i)) {
                st->cond_n++;
                if (u > st->cond_ulp_max || st->cond_worst_index < 0) {
                    if (u > st->cond_ulp_max) st->cond_ulp_max = u;
                    if (u >= st->cond_ulp_max) st->cond_worst_index = i;
                }
            }
            /* at a tangency the normal is perpendicular to d: which side "faces the ray" is
               a coin toss, so normals are judged outside the band only */
            if (!(v->opts & CYL_NO_NORMAL) && ref->margin > band) {
                /* outward normals: the library with CYL_OUTWARD, and the alternatives */
                int outward = (v->opts & CYL_OUTWARD) || v->kind != EV_LIB;
                double sg = (outward && (rh->flags & CYL_F_INSIDE)) ? -1.0 : 1.0;
                double dx = o.n[0] - sg * rh->n[0], dy = o.n[1] - sg * rh->n[1],
                       dz = o.n[2] - sg * rh->n[2];
                double ne = sqrt(dx * dx + dy * dy + dz * dz);
                if (!(ne <= st->nrm_max)) st->nrm_max = ne;
            }
            if (v->kind == EV_LIB && !(v->opts & CYL_NO_ERRBOUND)) {
                st->terr_checked++;
                if (ref == &s->ref[i] && ev_well_conditioned(s, i)) {
                    double w = o.t_err / cyl_ref_ulp(rh, s->prec);
                    if (!(w <= st->terr_ulp_max)) st->terr_ulp_max = w;
                }
                if (!cyl_ref_t_within(rh, o.t, o.t_err)) {
                    if (st->terr_fail == 0) st->terr_fail_index = i;
                    st->terr_fail++;
                }
            }
        }
    }
    if (nu > 0) {
        qsort(ulps, (size_t)nu, sizeof *ulps, cmp_dbl);
        st->ulp_median = ulps[nu / 2];
        st->ulp_p99 = ulps[(int)((double)(nu - 1) * 0.99)];
        st->ulp_max = ulps[nu - 1];
    }
    free(ulps);
}
