#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mcspec.h"
#include "spectra_ref.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define BIG 4096

static mcs_dft plan, plan_copy;
static double s[BIG], re[BIG], im[BIG], ref_re[BIG], ref_im[BIG];

/* Root mean square of |S_k| (= ||s|| / sqrt(N) by Parseval): the scale that
 * keeps "relative" meaningful for frequencies where S_k is near zero. */
static double rms(size_t n, const double *v)
{
    double sum = 0.0;
    for (size_t j = 0; j < n; ++j)
        sum += v[j] * v[j];
    return sqrt(sum / (double)n);
}

/* Compares mcs_dft_real with the naive DFT on the first nfreq frequencies. */
static double worst_error(size_t n, size_t nfreq)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, n, s, re, im));
    spectra_naive_dft(n, s, nfreq, ref_re, ref_im);
    double scale = rms(n, s) + 1e-300;
    double e1 = spectra_max_rel_err(nfreq, re, ref_re, scale);
    double e2 = spectra_max_rel_err(nfreq, im, ref_im, scale);
    return e1 > e2 ? e1 : e2;
}

static void fill_random(size_t n, uint64_t seed)
{
    uint64_t st = seed;
    for (size_t j = 0; j < n; ++j)
        s[j] = spectra_uniform(&st, -1.0, 1.0);
}

static void test_every_n_from_1_to_300_agrees_with_the_naive_dft_to_1e_12(void)
{
    for (size_t n = 1; n <= 300; ++n) {
        fill_random(n, 0x9e3779b97f4a7c15u + n);
        double e = worst_error(n, n);
        if (!(e < 1e-12)) {
            char msg[64];
            (void)snprintf(msg, sizeof msg, "dense, n = %zu, error %g", n, e);
            TEST_FAIL_MESSAGE(msg);
        }
        /* A sparse trial (few non-zero bins), the shape the direct path exploits. */
        for (size_t j = 0; j < n; ++j)
            s[j] = (j % 7u == 3u) ? 1.0 + (double)j / (double)n : 0.0;
        e = worst_error(n, n);
        if (!(e < 1e-12)) {
            char msg[64];
            (void)snprintf(msg, sizeof msg, "sparse, n = %zu, error %g", n, e);
            TEST_FAIL_MESSAGE(msg);
        }
    }
}

static void test_large_n_of_every_path_agree_with_the_naive_dft_to_1e_12(void)
{
    /* power of two, prime, odd 3,5-smooth, even 2,3,5-smooth, twice a prime,
     * odd with a factor 7 */
    static const size_t ns[] = {4096u, 4093u, 3375u, 4000u, 4078u, 2401u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        size_t n = ns[i];
        fill_random(n, 12345u + n);
        double e = worst_error(n, n / 2u + 1u);
        if (!(e < 1e-12)) {
            char msg[64];
            (void)snprintf(msg, sizeof msg, "n = %zu, error %g", n, e);
            TEST_FAIL_MESSAGE(msg);
        }
    }
}

static int fftw_backend(void)
{
    return strcmp(mcs_dft_backend(), "fftw3") == 0;
}

static void test_the_back_end_is_named(void)
{
    TEST_ASSERT_TRUE(strcmp(mcs_dft_backend(), "kissfft") == 0 || fftw_backend());
}

static void test_each_n_is_routed_to_the_path_its_factors_allow(void)
{
    static const struct {
        size_t n;
        mcs_dft_path path;
    } cases[] = {
        {1u, MCS_DFT_PATH_TRIVIAL},      {2u, MCS_DFT_PATH_TRIVIAL},
        {4u, MCS_DFT_PATH_KISS_REAL},    {6u, MCS_DFT_PATH_KISS_REAL},
        {4096u, MCS_DFT_PATH_KISS_REAL}, {3u, MCS_DFT_PATH_KISS_COMPLEX},
        {75u, MCS_DFT_PATH_KISS_COMPLEX}, {7u, MCS_DFT_PATH_DIRECT},
        {14u, MCS_DFT_PATH_DIRECT},      {4093u, MCS_DFT_PATH_DIRECT},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, cases[i].n));
        /* FFTW takes every N >= 3 */
        const int fftw = fftw_backend() && cases[i].n >= 3u;
        TEST_ASSERT_EQUAL_INT(fftw ? MCS_DFT_PATH_FFTW : cases[i].path, plan.path);
    }
}

static void test_n_1_and_2_give_the_hand_computed_values(void)
{
    s[0] = 3.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, 1u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, 1u, s, re, im));
    TEST_ASSERT_EQUAL_DOUBLE(3.0, re[0]);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, im[0]);
    s[0] = 3.0;
    s[1] = 1.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, 2u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, 2u, s, re, im));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 4.0 / sqrt(2.0), re[0]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 2.0 / sqrt(2.0), re[1]);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, im[0]);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, im[1]);
}

