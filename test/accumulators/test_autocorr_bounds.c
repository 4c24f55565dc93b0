/* Tests for the autocorrelation accumulator's power read-out at the weight
 * limit (issue 22 item 2): a power is never negative, and every power is
 * within the rounding bound autocorr.h states of the exact mean of |S_k|^2
 * over the trials, formed in long double from the trials' s. */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "mcspec.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define N 16u
#define TMAX 64u

static mcs_autocorr ac;
static mcs_dft plan;
static double trial_s[TMAX][N];
static size_t trial_k[TMAX];
static size_t trials;

static void add_trial(size_t k, const size_t *bins, const double *w)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_add_bins(&ac, k, bins, w));
    TEST_ASSERT_TRUE(trials < TMAX);
    memset(trial_s[trials], 0, sizeof trial_s[trials]);
    for (size_t j = 0; j < k; ++j)
        trial_s[trials][bins[j]] += w[j];
    trial_k[trials++] = k;
}

/* |S_k|^2 of trial t, eq. 7 in long double. A trial whose s is w (1 + [n < 4])
 * (the heavy one below) has S_k = 0 exactly for k = 4, 8, 12 (the four
 * e^{-i pi k n / 8} sum to 0), which long double twiddles would not give:
 * `heavy` takes that closed form, w^2 sin^2(pi k / 4) / sin^2(pi k / 16) / N. */
static long double power_of(size_t t, size_t k, int heavy)
{
    const long double pi = 3.141592653589793238462643383279502884L;
    if (heavy) {
        const long double w = trial_s[t][4];
        if (k == 0u)
            return (20.0L * w) * (20.0L * w) / (long double)N;
        if (k % 4u == 0u)
            return 0.0L;
        const long double a = sinl(pi * (long double)k / 4.0L), b = sinl(pi * (long double)k / 16.0L);
        return w * w * (a * a) / (b * b) / (long double)N;
    }
    long double re = 0.0L, im = 0.0L;
    for (size_t n = 0; n < N; ++n) {
        const long double arg = 2.0L * pi * (long double)((k * n) % N) / (long double)N;
        re += trial_s[t][n] * cosl(arg);
        im -= trial_s[t][n] * sinl(arg);
    }
    return (re * re + im * im) / (long double)N;
}

/* The bound autocorr.h states: (2N + 16 ceil(log2 N) + 192 + T N^2 eps) eps
 * <A(0)>, <A(0)> the mean over the trials of sum_n s_n^2 (of sum_n (s_n -
 * S/N)^2 for a trial of K >= N samples, whose lags are kept centred). */
static long double stated_bound(void)
{
    long double a0 = 0.0L;
    for (size_t t = 0; t < trials; ++t) {
        long double total = 0.0L, sq = 0.0L;
        for (size_t n = 0; n < N; ++n)
            total += trial_s[t][n];
        const long double c = trial_k[t] >= N ? total / (long double)N : 0.0L;
        for (size_t n = 0; n < N; ++n)
            sq += (trial_s[t][n] - c) * (trial_s[t][n] - c);
        a0 += sq;
    }
    const long double tt = (long double)trials, eps = DBL_EPSILON;
    const long double gamma = (2.0L * N + 16.0L * 4.0L + 192.0L + tt * N * N * eps) * eps;
    return gamma * a0 / tt;
}

/* 40 ordinary trials (k samples, weights in [1, 1.75]) and one of 20
 * weights of w each: one in every bin and one more in bins 0..3. */
static void ordinary_then_heavy(size_t k, double w, uint64_t seed)
{
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, seed, 22u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_init(&ac, N));
    trials = 0u;
    for (size_t t = 0; t < 40u; ++t) {
        size_t bins[20];
        double ws[20];
        for (size_t j = 0; j < k; ++j) {
            uint32_t b = 0u;
            double u = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_bounded(&rng, N, &b));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(&rng, &u));
            bins[j] = b;
            ws[j] = 1.0 + 0.75 * u;
        }
        add_trial(k, bins, ws);
    }
    size_t hb[20];
    double hw[20];
    for (size_t j = 0; j < 20u; ++j) {
        hb[j] = j < N ? j : j - N;
        hw[j] = w;
    }
    add_trial(20u, hb, hw);
}

static void expect_powers(const char *label)
{
    double power[N];
    char what[200];
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_autocorr_power(&ac, &plan, N, power));
    const long double bound = stated_bound();
    for (size_t k = 0; k < N; ++k) {
        long double exact = 0.0L;
        for (size_t t = 0; t < trials; ++t)
            exact += power_of(t, k, t == trials - 1u);
        exact /= (long double)trials;
        (void)snprintf(what, sizeof what, "%s: power[%zu] %.6g, exact %.6Lg, bound %.3Lg", label,
                       k, power[k], exact, bound);
        TEST_ASSERT_TRUE_MESSAGE(power[k] >= 0.0, what);
        TEST_ASSERT_TRUE_MESSAGE(fabsl((long double)power[k] - exact) <= bound, what);
    }
}

/* Issue 22 item 2: 40 ordinary trials and one of total weight 2^100 gave
 * power[4] = -2.72e39 beside power[0] = 2.45e57 with MCS_OK (the spectrum
 * and moment accumulators stay >= 0). Here at 2^100 and at the limit (20
 * weights of 2^215: 1.25 2^219 <= MCS_AUTOCORR_MAX_TRIAL), with the
 * ordinary trials summed as pairs (K = 5 < N) and centred (K = 20 >= N). */
static void test_powers_stay_non_negative_and_within_their_bound_at_the_weight_limit(void)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, N));
    TEST_ASSERT_TRUE(20.0 * 0x1p215 <= MCS_AUTOCORR_MAX_TRIAL);
    static const double heavy[3] = {0x1p100 / 20.0, 0x1p160, 0x1p215};
    for (size_t i = 0; i < 3u; ++i) {
        ordinary_then_heavy(5u, heavy[i], 3u + i);
        expect_powers("K = 5");
        ordinary_then_heavy(20u, heavy[i], 7u + i);
        expect_powers("K = 20");
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_powers_stay_non_negative_and_within_their_bound_at_the_weight_limit);
    return UNITY_END();
}
