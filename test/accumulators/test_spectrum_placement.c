/* Where an accumulator lies in memory changes its speed (the arrays' cache-line
 * alignment: include/mcspec/dft.h), never its numbers: the same trials into
 * objects at two alignments give the same bits on every path. */
#include "mcspec.h"
#include "unity.h"

#include <string.h>

void setUp(void) {}
void tearDown(void) {}

static _Alignas(64) unsigned char place_a[sizeof(mcs_spectrum) + 64];
static _Alignas(64) unsigned char place_b[sizeof(mcs_spectrum) + 64];
static size_t bins[64];
static double weights[64];

static void fill(mcs_spectrum *acc, size_t n, mcs_spectrum_path path)
{
    mcs_pattern pat;
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_RANDOM, n, 37u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 3u, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(acc, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_path(acc, path));
    for (int i = 0; i < 600; ++i) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &rng, 37u, bins, weights, NULL));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(acc, 37u, bins, weights));
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_flush(acc));
}

static void test_every_path_gives_the_same_bits_at_a_16_and_a_64_byte_boundary(void)
{
    static const size_t ns[] = {4093u, 1024u, 64u};
    static const mcs_spectrum_path paths[] = {MCS_SPECTRUM_PATH_PAIR, MCS_SPECTRUM_PATH_SPARSE,
                                              MCS_SPECTRUM_PATH_FFT};
    /* 16 past a 64-byte boundary: the arrays at 16 mod 32, the slow place. */
    mcs_spectrum *a = (mcs_spectrum *)(void *)(place_a + 16), *b = (mcs_spectrum *)(void *)place_b;
    for (size_t i = 0; i < 3u; ++i)
        for (size_t p = 0; p < 3u; ++p) {
            fill(a, ns[i], paths[p]);
            fill(b, ns[i], paths[p]);
            for (size_t f = 0; f <= ns[i] / 2u; ++f) {
                double va, vb, ea, eb;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(a, f, &va));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(b, f, &vb));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(a, f, &ea));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(b, f, &eb));
                TEST_ASSERT_EQUAL_MEMORY(&vb, &va, sizeof va);
                TEST_ASSERT_EQUAL_MEMORY(&eb, &ea, sizeof ea);
            }
        }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_path_gives_the_same_bits_at_a_16_and_a_64_byte_boundary);
    return UNITY_END();
}
