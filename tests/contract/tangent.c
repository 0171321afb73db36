/* Contract tests, tangent, rim and parallel: the decision boundaries. The rim (a point on it
 * belongs to the surface, one ulp past it does not), the tangent band (grazing contacts flagged,
 * CYL_NO_TANGENT drops them), the parallel band, and the documented default values of the two
 * tolerances.
 *
 * Written once for both precisions (see contract.h). make test runs it inside tests/test_float.c
 * and tests/test_double.c; alone: make test-one T=tangent CFG=gcc-O0 (tests/README.md).
 */
#include "contract.h"

/* ================================================================== rim */

/* Axis-aligned ray in the plane of the high cap: both wall crossings lie on the rim (v = h/2),
 * which belongs to the surface: exact, inclusive. One ulp above the plane: nothing. */
static void test_rim_exact(void)
{
    Ray ray = mk_ray(-3, 0, 1, 1, 0, 0);
    Cyl cyl = z_cyl(2);
    Hit hs[2];
    unsigned k;
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, 0, hs), "open: both rim points are on the surface");
    HIT_EXACT(&hs[0], 2, CYL_SIDE, 0u, "rim entry");
    HIT_EXACT(&hs[1], 4, CYL_SIDE, CYL_F_INSIDE, "rim exit");
    EXACT(1, hs[0].v, "v = h/2 exactly");

    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_CAPS, hs), "capped: rim entry and exit");
    EXACT(2, hs[0].t, "rim entry t");
    EXACT(4, hs[1].t, "rim exit t");
    /* the header documents "a hit exactly on the rim is reported as CYL_SIDE" */
    EQ_INT(CYL_SIDE, hs[0].part, "rim point reported as the side");
    EQ_INT(CYL_SIDE, hs[1].part, "rim point reported as the side");
    EQ_INT(0, hs[0].flags & CYL_F_INSIDE, "entry is not inside");
    EQ_INT(CYL_F_INSIDE, hs[1].flags & CYL_F_INSIDE, "exit is inside");

    /* Just outside the rim (one ulp above the cap plane) and just inside. */
    for (k = 0; k < 2; k++) {
        unsigned opts = k ? CYL_CAPS : 0u;
        Ray up = ray, down = ray;
        up.o[2] = T_NEXT(L(1), L(2));
        down.o[2] = T_NEXT(L(1), L(0));
        sentinel(hs, 2);
        EQ_INT(0, rt_intersect_all(&up, &cyl, opts, hs), "one ulp above the rim plane: miss");
        EQ_INT(0, rt_occluded(&up, &cyl, opts), "occluded: miss above the rim");
        sentinel(hs, 2);
        EQ_INT(2, rt_intersect_all(&down, &cyl, opts, hs), "one ulp below the rim: hit");
        HIT_EXACT(&hs[0], 2, CYL_SIDE, 0u, "below rim entry");
        HIT_EXACT(&hs[1], 4, CYL_SIDE, CYL_F_INSIDE, "below rim exit");
    }
}

/* Oblique rays through the rim circles and just past them. */
static void test_rim_oblique(void)
{
    Cyl cyl = z_cyl(2);
    Ray ray = mk_ray(-3, 0, -3, 1, 0, 1); /* through (-1,0,-1) at t=2 and (1,0,1) at t=4 */
    Hit hs[2];
    T past = L(1.0 / 1024);
    sentinel(hs, 2);
    /* Capped solid: watertight at the rim whatever the rounding (entry and exit exist). */
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_CAPS, hs), "capped rim-to-rim: two hits");
    NEAR(2, hs[0].t, TOL_T_ULP4 * 4, "entry at the low rim");
    NEAR(4, hs[1].t, TOL_T_ULP4 * 4, "exit at the high rim");
    CHECK(hs[0].part == CYL_SIDE || hs[0].part == CYL_CAP_LOW, "low rim: side or low cap");
    CHECK(hs[1].part == CYL_SIDE || hs[1].part == CYL_CAP_HIGH, "high rim: side or high cap");

    /* Starting 1/1024 lower: the first wall crossing is below the tube (v = -1 - 1/1024). */
    ray.o[2] = L(-3) - past;
    sentinel(hs, 2);
    EQ_INT(1, CYL(intersect_all)(&ray, &cyl, 0, hs), "open: low crossing is past the rim");
    HIT_NEAR(&hs[0], 4, CYL_SIDE, CYL_F_INSIDE, "open: only the high crossing, from inside");
    NEAR(1 - 1.0 / 1024, hs[0].v, TOL_V * 8, "v just below the high rim");
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_CAPS, hs), "capped: cap entry, wall exit");
    HIT_NEAR(&hs[0], 2 + 1.0 / 1024, CYL_CAP_LOW, 0u, "enters the low cap just inside the rim");
    HIT_NEAR(&hs[1], 4, CYL_SIDE, CYL_F_INSIDE, "leaves through the wall");
}

