/* Discrepancies of a point set in [0,1)^d: the L2 discrepancies by their
 * closed forms (Warnock's L2 star; Hickernell's centred, wrap-around,
 * symmetric and generalized L2; the unanchored L2), their exact expectations
 * for independent uniform points, the exact (L-infinity) star discrepancy in
 * 2D, and an accumulator of their means and standard errors over sets
 * (docs/measures.md).
 *
 * Every L2 discrepancy here is a worst-case integration error in a
 * reproducing-kernel space: with a kernel h(x, y) = prod_k h1(x_k, y_k),
 *     D^2 = C0 - (2/K) sum_i g(x_i) + (1/K^2) sum_{i,j} h(x_i, x_j),
 *     g(x) = int h(x, y) dy,   C0 = int int h(x, y) dx dy,
 * so D^2 is the squared distance between the mean embedding of the K points
 * and that of the uniform measure; it is reported squared (the root is the
 * caller's sqrt). Per coordinate (c = |x - 1/2|, m = max(x, y), n = min(x, y),
 * t = |x - y|):
 *
 *   measure      h1(x, y)                 g1(x)               C0^(1/d)  h1(x, x)
 *   L2 star      1 - m                    (1 - x^2) / 2       1/3       1 - x
 *   centred      1 + (cx + cy - t) / 2    1 + (c - c^2) / 2   13/12     1 + c
 *   wrap-around  3/2 - t (1 - t)          4/3                 4/3       3/2
 *   symmetric    2 (1 - t)                1 + 2 x - 2 x^2     4/3       2
 *   generalized  2 - m                    (3 - x^2) / 2       4/3       2 - x
 *   unanchored   n (1 - m)                x (1 - x) / 2       1/12      x (1 - x)
 *
 * (Warnock 1972; Hickernell 1998, "A generalized discrepancy and quadrature
 * error bound", Math. Comp. 67; the unanchored form as in Lemieux 2009,
 * Monte Carlo and Quasi-Monte Carlo Sampling). These are utk's formulas
 * (utk::L2Discrepancy, CenteredL2Discrepancy, SymmetricL2Discrepancy,
 * GL2Discrepancy, UnanchoredL2Discrepancy) squared; utk has no wrap-around
 * form, which follows Hickernell 1998, WD^2 = -(4/3)^d + (1/K^2) sum_{i,j}
 * prod_k (3/2 - t (1 - t)).
 *
 * Exact expectation over K independent uniform points (the "exact random"
 * value). E g(x_i) = C0 since g integrates h over y; for i != j,
 * E h(x_i, x_j) = C0 by independence; the K diagonal terms give E h(x, x) =
 * prod_k E h1(x_k, x_k). So
 *     E[D^2] = C0 - 2 C0 + (1/K) E h(x, x) + (1 - 1/K) C0 = (E h(x, x) - C0) / K:
 *   L2 star      (2^-d - 3^-d) / K                   (E(1 - x) = 1/2)
 *   centred      ((5/4)^d - (13/12)^d) / K           (E(1 + c) = 5/4)
 *   wrap-around  ((3/2)^d - (4/3)^d) / K
 *   symmetric    (2^d - (4/3)^d) / K
 *   generalized  ((3/2)^d - (4/3)^d) / K             (E(2 - x) = 3/2)
 *   unanchored   (6^-d - 12^-d) / K                  (E x (1 - x) = 1/6)
 * and over jittered points (one per cell of a grid) as
 * mcs_discrepancy_l2_exact_jittered says.
 *
 * Cost O(d K^2): one pass over the K (K - 1)/2 pairs gives all six. The pair
 * sums add blocks of 64 terms, then Kahan-sum the blocks, so their rounding
 * stays near (d + 70) u of their size (u = 2^-53); D^2 itself is a difference
 * of terms of size C0, so its absolute error is a few (d + 70) u C0 (a
 * low-discrepancy set with D^2 far below C0 keeps that absolute error), and a
 * value within that of 0 may come out slightly negative. */
#ifndef MCSPEC_DISCREPANCY_H
#define MCSPEC_DISCREPANCY_H

