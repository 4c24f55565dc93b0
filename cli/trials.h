/* The trial loop of the mcspec command, shared by `pattern` and `variance`
 * (and by anything that splits a run into pieces: several streams in one
 * process, or one stream per MPI rank).
 *
 * Streams: stream s of a run with seed S is the PCG32 generator seeded with
 * mcs_rng_seed(initstate = S, initseq = s). A call draws its trials from
 * that generator, seeded afresh when the call starts, so the trials a call
 * draws are a function of (S, s, last - first) alone; `first` and `last`
 * place them in a larger run (progress counts them as trials first..last-1
 * of it). Splitting T trials over P streams is one call per stream, with
 * the shares and the merge order of streams.h. */
#ifndef MCSPEC_CLI_TRIALS_H
#define MCSPEC_CLI_TRIALS_H

#include <stddef.h>
#include <stdint.h>

#include "mcspec.h"
#include "progress.h"

/* Where each trial goes; any member may be NULL (not accumulated). */
typedef struct {
    mcs_spectrum *spectrum; /* S_k statistics (initialised for the pattern's N) */
    const double *f;        /* integrand f[N] for the estimator I (eq. 8) ... */
    mcs_welford *estimate;  /* ... whose values go here (both set, or neither) */
} cli_sinks;

/* Draws trials [first, last) of stream `stream` of pattern pat (initialised)
 * into sinks. Returns 0, or CLI_EXIT_FAIL after a message (a library call
 * failed; the sinks then hold the trials before the failing one). progress
 * may be NULL. */
int cli_run_trials(const char *cmd, const mcs_pattern *pat, uint64_t seed, uint64_t stream,
                   uint64_t first, uint64_t last, cli_sinks *sinks, cli_progress *progress);

#endif /* MCSPEC_CLI_TRIALS_H */