/* ================================================================== tangent boundary */
/* Ray along x at height rho = 1 - delta (or 1 + delta) above the axis of the unit cylinder:
 * e = 1 - rho^2 = 2 delta - delta^2 (resp. -2 delta - delta^2). delta = 2 tol gives |e| ~ 4 tol,
 * delta = tol/8 gives |e| ~ tol/4; each rho is exactly representable. */
static void tangent_case(T rho, int expect_hit, int expect_tangent)
{
    Ray ray = mk_ray(-3, rho, 0, 1, 0, 0);
    Cyl cyl = z_cyl(2);
    Hit h, hs[2];
    long double e = 1.0L - (long double)rho * (long double)rho;
    char m[120];
    snprintf(m, sizeof m, "rho = 1 %+.3Lg (e = %.3Lg, tol = %.3Lg)",
             (long double)rho - 1.0L, e, (long double)TOL_TANGENT);
    sentinel(&h, 1);
    if (!expect_hit) {
        Hit before = h;
        EQ_INT(CYL_MISS, CYL(intersect)(&ray, &cyl, 0, &h), m);
        CHECK(memcmp(&before, &h, sizeof h) == 0, "miss leaves *hit untouched");
        EQ_INT(0, CYL(intersect_all)(&ray, &cyl, 0, hs), m);
        EQ_INT(0, CYL(occluded)(&ray, &cyl, CYL_NO_TANGENT), m);
        return;
    }
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, 0, &h), m);
    EQ_INT(expect_tangent ? CYL_F_TANGENT : 0, h.flags & CYL_F_TANGENT, m);
    EQ_INT(CYL_SIDE, h.part, m);
    NORMAL_RULE(&ray, &cyl, 0u, &h, m);
    if (e >= 0) { /* a real contact exists: t_err must contain the exact first root */
        long double t1 = 3.0L - sqrtl(e);
        NEAR(t1, h.t, (long double)h.t_err + TOL_REF * 3, "tangent-zone t within t_err");
    }
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, 0, hs), m);
    CHECK(hs[0].t <= hs[1].t, "sorted");
    if (expect_tangent) {
        NEAR(3, hs[0].t, TOL_TANGENT_SPREAD(1.0L), "grazing hit at about t_c");
        NEAR(3, hs[1].t, TOL_TANGENT_SPREAD(1.0L), "grazing hit at about t_c");
        EQ_INT(CYL_F_TANGENT, hs[0].flags & CYL_F_TANGENT, "both grazing hits flagged");
        EQ_INT(CYL_F_TANGENT, hs[1].flags & CYL_F_TANGENT, "both grazing hits flagged");
        sentinel(&h, 1);
        EQ_INT(CYL_MISS, CYL(intersect)(&ray, &cyl, CYL_NO_TANGENT, &h), "CYL_NO_TANGENT: miss");
        EQ_INT(0, CYL(intersect_all)(&ray, &cyl, CYL_NO_TANGENT, hs), "CYL_NO_TANGENT: none");
        EQ_INT(0, CYL(occluded)(&ray, &cyl, CYL_NO_TANGENT), "CYL_NO_TANGENT: not occluded");
        EQ_INT(1, CYL(occluded)(&ray, &cyl, 0), "grazing contact occludes by default");
        /* the same on the capped solid (the contact is between the caps) */
        sentinel(hs, 2);
        EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_CAPS, hs), "capped grazing: two hits");
        EQ_INT(CYL_SIDE, hs[0].part, "capped grazing hit is on the side");
        EQ_INT(CYL_F_TANGENT, hs[0].flags & CYL_F_TANGENT, "capped grazing hit flagged");
        EQ_INT(0, CYL(occluded)(&ray, &cyl, CYL_CAPS | CYL_NO_TANGENT),
               "capped, CYL_NO_TANGENT: not occluded");
    } else {
        long double half = sqrtl(e);
        NEAR(3.0L - half, hs[0].t, TOL_T_ULP4 * 4 + (long double)hs[0].t_err, "entry");
        NEAR(3.0L + half, hs[1].t, TOL_T_ULP4 * 4 + (long double)hs[1].t_err, "exit");
        CHECK(hs[0].t < hs[1].t, "two distinct crossings outside the tangent band");
        EQ_INT(0, hs[0].flags & CYL_F_TANGENT, "no tangent flag at e = 4 tol");
        EQ_INT(CYL_F_INSIDE, hs[1].flags & CYL_F_INSIDE, "exit flagged inside");
        sentinel(&h, 1);
        EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, CYL_NO_TANGENT, &h),
               "CYL_NO_TANGENT keeps a clear hit");
    }
}

