#include "mcspec/pattern2d.h"
#include "mcspec/pointset2d.h"
#include "mcspec/rng.h"
#include "points_ref.h"
#include "unity.h"

#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define MAXK 256

static mcs_pointset2d acc, acc2, acc3, snapshot;
static double pts[2 * MAXK];

static void test_one_trial_matches_the_direct_sum_at_every_wave_vector(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 1u, 9u);
    const size_t ks[3] = {1u, 13u, 100u};
    const size_t fmax = MCS_MAX_FREQ < 40 ? MCS_MAX_FREQ : 40; /* past one re-anchoring */
    for (int c = 0; c < 3; ++c) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&acc, fmax));
        points_uniform(&rng, 2 * ks[c], pts);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc, ks[c], pts));
        for (long fy = -(long)fmax; fy <= (long)fmax; ++fy)
            for (long fx = -(long)fmax; fx <= (long)fmax; ++fx) {
                double p = 0.0;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_power(&acc, fx, fy, &p));
                TEST_ASSERT_DOUBLE_WITHIN(1e-12 * (double)ks[c], points_periodogram(2u, ks[c], pts, fx, fy), p);
            }
    }
}

static void test_radial_average_of_one_trial_is_the_whole_plane_annulus_mean(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 2u, 9u);
    const long fmax = 12;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&acc, (size_t)fmax));
    points_uniform(&rng, 2 * 20u, pts);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc, 20u, pts));
    size_t total = 0u;
    for (size_t r = 0; r <= (size_t)fmax; ++r) {
        double sum = 0.0, n = 0.0, got = 0.0;
        for (long fy = -fmax; fy <= fmax; ++fy)
            for (long fx = -fmax; fx <= fmax; ++fx) {
                double d = sqrt((double)(fx * fx + fy * fy));
                if (d >= (double)r && d < (double)r + 1.0) {
                    double p = 0.0;
                    mcs_pointset2d_power(&acc, fx, fy, &p);
                    sum += p;
                    n += 1.0;
                }
            }
        size_t size = 0u;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_ring_size(r, &size));
        TEST_ASSERT_EQUAL_DOUBLE(n, (double)size);
        total += size;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial(&acc, r, &got));
        TEST_ASSERT_DOUBLE_WITHIN(1e-12 * sum / n + 1e-14, sum / n, got);
    }
    /* The annuli 0..F tile the disc |f| < F + 1. */
    size_t disc = 0u;
    for (long fy = -fmax - 1; fy <= fmax + 1; ++fy)
        for (long fx = -fmax - 1; fx <= fmax + 1; ++fx)
            disc += fx * fx + fy * fy < (fmax + 1) * (fmax + 1);
    TEST_ASSERT_EQUAL_UINT(disc, total);
    size_t s0 = 0u, s1 = 0u;
    mcs_pointset2d_ring_size(0u, &s0);
    mcs_pointset2d_ring_size(1u, &s1);
    TEST_ASSERT_EQUAL_UINT(1u, s0);
    TEST_ASSERT_EQUAL_UINT(8u, s1);
}

/* Annuli exist up to the largest cutoff, MCS_MAX_FREQ: ring sizes are exact
 * there (against a count over the square) and every annulus read-out of a
 * larger radius is refused, whatever its size, with *out untouched
 * (finding N2: radius SIZE_MAX looped for ever, ring_size(SIZE_MAX) gave 0). */
static void test_annulus_read_outs_stop_at_the_largest_cutoff(void)
{
    const long fmax = MCS_MAX_FREQ;
    for (long r = 0; r <= fmax; ++r) {
        size_t want = 0u, size = 0u;
        for (long fy = -r - 1; fy <= r + 1; ++fy)
            for (long fx = -r - 1; fx <= r + 1; ++fx)
                want += fx * fx + fy * fy >= r * r && fx * fx + fy * fy < (r + 1) * (r + 1);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_ring_size((size_t)r, &size));
        TEST_ASSERT_EQUAL_UINT(want, size);
    }
    mcs_pattern2d p = points_pattern2d(MCS_PATTERN2D_JITTERED, 6u, 3u, 2u);
    double v = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_exact_radial(&p, (size_t)fmax, &v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_exact_anisotropy(&p, (size_t)fmax, &v));
    const size_t past[3] = {(size_t)fmax + 1u, (size_t)1 << 31, SIZE_MAX};
    for (int c = 0; c < 3; ++c) {
        size_t size = 7u;
        v = -1.0;
        TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset2d_ring_size(past[c], &size));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset2d_exact_radial(&p, past[c], &v));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE,
                              mcs_pointset2d_exact_anisotropy(&p, past[c], &v));
        TEST_ASSERT_EQUAL_UINT(7u, size);
        TEST_ASSERT_EQUAL_DOUBLE(-1.0, v);
    }
}

