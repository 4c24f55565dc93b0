/* mcspec show: what a saved accumulator holds. */
#include "cli.h"
#include "output.h"
#include "plot.h"
#include "predict.h"
#include "record.h"

#include "mcspec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CMD "mcspec show"

static const char help[] =
    "usage: mcspec show FILE [--csv] [--plot FILE [--log]] [--radial]\n"
    "\n"
    "Prints the accumulator saved in FILE (by --save, mcspec merge or\n"
    "mcspec-mpi; the format is docs/format.md), after checking the whole record:\n"
    "a truncated, corrupted or unknown file is refused with what is wrong.\n"
    "\n"
    "spectrum  the half spectrum k = 0..N/2 as mcspec spectrum prints it: <S_k>,\n"
    "          its standard error, <|S_k|^2> and its standard error (eq. 7, 14)\n"
    "moment    <S_k> (eq. 15) and <|S_k|^2> (eq. 16) from the primal moments, k =\n"
    "          0..N/2, same columns (the standard errors are empty: the moment\n"
    "          accumulator keeps sums, not spreads)\n"
    "autocorr  <S_k> and <|S_k|^2> by Wiener-Khinchin, same columns, stderrs empty\n"
    "welford   count, mean, its standard error, the variance and its standard error\n"
    "pointset  the mean periodogram P(f), f = 0..F, and its standard error\n"
    "pointset2d  P at every wave vector |kx|, |ky| <= F and its standard error; with\n"
    "          --radial the annulus averages, their standard errors and psa's\n"
    "          anisotropy in dB (empty where it is not defined)\n"
    "spectrum2d  <S_k> and <|S_k|^2> with standard errors at every (k1, k2)\n"
    "\n"
    "Options:\n"
    "  --csv        print CSV only: for spectra the header\n"
    "               freq,mean_re,mean_im,mean_stderr,power,power_stderr\n"
    "               and one row per frequency; for welford\n"
    "               count,mean,mean_stderr,variance,variance_stderr\n"
    "               and one row; for the point sets and 2D spectra\n"
    "               freq,power,power_stderr\n"
    "               kx,ky,power,power_stderr  (radius,power,power_stderr,anisotropy_db)\n"
    "               k1,k2,mean_re,mean_im,mean_stderr,power,power_stderr\n"
    "               and one row per frequency (an empty field: no value)\n"
    "  --plot FILE  also draw the power spectrum (k >= 1) with its standard-error\n"
    "               band to FILE, .svg or .png (needs gnuplot); for pointset2d the\n"
    "               image of <P(k)> beside its radial profile (not for welford and\n"
    "               spectrum2d)\n"
    "  --log        --plot: the power (pointset2d: the radial profile) on a log y\n"
    "               axis; zeros, and values below 1e-12 of the highest, are not\n"
    "               drawn\n"
    "  --radial     pointset2d: the radial profile instead of every wave vector\n"
    "  --help       this text\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage or input (one line on stderr).\n";

typedef struct {
    const char *path, *plot;
    int csv, radial;
    int log_y; /* --log */
} show_opts;

static int parse(int argc, char **argv, show_opts *o)
{
    cli_opt opts[] = {
        {"csv", CLI_OPT_FLAG, &o->csv, 0, 0, 0},
        {"plot", CLI_OPT_STRING, &o->plot, 0, 0, 0},
        {"radial", CLI_OPT_FLAG, &o->radial, 0, 0, 0},
        {"log", CLI_OPT_FLAG, &o->log_y, 0, 0, 0},
    };
    int rc = cli_parse_one(CMD, help, NULL, opts, CLI_COUNT(opts), argc, argv, &o->path);
    if (rc != CLI_PARSED)
        return rc;
    if (o->path == NULL)
        return cli_fail(CMD, "which record? give FILE");
    if (cli_plot_check_log(CMD, o->log_y, o->plot) != 0)
        return CLI_EXIT_USAGE;
    /* gnuplot only once the record is known to have a figure (cli_cmd_show). */
    if (o->plot != NULL)
        return cli_plot_check_file(CMD, o->plot);
    return 0;
}

static void blank_row(cli_spectrum_row *r, size_t freq)
{
    r->freq = freq;
    r->mean_stderr = r->power_stderr = NAN;
    r->exact = r->closed = r->z_exact = r->z_closed = NAN;
}

