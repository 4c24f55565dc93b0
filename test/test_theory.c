/* Tests for the theory module: exact moments against brute-force enumeration
 * of every outcome, against the note's closed forms where those are exact,
 * against the generator on many trials (5 standard errors), and bad input. */
#include "mcspec.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define NMAX MCS_MAX_COV_N
#define KMAX 64
#define SENTINEL (-7.25e300)
#define TEST_PI 3.14159265358979323846

static const mcs_pattern_kind all_kinds[MCS_PATTERN_KIND_COUNT] = {
    MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED, MCS_PATTERN_HOMOGENIZED, MCS_PATTERN_UNIFORM,
    MCS_PATTERN_JITTER};

static mcs_importance imp;
static mcs_theory th;
static mcs_theory th2;
static mcs_theory th_copy;

/* ---- helpers ---------------------------------------------------------------- */

static void assert_close(double expected, double actual, double rel, const char *what)
{
    double tol = rel * fmax(1.0, fabs(expected));
    if (!(fabs(expected - actual) <= tol)) {
        char msg[160];
        snprintf(msg, sizeof msg, "%s: expected %.17g, got %.17g", what, expected, actual);
        TEST_FAIL_MESSAGE(msg);
    }
}

static void init_importance(size_t n, const double *w)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, w));
}

static void init_theory(mcs_theory *t, mcs_pattern_kind kind, size_t n, size_t k,
                        const mcs_importance *im)
{
    mcs_pattern pat;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, kind, n, k, im));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(t, &pat));
}

/* A fixed, lumpy test integrand. */
static void make_f(size_t n, double *f, double phase)
{
    for (size_t b = 0; b < n; ++b)
        f[b] = 1.0 + sin(2.3 * (double)b + phase) + 0.5 * cos(0.7 * (double)(b * b)) +
               (double)b / (double)n;
}

/* Normalised DFT (eq. 7) of x, O(N^2), independent of the library. */
static void ref_dft(size_t n, const double *x, double *re, double *im)
{
    for (size_t k = 0; k < n; ++k) {
        double r = 0.0, i = 0.0;
        for (size_t t = 0; t < n; ++t) {
            double a = 2.0 * TEST_PI * (double)((k * t) % n) / (double)n;
            r += cos(a) * x[t];
            i -= sin(a) * x[t];
        }
        re[k] = r / sqrt((double)n);
        im[k] = i / sqrt((double)n);
    }
}

/* ---- brute force: every outcome, by a route independent of the overlap
 * formula. All interval endpoints in u (bin edges or CDF values, strata) are
 * multiples of 1/grid, so a sample's bin is constant on each grid cell: the
 * cell midpoint is pushed through the library's warp (or floor(u N)), the
 * trial's dense s is formed and weighted by the cell probabilities. --------- */

static double bf_mean[NMAX];
static double bf_second[NMAX * NMAX];

static size_t bf_bin(const mcs_importance *im, size_t n, double u, double *w)
{
    if (im != NULL) {
        size_t b = 0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_warp(im, u, NULL, &b));
        *w = 1.0 / im->p[b];
        return b;
    }
    size_t b = (size_t)(u * (double)n);
    *w = 1.0;
    return b < n ? b : n - 1u;
}

/* Adds one equally likely outcome; brute_force divides by their number at
 * the end (without importance every sum is then an exact integer). */
static void bf_add(size_t n, size_t k, const size_t *bins, const double *w, size_t shift)
{
    double s[NMAX] = {0.0};
    for (size_t j = 0; j < k; ++j)
        s[(bins[j] + shift) % n] += w[j];
    for (size_t m = 0; m < n; ++m) {
        bf_mean[m] += s[m];
        for (size_t b = 0; b < n; ++b)
            bf_second[m * n + b] += s[m] * s[b];
    }
}

static void bf_normalise(size_t n, double outcomes)
{
    for (size_t m = 0; m < n; ++m) {
        bf_mean[m] /= outcomes;
        for (size_t b = 0; b < n; ++b)
            bf_second[m * n + b] /= outcomes;
    }
}

/* Odometer over k digits in [0, base): returns 0 when it wraps. */
static int odometer_next(size_t *digit, size_t k, size_t base)
{
    for (size_t j = 0; j < k; ++j) {
        if (++digit[j] < base)
            return 1;
        digit[j] = 0;
    }
    return 0;
}

static void brute_force(mcs_pattern_kind kind, size_t n, size_t k, const mcs_importance *im,
                        size_t grid)
{
    memset(bf_mean, 0, sizeof bf_mean);
    memset(bf_second, 0, sizeof bf_second);
    size_t bins[KMAX] = {0}, digit[KMAX] = {0};
    double w[KMAX] = {0.0};
    const double gd = (double)grid;
    switch (kind) {
    case MCS_PATTERN_RANDOM:
        do {
            for (size_t j = 0; j < k; ++j)
                bins[j] = bf_bin(im, n, ((double)digit[j] + 0.5) / gd, &w[j]);
            bf_add(n, k, bins, w, 0u);
        } while (odometer_next(digit, k, grid));
        bf_normalise(n, pow(gd, (double)k));
        break;
    case MCS_PATTERN_STRATIFIED:
    case MCS_PATTERN_HOMOGENIZED: {
        TEST_ASSERT_EQUAL_UINT(0u, grid % k);
        size_t cells = grid / k;
        size_t shifts = kind == MCS_PATTERN_HOMOGENIZED ? n : 1u;
        do {
            for (size_t j = 0; j < k; ++j)
                bins[j] = bf_bin(im, n, ((double)(j * cells + digit[j]) + 0.5) / gd, &w[j]);
            for (size_t d = 0; d < shifts; ++d)
                bf_add(n, k, bins, w, d);
        } while (odometer_next(digit, k, cells));
        bf_normalise(n, pow((double)cells, (double)k) * (double)shifts);
        break;
    }
    case MCS_PATTERN_JITTER:
        for (size_t c = 0; c < grid; ++c) {
            double beta = ((double)c + 0.5) / gd;
            for (size_t j = 0; j < k; ++j)
                bins[j] = bf_bin(im, n, ((double)j + beta) / (double)k, &w[j]);
            bf_add(n, k, bins, w, 0u);
        }
        bf_normalise(n, gd);
        break;
    case MCS_PATTERN_UNIFORM: { /* deterministic: the one outcome is the generator's */
        mcs_pattern pat;
        mcs_rng rng;
        mcs_rng_seed(&rng, 9u, 9u);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, kind, n, k, im));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &rng, k, bins, w, NULL));
        bf_add(n, k, bins, w, 0u);
        break;
    }
    }
}

static void assert_theory_equals_brute_force(const mcs_theory *t, const char *label)
{
    char what[128];
    size_t n = t->n;
    for (size_t m = 0; m < n; ++m) {
        double v;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_mean_s(t, m, &v));
        snprintf(what, sizeof what, "%s <s_%zu>", label, m);
        assert_close(bf_mean[m], v, 1e-12, what);
        for (size_t b = 0; b < n; ++b) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_second(t, m, b, &v));
            snprintf(what, sizeof what, "%s <s_%zu s_%zu>", label, m, b);
            assert_close(bf_second[m * n + b], v, 1e-12, what);
        }
    }
}

