/* mcspec variance: Var[I] of a caller's integrand, measured beside exact,
 * per pattern kind. */
#include "atomic.h"
#include "cli.h"
#include "input.h"
#include "predict.h"
#include "progress.h"
#include "record.h"
#include "trials.h"

#include "mcspec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define CMD "mcspec variance"
#define DEFAULT_TRIALS 10000u
#define DEFAULT_SEED 1u
#define CSV_HEADER                                                                          \
    "kind,n,k,trials,mean,mean_stderr,variance,variance_stderr,exact,z_exact,bias,exact_mean," \
    "z_mean"

static const char help[] =
    "usage: mcspec variance --k K [--trials T] [--seed S] [--kind KIND]\n"
    "                       [--importance FILE] [--csv] [--save FILE] [FILE|-]\n"
    "\n"
    "The variance of the Monte Carlo estimator I = (1/K) sum_n f_n s_n (eq. 8)\n"
    "of an integrand f given as N values, one per line, in FILE (or standard\n"
    "input: '-' or no FILE), for each pattern kind: T trials of K samples over\n"
    "the N bins, and per kind the mean of I with its standard error, the\n"
    "measured Var[I] with its standard error, the exact Var[I] and the z-score\n"
    "z = (variance - exact) / variance_stderr (0 for a deterministic estimate\n"
    "that agrees to rounding); and the estimator's exact bias <I> - (1/N) sum f_n,\n"
    "the exact mean (1/N) sum f_n + bias and z_mean = (mean - exact_mean) /\n"
    "mean_stderr. The bias is 0 but for the uniform pattern's fixed counts and the\n"
    "bins an importance weight of 0 never draws (their f_n is never sampled).\n"
    "'#' lines and blank lines in FILE are skipped;\n"
    "N is the number of values, 1.." CLI_STR(MCS_MAX_N) ".\n"
    "\n"
    "Exact: (1/K^2) f^T Cov(s) f for every N, kind and importance function, from\n"
    "mcs_theory's exact moments for N <= " CLI_STR(MCS_MAX_COV_N) " and from mcs_theory_spectrum\n"
    "above.\n"
    "\n"
    "Options:\n"
    "  --k K              samples per trial K, 1.." CLI_STR(CLI_MAX_K) " (required)\n"
    "  --trials T         trials per kind, at least 4 (default 10000)\n"
    "  --seed S           PCG32 seed (default 1); kind i (random 0, stratified 1,\n"
    "                     homogenized 2, uniform 3, jitter 4) runs on stream i, so\n"
    "                     its numbers do not depend on which other kinds run\n"
    "  --kind KIND        only this kind (default: every kind; with --importance,\n"
    "                     every kind but homogenized, which is not defined there)\n"
    "  --importance FILE  warp the samples through the importance function whose N\n"
    "                     weights (>= 0, one per line) are in FILE\n"
    "  --csv              print CSV only: the header\n"
    "                     " CSV_HEADER "\n"
    "                     and one row per kind; an empty field has no value\n"
    "  --save FILE        also save the estimator's accumulator (mean, M2, M3, M4\n"
    "                     of I; a welford record, docs/format.md) to FILE, written\n"
    "                     atomically (a regular file or a new name); needs --kind\n"
    "                     (one record per file)\n"
    "  --help             this text\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage or input (one line on stderr).\n";

typedef struct {
    size_t k;
    uint64_t trials, seed;
    const char *kind, *importance, *path;
    int csv;
    const char *save;
} variance_opts;

typedef struct {
    double mean, mean_se, var, var_se, exact, z, bias, exact_mean, z_mean;
    const char *source;
    mcs_welford acc; /* the estimator's statistics, for --save */
} variance_row;

