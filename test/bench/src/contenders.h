/* mcspec's own contenders for the spectra grid: the spectrum accumulator on
 * AUTO and on each forced path, and the reference figures (the draw alone,
 * the bare transform, the pair-histogram autocorrelation). Each trial is a
 * fresh pattern draw followed by the add, as a user's loop would be. */
#ifndef BENCH_CONTENDERS_H
#define BENCH_CONTENDERS_H

#include <stddef.h>
#include "floors.h"
#include "harness.h"

/* Number of spectrum paths measured (AUTO first, then each forced path). */
size_t bench_spectrum_path_count(void);

/* Fills out[0 .. bench_spectrum_path_count()) with the spectrum contenders,
 * AUTO at index 0. Returns the count. */
size_t bench_spectrum_contenders(bench_contender *out);

/* Fills out[0..3) with the reference figures: "draw" (mcs_pattern_draw
 * alone), "dft" (mcs_dft_real_half of a dense s alone) and "autocorr"
 * (draw + mcs_autocorr_add_bins: the O(K^2) pair route, no standard errors).
 * Returns 3. */
size_t bench_reference_contenders(bench_contender *out);

/* Fills pool with BENCH_POOL_TRIALS trials of cell drawn by mcs_pattern_draw
 * (cell->n <= BENCH_POOL_MAX_N, cell->k <= BENCH_POOL_MAX_K). */
int bench_pool_fill(bench_pool *pool, const bench_cell *cell);

/* mcs_moment_add_bins over the pool's trials in turn; read-outs indexed as
 * bench_moment_floors' (mcs_moment_second and mcs_moment_mean_s). */
bench_contender bench_moment_contender(const bench_pool *pool);

#endif /* BENCH_CONTENDERS_H */
