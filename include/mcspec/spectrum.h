/* The spectrum accumulator (eq. 7, 13, 14). Per trial it forms
 * S_k = N^{-1/2} sum_n e^{-2 pi i k n/N} s_n and keeps, per frequency, the
 * running mean of S_k (complex) and of |S_k|^2 with a Welford M2 for each, so
 * it reports <S_k>, <|S_k|^2> and the standard error of each. Welford rather
 * than sums of powers: <|S_0|^2> is K^2/N while its variance may be tiny, and
 * sums of squares would cancel.
 *
 * s is real, so S_{N-k} = conj(S_k): only k = 0..N/2 are stored; read-outs
 * for k > N/2 are served by symmetry.
 *
 * Three paths turn a trial of K (bin, weight) pairs into statistics; every
 * one gives the same means to rounding, and standard errors of the same
 * quantities:
 * - SPARSE: S_k = N^{-1/2} sum_j w_j e^{-2 pi i k n_j/N} for every k, O(K N),
 *   in blocks of MCS_SPECTRUM_BLOCK frequencies (one twiddle-table read per
 *   sample and block, times the sample's in-block phases), fused with the
 *   update: each group of 8 blocks is updated right after it is summed,
 *   while its values are in L1 (up to MCS_SPECTRUM_CHUNK samples; more are
 *   summed chunk by chunk, then updated once).
 * - FFT: scatter into a dense s, one real DFT (dft.h), O(N log N).
 * - PAIR: no transform per trial. The trials of a batch add up
 *   sum_s_n and the pair histogram h(d) = sum over sample pairs j < j' with
 *   n_j' - n_j = d (mod N) of w_j w_j' (plus half of w_j^2 at d = 0), O(K^2).
 *   A closed batch of B trials has, by Wiener-Khinchin,
 *     mean over its trials of |S_k|^2 = (2/N) sum_d h(d) cos(2 pi k d/N) / B,
 *     mean over its trials of S_k     = N^{-1/2} DFT(sum_s)_k / B,
 *   two DFTs per batch; the batch then enters the statistics as one unit of
 *   weight B (below). Standard errors are therefore by batch means.
 * MCS_SPECTRUM_PATH_AUTO chooses per trial the path of least modelled cost
 * (see spectrum_cost.c for the model, its constants and how they were
 * measured).
 *
 * Units and standard errors. The statistics are a weighted Welford over
 * units: a trial of the SPARSE or FFT path is a unit of weight 1, a batch of
 * the PAIR path a unit of weight B. With T trials in U units and
 * M2 = sum_u w_u |x_u - mean|^2, E[M2] = (U - 1) sigma^2 for i.i.d. trials
 * whatever the weights, so the standard error of a mean is
 * sqrt(M2 / (U - 1) / T): the usual one when every unit is one trial, batch
 * means when units are batches, and valid for any mix (AUTO may use
 * several paths in one accumulator). It needs U >= 2.
 *
 * The batch rule (PAIR): a batch closes after the trial that brings it to
 * at least MCS_SPECTRUM_BATCH_MIN (16) trials if (a) its sample pairs
 * (K (K + 1) / 2 per trial) pay for closing it: at least
 * MCS_SPECTRUM_BATCH_RATIO (8) times the modelled cost of the close (two
 * DFTs and the update, spectrum_cost.c) counted in pair-histogram adds, as
 * modelled for one reference machine (AVX2 kernels, the default build's DFT
 * path for N) whatever the CPU and back end, so the batches, and records,
 * are the same on every machine; or
 * (b) fewer than MCS_SPECTRUM_BATCH_UNITS (32) units are closed; or (c) it
 * holds MCS_SPECTRUM_BATCH_MAX (1024) trials. (a) keeps the close at about
 * 1/8 of the pair work, (b) gives a run 32 units (batches of 16) by its
 * 512th trial, so its standard errors rest on many units early, and (c)
 * bounds the batches: a run of T trials has at least
 * min(T / 16, 32 + (T - 512) / 1024) units. Batch sizes depend on trial
 * and unit counts only, never on the values, so the standard errors stay
 * unbiased. mcs_spectrum_set_batch fixes B instead (B = 1 makes every trial
 * its own unit, with the same standard errors as the other paths). The
 * open batch is part of every read-out (its mean and power are summed
 * directly from the open sums at O(N) per call, so read-outs stay const
 * and exact); mcs_spectrum_flush closes it early.
 *
 * Accepted input: every weight (or dense s_n) finite and >= 0, and a trial's
 * weights summing to at most MCS_SPECTRUM_MAX_SUM (2^100, about 1.27e30).
 * Then |S_k| <= 2^100, |S_k|^4 <= 2^400 and every M2 stays below 2^470 for
 * any count up to MCS_SPECTRUM_MAX_COUNT: no square or fourth power, no
 * transform and no read-out can overflow.
 *
 * Aliasing: input arrays (bins, weights, points, s) must not lie inside the
 * accumulator (MCS_ERR_ALIAS). merge accepts dst == src; any other overlap
 * of the two is MCS_ERR_ALIAS.
 *
 * Size: sizeof(mcs_spectrum) is the embedded mcs_dft (about 66 * MCS_MAX_N
 * bytes) plus, in doubles, 8 * MCS_SPECTRUM_HALF of statistics and scratch,
 * 3 * MCS_MAX_N for the open pair batch, MCS_MAX_N of dense scratch and
 * 2 * MCS_SPECTRUM_CHUNK for binned points: about 130 * MCS_MAX_N bytes
 * plus 9 KiB in all (535 744 at the default 4096 on x86-64, 43 448 at
 * MCS_MAX_N = 256 on Cortex-M, make sizes; shrink it with -DMCS_MAX_N=...).
 * It holds no pointers, so it may be copied. */
