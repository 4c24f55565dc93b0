/* mcspec spectrum: the spectrum of point sets read from a file. */
#include "cli.h"
#include "input.h"
#include "output.h"
#include "plot.h"
#include "progress.h"
#include "record.h"

#include "mcspec.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define CMD "mcspec spectrum"
#define DEFAULT_N 256

static const char help[] =
    "usage: mcspec spectrum [--n N] [--weights] [--wrap] [--csv]\n"
    "                       [--plot FILE [--log]] [--save FILE] [FILE|-]\n"
    "       mcspec spectrum --freq F [--dim 1|2] [--radial] [--wrap] [--csv]\n"
    "                       [--plot FILE [--log]] [--save FILE] [FILE|-]\n"
    "\n"
    "The Fourier spectrum of point sets read from FILE (or standard input, given\n"
    "as '-' or by giving no FILE): each set is one trial.\n"
    "\n"
    "Binned (the default, 1D): each point x in [0,1) falls in bin floor(N x) of N\n"
    "bins, s_n is the number of points in bin n (the sum of their weights with\n"
    "--weights, eq. 38), and per trial S_k = N^(-1/2) sum_n exp(-2 pi i k n / N) s_n\n"
    "(eq. 7). Printed for every frequency k = 0..N/2 (S_(N-k) is the conjugate of\n"
    "S_k): the mean <S_k> over the sets (real and imaginary parts), its standard\n"
    "error, the power spectrum <|S_k|^2> and its standard error.\n"
    "\n"
    "Point sets, no binning (--freq F): per set of K points x_j the periodogram\n"
    "P(k) = |sum_j exp(-2 pi i k x_j)|^2 / K at the integer frequencies k = 0..F\n"
    "(--dim 1), or with --dim 2 P(k) = |sum_j exp(-2 pi i k.x_j)|^2 / K at the\n"
    "wave vectors k = (kx, ky), |kx|, |ky| <= F (k.x_j the dot product),\n"
    "and its mean over the sets with its standard error (random points give\n"
    "P = 1 at k != 0; P(0) = K). With --radial (2D) the annuli r <= |k| < r + 1,\n"
    "r = 0..F, instead: the radial average of P, its standard error (over the\n"
    "sets), and psa's anisotropy 10 log10(variance / mean^2) over the annulus in\n"
    "dB (empty where it is not defined: r = 0, or an annulus of zeros).\n"
    "\n"
    "Above the table: the number of sets and the fewest and most points in a\n"
    "set. Standard errors need two sets or more.\n"
    "\n"
    "Input: one point per line, its coordinates (one, or two with --dim 2)\n"
    "separated by spaces or tabs; with --weights (binned only) a last column is\n"
    "the point's weight (finite, >= 0; a set's weights sum to at most\n"
    "MCS_SPECTRUM_MAX_SUM). A line starting with '#' ends the current set (utk's\n"
    "convention); '#' lines before the first point are a header; a\n"
    "final '#' is allowed; two '#' lines with no point between them are an error\n"
    "(an empty set). Blank lines are ignored; a NUL byte is an error (the input\n"
    "is text). Everything is read and checked before anything is printed: a\n"
    "malformed line stops the run with the file, the line number and what was\n"
    "wrong, exit 2.\n"
    "\n"
    "Options:\n"
    "  --n N        bins N, 1.." CLI_STR(MCS_MAX_N) " (default 256; not with --freq)\n"
    "  --freq F     the point-set spectrum up to frequency F instead (no bins):\n"
    "               F = 1.." CLI_STR(MCS_POINTSET_MAX_FREQ) " in 1D, 1.."
    CLI_STR(MCS_POINTSET2D_MAX_FREQ) " in 2D, memory allowing (about 270 F^2 B in 2D)\n"
    "  --dim D      coordinates per point, 1 (default) or 2 (needs --freq)\n"
    "  --radial     --dim 2: one row per annulus instead of per wave vector\n"
    "  --weights    each line holds a point and its weight (binned only)\n"
    "  --wrap       take coordinates modulo 1 (default: outside [0,1) is an error)\n"
    "  --csv        print CSV only: the header, exactly\n"
    "               freq,mean_re,mean_im,mean_stderr,power,power_stderr  (binned)\n"
    "               freq,power,power_stderr                     (--freq, 1D)\n"
    "               kx,ky,power,power_stderr                    (--freq, 2D)\n"
    "               radius,power,power_stderr,anisotropy_db     (--radial)\n"
    "               and one row per frequency, wave vector or annulus (an empty\n"
    "               field: no value)\n"
    "  --plot FILE  also draw the power spectrum (k >= 1) with its standard-error\n"
    "               band to FILE, .svg or .png (needs gnuplot); in 2D the image of\n"
    "               <P(k)> beside its radial profile\n"
    "  --log        --plot: the power (2D: the radial profile) on a log y axis;\n"
    "               zeros, and values below 1e-12 of the highest, are not drawn\n"
    "  --save FILE  also save the accumulator (spectrum, pointset or pointset2d)\n"
    "               to FILE (docs/format.md; read by mcspec show, merged with\n"
    "               other files by mcspec merge), written atomically: a temporary\n"
    "               file beside FILE, flushed, then renamed, so FILE is never left\n"
    "               half-written (FILE: a regular file or a new name)\n"
    "  --help       this text\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage or input (one line on stderr).\n";

