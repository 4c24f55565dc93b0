/* mcspec discrepancy: the L2 discrepancies (and the exact 2D star
 * discrepancy) of point sets read from a file or drawn from a named kind,
 * mean over the sets beside the exact expectation for independent uniform
 * points and, for a kind whose expectation is known, the kind's own. */
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

#define CMD "mcspec discrepancy"
#define CSV_HEADER "measure,value,stderr,exact_random,root,exact"

/* Most coordinates a point line may have: the reader's cap, which is the
 * library's MCS_DISCREPANCY_MAX_DIM. */
#define MAX_DIM CLI_MAX_DIM
_Static_assert(CLI_MAX_DIM <= MCS_DISCREPANCY_MAX_DIM, "the reader takes what the library takes");

static const char help[] =
    "usage: mcspec discrepancy [--dim D] [--wrap] [--csv] [--save FILE] [FILE|-]\n"
    "       mcspec discrepancy KIND --dim D --k K [--sets T] [--seed S] [--csv] [--save FILE]\n"
    "\n"
    "The L2 discrepancies of point sets read from FILE (or standard input, given\n"
    "as '-' or by giving no FILE), one set per trial: per set the squared\n"
    "discrepancy D^2 by its closed form, O(D K^2) for K points, and over the\n"
    "sets its mean (value), the standard error of the mean, the exact E[D^2] of\n"
    "independent uniform points in sets of the same sizes (exact_random) and\n"
    "root = sqrt(value), on utk's scale (utk prints one set's D, the root of\n"
    "its D^2; with one set the two agree), and exact, the exact E[D^2] of the\n"
    "sets' own kind where it is known (KIND random: exact_random; jittered in\n"
    "2D, one uniform point per cell of its m x n grid, stratified in 1D, and\n"
    "sobol-owen and halton-owen in 1D with K a power of 2, which are stratified\n"
    "sets: the jittered closed form; empty otherwise and for files). Rows:\n"
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
    "table, z = (value - exact) / stderr, or against exact_random without exact.\n"
    "\n"
    "Input: one point per line, D coordinates in [0,1) separated by spaces or\n"
    "tabs; a line starting with '#' ends the current set (utk's convention), as\n"
    "for mcspec spectrum. Everything is read and checked before anything is\n"
    "printed: a malformed line stops the run with the file, the line number\n"
    "and what was wrong, exit 2.\n"
    "\n"
    "KIND (instead of a file): T sets of K points of a kind of mcspec sample, in\n"
    "D dimensions it has (mcspec sample --help lists them), drawn from PCG32\n"
    "seeded with S as mcspec sample --seed S draws them.\n"
    "\n"
    "Options:\n"
    "  --dim D   coordinates per point, 1 to " CLI_STR(CLI_MAX_DIM) " (default: as many as the\n"
    "            first point line has; every line must then have as many)\n"
    "            (KIND: required, 1 to 64 as KIND has them)\n"
    "  --k K     KIND: points per set, 1.." CLI_STR(CLI_MAX_K) "\n"
    "  --sets T  KIND: sets, 1..1000000 (default 64)\n"
    "  --seed S  KIND: the PCG32 seed (default 1)\n"
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
    size_t dim, k, sets;
    uint64_t seed;
    int wrap, csv, kind_mode;
    const char *path; /* the file, or KIND */
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
        {"k", CLI_OPT_SIZE, &o->k, 1, CLI_MAX_K, 0},
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

/* v: value, stderr, exact_random, root, exact. */
static void print_row(int csv, mcs_discrepancy_measure m, const double *v)
{
    if (csv) {
        printf("%s", mcs_discrepancy_measure_str(m));
        cli_print_values(1, v, 5);
        return;
    }
    printf("%-15s", mcs_discrepancy_measure_str(m));
    for (int i = 0; i < 5; ++i) {
        char buf[40];
        cli_table_double(buf, sizeof buf, 13, v[i]);
        printf(" %s", buf);
    }
    const double want = isnan(v[4]) ? v[2] : v[4];
    const double z = cli_z(v[0], want, v[1], 1e-12 * fabs(want));
    if (isnan(z))
        printf(" %8s\n", "-");
    else
        printf(" %8.2f\n", z);
}

