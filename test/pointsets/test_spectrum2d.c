#include "mcspec/pattern2d.h"
#include "mcspec/rng.h"
#include "mcspec/spectrum2d.h"
#include "points_ref.h"
#include "unity.h"

#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define MAXN 64
#define MAXK 64

/* An accumulator and its buffer (N1 N2 <= 64 here): the whole is what
 * "changes nothing" compares. */
typedef struct {
    mcs_spectrum2d h;
    _Alignas(64) unsigned char mem[MCS_SPECTRUM2D_SIZE(64u, 64u)];
} obj;
static obj o_acc, o_acc2, o_acc3, o_snap;
#define acc (o_acc.h)
#define acc2 (o_acc2.h)
#define acc3 (o_acc3.h)

static mcs_status init(mcs_spectrum2d *a, size_t n1, size_t n2)
{
    obj *o = (obj *)(void *)a;
    return mcs_spectrum2d_init(&o->h, n1, n2, o->mem, sizeof o->mem);
}
static double pts[2 * MAXK], w[MAXK];
static double s[MAXN], fr[MAXN], fi[MAXN], gr[MAXN], gi[MAXN], f[MAXN];

/* Naive 2D eq. 7 in long double. */
static void naive_dft(size_t n1, size_t n2, const double *v, double *re, double *im)
{
    const long double two_pi = 6.283185307179586476925286766559L;
    for (size_t k2 = 0; k2 < n2; ++k2)
        for (size_t k1 = 0; k1 < n1; ++k1) {
            long double ar = 0.0L, ai = 0.0L;
            for (size_t b2 = 0; b2 < n2; ++b2)
                for (size_t b1 = 0; b1 < n1; ++b1) {
                    long double t = (long double)((k1 * b1) % n1) / n1 +
                                    (long double)((k2 * b2) % n2) / n2;
                    ar += v[b2 * n1 + b1] * cosl(two_pi * t);
                    ai -= v[b2 * n1 + b1] * sinl(two_pi * t);
                }
            re[k2 * n1 + k1] = (double)(ar / sqrtl((long double)(n1 * n2)));
            im[k2 * n1 + k1] = (double)(ai / sqrtl((long double)(n1 * n2)));
        }
}

/* Dense s from a trial's points (and weights). */
static void bin_trial(size_t n1, size_t n2, size_t k, const double *p, const double *wt,
                      double *out)
{
    memset(out, 0, n1 * n2 * sizeof *out);
    for (size_t j = 0; j < k; ++j)
        out[(size_t)(p[2 * j + 1] * n2) * n1 + (size_t)(p[2 * j] * n1)] += wt ? wt[j] : 1.0;
}

/* A lumpy integrand over bins: a smooth wave, an edge and a spike. */
static void lumpy(size_t n1, size_t n2, double *out)
{
    for (size_t b2 = 0; b2 < n2; ++b2)
        for (size_t b1 = 0; b1 < n1; ++b1) {
            double x = (b1 + 0.5) / n1, y = (b2 + 0.5) / n2;
            out[b2 * n1 + b1] = 0.5 + 0.3 * sin(6.283185307179586 * (x + 2.0 * y)) +
                                (x * x + y > 0.6 ? 0.4 : 0.0) + (b1 == 1 && b2 == 0 ? 1.0 : 0.0);
        }
}

static void test_transform_is_the_2d_eq_7(void)
{
    const size_t shapes[3][2] = {{5u, 6u}, {8u, 4u}, {1u, 7u}};
    uint64_t st = 99u;
    for (int c = 0; c < 3; ++c) {
        size_t n1 = shapes[c][0], n2 = shapes[c][1];
        for (size_t i = 0; i < n1 * n2; ++i) {
            st = st * 6364136223846793005u + 1u;
            s[i] = (i % 3u == 1u) ? 0.0 : (double)(st >> 40) / 16777216.0 - 0.3;
        }
        TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, n1, n2));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_transform(&acc, s, fr, fi));
        naive_dft(n1, n2, s, gr, gi);
        for (size_t i = 0; i < n1 * n2; ++i) {
            TEST_ASSERT_DOUBLE_WITHIN(1e-13, gr[i], fr[i]);
            TEST_ASSERT_DOUBLE_WITHIN(1e-13, gi[i], fi[i]);
        }
    }
}

