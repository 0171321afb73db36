/* test_readme.c: the README's usage snippet, compiled with the strict warnings and run.
 * mk/readme.mk extracts the snippet into build/readme/snippet.inc; its printf goes to a buffer
 * here, so the test can check what a reader of the README would see. */
#include <stdio.h>
#include <string.h>
#include "cylinder_isect.h"
#include "unity.h"

static char out[512];
#define printf(...) snprintf(out, sizeof out, __VA_ARGS__)
static void readme_snippet(void)
{
#include "snippet.inc"
}
#undef printf

void setUp(void) {}
void tearDown(void) {}

/* The snippet's ray enters the unit cylinder's wall at x = -sqrt(1 - 0.5^2): t = 5 - sqrt(0.75),
   whose correctly rounded double prints as 4.1339745962155616; the normal faces the ray. The
   whole line is the one README.md says the snippet prints (and the header's QUICK START). */
static void test_readme_snippet_prints_the_hit(void)
{
    out[0] = 0;
    readme_snippet();
    TEST_ASSERT_EQUAL_STRING("t = 4.1339745962155616 +- 1.6e-14, n = (-0.866025, 0.5, 0)\n", out);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_readme_snippet_prints_the_hit);
    return UNITY_END();
}
