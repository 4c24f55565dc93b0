#include "mcspec.h"
#include "spectra_ref.h"
#include "unity.h"

#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

static mcs_importance imp; /* large: keep off the stack */
static mcs_importance imp_copy;

static void test_weights_are_normalised_into_g_p_cdf_and_harmonic_mean(void)
{
    const double w[4] = {2.0, 4.0, 6.0, 8.0}; /* any scale: g = .1 .2 .3 .4 */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 4u, w));
    TEST_ASSERT_EQUAL_UINT(4u, imp.n);
    const double g[4] = {0.1, 0.2, 0.3, 0.4};
    double sum_inv_p = 0.0;
    for (int b = 0; b < 4; ++b) {
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, g[b], imp.g[b]);
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, 4.0 * g[b], imp.p[b]);
        sum_inv_p += 1.0 / (4.0 * g[b]);
    }
    TEST_ASSERT_EQUAL_DOUBLE(0.0, imp.cdf[0]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.3, imp.cdf[2]);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, imp.cdf[4]);
    /* eq. 44: H = N / sum 1/p_n, here 4 / (2.5 + 1.25 + 5/6 + 0.625). */
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, 4.0 / sum_inv_p, imp.harmonic_mean);
    TEST_ASSERT_TRUE(imp.harmonic_mean < 1.0);
}

static void test_uniform_weights_give_unit_density_and_h_equal_one(void)
{
    double w[37];
    for (int b = 0; b < 37; ++b)
        w[b] = 3.5;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 37u, w));
    for (int b = 0; b < 37; ++b)
        TEST_ASSERT_DOUBLE_WITHIN(1e-14, 1.0, imp.p[b]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, 1.0, imp.harmonic_mean);
}

static void test_warp_maps_each_cdf_interval_linearly_onto_its_bin(void)
{
    const double w[4] = {1.0, 2.0, 3.0, 4.0};
    mcs_importance_init(&imp, 4u, w);
    double x = -1.0;
    size_t bin = 99u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_warp(&imp, 0.0, &x, &bin));
    TEST_ASSERT_EQUAL_UINT(0u, bin);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, x);
    /* u = 0.45 is halfway through I_2 = [0.3, 0.6): x = (2 + 0.5)/4. */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_warp(&imp, 0.45, &x, &bin));
    TEST_ASSERT_EQUAL_UINT(2u, bin);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, 0.625, x);
    /* Bin edges belong to the bin above them. */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_warp(&imp, imp.cdf[3], &x, &bin));
    TEST_ASSERT_EQUAL_UINT(3u, bin);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_warp(&imp, nextafter(1.0, 0.0), &x, &bin));
    TEST_ASSERT_EQUAL_UINT(3u, bin);
    TEST_ASSERT_TRUE(x < 1.0);
}

static void test_warp_is_monotone_and_keeps_points_in_their_bins(void)
{
    double w[50];
    for (int b = 0; b < 50; ++b)
        w[b] = 0.01 + (double)((b * 37) % 11);
    mcs_importance_init(&imp, 50u, w);
    double prev = -1.0;
    for (int i = 0; i < 20000; ++i) {
        double u = (double)i / 20000.0, x;
        size_t bin;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_warp(&imp, u, &x, &bin));
        TEST_ASSERT_TRUE(x >= prev);
        TEST_ASSERT_TRUE(x >= 0.0 && x < 1.0);
        TEST_ASSERT_EQUAL_UINT(bin, (size_t)floor(x * 50.0));
        TEST_ASSERT_TRUE(u >= imp.cdf[bin] && u < imp.cdf[bin + 1u]);
        prev = x;
    }
}

