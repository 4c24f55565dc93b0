/* The spectrum accumulator: its paths agree to rounding, and merges and the
 * open PAIR batch keep the statistics of one pass. Bad input is in
 * test_spectrum_input.c, the statistical claims in test_spectrum_stats.c. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mcspec.h"
#include "spectra_ref.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static mcs_spectrum acc, acc2, acc3, before;
static mcs_importance imp;
static size_t bins[256];
static double weights[256], points[256], dense[MCS_MAX_N];

static const mcs_spectrum_path every_path[] = {MCS_SPECTRUM_PATH_SPARSE, MCS_SPECTRUM_PATH_FFT,
                                               MCS_SPECTRUM_PATH_PAIR, MCS_SPECTRUM_PATH_AUTO};
#define PATHS (sizeof every_path / sizeof every_path[0])

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

/* Every read-out of a and b agrees to tol on the scale of the spectrum (its
 * mean power: rounding is relative to that, not to one frequency, whose
 * power may be 0). Standard errors too when `spread` (both must rest on the
 * same units; for a deterministic S_k they are differences of nearby
 * quantities, so they get 1e3 tol). */
static void assert_same_statistics(const mcs_spectrum *a, const mcs_spectrum *b, double tol,
                                   int spread)
{
    uint64_t ca, cb;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_count(a, &ca));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_count(b, &cb));
    TEST_ASSERT_EQUAL_UINT64(ca, cb);
    const double level = spectra_mean_power(b), amp = sqrt(level);
    for (size_t k = 0; k < a->n; ++k) {
        double ar, ai, br, bi, ap, bp;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(a, k, &ar, &ai));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(b, k, &br, &bi));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(a, k, &ap));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(b, k, &bp));
        assert_close(br, ar, tol, amp, "Re <S_k>", k);
        assert_close(bi, ai, tol, amp, "Im <S_k>", k);
        assert_close(bp, ap, tol, level, "<|S_k|^2>", k);
        if (!spread)
            continue;
        double as, bs, aps, bps;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(a, k, &as));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(b, k, &bs));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(a, k, &aps));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(b, k, &bps));
        assert_close(bs, as, 1e3 * tol, amp, "stderr <S_k>", k);
        assert_close(bps, aps, 1e3 * tol, level, "stderr <|S_k|^2>", k);
    }
}

/* Every stream of this file uses PCG32 sequence 0x5eedu. */
#define STREAM_SEQ 0x5eedu

static void stream_draw(spectra_stream *st)
{
    spectra_stream_draw(st, bins, weights, points);
}

/* Feeds `trials` trials of a pattern to a. */
static void run(mcs_spectrum *a, mcs_pattern_kind kind, size_t n, size_t k,
                const mcs_importance *importance, uint64_t seed, size_t trials)
{
    spectra_run(a, kind, n, k, importance, seed, STREAM_SEQ, trials, bins, weights);
}

static void make_importance(size_t n)
{
    spectra_make_importance(&imp, n, 0.2, 7u, 3u, 2.0);
}

static void init_with(mcs_spectrum *a, size_t n, mcs_spectrum_path path, uint64_t batch)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(a, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_path(a, path));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_batch(a, batch));
}

/* ---------------- the paths agree ---------------- */

static void test_every_path_gives_the_same_means_to_rounding(void)
{
    static const struct {
        size_t n, k;
        int importance;
    } cases[] = {{1u, 3u, 0},   {2u, 5u, 0},     {7u, 5u, 1},    {16u, 4u, 0},
                 {45u, 9u, 1},  {64u, 13u, 0},   {100u, 30u, 1}, {1024u, 6u, 0},
                 {13u, 40u, 1}, {26u, 20u, 0},   {64u, 100u, 1}, {4093u, 3u, 0}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        const size_t n = cases[i].n, k = cases[i].k, trials = n > 1000u ? 40u : 200u;
        const mcs_importance *ip = NULL;
        if (cases[i].importance) {
            make_importance(n);
            ip = &imp;
        }
        init_with(&acc, n, MCS_SPECTRUM_PATH_FFT, 0u); /* the reference */
        run(&acc, MCS_PATTERN_STRATIFIED, n, k, ip, 100u + i, trials);
        for (size_t p = 0; p < PATHS; ++p) {
            init_with(&acc2, n, every_path[p], 0u);
            run(&acc2, MCS_PATTERN_STRATIFIED, n, k, ip, 100u + i, trials);
            /* per-trial units: the standard errors agree too */
            assert_same_statistics(&acc2, &acc, 1e-12, every_path[p] == MCS_SPECTRUM_PATH_SPARSE);
        }
    }
}