static void test_tangent_boundary(void)
{
    T tol = (T)TOL_TANGENT;
    tangent_case(L(1) - 2 * tol, 1, 0);   /* e = +4 tol (1 - tol): clear hit */
    tangent_case(L(1) - tol / 8, 1, 1);   /* e = +tol/4: grazing, flagged */
    tangent_case(L(1) + tol / 8, 1, 1);   /* e = -tol/4: grazing within the band, flagged */
    tangent_case(L(1) + 2 * tol, 0, 0);   /* e = -4 tol (1 + tol): clear miss */
}

/* ================================================================== parallel boundary */
/* d = (s, 0, 1): sin(theta) = s / sqrt(1 + s^2) = s to within s^3/2. s = tol/4 is inside the
 * parallel band, s = 4 tol outside. */
static void test_parallel_boundary(void)
{
    T tol = (T)TOL_PARALLEL;
    T s_in = tol / 4, s_out = tol * 4;
    Cyl cyl = z_cyl(2);
    Hit h;
    Ray ray;

    /* From the centre of a capped cylinder: exit through the high cap either way. */
    ray = mk_ray(0, 0, 0, s_in, 0, 1);
    sentinel(&h, 1);
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, CYL_CAPS, &h), "sin = tol/4, capped");
    HIT_NEAR(&h, 1, CYL_CAP_HIGH, CYL_F_INSIDE | CYL_F_PARALLEL, "parallel flag set at tol/4");
    ray = mk_ray(0, 0, 0, s_out, 0, 1);
    sentinel(&h, 1);
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, CYL_CAPS, &h), "sin = 4 tol, capped");
    HIT_NEAR(&h, 1, CYL_CAP_HIGH, CYL_F_INSIDE, "no parallel flag at 4 tol");

    /* From below: enters the low cap. */
    ray = mk_ray(0, 0, -5, s_in, 0, 1);
    sentinel(&h, 1);
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, CYL_CAPS | CYL_OUTWARD, &h), "from below, tol/4");
    HIT_NEAR(&h, 4, CYL_CAP_LOW, CYL_F_PARALLEL, "low cap entry, parallel");
    VEC_NEAR(h.n, 0, 0, -1, TOL_NORMAL, "low cap outward normal");
    ray = mk_ray(0, 0, -5, s_out, 0, 1);
    sentinel(&h, 1);
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, CYL_CAPS, &h), "from below, 4 tol");
    HIT_NEAR(&h, 4, CYL_CAP_LOW, 0u, "low cap entry, not parallel");

    /* Infinite tube from the axis: at 4 tol the wall is met at t = 1/s; inside the band never. */
    cyl.h = T_INF;
    ray = mk_ray(0, 0, 0, s_out, 0, 1);
    sentinel(&h, 1);
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, 0, &h), "infinite tube, 4 tol: far wall hit");
    NEAR(1.0L / (long double)s_out, h.t, (long double)h.t_err + TOL_REF / (long double)s_out,
         "t = 1/s within t_err");
    NEAR(1.0L / (long double)s_out, h.t, TOL_T_ULP4 / (long double)s_out, "t = 1/s");
    EQ_INT(CYL_SIDE, h.part, "side");
    EQ_INT(CYL_F_INSIDE, h.flags, "exit from inside, not parallel");
    ray = mk_ray(0, 0, 0, s_in, 0, 1);
    sentinel(&h, 1);
    EQ_INT(CYL_MISS, CYL(intersect)(&ray, &cyl, 0, &h), "infinite tube, tol/4: no wall hit");
    EQ_INT(CYL_MISS, CYL(intersect)(&ray, &cyl, CYL_CAPS, &h), "infinite tube, tol/4, caps");

    /* A parallel ray outside the tube's radius misses even the caps. */
    cyl.h = 2;
    ray = mk_ray(2, 0, -5, s_in, 0, 1);
    EQ_INT(0, CYL(occluded)(&ray, &cyl, CYL_CAPS), "parallel outside the radius");
}

