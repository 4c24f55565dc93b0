/* mcspec projections: every 2D projection of a d-dimensional point file or
 * sampler, tested against independent dimensions (projections.h). */
#include "cli.h"
#include "input.h"
#include "plot.h"
#include "sample.h"

#include "mcspec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define CMD "mcspec projections"
#define CSV_HEADER                                                                          \
    "dim_i,dim_j,radial_low,radial_low_stderr,anisotropy_db,discrepancy,peak,peak_stderr,"   \
    "flagged,radial_low_ref,radial_low_z,discrepancy_stderr,discrepancy_random,peak_max,"   \
    "peak_threshold"
#define DEFAULT_FREQ 8u
#define DEFAULT_RADIUS 3u
#define DEFAULT_SETS 32u
#define DEFAULT_DISC_SETS 4u

static const char help[] =
    "usage: mcspec projections FILE|- [--freq F] [--radius R] [--disc-sets S]\n"
    "                          [--csv] [--plot FILE.png|FILE.svg]\n"
    "       mcspec projections KIND --dim D --k K [--sets T] [--seed S] [same options]\n"
    "\n"
    "For every pair of dimensions (i, j) of the point sets of FILE (utk's format,\n"
    "any dimension 2..64; '#' lines end sets) or of T sets of K points drawn from\n"
    "KIND in D dimensions (the kinds of mcspec sample), how far the pair's 2D\n"
    "projection departs from what independent dimensions would give:\n"
    "  radial_low     mean periodogram P(f) over the off-axis wave vectors of the\n"
    "                 low disc 0 < |f| <= R (f_x, f_y != 0; the axes are each\n"
    "                 dimension's own 1D spectrum), over the sets, +- its stderr\n"
    "  radial_low_ref the same for the two 1D sets paired at random: 1 + (P_i -\n"
    "                 1)(P_j - 1)/(K - 1) from the 1D periodograms (1 for random\n"
    "                 points, K/(K-1) for two stratified dimensions)\n"
    "  radial_low_z   (radial_low - ref) / its stderr over the sets\n"
    "  anisotropy_db  psa's anisotropy of the mean periodogram, averaged over the\n"
    "                 annuli r = 1..F\n"
    "  discrepancy    squared wrap-around L2 discrepancy of the projection, over\n"
    "                 the first S sets (discrepancy_random: E for random points)\n"
    "  peak           largest off-axis P / ref over |f_x|, |f_y| <= F per set,\n"
    "                 mean over sets +- stderr; peak_max the largest of all\n"
    "  flagged        1 if radial_low_z > 5 (more low-frequency power than\n"
    "                 independence) or peak_max > peak_threshold = ln(n T m /\n"
    "                 5.7e-7), the Bonferroni bound of the largest of n T unit\n"
    "                 exponentials over m pairs (n = 2 F^2)\n"
    "docs/projections.md derives the test. Then a d x d matrix of radial_low /\n"
    "ref with flagged pairs marked '*', and the list of flagged pairs.\n"
    "\n"
    "Options:\n"
    "  --freq F       cutoff of the periodogram box, 1..64 (default 8)\n"
    "  --radius R     radius of the low disc, 1..F (default 3)\n"
    "  --disc-sets S  sets whose discrepancies are computed (O(K^2) a pair), 0..\n"
    "                 (default 4)\n"
    "  --dim D, --k K, --sets T (default 32), --seed S (default 1): KIND's sets,\n"
    "                 drawn as mcspec sample draws them (--k selects this form)\n"
    "  --csv          print CSV only: the header, first columns exactly\n"
    "                 dim_i,dim_j,radial_low,radial_low_stderr,anisotropy_db,\n"
    "                 discrepancy,peak,peak_stderr,flagged\n"
    "                 then radial_low_ref,radial_low_z,discrepancy_stderr,\n"
    "                 discrepancy_random,peak_max,peak_threshold; one row per pair\n"
    "  --plot FILE    also draw the d x d heat map of log10(radial_low / ref),\n"
    "                 flagged pairs crossed, to FILE (.png or .svg; needs gnuplot)\n"
    "  --help         this text\n"
    "\n"
    "Exit status: 0 on success (flagged pairs or not), 2 on bad usage or input\n"
    "(one line on stderr).\n";

typedef struct {
    size_t freq, radius, disc_sets, dim, k, sets;
    uint64_t seed;
    int csv, kind_mode;
    const char *arg, *plot;
} proj_opts;

/* The sets of a file, kept until the largest K is known. */
typedef struct {
    double *coords;
    size_t *k;
    size_t nsets, cap_sets, ncoords, cap_coords, dim;
    const cli_pointset_stats *stats;
} file_sets;

