/* Tests of the integration-error accumulator (integrate.h) and the
 * prediction from the spectrum (integrand.h), with fixed seeds: the
 * measured MSE of random and jittered sets within 5 standard errors of the
 * exact MSE for every family in 1D and 2D; the point-set eq. 14 prediction
 * from the measured mean periodogram, for the periodic families, below the
 * measured MSE by at most 5 standard errors and above it by at most its
 * tail bound plus 5; convergence slopes fitted over growing K within 0.1 of
 * the published rates (random K^-1; jittered K^-2 smooth and K^-1.5
 * discontinuous in 2D, K^-3 and K^-2 in 1D), from the exact MSE at large K
 * and from the measured MSE at small K; merge of halves against one pass;
 * bad input that changes nothing. */
#include "mcspec.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define MAX_K 1024
#define M 4 /* integrands per set */
static double pts[2 * MAX_K];

static const mcs_integrand_family families[] = {
    MCS_INTEGRAND_GAUSSIAN, MCS_INTEGRAND_GAUSSIAN_PERIODIC, MCS_INTEGRAND_HEAVISIDE,
    MCS_INTEGRAND_DISK, MCS_INTEGRAND_COSINE};
#define NFAM (sizeof families / sizeof families[0])

/* One set of k points: random, or the jittered grid of mx x my cells
 * (1D: k cells). */
static void draw_set(mcs_rng *rng, size_t dim, int jittered, size_t mx, size_t k)
{
    for (size_t j = 0; j < k; ++j)
        for (size_t d = 0; d < dim; ++d) {
            double u;
            mcs_rng_double(rng, &u);
            if (jittered) {
                const size_t cell = d == 0 ? j % mx : j / mx, n = d == 0 ? mx : k / mx;
                u = ((double)cell + u) / (double)n;
                if (u >= 1.0)
                    u = nextafter(1.0, 0.0);
            }
            pts[j * dim + d] = u;
        }
}

static void draw_integrands(mcs_rng *rng, mcs_integrand_family fam, size_t dim, mcs_integrand *fs,
                            size_t m)
{
    for (size_t i = 0; i < m; ++i)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_draw(&fs[i], fam, dim, rng));
}

/* T sets of k points (fresh integrands each) into acc. */
static void run(mcs_integrate *acc, mcs_rng *rng, size_t dim, int jittered, size_t mx, size_t k,
                size_t sets)
{
    mcs_integrand fs[M];
    for (size_t t = 0; t < sets; ++t) {
        draw_set(rng, dim, jittered, mx, k);
        draw_integrands(rng, acc->family, dim, fs, M);
        TEST_ASSERT_EQUAL_INT(MCS_OK,
                              mcs_integrate_add(acc, M, fs, k, pts,
                                                jittered ? MCS_INTEGRATE_JITTERED : MCS_INTEGRATE_RANDOM,
                                                mx, dim == 2u ? k / mx : 1u));
    }
}

static double z_of(const mcs_integrate *acc)
{
    double mse, se, ex;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_mse(acc, &mse));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_mse_stderr(acc, &se));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_exact(acc, &ex));
    return (mse - ex) / se;
}

static void test_measured_mse_is_within_5_stderr_of_exact(void)
{
    double zmax = 0.0;
    for (size_t dim = 1; dim <= 2; ++dim)
        for (size_t fi = 0; fi < NFAM; ++fi)
            for (int jit = 0; jit <= 1; ++jit) {
                mcs_integrate acc;
                mcs_rng rng;
                mcs_rng_seed(&rng, 2025u + fi, 11u + dim + 2u * (size_t)jit);
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_init(&acc, families[fi], dim));
                const size_t k = 64u, mx = dim == 2u ? 8u : 64u;
                run(&acc, &rng, dim, jit, mx, k, 600u);
                const double z = z_of(&acc);
                char msg[80];
                snprintf(msg, sizeof msg, "%s %zuD %s: z = %.2f", mcs_integrand_family_str(families[fi]),
                         dim, jit ? "jittered" : "random", z);
                TEST_ASSERT_TRUE_MESSAGE(fabs(z) < 5.0, msg);
                zmax = fmax(zmax, fabs(z));
            }
    printf("largest |z| over 20 cases: %.2f\n", zmax);
}

