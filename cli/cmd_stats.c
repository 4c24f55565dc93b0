/* mcspec stats: the spatial statistics of point sets read from a file, the
 * minimum and average minimum distances over the maximal packing distance,
 * and psa's effective Nyquist frequency and oscillation metric of each
 * set's radial power spectrum (1D and 2D), of point sets read from a file
 * or drawn from a named kind, with the exact expectation for independent
 * uniform points where theory gives it. */
#include "atomic.h"
#include "cli.h"
#include "input.h"
#include "kindsets.h"
#include "measure_rows.h"
#include "output.h"
#include "progress.h"
#include "record.h"

#include "mcspec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The entry point, declared here until cli.h lists it with the others. */

#define CMD "mcspec stats"
#define CSV_HEADER "statistic,value,stderr,exact"

/* Most coordinates a point line may have: the library's cap (the densest
 * lattice packings are known to d = 8). */
#define MAX_DIM MCS_SPACING_MAX_DIM

static const char help[] =
    "usage: mcspec stats [--dim D] [--freq F] [--wrap] [--csv] [--save FILE] [FILE|-]\n"
    "       mcspec stats KIND --dim D --k K [--sets T] [--seed S] [--freq F] [--csv] [--save FILE]\n"
    "\n"
    "The spatial statistics of point sets read from FILE (or standard input,\n"
    "given as '-' or by giving no FILE), one set per trial, with distances taken\n"
    "in the unit torus (per coordinate min(|u - v|, 1 - |u - v|)): per set\n"
    "  min_distance      the smallest distance between two of its points\n"
    "  avg_min_distance  the mean over its points of the distance to the\n"
    "                    nearest other point\n"
    "each as a fraction of the maximal packing distance of K points, d_max =\n"
    "sqrt(2 / (sqrt(3) K)) in 2D (the hexagonal lattice's spacing; psa's\n"
    "normalisation, Lagae and Dutre 2008) and 1/K in 1D, so a hexagonal lattice\n"
    "gives 1, a square grid 0.93, and independent uniform points about 0.47\n"
    "(avg) in 2D; in 1D and 2D also, from the set's periodogram (radial average\n"
    "over annuli of width 1 in 2D, P at each frequency in 1D, up to F)\n"
    "  effective_nyquist psa's effective Nyquist frequency over sqrt(K) (K in\n"
    "                    1D): where the mean power over the disk first stays\n"
    "                    below 0.1 (Heck, Schloemer and Deussen 2013)\n"
    "  oscillations      psa's oscillation metric: 10 x the RMS of P - 1 over\n"
    "                    the 5 sqrt(K) frequencies past P's first rise to 0.98\n"
    "                    (cut at F)\n"
    "then their mean over the sets (value) and its standard error. psa applies\n"
    "the last two to the mean spectrum of its sets: the rows\n"
    "effective_nyquist_of_mean and oscillations_of_mean do that (no stderr).\n"
    "The column exact is the exact expectation of the row for KIND random where\n"
    "theory gives it (empty otherwise and for files): avg_min_distance in 1D\n"
    "(1/2) and 2D (the integral of (1 - A(r))^(K-1), A the toroidal disk's\n"
    "area) and in 3D to 8D from the K where the ball's closed form is exact\n"
    "to rounding (52 in 3D, 104 in 4D, ... 2370 in 8D), min_distance in 1D\n"
    "(1/K: E = 1/K^2, the least Dirichlet gap).\n"
    "Definitions and references: docs/measures.md.\n"
    "\n"
    "Input: one point per line, D coordinates in [0,1) separated by spaces or\n"
    "tabs; a line starting with '#' ends the current set (utk's convention), as\n"
    "for mcspec spectrum; every set needs 2 points or more. Everything is read\n"
    "and checked before anything is printed: a malformed line stops the run\n"
    "with the file, the line number and what was wrong, exit 2.\n"
    "\n"
    "KIND (instead of a file): T sets of K points of a kind of mcspec sample, in\n"
    "D dimensions it has (up to 8 here), drawn from PCG32 seeded with S as\n"
    "mcspec sample --seed S draws them.\n"
    "\n"
    "Options:\n"
    "  --dim D   coordinates per point, 1 to " CLI_STR(MCS_SPACING_MAX_DIM) " (default: as many as the\n"
    "            first point line has; every line must then have as many)\n"
    "            (KIND: required)\n"
    "  --k K     KIND: points per set, 2.." CLI_STR(CLI_MAX_K) "\n"
    "  --sets T  KIND: sets, 1..1000000 (default 64)\n"
    "  --seed S  KIND: the PCG32 seed (default 1)\n"
    "  --freq F  the periodogram's cutoff (default: ceil(5 sqrt(K)) in 2D, 5 K in\n"
    "            1D, K of the first set)\n"
    "  --wrap    take coordinates modulo 1 (default: outside [0,1) is an error)\n"
    "  --csv     print CSV only: the header, exactly\n"
    "            " CSV_HEADER "\n"
    "            and one row per statistic (an empty field: no value)\n"
    "  --save FILE  also save the accumulator of min_distance and avg_min_distance\n"
    "            (a spacing record, docs/format.md; the spectral rows are not in\n"
    "            it) for mcspec merge and mcspec show, written atomically\n"
    "  --help    this text\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage or input (one line on stderr).\n";

