/* The stream rule (see streams.h). */
#include "streams.h"
#include "cli.h"
#include "record.h"
#include "trials.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void cli_stream_share(uint64_t trials, uint64_t streams, uint64_t i, uint64_t *first,
                      uint64_t *count)
{
    const uint64_t base = trials / streams, extra = trials % streams;
    *count = base + (i < extra ? 1u : 0u);
    *first = i * base + (i < extra ? i : extra); /* <= trials: no overflow */
}

/* One stream's share of the run into acc. */
static int run_one(const char *cmd, const cli_stream_job *job, uint64_t seed, uint64_t trials,
                   uint64_t streams, uint64_t i, void *acc, cli_progress *progress)
{
    uint64_t first = 0u, count = 0u;
    cli_stream_share(trials, streams, i, &first, &count);
    return job->run(cmd, job->ctx, seed, i, first, first + count, acc, progress);
}

int cli_run_job(const char *cmd, const cli_stream_job *job, uint64_t seed, uint64_t trials,
                uint64_t streams, uint64_t only, void *acc, cli_progress *progress)
{
    if (only < streams)
        return run_one(cmd, job, seed, trials, streams, only, acc, progress);
    if (streams == 1u) /* a tree of one leaf is that leaf */
        return run_one(cmd, job, seed, trials, 1u, 0u, acc, progress);
    cli_merge_tree *tree = cli_alloc(cmd, 1, sizeof *tree);
    if (tree == NULL)
        return CLI_EXIT_FAIL;
    int rc = 0;
    for (uint64_t i = 0; rc == 0 && i < streams; ++i) {
        cli_acc leaf = {job->kind, NULL};
        char what[48];
        snprintf(what, sizeof what, "stream %llu", (unsigned long long)i);
        rc = cli_acc_new(cmd, job->kind, job->shape, &leaf);
        if (rc == 0)
            rc = run_one(cmd, job, seed, trials, streams, i, leaf.obj, progress);
        if (rc == 0)
            rc = cli_tree_push(cmd, tree, &leaf, what);
        cli_acc_free(&leaf);
    }
    cli_acc all = {job->kind, NULL};
    if (rc == 0)
        rc = cli_tree_finish(cmd, tree, &all);
    if (rc == 0)
        cli_acc_copy_to(&all, acc);
    cli_acc_free(&all);
    cli_tree_free(tree);
    free(tree);
    return rc;
}

/* A 1D pattern's trials into a spectrum: cli_stream_job's run. */
static int run_pattern(const char *cmd, const void *ctx, uint64_t seed, uint64_t stream,
                       uint64_t first, uint64_t last, void *acc, cli_progress *progress)
{
    cli_sinks sinks = {acc, NULL, NULL};
    return cli_run_trials(cmd, ctx, seed, stream, first, last, &sinks, progress);
}

int cli_run_streams(const char *cmd, const mcs_pattern *pat, uint64_t seed, uint64_t trials,
                    uint64_t streams, uint64_t only, mcs_spectrum *acc, cli_progress *progress)
{
    const cli_stream_job job = {MCS_IO_KIND_SPECTRUM, {pat->n, 0u}, run_pattern, pat};
    return cli_run_job(cmd, &job, seed, trials, streams, only, acc, progress);
}
