#include "mcspec/pattern2d.h"
#include "mcspec/rng.h"
#include "points_ref.h"
#include "unity.h"

#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define MAXK 256
#define GUARD (-555.0)

static double pts[2 * MAXK + 2];
static unsigned count[MAXK * MAXK];

static const mcs_pattern2d_kind all_kinds[MCS_PATTERN2D_KIND_COUNT] = {
    MCS_PATTERN2D_RANDOM, MCS_PATTERN2D_JITTERED, MCS_PATTERN2D_GRID, MCS_PATTERN2D_SHIFTED_GRID,
    MCS_PATTERN2D_NROOKS, MCS_PATTERN2D_MULTI_JITTERED, MCS_PATTERN2D_CMJ};

/* Every box of a cols x rows partition of the square holds exactly one point. */
static void assert_one_per_box(size_t k, size_t cols, size_t rows)
{
    memset(count, 0, cols * rows * sizeof count[0]);
    for (size_t j = 0; j < k; ++j) {
        size_t c = (size_t)(pts[2 * j] * (double)cols), r = (size_t)(pts[2 * j + 1] * (double)rows);
        TEST_ASSERT_TRUE(c < cols && r < rows);
        count[r * cols + c]++;
    }
    for (size_t b = 0; b < cols * rows; ++b)
        TEST_ASSERT_EQUAL_UINT(1u, count[b]);
}

/* The strata init records for (k, sx, sy) are (want_x, want_y). */
static void assert_strata(mcs_pattern2d_kind kind, size_t k, size_t sx, size_t sy, size_t want_x,
                          size_t want_y)
{
    mcs_pattern2d p = points_pattern2d(kind, k, sx, sy);
    TEST_ASSERT_EQUAL_UINT(want_x, p.strata_x);
    TEST_ASSERT_EQUAL_UINT(want_y, p.strata_y);
}

static void test_default_strata_are_the_most_nearly_square_grid(void)
{
    assert_strata(MCS_PATTERN2D_JITTERED, 12u, 0u, 0u, 4u, 3u);
    assert_strata(MCS_PATTERN2D_JITTERED, 64u, 0u, 0u, 8u, 8u);
    assert_strata(MCS_PATTERN2D_JITTERED, 13u, 0u, 0u, 13u, 1u);
    assert_strata(MCS_PATTERN2D_CMJ, 12u, 2u, 6u, 2u, 6u);
}

static void test_every_kind_writes_k_points_inside_the_unit_square(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 5u, 5u);
    const size_t shapes[4][2] = {{4u, 4u}, {5u, 3u}, {1u, 7u}, {16u, 16u}};
    for (int c = 0; c < MCS_PATTERN2D_KIND_COUNT; ++c)
        for (int s = 0; s < 4; ++s) {
            size_t k = shapes[s][0] * shapes[s][1];
            mcs_pattern2d p = points_pattern2d(all_kinds[c], k, shapes[s][0], shapes[s][1]);
            for (int t = 0; t < 20; ++t) {
                pts[2 * k] = GUARD;
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_draw(&p, &rng, k, pts));
                TEST_ASSERT_EQUAL_DOUBLE(GUARD, pts[2 * k]);
                for (size_t j = 0; j < 2 * k; ++j)
                    TEST_ASSERT_TRUE(pts[j] >= 0.0 && pts[j] < 1.0);
            }
        }
}

static void test_stratified_kinds_keep_their_stratification_every_trial(void)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 6u, 1u);
    const size_t shapes[3][2] = {{4u, 4u}, {5u, 3u}, {2u, 8u}};
    for (int s = 0; s < 3; ++s) {
        size_t m = shapes[s][0], n = shapes[s][1], k = m * n;
        for (int t = 0; t < 50; ++t) {
            mcs_pattern2d p = points_pattern2d(MCS_PATTERN2D_JITTERED, k, m, n);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_draw(&p, &rng, k, pts));
            assert_one_per_box(k, m, n);
            p = points_pattern2d(MCS_PATTERN2D_SHIFTED_GRID, k, m, n);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_draw(&p, &rng, k, pts));
            assert_one_per_box(k, m, n);
            p = points_pattern2d(MCS_PATTERN2D_NROOKS, k, m, n);
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_draw(&p, &rng, k, pts));
            assert_one_per_box(k, k, 1u);
            assert_one_per_box(k, 1u, k);
            for (int mj = 0; mj < 2; ++mj) {
                p = points_pattern2d(mj ? MCS_PATTERN2D_CMJ : MCS_PATTERN2D_MULTI_JITTERED, k, m, n);
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_draw(&p, &rng, k, pts));
                assert_one_per_box(k, m, n);
                assert_one_per_box(k, k, 1u);
                assert_one_per_box(k, 1u, k);
            }
        }
    }
}

