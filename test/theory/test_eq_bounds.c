/* Tests for the limits of the closed forms (issue 10): re == im refused,
 * integrands above MCS_ESTIMATE_MAX_ABS (and powers above
 * MCS_EQ_MAX_POWER) refused rather than read out as inf or NaN, and the
 * variances never negative. The forms themselves are tested in test_eq.c. */
#include "mcspec.h"
#include "theory_ref.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define SENTINEL (-7.25e300)

static mcs_importance imp, imp_copy;

/* The call is made before its output is looked at (the evaluation order of
 * a function's arguments is unspecified, so the two are kept apart). */
#define EXPECT(check, call, ...)            \
    do {                                    \
        const mcs_status st_ = (call);      \
        check(st_, __VA_ARGS__);            \
    } while (0)

/* ---- item 10: one double for both parts of a complex result --------------- */

typedef mcs_status (*pair_fn)(size_t, size_t, size_t, size_t, double *, double *);
typedef mcs_status (*imp_pair_fn)(const mcs_importance *, size_t, size_t, size_t, double *,
                                  double *);

/* The call into one double: MCS_ERR_ALIAS and the double untouched; into two
 * it gives (re, im), and into two inside imp (read by the imp forms) the same. */
static void expect_alias_refused(mcs_status both_st, double both)
{
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, both_st);
    TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, both);
}

static void test_a_complex_result_into_one_double_is_refused_and_elsewhere_is_written(void)
{
    const pair_fn pairs[3] = {mcs_eq30_stratified_delta_printed,
                              mcs_eq30_stratified_delta_corrected, mcs_eq30_stratified_cross};
    for (int i = 0; i < 3; ++i) {
        double both = SENTINEL, re = SENTINEL, im = SENTINEL;
        EXPECT(expect_alias_refused, pairs[i](12u, 4u, 1u, 5u, &both, &both), both);
        TEST_ASSERT_EQUAL_INT(MCS_OK, pairs[i](12u, 4u, 1u, 5u, &re, &im));
        TEST_ASSERT_TRUE(im != 0.0); /* so re == im would have lost a part */
    }
    double both = SENTINEL;
    EXPECT(expect_alias_refused, mcs_eq34_uniform_spectrum(8u, 4u, 4u, &both, &both), both);
    EXPECT(expect_alias_refused, mcs_eq35_jitter_mean(8u, 4u, 0u, &both, &both), both);
    /* a bad argument keeps its own status: ALIAS is the last check */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_eq30_stratified_cross(12u, 5u, 1u, 5u, &both, &both));

    theory_lumpy_importance(&imp, 12u);
    const imp_pair_fn ipairs[2] = {mcs_eq43_importance_cross,
                                   mcs_eq49_importance_stratified_cross};
    for (int i = 0; i < 2; ++i) {
        double re = SENTINEL, im = SENTINEL;
        both = SENTINEL;
        memcpy(&imp_copy, &imp, sizeof imp);
        EXPECT(expect_alias_refused, ipairs[i](&imp, 4u, 1u, 6u, &both, &both), both);
        TEST_ASSERT_EQUAL_MEMORY(&imp_copy, &imp, sizeof imp);
        TEST_ASSERT_EQUAL_INT(MCS_OK, ipairs[i](&imp, 4u, 1u, 6u, &re, &im));
        TEST_ASSERT_TRUE(im != 0.0);
        /* written last: the result may go over the p_n it is formed from */
        TEST_ASSERT_EQUAL_INT(MCS_OK, ipairs[i](&imp, 4u, 1u, 6u, &imp.p[0], &imp.p[1]));
        TEST_ASSERT_EQUAL_DOUBLE(re, imp.p[0]);
        TEST_ASSERT_EQUAL_DOUBLE(im, imp.p[1]);
        memcpy(&imp, &imp_copy, sizeof imp);
    }
}

/* ---- item 5: magnitudes ------------------------------------------------------ */

#define NBIG (MCS_MAX_COV_N + 8)
static double f_max[MCS_MAX_N], f_over[MCS_MAX_N], power_max[MCS_MAX_N];
static mcs_theory th;
static mcs_pattern pat;