typedef struct {
    size_t n, freq, dim;
    int weights, wrap, csv, radial;
    const char *freq_text; /* --freq as given: its range depends on --dim */
    const char *plot;
    const char *path;
    const char *save;
    int log_y; /* --log */
} spectrum_opts;

/* --freq F into o->freq, within the cap of the accumulator --dim picks:
 * MCS_POINTSET_MAX_FREQ (mcs_pointset) or MCS_POINTSET2D_MAX_FREQ
 * (mcs_pointset2d); whether this machine holds it is cli_acc_new's. */
static int parse_freq(spectrum_opts *o)
{
    if (o->freq_text == NULL)
        return 0;
    const int two = o->dim == 2u;
    const size_t cap = two ? (size_t)MCS_POINTSET2D_MAX_FREQ : (size_t)MCS_POINTSET_MAX_FREQ;
    uint64_t v = 0;
    if (cli_parse_u64(o->freq_text, 1u, cap, &v) != 0)
        return cli_fail(CMD, "--freq expects a whole number from 1 to %zu for --dim %zu (%s), "
                        "not '%s'", cap, o->dim,
                        two ? "MCS_POINTSET2D_MAX_FREQ" : "MCS_POINTSET_MAX_FREQ", o->freq_text);
    o->freq = (size_t)v;
    return 0;
}

/* The combinations --dim, --freq, --n, --weights and --radial allow. */
static int check_mode(spectrum_opts *o, int n_given)
{
    int rc = parse_freq(o);
    if (rc != 0)
        return rc;
    if (o->freq == 0u && o->dim == 2u)
        return cli_fail(CMD, "--dim 2 needs --freq F: the 2D spectrum of points is not binned");
    if (o->freq == 0u && o->radial)
        return cli_fail(CMD, "--radial needs --dim 2 --freq F");
    if (o->freq == 0u)
        return 0;
    if (n_given)
        return cli_fail(CMD, "--n (bins) and --freq (no binning) exclude each other");
    if (o->weights)
        return cli_fail(CMD, "--weights needs binning: drop --freq, or the weight column");
    if (o->radial && o->dim != 2u)
        return cli_fail(CMD, "--radial needs --dim 2");
    return 0;
}

static int parse(int argc, char **argv, spectrum_opts *o)
{
    cli_opt opts[] = {
        {"n", CLI_OPT_SIZE, &o->n, 1, MCS_MAX_N, 0},
        {"freq", CLI_OPT_STRING, &o->freq_text, 0, 0, 0},
        {"dim", CLI_OPT_SIZE, &o->dim, 1, 2, 0},
        {"radial", CLI_OPT_FLAG, &o->radial, 0, 0, 0},
        {"weights", CLI_OPT_FLAG, &o->weights, 0, 0, 0},
        {"wrap", CLI_OPT_FLAG, &o->wrap, 0, 0, 0},
        {"csv", CLI_OPT_FLAG, &o->csv, 0, 0, 0},
        {"plot", CLI_OPT_STRING, &o->plot, 0, 0, 0},
        {"log", CLI_OPT_FLAG, &o->log_y, 0, 0, 0},
        {"save", CLI_OPT_STRING, &o->save, 0, 0, 0},
    };
    int rc = cli_parse_one(CMD, help, NULL, opts, CLI_COUNT(opts), argc, argv, &o->path);
    if (rc != CLI_PARSED)
        return rc;
    rc = check_mode(o, opts[0].given);
    if (rc == 0)
        rc = cli_plot_check_log(CMD, o->log_y, o->plot);
    if (rc != 0)
        return rc;
    if (o->path == NULL && isatty(STDIN_FILENO))
        return cli_fail(CMD, "no input: give a point file, or '-' to read standard input");
    return cli_check_outputs(CMD, o->save, o->plot);
}

/* What add_set needs: the accumulator, and where the set came from. */
typedef struct {
    const cli_acc *acc;
    const char *name;                 /* the input, as messages name it */
    const cli_pointset_stats *stats;  /* its lines up to the set's end */
} add_ctx;

