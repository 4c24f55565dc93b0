/* Spectrum output of the mcspec command: one row per frequency k = 0..N/2,
 * printed as an aligned table or as CSV, and the same rows feed the plots.
 * Shared by every subcommand that shows a spectrum (spectrum, pattern, and
 * anything that shows a saved accumulator). */
#ifndef MCSPEC_CLI_OUTPUT_H
#define MCSPEC_CLI_OUTPUT_H

#include <stddef.h>

#include "mcspec.h"
#include "predict.h"

/* CSV headers, exactly. */
#define CLI_SPECTRUM_CSV_HEADER "freq,mean_re,mean_im,mean_stderr,power,power_stderr"
#define CLI_PREDICTION_CSV_HEADER ",exact,closed,z_exact,z_closed"

/* One frequency. NaN marks a value that does not exist (a standard error of
 * a single trial, a prediction the theory does not give). */
typedef struct {
    size_t freq;
    double mean_re, mean_im, mean_stderr; /* <S_k> and its standard error */
    double power, power_stderr;           /* <|S_k|^2> and its standard error */
    double exact, closed;                 /* predictions of <|S_k|^2> */
    double z_exact, z_closed;             /* (power - prediction) / stderr */
} cli_spectrum_row;

/* rows[0..N/2] from acc (at least one trial). pred may be NULL (no
 * predictions); scale is the size of a typical power value (K/N), below
 * 1e-9 of which a difference counts as rounding in the z-scores. *nrows set
 * to N/2 + 1; rows holds CLI_HALF_MAX entries. Returns 0 or CLI_EXIT_FAIL. */
int cli_spectrum_rows(const char *cmd, const mcs_spectrum *acc, const cli_prediction *pred,
                      double scale, cli_spectrum_row *rows, size_t *nrows);

/* Prints rows: CSV (the header, then one line per row, nothing else) or a
 * table (a header line, then aligned rows). with_prediction adds the
 * exact, closed and z columns. */
void cli_print_spectrum(int csv, int with_prediction, const cli_spectrum_row *rows,
                        size_t nrows);

/* A line of text above a table (nothing in CSV mode). */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
void cli_note(int csv, const char *fmt, ...);

#endif /* MCSPEC_CLI_OUTPUT_H */
