/* Tests for the exact moments (mcs_theory) and the closed forms read from
 * them (eq. 2, 4, 13) on an object whose stored values no mcs_theory_init
 * writes: each read-out returns MCS_ERR_INVARIANT with every output and the
 * object byte for byte unchanged, never a NaN or a negative power or
 * variance with MCS_OK; and every object init does write reads out. (The
 * O(N) exact spectra, mcs_theory_spectrum, have theirs in
 * test_theory_spectrum_corrupt.c.) */
#include "mcspec.h"
#include "theory_ref.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define SENTINEL (-7.25e300)
#define N 12u
#define K 5u

static const mcs_pattern_kind all_kinds[MCS_PATTERN_KIND_COUNT] = {
    MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED, MCS_PATTERN_HOMOGENIZED, MCS_PATTERN_UNIFORM,
    MCS_PATTERN_JITTER};

static mcs_theory th, sound, th_copy;
static mcs_importance imp;
static double f[N], g[N];

/* Every output one call of each read-out writes, filled with SENTINEL first. */
static struct {
    double scalar[2];
    double re[N * N], im[N * N];
} out, out_sentinel;

static void fill_outputs(void)
{
    out.scalar[0] = out.scalar[1] = SENTINEL;
    for (size_t j = 0; j < N * N; ++j)
        out.re[j] = out.im[j] = SENTINEL;
    memcpy(&out_sentinel, &out, sizeof out);
}

/* The read-outs of a mcs_theory, by number: what each reads decides which
 * corruption it must see. */
enum {
    R_BIN_MEAN,
    R_BIN_SECOND,
    R_MEAN,
    R_POWER,
    R_CROSS,
    R_COVARIANCE,
    R_CROSS_MATRIX,
    R_COVARIANCE_MATRIX,
    R_ESTIMATOR_MEAN,
    R_VARIANCE,
    R_ESTIMATOR_COVARIANCE,
    R_EQ2,
    R_EQ4,
    R_EQ13,
    R_COUNT
};

static const char *const names[R_COUNT] = {
    "bin_mean", "bin_second", "mean", "power", "cross", "covariance", "cross_matrix",
    "covariance_matrix", "estimator_mean", "variance", "estimator_covariance", "eq2", "eq4",
    "eq13"};

/* Read-out r of th at bins (a, b) (or frequencies), into out. */
static mcs_status read_out(int r, size_t a, size_t b)
{
    double *x = &out.scalar[0], *y = &out.scalar[1];
    switch (r) {
    case R_BIN_MEAN: return mcs_theory_bin_mean(&th, a, x);
    case R_BIN_SECOND: return mcs_theory_bin_second(&th, a, b, x);
    case R_MEAN: return mcs_theory_mean(&th, a, x, y);
    case R_POWER: return mcs_theory_power(&th, a, x);
    case R_CROSS: return mcs_theory_cross(&th, a, b, x, y);
    case R_COVARIANCE: return mcs_theory_covariance(&th, a, b, x, y);
    case R_CROSS_MATRIX: return mcs_theory_cross_matrix(&th, N, out.re, out.im);
    case R_COVARIANCE_MATRIX: return mcs_theory_covariance_matrix(&th, N, out.re, out.im);
    case R_ESTIMATOR_MEAN: return mcs_theory_estimator_mean(&th, N, K, f, x);
    case R_VARIANCE: return mcs_theory_variance(&th, N, K, f, x);
    case R_ESTIMATOR_COVARIANCE: return mcs_theory_estimator_covariance(&th, N, K, f, g, x);
    case R_EQ2: return mcs_eq2_uncorrelated_variance(&th, N, K, f, g, x);
    case R_EQ4: return mcs_eq4_correlated_variance(&th, N, K, f, g, x);
    default: return mcs_eq13_variance(&th, N, K, f, x);
    }
}

/* Read-out r on the corrupted th: MCS_ERR_INVARIANT, nothing written, th
 * unchanged. */
static void assert_refused(int r, size_t a, size_t b, const char *what)
{
    char msg[160];
    snprintf(msg, sizeof msg, "%s: %s at (%zu, %zu)", what, names[r], a, b);
    memcpy(&th_copy, &th, sizeof th);
    fill_outputs();
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT, read_out(r, a, b), msg);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&out_sentinel, &out, sizeof out, msg);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&th_copy, &th, sizeof th, msg);
}

