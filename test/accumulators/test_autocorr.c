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
    spectra_make_importance(&imp, n, 0.3, 5u, 2u, 1.5);
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

#define AC_UNCHANGED(status, call) SPECTRA_UNCHANGED(ac, ac_before, status, call)

static mcs_status add_bins(void *obj, size_t k, const size_t *b, const double *w)
{
    return mcs_autocorr_add_bins((mcs_autocorr *)obj, k, b, w);
}

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
    spectra_refuses_bad_trials(&ac, &ac_before, sizeof ac, 8u, add_bins, b, w, 0u, 2u);

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

/* Issue 10 items 2 and 5. Weights near DBL_MAX (one of 1.5e154 was enough)
 * used to be accepted and give power [inf, 0, 0, ...], untransformed, with
 * MCS_OK: now the trial is refused. An object whose sums are beyond anything
 * trials produce (overwritten) is refused before anything is written, so
 * the transform never runs on values it could not take. */
static void test_an_overflowed_sum_is_refused_before_anything_is_written(void)
{
    size_t b[2] = {1u, 3u};
    double w[2] = {1e308, 1e308}, w1[1] = {1.5e154};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, 8u));
    AC_UNCHANGED(MCS_ERR_MAGNITUDE, mcs_autocorr_add_bins(&ac, 2u, b, w));
    AC_UNCHANGED(MCS_ERR_MAGNITUDE, mcs_autocorr_add_bins(&ac, 1u, b, w1));
    w[0] = w[1] = 1.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac, 2u, b, w));
    for (size_t j = 0; j < 16u; ++j)
        power[j] = re[j] = im[j] = 7.0;
    ac.sum_lag[0] = 1e308;
    AC_UNCHANGED(MCS_ERR_INVARIANT, mcs_autocorr_power(&ac, &plan, 8u, power));
    ac.sum_lag[0] = 1.0;
    ac.sum_s[3] = INFINITY;
    AC_UNCHANGED(MCS_ERR_INVARIANT, mcs_autocorr_mean(&ac, &plan, 8u, re, im));
    AC_UNCHANGED(MCS_ERR_INVARIANT, mcs_autocorr_power(&ac, &plan, 8u, power));
    for (size_t j = 0; j < 16u; ++j) {
        TEST_ASSERT_EQUAL_DOUBLE(7.0, power[j]);
        TEST_ASSERT_EQUAL_DOUBLE(7.0, re[j]);
        TEST_ASSERT_EQUAL_DOUBLE(7.0, im[j]);
    }
}

/* ---------------- issues 10 and 12: accuracy, count, limits, overlap ---------------- */

/* The power and mean of ac against those of spec, to tol relative (the mean
 * relative to sqrt of the power). */
static void expect_agreement(size_t n, double tol, size_t tag)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_power(&ac, &plan, n, power));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_mean(&ac, &plan, n, re, im));
    for (size_t f = 0; f < n; ++f) {
        double sp, sr, si;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&spec, f, &sp));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&spec, f, &sr, &si));
        spectra_assert_close(sp, power[f], tol, 0.0, "<|S_k|^2>", tag, f);
        spectra_assert_close(sr, re[f], tol, sqrt(sp), "Re <S_k>", tag, f);
        spectra_assert_close(si, im[f], tol, sqrt(sp), "Im <S_k>", tag, f);
    }
}

/* Issue 12: N = 3, K = 1000, jitter with importance (s_n ~ 333, power ~0.8
 * at k = 1): the plain sums of pair products drifted from the spectrum
 * accumulator by 3.6e-3 to 1.8e-2 over 40 000 trials. Centred dense trials
 * and compensated sums agree to 1e-12 at 10 000 and 40 000 trials, and for
 * K = 10 and 100 as well (the error does not grow with K). */
static void test_power_agrees_with_the_spectrum_to_1e_12_whatever_k_and_trials(void)
{
    static const size_t ks[3] = {10u, 100u, 1000u};
    const double w[3] = {1.0, 2.0, 4.5};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 3u, w));
    for (size_t i = 0; i < 3u; ++i) {
        const size_t k = ks[i], last = k == 1000u ? 40000u : 5000u;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac, 3u));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&spec, 3u));
        spectra_stream st;
        spectra_stream_init(&st, MCS_PATTERN_JITTER, 3u, k, &imp, 5u + i, 7u);
        for (size_t t = 1; t <= last; ++t) {
            static size_t b[1000];
            static double wt[1000];
            spectra_stream_draw(&st, b, wt, NULL);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac, k, b, wt));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&spec, k, b, wt));
            if (t == 10000u || t == last)
                expect_agreement(3u, 1e-12, k);
        }
    }
}

/* Both routes at large N, K < N (sample pairs) and K = N (centred dense s),
 * agree with the spectrum accumulator to 1e-12 of each power. */