static size_t gcd(size_t a, size_t b)
{
    while (b != 0u) {
        size_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

static size_t lcm(size_t a, size_t b)
{
    return a / gcd(a, b) * b;
}

/* Enumerates every kind for (n, k) with grid = lcm(denominator of edges, k);
 * random only while grid^k stays small. */
static void check_all_kinds_by_enumeration(size_t n, size_t k, const mcs_importance *im,
                                           size_t edge_denominator)
{
    size_t grid = lcm(edge_denominator, k);
    for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
        mcs_pattern_kind kind = all_kinds[i];
        if (im != NULL && kind == MCS_PATTERN_HOMOGENIZED)
            continue;
        if (kind == MCS_PATTERN_RANDOM && pow((double)grid, (double)k) > 2e6)
            continue;
        char label[96];
        snprintf(label, sizeof label, "%s N=%zu K=%zu%s", mcs_pattern_kind_str(kind), n, k,
                 im != NULL ? " importance" : "");
        init_theory(&th, kind, n, k, im);
        brute_force(kind, n, k, im, grid);
        assert_theory_equals_brute_force(&th, label);
    }
}

/* ---- exact moments against enumeration --------------------------------------- */

static void test_exact_moments_match_enumeration_of_every_outcome_without_importance(void)
{
    static const size_t shapes[][2] = {{4u, 2u}, {4u, 3u}, {6u, 4u}, {5u, 2u}, {3u, 5u},
                                       {1u, 3u}, {6u, 3u}, {2u, 7u}, {7u, 2u}};
    for (size_t s = 0; s < sizeof shapes / sizeof shapes[0]; ++s)
        check_all_kinds_by_enumeration(shapes[s][0], shapes[s][1], NULL, shapes[s][0]);
}

static void test_exact_moments_match_enumeration_of_every_outcome_with_importance(void)
{
    /* g = (1, 3, 2, 2)/8: CDF 0, 1/8, 1/2, 3/4, 1, strata do not line up for K = 3, 4, 5 */
    static const double w4[4] = {1.0, 3.0, 2.0, 2.0};
    init_importance(4u, w4);
    for (size_t k = 1; k <= 5; ++k)
        check_all_kinds_by_enumeration(4u, k, &imp, 8u);
    /* g = (1, 2, 1)/4 */
    static const double w3[3] = {1.0, 2.0, 1.0};
    init_importance(3u, w3);
    for (size_t k = 1; k <= 4; ++k)
        check_all_kinds_by_enumeration(3u, k, &imp, 4u);
    /* g = (3, 1, 1, 1, 2)/8 with K = 6 (denominator 8, grid 24) */
    static const double w5[5] = {3.0, 1.0, 1.0, 1.0, 2.0};
    init_importance(5u, w5);
    check_all_kinds_by_enumeration(5u, 6u, &imp, 8u);
}

static void test_uniform_pattern_without_importance_bins_every_sample_exactly(void)
{
    /* The exact bin of (j + 1/2)/K is floor((2j + 1) N / (2K)); with N/K even
     * every sample sits on a bin edge, so rounding must not move one down
     * (the generator once put u_3 = 7/12 of N = 24, K = 6 in bin 13). The
     * theory, the generator (brute_force draws it) and exact integer binning
     * must all agree. */
    for (size_t n = 1; n <= NMAX; n += (n < 16u ? 1u : 7u))
        for (size_t k = 1; k <= KMAX; ++k) {
            double count[NMAX] = {0.0};
            for (size_t j = 0; j < k; ++j)
                count[((2u * j + 1u) * n) / (2u * k)] += 1.0;
            init_theory(&th, MCS_PATTERN_UNIFORM, n, k, NULL);
            brute_force(MCS_PATTERN_UNIFORM, n, k, NULL, 1u);
            assert_theory_equals_brute_force(&th, "uniform vs generator");
            for (size_t b = 0; b < n; ++b)
                TEST_ASSERT_EQUAL_DOUBLE(count[b], th.mean_s[b]);
        }
}

static void test_large_k_costs_nothing_and_keeps_sum_rules(void)
{
    /* K = 10^9 for random, stratified and jitter: O(N^2) whatever K; the
     * moments obey sum_n <s_n> p_n = K and sum_mn p_m p_n <s_m s_n> = K^2. */
    double w[9];
    for (size_t b = 0; b < 9; ++b)
        w[b] = 1.0 + (double)((b * 5u) % 7u);
    init_importance(9u, w);
    const size_t big = 1000000000u;
    static const mcs_pattern_kind kinds[3] = {MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED,
                                             MCS_PATTERN_JITTER};
    for (int i = 0; i < 3; ++i) {
        init_theory(&th, kinds[i], 9u, big, &imp);
        double s1 = 0.0, s2 = 0.0;
        for (size_t m = 0; m < 9; ++m) {
            s1 += th.mean_s[m] * imp.p[m];
            for (size_t b = 0; b < 9; ++b)
                s2 += th.second[m * 9 + b] * imp.p[m] * imp.p[b];
        }
        assert_close(1e9, s1, 1e-12, "sum r_n");
        assert_close(1e18, s2, 1e-10, "sum r_m r_n");
    }
}

/* ---- linear algebra: spectra and variance --------------------------------- */

static void test_cross_spectrum_is_the_eq16_transform_of_the_primal_moments(void)
{
    double re[NMAX], im[NMAX], f[NMAX];
    init_importance(6u, (const double[]){1.0, 2.0, 5.0, 1.0, 3.0, 1.0});
    init_theory(&th, MCS_PATTERN_JITTER, 6u, 4u, &imp);
    const size_t n = 6;
    /* <S_k> against an independent DFT of <s> */
    ref_dft(n, th.mean_s, re, im);
    for (size_t k = 0; k < n; ++k) {
        double r, i;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_spectrum_mean(&th, k, &r, &i));
        assert_close(re[k], r, 1e-13, "<S_k> re");
        assert_close(im[k], i, 1e-13, "<S_k> im");
    }
    /* <S_k S_l*> = (1/N) sum_mn e^{-i(km - ln)} <s_m s_n> by brute O(N^4) */
    for (size_t k = 0; k < n; ++k)
        for (size_t l = 0; l < n; ++l) {
            double r = 0.0, i = 0.0;
            for (size_t m = 0; m < n; ++m)
                for (size_t b = 0; b < n; ++b) {
                    double a = 2.0 * TEST_PI * ((double)(k * m) - (double)(l * b)) / (double)n;
                    r += cos(a) * th.second[m * n + b];
                    i -= sin(a) * th.second[m * n + b];
                }
            double cr, ci, vr, vi, kr, ki, lr, li, p;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross(&th, k, l, &cr, &ci));
            assert_close(r / (double)n, cr, 1e-13, "cross re");
            assert_close(i / (double)n, ci, 1e-13, "cross im");
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_covariance(&th, k, l, &vr, &vi));
            mcs_theory_spectrum_mean(&th, k, &kr, &ki);
            mcs_theory_spectrum_mean(&th, l, &lr, &li);
            assert_close(cr - (kr * lr + ki * li), vr, 1e-13, "cov re");
            assert_close(ci - (ki * lr - kr * li), vi, 1e-13, "cov im");
            if (k == l) {
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, k, &p));
                assert_close(cr, p, 1e-15, "power");
                assert_close(0.0, ci, 1e-14, "power imaginary part");
            }
        }
    /* Parseval on the moments: sum_k <|S_k|^2> = sum_n <s_n^2> */
    double sp = 0.0, ss = 0.0;
    for (size_t k = 0; k < n; ++k) {
        double p;
        mcs_theory_power(&th, k, &p);
        sp += p;
        ss += th.second[k * n + k];
    }
    assert_close(ss, sp, 1e-13, "Parseval");
    (void)f;
}

static void test_primal_and_spectral_variance_agree_for_every_kind_with_and_without_importance(void)
{
    static const size_t shapes[][2] = {{7u, 3u}, {16u, 4u}, {12u, 5u}, {64u, 8u}, {1u, 2u}};
    double f[NMAX], w[NMAX];
    for (size_t s = 0; s < sizeof shapes / sizeof shapes[0]; ++s) {
        size_t n = shapes[s][0], k = shapes[s][1];
        for (size_t b = 0; b < n; ++b)
            w[b] = 1.0 + (double)((b * 7u) % 5u);
        init_importance(n, w);
        make_f(n, f, 0.3);
        for (int with_imp = 0; with_imp < 2; ++with_imp)
            for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
                if (with_imp && all_kinds[i] == MCS_PATTERN_HOMOGENIZED)
                    continue;
                init_theory(&th, all_kinds[i], n, k, with_imp ? &imp : NULL);
                double vp = SENTINEL, vs = SENTINEL;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, f, &vp));
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance_spectral(&th, n, f, &vs));
                TEST_ASSERT_TRUE(vp >= -1e-12);
                assert_close(vp, vs, 1e-11, "primal vs spectral Var[I]");
            }
    }
}

static void test_every_unbiased_kind_has_mean_k_over_n_and_the_eq11_estimator_mean(void)
{
    double f[NMAX], w[NMAX];
    const size_t n = 10, k = 4;
    for (size_t b = 0; b < n; ++b)
        w[b] = 0.5 + (double)b;
    init_importance(n, w);
    make_f(n, f, 1.1);
    double fbar;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq11_unbiased_mean(n, f, &fbar));
    for (int with_imp = 0; with_imp < 2; ++with_imp)
        for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
            if (all_kinds[i] == MCS_PATTERN_UNIFORM ||
                (with_imp && all_kinds[i] == MCS_PATTERN_HOMOGENIZED))
                continue;
            init_theory(&th, all_kinds[i], n, k, with_imp ? &imp : NULL);
            for (size_t b = 0; b < n; ++b)
                assert_close(0.4, th.mean_s[b], 1e-14, "<s_n> = K/N");
            double mean;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_estimator_mean(&th, n, f, &mean));
            assert_close(fbar, mean, 1e-14, "eq. 9 = eq. 11");
        }
}

/* ---- section 3 closed forms ----------------------------------------------- */

