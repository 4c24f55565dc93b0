/* Tests for the note's closed forms (eq.h): each against the exact moments
 * where the note is exact, the printed forms shown wrong where they are, the
 * section 1 variances against the generator, and bad input. */
#include "mcspec.h"
#include "theory_ref.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define NMAX MCS_MAX_COV_N
#define KMAX 64
#define SENTINEL (-7.25e300)

static const mcs_pattern_kind all_kinds[MCS_PATTERN_KIND_COUNT] = {
    MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED, MCS_PATTERN_HOMOGENIZED, MCS_PATTERN_UNIFORM,
    MCS_PATTERN_JITTER};

static mcs_importance imp;
static mcs_theory th;
static mcs_theory th2;
static mcs_theory th_copy;
static mcs_welford acc_fg_corr, acc_f_only;

static void init_importance(size_t n, const double *w)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, w));
}

/* Eq. 52 corrected in its primal form, (1/K) [(1/N) sum_n f_n^2 / p_n - fbar^2]:
 * the cross-check on the spectral form mcs_eq52_variance_corrected (equal by
 * Parseval). */
static double eq52_corrected_primal(const mcs_importance *im, size_t k, const double *f)
{
    double mean = 0.0, m2 = 0.0;
    for (size_t b = 0; b < im->n; ++b) {
        mean += f[b];
        m2 += f[b] * f[b] / im->p[b];
    }
    mean /= (double)im->n;
    m2 /= (double)im->n;
    return (m2 - mean * mean) / (double)k;
}

/* ---- section 3 closed forms ----------------------------------------------- */

static void test_random_power_is_k_over_n_exactly_at_every_nonzero_frequency(void)
{
    static const size_t shapes[][2] = {{32u, 4u}, {13u, 5u}, {8u, 20u}, {64u, 3u}};
    for (size_t s = 0; s < 4; ++s) {
        size_t n = shapes[s][0], k = shapes[s][1];
        theory_init(&th, MCS_PATTERN_RANDOM, n, k, NULL);
        double p0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, 0u, &p0));
        theory_assert_close((double)(k * k) / (double)n, p0, 1e-13, "S_0^2 = K^2/N");
        for (size_t q = 1; q < n; ++q) {
            double p, e;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, q, &p));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq23_random_power(n, k, q, &e));
            theory_assert_close(e, p, 1e-13, "eq. 23 exact");
        }
    }
}

static void test_random_variance_is_eq24_and_eq25_exactly(void)
{
    double f[NMAX];
    const size_t n = 24, k = 5;
    theory_make_f(n, f, 0.2);
    theory_init(&th, MCS_PATTERN_RANDOM, n, k, NULL);
    double v, v13, v24, v25, power[NMAX], v14;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, k, f, &v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq24_random_variance(n, k, f, &v24));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq25_random_variance(n, k, f, &v25));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq13_variance(&th, n, k, f, &v13));
    for (size_t q = 0; q < n; ++q)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, q, &power[q]));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq14_variance(n, k, f, power, &v14));
    theory_assert_close(v, v24, 1e-12, "eq. 24");
    theory_assert_close(v, v25, 1e-12, "eq. 25");
    theory_assert_close(v, v13, 1e-12, "eq. 13");
    theory_assert_close(v, v14, 1e-12, "eq. 14 (random is stationary)");
}

static void test_stratified_power_is_eq33_exact_and_the_printed_sinc_form_is_its_limit(void)
{
    double maxdiff = 0.0;
    size_t at = 0;
    static const size_t shapes[][2] = {{32u, 4u}, {12u, 3u}, {64u, 8u}, {8u, 8u}, {6u, 1u}};
    for (size_t s = 0; s < sizeof shapes / sizeof shapes[0]; ++s) {
        size_t n = shapes[s][0], k = shapes[s][1];
        theory_init(&th, MCS_PATTERN_STRATIFIED, n, k, NULL);
        theory_init(&th2, MCS_PATTERN_HOMOGENIZED, n, k, NULL);
        for (size_t q = 1; q < n; ++q) {
            double p, ph, e, lim, d32;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, q, &p));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th2, q, &ph));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq33_stratified_power_exact(n, k, q, &e));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq33_stratified_power_limit(n, k, q, &lim));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq32_stratified_delta(n, k, q, &d32));
            theory_assert_close(e, p, 1e-13, "eq. 33 exact vs stratified");
            theory_assert_close(e, ph, 1e-13, "eq. 33 exact vs homogenized");
            theory_assert_close((double)k / (double)n + d32, p, 1e-13, "eq. 23 + eq. 32");
            if (s == 0 && fabs(e - lim) > maxdiff) {
                maxdiff = fabs(e - lim);
                at = q;
            }
        }
    }
    printf("eq. 33 at N=32, K=4: largest |exact - limit| = %.4f at k = %zu (K/N = 0.125)\n",
           maxdiff, at);
    TEST_ASSERT_TRUE(maxdiff > 1e-4); /* the limit is not the finite-N spectrum ... */
    /* ... but converges to it: at a fixed signed frequency the gap shrinks with N,
     * and the limit form is even in the signed frequency (index N - q is -q). */
    double gap_small = 0.0, gap_large = 0.0;
    for (size_t q = 1; q <= 3u; ++q) {
        double e, lim, lim_neg;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq33_stratified_power_exact(32u, 4u, q, &e));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq33_stratified_power_limit(32u, 4u, q, &lim));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq33_stratified_power_limit(32u, 4u, 32u - q, &lim_neg));
        TEST_ASSERT_EQUAL_DOUBLE(lim, lim_neg);
        gap_small = fmax(gap_small, fabs(e - lim) / e);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq33_stratified_power_exact(4096u, 4u, q, &e));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq33_stratified_power_limit(4096u, 4u, q, &lim));
        gap_large = fmax(gap_large, fabs(e - lim) / e);
    }
    TEST_ASSERT_TRUE(gap_large < 1e-3 * gap_small);
}

