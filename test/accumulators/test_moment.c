/* Tests for the primal moment accumulator: against the spectrum accumulator
 * and brute force, covariances, the estimator read-outs, merge, the note's
 * cross spectra measured on it, guard words after matrix outputs, and bad
 * input. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mcspec.h"
#include "spectra_ref.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define PI 3.14159265358979323846
#define COV MCS_MAX_COV_N

static mcs_moment mom, mom2, mom3, mom_before;
static mcs_spectrum spec;
static mcs_importance imp;
static mcs_dft plan;
static size_t bins[256];
static double weights[256], dense[MCS_MAX_N], re[MCS_MAX_N], im[MCS_MAX_N];
/* one element more than any matrix output: the guard word */
static double mat_re[COV * COV + 1], mat_im[COV * COV + 1];

/* Every stream of this file uses PCG32 sequence 0xabcdu. */
#define STREAM_SEQ 0xabcdu

static void stream_draw(spectra_stream *st)
{
    spectra_stream_draw(st, bins, weights, NULL);
}

/* One trial of st: added to mom, its dense s in dense and its transform
 * S_k in re, im (the plan set up for N), for the brute-force references. */
static void draw_transformed(spectra_stream *st, size_t n, size_t k)
{
    stream_draw(st);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&mom, k, bins, weights));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_dense(n, k, bins, weights, dense));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, n, dense, re, im));
}

/* Empties count pairs of accumulators for Re and Im of S_k S_l*. */
static void cross_init(size_t count, mcs_welford *wr, mcs_welford *wi)
{
    for (size_t j = 0; j < count; ++j) {
        mcs_welford_init(&wr[j]);
        mcs_welford_init(&wi[j]);
    }
}

/* Adds S_k S_l* of the last transformed trial to (wr, wi). */
static void cross_add(size_t k, size_t l, mcs_welford *wr, mcs_welford *wi)
{
    mcs_welford_add(wr, re[k] * re[l] + im[k] * im[l]);
    mcs_welford_add(wi, im[k] * re[l] - re[k] * im[l]);
}

static void make_importance(size_t n)
{
    spectra_make_importance(&imp, n, 0.3, 5u, 2u, 1.5);
}

/* ---------------- agreement with the spectrum accumulator ---------------- */

static void test_moment_and_spectrum_agree_on_every_mean_and_power(void)
{
    static const struct {
        size_t n, k;
        mcs_pattern_kind kind;
        int importance;
    } cases[] = {
        {1u, 2u, MCS_PATTERN_RANDOM, 0},      {2u, 3u, MCS_PATTERN_STRATIFIED, 0},
        {7u, 3u, MCS_PATTERN_RANDOM, 1},      {16u, 4u, MCS_PATTERN_STRATIFIED, 1},
        {24u, 5u, MCS_PATTERN_JITTER, 0},     {33u, 8u, MCS_PATTERN_HOMOGENIZED, 0},
        {(size_t)COV, 64u, MCS_PATTERN_RANDOM, 1},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        size_t n = cases[i].n, k = cases[i].k;
        const mcs_importance *ip = NULL;
        if (cases[i].importance) {
            make_importance(n);
            ip = &imp;
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_init(&spec, n));
        spectra_stream st;
        spectra_stream_init(&st, cases[i].kind, n, k, ip, 60u + i, STREAM_SEQ);
        for (size_t t = 0; t < 2000u; ++t) {
            stream_draw(&st);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&mom, k, bins, weights));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_add_bins(&spec, k, bins, weights));
        }
        /* Rounding in either method is relative to the pattern's energy, not to
         * one frequency's value (jitter has exact zeros): the scale is the mean
         * power (1/N) sum_k <|S_k|^2> = <sum_n s_n^2> / N. */
        const double level = spectra_mean_power(&spec);
        for (size_t f = 0; f < n; ++f) {
            double mr, mi, sr, si, mp, sp;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_mean(&mom, f, &mr, &mi));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_mean(&spec, f, &sr, &si));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_power(&mom, f, &mp));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum_power(&spec, f, &sp));
            /* relative to the frequency's own scale sqrt(<|S_k|^2>) for the mean */
            spectra_assert_close(sr, mr, 1e-10, sqrt(level), "Re <S_k>", n, f);
            spectra_assert_close(si, mi, 1e-10, sqrt(level), "Im <S_k>", n, f);
            spectra_assert_close(sp, mp, 1e-10, level, "<|S_k|^2>", n, f);
        }
    }
}