static void test_random_power_is_k_over_n_exactly_at_every_nonzero_frequency(void)
{
    static const size_t shapes[][2] = {{32u, 4u}, {13u, 5u}, {8u, 20u}, {64u, 3u}};
    for (size_t s = 0; s < 4; ++s) {
        size_t n = shapes[s][0], k = shapes[s][1];
        init_theory(&th, MCS_PATTERN_RANDOM, n, k, NULL);
        double p0;
        mcs_theory_power(&th, 0u, &p0);
        assert_close((double)(k * k) / (double)n, p0, 1e-13, "S_0^2 = K^2/N");
        for (size_t q = 1; q < n; ++q) {
            double p, e;
            mcs_theory_power(&th, q, &p);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq23_random_power(n, k, q, &e));
            assert_close(e, p, 1e-13, "eq. 23 exact");
        }
    }
}

static void test_random_variance_is_eq24_and_eq25_exactly(void)
{
    double f[NMAX];
    const size_t n = 24, k = 5;
    make_f(n, f, 0.2);
    init_theory(&th, MCS_PATTERN_RANDOM, n, k, NULL);
    double v, v13, v24, v25, power[NMAX], v14;
    mcs_theory_variance(&th, n, f, &v);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq24_random_variance(n, k, f, &v24));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq25_random_variance(n, k, f, &v25));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq13_variance(&th, n, f, &v13));
    for (size_t q = 0; q < n; ++q)
        mcs_theory_power(&th, q, &power[q]);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq14_variance(n, k, f, power, &v14));
    assert_close(v, v24, 1e-12, "eq. 24");
    assert_close(v, v25, 1e-12, "eq. 25");
    assert_close(v, v13, 1e-12, "eq. 13");
    assert_close(v, v14, 1e-12, "eq. 14 (random is stationary)");
}

static void test_stratified_power_is_eq33_exact_and_the_printed_sinc_form_is_its_limit(void)
{
    double maxdiff = 0.0;
    size_t at = 0;
    static const size_t shapes[][2] = {{32u, 4u}, {12u, 3u}, {64u, 8u}, {8u, 8u}, {6u, 1u}};
    for (size_t s = 0; s < sizeof shapes / sizeof shapes[0]; ++s) {
        size_t n = shapes[s][0], k = shapes[s][1];
        init_theory(&th, MCS_PATTERN_STRATIFIED, n, k, NULL);
        init_theory(&th2, MCS_PATTERN_HOMOGENIZED, n, k, NULL);
        for (size_t q = 1; q < n; ++q) {
            double p, ph, e, lim, d32;
            mcs_theory_power(&th, q, &p);
            mcs_theory_power(&th2, q, &ph);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq33_stratified_power_exact(n, k, q, &e));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq33_stratified_power_limit(n, k, q, &lim));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq32_stratified_delta(n, k, q, &d32));
            assert_close(e, p, 1e-13, "eq. 33 exact vs stratified");
            assert_close(e, ph, 1e-13, "eq. 33 exact vs homogenized");
            assert_close((double)k / (double)n + d32, p, 1e-13, "eq. 23 + eq. 32");
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
        mcs_eq33_stratified_power_exact(32u, 4u, q, &e);
        mcs_eq33_stratified_power_limit(32u, 4u, q, &lim);
        mcs_eq33_stratified_power_limit(32u, 4u, 32u - q, &lim_neg);
        TEST_ASSERT_EQUAL_DOUBLE(lim, lim_neg);
        gap_small = fmax(gap_small, fabs(e - lim) / e);
        mcs_eq33_stratified_power_exact(4096u, 4u, q, &e);
        mcs_eq33_stratified_power_limit(4096u, 4u, q, &lim);
        gap_large = fmax(gap_large, fabs(e - lim) / e);
    }
    TEST_ASSERT_TRUE(gap_large < 1e-3 * gap_small);
}

static void test_eq31_as_printed_squares_the_bracket_and_eq32_does_not(void)
{
    const size_t n = 32, k = 4;
    init_theory(&th, MCS_PATTERN_STRATIFIED, n, k, NULL);
    double worst = 0.0;
    for (size_t q = 1; q < n; ++q) {
        double p, d31, d32;
        mcs_theory_power(&th, q, &p);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq31_stratified_delta_printed(n, k, q, &d31));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq32_stratified_delta(n, k, q, &d32));
        assert_close(p - (double)k / (double)n, d32, 1e-13, "eq. 32 is the exact Delta_kk");
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
        init_theory(&th, MCS_PATTERN_STRATIFIED, n, k, NULL);
        for (size_t a = 0; a < n; ++a)
            for (size_t b = 0; b < n; ++b) {
                double cr, ci, er, ei, dr, di, pr, pi;
                mcs_theory_cross(&th, a, b, &cr, &ci);
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq30_stratified_cross(n, k, a, b, &er, &ei));
                assert_close(er, cr, 1e-13, "stratified cross re");
                assert_close(ei, ci, 1e-13, "stratified cross im");
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
                    assert_close(dr, pr, 1e-13, "eq. 30 printed re");
                    assert_close(di, pi, 1e-13, "eq. 30 printed im");
                } else {
                    assert_close(0.0, dr, 1e-15, "corrected Delta off k = l mod K");
                    if (hypot(pr, pi) > 1e-3)
                        printed_wrong = 1;
                }
            }
    }
    /* N=8, K=4, k=1, l=2: exact 0, printed -0.302 - 0.125 i */
    double pr, pi;
    mcs_eq30_stratified_delta_printed(8u, 4u, 1u, 2u, &pr, &pi);
    printf("eq. 30 printed at N=8, K=4, (k,l)=(1,2): %.4f %+.4fi, exact <S_1 S_2*> = 0\n", pr, pi);
    TEST_ASSERT_TRUE(printed_wrong);
}

static void test_stratified_is_not_stationary_so_eq14_misses_its_variance_but_not_the_homogenized(void)
{
    const size_t n = 32, k = 4;
    double f[NMAX], power[NMAX];
    /* frequencies 1 and 1 + K: Cov(S_1, S_5) != 0 couples them */
    for (size_t b = 0; b < n; ++b)
        f[b] = 2.0 + cos(2.0 * TEST_PI * (double)b / 32.0 + 0.3) +
               cos(2.0 * TEST_PI * 5.0 * (double)b / 32.0);
    for (size_t q = 1; q < n; ++q)
        mcs_eq33_stratified_power_exact(n, k, q, &power[q]);
    power[0] = 0.0;
    double v14, vs, vh, v13;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq14_variance(n, k, f, power, &v14));
    init_theory(&th, MCS_PATTERN_STRATIFIED, n, k, NULL);
    init_theory(&th2, MCS_PATTERN_HOMOGENIZED, n, k, NULL);
    mcs_theory_variance(&th, n, f, &vs);
    mcs_theory_variance(&th2, n, f, &vh);
    mcs_eq13_variance(&th, n, f, &v13);
    assert_close(vh, v14, 1e-12, "eq. 14 + eq. 33 = homogenized Var[I]");
    assert_close(vs, v13, 1e-12, "eq. 13 (full double sum) = stratified Var[I]");
    printf("N=32 K=4, f at k = 1 and 5: stratified Var %.6g, eq. 14 with eq. 33 %.6g (homogenized %.6g)\n",
           vs, v14, vh);
    TEST_ASSERT_TRUE(fabs(vs - v14) > 0.05 * v14);
    /* and the homogenized cross spectrum is diagonal */
    for (size_t a = 0; a < n; a += 3)
        for (size_t b = 0; b < n; b += 5)
            if (a != b) {
                double r, i;
                mcs_theory_cross(&th2, a, b, &r, &i);
                assert_close(0.0, hypot(r, i), 1e-13, "homogenized off-diagonal");
            }
}

static void test_uniform_is_biased_at_multiples_of_k_as_eq34_and_jitter_matches_eq35_and_eq37(void)
{
    static const size_t shapes[][2] = {{16u, 4u}, {24u, 6u}, {12u, 3u}, {9u, 3u}};
    for (size_t s = 0; s < 4; ++s) {
        size_t n = shapes[s][0], k = shapes[s][1];
        init_theory(&th, MCS_PATTERN_UNIFORM, n, k, NULL);
        init_theory(&th2, MCS_PATTERN_JITTER, n, k, NULL);
        for (size_t q = 0; q < n; ++q) {
            double ur, ui, jr, ji, er, ei, pu, pj, e37;
            mcs_theory_spectrum_mean(&th, q, &ur, &ui);
            mcs_theory_spectrum_mean(&th2, q, &jr, &ji);
            mcs_theory_power(&th, q, &pu);
            mcs_theory_power(&th2, q, &pj);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq37_jitter_power(n, k, q, &e37));
            assert_close(e37, pu, 1e-13, "eq. 37 uniform power");
            assert_close(e37, pj, 1e-13, "eq. 37 jitter power");
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq35_jitter_mean(n, k, q, &er, &ei));
            assert_close(er, jr, 1e-13, "eq. 35 re");
            assert_close(ei, ji, 1e-13, "eq. 35 im");
            /* biased: |<S_{mu K}>| = K / sqrt N */
            double mag = hypot(ur, ui);
            assert_close(q % k == 0u ? (double)k / sqrt((double)n) : 0.0, mag, 1e-13, "bias");
            mcs_status st = mcs_eq34_uniform_spectrum(n, k, q, &er, &ei);
            if ((n / k) % 2u == 0u) {
                TEST_ASSERT_EQUAL_INT(MCS_OK, st);
                assert_close(er, ur, 1e-13, "eq. 34 re");
                assert_close(ei, ui, 1e-13, "eq. 34 im");
            } else {
                TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, st);
            }
        }
    }
}

