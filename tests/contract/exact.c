/* Contract tests, exact cases. Small-integer and axis-aligned scenes whose every quantity is exact
 * in any sane formulation, so == is the property under test: wall and cap hits, non-unit d and a,
 * the caps' order along the axis, origins on the surface and inside, open tube versus capped
 * solid, infinite height, and the cylinder built from a segment (from_segment).
 *
 * Written once for both precisions (see contract.h). make test runs it inside tests/test_float.c
 * and tests/test_double.c; alone: make test-one T=exact CFG=gcc-O0 (tests/README.md).
 */
#include "contract.h"

/* ================================================================== exact cases */

/* Ray along x through the axis of the unit z-cylinder: crossings at x = -1 and x = +1, i.e.
 * t = 2 and 4. Every quantity is a small integer, so any correct formulation is exact. */
static void test_exact_axis_aligned_through_axis(void)
{
    Ray ray = mk_ray(-3, 0, 0, 1, 0, 0);
    Cyl cyl = z_cyl(2);
    Hit h, hs[2];
    sentinel(&h, 1);
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, 0, &h), "intersect returns CYL_HIT");
    HIT_EXACT(&h, 2, CYL_SIDE, 0u, "near wall");
    EXACT(0, h.v, "v at z = 0");
    VEC_EXACT(h.n, -1, 0, 0, "n");
    CHECK(h.t_err >= 0 && (long double)h.t_err <= TOL_ERR_USEFUL * 2, "t_err finite, >= 0, useful");

    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, 0, hs), "intersect_all: both wall crossings");
    HIT_EXACT(&hs[0], 2, CYL_SIDE, 0u, "entry");
    HIT_EXACT(&hs[1], 4, CYL_SIDE, CYL_F_INSIDE, "exit");
    VEC_EXACT(hs[1].n, -1, 0, 0, "exit n faces the ray origin");
    EXACT(0, hs[1].v, "exit v");

    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_OUTWARD, hs), "intersect_all outward");
    VEC_EXACT(hs[0].n, -1, 0, 0, "entry outward n");
    VEC_EXACT(hs[1].n, 1, 0, 0, "exit outward n");

    EQ_INT(1, CYL(occluded)(&ray, &cyl, 0), "occluded");
}

/* 5-12-13 triangle: r = 13, ray at distance 12 from the axis, |w_perp| = 20: the chord is
 * x in [-5, 5], t = 11 and 21, discriminant 25, all exact in every formulation. */
static void test_exact_pythagorean_offset(void)
{
    Ray ray = mk_ray(-16, 12, L(0.5), 1, 0, 0);
    Cyl cyl = mk_cyl(0, 0, 0, 0, 0, 1, 13, 2);
    Hit hs[2];
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, 0, hs), "two hits");
    HIT_EXACT(&hs[0], 11, CYL_SIDE, 0u, "entry at x = -5");
    HIT_EXACT(&hs[1], 21, CYL_SIDE, CYL_F_INSIDE, "exit at x = +5");
    EXACT(0.5, hs[0].v, "v");
    EXACT(0.5, hs[1].v, "v");
    VEC_NEAR(hs[0].n, -5.0L / 13, 12.0L / 13, 0, TOL_NORMAL, "entry n");
    VEC_NEAR(hs[1].n, -5.0L / 13, -12.0L / 13, 0, TOL_NORMAL, "exit n (facing)");

    /* The axis' length and sign only orient v and the caps: a = (0,0,-7) flips v. */
    cyl.a[2] = -7;
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_OUTWARD, hs), "two hits, axis (0,0,-7)");
    HIT_EXACT(&hs[0], 11, CYL_SIDE, 0u, "entry");
    HIT_EXACT(&hs[1], 21, CYL_SIDE, CYL_F_INSIDE, "exit");
    EXACT(-0.5, hs[0].v, "v is measured along the given axis direction");
    VEC_NEAR(hs[1].n, 5.0L / 13, 12.0L / 13, 0, TOL_NORMAL, "exit n (outward)");
}

