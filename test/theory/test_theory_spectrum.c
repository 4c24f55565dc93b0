/* Tests for the exact spectra at any N (mcs_theory_spectrum): against
 * brute-force enumeration of every outcome at tiny N and K, against the
 * N x N moments of mcs_theory wherever both exist (every kind, with and
 * without importance, K dividing N or not, K > N), against the generator
 * through the spectrum accumulator at N up to MCS_MAX_N (5 standard errors),
 * never-negative variances and powers, and bad input. The sizes are chosen
 * apart from those of the other tests. */
#include "mcspec.h"
#include "spectra_ref.h"
#include "theory_ref.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define NMAX MCS_MAX_COV_N
#define SENTINEL (-7.25e300)

static const mcs_pattern_kind all_kinds[MCS_PATTERN_KIND_COUNT] = {
    MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED, MCS_PATTERN_HOMOGENIZED, MCS_PATTERN_UNIFORM,
    MCS_PATTERN_JITTER};

static mcs_theory_spectrum ts;
static mcs_theory_spectrum ts_copy;
static mcs_theory th;
static mcs_importance imp;
static double bf_mean[NMAX], bf_second[NMAX * NMAX];
static double power[MCS_MAX_N];

static void spectrum_init(mcs_pattern_kind kind, size_t n, size_t k, const mcs_importance *im)
{
    mcs_pattern pat;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, kind, n, k, im));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_init(&ts, &pat));
}

/* ---- read-outs of given moments, written out from their definitions ------- */

/* <S_k S_l*> = (1/N) sum_{m,n} e^{-2 pi i (k m - l n)/N} <s_m s_n>, angles
 * reduced exactly. */
static void moments_cross(size_t n, const double *second, size_t k, size_t l, double *re,
                          double *im)
{
    double r = 0.0, i = 0.0;
    for (size_t m = 0; m < n; ++m)
        for (size_t b = 0; b < n; ++b) {
            double a = 2.0 * THEORY_PI * (double)((k * m + (n - l) * b) % n) / (double)n;
            r += cos(a) * second[m * n + b];
            i -= sin(a) * second[m * n + b];
        }
    *re = r / (double)n;
    *im = i / (double)n;
}

/* (1/K^2) f^T (<s s^T> - <s><s>^T) g, and the size of its terms. */
static double moments_form(size_t n, size_t k, const double *mean, const double *second,
                           const double *f, const double *g, double *scale)
{
    double sum = 0.0, size = 0.0;
    for (size_t m = 0; m < n; ++m)
        for (size_t b = 0; b < n; ++b) {
            sum += f[m] * g[b] * (second[m * n + b] - mean[m] * mean[b]);
            size += fabs(f[m] * g[b]) * (fabs(second[m * n + b]) + fabs(mean[m] * mean[b]));
        }
    const double kd = (double)k;
    *scale = size / (kd * kd);
    return sum / (kd * kd);
}

static void assert_within(double expected, double actual, double scale, const char *what,
                          const char *label, size_t a, size_t b)
{
    if (!(fabs(expected - actual) <= 1e-12 * scale)) {
        char msg[200];
        snprintf(msg, sizeof msg, "%s %s (%zu, %zu): expected %.17g, got %.17g (scale %.3g)",
                 label, what, a, b, expected, actual, scale);
        TEST_FAIL_MESSAGE(msg);
    }
}

/* Every read-out of ts against the same read-out of the moments mean[n],
 * second[n * n] (K = k), to 1e-12 of the scale of the moments: (1/N)
 * sum |<s_m s_n>| for the spectra (it bounds every |<S_k S_l*>|), the size
 * of the terms of the form for the estimator. */
