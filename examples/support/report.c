#include "report.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char ex_common_usage[] =
    "options:\n"
    "  --n N         number of bins N\n"
    "  --k K         samples per trial K\n"
    "  --trials T    trials per measured quantity\n"
    "  --seed S      PCG32 seed (same seed, same output)\n"
    "  --csv         one CSV header line, then one row per table row\n"
    "  --help        this text\n";

const char ex_verdict_rules[] =
    "columns: closed = the note's closed form (for a bound row, the bound);\n"
    "exact = the exact discrete prediction (mcspec theory); measured +- stderr over\n"
    "the trials; z = (measured - prediction) / max(stderr, floor), floor being the\n"
    "row's rounding scale (1e-10 of K/N or K^2/N for spectra, 1e-12 of the size of\n"
    "a variance), so deterministic values that agree get z = 0;\n"
    "gap = |closed - exact| / max(|closed|, |exact|, floor).\n"
    "verdict, computed per row from those numbers (empty if closed or exact is -):\n"
    "  holds   gap <= 1e-9 (0 if |closed - exact| <= floor): the closed form is exact here\n"
    "  limit   not exact, but an N -> infinity form whose gap to the exact value\n"
    "          at a larger N (computed from exact finite-N values) is less than\n"
    "          half its gap at this N\n"
    "  fails   neither, and |z_closed| > 5 while |z_exact| <= 5: measured and\n"
    "          exact agree, the closed form does not\n"
    "  approx  otherwise: not exact, but this many trials do not separate it from\n"
    "          the exact value; the gap column states the size of its error\n"
    "bound rows (the note's inequalities): closed is the bound;\n"
    "  holds   exact <= bound (1e-9 relative): the bound is valid here\n"
    "  fails   exact > bound and z_closed > 5 while |z_exact| <= 5: the\n"
    "          measurement lies above the bound\n"
    "  approx  otherwise\n";

static int parse_u64(const char *s, uint64_t *out)
{
    if (s == NULL || *s == '\0' || *s == '-')
        return 0;
    char *end = NULL;
    errno = 0;
    unsigned long long v = strtoull(s, &end, 10);
    if (errno != 0 || end == NULL || *end != '\0')
        return 0;
    *out = (uint64_t)v;
    return 1;
}

static void usage_error(const char *prog, const char *what, const char *arg)
{
    fprintf(stderr, "%s: %s%s%s\n\nusage: %s [options]\n%s", prog, what, arg ? ": " : "",
            arg ? arg : "", prog, ex_common_usage);
}

/* Which of --n, --k, --trials, --seed argv[*i] names (-1 if none), and its
 * value: after '=' in the same word, else the next word (NULL if missing). */
static int option_of(int argc, char **argv, int *i, const char **val)
{
    static const char *const names[4] = {"--n", "--k", "--trials", "--seed"};
    const char *a = argv[*i];
    for (int w = 0; w < 4; ++w) {
        size_t len = strlen(names[w]);
        if (strcmp(a, names[w]) == 0) {
            *val = (*i + 1 < argc) ? argv[++*i] : NULL;
            return w;
        }
        if (strncmp(a, names[w], len) == 0 && a[len] == '=') {
            *val = a + len + 1;
            return w;
        }
    }
    return -1;
}

/* v in 1..max for --n or --k (name); else says so and returns 0. */
static int size_in_range(const char *prog, const char *name, uint64_t v, size_t max,
                         const char *val)
{
    if (v >= 1u && v <= max)
        return 1;
    char what[32];
    fprintf(stderr, "%s: %s must be in 1..%zu\n", prog, name, max);
    snprintf(what, sizeof what, "bad value for %s", name);
    usage_error(prog, what, val);
    return 0;
}