static void test_eq31_as_printed_squares_the_bracket_and_eq32_does_not(void)
{
    const size_t n = 32, k = 4;
    theory_init(&th, MCS_PATTERN_STRATIFIED, n, k, NULL);
    double worst = 0.0;
    for (size_t q = 1; q < n; ++q) {
        double p, d31, d32;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, q, &p));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq31_stratified_delta_printed(n, k, q, &d31));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq32_stratified_delta(n, k, q, &d32));
        theory_assert_close(p - (double)k / (double)n, d32, 1e-13, "eq. 32 is the exact Delta_kk");
        worst = fmax(worst, fabs(d31 - d32));
    }
    printf("eq. 31 as printed vs exact Delta_kk at N=32, K=4: largest difference %.4f\n", worst);
    TEST_ASSERT_TRUE(worst > 1e-3);
}

static void test_stratified_cross_spectrum_is_corrected_eq30_and_printed_eq30_misses_the_strata_phase(void)
{
    static const size_t shapes[][2] = {{8u, 4u}, {12u, 3u}, {16u, 4u}, {6u, 6u}};
    int printed_wrong = 0;
    for (size_t s = 0; s < 4; ++s) {
        size_t n = shapes[s][0], k = shapes[s][1];
        theory_init(&th, MCS_PATTERN_STRATIFIED, n, k, NULL);
        for (size_t a = 0; a < n; ++a)
            for (size_t b = 0; b < n; ++b) {
                double cr, ci, er, ei, dr, di, pr, pi;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross(&th, a, b, &cr, &ci));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq30_stratified_cross(n, k, a, b, &er, &ei));
                theory_assert_close(er, cr, 1e-13, "stratified cross re");
                theory_assert_close(ei, ci, 1e-13, "stratified cross im");
                TEST_ASSERT_EQUAL_INT(MCS_OK,
                                      mcs_eq30_stratified_delta_corrected(n, k, a, b, &dr, &di));
                if (a == 0u || b == 0u) {
                    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_eq30_stratified_delta_printed(
                                                              n, k, a, b, &pr, &pi));
                    continue;
                }
                TEST_ASSERT_EQUAL_INT(MCS_OK,
                                      mcs_eq30_stratified_delta_printed(n, k, a, b, &pr, &pi));
                if ((a + n - b) % k == 0u) { /* k = l (mod K): printed is right */
                    theory_assert_close(dr, pr, 1e-13, "eq. 30 printed re");
                    theory_assert_close(di, pi, 1e-13, "eq. 30 printed im");
                } else {
                    theory_assert_close(0.0, dr, 1e-15, "corrected Delta off k = l mod K");
                    if (hypot(pr, pi) > 1e-3)
                        printed_wrong = 1;
                }
            }
    }
    /* N=8, K=4, k=1, l=2: exact 0, printed -0.302 - 0.125 i */
    double pr, pi;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq30_stratified_delta_printed(8u, 4u, 1u, 2u, &pr, &pi));
    printf("eq. 30 printed at N=8, K=4, (k,l)=(1,2): %.4f %+.4fi, exact <S_1 S_2*> = 0\n", pr, pi);
    TEST_ASSERT_TRUE(printed_wrong);
}

static void test_stratified_is_not_stationary_so_eq14_misses_its_variance_but_not_the_homogenized(void)
{
    const size_t n = 32, k = 4;
    double f[NMAX], power[NMAX];
    /* frequencies 1 and 1 + K: Cov(S_1, S_5) != 0 couples them */
    for (size_t b = 0; b < n; ++b)
        f[b] = 2.0 + cos(2.0 * THEORY_PI * (double)b / 32.0 + 0.3) +
               cos(2.0 * THEORY_PI * 5.0 * (double)b / 32.0);
    for (size_t q = 1; q < n; ++q)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq33_stratified_power_exact(n, k, q, &power[q]));
    power[0] = 0.0;
    double v14, vs, vh, v13;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq14_variance(n, k, f, power, &v14));
    theory_init(&th, MCS_PATTERN_STRATIFIED, n, k, NULL);
    theory_init(&th2, MCS_PATTERN_HOMOGENIZED, n, k, NULL);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, k, f, &vs));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th2, n, k, f, &vh));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq13_variance(&th, n, k, f, &v13));
    theory_assert_close(vh, v14, 1e-12, "eq. 14 + eq. 33 = homogenized Var[I]");
    theory_assert_close(vs, v13, 1e-12, "eq. 13 (full double sum) = stratified Var[I]");
    printf("N=32 K=4, f at k = 1 and 5: stratified Var %.6g, eq. 14 with eq. 33 %.6g (homogenized %.6g)\n",
           vs, v14, vh);
    TEST_ASSERT_TRUE(fabs(vs - v14) > 0.05 * v14);
    /* and the homogenized cross spectrum is diagonal */
    for (size_t a = 0; a < n; a += 3)
        for (size_t b = 0; b < n; b += 5)
            if (a != b) {
                double r, i;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross(&th2, a, b, &r, &i));
                theory_assert_close(0.0, hypot(r, i), 1e-13, "homogenized off-diagonal");
            }
}

static void test_uniform_is_biased_at_multiples_of_k_as_eq34_and_jitter_matches_eq35_and_eq37(void)
{
    static const size_t shapes[][2] = {{16u, 4u}, {24u, 6u}, {12u, 3u}, {9u, 3u}};
    for (size_t s = 0; s < 4; ++s) {
        size_t n = shapes[s][0], k = shapes[s][1];
        theory_init(&th, MCS_PATTERN_UNIFORM, n, k, NULL);
        theory_init(&th2, MCS_PATTERN_JITTER, n, k, NULL);
        for (size_t q = 0; q < n; ++q) {
            double ur, ui, jr, ji, er, ei, pu, pj, e37;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_mean(&th, q, &ur, &ui));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_mean(&th2, q, &jr, &ji));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, q, &pu));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th2, q, &pj));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq37_jitter_power(n, k, q, &e37));
            theory_assert_close(e37, pu, 1e-13, "eq. 37 uniform power");
            theory_assert_close(e37, pj, 1e-13, "eq. 37 jitter power");
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq35_jitter_mean(n, k, q, &er, &ei));
            theory_assert_close(er, jr, 1e-13, "eq. 35 re");
            theory_assert_close(ei, ji, 1e-13, "eq. 35 im");
            /* biased: |<S_{mu K}>| = K / sqrt N */
            double mag = hypot(ur, ui);
            theory_assert_close(q % k == 0u ? (double)k / sqrt((double)n) : 0.0, mag, 1e-13, "bias");
            mcs_status st = mcs_eq34_uniform_spectrum(n, k, q, &er, &ei);
            if ((n / k) % 2u == 0u) {
                TEST_ASSERT_EQUAL_INT(MCS_OK, st);
                theory_assert_close(er, ur, 1e-13, "eq. 34 re");
                theory_assert_close(ei, ui, 1e-13, "eq. 34 im");
            } else {
                TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, st);
            }
        }
    }
}