static int parse(int argc, char **argv, variance_opts *o)
{
    cli_opt opts[] = {
        {"k", CLI_OPT_SIZE, &o->k, 1, CLI_MAX_K, 0},
        {"trials", CLI_OPT_U64, &o->trials, 4, UINT64_MAX / 2u, 0},
        {"seed", CLI_OPT_U64, &o->seed, 0, UINT64_MAX, 0},
        {"kind", CLI_OPT_STRING, &o->kind, 0, 0, 0},
        {"importance", CLI_OPT_STRING, &o->importance, 0, 0, 0},
        {"csv", CLI_OPT_FLAG, &o->csv, 0, 0, 0},
        {"save", CLI_OPT_STRING, &o->save, 0, 0, 0},
    };
    int rc = cli_parse_one(CMD, help, NULL, opts, CLI_COUNT(opts), argc, argv, &o->path);
    if (rc != CLI_PARSED)
        return rc;
    if (!opts[0].given)
        return cli_fail(CMD, "--k K is required (see %s --help)", CMD);
    if (o->kind != NULL && cli_pattern_kind(o->kind) < 0)
        return cli_fail(CMD, "unknown pattern '%s' for --kind (random, stratified, homogenized, "
                        "uniform, jitter)", o->kind);
    if (o->kind != NULL && o->importance != NULL && cli_pattern_kind(o->kind) == MCS_PATTERN_HOMOGENIZED)
        return cli_fail(CMD, "homogenized is not defined with an importance function; drop "
                        "--importance or choose another --kind");
    int stdin_uses = (o->path == NULL || strcmp(o->path, "-") == 0) +
                     (o->importance != NULL && strcmp(o->importance, "-") == 0);
    if (stdin_uses > 1)
        return cli_fail(CMD, "the integrand and --importance cannot both be read from '-'");
    if (o->path == NULL && isatty(STDIN_FILENO))
        return cli_fail(CMD, "no integrand: give a FILE of N values, or '-' to read standard input");
    if (o->save != NULL && o->kind == NULL)
        return cli_fail(CMD, "--save writes one record: choose its pattern with --kind KIND");
    if (o->save != NULL && cli_write_check(CMD, o->save) != 0)
        return CLI_EXIT_USAGE;
    return 0;
}

/* The integrand f, and the importance function if asked (into *imp_out). */
static int load_inputs(const variance_opts *o, double **f, size_t *n, mcs_importance *imp,
                       const mcs_importance **imp_out)
{
    int rc = cli_read_values(CMD, o->path, "integrand value", 0, MCS_MAX_N, f, n);
    if (rc != 0 || o->importance == NULL)
        return rc;
    double *w = NULL;
    size_t count = 0;
    rc = cli_read_values(CMD, o->importance, "importance weight", 1, MCS_MAX_N, &w, &count);
    if (rc == 0 && count != *n)
        rc = cli_fail(CMD, "%s holds %zu importance weights, but the integrand has %zu values",
                      cli_input_name(o->importance), count, *n);
    mcs_status st = rc == 0 ? mcs_importance_init(imp, *n, w) : MCS_OK;
    free(w);
    if (st != MCS_OK)
        rc = cli_fail(CMD, "%s: not an importance function: %s", cli_input_name(o->importance),
                      mcs_status_str(st));
    *imp_out = rc == 0 ? imp : NULL;
    return rc;
}

static double welford_or_nan(mcs_status (*fn)(const mcs_welford *, double *),
                             const mcs_welford *w)
{
    double v = 0.0;
    return fn(w, &v) == MCS_OK ? v : (double)NAN;
}

/* One kind: trials on stream `kind`, then the row. */
static int measure_kind(const variance_opts *o, mcs_pattern_kind kind, size_t n, const double *f,
                        const mcs_importance *imp, double f_mean, double f2_mean,
                        variance_row *row)
{
    mcs_pattern pat;
    mcs_status st = mcs_pattern_init(&pat, kind, n, o->k, imp);
    if (st != MCS_OK)
        return cli_fail(CMD, "cannot set up %s: %s", mcs_pattern_kind_str(kind), mcs_status_str(st));
    int rc = cli_predict_variance(CMD, &pat, f, &row->exact, &row->source);
    if (rc == 0)
        rc = cli_predict_bias(CMD, &pat, f, &row->bias);
    if (rc != 0)
        return rc;
    mcs_welford w;
    mcs_welford_init(&w);
    char label[96];
    snprintf(label, sizeof label, "%s %s", CMD, mcs_pattern_kind_str(kind));
    cli_progress progress;
    cli_progress_init(&progress, !o->csv, label, "trials", o->trials);
    cli_sinks sinks = {NULL, f, &w};
    rc = cli_run_trials(CMD, &pat, o->seed, (uint64_t)kind, 0u, o->trials, &sinks, &progress);
    cli_progress_end(&progress);
    if (rc != 0)
        return rc;
    row->mean = welford_or_nan(mcs_welford_mean, &w);
    row->mean_se = welford_or_nan(mcs_welford_stderr, &w);
    row->var = welford_or_nan(mcs_welford_variance, &w);
    row->var_se = welford_or_nan(mcs_welford_variance_stderr, &w);
    /* Rounding scale of a variance of values of size sqrt(mean f^2). */
    row->acc = w;
    row->z = cli_z(row->var, row->exact, row->var_se, 1e-12 * fmax(f2_mean, fabs(row->exact)));
    row->exact_mean = f_mean + row->bias;
    row->z_mean = cli_z(row->mean, row->exact_mean, row->mean_se, 1e-12 * sqrt(f2_mean));
    return 0;
}

