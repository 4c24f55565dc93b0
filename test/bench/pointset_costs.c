/* pointset_costs: measures the terms of the cost model behind
 * MCS_POINTSET_PATH_AUTO (src/pointsets/pointset_cost.c) on this machine and
 * fits its constants, so that they are measured, not guessed.
 *
 *   build/bench/pointset_costs [--quick]
 *
 * Every time is the fastest of a few adds of one pre-drawn random trial
 * with the path forced, by the thread's CPU clock. The fits (least squares,
 * nanoseconds; the Welford update U cells, O(F^d), is fitted too, as both
 * paths pay it, and left out of the model):
 *   1D DIRECT  K (D1 H + P1 (H/32 + 32)) + U1 (F + 1)       H = F + 1 padded to 32
 *   1D NUFFT   S1 K + T G1 n log2 n + U1 (F + 1)
 *   2D DIRECT  K (D2 (F + 1)(2F + 2) + P2 (F + 1)) + U2 (F + 1)(2F + 2)
 *   2D NUFFT   S2 K + T G2 n^2 log2 n + U2 (F + 1)(2F + 2)
 * with n the plan's grid and T the transforms a trial takes. Last, the grid
 * with AUTO's time over the faster forced path's. */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "mcspec.h"

#define MAX_OBS 128
#define MAX_COLS 4

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Least squares by the normal equations (a few well-scaled columns). */
static void fit(size_t rows, size_t cols, double x[][MAX_COLS], const double *y, double *coef)
{
    double a[MAX_COLS][MAX_COLS + 1];
    memset(a, 0, sizeof a);
    for (size_t r = 0; r < rows; ++r)
        for (size_t i = 0; i < cols; ++i) {
            /* relative errors: weigh each row by 1 / y */
            const double w = 1.0 / (y[r] * y[r]);
            for (size_t j = 0; j < cols; ++j)
                a[i][j] += w * x[r][i] * x[r][j];
            a[i][cols] += w * x[r][i] * y[r];
        }
    for (size_t i = 0; i < cols; ++i)
        for (size_t r = 0; r < cols; ++r) {
            if (r == i || a[i][i] == 0.0)
                continue;
            const double f = a[r][i] / a[i][i];
            for (size_t j = i; j <= cols; ++j)
                a[r][j] -= f * a[i][j];
        }
    for (size_t i = 0; i < cols; ++i)
        coef[i] = a[i][i] != 0.0 ? a[i][cols] / a[i][i] : 0.0;
}

static double *points;

static void draw(size_t count)
{
    mcs_rng rng;
    (void)mcs_rng_seed(&rng, 2024u, 24u);
    for (size_t j = 0; j < count; ++j)
        (void)mcs_rng_double(&rng, &points[j]);
}

/* Fastest of reps adds of k points (dims 1 or 2) on path, in ns. */
static double time_add(int dims, void *acc, size_t k, mcs_pointset_path path, int reps)
{
    double best = 1e300;
    for (int r = 0; r < reps; ++r) {
        mcs_status st;
        const double t0 = now();
        if (dims == 1) {
            (void)mcs_pointset_set_path(acc, path);
            st = mcs_pointset_add(acc, k, points);
        } else {
            (void)mcs_pointset2d_set_path(acc, path);
            st = mcs_pointset2d_add(acc, k, points);
        }
        const double t = now() - t0;
        if (st != MCS_OK) {
            fprintf(stderr, "add failed: %s\n", mcs_status_str(st));
            exit(1);
        }
        best = t < best ? t : best;
    }
    return best * 1e9;
}

typedef struct {
    size_t k, f;
    double direct, nufft, n, chunk;
} obs;

static obs cells[MAX_OBS];

static size_t chunk_of(int dims, size_t f)
{
    const size_t side = 2u * f + 1u, modes = dims == 1 ? 2u * side : 2u * side * side;
    return (modes > MCS_POINTSET_STAGE_MIN ? modes : (size_t)MCS_POINTSET_STAGE_MIN) / (size_t)dims;
}

