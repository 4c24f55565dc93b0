/* Lloyd's relaxation on the 2D torus (bluenoise.h): K uniform points, each
 * step moving every point to the centroid of its toroidal Voronoi cell. The
 * centroids are estimated on a lattice of G x G points, G = ceil(sqrt(K
 * resolution)), shifted by one uniform offset per step: a lattice point
 * belongs to the cell of its nearest generator, and a cell's centroid is its
 * generator plus the mean of its lattice points' toroidal displacements from
 * it. The estimate is the exact centroid of a quadrature of about
 * `resolution` nodes per cell, so its error is a fraction of the lattice
 * spacing 1/G (docs/samplers.md measures it); a cell holding no lattice point
 * keeps its generator. */
#include "blue_internal.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>

static size_t lattice_side(size_t k, uint32_t resolution)
{
    return (size_t)ceil(sqrt((double)k * (double)resolution));
}

size_t mcs_blue_lloyd_work_bytes_(size_t k)
{
    const size_t side = mcs_blue_grid_side_(2u, k);
    return mcs_blue_carve_bytes_(side * side, 4u) + mcs_blue_carve_bytes_(k, 4u) +
           mcs_blue_carve_bytes_(2u * k, 8u) + mcs_blue_carve_bytes_(3u * k, 8u);
}

/* The toroidal displacement b - a in [-1/2, 1/2]. */
static double displacement(double a, double b)
{
    double d = b - a;
    if (d > 0.5)
        d -= 1.0;
    else if (d < -0.5)
        d += 1.0;
    return d;
}

static void lloyd_step(mcs_blue_grid_ *g, size_t k, size_t lattice, mcs_rng *rng, double *sum)
{
    mcs_blue_grid_clear_(g);
    for (size_t i = 0; i < k; ++i)
        mcs_blue_grid_add_(g, g->pts + 2u * i); /* the same slot: rebuilds the cells */
    for (size_t i = 0; i < 3u * k; ++i)
        sum[i] = 0.0;
    const double sx = mcs_blue_uniform_(rng), sy = mcs_blue_uniform_(rng);
    const double step = 1.0 / (double)lattice;
    for (size_t row = 0; row < lattice; ++row) {
        double q[2];
        q[1] = mcs_blue_wrap_(((double)row + sy) * step);
        for (size_t col = 0; col < lattice; ++col) {
            q[0] = mcs_blue_wrap_(((double)col + sx) * step);
            uint32_t near = MCS_BLUE_NONE;
            (void)mcs_blue_grid_nearest_(g, q, &near);
            const size_t i = (size_t)near;
            const double *at = g->pts + 2u * i;
            sum[3u * i] += displacement(at[0], q[0]);
            sum[3u * i + 1u] += displacement(at[1], q[1]);
            sum[3u * i + 2u] += 1.0;
        }
    }
    for (size_t i = 0; i < k; ++i) {
        const double n = sum[3u * i + 2u];
        if (n > 0.0) {
            g->pts[2u * i] = mcs_blue_wrap_(g->pts[2u * i] + sum[3u * i] / n);
            g->pts[2u * i + 1u] = mcs_blue_wrap_(g->pts[2u * i + 1u] + sum[3u * i + 1u] / n);
        }
    }
}

mcs_status mcs_blue_lloyd_(size_t k, const mcs_bluenoise_params *p, mcs_rng *rng, void *work,
                           double *points)
{
    const size_t side = mcs_blue_grid_side_(2u, k);
    mcs_blue_carver_ cv = {(unsigned char *)work, mcs_blue_lloyd_work_bytes_(k)};
    mcs_blue_grid_ g;
    g.head = mcs_blue_carve_(&cv, side * side, 4u);
    g.next = mcs_blue_carve_(&cv, k, 4u);
    g.pts = mcs_blue_carve_(&cv, 2u * k, 8u);
    double *pts = g.pts;
    double *sum = mcs_blue_carve_(&cv, 3u * k, 8u);
    mcs_blue_grid_init_(&g, 2u, k, k);
    for (size_t i = 0; i < 2u * k; ++i)
        pts[i] = mcs_blue_uniform_(rng);
    const size_t lattice = lattice_side(k, p->resolution);
    for (uint32_t it = 0; it < p->iterations; ++it)
        lloyd_step(&g, k, lattice, rng, sum);
    for (size_t i = 0; i < 2u * k; ++i)
        points[i] = pts[i];
    return MCS_OK;
}
