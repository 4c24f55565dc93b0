/* The array read-outs: mcs_spectrum_read_all and mcs_theory_spectrum_read_all
 * give every stored frequency k = 0..N/2 bit for bit as the per-frequency
 * calls do, on every path and kind, N odd and even; and refuse bad calls
 * (a NULL set of arrays, a wrong length, overlapping arrays, too few units,
 * an overwritten object) without writing a byte. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "mcspec.h"
#include "spectra_ref.h"
#include "unity.h"

void tearDown(void) {}

static mcs_spectrum acc, copy;
static mcs_theory_spectrum ts, ts_copy;
static mcs_importance imp;
static size_t bins[300];
static double weights[300], dense[MCS_MAX_N];

#define HALF_CAP (MCS_MAX_N / 2 + 2)
#define SENTINEL (-12345.678)

/* Five output arrays, each one longer than N/2 + 1 for a guard word. */
static double out[5][HALF_CAP];
/* What the per-frequency calls give. */
static double ref[5][HALF_CAP];

static void fill_sentinel(void)
{
    for (int a = 0; a < 5; ++a)
        for (size_t q = 0; q < HALF_CAP; ++q)
            out[a][q] = SENTINEL;
}

/* Every entry from q = 0 still the sentinel. */
static void assert_untouched(const char *what)
{
    for (int a = 0; a < 5; ++a)
        for (size_t q = 0; q < HALF_CAP; ++q)
            if (out[a][q] != SENTINEL) {
                char msg[96];
                (void)snprintf(msg, sizeof msg, "%s: array %d written at %zu", what, a, q);
                TEST_FAIL_MESSAGE(msg);
            }
}

/* out[a][0..len) bit-equal to ref[a][0..len), and out[a][len] the guard. */
static void assert_same_bits(int a, size_t len, const char *what, size_t n)
{
    for (size_t q = 0; q < len; ++q)
        if (memcmp(&out[a][q], &ref[a][q], sizeof(double)) != 0) {
            char msg[160];
            (void)snprintf(msg, sizeof msg, "%s, N = %zu, array %d at k = %zu: %.17g, per call %.17g",
                           what, n, a, q, out[a][q], ref[a][q]);
            TEST_FAIL_MESSAGE(msg);
        }
    TEST_ASSERT_EQUAL_DOUBLE_MESSAGE(SENTINEL, out[a][len], "guard word overwritten");
}

/* ---------------- measured ---------------- */

static void measured_reference(const mcs_spectrum *a, int spread)
{
    const size_t h = a->n / 2u + 1u;
    for (size_t q = 0; q < h; ++q) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(a, q, &ref[0][q], &ref[1][q]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(a, q, &ref[3][q]));
        if (spread) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(a, q, &ref[2][q]));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(a, q, &ref[4][q]));
        }
    }
}

static void assert_measured_arrays(const mcs_spectrum *a, const char *what)
{
    const size_t n = a->n, h = n / 2u + 1u;
    measured_reference(a, 1);
    fill_sentinel();
    TEST_ASSERT_EQUAL_INT(MCS_OK,
                          mcs_spectrum_read_all(a, h, out[0], out[1], out[2], out[3], out[4]));
    for (int k = 0; k < 5; ++k)
        assert_same_bits(k, h, what, n);
    /* one array at a time: the same bits, the others not written */
    for (int k = 0; k < 5; ++k) {
        double *o[5] = {NULL, NULL, NULL, NULL, NULL};
        o[k] = out[k];
        fill_sentinel();
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_read_all(a, h, o[0], o[1], o[2], o[3], o[4]));
        assert_same_bits(k, h, what, n);
        for (int j = 0; j < 5; ++j)
            if (j != k)
                TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, out[j][0]);
    }
}

static const size_t all_sizes[] = {1u, 2u, 3u, 4u, 5u, 8u, 15u, 16u, 33u, 64u, 100u, 257u, 1024u};
/* the sizes a build's MCS_MAX_N allows (-DMCS_MAX_N=256 builds too) */
static size_t sizes[sizeof all_sizes / sizeof all_sizes[0]];
static size_t n_sizes;

void setUp(void)
{
    n_sizes = 0u;
    for (size_t i = 0; i < sizeof all_sizes / sizeof all_sizes[0]; ++i)
        if (all_sizes[i] <= (size_t)MCS_MAX_N)
            sizes[n_sizes++] = all_sizes[i];
}

/* trials of a pattern through path (batch fixed at 8 for PAIR, so units
 * close and one batch stays open) with an uneven importance function. */