/* ---------------- primal sums and eq. 16 against brute force ---------------- */

static void test_primal_moments_and_cross_spectrum_match_brute_force(void)
{
    enum { N = 10, K = 4, T = 300 };
    static double sum_s[N], sum_ss[N][N];
    static double cross_re[N][N], cross_im[N][N];
    make_importance(N);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, N));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, N));
    memset(sum_s, 0, sizeof sum_s);
    memset(sum_ss, 0, sizeof sum_ss);
    memset(cross_re, 0, sizeof cross_re);
    memset(cross_im, 0, sizeof cross_im);
    spectra_stream st;
    spectra_stream_init(&st, MCS_PATTERN_STRATIFIED, N, K, &imp, 3u, STREAM_SEQ);
    for (size_t t = 0; t < T; ++t) {
        draw_transformed(&st, N, K);
        for (size_t m = 0; m < N; ++m) {
            sum_s[m] += dense[m];
            for (size_t c = 0; c < N; ++c) {
                sum_ss[m][c] += dense[m] * dense[c];
                /* S_m S_c* */
                cross_re[m][c] += re[m] * re[c] + im[m] * im[c];
                cross_im[m][c] += im[m] * re[c] - re[m] * im[c];
            }
        }
    }
    uint64_t count;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_count(&mom, &count));
    TEST_ASSERT_EQUAL_UINT64(T, count);
    spectra_guard_set(mat_re, N * N);
    spectra_guard_set(mat_im, N * N);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_cross_matrix(&mom, N, mat_re, mat_im));
    spectra_guard_check(mat_re, N * N, "mcs_moment_cross_matrix (re)");
    spectra_guard_check(mat_im, N * N, "mcs_moment_cross_matrix (im)");
    for (size_t m = 0; m < N; ++m) {
        double v;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_bin_mean(&mom, m, &v));
        spectra_assert_close(sum_s[m] / T, v, 1e-13, 0.0, "<s_n>", m, m);
        for (size_t c = 0; c < N; ++c) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_bin_second(&mom, m, c, &v));
            /* <s_m s_n> = Cov(d) + <s_m><s_n>: rounding relative to the bins' scale */
            const double bin_scale = sqrt(sum_ss[m][m] * sum_ss[c][c]) / T;
            spectra_assert_close(sum_ss[m][c] / T, v, 1e-13, bin_scale, "<s_m s_n>", m, c);
            double xr, xi;
            const double scale = sqrt(cross_re[m][m] * cross_re[c][c]) / T;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_cross(&mom, m, c, &xr, &xi));
            spectra_assert_close(cross_re[m][c] / T, xr, 1e-12, scale, "Re <S_k S_l*>", m, c);
            spectra_assert_close(cross_im[m][c] / T, xi, 1e-12, scale, "Im <S_k S_l*>", m, c);
            spectra_assert_close(xr, mat_re[m * N + c], 1e-12, scale, "matrix Re", m, c);
            spectra_assert_close(xi, mat_im[m * N + c], 1e-12, scale, "matrix Im", m, c);
        }
    }
}

