#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mcspec.h"
#include "spectra_ref.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define PI 3.14159265358979323846

static mcs_spectrum acc, acc2, acc3, before;
static mcs_importance imp;
static size_t bins[256];
static double weights[256], points[256], dense[MCS_MAX_N];

/* |a - b| <= tol * (|b| + scale) */
static void assert_close(double expected, double actual, double tol, double scale,
                         const char *what, size_t freq)
{
    if (!(fabs(actual - expected) <= tol * (fabs(expected) + scale))) {
        char msg[128];
        (void)snprintf(msg, sizeof msg, "%s at k = %zu: expected %.17g, got %.17g", what, freq,
                       expected, actual);
        TEST_FAIL_MESSAGE(msg);
    }
}

/* Every read-out of a and b agrees to tol, relative to the natural scale of
 * each frequency (sqrt of its power for S_k, its power for |S_k|^2). */
static void assert_same_statistics(const mcs_spectrum *a, const mcs_spectrum *b, double tol)
{
    uint64_t ca, cb;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_count(a, &ca));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_count(b, &cb));
    TEST_ASSERT_EQUAL_UINT64(ca, cb);
    for (size_t k = 0; k < a->n; ++k) {
        double ar, ai, br, bi, ap, bp, as, bs, aps, bps;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(a, k, &ar, &ai));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(b, k, &br, &bi));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(a, k, &ap));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(b, k, &bp));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(a, k, &as));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(b, k, &bs));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(a, k, &aps));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(b, k, &bps));
        const double amp = sqrt(bp);
        assert_close(br, ar, tol, amp, "Re <S_k>", k);
        assert_close(bi, ai, tol, amp, "Im <S_k>", k);
        assert_close(bp, ap, tol, 0.0, "<|S_k|^2>", k);
        /* Standard errors come from M2, a difference of nearby quantities for
         * a deterministic S_k; compare them on the scale of the value. */
        assert_close(bs, as, 1e3 * tol, amp, "stderr <S_k>", k);
        assert_close(bps, aps, 1e3 * tol, bp, "stderr <|S_k|^2>", k);
    }
}

/* Every stream of this file uses PCG32 sequence 0x5eedu. */
#define STREAM_SEQ 0x5eedu

static void stream_draw(spectra_stream *st)
{
    spectra_stream_draw(st, bins, weights, points);
}

/* Feeds `trials` trials of a pattern to acc. */
static void run(mcs_spectrum *a, mcs_pattern_kind kind, size_t n, size_t k,
                const mcs_importance *importance, uint64_t seed, size_t trials)
{
    spectra_stream st;
    spectra_stream_init(&st, kind, n, k, importance, seed, STREAM_SEQ);
    for (size_t t = 0; t < trials; ++t) {
        stream_draw(&st);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(a, k, bins, weights));
    }
}

static void make_importance(size_t n)
{
    static double g[MCS_MAX_N];
    for (size_t b = 0; b < n; ++b)
        g[b] = 0.2 + (double)((b * 7u) % n) / (double)n + (b == 3u ? 2.0 : 0.0);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, g));
}

/* ---------------- identities to rounding ---------------- */

static void test_sparse_and_fft_paths_give_the_same_statistics(void)
{
    static const struct {
        size_t n, k;
        int importance;
    } cases[] = {{1u, 3u, 0}, {2u, 5u, 0}, {7u, 5u, 1},  {16u, 4u, 0},
                 {45u, 9u, 1}, {64u, 13u, 0}, {100u, 30u, 1}, {1024u, 6u, 0},
                 {13u, 40u, 1}, {26u, 20u, 0}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        size_t n = cases[i].n, k = cases[i].k;
        const mcs_importance *ip = NULL;
        if (cases[i].importance) {
            make_importance(n);
            ip = &imp;
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc2, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc3, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_path(&acc, MCS_SPECTRUM_PATH_SPARSE));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_path(&acc2, MCS_SPECTRUM_PATH_FFT));
        spectra_stream st;
        spectra_stream_init(&st, MCS_PATTERN_STRATIFIED, n, k, ip, 100u + i, STREAM_SEQ);
        for (size_t t = 0; t < 200u; ++t) {
            stream_draw(&st);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, k, bins, weights));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc2, k, bins, weights));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc3, k, bins, weights));
        }
        assert_same_statistics(&acc, &acc2, 1e-12);
        assert_same_statistics(&acc3, &acc2, 1e-12);
    }
}

