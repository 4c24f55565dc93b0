/* Text input of the mcspec command: point sets and lists of values.
 *
 * Every error names the input, the line and what was wrong, as one line on
 * stderr, and the reader stops there; a reader calls back only with complete,
 * validated data, so a caller that prints after reading never prints
 * anything partial. A NUL byte anywhere in a line (a comment too) is such an
 * error: the input is text. "-" (or NULL) is standard input. */
#ifndef MCSPEC_CLI_INPUT_H
#define MCSPEC_CLI_INPUT_H

#include <stddef.h>
#include <stdint.h>

#include "progress.h"

/* Point-set files (utk's convention): one point per line, its coordinates
 * separated by blanks (spaces or tabs), then its weight when `weights` is
 * set; a line starting with '#' ends the current set; blank lines are
 * ignored. '#' lines before the first point are a header and are skipped; a
 * '#' line right after another (only blank lines between) would make an empty
 * set and is an error; a final '#' line is allowed. Coordinates must be
 * finite and in [0,1) (with `wrap`, any finite value is taken modulo 1);
 * weights finite and >= 0. */
/* Most coordinates a point line may have (utk's files of any dimension;
 * the discrepancies' cap, MCS_DISCREPANCY_MAX_DIM, is the same 64). */
#define CLI_MAX_DIM 64u

typedef struct {
    /* coordinates per point, 1 to CLI_MAX_DIM; 0: the first point line
     * fixes it (its columns, less the weight column with `weights`), and
     * every later line must have as many (cli_pointset_stats.dim says it) */
    size_t dim;
    int weights; /* a weight column follows the coordinates */
    int wrap;    /* take coordinates modulo 1 instead of rejecting them */
    /* With weights: the most one set's weights may sum to (0: no limit), and
     * the accumulator it is the limit of, for the message ("mcs_spectrum,
     * MCS_SPECTRUM_MAX_SUM"). The line where the running sum passes it is
     * the error. */
    double weight_sum_max;
    const char *weight_sum_what;
} cli_pointset_format;

typedef struct {
    uint64_t sets;       /* complete sets passed to the callback */
    size_t dim;          /* coordinates per point (fmt's, or the file's with dim 0) */
    size_t k_min, k_max; /* fewest and most points in a set */
    unsigned long lines; /* lines read (during a callback: up to the set's end) */
} cli_pointset_stats;

/* Receives one complete set: k points, coords[k * dim] (point j at
 * coords[j * dim ...]), weights[k] or NULL without a weight column. Returns
 * 0 to go on, or an exit status to stop with (it has printed why). */
typedef int (*cli_pointset_fn)(void *ctx, size_t k, const double *coords,
                               const double *weights);

/* Reads every set of path. Returns 0, or an exit status after one line on
 * stderr. progress (may be NULL) counts sets. */
int cli_read_pointsets(const char *cmd, const char *path, const cli_pointset_format *fmt,
                       cli_pointset_fn fn, void *ctx, cli_pointset_stats *stats,
                       cli_progress *progress);

/* cli_read_pointsets for one of psa's point files: its first line (blank
 * lines aside) holds the point count K >= 1 alone, then exactly K point
 * lines follow, one set per file; no '#' lines and no weights (fmt->weights
 * must be 0). Coordinates, dim and wrap as fmt says. Returns 0 after one
 * set, or an exit status after one line on stderr. */
int cli_read_psa(const char *cmd, const char *path, const cli_pointset_format *fmt,
                 cli_pointset_fn fn, void *ctx, cli_pointset_stats *stats,
                 cli_progress *progress);

/* A list of values, one finite number per line ('#' lines and blank lines
 * are skipped), at most max of them; with `nonneg`, each must be >= 0
 * (importance weights: 0 is a bin that is never drawn).
 * *values is allocated (the caller frees it) and holds *count >= 1 values.
 * what names the values in messages ("integrand value"). Returns 0 or an
 * exit status after one line on stderr. */
int cli_read_values(const char *cmd, const char *path, const char *what, int positive,
                    size_t max, double **values, size_t *count);

/* The name messages use for path: "<stdin>" for NULL or "-". */
const char *cli_input_name(const char *path);

#endif /* MCSPEC_CLI_INPUT_H */