static void assert_matches_moments(size_t n, size_t k, const double *mean, const double *second,
                                   const char *label)
{
    double scale = 0.0, mscale = 0.0, f[NMAX], g[NMAX], re[NMAX], im[NMAX];
    for (size_t j = 0; j < n * n; ++j)
        scale += fabs(second[j]) / (double)n;
    for (size_t j = 0; j < n; ++j)
        mscale += fabs(mean[j]) / sqrt((double)n);
    theory_ref_dft(n, mean, re, im);
    const size_t step = n <= 9u ? 1u : n / 5u;
    for (size_t a = 0; a < n; ++a) {
        double r, i, p;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_mean(&ts, a, &r, &i));
        assert_within(re[a], r, mscale, "Re <S_k>", label, a, a);
        assert_within(im[a], i, mscale, "Im <S_k>", label, a, a);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_power(&ts, a, &p));
        moments_cross(n, second, a, a, &r, &i);
        assert_within(r, p, scale, "power", label, a, a);
        for (size_t b = a % step; b < n; b += step) {
            double er, ei, cr, ci, vr, vi;
            moments_cross(n, second, a, b, &er, &ei);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_cross(&ts, a, b, &cr, &ci));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_covariance(&ts, a, b, &vr, &vi));
            assert_within(er, cr, scale, "Re cross", label, a, b);
            assert_within(ei, ci, scale, "Im cross", label, a, b);
            /* Cov = cross - <S_a><S_b>* */
            assert_within(er - (re[a] * re[b] + im[a] * im[b]), vr, scale, "Re cov", label, a, b);
            assert_within(ei - (im[a] * re[b] - re[a] * im[b]), vi, scale, "Im cov", label, a, b);
        }
    }
    theory_make_f(n, f, 0.4);
    theory_make_f(n, g, 2.1);
    double v, fs, want = moments_form(n, k, mean, second, f, f, &fs);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&ts, n, k, f, &v));
    assert_within(want, v, fs, "Var[I]", label, n, k);
    want = moments_form(n, k, mean, second, f, g, &fs);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_estimator_covariance(&ts, n, k, f, g, &v));
    assert_within(want, v, fs, "Cov(I_f, I_g)", label, n, k);
    double em = 0.0, es = 0.0;
    for (size_t b = 0; b < n; ++b) {
        em += f[b] * mean[b] / (double)k;
        es += fabs(f[b] * mean[b]) / (double)k;
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_estimator_mean(&ts, n, k, f, &v));
    assert_within(em, v, es, "<I>", label, n, k);
}

/* ---- against enumeration of every outcome ----------------------------------- */

static void check_kinds_by_enumeration(size_t n, size_t k, const mcs_importance *im,
                                       size_t edge_denominator)
{
    const size_t grid = theory_lcm(edge_denominator, k);
    for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
        const mcs_pattern_kind kind = all_kinds[i];
        if ((im != NULL && kind == MCS_PATTERN_HOMOGENIZED) ||
            (kind == MCS_PATTERN_RANDOM && pow((double)grid, (double)k) > 1e6))
            continue;
        char label[96];
        snprintf(label, sizeof label, "%s N=%zu K=%zu%s", mcs_pattern_kind_str(kind), n, k,
                 im != NULL ? " importance" : "");
        spectrum_init(kind, n, k, im);
        theory_brute_force(kind, n, k, im, grid, bf_mean, bf_second);
        assert_matches_moments(n, k, bf_mean, bf_second, label);
    }
}

static void test_exact_spectra_match_enumeration_of_every_outcome_without_importance(void)
{
    static const size_t shapes[][2] = {{5u, 3u}, {7u, 3u}, {3u, 4u}, {2u, 5u},
                                       {8u, 3u}, {1u, 4u}, {9u, 2u}, {5u, 5u}};
    for (size_t s = 0; s < sizeof shapes / sizeof shapes[0]; ++s)
        check_kinds_by_enumeration(shapes[s][0], shapes[s][1], NULL, shapes[s][0]);
}

