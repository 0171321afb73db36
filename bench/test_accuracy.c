/* test_accuracy.c: the accuracy targets of issue 3, asserted on a fixed-seed sample of every
 * case family (bench/cases.c) against the exact MPFR reference (ref/cyl_ref.c).
 * Timing is not asserted here (shared, noisy machine): see `make report` for ns per call.
 *
 * Targets (p = 24 float, 53 double; band = 2^-(p-8)):
 *   1. t_err contains the exact t for every compared hit, every family, every library variant
 *      that computes t_err.
 *   2. Default path: no misclassification with a margin above the band in the well, huge, tiny
 *      and axis families (intersect, intersect_all and occluded); t within 4 ulps there
 *      (well-conditioned hits, see ev_kappa).
 *   2b. Default path, always asserted (also where the 4 ulps are not): t within
 *      DEFAULT_ULPS_PER_KAPPA ulps per unit of the data's own condition (ev_kappa_full) on every
 *      compared hit above the band of target 2's families, DEFAULT_ULPS_PER_KAPPA_ALL on every
 *      family: what a backward-stable method gives, and what the header's ACCURACY states.
 *   3. CYL_PRECISE: no misclassification with a margin above the band in every family
 *      (intersect, intersect_all and occluded); t within 2 ulps on every well-conditioned hit.
 *      Also on rays built one by one where the plain decisions go wrong: t-range ends by
 *      grazing crossings, the tangent band's edges (near and far origins), far rims.
 */
#include "unity.h"
#include "eval.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define SEED 20261122u         /* the report's default seed */
#define N_PER_SET 1000         /* cases per family x caps x precision: a few s in total */
#define DEFAULT_ULPS_MAX 4.0   /* target 2: default path, ulps of the exact t */
#define PRECISE_ULPS_MAX 2.0   /* target 3: CYL_PRECISE, ulps of the exact t */
/* Target 2b: ulps of the exact t over ev_kappa_full, which bounds (in units of u|t|) how far
   rounding every input by a relative u can move t: about 1 for a backward-stable method. */
#define DEFAULT_ULPS_PER_KAPPA 2.0     /* target 2's families */
#define DEFAULT_ULPS_PER_KAPPA_ALL 3.0 /* every family (far origins, grazing rays, ...) */
/* ACCURACY_4ULPS=0 (make ACCURACY_TARGETS=off): target 2's ulps are printed, not asserted,
   where the default tier computes in the API's own type (double, and float computed in float);
   its classification and every other target are. CI's run of v2, whose default tier does not
   meet the 4 ulps there (issue 28). */
#ifndef ACCURACY_4ULPS
#define ACCURACY_4ULPS 1
#endif
#if ACCURACY_4ULPS || !(defined(CYL_FLOAT_WIDE) && CYL_FLOAT_WIDE)
#define FLOAT_4ULPS ACCURACY_4ULPS
#else
#define FLOAT_4ULPS 1 /* computed in double, the float API meets them in every header */
#endif

/* Target 3 needs CYL_PRECISE, absent where the header defines CYL_NO_PRECISE (v2 with
   CYL_NO_DOUBLE, and the test_accuracy_noprec runner): main then leaves its tests out. */
#ifdef CYL_NO_PRECISE
#define HAVE_PRECISE 0
#else
#define HAVE_PRECISE 1
#endif

/* Exact equality, for the places where exactness is the point (-Wfloat-equal forbids ==). */
static int same(double a, double b) { return !(a < b) && !(a > b) && a - a < 1 && b - b < 1; }

void setUp(void) {}
void tearDown(void) {}

/* One evaluated sample: stats[prec_i][family][caps][variant] for the variants of that prec. */
static ev_stats stats[2][BF_COUNT][2][32];
static int have_stats;

static void evaluate_all(void)
{
    int pi, fam, caps, i;
    if (have_stats) return;
    for (pi = 0; pi < 2; ++pi)
        for (fam = 0; fam < BF_COUNT; ++fam)
            for (caps = 0; caps < 2; ++caps) {
                ev_set s;
                int prec = pi == 0 ? 24 : 53;
                ev_set_make(&s, prec, fam, caps, SEED, N_PER_SET);
                for (i = 0; i < ev_variant_count && i < 32; ++i) {
                    const ev_variant *v = &ev_variants[i];
                    memset(&stats[pi][fam][caps][i], 0, sizeof(ev_stats));
                    if (v->prec != prec || v->kind != EV_LIB || !ev_variant_available(v)) continue;
                    ev_eval(v, &s, &stats[pi][fam][caps][i]);
                }
                ev_set_free(&s);
            }
    have_stats = 1;
}

static int find_variant(int prec, const char *name)
{
    int i;
    for (i = 0; i < ev_variant_count; ++i)
        if (ev_variants[i].prec == prec && !strcmp(ev_variants[i].name, name)) return i;
    return -1;
}

