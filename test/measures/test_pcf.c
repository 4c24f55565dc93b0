/* Tests of the pair correlation (pcf.h): psa's RDF against a direct count
 * of every pair (bit for bit, on the cell-grid path and the all-pairs
 * path), the Gaussian-kernel PCF against a direct sum (to rounding), both
 * in 1D and 2D; random sets give E g = 1 (RDF) and the kernel's exact
 * random curve within 5 standard errors, with fixed seeds, which psa's
 * normalisation by K^2 or a ring of the wrong area fails; the merge of two
 * halves equals one pass; the radial power from the RDF against an
 * independent Bessel series; bad input changes nothing. */
#include "mcspec.h"
#include "points_ref.h"
#include "unity.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define MAX_K 2048
#define MAX_BINS 64
static double pts[2 * MAX_K];
static unsigned char work[MCS_PCF_WORK_SIZE(MAX_K) + 8];
static unsigned char mem_a[MCS_PCF_SIZE(MAX_BINS) + 3], mem_b[MCS_PCF_SIZE(MAX_BINS) + 5];

static const double pi = 3.14159265358979323846;

static mcs_pcf make(unsigned char *mem, size_t dim, mcs_pcf_estimator e, size_t bins, double r,
                    double sigma)
{
    mcs_pcf acc;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_init(&acc, dim, e, bins, r, sigma, mem + 1,
                                               MCS_PCF_SIZE(bins)));
    return acc;
}

static void add(mcs_pcf *acc, size_t k, const double *p)
{
    size_t need = 0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_work_size(acc, k, &need));
    TEST_ASSERT_TRUE(need <= MCS_PCF_WORK_SIZE(k));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_add(acc, k, p, work + 3, need));
}

static double mean(const mcs_pcf *acc, size_t b)
{
    double v = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_mean(acc, b, &v));
    return v;
}

static double stderr_of(const mcs_pcf *acc, size_t b)
{
    double v = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_stderr(acc, b, &v));
    return v;
}

static double spacing(size_t dim, size_t k)
{
    return dim == 1u ? 1.0 / (double)k : 1.0 / sqrt((double)k);
}

static double torus_dist(size_t dim, const double *a, const double *b)
{
    double d2 = 0.0;
    for (size_t i = 0; i < dim; ++i) {
        double t = fabs(a[i] - b[i]);
        t = t > 0.5 ? 1.0 - t : t;
        d2 += t * t;
    }
    return sqrt(d2);
}

/* psa's RDF by a direct count over the pairs i < j, pcf.h's formula. */
static void brute_rdf(size_t dim, size_t k, const double *p, size_t bins, double r, double *g)
{
    const double s = spacing(dim, k), w = r / (double)bins * s, scale = (double)bins / (r * s);
    double c[MAX_BINS] = {0};
    for (size_t i = 0; i < k; ++i)
        for (size_t j = i + 1; j < k; ++j) {
            const double u = torus_dist(dim, p + i * dim, p + j * dim) * scale;
            if (u < (double)bins)
                c[(size_t)u] += 1.0;
        }
    for (size_t b = 0; b < bins; ++b) {
        const double r0 = (double)b * w, r1 = (double)(b + 1u) * w;
        const double area = dim == 1u ? 2.0 * (r1 - r0) : pi * (r1 * r1 - r0 * r0);
        g[b] = 2.0 * c[b] / ((double)k * (double)(k - 1u) * area);
    }
}

/* The kernel PCF by a direct sum over every pair (no cutoff), long double. */
static void brute_kernel(size_t dim, size_t k, const double *p, size_t bins, double r,
                         double sigma, double *g)
{
    const double s = spacing(dim, k), w = r / (double)bins * s, sg = sigma * s;
    for (size_t b = 0; b < bins; ++b) {
        const double rb = ((double)b + 0.5) * w;
        long double sum = 0.0L;
        for (size_t i = 0; i < k; ++i)
            for (size_t j = i + 1; j < k; ++j) {
                const double t = rb - torus_dist(dim, p + i * dim, p + j * dim);
                sum += 2.0L * expl(-0.5L * (long double)(t * t) / ((long double)sg * sg)) /
                       ((long double)sg * sqrtl(2.0L * 3.14159265358979323846264L));
            }
        const double surf = dim == 1u ? 2.0 : 2.0 * pi * rb;
        g[b] = (double)(sum / ((long double)k * (long double)(k - 1u) * surf));
    }
}

