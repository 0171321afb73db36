/* Compiled by tests/config/check-refused.sh: must build normally and must stop with the
 * header's #error under each flag set the header refuses (-ffast-math; under V=2 also the
 * configuration macros v2 dropped). */
#include "cylinder_isect.h"

int cfg_refused_probe(void);
int cfg_refused_probe(void) { return CYL_HIT; }
