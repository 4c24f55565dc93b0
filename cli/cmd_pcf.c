/* mcspec pcf: the pair correlation of point sets read from a file or drawn
 * from a named 2D pattern (the Gaussian-kernel PCF, or psa's RDF), mean and
 * standard error per bin over the sets beside the exact value, a figure,
 * and psa's spectral check (the radial power the RDF implies against the
 * measured one). */
#include "atomic.h"
#include "cli.h"
#include "input.h"
#include "kindsets.h"
#include "measure_rows.h"
#include "output.h"
#include "plot.h"
#include "progress.h"
#include "record.h"

#include "mcspec.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define CMD "mcspec pcf"
#define CSV_HEADER "r,pcf,pcf_stderr,exact"
#define CSV_SPECTRAL "freq,power_from_rdf,power,power_stderr,difference"

static const char help[] =
    "usage: mcspec pcf [options] [FILE|-]\n"
    "       mcspec pcf KIND --k K [--dim D] [--sets T] [--seed S] [options]\n"
    "\n"
    "The pair correlation g(r) of point sets in 1D or 2D (the dimension from the\n"
    "file), one set per trial, with toroidal distances, for r up to a radius in\n"
    "units of the mean spacing (1/K in 1D, 1/sqrt(K) in 2D), in bins; per bin the\n"
    "mean over the sets, its standard error, and the exact value where one is\n"
    "known. Two estimators (docs/measures.md):\n"
    "  default  the Gaussian-kernel PCF of Oztireli and Gross (2012), as utk's PCF\n"
    "           without its open-square edge factor (the torus has no edge)\n"
    "  --rdf    psa's radial distribution function: pair counts per ring over\n"
    "           K (K - 1) / 2 times the ring's area, psa's normalisation\n"
    "Random points give g = 1 (RDF: exactly, every bin).\n"
    "\n"
    "With KIND (every kind of mcspec sample: the 2D patterns random, jittered,\n"
    "grid, shifted-grid, n-rooks, multi-jittered, cmj, the samplers, blue noise\n"
    "such as poisson-disk; 2D unless --dim 1) the sets are drawn from it and the\n"
    "exact column holds E g, both estimators: random, and jittered, grid,\n"
    "shifted-grid and n-rooks from their strata (empty for the other kinds). For\n"
    "a FILE the exact column is empty unless --exact random says the points are\n"
    "independent and uniform.\n"
    "\n"
    "Input: one point per line, 1 or 2 coordinates in [0,1); a line starting\n"
    "with '#' ends the current set (utk's convention). Everything is read and\n"
    "checked before anything is printed; a malformed line stops the run, exit 2.\n"
    "\n"
    "Options:\n"
    "  --radius R       largest r, mean spacings (default 3); every set needs\n"
    "                   (R + 8 sigma for the kernel) / sqrt(K) <= 1/2 in 2D\n"
    "  --bins B         bins over [0, R) (default 60)\n"
    "  --bin-width W    bins of width W instead (R is rounded up to B W)\n"
    "  --sigma S        the kernel's standard deviation, mean spacings (default 0.1)\n"
    "  --rdf            psa's RDF instead of the kernel PCF\n"
    "  --exact random   fill the exact column for independent uniform points\n"
    "  --spectral F     psa's spectral check instead of g (needs --rdf): the radial\n"
    "                   power the mean RDF implies (g = 1 past R) beside the\n"
    "                   periodogram's radial average, annuli 1..F in 2D\n"
    "                   (frequencies 1..F in 1D), and their difference; CSV header\n"
    "                   " CSV_SPECTRAL "\n"
    "  --k K            points per set of KIND (required with KIND)\n"
    "  --dim D          dimension of KIND's sets, 1 or 2 (default 2)\n"
    "  --sets T         sets of KIND (default 100)\n"
    "  --seed S         PCG32 seed of KIND's sets (default 1)\n"
    "  --wrap           take coordinates modulo 1 (default: outside [0,1) is an\n"
    "                   error)\n"
    "  --plot FILE      draw g with its standard-error band and the exact curve\n"
    "                   (FILE.png or FILE.svg, by gnuplot)\n"
    "  --save FILE      also save the accumulator (a pcf record, docs/format.md)\n"
    "                   for mcspec merge and mcspec show, written atomically (as\n"
    "                   mcspec spectrum --save); show rebuilds the exact column of\n"
    "                   a KIND's record, not --exact random of a FILE's\n"
    "  --csv            print CSV only: the header, exactly\n"
    "                   " CSV_HEADER "\n"
    "                   then one row per bin, r its centre (an empty field: no value)\n"
    "  --help           this text\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage or input (one line on stderr).\n";

