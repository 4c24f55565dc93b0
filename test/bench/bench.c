/* mcspec speed bench (make bench): mcspec against what its users would pick
 * instead, from one interleaved run on this machine.
 *
 *   spectra  draw + add per trial: mcspec AUTO and each forced path, the FFTW
 *            peer and the numpy peer, N x K x {stratified, random}, trials/s,
 *            ratios and the targets; reference figures (draw, bare
 *            DFT, autocorr) from the same rounds
 *   moment   mcs_moment_add_bins against three plain C loops (same sums)
 *   draw     mcs_pattern_draw against a bare PCG32 bounded draw per sample
 *
 * Options: --quick (a subset, fewer rounds), --wall-clock (time slices by the
 * wall clock instead of the thread's CPU clock), --rounds R, --slice-ms T,
 * --cell N,K (that cell of the grid only, both patterns), --python PATH (an
 * interpreter that imports numpy), --numpy-peer SCRIPT.
 * Timing: test/bench/src/harness.h; peers: peer_fftw.h, peer_numpy.h. */

#if defined(__linux__)
#define _GNU_SOURCE /* sched_getcpu, sched_setaffinity */
#include <sched.h>
#endif
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contenders.h"
#include "floors.h"
#include "harness.h"
#include "mcspec.h"
#include "pcg32_ref.h"
#include "peer_fftw.h"
#include "peer_numpy.h"
#include "report.h"

#ifndef BENCH_CC
#define BENCH_CC "cc"
#endif
#ifndef BENCH_CC_VERSION
#define BENCH_CC_VERSION "unknown version"
#endif
#ifndef BENCH_FLAGS
#define BENCH_FLAGS "unknown"
#endif

#define GRID_MAX_CELLS 64u

typedef struct {
    int quick;
    int wall;
    size_t rounds;
    double slice_seconds;
    const char *python;
    const char *numpy_script;
    size_t only_n, only_k; /* --cell N,K: that cell of the grid only (0: all) */
} bench_options;

static int parse_options(int argc, char **argv, bench_options *opt)
{
    opt->quick = 0;
    opt->wall = 0;
    opt->rounds = 0u;
    opt->slice_seconds = 2e-3;
    opt->python = NULL;
    opt->numpy_script = "test/bench/src/peer_numpy.py";
    opt->only_n = 0u;
    opt->only_k = 0u;
    for (int i = 1; i < argc; ++i) {
        const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(a, "--quick") == 0) {
            opt->quick = 1;
        } else if (strcmp(a, "--wall-clock") == 0) {
            opt->wall = 1;
        } else if (strcmp(a, "--rounds") == 0 && v != NULL) {
            opt->rounds = (size_t)strtoul(v, NULL, 10);
            ++i;
        } else if (strcmp(a, "--slice-ms") == 0 && v != NULL) {
            opt->slice_seconds = 1e-3 * strtod(v, NULL);
            ++i;
        } else if (strcmp(a, "--python") == 0 && v != NULL) {
            opt->python = v;
            ++i;
        } else if (strcmp(a, "--cell") == 0 && v != NULL &&
                   sscanf(v, "%zu,%zu", &opt->only_n, &opt->only_k) == 2) {
            ++i;
        } else if (strcmp(a, "--numpy-peer") == 0 && v != NULL) {
            opt->numpy_script = v;
            ++i;
        } else {
            fprintf(stderr, "usage: %s [--quick] [--wall-clock] [--rounds R] [--slice-ms T] "
                            "[--cell N,K] [--python PATH] [--numpy-peer SCRIPT]\n", argv[0]);
            return 1;
        }
    }
    if (opt->rounds == 0u)
        opt->rounds = opt->quick ? 7u : 31u;
    if (opt->rounds > BENCH_MAX_ROUNDS || !(opt->slice_seconds > 0.0)) {
        fprintf(stderr, "bench: rounds must be 1..%d, the slice positive\n", BENCH_MAX_ROUNDS);
        return 1;
    }
    if (opt->only_n != 0u && (opt->only_n > (size_t)MCS_MAX_N || opt->only_k == 0u ||
                              opt->only_k > 256u)) {
        fprintf(stderr, "bench: --cell N,K needs N in 1..%d and K in 1..256\n", MCS_MAX_N);
        return 1;
    }
    return 0;
}

/* The reference demo's first outputs for pcg32_srandom_r(42, 54): the bench's
 * copy of PCG32 must be the reference generator. */
static int pcg32_copy_is_reference(void)
{
    static const uint32_t expect[6] = {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u,
                                       0x83d2f293u, 0xbfa4784bu, 0xcbed606eu};
    pcg32_random_t rng;
    pcg32_srandom_r(&rng, 42u, 54u);
    for (size_t i = 0; i < 6u; ++i)
        if (pcg32_random_r(&rng) != expect[i])
            return 0;
    return 1;
}

static uint64_t cell_seed(size_t n, size_t k, int kind)
{
    return 1000003u * (uint64_t)n + 1009u * (uint64_t)k + (uint64_t)kind + 1u;
}