/* An importance function as lumpy as accepted: g_0 just above
 * MCS_IMPORTANCE_MIN_G, so 1/p_0 is near 2^32 / N. */
static void steep_importance(size_t n)
{
    static double w[MCS_MAX_N];
    double rest = 0.0;
    for (size_t b = 1; b < n; ++b)
        rest += w[b] = 1.0 + (double)(b % 3u);
    w[0] = 1.01 * MCS_IMPORTANCE_MIN_G * rest;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, w));
}

/* f at the bound, alternating in sign (the largest squares and
 * differences), and the same with one entry one ulp beyond it. */
static void make_extreme_f(size_t n)
{
    for (size_t b = 0; b < n; ++b) {
        f_max[b] = b % 2u ? -MCS_ESTIMATE_MAX_ABS : MCS_ESTIMATE_MAX_ABS;
        f_over[b] = f_max[b];
        power_max[b] = b % 3u ? MCS_EQ_MAX_POWER : -MCS_EQ_MAX_POWER;
    }
    f_over[n - 1u] = nextafter(MCS_ESTIMATE_MAX_ABS, INFINITY);
}

static void expect_finite(mcs_status st, double v, int nonneg)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, st);
    TEST_ASSERT_TRUE(isfinite(v));
    if (nonneg) {
        TEST_ASSERT_TRUE(v >= 0.0);
    }
}

static void expect_magnitude(mcs_status st, double v)
{
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MAGNITUDE, st);
    TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, v);
}

static void test_integrands_up_to_the_bound_give_finite_forms_and_beyond_are_refused(void)
{
    /* f = 1e200 gave eq. 25 = inf with MCS_OK, 1e300 NaN in eq. 52 and 55.
     * Every f-form at the bound, at N up to the covariance size (term by
     * term) and above it (Parseval), with the steepest importance. */
    typedef mcs_status (*imp_f_fn)(const mcs_importance *, size_t, const double *, double *);
    const imp_f_fn imp_forms[5] = {mcs_eq52_variance_printed, mcs_eq52_variance_corrected,
                                   mcs_eq55_variance_convolution, mcs_eq58_bound_printed,
                                   mcs_eq58_bound_corrected};
    const size_t sizes[2] = {MCS_MAX_COV_N, NBIG};
    for (int s = 0; s < 2; ++s) {
        const size_t n = sizes[s];
        make_extreme_f(n);
        steep_importance(n);
        double v = SENTINEL;
        EXPECT(expect_finite, mcs_eq11_unbiased_mean(n, f_max, &v), v, 0);
        EXPECT(expect_finite, mcs_eq24_random_variance(n, 1u, f_max, &v), v, 1);
        EXPECT(expect_finite, mcs_eq25_random_variance(n, 1u, f_max, &v), v, 1);
        EXPECT(expect_finite, mcs_eq14_variance(n, 1u, f_max, power_max, &v), v, 0);
        for (int i = 0; i < 5; ++i)
            EXPECT(expect_finite, imp_forms[i](&imp, 1u, f_max, &v), v, i != 2);
        v = SENTINEL;
        EXPECT(expect_magnitude, mcs_eq11_unbiased_mean(n, f_over, &v), v);
        EXPECT(expect_magnitude, mcs_eq24_random_variance(n, 1u, f_over, &v), v);
        EXPECT(expect_magnitude, mcs_eq25_random_variance(n, 1u, f_over, &v), v);
        EXPECT(expect_magnitude, mcs_eq14_variance(n, 1u, f_over, power_max, &v), v);
        power_max[1] = nextafter(MCS_EQ_MAX_POWER, INFINITY);
        EXPECT(expect_magnitude, mcs_eq14_variance(n, 1u, f_max, power_max, &v), v);
        for (int i = 0; i < 5; ++i)
            EXPECT(expect_magnitude, imp_forms[i](&imp, 1u, f_over, &v), v);
    }
}

