/* The exact binned statistics of a fixed point set under a uniform
 * Cranley-Patterson rotation x_j = a_j + beta mod 1 (theory.h,
 * "The rotation average of a fixed point set"). With A_j = N a_j the bin
 * offset n_j - n_j' of two rotated points is floor(D) or floor(D) + 1 (mod
 * N), D = A_j - A_j', the latter with probability frac(D); the bin of a
 * rotated point is uniform on [0, N) and independent of that offset. So the
 * rotation-averaged histogram h(d) of the offsets of the K^2 ordered pairs
 * carries everything:
 *     <|S_q|^2> = (1/N) sum_d h(d) cos(2 pi q d / N),
 *     Var[I]    = (1/K^2) sum_d h(d) R(d) - fbar^2,  R(d) = (1/N) sum_n f_n f_{n+d}. */
#include "theory_internal.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define TWO_PI 6.283185307179586476925286766559

/* h(d), d < n, of the K^2 ordered pairs of points a[k]. */
static void rotation_offsets(size_t n, size_t k, const double *a, double *h)
{
    memset(h, 0, n * sizeof h[0]);
    for (size_t j = 0; j < k; ++j)
        for (size_t jj = 0; jj < k; ++jj) {
            double dist = (double)n * (a[j] - a[jj]);
            double fl = floor(dist), phi = dist - fl;
            long m = (long)fl % (long)n;
            size_t d = (size_t)(m < 0 ? m + (long)n : m);
            h[d] += 1.0 - phi;
            h[(d + 1u) % n] += phi;
        }
}

static double rotation_power(size_t n, const double *h, size_t freq)
{
    double sum = 0.0;
    for (size_t d = 0; d < n; ++d)
        sum += h[d] * cos(TWO_PI * (double)((freq * d) % n) / (double)n);
    return sum / (double)n;
}

/* sum_d h(d) = K^2, so subtracting fbar^2 is centring f: the sum then holds
 * no O(fbar^2) terms that cancel. */
static double rotation_variance(size_t n, size_t k, const double *h, const double *f)
{
    double fbar = 0.0, second = 0.0;
    for (size_t b = 0; b < n; ++b)
        fbar += f[b] / (double)n;
    for (size_t d = 0; d < n; ++d) {
        double r = 0.0;
        for (size_t b = 0; b < n; ++b)
            r += (f[b] - fbar) * (f[(b + d) % n] - fbar);
        second += h[d] * r / (double)n;
    }
    return second / ((double)k * (double)k);
}

mcs_status mcs_theory_rotation_init(mcs_theory_rotation *rot, size_t n, size_t k,
                                    const double *points, double *work, size_t len)
{
    if (rot == NULL || points == NULL || work == NULL)
        return MCS_ERR_NULL;
    if (n == 0u || n > (size_t)MCS_MAX_N)
        return MCS_ERR_N_RANGE;
    if (k == 0u || k > (size_t)MCS_MAX_K)
        return MCS_ERR_K_RANGE;
    if (len < MCS_THEORY_ROTATION_LEN(n))
        return MCS_ERR_SPACE;
    const size_t pb = mcs_bytes_(k, sizeof *points), wb = n * sizeof *work;
    if (mcs_overlap_(work, wb, points, pb) || mcs_overlap_(work, wb, rot, sizeof *rot) ||
        mcs_overlap_(rot, sizeof *rot, points, pb))
        return MCS_ERR_ALIAS;
    mcs_status st = mcs_check_points_(k, mcs_points_d_(points), NULL);
    if (st != MCS_OK)
        return st;
    rotation_offsets(n, k, points, work);
    rot->n = n;
    rot->k = k;
    rot->offsets = work;
    return MCS_OK;
}

/* A set-up object: n and k in range and its offsets given (else UNINIT),
 * each offset finite and >= 0 (else INVARIANT: the caller's buffer was
 * written since, and would give no rotation average). O(N). */
