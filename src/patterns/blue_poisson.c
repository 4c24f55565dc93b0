/* Dart throwing and Bridson's Poisson-disk sampling on the torus [0,1)^d,
 * d = 1..3 (bluenoise.h), over a linked-cell grid in the caller's work. */
#include "blue_internal.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#define TWO_PI 6.283185307179586476925286766559

/* Points a set at radius >= MCS_BLUENOISE_MIN_RADIUS d_max(k) can hold: the
 * packing bound N <= k / radius^dim (d_max(N) >= r), and 2 for rounding. */
static size_t capacity(size_t dim, size_t k)
{
    return MCS_BLUENOISE_MAXIMAL_CAP(dim, k);
}

size_t mcs_blue_poisson_work_bytes_(size_t dim, size_t k)
{
    const size_t cap = capacity(dim, k), side = mcs_blue_grid_side_(dim, k);
    size_t cells = 1u;
    for (size_t c = 0; c < dim; ++c)
        cells *= side;
    return mcs_blue_carve_bytes_(cells, 4u) + 2u * mcs_blue_carve_bytes_(cap, 4u) +
           mcs_blue_carve_bytes_(cap * dim, 8u);
}

/* A uniform point of the torus. */
static void uniform_point(mcs_rng *rng, size_t dim, double *p)
{
    for (size_t c = 0; c < dim; ++c)
        p[c] = mcs_blue_uniform_(rng);
}

/* A point uniform in the shell r..2r around centre (by volume), wrapped. */
static void shell_point(mcs_rng *rng, size_t dim, const double *centre, double r, double *p)
{
    const double u = mcs_blue_uniform_(rng);
    const double scale = (double)(1u << dim) - 1.0; /* (2r)^d - r^d over r^d */
    const double rho = r * pow(1.0 + scale * u, 1.0 / (double)dim);
    double dir[3] = {0.0, 0.0, 0.0};
    if (dim == 1u) {
        dir[0] = mcs_blue_uniform_(rng) < 0.5 ? -1.0 : 1.0;
    } else if (dim == 2u) {
        const double a = TWO_PI * mcs_blue_uniform_(rng);
        dir[0] = cos(a);
        dir[1] = sin(a);
    } else { /* Archimedes: z uniform on [-1, 1] is uniform on the sphere */
        const double z = 2.0 * mcs_blue_uniform_(rng) - 1.0, a = TWO_PI * mcs_blue_uniform_(rng);
        const double s = sqrt(1.0 - z * z);
        dir[0] = s * cos(a);
        dir[1] = s * sin(a);
        dir[2] = z;
    }
    for (size_t c = 0; c < dim && c < 3u; ++c)
        p[c] = mcs_blue_wrap_(centre[c] + rho * dir[c]);
}

/* Dart throwing: up to budget darts, until stop points are kept. */
static void throw_darts(mcs_blue_grid_ *g, mcs_rng *rng, double r, uint64_t budget, size_t stop)
{
    double p[3];
    for (uint64_t t = 0; t < budget && g->count < stop; ++t) {
        uniform_point(rng, g->dim, p);
        if (!mcs_blue_grid_conflict_(g, p, r))
            mcs_blue_grid_add_(g, p);
    }
}

/* Bridson (2007): an active list of points that may still have room around
 * them; a random active point gets up to attempts candidates in its shell,
 * the first one farther than r from every point joins (and is active), and
 * a point whose candidates all fail leaves the list. */
static void bridson(mcs_blue_grid_ *g, mcs_rng *rng, double r, uint32_t attempts, uint32_t *active)
{
    double p[3];
    uniform_point(rng, g->dim, p);
    mcs_blue_grid_add_(g, p);
    active[0] = 0u;
    size_t live = 1u;
    while (live > 0u && g->count < g->cap) {
        const uint32_t slot = mcs_blue_bounded_(rng, (uint32_t)live);
        const double *centre = g->pts + (size_t)active[slot] * g->dim;
        int placed = 0;
        for (uint32_t a = 0; a < attempts && !placed; ++a) {
            shell_point(rng, g->dim, centre, r, p);
            if (!mcs_blue_grid_conflict_(g, p, r)) {
                active[live++] = (uint32_t)g->count;
                mcs_blue_grid_add_(g, p);
                placed = 1;
            }
        }
        if (!placed)
            active[slot] = active[--live];
    }
}

mcs_status mcs_blue_poisson_(const mcs_blue_job_ *job)
{
    const size_t dim = job->dim, k = job->k;
    const mcs_bluenoise_params *p = &job->p;
    mcs_rng *rng = job->rng;
    double *points = job->points;
    const size_t hold = capacity(dim, k), side = mcs_blue_grid_side_(dim, k);
    size_t cells = 1u;
    for (size_t c = 0; c < dim; ++c)
        cells *= side;
    mcs_blue_carver_ cv = {(unsigned char *)job->work, mcs_blue_poisson_work_bytes_(dim, k)};
    mcs_blue_grid_ g;
    g.head = mcs_blue_carve_(&cv, cells, 4u);
    g.next = mcs_blue_carve_(&cv, hold, 4u);
    uint32_t *active = mcs_blue_carve_(&cv, hold, 4u);
    g.pts = mcs_blue_carve_(&cv, hold * dim, 8u);
    const double *pts = g.pts;
    mcs_blue_grid_init_(&g, dim, k, hold);

    const double r = p->radius * mcs_blue_packing_distance_(dim, k);
    const int dart = job->kind == MCS_BLUENOISE_DART_THROWING;
    if (dart)
        throw_darts(&g, rng, r, (uint64_t)p->attempts * (uint64_t)k, job->maximal ? hold : k);
    else
        bridson(&g, rng, r, p->attempts, active);

    if (job->maximal) { /* the caller's cap >= hold, checked before */
        for (size_t j = 0; j < g.count * dim; ++j)
            points[j] = pts[j];
        *job->count = g.count;
        return MCS_OK;
    }
    if (g.count < k)
        return MCS_ERR_EMPTY;
    if (dart) {
        for (size_t j = 0; j < k * dim; ++j)
            points[j] = pts[j];
        return MCS_OK;
    }
    /* Bridson's set grows from its first point, so its first k points are a
     * blob: take a uniformly random k of the n (a partial Fisher-Yates
     * shuffle of the indices, in the emptied active list). */
    const size_t n = g.count;
    for (size_t i = 0; i < n; ++i)
        active[i] = (uint32_t)i;
    for (size_t i = 0; i < k; ++i) {
        const size_t j = i + mcs_blue_bounded_(rng, (uint32_t)(n - i));
        const uint32_t t = active[i];
        active[i] = active[j];
        active[j] = t;
        for (size_t c = 0; c < dim; ++c)
            points[i * dim + c] = pts[(size_t)active[i] * dim + c];
    }
    return MCS_OK;
}