static void test_bad_weights_return_an_error_and_leave_the_struct_untouched(void)
{
    const double good[3] = {1.0, 2.0, 3.0};
    mcs_importance_init(&imp, 3u, good);
    memcpy(&imp_copy, &imp, sizeof imp);
    const double nan_w[3] = {1.0, NAN, 1.0};
    const double inf_w[3] = {1.0, INFINITY, 1.0};
    const double neg_w[3] = {1.0, -1.0, 3.0};
    const double zero_w[3] = {0.0, -0.0, 0.0}; /* nothing to sample */
    const double tiny_w[3] = {1e308, 0.3, 0.3};
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_importance_init(NULL, 3u, good));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_importance_init(&imp, 3u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_importance_init(&imp, 0u, good));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_importance_init(&imp, MCS_MAX_N + 1u, good));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_importance_init(&imp, 3u, nan_w));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_importance_init(&imp, 3u, inf_w));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NEGATIVE, mcs_importance_init(&imp, 3u, neg_w));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ZERO_WEIGHT, mcs_importance_init(&imp, 3u, zero_w));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ZERO_WEIGHT, mcs_importance_init(&imp, 3u, tiny_w));
    TEST_ASSERT_EQUAL_MEMORY(&imp_copy, &imp, sizeof imp);
}

static void test_bad_warp_input_returns_an_error_and_leaves_outputs_untouched(void)
{
    const double good[3] = {1.0, 2.0, 3.0};
    mcs_importance_init(&imp, 3u, good);
    double x = 7.0;
    size_t bin = 77u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_importance_warp(NULL, 0.5, &x, &bin));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_importance_warp(&imp, 1.0, &x, &bin));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_importance_warp(&imp, -0.25, &x, &bin));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_importance_warp(&imp, NAN, &x, &bin));
    memset(&imp_copy, 0, sizeof imp_copy);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_importance_warp(&imp_copy, 0.5, &x, &bin));
    TEST_ASSERT_EQUAL_DOUBLE(7.0, x);
    TEST_ASSERT_EQUAL_UINT(77u, bin);
    /* Either output may be omitted. */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_warp(&imp, 0.3, NULL, &bin));
    TEST_ASSERT_EQUAL_UINT(1u, bin);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_warp(&imp, 0.5, &x, NULL));
}

/* Q_k (eq. 43) is eq. 7 applied to 1/p: against an independent long-double
 * DFT for N with and without a fast factorisation, up to MCS_MAX_N; and
 * eq. 44, N^{-1/2} Q_0 = 1/H. */
static void test_q_is_the_eq7_transform_of_one_over_p_and_q0_gives_one_over_h(void)
{
    static const size_t sizes[] = {1u, 2u, 7u, 12u, 97u, 1000u, (size_t)MCS_MAX_N};
    static double w[MCS_MAX_N], inv_p[MCS_MAX_N], ref_re[MCS_MAX_N], ref_im[MCS_MAX_N];
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; ++i) {
        const size_t n = sizes[i];
        for (size_t b = 0; b < n; ++b)
            w[b] = 0.25 + (double)((b * 7u) % 11u) + (b == n / 3u ? 5.0 : 0.0);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, w));
        double scale = 0.0;
        for (size_t b = 0; b < n; ++b) {
            inv_p[b] = 1.0 / imp.p[b];
            scale += inv_p[b] * inv_p[b];
        }
        scale = sqrt(scale); /* |Q_k| <= sqrt(sum 1/p^2): rounding is relative to it */
        spectra_naive_dft(n, inv_p, n, ref_re, ref_im);
        const size_t step = n > 100u ? n / 37u : 1u;
        for (size_t k = 0; k < n; k += step) {
            double re = 0.0, im = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_q(&imp, k, &re, &im));
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * scale, ref_re[k], re);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * scale, ref_im[k], im);
        }
        double q0r, q0i;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_q(&imp, 0u, &q0r, &q0i));
        TEST_ASSERT_DOUBLE_WITHIN(1e-13 / imp.harmonic_mean, 1.0 / imp.harmonic_mean,
                                  q0r / sqrt((double)n));
        TEST_ASSERT_EQUAL_DOUBLE(0.0, q0i);
    }
}

static void test_bad_q_input_returns_an_error_and_leaves_outputs_untouched(void)
{
    static mcs_importance zero; /* never initialised */
    const double w[4] = {1.0, 2.0, 3.0, 4.0};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 4u, w));
    memcpy(&imp_copy, &imp, sizeof imp);
    double re = 9.0, im = 9.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_importance_q(NULL, 0u, &re, &im));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_importance_q(&imp, 0u, NULL, &im));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_importance_q(&imp, 0u, &re, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_importance_q(&zero, 0u, &re, &im));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_importance_q(&imp, 4u, &re, &im));
    TEST_ASSERT_EQUAL_DOUBLE(9.0, re);
    TEST_ASSERT_EQUAL_DOUBLE(9.0, im);
    TEST_ASSERT_EQUAL_MEMORY(&imp_copy, &imp, sizeof imp);
}

