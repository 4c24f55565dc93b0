/* The spectrum accumulators' contract under bad input: every refused call
 * returns its status and changes nothing, including the overflowing,
 * aliased and full-count cases of issue 10 (items 1, 5, 9, 10) for the 1D
 * accumulator and the binned 2D one. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mcspec.h"
#include "spectra_ref.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static mcs_spectrum acc, acc2, acc3, before;
/* A 2D spectrum with its buffer: the whole is what "unchanged" compares. */
typedef struct {
    mcs_spectrum2d acc;
    unsigned char mem[MCS_SPECTRUM2D_SIZE(8u, 8u)];
} sp2_with_buffer;
static sp2_with_buffer sp2_all, sp2_before;
static mcs_spectrum2d *const sp2p = &sp2_all.acc;
#define sp2 (*sp2p)
static size_t bins[256];
static double weights[256], dense[MCS_MAX_N];

static const mcs_spectrum_path every_path[] = {MCS_SPECTRUM_PATH_SPARSE, MCS_SPECTRUM_PATH_FFT,
                                               MCS_SPECTRUM_PATH_PAIR, MCS_SPECTRUM_PATH_AUTO};
#define PATHS (sizeof every_path / sizeof every_path[0])

/* Feeds `trials` trials of a pattern (PCG32 sequence 0x5eed) to a. */
static void run(mcs_spectrum *a, mcs_pattern_kind kind, size_t n, size_t k,
                const mcs_importance *importance, uint64_t seed, size_t trials)
{
    spectra_stream st;
    spectra_stream_init(&st, kind, n, k, importance, seed, 0x5eedu);
    for (size_t t = 0; t < trials; ++t) {
        spectra_stream_draw(&st, bins, weights, NULL);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(a, k, bins, weights));
    }
}

static void init_with(mcs_spectrum *a, size_t n, mcs_spectrum_path path, uint64_t batch)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(a, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_path(a, path));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_batch(a, batch));
}

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
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_set_batch(NULL, 4u));
    EXPECT_UNCHANGED(MCS_ERR_K_RANGE, mcs_spectrum_set_batch(&acc, MCS_SPECTRUM_BATCH_LIMIT + 1u));
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_flush(NULL));

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

/* The scan of bins and weights has two copies (spectrum.c's scalar one, an
 * AVX2 one): a bad sample at any position, in a lane or in the tail, gets
 * the same status from both and changes nothing; a good trial passes both. */
static void test_both_scans_find_a_bad_sample_at_every_position(void)
{
    static const double bad_w[3] = {NAN, INFINITY, -1.0};
    static const mcs_status bad_st[3] = {MCS_ERR_NOT_FINITE, MCS_ERR_NOT_FINITE,
                                         MCS_ERR_NEGATIVE};
    size_t b[11];
    double w[11];
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 20u));
    const int copies = acc.simd ? 2 : 1; /* this CPU runs the AVX2 copy too */
    for (int c = 0; c < copies; ++c)
        for (size_t pos = 0; pos < 11u; ++pos)
            for (int bad = 0; bad < 5; ++bad) {
                init_with(&acc, 20u, MCS_SPECTRUM_PATH_FFT, 0u);
                acc.simd = c;
                for (size_t j = 0; j < 11u; ++j) {
                    b[j] = (j * 7u) % 20u;
                    w[j] = 0.5 + (double)j;
                }
                if (bad < 3)
                    w[pos] = bad_w[bad];
                else
                    b[pos] = bad == 3 ? 20u : SIZE_MAX;
                EXPECT_UNCHANGED(bad < 3 ? bad_st[bad] : MCS_ERR_BIN_RANGE,
                                 mcs_spectrum_add_bins(&acc, 11u, b, w));
                b[pos] = (pos * 7u) % 20u;
                w[pos] = 0.5 + (double)pos;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, 11u, b, w));
            }
}

/* Issue 10, item 1: finite weights whose sum overflows in one bin made the
 * FFT path's DFT fail; the add still returned MCS_OK, counted the trial and
 * took the previous trial's spectrum. Item 5: the largest accepted input is
 * documented (a trial's weights sum to at most MCS_SPECTRUM_MAX_SUM) and
 * larger is refused, so no square or fourth power can overflow. */