/* t is in units of d: d = (2,0,0) halves t exactly; a = (0,0,8) changes nothing. */
static void test_exact_nonunit_d_and_a(void)
{
    Ray ray = mk_ray(-3, 0, 0, 2, 0, 0);
    Cyl cyl = mk_cyl(0, 0, 0, 0, 0, 8, 1, 2);
    Hit hs[2];
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, 0, hs), "two hits");
    HIT_EXACT(&hs[0], 1, CYL_SIDE, 0u, "t halves with |d| doubled");
    HIT_EXACT(&hs[1], 2, CYL_SIDE, CYL_F_INSIDE, "t halves with |d| doubled");
    VEC_EXACT(hs[0].n, -1, 0, 0, "n is unit whatever |d|");

    ray.d[0] = L(0.25);
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, 0, hs), "two hits, |d| = 1/4");
    HIT_EXACT(&hs[0], 8, CYL_SIDE, 0u, "t quadruples");
    HIT_EXACT(&hs[1], 16, CYL_SIDE, CYL_F_INSIDE, "t quadruples");
}

/* Axis pointing down: CAP_LOW is at c - a_hat h/2 = z = +1, CAP_HIGH at z = -1. A ray going up
 * along the axis enters through CAP_HIGH (v = +1) and leaves through CAP_LOW (v = -1). */
static void test_exact_caps_follow_axis_direction(void)
{
    Ray ray = mk_ray(0, 0, -5, 0, 0, 1);
    Cyl cyl = mk_cyl(0, 0, 0, 0, 0, -1, 1, 2);
    Hit hs[2];
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_CAPS, hs), "two cap hits");
    HIT_EXACT(&hs[0], 4, CYL_CAP_HIGH, CYL_F_PARALLEL, "entry through the cap at c + a_hat h/2");
    EXACT(1, hs[0].v, "entry v = +h/2");
    VEC_EXACT(hs[0].n, 0, 0, -1, "entry n");
    HIT_EXACT(&hs[1], 6, CYL_CAP_LOW, CYL_F_PARALLEL | CYL_F_INSIDE, "exit through c - a_hat h/2");
    EXACT(-1, hs[1].v, "exit v = -h/2");
    VEC_EXACT(hs[1].n, 0, 0, -1, "exit n faces the ray origin");

    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_CAPS | CYL_OUTWARD, hs), "outward");
    VEC_EXACT(hs[0].n, 0, 0, -1, "CAP_HIGH outward = +a_hat = (0,0,-1)");
    VEC_EXACT(hs[1].n, 0, 0, 1, "CAP_LOW outward = -a_hat = (0,0,1)");

    /* The same ray with the axis up: CAP_LOW first. */
    cyl.a[2] = 3;
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_CAPS | CYL_OUTWARD, hs), "axis up");
    HIT_EXACT(&hs[0], 4, CYL_CAP_LOW, CYL_F_PARALLEL, "entry through CAP_LOW");
    EXACT(-1, hs[0].v, "v = -h/2");
    VEC_EXACT(hs[0].n, 0, 0, -1, "CAP_LOW outward = -a_hat");
    HIT_EXACT(&hs[1], 6, CYL_CAP_HIGH, CYL_F_PARALLEL | CYL_F_INSIDE, "exit through CAP_HIGH");
    VEC_EXACT(hs[1].n, 0, 0, 1, "CAP_HIGH outward = +a_hat");

    /* Open tube: the axis-parallel ray never touches the wall. */
    sentinel(hs, 2);
    EQ_INT(0, CYL(intersect_all)(&ray, &cyl, 0, hs), "open tube: no hit for a parallel ray");
}

/* An oblique ray through both caps from off the axis (neither parallel nor near the axis line:
   the hot path's slab ends, not the exact path's): t = (∓h/2 − a·(o − c))/(a·d) is exact
   here, in both axis directions. */
