/* Compile configuration: user overrides of the environment macros, each shown to be used.
 *   CYL_SQRTF / CYL_SQRT / CYL_FMAF / CYL_FMA  counting wrappers: the counters must move.
 *   CYL_DEF defined empty: the functions get external linkage; cfg_overrides_ext.c calls
 *     cyl_strerror through its own prototype, so the link only succeeds if CYL_DEF was used.
 *   CYL_TANGENT_TOLF/CYL_TANGENT_TOL and CYL_PARALLEL_TOLF/CYL_PARALLEL_TOL widened: a contact
 *     outside the default bands must now be flagged. */
#include <math.h>
#include <string.h>

static long n_sqrtf, n_sqrt, n_fmaf, n_fma;
static float count_sqrtf(float x) { n_sqrtf++; return sqrtf(x); }
static double count_sqrt(double x) { n_sqrt++; return sqrt(x); }
static float count_fmaf(float a, float b, float c) { n_fmaf++; return fmaf(a, b, c); }
static double count_fma(double a, double b, double c) { n_fma++; return fma(a, b, c); }

#define CYL_SQRTF(x) count_sqrtf(x)
#define CYL_SQRT(x) count_sqrt(x)
#define CYL_FMAF(a, b, c) count_fmaf(a, b, c)
#define CYL_FMA(a, b, c) count_fma(a, b, c)
#define CYL_DEF
/* Widened bands (defaults 2^-16 / 2^-45 and 2^-24 / 2^-53). */
#define CYL_TANGENT_TOLF (1.0f / 256.0f)      /* 2^-8 */
#define CYL_TANGENT_TOL (1.0 / 1048576.0)     /* 2^-20 */
#define CYL_PARALLEL_TOLF (1.0f / 1024.0f)    /* 2^-10 */
#define CYL_PARALLEL_TOL (1.0 / 1073741824.0) /* 2^-30 */
#include "cylinder_isect.h"

#include "unity.h"

const char *ext_strerror(int code); /* cfg_overrides_ext.c */

void setUp(void) {}
void tearDown(void) {}

static cylf_ray ray_f(float oy, float dx, float dz)
{
    cylf_ray r;
    memset(&r, 0, sizeof r);
    r.o[0] = -3; r.o[1] = oy; r.d[0] = dx; r.d[2] = dz; r.tmax = (float)INFINITY;
    return r;
}
static cyld_ray ray_d(double oy, double dx, double dz)
{
    cyld_ray r;
    memset(&r, 0, sizeof r);
    r.o[0] = -3; r.o[1] = oy; r.d[0] = dx; r.d[2] = dz; r.tmax = INFINITY;
    return r;
}
static cylf_cylinder cyl_f(void)
{
    cylf_cylinder c;
    memset(&c, 0, sizeof c);
    c.a[2] = 1; c.r = 1; c.h = 2;
    return c;
}
static cyld_cylinder cyl_d(void)
{
    cyld_cylinder c;
    memset(&c, 0, sizeof c);
    c.a[2] = 1; c.r = 1; c.h = 2;
    return c;
}

