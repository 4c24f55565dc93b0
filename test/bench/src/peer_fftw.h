/* The FFTW peer: the loop a careful C user would write with FFTW instead of
 * mcspec. Per trial: draw K samples with the reference PCG32 (pcg32_ref.h),
 * scatter them into a dense s, one r2c transform (planned once per N with
 * FFTW_MEASURE), then per frequency k = 0..N/2 running sums of Re S_k, Im S_k,
 * |S_k|^2 and |S_k|^4 with S_k normalised by 1/sqrt(N) (eq. 7): the same
 * read-outs as mcs_spectrum (<S_k>, its standard error, <|S_k|^2>, its
 * standard error), formed from the sums at the end.
 *
 * Built with FFTW only when fftw3 is available (BENCH_HAVE_FFTW=1); without
 * it the contender reports itself unavailable. */
#ifndef BENCH_PEER_FFTW_H
#define BENCH_PEER_FFTW_H

#include "harness.h"

/* 1 if this build has the FFTW peer. */
int bench_fftw_available(void);

/* FFTW's version string, or "not available". */
const char *bench_fftw_version(void);

/* The FFTW peer as a contender (unavailable without FFTW). */
bench_contender bench_fftw_contender(void);

/* Frees FFTW's plans and buffers (at exit). */
void bench_fftw_cleanup(void);

#endif /* BENCH_PEER_FFTW_H */
