/* Exact point-set power spectra of the 2D patterns (pointset2d.h). */
#include "mcspec/pointset2d.h"
#include "pointset_internal.h"

#include <math.h>

static int pattern_is_valid(const mcs_pattern2d *pat)
{
    return (unsigned)pat->kind < (unsigned)MCS_PATTERN2D_KIND_COUNT && pat->k >= 1u &&
           pat->k <= (size_t)MCS_PATTERN2D_MAX_K && pat->strata_x >= 1u &&
           pat->k % pat->strata_x == 0u && pat->k / pat->strata_x == pat->strata_y;
}

static mcs_status check(const mcs_pattern2d *pat, const double *out)
{
    if (pat == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (!pattern_is_valid(pat))
        return MCS_ERR_UNINIT;
    if (pat->kind == MCS_PATTERN2D_MULTI_JITTERED || pat->kind == MCS_PATTERN2D_CMJ)
        return MCS_ERR_KIND;
    return MCS_OK;
}

/* E P(f) for f != 0, pattern already checked. |phi(f)|^2 = sinc^2(pi f / d)
 * is |E e^{-2 pi i f xi / d}|^2 for xi uniform on [0,1), the factor each
 * stratum of width 1/d puts on a pair term. */
static double exact_nonzero(const mcs_pattern2d *pat, size_t fx, size_t fy)
{
    const size_t m = pat->strata_x, n = pat->strata_y, k = pat->k;
    switch (pat->kind) {
    case MCS_PATTERN2D_RANDOM: return 1.0;
    case MCS_PATTERN2D_JITTERED:
        /* Pair terms: |sum_j E e_j|^2 - sum_j |E e_j|^2, the first 0 at f != 0. */
        return 1.0 - mcs_ps_sinc2(fx, m) * mcs_ps_sinc2(fy, n);
    case MCS_PATTERN2D_GRID:
    case MCS_PATTERN2D_SHIFTED_GRID:
        return fx % m == 0u && fy % n == 0u ? (double)k : 0.0;
    default: { /* n-rooks */
        if (k == 1u)
            return 1.0; /* no pairs */
        double dx = fx % k == 0u ? (double)k - 1.0 : -1.0;
        double dy = fy % k == 0u ? (double)k - 1.0 : -1.0;
        return 1.0 + mcs_ps_sinc2(fx, k) * mcs_ps_sinc2(fy, k) * dx * dy / ((double)k - 1.0);
    }
    }
}

mcs_status mcs_pointset2d_exact_power(const mcs_pattern2d *pat, long freq_x, long freq_y,
                                      double *out)
{
    mcs_status st = check(pat, out);
    if (st != MCS_OK)
        return st;
    size_t fx = mcs_ps_abs(freq_x), fy = mcs_ps_abs(freq_y);
    *out = fx == 0u && fy == 0u ? (double)pat->k : exact_nonzero(pat, fx, fy);
    return MCS_OK;
}

/* Whole-plane mean and unbiased variance (divisor n - 1) of the exact power
 * over annulus r; returns the count n. Every term is even in fx and in fy,
 * so the quadrant ax, ay >= 0 is enumerated with sign multiplicities. */
static double exact_ring(const mcs_pattern2d *pat, size_t r, double *mean, double *var)
{
    double sum = 0.0, n = 0.0, ss = 0.0;
    for (int pass = 0; pass < 2; ++pass)
        for (size_t ay = 0; ay <= r; ++ay)
            for (size_t ax = 0; ax <= r; ++ax) {
                if (mcs_ps_isqrt(ax * ax + ay * ay) != r)
                    continue;
                double w = (ax > 0u ? 2.0 : 1.0) * (ay > 0u ? 2.0 : 1.0);
                double p = ax == 0u && ay == 0u ? (double)pat->k : exact_nonzero(pat, ax, ay);
                if (pass == 0) {
                    sum += w * p;
                    n += w;
                } else {
                    ss += w * (p - sum / n) * (p - sum / n);
                }
            }
    *mean = sum / n;
    *var = n > 1.0 ? ss / (n - 1.0) : 0.0;
    return n;
}

mcs_status mcs_pointset2d_exact_radial(const mcs_pattern2d *pat, size_t radius, double *out)
{
    mcs_status st = check(pat, out);
    if (st != MCS_OK)
        return st;
    double var = 0.0;
    (void)exact_ring(pat, radius, out, &var);
    return MCS_OK;
}

mcs_status mcs_pointset2d_exact_anisotropy(const mcs_pattern2d *pat, size_t radius,
                                           double *out_db)
{
    mcs_status st = check(pat, out_db);
    if (st != MCS_OK)
        return st;
    double mean = 0.0, var = 0.0;
    double n = exact_ring(pat, radius, &mean, &var);
    /* Differences at the rounding level of the mean are no variance. */
    if (n < 2.0 || !(mean > 0.0) || !(var > 1e-24 * mean * mean))
        return MCS_ERR_DOMAIN;
    *out_db = 10.0 * log10(var / (mean * mean));
    return MCS_OK;
}