/* Stores option `which` = v in *opt; returns 0 (after the usage) if out of range. */
static int set_option(const char *prog, int which, uint64_t v, const char *val, ex_options *opt,
                      size_t max_n, size_t max_k)
{
    switch (which) {
    case 0:
        if (!size_in_range(prog, "--n", v, max_n, val))
            return 0;
        opt->n = (size_t)v;
        return 1;
    case 1:
        if (!size_in_range(prog, "--k", v, max_k, val))
            return 0;
        opt->k = (size_t)v;
        return 1;
    case 2:
        if (v < 4u || v > 100000000u) {
            usage_error(prog, "--trials must be in 4..100000000", val);
            return 0;
        }
        opt->trials = (unsigned long)v;
        return 1;
    default:
        opt->seed = v;
        return 1;
    }
}

static void print_help(const char *prog, const ex_options *opt, size_t max_n, const char *help)
{
    printf("usage: %s [options]\n\n%s\n%sdefaults: --n %zu (at most %zu) --k %zu "
           "--trials %lu --seed %" PRIu64 "\n\n%s",
           prog, help, ex_common_usage, opt->n, max_n, opt->k, opt->trials, opt->seed,
           ex_verdict_rules);
}

int ex_parse_options(int argc, char **argv, ex_options *opt, size_t max_n, size_t max_k,
                     const char *help)
{
    const char *prog = argc > 0 ? argv[0] : "example";
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            print_help(prog, opt, max_n, help);
            return EX_PARSE_HELP;
        }
        if (strcmp(a, "--csv") == 0) {
            opt->csv = 1;
            continue;
        }
        const char *val = NULL;
        int which = option_of(argc, argv, &i, &val);
        if (which < 0) {
            usage_error(prog, "unknown option", a);
            return EX_PARSE_ERROR;
        }
        uint64_t v = 0;
        if (!parse_u64(val, &v)) {
            usage_error(prog, "not a non-negative integer", val ? val : "(missing)");
            return EX_PARSE_ERROR;
        }
        if (!set_option(prog, which, v, val, opt, max_n, max_k))
            return EX_PARSE_ERROR;
    }
    return EX_PARSE_OK;
}

static double floor_or_tiny(double abs_floor)
{
    return abs_floor > 0.0 ? abs_floor : 1e-300;
}

double ex_z(double measured, double predicted, double stderr_, double abs_floor)
{
    if (isnan(measured) || isnan(predicted) || isnan(stderr_))
        return EX_NA;
    double scale = fmax(stderr_, floor_or_tiny(abs_floor));
    return (measured - predicted) / scale;
}

double ex_z_complex(ex_complex measured, ex_complex predicted, ex_complex stderr_,
                    double abs_floor)
{
    return fmax(fabs(ex_z(measured.re, predicted.re, stderr_.re, abs_floor)),
                fabs(ex_z(measured.im, predicted.im, stderr_.im, abs_floor)));
}

double ex_rel_gap(double closed_form, double exact, double abs_floor)
{
    double fl = floor_or_tiny(abs_floor), d = fabs(closed_form - exact);
    if (d <= fl)
        return 0.0; /* a difference below the rounding scale is no difference */
    return d / fmax(fmax(fabs(closed_form), fabs(exact)), fl);
}

/* The measurement sides with the exact value against the closed form. */
static int refutes(double zc, double ze)
{
    return !isnan(zc) && !isnan(ze) && fabs(zc) > EX_Z_REJECT && fabs(ze) <= EX_Z_REJECT;
}

const char *ex_verdict(double closed_form, double exact, double measured, double stderr_,
                       double gap_larger_n, double abs_floor)
{
    double gap = ex_rel_gap(closed_form, exact, abs_floor);
    if (gap <= EX_EXACT_RTOL)
        return "holds";
    if (!isnan(gap_larger_n) && gap_larger_n < 0.5 * gap)
        return "limit";
    double zc = ex_z(measured, closed_form, stderr_, abs_floor);
    double ze = ex_z(measured, exact, stderr_, abs_floor);
    if (refutes(zc, ze))
        return "fails";
    return "approx";
}

