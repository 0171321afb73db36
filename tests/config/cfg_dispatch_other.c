/* The unit of the dispatch test built without the FMA copy (see cfg_dispatch_main.c). */
#define CYL_FMA_DISPATCH 0
#include "cfg_dispatch.h"

int no_dispatch_call(int want, const cyld_ray *ray, const cyld_cylinder *cyl, unsigned opts,
                     cyld_hit hits[2])
{
    return want == 2 ? cyld_intersect_all(ray, cyl, opts, hits) : cyld_intersect(ray, cyl, opts, hits);
}