static void test_pair_batches_of_one_give_the_per_trial_standard_errors(void)
{
    static const size_t ns[] = {9u, 64u, 101u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        make_importance(ns[i]);
        init_with(&acc, ns[i], MCS_SPECTRUM_PATH_SPARSE, 0u);
        init_with(&acc2, ns[i], MCS_SPECTRUM_PATH_PAIR, 1u);
        run(&acc, MCS_PATTERN_RANDOM, ns[i], 6u, &imp, 60u + i, 150u);
        run(&acc2, MCS_PATTERN_RANDOM, ns[i], 6u, &imp, 60u + i, 150u);
        TEST_ASSERT_EQUAL_UINT64(150u, acc2.units);
        assert_same_statistics(&acc2, &acc, 1e-12, 1);
    }
}

static void test_baseline_and_avx2_kernels_give_the_same_bits(void)
{
    /* Without AVX2 both runs take the baseline kernels and agree trivially. */
    static const size_t ns[] = {64u, 90u, 1024u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i)
        for (size_t p = 0; p < PATHS; ++p) {
            init_with(&acc, ns[i], every_path[p], 0u);
            init_with(&acc2, ns[i], every_path[p], 0u);
            acc2.simd = 0;
            run(&acc, MCS_PATTERN_JITTER, ns[i], 70u, NULL, 5u, 100u);
            run(&acc2, MCS_PATTERN_JITTER, ns[i], 70u, NULL, 5u, 100u);
            run(&acc, MCS_PATTERN_RANDOM, ns[i], 9u, NULL, 6u, 100u);
            run(&acc2, MCS_PATTERN_RANDOM, ns[i], 9u, NULL, 6u, 100u);
            const size_t bytes = MCS_SPECTRUM_HALF * sizeof(double);
            TEST_ASSERT_EQUAL_MEMORY(acc2.mean_re, acc.mean_re, bytes);
            TEST_ASSERT_EQUAL_MEMORY(acc2.mean_im, acc.mean_im, bytes);
            TEST_ASSERT_EQUAL_MEMORY(acc2.m2_s, acc.m2_s, bytes);
            TEST_ASSERT_EQUAL_MEMORY(acc2.mean_pow, acc.mean_pow, bytes);
            TEST_ASSERT_EQUAL_MEMORY(acc2.m2_pow, acc.m2_pow, bytes);
        }
}

static void test_bins_dense_and_points_give_the_same_statistics(void)
{
    static const size_t ns[] = {7u, 32u, 90u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i)
        for (size_t p = 0; p < PATHS; ++p) {
            const size_t n = ns[i], k = 11u;
            make_importance(n);
            init_with(&acc, n, every_path[p], 0u);
            init_with(&acc2, n, every_path[p], 0u);
            init_with(&acc3, n, every_path[p], 0u);
            spectra_stream st;
            spectra_stream_init(&st, MCS_PATTERN_RANDOM, n, k, &imp, 7u + i, STREAM_SEQ);
            for (size_t t = 0; t < 100u; ++t) {
                stream_draw(&st);
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, k, bins, weights));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_dense(n, k, bins, weights, dense));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_dense(&acc2, n, dense));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_points(&acc3, k, points, weights));
            }
            /* dense trials always take the FFT path; points the same as bins */
            assert_same_statistics(&acc2, &acc, 1e-12, every_path[p] == MCS_SPECTRUM_PATH_SPARSE);
            assert_same_statistics(&acc3, &acc, 1e-12, 1);
        }
}