static void test_exact_spectra_match_enumeration_of_every_outcome_with_importance(void)
{
    /* g = (2, 1, 3, 1, 1)/8: CDF edges at multiples of 1/8, strata of K = 3
     * and K = 5 cut bins anywhere */
    static const double w5[5] = {2.0, 1.0, 3.0, 1.0, 1.0};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 5u, w5));
    for (size_t k = 2; k <= 5; ++k)
        check_kinds_by_enumeration(5u, k, &imp, 8u);
    /* g = (1, 4, 1)/6 with K = 4 (grid 12), and K = 7 > N (grid 42) */
    static const double w3[3] = {1.0, 4.0, 1.0};
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, 3u, w3));
    check_kinds_by_enumeration(3u, 4u, &imp, 6u);
    check_kinds_by_enumeration(3u, 7u, &imp, 6u);
}

/* ---- against the N x N moments -------------------------------------------- */

static void test_both_routes_agree_to_1e_12_for_every_kind_with_and_without_importance(void)
{
    /* K dividing N or not, K > N, N = 1 and N = MCS_MAX_COV_N */
    static const size_t shapes[][2] = {{1u, 1u},  {1u, 6u},   {2u, 9u},     {9u, 3u},
                                       {9u, 4u},  {24u, 8u},  {24u, 100u},  {37u, 2u},
                                       {61u, 7u}, {NMAX, 64u}, {NMAX, 1000u}};
    for (size_t s = 0; s < sizeof shapes / sizeof shapes[0]; ++s) {
        const size_t n = shapes[s][0], k = shapes[s][1];
        theory_lumpy_importance(&imp, n);
        for (int with_imp = 0; with_imp < 2; ++with_imp)
            for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
                const mcs_importance *im = with_imp ? &imp : NULL;
                if (im != NULL && all_kinds[i] == MCS_PATTERN_HOMOGENIZED)
                    continue;
                char label[96];
                snprintf(label, sizeof label, "%s N=%zu K=%zu%s vs mcs_theory",
                         mcs_pattern_kind_str(all_kinds[i]), n, k, with_imp ? " importance" : "");
                theory_init(&th, all_kinds[i], n, k, im);
                spectrum_init(all_kinds[i], n, k, im);
                assert_matches_moments(n, k, th.mean_s, th.second, label);
            }
    }
}

static void test_the_power_spectrum_holds_every_power_and_writes_nothing_past_n(void)
{
    static const size_t sizes[3] = {1u, 77u, MCS_MAX_N};
    static double buf[MCS_MAX_N + 1];
    for (size_t s = 0; s < 3; ++s) {
        const size_t n = sizes[s];
        theory_lumpy_importance(&imp, n);
        spectrum_init(MCS_PATTERN_JITTER, n, 13u, &imp);
        spectra_guard_set(buf, n);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power_spectrum(&ts, n, buf));
        spectra_guard_check(buf, n, "power spectrum");
        for (size_t q = 0; q < n; q += 1u + n / 50u) {
            double p;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_power(&ts, q, &p));
            TEST_ASSERT_EQUAL_DOUBLE(p, buf[q]);
        }
    }
}

/* ---- against the generator at large N --------------------------------------- */

static mcs_spectrum acc;
static size_t trial_bins[64];
static double trial_w[64], dense[MCS_MAX_N], fbig[MCS_MAX_N];

/* z of a measurement against its exact value: |z| <= 5, or, for a value the
 * pattern fixes (standard error at rounding level), agreement to rounding. */
static void assert_z(double measured, double exact, double se, double scale, const char *what,
                     const char *label, size_t freq)
{
    char msg[200];
    if (se > 1e-9 * scale) {
        double z = (measured - exact) / se;
        snprintf(msg, sizeof msg, "%s %s at %zu: measured %.9g, exact %.9g, z = %.2f", label,
                 what, freq, measured, exact, z);
        TEST_ASSERT_TRUE_MESSAGE(fabs(z) <= 5.0, msg);
    } else {
        snprintf(msg, sizeof msg, "%s %s at %zu: measured %.17g, exact %.17g (deterministic)",
                 label, what, freq, measured, exact);
        TEST_ASSERT_TRUE_MESSAGE(fabs(measured - exact) <= 1e-9 * scale, msg);
    }
}