/* ---------------------------------------------------------------- reference self-checks */

static void check_ref(double ox, double oy, double oz, double dx, double dy, double dz,
                      double r, double h, unsigned opts, int status, int count, double t0,
                      int part0, double t1)
{
    cyl_ref_case in;
    cyl_ref_result res;
    memset(&in, 0, sizeof in);
    in.o[0] = ox; in.o[1] = oy; in.o[2] = oz;
    in.d[0] = dx; in.d[1] = dy; in.d[2] = dz;
    in.a[2] = 2.0;                     /* axis z, length 2: only the direction counts */
    in.r = r; in.h = h;
    in.tmin = 0; in.tmax = (double)INFINITY;
    in.opts = opts; in.prec = 53;
    TEST_ASSERT_EQUAL_INT(status, cyl_ref_intersect(&in, &res));
    TEST_ASSERT_EQUAL_INT(count, res.count);
    if (count > 0) {
        /* exact answers: compared with == on purpose */
        TEST_ASSERT_TRUE(same(res.hit[0].t[0], t0) && same(res.hit[0].t[1], 0.0));
        TEST_ASSERT_EQUAL_INT(part0, res.hit[0].part);
    }
    if (count > 1) TEST_ASSERT_TRUE(same(res.hit[1].t[0], t1));
}

static void test_reference_exact_answers(void)
{
    cyl_ref_case in;
    cyl_ref_result res;
    /* through the axis: wall at x = -1 and x = +1 */
    check_ref(-5, 0, 0, 1, 0, 0, 1, 4, 0u, CYL_HIT, 2, 4.0, CYL_SIDE, 6.0);
    /* along the axis, capped: enters the low cap at z = -2, leaves at z = +2 */
    check_ref(0.5, 0, -9, 0, 0, 1, 1, 4, CYL_CAPS, CYL_HIT, 2, 7.0, CYL_CAP_LOW, 11.0);
    /* along the axis, open tube: parallel, no wall */
    check_ref(0.5, 0, -9, 0, 0, 1, 1, 4, 0u, CYL_MISS, 0, 0, 0, 0);
    /* above the tube, open: the wall ends at z = 2 */
    check_ref(-5, 0, 3, 1, 0, 0, 1, 4, 0u, CYL_MISS, 0, 0, 0, 0);
    /* origin inside, capped: leaves through the high cap at t = 2 */
    check_ref(0, 0, 0, 0, 0, 1, 1, 4, CYL_CAPS, CYL_HIT, 1, 2.0, CYL_CAP_HIGH, 0);
    /* exact tangency y = r: a double root, margin 0 */
    memset(&in, 0, sizeof in);
    in.o[0] = -5; in.o[1] = 1; in.d[0] = 2; in.a[2] = 1; in.r = 1; in.h = 4;
    in.tmax = (double)INFINITY; in.prec = 24;
    TEST_ASSERT_EQUAL_INT(CYL_HIT, cyl_ref_intersect(&in, &res));
    TEST_ASSERT_TRUE(same(res.e, 0.0) && same(res.margin, 0.0));
    TEST_ASSERT_TRUE(same(res.hit[0].t[0], 2.5));
    TEST_ASSERT_TRUE((res.hit[0].flags & CYL_F_TANGENT) != 0);
    /* the same with CYL_NO_TANGENT is a miss */
    in.opts = CYL_NO_TANGENT;
    TEST_ASSERT_EQUAL_INT(CYL_MISS, cyl_ref_intersect(&in, &res));
    /* validation order */
    in.r = -1; in.h = 0;
    TEST_ASSERT_EQUAL_INT(CYL_E_RADIUS, cyl_ref_intersect(&in, &res));
}

static void test_reference_t_within_is_exact(void)
{
    cyl_ref_hit h;
    memset(&h, 0, sizeof h);
    h.t[0] = 1.0; h.t[1] = 0x1p-80;       /* exact t = 1 + 2^-80 */
    TEST_ASSERT_TRUE(cyl_ref_t_within(&h, 1.0, 0x1p-80));
    TEST_ASSERT_FALSE(cyl_ref_t_within(&h, 1.0, 0x1p-81));
    TEST_ASSERT_FALSE(cyl_ref_t_within(&h, 1.0, 0.0));
    /* 1 + 2^-51 is 2 ulps (of 1, in double) above 1, so about 2 - 2^-29 ulps above t */
    TEST_ASSERT_TRUE(cyl_ref_ulps(&h, 1.0 + 0x1p-51, 53) > 1.99);
    TEST_ASSERT_TRUE(cyl_ref_ulps(&h, 1.0 + 0x1p-51, 53) < 2.0);
}

