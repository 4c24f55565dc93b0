/* The spectrum accumulator's statistical claims, with fixed seeds: the
 * note's spectra measured on the default path and on a per-trial one, and
 * the calibration of the standard errors (batch means on the PAIR path):
 * z-scores of measured against exact values are N(0, 1) across patterns. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mcspec.h"
#include "spectra_ref.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define PI 3.14159265358979323846
#define STREAM_SEQ 0x5eedu

static mcs_spectrum acc;
static mcs_importance imp;
static mcs_theory theory;
static size_t bins[64];
static double weights[64];

static void run(mcs_spectrum *a, mcs_pattern_kind kind, size_t n, size_t k,
                const mcs_importance *importance, uint64_t seed, size_t trials)
{
    spectra_run(a, kind, n, k, importance, seed, STREAM_SEQ, trials, bins, weights);
}

static void make_importance(size_t n)
{
    spectra_make_importance(&imp, n, 0.2, 7u, 3u, 2.0);
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

/* Each claim on the default path (AUTO, which takes PAIR here) and forced SPARSE. */
static const mcs_spectrum_path two_paths[] = {MCS_SPECTRUM_PATH_AUTO, MCS_SPECTRUM_PATH_SPARSE};

static void measure(size_t p, mcs_pattern_kind kind, size_t n, size_t k,
                    const mcs_importance *importance, uint64_t seed, size_t trials)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_path(&acc, two_paths[p]));
    run(&acc, kind, n, k, importance, seed + 1000u * p, trials);
}

static void test_random_power_is_k_over_n_and_mean_is_zero(void)
{
    for (size_t p = 0; p < 2u; ++p) {
        measure(p, MCS_PATTERN_RANDOM, 16u, 4u, NULL, 23u, 100000u);
        assert_spectrum(&acc, 4u, 1.0, random_power, 1);
    }
}

static void test_stratified_power_follows_the_exact_finite_n_form(void)
{
    for (size_t p = 0; p < 2u; ++p) {
        measure(p, MCS_PATTERN_STRATIFIED, 32u, 4u, NULL, 29u, 200000u);
        assert_spectrum(&acc, 4u, 1.0, stratified_power, 1);
    }
}

static void test_jitter_power_is_k2_over_n_at_multiples_of_k_and_zero_elsewhere(void)
{
    for (size_t p = 0; p < 2u; ++p) {
        measure(p, MCS_PATTERN_JITTER, 24u, 4u, NULL, 31u, 20000u);
        assert_spectrum(&acc, 4u, 1.0, jitter_power, 1);
    }
}

static void test_uniform_is_biased_at_multiples_of_k(void)
{
    measure(0u, MCS_PATTERN_UNIFORM, 24u, 4u, NULL, 37u, 10u);
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
    for (size_t p = 0; p < 2u; ++p) {
        measure(p, MCS_PATTERN_RANDOM, 12u, 3u, &imp, 41u, 100000u);
        assert_spectrum(&acc, 3u, imp.harmonic_mean, importance_power, 1);
    }
}


/* ---------------- calibration of the standard errors ---------------- */

/* Patterns with exact moments from mcs_theory (N <= 64), K dividing N or not,
 * with and without importance. (Jitter's power is the same in every trial,
 * so it calibrates only the mean.) */
static const struct {
    mcs_pattern_kind kind;
    size_t n, k;
    int importance;
} configs[] = {
    {MCS_PATTERN_RANDOM, 16u, 4u, 0},      {MCS_PATTERN_STRATIFIED, 32u, 8u, 0},
    {MCS_PATTERN_STRATIFIED, 30u, 7u, 0},  {MCS_PATTERN_JITTER, 24u, 5u, 0},
    {MCS_PATTERN_RANDOM, 12u, 3u, 1},      {MCS_PATTERN_HOMOGENIZED, 16u, 4u, 0},
    {MCS_PATTERN_STRATIFIED, 20u, 6u, 1},  {MCS_PATTERN_RANDOM, 40u, 9u, 1},
};
#define CONFIGS (sizeof configs / sizeof configs[0])
#define RUNS 80u          /* independent runs per pattern (M = 560 to 640 in all) */
#define RUN_TRIALS 1024u

/* z-scores over M runs, one frequency per run (k = 1, 2, ... in turn, so
 * runs are independent): z = (<|S_k|^2> - exact) / se for the power, and
 * q = |<S_k> - exact|^2 / se^2 for the mean (E q = 1: se^2 estimates
 * E|<S_k> - exact|^2 for the complex spread). */
typedef struct {
    double z_sum, z_sq, q_sum;
    size_t z_used, q_used, runs;
} z_tally;