#include <stddef.h>
#include <stdint.h>
#include "status.h"
#include "welford.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest dimension d of the closed forms (not a capacity: nothing is sized
 * by it). At d = 64 the constants span 12^-64 ~ 1e-69 to 2^64 ~ 2e19, still
 * far inside a double's range, and no product of 64 factors can underflow to
 * a subnormal except at points within 1e-250 of a face. */
#define MCS_DISCREPANCY_MAX_DIM 64

/* Largest K of the exact star discrepancy (O(K^2) steps: 17e6 at 4096). */
#define MCS_DISCREPANCY_STAR_MAX_K 4096

/* The measures, in the order of mcs_discrepancy_l2's output. */
typedef enum {
    MCS_DISCREPANCY_L2_STAR = 0,    /* Warnock's L2 star discrepancy, squared */
    MCS_DISCREPANCY_L2_CENTERED,    /* Hickernell's centred L2 (CD), squared */
    MCS_DISCREPANCY_L2_WRAPAROUND,  /* Hickernell's wrap-around L2 (WD), squared */
    MCS_DISCREPANCY_L2_SYMMETRIC,   /* Hickernell's symmetric L2 (SD), squared */
    MCS_DISCREPANCY_L2_GENERALIZED, /* Hickernell's generalized L2 star (beta = 1), squared */
    MCS_DISCREPANCY_L2_UNANCHORED,  /* the unanchored L2 (boxes anywhere), squared */
    MCS_DISCREPANCY_STAR,           /* the exact L-infinity star discrepancy in 2D,
                                       squared in the accumulator */
    MCS_DISCREPANCY_MEASURES        /* how many there are */
} mcs_discrepancy_measure;

/* The L2 measures: the first MCS_DISCREPANCY_L2_COUNT of the list. */
#define MCS_DISCREPANCY_L2_COUNT 6

/* Name of a measure as in the command's CSV ("l2_star", "l2_centered",
 * "l2_wraparound", "l2_symmetric", "l2_generalized", "l2_unanchored",
 * "star"), or "unknown"; never NULL. */
const char *mcs_discrepancy_measure_str(mcs_discrepancy_measure measure);

/* The six squared L2 discrepancies of one set, d2[measure] for each L2
 * measure (caller array of MCS_DISCREPANCY_L2_COUNT doubles): k points of
 * dim coordinates, points[k * dim] interleaved (point i at points[i * dim]),
 * each coordinate in [0, 1). O(dim k^2). MCS_ERR_NULL, MCS_ERR_DOMAIN (dim
 * not in 1..MCS_DISCREPANCY_MAX_DIM), MCS_ERR_K_RANGE (k = 0),
 * MCS_ERR_POINT_RANGE (a coordinate outside [0, 1) or NaN, or k * dim past
 * SIZE_MAX). d2 untouched on error; d2 is written only after every point has
 * been read, so it may overlap points. */
mcs_status mcs_discrepancy_l2(size_t k, size_t dim, const double *points, double *d2);

/* mcs_discrepancy_l2 for float points, read in place: each widens to double
 * exactly, so d2 is bit-equal to mcs_discrepancy_l2's on the widened points.
 * Statuses as mcs_discrepancy_l2. */
mcs_status mcs_discrepancy_l2_f(size_t k, size_t dim, const float *points, double *d2);

/* E[D^2] of an L2 measure over k independent uniform points in dim
 * dimensions (the table above). MCS_ERR_NULL, MCS_ERR_KIND (not a measure),
 * MCS_ERR_DOMAIN (MCS_DISCREPANCY_STAR: no closed form; dim not in
 * 1..MCS_DISCREPANCY_MAX_DIM), MCS_ERR_K_RANGE (k = 0). *out untouched on
 * error. */
mcs_status mcs_discrepancy_l2_exact_random(mcs_discrepancy_measure measure, size_t k, size_t dim,
                                           double *out);

