/* The 2D projections of a d-dimensional sampler: for every pair of
 * dimensions (i, j), i < j, over one or many point sets of K points,
 *  - radial_low: the mean periodogram P(f) = |sum_k e^{-2 pi i (f_x x_ki +
 *    f_y x_kj)}|^2 / K over the off-axis wave vectors of the low disc,
 *    0 < |f| <= R with f_x != 0 and f_y != 0 (R = `radius`); the axis wave
 *    vectors are each dimension's own 1D spectrum, which no pairing of the
 *    two dimensions changes, so they say nothing about the pair;
 *  - anisotropy_db: psa's anisotropy (pointset2d.h: 10 log10 of the
 *    variance over an annulus of the mean periodogram over its squared
 *    mean), averaged in dB over the annuli r = 1..F where it is finite;
 *  - discrepancy: the squared wrap-around L2 discrepancy of the projection
 *    (mcs_discrepancy_l2, Hickernell's WD: shift-invariant, as the
 *    periodogram is), over the first disc_sets sets only (O(K^2) a pair);
 *  - peak: the periodogram's largest off-axis value over |f|_inf <= F,
 *    relative to its independent-dimension reference (below).
 * Each with its standard error over sets (with one set: the spread over the
 * disc's wave vectors, treated as independent).
 *
 * The reference is what independent dimensions give: the same two 1D sets
 * paired at random (a uniformly random permutation of one against the
 * other) have E[P(f) | the 1D sets] = 1 + (P_i(f_x) - 1)(P_j(f_y) - 1)/(K-1)
 * exactly, P_i the 1D periodogram of dimension i of that set (1 for random
 * points, K/(K-1) for two stratified dimensions). Per set the radial
 * statistic is the mean over the disc of P(f) - ref(f), expectation 0 for
 * independent dimensions; its z = mean / stderr over sets, the stderr
 * floored at the one independent dimensions would give (each P(f) an
 * exponential of mean ref(f), independent over the disc: sum ref^2 /
 * n_low^2 a set), since with few sets the spread over sets is itself
 * uncertain. The peak of P/ref
 * over the n = 2 F^2 off-axis wave vectors of the half box is about the
 * maximum of n unit exponentials (the sum over a random pairing is close to
 * complex normal): P(max > q) ~ n e^-q. A pair is flagged when its radial z
 * exceeds 5 (one-sided: more power than independent dimensions, which is
 * what turns into error; a net's pairs have less) or when its largest peak
 * over all T sets exceeds q = ln(n T m / alpha), the Bonferroni threshold
 * over the m = d(d-1)/2 pairs at alpha = 5.7e-7 (the two-sided normal tail
 * beyond 5 standard deviations): independent dimensions are then flagged
 * with probability about 1e-6 per pair. docs/projections.md derives it.
 *
 * Memory: a fixed header over a caller-owned buffer (mcs_projections_size,
 * then mcs_projections_init; MCS_PROJECTIONS_SIZE for a static buffer). Cost
 * per set: O(d^2 K F^2 / 2) for the spectra, O(d^2 K^2) for the
 * discrepancies of the first disc_sets sets. */
#ifndef MCSPEC_PROJECTIONS_H
#define MCSPEC_PROJECTIONS_H

#include <stddef.h>
#include <stdint.h>
#include "status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest dimension d and cutoff F. */
#define MCS_PROJECTIONS_MAX_DIM 64
#define MCS_PROJECTIONS_MAX_FREQ 64

/* Stored wave vectors of one pair: fx = -F..F by fy = 0..F. */
#define MCS_PROJECTIONS_CELLS_(f) ((2u * (size_t)(f) + 1u) * ((size_t)(f) + 1u))
/* Doubles of statistics per pair besides its mean periodogram. */
#define MCS_PROJECTIONS_PAIR_STATS_ 18u
/* Bytes of buffer for d dimensions, cutoff F and sets of up to k_max points,
 * as a constant expression: exactly what mcs_projections_size reports. */
#define MCS_PROJECTIONS_SIZE(d, f, k_max)                                                  \
    (8u + 8u * ((size_t)(d) * ((size_t)(d) - 1u) / 2u *                                    \
                    (MCS_PROJECTIONS_CELLS_(f) + MCS_PROJECTIONS_PAIR_STATS_) +            \
                2u * MCS_PROJECTIONS_CELLS_(f) + (size_t)(d) * ((size_t)(f) + 1u) +        \
                2u * (size_t)(k_max) + 6u * (size_t)(f) + 6u))

