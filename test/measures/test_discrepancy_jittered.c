/* Tests of the exact L2 discrepancies of jittered points
 * (mcs_discrepancy_l2_exact_jittered, _jittered2d): against an independent
 * quadrature of the per-stratum means a(s) = E h1(u, u) and b(s) = E h1(u, v)
 * of each kernel (Gauss-Legendre on the polynomial pieces, split at 1/2 and
 * along the diagonal, exact for those degrees), combined as
 * (prod A - prod B) / K^2 in long double; against one point (n = 1: the
 * random expectation of K = 1); and against Monte Carlo means of the closed
 * form D^2 over jittered sets drawn here, by mcs_pattern's stratified kind
 * (1D) and mcs_pattern2d's jittered kind (square and 4 x 2 strata), within
 * 5 standard errors, with standard errors below 2 % of the value so a
 * formula wrong by 10 % fails. */
#include "mcspec.h"
#include "unity.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

enum { L2N = MCS_DISCREPANCY_L2_COUNT };

/* ---- the kernels, written again from the header's table ------------------------ */

static long double h1(int m, long double x, long double y)
{
    const long double mx = x > y ? x : y, mn = x > y ? y : x, t = mx - mn;
    const long double cx = fabsl(x - 0.5L), cy = fabsl(y - 0.5L);
    switch (m) {
    case 0: return 1.0L - mx;
    case 1: return 1.0L + (cx + cy - t) / 2.0L;
    case 2: return 1.5L - t * (1.0L - t);
    case 3: return 2.0L * (1.0L - t);
    case 4: return 2.0L - mx;
    default: return mn * (1.0L - mx);
    }
}

/* 8-point Gauss-Legendre on [-1, 1]: exact to degree 15. */
static const long double gl_x[8] = {
    -0.9602898564975362316835609L, -0.7966664774136267395915539L, -0.5255324099163289858177390L,
    -0.1834346424956498049394761L, 0.1834346424956498049394761L,  0.5255324099163289858177390L,
    0.7966664774136267395915539L,  0.9602898564975362316835609L};
static const long double gl_w[8] = {
    0.1012285362903762591525314L, 0.2223810344533744705443560L, 0.3137066458778872873379622L,
    0.3626837833783619829651504L, 0.3626837833783619829651504L, 0.3137066458778872873379622L,
    0.2223810344533744705443560L, 0.1012285362903762591525314L};

static long double node(long double a, long double b, int i)
{
    return 0.5L * (a + b) + 0.5L * (b - a) * gl_x[i];
}

/* int_a^b h1(x, x) dx, split at 1/2. */
static long double diag_integral(int m, long double a, long double b)
{
    if (a < 0.5L && b > 0.5L)
        return diag_integral(m, a, 0.5L) + diag_integral(m, 0.5L, b);
    long double s = 0.0L;
    for (int i = 0; i < 8; ++i)
        s += gl_w[i] * h1(m, node(a, b, i), node(a, b, i));
    return 0.5L * (b - a) * s;
}

/* int over [a, b]^2 of h1, pieces: split at 1/2, then each diagonal square
 * into its triangles y < x and y > x (Duffy: y = a + (x - a) s). */
static long double square_integral(int m, long double a, long double b)
{
    if (a < 0.5L && b > 0.5L) {
        long double s = square_integral(m, a, 0.5L) + square_integral(m, 0.5L, b);
        for (int i = 0; i < 8; ++i) /* the two off-diagonal rectangles, no kink inside */
            for (int j = 0; j < 8; ++j) {
                const long double x = node(a, 0.5L, i), y = node(0.5L, b, j);
                s += 2.0L * 0.25L * (0.5L - a) * (b - 0.5L) * gl_w[i] * gl_w[j] * h1(m, x, y);
            }
        return s;
    }
    long double s = 0.0L;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
            const long double x = node(a, b, i), r = 0.5L * (1.0L + gl_x[j]);
            const long double lo = a + (x - a) * r, hi = b - (b - x) * r; /* y below and above x */
            const long double w = 0.25L * (b - a) * gl_w[i] * gl_w[j];
            s += w * ((x - a) * h1(m, x, lo) + (b - x) * h1(m, x, hi));
        }
    return s;
}