static void test_both_routes_agree_with_the_spectrum_at_large_n(void)
{
    static const size_t shapes[3][2] = {{4096u, 64u}, {1024u, 1024u}, {97u, 200u}};
    for (size_t i = 0; i < 3u; ++i) {
        const size_t n = shapes[i][0], k = shapes[i][1];
        static size_t b[1024];
        static double wt[1024];
        make_importance(n);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&spec, n));
        spectra_stream st;
        spectra_stream_init(&st, MCS_PATTERN_STRATIFIED, n, k, &imp, 9u + i, 7u);
        for (size_t t = 0; t < 30u; ++t) {
            spectra_stream_draw(&st, b, wt, NULL);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac, k, b, wt));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&spec, k, b, wt));
        }
        expect_agreement(n, 1e-12, n);
    }
}

/* Issue 10 item 9: the count stops at MCS_MAX_COUNT (64 self-merges wrapped
 * it to 0 with MCS_OK); self-merges keep the averages. Item 5: trials at
 * MCS_AUTOCORR_MAX_TRIAL, merged up to 2^52 trials, read out finite. */
static void test_the_count_stops_at_its_maximum_and_the_weight_limit_stays_finite(void)
{
    const double lim = MCS_AUTOCORR_MAX_TRIAL;
    size_t b[8] = {0u, 1u, 2u, 3u, 4u, 5u, 6u, 7u};
    double w[8] = {lim / 2.0, lim / 2.0, 0, 0, 0, 0, 0, 0}, w8[8];
    for (size_t j = 0; j < 8u; ++j)
        w8[j] = j == 3u ? 0.0 : lim / 8.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac, 2u, b, w));  /* pairs */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac, 8u, b, w8)); /* dense */
    static double before[8];
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_power(&ac, &plan, 8u, before));
    for (int i = 0; i < 52; ++i)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_merge(&ac, &ac));
    uint64_t c = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_count(&ac, &c));
    TEST_ASSERT_EQUAL_UINT64((uint64_t)MCS_MAX_COUNT, c);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_power(&ac, &plan, 8u, power));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_mean(&ac, &plan, 8u, re, im));
    for (size_t f = 0; f < 8u; ++f) {
        TEST_ASSERT_TRUE(isfinite(power[f]) && isfinite(re[f]) && isfinite(im[f]));
        TEST_ASSERT_DOUBLE_WITHIN(1e-14 * before[0], before[f], power[f]);
    }
    AC_UNCHANGED(MCS_ERR_COUNT, mcs_autocorr_merge(&ac, &ac));
    AC_UNCHANGED(MCS_ERR_COUNT, mcs_autocorr_add_bins(&ac, 2u, b, w));
    w[1] = nextafter(lim, INFINITY);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac, 8u));
    AC_UNCHANGED(MCS_ERR_MAGNITUDE, mcs_autocorr_add_bins(&ac, 2u, b, w));
}

/* Issue 10 item 10: outputs overlapping each other, the accumulator or the
 * plan's scratch, and inputs inside the accumulator, are refused with
 * nothing written. */
static void test_overlapping_arrays_are_refused_and_nothing_is_written(void)
{
    size_t b[3] = {0u, 4u, 7u};
    double w[3] = {1.0, 2.0, 0.5};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac, 3u, b, w));
    static mcs_dft plan_before;
    memcpy(&plan_before, &plan, sizeof plan);
    for (size_t j = 0; j < 16u; ++j)
        re[j] = 7.0;
    AC_UNCHANGED(MCS_ERR_ALIAS, mcs_autocorr_mean(&ac, &plan, 8u, re, re));
    AC_UNCHANGED(MCS_ERR_ALIAS, mcs_autocorr_mean(&ac, &plan, 8u, re, re + 4));
    AC_UNCHANGED(MCS_ERR_ALIAS, mcs_autocorr_power(&ac, &plan, 8u, plan.work));
    AC_UNCHANGED(MCS_ERR_ALIAS, mcs_autocorr_power(&ac, &plan, 8u, ac.sum_s));
    AC_UNCHANGED(MCS_ERR_ALIAS, mcs_autocorr_add_bins(&ac, 3u, b, ac.lo_s));
    TEST_ASSERT_EQUAL_MEMORY(&plan_before, &plan, sizeof plan);
    for (size_t j = 0; j < 16u; ++j)
        TEST_ASSERT_EQUAL_DOUBLE(7.0, re[j]);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_autocorrelation_and_spectrum_agree_for_any_n);
    RUN_TEST(test_merge_of_halves_equals_one_pass);
    RUN_TEST(test_bad_input_returns_an_error_and_changes_nothing);
    RUN_TEST(test_an_overflowed_sum_is_refused_before_anything_is_written);
    RUN_TEST(test_power_agrees_with_the_spectrum_to_1e_12_whatever_k_and_trials);
    RUN_TEST(test_both_routes_agree_with_the_spectrum_at_large_n);
    RUN_TEST(test_the_count_stops_at_its_maximum_and_the_weight_limit_stays_finite);
    RUN_TEST(test_overlapping_arrays_are_refused_and_nothing_is_written);
    return UNITY_END();
}
