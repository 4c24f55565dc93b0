#include "mcspec/pattern.h"
#include "importance_internal.h"
#include "core/internal.h"
#include "random/rng_inline.h"
#include "core/simd.h"

#include <math.h>
#include <string.h>

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

/* Bin floor(t), clamped to N - 1, as floor(min(t, N - 1)) (top = N - 1):
 * the same for t in [0, N], and the clamp is one floating-point minimum
 * beside the generator's integer work rather than a compare and a move
 * among it (the draw is bound by integer instructions). t < 2^63, so the
 * signed conversion is exact and one instruction, where one to size_t is a
 * compare and two on x86-64. Weight 1; the point if asked. */
static inline void place_plain(size_t n, double top, size_t j, double u, double t, size_t *bins,
                               double *vw, double *points)
{
    const double tc = t < top ? t : top; /* apart: GCC 12 made a branch of it inside the cast */
    const size_t b = (size_t)(int64_t)tc;
    bins[j] = b;
    vw[j] = 1.0;
    if (points != NULL)
        points[j] = plain_point(n, b, u, t);
}

/* How draw_own forms a sample's t (and u) from its v: random t = v N;
 * strata t = (j + v) N / K, by one rounding from exact. When K is a power
 * of two, (j + v) N / K is (j + v) times N/K: N/K is exact, and scaling by
 * a power of two commutes with rounding, so it is bit for bit the same and
 * one dependent operation shorter; u = (j + v)/K is then exact. */
typedef enum { OWN_RANDOM, OWN_POW2, OWN_DIV } own_mode;

typedef struct {
    size_t n;
    double top, nd, kd, inv_k, nk; /* N - 1, N, K, 1/K, N/K (inv_k, nk: OWN_POW2) */
} own_scale;

/* 1/K for K a power of two, exactly, without a division: the exponent field
 * of 2^-e is 2046 minus that of 2^e, and both mantissas are zero (IEEE
 * binary64, as everywhere in mcspec). */
static double inverse_pow2(double kd)
{
    uint64_t bits;
    memcpy(&bits, &kd, sizeof bits);
    bits = (UINT64_C(2046) << 52) - bits;
    double inv;
    memcpy(&inv, &bits, sizeof inv);
    return inv;
}

/* N, K < 2^31: the signed conversions are exact and one instruction each,
 * where those from size_t are a test and two. */
static own_scale own_scale_of(own_mode mode, size_t n, size_t k)
{
    own_scale sc = {n, (double)(int64_t)(n - 1u), (double)(int64_t)n, (double)(int64_t)k, 0.0, 0.0};
    if (mode == OWN_POW2) {
        sc.inv_k = inverse_pow2(sc.kd);
        sc.nk = sc.nd * sc.inv_k;
    }
    return sc;
}

/* Sample j of draw_own_body from its v (jd = j, exactly). */
static MCS_ALWAYS_INLINE void place_own(own_mode mode, const own_scale *sc, size_t j, double jd,
                                        double v, size_t *bins, double *w, double *points)
{
    const double jv = jd + v;
    double t, u;
    if (mode == OWN_RANDOM) {
        t = v * sc->nd;
        u = v;
    } else if (mode == OWN_POW2) {
        t = jv * sc->nk;
        u = jv * sc->inv_k;
    } else {
        t = jv * sc->nd / sc->kd;
        u = jv / sc->kd;
    }
    place_plain(sc->n, sc->top, j, mode == OWN_RANDOM || u < 1.0 ? u : MCS_BELOW_ONE, t, bins, w,
                points);
}

/* The samples that draw their own v (random, stratified, homogenized),
 * without importance: the generator's doubles go straight to the bins, with
 * no pass through memory, two per turn of the loop (rng_inline.h). mode and
 * whether points is NULL are constants in every copy, so no per-sample test
 * is left (the bench draws without points). */
