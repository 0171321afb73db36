/* Contract tests, the t range [tmin, tmax]. Both ends inclusive to the ulp, hits behind the
 * origin, a t too large to represent, and the three entry points agreeing on sorted hits and on
 * what a moved tmin leaves.
 *
 * Written once for both precisions (see contract.h). make test runs it inside tests/test_float.c
 * and tests/test_double.c; alone: make test-one T=t_range CFG=gcc-O0 (tests/README.md).
 */
#include "contract.h"

/* A hit whose t is not representable (|d| so small that t overflows) is a miss, not an inf. */
static void test_unrepresentable_t_is_a_miss(void)
{
    Ray ray = mk_ray(-3, 0, 0, T_LDEXP(1, -T_MAX_EXP), 0, 0); /* t = 2^(MAX_EXP+1) > T_MAX */
    Cyl cyl = z_cyl(2);
    Hit h, h0, hs[2];
    sentinel(&h, 1);
    h0 = h;
    EQ_INT(CYL_MISS, CYL(intersect)(&ray, &cyl, 0, &h), "t overflows: miss");
    CHECK(memcmp(&h, &h0, sizeof h) == 0, "miss leaves *hit untouched");
    EQ_INT(0, CYL(intersect_all)(&ray, &cyl, 0, hs), "t overflows: no hits");
    EQ_INT(0, CYL(occluded)(&ray, &cyl, 0), "t overflows: not occluded");
    /* 8 times larger d: t = 2^(MAX_EXP-2), representable and exact */
    ray.d[0] = T_LDEXP(1, 3 - T_MAX_EXP);
    sentinel(&h, 1);
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, 0, &h), "t near the top of the range");
    EXACT(T_LDEXP(1, T_MAX_EXP - 2), h.t, "t = 2 / 2^(3-MAX_EXP), a power of two");
}

/* ================================================================== tmin / tmax */
static void test_tmin_tmax_boundaries(void)
{
    Ray ray = mk_ray(-3, 0, 0, 1, 0, 0); /* hits at t = 2 and 4, exact */
    Cyl cyl = z_cyl(2);
    Hit h, hs[2];

    ray.tmin = 2;
    sentinel(&h, 1);
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, 0, &h), "hit exactly at tmin");
    HIT_EXACT(&h, 2, CYL_SIDE, 0u, "t = tmin is included");

    ray.tmin = T_NEXT(L(2), L(3));
    sentinel(&h, 1);
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, 0, &h), "tmin one ulp past the entry");
    HIT_EXACT(&h, 4, CYL_SIDE, CYL_F_INSIDE, "entry excluded, the exit is next");

    ray.tmin = 0;
    ray.tmax = 2;
    sentinel(&h, 1);
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, 0, &h), "hit exactly at tmax");
    HIT_EXACT(&h, 2, CYL_SIDE, 0u, "t = tmax is included");
    sentinel(hs, 2);
    EQ_INT(1, CYL(intersect_all)(&ray, &cyl, 0, hs), "tmax = 2 keeps only the entry");

    ray.tmax = T_NEXT(L(2), L(0));
    sentinel(&h, 1);
    {
        Hit before = h;
        EQ_INT(CYL_MISS, CYL(intersect)(&ray, &cyl, 0, &h), "tmax one ulp before the entry");
        CHECK(memcmp(&before, &h, sizeof h) == 0, "miss leaves *hit untouched");
    }
    EQ_INT(0, CYL(occluded)(&ray, &cyl, 0), "occluded: tmax one ulp short");

    ray.tmin = 2;
    ray.tmax = 2;
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, 0, &h), "tmin = tmax = t is a hit");
    ray.tmin = 3;
    ray.tmax = 3;
    EQ_INT(CYL_MISS, CYL(intersect)(&ray, &cyl, 0, &h), "tmin = tmax between hits: miss");

    ray.tmin = 2;
    ray.tmax = 4;
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, 0, hs), "[2, 4] holds both hits");
    ray.tmax = T_NEXT(L(4), L(0));
    EQ_INT(1, CYL(intersect_all)(&ray, &cyl, 0, hs), "tmax one ulp short of the exit");
    ray.tmin = T_NEXT(L(4), L(5));
    ray.tmax = T_INF;
    EQ_INT(0, CYL(intersect_all)(&ray, &cyl, 0, hs), "tmin one ulp past the exit");

    /* Hits behind the origin are found with a negative range; intersect gives the first. */
    ray = mk_ray(3, 0, 0, 1, 0, 0); /* hits at t = -4 and -2 */
    EQ_INT(CYL_MISS, CYL(intersect)(&ray, &cyl, 0, &h), "both hits behind: miss for t >= 0");
    ray.tmin = -T_INF;
    sentinel(hs, 2);
    EQ_INT(2, CYL(intersect_all)(&ray, &cyl, 0, hs), "tmin = -inf: both hits");
    HIT_EXACT(&hs[0], -4, CYL_SIDE, 0u, "sorted: t = -4 first");
    HIT_EXACT(&hs[1], -2, CYL_SIDE, CYL_F_INSIDE, "then t = -2");
    sentinel(&h, 1);
    EQ_INT(CYL_HIT, CYL(intersect)(&ray, &cyl, 0, &h), "intersect with tmin = -inf");
    HIT_EXACT(&h, -4, CYL_SIDE, 0u, "intersect returns the first hit in range");
}

