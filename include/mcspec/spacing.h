/* Spatial statistics of a point set in the unit torus [0,1)^d, d = 1..8
 * (docs/measures.md): the global minimum distance between two points and
 * the average minimum distance (the mean over the points of the distance to
 * the nearest other point), both as fractions of the maximal packing
 * distance of K points (Lagae and Dutre 2008, "A comparison of methods for
 * generating Poisson disk distributions", Computer Graphics Forum 27; psa's
 * "Gbl. Mindist" and "Avg. Mindist"); and an accumulator of their means and
 * standard errors over sets.
 *
 * Distances are toroidal: per coordinate min(|u - v|, 1 - |u - v|), so a
 * point near one face is close to points near the opposite one (utk's
 * MinDist with toroidal on; psa's SquaredDistUnitTorus).
 *
 * The maximal packing distance is the largest minimum distance K points can
 * have at density K: twice the packing radius of the densest lattice packing
 * at that density, d_max = 2 (delta_d / K)^(1/d), with delta_d the lattice's
 * centre density (Conway and Sloane, Sphere Packings, Lattices and Groups,
 * table 1.2; these lattices are the densest lattice packings for d <= 8):
 *     d        1     2            3            4     5            6            7     8
 *     lattice  Z     A2 (hex)     A3 (fcc)     D4    D5           E6           E7    E8
 *     delta_d  1/2   1/(2 sqrt 3) 1/(4 sqrt 2) 1/8   1/(8 sqrt 2) 1/(8 sqrt 3) 1/16  1/16
 * so d_max = 1/K in 1D and sqrt(2 / (sqrt(3) K)) in 2D (psa's rnorm), and
 * (sqrt(2) / K)^(1/3) in 3D. Beyond d = 8 the densest lattice is not known
 * for every d, which is why the statistics stop there.
 *
 * Search. Small sets, and sets where the grid would not pay, are searched
 * by brute force, O(d K^2). Otherwise the points are sorted by counting sort
 * into a grid of m^d cells (m the largest whole number with m^d <= K, at
 * least 3), and each point searches rings of cells of Chebyshev radius
 * r = 0, 1, ... around its own, toroidally, until the best distance found is
 * at most r / m (every cell further out is at least that far) or every cell
 * has been seen: expected O(3^d K) work for well-spread sets. The grid is
 * used when 3^d (1 + K / m^d) < K / 2, an estimate of its cost per point
 * against the brute force's K; mcs_spacing_work_size says which (0 bytes:
 * brute force). The distances are the same doubles either way: each is
 * summed coordinate by coordinate in the same order. */
#ifndef MCSPEC_SPACING_H
#define MCSPEC_SPACING_H

#include <stddef.h>
#include <stdint.h>
#include "status.h"
#include "welford.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest dimension d (the table above). */
#define MCS_SPACING_MAX_DIM 8

/* The statistics of a set, in the order of mcs_spacing_distances' output. */
typedef enum {
    MCS_SPACING_MIN_DISTANCE = 0, /* min over pairs of the distance, / d_max */
    MCS_SPACING_AVG_MIN_DISTANCE, /* mean over points of the nearest distance, / d_max */
    MCS_SPACING_STATISTICS        /* how many there are */
} mcs_spacing_statistic;

/* Name of a statistic as in the command's CSV ("min_distance",
 * "avg_min_distance"), or "unknown"; never NULL. */
const char *mcs_spacing_statistic_str(mcs_spacing_statistic statistic);

/* The maximal packing distance d_max of k points in dim dimensions (the
 * table above). MCS_ERR_NULL, MCS_ERR_DOMAIN (dim not in
 * 1..MCS_SPACING_MAX_DIM), MCS_ERR_K_RANGE (k = 0). *out untouched on error. */
mcs_status mcs_spacing_packing_distance(size_t dim, size_t k, double *out);

/* Bytes of work a set of up to k points needs in any dimension: the grid's
 * m^d + 1 <= k + 1 cell starts and the k point indices, size_t each, and
 * the slack to align the caller's buffer. A constant expression, so firmware
 * can declare an exact static buffer; at least mcs_spacing_work_size's
 * answer for every dim. */
#define MCS_SPACING_WORK_SIZE(k) ((2u * (size_t)(k) + 2u) * sizeof(size_t))

/* *bytes = the work a set of k points in dim dimensions needs: 0 when it is
 * searched by brute force (work may then be NULL), else
 * (m^d + 2 + k) sizeof(size_t). MCS_ERR_NULL, MCS_ERR_DOMAIN, MCS_ERR_K_RANGE
 * (k < 2: no nearest other point; or the bytes past SIZE_MAX). *bytes
 * untouched on error. */
mcs_status mcs_spacing_work_size(size_t dim, size_t k, size_t *bytes);

/* The statistics of one set: out[MCS_SPACING_MIN_DISTANCE] and
 * out[MCS_SPACING_AVG_MIN_DISTANCE] (caller array of MCS_SPACING_STATISTICS
 * doubles), each divided by d_max. k points of dim coordinates,
 * points[k * dim] interleaved, each in [0, 1); two equal points are at
 * distance 0. work is the caller's scratch of work_bytes (any alignment;
 * contents on return unspecified). MCS_ERR_NULL (points, out; work when
 * mcs_spacing_work_size is not 0), MCS_ERR_DOMAIN (dim), MCS_ERR_K_RANGE
 * (k < 2), MCS_ERR_POINT_RANGE (a coordinate outside [0, 1) or NaN, or
 * k * dim past SIZE_MAX), MCS_ERR_SPACE (work_bytes below
 * mcs_spacing_work_size), MCS_ERR_ALIAS (work overlapping points). Nothing
 * written on error, work included. */