/* The prediction from the measured <P(k)> of the same sets. */
static void test_prediction_brackets_the_measured_mse(void)
{
    const mcs_integrand_family periodic[3] = {MCS_INTEGRAND_GAUSSIAN_PERIODIC, MCS_INTEGRAND_DISK,
                                              MCS_INTEGRAND_COSINE};
    enum { T = 400, F = 24 };
    static unsigned char mem[MCS_POINTSET2D_SIZE_DIRECT(F)];
    static unsigned char mem1[MCS_POINTSET_SIZE_DIRECT(4 * F)];
    static mcs_integrand all[T * M];
    for (size_t dim = 1; dim <= 2; ++dim)
        for (int fi = 0; fi < 3; ++fi)
            for (int jit = 0; jit <= 1; ++jit) {
                mcs_pointset2d ps;
                mcs_pointset ps1;
                mcs_integrate acc;
                mcs_rng rng;
                mcs_rng_seed(&rng, 77u + (uint64_t)fi, 5u + dim + 2u * (uint64_t)jit);
                if (dim == 2u)
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&ps, F, MCS_POINTSET_DIRECT_ONLY,
                                                                      mem, sizeof mem));
                else
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&ps1, 4 * F, MCS_POINTSET_DIRECT_ONLY,
                                                                    mem1, sizeof mem1));
                mcs_integrate_init(&acc, periodic[fi], dim);
                const size_t k = 64u, mx = dim == 2u ? 8u : 64u;
                for (size_t t = 0; t < T; ++t) {
                    draw_set(&rng, dim, jit, mx, k);
                    draw_integrands(&rng, periodic[fi], dim, &all[t * M], M);
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_add(&acc, M, &all[t * M], k, pts,
                                                                    MCS_INTEGRATE_NONE, 0, 0));
                    if (dim == 2u)
                        mcs_pointset2d_add(&ps, k, pts);
                    else
                        mcs_pointset_add(&ps1, k, pts);
                }
                double pred = NAN, tail = NAN, mse, se;
                if (dim == 2u)
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_predict(all, T * M, &ps, k, &pred, &tail));
                else
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_predict_1d(all, T * M, &ps1, k, &pred, &tail));
                mcs_integrate_mse(&acc, &mse);
                mcs_integrate_mse_stderr(&acc, &se);
                char msg[160];
                snprintf(msg, sizeof msg, "%s %zuD %s: mse %.4g se %.2g pred %.4g tail %.2g (z %.2f)",
                         mcs_integrand_family_str(periodic[fi]), dim, jit ? "jittered" : "random", mse,
                         se, pred, tail, (mse - pred) / se);
                printf("%s\n", msg);
                TEST_ASSERT_TRUE_MESSAGE(mse > pred - 5.0 * se, msg);
                TEST_ASSERT_TRUE_MESSAGE(mse < pred + tail + 5.0 * se, msg);
                /* smooth families: what F leaves out is rounding (exp(-4 pi^2 s^2 F^2), or none) */
                if (periodic[fi] != MCS_INTEGRAND_DISK) {
                    TEST_ASSERT_TRUE_MESSAGE(tail < 1e-9 * pred, msg);
                }
            }
}

