#include "mcspec/pattern.h"
#include "importance_internal.h"
#include "internal.h"
#include "rng_inline.h"

#include <math.h>

const char *mcs_pattern_kind_str(mcs_pattern_kind kind)
{
    switch (kind) {
    case MCS_PATTERN_RANDOM: return "random";
    case MCS_PATTERN_STRATIFIED: return "stratified";
    case MCS_PATTERN_HOMOGENIZED: return "homogenized";
    case MCS_PATTERN_UNIFORM: return "uniform";
    case MCS_PATTERN_JITTER: return "jitter";
    }
    return "unknown";
}

/* Every p_n exactly 1: the uniform density (mcs_importance_init gives it for
 * equal weights), which is drawn as no importance function at all. */
static int is_flat(const mcs_importance *imp)
{
    for (size_t b = 0; b < imp->n; ++b)
        if (imp->p[b] != 1.0)
            return 0;
    return 1;
}

mcs_status mcs_pattern_init(mcs_pattern *pat, mcs_pattern_kind kind, size_t n, size_t k,
                            const mcs_importance *importance)
{
    if (pat == NULL)
        return MCS_ERR_NULL;
    if (n == 0u || n > (size_t)MCS_MAX_N)
        return MCS_ERR_N_RANGE;
    if (k == 0u || k > (size_t)MCS_MAX_K)
        return MCS_ERR_K_RANGE;
    if (!mcs_kind_is_valid_(kind))
        return MCS_ERR_KIND;
    if (importance != NULL) {
        if (!mcs_importance_is_valid_(importance))
            return MCS_ERR_UNINIT;
        if (importance->n != n)
            return MCS_ERR_MISMATCH;
        /* The homogenizing shift moves samples by whole bins, which under a
         * non-uniform density would no longer follow p: not defined (for a
         * flat one either, to keep the rule simple). */
        if (kind == MCS_PATTERN_HOMOGENIZED)
            return MCS_ERR_KIND;
        if (is_flat(importance))
            importance = NULL;
    }
    pat->kind = kind;
    pat->n = n;
    pat->k = k;
    pat->importance = importance;
    return MCS_OK;
}

/* (j + v)/K by one correctly rounded division, kept below 1 when rounding
 * would reach it. */
static double stratum_point(size_t j, double v, size_t k)
{
    double u = ((double)j + v) / (double)k;
    return u < 1.0 ? u : nextafter(1.0, 0.0);
}

/* Canonical u -> (bin, weight, x), through the importance warp if any.
 * Without importance the bin is floor(t), t = u N given exactly where
 * possible: the uniform pattern with N/K even puts every u_j on a bin edge,
 * and u rounded then times N can land just below it (N = 24, K = 6 gave bin
 * 13 for u_3 = 7/12); t = (j + v) N / K is one rounding from exact, which
 * cannot cross an integer. */
static void place(const mcs_pattern *pat, double u, double t, size_t *bin, double *weight,
                  double *x)
{
    if (pat->importance != NULL) {
        mcs_importance_warp_unchecked(pat->importance, u, x, bin);
        *weight = 1.0 / pat->importance->p[*bin];
    } else {
        size_t b = (size_t)t;
        b = b < pat->n ? b : pat->n - 1u;
        *bin = b;
        *weight = 1.0;
        double frac = t - (double)b;
        *x = (size_t)(u * (double)pat->n) == b
                 ? u
                 : mcs_importance_point_in_bin(pat->n, b, frac < 1.0 ? frac : nextafter(1.0, 0.0));
    }
}

/* A configuration mcs_pattern_init could have produced, drawn with a seeded rng. */
static mcs_status check_drawable(const mcs_pattern *pat, const mcs_rng *rng)
{
    if (pat->n == 0u || pat->n > (size_t)MCS_MAX_N || pat->k == 0u ||
        pat->k > (size_t)MCS_MAX_K || !mcs_kind_is_valid_(pat->kind))
        return MCS_ERR_UNINIT;
    if (pat->importance != NULL && (!mcs_importance_is_valid_(pat->importance) ||
                                    pat->importance->n != pat->n))
        return MCS_ERR_UNINIT;
    return mcs_rng_is_seeded_(rng) ? MCS_OK : MCS_ERR_UNINIT;
}

/* The draw's outputs overlap each other, or an object it reads while writing
 * them: each output is written sample by sample, so no overlap can work. */
static int draw_aliases(const mcs_pattern *pat, const mcs_rng *rng, size_t k,
                        const size_t *bins, const double *weights, const double *points)
{
    const void *out[3] = {bins, weights, points};
    const size_t len[3] = {mcs_bytes_(k, sizeof *bins), mcs_bytes_(k, sizeof *weights),
                           points != NULL ? mcs_bytes_(k, sizeof *points) : 0u};
    const size_t imp_len = pat->importance != NULL ? sizeof *pat->importance : 0u;
    for (size_t a = 0; a < 3u; ++a) {
        for (size_t b = a + 1u; b < 3u; ++b)
            if (mcs_overlap_(out[a], len[a], out[b], len[b]))
                return 1;
        if (mcs_overlap_(out[a], len[a], pat, sizeof *pat) ||
            mcs_overlap_(out[a], len[a], rng, sizeof *rng) ||
            mcs_overlap_(out[a], len[a], pat->importance, imp_len))
            return 1;
    }
    return 0;
}

