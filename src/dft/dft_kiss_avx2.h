/* KissFFT's forward transform compiled for AVX2 (src/dft/dft_kiss_avx2.c), for
 * dft.c: the same bits as mcs_kiss_fft, on a state placed by
 * mcs_kiss_fft_alloc. Only where MCS_AVX2_CLONES (simd.h). */
#ifndef MCSPEC_DFT_KISS_AVX2_H
#define MCSPEC_DFT_KISS_AVX2_H

#include "kiss_fft.h"

void mcs_kiss_fft_avx2(kiss_fft_cfg cfg, const kiss_fft_cpx *fin, kiss_fft_cpx *fout);

#endif /* MCSPEC_DFT_KISS_AVX2_H */