static void test_exact_oblique_through_both_caps(void)
{
    Ray ray = mk_ray(0.25, 0, -5, 0.0625, 0, 1);
    Cyl cyl = z_cyl(2);
    Hit hs[2];
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_CAPS, hs), "two cap hits");
    HIT_EXACT(&hs[0], 4, CYL_CAP_LOW, 0u, "entry through the low cap at x = 0.5");
    EXACT(-1, hs[0].v, "entry v = -h/2");
    VEC_EXACT(hs[0].n, 0, 0, -1, "entry n");
    HIT_EXACT(&hs[1], 6, CYL_CAP_HIGH, CYL_F_INSIDE, "exit through the high cap at x = 0.625");
    EXACT(1, hs[1].v, "exit v = +h/2");
    VEC_EXACT(hs[1].n, 0, 0, -1, "exit n faces the ray origin");

    cyl.a[2] = -4; /* the axis down: the same planes, their parts swapped */
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_CAPS | CYL_OUTWARD, hs), "axis down");
    HIT_EXACT(&hs[0], 4, CYL_CAP_HIGH, 0u, "entry through CAP_HIGH");
    VEC_EXACT(hs[0].n, 0, 0, -1, "CAP_HIGH outward = +a_hat");
    HIT_EXACT(&hs[1], 6, CYL_CAP_LOW, CYL_F_INSIDE, "exit through CAP_LOW");
    VEC_EXACT(hs[1].n, 0, 0, 1, "CAP_LOW outward = -a_hat");
}

/* A ray starting on the wall: t = 0 is in [tmin, tmax] = [0, inf] and is reported (inclusive). */
static void test_exact_origin_on_surface(void)
{
    Ray ray = mk_ray(-1, 0, 0, 1, 0, 0);
    Cyl cyl = z_cyl(2);
    Hit hs[2];
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, 0, hs), "t = 0 and t = 2");
    HIT_EXACT(&hs[0], 0, CYL_SIDE, 0u, "t = 0 = tmin is included");
    HIT_EXACT(&hs[1], 2, CYL_SIDE, CYL_F_INSIDE, "far wall");
    ray.tmin = T_NEXT(L(0), L(1));
    sentinel(hs, 2);
    EQ_INT(1, CYL(intersect_all)(&ray, &cyl, 0, hs), "tmin just above 0 drops the t = 0 hit");
    HIT_EXACT(&hs[0], 2, CYL_SIDE, CYL_F_INSIDE, "far wall");
}

/* ================================================================== open versus capped */

/* Ray from below the low cap, inside the tube's radius, slanted so that it meets the wall from
 * inside at z = 0.5: the open tube gives only that exit; the capped solid gives cap entry and
 * the same wall exit. */
static void test_open_versus_capped(void)
{
    Ray ray = mk_ray(0, 0, L(-1.5), L(0.5), 0, 1);
    Cyl cyl = z_cyl(2);
    Hit hs[2], h;

    sentinel(hs, 2);
    EQ_INT(1, CYL(intersect_all)(&ray, &cyl, 0, hs), "open: one wall crossing in range");
    HIT_NEAR(&hs[0], 2, CYL_SIDE, CYL_F_INSIDE, "open: wall met from inside");
    NEAR(0.5, hs[0].v, TOL_V * 4, "v");
    VEC_NEAR(hs[0].n, -1, 0, 0, TOL_NORMAL, "facing n of an exit");

    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_CAPS, hs), "capped: entry and exit");
    HIT_NEAR(&hs[0], 0.5, CYL_CAP_LOW, 0u, "capped: enters through the low cap");
    NEAR(-1, hs[0].v, TOL_V * 4, "cap v = -h/2");
    VEC_NEAR(hs[0].n, 0, 0, -1, TOL_NORMAL, "cap n");
    HIT_NEAR(&hs[1], 2, CYL_SIDE, CYL_F_INSIDE, "capped: leaves through the wall");

    sentinel(&h, 1);
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, CYL_CAPS | CYL_OUTWARD, &h), "intersect capped");
    HIT_NEAR(&h, 0.5, CYL_CAP_LOW, 0u, "nearest is the cap");
    VEC_NEAR(h.n, 0, 0, -1, TOL_NORMAL, "CAP_LOW outward n = -a_hat");
    sentinel(&h, 1);
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, CYL_OUTWARD, &h), "intersect open");
    VEC_NEAR(h.n, 1, 0, 0, TOL_NORMAL, "outward n of the exit points away from the axis");
}

