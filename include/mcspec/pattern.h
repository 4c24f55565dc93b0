/* Sample patterns over N bins: K canonical points u_j by a rule, optionally
 * warped through an importance function, then binned. A trial is K pairs
 * (bin n_j, weight w_j = 1/p_{n_j}): the sparse form of s_n = r_n / p_n
 * (eq. 38). K need not divide N. */
#ifndef MCSPEC_PATTERN_H
#define MCSPEC_PATTERN_H

#include <stddef.h>
#include "config.h"
#include "status.h"
#include "rng.h"
#include "importance.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    MCS_PATTERN_RANDOM = 0,      /* u_j i.i.d. uniform (section 3.1) */
    MCS_PATTERN_STRATIFIED = 1,  /* u_j = (j + xi_j)/K (section 3.2) */
    MCS_PATTERN_HOMOGENIZED = 2, /* stratified, shifted cyclically by a random whole
                                    number of bins (no importance function) */
    MCS_PATTERN_UNIFORM = 3,     /* u_j = (j + 1/2)/K, deterministic (section 3.3) */
    MCS_PATTERN_JITTER = 4       /* u_j = (j + beta)/K, one beta per trial (section 3.3) */
} mcs_pattern_kind;

#define MCS_PATTERN_KIND_COUNT 5

/* Largest K a pattern takes: 2^30 (1 073 741 824) samples per trial. Why
 * this bound: u_j = (j + xi)/K keeps
 * at least 53 - 30 = 23 bits of the in-stratum offset xi, and j N (N up to
 * 2^12) stays an exact integer in a double, so bins are found exactly (past
 * ~2^50 they are not); and a trial's total weight, at most
 * K / (N MCS_IMPORTANCE_MIN_G) < 2^62, stays far inside every accumulator's
 * magnitude limit. (Exact theory of a uniform pattern finds its bin counts by
 * bisection, O(N log K): K does not bound its time.) */
#define MCS_MAX_K 1073741824u

typedef struct {
    mcs_pattern_kind kind;
    size_t n;                         /* bins N, 1..MCS_MAX_N */
    size_t k;                         /* samples per trial K, 1..MCS_MAX_K */
    const mcs_importance *importance; /* caller-owned, NULL for the uniform density (also
                                         when a flat one was given); must outlive the pattern */
} mcs_pattern;

/* Name of a kind ("random", "stratified", "homogenized", "uniform",
 * "jitter"), or "unknown". */
const char *mcs_pattern_kind_str(mcs_pattern_kind kind);

/* Configures a pattern. importance may be NULL; if not, its n must equal n.
 * A flat importance function (every p_n = 1: equal weights) is the uniform
 * density, so the pattern stores NULL and draws bit for bit what it draws
 * without one (the rounded CDF of 1/N steps could not put a point that lies
 * exactly on a bin edge, such as the uniform pattern's, in the same bin).
 * MCS_ERR_NULL, MCS_ERR_N_RANGE, MCS_ERR_K_RANGE (k = 0 or k > MCS_MAX_K),
 * MCS_ERR_KIND (unknown kind, or homogenized with an importance function,
 * flat or not), MCS_ERR_MISMATCH, MCS_ERR_UNINIT (importance not initialised).
 * *pat untouched on error. */
mcs_status mcs_pattern_init(mcs_pattern *pat, mcs_pattern_kind kind, size_t n, size_t k,
                            const mcs_importance *importance);

/* Draws one trial: bins[k] (n_j in [0,N)), weights[k] (w_j = 1/p_{n_j}, 1 without
 * importance) and, if points is not NULL, points[k] (x_j in [0,1), floor(N x_j) = n_j).
 * No sample lands in a bin outside the importance function's support.
 * k must equal pat->k (it is the length of every caller array). The three
 * arrays must not overlap each other, *pat, *rng or the importance function.
 * MCS_ERR_NULL, MCS_ERR_MISMATCH (k != pat->k), MCS_ERR_UNINIT (pat not as
 * init leaves one, or an rng never seeded), MCS_ERR_ALIAS (overlap). On error nothing is written
 * and rng is not advanced. */
mcs_status mcs_pattern_draw(const mcs_pattern *pat, mcs_rng *rng, size_t k, size_t *bins,
                            double *weights, double *points);

/* Bins caller points (a renderer's own samples) into (bin, weight) form over
 * n bins: bin floor(N x_j), weight 1/p_bin (1 if importance is NULL; 0 in a
 * bin outside the support, g_bin = 0: s_n = 0 there, as for drawn trials).
 * points[k] in [0,1); bins[k], weights[k] written; no two of the three arrays
 * (nor an output and the importance function) may overlap.
 * MCS_ERR_NULL, MCS_ERR_N_RANGE, MCS_ERR_K_RANGE (k = 0), MCS_ERR_MISMATCH
 * (importance->n != n), MCS_ERR_POINT_RANGE, MCS_ERR_ALIAS, MCS_ERR_INVARIANT
 * (an importance object with p_n < 0, NaN, too small for 1/p_n to be finite,
 * or 0 with g_n > 0, at a bin in use: only a corrupted one).
 * Outputs untouched on error. */
mcs_status mcs_pattern_bin_points(size_t n, size_t k, const mcs_importance *importance,
                                  const double *points, size_t *bins, double *weights);

/* mcs_pattern_bin_points for float points, read in place: each x_j widens
 * to double exactly, so bins and weights are bit-equal to the double call's
 * on the widened points (a float just below 1.0f is in [0,1); 1.0f is not).
 * Statuses as mcs_pattern_bin_points. */
mcs_status mcs_pattern_bin_points_f(size_t n, size_t k, const mcs_importance *importance,
                                    const float *points, size_t *bins, double *weights);

/* Largest total weight of one trial mcs_pattern_dense accepts: 2^220, so no
 * s_n overflows (MCS_ERR_MAGNITUDE beyond it). */
#define MCS_PATTERN_MAX_DENSE 1.684996666696915e+66

/* Dense s_n = r_n / p_n (eq. 38) from a trial's k (bin, weight) pairs:
 * s[bin] is the sum of the weights of the samples in that bin.
 * bins[k] in [0,n), weights[k] finite and >= 0, s[n] written; s must not
 * overlap bins or weights (it is zeroed before they are read).
 * MCS_ERR_NULL, MCS_ERR_N_RANGE, MCS_ERR_K_RANGE (k = 0), MCS_ERR_BIN_RANGE,
 * MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE, MCS_ERR_ALIAS. s untouched on error. */
mcs_status mcs_pattern_dense(size_t n, size_t k, const size_t *bins, const double *weights,
                             double *s);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_PATTERN_H */