mcs_status mcs_pattern_draw(const mcs_pattern *pat, mcs_rng *rng, size_t k, size_t *bins,
                            double *weights, double *points)
{
    if (pat == NULL || rng == NULL || bins == NULL || weights == NULL)
        return MCS_ERR_NULL;
    mcs_status st = check_drawable(pat, rng);
    if (st != MCS_OK)
        return st;
    if (k != pat->k)
        return MCS_ERR_MISMATCH;
    if (draw_aliases(pat, rng, k, bins, weights, points))
        return MCS_ERR_ALIAS;

    const double nd = (double)pat->n, kd = (double)k;
    double beta = 0.5;
    if (pat->kind == MCS_PATTERN_JITTER)
        beta = mcs_rng_double_(rng);

    for (size_t j = 0; j < k; ++j) {
        double u, t, v;
        switch (pat->kind) {
        case MCS_PATTERN_RANDOM:
            u = mcs_rng_double_(rng);
            t = u * nd;
            break;
        case MCS_PATTERN_STRATIFIED:
        case MCS_PATTERN_HOMOGENIZED:
            v = mcs_rng_double_(rng);
            u = stratum_point(j, v, k);
            t = ((double)j + v) * nd / kd;
            break;
        default: /* uniform (beta = 1/2) and jitter (one beta per trial) */
            u = stratum_point(j, beta, k);
            t = ((double)j + beta) * nd / kd;
            break;
        }
        double x;
        place(pat, u, t, &bins[j], &weights[j], &x);
        if (points != NULL)
            points[j] = x;
    }

    if (pat->kind == MCS_PATTERN_HOMOGENIZED) {
        /* Cyclic shift by a whole number of bins, drawn after the strata. */
        size_t n = pat->n;
        size_t shift = (size_t)mcs_rng_bounded_(rng, (uint32_t)n);
        for (size_t j = 0; j < k; ++j) {
            size_t b = bins[j];
            size_t nb = (b + shift) % n;
            if (points != NULL) {
                double t = points[j] * (double)n - (double)b;
                points[j] = mcs_importance_point_in_bin(n, nb, t < 1.0 ? t : nextafter(1.0, 0.0));
            }
            bins[j] = nb;
        }
    }
    return MCS_OK;
}

/* The body of both bin_points calls, over double or float points
 * (internal.h): the same bins and weights from the widened points. */
static MCS_ALWAYS_INLINE mcs_status bin_points(size_t n, size_t k, const mcs_importance *importance,
                                               mcs_points_ points, size_t *bins, double *weights)
{
    const void *pa = mcs_points_addr_(points);
    if (pa == NULL || bins == NULL || weights == NULL)
        return MCS_ERR_NULL;
    if (n == 0u || n > (size_t)MCS_MAX_N)
        return MCS_ERR_N_RANGE;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (importance != NULL && (!mcs_importance_is_valid_(importance) || importance->n != n))
        return MCS_ERR_MISMATCH;
    const size_t pb = mcs_points_bytes_(points, k), bb = mcs_bytes_(k, sizeof *bins);
    const size_t wb = mcs_bytes_(k, sizeof *weights);
    const size_t ib = importance != NULL ? sizeof *importance : 0u;
    if (mcs_overlap_(pa, pb, bins, bb) || mcs_overlap_(pa, pb, weights, wb) ||
        mcs_overlap_(bins, bb, weights, wb) || mcs_overlap_(bins, bb, importance, ib) ||
        mcs_overlap_(weights, wb, importance, ib))
        return MCS_ERR_ALIAS;
    mcs_status st = mcs_check_points_(k, points, NULL);
    if (st != MCS_OK)
        return st;
    for (size_t j = 0; j < k; ++j) {
        size_t b = mcs_point_bin_(mcs_point_(points, j), n);
        bins[j] = b;
        weights[j] = importance != NULL ? 1.0 / importance->p[b] : 1.0;
    }
    return MCS_OK;
}

mcs_status mcs_pattern_bin_points(size_t n, size_t k, const mcs_importance *importance,
                                  const double *points, size_t *bins, double *weights)
{
    return bin_points(n, k, importance, mcs_points_d_(points), bins, weights);
}

mcs_status mcs_pattern_bin_points_f(size_t n, size_t k, const mcs_importance *importance,
                                    const float *points, size_t *bins, double *weights)
{
    return bin_points(n, k, importance, mcs_points_f_(points), bins, weights);
}

mcs_status mcs_pattern_dense(size_t n, size_t k, const size_t *bins, const double *weights,
                             double *s)
{
    if (bins == NULL || weights == NULL || s == NULL)
        return MCS_ERR_NULL;
    if (n == 0u || n > (size_t)MCS_MAX_N)
        return MCS_ERR_N_RANGE;
    const size_t sb = n * sizeof *s;
    if (mcs_overlap_(s, sb, bins, mcs_bytes_(k, sizeof *bins)) ||
        mcs_overlap_(s, sb, weights, mcs_bytes_(k, sizeof *weights)))
        return MCS_ERR_ALIAS;
    mcs_status st = mcs_check_sparse_(n, k, bins, weights);
    if (st != MCS_OK)
        return st;
    /* A bin's s_n is a sum of weights: bound the trial's total (the same
     * 2^220 as the moment and autocorrelation accumulators) so no s_n can
     * overflow to inf. */
    double total = 0.0;
    for (size_t j = 0; j < k; ++j)
        total += weights[j];
    if (!(total <= MCS_PATTERN_MAX_DENSE))
        return MCS_ERR_MAGNITUDE;
    for (size_t b = 0; b < n; ++b)
        s[b] = 0.0;
    for (size_t j = 0; j < k; ++j)
        s[bins[j]] += weights[j];
    return MCS_OK;
}
