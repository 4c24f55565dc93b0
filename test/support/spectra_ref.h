/* Independent references for the spectra tests (dft, spectrum, moment). */
#ifndef SPECTRA_REF_H
#define SPECTRA_REF_H

#include <stddef.h>
#include <stdint.h>

#include "mcspec.h"

/* Naive O(N^2) eq. 7 in long double with exactly reduced angles:
 * re[k], im[k] for k = 0..nfreq-1 (nfreq <= n <= 4096). */
void spectra_naive_dft(size_t n, const double *s, size_t nfreq, double *re, double *im);

/* Uniform double in [lo, hi) from a small xorshift stream (independent of PCG32). */
double spectra_uniform(uint64_t *state, double lo, double hi);

/* Largest |a_k - b_k| / (|b_k| + scale) over k < n. */
double spectra_max_rel_err(size_t n, const double *a, const double *b, double scale);

/* A seeded pattern stream: a pattern and its own PCG32 (seed, seq). */
typedef struct {
    mcs_pattern pat;
    mcs_rng rng;
    size_t k;
} spectra_stream;

/* Configures the pattern and seeds the stream; fails the test on error. */
void spectra_stream_init(spectra_stream *st, mcs_pattern_kind kind, size_t n, size_t k,
                         const mcs_importance *importance, uint64_t seed, uint64_t seq);

/* Draws one trial into bins[k], weights[k] and, if not NULL, points[k]. */
void spectra_stream_draw(spectra_stream *st, size_t *bins, double *weights, double *points);

#endif /* SPECTRA_REF_H */
