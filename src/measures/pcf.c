/* Pair correlation of point sets: psa's RDF and the Gaussian-kernel PCF
 * over a cell grid, and their accumulator over sets (pcf.h). */
#include "mcspec/pcf.h"
#include "measures_internal.h"
#include "pcf_internal.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

/* Kernel terms farther than this many sigma from a bin centre are left out
 * (e^-32 of the peak). */
#define KERNEL_REACH 8.0

/* Sets below this many points take all pairs (the grid would not pay). */
#define GRID_MIN_K 16u

static const double pi = 3.14159265358979323846;

double mcs_pcf_spacing_(size_t dim, size_t k)
{
    return dim == 1u ? 1.0 / (double)k : 1.0 / sqrt((double)k);
}

double mcs_pcf_cutoff_(const mcs_pcf *acc)
{
    return acc->radius + (acc->estimator == MCS_PCF_GAUSSIAN ? KERNEL_REACH * acc->sigma : 0.0);
}

/* The measure of ring [r0, r1) (absolute units) in dim dimensions. */
double mcs_pcf_ring_(size_t dim, double r0, double r1)
{
    return dim == 1u ? 2.0 * (r1 - r0) : pi * (r1 * r1 - r0 * r0);
}

mcs_status mcs_pcf_size(size_t bins, size_t *bytes)
{
    if (bytes == NULL)
        return MCS_ERR_NULL;
    if (bins == 0u || bins > (size_t)MCS_PCF_MAX_BINS)
        return MCS_ERR_N_RANGE;
    *bytes = MCS_PCF_SIZE(bins);
    return MCS_OK;
}

static int estimator_ok(mcs_pcf_estimator e)
{
    return e == MCS_PCF_RDF || e == MCS_PCF_GAUSSIAN;
}

static int positive_finite(double x)
{
    return isfinite(x) && x > 0.0;
}

/* The arrays init lays over mem. */
static void layout(mcs_pcf *acc)
{
    double *base = mcs_meas_align_(acc->mem, 64u);
    acc->mean = base;
    acc->m2 = base + acc->bins;
    acc->value = base + 2u * acc->bins;
}

mcs_status mcs_pcf_check_(const mcs_pcf *acc)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if ((acc->dim != 1u && acc->dim != 2u) || !estimator_ok(acc->estimator) || acc->bins == 0u ||
        acc->bins > (size_t)MCS_PCF_MAX_BINS || !positive_finite(acc->radius) ||
        (acc->estimator == MCS_PCF_GAUSSIAN ? !positive_finite(acc->sigma) : acc->sigma != 0.0) ||
        acc->mem == NULL || acc->bytes != MCS_PCF_SIZE(acc->bins))
        return MCS_ERR_UNINIT;
    mcs_pcf shape = *acc;
    layout(&shape);
    if (shape.mean != acc->mean || shape.m2 != acc->m2 || shape.value != acc->value ||
        mcs_overlap_(acc, sizeof *acc, acc->mem, acc->bytes))
        return MCS_ERR_UNINIT;
    if (!mcs_meas_k_range_ok_(acc->count, acc->k_min, acc->k_max) ||
        acc->count > (uint64_t)MCS_MAX_COUNT || (acc->count > 0u && acc->k_min < 2u))
        return MCS_ERR_INVARIANT;
    for (size_t b = 0; b < acc->bins; ++b) {
        const double mu = acc->mean[b], m2 = acc->m2[b];
        if (!isfinite(mu) || !isfinite(m2) || m2 < 0.0 ||
            (acc->count == 0u && (mu != 0.0 || m2 != 0.0)) || (acc->count == 1u && m2 != 0.0))
            return MCS_ERR_INVARIANT;
    }
    return MCS_OK;
}

