/* Tests for the exact moments: against brute-force enumeration of every
 * outcome, the read-out against independent transforms and against the
 * measured moments (the same calls on a mcs_moment), against the generator
 * on many trials (5 standard errors), guard words after the matrices, and
 * bad input. The closed forms are tested in test_eq.c. */
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
#define KMAX 64
#define SENTINEL (-7.25e300)

static const mcs_pattern_kind all_kinds[MCS_PATTERN_KIND_COUNT] = {
    MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED, MCS_PATTERN_HOMOGENIZED, MCS_PATTERN_UNIFORM,
    MCS_PATTERN_JITTER};

static mcs_importance imp;
static mcs_theory th;
static mcs_theory th_copy;
static mcs_moment mom;
/* one element more than any matrix output: the guard word */
static double mat_re[NMAX * NMAX + 1], mat_im[NMAX * NMAX + 1];

static void init_importance(size_t n, const double *w)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_importance_init(&imp, n, w));
}

/* ---- brute force (test/support/theory_ref.c): every outcome ---------------- */

static double bf_mean[NMAX];
static double bf_second[NMAX * NMAX];

static void brute_force(mcs_pattern_kind kind, size_t n, size_t k, const mcs_importance *im,
                        size_t grid)
{
    theory_brute_force(kind, n, k, im, grid, bf_mean, bf_second);
}

static void assert_theory_equals_brute_force(const mcs_theory *t, const char *label)
{
    char what[128];
    size_t n = t->n;
    for (size_t m = 0; m < n; ++m) {
        double v;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_bin_mean(t, m, &v));
        snprintf(what, sizeof what, "%s <s_%zu>", label, m);
        theory_assert_close(bf_mean[m], v, 1e-12, what);
        for (size_t b = 0; b < n; ++b) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_bin_second(t, m, b, &v));
            snprintf(what, sizeof what, "%s <s_%zu s_%zu>", label, m, b);
            theory_assert_close(bf_second[m * n + b], v, 1e-12, what);
        }
    }
}

/* Enumerates every kind for (n, k) with grid = lcm(denominator of edges, k);
 * random only while grid^k stays small. */
static void check_all_kinds_by_enumeration(size_t n, size_t k, const mcs_importance *im,
                                           size_t edge_denominator)
{
    size_t grid = theory_lcm(edge_denominator, k);
    for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
        mcs_pattern_kind kind = all_kinds[i];
        if (im != NULL && kind == MCS_PATTERN_HOMOGENIZED)
            continue;
        if (kind == MCS_PATTERN_RANDOM && pow((double)grid, (double)k) > 2e6)
            continue;
        char label[96];
        snprintf(label, sizeof label, "%s N=%zu K=%zu%s", mcs_pattern_kind_str(kind), n, k,
                 im != NULL ? " importance" : "");
        theory_init(&th, kind, n, k, im);
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
            theory_init(&th, MCS_PATTERN_UNIFORM, n, k, NULL);
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
        theory_init(&th, kinds[i], 9u, big, &imp);
        double s1 = 0.0, s2 = 0.0;
        for (size_t m = 0; m < 9; ++m) {
            s1 += th.mean_s[m] * imp.p[m];
            for (size_t b = 0; b < 9; ++b)
                s2 += th.second[m * 9 + b] * imp.p[m] * imp.p[b];
        }
        theory_assert_close(1e9, s1, 1e-12, "sum r_n");
        theory_assert_close(1e18, s2, 1e-10, "sum r_m r_n");
    }
}

/* Var[I] through the spectra, the cross-check on the primal form of
 * mcs_theory_variance: (1/K^2) sum over ALL k, l of F_k* F_l Cov(S_k, S_l),
 * F by an independent DFT, each Cov(S_k, S_l) by eq. 16. O(N^4). */