/* ---- section 4 closed forms ------------------------------------------------ */

static void test_random_importance_matches_eq41_eq43_eq44_eq45_eq46_exactly(void)
{
    const size_t n = 12, k = 5;
    theory_lumpy_importance(&imp, n);
    theory_init(&th, MCS_PATTERN_RANDOM, n, k, &imp);
    double q0r, q0i; /* eq. 44: N^{-1/2} Q_0 = 1/H */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_q(&imp, 0u, &q0r, &q0i));
    theory_assert_close(1.0 / imp.harmonic_mean, q0r / sqrt((double)n), 1e-14, "eq. 44");
    for (size_t m = 0; m < n; ++m)
        for (size_t b = 0; b < n; ++b) {
            double e41, v;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq41_importance_second(&imp, k, m, b, &e41));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_bin_second(&th, m, b, &v));
            theory_assert_close(e41, v, 1e-13, "eq. 41");
        }
    for (size_t a = 0; a < n; ++a)
        for (size_t b = 0; b < n; ++b) {
            double cr, ci, er, ei;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross(&th, a, b, &cr, &ci));
            if (a == 0u && b == 0u) {
                TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_eq43_importance_cross(&imp, k, a, b, &er, &ei));
                double e46;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq46_importance_power0(&imp, k, &e46));
                theory_assert_close(e46, cr, 1e-13, "eq. 46");
                continue;
            }
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq43_importance_cross(&imp, k, a, b, &er, &ei));
            theory_assert_close(er, cr, 1e-13, "eq. 43 re");
            theory_assert_close(ei, ci, 1e-13, "eq. 43 im");
            if (a == b) {
                double e45;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq45_importance_power(&imp, k, a, &e45));
                theory_assert_close(e45, cr, 1e-13, "eq. 45");
                TEST_ASSERT_TRUE(e45 > (double)k / (double)n); /* strictly above K/N */
            }
        }
}

static void test_stratified_importance_matches_eq50_eq51_only_for_uniform_g(void)
{
    const size_t n = 16, k = 4;
    double w[NMAX] = {0.0};
    for (size_t b = 0; b < n; ++b)
        w[b] = 1.0;
    init_importance(n, w);
    theory_init(&th, MCS_PATTERN_STRATIFIED, n, k, &imp);
    double p0, e51;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, 0u, &p0));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq46_importance_power0(&imp, k, &e51)); /* eq. 51 */
    theory_assert_close(e51, p0, 1e-13, "eq. 51, uniform g");
    for (size_t q = 1; q < n; ++q) {
        double p, e50, e33, d32;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, q, &p));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq50_importance_stratified_power(&imp, k, q, &e50));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq33_stratified_power_limit(n, k, q, &e33));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq32_stratified_delta(n, k, q, &d32));
        theory_assert_close(e33, e50, 1e-13, "eq. 50 at H = 1 is eq. 33's limit");
        theory_assert_close((double)k / (double)n / imp.harmonic_mean + d32, p, 1e-13,
                     "finite-N eq. 50, uniform g");
    }
    /* Non-uniform g: eq. 51 and the finite-N eq. 50 are both off */
    theory_lumpy_importance(&imp, n);
    theory_init(&th, MCS_PATTERN_STRATIFIED, n, k, &imp);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, 0u, &p0));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq46_importance_power0(&imp, k, &e51));
    double worst = 0.0;
    for (size_t q = 1; q < n; ++q) {
        double p, d32;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, q, &p));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq32_stratified_delta(n, k, q, &d32));
        worst = fmax(worst, fabs(p - ((double)k / (double)n / imp.harmonic_mean + d32)));
    }
    printf("stratified + lumpy g, N=16 K=4: <|S_0|^2> exact %.5f vs eq. 51 %.5f; "
           "largest |finite-N eq. 50 - exact| %.5f\n", p0, e51, worst);
    TEST_ASSERT_TRUE(fabs(p0 - e51) > 1e-3);
    TEST_ASSERT_TRUE(worst > 1e-3);
}

static void test_stratified_importance_obeys_eq49_to_51_whenever_each_stratum_is_n_over_k_whole_bins(void)
{
    /* g non-uniform but every block of N/K = 4 bins has mass 1/K: the strata
     * are whole bins, eq. 48 holds exactly, and with it eq. 49 (with the
     * strata phase of corrected eq. 30), eq. 51 and the finite-N eq. 50. */
    const size_t n = 16, k = 4;
    double w[NMAX] = {0.0};
    for (size_t b = 0; b < n; ++b)
        w[b] = 1.0 + (double)(b % 4u);
    init_importance(n, w);
    theory_init(&th, MCS_PATTERN_STRATIFIED, n, k, &imp);
    double c = (double)k / (double)n / sqrt((double)n);
    for (size_t a = 0; a < n; ++a)
        for (size_t b = 0; b < n; ++b) {
            double cr, ci, qr, qi, dr, di, pr, pi;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross(&th, a, b, &cr, &ci));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_q(&imp, (a + n - b) % n, &qr, &qi));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq30_stratified_delta_corrected(n, k, a, b, &dr, &di));
            double er = c * qr + dr + (a == 0u && b == 0u ? (double)(k * k) / (double)n : 0.0);
            theory_assert_close(er, cr, 1e-13, "eq. 49 corrected re");
            theory_assert_close(c * qi + di, ci, 1e-13, "eq. 49 corrected im");
            if (a != 0u && b != 0u && (a + n - b) % k == 0u) {
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq49_importance_stratified_cross(&imp, k, a, b,
                                                                                   &pr, &pi));
                theory_assert_close(cr, pr, 1e-13, "eq. 49 printed re, k = l mod K");
                theory_assert_close(ci, pi, 1e-13, "eq. 49 printed im, k = l mod K");
            }
        }
    double p0, e51;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, 0u, &p0));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq46_importance_power0(&imp, k, &e51));
    theory_assert_close(e51, p0, 1e-13, "eq. 51, whole-bin strata");
    TEST_ASSERT_TRUE(imp.harmonic_mean < 0.9); /* genuinely non-uniform */
}