static void test_covariance_is_the_cross_spectrum_minus_the_mean_product(void)
{
    enum { N = 9, K = 5 };
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, N));
    spectra_stream st;
    spectra_stream_init(&st, MCS_PATTERN_UNIFORM, N, K, NULL, 1u, STREAM_SEQ); /* biased: <S_k> != 0 */
    for (size_t t = 0; t < 3u; ++t) {
        stream_draw(&st);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&mom, K, bins, weights));
    }
    spectra_guard_set(mat_re, N * N);
    spectra_guard_set(mat_im, N * N);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_covariance_matrix(&mom, N, mat_re, mat_im));
    spectra_guard_check(mat_re, N * N, "mcs_moment_covariance_matrix (re)");
    spectra_guard_check(mat_im, N * N, "mcs_moment_covariance_matrix (im)");
    for (size_t k = 0; k < N; ++k) {
        double mk_r, mk_i, p;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_mean(&mom, k, &mk_r, &mk_i));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_power(&mom, k, &p));
        for (size_t l = 0; l < N; ++l) {
            double ml_r, ml_i, xr, xi, cr, ci;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_mean(&mom, l, &ml_r, &ml_i));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_cross(&mom, k, l, &xr, &xi));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_covariance(&mom, k, l, &cr, &ci));
            const double want_r = xr - (mk_r * ml_r + mk_i * ml_i);
            const double want_i = xi - (mk_i * ml_r - mk_r * ml_i);
            const double scale = (double)(K * K) / N;
            /* a deterministic pattern: every covariance vanishes */
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * scale, want_r, cr);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * scale, want_i, ci);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * scale, 0.0, cr);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * scale, 0.0, ci);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * scale, cr, mat_re[k * N + l]);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * scale, ci, mat_im[k * N + l]);
            if (k == l) {
                TEST_ASSERT_DOUBLE_WITHIN(1e-12 * scale, p, xr);
                TEST_ASSERT_DOUBLE_WITHIN(1e-12 * scale, 0.0, xi);
            }
        }
    }
}

static void test_dense_and_sparse_trials_accumulate_the_same_sums(void)
{
    enum { N = 20, K = 9 };
    make_importance(N);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, N));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom2, N));
    spectra_stream st;
    spectra_stream_init(&st, MCS_PATTERN_RANDOM, N, K, &imp, 12u, STREAM_SEQ);
    for (size_t t = 0; t < 200u; ++t) {
        stream_draw(&st);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&mom, K, bins, weights));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern_dense(N, K, bins, weights, dense));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_dense(&mom2, N, dense));
    }
    for (size_t m = 0; m < N; ++m)
        for (size_t c = 0; c < N; ++c) {
            double a, b;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_bin_second(&mom, m, c, &a));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_bin_second(&mom2, m, c, &b));
            spectra_assert_close(a, b, 1e-13, 0.0, "<s_m s_n>", m, c);
            /* both triangles are stored, each pair added to both: exactly symmetric */
            TEST_ASSERT_EQUAL_MEMORY(&mom.sum_dd[m * N + c], &mom.sum_dd[c * N + m], sizeof a);
            TEST_ASSERT_EQUAL_MEMORY(&mom2.sum_dd[m * N + c], &mom2.sum_dd[c * N + m], sizeof a);
        }
}

/* The estimator read-outs are the statistics of I = (1/K) sum_n f_n s_n over
 * the trials added, to rounding: its mean, its population variance and the
 * population covariance of two integrands estimated from the same trials. */
static void test_estimator_read_outs_equal_the_statistics_of_i_over_the_same_trials(void)
{
    enum { N = 12, K = 5, T = 3000 };
    static double est_f[T], est_g[T];
    double f[N], g[N];
    for (size_t b = 0; b < N; ++b) {
        f[b] = 1.0 + 0.5 * sin(0.9 * (double)b) + (double)b / N;
        g[b] = f[(b + 3u) % N] * (b % 2u ? 1.5 : 0.5);
    }
    make_importance(N);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, N));
    spectra_stream st;
    spectra_stream_init(&st, MCS_PATTERN_STRATIFIED, N, K, &imp, 44u, STREAM_SEQ);
    double mean_f = 0.0, mean_g = 0.0;
    for (size_t t = 0; t < T; ++t) {
        stream_draw(&st);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&mom, K, bins, weights));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_bins(N, K, f, bins, weights, &est_f[t]));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_estimate_bins(N, K, g, bins, weights, &est_g[t]));
        mean_f += est_f[t] / T;
        mean_g += est_g[t] / T;
    }
    double var_f = 0.0, cov_fg = 0.0; /* two passes: no cancellation in the reference */
    for (size_t t = 0; t < T; ++t) {
        var_f += (est_f[t] - mean_f) * (est_f[t] - mean_f) / T;
        cov_fg += (est_f[t] - mean_f) * (est_g[t] - mean_g) / T;
    }
    double m, v, c;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_estimator_mean(&mom, N, K, f, &m));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_variance(&mom, N, K, f, &v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_estimator_covariance(&mom, N, K, f, g, &c));
    /* rounding in the primal form is relative to <I^2>, not to Var[I] */
    spectra_assert_close(mean_f, m, 1e-12, 0.0, "<I>", N, K);
    spectra_assert_close(var_f, v, 1e-10, mean_f * mean_f, "Var[I]", N, K);
    spectra_assert_close(cov_fg, c, 1e-10, fabs(mean_f * mean_g), "Cov(I_f, I_g)", N, K);
    TEST_ASSERT_TRUE(var_f > 1e-4 * mean_f * mean_f); /* a variance the tolerance can see */
    /* K enters as 1/K and 1/K^2: the caller names it */
    double m2, v2;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_estimator_mean(&mom, N, 2u * K, f, &m2));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_variance(&mom, N, 2u * K, f, &v2));
    spectra_assert_close(m / 2.0, m2, 1e-15, 0.0, "<I> at 2K", N, K);
    spectra_assert_close(v / 4.0, v2, 1e-15, 0.0, "Var[I] at 2K", N, K);
}

