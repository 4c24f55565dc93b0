/* Blue-noise samplers and progressive multi-jittered (0,2) sequences on the
 * unit torus [0,1)^d (docs/samplers.md has each definition, its reference and
 * the figures measured):
 *
 *   kind           dim    a set of K points
 *   dart-throwing  1..3   random darts, each kept when it is at least r from
 *                         every point kept so far (toroidal distance), until K
 *                         are kept or the budget of attempts K darts is spent
 *   poisson-disk   1..3   Bridson (2007): from one random point, up to
 *                         `attempts` candidates per active point in the shell
 *                         r..2r, run until no point is active (a set maximal
 *                         for the method, N points); the K points are a
 *                         uniformly random subset of the N (a subset keeps
 *                         the distance r)
 *   lloyd          2      K uniform points moved `iterations` times to the
 *                         centroids of their toroidal Voronoi cells, the
 *                         centroids estimated on a lattice of about
 *                         `resolution` points per cell (docs/samplers.md)
 *   pmj02          2      the first K points of a progressive multi-jittered
 *                         (0,2) sequence (Christensen, Kensler and Kilpatrick
 *                         2018), valid strata enumerated as Pharr (2019)
 *   pmj02bn        2      the same with best-candidate selection: of
 *                         `candidates` uniform draws among the valid
 *                         positions, the one farthest from the points so far
 *
 * r = radius d_max, with d_max = 2 (delta_d / K)^(1/d) the maximal packing
 * distance of K points (spacing.h; sqrt(2 / (sqrt(3) K)) in 2D). Every
 * toroidal distance between two points of a dart-throwing or poisson-disk
 * set is >= r. Points are written interleaved, points[dim j + c]; every
 * coordinate in [0, 1). The draws are deterministic functions of the rng's
 * state.
 *
 * Memory: each draw works in a caller buffer (mcs_bluenoise_work_size, or
 * MCS_BLUENOISE_WORK_SIZE(dim, k) for a static one, any alignment). The set is
 * built there and copied to points at the end, so a failed draw writes
 * nothing and leaves the rng as it was. */
#ifndef MCSPEC_BLUENOISE_H
#define MCSPEC_BLUENOISE_H

#include <stddef.h>
#include <stdint.h>
#include "status.h"
#include "rng.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    MCS_BLUENOISE_DART_THROWING = 0, /* dim 1..3 */
    MCS_BLUENOISE_POISSON_DISK = 1,  /* dim 1..3 (Bridson) */
    MCS_BLUENOISE_LLOYD = 2,         /* dim 2 */
    MCS_BLUENOISE_PMJ02 = 3,         /* dim 2 */
    MCS_BLUENOISE_PMJ02BN = 4        /* dim 2 */
} mcs_bluenoise_kind;

#define MCS_BLUENOISE_KIND_COUNT 5

/* Most points per set: 2^24 (indices and the strata of pmj02 in 32 bits). */
#define MCS_BLUENOISE_MAX_K 16777216u
/* Largest dimension of the Poisson kinds (the packing bound N <= K /
 * radius^d that sizes their work is proven up to 3: Thue, Hales). */
#define MCS_BLUENOISE_MAX_DIM 3u
/* The radius range of the Poisson kinds, as a fraction of d_max. */
#define MCS_BLUENOISE_MIN_RADIUS 0.5
#define MCS_BLUENOISE_MAX_RADIUS 1.0
/* Largest attempts, iterations, resolution and candidates. */
#define MCS_BLUENOISE_MAX_ATTEMPTS 100000u
#define MCS_BLUENOISE_MAX_ITERATIONS 1000u
#define MCS_BLUENOISE_MAX_RESOLUTION 1024u
#define MCS_BLUENOISE_MAX_CANDIDATES 1000u

/* Parameters of a draw; a field at 0 takes the kind's default (below).
 * Fields a kind does not read must be 0. */
typedef struct {
    double radius;       /* r / d_max: dart-throwing 0.75 (0.70 in 1D), poisson-disk 0.65 (0.60 in 1D) */
    uint32_t attempts;   /* dart-throwing 1000 darts per point; poisson-disk 30 per active point */
    uint32_t iterations; /* lloyd: 10 Lloyd steps */
    uint32_t resolution; /* lloyd: 64 lattice points per Voronoi cell, about */
    uint32_t candidates; /* pmj02bn: 10 candidates per point */
} mcs_bluenoise_params;

/* Name of a kind ("dart-throwing", "poisson-disk", "lloyd", "pmj02",
 * "pmj02bn"), or "unknown"; never NULL. */
const char *mcs_bluenoise_kind_str(mcs_bluenoise_kind kind);

/* 1 if kind is defined in dimension dim (the table above), else 0. */
int mcs_bluenoise_has_dim(mcs_bluenoise_kind kind, size_t dim);

