/* Precision-independent facts of the cylinder_isect.h API: return codes, option and flag bits,
 * parts, and cyl_strerror. */
#include <limits.h>
#include <string.h>

#include "unity.h"
#include "cylinder_isect.h"

void setUp(void) {}
void tearDown(void) {}

static const int all_codes[] = {CYL_HIT,         CYL_MISS,        CYL_E_NULL,
                                CYL_E_NONFINITE, CYL_E_ZERO_DIR,  CYL_E_ZERO_AXIS,
                                CYL_E_RADIUS,    CYL_E_HEIGHT,    CYL_E_TRANGE,
                                CYL_E_OPTION};
#define N_CODES (sizeof all_codes / sizeof all_codes[0])

static void test_return_code_values(void)
{
    /* The documented values: callers store and compare them, so they are part of the ABI. */
    TEST_ASSERT_EQUAL_INT(1, CYL_HIT);
    TEST_ASSERT_EQUAL_INT(0, CYL_MISS);
    TEST_ASSERT_EQUAL_INT(-1, CYL_E_NULL);
    TEST_ASSERT_EQUAL_INT(-2, CYL_E_NONFINITE);
    TEST_ASSERT_EQUAL_INT(-3, CYL_E_ZERO_DIR);
    TEST_ASSERT_EQUAL_INT(-4, CYL_E_ZERO_AXIS);
    TEST_ASSERT_EQUAL_INT(-5, CYL_E_RADIUS);
    TEST_ASSERT_EQUAL_INT(-6, CYL_E_HEIGHT);
    TEST_ASSERT_EQUAL_INT(-7, CYL_E_TRANGE);
    TEST_ASSERT_EQUAL_INT(-8, CYL_E_OPTION);
}

static void test_option_flag_part_values(void)
{
    TEST_ASSERT_EQUAL_HEX32(0x01u, CYL_CAPS);
    TEST_ASSERT_EQUAL_HEX32(0x02u, CYL_OUTWARD);
    TEST_ASSERT_EQUAL_HEX32(0x04u, CYL_NO_TANGENT);
    TEST_ASSERT_EQUAL_HEX32(0x08u, CYL_PRECISE);
    TEST_ASSERT_EQUAL_HEX32(0x10u, CYL_NO_NORMAL);
    TEST_ASSERT_EQUAL_HEX32(0x20u, CYL_NO_ERRBOUND);
    TEST_ASSERT_EQUAL_HEX32(0x40u, CYL_TRUSTED);
    TEST_ASSERT_EQUAL_HEX32(CYL_CAPS | CYL_OUTWARD | CYL_NO_TANGENT | CYL_PRECISE | CYL_NO_NORMAL |
                                CYL_NO_ERRBOUND | CYL_TRUSTED,
                            CYL_OPTIONS_ALL);
    TEST_ASSERT_EQUAL_INT(0, CYL_SIDE);
    TEST_ASSERT_EQUAL_INT(1, CYL_CAP_LOW);
    TEST_ASSERT_EQUAL_INT(2, CYL_CAP_HIGH);
    TEST_ASSERT_EQUAL_HEX32(1u, CYL_F_INSIDE);
    TEST_ASSERT_EQUAL_HEX32(2u, CYL_F_TANGENT);
    TEST_ASSERT_EQUAL_HEX32(4u, CYL_F_PARALLEL);
}

static void test_strerror_distinct_nonempty(void)
{
    size_t i, j;
    for (i = 0; i < N_CODES; i++) {
        const char *s = cyl_strerror(all_codes[i]);
        TEST_ASSERT_NOT_NULL(s);
        TEST_ASSERT_TRUE_MESSAGE(s[0] != '\0', "empty message");
        for (j = 0; j < i; j++)
            TEST_ASSERT_TRUE_MESSAGE(strcmp(s, cyl_strerror(all_codes[j])) != 0,
                                     "two codes share a message");
    }
}

static void test_strerror_unknown_codes(void)
{
    static const int unknown[] = {2, 42, -9, -100, INT_MAX, INT_MIN};
    size_t i, j;
    for (i = 0; i < sizeof unknown / sizeof unknown[0]; i++) {
        const char *s = cyl_strerror(unknown[i]);
        TEST_ASSERT_NOT_NULL(s);
        TEST_ASSERT_TRUE_MESSAGE(s[0] != '\0', "empty message for an unknown code");
        /* an unknown code must not masquerade as a known one */
        for (j = 0; j < N_CODES; j++)
            TEST_ASSERT_TRUE_MESSAGE(strcmp(s, cyl_strerror(all_codes[j])) != 0,
                                     "unknown code described as a known one");
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_return_code_values);
    RUN_TEST(test_option_flag_part_values);
    RUN_TEST(test_strerror_distinct_nonempty);
    RUN_TEST(test_strerror_unknown_codes);
    return UNITY_END();
}
