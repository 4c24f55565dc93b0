/* Tests of the exact spacing expectations of random points
 * (mcs_spacing_exact_random): the 2D average minimum distance against an
 * independent quadrature of int (1 - A(r))^(K-1) dr, with A(r), the area of
 * the toroidal disk, integrated here from its chords (not the segment
 * formula); Gamma(K) / Gamma(K + 1/2) against a long double recurrence
 * where the library switches to Stirling's series; the large-K limit; and
 * Monte Carlo means of mcs_spacing over random sets with fixed seeds within
 * 5 standard errors (1D min and avg, 2D avg at K = 2, where the torus
 * corners matter most, and K = 16), with standard errors small enough that
 * the plausible wrong forms (a plain disk area, 1/K instead of 1/K^2) fail. */
#include "mcspec.h"
#include "unity.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

void setUp(void) {}
void tearDown(void) {}

static const long double pi_l = 3.141592653589793238462643383279503L;

/* 32-point Gauss-Legendre nodes and weights on [-1, 1], by Newton on P_32. */
static long double gx[32], gw[32];

static void gauss_legendre(void)
{
    const int n = 32;
    for (int i = 0; i < n; ++i) {
        long double x = cosl(pi_l * (i + 0.75L) / (n + 0.5L)), dp = 0.0L;
        for (int it = 0; it < 100; ++it) {
            long double p0 = 1.0L, p1 = x;
            for (int j = 2; j <= n; ++j) {
                const long double p2 = ((2 * j - 1) * x * p1 - (j - 1) * p0) / j;
                p0 = p1;
                p1 = p2;
            }
            dp = n * (x * p1 - p0) / (x * x - 1.0L);
            const long double dx = p1 / dp;
            x -= dx;
            if (fabsl(dx) < 1e-19L)
                break;
        }
        gx[i] = x;
        gw[i] = 2.0L / ((1.0L - x * x) * dp * dp);
    }
}

/* Area of {|p| <= r} in [-1/2, 1/2]^2, from chords: 4 int_0^{1/2} min(1/2,
 * sqrt(r^2 - x^2)) dx, the chord part by x = r sin(theta). */
static long double area_ref(long double r)
{
    const long double x0 = r > 0.5L ? sqrtl(r * r - 0.25L) : 0.0L;
    const long double t0 = asinl(x0 / r), t1 = r > 0.5L ? asinl(0.5L / r) : pi_l / 2.0L;
    long double chord = 0.0L;
    for (int i = 0; i < 32; ++i) {
        const long double t = 0.5L * (t0 + t1) + 0.5L * (t1 - t0) * gx[i], c = cosl(t);
        chord += gw[i] * r * r * c * c;
    }
    chord *= 0.5L * (t1 - t0);
    return 4.0L * (0.5L * x0 + chord);
}

/* E R = int_0^{sqrt 2/2} (1 - A)^(K-1) dr: [0, 1/2] in 16 panels; [1/2,
 * sqrt 2/2] with r = 1/2 + L s^2, in which A is smooth, 16 panels. */
static double nearest_ref(size_t k)
{
    const long double km1 = (long double)(k - 1u), len = sqrtl(0.5L) - 0.5L;
    long double sum = 0.0L;
    for (int p = 0; p < 16; ++p)
        for (int i = 0; i < 32; ++i) {
            const long double r = (p + 0.5L + 0.5L * gx[i]) / 32.0L; /* panels of 1/32 */
            sum += gw[i] / 64.0L * powl(1.0L - area_ref(r), km1);
        }
    for (int p = 0; p < 16; ++p)
        for (int i = 0; i < 32; ++i) {
            const long double s = (p + 0.5L + 0.5L * gx[i]) / 16.0L, r = 0.5L + len * s * s;
            const long double u = 1.0L - area_ref(r);
            sum += gw[i] / 32.0L * 2.0L * len * s * powl(u > 0.0L ? u : 0.0L, km1);
        }
    return (double)sum;
}

static double dmax(size_t dim, size_t k)
{
    double d = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_packing_distance(dim, k, &d));
    return d;
}

static double exact(mcs_spacing_statistic s, size_t dim, size_t k)
{
    double e = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_exact_random(s, dim, k, &e));
    return e;
}