/* ---- section 4 closed forms ------------------------------------------------ */

static void lumpy_importance(size_t n)
{
    double w[NMAX] = {0.0};
    for (size_t b = 0; b < n; ++b)
        w[b] = 0.3 + (double)((b * 7u) % 5u) + 0.1 * (double)b;
    init_importance(n, w);
}

static void test_random_importance_matches_eq41_eq43_eq44_eq45_eq46_exactly(void)
{
    const size_t n = 12, k = 5;
    lumpy_importance(n);
    init_theory(&th, MCS_PATTERN_RANDOM, n, k, &imp);
    double inv_h;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq44_inverse_harmonic_mean(&imp, &inv_h));
    assert_close(1.0 / imp.harmonic_mean, inv_h, 1e-14, "eq. 44");
    double q0r, q0i;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_q(&imp, 0u, &q0r, &q0i));
    assert_close(inv_h, q0r / sqrt((double)n), 1e-14, "N^{-1/2} Q_0 = 1/H");
    for (size_t m = 0; m < n; ++m)
        for (size_t b = 0; b < n; ++b) {
            double e41, v;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq41_importance_second(&imp, k, m, b, &e41));
            mcs_theory_second(&th, m, b, &v);
            assert_close(e41, v, 1e-13, "eq. 41");
        }
    for (size_t a = 0; a < n; ++a)
        for (size_t b = 0; b < n; ++b) {
            double cr, ci, er, ei;
            mcs_theory_cross(&th, a, b, &cr, &ci);
            if (a == 0u && b == 0u) {
                TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_eq43_importance_cross(&imp, k, a, b, &er, &ei));
                double e46;
                TEST_ASSERT_EQUAL_INT(MCS_OK,
                                      mcs_eq46_importance_power0(n, k, imp.harmonic_mean, &e46));
                assert_close(e46, cr, 1e-13, "eq. 46");
                continue;
            }
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq43_importance_cross(&imp, k, a, b, &er, &ei));
            assert_close(er, cr, 1e-13, "eq. 43 re");
            assert_close(ei, ci, 1e-13, "eq. 43 im");
            if (a == b) {
                double e45;
                TEST_ASSERT_EQUAL_INT(MCS_OK,
                                      mcs_eq45_importance_power(n, k, imp.harmonic_mean, a, &e45));
                assert_close(e45, cr, 1e-13, "eq. 45");
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
    init_theory(&th, MCS_PATTERN_STRATIFIED, n, k, &imp);
    double p0, e51;
    mcs_theory_power(&th, 0u, &p0);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq51_importance_stratified_power0(n, k, imp.harmonic_mean, &e51));
    assert_close(e51, p0, 1e-13, "eq. 51, uniform g");
    for (size_t q = 1; q < n; ++q) {
        double p, e50, e33, d32;
        mcs_theory_power(&th, q, &p);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq50_importance_stratified_power(n, k, imp.harmonic_mean, q, &e50));
        mcs_eq33_stratified_power_limit(n, k, q, &e33);
        mcs_eq32_stratified_delta(n, k, q, &d32);
        assert_close(e33, e50, 1e-13, "eq. 50 at H = 1 is eq. 33's limit");
        assert_close((double)k / (double)n / imp.harmonic_mean + d32, p, 1e-13,
                     "finite-N eq. 50, uniform g");
    }
    /* Non-uniform g: eq. 51 and the finite-N eq. 50 are both off */
    lumpy_importance(n);
    init_theory(&th, MCS_PATTERN_STRATIFIED, n, k, &imp);
    mcs_theory_power(&th, 0u, &p0);
    mcs_eq51_importance_stratified_power0(n, k, imp.harmonic_mean, &e51);
    double worst = 0.0;
    for (size_t q = 1; q < n; ++q) {
        double p, d32;
        mcs_theory_power(&th, q, &p);
        mcs_eq32_stratified_delta(n, k, q, &d32);
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
    init_theory(&th, MCS_PATTERN_STRATIFIED, n, k, &imp);
    double c = (double)k / (double)n / sqrt((double)n);
    for (size_t a = 0; a < n; ++a)
        for (size_t b = 0; b < n; ++b) {
            double cr, ci, qr, qi, dr, di, pr, pi;
            mcs_theory_cross(&th, a, b, &cr, &ci);
            mcs_theory_q(&imp, (a + n - b) % n, &qr, &qi);
            mcs_eq30_stratified_delta_corrected(n, k, a, b, &dr, &di);
            double er = c * qr + dr + (a == 0u && b == 0u ? (double)(k * k) / (double)n : 0.0);
            assert_close(er, cr, 1e-13, "eq. 49 corrected re");
            assert_close(c * qi + di, ci, 1e-13, "eq. 49 corrected im");
            if (a != 0u && b != 0u && (a + n - b) % k == 0u) {
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq49_importance_stratified_cross(&imp, k, a, b,
                                                                                   &pr, &pi));
                assert_close(cr, pr, 1e-13, "eq. 49 printed re, k = l mod K");
                assert_close(ci, pi, 1e-13, "eq. 49 printed im, k = l mod K");
            }
        }
    double p0, e51;
    mcs_theory_power(&th, 0u, &p0);
    mcs_eq51_importance_stratified_power0(n, k, imp.harmonic_mean, &e51);
    assert_close(e51, p0, 1e-13, "eq. 51, whole-bin strata");
    TEST_ASSERT_TRUE(imp.harmonic_mean < 0.9); /* genuinely non-uniform */
}

static void test_eq52_printed_misses_the_k0_terms_and_the_corrected_forms_are_the_variance(void)
{
    const size_t n = 16, k = 3;
    double f[NMAX];
    lumpy_importance(n);
    init_theory(&th, MCS_PATTERN_RANDOM, n, k, &imp);
    for (int c = 0; c < 2; ++c) {
        if (c == 0)
            make_f(n, f, 0.4);
        else
            for (size_t b = 0; b < n; ++b)
                f[b] = 2.0; /* constant f: F_{k>0} = 0, yet Var[I] > 0 under importance */
        double v, vs, printed, corr, prim;
        mcs_theory_variance(&th, n, f, &v);
        mcs_theory_variance_spectral(&th, n, f, &vs);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq52_variance_printed(&imp, k, f, &printed));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq52_variance_corrected(&imp, k, f, &corr));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq52_variance_corrected_primal(&imp, k, f, &prim));
        assert_close(v, corr, 1e-12, "eq. 52 corrected");
        assert_close(v, prim, 1e-12, "eq. 52 corrected, primal");
        assert_close(v, vs, 1e-12, "spectral");
        printf("eq. 52 (%s f): exact Var %.6g, printed %.6g\n", c ? "constant" : "lumpy", v,
               printed);
        TEST_ASSERT_TRUE(fabs(v - printed) > 0.01 * v);
    }
}

static void test_eq55_vanishes_for_f_proportional_to_p_and_equals_its_parseval_form(void)
{
    const size_t n = 12, k = 2;
    double f[NMAX];
    lumpy_importance(n);
    for (int c = 0; c < 2; ++c) {
        if (c == 0)
            make_f(n, f, 0.8);
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
        assert_close((m2 - fbar * mfp) / (double)k, e55, 1e-12, "eq. 55 by Parseval");
        double v;
        init_theory(&th, MCS_PATTERN_RANDOM, n, k, &imp);
        mcs_theory_variance(&th, n, f, &v);
        if (c == 1) {
            assert_close(0.0, e55, 1e-12, "eq. 55 at f = c p");
            assert_close(0.0, v, 1e-12, "Var at f = c p");
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
    lumpy_importance(n);
    for (size_t b = 0; b < n; ++b)
        f[b] = 1.0;
    init_theory(&th, MCS_PATTERN_RANDOM, n, k, &imp);
    double v, printed, corr;
    mcs_theory_variance(&th, n, f, &v);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq58_bound_printed(n, k, imp.harmonic_mean, f, &printed));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq58_bound_corrected(n, k, imp.harmonic_mean, f, &corr));
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
        init_theory(&th, MCS_PATTERN_RANDOM, nn, 1u + (size_t)(t % 4), &imp);
        mcs_theory_variance(&th, nn, f, &v);
        mcs_eq58_bound_corrected(nn, th.k, imp.harmonic_mean, f, &corr);
        TEST_ASSERT_TRUE(corr >= v * (1.0 - 1e-12) - 1e-15);
    }
}

