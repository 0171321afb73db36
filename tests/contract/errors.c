/* Contract tests, errors. Every error code of every entry point, the documented order when several
 * errors meet, what CYL_TRUSTED keeps checking, and that no call writes its inputs, nor its output
 * on a miss or an error.
 *
 * Written once for both precisions (see contract.h). make test runs it inside tests/test_float.c
 * and tests/test_double.c; alone: make test-one T=errors CFG=gcc-O0 (tests/README.md).
 */
#include "contract.h"

/* ================================================================== errors */
static void expect_error_at(const Ray *ray, const Cyl *cyl, unsigned opts, int code,
                            const char *what, int line)
{
    Hit h, h0, hs[2], hs0[2];
    Ray ray_copy;
    Cyl cyl_copy;
    char m[200];
    if (ray) ray_copy = *ray; else memset(&ray_copy, 0, sizeof ray_copy);
    if (cyl) cyl_copy = *cyl; else memset(&cyl_copy, 0, sizeof cyl_copy);
    sentinel(&h, 1); sentinel(&h0, 1); sentinel(hs, 2); sentinel(hs0, 2);
    snprintf(m, sizeof m, "%s: intersect", what);
    chk_int_at(code, rt_intersect(ray, cyl, opts, &h), m, line);
    snprintf(m, sizeof m, "%s: intersect left *hit untouched", what);
    UNITY_TEST_ASSERT(memcmp(&h, &h0, sizeof h) == 0, line, m);
    snprintf(m, sizeof m, "%s: intersect_all", what);
    chk_int_at(code, rt_intersect_all(ray, cyl, opts, hs), m, line);
    snprintf(m, sizeof m, "%s: intersect_all left hits[] untouched", what);
    UNITY_TEST_ASSERT(memcmp(hs, hs0, sizeof hs) == 0, line, m);
    snprintf(m, sizeof m, "%s: occluded", what);
    chk_int_at(code, rt_occluded(ray, cyl, opts), m, line);
    snprintf(m, sizeof m, "%s: inputs unchanged", what);
    UNITY_TEST_ASSERT(!ray || memcmp(ray, &ray_copy, sizeof ray_copy) == 0, line, m);
    UNITY_TEST_ASSERT(!cyl || memcmp(cyl, &cyl_copy, sizeof cyl_copy) == 0, line, m);
}
#define EXPECT_ERROR(ray, cyl, opts, code, what) \
    expect_error_at((ray), (cyl), (opts), (code), (what), __LINE__)

static void test_error_null(void)
{
    Ray ray = mk_ray(-3, 0, 0, 1, 0, 0);
    Cyl cyl = z_cyl(2);
    EXPECT_ERROR(NULL, &cyl, 0, CYL_E_NULL, "NULL ray");
    EXPECT_ERROR(&ray, NULL, 0, CYL_E_NULL, "NULL cylinder");
    EQ_INT(CYL_E_NULL, CYL(intersect)(&ray, &cyl, 0, NULL), "NULL hit");
    EQ_INT(CYL_E_NULL, CYL(intersect_all)(&ray, &cyl, 0, NULL), "NULL hits");
    /* NULL comes first: a NULL cylinder with a NaN ray and a bad option is still E_NULL. */
    ray.o[0] = T_NAN;
    EXPECT_ERROR(&ray, NULL, 0x80u, CYL_E_NULL, "NULL before NONFINITE and OPTION");
    EQ_INT(CYL_E_NULL, CYL(intersect)(&ray, &cyl, 0x80u, NULL), "NULL hit before NONFINITE");
}

