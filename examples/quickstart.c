/* The README's quick start, compiled and run: a renderer's own sample
 * positions and mcspec's stratified pattern into spectrum accumulators,
 * read back with standard errors beside the exact prediction. */
#include "mcspec.h"

#include <stdio.h>

#define N 256
#define K 16

/* Big state lives in static storage (or the caller's arena), never on the stack. */
static mcs_spectrum acc;
static mcs_spectrum mine;

/* A renderer's own sampler: a rank-1 lattice shifted per pixel. */
static void my_samples(unsigned pixel, double *x)
{
    double shift = (double)((pixel * 2654435761u) % 1000u) / 1000.0;
    for (unsigned j = 0; j < K; ++j) {
        double v = (double)j / K + shift;
        x[j] = v - (double)(unsigned)v;
    }
}

int main(void)
{
    mcs_rng rng;
    mcs_pattern pat;
    size_t bins[K];
    double weights[K], x[K];

    if (mcs_rng_seed(&rng, 42u, 54u) != MCS_OK ||
        mcs_pattern_init(&pat, MCS_PATTERN_STRATIFIED, N, K, NULL) != MCS_OK ||
        mcs_spectrum_init(&acc, N) != MCS_OK || mcs_spectrum_init(&mine, N) != MCS_OK)
        return 1;

    for (unsigned t = 0; t < 20000u; ++t) {
        /* mcspec's pattern ... */
        mcs_pattern_draw(&pat, &rng, K, bins, weights, NULL);
        mcs_spectrum_add_bins(&acc, K, bins, weights);
        /* ... and the renderer's own points, binned into the same (bin, weight) form. */
        my_samples(t, x);
        mcs_pattern_bin_points(N, K, NULL, x, bins, weights);
        mcs_spectrum_add_bins(&mine, K, bins, weights);
    }

    printf("freq   stratified <|S_k|^2>      exact (eq. 33, finite N)   renderer lattice (eq. 37)\n");
    const size_t freqs[5] = {1u, 8u, 16u, 17u, 128u};
    for (int i = 0; i < 5; ++i) {
        double p, se, exact, q, qse;
        mcs_spectrum_power(&acc, freqs[i], &p);
        mcs_spectrum_power_stderr(&acc, freqs[i], &se);
        mcs_spectrum_power(&mine, freqs[i], &q);
        mcs_spectrum_power_stderr(&mine, freqs[i], &qse);
        /* K divides N here, so the exact finite-N form of eq. 33 applies. */
        mcs_status st = mcs_eq33_stratified_power_exact(N, K, freqs[i], &exact);
        printf("%4zu   %.5f +- %.5f   %14.5f              %.5f +- %.5f  %s\n", freqs[i], p, se, exact, q,
               qse, st == MCS_OK ? "" : mcs_status_str(st));
    }
    /* A failed call says why and changes nothing. */
    mcs_status st = mcs_spectrum_add_bins(&acc, 0u, bins, weights);
    printf("adding a trial of 0 samples: %s\n", mcs_status_str(st));
    return 0;
}
