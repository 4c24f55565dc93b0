/* The rotation average of a fixed point set (mcs_theory_rotation): against
 * an independent brute-force average over a fine grid of the rotation beta
 * for tiny N and K (exact: every bin is constant on each grid cell),
 * against mcspec's jitter theory for the van der Corput set it reduces to,
 * and against Monte Carlo over beta within 5 standard errors (with the
 * jitter prediction shown to fail there, so the check can tell formulas
 * apart); bad calls change nothing. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mcspec.h"
#include "theory_ref.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static mcs_theory_rotation rot;
static double work[MCS_THEORY_ROTATION_LEN(MCS_MAX_N) + 1u];
static double f[MCS_MAX_N];

/* ---- brute force over beta ---- */

/* Points a_j = idx[j] / grid. A sample moves to the next bin where
 * N (a_j + beta) crosses a whole number, i.e. at multiples of 1/(N grid) in
 * beta, so the cell midpoints beta_c = (c + 1/2) / (N grid), c < N grid,
 * give the exact average. The bin is found in integers:
 * floor(N (a_j + beta_c)) = floor((2 (N idx_j + c) + 1) / (2 grid)) mod N. */
typedef struct {
    long double power[64], mean, var;
} bf_result;

static void brute_force(size_t n, size_t k, const size_t *idx, size_t grid, const double *fv,
                        bf_result *out)
{
    const size_t cells = n * grid;
    long double isum = 0.0L, i2 = 0.0L;
    static long double ivals[64 * 64];
    memset(out, 0, sizeof *out);
    for (size_t c = 0; c < cells; ++c) {
        size_t bin[16];
        long double est = 0.0L;
        for (size_t j = 0; j < k; ++j) {
            bin[j] = ((2u * (n * idx[j] + c) + 1u) / (2u * grid)) % n;
            est += (long double)fv[bin[j]];
        }
        est /= (long double)k;
        ivals[c] = est;
        isum += est;
        for (size_t q = 0; q < n; ++q) {
            long double re = 0.0L, im = 0.0L;
            for (size_t j = 0; j < k; ++j) {
                const long double a = 2.0L * 3.14159265358979323846264338327950288L *
                                      (long double)((q * bin[j]) % n) / (long double)n;
                re += cosl(a);
                im -= sinl(a);
            }
            out->power[q] += (re * re + im * im) / (long double)n;
        }
    }
    out->mean = isum / (long double)cells;
    for (size_t c = 0; c < cells; ++c)
        i2 += (ivals[c] - out->mean) * (ivals[c] - out->mean);
    out->var = i2 / (long double)cells;
    for (size_t q = 0; q < n; ++q)
        out->power[q] /= (long double)cells;
}

static void init_set(size_t n, size_t k, const size_t *idx, size_t grid)
{
    double a[16];
    for (size_t j = 0; j < k; ++j)
        a[j] = (double)idx[j] / (double)grid;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_rotation_init(&rot, n, k, a, work,
                                                           MCS_THEORY_ROTATION_LEN(n)));
}

static void check_against_brute_force(size_t n, size_t k, const size_t *idx, size_t grid)
{
    char what[96];
    bf_result bf;
    theory_make_f(n, f, 0.4 * (double)n);
    brute_force(n, k, idx, grid, f, &bf);
    init_set(n, k, idx, grid);
    const double scale = (double)k * (double)k / (double)n; /* the largest power, at k = 0 */
    for (size_t q = 0; q < n; ++q) {
        double p, re, im;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_rotation_power(&rot, q, &p));
        (void)snprintf(what, sizeof what, "N = %zu, K = %zu: power at k = %zu", n, k, q);
        TEST_ASSERT_TRUE_MESSAGE(fabs(p - (double)bf.power[q]) <= 1e-12 * scale, what);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_rotation_mean(&rot, q, &re, &im));
        TEST_ASSERT_EQUAL_DOUBLE(q == 0u ? (double)k / sqrt((double)n) : 0.0, re);
        TEST_ASSERT_EQUAL_DOUBLE(0.0, im);
    }
    double v;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_rotation_variance(&rot, n, k, f, &v));
    (void)snprintf(what, sizeof what, "N = %zu, K = %zu: Var[I] %.17g, brute force %.17Lg", n, k,
                   v, bf.var);
    TEST_ASSERT_TRUE_MESSAGE(fabs(v - (double)bf.var) <= 1e-12 * ((double)bf.var + 1e-3), what);
    /* <I> is the mean of f: every rotated point's bin is uniform */
    double fbar = 0.0;
    for (size_t b = 0; b < n; ++b)
        fbar += f[b] / (double)n;
    TEST_ASSERT_TRUE(fabs((double)bf.mean - fbar) <= 1e-14);
}

