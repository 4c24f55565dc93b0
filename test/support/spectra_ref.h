/* Independent references for the spectra tests (dft, spectrum, moment). */
#ifndef SPECTRA_REF_H
#define SPECTRA_REF_H

#include <stddef.h>
#include <stdint.h>

/* Naive O(N^2) eq. 7 in long double with exactly reduced angles:
 * re[k], im[k] for k = 0..nfreq-1 (nfreq <= n <= 4096). */
void spectra_naive_dft(size_t n, const double *s, size_t nfreq, double *re, double *im);

/* Uniform double in [lo, hi) from a small xorshift stream (independent of PCG32). */
double spectra_uniform(uint64_t *state, double lo, double hi);

/* Largest |a_k - b_k| / (|b_k| + scale) over k < n. */
double spectra_max_rel_err(size_t n, const double *a, const double *b, double scale);

#endif /* SPECTRA_REF_H */
