/* Shared by the section examples: one measurement run of one pattern.
 *
 * A run draws `trials` trials with mcs_pattern_draw from its own PCG32 stream
 * (seed, stream), so every pattern's numbers are independent of what else an
 * example measures and in which order. Per trial it feeds
 *  - the caller's mcs_spectrum and mcs_moment (either may be NULL),
 *  - scalar Welford accumulators of Re S_k and Im S_k at a few probed
 *    frequencies and of Re and Im of S_k S_l* at a few probed pairs, S_k by a
 *    direct sum over the K samples, S_k = N^{-1/2} sum_j w_j e^{-2 pi i k n_j/N}
 *    (these give the standard errors that mcs_moment does not),
 *  - the estimator I = (1/K) sum_n f_n s_n (eq. 8) of up to EX_MAX_F integrands,
 *  - the Parseval sum P = sum_{k>=1} |S_k|^2 = sum_n s_n^2 - S_0^2, whose mean
 *    is the total power over k >= 1 (a scalar per trial, so its standard error
 *    is honest even though the |S_k|^2 of one trial are correlated). */
#ifndef MCSPEC_EXAMPLE_MEASURE_H
#define MCSPEC_EXAMPLE_MEASURE_H

#include <stddef.h>
#include <stdint.h>

#include "mcspec.h"

#define EX_MAX_PROBE 16 /* probed frequencies per run */
#define EX_MAX_PAIR 16  /* probed (k, l) pairs per run */
#define EX_MAX_F 4      /* integrands per run */
#define EX_MAX_K 4096   /* samples per trial */

typedef struct {
    mcs_pattern pattern;
    mcs_rng rng;
    size_t n, k;
    size_t nfreq;
    size_t freq[EX_MAX_PROBE];
    size_t npair;
    size_t pair_k[EX_MAX_PAIR], pair_l[EX_MAX_PAIR];
    size_t nf;
    const double *f[EX_MAX_F];           /* caller's integrands f[n], outlive the run */
    mcs_welford s_re[EX_MAX_PROBE], s_im[EX_MAX_PROBE];
    mcs_welford x_re[EX_MAX_PAIR], x_im[EX_MAX_PAIR];
    mcs_welford estimate[EX_MAX_F];
    mcs_welford parseval;                /* sum_{k>=1} |S_k|^2 per trial */
    double cos_table[MCS_MAX_N], sin_table[MCS_MAX_N];
} ex_run;

/* Configures a run of pattern kind over n bins with k samples (importance may
 * be NULL), seeded with (seed, stream). Returns MCS_OK or the library's
 * status (k above EX_MAX_K: MCS_ERR_K_RANGE). */
mcs_status ex_run_init(ex_run *run, mcs_pattern_kind kind, size_t n, size_t k,
                       const mcs_importance *importance, uint64_t seed, uint64_t stream);

/* Probes S_freq; returns its index, or -1 if freq >= N or the table is full.
 * A frequency probed twice shares one index. */
int ex_run_probe(ex_run *run, size_t freq);
/* Probes S_k S_l*; returns its index, or -1 if out of range or full. */
int ex_run_probe_pair(ex_run *run, size_t k, size_t l);
/* Adds an integrand f[n] (n = N values); returns its index or -1 if full. */
int ex_run_integrand(ex_run *run, const double *f);

/* Draws the trials. spectrum and moment may be NULL; if given they must be
 * initialised for N (they are not emptied first). Returns the first failing
 * status, or MCS_OK. */
mcs_status ex_run_go(ex_run *run, unsigned long trials, mcs_spectrum *spectrum,
                     mcs_moment *moment);

/* Copies the candidate frequencies that lie in [1, N) to out, dropping
 * repeats, in order; returns how many. out holds at least ncand. */
size_t ex_pick_freqs(size_t n, const size_t *cand, size_t ncand, size_t *out);

/* Mean and standard error of a Welford accumulator (EX_NA if too few values). */
double ex_mean(const mcs_welford *w, double *stderr_out);
/* Unbiased variance and its standard error (EX_NA if too few values). */
double ex_variance(const mcs_welford *w, double *stderr_out);

#endif /* MCSPEC_EXAMPLE_MEASURE_H */
