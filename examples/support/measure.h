/* Shared by the section examples: one measurement run of one pattern.
 *
 * A run draws `trials` trials with mcs_pattern_draw from its own PCG32 stream
 * (seed, stream), so every pattern's numbers are independent of what else an
 * example measures and in which order. A trial is one draw of the pattern, or
 * several independent draws from the same stream, one after the other (so
 * that section 1 can put shared and independent samples side by side). Per
 * trial it feeds
 *  - from the first draw: the caller's mcs_spectrum and mcs_moment (either
 *    may be NULL),
 *  - from the first draw: scalar Welford accumulators of Re S_k and Im S_k at
 *    a few probed frequencies and of Re and Im of S_k S_l* at a few probed
 *    pairs, S_k by a direct sum over the K samples,
 *    S_k = N^{-1/2} sum_j w_j e^{-2 pi i k n_j/N} (these give the standard
 *    errors that mcs_moment does not),
 *  - the estimator I = (1/K) sum_n f_n s_n (eq. 8) of up to EX_MAX_F
 *    integrands, each on the draw it was added for, and the differences of
 *    pairs of those estimates within the trial,
 *  - from the first draw: the Parseval sum P = sum_{k>=1} |S_k|^2
 *    = sum_n s_n^2 - S_0^2, whose mean is the total power over k >= 1 (a
 *    scalar per trial, so its standard error is honest even though the
 *    |S_k|^2 of one trial are correlated). */
#ifndef MCSPEC_EXAMPLE_MEASURE_H
#define MCSPEC_EXAMPLE_MEASURE_H

#include <stddef.h>
#include <stdint.h>

#include "exact.h"
#include "mcspec.h"
#include "report.h"

#define EX_MAX_PROBE 16 /* probed frequencies per run */
#define EX_MAX_PAIR 16  /* probed (k, l) pairs per run */
#define EX_MAX_F 4      /* integrands per run */
#define EX_MAX_DIFF 4   /* differences of two integrands' estimates per run */
#define EX_MAX_DRAW 3   /* draws per trial */
#define EX_MAX_K 4096   /* samples per draw */

typedef struct {
    mcs_pattern pattern;
    mcs_rng rng;
    size_t n, k;
    size_t draws;                        /* per trial, 1 + the largest integrand draw */
    size_t nfreq;
    size_t freq[EX_MAX_PROBE];
    size_t npair;
    size_t pair_k[EX_MAX_PAIR], pair_l[EX_MAX_PAIR];
    size_t nf;
    const double *f[EX_MAX_F];           /* caller's integrands f[n], outlive the run */
    size_t f_draw[EX_MAX_F];             /* the draw each integrand is estimated on */
    size_t ndiff;
    size_t diff_a[EX_MAX_DIFF], diff_b[EX_MAX_DIFF];
    mcs_welford s_re[EX_MAX_PROBE], s_im[EX_MAX_PROBE];
    mcs_welford x_re[EX_MAX_PAIR], x_im[EX_MAX_PAIR];
    mcs_welford estimate[EX_MAX_F];
    mcs_welford difference[EX_MAX_DIFF]; /* estimate a - estimate b, per trial */
    mcs_welford parseval;                /* sum_{k>=1} |S_k|^2 per trial */
    double cos_table[MCS_MAX_N], sin_table[MCS_MAX_N];
} ex_run;

/* Configures a run of pattern kind over n bins with k samples (importance may
 * be NULL), seeded with (seed, stream), one draw per trial. Returns MCS_OK or
 * the library's status (k above EX_MAX_K: MCS_ERR_K_RANGE). */
mcs_status ex_run_init(ex_run *run, mcs_pattern_kind kind, size_t n, size_t k,
                       const mcs_importance *importance, uint64_t seed, uint64_t stream);

/* ex_run_init, then the exact moments of the run's pattern into exact
 * (ex_exact_init) and an empty spectrum accumulator over N into spectrum
 * (mcs_spectrum_init), either of which may be NULL. Returns the first
 * failing status, or MCS_OK. */
mcs_status ex_run_setup(ex_run *run, ex_exact *exact, mcs_spectrum *spectrum,
                        mcs_pattern_kind kind, size_t n, size_t k,
                        const mcs_importance *importance, uint64_t seed, uint64_t stream);

/* Probes S_freq; returns its index, or -1 if freq >= N or the table is full.
 * A frequency probed twice shares one index. */
int ex_run_probe(ex_run *run, size_t freq);
/* Probes S_k S_l*; returns its index, or -1 if out of range or full. */
int ex_run_probe_pair(ex_run *run, size_t k, size_t l);
/* Adds an integrand f[n] (n = N values) estimated on the first draw; returns
 * its index or -1 if full. */
int ex_run_integrand(ex_run *run, const double *f);
/* The same on draw `draw` of each trial (< EX_MAX_DRAW; the run draws that
 * many patterns per trial from then on); -1 if full or draw is too large. */
int ex_run_integrand_on(ex_run *run, const double *f, size_t draw);
/* Accumulates estimate a - estimate b per trial (integrand indices); returns
 * its index in difference[], or -1 if full or out of range. */
int ex_run_difference(ex_run *run, int a, int b);

/* Draws the trials. spectrum and moment may be NULL; if given they must be
 * initialised for N (they are not emptied first). Returns the first failing
 * status, or MCS_OK. */
mcs_status ex_run_go(ex_run *run, unsigned long trials, mcs_spectrum *spectrum,
                     mcs_moment *moment);

/* Measured <S_freq> at probe index idx, and the standard errors of its parts
 * (stderr_out may be NULL). */
ex_complex ex_run_mean(const ex_run *run, int idx, ex_complex *stderr_out);
/* Measured <S_k S_l*> at pair index idx, and the standard errors of its parts
 * (stderr_out may be NULL). */
ex_complex ex_run_mean_pair(const ex_run *run, int idx, ex_complex *stderr_out);

/* Measured mean over k >= 1 of <|S_k|^2>: the run's Parseval sum over N - 1,
 * and its standard error into *stderr_out (EX_NA for N = 1). */
double ex_run_mean_power(const ex_run *run, double *stderr_out);

/* Prints eq. 11's row "<I>" of a run: the closed form is the mean of f
 * (mcs_eq11_unbiased_mean), the exact value the estimator mean of exact,
 * the measurement the mean of the run's first integrand (which must be f) with
 * its standard error. Returns the row. */
ex_row ex_estimator_mean_row(const ex_options *opt, const char *section, const char *pattern,
                             const ex_exact *exact, const ex_run *run, const double *f);

/* Copies the candidate frequencies that lie in [1, N) to out, dropping
 * repeats, in order; returns how many. out holds at least ncand. */
size_t ex_pick_freqs(size_t n, const size_t *cand, size_t ncand, size_t *out);

#endif /* MCSPEC_EXAMPLE_MEASURE_H */
