#include "peer_fftw.h"

#include <stddef.h>

#if defined(BENCH_HAVE_FFTW) && BENCH_HAVE_FFTW

#include <fftw3.h>
#include <math.h>
#include <string.h>

#include "mcspec/pattern.h"
#include "pcg32_ref.h"

#define FFTW_MAX_N 4096u
#define FFTW_MAX_K 256u
#define MAX_PLANS 8u

/* One plan per N, made once with FFTW_MEASURE and kept for the run. */
typedef struct {
    size_t n;
    fftw_plan plan;
    double *in;
    fftw_complex *out;
} fftw_slot;

typedef struct {
    fftw_slot *slot;
    size_t n, k;
    int stratified;
    pcg32_random_t rng;
    double scale; /* 1/sqrt(N), eq. 7 */
    double count;
    size_t bins[FFTW_MAX_K];
    double sum_re[FFTW_MAX_N / 2 + 1];
    double sum_im[FFTW_MAX_N / 2 + 1];
    double sum_pow[FFTW_MAX_N / 2 + 1];
    double sum_pow2[FFTW_MAX_N / 2 + 1];
} fftw_peer;

static fftw_slot slots[MAX_PLANS];
static size_t slot_count;
static fftw_peer peer;

static fftw_slot *slot_for(size_t n)
{
    for (size_t i = 0; i < slot_count; ++i)
        if (slots[i].n == n)
            return &slots[i];
    if (slot_count == MAX_PLANS)
        return NULL;
    fftw_slot *s = &slots[slot_count];
    s->in = fftw_alloc_real(n);
    s->out = fftw_alloc_complex(n / 2u + 1u);
    if (s->in == NULL || s->out == NULL)
        return NULL;
    s->plan = fftw_plan_dft_r2c_1d((int)n, s->in, s->out, FFTW_MEASURE);
    if (s->plan == NULL)
        return NULL;
    /* FFTW_MEASURE scribbled on the input; the trials keep it all zero
     * between transforms (r2c out of place preserves its input). */
    memset(s->in, 0, n * sizeof s->in[0]);
    s->n = n;
    ++slot_count;
    return s;
}

static int fftw_prepare(void *ctx, const bench_cell *cell)
{
    fftw_peer *p = ctx;
    if (cell->n > FFTW_MAX_N || cell->k > FFTW_MAX_K)
        return BENCH_FAILED;
    if (cell->kind != MCS_PATTERN_RANDOM && cell->kind != MCS_PATTERN_STRATIFIED)
        return BENCH_FAILED;
    p->slot = slot_for(cell->n);
    if (p->slot == NULL)
        return BENCH_FAILED;
    p->n = cell->n;
    p->k = cell->k;
    p->stratified = cell->kind == MCS_PATTERN_STRATIFIED;
    pcg32_srandom_r(&p->rng, cell->seed, 13u);
    p->scale = 1.0 / sqrt((double)cell->n);
    p->count = 0.0;
    memset(p->sum_re, 0, sizeof p->sum_re);
    memset(p->sum_im, 0, sizeof p->sum_im);
    memset(p->sum_pow, 0, sizeof p->sum_pow);
    memset(p->sum_pow2, 0, sizeof p->sum_pow2);
    return BENCH_OK;
}

/* K bins into p->bins and the dense s: random, one bounded draw per sample;
 * stratified, bin floor((j + u) N / K) with u = r / 2^32. */
static void draw_into(fftw_peer *p, double *in)
{
    const size_t n = p->n, k = p->k;
    if (p->stratified) {
        const double step = (double)n / (double)k;
        for (size_t j = 0; j < k; ++j) {
            double u = (double)pcg32_random_r(&p->rng) * (1.0 / 4294967296.0);
            size_t b = (size_t)(((double)j + u) * step);
            p->bins[j] = b < n ? b : n - 1u;
        }
    } else {
        for (size_t j = 0; j < k; ++j)
            p->bins[j] = pcg32_boundedrand_r(&p->rng, (uint32_t)n);
    }
    for (size_t j = 0; j < k; ++j)
        in[p->bins[j]] += 1.0;
}

static void one_trial(fftw_peer *p)
{
    fftw_slot *s = p->slot;
    draw_into(p, s->in);
    fftw_execute(s->plan);
    for (size_t j = 0; j < p->k; ++j)
        s->in[p->bins[j]] = 0.0;
    const size_t h1 = p->n / 2u + 1u;
    const double scale = p->scale;
    for (size_t q = 0; q < h1; ++q) {
        const double re = s->out[q][0] * scale, im = s->out[q][1] * scale;
        const double pw = re * re + im * im;
        p->sum_re[q] += re;
        p->sum_im[q] += im;
        p->sum_pow[q] += pw;
        p->sum_pow2[q] += pw * pw;
    }
    p->count += 1.0;
}

static int fftw_run(void *ctx, size_t calls)
{
    for (size_t i = 0; i < calls; ++i)
        one_trial(ctx);
    return BENCH_OK;
}

/* <|S_k|^2> and its standard error from the sums of |S_k|^2 and |S_k|^4. */
static int fftw_readout(void *ctx, size_t freq, double *value, double *stderr_out)
{
    const fftw_peer *p = ctx;
    if (p->count < 2.0)
        return BENCH_FAILED;
    size_t q = freq <= p->n / 2u ? freq : p->n - freq;
    double t = p->count, mean = p->sum_pow[q] / t;
    double var = (p->sum_pow2[q] - t * mean * mean) / (t - 1.0);
    *value = mean;
    *stderr_out = sqrt((var > 0.0 ? var : 0.0) / t);
    return BENCH_OK;
}

int bench_fftw_available(void)
{
    return 1;
}

const char *bench_fftw_version(void)
{
    return fftw_version;
}

bench_contender bench_fftw_contender(void)
{
    bench_contender c = {"FFTW", &peer, 1u, fftw_prepare, fftw_run, NULL, fftw_readout, 0.0, 0u};
    return c;
}

void bench_fftw_cleanup(void)
{
    for (size_t i = 0; i < slot_count; ++i) {
        fftw_destroy_plan(slots[i].plan);
        fftw_free(slots[i].in);
        fftw_free(slots[i].out);
    }
    slot_count = 0u;
    fftw_cleanup();
}

#else /* no FFTW in this build */

static int fftw_unavailable(void *ctx, const bench_cell *cell)
{
    (void)ctx;
    (void)cell;
    return BENCH_UNAVAILABLE;
}

int bench_fftw_available(void)
{
    return 0;
}

const char *bench_fftw_version(void)
{
    return "not available";
}

bench_contender bench_fftw_contender(void)
{
    bench_contender c = {"FFTW", NULL, 1u, fftw_unavailable, NULL, NULL, NULL, 0.0, 0u};
    return c;
}

void bench_fftw_cleanup(void)
{
}

#endif
