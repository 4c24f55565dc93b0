/* Spectrum rows, table and CSV (see output.h). */
#include "output.h"
#include "cli.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>

/* A standard error, or NaN when the accumulator has too few trials for one. */
static double stderr_or_nan(mcs_status st, const double *v)
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
        r->mean_stderr = stderr_or_nan(mcs_spectrum_mean_stderr(acc, f, &se), &se);
        r->power_stderr = stderr_or_nan(mcs_spectrum_power_stderr(acc, f, &se), &se);
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
