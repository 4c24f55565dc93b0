/* mcspec merge: several saved accumulators into one. */
#include "atomic.h"
#include "cli.h"
#include "record.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CMD "mcspec merge"
#define MAX_INPUTS 65536u

static const char help[] =
    "usage: mcspec merge FILE... -o OUT\n"
    "\n"
    "Merges the accumulators saved in the FILEs (by --save of mcspec spectrum or\n"
    "pattern, or by mcspec-mpi) into one and writes it to OUT: the same\n"
    "statistics as one run over all their trials (Chan et al.'s merge of means\n"
    "and sums of squared deviations). Every FILE must hold the same kind of\n"
    "record with the same N; a file that is not a valid record (truncated,\n"
    "corrupted, another kind or N) stops the merge with a message naming it,\n"
    "and OUT is not written.\n"
    "\n"
    "The files are merged in the tree order (FILE 1 + FILE 2), (FILE 3 + FILE 4),\n"
    "((1 + 2) + (3 + 4)), ..., the order mcspec-mpi reduces its ranks in: the P\n"
    "files of `mcspec pattern ... --streams P --stream I --save FILE_I`, given in\n"
    "the order I = 0..P-1, merge to the bytes `mcspec pattern ... --streams P\n"
    "--save FILE` writes. Merging records of different patterns, K or importance\n"
    "functions is allowed by the format (it only knows N) but mixes two\n"
    "distributions: keep one run's files together.\n"
    "\n"
    "Options:\n"
    "  -o, --output OUT   the merged record (required); written atomically: a\n"
    "                     temporary file beside OUT, flushed, then renamed (so OUT\n"
    "                     must be a regular file or a new name)\n"
    "  --help             this text\n"
    "\n"
    "Prints one line: the kind, N, trials and inputs of the merged record.\n"
    "Exit status: 0 on success, 2 on bad usage or input (one line on stderr).\n";

/* -o OUT is --output OUT: rewrite it before the shared parser sees it. */
static void alias_short_output(int argc, char **argv)
{
    static char output[] = "--output";
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--") == 0)
            break;
        if (strcmp(argv[i], "-o") == 0)
            argv[i] = output;
    }
}

/* Reads every input, checks they agree, and pushes them through the tree. */
static int merge_all(const char **files, size_t nfiles, cli_acc *out)
{
    cli_merge_tree *tree = cli_alloc(CMD, 1, sizeof *tree);
    if (tree == NULL)
        return CLI_EXIT_FAIL;
    memset(tree, 0, sizeof *tree);
    /* The first file, reloaded as a reference for the shape checks. */
    cli_acc first = {MCS_IO_KIND_SPECTRUM, NULL};
    int rc = cli_acc_read(CMD, files[0], &first);
    for (size_t i = 0; rc == 0 && i < nfiles; ++i) {
        cli_acc acc = {MCS_IO_KIND_SPECTRUM, NULL};
        char da[96], db[96];
        rc = cli_acc_read(CMD, files[i], &acc);
        if (rc == 0 && !cli_acc_same(&first, &acc)) {
            rc = cli_fail(CMD, "%s holds %s, %s %s: cannot merge", files[i],
                          cli_acc_describe(&acc, da, sizeof da), files[0],
                          cli_acc_describe(&first, db, sizeof db));
            cli_acc_free(&acc);
        }
        if (rc == 0)
            rc = cli_tree_push(CMD, tree, &acc, files[i]);
    }
    if (rc == 0)
        rc = cli_tree_finish(CMD, tree, out);
    cli_acc_free(&first);
    cli_tree_free(tree);
    free(tree);
    return rc;
}

int cli_cmd_merge(int argc, char **argv)
{
    const char *output = NULL;
    cli_opt opts[] = {{"output", CLI_OPT_STRING, &output, 0, 0, 0}};
    const char **files = cli_alloc(CMD, MAX_INPUTS, sizeof *files);
    if (files == NULL)
        return CLI_EXIT_FAIL;
    alias_short_output(argc, argv);
    cli_parser p = {CMD, help, opts, 1, files, MAX_INPUTS, 0, NULL};
    int rc = cli_parse(&p, argc, argv);
    if (rc != CLI_PARSED) {
        free(files);
        return rc == CLI_HELP ? CLI_EXIT_OK : rc;
    }
    if (output == NULL)
        rc = cli_fail(CMD, "where to? give -o OUT (see %s --help)", CMD);
    else if (p.nargs == 0u)
        rc = cli_fail(CMD, "which records? give one or more FILEs");
    if (rc == 0)
        rc = cli_write_check(CMD, output);
    cli_acc merged = {MCS_IO_KIND_SPECTRUM, NULL};
    if (rc == 0)
        rc = merge_all(files, p.nargs, &merged);
    if (rc == 0)
        rc = cli_acc_write(CMD, output, &merged);
    char what[96];
    if (rc == 0)
        printf("%s: %s, %llu trials from %zu file%s\n", output,
               cli_acc_describe(&merged, what, sizeof what),
               (unsigned long long)cli_acc_count(&merged), p.nargs, p.nargs == 1u ? "" : "s");
    cli_acc_free(&merged);
    free(files);
    return rc;
}