typedef struct {
    int rdf, wrap, csv;
    size_t bins, k, spectral;
    uint64_t sets, seed;
    const char *radius_s, *width_s, *sigma_s, *exact_s, *plot, *arg;
    const char *save; /* --save FILE */
    double radius, sigma;
    int kind;  /* a 2D pattern (mcs_pattern2d_kind), or -1: a file or another kind */
    int drawn; /* sets drawn from KIND (a 2D pattern or any kind of mcspec sample) */
    size_t dim; /* --dim of a drawn KIND (default 2) */
    int bins_given, k_given;
} pcf_opts;

typedef struct {
    mcs_pcf acc;
    const pcf_opts *o;
    const char *name;
    uint64_t sets;
    void *work;
    size_t work_bytes;
    mcs_pointset ps1;   /* --spectral, 1D */
    mcs_pointset2d ps2; /* --spectral, 2D */
    void *ps_mem;
    const cli_pointset_stats *stats;
} pcf_ctx;

/* A positive finite number from text, or a one-line error. */
static int parse_positive(const char *opt, const char *text, double *out)
{
    char *end = NULL;
    errno = 0;
    const double v = strtod(text, &end);
    if (end == text || *end != '\0' || errno != 0 || !isfinite(v) || !(v > 0.0))
        return cli_fail(CMD, "--%s %s: give a positive number", opt, text);
    *out = v;
    return 0;
}

static int pattern_kind(const char *name)
{
    for (int i = 0; i < MCS_PATTERN2D_KIND_COUNT; ++i)
        if (strcmp(name, mcs_pattern2d_kind_str((mcs_pattern2d_kind)i)) == 0)
            return i;
    return -1;
}

static int check_values(pcf_opts *o)
{
    int rc = parse_positive("radius", o->radius_s, &o->radius);
    if (rc == 0)
        rc = parse_positive("sigma", o->sigma_s, &o->sigma);
    if (rc == 0 && o->width_s != NULL) {
        double w = 0.0;
        if (o->bins_given)
            return cli_fail(CMD, "--bins and --bin-width: give one of them");
        if ((rc = parse_positive("bin-width", o->width_s, &w)) != 0)
            return rc;
        const double b = ceil(o->radius / w * (1.0 - 1e-12));
        if (!(b >= 1.0 && b <= (double)MCS_PCF_MAX_BINS))
            return cli_fail(CMD, "--bin-width %s: makes %.0f bins; at most %u", o->width_s, b,
                            MCS_PCF_MAX_BINS);
        o->bins = (size_t)b;
        o->radius = b * w;
    }
    if (rc == 0 && o->exact_s != NULL && strcmp(o->exact_s, "random") != 0)
        return cli_fail(CMD, "--exact %s: the only model a point file can be said to follow is "
                        "'random'", o->exact_s);
    if (rc == 0 && o->spectral > 0u && !o->rdf)
        return cli_fail(CMD, "--spectral needs --rdf (the check transforms psa's histogram)");
    if (rc == 0 && o->spectral > 0u && o->plot != NULL)
        return cli_fail(CMD, "--plot draws g; leave it out with --spectral");
    return rc;
}