/* The FFT path sums each bin's weights in index order, whether a bin's
 * samples come in a run (stratified with K > N: the run is summed in a
 * register) or apart (random): the same bits as mcs_pattern_dense's s. And
 * its update (with FFTW, fused with the transform's last pass and scaled
 * there) gives the dense path's bits: means and standard errors, at even
 * and odd N and where the last group of four frequencies is mostly pad. */
static void test_the_fft_path_sums_weights_as_the_dense_form_does(void)
{
    static const struct {
        mcs_pattern_kind kind;
        size_t n, k;
    } cases[] = {{MCS_PATTERN_STRATIFIED, 32u, 200u}, {MCS_PATTERN_RANDOM, 7u, 40u},
                 {MCS_PATTERN_STRATIFIED, 90u, 11u},  {MCS_PATTERN_RANDOM, 64u, 64u},
                 {MCS_PATTERN_STRATIFIED, 63u, 21u},  {MCS_PATTERN_RANDOM, 4u, 9u}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        const size_t n = cases[i].n, k = cases[i].k;
        make_importance(n);
        init_with(&acc, n, MCS_SPECTRUM_PATH_FFT, 0u);
        init_with(&acc2, n, MCS_SPECTRUM_PATH_FFT, 0u);
        spectra_stream st;
        spectra_stream_init(&st, cases[i].kind, n, k, &imp, 11u + i, STREAM_SEQ);
        for (size_t t = 0; t < 50u; ++t) {
            stream_draw(&st);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, k, bins, weights));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_dense(n, k, bins, weights, dense));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_dense(&acc2, n, dense));
        }
        for (size_t q = 0; q <= n / 2u; ++q) {
            double v[10];
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&acc, q, &v[0], &v[1]));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&acc, q, &v[2]));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(&acc, q, &v[3]));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(&acc, q, &v[4]));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&acc2, q, &v[5], &v[6]));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&acc2, q, &v[7]));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(&acc2, q, &v[8]));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(&acc2, q, &v[9]));
            TEST_ASSERT_EQUAL_MEMORY(&v[5], &v[0], 5u * sizeof v[0]);
        }
        /* the pad past N/2 stays 0 */
        for (size_t q = n / 2u + 1u; q < MCS_SPECTRUM_HALF && q < n / 2u + 9u; ++q) {
            TEST_ASSERT_EQUAL_DOUBLE(0.0, acc.mean_re[q]);
            TEST_ASSERT_EQUAL_DOUBLE(0.0, acc.m2_s[q]);
            TEST_ASSERT_EQUAL_DOUBLE(0.0, acc.m2_pow[q]);
        }
    }
}

static void test_points_without_weights_count_as_weight_one(void)
{
    for (size_t p = 0; p < PATHS; ++p) {
        init_with(&acc, 20u, every_path[p], 0u);
        init_with(&acc2, 20u, every_path[p], 0u);
        spectra_stream st;
        spectra_stream_init(&st, MCS_PATTERN_JITTER, 20u, 80u, NULL, 3u, STREAM_SEQ);
        for (size_t t = 0; t < 50u; ++t) {
            stream_draw(&st);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_points(&acc, 80u, points, NULL));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc2, 80u, bins, weights));
        }
        assert_same_statistics(&acc, &acc2, 1e-12, 1);
    }
}

static void test_one_trial_matches_the_naive_dft_on_every_path(void)
{
    static double re[MCS_MAX_N], im[MCS_MAX_N];
    static const size_t ns[] = {5u, 64u, 97u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i)
        for (size_t p = 0; p < PATHS; ++p) {
            const size_t n = ns[i];
            init_with(&acc, n, every_path[p], 0u);
            spectra_stream st;
            spectra_stream_init(&st, MCS_PATTERN_RANDOM, n, 9u, NULL, 5u, STREAM_SEQ);
            stream_draw(&st);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, 9u, bins, weights));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_dense(n, 9u, bins, weights, dense));
            spectra_naive_dft(n, dense, n, re, im);
            for (size_t k = 0; k < n; ++k) {
                double mr, mi, pw;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&acc, k, &mr, &mi));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&acc, k, &pw));
                assert_close(re[k], mr, 1e-13, 1.0, "Re S_k", k);
                assert_close(im[k], mi, 1e-13, 1.0, "Im S_k", k);
                assert_close(re[k] * re[k] + im[k] * im[k], pw, 1e-13, 1.0, "|S_k|^2", k);
            }
        }
}

