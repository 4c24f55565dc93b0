#include "mcspec/pattern2d.h"
#include "mcspec/pointset2d.h"
#include "mcspec/rng.h"
#include "nufft_skip.h"
#include "points_ref.h"
#include "unity.h"

#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define MAXK 256

/* An accumulator and its buffer (F up to 40): the whole is what "changes
 * nothing" compares. */
typedef struct {
    mcs_pointset2d h;
    _Alignas(64) unsigned char mem[MCS_POINTSET2D_SIZE(40u)];
} obj;
static obj o_acc, o_acc2, o_acc3, o_snap;
#define acc (o_acc.h)
#define acc2 (o_acc2.h)
#define acc3 (o_acc3.h)
static double pts[2 * MAXK];

static mcs_status init(mcs_pointset2d *a, size_t f)
{
    obj *o = (obj *)(void *)a;
    return mcs_pointset2d_init(&o->h, f, 0u, o->mem, sizeof o->mem);
}

static void test_one_trial_matches_the_direct_sum_at_every_wave_vector(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 1u, 9u);
    const size_t ks[3] = {1u, 13u, 100u};
    const size_t fmax = 40; /* past one re-anchoring */
    for (int c = 0; c < 3; ++c) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, fmax));
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
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, (size_t)fmax));
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

/* Annuli exist up to the largest cutoff, MCS_POINTSET2D_MAX_FREQ: ring
 * sizes are exact (against a count over the square, to 64), the annulus
 * read-outs of the largest take O(radius) steps, and every one of a larger
 * radius is refused, whatever its size, with *out untouched (finding N2:
 * radius SIZE_MAX looped for ever, ring_size(SIZE_MAX) gave 0). */
static void test_annulus_read_outs_stop_at_the_largest_cutoff(void)
{
    for (long r = 0; r <= 64; ++r) {
        size_t want = 0u, size = 0u;
        for (long fy = -r - 1; fy <= r + 1; ++fy)
            for (long fx = -r - 1; fx <= r + 1; ++fx)
                want += fx * fx + fy * fy >= r * r && fx * fx + fy * fy < (r + 1) * (r + 1);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_ring_size((size_t)r, &size));
        TEST_ASSERT_EQUAL_UINT(want, size);
    }
    const size_t fmax = MCS_POINTSET2D_MAX_FREQ;
    size_t size = 0u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_ring_size(fmax, &size));
    TEST_ASSERT_TRUE(size > 6u * fmax && size < 7u * fmax); /* about 2 pi r */
    mcs_pattern2d p = points_pattern2d(MCS_PATTERN2D_JITTERED, 6u, 3u, 2u);
    double v = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_exact_radial(&p, fmax, &v));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_exact_anisotropy(&p, fmax, &v));
    const size_t past[3] = {fmax + 1u, (size_t)1 << 31, SIZE_MAX};
    for (int c = 0; c < 3; ++c) {
        size = 7u;
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
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, fmax));
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
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 7u));
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
    init(&acc, 6u);
    init(&acc2, 6u);
    init(&acc3, 6u);
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
    memset(&o_acc2, 0, sizeof o_acc2);
    o_snap = o_acc2;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset2d_init(NULL, 4u, 0u, o_acc2.mem, sizeof o_acc2.mem));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, init(&acc2, 0u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset2d_init(&acc2, MCS_POINTSET2D_MAX_FREQ + 1u,
                                                                  0u, o_acc2.mem, SIZE_MAX));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_SPACE, init(&acc2, 200u));
    TEST_ASSERT_EQUAL_MEMORY(&o_snap, &o_acc2, sizeof o_acc2);

    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 5u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_pointset2d_power(&acc, 1, 0, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_pointset2d_radial(&acc, 1u, &out));
    pts[0] = 0.1;
    pts[1] = 0.2;
    pts[2] = 0.3;
    pts[3] = 0.4;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc, 2u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_pointset2d_power_stderr(&acc, 1, 0, &out));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_pointset2d_radial_stderr(&acc, 1u, &out));
    o_snap = o_acc;
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
    init(&acc3, 4u);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_pointset2d_merge(&acc, &acc3));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset2d_merge(NULL, &acc3));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset2d_add_planar(&acc, 2u, pts, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pointset2d_add_planar(&acc, 2u, NULL, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pointset2d_add(&acc, 2u, acc.re));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pointset2d_add_planar(&acc, 2u, pts, acc.mean));
    TEST_ASSERT_EQUAL_MEMORY(&o_snap, &o_acc, sizeof o_acc);

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

