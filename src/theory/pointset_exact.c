/* Exact point-set power spectra of the 2D patterns (pointset2d.h). */
#include "mcspec/pointset2d.h"
#include "patterns/pattern2d_internal.h"
#include "pointsets/pointset_internal.h"

#include <math.h>

static mcs_status check(const mcs_pattern2d *pat, const double *out)
{
    if (pat == NULL || out == NULL)
        return MCS_ERR_NULL;
    if (!mcs_pattern2d_is_valid_(pat))
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

/* The exact power over annulus r, the whole plane counted. Every term is
 * even in fx and in fy, so the quadrant ax, ay >= 0 is enumerated with sign
 * multiplicities, row by row over the annulus's columns only. */
static void exact_ring(const mcs_pattern2d *pat, size_t r, mcs_ps_ring *g)
{
    for (int pass = 0; pass < 2; ++pass)
        for (size_t ay = 0; ay <= r; ++ay) {
            size_t lo, hi;
            mcs_ps_ring_span(r, ay, &lo, &hi);
            for (size_t ax = lo; ax <= hi; ++ax) {
                double p = ax == 0u && ay == 0u ? (double)pat->k : exact_nonzero(pat, ax, ay);
                mcs_ps_ring_add(g, pass, mcs_ps_ring_mult(ax, ay), p);
            }
        }
}

/* The checks of an annulus read-out: annuli exist up to the largest cutoff
 * an accumulator takes (O(radius) rows each). */
static mcs_status check_ring(const mcs_pattern2d *pat, size_t radius, const double *out)
{
    mcs_status st = check(pat, out);
    return st == MCS_OK && radius > (size_t)MCS_POINTSET2D_MAX_FREQ ? MCS_ERR_FREQ_RANGE : st;
}

mcs_status mcs_pointset2d_exact_radial(const mcs_pattern2d *pat, size_t radius, double *out)
{
    mcs_status st = check_ring(pat, radius, out);
    if (st != MCS_OK)
        return st;
    mcs_ps_ring g = {0.0, 0.0, 0.0};
    exact_ring(pat, radius, &g);
    *out = g.sum / g.n;
    return MCS_OK;
}

mcs_status mcs_pointset2d_exact_anisotropy(const mcs_pattern2d *pat, size_t radius,
                                           double *out_db)
{
    mcs_status st = check_ring(pat, radius, out_db);
    if (st != MCS_OK)
        return st;
    mcs_ps_ring g = {0.0, 0.0, 0.0};
    exact_ring(pat, radius, &g);
    /* Differences at the rounding level of the mean are no variance. */
    return mcs_ps_ring_db(&g, 0.0, 1e-24, out_db);
}