/* The exact E[D^2] of the sets' kind, per measure (NaN: not known). */
typedef struct {
    const char *source; /* "random (seed 1)", or NULL for the input's name */
    double exact[MCS_DISCREPANCY_MEASURES];
} disc_exact;

void cli_discrepancy_rows(int csv, const mcs_discrepancy *acc,
                          const double exact[MCS_DISCREPANCY_MEASURES])
{
    uint64_t star = 0u, sets = 0u;
    (void)mcs_discrepancy_count(acc, MCS_DISCREPANCY_STAR, &star);
    (void)mcs_discrepancy_count(acc, MCS_DISCREPANCY_L2_STAR, &sets);
    const int with_star = acc->dim == 2u && star == sets;
    if (csv)
        puts(CSV_HEADER);
    else
        printf("\n%-15s %13s %13s %13s %13s %13s %8s\n", "measure", "value", "stderr",
               "exact_random", "root", "exact", "z");
    for (int i = 0; i < MCS_DISCREPANCY_MEASURES; ++i) {
        const mcs_discrepancy_measure m = (mcs_discrepancy_measure)i;
        if (m == MCS_DISCREPANCY_STAR && !with_star)
            continue;
        double v[5] = {read_or_nan(mcs_discrepancy_mean, acc, m),
                       read_or_nan(mcs_discrepancy_stderr, acc, m),
                       read_or_nan(mcs_discrepancy_exact_random, acc, m), (double)NAN, exact[i]};
        v[3] = sqrt(fmax(v[0], 0.0)); /* a D^2 within rounding of 0 may be slightly negative */
        print_row(csv, m, v);
    }
}

static void report(const disc_opts *o, const mcs_discrepancy *acc,
                   const cli_pointset_stats *stats, const disc_exact *ex)
{
    uint64_t star = 0;
    mcs_discrepancy_count(acc, MCS_DISCREPANCY_STAR, &star);
    const int with_star = stats->dim == 2u && star == stats->sets;
    if (!o->csv) {
        cli_sets_line(CMD, ex->source, o->path, stats);
        printf("value: mean over the sets of D^2; root = sqrt(value); exact_random: E[D^2] of "
               "independent uniform points; exact: E[D^2] of the sets' kind (- where not "
               "known); z = (value - exact, else exact_random) / stderr\n");
        if (stats->dim == 2u && !with_star)
            printf("star: not computed (a set has more than %d points)\n",
                   MCS_DISCREPANCY_STAR_MAX_K);
    }
    cli_discrepancy_rows(o->csv, acc, ex->exact);
}

/* The exact E[D^2] of KIND's sets where the library has it: random (any
 * dimension), 2D jittered over its strata, 1D stratified (n = K strata),
 * and the 1D Owen-scrambled base-2 kinds at K = 2^m: a scrambled (0,m,1)-net
 * has the pair laws of the stratified pattern (docs/owen.md, "The 1D
 * identity"), and D^2 depends on the points through pairs only. */
void cli_discrepancy_exact(const char *name, size_t dim, size_t k,
                           double exact[MCS_DISCREPANCY_MEASURES])
{
    mcs_pattern2d grid;
    const int jittered = name != NULL && strcmp(name, "jittered") == 0 && dim == 2u &&
                         mcs_pattern2d_init(&grid, MCS_PATTERN2D_JITTERED, k, 0u, 0u) == MCS_OK;
    for (int i = 0; i < MCS_DISCREPANCY_MEASURES; ++i) {
        const mcs_discrepancy_measure m = (mcs_discrepancy_measure)i;
        double v = NAN;
        mcs_status st = MCS_ERR_DOMAIN;
        if (name == NULL || m == MCS_DISCREPANCY_STAR)
            st = MCS_ERR_DOMAIN;
        else if (strcmp(name, "random") == 0)
            st = mcs_discrepancy_l2_exact_random(m, k, dim, &v);
        else if (jittered)
            st = mcs_discrepancy_l2_exact_jittered2d(m, grid.strata_x, grid.strata_y, &v);
        else if (dim == 1u && (strcmp(name, "stratified") == 0 ||
                               ((strcmp(name, "sobol-owen") == 0 || strcmp(name, "halton-owen") == 0) &&
                                (k & (k - 1u)) == 0u)))
            st = mcs_discrepancy_l2_exact_jittered(m, k, 1u, &v);
        exact[i] = st == MCS_OK ? v : (double)NAN;
    }
}