typedef struct {
    size_t dim;       /* d, 2..MCS_PROJECTIONS_MAX_DIM; 0 before init */
    size_t freq;      /* F, 1..MCS_PROJECTIONS_MAX_FREQ */
    size_t radius;    /* R of the low disc, 1..F */
    size_t k_max;     /* largest set */
    size_t disc_sets; /* sets (the first ones) whose discrepancies are computed */
    uint64_t sets;    /* sets added */
    size_t k_last;    /* K of the last set added (0 before any) */
    void *mem;        /* the caller's buffer */
    size_t bytes;     /* its size as given */
    double *pairs;    /* per pair: stats, then the mean periodogram */
    double *scratch;  /* S(f) of one pair, 1D periodograms, phases, pair points */
    uintptr_t key;    /* a hash of the fields above, set by init and add */
} mcs_projections;

/* The read-out of one pair (i, j). */
typedef struct {
    double radial_low;        /* mean P over the low off-axis disc, over sets */
    double radial_low_stderr; /* its standard error */
    double radial_low_ref;    /* the same mean of the independent-dimension reference */
    double radial_low_z;      /* (radial_low - ref) / the stderr of the difference, floored */
    double anisotropy_db;     /* psa's anisotropy, averaged over annuli 1..F (NaN: none) */
    double discrepancy;       /* squared WD of the projection, mean over the sets computed */
    double discrepancy_stderr; /* its standard error (NaN below 2 sets) */
    double discrepancy_random; /* E[WD^2] of K independent uniform points (K of the last set) */
    double peak;              /* mean over sets of the largest P / ref off axis */
    double peak_stderr;       /* its standard error (one set: the max's null sd, pi/sqrt 6) */
    double peak_max;          /* the largest over all sets */
    double peak_threshold;    /* the Bonferroni threshold q it is flagged above */
    int flagged;              /* 1 if radial_low_z > 5 or peak_max > peak_threshold */
} mcs_projections_pair;

/* Bytes of buffer for dim, freq and sets of up to k_max points into *bytes.
 * MCS_ERR_NULL, MCS_ERR_DOMAIN (dim not in 2..MCS_PROJECTIONS_MAX_DIM),
 * MCS_ERR_FREQ_RANGE (freq not in 1..MCS_PROJECTIONS_MAX_FREQ),
 * MCS_ERR_K_RANGE (k_max = 0 or above 2^31). *bytes untouched on error. */
mcs_status mcs_projections_size(size_t dim, size_t freq, size_t k_max, size_t *bytes);

/* Empties p over mem[bytes] (any alignment; the caller owns it and keeps it
 * while p is used): radius R of the low disc (1..freq), discrepancies of the
 * first disc_sets sets (0: none). Statuses as mcs_projections_size, and
 * MCS_ERR_NULL (p, mem), MCS_ERR_DOMAIN (radius out of range), MCS_ERR_SPACE
 * (bytes too small), MCS_ERR_ALIAS (mem overlaps *p). *p and mem untouched
 * on error. */
mcs_status mcs_projections_init(mcs_projections *p, size_t dim, size_t freq, size_t radius,
                                size_t k_max, size_t disc_sets, void *mem, size_t bytes);

/* Adds one set of k points of p->dim coordinates, points[k * dim]
 * interleaved (point k at points[k * dim]), each in [0, 1). MCS_ERR_NULL,
 * MCS_ERR_UNINIT (p not from init), MCS_ERR_K_RANGE (k = 0 or above k_max),
 * MCS_ERR_POINT_RANGE (a coordinate outside [0, 1) or NaN), MCS_ERR_ALIAS
 * (points overlap *p or its buffer), MCS_ERR_COUNT (2^53 sets). Every point
 * is checked first: on error neither *p nor its buffer changes. */
mcs_status mcs_projections_add(mcs_projections *p, size_t k, const double *points);

/* The read-out of pair (i, j), i != j (either order), into *out.
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_DOMAIN (i or j >= dim, or i == j),
 * MCS_ERR_EMPTY (no set). *out untouched on error. */
mcs_status mcs_projections_pair_stats(const mcs_projections *p, size_t i, size_t j,
                                      mcs_projections_pair *out);

/* Number of pairs flagged, into *count. Statuses as
 * mcs_projections_pair_stats without the DOMAIN case. */
mcs_status mcs_projections_flagged(const mcs_projections *p, size_t *count);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_PROJECTIONS_H */