/* Per trial: the spectrum accumulator, I of f, and sum_{k>=1} |S_k|^2 by
 * Parseval (a per-trial scalar, so its standard error is honest). */
static void draw_trials(spectra_stream *st, size_t n, size_t k, unsigned long trials,
                        mcs_welford *est, mcs_welford *parseval)
{
    for (unsigned long t = 0; t < trials; ++t) {
        double e, sum = 0.0, sum2 = 0.0;
        spectra_stream_draw(st, trial_bins, trial_w, NULL);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&acc, k, trial_bins, trial_w));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_bins(n, k, fbig, trial_bins, trial_w, &e));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_dense(n, k, trial_bins, trial_w, dense));
        for (size_t b = 0; b < n; ++b) {
            sum += dense[b];
            sum2 += dense[b] * dense[b];
        }
        mcs_welford_add(est, e);
        mcs_welford_add(parseval, sum2 - sum * sum / (double)n);
    }
}

/* Every stride-th frequency; with stride 1 also the sum over k >= 1. */
static void check_against_generator(mcs_pattern_kind kind, size_t n, size_t k,
                                    const mcs_importance *im, unsigned long trials, size_t stride)
{
    char label[96];
    snprintf(label, sizeof label, "%s N=%zu K=%zu%s", mcs_pattern_kind_str(kind), n, k,
             im != NULL ? " importance" : "");
    spectrum_init(kind, n, k, im);
    for (size_t q = 0; q < n; q += stride)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_power(&ts, q, &power[q]));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&acc, n));
    spectra_stream st;
    spectra_stream_init(&st, kind, n, k, im, 0x5eedu + n, (uint64_t)kind * 2u + (im != NULL));
    mcs_welford est, parseval;
    mcs_welford_init(&est);
    mcs_welford_init(&parseval);
    draw_trials(&st, n, k, trials, &est, &parseval);
    const double scale = power[0] / (double)k; /* (K/N) times the mean weight, roughly */
    double tail = 0.0, m, se, re, im_, mr, mi;
    for (size_t q = 0; q < n; q += stride) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&acc, q, &m));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power_stderr(&acc, q, &se));
        assert_z(m, power[q], se, scale, "power", label, q);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&acc, q, &re, &im_));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean_stderr(&acc, q, &se));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_mean(&ts, q, &mr, &mi));
        assert_z(hypot(re - mr, im_ - mi), 0.0, se, sqrt(power[0]), "|<S_k> - exact|", label, q);
        tail += q > 0u ? power[q] : 0.0;
    }
    double v, vm, vse;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_mean(&parseval, &m));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_stderr(&parseval, &se));
    /* Two samples in one bin, rare at N >> K, make this sum vary; trials
     * that never saw it have no standard error, and their mean misses the
     * rare event's share, so only a sum seen to vary is compared. */
    if (se > 0.0 && stride == 1u)
        assert_z(m, tail, se, tail + scale, "sum_{k>=1} power", label, 0u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&ts, n, k, fbig, &v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_variance(&est, &vm));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_variance_stderr(&est, &vse));
    assert_z(vm, v, vse, 1.0, "Var[I]", label, 0u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_estimator_mean(&ts, n, k, fbig, &v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_mean(&est, &vm));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_stderr(&est, &vse));
    assert_z(vm, v, vse, 1.0, "<I>", label, 0u);
}