static void test_s0_is_k_over_root_n_in_every_trial_without_importance(void)
{
    static const size_t ns[] = {16u, 30u, 256u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i)
        for (size_t p = 0; p < PATHS; ++p) {
            const size_t n = ns[i];
            init_with(&acc, n, every_path[p], 0u);
            run(&acc, MCS_PATTERN_RANDOM, n, 12u, NULL, 1u, 300u);
            double re, im, se, pw, pse;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&acc, 0u, &re, &im));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(&acc, 0u, &se));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&acc, 0u, &pw));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(&acc, 0u, &pse));
            const double s0 = 12.0 / sqrt((double)n);
            TEST_ASSERT_DOUBLE_WITHIN(1e-13 * s0, s0, re);
            TEST_ASSERT_EQUAL_DOUBLE(0.0, im);
            TEST_ASSERT_DOUBLE_WITHIN(1e-13 * s0 * s0, s0 * s0, pw);
            /* Welford: a constant has no spread, not a cancellation residue. */
            TEST_ASSERT_TRUE(se < 1e-13 * s0);
            TEST_ASSERT_TRUE(pse < 1e-13 * s0 * s0);
        }
}

static void test_parseval_holds_for_every_trial(void)
{
    /* One trial: sum_k |S_k|^2 = sum_n s_n^2, read back through the symmetric half. */
    static const size_t ns[] = {9u, 64u, 77u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i)
        for (size_t p = 0; p < PATHS; ++p) {
            const size_t n = ns[i];
            make_importance(n);
            init_with(&acc, n, every_path[p], 0u);
            run(&acc, MCS_PATTERN_STRATIFIED, n, 7u, &imp, 2u, 1u);
            double energy = 0.0, total = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_dense(n, 7u, bins, weights, dense));
            for (size_t b = 0; b < n; ++b)
                energy += dense[b] * dense[b];
            for (size_t k = 0; k < n; ++k) {
                double pw;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&acc, k, &pw));
                total += pw;
            }
            TEST_ASSERT_DOUBLE_WITHIN(1e-13 * energy, energy, total);
        }
}

/* ---------------- the PAIR path's batches ---------------- */

static void test_the_batch_rule_gives_32_batches_of_16_then_up_to_1024(void)
{
    /* K = 1: one pair per trial never pays for a close at N = 4096 (rule
     * (a)), so after the first 32 units of 16 (rule (b)) batches hold 1024
     * (rule (c)). */
    init_with(&acc, 4096u, MCS_SPECTRUM_PATH_PAIR, 0u);
    uint64_t units;
    run(&acc, MCS_PATTERN_RANDOM, 4096u, 1u, NULL, 3u, 16u * 31u + 15u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_units(&acc, &units));
    TEST_ASSERT_EQUAL_UINT64(32u, units); /* 31 closed and the open batch */
    TEST_ASSERT_EQUAL_UINT64(15u, acc.open_count);
    run(&acc, MCS_PATTERN_RANDOM, 4096u, 1u, NULL, 4u, 1u + 1023u);
    TEST_ASSERT_EQUAL_UINT64(32u, acc.units);
    TEST_ASSERT_EQUAL_UINT64(1023u, acc.open_count);
    run(&acc, MCS_PATTERN_RANDOM, 4096u, 1u, NULL, 5u, 1u);
    TEST_ASSERT_EQUAL_UINT64(33u, acc.units);
    TEST_ASSERT_EQUAL_UINT64(0u, acc.open_count);
    TEST_ASSERT_EQUAL_UINT64(16u * 32u + 1024u, acc.count);
}

