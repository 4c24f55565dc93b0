/* Shared helpers of the point-set, 2D pattern, sampler and 2D spectrum tests. */
#ifndef POINTS_REF_H
#define POINTS_REF_H

#include <stddef.h>
#include <stdint.h>

#include "mcspec.h"

/* A 2D pattern from mcs_pattern2d_init; fails the test on error. */
mcs_pattern2d points_pattern2d(mcs_pattern2d_kind kind, size_t k, size_t strata_x,
                               size_t strata_y);

/* out[n] uniform in [0, 1) from rng: n / 2 random 2D points, or n 1D ones. */
void points_uniform(mcs_rng *rng, size_t n, double *out);

/* The point-set periodogram |sum_j e^{-2 pi i f.x_j}|^2 / K of k points by a
 * direct sum in long double, independent of the library: dim 1 reads p[k]
 * at frequency fx (fy ignored), dim 2 reads p[2 k] interleaved at (fx, fy). */
double points_periodogram(size_t dim, size_t k, const double *p, long fx, long fy);

/* Fails the test unless a mean b and its standard error sb equal a and sa to
 * rounding: an accumulator merged from two halves against one pass. */
void points_assert_merged(double a, double sa, double b, double sb);

/* Fills buf[n] with guard; guard_check fails the test unless every one of
 * them still holds it (a call that failed wrote nothing). */
void points_guard_fill(double *buf, size_t n, double guard);
void points_guard_check(const double *buf, size_t n, double guard);

/* An accumulator kind for points_assert_count_bound: its size, where its
 * count lives, a call that adds one fixed trial and its merge. */
typedef struct {
    size_t size;
    uint64_t *(*count)(void *acc);
    int (*add_one)(void *acc);
    int (*merge)(void *dst, const void *src);
} points_counted;

/* Counts are exact in a double up to MCS_MAX_COUNT: fails the test unless an
 * add or merge that would pass it (or starts past it, as a corrupted count
 * does) returns MCS_ERR_COUNT and changes nothing, one that lands on it is
 * taken, and 70 self-merges double the count up to the bound and never wrap
 * it. a and b: two empty accumulators of one configuration; snap_a, snap_b:
 * two more of the kind, overwritten. */
void points_assert_count_bound(const points_counted *kind, void *a, void *b, void *snap_a,
                               void *snap_b);

#endif /* POINTS_REF_H */