static void test_sqrt_and_fma_overrides_are_called(void)
{
    cylf_ray rf = ray_f(0.5f, 1, 0);
    cylf_cylinder cf = cyl_f();
    cyld_ray rd = ray_d(0.5, 1, 0);
    cyld_cylinder cd = cyl_d();
    cylf_hit hf;
    cyld_hit hd;
    memset(&hf, 0, sizeof hf);
    memset(&hd, 0, sizeof hd);
    n_sqrtf = n_sqrt = n_fmaf = n_fma = 0;
    TEST_ASSERT_EQUAL_INT(CYL_HIT, cyld_intersect(&rd, &cd, 0, &hd));
    TEST_ASSERT_TRUE_MESSAGE(n_sqrt > 0, "CYL_SQRT used by cyld_intersect");
    n_sqrt = 0;
    TEST_ASSERT_EQUAL_INT(CYL_HIT, cylf_intersect(&rf, &cf, 0, &hf));
#if CYL_FLOAT_WIDE /* the float API's fast path computes in double */
    TEST_ASSERT_TRUE_MESSAGE(n_sqrt > 0, "CYL_SQRT used by cylf_intersect (CYL_FLOAT_WIDE)");
#else
    TEST_ASSERT_TRUE_MESSAGE(n_sqrtf > 0, "CYL_SQRTF used by cylf_intersect");
#endif
    n_sqrt = 0;
#ifndef CYL_NO_PRECISE /* the precise tier's calls (none where the header defines CYL_NO_PRECISE) */
    TEST_ASSERT_EQUAL_INT(CYL_HIT, cylf_intersect(&rf, &cf, CYL_PRECISE, &hf));
#if CYL_FLOAT_WIDE /* the float API's precise tier computes in double too, solver included */
    TEST_ASSERT_TRUE_MESSAGE(n_sqrt > 0, "CYL_SQRT used by cylf_intersect's precise tier");
#else
    TEST_ASSERT_TRUE_MESSAGE(n_sqrtf > 0, "CYL_SQRTF used by cylf_intersect's precise tier");
#endif
#endif
#if CYL_FLOAT_WIDE
    {
        /* cylf_from_segment's length is a float square root */
        const float p0[3] = {0, 0, 0}, p1[3] = {0, 0, 2};
        cylf_cylinder cs = cylf_from_segment(p0, p1, 1);
        TEST_ASSERT_EQUAL_FLOAT(2.0f, cs.h); /* exact: sqrt(4) */
    }
    TEST_ASSERT_TRUE_MESSAGE(n_sqrtf > 0, "CYL_SQRTF used by cylf_from_segment");
#endif
#ifndef CYL_NO_PRECISE
    TEST_ASSERT_EQUAL_INT(CYL_HIT, cyld_intersect(&rd, &cd, CYL_PRECISE, &hd));
#endif
#if CYL_VERSION_MAJOR >= 2
    /* v2 uses fma only on its exact path, which a double ray within 2^-8 of the axis direction
       takes (the float API computed in double forms its products exactly and needs none) */
    {
        cyld_ray steep = ray_d(0.5, 1.0 / 1024, 1);
        cyld_hit hs;
        steep.o[0] = 0;
        steep.o[2] = -3;
        n_fma = 0;
        TEST_ASSERT_EQUAL_INT(CYL_HIT, cyld_intersect(&steep, &cd, CYL_CAPS, &hs));
        TEST_ASSERT_TRUE_MESSAGE(n_fma > 0, "CYL_FMA used by the exact path (a ray near the axis direction)");
        (void)count_fmaf; /* CYL_FMAF serves only the float API computed in float */
    }
#else
    TEST_ASSERT_TRUE_MESSAGE(n_fmaf > 0, "CYL_FMAF used (default or precise path)");
    TEST_ASSERT_TRUE_MESSAGE(n_fma > 0, "CYL_FMA used (default or precise path)");
#endif
    /* the overrides are not just called but their results used: t = 3 - sqrt(3/4) */
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 3.0 - sqrt(0.75), hd.t); /* 1e-12: ~4000 ulp, loose */
}

static void test_def_override_gives_external_linkage(void)
{
    /* ext_strerror calls cyl_strerror from another translation unit that never includes the
     * header: this links only because CYL_DEF (empty) made cyl_strerror external. */
    TEST_ASSERT_EQUAL_PTR(cyl_strerror(CYL_E_TRANGE), ext_strerror(CYL_E_TRANGE));
}

static void test_tolerance_overrides_are_used(void)
{
    cylf_cylinder cf = cyl_f();
    cyld_cylinder cd = cyl_d();
    cylf_hit hf;
    cyld_hit hd;
    /* e = 1 - rho^2 ~ 2^-10: outside the default float band 2^-16, inside the widened 2^-8. */
    cylf_ray rf = ray_f(1.0f - 1.0f / 2048.0f, 1, 0);
    /* e ~ 2^-22: outside the default double band 2^-45, inside the widened 2^-20. */
    cyld_ray rd = ray_d(1.0 - 1.0 / 8388608.0, 1, 0);
    TEST_ASSERT_EQUAL_INT(CYL_HIT, cylf_intersect(&rf, &cf, 0, &hf));
    TEST_ASSERT_EQUAL_HEX32(CYL_F_TANGENT, hf.flags & CYL_F_TANGENT);
    TEST_ASSERT_EQUAL_INT(CYL_MISS, cylf_intersect(&rf, &cf, CYL_NO_TANGENT, &hf));
    TEST_ASSERT_EQUAL_INT(CYL_HIT, cyld_intersect(&rd, &cd, 0, &hd));
    TEST_ASSERT_EQUAL_HEX32(CYL_F_TANGENT, hd.flags & CYL_F_TANGENT);
    TEST_ASSERT_EQUAL_INT(CYL_MISS, cyld_intersect(&rd, &cd, CYL_NO_TANGENT, &hd));
    /* sin = 2^-12 (float) / 2^-32 (double): parallel only under the widened bounds. */
    rf = ray_f(0, 1.0f / 4096.0f, 1);
    rf.o[0] = 0; rf.o[2] = -5;
    TEST_ASSERT_EQUAL_INT(CYL_HIT, cylf_intersect(&rf, &cf, CYL_CAPS, &hf));
    TEST_ASSERT_EQUAL_HEX32(CYL_F_PARALLEL, hf.flags & CYL_F_PARALLEL);
    rd = ray_d(0, 1.0 / 4294967296.0, 1);
    rd.o[0] = 0; rd.o[2] = -5;
    TEST_ASSERT_EQUAL_INT(CYL_HIT, cyld_intersect(&rd, &cd, CYL_CAPS, &hd));
    TEST_ASSERT_EQUAL_HEX32(CYL_F_PARALLEL, hd.flags & CYL_F_PARALLEL);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_sqrt_and_fma_overrides_are_called);
    RUN_TEST(test_def_override_gives_external_linkage);
    RUN_TEST(test_tolerance_overrides_are_used);
    return UNITY_END();
}