static double spectral_variance(const mcs_theory *t, const double *f)
{
    const size_t n = t->n;
    double fr[NMAX], fi[NMAX];
    theory_ref_dft(n, f, fr, fi);
    double total = 0.0;
    for (size_t a = 0; a < n; ++a)
        for (size_t b = 0; b < n; ++b) {
            double cr, ci;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_covariance(t, a, b, &cr, &ci));
            /* F_a* F_b = (fr_a - i fi_a)(fr_b + i fi_b); the real part of the product */
            double ar = fr[a] * fr[b] + fi[a] * fi[b];
            double ai = fr[a] * fi[b] - fi[a] * fr[b];
            total += ar * cr - ai * ci;
        }
    const double kd = (double)t->k;
    return total / (kd * kd);
}

/* ---- linear algebra: spectra and variance --------------------------------- */

static void test_cross_spectrum_is_the_eq16_transform_of_the_primal_moments(void)
{
    double re[NMAX], im[NMAX];
    init_importance(6u, (const double[]){1.0, 2.0, 5.0, 1.0, 3.0, 1.0});
    theory_init(&th, MCS_PATTERN_JITTER, 6u, 4u, &imp);
    const size_t n = 6;
    /* <S_k> against an independent DFT of <s> */
    theory_ref_dft(n, th.mean_s, re, im);
    for (size_t k = 0; k < n; ++k) {
        double r, i;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_mean(&th, k, &r, &i));
        theory_assert_close(re[k], r, 1e-13, "<S_k> re");
        theory_assert_close(im[k], i, 1e-13, "<S_k> im");
    }
    /* <S_k S_l*> = (1/N) sum_mn e^{-i(km - ln)} <s_m s_n> by brute O(N^4) */
    for (size_t k = 0; k < n; ++k)
        for (size_t l = 0; l < n; ++l) {
            double r = 0.0, i = 0.0;
            for (size_t m = 0; m < n; ++m)
                for (size_t b = 0; b < n; ++b) {
                    double a = 2.0 * THEORY_PI * ((double)(k * m) - (double)(l * b)) / (double)n;
                    r += cos(a) * th.second[m * n + b];
                    i -= sin(a) * th.second[m * n + b];
                }
            double cr, ci, vr, vi, kr, ki, lr, li, p;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross(&th, k, l, &cr, &ci));
            theory_assert_close(r / (double)n, cr, 1e-13, "cross re");
            theory_assert_close(i / (double)n, ci, 1e-13, "cross im");
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_covariance(&th, k, l, &vr, &vi));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_mean(&th, k, &kr, &ki));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_mean(&th, l, &lr, &li));
            theory_assert_close(cr - (kr * lr + ki * li), vr, 1e-13, "cov re");
            theory_assert_close(ci - (ki * lr - kr * li), vi, 1e-13, "cov im");
            if (k == l) {
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, k, &p));
                theory_assert_close(cr, p, 1e-15, "power");
                theory_assert_close(0.0, ci, 1e-14, "power imaginary part");
            }
        }
    /* Parseval on the moments: sum_k <|S_k|^2> = sum_n <s_n^2> */
    double sp = 0.0, ss = 0.0;
    for (size_t k = 0; k < n; ++k) {
        double p;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, k, &p));
        sp += p;
        ss += th.second[k * n + k];
    }
    theory_assert_close(ss, sp, 1e-13, "Parseval");
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
        theory_make_f(n, f, 0.3);
        for (int with_imp = 0; with_imp < 2; ++with_imp)
            for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
                if (with_imp && all_kinds[i] == MCS_PATTERN_HOMOGENIZED)
                    continue;
                theory_init(&th, all_kinds[i], n, k, with_imp ? &imp : NULL);
                double vp = SENTINEL;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, k, f, &vp));
                double vs = spectral_variance(&th, f);
                TEST_ASSERT_TRUE(vp >= -1e-12);
                theory_assert_close(vp, vs, 1e-11, "primal vs spectral Var[I]");
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
    theory_make_f(n, f, 1.1);
    double fbar;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq11_unbiased_mean(n, f, &fbar));
    for (int with_imp = 0; with_imp < 2; ++with_imp)
        for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
            if (all_kinds[i] == MCS_PATTERN_UNIFORM ||
                (with_imp && all_kinds[i] == MCS_PATTERN_HOMOGENIZED))
                continue;
            theory_init(&th, all_kinds[i], n, k, with_imp ? &imp : NULL);
            for (size_t b = 0; b < n; ++b)
                theory_assert_close(0.4, th.mean_s[b], 1e-14, "<s_n> = K/N");
            double mean;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_estimator_mean(&th, n, k, f, &mean));
            theory_assert_close(fbar, mean, 1e-14, "eq. 9 = eq. 11");
        }
}