/* Pattern j of the sweeps: every kind, without (even j) and with importance. */
static int init_sound(int j)
{
    const mcs_importance *im = j % 2 ? &imp : NULL;
    if (im != NULL && all_kinds[j / 2] == MCS_PATTERN_HOMOGENIZED)
        return 0;
    theory_init(&sound, all_kinds[j / 2], N, K, im);
    memcpy(&th, &sound, sizeof th);
    return 1;
}

static void prepare(void)
{
    theory_lumpy_importance(&imp, N);
    theory_make_f(N, f, 0.7);
    theory_make_f(N, g, 2.1);
}

#define NBAD 5
static const double bad_common[NBAD] = {(double)NAN, -1e9, 1e300, (double)INFINITY, -1e-300};

/* <s_b> NaN, negative, huge or infinite: every read-out refuses it, wherever
 * b is (the O(N) part of the object is checked by every read-out). */
static void test_a_corrupted_mean_is_refused_by_every_read_out(void)
{
    prepare();
    for (int j = 0; j < 2 * MCS_PATTERN_KIND_COUNT; ++j) {
        if (!init_sound(j))
            continue;
        for (size_t b = 0; b < N; b += 5u)
            for (int v = 0; v < NBAD; ++v) {
                th.mean_s[b] = bad_common[v];
                for (int r = 0; r < R_COUNT; ++r)
                    assert_refused(r, (b + 1u) % N, 2u, "mean_s");
                th.mean_s[b] = sound.mean_s[b];
            }
        TEST_ASSERT_EQUAL_MEMORY(&sound, &th, sizeof th);
    }
}

/* A twiddle NaN or outside [-1, 1], and a has_importance init never writes. */
static void test_a_corrupted_twiddle_or_flag_is_refused_by_every_read_out(void)
{
    static const double bad[4] = {(double)NAN, -1e9, 1e300, 1.5};
    prepare();
    for (int j = 0; j < 2 * MCS_PATTERN_KIND_COUNT; ++j) {
        if (!init_sound(j))
            continue;
        for (size_t b = 1; b < N; b += 4u)
            for (int v = 0; v < 4; ++v)
                for (int table = 0; table < 2; ++table) {
                    double *t = table == 0 ? th.cos_table : th.sin_table;
                    t[b] = bad[v];
                    for (int r = 0; r < R_COUNT; ++r)
                        assert_refused(r, 3u, 1u, table == 0 ? "cos_table" : "sin_table");
                    t[b] = (table == 0 ? sound.cos_table : sound.sin_table)[b];
                }
        th.has_importance = 2;
        for (int r = 0; r < R_COUNT; ++r)
            assert_refused(r, 1u, 2u, "has_importance");
        th.has_importance = sound.has_importance;
        TEST_ASSERT_EQUAL_MEMORY(&sound, &th, sizeof th);
    }
}

/* Whether read-out r reads the whole second-moment matrix (bin_mean, mean
 * and estimator_mean read only <s>; bin_second reads its entry). */
static int reads_second(int r)
{
    return r != R_BIN_MEAN && r != R_MEAN && r != R_ESTIMATOR_MEAN && r != R_BIN_SECOND;
}

/* <s_b s_b> NaN, negative, huge, infinite, or below <s_b>^2 (a negative
 * variance of s_b): refused by every read-out of the matrix and by
 * bin_second at (b, b) and on b's row. */
static void test_a_corrupted_diagonal_second_moment_is_refused(void)
{
    prepare();
    for (int j = 0; j < 2 * MCS_PATTERN_KIND_COUNT; ++j) {
        if (!init_sound(j))
            continue;
        for (size_t b = 0; b < N; b += 3u) {
            const size_t at = b * N + b;
            const double m = sound.mean_s[b];
            for (int v = 0; v <= NBAD; ++v) {
                th.second[at] = v < NBAD ? bad_common[v] : 0.25 * m * m - 1e-3;
                for (int r = 0; r < R_COUNT; ++r)
                    if (reads_second(r))
                        assert_refused(r, (b + 2u) % N, b, "diagonal");
                assert_refused(R_BIN_SECOND, b, b, "diagonal");
                assert_refused(R_BIN_SECOND, b, (b + 5u) % N, "diagonal, its row");
                assert_refused(R_BIN_SECOND, (b + 7u) % N, b, "diagonal, its column");
                th.second[at] = sound.second[at];
            }
        }
        TEST_ASSERT_EQUAL_MEMORY(&sound, &th, sizeof th);
    }
}

