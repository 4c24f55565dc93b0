/* Tests of the exact pair correlation of the 2D patterns (pcf.h:
 * mcs_pcf_exact): the mean RDF of jittered (square, oblong and one-row
 * strata) and n-rooks sets within 5 standard errors of the exact value in
 * every bin, with fixed seeds, where g = 1 is refused; the grid and the
 * shifted grid equal their one set's RDF; the same-cell ring integrals of
 * the jittered grid sum to the triangle product's mass, 1, to 1e-12 once
 * the radius covers its support; and the refusals. */
#include "mcspec.h"
#include "points_ref.h"
#include "unity.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define MAX_K 256
#define BINS 24
static double pts[2 * MAX_K];
static unsigned char work[MCS_PCF_WORK_SIZE(MAX_K)];
static unsigned char mem[MCS_PCF_SIZE(64)];

static const double pi = 3.14159265358979323846;

static mcs_pcf make_est(mcs_pcf_estimator e, size_t bins, double radius)
{
    mcs_pcf acc;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_init(&acc, 2u, e, bins, radius, 0.12, mem, sizeof mem));
    return acc;
}

static mcs_pcf make(size_t bins, double radius)
{
    return make_est(MCS_PCF_RDF, bins, radius);
}

static double exact(const mcs_pcf *acc, const mcs_pattern2d *pat, size_t b)
{
    double v = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_exact(acc, pat, b, &v));
    return v;
}

static void sets_agree_est(mcs_pcf_estimator e, mcs_pattern2d_kind kind, size_t k, size_t sx,
                           size_t sy, size_t sets)
{
    const mcs_pattern2d pat = points_pattern2d(kind, k, sx, sy);
    mcs_rng rng;
    mcs_rng_seed(&rng, 2026u, (uint64_t)k * 10u + (uint64_t)kind);
    mcs_pcf acc = make_est(e, BINS, e == MCS_PCF_RDF ? 2.4 : 1.8);
    for (size_t t = 0; t < sets; ++t) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_draw(&pat, &rng, k, pts));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_add(&acc, k, pts, work, sizeof work));
    }
    double worst = 0.0, chi2 = 0.0, chi2_one = 0.0;
    for (size_t b = 0; b < BINS; ++b) {
        double m = NAN, se = NAN;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_mean(&acc, b, &m));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_stderr(&acc, b, &se));
        const double z = (m - exact(&acc, &pat, b)) / se, z1 = (m - 1.0) / se;
        worst = fabs(z) > worst ? fabs(z) : worst;
        chi2 += z * z;
        chi2_one += z1 * z1;
    }
    char msg[128];
    snprintf(msg, sizeof msg, "%s %s K=%zu (%zu x %zu): worst z %.2f, chi2 %.1f, chi2 of g = 1 %.0f",
             e == MCS_PCF_RDF ? "RDF" : "kernel", mcs_pattern2d_kind_str(kind), k, sx, sy, worst,
             chi2, chi2_one);
    if (getenv("PCF_VERBOSE") != NULL)
        printf("%s\n", msg);
    TEST_ASSERT_TRUE_MESSAGE(worst < 5.0, msg);
    TEST_ASSERT_TRUE_MESSAGE(chi2 < BINS + 8.0 * sqrt(2.0 * BINS), msg);
    TEST_ASSERT_TRUE_MESSAGE(chi2_one > 10.0 * BINS, msg);
}

static void sets_agree(mcs_pattern2d_kind kind, size_t k, size_t sx, size_t sy, size_t sets)
{
    sets_agree_est(MCS_PCF_RDF, kind, k, sx, sy, sets);
}

/* The kernel PCF (sigma 0.12 spacings) of the same patterns: the pair
 * count within d integrated against the kernel's derivative. */
static void test_kernel_pcfs_of_jittered_and_nrooks_sets_match_their_exact_curves(void)
{
    sets_agree_est(MCS_PCF_GAUSSIAN, MCS_PATTERN2D_JITTERED, 64u, 8u, 8u, 600u);
    sets_agree_est(MCS_PCF_GAUSSIAN, MCS_PATTERN2D_JITTERED, 48u, 8u, 6u, 600u);
    sets_agree_est(MCS_PCF_GAUSSIAN, MCS_PATTERN2D_NROOKS, 64u, 8u, 8u, 600u);
}

static void test_jittered_sets_match_the_exact_rdf_within_five_standard_errors(void)
{
    sets_agree(MCS_PATTERN2D_JITTERED, 64u, 8u, 8u, 1500u);
    sets_agree(MCS_PATTERN2D_JITTERED, 48u, 8u, 6u, 1500u);
    sets_agree(MCS_PATTERN2D_JITTERED, 31u, 31u, 1u, 2000u);
}

static void test_nrooks_sets_match_the_exact_rdf_within_five_standard_errors(void)
{
    sets_agree(MCS_PATTERN2D_NROOKS, 64u, 8u, 8u, 1500u);
    sets_agree(MCS_PATTERN2D_NROOKS, 25u, 5u, 5u, 3000u);
}

