/* CYL_FMA_DISPATCH: on x86-64 built without -mfma, CYL_PRECISE calls run a copy of the body
 * built for the FMA where the CPU has it. That copy must change the cost, not the answers: its
 * exact products are exact either way and it contracts nothing. This unit (the header's
 * default: the copy, where this CPU has the FMA) and cfg_dispatch_other.c (CYL_FMA_DISPATCH 0)
 * answer every case family of bench/cases.c in both APIs, open and capped, with and without
 * CYL_OUTWARD and CYL_NO_TANGENT, through every entry point: the same return values and the
 * same bits in every hit. Built with CFG_PAIR_STRUCT, the other unit forms the hot path's pairs
 * (N1) as structs, lane by lane, where this one has vectors: the same bits again, every tier.
 * With CFG_PORTABLE the other unit comes from a compiler without GNU C (mk/tests.mk: tcc), so
 * it takes every environment hook's portable branch: the same bits again, every tier. */
#include "cfg_dispatch.h"
#include "cases.h"

#include <string.h>

#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define CASES_PER_FAMILY 1000

static const unsigned opts[] = {CYL_PRECISE, CYL_PRECISE | CYL_CAPS, CYL_PRECISE | CYL_CAPS | CYL_OUTWARD,
                                CYL_PRECISE | CYL_NO_TANGENT
#if defined(CFG_PAIR_STRUCT) || defined(CFG_PORTABLE)
                                , 0u, CYL_CAPS, CYL_CAPS | CYL_OUTWARD, CYL_NO_TANGENT,
                                CYL_CAPS | CYL_NO_NORMAL | CYL_NO_ERRBOUND
#endif
};
#define NOPTS ((int)(sizeof opts / sizeof opts[0]))

static void skip_without_dispatch(void)
{
#if defined(CFG_PAIR_STRUCT) || defined(CFG_PORTABLE)
    /* nothing to skip: the two units differ in their pairs' form, or their hooks' */
#elif !CYL_FMA_DISPATCH
    TEST_IGNORE_MESSAGE("CYL_FMA_DISPATCH is 0 here (not x86-64, or built with the FMA)");
#else
    if (!__builtin_cpu_supports("fma")) TEST_IGNORE_MESSAGE("this CPU has no FMA: nothing dispatched");
#endif
}

/* One case of bench/cases.c (its values exact in T) through every option set and entry point
   of both units (P: f or d, T its type): the number of calls that hit. */
#define SAME_BITS(P, T)                                                                         \
    static int same_bits_##P(const bench_case *c, const char *family)                          \
    {                                                                                           \
        cyl##P##_ray ray;                                                                       \
        cyl##P##_cylinder cyl;                                                                  \
        int j, k, want, hits = 0;                                                               \
        for (j = 0; j < 3; j++) {                                                               \
            ray.o[j] = (T)c->o[j], ray.d[j] = (T)c->d[j];                                       \
            cyl.c[j] = (T)c->c[j], cyl.a[j] = (T)c->a[j];                                       \
        }                                                                                       \
        ray.tmin = (T)c->tmin, ray.tmax = (T)c->tmax, cyl.r = (T)c->r, cyl.h = (T)c->h;         \
        for (k = 0; k < NOPTS; k++)                                                             \
            for (want = 0; want <= 2; want++) {                                                 \
                cyl##P##_hit a[2], b[2];                                                        \
                int ra, rb;                                                                     \
                memset(a, 0, sizeof a), memset(b, 0, sizeof b);                                 \
                ra = want == 0 ? cyl##P##_occluded(&ray, &cyl, opts[k])                         \
                     : want == 1 ? cyl##P##_intersect(&ray, &cyl, opts[k], a)                   \
                                 : cyl##P##_intersect_all(&ray, &cyl, opts[k], a);              \
                rb = other_##P(want, &ray, &cyl, opts[k], b);                                   \
                TEST_ASSERT_EQUAL_INT_MESSAGE(rb, ra, family);                                  \
                TEST_ASSERT_EQUAL_MEMORY_MESSAGE(b, a, sizeof a, family);                       \
                hits += want > 0 && ra > 0;                                                     \
            }                                                                                   \
        return hits;                                                                            \
    }
SAME_BITS(f, float)
SAME_BITS(d, double)

/* Every family's cases in precision prec (24, 53) through same. */
static void check_families(int prec, int (*same)(const bench_case *, const char *))
{
    int fam, i, hits = 0;
    skip_without_dispatch();
    for (fam = 0; fam < BF_COUNT; fam++)
        for (i = 0; i < CASES_PER_FAMILY; i++) {
            bench_case c;
            bench_case_gen(fam, prec, 20261205u, (uint64_t)i, &c);
            hits += same(&c, bench_family_name(fam));
        }
    TEST_ASSERT_TRUE(hits > BF_COUNT * CASES_PER_FAMILY); /* the comparison saw hits */
}

static void test_both_units_give_the_same_bits_double(void) { check_families(53, same_bits_d); }
static void test_both_units_give_the_same_bits_float(void) { check_families(24, same_bits_f); }

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_both_units_give_the_same_bits_double);
    RUN_TEST(test_both_units_give_the_same_bits_float);
    return UNITY_END();
}
