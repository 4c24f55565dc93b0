/* Tests for overwritten moment and autocorrelation objects (issue 22 item
 * 4): sums that no trials give (a negative sum of squares, a negative batch
 * diagonal, an N edited since init, a lag-0 sum below 0, sums whose
 * variance or spectrum is negative beyond rounding) are refused by every
 * read-out and merge with MCS_ERR_INVARIANT and nothing written; they gave
 * NaN or negative results with MCS_OK. */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "mcspec.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static mcs_moment mom, bad, before, other;
static mcs_autocorr ac, ac_bad, ac_before, ac_other;
static mcs_dft plan;
static double mat_re[64 * 64], mat_im[64 * 64], out[64], out2[64];

#define N 6u

/* 30 trials of 3 samples (and some of 8, densely) on N = 6 bins. */
static void fill_moment(void)
{
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 4u, 22u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, N));
    for (size_t t = 0; t < 30u; ++t) {
        size_t bins[8];
        double w[8];
        const size_t k = t % 5u == 4u ? 8u : 3u;
        for (size_t j = 0; j < k; ++j) {
            uint32_t b = 0u;
            double u = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_bounded(&rng, N, &b));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(&rng, &u));
            bins[j] = b;
            w[j] = 0.5 + u;
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&mom, k, bins, w));
    }
    TEST_ASSERT_TRUE(mom.batch_count > 0u);
}

/* Every read-out and a merge either way refuse bad, and nothing changes:
 * neither the outputs nor the objects. */
static void expect_moment_refused(const char *what)
{
    const double f[N] = {1, 2, 3, 1, 2, 3};
    double v = 7.0, re = 7.0, im = 7.0;
    for (size_t j = 0; j < N * N; ++j)
        mat_re[j] = mat_im[j] = 7.0;
    memcpy(&before, &bad, sizeof bad);
    memcpy(&other, &mom, sizeof mom);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT, mcs_moment_bin_mean(&bad, 1u, &v), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT, mcs_moment_bin_second(&bad, 1u, 1u, &v), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT, mcs_moment_mean(&bad, 1u, &re, &im), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT, mcs_moment_power(&bad, 1u, &v), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT, mcs_moment_cross(&bad, 1u, 2u, &re, &im), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT,
                                  mcs_moment_covariance(&bad, 2u, 2u, &re, &im), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT,
                                  mcs_moment_cross_matrix(&bad, bad.n, mat_re, mat_im), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT,
                                  mcs_moment_covariance_matrix(&bad, bad.n, mat_re, mat_im), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT,
                                  mcs_moment_estimator_mean(&bad, bad.n, 3u, f, &v), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT, mcs_moment_variance(&bad, bad.n, 3u, f, &v),
                                  what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT,
                                  mcs_moment_estimator_covariance(&bad, bad.n, 3u, f, f, &v), what);
    if (bad.n == N) {
        TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT, mcs_moment_merge(&other, &bad), what);
        TEST_ASSERT_EQUAL_MEMORY(&mom, &other, sizeof mom);
    }
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT, mcs_moment_merge(&bad, &bad), what);
    TEST_ASSERT_EQUAL_MEMORY(&before, &bad, sizeof bad);
    TEST_ASSERT_EQUAL_DOUBLE(7.0, v);
    TEST_ASSERT_EQUAL_DOUBLE(7.0, re);
    TEST_ASSERT_EQUAL_DOUBLE(7.0, im);
    for (size_t j = 0; j < N * N; ++j)
        TEST_ASSERT_EQUAL_DOUBLE(7.0, mat_re[j]);
    size_t len = 0u;
    static uint8_t rec[1u << 16];
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT,
                                  mcs_io_save_moment(&bad, sizeof rec, rec, &len), what);
}