static void test_error_nonfinite(void)
{
    const T bad[3] = {T_NAN, T_INF, -T_INF};
    int i, k;
    for (k = 0; k < 3; k++) {
        for (i = 0; i < 3; i++) {
            Ray ray = mk_ray(-3, 0, 0, 1, 0, 0);
            Cyl cyl = z_cyl(2);
            ray.o[i] = bad[k];
            EXPECT_ERROR(&ray, &cyl, 0, CYL_E_NONFINITE, "non-finite o");
            ray = mk_ray(-3, 0, 0, 1, 0, 0);
            ray.d[i] = bad[k];
            EXPECT_ERROR(&ray, &cyl, 0, CYL_E_NONFINITE, "non-finite d");
            ray = mk_ray(-3, 0, 0, 1, 0, 0);
            cyl.c[i] = bad[k];
            EXPECT_ERROR(&ray, &cyl, 0, CYL_E_NONFINITE, "non-finite c");
            cyl = z_cyl(2);
            cyl.a[i] = bad[k];
            EXPECT_ERROR(&ray, &cyl, 0, CYL_E_NONFINITE, "non-finite a");
        }
    }
    {   /* a NaN direction is NONFINITE, not ZERO_DIR */
        Ray ray = mk_ray(-3, 0, 0, 0, 0, 0);
        Cyl cyl = z_cyl(2);
        ray.d[1] = T_NAN;
        EXPECT_ERROR(&ray, &cyl, 0, CYL_E_NONFINITE, "d = (0, NaN, 0)");
    }
}

static void test_error_zero_dir_axis(void)
{
    Ray ray = mk_ray(-3, 0, 0, 0, 0, 0);
    Cyl cyl = z_cyl(2);
    EXPECT_ERROR(&ray, &cyl, 0, CYL_E_ZERO_DIR, "d = 0");
    ray.d[0] = -L(0.0);
    ray.d[2] = -L(0.0);
    EXPECT_ERROR(&ray, &cyl, 0, CYL_E_ZERO_DIR, "d = (-0, 0, -0)");
    cyl.a[2] = 0;
    EXPECT_ERROR(&ray, &cyl, 0, CYL_E_ZERO_DIR, "ZERO_DIR before ZERO_AXIS");
    ray.d[0] = 1;
    EXPECT_ERROR(&ray, &cyl, 0, CYL_E_ZERO_AXIS, "a = 0");
    cyl.a[1] = -L(0.0);
    EXPECT_ERROR(&ray, &cyl, 0, CYL_E_ZERO_AXIS, "a = (0, -0, 0)");
}

static void test_error_radius_height(void)
{
    const T bad_r[] = {0, -L(0.0), -1, T_NAN, T_INF, -T_INF};
    const T bad_h[] = {0, -L(0.0), -1, T_NAN, -T_INF};
    size_t i;
    Ray ray = mk_ray(-3, 0, 0, 1, 0, 0);
    Cyl cyl;
    for (i = 0; i < sizeof bad_r / sizeof bad_r[0]; i++) {
        cyl = z_cyl(2);
        cyl.r = bad_r[i];
        EXPECT_ERROR(&ray, &cyl, 0, CYL_E_RADIUS, "bad radius");
    }
    for (i = 0; i < sizeof bad_h / sizeof bad_h[0]; i++) {
        cyl = z_cyl(bad_h[i]);
        EXPECT_ERROR(&ray, &cyl, 0, CYL_E_HEIGHT, "bad height");
        EXPECT_ERROR(&ray, &cyl, CYL_CAPS, CYL_E_HEIGHT, "bad height, capped");
    }
    /* Tiny but positive values are valid: the ray crosses the 2^-100 thin cylinder at t = 3. */
    cyl = z_cyl(T_LDEXP(1, -100));
    cyl.r = T_LDEXP(1, -100);
    {
        Hit h;
        sentinel(&h, 1);
        EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, 0, &h), "tiny r and h are valid");
        NEAR(3, h.t, TOL_T_ULP4 * 3, "t at the tiny cylinder");
    }
}