static void test_eq52_printed_misses_the_k0_terms_and_the_corrected_forms_are_the_variance(void)
{
    const size_t n = 16, k = 3;
    double f[NMAX];
    theory_lumpy_importance(&imp, n);
    theory_init(&th, MCS_PATTERN_RANDOM, n, k, &imp);
    for (int c = 0; c < 2; ++c) {
        if (c == 0)
            theory_make_f(n, f, 0.4);
        else
            for (size_t b = 0; b < n; ++b)
                f[b] = 2.0; /* constant f: F_{k>0} = 0, yet Var[I] > 0 under importance */
        double v, printed, corr, prim;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, k, f, &v));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq52_variance_printed(&imp, k, f, &printed));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq52_variance_corrected(&imp, k, f, &corr));
        prim = eq52_corrected_primal(&imp, k, f);
        theory_assert_close(v, corr, 1e-12, "eq. 52 corrected");
        theory_assert_close(v, prim, 1e-12, "eq. 52 corrected, primal");
        printf("eq. 52 (%s f): exact Var %.6g, printed %.6g\n", c ? "constant" : "lumpy", v,
               printed);
        TEST_ASSERT_TRUE(fabs(v - printed) > 0.01 * v);
    }
}

static void test_eq55_vanishes_for_f_proportional_to_p_and_equals_its_parseval_form(void)
{
    const size_t n = 12, k = 2;
    double f[NMAX];
    theory_lumpy_importance(&imp, n);
    for (int c = 0; c < 2; ++c) {
        if (c == 0)
            theory_make_f(n, f, 0.8);
        else
            for (size_t b = 0; b < n; ++b)
                f[b] = 3.0 * imp.p[b];
        double e55, fbar = 0.0, m2 = 0.0, mfp = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq55_variance_convolution(&imp, k, f, &e55));
        for (size_t b = 0; b < n; ++b) {
            fbar += f[b] / (double)n;
            m2 += f[b] * f[b] / imp.p[b] / (double)n;
            mfp += f[b] / imp.p[b] / (double)n;
        }
        theory_assert_close((m2 - fbar * mfp) / (double)k, e55, 1e-12, "eq. 55 by Parseval");
        double v;
        theory_init(&th, MCS_PATTERN_RANDOM, n, k, &imp);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, k, f, &v));
        if (c == 1) {
            theory_assert_close(0.0, e55, 1e-12, "eq. 55 at f = c p");
            theory_assert_close(0.0, v, 1e-12, "Var at f = c p");
        } else {
            printf("eq. 55 lumpy f: %.6g vs exact Var %.6g\n", e55, v);
            TEST_ASSERT_TRUE(fabs(e55 - v) > 1e-3 * v);
        }
    }
}

static void test_eq58_printed_is_not_a_bound_and_the_corrected_bound_holds(void)
{
    double f[NMAX], w[NMAX];
    const size_t n = 10, k = 3;
    theory_lumpy_importance(&imp, n);
    for (size_t b = 0; b < n; ++b)
        f[b] = 1.0;
    theory_init(&th, MCS_PATTERN_RANDOM, n, k, &imp);
    double v, printed, corr;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, k, f, &v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq58_bound_printed(&imp, k, f, &printed));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq58_bound_corrected(&imp, k, f, &corr));
    printf("eq. 58, constant f, lumpy p: Var %.6g, printed bound %.3g, corrected bound %.6g\n", v,
           printed, corr);
    TEST_ASSERT_TRUE(printed < v * 0.5);
    TEST_ASSERT_TRUE(corr >= v);
    /* many random f and p: the corrected bound always holds */
    mcs_rng rng;
    mcs_rng_seed(&rng, 58u, 1u);
    for (int t = 0; t < 300; ++t) {
        size_t nn = 2u + (size_t)(t % 15);
        for (size_t b = 0; b < nn; ++b) {
            double u, x;
            mcs_rng_double(&rng, &u);
            mcs_rng_double(&rng, &x);
            w[b] = 0.01 + u * u * 4.0;
            f[b] = (x - 0.3) * 5.0;
        }
        init_importance(nn, w);
        theory_init(&th, MCS_PATTERN_RANDOM, nn, 1u + (size_t)(t % 4), &imp);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, nn, th.k, f, &v));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq58_bound_corrected(&imp, th.k, f, &corr));
        TEST_ASSERT_TRUE(corr >= v * (1.0 - 1e-12) - 1e-15);
    }
}

/* ---- section 1 ------------------------------------------------------------ */

/* (1/K) N^{-3/2} sum_{k >= k0, l >= l0} F_k* F_l Q_{k-l}, the note's double
 * sum from reference transforms of f and 1/p. */
static double fq_reference(const mcs_importance *im, size_t k, const double *f, size_t k0,
                           size_t l0)
{
    static double fr[MCS_MAX_N], fi[MCS_MAX_N], q[MCS_MAX_N], qr[MCS_MAX_N], qi[MCS_MAX_N];
    const size_t n = im->n;
    for (size_t b = 0; b < n; ++b)
        q[b] = 1.0 / im->p[b];
    theory_ref_dft(n, f, fr, fi);
    theory_ref_dft(n, q, qr, qi);
    double sum = 0.0;
    for (size_t a = k0; a < n; ++a)
        for (size_t b = l0; b < n; ++b) {
            const size_t d = (a + n - b) % n;
            const double ar = fr[a] * fr[b] + fi[a] * fi[b], ai = fr[a] * fi[b] - fi[a] * fr[b];
            sum += ar * qr[d] - ai * qi[d];
        }
    return sum / ((double)k * (double)n * sqrt((double)n));
}

