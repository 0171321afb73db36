/* Shared declarations of the dispatch test (cfg_dispatch_main.c, cfg_dispatch_other.c). */
#ifndef CFG_DISPATCH_H
#define CFG_DISPATCH_H
#include "cylinder_isect.h"
/* cyl?_occluded (want 0), cyl?_intersect (1) or cyl?_intersect_all (2) in the other unit: built
   with CYL_FMA_DISPATCH 0 (CYL_PRECISE calls in plain SSE2, the double API's products by
   Dekker), or with CFG_PAIR_STRUCT the pairs as structs. */
int other_d(int want, const cyld_ray *ray, const cyld_cylinder *cyl, unsigned opts, cyld_hit hits[2]);
int other_f(int want, const cylf_ray *ray, const cylf_cylinder *cyl, unsigned opts, cylf_hit hits[2]);
#endif