static int moment_rows(const mcs_moment *m, cli_spectrum_row *rows, size_t *nrows)
{
    *nrows = m->n / 2u + 1u;
    for (size_t f = 0; f < *nrows; ++f) {
        blank_row(&rows[f], f);
        mcs_status st = mcs_moment_mean(m, f, &rows[f].mean_re, &rows[f].mean_im);
        if (st == MCS_OK)
            st = mcs_moment_power(m, f, &rows[f].power);
        if (st != MCS_OK)
            return cli_internal(CMD, "reading the moments failed: %s", mcs_status_str(st));
    }
    return 0;
}

static int autocorr_rows(const mcs_autocorr *a, cli_spectrum_row *rows, size_t *nrows)
{
    const size_t n = a->n;
    mcs_dft *plan = cli_alloc(CMD, 1, sizeof *plan);
    double *buf = cli_alloc(CMD, 3u * n, sizeof *buf);
    int rc = plan != NULL && buf != NULL ? 0 : CLI_EXIT_FAIL;
    mcs_status st = MCS_OK;
    if (rc == 0) {
        st = mcs_dft_init(plan, n);
        if (st == MCS_OK)
            st = mcs_autocorr_mean(a, plan, n, buf, buf + n);
        if (st == MCS_OK)
            st = mcs_autocorr_power(a, plan, n, buf + 2u * n);
        if (st != MCS_OK)
            rc = cli_internal(CMD, "reading the autocorrelation failed: %s", mcs_status_str(st));
    }
    *nrows = n / 2u + 1u;
    for (size_t f = 0; rc == 0 && f < *nrows; ++f) {
        blank_row(&rows[f], f);
        rows[f].mean_re = buf[f];
        rows[f].mean_im = buf[n + f];
        rows[f].power = buf[2u * n + f];
    }
    free(buf);
    free(plan);
    return rc;
}

/* A point-set record: pointset (f = 0..F) or pointset2d (every wave vector
 * or, with --radial, the annuli); --plot draws the spectrum, or the image
 * and the radial profile. */
static int show_pointset(const show_opts *o, const cli_acc *acc, const char *title)
{
    const char *const notes[] = {title, "", NULL};
    const cli_ps_report rep = {o->csv, o->radial, o->plot, o->log_y, title,
                               acc->kind == MCS_IO_KIND_POINTSET ? "f = 0 not drawn" : NULL,
                               NULL, NULL, notes};
    if (acc->kind == MCS_IO_KIND_POINTSET)
        return cli_report_pointset(CMD, &rep, acc->obj);
    return cli_report_pointset2d(CMD, &rep, acc->obj);
}

