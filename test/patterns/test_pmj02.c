/* pmj02 and pmj02bn (bluenoise.h): every prefix of 2^m points is a (0,m,2)-net
 * (each elementary interval 2^-a x 2^-(m-a) holds exactly one point), the
 * sequence is progressive (K points are the first K of any longer draw),
 * draws are deterministic, and the best-candidate variant spreads its
 * points farther apart than the plain one. */
#include "mcspec/bluenoise.h"
#include "mcspec/pointset2d.h"
#include "mcspec/rng.h"
#include "unity.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define MAXK 16384
static double pts[2u * MAXK], other[2u * MAXK];
static unsigned char work[MCS_BLUENOISE_WORK_SIZE(2, MAXK)];
static unsigned char seen[MAXK];

static void draw(mcs_bluenoise_kind kind, size_t k, uint64_t seed, double *out)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, seed, 54u);
    size_t bytes = 0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_bluenoise_work_size(kind, 2u, k, &bytes));
    TEST_ASSERT_TRUE(bytes <= sizeof work);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_bluenoise_draw(kind, 2u, k, NULL, &rng, work, bytes, out));
}

/* The first 2^m points, for every shape a = 0..m: each cell of 2^a columns by
 * 2^(m-a) rows holds one point (brute force over the cells). Returns the
 * number of (m, a) shapes checked, or -1 on the first failure. */
static long net_shapes(const double *p, size_t k)
{
    long shapes = 0;
    for (unsigned m = 0; ((size_t)1u << m) <= k; ++m) {
        const size_t n = (size_t)1u << m;
        for (unsigned a = 0; a <= m; ++a) {
            memset(seen, 0, n);
            for (size_t j = 0; j < n; ++j) {
                const size_t cx = (size_t)ldexp(p[2u * j], (int)a);
                const size_t cy = (size_t)ldexp(p[2u * j + 1u], (int)(m - a));
                const size_t cell = cy * ((size_t)1u << a) + cx;
                if (cx >> a != 0u || cy >> (m - a) != 0u || seen[cell]++)
                    return -1;
            }
            ++shapes;
        }
    }
    return shapes;
}

static void every_prefix_is_a_net(mcs_bluenoise_kind kind, size_t k, unsigned seeds)
{
    for (unsigned s = 0; s < seeds; ++s) {
        draw(kind, k, 1000u + s, pts);
        for (size_t j = 0; j < 2u * k; ++j)
            TEST_ASSERT_TRUE(pts[j] >= 0.0 && pts[j] < 1.0);
        const long shapes = net_shapes(pts, k);
        TEST_ASSERT_TRUE_MESSAGE(shapes > 0, "an elementary interval holds two points");
    }
}

static void test_pmj02_prefixes_of_every_power_of_two_up_to_2_14_are_0_m_2_nets(void)
{
    every_prefix_is_a_net(MCS_BLUENOISE_PMJ02, 4096u, 24u);
    every_prefix_is_a_net(MCS_BLUENOISE_PMJ02, MAXK, 2u);
}

static void test_pmj02bn_prefixes_of_every_power_of_two_up_to_2_12_are_0_m_2_nets(void)
{
    every_prefix_is_a_net(MCS_BLUENOISE_PMJ02BN, 4096u, 4u);
}

/* The check itself fails on a set that is not a net: the points of a random
 * draw, and a pmj02 set with two points swapped in y. */
static void test_the_net_check_rejects_sets_that_are_not_nets(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 5u, 6u);
    for (size_t j = 0; j < 2u * 256u; ++j)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(&rng, &pts[j]));
    TEST_ASSERT_EQUAL_INT(-1, net_shapes(pts, 256u));
    draw(MCS_BLUENOISE_PMJ02, 256u, 3u, pts);
    TEST_ASSERT_EQUAL_INT(9 * 10 / 2, net_shapes(pts, 256u)); /* m = 0..8: 45 shapes */
    const double y = pts[2u * 3u + 1u];
    pts[2u * 3u + 1u] = pts[2u * 200u + 1u];
    pts[2u * 200u + 1u] = y;
    TEST_ASSERT_EQUAL_INT(-1, net_shapes(pts, 256u));
}

static void test_a_set_of_k_points_is_the_first_k_of_a_longer_draw(void)
{
    const mcs_bluenoise_kind kinds[2] = {MCS_BLUENOISE_PMJ02, MCS_BLUENOISE_PMJ02BN};
    for (int i = 0; i < 2; ++i) {
        draw(kinds[i], 1024u, 77u, pts);
        draw(kinds[i], 1000u, 77u, other);
        TEST_ASSERT_EQUAL_MEMORY(pts, other, 2u * 1000u * sizeof(double));
        draw(kinds[i], 3u, 77u, other);
        TEST_ASSERT_EQUAL_MEMORY(pts, other, 2u * 3u * sizeof(double));
    }
}