static void test_above_the_covariance_size_the_f_forms_are_their_parseval_equals(void)
{
    /* N past MCS_MAX_COV_N: eq. 52 (printed, corrected), 55, 58 and 24 take
     * O(N) forms equal by Parseval to the note's sums, which the reference
     * transforms compute here term by term; eq. 14 keeps its O(N^2) sum. */
    static double f[MCS_MAX_N], power[MCS_MAX_N], fr[MCS_MAX_N], fi[MCS_MAX_N];
    static const size_t sizes[3] = {(size_t)MCS_MAX_COV_N + 1u, 97u, 250u};
    for (size_t s = 0; s < 3; ++s) {
        const size_t n = sizes[s], k = 6u;
        theory_lumpy_importance(&imp, n);
        theory_make_f(n, f, 0.7);
        double v, fbar = 0.0, scale = 0.0;
        for (size_t b = 0; b < n; ++b) {
            fbar += f[b] / (double)n;
            scale += f[b] * f[b] / imp.p[b] / (double)n / (double)k; /* the size of the terms */
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq52_variance_printed(&imp, k, f, &v));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12 * scale, fq_reference(&imp, k, f, 1u, 1u), v);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq55_variance_convolution(&imp, k, f, &v));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12 * scale, fq_reference(&imp, k, f, 1u, 0u), v);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq52_variance_corrected(&imp, k, f, &v));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12 * scale,
                                  fq_reference(&imp, k, f, 0u, 0u) - fbar * fbar / (double)k, v);
        theory_ref_dft(n, f, fr, fi);
        double ac = 0.0, e14 = 0.0;
        for (size_t q = 1; q < n; ++q) {
            power[q] = 1.0 + 0.5 * sin((double)q);
            ac += fr[q] * fr[q] + fi[q] * fi[q];
            e14 += (fr[q] * fr[q] + fi[q] * fi[q]) * power[q] / (double)(k * k);
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq58_bound_printed(&imp, k, f, &v));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12 * scale * imp.harmonic_mean, ac / imp.harmonic_mean / (double)k, v);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq24_random_variance(n, k, f, &v));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12 * ac, ac / (double)(k * n), v);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq14_variance(n, k, f, power, &v));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12 * e14, e14, v);
    }
}

static void test_eq4_is_var_f_plus_var_g_minus_twice_the_covariance_and_eq2_drops_it(void)
{
    const size_t n = 16, k = 4;
    double f[NMAX], g[NMAX];
    theory_make_f(n, f, 0.1);
    for (size_t b = 0; b < n; ++b)
        g[b] = f[(b + 1u) % n]; /* a shifted copy: a "gradient" pair */
    for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
        theory_init(&th, all_kinds[i], n, k, NULL);
        double vf, vg, cfg, e2, e4;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, k, f, &vf));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, k, g, &vg));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_estimator_covariance(&th, n, k, f, g, &cfg));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq2_uncorrelated_variance(&th, n, k, f, g, &e2));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq4_correlated_variance(&th, n, k, f, g, &e4));
        theory_assert_close(vf + vg, e2, 1e-12, "eq. 2");
        theory_assert_close(vf + vg - 2.0 * cfg, e4, 1e-12, "eq. 4 = eq. 6");
    }
}

static void test_correlated_and_uncorrelated_gradient_variance_match_eq4_and_eq2_on_trials(void)
{
    const size_t n = 16, k = 4, trials = 40000;
    double f[NMAX], g[NMAX];
    theory_make_f(n, f, 0.1);
    for (size_t b = 0; b < n; ++b)
        g[b] = f[(b + 1u) % n];
    mcs_pattern pat;
    mcs_pattern_init(&pat, MCS_PATTERN_STRATIFIED, n, k, NULL);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(&th, &pat));
    mcs_rng rng;
    mcs_rng_seed(&rng, 4u, 2u);
    mcs_welford_init(&acc_fg_corr);
    mcs_welford_init(&acc_f_only);
    size_t bins[KMAX];
    double w[KMAX] = {0.0};
    for (size_t t = 0; t < trials; ++t) {
        double a, b;
        mcs_pattern_draw(&pat, &rng, k, bins, w, NULL);
        mcs_estimate_bins(n, k, f, bins, w, &a);
        mcs_estimate_bins(n, k, g, bins, w, &b);
        mcs_welford_add(&acc_fg_corr, a - b); /* one shared trial: eq. 3 */
        mcs_pattern_draw(&pat, &rng, k, bins, w, NULL);
        mcs_estimate_bins(n, k, g, bins, w, &b);
        mcs_welford_add(&acc_f_only, a - b); /* independent trials: eq. 1 */
    }
    double e2, e4, v, se;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq2_uncorrelated_variance(&th, n, k, f, g, &e2));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq4_correlated_variance(&th, n, k, f, g, &e4));
    mcs_welford_variance(&acc_fg_corr, &v);
    mcs_welford_variance_stderr(&acc_fg_corr, &se);
    TEST_ASSERT_TRUE(fabs(v - e4) < 5.0 * se);
    mcs_welford_variance(&acc_f_only, &v);
    mcs_welford_variance_stderr(&acc_f_only, &se);
    TEST_ASSERT_TRUE(fabs(v - e2) < 5.0 * se);
    TEST_ASSERT_TRUE(fabs(e2 - e4) > 10.0 * se); /* the test can tell them apart */
}

/* ---- bad input ------------------------------------------------------------- */

static double o1, o2;

static void reset_out(void)
{
    o1 = SENTINEL;
    o2 = SENTINEL;
}

