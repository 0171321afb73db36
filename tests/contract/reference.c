/* Contract tests, against the long double reference (reference.h). The fixed scenes and 3000
 * seeded random ones under every option set: classification, count, t within t_err, useful t_err,
 * v and normals; CYL_PRECISE against the same reference; t_err containing closed-form roots.
 *
 * Written once for both precisions (see contract.h). make test runs it inside tests/test_float.c
 * and tests/test_double.c; alone: make test-one T=reference CFG=gcc-O0 (tests/README.md).
 */
#include "reference.h"

/* ================================================================== reference comparison */
/* The fixed scenes must exercise what they claim: a precondition of the reference test (not a
 * test of its own, since it does not depend on the library). */
static void chk_scene_coverage(void)
{
    size_t i;
    int seen_side = 0, seen_low = 0, seen_high = 0, seen_inside_first = 0, seen_miss = 0;
    for (i = 0; i < N_SCENES; i++) {
        Ray ray;
        Cyl cyl;
        RefHit rh[2];
        int n, j;
        scene_get(&scenes[i], &ray, &cyl);
        n = ref_solve(&ray, &cyl, 1, rh);
        if (n == 0) seen_miss++;
        if (n == 1 && (rh[0].flags & CYL_F_INSIDE)) seen_inside_first++;
        for (j = 0; j < n; j++) {
            if (rh[j].part == CYL_SIDE) seen_side++;
            if (rh[j].part == CYL_CAP_LOW) seen_low++;
            if (rh[j].part == CYL_CAP_HIGH) seen_high++;
        }
    }
    CHECK(seen_side && seen_low && seen_high && seen_inside_first && seen_miss,
          "scene list covers side, both caps, inside origins and misses");
}

/* Every generic scene under every option set: count, parts, flags, t within t_err, useful
 * t_err, v, normals, against the long double reference. */
static void test_scenes_against_reference(void)
{
    size_t i, k;
    int j;
    char m[160];
    chk_scene_coverage();
    for (i = 0; i < N_SCENES; i++) {
        for (k = 0; k < N_OPT_SETS; k++) {
            Ray ray;
            Cyl cyl;
            Hit hs[2];
            RefHit rh[2];
            unsigned opts = opt_sets[k];
            int n, nref;
            scene_get(&scenes[i], &ray, &cyl);
            nref = ref_solve(&ray, &cyl, (opts & CYL_CAPS) != 0, rh);
            sentinel(hs, 2);
            n = rt_intersect_all(&ray, &cyl, opts, hs);
            snprintf(m, sizeof m, "%s, opts 0x%x: count", scenes[i].name, opts);
            EQ_INT(nref, n, m);
            for (j = 0; j < n && j < nref; j++) {
                snprintf(m, sizeof m, "%s, opts 0x%x, hit %d", scenes[i].name, opts, j);
                CHK_AGAINST_REF(&ray, &cyl, opts, &hs[j], &rh[j], m);
                NORMAL_RULE(&ray, &cyl, opts, &hs[j], m);
            }
        }
    }
}

/* ================================================================== random scenes */
/* The scene's relative distance to the nearest decision boundary of the exact geometry:
 * tangency |e|, parallel sin, rim |v| = h/2 (relative to h/2 + r), cap edge rho = r (relative to
 * r), t = tmin (relative to r/|d|). Scenes nearer than TOL_MARGIN are skipped: there, rounding
 * may rightly decide either way, and the reference's classification is not the only right one. */
static long double ref_margin(const Ray *ray, const Cyl *cyl)
{
    RefGeom g;
    long double u[3], q[3], A, B, C, disc, m, x;
    int k;
    ref_geom(ray, cyl, &g);
    crossl3(g.ah, g.d, u);
    crossl3(g.ah, g.w, q);
    A = dotl3(u, u);
    B = dotl3(u, q);
    C = dotl3(q, q) - g.r * g.r;
    m = sqrtl(A) / g.dnorm; /* sin(theta) */
    if (A > 0) {
        disc = B * B - A * C;
        x = fabsl(disc / (A * g.r * g.r)); /* |e| */
        if (x < m) m = x;
        if (disc >= 0) {
            for (k = -1; k <= 1; k += 2) {
                long double t = (-B + (long double)k * sqrtl(disc)) / A;
                long double v = g.aw + t * g.ad;
                x = fabsl(t) / g.tscale;
                if (x < m) m = x;
                if (!isinf(g.H)) {
                    x = fabsl(fabsl(v) - g.H) / (g.H + g.r);
                    if (x < m) m = x;
                }
            }
        }
    }
    if (!isinf(g.H) && fabsl(g.ad) > 0) {
        for (k = -1; k <= 1; k += 2) {
            long double t = ((long double)k * g.H - g.aw) / g.ad, p[3], pa;
            int i;
            for (i = 0; i < 3; i++) p[i] = g.w[i] + t * g.d[i];
            pa = dotl3(g.ah, p);
            for (i = 0; i < 3; i++) p[i] -= g.ah[i] * pa;
            x = fabsl(sqrtl(dotl3(p, p)) - g.r) / g.r;
            if (x < m) m = x;
            x = fabsl(t) / g.tscale;
            if (x < m) m = x;
        }
    }
    return m;
}

