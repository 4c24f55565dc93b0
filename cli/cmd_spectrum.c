/* mcspec spectrum: the spectrum of point sets read from a file. */
#include "atomic.h"
#include "cli.h"
#include "input.h"
#include "output.h"
#include "plot.h"
#include "progress.h"
#include "psets.h"
#include "record.h"

#include "mcspec.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The table's name; messages name the command running (mcspec-mpi's too). */
#define TITLE "mcspec spectrum"
static const char *cmd_name = TITLE;
#define CMD cmd_name
#define DEFAULT_N 256

static const char help[] =
    "usage: mcspec spectrum [--n N] [--weights] [--wrap] [--csv]\n"
    "                       [--plot FILE [--log]] [--save FILE] [FILE|-]\n"
    "       mcspec spectrum [--freq F|auto] [--dim 1|2] [--dims I[,J]] [--radial\n"
    "                       [--bin-width W]] [--norm] [--path P] [--format utk|psa]\n"
    "                       [--wrap] [--csv] [--plot FILE [--log]] [--pfm FILE]\n"
    "                       [--save FILE] [FILE...|-]\n"
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
    CLI_STR(MCS_POINTSET2D_MAX_FREQ) " in 2D, memory allowing (about 540 F^2 B in 2D);\n"
    "               'auto', and the default in 2D: utk's and psa's rule, below\n"
    "  --dim D      coordinates per point, 1 (default) or 2 (point sets)\n"
    "  --dims, --bin-width, --norm, --format, --pfm: see the conventions below\n"
    "  --radial     --dim 2: one row per annulus instead of per wave vector\n"
    "  --weights    each line holds a point and its weight (binned only)\n"
    "  --wrap       take coordinates modulo 1 (default: outside [0,1) is an error)\n"
    "  --csv        print CSV only: the header, exactly\n"
    "               freq,mean_re,mean_im,mean_stderr,power,power_stderr  (binned)\n"
    "               freq,power,power_stderr                     (--freq, 1D)\n"
    "               kx,ky,power,power_stderr                    (2D)\n"
    "               radius,power,power_stderr,anisotropy_db     (--radial)\n"
    "               and one row per frequency, wave vector or annulus (an empty\n"
    "               field: no value)\n"
    "  --plot FILE  also draw the power spectrum (k >= 1) with its standard-error\n"
    "               band to FILE, .svg or .png (needs gnuplot); in 2D the image of\n"
    "               <P(k)> beside its radial profile\n"
    "  --log        --plot: the power (2D: the radial profile) on a log y axis;\n"
    "               zeros, and values below 1e-12 of the highest, are not drawn\n"
    "\n";

static const char help_more[] =
    "  --save FILE  also save the accumulator (spectrum, pointset or pointset2d)\n"
    "               to FILE (docs/format.md; read by mcspec show, merged with\n"
    "               other files by mcspec merge), written atomically: a temporary\n"
    "               file beside FILE, flushed, then renamed, so FILE is never left\n"
    "               half-written (FILE: a regular file or a new name)\n"
    "  --help       this text\n"
    "\n"
    "Conventions of utk and psa (point sets, no binning):\n"
    "  default F    without --freq in 2D (or with --freq auto):\n"
    "               F = ceil(5 sqrt(K)), K the most points in a set (640 for 16384\n"
    "               points, 160 for 1024), capped at the largest F of the dimension\n"
    "               (MCS_POINTSET2D_MAX_FREQ, MCS_POINTSET_MAX_FREQ); the table's\n"
    "               first line says the F used and why\n"
    "  --bin-width W  --radial: annuli r <= |k| < r + W, r = 0, W, 2W, .. (the\n"
    "               complete ones, r + W <= F + 1); default 1; psa and utk use 2.\n"
    "               A set's average over an annulus is the size-weighted average of\n"
    "               its unit annuli, and the standard error that of those per-set\n"
    "               averages over the sets (not an average of standard errors)\n"
    "  --norm       point sets: append the normalised frequency, each integer\n"
    "               frequency over sqrt(K), K the most points in a set, after\n"
    "               every column above: freq_norm; kx_norm,ky_norm; radius_norm\n"
    "  --format F   utk (default): as under Input above; psa: one set per file,\n"
    "               the point count alone on the first line, then that many point\n"
    "               lines, no '#' lines; give several files for several sets;\n"
    "               2D unless --dim 1 or --dims says otherwise\n"
    "  --dims I[,J] the coordinates read from files of any dimension, 0-based:\n"
    "               '--dims 0,2' reads x and z of 3D points as a 2D set (implies\n"
    "               --dim 2), '--dims 1' the second coordinate as a 1D set\n"
    "  FILE...      several files are read in order, their sets one run (--save\n"
    "               records up to 16 files; standard input only alone)\n"
    "  --path P     point sets: auto (default: per set the faster of the two by\n"
    "               the measured cost model), direct (the exact sum, O(K F^d)) or\n"
    "               nufft (the type-1 NUFFT, within 1e-9 max(P, 1) of it), to check\n"
    "               one against the other\n"
    "  --pfm FILE   2D: also write the mean periodogram <P(kx, ky)>, |kx|, |ky| <= F,\n"
    "               as a PFM image (\"Pf\", one little-endian float per pixel, rows\n"
    "               from ky = -F at the bottom to ky = F at the top, kx = -F at the\n"
    "               left), DC included; --plot draws it tone-mapped (log, DC masked)\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage or input (one line on stderr).\n";

