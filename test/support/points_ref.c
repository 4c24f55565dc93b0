#include "points_ref.h"

#include <math.h>

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