/* ---- section 1 ------------------------------------------------------------ */

static void test_eq4_is_var_f_plus_var_g_minus_twice_the_covariance_and_eq2_drops_it(void)
{
    const size_t n = 16, k = 4;
    double f[NMAX], g[NMAX];
    make_f(n, f, 0.1);
    for (size_t b = 0; b < n; ++b)
        g[b] = f[(b + 1u) % n]; /* a shifted copy: a "gradient" pair */
    for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
        init_theory(&th, all_kinds[i], n, k, NULL);
        double vf, vg, cfg, e2, e2fg, e4;
        mcs_theory_variance(&th, n, f, &vf);
        mcs_theory_variance(&th, n, g, &vg);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_estimator_covariance(&th, n, f, g, &cfg));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq2_uncorrelated_variance(vf, vg, &e2));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq2_uncorrelated_variance_fg(&th, n, f, g, &e2fg));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq4_correlated_variance(&th, n, f, g, &e4));
        assert_close(vf + vg, e2, 1e-14, "eq. 2");
        assert_close(vf + vg, e2fg, 1e-12, "eq. 2 from f, g");
        assert_close(vf + vg - 2.0 * cfg, e4, 1e-12, "eq. 4 = eq. 6");
    }
}

/* ---- statistics: theory against the generator ----------------------------- */

typedef struct {
    mcs_pattern_kind kind;
    size_t n, k;
    int importance;
} stat_case;

/* Per-trial Welford on every primal entry and every <S_k S_l*>: the measured
 * mean must sit within 5 standard errors of the exact value (or equal it to
 * rounding where the quantity is deterministic). */
static mcs_welford acc_s[NMAX], acc_ss[NMAX * NMAX], acc_cr[NMAX * NMAX], acc_ci[NMAX * NMAX];
static mcs_welford acc_var, acc_fg_corr, acc_f_only;

static void check_within(const mcs_welford *acc, double exact, const char *what)
{
    double mean, se;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_mean(acc, &mean));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_welford_stderr(acc, &se));
    double tol = se > 1e-12 * fmax(1.0, fabs(exact)) ? 5.0 * se : 1e-9 * fmax(1.0, fabs(exact));
    if (!(fabs(mean - exact) <= tol)) {
        char msg[200];
        snprintf(msg, sizeof msg, "%s: measured %.10g +- %.3g, exact %.10g (%.1f se)", what, mean,
                 se, exact, se > 0.0 ? fabs(mean - exact) / se : (double)INFINITY);
        TEST_FAIL_MESSAGE(msg);
    }
}

static void run_stat_case(const stat_case *c, size_t trials, uint64_t seed)
{
    size_t n = c->n, k = c->k;
    if (c->importance)
        lumpy_importance(n);
    mcs_pattern pat;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, c->kind, n, k, c->importance ? &imp : NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(&th, &pat));
    for (size_t i = 0; i < n; ++i)
        mcs_welford_init(&acc_s[i]);
    for (size_t i = 0; i < n * n; ++i) {
        mcs_welford_init(&acc_ss[i]);
        mcs_welford_init(&acc_cr[i]);
        mcs_welford_init(&acc_ci[i]);
    }
    mcs_welford_init(&acc_var);
    double f[NMAX];
    make_f(n, f, 0.5);
    mcs_rng rng;
    mcs_rng_seed(&rng, seed, 17u);
    size_t bins[KMAX];
    double w[KMAX], s[NMAX], sr[NMAX], si[NMAX];
    for (size_t t = 0; t < trials; ++t) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &rng, k, bins, w, NULL));
        mcs_pattern_dense(n, k, bins, w, s);
        double est;
        mcs_estimate_bins(n, f, k, bins, w, &est);
        mcs_welford_add(&acc_var, est);
        ref_dft(n, s, sr, si);
        for (size_t m = 0; m < n; ++m) {
            mcs_welford_add(&acc_s[m], s[m]);
            for (size_t b = 0; b < n; ++b) {
                mcs_welford_add(&acc_ss[m * n + b], s[m] * s[b]);
                /* S_m S_b* */
                mcs_welford_add(&acc_cr[m * n + b], sr[m] * sr[b] + si[m] * si[b]);
                mcs_welford_add(&acc_ci[m * n + b], si[m] * sr[b] - sr[m] * si[b]);
            }
        }
    }
    char what[128];
    const char *name = mcs_pattern_kind_str(c->kind);
    for (size_t m = 0; m < n; ++m) {
        snprintf(what, sizeof what, "%s%s <s_%zu>", name, c->importance ? "+imp" : "", m);
        check_within(&acc_s[m], th.mean_s[m], what);
        for (size_t b = 0; b < n; ++b) {
            double cr, ci;
            snprintf(what, sizeof what, "%s%s <s_%zu s_%zu>", name, c->importance ? "+imp" : "", m, b);
            check_within(&acc_ss[m * n + b], th.second[m * n + b], what);
            mcs_theory_cross(&th, m, b, &cr, &ci);
            snprintf(what, sizeof what, "%s%s Re<S_%zu S_%zu*>", name, c->importance ? "+imp" : "", m, b);
            check_within(&acc_cr[m * n + b], cr, what);
            snprintf(what, sizeof what, "%s%s Im<S_%zu S_%zu*>", name, c->importance ? "+imp" : "", m, b);
            check_within(&acc_ci[m * n + b], ci, what);
        }
    }
    /* Var[I] measured against the exact value, with the variance's own standard error */
    double var, var_se, exact;
    mcs_welford_variance(&acc_var, &var);
    mcs_welford_variance_stderr(&acc_var, &var_se);
    mcs_theory_variance(&th, n, f, &exact);
    if (var_se > 1e-12) {
        if (!(fabs(var - exact) <= 5.0 * var_se)) {
            char msg[160];
            snprintf(msg, sizeof msg, "%s%s Var[I]: measured %.8g +- %.3g, exact %.8g", name,
                     c->importance ? "+imp" : "", var, var_se, exact);
            TEST_FAIL_MESSAGE(msg);
        }
    } else {
        assert_close(exact, var, 1e-9, "deterministic Var[I]");
    }
}

static void test_exact_moments_and_cross_spectra_agree_with_the_generator_within_5_standard_errors(void)
{
    static const stat_case cases[] = {
        {MCS_PATTERN_RANDOM, 8u, 3u, 0},      {MCS_PATTERN_STRATIFIED, 8u, 4u, 0},
        {MCS_PATTERN_STRATIFIED, 7u, 3u, 0},  {MCS_PATTERN_HOMOGENIZED, 6u, 4u, 0},
        {MCS_PATTERN_UNIFORM, 8u, 3u, 0},     {MCS_PATTERN_JITTER, 7u, 3u, 0},
        {MCS_PATTERN_RANDOM, 8u, 3u, 1},      {MCS_PATTERN_STRATIFIED, 8u, 4u, 1},
        {MCS_PATTERN_STRATIFIED, 6u, 5u, 1},  {MCS_PATTERN_UNIFORM, 7u, 4u, 1},
        {MCS_PATTERN_JITTER, 8u, 3u, 1},      {MCS_PATTERN_JITTER, 5u, 7u, 1}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i)
        run_stat_case(&cases[i], 40000u, 1000u + i);
}

/* The same comparison through the library's own primal accumulator: B
 * independent batches of trials, each read out through mcs_moment (eq. 15,
 * 16), and the spread of the batch values gives the standard error. */
#define MOMENT_BATCHES 64u
static mcs_moment batch;
static mcs_welford bat_s[NMAX], bat_ss[NMAX * NMAX], bat_cr[NMAX * NMAX], bat_ci[NMAX * NMAX],
    bat_cov_r[NMAX * NMAX], bat_cov_i[NMAX * NMAX], bat_pow[NMAX], bat_mr[NMAX], bat_mi[NMAX];

