/* The vectorisable kernels of the spectrum accumulator, written once and
 * compiled twice by spectrum_kernels.c: KERNEL(name) names this copy's
 * functions (name_generic for the baseline ISA, name_avx2 under a target
 * pragma on x86-64). Loops over one block of MCS_SPECTRUM_BLOCK frequencies
 * have a fixed trip count and no branches, so the compiler vectorises them
 * at -O2; every lane does the same IEEE operations in the same order in
 * both copies (no contraction into FMA: ISO C mode), so the copies give the
 * same bits and the choice between them is invisible in the results.
 *
 * Included only by spectrum_kernels.c, after its definitions of BLOCK,
 * CHUNK, unit_factors, and with KERNEL defined. */

#define MCS_PHASE_BLOCK_ BLOCK
#include "dft/phase_block.h"
#undef MCS_PHASE_BLOCK_

/* The update of one block from its values: x = xr + i xi, power xp. A unit
 * of weight w joining closed units of weight w_old moves each mean by f d
 * and adds g |d|^2 to its M2 (unit_factors). */
static inline void KERNEL(update_lanes)(mcs_spectrum *acc, size_t q0, const double *restrict xr,
                                        const double *restrict xi, const double *restrict xp,
                                        unit_factors u)
{
    double *restrict mr = acc->mean_re + q0, *restrict mi = acc->mean_im + q0;
    double *restrict mp = acc->mean_pow + q0;
    double *restrict m2s = acc->m2_s + q0, *restrict m2p = acc->m2_pow + q0;
    for (size_t r = 0; r < BLOCK; ++r) {
        const double dr = xr[r] - mr[r], di = xi[r] - mi[r], dp = xp[r] - mp[r];
        mr[r] += u.f * dr;
        mi[r] += u.f * di;
        mp[r] += u.f * dp;
        m2s[r] += u.g * (dr * dr + di * di);
        m2p[r] += u.g * (dp * dp);
    }
}

/* One trial's block: its power is |S_k|^2 (in acc->pw, not on the stack). */
static inline void KERNEL(update_block)(mcs_spectrum *acc, size_t q0, const double *restrict xr,
                                        const double *restrict xi, unit_factors u)
{
    double *restrict xp = acc->pw + q0;
    for (size_t r = 0; r < BLOCK; ++r)
        xp[r] = xr[r] * xr[r] + xi[r] * xi[r];
    KERNEL(update_lanes)(acc, q0, xr, xi, xp, u);
}

#if defined(MCS_DFT_FFTW) /* the FFTW back end only: spectrum_kernels.c's update_fftw */
/* Lanes of the FFT path's update from FFTW's output (update_interleaved): a
 * group of four is one AVX2 vector, and a group, not a block of eight, is
 * the unit of the pad (N = 64: 9 groups for the 33 frequencies, 10 in
 * blocks). */
#define MCS_UPDATE_GROUP_ 4u

/* One trial's update from an r2c output o of interleaved (re, im), not yet
 * scaled (the FFTW back end's, mcs_dft_fftw_out_), for the frequencies
 * q < count (a multiple of MCS_UPDATE_GROUP_; entries past N/2 are 0):
 * x = scale o, the values and operations of the split (re = scale out[2k],
 * im = scale out[2k + 1]) and update_block, in one pass that stores no S_k.
 * A leaf, as update_range. Its five update lines are update_lanes' own,
 * written out: a shared inline step over a struct of restrict pointers left
 * this loop scalar at -O2 (GCC 12). */
MCS_NOINLINE static void KERNEL(update_interleaved)(mcs_spectrum *acc, size_t count,
                                                    const double *restrict o, double scale,
                                                    unit_factors u)
{
    for (size_t q0 = 0; q0 < count; q0 += MCS_UPDATE_GROUP_) {
        const double *restrict og = o + 2u * q0;
        double *restrict mr = acc->mean_re + q0, *restrict mi = acc->mean_im + q0;
        double *restrict mp = acc->mean_pow + q0;
        double *restrict m2s = acc->m2_s + q0, *restrict m2p = acc->m2_pow + q0;
        for (size_t r = 0; r < MCS_UPDATE_GROUP_; ++r) {
            const double xr = scale * og[2u * r], xi = scale * og[2u * r + 1u];
            const double xp = xr * xr + xi * xi;
            const double dr = xr - mr[r], di = xi - mi[r], dp = xp - mp[r];
            mr[r] += u.f * dr;
            mi[r] += u.f * di;
            mp[r] += u.f * dp;
            m2s[r] += u.g * (dr * dr + di * di);
            m2p[r] += u.g * (dp * dp);
        }
    }
}
#endif

