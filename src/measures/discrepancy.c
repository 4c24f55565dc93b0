/* The L2 discrepancies by their closed forms, their exact expectations for
 * random points, and the accumulator over sets (discrepancy.h). */
#include "mcspec/discrepancy.h"
#include "measures_internal.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

enum { L2N = MCS_DISCREPANCY_L2_COUNT };

/* Pair terms are summed in blocks of this many, then the blocks Kahan-summed:
 * each block's rounding is at most BLOCK u of its size and the total's no
 * more (mcs_kahan_add_), where one running sum of K^2 / 2 terms could lose
 * K^2 u / 2 in the worst case. */
#define BLOCK 64u

const char *mcs_discrepancy_measure_str(mcs_discrepancy_measure measure)
{
    switch (measure) {
    case MCS_DISCREPANCY_L2_STAR: return "l2_star";
    case MCS_DISCREPANCY_L2_CENTERED: return "l2_centered";
    case MCS_DISCREPANCY_L2_WRAPAROUND: return "l2_wraparound";
    case MCS_DISCREPANCY_L2_SYMMETRIC: return "l2_symmetric";
    case MCS_DISCREPANCY_L2_GENERALIZED: return "l2_generalized";
    case MCS_DISCREPANCY_L2_UNANCHORED: return "l2_unanchored";
    case MCS_DISCREPANCY_STAR: return "star";
    case MCS_DISCREPANCY_MEASURES: break;
    }
    return "unknown";
}

static int measure_ok(mcs_discrepancy_measure m)
{
    return (unsigned)m < (unsigned)MCS_DISCREPANCY_MEASURES; /* a negative value wraps above */
}

static int dim_ok(size_t dim)
{
    return dim >= 1u && dim <= (size_t)MCS_DISCREPANCY_MAX_DIM;
}

/* C0 = int int h of each measure (the header's table), in dim dimensions. */
static void constants(size_t dim, double *c0)
{
    const double d = (double)dim, four_thirds = pow(4.0 / 3.0, d);
    c0[MCS_DISCREPANCY_L2_STAR] = pow(1.0 / 3.0, d);
    c0[MCS_DISCREPANCY_L2_CENTERED] = pow(13.0 / 12.0, d);
    c0[MCS_DISCREPANCY_L2_WRAPAROUND] = four_thirds;
    c0[MCS_DISCREPANCY_L2_SYMMETRIC] = four_thirds;
    c0[MCS_DISCREPANCY_L2_GENERALIZED] = four_thirds;
    c0[MCS_DISCREPANCY_L2_UNANCHORED] = pow(1.0 / 12.0, d);
}

/* E h(x, x) of each measure: the product over coordinates of E h1(x, x). */
static void diagonal_means(size_t dim, double *e)
{
    const double d = (double)dim, three_halves = pow(1.5, d);
    e[MCS_DISCREPANCY_L2_STAR] = pow(0.5, d);
    e[MCS_DISCREPANCY_L2_CENTERED] = pow(1.25, d);
    e[MCS_DISCREPANCY_L2_WRAPAROUND] = three_halves;
    e[MCS_DISCREPANCY_L2_SYMMETRIC] = ldexp(1.0, (int)dim);
    e[MCS_DISCREPANCY_L2_GENERALIZED] = three_halves;
    e[MCS_DISCREPANCY_L2_UNANCHORED] = pow(1.0 / 6.0, d);
}

/* The terms of point i, each measure: h(x_i, x_i) / K - 2 g(x_i), so that
 * their sum over the points, over K, is the closed form's middle part. */
static MCS_ALWAYS_INLINE void point_terms(size_t dim, mcs_points_ p, size_t i, double kk,
                                          double *t)
{
    double gs = 1.0, gc = 1.0, gy = 1.0, gg = 1.0, gn = 1.0, gw = 1.0;
    double hs = 1.0, hc = 1.0, hw = 1.0, hy = 1.0, hg = 1.0, hn = 1.0;
    for (size_t a = 0; a < dim; ++a) {
        const double u = mcs_point_(p, i * dim + a), c = fabs(u - 0.5), q = u * (1.0 - u);
        gs *= 0.5 * (1.0 - u * u);
        gc *= 1.0 + 0.5 * (c - c * c);
        gw *= 4.0 / 3.0;
        gy *= 1.0 + 2.0 * q;
        gg *= 0.5 * (3.0 - u * u);
        gn *= 0.5 * q;
        hs *= 1.0 - u;
        hc *= 1.0 + c;
        hw *= 1.5;
        hy *= 2.0;
        hg *= 2.0 - u;
        hn *= q;
    }
    t[0] = hs / kk - 2.0 * gs;
    t[1] = hc / kk - 2.0 * gc;
    t[2] = hw / kk - 2.0 * gw;
    t[3] = hy / kk - 2.0 * gy;
    t[4] = hg / kk - 2.0 * gg;
    t[5] = hn / kk - 2.0 * gn;
}