static void test_families_are_reproducible(void)
{
    bench_case a, b, c;
    int fam;
    for (fam = 0; fam < BF_COUNT; ++fam) {
        memset(&a, 0, sizeof a); memset(&b, 0, sizeof b); memset(&c, 0, sizeof c);
        bench_case_gen(fam, 24, 7, 3, &a);
        bench_case_gen(fam, 24, 7, 3, &b);
        bench_case_gen(fam, 24, 8, 3, &c);
        TEST_ASSERT_EQUAL_MEMORY(&a, &b, sizeof a);
        TEST_ASSERT_TRUE(memcmp(&a, &c, sizeof a) != 0);
        /* float cases hold float values exactly */
        TEST_ASSERT_TRUE(same((double)(float)a.o[0], a.o[0]) && same((double)(float)a.r, a.r));
    }
}

/* ---------------------------------------------------------------- targets */

static char msg[4096];

static void test_terr_contains_exact_t(void)
{
    int pi, fam, caps, i, fails = 0, checked = 0;
    size_t len = 0;
    evaluate_all();
    msg[0] = 0;
    for (pi = 0; pi < 2; ++pi)
        for (fam = 0; fam < BF_COUNT; ++fam)
            for (caps = 0; caps < 2; ++caps)
                for (i = 0; i < ev_variant_count && i < 32; ++i) {
                    const ev_stats *st = &stats[pi][fam][caps][i];
                    checked += st->terr_checked;
                    if (st->terr_fail == 0) continue;
                    fails += st->terr_fail;
                    if (len < sizeof msg - 200)
                        len += (size_t)snprintf(msg + len, sizeof msg - len,
                                                "[%s %s caps=%d %s: %d/%d, first case %d] ",
                                                pi ? "double" : "float", bench_family_name(fam),
                                                caps, ev_variants[i].name, st->terr_fail,
                                                st->terr_checked, st->terr_fail_index);
                }
    TEST_ASSERT_TRUE(checked > 1000);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, fails, msg);
}

/* The float API's t_err on the default path, in ulps of the exact t over the well-conditioned
   hits of the benign families: computed in double (CYL_FLOAT_WIDE), its bounds lie far below
   float's rounding, which t_err then adds, so t_err is that rounding, within an ulp (v1's and
   v2's, whose N5 takes N9's root bound only where it is below 2^-7 of float's ulp); computed
   in float, the residual bound in float's own u, within TERR_ULPS_NARROW. */
#define TERR_ULPS_WIDE 1.0
#define TERR_ULPS_NARROW 4096.0
static void test_default_terr_float_width(void)
{
    static const int fams[] = {BF_WELL, BF_FAR, BF_HUGE, BF_TINY, BF_AXIS, BF_TRANGE};
#if defined(CYL_FLOAT_WIDE) && !CYL_FLOAT_WIDE
    const double lim = TERR_ULPS_NARROW;
#else
    const double lim = TERR_ULPS_WIDE;
#endif
    int vi = find_variant(24, "lib"), f, caps, n = 0, wf = 0, wc = 0;
    double worst = 0;
    TEST_ASSERT_TRUE(vi >= 0);
    evaluate_all();
    for (f = 0; f < (int)(sizeof fams / sizeof fams[0]); ++f)
        for (caps = 0; caps < 2; ++caps) {
            const ev_stats *st = &stats[0][fams[f]][caps][vi];
            n += st->cond_n;
            if (!(st->terr_ulp_max <= worst)) worst = st->terr_ulp_max, wf = fams[f], wc = caps;
        }
    snprintf(msg, sizeof msg, "float lib: t_err up to %.3g ulps (%s caps=%d), limit %g", worst,
             bench_family_name(wf), wc, lim);
    TEST_ASSERT_TRUE(n > 1000);
    TEST_ASSERT_TRUE_MESSAGE(worst <= lim, msg);
}

static void check_targets(int prec, const char *variant, const int *families, int nfam,
                          double ulps_max)
{
    int pi = prec == 24 ? 0 : 1, vi = find_variant(prec, variant), f, caps, bad = 0, cond = 0;
    double worst = 0;
    size_t len = 0;
    TEST_ASSERT_TRUE(vi >= 0);
    if (!ev_variant_available(&ev_variants[vi])) {
        /* a variant this build cannot run is a tier the header compiles out, nothing else */
        TEST_ASSERT_TRUE_MESSAGE(!HAVE_PRECISE && (ev_variants[vi].opts & CYL_PRECISE) != 0u,
                                 "the variant answers an easy case with an error");
        TEST_IGNORE_MESSAGE("variant compiled out");
    }
    evaluate_all();
    msg[0] = 0;
    for (f = 0; f < nfam; ++f)
        for (caps = 0; caps < 2; ++caps) {
            const ev_stats *st = &stats[pi][families[f]][caps][vi];
            cond += st->cond_n;
            if (st->cond_ulp_max > worst) worst = st->cond_ulp_max;
            if (st->miscls_out == 0 && st->all_miscls_out == 0 && st->occ_miscls_out == 0 &&
                st->cond_ulp_max <= ulps_max) continue;
            bad++;
            if (len < sizeof msg - 240)
                len += (size_t)snprintf(msg + len, sizeof msg - len,
                                        "[%s caps=%d: %d misclassified beyond 2^-%d (worst "
                                        "margin %.3g, case %d), intersect_all %d, occluded %d; "
                                        "max %.3g ulps (case %d)] ",
                                        bench_family_name(families[f]), caps, st->miscls_out,
                                        prec - 8, st->miscls_worst_margin,
                                        st->miscls_worst_index, st->all_miscls_out,
                                        st->occ_miscls_out, st->cond_ulp_max,
                                        st->cond_worst_index);
        }
    TEST_ASSERT_TRUE(cond > 100);   /* the sample has well-conditioned hits to judge */
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, bad, msg);
    if (!(ulps_max <= DBL_MAX)) { /* the ulps not asserted: say what they are */
        snprintf(msg, sizeof msg, "%s %s: max %.3g ulps on well-conditioned hits, not asserted "
                 "(ACCURACY_4ULPS=0)", prec == 24 ? "float" : "double", variant, worst);
        TEST_MESSAGE(msg);
    }
}