mcs_status mcs_pcf_init(mcs_pcf *acc, size_t dim, mcs_pcf_estimator estimator, size_t bins,
                        double radius, double sigma, void *mem, size_t bytes)
{
    if (acc == NULL || mem == NULL)
        return MCS_ERR_NULL;
    if (dim != 1u && dim != 2u)
        return MCS_ERR_DOMAIN;
    if (!estimator_ok(estimator))
        return MCS_ERR_KIND;
    if (bins == 0u || bins > (size_t)MCS_PCF_MAX_BINS)
        return MCS_ERR_N_RANGE;
    if (!positive_finite(radius) || (estimator == MCS_PCF_GAUSSIAN && !positive_finite(sigma)))
        return MCS_ERR_DOMAIN;
    if (bytes < MCS_PCF_SIZE(bins))
        return MCS_ERR_SPACE;
    if (mcs_overlap_(acc, sizeof *acc, mem, MCS_PCF_SIZE(bins)))
        return MCS_ERR_ALIAS;
    mcs_pcf a;
    memset(&a, 0, sizeof a);
    a.dim = dim;
    a.estimator = estimator;
    a.bins = bins;
    a.radius = radius;
    a.sigma = estimator == MCS_PCF_GAUSSIAN ? sigma : 0.0;
    a.mem = mem;
    a.bytes = MCS_PCF_SIZE(bins);
    layout(&a);
    memset(a.mean, 0, 3u * bins * sizeof(double));
    *acc = a;
    return MCS_OK;
}

/* ---- The pairs ------------------------------------------------------------------ */

/* Cells per axis for a set of k points with cutoff c (absolute): the
 * largest m <= 1/c with m^dim <= k, or 0 for all pairs (m < 3: the 3^d
 * neighbours would repeat cells). */
static size_t grid_side(size_t dim, size_t k, double c)
{
    if (k < GRID_MIN_K)
        return 0u;
    /* A hair below 1/c: a coordinate on a cell edge may round into the next
     * cell, and the margin keeps its true neighbours in the 3^d it scans. */
    double m = floor(1.0 / (c * (1.0 + 1e-9)));
    const double cap = dim == 1u ? (double)k : floor(sqrt((double)k));
    m = m < cap ? m : cap;
    size_t side = m >= 3.0 ? (size_t)m : 0u;
    while (dim == 2u && side > 0u && side * side > k) /* sqrt rounding */
        --side;
    return side >= 3u ? side : 0u;
}

mcs_status mcs_pcf_set_check_(const mcs_pcf *acc, size_t k, size_t *side, size_t *bytes)
{
    if (k < 2u || k > (SIZE_MAX / sizeof(size_t) - 2u) / 2u)
        return MCS_ERR_K_RANGE;
    const double c = mcs_pcf_cutoff_(acc) * mcs_pcf_spacing_(acc->dim, k);
    if (!(c <= 0.5))
        return MCS_ERR_K_RANGE;
    const size_t m = grid_side(acc->dim, k, c);
    const size_t cells = acc->dim == 1u ? m : m * m;
    *side = m;
    *bytes = m == 0u ? 0u : (cells + 2u + k) * sizeof(size_t);
    return MCS_OK;
}

mcs_status mcs_pcf_work_size(const mcs_pcf *acc, size_t k, size_t *bytes)
{
    mcs_status st = bytes == NULL ? MCS_ERR_NULL : mcs_pcf_check_(acc);
    size_t side = 0, need = 0;
    if (st == MCS_OK)
        st = mcs_pcf_set_check_(acc, k, &side, &need);
    if (st == MCS_OK)
        *bytes = need;
    return st;
}

typedef struct {
    size_t dim, bins;
    const double *p;
    double *sum;         /* per bin: 2 x the pair count, or 2 x the kernel sum */
    int gaussian;
    double scale;        /* RDF: the bin of distance d is floor(d * scale) */
    double width, sigma; /* Gaussian: bin width and sigma, absolute */
    double reach2;       /* squared cutoff, absolute */
    double norm;         /* Gaussian: 1 / (sigma sqrt(2 pi)) */
} pair_ctx;

static MCS_ALWAYS_INLINE double torus_d2(const double *a, const double *b, size_t dim)
{
    double d2 = 0.0;
    for (size_t i = 0; i < dim; ++i) {
        double t = fabs(a[i] - b[i]);
        t = t > 0.5 ? 1.0 - t : t;
        d2 += t * t;
    }
    return d2;
}

