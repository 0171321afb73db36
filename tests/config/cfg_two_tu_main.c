/* Two translation units include cylinder_isect.h and are linked together (this one and
 * cfg_two_tu_other.c): no duplicate symbols, and both compute the same answers. */
#include "cylinder_isect.h"

#include <math.h>
#include <string.h>

#include "unity.h"
#include "cfg_two_tu.h"

void setUp(void) {}
void tearDown(void) {}

static void test_both_units_agree(void)
{
    cylf_ray rf;
    cylf_cylinder cf;
    cylf_hit hf;
    cyld_ray rd;
    cyld_cylinder cd;
    cyld_hit hd;
    float tf = 0;
    double td = 0;
    const char *msg = NULL;
    memset(&rf, 0, sizeof rf); memset(&cf, 0, sizeof cf);
    memset(&rd, 0, sizeof rd); memset(&cd, 0, sizeof cd);
    memset(&hf, 0, sizeof hf); memset(&hd, 0, sizeof hd);
    rf.o[0] = -3; rf.o[1] = 0.5f; rf.d[0] = 1; rf.tmax = (float)INFINITY;
    cf.a[2] = 1; cf.r = 1; cf.h = 2;
    rd.o[0] = -3; rd.o[1] = 0.5; rd.d[0] = 1; rd.tmax = INFINITY;
    cd.a[2] = 1; cd.r = 1; cd.h = 2;
    TEST_ASSERT_TRUE(other_tu_first_hit(&tf, &td, &msg));
    TEST_ASSERT_EQUAL_INT(CYL_HIT, cylf_intersect(&rf, &cf, CYL_CAPS, &hf));
    TEST_ASSERT_EQUAL_INT(CYL_HIT, cyld_intersect(&rd, &cd, CYL_CAPS, &hd));
    /* the same inline code on the same inputs: bitwise the same t */
    TEST_ASSERT_EQUAL_MEMORY(&hf.t, &tf, sizeof tf);
    TEST_ASSERT_EQUAL_MEMORY(&hd.t, &td, sizeof td);
    TEST_ASSERT_EQUAL_STRING(cyl_strerror(CYL_E_RADIUS), msg);
    /* and a sane value: 3 - sqrt(3/4) */
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, 3.0 - sqrt(0.75), (double)tf); /* 1e-6: ~8 float ulp at 2.13 */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_both_units_agree);
    return UNITY_END();
}