static int keep_set(void *ctx, size_t k, const double *coords, const double *weights)
{
    (void)weights;
    file_sets *f = ctx;
    const size_t dim = f->stats->dim, need = f->ncoords + k * dim;
    if (f->nsets == f->cap_sets) {
        size_t cap = f->cap_sets ? 2u * f->cap_sets : 64u;
        size_t *nk = realloc(f->k, cap * sizeof *nk);
        if (nk == NULL)
            return cli_internal(CMD, "out of memory");
        f->k = nk;
        f->cap_sets = cap;
    }
    if (need > f->cap_coords) {
        size_t cap = f->cap_coords ? f->cap_coords : 4096u;
        while (cap < need)
            cap *= 2u;
        double *nc = realloc(f->coords, cap * sizeof *nc);
        if (nc == NULL)
            return cli_internal(CMD, "out of memory");
        f->coords = nc;
        f->cap_coords = cap;
    }
    memcpy(f->coords + f->ncoords, coords, k * dim * sizeof *coords);
    f->ncoords = need;
    f->k[f->nsets++] = k;
    f->dim = dim;
    return 0;
}

static int parse(int argc, char **argv, proj_opts *o)
{
    cli_opt opts[] = {
        {"freq", CLI_OPT_SIZE, &o->freq, 1, MCS_PROJECTIONS_MAX_FREQ, 0},
        {"radius", CLI_OPT_SIZE, &o->radius, 1, MCS_PROJECTIONS_MAX_FREQ, 0},
        {"disc-sets", CLI_OPT_SIZE, &o->disc_sets, 0, 1000000, 0},
        {"dim", CLI_OPT_SIZE, &o->dim, 2, MCS_PROJECTIONS_MAX_DIM, 0},
        {"k", CLI_OPT_SIZE, &o->k, 1, CLI_MAX_K, 0},
        {"sets", CLI_OPT_SIZE, &o->sets, 1, 1000000, 0},
        {"seed", CLI_OPT_U64, &o->seed, 0, UINT64_MAX, 0},
        {"csv", CLI_OPT_FLAG, &o->csv, 0, 0, 0},
        {"plot", CLI_OPT_STRING, &o->plot, 0, 0, 0},
    };
    int rc = cli_parse_one(CMD, help, NULL, opts, CLI_COUNT(opts), argc, argv, &o->arg);
    if (rc != CLI_PARSED)
        return rc;
    o->kind_mode = opts[4].given;
    if (o->radius > o->freq)
        return cli_fail(CMD, "--radius %zu is above --freq %zu: give R <= F", o->radius, o->freq);
    if (o->kind_mode) {
        if (o->arg == NULL)
            return cli_fail(CMD, "--k draws sets of a KIND: give KIND (see mcspec sample --help)");
        if (!opts[3].given)
            return cli_fail(CMD, "give --dim D (2..%d) with KIND", MCS_PROJECTIONS_MAX_DIM);
    } else {
        if (opts[3].given || opts[5].given || opts[6].given)
            return cli_fail(CMD, "--dim, --sets and --seed go with KIND --k K, not a file");
        if (o->arg == NULL && isatty(STDIN_FILENO))
            return cli_fail(CMD, "no input: give a point file, '-', or KIND --dim D --k K");
    }
    if (o->plot != NULL && cli_plot_check(CMD, o->plot) != 0)
        return CLI_EXIT_USAGE;
    return 0;
}

/* ---- Output -------------------------------------------------------------- */

static void csv_row(size_t i, size_t j, const mcs_projections_pair *r)
{
    const double v[14] = {r->radial_low,       r->radial_low_stderr, r->anisotropy_db,
                          r->discrepancy,      r->peak,              r->peak_stderr,
                          (double)r->flagged,  r->radial_low_ref,    r->radial_low_z,
                          r->discrepancy_stderr, r->discrepancy_random, r->peak_max,
                          r->peak_threshold,   0.0};
    printf("%zu,%zu", i, j);
    for (int c = 0; c < 13; ++c) {
        char buf[40];
        if (c == 6)
            snprintf(buf, sizeof buf, "%d", r->flagged);
        else
            cli_csv_double(buf, sizeof buf, v[c]);
        printf(",%s", buf);
    }
    putchar('\n');
}

static void table_row(size_t i, size_t j, const mcs_projections_pair *r)
{
    char b[8][40];
    cli_table_double(b[0], sizeof b[0], 9, r->radial_low);
    cli_table_double(b[1], sizeof b[1], 9, r->radial_low_stderr);
    cli_table_double(b[2], sizeof b[2], 9, r->radial_low_ref);
    cli_table_double(b[3], sizeof b[3], 8, r->radial_low_z);
    cli_table_double(b[4], sizeof b[4], 8, r->anisotropy_db);
    cli_table_double(b[5], sizeof b[5], 11, r->discrepancy);
    cli_table_double(b[6], sizeof b[6], 8, r->peak);
    cli_table_double(b[7], sizeof b[7], 8, r->peak_max);
    printf("%3zu %3zu %s %s %s %s %s %s %s %s %s\n", i, j, b[0], b[1], b[2], b[3], b[4], b[5],
           b[6], b[7], r->flagged ? "FLAGGED" : "-");
}