static void test_one_trial_gives_the_transform_of_its_weighted_bin_counts(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 1u, 2u);
    const size_t shapes[3][2] = {{5u, 6u}, {8u, 4u}, {7u, 1u}};
    for (int c = 0; c < 3; ++c) {
        size_t n1 = shapes[c][0], n2 = shapes[c][1], k = 11u;
        for (int weighted = 0; weighted < 2; ++weighted) {
            points_uniform(&rng, 2 * k, pts);
            for (size_t j = 0; j < k; ++j)
                w[j] = 0.25 + (double)j;
            TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, n1, n2));
            TEST_ASSERT_EQUAL_INT(MCS_OK,
                                  mcs_spectrum2d_add_points(&acc, k, pts, weighted ? w : NULL));
            bin_trial(n1, n2, k, pts, weighted ? w : NULL, s);
            naive_dft(n1, n2, s, gr, gi);
            for (size_t k2 = 0; k2 < n2; ++k2)
                for (size_t k1 = 0; k1 < n1; ++k1) {
                    double re = 0.0, im = 0.0, p = 0.0, g2 = 0.0;
                    size_t i = k2 * n1 + k1;
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_mean(&acc, k1, k2, &re, &im));
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_power(&acc, k1, k2, &p));
                    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * k * k, gr[i], re);
                    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * k * k, gi[i], im);
                    g2 = gr[i] * gr[i] + gi[i] * gi[i];
                    TEST_ASSERT_DOUBLE_WITHIN(1e-11 * k * k * k, g2, p);
                }
            if (!weighted) {
                double re = 0.0, im = 0.0;
                mcs_spectrum2d_mean(&acc, 0u, 0u, &re, &im);
                TEST_ASSERT_DOUBLE_WITHIN(1e-12, (double)k / sqrt((double)(n1 * n2)), re);
            }
        }
    }
}

/* S_k of a dense s at one wave vector, by a direct double sum. */
static void dft_at(size_t n1, size_t n2, const double *v, size_t k1, size_t k2, double *re,
                   double *im)
{
    double ar = 0.0, ai = 0.0;
    for (size_t b2 = 0; b2 < n2; ++b2)
        for (size_t b1 = 0; b1 < n1; ++b1) {
            double t = (double)((k1 * b1) % n1) / n1 + (double)((k2 * b2) % n2) / n2;
            ar += v[b2 * n1 + b1] * cos(6.283185307179586 * t);
            ai -= v[b2 * n1 + b1] * sin(6.283185307179586 * t);
        }
    *re = ar / sqrt((double)(n1 * n2));
    *im = ai / sqrt((double)(n1 * n2));
}

/* Trials of pat into acc. Per trial also I = (1/K) sum f_n s_n, kept as the
 * central moments c2 = <(I - mu)^2> and c4 = <(I - mu)^4> about the exact
 * mean mu (every kind here is unbiased), and, if want_cross, the cross
 * moment S_a S_b^* at a = (a1, a2), b = (b1, b2) with its spread. */
static double c2, c4, x_re, x_im, x_re2, x_im2;

static void run_trials(const mcs_pattern2d *pat, size_t n1, size_t n2, int trials, uint64_t seed,
                       int want_cross, const size_t *ab)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, seed, 42u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, n1, n2));
    double mu = 0.0;
    for (size_t i = 0; i < n1 * n2; ++i)
        mu += f[i] / (double)(n1 * n2);
    c2 = c4 = x_re = x_im = x_re2 = x_im2 = 0.0;
    for (int t = 0; t < trials; ++t) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_draw(pat, &rng, pat->k, pts));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points(&acc, pat->k, pts, NULL));
        bin_trial(n1, n2, pat->k, pts, NULL, s);
        double est = 0.0;
        for (size_t i = 0; i < n1 * n2; ++i)
            est += f[i] * s[i] / (double)pat->k;
        double d2 = (est - mu) * (est - mu);
        c2 += d2 / trials;
        c4 += d2 * d2 / trials;
        if (want_cross) {
            double ar, ai, br, bi;
            dft_at(n1, n2, s, ab[0], ab[1], &ar, &ai);
            dft_at(n1, n2, s, ab[2], ab[3], &br, &bi);
            double cr = ar * br + ai * bi, ci = ai * br - ar * bi; /* S_a S_b^* */
            x_re += cr / trials;
            x_im += ci / trials;
            x_re2 += cr * cr / trials;
            x_im2 += ci * ci / trials;
        }
    }
}

