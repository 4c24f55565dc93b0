/* Minimum and average minimum toroidal distances of a point set, over the
 * maximal packing distance, and their accumulator over sets (spacing.h). */
#include "mcspec/spacing.h"
#include "measures_internal.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#define MAXD MCS_SPACING_MAX_DIM

/* Centre densities of the densest lattice packings, d = 1..8 (spacing.h):
 * 1/2, 1/(2 sqrt 3), 1/(4 sqrt 2), 1/8, 1/(8 sqrt 2), 1/(8 sqrt 3), 1/16, 1/16. */
static const double centre_density[MAXD] = {
    0.5, 0.28867513459481288225, 0.17677669529663688110, 0.125,
    0.088388347648318440550, 0.072168783648703220563, 0.0625, 0.0625};

/* A grid search stops once the best squared distance is within this
 * fraction below (r / m)^2: a coordinate's cell, floor(x m), can be off by
 * one where x m rounds across a whole number, so the ring bound is kept a
 * hair short of exact (it costs at most one more ring, rarely). */
#define REACH_MARGIN 1e-9

const char *mcs_spacing_statistic_str(mcs_spacing_statistic statistic)
{
    switch (statistic) {
    case MCS_SPACING_MIN_DISTANCE: return "min_distance";
    case MCS_SPACING_AVG_MIN_DISTANCE: return "avg_min_distance";
    case MCS_SPACING_STATISTICS: break;
    }
    return "unknown";
}

static int dim_ok(size_t dim)
{
    return dim >= 1u && dim <= (size_t)MAXD;
}

static double packing_distance(size_t dim, size_t k)
{
    return 2.0 * pow(centre_density[dim - 1u] / (double)k, 1.0 / (double)dim);
}

mcs_status mcs_spacing_packing_distance(size_t dim, size_t k, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    if (!dim_ok(dim))
        return MCS_ERR_DOMAIN;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    *out = packing_distance(dim, k);
    return MCS_OK;
}

/* ---- The grid ------------------------------------------------------------------- */

/* b^e, or SIZE_MAX if that overflows. */
static size_t power_sat(size_t b, size_t e)
{
    size_t r = 1u;
    for (size_t i = 0; i < e; ++i) {
        if (b != 0u && r > SIZE_MAX / b)
            return SIZE_MAX;
        r *= b;
    }
    return r;
}

/* Cells per axis: the largest m with m^dim <= k, or 0 if the brute force
 * is the cheaper search (m < 3, or 3^d (1 + k / m^d) >= k / 2: a point
 * scans about 3^d cells and the points in them, against k for the brute
 * force). */
static size_t grid_side(size_t dim, size_t k)
{
    size_t m = (size_t)pow((double)k, 1.0 / (double)dim);
    while (m > 1u && power_sat(m, dim) > k)
        --m;
    while (power_sat(m + 1u, dim) <= k)
        ++m;
    if (m < 3u)
        return 0u;
    const double cost = pow(3.0, (double)dim) * (1.0 + (double)k / (double)power_sat(m, dim));
    return cost < 0.5 * (double)k ? m : 0u;
}

/* The checks every set passes before anything is read or written, and the
 * work it needs (*need, 0 for the brute force) and its grid side (*side). */
static mcs_status check_size(size_t dim, size_t k, size_t *side, size_t *need)
{
    if (!dim_ok(dim))
        return MCS_ERR_DOMAIN;
    /* The set's k dim doubles must fit in memory: this also keeps the grid
     * search below finite (m^dim saturates at SIZE_MAX, never above k). */
    if (k < 2u || k > SIZE_MAX / (dim * sizeof(double)))
        return MCS_ERR_K_RANGE;
    *side = grid_side(dim, k);
    *need = 0u;
    if (*side == 0u)
        return MCS_OK;
    const size_t words = power_sat(*side, dim) + 2u + k; /* cells + 1, order[k], slack */
    if (words < k || words > SIZE_MAX / sizeof(size_t))
        return MCS_ERR_K_RANGE;
    *need = words * sizeof(size_t);
    return MCS_OK;
}

mcs_status mcs_spacing_work_size(size_t dim, size_t k, size_t *bytes)
{
    size_t side = 0, need = 0;
    mcs_status st = bytes == NULL ? MCS_ERR_NULL : check_size(dim, k, &side, &need);
    if (st == MCS_OK)
        *bytes = need;
    return st;
}