static int parse(int argc, char **argv, pcf_opts *o)
{
    cli_opt opts[] = {
        {"rdf", CLI_OPT_FLAG, &o->rdf, 0, 0, 0},
        {"radius", CLI_OPT_STRING, &o->radius_s, 0, 0, 0},
        {"bins", CLI_OPT_SIZE, &o->bins, 1, MCS_PCF_MAX_BINS, 0},
        {"bin-width", CLI_OPT_STRING, &o->width_s, 0, 0, 0},
        {"sigma", CLI_OPT_STRING, &o->sigma_s, 0, 0, 0},
        {"exact", CLI_OPT_STRING, &o->exact_s, 0, 0, 0},
        {"spectral", CLI_OPT_SIZE, &o->spectral, 1, MCS_POINTSET2D_MAX_FREQ, 0},
        {"k", CLI_OPT_SIZE, &o->k, 2, MCS_PATTERN2D_MAX_K, 0},
        {"sets", CLI_OPT_U64, &o->sets, 1, UINT64_MAX, 0},
        {"seed", CLI_OPT_U64, &o->seed, 0, UINT64_MAX, 0},
        {"wrap", CLI_OPT_FLAG, &o->wrap, 0, 0, 0},
        {"plot", CLI_OPT_STRING, &o->plot, 0, 0, 0},
        {"csv", CLI_OPT_FLAG, &o->csv, 0, 0, 0},
        {"save", CLI_OPT_STRING, &o->save, 0, 0, 0},
        {"dim", CLI_OPT_SIZE, &o->dim, 1, 2, 0},
    };
    int rc = cli_parse_one(CMD, help, NULL, opts, CLI_COUNT(opts), argc, argv, &o->arg);
    if (rc != CLI_PARSED)
        return rc;
    o->bins_given = opts[2].given;
    o->k_given = opts[7].given;
    const int dim_given = cli_opt_given(opts, CLI_COUNT(opts), "dim");
    if (o->k_given || (o->arg != NULL && cli_kind_known(o->arg) && access(o->arg, F_OK) != 0)) {
        if (o->arg == NULL || !cli_kind_known(o->arg))
            return cli_fail(CMD, "--k is for a named kind: give KIND (a kind of mcspec sample, "
                            "such as jittered or poisson-disk) before it");
        o->drawn = 1;
        o->kind = o->dim == 2u ? pattern_kind(o->arg) : -1;
        if (!o->k_given)
            return cli_fail(CMD, "%s: --k K is required with a pattern", o->arg);
        if (o->exact_s != NULL)
            return cli_fail(CMD, "--exact is for point files; a pattern's exact column is its own");
    } else if (dim_given) {
        return cli_fail(CMD, "--dim is for a named kind (a file's points carry theirs)");
    } else if (opts[8].given || opts[9].given) {
        return cli_fail(CMD, "--sets and --seed are for a named pattern (mcspec pcf KIND --k K)");
    } else if (o->arg == NULL && isatty(STDIN_FILENO)) {
        return cli_fail(CMD, "no input: give a point file, '-' for standard input, or a KIND");
    }
    if ((rc = check_values(o)) != 0)
        return rc;
    return o->plot != NULL ? cli_plot_check(CMD, o->plot) : 0;
}

/* The first set fixes the dimension: the accumulators are made then. */
static int start(pcf_ctx *c, size_t dim)
{
    const pcf_opts *o = c->o;
    if (dim != 1u && dim != 2u)
        return cli_fail(CMD, "%s: the points have %zu coordinates; the pair correlation takes "
                        "1 or 2", c->name, dim);
    void *mem = cli_alloc(CMD, 1, MCS_PCF_SIZE(o->bins));
    if (mem == NULL)
        return CLI_EXIT_FAIL;
    if (mcs_pcf_init(&c->acc, dim, o->rdf ? MCS_PCF_RDF : MCS_PCF_GAUSSIAN, o->bins, o->radius,
                     o->sigma, mem, MCS_PCF_SIZE(o->bins)) != MCS_OK) {
        free(mem);
        return cli_internal(CMD, "mcs_pcf_init failed");
    }
    if (o->spectral > 0u) {
        size_t bytes = 0;
        mcs_status st = dim == 1u ? mcs_pointset_size(o->spectral, 0u, &bytes)
                                  : mcs_pointset2d_size(o->spectral, 0u, &bytes);
        if (st != MCS_OK)
            return cli_fail(CMD, "--spectral %zu: %s", o->spectral, mcs_status_str(st));
        if ((c->ps_mem = cli_alloc(CMD, 1, bytes)) == NULL)
            return CLI_EXIT_FAIL;
        st = dim == 1u ? mcs_pointset_init(&c->ps1, o->spectral, 0u, c->ps_mem, bytes)
                       : mcs_pointset2d_init(&c->ps2, o->spectral, 0u, c->ps_mem, bytes);
        if (st != MCS_OK)
            return cli_internal(CMD, "point-set init failed: %s", mcs_status_str(st));
    }
    return 0;
}

