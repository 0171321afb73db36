/* The contract tests of cylinder_isect.h for double (cyld_*): tests/test_float.c's runner with
 * T_DOUBLE defined (see tests/contract/contract.h). */
#define T_DOUBLE
#include "test_float.c"