static int add_set(void *ctx, size_t k, const double *coords, const double *weights)
{
    const add_ctx *c = ctx;
    const cli_acc *acc = c->acc;
    mcs_status st;
    if (acc->kind == MCS_IO_KIND_POINTSET)
        st = mcs_pointset_add(acc->obj, k, coords);
    else if (acc->kind == MCS_IO_KIND_POINTSET2D)
        st = mcs_pointset2d_add(acc->obj, k, coords);
    else
        st = mcs_spectrum_add_points(acc->obj, k, coords, weights);
    /* The reader refuses a sum above the limit on its line; a sum the
     * library's own (vectorised) order rounds past it lands here. */
    if (st == MCS_ERR_MAGNITUDE)
        return cli_fail(CMD, "%s: line %lu: the set ending here has weights summing above "
                        "%g, the most a set may sum to (mcs_spectrum, MCS_SPECTRUM_MAX_SUM): "
                        "scale the weights down", c->name, c->stats->lines, MCS_SPECTRUM_MAX_SUM);
    if (st != MCS_OK)
        return cli_internal(CMD, "adding a point set failed: %s", mcs_status_str(st));
    return 0;
}

/* "K = 8" or "K = 4 to 9" */
static void k_range(const cli_pointset_stats *stats, char *buf, size_t size)
{
    if (stats->k_min == stats->k_max)
        snprintf(buf, size, "K = %zu", stats->k_min);
    else
        snprintf(buf, size, "K = %zu to %zu", stats->k_min, stats->k_max);
}

static int report_binned(const spectrum_opts *o, const mcs_spectrum *acc,
                         const cli_pointset_stats *stats, const char *const *notes)
{
    cli_spectrum_row *rows = cli_alloc(CMD, CLI_HALF_MAX, sizeof *rows);
    if (rows == NULL)
        return CLI_EXIT_FAIL;
    size_t nrows = 0;
    int rc = cli_spectrum_rows(CMD, acc, NULL, 1.0, rows, &nrows);
    if (rc == 0 && o->plot != NULL) {
        char title[512], sub[256], kset[64];
        snprintf(title, sizeof title, "%s: power spectrum over N = %zu bins",
                 cli_input_name(o->path), o->n);
        k_range(stats, kset, sizeof kset);
        snprintf(sub, sizeof sub, "%llu point sets (trials), %s points per set%s; k = 0 not drawn",
                 (unsigned long long)stats->sets, kset, o->weights ? ", weighted" : "");
        cli_plot_info info = {title, sub, NULL, NULL, NULL, o->log_y};
        rc = cli_plot_spectrum(CMD, o->plot, &info, rows, nrows);
    }
    for (size_t i = 0; rc == 0 && notes[i] != NULL; ++i)
        cli_note(o->csv, "%s", notes[i]);
    if (rc == 0)
        cli_print_spectrum(o->csv, 0, rows, nrows);
    free(rows);
    return rc;
}

/* The table's notes, the figure's titles, then the rows of acc. */
static int report(const spectrum_opts *o, const cli_acc *acc, const cli_pointset_stats *stats)
{
    const char *name = cli_input_name(o->path);
    char what[256], counts[256], title[512], sub[256], kset[64];
    if (o->freq == 0u)
        snprintf(what, sizeof what, "%s: %s, N = %zu bins, bin floor(N x)%s", CMD, name, o->n,
                 o->weights ? ", weights from the second column" : "");
    else if (o->dim == 1u)
        snprintf(what, sizeof what, "%s: %s, point sets in 1D, no binning: "
                 "P(k) = |sum_j exp(-2 pi i k x_j)|^2 / K, k = 0..F, F = %zu", CMD, name, o->freq);
    else
        snprintf(what, sizeof what, "%s: %s, point sets in 2D, no binning: "
                 "P(k) = |sum_j exp(-2 pi i k.x_j)|^2 / K, |kx|, |ky| <= F = %zu", CMD, name,
                 o->freq);
    snprintf(counts, sizeof counts, "trials (point sets) %llu, K per set: min %zu, max %zu "
             "(%lu lines read)", (unsigned long long)stats->sets, stats->k_min, stats->k_max,
             stats->lines);
    const char *const notes[] = {what, counts, "", NULL};
    if (acc->kind == MCS_IO_KIND_SPECTRUM)
        return report_binned(o, acc->obj, stats, notes);
    k_range(stats, kset, sizeof kset);
    snprintf(title, sizeof title, "%s: point-set spectrum, F = %zu", name, o->freq);
    snprintf(sub, sizeof sub, "%llu point sets (trials), %s points per set",
             (unsigned long long)stats->sets, kset);
    const cli_ps_report rep = {o->csv, o->radial, o->plot, o->log_y, title, sub, NULL, NULL, notes};
    if (acc->kind == MCS_IO_KIND_POINTSET)
        return cli_report_pointset(CMD, &rep, acc->obj);
    return cli_report_pointset2d(CMD, &rep, acc->obj);
}