static void run_moment_case(const stat_case *c, size_t trials_per_batch, uint64_t seed)
{
    size_t n = c->n, k = c->k;
    if (c->importance)
        lumpy_importance(n);
    mcs_pattern pat;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, c->kind, n, k, c->importance ? &imp : NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(&th, &pat));
    for (size_t i = 0; i < n; ++i) {
        mcs_welford_init(&bat_s[i]);
        mcs_welford_init(&bat_pow[i]);
        mcs_welford_init(&bat_mr[i]);
        mcs_welford_init(&bat_mi[i]);
    }
    for (size_t i = 0; i < n * n; ++i) {
        mcs_welford_init(&bat_ss[i]);
        mcs_welford_init(&bat_cr[i]);
        mcs_welford_init(&bat_ci[i]);
        mcs_welford_init(&bat_cov_r[i]);
        mcs_welford_init(&bat_cov_i[i]);
    }
    mcs_rng rng;
    mcs_rng_seed(&rng, seed, 29u);
    size_t bins[KMAX];
    double w[KMAX];
    for (size_t bt = 0; bt < MOMENT_BATCHES; ++bt) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&batch, n));
        for (size_t t = 0; t < trials_per_batch; ++t) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &rng, k, bins, w, NULL));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&batch, k, bins, w));
        }
        for (size_t m = 0; m < n; ++m) {
            double v, r, i;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_mean_s(&batch, m, &v));
            mcs_welford_add(&bat_s[m], v);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_power(&batch, m, &v));
            mcs_welford_add(&bat_pow[m], v);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_spectrum_mean(&batch, m, &r, &i));
            mcs_welford_add(&bat_mr[m], r);
            mcs_welford_add(&bat_mi[m], i);
            for (size_t b = 0; b < n; ++b) {
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_second(&batch, m, b, &v));
                mcs_welford_add(&bat_ss[m * n + b], v);
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_cross(&batch, m, b, &r, &i));
                mcs_welford_add(&bat_cr[m * n + b], r);
                mcs_welford_add(&bat_ci[m * n + b], i);
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_covariance(&batch, m, b, &r, &i));
                mcs_welford_add(&bat_cov_r[m * n + b], r);
                mcs_welford_add(&bat_cov_i[m * n + b], i);
            }
        }
    }
    char what[128];
    const char *name = mcs_pattern_kind_str(c->kind);
    const char *tag = c->importance ? "+imp" : "";
    for (size_t m = 0; m < n; ++m) {
        double v, r, i;
        snprintf(what, sizeof what, "moment %s%s <s_%zu>", name, tag, m);
        check_within(&bat_s[m], th.mean_s[m], what);
        mcs_theory_power(&th, m, &v);
        snprintf(what, sizeof what, "moment %s%s <|S_%zu|^2>", name, tag, m);
        check_within(&bat_pow[m], v, what);
        mcs_theory_spectrum_mean(&th, m, &r, &i);
        snprintf(what, sizeof what, "moment %s%s Re<S_%zu>", name, tag, m);
        check_within(&bat_mr[m], r, what);
        snprintf(what, sizeof what, "moment %s%s Im<S_%zu>", name, tag, m);
        check_within(&bat_mi[m], i, what);
        for (size_t b = 0; b < n; ++b) {
            snprintf(what, sizeof what, "moment %s%s <s_%zu s_%zu>", name, tag, m, b);
            check_within(&bat_ss[m * n + b], th.second[m * n + b], what);
            mcs_theory_cross(&th, m, b, &r, &i);
            snprintf(what, sizeof what, "moment %s%s Re<S_%zu S_%zu*>", name, tag, m, b);
            check_within(&bat_cr[m * n + b], r, what);
            snprintf(what, sizeof what, "moment %s%s Im<S_%zu S_%zu*>", name, tag, m, b);
            check_within(&bat_ci[m * n + b], i, what);
            /* A batch's Cov(S_k, S_l) is centred on its own means: biased by
             * a factor (T - 1)/T, which the comparison must include. */
            mcs_theory_covariance(&th, m, b, &r, &i);
            double shrink = ((double)trials_per_batch - 1.0) / (double)trials_per_batch;
            snprintf(what, sizeof what, "moment %s%s Re Cov(S_%zu, S_%zu)", name, tag, m, b);
            check_within(&bat_cov_r[m * n + b], r * shrink, what);
            snprintf(what, sizeof what, "moment %s%s Im Cov(S_%zu, S_%zu)", name, tag, m, b);
            check_within(&bat_cov_i[m * n + b], i * shrink, what);
        }
    }
}

static void test_exact_moments_agree_with_the_moment_accumulator_within_5_standard_errors(void)
{
    static const stat_case cases[] = {
        {MCS_PATTERN_RANDOM, 8u, 3u, 0},      {MCS_PATTERN_STRATIFIED, 8u, 4u, 0},
        {MCS_PATTERN_STRATIFIED, 7u, 3u, 0},  {MCS_PATTERN_HOMOGENIZED, 6u, 4u, 0},
        {MCS_PATTERN_UNIFORM, 8u, 3u, 0},     {MCS_PATTERN_JITTER, 7u, 3u, 0},
        {MCS_PATTERN_RANDOM, 8u, 3u, 1},      {MCS_PATTERN_STRATIFIED, 8u, 4u, 1},
        {MCS_PATTERN_STRATIFIED, 6u, 5u, 1},  {MCS_PATTERN_UNIFORM, 7u, 4u, 1},
        {MCS_PATTERN_JITTER, 8u, 3u, 1},      {MCS_PATTERN_JITTER, 5u, 7u, 1}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i)
        run_moment_case(&cases[i], 500u, 2000u + i);
}