/* ================================================================== inside origins */
static void test_origin_inside(void)
{
    Ray ray = mk_ray(L(0.25), 0, 0, 1, 0, 0);
    Cyl cyl = z_cyl(2);
    Hit h, hs[2];
    unsigned k;
    for (k = 0; k < 2; k++) {
        unsigned opts = k ? CYL_CAPS : 0u;
        sentinel(hs, 2);
        EQ_INT(1, rt_intersect_all(&ray, &cyl, opts, hs), "inside: only the exit");
        HIT_EXACT(&hs[0], 0.75, CYL_SIDE, CYL_F_INSIDE, "exit from inside");
        VEC_EXACT(hs[0].n, -1, 0, 0, "facing n points back to the origin");
        sentinel(&h, 1);
        EQ_INT(CYL_HIT, rt_intersect(&ray, &cyl, opts | CYL_OUTWARD, &h), "intersect");
        HIT_EXACT(&h, 0.75, CYL_SIDE, CYL_F_INSIDE, "exit from inside");
        VEC_EXACT(h.n, 1, 0, 0, "outward n");
    }
    /* Along the axis from the centre: capped -> high cap exit; open or infinite -> nothing. */
    ray = mk_ray(0, 0, 0, 0, 0, 1);
    sentinel(&h, 1);
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, CYL_CAPS, &h), "capped, parallel from inside");
    HIT_EXACT(&h, 1, CYL_CAP_HIGH, CYL_F_INSIDE | CYL_F_PARALLEL, "exit through the high cap");
    EXACT(1, h.v, "v = h/2");
    VEC_EXACT(h.n, 0, 0, -1, "facing n");
    sentinel(&h, 1);
    EQ_INT(CYL_MISS, CYL(intersect)(&ray, &cyl, 0, &h), "open tube, parallel from inside");
    cyl.h = T_INF;
    EQ_INT(CYL_MISS, CYL(intersect)(&ray, &cyl, CYL_CAPS, &h),
           "infinite tube has no caps even with CYL_CAPS");
    EQ_INT(0, CYL(occluded)(&ray, &cyl, CYL_CAPS), "occluded agrees");
}

/* ================================================================== infinite height */
static void test_infinite_height(void)
{
    Ray ray = mk_ray(-3, 0, 1048576, 1, 0, 0); /* z = 2^20, exact in float */
    Cyl cyl = z_cyl(T_INF);
    Hit hs[2];
    unsigned k;
    for (k = 0; k < 2; k++) {
        unsigned opts = k ? CYL_CAPS : 0u;
        sentinel(hs, 2);
        EQ_INT(2, rt_intersect_all(&ray, &cyl, opts, hs), "infinite tube: two wall hits");
        HIT_EXACT(&hs[0], 2, CYL_SIDE, 0u, "entry");
        HIT_EXACT(&hs[1], 4, CYL_SIDE, CYL_F_INSIDE, "exit");
        EXACT(1048576, hs[0].v, "v far along the axis");
    }
    cyl.h = 2;
    EQ_INT(0, CYL(occluded)(&ray, &cyl, CYL_CAPS), "the same ray misses a finite cylinder");
}

/* ================================================================== extreme inputs */
/* o − c beyond the largest finite value, o and c finite and of opposite signs: the answer is
   still exact (t = (2X ∓ r)/4 with X = 1.5·2^(max_exp−1), r = 2^(max_exp−3), h = 4r). */
static void test_extreme_o_minus_c_overflows(void)
{
    const T X = T_LDEXP(L(1.5), T_MAX_EXP - 1), R = T_LDEXP(L(1), T_MAX_EXP - 3);
    Ray ray = mk_ray(X, 0, 0, -4, 0, 0);
    Cyl cyl = mk_cyl(-X, 0, 0, 0, 0, 1, R, 4 * R);
    Hit hs[2];
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_CAPS, hs), "two wall hits");
    HIT_EXACT(&hs[0], T_LDEXP(L(11), T_MAX_EXP - 5), CYL_SIDE, 0u, "entry at x = r - X");
    HIT_EXACT(&hs[1], T_LDEXP(L(13), T_MAX_EXP - 5), CYL_SIDE, CYL_F_INSIDE, "exit at x = -r - X");
    VEC_EXACT(hs[0].n, 1, 0, 0, "entry n");
    EXACT(0, hs[1].v, "exit v");
    CHECK(hs[0].t_err >= 0 && hs[0].t_err < hs[0].t, "t_err finite and useful");
}

