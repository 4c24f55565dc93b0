/* Tests of the spatial statistics (spacing.h): the minimum and average
 * minimum toroidal distances against a brute-force search over every pair
 * (the same doubles, bit for bit, on the grid path and the brute-force
 * path), for random, clustered, lattice, duplicated and wrapping sets in
 * d = 1..8; hand-made sets; the maximal packing distance; the expectation
 * of the nearest-neighbour distance of independent uniform points
 * (P(NN > r) = (1 - V_d r^d)^(K-1) for r <= 1/2, so
 * E NN = V_d^(-1/d) Gamma(1 + 1/d) Gamma(K) / Gamma(K + 1/d) to far below
 * rounding, and in 1D E min = 1/K^2) within 5 standard errors with fixed
 * seeds, which the wrong normalisations fail; the accumulator against
 * mcs_welford, its merge, and bad input. */
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

enum { NS = MCS_SPACING_STATISTICS };

#define MAX_K 4000
static double pts[MAX_K * 8];
static unsigned char work[MCS_SPACING_WORK_SIZE(MAX_K) + 64];

static void uniform(mcs_rng *rng, size_t n, double *out)
{
    for (size_t i = 0; i < n; ++i)
        mcs_rng_double(rng, &out[i]);
}

static double packing(size_t dim, size_t k)
{
    double d = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_packing_distance(dim, k, &d));
    return d;
}

/* The two statistics by brute force, every ordered pair, the squared
 * toroidal distance summed coordinate by coordinate. */
static void brute(size_t k, size_t dim, const double *p, double *out)
{
    double mn = INFINITY, sum = 0.0;
    for (size_t i = 0; i < k; ++i) {
        double best = INFINITY;
        for (size_t j = 0; j < k; ++j) {
            if (j == i)
                continue;
            double d2 = 0.0;
            for (size_t a = 0; a < dim; ++a) {
                double t = fabs(p[i * dim + a] - p[j * dim + a]);
                t = t > 0.5 ? 1.0 - t : t;
                d2 += t * t;
            }
            best = d2 < best ? d2 : best;
        }
        mn = best < mn ? best : mn;
        sum += sqrt(best);
    }
    const double dmax = packing(dim, k);
    out[MCS_SPACING_MIN_DISTANCE] = sqrt(mn) / dmax;
    out[MCS_SPACING_AVG_MIN_DISTANCE] = sum / (double)k / dmax;
}

static void distances_ok(size_t k, size_t dim, const double *p, double *out)
{
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_distances(k, dim, p, work + 3, sizeof work - 3, out));
}

static size_t work_size(size_t dim, size_t k)
{
    size_t b = 0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_work_size(dim, k, &b));
    return b;
}

/* ---- against the brute force -------------------------------------------------- */

/* Sets of six shapes: uniform; clustered (all points in a corner box of
 * side 0.2, so most cells are empty and searches go out several rings);
 * on a coarse lattice (many equal distances, points on cell edges); with a
 * duplicate (distance 0); hugging the faces (nearest neighbours across the
 * wrap); a cluster in a box of side 0.1 and one point across the torus
 * from it, whose search must go out to the last ring. */
static void make_set(mcs_rng *rng, int shape, size_t k, size_t dim, double *p)
{
    uniform(rng, k * dim, p);
    for (size_t i = 0; i < k * dim; ++i) {
        if (shape == 1)
            p[i] = 0.8 + 0.2 * p[i];
        else if (shape == 2)
            p[i] = floor(p[i] * 5.0) / 5.0;
        else if (shape == 4)
            p[i] = p[i] < 0.5 ? 0.01 * p[i] : 1.0 - 0.01 * p[i];
        else if (shape == 5)
            p[i] = i < dim ? 0.55 : 0.1 * p[i];
        p[i] = p[i] < 1.0 ? p[i] : 0.0;
    }
    if (shape == 3)
        memcpy(p + (k - 1) * dim, p, dim * sizeof *p);
}