static void test_grid_is_the_cell_centres_and_shifted_grid_moves_them_together(void)
{
    mcs_rng rng, rng0;
    mcs_rng_seed(&rng, 7u, 7u);
    rng0 = rng;
    mcs_pattern2d p = points_pattern2d(MCS_PATTERN2D_GRID, 15u, 5u, 3u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_draw(&p, &rng, 15u, pts));
    TEST_ASSERT_EQUAL_MEMORY(&rng0, &rng, sizeof rng); /* deterministic: no draws */
    for (size_t j = 0; j < 3u; ++j)
        for (size_t i = 0; i < 5u; ++i) {
            TEST_ASSERT_EQUAL_DOUBLE((i + 0.5) / 5.0, pts[2 * (j * 5 + i)]);
            TEST_ASSERT_EQUAL_DOUBLE((j + 0.5) / 3.0, pts[2 * (j * 5 + i) + 1]);
        }
    p = points_pattern2d(MCS_PATTERN2D_SHIFTED_GRID, 15u, 5u, 3u);
    for (int t = 0; t < 20; ++t) {
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_draw(&p, &rng, 15u, pts));
        double bx = pts[0] * 5.0, by = pts[1] * 3.0;
        for (size_t j = 0; j < 3u; ++j)
            for (size_t i = 0; i < 5u; ++i) {
                TEST_ASSERT_DOUBLE_WITHIN(1e-14, bx, pts[2 * (j * 5 + i)] * 5.0 - (double)i);
                TEST_ASSERT_DOUBLE_WITHIN(1e-14, by, pts[2 * (j * 5 + i) + 1] * 3.0 - (double)j);
            }
    }
}

static void test_kensler_permute_is_a_permutation_of_every_length(void)
{
    static unsigned char seen[1000];
    const uint32_t lens[6] = {1u, 2u, 3u, 17u, 256u, 1000u};
    for (int l = 0; l < 6; ++l) {
        for (uint32_t key = 0u; key < 5u; ++key) {
            memset(seen, 0, sizeof seen);
            uint32_t moved = 0u;
            for (uint32_t i = 0; i < lens[l]; ++i) {
                uint32_t v = mcs_pattern2d_permute(i, lens[l], key * 0x9e3779b9u);
                TEST_ASSERT_TRUE(v < lens[l]);
                seen[v] = 1u;
                moved += v != i;
            }
            for (uint32_t i = 0; i < lens[l]; ++i)
                TEST_ASSERT_EQUAL_UINT8(1u, seen[i]);
            if (lens[l] >= 17u) {
                TEST_ASSERT_TRUE(moved > lens[l] / 2u); /* it shuffles */
            }
        }
    }
    TEST_ASSERT_EQUAL_UINT32(0u, mcs_pattern2d_permute(5u, 5u, 1u));
    TEST_ASSERT_EQUAL_UINT32(0u, mcs_pattern2d_permute(0u, 0u, 1u));
}

/* The final offset (i + p) mod l must not wrap in 32 bits: with p near 2^32
 * the images of a wrapped sum are not a permutation (finding N1). Every
 * length up to 300 under keys at both ends of the range and near 2^32 - l. */
static void test_kensler_permute_is_a_permutation_for_keys_near_two_to_the_32(void)
{
    static unsigned char seen[300];
    for (uint32_t l = 1u; l <= 300u; ++l) {
        const uint32_t keys[7] = {0u, 1u, 0x7fffffffu, 0x80000000u, 0xffffffffu - l,
                                  0xffffffffu - l / 2u, 0xffffffffu};
        for (int c = 0; c < 7; ++c) {
            memset(seen, 0, sizeof seen);
            for (uint32_t i = 0; i < l; ++i) {
                uint32_t v = mcs_pattern2d_permute(i, l, keys[c]);
                TEST_ASSERT_TRUE(v < l);
                TEST_ASSERT_EQUAL_UINT8(0u, seen[v]); /* no image twice */
                seen[v] = 1u;
            }
        }
    }
}

/* Unbiasedness: the mean number of points in a box B, over the trials, is
 * K |B| for every kind but the (biased) fixed grid. The boxes straddle the
 * strata edges, so a pattern whose points piled up anywhere would fail. */
static void test_every_randomised_kind_puts_k_times_area_points_in_a_box_on_average(void)
{
    enum { T = 3000 };
    const double box[3][4] = {{0.13, 0.58, 0.21, 0.47}, {0.0, 0.31, 0.66, 1.0}, {0.4, 0.9, 0.05, 0.95}};
    mcs_rng rng;
    mcs_rng_seed(&rng, 8u, 3u);
    for (int c = 0; c < MCS_PATTERN2D_KIND_COUNT; ++c) {
        if (all_kinds[c] == MCS_PATTERN2D_GRID)
            continue;
        mcs_pattern2d p = points_pattern2d(all_kinds[c], 12u, 4u, 3u);
        for (int b = 0; b < 3; ++b) {
            double sum = 0.0, sum2 = 0.0, area = (box[b][1] - box[b][0]) * (box[b][3] - box[b][2]);
            for (int t = 0; t < T; ++t) {
                TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_draw(&p, &rng, 12u, pts));
                double n_in = 0.0;
                for (size_t j = 0; j < 12u; ++j)
                    n_in += pts[2 * j] >= box[b][0] && pts[2 * j] < box[b][1] &&
                            pts[2 * j + 1] >= box[b][2] && pts[2 * j + 1] < box[b][3];
                sum += n_in;
                sum2 += n_in * n_in;
            }
            double mean = sum / T, var = (sum2 - sum * mean) / (T - 1);
            TEST_ASSERT_DOUBLE_WITHIN(5.0 * sqrt(var / T) + 1e-12, 12.0 * area, mean);
        }
    }
}