/* E[D^2] of an L2 measure over a jittered grid: n^dim cells of side 1/n, one
 * independent uniform point in each, K = n^dim (dim = 1: the stratified
 * pattern u_j = (j + xi_j) / K with n = K). With e = E h1(x, x) of the table
 * above and per axis Delta(n) = 1/6 (L2 star, centred, generalized), 2/3
 * (symmetric), 1/3 - 1/(6n) (wrap-around), 1/6 - 1/(12n) (unanchored),
 *     E[D^2] = (e^d - (e - Delta(n) / n)^d) / K,
 * e.g. ((1/2)^d - (1/2 - 1/(6n))^d) / K for the L2 star (1D: 1/(6 K^2));
 * the derivation is in discrepancy.c. The exact star discrepancy has no such
 * form. MCS_ERR_NULL, MCS_ERR_KIND (not a measure), MCS_ERR_DOMAIN
 * (MCS_DISCREPANCY_STAR; dim not in 1..MCS_DISCREPANCY_MAX_DIM),
 * MCS_ERR_K_RANGE (n = 0, or n^dim past SIZE_MAX). *out untouched on error. */
mcs_status mcs_discrepancy_l2_exact_jittered(mcs_discrepancy_measure measure, size_t n, size_t dim,
                                             double *out);

/* The same for a 2D grid of nx columns by ny rows of cells (1/nx by 1/ny,
 * K = nx ny, mcs_pattern2d's jittered kind with strata_x = nx, strata_y =
 * ny): (e^2 - (e - Delta(nx) / nx) (e - Delta(ny) / ny)) / K. Statuses as
 * mcs_discrepancy_l2_exact_jittered (MCS_ERR_K_RANGE: nx or ny 0, or nx ny
 * past SIZE_MAX). *out untouched on error. */
mcs_status mcs_discrepancy_l2_exact_jittered2d(mcs_discrepancy_measure measure, size_t nx,
                                               size_t ny, double *out);

/* ---- The exact star discrepancy in 2D ----------------------------------------
 * D* = sup over boxes B = [0, a) x [0, b) of | #(P in B) / K - a b |. The sup
 * is a maximum over the grid of the points' coordinates and 1: of
 * a b - #(x < a, y < b) / K (open boxes, a in X and 1, b in Y and 1) and
 * #(x <= a, y <= b) / K - a b (closed boxes, a in X, b in Y) (Niederreiter
 * 1992, Random Number Generation and Quasi-Monte Carlo Methods, ch. 2). One
 * sweep in x over a y-sorted list of the points passed, O(K^2) steps
 * (sorting O(K log K), heapsort in place). It bounds the L2 star discrepancy
 * of the same set from above: D*_2 <= D*. */

/* Bytes of work a star discrepancy of up to k points needs: three doubles a
 * point, and the slack to align the caller's buffer to a double. A constant
 * expression, so firmware can declare an exact static buffer; it is the
 * value mcs_discrepancy_star_work_size gives. */
#define MCS_DISCREPANCY_STAR_WORK_SIZE(k) (3u * (size_t)(k) * sizeof(double) + sizeof(double))

/* *bytes = MCS_DISCREPANCY_STAR_WORK_SIZE(k). MCS_ERR_NULL, MCS_ERR_K_RANGE
 * (k = 0 or above MCS_DISCREPANCY_STAR_MAX_K). *bytes untouched on error. */
mcs_status mcs_discrepancy_star_work_size(size_t k, size_t *bytes);

/* The exact star discrepancy D* (not squared) of k points in 2D,
 * points[2 k] interleaved (x_0, y_0, x_1, ...), in [0, 1). work is the
 * caller's scratch of work_bytes (any alignment; its contents on return are
 * unspecified). MCS_ERR_NULL, MCS_ERR_K_RANGE (k = 0 or above
 * MCS_DISCREPANCY_STAR_MAX_K), MCS_ERR_POINT_RANGE, MCS_ERR_SPACE
 * (work_bytes below mcs_discrepancy_star_work_size), MCS_ERR_ALIAS (work
 * overlaps points). Nothing written on error, work included. */
mcs_status mcs_discrepancy_star(size_t k, const double *points, void *work, size_t work_bytes,
                                double *out);

/* mcs_discrepancy_star for float points (bit-equal on the widened points). */
mcs_status mcs_discrepancy_star_f(size_t k, const float *points, void *work, size_t work_bytes,
                                  double *out);

/* ---- Accumulator over sets ----------------------------------------------------
 * Per measure, a Welford accumulator (welford.h) of the squared discrepancy
 * of each set added, so the mean over sets, its standard error and the merge
 * of two accumulators come from mcs_welford. The star is the square of D*
 * too, so every root reads on the same scale; it is added only for the sets
 * it is computed for (see mcs_discrepancy_add), and its count says how many.
 * A Welford of 1/K over the sets gives the exact random expectation of the
 * mean of mixed-K sets. Fixed size (344 bytes on x86-64), no pointers: it
 * may be copied. */
