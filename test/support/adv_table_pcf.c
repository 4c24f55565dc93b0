/* Adversarial table: the pair correlation (pcf.h; its accumulator is
 * T_PCF, an mcs_pcf over a buffer inside the object, adv_objects.c) and
 * the radial metrics (radial.h). */
#include "adv_table.h"

#include <float.h>
#include <math.h>
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
/* After a success every bin of an accumulator with sets reads out finite. */
static int pcf_sound(int st, const mcs_pcf *acc)
{
    if (st != MCS_OK || acc == NULL)
        return st;
    uint64_t n = 0;
    if (mcs_pcf_count(acc, &n) != MCS_OK)
        return broken("count refused after MCS_OK");
    for (size_t b = 0; b < acc->bins && n > 0u; ++b) {
        double m = NAN, se = NAN;
        if (mcs_pcf_mean(acc, b, &m) != MCS_OK || !(isfinite(m) && m >= 0.0))
            return broken("bin %zu mean %.17g", b, m);
        if (n > 1u && (mcs_pcf_stderr(acc, b, &se) != MCS_OK || !(isfinite(se) && se >= 0.0)))
            return broken("bin %zu stderr %.17g", b, se);
    }
    return st;
}

static int t_pcf_init(const adv_val *a)
{
    return pcf_sound(mcs_pcf_init(a[0].p, a[1].z, (mcs_pcf_estimator)a[2].e, a[3].z, a[4].d, a[5].d,
                                  a[6].p, a[7].z),
                     a[0].p);
}
static int t_pcf_work_size(const adv_val *a)
{
    int st = mcs_pcf_work_size(a[0].p, a[1].z, a[2].p);
    return st == MCS_OK && *(size_t *)a[2].p > MCS_PCF_WORK_SIZE(a[1].z)
               ? broken("%zu bytes, above MCS_PCF_WORK_SIZE(k)", *(size_t *)a[2].p)
               : st;
}
static int t_pcf_add(const adv_val *a)
{
    return pcf_sound(mcs_pcf_add(a[0].p, a[1].z, a[2].p, a[3].p, a[4].z), a[0].p);
}
static int t_pcf_merge(const adv_val *a) { return pcf_sound(mcs_pcf_merge(a[0].p, a[1].p), a[0].p); }
static int t_pcf_count(const adv_val *a) { return mcs_pcf_count(a[0].p, a[1].p); }
static int t_pcf_radius_at(const adv_val *a) { return mcs_pcf_radius_at(a[0].p, a[1].z, a[2].p); }
static int t_pcf_mean(const adv_val *a) { return mcs_pcf_mean(a[0].p, a[1].z, a[2].p); }
static int t_pcf_stderr(const adv_val *a) { return mcs_pcf_stderr(a[0].p, a[1].z, a[2].p); }
static int t_pcf_read_all(const adv_val *a)
{
    return mcs_pcf_read_all(a[0].p, a[1].z, a[2].p, a[3].p, a[4].p);
}
static int t_pcf_power(const adv_val *a) { return mcs_pcf_power(a[0].p, a[1].d, a[2].p); }
static int t_pcf_exact(const adv_val *a) { return mcs_pcf_exact(a[0].p, a[1].p, a[2].z, a[3].p); }

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

#define ANY_POSITIVE(nm, b)                                                               \
    {.name = nm, .kind = K_DBL, .role = R_RANGE, .dbase = b, .dlo = DBL_TRUE_MIN, .dhi = DBL_MAX, \
     .flags = 0}
#define FREQ                                                                              \
    {.name = "freq", .kind = K_DBL, .role = R_RANGE, .dbase = 3.0, .dlo = 0.0,            \
     .dhi = MCS_PCF_MAX_FREQ, .flags = F_OKIN}
#define ACC_IN OBJ_IN("acc", T_PCF, 0)
#define BIN SZ_INDEX("bin", 0, 0, 7, F_OKIN)
#define LONG_K(lo_)                                                                       \
    {.name = "k", .kind = K_SIZE, .role = Z_LEN, .base = ADV_LONG_LEN, .lo = lo_, .hi = SIZE_MAX, \
     .flags = F_OKIN}

const adv_fn adv_fns_pcf[] = {
    FN(pcf_size, EF_NONE, 1, 0, SZ_DEF("bins", 16, 1, MCS_PCF_MAX_BINS, F_OKIN),
       OUT("bytes", E_Z, O_RAW, 0)),
    FN(pcf_init, EF_INIT, 1, 0, OBJ_OUT("acc", T_PCF), SZ_DEF("dim", 2, 1, 2, F_OKIN),
       ENM("estimator", 1, 0, 1, F_OKIN), SZ_DEF("bins", 8, 1, MCS_PCF_MAX_BINS, 0),
       ANY_POSITIVE("radius", 0.5), ANY_POSITIVE("sigma", 0.01), MEM(7),
       SZ_LEN("bytes", MCS_PCF_SIZE(8))),
    FN(pcf_work_size, EF_NONE, 1, 0, ACC_IN, SZ_NOMAX("k", 64), OUT("bytes", E_Z, O_RAW, 0)),
    FN(pcf_add, EF_ADD, 1, 0, OBJ_IO("acc", T_PCF, 0), LONG_K(2),
       AIN("points", E_D, R_POINT, LEN(L_OBJNN, 0), 0), AOUT("work", E_U8, O_RAW, LEN(L_SLOT, 4), 0),
       SZ_LEN("work_bytes", MCS_PCF_WORK_SIZE(ADV_LONG_LEN))),
    FN(pcf_merge, EF_MERGE, 1, 0, OBJ_IO("dst", T_PCF, 0), OBJ_IN("src", T_PCF, F_SIZED)),
    FN(pcf_count, EF_NONE, 1, 0, ACC_IN, OUT("count", E_U64, O_RAW, 0)),
    FN(pcf_radius_at, EF_NONE, 1, 0, ACC_IN, BIN, OUT("out", E_D, O_NN, 0)),
    FN(pcf_mean, EF_NONE, 1, 0, ACC_IN, BIN, OUT("out", E_D, O_NN, 0)),
    FN(pcf_stderr, EF_NONE, 1, 0, ACC_IN, BIN, OUT("out", E_D, O_NN, 0)),
    FN(pcf_read_all, EF_NONE, 1, 0, ACC_IN, SZ_MATCH("bins", 8, 8),
       AOUT("radius", E_D, O_NN, LEN(L_SLOT, 1), F_NULLOK),
       AOUT("mean", E_D, O_NN, LEN(L_SLOT, 1), F_NULLOK),
       AOUT("stderr", E_D, O_NN, LEN(L_SLOT, 1), F_NULLOK)),
    FN(pcf_power, EF_NONE, 1, 0, ACC_IN, FREQ, OUT("out", E_D, O_VAL, 0)),
    FN(pcf_exact, EF_NONE, 1, 0, ACC_IN, OBJ_IN("pat", T_PAT2D, F_NULLOK), BIN,
       OUT("out", E_D, O_NN, 0)),
    FN(radial_effective_nyquist, EF_NONE, 1, 0, RADIAL),
    FN(radial_oscillations, EF_NONE, 1, 0, RADIAL),
};
const size_t adv_fns_pcf_count = sizeof adv_fns_pcf / sizeof adv_fns_pcf[0];