/* <s_a s_b>, a != b, NaN, negative (beyond rounding: 1e-3 of
 * sqrt(<s_a^2> <s_b^2>), which init's rounding never reaches), huge,
 * infinite or past Cauchy-Schwarz (above sqrt(<s_a^2> <s_b^2>)): refused by
 * every read-out of the matrix and by bin_second at (a, b). */
static void test_a_corrupted_off_diagonal_second_moment_is_refused(void)
{
    prepare();
    for (int j = 0; j < 2 * MCS_PATTERN_KIND_COUNT; ++j) {
        if (!init_sound(j))
            continue;
        for (size_t a = 0; a < N; a += 4u) {
            const size_t b = (a + 5u) % N, at = a * N + b;
            const double cs = sqrt(sound.second[a * N + a] * sound.second[b * N + b]);
            for (int v = 0; v <= NBAD; ++v) {
                th.second[at] = v < NBAD - 1 ? bad_common[v] : v == NBAD - 1 ? -1e-3 * cs - 1e-300
                                                                           : 2.0 * cs + 1.0;
                for (int r = 0; r < R_COUNT; ++r)
                    if (reads_second(r))
                        assert_refused(r, 1u, 4u, "off-diagonal");
                assert_refused(R_BIN_SECOND, a, b, "off-diagonal");
                th.second[at] = sound.second[at];
            }
        }
        TEST_ASSERT_EQUAL_MEMORY(&sound, &th, sizeof th);
    }
}

/* Moments that each pass their own bounds but no pattern has: <s_n> = 1,
 * <s_n^2> = 1 and <s_m s_n> = 1 for neighbours m = n +- 1, else 0, over
 * N = 4 bins. The form y^T <s s^T> y of the zero-mean y = (1, -1, 1, -1) is
 * -2, so the power at k = 2, the variance of y and eq. 2, 4 and 13 of it
 * would be negative: refused, nothing written. (The power and the
 * covariance matrix refused it already; the others returned it.) */
static void test_moments_no_pattern_has_give_no_negative_power_or_variance(void)
{
    static const double y[4] = {1.0, -1.0, 1.0, -1.0}, zero[4] = {0.0, 0.0, 0.0, 0.0};
    theory_init(&th, MCS_PATTERN_RANDOM, 4u, K, NULL);
    for (size_t m = 0; m < 4u; ++m) {
        th.mean_s[m] = 1.0;
        for (size_t c = 0; c < 4u; ++c)
            th.second[m * 4u + c] = (m > c ? m - c : c - m) <= 1u ? 1.0 : 0.0;
    }
    memcpy(&th_copy, &th, sizeof th);
    for (int r = 0; r < 7; ++r) {
        fill_outputs();
        double *x = &out.scalar[0];
        mcs_status st;
        switch (r) {
        case 0: st = mcs_theory_power(&th, 2u, x); break;
        case 1: st = mcs_theory_cross_matrix(&th, 4u, out.re, out.im); break;
        case 2: st = mcs_theory_covariance_matrix(&th, 4u, out.re, out.im); break;
        case 3: st = mcs_theory_variance(&th, 4u, K, y, x); break;
        case 4: st = mcs_eq2_uncorrelated_variance(&th, 4u, K, y, y, x); break;
        case 5: st = mcs_eq4_correlated_variance(&th, 4u, K, y, zero, x); break;
        default: st = mcs_eq13_variance(&th, 4u, K, y, x); break;
        }
        TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_ERR_INVARIANT, st, "read-out of impossible moments");
        TEST_ASSERT_EQUAL_MEMORY(&out_sentinel, &out, sizeof out);
        TEST_ASSERT_EQUAL_MEMORY(&th_copy, &th, sizeof th);
    }
}

/* A jitter pattern whose bins 2, 4, 7 and 9 carry importance weights near
 * the smallest accepted (1/p near 2.5e8): init's rounding of the bin edges
 * (in t = u K units) leaves its odd powers at -8.7 against a scale of 2e8,
 * far below the shared read-out's own rounding bound, which refused them
 * as moments no pattern has (MCS_ERR_INVARIANT from power, cross(k, k),
 * covariance(k, k) and the covariance matrix; the cross matrix returned
 * -1.9 on its diagonal). They are rounding: each reads >= 0. */
