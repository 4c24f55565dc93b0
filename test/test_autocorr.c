/* Tests for the autocorrelation accumulator: its Wiener-Khinchin power
 * spectrum and its <S_k> against the spectrum accumulator for any N, merge,
 * guard words after every output array, and bad input. */
#include <math.h>
#include <string.h>

#include "mcspec.h"
#include "spectra_ref.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static mcs_autocorr ac, ac2, ac3, ac_before;
static mcs_spectrum spec;
static mcs_importance imp;
static mcs_dft plan;
static size_t bins[256];
/* one element more than any output: the guard word */
static double weights[256], re[MCS_MAX_N + 1], im[MCS_MAX_N + 1], power[MCS_MAX_N + 1];

/* Every stream of this file uses PCG32 sequence 0xabcdu. */
#define STREAM_SEQ 0xabcdu

static void make_importance(size_t n)
{
    static double g[MCS_MAX_N];
    for (size_t b = 0; b < n; ++b)
        g[b] = 0.3 + (double)((b * 5u) % n) / (double)n + (b == 2u ? 1.5 : 0.0);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, g));
}

static void test_autocorrelation_and_spectrum_agree_for_any_n(void)
{
    static const struct {
        size_t n, k;
        mcs_pattern_kind kind;
        int importance;
    } cases[] = {
        {1u, 3u, MCS_PATTERN_RANDOM, 0},       {2u, 2u, MCS_PATTERN_RANDOM, 1},
        {3u, 2u, MCS_PATTERN_STRATIFIED, 0},   {16u, 4u, MCS_PATTERN_RANDOM, 1},
        {97u, 10u, MCS_PATTERN_STRATIFIED, 1}, {1000u, 33u, MCS_PATTERN_JITTER, 0},
        {4093u, 16u, MCS_PATTERN_RANDOM, 0},   {4096u, 64u, MCS_PATTERN_STRATIFIED, 1},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        size_t n = cases[i].n, k = cases[i].k;
        const mcs_importance *ip = NULL;
        if (cases[i].importance) {
            make_importance(n);
            ip = &imp;
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&spec, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, n));
        spectra_stream st;
        spectra_stream_init(&st, cases[i].kind, n, k, ip, 80u + i, STREAM_SEQ);
        size_t trials = n > 1000u ? 50u : 500u;
        for (size_t t = 0; t < trials; ++t) {
            spectra_stream_draw(&st, bins, weights, NULL);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac, k, bins, weights));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&spec, k, bins, weights));
        }
        spectra_guard_set(power, n);
        spectra_guard_set(re, n);
        spectra_guard_set(im, n);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_power(&ac, &plan, n, power));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_mean(&ac, &plan, n, re, im));
        spectra_guard_check(power, n, "mcs_autocorr_power");
        spectra_guard_check(re, n, "mcs_autocorr_mean (re)");
        spectra_guard_check(im, n, "mcs_autocorr_mean (im)");
        const double level = spectra_mean_power(&spec);
        for (size_t f = 0; f < n; ++f) {
            double sr, si, sp;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&spec, f, &sr, &si));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&spec, f, &sp));
            spectra_assert_close(sr, re[f], 1e-10, sqrt(level), "Re <S_k>", n, f);
            spectra_assert_close(si, im[f], 1e-10, sqrt(level), "Im <S_k>", n, f);
            spectra_assert_close(sp, power[f], 1e-10, level, "<|S_k|^2>", n, f);
        }
    }
}

static void test_merge_of_halves_equals_one_pass(void)
{
    enum { N = 30, K = 7 };
    make_importance(N);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac, N));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac2, N));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac3, N));
    spectra_stream st;
    spectra_stream_init(&st, MCS_PATTERN_STRATIFIED, N, K, &imp, 21u, STREAM_SEQ);
    for (size_t t = 0; t < 500u; ++t) {
        spectra_stream_draw(&st, bins, weights, NULL);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac, K, bins, weights));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(t < 200u ? &ac2 : &ac3, K, bins, weights));
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_merge(&ac2, &ac3));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, N));
    static double power2[MCS_MAX_N];
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_power(&ac, &plan, N, power));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_power(&ac2, &plan, N, power2));
    uint64_t c2;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_count(&ac2, &c2));
    TEST_ASSERT_EQUAL_UINT64(500u, c2);
    for (size_t k = 0; k < N; ++k)
        spectra_assert_close(power[k], power2[k], 1e-12, 0.0, "autocorr power", k, k);
}