static void expect_fail(mcs_status want, mcs_status got)
{
    TEST_ASSERT_EQUAL_INT(want, got);
    double s = SENTINEL;
    TEST_ASSERT_EQUAL_MEMORY(&s, &o1, sizeof s);
    TEST_ASSERT_EQUAL_MEMORY(&s, &o2, sizeof s);
    TEST_ASSERT_EQUAL_MEMORY(&th_copy, &th, sizeof th);
    reset_out();
}

static void test_bad_arguments_to_the_section_2_and_random_forms_return_an_error(void)
{
    theory_init(&th, MCS_PATTERN_RANDOM, 4u, 2u, NULL);
    memcpy(&th_copy, &th, sizeof th);
    double f[NMAX], bad_f[NMAX], power[NMAX];
    theory_make_f(NMAX, f, 0.0);
    memcpy(bad_f, f, sizeof f);
    bad_f[2] = INFINITY;
    for (size_t b = 0; b < NMAX; ++b)
        power[b] = 0.1;
    const size_t too_big = (size_t)MCS_MAX_N + 1u;
    reset_out();

    expect_fail(MCS_ERR_NULL, mcs_eq11_unbiased_mean(4u, NULL, &o1));
    expect_fail(MCS_ERR_N_RANGE, mcs_eq11_unbiased_mean(0u, f, &o1));
    expect_fail(MCS_ERR_N_RANGE, mcs_eq11_unbiased_mean(too_big, f, &o1));
    expect_fail(MCS_ERR_NOT_FINITE, mcs_eq11_unbiased_mean(4u, bad_f, &o1));

    expect_fail(MCS_ERR_NULL, mcs_eq14_variance(4u, 2u, f, NULL, &o1));
    expect_fail(MCS_ERR_N_RANGE, mcs_eq14_variance(too_big, 2u, f, power, &o1));
    expect_fail(MCS_ERR_K_RANGE, mcs_eq14_variance(4u, 0u, f, power, &o1));
    expect_fail(MCS_ERR_NOT_FINITE, mcs_eq14_variance(4u, 2u, bad_f, power, &o1));
    expect_fail(MCS_ERR_NOT_FINITE, mcs_eq14_variance(4u, 2u, f, bad_f, &o1));

    expect_fail(MCS_ERR_NULL, mcs_eq23_random_power(4u, 2u, 1u, NULL));
    expect_fail(MCS_ERR_N_RANGE, mcs_eq23_random_power(0u, 2u, 1u, &o1));
    expect_fail(MCS_ERR_K_RANGE, mcs_eq23_random_power(4u, 0u, 1u, &o1));
    expect_fail(MCS_ERR_FREQ_RANGE, mcs_eq23_random_power(4u, 2u, 4u, &o1));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq23_random_power(4u, 2u, 0u, &o1));

    mcs_status (*const fk[])(size_t, size_t, const double *, double *) = {
        mcs_eq24_random_variance, mcs_eq25_random_variance};
    for (size_t i = 0; i < 2; ++i) {
        expect_fail(MCS_ERR_NULL, fk[i](4u, 2u, NULL, &o1));
        expect_fail(MCS_ERR_NULL, fk[i](4u, 2u, f, NULL));
        expect_fail(MCS_ERR_N_RANGE, fk[i](0u, 2u, f, &o1));
        expect_fail(MCS_ERR_K_RANGE, fk[i](4u, 0u, f, &o1));
        expect_fail(MCS_ERR_NOT_FINITE, fk[i](4u, 2u, bad_f, &o1));
    }
    expect_fail(MCS_ERR_N_RANGE, mcs_eq24_random_variance(too_big, 2u, f, &o1));
    expect_fail(MCS_ERR_N_RANGE, mcs_eq25_random_variance(too_big, 2u, f, &o1));
}

static void test_bad_arguments_to_the_stratified_and_jitter_forms_return_an_error(void)
{
    const size_t too_big = (size_t)MCS_MAX_N + 1u;
    theory_init(&th, MCS_PATTERN_RANDOM, 4u, 2u, NULL);
    memcpy(&th_copy, &th, sizeof th);
    reset_out();
    /* pair forms of eq. 30 */
    mcs_status (*const pair[])(size_t, size_t, size_t, size_t, double *, double *) = {
        mcs_eq30_stratified_delta_printed, mcs_eq30_stratified_delta_corrected,
        mcs_eq30_stratified_cross};
    for (size_t i = 0; i < 3; ++i) {
        expect_fail(MCS_ERR_NULL, pair[i](8u, 4u, 1u, 1u, NULL, &o2));
        expect_fail(MCS_ERR_NULL, pair[i](8u, 4u, 1u, 1u, &o1, NULL));
        expect_fail(MCS_ERR_N_RANGE, pair[i](0u, 4u, 1u, 1u, &o1, &o2));
        expect_fail(MCS_ERR_K_RANGE, pair[i](8u, 0u, 1u, 1u, &o1, &o2));
        expect_fail(MCS_ERR_FREQ_RANGE, pair[i](8u, 4u, 8u, 1u, &o1, &o2));
        expect_fail(MCS_ERR_FREQ_RANGE, pair[i](8u, 4u, 1u, 8u, &o1, &o2));
        expect_fail(MCS_ERR_DOMAIN, pair[i](8u, 3u, 1u, 1u, &o1, &o2)); /* K does not divide N */
        expect_fail(MCS_ERR_DOMAIN, pair[i](4u, 8u, 1u, 1u, &o1, &o2)); /* K > N */
    }
    expect_fail(MCS_ERR_DOMAIN, mcs_eq30_stratified_delta_printed(8u, 4u, 0u, 1u, &o1, &o2));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq30_stratified_delta_printed(8u, 4u, 1u, 0u, &o1, &o2));

    /* one-frequency stratified forms: K | N and freq >= 1 */
    mcs_status (*const strat[])(size_t, size_t, size_t, double *) = {
        mcs_eq31_stratified_delta_printed, mcs_eq32_stratified_delta,
        mcs_eq33_stratified_power_exact, mcs_eq33_stratified_power_limit};
    for (size_t i = 0; i < 4; ++i) {
        expect_fail(MCS_ERR_NULL, strat[i](8u, 4u, 1u, NULL));
        expect_fail(MCS_ERR_N_RANGE, strat[i](too_big, 4u, 1u, &o1));
        expect_fail(MCS_ERR_K_RANGE, strat[i](8u, 0u, 1u, &o1));
        expect_fail(MCS_ERR_FREQ_RANGE, strat[i](8u, 4u, 8u, &o1));
        expect_fail(MCS_ERR_DOMAIN, strat[i](8u, 3u, 1u, &o1));
        expect_fail(MCS_ERR_DOMAIN, strat[i](8u, 4u, 0u, &o1));
    }
    /* jitter and uniform forms: K | N, freq 0 allowed */
    expect_fail(MCS_ERR_NULL, mcs_eq37_jitter_power(8u, 4u, 1u, NULL));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq37_jitter_power(8u, 3u, 1u, &o1));
    expect_fail(MCS_ERR_FREQ_RANGE, mcs_eq37_jitter_power(8u, 4u, 9u, &o1));
    expect_fail(MCS_ERR_K_RANGE, mcs_eq37_jitter_power(8u, 0u, 1u, &o1));
    mcs_status (*const cplx[])(size_t, size_t, size_t, double *, double *) = {
        mcs_eq34_uniform_spectrum, mcs_eq35_jitter_mean};
    for (size_t i = 0; i < 2; ++i) {
        expect_fail(MCS_ERR_NULL, cplx[i](8u, 4u, 1u, &o1, NULL));
        expect_fail(MCS_ERR_N_RANGE, cplx[i](0u, 4u, 1u, &o1, &o2));
        expect_fail(MCS_ERR_K_RANGE, cplx[i](8u, 0u, 1u, &o1, &o2));
        expect_fail(MCS_ERR_FREQ_RANGE, cplx[i](8u, 4u, 8u, &o1, &o2));
        expect_fail(MCS_ERR_DOMAIN, cplx[i](8u, 5u, 1u, &o1, &o2));
    }
    expect_fail(MCS_ERR_DOMAIN, mcs_eq34_uniform_spectrum(12u, 4u, 1u, &o1, &o2)); /* N/K odd */
}

