/* Plain C floors written in the bench, against which mcspec's primal kernels
 * are measured: three ways a C user would accumulate the sums of the moment
 * accumulator (sum over trials of s_n, and of s_m s_n for m <= n), and a bare
 * PCG32 bounded draw per sample for the pattern draw. */
#ifndef BENCH_FLOORS_H
#define BENCH_FLOORS_H

#include <stddef.h>
#include "harness.h"

#define BENCH_POOL_TRIALS 64u /* trials in a pool: also the batch of the X^T X loop */
#define BENCH_POOL_MAX_N 64u
#define BENCH_POOL_MAX_K 64u

/* Pre-drawn trials in sparse form, cycled through by the moment contenders so
 * that only the accumulation is timed. */
typedef struct {
    size_t n, k;
    size_t bins[BENCH_POOL_TRIALS][BENCH_POOL_MAX_K];
    double weights[BENCH_POOL_TRIALS][BENCH_POOL_MAX_K];
} bench_pool;

/* The three moment floors over pool, in out[0..3): "pairs" (every pair of
 * samples, O(K^2)), "dense" (dense s, then the upper triangle s_m s_n, O(N^2))
 * and "XtX" (the 64 trials of the pool as a 64 x N matrix X, upper triangle of
 * X^T X by dot products, one call per 64 trials). Read-out index i < N*N
 * (i = m N + n, m <= n) gives the mean of s_m s_n, i = N*N + n the mean of
 * s_n. Returns 3. */
size_t bench_moment_floors(bench_contender *out, const bench_pool *pool);

/* A bare draw: one pcg32_boundedrand_r(N) per sample, K per trial. */
bench_contender bench_bare_draw_contender(void);

#endif /* BENCH_FLOORS_H */