typedef struct {
    size_t dim, freq, k, sets;
    uint64_t seed;
    int wrap, csv, kind_mode;
    const char *path; /* the file, or KIND */
    const char *save; /* --save FILE */
} stats_opts;

/* The spectral rows: per-set values, and the values of the mean spectrum. */
enum { SPEC_NYQUIST = 0, SPEC_OSCILLATIONS, SPEC_ROWS };
static const char *const spec_names[SPEC_ROWS] = {"effective_nyquist", "oscillations"};

typedef struct {
    size_t freq;          /* F; 0 until the first set */
    mcs_pointset ps1;     /* one set's periodogram, 1D */
    mcs_pointset2d ps2;   /* 2D */
    void *mem;
    size_t bytes;
    double *power;        /* one set's radial power, [F + 1] */
    double *sum;          /* their sum over the sets */
    size_t k_first;
    int same_k;
    mcs_welford stat[SPEC_ROWS];
} spectral_ctx;

typedef struct {
    mcs_spacing acc;
    const char *name; /* the input's name in messages */
    uint64_t sets;    /* sets seen, for messages */
    void *work;       /* scratch, grown to the largest set's need */
    size_t work_bytes;
    const cli_pointset_stats *stats; /* the reader's: the file's dimension */
    size_t freq_opt;                 /* --freq, 0: the default */
    spectral_ctx spec;
} stats_ctx;

static int parse(int argc, char **argv, stats_opts *o)
{
    cli_opt opts[] = {
        {"dim", CLI_OPT_SIZE, &o->dim, 1, MAX_DIM, 0},
        {"freq", CLI_OPT_SIZE, &o->freq, 1, MCS_POINTSET2D_MAX_FREQ, 0},
        {"wrap", CLI_OPT_FLAG, &o->wrap, 0, 0, 0},
        {"csv", CLI_OPT_FLAG, &o->csv, 0, 0, 0},
        {"k", CLI_OPT_SIZE, &o->k, 2, CLI_MAX_K, 0},
        {"sets", CLI_OPT_SIZE, &o->sets, 1, 1000000, 0},
        {"seed", CLI_OPT_U64, &o->seed, 0, UINT64_MAX, 0},
        {"save", CLI_OPT_STRING, &o->save, 0, 0, 0},
    };
    int rc = cli_parse_one(CMD, help, NULL, opts, CLI_COUNT(opts), argc, argv, &o->path);
    if (rc != CLI_PARSED)
        return rc;
    const cli_kind_args args = {o->path, o->dim, o->save};
    return cli_kind_or_file(CMD, opts, CLI_COUNT(opts), &args, &o->kind_mode);
}

/* The periodogram's accumulators over one buffer, for cutoff F. */
static int spectral_start(spectral_ctx *sp, size_t dim, size_t freq, size_t k)
{
    size_t bytes = 0;
    mcs_status st = dim == 1u ? mcs_pointset_size(freq, 0u, &bytes)
                              : mcs_pointset2d_size(freq, 0u, &bytes);
    if (st != MCS_OK)
        return cli_fail(CMD, "--freq %zu: %s (at most %d in 2D)", freq, mcs_status_str(st),
                        MCS_POINTSET2D_MAX_FREQ);
    sp->mem = cli_alloc(CMD, 1, bytes);
    sp->power = cli_alloc(CMD, 2u * (freq + 1u), sizeof *sp->power);
    if (sp->mem == NULL || sp->power == NULL)
        return CLI_EXIT_FAIL;
    sp->sum = sp->power + freq + 1u;
    for (size_t i = 0; i <= freq; ++i)
        sp->sum[i] = 0.0;
    sp->bytes = bytes;
    sp->freq = freq;
    sp->k_first = k;
    sp->same_k = 1;
    for (int r = 0; r < SPEC_ROWS; ++r)
        mcs_welford_init(&sp->stat[r]);
    return 0;
}

