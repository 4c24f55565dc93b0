/* The block-phase kernel of the sparse DFT, shared by the dft module's direct
 * sum and the spectrum's SPARSE path, and included by their SIMD bodies
 * (dft_simd.h, spectrum_simd.h) so that it is compiled into each copy.
 *
 * S_k = sum_j w_j e^{-2 pi i k n_j/N} for the 8 frequencies k0 + r of a
 * block: e^{-2 pi i (k0 + r) n_j/N} = e^{-2 pi i k0 n_j/N} e^{-2 pi i r n_j/N},
 * so per sample the twiddle table is read once per block (at the index
 * k0 n_j mod N, advanced by 8 n_j mod N each block: exact integers) and
 * multiplied by the sample's in-block phases w_j e^{-2 pi i r n_j/N},
 * computed once per trial: (c - i s)(pr + i pi) = (c pr + s pi) + i (c pi - s pr).
 * The phases of sample j are phase[16 j .. 16 j + 8) (real) and
 * phase[16 j + 8 .. 16 j + 16) (imaginary). The 16 accumulators are named
 * scalars so that they stay in registers. One call does `blocks` blocks and
 * adds (or with add = 0 stores) their sums to out_re, out_im: a leaf
 * function, so no vector value lives across a call (which the AVX2 copy
 * would spill to a realigned, dynamic frame) and the call costs nothing
 * per block.
 *
 * Requires KERNEL() and MCS_PHASE_BLOCK_ (8); MCS_PHASE_BLOCK_RE_ adds the
 * real-only variant. */

/* One lane r of the block: the real part always, the imaginary part when
 * the constant want_im asks for it (the other copy drops it entirely). */
#define MCS_LANE_(r)                                                                         \
    do {                                                                                     \
        ar##r += c * pr[r] + s * pi[r];                                                      \
        if (want_im)                                                                         \
            ai##r += c * pi[r] - s * pr[r];                                                  \
    } while (0)

/* The kernel, written once: inlined into the two leaf functions below with
 * want_im a constant, so each is the loop it names. */
static MCS_ALWAYS_INLINE void KERNEL(phase_block_body)(const mcs_phase_ctx_ *ctx, size_t count,
                                                       size_t blocks, int add,
                                                       double *restrict out_re,
                                                       double *restrict out_im, int want_im)
{
    const size_t n = ctx->n;
    const double *ct = ctx->cos_table, *st = ctx->sin_table, *phase = ctx->phase;
    size_t *index = ctx->index;
    const size_t *step = ctx->step;
    for (size_t blk = 0; blk < blocks; ++blk) {
        double ar0 = 0.0, ar1 = 0.0, ar2 = 0.0, ar3 = 0.0, ar4 = 0.0, ar5 = 0.0, ar6 = 0.0;
        double ar7 = 0.0, ai0 = 0.0, ai1 = 0.0, ai2 = 0.0, ai3 = 0.0, ai4 = 0.0, ai5 = 0.0;
        double ai6 = 0.0, ai7 = 0.0;
        for (size_t j = 0; j < count; ++j) {
            const size_t i = index[j];
            const double c = ct[i], s = st[i];
            const double *restrict pr = phase + j * 2u * MCS_PHASE_BLOCK_;
            const double *restrict pi = pr + MCS_PHASE_BLOCK_;
            MCS_LANE_(0);
            MCS_LANE_(1);
            MCS_LANE_(2);
            MCS_LANE_(3);
            MCS_LANE_(4);
            MCS_LANE_(5);
            MCS_LANE_(6);
            MCS_LANE_(7);
            const size_t next = i + step[j];
            index[j] = next >= n ? next - n : next;
        }
        double *re = out_re + blk * MCS_PHASE_BLOCK_;
        double *im = want_im ? out_im + blk * MCS_PHASE_BLOCK_ : NULL;
        for (size_t r = 0; !add && r < MCS_PHASE_BLOCK_; ++r) {
            re[r] = 0.0;
            if (want_im)
                im[r] = 0.0;
        }
        re[0] += ar0, re[1] += ar1, re[2] += ar2, re[3] += ar3;
        re[4] += ar4, re[5] += ar5, re[6] += ar6, re[7] += ar7;
        if (want_im) {
            im[0] += ai0, im[1] += ai1, im[2] += ai2, im[3] += ai3;
            im[4] += ai4, im[5] += ai5, im[6] += ai6, im[7] += ai7;
        }
    }
}

MCS_NOINLINE static void KERNEL(phase_block)(const mcs_phase_ctx_ *ctx, size_t count,
                                             size_t blocks, int add, double *restrict out_re,
                                             double *restrict out_im)
{
    KERNEL(phase_block_body)(ctx, count, blocks, add, out_re, out_im, 1);
}

#if defined(MCS_PHASE_BLOCK_RE_)
/* The real parts only (always added): half the work, for a transform whose
 * imaginary parts are not wanted (the pair histogram's); compiled where
 * asked for. */
MCS_NOINLINE static void KERNEL(phase_block_re)(const mcs_phase_ctx_ *ctx, size_t count,
                                                size_t blocks, double *restrict out_re)
{
    KERNEL(phase_block_body)(ctx, count, blocks, 1, out_re, NULL, 0);
}
#endif

#undef MCS_LANE_