static void print_row(const variance_opts *o, const char *kind, size_t n, const variance_row *r)
{
    double v[9] = {r->mean, r->mean_se, r->var,  r->var_se,      r->exact,
                   r->z,    r->bias,    r->exact_mean, r->z_mean};
    char buf[40];
    if (o->csv) {
        printf("%s,%zu,%zu,%llu", kind, n, o->k, (unsigned long long)o->trials);
        for (int i = 0; i < 9; ++i) {
            cli_csv_double(buf, sizeof buf, v[i]);
            printf(",%s", buf);
        }
        putchar('\n');
        return;
    }
    printf("%-12s", kind);
    for (int i = 0; i < 5; ++i) {
        cli_table_double(buf, sizeof buf, 14, v[i]);
        printf(" %s", buf);
    }
    if (isnan(r->z))
        printf(" %8s", "-");
    else
        printf(" %8.2f", r->z);
    cli_table_double(buf, sizeof buf, 12, r->bias);
    printf(" %s", buf);
    if (isnan(r->z_mean))
        printf(" %7s", "-");
    else
        printf(" %7.2f", r->z_mean);
    printf("  %s\n", r->source[0] != '\0' ? r->source : "none at this N");
}

static void print_header(const variance_opts *o, size_t n, const double *f,
                         const mcs_importance *imp)
{
    if (o->csv) {
        puts(CSV_HEADER);
        return;
    }
    double sum = 0.0;
    for (size_t i = 0; i < n; ++i)
        sum += f[i];
    printf("%s: integrand f from %s (N = %zu values, mean %.6g), K = %zu samples,\n", CMD,
           cli_input_name(o->path), n, sum / (double)n, o->k);
    printf("%llu trials per kind, seed %llu (kind i on stream i)\n", (unsigned long long)o->trials,
           (unsigned long long)o->seed);
    if (imp != NULL)
        printf("importance function: %s, harmonic mean H = %.6g\n", cli_input_name(o->importance),
               imp->harmonic_mean);
    printf("\n%-12s %14s %14s %14s %14s %14s %8s %12s %7s  %s\n", "kind", "mean", "mean_stderr",
           "variance", "var_stderr", "exact", "z_exact", "bias", "z_mean", "exact from");
}

static int run_kinds(const variance_opts *o, const double *f, size_t n, const mcs_importance *imp)
{
    double f1 = 0.0, f2 = 0.0;
    for (size_t i = 0; i < n; ++i) {
        f1 += f[i];
        f2 += f[i] * f[i] / (double)n;
    }
    f1 /= (double)n;
    variance_row rows[MCS_PATTERN_KIND_COUNT];
    int done[MCS_PATTERN_KIND_COUNT] = {0};
    for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i) {
        mcs_pattern_kind kind = (mcs_pattern_kind)i;
        if (o->kind != NULL ? cli_pattern_kind(o->kind) != i
                            : (imp != NULL && kind == MCS_PATTERN_HOMOGENIZED))
            continue;
        int rc = measure_kind(o, kind, n, f, imp, f1, f2, &rows[i]);
        if (rc != 0)
            return rc;
        done[i] = 1;
    }
    print_header(o, n, f, imp);
    for (int i = 0; i < MCS_PATTERN_KIND_COUNT; ++i)
        if (done[i])
            print_row(o, mcs_pattern_kind_str((mcs_pattern_kind)i), n, &rows[i]);
    if (o->save != NULL) {
        cli_acc saved = {MCS_IO_KIND_WELFORD, &rows[cli_pattern_kind(o->kind)].acc};
        return cli_acc_write(CMD, o->save, &saved);
    }
    return 0;
}

int cli_cmd_variance(int argc, char **argv)
{
    variance_opts o = {0, DEFAULT_TRIALS, DEFAULT_SEED, NULL, NULL, NULL, 0, NULL};
    int rc = parse(argc, argv, &o);
    if (rc != 0)
        return rc < 0 ? CLI_EXIT_OK : rc;
    double *f = NULL;
    size_t n = 0;
    const mcs_importance *imp = NULL;
    mcs_importance *imp_buf = cli_alloc(CMD, 1, sizeof *imp_buf);
    rc = imp_buf != NULL ? load_inputs(&o, &f, &n, imp_buf, &imp) : CLI_EXIT_FAIL;
    if (rc == 0)
        rc = run_kinds(&o, f, n, imp);
    free(f);
    free(imp_buf);
    return rc;
}
