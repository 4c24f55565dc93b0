/* The blue-noise samplers' entry points (bluenoise.h): names, parameters,
 * work sizes and the checks before a draw; the samplers themselves are in
 * blue_poisson.c, blue_lloyd.c and pmj02.c. */
#include "mcspec/bluenoise.h"
#include "blue_internal.h"
#include "core/internal.h"
#include "random/rng_inline.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>

/* Defaults (bluenoise.h; docs/samplers.md says why these). In 1D dart
 * throwing jams at Renyi's parking constant 0.7476 and Bridson near 0.67,
 * so their 1D radii are lower. */
#define DART_RADIUS_1D 0.70
#define DISK_RADIUS_1D 0.60
#define DART_RADIUS 0.75
#define DART_ATTEMPTS 1000u
#define DISK_RADIUS 0.65
#define DISK_ATTEMPTS 30u
#define LLOYD_ITERATIONS 10u
#define LLOYD_RESOLUTION 64u
#define BN_CANDIDATES 10u

const char *mcs_bluenoise_kind_str(mcs_bluenoise_kind kind)
{
    switch (kind) {
    case MCS_BLUENOISE_DART_THROWING: return "dart-throwing";
    case MCS_BLUENOISE_POISSON_DISK: return "poisson-disk";
    case MCS_BLUENOISE_LLOYD: return "lloyd";
    case MCS_BLUENOISE_PMJ02: return "pmj02";
    case MCS_BLUENOISE_PMJ02BN: return "pmj02bn";
    }
    return "unknown";
}

static int is_poisson(mcs_bluenoise_kind kind)
{
    return kind == MCS_BLUENOISE_DART_THROWING || kind == MCS_BLUENOISE_POISSON_DISK;
}

static int kind_ok(mcs_bluenoise_kind kind)
{
    return (unsigned)kind < (unsigned)MCS_BLUENOISE_KIND_COUNT; /* enum may be unsigned */
}

int mcs_bluenoise_has_dim(mcs_bluenoise_kind kind, size_t dim)
{
    if (!kind_ok(kind))
        return 0;
    if (is_poisson(kind))
        return dim >= 1u && dim <= (size_t)MCS_BLUENOISE_MAX_DIM;
    return dim == 2u;
}

/* Which fields a kind reads: radius, attempts, iterations, resolution,
 * candidates. */
static void fields_of(mcs_bluenoise_kind kind, int used[5])
{
    for (int f = 0; f < 5; ++f)
        used[f] = 0;
    if (is_poisson(kind))
        used[0] = used[1] = 1;
    else if (kind == MCS_BLUENOISE_LLOYD)
        used[2] = used[3] = 1;
    else if (kind == MCS_BLUENOISE_PMJ02BN)
        used[4] = 1;
}

mcs_status mcs_bluenoise_params_resolve(mcs_bluenoise_kind kind, size_t dim,
                                        const mcs_bluenoise_params *params,
                                        mcs_bluenoise_params *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    if (!mcs_bluenoise_has_dim(kind, dim))
        return MCS_ERR_KIND;
    mcs_bluenoise_params p = {0.0, 0u, 0u, 0u, 0u};
    if (params != NULL)
        p = *params;
    if (!isfinite(p.radius))
        return MCS_ERR_NOT_FINITE;
    int used[5];
    fields_of(kind, used);
    const int set[5] = {p.radius != 0.0, p.attempts != 0u, p.iterations != 0u, p.resolution != 0u,
                        p.candidates != 0u};
    for (int f = 0; f < 5; ++f)
        if (set[f] && !used[f])
            return MCS_ERR_DOMAIN;
    if (set[0] && !(p.radius >= MCS_BLUENOISE_MIN_RADIUS && p.radius <= MCS_BLUENOISE_MAX_RADIUS))
        return MCS_ERR_DOMAIN;
    if (p.attempts > MCS_BLUENOISE_MAX_ATTEMPTS || p.iterations > MCS_BLUENOISE_MAX_ITERATIONS ||
        p.resolution > MCS_BLUENOISE_MAX_RESOLUTION || p.candidates > MCS_BLUENOISE_MAX_CANDIDATES)
        return MCS_ERR_DOMAIN;
    const int dart = kind == MCS_BLUENOISE_DART_THROWING;
    if (used[0] && !set[0])
        p.radius = dart ? (dim == 1u ? DART_RADIUS_1D : DART_RADIUS)
                        : (dim == 1u ? DISK_RADIUS_1D : DISK_RADIUS);
    if (used[1] && !set[1])
        p.attempts = dart ? DART_ATTEMPTS : DISK_ATTEMPTS;
    if (used[2] && !set[2])
        p.iterations = LLOYD_ITERATIONS;
    if (used[3] && !set[3])
        p.resolution = LLOYD_RESOLUTION;
    if (used[4] && !set[4])
        p.candidates = BN_CANDIDATES;
    *out = p;
    return MCS_OK;
}

static mcs_status check_shape(mcs_bluenoise_kind kind, size_t dim, size_t k)
{
    if (!mcs_bluenoise_has_dim(kind, dim))
        return MCS_ERR_KIND;
    if (k == 0u || k > (size_t)MCS_BLUENOISE_MAX_K)
        return MCS_ERR_K_RANGE;
    /* With a 32-bit size_t the work of the largest sets would pass SIZE_MAX
     * (at most 8 + 8 dim bytes per point of the 2^dim k + 2 the Poisson
     * kinds hold, and 4 per cell: 300 k bytes bounds every kind). */
    if ((double)k * 300.0 > (double)SIZE_MAX)
        return MCS_ERR_K_RANGE;
    return MCS_OK;
}

