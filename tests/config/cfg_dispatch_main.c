/* CYL_FMA_DISPATCH: on x86-64 built without -mfma, the double API's CYL_PRECISE calls run a
 * copy of the body built for the FMA where the CPU has it. That copy must change the cost, not
 * the answers: its exact products are exact either way and it contracts nothing. This unit
 * (the header's default: the copy, where this CPU has the FMA) and cfg_dispatch_other.c
 * (CYL_FMA_DISPATCH 0) answer every case family of bench/cases.c, open and capped, with and
 * without CYL_OUTWARD and CYL_NO_TANGENT; every return value and hit must be the same bits. */
#include "cfg_dispatch.h"
#include "cases.h"

#include <string.h>

#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define CASES_PER_FAMILY 1500

static void test_dispatch_gives_the_same_bits(void)
{
    static const unsigned opts[] = {CYL_PRECISE, CYL_PRECISE | CYL_CAPS,
                                    CYL_PRECISE | CYL_CAPS | CYL_OUTWARD,
                                    CYL_PRECISE | CYL_NO_TANGENT};
    int fam, i, k, want, hits = 0;
#if !CYL_FMA_DISPATCH
    TEST_IGNORE_MESSAGE("CYL_FMA_DISPATCH is 0 here (not x86-64, or built with the FMA)");
#else
    if (!__builtin_cpu_supports("fma")) TEST_IGNORE_MESSAGE("this CPU has no FMA: nothing dispatched");
#endif
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
            for (k = 0; k < (int)(sizeof opts / sizeof opts[0]); k++)
                for (want = 1; want <= 2; want++) {
                    cyld_hit a[2], b[2];
                    int ra, rb;
                    memset(a, 0, sizeof a), memset(b, 0, sizeof b);
                    ra = want == 2 ? cyld_intersect_all(&ray, &cyl, opts[k], a)
                                   : cyld_intersect(&ray, &cyl, opts[k], a);
                    rb = no_dispatch_call(want, &ray, &cyl, opts[k], b);
                    TEST_ASSERT_EQUAL_INT_MESSAGE(rb, ra, bench_family_name(fam));
                    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(b, a, sizeof a, bench_family_name(fam));
                    hits += ra > 0;
                }
        }
    TEST_ASSERT_TRUE(hits > BF_COUNT * CASES_PER_FAMILY); /* the comparison saw hits */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_dispatch_gives_the_same_bits);
    return UNITY_END();
}