static int add_set(void *ctx, size_t k, const double *coords, const double *weights)
{
    (void)weights;
    pcf_ctx *c = ctx;
    int rc = 0;
    if (c->acc.dim == 0u && (rc = start(c, c->stats != NULL ? c->stats->dim : 2u)) != 0)
        return rc;
    ++c->sets;
    size_t need = 0;
    mcs_status st = mcs_pcf_work_size(&c->acc, k, &need);
    if (st == MCS_ERR_K_RANGE) {
        const double cut = c->acc.radius + (c->o->rdf ? 0.0 : 8.0 * c->acc.sigma);
        const double kmin = c->acc.dim == 1u ? 2.0 * cut : 4.0 * cut * cut;
        return cli_fail(CMD, "%s: set %llu has %zu points; the radius %g%s mean spacings "
                        "reaches past half the torus there (needs K >= %.0f, or a smaller "
                        "--radius)", c->name, (unsigned long long)c->sets, k, c->acc.radius,
                        c->o->rdf ? "" : " + 8 sigma", ceil(kmin > 2.0 ? kmin : 2.0));
    }
    if (st == MCS_OK && cli_grow(CMD, &c->work, &c->work_bytes, need, k) != 0)
        return CLI_EXIT_FAIL;
    if (st == MCS_OK)
        st = mcs_pcf_add(&c->acc, k, coords, c->work, c->work_bytes);
    if (st == MCS_OK && c->o->spectral > 0u)
        st = c->acc.dim == 1u ? mcs_pointset_add(&c->ps1, k, coords)
                              : mcs_pointset2d_add(&c->ps2, k, coords);
    if (st != MCS_OK)
        return cli_internal(CMD, "adding a point set failed: %s", mcs_status_str(st));
    return 0;
}

static int draw_sets(pcf_ctx *c, const pcf_opts *o)
{
    mcs_pattern2d pat;
    mcs_rng rng;
    if (mcs_pattern2d_init(&pat, (mcs_pattern2d_kind)o->kind, o->k, 0u, 0u) != MCS_OK ||
        mcs_rng_seed(&rng, o->seed, 0u) != MCS_OK)
        return cli_internal(CMD, "pattern init failed");
    double *pts = cli_alloc(CMD, 2u * o->k, sizeof *pts);
    if (pts == NULL)
        return CLI_EXIT_FAIL;
    cli_progress progress;
    cli_progress_init(&progress, !o->csv, CMD, "sets drawn", o->sets);
    int rc = 0;
    for (uint64_t t = 0; t < o->sets && rc == 0; ++t) {
        if (mcs_pattern2d_draw(&pat, &rng, o->k, pts) != MCS_OK)
            rc = cli_internal(CMD, "drawing a set failed");
        else
            rc = add_set(c, o->k, pts, NULL);
        cli_progress_update(&progress, t + 1u);
    }
    cli_progress_end(&progress);
    free(pts);
    return rc;
}

/* T sets of a kind of mcspec sample that is not a 2D pattern (blue noise,
 * the any-dimension samplers, the 1D kinds), as mcspec sample --seed draws
 * them. */