#ifndef MCSPEC_SPECTRUM_H
#define MCSPEC_SPECTRUM_H

#include <stddef.h>
#include <stdint.h>
#include "config.h"
#include "status.h"
#include "dft.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Frequencies the sparse kernel and the update handle at once. */
#define MCS_SPECTRUM_BLOCK 8

/* Stored frequencies k = 0..MCS_MAX_N/2, padded to a whole number of blocks
 * (the pad entries stay 0). */
#define MCS_SPECTRUM_HALF \
    (((MCS_MAX_N) / 2 + MCS_SPECTRUM_BLOCK) / MCS_SPECTRUM_BLOCK * MCS_SPECTRUM_BLOCK)

/* Samples the sparse kernel keeps in-block phases for (more are taken in
 * chunks of this many; the phases live in the plan's direct-path scratch),
 * and that points are binned in at a time. Fixed (dft.h), as the order of
 * the sums, and so the bits of every statistic, follow it. */
#define MCS_SPECTRUM_CHUNK MCS_DFT_CHUNK

/* Largest sum of one trial's weights (2^100). */
#define MCS_SPECTRUM_MAX_SUM 0x1p100

/* Largest trial count: the library's MCS_MAX_COUNT (2^53, config.h: every
 * count is then exact as a double). */
#define MCS_SPECTRUM_MAX_COUNT ((uint64_t)MCS_MAX_COUNT)

/* The batch rule of the PAIR path (above). */
#define MCS_SPECTRUM_BATCH_MIN 16u
#define MCS_SPECTRUM_BATCH_MAX 1024u
#define MCS_SPECTRUM_BATCH_RATIO 8.0
#define MCS_SPECTRUM_BATCH_UNITS 32u

/* How a sparse trial is transformed. */
typedef enum {
    MCS_SPECTRUM_PATH_AUTO = 0,   /* least modelled cost, chosen per trial (the default) */
    MCS_SPECTRUM_PATH_SPARSE = 1, /* always the O(K N) block-phase sum */
    MCS_SPECTRUM_PATH_FFT = 2,    /* always dense s through the DFT */
    MCS_SPECTRUM_PATH_PAIR = 3    /* always the O(K^2) pair histogram, batch means */
} mcs_spectrum_path;

