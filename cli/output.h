/* Spectrum output of the mcspec command: one row per frequency k = 0..N/2,
 * printed as an aligned table or as CSV, and the same rows feed the plots.
 * Shared by every subcommand that shows a spectrum (spectrum, pattern, and
 * anything that shows a saved accumulator). */
#ifndef MCSPEC_CLI_OUTPUT_H
#define MCSPEC_CLI_OUTPUT_H

#include <stddef.h>

#include "mcspec.h"
#include "predict.h"

/* *v if the call that wrote it returned MCS_OK, else NaN (no value). A
 * pointer, not a value: the call that writes *v is another argument of the
 * same call, and C leaves their order open. */
double cli_or_nan(mcs_status st, const double *v);

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

/* ---- Point-set spectra (no binning): 1D, 2D, 2D radial ----------------------- */

#define CLI_POINTSET_CSV_HEADER "freq,power,power_stderr"
#define CLI_POINTSET2D_CSV_HEADER "kx,ky,power,power_stderr"
#define CLI_RADIAL_CSV_HEADER "radius,power,power_stderr,anisotropy_db"
#define CLI_EXACT_CSV_HEADER ",exact,z_exact"

/* Rows per frequency f = 0..F (1D), per wave vector, ky = -F..F outer and
 * kx = -F..F inner (2D), or per annulus r = 0..F (radial). */
typedef enum { CLI_PS_1D, CLI_PS_2D, CLI_PS_RADIAL } cli_ps_layout;

/* One row. NaN marks a value that does not exist. */
typedef struct {
    long kx, ky;           /* 1D: the frequency in kx; 2D: the wave vector; radial: r in kx */
    double power, power_stderr;
    double anisotropy_db;  /* radial: psa's anisotropy of the annulus */
    double exact, z_exact; /* the exact <P> and (power - exact) / power_stderr */
} cli_ps_row;

/* Rows a layout has for cutoff F. */
size_t cli_ps_row_count(cli_ps_layout layout, size_t freq_max);

/* The rows of a 1D (acc a mcs_pointset) or 2D (a mcs_pointset2d, CLI_PS_2D
 * or CLI_PS_RADIAL) point-set spectrum with at least one trial, exact NaN;
 * rows holds cli_ps_row_count entries. Returns 0 or CLI_EXIT_FAIL. */
int cli_ps_rows(const char *cmd, cli_ps_layout layout, const void *acc, cli_ps_row *rows,
                size_t *nrows);

/* Sets z_exact of every row from its exact value; a difference below 1e-9
 * of max(|exact|, scale) is rounding (as cli_spectrum_rows). */
void cli_ps_rows_z(cli_ps_row *rows, size_t nrows, double scale);

/* Prints rows: CSV (the header, then the rows, nothing else) or a table;
 * with_exact adds the exact and z_exact columns. */
void cli_print_ps(int csv, cli_ps_layout layout, int with_exact, const cli_ps_row *rows,
                  size_t nrows);

/* The normalised frequency columns appended after the others: the integer
 * frequency over norm (sqrt(K)), named with "_norm" ("freq_norm",
 * "kx_norm,ky_norm", "radius_norm"). */
#define CLI_NORM_SUFFIX "_norm"

/* cli_print_ps with those columns when norm > 0 (none when 0). */
void cli_print_ps_norm(int csv, cli_ps_layout layout, int with_exact, double norm,
                       const cli_ps_row *rows, size_t nrows);

/* The 2D rows plane[nplane] (CLI_PS_2D, (2F + 1)^2 of them) as a PFM image
 * at path, written atomically: "Pf", side 2F + 1 both ways, scale -1.0
 * (little-endian), then <P> as float32 per pixel, the first scan line
 * ky = -F (the bottom of the image, as the format says), kx = -F first in a
 * line; DC included. Returns 0 or an exit status after a message. */
int cli_write_pfm(const char *cmd, const char *path, const cli_ps_row *plane, size_t nplane);

/* 1D rows as spectrum rows for cli_plot_spectrum (power, its standard error,
 * exact; the rest NaN). */
void cli_ps_as_spectrum(const cli_ps_row *rows, size_t nrows, cli_spectrum_row *out);

/* Exact <P> of a 2D point-set spectrum: at a wave vector and per annulus
 * (NaN where there is none), and the size of a typical value for the
 * z-scores' rounding floor. */
typedef struct {
    const void *ctx;
    double (*at)(const void *ctx, long kx, long ky);
    double (*radial)(const void *ctx, size_t r);
    double scale;
} cli_exact2d;

/* Radial annuli of width W other than the library's unit annuli: count
 * annuli r = b W, b = 0..count-1, their mean, standard error and anisotropy
 * (NaN: none) from at. */
typedef struct {
    size_t width, count;
    const void *ctx;
    void (*at)(const void *ctx, size_t b, double *mean, double *se, double *aniso);
} cli_ps_bins;

/* How to report a point-set spectrum. */
typedef struct {
    int csv, radial;          /* CSV only; 2D: the annuli instead of every wave vector */
    const char *plot;         /* the figure's path (plot.h), or NULL */
    int log_y;                /* the figure's profile on a log y axis (--log) */
    const char *title, *subtitle; /* the figure's title lines */
    const char *exact_label;  /* the exact series' legend, when exact is set */
    const cli_exact2d *exact; /* exact values and z-scores, or NULL: no such columns */
    const char *const *notes; /* lines above the table (NULL-terminated; NULL: none) */
} cli_ps_report;

/* What `mcspec spectrum` adds to a report (cli_report_pointset*_with). */
typedef struct {
    double norm;             /* > 0: the normalised columns, frequency / norm; 0: none */
    const cli_ps_bins *bins; /* the annuli of the radial rows (NULL: width 1, the library's) */
    const char *pfm;         /* 2D: also write the mean periodogram as a PFM image here */
} cli_ps_extra;

/* Reports acc (a mcs_pointset2d with a trial): draws the figure first if
 * asked (so a failed plot prints nothing), then the notes and the rows of
 * rep->radial. Returns 0 or an exit status after a message. */
int cli_report_pointset2d(const char *cmd, const cli_ps_report *rep, const mcs_pointset2d *acc);
int cli_report_pointset2d_with(const char *cmd, const cli_ps_report *rep,
                               const cli_ps_extra *extra, const mcs_pointset2d *acc);

/* The same for a 1D point-set spectrum (a mcs_pointset with a trial): the
 * figure is the power spectrum f >= 1 (cli_plot_spectrum); no exact values
 * (rep->exact must be NULL). */
int cli_report_pointset(const char *cmd, const cli_ps_report *rep, const mcs_pointset *acc);
int cli_report_pointset_with(const char *cmd, const cli_ps_report *rep, const cli_ps_extra *extra,
                             const mcs_pointset *acc);

/* The values of one line after its first field: ",v" CSV fields or " v"
 * table columns of width 13 (NaN: empty or "-"), then the newline. */
void cli_print_values(int csv, const double *v, size_t nv);

/* A line of text above a table (nothing in CSV mode). */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
void cli_note(int csv, const char *fmt, ...);

#endif /* MCSPEC_CLI_OUTPUT_H */