static int draw_sample_kind(pcf_ctx *c, const pcf_opts *o, cli_pointset_stats *stats)
{
    cli_sample_source src;
    int rc = cli_sample_init(CMD, o->arg, o->dim, o->k, MCS_MAX_N, &src);
    if (rc != 0)
        return rc;
    c->stats = stats;
    cli_progress progress;
    cli_progress_init(&progress, !o->csv, CMD, "sets drawn", o->sets);
    rc = cli_kind_feed(CMD, &src, o->sets, o->seed, add_set, c, stats, &progress);
    cli_progress_end(&progress);
    cli_sample_free(&src);
    return rc;
}

/* The exact column of bin b, or NaN. */
static double exact_of(const pcf_ctx *c, size_t b)
{
    const pcf_opts *o = c->o;
    double v = NAN;
    mcs_pattern2d pat;
    if (o->kind >= 0) {
        if (mcs_pattern2d_init(&pat, (mcs_pattern2d_kind)o->kind, o->k, 0u, 0u) != MCS_OK ||
            mcs_pcf_exact(&c->acc, &pat, b, &v) != MCS_OK)
            v = NAN;
    } else if (o->drawn) { /* another kind: random points' g in 1D, else none */
        if (strcmp(o->arg, "random") != 0 || mcs_pcf_exact(&c->acc, NULL, b, &v) != MCS_OK)
            v = NAN;
    } else if (o->exact_s != NULL && mcs_pcf_exact(&c->acc, NULL, b, &v) != MCS_OK) {
        v = NAN;
    }
    return v;
}

typedef struct {
    const pcf_ctx *c;
    const char *title, *subtitle;
} pcf_figure;

static int write_figure(FILE *fp, const char *tmp, const void *ctx)
{
    const pcf_figure *fig = ctx;
    const mcs_pcf *acc = &fig->c->acc;
    FILE *data = cli_plot_data(tmp, "data.txt");
    if (data == NULL)
        return -1;
    int exact = 0;
    double top = 1.0;
    for (size_t b = 0; b < acc->bins; ++b) {
        double r = NAN, m = NAN, se = 0.0;
        (void)mcs_pcf_radius_at(acc, b, &r);
        (void)mcs_pcf_mean(acc, b, &m);
        if (mcs_pcf_stderr(acc, b, &se) != MCS_OK)
            se = 0.0;
        const double e = exact_of(fig->c, b);
        exact |= !isnan(e);
        top = fmax(top, fmax(m + se, isnan(e) ? 0.0 : e));
        fprintf(data, "%.17g %.17g %.17g %.17g", r, m, m - se, m + se);
        cli_plot_value(data, e);
        fputc('\n', data);
    }
    if (fclose(data) != 0)
        return -1;
    const cli_plot_info info = {fig->title, fig->subtitle, NULL, NULL, NULL, 0};
    fputs("set title ", fp);
    cli_plot_title(fp, &info);
    fputs("\nset xlabel \"r (mean spacings)\"\nset ylabel ", fp);
    cli_plot_string(fp, acc->estimator == MCS_PCF_RDF ? "g(r)   (psa's RDF, mean over sets)"
                                                      : "g(r)   (Gaussian-kernel PCF, mean over sets)");
    fputc('\n', fp);
    cli_plot_style(fp);
    fprintf(fp, "set xrange [0:%.17g]\nset yrange [0:%.17g]\n", acc->radius, 1.3 * top);
    fputs("plot ", fp);
    cli_plot_data_ref(fp, tmp, "data.txt");
    fputs(" using 1:3:4 with filledcurves fc rgb '#9ecae1' fs solid 0.5 noborder "
          "title \"measured ± 1 standard error\", ", fp);
    if (exact) {
        cli_plot_data_ref(fp, tmp, "data.txt");
        fputs(" using 1:5 with lines lw 2 lc rgb '#d62728' title \"exact\", ", fp);
    }
    cli_plot_data_ref(fp, tmp, "data.txt");
    fputs(" using 1:2 with lines lw 1.5 lc rgb '#08519c' title \"measured (mean over sets)\"\n", fp);
    return 0;
}

