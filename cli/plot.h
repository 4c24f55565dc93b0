/* Figures of the mcspec command, drawn by gnuplot.
 *
 * Why gnuplot: it is a C program with no language runtime to install (one
 * small Debian package, gnuplot-nox, with the pngcairo and svg terminals),
 * it reads a plain data file and a short script, and it renders the same
 * figure headless in CI and on a desktop; matplotlib would bring a Python
 * runtime and NumPy to a C library's command line.
 *
 * The data and the script go to a fresh temporary directory, gnuplot runs
 * there, and the figure is moved into place under its final name only when
 * gnuplot succeeded (through a temporary file in the destination directory
 * and rename), so a failed run never leaves a partial figure. */
#ifndef MCSPEC_CLI_PLOT_H
#define MCSPEC_CLI_PLOT_H

#include <stddef.h>
#include <stdio.h>

#include "output.h"

/* Figure size in pixels (PNG) or SVG user units, for every figure. */
#define CLI_PLOT_WIDTH 960
#define CLI_PLOT_HEIGHT 600

typedef struct {
    const char *title;        /* first title line (what was measured) */
    const char *subtitle;     /* second title line, or NULL */
    const char *exact_label;  /* legend of the exact series; NULL: not drawn */
    const char *closed_label; /* legend of the closed form; NULL: not drawn */
    const char *ylabel;       /* the spectrum's y axis; NULL: <|S_k|^2> */
    int log_y;                /* --log: the spectrum's (the profile's) y axis in log scale */
} cli_plot_info;

/* Checks a --plot FILE before any work is done: cli_plot_check_file, then
 * cli_plot_check_gnuplot. Returns 0 or CLI_EXIT_USAGE after one line on
 * stderr. */
int cli_plot_check(const char *cmd, const char *path);

/* The file half: path ends in .svg or .png, is a regular file or a new name
 * (cli_not_regular), and its directory is writable. 0 or CLI_EXIT_USAGE. */
int cli_plot_check_file(const char *cmd, const char *path);

/* The program half: gnuplot is on PATH. A command that may find it has no
 * figure to draw (mcspec show of a welford record) says so first and asks
 * this only when it will draw. 0 or CLI_EXIT_USAGE. */
int cli_plot_check_gnuplot(const char *cmd);

/* --log is for the figure: CLI_EXIT_USAGE after one line when log is set
 * without --plot (plot NULL), else 0. */
int cli_plot_check_log(const char *cmd, int log, const char *plot);

/* Both checks a command that saves and plots makes before any work: --save
 * FILE (cli_write_check) and --plot FILE (cli_plot_check); either may be
 * NULL (not asked). Returns 0 or CLI_EXIT_USAGE after a message. */
int cli_check_outputs(const char *cmd, const char *save, const char *plot);

/* Draws the power spectrum of rows with k >= 1 (S_0 = K / sqrt(N) would
 * dwarf the rest): measured values with a band of one standard error, and
 * the exact and closed-form series where their labels are set and they
 * have values. Returns 0, or an exit status after one line on stderr. */
int cli_plot_spectrum(const char *cmd, const char *path, const cli_plot_info *info,
                      const cli_spectrum_row *rows, size_t nrows);

/* Draws a 2D point-set spectrum: on the left the image of <P(k)> over the
 * wave vectors of rows2d (CLI_PS_2D rows; P(0) = K is off the colour scale),
 * on the right the radial profile of radial (CLI_PS_RADIAL rows, r >= 1)
 * with its standard-error band and, where info->exact_label is set and the
 * rows have them, the exact values. Returns 0, or an exit status after one
 * line on stderr. */
int cli_plot_pointset2d(const char *cmd, const char *path, const cli_plot_info *info,
                        const cli_ps_row *rows2d, size_t nrows2d, const cli_ps_row *radial,
                        size_t nradial);

/* ---- For the figures' writers (plot.c, plot2d.c) ------------------------------- */

/* Writes a figure's data files into tmp (cli_plot_data) and its gnuplot
 * script after the terminal and output lines to fp. 0, or -1 on a write
 * error. */
typedef int (*cli_plot_writer)(FILE *fp, const char *tmp, const void *ctx);

/* Runs write in a fresh temporary directory, gnuplot on the script, and
 * moves the figure to path (see above). Returns 0 or an exit status. */
int cli_plot_render(const char *cmd, const char *path, cli_plot_writer write, const void *ctx);

/* A data file tmp/name for writing ("data.txt" or "data2.txt"), and its
 * name as a gnuplot string in a script. */
FILE *cli_plot_data(const char *tmp, const char *name);
void cli_plot_data_ref(FILE *fp, const char *tmp, const char *name);

/* " %.17g", or " NaN" (gnuplot breaks a line there); a gnuplot string;
 * info's two title lines as one gnuplot string. */
void cli_plot_value(FILE *fp, double x);
void cli_plot_string(FILE *fp, const char *s);
void cli_plot_title(FILE *fp, const cli_plot_info *info);

/* The key, grid and border every panel uses. */
void cli_plot_style(FILE *fp);

/* A profile panel's plot command over data columns 1 x, 2 measured, 3 and 4
 * measured -+ one standard error, 5 exact, 6 closed: the band, the exact and
 * closed lines (NULL label: not drawn) and the measured points, with the
 * legend entries "<measured> ± 1 standard error" and "<measured> (mean over
 * trials)". */
typedef struct {
    const char *tmp, *data;  /* the data file in tmp */
    const char *measured;    /* what the measured series is, "measured" */
    const char *exact_label, *closed_label;
} cli_plot_series;
void cli_plot_profile(FILE *fp, const cli_plot_series *s);

/* The y axis of a profile panel. Linear: [0, 1.45 x the highest value
 * drawn] (room for the key; 1 when nothing is positive). Log (--log): from
 * below the lowest positive value to where the highest sits at 70% of the
 * height, two decades at least ([0.1, 10] when nothing is positive); a
 * value <= 0, or below 1e-12 of the highest of all rows, row 0 too (the
 * rounding residue of a zero), is off the axis: a line (band edge, exact,
 * closed) goes down to its bottom there, a measured point is not drawn. */
typedef struct {
    int log;
    double hi;            /* highest value drawn (power + stderr, exact, closed) */
    double scale;         /* highest value of all the rows, for the floor */
    double lo;            /* log: lowest value drawn above scale x 1e-12 */
    double bottom, top;   /* the range */
} cli_plot_axis;

/* The values of row i of a caller's rows: power, its standard error, exact
 * and closed (NaN: none). */
typedef void (*cli_plot_row_fn)(const void *rows, size_t i, double v[4]);

/* The axis of rows first..n-1 (get reads them), linear or log. */
void cli_plot_axis_init(cli_plot_axis *a, int log, const void *rows, size_t first, size_t n,
                        cli_plot_row_fn get);

/* The axis's script lines: its scale, tic format and range. */
void cli_plot_axis_write(FILE *fp, const cli_plot_axis *a);

/* One line of such a data file: x, the measured value, value -+ its
 * standard error (none: 0), exact and closed (NaN: no value), each as the
 * axis draws it. */
void cli_plot_profile_row(FILE *fp, const cli_plot_axis *a, long x, double power,
                          double stderr_, double exact, double closed);

#endif /* MCSPEC_CLI_PLOT_H */