static void test_error_trange_option(void)
{
    Ray ray = mk_ray(-3, 0, 0, 1, 0, 0);
    Cyl cyl = z_cyl(2);
    unsigned bit;
    ray.tmin = 3;
    ray.tmax = 2;
    EXPECT_ERROR(&ray, &cyl, 0, CYL_E_TRANGE, "tmin > tmax");
    ray.tmin = T_NAN;
    ray.tmax = 2;
    EXPECT_ERROR(&ray, &cyl, 0, CYL_E_TRANGE, "tmin NaN");
    ray.tmin = 0;
    ray.tmax = T_NAN;
    EXPECT_ERROR(&ray, &cyl, 0, CYL_E_TRANGE, "tmax NaN");
    ray.tmin = T_INF;
    ray.tmax = -T_INF;
    EXPECT_ERROR(&ray, &cyl, 0, CYL_E_TRANGE, "tmin = +inf > tmax = -inf");
    ray.tmin = -T_INF;
    ray.tmax = T_INF;
    EQ_INT(1, CYL(occluded)(&ray, &cyl, 0), "[-inf, inf] is a valid range");
    ray.tmin = T_INF;
    EQ_INT(0, CYL(occluded)(&ray, &cyl, 0), "[inf, inf] is a valid, empty-of-hits range");
    ray.tmin = 0;
    for (bit = 0x80u; bit != 0u; bit <<= 1)
        EXPECT_ERROR(&ray, &cyl, bit, CYL_E_OPTION, "unknown option bit");
    EXPECT_ERROR(&ray, &cyl, CYL_CAPS | 0x200u, CYL_E_OPTION, "known bits plus an unknown one");
    /* the header documents that CYL_TRUSTED keeps the NULL and option checks */
    EXPECT_ERROR(&ray, &cyl, CYL_TRUSTED | 0x80u, CYL_E_OPTION, "CYL_TRUSTED keeps the option check");
    EXPECT_ERROR(NULL, &cyl, CYL_TRUSTED, CYL_E_NULL, "CYL_TRUSTED keeps the NULL check");
    EXPECT_ERROR(&ray, NULL, CYL_TRUSTED, CYL_E_NULL, "CYL_TRUSTED keeps the NULL check");
    {
        Hit h;
        sentinel(&h, 1);
        /* every known bit at once; without the precise tier, all but CYL_PRECISE (which is then
           an unknown bit: CYL_E_OPTION) */
        if (HAVE_PRECISE) {
            EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, CYL_OPTIONS_ALL, &h), "CYL_OPTIONS_ALL valid");
        } else {
            EXPECT_ERROR(&ray, &cyl, CYL_OPTIONS_ALL, CYL_E_OPTION, "CYL_PRECISE compiled out");
            EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, CYL_OPTIONS_ALL & ~CYL_PRECISE, &h),
                   "CYL_OPTIONS_ALL but CYL_PRECISE valid");
        }
        EQ_INT(0, CYL_OPTIONS_ALL & 0x80u, "CYL_OPTIONS_ALL has no unknown bit");
    }
}

/* Several errors at once: the first in the documented order wins (NULL, NONFINITE, ZERO_DIR,
 * ZERO_AXIS, RADIUS, HEIGHT, TRANGE, OPTION). Each line pairs an error with every later one. */