static void describe(const pcf_ctx *c, char *title, size_t tsize, char *sub, size_t ssize)
{
    const pcf_opts *o = c->o;
    const mcs_pcf *acc = &c->acc;
    if (o->drawn)
        snprintf(title, tsize, "%s %s: %zuD, K = %zu, %llu sets (seed %llu)", CMD, o->arg,
                 acc->dim, o->k, (unsigned long long)c->sets, (unsigned long long)o->seed);
    else
        snprintf(title, tsize, "%s: %s, %llu point sets in %zuD, K = %zu to %zu", CMD, c->name,
                 (unsigned long long)c->sets, acc->dim, acc->k_min, acc->k_max);
    if (acc->estimator == MCS_PCF_RDF)
        snprintf(sub, ssize, "psa's RDF, %zu bins over [0, %g) mean spacings", acc->bins,
                 acc->radius);
    else
        snprintf(sub, ssize, "Gaussian-kernel PCF (sigma %g), %zu bins over [0, %g) mean spacings",
                 acc->sigma, acc->bins, acc->radius);
}

/* A pcf row: v = r, pcf, pcf_stderr, exact; the table adds z. */
void cli_pcf_row(int csv, const double *v)
{
    if (csv) {
        char buf[40];
        cli_csv_double(buf, sizeof buf, v[0]);
        printf("%s", buf);
        cli_print_values(1, v + 1, 3);
        return;
    }
    printf("%9.4f", v[0]);
    for (int i = 1; i < 4; ++i) {
        char buf[40];
        cli_table_double(buf, sizeof buf, 13, v[i]);
        printf(" %s", buf);
    }
    const double z = cli_z(v[1], v[3], v[2], 1e-12);
    if (isnan(z))
        printf(" %8s\n", "-");
    else
        printf(" %8.2f\n", z);
}

static void report(const pcf_ctx *c)
{
    const pcf_opts *o = c->o;
    char title[256], sub[160];
    describe(c, title, sizeof title, sub, sizeof sub);
    if (o->csv) {
        puts(CSV_HEADER);
    } else {
        printf("%s\n%s; r: bin centre; z = (pcf - exact) / stderr\n\n%9s %13s %13s %13s %8s\n",
               title, sub, "r", "pcf", "pcf_stderr", "exact", "z");
    }
    for (size_t b = 0; b < c->acc.bins; ++b) {
        double v[4] = {NAN, NAN, NAN, NAN};
        (void)mcs_pcf_radius_at(&c->acc, b, &v[0]);
        (void)mcs_pcf_mean(&c->acc, b, &v[1]);
        (void)mcs_pcf_stderr(&c->acc, b, &v[2]);
        v[3] = exact_of(c, b);
        cli_pcf_row(o->csv, v);
    }
}

/* The mean |f| over the integer wave vectors of annulus r (r <= |f| < r + 1). */
static double annulus_mean_radius(size_t r)
{
    const long hi = (long)r + 1;
    double sum = 0.0, n = 0.0;
    for (long x = -hi; x <= hi; ++x)
        for (long y = -hi; y <= hi; ++y) {
            const double f = sqrt((double)(x * x + y * y));
            if (f >= (double)r && f < (double)r + 1.0) {
                sum += f;
                n += 1.0;
            }
        }
    return sum / n;
}

