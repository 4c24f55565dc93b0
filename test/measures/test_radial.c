/* Tests of psa's spectral statistics (radial.h): the effective Nyquist
 * frequency and the oscillation metric against a transliteration of psa's
 * statistics.cpp (its arrays and loops as written, in double) on random
 * spectra, and hand-computed values: white noise (0 and 0), a step from 0
 * to 1 at sqrt(K) (0.95 of the scale), a step to 1.1 (the trapezoid of a
 * linear integrand, exact); and bad input. */
#include "mcspec.h"
#include "unity.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define N 400
static double power[N];

/* psa's EffectiveNyquist: cumpower[i] *= dx 2 x_i, prefix sums, / x_i^2;
 * then the two threshold scans; returned as nu_j / sqrt(K) (x / 2 times
 * psa's fnorm 2 / sqrt(K)). 1D takes weight 1 and / x_i, entry 0 left out. */
static double psa_nyquist(size_t dim, size_t k, size_t n, const double *p, double dx)
{
    double cum[N];
    for (size_t i = 0; i < n; ++i)
        cum[i] = i == 0u ? 0.0 : p[i] * dx * (dim == 1u ? 1.0 : 2.0 * (double)i * dx);
    for (size_t i = 1; i < n; ++i)
        cum[i] += cum[i - 1];
    for (size_t i = 1; i < n; ++i)
        cum[i] /= dim == 1u ? (double)i * dx : ((double)i * dx) * ((double)i * dx);
    const double scale = dim == 1u ? (double)k : sqrt((double)k);
    size_t i0 = (size_t)(scale / 2.0 / dx);
    for (size_t i = i0 > 0u ? i0 : 1u; i < n; ++i)
        if (cum[i] > 0.5)
            for (size_t j = i; j > 0u; j--)
                if (cum[j] < 0.1)
                    return (double)j * dx / 2.0 * (2.0 / scale);
    return 0.0;
}

/* psa's OscillationsMetric with its Integrate (the trapezoid from x0's
 * index to ToIndex(x1 + dx)). */
static double psa_osci(size_t dim, size_t k, size_t n, const double *p, double dx)
{
    double nuosci = 0.0, maxp = 0.0;
    for (size_t i = 1; i < n && maxp < 0.98; ++i)
        if (p[i] > maxp) {
            maxp = p[i];
            nuosci = (double)i * dx;
        }
    const double scale = dim == 1u ? (double)k : sqrt((double)k);
    const double x0 = nuosci, x1 = fmin(x0 + 10.0 * scale / 2.0, (double)n * dx);
    double c[N];
    for (size_t i = 0; i < n; ++i) {
        const double nu = (double)i * dx;
        c[i] = nu < x0 ? 0.0 : (p[i] - 1.0) * (p[i] - 1.0) * (dim == 1u ? 1.0 : nu);
    }
    size_t i0 = (size_t)(x0 / dx), i1 = (size_t)((x1 + dx) / dx);
    i1 = i1 < n - 1u ? i1 : n - 1u;
    double t = 0.5 * (c[i0] + c[i1]), m = 0.0;
    for (size_t i = i0 + 2u; i < i1; i += 2u) {
        t += c[i];
        m += c[i - 1u];
    }
    const double integral = dx * (t + m) * (dim == 1u ? 1.0 : 2.0);
    const double measure = dim == 1u ? x1 - x0 : x1 * x1 - x0 * x0;
    return 10.0 * sqrt(integral / measure);
}

static double nyq(size_t dim, size_t k, size_t n, double step)
{
    double v = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_radial_effective_nyquist(dim, k, n, power, step, &v));
    return v;
}

static double osc(size_t dim, size_t k, size_t n, double step)
{
    double v = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_radial_oscillations(dim, k, n, power, step, &v));
    return v;
}

static void test_white_noise_has_no_effective_nyquist_and_no_oscillation(void)
{
    for (size_t i = 0; i < N; ++i)
        power[i] = 1.0;
    power[0] = 400.0;
    TEST_ASSERT_EQUAL_DOUBLE(0.0, nyq(2u, 400u, N, 1.0));
    TEST_ASSERT_EQUAL_DOUBLE(0.0, osc(2u, 400u, N, 1.0));
    TEST_ASSERT_EQUAL_DOUBLE(0.0, nyq(1u, 40u, N, 1.0));
}

