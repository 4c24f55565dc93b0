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
    "usage: mcspec show FILE [--csv] [--plot FILE] [--radial]\n"
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
    "               band to FILE, .svg or .png (needs gnuplot; 1D spectra and point\n"
    "               sets only)\n"
    "  --radial     pointset2d: the radial profile instead of every wave vector\n"
    "  --help       this text\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage or input (one line on stderr).\n";

typedef struct {
    const char *path, *plot;
    int csv, radial;
} show_opts;

static int parse(int argc, char **argv, show_opts *o)
{
    cli_opt opts[] = {
        {"csv", CLI_OPT_FLAG, &o->csv, 0, 0, 0},
        {"plot", CLI_OPT_STRING, &o->plot, 0, 0, 0},
        {"radial", CLI_OPT_FLAG, &o->radial, 0, 0, 0},
    };
    const char *args[1] = {NULL};
    cli_parser p = {CMD, help, opts, sizeof opts / sizeof opts[0], args, 1, 0};
    int rc = cli_parse(&p, argc, argv);
    if (rc != CLI_PARSED)
        return rc == CLI_HELP ? -1 : CLI_EXIT_USAGE;
    if (p.nargs == 0u)
        return cli_fail(CMD, "which record? give FILE");
    o->path = args[0];
    if (o->plot != NULL)
        return cli_plot_check(CMD, o->plot);
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

/* Values of one line: CSV fields or table columns (NaN: empty or "-"). */
static void print_values(int csv, const double *v, size_t nv)
{
    for (size_t i = 0; i < nv; ++i) {
        char buf[40];
        if (csv)
            cli_csv_double(buf, sizeof buf, v[i]);
        else
            cli_table_double(buf, sizeof buf, 13, v[i]);
        printf(csv ? ",%s" : " %s", buf);
    }
    putchar('\n');
}

/* The mean periodogram of a 1D point set as spectrum rows (power only). */
static int pointset_rows(const mcs_pointset *p, cli_spectrum_row *rows, size_t *nrows)
{
    *nrows = p->freq_max + 1u;
    for (size_t f = 0; f < *nrows; ++f) {
        double se = 0.0;
        blank_row(&rows[f], f);
        rows[f].mean_re = rows[f].mean_im = (double)NAN;
        mcs_status st = mcs_pointset_power(p, (long)f, &rows[f].power);
        if (st != MCS_OK)
            return cli_internal(CMD, "reading the point set failed: %s", mcs_status_str(st));
        rows[f].power_stderr = mcs_pointset_power_stderr(p, (long)f, &se) == MCS_OK ? se : (double)NAN;
    }
    return 0;
}

static void print_pointset(int csv, const cli_spectrum_row *rows, size_t nrows)
{
    printf(csv ? "freq,power,power_stderr\n" : "%5s %13s %13s\n", "freq", "power",
           "power_stderr");
    for (size_t i = 0; i < nrows; ++i) {
        printf(csv ? "%zu" : "%5zu", rows[i].freq);
        const double v[2] = {rows[i].power, rows[i].power_stderr};
        print_values(csv, v, 2u);
    }
}

/* *v if st says it was written, else NaN. A pointer, not a value: the call
 * that writes *v is another argument, and C leaves their order open. */
static double read_or_nan(mcs_status st, const double *v)
{
    return st == MCS_OK ? *v : (double)NAN;
}

static void show_pointset2d(const show_opts *o, const mcs_pointset2d *p)
{
    const long f = (long)p->freq_max;
    if (o->radial) {
        printf(o->csv ? "radius,power,power_stderr,anisotropy_db\n" : "%6s %13s %13s %13s\n",
               "radius", "power", "power_stderr", "anisotropy_db");
        for (long r = 0; r <= f; ++r) {
            double v[3] = {0.0, 0.0, 0.0};
            v[0] = read_or_nan(mcs_pointset2d_radial(p, (size_t)r, &v[0]), &v[0]);
            v[1] = read_or_nan(mcs_pointset2d_radial_stderr(p, (size_t)r, &v[1]), &v[1]);
            v[2] = read_or_nan(mcs_pointset2d_anisotropy(p, (size_t)r, &v[2]), &v[2]);
            printf(o->csv ? "%ld" : "%6ld", r);
            print_values(o->csv, v, 3u);
        }
        return;
    }
    printf(o->csv ? "kx,ky,power,power_stderr\n" : "%5s %5s %13s %13s\n", "kx", "ky", "power",
           "power_stderr");
    for (long fy = -f; fy <= f; ++fy)
        for (long fx = -f; fx <= f; ++fx) {
            double v[2] = {0.0, 0.0};
            v[0] = read_or_nan(mcs_pointset2d_power(p, fx, fy, &v[0]), &v[0]);
            v[1] = read_or_nan(mcs_pointset2d_power_stderr(p, fx, fy, &v[1]), &v[1]);
            printf(o->csv ? "%ld,%ld" : "%5ld %5ld", fx, fy);
            print_values(o->csv, v, 2u);
        }
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
            v[0] = read_or_nan(st, &v[0]);
            v[1] = read_or_nan(st, &v[1]);
            v[2] = read_or_nan(mcs_spectrum2d_mean_stderr(s, k1, k2, &v[2]), &v[2]);
            v[3] = read_or_nan(mcs_spectrum2d_power(s, k1, k2, &v[3]), &v[3]);
            v[4] = read_or_nan(mcs_spectrum2d_power_stderr(s, k1, k2, &v[4]), &v[4]);
            printf(o->csv ? "%zu,%zu" : "%5zu %5zu", k1, k2);
            print_values(o->csv, v, 5u);
        }
}

