/* Tests for the moment accumulator's accuracy with large weights (issue 22
 * item 1): trials that differ by small amounts on top of a large common
 * weight, which importance sampling produces (1/p_n reaches 2^32 / N).
 * Every reference is formed in long double from the trials' s (each s_n the
 * sum of its bin's weights in sample order, the trial as the library takes
 * it), and every tolerance is the rounding bound moment.h states for
 * Var[I], evaluated in long double from the same trials. */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "mcspec.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define NMAX 64u
#define TMAX (2u * MCS_MOMENT_BATCH + 1200u)

static mcs_moment mom, mom2;
static uint8_t rec[1u << 17];
/* The trials of a case, densely, as the library takes them. */
static double trial_s[TMAX][NMAX];
static size_t trials;
static double case_w; /* the common weight of the case, for messages */

/* ---------------- the reference and the stated bound ---------------- */

/* A trial's s from its sparse form, summed in sample order. */
static void record_trial(size_t n, size_t k, const size_t *bins, const double *w)
{
    TEST_ASSERT_TRUE(trials < TMAX);
    double *s = trial_s[trials++];
    memset(s, 0, n * sizeof *s);
    for (size_t j = 0; j < k; ++j)
        s[bins[j]] += w[j];
}

static void add_trial(mcs_moment *acc, size_t n, size_t k, const size_t *bins, const double *w)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(acc, k, bins, w));
    record_trial(n, k, bins, w);
}

/* Var[I] = (1/T) sum_t (I_t - <I>)^2, I_t = (1/K) sum_n f_n s_n, in long
 * double: two passes over I_t - I_0, formed from s_t - s_0 bin by bin (the
 * difference of two doubles, exact where they are close), so that no large
 * common weight cancels in long double either. */
static long double deviation(size_t n, size_t k, const double *f, size_t t)
{
    long double i = 0.0L;
    for (size_t m = 0; m < n; ++m)
        i += (long double)f[m] * ((long double)trial_s[t][m] - trial_s[0][m]);
    return i / (long double)k;
}

static long double exact_variance(size_t n, size_t k, const double *f)
{
    long double mean = 0.0L, var = 0.0L;
    for (size_t t = 0; t < trials; ++t)
        mean += deviation(n, k, f, t);
    mean /= (long double)trials;
    for (size_t t = 0; t < trials; ++t) {
        const long double dev = deviation(n, k, f, t) - mean;
        var += dev * dev;
    }
    return var / (long double)trials;
}

/* Sums over the trials of d = s - c and d d^T (c the object's shift), in
 * long double, for the stated bound; taken once per object (a merge into
 * itself or a save and load keeps the shift and the averages). */
static long double ref_d[NMAX], ref_dd[NMAX][NMAX];

static void reference_sums(const mcs_moment *acc, size_t n)
{
    memset(ref_d, 0, sizeof ref_d);
    memset(ref_dd, 0, sizeof ref_dd);
    for (size_t t = 0; t < trials; ++t)
        for (size_t m = 0; m < n; ++m) {
            const long double dm = (long double)trial_s[t][m] - acc->shift[m];
            if (dm == 0.0L)
                continue;
            ref_d[m] += dm;
            for (size_t q = 0; q < n; ++q)
                ref_dd[m][q] += dm * ((long double)trial_s[t][q] - acc->shift[q]);
        }
}

/* The bound moment.h states for mcs_moment_variance, <.> the average over
 * the trials of d = s - c (reference_sums):
 *   (2N + 16) eps (1/K^2) sum_{m,n} |f_m| |f_n| (|<d_m d_n>| + |<d_m>| |<d_n>|)
 *   + 3 gamma (1/K^2) (sum_m |f_m| sqrt(<d_m^2>))^2,
 * gamma = (MCS_MOMENT_BATCH + 64) eps. */