/* Largest |z| between a contender's <|S_1|^2> and AUTO's (contender 0). The
 * small absolute term, rounding on the scale of the spectrum (K^2/N, the
 * power at k = 0), keeps a deterministic spectrum (stratified with N | K:
 * zero variance, <|S_1|^2> = 0 to rounding) from dividing rounding by zero. */
static double zmax_against_auto(const bench_contender *list, size_t count, const bench_run *run,
                                const bench_cell *cell)
{
    const double scale = (double)cell->k * (double)cell->k / (double)cell->n;
    double p0, s0, worst = 0.0;
    if (list[0].readout(list[0].ctx, 1u, &p0, &s0) != BENCH_OK)
        return (double)NAN;
    for (size_t c = 1; c < count; ++c) {
        double p, s;
        if (!run->available[c] || list[c].readout == NULL)
            continue;
        if (list[c].readout(list[c].ctx, 1u, &p, &s) != BENCH_OK)
            return (double)NAN;
        double z = fabs(p - p0) / (sqrt(s * s + s0 * s0) + 1e-9 * fabs(p0) + 1e-12 * scale);
        worst = z > worst ? z : worst;
    }
    return worst;
}

static size_t grid_contenders(bench_contender *list, bench_grid_layout *lay)
{
    size_t c = bench_spectrum_contenders(list);
    lay->paths = c;
    lay->fftw = c;
    list[c++] = bench_fftw_contender();
    lay->numpy = c;
    list[c++] = bench_numpy_contender();
    lay->draw = c;
    lay->dft = c + 1u;
    lay->autocorr = c + 2u;
    c += bench_reference_contenders(list + c);
    lay->count = c;
    return c;
}

static int run_grid(const bench_options *opt, bench_tally *tally)
{
    static const size_t ns_full[] = {64u, 256u, 1024u, 4096u, 4093u};
    static const size_t ks_full[] = {4u, 8u, 16u, 64u, 256u};
    static const size_t ns_quick[] = {64u, 1024u, 4093u};
    static const size_t ks_quick[] = {8u, 64u};
    static const int kinds[] = {MCS_PATTERN_STRATIFIED, MCS_PATTERN_RANDOM};
    static bench_grid_result results[GRID_MAX_CELLS];
    const size_t *ns = opt->quick ? ns_quick : ns_full, *ks = opt->quick ? ks_quick : ks_full;
    size_t n_count = opt->quick ? 3u : 5u, k_count = opt->quick ? 2u : 5u;
    if (opt->only_n != 0u) {
        ns = &opt->only_n;
        ks = &opt->only_k;
        n_count = k_count = 1u;
    }
    bench_contender list[BENCH_MAX_CONTENDERS];
    bench_grid_layout lay;
    size_t count = grid_contenders(list, &lay), cells = 0u;
    report_grid_legend(list, &lay);
    for (size_t ik = 0; ik < 2u; ++ik)
        for (size_t in = 0; in < n_count; ++in)
            for (size_t iK = 0; iK < k_count; ++iK) {
                bench_grid_result *res = &results[cells++];
                bench_cell cell = {ns[in], ks[iK], kinds[ik], cell_seed(ns[in], ks[iK], kinds[ik])};
                res->cell = cell;
                if (bench_interleave(list, count, &cell, opt->rounds, opt->slice_seconds,
                                     &res->run) != BENCH_OK)
                    return 1;
                res->zmax = zmax_against_auto(list, count, &res->run, &cell);
                res->numpy_batch = res->run.available[lay.numpy] ? bench_numpy_batch() : 0u;
                report_grid_row(res, list, &lay, tally);
            }
    report_reference_table(results, cells, &lay);
    return 0;
}

/* One pass over the pool from empty sums by every contender; the largest
 * difference of a sum (mean times the pool's trial count) from mcs_moment's. */
static double moment_sum_diff(bench_contender *list, size_t count, const bench_cell *cell)
{
    const size_t n = cell->n;
    double worst = 0.0;
    for (size_t c = 0; c < count; ++c)
        if (list[c].prepare(list[c].ctx, cell) != BENCH_OK ||
            list[c].run(list[c].ctx, BENCH_POOL_TRIALS / list[c].trials_per_call) != BENCH_OK)
            return (double)NAN;
    for (size_t i = 0; i < n * n + n; ++i) {
        if (i < n * n && i / n > i % n)
            continue; /* the floors keep the upper triangle only */
        double v0, v, se;
        if (list[0].readout(list[0].ctx, i, &v0, &se) != BENCH_OK)
            return (double)NAN;
        for (size_t c = 1; c < count; ++c) {
            if (list[c].readout(list[c].ctx, i, &v, &se) != BENCH_OK)
                return (double)NAN;
            double d = fabs(v - v0) * (double)BENCH_POOL_TRIALS;
            worst = d > worst ? d : worst;
        }
    }
    return worst;
}