static void assert_spectrum_matches_exact(const mcs_pattern2d *pat, size_t n1, size_t n2)
{
    for (size_t k2 = 0; k2 < n2; ++k2)
        for (size_t k1 = 0; k1 < n1; ++k1) {
            double p = 0.0, se = 0.0, ex = 0.0, mr = 0.0, mi = 0.0, mse = 0.0, er = 0.0, ei = 0.0;
            mcs_spectrum2d_power(&acc, k1, k2, &p);
            mcs_spectrum2d_power_stderr(&acc, k1, k2, &se);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_exact_power(pat, n1, n2, k1, k2, &ex));
            TEST_ASSERT_DOUBLE_WITHIN(5.0 * se + 1e-9 * pat->k, ex, p);
            mcs_spectrum2d_mean(&acc, k1, k2, &mr, &mi);
            mcs_spectrum2d_mean_stderr(&acc, k1, k2, &mse);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_exact_mean(pat, n1, n2, k1, k2, &er, &ei));
            TEST_ASSERT_DOUBLE_WITHIN(5.0 * mse + 1e-9 * pat->k, er, mr);
            TEST_ASSERT_DOUBLE_WITHIN(5.0 * mse + 1e-9 * pat->k, ei, mi);
        }
}

/* The measured <(I - mu)^2> against the exact eq. 13, within 5 standard
 * errors sqrt((c4 - c2^2) / T). */
static void assert_variance_matches_exact(const mcs_pattern2d *pat, size_t n1, size_t n2,
                                          int trials)
{
    double v13 = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_transform(&acc, f, fr, fi));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_exact_variance(pat, n1, n2, fr, fi, &v13));
    TEST_ASSERT_TRUE(v13 > 0.0);
    TEST_ASSERT_DOUBLE_WITHIN(5.0 * sqrt((c4 - c2 * c2) / trials), v13, c2);
}

static void test_measured_binned_spectra_match_the_exact_theory(void)
{
    mcs_pattern2d p = points_pattern2d(MCS_PATTERN2D_RANDOM, 6u, 0u, 0u);
    lumpy(5u, 7u, f);
    run_trials(&p, 5u, 7u, 20000, 1u, 0, NULL);
    assert_spectrum_matches_exact(&p, 5u, 7u);
    p = points_pattern2d(MCS_PATTERN2D_JITTERED, 6u, 2u, 3u);
    run_trials(&p, 4u, 6u, 20000, 2u, 0, NULL);
    assert_spectrum_matches_exact(&p, 4u, 6u);
    p = points_pattern2d(MCS_PATTERN2D_SHIFTED_GRID, 6u, 2u, 3u);
    run_trials(&p, 4u, 6u, 5000, 3u, 0, NULL);
    assert_spectrum_matches_exact(&p, 4u, 6u);
}

