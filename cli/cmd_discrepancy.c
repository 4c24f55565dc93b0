/* mcspec discrepancy: the L2 discrepancies (and the exact 2D star
 * discrepancy) of point sets read from a file, mean over the sets beside the
 * exact expectation for independent uniform points. */
#include "cli.h"
#include "input.h"
#include "output.h"
#include "progress.h"
#include "record.h"

#include "mcspec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

/* The entry point, declared here until cli.h lists it with the others. */

#define CMD "mcspec discrepancy"
#define CSV_HEADER "measure,value,stderr,exact_random,root"

/* Most coordinates a point line may have: the reader's cap, which is the
 * library's MCS_DISCREPANCY_MAX_DIM. */
#define MAX_DIM CLI_MAX_DIM
_Static_assert(CLI_MAX_DIM <= MCS_DISCREPANCY_MAX_DIM, "the reader takes what the library takes");

static const char help[] =
    "usage: mcspec discrepancy [--dim D] [--wrap] [--csv] [--save FILE] [FILE|-]\n"
    "\n"
    "The L2 discrepancies of point sets read from FILE (or standard input, given\n"
    "as '-' or by giving no FILE), one set per trial: per set the squared\n"
    "discrepancy D^2 by its closed form, O(D K^2) for K points, and over the\n"
    "sets its mean (value), the standard error of the mean, the exact E[D^2] of\n"
    "independent uniform points in sets of the same sizes (exact_random) and\n"
    "root = sqrt(value), on utk's scale (utk prints one set's D, the root of\n"
    "its D^2; with one set the two agree). Rows:\n"
    "  l2_star         Warnock's L2 star discrepancy (utk L2Discrepancy)\n"
    "  l2_centered     Hickernell's centred L2 (utk CenteredL2Discrepancy)\n"
    "  l2_wraparound   Hickernell's wrap-around L2 (not in utk)\n"
    "  l2_symmetric    Hickernell's symmetric L2 (utk SymmetricL2Discrepancy)\n"
    "  l2_generalized  Hickernell's generalized L2 (utk GL2Discrepancy)\n"
    "  l2_unanchored   the unanchored L2, boxes anywhere (utk UnanchoredL2)\n"
    "  star            the exact star (L-infinity) discrepancy D*, squared like\n"
    "                  the others (root = D* for one set); --dim 2 and every set\n"
    "                  of at most " CLI_STR(MCS_DISCREPANCY_STAR_MAX_K)
    " points only, and no exact_random\n"
    "The formulas, their expectations and references: docs/measures.md. In the\n"
    "table, z = (value - exact_random) / stderr.\n"
    "\n"
    "Input: one point per line, D coordinates in [0,1) separated by spaces or\n"
    "tabs; a line starting with '#' ends the current set (utk's convention), as\n"
    "for mcspec spectrum. Everything is read and checked before anything is\n"
    "printed: a malformed line stops the run with the file, the line number\n"
    "and what was wrong, exit 2.\n"
    "\n"
    "Options:\n"
    "  --dim D   coordinates per point, 1 to " CLI_STR(CLI_MAX_DIM) " (default: as many as the\n"
    "            first point line has; every line must then have as many)\n"
    "  --wrap    take coordinates modulo 1 (default: outside [0,1) is an error)\n"
    "  --csv     print CSV only: the header, exactly\n"
    "            " CSV_HEADER "\n"
    "            and one row per measure (an empty field: no value)\n"
    "  --save FILE  also save the accumulator (a discrepancy record, docs/format.md)\n"
    "            for mcspec merge and mcspec show, written atomically (as\n"
    "            mcspec spectrum --save)\n"
    "  --help    this text\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage or input (one line on stderr).\n";

typedef struct {
    size_t dim;
    int wrap, csv;
    const char *path;
    const char *save; /* --save FILE */
} disc_opts;

typedef struct {
    mcs_discrepancy acc; /* initialised at the first set, when the dimension is known */
    void *work;          /* the star's scratch (2D), or NULL */
    size_t work_bytes;
    const cli_pointset_stats *stats; /* the reader's: the file's dimension */
} disc_ctx;

static int parse(int argc, char **argv, disc_opts *o)
{
    cli_opt opts[] = {
        {"dim", CLI_OPT_SIZE, &o->dim, 1, MAX_DIM, 0},
        {"wrap", CLI_OPT_FLAG, &o->wrap, 0, 0, 0},
        {"csv", CLI_OPT_FLAG, &o->csv, 0, 0, 0},
        {"save", CLI_OPT_STRING, &o->save, 0, 0, 0},
    };
    int rc = cli_parse_one(CMD, help, NULL, opts, CLI_COUNT(opts), argc, argv, &o->path);
    if (rc != CLI_PARSED)
        return rc;
    if (o->path == NULL && isatty(STDIN_FILENO))
        return cli_fail(CMD, "no input: give a point file, or '-' to read standard input");
    return 0;
}

