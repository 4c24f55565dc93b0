/* spectrum_costs: measures the parts of the cost model behind
 * MCS_SPECTRUM_PATH_AUTO (src/accumulators/spectrum_cost.c, src/dft/dft.c) on this machine
 * and fits its constants, so that they are measured, not guessed.
 *
 *   make spectrum-costs          (or build/bench/spectrum_costs [--quick] [--generic])
 *
 * --generic times the baseline kernels where the AVX2 ones would run.
 *
 * Every time is the fastest of several passes over a ring of pre-drawn
 * random trials (no draw in the time), by the thread's CPU clock:
 *   dft(N)         mcs_dft_real_half alone
 *   SPARSE, FFT    mcs_spectrum_add_bins per trial with the path forced
 *   PAIR           the same with one batch that never closes (pairs only)
 *   close(N)       mcs_spectrum_flush of a batch
 * and the fits (least squares, nanoseconds; H = N/2 + 1 padded to 8):
 *   SPARSE - FFT's per-call overhead  ~ C_TERM K H + C_PHASE K + C_UPDATE H
 *   FFT - dft(N)                      ~ C_SCATTER K + C_UPDATE H
 *   PAIR                              ~ C_PAIR K (K - 1)/2 + C_SINGLE K
 *   close(N) - 2 dft(N)               ~ C_UPDATE H + C_FOLD N
 *   dft(N) per path                   ~ a N log2 N (+ b), direct: a nnz H
 * Each fit also has a constant term (argument checks and the call, which
 * every path pays and the choice ignores). Last, the grid with AUTO's time
 * over the best forced path's, which is what the model is for. */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "mcspec.h"

#define RING 64u
#define MAX_K 256u
#define MAX_ROWS 128u
#define MAX_COLS 5u

static size_t ring_bins[RING][MAX_K];
static double ring_weights[RING][MAX_K];
static mcs_spectrum acc;
static mcs_dft plan;
static double dense[MCS_MAX_N], out_re[MCS_MAX_N], out_im[MCS_MAX_N];

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static void fill_ring(size_t n, size_t k)
{
    mcs_pattern pat;
    mcs_rng rng;
    if (mcs_pattern_init(&pat, MCS_PATTERN_RANDOM, n, k, NULL) != MCS_OK ||
        mcs_rng_seed(&rng, 1000u + n, k) != MCS_OK)
        exit(1);
    for (size_t t = 0; t < RING; ++t)
        if (mcs_pattern_draw(&pat, &rng, k, ring_bins[t], ring_weights[t], NULL) != MCS_OK)
            exit(1);
}

/* Runs `calls` trials; the caller has set the path. */
static void add_trials(size_t k, size_t calls)
{
    for (size_t t = 0; t < calls; ++t) {
        mcs_status st = mcs_spectrum_add_bins(&acc, k, ring_bins[t % RING], ring_weights[t % RING]);
        if (st != MCS_OK) {
            fprintf(stderr, "spectrum_costs: add_bins: %s\n", mcs_status_str(st));
            exit(1);
        }
    }
}

static void start(size_t n, mcs_spectrum_path path, uint64_t batch);

/* Fastest ns per trial over `passes` passes of about `budget` seconds. */
static double time_path(size_t n, size_t k, mcs_spectrum_path path, uint64_t batch,
                        double budget, int passes)
{
    double best = INFINITY;
    size_t calls = 1u;
    for (int p = -1; p < passes; ++p) { /* pass -1 sizes the passes and warms up */
        start(n, path, batch);
        add_trials(k, RING);
        const double t0 = now();
        add_trials(k, calls);
        const double dt = now() - t0;
        if (p < 0) {
            calls = (size_t)(budget / (dt / (double)calls + 1e-9)) + 1u;
            continue;
        }
        best = fmin(best, dt / (double)calls);
    }
    return 1e9 * best;
}

static double time_dft(size_t n, int passes)
{
    if (mcs_dft_init(&plan, n) != MCS_OK)
        exit(1);
    for (size_t j = 0; j < n; ++j)
        dense[j] = (double)((j * 7u) % 5u);
    double best = INFINITY;
    const size_t calls = 2000000u / (n + 16u) + 8u;
    for (int p = 0; p < passes; ++p) {
        const double t0 = now();
        for (size_t c = 0; c < calls; ++c)
            if (mcs_dft_real_half(&plan, n, dense, out_re, out_im) != MCS_OK)
                exit(1);
        best = fmin(best, (now() - t0) / (double)calls);
    }
    return 1e9 * best;
}

static int generic_kernels; /* --generic: the baseline kernels even where AVX2 runs */