static const int default_families[] = {BF_WELL, BF_HUGE, BF_TINY, BF_AXIS};
static const int all_families[] = {BF_WELL, BF_FAR, BF_PARALLEL, BF_GRAZING, BF_THIN,
                                   BF_SURFACE, BF_HUGE, BF_TINY, BF_AXIS, BF_TRANGE, BF_FLAT};

static void test_default_path_float(void)
{
    check_targets(24, "lib", default_families, 4, FLOAT_4ULPS ? DEFAULT_ULPS_MAX : (double)INFINITY);
}
static void test_default_path_double(void)
{
    check_targets(53, "lib", default_families, 4, ACCURACY_4ULPS ? DEFAULT_ULPS_MAX : (double)INFINITY);
}
/* Target 2b over families[0 .. nfam-1]: the largest ulps per unit of κ_full, at most per_kappa_max. */
static void check_stability(int prec, const int *families, int nfam, double per_kappa_max)
{
    int pi = prec == 24 ? 0 : 1, vi = find_variant(prec, "lib"), f, caps, n = 0, wf = 0, wc = 0, wi = -1;
    double worst = 0;
    TEST_ASSERT_TRUE(vi >= 0);
    evaluate_all();
    for (f = 0; f < nfam; ++f)
        for (caps = 0; caps < 2; ++caps) {
            const ev_stats *st = &stats[pi][families[f]][caps][vi];
            n += st->compared;
            if (st->stab_worst_index >= 0 && st->stab_max > worst)
                worst = st->stab_max, wf = families[f], wc = caps, wi = st->stab_worst_index;
        }
    snprintf(msg, sizeof msg, "%s lib: %.3g ulps per unit of kappa_full (%s caps=%d, case %d), limit %g",
             prec == 24 ? "float" : "double", worst, bench_family_name(wf), wc, wi, per_kappa_max);
    TEST_ASSERT_TRUE(n > 1000);
    TEST_ASSERT_TRUE_MESSAGE(worst <= per_kappa_max, msg);
}
static void test_default_stability_float(void)
{
    check_stability(24, default_families, 4, DEFAULT_ULPS_PER_KAPPA);
    check_stability(24, all_families, BF_COUNT, DEFAULT_ULPS_PER_KAPPA_ALL);
}
static void test_default_stability_double(void)
{
    check_stability(53, default_families, 4, DEFAULT_ULPS_PER_KAPPA);
    check_stability(53, all_families, BF_COUNT, DEFAULT_ULPS_PER_KAPPA_ALL);
}

static void test_precise_float(void)
{
#if CYL_FLOAT_WIDE
    check_targets(24, "lib+PRECISE", all_families, BF_COUNT, PRECISE_ULPS_MAX);
#else
    /* In float only, the flat family (last in all_families) is past what float's double
       words resolve: a rim decision there errs by about 2^-46 r/(h sin) (the header's Extreme
       ratios), so it is left out here. */
    check_targets(24, "lib+PRECISE", all_families, BF_COUNT - 1, PRECISE_ULPS_MAX);
#endif
}
static void test_precise_double(void)
{
    check_targets(53, "lib+PRECISE", all_families, BF_COUNT, PRECISE_ULPS_MAX);
}

/* CYL_PRECISE against t-range ends put just outside the band of the exact nearest crossing, on
 * grazing rays (ray-axis distance r(1 ± 10^-k)), where the plain roundings move a root by about
 * u/√|e| relative, more than the distance to the end: the tier must decide these right (by its
 * bound, else by the solver), while inside the band it may take the plain comparison. The
 * default path fails this check (116 of the 512 double cases take the wrong crossing). */
#define TRANGE_CASES 300          /* grazing cases per precision and caps setting */
#define TRANGE_BANDS 4.0          /* the end sits this many bands from the exact crossing */