static MCS_ALWAYS_INLINE void draw_own_body(own_mode mode, size_t n, size_t k, mcs_rng *rng,
                                            size_t *bins, double *w, double *points)
{
    const own_scale sc = own_scale_of(mode, n, k);
    const mcs_rng_lanes_ lanes = mcs_rng_lanes_of_(rng->inc);
    uint64_t s = rng->state;
    size_t j = 0;
    double jd = 0.0; /* j, counted in floating point: the integer units are the busy ones */
    for (; j + 2u <= k; j += 2u) {
        double v0, v1;
        s = mcs_rng_two_doubles_(s, &lanes, &v0, &v1);
        place_own(mode, &sc, j, jd, v0, bins, w, points);
        place_own(mode, &sc, j + 1u, jd + 1.0, v1, bins, w, points);
        jd += 2.0;
    }
    rng->state = s;
    if (j < k)
        place_own(mode, &sc, j, jd, mcs_rng_double_(rng), bins, w, points);
}

/* One copy of draw_own_body per mode, each with and without points. */
#define MCS_DRAW_OWN_(name, mode)                                                           \
    static MCS_NOINLINE mcs_status name(size_t n, size_t k, mcs_rng *rng, size_t *bins,     \
                                        double *w, double *points)                          \
    {                                                                                       \
        if (points == NULL)                                                                 \
            draw_own_body(mode, n, k, rng, bins, w, NULL);                                  \
        else                                                                                \
            draw_own_body(mode, n, k, rng, bins, w, points);                                \
        return MCS_OK;                                                                      \
    }
MCS_DRAW_OWN_(draw_own_random, OWN_RANDOM)
MCS_DRAW_OWN_(draw_own_pow2, OWN_POW2)
MCS_DRAW_OWN_(draw_own_div, OWN_DIV)
#undef MCS_DRAW_OWN_

/* Each returns MCS_OK, so that mcs_pattern_draw ends in a jump to it. */
static MCS_ALWAYS_INLINE mcs_status draw_own(const mcs_pattern *pat, mcs_rng *rng, size_t *bins,
                                             double *w, double *points)
{
    const size_t n = pat->n, k = pat->k;
    if (pat->kind == MCS_PATTERN_RANDOM)
        return draw_own_random(n, k, rng, bins, w, points);
    if ((k & (k - 1u)) == 0u)
        return draw_own_pow2(n, k, rng, bins, w, points);
    return draw_own_div(n, k, rng, bins, w, points);
}

/* Uniform (beta 1/2) and jitter (the trial's beta) without importance: u =
 * (j + beta)/K and t = (j + beta) N / K, as draw_own's strata. */
static void draw_beta(const mcs_pattern *pat, double beta, size_t *bins, double *w, double *points)
{
    const size_t n = pat->n, k = pat->k;
    const double top = (double)(n - 1u), nd = (double)n, kd = (double)k;
    if ((k & (k - 1u)) == 0u) {
        const double inv_k = inverse_pow2(kd), nk = nd * inv_k;
        for (size_t j = 0; j < k; ++j) {
            double jv = (double)j + beta, u = jv * inv_k;
            place_plain(n, top, j, u < 1.0 ? u : MCS_BELOW_ONE, jv * nk, bins, w, points);
        }
    } else {
        for (size_t j = 0; j < k; ++j) {
            double jv = (double)j + beta, u = jv / kd;
            place_plain(n, top, j, u < 1.0 ? u : MCS_BELOW_ONE, jv * nd / kd, bins, w, points);
        }
    }
}

/* The samples through the importance warp (u as in draw_own, v in vw on
 * entry unless the kind has one beta per trial). */
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
    /* init never pairs homogenized strata with an importance function */
    if (pat->importance != NULL &&
        (!mcs_importance_is_valid_(pat->importance) || pat->importance->n != pat->n ||
         pat->kind == MCS_PATTERN_HOMOGENIZED))
        return MCS_ERR_UNINIT;
    return mcs_rng_is_seeded_(rng) ? MCS_OK : MCS_ERR_UNINIT;
}

/* mcs_overlap_ for two lengths known to be nonzero (no tests for zero),
 * combined by | below rather than ||: the draw tests up to twelve pairs per
 * call, and every pair is tested on the way to a draw anyway. */
