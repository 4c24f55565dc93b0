/* Progress on stderr for long runs: only when stderr is a terminal, never in
 * CSV mode (the caller decides), and only once a run has taken more than a
 * second (MCSPEC_PROGRESS_DELAY in the environment sets another delay in
 * seconds), so quick runs print nothing at all. With a known total the line
 * gives the share done, the time taken and an estimate of the time left (at
 * the rate so far). */
#ifndef MCSPEC_CLI_PROGRESS_H
#define MCSPEC_CLI_PROGRESS_H

#include <stdint.h>

typedef struct {
    int enabled;        /* 0: every call is a no-op */
    const char *label;  /* "mcspec pattern random" */
    const char *unit;   /* "trials", "sets" */
    uint64_t total;     /* 0 when unknown (reading a file) */
    uint64_t from;      /* the count the run starts at (its units before it are not its own) */
    double start;       /* monotonic seconds at init */
    double delay;       /* seconds before the first line */
    double last;        /* time of the last line printed */
    int shown;          /* a line is on the terminal and must be cleared */
} cli_progress;

/* Enabled when want is non-zero and stderr is a terminal. */
void cli_progress_init(cli_progress *pr, int want, const char *label, const char *unit,
                       uint64_t total);
/* The run counts units from..total-1 of a larger one (a --stream share):
 * the line gives its own share, and the estimate its own rate. */
void cli_progress_span(cli_progress *pr, uint64_t from, uint64_t total);
/* Reports done units (cheap when nothing is due: call it per trial). */
void cli_progress_update(cli_progress *pr, uint64_t done);
/* Clears the progress line, if one was printed. */
void cli_progress_end(cli_progress *pr);

#endif /* MCSPEC_CLI_PROGRESS_H */
