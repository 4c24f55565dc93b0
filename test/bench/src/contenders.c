#include "contenders.h"

#include <string.h>

#include "mcspec.h"

/* The spectrum paths the bench measures, AUTO first. A new path of
 * mcs_spectrum_set_path is one more line here. */
static const struct {
    const char *name;
    mcs_spectrum_path path;
} spectrum_paths[] = {
    {"AUTO", MCS_SPECTRUM_PATH_AUTO},
    {"SPARSE", MCS_SPECTRUM_PATH_SPARSE},
    {"FFT", MCS_SPECTRUM_PATH_FFT},
    {"PAIR", MCS_SPECTRUM_PATH_PAIR},
};

#define PATH_COUNT (sizeof spectrum_paths / sizeof spectrum_paths[0])
#define MAX_K 256u

/* A pattern with its generator and one trial's worth of (bin, weight). */
typedef struct {
    mcs_pattern pat;
    mcs_rng rng;
    size_t bins[MAX_K];
    double weights[MAX_K];
} trial_source;

typedef struct {
    trial_source src;
    mcs_spectrum_path path;
    /* On a 64-byte boundary, as docs/integrating.md advises (a static
     * object's or aligned_alloc's): inside this struct it would otherwise
     * sit wherever the fields before it leave it, and at 8 or 16 mod 32 the
     * direct DFT of a prime N runs 1.35x slower (include/mcspec/dft.h), which
     * made whichever contender got the lucky offset look fastest. */
    _Alignas(64) mcs_spectrum spec;
} spectrum_ctx;

typedef struct {
    trial_source src;
    _Alignas(64) mcs_dft plan;
    double s[MCS_MAX_N];
    double re[MCS_MAX_N / 2 + 1];
    double im[MCS_MAX_N / 2 + 1];
} dft_ctx;

typedef struct {
    trial_source src;
    mcs_autocorr acorr;
} autocorr_ctx;

/* Static: each mcs_spectrum is ~400 KB, too large for a stack. */
static spectrum_ctx spectrum_ctxs[PATH_COUNT];
static trial_source draw_ctx;
static dft_ctx dft_state;
static autocorr_ctx autocorr_state;

static int source_prepare(trial_source *src, const bench_cell *cell)
{
    if (cell->k > MAX_K)
        return BENCH_FAILED;
    if (mcs_pattern_init(&src->pat, (mcs_pattern_kind)cell->kind, cell->n, cell->k, NULL) !=
        MCS_OK)
        return BENCH_FAILED;
    return mcs_rng_seed(&src->rng, cell->seed, 11u) == MCS_OK ? BENCH_OK : BENCH_FAILED;
}

static int source_draw(trial_source *src)
{
    return mcs_pattern_draw(&src->pat, &src->rng, src->pat.k, src->bins, src->weights, NULL) ==
                   MCS_OK
               ? BENCH_OK
               : BENCH_FAILED;
}

static int spectrum_prepare(void *ctx, const bench_cell *cell)
{
    spectrum_ctx *c = ctx;
    if (source_prepare(&c->src, cell) != BENCH_OK || mcs_spectrum_init(&c->spec, cell->n) != MCS_OK)
        return BENCH_FAILED;
    return mcs_spectrum_set_path(&c->spec, c->path) == MCS_OK ? BENCH_OK : BENCH_FAILED;
}

static int spectrum_run(void *ctx, size_t calls)
{
    spectrum_ctx *c = ctx;
    for (size_t i = 0; i < calls; ++i) {
        if (source_draw(&c->src) != BENCH_OK ||
            mcs_spectrum_add_bins(&c->spec, c->src.pat.k, c->src.bins, c->src.weights) != MCS_OK)
            return BENCH_FAILED;
    }
    return BENCH_OK;
}

static int spectrum_readout(void *ctx, size_t freq, double *value, double *stderr_out)
{
    const spectrum_ctx *c = ctx;
    return mcs_spectrum_power(&c->spec, freq, value) == MCS_OK &&
                   mcs_spectrum_power_stderr(&c->spec, freq, stderr_out) == MCS_OK
               ? BENCH_OK
               : BENCH_FAILED;
}

size_t bench_spectrum_path_count(void)
{
    return PATH_COUNT;
}

size_t bench_spectrum_contenders(bench_contender *out)
{
    for (size_t p = 0; p < PATH_COUNT; ++p) {
        spectrum_ctxs[p].path = spectrum_paths[p].path;
        bench_contender c = {spectrum_paths[p].name, &spectrum_ctxs[p], 1u, spectrum_prepare,
                             spectrum_run, NULL, spectrum_readout, 0.0, 0u};
        /* The pair route closes a batch at most every MCS_SPECTRUM_BATCH_MAX trials. */
        if (spectrum_paths[p].path == MCS_SPECTRUM_PATH_PAIR || spectrum_paths[p].path == MCS_SPECTRUM_PATH_AUTO)
            c.period = MCS_SPECTRUM_BATCH_MAX;
        out[p] = c;
    }
    return PATH_COUNT;
}

static int draw_prepare(void *ctx, const bench_cell *cell)
{
    return source_prepare(ctx, cell);
}