static void test_a_trial_whose_weights_overflow_is_refused_on_every_path(void)
{
    size_t b[3] = {4u, 4u, 9u};
    double x[3] = {0.2, 0.21, 0.5};
    for (size_t p = 0; p < PATHS; ++p) {
        double w[3] = {1e308, 1e308, 1.0};
        init_with(&acc, 20u, every_path[p], 0u);
        run(&acc, MCS_PATTERN_RANDOM, 20u, 4u, NULL, 1u, 3u);
        EXPECT_UNCHANGED(MCS_ERR_MAGNITUDE, mcs_spectrum_add_bins(&acc, 3u, b, w));
        EXPECT_UNCHANGED(MCS_ERR_MAGNITUDE, mcs_spectrum_add_points(&acc, 3u, x, w));
        for (size_t j = 0; j < 20u; ++j)
            dense[j] = j == 4u ? 1e308 : 0.0;
        dense[5] = 1e308;
        EXPECT_UNCHANGED(MCS_ERR_MAGNITUDE, mcs_spectrum_add_dense(&acc, 20u, dense));
        /* the bound itself: 2^100 accepted, the next double above refused */
        w[0] = MCS_SPECTRUM_MAX_SUM / 2.0;
        w[1] = MCS_SPECTRUM_MAX_SUM / 2.0;
        w[2] = nextafter(0.0, 1.0) * 0x1p60; /* lost in the sum's rounding: still the bound */
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, 3u, b, w));
        w[2] = MCS_SPECTRUM_MAX_SUM * 0x1p-52;
        EXPECT_UNCHANGED(MCS_ERR_MAGNITUDE, mcs_spectrum_add_bins(&acc, 3u, b, w));
    }
}

static void test_read_outs_stay_finite_at_the_largest_accepted_input(void)
{
    /* Trials at the bound alternating with tiny ones: the largest spread of
     * |S_k|^2 the accumulator can meet, over many units. */
    size_t b[2] = {0u, 3u};
    double big[2] = {MCS_SPECTRUM_MAX_SUM / 2.0, MCS_SPECTRUM_MAX_SUM / 2.0}, small[2] = {0.0, 1.0};
    for (size_t p = 0; p < PATHS; ++p) {
        init_with(&acc, 16u, every_path[p], every_path[p] == MCS_SPECTRUM_PATH_PAIR ? 4u : 0u);
        for (size_t t = 0; t < 200u; ++t)
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, 2u, b, t % 3u ? small : big));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_merge(&acc, &acc));
        for (size_t k = 0; k < 16u; ++k) {
            double re, im, pw, se, pse;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&acc, k, &re, &im));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&acc, k, &pw));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(&acc, k, &se));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(&acc, k, &pse));
            TEST_ASSERT_TRUE(isfinite(re) && isfinite(im) && isfinite(pw) && isfinite(se) &&
                             isfinite(pse) && pw >= 0.0 && se >= 0.0 && pse >= 0.0);
        }
    }
}

/* Issue 10, item 10: input arrays inside the accumulator are refused (the
 * paths write its scratch while they read them), as is a merge of two
 * overlapping accumulators that are not the same object. */
