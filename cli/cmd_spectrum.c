/* mcspec spectrum: the spectrum of point sets read from a file. */
#include "atomic.h"
#include "cli.h"
#include "input.h"
#include "output.h"
#include "plot.h"
#include "progress.h"
#include "record.h"

#include "mcspec.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define CMD "mcspec spectrum"
#define DEFAULT_N 256

static const char help[] =
    "usage: mcspec spectrum [--n N] [--weights] [--wrap] [--csv] [--plot FILE]\n"
    "                       [--save FILE] [FILE|-]\n"
    "\n"
    "The Fourier spectrum of point sets read from FILE (or standard input, given\n"
    "as '-' or by giving no FILE): each set is one trial. Each point x in [0,1)\n"
    "falls in bin floor(N x) of N bins, s_n is the number of points in bin n (the\n"
    "sum of their weights with --weights, eq. 38), and per trial\n"
    "S_k = N^(-1/2) sum_n exp(-2 pi i k n / N) s_n (eq. 7). Printed for every\n"
    "frequency k = 0..N/2 (S_(N-k) is the conjugate of S_k): the mean <S_k> over\n"
    "the sets (real and imaginary parts), its standard error, the power spectrum\n"
    "<|S_k|^2> and its standard error; above the table, the number of sets and\n"
    "the fewest and most points in a set. Standard errors need two sets or more.\n"
    "\n"
    "Input: one point per line; with --weights a second column is the point's\n"
    "weight (finite, >= 0). Columns are separated by spaces or tabs. A line\n"
    "starting with '#' ends the current set (utk's convention); '#' lines before\n"
    "the first point are a header; a final '#' is allowed; two '#' lines with no\n"
    "point between them are an error (an empty set). Blank lines are ignored.\n"
    "Everything is read and checked before anything is printed: a malformed line\n"
    "stops the run with the file, the line number and what was wrong, exit 2.\n"
    "\n"
    "Options:\n"
    "  --n N        bins N, 1.." CLI_STR(MCS_MAX_N) " (default 256)\n"
    "  --weights    each line holds a point and its weight\n"
    "  --wrap       take coordinates modulo 1 (default: outside [0,1) is an error)\n"
    "  --csv        print CSV only: the header\n"
    "               freq,mean_re,mean_im,mean_stderr,power,power_stderr\n"
    "               and one row per frequency (an empty field: no value)\n"
    "  --plot FILE  also draw the power spectrum (k >= 1) with its standard-error\n"
    "               band to FILE, .svg or .png (needs gnuplot)\n"
    "  --save FILE  also save the spectrum accumulator to FILE (docs/format.md;\n"
    "               read by mcspec show, merged with other files by mcspec merge),\n"
    "               written atomically: a temporary file beside FILE, flushed,\n"
    "               then renamed, so FILE is never left half-written\n"
    "  --help       this text\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage or input (one line on stderr).\n";

typedef struct {
    size_t n;
    int weights, wrap, csv;
    const char *plot;
    const char *path;
    const char *save;
} spectrum_opts;

static int parse(int argc, char **argv, spectrum_opts *o)
{
    cli_opt opts[] = {
        {"n", CLI_OPT_SIZE, &o->n, 1, MCS_MAX_N, 0},
        {"weights", CLI_OPT_FLAG, &o->weights, 0, 0, 0},
        {"wrap", CLI_OPT_FLAG, &o->wrap, 0, 0, 0},
        {"csv", CLI_OPT_FLAG, &o->csv, 0, 0, 0},
        {"plot", CLI_OPT_STRING, &o->plot, 0, 0, 0},
        {"save", CLI_OPT_STRING, &o->save, 0, 0, 0},
    };
    const char *args[1] = {NULL};
    cli_parser p = {CMD, help, opts, sizeof opts / sizeof opts[0], args, 1, 0};
    int rc = cli_parse(&p, argc, argv);
    if (rc != CLI_PARSED)
        return rc == CLI_HELP ? -1 : CLI_EXIT_USAGE;
    o->path = p.nargs > 0u ? args[0] : NULL;
    if (o->path == NULL && isatty(STDIN_FILENO))
        return cli_fail(CMD, "no input: give a point file, or '-' to read standard input");
    if (o->save != NULL && cli_write_check(CMD, o->save) != 0)
        return CLI_EXIT_USAGE;
    if (o->plot != NULL)
        return cli_plot_check(CMD, o->plot);
    return 0;
}

