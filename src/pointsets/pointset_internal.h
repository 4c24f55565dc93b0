/* Helpers shared by the point-set periodogram accumulators (pointset.c,
 * pointset2d.c, pointset_exact.c) and the binned 2D spectrum (spectrum2d.c,
 * spectrum2d_exact.c): the outer-product kernel of a trial, the per-cell
 * Welford and Chan updates, the read-out of a mean or its standard error,
 * and the annulus arithmetic; private header. */
#ifndef MCSPEC_POINTSET_INTERNAL_H
#define MCSPEC_POINTSET_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "accumulators/acc_internal.h"
#include "mcspec/status.h"

/* Phases are advanced by one complex multiplication per frequency; every
 * MCS_PS_ANCHOR steps they are recomputed from sin and cos, so rounding
 * accumulates over at most this many products (a few 1e-15 in all). */
#define MCS_PS_ANCHOR 32u

/* The first check of a point-set or binned 2D accumulator's init:
 * MCS_ERR_NULL without the object, MCS_ERR_FREQ_RANGE unless 1 <= f <= cap. */
static inline mcs_status mcs_ps_check_init(const void *acc, size_t freq_max, size_t cap)
{
    mcs_status st = mcs_check_init_(acc, freq_max, cap);
    return st == MCS_ERR_N_RANGE ? MCS_ERR_FREQ_RANGE : st;
}

/* A count read-out: *out = count when the object's own check gave st, MCS_OK
 * (count is read only then: the caller passes 0 otherwise). */
static inline mcs_status mcs_ps_count_out(mcs_status st, uint64_t count, uint64_t *out)
{
    if (st == MCS_OK)
        *out = count;
    return st;
}

/* e^{-2 pi i f x} for x in [0,1): f x reduced mod 1 first so the angle stays
 * in [0, 2 pi) however large f is. */
static inline void mcs_ps_phase(double x, size_t f, double *re, double *im)
{
    double t = (double)f * x;
    t -= floor(t);
    double a = MCS_TWO_PI * t;
    *re = cos(a);
    *im = -sin(a);
}

/* re[f] + i im[f] = amp e^{-2 pi i f x}, f = 0..fmax, by rotation with
 * re-anchoring (amp is 1 for a point, 0 for a padding slot). */
static inline void mcs_ps_phase_row(double x, double amp, size_t fmax, double *re, double *im)
{
    double wr, wi;
    mcs_ps_phase(x, 1u, &wr, &wi);
    for (size_t c = 0; c <= fmax; c += MCS_PS_ANCHOR) {
        double zr, zi;
        mcs_ps_phase(x, c, &zr, &zi);
        zr *= amp;
        zi *= amp;
        size_t end = fmax - c < MCS_PS_ANCHOR ? fmax + 1u : c + MCS_PS_ANCHOR;
        for (size_t f = c; f < end; ++f) {
            re[f] = zr;
            im[f] = zi;
            double t = zr * wr - zi * wi;
            zi = zr * wi + zi * wr;
            zr = t;
        }
    }
}

/* s[c] += sum over four points p of x_p[c] (a_p + i b_p), c < stride (even),
 * with y = (a_0, b_0, ..., a_3, b_3): one row of an outer-product sum.
 * restrict: the phase rows and the sums are disjoint parts of the
 * accumulator, which lets the compiler vectorise the loop. */
static inline void mcs_ps_row_update4(size_t stride, double *restrict sr, double *restrict si,
                       const double *restrict x0r, const double *restrict x0i,
                       const double *restrict x1r, const double *restrict x1i,
                       const double *restrict x2r, const double *restrict x2i,
                       const double *restrict x3r, const double *restrict x3i, const double *y)
{
    const double a0 = y[0], b0 = y[1], a1 = y[2], b1 = y[3];
    const double a2 = y[4], b2 = y[5], a3 = y[6], b3 = y[7];
    /* Two columns per step (stride is even): the pair is one vector operation
     * at -O2, where gcc vectorises straight-line code but not loops of
     * unknown length. */
    for (size_t c = 0; c < stride; c += 2u) {
        for (size_t d = c; d < c + 2u; ++d) {
            sr[d] += ((x0r[d] * a0 - x0i[d] * b0) + (x1r[d] * a1 - x1i[d] * b1)) +
                     ((x2r[d] * a2 - x2i[d] * b2) + (x3r[d] * a3 - x3i[d] * b3));
            si[d] += ((x0r[d] * b0 + x0i[d] * a0) + (x1r[d] * b1 + x1i[d] * a1)) +
                     ((x2r[d] * b2 + x2i[d] * a2) + (x3r[d] * b3 + x3i[d] * a3));
        }
    }
}

/* S[r stride + c] += sum over four points p of y_p[r] x_p[c], r < rows,
 * c < stride (even): a trial's sum over points as outer products of per-point
 * rows, four points per pass over S. x[2p], x[2p + 1] are point p's x row
 * (re, im), y[2p], y[2p + 1] its y row. */
static inline void mcs_ps_outer4(size_t rows, size_t stride, double *re, double *im,
                                 const double *const x[8], const double *const y[8])
{
    for (size_t r = 0; r < rows; ++r) {
        const double c[8] = {y[0][r], y[1][r], y[2][r], y[3][r],
                             y[4][r], y[5][r], y[6][r], y[7][r]};
        mcs_ps_row_update4(stride, re + r * stride, im + r * stride, x[0], x[1], x[2], x[3], x[4],
                           x[5], x[6], x[7], c);
    }
}