/* ---- issue 10 item 8 and issue 12: scale, tiny weights, the sampled CDF ---- */

/* Issue 10 item 8: any positive scale is accepted (all equal at DBL_MAX, mixed
 * near it, all subnormal); a weight too small next to the rest is refused
 * ({1e308, 0.3, 0.3} used to pass with H = 0, outside the documented (0, 1]). */
static void test_any_scale_is_accepted_and_a_negligible_weight_is_refused(void)
{
    const double all_max[3] = {1e308, 1e308, 1e308};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 3u, all_max));
    for (int b = 0; b < 3; ++b)
        TEST_ASSERT_EQUAL_DOUBLE(1.0, imp.p[b]);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, imp.harmonic_mean);
    const double near_max[3] = {1.7e308, 0.85e308, 1.7e308}; /* sum overflows unscaled */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 3u, near_max));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.2, imp.g[1]);
    const double sub[2] = {5e-324, 1e-323}; /* the two smallest subnormals: 1 : 2 */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 2u, sub));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 1.0 / 3.0, imp.g[0]);
    TEST_ASSERT_TRUE(imp.harmonic_mean > 0.0 && imp.harmonic_mean <= 1.0);

    memcpy(&imp_copy, &imp, sizeof imp);
    const double tiny[3] = {1e308, 0.3, 0.3};
    const double very_small[2] = {1.0, 1e-17}; /* issue 12: its bin was never drawn */
    const double small[2] = {1.0, 1e-12};
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ZERO_WEIGHT, mcs_importance_init(&imp, 3u, tiny));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ZERO_WEIGHT, mcs_importance_init(&imp, 2u, very_small));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ZERO_WEIGHT, mcs_importance_init(&imp, 2u, small));
    TEST_ASSERT_EQUAL_MEMORY(&imp_copy, &imp, sizeof imp);
    /* The threshold itself: g = w / (1 + w) against 2^-32. */
    const double at[2] = {1.0, 1.0001 * MCS_IMPORTANCE_MIN_G};
    const double below[2] = {1.0, 0.9999 * MCS_IMPORTANCE_MIN_G};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 2u, at));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ZERO_WEIGHT, mcs_importance_init(&imp, 2u, below));
}

/* Issue 23 item 4: g_n = 0 is the support condition of a renderer's
 * importance sampling. A weight of exactly 0 puts its bin outside the
 * support: g_n = p_n = 0 exactly, an empty CDF interval (its two entries
 * the same double, 1 past the last positive weight), never reached by the
 * warp, and left out of H and Q (1/p_n read as 0). Leading, consecutive
 * and trailing zeros, and -0.0. */
