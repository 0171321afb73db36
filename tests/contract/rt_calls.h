/* rt_calls.h: the entry points for options known only at run time (a loop over option sets, a
 * helper's parameter), one out-of-line copy each. v2 forces its entry points inline, so a direct
 * call copies the whole body into its call site, and with a variable opts that body keeps every
 * option's code: the test runners' compile time. Calls with constant options stay direct: they
 * test the code a user's call site folds to.
 *
 * RT_CALLS(PRE, P) defines PRE##intersect, PRE##intersect_all and PRE##occluded over cylP_*
 * (contract.h: rt_ over its precision; fuzz/test_fuzz_regressions.c: rt_f_ and rt_d_). */
#ifndef RT_CALLS_H
#define RT_CALLS_H

#include "cylinder_isect.h"

#if defined(__GNUC__)
#define RT_FN static __attribute__((noinline, unused))
#else
#define RT_FN static inline
#endif
#define RT_CALLS(PRE, P)                                                                       \
    RT_FN int PRE##intersect(const cyl##P##_ray *r, const cyl##P##_cylinder *c, unsigned o,    \
                             cyl##P##_hit *h)                                                  \
    { return cyl##P##_intersect(r, c, o, h); }                                                \
    RT_FN int PRE##intersect_all(const cyl##P##_ray *r, const cyl##P##_cylinder *c, unsigned o, \
                                 cyl##P##_hit *h)                                              \
    { return cyl##P##_intersect_all(r, c, o, h); }                                            \
    RT_FN int PRE##occluded(const cyl##P##_ray *r, const cyl##P##_cylinder *c, unsigned o)     \
    { return cyl##P##_occluded(r, c, o); }

#endif