static void test_correlated_and_uncorrelated_gradient_variance_match_eq4_and_eq2_on_trials(void)
{
    const size_t n = 16, k = 4, trials = 40000;
    double f[NMAX], g[NMAX];
    make_f(n, f, 0.1);
    for (size_t b = 0; b < n; ++b)
        g[b] = f[(b + 1u) % n];
    mcs_pattern pat;
    mcs_pattern_init(&pat, MCS_PATTERN_STRATIFIED, n, k, NULL);
    mcs_theory_init(&th, &pat);
    mcs_rng rng;
    mcs_rng_seed(&rng, 4u, 2u);
    mcs_welford_init(&acc_fg_corr);
    mcs_welford_init(&acc_f_only);
    size_t bins[KMAX];
    double w[KMAX] = {0.0};
    for (size_t t = 0; t < trials; ++t) {
        double a, b;
        mcs_pattern_draw(&pat, &rng, k, bins, w, NULL);
        mcs_estimate_bins(n, f, k, bins, w, &a);
        mcs_estimate_bins(n, g, k, bins, w, &b);
        mcs_welford_add(&acc_fg_corr, a - b); /* one shared trial: eq. 3 */
        mcs_pattern_draw(&pat, &rng, k, bins, w, NULL);
        mcs_estimate_bins(n, g, k, bins, w, &b);
        mcs_welford_add(&acc_f_only, a - b); /* independent trials: eq. 1 */
    }
    double e2, e4, v, se;
    mcs_eq2_uncorrelated_variance_fg(&th, n, f, g, &e2);
    mcs_eq4_correlated_variance(&th, n, f, g, &e4);
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

static void test_bad_theory_init_returns_an_error_and_changes_nothing(void)
{
    double w[4] = {1.0, 2.0, 3.0, 4.0};
    init_importance(4u, w);
    init_theory(&th, MCS_PATTERN_JITTER, 4u, 3u, &imp);
    memcpy(&th_copy, &th, sizeof th);
    reset_out();
    mcs_pattern pat;
    mcs_pattern_init(&pat, MCS_PATTERN_RANDOM, 8u, 3u, NULL);
    expect_fail(MCS_ERR_NULL, mcs_theory_init(NULL, &pat));
    expect_fail(MCS_ERR_NULL, mcs_theory_init(&th, NULL));
    mcs_pattern bad = pat;
    bad.n = 0u;
    expect_fail(MCS_ERR_UNINIT, mcs_theory_init(&th, &bad));
    bad = pat;
    bad.k = 0u;
    expect_fail(MCS_ERR_UNINIT, mcs_theory_init(&th, &bad));
    bad = pat;
    bad.kind = (mcs_pattern_kind)77;
    expect_fail(MCS_ERR_UNINIT, mcs_theory_init(&th, &bad));
    bad = pat;
    bad.n = (size_t)MCS_MAX_COV_N + 1u;
    expect_fail(MCS_ERR_N_RANGE, mcs_theory_init(&th, &bad));
    bad = pat;
    bad.kind = MCS_PATTERN_HOMOGENIZED;
    bad.n = 4u;
    bad.importance = &imp;
    expect_fail(MCS_ERR_KIND, mcs_theory_init(&th, &bad));
    bad.kind = MCS_PATTERN_RANDOM;
    bad.n = 5u;
    expect_fail(MCS_ERR_UNINIT, mcs_theory_init(&th, &bad));
}

static void test_bad_read_outs_return_an_error_and_change_nothing(void)
{
    init_theory(&th, MCS_PATTERN_STRATIFIED, 8u, 3u, NULL);
    memcpy(&th_copy, &th, sizeof th);
    static mcs_theory zero; /* never initialised */
    double f[NMAX], g[NMAX];
    make_f(8u, f, 0.0);
    make_f(8u, g, 1.0);
    double bad_f[NMAX];
    memcpy(bad_f, f, sizeof f);
    bad_f[3] = NAN;
    reset_out();

    expect_fail(MCS_ERR_NULL, mcs_theory_mean_s(NULL, 0u, &o1));
    expect_fail(MCS_ERR_NULL, mcs_theory_mean_s(&th, 0u, NULL));
    expect_fail(MCS_ERR_UNINIT, mcs_theory_mean_s(&zero, 0u, &o1));
    expect_fail(MCS_ERR_BIN_RANGE, mcs_theory_mean_s(&th, 8u, &o1));

    expect_fail(MCS_ERR_NULL, mcs_theory_second(&th, 0u, 0u, NULL));
    expect_fail(MCS_ERR_UNINIT, mcs_theory_second(&zero, 0u, 0u, &o1));
    expect_fail(MCS_ERR_BIN_RANGE, mcs_theory_second(&th, 0u, 8u, &o1));
    expect_fail(MCS_ERR_BIN_RANGE, mcs_theory_second(&th, 8u, 0u, &o1));

    expect_fail(MCS_ERR_NULL, mcs_theory_spectrum_mean(&th, 0u, &o1, NULL));
    expect_fail(MCS_ERR_NULL, mcs_theory_spectrum_mean(NULL, 0u, &o1, &o2));
    expect_fail(MCS_ERR_UNINIT, mcs_theory_spectrum_mean(&zero, 0u, &o1, &o2));
    expect_fail(MCS_ERR_FREQ_RANGE, mcs_theory_spectrum_mean(&th, 8u, &o1, &o2));

    expect_fail(MCS_ERR_NULL, mcs_theory_cross(&th, 0u, 0u, NULL, &o2));
    expect_fail(MCS_ERR_UNINIT, mcs_theory_cross(&zero, 0u, 0u, &o1, &o2));
    expect_fail(MCS_ERR_FREQ_RANGE, mcs_theory_cross(&th, 0u, 9u, &o1, &o2));
    expect_fail(MCS_ERR_FREQ_RANGE, mcs_theory_cross(&th, 8u, 0u, &o1, &o2));

    expect_fail(MCS_ERR_NULL, mcs_theory_covariance(&th, 0u, 0u, &o1, NULL));
    expect_fail(MCS_ERR_UNINIT, mcs_theory_covariance(&zero, 0u, 0u, &o1, &o2));
    expect_fail(MCS_ERR_FREQ_RANGE, mcs_theory_covariance(&th, 1u, 8u, &o1, &o2));

    expect_fail(MCS_ERR_NULL, mcs_theory_power(&th, 0u, NULL));
    expect_fail(MCS_ERR_UNINIT, mcs_theory_power(&zero, 0u, &o1));
    expect_fail(MCS_ERR_FREQ_RANGE, mcs_theory_power(&th, 8u, &o1));

    /* functions of one integrand */
    mcs_status (*const one[])(const mcs_theory *, size_t, const double *, double *) = {
        mcs_theory_estimator_mean, mcs_theory_variance, mcs_theory_variance_spectral,
        mcs_eq13_variance};
    for (size_t i = 0; i < sizeof one / sizeof one[0]; ++i) {
        expect_fail(MCS_ERR_NULL, one[i](NULL, 8u, f, &o1));
        expect_fail(MCS_ERR_NULL, one[i](&th, 8u, NULL, &o1));
        expect_fail(MCS_ERR_NULL, one[i](&th, 8u, f, NULL));
        expect_fail(MCS_ERR_UNINIT, one[i](&zero, 8u, f, &o1));
        expect_fail(MCS_ERR_MISMATCH, one[i](&th, 7u, f, &o1));
        expect_fail(MCS_ERR_NOT_FINITE, one[i](&th, 8u, bad_f, &o1));
    }
    /* functions of two integrands */
    mcs_status (*const two[])(const mcs_theory *, size_t, const double *, const double *,
                              double *) = {mcs_theory_estimator_covariance,
                                           mcs_eq2_uncorrelated_variance_fg,
                                           mcs_eq4_correlated_variance};
    for (size_t i = 0; i < sizeof two / sizeof two[0]; ++i) {
        expect_fail(MCS_ERR_NULL, two[i](NULL, 8u, f, g, &o1));
        expect_fail(MCS_ERR_NULL, two[i](&th, 8u, f, NULL, &o1));
        expect_fail(MCS_ERR_NULL, two[i](&th, 8u, NULL, g, &o1));
        expect_fail(MCS_ERR_NULL, two[i](&th, 8u, f, g, NULL));
        expect_fail(MCS_ERR_UNINIT, two[i](&zero, 8u, f, g, &o1));
        expect_fail(MCS_ERR_MISMATCH, two[i](&th, 9u, f, g, &o1));
        expect_fail(MCS_ERR_NOT_FINITE, two[i](&th, 8u, bad_f, g, &o1));
        expect_fail(MCS_ERR_NOT_FINITE, two[i](&th, 8u, f, bad_f, &o1));
    }
    double big[NMAX];
    for (size_t b = 0; b < 8; ++b)
        big[b] = b % 2u ? 1.7e308 : -1.7e308;
    double negbig[NMAX];
    for (size_t b = 0; b < 8; ++b)
        negbig[b] = -big[b];
    expect_fail(MCS_ERR_NOT_FINITE, mcs_eq4_correlated_variance(&th, 8u, big, negbig, &o1));
}

static void test_bad_closed_form_arguments_return_an_error_and_change_nothing(void)
{
    init_theory(&th, MCS_PATTERN_RANDOM, 4u, 2u, NULL);
    memcpy(&th_copy, &th, sizeof th);
    double f[NMAX], bad_f[NMAX], power[NMAX];
    make_f(NMAX, f, 0.0);
    memcpy(bad_f, f, sizeof f);
    bad_f[2] = INFINITY;
    for (size_t b = 0; b < NMAX; ++b)
        power[b] = 0.1;
    const size_t too_big = (size_t)MCS_MAX_N + 1u, cov_big = (size_t)MCS_MAX_COV_N + 1u;
    reset_out();

    expect_fail(MCS_ERR_NULL, mcs_eq2_uncorrelated_variance(1.0, 1.0, NULL));
    expect_fail(MCS_ERR_NOT_FINITE, mcs_eq2_uncorrelated_variance(NAN, 1.0, &o1));
    expect_fail(MCS_ERR_NEGATIVE, mcs_eq2_uncorrelated_variance(1.0, -1.0, &o1));

    expect_fail(MCS_ERR_NULL, mcs_eq11_unbiased_mean(4u, NULL, &o1));
    expect_fail(MCS_ERR_N_RANGE, mcs_eq11_unbiased_mean(0u, f, &o1));
    expect_fail(MCS_ERR_N_RANGE, mcs_eq11_unbiased_mean(too_big, f, &o1));
    expect_fail(MCS_ERR_NOT_FINITE, mcs_eq11_unbiased_mean(4u, bad_f, &o1));

    expect_fail(MCS_ERR_NULL, mcs_eq14_variance(4u, 2u, f, NULL, &o1));
    expect_fail(MCS_ERR_N_RANGE, mcs_eq14_variance(cov_big, 2u, f, power, &o1));
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
    expect_fail(MCS_ERR_N_RANGE, mcs_eq24_random_variance(cov_big, 2u, f, &o1));
    expect_fail(MCS_ERR_N_RANGE, mcs_eq25_random_variance(too_big, 2u, f, &o1));

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

    /* H forms */
    expect_fail(MCS_ERR_NULL, mcs_eq45_importance_power(8u, 2u, 0.5, 1u, NULL));
    expect_fail(MCS_ERR_N_RANGE, mcs_eq45_importance_power(0u, 2u, 0.5, 1u, &o1));
    expect_fail(MCS_ERR_K_RANGE, mcs_eq45_importance_power(8u, 0u, 0.5, 1u, &o1));
    expect_fail(MCS_ERR_FREQ_RANGE, mcs_eq45_importance_power(8u, 2u, 0.5, 8u, &o1));
    expect_fail(MCS_ERR_NOT_FINITE, mcs_eq45_importance_power(8u, 2u, NAN, 1u, &o1));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq45_importance_power(8u, 2u, 0.0, 1u, &o1));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq45_importance_power(8u, 2u, 1.5, 1u, &o1));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq45_importance_power(8u, 2u, 0.5, 0u, &o1));
    expect_fail(MCS_ERR_NULL, mcs_eq46_importance_power0(8u, 2u, 0.5, NULL));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq46_importance_power0(8u, 2u, -0.5, &o1));
    expect_fail(MCS_ERR_K_RANGE, mcs_eq46_importance_power0(8u, 0u, 0.5, &o1));
    expect_fail(MCS_ERR_NULL, mcs_eq50_importance_stratified_power(8u, 2u, 0.5, 1u, NULL));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq50_importance_stratified_power(8u, 3u, 0.5, 1u, &o1));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq50_importance_stratified_power(8u, 2u, 0.5, 0u, &o1));
    expect_fail(MCS_ERR_NOT_FINITE, mcs_eq50_importance_stratified_power(8u, 2u, INFINITY, 1u, &o1));
    expect_fail(MCS_ERR_NULL, mcs_eq51_importance_stratified_power0(8u, 2u, 0.5, NULL));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq51_importance_stratified_power0(8u, 3u, 0.5, &o1));
    expect_fail(MCS_ERR_N_RANGE, mcs_eq51_importance_stratified_power0(too_big, 2u, 0.5, &o1));

    mcs_status (*const bound[])(size_t, size_t, double, const double *, double *) = {
        mcs_eq58_bound_printed, mcs_eq58_bound_corrected};
    for (size_t i = 0; i < 2; ++i) {
        expect_fail(MCS_ERR_NULL, bound[i](4u, 2u, 0.5, NULL, &o1));
        expect_fail(MCS_ERR_NULL, bound[i](4u, 2u, 0.5, f, NULL));
        expect_fail(MCS_ERR_N_RANGE, bound[i](0u, 2u, 0.5, f, &o1));
        expect_fail(MCS_ERR_K_RANGE, bound[i](4u, 0u, 0.5, f, &o1));
        expect_fail(MCS_ERR_DOMAIN, bound[i](4u, 2u, 2.0, f, &o1));
        expect_fail(MCS_ERR_NOT_FINITE, bound[i](4u, 2u, NAN, f, &o1));
        expect_fail(MCS_ERR_NOT_FINITE, bound[i](4u, 2u, 0.5, bad_f, &o1));
    }
    expect_fail(MCS_ERR_N_RANGE, mcs_eq58_bound_printed(cov_big, 2u, 0.5, f, &o1));
}

