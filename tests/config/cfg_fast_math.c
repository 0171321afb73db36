/* Compiled by tests/config/check-fast-math.sh: must build normally and must stop with the
 * header's #error under -ffast-math. */
#include "cylinder_isect.h"

int cfg_fast_math_probe(void);
int cfg_fast_math_probe(void) { return CYL_HIT; }