static void test_bad_configuration_returns_an_error_and_changes_nothing(void)
{
    mcs_pattern2d p, before;
    memset(&p, 0x3c, sizeof p);
    before = p;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern2d_init(NULL, MCS_PATTERN2D_RANDOM, 4u, 0u, 0u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_KIND, mcs_pattern2d_init(&p, (mcs_pattern2d_kind)7, 4u, 0u, 0u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pattern2d_init(&p, MCS_PATTERN2D_RANDOM, 0u, 0u, 0u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE,
                          mcs_pattern2d_init(&p, MCS_PATTERN2D_RANDOM,
                                             (size_t)MCS_PATTERN2D_MAX_K + 1u, 0u, 0u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_pattern2d_init(&p, MCS_PATTERN2D_GRID, 12u, 5u, 3u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_pattern2d_init(&p, MCS_PATTERN2D_GRID, 12u, 0u, 3u));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_pattern2d_init(&p, MCS_PATTERN2D_GRID, 12u, 5u, 0u));
    TEST_ASSERT_EQUAL_MEMORY(&before, &p, sizeof p);
    TEST_ASSERT_EQUAL_STRING("n-rooks", mcs_pattern2d_kind_str(MCS_PATTERN2D_NROOKS));
    TEST_ASSERT_EQUAL_STRING("unknown", mcs_pattern2d_kind_str((mcs_pattern2d_kind)70));
}

static void test_bad_draw_writes_nothing_and_does_not_advance_the_rng(void)
{
    mcs_rng rng, rng0;
    mcs_rng_seed(&rng, 1u, 2u);
    rng0 = rng;
    mcs_pattern2d p = points_pattern2d(MCS_PATTERN2D_JITTERED, 4u, 2u, 2u), bad = p;
    bad.strata_y = 3u; /* 2 x 3 != 4: not from init */
    points_guard_fill(pts, 10u, GUARD);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern2d_draw(NULL, &rng, 4u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern2d_draw(&p, NULL, 4u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_NULL, mcs_pattern2d_draw(&p, &rng, 4u, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_pattern2d_draw(&p, &rng, 3u, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pattern2d_draw(&bad, &rng, 4u, pts));
    points_guard_check(pts, 10u, GUARD);
    TEST_ASSERT_EQUAL_MEMORY(&rng0, &rng, sizeof rng);
}

/* A never-seeded (zeroed) generator outputs only zeros: n-rooks and
 * multi-jittered would loop for ever in its bounded draws, the other kinds
 * would return a fixed set as if random. Every kind refuses it, as
 * mcs_pattern_draw does, even the grid that draws nothing from it. */
static void test_draw_with_a_never_seeded_rng_is_refused_and_writes_nothing(void)
{
    mcs_rng rng, rng0;
    memset(&rng, 0, sizeof rng);
    rng0 = rng;
    for (int c = 0; c < MCS_PATTERN2D_KIND_COUNT; ++c) {
        mcs_pattern2d p = points_pattern2d(all_kinds[c], 12u, 4u, 3u);
        points_guard_fill(pts, 26u, GUARD);
        TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pattern2d_draw(&p, &rng, 12u, pts));
        TEST_ASSERT_EQUAL_INT(MCS_ERR_UNINIT, mcs_pattern2d_draw(&p, &rng, 11u, pts));
        points_guard_check(pts, 26u, GUARD);
        TEST_ASSERT_EQUAL_MEMORY(&rng0, &rng, sizeof rng);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_default_strata_are_the_most_nearly_square_grid);
    RUN_TEST(test_every_kind_writes_k_points_inside_the_unit_square);
    RUN_TEST(test_stratified_kinds_keep_their_stratification_every_trial);
    RUN_TEST(test_grid_is_the_cell_centres_and_shifted_grid_moves_them_together);
    RUN_TEST(test_kensler_permute_is_a_permutation_of_every_length);
    RUN_TEST(test_kensler_permute_is_a_permutation_for_keys_near_two_to_the_32);
    RUN_TEST(test_every_randomised_kind_puts_k_times_area_points_in_a_box_on_average);
    RUN_TEST(test_bad_configuration_returns_an_error_and_changes_nothing);
    RUN_TEST(test_bad_draw_writes_nothing_and_does_not_advance_the_rng);
    RUN_TEST(test_draw_with_a_never_seeded_rng_is_refused_and_writes_nothing);
    return UNITY_END();
}