static void trange_case(int prec, const bench_case *k, unsigned opts, double tmin,
                        cyl_ref_result *rr, int *rc, double *t, double *terr, int *part)
{
    cyl_ref_case in;
    int j;
    memset(&in, 0, sizeof in);
    for (j = 0; j < 3; ++j) {
        in.o[j] = k->o[j]; in.d[j] = k->d[j]; in.c[j] = k->c[j]; in.a[j] = k->a[j];
    }
    in.tmin = tmin; in.tmax = k->tmax; in.r = k->r; in.h = k->h;
    in.opts = opts; in.prec = prec;
    cyl_ref_intersect(&in, rr);
    if (prec == 24) {
        cylf_ray ray; cylf_cylinder cyl; cylf_hit h;
        for (j = 0; j < 3; ++j) {
            ray.o[j] = (float)k->o[j]; ray.d[j] = (float)k->d[j];
            cyl.c[j] = (float)k->c[j]; cyl.a[j] = (float)k->a[j];
        }
        ray.tmin = (float)tmin; ray.tmax = (float)k->tmax; cyl.r = (float)k->r; cyl.h = (float)k->h;
        memset(&h, 0, sizeof h); /* a miss leaves it untouched, and it is read below */
        *rc = cylf_intersect(&ray, &cyl, opts, &h);
        *t = h.t; *terr = h.t_err; *part = h.part;
    } else {
        cyld_ray ray; cyld_cylinder cyl; cyld_hit h;
        for (j = 0; j < 3; ++j) {
            ray.o[j] = k->o[j]; ray.d[j] = k->d[j]; cyl.c[j] = k->c[j]; cyl.a[j] = k->a[j];
        }
        ray.tmin = tmin; ray.tmax = k->tmax; cyl.r = k->r; cyl.h = k->h;
        memset(&h, 0, sizeof h);
        *rc = cyld_intersect(&ray, &cyl, opts, &h);
        *t = h.t; *terr = h.t_err; *part = h.part;
    }
}

static void check_precise_trange_grazing(int prec)
{
    int i, caps, side, checked = 0, bad = 0;
    size_t len = 0;
    double band = ldexp(1.0, -(prec - 8));
    msg[0] = 0;
    for (i = 0; i < TRANGE_CASES; ++i)
        for (caps = 0; caps < 2; ++caps) {
            unsigned opts = CYL_PRECISE | (caps ? CYL_CAPS : 0u);
            bench_case k;
            cyl_ref_result rr;
            int rc, part;
            double t, terr, t0, scale, dl;
            bench_case_gen(BF_GRAZING, prec, SEED, (uint64_t)i, &k);
            trange_case(prec, &k, opts, k.tmin, &rr, &rc, &t, &terr, &part);
            if (rr.status != CYL_HIT) continue;
            t0 = rr.hit[0].t[0];
            dl = sqrt(k.d[0] * k.d[0] + k.d[1] * k.d[1] + k.d[2] * k.d[2]);
            scale = fabs(t0) > k.r / dl ? fabs(t0) : k.r / dl;
            for (side = -1; side <= 1; side += 2) {
                double tmin = t0 + side * TRANGE_BANDS * band * scale, te;
                if (prec == 24) tmin = (double)(float)tmin;
                trange_case(prec, &k, opts, tmin, &rr, &rc, &t, &terr, &part);
                if (!(rr.margin > band)) continue; /* some other decision is within its band */
                checked++;
                te = rr.status == CYL_HIT ? rr.hit[0].t[0] + rr.hit[0].t[1] : 0;
                if (rc == rr.status &&
                    (rc != CYL_HIT || (part == rr.hit[0].part && fabs(t - te) <= terr)))
                    continue;
                bad++;
                if (len < sizeof msg - 160)
                    len += (size_t)snprintf(msg + len, sizeof msg - len,
                                            "[case %d caps=%d tmin %s: rc %d (exact %d), t %.17g "
                                            "(exact %.17g)] ", i, caps, side < 0 ? "below" : "above",
                                            rc, rr.status, t, te);
            }
        }
    /* cases with a hit whose every margin is above the band: 228 float, 512 double */
    TEST_ASSERT_TRUE(checked > TRANGE_CASES / 2);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, bad, msg);
}

static void test_precise_trange_grazing_float(void) { check_precise_trange_grazing(24); }
static void test_precise_trange_grazing_double(void) { check_precise_trange_grazing(53); }

/* CYL_PRECISE on grazing rays built one by one around the tangent band: axis z, r = 1, the
 * ray's closest approach to the axis at ρ = 1 + σ·10^-k (σ = ±1, k = 2 .. 15 in double, 2 .. 8
 * in float), so e = 1 − ρ²/r² runs from well outside the band to inside it on both sides.
 * These pin the tier's paths that the family samples only reach by chance: a contact inside
 * the band decided and answered from double-word coefficients (two roots, or none and both
 * ends at the point of closest approach), and a crossing whose start one step with the plain
 * √(|a|²D) cannot correct (the step with √ from its own residual, or more steps). Against the
 * exact reference: the same count, parts and crossings wherever the margin exceeds the band;
 * t_err contains the exact t; and t within INBAND_ULPS_MAX ulps of it on every hit, contacts
 * inside the band included (the plain D, which errs by about the band's width, leaves those
 * off by orders of magnitude more: with the double-word path short-circuited, this test fails
 * in double). */