/* The 5-12-13 scene seen from an origin X away, X so large that t's ulp exceeds the cylinder: entry and
 * exit (exact t = X - 5 and X + 5) round to the same t, and the point o + t·d lies on neither wall. The
 * normal is still each crossing's, from the ray's line and r, not from that rounded point; part, flags
 * and v are exact and t_err holds the exact t. X = 2^8/eps, and 2^36 (float) or 2^240 (double: past
 * the hot path's range, the exact path answers). */
static void test_far_origin_normal_is_the_crossings(void)
{
#ifdef T_DOUBLE
    const int far_exp = 240;
#else
    const int far_exp = 36;
#endif
    const T xs[2] = {L(256) / T_EPS, T_LDEXP(L(1), far_exp)};
    const Cyl cyl = mk_cyl(0, 0, 0, 0, 0, 1, 13, 2);
    Hit hs[2];
    char m[160];
    int i, k;
    for (i = 0; i < 2; i++)
        for (k = 0; k < 2; k++) {
            const Ray ray = mk_ray(-xs[i], 12, L(0.5), 1, 0, 0);
            const long double X = (long double)xs[i], out = k ? 1.0L : -1.0L; /* the exit's outward x */
            snprintf(m, sizeof m, "origin %.6Lg away, %s normals", X, k ? "outward" : "facing");
            sentinel(hs, 2);
            EQ_INT(2, CYL(intersect_all)(&ray, &cyl, k ? CYL_OUTWARD : 0u, hs), m);
            EQ_INT(CYL_SIDE, hs[0].part, m), EQ_INT(0, hs[0].flags, m);
            EQ_INT(CYL_SIDE, hs[1].part, m), EQ_INT(CYL_F_INSIDE, hs[1].flags, m);
            EXACT(0.5, hs[0].v, m), EXACT(0.5, hs[1].v, m);
            CHECK(fabsl((long double)hs[0].t - (X - 5)) <= (long double)hs[0].t_err, m);
            CHECK(fabsl((long double)hs[1].t - (X + 5)) <= (long double)hs[1].t_err, m);
#if CYL_VERSION_MAJOR >= 2 /* v1's normal is the rounded point's */
            VEC_NEAR(hs[0].n, -5.0L / 13, 12.0L / 13, 0, TOL_NORMAL, m);
            VEC_NEAR(hs[1].n, out * 5 / 13, out * 12 / 13, 0, TOL_NORMAL, m);
#else
            (void)out;
#endif
        }
}

#if CYL_VERSION_MAJOR >= 2
/* A ray along the axis of a capped cylinder of finite height h leaves through the high cap at
   h/2 (here |d| = |a|, so t = h/(2|a|)), with t_err holding, whatever the range of h|a|/2. */
static void chk_axis_exit(const Ray *ray, const Cyl *cyl, long double t, const char *what)
{
    Hit hs[2];
    char m[160];
    sentinel(hs, 2);
    snprintf(m, sizeof m, "%s: one hit, the high cap from inside", what);
    EQ_INT(1, CYL(intersect_all)(ray, cyl, CYL_CAPS, hs), m);
    EQ_INT(CYL_CAP_HIGH, hs[0].part, m);
    EQ_INT(CYL_F_INSIDE | CYL_F_PARALLEL, hs[0].flags, m);
    snprintf(m, sizeof m, "%s: t_err holds at t = %.6Lg, and is useful", what, t);
    CHECK(fabsl((long double)hs[0].t - t) <= (long double)hs[0].t_err && (long double)hs[0].t_err <= TOL_ERR_USEFUL * t, m);
}
#endif

/* h the largest finite value and |a| > 2: (h/2)|a| overflows. A ray across the axis meets the
   wall far inside the caps (N2: the hot path needs no test of it), so the capped solid's hits are
   the wall's, exact; rays along the axis (the exact path's) leave through the high cap. */