static void test_distances_equal_a_brute_force_search_bit_for_bit(void)
{
    static const size_t ks[] = {2, 3, 10, 97, 700, 1500};
    mcs_rng rng;
    mcs_rng_seed(&rng, 31u, 3u);
    int grid_runs = 0, brute_runs = 0;
    for (size_t dim = 1; dim <= 8u; ++dim)
        for (size_t a = 0; a < sizeof ks / sizeof ks[0]; ++a)
            for (int shape = 0; shape < 6; ++shape) {
                const size_t k = ks[a];
                if (k * k * dim > 10000000u && shape != 0)
                    continue; /* keep the brute force of the test quick */
                make_set(&rng, shape, k, dim, pts);
                double got[NS], want[NS];
                distances_ok(k, dim, pts, got);
                brute(k, dim, pts, want);
                char msg[64];
                snprintf(msg, sizeof msg, "d=%zu K=%zu shape %d", dim, k, shape);
                TEST_ASSERT_EQUAL_MEMORY_MESSAGE(want, got, sizeof want, msg);
                if (work_size(dim, k) > 0u)
                    ++grid_runs;
                else
                    ++brute_runs;
            }
    TEST_ASSERT_TRUE(grid_runs >= 20);
    TEST_ASSERT_TRUE(brute_runs >= 20);
}

static void test_the_grid_is_used_where_it_pays(void)
{
    TEST_ASSERT_EQUAL_UINT64(0u, work_size(2, 8));   /* m = 2 */
    TEST_ASSERT_EQUAL_UINT64(0u, work_size(2, 20));  /* 9 (1 + 20/16) > 10 */
    TEST_ASSERT_EQUAL_UINT64((size_t)(16 * 16 + 2 + 256) * sizeof(size_t), work_size(2, 256));
    TEST_ASSERT_EQUAL_UINT64((size_t)(11 * 11 * 11 + 2 + 1500) * sizeof(size_t), work_size(3, 1500));
    TEST_ASSERT_EQUAL_UINT64(0u, work_size(8, 60000)); /* m = 3: 3^8 (1 + 9.1) > 30000 */
    for (size_t dim = 1; dim <= 8u; ++dim)
        for (size_t k = 2; k < 5000u; k = k * 3u / 2u + 1u)
            TEST_ASSERT_TRUE(work_size(dim, k) <= MCS_SPACING_WORK_SIZE(k));
}

/* ---- hand-made sets and the packing distance ------------------------------------ */

static void test_packing_distance_is_the_densest_lattice_s(void)
{
    TEST_ASSERT_DOUBLE_WITHIN(1e-16, 1.0 / 64, packing(1, 64));
    TEST_ASSERT_DOUBLE_WITHIN(1e-16, sqrt(2.0 / (sqrt(3.0) * 256)), packing(2, 256));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, cbrt(sqrt(2.0) / 1000), packing(3, 1000));
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 2.0 * pow(1.0 / (8 * 81), 0.25), packing(4, 81)); /* D4 */
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 2.0 * pow(1.0 / (8 * sqrt(2.0) * 32), 0.2), packing(5, 32)); /* D5 */
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 2.0 * pow(1.0 / (8 * sqrt(3.0) * 64), 1.0 / 6), packing(6, 64)); /* E6 */
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 2.0 * pow(1.0 / (16 * 128.0), 1.0 / 7), packing(7, 128)); /* E7 */
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 2.0 * pow(1.0 / (16 * 256.0), 0.125), packing(8, 256)); /* E8 */
    double d = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spacing_packing_distance(2, 1, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_spacing_packing_distance(0, 1, &d));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_spacing_packing_distance(9, 1, &d));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_spacing_packing_distance(2, 0, &d));
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, d);
}

static void test_hand_made_sets(void)
{
    double out[NS];
    /* K equally spaced points on the circle: every gap 1/K = d_max. */
    for (size_t i = 0; i < 50; ++i)
        pts[i] = (double)i / 50.0;
    distances_ok(50, 1, pts, out);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0, out[MCS_SPACING_MIN_DISTANCE]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0, out[MCS_SPACING_AVG_MIN_DISTANCE]);
    /* An m x m square grid: spacing 1/m against d_max = sqrt(2 / sqrt 3) / m,
     * so sqrt(sqrt(3) / 2) = 0.9306 (the hexagonal lattice would give 1). */
    for (size_t i = 0; i < 400; ++i) {
        pts[2 * i] = (double)(i % 20) / 20.0 + 0.025;
        pts[2 * i + 1] = (double)(i / 20) / 20.0 + 0.025;
    }
    distances_ok(400, 2, pts, out);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, sqrt(sqrt(3.0) / 2), out[MCS_SPACING_MIN_DISTANCE]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, sqrt(sqrt(3.0) / 2), out[MCS_SPACING_AVG_MIN_DISTANCE]);
    /* Two points across the wrap: 0.01 and 0.99 are 0.02 apart. */
    const double wrap[2] = {0.01, 0.99};
    distances_ok(2, 1, wrap, out);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.02 * 2, out[MCS_SPACING_MIN_DISTANCE]);
    /* A duplicate: minimum 0, and its two points add 0 to the average. */
    const double dup[6] = {0.25, 0.25, 0.25, 0.25, 0.75, 0.75};
    distances_ok(3, 2, dup, out);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, out[MCS_SPACING_MIN_DISTANCE]);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, sqrt(0.5) / 3 / packing(2, 3), out[MCS_SPACING_AVG_MIN_DISTANCE]);
}