/* Jittered is not stationary: S_k and S_l correlate when k = l mod (m, n). */
static void test_jittered_cross_spectrum_off_the_diagonal_matches_the_exact_covariance(void)
{
    const size_t n1 = 6u, n2 = 4u;
    mcs_pattern2d p = points_pattern2d(MCS_PATTERN2D_JITTERED, 4u, 2u, 2u);
    const size_t ab[4] = {1u, 1u, 3u, 3u}; /* (1, 1) and (3, 3): same class mod (2, 2) */
    lumpy(n1, n2, f);
    run_trials(&p, n1, n2, 40000, 4u, 1, ab);
    double er = 0.0, ei = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK,
                          mcs_spectrum2d_exact_covariance(&p, n1, n2, 1u, 1u, 3u, 3u, &er, &ei));
    TEST_ASSERT_TRUE(fabs(er) + fabs(ei) > 0.01); /* a real off-diagonal term */
    double se_r = sqrt((x_re2 - x_re * x_re) / 40000.0);
    double se_i = sqrt((x_im2 - x_im * x_im) / 40000.0);
    TEST_ASSERT_DOUBLE_WITHIN(5.0 * se_r, er, x_re);
    TEST_ASSERT_DOUBLE_WITHIN(5.0 * se_i, ei, x_im);
    TEST_ASSERT_EQUAL_INT(MCS_OK,
                          mcs_spectrum2d_exact_covariance(&p, n1, n2, 1u, 0u, 2u, 0u, &er, &ei));
    TEST_ASSERT_EQUAL_DOUBLE(0.0, er); /* different classes: uncorrelated */
    TEST_ASSERT_EQUAL_DOUBLE(0.0, ei);
}

/* Trials of pat on n1 x n2 bins, the measured Var[I] of the integrand f
 * checked against the exact eq. 13, and the exact eq. 13 and eq. 14 out. */
static void exact_variances(const mcs_pattern2d *pat, size_t n1, size_t n2, int trials,
                            uint64_t seed, double *v13, double *v14)
{
    run_trials(pat, n1, n2, trials, seed, 0, NULL);
    assert_variance_matches_exact(pat, n1, n2, trials);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_exact_variance(pat, n1, n2, fr, fi, v13));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_exact_variance14(pat, n1, n2, fr, fi, v14));
}

static void test_exact_variance_matches_monte_carlo_and_eq_14_only_for_stationary_kinds(void)
{
    const int T = 40000;
    mcs_pattern2d p = points_pattern2d(MCS_PATTERN2D_RANDOM, 6u, 0u, 0u);
    lumpy(5u, 7u, f);
    double v13 = 0.0, v14 = 0.0, vm = 0.0;
    exact_variances(&p, 5u, 7u, T, 5u, &v13, &v14);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * v13, v13, v14);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_variance14(&acc, 6u, fr, fi, &vm));
    TEST_ASSERT_DOUBLE_WITHIN(0.05 * v14, v14, vm);

    lumpy(8u, 6u, f);
    p = points_pattern2d(MCS_PATTERN2D_SHIFTED_GRID, 6u, 2u, 3u);
    exact_variances(&p, 8u, 6u, T, 6u, &v13, &v14);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * v13, v13, v14);

    p = points_pattern2d(MCS_PATTERN2D_JITTERED, 6u, 2u, 3u);
    exact_variances(&p, 8u, 6u, T, 7u, &v13, &v14);
    TEST_ASSERT_TRUE(fabs(v14 - v13) > 0.05 * v13); /* the cross terms matter */
}

/* Independent check: Var[I] by enumerating every equally likely trial. */
static double enumerate_variance(const mcs_pattern2d *p, size_t n1, size_t n2)
{
    const size_t m = p->strata_x, a = n1 / m, b = n2 / p->strata_y, k = p->k;
    double sum = 0.0, sum2 = 0.0, count = 0.0;
    size_t configs = 1u;
    for (size_t j = 0; j < k; ++j)
        configs *= p->kind == MCS_PATTERN2D_RANDOM ? n1 * n2 : a * b;
    if (p->kind == MCS_PATTERN2D_SHIFTED_GRID)
        configs = a * b;
    for (size_t c = 0; c < configs; ++c) {
        double est = 0.0;
        size_t code = c;
        for (size_t j = 0; j < k; ++j) {
            size_t b1, b2;
            if (p->kind == MCS_PATTERN2D_RANDOM) {
                b1 = code % n1;
                b2 = (code / n1) % n2;
                code /= n1 * n2;
            } else {
                size_t off = p->kind == MCS_PATTERN2D_SHIFTED_GRID ? c : code % (a * b);
                b1 = (j % m) * a + off % a;
                b2 = (j / m) * b + off / a;
                code /= a * b;
            }
            est += f[b2 * n1 + b1] / (double)k;
        }
        sum += est;
        sum2 += est * est;
        count += 1.0;
    }
    return sum2 / count - (sum / count) * (sum / count);
}

