/* Copies of the three objects over caller buffers (pointset_common.c): a
 * copy onto itself moves the object to the new buffer with its statistics
 * and settings, as a copy to another header would, and leaves the old
 * buffer free. */
#include "mcspec/pointset.h"
#include "mcspec/pointset2d.h"
#include "mcspec/rng.h"
#include "mcspec/spectrum2d.h"
#include "nufft_skip.h"
#include "unity.h"

#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define BUF 131072u
#define K 24u

static unsigned char old_mem[BUF], new_mem[BUF], ref_mem[BUF];
static double pts[2u * K];

/* Trial t's K points in 2D (or 2 K in 1D); the first coordinates are
 * exactly 1.0, which only wrap lets in. */
static void trial(unsigned t)
{
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 77u + t, 5u));
    for (size_t j = 0; j < 2u * K; ++j)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(&rng, &pts[j]));
    pts[0] = pts[1] = 1.0;
}

/* The old buffer overwritten: an object that still read it would change. */
static void scribble_old_buffer(void)
{
    memset(old_mem, 0xa5, sizeof old_mem);
}

static void test_a_pointset_copied_onto_itself_keeps_its_statistics_and_settings(void)
{
    static mcs_pointset acc, ref;
    const size_t fmax = 21u;
    size_t need = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_size(fmax, 0u, &need));
    TEST_ASSERT_TRUE(need + 3u <= BUF);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&acc, fmax, 0u, old_mem + 3u, BUF - 3u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_set_wrap(&acc, 1));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_set_path(&acc, MCS_TEST_LAST_PATH));
    for (unsigned t = 0; t < 3u; ++t) {
        trial(t);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc, 2u * K, pts));
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_copy(&ref, ref_mem, BUF, &acc));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_copy(&acc, new_mem + 5u, BUF - 5u, &acc));
    scribble_old_buffer();
    TEST_ASSERT_TRUE(acc.mem == (void *)(new_mem + 5u));
    TEST_ASSERT_EQUAL_INT(1, acc.wrap);
    TEST_ASSERT_EQUAL_INT(MCS_TEST_LAST_PATH, acc.path);
    trial(9u); /* a trial after the move: the wrap and the forced path still hold */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&acc, 2u * K, pts));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&ref, 2u * K, pts));
    uint64_t n = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_count(&acc, &n));
    TEST_ASSERT_EQUAL_UINT64(4u, n);
    for (long f = 0; f <= (long)fmax; ++f) {
        double a = 0.0, b = 1.0, sa = 0.0, sb = 1.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power(&acc, f, &a));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power(&ref, f, &b));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power_stderr(&acc, f, &sa));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power_stderr(&ref, f, &sb));
        TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
        TEST_ASSERT_EQUAL_MEMORY(&sb, &sa, sizeof sa);
    }
}

static void test_a_pointset2d_copied_onto_itself_keeps_its_statistics_and_settings(void)
{
    static mcs_pointset2d acc, ref;
    const size_t fmax = 5u;
    size_t need = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_size(fmax, 0u, &need));
    TEST_ASSERT_TRUE(need + 3u <= BUF);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&acc, fmax, 0u, old_mem + 3u, BUF - 3u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_set_wrap(&acc, 1));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_set_path(&acc, MCS_POINTSET_PATH_DIRECT));
    for (unsigned t = 0; t < 3u; ++t) {
        trial(t);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc, K, pts));
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_copy(&ref, ref_mem, BUF, &acc));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_copy(&acc, new_mem + 5u, BUF - 5u, &acc));
    scribble_old_buffer();
    TEST_ASSERT_TRUE(acc.mem == (void *)(new_mem + 5u));
    TEST_ASSERT_EQUAL_INT(1, acc.wrap);
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_DIRECT, acc.path);
    trial(9u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc, K, pts));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&ref, K, pts));
    uint64_t n = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_count(&acc, &n));
    TEST_ASSERT_EQUAL_UINT64(4u, n);
    for (long fy = -(long)fmax; fy <= (long)fmax; ++fy)
        for (long fx = -(long)fmax; fx <= (long)fmax; ++fx) {
            double a = 0.0, b = 1.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_power_stderr(&acc, fx, fy, &a));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_power_stderr(&ref, fx, fy, &b));
            TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
        }
    for (size_t r = 0; r <= fmax; ++r) {
        double a = 0.0, b = 1.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial(&acc, r, &a));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial(&ref, r, &b));
        TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
    }
}

static void test_a_spectrum2d_copied_onto_itself_keeps_its_statistics_and_wrap(void)
{
    static mcs_spectrum2d acc, ref;
    const size_t n1 = 7u, n2 = 6u;
    size_t need = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_size(n1, n2, &need));
    TEST_ASSERT_TRUE(need + 3u <= BUF);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_init(&acc, n1, n2, old_mem + 3u, BUF - 3u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_set_wrap(&acc, 1));
    for (unsigned t = 0; t < 3u; ++t) {
        trial(t);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points(&acc, K, pts, NULL));
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_copy(&ref, ref_mem, BUF, &acc));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_copy(&acc, new_mem + 5u, BUF - 5u, &acc));
    scribble_old_buffer();
    TEST_ASSERT_TRUE(acc.mem == (void *)(new_mem + 5u));
    TEST_ASSERT_EQUAL_INT(1, acc.wrap);
    trial(9u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points(&acc, K, pts, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points(&ref, K, pts, NULL));
    uint64_t n = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_count(&acc, &n));
    TEST_ASSERT_EQUAL_UINT64(4u, n);
    for (size_t k2 = 0; k2 < n2; ++k2)
        for (size_t k1 = 0; k1 < n1; ++k1) {
            double a[3] = {0.0, 0.0, 0.0}, b[3] = {1.0, 1.0, 1.0};
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_mean(&acc, k1, k2, &a[0], &a[1]));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_mean(&ref, k1, k2, &b[0], &b[1]));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_power_stderr(&acc, k1, k2, &a[2]));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_power_stderr(&ref, k1, k2, &b[2]));
            TEST_ASSERT_EQUAL_MEMORY(b, a, sizeof a);
        }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_pointset_copied_onto_itself_keeps_its_statistics_and_settings);
    RUN_TEST(test_a_pointset2d_copied_onto_itself_keeps_its_statistics_and_settings);
    RUN_TEST(test_a_spectrum2d_copied_onto_itself_keeps_its_statistics_and_wrap);
    return UNITY_END();
}