static void test_extreme_half_height_times_axis_overflows(void)
{
    Ray ray = mk_ray(-3, 0, L(0.5), 1, 0, 0);
    Cyl cyl = mk_cyl(0, 0, 0, 0, 0, 4, 1, T_MAX);
    Hit hs[2];
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_CAPS, hs), "two wall hits");
    HIT_EXACT(&hs[0], 2, CYL_SIDE, 0u, "entry at x = -1");
    HIT_EXACT(&hs[1], 4, CYL_SIDE, CYL_F_INSIDE, "exit at x = +1");
    EXACT(0.5, hs[0].v, "entry v");
    VEC_EXACT(hs[0].n, -1, 0, 0, "entry n");
#if CYL_VERSION_MAJOR >= 2 /* v1 misses some (the float API computed in float; h/r beyond its range) */
    ray = mk_ray(0, 0, L(0.5), 0, 0, 4);
    chk_axis_exit(&ray, &cyl, ((long double)T_MAX / 2 - 0.5L) / 4, "a = (0, 0, 4)");
    ray = mk_ray(0, 0, 0, L(1.9), L(1.9), L(1.9)), cyl = mk_cyl(0, 0, 0, L(1.9), L(1.9), L(1.9), 1, T_MAX);
    chk_axis_exit(&ray, &cyl, (long double)T_MAX / 2 / (sqrtl(3.0L) * (long double)L(1.9)), "a = (1.9, 1.9, 1.9)");
    ray = mk_ray(0, 0, 0, 0, 0, 1);
    cyl = mk_cyl(0, 0, 0, 0, 0, 1, T_LDEXP(L(1), -T_MAX_EXP / 2), T_LDEXP(L(1), 3 * T_MAX_EXP / 5));
    chk_axis_exit(&ray, &cyl, ldexpl(1.0L, 3 * T_MAX_EXP / 5 - 1), "r = 2^(-emax/2), h = 2^(3 emax/5)");
#endif
}

/* h/2 above 2^1220 r (the float API computed in float: 2^155): no power-of-two scale holds both, so
   the exact path clamps h/2, far beyond every wall point, and answers raised (t_err = +inf). A ray
   across the axis of such a thin tall tube still crosses its wall at its true radius, twice. */
static void test_extreme_height_beyond_radius_range(void)
{
    const T r = T_LDEXP(L(1), 2 - T_MAX_EXP), x = T_LDEXP(r, 10);
    Ray ray = mk_ray(-x, 0, 0, 1, 0, 0);
    Cyl cyl = mk_cyl(0, 0, 0, 0, 0, 1, r, T_LDEXP(L(1), 3 * T_MAX_EXP / 8));
    Hit hs[2];
    unsigned k;
    for (k = 0; k < 2; k++) {
        sentinel(hs, 2);
        EQ_INT(2, rt_intersect_all(&ray, &cyl, k ? CYL_CAPS : 0u, hs), "two wall hits");
        EQ_INT(CYL_SIDE, hs[0].part, "entry on the wall");
        EQ_INT(CYL_SIDE, hs[1].part, "exit on the wall");
        CHECK(fabsl((long double)hs[0].t - ((long double)x - (long double)r)) <= (long double)hs[0].t_err, "entry: t_err holds");
        CHECK(fabsl((long double)hs[1].t - ((long double)x + (long double)r)) <= (long double)hs[1].t_err, "exit: t_err holds");
    }
#if CYL_VERSION_MAJOR >= 2 /* v1 misses it */
    ray = mk_ray(0, 0, 0, 0, 0, 1); /* and one along the axis leaves through the high cap */
    sentinel(hs, 2);
    EQ_INT(1, CYL(intersect_all)(&ray, &cyl, CYL_CAPS, hs), "along the axis: one hit");
    EQ_INT(CYL_CAP_HIGH, hs[0].part, "the high cap");
    CHECK(fabsl((long double)hs[0].t - (long double)cyl.h / 2) <= (long double)hs[0].t_err, "cap: t_err holds");
#endif
}

/* t = δ and δ + 2r from an origin δ outside the wall of an infinite tube, 3·2^(max_exp−1) along
   its axis from c (o − c overflows again): t and v come back from the exact path's scaling by
   more than 2^max_exp; v saturates at the largest finite value. t is exact where the exact path
   takes its Newton steps (v2: not under CYL_NO_PRECISE, where float computed in float errs by
   2^-21 |t|, from (r + δ)² − r²'s rounding), and within t_err in any build. */