static void test_exact_variance_equals_enumeration_on_tiny_grids(void)
{
    const mcs_pattern2d_kind kinds[3] = {MCS_PATTERN2D_RANDOM, MCS_PATTERN2D_JITTERED,
                                         MCS_PATTERN2D_SHIFTED_GRID};
    for (int c = 0; c < 3; ++c) {
        const size_t n1 = 4u, n2 = 2u;
        mcs_pattern2d p = points_pattern2d(kinds[c], 2u, 2u, 1u);
        lumpy(n1, n2, f);
        TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, n1, n2));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_transform(&acc, f, fr, fi));
        double v = 0.0, e = enumerate_variance(&p, n1, n2);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_exact_variance(&p, n1, n2, fr, fi, &v));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12 * e + 1e-15, e, v);
    }
}

static void test_merge_of_halves_equals_one_pass(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 8u, 8u);
    init(&acc, 5u, 4u);
    init(&acc2, 5u, 4u);
    init(&acc3, 5u, 4u);
    for (int t = 0; t < 100; ++t) {
        points_uniform(&rng, 10u, pts);
        mcs_spectrum2d_add_points(&acc, 5u, pts, NULL);
        mcs_spectrum2d_add_points(t < 30 ? &acc2 : &acc3, 5u, pts, NULL);
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_merge(&acc2, &acc3));
    uint64_t n = 0u;
    mcs_spectrum2d_count(&acc2, &n);
    TEST_ASSERT_EQUAL_UINT64(100u, n);
    for (size_t k2 = 0; k2 < 4u; ++k2)
        for (size_t k1 = 0; k1 < 5u; ++k1) {
            double a = 0.0, b = 0.0, sa = 0.0, sb = 0.0, ar = 0.0, ai = 0.0, br = 0.0, bi = 0.0;
            mcs_spectrum2d_power(&acc, k1, k2, &a);
            mcs_spectrum2d_power(&acc2, k1, k2, &b);
            mcs_spectrum2d_power_stderr(&acc, k1, k2, &sa);
            mcs_spectrum2d_power_stderr(&acc2, k1, k2, &sb);
            points_assert_merged(a, sa, b, sb);
            mcs_spectrum2d_mean(&acc, k1, k2, &ar, &ai);
            mcs_spectrum2d_mean(&acc2, k1, k2, &br, &bi);
            mcs_spectrum2d_mean_stderr(&acc, k1, k2, &sa);
            mcs_spectrum2d_mean_stderr(&acc2, k1, k2, &sb);
            points_assert_merged(ar, sa, br, sb);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12, ai, bi);
        }
}

