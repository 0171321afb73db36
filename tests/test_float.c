/* The contract tests (tests/core_tests.inc) instantiated for float: cylf_*. */
#include <float.h>
#include <math.h>

#include "unity.h"
#include "cylinder_isect.h"

#define T float
#define CYL(x) cylf_##x
#define TOL_TANGENT CYL_TANGENT_TOLF
#define TOL_PARALLEL CYL_PARALLEL_TOLF
#define T_EPS FLT_EPSILON
#define T_SQRT sqrtf
#define T_FABS fabsf
#define T_NEXT nextafterf
#define T_LDEXP ldexpf
#define T_BIG_EXP 50 /* lengths scaled by 2^+-50: squares stay finite only with prescaling */
#define T_DIR_EXP 60 /* d and a scaled by 2^+-60 */
#define T_MAX_EXP FLT_MAX_EXP
#include "core_tests.inc"

void setUp(void) {}
void tearDown(void) {}

int main(void)
{
    UNITY_BEGIN();
    core_run_all();
    return UNITY_END();
}