static void fill(mcs_spectrum *a, size_t n, mcs_spectrum_path path, size_t trials)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(a, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_path(a, path));
    if (path == MCS_SPECTRUM_PATH_PAIR)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_batch(a, 8u));
    spectra_make_importance(&imp, n, 0.2, 7u, 3u, 2.0);
    const size_t k = n < 40u ? 7u : 40u;
    spectra_run(a, MCS_PATTERN_STRATIFIED, n, k, &imp, 0x51u + n, 0xa77u, trials, bins, weights);
}

static void test_measured_arrays_equal_the_per_frequency_calls_on_every_path(void)
{
    static const mcs_spectrum_path paths[] = {MCS_SPECTRUM_PATH_SPARSE, MCS_SPECTRUM_PATH_FFT,
                                              MCS_SPECTRUM_PATH_PAIR, MCS_SPECTRUM_PATH_AUTO};
    static const char *const names[] = {"sparse", "fft", "pair (open batch)", "auto"};
    for (size_t i = 0; i < n_sizes; ++i)
        for (size_t p = 0; p < 4u; ++p) {
            fill(&acc, sizes[i], paths[p], 61u); /* 61 = 7 batches of 8 and an open one */
            assert_measured_arrays(&acc, names[p]);
            if (paths[p] == MCS_SPECTRUM_PATH_PAIR) {
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_flush(&acc));
                assert_measured_arrays(&acc, "pair (flushed)");
            }
        }
}

static void test_measured_arrays_equal_the_per_frequency_calls_for_dense_trials(void)
{
    uint64_t state = 99u;
    for (size_t i = 0; i < n_sizes; ++i) {
        const size_t n = sizes[i];
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, n));
        for (int t = 0; t < 20; ++t) {
            for (size_t b = 0; b < n; ++b)
                dense[b] = spectra_uniform(&state, 0.0, 3.0);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_dense(&acc, n, dense));
        }
        assert_measured_arrays(&acc, "dense");
    }
}

static void test_measured_arrays_refuse_a_wrong_length_and_write_nothing(void)
{
    fill(&acc, 16u, MCS_SPECTRUM_PATH_SPARSE, 10u);
    const size_t bad[] = {0u, 1u, 8u, 10u, 16u, SIZE_MAX};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        fill_sentinel();
        SPECTRA_UNCHANGED(acc, copy, MCS_ERR_MISMATCH,
                          mcs_spectrum_read_all(&acc, bad[i], out[0], out[1], out[2], out[3],
                                                out[4]));
        assert_untouched("wrong length");
    }
}

static void test_measured_arrays_refuse_null_and_uninitialised_objects(void)
{
    fill(&acc, 16u, MCS_SPECTRUM_PATH_FFT, 10u);
    fill_sentinel();
    SPECTRA_UNCHANGED(acc, copy, MCS_ERR_NULL,
                      mcs_spectrum_read_all(&acc, 9u, NULL, NULL, NULL, NULL, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL,
                          mcs_spectrum_read_all(NULL, 9u, out[0], out[1], out[2], out[3], out[4]));
    mcs_spectrum zero;
    memset(&zero, 0, sizeof zero);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT,
                          mcs_spectrum_read_all(&zero, 1u, out[0], out[1], out[2], out[3], out[4]));
    assert_untouched("null or uninitialised");
}

static void test_measured_arrays_refuse_overlapping_arrays(void)
{
    fill(&acc, 16u, MCS_SPECTRUM_PATH_SPARSE, 10u);
    const size_t h = 9u;
    fill_sentinel();
    /* the same array twice, a partial overlap (one entry apart), and the
     * last entry of one on the first of another */
    SPECTRA_UNCHANGED(acc, copy, MCS_ERR_ALIAS,
                      mcs_spectrum_read_all(&acc, h, out[0], out[0], NULL, NULL, NULL));
    SPECTRA_UNCHANGED(acc, copy, MCS_ERR_ALIAS,
                      mcs_spectrum_read_all(&acc, h, out[0], NULL, NULL, out[0] + 1, NULL));
    SPECTRA_UNCHANGED(acc, copy, MCS_ERR_ALIAS,
                      mcs_spectrum_read_all(&acc, h, NULL, out[0] + h - 1u, out[2], out[3],
                                            out[0]));
    assert_untouched("overlap");
    /* an array inside the accumulator itself */
    SPECTRA_UNCHANGED(acc, copy, MCS_ERR_ALIAS,
                      mcs_spectrum_read_all(&acc, h, out[0], acc.re, NULL, NULL, NULL));
    assert_untouched("inside the object");
    /* adjacent arrays do not overlap */
    TEST_ASSERT_EQUAL_INT(MCS_OK,
                          mcs_spectrum_read_all(&acc, h, out[0], out[0] + h, NULL, NULL, NULL));
}