typedef struct {
    size_t dim, m, cells;
    size_t stride[MAXD]; /* m^a */
    size_t *start;       /* start[c] .. start[c + 1]: the points of cell c in order[] */
    size_t *order;
} grid;

static MCS_ALWAYS_INLINE size_t axis_cell(double x, size_t m)
{
    const size_t c = (size_t)(x * (double)m);
    return c < m ? c : m - 1u;
}

static MCS_ALWAYS_INLINE size_t cell_of(const grid *g, mcs_points_ p, size_t i)
{
    size_t c = 0;
    for (size_t a = 0; a < g->dim; ++a)
        c += axis_cell(mcs_point_(p, i * g->dim + a), g->m) * g->stride[a];
    return c;
}

/* Counting sort of the k points into their cells. */
static MCS_ALWAYS_INLINE void grid_build(grid *g, mcs_points_ p, size_t k)
{
    memset(g->start, 0, (g->cells + 1u) * sizeof *g->start);
    for (size_t i = 0; i < k; ++i)
        ++g->start[cell_of(g, p, i) + 1u];
    for (size_t c = 0; c < g->cells; ++c)
        g->start[c + 1u] += g->start[c];
    for (size_t i = 0; i < k; ++i)
        g->order[g->start[cell_of(g, p, i)]++] = i;
    for (size_t c = g->cells; c > 0u; --c) /* each start moved to the next cell's: back */
        g->start[c] = g->start[c - 1u];
    g->start[0] = 0u;
}

/* Squared toroidal distance of points i and j, coordinate by coordinate. */
static MCS_ALWAYS_INLINE double dist2(mcs_points_ p, size_t dim, size_t i, size_t j)
{
    double s = 0.0;
    for (size_t a = 0; a < dim; ++a) {
        double t = fabs(mcs_point_(p, i * dim + a) - mcs_point_(p, j * dim + a));
        t = t > 0.5 ? 1.0 - t : t;
        s += t * t;
    }
    return s;
}

/* The points of cell c against point i: the least squared distance so far. */
static MCS_ALWAYS_INLINE double scan_cell(const grid *g, mcs_points_ p, size_t i, size_t c,
                                          double best)
{
    for (size_t q = g->start[c]; q < g->start[c + 1u]; ++q) {
        const size_t j = g->order[q];
        if (j == i)
            continue;
        const double d2 = dist2(p, g->dim, i, j);
        best = d2 < best ? d2 : best;
    }
    return best;
}

/* Every cell at Chebyshev offset exactly r from home (toroidally), by an
 * odometer over the offsets in [-r, r]^d that skips the inner cube. */
static MCS_ALWAYS_INLINE double scan_ring(const grid *g, mcs_points_ p, size_t i,
                                          const size_t *home, size_t r, double best)
{
    ptrdiff_t off[MAXD] = {0};
    const ptrdiff_t rr = (ptrdiff_t)r, m = (ptrdiff_t)g->m;
    for (size_t a = 0; a < g->dim; ++a)
        off[a] = -rr;
    for (;;) {
        int on_ring = 0;
        size_t c = 0;
        for (size_t a = 0; a < g->dim; ++a) {
            on_ring |= off[a] == rr || off[a] == -rr;
            c += (size_t)(((ptrdiff_t)home[a] + m + off[a]) % m) * g->stride[a];
        }
        if (on_ring || r == 0u)
            best = scan_cell(g, p, i, c, best);
        size_t a = 0;
        while (a < g->dim && off[a] == rr)
            off[a++] = -rr;
        if (a == g->dim)
            return best;
        ++off[a];
    }
}

/* The squared distance from point i to its nearest other point: rings out
 * from its cell until nothing further can be nearer, or every cell is seen. */
static MCS_ALWAYS_INLINE double nearest_grid(const grid *g, mcs_points_ p, size_t i)
{
    size_t home[MAXD];
    for (size_t a = 0; a < g->dim; ++a)
        home[a] = axis_cell(mcs_point_(p, i * g->dim + a), g->m);
    double best = HUGE_VAL;
    for (size_t r = 0;; ++r) {
        best = scan_ring(g, p, i, home, r, best);
        const double reach = ((double)r - REACH_MARGIN) / (double)g->m;
        if ((r > 0u && best <= reach * reach) || 2u * r + 1u >= g->m)
            return best;
    }
}

static MCS_ALWAYS_INLINE double nearest_brute(mcs_points_ p, size_t dim, size_t k, size_t i)
{
    double best = HUGE_VAL;
    for (size_t j = 0; j < k; ++j) {
        if (j == i)
            continue;
        const double d2 = dist2(p, dim, i, j);
        best = d2 < best ? d2 : best;
    }
    return best;
}