static void start(size_t n, mcs_spectrum_path path, uint64_t batch)
{
    if (mcs_spectrum_init(&acc, n) != MCS_OK || mcs_spectrum_set_path(&acc, path) != MCS_OK ||
        mcs_spectrum_set_batch(&acc, batch) != MCS_OK)
        exit(1);
    if (generic_kernels)
        acc.simd = 0; /* a public field: both kernel sets give the same bits */
}

/* Time of one mcs_spectrum_flush of a batch of 4 trials of k samples: rounds
 * of (4 trials, flush) less rounds of 4 trials alone, so that neither the
 * trials nor the clock's own cost count. */
static double time_close(size_t n, size_t k, int passes)
{
    const size_t rounds = 200u;
    double best = INFINITY;
    for (int p = 0; p < passes; ++p) {
        start(n, MCS_SPECTRUM_PATH_PAIR, UINT64_C(1) << 32);
        double t0 = now();
        for (size_t r = 0; r < rounds; ++r) {
            add_trials(k, 4u);
            if (mcs_spectrum_flush(&acc) != MCS_OK)
                exit(1);
        }
        const double with = now() - t0;
        start(n, MCS_SPECTRUM_PATH_PAIR, UINT64_C(1) << 32);
        t0 = now();
        for (size_t r = 0; r < rounds; ++r)
            add_trials(k, 4u);
        best = fmin(best, (with - (now() - t0)) / (double)rounds);
    }
    return 1e9 * best;
}

/* Least squares: rows of x (cols regressors) against y; coef[cols]. */
static void fit(size_t rows, size_t cols, double x[][MAX_COLS], const double *y, double *coef)
{
    double a[MAX_COLS][MAX_COLS + 1];
    memset(a, 0, sizeof a);
    for (size_t r = 0; r < rows; ++r)
        for (size_t i = 0; i < cols; ++i) {
            for (size_t j = 0; j < cols; ++j)
                a[i][j] += x[r][i] * x[r][j];
            a[i][cols] += x[r][i] * y[r];
        }
    for (size_t i = 0; i < cols; ++i) { /* Gauss-Jordan with partial pivoting */
        size_t piv = i;
        for (size_t r = i + 1u; r < cols; ++r)
            if (fabs(a[r][i]) > fabs(a[piv][i]))
                piv = r;
        for (size_t j = 0; j <= cols; ++j) {
            double t = a[i][j];
            a[i][j] = a[piv][j];
            a[piv][j] = t;
        }
        for (size_t r = 0; r < cols; ++r) {
            if (r == i || a[i][i] == 0.0)
                continue;
            const double m = a[r][i] / a[i][i];
            for (size_t j = i; j <= cols; ++j)
                a[r][j] -= m * a[i][j];
        }
    }
    for (size_t i = 0; i < cols; ++i)
        coef[i] = a[i][i] != 0.0 ? a[i][cols] / a[i][i] : 0.0;
}

static double stored(size_t n)
{
    return (double)((n / 2u + MCS_SPECTRUM_BLOCK) / MCS_SPECTRUM_BLOCK * MCS_SPECTRUM_BLOCK);
}

typedef struct {
    size_t n, k;
    double sparse, fft, pair, autoc, pair_rule;
} cell;

