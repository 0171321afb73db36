/* test_fuzz_regressions.c: one named Unity test per fuzzer finding. Each replays its input from
 * fuzz/findings/ through every invariant of fuzz_check.h (the same checks as the fuzzer).
 *
 * A finding whose fix in cylinder_isect.h is still pending is marked OPEN: its test reports
 * Unity "Ignored" with the violated invariant instead of failing `make test` for everybody, and
 * says so loudly once it passes. When the fix lands: change OPEN to FIXED (a hard regression
 * test from then on) and copy the input into fuzz/corpus/ so the fuzzer starts from it.
 * docs/fuzzing.md lists the findings.
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"

static int open_issue;
static void regress_fail(const char *msg);
#define FZ_FAIL(msg) regress_fail(msg)
#include "fuzz_check.h"

#ifndef FUZZ_FINDINGS_DIR
#define FUZZ_FINDINGS_DIR "fuzz/findings"
#endif

#define OPEN 1
#define FIXED 0

void setUp(void) {}
void tearDown(void) {}

static void regress_fail(const char *msg)
{
  static char buf[2200];
  if (open_issue) {
    snprintf(buf, sizeof buf, "OPEN finding, fix pending in cylinder_isect.h: %s", msg);
    TEST_IGNORE_MESSAGE(buf);
  }
  TEST_FAIL_MESSAGE(msg);
}

static void replay_finding(const char *name, int status)
{
  static unsigned char buf[4096];
  char path[1024];
  size_t n;
  FILE *f;
  snprintf(path, sizeof path, "%s/%s", FUZZ_FINDINGS_DIR, name);
  f = fopen(path, "rb");
  if (!f) TEST_FAIL_MESSAGE(path);
  n = fread(buf, 1, sizeof buf, f);
  fclose(f);
  open_issue = status == OPEN;
  fz_one(buf, n);
  open_issue = 0;
  if (status == OPEN) printf("NOTE: open finding %s now passes: mark it FIXED and add it to fuzz/corpus/\n", name);
}

/* Finding 1. Unknown option bit together with an invalid input (d = 0): the library answers
 * CYL_E_OPTION, the contract's order says CYL_E_ZERO_DIR (option bits are checked last). */
static void test_option_error_checked_before_input_errors(void)
{
  replay_finding("option-error-checked-before-input-errors", OPEN);
}

/* Finding 2. Float, r = 2^-127 against |o - c| ~ 2^64: after the power-of-two prescale r^2 flushes
 * to zero, and a clear miss (rho = 2^60 r) comes back as two tangent hits whose ray-facing
 * normal has n.d > 0. */
static void test_float_tiny_radius_spurious_tangent(void)
{
  replay_finding("float-tiny-radius-spurious-tangent", OPEN);
}

/* Finding 3. Float, subnormal r = 2^-133 with h = 2: the ray crosses the axis (e = 1), the exact
 * hits are t = 4e-40 and 6e-40; float returns t = 0 and 5e-40, both flagged tangent. Same root
 * cause as finding 2 (r much smaller than the prescale length). */
static void test_float_subnormal_radius_spurious_tangent(void)
{
  replay_finding("float-subnormal-radius-spurious-tangent", OPEN);
}

/* Finding 4. Double, h = 2^-1050 (subnormal) seen from |o - c| = 2^127: h/2 underflows in the
 * scaled frame, and a ray whose wall crossings lie 2^700 half-heights off the band gets a wall
 * hit (v = -0) with n.d > 0. The exact answer (MPFR reference) is a miss. */
static void test_double_subnormal_height_spurious_wall_hit(void)
{
  replay_finding("double-subnormal-height-spurious-wall-hit", OPEN);
}

/* Finding 5. Float, origin 1.7e7 from a unit cylinder (ulp of t = 1 = r): the normal comes from
 * the rounded hit point o + t d, and the "ray-facing" normal of the entry hit is (0, 0, -1)
 * with d = (-1, -1, -1): n.d = +1, against the contract n.d <= 0. */
static void test_float_far_origin_normal_faces_away(void)
{
  replay_finding("float-far-origin-normal-faces-away", OPEN);
}

/* Finding 6. Float, o = 1.25 2^70 on the x axis, d = 2^101 x, r = 2^27: same rounded hit point as
 * finding 5, and the normal is not even unit: |n| = 0.729 (n = (0, -0.73, 0)); the exact
 * normals are (-1, 0, 0) and (1, 0, 0). */
static void test_float_far_ray_normal_not_unit(void)
{
  replay_finding("float-far-ray-normal-not-unit", OPEN);
}

/* Finding 7. Float, capped, a ray along the axis through a disk (h = 1680, |d| = 1.75 2^66): both
 * cap crossings round to the same t, and the entry is labelled CAP_LOW although the ray comes
 * from the high side (a.d < 0): parts (and normals) of entry and exit are swapped. */
static void test_float_thin_disk_caps_swapped_at_equal_t(void)
{
  replay_finding("float-thin-disk-caps-swapped-at-equal-t", OPEN);
}

/* Finding 7, double: h = 2^-68.8 disk, d = (0, 32, -2048) against an axis along +z: entry
 * reported on CAP_LOW at t = 2^-11, exit on CAP_HIGH at the same t; the ray enters through
 * CAP_HIGH. */
static void test_double_thin_disk_caps_swapped_at_equal_t(void)
{
  replay_finding("double-thin-disk-caps-swapped-at-equal-t", OPEN);
}

/* Finding 8. Float, capped: a CAP_HIGH hit reports v = 0x1.0488p-15 while h/2 = 0x1.0486ap-15: v is
 * computed from the hit point instead of being exactly +-h/2 as the contract says, and leaves
 * [-h/2, h/2]. */
static void test_float_cap_hit_v_above_half_height(void)
{
  replay_finding("float-cap-hit-v-above-half-height", OPEN);
}

/* Finding 9. Float, a hit whose exact t = -7.4e-46 lies below the smallest subnormal: the library
 * returns t = -2^-149 with t_err = 0. The bound leaves out the rounding of t itself (half a
 * subnormal ulp here), so the exact t is not in [t - t_err, t + t_err]. */
static void test_float_subnormal_t_zero_error_bound(void)
{
  replay_finding("float-subnormal-t-zero-error-bound", OPEN);
}

/* Finding 10 (fixed in cylinder_isect.h 7b10f29..07a8b34). Double, axis (2^-1030, 0, 1), a ray
 * through the axis: the default tier found both crossings (t = 606.8, 910.2, as the MPFR
 * reference), CYL_PRECISE found none. */
static void test_double_precise_tier_misses_with_subnormal_axis(void)
{
  replay_finding("double-precise-tier-misses-with-subnormal-axis", FIXED);
}

int main(void)
{
  UNITY_BEGIN();
  RUN_TEST(test_option_error_checked_before_input_errors);
  RUN_TEST(test_float_tiny_radius_spurious_tangent);
  RUN_TEST(test_float_subnormal_radius_spurious_tangent);
  RUN_TEST(test_double_subnormal_height_spurious_wall_hit);
  RUN_TEST(test_float_far_origin_normal_faces_away);
  RUN_TEST(test_float_far_ray_normal_not_unit);
  RUN_TEST(test_float_thin_disk_caps_swapped_at_equal_t);
  RUN_TEST(test_double_thin_disk_caps_swapped_at_equal_t);
  RUN_TEST(test_float_cap_hit_v_above_half_height);
  RUN_TEST(test_float_subnormal_t_zero_error_bound);
  RUN_TEST(test_double_precise_tier_misses_with_subnormal_axis);
  return UNITY_END();
}
