// The header as C++: compiled by make cxx-compat with g++ and clang++ in C++11 and C++17,
// -Wall -Wextra -Werror and the project's strict set, in each precision configuration, then
// run: every entry point once, with answers known in closed form. Exit status 0 = all passed.
#include "cylinder_isect.h"
#include <cmath>
#include <cstdio>

namespace {

int failures = 0;

void check(bool ok, const char *what, int line)
{
    if (!ok) {
        std::printf("cxx_check.cpp:%d: FAIL: %s\n", line, what);
        ++failures;
    }
}
#define CHECK(c) check((c), #c, __LINE__)

// The scene is exact in binary and well conditioned: a few ulps; 2^-18 relative catches a
// wrong root or a wrong scale.
template <typename T> bool near(T x, T want)
{
    return std::fabs(x - want) <= (T(1) / T(262144)) * (T(1) + std::fabs(want));
}

#ifndef CYL_NO_FLOAT
void float_api()
{
    // Unit tube along z, h = 2; ray along +x from x = -5: wall at t = 4 and 6.
    cylf_ray ray = {{-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.0f, HUGE_VALF};
    cylf_cylinder cyl = {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, 1.0f, 2.0f};
    cylf_hit hit, hits[2];
    CHECK(cylf_intersect(&ray, &cyl, 0u, &hit) == CYL_HIT && near(hit.t, 4.0f));
    CHECK(near(hit.n[0], -1.0f) && hit.part == CYL_SIDE);
    CHECK(cylf_intersect_all(&ray, &cyl, CYL_OUTWARD, hits) == 2 && near(hits[1].t, 6.0f));
    CHECK(near(hits[1].n[0], 1.0f) && (hits[1].flags & CYL_F_INSIDE) != 0u);
    CHECK(cylf_occluded(&ray, &cyl, CYL_CAPS) == 1);
    const float p0[3] = {0.0f, 0.0f, -1.0f}, p1[3] = {0.0f, 0.0f, 1.0f};
    cylf_cylinder seg = cylf_from_segment(p0, p1, 1.0f);
    CHECK(cylf_intersect(&ray, &seg, CYL_CAPS | CYL_TRUSTED, &hit) == CYL_HIT && near(hit.t, 4.0f));
    CHECK(cylf_intersect(&ray, nullptr, 0u, &hit) == CYL_E_NULL);
#ifdef CYL_NO_PRECISE
    CHECK(cylf_intersect(&ray, &cyl, CYL_PRECISE, &hit) == CYL_E_OPTION);
#else
    CHECK(cylf_intersect(&ray, &cyl, CYL_PRECISE, &hit) == CYL_HIT && near(hit.t, 4.0f));
#endif
}
#endif

#ifndef CYL_NO_DOUBLE
void double_api()
{
    cyld_ray ray = {{-5.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, 0.0, HUGE_VAL};
    cyld_cylinder cyl = {{0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 1.0, 2.0};
    cyld_hit hit, hits[2];
    CHECK(cyld_intersect(&ray, &cyl, 0u, &hit) == CYL_HIT && near(hit.t, 4.0));
    CHECK(cyld_intersect_all(&ray, &cyl, 0u, hits) == 2 && near(hits[1].t, 6.0));
    CHECK(cyld_occluded(&ray, &cyl, 0u) == 1);
    const double p0[3] = {0.0, 0.0, -1.0}, p1[3] = {0.0, 0.0, 1.0};
    cyld_cylinder seg = cyld_from_segment(p0, p1, 1.0);
    CHECK(cyld_intersect(&ray, &seg, CYL_CAPS, &hit) == CYL_HIT && near(hit.t, 4.0));
    cyl.r = -1.0;
    CHECK(cyld_intersect(&ray, &cyl, 0u, &hit) == CYL_E_RADIUS);
}
#endif

} // namespace

int main()
{
#ifndef CYL_NO_FLOAT
    float_api();
#endif
#ifndef CYL_NO_DOUBLE
    double_api();
#endif
    CHECK(cyl_strerror(CYL_E_OPTION) != nullptr);
    std::printf("%s\n", failures == 0 ? "cxx_check: OK" : "cxx_check: FAILED");
    return failures == 0 ? 0 : 1;
}