static void test_bins_dense_and_points_give_the_same_statistics(void)
{
    static const size_t ns[] = {7u, 32u, 90u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        size_t n = ns[i], k = 11u;
        make_importance(n);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc2, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc3, n));
        spectra_stream st;
        spectra_stream_init(&st, MCS_PATTERN_RANDOM, n, k, &imp, 7u + i, STREAM_SEQ);
        for (size_t t = 0; t < 100u; ++t) {
            stream_draw(&st);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, k, bins, weights));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_dense(n, k, bins, weights, dense));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_dense(&acc2, n, dense));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_points(&acc3, k, points, weights));
        }
        assert_same_statistics(&acc2, &acc, 1e-12);
        assert_same_statistics(&acc3, &acc, 1e-12);
    }
}

static void test_points_without_weights_count_as_weight_one(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 20u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc2, 20u));
    spectra_stream st;
    spectra_stream_init(&st, MCS_PATTERN_JITTER, 20u, 6u, NULL, 3u, STREAM_SEQ);
    for (size_t t = 0; t < 50u; ++t) {
        stream_draw(&st);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_points(&acc, 6u, points, NULL));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc2, 6u, bins, weights));
    }
    assert_same_statistics(&acc, &acc2, 1e-12);
}

static void test_one_trial_matches_the_naive_dft(void)
{
    static double re[MCS_MAX_N], im[MCS_MAX_N];
    static const size_t ns[] = {5u, 64u, 97u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        size_t n = ns[i];
        for (int path = 1; path <= 2; ++path) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, n));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_path(&acc, (mcs_spectrum_path)path));
            spectra_stream st;
            spectra_stream_init(&st, MCS_PATTERN_RANDOM, n, 9u, NULL, 5u, STREAM_SEQ);
            stream_draw(&st);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, 9u, bins, weights));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_dense(n, 9u, bins, weights, dense));
            spectra_naive_dft(n, dense, n, re, im);
            for (size_t k = 0; k < n; ++k) {
                double mr, mi, p;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&acc, k, &mr, &mi));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&acc, k, &p));
                assert_close(re[k], mr, 1e-13, 1.0, "Re S_k", k);
                assert_close(im[k], mi, 1e-13, 1.0, "Im S_k", k);
                assert_close(re[k] * re[k] + im[k] * im[k], p, 1e-13, 1.0, "|S_k|^2", k);
            }
        }
    }
}

static void test_s0_is_k_over_root_n_in_every_trial_without_importance(void)
{
    static const size_t ns[] = {16u, 30u, 256u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        size_t n = ns[i];
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, n));
        run(&acc, MCS_PATTERN_RANDOM, n, 12u, NULL, 1u, 300u);
        double re, im, se, p, pse;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&acc, 0u, &re, &im));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(&acc, 0u, &se));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&acc, 0u, &p));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(&acc, 0u, &pse));
        const double s0 = 12.0 / sqrt((double)n);
        TEST_ASSERT_DOUBLE_WITHIN(1e-13 * s0, s0, re);
        TEST_ASSERT_EQUAL_DOUBLE(0.0, im);
        TEST_ASSERT_DOUBLE_WITHIN(1e-13 * s0 * s0, s0 * s0, p);
        /* Welford: a constant has no spread, not a cancellation residue. */
        TEST_ASSERT_TRUE(se < 1e-13 * s0);
        TEST_ASSERT_TRUE(pse < 1e-13 * s0 * s0);
    }
}