int main(int argc, char **argv)
{
    int quick = 0;
    for (int a = 1; a < argc; ++a) {
        quick |= strcmp(argv[a], "--quick") == 0;
        generic_kernels |= strcmp(argv[a], "--generic") == 0;
    }
    static const size_t ns[] = {64u, 256u, 1024u, 4096u, 1000u, 3375u, 4093u};
    static const size_t ks[] = {1u, 2u, 4u, 8u, 16u, 32u, 64u, 128u, 256u};
    const size_t n_count = quick ? 4u : sizeof ns / sizeof ns[0];
    const size_t k_count = sizeof ks / sizeof ks[0];
    const double budget = quick ? 2e-3 : 6e-3;
    const int passes = quick ? 3 : 5;
    static cell cells[MAX_ROWS];
    static double x[MAX_ROWS][MAX_COLS], y[MAX_ROWS];
    double dft_t[8], close_t[8], coef[MAX_COLS];
    size_t count = 0u;

    printf("spectrum_costs: mcspec %s, DFT back end %s, %s kernels; ns per trial, fastest of %d "
           "passes\n", mcs_version(), mcs_dft_backend(), generic_kernels ? "baseline" : "default",
           passes);
    printf("%5s %4s | %9s %9s %9s %9s | %9s %9s | %s\n", "N", "K", "SPARSE", "FFT", "PAIR",
           "PAIR rule", "AUTO", "best", "AUTO/best");
    for (size_t i = 0; i < n_count; ++i) {
        const size_t n = ns[i];
        dft_t[i] = time_dft(n, passes);
        fill_ring(n, 8u);
        close_t[i] = time_close(n, 8u, passes);
        for (size_t j = 0; j < k_count; ++j) {
            const size_t k = ks[j];
            cell *c = &cells[count++];
            fill_ring(n, k);
            c->n = n;
            c->k = k;
            c->sparse = time_path(n, k, MCS_SPECTRUM_PATH_SPARSE, 0u, budget, passes);
            c->fft = time_path(n, k, MCS_SPECTRUM_PATH_FFT, 0u, budget, passes);
            c->pair = time_path(n, k, MCS_SPECTRUM_PATH_PAIR, UINT64_C(1) << 32, budget, passes);
            c->pair_rule = time_path(n, k, MCS_SPECTRUM_PATH_PAIR, 0u, 4.0 * budget, passes);
            c->autoc = time_path(n, k, MCS_SPECTRUM_PATH_AUTO, 0u, 4.0 * budget, passes);
            const double best = fmin(c->sparse, fmin(c->fft, c->pair_rule));
            printf("%5zu %4zu | %9.1f %9.1f %9.1f %9.1f | %9.1f %9.1f | %.2f\n", n, k, c->sparse,
                   c->fft, c->pair, c->pair_rule, c->autoc, best, c->autoc / best);
            fflush(stdout);
        }
        printf("%5zu dft %.1f ns, close %.1f ns (2 dft + %.1f)\n", n, dft_t[i], close_t[i],
               close_t[i] - 2.0 * dft_t[i]);
    }

    /* PAIR ~ C_PAIR K(K-1)/2 + C_SINGLE K + c */
    size_t rows = 0u;
    for (size_t r = 0; r < count; ++r) {
        const double k = (double)cells[r].k;
        if (cells[r].k < 2u)
            continue;
        x[rows][0] = 0.5 * k * (k - 1.0);
        x[rows][1] = k;
        x[rows][2] = 1.0;
        y[rows++] = cells[r].pair;
    }
    fit(rows, 3u, x, y, coef);
    printf("\nfit PAIR:   C_PAIR %.3f  C_SINGLE %.3f  (+ %.1f per call)\n", coef[0], coef[1], coef[2]);
    /* FFT - dft ~ C_SCATTER K + C_UPDATE H + c, on N the transform does in
     * N log N (not the direct sum) */
    rows = 0u;
    for (size_t r = 0; r < count; ++r) {
        size_t idx = 0u;
        while (ns[idx] != cells[r].n)
            ++idx;
        if (cells[r].n == 4093u)
            continue;
        x[rows][0] = (double)cells[r].k;
        x[rows][1] = stored(cells[r].n);
        x[rows][2] = 1.0;
        y[rows++] = cells[r].fft - dft_t[idx];
    }
    fit(rows, 3u, x, y, coef);
    printf("fit FFT:    C_SCATTER %.3f  C_UPDATE %.3f  (+ %.1f per call)\n", coef[0], coef[1], coef[2]);
    const double c_update = coef[1];
    /* SPARSE ~ C_TERM K H + C_PHASE K + C_UPDATE H + c, fused kernel only */
    rows = 0u;
    for (size_t r = 0; r < count; ++r) {
        const double k = (double)cells[r].k, h = stored(cells[r].n);
        if (cells[r].k > MCS_SPECTRUM_CHUNK)
            continue;
        x[rows][0] = k * h;
        x[rows][1] = k;
        x[rows][2] = h;
        x[rows][3] = 1.0;
        y[rows++] = cells[r].sparse;
    }
    fit(rows, 4u, x, y, coef);
    printf("fit SPARSE: C_TERM %.3f  C_PHASE %.3f  C_UPDATE %.3f  (+ %.1f per call), K <= %d\n",
           coef[0], coef[1], coef[2], coef[3], MCS_SPECTRUM_CHUNK);
    /* close - 2 dft ~ C_UPDATE H + C_FOLD N + c */
    rows = 0u;
    for (size_t i = 0; i < n_count; ++i) {
        if (ns[i] == 4093u)
            continue;
        x[rows][0] = (double)ns[i];
        x[rows][1] = 1.0;
        y[rows++] = close_t[i] - 2.0 * dft_t[i] - c_update * stored(ns[i]);
    }
    fit(rows, 2u, x, y, coef);
    printf("fit close:  C_FOLD %.3f  (+ %.1f per close), with C_UPDATE from FFT\n", coef[0], coef[1]);
    printf("dft per N log2 N:");
    for (size_t i = 0; i < n_count; ++i)
        printf("  %zu: %.3f", ns[i], dft_t[i] / ((double)ns[i] * log2((double)ns[i])));
    if (n_count > 6u)
        printf("\ndirect sum (N = 4093, dense input): %.3f ns per (bin, frequency)",
               dft_t[6] / (4093.0 * (4093.0 / 2.0 + 1.0)));
    printf("\n");
    return 0;
}