static void test_the_rdf_equals_a_direct_pair_count_bit_for_bit(void)
{
    static const size_t ks[] = {2, 7, 15, 16, 100, 1000, 2048};
    mcs_rng rng;
    mcs_rng_seed(&rng, 25u, 1u);
    int grid = 0, brute = 0;
    for (size_t dim = 1; dim <= 2u; ++dim)
        for (size_t a = 0; a < sizeof ks / sizeof ks[0]; ++a) {
            const size_t k = ks[a];
            const double radius = dim == 1u ? (k < 8u ? 0.5 * (double)k : 3.0)
                                            : (k < 40u ? 0.5 * sqrt((double)k) : 2.5);
            points_uniform(&rng, k * dim, pts);
            if (k > 100u) /* a coarse lattice too: many equal distances */
                for (size_t i = 0; i < k * dim / 2u; ++i)
                    pts[i] = floor(pts[i] * 64.0) / 64.0;
            mcs_pcf acc = make(mem_a, dim, MCS_PCF_RDF, 40u, radius, 0.0);
            size_t need = 0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_work_size(&acc, k, &need));
            need > 0u ? ++grid : ++brute;
            add(&acc, k, pts);
            double want[MAX_BINS], got[MAX_BINS];
            brute_rdf(dim, k, pts, 40u, radius, want);
            for (size_t b = 0; b < 40u; ++b)
                got[b] = mean(&acc, b);
            char msg[96];
            snprintf(msg, sizeof msg, "%zuD K=%zu", dim, k);
            TEST_ASSERT_EQUAL_MEMORY_MESSAGE(want, got, sizeof(double) * 40u, msg);
        }
    TEST_ASSERT_TRUE(grid >= 4);
    TEST_ASSERT_TRUE(brute >= 4);
}

static void test_the_kernel_pcf_equals_a_direct_sum_to_rounding(void)
{
    static const size_t ks[] = {40, 150, 400};
    mcs_rng rng;
    mcs_rng_seed(&rng, 25u, 2u);
    for (size_t dim = 1; dim <= 2u; ++dim)
        for (size_t a = 0; a < sizeof ks / sizeof ks[0]; ++a) {
            const size_t k = ks[a];
            points_uniform(&rng, k * dim, pts);
            const double radius = 1.5, sigma = 0.08;
            mcs_pcf acc = make(mem_a, dim, MCS_PCF_GAUSSIAN, 30u, radius, sigma);
            add(&acc, k, pts);
            double want[MAX_BINS];
            brute_kernel(dim, k, pts, 30u, radius, sigma, want);
            for (size_t b = 0; b < 30u; ++b)
                TEST_ASSERT_DOUBLE_WITHIN(1e-12 * (fabs(want[b]) + 1.0), want[b], mean(&acc, b));
        }
}

/* Over T random sets every bin lies within 5 standard errors of its exact
 * value, and psa's ring area with K^2 pairs in place of K (K - 1) (what a
 * density K normalisation gives) is refused in some bin. */
static void random_sets_agree(size_t dim, mcs_pcf_estimator e, size_t k, size_t sets)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 2012u, (uint64_t)(dim * 2u + (size_t)e));
    mcs_pcf acc = make(mem_a, dim, e, 24u, 2.4, 0.1);
    for (size_t t = 0; t < sets; ++t) {
        points_uniform(&rng, k * dim, pts);
        add(&acc, k, pts);
    }
    double worst = 0.0, chi2 = 0.0, wrong = 0.0;
    for (size_t b = 0; b < 24u; ++b) {
        double exact = NAN;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_exact(&acc, NULL, b, &exact));
        const double z = (mean(&acc, b) - exact) / stderr_of(&acc, b);
        const double zw = (mean(&acc, b) * (double)(k - 1u) / (double)k - exact) / stderr_of(&acc, b);
        worst = fabs(z) > worst ? fabs(z) : worst;
        chi2 += z * z;
        wrong += zw * zw;
    }
    char msg[96];
    snprintf(msg, sizeof msg, "%zuD est %d: worst z %.2f, chi2 %.1f, K^2 chi2 %.1f", dim, (int)e,
             worst, chi2, wrong);
    TEST_ASSERT_TRUE_MESSAGE(worst < 5.0, msg);
    if (getenv("PCF_VERBOSE") != NULL)
        printf("%s\n", msg);
    if (e == MCS_PCF_RDF) {
        TEST_ASSERT_TRUE_MESSAGE(wrong > 24.0 + 10.0 * sqrt(48.0), msg);
    }
}