/* Measured <P(f)> against the exact spectrum at every |fx|, |fy| <= F and the
 * annulus averages against the exact ones, within 5 standard errors (1e-9 K
 * for the deterministic grids). */
static void check_kind_against_exact(const mcs_pattern2d *pat, int trials, size_t fmax, uint64_t seed)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, seed, 77u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&acc, fmax));
    for (int t = 0; t < trials; ++t) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_draw(pat, &rng, pat->k, pts));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc, pat->k, pts));
    }
    const double tiny = 1e-9 * (double)pat->k;
    for (long fy = -(long)fmax; fy <= (long)fmax; ++fy)
        for (long fx = -(long)fmax; fx <= (long)fmax; ++fx) {
            double p = 0.0, se = 0.0, ex = 0.0;
            mcs_pointset2d_power(&acc, fx, fy, &p);
            mcs_pointset2d_power_stderr(&acc, fx, fy, &se);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_exact_power(pat, fx, fy, &ex));
            TEST_ASSERT_DOUBLE_WITHIN(5.0 * se + tiny, ex, p);
        }
    for (size_t r = 0; r <= fmax; ++r) {
        double p = 0.0, se = 0.0, ex = 0.0;
        mcs_pointset2d_radial(&acc, r, &p);
        mcs_pointset2d_radial_stderr(&acc, r, &se);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_exact_radial(pat, r, &ex));
        TEST_ASSERT_DOUBLE_WITHIN(5.0 * se + tiny, ex, p);
    }
}

static void test_random_and_jittered_points_match_their_exact_spectra(void)
{
    mcs_pattern2d p = points_pattern2d(MCS_PATTERN2D_RANDOM, 9u, 0u, 0u);
    check_kind_against_exact(&p, 4000, 8u, 1u);
    p = points_pattern2d(MCS_PATTERN2D_JITTERED, 12u, 4u, 3u);
    check_kind_against_exact(&p, 20000, 9u, 2u);
    p = points_pattern2d(MCS_PATTERN2D_JITTERED, 5u, 5u, 1u);
    check_kind_against_exact(&p, 10000, 6u, 3u);
}

static void test_grids_give_the_exact_comb_with_or_without_the_shift(void)
{
    mcs_pattern2d p = points_pattern2d(MCS_PATTERN2D_GRID, 6u, 3u, 2u);
    check_kind_against_exact(&p, 3, 10u, 4u);
    p = points_pattern2d(MCS_PATTERN2D_SHIFTED_GRID, 6u, 3u, 2u);
    check_kind_against_exact(&p, 50, 10u, 5u);
    double v = 0.0;
    mcs_pointset2d_exact_power(&p, 3, -4, &v);
    TEST_ASSERT_EQUAL_DOUBLE(6.0, v);
    mcs_pointset2d_exact_power(&p, 3, 1, &v);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, v);
}

static void test_n_rooks_points_match_their_exact_spectrum(void)
{
    mcs_pattern2d p = points_pattern2d(MCS_PATTERN2D_NROOKS, 5u, 0u, 0u);
    check_kind_against_exact(&p, 40000, 6u, 6u);
    p = points_pattern2d(MCS_PATTERN2D_NROOKS, 1u, 0u, 0u);
    check_kind_against_exact(&p, 2000, 3u, 7u);
}

/* With many trials the measured anisotropy converges to the exact one (the
 * trial noise adds about Var(P) / T to the annulus variance). */
static void assert_anisotropy_matches_exact(const mcs_pattern2d *p, size_t r_lo, size_t r_hi)
{
    for (size_t r = r_lo; r <= r_hi; ++r) {
        double meas = 0.0, ex = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_anisotropy(&acc, r, &meas));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_exact_anisotropy(p, r, &ex));
        TEST_ASSERT_TRUE(ex > -20.0); /* well above the trial noise, about -43 dB */
        TEST_ASSERT_DOUBLE_WITHIN(0.5, ex, meas);
    }
}