static size_t work_bytes(mcs_bluenoise_kind kind, size_t dim, size_t k)
{
    if (is_poisson(kind))
        return mcs_blue_poisson_work_bytes_(dim, k);
    if (kind == MCS_BLUENOISE_LLOYD)
        return mcs_blue_lloyd_work_bytes_(k);
    return mcs_pmj02_work_bytes_(k);
}

mcs_status mcs_bluenoise_work_size(mcs_bluenoise_kind kind, size_t dim, size_t k, size_t *bytes)
{
    if (bytes == NULL)
        return MCS_ERR_NULL;
    const mcs_status st = check_shape(kind, dim, k);
    if (st != MCS_OK)
        return st;
    *bytes = work_bytes(kind, dim, k);
    return MCS_OK;
}

/* A draw's or a maximal set's arguments. */
typedef struct {
    mcs_bluenoise_kind kind;
    size_t dim, k;
    const mcs_bluenoise_params *params;
    mcs_rng *rng;
    void *work;
    size_t work_bytes;
    double *points;
    size_t points_len; /* doubles */
} call_;

/* Everything a draw or a maximal set checks before it runs, in the order
 * bluenoise.h lists the statuses; *p gets the resolved parameters. */
static mcs_status check_draw(const call_ *c, mcs_bluenoise_params *p)
{
    if (c->rng == NULL || c->work == NULL || c->points == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_shape(c->kind, c->dim, c->k);
    if (st == MCS_OK)
        st = mcs_bluenoise_params_resolve(c->kind, c->dim, c->params, p);
    if (st != MCS_OK)
        return st;
    if (!mcs_rng_is_seeded_(c->rng))
        return MCS_ERR_UNINIT;
    const size_t need = work_bytes(c->kind, c->dim, c->k);
    if (c->work_bytes < need)
        return MCS_ERR_SPACE;
    const size_t pts_bytes = mcs_bytes_(c->points_len, sizeof *c->points);
    if (mcs_overlap_(c->work, need, c->points, pts_bytes) ||
        mcs_overlap_(c->work, need, c->rng, sizeof *c->rng) ||
        mcs_overlap_(c->points, pts_bytes, c->rng, sizeof *c->rng))
        return MCS_ERR_ALIAS;
    return MCS_OK;
}

mcs_status mcs_bluenoise_draw(mcs_bluenoise_kind kind, size_t dim, size_t k,
                              const mcs_bluenoise_params *params, mcs_rng *rng, void *work,
                              size_t work_bytes_given, double *points)
{
    const call_ c = {kind, dim, k, params, rng, work, work_bytes_given, points, k * dim};
    mcs_blue_job_ job = {kind, dim, k, {0.0, 0u, 0u, 0u, 0u}, NULL, work, 0, points, NULL};
    mcs_status st = check_draw(&c, &job.p);
    if (st != MCS_OK)
        return st;
    mcs_rng local = *rng; /* committed only on success */
    job.rng = &local;
    if (is_poisson(kind))
        st = mcs_blue_poisson_(&job);
    else if (kind == MCS_BLUENOISE_LLOYD)
        st = mcs_blue_lloyd_(k, &job.p, &local, work, points);
    else
        st = mcs_pmj02_(k, kind == MCS_BLUENOISE_PMJ02BN ? job.p.candidates : 1u, &local, work,
                        points);
    if (st == MCS_OK)
        *rng = local;
    return st;
}

mcs_status mcs_bluenoise_maximal(mcs_bluenoise_kind kind, size_t dim, size_t k,
                                 const mcs_bluenoise_params *params, mcs_rng *rng, void *work,
                                 size_t work_bytes_given, size_t cap, double *points, size_t *count)
{
    if (count == NULL)
        return MCS_ERR_NULL;
    if (kind_ok(kind) && !is_poisson(kind))
        return MCS_ERR_KIND;
    const size_t len = cap > SIZE_MAX / 4u ? SIZE_MAX : cap * dim;
    const call_ c = {kind, dim, k, params, rng, work, work_bytes_given, points, len};
    mcs_blue_job_ job = {kind, dim, k, {0.0, 0u, 0u, 0u, 0u}, NULL, work, 1, points, count};
    mcs_status st = check_draw(&c, &job.p);
    if (st == MCS_OK && cap < MCS_BLUENOISE_MAXIMAL_CAP(dim, k))
        st = MCS_ERR_SPACE;
    if (st == MCS_OK && (mcs_overlap_(count, sizeof *count, points, mcs_bytes_(len, sizeof *points)) ||
                         mcs_overlap_(count, sizeof *count, rng, sizeof *rng) ||
                         mcs_overlap_(count, sizeof *count, work, work_bytes(kind, dim, k))))
        st = MCS_ERR_ALIAS;
    if (st != MCS_OK)
        return st;
    mcs_rng local = *rng;
    job.rng = &local;
    st = mcs_blue_poisson_(&job);
    if (st == MCS_OK)
        *rng = local;
    return st;
}
