/* Pair correlation of point sets in the unit torus, 1D and 2D
 * (docs/measures.md): psa's radial distribution function (a histogram of
 * the toroidal pair distances over ring areas) and the Gaussian-kernel pair
 * correlation function of Oztireli and Gross (2012, "Analysis and synthesis
 * of point distributions based on pair correlation", ACM TOG 31(6)), as
 * utk computes it; their means over sets with standard errors (Welford per
 * bin), mergeable; the radial power the RDF implies (psa's spectral check);
 * and exact values (random points; the jittered grid, grid, shifted grid and
 * n-rooks of pattern2d.h).
 *
 * Units. A set has K points; its mean spacing is s = 1/K in 1D and
 * 1/sqrt(K) in 2D. The radius R and the kernel's sigma are given in mean
 * spacings, so sets of any K share the bins; a pair at toroidal distance d
 * (per coordinate min(|u - v|, 1 - |u - v|)) sits at d / s. B bins of width
 * w = R / B cover [0, R); bin b is [b w, (b + 1) w), read out at its centre.
 *
 *   RDF (psa's PointSet::RDF): c_b = pairs {i < j} with d in bin b, the bin
 *     floor(d * (B / (R s))) with the quotient and product rounded as
 *     written;
 *       g_b = c_b / (K (K - 1) / 2 * A_b),
 *     A_b the measure of the toroidal ring: pi ((b + 1)^2 - b^2) (w s)^2 in
 *     2D, 2 w s in 1D. psa's scale, npoints (npoints - 1) / 2 * PI * dx^2
 *     (2 i + 1), is this; psa's bins are in absolute distance up to 1/2.
 *     For independent uniform points E g_b = 1 exactly for R s <= 1/2.
 *   Gaussian (utk::PCF, Oztireli and Gross's estimator): at the centre r of
 *     bin b,
 *       g(r) = 2 sum_{i < j} k(r - d_ij) / (K (K - 1) S(r)),
 *     k the normal density of standard deviation sigma s, S(r) = 2 pi r
 *     (2D) or 2 (1D). Pairs with d farther than 8 sigma s from r are left
 *     out (their terms are below e^-32 = 1.3e-14 of the peak). utk divides
 *     further by (1 - 4 r/pi + r^2/pi), the isotropised set covariance of
 *     the open square, even for toroidal distances; on the torus there is
 *     no edge, so mcspec does not (utk's values are mcspec's over that
 *     factor).
 *
 * Every set must have R s + (Gaussian) 8 sigma s <= 1/2 (so every ring lies
 * inside the torus' fundamental square, and random points give E g = 1).
 *
 * Pairs closer than the cutoff R s (+ 8 sigma s) are found in a grid of
 * m^d cells, m = floor(1 / cutoff) capped so m^d <= K, each point looking
 * at its 3^d neighbouring cells: about 3^d K (1 + K cutoff^d) distance
 * evaluations instead of K^2 / 2. m < 3 (or sets of fewer than 16 points):
 * all pairs. The counts are the same integers either way.
 *
 * Memory: a fixed header over a caller-owned buffer (pointset2d.h's style):
 * mcs_pcf_size, then mcs_pcf_init over mem; MCS_PCF_SIZE(B) for a static
 * buffer. The cell grid's work is passed per set (mcs_pcf_work_size,
 * MCS_PCF_WORK_SIZE(K)). A copy of the header shares the buffer. */
#ifndef MCSPEC_PCF_H
#define MCSPEC_PCF_H

#include <stddef.h>
#include <stdint.h>
#include "status.h"
#include "pattern2d.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Most bins. */
#define MCS_PCF_MAX_BINS 1048576u

/* Largest frequency of mcs_pcf_power (cycles per unit length; a
 * periodogram's is at most a few million). */
#define MCS_PCF_MAX_FREQ 1e12

/* The estimators. */
typedef enum {
    MCS_PCF_RDF = 0,     /* psa's histogram over ring areas */
    MCS_PCF_GAUSSIAN = 1 /* the Gaussian-kernel PCF (Oztireli and Gross 2012; utk) */
} mcs_pcf_estimator;

/* Bytes of buffer for B bins (1..MCS_PCF_MAX_BINS): the per-bin mean, M2
 * and one set's values, doubles, and 64 bytes to align. Exactly what
 * mcs_pcf_size reports. */
#define MCS_PCF_SIZE(bins) (64u + 24u * (size_t)(bins))

/* Bytes of cell-grid work for a set of up to k points, a constant
 * expression, at least what mcs_pcf_work_size reports for any object. */