static void show_spectrum2d(const show_opts *o, const mcs_spectrum2d *s)
{
    printf(o->csv ? "k1,k2,mean_re,mean_im,mean_stderr,power,power_stderr\n"
                  : "%5s %5s %13s %13s %13s %13s %13s\n",
           "k1", "k2", "mean_re", "mean_im", "mean_stderr", "power", "power_stderr");
    for (size_t k2 = 0; k2 < s->n_y; ++k2)
        for (size_t k1 = 0; k1 < s->n_x; ++k1) {
            double v[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
            mcs_status st = mcs_spectrum2d_mean(s, k1, k2, &v[0], &v[1]);
            v[0] = cli_or_nan(st, &v[0]);
            v[1] = cli_or_nan(st, &v[1]);
            v[2] = cli_or_nan(mcs_spectrum2d_mean_stderr(s, k1, k2, &v[2]), &v[2]);
            v[3] = cli_or_nan(mcs_spectrum2d_power(s, k1, k2, &v[3]), &v[3]);
            v[4] = cli_or_nan(mcs_spectrum2d_power_stderr(s, k1, k2, &v[4]), &v[4]);
            printf(o->csv ? "%zu,%zu" : "%5zu %5zu", k1, k2);
            cli_print_values(o->csv, v, 5u);
        }
}

static int show_spectrum(const show_opts *o, const cli_acc *acc, const char *title)
{
    cli_spectrum_row *rows = cli_alloc(CMD, CLI_HALF_MAX, sizeof *rows);
    if (rows == NULL)
        return CLI_EXIT_FAIL;
    size_t nrows = 0u;
    int rc = 0;
    if (acc->kind == MCS_IO_KIND_SPECTRUM)
        rc = cli_spectrum_rows(CMD, acc->obj, NULL, 1.0, rows, &nrows);
    else if (acc->kind == MCS_IO_KIND_MOMENT)
        rc = moment_rows(acc->obj, rows, &nrows);
    else
        rc = autocorr_rows(acc->obj, rows, &nrows);
    if (rc == 0 && o->plot != NULL) {
        cli_plot_info info = {title, "k = 0 not drawn", NULL, NULL, NULL, o->log_y};
        rc = cli_plot_spectrum(CMD, o->plot, &info, rows, nrows);
    }
    if (rc == 0) {
        cli_note(o->csv, "%s", title);
        cli_note(o->csv, "%s", "");
        cli_print_spectrum(o->csv, 0, rows, nrows);
    }
    free(rows);
    return rc;
}

static int show_welford(const show_opts *o, const mcs_welford *w)
{
    double v[4] = {0.0, 0.0, 0.0, 0.0};
    v[0] = cli_or_nan(mcs_welford_mean(w, &v[0]), &v[0]);
    v[1] = cli_or_nan(mcs_welford_stderr(w, &v[1]), &v[1]);
    v[2] = cli_or_nan(mcs_welford_variance(w, &v[2]), &v[2]);
    v[3] = cli_or_nan(mcs_welford_variance_stderr(w, &v[3]), &v[3]);
    char buf[4][40];
    if (o->csv) {
        for (int i = 0; i < 4; ++i)
            cli_csv_double(buf[i], sizeof buf[i], v[i]);
        printf("count,mean,mean_stderr,variance,variance_stderr\n%llu,%s,%s,%s,%s\n",
               (unsigned long long)w->count, buf[0], buf[1], buf[2], buf[3]);
        return 0;
    }
    for (int i = 0; i < 4; ++i)
        cli_table_double(buf[i], sizeof buf[i], 13, v[i]);
    printf("%s: saved welford (a scalar's mean and spread)\n\n", o->path);
    printf("%20s %13s %13s %13s %13s\n", "count", "mean", "mean_stderr", "variance",
           "variance_stderr");
    printf("%20llu %s %s %s %s\n", (unsigned long long)w->count, buf[0], buf[1], buf[2],
           buf[3]);
    return 0;
}

int cli_cmd_show(int argc, char **argv)
{
    show_opts o = {NULL, NULL, 0, 0, 0};
    int rc = parse(argc, argv, &o);
    if (rc != 0)
        return rc < 0 ? CLI_EXIT_OK : rc;
    cli_acc acc = {MCS_IO_KIND_SPECTRUM, NULL};
    rc = cli_acc_read(CMD, o.path, &acc);
    if (rc != 0)
        return rc;
    char what[96], title[512];
    cli_acc_describe(&acc, what, sizeof what);
    snprintf(title, sizeof title, "%s: %s, %llu trials", o.path, what,
             (unsigned long long)cli_acc_count(&acc));
    if (o.plot != NULL && (acc.kind == MCS_IO_KIND_WELFORD || acc.kind == MCS_IO_KIND_SPECTRUM2D))
        rc = cli_fail(CMD, "%s holds %s: no plot for it (drop --plot)", o.path, what);
    else if (o.radial && acc.kind != MCS_IO_KIND_POINTSET2D)
        rc = cli_fail(CMD, "%s holds %s: --radial is for pointset2d records", o.path, what);
    else if (acc.kind != MCS_IO_KIND_WELFORD && cli_acc_count(&acc) == 0u)
        rc = cli_fail(CMD, "%s holds %s with no trials: nothing to show", o.path, what);
    else if (o.plot != NULL && cli_plot_check_gnuplot(CMD) != 0)
        rc = CLI_EXIT_USAGE;
    else if (acc.kind == MCS_IO_KIND_WELFORD)
        rc = show_welford(&o, acc.obj);
    else if (acc.kind == MCS_IO_KIND_POINTSET || acc.kind == MCS_IO_KIND_POINTSET2D)
        rc = show_pointset(&o, &acc, title);
    else if (acc.kind == MCS_IO_KIND_SPECTRUM2D) {
        cli_note(o.csv, "%s\n", title);
        show_spectrum2d(&o, acc.obj);
    } else
        rc = show_spectrum(&o, &acc, title);
    cli_acc_free(&acc);
    return rc;
}
