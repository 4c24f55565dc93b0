/* The point-set batches (pointset_batch.c): T sets in one call and whole
 * read-out arrays, bit for bit the per-set and per-frequency calls; a
 * refused batch changes no byte of the object or its buffer. */
#include "mcspec/pointset.h"
#include "mcspec/pointset2d.h"
#include "mcspec/rng.h"
#include "unity.h"

#include <math.h>
#include <string.h>

void setUp(void) {}
void tearDown(void) {}

#define F1 40u
#define F2 12u
#define SETS 7u
#define K 50u
#define SIDE (2u * F2 + 1u)

typedef struct {
    mcs_pointset h;
    _Alignas(64) unsigned char mem[MCS_POINTSET_SIZE(F1)];
} obj1;
typedef struct {
    mcs_pointset2d h;
    _Alignas(64) unsigned char mem[MCS_POINTSET2D_SIZE(F2)];
} obj2;
static obj1 a1, b1, snap1;
static obj2 a2, b2, snap2;
static double pts[2u * SETS * K];
static float ptsf[2u * SETS * K];
static double got[SIDE * SIDE], want[SIDE * SIDE], got_se[SIDE * SIDE];

static void fill(size_t n)
{
    mcs_rng rng;
    mcs_rng_seed(&rng, 5u, 3u);
    for (size_t i = 0; i < n; ++i) {
        mcs_rng_double(&rng, &pts[i]);
        ptsf[i] = (float)pts[i];
        if (ptsf[i] >= 1.0f)
            ptsf[i] = 0.5f;
    }
}

static void test_a_1d_batch_is_bit_for_bit_the_sets_added_one_by_one(void)
{
    fill(SETS * K);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&a1.h, F1, 0u, a1.mem, sizeof a1.mem));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&b1.h, F1, 0u, b1.mem, sizeof b1.mem));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add_sets(&a1.h, SETS, K, pts));
    for (size_t t = 0; t < SETS; ++t)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add(&b1.h, K, pts + t * K));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_read_all(&a1.h, F1 + 1u, got, got_se));
    for (size_t f = 0; f <= F1; ++f) {
        double p = 0.0, s = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power(&b1.h, (long)f, &p));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_power_stderr(&b1.h, (long)f, &s));
        TEST_ASSERT_EQUAL_MEMORY(&p, &got[f], sizeof p);
        TEST_ASSERT_EQUAL_MEMORY(&s, &got_se[f], sizeof s);
    }
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add_sets_f(&a1.h, SETS, K, ptsf));
    for (size_t t = 0; t < SETS; ++t)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_add_f(&b1.h, K, ptsf + t * K));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_read_all(&a1.h, F1 + 1u, got, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_read_all(&b1.h, F1 + 1u, want, NULL));
    TEST_ASSERT_EQUAL_MEMORY(want, got, (F1 + 1u) * sizeof got[0]);
}

static void test_a_2d_batch_and_its_arrays_are_bit_for_bit_the_single_calls(void)
{
    fill(2u * SETS * K);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&a2.h, F2, 0u, a2.mem, sizeof a2.mem));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&b2.h, F2, 0u, b2.mem, sizeof b2.mem));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add_sets(&a2.h, SETS, K, pts));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add_sets_f(&a2.h, SETS, K, ptsf));
    for (size_t t = 0; t < SETS; ++t)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add(&b2.h, K, pts + 2u * t * K));
    for (size_t t = 0; t < SETS; ++t)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add_f(&b2.h, K, ptsf + 2u * t * K));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_read_all(&a2.h, SIDE, got, got_se));
    const long f = (long)F2;
    for (long fy = -f; fy <= f; ++fy)
        for (long fx = -f; fx <= f; ++fx) {
            const size_t i = (size_t)(fy + f) * SIDE + (size_t)(fx + f);
            double p = 0.0, s = 0.0;
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_power(&b2.h, fx, fy, &p));
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_power_stderr(&b2.h, fx, fy, &s));
            TEST_ASSERT_EQUAL_MEMORY(&p, &got[i], sizeof p);
            TEST_ASSERT_EQUAL_MEMORY(&s, &got_se[i], sizeof s);
        }
    double rad[F2 + 1u], rse[F2 + 1u], an[F2 + 1u];
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial_all(&a2.h, F2 + 1u, rad, rse, an));
    TEST_ASSERT_TRUE(isnan(an[0]));
    for (size_t r = 0; r <= F2; ++r) {
        double p = 0.0, s = 0.0, d = 0.0;
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial(&b2.h, r, &p));
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_radial_stderr(&b2.h, r, &s));
        TEST_ASSERT_EQUAL_MEMORY(&p, &rad[r], sizeof p);
        TEST_ASSERT_EQUAL_MEMORY(&s, &rse[r], sizeof s);
        if (r > 0u) {
            TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_anisotropy(&b2.h, r, &d));
            TEST_ASSERT_EQUAL_MEMORY(&d, &an[r], sizeof d);
        }
    }
}

static void test_a_batch_with_one_bad_point_in_its_last_set_changes_nothing(void)
{
    fill(2u * SETS * K);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_init(&a2.h, F2, 0u, a2.mem, sizeof a2.mem));
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset2d_add_sets(&a2.h, 2u, K, pts));
    memcpy(&snap2, &a2, sizeof a2);
    pts[2u * SETS * K - 1u] = NAN;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pointset2d_add_sets(&a2.h, SETS, K, pts));
    pts[2u * SETS * K - 1u] = 1.0;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pointset2d_add_sets(&a2.h, SETS, K, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_K_RANGE, mcs_pointset2d_add_sets(&a2.h, 0u, K, pts));
    TEST_ASSERT_EQUAL_MEMORY(&snap2, &a2, sizeof a2);
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pointset_init(&a1.h, F1, 0u, a1.mem, sizeof a1.mem));
    memcpy(&snap1, &a1, sizeof a1);
    pts[SETS * K - 1u] = -0.25;
    TEST_ASSERT_EQUAL_INT(MCS_ERR_POINT_RANGE, mcs_pointset_add_sets(&a1.h, SETS, K, pts));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_EMPTY, mcs_pointset_read_all(&a1.h, F1 + 1u, got, NULL));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_MISMATCH, mcs_pointset_read_all(&a1.h, F1, got, NULL));
    TEST_ASSERT_EQUAL_MEMORY(&snap1, &a1, sizeof a1);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_a_1d_batch_is_bit_for_bit_the_sets_added_one_by_one);
    RUN_TEST(test_a_2d_batch_and_its_arrays_are_bit_for_bit_the_single_calls);
    RUN_TEST(test_a_batch_with_one_bad_point_in_its_last_set_changes_nothing);
    return UNITY_END();
}