/* One set and its scratch, as the calls take them: passed by address, so no
 * helper takes more arguments than the registers hold (a pushed argument
 * makes gcc report the caller's frame as dynamic). */
typedef struct {
    size_t k, dim;
    mcs_points_ p;
    void *work;
    size_t work_bytes;
} set_view;

/* The checks of a set with its work (see mcs_spacing_distances), and the
 * grid side it is searched with. */
static mcs_status check_set(const set_view *s, size_t *side)
{
    if (mcs_points_addr_(s->p) == NULL)
        return MCS_ERR_NULL;
    size_t need = 0;
    mcs_status st = dim_ok(s->dim) && s->k > SIZE_MAX / s->dim
                        ? MCS_ERR_POINT_RANGE
                        : check_size(s->dim, s->k, side, &need);
    if (st == MCS_OK && need > 0u && s->work == NULL)
        st = MCS_ERR_NULL;
    if (st == MCS_OK && s->work_bytes < need)
        st = MCS_ERR_SPACE;
    if (st == MCS_OK && need > 0u &&
        mcs_overlap_(s->work, s->work_bytes, mcs_points_addr_(s->p),
                     mcs_points_bytes_(s->p, s->k * s->dim)))
        st = MCS_ERR_ALIAS;
    return st == MCS_OK ? mcs_check_points_(s->k * s->dim, s->p, NULL) : st;
}

static MCS_ALWAYS_INLINE void tally(double best, double *mn, double *sum)
{
    *mn = best < *mn ? best : *mn;
    *sum += sqrt(best);
}

/* out[] of a checked set: index order on both paths, so the same doubles. */
static MCS_ALWAYS_INLINE void statistics(const set_view *s, size_t side, double *out)
{
    const size_t k = s->k, dim = s->dim;
    const mcs_points_ p = s->p;
    double mn = HUGE_VAL, sum = 0.0;
    if (side > 0u) {
        grid g;
        g.dim = dim;
        g.m = side;
        g.cells = power_sat(side, dim);
        for (size_t a = 0; a < dim; ++a)
            g.stride[a] = power_sat(side, a);
        g.start = mcs_meas_align_(s->work, sizeof(size_t));
        g.order = g.start + g.cells + 1u;
        grid_build(&g, p, k);
        for (size_t i = 0; i < k; ++i)
            tally(nearest_grid(&g, p, i), &mn, &sum);
    } else {
        for (size_t i = 0; i < k; ++i)
            tally(nearest_brute(p, dim, k, i), &mn, &sum);
    }
    const double dmax = packing_distance(dim, k);
    out[MCS_SPACING_MIN_DISTANCE] = sqrt(mn) / dmax;
    out[MCS_SPACING_AVG_MIN_DISTANCE] = sum / (double)k / dmax;
}

static MCS_ALWAYS_INLINE mcs_status distances(const set_view *s, double *out)
{
    size_t side = 0;
    mcs_status st = out == NULL ? MCS_ERR_NULL : check_set(s, &side);
    if (st == MCS_OK)
        statistics(s, side, out);
    return st;
}

mcs_status mcs_spacing_distances(size_t k, size_t dim, const double *points, void *work,
                                 size_t work_bytes, double *out)
{
    const set_view s = {k, dim, mcs_points_d_(points), work, work_bytes};
    return distances(&s, out);
}

mcs_status mcs_spacing_distances_f(size_t k, size_t dim, const float *points, void *work,
                                   size_t work_bytes, double *out)
{
    const set_view s = {k, dim, mcs_points_f_(points), work, work_bytes};
    return distances(&s, out);
}

/* ---- The accumulator ------------------------------------------------------------- */

static mcs_status check_acc(const mcs_spacing *acc)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (!dim_ok(acc->dim))
        return MCS_ERR_UNINIT;
    const uint64_t n = acc->stat[0].count;
    int ok = mcs_meas_k_range_ok_(n, acc->k_min, acc->k_max);
    for (int s = 0; s < MCS_SPACING_STATISTICS; ++s)
        ok = ok && mcs_meas_welford_ok_(&acc->stat[s]) && acc->stat[s].count == n;
    return ok ? MCS_OK : MCS_ERR_INVARIANT;
}