static void test_rotation_averages_equal_a_brute_force_average_over_beta(void)
{
    static const size_t s1[] = {0u, 3u, 7u}, s2[] = {0u, 1u, 4u, 5u}, s3[] = {1u, 3u};
    static const size_t s4[] = {2u, 2u, 5u, 11u, 12u}, s5[] = {0u}, s6[] = {5u, 1u, 6u};
    check_against_brute_force(5u, 3u, s1, 8u);
    check_against_brute_force(7u, 4u, s2, 6u);
    check_against_brute_force(6u, 2u, s3, 4u);
    check_against_brute_force(9u, 5u, s4, 13u); /* a repeated point, two a grid step apart */
    check_against_brute_force(1u, 1u, s5, 1u);
    check_against_brute_force(4u, 1u, s5, 2u);
    check_against_brute_force(12u, 3u, s6, 7u);
}

/* K = 2^m van der Corput points rotated are uniform jitter: the rotation
 * average must give mcspec's jitter theory (a second, independent route). */
static void test_a_rotated_van_der_corput_set_is_uniform_jitter(void)
{
    static mcs_theory_spectrum ts;
    static const size_t ns[] = {16u, 37u, 64u, 100u};
    for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i) {
        const size_t n = ns[i], k = 8u;
        double a[8];
        for (size_t j = 0; j < k; ++j) { /* radical inverse in base 2 of j < 8 */
            a[j] = (double)(((j & 1u) << 2) | (j & 2u) | ((j & 4u) >> 2)) / 8.0;
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_rotation_init(&rot, n, k, a, work, n));
        mcs_pattern pat;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_JITTER, n, k, NULL));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_init(&ts, &pat));
        const double scale = (double)k * (double)k / (double)n;
        for (size_t q = 0; q < n; ++q) {
            double p, pj;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_rotation_power(&rot, q, &p));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_power(&ts, q, &pj));
            TEST_ASSERT_TRUE(fabs(p - pj) <= 1e-13 * scale);
        }
        theory_make_f(n, f, 1.0);
        double v, vj;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_rotation_variance(&rot, n, k, f, &v));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&ts, n, k, f, &vj));
        theory_assert_close(vj, v, 1e-12, "rotated van der Corput Var[I] against jitter");
    }
}

/* The rotated van der Corput set is jitter, whose power is 0 off the
 * multiples of K and whose Var[I] is 0 for an f without energy there; the
 * rotation average, a sum of terms of both signs, left those at -2.5e-16
 * (power) and -1e-18 (variance): they read 0 now, and no read-out is
 * negative. */