/* ---- the matrices, and measured vs exact through the same read-out ------- */

static void test_the_matrices_hold_every_entry_read_out_and_write_nothing_past_n_squared(void)
{
    static const size_t shapes[][2] = {{6u, 4u}, {NMAX, 8u}, {1u, 3u}};
    for (size_t s = 0; s < sizeof shapes / sizeof shapes[0]; ++s) {
        const size_t n = shapes[s][0], k = shapes[s][1];
        theory_lumpy_importance(&imp, n);
        theory_init(&th, MCS_PATTERN_JITTER, n, k, &imp);
        for (int cov = 0; cov < 2; ++cov) {
            spectra_guard_set(mat_re, n * n);
            spectra_guard_set(mat_im, n * n);
            TEST_ASSERT_EQUAL_INT(MCS_OK, cov ? mcs_theory_covariance_matrix(&th, n, mat_re, mat_im)
                                              : mcs_theory_cross_matrix(&th, n, mat_re, mat_im));
            spectra_guard_check(mat_re, n * n, "theory matrix (re)");
            spectra_guard_check(mat_im, n * n, "theory matrix (im)");
            double p0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, 0u, &p0));
            for (size_t a = 0; a < n; ++a)
                for (size_t b = 0; b < n; ++b) {
                    double r, i;
                    TEST_ASSERT_EQUAL_INT(MCS_OK, cov ? mcs_theory_covariance(&th, a, b, &r, &i)
                                                      : mcs_theory_cross(&th, a, b, &r, &i));
                    /* rounding is relative to the largest entry, <|S_0|^2> */
                    spectra_assert_close(r, mat_re[a * n + b], 1e-13, p0, "matrix re", a, b);
                    spectra_assert_close(i, mat_im[a * n + b], 1e-13, p0, "matrix im", a, b);
                }
        }
    }
}

/* One trial of the uniform pattern without importance is its own
 * expectation, and its sums are whole numbers: the accumulator of that one
 * trial holds the exact moments bit for bit, and since measured and exact
 * moments go through the same read-out, every call agrees bit for bit too --
 * but the covariances, which the accumulator reads from its sums of
 * deviations (exactly 0 here) and the exact moments as <S S*> - <S><S>*
 * (0 to rounding). */