#define INBAND_ULPS_MAX 4.0  /* a root or −B/A from coefficients good to about 2u, rounded */

/* x rounded to float, through memory: gcc 12.2 -O2 dropped the conversions of the plain
   (double)(float) round trip in the loop below, vectorized with its neighbours (SLP; not with
   -fno-tree-slp-vectorize), so the reference saw the unrounded case */
static double to_float(double x)
{
    volatile float f = (float)x;
    return (double)f;
}

/* The axis a, its length na and two directions across it, e1 and e2 (orthonormal with a/na:
   exactly for z_axis, within rounding for oblique, which only moves where the rounded case
   lands); the cylinder's center, r = 1 and h = 3 are band_case's. */
typedef struct band_frame { double a[3], na, e1[3], e2[3]; } band_frame;
static const band_frame z_axis = {{0, 0, 2}, 2, {1, 0, 0}, {0, 1, 0}};
static const double band_c[3] = {0.25, -0.5, 0.125};

/* The ray (o, dn) against the cylinder c = (0.25, -0.5, 0.125), a, r = 1, h = 3 by CYL_PRECISE's
   intersect_all and the exact reference: a count, part or INSIDE flag differing where the margin
   exceeds the band, a t outside its t_err, or more than INBAND_ULPS_MAX ulps off, is counted bad. */
static void band_case(int prec, const double a[3], double o[3], double dn[3], unsigned opts,
                      const char *what, int *checked, int *inband, int *bad, size_t *len)
{
    const double *c = band_c, r = 1, h = 3;
    double band = ldexp(1.0, -(prec - 8)), t[2] = {0, 0}, te[2] = {0, 0};
    cyl_ref_case in;
    cyl_ref_result rr;
    int j, n, part[2] = {0, 0}, wrong = 0;
    unsigned fl[2] = {0u, 0u};
    if (prec == 24)
        for (j = 0; j < 3; ++j) { o[j] = to_float(o[j]); dn[j] = to_float(dn[j]); }
    memset(&in, 0, sizeof in);
    for (j = 0; j < 3; ++j) { in.o[j] = o[j]; in.d[j] = dn[j]; in.c[j] = c[j]; in.a[j] = a[j]; }
    in.tmin = 0; in.tmax = (double)INFINITY; in.r = r; in.h = h; in.opts = opts; in.prec = prec;
    cyl_ref_intersect(&in, &rr);
    if (prec == 24) {
        cylf_ray ray; cylf_cylinder cyl; cylf_hit hs[2];
        memset(hs, 0, sizeof hs);
        for (j = 0; j < 3; ++j) {
            ray.o[j] = (float)o[j]; ray.d[j] = (float)dn[j];
            cyl.c[j] = (float)c[j]; cyl.a[j] = (float)a[j];
        }
        ray.tmin = 0; ray.tmax = (float)INFINITY; cyl.r = (float)r; cyl.h = (float)h;
        n = cylf_intersect_all(&ray, &cyl, opts, hs);
        for (j = 0; j < 2; ++j) { t[j] = hs[j].t; te[j] = hs[j].t_err; part[j] = hs[j].part; fl[j] = hs[j].flags; }
    } else {
        cyld_ray ray; cyld_cylinder cyl; cyld_hit hs[2];
        memset(hs, 0, sizeof hs);
        for (j = 0; j < 3; ++j) { ray.o[j] = o[j]; ray.d[j] = dn[j]; cyl.c[j] = c[j]; cyl.a[j] = a[j]; }
        ray.tmin = 0; ray.tmax = (double)INFINITY; cyl.r = r; cyl.h = h;
        n = cyld_intersect_all(&ray, &cyl, opts, hs);
        for (j = 0; j < 2; ++j) { t[j] = hs[j].t; te[j] = hs[j].t_err; part[j] = hs[j].part; fl[j] = hs[j].flags; }
    }
    (*checked)++;
    if (fabs(rr.e) <= (prec == 24 ? (double)CYL_TANGENT_TOLF : (double)CYL_TANGENT_TOL)) (*inband)++;
    if (n != rr.count) wrong = rr.margin > band;
    if (n == 2 && !(t[0] <= t[1])) wrong = 1; /* sorted by t */
    for (j = 0; j < n; ++j) /* a cap crossing is no grazing wall contact */
        if (part[j] != CYL_SIDE && (fl[j] & CYL_F_TANGENT) != 0u) wrong = 1;
    for (j = 0; !wrong && j < n && j < rr.count; ++j) {
        const cyl_ref_hit *x = &rr.hit[j];
        if (part[j] != x->part || ((fl[j] ^ x->flags) & CYL_F_INSIDE) != 0u) {
            wrong = rr.margin > band;
            break;
        }
        if (!cyl_ref_t_within(x, t[j], te[j]) || !(fabs(cyl_ref_ulps(x, t[j], prec)) <= INBAND_ULPS_MAX))
            wrong = 1;
    }
    if (!wrong) return;
    (*bad)++;
    if (*len < sizeof msg - 200)
        *len += (size_t)snprintf(msg + *len, sizeof msg - *len,
                                 "[%s opts %u: count %d (exact %d), t %.17g +- %.3g (exact %.17g, "
                                 "%.3g ulps)] ", what, opts, n, rr.count, t[0], te[0], rr.hit[0].t[0],
                                 rr.count > 0 ? cyl_ref_ulps(&rr.hit[0], t[0], prec) : 0.0);
}