static void test_merge_of_halves_equals_one_pass(void)
{
    enum { N = 30, K = 7 };
    make_importance(N);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, N));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom2, N));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom3, N));
    spectra_stream st;
    spectra_stream_init(&st, MCS_PATTERN_STRATIFIED, N, K, &imp, 21u, STREAM_SEQ);
    for (size_t t = 0; t < 500u; ++t) {
        stream_draw(&st);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&mom, K, bins, weights));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(t < 200u ? &mom2 : &mom3, K, bins, weights));
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_merge(&mom2, &mom3));
    uint64_t c1;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_count(&mom2, &c1));
    TEST_ASSERT_EQUAL_UINT64(500u, c1);
    for (size_t k = 0; k < N; ++k) {
        for (size_t l = 0; l < N; ++l) {
            double ar, ai, br, bi;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_cross(&mom, k, l, &ar, &ai));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_cross(&mom2, k, l, &br, &bi));
            spectra_assert_close(ar, br, 1e-12, 1.0, "Re <S_k S_l*>", k, l);
            spectra_assert_close(ai, bi, 1e-12, 1.0, "Im <S_k S_l*>", k, l);
        }
    }
}

/* ---------------- the note, measured on the moment accumulator ---------------- */

/* Eq. 43: importance-sampled random, <S_k S_l*> = (K/N) N^{-1/2} Q_{k-l} for
 * (k, l) != (0, 0), Q the DFT of 1/p; the diagonal is eq. 45, and eq. 46 at 0.
 * Standard errors from Welford accumulators of S_k S_l* per trial. */