static void matrix(const mcs_projections *p)
{
    const size_t d = p->dim;
    printf("\nradial_low / ref by pair (1: as independent dimensions; * flagged):\n    ");
    for (size_t j = 0; j < d; ++j)
        printf(" %7zu", j);
    putchar('\n');
    for (size_t i = 0; i < d; ++i) {
        printf("%3zu ", i);
        for (size_t j = 0; j < d; ++j) {
            mcs_projections_pair r;
            if (i == j || mcs_projections_pair_stats(p, i, j, &r) != MCS_OK) {
                printf(" %7s", "-");
                continue;
            }
            printf(" %6.3f%c", r.radial_low / r.radial_low_ref, r.flagged ? '*' : ' ');
        }
        putchar('\n');
    }
}

typedef struct {
    const mcs_projections *p;
    const char *title;
} heat_figure;

static int write_heat(FILE *fp, const char *tmp, const void *ctx)
{
    const heat_figure *fig = ctx;
    const size_t d = fig->p->dim;
    FILE *data = cli_plot_data(tmp, "data.txt");
    if (data == NULL)
        return -1;
    fputs("# i j log10(radial_low/ref)\n", data);
    for (size_t j = 0; j < d; ++j) {
        for (size_t i = 0; i < d; ++i) {
            mcs_projections_pair r;
            double v = (double)NAN;
            if (i != j && mcs_projections_pair_stats(fig->p, i, j, &r) == MCS_OK &&
                r.radial_low > 0.0 && r.radial_low_ref > 0.0)
                v = log10(r.radial_low / r.radial_low_ref);
            fprintf(data, "%zu %zu", i, j);
            cli_plot_value(data, v);
            fputc('\n', data);
        }
        fputc('\n', data);
    }
    if (fclose(data) != 0)
        return -1;
    fprintf(fp, "set title \"%s\\nlog10(radial_low / independent reference) per pair; x: flagged\" "
                "noenhanced\n", fig->title);
    fputs("set xlabel \"dimension i\"\nset ylabel \"dimension j\"\nset size ratio -1\n"
          "set cblabel \"log10(radial_low / ref)\" noenhanced\nunset key\n"
          "set palette defined (-2 '#2166ac', 0 '#f7f7f7', 2 '#b2182b')\nset cbrange [-2:2]\n",
          fp);
    fprintf(fp, "set xrange [-0.5:%.1f]\nset yrange [-0.5:%.1f]\n", (double)d - 0.5,
            (double)d - 0.5);
    for (size_t i = 0; i < d; ++i)
        for (size_t j = 0; j < d; ++j) {
            mcs_projections_pair r;
            if (i != j && mcs_projections_pair_stats(fig->p, i, j, &r) == MCS_OK && r.flagged)
                fprintf(fp, "set label \"x\" at %zu,%zu center front font \",14\"\n", i, j);
        }
    fputs("plot ", fp);
    cli_plot_data_ref(fp, tmp, "data.txt");
    fputs(" using 1:2:3 with image notitle\n", fp);
    return 0;
}

static int report(const proj_opts *o, const mcs_projections *p, const char *source)
{
    const size_t d = p->dim;
    size_t nflag = 0;
    (void)mcs_projections_flagged(p, &nflag);
    if (o->csv) {
        puts(CSV_HEADER);
    } else {
        printf("%s: %s, %llu sets of up to %zu points in %zuD; F = %zu, low disc R = %zu, "
               "discrepancy over %zu sets\n",
               CMD, source, (unsigned long long)p->sets, p->k_max, d, p->freq, p->radius,
               p->disc_sets < p->sets ? p->disc_sets : (size_t)p->sets);
        printf("\n  i   j radial_lo    stderr       ref        z  aniso_dB discrepancy     "
               "peak peak_max flagged\n");
    }
    for (size_t i = 0; i < d; ++i)
        for (size_t j = i + 1u; j < d; ++j) {
            mcs_projections_pair r;
            if (mcs_projections_pair_stats(p, i, j, &r) != MCS_OK)
                return cli_internal(CMD, "reading pair (%zu, %zu) failed", i, j);
            if (o->csv)
                csv_row(i, j, &r);
            else
                table_row(i, j, &r);
        }
    if (!o->csv) {
        matrix(p);
        printf("\n%zu of %zu pairs flagged", nflag, d * (d - 1u) / 2u);
        if (nflag > 0u) {
            printf(":");
            for (size_t i = 0; i < d; ++i)
                for (size_t j = i + 1u; j < d; ++j) {
                    mcs_projections_pair r;
                    if (mcs_projections_pair_stats(p, i, j, &r) == MCS_OK && r.flagged)
                        printf(" (%zu,%zu)", i, j);
                }
        }
        putchar('\n');
    }
    if (o->plot != NULL) {
        const heat_figure fig = {p, source};
        return cli_plot_render(CMD, o->plot, write_heat, &fig);
    }
    return 0;
}

