/* The cost model behind MCS_SPECTRUM_PATH_AUTO and the PAIR path's batch
 * rule (spectrum.h).
 *
 * Modelled time of one trial of K samples on N bins, H the stored
 * frequencies N/2 + 1 padded to whole blocks of 8, in nanoseconds:
 *
 *   SPARSE  C_TERM K H + C_PHASE K + C_UPDATE H
 *   FFT     dft(N, K) + C_SCATTER K + C_UPDATE H
 *   PAIR    C_PAIR K (K - 1) / 2 + C_SINGLE K + close(N) / B(K)
 *
 * with dft(N, nnz) the dft module's model of one transform (dft.c:
 * N log2 N terms for KissFFT or FFTW, nnz H for the direct sum), close(N)
 * = two such transforms (of the pair histogram and of the sums, with as many
 * non-zero entries as the batch can have) + C_UPDATE H + C_FOLD N the cost
 * of closing a batch, and B(K) the batch size the rule gives a trial of K
 * samples now. Costs every
 * path shares (argument checks, the call) are left out: they do not move
 * the choice.
 *
 * The constants were fitted to `make spectrum-costs` (test/bench/
 * spectrum_costs.c), which times each forced path on pre-drawn trials over
 * a grid of N in {64, 256, 1024, 4096, 1000, 3375, 4093} and K from 1 to 256
 * and prints least-squares fits, with --generic for the baseline kernels.
 * On the bench machine (AMD EPYC with AVX-512, 2 shared cores, gcc 12 -O2)
 * it gave C_PAIR 0.30-0.31, C_SINGLE 2-3, C_SCATTER 1.9, C_TERM 0.30 (AVX2)
 * and 0.45 (baseline), C_UPDATE 0.8-0.9 (AVX2) and 1.2-1.5 (baseline),
 * C_FOLD 1.4, rounded below; the DFT's own constants are in dft.c. The fits
 * are noisy on a shared machine, but only ratios matter, and only near the
 * crossovers, where the paths cost about the same anyway; make bench checks
 * that AUTO stays within 1.15x of the best forced path in every cell of its
 * grid. */
#include <math.h>

#include "dft/dft_internal.h"
#include "spectrum_internal.h"

/* The two vectorised kernels, baseline and AVX2 (acc->simd). */
static const double C_TERM[2] = {0.45, 0.30};   /* one sample at one frequency, block phases */
static const double C_UPDATE[2] = {1.20, 0.80}; /* one frequency's weighted Welford step */
#define C_PHASE 2.0    /* one sample's in-block phases */
#define C_SCATTER 2.0  /* one sample scattered into s and cleared again */
#define C_PAIR 0.31    /* one sample pair into the histogram */
#define C_SINGLE 2.0   /* one sample's sum and self term */
#define C_FOLD 1.4     /* one bin of the batch close's fold, scaling and clearing */

/* acc->cost[]: the parts that depend on N only. */
enum { SPARSE_FIXED, SPARSE_PER_K, FFT_FIXED, DFT_PER_NNZ, CLOSE_FIXED };

void mcs_spectrum_cost_init_(mcs_spectrum *acc)
{
    const double h = (double)(mcs_spectrum_blocks_(acc->n) * MCS_SPECTRUM_BLOCK);
    const double dft_empty = mcs_dft_cost_(&acc->plan, 0u);
    const double update = C_UPDATE[acc->simd != 0] * h;
    acc->cost[SPARSE_FIXED] = update;
    acc->cost[SPARSE_PER_K] = C_TERM[acc->simd != 0] * h + C_PHASE;
    acc->cost[FFT_FIXED] = dft_empty + update;
    acc->cost[DFT_PER_NNZ] = mcs_dft_cost_(&acc->plan, 1u) - dft_empty; /* direct sum only */
    acc->cost[CLOSE_FIXED] = 2.0 * dft_empty + update + C_FOLD * (double)acc->n;
    /* Batch rule (a): a batch pays for its close once its pairs cost
     * MCS_SPECTRUM_BATCH_RATIO times as much (the close of a full
     * histogram, the most it can cost), as modelled for the reference
     * machine (AVX2 kernels, the default build's DFT path for N), not for
     * this one: batch sizes decide the units and so the standard errors, and
     * with this CPU's and back end's constants the same trials made 70 units
     * with the AVX2 kernels, 60 without and 52 with FFTW. On this machine the
     * close then costs about 1/8 of the pairs give or take the ratio of the
     * two machines' speeds. */
    const double ref_empty = mcs_dft_reference_cost_(acc->n, 0u);
    const double ref_close = 2.0 * ref_empty + C_UPDATE[1] * h + C_FOLD * (double)acc->n;
    const double ref_per_nnz = mcs_dft_reference_cost_(acc->n, 1u) - ref_empty;
    const double dense = ref_close + 1.25 * ref_per_nnz * (double)acc->n;
    acc->close_work = MCS_SPECTRUM_BATCH_RATIO * dense / C_PAIR;
}

