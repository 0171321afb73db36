/* test_readme.c: the README's usage snippet, compiled with the strict warnings and run.
 * mk/readme.mk extracts it (scripts/sync-readme.py --snippet) into build/readme/snippet.inc as
 * readme_snippet(), with readme_prints: the line README.md says it prints. The snippet's printf
 * goes to a buffer here, so the test checks what a reader of the README would see. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "cylinder_isect.h"
#include "unity.h"

static char out[512];
#define printf(...) snprintf(out, sizeof out, __VA_ARGS__)
#include "snippet.inc"
#undef printf

void setUp(void) { out[0] = 0; }
void tearDown(void) {}

/* The snippet's ray o = (-5, 0.5, 0.25), d = (1, 0, 0) enters the unit cylinder's wall at
   x = -sqrt(1 - 0.5^2): t = 5 - sqrt(0.75), inside the caps (z = 0.25, h/2 = 1). The printed t
   (%.17g, which round-trips a double) must be the double nearest that, the printed bound must
   contain it and be tight, and the normal (-sqrt(0.75), 0.5, 0) faces the ray. */
static void test_readme_snippet_finds_the_exact_hit(void)
{
    double t, t_err, n[3];
    long double exact = 5.0L - sqrtl(0.75L);
    readme_snippet();
    TEST_ASSERT_EQUAL_INT(5, sscanf(out, "t = %lf +- %lf, n = (%lf, %lf, %lf)", &t, &t_err,
                                    &n[0], &n[1], &n[2]));
    TEST_ASSERT_TRUE(fabsl((long double)t - exact) <= fabsl((long double)nextafter(t, 0.0) - exact));
    TEST_ASSERT_TRUE(fabsl((long double)t - exact) <= fabsl((long double)nextafter(t, 10.0) - exact));
    TEST_ASSERT_TRUE(fabsl((long double)t - exact) <= (long double)t_err && t_err < 1e-12);
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, -sqrt(0.75), n[0]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, 0.5, n[1]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, 0.0, n[2]);
}

#if CYL_VERSION_MAJOR >= 2
/* The line with its bound ("+- X") cut out: v2 prints v1's t and n, and a bound of its own. */
static void without_bound(const char *line, char *cut, size_t size)
{
    const char *pm = strstr(line, " +- "), *n = pm ? strstr(pm, ", n = ") : NULL;
    TEST_ASSERT_NOT_NULL_MESSAGE(n, line);
    snprintf(cut, size, "%.*s%s", (int)(pm - line), line, n);
}
#endif

/* README.md states the snippet's output in the line after it: that line must be what it prints.
   It quotes the product header (v1) until v2 replaces it; v2 (make test V=2) must print the same
   t and n, its bound being checked by the test above. */
static void test_readme_states_what_the_snippet_prints(void)
{
    readme_snippet();
#if CYL_VERSION_MAJOR >= 2
    {
        char want[256], got[256];
        without_bound(readme_prints, want, sizeof want);
        without_bound(out, got, sizeof got);
        TEST_ASSERT_EQUAL_STRING(want, got);
    }
#else
    TEST_ASSERT_EQUAL_STRING(readme_prints, out);
#endif
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_readme_snippet_finds_the_exact_hit);
    RUN_TEST(test_readme_states_what_the_snippet_prints);
    return UNITY_END();
}
