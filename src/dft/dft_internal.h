/* Private interface of the dft module: the transform without its argument
 * checks, for the spectrum accumulator (which has made them already), its
 * cost for the AUTO model, and the FFTW back end's entry points. */
#ifndef MCSPEC_DFT_INTERNAL_H
#define MCSPEC_DFT_INTERNAL_H

#include <stddef.h>

#include "mcspec/dft.h"
#include "core/internal.h"

/* S_k of eq. 7 for k = 0..N/2 into re, im (im may be NULL). Preconditions,
 * which mcs_dft_real_half checks and this does not: plan set up for its N;
 * s[N] finite with sum |s_n| <= MCS_DFT_MAX_ABS_SUM (so nothing overflows
 * and the call cannot fail); re and im disjoint; none of s, re, im inside
 * *plan. s may alias re or im. */
void mcs_dft_half_(mcs_dft *plan, const double *s, double *re, double *im);

/* Modelled time of mcs_dft_half_ for this plan, in nanoseconds, when at most
 * nnz entries of s are non-zero (only the direct path depends on nnz). The
 * constants come from the bench; see the definition. */
double mcs_dft_cost_(const mcs_dft *plan, size_t nnz);

/* The same model for a plan of n bins on the reference machine, the same
 * on every CPU and back end: the default build's path for n (KissFFT or the
 * direct sum) with its AVX2 kernels. For choices whose outcome shows in the
 * results (the spectrum's batch sizes), which must not follow the machine. */
double mcs_dft_reference_cost_(size_t n, size_t nnz);

/* The block-phase kernel's view of a plan (phase_block.h): its N, twiddle
 * table and direct-path scratch. One pointer, so that the kernel's
 * arguments fit in registers (stack arguments make a frame dynamic). */
typedef struct {
    size_t n;
    const double *cos_table, *sin_table;
    double *phase;
    size_t *index;
    const size_t *step;
} mcs_phase_ctx_;

static inline mcs_phase_ctx_ mcs_phase_ctx_of_(mcs_dft *plan)
{
    mcs_phase_ctx_ c = {plan->n, plan->cos_table, plan->sin_table, plan->direct_phase,
                        plan->direct_index, plan->direct_step};
    return c;
}

/* mcs_overlap_ (1 when two byte ranges share a byte) lives in internal.h. */

/* The FFTW back end (src/dft/dft_fftw.c, built with -DMCS_DFT_FFTW). In the
 * default build these are stubs that report no plan. */
int mcs_dft_fftw_prepare_(mcs_dft *plan, size_t n); /* 1 if FFTW has a plan for n */
void mcs_dft_fftw_half_(mcs_dft *plan, const double *s, double *re, double *im, double scale);
int mcs_dft_fftw_is_ready_(size_t n); /* 1 if a plan for n was made in this process */
const char *mcs_dft_fftw_name_(void);

/* Complex entries past N/2 that mcs_dft_fftw_out_ can zero. */
#define MCS_DFT_FFTW_PAD 8u

/* The FFTW back end's r2c of s (plan->path MCS_DFT_PATH_FFTW; preconditions
 * as mcs_dft_half_) without the scale or the split: sqrt(N) S_k of eq. 7 as
 * interleaved (re, im) for k < count, count <= N/2 + 1 + MCS_DFT_FFTW_PAD,
 * Im of k = 0 and N/2 exactly 0, entries k > N/2 zero. For a caller that
 * scales and splits in its own pass over the values (the spectrum FFT path:
 * its update reads them once). Points into plan->work, valid until the next
 * transform with plan. FFTW builds (MCS_DFT_FFTW) only. */
const double *mcs_dft_fftw_out_(mcs_dft *plan, const double *s, size_t count);

#endif /* MCSPEC_DFT_INTERNAL_H */