/* Deterministic generator (64-bit LCG, Knuth's MMIX constants): dyadic values k/64, exact in
 * both precisions, so float and double runs see the same scenes. */
static unsigned long long rng_state;
static double rng_dyadic(int lo, int hi) /* k/64 for k in [lo*64, hi*64] */
{
    unsigned long long span = (unsigned long long)(hi - lo) * 64u + 1u;
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return (double)lo + (double)((rng_state >> 33) % span) / 64.0;
}

static void random_scene(Ray *ray, Cyl *cyl)
{
    double o[3], d[3], c[3], a[3], r, h;
    int i;
    do {
        for (i = 0; i < 3; i++) a[i] = rng_dyadic(-1, 1);
    } while (fabs(a[0]) + fabs(a[1]) + fabs(a[2]) < 0.25);
    for (i = 0; i < 3; i++) {
        c[i] = rng_dyadic(-1, 1);
        o[i] = rng_dyadic(-5, 5);
    }
    do { /* aimed at a point near the center (most scenes hit), its length random */
        double len = rng_dyadic(0, 2) + 0.25;
        for (i = 0; i < 3; i++) d[i] = (c[i] + rng_dyadic(-2, 2) - o[i]) * len;
    } while (fabs(d[0]) + fabs(d[1]) + fabs(d[2]) < 0.25);
    r = rng_dyadic(0, 2) + 0.125;
    h = rng_dyadic(0, 6) + 0.125;
    if (rng_dyadic(0, 1) > 0.875) h = (double)INFINITY;
    *ray = mk_ray((T)o[0], (T)o[1], (T)o[2], (T)d[0], (T)d[1], (T)d[2]);
    *cyl = mk_cyl((T)c[0], (T)c[1], (T)c[2], (T)a[0], (T)a[1], (T)a[2], (T)r, (T)h);
}

/* 3000 seeded random scenes under five option sets (three without CYL_PRECISE): classification,
 * count, t within t_err, useful t_err, v and normals against the reference; intersect and
 * occluded consistent. */
static void test_random_scenes_against_reference(void)
{
    static const unsigned ropts[] = {0u, CYL_CAPS, CYL_CAPS | CYL_OUTWARD, CYL_PRECISE,
                                     CYL_CAPS | CYL_PRECISE};
    size_t k;
    int i, checked = 0, skipped = 0, hits_seen = 0;
    char m[200];
    rng_state = 20261122u;
    for (i = 0; i < 3000; i++) {
        Ray ray;
        Cyl cyl;
        random_scene(&ray, &cyl);
        if (ref_margin(&ray, &cyl) < TOL_MARGIN) {
            skipped++;
            continue;
        }
        checked++;
        for (k = 0; k < sizeof ropts / sizeof ropts[0]; k++) {
            Hit hs[2], h;
            RefHit rh[2];
            unsigned opts = ropts[k];
            int n, nref, j;
            if (NO_PRECISE_SET(opts)) continue;
            nref = ref_solve(&ray, &cyl, (opts & CYL_CAPS) != 0, rh);
            sentinel(hs, 2);
            n = rt_intersect_all(&ray, &cyl, opts, hs);
            snprintf(m, sizeof m, "random scene %d, opts 0x%x", i, opts);
            EQ_INT(nref, n, m);
            hits_seen += n;
            for (j = 0; j < n; j++) {
                CHK_AGAINST_REF_LOOSE(&ray, &cyl, opts, &hs[j], &rh[j], m);
                NORMAL_RULE(&ray, &cyl, opts, &hs[j], m);
            }
            sentinel(&h, 1);
            EQ_INT(n ? CYL_HIT : CYL_MISS, rt_intersect(&ray, &cyl, opts, &h), m);
            if (n) SAME_HIT(&hs[0], &h, 1, m);
            EQ_INT(n > 0, rt_occluded(&ray, &cyl, opts), m);
        }
    }
    /* the test is not vacuous: most scenes are checked, and many of them hit */
    snprintf(m, sizeof m, "%d scenes checked, %d skipped, %d hits", checked, skipped, hits_seen);
    CHECK(checked >= 4 * skipped, m);
    CHECK(hits_seen >= checked, m);
    TEST_MESSAGE(m);
}

/* CYL_PRECISE: the same classification as the default path on easy cases, and t as accurate;
   compiled out (CYL_NO_PRECISE), the bit is refused by every entry point, *hit untouched. */
