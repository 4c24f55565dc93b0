/* Tests for the merges of the point-set and binned 2D accumulators on
 * objects that overlap in memory without being the same object: refused
 * with MCS_ERR_ALIAS, both unchanged, as the spectrum, moment and autocorr
 * merges refuse them; a merge into itself (src == dst) still doubles. */
#include "mcspec.h"
#include "points_ref.h"
#include "unity.h"

#include <stddef.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

static double pts[2 * 8];

/* Two set-up accumulators of one type in an arena, src starting at dst's
 * scratch (its last scratch arrays for spectrum2d, whose twiddles follow
 * its first), so each is a valid object: dst gets its trials first
 * (its add writes the scratch src then takes), then src is set up and gets
 * its own. */
#define OVERLAP_ARENA(type)                                                                  \
    static union {                                                                           \
        type align;                                                                          \
        unsigned char bytes[2u * sizeof(type)];                                              \
    } arena_##type;                                                                          \
    static unsigned char copy_##type[2u * sizeof(type)]

OVERLAP_ARENA(mcs_pointset);
OVERLAP_ARENA(mcs_pointset2d);
OVERLAP_ARENA(mcs_spectrum2d);

static void add_trials(int (*add)(void *, const double *), void *acc, uint64_t seed)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, seed, 3u);
    for (int t = 0; t < 5; ++t) {
        points_uniform(&rng, 16u, pts);
        TEST_ASSERT_EQUAL_INT(MCS_OK, add(acc, pts));
    }
}

static int add_pointset(void *acc, const double *p) { return mcs_pointset_add(acc, 8u, p); }
static int add_pointset2d(void *acc, const double *p) { return mcs_pointset2d_add(acc, 8u, p); }
static int add_spectrum2d(void *acc, const double *p)
{
    return mcs_spectrum2d_add_points(acc, 8u, p, NULL);
}

static void test_a_pointset_merge_of_overlapping_objects_is_refused(void)
{
    mcs_pointset *dst = &arena_mcs_pointset.align;
    mcs_pointset *src = (mcs_pointset *)(void *)(arena_mcs_pointset.bytes + offsetof(mcs_pointset, re));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(dst, 6u));
    add_trials(add_pointset, dst, 1u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(src, 6u));
    add_trials(add_pointset, src, 2u);
    memcpy(copy_mcs_pointset, arena_mcs_pointset.bytes, sizeof copy_mcs_pointset);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pointset_merge(dst, src));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pointset_merge(src, dst));
    TEST_ASSERT_EQUAL_MEMORY(copy_mcs_pointset, arena_mcs_pointset.bytes, sizeof copy_mcs_pointset);
    double before = 0.0, after = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power(dst, 3, &before));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_merge(dst, dst)); /* itself: doubles */
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power(dst, 3, &after));
    TEST_ASSERT_EQUAL_UINT64(10u, dst->count);
    TEST_ASSERT_EQUAL_DOUBLE(before, after);
}

static void test_a_pointset2d_merge_of_overlapping_objects_is_refused(void)
{
    mcs_pointset2d *dst = &arena_mcs_pointset2d.align;
    mcs_pointset2d *src =
        (mcs_pointset2d *)(void *)(arena_mcs_pointset2d.bytes + offsetof(mcs_pointset2d, re));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(dst, 3u));
    add_trials(add_pointset2d, dst, 1u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(src, 3u));
    add_trials(add_pointset2d, src, 2u);
    memcpy(copy_mcs_pointset2d, arena_mcs_pointset2d.bytes, sizeof copy_mcs_pointset2d);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pointset2d_merge(dst, src));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_pointset2d_merge(src, dst));
    TEST_ASSERT_EQUAL_MEMORY(copy_mcs_pointset2d, arena_mcs_pointset2d.bytes,
                             sizeof copy_mcs_pointset2d);
    double before = 0.0, after = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_power(dst, 1, 2, &before));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_merge(dst, dst));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_power(dst, 1, 2, &after));
    TEST_ASSERT_EQUAL_UINT64(10u, dst->count);
    TEST_ASSERT_EQUAL_DOUBLE(before, after);
}

static void test_a_spectrum2d_merge_of_overlapping_objects_is_refused(void)
{
    mcs_spectrum2d *dst = &arena_mcs_spectrum2d.align;
    mcs_spectrum2d *src =
        (mcs_spectrum2d *)(void *)(arena_mcs_spectrum2d.bytes + offsetof(mcs_spectrum2d, rows));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_init(dst, 4u, 3u));
    add_trials(add_spectrum2d, dst, 1u);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_init(src, 4u, 3u));
    add_trials(add_spectrum2d, src, 2u);
    memcpy(copy_mcs_spectrum2d, arena_mcs_spectrum2d.bytes, sizeof copy_mcs_spectrum2d);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_spectrum2d_merge(dst, src));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, mcs_spectrum2d_merge(src, dst));
    TEST_ASSERT_EQUAL_MEMORY(copy_mcs_spectrum2d, arena_mcs_spectrum2d.bytes,
                             sizeof copy_mcs_spectrum2d);
    double before = 0.0, after = 0.0;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_power(dst, 1u, 2u, &before));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_merge(dst, dst));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_spectrum2d_power(dst, 1u, 2u, &after));
    TEST_ASSERT_EQUAL_UINT64(10u, dst->count);
    TEST_ASSERT_EQUAL_DOUBLE(before, after);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_pointset_merge_of_overlapping_objects_is_refused);
    RUN_TEST(test_a_pointset2d_merge_of_overlapping_objects_is_refused);
    RUN_TEST(test_a_spectrum2d_merge_of_overlapping_objects_is_refused);
    return UNITY_END();
}
