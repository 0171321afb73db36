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

/* Finding 1. Unknown option bit together with an invalid input (d = 0): the library answered
 * CYL_E_OPTION, the contract's order says CYL_E_ZERO_DIR (option bits are checked last). */
static void test_option_error_checked_before_input_errors(void)
{
  replay_finding("option-error-checked-before-input-errors", OPEN);
}

/* Finding 2. Float, r = 2^-127 against |o - c| ~ 2^64: after the power-of-two prescale r (and r^2)
 * flush toward zero, and a clear miss (rho = 2^60 r) came back as two tangent hits whose
 * ray-facing normal has n.d > 0. */
static void test_float_tiny_radius_spurious_tangent(void)
{
  replay_finding("float-tiny-radius-spurious-tangent", OPEN);
}

/* Finding 3. Float, subnormal r = 2^-133 with h = 2 (a needle through the ray): the ray crosses
 * the axis (e = 1), the exact hits are t = 4e-40 and 6e-40; float returned t = 0 and 5e-40,
 * both flagged tangent. Same root cause as finding 2 (r underflows in the scaled frame). */
static void test_float_subnormal_radius_spurious_tangent(void)
{
  replay_finding("float-subnormal-radius-spurious-tangent", OPEN);
}

/* Finding 4. Float, origin 1.7e7 from a unit cylinder (ulp of t = 1 = r): the hit point o + t d
 * is not resolvable, the normal is computed from it, and the "ray-facing" normal of the entry
 * hit is (0, 0, -1) with d = (-1, -1, -1): n.d = +1, against the contract n.d <= 0. */
static void test_float_far_origin_normal_faces_away(void)
{
  replay_finding("float-far-origin-normal-faces-away", OPEN);
}

int main(void)
{
  UNITY_BEGIN();
  RUN_TEST(test_option_error_checked_before_input_errors);
  RUN_TEST(test_float_tiny_radius_spurious_tangent);
  RUN_TEST(test_float_subnormal_radius_spurious_tangent);
  RUN_TEST(test_float_far_origin_normal_faces_away);
  return UNITY_END();
}
