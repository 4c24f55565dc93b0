#include "points_ref.h"

#include <math.h>
#include <string.h>

#include "unity.h"

mcs_pattern2d points_pattern2d(mcs_pattern2d_kind kind, size_t k, size_t strata_x,
                               size_t strata_y)
{
    mcs_pattern2d p;
    TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_pattern2d_init(&p, kind, k, strata_x, strata_y));
    return p;
}

void points_uniform(mcs_rng *rng, size_t n, double *out)
{
    for (size_t i = 0; i < n; ++i)
        TEST_ASSERT_EQUAL_INT(MCS_OK, mcs_rng_double(rng, &out[i]));
}

double points_periodogram(size_t dim, size_t k, const double *p, long fx, long fy)
{
    const long double two_pi = 6.283185307179586476925286766559L;
    long double re = 0.0L, im = 0.0L;
    for (size_t j = 0; j < k; ++j) {
        long double t = dim == 1u ? (long double)fx * (long double)p[j]
                                  : (long double)fx * p[2 * j] + (long double)fy * p[2 * j + 1];
        re += cosl(two_pi * t);
        im -= sinl(two_pi * t);
    }
    return (double)((re * re + im * im) / (long double)k);
}

void points_assert_merged(double a, double sa, double b, double sb)
{
    TEST_ASSERT_DOUBLE_WITHIN(1e-12 * fabs(a) + 1e-14, a, b);
    TEST_ASSERT_DOUBLE_WITHIN(1e-10 * sa + 1e-15, sa, sb);
}

void points_guard_fill(double *buf, size_t n, double guard)
{
    for (size_t i = 0; i < n; ++i)
        buf[i] = guard;
}

void points_guard_check(const double *buf, size_t n, double guard)
{
    for (size_t i = 0; i < n; ++i)
        TEST_ASSERT_EQUAL_DOUBLE(guard, buf[i]);
}

/* The bound refuses, whole: a full (or corrupted) count a against b. */
static void assert_full_count_refused(const points_counted *kind, void *a, void *b, void *snap_a,
                                      void *snap_b)
{
    memcpy(snap_a, a, kind->size);
    memcpy(snap_b, b, kind->size);
    TEST_ASSERT_EQUAL_INT(MCS_ERR_COUNT, kind->add_one(a));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_COUNT, kind->merge(a, b));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_COUNT, kind->merge(b, a));
    TEST_ASSERT_EQUAL_INT(MCS_ERR_COUNT, kind->merge(a, a));
    TEST_ASSERT_EQUAL_MEMORY(snap_a, a, kind->size);
    TEST_ASSERT_EQUAL_MEMORY(snap_b, b, kind->size);
}

void points_assert_count_bound(const points_counted *kind, void *a, void *b, void *snap_a,
                               void *snap_b)
{
    const uint64_t cap = (uint64_t)MCS_MAX_COUNT;
    TEST_ASSERT_EQUAL_INT(MCS_OK, kind->add_one(a));
    TEST_ASSERT_EQUAL_INT(MCS_OK, kind->add_one(b));
    *kind->count(a) = cap;
    assert_full_count_refused(kind, a, b, snap_a, snap_b);
    *kind->count(a) = UINT64_MAX;
    assert_full_count_refused(kind, a, b, snap_a, snap_b);
    *kind->count(a) = cap - 1u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, kind->add_one(a));
    TEST_ASSERT_EQUAL_UINT64(cap, *kind->count(a));
    *kind->count(a) = cap - 1u;
    TEST_ASSERT_EQUAL_INT(MCS_OK, kind->merge(a, b));
    TEST_ASSERT_EQUAL_UINT64(cap, *kind->count(a));
    for (int m = 0; m < 70; ++m) {
        const uint64_t before = *kind->count(b);
        const int st = kind->merge(b, b);
        TEST_ASSERT_EQUAL_UINT64(st == MCS_OK ? 2u * before : before, *kind->count(b));
        TEST_ASSERT_TRUE(st == MCS_OK || st == MCS_ERR_COUNT);
    }
    TEST_ASSERT_EQUAL_UINT64(cap, *kind->count(b)); /* 2^53 = MCS_MAX_COUNT, doubling from 1 */
}