static void test_precise_same_classification(void)
{
    size_t i, k;
    char m[160];
    if (!HAVE_PRECISE) {
        for (i = 0; i < N_SCENES; i++) {
            Ray ray;
            Cyl cyl;
            Hit h[2], s[2];
            scene_get(&scenes[i], &ray, &cyl);
            sentinel(h, 2), sentinel(s, 2);
            snprintf(m, sizeof m, "%s: CYL_PRECISE compiled out", scenes[i].name);
            EQ_INT(CYL_E_OPTION, CYL(intersect)(&ray, &cyl, CYL_PRECISE, h), m);
            EQ_INT(CYL_E_OPTION, CYL(intersect_all)(&ray, &cyl, CYL_CAPS | CYL_PRECISE, h), m);
            EQ_INT(CYL_E_OPTION, CYL(occluded)(&ray, &cyl, CYL_PRECISE), m);
            CHECK(memcmp(h, s, sizeof h) == 0, m);
        }
        return;
    }
    for (i = 0; i < N_SCENES; i++) {
        for (k = 0; k < N_OPT_SETS; k++) {
            Ray ray;
            Cyl cyl;
            Hit base[2], prec[2], h;
            RefHit rh[2];
            unsigned opts = opt_sets[k];
            int n, j;
            scene_get(&scenes[i], &ray, &cyl);
            sentinel(base, 2);
            sentinel(prec, 2);
            n = rt_intersect_all(&ray, &cyl, opts, base);
            snprintf(m, sizeof m, "%s, opts 0x%x: CYL_PRECISE", scenes[i].name, opts);
            EQ_INT(n, rt_intersect_all(&ray, &cyl, opts | CYL_PRECISE, prec), m);
            EQ_INT(n, ref_solve(&ray, &cyl, (opts & CYL_CAPS) != 0, rh), m);
            for (j = 0; j < n; j++) {
                EQ_INT(base[j].part, prec[j].part, m);
                EQ_INT(base[j].flags, prec[j].flags, m);
                CHK_AGAINST_REF(&ray, &cyl, opts, &prec[j], &rh[j], m);
            }
            sentinel(&h, 1);
            EQ_INT(n > 0 ? CYL_HIT : CYL_MISS, rt_intersect(&ray, &cyl, opts | CYL_PRECISE, &h), m);
            EQ_INT(n > 0, rt_occluded(&ray, &cyl, opts | CYL_PRECISE), m);
        }
    }
    {   /* and on the exact case, exactly */
        Ray ray = mk_ray(-3, 0, 0, 1, 0, 0);
        Cyl cyl = z_cyl(2);
        Hit h;
        sentinel(&h, 1);
        EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, CYL_PRECISE, &h), "precise exact case");
        HIT_EXACT(&h, 2, CYL_SIDE, 0u, "precise exact case");
    }
}

/* ================================================================== t_err containment */
/* Closed forms, axis-aligned: ray along x at height y0 in the unit z-cylinder, c = 0:
 * t = -ox -+ sqrt(1 - y0^2), evaluated in long double from the stored inputs. */
static void test_t_err_contains_closed_form(void)
{
    static const double ys[] = {0.5, 0.1, 0.7, 0.99, 0.3333333333333333, 0.015625};
    static const double oxs[] = {-3, -1.1, -1000.5, 0.2};
    size_t i, k;
    unsigned p;
    char m[160];
    for (i = 0; i < sizeof ys / sizeof ys[0]; i++) {
        for (k = 0; k < sizeof oxs / sizeof oxs[0]; k++) {
            for (p = 0; p < 2; p++) {
                unsigned opts = p ? CYL_PRECISE : 0u;
                Ray ray = mk_ray((T)oxs[k], (T)ys[i], 0, 1, 0, 0);
                Cyl cyl = z_cyl(T_INF);
                Hit hs[2];
                long double y = (long double)ray.o[1], ox = (long double)ray.o[0];
                long double half = sqrtl(1.0L - y * y);
                long double tt[2];
                int n, j, want;
                if (NO_PRECISE_SET(opts)) continue;
                tt[0] = -ox - half;
                tt[1] = -ox + half;
                want = (tt[0] >= 0) + (tt[1] >= 0);
                sentinel(hs, 2);
                n = rt_intersect_all(&ray, &cyl, opts, hs);
                snprintf(m, sizeof m, "y0 = %g, ox = %g, opts 0x%x", ys[i], oxs[k], opts);
                EQ_INT(want, n, m);
                for (j = 0; j < n; j++) {
                    long double t = tt[2 - n + j];
                    long double sc = fabsl(t) > 1 ? fabsl(t) : 1;
                    NEAR(t, hs[j].t, (long double)hs[j].t_err + TOL_REF * sc, m);
                    CHECK((long double)hs[j].t_err <= TOL_ERR_USEFUL * sc, "t_err useful");
                    NEAR(t, hs[j].t, (TOL_T_ULP4 + TOL_REF) * sc, m);
                }
            }
        }
    }
}

/* Every test of this file, in order; the runner that includes it calls this. */
static void run_reference(void)
{
    UnitySetTestFile(__FILE__); /* failures point into this file */
    RUN_TEST(test_random_scenes_against_reference);
    RUN_TEST(test_scenes_against_reference);
    RUN_TEST(test_precise_same_classification);
    RUN_TEST(test_t_err_contains_closed_form);
}

#ifndef CONTRACT_ALL /* built alone, for one configuration: see tests/README.md */
int main(void)
{
    UNITY_BEGIN();
    run_reference();
    return UNITY_END();
}
#endif