/* One ordered pair at squared distance d2 (below the cutoff). */
static void tally(const pair_ctx *c, double d2)
{
    const double d = sqrt(d2);
    if (!c->gaussian) {
        const double u = d * c->scale;
        if (u < (double)c->bins)
            c->sum[(size_t)u] += 1.0;
        return;
    }
    /* Bin centres within KERNEL_REACH sigma of d. */
    const double lo = (d - KERNEL_REACH * c->sigma) / c->width - 0.5;
    const double hi = (d + KERNEL_REACH * c->sigma) / c->width - 0.5;
    size_t b0 = lo <= 0.0 ? 0u : (size_t)ceil(lo);
    size_t b1 = hi < 0.0 ? 0u : (size_t)floor(hi) + 1u;
    b1 = b1 < c->bins ? b1 : c->bins;
    for (size_t b = b0; b < b1; ++b) {
        const double t = ((double)b + 0.5) * c->width - d;
        c->sum[b] += c->norm * exp(-0.5 * (t * t) / (c->sigma * c->sigma));
    }
}

static void all_pairs(const pair_ctx *c, size_t k)
{
    for (size_t i = 0; i < k; ++i)
        for (size_t j = 0; j < k; ++j) {
            if (j == i)
                continue;
            const double d2 = torus_d2(c->p + i * c->dim, c->p + j * c->dim, c->dim);
            if (d2 < c->reach2)
                tally(c, d2);
        }
}

static size_t cell_of(double x, size_t m)
{
    size_t a = (size_t)(x * (double)m);
    return a < m ? a : m - 1u;
}

static size_t point_cell(const double *q, size_t dim, size_t m)
{
    return dim == 1u ? cell_of(q[0], m) : cell_of(q[1], m) * m + cell_of(q[0], m);
}

/* Counting sort of the points into m^dim cells: order[start[c] ..
 * start[c + 1]) are the points of cell c. */
static void grid_build(const pair_ctx *c, size_t k, size_t m, size_t *start, size_t *order)
{
    const size_t cells = c->dim == 1u ? m : m * m;
    memset(start, 0, (cells + 1u) * sizeof *start);
    for (size_t i = 0; i < k; ++i)
        ++start[point_cell(c->p + i * c->dim, c->dim, m) + 1u];
    for (size_t a = 0; a < cells; ++a)
        start[a + 1u] += start[a];
    for (size_t i = 0; i < k; ++i) {
        const size_t cell = point_cell(c->p + i * c->dim, c->dim, m);
        order[start[cell]++] = i;
    }
    for (size_t a = cells; a > 0u; --a) /* shift back: start[a] was advanced to start[a + 1] */
        start[a] = start[a - 1u];
    start[0] = 0u;
}

/* Every ordered pair within a cell's 3^dim neighbourhood (m >= 3, so the
 * neighbours are distinct cells and every pair closer than 1/m is seen
 * once from each end). */
static void grid_pairs(const pair_ctx *c, size_t k, size_t m, size_t *start, size_t *order)
{
    grid_build(c, k, m, start, order);
    const size_t ny = c->dim == 1u ? 1u : m;
    for (size_t i = 0; i < k; ++i) {
        const double *q = c->p + i * c->dim;
        const size_t cx = cell_of(q[0], m), cy = c->dim == 1u ? 0u : cell_of(q[1], m);
        for (size_t oy = 0; oy < (ny == 1u ? 1u : 3u); ++oy)
            for (size_t ox = 0; ox < 3u; ++ox) {
                const size_t x = (cx + m + ox - 1u) % m;
                const size_t y = ny == 1u ? 0u : (cy + m + oy - 1u) % m;
                const size_t cell = y * m + x;
                for (size_t t = start[cell]; t < start[cell + 1u]; ++t) {
                    const size_t j = order[t];
                    if (j == i)
                        continue;
                    const double d2 = torus_d2(q, c->p + j * c->dim, c->dim);
                    if (d2 < c->reach2)
                        tally(c, d2);
                }
            }
    }
}