static void test_the_upper_half_is_the_exact_conjugate_of_the_lower(void)
{
    static const size_t ns[] = {9u, 10u, 13u, 64u, 75u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        size_t n = ns[i];
        fill_random(n, 77u);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, n, s, re, im));
        TEST_ASSERT_EQUAL_DOUBLE(0.0, im[0]);
        for (size_t k = 1; k < n; ++k) {
            TEST_ASSERT_EQUAL_DOUBLE(re[n - k], re[k]);
            TEST_ASSERT_EQUAL_DOUBLE(-im[n - k], im[k]);
        }
    }
}

static void test_half_output_matches_the_full_output_and_writes_nothing_beyond(void)
{
    static double hr[BIG], hi[BIG];
    static const size_t ns[] = {1u, 2u, 8u, 15u, 22u, 23u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        size_t n = ns[i], h = n / 2u;
        fill_random(n, 5u);
        for (size_t k = 0; k < n + 4u; ++k)
            hr[k] = hi[k] = 1234.5; /* guard words */
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, n, s, re, im));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real_half(&plan, n, s, hr, hi));
        for (size_t k = 0; k <= h; ++k) {
            TEST_ASSERT_EQUAL_DOUBLE(re[k], hr[k]);
            TEST_ASSERT_EQUAL_DOUBLE(im[k], hi[k]);
        }
        for (size_t k = h + 1u; k < n + 4u; ++k) {
            TEST_ASSERT_EQUAL_DOUBLE(1234.5, hr[k]);
            TEST_ASSERT_EQUAL_DOUBLE(1234.5, hi[k]);
        }
    }
}

static void test_input_may_alias_an_output_and_im_may_be_null(void)
{
    static double copy[BIG];
    static const size_t ns[] = {2u, 12u, 15u, 17u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        size_t n = ns[i];
        fill_random(n, 99u);
        memcpy(copy, s, n * sizeof s[0]);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, n, s, re, im));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, n, copy, copy, NULL));
        TEST_ASSERT_EQUAL_MEMORY(re, copy, n * sizeof re[0]);
        memcpy(copy, s, n * sizeof s[0]);
        static double r2[BIG];
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, n, copy, r2, copy));
        TEST_ASSERT_EQUAL_MEMORY(re, r2, n * sizeof re[0]);
        TEST_ASSERT_EQUAL_MEMORY(im, copy, n * sizeof im[0]);
    }
}

static void test_a_copied_plan_gives_the_same_transform(void)
{
    static double re2[BIG], im2[BIG];
    static const size_t ns[] = {64u, 45u, 7u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        size_t n = ns[i];
        fill_random(n, 3u);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, n));
        plan_copy = plan;
        memset(&plan, 0xa5, sizeof plan); /* the original is gone */
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan_copy, n, s, re, im));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, n, s, re2, im2));
        TEST_ASSERT_EQUAL_MEMORY(re2, re, n * sizeof re[0]);
        TEST_ASSERT_EQUAL_MEMORY(im2, im, n * sizeof im[0]);
    }
}

/* The AVX2 copies (KissFFT's transform, the direct kernel) and the baseline
 * ones give the same bits at every path's N; only CPUs with AVX2 run both. */
static void test_the_avx2_and_baseline_copies_give_the_same_bits(void)
{
    static double re2[BIG], im2[BIG];
    static const size_t big[] = {4096u, 4093u, 3375u, 4000u, 1024u, 960u};
    int ran = 0;
    for (size_t i = 0; i < 300u + sizeof big / sizeof big[0]; ++i) {
        const size_t n = i < 300u ? i + 1u : big[i - 300u];
        fill_random(n, 77u + n);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, n));
        if (plan.simd == 0)
            continue;
        ran = 1;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real_half(&plan, n, s, re, im));
        plan.simd = 0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real_half(&plan, n, s, re2, im2));
        TEST_ASSERT_EQUAL_MEMORY(re, re2, (n / 2u + 1u) * sizeof re[0]);
        TEST_ASSERT_EQUAL_MEMORY(im, im2, (n / 2u + 1u) * sizeof im[0]);
    }
    if (!ran)
        TEST_IGNORE_MESSAGE("this CPU has no AVX2: one copy only");
}

static void test_parseval_holds_to_rounding(void)
{
    static const size_t ns[] = {1u, 2u, 31u, 64u, 243u, 1000u, 4093u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        size_t n = ns[i];
        fill_random(n, 42u + n);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, n, s, re, im));
        double time = 0.0, freq = 0.0;
        for (size_t j = 0; j < n; ++j) {
            time += s[j] * s[j];
            freq += re[j] * re[j] + im[j] * im[j];
        }
        TEST_ASSERT_DOUBLE_WITHIN(1e-12 * time, time, freq);
    }
}

