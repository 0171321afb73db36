/* The other unit of the dispatch test (see cfg_dispatch_main.c): built without the FMA copy,
   or (CFG_PAIR_STRUCT) with the pairs of N1 as structs, the form of targets without vectors. */
#ifdef CFG_PAIR_STRUCT
#define CYL__PAIR_STRUCT
#else
#define CYL_FMA_DISPATCH 0
#endif
#include "cfg_dispatch.h"

int other_d(int want, const cyld_ray *ray, const cyld_cylinder *cyl, unsigned opts, cyld_hit hits[2])
{
    if (want == 0) return cyld_occluded(ray, cyl, opts);
    return want == 2 ? cyld_intersect_all(ray, cyl, opts, hits) : cyld_intersect(ray, cyl, opts, hits);
}

int other_f(int want, const cylf_ray *ray, const cylf_cylinder *cyl, unsigned opts, cylf_hit hits[2])
{
    if (want == 0) return cylf_occluded(ray, cyl, opts);
    return want == 2 ? cylf_intersect_all(ray, cyl, opts, hits) : cylf_intersect(ray, cyl, opts, hits);
}