/* Blocks [b0, b1) from acc->re, acc->im (x = re + i im) and power xp, or
 * |x|^2 without xp. A leaf: no vector value lives across a call. */
MCS_NOINLINE static void KERNEL(update_range)(mcs_spectrum *acc, size_t b0, size_t b1,
                                              const double *xp, unit_factors u)
{
    for (size_t b = b0; b < b1; ++b) {
        const size_t q0 = b * BLOCK;
        if (xp != NULL)
            KERNEL(update_lanes)(acc, q0, acc->re + q0, acc->im + q0, xp + q0, u);
        else
            KERNEL(update_block)(acc, q0, acc->re + q0, acc->im + q0, u);
    }
}

/* Samples [j0, j1) of t, weights scaled by N^{-1/2} (eq. 7): the twiddle
 * index of each (k0 n_j mod N, from k0 = 0), its step BLOCK n_j mod N, and
 * its in-block phases w e^{-2 pi i r n_j/N}, r < BLOCK, as (re[8], im[8]),
 * in the plan's direct-path scratch (no transform runs meanwhile). */
static void KERNEL(sparse_setup)(mcs_spectrum *acc, const mcs_spectrum_trial_ *t, size_t j0,
                                 size_t j1)
{
    const size_t n = acc->n;
    const double *ct = acc->plan.cos_table, *st = acc->plan.sin_table;
    const double scale = 1.0 / sqrt((double)n);
    for (size_t j = j0; j < j1; ++j) {
        const size_t b = mcs_spectrum_trial_bin_(t, n, j);
        const double w = scale * mcs_spectrum_trial_weight_(t, j);
        double *pr = acc->plan.direct_phase + (j - j0) * 2u * BLOCK, *pi = pr + BLOCK;
        size_t i = 0u;
        for (size_t r = 0; r < BLOCK; ++r) {
            pr[r] = w * ct[i];
            pi[r] = -w * st[i];
            i += b;
            i = i >= n ? i - n : i;
        }
        acc->plan.direct_index[j - j0] = 0u;
        acc->plan.direct_step[j - j0] = (BLOCK * b) % n; /* exact: b < N */
    }
}

/* Blocks the fused SPARSE path sums before it updates them (64
 * frequencies: their values are still in L1 when the update reads them). */
#define MCS_FUSED_BLOCKS_ 8u

/* The SPARSE path for one trial. Up to CHUNK samples, fused: the S_k of a
 * group of blocks by block phases (one twiddle-table read per sample and
 * block, times its in-block phases), then that group's update. More samples
 * are summed chunk by chunk into acc->re, acc->im (the first chunk stores,
 * later ones add) and updated once. Pad lanes k > N/2 are zeroed so the pad
 * stays 0. */
static void KERNEL(sparse_trial)(mcs_spectrum *acc, const mcs_spectrum_trial_ *t, unit_factors u)
{
    const size_t n = acc->n, h1 = n / 2u + 1u, blocks = mcs_spectrum_blocks_(n);
    const mcs_phase_ctx_ ctx = mcs_phase_ctx_of_(&acc->plan);
    if (t->k <= CHUNK) {
        KERNEL(sparse_setup)(acc, t, 0u, t->k);
        for (size_t b0 = 0; b0 < blocks; b0 += MCS_FUSED_BLOCKS_) {
            const size_t b1 = blocks - b0 > MCS_FUSED_BLOCKS_ ? b0 + MCS_FUSED_BLOCKS_ : blocks;
            KERNEL(phase_block)(&ctx, t->k, b1 - b0, 0, acc->re + b0 * BLOCK,
                                acc->im + b0 * BLOCK);
            if (b1 == blocks)
                for (size_t q = h1; q < blocks * BLOCK; ++q)
                    acc->re[q] = acc->im[q] = 0.0;
            KERNEL(update_range)(acc, b0, b1, NULL, u);
        }
        return;
    }
    for (size_t j0 = 0; j0 < t->k; j0 += CHUNK) {
        const size_t j1 = t->k - j0 > CHUNK ? j0 + CHUNK : t->k;
        KERNEL(sparse_setup)(acc, t, j0, j1);
        KERNEL(phase_block)(&ctx, j1 - j0, blocks, j0 > 0u, acc->re, acc->im);
    }
    for (size_t q = h1; q < blocks * BLOCK; ++q)
        acc->re[q] = acc->im[q] = 0.0;
    KERNEL(update_range)(acc, 0u, blocks, NULL, u);
}