/* Lattice distances sqrt(a^2 + b^2) spacings against bin edges of width
 * 3.3/23: none falls within 1e-9 of an edge, so rounding cannot move one. */
static void test_the_grid_and_the_shifted_grid_equal_their_exact_rdf(void)
{
    { /* the kernel: every lattice pair's term, deterministic */
        const mcs_pattern2d grid = points_pattern2d(MCS_PATTERN2D_GRID, 64u, 0u, 0u);
        mcs_rng r0;
        mcs_rng_seed(&r0, 5u, 6u);
        mcs_pcf kern = make_est(MCS_PCF_GAUSSIAN, 20u, 2.0);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_draw(&grid, &r0, 64u, pts));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_add(&kern, 64u, pts, work, sizeof work));
        for (size_t b = 0; b < 20u; ++b) {
            double m = NAN;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_mean(&kern, b, &m));
            const double x = exact(&kern, &grid, b);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * (x + 1.0), x, m);
        }
    }
    const mcs_pattern2d kinds[2] = {points_pattern2d(MCS_PATTERN2D_GRID, 64u, 0u, 0u),
                                    points_pattern2d(MCS_PATTERN2D_SHIFTED_GRID, 64u, 0u, 0u)};
    mcs_rng rng;
    mcs_rng_seed(&rng, 5u, 5u);
    for (int i = 0; i < 2; ++i) {
        mcs_pcf acc = make(23u, 3.3);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_draw(&kinds[i], &rng, 64u, pts));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_add(&acc, 64u, pts, work, sizeof work));
        double nonzero = 0.0;
        for (size_t b = 0; b < 23u; ++b) {
            double m = NAN;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_mean(&acc, b, &m));
            const double e = exact(&acc, &kinds[i], b);
            TEST_ASSERT_DOUBLE_WITHIN(1e-12 * (e + 1.0), e, m);
            nonzero += e > 0.0 ? 1.0 : 0.0;
        }
        TEST_ASSERT_TRUE(nonzero >= 6.0);
    }
}

/* Sum over bins of K A_b - (K - 1) A_b g_b is the same-cell mass inside
 * the radius: 1 once the radius passes sqrt(1/m^2 + 1/n^2). */
static void test_the_same_cell_ring_integrals_sum_to_one(void)
{
    const size_t shapes[3][2] = {{8u, 8u}, {8u, 6u}, {16u, 4u}};
    for (int i = 0; i < 3; ++i) {
        const size_t m = shapes[i][0], n = shapes[i][1], k = m * n;
        const mcs_pattern2d pat = points_pattern2d(MCS_PATTERN2D_JITTERED, k, m, n);
        const double s = 1.0 / sqrt((double)k), radius = 0.49 / s;
        mcs_pcf acc = make(37u, radius);
        double sum = 0.0;
        const double w = radius / 37.0 * s;
        for (size_t b = 0; b < 37u; ++b) {
            const double area = pi * ((double)(b + 1u) * w * (double)(b + 1u) * w - (double)b * w * (double)b * w);
            sum += (double)k * area - (double)(k - 1u) * area * exact(&acc, &pat, b);
        }
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0, sum);
    }
}

static void test_exact_refuses_what_it_has_no_value_for(void)
{
    mcs_pcf acc = make(8u, 2.0);
    const mcs_pattern2d mj = points_pattern2d(MCS_PATTERN2D_MULTI_JITTERED, 64u, 0u, 0u);
    const mcs_pattern2d small = points_pattern2d(MCS_PATTERN2D_JITTERED, 9u, 0u, 0u);
    double v = 7.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_pcf_exact(&acc, &mj, 0u, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pcf_exact(&acc, &small, 0u, &v)); /* 2/3 > 1/2 */
    TEST_ASSERT_EQUAL_INT(MCS_ERR_BIN_RANGE, mcs_pcf_exact(&acc, NULL, 8u, &v));
    mcs_pcf kern;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_init(&kern, 2u, MCS_PCF_GAUSSIAN, 8u, 2.0, 0.1, mem, sizeof mem));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_pcf_exact(&kern, &mj, 0u, &v));
    const mcs_pattern2d jit = points_pattern2d(MCS_PATTERN2D_JITTERED, 64u, 0u, 0u);
    mcs_pcf one;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pcf_init(&one, 1u, MCS_PCF_RDF, 8u, 2.0, 0.0, mem, sizeof mem));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_pcf_exact(&one, &jit, 0u, &v));
    TEST_ASSERT_EQUAL_DOUBLE(7.0, v);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_jittered_sets_match_the_exact_rdf_within_five_standard_errors);
    RUN_TEST(test_nrooks_sets_match_the_exact_rdf_within_five_standard_errors);
    RUN_TEST(test_kernel_pcfs_of_jittered_and_nrooks_sets_match_their_exact_curves);
    RUN_TEST(test_the_grid_and_the_shifted_grid_equal_their_exact_rdf);
    RUN_TEST(test_the_same_cell_ring_integrals_sum_to_one);
    RUN_TEST(test_exact_refuses_what_it_has_no_value_for);
    return UNITY_END();
}