static void test_2d_average_minimum_distance_matches_an_independent_quadrature(void)
{
    static const size_t ks[] = {2, 3, 4, 5, 8, 13, 30, 64, 65, 100};
    for (size_t i = 0; i < sizeof ks / sizeof ks[0]; ++i) {
        const double want = nearest_ref(ks[i]) / dmax(2, ks[i]);
        const double got = exact(MCS_SPACING_AVG_MIN_DISTANCE, 2, ks[i]);
        char msg[80];
        snprintf(msg, sizeof msg, "K = %zu: %.17g against %.17g", ks[i], got, want);
        TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-13 * want, want, got, msg);
    }
    /* K = 2 by hand: int_0^{rmax} (1 - A) dr is the mean toroidal distance
     * of two points, E |p| for p uniform on the square: (sqrt 2 + asinh 1) / 6. */
    const double two = (sqrt(2.0) + asinh(1.0)) / 6.0 / dmax(2, 2);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14, two, exact(MCS_SPACING_AVG_MIN_DISTANCE, 2, 2));
}

/* Gamma(K) / Gamma(K + 1/2) by the recurrence in long double. */
static long double ratio_ref(size_t k)
{
    long double r = 2.0L / sqrtl(pi_l);
    for (size_t j = 1; j < k; ++j)
        r *= (long double)j / ((long double)j + 0.5L);
    return r;
}

static void test_large_sets_follow_the_gamma_ratio_and_its_limit(void)
{
    static const size_t ks[] = {65, 66, 200, 1000, 12345, 100000};
    for (size_t i = 0; i < sizeof ks / sizeof ks[0]; ++i) {
        /* the corrections are below (1 - pi/4)^64 / 4 ~ 1e-43 here */
        const double want = (double)(0.5L * ratio_ref(ks[i])) / dmax(2, ks[i]);
        TEST_ASSERT_DOUBLE_WITHIN(2e-14 * want, want, exact(MCS_SPACING_AVG_MIN_DISTANCE, 2, ks[i]));
    }
    const double limit = sqrt(sqrt(3.0) / 8.0);
    TEST_ASSERT_DOUBLE_WITHIN(1e-6, limit, exact(MCS_SPACING_AVG_MIN_DISTANCE, 2, 10000000u));
    TEST_ASSERT_TRUE(exact(MCS_SPACING_AVG_MIN_DISTANCE, 2, 1000000u) > limit); /* from above: 1 + 1/(8K) */
}

/* Gamma(K) / Gamma(K + a) by the recurrence in long double. */
static long double ratio_ref_a(size_t k, long double a, long double gamma_1a)
{
    long double r = 1.0L / gamma_1a;
    for (size_t j = 1; j < k; ++j)
        r *= (long double)j / ((long double)j + a);
    return r;
}

static void test_3d_to_8d_give_the_ball_s_value_from_the_first_k_the_bound_allows(void)
{
    static const size_t first[9] = {0, 0, 0, 52, 104, 212, 450, 1007, 2370};
    /* V_d^(-1/d) and Gamma(1 + 1/d), written again */
    for (size_t d = 3; d <= 8; ++d) {
        const long double v = powl(pi_l, (long double)d / 2.0L) / tgammal((long double)d / 2.0L + 1.0L);
        const long double a = 1.0L / (long double)d, g = tgammal(1.0L + a);
        double e = 7.0;
        TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN,
                              mcs_spacing_exact_random(MCS_SPACING_AVG_MIN_DISTANCE, d, first[d] - 1u, &e));
        TEST_ASSERT_EQUAL_DOUBLE(7.0, e);
        const size_t ks[4] = {first[d], first[d] + 1u, 5000u, 123457u};
        for (int i = 0; i < 4; ++i) {
            const long double want = powl(v, -a) * g * ratio_ref_a(ks[i], a, g);
            const double got = exact(MCS_SPACING_AVG_MIN_DISTANCE, d, ks[i]) * dmax(d, ks[i]);
            TEST_ASSERT_DOUBLE_WITHIN(2e-14 * (double)want, (double)want, got);
        }
        TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN,
                              mcs_spacing_exact_random(MCS_SPACING_MIN_DISTANCE, d, 100000u, &e));
    }
}

static void test_1d_values_are_their_closed_forms(void)
{
    for (size_t k = 2; k < 100; k += 7) {
        TEST_ASSERT_EQUAL_DOUBLE(0.5, exact(MCS_SPACING_AVG_MIN_DISTANCE, 1, k));
        TEST_ASSERT_DOUBLE_WITHIN(1e-16, 1.0 / (double)k, exact(MCS_SPACING_MIN_DISTANCE, 1, k));
    }
}