static void test_s0_is_k_over_root_n_for_an_unweighted_pattern(void)
{
    static size_t bins[64];
    static double w[64];
    mcs_pattern pat;
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 7u, 11u));
    static const size_t ns[] = {7u, 64u, 100u, 1024u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        size_t n = ns[i];
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_RANDOM, n, 13u, NULL));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &rng, 13u, bins, w, NULL));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_dense(n, 13u, bins, w, s));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, n, s, re, im));
        TEST_ASSERT_DOUBLE_WITHIN(1e-13, 13.0 / sqrt((double)n), re[0]);
        TEST_ASSERT_EQUAL_DOUBLE(0.0, im[0]);
    }
}

/* Eq. 8: (1/K) sum_n f_n s_n = (1/K) sum_k F_k* S_k for any f, with importance. */
static void test_the_estimate_is_the_same_dot_product_in_both_domains(void)
{
    static double f[BIG], fre[BIG], fim[BIG], g[BIG];
    static size_t bins[32];
    static double w[32];
    mcs_importance imp;
    mcs_pattern pat;
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 8u, 12u));
    static const size_t ns[] = {16u, 63u, 97u, 512u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        size_t n = ns[i];
        uint64_t st = 1000u + n;
        for (size_t j = 0; j < n; ++j) {
            f[j] = spectra_uniform(&st, -2.0, 3.0);
            g[j] = spectra_uniform(&st, 0.1, 1.0);
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, g));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_STRATIFIED, n, 32u, &imp));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &rng, 32u, bins, w, NULL));
        double primal;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_bins(n, 32u, f, bins, w, &primal));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_dense(n, 32u, bins, w, s));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, n, s, re, im));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, n, f, fre, fim));
        double dual = 0.0, dual_im = 0.0, mag = 0.0;
        for (size_t k = 0; k < n; ++k) {
            /* F* S = (a - ib)(c + id) */
            dual += fre[k] * re[k] + fim[k] * im[k];
            dual_im += fre[k] * im[k] - fim[k] * re[k];
            mag += fabs(fre[k] * re[k]) + fabs(fim[k] * im[k]);
        }
        dual /= 32.0;
        TEST_ASSERT_DOUBLE_WITHIN(1e-13 * mag, primal, dual);
        TEST_ASSERT_DOUBLE_WITHIN(1e-13 * mag, 0.0, dual_im);
    }
}

static void test_bad_input_returns_an_error_and_changes_nothing(void)
{
    static mcs_dft before;
    static double re_before[BIG], im_before[BIG];
    fill_random(64u, 1u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, 64u));
    for (size_t k = 0; k < 64u; ++k)
        re[k] = im[k] = -7.0;
    memcpy(&before, &plan, sizeof plan);
    memcpy(re_before, re, sizeof re);
    memcpy(im_before, im, sizeof im);

    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_dft_init(NULL, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_dft_init(&plan, 0u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_dft_init(&plan, (size_t)MCS_MAX_N + 1u));
    TEST_ASSERT_EQUAL_MEMORY(&before, &plan, sizeof plan);

    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_check(&plan, 64u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_dft_check(NULL, 64u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_dft_check(&plan, 65u));
    memcpy(&plan_copy, &plan, sizeof plan);
    memset(plan_copy.kiss_state, 0, sizeof plan_copy.kiss_state); /* KissFFT state lost */
    if (!fftw_backend()) {
        TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_dft_check(&plan_copy, 64u));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_dft_real(&plan_copy, 64u, s, re, im));
    }
    plan_copy.path = (mcs_dft_path)9;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_dft_check(&plan_copy, 64u));
    TEST_ASSERT_EQUAL_MEMORY(&before, &plan, sizeof plan);

    for (int half = 0; half < 2; ++half) {
        mcs_status (*fn)(mcs_dft *, size_t, const double *, double *, double *) =
            half ? mcs_dft_real_half : mcs_dft_real;
        TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, fn(NULL, 64u, s, re, im));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, fn(&plan, 64u, NULL, re, im));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, fn(&plan, 64u, s, NULL, im));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, fn(&plan, 63u, s, re, im));
        s[17] = NAN;
        TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, fn(&plan, 64u, s, re, im));
        s[17] = INFINITY;
        TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, fn(&plan, 64u, s, re, im));
        s[17] = 0.5;
        TEST_ASSERT_EQUAL_MEMORY(&before, &plan, sizeof plan);
        TEST_ASSERT_EQUAL_MEMORY(re_before, re, sizeof re);
        TEST_ASSERT_EQUAL_MEMORY(im_before, im, sizeof im);

        memset(&plan_copy, 0, sizeof plan_copy);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, fn(&plan_copy, 64u, s, re, im));
        TEST_ASSERT_EQUAL_MEMORY(re_before, re, sizeof re);
        TEST_ASSERT_EQUAL_MEMORY(im_before, im, sizeof im);
    }
}

