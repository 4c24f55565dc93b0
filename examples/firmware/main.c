/* mcspec on a Cortex-M. Three runs, each into static accumulators, their
 * results left in volatiles for a debugger to read; then it idles. No heap,
 * no stdio: everything lives in .bss.
 *  1. stratified trials over N = 256 bins into an mcs_spectrum: <|S_1|^2>;
 *  2. a 4 x 4 jittered 2D pattern into the unbinned 2D point-set spectrum
 *     (annulus average at radius 2) and the binned one on 8 x 8 bins
 *     (<|S_(1,1)|^2>), each beside its exact value from the library;
 *  3. a Cranley-Patterson rotated van der Corput set of 16 points into the
 *     1D point-set spectrum: <P(16)> = 16 and <P(1)> = 0 (uniform jitter).
 * Built by `make cross` (mk/cross.mk) with the library at FW_DEFS
 * (MCS_MAX_N = 256 for the mcs_spectrum). The point-set and 2D spectra take
 * their sizes at run time over caller memory: here static buffers of the
 * exact size, from the constant size macros, without the NUFFT's memory
 * (MCS_POINTSET_DIRECT_ONLY: sets of 16 points never need it). */
#include <stddef.h>
#include <stdint.h>
#include "mcspec.h"

#define FW_N 256u     /* bins N */
#define FW_K 16u      /* samples per trial K (divides N) */
#define FW_TRIALS 64u /* trials per run */
#define FW_STRATA 4u  /* 2D: FW_STRATA x FW_STRATA jittered cells */
#define FW_K2 16u     /* = FW_STRATA * FW_STRATA points per 2D trial */
#define FW_FREQ 8u    /* 2D point-set cutoff F */
#define FW_FREQ_1D 32u /* 1D point-set cutoff */
#define FW_SIDE 8u    /* bins per side of the binned 2D spectrum */

#if FW_K2 != FW_STRATA * FW_STRATA
#error "FW_K2 must be FW_STRATA squared"
#endif

int main(void);

/* Sizes at FW_DEFS on Cortex-M (make sizes; the buffers' from the macros). */
static mcs_spectrum spectrum;     /* 26 264 B */
static mcs_pointset2d pointset2d; /* header 144 B */
static mcs_spectrum2d spectrum2d; /* header 76 B */
static mcs_pointset pointset;     /* header 136 B */
static unsigned char pointset2d_mem[MCS_POINTSET2D_SIZE_DIRECT(FW_FREQ)]; /* 8 063 B */
static unsigned char spectrum2d_mem[MCS_SPECTRUM2D_SIZE(FW_SIDE, FW_SIDE)]; /* 3 647 B */
static unsigned char pointset_mem[MCS_POINTSET_SIZE_DIRECT(FW_FREQ_1D)];  /* 3 967 B */
static mcs_pattern pattern;
static mcs_pattern2d pattern2d;
static mcs_sampler sampler;
static mcs_rng rng;
static size_t bins[FW_K];
static double weights[FW_K];
static double points[2u * FW_K2];

/* Read back with a debugger: status of the runs (the first error, or 0) and
 * the measured values beside their exact ones. fw_power_k1 is to compare
 * with K/N - (K/N)^3 sin^2(pi/K) / sin^2(pi/N). */
volatile int32_t fw_status;
volatile double fw_power_k1;
volatile uint32_t fw_trials;
volatile double fw_radial_r2, fw_radial_r2_exact;
volatile double fw_binned_power_k11, fw_binned_power_k11_exact;
volatile double fw_comb_power_f16, fw_comb_power_f1;

static mcs_status run_1d_bins(void)
{
    mcs_status st = mcs_pattern_init(&pattern, MCS_PATTERN_STRATIFIED, FW_N, FW_K, NULL);
    if (st == MCS_OK)
        st = mcs_spectrum_init(&spectrum, FW_N);
    for (uint32_t t = 0u; t < FW_TRIALS && st == MCS_OK; ++t) {
        st = mcs_pattern_draw(&pattern, &rng, FW_K, bins, weights, NULL);
        if (st == MCS_OK)
            st = mcs_spectrum_add_bins(&spectrum, FW_K, bins, weights);
        if (st == MCS_OK)
            fw_trials = t + 1u;
    }
    double power = 0.0;
    if (st == MCS_OK)
        st = mcs_spectrum_power(&spectrum, 1u, &power);
    fw_power_k1 = power;
    return st;
}

