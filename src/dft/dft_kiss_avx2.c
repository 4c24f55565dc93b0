/* KissFFT's transform compiled a second time for AVX2 (simd.h): the vendored
 * kiss_fft.c, byte for byte, included between MCS_AVX2_BEGIN and
 * MCS_AVX2_END under other names. dft.c calls mcs_kiss_fft_avx2 on the state
 * the baseline mcs_kiss_fft_alloc placed (the same struct: same source, same
 * configuration) when a plan's simd flag is set.
 *
 * Same bits as the baseline copy: the same IEEE operations in the same
 * order (ISO C mode contracts nothing into an FMA, and the avx2 target does
 * not enable FMA); only the instruction selection differs, about 13 % faster
 * for gcc 12 at the transform lengths of the bench (test_dft compares the
 * two copies bit for bit). On other targets this file compiles to nothing. */
#include "core/simd.h"

#if MCS_AVX2_CLONES
/* The system headers KissFFT includes, first: declarations from them must
 * not take the target attribute. */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#undef kiss_fft
#undef kiss_fft_alloc
#undef kiss_fft_stride
#undef kiss_fft_cleanup
#undef kiss_fft_next_fast_size
#define kiss_fft mcs_kiss_fft_avx2
#define kiss_fft_alloc mcs_kiss_fft_alloc_avx2
#define kiss_fft_stride mcs_kiss_fft_stride_avx2
#define kiss_fft_cleanup mcs_kiss_fft_cleanup_avx2
#define kiss_fft_next_fast_size mcs_kiss_fft_next_fast_size_avx2
/* Declared under the new names, outside the target region. */
#include "kiss_fft.h"

#include "dft_kiss_avx2.h"

MCS_AVX2_BEGIN
/* A second copy of the vendored source, on purpose (see above). */
#include "kiss_fft.c" /* NOLINT(bugprone-suspicious-include) */
MCS_AVX2_END
#else
/* ISO C wants a declaration in every translation unit. */
typedef int mcs_dft_kiss_avx2_unused_;
#endif
