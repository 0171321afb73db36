/* The unit of the dispatch test built without the FMA copy (see cfg_dispatch_main.c). */
#define CYL_FMA_DISPATCH 0
#include "cfg_dispatch.h"

int no_dispatch_d(int want, const cyld_ray *ray, const cyld_cylinder *cyl, unsigned opts, cyld_hit hits[2])
{
    if (want == 0) return cyld_occluded(ray, cyl, opts);
    return want == 2 ? cyld_intersect_all(ray, cyl, opts, hits) : cyld_intersect(ray, cyl, opts, hits);
}

int no_dispatch_f(int want, const cylf_ray *ray, const cylf_cylinder *cyl, unsigned opts, cylf_hit hits[2])
{
    if (want == 0) return cylf_occluded(ray, cyl, opts);
    return want == 2 ? cylf_intersect_all(ray, cyl, opts, hits) : cylf_intersect(ray, cyl, opts, hits);
}