static void test_bad_importance_arguments_return_an_error_and_change_nothing(void)
{
    theory_lumpy_importance(&imp, 8u);
    theory_init(&th, MCS_PATTERN_RANDOM, 8u, 2u, &imp);
    memcpy(&th_copy, &th, sizeof th);
    static mcs_importance zero_imp; /* n = 0: never initialised */
    static mcs_importance big_imp;  /* n above MCS_MAX_COV_N: the f forms take it */
    double f[NMAX + 1], bad_f[NMAX + 1];
    theory_make_f(NMAX + 1, f, 0.0);
    memcpy(bad_f, f, sizeof f);
    bad_f[1] = NAN;
    double wb[NMAX + 1];
    for (size_t b = 0; b < NMAX + 1; ++b)
        wb[b] = 1.0 + (double)b;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&big_imp, NMAX + 1, wb));
    reset_out();

    expect_fail(MCS_ERR_NULL, mcs_eq41_importance_second(&imp, 2u, 0u, 0u, NULL));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq41_importance_second(NULL, 2u, 0u, 0u, &o1));
    expect_fail(MCS_ERR_UNINIT, mcs_eq41_importance_second(&zero_imp, 2u, 0u, 0u, &o1));
    expect_fail(MCS_ERR_K_RANGE, mcs_eq41_importance_second(&imp, 0u, 0u, 0u, &o1));
    expect_fail(MCS_ERR_BIN_RANGE, mcs_eq41_importance_second(&imp, 2u, 8u, 0u, &o1));
    expect_fail(MCS_ERR_BIN_RANGE, mcs_eq41_importance_second(&imp, 2u, 0u, 8u, &o1));

    expect_fail(MCS_ERR_NULL, mcs_eq43_importance_cross(&imp, 2u, 1u, 0u, &o1, NULL));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq43_importance_cross(NULL, 2u, 1u, 0u, &o1, &o2));
    expect_fail(MCS_ERR_UNINIT, mcs_eq43_importance_cross(&zero_imp, 2u, 1u, 0u, &o1, &o2));
    expect_fail(MCS_ERR_K_RANGE, mcs_eq43_importance_cross(&imp, 0u, 1u, 0u, &o1, &o2));
    expect_fail(MCS_ERR_FREQ_RANGE, mcs_eq43_importance_cross(&imp, 2u, 1u, 8u, &o1, &o2));
    expect_fail(MCS_ERR_FREQ_RANGE, mcs_eq43_importance_cross(&imp, 2u, 8u, 1u, &o1, &o2));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq43_importance_cross(&imp, 2u, 0u, 0u, &o1, &o2));

    expect_fail(MCS_ERR_NULL, mcs_eq45_importance_power(&imp, 2u, 1u, NULL));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq45_importance_power(NULL, 2u, 1u, &o1));
    expect_fail(MCS_ERR_UNINIT, mcs_eq45_importance_power(&zero_imp, 2u, 1u, &o1));
    expect_fail(MCS_ERR_K_RANGE, mcs_eq45_importance_power(&imp, 0u, 1u, &o1));
    expect_fail(MCS_ERR_FREQ_RANGE, mcs_eq45_importance_power(&imp, 2u, 8u, &o1));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq45_importance_power(&imp, 2u, 0u, &o1));
    expect_fail(MCS_ERR_NULL, mcs_eq46_importance_power0(&imp, 2u, NULL));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq46_importance_power0(NULL, 2u, &o1));
    expect_fail(MCS_ERR_UNINIT, mcs_eq46_importance_power0(&zero_imp, 2u, &o1));
    expect_fail(MCS_ERR_K_RANGE, mcs_eq46_importance_power0(&imp, 0u, &o1));
    expect_fail(MCS_ERR_NULL, mcs_eq50_importance_stratified_power(&imp, 2u, 1u, NULL));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq50_importance_stratified_power(NULL, 2u, 1u, &o1));
    expect_fail(MCS_ERR_UNINIT, mcs_eq50_importance_stratified_power(&zero_imp, 2u, 1u, &o1));
    expect_fail(MCS_ERR_K_RANGE, mcs_eq50_importance_stratified_power(&imp, 0u, 1u, &o1));
    expect_fail(MCS_ERR_FREQ_RANGE, mcs_eq50_importance_stratified_power(&imp, 2u, 8u, &o1));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq50_importance_stratified_power(&imp, 3u, 1u, &o1));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq50_importance_stratified_power(&imp, 2u, 0u, &o1));

    expect_fail(MCS_ERR_NULL, mcs_eq49_importance_stratified_cross(&imp, 2u, 1u, 1u, NULL, &o2));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq49_importance_stratified_cross(NULL, 2u, 1u, 1u, &o1, &o2));
    expect_fail(MCS_ERR_UNINIT,
                mcs_eq49_importance_stratified_cross(&zero_imp, 2u, 1u, 1u, &o1, &o2));
    expect_fail(MCS_ERR_K_RANGE, mcs_eq49_importance_stratified_cross(&imp, 0u, 1u, 1u, &o1, &o2));
    expect_fail(MCS_ERR_FREQ_RANGE,
                mcs_eq49_importance_stratified_cross(&imp, 2u, 8u, 1u, &o1, &o2));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq49_importance_stratified_cross(&imp, 3u, 1u, 1u, &o1, &o2));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq49_importance_stratified_cross(&imp, 2u, 0u, 1u, &o1, &o2));

    mcs_status (*const fimp[])(const mcs_importance *, size_t, const double *, double *) = {
        mcs_eq52_variance_printed, mcs_eq52_variance_corrected, mcs_eq55_variance_convolution,
        mcs_eq58_bound_printed, mcs_eq58_bound_corrected};
    for (size_t i = 0; i < sizeof fimp / sizeof fimp[0]; ++i) {
        expect_fail(MCS_ERR_NULL, fimp[i](&imp, 2u, NULL, &o1));
        expect_fail(MCS_ERR_NULL, fimp[i](&imp, 2u, f, NULL));
        expect_fail(MCS_ERR_DOMAIN, fimp[i](NULL, 2u, f, &o1));
        expect_fail(MCS_ERR_UNINIT, fimp[i](&zero_imp, 2u, f, &o1));
        expect_fail(MCS_ERR_K_RANGE, fimp[i](&imp, 0u, f, &o1));
        expect_fail(MCS_ERR_NOT_FINITE, fimp[i](&imp, 2u, bad_f, &o1));
        TEST_ASSERT_EQUAL_INT(MCS_OK, fimp[i](&big_imp, 2u, f, &o1)); /* any N */
        reset_out();
    }
}

