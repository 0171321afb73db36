/* Compile configuration: -DCYL_NO_PRECISE compiles the precise tier out; CYL_PRECISE is then an
 * unknown option (CYL_E_OPTION, *hit untouched) and the default path is unaffected. */
#include "cylinder_isect.h"

#include <math.h>
#include <string.h>

#include "unity.h"

#ifndef CYL_NO_PRECISE
#error "build this file with -DCYL_NO_PRECISE (mk/tests.mk does)"
#endif

void setUp(void) {}
void tearDown(void) {}

/* The ray x = -3 + t along x through the unit cylinder about z, h = 2, in both precisions. */
static void scene(cylf_ray *rf, cylf_cylinder *cf, cyld_ray *rd, cyld_cylinder *cd)
{
    memset(rf, 0, sizeof *rf); memset(cf, 0, sizeof *cf);
    memset(rd, 0, sizeof *rd); memset(cd, 0, sizeof *cd);
    rf->o[0] = -3; rf->d[0] = 1; rf->tmax = (float)INFINITY;
    cf->a[2] = 1; cf->r = 1; cf->h = 2;
    rd->o[0] = -3; rd->d[0] = 1; rd->tmax = INFINITY;
    cd->a[2] = 1; cd->r = 1; cd->h = 2;
}

static void test_precise_is_an_unknown_option(void)
{
    cylf_ray rf;
    cylf_cylinder cf;
    cylf_hit hf, hf0;
    cyld_ray rd;
    cyld_cylinder cd;
    cyld_hit hd[2], hd0[2];
    scene(&rf, &cf, &rd, &cd);
    memset(&hf, 0, sizeof hf); memset(&hd, 0, sizeof hd);
    memset(&hf, 0x5A, sizeof hf); hf0 = hf;
    memset(hd, 0x5A, sizeof hd); memcpy(hd0, hd, sizeof hd);
    TEST_ASSERT_EQUAL_INT(CYL_E_OPTION, cylf_intersect(&rf, &cf, CYL_PRECISE, &hf));
    TEST_ASSERT_EQUAL_MEMORY(&hf0, &hf, sizeof hf);
    TEST_ASSERT_EQUAL_INT(CYL_E_OPTION, cylf_occluded(&rf, &cf, CYL_CAPS | CYL_PRECISE));
    TEST_ASSERT_EQUAL_INT(CYL_E_OPTION, cyld_intersect_all(&rd, &cd, CYL_PRECISE, hd));
    TEST_ASSERT_EQUAL_MEMORY(hd0, hd, sizeof hd);
    TEST_ASSERT_EQUAL_INT(CYL_E_OPTION, cyld_occluded(&rd, &cd, CYL_PRECISE));
}

static void test_default_path_unaffected(void)
{
    cylf_ray rf;
    cylf_cylinder cf;
    cylf_hit hf;
    cyld_ray rd;
    cyld_cylinder cd;
    cyld_hit hd[2];
    scene(&rf, &cf, &rd, &cd);
    memset(&hf, 0, sizeof hf); memset(&hd, 0, sizeof hd);
    TEST_ASSERT_EQUAL_INT(CYL_HIT, cylf_intersect(&rf, &cf, CYL_CAPS | CYL_OUTWARD, &hf));
    TEST_ASSERT_TRUE(hf.t >= 2 && hf.t <= 2); /* exact case: t = 2 */
    TEST_ASSERT_EQUAL_INT(2, cyld_intersect_all(&rd, &cd, 0, hd));
    TEST_ASSERT_TRUE(hd[1].t >= 4 && hd[1].t <= 4); /* exact case: t = 4 */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_precise_is_an_unknown_option);
    RUN_TEST(test_default_path_unaffected);
    return UNITY_END();
}
