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

#include "output.h"

/* Figure size in pixels (PNG) or SVG user units, for every figure. */
#define CLI_PLOT_WIDTH 960
#define CLI_PLOT_HEIGHT 600

typedef struct {
    const char *title;        /* first title line (what was measured) */
    const char *subtitle;     /* second title line, or NULL */
    const char *exact_label;  /* legend of the exact series; NULL: not drawn */
    const char *closed_label; /* legend of the closed form; NULL: not drawn */
} cli_plot_info;

/* Checks a --plot FILE before any work is done: it ends in .svg or .png, its
 * directory is writable, and gnuplot is on PATH. Returns 0 or
 * CLI_EXIT_USAGE after one line on stderr. */
int cli_plot_check(const char *cmd, const char *path);

/* Draws the power spectrum of rows with k >= 1 (S_0 = K / sqrt(N) would
 * dwarf the rest): measured values with a band of one standard error, and
 * the exact and closed-form series where their labels are set and they
 * have values. Returns 0, or an exit status after one line on stderr. */
int cli_plot_spectrum(const char *cmd, const char *path, const cli_plot_info *info,
                      const cli_spectrum_row *rows, size_t nrows);

#endif /* MCSPEC_CLI_PLOT_H */
