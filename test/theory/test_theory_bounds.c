/* Tests for the limits of the exact moments (issue 10): the uniform pattern's
 * set-up at the largest K in bounded time with the generator's own counts,
 * a pattern K above MCS_MAX_K refused, the cross matrix's diagonal never
 * negative, integrands above MCS_ESTIMATE_MAX_ABS refused rather than read
 * out as inf or NaN, and re == im refused. The
 * theory itself is tested in test_theory.c and test_theory_spectrum.c. */
#include "mcspec.h"
#include "theory_ref.h"
#include "unity.h"

#include <math.h>
#include <stdint.h>
#include <string.h>
#include <time.h>

void setUp(void) {}
void tearDown(void) {}

#define SENTINEL (-7.25e300)

static mcs_importance imp;
static mcs_pattern pat;
static mcs_theory th, th_copy;
static mcs_theory_spectrum ts, ts_copy;
static mcs_rng rng;
static size_t bins[4096];
static double weights[4096];

static double cpu_seconds(void)
{
    return (double)clock() / (double)CLOCKS_PER_SEC;
}

/* ---- item 4: the uniform pattern at any accepted K --------------------------- */

static void test_uniform_counts_are_the_generators_for_every_small_n_and_k(void)
{
    /* The bisection for the bin counts against the generator's own trial
     * (one draw is the whole uniform pattern), with and without a lumpy
     * importance function, N/K even, odd, and K not dividing N or above it. */
    for (size_t n = 1; n <= 40u; n += (n < 12u ? 1u : 7u)) {
        theory_lumpy_importance(&imp, n);
        for (size_t k = 1; k <= 300u; k += (k < 20u ? 1u : 37u))
            for (int with = 0; with < 2; ++with) {
                const mcs_importance *im = with ? &imp : NULL;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_UNIFORM, n, k, im));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 7u, 11u));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &rng, k, bins, weights, NULL));
                double count[40] = {0.0};
                for (size_t j = 0; j < k; ++j)
                    count[bins[j]] += 1.0;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_init(&ts, &pat));
                if (n <= (size_t)MCS_MAX_COV_N)
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(&th, &pat));
                for (size_t b = 0; b < n; ++b) {
                    const double want = count[b] * (im != NULL ? 1.0 / imp.p[b] : 1.0);
                    TEST_ASSERT_EQUAL_DOUBLE(want, ts.mean_s[b]);
                    if (n <= (size_t)MCS_MAX_COV_N)
                        TEST_ASSERT_EQUAL_DOUBLE(want, th.mean_s[b]);
                }
            }
    }
}

static void test_uniform_theory_at_the_largest_k_is_quick_and_exact(void)
{
    /* K = MCS_MAX_K used to walk 2^30 samples (3.7 s per init, far more with
     * importance). Now each init is O(N log K); without importance the
     * counts are the exact integers floor((2 K c - N - 1) / (2N)) + 1 below
     * bin c, and with importance they still add up to K. */
    const size_t k = (size_t)MCS_MAX_K;
    const size_t sizes[2] = {12u, MCS_MAX_COV_N};
    for (int s = 0; s < 2; ++s) {
        const size_t n = sizes[s];
        theory_lumpy_importance(&imp, n);
        for (int with = 0; with < 2; ++with) {
            const mcs_importance *im = with ? &imp : NULL;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_UNIFORM, n, k, im));
            const double t0 = cpu_seconds();
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(&th, &pat));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_init(&ts, &pat));
            TEST_ASSERT_TRUE_MESSAGE(cpu_seconds() - t0 < 0.25, "uniform set-up at K = 2^30");
            double total = 0.0;
            for (size_t b = 0; b < n; ++b) {
                const double r = th.mean_s[b] * (im != NULL ? imp.p[b] : 1.0);
                TEST_ASSERT_EQUAL_DOUBLE(th.mean_s[b], ts.mean_s[b]);
                total += r;
                if (im == NULL) {
                    const uint64_t lo = b == 0u ? 0u : (2u * k * b - n - 1u) / (2u * n) + 1u;
                    const uint64_t hi = (2u * k * (b + 1u) - n - 1u) / (2u * n) + 1u;
                    TEST_ASSERT_EQUAL_DOUBLE((double)(hi - lo), r);
                }
            }
            theory_assert_close((double)k, total, 1e-12, "sum of the counts");
            double v = SENTINEL;
            static double f[MCS_MAX_COV_N];
            theory_make_f(n, f, 0.3);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&ts, n, k, f, &v));
            TEST_ASSERT_EQUAL_DOUBLE(0.0, v); /* deterministic */
        }
    }
}