static void test_importance_sampled_cross_spectrum_is_q_of_k_minus_l(void)
{
    enum { N = 12, K = 3, T = 150000, NK = 3 };
    static const size_t ks[NK] = {0u, 1u, 5u};
    static mcs_welford wr[NK][N], wi[NK][N];
    static double q_re[N], q_im[N], inv_p[N];
    make_importance(N);
    for (size_t b = 0; b < N; ++b)
        inv_p[b] = 1.0 / imp.p[b];
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, N));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_real(&plan, N, inv_p, q_re, q_im));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, N));
    cross_init(NK * N, &wr[0][0], &wi[0][0]);
    spectra_stream st;
    spectra_stream_init(&st, MCS_PATTERN_RANDOM, N, K, &imp, 77u, STREAM_SEQ);
    for (size_t t = 0; t < T; ++t) {
        draw_transformed(&st, N, K);
        for (size_t a = 0; a < NK; ++a) {
            const size_t k = ks[a];
            for (size_t l = 0; l < N; ++l)
                cross_add(k, l, &wr[a][l], &wi[a][l]);
        }
    }
    const double kn = (double)K / N, h = imp.harmonic_mean;
    for (size_t a = 0; a < NK; ++a) {
        const size_t k = ks[a];
        for (size_t l = 0; l < N; ++l) {
            double pr, pi, xr, xi, mr, mi, ser, sei;
            const size_t d = (k + N - l) % N;
            if (k == 0u && l == 0u) {
                pr = (double)(K * K) / N + kn * (1.0 / h - 1.0); /* eq. 46 */
                pi = 0.0;
            } else {
                pr = kn / sqrt((double)N) * q_re[d]; /* eq. 43 */
                pi = kn / sqrt((double)N) * q_im[d];
            }
            if (k == l && k != 0u)
                TEST_ASSERT_DOUBLE_WITHIN(1e-12, kn / h, pr); /* eq. 45 is eq. 43 at k = l */
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_cross(&mom, k, l, &xr, &xi));
            mcs_welford_mean(&wr[a][l], &mr);
            mcs_welford_mean(&wi[a][l], &mi);
            mcs_welford_stderr(&wr[a][l], &ser);
            mcs_welford_stderr(&wi[a][l], &sei);
            /* the accumulator is the trial average, to rounding */
            spectra_assert_close(mr, xr, 1e-10, sqrt(ser * ser + sei * sei) * 1e2, "Re vs trials", k, l);
            spectra_assert_close(mi, xi, 1e-10, sqrt(ser * ser + sei * sei) * 1e2, "Im vs trials", k, l);
            /* and the note's prediction, within 5 standard errors */
            if (!(fabs(xr - pr) <= 5.0 * ser + 1e-12) || !(fabs(xi - pi) <= 5.0 * sei + 1e-12)) {
                char msg[200];
                (void)snprintf(msg, sizeof msg,
                               "<S_%zu S_%zu*> = %.5g%+.5gi +- (%.2g, %.2g), eq. 43 %.5g%+.5gi", k,
                               l, xr, xi, ser, sei, pr, pi);
                TEST_FAIL_MESSAGE(msg);
            }
        }
    }
}

/* Stratified with K | N (eq. 28-30): <S_k S_l*> = (K/N) delta_kl + Delta_kl
 * with Delta_kl = -(K/N)^3 A_k conj(A_l) when k = l (mod K) and 0 otherwise,
 * A_k = (1 - e^{-2 pi i k/K}) / (1 - e^{-2 pi i k/N}); (k, l) != (0, 0). The
 * off-diagonal terms with k = l (mod K) are what makes the pattern
 * non-stationary. */
static void test_stratified_off_diagonal_terms_follow_eq_30(void)
{
    enum { N = 16, K = 4, T = 100000 };
    static mcs_welford wr[N][N], wi[N][N];
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, N));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_dft_init(&plan, N));
    cross_init(N * N, &wr[0][0], &wi[0][0]);
    spectra_stream st;
    spectra_stream_init(&st, MCS_PATTERN_STRATIFIED, N, K, NULL, 99u, STREAM_SEQ);
    for (size_t t = 0; t < T; ++t) {
        draw_transformed(&st, N, K);
        for (size_t k = 1; k < 4u; ++k)
            for (size_t l = 0; l < N; ++l)
                cross_add(k, l, &wr[k][l], &wi[k][l]);
    }
    const double kn = (double)K / N;
    size_t nonzero_off_diagonal = 0u;
    for (size_t k = 1; k < 4u; ++k) {
        for (size_t l = 0; l < N; ++l) {
            double pr = k == l ? kn : 0.0, pi = 0.0;
            if ((k + N - l) % K == 0u && l % K != 0u) {
                /* A_k conj(A_l) */
                const double ak = 2.0 * PI * (double)k, al = 2.0 * PI * (double)l;
                const double nr_k = 1.0 - cos(ak / K), ni_k = sin(ak / K);
                const double dr_k = 1.0 - cos(ak / N), di_k = sin(ak / N);
                const double nr_l = 1.0 - cos(al / K), ni_l = sin(al / K);
                const double dr_l = 1.0 - cos(al / N), di_l = sin(al / N);
                /* A_k = (nr_k + i ni_k) / (dr_k + i di_k) */
                const double den_k = dr_k * dr_k + di_k * di_k, den_l = dr_l * dr_l + di_l * di_l;
                const double akr = (nr_k * dr_k + ni_k * di_k) / den_k;
                const double aki = (ni_k * dr_k - nr_k * di_k) / den_k;
                const double alr = (nr_l * dr_l + ni_l * di_l) / den_l;
                const double ali = (ni_l * dr_l - nr_l * di_l) / den_l;
                pr -= kn * kn * kn * (akr * alr + aki * ali);
                pi -= kn * kn * kn * (aki * alr - akr * ali);
                if (k != l)
                    ++nonzero_off_diagonal;
            }
            double xr, xi, ser, sei;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_cross(&mom, k, l, &xr, &xi));
            mcs_welford_stderr(&wr[k][l], &ser);
            mcs_welford_stderr(&wi[k][l], &sei);
            if (!(fabs(xr - pr) <= 5.0 * ser + 1e-12) || !(fabs(xi - pi) <= 5.0 * sei + 1e-12)) {
                char msg[200];
                (void)snprintf(msg, sizeof msg,
                               "<S_%zu S_%zu*> = %.5g%+.5gi +- (%.2g, %.2g), eq. 30 %.5g%+.5gi", k,
                               l, xr, xi, ser, sei, pr, pi);
                TEST_FAIL_MESSAGE(msg);
            }
        }
    }
    TEST_ASSERT_TRUE(nonzero_off_diagonal >= 6u);
}