static int show_spectrum(const show_opts *o, const cli_acc *acc)
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
    else if (acc->kind == MCS_IO_KIND_AUTOCORR)
        rc = autocorr_rows(acc->obj, rows, &nrows);
    else
        rc = pointset_rows(acc->obj, rows, &nrows);
    char title[512], what[96];
    snprintf(title, sizeof title, "%s: %s, %llu trials", o->path,
             cli_acc_describe(acc, what, sizeof what), (unsigned long long)cli_acc_count(acc));
    if (rc == 0 && o->plot != NULL) {
        cli_plot_info info = {title, "k = 0 not drawn", NULL, NULL};
        rc = cli_plot_spectrum(CMD, o->plot, &info, rows, nrows);
    }
    if (rc == 0) {
        cli_note(o->csv, "%s", title);
        cli_note(o->csv, "%s", "");
        if (acc->kind == MCS_IO_KIND_POINTSET)
            print_pointset(o->csv, rows, nrows);
        else
            cli_print_spectrum(o->csv, 0, rows, nrows);
    }
    free(rows);
    return rc;
}

static int show_welford(const show_opts *o, const mcs_welford *w)
{
    double v[4] = {0.0, 0.0, 0.0, 0.0};
    v[0] = read_or_nan(mcs_welford_mean(w, &v[0]), &v[0]);
    v[1] = read_or_nan(mcs_welford_stderr(w, &v[1]), &v[1]);
    v[2] = read_or_nan(mcs_welford_variance(w, &v[2]), &v[2]);
    v[3] = read_or_nan(mcs_welford_variance_stderr(w, &v[3]), &v[3]);
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
    show_opts o = {NULL, NULL, 0, 0};
    int rc = parse(argc, argv, &o);
    if (rc != 0)
        return rc < 0 ? CLI_EXIT_OK : rc;
    cli_acc acc = {MCS_IO_KIND_SPECTRUM, NULL};
    rc = cli_acc_read(CMD, o.path, &acc);
    if (rc != 0)
        return rc;
    char what[96];
    const int plottable = acc.kind == MCS_IO_KIND_SPECTRUM || acc.kind == MCS_IO_KIND_MOMENT ||
                          acc.kind == MCS_IO_KIND_AUTOCORR || acc.kind == MCS_IO_KIND_POINTSET;
    cli_acc_describe(&acc, what, sizeof what);
    if (o.plot != NULL && !plottable)
        rc = cli_fail(CMD, "%s holds %s: no plot for it (drop --plot)", o.path, what);
    else if (o.radial && acc.kind != MCS_IO_KIND_POINTSET2D)
        rc = cli_fail(CMD, "%s holds %s: --radial is for pointset2d records", o.path, what);
    else if (acc.kind != MCS_IO_KIND_WELFORD && cli_acc_count(&acc) == 0u)
        rc = cli_fail(CMD, "%s holds %s with no trials: nothing to show", o.path, what);
    else if (acc.kind == MCS_IO_KIND_WELFORD)
        rc = show_welford(&o, acc.obj);
    else if (acc.kind == MCS_IO_KIND_POINTSET2D || acc.kind == MCS_IO_KIND_SPECTRUM2D) {
        cli_note(o.csv, "%s: %s, %llu trials\n", o.path, what,
                 (unsigned long long)cli_acc_count(&acc));
        if (acc.kind == MCS_IO_KIND_POINTSET2D)
            show_pointset2d(&o, acc.obj);
        else
            show_spectrum2d(&o, acc.obj);
    } else
        rc = show_spectrum(&o, &acc);
    cli_acc_free(&acc);
    return rc;
}