static void test_a_pattern_k_above_the_largest_is_refused_by_both_inits(void)
{
    /* mcs_pattern_init never makes one; a hand-set K = SIZE_MAX never
     * returned from the uniform set-up, and is now refused at once. */
    const size_t ks[2] = {(size_t)MCS_MAX_K + 1u, SIZE_MAX};
    for (int i = 0; i < 2; ++i)
        for (int kind = 0; kind < MCS_PATTERN_KIND_COUNT; ++kind) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, (mcs_pattern_kind)kind, 12u, 3u, NULL));
            pat.k = ks[i];
            memset(&th, 0x5A, sizeof th);
            memcpy(&th_copy, &th, sizeof th);
            TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_theory_init(&th, &pat));
            TEST_ASSERT_EQUAL_MEMORY(&th_copy, &th, sizeof th);
            memset(&ts, 0x5A, sizeof ts);
            memcpy(&ts_copy, &ts, sizeof ts);
            TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_theory_spectrum_init(&ts, &pat));
            TEST_ASSERT_EQUAL_MEMORY(&ts_copy, &ts, sizeof ts);
        }
}

/* ---- item 7: powers never negative -------------------------------------------- */

/* Configuration j of the 2 x kinds (kind j / 2, with imp when j is odd) in
 * pat; 0 for the one that is not defined (homogenized with importance). */
static int pattern_of(int j, size_t n, size_t k)
{
    const mcs_pattern_kind kind = (mcs_pattern_kind)(j / 2);
    const mcs_importance *im = j % 2 ? &imp : NULL;
    if (im != NULL && kind == MCS_PATTERN_HOMOGENIZED)
        return 0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, kind, n, k, im));
    return 1;
}

static double mat_re[MCS_MAX_COV_N * MCS_MAX_COV_N], mat_im[MCS_MAX_COV_N * MCS_MAX_COV_N];

static void test_the_cross_matrix_diagonal_and_cross_k_k_are_the_power_and_never_negative(void)
{
    /* The diagonal <|S_k|^2> of mcs_theory_cross_matrix was not clamped as
     * mcs_theory_power is: uniform, N = 2, K = 7 through g = {1, 6} gave
     * -8.9e-16 where S_1 is exactly 0 (fuzz_api). Every kind over a range of
     * N and K, with and without importance: >= 0 and equal to the power. */
    static double w[MCS_MAX_COV_N];
    for (size_t n = 1; n <= (size_t)MCS_MAX_COV_N; n += (n < 8u ? 1u : 9u)) {
        for (size_t b = 0; b < n; ++b)
            w[b] = 1.0 + (double)((b * 5u) % 7u);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, w));
        for (size_t k = 1; k <= 42u; k += (n < 8u ? 1u : 5u))
            for (int j = 0; j < 2 * MCS_PATTERN_KIND_COUNT; ++j) {
                if (!pattern_of(j, n, k))
                    continue;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(&th, &pat));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross_matrix(&th, n, mat_re, mat_im));
                for (size_t q = 0; q < n; ++q) {
                    double power = SENTINEL;
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, q, &power));
                    TEST_ASSERT_TRUE(mat_re[q * n + q] >= 0.0);
                    theory_assert_close(power, mat_re[q * n + q], 1e-12, "diagonal = power");
                    /* mcs_theory_cross(k, k) is the same power (fuzz_api: -1.5e-17) */
                    double cr = SENTINEL, ci = SENTINEL;
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross(&th, q, q, &cr, &ci));
                    TEST_ASSERT_TRUE(cr >= 0.0);
                    theory_assert_close(power, cr, 1e-12, "cross(k, k) = power");
                }
            }
    }
}

/* A power no moments give (below minus its rounding bound: only a corrupted
 * object) is refused by mcs_theory_power and mcs_theory_cross(k, k) as the
 * cross matrix refuses it, nothing written; cross(k, k) is real exactly. */
static void test_a_power_below_its_rounding_bound_is_refused_and_cross_k_k_is_real(void)
{
    static double w[8] = {1.0, 2.0, 3.0, 1.0, 5.0, 1.0, 2.0, 4.0};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 8u, w));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_STRATIFIED, 8u, 3u, &imp));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(&th, &pat));
    for (size_t q = 0; q < 8u; ++q) {
        double cr = SENTINEL, ci = SENTINEL;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross(&th, q, q, &cr, &ci));
        TEST_ASSERT_EQUAL_DOUBLE(0.0, ci);
        TEST_ASSERT_FALSE(signbit(ci));
    }
    /* <s_3 s_3> far below any <s_3>^2: the power is negative at every k */
    th.second[3u * 8u + 3u] = -50.0;
    th_copy = th;
    for (size_t q = 0; q < 8u; ++q) {
        double p = SENTINEL, cr = SENTINEL, ci = SENTINEL;
        TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_theory_power(&th, q, &p));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_theory_cross(&th, q, q, &cr, &ci));
        TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, p);
        TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, cr);
        TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, ci);
    }
    TEST_ASSERT_EQUAL_MEMORY(&th_copy, &th, sizeof th);
}

/* ---- item 5: integrands up to the bound ----------------------------------- */

static double f_max[MCS_MAX_N], g_max[MCS_MAX_N], f_over[MCS_MAX_N];