/* One set's radial power (annulus r at its inner radius in 2D, P(f) in
 * 1D) from a fresh accumulator, its two metrics into the Welfords. */
static int spectral_add(spectral_ctx *sp, size_t dim, size_t k, const double *coords)
{
    mcs_status st = dim == 1u ? mcs_pointset_init(&sp->ps1, sp->freq, 0u, sp->mem, sp->bytes)
                              : mcs_pointset2d_init(&sp->ps2, sp->freq, 0u, sp->mem, sp->bytes);
    if (st == MCS_OK)
        st = dim == 1u ? mcs_pointset_add(&sp->ps1, k, coords)
                       : mcs_pointset2d_add(&sp->ps2, k, coords);
    for (size_t i = 0; i <= sp->freq && st == MCS_OK; ++i)
        st = dim == 1u ? mcs_pointset_power(&sp->ps1, (long)i, &sp->power[i])
                       : mcs_pointset2d_radial(&sp->ps2, i, &sp->power[i]);
    if (st != MCS_OK)
        return cli_internal(CMD, "the periodogram of a set failed: %s", mcs_status_str(st));
    for (size_t i = 0; i <= sp->freq; ++i)
        sp->sum[i] += sp->power[i];
    sp->same_k = sp->same_k && k == sp->k_first;
    double v[SPEC_ROWS];
    const size_t n = sp->freq + 1u;
    st = mcs_radial_effective_nyquist(dim, k, n, sp->power, 1.0, &v[SPEC_NYQUIST]);
    if (st == MCS_OK && mcs_radial_oscillations(dim, k, n, sp->power, 1.0, &v[SPEC_OSCILLATIONS]) != MCS_OK)
        v[SPEC_OSCILLATIONS] = (double)NAN; /* no rise to 0.98 before F: no value */
    for (int r = 0; r < SPEC_ROWS && st == MCS_OK; ++r)
        if (!isnan(v[r]))
            st = mcs_welford_add(&sp->stat[r], v[r]);
    if (st != MCS_OK)
        return cli_internal(CMD, "the spectral statistics of a set failed: %s", mcs_status_str(st));
    return 0;
}

static size_t default_freq(size_t dim, size_t k)
{
    return dim == 1u ? 5u * k : (size_t)ceil(5.0 * sqrt((double)k));
}

static int add_set(void *ctx, size_t k, const double *coords, const double *weights)
{
    (void)weights;
    stats_ctx *c = ctx;
    if (c->acc.dim == 0u) {
        if (c->stats->dim > MCS_SPACING_MAX_DIM)
            return cli_fail(CMD, "%s: the points have %zu coordinates; the spacing statistics "
                            "take 1 to %d (the densest packings are known to d = %d)", c->name,
                            c->stats->dim, MCS_SPACING_MAX_DIM, MCS_SPACING_MAX_DIM);
        if (mcs_spacing_init(&c->acc, c->stats->dim) != MCS_OK)
            return cli_internal(CMD, "mcs_spacing_init failed");
    }
    ++c->sets;
    if (k < 2u)
        return cli_fail(CMD, "%s: point set %llu has a single point (a nearest other point "
                        "needs 2 or more)", c->name, (unsigned long long)c->sets);
    size_t need = 0;
    mcs_status st = mcs_spacing_work_size(c->acc.dim, k, &need);
    if (st == MCS_OK && cli_grow(CMD, &c->work, &c->work_bytes, need, k) != 0)
        return CLI_EXIT_FAIL;
    if (st == MCS_OK)
        st = mcs_spacing_add(&c->acc, k, coords, c->work, c->work_bytes);
    if (st != MCS_OK)
        return cli_internal(CMD, "adding a point set failed: %s", mcs_status_str(st));
    const size_t dim = c->acc.dim;
    if (dim > 2u)
        return 0;
    int rc = 0;
    if (c->spec.freq == 0u) {
        size_t f = c->freq_opt != 0u ? c->freq_opt : default_freq(dim, k);
        f = f < (size_t)MCS_POINTSET2D_MAX_FREQ || dim == 1u ? f : (size_t)MCS_POINTSET2D_MAX_FREQ;
        rc = spectral_start(&c->spec, dim, f, k);
    }
    return rc != 0 ? rc : spectral_add(&c->spec, dim, k, coords);
}