static void test_error_check_order(void)
{
    Ray ray;
    Cyl cyl;
    /* later = every error after ZERO_DIR at once */
    ray = mk_ray(-3, 0, 0, 0, 0, 0);
    cyl = mk_cyl(0, 0, 0, 0, 0, 0, -1, 0);
    ray.tmin = 5;
    ray.tmax = 1;
    EXPECT_ERROR(&ray, &cyl, 0, CYL_E_ZERO_DIR, "ZERO_DIR before ZERO_AXIS..TRANGE");
    ray.d[0] = 1;
    EXPECT_ERROR(&ray, &cyl, 0, CYL_E_ZERO_AXIS, "ZERO_AXIS before RADIUS..TRANGE");
    cyl.a[2] = 1;
    EXPECT_ERROR(&ray, &cyl, 0, CYL_E_RADIUS, "RADIUS before HEIGHT, TRANGE");
    cyl.r = 1;
    EXPECT_ERROR(&ray, &cyl, 0, CYL_E_HEIGHT, "HEIGHT before TRANGE");
    ray = mk_ray(T_NAN, 0, 0, 0, 0, 0);
    cyl = mk_cyl(0, 0, 0, 0, 0, 0, -1, 0);
    ray.tmin = 5;
    ray.tmax = 1;
    EXPECT_ERROR(&ray, &cyl, 0, CYL_E_NONFINITE, "NONFINITE before ZERO_DIR..TRANGE");
    /* OPTION is checked last of all */
    EXPECT_ERROR(&ray, &cyl, 0x100u, CYL_E_NONFINITE, "NONFINITE before OPTION");
    ray = mk_ray(-3, 0, 0, 0, 0, 0);
    ray.tmin = 5;
    ray.tmax = 1;
    EXPECT_ERROR(&ray, &cyl, 0x80u, CYL_E_ZERO_DIR, "ZERO_DIR before OPTION");
    ray.d[0] = 1;
    EXPECT_ERROR(&ray, &cyl, 0x80u, CYL_E_ZERO_AXIS, "ZERO_AXIS before OPTION");
    cyl.a[2] = 1;
    EXPECT_ERROR(&ray, &cyl, 0x80u, CYL_E_RADIUS, "RADIUS before OPTION");
    cyl.r = 1;
    EXPECT_ERROR(&ray, &cyl, 0x80u, CYL_E_HEIGHT, "HEIGHT before OPTION");
    cyl.h = 2;
    EXPECT_ERROR(&ray, &cyl, 0x80u, CYL_E_TRANGE, "TRANGE before OPTION");
}

/* ================================================================== inputs untouched, misses */
static void test_inputs_unmodified_and_miss_untouched(void)
{
    size_t i, k;
    for (i = 0; i < N_SCENES; i++) {
        for (k = 0; k < N_OPT_SETS; k++) {
            Ray ray, ray0;
            Cyl cyl, cyl0;
            Hit h, h0, hs[2], hs0[2];
            int rc, n;
            scene_get(&scenes[i], &ray, &cyl);
            ray0 = ray;
            cyl0 = cyl;
            sentinel(&h, 1); sentinel(&h0, 1); sentinel(hs, 2); sentinel(hs0, 2);
            rc = rt_intersect(&ray, &cyl, opt_sets[k], &h);
            n = rt_intersect_all(&ray, &cyl, opt_sets[k], hs);
            (void)rt_occluded(&ray, &cyl, opt_sets[k]);
            CHECK(memcmp(&ray, &ray0, sizeof ray) == 0, scenes[i].name);
            CHECK(memcmp(&cyl, &cyl0, sizeof cyl) == 0, scenes[i].name);
            if (rc == CYL_MISS) CHECK(memcmp(&h, &h0, sizeof h) == 0, "miss: *hit untouched");
            if (n == 0) CHECK(memcmp(hs, hs0, sizeof hs) == 0, "no hit: hits[] untouched");
            /* the header documents hits[i] for i >= count as untouched too */
            if (n == 1)
                CHECK(memcmp(&hs[1], &hs0[1], sizeof hs[1]) == 0, "one hit: hits[1] untouched");
        }
    }
}

/* CYL_TRUSTED with inputs that break its promise (one of the 16 inputs NaN, infinite, zero or
 * negative): validation is skipped, so no CYL_E_* code comes back, yet every call returns, writes
 * nothing it does not own, leaves *hit alone on a miss and hits[i >= count] always; under the
 * sanitizer builds of make test, without undefined behaviour. The answer itself is unspecified. */