/* h(x_i, x_j) of each measure added to acc[]. */
static MCS_ALWAYS_INLINE void add_pair(size_t dim, mcs_points_ p, size_t i, size_t j, double *acc)
{
    double s = 1.0, c = 1.0, w = 1.0, y = 1.0, g = 1.0, n = 1.0;
    for (size_t a = 0; a < dim; ++a) {
        const double u = mcs_point_(p, i * dim + a), v = mcs_point_(p, j * dim + a);
        const double mx = u > v ? u : v, mn = u > v ? v : u, t = mx - mn;
        s *= 1.0 - mx;
        c *= 1.0 + 0.5 * (fabs(u - 0.5) + fabs(v - 0.5) - t);
        w *= 1.5 - t * (1.0 - t);
        y *= 2.0 - 2.0 * t;
        g *= 2.0 - mx;
        n *= mn * (1.0 - mx);
    }
    acc[0] += s;
    acc[1] += c;
    acc[2] += w;
    acc[3] += y;
    acc[4] += g;
    acc[5] += n;
}

/* The two sums of the closed forms, Kahan-summed (pairs in blocks of BLOCK):
 * point = sum_i (h(x_i, x_i) / K - 2 g(x_i)) and pair = sum_{i<j} h(x_i, x_j),
 * then D^2 = C0 + point / K + 2 pair / K^2. */
static MCS_ALWAYS_INLINE void l2_values(size_t k, size_t dim, mcs_points_ p, double *d2)
{
    const double kk = (double)k;
    double point[L2N] = {0}, point_lo[L2N] = {0}, pair[L2N] = {0}, pair_lo[L2N] = {0};
    for (size_t i = 0; i < k; ++i) {
        double t[L2N];
        point_terms(dim, p, i, kk, t);
        for (int m = 0; m < L2N; ++m)
            mcs_kahan_add_(&point[m], &point_lo[m], t[m]);
        for (size_t j0 = i + 1u; j0 < k; j0 += BLOCK) {
            const size_t j1 = k - j0 < BLOCK ? k : j0 + BLOCK;
            double block[L2N] = {0};
            for (size_t j = j0; j < j1; ++j)
                add_pair(dim, p, i, j, block);
            for (int m = 0; m < L2N; ++m)
                mcs_kahan_add_(&pair[m], &pair_lo[m], block[m]);
        }
    }
    double c0[L2N];
    constants(dim, c0);
    for (int m = 0; m < L2N; ++m)
        d2[m] = c0[m] + point[m] / kk + 2.0 * pair[m] / (kk * kk);
}

/* The checks of a set: dim in range, k >= 1, every coordinate in [0, 1). */
static mcs_status check_set(size_t k, size_t dim, mcs_points_ p)
{
    if (!dim_ok(dim))
        return MCS_ERR_DOMAIN;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (k > SIZE_MAX / dim)
        return MCS_ERR_POINT_RANGE;
    return mcs_check_points_(k * dim, p, NULL);
}

