#include "floors.h"

#include <string.h>

#include "pcg32_ref.h"

#define PN BENCH_POOL_MAX_N
#define PT BENCH_POOL_TRIALS

typedef struct {
    const bench_pool *pool;
    size_t next;  /* next pool trial */
    double count; /* trials added */
    double sum_s[PN];
    double sum_ss[PN * PN]; /* [m * N + n], m <= n */
    double s[PN];           /* dense s of one trial */
    double xt[PN][PT];      /* X^T: bin by trial */
} floor_ctx;

static floor_ctx pairs_ctx, dense_ctx, xtx_ctx;

static int floor_prepare(void *ctx, const bench_cell *cell)
{
    floor_ctx *c = ctx;
    if (c->pool->n != cell->n || c->pool->k != cell->k || cell->n > PN)
        return BENCH_FAILED;
    c->next = 0u;
    c->count = 0.0;
    memset(c->sum_s, 0, sizeof c->sum_s);
    memset(c->sum_ss, 0, sizeof c->sum_ss);
    return BENCH_OK;
}

static int floor_readout(void *ctx, size_t index, double *value, double *stderr_out)
{
    const floor_ctx *c = ctx;
    const size_t n = c->pool->n;
    if (c->count == 0.0 || index >= n * n + n)
        return BENCH_FAILED;
    *value = (index < n * n ? c->sum_ss[index] : c->sum_s[index - n * n]) / c->count;
    *stderr_out = 0.0;
    return BENCH_OK;
}

/* Every pair j < j' once: s_m s_n (m < n) gets w_j w_j' from the one ordered
 * pair that starts in m; s_m^2 gets it from both orders (twice) and w_j^2
 * from j = j'. */
static void pairs_trial(floor_ctx *c, const size_t *b, const double *w)
{
    const size_t n = c->pool->n, k = c->pool->k;
    for (size_t j = 0; j < k; ++j) {
        c->sum_s[b[j]] += w[j];
        c->sum_ss[b[j] * n + b[j]] += w[j] * w[j];
        for (size_t i = j + 1u; i < k; ++i) {
            const size_t lo = b[i] < b[j] ? b[i] : b[j], hi = b[i] < b[j] ? b[j] : b[i];
            const double twice = lo == hi ? 2.0 : 1.0;
            c->sum_ss[lo * n + hi] += twice * w[j] * w[i];
        }
    }
}

static int pairs_run(void *ctx, size_t calls)
{
    floor_ctx *c = ctx;
    for (size_t i = 0; i < calls; ++i) {
        pairs_trial(c, c->pool->bins[c->next], c->pool->weights[c->next]);
        c->next = (c->next + 1u) % PT;
    }
    c->count += (double)calls;
    return BENCH_OK;
}

/* Dense s, then the whole upper triangle: N (N + 1) / 2 multiply-adds whose
 * inner loop the compiler vectorises. */
static void dense_trial(floor_ctx *c, const size_t *b, const double *w)
{
    const size_t n = c->pool->n, k = c->pool->k;
    double *s = c->s;
    memset(s, 0, n * sizeof s[0]);
    for (size_t j = 0; j < k; ++j)
        s[b[j]] += w[j];
    for (size_t m = 0; m < n; ++m) {
        const double sm = s[m];
        double *row = c->sum_ss + m * n;
        c->sum_s[m] += sm;
        for (size_t q = m; q < n; ++q)
            row[q] += sm * s[q];
    }
}

static int dense_run(void *ctx, size_t calls)
{
    floor_ctx *c = ctx;
    for (size_t i = 0; i < calls; ++i) {
        dense_trial(c, c->pool->bins[c->next], c->pool->weights[c->next]);
        c->next = (c->next + 1u) % PT;
    }
    c->count += (double)calls;
    return BENCH_OK;
}

/* Sum over the 64 trials, four partial sums so the additions need not wait
 * on each other (and pair into vector registers). */
static double dot_trials(const double *a, const double *b)
{
    double acc0 = 0.0, acc1 = 0.0, acc2 = 0.0, acc3 = 0.0;
    for (size_t t = 0; t < PT; t += 4u) {
        acc0 += a[t] * b[t];
        acc1 += a[t + 1u] * b[t + 1u];
        acc2 += a[t + 2u] * b[t + 2u];
        acc3 += a[t + 3u] * b[t + 3u];
    }
    return (acc0 + acc1) + (acc2 + acc3);
}

/* All 64 pool trials as X (trial by bin), stored transposed; the sums get
 * row sums of X^T and the upper triangle of X^T X. */
static void xtx_batch(floor_ctx *c)
{
    const size_t n = c->pool->n, k = c->pool->k;
    static const double ones[PT] = {
        1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
        1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
        1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
    memset(c->xt, 0, n * sizeof c->xt[0]);
    for (size_t t = 0; t < PT; ++t)
        for (size_t j = 0; j < k; ++j)
            c->xt[c->pool->bins[t][j]][t] += c->pool->weights[t][j];
    for (size_t m = 0; m < n; ++m) {
        c->sum_s[m] += dot_trials(c->xt[m], ones);
        for (size_t q = m; q < n; ++q)
            c->sum_ss[m * n + q] += dot_trials(c->xt[m], c->xt[q]);
    }
}

static int xtx_run(void *ctx, size_t calls)
{
    floor_ctx *c = ctx;
    for (size_t i = 0; i < calls; ++i)
        xtx_batch(c);
    c->count += (double)calls * (double)PT;
    return BENCH_OK;
}

size_t bench_moment_floors(bench_contender *out, const bench_pool *pool)
{
    pairs_ctx.pool = dense_ctx.pool = xtx_ctx.pool = pool;
    bench_contender pairs = {"pairs", &pairs_ctx, 1u, floor_prepare, pairs_run,
                             NULL, floor_readout, 0.0, 0u};
    bench_contender dense = {"dense", &dense_ctx, 1u, floor_prepare, dense_run,
                             NULL, floor_readout, 0.0, 0u};
    bench_contender xtx = {"XtX", &xtx_ctx, PT, floor_prepare, xtx_run, NULL, floor_readout, 0.0, 0u};
    out[0] = pairs;
    out[1] = dense;
    out[2] = xtx;
    return 3u;
}

typedef struct {
    pcg32_random_t rng;
    uint32_t n;
    size_t k;
    size_t bins[256];
} bare_draw_ctx;

static bare_draw_ctx bare;

static int bare_prepare(void *ctx, const bench_cell *cell)
{
    bare_draw_ctx *c = ctx;
    if (cell->k > sizeof c->bins / sizeof c->bins[0])
        return BENCH_FAILED;
    pcg32_srandom_r(&c->rng, cell->seed, 17u);
    c->n = (uint32_t)cell->n;
    c->k = cell->k;
    return BENCH_OK;
}

static int bare_run(void *ctx, size_t calls)
{
    bare_draw_ctx *c = ctx;
    for (size_t i = 0; i < calls; ++i)
        for (size_t j = 0; j < c->k; ++j)
            c->bins[j] = pcg32_boundedrand_r(&c->rng, c->n);
    return BENCH_OK;
}

bench_contender bench_bare_draw_contender(void)
{
    bench_contender c = {"pcg32", &bare, 1u, bare_prepare, bare_run, NULL, NULL, 0.0, 0u};
    return c;
}