static void test_parseval_holds_for_every_trial(void)
{
    /* One trial: sum_k |S_k|^2 = sum_n s_n^2, read back through the symmetric half. */
    static const size_t ns[] = {9u, 64u, 77u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        size_t n = ns[i];
        make_importance(n);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, n));
        run(&acc, MCS_PATTERN_STRATIFIED, n, 7u, &imp, 2u, 1u);
        double energy = 0.0, total = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_dense(n, 7u, bins, weights, dense));
        for (size_t b = 0; b < n; ++b)
            energy += dense[b] * dense[b];
        for (size_t k = 0; k < n; ++k) {
            double p;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&acc, k, &p));
            total += p;
        }
        TEST_ASSERT_DOUBLE_WITHIN(1e-13 * energy, energy, total);
    }
}

static void test_merge_of_halves_equals_one_pass(void)
{
    static const size_t ns[] = {12u, 64u, 101u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        size_t n = ns[i], k = 5u;
        make_importance(n);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc2, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc3, n));
        spectra_stream st;
        spectra_stream_init(&st, MCS_PATTERN_RANDOM, n, k, &imp, 40u + i, STREAM_SEQ);
        for (size_t t = 0; t < 700u; ++t) {
            stream_draw(&st);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, k, bins, weights));
            mcs_spectrum *half = t < 300u ? &acc2 : &acc3;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(half, k, bins, weights));
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_merge(&acc2, &acc3));
        assert_same_statistics(&acc2, &acc, 1e-12);
    }
}

static void test_merge_with_an_empty_side_copies_or_keeps(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 24u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc2, 24u));
    run(&acc, MCS_PATTERN_JITTER, 24u, 4u, NULL, 9u, 50u);
    memcpy(&before, &acc, sizeof acc);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_merge(&acc, &acc2)); /* empty src */
    TEST_ASSERT_EQUAL_MEMORY(&before, &acc, sizeof acc);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_merge(&acc2, &acc)); /* empty dst */
    assert_same_statistics(&acc2, &acc, 0.0);
}

static void test_merge_with_itself_doubles_the_count_and_keeps_the_means(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 10u));
    run(&acc, MCS_PATTERN_RANDOM, 10u, 3u, NULL, 4u, 40u);
    memcpy(&before, &acc, sizeof acc);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_merge(&acc, &acc));
    TEST_ASSERT_EQUAL_UINT64(80u, acc.count);
    for (size_t k = 0; k < 10u; ++k) {
        double a, b;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&acc, k, &a));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&before, k, &b));
        TEST_ASSERT_EQUAL_DOUBLE(b, a);
    }
}

static void test_a_copied_accumulator_keeps_working(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 48u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc2, 48u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_path(&acc, MCS_SPECTRUM_PATH_FFT));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_path(&acc2, MCS_SPECTRUM_PATH_FFT));
    run(&acc, MCS_PATTERN_RANDOM, 48u, 5u, NULL, 8u, 10u);
    run(&acc2, MCS_PATTERN_RANDOM, 48u, 5u, NULL, 8u, 10u);
    memcpy(&acc3, &acc, sizeof acc);
    memset(&acc, 0x5a, sizeof acc);
    run(&acc3, MCS_PATTERN_RANDOM, 48u, 5u, NULL, 18u, 10u);
    run(&acc2, MCS_PATTERN_RANDOM, 48u, 5u, NULL, 18u, 10u);
    assert_same_statistics(&acc3, &acc2, 0.0);
}

/* ---------------- the note's spectra, measured ---------------- */

/* Asserts |measured - predicted| < 5 stderr (or 1e-12 of the scale when the
 * quantity is deterministic) for <|S_k|^2> at every frequency selected by
 * `predict` (returns 0 to skip), and <S_k> = 0 for k != 0 unless skip_mean. */
typedef double (*power_fn)(size_t n, size_t k, size_t freq, double h, int *use);