const char *ex_verdict_bound(double bound, double exact, double measured, double stderr_,
                             double abs_floor)
{
    double scale = fmax(fmax(fabs(bound), fabs(exact)), floor_or_tiny(abs_floor));
    if (exact - bound <= EX_EXACT_RTOL * scale)
        return "holds";
    double zc = ex_z(measured, bound, stderr_, abs_floor);
    double ze = ex_z(measured, exact, stderr_, abs_floor);
    if (refutes(zc, ze) && zc > 0.0)
        return "fails";
    return "approx";
}

static unsigned disagreements = 0u;

static void csv_double(double v)
{
    if (isnan(v))
        printf(",");
    else
        printf(",%.10g", v);
}

static void csv_freq(long f)
{
    if (f < 0)
        printf(",");
    else
        printf(",%ld", f);
}

void ex_begin(const ex_options *opt, const char *title)
{
    disagreements = 0u;
    if (opt->csv) {
        printf("section,quantity,equation,pattern,n,k,freq,freq2,closed_form,exact,measured,"
               "stderr,z_closed,z_exact,verdict\n");
        return;
    }
    printf("%s\n", title);
    printf("N = %zu bins, K = %zu samples, %lu trials, seed %" PRIu64 "\n", opt->n, opt->k,
           opt->trials, opt->seed);
    printf("(verdict rules: --help)\n\n");
    printf("%-30s %-9s %-15s %-7s %12s %12s %12s %10s %8s %8s %8s  %s\n", "quantity", "eq.",
           "pattern", "freq", "closed", "exact", "measured", "stderr", "z_closed", "z_exact",
           "gap", "verdict");
}

static void table_double(double v, int width, int prec)
{
    if (isnan(v))
        printf(" %*s", width, "-");
    else if (isinf(v))
        printf(" %*s", width, v > 0 ? "+inf" : "-inf");
    else
        printf(" %*.*g", width, prec, v);
}

static const char *row_print(const ex_options *opt, const ex_row *row, int bound)
{
    double zc = ex_z(row->measured, row->closed_form, row->stderr_, row->abs_floor);
    double ze = ex_z(row->measured, row->exact, row->stderr_, row->abs_floor);
    int comparable = !isnan(row->closed_form) && !isnan(row->exact);
    double gap = comparable ? ex_rel_gap(row->closed_form, row->exact, row->abs_floor) : EX_NA;
    const char *verdict = "";
    if (comparable && bound)
        verdict = ex_verdict_bound(row->closed_form, row->exact, row->measured, row->stderr_,
                                   row->abs_floor);
    else if (comparable)
        verdict = ex_verdict(row->closed_form, row->exact, row->measured, row->stderr_,
                             row->limit_gap, row->abs_floor);
    if (!isnan(ze) && fabs(ze) > EX_Z_REJECT)
        ++disagreements;
    if (opt->csv) {
        printf("%s,%s,%s,%s,%zu,%zu", row->section, row->quantity, row->equation, row->pattern,
               opt->n, opt->k);
        csv_freq(row->freq);
        csv_freq(row->freq2);
        csv_double(row->closed_form);
        csv_double(row->exact);
        csv_double(row->measured);
        csv_double(row->stderr_);
        csv_double(zc);
        csv_double(ze);
        printf(",%s\n", verdict);
        return verdict;
    }
    char freq[48] = "-";
    if (row->freq >= 0 && row->freq2 >= 0)
        snprintf(freq, sizeof freq, "%ld,%ld", row->freq, row->freq2);
    else if (row->freq >= 0)
        snprintf(freq, sizeof freq, "%ld", row->freq);
    printf("%-30s %-9s %-15s %-7s", row->quantity, row->equation, row->pattern, freq);
    table_double(row->closed_form, 12, 6);
    table_double(row->exact, 12, 6);
    table_double(row->measured, 12, 6);
    table_double(row->stderr_, 10, 3);
    table_double(zc, 8, 3);
    table_double(ze, 8, 3);
    table_double(gap, 8, 2);
    printf("  %s%s\n", bound ? "bound " : "", verdict);
    return verdict;
}