static long double stated_bound(size_t n, size_t k, const double *f)
{
    const long double tt = (long double)trials, kk = (long double)k, eps = DBL_EPSILON;
    long double form = 0.0L, root = 0.0L;
    for (size_t m = 0; m < n; ++m) {
        root += fabsl((long double)f[m]) * sqrtl(ref_dd[m][m] / tt);
        for (size_t q = 0; q < n; ++q)
            form += fabsl((long double)f[m] * f[q]) *
                    (fabsl(ref_dd[m][q] / tt) + fabsl(ref_d[m] / tt) * fabsl(ref_d[q] / tt));
    }
    const long double gamma = ((long double)MCS_MOMENT_BATCH + 64.0L) * eps;
    return ((2.0L * (long double)n + 16.0L) * eps * form + 3.0L * gamma * root * root) /
           (kk * kk);
}

/* Var[I] of acc read within the stated bound of the reference, >= 0, and
 * every diagonal covariance read out (no MCS_ERR_INVARIANT). */
static void expect_variance(const mcs_moment *acc, size_t n, size_t k, const double *f,
                            long double want, const char *label)
{
    char what[160];
    double v = -1.0;
    TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_OK, mcs_moment_variance(acc, n, k, f, &v), what);
    const long double bound = stated_bound(n, k, f);
    (void)snprintf(what, sizeof what, "%s: W %g: Var[I] %.17g, exact %.17Lg, bound %.3Lg", label,
                   case_w, v, want, bound);
    TEST_ASSERT_TRUE_MESSAGE(v >= 0.0, what);
    TEST_ASSERT_TRUE_MESSAGE(fabsl((long double)v - want) <= bound, what);
    for (size_t freq = 0; freq < n; ++freq) {
        double re = -1.0, im = 0.0;
        TEST_ASSERT_EQUAL_INT_MESSAGE(MCS_OK, mcs_moment_covariance(acc, freq, freq, &re, &im),
                                      what);
        TEST_ASSERT_TRUE_MESSAGE(re >= 0.0, what);
    }
}

/* ---------------- the reproducer of issue 22 ---------------- */

/* N = 6, K = 3, f = (1, 2, 3, 1, 2, 3). Trial 1 (k = 10 > N: binned whole)
 * gives s = (0, 5, 0, 0, 2, W + 1) (weights 1 and W in bin 5, in that order:
 * (W + 1) rounded), trial 2 one sample of W in bin 5. I_1 - I_2 = (10 + 4 +
 * 3 (s_5 - W)) / 3, so Var[I] = ((I_1 - I_2) / 2)^2: (17/6)^2 = 289/36 when
 * W + 1 is a double, (14/6)^2 = 49/9 when it rounds to W. The object is
 * then merged into itself (the same averages). */
static void reproducer(double scale, double w, long double want)
{
    const size_t b1[10] = {4u, 1u, 1u, 5u, 5u, 0u, 4u, 1u, 1u, 1u};
    const double unit[10] = {1, 1, 1, 0, 1, 0, 1, 1, 1, 1};
    const size_t b2[1] = {5u};
    const double f[6] = {1, 2, 3, 1, 2, 3};
    double w1[10], w2[1] = {scale * w};
    for (size_t j = 0; j < 10u; ++j)
        w1[j] = scale * unit[j];
    w1[3] = scale * w;
    trials = 0u;
    case_w = scale * w;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, 6u));
    add_trial(&mom, 6u, 10u, b1, w1);
    add_trial(&mom, 6u, 1u, b2, w2);
    TEST_ASSERT_TRUE(fabsl(exact_variance(6u, 3u, f) - want) <= 1e-15L * want);
    reference_sums(&mom, 6u);
    expect_variance(&mom, 6u, 3u, f, want, "two trials");
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_merge(&mom, &mom));
    memcpy(trial_s[2], trial_s[0], sizeof trial_s[0]);
    memcpy(trial_s[3], trial_s[1], sizeof trial_s[1]);
    trials = 4u;
    reference_sums(&mom, 6u);
    expect_variance(&mom, 6u, 3u, f, want, "merged into itself");
}