static void test_trusted_broken_promise(void)
{
    const T bad[5] = {T_NAN, T_INF, -T_INF, 0, -1};
    const unsigned opts[2] = {CYL_TRUSTED, CYL_TRUSTED | CYL_CAPS | CYL_NO_TANGENT};
    int slot, b, k, j;
    for (slot = 0; slot < 16; slot++)
        for (b = 0; b < 5; b++)
            for (k = 0; k < 2; k++) {
                Ray ray = mk_ray(-3, L(0.25), L(0.125), 1, 0, 0), ray0;
                Cyl cyl = z_cyl(2), cyl0;
                Hit h, h0, hs[2], hs0[2];
                T *in[16] = {&ray.o[0], &ray.o[1], &ray.o[2], &ray.d[0], &ray.d[1], &ray.d[2], &ray.tmin,
                             &ray.tmax, &cyl.c[0], &cyl.c[1], &cyl.c[2], &cyl.a[0], &cyl.a[1], &cyl.a[2], &cyl.r, &cyl.h};
                int rc, n, oc;
                char m[4][120];
                static const char *const what[4] = {"no validation code", "inputs unchanged",
                                                    "*hit untouched on a miss", "hits[count..] untouched"};
                *in[slot] = bad[b];
                ray0 = ray, cyl0 = cyl;
                sentinel(&h, 1); sentinel(&h0, 1); sentinel(hs, 2); sentinel(hs0, 2);
                rc = rt_intersect(&ray, &cyl, opts[k], &h);
                n = rt_intersect_all(&ray, &cyl, opts[k], hs);
                oc = rt_occluded(&ray, &cyl, opts[k]);
                for (j = 0; j < 4; j++)
                    snprintf(m[j], sizeof m[j], "input %d = %Lg, opts 0x%x: %s", slot, (long double)bad[b], opts[k], what[j]);
                CHECK((rc == 0 || rc == 1) && n >= 0 && n <= 2 && (oc == 0 || oc == 1), m[0]);
                CHECK(memcmp(&ray, &ray0, sizeof ray) == 0 && memcmp(&cyl, &cyl0, sizeof cyl) == 0, m[1]);
                CHECK(rc != 0 || memcmp(&h, &h0, sizeof h) == 0, m[2]);
                CHECK(n == 2 || memcmp(&hs[n], &hs0[n], (size_t)(2 - n) * sizeof hs[0]) == 0, m[3]);
            }
}

/* A degenerate segment (p0 == p1) gives a = 0 and h = 0; the documented check order puts
 * CYL_E_ZERO_AXIS before CYL_E_HEIGHT, so that is the error intersect must report. */
static void test_from_segment_degenerate(void)
{
    const T p[3] = {1, 2, 3};
    Cyl cyl = CYL(from_segment)(p, p, 1);
    Ray ray = mk_ray(-3, 2, 3, 1, 0, 0);
    EXACT(0, cyl.h, "h = 0");
    VEC_EXACT(cyl.a, 0, 0, 0, "a = 0");
    EXPECT_ERROR(&ray, &cyl, 0, CYL_E_ZERO_AXIS, "p0 == p1: zero axis (before the zero height)");
}

/* Every test of this file, in order; the runner that includes it calls this. */
static void run_errors(void)
{
    UnitySetTestFile(__FILE__); /* failures point into this file */
    RUN_TEST(test_error_null);
    RUN_TEST(test_error_nonfinite);
    RUN_TEST(test_error_zero_dir_axis);
    RUN_TEST(test_error_radius_height);
    RUN_TEST(test_error_trange_option);
    RUN_TEST(test_error_check_order);
    RUN_TEST(test_inputs_unmodified_and_miss_untouched);
    RUN_TEST(test_trusted_broken_promise);
    RUN_TEST(test_from_segment_degenerate);
}

#ifndef CONTRACT_ALL /* built alone, for one configuration: see tests/README.md */
int main(void)
{
    UNITY_BEGIN();
    run_errors();
    return UNITY_END();
}
#endif
