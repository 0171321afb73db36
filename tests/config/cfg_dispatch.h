/* Shared declaration of the dispatch test (cfg_dispatch_main.c, cfg_dispatch_other.c). */
#ifndef CFG_DISPATCH_H
#define CFG_DISPATCH_H
#include "cylinder_isect.h"
/* cyld_intersect_all (want 2) or cyld_intersect (want 1) in a unit built with
   CYL_FMA_DISPATCH 0: the double API's CYL_PRECISE calls in plain SSE2, Dekker's products. */
int no_dispatch_call(int want, const cyld_ray *ray, const cyld_cylinder *cyl, unsigned opts,
                     cyld_hit hits[2]);
#endif