/* ================================================================== consistency */
static void test_all_sorted_consistent_with_intersect_and_occluded(void)
{
    size_t i, k;
    char m[160];
    for (i = 0; i < N_SCENES; i++) {
        for (k = 0; k < N_OPT_SETS; k++) {
            Ray ray;
            Cyl cyl;
            Hit h, hs[2];
            unsigned opts = opt_sets[k];
            int n, rc, occ;
            scene_get(&scenes[i], &ray, &cyl);
            sentinel(&h, 1);
            sentinel(hs, 2);
            n = rt_intersect_all(&ray, &cyl, opts, hs);
            rc = rt_intersect(&ray, &cyl, opts, &h);
            occ = rt_occluded(&ray, &cyl, opts);
            snprintf(m, sizeof m, "%s, opts 0x%x", scenes[i].name, opts);
            CHECK(n >= 0 && n <= 2, m);
            EQ_INT(n > 0 ? CYL_HIT : CYL_MISS, rc, m);
            EQ_INT(n > 0 ? 1 : 0, occ, m);
            if (n > 0) SAME_HIT(&hs[0], &h, 1, m); /* the same hit: bitwise the same answer */
            if (n == 2) {
                CHECK(hs[0].t <= hs[1].t, "intersect_all sorted by t");
                /* tmin midway between the hits (far from both decisions): intersect returns
                 * the second hit, and intersect_all only that one */
                ray.tmin = hs[0].t + (hs[1].t - hs[0].t) / 2;
                if (hs[0].t < ray.tmin && ray.tmin < hs[1].t) {
                    Hit hs2[2];
                    sentinel(&h, 1);
                    sentinel(hs2, 2);
                    EQ_INT(CYL_HIT, rt_intersect(&ray, &cyl, opts, &h), m);
                    SAME_HIT(&hs[1], &h, 0, m);
                    EQ_INT(1, rt_intersect_all(&ray, &cyl, opts, hs2), m);
                    SAME_HIT(&hs[1], &hs2[0], 1, m);
                }
                /* tmin one ulp past the first hit is a decision within rounding of its
                 * boundary: either answer is allowed, but intersect and intersect_all must
                 * agree and stay in [tmin, tmax] */
                ray.tmin = T_NEXT(hs[0].t, T_INF);
                {
                    Hit hs2[2];
                    int n2;
                    sentinel(&h, 1);
                    sentinel(hs2, 2);
                    n2 = rt_intersect_all(&ray, &cyl, opts, hs2);
                    CHECK(n2 >= 1, "the second hit stays in range");
                    EQ_INT(CYL_HIT, rt_intersect(&ray, &cyl, opts, &h), m);
                    SAME_HIT(&hs2[0], &h, 1, m);
                    CHECK(h.t >= ray.tmin && h.t <= ray.tmax, "intersect: t within [tmin, tmax]");
                }
            }
        }
    }
}

/* Every test of this file, in order; the runner that includes it calls this. */
static void run_t_range(void)
{
    UnitySetTestFile(__FILE__); /* failures point into this file */
    RUN_TEST(test_tmin_tmax_boundaries);
    RUN_TEST(test_unrepresentable_t_is_a_miss);
    RUN_TEST(test_all_sorted_consistent_with_intersect_and_occluded);
}

#ifndef CONTRACT_ALL /* built alone, for one configuration: see tests/README.md */
int main(void)
{
    UNITY_BEGIN();
    run_t_range();
    return UNITY_END();
}
#endif