#define MCS_PCF_WORK_SIZE(k) ((2u * (size_t)(k) + 2u) * sizeof(size_t))

/* The header: set by mcs_pcf_init, read-only to the caller. */
typedef struct {
    size_t dim;                  /* 1 or 2; 0 before init */
    mcs_pcf_estimator estimator; /* init's */
    size_t bins;                 /* B */
    double radius;               /* R, in mean spacings */
    double sigma;                /* the kernel's, in mean spacings (0 for the RDF) */
    uint64_t count;              /* sets added */
    size_t k_min, k_max;         /* fewest and most points in a set added (0, 0 before any) */
    void *mem;                   /* the caller's buffer, as given */
    size_t bytes;                /* its bytes in use (the size query's) */
    double *mean, *m2;           /* per bin: mean over sets of g, Welford's M2 */
    double *value;               /* scratch: one set's g */
} mcs_pcf;

/* *bytes = MCS_PCF_SIZE(bins). MCS_ERR_NULL, MCS_ERR_N_RANGE (bins 0 or
 * above MCS_PCF_MAX_BINS). *bytes untouched on error. */
mcs_status mcs_pcf_size(size_t bins, size_t *bytes);

/* Empties acc for sets in dim (1, 2) dimensions, estimator, bins bins over
 * [0, radius) mean spacings, kernel sigma (mean spacings; read only for
 * MCS_PCF_GAUSSIAN), over mem[bytes] (any alignment). MCS_ERR_NULL (acc,
 * mem), MCS_ERR_DOMAIN (dim; radius not finite and > 0; sigma not finite
 * and > 0 for the kernel), MCS_ERR_KIND (estimator), MCS_ERR_N_RANGE
 * (bins), MCS_ERR_SPACE (bytes below MCS_PCF_SIZE(bins)), MCS_ERR_ALIAS
 * (mem overlaps *acc). Neither *acc nor mem changes on error. */
mcs_status mcs_pcf_init(mcs_pcf *acc, size_t dim, mcs_pcf_estimator estimator, size_t bins,
                        double radius, double sigma, void *mem, size_t bytes);

/* Every call below returns MCS_ERR_UNINIT for a header not from
 * mcs_pcf_init (its fields not a valid shape over its buffer) and
 * MCS_ERR_INVARIANT for values no adds produce (a mean not finite, an M2
 * negative or not finite, counts out of order), changing nothing. */

/* *bytes = the cell-grid work a set of k points needs (0: all pairs, work
 * may be NULL). MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_K_RANGE (k < 2, a
 * cutoff past 1/2 at this k, or MCS_PCF_WORK_SIZE(k) past SIZE_MAX).
 * *bytes untouched on error. */
mcs_status mcs_pcf_work_size(const mcs_pcf *acc, size_t k, size_t *bytes);

/* Adds one set: points[k * dim] interleaved, each coordinate in [0, 1);
 * work[work_bytes] the caller's scratch (contents on return unspecified).
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_INVARIANT, MCS_ERR_K_RANGE (as
 * mcs_pcf_work_size), MCS_ERR_POINT_RANGE (a coordinate outside [0, 1) or
 * NaN), MCS_ERR_SPACE (work_bytes below mcs_pcf_work_size), MCS_ERR_ALIAS
 * (points or work overlapping *acc or its buffer, or each other),
 * MCS_ERR_COUNT (the count at MCS_MAX_COUNT). On error nothing changes,
 * work included. */
mcs_status mcs_pcf_add(mcs_pcf *acc, size_t k, const double *points, void *work,
                       size_t work_bytes);

/* dst <- dst union src (Chan et al.); src unchanged; dst == src allowed.
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_INVARIANT, MCS_ERR_MISMATCH (a
 * different dim, estimator, bins, radius or sigma), MCS_ERR_COUNT,
 * MCS_ERR_ALIAS (distinct headers whose buffers overlap). dst untouched on
 * error. */
mcs_status mcs_pcf_merge(mcs_pcf *dst, const mcs_pcf *src);

/* Sets added. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_INVARIANT. */
mcs_status mcs_pcf_count(const mcs_pcf *acc, uint64_t *count);

/* The centre of bin in mean spacings, (bin + 1/2) R / B. MCS_ERR_NULL,
 * MCS_ERR_UNINIT, MCS_ERR_INVARIANT, MCS_ERR_BIN_RANGE (bin >= B). */
mcs_status mcs_pcf_radius_at(const mcs_pcf *acc, size_t bin, double *out);

/* Mean over the sets of g in bin; its standard error over the sets.
 * Statuses as mcs_pcf_radius_at, MCS_ERR_EMPTY (no set; below 2 sets for
 * the standard error). *out untouched on error. */