/* The CRC-32 and length of the bytes of fp, copied to copy when not NULL. */
static int checksum(FILE *fp, FILE *copy, uint32_t *crc, uint64_t *bytes)
{
    static unsigned char buf[1u << 16];
    size_t got;
    *crc = 0u;
    *bytes = 0u;
    while ((got = fread(buf, 1u, sizeof buf, fp)) > 0u) {
        *crc = cli_crc32_update(*crc, buf, got);
        *bytes += got;
        if (copy != NULL && fwrite(buf, 1u, got, copy) != got)
            return -1;
    }
    return ferror(fp) ? -1 : 0;
}

/* --save of standard input: its bytes go to an unnamed temporary file that
 * becomes standard input, so the reader reads what was checksummed (and
 * names it <stdin> as ever). */
static int checksum_stdin(uint32_t *crc, uint64_t *bytes)
{
    FILE *copy = tmpfile();
    if (copy == NULL)
        return cli_fail(CMD, "<stdin>: cannot keep a copy to checksum: %s", strerror(errno));
    int bad = checksum(stdin, copy, crc, bytes) != 0 || fflush(copy) != 0;
    const int err = errno;
    if (!bad && dup2(fileno(copy), STDIN_FILENO) < 0)
        bad = 1;
    fclose(copy);
    if (bad)
        return cli_fail(CMD, "<stdin>: cannot read it to checksum: %s", strerror(err));
    clearerr(stdin);
    rewind(stdin);
    return 0;
}

/* The CRC-32 and length of the file path, read again after the point sets. */
static int checksum_path(const char *path, uint32_t *crc, uint64_t *bytes)
{
    FILE *fp = fopen(path, "rb");
    int bad = fp == NULL || checksum(fp, NULL, crc, bytes) != 0;
    const int err = errno;
    if (fp != NULL)
        fclose(fp);
    return bad ? cli_fail(CMD, "cannot read '%s' to checksum it: %s", path, strerror(err)) : 0;
}

int cli_cmd_spectrum(int argc, char **argv)
{
    spectrum_opts o = {DEFAULT_N, 0, 1, 0, 0, 0, 0, NULL, NULL, NULL, NULL, 0};
    int rc = parse(argc, argv, &o);
    if (rc != 0)
        return rc < 0 ? CLI_EXIT_OK : rc;
    const mcs_io_kind kind = o.freq == 0u ? MCS_IO_KIND_SPECTRUM
                             : o.dim == 2u ? MCS_IO_KIND_POINTSET2D
                                           : MCS_IO_KIND_POINTSET;
    const size_t shape[2] = {o.freq == 0u ? o.n : o.freq, 0u};
    cli_acc acc = {kind, NULL};
    rc = cli_acc_new(CMD, kind, shape, &acc);
    if (rc != 0)
        return rc;
    cli_pointset_format fmt = {o.dim, o.weights, o.wrap, MCS_SPECTRUM_MAX_SUM,
                               "mcs_spectrum, MCS_SPECTRUM_MAX_SUM"};
    cli_pointset_stats stats;
    cli_progress progress;
    /* The record's provenance: the input's checksum, of the bytes read. */
    const int from_stdin = o.path == NULL || strcmp(o.path, "-") == 0;
    uint32_t crc = 0u;
    uint64_t bytes = 0u;
    if (o.save != NULL && from_stdin)
        rc = checksum_stdin(&crc, &bytes);
    cli_progress_init(&progress, !o.csv, CMD, "sets read", 0);
    add_ctx ctx = {&acc, cli_input_name(o.path), &stats};
    if (rc == 0)
        rc = cli_read_pointsets(CMD, o.path, &fmt, add_set, &ctx, &stats, &progress);
    cli_progress_end(&progress);
    if (rc == 0 && o.save != NULL && !from_stdin)
        rc = checksum_path(o.path, &crc, &bytes);
    if (rc == 0)
        rc = report(&o, &acc, &stats);
    mcs_io_provenance *prov = rc == 0 && o.save != NULL ? cli_alloc(CMD, 1, sizeof *prov) : NULL;
    if (rc == 0 && o.save != NULL && prov == NULL)
        rc = CLI_EXIT_FAIL;
    if (rc == 0 && o.save != NULL) {
        cli_input_provenance(cli_input_name(o.path), crc, bytes, prov);
        rc = cli_acc_write_with(CMD, o.save, &acc, prov);
    }
    free(prov);
    cli_acc_free(&acc);
    return rc;
}