typedef struct {
    size_t n, freq, dim, width;
    int weights, wrap, csv, radial;
    const char *freq_text; /* --freq as given: its range depends on --dim */
    const char *plot;
    const char **paths;    /* the FILE arguments (npaths of them; none: stdin) */
    size_t npaths;
    const char *save;
    const char *pfm;
    int log_y;             /* --log */
    int norm;              /* --norm */
    mcs_pointset_path path; /* --path */
    int freq_auto;         /* F from the rule (no --freq in 2D, or --freq auto) */
    const cli_ps_driver *drv; /* mcspec-mpi's, or NULL */
    cli_ps_input in;       /* --format, --dims, --wrap, the point sets' dimension */
} spectrum_opts;

/* The largest F of the accumulator --dim picks. */
static size_t freq_cap(size_t dim)
{
    return dim == 2u ? (size_t)MCS_POINTSET2D_MAX_FREQ : (size_t)MCS_POINTSET_MAX_FREQ;
}

/* --freq F (or auto) into o->freq, within the cap of the accumulator --dim
 * picks; whether this machine holds it is cli_acc_new's. */
static int parse_freq(spectrum_opts *o)
{
    if (o->freq_text == NULL) {
        o->freq_auto = o->dim == 2u;
        return 0;
    }
    if (strcmp(o->freq_text, "auto") == 0) {
        o->freq_auto = 1;
        return 0;
    }
    const int two = o->dim == 2u;
    const size_t cap = freq_cap(o->dim);
    uint64_t v = 0;
    if (cli_parse_u64(o->freq_text, 1u, cap, &v) != 0)
        return cli_fail(CMD, "--freq expects a whole number from 1 to %zu for --dim %zu (%s), "
                        "not '%s'", cap, o->dim,
                        two ? "MCS_POINTSET2D_MAX_FREQ" : "MCS_POINTSET_MAX_FREQ", o->freq_text);
    o->freq = (size_t)v;
    return 0;
}

/* --dims against --dim: two indices are a 2D analysis, one a 1D one. */
static int check_dims(spectrum_opts *o, const char *dims, int dim_given)
{
    if (dims == NULL)
        return 0;
    int rc = cli_ps_parse_dims(CMD, dims, &o->in);
    if (rc != 0)
        return rc;
    if (dim_given && o->dim != o->in.ndims)
        return cli_fail(CMD, "--dims %s reads %zu coordinate%s but --dim is %zu: give one "
                        "index per dimension", dims, o->in.ndims, o->in.ndims == 1u ? "" : "s",
                        o->dim);
    o->dim = o->in.ndims;
    if (o->dim == 1u && o->freq_text == NULL)
        return cli_fail(CMD, "--dims %s (1D) needs --freq F or --freq auto: the binned "
                        "spectrum reads one-coordinate files", dims);
    return 0;
}

