/* Compile configuration: CYL_NO_FLOAT leaves out every cylf_* name and keeps cyld_*.
 * The proof of absence: this file defines its own, incompatible cylf_ray, cylf_intersect and
 * cylf_from_segment after the include, which only compiles if the header declared none. */
#define CYL_NO_FLOAT
#include "cylinder_isect.h"

#include <math.h>
#include <string.h>

#include "unity.h"

typedef int cylf_ray;
typedef long cylf_cylinder;
static int cylf_intersect(int x) { return x + 1; }
static int cylf_from_segment(void) { return 7; }

void setUp(void) {}
void tearDown(void) {}

static void test_float_names_are_free(void)
{
    cylf_ray r = 41;
    cylf_cylinder c = 1;
    TEST_ASSERT_EQUAL_INT(42, cylf_intersect(r));
    TEST_ASSERT_EQUAL_INT(7, cylf_from_segment() * (int)c);
}

static void test_double_api_still_works(void)
{
    cyld_ray ray;
    cyld_cylinder cyl;
    cyld_hit hit;
    memset(&ray, 0, sizeof ray);
    memset(&cyl, 0, sizeof cyl);
    memset(&hit, 0, sizeof hit);
    ray.o[0] = -3; ray.d[0] = 1; ray.tmax = INFINITY;
    cyl.a[2] = 1; cyl.r = 1; cyl.h = 2;
    TEST_ASSERT_EQUAL_INT(CYL_HIT, cyld_intersect(&ray, &cyl, 0, &hit));
    TEST_ASSERT_TRUE(hit.t >= 2 && hit.t <= 2); /* exact case: t = 2 */
    TEST_ASSERT_NOT_NULL(cyl_strerror(CYL_E_NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_float_names_are_free);
    RUN_TEST(test_double_api_still_works);
    return UNITY_END();
}