static uint64_t *count_of(void *a) { return &((mcs_pointset2d *)a)->state->count; }
static int add_one(void *a) { return mcs_pointset2d_add(a, 2u, pts); }
static int merge(void *dst, const void *src) { return mcs_pointset2d_merge(dst, src); }

static void test_the_trial_count_stops_at_mcs_max_count_and_never_wraps(void)
{
    const points_counted kind = {sizeof o_acc, count_of, add_one, merge};
    for (int j = 0; j < 4; ++j)
        pts[j] = 0.125 + 0.25 * j; /* two points in 1D or 2D */
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 3u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc2, 3u));
    points_assert_count_bound(&kind, &o_acc, &o_acc2, &o_acc3, &o_snap);
}


/* ---- run-time sizes, paths, layouts and wrap ---- */

static void test_the_size_macro_bounds_the_size_query_and_the_caps_fit(void)
{
    static char fits_a_static_buffer[MCS_POINTSET2D_SIZE(16u)];
    (void)fits_a_static_buffer;
    size_t prev = 0u, bytes = 0u, direct = 0u;
    for (size_t f = 1u; f <= 2100u; f += f < 100u ? 1u : 53u) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_size(f, 0u, &bytes));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_size(f, MCS_POINTSET_DIRECT_ONLY, &direct));
        TEST_ASSERT_TRUE(bytes <= MCS_POINTSET2D_SIZE(f));
        TEST_ASSERT_EQUAL_UINT64((uint64_t)MCS_POINTSET2D_SIZE_DIRECT(f), (uint64_t)direct);
        /* without the NUFFT (config.h) flags 0 take the direct size */
        TEST_ASSERT_TRUE((MCS_CONFIG_NUFFT ? direct < bytes : direct == bytes) && bytes >= prev);
        prev = bytes;
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_size(2048u, 0u, &bytes));
    TEST_ASSERT_TRUE(bytes < (size_t)1600 << 20); /* fits a 32-bit size_t, as its cap there */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_size(MCS_POINTSET2D_MAX_FREQ, 0u, &bytes));
    TEST_ASSERT_TRUE(bytes <= MCS_POINTSET2D_SIZE(MCS_POINTSET2D_MAX_FREQ));
    bytes = 7u;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset2d_size(MCS_POINTSET2D_MAX_FREQ + 1u, 0u, &bytes));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_FREQ_RANGE, mcs_pointset2d_size(SIZE_MAX, 0u, &bytes));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pointset2d_size(4u, 4u, &bytes));
    TEST_ASSERT_EQUAL_UINT64(7u, bytes);
}

/* Planar arrays give the bits of interleaved points, as double or float,
 * on the direct path and the NUFFT's (with several transforms a set: F = 4
 * takes 4096 points a transform), wrapped or not. */