/* The combinations --dim, --freq, --n, --weights and --radial allow. */
static int check_mode(spectrum_opts *o, int n_given, int width_given)
{
    int rc = parse_freq(o);
    if (rc != 0)
        return rc;
    const int points = o->freq != 0u || o->freq_auto;
    if (!points && o->radial)
        return cli_fail(CMD, "--radial needs --dim 2 --freq F (or --dim 2 alone: the default F)");
    const int forced = o->path != MCS_POINTSET_PATH_AUTO;
    if (!points && (o->in.psa || o->pfm != NULL || o->norm || forced))
        return cli_fail(CMD, "%s is for point sets: add --freq F or --dim 2",
                        o->pfm != NULL ? "--pfm"
                        : o->norm      ? "--norm"
                        : forced       ? "--path"
                                       : "--format psa");
    if (!points && o->npaths > 1u)
        return cli_fail(CMD, "unexpected argument '%s': the binned spectrum reads one FILE "
                        "(several files need --freq F or --dim 2)", o->paths[1]);
    if (width_given && !o->radial)
        return cli_fail(CMD, "--bin-width needs --radial (the annuli of --dim 2)");
    if (o->pfm != NULL && o->dim != 2u)
        return cli_fail(CMD, "--pfm needs --dim 2 (the image of the 2D periodogram)");
    if (!points)
        return 0;
    if (n_given)
        return cli_fail(CMD, "--n (bins) and --freq (no binning) exclude each other");
    if (o->weights)
        return cli_fail(CMD, "--weights needs binning: drop --freq, or the weight column");
    if (o->radial && o->dim != 2u)
        return cli_fail(CMD, "--radial needs --dim 2");
    if (o->freq != 0u && cli_ps_bin_count(o->freq, o->width) == 0u)
        return cli_fail(CMD, "--bin-width %zu is wider than the annuli up to F = %zu hold: give "
                        "1 to %zu", o->width, o->freq, o->freq + 1u);
    return 0;
}

static int parse(int argc, char **argv, spectrum_opts *o)
{
    const char *dims = NULL, *format = NULL, *path = NULL;
    cli_opt opts[] = {
        {"n", CLI_OPT_SIZE, &o->n, 1, MCS_MAX_N, 0},
        {"freq", CLI_OPT_STRING, &o->freq_text, 0, 0, 0},
        {"dim", CLI_OPT_SIZE, &o->dim, 1, 2, 0},
        {"radial", CLI_OPT_FLAG, &o->radial, 0, 0, 0},
        {"bin-width", CLI_OPT_SIZE, &o->width, 1, (uint64_t)MCS_POINTSET2D_MAX_FREQ + 1u, 0},
        {"dims", CLI_OPT_STRING, &dims, 0, 0, 0},
        {"format", CLI_OPT_STRING, &format, 0, 0, 0},
        {"weights", CLI_OPT_FLAG, &o->weights, 0, 0, 0},
        {"wrap", CLI_OPT_FLAG, &o->wrap, 0, 0, 0},
        {"csv", CLI_OPT_FLAG, &o->csv, 0, 0, 0},
        {"plot", CLI_OPT_STRING, &o->plot, 0, 0, 0},
        {"pfm", CLI_OPT_STRING, &o->pfm, 0, 0, 0},
        {"log", CLI_OPT_FLAG, &o->log_y, 0, 0, 0},
        {"norm", CLI_OPT_FLAG, &o->norm, 0, 0, 0},
        {"path", CLI_OPT_STRING, &path, 0, 0, 0},
        {"save", CLI_OPT_STRING, &o->save, 0, 0, 0},
    };
    const size_t max_args = (size_t)argc + 1u;
    o->paths = cli_alloc(CMD, max_args, sizeof *o->paths);
    if (o->paths == NULL)
        return CLI_EXIT_FAIL;
    cli_parser p = {CMD, help, opts, CLI_COUNT(opts), o->paths, max_args, 0u, help_more};
    int rc = cli_parse(&p, argc, argv);
    if (rc != CLI_PARSED)
        return rc;
    o->npaths = p.nargs;
    rc = cli_ps_parse_format(CMD, format, &o->in);
    if (rc == 0)
        rc = cli_ps_parse_path(CMD, path, &o->path);
    if (rc == 0 && o->in.psa && !opts[2].given && dims == NULL)
        o->dim = 2u; /* psa's point sets are 2D */
    if (rc == 0)
        rc = check_dims(o, dims, opts[2].given);
    if (rc == 0)
        rc = check_mode(o, opts[0].given, opts[4].given);
    if (rc == 0)
        rc = cli_plot_check_log(CMD, o->log_y, o->plot);
    if (rc != 0)
        return rc;
    for (size_t i = 0; i < o->npaths; ++i)
        if (o->npaths > 1u && strcmp(o->paths[i], "-") == 0)
            return cli_fail(CMD, "standard input ('-') can only be read alone, not among "
                            "several files");
    if (o->save != NULL && o->npaths > MCS_IO_PROV_MAX_INPUTS)
        return cli_fail(CMD, "--save records at most %u input files (MCS_IO_PROV_MAX_INPUTS), "
                        "not %zu: merge the records of smaller runs with mcspec merge",
                        MCS_IO_PROV_MAX_INPUTS, o->npaths);
    if (o->drv != NULL && (o->freq == 0u && !o->freq_auto))
        return cli_fail(CMD, "the ranks share point-set spectra only: give --freq F or --dim 2");
    if (o->drv != NULL && (o->npaths == 0u || strcmp(o->paths[0], "-") == 0))
        return cli_fail(CMD, "give the point files: the ranks cannot share standard input");
    if (o->npaths == 0u && isatty(STDIN_FILENO))
        return cli_fail(CMD, "no input: give a point file, or '-' to read standard input");
    o->in.dim = o->dim;
    o->in.wrap = o->wrap;
    rc = cli_check_outputs(CMD, o->save, o->plot);
    if (rc == 0 && o->pfm != NULL)
        rc = cli_write_check(CMD, o->pfm);
    return rc;
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
                 cli_input_name(o->npaths > 0u ? o->paths[0] : NULL), o->n);
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