static void test_section_1_forms_at_the_bound_are_finite_for_the_heaviest_pattern(void)
{
    /* The exact moments at their largest: K = MCS_MAX_K samples through the
     * steepest importance function. f and g at the bound give finite,
     * non-negative variances; one ulp beyond is refused. */
    const size_t n = MCS_MAX_COV_N;
    steep_importance(n);
    make_extreme_f(n);
    static double g_max[MCS_MAX_COV_N];
    for (size_t b = 0; b < n; ++b)
        g_max[b] = f_max[(b + 1u) % n]; /* f - g = +-2^111 */
    for (int kind = 0; kind < MCS_PATTERN_KIND_COUNT; ++kind) {
        const mcs_importance *im = kind == MCS_PATTERN_HOMOGENIZED ? NULL : &imp;
        const size_t k = (size_t)MCS_MAX_K;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, (mcs_pattern_kind)kind, n, k, im));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(&th, &pat));
        double v = SENTINEL;
        EXPECT(expect_finite, mcs_eq2_uncorrelated_variance(&th, n, k, f_max, g_max, &v), v, 1);
        EXPECT(expect_finite, mcs_eq4_correlated_variance(&th, n, k, f_max, g_max, &v), v, 1);
        EXPECT(expect_finite, mcs_eq13_variance(&th, n, k, f_max, &v), v, 0);
        v = SENTINEL;
        EXPECT(expect_magnitude, mcs_eq2_uncorrelated_variance(&th, n, k, f_max, f_over, &v), v);
        EXPECT(expect_magnitude, mcs_eq4_correlated_variance(&th, n, k, f_over, g_max, &v), v);
        EXPECT(expect_magnitude, mcs_eq13_variance(&th, n, k, f_over, &v), v);
    }
}

static void test_an_importance_function_init_never_made_gives_no_infinite_form(void)
{
    /* fuzz_api: a zeroed importance object whose n a flipped byte made 16
     * gave eq. 55 = NaN with MCS_OK. With every p_n and H zeroed, or one p_n
     * zeroed, each importance form either returns a finite value or an
     * error with its outputs untouched; the f-forms, which read every p_n,
     * return MCS_ERR_INVARIANT. */
    typedef mcs_status (*imp_f_fn)(const mcs_importance *, size_t, const double *, double *);
    const imp_f_fn imp_forms[5] = {mcs_eq52_variance_printed, mcs_eq52_variance_corrected,
                                   mcs_eq55_variance_convolution, mcs_eq58_bound_printed,
                                   mcs_eq58_bound_corrected};
    double f[16];
    theory_make_f(16u, f, 0.2);
    for (int how = 0; how < 2; ++how) {
        theory_lumpy_importance(&imp, 16u);
        if (how == 0) {
            memset(&imp, 0, sizeof imp);
            imp.n = 16u;
        } else {
            imp.p[3] = 0.0;
        }
        for (int i = 0; i < 5; ++i) {
            double v = SENTINEL;
            const mcs_status st = imp_forms[i](&imp, 2u, f, &v);
            TEST_ASSERT_TRUE(how == 0 || i >= 3 || st == MCS_ERR_INVARIANT);
            TEST_ASSERT_TRUE(st == MCS_OK ? isfinite(v) : v == SENTINEL);
        }
        double o[8];
        mcs_status st[8];
        for (int j = 0; j < 8; ++j)
            o[j] = SENTINEL;
        st[0] = mcs_eq41_importance_second(&imp, 3u, 3u, 3u, &o[0]);
        st[1] = mcs_eq43_importance_cross(&imp, 4u, 1u, 2u, &o[1], &o[2]);
        st[2] = mcs_eq45_importance_power(&imp, 3u, 5u, &o[3]);
        st[3] = mcs_eq46_importance_power0(&imp, 3u, &o[4]);
        st[4] = mcs_eq49_importance_stratified_cross(&imp, 4u, 1u, 2u, &o[5], &o[6]);
        st[5] = mcs_eq50_importance_stratified_power(&imp, 4u, 5u, &o[7]);
        const int first[6] = {0, 1, 3, 4, 5, 7}, count[6] = {1, 2, 1, 1, 2, 1};
        for (int c = 0; c < 6; ++c)
            for (int j = first[c]; j < first[c] + count[c]; ++j)
                TEST_ASSERT_TRUE(st[c] == MCS_OK ? isfinite(o[j]) : o[j] == SENTINEL);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, st[0]); /* 1/p_3 */
        TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, st[1]); /* Q */
    }
}