/* Means over t random sets of k points in dim dimensions. */
static void monte_carlo(size_t dim, size_t k, uint64_t t, mcs_spacing *acc)
{
    static double pts[64 * 3];
    size_t bytes = 0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_work_size(dim, k, &bytes));
    void *work = bytes > 0u ? malloc(bytes) : NULL;
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 777u + k, dim));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_init(acc, dim));
    for (uint64_t s = 0; s < t; ++s) {
        for (size_t i = 0; i < k * dim; ++i)
            mcs_rng_double(&rng, &pts[i]);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_add(acc, k, pts, work, bytes));
    }
    free(work);
}

static void assert_z(const mcs_spacing *acc, mcs_spacing_statistic s, double want, double rel)
{
    double mean = 0.0, se = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_mean(acc, s, &mean));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_stderr(acc, s, &se));
    char msg[120];
    snprintf(msg, sizeof msg, "%s: mean %.6g exact %.6g se %.3g z %.2f",
             mcs_spacing_statistic_str(s), mean, want, se, (mean - want) / se);
    TEST_ASSERT_TRUE_MESSAGE(fabs(mean - want) < 5.0 * se, msg);
    TEST_ASSERT_TRUE_MESSAGE(se < rel * want, msg);
}

static void test_monte_carlo_means_of_random_sets_are_within_5_stderr(void)
{
    mcs_spacing acc;
    monte_carlo(1, 8, 20000u, &acc);
    assert_z(&acc, MCS_SPACING_MIN_DISTANCE, exact(MCS_SPACING_MIN_DISTANCE, 1, 8), 0.01);
    assert_z(&acc, MCS_SPACING_AVG_MIN_DISTANCE, exact(MCS_SPACING_AVG_MIN_DISTANCE, 1, 8), 0.01);
    /* K = 2: the corners beyond r = 1/2 add 1.7 % to E R (0.03 % at K = 4), so
     * a plain disk area is more than 10 se off. */
    monte_carlo(2, 2, 100000u, &acc);
    assert_z(&acc, MCS_SPACING_AVG_MIN_DISTANCE, exact(MCS_SPACING_AVG_MIN_DISTANCE, 2, 2), 0.0015);
    monte_carlo(2, 16, 4000u, &acc);
    assert_z(&acc, MCS_SPACING_AVG_MIN_DISTANCE, exact(MCS_SPACING_AVG_MIN_DISTANCE, 2, 16), 0.01);
    monte_carlo(3, 52, 2000u, &acc);
    assert_z(&acc, MCS_SPACING_AVG_MIN_DISTANCE, exact(MCS_SPACING_AVG_MIN_DISTANCE, 3, 52), 0.01);
}

static void test_bad_input_is_refused_and_writes_nothing(void)
{
    double e = 7.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spacing_exact_random(MCS_SPACING_MIN_DISTANCE, 1, 4, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_spacing_exact_random(MCS_SPACING_STATISTICS, 1, 4, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_spacing_exact_random((mcs_spacing_statistic)-1, 1, 4, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_spacing_exact_random(MCS_SPACING_MIN_DISTANCE, 0, 4, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_spacing_exact_random(MCS_SPACING_MIN_DISTANCE, 9, 4, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_spacing_exact_random(MCS_SPACING_MIN_DISTANCE, 2, 4, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_spacing_exact_random(MCS_SPACING_AVG_MIN_DISTANCE, 3, 4, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_spacing_exact_random(MCS_SPACING_MIN_DISTANCE, 1, 1, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_spacing_exact_random(MCS_SPACING_AVG_MIN_DISTANCE, 2, 0, &e));
    TEST_ASSERT_EQUAL_DOUBLE(7.0, e);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_exact_random(MCS_SPACING_AVG_MIN_DISTANCE, 2, SIZE_MAX, &e));
    TEST_ASSERT_TRUE(isfinite(e) && e > 0.0);
}

int main(void)
{
    gauss_legendre();
    UNITY_BEGIN();
    RUN_TEST(test_2d_average_minimum_distance_matches_an_independent_quadrature);
    RUN_TEST(test_large_sets_follow_the_gamma_ratio_and_its_limit);
    RUN_TEST(test_3d_to_8d_give_the_ball_s_value_from_the_first_k_the_bound_allows);
    RUN_TEST(test_1d_values_are_their_closed_forms);
    RUN_TEST(test_monte_carlo_means_of_random_sets_are_within_5_stderr);
    RUN_TEST(test_bad_input_is_refused_and_writes_nothing);
    return UNITY_END();
}
