/* One configuration of cylinder_isect as a scene would use it: a single non-inline wrapper that
 * calls the API with constant options, so the compiler can fold away what the options leave
 * out. Built once per row of embedded/configs.txt by scripts/cross.sh sizes (and by
 * scripts/cross.sh embedded for the microcontroller checks), e.g.
 *   cc -O2 -DCFG_NAME=cfgf_capped -DCFG_DOUBLE=0 -DCFG_ENTRY=CFG_INTERSECT -DCFG_OPTS=CYL_CAPS
 * Each configuration lives alone in its translation unit, so the size of the object's code is
 * the size of the routine for that configuration (static inline functions called once are
 * inlined; nothing from another configuration is shared or counted).
 * Entry points: CFG_INTERSECT, CFG_ALL, CFG_OCCLUDED, CFG_EVERY (all three, chosen at run time),
 * CFG_PAIR (intersect and occluded with the same constant options, chosen at run time), CFG_MIXED
 * (cylf_intersect with the options and, in the same object, cyld_intersect with 0: the issue's
 * translation unit of two APIs; built only where double is compiled in).
 * CFG_RUNTIME=1 reads the options from cfg_runtime_opts (defined elsewhere), so nothing folds. */
#include "cylinder_isect.h"

#define CFG_INTERSECT 0
#define CFG_ALL 1
#define CFG_OCCLUDED 2
#define CFG_EVERY 3
#define CFG_PAIR 4
#define CFG_MIXED 5

#ifndef CFG_NAME
#error "CFG_NAME (the wrapper's name) must be defined"
#endif
#ifndef CFG_DOUBLE
#define CFG_DOUBLE 0
#endif
#ifndef CFG_ENTRY
#define CFG_ENTRY CFG_INTERSECT
#endif
#ifndef CFG_RUNTIME
#define CFG_RUNTIME 0
#endif

#if CFG_DOUBLE
#define CFG_P(name) cyld_##name
#else
#define CFG_P(name) cylf_##name
#endif

#if CFG_RUNTIME
/* Options unknown at compile time: every feature stays in the code. */
extern unsigned cfg_runtime_opts;
extern int cfg_runtime_entry;
#define CFG_OPTIONS cfg_runtime_opts
#else
#ifndef CFG_OPTS
#define CFG_OPTS 0u
#endif
#define CFG_OPTIONS ((unsigned)(CFG_OPTS))
#if CFG_ENTRY == CFG_PAIR
extern int cfg_runtime_entry;
#endif
#endif

#if CFG_ENTRY == CFG_MIXED && !CFG_DOUBLE && !defined(CYL_NO_DOUBLE)
/* The second API of the mixed translation unit, with the default options. */
int cfg_mixed_double(const cyld_ray *ray, const cyld_cylinder *cyl, cyld_hit *hit);
int cfg_mixed_double(const cyld_ray *ray, const cyld_cylinder *cyl, cyld_hit *hit)
{
    return cyld_intersect(ray, cyl, 0u, hit);
}
#endif

/* Same signature for every configuration so that embedded/timing.c can call them all. */
int CFG_NAME(const CFG_P(ray) *ray, const CFG_P(cylinder) *cyl, CFG_P(hit) hits[2]);

int CFG_NAME(const CFG_P(ray) *ray, const CFG_P(cylinder) *cyl, CFG_P(hit) hits[2])
{
#if CFG_ENTRY == CFG_INTERSECT || CFG_ENTRY == CFG_MIXED
    return CFG_P(intersect)(ray, cyl, CFG_OPTIONS, hits);
#elif CFG_ENTRY == CFG_ALL
    return CFG_P(intersect_all)(ray, cyl, CFG_OPTIONS, hits);
#elif CFG_ENTRY == CFG_OCCLUDED
    (void)hits;
    return CFG_P(occluded)(ray, cyl, CFG_OPTIONS);
#elif CFG_ENTRY == CFG_PAIR && !CFG_RUNTIME
    if (cfg_runtime_entry == CFG_OCCLUDED) return CFG_P(occluded)(ray, cyl, CFG_OPTIONS);
    return CFG_P(intersect)(ray, cyl, CFG_OPTIONS, hits);
#elif CFG_ENTRY == CFG_EVERY && CFG_RUNTIME
    switch (cfg_runtime_entry) {
    case CFG_ALL:
        return CFG_P(intersect_all)(ray, cyl, CFG_OPTIONS, hits);
    case CFG_OCCLUDED:
        return CFG_P(occluded)(ray, cyl, CFG_OPTIONS);
    default:
        return CFG_P(intersect)(ray, cyl, CFG_OPTIONS, hits);
    }
#else
#error "CFG_ENTRY must be CFG_INTERSECT, CFG_ALL, CFG_OCCLUDED, CFG_PAIR, CFG_MIXED, or CFG_EVERY with CFG_RUNTIME=1"
#endif
}