static void assert_spectrum(const mcs_spectrum *a, size_t k, double h, power_fn predict,
                            int check_mean)
{
    const size_t n = a->n;
    for (size_t f = 0; f < n; ++f) {
        int use = 1;
        const double want = predict(n, k, f, h, &use);
        double p, pse;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(a, f, &p));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(a, f, &pse));
        const double scale = (double)(k * k) / (double)n;
        if (use && !(fabs(p - want) <= 5.0 * pse + 1e-12 * scale)) {
            char msg[160];
            (void)snprintf(msg, sizeof msg,
                           "<|S_%zu|^2>: measured %.6g +- %.2g, predicted %.6g (%.1f se)", f,
                           p, pse, want, fabs(p - want) / pse);
            TEST_FAIL_MESSAGE(msg);
        }
        if (check_mean && f != 0u) {
            double re, im, se;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(a, f, &re, &im));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(a, f, &se));
            const double mag = sqrt(re * re + im * im);
            /* |<S_k>| of a zero-mean complex estimate: 5 se on the modulus */
            if (!(mag <= 5.0 * se + 1e-12 * sqrt(scale))) {
                char msg[128];
                (void)snprintf(msg, sizeof msg, "<S_%zu> = %.3g + %.3gi, stderr %.3g", f, re,
                               im, se);
                TEST_FAIL_MESSAGE(msg);
            }
        }
    }
}

static double random_power(size_t n, size_t k, size_t f, double h, int *use)
{
    (void)h;
    *use = f != 0u;
    return (double)k / (double)n; /* eq. 23 */
}

static double stratified_power(size_t n, size_t k, size_t f, double h, int *use)
{
    (void)h;
    *use = f != 0u;
    const double kn = (double)k / (double)n;
    const double a = sin(PI * (double)f / (double)k), b = sin(PI * (double)f / (double)n);
    return kn - kn * kn * kn * (a * a) / (b * b); /* exact finite-N form of eq. 33 */
}

static double jitter_power(size_t n, size_t k, size_t f, double h, int *use)
{
    (void)h;
    *use = f != 0u;
    return f % k == 0u ? (double)(k * k) / (double)n : 0.0; /* eq. 37 */
}

static double importance_power(size_t n, size_t k, size_t f, double h, int *use)
{
    *use = 1;
    const double kn = (double)k / (double)n;
    if (f == 0u)
        return (double)(k * k) / (double)n + kn * (1.0 / h - 1.0); /* eq. 46 */
    return kn / h;                                                  /* eq. 45 */
}

static void test_random_power_is_k_over_n_and_mean_is_zero(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 16u));
    run(&acc, MCS_PATTERN_RANDOM, 16u, 4u, NULL, 23u, 200000u);
    assert_spectrum(&acc, 4u, 1.0, random_power, 1);
}

static void test_stratified_power_follows_the_exact_finite_n_form(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 32u));
    run(&acc, MCS_PATTERN_STRATIFIED, 32u, 4u, NULL, 29u, 400000u);
    assert_spectrum(&acc, 4u, 1.0, stratified_power, 1);
}

static void test_jitter_power_is_k2_over_n_at_multiples_of_k_and_zero_elsewhere(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 24u));
    run(&acc, MCS_PATTERN_JITTER, 24u, 4u, NULL, 31u, 20000u);
    assert_spectrum(&acc, 4u, 1.0, jitter_power, 1);
}

static void test_uniform_is_biased_at_multiples_of_k(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 24u));
    run(&acc, MCS_PATTERN_UNIFORM, 24u, 4u, NULL, 37u, 10u);
    for (size_t f = 0; f < 24u; ++f) {
        double re, im;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&acc, f, &re, &im));
        const double mag = sqrt(re * re + im * im);
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, f % 4u == 0u ? 4.0 / sqrt(24.0) : 0.0, mag);
    }
}

static void test_importance_sampled_random_power_is_k_over_n_h(void)
{
    make_importance(12u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 12u));
    run(&acc, MCS_PATTERN_RANDOM, 12u, 3u, &imp, 41u, 200000u);
    assert_spectrum(&acc, 3u, imp.harmonic_mean, importance_power, 1);
}

/* ---------------- bad input ---------------- */

#define EXPECT_UNCHANGED(status, call)                                                       \
    do {                                                                                     \
        memcpy(&before, &acc, sizeof acc);                                                   \
        TEST_ASSERT_EQUAL_INT((status), (call));                                             \
        TEST_ASSERT_EQUAL_MEMORY(&before, &acc, sizeof acc);                                 \
    } while (0)