static void test_bad_input_returns_an_error_and_changes_nothing(void)
{
    double re = -1.0, im = -1.0;
    memset(&o_acc2, 0, sizeof o_acc2);
    o_snap = o_acc2;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spectrum2d_init(NULL, 4u, 4u, o_acc2.mem, sizeof o_acc2.mem));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spectrum2d_init(&acc2, 4u, 4u, NULL, sizeof o_acc2.mem));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, init(&acc2, 0u, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_spectrum2d_init(&acc2, 4u, MCS_SPECTRUM2D_MAX_SIDE + 1u,
                                                               o_acc2.mem, SIZE_MAX));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, init(&acc2, 128u, 64u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_spectrum2d_init((mcs_spectrum2d *)(void *)o_acc2.mem, 4u, 4u,
                                                             o_acc2.mem, sizeof o_acc2.mem));
    TEST_ASSERT_EQUAL_MEMORY(&o_snap, &o_acc2, sizeof o_acc2);
    size_t bytes = 0u;
    for (size_t n1 = 1u; n1 <= 70u; n1 += 3u)
        for (size_t n2 = 1u; n2 <= 70u; n2 += 5u) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_size(n1, n2, &bytes));
            TEST_ASSERT_EQUAL_UINT64((uint64_t)MCS_SPECTRUM2D_SIZE(n1, n2), (uint64_t)bytes);
        }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_size(MCS_SPECTRUM2D_MAX_SIDE, MCS_SPECTRUM2D_MAX_SIDE, &bytes));
    TEST_ASSERT_EQUAL_UINT64((uint64_t)MCS_SPECTRUM2D_SIZE(MCS_SPECTRUM2D_MAX_SIDE, MCS_SPECTRUM2D_MAX_SIDE), (uint64_t)bytes);
    TEST_ASSERT_TRUE(bytes < (size_t)512 << 20); /* fits a 32-bit size_t */

    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 4u, 3u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_spectrum2d_power(&acc, 1u, 1u, &re));
    pts[0] = 0.1;
    pts[1] = 0.2;
    pts[2] = 0.7;
    pts[3] = 0.9;
    w[0] = 1.0;
    w[1] = 2.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points(&acc, 2u, pts, w));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_spectrum2d_power_stderr(&acc, 1u, 1u, &re));
    o_snap = o_acc;
    w[1] = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NEGATIVE, mcs_spectrum2d_add_points(&acc, 2u, pts, w));
    w[1] = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_spectrum2d_add_points(&acc, 2u, pts, w));
    pts[3] = 1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_spectrum2d_add_points(&acc, 2u, pts, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_spectrum2d_add_points(&acc, 0u, pts, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spectrum2d_add_points(&acc, 2u, NULL, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_spectrum2d_add_points(&acc2, 2u, pts, NULL));
    init(&acc3, 3u, 4u);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_spectrum2d_merge(&acc, &acc3));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_spectrum2d_merge(&acc, &acc2));
    s[0] = INFINITY;
    fr[0] = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NOT_FINITE, mcs_spectrum2d_transform(&acc, s, fr, fi));
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, fr[0]);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_spectrum2d_add_points(&acc, 2u, acc.re, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_spectrum2d_add_points(&acc, 2u, pts, acc.im));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spectrum2d_add_points_planar(&acc, 2u, pts, NULL, NULL));
    TEST_ASSERT_EQUAL_MEMORY(&o_snap, &o_acc, sizeof o_acc);

    re = im = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_spectrum2d_mean(&acc, 4u, 0u, &re, &im));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_spectrum2d_power(&acc, 0u, 3u, &re));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_spectrum2d_power(&acc2, 0u, 0u, &re));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_spectrum2d_variance14(&acc, 0u, fr, fi, &re));
    mcs_pattern2d p = points_pattern2d(MCS_PATTERN2D_JITTERED, 6u, 2u, 3u);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_spectrum2d_exact_power(&p, 5u, 6u, 1u, 1u, &re));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_spectrum2d_exact_power(&p, 4u, 0u, 1u, 1u, &re));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_spectrum2d_exact_power(&p, 4u, 6u, 4u, 1u, &re));
    p = points_pattern2d(MCS_PATTERN2D_NROOKS, 6u, 2u, 3u);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_spectrum2d_exact_power(&p, 4u, 6u, 1u, 1u, &re));
    p = points_pattern2d(MCS_PATTERN2D_GRID, 6u, 2u, 3u);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_spectrum2d_exact_variance(&p, 4u, 6u, fr, fi, &re));
    p.strata_x = 4u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT,
                          mcs_spectrum2d_exact_covariance(&p, 4u, 6u, 0u, 0u, 0u, 0u, &re, &im));
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, re);
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, im);
}


/* Planar points give the bits of interleaved ones (double and float); the
 * wrapped 1.0 falls in bin 0 and 1.5, -0.1, NaN stay refused; a copy reads
 * out like the original over its own buffer. */