static void test_a_moment_whose_sums_no_trials_give_is_refused_everywhere(void)
{
    fill_moment();
    /* a sum of squares below 0: the closed diagonal */
    memcpy(&bad, &mom, sizeof mom);
    bad.sum_dd[2 * N + 2] = -1.0;
    expect_moment_refused("closed diagonal -1");
    /* the open batch's half squares below 0 */
    memcpy(&bad, &mom, sizeof mom);
    bad.batch_w[3 * N + 3] = -bad.batch_w[3 * N + 3] - 0.5;
    expect_moment_refused("batch diagonal < 0");
    /* N edited since init: the arrays read with another stride */
    memcpy(&bad, &mom, sizeof mom);
    bad.n = N - 1u;
    expect_moment_refused("N - 1");
    memcpy(&bad, &mom, sizeof mom);
    bad.n = N + 1u;
    expect_moment_refused("N + 1");
    /* one triangle of the sums changed: no longer symmetric */
    memcpy(&bad, &mom, sizeof mom);
    size_t off = 1u;
    while (bad.sum_dd[off] == 0.0 && off + 1u < N * N)
        off += off % (N + 1u) == N ? 2u : 1u; /* off the diagonal */
    bad.sum_dd[off] *= 0.5;
    expect_moment_refused("asymmetric");
    /* a first sum past its variance: (sum d)^2 > T sum d^2 */
    memcpy(&bad, &mom, sizeof mom);
    bad.sum_d[4] = 2.0 * sqrt((double)bad.count * (bad.sum_dd[4 * N + 4] + 1.0)) + 5.0;
    expect_moment_refused("first sum past its variance");
    /* an entry past Cauchy-Schwarz, |D_mn| > sqrt(D_m D_n) */
    memcpy(&bad, &mom, sizeof mom);
    bad.sum_dd[1 * N + 4] = bad.sum_dd[4 * N + 1] = 1e6; /* the diagonals are about 30 */
    expect_moment_refused("past Cauchy-Schwarz");
    /* a compensation of its sum's size */
    memcpy(&bad, &mom, sizeof mom);
    bad.lo_d[0] = bad.sum_d[0] + 1.0;
    expect_moment_refused("compensation");
}

/* Sums whose 2 x 2 minors and bins all pass but which are no covariance:
 * N = 3, d sums [[1, -1, -1], [-1, 1, -1], [-1, -1, 1]] with first sums 0
 * (f = (1, 1, 1) gives f^T D f = -3). Var[I] and <|S_0|^2> were negative
 * with MCS_OK; beyond their rounding bounds they are refused. */
static void test_sums_that_are_no_covariance_are_refused_by_the_read_outs_that_see_it(void)
{
    const size_t b2[2] = {0u, 1u};
    const double w2[2] = {0.0, 0.0}, f[3] = {1.0, 1.0, 1.0};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&bad, 3u));
    for (int t = 0; t < 5; ++t) /* five empty trials: shift 0, sums 0 */
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&bad, 2u, b2, w2));
    for (size_t m = 0; m < 3u; ++m)
        for (size_t q = 0; q < 3u; ++q)
            bad.sum_dd[m * 3u + q] = m == q ? 1.0 : -1.0;
    memset(bad.batch_w, 0, sizeof bad.batch_w);
    bad.batch_count = bad.batch_sparse = 0u;
    double v = 7.0, re = 7.0, im = 7.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_moment_variance(&bad, 3u, 1u, f, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_moment_power(&bad, 0u, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_moment_cross(&bad, 0u, 0u, &re, &im));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_moment_covariance(&bad, 0u, 0u, &re, &im));
    for (size_t j = 0; j < 9u; ++j)
        mat_re[j] = 7.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_moment_cross_matrix(&bad, 3u, mat_re, mat_im));
    for (size_t j = 0; j < 9u; ++j)
        TEST_ASSERT_EQUAL_DOUBLE(7.0, mat_re[j]);
    TEST_ASSERT_EQUAL_DOUBLE(7.0, v);
    TEST_ASSERT_EQUAL_DOUBLE(7.0, re);
    /* other frequencies and integrands see a valid part: they read out */
    const double g[3] = {1.0, -1.0, 0.0};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_variance(&bad, 3u, 1u, g, &v));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 4.0 / 5.0, v);
}