static void test_extreme_unscaled_beyond_max_exp(void)
{
    const T X = T_LDEXP(L(1.5), T_MAX_EXP - 1), R = T_LDEXP(L(1), T_MAX_EXP - 4);
    const T dl = T_LDEXP(L(1), T_MAX_EXP - 24);
    Ray ray = mk_ray(-(R + dl), 0, X, 1, 0, 0);
    Cyl cyl = mk_cyl(0, 0, -X, 0, 0, 1, R, T_INF);
    Hit hs[2];
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, 0, hs), "two wall hits");
    chk_hit_at(&hs[0], dl, CYL_SIDE, 0u, HAVE_PRECISE, "entry", __LINE__);
    chk_hit_at(&hs[1], dl + 2 * R, CYL_SIDE, CYL_F_INSIDE, HAVE_PRECISE, "exit", __LINE__);
    CHECK(fabsl((long double)hs[0].t - (long double)dl) <= (long double)hs[0].t_err, "entry: t_err holds");
    CHECK(fabsl((long double)hs[1].t - (long double)(dl + 2 * R)) <= (long double)hs[1].t_err, "exit: t_err holds");
    EXACT(T_MAX, hs[0].v, "v saturated");
}

/* A cylinder thinner than the range resolves (r = 2^-(2·T_BIG_EXP) |o − c|; the exact path
   answers those with r raised to its range and t_err = +inf): a ray through its axis hits it. */
static void test_extreme_thin_cylinder(void)
{
    Ray ray = mk_ray(-1, 0, 0, 1, 0, 0);
    Cyl cyl = mk_cyl(0, 0, 0, 0, 0, 1, T_LDEXP(L(1), -2 * T_BIG_EXP), 2);
    Hit hs[2];
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, 0, hs), "two wall hits");
    HIT_NEAR(&hs[0], 1, CYL_SIDE, 0u, "entry at 1 - r");
    HIT_NEAR(&hs[1], 1, CYL_SIDE, CYL_F_INSIDE, "exit at 1 + r");
    CHECK(hs[0].t_err >= T_FABS(hs[0].t - 1) - T_EPS, "t_err holds (+inf where r was raised)");
}

/* h the smallest subnormal times 3, so h/2 is no value of T: a wall hit on the rim (v = h/2
   exactly) reports v rounded into [−h/2, h/2], not past it. */
static void test_extreme_subnormal_height(void)
{
    const T tiny = T_LDEXP(L(1), T_TINY_EXP);
    Ray ray = mk_ray(-2, 0, 0, 2, 0, 3 * tiny);
    Cyl cyl = z_cyl(3 * tiny);
    Hit h;
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, 0, &h), "the wall at the rim");
    HIT_EXACT(&h, L(0.5), CYL_SIDE, 0u, "rim point");
    CHECK(fabsl((long double)h.v) <= 1.5L * (long double)tiny, "|v| <= h/2");
}

