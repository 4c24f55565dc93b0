/* Benchmark of the spectrum accumulator and the autocorrelation (moment
 * power) path against their floors, all measured in this run:
 *   draw      mcs_pattern_draw alone
 *   fft       one bare kiss_fftr of size N (the real transform, KissFFT's own)
 *   spectrum  draw + mcs_spectrum_add_bins (automatic path)
 *   sparse    draw + mcs_spectrum_add_bins forced to the sparse path
 *   fftpath   draw + mcs_spectrum_add_bins forced to the FFT path
 *   autocorr  draw + mcs_autocorr_add_bins (the moment power path)
 * Ratios: spec/(draw+fft) (target <= 1.5 at N >= 256) and autocorr/spec
 * (target < 1 where K^2 < N log2 N). Times are per trial. */
#define _POSIX_C_SOURCE 199309L

#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "kiss_fftr.h"
#include "mcspec.h"

#define MEASURE_SECONDS 0.02
#define ROUNDS 5 /* best of, rounds interleaved over the jobs: other processes
                  only ever slow a run down, and alike for every job */

static mcs_spectrum spec;
static mcs_autocorr acorr;
static size_t bins[64];
static double weights[64];
static double kiss_mem[16384];
static double fft_in[4096];
static kiss_fft_cpx fft_out[2049];

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

typedef enum { JOB_DRAW, JOB_FFT, JOB_SPECTRUM, JOB_AUTOCORR } job_kind;

typedef struct {
    job_kind kind;
    const mcs_pattern *pat;
    mcs_rng *rng;
    kiss_fftr_cfg cfg;
} job;

static int run_once(const job *jb)
{
    size_t k = jb->pat->k;
    switch (jb->kind) {
    case JOB_DRAW:
        return mcs_pattern_draw(jb->pat, jb->rng, k, bins, weights, NULL) != MCS_OK;
    case JOB_FFT:
        kiss_fftr(jb->cfg, fft_in, fft_out);
        return 0;
    case JOB_SPECTRUM:
        return mcs_pattern_draw(jb->pat, jb->rng, k, bins, weights, NULL) != MCS_OK ||
               mcs_spectrum_add_bins(&spec, k, bins, weights) != MCS_OK;
    case JOB_AUTOCORR:
        return mcs_pattern_draw(jb->pat, jb->rng, k, bins, weights, NULL) != MCS_OK ||
               mcs_autocorr_add_bins(&acorr, k, bins, weights) != MCS_OK;
    }
    return 1;
}

/* Seconds per call, over batches until MEASURE_SECONDS have passed. */
static double per_call_once(const job *jb)
{
    unsigned long calls = 0;
    unsigned long batch = 16;
    double t0 = now(), t;
    for (;;) {
        for (unsigned long i = 0; i < batch; ++i)
            if (run_once(jb)) {
                fprintf(stderr, "bench: a call failed\n");
                return NAN;
            }
        calls += batch;
        t = now() - t0;
        if (t >= MEASURE_SECONDS)
            break;
        if (batch < 4096)
            batch *= 2;
    }
    return t / (double)calls;
}

int main(void)
{
    static const size_t ns[] = {64u, 256u, 1024u, 4096u};
    static const size_t ks[] = {8u, 64u};
    static const mcs_pattern_kind kinds[] = {MCS_PATTERN_STRATIFIED, MCS_PATTERN_RANDOM};
    mcs_rng rng;
    mcs_rng_seed(&rng, 2024u, 7u);
    for (size_t i = 0; i < 4096u; ++i)
        fft_in[i] = (double)(i % 7u);

    printf("mcspec spectra bench: microseconds per trial; ratios from the same run\n");
    printf("%-10s %5s %3s | %7s %7s | %8s %7s %7s %8s | %13s %13s | %s\n", "pattern", "N", "K",
           "draw", "fft", "spectrum", "sparse", "fftpath", "autocorr", "spec/(d+fft)",
           "autoc/spec", "spectrum path, trials/s spectrum, autocorr");
    int all_ok = 1;
    for (size_t ik = 0; ik < 2; ++ik) {
        for (size_t in = 0; in < 4; ++in) {
            for (size_t iK = 0; iK < 2; ++iK) {
                size_t n = ns[in], k = ks[iK];
                mcs_pattern pat;
                if (mcs_pattern_init(&pat, kinds[ik], n, k, NULL) != MCS_OK)
                    return 1;
                size_t len = sizeof kiss_mem;
                kiss_fftr_cfg cfg = kiss_fftr_alloc((int)n, 0, kiss_mem, &len);
                if (cfg == NULL) {
                    fprintf(stderr, "bench: kiss_fftr state too large\n");
                    return 1;
                }
                /* draw, fft, spectrum (auto), sparse, fft path, autocorr */
                static const job_kind kinds_of[6] = {JOB_DRAW, JOB_FFT, JOB_SPECTRUM,
                                                     JOB_SPECTRUM, JOB_SPECTRUM, JOB_AUTOCORR};
                static const mcs_spectrum_path paths[6] = {
                    MCS_SPECTRUM_PATH_AUTO, MCS_SPECTRUM_PATH_AUTO, MCS_SPECTRUM_PATH_AUTO,
                    MCS_SPECTRUM_PATH_SPARSE, MCS_SPECTRUM_PATH_FFT, MCS_SPECTRUM_PATH_AUTO};
                double best[6];
                for (int r = 0; r < ROUNDS; ++r) {
                    for (int m = 0; m < 6; ++m) {
                        job jb = {kinds_of[m], &pat, &rng, cfg};
                        mcs_spectrum_init(&spec, n);
                        mcs_spectrum_set_path(&spec, paths[m]);
                        mcs_autocorr_init(&acorr, n);
                        double t = per_call_once(&jb);
                        best[m] = (r == 0 || t < best[m]) ? t : best[m];
                    }
                }
                double t_draw = best[0], t_fft = best[1], t_spec = best[2];
                double t_sparse = best[3], t_fftpath = best[4], t_auto = best[5];
                mcs_spectrum_init(&spec, n);
                const char *chosen = k <= spec.sparse_max_k ? "sparse" : "fft";
                double r_spec = t_spec / (t_draw + t_fft);
                double r_auto = t_auto / t_spec;
                double nlog = (double)n * log2((double)n);
                int spec_target = n < 256u || r_spec <= 1.5;
                int auto_target = !((double)(k * k) < nlog) || r_auto < 1.0;
                all_ok &= spec_target && auto_target;
                printf("%-10s %5zu %3zu | %7.3f %7.3f | %8.3f %7.3f %7.3f %8.3f | %6.2f %-6s "
                       "%6.2f %-6s | %-6s %9.0f %9.0f\n",
                       mcs_pattern_kind_str(kinds[ik]), n, k, 1e6 * t_draw, 1e6 * t_fft,
                       1e6 * t_spec, 1e6 * t_sparse, 1e6 * t_fftpath, 1e6 * t_auto, r_spec,
                       n < 256u ? "(n/a)" : (r_spec <= 1.5 ? "ok" : "MISS"), r_auto,
                       (double)(k * k) < nlog ? (r_auto < 1.0 ? "ok" : "MISS") : "(n/a)",
                       chosen, 1.0 / t_spec, 1.0 / t_auto);
            }
        }
    }
    printf("targets: spectrum <= 1.5 x (draw + fft) at N >= 256; autocorr faster than "
           "spectrum where K^2 < N log2 N: %s\n",
           all_ok ? "all met" : "NOT all met");
    return 0;
}
