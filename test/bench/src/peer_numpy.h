/* The numpy peer (peer_numpy.py) as a contender: a Python co-process started
 * once per run and driven over two pipes, one command per line. While it runs
 * a slice the C harness waits on the pipe, so the peer has the core to itself
 * exactly like a C contender during its slice, and its slices take their turn
 * in the same interleaved rounds. The peer times itself around whole batches
 * with the same kind of clock as the harness (its thread's CPU time unless
 * told otherwise), so pipe latency is not counted; a slice is at least one
 * batch, so at large N it can run longer than the C contenders' ~2 ms. */
#ifndef BENCH_PEER_NUMPY_H
#define BENCH_PEER_NUMPY_H

#include <stddef.h>
#include "harness.h"

/* Starts `python script`, timing by the wall clock if wall is non-zero, else
 * by the thread's CPU clock (as the harness). BENCH_OK, or BENCH_UNAVAILABLE
 * (no interpreter given, or it could not start or import numpy; the reason
 * goes to stderr). */
int bench_numpy_start(const char *python, const char *script, int wall);

/* Tells the co-process to quit and reaps it. */
void bench_numpy_stop(void);

/* "numpy X (Python Y, /path/to/python)", or "not available". */
const char *bench_numpy_describe(void);

/* The batch size the peer chose for the last prepared cell (0 if none). */
size_t bench_numpy_batch(void);

/* The numpy peer as a contender (unavailable if the co-process is not running). */
bench_contender bench_numpy_contender(void);

#endif /* BENCH_PEER_NUMPY_H */
