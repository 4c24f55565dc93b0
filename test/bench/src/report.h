/* The bench's tables: trials/s, ratios and the targets, each verdict
 * computed from the medians of this run. */
#ifndef BENCH_REPORT_H
#define BENCH_REPORT_H

#include <stddef.h>
#include "harness.h"

/* Where each contender of the spectra grid sits in the contender list. */
typedef struct {
    size_t paths; /* [0, paths): mcspec spectrum paths, AUTO at 0 */
    size_t fftw, numpy;
    size_t draw, dft, autocorr;
    size_t count;
} bench_grid_layout;

/* One cell of the spectra grid, measured. */
typedef struct {
    bench_cell cell;
    bench_run run;
    double zmax;        /* largest |z| of a contender's <|S_1|^2> against AUTO's */
    size_t numpy_batch; /* batch size the numpy peer chose (0 if unavailable) */
} bench_grid_result;

/* Verdict counts for the closing summary. */
typedef struct {
    size_t fftw_checked, fftw_met;
    size_t numpy_checked, numpy_met;
    size_t auto_checked, auto_met;
    size_t disagree;
    size_t moment_checked, moment_met;
    size_t draw_checked, draw_met;
} bench_tally;

/* The speed targets for AUTO in a cell. */
typedef struct {
    double fftw_min;  /* AUTO / FFTW at least this */
    double numpy_min; /* AUTO / numpy at least this */
} bench_target;

bench_target bench_target_for(size_t n, size_t k);

/* Spectra grid: legend, then one row per cell (a header when the pattern
 * changes), then the reference figures of every cell from the same runs. */
void report_grid_legend(const bench_contender *list, const bench_grid_layout *lay);
void report_grid_row(const bench_grid_result *res, const bench_contender *list,
                     const bench_grid_layout *lay, bench_tally *tally);
void report_reference_table(const bench_grid_result *res, size_t count,
                            const bench_grid_layout *lay);

/* mcs_moment against the best of the plain loops: contender 0 is mcs_moment,
 * 1..count-1 the floors; max_diff is the largest |difference| of the sums
 * after one pass over the same trials. */
void report_moment_header(const bench_contender *list, size_t count);
void report_moment_row(const bench_cell *cell, const bench_run *run,
                       const bench_contender *list, double max_diff, bench_tally *tally);

/* mcs_pattern_draw (contender 0) against the bare PCG32 draw (contender 1). */
void report_draw_header(void);
void report_draw_row(const bench_cell *cell, const bench_run *run, bench_tally *tally);

void report_summary(const bench_tally *tally);

#endif /* BENCH_REPORT_H */