static void test_anisotropy_of_jittered_and_n_rooks_points_converges_to_the_exact_one(void)
{
    mcs_pattern2d p = points_pattern2d(MCS_PATTERN2D_JITTERED, 16u, 4u, 4u);
    check_kind_against_exact(&p, 20000, 8u, 8u);
    assert_anisotropy_matches_exact(&p, 1u, 2u);
    double v = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pointset2d_anisotropy(&acc, 0u, &v));
    p = points_pattern2d(MCS_PATTERN2D_NROOKS, 16u, 0u, 0u);
    check_kind_against_exact(&p, 20000, 8u, 9u);
    assert_anisotropy_matches_exact(&p, 1u, 7u);
    /* Random points are exactly isotropic: no finite exact anisotropy. */
    p = points_pattern2d(MCS_PATTERN2D_RANDOM, 16u, 0u, 0u);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pointset2d_exact_anisotropy(&p, 3u, &v));
}

/* psa's definition, recomputed here from the power read-outs. */
static void test_anisotropy_is_psa_variance_over_squared_mean_in_decibels(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 3u, 3u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&acc, 7u));
    for (int t = 0; t < 30; ++t) {
        points_uniform(&rng, 2 * 10u, pts);
        mcs_pointset2d_add(&acc, 10u, pts);
    }
    for (size_t r = 1; r <= 7u; ++r) {
        double vals[256];
        size_t n = 0u;
        for (long fy = -7; fy <= 7; ++fy)
            for (long fx = -7; fx <= 7; ++fx) {
                double d = sqrt((double)(fx * fx + fy * fy));
                if (d >= (double)r && d < (double)r + 1.0)
                    mcs_pointset2d_power(&acc, fx, fy, &vals[n++]);
            }
        double mean = 0.0, var = 0.0, got = 0.0;
        for (size_t i = 0; i < n; ++i)
            mean += vals[i] / (double)n;
        for (size_t i = 0; i < n; ++i)
            var += (vals[i] - mean) * (vals[i] - mean) / (double)(n - 1u);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_anisotropy(&acc, r, &got));
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 10.0 * log10(var / (mean * mean)), got);
    }
}

static void test_merge_of_halves_equals_one_pass(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 4u, 1u);
    mcs_pointset2d_init(&acc, 6u);
    mcs_pointset2d_init(&acc2, 6u);
    mcs_pointset2d_init(&acc3, 6u);
    for (int t = 0; t < 200; ++t) {
        size_t k = 1u + (size_t)t % 7u;
        points_uniform(&rng, 2 * k, pts);
        mcs_pointset2d_add(&acc, k, pts);
        mcs_pointset2d_add(t < 70 ? &acc2 : &acc3, k, pts);
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_merge(&acc2, &acc3));
    uint64_t n = 0u;
    mcs_pointset2d_count(&acc2, &n);
    TEST_ASSERT_EQUAL_UINT64(200u, n);
    for (long fy = -6; fy <= 6; ++fy)
        for (long fx = -6; fx <= 6; ++fx) {
            double a = 0.0, b = 0.0, sa = 0.0, sb = 0.0;
            mcs_pointset2d_power(&acc, fx, fy, &a);
            mcs_pointset2d_power(&acc2, fx, fy, &b);
            mcs_pointset2d_power_stderr(&acc, fx, fy, &sa);
            mcs_pointset2d_power_stderr(&acc2, fx, fy, &sb);
            points_assert_merged(a, sa, b, sb);
        }
    for (size_t r = 0; r <= 6u; ++r) {
        double a = 0.0, b = 0.0, sa = 0.0, sb = 0.0;
        mcs_pointset2d_radial(&acc, r, &a);
        mcs_pointset2d_radial(&acc2, r, &b);
        mcs_pointset2d_radial_stderr(&acc, r, &sa);
        mcs_pointset2d_radial_stderr(&acc2, r, &sb);
        points_assert_merged(a, sa, b, sb);
    }
}

