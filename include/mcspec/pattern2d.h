/* 2D sample patterns on the unit torus [0,1)^2, K points per trial.
 *
 * Grid kinds use strata_x x strata_y = K cells of size 1/strata_x by
 * 1/strata_y; cell (i, j) is column i, row j.
 *
 *   random          x_j, y_j i.i.d. uniform
 *   jittered        one uniform point per cell: ((i + xi)/m, (j + eta)/n)
 *   grid            cell centres ((i + 1/2)/m, (j + 1/2)/n), deterministic
 *   shifted grid    ((i + bx)/m, (j + by)/n), one uniform (bx, by) per trial
 *                   (2D uniform jitter: the grid under a random toroidal shift)
 *   n-rooks         x_j = (pi(j) + xi_j)/K, y_j = (j + eta_j)/K with pi a uniform
 *                   random permutation (Latin hypercube: one point per column
 *                   and per row of the K x K grid)
 *   multi-jittered  Chiu, Shirley and Wang (1994): jittered on the m x n cells
 *                   and n-rooks on the K x K fine grid, by shuffling the
 *                   canonical arrangement within columns and within rows
 *   cmj             Kensler (2013) correlated multi-jittered: the same
 *                   column and row shuffles for every cell, from his permute
 *                   and randfloat hashes keyed by one 32-bit seed per trial
 *
 * with m = strata_x, n = strata_y. Points are written interleaved:
 * points[2 j] = x_j, points[2 j + 1] = y_j, every coordinate in [0, 1).
 * sizeof(mcs_pattern2d) is 32 bytes on x86-64 (16 on 32-bit targets). */
#ifndef MCSPEC_PATTERN2D_H
#define MCSPEC_PATTERN2D_H

#include <stddef.h>
#include <stdint.h>
#include "status.h"
#include "rng.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    MCS_PATTERN2D_RANDOM = 0,
    MCS_PATTERN2D_JITTERED = 1,
    MCS_PATTERN2D_GRID = 2,
    MCS_PATTERN2D_SHIFTED_GRID = 3,
    MCS_PATTERN2D_NROOKS = 4,
    MCS_PATTERN2D_MULTI_JITTERED = 5,
    MCS_PATTERN2D_CMJ = 6
} mcs_pattern2d_kind;

#define MCS_PATTERN2D_KIND_COUNT 7

/* Largest K a 2D pattern accepts (cmj keys its hashes with 32-bit indices). */
#define MCS_PATTERN2D_MAX_K 0x7fffffffu

typedef struct {
    mcs_pattern2d_kind kind;
    size_t k;        /* points per trial K */
    size_t strata_x; /* m: columns of cells */
    size_t strata_y; /* n: rows of cells; m n = K */
} mcs_pattern2d;

/* Name of a kind ("random", "jittered", "grid", "shifted-grid", "n-rooks",
 * "multi-jittered", "cmj"), or "unknown". */
const char *mcs_pattern2d_kind_str(mcs_pattern2d_kind kind);

/* Configures a pattern of k points. strata_x = strata_y = 0 picks the most
 * nearly square grid: strata_y the largest divisor of k not above sqrt(k),
 * strata_x = k / strata_y (so a prime k gives k x 1). Otherwise
 * strata_x * strata_y must equal k. Random and n-rooks record the strata but
 * do not use them. MCS_ERR_NULL, MCS_ERR_KIND, MCS_ERR_K_RANGE (k = 0 or
 * above MCS_PATTERN2D_MAX_K), MCS_ERR_MISMATCH (strata do not multiply to k,
 * or only one of them is 0). *pat untouched on error. */
mcs_status mcs_pattern2d_init(mcs_pattern2d *pat, mcs_pattern2d_kind kind, size_t k,
                              size_t strata_x, size_t strata_y);

/* One trial: points[2 k] written; k must equal pat->k. The grid kind draws
 * nothing from rng (it must still be seeded); cmj draws one 32-bit seed per
 * trial. MCS_ERR_NULL, MCS_ERR_UNINIT (pat not from mcs_pattern2d_init, or
 * rng never seeded), MCS_ERR_MISMATCH (k != pat->k).
 * On error nothing is written and rng is not advanced. */
mcs_status mcs_pattern2d_draw(const mcs_pattern2d *pat, mcs_rng *rng, size_t k, double *points);

/* Kensler's keyed permutation: the image of i in a pseudo-random permutation
 * of [0, l) chosen by key p (cycle-walking a hash over the next power of 2).
 * i < l required; returns 0 for l = 0 or i >= l. A permutation for every
 * key: the final (i + p) mod l is summed in 64 bits, so for p + i >= 2^32 it
 * differs from the paper's 32-bit code, whose sum wraps there and then maps
 * two i to one image. Exposed for tests and for renderers that want the same
 * shuffles. */
uint32_t mcs_pattern2d_permute(uint32_t i, uint32_t l, uint32_t p);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_PATTERN2D_H */
