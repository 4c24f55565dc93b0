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

/* The point of a sample without importance: u itself when it lies in bin b
 * (b = floor(t)). t is one rounding from exact, so it picks the bin: the
 * uniform pattern with N/K even puts every u_j on a bin edge, and u rounded
 * then times N can land just below it (N = 24, K = 6 gave bin 13 for u_3 =
 * 7/12); then the point is moved into b. */
static double plain_point(size_t n, size_t b, double u, double t)
{
    if ((size_t)(u * (double)n) == b)
        return u;
    double frac = t - (double)b;
    return mcs_importance_point_in_bin(n, b, frac < 1.0 ? frac : nextafter(1.0, 0.0));
}

/* The largest double below 1: where u would round up to 1, it stays inside. */
#define MCS_BELOW_ONE 0x1.fffffffffffffp-1

/* Bin floor(t) (t in [0, N]: the signed conversion is exact and one
 * instruction, where one to size_t is a compare and two on x86-64), clamped
 * to N - 1; weight 1; the point if asked. */
static inline void place_plain(size_t n, size_t j, double u, double t, size_t *bins, double *vw,
                               double *points)
{
    size_t b = (size_t)(int64_t)t;
    b = b < n ? b : n - 1u;
    bins[j] = b;
    vw[j] = 1.0;
    if (points != NULL)
        points[j] = plain_point(n, b, u, t);
}

/* The samples without importance. Random: u = v, t = u N. Strata: u = (j +
 * v)/K and t = (j + v) N / K, each by one rounding from exact; when K is a
 * power of two the division is a multiplication by 1/K, exact and bit for
 * bit the same, and several times cheaper. v is each sample's own (random,
 * stratified, homogenized: vw holds them on entry) or the trial's beta
 * (uniform 1/2, jitter); vw holds the weights on return. One loop per case,
 * so none tests the case per sample (one with a select was 6-8% slower). */
static void draw_plain(const mcs_pattern *pat, size_t k, double beta, size_t *bins, double *vw,
                       double *points)
{
    const size_t n = pat->n;
    const double nd = (double)n, kd = (double)k, inv_k = 1.0 / kd;
    const int pow2 = (k & (k - 1u)) == 0u;
    const int own_v = pat->kind != MCS_PATTERN_UNIFORM && pat->kind != MCS_PATTERN_JITTER;
    if (pat->kind == MCS_PATTERN_RANDOM) {
        for (size_t j = 0; j < k; ++j)
            place_plain(n, j, vw[j], vw[j] * nd, bins, vw, points);
    } else if (own_v && pow2) {
        for (size_t j = 0; j < k; ++j) {
            double jv = (double)j + vw[j], u = jv * inv_k;
            place_plain(n, j, u < 1.0 ? u : MCS_BELOW_ONE, jv * nd * inv_k, bins, vw, points);
        }
    } else if (pow2) { /* uniform and jitter: one beta for the trial */
        for (size_t j = 0; j < k; ++j) {
            double jv = (double)j + beta, u = jv * inv_k;
            place_plain(n, j, u < 1.0 ? u : MCS_BELOW_ONE, jv * nd * inv_k, bins, vw, points);
        }
    } else {
        for (size_t j = 0; j < k; ++j) {
            double jv = (double)j + (own_v ? vw[j] : beta), u = jv / kd;
            place_plain(n, j, u < 1.0 ? u : MCS_BELOW_ONE, jv * nd / kd, bins, vw, points);
        }
    }
}

/* The samples through the importance warp (u as in draw_plain). */
static void draw_warped(const mcs_pattern *pat, size_t k, double beta, size_t *bins, double *vw,
                        double *points)
{
    const int own_v = pat->kind != MCS_PATTERN_UNIFORM && pat->kind != MCS_PATTERN_JITTER;
    for (size_t j = 0; j < k; ++j) {
        double v = own_v ? vw[j] : beta;
        double u = pat->kind == MCS_PATTERN_RANDOM ? v : stratum_point(j, v, k);
        double x;
        mcs_importance_warp_unchecked(pat->importance, u, &x, &bins[j]);
        vw[j] = 1.0 / pat->importance->p[bins[j]];
        if (points != NULL)
            points[j] = x;
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

    double beta = 0.5;
    if (pat->kind == MCS_PATTERN_JITTER)
        beta = mcs_rng_double_(rng);
    else if (pat->kind != MCS_PATTERN_UNIFORM)
        mcs_rng_fill_doubles_(rng, k, weights); /* each sample's v, read before its weight is written */
    if (pat->importance == NULL)
        draw_plain(pat, k, beta, bins, weights, points);
    else
        draw_warped(pat, k, beta, bins, weights, points);

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
    /* mcs_importance_init keeps every p_n positive, so 1/p_n is finite; an
     * object that says otherwise at a bin in use is refused before anything
     * is written (fuzz_api: a zeroed importance object gave weights of inf). */
    for (size_t j = 0; importance != NULL && j < k; ++j) {
        const double p = importance->p[mcs_point_bin_(mcs_point_(points, j), n)];
        if (!(p > 0.0 && isfinite(1.0 / p)))
            return MCS_ERR_INVARIANT;
    }
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
    if (!(mcs_weights_total_(k, weights) <= MCS_PATTERN_MAX_DENSE))
        return MCS_ERR_MAGNITUDE;
    for (size_t b = 0; b < n; ++b)
        s[b] = 0.0;
    for (size_t j = 0; j < k; ++j)
        s[bins[j]] += weights[j];
    return MCS_OK;
}