static size_t run_grid(int dims, const size_t *ks, size_t nk, const size_t *fs, size_t nf, int quick)
{
    size_t count = 0;
    for (size_t a = 0; a < nf; ++a) {
        const size_t f = fs[a];
        size_t bytes = 0;
        mcs_status st = dims == 1 ? mcs_pointset_size(f, 0u, &bytes) : mcs_pointset2d_size(f, 0u, &bytes);
        void *mem = st == MCS_OK ? malloc(bytes) : NULL;
        mcs_pointset p1;
        mcs_pointset2d p2;
        void *acc = dims == 1 ? (void *)&p1 : (void *)&p2;
        if (mem == NULL || (dims == 1 ? mcs_pointset_init(&p1, f, 0u, mem, bytes)
                                      : mcs_pointset2d_init(&p2, f, 0u, mem, bytes)) != MCS_OK) {
            fprintf(stderr, "no object for F = %zu\n", f);
            exit(1);
        }
        const size_t n = dims == 1 ? p1.plan.n : p2.plan.n;
        for (size_t b = 0; b < nk; ++b) {
            const size_t k = ks[b];
            const double work = (double)k * (dims == 1 ? (double)f : 2.0 * (double)f * (double)f);
            if (work > (quick ? 3e8 : 3e9))
                continue; /* the direct sum alone would take seconds */
            const int reps = work > 1e8 ? 1 : work > 1e6 ? 3 : 7;
            (void)time_add(dims, acc, k, MCS_POINTSET_PATH_NUFFT, 1); /* warm-up */
            obs *o = &cells[count++];
            o->k = k;
            o->f = f;
            o->n = (double)n;
            o->chunk = (double)chunk_of(dims, f);
            o->direct = time_add(dims, acc, k, MCS_POINTSET_PATH_DIRECT, reps);
            o->nufft = time_add(dims, acc, k, MCS_POINTSET_PATH_NUFFT, reps);
            const double t_auto = time_add(dims, acc, k, MCS_POINTSET_PATH_AUTO, reps);
            const double best = o->direct < o->nufft ? o->direct : o->nufft;
            printf("%dD K %6zu F %5zu  direct %12.0f  nufft %12.0f ns  auto/best %.2f\n", dims, k,
                   f, o->direct, o->nufft, t_auto / best);
        }
        free(mem);
    }
    return count;
}

/* The direct path's constants first (with U, the Welford update both paths
 * pay), then the NUFFT's from its times less that U: the NUFFT's terms in F
 * (the transform, the gather of the modes, U) grow alike, so fitted
 * together they trade off against each other. */
static void fit_paths(int dims, size_t count)
{
    static double x[MAX_OBS][MAX_COLS], y[MAX_OBS];
    double c[MAX_COLS];
    for (size_t i = 0; i < count; ++i) {
        const obs *o = &cells[i];
        const double f = (double)o->f, k = (double)o->k;
        const double h = floor(f / 32.0 + 1.0) * 32.0;
        const double stored = dims == 1 ? f + 1.0 : (f + 1.0) * (2.0 * f + 2.0);
        x[i][0] = dims == 1 ? k * h : k * stored;
        x[i][1] = dims == 1 ? k * (h / 32.0 + 32.0) : k * (f + 1.0);
        x[i][2] = stored;
        y[i] = o->direct;
    }
    fit(count, 3, x, y, c);
    const double u = c[2];
    printf("%dD DIRECT: D%d %.3f  P%d %.2f  U%d %.2f\n", dims, dims, c[0], dims, c[1], dims, u);
    for (size_t i = 0; i < count; ++i) {
        const obs *o = &cells[i];
        const double f = (double)o->f, k = (double)o->k, t = ceil(k / o->chunk);
        const double stored = dims == 1 ? f + 1.0 : (f + 1.0) * (2.0 * f + 2.0);
        x[i][0] = k;
        x[i][1] = dims == 1 ? t * o->n * log2(o->n) : t * o->n * o->n * log2(o->n);
        y[i] = o->nufft - u * stored;
        y[i] = y[i] > 0.05 * o->nufft ? y[i] : 0.05 * o->nufft;
    }
    fit(count, 2, x, y, c);
    printf("%dD NUFFT: S%d %.1f  G%d %.3f\n", dims, dims, c[0], dims, c[1]);
}

int main(int argc, char **argv)
{
    const int quick = argc > 1 && strcmp(argv[1], "--quick") == 0;
    static const size_t ks[] = {16, 64, 256, 1024, 4096, 16384, 65536};
    static const size_t f1[] = {16, 64, 256, 1024, 4096, 16384};
    static const size_t f2[] = {4, 8, 16, 32, 64, 128, 320, 640};
    points = malloc(2u * 65536u * sizeof *points);
    if (points == NULL)
        return 1;
    draw(2u * 65536u);
    size_t count = run_grid(1, ks, sizeof ks / sizeof ks[0], f1, sizeof f1 / sizeof f1[0], quick);
    fit_paths(1, count);
    count = run_grid(2, ks, sizeof ks / sizeof ks[0], f2, sizeof f2 / sizeof f2[0], quick);
    fit_paths(2, count);
    free(points);
    return 0;
}