/* W from 1 to near MCS_MOMENT_MAX_TRIAL: the same variance for every W. It
 * was right up to W = 1e7, 7.5278 at 1e8 and 1e9 (6 % low), -8184.47 at
 * 1e10 with MCS_OK, and after the self-merge MCS_ERR_INVARIANT for every
 * covariance of an object built by valid calls. */
static void test_the_variance_of_two_trials_does_not_depend_on_their_common_weight(void)
{
    static const double exact_w[] = {1.0, 1e4, 1e7, 1e8, 1e9, 1e10, 1e12, 1e15, 0x1p52};
    static const double rounded_w[] = {1e17, 1e20, 1e40, 1e60, 1e66};
    for (size_t i = 0; i < sizeof exact_w / sizeof exact_w[0]; ++i)
        reproducer(1.0, exact_w[i], 289.0L / 36.0L);
    for (size_t i = 0; i < sizeof rounded_w / sizeof rounded_w[0]; ++i)
        reproducer(1.0, rounded_w[i], 49.0L / 9.0L); /* W + 1 rounds to W */
}

/* The same with every weight scaled by a power of two (all sums exact), so
 * that the cancellation (W against differences of 1) and the magnitude
 * (up to 2^218, the limit is 2^220) are both at their extremes. */
static void test_the_variance_is_exact_to_its_bound_at_every_scale_up_to_the_limit(void)
{
    static const double scales[] = {0x1p-60, 0x1p100, 0x1p160};
    static const double ws[] = {1e4, 1e8, 1e12, 1e15};
    for (size_t s = 0; s < sizeof scales / sizeof scales[0]; ++s)
        for (size_t i = 0; i < sizeof ws / sizeof ws[0]; ++i)
            reproducer(scales[s], ws[i], 289.0L / 36.0L * scales[s] * scales[s]);
    reproducer(0x1p166, 0x1p52, 289.0L / 36.0L * 0x1p166L * 0x1p166L);
    TEST_ASSERT_TRUE(0x1p166 * (0x1p52 + 8.0) <= MCS_MOMENT_MAX_TRIAL);
}

/* ---------------- many trials around a large common weight ---------------- */

/* T trials of K random samples (weights in [1, 2)) on N = 64 bins, one more
 * sample always in bin 0 weighing W plus a small whole number: every kernel
 * (pairs of samples, dense rows) and, past MCS_MOMENT_BATCH trials, a fold
 * of the batch see trials whose s_0 cancels W. Var[I] of two integrands
 * after a merge of two halves (or, with halves = 0, one pass), a save and
 * load and a merge into itself, within the stated bound. */
static void many_trials(double w, size_t k, size_t count, int halves)
{
    const size_t n = NMAX;
    double f[NMAX], g[NMAX];
    for (size_t m = 0; m < n; ++m) {
        f[m] = 1.0 + 0.25 * (double)(m % 5u);
        g[m] = (m % 2u ? -1.0 : 1.0) * (0.5 + 0.125 * (double)(m % 7u));
    }
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 22u, (uint64_t)k));
    case_w = w;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom2, n));
    trials = 0u;
    for (size_t t = 0; t < count; ++t) {
        size_t bins[NMAX + 1u];
        double ws[NMAX + 1u];
        uint32_t j4 = 0u;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_bounded(&rng, 4u, &j4));
        bins[0] = 0u;
        ws[0] = w + (double)j4;
        for (size_t j = 1; j <= k; ++j) {
            uint32_t b = 0u;
            double u = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_bounded(&rng, (uint32_t)n, &b));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(&rng, &u));
            bins[j] = b;
            ws[j] = 1.0 + u;
        }
        add_trial(halves && t >= count / 2u ? &mom2 : &mom, n, k + 1u, bins, ws);
    }
    if (halves)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_merge(&mom, &mom2));
    const long double vf = exact_variance(n, k + 1u, f), vg = exact_variance(n, k + 1u, g);
    reference_sums(&mom, n);
    expect_variance(&mom, n, k + 1u, f, vf, "f");
    expect_variance(&mom, n, k + 1u, g, vg, "g");
    size_t len = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_save_moment(&mom, sizeof rec, rec, &len));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_io_load_moment(&mom2, len, rec));
    expect_variance(&mom2, n, k + 1u, f, vf, "loaded, f");
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_merge(&mom2, &mom2));
    memcpy(trial_s[trials], trial_s[0], trials * sizeof trial_s[0]);
    trials *= 2u;
    expect_variance(&mom2, n, k + 1u, g, vg, "merged into itself, g");
}

