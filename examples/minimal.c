/* minimal.c: the README's usage snippet as a complete program.
 * One ray, one cylinder: print the hit's t (with its error bound), the point and the normal.
 *
 *   cc -std=c99 -I. examples/minimal.c -lm -o minimal && ./minimal
 */
#include <stdio.h>
#include "cylinder_isect.h"

int main(void)
{
    /* A ray along +x that passes the axis at height 0.25 and 0.5 to the side. */
    cylf_ray ray = {{-5.0f, 0.5f, 0.25f}, {1.0f, 0.0f, 0.0f}, 0.0f, 100.0f};
    /* Center at the origin, axis along z, radius 1, height 2 (it spans z in [-1, 1]). */
    cylf_cylinder cyl = {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, 1.0f, 2.0f};
    cylf_hit hit;
    float p[3];
    int i, rc = cylf_intersect(&ray, &cyl, CYL_CAPS, &hit);

    if (rc < 0) {
        fprintf(stderr, "error: %s\n", cyl_strerror(rc));
        return 1;
    }
    if (rc == CYL_MISS) {
        printf("miss\n");
        return 0;
    }
    for (i = 0; i < 3; i++) p[i] = ray.o[i] + hit.t * ray.d[i];
    printf("t      = %.7f +/- %.2g\n", (double)hit.t, (double)hit.t_err);
    printf("point  = (%.7f, %.7f, %.7f)\n", (double)p[0], (double)p[1], (double)p[2]);
    printf("normal = (%.7f, %.7f, %.7f)\n", (double)hit.n[0], (double)hit.n[1],
           (double)hit.n[2]);
    printf("part   = %s\n", hit.part == CYL_SIDE ? "side" : "cap");
    return 0;
}
