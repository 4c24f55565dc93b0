/* Independent references for the spectra tests (dft, spectrum, moment). */
#ifndef SPECTRA_REF_H
#define SPECTRA_REF_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

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

/* The importance function of the tests, uneven and without a pattern a
 * formula could hide behind: g_b = base + ((mult b) mod N) / N, plus bump
 * at bin bump_bin. Fails the test on error. */
void spectra_make_importance(mcs_importance *imp, size_t n, double base, size_t mult,
                             size_t bump_bin, double bump);

/* Adds `trials` trials of the pattern (kind, n, k, importance), drawn from
 * PCG32 stream (seed, seq), to a; bins[k] and weights[k] hold the last one.
 * Fails the test on error. */
void spectra_run(mcs_spectrum *a, mcs_pattern_kind kind, size_t n, size_t k,
                 const mcs_importance *importance, uint64_t seed, uint64_t seq, size_t trials,
                 size_t *bins, double *weights);

/* call returns status and leaves the object obj as it was (copy: an object
 * of its type to hold the bytes before the call). */
#define SPECTRA_UNCHANGED(obj, copy, status, call)                                           \
    do {                                                                                     \
        memcpy(&(copy), &(obj), sizeof(obj));                                                \
        TEST_ASSERT_EQUAL_INT((status), (call));                                             \
        TEST_ASSERT_EQUAL_MEMORY(&(copy), &(obj), sizeof(obj));                              \
    } while (0)

/* An accumulator's add_bins through one signature (a small wrapper per
 * type: a call through a cast function pointer is undefined). */
typedef mcs_status (*spectra_add_bins_fn)(void *obj, size_t k, const size_t *bins,
                                          const double *weights);

/* The bad sparse trials every accumulator of N = n bins refuses, each with
 * its status and with obj (size bytes; scratch holds its copy) left
 * byte-identical: a NULL object, bins or weights (MCS_ERR_NULL), K = 0
 * (MCS_ERR_K_RANGE), bins[bin_at] = N (MCS_ERR_BIN_RANGE), weights[weight_at]
 * NaN (MCS_ERR_NOT_FINITE) and negative (MCS_ERR_NEGATIVE). bins[3] and
 * weights[3] are a valid trial, as they were on return. */
void spectra_refuses_bad_trials(void *obj, void *scratch, size_t size, size_t n,
                                spectra_add_bins_fn add, size_t *bins, double *weights,
                                size_t bin_at, size_t weight_at);

/* Fails the test unless |actual - expected| <= tol * (|expected| + scale);
 * the message names what and the indices a, b. */
void spectra_assert_close(double expected, double actual, double tol, double scale,
                          const char *what, size_t a, size_t b);

/* (1/N) sum_k <|S_k|^2> of a spectrum accumulator: the natural scale of a
 * pattern's power (rounding is relative to it, not to one frequency). */
double spectra_mean_power(const mcs_spectrum *acc);

/* Guard words after an output array: a caller buffer one element longer
 * than the output, its last element a sentinel that a correct call never
 * writes. guard_set writes it at buf[len]; guard_check fails the test unless
 * it is still there. */
void spectra_guard_set(double *buf, size_t len);
void spectra_guard_check(const double *buf, size_t len, const char *what);

#endif /* SPECTRA_REF_H */