/* The table's notes, the figure's titles, then the rows of the binned
 * spectrum. */
static int report(const spectrum_opts *o, const cli_acc *acc, const cli_pointset_stats *stats)
{
    const char *name = cli_input_name(o->npaths > 0u ? o->paths[0] : NULL);
    char what[256], counts[256];
    snprintf(what, sizeof what, "%s: %s, N = %zu bins, bin floor(N x)%s", TITLE, name, o->n,
             o->weights ? ", weights from the second column" : "");
    snprintf(counts, sizeof counts, "trials (point sets) %llu, K per set: min %zu, max %zu "
             "(%lu lines read)", (unsigned long long)stats->sets, stats->k_min, stats->k_max,
             stats->lines);
    const char *const notes[] = {what, counts, "", NULL};
    return report_binned(o, acc->obj, stats, notes);
}

/* "a.txt" or "a.txt and 3 more files" */
static void inputs_name(const spectrum_opts *o, char *buf, size_t size)
{
    const char *first = cli_input_name(o->npaths > 0u ? o->paths[0] : NULL);
    if (o->npaths > 1u)
        snprintf(buf, size, "%s and %zu more file%s", first, o->npaths - 1u,
                 o->npaths == 2u ? "" : "s");
    else
        snprintf(buf, size, "%s", first);
}

/* The point-set report: notes saying F, its rule, the annuli and the
 * normalisation, then the rows (psets.h's annuli when W > 1). */