/* A = sum_s E h1(u, u) and B = sum_s E h1(u, v) over the n strata of an axis. */
static void axis_sums(int m, size_t n, long double *a, long double *b)
{
    const long double w = 1.0L / (long double)n;
    *a = *b = 0.0L;
    for (size_t s = 0; s < n; ++s) {
        const long double lo = (long double)s * w, hi = (long double)(s + 1u) * w;
        *a += diag_integral(m, lo, hi) / w;
        *b += square_integral(m, lo, hi) / (w * w);
    }
}

static double reference(int m, size_t dim, const size_t *strata)
{
    long double pa = 1.0L, pb = 1.0L, k = 1.0L;
    for (size_t l = 0; l < dim; ++l) {
        long double a, b;
        axis_sums(m, strata[l], &a, &b);
        pa *= a;
        pb *= b;
        k *= (long double)strata[l];
    }
    return (double)((pa - pb) / (k * k));
}

static double exact(int m, size_t n, size_t dim)
{
    double e = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_l2_exact_jittered((mcs_discrepancy_measure)m, n,
                                                                    dim, &e));
    return e;
}

static double exact2d(int m, size_t nx, size_t ny)
{
    double e = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK,
                          mcs_discrepancy_l2_exact_jittered2d((mcs_discrepancy_measure)m, nx, ny, &e));
    return e;
}

/* ---- tests ------------------------------------------------------------------------- */

static void test_exact_jittered_matches_a_quadrature_of_each_kernel(void)
{
    static const size_t ns[] = {1, 2, 3, 5, 8, 13};
    static const size_t dims[] = {1, 2, 3, 6};
    for (int m = 0; m < L2N; ++m)
        for (size_t i = 0; i < sizeof ns / sizeof ns[0]; ++i)
            for (size_t j = 0; j < sizeof dims / sizeof dims[0]; ++j) {
                const size_t strata[6] = {ns[i], ns[i], ns[i], ns[i], ns[i], ns[i]};
                const double want = reference(m, dims[j], strata);
                TEST_ASSERT_DOUBLE_WITHIN(1e-12 * want, want, exact(m, ns[i], dims[j]));
            }
}

static void test_exact_jittered2d_matches_the_quadrature_for_unequal_strata(void)
{
    static const size_t grid[][2] = {{4, 2}, {2, 4}, {1, 7}, {16, 8}, {3, 5}};
    for (int m = 0; m < L2N; ++m)
        for (size_t g = 0; g < sizeof grid / sizeof grid[0]; ++g) {
            const double want = reference(m, 2u, grid[g]);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * want, want, exact2d(m, grid[g][0], grid[g][1]));
        }
    /* Square strata: the two calls agree to rounding. */
    for (int m = 0; m < L2N; ++m)
        TEST_ASSERT_DOUBLE_WITHIN(1e-15 * exact(m, 6, 2), exact(m, 6, 2), exact2d(m, 6, 6));
}

