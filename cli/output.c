/* Spectrum rows, table and CSV (see output.h). */
#include "output.h"
#include "cli.h"
#include "atomic.h"
#include "plot.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

double cli_or_nan(mcs_status st, const double *v)
{
    return st == MCS_OK ? *v : (double)NAN;
}

int cli_spectrum_rows(const char *cmd, const mcs_spectrum *acc, const cli_prediction *pred,
                      double scale, cli_spectrum_row *rows, size_t *nrows)
{
    size_t count = acc->n / 2u + 1u;
    for (size_t f = 0; f < count; ++f) {
        cli_spectrum_row *r = &rows[f];
        double se = 0.0;
        r->freq = f;
        mcs_status st = mcs_spectrum_mean(acc, f, &r->mean_re, &r->mean_im);
        if (st == MCS_OK)
            st = mcs_spectrum_power(acc, f, &r->power);
        if (st != MCS_OK)
            return cli_internal(cmd, "reading the spectrum failed: %s", mcs_status_str(st));
        r->mean_stderr = cli_or_nan(mcs_spectrum_mean_stderr(acc, f, &se), &se);
        r->power_stderr = cli_or_nan(mcs_spectrum_power_stderr(acc, f, &se), &se);
        r->exact = pred != NULL ? pred->exact[f] : (double)NAN;
        r->closed = pred != NULL ? pred->closed[f] : (double)NAN;
        r->z_exact = cli_z(r->power, r->exact, r->power_stderr,
                           1e-9 * fmax(fabs(r->exact), scale));
        r->z_closed = cli_z(r->power, r->closed, r->power_stderr,
                            1e-9 * fmax(fabs(r->closed), scale));
    }
    *nrows = count;
    return 0;
}

static void print_csv_row(int with_prediction, const cli_spectrum_row *r)
{
    double v[10] = {r->mean_re, r->mean_im, r->mean_stderr, r->power, r->power_stderr,
                    r->exact, r->closed, r->z_exact, r->z_closed, 0.0};
    size_t nv = with_prediction ? 9u : 5u;
    printf("%zu", r->freq);
    for (size_t i = 0; i < nv; ++i) {
        char buf[40];
        cli_csv_double(buf, sizeof buf, v[i]);
        printf(",%s", buf);
    }
    putchar('\n');
}

static void print_table_row(int with_prediction, const cli_spectrum_row *r)
{
    double v[7] = {r->mean_re, r->mean_im, r->mean_stderr, r->power, r->power_stderr,
                   r->exact, r->closed};
    size_t nv = with_prediction ? 7u : 5u;
    printf("%5zu", r->freq);
    for (size_t i = 0; i < nv; ++i) {
        char buf[40];
        cli_table_double(buf, sizeof buf, 13, v[i]);
        printf(" %s", buf);
    }
    if (with_prediction) {
        for (int i = 0; i < 2; ++i) {
            double z = i == 0 ? r->z_exact : r->z_closed;
            if (isnan(z))
                printf(" %8s", "-");
            else
                printf(" %8.2f", z);
        }
    }
    putchar('\n');
}

void cli_print_spectrum(int csv, int with_prediction, const cli_spectrum_row *rows,
                        size_t nrows)
{
    if (csv)
        printf("%s%s\n", CLI_SPECTRUM_CSV_HEADER, with_prediction ? CLI_PREDICTION_CSV_HEADER : "");
    else if (with_prediction)
        printf("%5s %13s %13s %13s %13s %13s %13s %13s %8s %8s\n", "freq", "mean_re", "mean_im",
               "mean_stderr", "power", "power_stderr", "exact", "closed", "z_exact", "z_closed");
    else
        printf("%5s %13s %13s %13s %13s %13s\n", "freq", "mean_re", "mean_im", "mean_stderr",
               "power", "power_stderr");
    for (size_t i = 0; i < nrows; ++i) {
        if (csv)
            print_csv_row(with_prediction, &rows[i]);
        else
            print_table_row(with_prediction, &rows[i]);
    }
}

void cli_note(int csv, const char *fmt, ...)
{
    if (csv)
        return;
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    putchar('\n');
}

/* ---- Point-set spectra -------------------------------------------------------- */

size_t cli_ps_row_count(cli_ps_layout layout, size_t freq_max)
{
    return layout == CLI_PS_2D ? (2u * freq_max + 1u) * (2u * freq_max + 1u) : freq_max + 1u;
}

static void blank_ps_row(cli_ps_row *r, long kx, long ky)
{
    r->kx = kx;
    r->ky = ky;
    r->power = r->power_stderr = r->anisotropy_db = r->exact = r->z_exact = (double)NAN;
}

/* One row of acc in layout at (kx, ky) (radial: r = kx). The mean needs a
 * trial; the rest may be missing (NaN). */