static void test_exact_spectra_agree_with_the_generator_within_5_standard_errors_at_large_n(void)
{
    /* A prime N at the top of the range with few samples, and an N that K
     * does not divide with more; every kind, with and without importance. */
    static const size_t shapes[][4] = {{MCS_MAX_N - 3u, 6u, 2500u, 7u}, {1500u, 41u, 1500u, 1u}};
    for (size_t s = 0; s < 2; ++s) {
        const size_t n = shapes[s][0], k = shapes[s][1];
        /* 1/p within [0.6, 5]: a variance carried by rare heavy samples would
         * need far more trials than its standard error suggests */
        for (size_t b = 0; b < n; ++b)
            dense[b] = 0.6 + 0.4 * sin(6.0 * THEORY_PI * (double)b / (double)n) +
                       (10u * b >= 4u * n ? 0.3 : 0.0);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, dense));
        theory_make_f(n, fbig, 0.9);
        for (int with_imp = 0; with_imp < 2; ++with_imp)
            for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i)
                if (!(with_imp && all_kinds[i] == MCS_PATTERN_HOMOGENIZED))
                    check_against_generator(all_kinds[i], n, k, with_imp ? &imp : NULL,
                                            shapes[s][2], shapes[s][3]);
    }
}

/* ---- never negative ------------------------------------------------------- */

static void test_variances_and_powers_are_never_negative_and_exactly_zero_where_nothing_varies(void)
{
    /* jitter with N/K = 5 whole bins per stratum and an f whose every
     * stratum sums alike: I is the same for every beta */
    double f[50];
    for (size_t b = 0; b < 50u; ++b)
        f[b] = 0.5 + 0.3 * sin(2.0 * THEORY_PI * ((double)b + 0.5) / 50.0) + (b >= 15u ? 0.4 : 0.0);
    double v = SENTINEL;
    spectrum_init(MCS_PATTERN_JITTER, 50u, 10u, NULL);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&ts, 50u, 10u, f, &v));
    TEST_ASSERT_TRUE(v >= 0.0 && v <= 1e-30); /* rounding of the jumps only */
    /* the uniform pattern: nothing is random */
    for (size_t n = 1; n <= 300u; n += 37u) {
        theory_lumpy_importance(&imp, n);
        spectrum_init(MCS_PATTERN_UNIFORM, n, 7u, &imp);
        for (size_t q = 0; q < n; ++q) {
            double r, i, cr, ci;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_covariance(&ts, q, (q * 3u) % n, &r, &i));
            TEST_ASSERT_EQUAL_DOUBLE(0.0, r);
            TEST_ASSERT_EQUAL_DOUBLE(0.0, i);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_power(&ts, q, &r));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_mean(&ts, q, &cr, &ci));
            TEST_ASSERT_EQUAL_DOUBLE(cr * cr + ci * ci, r);
        }
    }
    /* every power and variance over a sweep of shapes, kinds and importance */
    for (size_t n = 1; n <= 200u; n += 19u)
        for (size_t k = 1; k <= 3u * n; k += n / 3u + 1u) {
            theory_lumpy_importance(&imp, n);
            theory_make_f(n, fbig, (double)k);
            for (int j = 0; j < 2 * MCS_PATTERN_KIND_COUNT; ++j) {
                const mcs_importance *im = j % 2 ? &imp : NULL;
                if (im != NULL && all_kinds[j / 2] == MCS_PATTERN_HOMOGENIZED)
                    continue;
                spectrum_init(all_kinds[j / 2], n, k, im);
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power_spectrum(&ts, n, power));
                for (size_t q = 0; q < n; ++q)
                    TEST_ASSERT_TRUE(power[q] >= 0.0);
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&ts, n, k, fbig, &v));
                TEST_ASSERT_TRUE(v >= 0.0);
            }
        }
}

static void test_importance_proportional_to_f_has_no_variance_for_any_kind(void)
{
    /* f / p is the same in every bin: every sample adds the same value */
    const size_t n = 333u, k = 12u;
    for (size_t b = 0; b < n; ++b)
        fbig[b] = 1.0 + 0.8 * sin(0.05 * (double)b) + 0.01 * (double)(b % 7u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, fbig));
    double fbar = 0.0;
    for (size_t b = 0; b < n; ++b)
        fbar += fbig[b] / (double)n;
    static const mcs_pattern_kind kinds[3] = {MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED,
                                             MCS_PATTERN_JITTER};
    for (int i = 0; i < 3; ++i) {
        double v = SENTINEL, plain = SENTINEL;
        spectrum_init(kinds[i], n, k, NULL);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&ts, n, k, fbig, &plain));
        spectrum_init(kinds[i], n, k, &imp);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&ts, n, k, fbig, &v));
        TEST_ASSERT_TRUE(v >= 0.0 && v <= 1e-28 * fbar * fbar);
        TEST_ASSERT_TRUE(plain > 1e-6 * fbar * fbar); /* and without importance it has */
    }
}

