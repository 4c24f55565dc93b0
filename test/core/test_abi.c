/* mcs_abi_sizeof (abi.h): the size and alignment of every public struct as
 * the compiler of this test lays it out, which a binding relies on. */
#include "mcspec.h"
#include "unity.h"

#include <stdalign.h>

void setUp(void) {}
void tearDown(void) {}

#define CHECK(t, c)                                                          \
    do {                                                                     \
        size_t s = 0u, a = 0u;                                               \
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_abi_sizeof(t, &s, &a));            \
        TEST_ASSERT_EQUAL_UINT64((uint64_t)(sizeof(c)), (uint64_t)(s));         \
        TEST_ASSERT_EQUAL_UINT64((uint64_t)(alignof(c)), (uint64_t)(a));        \
    } while (0)

static void test_every_type_has_the_size_and_alignment_of_its_struct(void)
{
    CHECK(MCS_ABI_RNG, mcs_rng);
    CHECK(MCS_ABI_IMPORTANCE, mcs_importance);
    CHECK(MCS_ABI_PATTERN, mcs_pattern);
    CHECK(MCS_ABI_PATTERN2D, mcs_pattern2d);
    CHECK(MCS_ABI_SAMPLER, mcs_sampler);
    CHECK(MCS_ABI_WELFORD, mcs_welford);
    CHECK(MCS_ABI_DFT, mcs_dft);
    CHECK(MCS_ABI_SPECTRUM, mcs_spectrum);
    CHECK(MCS_ABI_MOMENT, mcs_moment);
    CHECK(MCS_ABI_AUTOCORR, mcs_autocorr);
    CHECK(MCS_ABI_POINTSET, mcs_pointset);
    CHECK(MCS_ABI_POINTSET2D, mcs_pointset2d);
    CHECK(MCS_ABI_SPECTRUM2D, mcs_spectrum2d);
    CHECK(MCS_ABI_THEORY, mcs_theory);
    CHECK(MCS_ABI_THEORY_SPECTRUM, mcs_theory_spectrum);
    CHECK(MCS_ABI_DISCREPANCY, mcs_discrepancy);
    CHECK(MCS_ABI_SPACING, mcs_spacing);
    CHECK(MCS_ABI_PROVENANCE, mcs_io_provenance);
    CHECK(MCS_ABI_PCF, mcs_pcf);
    CHECK(MCS_ABI_INTEGRAND, mcs_integrand);
    CHECK(MCS_ABI_INTEGRATE, mcs_integrate);
    CHECK(MCS_ABI_PROJECTIONS, mcs_projections);
    CHECK(MCS_ABI_PROJECTIONS_PAIR, mcs_projections_pair);
    CHECK(MCS_ABI_BLUENOISE_PARAMS, mcs_bluenoise_params);
}

static void test_an_unknown_type_or_no_output_is_refused_untouched(void)
{
    size_t s = 77u, a = 78u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_abi_sizeof(MCS_ABI_TYPE_COUNT, &s, &a));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_abi_sizeof((mcs_abi_type)-1, &s, &a));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_abi_sizeof(MCS_ABI_RNG, NULL, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_abi_sizeof(MCS_ABI_RNG, &s, &s));
    TEST_ASSERT_EQUAL_UINT64((uint64_t)(77u), (uint64_t)(s));
    TEST_ASSERT_EQUAL_UINT64((uint64_t)(78u), (uint64_t)(a));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_abi_sizeof(MCS_ABI_RNG, NULL, &a));
    TEST_ASSERT_EQUAL_UINT64((uint64_t)(alignof(mcs_rng)), (uint64_t)(a));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_type_has_the_size_and_alignment_of_its_struct);
    RUN_TEST(test_an_unknown_type_or_no_output_is_refused_untouched);
    return UNITY_END();
}
