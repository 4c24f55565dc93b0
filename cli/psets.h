/* Point sets from many files into one point-set spectrum, the way
 * `mcspec spectrum` and `mcspec-mpi spectrum` both do it, so the two give
 * the same bytes.
 *
 * Reading: utk's files (sets ended by '#' lines, any number of coordinates)
 * or psa's (the point count first, one set per file), several files in
 * order; `--dims i,j` picks the coordinates a 2D analysis reads (`--dims i`
 * for 1D) from files of any dimension.
 *
 * Accumulating: each set is transformed alone into a one-trial object (the
 * scratch), which is then merged into the run's object in the order of the
 * sets. A one-trial object is what mcspec-mpi's ranks send to rank 0, which
 * merges them in the same order, so one process and P ranks do the same
 * floating-point operations. From the one-trial object the set's radial
 * averages over annuli of width W (r <= |k| < r + W, r = 0, W, 2W, ...)
 * are formed from the library's unit annuli, sum over the unit annuli of
 * n_r x (the set's average over annulus r) / sum of n_r, and their mean and
 * standard error over the sets kept here (Welford): the standard error of an
 * annulus is that of the per-set annulus means, never an average of the unit
 * annuli's standard errors (the unit annuli of one set are correlated). */
#ifndef MCSPEC_CLI_PSETS_H
#define MCSPEC_CLI_PSETS_H

#include <stddef.h>
#include <stdint.h>

#include "input.h"
#include "progress.h"
#include "record.h"

#include "mcspec.h"

/* The default cutoff rule of utk and psa, about 5 sqrt(K): ceil(5 sqrt(K))
 * for the most points K in a set, capped at cap (the command's largest F). */
size_t cli_default_freq(size_t k_max, size_t cap);

/* How the point files are read. */
typedef struct {
    int psa;          /* psa's files (count first, one set each), else utk's */
    size_t dim;       /* the analysis: 1 or 2 coordinates per point */
    size_t ndims;     /* 0: the file's points have exactly dim coordinates; else dim */
    size_t dims[2];   /* ... and the coordinates read, 0-based (--dims) */
    int wrap;         /* take coordinates modulo 1 */
} cli_ps_input;

/* Parses --dims "i" or "i,j" (0..CLI_MAX_DIM-1, distinct) into in->dims and
 * in->ndims. 0, or an exit status after one line on stderr. */
int cli_ps_parse_dims(const char *cmd, const char *text, cli_ps_input *in);

/* --format utk|psa (NULL: utk) into in->psa; --path auto|direct|nufft
 * (NULL: leave *path) into *path. 0 or an exit status after a message. */
int cli_ps_parse_format(const char *cmd, const char *format, cli_ps_input *in);
int cli_ps_parse_path(const char *cmd, const char *text, mcs_pointset_path *path);

/* Receives one set of k points of in->dim coordinates (pts[k dim]), the
 * set's number (0-based over all files) and the name of its file. */
typedef int (*cli_ps_set_fn)(void *ctx, uint64_t set, size_t k, const double *pts,
                             const char *name);

/* Reads every set of the files paths[npaths] in order (a NULL or "-" path is
 * standard input) into fn. stats: the sets, K range and lines of all files
 * (lines: of the last file). Returns 0 or an exit status after a message. */
int cli_ps_read(const char *cmd, const cli_ps_input *in, const char *const *paths,
                size_t npaths, cli_ps_set_fn fn, void *ctx, cli_pointset_stats *stats,
                cli_progress *progress);

/* The run's accumulator, the scratch and the annuli of width W. */
typedef struct {
    const char *cmd;
    size_t dim, freq, width;
    mcs_pointset_path path; /* the scratch's path: AUTO, or one forced (--path) */
    cli_acc acc;          /* the run's mcs_pointset or mcs_pointset2d (merges only) */
    cli_acc one;          /* the scratch: one set at a time */
    size_t nbins;         /* annuli of width W: r = 0, W, .., (nbins - 1) W */
    double *bin_mean, *bin_m2; /* per annulus over the sets, Welford (W > 1) */
    double *ring_n;       /* wave vectors of each unit annulus r = 0..F */
    uint64_t sets;
} cli_ps_sink;

/* Complete annuli of width W below F + 1: floor((F + 1) / W). */
size_t cli_ps_bin_count(size_t freq, size_t width);

/* The sink for cutoff freq, dimension dim, annuli of width width (2D). 0 or
 * an exit status after a message (memory: the command's cli_acc_new). */
int cli_ps_sink_init(const char *cmd, size_t dim, size_t freq, size_t width, cli_ps_sink *s);
void cli_ps_sink_free(cli_ps_sink *s);

/* The scratch emptied and the set of k points transformed into it. */
int cli_ps_sink_transform(cli_ps_sink *s, size_t k, const double *pts);

/* A one-trial object (the scratch, or one loaded from a rank's record)
 * merged into the run's, its annuli of width W into the sink's. */
int cli_ps_sink_absorb(cli_ps_sink *s, const void *one);

/* Annulus b of width W (W > 1) after the sets: mean, standard error (NaN
 * below two sets), psa's anisotropy over its wave vectors of the mean
 * periodogram (NaN where not defined). W = 1: the library's own. */
void cli_ps_sink_bin(const void *sink, size_t b, double *mean, double *se, double *aniso);

/* --save of standard input: its bytes go to an unnamed temporary file that
 * becomes standard input (read again from its start after a pass with
 * rewind), their CRC-32 and length into *crc, *bytes. */
int cli_ps_checksum_stdin(const char *cmd, uint32_t *crc, uint64_t *bytes);

/* The CRC-32 and length of the file path. */
int cli_ps_checksum_path(const char *cmd, const char *path, uint32_t *crc, uint64_t *bytes);

/* The provenance of the inputs paths[npaths] (none: standard input, whose
 * CRC and length are stdin_crc, stdin_bytes), at most
 * MCS_IO_PROV_MAX_INPUTS files. 0 or an exit status after a message. */
int cli_ps_provenance(const char *cmd, const char *const *paths, size_t npaths,
                      uint32_t stdin_crc, uint64_t stdin_bytes, mcs_io_provenance *prov);

/* How the sets of a point-set run reach the sink: one process (NULL), or
 * mcspec-mpi's ranks. Every rank runs the whole command on the same
 * arguments (parsing, reading every file, the default F), so all see the
 * same sets in the same order; set() gets each set on every rank and does
 * that rank's part (rank 0: absorb the sets in order, its own transformed
 * here and the others' received; rank r: transform and send the sets
 * m = r mod P). Only the root prints, plots and saves. */
typedef struct {
    const char *cmd;  /* the messages' prefix ("mcspec-mpi spectrum: rank 0") */
    int is_root;
    void *ctx;
    /* after every rank set up its sink (rc its status): the status all go on with */
    int (*start)(void *ctx, int rc);
    int (*set)(void *ctx, cli_ps_sink *sink, uint64_t set, size_t k, const double *pts);
    /* after the last set: 0, or the status every rank exits with */
    int (*finish)(void *ctx, cli_ps_sink *sink, int rc);
} cli_ps_driver;

/* `mcspec spectrum` (argv[0] is "spectrum"), with drv NULL for one process.
 * Under a driver, point sets only, from files only. Returns the exit status. */
int cli_spectrum_run(int argc, char **argv, const cli_ps_driver *drv);

#endif /* MCSPEC_CLI_PSETS_H */
