/* mcspec stats: the spatial statistics of point sets read from a file, the
 * minimum and average minimum distances over the maximal packing distance. */
#include "cli.h"
#include "input.h"
#include "output.h"
#include "progress.h"

#include "mcspec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

/* The entry point, declared here until cli.h lists it with the others. */

#define CMD "mcspec stats"
#define CSV_HEADER "statistic,value,stderr"

/* Most coordinates a point line may have: the library's cap (the densest
 * lattice packings are known to d = 8). */
#define MAX_DIM MCS_SPACING_MAX_DIM

static const char help[] =
    "usage: mcspec stats [--dim D] [--wrap] [--csv] [FILE|-]\n"
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
    "(avg) in 2D; then their mean over the sets (value) and its standard error.\n"
    "Definitions and references: docs/measures.md.\n"
    "\n"
    "Input: one point per line, D coordinates in [0,1) separated by spaces or\n"
    "tabs; a line starting with '#' ends the current set (utk's convention), as\n"
    "for mcspec spectrum; every set needs 2 points or more. Everything is read\n"
    "and checked before anything is printed: a malformed line stops the run\n"
    "with the file, the line number and what was wrong, exit 2.\n"
    "\n"
    "Options:\n"
    "  --dim D   coordinates per point, 1 to " CLI_STR(MCS_SPACING_MAX_DIM) " (default: as many as the\n"
    "            first point line has; every line must then have as many)\n"
    "  --wrap    take coordinates modulo 1 (default: outside [0,1) is an error)\n"
    "  --csv     print CSV only: the header, exactly\n"
    "            " CSV_HEADER "\n"
    "            and one row per statistic (an empty field: no value)\n"
    "  --help    this text\n"
    "\n"
    "Exit status: 0 on success, 2 on bad usage or input (one line on stderr).\n";

typedef struct {
    size_t dim;
    int wrap, csv;
    const char *path;
} stats_opts;

typedef struct {
    mcs_spacing acc;
    const char *name; /* the input's name in messages */
    uint64_t sets;    /* sets seen, for messages */
    void *work;       /* scratch, grown to the largest set's need */
    size_t work_bytes;
    const cli_pointset_stats *stats; /* the reader's: the file's dimension */
} stats_ctx;

static int parse(int argc, char **argv, stats_opts *o)
{
    cli_opt opts[] = {
        {"dim", CLI_OPT_SIZE, &o->dim, 1, MAX_DIM, 0},
        {"wrap", CLI_OPT_FLAG, &o->wrap, 0, 0, 0},
        {"csv", CLI_OPT_FLAG, &o->csv, 0, 0, 0},
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
    if (st == MCS_OK && need > c->work_bytes) {
        void *w = realloc(c->work, need);
        if (w == NULL)
            return cli_internal(CMD, "out of memory for a set of %zu points", k);
        c->work = w;
        c->work_bytes = need;
    }
    if (st == MCS_OK)
        st = mcs_spacing_add(&c->acc, k, coords, c->work, c->work_bytes);
    if (st != MCS_OK)
        return cli_internal(CMD, "adding a point set failed: %s", mcs_status_str(st));
    return 0;
}

static void report(const stats_opts *o, const mcs_spacing *acc, const cli_pointset_stats *stats)
{
    if (o->csv) {
        puts(CSV_HEADER);
    } else {
        printf("%s: %s, %llu point sets in %zuD, K = %zu to %zu points per set (%lu lines read)\n",
               CMD, cli_input_name(o->path), (unsigned long long)stats->sets, stats->dim,
               stats->k_min, stats->k_max, stats->lines);
        printf("toroidal distances as fractions of the maximal packing distance d_max = %s; "
               "value: mean over the sets\n", stats->dim == 1u   ? "1/K"
                                              : stats->dim == 2u ? "sqrt(2 / (sqrt(3) K))"
                                                                 : "that of the densest lattice "
                                                                   "packing (docs/measures.md)");
        printf("\n%-17s %13s %13s\n", "statistic", "value", "stderr");
    }
    for (int i = 0; i < MCS_SPACING_STATISTICS; ++i) {
        const mcs_spacing_statistic s = (mcs_spacing_statistic)i;
        double v[2] = {(double)NAN, (double)NAN};
        if (mcs_spacing_mean(acc, s, &v[0]) != MCS_OK)
            v[0] = (double)NAN;
        if (mcs_spacing_stderr(acc, s, &v[1]) != MCS_OK)
            v[1] = (double)NAN;
        printf(o->csv ? "%s" : "%-17s", mcs_spacing_statistic_str(s));
        cli_print_values(o->csv, v, 2);
    }
}

int cli_cmd_stats(int argc, char **argv)
{
    stats_opts o = {0, 0, 0, NULL};
    int rc = parse(argc, argv, &o);
    if (rc != 0)
        return rc < 0 ? CLI_EXIT_OK : rc;
    cli_pointset_stats stats;
    stats_ctx ctx = {.name = cli_input_name(o.path), .sets = 0, .work = NULL, .work_bytes = 0,
                     .stats = &stats};
    ctx.acc.dim = 0; /* initialised at the first set, when the dimension is known */
    cli_pointset_format fmt = {.dim = o.dim, .weights = 0, .wrap = o.wrap};
    cli_progress progress;
    cli_progress_init(&progress, !o.csv, CMD, "sets read", 0);
    rc = cli_read_pointsets(CMD, o.path, &fmt, add_set, &ctx, &stats, &progress);
    cli_progress_end(&progress);
    if (rc == 0)
        report(&o, &ctx.acc, &stats);
    free(ctx.work);
    return rc;
}