static MCS_ALWAYS_INLINE mcs_status l2(size_t k, size_t dim, mcs_points_ p, double *d2)
{
    if (mcs_points_addr_(p) == NULL || d2 == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_set(k, dim, p);
    if (st != MCS_OK)
        return st;
    double v[L2N];
    l2_values(k, dim, p, v);
    memcpy(d2, v, sizeof v);
    return MCS_OK;
}

mcs_status mcs_discrepancy_l2(size_t k, size_t dim, const double *points, double *d2)
{
    return l2(k, dim, mcs_points_d_(points), d2);
}

mcs_status mcs_discrepancy_l2_f(size_t k, size_t dim, const float *points, double *d2)
{
    return l2(k, dim, mcs_points_f_(points), d2);
}

/* (E h(x, x) - C0) of measure m: K times its exact random expectation. */
static double random_numerator(int m, size_t dim)
{
    double c0[L2N], e[L2N];
    constants(dim, c0);
    diagonal_means(dim, e);
    return e[m] - c0[m];
}

mcs_status mcs_discrepancy_l2_exact_random(mcs_discrepancy_measure measure, size_t k, size_t dim,
                                           double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    if (!measure_ok(measure))
        return MCS_ERR_KIND;
    if (measure == MCS_DISCREPANCY_STAR || !dim_ok(dim))
        return MCS_ERR_DOMAIN;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    *out = random_numerator((int)measure, dim) / (double)k;
    return MCS_OK;
}

/* ---- Jittered points ----------------------------------------------------------
 * One point uniform in each cell of a grid of n_1 x ... x n_d cells, K =
 * prod n_l. With mu_c the uniform measure on cell c, the uniform measure is
 * (1/K) sum_c mu_c and the points are independent, each unbiased for its
 * cell, so the cross terms of E||(1/K) sum_c (h(x_c, .) - mu_c h)||^2 vanish:
 *     E[D^2] = (1/K^2) sum_c (E h(x, x) - E h(x, y)),  x, y iid in cell c.
 * Both terms factor over the axes: sum_c E h(x, x) = prod_l A_l and
 * sum_c E h(x, y) = prod_l B_l, with, over the n strata s of an axis,
 * A = sum_s E h1(u, u) = n e (e = E h1(x, x) of a uniform x, as for random
 * points) and A - B = Delta = sum_s (E h1(u, u) - E h1(u, v)), u, v iid on
 * [s/n, (s + 1)/n) of width w = 1/n. Per measure (E t = w/3, E t^2 = w^2/6,
 * t = |u - v|; E max(u, v) - E u = E u - E min(u, v) = w/6; Var u = w^2/12):
 *   L2 star, generalized  E max - E u, summed:                       1/6
 *   centred   E (cu + cv - t)/2 - ... : the c terms cancel, E t / 2:  1/6
 *     (so the kink of c = |x - 1/2| does not enter, even for odd n)
 *   wrap-around  E t (1 - t), summed: n (w/3 - w^2/6) =      1/3 - 1/(6n)
 *   symmetric    2 E t, summed:                                        2/3
 *   unanchored   E u(1-u) - E min (1 - max) = (E u - E min) - Var u,
 *                summed: n (w/6 - w^2/12) =                   1/6 - 1/(12n)
 * Then E[D^2] = (prod_l A_l - prod_l B_l) / K^2 = (e^d - prod_l b_l) / K with
 * b_l = e - Delta(n_l) / n_l, summed without cancellation as
 * sum_l (prod_{i<l} b_i) (e - b_l) e^(d-1-l). One stratum (n = 1) gives
 * b = C0^(1/d): the random expectation of one point. */

/* Delta of measure m for an axis of n strata (the table above). */
static double jitter_delta(int m, double n)
{
    switch (m) {
    case MCS_DISCREPANCY_L2_WRAPAROUND: return 1.0 / 3.0 - 1.0 / (6.0 * n);
    case MCS_DISCREPANCY_L2_SYMMETRIC: return 2.0 / 3.0;
    case MCS_DISCREPANCY_L2_UNANCHORED: return 1.0 / 6.0 - 1.0 / (12.0 * n);
    default: return 1.0 / 6.0; /* star, centred, generalized */
    }
}

/* E[D^2] of measure m for a grid whose first axis has n_first strata and the
 * dim - 1 others n_rest each (checked: dim in range, K = n_first n_rest^(dim-1)). */
static double jittered_value(int m, size_t dim, size_t n_first, size_t n_rest)
{
    double e1[L2N];
    diagonal_means(1u, e1);
    const double e = e1[m];
    double k = 1.0, prefix = 1.0, sum = 0.0;
    for (size_t l = 0; l < dim; ++l) {
        const double n = (double)(l == 0u ? n_first : n_rest), gap = jitter_delta(m, n) / n;
        sum += prefix * gap * pow(e, (double)(dim - 1u - l));
        prefix *= e - gap;
        k *= n;
    }
    return sum / k;
}

/* Whether n_first n_rest^(dim - 1) points, each n at least 1, fit a size_t. */
static int grid_ok(size_t dim, size_t n_first, size_t n_rest)
{
    if (n_first == 0u || n_rest == 0u)
        return 0;
    size_t k = n_first;
    for (size_t l = 1; l < dim; ++l) {
        if (k > SIZE_MAX / n_rest)
            return 0;
        k *= n_rest;
    }
    return 1;
}

static mcs_status exact_jittered(mcs_discrepancy_measure measure, size_t dim, size_t n_first,
                                 size_t n_rest, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    if (!measure_ok(measure))
        return MCS_ERR_KIND;
    if (measure == MCS_DISCREPANCY_STAR || !dim_ok(dim))
        return MCS_ERR_DOMAIN;
    if (!grid_ok(dim, n_first, n_rest))
        return MCS_ERR_K_RANGE;
    *out = jittered_value((int)measure, dim, n_first, n_rest);
    return MCS_OK;
}

mcs_status mcs_discrepancy_l2_exact_jittered(mcs_discrepancy_measure measure, size_t n, size_t dim,
                                             double *out)
{
    return exact_jittered(measure, dim, n, n, out);
}

mcs_status mcs_discrepancy_l2_exact_jittered2d(mcs_discrepancy_measure measure, size_t nx,
                                               size_t ny, double *out)
{
    return exact_jittered(measure, 2u, nx, ny, out);
}

/* ---- The accumulator ------------------------------------------------------------- */

/* MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_INVARIANT as the header says. */
static mcs_status check_acc(const mcs_discrepancy *acc)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (!dim_ok(acc->dim))
        return MCS_ERR_UNINIT;
    const uint64_t n = acc->inv_k.count;
    int ok = mcs_meas_welford_ok_(&acc->inv_k) && mcs_meas_k_range_ok_(n, acc->k_min, acc->k_max);
    for (int m = 0; m < L2N; ++m)
        ok = ok && mcs_meas_welford_ok_(&acc->d2[m]) && acc->d2[m].count == n;
    ok = ok && mcs_meas_welford_ok_(&acc->d2[MCS_DISCREPANCY_STAR]) &&
         acc->d2[MCS_DISCREPANCY_STAR].count <= n;
    return ok ? MCS_OK : MCS_ERR_INVARIANT;
}

