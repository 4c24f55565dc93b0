#include "mcspec/pattern2d.h"
#include "pattern2d_internal.h"
#include "random/rng_inline.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>

const char *mcs_pattern2d_kind_str(mcs_pattern2d_kind kind)
{
    switch (kind) {
    case MCS_PATTERN2D_RANDOM: return "random";
    case MCS_PATTERN2D_JITTERED: return "jittered";
    case MCS_PATTERN2D_GRID: return "grid";
    case MCS_PATTERN2D_SHIFTED_GRID: return "shifted-grid";
    case MCS_PATTERN2D_NROOKS: return "n-rooks";
    case MCS_PATTERN2D_MULTI_JITTERED: return "multi-jittered";
    case MCS_PATTERN2D_CMJ: return "cmj";
    }
    return "unknown";
}

/* strata_y = the largest divisor of k with strata_y^2 <= k. */
static void square_strata(size_t k, size_t *sx, size_t *sy)
{
    size_t best = 1u;
    for (size_t d = 1u; d <= k / d; ++d)
        if (k % d == 0u)
            best = d;
    *sy = best;
    *sx = k / best;
}

mcs_status mcs_pattern2d_init(mcs_pattern2d *pat, mcs_pattern2d_kind kind, size_t k,
                              size_t strata_x, size_t strata_y)
{
    if (pat == NULL)
        return MCS_ERR_NULL;
    if (!mcs_pattern2d_kind_is_valid_(kind))
        return MCS_ERR_KIND;
    if (k == 0u || k > (size_t)MCS_PATTERN2D_MAX_K)
        return MCS_ERR_K_RANGE;
    if (strata_x == 0u && strata_y == 0u) {
        square_strata(k, &strata_x, &strata_y);
    } else if (strata_x == 0u || strata_y == 0u || k % strata_x != 0u || k / strata_x != strata_y) {
        return MCS_ERR_MISMATCH;
    }
    pat->kind = kind;
    pat->k = k;
    pat->strata_x = strata_x;
    pat->strata_y = strata_y;
    return MCS_OK;
}

/* (a + v) / d by one rounding, kept below 1 where rounding would reach it
 * (a <= d - 1, v < 1). */
static double fine_point(size_t a, double v, size_t d)
{
    double u = ((double)a + v) / (double)d;
    return u < 1.0 ? u : nextafter(1.0, 0.0);
}

/* Random, jittered and the two grids: cell (i, j) = point j * m + i. */
static void draw_cells(const mcs_pattern2d *pat, mcs_rng *rng, double *points)
{
    const size_t m = pat->strata_x, n = pat->strata_y;
    double bx = 0.5, by = 0.5;
    if (pat->kind == MCS_PATTERN2D_SHIFTED_GRID) {
        bx = mcs_rng_double_(rng);
        by = mcs_rng_double_(rng);
    }
    for (size_t j = 0; j < n; ++j) {
        for (size_t i = 0; i < m; ++i) {
            double *p = points + 2u * (j * m + i);
            if (pat->kind == MCS_PATTERN2D_RANDOM) {
                p[0] = mcs_rng_double_(rng);
                p[1] = mcs_rng_double_(rng);
                continue;
            }
            if (pat->kind == MCS_PATTERN2D_JITTERED) {
                bx = mcs_rng_double_(rng);
                by = mcs_rng_double_(rng);
            }
            p[0] = fine_point(i, bx, m);
            p[1] = fine_point(j, by, n);
        }
    }
}

/* Exchanges points[a] and points[b]: one step of a shuffle. */
static void swap_at(double *points, size_t a, size_t b)
{
    double t = points[a];
    points[a] = points[b];
    points[b] = t;
}

/* Fisher-Yates on the x slots (they hold the permutation as exact integers
 * until it is complete, so no scratch array is needed). */
static void draw_nrooks(size_t k, mcs_rng *rng, double *points)
{
    for (size_t j = 0; j < k; ++j)
        points[2u * j] = (double)j;
    for (size_t j = k - 1u; j > 0u; --j) {
        size_t r = mcs_rng_bounded_(rng, (uint32_t)(j + 1u));
        swap_at(points, 2u * j, 2u * r);
    }
    for (size_t j = 0; j < k; ++j) {
        points[2u * j] = fine_point((size_t)points[2u * j], mcs_rng_double_(rng), k);
        points[2u * j + 1u] = fine_point(j, mcs_rng_double_(rng), k);
    }
}

/* Chiu, Shirley and Wang: the canonical arrangement puts cell (i, j) at fine
 * column i n + j and fine row j m + i (one point per fine column and row),
 * then shuffles the fine columns among the cells of each column and the fine
 * rows among the cells of each row, which keeps both properties. */
