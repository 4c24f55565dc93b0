/* The exact star discrepancy of a 2D point set (discrepancy.h): a sweep in x
 * over the grid of the points' coordinates, O(K^2) steps in the caller's
 * scratch. */
#include "mcspec/discrepancy.h"
#include "measures_internal.h"

#include <stddef.h>
#include <string.h>

mcs_status mcs_discrepancy_star_work_size(size_t k, size_t *bytes)
{
    if (bytes == NULL)
        return MCS_ERR_NULL;
    if (k == 0u || k > (size_t)MCS_DISCREPANCY_STAR_MAX_K)
        return MCS_ERR_K_RANGE;
    *bytes = MCS_DISCREPANCY_STAR_WORK_SIZE(k);
    return MCS_OK;
}

/* Pair a of xy[] (x, y) comes before pair b: by x, then by y. */
static int before(const double *xy, size_t a, size_t b)
{
    const double xa = xy[2u * a], xb = xy[2u * b];
    return xa < xb || (xa == xb && xy[2u * a + 1u] < xy[2u * b + 1u]);
}

static void swap_pairs(double *xy, size_t a, size_t b)
{
    const double x = xy[2u * a], y = xy[2u * a + 1u];
    xy[2u * a] = xy[2u * b];
    xy[2u * a + 1u] = xy[2u * b + 1u];
    xy[2u * b] = x;
    xy[2u * b + 1u] = y;
}

/* Restores the max-heap below root among the first n pairs. */
static void sift_down(double *xy, size_t root, size_t n)
{
    for (;;) {
        size_t child = 2u * root + 1u;
        if (child >= n)
            return;
        if (child + 1u < n && before(xy, child, child + 1u))
            ++child;
        if (!before(xy, root, child))
            return;
        swap_pairs(xy, root, child);
        root = child;
    }
}

/* Heapsort of the k pairs of xy in place: O(k log k), no recursion, no
 * memory (the C library's qsort may allocate). */
static void sort_pairs(double *xy, size_t k)
{
    for (size_t i = k / 2u; i-- > 0u;)
        sift_down(xy, i, k);
    for (size_t n = k; n-- > 1u;) {
        swap_pairs(xy, 0u, n);
        sift_down(xy, 0u, n);
    }
}

/* Open boxes [0, a) x [0, b) for every b in ys[n] (the y of the points with
 * x < a, sorted) and b = 1: a b - #(y < b) / K, #(y < b) the index of the
 * first of a run of equal values. */
static double open_boxes(const double *ys, size_t n, double a, double kk)
{
    double best = a - (double)n / kk;
    for (size_t p = 0; p < n; ++p)
        if (p == 0u || ys[p] != ys[p - 1u]) {
            const double dev = a * ys[p] - (double)p / kk;
            best = dev > best ? dev : best;
        }
    return best;
}

/* Closed boxes [0, a] x [0, b] for every b in ys[n] (the y of the points
 * with x <= a): #(y <= b) / K - a b, #(y <= b) one past the last of a run. */
static double closed_boxes(const double *ys, size_t n, double a, double kk)
{
    double best = 0.0;
    for (size_t p = 0; p < n; ++p)
        if (p + 1u == n || ys[p + 1u] != ys[p]) {
            const double dev = (double)(p + 1u) / kk - a * ys[p];
            best = dev > best ? dev : best;
        }
    return best;
}

/* Inserts y into the sorted ys[*n], after any equal values. */
static void insert_sorted(double *ys, size_t *n, double y)
{
    size_t lo = 0, hi = *n;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2u;
        if (ys[mid] <= y)
            lo = mid + 1u;
        else
            hi = mid;
    }
    memmove(ys + lo + 1u, ys + lo, (*n - lo) * sizeof *ys);
    ys[lo] = y;
    ++*n;
}

/* The sweep over xy[2 k] sorted by x: at each distinct x = a the open boxes
 * (before its points join) and the closed ones (after), then a = 1. A
 * maximum over b in the y's of the points with x < a (open) or x <= a
 * (closed) suffices: between two such values the count is constant and a b
 * monotone, so each piece's extreme is at one of its ends. */
static double sweep(const double *xy, size_t k, double *ys)
{
    const double kk = (double)k;
    double best = 0.0;
    size_t n = 0, i = 0;
    while (i < k) {
        const double a = xy[2u * i];
        double dev = open_boxes(ys, n, a, kk);
        best = dev > best ? dev : best;
        for (; i < k && xy[2u * i] == a; ++i)
            insert_sorted(ys, &n, xy[2u * i + 1u]);
        dev = closed_boxes(ys, n, a, kk);
        best = dev > best ? dev : best;
    }
    const double dev = open_boxes(ys, n, 1.0, kk);
    return dev > best ? dev : best;
}

static MCS_ALWAYS_INLINE mcs_status star(size_t k, mcs_points_ p, void *work, size_t work_bytes,
                                         double *out)
{
    if (mcs_points_addr_(p) == NULL || work == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (k == 0u || k > (size_t)MCS_DISCREPANCY_STAR_MAX_K)
        return MCS_ERR_K_RANGE;
    if (work_bytes < MCS_DISCREPANCY_STAR_WORK_SIZE(k))
        return MCS_ERR_SPACE;
    if (mcs_overlap_(work, work_bytes, mcs_points_addr_(p), mcs_points_bytes_(p, 2u * k)))
        return MCS_ERR_ALIAS;
    mcs_status st = mcs_check_points_(2u * k, p, NULL);
    if (st != MCS_OK)
        return st;
    double *xy = mcs_meas_align_(work, sizeof(double));
    for (size_t j = 0; j < 2u * k; ++j)
        xy[j] = mcs_point_(p, j);
    sort_pairs(xy, k);
    *out = sweep(xy, k, xy + 2u * k);
    return MCS_OK;
}

mcs_status mcs_discrepancy_star(size_t k, const double *points, void *work, size_t work_bytes,
                                double *out)
{
    return star(k, mcs_points_d_(points), work, work_bytes, out);
}

mcs_status mcs_discrepancy_star_f(size_t k, const float *points, void *work, size_t work_bytes,
                                  double *out)
{
    return star(k, mcs_points_f_(points), work, work_bytes, out);
}