static void test_one_uniform_trial_reads_out_exactly_as_its_exact_moments(void)
{
    enum { N = 24, K = 9 };
    size_t bins[K];
    double w[K], f[N], g[N];
    theory_make_f(N, f, 0.7);
    theory_make_f(N, g, 2.1);
    mcs_pattern pat;
    mcs_rng rng;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, MCS_PATTERN_UNIFORM, N, K, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(&th, &pat));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_seed(&rng, 5u, 5u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &rng, K, bins, w, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, N));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&mom, K, bins, w));
    double a[2], b[2];
    for (size_t p = 0; p < N; ++p)
        for (size_t q = 0; q < N; ++q) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_bin_second(&th, p, q, &a[0]));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_bin_second(&mom, p, q, &b[0]));
            TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a[0]);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_covariance(&th, p, q, &a[0], &a[1]));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_covariance(&mom, p, q, &b[0], &b[1]));
            TEST_ASSERT_DOUBLE_WITHIN(1e-14 * K * K / N, a[0], b[0]);
            TEST_ASSERT_DOUBLE_WITHIN(1e-14 * K * K / N, a[1], b[1]);
        }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_estimator_covariance(&th, N, K, f, g, &a[0]));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_estimator_covariance(&mom, N, K, f, g, &b[0]));
    TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a[0]);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_estimator_mean(&th, N, K, f, &a[0]));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_estimator_mean(&mom, N, K, f, &b[0]));
    TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a[0]);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_covariance_matrix(&th, N, mat_re, mat_im));
    double p3;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_power(&mom, 3u, &p3));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_cross_matrix(&mom, N, mat_re, mat_im));
    TEST_ASSERT_EQUAL_MEMORY(&p3, &mat_re[3 * N + 3], sizeof p3);
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
static mcs_welford acc_var;

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
        theory_lumpy_importance(&imp, n);
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
    theory_make_f(n, f, 0.5);
    mcs_rng rng;
    mcs_rng_seed(&rng, seed, 17u);
    size_t bins[KMAX];
    double w[KMAX], s[NMAX], sr[NMAX], si[NMAX];
    for (size_t t = 0; t < trials; ++t) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_draw(&pat, &rng, k, bins, w, NULL));
        mcs_pattern_dense(n, k, bins, w, s);
        double est;
        mcs_estimate_bins(n, k, f, bins, w, &est);
        mcs_welford_add(&acc_var, est);
        theory_ref_dft(n, s, sr, si);
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
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross(&th, m, b, &cr, &ci));
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
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, k, f, &exact));
    if (var_se > 1e-12) {
        if (!(fabs(var - exact) <= 5.0 * var_se)) {
            char msg[160];
            snprintf(msg, sizeof msg, "%s%s Var[I]: measured %.8g +- %.3g, exact %.8g", name,
                     c->importance ? "+imp" : "", var, var_se, exact);
            TEST_FAIL_MESSAGE(msg);
        }
    } else {
        theory_assert_close(exact, var, 1e-9, "deterministic Var[I]");
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
    bat_cov_r[NMAX * NMAX], bat_cov_i[NMAX * NMAX], bat_pow[NMAX], bat_mr[NMAX], bat_mi[NMAX],
    bat_est, bat_var;

/* One batch's read-outs, each into the Welford accumulator of its entry. */
static void add_batch_read_outs(size_t n, size_t k, const double *f)
{
    double v, r, i;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_estimator_mean(&batch, n, k, f, &v));
    mcs_welford_add(&bat_est, v);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_variance(&batch, n, k, f, &v));
    mcs_welford_add(&bat_var, v);
    for (size_t m = 0; m < n; ++m) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_bin_mean(&batch, m, &v));
        mcs_welford_add(&bat_s[m], v);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_power(&batch, m, &v));
        mcs_welford_add(&bat_pow[m], v);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_mean(&batch, m, &r, &i));
        mcs_welford_add(&bat_mr[m], r);
        mcs_welford_add(&bat_mi[m], i);
        for (size_t b = 0; b < n; ++b) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_bin_second(&batch, m, b, &v));
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

/* Every batch read-out against the exact value; a batch's covariances (and
 * its Var[I]) are centred on its own means, biased by (T - 1)/T. */