/* The parameters a draw of kind in dim dimensions uses when given params
 * (NULL: all 0), the defaults filled in, into *out. MCS_ERR_NULL (out),
 * MCS_ERR_KIND (kind, or kind not defined in dim),
 * MCS_ERR_NOT_FINITE (radius NaN or infinite), MCS_ERR_DOMAIN (radius not 0
 * and outside [MCS_BLUENOISE_MIN_RADIUS, MCS_BLUENOISE_MAX_RADIUS], a field
 * above its maximum, or a field the kind does not read not 0). *out
 * untouched on error. */
mcs_status mcs_bluenoise_params_resolve(mcs_bluenoise_kind kind, size_t dim,
                                        const mcs_bluenoise_params *params,
                                        mcs_bluenoise_params *out);

/* Bytes of work a draw of k points of kind in dim dimensions needs (any
 * parameters), into *bytes; at most MCS_BLUENOISE_WORK_SIZE(dim, k).
 * MCS_ERR_NULL, MCS_ERR_KIND (kind, or kind not defined in dim),
 * MCS_ERR_K_RANGE (k = 0 or above MCS_BLUENOISE_MAX_K, or 300 k bytes past
 * SIZE_MAX: 32-bit targets stop near 14 million points). *bytes untouched on
 * error. */
mcs_status mcs_bluenoise_work_size(mcs_bluenoise_kind kind, size_t dim, size_t k, size_t *bytes);

/* A constant expression (dim 1..3) at least mcs_bluenoise_work_size's
 * answer for every kind in dim dimensions: the Poisson kinds hold up to
 * 2^dim K + 2 points (the packing bound N <= K / radius^dim at radius 0.5)
 * of dim doubles and two 32-bit links each, the grid's at most K cells, and
 * alignment slack; the other kinds need less. */
#define MCS_BLUENOISE_WORK_SIZE(dim, k)                                                    \
    ((((size_t)1u << (dim)) * (size_t)(k) + 2u) * (8u * (size_t)(dim) + 8u) +              \
     4u * (size_t)(k) + 128u)

/* One set of k points of kind into points[k * dim]. params NULL for the
 * defaults. work is the caller's scratch of work_bytes (contents on return
 * unspecified). MCS_ERR_NULL (rng, points, work), MCS_ERR_KIND,
 * MCS_ERR_K_RANGE, the statuses of mcs_bluenoise_params_resolve,
 * MCS_ERR_UNINIT (rng never seeded), MCS_ERR_SPACE (work_bytes below
 * mcs_bluenoise_work_size), MCS_ERR_ALIAS (work, points and *rng not
 * disjoint), MCS_ERR_EMPTY (a Poisson kind could not place k points at that
 * radius: dart throwing spent its budget, or Bridson's maximal set has fewer
 * than k points; ask a smaller radius or more attempts), MCS_ERR_INVARIANT
 * (pmj02 found no valid stratum: never observed, a defect if seen).
 * On error points and *rng are as they were, and so is work except after
 * MCS_ERR_EMPTY and MCS_ERR_INVARIANT (the failed run's scratch). */
mcs_status mcs_bluenoise_draw(mcs_bluenoise_kind kind, size_t dim, size_t k,
                              const mcs_bluenoise_params *params, mcs_rng *rng, void *work,
                              size_t work_bytes, double *points);

/* Points a maximal set of the Poisson kinds can hold (dim 1..3): the packing
 * bound N <= k / radius^dim at radius 0.5, and 2 for rounding. */
#define MCS_BLUENOISE_MAXIMAL_CAP(dim, k) (((size_t)1u << (dim)) * (size_t)(k) + 2u)

/* The method's maximal set for the Poisson kinds at radius r = radius
 * d_max(k): dart throwing spends its whole budget (attempts k darts),
 * Bridson runs until no point is active. Its n points (in the order placed)
 * go to points[n * dim] of the caller's points[cap * dim], cap at least
 * MCS_BLUENOISE_MAXIMAL_CAP(dim, k), and n to *count; the rest of points is
 * not written. Its ratio r / d_max(n) is the figure Lagae and Dutre (2008)
 * tabulate. Statuses as mcs_bluenoise_draw, but MCS_ERR_KIND also for a
 * kind that is not a Poisson kind, MCS_ERR_NULL for count, MCS_ERR_SPACE
 * also for cap below MCS_BLUENOISE_MAXIMAL_CAP(dim, k), MCS_ERR_ALIAS also
 * for count overlapping the others, and no MCS_ERR_EMPTY. On error
 * nothing is written, work included, and the rng is as it was. */
mcs_status mcs_bluenoise_maximal(mcs_bluenoise_kind kind, size_t dim, size_t k,
                                 const mcs_bluenoise_params *params, mcs_rng *rng, void *work,
                                 size_t work_bytes, size_t cap, double *points, size_t *count);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_BLUENOISE_H */