static void test_many_trials_around_a_large_weight_keep_their_variance(void)
{
    static const double ws[] = {1.0, 1e8, 1e12, 1e15};
    for (size_t i = 0; i < sizeof ws / sizeof ws[0]; ++i) {
        many_trials(ws[i], 7u, 2000u, 1);  /* pairs of samples */
        many_trials(ws[i], 40u, 600u, 1);  /* dense rows */
    }
    many_trials(1e12, 7u, MCS_MOMENT_BATCH + 600u, 0); /* past a fold */
}

/* The shift settles over the first MCS_MOMENT_SETTLE trials (moment.h):
 * the first trial's s on the bins every one of them fills, 0 elsewhere,
 * and the sums move with it, so every read-out is that of the trials
 * added (the moves within the stated bound). Bins 0 and 1 are filled by
 * every trial (bin 0 around 1e12), bin b = 2..5 by trials 1 .. b - 1 (and
 * from trial 11 on), so bins 2, 3, 4 drop out at trials 2, 3, 4 and bin 5
 * stays, bin 6 by trials 1 and 5 and a few more. */
static void test_the_shift_keeps_only_the_bins_the_first_trials_all_fill(void)
{
    const size_t n = 8u;
    const double big = 1e12, f[8] = {1, -2, 3, 0.5, 1, 1, 2, -1};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, n));
    trials = 0u;
    case_w = big;
    for (size_t t = 0; t < 40u; ++t) {
        size_t bins[8];
        double w[8];
        size_t k = 0u;
        bins[k] = 0u, w[k++] = big + (double)(t % 3u);
        bins[k] = 1u, w[k++] = 2.0 + 0.25 * (double)(t % 5u);
        for (size_t b = 2u; b < 6u; ++b)
            if (t + 1u < b || t >= 10u)
                bins[k] = b, w[k++] = 1.0 + 0.125 * (double)((t + b) % 7u);
        if (t == 0u || t == 4u || t % 9u == 3u)
            bins[k] = 6u, w[k++] = 3.0;
        add_trial(&mom, n, k, bins, w);
    }
    for (size_t b = 0; b < n; ++b) /* kept where all of the first four fill it */
        TEST_ASSERT_EQUAL_DOUBLE(b < 2u || b == 5u ? trial_s[0][b] : 0.0, mom.shift[b]);
    reference_sums(&mom, n);
    expect_variance(&mom, n, 2u, f, exact_variance(n, 2u, f), "settled");
    for (size_t b = 0; b < n; ++b) {
        long double mean = 0.0L;
        for (size_t t = 0; t < trials; ++t)
            mean += (long double)trial_s[t][b] - trial_s[0][b];
        mean = trial_s[0][b] + mean / (long double)trials;
        double v = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_bin_mean(&mom, b, &v));
        TEST_ASSERT_TRUE(fabsl((long double)v - mean) <= 1e-15L * fabsl(mean) + 1e-15L);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_the_variance_of_two_trials_does_not_depend_on_their_common_weight);
    RUN_TEST(test_the_variance_is_exact_to_its_bound_at_every_scale_up_to_the_limit);
    RUN_TEST(test_many_trials_around_a_large_weight_keep_their_variance);
    RUN_TEST(test_the_shift_keeps_only_the_bins_the_first_trials_all_fill);
    return UNITY_END();
}