static void test_eq52_of_an_overwritten_importance_function_is_refused_not_negative(void)
{
    /* fuzz_api: an importance object with one p_n overwritten gave eq. 52
     * corrected = -3.8e-4 with MCS_OK. Both eq. 52 forms are sums of squares
     * weighted by p_n: a negative p_n makes them negative beyond rounding,
     * which only an overwritten object gives (MCS_ERR_INVARIANT, nothing
     * written). Eq. 55 may be negative, but not from this object either:
     * every form refuses a p_n init never writes (since zero-probability
     * bins made p_n = 0 legal, each form checks its object, O(N)). At
     * N = 16 (term by term) and N = 96 > MCS_MAX_COV_N (Parseval). */
    static const size_t ns[2] = {16u, 96u};
    double f[96];
    for (size_t i = 0; i < 2u; ++i) {
        theory_make_f(ns[i], f, 0.2);
        theory_lumpy_importance(&imp, ns[i]);
        imp.p[3] = -4.0; /* the term p_3 (f_3 / p_3 - fbar)^2 then outweighs the rest */
        f[3] = 50.0;
        double v = SENTINEL;
        TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_eq52_variance_corrected(&imp, 2u, f, &v));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_eq52_variance_printed(&imp, 2u, f, &v));
        TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, v);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_eq55_variance_convolution(&imp, 2u, f, &v));
        TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, v);
    }
}

/* ---- item 7: variances never negative ------------------------------------------ */

static void test_eq52_of_a_zero_variance_integrand_is_never_negative(void)
{
    /* Flat importance and f = {0.1, 0.1} gave eq. 52 corrected = -3.5e-18:
     * the exact value is 0, and the term-by-term sum rounds around it. For
     * f proportional to p (every lumpy g too) the exact eq. 52 corrected is 0
     * and eq. 52 printed (1/K)(1/N) sum q (f - fbar)^2 is not negative:
     * both read >= 0 and within rounding of their primal forms. */
    static double w[MCS_MAX_COV_N], f[MCS_MAX_COV_N];
    const double scales[4] = {0.1, 1.0 / 3.0, 7.3e-5, 2.9e17};
    for (size_t n = 2; n <= (size_t)MCS_MAX_COV_N; n += (n < 12u ? 1u : 13u))
        for (int lumpy = 0; lumpy < 2; ++lumpy)
            for (int s = 0; s < 4; ++s) {
                for (size_t b = 0; b < n; ++b)
                    w[b] = lumpy ? 1.0 + (double)((b * 7u) % 5u) : 1.0;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, w));
                double fbar = 0.0, primal = 0.0;
                for (size_t b = 0; b < n; ++b)
                    fbar += f[b] = scales[s] * imp.p[b];
                fbar /= (double)n;
                for (size_t b = 0; b < n; ++b)
                    primal += (f[b] - fbar) * (f[b] - fbar) / imp.p[b];
                primal /= (double)n * 3.0;
                double corrected = SENTINEL, printed = SENTINEL;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq52_variance_corrected(&imp, 3u, f, &corrected));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq52_variance_printed(&imp, 3u, f, &printed));
                const double scale = scales[s] * scales[s];
                TEST_ASSERT_TRUE(corrected >= 0.0 && corrected <= 1e-13 * scale);
                TEST_ASSERT_TRUE(printed >= 0.0);
                TEST_ASSERT_TRUE(fabs(printed - primal) <= 1e-13 * scale);
            }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_complex_result_into_one_double_is_refused_and_elsewhere_is_written);
    RUN_TEST(test_integrands_up_to_the_bound_give_finite_forms_and_beyond_are_refused);
    RUN_TEST(test_section_1_forms_at_the_bound_are_finite_for_the_heaviest_pattern);
    RUN_TEST(test_an_importance_function_init_never_made_gives_no_infinite_form);
    RUN_TEST(test_eq52_of_an_overwritten_importance_function_is_refused_not_negative);
    RUN_TEST(test_eq52_of_a_zero_variance_integrand_is_never_negative);
    return UNITY_END();
}
