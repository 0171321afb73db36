/* test_examples.c: Unity runner for the examples (issue 5), run by `make test` from the
 * repository root.
 *  - examples/minimal prints the hit the geometry predicts;
 *  - every scene rendered headless matches its reference PNG in examples/ref/;
 *  - culling changes no pixel (against --no-cull);
 *  - float and double renders of a scene agree, and the error view finds no pixel where the
 *    float and double answers are farther apart than their two error bounds allow.
 * The paths of the programs come from the build (mk/examples.mk). */
#define _POSIX_C_SOURCE 200809L
#include "unity.h"
#include "png_io.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#ifndef VIEWER_BIN
#define VIEWER_BIN "build/examples/viewer"
#endif
#ifndef MINIMAL_BIN
#define MINIMAL_BIN "build/examples/minimal"
#endif
#ifndef OUT_DIR
#define OUT_DIR "build/examples/test"
#endif
#define SCENE_DIR "examples/scenes"
#define REF_DIR "examples/ref"
#define TEST_SIZE "160x120" /* the size of the reference renders */

/* A pixel differs when a channel is off by more than this many levels of 255: shading
   rounding may move by a level or two between compilers, a different hit moves it by far
   more. */
#define PIXEL_TOL_LEVELS 6
/* At most this fraction of pixels may differ from the reference: silhouette and rim pixels
   whose hit/miss decision lies within the library's tangent tolerance may flip between builds
   (0.3% of 160x120 is 57 pixels, about one silhouette edge's worth of flips). */
#define REF_MAX_BAD_FRACTION 0.003
/* Float and double renders of the same scene: only pixels on silhouettes, rims and shadow
   edges (where one rounding decides) may differ. */
#define PRECISION_MAX_BAD_FRACTION 0.01
/* Error view: pixels where the double path does not find the float hit's crossing (hit or miss
   decided within a rounding at rims and silhouettes), as a fraction of the hit pixels. */
#define UNCONFIRMED_MAX_FRACTION 0.01

void setUp(void) {}
void tearDown(void) {}

/* Runs a shell command; returns its exit status and its stdout (up to n-1 bytes) in out. */
static int run(const char *cmd, char *out, size_t n)
{
    FILE *p = popen(cmd, "r");
    size_t len = 0, got;
    if (!p) return -1;
    while (len + 1 < n && (got = fread(out + len, 1, n - 1 - len, p)) > 0) len += got;
    out[len] = 0;
    return pclose(p);
}

static void render(const char *scene, const char *extra, const char *png, char *out, size_t n)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s --headless --size %s %s --out %s %s/%s.txt 2>&1", VIEWER_BIN,
             TEST_SIZE, extra, png, SCENE_DIR, scene);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, run(cmd, out, n), out);
    TEST_ASSERT_NULL_MESSAGE(strstr(out, "returned an error"), out);
}

static double diff_fraction(const char *a_path, const char *b_path, int *max_diff)
{
    image a, b;
    long bad;
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, png_read_rgb(a_path, &a), a_path);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, png_read_rgb(b_path, &b), b_path);
    bad = image_count_diff(&a, &b, PIXEL_TOL_LEVELS, max_diff);
    free(a.rgb);
    free(b.rgb);
    TEST_ASSERT_TRUE_MESSAGE(bad >= 0, "image sizes differ");
    return (double)bad / ((double)a.w * (double)a.h);
}

static void check_scene_against_reference(const char *scene)
{
    char png[256], ref[256], out[1024], msg[512];
    int max_diff;
    double frac;
    snprintf(png, sizeof png, "%s/%s.png", OUT_DIR, scene);
    snprintf(ref, sizeof ref, "%s/%s.png", REF_DIR, scene);
    render(scene, "", png, out, sizeof out);
    frac = diff_fraction(png, ref, &max_diff);
    snprintf(msg, sizeof msg, "%s: %.4f of the pixels differ from %s (largest %d levels)",
             scene, frac, ref, max_diff);
    TEST_ASSERT_TRUE_MESSAGE(frac <= REF_MAX_BAD_FRACTION, msg);
}

static void check_float_matches_double(const char *scene)
{
    char f[256], d[256], out[1024], msg[512];
    int max_diff;
    double frac;
    snprintf(f, sizeof f, "%s/%s-float.png", OUT_DIR, scene);
    snprintf(d, sizeof d, "%s/%s-double.png", OUT_DIR, scene);
    render(scene, "", f, out, sizeof out);
    render(scene, "--double", d, out, sizeof out);
    frac = diff_fraction(f, d, &max_diff);
    snprintf(msg, sizeof msg, "%s: float and double renders differ on %.4f of the pixels",
             scene, frac);
    TEST_ASSERT_TRUE_MESSAGE(frac <= PRECISION_MAX_BAD_FRACTION, msg);
}

/* Culling (frustum grids and the tube pretest) only skips library calls that cannot hit: the
   image must be the one that testing every cylinder gives, to the last bit. */
static void check_culling_is_exact(const char *scene, const char *extra)
{
    char a[256], b[256], out[1024], opts[128], msg[512];
    int max_diff;
    double frac;
    snprintf(a, sizeof a, "%s/%s-culled.png", OUT_DIR, scene);
    snprintf(b, sizeof b, "%s/%s-unculled.png", OUT_DIR, scene);
    snprintf(opts, sizeof opts, "--no-cull %s", extra);
    render(scene, extra, a, out, sizeof out);
    render(scene, opts, b, out, sizeof out);
    frac = diff_fraction(a, b, &max_diff);
    snprintf(msg, sizeof msg, "%s %s: culled and unculled renders differ on %.4f of the pixels "
             "(largest %d levels)", scene, extra, frac, max_diff);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, max_diff, msg); /* exactness is the point */
}