static void test_random_sets_give_g_of_one_within_five_standard_errors(void)
{
    random_sets_agree(2u, MCS_PCF_RDF, 64u, 1200u);
    random_sets_agree(1u, MCS_PCF_RDF, 32u, 1500u);
}

static void test_random_sets_give_the_kernels_exact_curve_within_five_standard_errors(void)
{
    random_sets_agree(2u, MCS_PCF_GAUSSIAN, 64u, 400u);
    random_sets_agree(1u, MCS_PCF_GAUSSIAN, 32u, 400u);
    mcs_pcf acc = make(mem_a, 2u, MCS_PCF_GAUSSIAN, 24u, 2.4, 0.1);
    double e0 = NAN, e23 = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_exact(&acc, NULL, 0u, &e0));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_exact(&acc, NULL, 23u, &e23));
    /* At r = sigma / 2: Phi(0.5) + 2 phi(0.5). */
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.69146246127401310 + 2.0 * 0.35206532676429952, e0);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 1.0, e23);
}

static void test_merging_two_halves_equals_one_pass(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 7u, 7u);
    mcs_pcf one = make(mem_a, 2u, MCS_PCF_GAUSSIAN, 20u, 2.0, 0.15);
    mcs_pcf half = make(mem_b, 2u, MCS_PCF_GAUSSIAN, 20u, 2.0, 0.15);
    static unsigned char mem_c[MCS_PCF_SIZE(MAX_BINS) + 64];
    mcs_pcf other = make(mem_c, 2u, MCS_PCF_GAUSSIAN, 20u, 2.0, 0.15);
    for (int t = 0; t < 30; ++t) {
        const size_t k = 50u + (size_t)t;
        points_uniform(&rng, 2u * k, pts);
        add(&one, k, pts);
        add(t < 11 ? &half : &other, k, pts);
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_merge(&half, &other));
    uint64_t n = 0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_count(&half, &n));
    TEST_ASSERT_EQUAL_UINT64(30u, n);
    TEST_ASSERT_EQUAL_UINT64(50u, half.k_min);
    TEST_ASSERT_EQUAL_UINT64(79u, half.k_max);
    for (size_t b = 0; b < 20u; ++b)
        points_assert_merged(mean(&one, b), stderr_of(&one, b), mean(&half, b), stderr_of(&half, b));
    /* A self-merge doubles the count and keeps the means. */
    const double m3 = mean(&half, 3u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_merge(&half, &half));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15 * m3, m3, mean(&half, 3u));
}

/* The whole-array read-out is the per-bin calls bit for bit, and a refused
 * one (a wrong length, one set for the standard error, an array inside the
 * object's buffer) writes nothing. */
static void test_reading_every_bin_at_once_equals_the_per_bin_calls(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 9u, 9u);
    mcs_pcf acc = make(mem_a, 2u, MCS_PCF_RDF, 16u, 2.5, 0.0);
    static double r[16], m[16], se[16], r2[16];
    points_uniform(&rng, 2u * 64u, pts);
    add(&acc, 64u, pts);
    for (size_t b = 0; b < 16u; ++b)
        r2[b] = m[b] = se[b] = -7.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_pcf_read_all(&acc, 16u, r2, m, se));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_pcf_read_all(&acc, 15u, r2, m, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pcf_read_all(&acc, 16u, acc.mean, NULL, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pcf_read_all(&acc, 16u, r2, r2, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pcf_read_all(&acc, 16u, NULL, NULL, NULL));
    for (size_t b = 0; b < 16u; ++b)
        TEST_ASSERT_TRUE(r2[b] == -7.0 && m[b] == -7.0 && se[b] == -7.0);
    for (int t = 0; t < 5; ++t) {
        points_uniform(&rng, 2u * 64u, pts);
        add(&acc, 64u, pts);
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_read_all(&acc, 16u, r, m, se));
    for (size_t b = 0; b < 16u; ++b) {
        double one = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_radius_at(&acc, b, &one));
        TEST_ASSERT_EQUAL_MEMORY(&one, &r[b], sizeof one);
        one = mean(&acc, b);
        TEST_ASSERT_EQUAL_MEMORY(&one, &m[b], sizeof one);
        one = stderr_of(&acc, b);
        TEST_ASSERT_EQUAL_MEMORY(&one, &se[b], sizeof one);
    }
}

