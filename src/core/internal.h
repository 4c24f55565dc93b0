/* Private helpers shared by several modules: the twiddle table and the input
 * checks every accumulator and closed form applies before it writes anything.
 * Static inline, so each module gets its own copy and nothing is exported. */
#ifndef MCSPEC_INTERNAL_H
#define MCSPEC_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "mcspec/estimate.h"
#include "mcspec/pattern.h"
#include "mcspec/status.h"

#define MCS_TWO_PI 6.283185307179586476925286766559

/* cos and sin of 2 pi idx / n, idx in [0, n). The caller reduces the index
 * exactly (k t mod N), so every twiddle is within an ulp whatever k t is. */
static inline double mcs_twiddle_angle_(size_t idx, size_t n)
{
    return MCS_TWO_PI / (double)n * (double)idx;
}

/* The twiddle table of N points: c[j] = cos(2 pi j/N), s[j] = sin(2 pi j/N),
 * j < n. Shared by the DFT plan, the moment accumulator and the exact moments
 * so that measured and exact read-outs use the same roots to the last bit. */
static inline void mcs_twiddles_(size_t n, double *c, double *s)
{
    for (size_t j = 0; j < n; ++j) {
        const double a = mcs_twiddle_angle_(j, n);
        c[j] = cos(a);
        s[j] = sin(a);
    }
}

/* Set up by mcs_importance_init (n in range; the rest follows from n). */
static inline int mcs_importance_is_valid_(const mcs_importance *imp)
{
    return imp->n >= 1u && imp->n <= (size_t)MCS_MAX_N;
}

static inline int mcs_kind_is_valid_(mcs_pattern_kind kind)
{
    return kind == MCS_PATTERN_RANDOM || kind == MCS_PATTERN_STRATIFIED ||
           kind == MCS_PATTERN_HOMOGENIZED || kind == MCS_PATTERN_UNIFORM ||
           kind == MCS_PATTERN_JITTER;
}

/* A sample weight (or a dense s_n): finite and >= 0. */
static inline mcs_status mcs_check_weight_(double w)
{
    if (!isfinite(w))
        return MCS_ERR_NOT_FINITE;
    if (w < 0.0)
        return MCS_ERR_NEGATIVE;
    return MCS_OK;
}

/* One trial in sparse form: k >= 1, bins[k] < n, weights[k] as
 * mcs_check_weight_. K_RANGE, BIN_RANGE, NOT_FINITE, NEGATIVE. */
static inline mcs_status mcs_check_sparse_(size_t n, size_t k, const size_t *bins,
                                           const double *weights)
{
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    for (size_t j = 0; j < k; ++j) {
        if (bins[j] >= n)
            return MCS_ERR_BIN_RANGE;
        mcs_status st = mcs_check_weight_(weights[j]);
        if (st != MCS_OK)
            return st;
    }
    return MCS_OK;
}

/* The checks of an init call: MCS_ERR_NULL without the object, MCS_ERR_N_RANGE
 * unless n is in [1, cap]. */
static inline mcs_status mcs_check_init_(const void *obj, size_t n, size_t cap)
{
    if (obj == NULL)
        return MCS_ERR_NULL;
    return n >= 1u && n <= cap ? MCS_OK : MCS_ERR_N_RANGE;
}

/* The first check of every other call on an object: MCS_ERR_NULL without it,
 * MCS_ERR_UNINIT unless its n (0 before init) is in [1, cap]. */
static inline mcs_status mcs_check_object_(const void *obj, size_t n, size_t cap)
{
    if (obj == NULL)
        return MCS_ERR_NULL;
    return n >= 1u && n <= cap ? MCS_OK : MCS_ERR_UNINIT;
}

/* A dense trial s[n] for an object of N = obj_n bins whose own check gave
 * obj_status: MCS_ERR_NULL without s, then obj_status, MCS_ERR_MISMATCH
 * unless n == obj_n, then every s_n as mcs_check_weight_. */
static inline mcs_status mcs_check_dense_(mcs_status obj_status, size_t obj_n, size_t n,
                                          const double *s)
{
    if (s == NULL)
        return MCS_ERR_NULL;
    if (obj_status != MCS_OK)
        return obj_status;
    if (n != obj_n)
        return MCS_ERR_MISMATCH;
    for (size_t j = 0; j < n; ++j) {
        mcs_status st = mcs_check_weight_(s[j]);
        if (st != MCS_OK)
            return st;
    }
    return MCS_OK;
}

/* Every x[n] finite. x * 0 is 0 for finite x and NaN for NaN or infinity, so a
 * branch-free sum of them is 0 exactly when all are finite; four partial sums
 * keep the adds from waiting on each other. */
static inline int mcs_all_finite_(size_t n, const double *x)
{
    double z0 = 0.0, z1 = 0.0, z2 = 0.0, z3 = 0.0;
    size_t j = 0;
    for (; j + 4u <= n; j += 4u) {
        z0 += x[j] * 0.0;
        z1 += x[j + 1u] * 0.0;
        z2 += x[j + 2u] * 0.0;
        z3 += x[j + 3u] * 0.0;
    }
    for (; j < n; ++j)
        z0 += x[j] * 0.0;
    return (z0 + z1) + (z2 + z3) == 0.0;
}

/* An integrand f[n] of a closed form (eq.h) or an exact spectrum (theory.h):
 * finite (NOT_FINITE), |f_n| <= MCS_ESTIMATE_MAX_ABS = 2^110 (MAGNITUDE), the
 * largest term the estimator takes. With moments below 2^124 (K <= 2^30
 * samples of weight < 2^32) no square or sum of products then passes 2^400. */