/* Least-squares slope of log y against log x. */
static double slope(const double *x, const double *y, size_t n)
{
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (size_t i = 0; i < n; ++i) {
        const double a = log(x[i]), b = log(y[i]);
        sx += a;
        sy += b;
        sxx += a * a;
        sxy += a * b;
    }
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

static double rate(mcs_integrand_family fam, size_t dim)
{
    const int smooth = fam != MCS_INTEGRAND_HEAVISIDE && fam != MCS_INTEGRAND_DISK;
    return dim == 2u ? (smooth ? -2.0 : -1.5) : (smooth ? -3.0 : -2.0);
}

static void test_exact_jittered_slopes_match_the_published_rates(void)
{
    for (size_t dim = 1; dim <= 2; ++dim)
        for (size_t fi = 0; fi < NFAM; ++fi) {
            double ks[4], mse[4];
            for (int s = 0; s < 4; ++s) {
                const size_t m = dim == 2u ? (16u << s) : (64u << (2 * s)); /* K = 256 .. 16384 */
                mcs_rng rng;
                mcs_rng_seed(&rng, 3u, 9u);
                double sum = 0.0;
                for (int i = 0; i < 32; ++i) {
                    mcs_integrand f;
                    double v;
                    mcs_integrand_draw(&f, families[fi], dim, &rng);
                    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrand_jittered_mse(&f, m, dim == 2u ? m : 1u, &v));
                    sum += v;
                }
                ks[s] = dim == 2u ? (double)(m * m) : (double)m;
                mse[s] = sum / 32.0;
            }
            const double b = slope(ks, mse, 4);
            char msg[80];
            snprintf(msg, sizeof msg, "%s %zuD: slope %.3f", mcs_integrand_family_str(families[fi]), dim, b);
            TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(0.1, rate(families[fi], dim), b, msg);
        }
}

/* Measured slopes at affordable sizes: K = 64, 256, 1024 in 2D. */
static void test_measured_slopes_match_the_published_rates(void)
{
    const struct {
        mcs_integrand_family fam;
        int jit;
        double rate;
    } cases[] = {{MCS_INTEGRAND_GAUSSIAN, 0, -1.0},  {MCS_INTEGRAND_HEAVISIDE, 0, -1.0},
                 {MCS_INTEGRAND_GAUSSIAN, 1, -2.0},  {MCS_INTEGRAND_GAUSSIAN_PERIODIC, 1, -2.0},
                 {MCS_INTEGRAND_HEAVISIDE, 1, -1.5}, {MCS_INTEGRAND_DISK, 1, -1.5}};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        double ks[3], mse[3];
        for (int s = 0; s < 3; ++s) {
            const size_t m = 8u << s, k = m * m;
            mcs_integrate acc;
            mcs_rng rng;
            mcs_rng_seed(&rng, 31u + c, 1u + (uint64_t)s);
            mcs_integrate_init(&acc, cases[c].fam, 2u);
            run(&acc, &rng, 2u, cases[c].jit, m, k, 1024u >> (2 * s) > 64u ? 1024u >> (2 * s) : 64u);
            ks[s] = (double)k;
            mcs_integrate_mse(&acc, &mse[s]);
        }
        const double b = slope(ks, mse, 3);
        char msg[80];
        snprintf(msg, sizeof msg, "%s %s: slope %.3f", mcs_integrand_family_str(cases[c].fam),
                 cases[c].jit ? "jittered" : "random", b);
        printf("%s\n", msg);
        TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(0.1, cases[c].rate, b, msg);
    }
}

static void test_merge_of_halves_equals_one_pass(void)
{
    mcs_integrate one, a, b;
    mcs_rng r1, r2;
    mcs_rng_seed(&r1, 8u, 8u);
    mcs_rng_seed(&r2, 8u, 8u);
    mcs_integrate_init(&one, MCS_INTEGRAND_DISK, 2u);
    mcs_integrate_init(&a, MCS_INTEGRAND_DISK, 2u);
    mcs_integrate_init(&b, MCS_INTEGRAND_DISK, 2u);
    run(&one, &r1, 2u, 1, 4u, 16u, 40u);
    run(&a, &r2, 2u, 1, 4u, 16u, 15u);
    run(&b, &r2, 2u, 1, 4u, 16u, 25u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_merge(&a, &b));
    double x, y;
    uint64_t n;
    mcs_integrate_count(&a, &n);
    TEST_ASSERT_EQUAL_UINT64(40u, n);
    mcs_integrate_mse(&one, &x);
    mcs_integrate_mse(&a, &y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14 * x, x, y);
    mcs_integrate_exact(&one, &x);
    mcs_integrate_exact(&a, &y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-14 * x, x, y);
    mcs_integrate_mse_stderr(&one, &x);
    mcs_integrate_mse_stderr(&a, &y);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * x, x, y);
}