/* ---- random points: the nearest-neighbour expectation ---------------------------- */

/* E NN of K uniform points in the d-torus (the header comment of this file). */
static double expected_nn(size_t dim, size_t k)
{
    const double d = (double)dim;
    const double vol = pow(3.14159265358979323846, d / 2) / tgamma(d / 2 + 1);
    return pow(vol, -1.0 / d) * tgamma(1.0 + 1.0 / d) *
           exp(lgamma((double)k) - lgamma((double)k + 1.0 / d));
}

static void test_random_sets_meet_the_nearest_neighbour_expectation(void)
{
    static const size_t dims[] = {1, 2, 3, 4};
    static const size_t ks[] = {50, 256, 512, 1000};
    static const int sets[] = {3000, 1000, 300, 150};
    int tried = 0, caught = 0;
    for (size_t c = 0; c < 4; ++c) {
        const size_t dim = dims[c], k = ks[c];
        mcs_spacing acc;
        mcs_spacing_init(&acc, dim);
        mcs_rng rng;
        mcs_rng_seed(&rng, 500u + dim, 1u);
        for (int t = 0; t < sets[c]; ++t) {
            uniform(&rng, k * dim, pts);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_add(&acc, k, pts, work, sizeof work));
        }
        double mean, se;
        mcs_spacing_mean(&acc, MCS_SPACING_AVG_MIN_DISTANCE, &mean);
        mcs_spacing_stderr(&acc, MCS_SPACING_AVG_MIN_DISTANCE, &se);
        const double dmax = packing(dim, k), want = expected_nn(dim, k) / dmax;
        char msg[128];
        snprintf(msg, sizeof msg, "d=%zu K=%zu: avg %.6f exact %.6f z %.2f", dim, k, mean, want,
                 (mean - want) / se);
        TEST_ASSERT_TRUE_MESSAGE(fabs(mean - want) < 5.0 * se, msg);
        /* wrong forms a looser test could pass, each caught when more than 1%
         * off: the cubic lattice's K^(-1/d) for d_max, and the E NN of K
         * other points instead of K - 1 */
        const double wrong[2] = {expected_nn(dim, k) / pow((double)k, -1.0 / (double)dim),
                                 expected_nn(dim, k + 1u) / dmax};
        for (int w = 0; w < 2; ++w) {
            if (fabs(wrong[w] - want) < 0.01 * want)
                continue; /* within 1%: 1D's cubic lattice is the packing; K + 1 from 2D on */
            ++tried;
            caught += fabs(mean - wrong[w]) > 5.0 * se;
        }
        if (dim == 1u) { /* the minimum spacing of K uniform points on a circle: 1/K^2 */
            mcs_spacing_mean(&acc, MCS_SPACING_MIN_DISTANCE, &mean);
            mcs_spacing_stderr(&acc, MCS_SPACING_MIN_DISTANCE, &se);
            const double m1 = 1.0 / (double)k; /* (1/K^2) / (1/K) */
            snprintf(msg, sizeof msg, "1D min: %.6f exact %.6f z %.2f", mean, m1, (mean - m1) / se);
            TEST_ASSERT_TRUE_MESSAGE(fabs(mean - m1) < 5.0 * se, msg);
        }
    }
    TEST_ASSERT_EQUAL_INT(tried, caught);
    TEST_ASSERT_TRUE(tried >= 4);
}

/* ---- float points, bad input ------------------------------------------------------ */

static void test_float_points_give_the_bits_of_their_widened_doubles(void)
{
    enum { K = 600, D = 2 };
    static float pf[K * D];
    mcs_rng rng;
    mcs_rng_seed(&rng, 9u, 9u);
    for (size_t i = 0; i < K * D; ++i) {
        double u;
        mcs_rng_double(&rng, &u);
        pf[i] = (float)u < 1.0f ? (float)u : 0.0f;
        pts[i] = pf[i];
    }
    double a[NS], b[NS];
    distances_ok(K, D, pts, a);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_distances_f(K, D, pf, work, sizeof work, b));
    TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a);
    mcs_spacing sa, sb;
    mcs_spacing_init(&sa, D);
    mcs_spacing_init(&sb, D);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_add(&sa, K, pts, work, sizeof work));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_add_f(&sb, K, pf, work, sizeof work));
    TEST_ASSERT_EQUAL_MEMORY(&sa, &sb, sizeof sa);
}