static void test_bad_input_returns_an_error_and_changes_nothing(void)
{
    double out = -1.0;
    uint64_t n = 0u;
    memset(&acc2, 0, sizeof acc2);
    snapshot = acc2;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset2d_init(NULL, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset2d_init(&acc2, 0u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset2d_init(&acc2, MCS_MAX_FREQ + 1u));
    TEST_ASSERT_EQUAL_MEMORY(&snapshot, &acc2, sizeof acc2);

    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&acc, 5u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_pointset2d_power(&acc, 1, 0, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_pointset2d_radial(&acc, 1u, &out));
    pts[0] = 0.1;
    pts[1] = 0.2;
    pts[2] = 0.3;
    pts[3] = 0.4;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc, 2u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_pointset2d_power_stderr(&acc, 1, 0, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_pointset2d_radial_stderr(&acc, 1u, &out));
    snapshot = acc;
    const double bad[4] = {1.0, -1e-300, NAN, -INFINITY};
    for (int b = 0; b < 4; ++b) {
        pts[3] = bad[b];
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pointset2d_add(&acc, 2u, pts));
    }
    pts[3] = 0.4;
    pts[0] = 1.5;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pointset2d_add(&acc, 2u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pointset2d_add(&acc, 0u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset2d_add(&acc, 2u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pointset2d_add(&acc2, 2u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pointset2d_merge(&acc, &acc2));
    mcs_pointset2d_init(&acc3, 4u);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_pointset2d_merge(&acc, &acc3));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset2d_merge(NULL, &acc3));
    TEST_ASSERT_EQUAL_MEMORY(&snapshot, &acc, sizeof acc);

    out = -1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset2d_power(&acc, 6, 0, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset2d_power(&acc, 0, -6, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset2d_radial(&acc, 6u, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset2d_anisotropy(&acc, 6u, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pointset2d_power(&acc2, 0, 0, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pointset2d_count(&acc2, &n));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset2d_radial(&acc, 1u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset2d_ring_size(1u, NULL));
    mcs_pattern2d p = points_pattern2d(MCS_PATTERN2D_CMJ, 4u, 0u, 0u), bad_pat = p;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_pointset2d_exact_power(&p, 1, 1, &out));
    p.kind = MCS_PATTERN2D_MULTI_JITTERED;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_pointset2d_exact_radial(&p, 1u, &out));
    bad_pat.kind = MCS_PATTERN2D_JITTERED;
    bad_pat.strata_x = 3u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pointset2d_exact_power(&bad_pat, 1, 1, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset2d_exact_power(NULL, 1, 1, &out));
    TEST_ASSERT_EQUAL_DOUBLE(-1.0, out);
}

static uint64_t *count_of(void *a) { return &((mcs_pointset2d *)a)->count; }
static int add_one(void *a) { return mcs_pointset2d_add(a, 2u, pts); }
static int merge(void *dst, const void *src) { return mcs_pointset2d_merge(dst, src); }

static void test_the_trial_count_stops_at_mcs_max_count_and_never_wraps(void)
{
    const points_counted kind = {sizeof acc, count_of, add_one, merge};
    for (int j = 0; j < 4; ++j)
        pts[j] = 0.125 + 0.25 * j; /* two points in 1D or 2D */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&acc, 3u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&acc2, 3u));
    points_assert_count_bound(&kind, &acc, &acc2, &acc3, &snapshot);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_one_trial_matches_the_direct_sum_at_every_wave_vector);
    RUN_TEST(test_radial_average_of_one_trial_is_the_whole_plane_annulus_mean);
    RUN_TEST(test_annulus_read_outs_stop_at_the_largest_cutoff);
    RUN_TEST(test_random_and_jittered_points_match_their_exact_spectra);
    RUN_TEST(test_grids_give_the_exact_comb_with_or_without_the_shift);
    RUN_TEST(test_n_rooks_points_match_their_exact_spectrum);
    RUN_TEST(test_anisotropy_of_jittered_and_n_rooks_points_converges_to_the_exact_one);
    RUN_TEST(test_anisotropy_is_psa_variance_over_squared_mean_in_decibels);
    RUN_TEST(test_merge_of_halves_equals_one_pass);
    RUN_TEST(test_bad_input_returns_an_error_and_changes_nothing);
    RUN_TEST(test_the_trial_count_stops_at_mcs_max_count_and_never_wraps);
    return UNITY_END();
}