static mcs_status ps_row(cli_ps_layout layout, const void *acc, cli_ps_row *r)
{
    double v = 0.0;
    mcs_status st;
    if (layout == CLI_PS_1D) {
        st = mcs_pointset_power(acc, r->kx, &r->power);
        r->power_stderr = cli_or_nan(mcs_pointset_power_stderr(acc, r->kx, &v), &v);
    } else if (layout == CLI_PS_2D) {
        st = mcs_pointset2d_power(acc, r->kx, r->ky, &r->power);
        r->power_stderr = cli_or_nan(mcs_pointset2d_power_stderr(acc, r->kx, r->ky, &v), &v);
    } else {
        st = mcs_pointset2d_radial(acc, (size_t)r->kx, &r->power);
        r->power_stderr = cli_or_nan(mcs_pointset2d_radial_stderr(acc, (size_t)r->kx, &v), &v);
        r->anisotropy_db = cli_or_nan(mcs_pointset2d_anisotropy(acc, (size_t)r->kx, &v), &v);
    }
    return st;
}

int cli_ps_rows(const char *cmd, cli_ps_layout layout, const void *acc, cli_ps_row *rows,
                size_t *nrows)
{
    const long f = layout == CLI_PS_1D ? (long)((const mcs_pointset *)acc)->freq_max
                                       : (long)((const mcs_pointset2d *)acc)->freq_max;
    size_t n = 0u;
    for (long ky = layout == CLI_PS_2D ? -f : 0; ky <= (layout == CLI_PS_2D ? f : 0); ++ky)
        for (long kx = layout == CLI_PS_2D ? -f : 0; kx <= f; ++kx) {
            blank_ps_row(&rows[n], kx, ky);
            mcs_status st = ps_row(layout, acc, &rows[n++]);
            if (st != MCS_OK)
                return cli_internal(cmd, "reading the point-set spectrum failed: %s",
                                    mcs_status_str(st));
        }
    *nrows = n;
    return 0;
}

void cli_ps_rows_z(cli_ps_row *rows, size_t nrows, double scale)
{
    for (size_t i = 0; i < nrows; ++i)
        rows[i].z_exact = cli_z(rows[i].power, rows[i].exact, rows[i].power_stderr,
                                1e-9 * fmax(fabs(rows[i].exact), scale));
}

void cli_print_values(int csv, const double *v, size_t nv)
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

static void print_ps_header(int csv, cli_ps_layout layout, int with_exact, int with_norm)
{
    static const char *const csv_header[3] = {CLI_POINTSET_CSV_HEADER, CLI_POINTSET2D_CSV_HEADER,
                                              CLI_RADIAL_CSV_HEADER};
    static const char *const norm_header[3] = {
        ",freq" CLI_NORM_SUFFIX, ",kx" CLI_NORM_SUFFIX ",ky" CLI_NORM_SUFFIX,
        ",radius" CLI_NORM_SUFFIX};
    if (csv) {
        printf("%s%s%s\n", csv_header[layout], with_exact ? CLI_EXACT_CSV_HEADER : "",
               with_norm ? norm_header[layout] : "");
        return;
    }
    if (layout == CLI_PS_1D)
        printf("%5s", "freq");
    else if (layout == CLI_PS_2D)
        printf("%5s %5s", "kx", "ky");
    else
        printf("%6s", "radius");
    printf(" %13s %13s", "power", "power_stderr");
    if (layout == CLI_PS_RADIAL)
        printf(" %13s", "anisotropy_db");
    if (with_exact)
        printf(" %13s %13s", "exact", "z_exact");
    if (with_norm && layout == CLI_PS_2D)
        printf(" %13s %13s", "kx" CLI_NORM_SUFFIX, "ky" CLI_NORM_SUFFIX);
    else if (with_norm)
        printf(" %13s", layout == CLI_PS_1D ? "freq" CLI_NORM_SUFFIX : "radius" CLI_NORM_SUFFIX);
    putchar('\n');
}

void cli_print_ps(int csv, cli_ps_layout layout, int with_exact, const cli_ps_row *rows,
                  size_t nrows)
{
    cli_print_ps_norm(csv, layout, with_exact, 0.0, rows, nrows);
}