/* One 2D pattern, two spectra: unbinned (point set) and binned. */
static mcs_status run_2d_points(void)
{
    mcs_status st = mcs_pattern2d_init(&pattern2d, MCS_PATTERN2D_JITTERED, FW_K2, FW_STRATA,
                                       FW_STRATA);
    if (st == MCS_OK)
        st = mcs_pointset2d_init(&pointset2d, FW_FREQ, MCS_POINTSET_DIRECT_ONLY, pointset2d_mem,
                                 sizeof pointset2d_mem);
    if (st == MCS_OK)
        st = mcs_spectrum2d_init(&spectrum2d, FW_SIDE, FW_SIDE, spectrum2d_mem,
                                 sizeof spectrum2d_mem);
    for (uint32_t t = 0u; t < FW_TRIALS && st == MCS_OK; ++t) {
        st = mcs_pattern2d_draw(&pattern2d, &rng, FW_K2, points);
        if (st == MCS_OK)
            st = mcs_pointset2d_add(&pointset2d, FW_K2, points);
        if (st == MCS_OK)
            st = mcs_spectrum2d_add_points(&spectrum2d, FW_K2, points, NULL);
    }
    double v[4] = {0.0, 0.0, 0.0, 0.0};
    if (st == MCS_OK)
        st = mcs_pointset2d_radial(&pointset2d, 2u, &v[0]);
    if (st == MCS_OK)
        st = mcs_pointset2d_exact_radial(&pattern2d, 2u, &v[1]);
    if (st == MCS_OK)
        st = mcs_spectrum2d_power(&spectrum2d, 1u, 1u, &v[2]);
    if (st == MCS_OK)
        st = mcs_spectrum2d_exact_power(&pattern2d, FW_SIDE, FW_SIDE, 1u, 1u, &v[3]);
    fw_radial_r2 = v[0];
    fw_radial_r2_exact = v[1];
    fw_binned_power_k11 = v[2];
    fw_binned_power_k11_exact = v[3];
    return st;
}

/* A rotated van der Corput set of 2^4 points is uniform jitter: its
 * periodogram is the comb K at multiples of K and 0 elsewhere, every trial. */
static mcs_status run_1d_sampler(void)
{
    mcs_status st = mcs_sampler_init(&sampler, MCS_SAMPLER_VAN_DER_CORPUT, 1u, FW_K);
    if (st == MCS_OK)
        st = mcs_pointset_init(&pointset, FW_FREQ_1D, MCS_POINTSET_DIRECT_ONLY, pointset_mem,
                               sizeof pointset_mem);
    for (uint32_t t = 0u; t < FW_TRIALS && st == MCS_OK; ++t) {
        st = mcs_sampler_draw(&sampler, &rng, FW_K, points);
        if (st == MCS_OK)
            st = mcs_pointset_add(&pointset, FW_K, points);
    }
    double p16 = 0.0, p1 = 0.0;
    if (st == MCS_OK)
        st = mcs_pointset_power(&pointset, (long)FW_K, &p16);
    if (st == MCS_OK)
        st = mcs_pointset_power(&pointset, 1, &p1);
    fw_comb_power_f16 = p16;
    fw_comb_power_f1 = p1;
    return st;
}

static mcs_status run(void)
{
    mcs_status st = mcs_rng_seed(&rng, 0x853c49e6748fea9bu, 0xda3e39cb94b95bdbu);
    if (st == MCS_OK)
        st = run_1d_bins();
    if (st == MCS_OK)
        st = run_2d_points();
    if (st == MCS_OK)
        st = run_1d_sampler();
    return st;
}

int main(void)
{
    fw_status = (int32_t)run();
    for (;;) {
        __asm__ volatile("wfi");
    }
}