static void check_batches(const char *name, const char *tag, size_t n, size_t k, const double *f,
                          double shrink)
{
    char what[128];
    double v, r, i;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_estimator_mean(&th, n, k, f, &v));
    snprintf(what, sizeof what, "moment %s%s <I>", name, tag);
    check_within(&bat_est, v, what);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, k, f, &v));
    snprintf(what, sizeof what, "moment %s%s Var[I]", name, tag);
    check_within(&bat_var, v * shrink, what);
    for (size_t m = 0; m < n; ++m) {
        snprintf(what, sizeof what, "moment %s%s <s_%zu>", name, tag, m);
        check_within(&bat_s[m], th.mean_s[m], what);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, m, &v));
        snprintf(what, sizeof what, "moment %s%s <|S_%zu|^2>", name, tag, m);
        check_within(&bat_pow[m], v, what);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_mean(&th, m, &r, &i));
        snprintf(what, sizeof what, "moment %s%s Re<S_%zu>", name, tag, m);
        check_within(&bat_mr[m], r, what);
        snprintf(what, sizeof what, "moment %s%s Im<S_%zu>", name, tag, m);
        check_within(&bat_mi[m], i, what);
        for (size_t b = 0; b < n; ++b) {
            snprintf(what, sizeof what, "moment %s%s <s_%zu s_%zu>", name, tag, m, b);
            check_within(&bat_ss[m * n + b], th.second[m * n + b], what);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_cross(&th, m, b, &r, &i));
            snprintf(what, sizeof what, "moment %s%s Re<S_%zu S_%zu*>", name, tag, m, b);
            check_within(&bat_cr[m * n + b], r, what);
            snprintf(what, sizeof what, "moment %s%s Im<S_%zu S_%zu*>", name, tag, m, b);
            check_within(&bat_ci[m * n + b], i, what);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_covariance(&th, m, b, &r, &i));
            snprintf(what, sizeof what, "moment %s%s Re Cov(S_%zu, S_%zu)", name, tag, m, b);
            check_within(&bat_cov_r[m * n + b], r * shrink, what);
            snprintf(what, sizeof what, "moment %s%s Im Cov(S_%zu, S_%zu)", name, tag, m, b);
            check_within(&bat_cov_i[m * n + b], i * shrink, what);
        }
    }
}

static void run_moment_case(const stat_case *c, size_t trials_per_batch, uint64_t seed)
{
    size_t n = c->n, k = c->k;
    if (c->importance)
        theory_lumpy_importance(&imp, n);
    mcs_pattern pat;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_init(&pat, c->kind, n, k, c->importance ? &imp : NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_init(&th, &pat));
    mcs_welford_init(&bat_est);
    mcs_welford_init(&bat_var);
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
    double f[NMAX];
    theory_make_f(n, f, 0.9);
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
        add_batch_read_outs(n, k, f);
    }
    double shrink = ((double)trials_per_batch - 1.0) / (double)trials_per_batch;
    check_batches(mcs_pattern_kind_str(c->kind), c->importance ? "+imp" : "", n, k, f, shrink);
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
    theory_init(&th, MCS_PATTERN_JITTER, 4u, 3u, &imp);
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
    theory_init(&th, MCS_PATTERN_STRATIFIED, 8u, 3u, NULL);
    memcpy(&th_copy, &th, sizeof th);
    static mcs_theory zero; /* never initialised */
    reset_out();

    expect_fail(MCS_ERR_NULL, mcs_theory_bin_mean(NULL, 0u, &o1));
    expect_fail(MCS_ERR_NULL, mcs_theory_bin_mean(&th, 0u, NULL));
    expect_fail(MCS_ERR_UNINIT, mcs_theory_bin_mean(&zero, 0u, &o1));
    expect_fail(MCS_ERR_BIN_RANGE, mcs_theory_bin_mean(&th, 8u, &o1));

    expect_fail(MCS_ERR_NULL, mcs_theory_bin_second(&th, 0u, 0u, NULL));
    expect_fail(MCS_ERR_UNINIT, mcs_theory_bin_second(&zero, 0u, 0u, &o1));
    expect_fail(MCS_ERR_BIN_RANGE, mcs_theory_bin_second(&th, 0u, 8u, &o1));
    expect_fail(MCS_ERR_BIN_RANGE, mcs_theory_bin_second(&th, 8u, 0u, &o1));

    expect_fail(MCS_ERR_NULL, mcs_theory_mean(&th, 0u, &o1, NULL));
    expect_fail(MCS_ERR_NULL, mcs_theory_mean(NULL, 0u, &o1, &o2));
    expect_fail(MCS_ERR_UNINIT, mcs_theory_mean(&zero, 0u, &o1, &o2));
    expect_fail(MCS_ERR_FREQ_RANGE, mcs_theory_mean(&th, 8u, &o1, &o2));

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

    theory_check_bad_integrands(&th, mcs_theory_estimator_mean, NULL);
    theory_check_bad_integrands(&th, mcs_theory_variance, NULL);
    theory_check_bad_integrands(&th, NULL, mcs_theory_estimator_covariance);
}