static void test_draws_are_deterministic_for_a_seed_and_differ_between_seeds(void)
{
    draw(MCS_BLUENOISE_PMJ02, 512u, 9u, pts);
    draw(MCS_BLUENOISE_PMJ02, 512u, 9u, other);
    TEST_ASSERT_EQUAL_MEMORY(pts, other, 2u * 512u * sizeof(double));
    draw(MCS_BLUENOISE_PMJ02, 512u, 10u, other);
    TEST_ASSERT_TRUE(memcmp(pts, other, 2u * 512u * sizeof(double)) != 0);
}

/* The one-point set and sets of 2 and 3 points: nets where they are powers of two. */
static void test_the_smallest_sets_are_nets(void)
{
    for (size_t k = 1; k <= 3u; ++k) {
        draw(MCS_BLUENOISE_PMJ02, k, 4u, pts);
        TEST_ASSERT_TRUE(net_shapes(pts, k) > 0);
    }
}

/* The average over the points of the distance to the nearest other point
 * (toroidal, brute force), per set: its mean over sets and standard error. */
static void avg_min_distance(mcs_bluenoise_kind kind, size_t k, unsigned sets, double *mean,
                             double *se)
{
    double sum = 0.0, sum2 = 0.0;
    for (unsigned s = 0; s < sets; ++s) {
        draw(kind, k, 300u + s, pts);
        double avg = 0.0;
        for (size_t i = 0; i < k; ++i) {
            double best = 1.0;
            for (size_t j = 0; j < k; ++j) {
                double d2 = 0.0;
                for (size_t c = 0; c < 2u && j != i; ++c) {
                    double d = fabs(pts[2u * i + c] - pts[2u * j + c]);
                    d = d > 0.5 ? 1.0 - d : d;
                    d2 += d * d;
                }
                best = j != i && d2 < best ? d2 : best;
            }
            avg += sqrt(best) / (double)k;
        }
        sum += avg;
        sum2 += avg * avg;
    }
    *mean = sum / sets;
    *se = sqrt((sum2 / sets - *mean * *mean) / (sets - 1u));
}

/* Best candidates push the points apart: the average nearest distance of
 * pmj02bn exceeds pmj02's by many standard errors (measured 0.639 against
 * 0.605 d_max at K = 64, about 10 standard errors over 200 sets). */
static void test_best_candidates_spread_the_points_farther_apart(void)
{
    double plain, plain_se, bn, bn_se;
    avg_min_distance(MCS_BLUENOISE_PMJ02, 64u, 200u, &plain, &plain_se);
    avg_min_distance(MCS_BLUENOISE_PMJ02BN, 64u, 200u, &bn, &bn_se);
    const double z = (bn - plain) / sqrt(plain_se * plain_se + bn_se * bn_se);
    TEST_ASSERT_TRUE_MESSAGE(z > 5.0, "pmj02bn no farther apart than pmj02");
}

/* A (0,m,2)-net's periodogram is far below random points' 1 at the lowest
 * frequencies (measured 0.0002, 0.002, 0.01 in the annuli 1, 2, 4 at
 * K = 1024): asserted below 0.1 by more than 10 standard errors in the
 * annuli 1..3 over 20 sets of 256 points, for both kinds. */
static void test_the_periodogram_is_far_below_one_at_low_frequency(void)
{
    static unsigned char mem[MCS_POINTSET2D_SIZE_DIRECT(4)];
    const mcs_bluenoise_kind kinds[2] = {MCS_BLUENOISE_PMJ02, MCS_BLUENOISE_PMJ02BN};
    for (int i = 0; i < 2; ++i) {
        mcs_pointset2d acc;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&acc, 4u, MCS_POINTSET_DIRECT_ONLY, mem,
                                                          sizeof mem));
        for (unsigned s = 0; s < 20u; ++s) {
            draw(kinds[i], 256u, 60u + s, pts);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc, 256u, pts));
        }
        for (size_t r = 1; r <= 3u; ++r) {
            double mean = 0.0, se = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial(&acc, r, &mean));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial_stderr(&acc, r, &se));
            TEST_ASSERT_TRUE_MESSAGE(0.1 - mean > 10.0 * se, "low-frequency power not far below 1");
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_pmj02_prefixes_of_every_power_of_two_up_to_2_14_are_0_m_2_nets);
    RUN_TEST(test_pmj02bn_prefixes_of_every_power_of_two_up_to_2_12_are_0_m_2_nets);
    RUN_TEST(test_the_net_check_rejects_sets_that_are_not_nets);
    RUN_TEST(test_a_set_of_k_points_is_the_first_k_of_a_longer_draw);
    RUN_TEST(test_draws_are_deterministic_for_a_seed_and_differ_between_seeds);
    RUN_TEST(test_the_smallest_sets_are_nets);
    RUN_TEST(test_best_candidates_spread_the_points_farther_apart);
    RUN_TEST(test_the_periodogram_is_far_below_one_at_low_frequency);
    return UNITY_END();
}