static inline mcs_status mcs_check_integrand_(size_t n, const double *f)
{
    if (!mcs_all_finite_(n, f))
        return MCS_ERR_NOT_FINITE;
    for (size_t j = 0; j < n; ++j)
        if (!(fabs(f[j]) <= MCS_ESTIMATE_MAX_ABS))
            return MCS_ERR_MAGNITUDE;
    return MCS_OK;
}

/* The sum of a trial's k weights (each already checked finite and >= 0), in
 * sample order: what the accumulators and the dense form bound so that no
 * bin's s_n can overflow. */
static inline double mcs_weights_total_(size_t k, const double *weights)
{
    double total = 0.0;
    for (size_t j = 0; j < k; ++j)
        total += weights[j];
    return total;
}

/* Bytes of count elements of elem bytes each, saturating at SIZE_MAX (an array
 * that large cannot exist, so an overlap test with it stays conservative). */
static inline size_t mcs_bytes_(size_t count, size_t elem)
{
    return count > SIZE_MAX / elem ? SIZE_MAX : count * elem;
}

/* Forces a body into its callers: the point-taking calls write their body
 * once over mcs_points_ and call it from a double and a float entry point,
 * each with a constant pointer kind, so each copy loses the other's branch. */
#if defined(__GNUC__) || defined(__clang__)
#define MCS_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define MCS_ALWAYS_INLINE inline
#endif

/* Caller points of a point-taking call: the double array (d) or the float
 * one (f, from the _f calls), the other pointer NULL. A float widens to a
 * double exactly, so every later step sees the same value either way: a _f
 * call gives the bits of the double call on the widened points, with no
 * copy of the samples. */
typedef struct {
    const double *d;
    const float *f;
} mcs_points_;

static inline mcs_points_ mcs_points_d_(const double *x)
{
    mcs_points_ p = {x, NULL};
    return p;
}

static inline mcs_points_ mcs_points_f_(const float *x)
{
    mcs_points_ p = {NULL, x};
    return p;
}

/* x_j, widened exactly when the points are float. */
static inline double mcs_point_(mcs_points_ p, size_t j)
{
    return p.f != NULL ? (double)p.f[j] : p.d[j];
}

/* The array's address and the bytes of its first k points (overlap tests). */
static inline const void *mcs_points_addr_(mcs_points_ p)
{
    return p.f != NULL ? (const void *)p.f : (const void *)p.d;
}

static inline size_t mcs_points_bytes_(mcs_points_ p, size_t k)
{
    return mcs_bytes_(k, p.f != NULL ? sizeof *p.f : sizeof *p.d);
}

/* Caller points of one trial: points[k] in [0, 1) (NaN is not; a float
 * just below 1.0f is inside, 1.0f is not), and weights[k] as
 * mcs_check_weight_ unless weights is NULL (all 1).
 * POINT_RANGE, NOT_FINITE, NEGATIVE. */
static inline mcs_status mcs_check_points_(size_t k, mcs_points_ points, const double *weights)
{
    for (size_t j = 0; j < k; ++j) {
        const double x = mcs_point_(points, j);
        if (!(x >= 0.0 && x < 1.0))
            return MCS_ERR_POINT_RANGE;
        mcs_status st = weights != NULL ? mcs_check_weight_(weights[j]) : MCS_OK;
        if (st != MCS_OK)
            return st;
    }
    return MCS_OK;
}

/* Writes a checked result: *out = value, MCS_OK. Lets a closed form read
 * "checked ? mcs_set_(out, formula) : status". */
static inline mcs_status mcs_set_(double *out, double value)
{
    *out = value;
    return MCS_OK;
}

/* Whether the byte ranges [a, a + a_bytes) and [b, b + b_bytes) share a byte.
 * The addresses are compared as integers: relational operators on pointers
 * into different objects are undefined in C. */
static inline int mcs_overlap_(const void *a, size_t a_bytes, const void *b, size_t b_bytes)
{
    const uintptr_t pa = (uintptr_t)a, pb = (uintptr_t)b;
    if (a_bytes == 0u || b_bytes == 0u)
        return 0;
    return pa >= pb ? pa - pb < b_bytes : pb - pa < a_bytes;
}

/* Kahan's compensated sum: *sum stays within a few ulp of the exact total of
 * every x added, however many (its error is 2u sum |x| to first order, with no
 * factor of the number of terms), because *lo carries each rounding error into
 * the next add. The sources refuse -ffast-math, which would fold it away. */
static inline void mcs_kahan_add_(double *sum, double *lo, double x)
{
    const double y = x - *lo;
    const double t = *sum + y;
    *lo = (t - *sum) - y;
    *sum = t;
}

/* The count after adding `more` to `count`: MCS_ERR_COUNT if it would pass
 * MCS_MAX_COUNT (config.h), so no counter wraps and every count is exact in a
 * double. */
static inline mcs_status mcs_check_count_(uint64_t count, uint64_t more)
{
    const uint64_t cap = (uint64_t)MCS_MAX_COUNT;
    return count <= cap && more <= cap - count ? MCS_OK : MCS_ERR_COUNT;
}

/* floor(N x) for x in [0,1), kept below N where x N rounds up to N. */
static inline size_t mcs_point_bin_(double x, size_t n)
{
    size_t b = (size_t)(x * (double)n);
    return b < n ? b : n - 1u;
}

#endif /* MCSPEC_INTERNAL_H */