static mcs_status check_rotation(int outputs, const mcs_theory_rotation *rot)
{
    if (!outputs || rot == NULL)
        return MCS_ERR_NULL;
    if (rot->n == 0u || rot->n > (size_t)MCS_MAX_N || rot->k == 0u ||
        rot->k > (size_t)MCS_MAX_K || rot->offsets == NULL)
        return MCS_ERR_UNINIT;
    for (size_t d = 0; d < rot->n; ++d)
        if (!(rot->offsets[d] >= 0.0 && rot->offsets[d] <= 0x1p61))
            return MCS_ERR_INVARIANT;
    return MCS_OK;
}

/* The rotation moves every point by the same uniform beta, so the pattern is
 * stationary and S_0 = K / sqrt(N) in every trial: <S_k> is that at k = 0
 * and 0 elsewhere, exactly. */
mcs_status mcs_theory_rotation_mean(const mcs_theory_rotation *rot, size_t freq, double *re,
                                    double *im)
{
    mcs_status st = check_rotation(re != NULL && im != NULL, rot);
    if (st == MCS_OK && freq >= rot->n)
        st = MCS_ERR_FREQ_RANGE;
    if (st == MCS_OK && mcs_overlap_(re, sizeof *re, im, sizeof *im))
        st = MCS_ERR_ALIAS;
    if (st != MCS_OK)
        return st;
    *re = freq == 0u ? (double)rot->k / sqrt((double)rot->n) : 0.0;
    *im = 0.0;
    return MCS_OK;
}

/* How far rounding can take a read-out below its exact value, per unit of
 * its scale: init adds each h(d) from up to 2 K^2 terms in [0, 1], so an
 * entry errs by up to 2 K^2 DBL_EPSILON of itself; the read-out's own sum
 * of N terms (and the cosines and the centring of f) add N + 16. */
static double rounding_factor(const mcs_theory_rotation *rot)
{
    const double kd = (double)rot->k;
    return (2.0 * kd * kd + (double)rot->n + 16.0) * DBL_EPSILON;
}

/* A power or a variance that cannot be negative: one in [-tol, 0) is
 * rounding and reads 0 (a rotated van der Corput set, which is jitter, has
 * exact zeros the sum of mixed-sign terms leaves at -2.5e-16); one below
 * -tol comes from no offsets init writes (MCS_ERR_INVARIANT). */
static mcs_status set_nonnegative(double *out, double v, double tol)
{
    if (!(v >= -tol))
        return MCS_ERR_INVARIANT;
    *out = v > 0.0 ? v : 0.0;
    return MCS_OK;
}

mcs_status mcs_theory_rotation_power(const mcs_theory_rotation *rot, size_t freq, double *out)
{
    mcs_status st = check_rotation(out != NULL, rot);
    if (st == MCS_OK && freq >= rot->n)
        st = MCS_ERR_FREQ_RANGE;
    if (st != MCS_OK)
        return st;
    /* |sum_d h(d) cos| <= sum_d h(d) = K^2 */
    const double kd = (double)rot->k, tol = rounding_factor(rot) * kd * kd / (double)rot->n;
    return set_nonnegative(out, rotation_power(rot->n, rot->offsets, freq), tol);
}

/* (1/N) sum_n (f_n - fbar)^2, the scale of the variance read-out: |R(d)|
 * is at most it (Cauchy-Schwarz) and sum_d h(d) / K^2 = 1. */
static double centred_energy(size_t n, const double *f)
{
    double fbar = 0.0, e = 0.0;
    for (size_t b = 0; b < n; ++b)
        fbar += f[b] / (double)n;
    for (size_t b = 0; b < n; ++b)
        e += (f[b] - fbar) * (f[b] - fbar);
    return e / (double)n;
}

mcs_status mcs_theory_rotation_variance(const mcs_theory_rotation *rot, size_t n, size_t k,
                                        const double *f, double *out)
{
    mcs_status st = check_rotation(out != NULL && f != NULL, rot);
    if (st != MCS_OK)
        return st;
    if (n != rot->n)
        return MCS_ERR_MISMATCH;
    if (k == 0u)
        return MCS_ERR_K_RANGE;
    if (k != rot->k)
        return MCS_ERR_MISMATCH;
    st = mcs_check_integrand_(n, f);
    if (st != MCS_OK)
        return st;
    return set_nonnegative(out, rotation_variance(n, k, rot->offsets, f),
                           2.0 * rounding_factor(rot) * centred_energy(n, f));
}
