/* mcspec: the command line of the mcspec library. One subcommand per file
 * (cmd_<name>.c); this file only dispatches. */
#include "cli.h"

#include <signal.h>
#include <stdio.h>
#include <string.h>

#define CMD "mcspec"

/* Add a subcommand here and in cli.h; its --help documents it. */
static const cli_command commands[] = {
    {"spectrum", "spectrum of point sets read from a file (one set per trial)", cli_cmd_spectrum},
    {"pattern", "measured spectrum of a named pattern beside exact theory and the note",
     cli_cmd_pattern},
    {"variance", "Var[I] of an integrand given as N values, measured beside exact, per kind",
     cli_cmd_variance},
    {"merge", "merge accumulators saved by --save into one file", cli_cmd_merge},
    {"show", "print a saved accumulator as a table, CSV or plot", cli_cmd_show},
    {"discrepancy", "L2 and star discrepancies of point sets read from a file",
     cli_cmd_discrepancy},
    {"stats", "minimum and average minimum distances of point sets read from a file",
     cli_cmd_stats},
    {"sample", "point sets of a named pattern or sampler in any dimension, to stdout",
     cli_cmd_sample},
    {"projections", "every 2D projection of a d-dimensional sampler or point file, flagged",
     cli_cmd_projections},
    {"integrate", "integration error on integrand families, measured, exact and predicted",
     cli_cmd_integrate},
    {"pcf", "pair correlation (kernel PCF or psa's RDF) of point sets or a 2D pattern",
     cli_cmd_pcf},
    {"version", "print the library's version (also: mcspec --version)", cli_cmd_version},
};

#define COMMAND_COUNT (sizeof commands / sizeof commands[0])

static void usage(FILE *fp)
{
    fputs("usage: mcspec COMMAND [OPTIONS] [ARGS]\n"
          "       mcspec COMMAND --help\n"
          "       mcspec --version\n"
          "\n"
          "Fourier analysis of Monte Carlo sampling patterns (Ramamoorthi, \"Some Notes\n"
          "on Sampling\"; equation numbers refer to it). Commands:\n",
          fp);
    for (size_t i = 0; i < COMMAND_COUNT; ++i)
        fprintf(fp, "  %-12s %s\n", commands[i].name, commands[i].summary);
    fputs("\n"
          "Every command prints an aligned table, or with --csv only CSV (a header line\n"
          "and rows). Long runs show progress on stderr when it is a terminal (the share\n"
          "done and an estimate of the time left), never with --csv: the first line\n"
          "after 1 s, or after MCSPEC_PROGRESS_DELAY seconds if that is set in the\n"
          "environment. Exit status: 0 on success, 2 on bad usage or input (one line on\n"
          "stderr says what to fix), 1 on an internal failure.\n",
          fp);
}

/* Exit status of a command whose stdout could not be written (a full disk,
 * a closed pipe) is a failure, not a success with a truncated table. */
static int finish(int rc)
{
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "%s: cannot write the output\n", CMD);
        return rc != CLI_EXIT_OK ? rc : CLI_EXIT_FAIL;
    }
    return rc;
}

/* "spectrum, pattern, variance" from the table, for one-line messages. */
static void command_names(char *buf, size_t size)
{
    size_t used = 0;
    buf[0] = '\0';
    for (size_t i = 0; i < COMMAND_COUNT && used < size; ++i) {
        int w = snprintf(buf + used, size - used, "%s%s", i > 0u ? ", " : "", commands[i].name);
        used += w > 0 ? (size_t)w : 0u;
    }
}

int main(int argc, char **argv)
{
    /* A file-size limit (ulimit -f) would kill the command by SIGXFSZ in the
     * middle of a write, leaving a FILE.partXXXXXX behind; ignored, the write
     * fails with EFBIG, which the writers report and clean up after. */
    signal(SIGXFSZ, SIG_IGN);
    char names[256];
    command_names(names, sizeof names);
    if (argc < 2) {
        fprintf(stderr, "%s: which command? one of %s (see %s --help)\n", CMD, names, CMD);
        return CLI_EXIT_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
        strcmp(argv[1], "help") == 0) {
        usage(stdout);
        return finish(CLI_EXIT_OK);
    }
    if (strcmp(argv[1], "--version") == 0)
        return finish(cli_cmd_version(argc - 1, argv + 1));
    for (size_t i = 0; i < COMMAND_COUNT; ++i)
        if (strcmp(argv[1], commands[i].name) == 0)
            return finish(commands[i].run(argc - 1, argv + 1));
    fprintf(stderr, "%s: unknown command '%s' (one of %s; see %s --help)\n", CMD, argv[1],
            names, CMD);
    return CLI_EXIT_USAGE;
}