mcs_status mcs_discrepancy_init(mcs_discrepancy *acc, size_t dim)
{
    if (acc == NULL)
        return MCS_ERR_NULL;
    if (!dim_ok(dim))
        return MCS_ERR_DOMAIN;
    memset(acc, 0, sizeof *acc);
    acc->dim = dim;
    mcs_welford_init(&acc->inv_k);
    for (int m = 0; m < MCS_DISCREPANCY_MEASURES; ++m)
        mcs_welford_init(&acc->d2[m]);
    return MCS_OK;
}

/* Whether add computes the star for a set of k points in dim dimensions. */
static int takes_star(const void *work, size_t dim, size_t k)
{
    return work != NULL && dim == 2u && k <= (size_t)MCS_DISCREPANCY_STAR_MAX_K;
}

static MCS_ALWAYS_INLINE mcs_status add(mcs_discrepancy *acc, size_t k, mcs_points_ p, void *work,
                                        size_t work_bytes)
{
    mcs_status st = mcs_points_addr_(p) == NULL ? MCS_ERR_NULL : check_acc(acc);
    if (st == MCS_OK && k == 0u)
        st = MCS_ERR_K_RANGE;
    const int star = st == MCS_OK && takes_star(work, acc->dim, k);
    if (star && work_bytes < MCS_DISCREPANCY_STAR_WORK_SIZE(k))
        st = MCS_ERR_SPACE;
    if (star && st == MCS_OK &&
        (mcs_overlap_(work, work_bytes, mcs_points_addr_(p), mcs_points_bytes_(p, 2u * k)) ||
         mcs_overlap_(work, work_bytes, acc, sizeof *acc)))
        st = MCS_ERR_ALIAS;
    if (st == MCS_OK)
        st = check_set(k, acc->dim, p);
    /* A full count is refused before the work memory is written (the star's
     * sorted copy): a refused add changes nothing, work included. */
    for (int m = 0; m < MCS_DISCREPANCY_MEASURES && st == MCS_OK; ++m)
        if ((m < L2N || star) && acc->d2[m].count >= MCS_MAX_COUNT)
            st = MCS_ERR_COUNT;
    if (st == MCS_OK && acc->inv_k.count >= MCS_MAX_COUNT)
        st = MCS_ERR_COUNT;
    if (st != MCS_OK)
        return st;
    /* The closed forms through the entry points, not inlined here: the
     * frame stays that of one of them plus the copy below. */
    double v[MCS_DISCREPANCY_MEASURES];
    st = p.f != NULL ? mcs_discrepancy_l2_f(k, acc->dim, p.f, v)
                     : mcs_discrepancy_l2(k, acc->dim, p.d, v);
    if (st == MCS_OK && star) {
        st = p.f != NULL ? mcs_discrepancy_star_f(k, p.f, work, work_bytes, &v[L2N])
                         : mcs_discrepancy_star(k, p.d, work, work_bytes, &v[L2N]);
        v[L2N] *= v[L2N];
    }
    if (st != MCS_OK)
        return st;
    /* Every Welford updated on a copy, so a refused add changes nothing. */
    mcs_discrepancy next = *acc;
    st = mcs_welford_add(&next.inv_k, 1.0 / (double)k);
    for (int m = 0; m < MCS_DISCREPANCY_MEASURES && st == MCS_OK; ++m)
        if (m < L2N || star)
            st = mcs_welford_add(&next.d2[m], v[m]);
    if (st != MCS_OK)
        return st;
    next.k_min = acc->k_min == 0u || k < acc->k_min ? k : acc->k_min;
    next.k_max = k > acc->k_max ? k : acc->k_max;
    *acc = next;
    return MCS_OK;
}