/* ---------------- bad input ---------------- */

#define MOM_UNCHANGED(status, call) SPECTRA_UNCHANGED(mom, mom_before, status, call)

static mcs_status add_bins(void *obj, size_t k, const size_t *b, const double *w)
{
    return mcs_moment_add_bins((mcs_moment *)obj, k, b, w);
}

static void test_bad_input_to_adding_and_merging_changes_nothing(void)
{
    size_t b[3] = {0u, 4u, 7u};
    double w[3] = {1.0, 2.0, 0.5};
    uint64_t c = 7u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&mom, 3u, b, w));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_init(NULL, 8u));
    MOM_UNCHANGED(MCS_ERR_N_RANGE, mcs_moment_init(&mom, 0u));
    MOM_UNCHANGED(MCS_ERR_N_RANGE, mcs_moment_init(&mom, (size_t)COV + 1u));

    spectra_refuses_bad_trials(&mom, &mom_before, sizeof mom, 8u, add_bins, b, w, 2u, 1u);
    w[1] = -INFINITY;
    MOM_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_moment_add_bins(&mom, 3u, b, w));
    w[1] = 2.0;

    for (size_t j = 0; j < 8u; ++j)
        dense[j] = 1.0;
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_add_dense(&mom, 8u, NULL));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_add_dense(NULL, 8u, dense));
    MOM_UNCHANGED(MCS_ERR_MISMATCH, mcs_moment_add_dense(&mom, 9u, dense));
    dense[5] = NAN;
    MOM_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_moment_add_dense(&mom, 8u, dense));
    dense[5] = -1.0;
    MOM_UNCHANGED(MCS_ERR_NEGATIVE, mcs_moment_add_dense(&mom, 8u, dense));
    dense[5] = 1.0;

    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom2, 9u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&mom2, 3u, b, w));
    MOM_UNCHANGED(MCS_ERR_MISMATCH, mcs_moment_merge(&mom, &mom2));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_merge(&mom, NULL));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_merge(NULL, &mom2));
    memset(&mom3, 0, sizeof mom3);
    MOM_UNCHANGED(MCS_ERR_UNINIT, mcs_moment_merge(&mom, &mom3));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_count(&mom, NULL));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_count(NULL, &c));

    memset(&mom, 0, sizeof mom);
    MOM_UNCHANGED(MCS_ERR_UNINIT, mcs_moment_add_bins(&mom, 3u, b, w));
    MOM_UNCHANGED(MCS_ERR_UNINIT, mcs_moment_add_dense(&mom, 8u, dense));
    MOM_UNCHANGED(MCS_ERR_UNINIT, mcs_moment_count(&mom, &c));
    MOM_UNCHANGED(MCS_ERR_UNINIT, mcs_moment_merge(&mom, &mom2));
    TEST_ASSERT_EQUAL_UINT64(7u, c);
}

/* Every read-out of an accumulator in state (uninitialised, empty, or with
 * trials) on arguments that must fail with want; outputs checked after. */
static double v, vr, vi;