static int add_set(void *ctx, size_t k, const double *coords, const double *weights)
{
    (void)weights;
    disc_ctx *c = ctx;
    if (c->acc.dim == 0u) {
        if (mcs_discrepancy_init(&c->acc, c->stats->dim) != MCS_OK)
            return cli_internal(CMD, "mcs_discrepancy_init failed");
        if (c->stats->dim == 2u) {
            c->work_bytes = MCS_DISCREPANCY_STAR_WORK_SIZE(MCS_DISCREPANCY_STAR_MAX_K);
            c->work = cli_alloc(CMD, 1, c->work_bytes);
            if (c->work == NULL)
                return CLI_EXIT_FAIL;
        }
    }
    mcs_status st = mcs_discrepancy_add(&c->acc, k, coords, c->work, c->work_bytes);
    if (st != MCS_OK)
        return cli_internal(CMD, "adding a point set failed: %s", mcs_status_str(st));
    return 0;
}

static double read_or_nan(mcs_status (*read)(const mcs_discrepancy *, mcs_discrepancy_measure,
                                             double *),
                          const mcs_discrepancy *acc, mcs_discrepancy_measure m)
{
    double v = NAN;
    return read(acc, m, &v) == MCS_OK ? v : (double)NAN;
}

static void print_row(int csv, mcs_discrepancy_measure m, const double *v)
{
    if (csv) {
        printf("%s", mcs_discrepancy_measure_str(m));
        cli_print_values(1, v, 4);
        return;
    }
    printf("%-15s", mcs_discrepancy_measure_str(m));
    for (int i = 0; i < 4; ++i) {
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

static void report(const disc_opts *o, const mcs_discrepancy *acc,
                   const cli_pointset_stats *stats)
{
    uint64_t star = 0;
    mcs_discrepancy_count(acc, MCS_DISCREPANCY_STAR, &star);
    const int with_star = stats->dim == 2u && star == stats->sets;
    if (o->csv) {
        puts(CSV_HEADER);
    } else {
        printf("%s: %s, %llu point sets in %zuD, K = %zu to %zu points per set (%lu lines read)\n",
               CMD, cli_input_name(o->path), (unsigned long long)stats->sets, stats->dim,
               stats->k_min, stats->k_max, stats->lines);
        printf("value: mean over the sets of D^2; root = sqrt(value); exact_random: E[D^2] of "
               "independent uniform points; z = (value - exact_random) / stderr\n");
        if (stats->dim == 2u && !with_star)
            printf("star: not computed (a set has more than %d points)\n",
                   MCS_DISCREPANCY_STAR_MAX_K);
        printf("\n%-15s %13s %13s %13s %13s %8s\n", "measure", "value", "stderr", "exact_random",
               "root", "z");
    }
    for (int i = 0; i < MCS_DISCREPANCY_MEASURES; ++i) {
        const mcs_discrepancy_measure m = (mcs_discrepancy_measure)i;
        if (m == MCS_DISCREPANCY_STAR && !with_star)
            continue;
        double v[4] = {read_or_nan(mcs_discrepancy_mean, acc, m),
                       read_or_nan(mcs_discrepancy_stderr, acc, m),
                       read_or_nan(mcs_discrepancy_exact_random, acc, m), (double)NAN};
        v[3] = sqrt(fmax(v[0], 0.0)); /* a D^2 within rounding of 0 may be slightly negative */
        print_row(o->csv, m, v);
    }
}

int cli_cmd_discrepancy(int argc, char **argv)
{
    disc_opts o = {0, 0, 0, NULL, NULL};
    int rc = parse(argc, argv, &o);
    if (rc != 0)
        return rc < 0 ? CLI_EXIT_OK : rc;
    disc_ctx *ctx = cli_alloc(CMD, 1, sizeof *ctx);
    if (ctx == NULL)
        return CLI_EXIT_FAIL;
    cli_pointset_stats stats;
    ctx->acc.dim = 0;
    ctx->work = NULL;
    ctx->work_bytes = 0;
    ctx->stats = &stats;
    cli_pointset_format fmt = {.dim = o.dim, .weights = 0, .wrap = o.wrap};
    cli_save_target save = {o.save, o.path, 0u, 0u};
    rc = cli_save_begin(CMD, &save);
    cli_progress progress;
    cli_progress_init(&progress, !o.csv, CMD, "sets read", 0);
    if (rc == 0)
        rc = cli_read_pointsets(CMD, o.path, &fmt, add_set, ctx, &stats, &progress);
    cli_progress_end(&progress);
    if (rc == 0)
        report(&o, &ctx->acc, &stats);
    if (rc == 0)
        rc = cli_save_points(CMD, &save, MCS_IO_KIND_DISCREPANCY, &ctx->acc);
    free(ctx->work);
    free(ctx);
    return rc;
}