static void test_bad_importance_arguments_return_an_error_and_change_nothing(void)
{
    lumpy_importance(8u);
    init_theory(&th, MCS_PATTERN_RANDOM, 8u, 2u, &imp);
    memcpy(&th_copy, &th, sizeof th);
    static mcs_importance zero_imp; /* n = 0: never initialised */
    static mcs_importance big_imp;  /* n above MCS_MAX_COV_N for the f forms */
    double f[NMAX + 1], bad_f[NMAX + 1];
    make_f(NMAX + 1, f, 0.0);
    memcpy(bad_f, f, sizeof f);
    bad_f[1] = NAN;
    double wb[NMAX + 1];
    for (size_t b = 0; b < NMAX + 1; ++b)
        wb[b] = 1.0 + (double)b;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&big_imp, NMAX + 1, wb));
    reset_out();

    expect_fail(MCS_ERR_NULL, mcs_theory_q(&imp, 0u, NULL, &o2));
    expect_fail(MCS_ERR_DOMAIN, mcs_theory_q(NULL, 0u, &o1, &o2));
    expect_fail(MCS_ERR_UNINIT, mcs_theory_q(&zero_imp, 0u, &o1, &o2));
    expect_fail(MCS_ERR_FREQ_RANGE, mcs_theory_q(&imp, 8u, &o1, &o2));

    expect_fail(MCS_ERR_NULL, mcs_eq41_importance_second(&imp, 2u, 0u, 0u, NULL));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq41_importance_second(NULL, 2u, 0u, 0u, &o1));
    expect_fail(MCS_ERR_UNINIT, mcs_eq41_importance_second(&zero_imp, 2u, 0u, 0u, &o1));
    expect_fail(MCS_ERR_K_RANGE, mcs_eq41_importance_second(&imp, 0u, 0u, 0u, &o1));
    expect_fail(MCS_ERR_BIN_RANGE, mcs_eq41_importance_second(&imp, 2u, 8u, 0u, &o1));

    expect_fail(MCS_ERR_NULL, mcs_eq43_importance_cross(&imp, 2u, 1u, 0u, &o1, NULL));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq43_importance_cross(NULL, 2u, 1u, 0u, &o1, &o2));
    expect_fail(MCS_ERR_UNINIT, mcs_eq43_importance_cross(&zero_imp, 2u, 1u, 0u, &o1, &o2));
    expect_fail(MCS_ERR_K_RANGE, mcs_eq43_importance_cross(&imp, 0u, 1u, 0u, &o1, &o2));
    expect_fail(MCS_ERR_FREQ_RANGE, mcs_eq43_importance_cross(&imp, 2u, 1u, 8u, &o1, &o2));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq43_importance_cross(&imp, 2u, 0u, 0u, &o1, &o2));

    expect_fail(MCS_ERR_NULL, mcs_eq44_inverse_harmonic_mean(&imp, NULL));
    expect_fail(MCS_ERR_DOMAIN, mcs_eq44_inverse_harmonic_mean(NULL, &o1));
    expect_fail(MCS_ERR_UNINIT, mcs_eq44_inverse_harmonic_mean(&zero_imp, &o1));

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
        mcs_eq52_variance_printed, mcs_eq52_variance_corrected,
        mcs_eq52_variance_corrected_primal, mcs_eq55_variance_convolution};
    for (size_t i = 0; i < 4; ++i) {
        expect_fail(MCS_ERR_NULL, fimp[i](&imp, 2u, NULL, &o1));
        expect_fail(MCS_ERR_NULL, fimp[i](&imp, 2u, f, NULL));
        expect_fail(MCS_ERR_DOMAIN, fimp[i](NULL, 2u, f, &o1));
        expect_fail(MCS_ERR_UNINIT, fimp[i](&zero_imp, 2u, f, &o1));
        expect_fail(MCS_ERR_K_RANGE, fimp[i](&imp, 0u, f, &o1));
        expect_fail(MCS_ERR_NOT_FINITE, fimp[i](&imp, 2u, bad_f, &o1));
        if (i != 2u)
            expect_fail(MCS_ERR_N_RANGE, fimp[i](&big_imp, 2u, f, &o1));
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq52_variance_corrected_primal(&big_imp, 2u, f, &o1));
}

static void test_theory_struct_size_is_as_documented(void)
{
    printf("sizeof(mcs_theory) = %zu bytes at MCS_MAX_COV_N = %d\n", sizeof(mcs_theory),
           MCS_MAX_COV_N);
#if MCS_MAX_COV_N == 64
    if (sizeof(void *) == 8u)
        TEST_ASSERT_EQUAL_UINT(34336u, sizeof(mcs_theory));
#endif
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_exact_moments_match_enumeration_of_every_outcome_without_importance);
    RUN_TEST(test_exact_moments_match_enumeration_of_every_outcome_with_importance);
    RUN_TEST(test_uniform_pattern_without_importance_bins_every_sample_exactly);
    RUN_TEST(test_large_k_costs_nothing_and_keeps_sum_rules);
    RUN_TEST(test_cross_spectrum_is_the_eq16_transform_of_the_primal_moments);
    RUN_TEST(test_primal_and_spectral_variance_agree_for_every_kind_with_and_without_importance);
    RUN_TEST(test_every_unbiased_kind_has_mean_k_over_n_and_the_eq11_estimator_mean);
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
    RUN_TEST(test_eq4_is_var_f_plus_var_g_minus_twice_the_covariance_and_eq2_drops_it);
    RUN_TEST(test_exact_moments_and_cross_spectra_agree_with_the_generator_within_5_standard_errors);
    RUN_TEST(test_exact_moments_agree_with_the_moment_accumulator_within_5_standard_errors);
    RUN_TEST(test_correlated_and_uncorrelated_gradient_variance_match_eq4_and_eq2_on_trials);
    RUN_TEST(test_bad_theory_init_returns_an_error_and_changes_nothing);
    RUN_TEST(test_bad_read_outs_return_an_error_and_change_nothing);
    RUN_TEST(test_bad_closed_form_arguments_return_an_error_and_change_nothing);
    RUN_TEST(test_bad_importance_arguments_return_an_error_and_change_nothing);
    RUN_TEST(test_theory_struct_size_is_as_documented);
    return UNITY_END();
}