static inline int overlaps(const void *a, size_t a_bytes, const void *b, size_t b_bytes)
{
    const uintptr_t pa = (uintptr_t)a, pb = (uintptr_t)b;
    return pa >= pb ? pa - pb < b_bytes : pb - pa < a_bytes;
}

/* The draw's outputs overlap each other, or an object it reads while writing
 * them: each output is written sample by sample, so no overlap can work.
 * bins and weights are k >= 1 long; points and the importance function are
 * tested only when present (mcs_overlap_ gives 0 for their zero length). */
static int draw_aliases(const mcs_pattern *pat, const mcs_rng *rng, size_t k,
                        const size_t *bins, const double *weights, const double *points)
{
    const size_t lb = mcs_bytes_(k, sizeof *bins), lw = mcs_bytes_(k, sizeof *weights);
    const mcs_importance *imp = pat->importance;
    int hit = overlaps(bins, lb, weights, lw) | overlaps(bins, lb, pat, sizeof *pat) |
              overlaps(bins, lb, rng, sizeof *rng) | overlaps(weights, lw, pat, sizeof *pat) |
              overlaps(weights, lw, rng, sizeof *rng);
    if (imp != NULL)
        hit |= overlaps(bins, lb, imp, sizeof *imp) | overlaps(weights, lw, imp, sizeof *imp);
    if (points != NULL) { /* as long as weights */
        hit |= overlaps(points, lw, bins, lb) | overlaps(points, lw, weights, lw) |
               overlaps(points, lw, pat, sizeof *pat) | overlaps(points, lw, rng, sizeof *rng);
        if (imp != NULL)
            hit |= overlaps(points, lw, imp, sizeof *imp);
    }
    return hit;
}

/* Every draw but random and stratified without importance. Those two are
 * the hot ones (a trial of K = 8 takes ~20 ns): mcs_pattern_draw ends in a
 * jump to their own copy of the loop, with no frame of its own around it. */
static MCS_NOINLINE mcs_status draw_other(const mcs_pattern *pat, mcs_rng *rng, size_t *bins,
                                          double *weights, double *points)
{
    const size_t k = pat->k;
    const int own_v = pat->kind != MCS_PATTERN_UNIFORM && pat->kind != MCS_PATTERN_JITTER;
    const double beta = pat->kind == MCS_PATTERN_JITTER ? mcs_rng_double_(rng) : 0.5;
    if (pat->importance == NULL && own_v) {
        (void)draw_own(pat, rng, bins, weights, points);
    } else if (pat->importance == NULL) {
        draw_beta(pat, beta, bins, weights, points);
    } else {
        if (own_v) /* each sample's v, read before its weight is written */
            mcs_rng_fill_doubles_(rng, k, weights);
        draw_warped(pat, k, beta, bins, weights, points);
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
    if (pat->importance == NULL &&
        (pat->kind == MCS_PATTERN_RANDOM || pat->kind == MCS_PATTERN_STRATIFIED))
        return draw_own(pat, rng, bins, weights, points);
    return draw_other(pat, rng, bins, weights, points);
}

/* The weight 1/p of a caller's sample in a bin of density p; 0 in a bin
 * outside the support (p = 0), which the importance function never draws: a
 * renderer's sample there (its own sampler's) adds nothing, as s_n = 0. */
static double support_weight(double p)
{
    return p > 0.0 ? 1.0 / p : 0.0;
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
    /* mcs_importance_init keeps every p_n positive and bounded below, or 0
     * with g_n = 0 (outside the support); an object that says otherwise at a
     * bin in use is refused before anything is written (fuzz_api: a zeroed
     * importance object gave weights of inf). */
    if (importance != NULL && !mcs_importance_support_ok_(importance))
        return MCS_ERR_INVARIANT;
    for (size_t j = 0; importance != NULL && j < k; ++j)
        if (!mcs_importance_bin_ok_(importance, mcs_point_bin_(mcs_point_(points, j), n)))
            return MCS_ERR_INVARIANT;
    for (size_t j = 0; j < k; ++j) {
        size_t b = mcs_point_bin_(mcs_point_(points, j), n);
        bins[j] = b;
        weights[j] = importance != NULL ? support_weight(importance->p[b]) : 1.0;
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