static void test_bad_input_is_refused_and_changes_nothing(void)
{
    mcs_integrate acc, before, other;
    mcs_rng rng;
    mcs_rng_seed(&rng, 4u, 4u);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_integrate_init(&acc, MCS_INTEGRAND_FAMILIES, 2u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_integrate_init(&acc, MCS_INTEGRAND_DISK, 0u));
    mcs_integrate_init(&acc, MCS_INTEGRAND_DISK, 2u);
    double out = 5.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_integrate_mse(&acc, &out));
    run(&acc, &rng, 2u, 0, 4u, 16u, 3u);
    before = acc;
    mcs_integrand fs[M];
    draw_integrands(&rng, MCS_INTEGRAND_DISK, 2u, fs, M);
    draw_set(&rng, 2u, 0, 4u, 16u);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_integrate_add(&acc, M, NULL, 16u, pts, MCS_INTEGRATE_NONE, 0, 0));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_integrate_add(&acc, 0u, fs, 16u, pts, MCS_INTEGRATE_NONE, 0, 0));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_integrate_add(&acc, M, fs, 16u, pts, MCS_INTEGRATE_JITTERED, 4u, 3u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_integrate_add(&acc, M, fs, 16u, pts, (mcs_integrate_reference)7, 0, 0));
    pts[5] = 1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_integrate_add(&acc, M, fs, 16u, pts, MCS_INTEGRATE_NONE, 0, 0));
    pts[5] = 0.5;
    fs[2].width = 0.45;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_integrate_add(&acc, M, fs, 16u, pts, MCS_INTEGRATE_NONE, 0, 0));
    draw_integrands(&rng, MCS_INTEGRAND_GAUSSIAN, 2u, fs, M);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_integrate_add(&acc, M, fs, 16u, pts, MCS_INTEGRATE_NONE, 0, 0));
    TEST_ASSERT_EQUAL_MEMORY(&before, &acc, sizeof acc);
    mcs_integrate_init(&other, MCS_INTEGRAND_DISK, 1u);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_integrate_merge(&acc, &other));
    acc.sq.m2 = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_integrate_mse(&acc, &out));
    acc = before;
    /* one set without a reference: no exact column */
    draw_integrands(&rng, MCS_INTEGRAND_DISK, 2u, fs, M);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_integrate_add(&acc, M, fs, 16u, pts, MCS_INTEGRATE_NONE, 0, 0));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_integrate_exact(&acc, &out));
    TEST_ASSERT_EQUAL_DOUBLE(5.0, out);
    /* the prediction of a non-periodic family does not apply */
    static unsigned char mem[MCS_POINTSET2D_SIZE_DIRECT(4)];
    mcs_pointset2d ps;
    mcs_pointset2d_init(&ps, 4u, MCS_POINTSET_DIRECT_ONLY, mem, sizeof mem);
    double p = 1.0, t = 2.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_integrand_predict(fs, M, &ps, 16u, &p, &t));
    mcs_pointset2d_add(&ps, 16u, pts);
    draw_integrands(&rng, MCS_INTEGRAND_GAUSSIAN, 2u, fs, M);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_integrand_predict(fs, M, &ps, 16u, &p, &t));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_integrand_predict(fs, M, &ps, 16u, &p, &p));
    TEST_ASSERT_EQUAL_DOUBLE(1.0, p);
    TEST_ASSERT_EQUAL_DOUBLE(2.0, t);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_measured_mse_is_within_5_stderr_of_exact);
    RUN_TEST(test_prediction_brackets_the_measured_mse);
    RUN_TEST(test_exact_jittered_slopes_match_the_published_rates);
    RUN_TEST(test_measured_slopes_match_the_published_rates);
    RUN_TEST(test_merge_of_halves_equals_one_pass);
    RUN_TEST(test_bad_input_is_refused_and_changes_nothing);
    return UNITY_END();
}