static int report_points(const spectrum_opts *o, const cli_ps_sink *sink,
                         const cli_pointset_stats *stats)
{
    char name[320], what[512], fline[256], counts[256], extra[256], title[512], sub[256];
    char kset[64];
    inputs_name(o, name, sizeof name);
    const double root = sqrt((double)stats->k_max);
    if (o->dim == 1u)
        snprintf(what, sizeof what, "%s: %s, point sets in 1D, no binning: "
                 "P(k) = |sum_j exp(-2 pi i k x_j)|^2 / K, k = 0..F, F = %zu", TITLE, name,
                 o->freq);
    else
        snprintf(what, sizeof what, "%s: %s, point sets in 2D, no binning: "
                 "P(k) = |sum_j exp(-2 pi i k.x_j)|^2 / K, |kx|, |ky| <= F = %zu", TITLE, name,
                 o->freq);
    if (o->freq_auto)
        snprintf(fline, sizeof fline, "F = %zu: the default of utk and psa, ceil(5 sqrt(K)) = "
                 "%zu for K = %zu (the most points in a set), capped at %zu", o->freq,
                 cli_default_freq(stats->k_max, (size_t)-1), stats->k_max, freq_cap(o->dim));
    else
        snprintf(fline, sizeof fline, "F = %zu (--freq)", o->freq);
    snprintf(counts, sizeof counts, "trials (point sets) %llu, K per set: min %zu, max %zu "
             "(%zu file%s)", (unsigned long long)stats->sets, stats->k_min, stats->k_max,
             o->npaths > 1u ? o->npaths : 1u, o->npaths > 1u ? "s" : "");
    char annuli[96] = "";
    if (o->radial)
        snprintf(annuli, sizeof annuli, "annuli r <= |k| < r + %zu (--bin-width); ", o->width);
    snprintf(extra, sizeof extra, "%s%s%.6g", annuli,
             o->norm ? "*_norm columns: frequency / sqrt(K) = frequency / " : "sqrt(K) = ", root);
    const char *const notes[] = {what, fline, counts, extra, "", NULL};
    k_range(stats, kset, sizeof kset);
    snprintf(title, sizeof title, "%s: point-set spectrum, F = %zu", name, o->freq);
    snprintf(sub, sizeof sub, "%llu point sets (trials), %s points per set",
             (unsigned long long)stats->sets, kset);
    const cli_ps_report rep = {o->csv, o->radial, o->plot, o->log_y, title, sub, NULL, NULL, notes};
    const cli_ps_bins bins = {o->width, sink->nbins, sink, cli_ps_sink_bin};
    const cli_ps_extra ex = {o->norm ? root : 0.0, o->width > 1u ? &bins : NULL, o->pfm};
    if (o->dim == 1u)
        return cli_report_pointset_with(CMD, &rep, &ex, sink->acc.obj);
    return cli_report_pointset2d_with(CMD, &rep, &ex, sink->acc.obj);
}

/* What the point-set passes need. */
typedef struct {
    cli_ps_sink *sink;
    const cli_ps_driver *drv;
} points_ctx;

static int count_set(void *ctx, uint64_t set, size_t k, const double *pts, const char *name)
{
    (void)ctx, (void)set, (void)k, (void)pts, (void)name;
    return 0;
}

static int absorb_set(void *ctx, uint64_t set, size_t k, const double *pts, const char *name)
{
    (void)name;
    points_ctx *c = ctx;
    if (c->drv != NULL)
        return c->drv->set(c->drv->ctx, c->sink, set, k, pts);
    int rc = cli_ps_sink_transform(c->sink, k, pts);
    return rc != 0 ? rc : cli_ps_sink_absorb(c->sink, c->sink->one.obj);
}

/* Standard input again from its start, for a second pass. */
static void rewind_stdin(void)
{
    clearerr(stdin);
    rewind(stdin);
}

/* The point-set run: F from a first pass when it follows K, then every set
 * through the sink (psets.h), the report and the record. */
static int run_points(spectrum_opts *o, int from_stdin, uint32_t crc, uint64_t bytes)
{
    cli_pointset_stats stats;
    int rc = 0;
    if (o->freq_auto) {
        rc = cli_ps_read(CMD, &o->in, o->paths, o->npaths, count_set, NULL, &stats, NULL);
        if (rc != 0)
            return rc;
        if (from_stdin)
            rewind_stdin();
        o->freq = cli_default_freq(stats.k_max, freq_cap(o->dim));
        if (cli_ps_bin_count(o->freq, o->width) == 0u)
            return cli_fail(CMD, "--bin-width %zu is wider than the annuli up to F = %zu (the "
                            "default for K = %zu) hold: give 1 to %zu", o->width, o->freq,
                            stats.k_max, o->freq + 1u);
    }
    cli_ps_sink sink;
    rc = cli_ps_sink_init(CMD, o->dim, o->freq, o->width, &sink);
    sink.path = o->path;
    cli_progress progress;
    const int root = o->drv == NULL || o->drv->is_root;
    cli_progress_init(&progress, !o->csv && root, CMD, "sets read", 0);
    points_ctx ctx = {&sink, o->drv};
    if (o->drv != NULL)
        rc = o->drv->start(o->drv->ctx, rc);
    if (rc == 0)
        rc = cli_ps_read(CMD, &o->in, o->paths, o->npaths, absorb_set, &ctx, &stats, &progress);
    cli_progress_end(&progress);
    if (o->drv != NULL)
        rc = o->drv->finish(o->drv->ctx, &sink, rc);
    if (!root) {
        cli_ps_sink_free(&sink);
        return rc;
    }
    mcs_io_provenance *prov = rc == 0 && o->save != NULL ? cli_alloc(CMD, 1, sizeof *prov) : NULL;
    if (rc == 0 && o->save != NULL)
        rc = prov == NULL ? CLI_EXIT_FAIL : cli_ps_provenance(CMD, o->paths, o->npaths, crc, bytes, prov);
    if (rc == 0)
        rc = report_points(o, &sink, &stats);
    if (rc == 0 && o->save != NULL)
        rc = cli_acc_write_with(CMD, o->save, &sink.acc, prov);
    free(prov);
    cli_ps_sink_free(&sink);
    return rc;
}

