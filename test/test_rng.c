#include "mcspec.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static void test_seed_42_54_gives_the_pcg32_reference_vector(void)
{
    static const uint32_t expected[8] = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u, 0x83d2f293u,
                                         0xbfa4784bu, 0xcbed606eu, 0xbfc6a3adu, 0x812fff6du};
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 42u, 54u));
    for (int i = 0; i < 8; ++i) {
        uint32_t v = 0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_u32(&rng, &v));
        TEST_ASSERT_EQUAL_HEX32(expected[i], v);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_seed_42_54_gives_the_pcg32_reference_vector);
    return UNITY_END();
}
