/* The mcspec command: shared pieces every subcommand uses.
 *
 * One file per subcommand (cmd_<name>.c) with its entry point below; option
 * parsing, messages and exit codes here (options.c); input readers
 * (input.h), the spectrum table / CSV and its rows (output.h), predictions
 * (predict.h), the trial loop and progress (trials.h) and gnuplot figures
 * (plot.h) each in their own file. The command is an ordinary hosted
 * program: unlike the library it may allocate and print. */
#ifndef MCSPEC_CLI_H
#define MCSPEC_CLI_H

#include <stddef.h>
#include <stdint.h>

/* Exit statuses: success, bad usage or input (one line on stderr says what
 * to fix), and an internal failure (a library call failed where it cannot,
 * out of memory). */
enum { CLI_EXIT_OK = 0, CLI_EXIT_FAIL = 1, CLI_EXIT_USAGE = 2 };

/* A macro's value as a string literal (for --help texts that quote a
 * capacity such as MCS_MAX_N, which a build may override). */
#define CLI_STR_(x) #x
#define CLI_STR(x) CLI_STR_(x)

/* Largest K (samples per trial) the pattern subcommands take: the per-trial
 * arrays are 16 bytes a sample. No suffix: --help prints it (CLI_STR). */
#define CLI_MAX_K 1048576

/* A subcommand: name, one-line summary for `mcspec --help`, entry point
 * (argv[0] is the subcommand's name). */
typedef struct {
    const char *name;
    const char *summary;
    int (*run)(int argc, char **argv);
} cli_command;

int cli_cmd_spectrum(int argc, char **argv);
int cli_cmd_pattern(int argc, char **argv);
int cli_cmd_variance(int argc, char **argv);
int cli_cmd_merge(int argc, char **argv);
int cli_cmd_show(int argc, char **argv);
int cli_cmd_discrepancy(int argc, char **argv);
int cli_cmd_stats(int argc, char **argv);
int cli_cmd_integrate(int argc, char **argv);
int cli_cmd_pcf(int argc, char **argv);
int cli_cmd_version(int argc, char **argv);
int cli_cmd_sample(int argc, char **argv);
int cli_cmd_projections(int argc, char **argv);

/* Prints "cmd: message" as one line on stderr; returns CLI_EXIT_USAGE. */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
int cli_fail(const char *cmd, const char *fmt, ...);

/* As cli_fail, for failures that are not the user's (returns CLI_EXIT_FAIL). */
#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
int cli_internal(const char *cmd, const char *fmt, ...);

/* malloc that reports failure through cli_internal; NULL on failure. */
void *cli_alloc(const char *cmd, size_t count, size_t size);

/* Grows *buf (realloc) to at least need bytes, *bytes its size; k names the
 * set in the message. Returns 0, or CLI_EXIT_FAIL after a message (*buf and
 * *bytes as they were). */
int cli_grow(const char *cmd, void **buf, size_t *bytes, size_t need, size_t k);

/* ---- Options ------------------------------------------------------------- */

typedef enum {
    CLI_OPT_FLAG,   /* --name: *(int *)value = 1 */
    CLI_OPT_SIZE,   /* --name N: *(size_t *)value, whole number in [min, max] */
    CLI_OPT_U64,    /* --name N: *(uint64_t *)value, whole number in [min, max] */
    CLI_OPT_STRING  /* --name TEXT: *(const char **)value */
} cli_opt_type;

typedef struct {
    const char *name;  /* without the leading "--" */
    cli_opt_type type;
    void *value;       /* where the parsed value goes (holds the default on entry) */
    uint64_t min, max; /* bounds of a number */
    int given;         /* set to 1 by the parser when the option appears */
} cli_opt;

/* One subcommand's command line: its options, and up to max_args positional
 * arguments ("-" is one; "--" ends the options). */
typedef struct {
    const char *cmd;   /* "mcspec pattern": prefix of every message */
    const char *help;  /* printed to stdout by --help (or -h) */
    cli_opt *opts;
    size_t nopts;
    const char **args; /* positional arguments, caller array of max_args */
    size_t max_args;
    size_t nargs;      /* set by the parser */
    const char *help_more; /* printed after help, or NULL (C11 caps one literal at 4095) */
} cli_parser;

enum { CLI_PARSED = 0, CLI_HELP = -1, CLI_BAD = CLI_EXIT_USAGE };

/* Parses argv[1..argc-1] (--opt V and --opt=V both work). CLI_PARSED (0);
 * CLI_HELP (-1) after printing the help; CLI_BAD (CLI_EXIT_USAGE) after one
 * line on stderr. So a subcommand's parse returns what cli_parse did unless
 * it is 0, and its entry point exits CLI_EXIT_OK after --help. */
int cli_parse(cli_parser *p, int argc, char **argv);

/* cli_parse for a subcommand of at most one positional argument, which goes
 * to *arg (NULL when there is none); help_more may be NULL. */
int cli_parse_one(const char *cmd, const char *help, const char *help_more, cli_opt *opts,
                  size_t nopts, int argc, char **argv, const char **arg);

#define CLI_COUNT(array) (sizeof(array) / sizeof((array)[0]))

/* The library's pattern kind named text (mcs_pattern_kind_str), or -1. */
int cli_pattern_kind(const char *text);

/* Whole number in [min, max] from text (digits only). 0 or -1. */
int cli_parse_u64(const char *text, uint64_t min, uint64_t max, uint64_t *out);

/* ---- Output conventions shared by every subcommand ------------------------ */

/* A double for CSV: "%.17g" (round-trips), or empty when NaN (no value). */
void cli_csv_double(char *buf, size_t size, double x);
/* A double for a table column of width w: "%*.6g", or "-" when NaN. */
void cli_table_double(char *buf, size_t size, int width, double x);

/* (measured - predicted) / max(stderr, floor): a value that is deterministic
 * (stderr 0) and agrees to rounding gets z = 0, not 0/0. NaN if any input is
 * NaN. floor is the rounding scale below which a difference is zero. */
double cli_z(double measured, double predicted, double stderr_, double floor);

#endif /* MCSPEC_CLI_H */
