/* pngcmp: compares two PNG images pixel by pixel (used by scripts/viewer-check.sh).
 *
 *   pngcmp a.png b.png [tolerance_levels [max_fraction]]
 *
 * A pixel differs when one of its channels is off by more than tolerance_levels (default 0).
 * Exits 0 when at most max_fraction (default 0) of the pixels differ, 1 otherwise, 2 when a
 * file cannot be read or the sizes differ. */
#include "png_io.h"

int main(int argc, char **argv)
{
    image a, b;
    int tol = argc > 3 ? atoi(argv[3]) : 0, max_diff;
    double max_frac = argc > 4 ? atof(argv[4]) : 0.0, frac;
    long bad;
    if (argc < 3) {
        fprintf(stderr, "usage: pngcmp a.png b.png [tolerance_levels [max_fraction]]\n");
        return 2;
    }
    if (png_read_rgb(argv[1], &a) || png_read_rgb(argv[2], &b)) {
        fprintf(stderr, "pngcmp: cannot read %s or %s\n", argv[1], argv[2]);
        return 2;
    }
    bad = image_count_diff(&a, &b, tol, &max_diff);
    if (bad < 0) {
        fprintf(stderr, "pngcmp: sizes differ: %dx%d vs %dx%d\n", a.w, a.h, b.w, b.h);
        return 2;
    }
    frac = (double)bad / ((double)a.w * (double)a.h);
    printf("pngcmp: %ld of %dx%d pixels differ by more than %d levels (%.4f%%), largest %d\n",
           bad, a.w, a.h, tol, 100.0 * frac, max_diff);
    free(a.rgb);
    free(b.rgb);
    return frac <= max_frac ? 0 : 1;
}