static void test_the_total_count_never_varies_and_huge_k_costs_nothing(void)
{
    /* With f = p, I = (1/K) sum_n p_n s_n = (1/K) sum_n r_n = 1 in every
     * trial of every kind: mean 1, variance 0. At K = 10^9 and the largest N
     * every read-out is O(N) (the strata and the jitter pieces are counted
     * per bin edge, not per sample, and the uniform counts by bisection). */
    const size_t n = MCS_MAX_N, k = 1000000000u;
    theory_lumpy_importance(&imp, n);
    for (int j = 0; j < 2 * MCS_PATTERN_KIND_COUNT; ++j) {
        const mcs_pattern_kind kind = all_kinds[j / 2];
        const mcs_importance *im = j % 2 ? &imp : NULL;
        if (im != NULL && kind == MCS_PATTERN_HOMOGENIZED)
            continue;
        for (size_t b = 0; b < n; ++b)
            fbig[b] = im != NULL ? imp.p[b] : 1.0;
        spectrum_init(kind, n, k, im); /* uniform too: its counts by bisection, O(N log K) */
        double mean = SENTINEL, var = SENTINEL, p0 = SENTINEL, r, i;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_estimator_mean(&ts, n, ts.k, fbig, &mean));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_variance(&ts, n, ts.k, fbig, &var));
        theory_assert_close(1.0, mean, 1e-12, "<I> of f = p");
        TEST_ASSERT_TRUE(var >= 0.0 && var <= 1e-24);
        /* and the power at k = 0 is at least |<S_0>|^2 */
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_power(&ts, 0u, &p0));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_mean(&ts, 0u, &r, &i));
        TEST_ASSERT_TRUE(p0 >= r * r + i * i);
    }
}

/* ---- bad input ------------------------------------------------------------ */

static void expect_init_fails(mcs_status want, const mcs_pattern *pat)
{
    memcpy(&ts_copy, &ts, sizeof ts);
    TEST_ASSERT_EQUAL_INT(want, mcs_theory_spectrum_init(&ts, pat));
    TEST_ASSERT_EQUAL_MEMORY(&ts_copy, &ts, sizeof ts);
}

static void test_bad_init_returns_an_error_and_changes_nothing(void)
{
    mcs_pattern pat;
    theory_lumpy_importance(&imp, 20u);
    spectrum_init(MCS_PATTERN_RANDOM, 20u, 3u, NULL);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_theory_spectrum_init(NULL, &pat));
    expect_init_fails(MCS_ERR_NULL, NULL);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_JITTER, 20u, 3u, &imp));
    mcs_pattern bad = pat;
    bad.n = 0u;
    expect_init_fails(MCS_ERR_UNINIT, &bad);
    bad = pat;
    bad.k = 0u;
    expect_init_fails(MCS_ERR_UNINIT, &bad);
    bad = pat;
    bad.kind = (mcs_pattern_kind)99;
    expect_init_fails(MCS_ERR_UNINIT, &bad);
    bad = pat;
    bad.n = 21u; /* importance of another N */
    expect_init_fails(MCS_ERR_UNINIT, &bad);
    bad = pat;
    bad.n = (size_t)MCS_MAX_N + 1u;
    bad.importance = NULL;
    expect_init_fails(MCS_ERR_N_RANGE, &bad);
    bad = pat;
    bad.kind = MCS_PATTERN_HOMOGENIZED;
    expect_init_fails(MCS_ERR_KIND, &bad);
}

