/* Timing harness of the bench: contenders, interleaved rounds, medians, and
 * the description of the machine a run happened on.
 *
 * A cell (one N, K and pattern) is measured by giving every contender a short
 * slice of time (~2 ms) in turn, round after round; the starting contender
 * rotates each round so that none always runs first or after the same one.
 * Slowdowns from other processes hit the contenders alike, and the median
 * over rounds discards the slices they spoiled; by default a slice is timed
 * with the thread's CPU clock, so preemption is not counted at all. Ratios are medians of
 * per-round ratios, so each compares slices that ran next to each other. */
#ifndef BENCH_HARNESS_H
#define BENCH_HARNESS_H

#include <stddef.h>
#include <stdint.h>

#define BENCH_MAX_ROUNDS 64
#define BENCH_MAX_CONTENDERS 16

/* Return codes of contender callbacks. */
#define BENCH_OK 0
#define BENCH_UNAVAILABLE 1 /* peer not built or not installed: reported, not an error */
#define BENCH_FAILED (-1)

/* What is measured: pattern kind is an mcs_pattern_kind value. */
typedef struct {
    size_t n;
    size_t k;
    int kind;
    uint64_t seed;
} bench_cell;

/* One timed slice: trials done in seconds. */
typedef struct {
    double trials;
    double seconds;
} bench_slice;

/* A contender. C contenders give run(), timed by the harness; a contender that
 * times itself (the numpy co-process) gives slice() instead. */
typedef struct {
    const char *name;
    void *ctx;
    size_t trials_per_call; /* 1, or the batch of a batched loop */
    int (*prepare)(void *ctx, const bench_cell *cell);
    int (*run)(void *ctx, size_t calls);
    int (*slice)(void *ctx, double seconds, bench_slice *out);
    /* Optional: a read-out (e.g. <|S_1|^2> and its standard error) used to
     * check that contenders compute the same quantity. */
    int (*readout)(void *ctx, size_t freq, double *value, double *stderr_out);
    double pace; /* harness-owned: fastest seconds per call seen in this cell */
    /* Optional (0 = 1): calls over which the contender's cost repeats. A
     * spectrum accumulator on the PAIR path pays a batch close every batch
     * (2.5 ms at N = 4093), longer than a slice: a slice then holds at least
     * BENCH_PERIODS periods, so each slice's rate counts its closes in
     * proportion instead of some slices missing them and others holding one. */
    size_t period;
} bench_contender;

#define BENCH_PERIODS 4u

/* Trials/s of every contender in every round of one cell. */
typedef struct {
    size_t count;
    size_t rounds;
    int available[BENCH_MAX_CONTENDERS];
    double rate[BENCH_MAX_CONTENDERS][BENCH_MAX_ROUNDS];
} bench_run;

/* Monotonic wall-clock seconds. */
double bench_now(void);

/* Slices are timed by the calling thread's CPU clock (CLOCK_THREAD_CPUTIME_ID)
 * unless wall is non-zero: on a shared machine a slice then does not count
 * the time another process held the core. A contender that times itself
 * (the numpy peer) is told which clock to use through its own interface. */
void bench_use_wall_clock(int wall);

/* Prepares every contender for cell, then runs `rounds` interleaved rounds of
 * slices of `seconds` each. BENCH_FAILED if a contender fails. */
int bench_interleave(bench_contender *list, size_t count, const bench_cell *cell,
                     size_t rounds, double seconds, bench_run *out);

/* Median trials/s of contender c (NAN if unavailable). */
double bench_median_rate(const bench_run *run, size_t c);

/* Median over rounds of rate[a] / rate[b] (NAN if either is unavailable). */
double bench_median_ratio(const bench_run *run, size_t a, size_t b);

/* Interquartile range over median of contender c's rates: the noise of a cell. */
double bench_spread(const bench_run *run, size_t c);

/* Median of x[0..count) (sorts a copy; count <= BENCH_MAX_ROUNDS). */
double bench_median(const double *x, size_t count);

/* Prints the machine: CPU model, online CPUs, the compiler (its command, the
 * first line of its --version) and flags, and the load average. */
void bench_print_machine(const char *compiler_cmd, const char *compiler_version,
                         const char *flags);

/* Prints the load averages of /proc/loadavg after `label`. */
void bench_print_load(const char *label);

#endif /* BENCH_HARNESS_H */
