/* Helpers shared by the point-set periodogram accumulators (pointset.c,
 * pointset2d.c, pointset_exact.c); private header. */
#ifndef MCSPEC_POINTSET_INTERNAL_H
#define MCSPEC_POINTSET_INTERNAL_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

/* Phases are advanced by one complex multiplication per frequency; every
 * MCS_PS_ANCHOR steps they are recomputed from sin and cos, so rounding
 * accumulates over at most this many products (a few 1e-15 in all). */
#define MCS_PS_ANCHOR 32u

#define MCS_PS_TWO_PI 6.283185307179586476925286766559

/* e^{-2 pi i f x} for x in [0,1): f x reduced mod 1 first so the angle stays
 * in [0, 2 pi) however large f is. */
static inline void mcs_ps_phase(double x, size_t f, double *re, double *im)
{
    double t = (double)f * x;
    t -= floor(t);
    double a = MCS_PS_TWO_PI * t;
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

/* 1 if every x[i], i < count, lies in [0, 1) (NaN fails). */
static inline int mcs_ps_points_in_range(size_t count, const double *x)
{
    for (size_t i = 0; i < count; ++i)
        if (!(x[i] >= 0.0 && x[i] < 1.0))
            return 0;
    return 1;
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

/* sqrt(m2 / (T - 1) / T): standard error of a mean over T >= 2 trials. */
static inline double mcs_ps_stderr(double m2, uint64_t count)
{
    double t = (double)count;
    return sqrt(fmax(m2, 0.0) / (t - 1.0) / t);
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
    double s = sin(MCS_PS_TWO_PI * 0.5 * (double)(f % d) / (double)d);
    double a = MCS_PS_TWO_PI * 0.5 * (double)f / (double)d;
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

#endif /* MCSPEC_POINTSET_INTERNAL_H */