/* J1 by its power series, independent of the library's trapezoid rule. */
static double j1_series(double x)
{
    long double term = (long double)x / 2.0L, sum = term;
    for (int m = 1; m < 80; ++m) {
        term *= -(long double)x * x / (4.0L * m * (m + 1));
        sum += term;
    }
    return (double)sum;
}

/* J1 by the trapezoid rule in long double with many more points than the
 * library's: the reference above x = 1e4, where the library switches to
 * Hankel's expansion and the series cancels. */
static double j1_trapezoid(double x)
{
    const long m = (long)x + 2000;
    long double sum = 0.0L;
    for (long j = 0; j < m; ++j) {
        const long double t = 2.0L * 3.14159265358979323846264L * (long double)j / (long double)m;
        sum += cosl(t - (long double)x * sinl(t));
    }
    return (double)(sum / (long double)m);
}

/* A synthetic mean RDF, g = 0 below a and 1 above (a hard core): the
 * transform is 1 - (K - 1) pi a^2 2 J1(2 pi f a) / (2 pi f a). */
static void test_the_power_from_the_rdf_is_its_hankel_transform(void)
{
    const size_t k = 256u, bins = 32u;
    mcs_pcf acc = make(mem_a, 2u, MCS_PCF_RDF, bins, 4.0, 0.0);
    mcs_rng rng;
    mcs_rng_seed(&rng, 3u, 3u);
    points_uniform(&rng, 2u * k, pts);
    add(&acc, k, pts);
    for (size_t b = 0; b < bins; ++b)
        acc.mean[b] = b < 8u ? 0.0 : 1.0; /* a = 8 bins of 1/8 spacing = 1 spacing */
    const double a = 1.0 / 16.0;          /* 1 / sqrt(256) */
    const double fs[] = {0.0, 0.5, 3.0, 16.0, 40.0, 77.7, 900.0, 15000.0, 25000.0, 4e5};
    for (size_t i = 0; i < sizeof fs / sizeof fs[0]; ++i) {
        const double f = fs[i], x = 2.0 * pi * f * a;
        const double j1 = x < 50.0 ? j1_series(x) : j1_trapezoid(x);
        const double want = 1.0 - (double)(k - 1u) * pi * a * a * (f == 0.0 ? 1.0 : 2.0 * j1 / x);
        double got = NAN;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_power(&acc, f, &got));
        char msg[96];
        snprintf(msg, sizeof msg, "f = %g: %.17g vs %.17g", f, got, want);
        TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1e-12 * (double)k, want, got, msg);
    }
    /* 1D: 1 - (K - 1) 2 a sinc(2 pi f a). */
    mcs_pcf one = make(mem_b, 1u, MCS_PCF_RDF, bins, 4.0, 0.0);
    points_uniform(&rng, 64u, pts);
    add(&one, 64u, pts);
    for (size_t b = 0; b < bins; ++b)
        one.mean[b] = b < 8u ? 0.0 : 1.0;
    double got = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_power(&one, 5.0, &got));
    const double a1 = 1.0 / 64.0;
    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * 64.0, 1.0 - 63.0 * sin(2.0 * pi * 5.0 * a1) / (pi * 5.0), got);
}