static void test_measured_standard_errors_need_two_units(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 12u));
    fill_sentinel();
    SPECTRA_UNCHANGED(acc, copy, MCS_ERR_EMPTY,
                      mcs_spectrum_read_all(&acc, 7u, out[0], out[1], NULL, out[3], NULL));
    fill(&acc, 12u, MCS_SPECTRUM_PATH_SPARSE, 1u);
    SPECTRA_UNCHANGED(acc, copy, MCS_ERR_EMPTY,
                      mcs_spectrum_read_all(&acc, 7u, out[0], out[1], out[2], out[3], NULL));
    SPECTRA_UNCHANGED(acc, copy, MCS_ERR_EMPTY,
                      mcs_spectrum_read_all(&acc, 7u, NULL, NULL, NULL, NULL, out[4]));
    assert_untouched("one unit");
    /* the means need one trial only */
    measured_reference(&acc, 0);
    TEST_ASSERT_EQUAL_INT(MCS_OK,
                          mcs_spectrum_read_all(&acc, 7u, out[0], out[1], NULL, out[3], NULL));
    assert_same_bits(0, 7u, "one trial", 12u);
    assert_same_bits(1, 7u, "one trial", 12u);
    assert_same_bits(3, 7u, "one trial", 12u);
}

static void test_measured_arrays_refuse_an_overwritten_object_and_write_nothing(void)
{
    fill(&acc, 16u, MCS_SPECTRUM_PATH_SPARSE, 10u);
    acc.mean_pow[8] = NAN; /* the last stored frequency: found before anything is written */
    fill_sentinel();
    SPECTRA_UNCHANGED(acc, copy, MCS_ERR_NOT_FINITE,
                      mcs_spectrum_read_all(&acc, 9u, out[0], out[1], out[2], out[3], out[4]));
    assert_untouched("overwritten");
    /* a value not asked for is not judged */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_read_all(&acc, 9u, out[0], NULL, NULL, NULL, NULL));
}

/* S_0 and S_{N/2} are real for a real s, so Im <S_0> and Im <S_{N/2}> are
 * 0, exactly and with a + sign, on every path (the SPARSE path's sums
 * carried the sine table's sin(pi) = 1.2e-16 into them: -7.65e-17 for the
 * hand-worked file of test/golden/hand_n4_weights.txt). */
static int is_plus_zero(double x)
{
    const double zero = 0.0;
    return memcmp(&x, &zero, sizeof x) == 0;
}

static void test_the_imaginary_mean_at_k_0_and_nyquist_is_exactly_0(void)
{
    static const mcs_spectrum_path paths[] = {MCS_SPECTRUM_PATH_SPARSE, MCS_SPECTRUM_PATH_FFT,
                                              MCS_SPECTRUM_PATH_PAIR, MCS_SPECTRUM_PATH_AUTO};
    /* the hand-worked file: s = (1, 2, 0, 0) and s = (0, 0, 0, 0.5) */
    const size_t b1[2] = {0u, 1u}, b2[1] = {3u};
    const double w1[2] = {1.0, 2.0}, w2[1] = {0.5};
    for (size_t p = 0; p < 4u; ++p) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 4u));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_path(&acc, paths[p]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, 2u, b1, w1));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, 1u, b2, w2));
        double re, im;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&acc, 2u, &re, &im));
        TEST_ASSERT_EQUAL_DOUBLE(-0.375, re);
        TEST_ASSERT_TRUE_MESSAGE(is_plus_zero(im), "Im <S_2> of the hand-worked file");
    }
    for (size_t i = 0; i < n_sizes; ++i)
        for (size_t p = 0; p < 4u; ++p) {
            const size_t n = sizes[i];
            fill(&acc, n, paths[p], 37u);
            for (size_t q = 0; q < n; q += (n + 1u) / 2u) { /* 0, and N/2 when N is even */
                if (q != 0u && 2u * q != n)
                    continue;
                double re, im;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&acc, q, &re, &im));
                TEST_ASSERT_TRUE_MESSAGE(is_plus_zero(im), "Im <S_k> at k = 0 or N/2");
            }
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_read_all(&acc, n / 2u + 1u, NULL, out[1],
                                                                NULL, NULL, NULL));
            TEST_ASSERT_TRUE(is_plus_zero(out[1][0]));
            if (n % 2u == 0u) {
                TEST_ASSERT_TRUE(is_plus_zero(out[1][n / 2u]));
            }
        }
}

/* ---------------- exact ---------------- */

static void exact_reference(const mcs_theory_spectrum *t)
{
    const size_t h = t->n / 2u + 1u;
    for (size_t q = 0; q < h; ++q) {
        double zero;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_mean(t, q, &ref[0][q], &ref[1][q]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_covariance(t, q, q, &ref[2][q], &zero));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_power(t, q, &ref[3][q]));
    }
}

