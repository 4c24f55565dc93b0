/* mcspec on a Cortex-M: draws stratified trials over N = 256 bins into a
 * static spectrum accumulator, stores <|S_1|^2> in a volatile for a debugger
 * to read, then idles. No heap, no stdio: everything lives in .bss.
 * Built by `make cross` (mk/cross.mk) with the library at -DMCS_MAX_N=256. */
#include <stddef.h>
#include <stdint.h>
#include "mcspec.h"

#define FW_N 256u     /* bins N */
#define FW_K 16u      /* samples per trial K (divides N) */
#define FW_TRIALS 64u /* trials per run */

int main(void);

static mcs_spectrum spectrum; /* 26 264 B (26 KiB) at MCS_MAX_N = 256: make sizes */
static mcs_pattern pattern;
static mcs_rng rng;
static size_t bins[FW_K];
static double weights[FW_K];

/* Read back with a debugger: status of the run and the measured power at
 * k = 1, to compare with K/N - (K/N)^3 sin^2(pi/K) / sin^2(pi/N). */
volatile int32_t fw_status;
volatile double fw_power_k1;
volatile uint32_t fw_trials;

static mcs_status run(void)
{
    mcs_status st = mcs_rng_seed(&rng, 0x853c49e6748fea9bu, 0xda3e39cb94b95bdbu);
    if (st == MCS_OK)
        st = mcs_pattern_init(&pattern, MCS_PATTERN_STRATIFIED, FW_N, FW_K, NULL);
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

int main(void)
{
    fw_status = (int32_t)run();
    for (;;) {
        __asm__ volatile("wfi");
    }
}