/* T sets of KIND into ctx, as the file's sets would go. */
static int run_kind(const disc_opts *o, disc_ctx *ctx, cli_pointset_stats *stats, disc_exact *ex,
                    char *source, size_t source_size)
{
    cli_sample_source src;
    int rc = cli_sample_init(CMD, o->path, o->dim, o->k, MCS_MAX_N, &src);
    if (rc != 0)
        return rc;
    cli_discrepancy_exact(src.kind->name, src.dim, src.k, ex->exact);
    if (strcmp(o->path, "jittered") == 0)
        snprintf(source, source_size, "jittered %zu x %zu strata (seed %llu)",
                 src.pattern2d.strata_x, src.pattern2d.strata_y, (unsigned long long)o->seed);
    else
        snprintf(source, source_size, "%s (seed %llu)", o->path, (unsigned long long)o->seed);
    ex->source = source;
    cli_progress progress;
    cli_progress_init(&progress, !o->csv, CMD, "sets drawn", o->sets);
    rc = cli_kind_feed(CMD, &src, o->sets, o->seed, add_set, ctx, stats, &progress);
    cli_progress_end(&progress);
    cli_sample_free(&src);
    return rc;
}

int cli_cmd_discrepancy(int argc, char **argv)
{
    disc_opts o = {0, 0, 64, 1, 0, 0, 0, NULL, NULL};
    int rc = parse(argc, argv, &o);
    if (rc != 0)
        return rc < 0 ? CLI_EXIT_OK : rc;
    disc_exact ex = {.source = NULL};
    for (int i = 0; i < MCS_DISCREPANCY_MEASURES; ++i)
        ex.exact[i] = (double)NAN;
    char source[160];
    disc_ctx *ctx = cli_alloc(CMD, 1, sizeof *ctx);
    if (ctx == NULL)
        return CLI_EXIT_FAIL;
    cli_pointset_stats stats;
    ctx->acc.dim = 0;
    ctx->work = NULL;
    ctx->work_bytes = 0;
    ctx->stats = &stats;
    cli_save_target save = {o.save, o.path, 0u, 0u};
    if (o.kind_mode) {
        rc = o.save != NULL ? cli_write_check(CMD, o.save) : 0;
        if (rc == 0)
            rc = run_kind(&o, ctx, &stats, &ex, source, sizeof source);
    } else {
        cli_pointset_format fmt = {.dim = o.dim, .weights = 0, .wrap = o.wrap};
        rc = cli_save_begin(CMD, &save);
        cli_progress progress;
        cli_progress_init(&progress, !o.csv, CMD, "sets read", 0);
        if (rc == 0)
            rc = cli_read_pointsets(CMD, o.path, &fmt, add_set, ctx, &stats, &progress);
        cli_progress_end(&progress);
    }
    if (rc == 0)
        report(&o, &ctx->acc, &stats, &ex);
    if (rc == 0 && o.kind_mode) {
        const cli_run run = {(unsigned)o.dim, o.path, o.dim == 1u ? (uint64_t)MCS_MAX_N : 0u,
                             o.k, 0, 0u, o.seed, 1u, o.sets};
        rc = cli_save_drawn(CMD, o.save, &run, MCS_IO_KIND_DISCREPANCY, &ctx->acc);
    } else if (rc == 0) {
        rc = cli_save_points(CMD, &save, MCS_IO_KIND_DISCREPANCY, &ctx->acc);
    }
    free(ctx->work);
    free(ctx);
    return rc;
}
