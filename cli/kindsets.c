/* Point sets of a named kind fed like a file's sets (kindsets.h). */
#include "kindsets.h"
#include "cli.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int cli_opt_given(const cli_opt *opts, size_t nopts, const char *name)
{
    for (size_t i = 0; i < nopts; ++i)
        if (strcmp(opts[i].name, name) == 0)
            return opts[i].given;
    return 0;
}

int cli_kind_known(const char *name)
{
    char names[1024];
    cli_sample_names(names, sizeof names);
    const size_t len = strlen(name);
    for (const char *p = names; len > 0u && (p = strstr(p, name)) != NULL; p += len) {
        const int starts = p == names || p[-1] == ' ';
        const int ends = p[len] == '\0' || p[len] == ',';
        if (starts && ends)
            return 1;
    }
    return 0;
}

int cli_kind_or_file(const char *cmd, const cli_opt *opts, size_t nopts, const cli_kind_args *a,
                     int *kind_mode)
{
    *kind_mode = cli_opt_given(opts, nopts, "k");
    if (*kind_mode) {
        if (a->path == NULL || strcmp(a->path, "-") == 0)
            return cli_fail(cmd, "--k draws sets of a KIND: give KIND (see mcspec sample --help)");
        if (!cli_opt_given(opts, nopts, "dim"))
            return cli_fail(cmd, "give --dim D with KIND %s", a->path);
        if (cli_opt_given(opts, nopts, "wrap"))
            return cli_fail(cmd, "--wrap goes with a point file, not KIND --k K");
        if (a->save != NULL && a->dim > 2u)
            return cli_fail(cmd, "--save of a drawn KIND takes --dim 1 or 2 (a record names "
                                 "a pattern in 1D or 2D): write the sets with mcspec sample "
                                 "and save from the file");
        return 0;
    }
    if (cli_opt_given(opts, nopts, "sets") || cli_opt_given(opts, nopts, "seed"))
        return cli_fail(cmd, "--sets and --seed go with KIND --k K, not a point file");
    if (a->path != NULL && cli_kind_known(a->path) && access(a->path, F_OK) != 0)
        return cli_fail(cmd, "KIND %s draws sets with --dim D --k K: give --k K", a->path);
    if (a->path == NULL && isatty(STDIN_FILENO))
        return cli_fail(cmd, "no input: give a point file, or '-' to read standard input");
    return 0;
}

void cli_sets_line(const char *cmd, const char *source, const char *path,
                   const cli_pointset_stats *stats)
{
    if (source != NULL)
        printf("%s: %s, %llu point sets in %zuD, K = %zu points per set\n", cmd, source,
               (unsigned long long)stats->sets, stats->dim, stats->k_min);
    else
        printf("%s: %s, %llu point sets in %zuD, K = %zu to %zu points per set (%lu lines read)\n",
               cmd, cli_input_name(path), (unsigned long long)stats->sets, stats->dim,
               stats->k_min, stats->k_max, stats->lines);
}

int cli_kind_feed(const char *cmd, const cli_sample_source *src, uint64_t sets, uint64_t seed,
                  cli_pointset_fn fn, void *ctx, cli_pointset_stats *stats, cli_progress *progress)
{
    memset(stats, 0, sizeof *stats);
    stats->dim = src->dim;
    double *pts = cli_alloc(cmd, src->k * src->dim, sizeof *pts);
    if (pts == NULL)
        return CLI_EXIT_FAIL;
    mcs_rng rng;
    int rc = mcs_rng_seed(&rng, seed, 0u) == MCS_OK ? 0 : cli_internal(cmd, "mcs_rng_seed failed");
    for (uint64_t t = 0; rc == 0 && t < sets; ++t) {
        rc = cli_sample_draw(cmd, src, &rng, pts);
        if (rc == 0)
            rc = fn(ctx, src->k, pts, NULL);
        if (rc == 0) {
            stats->sets = t + 1u;
            stats->k_min = stats->k_max = src->k;
        }
        if (progress != NULL)
            cli_progress_update(progress, t + 1u);
    }
    free(pts);
    return rc;
}