typedef struct {
    size_t n;                            /* N; 0 before init */
    uint64_t count;                      /* trials added, the open batch included */
    uint64_t units;                      /* Welford units in the statistics (open batch not included) */
    mcs_spectrum_path path;              /* path policy, AUTO after init */
    int simd;                            /* kernels: 0 baseline, 1 AVX2 (x86-64 with AVX2, set
                                            by init; both give the same bits) */
    uint64_t batch;                      /* fixed batch size of the PAIR path; 0: the batch rule */
    uint64_t open_count;                 /* trials in the open PAIR batch */
    double open_work;                    /* sample pairs K (K + 1) / 2 summed over the open batch */
    double close_work;                   /* pairs that pay for closing a batch (the batch rule) */
    double cost[5];                      /* cost model from N (spectrum_cost.c) */
    size_t auto_k;                       /* AUTO's last choice: for this K ... */
    uint64_t auto_stage;                 /* ... and this many units (up to the first 32) ... */
    mcs_spectrum_path auto_path;         /* ... it chose this path (0 k: none yet) */
    mcs_dft plan;                        /* DFT plan for N, twiddle table shared with the kernels */
    double mean_re[MCS_SPECTRUM_HALF];   /* weighted running mean of Re S_k */
    double mean_im[MCS_SPECTRUM_HALF];   /* weighted running mean of Im S_k */
    double m2_s[MCS_SPECTRUM_HALF];      /* sum over units of w |S_k - mean|^2 (weighted Welford) */
    double mean_pow[MCS_SPECTRUM_HALF];  /* weighted running mean of |S_k|^2 */
    double m2_pow[MCS_SPECTRUM_HALF];    /* weighted Welford M2 of |S_k|^2 */
    double open_sum[MCS_MAX_N];          /* open batch: sum over its trials of s_n */
    double open_pairs[2 * (MCS_MAX_N)];  /* open batch: h(d) at [N + n_j' - n_j] (d mod N) */
    double s[MCS_MAX_N];                 /* scratch: dense s of the current trial, 0 between calls */
    double re[MCS_SPECTRUM_HALF];        /* scratch: S_k (or a batch's means) */
    double im[MCS_SPECTRUM_HALF];
    double pw[MCS_SPECTRUM_HALF];        /* scratch: a batch's mean |S_k|^2 */
    size_t chunk_bins[MCS_SPECTRUM_CHUNK];   /* scratch: bins of binned points */
    double chunk_weights[MCS_SPECTRUM_CHUNK];
} mcs_spectrum;

/* Empties the accumulator and builds its plan for n bins.
 * MCS_ERR_NULL, MCS_ERR_N_RANGE (n = 0 or n > MCS_MAX_N). *acc untouched on error. */
mcs_status mcs_spectrum_init(mcs_spectrum *acc, size_t n);

/* Chooses the path for later sparse trials (tests and benches force one).
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_KIND (unknown path). */
mcs_status mcs_spectrum_set_path(mcs_spectrum *acc, mcs_spectrum_path path);

/* Fixes the PAIR path's batch size at batch trials (1..MCS_SPECTRUM_BATCH_LIMIT),
 * or 0 to return to the batch rule. Affects batches opened later (an open
 * batch closes at the new size). MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_K_RANGE
 * (batch above the limit). */
#define MCS_SPECTRUM_BATCH_LIMIT (UINT64_C(1) << 32)
mcs_status mcs_spectrum_set_batch(mcs_spectrum *acc, uint64_t batch);

/* Closes the open PAIR batch now, as a unit of the trials it holds (nothing
 * to do without one). Read-outs are then O(1) again. MCS_ERR_NULL, MCS_ERR_UNINIT. */
mcs_status mcs_spectrum_flush(mcs_spectrum *acc);

/* Adds one trial in sparse form, e.g. from mcs_pattern_draw: s_n is the sum
 * of weights[j] over the j with bins[j] = n (eq. 38). bins[k] in [0, N),
 * weights[k] finite and >= 0, summing to at most MCS_SPECTRUM_MAX_SUM.
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_K_RANGE (k = 0), MCS_ERR_COUNT (the
 * count at MCS_SPECTRUM_MAX_COUNT), MCS_ERR_BIN_RANGE, MCS_ERR_NOT_FINITE,
 * MCS_ERR_NEGATIVE, MCS_ERR_MAGNITUDE (the weights' sum above
 * MCS_SPECTRUM_MAX_SUM), MCS_ERR_ALIAS (an array inside *acc).
 * *acc untouched on error. */
mcs_status mcs_spectrum_add_bins(mcs_spectrum *acc, size_t k, const size_t *bins,
                                 const double *weights);

/* Adds one trial given densely: s[n], n equal to the accumulator's N, values
 * finite and >= 0 with sum at most MCS_SPECTRUM_MAX_SUM. Always the FFT path.
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_MISMATCH (n), MCS_ERR_ALIAS (s inside
 * *acc), MCS_ERR_COUNT (count full), MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE,
 * MCS_ERR_MAGNITUDE. *acc untouched on error. */
mcs_status mcs_spectrum_add_dense(mcs_spectrum *acc, size_t n, const double *s);

/* Adds one trial of caller points (a renderer's own samples): points[k] in
 * [0,1) land in bin floor(N x); weights[k] finite and >= 0, or NULL for all 1
 * (pass 1/p of the bin under importance sampling); the sum as for
 * mcs_spectrum_add_bins. MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_K_RANGE,
 * MCS_ERR_COUNT, MCS_ERR_POINT_RANGE, MCS_ERR_NOT_FINITE, MCS_ERR_NEGATIVE,
 * MCS_ERR_MAGNITUDE, MCS_ERR_ALIAS. *acc untouched on error. */