static void test_planar_wrapped_and_copied_2d_spectra(void)
{
    enum { K = 40 };
    static double xy[2 * K], xs[K], ys[K], zero[2 * K];
    static float xyf[2 * K], xsf[K], ysf[K];
    static obj b, c, d;
    mcs_rng rng;
    mcs_rng_seed(&rng, 21u, 21u);
    for (size_t j = 0; j < K; ++j) {
        double u = 0.0, v = 0.0;
        mcs_rng_double(&rng, &u);
        mcs_rng_double(&rng, &v);
        xsf[j] = xyf[2u * j] = j % 5u == 1u ? 1.0f : (float)u < 1.0f ? (float)u : 0.25f;
        ysf[j] = xyf[2u * j + 1u] = (float)v < 1.0f ? (float)v : 0.25f;
        xs[j] = xy[2u * j] = (double)xsf[j];
        ys[j] = xy[2u * j + 1u] = (double)ysf[j];
        zero[2u * j] = xs[j] == 1.0 ? 0.0 : xs[j];
        zero[2u * j + 1u] = ys[j];
        w[j] = 0.5 + 0.01 * (double)j;
    }
    obj *const all[4] = {&o_acc, &b, &c, &d};
    for (int i = 0; i < 4; ++i) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, init(&all[i]->h, 7u, 6u));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_spectrum2d_add_points(&all[i]->h, K, xy, w));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_spectrum2d_set_wrap(&all[i]->h, -1));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_set_wrap(&all[i]->h, i < 3 ? 1 : 0));
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points(&acc, K, xy, w));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points_planar(&b.h, K, xs, ys, w));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points_planar_f(&c.h, K, xsf, ysf, w));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points(&d.h, K, zero, w));
    const size_t cells = 8u * 4u;
    for (int i = 1; i < 4; ++i) {
        TEST_ASSERT_EQUAL_MEMORY(acc.mean_re, all[i]->h.mean_re, cells * sizeof(double));
        TEST_ASSERT_EQUAL_MEMORY(acc.mean_im, all[i]->h.mean_im, cells * sizeof(double));
        TEST_ASSERT_EQUAL_MEMORY(acc.mean_pow, all[i]->h.mean_pow, cells * sizeof(double));
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points_f(&c.h, K, xyf, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_add_points_planar(&b.h, K, xs, ys, NULL));
    TEST_ASSERT_EQUAL_MEMORY(b.h.m2_pow, c.h.m2_pow, cells * sizeof(double));
    o_snap = o_acc;
    const double bad[3] = {1.5, -0.1, NAN};
    for (int i = 0; i < 3; ++i) {
        xy[3] = bad[i];
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_spectrum2d_add_points(&acc, K, xy, w));
    }
    TEST_ASSERT_EQUAL_MEMORY(&o_snap, &o_acc, sizeof o_acc);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_spectrum2d_copy(&acc2, o_acc.mem, sizeof o_acc.mem, &acc));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_copy(&acc2, o_acc2.mem, sizeof o_acc2.mem, &acc));
    for (size_t k2 = 0; k2 < 6u; ++k2)
        for (size_t k1 = 0; k1 < 7u; ++k1) {
            double x1 = 0.0, x2 = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_power(&acc, k1, k2, &x1));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_power(&acc2, k1, k2, &x2));
            TEST_ASSERT_EQUAL_DOUBLE(x1, x2);
        }
    mcs_spectrum2d shared = acc2;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_spectrum2d_merge(&acc2, &shared));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_merge(&acc2, &acc));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_transform_is_the_2d_eq_7);
    RUN_TEST(test_one_trial_gives_the_transform_of_its_weighted_bin_counts);
    RUN_TEST(test_measured_binned_spectra_match_the_exact_theory);
    RUN_TEST(test_jittered_cross_spectrum_off_the_diagonal_matches_the_exact_covariance);
    RUN_TEST(test_exact_variance_matches_monte_carlo_and_eq_14_only_for_stationary_kinds);
    RUN_TEST(test_exact_variance_equals_enumeration_on_tiny_grids);
    RUN_TEST(test_merge_of_halves_equals_one_pass);
    RUN_TEST(test_bad_input_returns_an_error_and_changes_nothing);
    RUN_TEST(test_planar_wrapped_and_copied_2d_spectra);
    return UNITY_END();
}