static void test_the_powers_of_a_pattern_with_tiny_bins_read_out_not_refused(void)
{
    static double w[10], mre[100], mim[100];
    for (size_t b = 0; b < 10u; ++b)
        w[b] = b == 2u || b == 4u || b == 7u || b == 9u ? 2.33e-10 * 10.0 * 1.01 : 1.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 10u, w));
    theory_init(&th, MCS_PATTERN_JITTER, 10u, 10u, &imp);
    for (size_t q = 0; q < 10u; ++q) {
        double p = SENTINEL, re = SENTINEL, im = SENTINEL;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, q, &p));
        TEST_ASSERT_TRUE(p >= 0.0);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross(&th, q, q, &re, &im));
        TEST_ASSERT_EQUAL_MEMORY(&p, &re, sizeof p);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_covariance(&th, q, q, &re, &im));
        TEST_ASSERT_TRUE(re >= 0.0);
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross_matrix(&th, 10u, mre, mim));
    for (size_t q = 0; q < 10u; ++q)
        TEST_ASSERT_TRUE(mre[q * 10u + q] >= 0.0);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_covariance_matrix(&th, 10u, mre, mim));
    for (size_t q = 0; q < 10u; ++q)
        TEST_ASSERT_TRUE(mre[q * 10u + q] >= 0.0);
}

/* Every object mcs_theory_init writes passes the checks: every kind, with
 * and without importance (a lumpy one, and one with a weight at the
 * smallest accepted 2^-32 of the total, whose 1/p is near 2^32 / N), K
 * below, at and above N, up to MCS_MAX_K; each entry read by bin_second,
 * and every read-out of the whole matrix once. */
static mcs_theory big;

static void test_every_object_init_writes_reads_out(void)
{
    static double w[MCS_MAX_COV_N];
    static double fb[MCS_MAX_COV_N], gb[MCS_MAX_COV_N];
    static double mre[MCS_MAX_COV_N * MCS_MAX_COV_N], mim[MCS_MAX_COV_N * MCS_MAX_COV_N];
    static const size_t ns[] = {1u, 2u, 3u, 7u, 12u, 31u, 64u};
    static const size_t ks[] = {1u, 2u, 5u, 12u, 64u, 1000u, 123457u, (size_t)MCS_MAX_K};
    for (size_t a = 0; a < sizeof ns / sizeof ns[0]; ++a)
        for (size_t c = 0; c < sizeof ks / sizeof ks[0]; ++c)
            for (int wi = 0; wi < 3; ++wi)
                for (int kind = 0; kind < MCS_PATTERN_KIND_COUNT; ++kind) {
                    const size_t n = ns[a], k = ks[c];
                    const mcs_importance *im = NULL;
                    if (wi > 0) {
                        if (all_kinds[kind] == MCS_PATTERN_HOMOGENIZED)
                            continue;
                        for (size_t b = 0; b < n; ++b)
                            w[b] = wi == 1 ? 0.3 + (double)((b * 7u) % 5u) : 1.0;
                        if (wi == 2)
                            w[n / 2u] = 0x1p-32 * (double)n * 1.0000001;
                        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, w));
                        im = &imp;
                    }
                    theory_init(&big, all_kinds[kind], n, k, im);
                    theory_make_f(n, fb, 0.3);
                    theory_make_f(n, gb, 1.9);
                    for (size_t m = 0; m < n; ++m)
                        for (size_t q = 0; q < n; ++q) {
                            double x = SENTINEL;
                            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_bin_second(&big, m, q, &x));
                        }
                    double v, vi;
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&big, n / 3u, &v));
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_covariance(&big, 0u, n - 1u, &v, &vi));
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross_matrix(&big, n, mre, mim));
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_covariance_matrix(&big, n, mre, mim));
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&big, n, k, fb, &v));
                    TEST_ASSERT_EQUAL_INT(MCS_OK,
                                          mcs_eq2_uncorrelated_variance(&big, n, k, fb, gb, &v));
                    TEST_ASSERT_EQUAL_INT(MCS_OK,
                                          mcs_eq4_correlated_variance(&big, n, k, fb, gb, &v));
                    if (n <= 12u)
                        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq13_variance(&big, n, k, fb, &v));
                }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_corrupted_mean_is_refused_by_every_read_out);
    RUN_TEST(test_a_corrupted_twiddle_or_flag_is_refused_by_every_read_out);
    RUN_TEST(test_a_corrupted_diagonal_second_moment_is_refused);
    RUN_TEST(test_a_corrupted_off_diagonal_second_moment_is_refused);
    RUN_TEST(test_moments_no_pattern_has_give_no_negative_power_or_variance);
    RUN_TEST(test_the_powers_of_a_pattern_with_tiny_bins_read_out_not_refused);
    RUN_TEST(test_every_object_init_writes_reads_out);
    return UNITY_END();
}