static void test_planar_points_equal_interleaved_ones_bit_for_bit(void)
{
    enum { K = 10000 };
    static double xy[2 * K], xs[K], ys[K];
    static float xyf[2 * K], xsf[K], ysf[K];
    static obj planar, planar_f, inter_f;
    mcs_rng rng;
    mcs_rng_seed(&rng, 11u, 11u);
    for (size_t j = 0; j < K; ++j) {
        float a = 0.0f, b = 0.0f;
        double u = 0.0, v = 0.0;
        mcs_rng_double(&rng, &u);
        mcs_rng_double(&rng, &v);
        a = (float)u < 1.0f ? (float)u : 0.5f;
        b = j >= 5000u && j % 1000u == 7u ? 1.0f : ((float)v < 1.0f ? (float)v : 0.5f);
        xyf[2u * j] = xsf[j] = a;
        xyf[2u * j + 1u] = ysf[j] = b;
        xy[2u * j] = xs[j] = (double)a;
        xy[2u * j + 1u] = ys[j] = (double)b;
    }
    for (int path = MCS_POINTSET_PATH_DIRECT; path <= MCS_TEST_LAST_PATH; ++path) {
        obj *const all[4] = {&o_acc, &planar, &planar_f, &inter_f};
        for (int i = 0; i < 4; ++i) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, init(&all[i]->h, 4u));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_set_path(&all[i]->h, (mcs_pointset_path)path));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_set_wrap(&all[i]->h, 1));
        }
        /* 5000 points without a 1.0 (two transforms of the caller's points
         * where they are), then all, with 1.0s to wrap (staged) */
        for (size_t n = 5000u; n <= K; n += K - 5000u) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc, n, xy));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add_planar(&planar.h, n, xs, ys));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add_planar_f(&planar_f.h, n, xsf, ysf));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add_f(&inter_f.h, n, xyf));
        }
        const size_t cells = 10u * 5u;
        for (int i = 1; i < 4; ++i) {
            TEST_ASSERT_EQUAL_MEMORY(acc.mean, all[i]->h.mean, cells * sizeof(double));
            TEST_ASSERT_EQUAL_MEMORY(acc.m2, all[i]->h.m2, cells * sizeof(double));
            TEST_ASSERT_EQUAL_MEMORY(acc.ring_mean, all[i]->h.ring_mean, 5u * sizeof(double));
            TEST_ASSERT_EQUAL_MEMORY(acc.ring_m2, all[i]->h.ring_m2, 5u * sizeof(double));
        }
    }
}

/* The 2D wrap: a coordinate of 1.0 is 0.0 exactly (x or y); 1.5, -0.1 and
 * NaN stay refused; without wrap 1.0 is refused. */
static void test_wrap_takes_one_as_zero_and_still_refuses_the_rest(void)
{
    static double zero[2 * MAXK];
    mcs_rng rng;
    mcs_rng_seed(&rng, 12u, 12u);
    points_uniform(&rng, 2u * MAXK, pts);
    for (size_t j = 0; j < 2u * MAXK; ++j) {
        pts[j] = j % 9u == 4u ? 1.0 : pts[j];
        zero[j] = pts[j] == 1.0 ? 0.0 : pts[j];
    }
    for (int path = MCS_POINTSET_PATH_DIRECT; path <= MCS_TEST_LAST_PATH; ++path) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 20u));
        TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc2, 20u));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_set_path(&acc, (mcs_pointset_path)path));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_set_path(&acc2, (mcs_pointset_path)path));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pointset2d_add(&acc, MAXK, pts));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_set_wrap(&acc, 1));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc, MAXK, pts));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc2, MAXK, zero));
        const size_t cells = 42u * 21u;
        TEST_ASSERT_EQUAL_MEMORY(acc2.mean, acc.mean, cells * sizeof(double));
        TEST_ASSERT_EQUAL_MEMORY(acc2.ring_mean, acc.ring_mean, 21u * sizeof(double));
        o_snap = o_acc;
        const double bad[3] = {1.5, -0.1, NAN};
        for (int i = 0; i < 3; ++i) {
            const double keep = pts[7];
            pts[7] = bad[i];
            TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pointset2d_add(&acc, MAXK, pts));
            TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pointset2d_add_planar(&acc, 7u, pts + 1, pts));
            pts[7] = keep;
        }
        TEST_ASSERT_EQUAL_MEMORY(&o_snap, &o_acc, sizeof o_acc);
    }
}

/* Random, jittered (a sqrt(K) x sqrt(K) grid of strata) and clustered (half
 * the points within 1e-3 of (0.3, 0.7)) sets of k points. */