/* A ray whose closest approach to the axis is rho·e1 + v0·â from c, at angle th to the axis,
   from sd before it. */
static void near_band_case(int prec, const band_frame *fr, double rho, double th, double sd, double v0,
                           unsigned opts, int *checked, int *inband, int *bad, size_t *len)
{
    double dn[3], o[3];
    char what[80];
    int j;
    for (j = 0; j < 3; ++j) {
        dn[j] = sin(th) * fr->e2[j] + cos(th) * fr->a[j] / fr->na;
        o[j] = band_c[j] + rho * fr->e1[j] + v0 * fr->a[j] / fr->na - sd * dn[j];
    }
    snprintf(what, sizeof what, "rho 1%+.0e th %.2f sd %.3g v0 %.2f", rho - 1, th, sd, v0);
    band_case(prec, fr->a, o, dn, opts, what, checked, inband, bad, len);
}

/* The sweep: rho = 1 ± 10^-k (k from k0 to 15 in double, to 8 in float) at the angles ths, from
   the distances sds, at the offsets v0s along fr's axis, open and capped; no bad case. */
static void sweep_band(int prec, const band_frame *fr, int k0, const double *sds, int nsd,
                       const double *v0s, int nv0, int *checked, int *inband)
{
    static const double ths[] = {0.3, 0.7, 1.1, 1.4};
    int k, sg, ti, si, vi, caps, bad = 0;
    size_t len = 0;
    msg[0] = 0;
    for (k = k0; k <= (prec == 24 ? 8 : 15); ++k)
        for (sg = -1; sg <= 1; sg += 2)
            for (ti = 0; ti < 4; ++ti)
                for (si = 0; si < nsd; ++si)
                    for (vi = 0; vi < nv0; ++vi)
                        for (caps = 0; caps < 2; ++caps)
                            near_band_case(prec, fr, 1 + sg * pow(10.0, -k), ths[ti], sds[si], v0s[vi],
                                           CYL_PRECISE | (caps ? CYL_CAPS : 0u), checked, inband,
                                           &bad, &len);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, bad, msg);
}

static void check_precise_near_band(int prec)
{
    static const double sds[] = {3, 5.5, 8}, v0s[] = {-0.7, 0.2, 1.1, 1.5}; /* the last: the high rim */
    int checked = 0, inband = 0;
    sweep_band(prec, &z_axis, 2, sds, 3, v0s, 4, &checked, &inband);
    /* every k covered; in double k = 14, 15 (and in float 6 .. 8) lie inside the band */
    TEST_ASSERT_TRUE(inband >= checked / 8);
}

static void test_precise_near_band_float(void) { check_precise_near_band(24); }
static void test_precise_near_band_double(void) { check_precise_near_band(53); }

/* An oblique axis a = (0.5, -0.75, 1.25): e1 = â × x̂ normalized, e2 = â × e1. */
static band_frame oblique_frame(void)
{
    band_frame fr = {{0.5, -0.75, 1.25}, 0, {0, 0, 0}, {0, 0, 0}};
    double na = fr.na = sqrt(0.5 * 0.5 + 0.75 * 0.75 + 1.25 * 1.25), n1;
    int j;
    fr.e1[1] = fr.a[2] / na, fr.e1[2] = -fr.a[1] / na, n1 = sqrt(fr.e1[1] * fr.e1[1] + fr.e1[2] * fr.e1[2]);
    fr.e1[1] /= n1, fr.e1[2] /= n1;
    for (j = 0; j < 3; ++j) {
        int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
        fr.e2[j] = (fr.a[j1] * fr.e1[j2] - fr.a[j2] * fr.e1[j1]) / na;
    }
    return fr;
}