typedef struct {
    size_t dim;       /* 1..MCS_DISCREPANCY_MAX_DIM; 0 before init */
    size_t k_min;     /* fewest points in a set added (0 before any) */
    size_t k_max;     /* most points in a set added */
    mcs_welford inv_k; /* 1/K of every set added */
    mcs_welford d2[MCS_DISCREPANCY_MEASURES]; /* the squared discrepancies, per measure */
} mcs_discrepancy;

/* Empties acc for sets in dim dimensions. MCS_ERR_NULL, MCS_ERR_DOMAIN (dim
 * not in 1..MCS_DISCREPANCY_MAX_DIM). *acc untouched on error. */
mcs_status mcs_discrepancy_init(mcs_discrepancy *acc, size_t dim);

/* Every call below but init returns MCS_ERR_UNINIT for an accumulator not
 * from mcs_discrepancy_init (dim out of range) and MCS_ERR_INVARIANT for one
 * no sequence of calls produces (a Welford mcs_welford refuses, L2 counts that
 * differ from the count of 1/K, a star count above them, k_min above k_max),
 * changing nothing. */

/* Adds one set of k points (points[k * dim] as mcs_discrepancy_l2): its six
 * squared L2 discrepancies and, when work is not NULL, dim is 2 and k <=
 * MCS_DISCREPANCY_STAR_MAX_K, the square of its exact star discrepancy (work
 * and work_bytes as mcs_discrepancy_star). With work NULL, or for a set the
 * star does not take, the star is skipped and its count stays. MCS_ERR_NULL
 * (acc, points), MCS_ERR_K_RANGE (k = 0), MCS_ERR_POINT_RANGE, MCS_ERR_SPACE
 * (work too small for a star it would compute), MCS_ERR_ALIAS (work
 * overlapping points or acc), MCS_ERR_MAGNITUDE and MCS_ERR_COUNT (from
 * mcs_welford_add). *acc untouched on error. */
mcs_status mcs_discrepancy_add(mcs_discrepancy *acc, size_t k, const double *points, void *work,
                               size_t work_bytes);

/* mcs_discrepancy_add for float points (bit-equal on the widened points). */
mcs_status mcs_discrepancy_add_f(mcs_discrepancy *acc, size_t k, const float *points, void *work,
                                 size_t work_bytes);

/* dst <- dst union src, per measure (mcs_welford_merge); src unchanged;
 * dst == src allowed. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_INVARIANT,
 * MCS_ERR_MISMATCH (different dim), MCS_ERR_COUNT. dst untouched on error. */
mcs_status mcs_discrepancy_merge(mcs_discrepancy *dst, const mcs_discrepancy *src);

/* Sets a measure was added for (every set for the L2 measures).
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_INVARIANT, MCS_ERR_KIND (not a
 * measure). *count untouched on error. */
mcs_status mcs_discrepancy_count(const mcs_discrepancy *acc, mcs_discrepancy_measure measure,
                                 uint64_t *count);

/* Mean over the sets of the measure's squared discrepancy. Statuses as
 * mcs_discrepancy_count, and MCS_ERR_EMPTY (no set). */
mcs_status mcs_discrepancy_mean(const mcs_discrepancy *acc, mcs_discrepancy_measure measure,
                                double *out);

/* Its standard error over the sets. MCS_ERR_EMPTY below 2 sets. */
mcs_status mcs_discrepancy_stderr(const mcs_discrepancy *acc, mcs_discrepancy_measure measure,
                                  double *out);

/* What the mean would be, exactly, for independent uniform points in sets of
 * the same sizes: mean over the sets of mcs_discrepancy_l2_exact_random,
 * (E h(x, x) - C0) times the mean of 1/K. MCS_ERR_DOMAIN for
 * MCS_DISCREPANCY_STAR; otherwise statuses as mcs_discrepancy_mean. */
mcs_status mcs_discrepancy_exact_random(const mcs_discrepancy *acc,
                                        mcs_discrepancy_measure measure, double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_DISCREPANCY_H */