/* ---- Runs ----------------------------------------------------------------- */

static int run(const proj_opts *o, size_t dim, size_t k_max, mcs_projections *p, void **mem)
{
    size_t bytes = 0;
    mcs_status st = mcs_projections_size(dim, o->freq, k_max, &bytes);
    if (st != MCS_OK)
        return cli_fail(CMD, "cannot analyse %zu dimensions with K up to %zu: %s", dim, k_max,
                        mcs_status_str(st));
    *mem = cli_alloc(CMD, 1, bytes);
    if (*mem == NULL)
        return CLI_EXIT_FAIL;
    st = mcs_projections_init(p, dim, o->freq, o->radius, k_max, o->disc_sets, *mem, bytes);
    return st == MCS_OK ? 0 : cli_internal(CMD, "mcs_projections_init: %s", mcs_status_str(st));
}

static int run_kind(const proj_opts *o)
{
    cli_sample_source src;
    int rc = cli_sample_init(CMD, o->arg, o->dim, o->k, MCS_MAX_N, &src);
    mcs_projections p;
    void *mem = NULL;
    double *pts = NULL;
    mcs_rng rng;
    if (rc == 0)
        rc = run(o, o->dim, o->k, &p, &mem);
    if (rc == 0) {
        pts = cli_alloc(CMD, o->k * o->dim, sizeof *pts);
        rc = pts == NULL || mcs_rng_seed(&rng, o->seed, 0u) != MCS_OK ? CLI_EXIT_FAIL : 0;
    }
    for (size_t t = 0; rc == 0 && t < o->sets; ++t) {
        rc = cli_sample_draw(CMD, &src, &rng, pts);
        mcs_status st = rc == 0 ? mcs_projections_add(&p, o->k, pts) : MCS_OK;
        if (st != MCS_OK)
            rc = cli_internal(CMD, "adding a set failed: %s", mcs_status_str(st));
    }
    if (rc == 0) {
        char source[160];
        snprintf(source, sizeof source, "%s (seed %llu)", o->arg, (unsigned long long)o->seed);
        rc = report(o, &p, source);
    }
    free(pts);
    free(mem);
    cli_sample_free(&src);
    return rc;
}

static int run_file(const proj_opts *o)
{
    file_sets f;
    memset(&f, 0, sizeof f);
    cli_pointset_stats stats;
    f.stats = &stats;
    cli_pointset_format fmt = {.dim = 0, .weights = 0, .wrap = 0};
    int rc = cli_read_pointsets(CMD, o->arg, &fmt, keep_set, &f, &stats, NULL);
    if (rc == 0 && (stats.dim < 2u || stats.dim > MCS_PROJECTIONS_MAX_DIM))
        rc = cli_fail(CMD, "%s has points of %zu coordinates: projections need 2 to %d",
                      cli_input_name(o->arg), stats.dim, MCS_PROJECTIONS_MAX_DIM);
    if (rc == 0 && f.nsets == 0u)
        rc = cli_fail(CMD, "%s holds no point set", cli_input_name(o->arg));
    mcs_projections p;
    void *mem = NULL;
    if (rc == 0)
        rc = run(o, stats.dim, stats.k_max, &p, &mem);
    size_t off = 0;
    for (size_t s = 0; rc == 0 && s < f.nsets; ++s) {
        mcs_status st = mcs_projections_add(&p, f.k[s], f.coords + off);
        off += f.k[s] * stats.dim;
        if (st != MCS_OK)
            rc = cli_internal(CMD, "adding set %zu failed: %s", s + 1u, mcs_status_str(st));
    }
    if (rc == 0)
        rc = report(o, &p, cli_input_name(o->arg));
    free(mem);
    free(f.coords);
    free(f.k);
    return rc;
}

int cli_cmd_projections(int argc, char **argv)
{
    proj_opts o = {DEFAULT_FREQ, DEFAULT_RADIUS, DEFAULT_DISC_SETS, 0, 0, DEFAULT_SETS, 1u,
                   0, 0, NULL, NULL};
    int rc = parse(argc, argv, &o);
    if (rc != 0)
        return rc < 0 ? CLI_EXIT_OK : rc;
    return o.kind_mode ? run_kind(&o) : run_file(&o);
}