static int run_moment(const bench_options *opt, bench_tally *tally)
{
    static const size_t ks[] = {8u, 64u};
    static const int kinds[] = {MCS_PATTERN_STRATIFIED, MCS_PATTERN_RANDOM};
    static bench_pool pool;
    static bench_run run;
    bench_contender list[4];
    list[0] = bench_moment_contender(&pool);
    size_t count = 1u + bench_moment_floors(list + 1, &pool);
    report_moment_header(list, count);
    for (size_t ik = 0; ik < 2u; ++ik)
        for (size_t iK = 0; iK < 2u; ++iK) {
            bench_cell cell = {64u, ks[iK], kinds[ik], cell_seed(64u, ks[iK], kinds[ik])};
            if (bench_pool_fill(&pool, &cell) != BENCH_OK)
                return 1;
            double diff = moment_sum_diff(list, count, &cell);
            if (bench_interleave(list, count, &cell, opt->rounds, opt->slice_seconds, &run) !=
                BENCH_OK)
                return 1;
            report_moment_row(&cell, &run, list, diff, tally);
        }
    return 0;
}

static int run_draw(const bench_options *opt, bench_tally *tally)
{
    static const size_t ns[] = {64u, 4096u};
    static const size_t ks[] = {8u, 64u};
    static const int kinds[] = {MCS_PATTERN_STRATIFIED, MCS_PATTERN_RANDOM};
    static bench_run run;
    bench_contender refs[3], list[2];
    (void)bench_reference_contenders(refs);
    list[0] = refs[0]; /* "draw": mcs_pattern_draw alone */
    list[1] = bench_bare_draw_contender();
    report_draw_header();
    for (size_t ik = 0; ik < 2u; ++ik)
        for (size_t in = 0; in < 2u; ++in)
            for (size_t iK = 0; iK < 2u; ++iK) {
                bench_cell cell = {ns[in], ks[iK], kinds[ik], cell_seed(ns[in], ks[iK], kinds[ik])};
                if (bench_interleave(list, 2u, &cell, opt->rounds, opt->slice_seconds, &run) !=
                    BENCH_OK)
                    return 1;
                report_draw_row(&cell, &run, tally);
            }
    return 0;
}

/* The C side and the numpy co-process on one CPU: the co-process, forked
 * later, inherits the mask, so whatever slows that core (another tenant of
 * a shared machine) slows both sides of the comparison alike. Without it a
 * full run here had the C side at two thirds of its speed for ten seconds
 * while the co-process ran on the other core at full speed. The CPU, or -1
 * where it cannot be set. */
static int pin_to_this_cpu(void)
{
#if defined(__linux__)
    const int cpu = sched_getcpu();
    if (cpu < 0)
        return -1;
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cpu, &set);
    return sched_setaffinity(0, sizeof set, &set) == 0 ? cpu : -1;
#else
    return -1;
#endif
}

static void print_setup(const bench_options *opt, int cpu)
{
    printf("mcspec speed bench%s: %zu interleaved rounds of %.1f ms slices per cell\n",
           opt->quick ? " (BENCH_QUICK: a subset of the grid)" : "", opt->rounds,
           1e3 * opt->slice_seconds);
    printf("slices timed by %s\n",
           opt->wall ? "the wall clock (CLOCK_MONOTONIC; Python time.perf_counter)"
                     : "the running thread's CPU clock (CLOCK_THREAD_CPUTIME_ID; Python "
                       "time.thread_time):\ntime in which another process holds the core is "
                       "not counted");
    bench_print_machine(BENCH_CC, BENCH_CC_VERSION, BENCH_FLAGS);
    printf("FFTW peer: %s\n", bench_fftw_available() ? bench_fftw_version() : "not available");
    printf("numpy peer: %s\n", bench_numpy_describe());
    if (cpu >= 0)
        printf("pinned: this process and the numpy co-process run on CPU %d\n", cpu);
    else
        printf("not pinned to one CPU (the co-process may run on another)\n");
}

int main(int argc, char **argv)
{
    bench_options opt;
    bench_tally tally;
    if (parse_options(argc, argv, &opt) != 0)
        return 2;
    if (!pcg32_copy_is_reference()) {
        fprintf(stderr, "bench: the copied PCG32 does not reproduce the reference outputs\n");
        return 1;
    }
    memset(&tally, 0, sizeof tally);
    bench_use_wall_clock(opt.wall);
    const int cpu = pin_to_this_cpu();
    (void)bench_numpy_start(opt.python, opt.numpy_script, opt.wall);
    double t0 = bench_now();
    print_setup(&opt, cpu);
    int rc = run_grid(&opt, &tally);
    rc = rc ? rc : run_moment(&opt, &tally);
    rc = rc ? rc : run_draw(&opt, &tally);
    if (rc == 0)
        report_summary(&tally);
    bench_numpy_stop();
    bench_fftw_cleanup();
    printf("\nwall time %.0f s; ", bench_now() - t0);
    bench_print_load("end:");
    return rc;
}
