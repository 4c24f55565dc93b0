/* Private interface of the NUFFT (src/dft/nufft*.c): the two stages of a
 * type-1 transform after mcs_nufft_type1 has checked its arguments. */
#ifndef MCSPEC_NUFFT_INTERNAL_H
#define MCSPEC_NUFFT_INTERNAL_H

#include <math.h>
#include <stddef.h>

#include "mcspec/nufft.h"

/* The "exponential of semicircle" kernel phi(z) = e^{beta (sqrt(1 - z^2) - 1)}
 * on |z| <= 1, with the exponent written as -beta z^2 / (1 + sqrt(1 - z^2)):
 * sqrt(1 - z^2) - 1 loses up to an ulp of 1 to cancellation, which beta
 * (up to 46) turns into a relative error of 5e-15 in phi near z = 0, the
 * NUFFT's accuracy floor at the largest widths (measured: 1.3e-14 K, against
 * 1e-15 K this way). 1 - z^2 is formed as (1 - z)(1 + z), exact near |z| = 1;
 * a z a rounding past -1 (a point whose t - w/2 rounds onto an integer) reads
 * as the kernel's edge value e^{-beta} instead of a NaN. */
static inline double mcs_nufft_kernel_(double z, double beta)
{
    double q = (1.0 - z) * (1.0 + z);
    q = q > 0.0 ? q : 0.0;
    return exp(-beta * (z * z) / (1.0 + sqrt(q)));
}

/* Zeroes the plan's grid and spreads the k points (k d coordinates, each in
 * [0, 1), already checked) onto it with the plan's kernel. */
void mcs_nufft_spread_(const mcs_nufft *plan, const double *points, size_t k);
void mcs_nufft_spread_f_(const mcs_nufft *plan, const float *points, size_t k);

/* Transforms the spread grid and writes the (2F + 1)^d corrected modes to out
 * (the layout of mcs_nufft_type1). Overwrites the grid and the scratch row. */
void mcs_nufft_modes_(const mcs_nufft *plan, double *out);

#endif /* MCSPEC_NUFFT_INTERNAL_H */