static int report_spectral(const pcf_ctx *c)
{
    const pcf_opts *o = c->o;
    const mcs_pcf *acc = &c->acc;
    if (acc->k_min != acc->k_max)
        return cli_fail(CMD, "--spectral: the sets have %zu to %zu points; the check needs one K",
                        acc->k_min, acc->k_max);
    char title[256], sub[160];
    describe(c, title, sizeof title, sub, sizeof sub);
    const double s = acc->dim == 1u ? 1.0 / (double)acc->k_max : 1.0 / sqrt((double)acc->k_max);
    if (o->csv)
        puts(CSV_SPECTRAL);
    else
        printf("%s\n%s\npower_from_rdf: 1 + (K - 1) x the %s of g - 1 over r < R = %g absolute "
               "(g = 1 beyond: the truncation)%s; power: the periodogram's %s; difference = "
               "power_from_rdf - power\n\n%9s %15s %13s %13s %13s\n",
               title, sub, acc->dim == 1u ? "cosine transform" : "Hankel transform",
               acc->radius * s,
               acc->dim == 1u ? "" : ", at the annulus' mean |f|",
               acc->dim == 1u ? "mean at f" : "radial average of annulus f <= |f| < f + 1",
               "freq", "power_from_rdf", "power", "power_stderr", "difference");
    for (size_t f = 1; f <= o->spectral; ++f) {
        double v[4] = {NAN, NAN, NAN, NAN};
        const double at = acc->dim == 1u ? (double)f : annulus_mean_radius(f);
        (void)mcs_pcf_power(acc, at, &v[0]);
        if (acc->dim == 1u) {
            (void)mcs_pointset_power(&c->ps1, (long)f, &v[1]);
            (void)mcs_pointset_power_stderr(&c->ps1, (long)f, &v[2]);
        } else {
            (void)mcs_pointset2d_radial(&c->ps2, f, &v[1]);
            (void)mcs_pointset2d_radial_stderr(&c->ps2, f, &v[2]);
        }
        v[3] = v[0] - v[1];
        if (o->csv)
            printf("%zu", f);
        else
            printf("%9zu  ", f);
        cli_print_values(o->csv, v, 4);
    }
    return 0;
}

int cli_cmd_pcf(int argc, char **argv)
{
    pcf_opts o;
    memset(&o, 0, sizeof o);
    o.bins = 60u;
    o.sets = 100u;
    o.seed = 1u;
    o.radius_s = "3";
    o.sigma_s = "0.1";
    o.kind = -1;
    o.dim = 2u;
    int rc = parse(argc, argv, &o);
    if (rc != 0)
        return rc < 0 ? CLI_EXIT_OK : rc;
    pcf_ctx *c = cli_alloc(CMD, 1, sizeof *c);
    if (c == NULL)
        return CLI_EXIT_FAIL;
    memset(c, 0, sizeof *c);
    c->o = &o;
    c->name = o.drawn ? o.arg : cli_input_name(o.arg);
    cli_pointset_stats stats;
    /* --save: checked before any work (a drawn KIND reads no standard input) */
    cli_save_target save = {o.save, o.arg, 0u, 0u};
    if (o.drawn)
        rc = o.save != NULL ? cli_write_check(CMD, o.save) : 0;
    else
        rc = cli_save_begin(CMD, &save);
    if (rc == 0 && o.kind >= 0) {
        rc = draw_sets(c, &o);
    } else if (rc == 0 && o.drawn) {
        rc = draw_sample_kind(c, &o, &stats);
    } else if (rc == 0) {
        c->stats = &stats;
        cli_pointset_format fmt = {.dim = 0, .weights = 0, .wrap = o.wrap};
        cli_progress progress;
        cli_progress_init(&progress, !o.csv, CMD, "sets read", 0);
        rc = cli_read_pointsets(CMD, o.arg, &fmt, add_set, c, &stats, &progress);
        cli_progress_end(&progress);
    }
    if (rc == 0 && o.spectral > 0u)
        rc = report_spectral(c);
    else if (rc == 0)
        report(c);
    if (rc == 0 && o.plot != NULL) {
        char title[256], sub[160];
        describe(c, title, sizeof title, sub, sizeof sub);
        const pcf_figure fig = {c, title, sub};
        rc = cli_plot_render(CMD, o.plot, write_figure, &fig);
    }
    if (rc == 0 && o.drawn) {
        const cli_run run = {(unsigned)o.dim, o.arg, o.dim == 1u ? (uint64_t)MCS_MAX_N : 0u, o.k,
                             0, 0u, o.seed, 1u, o.sets};
        rc = cli_save_drawn(CMD, o.save, &run, MCS_IO_KIND_PCF, &c->acc);
    } else if (rc == 0) {
        rc = cli_save_points(CMD, &save, MCS_IO_KIND_PCF, &c->acc);
    }
    free(c->acc.mem);
    free(c->ps_mem);
    free(c->work);
    free(c);
    return rc;
}