static void expect_read_outs_fail(mcs_status want)
{
    const double f[8] = {1, 2, 3, 4, 5, 6, 7, 8};
    MOM_UNCHANGED(want, mcs_moment_bin_mean(&mom, 0u, &v));
    MOM_UNCHANGED(want, mcs_moment_bin_second(&mom, 0u, 1u, &v));
    MOM_UNCHANGED(want, mcs_moment_mean(&mom, 1u, &vr, &vi));
    MOM_UNCHANGED(want, mcs_moment_power(&mom, 0u, &v));
    MOM_UNCHANGED(want, mcs_moment_cross(&mom, 0u, 1u, &vr, &vi));
    MOM_UNCHANGED(want, mcs_moment_covariance(&mom, 0u, 1u, &vr, &vi));
    MOM_UNCHANGED(want, mcs_moment_cross_matrix(&mom, 8u, mat_re, mat_im));
    MOM_UNCHANGED(want, mcs_moment_covariance_matrix(&mom, 8u, mat_re, mat_im));
    MOM_UNCHANGED(want, mcs_moment_estimator_mean(&mom, 8u, 3u, f, &v));
    MOM_UNCHANGED(want, mcs_moment_variance(&mom, 8u, 3u, f, &v));
    MOM_UNCHANGED(want, mcs_moment_estimator_covariance(&mom, 8u, 3u, f, f, &v));
}

static void expect_outputs_untouched(void)
{
    for (size_t j = 0; j < 65u; ++j) {
        TEST_ASSERT_EQUAL_DOUBLE(7.0, mat_re[j]);
        TEST_ASSERT_EQUAL_DOUBLE(7.0, mat_im[j]);
    }
    TEST_ASSERT_EQUAL_DOUBLE(7.0, v);
    TEST_ASSERT_EQUAL_DOUBLE(7.0, vr);
    TEST_ASSERT_EQUAL_DOUBLE(7.0, vi);
}

static void test_bad_read_outs_return_an_error_and_change_nothing(void)
{
    size_t b[3] = {0u, 4u, 7u};
    double w[3] = {1.0, 2.0, 0.5};
    double f[8] = {1, 2, 3, 4, 5, 6, 7, 8}, bad_f[8] = {1, 2, NAN, 4, 5, 6, 7, 8};
    v = vr = vi = 7.0;
    for (size_t j = 0; j < 65u; ++j)
        mat_re[j] = mat_im[j] = 7.0;
    memset(&mom, 0, sizeof mom);
    expect_read_outs_fail(MCS_ERR_UNINIT);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&mom, 8u));
    expect_read_outs_fail(MCS_ERR_EMPTY);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&mom, 3u, b, w));

    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_bin_mean(NULL, 1u, &v));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_bin_mean(&mom, 1u, NULL));
    MOM_UNCHANGED(MCS_ERR_BIN_RANGE, mcs_moment_bin_mean(&mom, 8u, &v));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_bin_second(&mom, 1u, 1u, NULL));
    MOM_UNCHANGED(MCS_ERR_BIN_RANGE, mcs_moment_bin_second(&mom, 1u, 8u, &v));
    MOM_UNCHANGED(MCS_ERR_BIN_RANGE, mcs_moment_bin_second(&mom, 8u, 1u, &v));
    MOM_UNCHANGED(MCS_ERR_FREQ_RANGE, mcs_moment_mean(&mom, 8u, &vr, &vi));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_mean(&mom, 1u, &vr, NULL));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_mean(&mom, 1u, NULL, &vi));
    MOM_UNCHANGED(MCS_ERR_FREQ_RANGE, mcs_moment_power(&mom, 8u, &v));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_power(&mom, 0u, NULL));
    MOM_UNCHANGED(MCS_ERR_FREQ_RANGE, mcs_moment_cross(&mom, 8u, 0u, &vr, &vi));
    MOM_UNCHANGED(MCS_ERR_FREQ_RANGE, mcs_moment_cross(&mom, 0u, 8u, &vr, &vi));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_cross(&mom, 0u, 1u, NULL, &vi));
    MOM_UNCHANGED(MCS_ERR_FREQ_RANGE, mcs_moment_covariance(&mom, 9u, 0u, &vr, &vi));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_covariance(&mom, 0u, 0u, &vr, NULL));
    MOM_UNCHANGED(MCS_ERR_MISMATCH, mcs_moment_cross_matrix(&mom, 7u, mat_re, mat_im));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_cross_matrix(&mom, 8u, mat_re, NULL));
    MOM_UNCHANGED(MCS_ERR_MISMATCH, mcs_moment_covariance_matrix(&mom, 9u, mat_re, mat_im));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_covariance_matrix(&mom, 8u, NULL, mat_im));

    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_estimator_mean(&mom, 8u, 3u, NULL, &v));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_estimator_mean(&mom, 8u, 3u, f, NULL));
    MOM_UNCHANGED(MCS_ERR_MISMATCH, mcs_moment_estimator_mean(&mom, 7u, 3u, f, &v));
    MOM_UNCHANGED(MCS_ERR_K_RANGE, mcs_moment_estimator_mean(&mom, 8u, 0u, f, &v));
    MOM_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_moment_estimator_mean(&mom, 8u, 3u, bad_f, &v));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_variance(NULL, 8u, 3u, f, &v));
    MOM_UNCHANGED(MCS_ERR_MISMATCH, mcs_moment_variance(&mom, 9u, 3u, f, &v));
    MOM_UNCHANGED(MCS_ERR_K_RANGE, mcs_moment_variance(&mom, 8u, 0u, f, &v));
    MOM_UNCHANGED(MCS_ERR_NOT_FINITE, mcs_moment_variance(&mom, 8u, 3u, bad_f, &v));
    MOM_UNCHANGED(MCS_ERR_NULL, mcs_moment_estimator_covariance(&mom, 8u, 3u, f, NULL, &v));
    MOM_UNCHANGED(MCS_ERR_K_RANGE, mcs_moment_estimator_covariance(&mom, 8u, 0u, f, f, &v));
    MOM_UNCHANGED(MCS_ERR_NOT_FINITE,
                  mcs_moment_estimator_covariance(&mom, 8u, 3u, f, bad_f, &v));
    expect_outputs_untouched();
}