/* The spacing rows' exact expectations (NaN: not known) and the source line. */
typedef struct {
    const char *source; /* "random (seed 1)", or NULL for the input's name */
    double exact[MCS_SPACING_STATISTICS];
} stats_exact;

/* A row: value, stderr, exact, and in the table z = (value - exact) / stderr. */
void cli_stats_row(int csv, const char *name, const double *v)
{
    printf(csv ? "%s" : "%-25s", name);
    if (csv) {
        cli_print_values(1, v, 3);
        return;
    }
    for (int i = 0; i < 3; ++i) {
        char buf[40];
        cli_table_double(buf, sizeof buf, 13, v[i]);
        printf(" %s", buf);
    }
    const double z = cli_z(v[0], v[2], v[1], 1e-12 * fabs(v[2]));
    if (isnan(z))
        printf(" %8s\n", "-");
    else
        printf(" %8.2f\n", z);
}

void cli_spacing_rows(int csv, const mcs_spacing *acc, const double exact[MCS_SPACING_STATISTICS])
{
    if (csv)
        puts(CSV_HEADER);
    else
        printf("\n%-25s %13s %13s %13s %8s\n", "statistic", "value", "stderr", "exact", "z");
    for (int i = 0; i < MCS_SPACING_STATISTICS; ++i) {
        const mcs_spacing_statistic s = (mcs_spacing_statistic)i;
        double v[3] = {(double)NAN, (double)NAN, exact[i]};
        if (mcs_spacing_mean(acc, s, &v[0]) != MCS_OK)
            v[0] = (double)NAN;
        if (mcs_spacing_stderr(acc, s, &v[1]) != MCS_OK)
            v[1] = (double)NAN;
        cli_stats_row(csv, mcs_spacing_statistic_str(s), v);
    }
}

void cli_spacing_exact(const char *name, size_t dim, size_t k,
                       double exact[MCS_SPACING_STATISTICS])
{
    for (int i = 0; i < MCS_SPACING_STATISTICS; ++i) {
        double v = NAN;
        exact[i] = name != NULL && strcmp(name, "random") == 0 &&
                           mcs_spacing_exact_random((mcs_spacing_statistic)i, dim, k, &v) == MCS_OK
                       ? v
                       : (double)NAN;
    }
}

static void report(const stats_opts *o, const mcs_spacing *acc, const cli_pointset_stats *stats,
                   spectral_ctx *spec, const stats_exact *ex)
{
    if (!o->csv) {
        cli_sets_line(CMD, ex->source, o->path, stats);
        printf("toroidal distances as fractions of the maximal packing distance d_max = %s; "
               "value: mean over the sets\n", stats->dim == 1u   ? "1/K"
                                              : stats->dim == 2u ? "sqrt(2 / (sqrt(3) K))"
                                                                 : "that of the densest lattice "
                                                                   "packing (docs/measures.md)");
        if (stats->dim <= 2u)
            printf("spectral rows: the periodogram up to F = %zu (radial average over annuli of "
                   "width 1 in 2D); effective_nyquist over %s\n", spec->freq,
                   stats->dim == 1u ? "K" : "sqrt(K)");
        printf("exact: the expectation for independent uniform points (- where not known); "
               "z = (value - exact) / stderr\n");
    }
    cli_spacing_rows(o->csv, acc, ex->exact);
    if (stats->dim > 2u || spec->freq == 0u)
        return;
    for (int r = 0; r < SPEC_ROWS; ++r) {
        double v[3] = {(double)NAN, (double)NAN, (double)NAN};
        if (mcs_welford_mean(&spec->stat[r], &v[0]) != MCS_OK)
            v[0] = (double)NAN;
        if (mcs_welford_stderr(&spec->stat[r], &v[1]) != MCS_OK)
            v[1] = (double)NAN;
        cli_stats_row(o->csv, spec_names[r], v);
    }
    /* psa's way: the metrics of the mean spectrum (one K only). */
    for (int r = 0; r < SPEC_ROWS; ++r) {
        double v[3] = {(double)NAN, (double)NAN, (double)NAN};
        const size_t n = spec->freq + 1u;
        for (size_t i = 0; i <= spec->freq; ++i)
            spec->power[i] = spec->sum[i] / (double)stats->sets;
        mcs_status st = MCS_ERR_MISMATCH;
        if (spec->same_k)
            st = r == SPEC_NYQUIST
                     ? mcs_radial_effective_nyquist(stats->dim, spec->k_first, n, spec->power, 1.0, &v[0])
                     : mcs_radial_oscillations(stats->dim, spec->k_first, n, spec->power, 1.0, &v[0]);
        if (st != MCS_OK)
            v[0] = (double)NAN;
        char name[40];
        snprintf(name, sizeof name, "%s_of_mean", spec_names[r]);
        cli_stats_row(o->csv, name, v);
    }
}