/* 30 trials of 4 samples on N = 16 bins. */
static void fill_autocorr(void)
{
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 5u, 22u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac, 16u));
    for (size_t t = 0; t < 30u; ++t) {
        size_t bins[4];
        double w[4];
        for (size_t j = 0; j < 4u; ++j) {
            uint32_t b = 0u;
            double u = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_bounded(&rng, 16u, &b));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(&rng, &u));
            bins[j] = b;
            w[j] = 1.0 + u;
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac, 4u, bins, w));
    }
}

static void expect_autocorr_refused(const char *what)
{
    for (size_t j = 0; j < 16u; ++j)
        out[j] = out2[j] = 7.0;
    memcpy(&ac_before, &ac_bad, sizeof ac_bad);
    memcpy(&ac_other, &ac, sizeof ac);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT, mcs_autocorr_power(&ac_bad, &plan, 16u, out),
                                  what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT,
                                  mcs_autocorr_mean(&ac_bad, &plan, 16u, out, out2), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT, mcs_autocorr_merge(&ac_other, &ac_bad), what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT, mcs_autocorr_merge(&ac_bad, &ac_other), what);
    TEST_ASSERT_EQUAL_MEMORY(&ac, &ac_other, sizeof ac);
    TEST_ASSERT_EQUAL_MEMORY(&ac_before, &ac_bad, sizeof ac_bad);
    for (size_t j = 0; j < 16u; ++j) {
        TEST_ASSERT_EQUAL_DOUBLE(7.0, out[j]);
        TEST_ASSERT_EQUAL_DOUBLE(7.0, out2[j]);
    }
}

static void test_an_autocorrelation_whose_sums_no_trials_give_is_refused(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, 16u));
    fill_autocorr();
    memcpy(&ac_bad, &ac, sizeof ac);
    ac_bad.sum_lag[0] = -1e6; /* read powers of about -1e5 with MCS_OK */
    expect_autocorr_refused("lag 0 of -1e6");
    memcpy(&ac_bad, &ac, sizeof ac);
    ac_bad.sum_lag[3] = 2.0 * ac.sum_lag[0] * 1.01; /* |A(3)| > A(0) */
    expect_autocorr_refused("lag past lag 0");
    memcpy(&ac_bad, &ac, sizeof ac);
    ac_bad.lo_dc = 1e-300; /* a compensation on a zero sum: merged, then unsaveable */
    expect_autocorr_refused("compensation of a zero sum");
    memcpy(&ac_bad, &ac, sizeof ac);
    ac_bad.sum_s[2] = -1.0;
    expect_autocorr_refused("sum of weights < 0");
}

/* Lags that pass every check of the stored sums but are no autocorrelation:
 * N = 4, T = 2, sum_s = (2, 0, 0, 0), lag sums 1, 1.5 and -0.75 (lag 2 =
 * N/2, halved): <|S_2|^2> = 2 (1 - 1.5 - 0.75) / (4 T) = -5/16, while the
 * sums of weights and squares agree (sum_d A(d) = 3.5 within [4/T, 4]).
 * Refused, not returned. Lags 1, 0, 0 are those of two trials of s = (1, 0,
 * 0, 0): every power 1/4. */
static void test_lags_whose_spectrum_is_negative_are_refused(void)
{
    mcs_dft plan4;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan4, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac_bad, 4u));
    ac_bad.count = 2u;
    ac_bad.sum_s[0] = 2.0;
    ac_bad.sum_lag[0] = 1.0;
    ac_bad.sum_lag[1] = 1.5;
    ac_bad.sum_lag[2] = -0.75;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_autocorr_power(&ac_bad, &plan4, 4u, out));
    ac_bad.sum_lag[1] = 0.0;
    ac_bad.sum_lag[2] = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_power(&ac_bad, &plan4, 4u, out));
    for (size_t k = 0; k < 4u; ++k)
        TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.25, out[k]);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_moment_whose_sums_no_trials_give_is_refused_everywhere);
    RUN_TEST(test_sums_that_are_no_covariance_are_refused_by_the_read_outs_that_see_it);
    RUN_TEST(test_an_autocorrelation_whose_sums_no_trials_give_is_refused);
    RUN_TEST(test_lags_whose_spectrum_is_negative_are_refused);
    return UNITY_END();
}