/* The same around the band's edges from far origins (1e3 .. 1e7 r along the ray) and an oblique
 * axis, where the plain e carries about u·|o − c|/r (N6): the hot path's s, m and P round, so
 * its band decision can be off by far more than the band. The tier must doubt the band itself
 * (band_doubt, N9): a crossing pair the plain D puts below the band returns as a miss before
 * any root bound is formed. The default path gets the count of 178 of the 1008 double cases
 * wrong beyond the band (as N6 allows it); with band_doubt short-circuited, so does this tier. */
static void check_precise_far_band(int prec)
{
    static const double sds[] = {1e3, 1e5, 1e7}, v0s[] = {-0.7, 0.2, 1.1};
    const band_frame fr = oblique_frame();
    int checked = 0, inband = 0;
    sweep_band(prec, &fr, prec == 24 ? 3 : 9, sds, 3, v0s, 3, &checked, &inband);
    /* k from outside the band into it: 864 float, 1008 double cases, 30 and 38 of them in it */
    TEST_ASSERT_TRUE(inband > 0 && inband < checked / 8);
}
static void test_precise_far_band_float(void) { check_precise_far_band(24); }
static void test_precise_far_band_double(void) { check_precise_far_band(53); }

/* CYL_PRECISE at the rim from far origins: rays from 1e3 .. 1e7 r away through the wall point at
 * angle phi around the oblique axis and axial v = (h/2)(1 + σ·10^-k), just inside or outside
 * the high rim, leaving the wall at angle be to its inward normal (toward +â for be > 0). The
 * plain v = (z0 + tζ)/|a| carries about u·|o − c|/(h/2) relative (N6), far more than these
 * margins; the tier must doubt the rim (its rim bounds, N9) and decide it exactly. The default
 * path decides 134 of the 1152 double cases wrong beyond the band (as N6 allows it); with the
 * rim certificates short-circuited, so does this tier. */
static void check_precise_far_rim(int prec)
{
    static const double phis[] = {0.4, 2.1, 4.0}, bes[] = {-1.2, -0.6, 0.6, 1.2}, sds[] = {1e3, 1e5, 1e7};
    const band_frame fr = oblique_frame();
    int j, k, sg, pi, bi, si, caps, checked = 0, inband = 0, bad = 0;
    size_t len = 0;
    msg[0] = 0;
    for (k = prec == 24 ? 3 : 6; k <= (prec == 24 ? 6 : 13); ++k)
        for (sg = -1; sg <= 1; sg += 2)
            for (pi = 0; pi < 3; ++pi)
                for (bi = 0; bi < 4; ++bi)
                    for (si = 0; si < 3; ++si)
                        for (caps = 0; caps < 2; ++caps) {
                            double n[3], p[3], dn[3], o[3], v = 1.5 * (1 + sg * pow(10.0, -k));
                            char what[80];
                            for (j = 0; j < 3; ++j) {
                                n[j] = cos(phis[pi]) * fr.e1[j] + sin(phis[pi]) * fr.e2[j];
                                p[j] = band_c[j] + n[j] + v * fr.a[j] / fr.na;
                                dn[j] = -cos(bes[bi]) * n[j] + sin(bes[bi]) * fr.a[j] / fr.na;
                                o[j] = p[j] - sds[si] * dn[j];
                            }
                            snprintf(what, sizeof what, "rim v 1%+.0e phi %.1f be %.1f sd %.3g",
                                     sg * pow(10.0, -k), phis[pi], bes[bi], sds[si]);
                            band_case(prec, fr.a, o, dn, CYL_PRECISE | (caps ? CYL_CAPS : 0u), what, &checked,
                                      &inband, &bad, &len);
                        }
    TEST_ASSERT_TRUE(checked == (prec == 24 ? 576 : 1152)); /* every k: 4 float, 8 double */
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, bad, msg);
}
static void test_precise_far_rim_float(void) { check_precise_far_rim(24); }
static void test_precise_far_rim_double(void) { check_precise_far_rim(53); }

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_reference_exact_answers);
    RUN_TEST(test_reference_t_within_is_exact);
    RUN_TEST(test_families_are_reproducible);
    RUN_TEST(test_terr_contains_exact_t);
    RUN_TEST(test_default_terr_float_width);
    RUN_TEST(test_default_path_float);
    RUN_TEST(test_default_path_double);
    RUN_TEST(test_default_stability_float);
    RUN_TEST(test_default_stability_double);
    if (HAVE_PRECISE) { /* the precise tier's targets where it is compiled in (not under CYL_NO_PRECISE) */
        RUN_TEST(test_precise_float);
        RUN_TEST(test_precise_double);
        RUN_TEST(test_precise_trange_grazing_float);
        RUN_TEST(test_precise_trange_grazing_double);
        RUN_TEST(test_precise_near_band_float);
        RUN_TEST(test_precise_near_band_double);
        RUN_TEST(test_precise_far_band_float);
        RUN_TEST(test_precise_far_band_double);
        RUN_TEST(test_precise_far_rim_float);
        RUN_TEST(test_precise_far_rim_double);
    }
    return UNITY_END();
}
