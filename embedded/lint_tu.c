/* The translation unit that scripts/cross.sh lint hands to cppcheck (MISRA C 2012 addon) and
 * clang-tidy: the header with every entry point called, so that every function body is
 * analysed. The script runs it once per precision (-DCYL_NO_DOUBLE, then -DCYL_NO_FLOAT): the
 * two instances of the body share their line numbers, which one whole-program analysis would
 * mix up. */
#include "cylinder_isect.h"

#ifndef CYL_NO_FLOAT
int lint_float(const cylf_ray *ray, const cylf_cylinder *cyl, unsigned opts, cylf_hit hits[2]);
cylf_cylinder lint_float_segment(const float p0[3], const float p1[3], float r);

int lint_float(const cylf_ray *ray, const cylf_cylinder *cyl, unsigned opts, cylf_hit hits[2])
{
    int a = cylf_intersect(ray, cyl, opts, &hits[0]);
    int b = cylf_intersect_all(ray, cyl, opts, hits);
    int c = cylf_occluded(ray, cyl, opts);
    return a + b + c;
}

cylf_cylinder lint_float_segment(const float p0[3], const float p1[3], float r)
{
    return cylf_from_segment(p0, p1, r);
}
#endif

#ifndef CYL_NO_DOUBLE
int lint_double(const cyld_ray *ray, const cyld_cylinder *cyl, unsigned opts, cyld_hit hits[2]);
cyld_cylinder lint_double_segment(const double p0[3], const double p1[3], double r);

int lint_double(const cyld_ray *ray, const cyld_cylinder *cyl, unsigned opts, cyld_hit hits[2])
{
    int a = cyld_intersect(ray, cyl, opts, &hits[0]);
    int b = cyld_intersect_all(ray, cyl, opts, hits);
    int c = cyld_occluded(ray, cyl, opts);
    return a + b + c;
}

cyld_cylinder lint_double_segment(const double p0[3], const double p1[3], double r)
{
    return cyld_from_segment(p0, p1, r);
}
#endif

const char *lint_strerror(int code);

const char *lint_strerror(int code)
{
    return cyl_strerror(code);
}