static void test_bad_input_is_refused_and_writes_nothing(void)
{
    double out[NS];
    size_t bytes = 7;
    points_guard_fill(out, NS, -9.0);
    memset(work, 0xC3, sizeof work);
    for (size_t i = 0; i < 2 * 300; ++i)
        pts[i] = (double)((i * 7919u) % 1009u) / 1009.0;
    const size_t need = work_size(2, 300);
    TEST_ASSERT_TRUE(need > 0u);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spacing_distances(300, 2, NULL, work, need, out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spacing_distances(300, 2, pts, work, need, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spacing_distances(300, 2, pts, NULL, need, out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_spacing_distances(300, 0, pts, work, need, out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_spacing_distances(300, 9, pts, work, need, out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_spacing_distances(1, 2, pts, work, need, out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_spacing_distances(0, 2, pts, work, need, out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, mcs_spacing_distances(300, 2, pts, work, need - 1, out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_spacing_distances(300, 2, pts, (void *)pts, need, out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_spacing_distances(SIZE_MAX / 2, 4, pts, work, need, out));
    const double bad[] = {1.0, -0.25, NAN, INFINITY};
    for (size_t i = 0; i < 4; ++i) {
        const double keep = pts[417];
        pts[417] = bad[i];
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_spacing_distances(300, 2, pts, work, need, out));
        pts[417] = keep;
    }
    points_guard_check(out, NS, -9.0);
    for (size_t i = 0; i < sizeof work; ++i)
        TEST_ASSERT_EQUAL_HEX8(0xC3, work[i]);
    /* a brute-force set needs no work */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_distances(5, 2, pts, NULL, 0, out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spacing_work_size(2, 5, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_spacing_work_size(9, 5, &bytes));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_spacing_work_size(2, 1, &bytes));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_spacing_work_size(1, SIZE_MAX / 4, &bytes));
    TEST_ASSERT_EQUAL_UINT64(7u, bytes);
    TEST_ASSERT_EQUAL_STRING("min_distance", mcs_spacing_statistic_str(MCS_SPACING_MIN_DISTANCE));
    TEST_ASSERT_EQUAL_STRING("avg_min_distance", mcs_spacing_statistic_str(MCS_SPACING_AVG_MIN_DISTANCE));
    TEST_ASSERT_EQUAL_STRING("unknown", mcs_spacing_statistic_str(MCS_SPACING_STATISTICS));
}

/* ---- the accumulator ---------------------------------------------------------------- */

static void test_accumulator_gives_the_welford_mean_and_stderr(void)
{
    enum { SETS = 50, D = 2 };
    mcs_spacing acc, a, b;
    mcs_welford ref[NS];
    mcs_spacing_init(&acc, D);
    mcs_spacing_init(&a, D);
    mcs_spacing_init(&b, D);
    for (int s = 0; s < NS; ++s)
        mcs_welford_init(&ref[s]);
    mcs_rng rng;
    mcs_rng_seed(&rng, 12u, 34u);
    size_t k_min = SIZE_MAX, k_max = 0;
    for (int t = 0; t < SETS; ++t) {
        const size_t k = 2u + (size_t)(t * 53 % 400);
        k_min = k < k_min ? k : k_min;
        k_max = k > k_max ? k : k_max;
        uniform(&rng, k * D, pts);
        double out[NS];
        distances_ok(k, D, pts, out);
        for (int s = 0; s < NS; ++s)
            mcs_welford_add(&ref[s], out[s]);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_add(&acc, k, pts, work, sizeof work));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_add(t % 3 ? &a : &b, k, pts, work, sizeof work));
    }
    uint64_t count = 0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_count(&acc, &count));
    TEST_ASSERT_EQUAL_UINT64(SETS, count);
    TEST_ASSERT_EQUAL_UINT64(k_min, acc.k_min);
    TEST_ASSERT_EQUAL_UINT64(k_max, acc.k_max);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_merge(&a, &b));
    for (int s = 0; s < NS; ++s) {
        double m, se, wm, wse, am, ase;
        mcs_welford_mean(&ref[s], &wm);
        mcs_welford_stderr(&ref[s], &wse);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_mean(&acc, (mcs_spacing_statistic)s, &m));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_stderr(&acc, (mcs_spacing_statistic)s, &se));
        TEST_ASSERT_EQUAL_DOUBLE(wm, m);
        TEST_ASSERT_EQUAL_DOUBLE(wse, se);
        mcs_spacing_mean(&a, (mcs_spacing_statistic)s, &am);
        mcs_spacing_stderr(&a, (mcs_spacing_statistic)s, &ase);
        points_assert_merged(m, se, am, ase);
    }
    TEST_ASSERT_EQUAL_UINT64(acc.k_min, a.k_min);
    TEST_ASSERT_EQUAL_UINT64(acc.k_max, a.k_max);
}

