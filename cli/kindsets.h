/* Point sets of a named kind for the commands that otherwise read point
 * files (mcspec discrepancy KIND, mcspec stats KIND): sets drawn by the kind
 * table of mcspec sample (sample.h) and fed, one by one, to the callback the
 * file reader feeds, so a command treats drawn and read sets the same way. */
#ifndef MCSPEC_CLI_KINDSETS_H
#define MCSPEC_CLI_KINDSETS_H

#include <stddef.h>
#include <stdint.h>

#include "cli.h"
#include "input.h"
#include "progress.h"
#include "sample.h"

/* Whether the option --name of opts[nopts] was given (by name, so that
 * options added to a table do not move the checks). */
int cli_opt_given(const cli_opt *opts, size_t nopts, const char *name);

/* Whether name is one of the kinds of mcspec sample. */
int cli_kind_known(const char *name);

/* What cli_kind_or_file checks: the operand, --dim and --save as parsed. */
typedef struct {
    const char *path; /* the operand: a point file, '-', KIND, or NULL */
    size_t dim;       /* --dim (0: not given) */
    const char *save; /* --save FILE, or NULL */
} cli_kind_args;

/* The usage checks of a command that takes a point file or KIND --dim D --k
 * K [--sets T] [--seed S] (mcspec discrepancy, mcspec stats), after
 * cli_parse_one filled opts[nopts]: *kind_mode = whether --k was given; then
 * KIND needs --dim and no --wrap, and --save only in 1D or 2D (a pattern
 * provenance); a file takes no --sets or --seed, a KIND name that is not a
 * file needs --k, and no operand needs standard input not to be a
 * terminal. Returns 0, or exit 2 after one line. */
int cli_kind_or_file(const char *cmd, const cli_opt *opts, size_t nopts, const cli_kind_args *a,
                     int *kind_mode);

/* The first line of a report: cmd, then source (a drawn KIND's description)
 * or the input's name, the sets, their dimension and sizes. */
void cli_sets_line(const char *cmd, const char *source, const char *path,
                   const cli_pointset_stats *stats);

/* Draws sets sets of src (set up by cli_sample_init) from PCG32 seeded with
 * (seed, 0), as mcspec sample --seed does, into fn, filling stats as the
 * reader does (dim before the first call, lines 0). Returns 0, or an exit
 * status after a message (fn's own, or a failed draw). */
int cli_kind_feed(const char *cmd, const cli_sample_source *src, uint64_t sets, uint64_t seed,
                  cli_pointset_fn fn, void *ctx, cli_pointset_stats *stats, cli_progress *progress);

#endif /* MCSPEC_CLI_KINDSETS_H */