static void test_read_outs_with_an_open_batch_equal_those_after_a_flush(void)
{
    static const size_t ns[] = {12u, 64u, 101u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        make_importance(ns[i]);
        init_with(&acc, ns[i], MCS_SPECTRUM_PATH_PAIR, 40u);
        run(&acc, MCS_PATTERN_STRATIFIED, ns[i], 9u, &imp, 8u + i, 100u); /* 2 closed, 20 open */
        TEST_ASSERT_EQUAL_UINT64(20u, acc.open_count);
        memcpy(&acc2, &acc, sizeof acc);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_flush(&acc2));
        TEST_ASSERT_EQUAL_UINT64(0u, acc2.open_count);
        TEST_ASSERT_EQUAL_UINT64(3u, acc2.units);
        assert_same_statistics(&acc, &acc2, 1e-12, 1);
    }
}

static void test_a_standard_error_needs_two_units(void)
{
    init_with(&acc, 32u, MCS_SPECTRUM_PATH_PAIR, 0u);
    run(&acc, MCS_PATTERN_RANDOM, 32u, 4u, NULL, 2u, 15u); /* one open batch */
    double v = 7.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&acc, 3u, &v));
    memcpy(&before, &acc, sizeof acc);
    v = 7.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_spectrum_power_stderr(&acc, 3u, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_spectrum_mean_stderr(&acc, 3u, &v));
    TEST_ASSERT_EQUAL_DOUBLE(7.0, v);
    run(&acc, MCS_PATTERN_RANDOM, 32u, 4u, NULL, 3u, 2u); /* a closed batch and an open one */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(&acc, 3u, &v));
    TEST_ASSERT_TRUE(v > 0.0);
}

/* ---------------- merges ---------------- */

static void test_merge_of_halves_equals_one_pass(void)
{
    static const size_t ns[] = {12u, 64u, 101u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i)
        for (size_t p = 0; p < PATHS; ++p) {
            /* PAIR with batches of 25: the halves (300 and 400 trials) split at a
             * batch boundary, so even the units agree. */
            const size_t n = ns[i], k = 5u;
            const uint64_t batch = every_path[p] == MCS_SPECTRUM_PATH_PAIR ? 25u : 0u;
            make_importance(n);
            init_with(&acc, n, every_path[p], batch);
            init_with(&acc2, n, every_path[p], batch);
            init_with(&acc3, n, every_path[p], batch);
            spectra_stream st;
            spectra_stream_init(&st, MCS_PATTERN_RANDOM, n, k, &imp, 40u + i, STREAM_SEQ);
            for (size_t t = 0; t < 700u; ++t) {
                stream_draw(&st);
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, k, bins, weights));
                mcs_spectrum *half = t < 300u ? &acc2 : &acc3;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(half, k, bins, weights));
            }
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_merge(&acc2, &acc3));
            /* AUTO's batches follow the rule, which the split moves */
            const int same_units = every_path[p] != MCS_SPECTRUM_PATH_AUTO;
            if (same_units)
                TEST_ASSERT_EQUAL_UINT64(acc.units, acc2.units);
            assert_same_statistics(&acc2, &acc, 1e-12, same_units);
        }
}

static void test_merging_open_batches_keeps_every_trial(void)
{
    /* Two accumulators with open batches of 7 and 9: the merge sums them into
     * one open batch of 16, which is then due (batch 16) and closes. */
    init_with(&acc, 40u, MCS_SPECTRUM_PATH_PAIR, 16u);
    init_with(&acc2, 40u, MCS_SPECTRUM_PATH_PAIR, 16u);
    init_with(&acc3, 40u, MCS_SPECTRUM_PATH_PAIR, 16u);
    spectra_stream st;
    spectra_stream_init(&st, MCS_PATTERN_STRATIFIED, 40u, 6u, NULL, 77u, STREAM_SEQ);
    for (size_t t = 0; t < 48u; ++t) {
        stream_draw(&st);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, 6u, bins, weights));
        mcs_spectrum *part = t < 16u + 7u ? &acc2 : &acc3;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(part, 6u, bins, weights));
    }
    TEST_ASSERT_EQUAL_UINT64(7u, acc2.open_count);
    TEST_ASSERT_EQUAL_UINT64(9u, acc3.open_count);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_merge(&acc2, &acc3));
    TEST_ASSERT_EQUAL_UINT64(48u, acc2.count);
    TEST_ASSERT_EQUAL_UINT64(0u, acc2.open_count);
    TEST_ASSERT_EQUAL_UINT64(3u, acc2.units);
    assert_same_statistics(&acc2, &acc, 1e-12, 0);
}