void cli_print_ps_norm(int csv, cli_ps_layout layout, int with_exact, double norm,
                       const cli_ps_row *rows, size_t nrows)
{
    const int with_norm = norm > 0.0;
    print_ps_header(csv, layout, with_exact, with_norm);
    for (size_t i = 0; i < nrows; ++i) {
        const cli_ps_row *r = &rows[i];
        if (layout == CLI_PS_2D)
            printf(csv ? "%ld,%ld" : "%5ld %5ld", r->kx, r->ky);
        else
            printf(csv ? "%ld" : (layout == CLI_PS_1D ? "%5ld" : "%6ld"), r->kx);
        double v[7];
        size_t nv = 0u;
        v[nv++] = r->power;
        v[nv++] = r->power_stderr;
        if (layout == CLI_PS_RADIAL)
            v[nv++] = r->anisotropy_db;
        if (with_exact) {
            v[nv++] = r->exact;
            v[nv++] = r->z_exact;
        }
        if (with_norm)
            v[nv++] = (double)r->kx / norm;
        if (with_norm && layout == CLI_PS_2D)
            v[nv++] = (double)r->ky / norm;
        cli_print_values(csv, v, nv);
    }
}

void cli_ps_as_spectrum(const cli_ps_row *rows, size_t nrows, cli_spectrum_row *out)
{
    for (size_t i = 0; i < nrows; ++i) {
        cli_spectrum_row *o = &out[i];
        o->freq = (size_t)rows[i].kx;
        o->mean_re = o->mean_im = o->mean_stderr = o->closed = o->z_closed = (double)NAN;
        o->power = rows[i].power;
        o->power_stderr = rows[i].power_stderr;
        o->exact = rows[i].exact;
        o->z_exact = rows[i].z_exact;
    }
}

static void print_notes(const cli_ps_report *rep)
{
    for (size_t i = 0; rep->notes != NULL && rep->notes[i] != NULL; ++i)
        cli_note(rep->csv, "%s", rep->notes[i]);
}

/* The exact average over the annuli r..r + width - 1: the unit annuli's,
 * weighted by their sizes. */
static double exact_band(const cli_exact2d *ex, size_t r, size_t width)
{
    double sum = 0.0, n = 0.0;
    for (size_t q = r; q < r + width; ++q) {
        size_t m = 0u;
        if (mcs_pointset2d_ring_size(q, &m) != MCS_OK)
            return (double)NAN;
        sum += (double)m * ex->radial(ex->ctx, q);
        n += (double)m;
    }
    return sum / n;
}

/* The exact values and z-scores of rows (layout 2D or radial; annuli of
 * width `width`). */
static void fill_exact(const cli_exact2d *ex, cli_ps_layout layout, size_t width,
                       cli_ps_row *rows, size_t nrows)
{
    for (size_t i = 0; i < nrows; ++i)
        rows[i].exact = layout == CLI_PS_2D ? ex->at(ex->ctx, rows[i].kx, rows[i].ky)
                        : width == 1u        ? ex->radial(ex->ctx, (size_t)rows[i].kx)
                                             : exact_band(ex, (size_t)rows[i].kx, width);
    cli_ps_rows_z(rows, nrows, ex->scale);
}

/* The radial rows of annuli other than the unit ones. */
static void bin_rows(const cli_ps_bins *bins, cli_ps_row *ring, size_t *nring)
{
    for (size_t b = 0; b < bins->count; ++b) {
        blank_ps_row(&ring[b], (long)(b * bins->width), 0);
        bins->at(bins->ctx, b, &ring[b].power, &ring[b].power_stderr, &ring[b].anisotropy_db);
    }
    *nring = bins->count;
}

/* Both layouts' rows of acc, exact values filled: plane[] (when not NULL),
 * ring[]. */
static int rows2d(const char *cmd, const cli_ps_report *rep, const cli_ps_extra *extra,
                  const mcs_pointset2d *acc, cli_ps_row *plane, size_t *nplane, cli_ps_row *ring,
                  size_t *nring)
{
    int rc = plane != NULL ? cli_ps_rows(cmd, CLI_PS_2D, acc, plane, nplane) : 0;
    if (rc == 0 && extra->bins != NULL)
        bin_rows(extra->bins, ring, nring);
    else if (rc == 0)
        rc = cli_ps_rows(cmd, CLI_PS_RADIAL, acc, ring, nring);
    const size_t width = extra->bins != NULL ? extra->bins->width : 1u;
    if (rc == 0 && rep->exact != NULL) {
        if (plane != NULL)
            fill_exact(rep->exact, CLI_PS_2D, 1u, plane, *nplane);
        fill_exact(rep->exact, CLI_PS_RADIAL, width, ring, *nring);
    }
    return rc;
}