/* ================================================================== from_segment */
static void test_from_segment(void)
{
    {
        const T p0[3] = {1, 2, 3}, p1[3] = {1, 2, 7};
        Cyl cyl = CYL(from_segment)(p0, p1, L(0.5));
        Ray ray = mk_ray(-2, 2, 4, 1, 0, 0);
        Hit h;
        long double cr[3], a[3], seg[3];
        int i;
        VEC_EXACT(cyl.c, 1, 2, 5, "center = midpoint");
        EXACT(4, cyl.h, "h = |p1 - p0|");
        EXACT(0.5, cyl.r, "r");
        for (i = 0; i < 3; i++) {
            a[i] = (long double)cyl.a[i];
            seg[i] = (long double)(p1[i] - p0[i]);
        }
        crossl3(a, seg, cr);
        CHECK(!(dotl3(cr, cr) > 0) && dotl3(a, seg) > 0, "axis along p1 - p0");
        sentinel(&h, 1);
        EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, 0, &h), "ray between the end points");
        HIT_EXACT(&h, 2.5, CYL_SIDE, 0u, "wall at x = 0.5");
        EXACT(-1, h.v, "v = z - 5");
        /* The cap at p0 is CAP_LOW. */
        ray = mk_ray(1, 2, 0, 0, 0, 1);
        sentinel(&h, 1);
        EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, CYL_CAPS, &h), "ray along the segment");
        HIT_EXACT(&h, 3, CYL_CAP_LOW, CYL_F_PARALLEL, "enters at p0 through CAP_LOW");
    }
    {   /* a slanted segment of length 5 (3-4-5) */
        const T p0[3] = {0, 0, 0}, p1[3] = {3, 4, 0};
        Cyl cyl = CYL(from_segment)(p0, p1, 1);
        Ray ray = mk_ray(L(1.5) + 4 * 2, 2 - 3 * 2, L(0.25), -4, 3, 0); /* aims at the midpoint */
        Hit hs[2];
        long double a[3], an;
        int i;
        VEC_EXACT(cyl.c, 1.5, 2, 0, "center = midpoint");
        NEAR(5, cyl.h, TOL_T_ULP4 * 5, "h = |p1 - p0| = 5");
        for (i = 0; i < 3; i++) a[i] = (long double)cyl.a[i];
        an = sqrtl(dotl3(a, a));
        NEAR(0.6, a[0] / an, TOL_NORMAL, "axis direction x");
        NEAR(0.8, a[1] / an, TOL_NORMAL, "axis direction y");
        NEAR(0, a[2] / an, TOL_NORMAL, "axis direction z");
        sentinel(hs, 2);
        /* |d| = 5, the origin is 10 from the axis: crossings at t = (10 -+ sqrt(1 - 1/16))/5 */
        EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_CAPS, hs), "crosses the tube");
        NEAR((10.0L - sqrtl(1.0L - 1.0L / 16)) / 5, hs[0].t, TOL_T_ULP4 * 4, "entry");
        NEAR((10.0L + sqrtl(1.0L - 1.0L / 16)) / 5, hs[1].t, TOL_T_ULP4 * 4, "exit");
        EQ_INT(CYL_SIDE, hs[0].part, "side");
        NEAR(0, hs[0].v, TOL_V * 16, "v = 0 at the midpoint");
        /* along the segment from before p0: CAP_LOW at p0 (t = 1), CAP_HIGH at p1 (t = 2) */
        ray = mk_ray(-3, -4, 0, 3, 4, 0);
        sentinel(hs, 2);
        EQ_INT(2, CYL(intersect_all)(&ray, &cyl, CYL_CAPS, hs), "along the segment");
        HIT_NEAR(&hs[0], 1, CYL_CAP_LOW, CYL_F_PARALLEL, "CAP_LOW at p0");
        HIT_NEAR(&hs[1], 2, CYL_CAP_HIGH, CYL_F_PARALLEL | CYL_F_INSIDE, "CAP_HIGH at p1");
        NEAR(-2.5, hs[0].v, TOL_V * 8, "v = -h/2 at p0");
    }
}

/* Every test of this file, in order; the runner that includes it calls this. */
static void run_exact(void)
{
    UnitySetTestFile(__FILE__); /* failures point into this file */
    RUN_TEST(test_exact_axis_aligned_through_axis);
    RUN_TEST(test_exact_pythagorean_offset);
    RUN_TEST(test_exact_nonunit_d_and_a);
    RUN_TEST(test_exact_caps_follow_axis_direction);
    RUN_TEST(test_exact_oblique_through_both_caps);
    RUN_TEST(test_exact_origin_on_surface);
    RUN_TEST(test_open_versus_capped);
    RUN_TEST(test_origin_inside);
    RUN_TEST(test_infinite_height);
    RUN_TEST(test_extreme_o_minus_c_overflows);
    RUN_TEST(test_far_origin_normal_is_the_crossings);
    RUN_TEST(test_extreme_half_height_times_axis_overflows);
    RUN_TEST(test_extreme_height_beyond_radius_range);
    RUN_TEST(test_extreme_thin_cylinder);
    RUN_TEST(test_extreme_unscaled_beyond_max_exp);
    RUN_TEST(test_extreme_subnormal_height);
    RUN_TEST(test_from_segment);
}

#ifndef CONTRACT_ALL /* built alone, for one configuration: see tests/README.md */
int main(void)
{
    UNITY_BEGIN();
    run_exact();
    return UNITY_END();
}
#endif