static void draw_set(int kind, mcs_rng *rng, size_t k, double *p)
{
    const size_t m = (size_t)sqrt((double)k);
    for (size_t j = 0; j < k; ++j) {
        double u = 0.0, v = 0.0;
        mcs_rng_double(rng, &u);
        mcs_rng_double(rng, &v);
        if (kind == 1) {
            u = ((double)(j % m) + u) / (double)m;
            v = ((double)(j / m) + v) / (double)m;
        } else if (kind == 2 && j % 2u) {
            u = 0.3 + 1e-3 * u;
            v = 0.7 + 1e-3 * v;
        }
        p[2u * j] = u;
        p[2u * j + 1u] = v;
    }
}

/* The largest |a - b| / max(P_b, 1) over every stored wave vector and
 * annulus, of the means (want 0) or the standard errors (1), each scaled by
 * b's mean there (as in 1D: the criterion is relative to the periodogram). */
static double worst_gap(const mcs_pointset2d *a, const mcs_pointset2d *b, int want_stderr)
{
    const long f = (long)a->freq_max;
    double worst = 0.0;
    for (long fy = 0; fy <= f; ++fy)
        for (long fx = -f; fx <= f; ++fx) {
            double pa = 0.0, pb = 0.0, scale = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_power(b, fx, fy, &scale));
            TEST_ASSERT_EQUAL_INT(MCS_OK, (want_stderr ? mcs_pointset2d_power_stderr
                                                       : mcs_pointset2d_power)(a, fx, fy, &pa));
            TEST_ASSERT_EQUAL_INT(MCS_OK, (want_stderr ? mcs_pointset2d_power_stderr
                                                       : mcs_pointset2d_power)(b, fx, fy, &pb));
            const double gap = fabs(pa - pb) / fmax(scale, 1.0);
            worst = gap > worst ? gap : worst;
        }
    for (size_t r = 0; r <= (size_t)f; ++r) {
        double pa = 0.0, pb = 0.0, scale = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial(b, r, &scale));
        TEST_ASSERT_EQUAL_INT(MCS_OK, (want_stderr ? mcs_pointset2d_radial_stderr
                                                   : mcs_pointset2d_radial)(a, r, &pa));
        TEST_ASSERT_EQUAL_INT(MCS_OK, (want_stderr ? mcs_pointset2d_radial_stderr
                                                   : mcs_pointset2d_radial)(b, r, &pb));
        const double gap = fabs(pa - pb) / fmax(scale, 1.0);
        worst = gap > worst ? gap : worst;
    }
    return worst;
}

/* K = 4096 points at F = 160 (half utk's 5 sqrt(K), which keeps the direct
 * sum near 0.1 s a set), two trials per kind:
 * the NUFFT path agrees with the direct sum to 1e-9 max(P, 1) at every wave
 * vector and annulus, for the means and the standard errors. */
static void test_the_nufft_path_agrees_with_the_direct_sum(void)
{
    MCS_TEST_NEEDS_NUFFT();
    enum { K = 4096, F = 160, T = 2 };
    static double set[2 * K];
    static _Alignas(64) unsigned char mem_d[MCS_POINTSET2D_SIZE(F)], mem_n[MCS_POINTSET2D_SIZE(F)];
    static mcs_pointset2d d, n;
    mcs_rng rng;
    mcs_rng_seed(&rng, 13u, 13u);
    for (int kind = 0; kind < 3; ++kind) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&d, F, 0u, mem_d, sizeof mem_d));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&n, F, 0u, mem_n, sizeof mem_n));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_set_path(&d, MCS_POINTSET_PATH_DIRECT));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_set_path(&n, MCS_POINTSET_PATH_NUFFT));
        for (int t = 0; t < T; ++t) {
            draw_set(kind, &rng, K, set);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&d, K, set));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&n, K, set));
        }
        TEST_ASSERT_TRUE(worst_gap(&n, &d, 0) <= 1e-9);
        TEST_ASSERT_TRUE(worst_gap(&n, &d, 1) <= 1e-9);
    }
}