static int draw_run(void *ctx, size_t calls)
{
    for (size_t i = 0; i < calls; ++i)
        if (source_draw(ctx) != BENCH_OK)
            return BENCH_FAILED;
    return BENCH_OK;
}

/* The transform alone, on one drawn trial's dense s (the input does not
 * change its cost). */
static int dft_prepare(void *ctx, const bench_cell *cell)
{
    dft_ctx *c = ctx;
    if (source_prepare(&c->src, cell) != BENCH_OK || source_draw(&c->src) != BENCH_OK ||
        mcs_dft_init(&c->plan, cell->n) != MCS_OK)
        return BENCH_FAILED;
    return mcs_pattern_dense(cell->n, cell->k, c->src.bins, c->src.weights, c->s) == MCS_OK
               ? BENCH_OK
               : BENCH_FAILED;
}

static int dft_run(void *ctx, size_t calls)
{
    dft_ctx *c = ctx;
    for (size_t i = 0; i < calls; ++i)
        if (mcs_dft_real_half(&c->plan, c->src.pat.n, c->s, c->re, c->im) != MCS_OK)
            return BENCH_FAILED;
    return BENCH_OK;
}

static int autocorr_prepare(void *ctx, const bench_cell *cell)
{
    autocorr_ctx *c = ctx;
    if (source_prepare(&c->src, cell) != BENCH_OK)
        return BENCH_FAILED;
    return mcs_autocorr_init(&c->acorr, cell->n) == MCS_OK ? BENCH_OK : BENCH_FAILED;
}

static int autocorr_run(void *ctx, size_t calls)
{
    autocorr_ctx *c = ctx;
    for (size_t i = 0; i < calls; ++i) {
        if (source_draw(&c->src) != BENCH_OK ||
            mcs_autocorr_add_bins(&c->acorr, c->src.pat.k, c->src.bins, c->src.weights) !=
                MCS_OK)
            return BENCH_FAILED;
    }
    return BENCH_OK;
}

size_t bench_reference_contenders(bench_contender *out)
{
    bench_contender draw = {"draw", &draw_ctx, 1u, draw_prepare, draw_run, NULL, NULL, 0.0, 0u};
    bench_contender dft = {"dft", &dft_state, 1u, dft_prepare, dft_run, NULL, NULL, 0.0, 0u};
    bench_contender acorr = {"autocorr", &autocorr_state, 1u, autocorr_prepare, autocorr_run,
                             NULL, NULL, 0.0, 0u};
    out[0] = draw;
    out[1] = dft;
    out[2] = acorr;
    return 3u;
}

int bench_pool_fill(bench_pool *pool, const bench_cell *cell)
{
    trial_source src;
    if (cell->n > BENCH_POOL_MAX_N || cell->k > BENCH_POOL_MAX_K ||
        source_prepare(&src, cell) != BENCH_OK)
        return BENCH_FAILED;
    pool->n = cell->n;
    pool->k = cell->k;
    for (size_t t = 0; t < BENCH_POOL_TRIALS; ++t) {
        if (source_draw(&src) != BENCH_OK)
            return BENCH_FAILED;
        memcpy(pool->bins[t], src.bins, cell->k * sizeof src.bins[0]);
        memcpy(pool->weights[t], src.weights, cell->k * sizeof src.weights[0]);
    }
    return BENCH_OK;
}

typedef struct {
    const bench_pool *pool;
    size_t next;
    mcs_moment acc;
} moment_ctx;

static moment_ctx moment_state;

static int moment_prepare(void *ctx, const bench_cell *cell)
{
    moment_ctx *c = ctx;
    if (c->pool->n != cell->n || c->pool->k != cell->k)
        return BENCH_FAILED;
    c->next = 0u;
    return mcs_moment_init(&c->acc, cell->n) == MCS_OK ? BENCH_OK : BENCH_FAILED;
}

static int moment_run(void *ctx, size_t calls)
{
    moment_ctx *c = ctx;
    for (size_t i = 0; i < calls; ++i) {
        if (mcs_moment_add_bins(&c->acc, c->pool->k, c->pool->bins[c->next],
                                c->pool->weights[c->next]) != MCS_OK)
            return BENCH_FAILED;
        c->next = (c->next + 1u) % BENCH_POOL_TRIALS;
    }
    return BENCH_OK;
}

static int moment_readout(void *ctx, size_t index, double *value, double *stderr_out)
{
    const moment_ctx *c = ctx;
    const size_t n = c->pool->n;
    mcs_status st = index < n * n ? mcs_moment_bin_second(&c->acc, index / n, index % n, value)
                                  : mcs_moment_bin_mean(&c->acc, index - n * n, value);
    *stderr_out = 0.0;
    return st == MCS_OK ? BENCH_OK : BENCH_FAILED;
}

bench_contender bench_moment_contender(const bench_pool *pool)
{
    moment_state.pool = pool;
    bench_contender c = {"mcs_moment", &moment_state, 1u, moment_prepare, moment_run, NULL,
                         moment_readout, 0.0, 0u};
    return c;
}
