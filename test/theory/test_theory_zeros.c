/* Exact zeros (theory_internal.h): where theory proves a value 0 for every
 * trial, both exact objects read exactly 0 (no rounding left), and nowhere
 * does a read-out read 0 where the brute-force enumeration of every outcome
 * (test/support/theory_ref.c) says the value is not. The rules are restated
 * here from the note and the header, independently of the library's code:
 * - S_0 and S_{N/2} are real: Im <S_k> = 0 there, and the imaginary part of
 *   a second moment of two such S;
 * - without importance S_0 = K / sqrt(N) in every trial, so Cov(S_0, S_l) = 0
 *   and a constant f has Var[I] = 0; <S_k> = 0 for k != 0 (every kind but
 *   uniform);
 * - random, homogenized and jitter without importance are stationary:
 *   Cov(S_k, S_l) = 0 for k != l; stratified without importance: unless
 *   gcd(N, K) divides k - l;
 * - jitter without importance (and uniform, whose counts repeat): S_k = 0
 *   unless gcd(N, K) divides k;
 * - uniform, and without importance every kind but random with N dividing
 *   K: s is deterministic, every covariance and Var[I] is 0. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mcspec.h"
#include "theory_ref.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define NMAX 12

static mcs_theory th;
static mcs_theory_spectrum ts;
static mcs_importance imp;
static double bf_mean[NMAX], bf_second[NMAX * NMAX];
static double mat_re[NMAX * NMAX], mat_im[NMAX * NMAX];
static long double bf_s_re[NMAX], bf_s_im[NMAX];

static size_t gcd(size_t a, size_t b)
{
    while (b != 0u) {
        const size_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* ---- the rules, restated ---- */

typedef struct {
    mcs_pattern_kind kind;
    size_t n, k;
    int imp;
} shape;

static int real_freq(const shape *s, size_t q) { return q == 0u || 2u * q == s->n; }

static int fixed_s(const shape *s)
{
    return s->kind == MCS_PATTERN_UNIFORM ||
           (!s->imp && s->kind != MCS_PATTERN_RANDOM && s->k % s->n == 0u);
}

static int s_zero(const shape *s, size_t q)
{
    if (q == 0u)
        return 0;
    if (!s->imp && fixed_s(s) && s->kind != MCS_PATTERN_UNIFORM)
        return 1;
    /* the uniform pattern's counts repeat every N/g bins here (the theory
     * checks its stored counts; every shape below has them repeat) */
    return (!s->imp && (s->kind == MCS_PATTERN_JITTER || s->kind == MCS_PATTERN_UNIFORM)) &&
           q % gcd(s->n, s->k) != 0u;
}

static int mean_zero(const shape *s, size_t q)
{
    return s_zero(s, q) || (q != 0u && !s->imp && s->kind != MCS_PATTERN_UNIFORM);
}

static int cov_zero(const shape *s, size_t k, size_t l)
{
    if (fixed_s(s) || s_zero(s, k) || s_zero(s, l) || (!s->imp && (k == 0u || l == 0u)))
        return 1;
    if (s->imp || k == l)
        return 0;
    if (s->kind == MCS_PATTERN_STRATIFIED)
        return (k + s->n - l) % gcd(s->n, s->k) != 0u;
    return s->kind != MCS_PATTERN_UNIFORM;
}

static int cross_zero(const shape *s, size_t k, size_t l)
{
    return s_zero(s, k) || s_zero(s, l) || (cov_zero(s, k, l) && (mean_zero(s, k) || mean_zero(s, l)));
}

/* ---- brute force, transformed in long double ---- */

static void bf_transform(size_t n)
{
    for (size_t q = 0; q < n; ++q) {
        long double r = 0.0L, i = 0.0L;
        for (size_t b = 0; b < n; ++b) {
            const long double a = 2.0L * 3.14159265358979323846264338327950288L *
                                  (long double)((q * b) % n) / (long double)n;
            r += cosl(a) * bf_mean[b];
            i -= sinl(a) * bf_mean[b];
        }
        bf_s_re[q] = r / sqrtl((long double)n);
        bf_s_im[q] = i / sqrtl((long double)n);
    }
}

/* Cov(S_k, S_l) from the enumerated moments. */
static void bf_cov(size_t n, size_t k, size_t l, long double *re, long double *im)
{
    long double r = 0.0L, i = 0.0L;
    const long double tp = 2.0L * 3.14159265358979323846264338327950288L / (long double)n;
    for (size_t m = 0; m < n; ++m)
        for (size_t b = 0; b < n; ++b) {
            const long double c = (long double)bf_second[m * n + b] -
                                  (long double)bf_mean[m] * (long double)bf_mean[b];
            const long double a = tp * (long double)(((k * m) % n + n - (l * b) % n) % n);
            r += cosl(a) * c;
            i -= sinl(a) * c;
        }
    *re = r / (long double)n;
    *im = i / (long double)n;
}

static int is_zero(double x)
{
    const double z = 0.0;
    return memcmp(&x, &z, sizeof x) == 0; /* +0 */
}