/* AUTO: the direct sum at a small K F^2, the NUFFT at a large one. */
static void test_auto_picks_the_nufft_for_large_k_f_and_the_direct_sum_for_small(void)
{
    mcs_pointset_path p = MCS_POINTSET_PATH_AUTO;
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 40u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_path_for(&acc, 16384u, &p));
#if !MCS_CONFIG_NUFFT
    /* Built without the NUFFT (config.h): AUTO is the direct sum, the NUFFT refused. */
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_DIRECT, p);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pointset2d_set_path(&acc, MCS_POINTSET_PATH_NUFFT));
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_AUTO, acc.path);
    TEST_ASSERT_TRUE(acc.stage == NULL && acc.plan.dim == 0u);
    MCS_TEST_NEEDS_NUFFT();
#endif
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_NUFFT, p);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_path_for(&acc, 8u, &p));
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_DIRECT, p);
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 4u));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_path_for(&acc, 1000000u, &p));
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_DIRECT, p); /* 50 wave vectors: no transform pays */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_path_for(&acc, MCS_POINTSET_NUFFT_MAX_K + 1u, &p));
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_DIRECT, p);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pointset2d_path_for(&acc, 0u, &p));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_set_path(&acc, MCS_POINTSET_PATH_NUFFT));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE,
                          mcs_pointset2d_add(&acc, MCS_POINTSET_NUFFT_MAX_K + 1u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&acc, 4u, MCS_POINTSET_DIRECT_ONLY, o_acc.mem,
                                                      sizeof o_acc.mem));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_DOMAIN, mcs_pointset2d_set_path(&acc, MCS_POINTSET_PATH_NUFFT));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_path_for(&acc, 8u, &p));
    TEST_ASSERT_EQUAL_INT(MCS_POINTSET_PATH_DIRECT, p);
}

/* A copy is its own object over its own buffer; the original's and its
 * read-outs agree, and its trials stay its own. */
static void test_a_copy_is_independent_of_the_original(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 14u, 14u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, init(&acc, 9u));
    for (int t = 0; t < 4; ++t) {
        points_uniform(&rng, 2u * 30u, pts);
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc, 30u, pts));
    }
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pointset2d_copy(&acc2, o_acc.mem, sizeof o_acc.mem, &acc));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_copy(&acc2, o_acc2.mem, sizeof o_acc2.mem, &acc));
    for (size_t r = 0; r <= 9u; ++r) {
        double a = 0.0, b = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial_stderr(&acc, r, &a));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial_stderr(&acc2, r, &b));
        TEST_ASSERT_EQUAL_DOUBLE(a, b);
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&acc2, 30u, pts));
    uint64_t na = 0u, nb = 0u;
    mcs_pointset2d_count(&acc, &na);
    mcs_pointset2d_count(&acc2, &nb);
    TEST_ASSERT_EQUAL_UINT64(4u, na);
    TEST_ASSERT_EQUAL_UINT64(5u, nb);
    mcs_pointset2d shared = acc2;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pointset2d_merge(&acc2, &shared));
    /* and it can move: the object over a new buffer */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_copy(&acc2, o_acc3.mem, sizeof o_acc3.mem, &acc2));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_count(&acc2, &nb));
    TEST_ASSERT_EQUAL_UINT64(5u, nb);
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
    RUN_TEST(test_the_size_macro_bounds_the_size_query_and_the_caps_fit);
    RUN_TEST(test_planar_points_equal_interleaved_ones_bit_for_bit);
    RUN_TEST(test_wrap_takes_one_as_zero_and_still_refuses_the_rest);
    RUN_TEST(test_the_nufft_path_agrees_with_the_direct_sum);
    RUN_TEST(test_auto_picks_the_nufft_for_large_k_f_and_the_direct_sum_for_small);
    RUN_TEST(test_a_copy_is_independent_of_the_original);
    return UNITY_END();
}