static void test_a_zero_weight_puts_its_bin_outside_the_support(void)
{
    const double w[9] = {0.0, 2.0, 0.0, -0.0, 1.0, 3.0, 0.0, 2.0, 0.0};
    const int in[9] = {0, 1, 0, 0, 1, 1, 0, 1, 0};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 9u, w));
    double inv = 0.0;
    for (size_t b = 0; b < 9u; ++b) {
        if (!in[b]) {
            TEST_ASSERT_TRUE(imp.g[b] == 0.0 && imp.p[b] == 0.0 && !signbit(imp.p[b]));
            TEST_ASSERT_TRUE(imp.cdf[b] == imp.cdf[b + 1u]);
        } else {
            TEST_ASSERT_DOUBLE_WITHIN(1e-15, w[b] / 8.0, imp.g[b]);
            TEST_ASSERT_EQUAL_DOUBLE(9.0 * imp.g[b], imp.p[b]);
            inv += 1.0 / imp.p[b];
        }
    }
    TEST_ASSERT_EQUAL_DOUBLE(0.0, imp.cdf[1]);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, imp.cdf[8]);
    TEST_ASSERT_EQUAL_DOUBLE(1.0, imp.cdf[9]);
    /* 1/H = (1/N) sum over the support of 1/p_n: above 1 here (4 bins of 9) */
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, 9.0 / inv, imp.harmonic_mean);
    TEST_ASSERT_TRUE(imp.harmonic_mean > 1.0);
    double qr, qi;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_q(&imp, 0u, &qr, &qi));
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, 1.0 / imp.harmonic_mean, qr / 3.0);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_q(&imp, 4u, &qr, &qi));
    TEST_ASSERT_TRUE(isfinite(qr) && isfinite(qi));
    /* the warp never returns a bin outside the support: a fine grid of u,
     * each CDF entry itself, and the largest u below 1 */
    for (size_t i = 0; i <= 20000u; ++i) {
        double u = i < 20000u ? (double)i / 20000.0 : nextafter(1.0, 0.0), x;
        size_t bin;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_warp(&imp, u, &x, &bin));
        TEST_ASSERT_TRUE(in[bin]);
        TEST_ASSERT_EQUAL_UINT(bin, (size_t)(x * 9.0));
        if (i < 9u && imp.cdf[i] < 1.0) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_warp(&imp, imp.cdf[i], &x, &bin));
            TEST_ASSERT_TRUE(in[bin]);
        }
    }
    /* a single positive weight: every sample in its bin, weight 1/N */
    const double one[5] = {0.0, 0.0, 7.0, 0.0, 0.0};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 5u, one));
    TEST_ASSERT_EQUAL_DOUBLE(1.0, imp.g[2]);
    TEST_ASSERT_EQUAL_DOUBLE(5.0, imp.p[2]);
    TEST_ASSERT_EQUAL_DOUBLE(25.0, imp.harmonic_mean); /* 5 / (1/5) */
    /* a tiny positive weight is still refused, beside zeros */
    const double tiny[4] = {0.0, 1.0, 1e-12, 0.0};
    memcpy(&imp_copy, &imp, sizeof imp);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ZERO_WEIGHT, mcs_importance_init(&imp, 4u, tiny));
    TEST_ASSERT_EQUAL_MEMORY(&imp_copy, &imp, sizeof imp);
}

/* Issue 10 item 10: one double for both outputs of a call is refused. */
static void test_one_storage_for_two_outputs_is_refused(void)
{
    const double w[3] = {1.0, 2.0, 3.0};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 3u, w));
    double both = 7.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_importance_q(&imp, 1u, &both, &both));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS,
                          mcs_importance_warp(&imp, 0.5, &both, (size_t *)(void *)&both));
    TEST_ASSERT_EQUAL_DOUBLE(7.0, both);
}

/* Found by fuzz_api: an object with a valid n but p_n = 0 (zeroed) gave Q_k =
 * NaN with MCS_OK; a result that is not finite is refused, outputs untouched. */
static void test_q_of_a_corrupted_object_is_refused_not_nan(void)
{
    memset(&imp, 0, sizeof imp);
    imp.n = 4u;
    double re = 7.0, im = 8.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_importance_q(&imp, 1u, &re, &im));
    TEST_ASSERT_EQUAL_DOUBLE(7.0, re);
    TEST_ASSERT_EQUAL_DOUBLE(8.0, im);
}

/* A CDF entry of -inf (a corrupted object: init writes none) at the search's
 * lower end made t = (u + inf) / inf NaN, and the warp and the draw returned
 * a NaN point with MCS_OK. Whatever the CDF holds, the point lies in the bin
 * the search returned. */
