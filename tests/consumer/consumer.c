/* consumer.c: a user's program built against an installed or embedded cylinder_isect (make
 * install-check, mk/install.mk): through pkg-config, CMake's find_package, add_subdirectory and
 * FetchContent. It prints the header's version and one hit; the check compares both. */
#include <stdio.h>
#include <cylinder_isect.h>

int main(void)
{
    /* A ray along +x at height 0.25, 0.5 to the side of the axis of a unit cylinder along z. */
    cylf_ray ray = {{-5.0f, 0.5f, 0.25f}, {1.0f, 0.0f, 0.0f}, 0.0f, 100.0f};
    cylf_cylinder cyl = {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, 1.0f, 2.0f};
    cylf_hit hit;
    int rc = cylf_intersect(&ray, &cyl, CYL_CAPS, &hit);

    printf("cylinder_isect %d.%d.%d\n", CYL_VERSION_MAJOR, CYL_VERSION_MINOR, CYL_VERSION_PATCH);
    if (rc != CYL_HIT) {
        printf("no hit: %s\n", rc < 0 ? cyl_strerror(rc) : "miss");
        return 1;
    }
    /* The wall at x = -sqrt(1 - 0.25): t = 5 - sqrt(0.75). */
    printf("hit %s t=%.6f\n", hit.part == CYL_SIDE ? "side" : "cap", (double)hit.t);
    return 0;
}