static void test_merge_with_an_empty_side_copies_or_keeps(void)
{
    for (size_t p = 0; p < PATHS; ++p) {
        init_with(&acc, 24u, every_path[p], 0u);
        init_with(&acc2, 24u, every_path[p], 0u);
        run(&acc, MCS_PATTERN_JITTER, 24u, 4u, NULL, 9u, 50u);
        memcpy(&before, &acc, sizeof acc);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_merge(&acc, &acc2)); /* empty src */
        TEST_ASSERT_EQUAL_MEMORY(&before, &acc, sizeof acc);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_merge(&acc2, &acc)); /* empty dst */
        assert_same_statistics(&acc2, &acc, 0.0, 1);
    }
}

static void test_merge_with_itself_doubles_the_count_and_keeps_the_means(void)
{
    for (size_t p = 0; p < PATHS; ++p) {
        init_with(&acc, 10u, every_path[p], 0u);
        run(&acc, MCS_PATTERN_RANDOM, 10u, 3u, NULL, 4u, 40u);
        memcpy(&before, &acc, sizeof acc);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_merge(&acc, &acc));
        TEST_ASSERT_EQUAL_UINT64(80u, acc.count);
        for (size_t k = 0; k < 10u; ++k) {
            double a, b;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&acc, k, &a));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&before, k, &b));
            TEST_ASSERT_DOUBLE_WITHIN(1e-15 * (b + 1.0), b, a);
        }
    }
}

static void test_a_copied_accumulator_keeps_working(void)
{
    for (size_t p = 0; p < PATHS; ++p) {
        init_with(&acc, 48u, every_path[p], 0u);
        init_with(&acc2, 48u, every_path[p], 0u);
        run(&acc, MCS_PATTERN_RANDOM, 48u, 5u, NULL, 8u, 10u);
        run(&acc2, MCS_PATTERN_RANDOM, 48u, 5u, NULL, 8u, 10u);
        memcpy(&acc3, &acc, sizeof acc);
        memset(&acc, 0x5a, sizeof acc);
        run(&acc3, MCS_PATTERN_RANDOM, 48u, 5u, NULL, 18u, 30u);
        run(&acc2, MCS_PATTERN_RANDOM, 48u, 5u, NULL, 18u, 30u);
        assert_same_statistics(&acc3, &acc2, 0.0, 1);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_path_gives_the_same_means_to_rounding);
    RUN_TEST(test_pair_batches_of_one_give_the_per_trial_standard_errors);
    RUN_TEST(test_baseline_and_avx2_kernels_give_the_same_bits);
    RUN_TEST(test_bins_dense_and_points_give_the_same_statistics);
    RUN_TEST(test_the_fft_path_sums_weights_as_the_dense_form_does);
    RUN_TEST(test_points_without_weights_count_as_weight_one);
    RUN_TEST(test_one_trial_matches_the_naive_dft_on_every_path);
    RUN_TEST(test_s0_is_k_over_root_n_in_every_trial_without_importance);
    RUN_TEST(test_parseval_holds_for_every_trial);
    RUN_TEST(test_the_batch_rule_gives_32_batches_of_16_then_up_to_1024);
    RUN_TEST(test_read_outs_with_an_open_batch_equal_those_after_a_flush);
    RUN_TEST(test_a_standard_error_needs_two_units);
    RUN_TEST(test_merge_of_halves_equals_one_pass);
    RUN_TEST(test_merging_open_batches_keeps_every_trial);
    RUN_TEST(test_merge_with_an_empty_side_copies_or_keeps);
    RUN_TEST(test_merge_with_itself_doubles_the_count_and_keeps_the_means);
    RUN_TEST(test_a_copied_accumulator_keeps_working);
    return UNITY_END();
}