static void test_aliasing_the_accumulator_is_refused(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 20u));
    run(&acc, MCS_PATTERN_RANDOM, 20u, 4u, NULL, 1u, 5u);
    size_t b[2] = {1u, 2u};
    double w[2] = {1.0, 1.0};
    for (size_t j = 0; j < 20u; ++j)
        acc.s[j] = 0.0; /* scratch, 0 between calls, so a valid dense trial */
    acc.chunk_bins[0] = 1u;
    acc.chunk_bins[1] = 2u;
    acc.chunk_weights[0] = acc.chunk_weights[1] = 0.25;
    EXPECT_UNCHANGED(MCS_ERR_ALIAS, mcs_spectrum_add_dense(&acc, 20u, acc.s));
    EXPECT_UNCHANGED(MCS_ERR_ALIAS, mcs_spectrum_add_bins(&acc, 2u, acc.chunk_bins, w));
    EXPECT_UNCHANGED(MCS_ERR_ALIAS, mcs_spectrum_add_bins(&acc, 2u, b, acc.chunk_weights));
    EXPECT_UNCHANGED(MCS_ERR_ALIAS, mcs_spectrum_add_points(&acc, 2u, acc.chunk_weights, NULL));

    /* Two set-up accumulators that overlap: src starts at dst's scratch. */
    static union {
        mcs_spectrum align;
        unsigned char bytes[2u * sizeof(mcs_spectrum)];
    } arena;
    mcs_spectrum *dst = &arena.align;
    mcs_spectrum *src = (mcs_spectrum *)(void *)(arena.bytes + offsetof(mcs_spectrum, s));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(dst, 20u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(src, 20u));
    run(src, MCS_PATTERN_RANDOM, 20u, 4u, NULL, 1u, 5u);
    memcpy(&before, dst, offsetof(mcs_spectrum, s));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_spectrum_merge(dst, src));
    TEST_ASSERT_EQUAL_MEMORY(&before, dst, offsetof(mcs_spectrum, s));
}

static void test_counts_stop_at_the_largest_count(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 8u));
    run(&acc, MCS_PATTERN_RANDOM, 8u, 2u, NULL, 1u, 3u);
    /* The same statistics, counted as if 2^53 trials had come in 2^53 units. */
    acc.count = MCS_SPECTRUM_MAX_COUNT;
    acc.units = MCS_SPECTRUM_MAX_COUNT - acc.open_count;
    acc.count = acc.units + acc.open_count;
    size_t b[2] = {1u, 2u};
    double w[2] = {1.0, 1.0};
    EXPECT_UNCHANGED(MCS_ERR_COUNT, mcs_spectrum_add_bins(&acc, 2u, b, w));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc2, 8u));
    run(&acc2, MCS_PATTERN_RANDOM, 8u, 2u, NULL, 2u, 1u);
    EXPECT_UNCHANGED(MCS_ERR_COUNT, mcs_spectrum_merge(&acc, &acc2));
    EXPECT_UNCHANGED(MCS_ERR_COUNT, mcs_spectrum_merge(&acc, &acc));
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
    EXPECT_UNCHANGED(MCS_ERR_NULL, mcs_spectrum_units(&acc, NULL));
    TEST_ASSERT_EQUAL_DOUBLE(7.0, re);
    TEST_ASSERT_EQUAL_DOUBLE(7.0, im);
    TEST_ASSERT_EQUAL_DOUBLE(7.0, v);

    /* an empty accumulator has no mean; one trial has no standard error */
    init_with(&acc, 20u, MCS_SPECTRUM_PATH_FFT, 0u);
    EXPECT_UNCHANGED(MCS_ERR_EMPTY, mcs_spectrum_mean(&acc, 1u, &re, &im));
    EXPECT_UNCHANGED(MCS_ERR_EMPTY, mcs_spectrum_power(&acc, 1u, &v));
    run(&acc, MCS_PATTERN_RANDOM, 20u, 4u, NULL, 1u, 1u);
    EXPECT_UNCHANGED(MCS_ERR_EMPTY, mcs_spectrum_mean_stderr(&acc, 1u, &v));
    EXPECT_UNCHANGED(MCS_ERR_EMPTY, mcs_spectrum_power_stderr(&acc, 1u, &v));
    TEST_ASSERT_EQUAL_DOUBLE(7.0, v);

    /* an accumulator that was never initialised, or whose counts disagree */
    memset(&acc, 0, sizeof acc);
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_add_bins(&acc, 4u, b, w));
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_add_points(&acc, 4u, x, w));
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_add_dense(&acc, 20u, dense));
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_set_path(&acc, MCS_SPECTRUM_PATH_FFT));
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_set_batch(&acc, 3u));
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_flush(&acc));
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_count(&acc, &c));
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_power(&acc, 0u, &v));
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_merge(&acc, &acc2));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, 20u));
    run(&acc, MCS_PATTERN_RANDOM, 20u, 4u, NULL, 1u, 5u);
    const uint64_t open = acc.open_count;
    acc.open_count = acc.count + 1u;
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_power(&acc, 0u, &v));
    acc.open_count = open;
    acc.simd = 2;
    EXPECT_UNCHANGED(MCS_ERR_UNINIT, mcs_spectrum_add_bins(&acc, 4u, b, w));
    init_with(&acc, 20u, MCS_SPECTRUM_PATH_FFT, 0u);
    run(&acc, MCS_PATTERN_RANDOM, 20u, 4u, NULL, 1u, 5u);
    acc.mean_pow[3] = NAN; /* overwritten statistics: refused, not returned */
    acc.m2_s[3] = -1.0;
    acc.m2_pow[3] = -1.0;
    v = 7.0;
    EXPECT_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_spectrum_power(&acc, 3u, &v));
    EXPECT_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_spectrum_power_stderr(&acc, 17u, &v));
    EXPECT_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_spectrum_mean_stderr(&acc, 3u, &v));
    TEST_ASSERT_EQUAL_DOUBLE(7.0, v);
    TEST_ASSERT_EQUAL_UINT64(7u, c);
}