static void test_bad_input_changes_nothing(void)
{
    mcs_pcf acc = make(mem_a, 2u, MCS_PCF_RDF, 16u, 2.0, 0.0);
    mcs_rng rng;
    mcs_rng_seed(&rng, 1u, 1u);
    points_uniform(&rng, 200u, pts);
    add(&acc, 100u, pts);
    mcs_pcf keep = acc;
    unsigned char buf[MCS_PCF_SIZE(16u) + 3];
    memcpy(buf, mem_a, sizeof buf);
    double nan_pts[200];
    memcpy(nan_pts, pts, sizeof nan_pts);
    nan_pts[77] = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pcf_add(&acc, 100u, nan_pts, work, sizeof work));
    nan_pts[77] = 1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pcf_add(&acc, 100u, nan_pts, work, sizeof work));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pcf_add(&acc, 1u, pts, work, sizeof work));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pcf_add(&acc, 15u, pts, work, sizeof work)); /* 2/sqrt(15) > 1/2 */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pcf_add(&acc, 100u, NULL, work, sizeof work));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, mcs_pcf_add(&acc, 100u, pts, work, 8u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pcf_add(&acc, 100u, pts, pts, sizeof work));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pcf_add(&acc, 100u, (const double *)(void *)acc.mean, work, sizeof work));
    mcs_pcf other = make(mem_b, 2u, MCS_PCF_RDF, 16u, 2.5, 0.0);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_pcf_merge(&acc, &other));
    TEST_ASSERT_EQUAL_MEMORY(&keep, &acc, sizeof acc);
    TEST_ASSERT_EQUAL_MEMORY(buf, mem_a, sizeof buf);
    mcs_pcf bad = acc;
    bad.bins = 17u;
    double v = 5.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pcf_mean(&bad, 0u, &v));
    bad = acc;
    bad.mean = bad.m2;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pcf_mean(&bad, 0u, &v));
    const double m2_3 = acc.m2[3];
    acc.m2[3] = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_pcf_mean(&acc, 0u, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_pcf_add(&acc, 100u, pts, work, sizeof work));
    acc.m2[3] = m2_3;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_BIN_RANGE, mcs_pcf_mean(&acc, 16u, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_pcf_stderr(&acc, 0u, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pcf_power(&acc, -1.0, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pcf_power(&acc, NAN, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pcf_power(&acc, 1.0000001e12, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pcf_work_size(&acc, SIZE_MAX / 8u, &(size_t){0}));
    TEST_ASSERT_EQUAL_DOUBLE(5.0, v);
    /* init's refusals */
    mcs_pcf fresh;
    memset(&fresh, 0xA5, sizeof fresh);
    const mcs_pcf fkeep = fresh;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pcf_init(&fresh, 3u, MCS_PCF_RDF, 4u, 1.0, 0.0, buf, sizeof buf));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pcf_init(&fresh, 2u, MCS_PCF_RDF, 4u, NAN, 0.0, buf, sizeof buf));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pcf_init(&fresh, 2u, MCS_PCF_GAUSSIAN, 4u, 1.0, 0.0, buf, sizeof buf));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pcf_init(&fresh, 2u, MCS_PCF_GAUSSIAN, 4u, INFINITY, 0.1, buf, sizeof buf));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_pcf_init(&fresh, 2u, (mcs_pcf_estimator)2, 4u, 1.0, 0.0, buf, sizeof buf));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_pcf_init(&fresh, 2u, MCS_PCF_RDF, 0u, 1.0, 0.0, buf, sizeof buf));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_pcf_init(&fresh, 2u, MCS_PCF_RDF, MCS_PCF_MAX_BINS + 1u, 1.0, 0.0, buf, SIZE_MAX));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, mcs_pcf_init(&fresh, 2u, MCS_PCF_RDF, 16u, 1.0, 0.0, buf, MCS_PCF_SIZE(16u) - 1u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pcf_init(&fresh, 2u, MCS_PCF_RDF, 1u, 1.0, 0.0, &fresh, sizeof buf));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pcf_init(&fresh, 2u, MCS_PCF_RDF, 1u, 1.0, 0.0, NULL, sizeof buf));
    TEST_ASSERT_EQUAL_MEMORY(&fkeep, &fresh, sizeof fresh);
    size_t bytes = 9u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_N_RANGE, mcs_pcf_size(0u, &bytes));
    TEST_ASSERT_EQUAL_UINT64(9u, bytes);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pcf_count(&fresh, &(uint64_t){0}));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_the_rdf_equals_a_direct_pair_count_bit_for_bit);
    RUN_TEST(test_the_kernel_pcf_equals_a_direct_sum_to_rounding);
    RUN_TEST(test_random_sets_give_g_of_one_within_five_standard_errors);
    RUN_TEST(test_random_sets_give_the_kernels_exact_curve_within_five_standard_errors);
    RUN_TEST(test_merging_two_halves_equals_one_pass);
    RUN_TEST(test_reading_every_bin_at_once_equals_the_per_bin_calls);
    RUN_TEST(test_the_power_from_the_rdf_is_its_hankel_transform);
    RUN_TEST(test_bad_input_changes_nothing);
    return UNITY_END();
}