void mcs_pcf_values_(const mcs_pcf *acc, size_t k, const double *points, size_t side, void *work,
                     double *g)
{
    const double s = mcs_pcf_spacing_(acc->dim, k);
    const double width = acc->radius / (double)acc->bins * s, cut = mcs_pcf_cutoff_(acc) * s;
    pair_ctx c;
    c.dim = acc->dim;
    c.bins = acc->bins;
    c.p = points;
    c.sum = g;
    c.gaussian = acc->estimator == MCS_PCF_GAUSSIAN;
    c.scale = (double)acc->bins / (acc->radius * s);
    c.width = width;
    c.sigma = acc->sigma * s;
    c.reach2 = cut * cut;
    c.norm = c.gaussian ? 1.0 / (c.sigma * sqrt(2.0 * pi)) : 0.0;
    memset(g, 0, acc->bins * sizeof *g);
    if (side > 0u) {
        size_t *start = mcs_meas_align_(work, sizeof(size_t));
        const size_t cells = acc->dim == 1u ? side : side * side;
        grid_pairs(&c, k, side, start, start + cells + 1u);
    } else {
        all_pairs(&c, k);
    }
    /* Ordered pairs: the sums are twice the unordered ones, so
     * g = sum / (K (K - 1) measure). */
    const double kk = (double)k * (double)(k - 1u);
    for (size_t b = 0; b < acc->bins; ++b) {
        double measure;
        if (c.gaussian) {
            const double r = ((double)b + 0.5) * width;
            measure = acc->dim == 1u ? 2.0 : 2.0 * pi * r;
        } else {
            measure = mcs_pcf_ring_(acc->dim, (double)b * width, (double)(b + 1u) * width);
        }
        g[b] = g[b] / (kk * measure);
    }
}

mcs_status mcs_pcf_add(mcs_pcf *acc, size_t k, const double *points, void *work,
                       size_t work_bytes)
{
    mcs_status st = points == NULL ? MCS_ERR_NULL : mcs_pcf_check_(acc);
    size_t side = 0, need = 0;
    if (st == MCS_OK)
        st = mcs_pcf_set_check_(acc, k, &side, &need);
    if (st != MCS_OK)
        return st;
    const size_t n = k * acc->dim;
    if (n / acc->dim != k || n > SIZE_MAX / sizeof(double))
        return MCS_ERR_POINT_RANGE;
    const size_t pbytes = n * sizeof(double);
    if (need > 0u && work == NULL)
        return MCS_ERR_NULL;
    if (work_bytes < need)
        return MCS_ERR_SPACE;
    if (mcs_overlap_(points, pbytes, acc, sizeof *acc) ||
        mcs_overlap_(points, pbytes, acc->mem, acc->bytes) ||
        (need > 0u && (mcs_overlap_(work, work_bytes, acc, sizeof *acc) ||
                       mcs_overlap_(work, work_bytes, acc->mem, acc->bytes) ||
                       mcs_overlap_(work, work_bytes, points, pbytes))))
        return MCS_ERR_ALIAS;
    st = mcs_check_points_(n, mcs_points_d_(points), NULL);
    if (st == MCS_OK)
        st = mcs_check_count_(acc->count, 1u);
    if (st != MCS_OK)
        return st;
    mcs_pcf_values_(acc, k, points, side, work, acc->value);
    const double n1 = (double)(acc->count + 1u);
    for (size_t b = 0; b < acc->bins; ++b) {
        const double x = acc->value[b], d = x - acc->mean[b];
        acc->mean[b] += d / n1;
        acc->m2[b] += d * (x - acc->mean[b]);
    }
    acc->k_min = acc->count == 0u || k < acc->k_min ? k : acc->k_min;
    acc->k_max = k > acc->k_max ? k : acc->k_max;
    ++acc->count;
    return MCS_OK;
}

mcs_status mcs_pcf_merge(mcs_pcf *dst, const mcs_pcf *src)
{
    mcs_status st = src == NULL ? MCS_ERR_NULL : mcs_pcf_check_(dst);
    if (st == MCS_OK)
        st = mcs_pcf_check_(src);
    if (st != MCS_OK)
        return st;
    if (dst->dim != src->dim || dst->estimator != src->estimator || dst->bins != src->bins ||
        !(dst->radius == src->radius) || !(dst->sigma == src->sigma))
        return MCS_ERR_MISMATCH;
    if (dst != src && (mcs_overlap_(dst->mem, dst->bytes, src->mem, src->bytes) ||
                       mcs_overlap_(dst, sizeof *dst, src->mem, src->bytes)))
        return MCS_ERR_ALIAS;
    if (mcs_check_count_(dst->count, src->count) != MCS_OK)
        return MCS_ERR_COUNT;
    if (src->count == 0u)
        return MCS_OK;
    const uint64_t na = dst->count, nb = src->count;
    const double fa = (double)na, fb = (double)nb, fn = fa + fb;
    for (size_t b = 0; b < dst->bins; ++b) {
        const double ma = dst->mean[b], mb = src->mean[b], d = mb - ma;
        const double m2 = dst->m2[b] + src->m2[b] + d * d * (fa * fb / fn);
        dst->mean[b] = na == 0u ? mb : ma + d * (fb / fn);
        dst->m2[b] = m2;
    }
    const size_t kmin = src->k_min, kmax = src->k_max;
    dst->k_min = na == 0u || kmin < dst->k_min ? kmin : dst->k_min;
    dst->k_max = kmax > dst->k_max ? kmax : dst->k_max;
    dst->count = na + nb;
    return MCS_OK;
}

