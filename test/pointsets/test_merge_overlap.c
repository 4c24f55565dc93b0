/* Tests for the merges of the point-set and binned 2D accumulators on
 * objects that overlap in memory without being the same object (their
 * headers or their buffers): refused with MCS_ERR_ALIAS, both unchanged, as
 * the spectrum, moment and autocorr merges refuse them; a merge into itself
 * (src == dst) still doubles. */
#include "mcspec.h"
#include "points_ref.h"
#include "unity.h"

#include <stddef.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

static double pts[2 * 8];

/* The cases of overlap, each with two valid objects: (a) src's buffer
 * starts in dst's scratch (dst gets its trials first, its add writing the
 * scratch src then takes over); (b) src's header sits in dst's scratch, over
 * a buffer of its own; (c) two headers over one buffer (a byte copy of a
 * header: the same object twice, not a copy). Each merge is refused with
 * MCS_ERR_ALIAS, both objects byte for byte unchanged; a merge into itself
 * still doubles the count. */
#define ARENA 400000u
static _Alignas(64) unsigned char arena[ARENA], spare[ARENA], copy_arena[ARENA],
    copy_spare[ARENA];

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

static void snapshot(void)
{
    memcpy(copy_arena, arena, ARENA);
    memcpy(copy_spare, spare, ARENA);
}

static void assert_unchanged(void)
{
    TEST_ASSERT_EQUAL_MEMORY(copy_arena, arena, ARENA);
    TEST_ASSERT_EQUAL_MEMORY(copy_spare, spare, ARENA);
}

/* One type: its init over (mem, bytes), a read-out at a fixed frequency and
 * its add; src goes into dst's scratch S_k, re. */
#define OVERLAP_TEST(name, type, init_call, read_call, add_fn)                         \
    static void test_a_##name##_merge_of_overlapping_objects_is_refused(void)                   \
    {                                                                                          \
        type *dst = (type *)(void *)arena, *src = NULL, hdr_copy;                               \
        unsigned char *mem = arena + 512u;                                                      \
        const size_t bytes = ARENA - 512u;                                                      \
        for (int c = 0; c < 3; ++c) {                                                           \
            memset(arena, 0, ARENA);                                                            \
            memset(spare, 0, ARENA);                                                            \
            TEST_ASSERT_EQUAL_INT(MCS_OK, init_call(dst, mem, bytes));                          \
            add_trials(add_fn, dst, 1u);                                                        \
            unsigned char *in_scratch = (unsigned char *)(void *)dst->re;                  \
            const size_t room = (size_t)(arena + ARENA - in_scratch);                           \
            if (c == 0) {                                                                       \
                src = (type *)(void *)spare;                                                    \
                TEST_ASSERT_EQUAL_INT(MCS_OK, init_call(src, in_scratch, room));                \
            } else if (c == 1) {                                                                \
                src = (type *)(void *)(in_scratch + 64u);                                       \
                TEST_ASSERT_EQUAL_INT(MCS_OK, init_call(src, spare, ARENA));                    \
            } else {                                                                            \
                memcpy(&hdr_copy, dst, sizeof hdr_copy);                                        \
                src = &hdr_copy;                                                                \
            }                                                                                   \
            if (c < 2)                                                                          \
                add_trials(add_fn, src, 2u);                                                    \
            snapshot();                                                                         \
            TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, name##_merge(dst, src));                       \
            TEST_ASSERT_EQUAL_INT(MCS_ERR_ALIAS, name##_merge(src, dst));                       \
            assert_unchanged();                                                                 \
        }                                                                                       \
        double before = 0.0, after = 0.0;                                                       \
        uint64_t count = 0u;                                                                    \
        TEST_ASSERT_EQUAL_INT(MCS_OK, read_call(dst, &before));                                 \
        TEST_ASSERT_EQUAL_INT(MCS_OK, name##_merge(dst, dst)); /* itself: doubles */            \
        TEST_ASSERT_EQUAL_INT(MCS_OK, read_call(dst, &after));                                  \
        TEST_ASSERT_EQUAL_INT(MCS_OK, name##_count(dst, &count));                               \
        TEST_ASSERT_EQUAL_UINT64(10u, count);                                                   \
        TEST_ASSERT_EQUAL_DOUBLE(before, after);                                                \
    }

static mcs_status ps_init(mcs_pointset *a, void *m, size_t b) { return mcs_pointset_init(a, 6u, 0u, m, b); }
static mcs_status ps2_init(mcs_pointset2d *a, void *m, size_t b) { return mcs_pointset2d_init(a, 3u, 0u, m, b); }
static mcs_status s2_init(mcs_spectrum2d *a, void *m, size_t b) { return mcs_spectrum2d_init(a, 4u, 3u, m, b); }
static mcs_status ps_read(const mcs_pointset *a, double *v) { return mcs_pointset_power(a, 3, v); }
static mcs_status ps2_read(const mcs_pointset2d *a, double *v) { return mcs_pointset2d_power(a, 1, 2, v); }
static mcs_status s2_read(const mcs_spectrum2d *a, double *v) { return mcs_spectrum2d_power(a, 1u, 2u, v); }
OVERLAP_TEST(mcs_pointset, mcs_pointset, ps_init, ps_read, add_pointset)
OVERLAP_TEST(mcs_pointset2d, mcs_pointset2d, ps2_init, ps2_read, add_pointset2d)
OVERLAP_TEST(mcs_spectrum2d, mcs_spectrum2d, s2_init, s2_read, add_spectrum2d)

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_mcs_pointset_merge_of_overlapping_objects_is_refused);
    RUN_TEST(test_a_mcs_pointset2d_merge_of_overlapping_objects_is_refused);
    RUN_TEST(test_a_mcs_spectrum2d_merge_of_overlapping_objects_is_refused);
    return UNITY_END();
}