mcs_status mcs_spacing_distances(size_t k, size_t dim, const double *points, void *work,
                                 size_t work_bytes, double *out);

/* mcs_spacing_distances for float points, read in place (bit-equal on the
 * widened points). */
mcs_status mcs_spacing_distances_f(size_t k, size_t dim, const float *points, void *work,
                                   size_t work_bytes, double *out);

/* The exact expectation of a statistic (divided by d_max, as
 * mcs_spacing_distances gives it) for k independent uniform points on the
 * torus in dim dimensions, where theory gives it in closed form:
 *   avg_min_distance, 1D: 1/2 (E = 1/(2k), d_max = 1/k);
 *   avg_min_distance, 2D: E = int_0^{sqrt(2)/2} (1 - A(r))^(k-1) dr, A(r) the
 *     area of the toroidal disk (pi r^2 up to 1/2, less four segments
 *     beyond), = Gamma(k) / (2 Gamma(k + 1/2)) plus two integrals below
 *     (1 - pi/4)^(k-1) / 4 by quadrature (spacing_exact.c), within 1e-15
 *     relative of a 40-digit evaluation (k = 2 to 1e5); over d_max, it tends
 *     to sqrt(sqrt(3) / 8) = 0.4653 from above as k grows;
 *   avg_min_distance, 3D to 8D: the ball's V_d^(-1/d) Gamma(1 + 1/d)
 *     Gamma(k) / Gamma(k + 1/d) (V_d the unit ball's volume), for k large
 *     enough that the part past r = 1/2, where the ball meets the cube's
 *     faces and has no short closed form, is below 2^-53 of it: its bound
 *     (sqrt(d)/2 - 1/2) (1 - V_d / 2^d)^(k-1) is, from k = 52 in 3D, 104,
 *     212, 450, 1007 and 2370 in 4D to 8D;
 *   min_distance, 1D: 1/k (E = 1/k^2, the least of k Dirichlet gaps).
 * MCS_ERR_NULL, MCS_ERR_KIND (not a statistic), MCS_ERR_DOMAIN (dim not in
 * 1..MCS_SPACING_MAX_DIM, or a case not listed: min_distance beyond 1D, the
 * average in 3D to 8D below those k),
 * MCS_ERR_K_RANGE (k < 2). *out untouched on error. */
mcs_status mcs_spacing_exact_random(mcs_spacing_statistic statistic, size_t dim, size_t k,
                                    double *out);

/* ---- Accumulator over sets ----------------------------------------------------
 * A Welford accumulator (welford.h) per statistic of the per-set values, so
 * the mean over sets, its standard error and the merge come from
 * mcs_welford. The scratch is passed per set, not kept: the accumulator has
 * a fixed size (104 bytes on x86-64) and no pointers (it may be copied), and
 * sets of any K stream through it with a buffer grown as they come. */
typedef struct {
    size_t dim;   /* 1..MCS_SPACING_MAX_DIM; 0 before init */
    size_t k_min; /* fewest points in a set added (0 before any) */
    size_t k_max; /* most points in a set added */
    mcs_welford stat[MCS_SPACING_STATISTICS]; /* the per-set values, per statistic */
} mcs_spacing;

/* Empties acc for sets in dim dimensions. MCS_ERR_NULL, MCS_ERR_DOMAIN.
 * *acc untouched on error. */
mcs_status mcs_spacing_init(mcs_spacing *acc, size_t dim);

/* Every call below but init returns MCS_ERR_UNINIT for an accumulator not
 * from mcs_spacing_init (dim out of range) and MCS_ERR_INVARIANT for one no
 * sequence of calls produces (a Welford mcs_welford refuses, counts that
 * differ, k_min above k_max), changing nothing. */

/* Adds the statistics of one set (arguments as mcs_spacing_distances).
 * Statuses as mcs_spacing_distances, MCS_ERR_ALIAS also for work
 * overlapping acc, and MCS_ERR_COUNT (the count at MCS_MAX_COUNT). *acc
 * untouched on error. */
mcs_status mcs_spacing_add(mcs_spacing *acc, size_t k, const double *points, void *work,
                           size_t work_bytes);

/* mcs_spacing_add for float points (bit-equal on the widened points). */
mcs_status mcs_spacing_add_f(mcs_spacing *acc, size_t k, const float *points, void *work,
                             size_t work_bytes);

/* dst <- dst union src (mcs_welford_merge); src unchanged; dst == src
 * allowed. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_INVARIANT, MCS_ERR_MISMATCH
 * (different dim), MCS_ERR_COUNT. dst untouched on error. */
mcs_status mcs_spacing_merge(mcs_spacing *dst, const mcs_spacing *src);

/* Sets added. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_INVARIANT. */
mcs_status mcs_spacing_count(const mcs_spacing *acc, uint64_t *count);

/* Mean over the sets of a statistic. MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_INVARIANT, MCS_ERR_KIND (not a statistic), MCS_ERR_EMPTY (no set).
 * *out untouched on error. */
mcs_status mcs_spacing_mean(const mcs_spacing *acc, mcs_spacing_statistic statistic, double *out);

/* Its standard error over the sets. MCS_ERR_EMPTY below 2 sets. */
mcs_status mcs_spacing_stderr(const mcs_spacing *acc, mcs_spacing_statistic statistic,
                              double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_SPACING_H */