static double scale_of(size_t n)
{
    double a = 0.0;
    for (size_t j = 0; j < n * n; ++j)
        a += fabs(bf_second[j]);
    return a / (double)n + 1e-300;
}

/* A read-out that must be 0 by a rule is +0; one that reads 0 must be 0 to
 * rounding in the brute force. */
static void judge(const char *what, const shape *s, size_t k, size_t l, int rule, double got,
                  long double bf, double scale)
{
    char msg[160];
    (void)snprintf(msg, sizeof msg, "%s N=%zu K=%zu %s%s at (%zu, %zu): %.17g, brute force %.3Lg",
                   what, s->n, s->k, mcs_pattern_kind_str(s->kind), s->imp ? "+imp" : "", k, l,
                   got, bf);
    if (rule) {
        TEST_ASSERT_TRUE_MESSAGE(is_zero(got), msg);
    }
    if (rule || got == 0.0) {
        TEST_ASSERT_TRUE_MESSAGE(fabsl(bf) <= 1e-12L * (long double)scale, msg);
    }
}

static void check_shape(const shape *s, size_t grid)
{
    const size_t n = s->n, k = s->k;
    mcs_pattern pat;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, s->kind, n, k, s->imp ? &imp : NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(&th, &pat));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_init(&ts, &pat));
    theory_brute_force(s->kind, n, k, s->imp ? &imp : NULL, grid, bf_mean, bf_second);
    bf_transform(n);
    const double scale = scale_of(n), amp = sqrt(scale);
    for (size_t a = 0; a < n; ++a) {
        double re, im;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_mean(&th, a, &re, &im));
        judge("Re <S_k> (N x N)", s, a, a, mean_zero(s, a), re, bf_s_re[a], amp);
        judge("Im <S_k> (N x N)", s, a, a, mean_zero(s, a) || real_freq(s, a), im, bf_s_im[a], amp);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_mean(&ts, a, &re, &im));
        judge("Re <S_k>", s, a, a, mean_zero(s, a), re, bf_s_re[a], amp);
        judge("Im <S_k>", s, a, a, mean_zero(s, a) || real_freq(s, a), im, bf_s_im[a], amp);
        for (size_t b = 0; b < n; ++b) {
            long double cr, ci;
            bf_cov(n, a, b, &cr, &ci);
            const int imz = a == b || (real_freq(s, a) && real_freq(s, b));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_covariance(&th, a, b, &re, &im));
            judge("Re Cov (N x N)", s, a, b, cov_zero(s, a, b), re, cr, scale);
            judge("Im Cov (N x N)", s, a, b, cov_zero(s, a, b) || imz, im, ci, scale);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_covariance(&ts, a, b, &re, &im));
            judge("Re Cov", s, a, b, cov_zero(s, a, b), re, cr, scale);
            judge("Im Cov", s, a, b, cov_zero(s, a, b) || imz, im, ci, scale);
            /* <S_k S_l*> = Cov + <S_k><S_l>* */
            const long double xr = cr + bf_s_re[a] * bf_s_re[b] + bf_s_im[a] * bf_s_im[b];
            const long double xi = ci + bf_s_im[a] * bf_s_re[b] - bf_s_re[a] * bf_s_im[b];
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross(&th, a, b, &re, &im));
            judge("Re cross (N x N)", s, a, b, cross_zero(s, a, b), re, xr, scale);
            judge("Im cross (N x N)", s, a, b, cross_zero(s, a, b) || imz, im, xi, scale);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_cross(&ts, a, b, &re, &im));
            judge("Re cross", s, a, b, cross_zero(s, a, b), re, xr, scale);
            judge("Im cross", s, a, b, cross_zero(s, a, b) || imz, im, xi, scale);
        }
        double p;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, a, &p));
        judge("power (N x N)", s, a, a, s_zero(s, a), p, bf_s_re[a] * bf_s_re[a], scale);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_power(&ts, a, &p));
        judge("power", s, a, a, s_zero(s, a), p, bf_s_re[a] * bf_s_re[a], scale);
    }
    /* the matrices carry the same zeros */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_covariance_matrix(&th, n, mat_re, mat_im));
    for (size_t a = 0; a < n; ++a)
        for (size_t b = 0; b < n; ++b)
            if (cov_zero(s, a, b)) {
                TEST_ASSERT_TRUE(is_zero(mat_re[a * n + b]) && is_zero(mat_im[a * n + b]));
            }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross_matrix(&th, n, mat_re, mat_im));
    for (size_t a = 0; a < n; ++a)
        for (size_t b = 0; b < n; ++b)
            if (cross_zero(s, a, b)) {
                TEST_ASSERT_TRUE(is_zero(mat_re[a * n + b]) && is_zero(mat_im[a * n + b]));
            }
    /* Var[I]: a constant f without importance, any f for a fixed s */
    double f[NMAX], c[NMAX], v;
    theory_make_f(n, f, 0.7);
    for (size_t b = 0; b < n; ++b)
        c[b] = 0.3; /* 0.3 K / K rounds: the sum of s f is not exact */
    const int fixed = fixed_s(s);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, k, c, &v));
    TEST_ASSERT_TRUE(!(fixed || !s->imp) || is_zero(v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&ts, n, k, c, &v));
    TEST_ASSERT_TRUE(!(fixed || !s->imp) || is_zero(v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, k, f, &v));
    TEST_ASSERT_TRUE(!fixed || is_zero(v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&ts, n, k, f, &v));
    TEST_ASSERT_TRUE(!fixed || is_zero(v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_estimator_covariance(&th, n, k, f, c, &v));
    TEST_ASSERT_TRUE(!(fixed || !s->imp) || is_zero(v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_estimator_covariance(&ts, n, k, c, f, &v));
    TEST_ASSERT_TRUE(!(fixed || !s->imp) || is_zero(v));
}

static void run_shapes(int with_imp)
{
    static const size_t shapes[][2] = {{4u, 2u}, {4u, 3u}, {6u, 4u}, {6u, 3u}, {6u, 2u},
                                       {8u, 4u}, {5u, 2u}, {3u, 5u}, {2u, 7u}, {4u, 8u},
                                       {1u, 3u}, {9u, 6u}, {12u, 8u}, {3u, 6u}, {8u, 6u}};
    for (size_t i = 0; i < sizeof shapes / sizeof shapes[0]; ++i) {
        const size_t n = shapes[i][0], k = shapes[i][1];
        if (with_imp && n < 2u)
            continue;
        size_t denom = n;
        if (with_imp) {
            /* weights 1 + (b mod 3), the last one raised so that they sum
             * to a power of two: the CDF is then exact, on a grid of it */
            double w[NMAX];
            size_t total = 0u, pow2 = 1u;
            for (size_t b = 0; b < n; ++b) {
                w[b] = 1.0 + (double)(b % 3u);
                total += 1u + b % 3u;
            }
            while (pow2 < total)
                pow2 *= 2u;
            w[n - 1u] += (double)(pow2 - total);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, w));
            denom = pow2;
        }
        for (int kind = 0; kind < MCS_PATTERN_KIND_COUNT; ++kind) {
            const shape s = {(mcs_pattern_kind)kind, n, k, with_imp};
            if (with_imp && kind == MCS_PATTERN_HOMOGENIZED)
                continue;
            /* enumerate while the outcomes stay few: their sums of 1/p are
             * not exact, and many of them would round visibly */
            const size_t grid = theory_lcm(denom, k);
            const double outcomes = kind == MCS_PATTERN_RANDOM ? pow((double)grid, (double)k)
                                    : kind == MCS_PATTERN_STRATIFIED ||
                                            kind == MCS_PATTERN_HOMOGENIZED
                                        ? pow((double)(grid / k), (double)k)
                                        : (double)grid;
            if (outcomes > 3e5)
                continue;
            check_shape(&s, grid);
        }
    }
}