static void test_one_stratum_is_one_random_point_and_the_star_has_its_closed_form(void)
{
    for (int m = 0; m < L2N; ++m)
        for (size_t d = 1; d <= 8; ++d) {
            double r = -1.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK,
                                  mcs_discrepancy_l2_exact_random((mcs_discrepancy_measure)m, 1, d, &r));
            TEST_ASSERT_DOUBLE_WITHIN(1e-14 * r, r, exact(m, 1, d));
        }
    /* The L2 star: ((n/2)^d - (n/2 - 1/6)^d) / K^2; 1D 1/(6 K^2). */
    for (size_t n = 1; n <= 9; ++n)
        for (size_t d = 1; d <= 4; ++d) {
            const double k = pow((double)n, (double)d);
            const double want = (pow(0.5 * (double)n, (double)d) - pow(0.5 * (double)n - 1.0 / 6.0, (double)d)) / (k * k);
            TEST_ASSERT_DOUBLE_WITHIN(1e-13 * want, want, exact(0, n, d));
        }
    TEST_ASSERT_DOUBLE_WITHIN(1e-18, 1.0 / (6.0 * 100.0 * 100.0), exact(0, 100, 1));
    /* Jittered is better than random for every measure, K > 1. */
    for (int m = 0; m < L2N; ++m) {
        double r = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_l2_exact_random((mcs_discrepancy_measure)m, 64, 2, &r));
        TEST_ASSERT_TRUE(exact(m, 8, 2) < r);
    }
    /* Large grids: no overflow, the 1/K^2 scaling of 1D. */
    TEST_ASSERT_DOUBLE_WITHIN(1e-13 * exact(0, 1000000, 1), 1.0 / 6.0 * 1e-12, exact(0, 1000000, 1));
    TEST_ASSERT_TRUE(exact(3, 2, 63) > 0.0);
}

/* One jittered set by hand in d dimensions, n strata per axis. */
static void jittered_nd(mcs_rng *rng, size_t n, size_t dim, size_t k, double *pts)
{
    for (size_t c = 0; c < k; ++c) {
        size_t rest = c;
        for (size_t l = 0; l < dim; ++l) {
            double xi = 0.0;
            mcs_rng_double(rng, &xi);
            pts[c * dim + l] = ((double)(rest % n) + xi) / (double)n;
            rest /= n;
        }
    }
}

enum { SOURCE_ND, SOURCE_PATTERN1D, SOURCE_PATTERN2D };

/* Mean and standard error of D^2 over t sets, every measure. */
static void monte_carlo(int source, size_t n, size_t dim, size_t nx, size_t ny, uint64_t t,
                        mcs_welford *w)
{
    static double pts[64 * 3];
    static size_t bins[64];
    static double weights[64];
    size_t k = 1;
    for (size_t l = 0; l < dim; ++l)
        k *= n;
    if (source == SOURCE_PATTERN2D)
        k = nx * ny;
    mcs_rng rng;
    mcs_pattern pat;
    mcs_pattern2d pat2;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 20261202u + k + dim, 7u));
    if (source == SOURCE_PATTERN1D)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_STRATIFIED, 4096u, k, NULL));
    if (source == SOURCE_PATTERN2D)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_init(&pat2, MCS_PATTERN2D_JITTERED, k, nx, ny));
    for (int m = 0; m < L2N; ++m)
        mcs_welford_init(&w[m]);
    for (uint64_t s = 0; s < t; ++s) {
        if (source == SOURCE_ND)
            jittered_nd(&rng, n, dim, k, pts);
        else if (source == SOURCE_PATTERN1D)
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &rng, k, bins, weights, pts));
        else
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_draw(&pat2, &rng, k, pts));
        double d2[L2N];
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_l2(k, dim, pts, d2));
        for (int m = 0; m < L2N; ++m)
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_add(&w[m], d2[m]));
    }
}

static void assert_within_5_stderr(const mcs_welford *w, const double *want)
{
    for (int m = 0; m < L2N; ++m) {
        double mean = 0.0, se = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_mean(&w[m], &mean));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_stderr(&w[m], &se));
        char msg[120];
        snprintf(msg, sizeof msg, "%s: mean %.6g exact %.6g se %.3g z %.2f",
                 mcs_discrepancy_measure_str((mcs_discrepancy_measure)m), mean, want[m], se,
                 (mean - want[m]) / se);
        TEST_ASSERT_TRUE_MESSAGE(fabs(mean - want[m]) < 5.0 * se, msg);
        TEST_ASSERT_TRUE_MESSAGE(se < 0.02 * want[m], msg); /* a 10 % error would fail */
    }
}