static void test_rotation_powers_and_variances_are_never_negative(void)
{
    const size_t n = 64u, k = 16u;
    double a[16];
    for (size_t j = 0; j < k; ++j) /* radical inverse in base 2 of j < 16 */
        a[j] = (double)(((j & 1u) << 3) | ((j & 2u) << 1) | ((j & 4u) >> 1) | ((j & 8u) >> 3)) /
               16.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_rotation_init(&rot, n, k, a, work, n));
    int zeros = 0;
    for (size_t q = 0; q < n; ++q) {
        double p;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_rotation_power(&rot, q, &p));
        TEST_ASSERT_TRUE_MESSAGE(p >= 0.0, "a negative power");
        zeros += p == 0.0;
        if (q % k == 0u)
            TEST_ASSERT_DOUBLE_WITHIN(1e-13, (double)(k * k) / (double)n, p);
        else
            TEST_ASSERT_TRUE(p <= 1e-13);
    }
    TEST_ASSERT_TRUE(zeros > 0);
    for (size_t m = 1; m < 16u; ++m) { /* cos(2 pi m n / N): no energy at multiples of 16 */
        for (size_t b = 0; b < n; ++b)
            f[b] = 0.5 + cos(2.0 * THEORY_PI * (double)((m * b) % n) / (double)n);
        double v;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_rotation_variance(&rot, n, k, f, &v));
        TEST_ASSERT_TRUE_MESSAGE(v >= 0.0 && v <= 1e-15, "Var[I] not at rounding level");
    }
}

/* ---- Monte Carlo over beta ---- */

static void test_monte_carlo_over_beta_agrees_within_five_standard_errors(void)
{
    static mcs_spectrum acc;
    static mcs_theory_spectrum jit;
    const size_t n = 37u, k = 8u, trials = 200000u;
    /* the first 8 Halton base-3 points: no pattern kind */
    const double a[8] = {0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0 / 9.0, 4.0 / 9.0, 7.0 / 9.0, 2.0 / 9.0,
                         5.0 / 9.0};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_rotation_init(&rot, n, k, a, work, n));
    mcs_pattern pat;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_JITTER, n, k, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_init(&jit, &pat));
    theory_make_f(n, f, 0.3);
    mcs_rng rng;
    mcs_welford est;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 2023u, 23u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, n));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_init(&est));
    for (size_t t = 0; t < trials; ++t) {
        double beta, x[8], w[8], i_est;
        size_t bins[8];
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(&rng, &beta));
        for (size_t j = 0; j < k; ++j) {
            x[j] = a[j] + beta;
            x[j] -= floor(x[j]);
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_bin_points(n, k, NULL, x, bins, w));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, k, bins, w));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_bins(n, k, f, bins, w, &i_est));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_add(&est, i_est));
    }
    double worst_jitter = 0.0;
    char what[120];
    for (size_t q = 1; q <= n / 2u; ++q) {
        double meas, se, p, pj;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&acc, q, &meas));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(&acc, q, &se));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_rotation_power(&rot, q, &p));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_power(&jit, q, &pj));
        (void)snprintf(what, sizeof what, "k = %zu: measured %.6g +- %.2g, rotation %.6g", q, meas,
                       se, p);
        TEST_ASSERT_TRUE_MESSAGE(fabs(meas - p) < 5.0 * se, what);
        worst_jitter = fmax(worst_jitter, fabs(meas - pj) / se);
    }
    TEST_ASSERT_TRUE_MESSAGE(worst_jitter > 5.0, "the jitter prediction is not told apart");
    double v, vse, vr, vj;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_variance(&est, &v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_variance_stderr(&est, &vse));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_rotation_variance(&rot, n, k, f, &vr));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&jit, n, k, f, &vj));
    (void)snprintf(what, sizeof what, "Var[I]: measured %.6g +- %.2g, rotation %.6g, jitter %.6g",
                   v, vse, vr, vj);
    TEST_ASSERT_TRUE_MESSAGE(fabs(v - vr) < 5.0 * vse, what);
    TEST_ASSERT_TRUE_MESSAGE(fabs(v - vj) > 5.0 * vse, what);
}

/* ---- bad calls ---- */

#define SENT 777.25

static void fill_work(void)
{
    for (size_t i = 0; i < sizeof work / sizeof work[0]; ++i)
        work[i] = SENT;
}

static void assert_work_untouched(void)
{
    for (size_t i = 0; i < sizeof work / sizeof work[0]; ++i)
        TEST_ASSERT_EQUAL_DOUBLE(SENT, work[i]);
}