static void test_bad_input_returns_an_error_and_changes_nothing(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 20u));
    run(&acc, MCS_PATTERN_RANDOM, 20u, 4u, NULL, 1u, 5u);
    size_t b[4] = {1u, 2u, 3u, 19u};
    double w[4] = {1.0, 1.0, 1.0, 1.0};
    double x[4] = {0.1, 0.2, 0.3, 0.999};

    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_init(NULL, 20u));
    EXPECT_UNCHANGED(MCS_ERR_N_RANGE, mcs_spectrum_init(&acc, 0u));
    EXPECT_UNCHANGED(MCS_ERR_N_RANGE, mcs_spectrum_init(&acc, (size_t)MCS_MAX_N + 1u));

    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_set_path(NULL, MCS_SPECTRUM_PATH_FFT));
    EXPECT_UNCHANGED(MCS_ERR_KIND, mcs_spectrum_set_path(&acc, (mcs_spectrum_path)7));

    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_add_bins(&acc, 4u, NULL, w));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_add_bins(&acc, 4u, b, NULL));
    EXPECT_UNCHANGED(MCS_ERR_K_RANGE, mcs_spectrum_add_bins(&acc, 0u, b, w));
    b[3] = 20u;
    EXPECT_UNCHANGED(MCS_ERR_BIN_RANGE, mcs_spectrum_add_bins(&acc, 4u, b, w));
    b[3] = 19u;
    w[3] = NAN;
    EXPECT_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_spectrum_add_bins(&acc, 4u, b, w));
    EXPECT_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_spectrum_add_points(&acc, 4u, x, w));
    w[3] = INFINITY;
    EXPECT_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_spectrum_add_bins(&acc, 4u, b, w));
    w[3] = -1.0;
    EXPECT_UNCHANGED(MCS_ERR_NEGATIVE, mcs_spectrum_add_bins(&acc, 4u, b, w));
    EXPECT_UNCHANGED(MCS_ERR_NEGATIVE, mcs_spectrum_add_points(&acc, 4u, x, w));
    w[3] = 1.0;

    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_add_points(&acc, 4u, NULL, w));
    EXPECT_UNCHANGED(MCS_ERR_K_RANGE, mcs_spectrum_add_points(&acc, 0u, x, w));
    x[2] = 1.0;
    EXPECT_UNCHANGED(MCS_ERR_POINT_RANGE, mcs_spectrum_add_points(&acc, 4u, x, w));
    x[2] = -0.1;
    EXPECT_UNCHANGED(MCS_ERR_POINT_RANGE, mcs_spectrum_add_points(&acc, 4u, x, NULL));
    x[2] = NAN;
    EXPECT_UNCHANGED(MCS_ERR_POINT_RANGE, mcs_spectrum_add_points(&acc, 4u, x, NULL));
    x[2] = 0.3;

    for (size_t j = 0; j < 20u; ++j)
        dense[j] = 0.5;
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_add_dense(&acc, 20u, NULL));
    EXPECT_UNCHANGED(MCS_ERR_MISMATCH, mcs_spectrum_add_dense(&acc, 19u, dense));
    dense[7] = NAN;
    EXPECT_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_spectrum_add_dense(&acc, 20u, dense));
    dense[7] = -0.5;
    EXPECT_UNCHANGED(MCS_ERR_NEGATIVE, mcs_spectrum_add_dense(&acc, 20u, dense));
    dense[7] = 0.5;

    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc2, 21u));
    run(&acc2, MCS_PATTERN_RANDOM, 21u, 4u, NULL, 2u, 5u);
    EXPECT_UNCHANGED(MCS_ERR_MISMATCH, mcs_spectrum_merge(&acc, &acc2));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_merge(&acc, NULL));
    memset(&acc3, 0, sizeof acc3);
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_merge(&acc, &acc3));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_merge(NULL, &acc));
}