/* ---------------- bad input ---------------- */

#define AC_UNCHANGED(status, call)                                                           \
    do {                                                                                     \
        memcpy(&ac_before, &ac, sizeof ac);                                                  \
        TEST_ASSERT_EQUAL_INT((status), (call));                                             \
        TEST_ASSERT_EQUAL_MEMORY(&ac_before, &ac, sizeof ac);                                \
    } while (0)

static void test_bad_input_returns_an_error_and_changes_nothing(void)
{
    size_t b[3] = {0u, 4u, 7u};
    double w[3] = {1.0, 2.0, 0.5};
    uint64_t c = 7u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, 8u));
    for (size_t j = 0; j < 16u; ++j)
        power[j] = re[j] = im[j] = 7.0;
    AC_UNCHANGED(MCS_ERR_EMPTY, mcs_autocorr_power(&ac, &plan, 8u, power));
    AC_UNCHANGED(MCS_ERR_EMPTY, mcs_autocorr_mean(&ac, &plan, 8u, re, im));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac, 3u, b, w));

    AC_UNCHANGED(MCS_ERR_NULL, mcs_autocorr_init(NULL, 8u));
    AC_UNCHANGED(MCS_ERR_N_RANGE, mcs_autocorr_init(&ac, 0u));
    AC_UNCHANGED(MCS_ERR_N_RANGE, mcs_autocorr_init(&ac, (size_t)MCS_MAX_N + 1u));
    AC_UNCHANGED(MCS_ERR_NULL, mcs_autocorr_add_bins(NULL, 3u, b, w));
    AC_UNCHANGED(MCS_ERR_NULL, mcs_autocorr_add_bins(&ac, 3u, NULL, w));
    AC_UNCHANGED(MCS_ERR_NULL, mcs_autocorr_add_bins(&ac, 3u, b, NULL));
    AC_UNCHANGED(MCS_ERR_K_RANGE, mcs_autocorr_add_bins(&ac, 0u, b, w));
    b[0] = 8u;
    AC_UNCHANGED(MCS_ERR_BIN_RANGE, mcs_autocorr_add_bins(&ac, 3u, b, w));
    b[0] = 0u;
    w[2] = NAN;
    AC_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_autocorr_add_bins(&ac, 3u, b, w));
    w[2] = -0.5;
    AC_UNCHANGED(MCS_ERR_NEGATIVE, mcs_autocorr_add_bins(&ac, 3u, b, w));
    w[2] = 0.5;

    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac2, 9u));
    AC_UNCHANGED(MCS_ERR_MISMATCH, mcs_autocorr_merge(&ac, &ac2));
    AC_UNCHANGED(MCS_ERR_NULL, mcs_autocorr_merge(NULL, &ac2));
    AC_UNCHANGED(MCS_ERR_NULL, mcs_autocorr_merge(&ac, NULL));
    memset(&ac3, 0, sizeof ac3);
    AC_UNCHANGED(MCS_ERR_UNINIT, mcs_autocorr_merge(&ac, &ac3));
    AC_UNCHANGED(MCS_ERR_NULL, mcs_autocorr_count(&ac, NULL));
    AC_UNCHANGED(MCS_ERR_NULL, mcs_autocorr_count(NULL, &c));

    static mcs_dft plan_before, plan9, zero_plan;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan9, 9u));
    memset(&zero_plan, 0, sizeof zero_plan);
    memcpy(&plan_before, &plan, sizeof plan);
    AC_UNCHANGED(MCS_ERR_MISMATCH, mcs_autocorr_power(&ac, &plan, 7u, power));
    AC_UNCHANGED(MCS_ERR_MISMATCH, mcs_autocorr_power(&ac, &plan9, 8u, power));
    AC_UNCHANGED(MCS_ERR_UNINIT, mcs_autocorr_power(&ac, &zero_plan, 8u, power));
    AC_UNCHANGED(MCS_ERR_NULL, mcs_autocorr_power(NULL, &plan, 8u, power));
    AC_UNCHANGED(MCS_ERR_NULL, mcs_autocorr_power(&ac, NULL, 8u, power));
    AC_UNCHANGED(MCS_ERR_NULL, mcs_autocorr_power(&ac, &plan, 8u, NULL));
    AC_UNCHANGED(MCS_ERR_MISMATCH, mcs_autocorr_mean(&ac, &plan, 9u, re, im));
    AC_UNCHANGED(MCS_ERR_MISMATCH, mcs_autocorr_mean(&ac, &plan9, 8u, re, im));
    AC_UNCHANGED(MCS_ERR_UNINIT, mcs_autocorr_mean(&ac, &zero_plan, 8u, re, im));
    AC_UNCHANGED(MCS_ERR_NULL, mcs_autocorr_mean(NULL, &plan, 8u, re, im));
    AC_UNCHANGED(MCS_ERR_NULL, mcs_autocorr_mean(&ac, NULL, 8u, re, im));
    AC_UNCHANGED(MCS_ERR_NULL, mcs_autocorr_mean(&ac, &plan, 8u, re, NULL));
    AC_UNCHANGED(MCS_ERR_NULL, mcs_autocorr_mean(&ac, &plan, 8u, NULL, im));
    TEST_ASSERT_EQUAL_MEMORY(&plan_before, &plan, sizeof plan);
    for (size_t j = 0; j < 16u; ++j) {
        TEST_ASSERT_EQUAL_DOUBLE(7.0, power[j]);
        TEST_ASSERT_EQUAL_DOUBLE(7.0, re[j]);
        TEST_ASSERT_EQUAL_DOUBLE(7.0, im[j]);
    }

    memset(&ac, 0, sizeof ac);
    AC_UNCHANGED(MCS_ERR_UNINIT, mcs_autocorr_add_bins(&ac, 3u, b, w));
    AC_UNCHANGED(MCS_ERR_UNINIT, mcs_autocorr_merge(&ac, &ac2));
    AC_UNCHANGED(MCS_ERR_UNINIT, mcs_autocorr_count(&ac, &c));
    AC_UNCHANGED(MCS_ERR_UNINIT, mcs_autocorr_power(&ac, &plan, 8u, power));
    AC_UNCHANGED(MCS_ERR_UNINIT, mcs_autocorr_mean(&ac, &plan, 8u, re, im));
    TEST_ASSERT_EQUAL_UINT64(7u, c);
}

static void test_an_overflowed_sum_is_refused_before_anything_is_written(void)
{
    /* Weights near DBL_MAX: each is valid, their sums and products are not. */
    size_t b[2] = {1u, 3u};
    double w[2] = {1e308, 1e308};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac, 2u, b, w));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac, 2u, b, w));
    for (size_t j = 0; j < 16u; ++j)
        power[j] = re[j] = im[j] = 7.0;
    AC_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_autocorr_power(&ac, &plan, 8u, power));
    AC_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_autocorr_mean(&ac, &plan, 8u, re, im));
    for (size_t j = 0; j < 16u; ++j) {
        TEST_ASSERT_EQUAL_DOUBLE(7.0, power[j]);
        TEST_ASSERT_EQUAL_DOUBLE(7.0, re[j]);
        TEST_ASSERT_EQUAL_DOUBLE(7.0, im[j]);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_autocorrelation_and_spectrum_agree_for_any_n);
    RUN_TEST(test_merge_of_halves_equals_one_pass);
    RUN_TEST(test_bad_input_returns_an_error_and_changes_nothing);
    RUN_TEST(test_an_overflowed_sum_is_refused_before_anything_is_written);
    return UNITY_END();
}