/* One complex read-out call that must fail: outputs and ts unchanged. */
static void expect_complex_fails(mcs_status want, mcs_status got, const double *re,
                                 const double *im)
{
    TEST_ASSERT_EQUAL_INT(want, got);
    TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, *re);
    TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, *im);
    TEST_ASSERT_EQUAL_MEMORY(&ts_copy, &ts, sizeof ts);
}

static void test_bad_read_outs_return_an_error_and_change_nothing(void)
{
    static mcs_theory_spectrum zero; /* never set up */
    const size_t n = 20u, k = 3u;
    spectrum_init(MCS_PATTERN_STRATIFIED, n, k, NULL);
    memcpy(&ts_copy, &ts, sizeof ts);
    double re = SENTINEL, im = SENTINEL;
    mcs_status (*const pair[])(const mcs_theory_spectrum *, size_t, size_t, double *, double *) =
        {mcs_theory_spectrum_cross, mcs_theory_spectrum_covariance};
    for (int i = 0; i < 2; ++i) {
        expect_complex_fails(MCS_ERR_NULL, pair[i](NULL, 1u, 2u, &re, &im), &re, &im);
        expect_complex_fails(MCS_ERR_NULL, pair[i](&ts, 1u, 2u, NULL, &im), &re, &im);
        expect_complex_fails(MCS_ERR_NULL, pair[i](&ts, 1u, 2u, &re, NULL), &re, &im);
        expect_complex_fails(MCS_ERR_UNINIT, pair[i](&zero, 1u, 2u, &re, &im), &re, &im);
        expect_complex_fails(MCS_ERR_FREQ_RANGE, pair[i](&ts, n, 2u, &re, &im), &re, &im);
        expect_complex_fails(MCS_ERR_FREQ_RANGE, pair[i](&ts, 1u, n, &re, &im), &re, &im);
    }
    expect_complex_fails(MCS_ERR_NULL, mcs_theory_spectrum_mean(&ts, 1u, &re, NULL), &re, &im);
    expect_complex_fails(MCS_ERR_UNINIT, mcs_theory_spectrum_mean(&zero, 1u, &re, &im), &re, &im);
    expect_complex_fails(MCS_ERR_FREQ_RANGE, mcs_theory_spectrum_mean(&ts, n, &re, &im), &re, &im);
    expect_complex_fails(MCS_ERR_NULL, mcs_theory_spectrum_power(&ts, 1u, NULL), &re, &im);
    expect_complex_fails(MCS_ERR_UNINIT, mcs_theory_spectrum_power(&zero, 1u, &re), &re, &im);
    expect_complex_fails(MCS_ERR_FREQ_RANGE, mcs_theory_spectrum_power(&ts, n, &re), &re, &im);
    static double buf[MCS_MAX_N];
    for (size_t q = 0; q <= n; ++q)
        buf[q] = SENTINEL;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_theory_power_spectrum(&ts, n, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_theory_power_spectrum(&zero, n, buf));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_theory_power_spectrum(&ts, n - 1u, buf));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_theory_power_spectrum(&ts, n + 1u, buf));
    for (size_t q = 0; q <= n; ++q)
        TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, buf[q]);
}

/* The integrand read-outs through one argument list. */
typedef mcs_status (*two_fn)(const mcs_theory_spectrum *, size_t, size_t, const double *,
                             const double *, double *);

static mcs_status mean_of(const mcs_theory_spectrum *t, size_t n, size_t k, const double *f,
                          const double *g, double *out)
{
    (void)g;
    return mcs_theory_spectrum_estimator_mean(t, n, k, f, out);
}

static mcs_status variance_of(const mcs_theory_spectrum *t, size_t n, size_t k, const double *f,
                              const double *g, double *out)
{
    (void)g;
    return mcs_theory_spectrum_variance(t, n, k, f, out);
}