static void draw_multi_jittered(const mcs_pattern2d *pat, mcs_rng *rng, double *points)
{
    const size_t m = pat->strata_x, n = pat->strata_y, k = pat->k;
    for (size_t j = 0; j < n; ++j)
        for (size_t i = 0; i < m; ++i) {
            double *p = points + 2u * (j * m + i);
            p[0] = fine_point(i * n + j, mcs_rng_double_(rng), k);
            p[1] = fine_point(j * m + i, mcs_rng_double_(rng), k);
        }
    for (size_t i = 0; i < m; ++i)
        for (size_t j = 0; j + 1u < n; ++j) {
            size_t r = j + mcs_rng_bounded_(rng, (uint32_t)(n - j));
            swap_at(points, 2u * (j * m + i), 2u * (r * m + i));
        }
    for (size_t j = 0; j < n; ++j)
        for (size_t i = 0; i + 1u < m; ++i) {
            size_t r = i + mcs_rng_bounded_(rng, (uint32_t)(m - i));
            swap_at(points, 2u * (j * m + i) + 1u, 2u * (j * m + r) + 1u);
        }
}

uint32_t mcs_pattern2d_permute(uint32_t i, uint32_t l, uint32_t p)
{
    if (l == 0u || i >= l)
        return 0u;
    uint32_t w = l - 1u; /* mask of the next power of two, minus one */
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    /* Kensler's hash is a bijection on [0, w]; walking the cycle until the
     * image falls below l gives a bijection on [0, l). */
    do {
        i ^= p;
        i *= 0xe170893du;
        i ^= p >> 16;
        i ^= (i & w) >> 4;
        i ^= p >> 8;
        i *= 0x0929eb3fu;
        i ^= p >> 23;
        i ^= (i & w) >> 1;
        i *= 1u | p >> 27;
        i *= 0x6935fa69u;
        i ^= (i & w) >> 11;
        i *= 0x74dcb303u;
        i ^= (i & w) >> 2;
        i *= 0x9e501cc3u;
        i ^= (i & w) >> 2;
        i *= 0xc860a3dfu;
        i &= w;
        i ^= i >> 5;
    } while (i >= l);
    /* Kensler's final rotation (i + p) mod l, summed in 64 bits: the 32-bit
     * sum wraps for p near 2^32, and the images are then no permutation. */
    return (uint32_t)(((uint64_t)i + p) % l);
}

/* Kensler's randfloat, as a double: all 32 hashed bits over 2^32, in [0, 1). */
static double kensler_randfloat(uint32_t i, uint32_t p)
{
    i ^= p;
    i ^= i >> 17;
    i ^= i >> 10;
    i *= 0xb36534e5u;
    i ^= i >> 12;
    i ^= i >> 21;
    i *= 0x93fc4795u;
    i ^= 0xdf6e307fu;
    i ^= i >> 17;
    i *= 1u | p >> 18;
    return (double)i * (1.0 / 4294967296.0);
}

/* Kensler's cmj(s, m, n, p): cell (i, j) = (s % m, s / m) takes fine column
 * i n + sy and fine row j m + sx, with sx, sy permuted by column and row
 * index alone (the same shuffle for every row: "correlated"). */
static void draw_cmj(const mcs_pattern2d *pat, mcs_rng *rng, double *points)
{
    const uint32_t m = (uint32_t)pat->strata_x, n = (uint32_t)pat->strata_y;
    const size_t k = pat->k;
    const uint32_t p = mcs_rng_next_(rng);
    for (uint32_t s = 0; s < (uint32_t)k; ++s) {
        uint32_t i = s % m, j = s / m;
        uint32_t sx = mcs_pattern2d_permute(i, m, p * 0xa511e9b3u);
        uint32_t sy = mcs_pattern2d_permute(j, n, p * 0x63d83595u);
        double jx = kensler_randfloat(s, p * 0xa399d265u);
        double jy = kensler_randfloat(s, p * 0x711ad6a5u);
        points[(size_t)2u * s] = fine_point((size_t)i * n + sy, jx, k);
        points[(size_t)2u * s + 1u] = fine_point((size_t)j * m + sx, jy, k);
    }
}

mcs_status mcs_pattern2d_draw(const mcs_pattern2d *pat, mcs_rng *rng, size_t k, double *points)
{
    if (pat == NULL || rng == NULL || points == NULL)
        return MCS_ERR_NULL;
    /* A never-seeded rng outputs only zeros, on which the bounded draws of
     * n-rooks and multi-jittered never return (rng_inline.h). */
    if (!mcs_pattern2d_is_valid_(pat) || !mcs_rng_is_seeded_(rng))
        return MCS_ERR_UNINIT;
    if (k != pat->k)
        return MCS_ERR_MISMATCH;
    switch (pat->kind) {
    case MCS_PATTERN2D_NROOKS: draw_nrooks(k, rng, points); break;
    case MCS_PATTERN2D_MULTI_JITTERED: draw_multi_jittered(pat, rng, points); break;
    case MCS_PATTERN2D_CMJ: draw_cmj(pat, rng, points); break;
    default: draw_cells(pat, rng, points); break;
    }
    return MCS_OK;
}