/* The viewer's error view prints "N hits ... max R t_err, K over bound, U unconfirmed". */
static void check_error_bound(const char *scene, const char *extra)
{
    char png[256], out[1024], opts[128];
    const char *p;
    double max_ratio;
    long hits, over, unconfirmed;
    snprintf(png, sizeof png, "%s/%s-error.png", OUT_DIR, scene);
    snprintf(opts, sizeof opts, "--view error %s", extra);
    render(scene, opts, png, out, sizeof out);
    p = strstr(out, " hits | max ");
    TEST_ASSERT_NOT_NULL_MESSAGE(p, out);
    while (p > out && p[-1] != ' ') p--;
    TEST_ASSERT_EQUAL_INT_MESSAGE(4, sscanf(p, "%ld hits | max %lf t_err, %ld over bound, %ld "
                                               "unconfirmed", &hits, &max_ratio, &over,
                                            &unconfirmed), out);
    TEST_ASSERT_TRUE_MESSAGE(hits > 0, out);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, over, out);
    TEST_ASSERT_TRUE_MESSAGE(max_ratio <= 1.0, out);
    TEST_ASSERT_TRUE_MESSAGE((double)unconfirmed <= UNCONFIRMED_MAX_FRACTION * (double)hits, out);
}

static void test_minimal_prints_the_predicted_hit(void)
{
    /* Ray o = (-5, 0.5, 0.25), d = +x; cylinder r = 1 about the z axis: the wall is reached at
       x = -sqrt(1 - 0.5^2), i.e. t = 5 - sqrt(0.75), with the normal facing the ray. */
    const double s = sqrt(0.75), tol = 1e-6; /* a few float ulps of numbers near 1 to 5 */
    char out[1024];
    const char *p;
    double t, err, x, y, z, nx, ny, nz;
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, run(MINIMAL_BIN, out, sizeof out), out);
    TEST_ASSERT_NOT_NULL_MESSAGE(p = strstr(out, "t      ="), out);
    TEST_ASSERT_EQUAL_INT_MESSAGE(2, sscanf(p, "t = %lf +/- %lf", &t, &err), out);
    TEST_ASSERT_NOT_NULL_MESSAGE(p = strstr(out, "point  ="), out);
    TEST_ASSERT_EQUAL_INT_MESSAGE(3, sscanf(p, "point = (%lf, %lf, %lf)", &x, &y, &z), out);
    TEST_ASSERT_NOT_NULL_MESSAGE(p = strstr(out, "normal ="), out);
    TEST_ASSERT_EQUAL_INT_MESSAGE(3, sscanf(p, "normal = (%lf, %lf, %lf)", &nx, &ny, &nz), out);
    TEST_ASSERT_DOUBLE_WITHIN(tol, 5.0 - s, t);
    TEST_ASSERT_TRUE_MESSAGE(fabs(t - (5.0 - s)) <= err + tol, "t outside its printed bound");
    TEST_ASSERT_DOUBLE_WITHIN(tol, -s, x);
    TEST_ASSERT_DOUBLE_WITHIN(tol, 0.5, y);
    TEST_ASSERT_DOUBLE_WITHIN(tol, 0.25, z);
    TEST_ASSERT_DOUBLE_WITHIN(tol, -s, nx);
    TEST_ASSERT_DOUBLE_WITHIN(tol, 0.5, ny);
    TEST_ASSERT_DOUBLE_WITHIN(tol, 0.0, nz);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(out, "part   = side"), out);
}

static void test_molecule_matches_reference(void) { check_scene_against_reference("molecule"); }
static void test_pipes_matches_reference(void) { check_scene_against_reference("pipes"); }
static void test_tubes_matches_reference(void) { check_scene_against_reference("tubes"); }
static void test_molecule_float_matches_double(void) { check_float_matches_double("molecule"); }
static void test_pipes_float_matches_double(void) { check_float_matches_double("pipes"); }
static void test_tubes_float_matches_double(void) { check_float_matches_double("tubes"); }
static void test_molecule_error_within_bound(void) { check_error_bound("molecule", ""); }
static void test_pipes_error_within_bound(void) { check_error_bound("pipes", ""); }
static void test_tubes_error_within_bound(void) { check_error_bound("tubes", ""); }
static void test_pipes_capped_error_within_bound(void) { check_error_bound("pipes", "--caps capped"); }
static void test_molecule_culling_exact(void) { check_culling_is_exact("molecule", ""); }
static void test_pipes_culling_exact(void) { check_culling_is_exact("pipes", "--caps open"); }
static void test_tubes_culling_exact(void) { check_culling_is_exact("tubes", "--double"); }

int main(void)
{
    char out[64];
    snprintf(out, sizeof out, "mkdir -p %s", OUT_DIR);
    if (run(out, out, sizeof out)) return 1;
    UNITY_BEGIN();
    RUN_TEST(test_minimal_prints_the_predicted_hit);
    RUN_TEST(test_molecule_matches_reference);
    RUN_TEST(test_pipes_matches_reference);
    RUN_TEST(test_tubes_matches_reference);
    RUN_TEST(test_molecule_float_matches_double);
    RUN_TEST(test_pipes_float_matches_double);
    RUN_TEST(test_tubes_float_matches_double);
    RUN_TEST(test_molecule_error_within_bound);
    RUN_TEST(test_pipes_error_within_bound);
    RUN_TEST(test_tubes_error_within_bound);
    RUN_TEST(test_pipes_capped_error_within_bound);
    RUN_TEST(test_molecule_culling_exact);
    RUN_TEST(test_pipes_culling_exact);
    RUN_TEST(test_tubes_culling_exact);
    return UNITY_END();
}