static void one_run(size_t c, size_t r, mcs_spectrum_path path, uint64_t batch, z_tally *zt)
{
    const size_t n = configs[c].n, k = configs[c].k, f = 1u + r % (n / 2u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_path(&acc, path));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_set_batch(&acc, batch));
    run(&acc, configs[c].kind, n, k, configs[c].importance ? &imp : NULL, 7919u * c + r + 1u,
        RUN_TRIALS);
    double pw, pse, re, im, se, want, wre, wim;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&acc, f, &pw));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(&acc, f, &pse));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&acc, f, &re, &im));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(&acc, f, &se));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&theory, f, &want));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_mean(&theory, f, &wre, &wim));
    zt->runs += 1u;
    if (pse > 1e-9 * want) { /* else |S_k|^2 is the same in every trial */
        const double z = (pw - want) / pse;
        zt->z_sum += z;
        zt->z_sq += z * z;
        zt->z_used += 1u;
    }
    if (se > 1e-9 * sqrt(want)) {
        const double dr = re - wre, di = im - wim;
        zt->q_sum += (dr * dr + di * di) / (se * se);
        zt->q_used += 1u;
    }
}

/* With M z-scores the mean has SE 1/sqrt(M) = 0.042 and the sample sd about
 * sqrt((kurtosis - 1) / (4 M)) = 0.031 (kurtosis about 3.2 for a t with
 * the 30-60 units a run has); batch means over U units make z a t_{U-1},
 * whose sd is up to 3% above 1 and whose mean moves by a few hundredths with
 * the skew of |S_k|^2. So: |mean z| < 4 SE + 0.03 = 0.2, |sd - 1| < 4 SE +
 * 0.03 = 0.155, and the mean of q (sd about 1.4 / sqrt(M) = 0.06, t excess
 * up to 0.07) within [0.75, 1.32]. A standard error off by the batch's
 * sqrt(B) (4 or more) or by counting trials for units fails all three. */
static void assert_calibrated(mcs_spectrum_path path, uint64_t batch)
{
    z_tally zt = {0.0, 0.0, 0.0, 0u, 0u, 0u};
    for (size_t c = 0; c < CONFIGS; ++c) {
        mcs_pattern pat;
        const mcs_importance *ip = NULL;
        if (configs[c].importance) {
            make_importance(configs[c].n);
            ip = &imp;
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, configs[c].kind, configs[c].n,
                                                       configs[c].k, ip));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(&theory, &pat));
        for (size_t r = 0; r < RUNS; ++r)
            one_run(c, r, path, batch, &zt);
    }
    TEST_ASSERT_EQUAL_UINT64(CONFIGS * RUNS, zt.runs);
    TEST_ASSERT_EQUAL_UINT64(zt.runs, zt.q_used);
    TEST_ASSERT_EQUAL_UINT64(zt.runs - RUNS, zt.z_used); /* all but jitter's */
    const double m = (double)zt.z_used, mean = zt.z_sum / m;
    const double sd = sqrt((zt.z_sq - m * mean * mean) / (m - 1.0)), q = zt.q_sum / (double)zt.q_used;
    char msg[160];
    (void)snprintf(msg, sizeof msg, "path %d batch %u: z mean %.3f sd %.3f over %zu, q mean %.3f",
                   (int)path, (unsigned)batch, mean, sd, zt.z_used, q);
    printf("calibration, %s\n", msg);
    TEST_ASSERT_TRUE_MESSAGE(fabs(mean) < 0.2, msg);
    TEST_ASSERT_TRUE_MESSAGE(fabs(sd - 1.0) < 0.155, msg);
    TEST_ASSERT_TRUE_MESSAGE(q > 0.75 && q < 1.32, msg);
}

static void test_pair_standard_errors_by_the_batch_rule_are_calibrated(void)
{
    assert_calibrated(MCS_SPECTRUM_PATH_PAIR, 0u);
}

static void test_pair_standard_errors_with_batches_of_16_are_calibrated(void)
{
    assert_calibrated(MCS_SPECTRUM_PATH_PAIR, 16u);
}

static void test_auto_standard_errors_are_calibrated(void)
{
    assert_calibrated(MCS_SPECTRUM_PATH_AUTO, 0u);
}

static void test_per_trial_standard_errors_are_calibrated(void)
{
    assert_calibrated(MCS_SPECTRUM_PATH_SPARSE, 0u);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_random_power_is_k_over_n_and_mean_is_zero);
    RUN_TEST(test_stratified_power_follows_the_exact_finite_n_form);
    RUN_TEST(test_jitter_power_is_k2_over_n_at_multiples_of_k_and_zero_elsewhere);
    RUN_TEST(test_uniform_is_biased_at_multiples_of_k);
    RUN_TEST(test_importance_sampled_random_power_is_k_over_n_h);
    RUN_TEST(test_pair_standard_errors_by_the_batch_rule_are_calibrated);
    RUN_TEST(test_pair_standard_errors_with_batches_of_16_are_calibrated);
    RUN_TEST(test_auto_standard_errors_are_calibrated);
    RUN_TEST(test_per_trial_standard_errors_are_calibrated);
    return UNITY_END();
}