static void test_bad_matrix_read_outs_return_an_error_and_write_nothing(void)
{
    mcs_status (*const matrix[])(const mcs_theory *, size_t, double *, double *) = {
        mcs_theory_cross_matrix, mcs_theory_covariance_matrix};
    static mcs_theory zero; /* never initialised */
    theory_init(&th, MCS_PATTERN_RANDOM, 8u, 3u, NULL);
    memcpy(&th_copy, &th, sizeof th);
    reset_out();
    for (size_t i = 0; i < 2u; ++i) {
        for (size_t j = 0; j < 82u; ++j)
            mat_re[j] = mat_im[j] = 7.0;
        expect_fail(MCS_ERR_NULL, matrix[i](NULL, 8u, mat_re, mat_im));
        expect_fail(MCS_ERR_NULL, matrix[i](&th, 8u, NULL, mat_im));
        expect_fail(MCS_ERR_NULL, matrix[i](&th, 8u, mat_re, NULL));
        expect_fail(MCS_ERR_UNINIT, matrix[i](&zero, 8u, mat_re, mat_im));
        expect_fail(MCS_ERR_MISMATCH, matrix[i](&th, 7u, mat_re, mat_im));
        expect_fail(MCS_ERR_MISMATCH, matrix[i](&th, 9u, mat_re, mat_im));
        for (size_t j = 0; j < 82u; ++j) {
            TEST_ASSERT_EQUAL_DOUBLE(7.0, mat_re[j]);
            TEST_ASSERT_EQUAL_DOUBLE(7.0, mat_im[j]);
        }
    }
}

static void test_exact_variances_and_powers_are_never_negative(void)
{
    /* Jitter over N = 50 with K = 10: every stratum is 5 whole bins and this f
     * sums alike over each, so I does not depend on beta and Var[I] = 0; as a
     * difference of second moments it came out -1.1e-16 (issue 12). */
    double f[50];
    for (size_t b = 0; b < 50u; ++b)
        f[b] = 0.5 + 0.3 * sin(2.0 * THEORY_PI * ((double)b + 0.5) / 50.0) + (b >= 15u ? 0.4 : 0.0);
    double v = SENTINEL;
    theory_init(&th, MCS_PATTERN_JITTER, 50u, 10u, NULL);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, 50u, 10u, f, &v));
    TEST_ASSERT_EQUAL_DOUBLE(0.0, v);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_eq4_correlated_variance(&th, 50u, 10u, f, f, &v));
    TEST_ASSERT_TRUE(v >= 0.0);
    /* every power and variance of a sweep, where several are 0 exactly */
    double g[NMAX];
    for (size_t n = 1; n <= NMAX; n += 9u)
        for (size_t k = 1; k <= 2u * n; k += n / 4u + 1u)
            for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
                theory_init(&th, all_kinds[i], n, k, NULL);
                theory_make_f(n, g, (double)k);
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_variance(&th, n, k, g, &v));
                TEST_ASSERT_TRUE(v >= 0.0);
                for (size_t q = 0; q < n; ++q) {
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_theory_power(&th, q, &v));
                    TEST_ASSERT_TRUE(v >= 0.0);
                }
            }
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
    RUN_TEST(test_the_matrices_hold_every_entry_read_out_and_write_nothing_past_n_squared);
    RUN_TEST(test_one_uniform_trial_reads_out_exactly_as_its_exact_moments);
    RUN_TEST(test_exact_moments_and_cross_spectra_agree_with_the_generator_within_5_standard_errors);
    RUN_TEST(test_exact_moments_agree_with_the_moment_accumulator_within_5_standard_errors);
    RUN_TEST(test_bad_theory_init_returns_an_error_and_changes_nothing);
    RUN_TEST(test_bad_read_outs_return_an_error_and_change_nothing);
    RUN_TEST(test_bad_matrix_read_outs_return_an_error_and_write_nothing);
    RUN_TEST(test_exact_variances_and_powers_are_never_negative);
    RUN_TEST(test_theory_struct_size_is_as_documented);
    return UNITY_END();
}