/* Zeroes a trial's sums re[cells], im[cells] before its points go in. */
static inline void mcs_ps_clear(size_t cells, double *re, double *im)
{
    memset(re, 0, cells * sizeof *re);
    memset(im, 0, cells * sizeof *im);
}

/* Welford update of (mean, m2) with value v as the count-th value. */
static inline void mcs_ps_welford(double *mean, double *m2, double v, uint64_t count)
{
    double d = v - *mean;
    *mean += d / (double)count;
    *m2 += d * (v - *mean);
}

/* Chan et al.: (mean_a, m2_a) over na values <- union with (mean_b, m2_b) over nb. */
static inline void mcs_ps_chan(double *mean_a, double *m2_a, uint64_t na, double mean_b,
                               double m2_b, uint64_t nb)
{
    double n = (double)na + (double)nb, d = mean_b - *mean_a;
    *mean_a += d * ((double)nb / n);
    *m2_a += m2_b + d * d * ((double)na * (double)nb / n);
}

/* (mean_a, m2_a) over na trials <- union with (mean_b, m2_b) over nb, cell by
 * cell over the first `cells` cells (Chan et al.). */
static inline void mcs_ps_chan_cells(size_t cells, double *mean_a, double *m2_a, uint64_t na,
                                     const double *mean_b, const double *m2_b, uint64_t nb)
{
    for (size_t i = 0; i < cells; ++i)
        mcs_ps_chan(&mean_a[i], &m2_a[i], na, mean_b[i], m2_b[i], nb);
}

/* sqrt(m2 / (T - 1) / T): standard error of a mean over T >= 2 trials. */
static inline double mcs_ps_stderr(double m2, uint64_t count)
{
    double t = (double)count;
    return sqrt(fmax(m2, 0.0) / (t - 1.0) / t);
}

/* A read-out of one cell over `count` trials: *out = its mean (want_stderr 0)
 * or the standard error of the mean (1). MCS_ERR_EMPTY without a trial, or
 * for the standard error without two; *out untouched then. */
static inline mcs_status mcs_ps_read(double mean, double m2, uint64_t count, int want_stderr,
                                     double *out)
{
    if (count < (want_stderr ? 2u : 1u))
        return MCS_ERR_EMPTY;
    *out = want_stderr ? mcs_ps_stderr(m2, count) : mean;
    return MCS_OK;
}

/* |f| as a size_t, without overflow at LONG_MIN. */
static inline size_t mcs_ps_abs(long f)
{
    return f < 0 ? (size_t)(-(f + 1)) + 1u : (size_t)f;
}

/* sinc^2(pi f / d) = sin^2(pi f/d) / (pi f/d)^2, 1 at f = 0. sin^2 has period
 * d in f, so the sine takes f mod d and stays accurate for large f. */
static inline double mcs_ps_sinc2(size_t f, size_t d)
{
    if (f == 0u)
        return 1.0;
    double s = sin(MCS_TWO_PI * 0.5 * (double)(f % d) / (double)d);
    double a = MCS_TWO_PI * 0.5 * (double)f / (double)d;
    return (s * s) / (a * a);
}

/* floor(sqrt(q)) exactly (the double root is corrected by integer steps):
 * the annulus of wave vector f is floor(|f|). */
static inline size_t mcs_ps_isqrt(size_t q)
{
    size_t r = (size_t)sqrt((double)q);
    while (r > 0u && r * r > q)
        --r;
    while ((r + 1u) * (r + 1u) <= q)
        ++r;
    return r;
}

/* How many whole-plane wave vectors (+-ax, +-ay) the quadrant wave vector
 * (ax, ay) stands for if it lies in annulus r (r <= |f| < r + 1), else 0. */
static inline double mcs_ps_ring_weight(size_t ax, size_t ay, size_t r)
{
    if (mcs_ps_isqrt(ax * ax + ay * ay) != r)
        return 0.0;
    return (ax > 0u ? 2.0 : 1.0) * (ay > 0u ? 2.0 : 1.0);
}

/* Weighted mean and unbiased variance of the values over an annulus, in two
 * passes over them (the variance of values near a large mean would cancel in
 * one): pass 0 sums w p and w, pass 1 the weighted squared deviations. */
typedef struct {
    double sum, n, ss;
} mcs_ps_ring;

static inline void mcs_ps_ring_add(mcs_ps_ring *g, int pass, double w, double p)
{
    if (pass == 0) {
        g->sum += w * p;
        g->n += w;
    } else {
        g->ss += w * (p - g->sum / g->n) * (p - g->sum / g->n);
    }
}

/* psa's anisotropy 10 log10(var / mean^2) of the annulus in dB (divisor
 * n - 1). MCS_ERR_DOMAIN when it is not finite: fewer than two wave vectors,
 * a mean not above mean_min (an empty annulus measured as rounding residue),
 * or a variance not above var_rel_min mean^2 (differences at the rounding
 * level of the mean are no variance). *out_db untouched then. */
static inline mcs_status mcs_ps_ring_db(const mcs_ps_ring *g, double mean_min,
                                        double var_rel_min, double *out_db)
{
    const double mean = g->sum / g->n, var = g->n > 1.0 ? g->ss / (g->n - 1.0) : 0.0;
    if (g->n < 2.0 || !(mean > mean_min) || !(var > var_rel_min * mean * mean))
        return MCS_ERR_DOMAIN;
    *out_db = 10.0 * log10(var / (mean * mean));
    return MCS_OK;
}

#endif /* MCSPEC_POINTSET_INTERNAL_H */