#ifndef T_DOUBLE
/* The parallel rule's documented limit (N10). A float ray leaves the wall of an axis-aligned tube
 * with sin(d, a) = 1.5e-8, below CYL_PARALLEL_TOLF = 2^-24, and crosses the wall again 36 radii
 * along the ray, at t = 2.735e-8. The inputs determine that crossing (a x d is exact for this a),
 * yet the float API calls the ray parallel and drops it, with and without CYL_PRECISE. The double
 * API, whose tolerance is 2^-53, finds it within t_err. A change of the rule must change this test. */
static void test_parallel_rule_drops_secondary_ray_from_wall(void)
{
    const cylf_ray ray = {{-0.023321451619267464f, 0.029028177261352539f, -0.65008270740509033f},
                          {-0.744712233543396f, 0.029028160497546196f, -49508412.0f}, 0.0f, 1.0f};
    const cylf_cylinder cyl = {{0.0f, 0.0f, -1.3091078996658325f}, {0.0f, 0.0f, 1.0f},
                               0.037236087024211884f, 2.6170697212219238f};
    cylf_hit h;
    /* the exact crossing: (o + t d) on the circle of radius r about the z axis, the root near
     * the origin (the other is negative); squares of floats are exact in long double */
    const long double ox = (long double)ray.o[0], oy = (long double)ray.o[1];
    const long double dx = (long double)ray.d[0], dy = (long double)ray.d[1];
    const long double r = (long double)cyl.r;
    long double A = dx * dx + dy * dy, B = ox * dx + oy * dy, C = ox * ox + oy * oy - r * r;
    long double q = -(B + (B < 0 ? -1 : 1) * sqrtl(B * B - A * C)), t_ref = C / q;
    CHECK(t_ref > 0 && t_ref < 1 && q / A < 0, "one crossing in [0, 1], the other behind");
    sentinel(&h, 1);
    EQ_INT(CYL_MISS, cylf_intersect(&ray, &cyl, 0u, &h), "float API: dropped as parallel");
#ifndef CYL_NO_PRECISE
    EQ_INT(CYL_MISS, cylf_intersect(&ray, &cyl, CYL_PRECISE, &h), "CYL_PRECISE: dropped too");
#endif
#ifndef CYL_NO_DOUBLE
    {
        cyld_ray dray;
        cyld_cylinder dcyl;
        cyld_hit dh;
        int i;
        for (i = 0; i < 3; i++) {
            dray.o[i] = (double)ray.o[i];
            dray.d[i] = (double)ray.d[i];
            dcyl.c[i] = (double)cyl.c[i];
            dcyl.a[i] = (double)cyl.a[i];
        }
        dray.tmin = (double)ray.tmin;
        dray.tmax = (double)ray.tmax;
        dcyl.r = (double)cyl.r;
        dcyl.h = (double)cyl.h;
        EQ_INT(CYL_HIT, cyld_intersect(&dray, &dcyl, 0u, &dh), "double API: the crossing is hit");
        EQ_INT(CYL_SIDE, dh.part, "on the wall");
        NEAR(t_ref, dh.t, (long double)dh.t_err + TOL_REF * t_ref, "double: t within t_err");
    }
#endif
}
#endif

/* ================================================================== tolerance macros */
static void test_tolerance_macros(void)
{
    /* The documented defaults (exact powers of two; overriding them is tested in tests/config). */
    CHECK(same_T((T)CYL_TANGENT_TOLF, (T)(1.0 / 65536)), "CYL_TANGENT_TOLF = 2^-16");
    CHECK(same_T((T)CYL_TANGENT_TOL, (T)ldexp(1.0, -45)), "CYL_TANGENT_TOL = 2^-45");
    CHECK(same_T((T)CYL_PARALLEL_TOLF, (T)ldexp(1.0, -24)), "CYL_PARALLEL_TOLF = 2^-24");
    CHECK(same_T((T)CYL_PARALLEL_TOL, (T)ldexp(1.0, -53)), "CYL_PARALLEL_TOL = 2^-53");
}

/* Every test of this file, in order; the runner that includes it calls this. */
static void run_tangent(void)
{
    UnitySetTestFile(__FILE__); /* failures point into this file */
    RUN_TEST(test_rim_exact);
    RUN_TEST(test_rim_oblique);
    RUN_TEST(test_tangent_boundary);
    RUN_TEST(test_parallel_boundary);
#ifndef T_DOUBLE
    RUN_TEST(test_parallel_rule_drops_secondary_ray_from_wall);
#endif
    RUN_TEST(test_tolerance_macros);
}

#ifndef CONTRACT_ALL /* built alone, for one configuration: see tests/README.md */
int main(void)
{
    UNITY_BEGIN();
    run_tangent();
    return UNITY_END();
}
#endif