static void test_integrands_up_to_the_bound_read_out_finite_for_the_heaviest_pattern(void)
{
    /* f of 1e300 gave an infinite Var[I] with MCS_OK. At the bound, with
     * K = MCS_MAX_K samples through the steepest importance function
     * accepted (1/p_0 near 2^32 / N), every estimator read-out is finite and
     * the variance >= 0; one ulp beyond is MCS_ERR_MAGNITUDE, nothing written. */
    const size_t n = 256u, k = (size_t)MCS_MAX_K;
    static double w[256];
    double rest = 0.0;
    for (size_t b = 1; b < n; ++b)
        rest += w[b] = 1.0 + (double)(b % 5u);
    w[0] = 1.01 * MCS_IMPORTANCE_MIN_G * rest;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, w));
    for (size_t b = 0; b < n; ++b) {
        f_max[b] = b % 2u ? -MCS_ESTIMATE_MAX_ABS : MCS_ESTIMATE_MAX_ABS;
        g_max[b] = b % 3u ? MCS_ESTIMATE_MAX_ABS : -MCS_ESTIMATE_MAX_ABS;
        f_over[b] = f_max[b];
    }
    f_over[7] = -nextafter(MCS_ESTIMATE_MAX_ABS, INFINITY);
    for (int j = 0; j < 2 * MCS_PATTERN_KIND_COUNT; ++j) {
        if (!pattern_of(j, n, k))
            continue;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_init(&ts, &pat));
        double v[3] = {SENTINEL, SENTINEL, SENTINEL};
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_estimator_mean(&ts, n, k, f_max, &v[0]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&ts, n, k, f_max, &v[1]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_estimator_covariance(&ts, n, k, f_max,
                                                                               g_max, &v[2]));
        TEST_ASSERT_TRUE(isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]) && v[1] >= 0.0);
        double o = SENTINEL;
        memcpy(&ts_copy, &ts, sizeof ts);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE,
                              mcs_theory_spectrum_estimator_mean(&ts, n, k, f_over, &o));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_theory_spectrum_variance(&ts, n, k, f_over, &o));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_theory_spectrum_estimator_covariance(
                                                     &ts, n, k, f_max, f_over, &o));
        TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, o);
        TEST_ASSERT_EQUAL_MEMORY(&ts_copy, &ts, sizeof ts);
    }
}

/* ---- item 10: one double for both parts of a complex result --------------- */

static void test_a_complex_result_into_one_double_is_refused_and_elsewhere_is_written(void)
{
    /* re == im gave MCS_OK with the real part overwritten by the imaginary
     * one. Refused now, the double untouched; any two doubles work, even
     * two inside the object itself (the result is written last). */
    theory_lumpy_importance(&imp, 12u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_STRATIFIED, 12u, 5u, &imp));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_init(&ts, &pat));
    mcs_status (*const pair[2])(const mcs_theory_spectrum *, size_t, size_t, double *,
                                double *) = {mcs_theory_spectrum_cross,
                                             mcs_theory_spectrum_covariance};
    for (int c = 0; c < 3; ++c) {
        double both = SENTINEL, re = SENTINEL, im = SENTINEL;
        memcpy(&ts_copy, &ts, sizeof ts);
        const mcs_status st = c == 2 ? mcs_theory_spectrum_mean(&ts, 3u, &both, &both)
                                     : pair[c](&ts, 3u, 4u, &both, &both);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, st);
        TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, both);
        TEST_ASSERT_EQUAL_MEMORY(&ts_copy, &ts, sizeof ts);
        /* into the object's own table of sines, entries the call reads */
        const mcs_status sep = c == 2 ? mcs_theory_spectrum_mean(&ts, 3u, &re, &im)
                                      : pair[c](&ts, 3u, 4u, &re, &im);
        TEST_ASSERT_EQUAL_INT(MCS_OK, sep);
        const mcs_status in = c == 2 ? mcs_theory_spectrum_mean(&ts, 3u, &ts.sin_table[1],
                                                               &ts.sin_table[3])
                                     : pair[c](&ts, 3u, 4u, &ts.sin_table[1], &ts.sin_table[3]);
        TEST_ASSERT_EQUAL_INT(MCS_OK, in);
        TEST_ASSERT_EQUAL_DOUBLE(re, ts.sin_table[1]);
        TEST_ASSERT_EQUAL_DOUBLE(im, ts.sin_table[3]);
        memcpy(&ts, &ts_copy, sizeof ts);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_uniform_counts_are_the_generators_for_every_small_n_and_k);
    RUN_TEST(test_uniform_theory_at_the_largest_k_is_quick_and_exact);
    RUN_TEST(test_a_pattern_k_above_the_largest_is_refused_by_both_inits);
    RUN_TEST(test_the_cross_matrix_diagonal_and_cross_k_k_are_the_power_and_never_negative);
    RUN_TEST(test_a_power_below_its_rounding_bound_is_refused_and_cross_k_k_is_real);
    RUN_TEST(test_integrands_up_to_the_bound_read_out_finite_for_the_heaviest_pattern);
    RUN_TEST(test_a_complex_result_into_one_double_is_refused_and_elsewhere_is_written);
    return UNITY_END();
}
