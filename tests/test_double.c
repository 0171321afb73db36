/* The contract tests (tests/core_tests.inc) instantiated for double: cyld_*. */
#include <float.h>
#include <math.h>

#include "unity.h"
#include "cylinder_isect.h"

#define T double
#define CYL(x) cyld_##x
#define TOL_TANGENT CYL_TANGENT_TOL
#define TOL_PARALLEL CYL_PARALLEL_TOL
#define T_EPS DBL_EPSILON
#define T_SQRT sqrt
#define T_FABS fabs
#define T_NEXT nextafter
#define T_LDEXP ldexp
#define T_BIG_EXP 400 /* lengths scaled by 2^+-400: squares stay finite only with prescaling */
#define T_DIR_EXP 500 /* d and a scaled by 2^+-500 */
#define T_MAX_EXP DBL_MAX_EXP
#include "core_tests.inc"

void setUp(void) {}
void tearDown(void) {}

int main(void)
{
    UNITY_BEGIN();
    core_run_all();
    return UNITY_END();
}