mcs_status mcs_spectrum_add_points(mcs_spectrum *acc, size_t k, const double *points,
                                   const double *weights);

/* mcs_spectrum_add_points for float points (a renderer's samples, read in
 * place, never copied): each x_j widens to double exactly, so every path
 * gives the bits of mcs_spectrum_add_points on the widened points (a float
 * just below 1.0f is in [0,1); 1.0f is not). Statuses as
 * mcs_spectrum_add_points. */
mcs_status mcs_spectrum_add_points_f(mcs_spectrum *acc, size_t k, const float *points,
                                     const double *weights);

/* dst <- dst union src (Chan et al. on the units, open batches summed): the
 * same means as one pass over both trial streams, to rounding, and standard
 * errors over the units of both. src unchanged; dst == src is allowed.
 * MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_MISMATCH (different N), MCS_ERR_ALIAS
 * (src and dst overlapping without being the same object), MCS_ERR_COUNT
 * (the counts would pass MCS_SPECTRUM_MAX_COUNT). dst untouched on error. */
mcs_status mcs_spectrum_merge(mcs_spectrum *dst, const mcs_spectrum *src);

/* Number of trials added. MCS_ERR_NULL, MCS_ERR_UNINIT. */
mcs_status mcs_spectrum_count(const mcs_spectrum *acc, uint64_t *count);

/* Number of units the standard errors rest on (closed units plus the open
 * batch, if any). MCS_ERR_NULL, MCS_ERR_UNINIT. */
mcs_status mcs_spectrum_units(const mcs_spectrum *acc, uint64_t *units);

/* <S_k> for freq in [0, N) (eq. 15 measured). MCS_ERR_NULL, MCS_ERR_UNINIT,
 * MCS_ERR_FREQ_RANGE, MCS_ERR_EMPTY (no trials), MCS_ERR_NOT_FINITE (only
 * for an object whose bytes were overwritten: accepted input keeps every
 * read-out finite). Outputs untouched on error. */
mcs_status mcs_spectrum_mean(const mcs_spectrum *acc, size_t freq, double *re, double *im);

/* Standard error of <S_k>: sqrt(M2 / (U - 1) / T) with M2 the weighted
 * spread |S_k - <S_k>|^2 (real and imaginary parts together). MCS_ERR_EMPTY
 * for fewer than 2 units; otherwise as mcs_spectrum_mean. */
mcs_status mcs_spectrum_mean_stderr(const mcs_spectrum *acc, size_t freq, double *stderr_out);

/* <|S_k|^2> for freq in [0, N): the power spectrum (eq. 14, 23).
 * Statuses as mcs_spectrum_mean. */
mcs_status mcs_spectrum_power(const mcs_spectrum *acc, size_t freq, double *power);

/* Standard error of <|S_k|^2>. MCS_ERR_EMPTY for fewer than 2 units. */
mcs_status mcs_spectrum_power_stderr(const mcs_spectrum *acc, size_t freq, double *stderr_out);

/* Every stored frequency k = 0..N/2 at once (a renderer's or a wrapper's
 * read-out): mean_re[k] + i mean_im[k] = <S_k>, mean_stderr[k], power[k] =
 * <|S_k|^2> and power_stderr[k], each bit for bit what mcs_spectrum_mean,
 * _mean_stderr, _power and _power_stderr return at freq = k (k > N/2 is
 * conj of N - k: s is real). Caller arrays of n_out doubles, n_out equal to
 * N/2 + 1 (else MCS_ERR_MISMATCH); exactly n_out entries are written to each
 * array given. Any array may be NULL when not wanted, not all of them
 * (MCS_ERR_NULL). The arrays must not overlap one another or *acc
 * (MCS_ERR_ALIAS). MCS_ERR_NULL, MCS_ERR_UNINIT, MCS_ERR_EMPTY (no trials,
 * or fewer than 2 units when a standard error is asked), MCS_ERR_NOT_FINITE
 * (an overwritten object, as the per-frequency calls). Every value is
 * checked before any is written: on error no array changes. O(N) (O(N^2)
 * with an open PAIR batch, as N calls of the per-frequency read-outs;
 * mcs_spectrum_flush makes it O(N) again). */
mcs_status mcs_spectrum_read_all(const mcs_spectrum *acc, size_t n_out, double *mean_re,
                                 double *mean_im, double *mean_stderr, double *power,
                                 double *power_stderr);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_SPECTRUM_H */