static void test_bad_set_ups_change_nothing(void)
{
    double a[4] = {0.1, 0.5, 0.7, 0.9};
    mcs_theory_rotation before;
    memset(&rot, 0x3c, sizeof rot);
    before = rot;
    fill_work();
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_theory_rotation_init(NULL, 8u, 4u, a, work, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_theory_rotation_init(&rot, 8u, 4u, NULL, work, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_theory_rotation_init(&rot, 8u, 4u, a, NULL, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_theory_rotation_init(&rot, 0u, 4u, a, work, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE,
                          mcs_theory_rotation_init(&rot, MCS_MAX_N + 1u, 4u, a, work, 9999u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_theory_rotation_init(&rot, 8u, 0u, a, work, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE,
                          mcs_theory_rotation_init(&rot, 8u, MCS_MAX_K + 1u, a, work, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, mcs_theory_rotation_init(&rot, 8u, 4u, a, work, 7u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_theory_rotation_init(&rot, 8u, 4u, work, work, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS,
                          mcs_theory_rotation_init(&rot, 8u, 4u, a, (double *)(void *)&rot, 8u));
    const double bad[4] = {1.0, -0.25, NAN, INFINITY};
    for (int i = 0; i < 4; ++i) {
        a[3] = bad[i]; /* the last point: found before anything is written */
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE,
                              mcs_theory_rotation_init(&rot, 8u, 4u, a, work, 8u));
    }
    TEST_ASSERT_EQUAL_MEMORY(&before, &rot, sizeof rot);
    assert_work_untouched();
}

static void test_bad_read_outs_change_nothing(void)
{
    const double a[3] = {0.0, 0.4, 0.8};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_rotation_init(&rot, 8u, 3u, a, work, 8u));
    theory_make_f(8u, f, 0.0);
    double out = SENT, re = SENT, im = SENT;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_theory_rotation_power(&rot, 1u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_theory_rotation_power(NULL, 1u, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_theory_rotation_power(&rot, 8u, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_theory_rotation_mean(&rot, 8u, &re, &im));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_theory_rotation_mean(&rot, 0u, &re, &re));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_theory_rotation_variance(&rot, 7u, 3u, f, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_theory_rotation_variance(&rot, 8u, 4u, f, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_theory_rotation_variance(&rot, 8u, 0u, f, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_theory_rotation_variance(&rot, 8u, 3u, NULL, &out));
    f[7] = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_theory_rotation_variance(&rot, 8u, 3u, f, &out));
    f[7] = 1e40;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, mcs_theory_rotation_variance(&rot, 8u, 3u, f, &out));
    f[7] = 0.5;
    /* the work array written since init */
    const double saved = work[5];
    work[5] = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_theory_rotation_power(&rot, 1u, &out));
    work[5] = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_theory_rotation_variance(&rot, 8u, 3u, f, &out));
    work[5] = saved;
    mcs_theory_rotation zero;
    memset(&zero, 0, sizeof zero);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_theory_rotation_power(&zero, 1u, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_theory_rotation_mean(&zero, 0u, &re, &im));
    TEST_ASSERT_EQUAL_DOUBLE(SENT, out);
    TEST_ASSERT_EQUAL_DOUBLE(SENT, re);
    TEST_ASSERT_EQUAL_DOUBLE(SENT, im);
    /* and a good call still works */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_rotation_variance(&rot, 8u, 3u, f, &out));
    TEST_ASSERT_TRUE(out >= 0.0);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_rotation_averages_equal_a_brute_force_average_over_beta);
    RUN_TEST(test_a_rotated_van_der_corput_set_is_uniform_jitter);
    RUN_TEST(test_rotation_powers_and_variances_are_never_negative);
    RUN_TEST(test_monte_carlo_over_beta_agrees_within_five_standard_errors);
    RUN_TEST(test_bad_set_ups_change_nothing);
    RUN_TEST(test_bad_read_outs_change_nothing);
    return UNITY_END();
}
