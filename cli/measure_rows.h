/* The rows of mcspec pcf, integrate, discrepancy and stats, shared with mcspec show
 * of their records (record_show.c), so a record prints what its run did. */
#ifndef MCSPEC_CLI_MEASURE_ROWS_H
#define MCSPEC_CLI_MEASURE_ROWS_H

#include <stddef.h>

#include "mcspec.h"

/* The exact E[D^2] per measure of sets of kind name (mcspec sample's names)
 * in dim dimensions with k points, NaN where not known: random (any
 * dimension), 2D jittered over the strata mcs_pattern2d_init chooses, 1D
 * stratified, and the 1D Owen-scrambled base-2 kinds at K = 2^m
 * (cmd_discrepancy.c says why). name NULL: a point file, every entry NaN. */
void cli_discrepancy_exact(const char *name, size_t dim, size_t k,
                           double exact[MCS_DISCREPANCY_MEASURES]);

/* The CSV header (csv) or the table's column header, then one row per
 * measure (the star row only when every set had it), with exact beside. */
void cli_discrepancy_rows(int csv, const mcs_discrepancy *acc,
                          const double exact[MCS_DISCREPANCY_MEASURES]);

/* The exact expectation per spacing statistic for sets of kind name, NaN
 * where not known (random points only: mcs_spacing_exact_random). */
void cli_spacing_exact(const char *name, size_t dim, size_t k,
                       double exact[MCS_SPACING_STATISTICS]);

/* The CSV header (csv) or the table's column header, then the distance rows
 * of acc with exact beside. */
void cli_spacing_rows(int csv, const mcs_spacing *acc, const double exact[MCS_SPACING_STATISTICS]);

/* A stats row: v = value, stderr, exact; the table adds z. */
void cli_stats_row(int csv, const char *name, const double *v);

/* A pcf row: v = r, pcf, pcf_stderr, exact; the table adds z (cmd_pcf.c). */
void cli_pcf_row(int csv, const double *v);

/* The published convergence rate of integrand family f in dim dimensions:
 * random points -1; jittered -(1 + 2/dim) smooth, -(1 + 1/dim) for the
 * discontinuous families (cmd_integrate.c). */
double cli_integrate_rate(size_t dim, int f, int jittered);

/* An integrate row: family, k ("" for no one K), v = mse, mse_stderr,
 * exact, predicted, predicted_tail, freq, sets, slope, rate_random,
 * rate_jittered (NaN: empty); the table adds z after exact. */
void cli_integrate_row(int csv, const char *family, const char *k, const double *v);

#endif /* MCSPEC_CLI_MEASURE_ROWS_H */