static int add_set(void *ctx, size_t k, const double *coords, const double *weights)
{
    mcs_status st = mcs_spectrum_add_points(ctx, k, coords, weights);
    if (st != MCS_OK)
        return cli_internal(CMD, "adding a point set failed: %s", mcs_status_str(st));
    return 0;
}

static int report(const spectrum_opts *o, const mcs_spectrum *acc,
                  const cli_pointset_stats *stats)
{
    cli_spectrum_row *rows = cli_alloc(CMD, CLI_HALF_MAX, sizeof *rows);
    if (rows == NULL)
        return CLI_EXIT_FAIL;
    size_t nrows = 0;
    int rc = cli_spectrum_rows(CMD, acc, NULL, 1.0, rows, &nrows);
    const char *name = cli_input_name(o->path);
    if (rc == 0 && o->plot != NULL) {
        char title[512], sub[256];
        snprintf(title, sizeof title, "%s: power spectrum over N = %zu bins", name, o->n);
        char kset[64];
        if (stats->k_min == stats->k_max)
            snprintf(kset, sizeof kset, "K = %zu", stats->k_min);
        else
            snprintf(kset, sizeof kset, "K = %zu to %zu", stats->k_min, stats->k_max);
        snprintf(sub, sizeof sub, "%llu point sets (trials), %s points per set%s; k = 0 not drawn",
                 (unsigned long long)stats->sets, kset, o->weights ? ", weighted" : "");
        cli_plot_info info = {title, sub, NULL, NULL};
        rc = cli_plot_spectrum(CMD, o->plot, &info, rows, nrows);
    }
    if (rc == 0) {
        cli_note(o->csv, "%s: %s, N = %zu bins, bin floor(N x)%s", CMD, name, o->n,
                 o->weights ? ", weights from the second column" : "");
        cli_note(o->csv, "trials (point sets) %llu, K per set: min %zu, max %zu (%lu lines read)",
                 (unsigned long long)stats->sets, stats->k_min, stats->k_max, stats->lines);
        cli_note(o->csv, "%s", "");
        cli_print_spectrum(o->csv, 0, rows, nrows);
    }
    free(rows);
    return rc;
}

int cli_cmd_spectrum(int argc, char **argv)
{
    spectrum_opts o = {DEFAULT_N, 0, 0, 0, NULL, NULL, NULL};
    int rc = parse(argc, argv, &o);
    if (rc != 0)
        return rc < 0 ? CLI_EXIT_OK : rc;
    mcs_spectrum *acc = cli_alloc(CMD, 1, sizeof *acc);
    if (acc == NULL)
        return CLI_EXIT_FAIL;
    mcs_status st = mcs_spectrum_init(acc, o.n);
    if (st != MCS_OK) {
        free(acc);
        return cli_internal(CMD, "mcs_spectrum_init: %s", mcs_status_str(st));
    }
    cli_pointset_format fmt = {1, o.weights, o.wrap};
    cli_pointset_stats stats;
    cli_progress progress;
    cli_progress_init(&progress, !o.csv, CMD, "sets read", 0);
    rc = cli_read_pointsets(CMD, o.path, &fmt, add_set, acc, &stats, &progress);
    cli_progress_end(&progress);
    if (rc == 0)
        rc = report(&o, acc, &stats);
    if (rc == 0 && o.save != NULL) {
        cli_acc saved = {MCS_IO_KIND_SPECTRUM, acc};
        rc = cli_acc_write(CMD, o.save, &saved);
    }
    free(acc);
    return rc;
}