/* Modelled cost of closing a batch of b trials of k samples: on the direct
 * DFT path it grows with the non-zero entries of the two sums (the pair
 * histogram, folded onto lags up to N/2, costs half per entry: only its
 * real part is summed). */
static double close_cost(const mcs_spectrum *acc, double b, double k)
{
    const double n = (double)acc->n;
    const double pairs = fmin(0.5 * n + 1.0, b * 0.5 * k * (k - 1.0) + 1.0), bins = fmin(n, b * k);
    return acc->cost[CLOSE_FIXED] + acc->cost[DFT_PER_NNZ] * (0.5 * pairs + bins);
}

/* Rule (b): the first units are small batches. */
static int early(const mcs_spectrum *acc)
{
    return acc->units < MCS_SPECTRUM_BATCH_UNITS;
}

/* The size at which the batch rule closes a batch of trials of k samples
 * (spectrum.h), as the cost model counts it. */
static double batch_for(const mcs_spectrum *acc, size_t k)
{
    if (acc->batch != 0u)
        return (double)acc->batch;
    if (early(acc))
        return (double)MCS_SPECTRUM_BATCH_MIN;
    const double b = ceil(acc->close_work / mcs_spectrum_pair_count_(k)); /* (a) */
    if (b >= (double)MCS_SPECTRUM_BATCH_MAX) /* (c) */
        return (double)MCS_SPECTRUM_BATCH_MAX;
    return b > (double)MCS_SPECTRUM_BATCH_MIN ? b : (double)MCS_SPECTRUM_BATCH_MIN;
}

static mcs_spectrum_path cheapest(const mcs_spectrum *acc, size_t k)
{
    const double kd = (double)k, nnz = (double)(k < acc->n ? k : acc->n);
    const double sparse = acc->cost[SPARSE_FIXED] + acc->cost[SPARSE_PER_K] * kd;
    const double fft = acc->cost[FFT_FIXED] + acc->cost[DFT_PER_NNZ] * nnz + C_SCATTER * kd;
    const double b = batch_for(acc, k);
    const double pair = C_PAIR * 0.5 * kd * (kd - 1.0) + C_SINGLE * kd + close_cost(acc, b, kd) / b;
    if (pair <= sparse && pair <= fft)
        return MCS_SPECTRUM_PATH_PAIR;
    return sparse <= fft ? MCS_SPECTRUM_PATH_SPARSE : MCS_SPECTRUM_PATH_FFT;
}

/* The model depends on k and, through rule (b), on whether the first units
 * are done; the last choice is kept for the next trial of the same shape. */
mcs_spectrum_path mcs_spectrum_auto_(mcs_spectrum *acc, size_t k)
{
    const uint64_t stage = early(acc) ? acc->units : MCS_SPECTRUM_BATCH_UNITS;
    if (k != acc->auto_k || stage != acc->auto_stage) {
        acc->auto_path = cheapest(acc, k);
        acc->auto_k = k;
        acc->auto_stage = stage;
    }
    return acc->auto_path;
}

int mcs_spectrum_batch_due_(const mcs_spectrum *acc)
{
    const uint64_t c = acc->open_count;
    if (acc->batch != 0u)
        return c >= acc->batch;
    if (c < MCS_SPECTRUM_BATCH_MIN)
        return 0;
    return acc->open_work >= acc->close_work || early(acc) || c >= MCS_SPECTRUM_BATCH_MAX;
}