static void test_a_step_at_sqrt_k_gives_the_last_frequency_below_the_step(void)
{
    for (size_t i = 0; i < N; ++i)
        power[i] = i < 20u ? 0.0 : 1.0;
    /* C_20 = (20 21 - 19 20) / 400 = 0.1 exactly is not below 0.1; C_19 = 0. */
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 19.0 / 20.0, nyq(2u, 400u, N, 1.0));
    for (size_t i = 0; i < N; ++i)
        power[i] = i < 20u ? 0.0 : 1.1;
    /* x0 = 20, x1 = 120, the trapezoid over 20..121 of 0.01 * 2 nu (exact). */
    TEST_ASSERT_DOUBLE_WITHIN(1e-13, sqrt((121.0 * 121.0 - 400.0) / 14000.0), osc(2u, 400u, N, 1.0));
}

static void test_the_metrics_match_psas_loops_on_random_spectra(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 2013u, 1u);
    for (int t = 0; t < 200; ++t) {
        const size_t dim = 1u + (size_t)(t % 2), k = dim == 1u ? 30u : 900u;
        const double step = t % 3 == 0 ? 0.5 : 1.0;
        const double edge = (20.0 + (double)(t % 17)) / step;
        for (size_t i = 0; i < N; ++i) {
            double u = 0.0;
            mcs_rng_double(&rng, &u);
            const double base = (double)i < edge ? 0.02 * (double)i / edge : 1.0;
            power[i] = base + 0.3 * (u - 0.5) + ((double)i > edge && (double)i < edge + 6.0 ? 0.8 : 0.0);
        }
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, psa_nyquist(dim, k, N, power, step), nyq(dim, k, N, step));
        const double want = psa_osci(dim, k, N, power, step);
        TEST_ASSERT_DOUBLE_WITHIN(1e-12 * want, want, osc(dim, k, N, step));
    }
}

static void test_bad_input_is_refused_and_writes_nothing(void)
{
    for (size_t i = 0; i < N; ++i)
        power[i] = 1.0;
    double v = 3.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_radial_effective_nyquist(2u, 4u, N, NULL, 1.0, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_radial_oscillations(2u, 4u, N, power, 1.0, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_radial_effective_nyquist(3u, 4u, N, power, 1.0, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_radial_effective_nyquist(2u, 4u, 1u, power, 1.0, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_radial_oscillations(2u, 4u, N, power, 0.0, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_radial_oscillations(2u, 4u, N, power, NAN, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_radial_oscillations(2u, 0u, N, power, 1.0, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_radial_oscillations(2u, 4u, N, power, 1e-101, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_radial_effective_nyquist(2u, 4u, N, power, 1e101, &v));
    power[9] = -2e100;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_radial_effective_nyquist(2u, 4u, N, power, 1.0, &v));
    power[9] = 1e100; /* the cap itself: finite results */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_radial_oscillations(1u, 4u, N, power, 1.0, &v));
    TEST_ASSERT_TRUE(isfinite(v));
    v = 3.0;
    power[9] = 1.0;
    power[7] = INFINITY;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_radial_oscillations(2u, 4u, N, power, 1.0, &v));
    power[7] = 1.0;
    power[0] = NAN; /* entry 0 is never read */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_radial_oscillations(2u, 4u, N, power, 1.0, &v));
    for (size_t i = 0; i < N; ++i)
        power[i] = 0.5; /* never reaches 0.98: nu_o is the argmax, the first entry */
    power[N - 1] = 0.9;
    double w = 3.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_radial_oscillations(2u, 4u, N, power, 1.0, &w));
    TEST_ASSERT_EQUAL_DOUBLE(3.0, w);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_white_noise_has_no_effective_nyquist_and_no_oscillation);
    RUN_TEST(test_a_step_at_sqrt_k_gives_the_last_frequency_below_the_step);
    RUN_TEST(test_the_metrics_match_psas_loops_on_random_spectra);
    RUN_TEST(test_bad_input_is_refused_and_writes_nothing);
    return UNITY_END();
}