mcs_status mcs_discrepancy_add(mcs_discrepancy *acc, size_t k, const double *points, void *work,
                               size_t work_bytes)
{
    return add(acc, k, mcs_points_d_(points), work, work_bytes);
}

mcs_status mcs_discrepancy_add_f(mcs_discrepancy *acc, size_t k, const float *points, void *work,
                                 size_t work_bytes)
{
    return add(acc, k, mcs_points_f_(points), work, work_bytes);
}

mcs_status mcs_discrepancy_merge(mcs_discrepancy *dst, const mcs_discrepancy *src)
{
    mcs_status st = src == NULL ? MCS_ERR_NULL : check_acc(dst);
    if (st == MCS_OK)
        st = check_acc(src);
    if (st == MCS_OK && dst->dim != src->dim)
        st = MCS_ERR_MISMATCH;
    if (st != MCS_OK)
        return st;
    mcs_discrepancy next = *dst;
    st = mcs_welford_merge(&next.inv_k, &src->inv_k);
    for (int m = 0; m < MCS_DISCREPANCY_MEASURES && st == MCS_OK; ++m)
        st = mcs_welford_merge(&next.d2[m], &src->d2[m]);
    if (st != MCS_OK)
        return st;
    if (src->inv_k.count > 0u) {
        next.k_min = dst->k_min == 0u || src->k_min < dst->k_min ? src->k_min : dst->k_min;
        next.k_max = src->k_max > dst->k_max ? src->k_max : dst->k_max;
    }
    *dst = next;
    return MCS_OK;
}

/* The Welford of measure in acc, after the checks every read-out makes. */
static mcs_status read_checked(const mcs_discrepancy *acc, mcs_discrepancy_measure measure,
                               const void *out, const mcs_welford **w)
{
    mcs_status st = out == NULL ? MCS_ERR_NULL : check_acc(acc);
    if (st == MCS_OK && !measure_ok(measure))
        st = MCS_ERR_KIND;
    if (st == MCS_OK)
        *w = &acc->d2[measure];
    return st;
}

mcs_status mcs_discrepancy_count(const mcs_discrepancy *acc, mcs_discrepancy_measure measure,
                                 uint64_t *count)
{
    const mcs_welford *w = NULL;
    mcs_status st = read_checked(acc, measure, count, &w);
    if (st == MCS_OK)
        *count = w->count;
    return st;
}

mcs_status mcs_discrepancy_mean(const mcs_discrepancy *acc, mcs_discrepancy_measure measure,
                                double *out)
{
    const mcs_welford *w = NULL;
    mcs_status st = read_checked(acc, measure, out, &w);
    return st == MCS_OK ? mcs_welford_mean(w, out) : st;
}

mcs_status mcs_discrepancy_stderr(const mcs_discrepancy *acc, mcs_discrepancy_measure measure,
                                  double *out)
{
    const mcs_welford *w = NULL;
    mcs_status st = read_checked(acc, measure, out, &w);
    return st == MCS_OK ? mcs_welford_stderr(w, out) : st;
}

mcs_status mcs_discrepancy_exact_random(const mcs_discrepancy *acc,
                                        mcs_discrepancy_measure measure, double *out)
{
    const mcs_welford *w = NULL;
    mcs_status st = read_checked(acc, measure, out, &w);
    if (st == MCS_OK && measure == MCS_DISCREPANCY_STAR)
        st = MCS_ERR_DOMAIN;
    double mean_inv_k = 0.0;
    if (st == MCS_OK)
        st = mcs_welford_mean(&acc->inv_k, &mean_inv_k);
    if (st == MCS_OK)
        *out = random_numerator((int)measure, acc->dim) * mean_inv_k;
    return st;
}