mcs_status mcs_pcf_count(const mcs_pcf *acc, uint64_t *count)
{
    mcs_status st = count == NULL ? MCS_ERR_NULL : mcs_pcf_check_(acc);
    if (st == MCS_OK)
        *count = acc->count;
    return st;
}

static mcs_status bin_checked(const mcs_pcf *acc, size_t bin, const double *out)
{
    mcs_status st = out == NULL ? MCS_ERR_NULL : mcs_pcf_check_(acc);
    if (st == MCS_OK && bin >= acc->bins)
        st = MCS_ERR_BIN_RANGE;
    return st;
}

mcs_status mcs_pcf_radius_at(const mcs_pcf *acc, size_t bin, double *out)
{
    mcs_status st = bin_checked(acc, bin, out);
    return st == MCS_OK ? mcs_set_(out, ((double)bin + 0.5) * acc->radius / (double)acc->bins)
                        : st;
}

mcs_status mcs_pcf_mean(const mcs_pcf *acc, size_t bin, double *out)
{
    mcs_status st = bin_checked(acc, bin, out);
    if (st == MCS_OK && acc->count == 0u)
        st = MCS_ERR_EMPTY;
    return st == MCS_OK ? mcs_set_(out, acc->mean[bin]) : st;
}

mcs_status mcs_pcf_stderr(const mcs_pcf *acc, size_t bin, double *out)
{
    mcs_status st = bin_checked(acc, bin, out);
    if (st == MCS_OK && acc->count < 2u)
        st = MCS_ERR_EMPTY;
    if (st != MCS_OK)
        return st;
    const double n = (double)acc->count;
    return mcs_set_(out, sqrt(acc->m2[bin] / (n - 1.0) / n));
}

/* One array's overlap with the others before it, the object and its buffer. */
static int array_aliases(const mcs_pcf *acc, double *const *arr, size_t i, size_t len)
{
    if (mcs_overlap_(arr[i], len, acc, sizeof *acc) || mcs_overlap_(arr[i], len, acc->mem, acc->bytes))
        return 1;
    for (size_t j = 0; j < i; ++j)
        if (arr[j] != NULL && mcs_overlap_(arr[i], len, arr[j], len))
            return 1;
    return 0;
}

mcs_status mcs_pcf_read_all(const mcs_pcf *acc, size_t bins, double *radius, double *mean,
                            double *stderr_out)
{
    double *const arr[3] = {radius, mean, stderr_out};
    if (radius == NULL && mean == NULL && stderr_out == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_pcf_check_(acc);
    if (st == MCS_OK && bins != acc->bins)
        st = MCS_ERR_MISMATCH;
    if (st == MCS_OK && ((mean != NULL && acc->count == 0u) ||
                         (stderr_out != NULL && acc->count < 2u)))
        st = MCS_ERR_EMPTY;
    for (size_t i = 0; st == MCS_OK && i < 3u; ++i)
        if (arr[i] != NULL && array_aliases(acc, arr, i, bins * sizeof(double)))
            st = MCS_ERR_ALIAS;
    if (st != MCS_OK)
        return st;
    const double n = (double)acc->count;
    for (size_t b = 0; b < bins; ++b) { /* the arithmetic of the per-bin calls */
        if (radius != NULL)
            radius[b] = ((double)b + 0.5) * acc->radius / (double)acc->bins;
        if (mean != NULL)
            mean[b] = acc->mean[b];
        if (stderr_out != NULL)
            stderr_out[b] = sqrt(acc->m2[b] / (n - 1.0) / n);
    }
    return MCS_OK;
}