static void assert_exact_arrays(const mcs_theory_spectrum *t, const char *what)
{
    const size_t h = t->n / 2u + 1u;
    exact_reference(t);
    fill_sentinel();
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_read_all(t, h, out[0], out[1], out[2], out[3]));
    for (int a = 0; a < 4; ++a)
        assert_same_bits(a, h, what, t->n);
    for (int a = 0; a < 4; ++a) {
        double *o[4] = {NULL, NULL, NULL, NULL};
        o[a] = out[a];
        fill_sentinel();
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_read_all(t, h, o[0], o[1], o[2], o[3]));
        assert_same_bits(a, h, what, t->n);
    }
}

static void test_exact_arrays_equal_the_per_frequency_calls_for_every_kind(void)
{
    static const size_t ks[] = {1u, 3u, 4u, 7u, 16u, 600u};
    for (size_t i = 0; i < n_sizes; ++i)
        for (int kind = 0; kind < MCS_PATTERN_KIND_COUNT; ++kind)
            for (size_t j = 0; j < sizeof ks / sizeof ks[0]; ++j)
                for (int with = 0; with < 2; ++with) {
                    const size_t n = sizes[i];
                    if (with && (kind == MCS_PATTERN_HOMOGENIZED || n == 1u))
                        continue;
                    spectra_make_importance(&imp, n, 0.2, 7u, 3u, 2.0);
                    mcs_pattern pat;
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, (mcs_pattern_kind)kind, n,
                                                                   ks[j], with ? &imp : NULL));
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_init(&ts, &pat));
                    assert_exact_arrays(&ts, mcs_pattern_kind_str((mcs_pattern_kind)kind));
                    if (n > 64u)
                        break; /* the largest N once per kind: O(N^2) per call */
                }
}

static void exact_init(size_t n)
{
    mcs_pattern pat;
    spectra_make_importance(&imp, n, 0.2, 7u, 3u, 2.0);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_JITTER, n, 5u, &imp));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_init(&ts, &pat));
}

static void test_exact_arrays_refuse_bad_calls_and_write_nothing(void)
{
    exact_init(16u);
    fill_sentinel();
    const size_t bad[] = {0u, 8u, 10u, 16u, SIZE_MAX};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i)
        SPECTRA_UNCHANGED(ts, ts_copy, MCS_ERR_MISMATCH,
                          mcs_theory_spectrum_read_all(&ts, bad[i], out[0], out[1], out[2],
                                                       out[3]));
    SPECTRA_UNCHANGED(ts, ts_copy, MCS_ERR_NULL,
                      mcs_theory_spectrum_read_all(&ts, 9u, NULL, NULL, NULL, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL,
                          mcs_theory_spectrum_read_all(NULL, 9u, out[0], out[1], out[2], out[3]));
    SPECTRA_UNCHANGED(ts, ts_copy, MCS_ERR_ALIAS,
                      mcs_theory_spectrum_read_all(&ts, 9u, out[0], NULL, out[0] + 8, NULL));
    SPECTRA_UNCHANGED(ts, ts_copy, MCS_ERR_ALIAS,
                      mcs_theory_spectrum_read_all(&ts, 9u, NULL, out[1], NULL, out[1]));
    assert_untouched("exact, bad call");
    SPECTRA_UNCHANGED(ts, ts_copy, MCS_ERR_ALIAS,
                      mcs_theory_spectrum_read_all(&ts, 9u, ts.length, NULL, NULL, NULL));
    memset(&ts_copy, 0, sizeof ts_copy);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT,
                          mcs_theory_spectrum_read_all(&ts_copy, 9u, out[0], out[1], out[2], out[3]));
    /* a body init never writes (an edge out of order): refused before a write */
    exact_init(16u);
    ts.edge[5] = ts.edge[7];
    SPECTRA_UNCHANGED(ts, ts_copy, MCS_ERR_INVARIANT,
                      mcs_theory_spectrum_read_all(&ts, 9u, out[0], out[1], out[2], out[3]));
    assert_untouched("exact, overwritten");
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_measured_arrays_equal_the_per_frequency_calls_on_every_path);
    RUN_TEST(test_measured_arrays_equal_the_per_frequency_calls_for_dense_trials);
    RUN_TEST(test_measured_arrays_refuse_a_wrong_length_and_write_nothing);
    RUN_TEST(test_measured_arrays_refuse_null_and_uninitialised_objects);
    RUN_TEST(test_measured_arrays_refuse_overlapping_arrays);
    RUN_TEST(test_measured_standard_errors_need_two_units);
    RUN_TEST(test_measured_arrays_refuse_an_overwritten_object_and_write_nothing);
    RUN_TEST(test_the_imaginary_mean_at_k_0_and_nyquist_is_exactly_0);
    RUN_TEST(test_exact_arrays_equal_the_per_frequency_calls_for_every_kind);
    RUN_TEST(test_exact_arrays_refuse_bad_calls_and_write_nothing);
    return UNITY_END();
}