/* T sets of KIND into ctx, as the file's sets would go; the exact column
 * for random points. */
static int run_kind(const stats_opts *o, stats_ctx *ctx, cli_pointset_stats *stats,
                    stats_exact *ex, char *source, size_t source_size)
{
    cli_sample_source src;
    int rc = cli_sample_init(CMD, o->path, o->dim, o->k, MCS_MAX_N, &src);
    if (rc != 0)
        return rc;
    cli_spacing_exact(o->path, o->dim, o->k, ex->exact);
    snprintf(source, source_size, "%s (seed %llu)", o->path, (unsigned long long)o->seed);
    ex->source = source;
    cli_progress progress;
    cli_progress_init(&progress, !o->csv, CMD, "sets drawn", o->sets);
    rc = cli_kind_feed(CMD, &src, o->sets, o->seed, add_set, ctx, stats, &progress);
    cli_progress_end(&progress);
    cli_sample_free(&src);
    return rc;
}

int cli_cmd_stats(int argc, char **argv)
{
    stats_opts o = {0, 0, 0, 64, 1, 0, 0, 0, NULL, NULL};
    int rc = parse(argc, argv, &o);
    if (rc != 0)
        return rc < 0 ? CLI_EXIT_OK : rc;
    stats_exact ex = {.source = NULL, .exact = {(double)NAN, (double)NAN}};
    char source[160];
    cli_pointset_stats stats;
    stats_ctx ctx = {.name = o.kind_mode ? o.path : cli_input_name(o.path), .sets = 0,
                     .work = NULL, .work_bytes = 0, .stats = &stats, .freq_opt = o.freq};
    ctx.acc.dim = 0; /* initialised at the first set, when the dimension is known */
    cli_save_target save = {o.save, o.path, 0u, 0u};
    if (o.kind_mode) {
        rc = o.save != NULL ? cli_write_check(CMD, o.save) : 0;
        if (rc == 0)
            rc = run_kind(&o, &ctx, &stats, &ex, source, sizeof source);
    } else {
        cli_pointset_format fmt = {.dim = o.dim, .weights = 0, .wrap = o.wrap};
        rc = cli_save_begin(CMD, &save);
        cli_progress progress;
        cli_progress_init(&progress, !o.csv, CMD, "sets read", 0);
        if (rc == 0)
            rc = cli_read_pointsets(CMD, o.path, &fmt, add_set, &ctx, &stats, &progress);
        cli_progress_end(&progress);
    }
    if (rc == 0)
        report(&o, &ctx.acc, &stats, &ctx.spec, &ex);
    if (rc == 0 && o.kind_mode) {
        const cli_run run = {(unsigned)o.dim, o.path, o.dim == 1u ? (uint64_t)MCS_MAX_N : 0u,
                             o.k, 0, 0u, o.seed, 1u, o.sets};
        rc = cli_save_drawn(CMD, o.save, &run, MCS_IO_KIND_SPACING, &ctx.acc);
    } else if (rc == 0) {
        rc = cli_save_points(CMD, &save, MCS_IO_KIND_SPACING, &ctx.acc);
    }
    free(ctx.work);
    free(ctx.spec.mem);
    free(ctx.spec.power);
    return rc;
}