/* Issue 10, item 10: re == im returned MCS_OK with one of the two outputs
 * lost, and s inside the plan's work area was overwritten by the transform
 * reading it. Both are refused now; s may still be re or im. */
static void test_aliased_outputs_and_arrays_inside_the_plan_are_refused(void)
{
    static mcs_dft before;
    static double re_before[BIG];
    static const size_t ns[] = {2u, 64u, 75u, 97u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        const size_t n = ns[i];
        fill_random(n, 31u + n);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, n));
        for (size_t k = 0; k < n; ++k)
            re[k] = -3.0;
        memcpy(re_before, re, sizeof re);
        for (int half = 0; half < 2; ++half) {
            mcs_status (*fn)(mcs_dft *, size_t, const double *, double *, double *) =
                half ? mcs_dft_real_half : mcs_dft_real;
            memcpy(&before, &plan, sizeof plan);
            TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, fn(&plan, n, s, re, re));
            TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, fn(&plan, n, s, re, re + 1));
            TEST_ASSERT_EQUAL_MEMORY(re_before, re, sizeof re);
            memcpy(plan.work + 7, s, n * sizeof s[0]);
            memcpy(&before, &plan, sizeof plan);
            TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, fn(&plan, n, plan.work + 7, re, im));
            TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, fn(&plan, n, plan.cos_table, re, im));
            TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, fn(&plan, n, s, plan.work, NULL));
            TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, fn(&plan, n, s, re, plan.sin_table));
            TEST_ASSERT_EQUAL_MEMORY(&before, &plan, sizeof plan);
            TEST_ASSERT_EQUAL_MEMORY(re_before, re, sizeof re);
        }
    }
}

/* Issue 10, item 5 for the transform: finite inputs whose sum passed
 * DBL_MAX gave MCS_OK with infinite outputs. The sum of |s_n| is bounded
 * (MCS_DFT_MAX_ABS_SUM), so a finite input now always gives finite outputs. */
static void test_finite_input_gives_finite_output_or_is_refused(void)
{
    static const size_t ns[] = {1u, 2u, 64u, 75u, 97u, 4096u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        const size_t n = ns[i];
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, n));
        for (size_t j = 0; j < n; ++j) /* the bound, spread with alternating signs */
            s[j] = (j % 2u ? -1.0 : 1.0) * MCS_DFT_MAX_ABS_SUM / (double)n;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, n, s, re, im));
        for (size_t k = 0; k < n; ++k)
            TEST_ASSERT_TRUE(isfinite(re[k]) && isfinite(im[k]));
        s[0] = 2.0 * s[0] + 1e300; /* now above the bound */
        for (size_t k = 0; k < n; ++k)
            re[k] = im[k] = -3.0;
        TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_dft_real(&plan, n, s, re, im));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_dft_real_half(&plan, n, s, re, im));
        for (size_t k = 0; k < n; ++k)
            TEST_ASSERT_TRUE(re[k] == -3.0 && im[k] == -3.0);
    }
    s[0] = 1e308;
    s[1] = 1e308;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, 2u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_dft_real(&plan, 2u, s, re, im));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_n_from_1_to_300_agrees_with_the_naive_dft_to_1e_12);
    RUN_TEST(test_large_n_of_every_path_agree_with_the_naive_dft_to_1e_12);
    RUN_TEST(test_the_back_end_is_named);
    RUN_TEST(test_each_n_is_routed_to_the_path_its_factors_allow);
    RUN_TEST(test_n_1_and_2_give_the_hand_computed_values);
    RUN_TEST(test_the_upper_half_is_the_exact_conjugate_of_the_lower);
    RUN_TEST(test_half_output_matches_the_full_output_and_writes_nothing_beyond);
    RUN_TEST(test_input_may_alias_an_output_and_im_may_be_null);
    RUN_TEST(test_a_copied_plan_gives_the_same_transform);
    RUN_TEST(test_the_avx2_and_baseline_copies_give_the_same_bits);
    RUN_TEST(test_parseval_holds_to_rounding);
    RUN_TEST(test_s0_is_k_over_root_n_for_an_unweighted_pattern);
    RUN_TEST(test_the_estimate_is_the_same_dot_product_in_both_domains);
    RUN_TEST(test_bad_input_returns_an_error_and_changes_nothing);
    RUN_TEST(test_aliased_outputs_and_arrays_inside_the_plan_are_refused);
    RUN_TEST(test_finite_input_gives_finite_output_or_is_refused);
    return UNITY_END();
}