mcs_status mcs_spacing_init(mcs_spacing *acc, size_t dim)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (!dim_ok(dim))
        return MCS_ERR_DOMAIN;
    memset(acc, 0, sizeof *acc);
    acc->dim = dim;
    for (int s = 0; s < MCS_SPACING_STATISTICS; ++s)
        mcs_welford_init(&acc->stat[s]);
    return MCS_OK;
}

static MCS_ALWAYS_INLINE mcs_status add(mcs_spacing *acc, const set_view *s)
{
    size_t side = 0;
    mcs_status st = check_acc(acc);
    if (st == MCS_OK)
        st = check_set(s, &side);
    if (st == MCS_OK && side > 0u && mcs_overlap_(s->work, s->work_bytes, acc, sizeof *acc))
        st = MCS_ERR_ALIAS;
    /* A full count is refused before the grid is built in the work memory:
     * a refused add changes nothing, work included. */
    for (int i = 0; i < MCS_SPACING_STATISTICS && st == MCS_OK; ++i)
        if (acc->stat[i].count >= MCS_MAX_COUNT)
            st = MCS_ERR_COUNT;
    if (st != MCS_OK)
        return st;
    double v[MCS_SPACING_STATISTICS];
    statistics(s, side, v);
    mcs_spacing next = *acc; /* updated on a copy: a refused add changes nothing */
    for (int i = 0; i < MCS_SPACING_STATISTICS && st == MCS_OK; ++i)
        st = mcs_welford_add(&next.stat[i], v[i]);
    if (st != MCS_OK)
        return st;
    next.k_min = acc->k_min == 0u || s->k < acc->k_min ? s->k : acc->k_min;
    next.k_max = s->k > acc->k_max ? s->k : acc->k_max;
    *acc = next;
    return MCS_OK;
}

mcs_status mcs_spacing_add(mcs_spacing *acc, size_t k, const double *points, void *work,
                           size_t work_bytes)
{
    const set_view s = {k, acc != NULL ? acc->dim : 0u, mcs_points_d_(points), work, work_bytes};
    return add(acc, &s);
}

mcs_status mcs_spacing_add_f(mcs_spacing *acc, size_t k, const float *points, void *work,
                             size_t work_bytes)
{
    const set_view s = {k, acc != NULL ? acc->dim : 0u, mcs_points_f_(points), work, work_bytes};
    return add(acc, &s);
}

mcs_status mcs_spacing_merge(mcs_spacing *dst, const mcs_spacing *src)
{
    mcs_status st = src == NULL ? MCS_ERR_NULL : check_acc(dst);
    if (st == MCS_OK)
        st = check_acc(src);
    if (st == MCS_OK && dst->dim != src->dim)
        st = MCS_ERR_MISMATCH;
    if (st != MCS_OK)
        return st;
    mcs_spacing next = *dst;
    for (int s = 0; s < MCS_SPACING_STATISTICS && st == MCS_OK; ++s)
        st = mcs_welford_merge(&next.stat[s], &src->stat[s]);
    if (st != MCS_OK)
        return st;
    if (src->stat[0].count > 0u) {
        next.k_min = dst->k_min == 0u || src->k_min < dst->k_min ? src->k_min : dst->k_min;
        next.k_max = src->k_max > dst->k_max ? src->k_max : dst->k_max;
    }
    *dst = next;
    return MCS_OK;
}

mcs_status mcs_spacing_count(const mcs_spacing *acc, uint64_t *count)
{
    mcs_status st = count == NULL ? MCS_ERR_NULL : check_acc(acc);
    if (st == MCS_OK)
        *count = acc->stat[0].count;
    return st;
}

static mcs_status read_checked(const mcs_spacing *acc, mcs_spacing_statistic statistic,
                               const double *out)
{
    mcs_status st = out == NULL ? MCS_ERR_NULL : check_acc(acc);
    if (st == MCS_OK && (unsigned)statistic >= (unsigned)MCS_SPACING_STATISTICS)
        st = MCS_ERR_KIND;
    return st;
}

mcs_status mcs_spacing_mean(const mcs_spacing *acc, mcs_spacing_statistic statistic, double *out)
{
    mcs_status st = read_checked(acc, statistic, out);
    return st == MCS_OK ? mcs_welford_mean(&acc->stat[statistic], out) : st;
}

mcs_status mcs_spacing_stderr(const mcs_spacing *acc, mcs_spacing_statistic statistic,
                              double *out)
{
    mcs_status st = read_checked(acc, statistic, out);
    return st == MCS_OK ? mcs_welford_stderr(&acc->stat[statistic], out) : st;
}
