/* CYL_FMA_DISPATCH: on x86-64 built without -mfma, CYL_PRECISE calls run a copy of the body
 * built for the FMA where the CPU has it. That copy must change the cost, not the answers: its
 * exact products are exact either way and it contracts nothing. This unit (the header's
 * default: the copy, where this CPU has the FMA) and cfg_dispatch_other.c (CYL_FMA_DISPATCH 0)
 * answer every case family of bench/cases.c in both APIs, open and capped, with and without
 * CYL_OUTWARD and CYL_NO_TANGENT, through every entry point: the same return values and the
 * same bits in every hit. */
#include "cfg_dispatch.h"
#include "cases.h"

#include <string.h>

#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define CASES_PER_FAMILY 1000

static const unsigned opts[] = {CYL_PRECISE, CYL_PRECISE | CYL_CAPS, CYL_PRECISE | CYL_CAPS | CYL_OUTWARD,
                                CYL_PRECISE | CYL_NO_TANGENT};
#define NOPTS ((int)(sizeof opts / sizeof opts[0]))

static void skip_without_dispatch(void)
{
#if !CYL_FMA_DISPATCH
    TEST_IGNORE_MESSAGE("CYL_FMA_DISPATCH is 0 here (not x86-64, or built with the FMA)");
#else
    if (!__builtin_cpu_supports("fma")) TEST_IGNORE_MESSAGE("this CPU has no FMA: nothing dispatched");
#endif
}

/* One case through every option set and entry point of both units (P: f or d): the number of
   calls that hit. */
#define SAME_BITS(P)                                                                            \
    static int same_bits_##P(const cyl##P##_ray *ray, const cyl##P##_cylinder *cyl,            \
                             const char *family)                                               \
    {                                                                                           \
        int k, want, hits = 0;                                                                  \
        for (k = 0; k < NOPTS; k++)                                                             \
            for (want = 0; want <= 2; want++) {                                                 \
                cyl##P##_hit a[2], b[2];                                                        \
                int ra, rb;                                                                     \
                memset(a, 0, sizeof a), memset(b, 0, sizeof b);                                 \
                ra = want == 0 ? cyl##P##_occluded(ray, cyl, opts[k])                           \
                     : want == 1 ? cyl##P##_intersect(ray, cyl, opts[k], a)                     \
                                 : cyl##P##_intersect_all(ray, cyl, opts[k], a);                \
                rb = no_dispatch_##P(want, ray, cyl, opts[k], b);                               \
                TEST_ASSERT_EQUAL_INT_MESSAGE(rb, ra, family);                                  \
                TEST_ASSERT_EQUAL_MEMORY_MESSAGE(b, a, sizeof a, family);                       \
                hits += want > 0 && ra > 0;                                                     \
            }                                                                                   \
        return hits;                                                                            \
    }
SAME_BITS(f)
SAME_BITS(d)

static void test_dispatch_gives_the_same_bits_double(void)
{
    int fam, i, hits = 0;
    skip_without_dispatch();
    for (fam = 0; fam < BF_COUNT; fam++)
        for (i = 0; i < CASES_PER_FAMILY; i++) {
            bench_case c;
            cyld_ray ray;
            cyld_cylinder cyl;
            bench_case_gen(fam, 53, 20261205u, (uint64_t)i, &c);
            memcpy(ray.o, c.o, sizeof ray.o), memcpy(ray.d, c.d, sizeof ray.d);
            ray.tmin = c.tmin, ray.tmax = c.tmax;
            memcpy(cyl.c, c.c, sizeof cyl.c), memcpy(cyl.a, c.a, sizeof cyl.a);
            cyl.r = c.r, cyl.h = c.h;
            hits += same_bits_d(&ray, &cyl, bench_family_name(fam));
        }
    TEST_ASSERT_TRUE(hits > BF_COUNT * CASES_PER_FAMILY); /* the comparison saw hits */
}

static void test_dispatch_gives_the_same_bits_float(void)
{
    int fam, i, j, hits = 0;
    skip_without_dispatch();
    for (fam = 0; fam < BF_COUNT; fam++)
        for (i = 0; i < CASES_PER_FAMILY; i++) {
            bench_case c;
            cylf_ray ray;
            cylf_cylinder cyl;
            bench_case_gen(fam, 24, 20261205u, (uint64_t)i, &c); /* values exact in float */
            for (j = 0; j < 3; j++) {
                ray.o[j] = (float)c.o[j], ray.d[j] = (float)c.d[j];
                cyl.c[j] = (float)c.c[j], cyl.a[j] = (float)c.a[j];
            }
            ray.tmin = (float)c.tmin, ray.tmax = (float)c.tmax, cyl.r = (float)c.r, cyl.h = (float)c.h;
            hits += same_bits_f(&ray, &cyl, bench_family_name(fam));
        }
    TEST_ASSERT_TRUE(hits > BF_COUNT * CASES_PER_FAMILY);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_dispatch_gives_the_same_bits_double);
    RUN_TEST(test_dispatch_gives_the_same_bits_float);
    return UNITY_END();
}