static void test_monte_carlo_means_of_jittered_sets_are_within_5_stderr(void)
{
    static const size_t cases[][2] = {{8, 1}, {4, 2}, {2, 3}, {3, 3}};
    mcs_welford w[L2N];
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        const size_t n = cases[c][0], dim = cases[c][1];
        monte_carlo(SOURCE_ND, n, dim, 1u, 1u, 20000u, w);
        double want[L2N];
        for (int m = 0; m < L2N; ++m)
            want[m] = exact(m, n, dim);
        assert_within_5_stderr(w, want);
    }
}

static void test_the_library_patterns_are_jittered_sets_with_their_strata(void)
{
    mcs_welford w[L2N];
    double want[L2N];
    /* 1D stratified, K = 16: n = K, d = 1. */
    monte_carlo(SOURCE_PATTERN1D, 16u, 1u, 1u, 1u, 20000u, w);
    for (int m = 0; m < L2N; ++m)
        want[m] = exact(m, 16u, 1u);
    assert_within_5_stderr(w, want);
    /* 2D jittered, 4 columns by 2 rows, and 4 x 4. */
    static const size_t grid[][2] = {{4, 2}, {4, 4}};
    for (size_t g = 0; g < 2; ++g) {
        monte_carlo(SOURCE_PATTERN2D, 0u, 2u, grid[g][0], grid[g][1], 20000u, w);
        for (int m = 0; m < L2N; ++m)
            want[m] = exact2d(m, grid[g][0], grid[g][1]);
        assert_within_5_stderr(w, want);
    }
}

static void test_bad_input_is_refused_and_writes_nothing(void)
{
    double e = 7.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_discrepancy_l2_exact_jittered(MCS_DISCREPANCY_L2_STAR, 2, 2, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_discrepancy_l2_exact_jittered(MCS_DISCREPANCY_MEASURES, 2, 2, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_discrepancy_l2_exact_jittered((mcs_discrepancy_measure)-1, 2, 2, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_discrepancy_l2_exact_jittered(MCS_DISCREPANCY_STAR, 2, 2, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_discrepancy_l2_exact_jittered(MCS_DISCREPANCY_L2_STAR, 2, 0, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_discrepancy_l2_exact_jittered(MCS_DISCREPANCY_L2_STAR, 2, 65, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_discrepancy_l2_exact_jittered(MCS_DISCREPANCY_L2_STAR, 0, 2, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_discrepancy_l2_exact_jittered(MCS_DISCREPANCY_L2_STAR, 3, 64, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_discrepancy_l2_exact_jittered(MCS_DISCREPANCY_L2_STAR, SIZE_MAX, 2, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_discrepancy_l2_exact_jittered2d(MCS_DISCREPANCY_L2_STAR, 2, 2, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_discrepancy_l2_exact_jittered2d(MCS_DISCREPANCY_STAR, 2, 2, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_discrepancy_l2_exact_jittered2d(MCS_DISCREPANCY_L2_STAR, 0, 2, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_discrepancy_l2_exact_jittered2d(MCS_DISCREPANCY_L2_STAR, 2, 0, &e));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE,
                          mcs_discrepancy_l2_exact_jittered2d(MCS_DISCREPANCY_L2_STAR, SIZE_MAX, 2, &e));
    TEST_ASSERT_EQUAL_DOUBLE(7.0, e);
    /* 2^64 cells do not fit; 2^63 do. */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_discrepancy_l2_exact_jittered(MCS_DISCREPANCY_L2_STAR, 2, 63, &e));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_exact_jittered_matches_a_quadrature_of_each_kernel);
    RUN_TEST(test_exact_jittered2d_matches_the_quadrature_for_unequal_strata);
    RUN_TEST(test_one_stratum_is_one_random_point_and_the_star_has_its_closed_form);
    RUN_TEST(test_monte_carlo_means_of_jittered_sets_are_within_5_stderr);
    RUN_TEST(test_the_library_patterns_are_jittered_sets_with_their_strata);
    RUN_TEST(test_bad_input_is_refused_and_writes_nothing);
    return UNITY_END();
}