/* The binned run, as before point sets took several files. */
static int run_binned(spectrum_opts *o, int from_stdin, uint32_t crc, uint64_t bytes)
{
    const char *path = o->npaths > 0u ? o->paths[0] : NULL;
    const size_t shape[2] = {o->n, 0u};
    cli_acc acc = {MCS_IO_KIND_SPECTRUM, NULL};
    int rc = cli_acc_new(CMD, MCS_IO_KIND_SPECTRUM, shape, &acc);
    if (rc != 0)
        return rc;
    cli_pointset_format fmt = {1u, o->weights, o->wrap, MCS_SPECTRUM_MAX_SUM,
                               "mcs_spectrum, MCS_SPECTRUM_MAX_SUM"};
    cli_pointset_stats stats;
    cli_progress progress;
    cli_progress_init(&progress, !o->csv, CMD, "sets read", 0);
    add_ctx ctx = {&acc, cli_input_name(path), &stats};
    rc = cli_read_pointsets(CMD, path, &fmt, add_set, &ctx, &stats, &progress);
    cli_progress_end(&progress);
    if (rc == 0 && o->save != NULL && !from_stdin)
        rc = cli_ps_checksum_path(CMD, path, &crc, &bytes);
    if (rc == 0)
        rc = report(o, &acc, &stats);
    mcs_io_provenance *prov = rc == 0 && o->save != NULL ? cli_alloc(CMD, 1, sizeof *prov) : NULL;
    if (rc == 0 && o->save != NULL && prov == NULL)
        rc = CLI_EXIT_FAIL;
    if (rc == 0 && o->save != NULL) {
        cli_input_provenance(cli_input_name(path), crc, bytes, prov);
        rc = cli_acc_write_with(CMD, o->save, &acc, prov);
    }
    free(prov);
    cli_acc_free(&acc);
    return rc;
}

int cli_cmd_spectrum(int argc, char **argv)
{
    return cli_spectrum_run(argc, argv, NULL);
}

int cli_spectrum_run(int argc, char **argv, const cli_ps_driver *drv)
{
    cmd_name = drv != NULL ? drv->cmd : TITLE;
    spectrum_opts o;
    memset(&o, 0, sizeof o);
    o.drv = drv;
    o.n = DEFAULT_N;
    o.dim = 1u;
    o.width = 1u;
    int rc = parse(argc, argv, &o);
    if (rc != 0) {
        free(o.paths);
        return rc < 0 ? CLI_EXIT_OK : rc;
    }
    const int points = o.freq != 0u || o.freq_auto;
    const int from_stdin = o.npaths == 0u || strcmp(o.paths[0], "-") == 0;
    /* The record's provenance: the input's checksum, of the bytes read; a
     * default F reads the sets twice, so standard input is kept then too. */
    uint32_t crc = 0u;
    uint64_t bytes = 0u;
    if (from_stdin && (o.save != NULL || (points && o.freq_auto)))
        rc = cli_ps_checksum_stdin(CMD, &crc, &bytes);
    if (rc == 0)
        rc = points ? run_points(&o, from_stdin, crc, bytes) : run_binned(&o, from_stdin, crc, bytes);
    free(o.paths);
    return rc;
}
