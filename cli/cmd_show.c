/* mcspec show: what a saved accumulator holds. */
#include "cli.h"
#include "input.h"
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
    "                   [--importance WEIGHTS]\n"
    "\n"
    "Prints the accumulator saved in FILE (by --save, mcspec merge or\n"
    "mcspec-mpi; the format is docs/format.md), after checking the whole record:\n"
    "a truncated, corrupted or unknown file is refused with what is wrong. Above\n"
    "the table: where its trials came from (its provenance: the pattern run and\n"
    "the streams it holds, or the point files it read; none in a version 1\n"
    "record).\n"
    "\n"
    "spectrum  the half spectrum k = 0..N/2 as mcspec spectrum prints it: <S_k>,\n"
    "          its standard error, <|S_k|^2> and its standard error (eq. 7, 14);\n"
    "          a record of a 1D pattern run (mcspec pattern --save, merge, mcspec-\n"
    "          mpi) also the exact and closed-form predictions and their z-scores,\n"
    "          as mcspec pattern prints them: the pattern is rebuilt from the\n"
    "          provenance (with an importance function, give its weights again)\n"
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
    "pcf, integrate, discrepancy, spacing  the table and CSV of mcspec pcf,\n"
    "          integrate, discrepancy and stats (the same header and columns),\n"
    "          but what a record cannot rebuild, left empty: the pcf's exact\n"
    "          column unless the record is of a drawn pattern (mcspec pcf KIND;\n"
    "          discrepancy and stats rebuild theirs from a drawn KIND too),\n"
    "          integrate's predicted, predicted_tail, freq and slope (they need\n"
    "          the sets' spectrum and integrands; k is empty for a merge of\n"
    "          records of different K), and for spacing the spectral rows of\n"
    "          mcspec stats (only min_distance and avg_min_distance are in it)\n"
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
    "  --importance WEIGHTS  the importance function a pattern record was drawn\n"
    "               with (the file given to mcspec pattern --importance), for the\n"
    "               predictions; its weights must have the checksum the record\n"
    "               keeps (exit 2 otherwise). Without it such a record shows the\n"
    "               measured columns only\n"
    "  --help       this text\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage or input (one line on stderr).\n";

typedef struct {
    const char *path, *plot;
    int csv, radial;
    int log_y; /* --log */
    const char *importance;
} show_opts;

