/* Second translation unit of the two-TU link test: includes the header again (default
 * CYL_DEF = static inline) and exposes one function of its own. Linking it with
 * cfg_two_tu_main.c must not give duplicate symbols. */
#include "cylinder_isect.h"

#include <math.h>
#include <string.h>

#include "cfg_two_tu.h"

int other_tu_first_hit(float *tf, double *td, const char **msg)
{
    cylf_ray rf;
    cylf_cylinder cf;
    cylf_hit hf;
    cyld_ray rd;
    cyld_cylinder cd;
    cyld_hit hd;
    int a, b;
    memset(&rf, 0, sizeof rf); memset(&cf, 0, sizeof cf);
    memset(&rd, 0, sizeof rd); memset(&cd, 0, sizeof cd);
    memset(&hf, 0, sizeof hf); memset(&hd, 0, sizeof hd);
    rf.o[0] = -3; rf.o[1] = 0.5f; rf.d[0] = 1; rf.tmax = (float)INFINITY;
    cf.a[2] = 1; cf.r = 1; cf.h = 2;
    rd.o[0] = -3; rd.o[1] = 0.5; rd.d[0] = 1; rd.tmax = INFINITY;
    cd.a[2] = 1; cd.r = 1; cd.h = 2;
    a = cylf_intersect(&rf, &cf, CYL_CAPS, &hf);
    b = cyld_intersect(&rd, &cd, CYL_CAPS, &hd);
    *tf = hf.t;
    *td = hd.t;
    *msg = cyl_strerror(CYL_E_RADIUS);
    return a == CYL_HIT && b == CYL_HIT;
}