ex_row ex_row_of(const char *section, const char *quantity, const char *equation,
                 const char *pattern, long freq, long freq2, double closed_form, double exact,
                 double measured, double stderr_, double abs_floor)
{
    ex_row r = {section, quantity, equation, pattern, freq, freq2, closed_form, exact,
                measured, stderr_, EX_NA, abs_floor};
    return r;
}

const char *ex_row_print(const ex_options *opt, const ex_row *row)
{
    return row_print(opt, row, 0);
}

const char *ex_row_print_bound(const ex_options *opt, const ex_row *row)
{
    return row_print(opt, row, 1);
}

void ex_row_print_complex(const ex_options *opt, const char *section, const char *quantity,
                          const char *equation, const char *pattern, long freq, long freq2,
                          ex_complex closed_form, ex_complex exact, ex_complex measured,
                          ex_complex stderr_, double abs_floor)
{
    char re[96], im[96];
    snprintf(re, sizeof re, "Re %s", quantity);
    snprintf(im, sizeof im, "Im %s", quantity);
    ex_row r = ex_row_of(section, re, equation, pattern, freq, freq2, closed_form.re, exact.re,
                         measured.re, stderr_.re, abs_floor);
    ex_row_print(opt, &r);
    r = ex_row_of(section, im, equation, pattern, freq, freq2, closed_form.im, exact.im,
                  measured.im, stderr_.im, abs_floor);
    ex_row_print(opt, &r);
}

void ex_heading(const ex_options *opt, const char *text)
{
    if (!opt->csv)
        printf("\n-- %s\n", text);
}

void ex_note(const ex_options *opt, const char *text)
{
    if (!opt->csv)
        printf("%s\n", text);
}

void ex_notef(const ex_options *opt, const char *fmt, ...)
{
    if (opt->csv)
        return;
    va_list ap;
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
}

unsigned ex_end(const ex_options *opt)
{
    if (!opt->csv) {
        if (disagreements > 0u)
            printf("\nWARNING: %u row(s) with |z_exact| > %g: the measurement disagrees with "
                   "the exact prediction\n",
                   disagreements, EX_Z_REJECT);
        else
            printf("\nEvery measured value agrees with its exact prediction (|z_exact| <= %g).\n",
                   EX_Z_REJECT);
    }
    return disagreements;
}

int ex_take_option(int *argc, char **argv, const char *name, const char **value)
{
    const size_t len = strlen(name);
    for (int i = 1; i < *argc; ++i) {
        const char *a = argv[i];
        int used = 0;
        if (strcmp(a, name) == 0) {
            if (i + 1 >= *argc) {
                usage_error(argv[0], "missing value for", name);
                return -1;
            }
            *value = argv[i + 1];
            used = 2;
        } else if (strncmp(a, name, len) == 0 && a[len] == '=') {
            *value = a + len + 1;
            used = 1;
        }
        if (used > 0) {
            for (int j = i; j + used < *argc; ++j)
                argv[j] = argv[j + used];
            *argc -= used;
            return 1;
        }
    }
    return 0;
}

double ex_variance_floor(size_t n, size_t k, const double *f, double v)
{
    double f2 = 0.0;
    for (size_t b = 0; b < n; ++b)
        f2 += f[b] * f[b] / (double)n;
    return fmax(1e-12 * fmax(fabs(v), 1e-12), 1e-15 * f2 / (double)k);
}

double ex_integrand(double x)
{
    const double pi = 3.14159265358979323846;
    return 0.5 + 0.3 * sin(2.0 * pi * x) + (x >= 0.3 ? 0.4 : 0.0);
}

void ex_integrand_bins(size_t n, double *f)
{
    for (size_t b = 0; b < n; ++b)
        f[b] = ex_integrand(((double)b + 0.5) / (double)n);
}
