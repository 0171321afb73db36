/* Compile configuration: CYL_NO_DOUBLE leaves out every cyld_* name and keeps cylf_*.
 * The proof of absence: this file defines its own, incompatible cyld_ray, cyld_intersect and
 * cyld_from_segment after the include, which only compiles if the header declared none. */
#define CYL_NO_DOUBLE
#include "cylinder_isect.h"

#include <math.h>
#include <string.h>

#include "unity.h"

typedef int cyld_ray;
typedef long cyld_cylinder;
static int cyld_intersect(int x) { return x + 1; }
static int cyld_from_segment(void) { return 7; }

void setUp(void) {}
void tearDown(void) {}

static void test_double_names_are_free(void)
{
    cyld_ray r = 41;
    cyld_cylinder c = 1;
    TEST_ASSERT_EQUAL_INT(42, cyld_intersect(r));
    TEST_ASSERT_EQUAL_INT(7, cyld_from_segment() * (int)c);
}

static void test_float_api_still_works(void)
{
    cylf_ray ray;
    cylf_cylinder cyl;
    cylf_hit hit;
    memset(&ray, 0, sizeof ray);
    memset(&cyl, 0, sizeof cyl);
    memset(&hit, 0, sizeof hit);
    ray.o[0] = -3; ray.d[0] = 1; ray.tmax = (float)INFINITY;
    cyl.a[2] = 1; cyl.r = 1; cyl.h = 2;
    TEST_ASSERT_EQUAL_INT(CYL_HIT, cylf_intersect(&ray, &cyl, 0, &hit));
    TEST_ASSERT_TRUE(hit.t >= 2 && hit.t <= 2); /* exact case: t = 2 */
    TEST_ASSERT_NOT_NULL(cyl_strerror(CYL_E_NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_double_names_are_free);
    RUN_TEST(test_float_api_still_works);
    return UNITY_END();
}