static void expect_integrand_fails(mcs_status want, two_fn fn, const mcs_theory_spectrum *t,
                                   size_t n, size_t k, const double *f, const double *g, int out)
{
    double o = SENTINEL;
    TEST_ASSERT_EQUAL_INT(want, fn(t, n, k, f, g, out ? &o : NULL));
    TEST_ASSERT_EQUAL_DOUBLE(SENTINEL, o);
    TEST_ASSERT_EQUAL_MEMORY(&ts_copy, &ts, sizeof ts);
}

static void test_bad_integrands_return_an_error_and_change_nothing(void)
{
    static mcs_theory_spectrum zero;
    const two_fn fns[3] = {mean_of, variance_of, mcs_theory_spectrum_estimator_covariance};
    const size_t n = 20u, k = 3u;
    double f[20], bad[20];
    theory_make_f(n, f, 0.0);
    memcpy(bad, f, sizeof f);
    bad[7] = INFINITY;
    spectrum_init(MCS_PATTERN_HOMOGENIZED, n, k, NULL);
    memcpy(&ts_copy, &ts, sizeof ts);
    for (int i = 0; i < 3; ++i) {
        expect_integrand_fails(MCS_ERR_NULL, fns[i], NULL, n, k, f, f, 1);
        expect_integrand_fails(MCS_ERR_NULL, fns[i], &ts, n, k, NULL, f, 1);
        expect_integrand_fails(MCS_ERR_NULL, fns[i], &ts, n, k, f, f, 0);
        expect_integrand_fails(MCS_ERR_UNINIT, fns[i], &zero, n, k, f, f, 1);
        expect_integrand_fails(MCS_ERR_MISMATCH, fns[i], &ts, n - 1u, k, f, f, 1);
        expect_integrand_fails(MCS_ERR_K_RANGE, fns[i], &ts, n, 0u, f, f, 1);
        expect_integrand_fails(MCS_ERR_MISMATCH, fns[i], &ts, n, k + 1u, f, f, 1);
        expect_integrand_fails(MCS_ERR_NOT_FINITE, fns[i], &ts, n, k, bad, f, 1);
    }
    expect_integrand_fails(MCS_ERR_NULL, fns[2], &ts, n, k, f, NULL, 1);
    expect_integrand_fails(MCS_ERR_NOT_FINITE, fns[2], &ts, n, k, f, bad, 1);
}

static void test_theory_spectrum_struct_size_is_as_documented(void)
{
    printf("sizeof(mcs_theory_spectrum) = %zu bytes at MCS_MAX_N = %d\n",
           sizeof(mcs_theory_spectrum), MCS_MAX_N);
#if MCS_MAX_N == 4096
    if (sizeof(void *) == 8u)
        TEST_ASSERT_EQUAL_UINT(262192u, sizeof(mcs_theory_spectrum));
#endif
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_exact_spectra_match_enumeration_of_every_outcome_without_importance);
    RUN_TEST(test_exact_spectra_match_enumeration_of_every_outcome_with_importance);
    RUN_TEST(test_both_routes_agree_to_1e_12_for_every_kind_with_and_without_importance);
    RUN_TEST(test_the_power_spectrum_holds_every_power_and_writes_nothing_past_n);
    RUN_TEST(test_exact_spectra_agree_with_the_generator_within_5_standard_errors_at_large_n);
    RUN_TEST(test_variances_and_powers_are_never_negative_and_exactly_zero_where_nothing_varies);
    RUN_TEST(test_importance_proportional_to_f_has_no_variance_for_any_kind);
    RUN_TEST(test_the_total_count_never_varies_and_huge_k_costs_nothing);
    RUN_TEST(test_bad_init_returns_an_error_and_changes_nothing);
    RUN_TEST(test_bad_read_outs_return_an_error_and_change_nothing);
    RUN_TEST(test_bad_integrands_return_an_error_and_change_nothing);
    RUN_TEST(test_theory_spectrum_struct_size_is_as_documented);
    return UNITY_END();
}
