/* Type-1 NUFFT, first stage: spreading the points onto the periodic grid.
 * Each point x becomes w kernel values per axis at the grid points nearest
 * t = n x; in 2D their outer product is added to the grid (w^2 adds). */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "nufft_internal.h"

#if MCS_CONFIG_NUFFT /* else nothing here (config.h) */

/* One coordinate x of a point: the kernel values phi((l - t) 2/w) at the w
 * grid points l = l0 .. l0 + w - 1, l0 = ceil(t - w/2), t = n x (so every
 * |(l - t) 2/w| <= 1), and those points' indices modulo n. l0 >= -w/2 and
 * l0 + w - 1 <= n + w/2 < 2n (n >= 2w), so one wrap suffices.
 * t is carried as t_hi + t_lo = n x exactly (fma gives the product's
 * rounding error): rounding t to a double would shift the point by up to
 * half an ulp of n, a phase error of pi k eps at mode k (3.5e-14 at
 * k = 100, above tol = 1e-14); l - t_hi is exact, and the offsets keep only
 * their own rounding, a few eps of a grid point whatever k. Indices are
 * 32-bit (n < 2^29 within the caps of nufft.h), which keeps spread_2d's
 * frame small. */
static void axis_weights(const mcs_nufft *plan, double x, double *ker, uint32_t *idx)
{
    const size_t w = plan->width;
    const double nd = (double)plan->n, scale = 2.0 / (double)w;
    const double t_hi = x * nd, t_lo = fma(x, nd, -t_hi);
    const double l0 = ceil(t_hi - 0.5 * (double)w);
    const ptrdiff_t n = (ptrdiff_t)plan->n;
    ptrdiff_t l = (ptrdiff_t)l0;
    for (size_t i = 0; i < w; ++i, ++l) {
        ker[i] = mcs_nufft_kernel_(((l0 + (double)i - t_hi) - t_lo) * scale, plan->beta);
        idx[i] = (uint32_t)(l < 0 ? l + n : (l >= n ? l - n : l));
    }
}

static void spread_1d(const mcs_nufft *plan, double x)
{
    double ker[MCS_NUFFT_MAX_WIDTH];
    uint32_t idx[MCS_NUFFT_MAX_WIDTH];
    axis_weights(plan, x, ker, idx);
    double *g = plan->grid;
    for (size_t i = 0; i < plan->width; ++i)
        g[idx[i]] += ker[i];
}

/* The 2D grid holds real row y at complex row y/2 of n, as its real part for
 * even y and its imaginary part for odd y: real (x, y) is double
 * (y - y % 2) n + 2 x + y % 2. */
static void spread_2d(const mcs_nufft *plan, double x, double y)
{
    double kx[MCS_NUFFT_MAX_WIDTH], ky[MCS_NUFFT_MAX_WIDTH];
    uint32_t ix[MCS_NUFFT_MAX_WIDTH], iy[MCS_NUFFT_MAX_WIDTH];
    axis_weights(plan, x, kx, ix);
    axis_weights(plan, y, ky, iy);
    const size_t w = plan->width, n = plan->n;
    for (size_t i = 0; i < w; ++i)
        ix[i] *= 2u; /* < 2n < 2^30 */
    for (size_t j = 0; j < w; ++j) {
        const size_t row_y = iy[j];
        double *row = plan->grid + (row_y & ~(size_t)1u) * n + (row_y & 1u);
        const double v = ky[j];
        for (size_t i = 0; i < w; ++i)
            row[ix[i]] += v * kx[i];
    }
}

static void clear_grid(const mcs_nufft *plan)
{
    const size_t count = plan->dim == 1u ? plan->n : plan->n * plan->n;
    memset(plan->grid, 0, count * sizeof(double));
}

void mcs_nufft_spread_(const mcs_nufft *plan, const double *points, size_t k)
{
    clear_grid(plan);
    if (plan->dim == 1u)
        for (size_t j = 0; j < k; ++j)
            spread_1d(plan, points[j]);
    else
        for (size_t j = 0; j < k; ++j)
            spread_2d(plan, points[2u * j], points[2u * j + 1u]);
}

void mcs_nufft_spread_f_(const mcs_nufft *plan, const float *points, size_t k)
{
    clear_grid(plan);
    if (plan->dim == 1u)
        for (size_t j = 0; j < k; ++j)
            spread_1d(plan, (double)points[j]);
    else
        for (size_t j = 0; j < k; ++j)
            spread_2d(plan, (double)points[2u * j], (double)points[2u * j + 1u]);
}

#else
/* ISO C wants a declaration in every translation unit. */
typedef int mcs_nufft_left_out_;
#endif /* MCS_CONFIG_NUFFT */