static void test_accumulator_refuses_bad_input_and_changes_nothing(void)
{
    mcs_spacing acc, before, other;
    const double p[6] = {0.1, 0.2, 0.5, 0.6, 0.9, 0.3};
    double v = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spacing_init(NULL, 2));
    memset(&acc, 0x77, sizeof acc);
    before = acc;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_spacing_init(&acc, 0));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_spacing_init(&acc, 9));
    TEST_ASSERT_EQUAL_MEMORY(&before, &acc, sizeof acc);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_spacing_add(&acc, 3, p, NULL, 0));
    mcs_spacing_init(&acc, 2);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_spacing_mean(&acc, MCS_SPACING_MIN_DISTANCE, &v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_add(&acc, 3, p, NULL, 0));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_spacing_stderr(&acc, MCS_SPACING_MIN_DISTANCE, &v));
    before = acc;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spacing_add(NULL, 3, p, NULL, 0));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spacing_add(&acc, 3, NULL, NULL, 0));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_spacing_add(&acc, 1, p, NULL, 0));
    for (size_t i = 0; i < 2 * 300; ++i)
        pts[i] = (double)((i * 7919u) % 1009u) / 1009.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spacing_add(&acc, 300, pts, NULL, 0));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, mcs_spacing_add(&acc, 300, pts, work, 16));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_spacing_add(&acc, 300, pts, (void *)&acc, sizeof work));
    TEST_ASSERT_EQUAL_MEMORY(&before, &acc, sizeof acc);
    mcs_spacing_init(&other, 3);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_spacing_merge(&acc, &other));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_spacing_merge(&acc, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_spacing_mean(&acc, MCS_SPACING_STATISTICS, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_spacing_mean(&acc, (mcs_spacing_statistic)-1, &v));
    TEST_ASSERT_EQUAL_MEMORY(&before, &acc, sizeof acc);
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, v);
    /* self-merge doubles the count */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spacing_merge(&acc, &acc));
    uint64_t count = 0;
    mcs_spacing_count(&acc, &count);
    TEST_ASSERT_EQUAL_UINT64(2u, count);
    /* corrupted states */
    before = acc;
    acc.stat[MCS_SPACING_AVG_MIN_DISTANCE].count = 5;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_spacing_count(&acc, &count));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_spacing_add(&acc, 3, p, NULL, 0));
    acc = before;
    acc.stat[MCS_SPACING_MIN_DISTANCE].mean = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_spacing_mean(&acc, MCS_SPACING_AVG_MIN_DISTANCE, &v));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_spacing_merge(&before, &acc));
    acc = before;
    acc.k_max = 0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_INVARIANT, mcs_spacing_stderr(&acc, MCS_SPACING_MIN_DISTANCE, &v));
    acc = before;
    acc.dim = 99;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_spacing_count(&acc, &count));
    TEST_ASSERT_EQUAL_UINT64(2u, count);
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, v);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_distances_equal_a_brute_force_search_bit_for_bit);
    RUN_TEST(test_the_grid_is_used_where_it_pays);
    RUN_TEST(test_packing_distance_is_the_densest_lattice_s);
    RUN_TEST(test_hand_made_sets);
    RUN_TEST(test_random_sets_meet_the_nearest_neighbour_expectation);
    RUN_TEST(test_float_points_give_the_bits_of_their_widened_doubles);
    RUN_TEST(test_bad_input_is_refused_and_writes_nothing);
    RUN_TEST(test_accumulator_gives_the_welford_mean_and_stderr);
    RUN_TEST(test_accumulator_refuses_bad_input_and_changes_nothing);
    return UNITY_END();
}