static void test_bad_arguments_to_the_section_1_and_eq13_forms_return_an_error(void)
{
    theory_init(&th, MCS_PATTERN_STRATIFIED, 8u, 3u, NULL);
    theory_check_bad_integrands(&th, mcs_eq13_variance, NULL);
    theory_check_bad_integrands(&th, NULL, mcs_eq2_uncorrelated_variance);
    theory_check_bad_integrands(&th, NULL, mcs_eq4_correlated_variance);
    /* f - g would overflow although f and g are finite: both are beyond
     * MCS_ESTIMATE_MAX_ABS, refused before any difference is formed */
    memcpy(&th_copy, &th, sizeof th);
    reset_out();
    double big[NMAX], negbig[NMAX];
    for (size_t b = 0; b < 8; ++b) {
        big[b] = b % 2u ? 1.7e308 : -1.7e308;
        negbig[b] = -big[b];
    }
    expect_fail(MCS_ERR_MAGNITUDE, mcs_eq4_correlated_variance(&th, 8u, 3u, big, negbig, &o1));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_random_power_is_k_over_n_exactly_at_every_nonzero_frequency);
    RUN_TEST(test_random_variance_is_eq24_and_eq25_exactly);
    RUN_TEST(test_stratified_power_is_eq33_exact_and_the_printed_sinc_form_is_its_limit);
    RUN_TEST(test_eq31_as_printed_squares_the_bracket_and_eq32_does_not);
    RUN_TEST(test_stratified_cross_spectrum_is_corrected_eq30_and_printed_eq30_misses_the_strata_phase);
    RUN_TEST(test_stratified_is_not_stationary_so_eq14_misses_its_variance_but_not_the_homogenized);
    RUN_TEST(test_uniform_is_biased_at_multiples_of_k_as_eq34_and_jitter_matches_eq35_and_eq37);
    RUN_TEST(test_random_importance_matches_eq41_eq43_eq44_eq45_eq46_exactly);
    RUN_TEST(test_stratified_importance_matches_eq50_eq51_only_for_uniform_g);
    RUN_TEST(test_stratified_importance_obeys_eq49_to_51_whenever_each_stratum_is_n_over_k_whole_bins);
    RUN_TEST(test_eq52_printed_misses_the_k0_terms_and_the_corrected_forms_are_the_variance);
    RUN_TEST(test_eq55_vanishes_for_f_proportional_to_p_and_equals_its_parseval_form);
    RUN_TEST(test_eq58_printed_is_not_a_bound_and_the_corrected_bound_holds);
    RUN_TEST(test_above_the_covariance_size_the_f_forms_are_their_parseval_equals);
    RUN_TEST(test_eq4_is_var_f_plus_var_g_minus_twice_the_covariance_and_eq2_drops_it);
    RUN_TEST(test_correlated_and_uncorrelated_gradient_variance_match_eq4_and_eq2_on_trials);
    RUN_TEST(test_bad_arguments_to_the_section_2_and_random_forms_return_an_error);
    RUN_TEST(test_bad_arguments_to_the_stratified_and_jitter_forms_return_an_error);
    RUN_TEST(test_bad_importance_arguments_return_an_error_and_change_nothing);
    RUN_TEST(test_bad_arguments_to_the_section_1_and_eq13_forms_return_an_error);
    return UNITY_END();
}