int cli_write_pfm(const char *cmd, const char *path, const cli_ps_row *plane, size_t nplane)
{
    /* (2F + 1)^2 rows, ky = -F..F outer, kx = -F..F inner: PFM's order,
     * whose first scan line is the bottom one. */
    const size_t side = (size_t)(2 * plane[nplane - 1u].kx + 1);
    char head[64];
    const int hlen = snprintf(head, sizeof head, "Pf\n%zu %zu\n-1.0\n", side, side);
    const size_t len = (size_t)hlen + 4u * nplane;
    unsigned char *buf = cli_alloc(cmd, 1, len);
    if (buf == NULL)
        return CLI_EXIT_FAIL;
    memcpy(buf, head, (size_t)hlen);
    for (size_t i = 0; i < nplane; ++i) {
        const float v = (float)plane[i].power;
        uint32_t u = 0u;
        memcpy(&u, &v, sizeof u);
        unsigned char *o = buf + hlen + 4u * i; /* little-endian, the scale's sign says */
        o[0] = (unsigned char)(u & 0xFFu);
        o[1] = (unsigned char)((u >> 8) & 0xFFu);
        o[2] = (unsigned char)((u >> 16) & 0xFFu);
        o[3] = (unsigned char)(u >> 24);
    }
    const int rc = cli_write_atomic(cmd, path, buf, len);
    free(buf);
    return rc;
}

int cli_report_pointset2d(const char *cmd, const cli_ps_report *rep, const mcs_pointset2d *acc)
{
    const cli_ps_extra none = {0.0, NULL, NULL};
    return cli_report_pointset2d_with(cmd, rep, &none, acc);
}

int cli_report_pointset2d_with(const char *cmd, const cli_ps_report *rep,
                               const cli_ps_extra *extra, const mcs_pointset2d *acc)
{
    const size_t f = acc->freq_max;
    /* The plane's (2F + 1)^2 rows only where they are printed or drawn: at
     * F = 2048 they are 1.2 GB, the annuli 2049 rows. */
    const int need_plane = !rep->radial || rep->plot != NULL || extra->pfm != NULL;
    cli_ps_row *plane =
        need_plane ? cli_alloc(cmd, cli_ps_row_count(CLI_PS_2D, f), sizeof *plane) : NULL;
    cli_ps_row *ring = cli_alloc(cmd, cli_ps_row_count(CLI_PS_RADIAL, f), sizeof *ring);
    size_t nplane = 0u, nring = 0u;
    int rc = (plane != NULL || !need_plane) && ring != NULL ? 0 : CLI_EXIT_FAIL;
    if (rc == 0)
        rc = rows2d(cmd, rep, extra, acc, plane, &nplane, ring, &nring);
    if (rc == 0 && rep->plot != NULL) {
        const char *exact = rep->exact != NULL ? rep->exact_label : NULL;
        const cli_plot_info info = {rep->title, rep->subtitle, exact, NULL, NULL, rep->log_y};
        rc = cli_plot_pointset2d(cmd, rep->plot, &info, plane, nplane, ring, nring);
    }
    if (rc == 0 && extra->pfm != NULL)
        rc = cli_write_pfm(cmd, extra->pfm, plane, nplane);
    if (rc == 0)
        print_notes(rep);
    if (rc == 0 && rep->radial)
        cli_print_ps_norm(rep->csv, CLI_PS_RADIAL, rep->exact != NULL, extra->norm, ring, nring);
    else if (rc == 0)
        cli_print_ps_norm(rep->csv, CLI_PS_2D, rep->exact != NULL, extra->norm, plane, nplane);
    free(plane);
    free(ring);
    return rc;
}

int cli_report_pointset(const char *cmd, const cli_ps_report *rep, const mcs_pointset *acc)
{
    const cli_ps_extra none = {0.0, NULL, NULL};
    return cli_report_pointset_with(cmd, rep, &none, acc);
}

int cli_report_pointset_with(const char *cmd, const cli_ps_report *rep, const cli_ps_extra *extra,
                             const mcs_pointset *acc)
{
    const size_t nmax = cli_ps_row_count(CLI_PS_1D, acc->freq_max);
    cli_ps_row *rows = cli_alloc(cmd, nmax, sizeof *rows);
    cli_spectrum_row *plot_rows = cli_alloc(cmd, nmax, sizeof *plot_rows);
    size_t nrows = 0u;
    int rc = rows != NULL && plot_rows != NULL ? 0 : CLI_EXIT_FAIL;
    if (rc == 0)
        rc = cli_ps_rows(cmd, CLI_PS_1D, acc, rows, &nrows);
    if (rc == 0 && rep->plot != NULL) {
        const cli_plot_info info = {rep->title, rep->subtitle, NULL, NULL,
                                    "⟨P(f)⟩   (point-set periodogram, mean over trials)",
                                    rep->log_y};
        cli_ps_as_spectrum(rows, nrows, plot_rows);
        rc = cli_plot_spectrum(cmd, rep->plot, &info, plot_rows, nrows);
    }
    if (rc == 0) {
        print_notes(rep);
        cli_print_ps_norm(rep->csv, CLI_PS_1D, 0, extra->norm, rows, nrows);
    }
    free(plot_rows);
    free(rows);
    return rc;
}
