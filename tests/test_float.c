/* The contract tests of cylinder_isect.h for float (cylf_*): every topic file of tests/contract/
 * in one runner, which make test builds in each configuration. tests/test_double.c is the same
 * runner for double. One topic alone: make test-one T=<topic> CFG=<configuration> (tests/README.md).
 */
#define CONTRACT_ALL
#include "contract/exact.c"     /* exact cases */
#include "contract/tangent.c"   /* tangent, rim and parallel */
#include "contract/errors.c"    /* invalid input */
#include "contract/t_range.c"   /* tmin / tmax */
#include "contract/invariance.c" /* scaling, translation, options that only drop work */
#include "contract/reference.c" /* against the long double reference */

int main(void)
{
    UNITY_BEGIN();
    run_exact();
    run_tangent();
    run_errors();
    run_t_range();
    run_invariance();
    run_reference();
    return UNITY_END();
}