static int parse(int argc, char **argv, show_opts *o)
{
    cli_opt opts[] = {
        {"csv", CLI_OPT_FLAG, &o->csv, 0, 0, 0},
        {"plot", CLI_OPT_STRING, &o->plot, 0, 0, 0},
        {"radial", CLI_OPT_FLAG, &o->radial, 0, 0, 0},
        {"log", CLI_OPT_FLAG, &o->log_y, 0, 0, 0},
        {"importance", CLI_OPT_STRING, &o->importance, 0, 0, 0},
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
static int show_pointset(const show_opts *o, const cli_acc *acc, const char *title,
                         const char *origin)
{
    const char *const notes[] = {title, origin, "", NULL};
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

/* What mcspec pattern predicted for the run a spectrum record's provenance
 * names, rebuilt: the pattern (and with --importance its importance
 * function, checked against the record's checksum) and cli_predict_power. */
typedef struct {
    int have;                /* the predictions below are set */
    cli_prediction *pred;
    double scale;            /* K/N, the z-scores' rounding scale, as mcspec pattern's */
    char why[256];           /* when not: the note saying why */
} show_theory;

/* The importance function of o->importance for prov (n bins) into imp. */
static int load_importance(const show_opts *o, const mcs_io_provenance *prov, size_t n,
                           mcs_importance *imp)
{
    double *w = NULL;
    size_t count = 0u;
    int rc = cli_read_values(CMD, o->importance, "importance weight", 1, MCS_MAX_N, &w, &count);
    if (rc != 0)
        return rc;
    const char *name = cli_input_name(o->importance);
    const uint32_t crc = count == n ? cli_weights_crc(n, w) : 0u;
    mcs_status st = MCS_OK;
    if (count != n)
        rc = cli_fail(CMD, "%s holds %zu importance weights, but %s has N = %zu bins", name,
                      count, o->path, n);
    else if (crc != prov->importance_crc)
        rc = cli_fail(CMD, "%s is not the importance function %s was drawn with (its weights' "
                      "CRC-32 is 0x%08lx, the record's 0x%08lx)", name, o->path,
                      (unsigned long)crc, (unsigned long)prov->importance_crc);
    else
        st = mcs_importance_init(imp, n, w);
    free(w);
    if (rc == 0 && st != MCS_OK)
        rc = cli_fail(CMD, "%s: not an importance function: %s", name, mcs_status_str(st));
    return rc;
}

static int predict(const show_opts *o, const mcs_spectrum *acc, const mcs_io_provenance *prov,
                   show_theory *th)
{
    const int drawn = prov->source == MCS_IO_SOURCE_PATTERN && prov->dim == 1u;
    th->have = 0;
    if (!drawn) {
        snprintf(th->why, sizeof th->why, "%s", "");
        return o->importance == NULL ? 0
                                     : cli_fail(CMD, "%s holds no pattern run: --importance is "
                                                "for records of mcspec pattern", o->path);
    }
    if (prov->n != acc->n)
        return cli_fail(CMD, "%s: its provenance says N = %llu, its spectrum N = %zu: not a "
                        "record mcspec writes", o->path, (unsigned long long)prov->n, acc->n);
    if (!prov->importance && o->importance != NULL)
        return cli_fail(CMD, "%s was drawn without an importance function: drop --importance",
                        o->path);
    if (prov->importance && o->importance == NULL) {
        snprintf(th->why, sizeof th->why, "exact, closed: give --importance WEIGHTS, the weights "
                 "the run was drawn with (CRC-32 0x%08lx)", (unsigned long)prov->importance_crc);
        return 0;
    }
    const int kind = cli_pattern_kind(prov->pattern);
    if (kind < 0) {
        snprintf(th->why, sizeof th->why, "exact, closed: none (pattern '%s' unknown to this "
                 "build)", prov->pattern);
        return 0;
    }
    mcs_importance *imp = prov->importance ? cli_alloc(CMD, 1, sizeof *imp) : NULL;
    if (prov->importance && imp == NULL)
        return CLI_EXIT_FAIL;
    int rc = prov->importance ? load_importance(o, prov, acc->n, imp) : 0;
    mcs_pattern pat;
    mcs_status st = rc == 0 ? mcs_pattern_init(&pat, (mcs_pattern_kind)kind, acc->n,
                                               (size_t)prov->k, imp)
                            : MCS_OK;
    if (rc == 0 && st != MCS_OK)
        rc = cli_fail(CMD, "%s: its provenance names a pattern this build cannot set up "
                      "(%s, K = %llu): %s", o->path, prov->pattern, (unsigned long long)prov->k,
                      mcs_status_str(st));
    if (rc == 0)
        rc = cli_predict_power(CMD, &pat, th->pred);
    free(imp);
    th->have = rc == 0;
    th->scale = (double)prov->k / (double)acc->n;
    return rc;
}

static int show_spectrum(const show_opts *o, const cli_acc *acc, const mcs_io_provenance *prov,
                         const char *title, const char *origin)
{
    cli_spectrum_row *rows = cli_alloc(CMD, CLI_HALF_MAX, sizeof *rows);
    show_theory th = {0, cli_alloc(CMD, 1, sizeof *th.pred), 1.0, ""};
    if (rows == NULL || th.pred == NULL) {
        free(rows);
        free(th.pred);
        return CLI_EXIT_FAIL;
    }
    size_t nrows = 0u;
    int rc = 0;
    if (acc->kind == MCS_IO_KIND_SPECTRUM)
        rc = predict(o, acc->obj, prov, &th);
    else if (o->importance != NULL)
        rc = cli_fail(CMD, "%s holds no pattern run: --importance is for records of mcspec "
                      "pattern", o->path);
    if (rc == 0 && acc->kind == MCS_IO_KIND_SPECTRUM)
        rc = cli_spectrum_rows(CMD, acc->obj, th.have ? th.pred : NULL, th.scale, rows, &nrows);
    else if (rc == 0 && acc->kind == MCS_IO_KIND_MOMENT)
        rc = moment_rows(acc->obj, rows, &nrows);
    else if (rc == 0)
        rc = autocorr_rows(acc->obj, rows, &nrows);
    char exact[160], closed[160];
    snprintf(exact, sizeof exact, "exact: %s", th.pred->exact_source);
    snprintf(closed, sizeof closed, "closed form: %s", th.pred->closed_source);
    if (rc == 0 && o->plot != NULL) {
        cli_plot_info info = {title, "k = 0 not drawn",
                              th.have && th.pred->exact_source[0] != '\0' ? exact : NULL,
                              th.have && th.pred->closed_source[0] != '\0' ? closed : NULL, NULL,
                              o->log_y};
        rc = cli_plot_spectrum(CMD, o->plot, &info, rows, nrows);
    }
    if (rc == 0) {
        cli_note(o->csv, "%s", title);
        cli_note(o->csv, "%s", origin);
        if (th.have)
            cli_note(o->csv, "exact: %s; closed: %s; z = (power - prediction) / power_stderr",
                     th.pred->exact_source[0] != '\0' ? th.pred->exact_source : "none at this N",
                     th.pred->closed_source[0] != '\0' ? th.pred->closed_source
                                                       : "none in the note");
        else if (th.why[0] != '\0')
            cli_note(o->csv, "%s", th.why);
        cli_note(o->csv, "%s", "");
        cli_print_spectrum(o->csv, th.have, rows, nrows);
    }
    free(th.pred);
    free(rows);
    return rc;
}

static int show_welford(const show_opts *o, const mcs_welford *w, const char *origin)
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
    printf("%s: saved welford (a scalar's mean and spread)\n%s\n\n", o->path, origin);
    printf("%20s %13s %13s %13s %13s\n", "count", "mean", "mean_stderr", "variance",
           "variance_stderr");
    printf("%20llu %s %s %s %s\n", (unsigned long long)w->count, buf[0], buf[1], buf[2],
           buf[3]);
    return 0;
}

/* The title's second line: where the trials came from. */
static void origin_line(const mcs_io_provenance *prov, char *buf, size_t size)
{
    char text[1024];
    if (prov->source == MCS_IO_SOURCE_PATTERN)
        snprintf(buf, size, "drawn: %s", cli_provenance_describe(prov, text, sizeof text));
    else if (prov->source == MCS_IO_SOURCE_POINTS)
        snprintf(buf, size, "read from %s", cli_provenance_describe(prov, text, sizeof text));
    else
        snprintf(buf, size, "provenance: none (a format version 1 record)");
}

int cli_cmd_show(int argc, char **argv)
{
    show_opts o = {NULL, NULL, 0, 0, 0, NULL};
    int rc = parse(argc, argv, &o);
    if (rc != 0)
        return rc < 0 ? CLI_EXIT_OK : rc;
    cli_acc acc = {MCS_IO_KIND_SPECTRUM, NULL};
    mcs_io_provenance *prov = cli_alloc(CMD, 1, sizeof *prov);
    if (prov == NULL)
        return CLI_EXIT_FAIL;
    rc = cli_acc_read_with(CMD, o.path, &acc, prov, NULL);
    if (rc != 0) {
        free(prov);
        return rc;
    }
    char what[96], title[1600], origin[1100];
    cli_acc_describe(&acc, what, sizeof what);
    origin_line(prov, origin, sizeof origin);
    snprintf(title, sizeof title, "%s: %s, %llu trials", o.path, what,
             (unsigned long long)cli_acc_count(&acc));
    const int spectrum_like = acc.kind == MCS_IO_KIND_SPECTRUM || acc.kind == MCS_IO_KIND_MOMENT ||
                              acc.kind == MCS_IO_KIND_AUTOCORR;
    const int measure = acc.kind == MCS_IO_KIND_PCF || acc.kind == MCS_IO_KIND_INTEGRATE ||
                        acc.kind == MCS_IO_KIND_DISCREPANCY || acc.kind == MCS_IO_KIND_SPACING;
    if (o.importance != NULL && !spectrum_like)
        rc = cli_fail(CMD, "%s holds no pattern run: --importance is for records of mcspec "
                      "pattern", o.path);
    else if (o.plot != NULL && (acc.kind == MCS_IO_KIND_WELFORD ||
                                acc.kind == MCS_IO_KIND_SPECTRUM2D || measure))
        rc = cli_fail(CMD, "%s holds %s: no plot for it (drop --plot)", o.path, what);
    else if (o.radial && acc.kind != MCS_IO_KIND_POINTSET2D)
        rc = cli_fail(CMD, "%s holds %s: --radial is for pointset2d records", o.path, what);
    else if (acc.kind != MCS_IO_KIND_WELFORD && cli_acc_count(&acc) == 0u)
        rc = cli_fail(CMD, "%s holds %s with no trials: nothing to show", o.path, what);
    else if (o.plot != NULL && cli_plot_check_gnuplot(CMD) != 0)
        rc = CLI_EXIT_USAGE;
    else if (acc.kind == MCS_IO_KIND_WELFORD)
        rc = show_welford(&o, acc.obj, origin);
    else if (measure)
        rc = cli_show_measure(o.csv, &acc, prov, title, origin);
    else if (acc.kind == MCS_IO_KIND_POINTSET || acc.kind == MCS_IO_KIND_POINTSET2D)
        rc = show_pointset(&o, &acc, title, origin);
    else if (acc.kind == MCS_IO_KIND_SPECTRUM2D) {
        cli_note(o.csv, "%s\n%s\n", title, origin);
        show_spectrum2d(&o, acc.obj);
    } else {
        rc = show_spectrum(&o, &acc, prov, title, origin);
    }
    cli_acc_free(&acc);
    free(prov);
    return rc;
}