mcs_status mcs_pcf_mean(const mcs_pcf *acc, size_t bin, double *out);
mcs_status mcs_pcf_stderr(const mcs_pcf *acc, size_t bin, double *out);

/* Every bin at once, bit for bit mcs_pcf_radius_at, _mean and _stderr:
 * radius[b], mean[b], stderr_out[b] for b = 0..B-1, caller arrays of bins
 * doubles, bins = B (else MCS_ERR_MISMATCH); any may be NULL, not all
 * (MCS_ERR_NULL); they must overlap neither each other, *acc nor its
 * buffer (MCS_ERR_ALIAS). MCS_ERR_UNINIT, MCS_ERR_INVARIANT, MCS_ERR_EMPTY
 * (no set with mean, fewer than 2 with stderr_out). Nothing written on
 * error. O(B). */
mcs_status mcs_pcf_read_all(const mcs_pcf *acc, size_t bins, double *radius, double *mean,
                            double *stderr_out);

/* psa's spectral check: the radial power the mean RDF implies at frequency
 * freq (cycles per unit length, >= 0), with g = 1 past the radius (the
 * truncation):
 *   P(f) = 1 + (K - 1) int (g(r) - 1) e^{-2 pi i f.r} dr
 *        = 1 + (K - 1) sum_b (g_b - 1) [r J1(2 pi f r) / f]_{r_b}^{r_b+1}      (2D)
 *        = 1 + (K - 1) sum_b (g_b - 1) [sin(2 pi f r) / (pi f)]_{r_b}^{r_b+1}  (1D)
 * exact for the histogram's piecewise-constant g (r in absolute units;
 * at f = 0 the limits pi r^2 and 2 r). The pair term is (K - 1), the
 * E|S|^2 / K of K points whose pair density is K (K - 1) g; psa's RDFtoRP
 * uses K and a Blackman window over the RDF instead. MCS_ERR_NULL,
 * MCS_ERR_UNINIT, MCS_ERR_INVARIANT, MCS_ERR_KIND (the Gaussian estimator),
 * MCS_ERR_EMPTY (no set), MCS_ERR_MISMATCH (sets of different K),
 * MCS_ERR_DOMAIN (freq not in [0, MCS_PCF_MAX_FREQ]). *out untouched on
 * error. */
mcs_status mcs_pcf_power(const mcs_pcf *acc, double freq, double *out);

/* The exact E g of bin for acc's estimator, bins and radius, for sets of
 * pat (pat NULL: independent uniform points in acc's dimension, any K):
 *   random      RDF: 1. Gaussian: Phi(r/sigma) + (sigma/r) phi(r/sigma) in
 *               2D, Phi(r/sigma) in 1D (the kernel's mass below r = 0 is
 *               lost), Phi and phi the standard normal's.
 *   jittered    RDF: (K A_b - I2_b) / ((K - 1) A_b), I2_b the mass in the
 *               ring of the difference of two points of one cell (a
 *               product of triangles of half-widths 1/m and 1/n)
 *   n-rooks     RDF: (K^2 A_b - K (Ix_b + Iy_b) + I2_b) / ((K - 1)^2 A_b),
 *               Ix, Iy the ring's mass of one axis' triangle (half-width
 *               1/K) and I2 of their product
 *   grid and shifted grid: deterministic, the lattice's offsets counted
 *   Gaussian, jittered and n-rooks: the expected pair count within d, N(d)
 *               (the same disk integrals), integrated against the kernel:
 *               int k(r - d) dN(d) over |r - d| <= 8 sigma, as counted;
 *               the grids: the sum over their offsets
 * (docs/measures.md derives them: the sum over cell offsets of the
 * per-axis difference densities is constant, so only the same-cell term
 * remains). The ring and disk integrals are one-dimensional quadratures
 * (Gauss-Legendre on pieces between the integrand's kinks, mapped to remove
 * the square-root ends); doubling the nodes and quartering the kernel's
 * pieces moves no value by more than 1e-14. MCS_ERR_NULL (acc, out),
 * MCS_ERR_UNINIT, MCS_ERR_INVARIANT, MCS_ERR_BIN_RANGE, MCS_ERR_KIND (a
 * kind not listed: multi-jittered, cmj), MCS_ERR_MISMATCH (a pattern with
 * a 1D acc), MCS_ERR_K_RANGE (the cutoff past 1/2 at the pattern's K).
 * *out untouched on error. */
mcs_status mcs_pcf_exact(const mcs_pcf *acc, const mcs_pattern2d *pat, size_t bin, double *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_PCF_H */