static void test_a_corrupted_cdf_entry_still_gives_a_point_inside_the_returned_bin(void)
{
    const double w[8] = {1.0, 2.0, 3.0, 4.0, 4.0, 3.0, 2.0, 1.0};
    static const double bad[4] = {-(double)INFINITY, (double)INFINITY, (double)NAN, -1e300};
    for (int i = 0; i < 4; ++i)
        for (size_t at = 1; at < 8u; ++at) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 8u, w));
            mcs_pattern pat;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_STRATIFIED, 8u, 16u, &imp));
            imp.cdf[at] = bad[i];
            for (int j = 0; j < 64; ++j) {
                double x = -1.0;
                size_t bin = 99u;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_warp(&imp, (j + 0.5) / 64.0, &x, &bin));
                TEST_ASSERT_TRUE(bin < 8u && x >= 0.0 && x < 1.0 && (size_t)(x * 8.0) == bin);
            }
            mcs_rng rng;
            mcs_rng_seed(&rng, 5u, at);
            size_t bins[16];
            double weights[16], points[16];
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &rng, 16u, bins, weights, points));
            for (size_t j = 0; j < 16u; ++j)
                TEST_ASSERT_TRUE(points[j] >= 0.0 && points[j] < 1.0 &&
                                 (size_t)(points[j] * 8.0) == bins[j]);
        }
}

/* Grid points k / 2^53 (the generator's u) in [a, b), a and b in [0, 1]. */
static double grid_count(double a, double b)
{
    return ceil(ldexp(b, 53)) - ceil(ldexp(a, 53));
}

/* Issue 12: p_n and the interval the generator samples agree exactly. Each
 * CDF entry is on the generator's grid, g_n is the length of its interval,
 * so P(bin n) = g_n exactly and <s_n> = K P(bin n) / p_n = K / N to rounding:
 * unbiased, even for weights of 3e-10 and 3.4e-10 of the total, where the bin
 * probability used to be off by ~1e-7 relative (1.4e-3 at 1e-12). */
static void test_bin_probabilities_are_the_stored_g_so_the_estimator_is_unbiased(void)
{
    static const double sets[4][5] = {{1.0, 1.2e-9, 1.0, 1.0, 1.0},
                                      {0.7, 2e-9, 0.2, 5.0, 1e-3},
                                      {1.0, 2.0, 3.0, 4.0, 5.0},
                                      {0.1, 0.1, 0.1, 0.1, 0.3}};
    for (int i = 0; i < 4; ++i) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 5u, sets[i]));
        double total = 0.0;
        for (int b = 0; b < 5; ++b)
            total += sets[i][b];
        for (size_t b = 0; b < 5u; ++b) {
            const double prob = grid_count(imp.cdf[b], imp.cdf[b + 1u]) / 9007199254740992.0;
            TEST_ASSERT_EQUAL_DOUBLE(imp.cdf[b + 1u] - imp.cdf[b], imp.g[b]);
            TEST_ASSERT_TRUE(prob == imp.g[b]);
            TEST_ASSERT_DOUBLE_WITHIN(4e-16, 1.0, prob / imp.p[b] * 5.0); /* <s_n> N / K */
            /* and g is what was asked for, to 2^-19 relative at worst */
            TEST_ASSERT_DOUBLE_WITHIN(2e-6 * sets[i][b] / total, sets[i][b] / total, imp.g[b]);
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_weights_are_normalised_into_g_p_cdf_and_harmonic_mean);
    RUN_TEST(test_uniform_weights_give_unit_density_and_h_equal_one);
    RUN_TEST(test_warp_maps_each_cdf_interval_linearly_onto_its_bin);
    RUN_TEST(test_warp_is_monotone_and_keeps_points_in_their_bins);
    RUN_TEST(test_bad_weights_return_an_error_and_leave_the_struct_untouched);
    RUN_TEST(test_bad_warp_input_returns_an_error_and_leaves_outputs_untouched);
    RUN_TEST(test_q_is_the_eq7_transform_of_one_over_p_and_q0_gives_one_over_h);
    RUN_TEST(test_bad_q_input_returns_an_error_and_leaves_outputs_untouched);
    RUN_TEST(test_any_scale_is_accepted_and_a_negligible_weight_is_refused);
    RUN_TEST(test_bin_probabilities_are_the_stored_g_so_the_estimator_is_unbiased);
    RUN_TEST(test_a_zero_weight_puts_its_bin_outside_the_support);
    RUN_TEST(test_one_storage_for_two_outputs_is_refused);
    RUN_TEST(test_q_of_a_corrupted_object_is_refused_not_nan);
    RUN_TEST(test_a_corrupted_cdf_entry_still_gives_a_point_inside_the_returned_bin);
    return UNITY_END();
}
