/* Private interface of the spectrum accumulator: one trial as its paths see
 * it, the kernels (spectrum_kernels.c), the cost model of AUTO and the batch
 * rule (spectrum_cost.c). Every function here runs after the public call has
 * validated its arguments, so none can fail. */
#ifndef MCSPEC_SPECTRUM_INTERNAL_H
#define MCSPEC_SPECTRUM_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include "core/internal.h"
#include "mcspec/spectrum.h"

/* One validated trial: k samples, bin from bins[j] or, when bins is NULL,
 * floor(N x_j) of the points (double, or float widened exactly: internal.h);
 * weight weights[j], or 1 when weights is NULL. */
typedef struct {
    size_t k;
    const size_t *bins;
    mcs_points_ points;
    const double *weights;
} mcs_spectrum_trial_;

/* floor(N x_j) of a trial of points. */
static inline size_t mcs_spectrum_point_bin_(const mcs_spectrum_trial_ *t, size_t n, size_t j)
{
    /* A trial has bins or points: the public calls refuse NULL for both. */
    return mcs_point_bin_(mcs_point_(t->points, j), n); // NOLINT(clang-analyzer-core.NullDereference): see above
}

static inline size_t mcs_spectrum_trial_bin_(const mcs_spectrum_trial_ *t, size_t n, size_t j)
{
    return t->bins != NULL ? t->bins[j] : mcs_spectrum_point_bin_(t, n, j);
}

static inline double mcs_spectrum_trial_weight_(const mcs_spectrum_trial_ *t, size_t j)
{
    return t->weights != NULL ? t->weights[j] : 1.0;
}

/* Stored frequencies k = 0..N/2 rounded up to whole blocks. */
static inline size_t mcs_spectrum_blocks_(size_t n)
{
    return (n / 2u + MCS_SPECTRUM_BLOCK) / MCS_SPECTRUM_BLOCK;
}

/* Trials in the closed units (the open batch excluded). */
static inline uint64_t mcs_spectrum_closed_(const mcs_spectrum *acc)
{
    return acc->count - acc->open_count;
}

/* ---- kernels (spectrum_kernels.c) ---- */

/* The SPARSE path for one trial: S_k by block phases, each block's update
 * fused (one unit of weight 1). */
void mcs_spectrum_sparse_(mcs_spectrum *acc, const mcs_spectrum_trial_ *t);

/* spectrum.c's scan of a trial's bins and weights for an object with AVX2
 * (acc->simd): 1 when every bin is below N and no weight is negative, and
 * in *sum the weights' sum by the same four partial sums, so the same bits.
 * Only where MCS_AVX2_CLONES (simd.h). */
int mcs_spectrum_bins_ok_avx2_(size_t n, size_t k, const size_t *b, const double *w,
                               double *sum);

/* The FFT path for one trial: scatter into acc->s, one DFT, the update,
 * acc->s cleared again (one unit of weight 1). */
void mcs_spectrum_fft_(mcs_spectrum *acc, const mcs_spectrum_trial_ *t);

/* A dense trial s[N] (not inside acc) through the DFT and the update. */
void mcs_spectrum_dense_(mcs_spectrum *acc, const double *s);

/* The PAIR path: the trial's pairs and sums into the open batch. Does not
 * close it. */
void mcs_spectrum_pairs_(mcs_spectrum *acc, const mcs_spectrum_trial_ *t);

/* Closes the open batch (open_count >= 1) as one unit of weight open_count. */
void mcs_spectrum_close_(mcs_spectrum *acc);

/* The open batch's mean of S_k and of |S_k|^2 at stored frequency q, summed
 * from the open sums in O(N) (open_count >= 1). */
void mcs_spectrum_open_values_(const mcs_spectrum *acc, size_t q, double *re, double *im,
                               double *power);

/* ---- cost model and batch rule (spectrum_cost.c) ---- */

/* Fills acc->cost_fft, cost_close and close_work from acc->plan. */
void mcs_spectrum_cost_init_(mcs_spectrum *acc);

/* The path AUTO takes for a trial of k samples (its choice is cached in acc). */
mcs_spectrum_path mcs_spectrum_auto_(mcs_spectrum *acc, size_t k);

/* 1 when the open batch is due to close (the batch rule, or the fixed size). */
int mcs_spectrum_batch_due_(const mcs_spectrum *acc);

/* Sample pairs of a trial of k samples, K (K + 1) / 2, as a double. */
static inline double mcs_spectrum_pair_count_(size_t k)
{
    const double kd = (double)k;
    return 0.5 * kd * (kd + 1.0);
}

#endif /* MCSPEC_SPECTRUM_INTERNAL_H */