static void test_zeros_by_theory_read_exactly_0_without_importance(void)
{
    run_shapes(0);
}

static void test_zeros_by_theory_read_exactly_0_with_importance(void)
{
    run_shapes(1);
}

/* What item 2 of issue 23 reported: sec1's jitter Var[I_f] read 3.0e-19 from
 * the N x N moments (a difference of second moments), 1.5e-32 measured. Its
 * f has, in exact arithmetic, no energy at the multiples of K, but its
 * stored doubles do: the exact variance of those doubles is ~1e-32, not 0,
 * so no rule forces it; the O(N) route, which forms no difference, gives
 * it to that level. */
static void test_a_small_variance_that_theory_does_not_prove_0_is_left_as_computed(void)
{
    const size_t n = 64u, k = 8u;
    double f[64];
    for (size_t b = 0; b < n; ++b) {
        const double y = ((double)b + 0.5) / (double)n;
        f[b] = 0.5 + 0.3 * sin(2.0 * THEORY_PI * (y + 0.5)) + (y >= 0.5 ? 0.4 : 0.0);
    }
    mcs_pattern pat;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_JITTER, n, k, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_init(&ts, &pat));
    double v;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&ts, n, k, f, &v));
    /* the variance over the N/K = 8 equally likely bin offsets of the comb
     * sums, in long double */
    long double c[8], mean = 0.0L, var = 0.0L;
    for (size_t m = 0; m < 8u; ++m) {
        c[m] = 0.0L;
        for (size_t j = 0; j < k; ++j)
            c[m] += (long double)f[m + 8u * j];
        c[m] /= (long double)k;
        mean += c[m] / 8.0L;
    }
    for (size_t m = 0; m < 8u; ++m)
        var += (c[m] - mean) * (c[m] - mean) / 8.0L;
    TEST_ASSERT_TRUE(v > 0.0 && v < 1e-30);
    TEST_ASSERT_TRUE(var > 0.0L && var < 1e-30L);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_zeros_by_theory_read_exactly_0_without_importance);
    RUN_TEST(test_zeros_by_theory_read_exactly_0_with_importance);
    RUN_TEST(test_a_small_variance_that_theory_does_not_prove_0_is_left_as_computed);
    return UNITY_END();
}