static void test_bad_read_outs_return_an_error_and_leave_the_outputs_alone(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 20u));
    run(&acc, MCS_PATTERN_RANDOM, 20u, 4u, NULL, 1u, 5u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc2, 21u));
    size_t b[4] = {1u, 2u, 3u, 19u};
    double w[4] = {1.0, 1.0, 1.0, 1.0};
    double x[4] = {0.1, 0.2, 0.3, 0.999};
    for (size_t j = 0; j < 20u; ++j)
        dense[j] = 0.5;
    double re = 7.0, im = 7.0, v = 7.0;
    uint64_t c = 7u;
    EXPECT_UNCHANGED(MCS_ERR_FREQ_RANGE, mcs_spectrum_mean(&acc, 20u, &re, &im));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_mean(&acc, 1u, NULL, &im));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_mean(&acc, 1u, &re, NULL));
    EXPECT_UNCHANGED(MCS_ERR_FREQ_RANGE, mcs_spectrum_mean_stderr(&acc, 20u, &v));
    EXPECT_UNCHANGED(MCS_ERR_FREQ_RANGE, mcs_spectrum_power(&acc, 25u, &v));
    EXPECT_UNCHANGED(MCS_ERR_FREQ_RANGE, mcs_spectrum_power_stderr(&acc, 20u, &v));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_power(&acc, 1u, NULL));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_count(&acc, NULL));
    TEST_ASSERT_EQUAL_DOUBLE(7.0, re);
    TEST_ASSERT_EQUAL_DOUBLE(7.0, im);
    TEST_ASSERT_EQUAL_DOUBLE(7.0, v);

    /* an empty accumulator has no mean; one trial has no standard error */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 20u));
    EXPECT_UNCHANGED(MCS_ERR_EMPTY, mcs_spectrum_mean(&acc, 1u, &re, &im));
    EXPECT_UNCHANGED(MCS_ERR_EMPTY, mcs_spectrum_power(&acc, 1u, &v));
    run(&acc, MCS_PATTERN_RANDOM, 20u, 4u, NULL, 1u, 1u);
    EXPECT_UNCHANGED(MCS_ERR_EMPTY, mcs_spectrum_mean_stderr(&acc, 1u, &v));
    EXPECT_UNCHANGED(MCS_ERR_EMPTY, mcs_spectrum_power_stderr(&acc, 1u, &v));
    TEST_ASSERT_EQUAL_DOUBLE(7.0, v);

    /* an accumulator that was never initialised */
    memset(&acc, 0, sizeof acc);
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_add_bins(&acc, 4u, b, w));
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_add_points(&acc, 4u, x, w));
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_add_dense(&acc, 20u, dense));
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_set_path(&acc, MCS_SPECTRUM_PATH_FFT));
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_count(&acc, &c));
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_power(&acc, 0u, &v));
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_merge(&acc, &acc2));
    TEST_ASSERT_EQUAL_UINT64(7u, c);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_sparse_and_fft_paths_give_the_same_statistics);
    RUN_TEST(test_bins_dense_and_points_give_the_same_statistics);
    RUN_TEST(test_points_without_weights_count_as_weight_one);
    RUN_TEST(test_one_trial_matches_the_naive_dft);
    RUN_TEST(test_s0_is_k_over_root_n_in_every_trial_without_importance);
    RUN_TEST(test_parseval_holds_for_every_trial);
    RUN_TEST(test_merge_of_halves_equals_one_pass);
    RUN_TEST(test_merge_with_an_empty_side_copies_or_keeps);
    RUN_TEST(test_merge_with_itself_doubles_the_count_and_keeps_the_means);
    RUN_TEST(test_a_copied_accumulator_keeps_working);
    RUN_TEST(test_random_power_is_k_over_n_and_mean_is_zero);
    RUN_TEST(test_stratified_power_follows_the_exact_finite_n_form);
    RUN_TEST(test_jitter_power_is_k2_over_n_at_multiples_of_k_and_zero_elsewhere);
    RUN_TEST(test_uniform_is_biased_at_multiples_of_k);
    RUN_TEST(test_importance_sampled_random_power_is_k_over_n_h);
    RUN_TEST(test_bad_input_returns_an_error_and_changes_nothing);
    RUN_TEST(test_bad_read_outs_return_an_error_and_leave_the_outputs_alone);
    return UNITY_END();
}