/* The binned 2D accumulator keeps the same bounds: a trial's weights sum to
 * at most MCS_SPECTRUM_MAX_SUM, counts stop at MCS_SPECTRUM_MAX_COUNT, the
 * transform's input is bounded and may not overlap its outputs, and no
 * read-out returns an overflow with MCS_OK. */
static void test_the_2d_accumulator_refuses_what_would_overflow_or_alias(void)
{
    static double s[64], re[64], im[64], f_re[64], f_im[64];
    const double pts[4] = {0.1, 0.2, 0.6, 0.7};
    double w[2] = {1e300, 1.0};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_init(&sp2, 8u, 8u, sp2_all.mem, sizeof sp2_all.mem));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points(&sp2, 2u, pts, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points(&sp2, 1u, pts + 2, NULL));
    memcpy(&sp2_before, &sp2_all, sizeof sp2_all);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_spectrum2d_add_points(&sp2, 2u, pts, w));
    w[0] = w[1] = MCS_SPECTRUM_MAX_SUM; /* twice the bound */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_spectrum2d_add_points(&sp2, 2u, pts, w));
    TEST_ASSERT_EQUAL_MEMORY(&sp2_before, &sp2_all, sizeof sp2_all);
    double a = 7.0, b = 7.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_spectrum2d_mean(&sp2, 1u, 2u, &a, &a));
    TEST_ASSERT_EQUAL_DOUBLE(7.0, a);
    for (size_t j = 0; j < 64u; ++j) {
        s[j] = j % 3u ? 0.5 : 1.5;
        f_re[j] = j == 9u ? 1e300 : 1.0;
        f_im[j] = 0.0;
    }
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_spectrum2d_transform(&sp2, s, s, im));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_spectrum2d_transform(&sp2, s, re, re));
    s[5] = 1e308;
    s[6] = 1e308;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_spectrum2d_transform(&sp2, s, re, im));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_spectrum2d_variance14(&sp2, 2u, f_re, f_im, &b));
    TEST_ASSERT_EQUAL_DOUBLE(7.0, b);
    /* full counts */
    sp2.state->count = MCS_SPECTRUM_MAX_COUNT;
    memcpy(&sp2_before, &sp2_all, sizeof sp2_all);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_COUNT, mcs_spectrum2d_add_points(&sp2, 2u, pts, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_COUNT, mcs_spectrum2d_merge(&sp2, &sp2));
    TEST_ASSERT_EQUAL_MEMORY(&sp2_before, &sp2_all, sizeof sp2_all);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_bad_input_returns_an_error_and_changes_nothing);
    RUN_TEST(test_both_scans_find_a_bad_sample_at_every_position);
    RUN_TEST(test_a_trial_whose_weights_overflow_is_refused_on_every_path);
    RUN_TEST(test_read_outs_stay_finite_at_the_largest_accepted_input);
    RUN_TEST(test_aliasing_the_accumulator_is_refused);
    RUN_TEST(test_counts_stop_at_the_largest_count);
    RUN_TEST(test_bad_read_outs_return_an_error_and_leave_the_outputs_alone);
    RUN_TEST(test_the_2d_accumulator_refuses_what_would_overflow_or_alias);
    return UNITY_END();
}
