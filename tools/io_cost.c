/* The per-level cost of a reduction of spectra (docs/scaling.md), measured:
 * for each N, the record size and the time to save a spectrum, load it, and
 * merge it into another (one level of a tree of merges is one of each, plus
 * the transfer of the record). Best of ROUNDS rounds of about
 * MEASURE_SECONDS each: other processes only ever slow a round down.
 * Usage: io_cost [N ...] (default 64 256 1024 4096, each <= MCS_MAX_N). */
#define _POSIX_C_SOURCE 199309L

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "mcspec.h"

#define MEASURE_SECONDS 0.05
#define ROUNDS 5

static mcs_spectrum a, b, c;
static unsigned char rec[64u + 40u * (MCS_MAX_N / 2u + 1u)];

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef enum { OP_SAVE, OP_LOAD, OP_MERGE } op_kind;

static int run_op(op_kind op, size_t len)
{
    size_t out = 0u;
    switch (op) {
    case OP_SAVE: return mcs_io_save_spectrum(&a, sizeof rec, rec, &out) != MCS_OK;
    case OP_LOAD: return mcs_io_load_spectrum(&c, len, rec) != MCS_OK;
    default: return mcs_spectrum_merge(&b, &a) != MCS_OK;
    }
}

/* Seconds per call of op, best of ROUNDS. */
static double time_op(op_kind op, size_t len)
{
    double best = 1e30;
    for (int r = 0; r < ROUNDS; ++r) {
        unsigned long reps = 0ul;
        const double t0 = now();
        double t1 = t0;
        while (t1 - t0 < MEASURE_SECONDS) {
            for (int i = 0; i < 16; ++i)
                if (run_op(op, len) != 0)
                    return -1.0;
            reps += 16ul;
            t1 = now();
        }
        const double per = (t1 - t0) / (double)reps;
        best = per < best ? per : best;
    }
    return best;
}

/* Two spectra of 200 stratified trials each (K = 8) at N. */
static int fill(size_t n)
{
    mcs_pattern pat;
    mcs_rng rng;
    size_t bins[8];
    double w[8];
    if (mcs_pattern_init(&pat, MCS_PATTERN_STRATIFIED, n, 8u, NULL) != MCS_OK ||
        mcs_rng_seed(&rng, 1u, 0u) != MCS_OK || mcs_spectrum_init(&a, n) != MCS_OK ||
        mcs_spectrum_init(&b, n) != MCS_OK)
        return 1;
    for (int t = 0; t < 400; ++t) {
        if (mcs_pattern_draw(&pat, &rng, 8u, bins, w, NULL) != MCS_OK ||
            mcs_spectrum_add_bins(t % 2 ? &a : &b, 8u, bins, w) != MCS_OK)
            return 1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    static const size_t defaults[] = {64u, 256u, 1024u, 4096u};
    const int count = argc > 1 ? argc - 1 : (int)(sizeof defaults / sizeof defaults[0]);
    printf("%6s %10s %10s %10s %10s %12s\n", "N", "bytes", "save_us", "load_us", "merge_us",
           "level_us");
    for (int i = 0; i < count; ++i) {
        const size_t n = argc > 1 ? (size_t)strtoul(argv[i + 1], NULL, 10) : defaults[i];
        size_t len = 0u;
        if (n == 0u || n > MCS_MAX_N || fill(n) != 0 ||
            mcs_io_save_spectrum(&a, sizeof rec, rec, &len) != MCS_OK) {
            fprintf(stderr, "io_cost: N = %zu is not a spectrum this build holds\n", n);
            return 2;
        }
        const double ts = time_op(OP_SAVE, len), tl = time_op(OP_LOAD, len);
        const double tm = time_op(OP_MERGE, len);
        if (ts < 0.0 || tl < 0.0 || tm < 0.0) {
            fprintf(stderr, "io_cost: a library call failed at N = %zu\n", n);
            return 1;
        }
        printf("%6zu %10zu %10.2f %10.2f %10.2f %12.2f\n", n, len, ts * 1e6, tl * 1e6, tm * 1e6,
               (ts + tl + tm) * 1e6);
    }
    return 0;
}