/* s is real, so S_0 and (even N) S_{N/2} are real in every trial: their
 * mean's imaginary part is exactly +0, not the transform's rounding. */
static void test_the_means_at_0_and_nyquist_are_exactly_real(void)
{
    static mcs_moment m;
    mcs_rng rng;
    mcs_rng_seed(&rng, 23u, 5u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_init(&m, 6u));
    for (int t = 0; t < 50; ++t) {
        size_t at[3];
        double w[3], u = 0.0, r = 0.0;
        for (size_t j = 0; j < 3u; ++j) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(&rng, &u));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(&rng, &r));
            at[j] = (size_t)(u * 6.0);
            w[j] = 0.3 + r;
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_add_bins(&m, 3u, at, w));
    }
    const double zero = 0.0;
    for (size_t k = 0; k < 6u; k += 3u) {
        double mr = -1.0, mi = -1.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_moment_mean(&m, k, &mr, &mi));
        TEST_ASSERT_EQUAL_MEMORY(&zero, &mi, sizeof mi);
        TEST_ASSERT_TRUE(mr > 0.0 || k == 3u);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_moment_and_spectrum_agree_on_every_mean_and_power);
    RUN_TEST(test_primal_moments_and_cross_spectrum_match_brute_force);
    RUN_TEST(test_covariance_is_the_cross_spectrum_minus_the_mean_product);
    RUN_TEST(test_dense_and_sparse_trials_accumulate_the_same_sums);
    RUN_TEST(test_estimator_read_outs_equal_the_statistics_of_i_over_the_same_trials);
    RUN_TEST(test_merge_of_halves_equals_one_pass);
    RUN_TEST(test_importance_sampled_cross_spectrum_is_q_of_k_minus_l);
    RUN_TEST(test_stratified_off_diagonal_terms_follow_eq_30);
    RUN_TEST(test_bad_input_to_adding_and_merging_changes_nothing);
    RUN_TEST(test_bad_read_outs_return_an_error_and_change_nothing);
    RUN_TEST(test_the_means_at_0_and_nyquist_are_exactly_real);
    return UNITY_END();
}
