/* Adversarial table: the object-free calls of the pair correlation and
 * the radial metrics (pcf.h's size query, radial.h). The accumulator's
 * calls are held to the same contract by test/measures/test_pcf.c
 * (NULLs, sizes 0 and max + 1, NaN and out-of-range points, aliasing,
 * uninitialised and edited headers, the object and its buffer compared
 * byte for byte after each refusal). */
#include "adv_table.h"

#include <stdarg.h>
#include <stdio.h>

#if defined(__GNUC__)
__attribute__((format(printf, 1, 2)))
#endif
static int broken(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(adv_note, sizeof adv_note, fmt, ap);
    va_end(ap);
    return ADV_BROKEN;
}

static int t_pcf_size(const adv_val *a)
{
    int st = mcs_pcf_size(a[0].z, a[1].p);
    return st == MCS_OK && *(size_t *)a[1].p != MCS_PCF_SIZE(a[0].z)
               ? broken("%zu bytes, not MCS_PCF_SIZE(bins)", *(size_t *)a[1].p)
               : st;
}
static int t_radial_effective_nyquist(const adv_val *a)
{
    return mcs_radial_effective_nyquist(a[0].z, a[1].z, a[2].z, a[3].p, a[4].d, a[5].p);
}
static int t_radial_oscillations(const adv_val *a)
{
    return mcs_radial_oscillations(a[0].z, a[1].z, a[2].z, a[3].p, a[4].d, a[5].p);
}

/* step: [MCS_RADIAL_MIN_STEP, MCS_RADIAL_MAX_STEP]. */
#define STEP                                                                              \
    {.name = "step", .kind = K_DBL, .role = R_RANGE, .dbase = 1.0,                        \
     .dlo = MCS_RADIAL_MIN_STEP, .dhi = MCS_RADIAL_MAX_STEP, .flags = 0}
#define RADIAL                                                                            \
    SZ_DEF("dim", 2, 1, 2, 0), SZ_NOMAX("k", 64), SZ_LEN("n", 64),                        \
        AIN("power", E_D, R_F, LEN(L_SLOT, 2), 0), STEP, OUT("out", E_D, O_NN, 0)

const adv_fn adv_fns_pcf[] = {
    FN(pcf_size, EF_NONE, 1, 0, SZ_DEF("bins", 16, 1, MCS_PCF_MAX_BINS, F_OKIN),
       OUT("bytes", E_Z, O_RAW, 0)),
    FN(radial_effective_nyquist, EF_NONE, 1, 0, RADIAL),
    FN(radial_oscillations, EF_NONE, 1, 0, RADIAL),
};
const size_t adv_fns_pcf_count = sizeof adv_fns_pcf / sizeof adv_fns_pcf[0];
