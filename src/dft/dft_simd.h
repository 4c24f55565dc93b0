/* The dft module's vectorisable kernel, compiled twice by dft.c (simd.h):
 * the direct sum over the non-zero s_n by block phases (phase_block.h).
 * Included only by dft.c, with KERNEL defined. */

#define MCS_PHASE_BLOCK_ 8u
#define MCS_PHASE_BLOCK_RE_
#include "phase_block.h"
#undef MCS_PHASE_BLOCK_RE_
#undef MCS_PHASE_BLOCK_

/* acc_re[k] (+ i acc_im[k]) = sum_n s_n e^{-2 pi i k n/N} for k < 8 blocks,
 * accumulated over passes of up to MCS_DFT_CHUNK non-zero bins; acc_im NULL:
 * real parts only. The accumulators come zeroed. */
static void KERNEL(direct_sums)(mcs_dft *plan, const double *s, double *acc_re, double *acc_im)
{
    const size_t n = plan->n, blocks = (n / 2u + 8u) / 8u;
    const double *ct = plan->cos_table, *st = plan->sin_table;
    const mcs_phase_ctx_ ctx = mcs_phase_ctx_of_(plan);
    size_t b = 0;
    for (;;) {
        size_t count = 0;
        for (; b < n && count < MCS_DFT_CHUNK; ++b) {
            const double w = s[b];
            if (w == 0.0)
                continue;
            double *pr = plan->direct_phase + count * 16u, *pi = pr + 8;
            size_t i = 0u;
            for (size_t r = 0; r < 8u; ++r) {
                pr[r] = w * ct[i];
                pi[r] = -w * st[i];
                i += b;
                i = i >= n ? i - n : i;
            }
            plan->direct_index[count] = 0u;
            plan->direct_step[count] = (8u * b) % n; /* exact: b < N */
            ++count;
        }
        if (count == 0u)
            return;
        if (acc_im == NULL)
            KERNEL(phase_block_re)(&ctx, count, blocks, acc_re);
        else
            KERNEL(phase_block)(&ctx, count, blocks, 1, acc_re, acc_im);
    }
}
