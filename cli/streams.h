/* The stream rule of mcspec (pattern --streams P / --stream I, mcspec-mpi):
 *
 * - stream i of a run with seed S draws from PCG32 seeded with
 *   mcs_rng_seed(initstate = S, initseq = i): P distinct sequences of one
 *   seed (stream 0 is the plain run of `mcspec pattern --seed S`);
 * - T trials are split over P streams as evenly as possible: stream i takes
 *   floor(T / P) trials, one more when i < T mod P, and its trials are trials
 *   first .. first + count - 1 of the run, first = i floor(T / P) + min(i, T mod P);
 * - the P accumulators are merged in the tree order of record.h.
 * So one process running P streams, P processes running one each (`--stream
 * I` then `mcspec merge`), and P MPI ranks all draw the same trials and merge
 * them the same way. */
#ifndef MCSPEC_CLI_STREAMS_H
#define MCSPEC_CLI_STREAMS_H

#include <stdint.h>

#include "mcspec.h"
#include "progress.h"

/* Stream i's share of T trials over P streams (P >= 1, i < P). */
void cli_stream_share(uint64_t trials, uint64_t streams, uint64_t i, uint64_t *first,
                      uint64_t *count);

/* Most streams a run may have (a merge tree of that many leaves has at most
 * 21 levels alive at once). No suffix: --help prints it (CLI_STR). */
#define CLI_MAX_STREAMS 1048576

/* A run to split over streams: the accumulator every stream fills (kind and
 * shape, as cli_acc_new), and how one stream draws trials [first, last) of
 * its PCG32 sequence (seed, stream) into such an accumulator (returns 0 or
 * an exit status after a message). */
typedef struct {
    mcs_io_kind kind;
    size_t shape[2];
    int (*run)(const char *cmd, const void *ctx, uint64_t seed, uint64_t stream, uint64_t first,
               uint64_t last, void *acc, cli_progress *progress);
    const void *ctx;
} cli_stream_job;

/* Draws a run of job into acc (an empty accumulator of job's kind and
 * shape): with only == streams, every stream of the P = streams, each into
 * its own accumulator, merged in the tree order; with only < streams, stream
 * `only` alone. trials >= streams. progress (may be NULL) counts the run's
 * trials. Returns 0 or an exit status after a message. */
int cli_run_job(const char *cmd, const cli_stream_job *job, uint64_t seed, uint64_t trials,
                uint64_t streams, uint64_t only, void *acc, cli_progress *progress);

/* cli_run_job for a 1D pattern into a spectrum initialised for pat's N. */
int cli_run_streams(const char *cmd, const mcs_pattern *pat, uint64_t seed, uint64_t trials,
                    uint64_t streams, uint64_t only, mcs_spectrum *acc, cli_progress *progress);

#endif /* MCSPEC_CLI_STREAMS_H */
