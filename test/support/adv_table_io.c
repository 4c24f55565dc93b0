/* Adversarial table: records (io.h) and exact spectra at any N
 * (mcs_theory_spectrum, theory.h). */
#include "adv_table.h"

#include <stdio.h>
#include <string.h>

/* A successful save must load back (io.h: "every record save writes loads
 * back"); the record is loaded into a scratch object of the same type. */
static int loads_back(int st, int type, const void *buf, const size_t *len)
{
    static _Alignas(64) unsigned char scratch[sizeof(mcs_spectrum)];
    if (st != MCS_OK || buf == NULL)
        return st;
    int back;
    switch (type) {
    case T_WELFORD: back = mcs_io_load_welford((void *)scratch, *len, buf); break;
    case T_SPECTRUM: back = mcs_io_load_spectrum((void *)scratch, *len, buf); break;
    case T_MOMENT: back = mcs_io_load_moment((void *)scratch, *len, buf); break;
    case T_AUTOCORR: back = mcs_io_load_autocorr((void *)scratch, *len, buf); break;
    case T_POINTSET: back = mcs_io_load_pointset((void *)scratch, *len, buf); break;
    case T_POINTSET2D: back = mcs_io_load_pointset2d((void *)scratch, *len, buf); break;
    default: back = mcs_io_load_spectrum2d((void *)scratch, *len, buf); break;
    }
    if (back == MCS_OK)
        return MCS_OK;
    snprintf(adv_note, sizeof adv_note, "the saved record does not load back (%s)",
             mcs_status_str((mcs_status)back));
    return ADV_BROKEN;
}

#define SAVE_THUNK(sfx, T)                                                          \
    static int t_io_save_##sfx(const adv_val *a)                                    \
    {                                                                               \
        return loads_back(mcs_io_save_##sfx(a[0].p, a[1].z, a[2].p, a[3].p), T, a[2].p, a[3].p); \
    }
#define LOAD_THUNK(sfx) \
    static int t_io_load_##sfx(const adv_val *a) { return mcs_io_load_##sfx(a[0].p, a[1].z, a[2].p); }
SAVE_THUNK(spectrum, T_SPECTRUM) SAVE_THUNK(moment, T_MOMENT) SAVE_THUNK(autocorr, T_AUTOCORR)
SAVE_THUNK(welford, T_WELFORD) SAVE_THUNK(pointset, T_POINTSET)
SAVE_THUNK(pointset2d, T_POINTSET2D) SAVE_THUNK(spectrum2d, T_SPECTRUM2D)
LOAD_THUNK(spectrum) LOAD_THUNK(moment) LOAD_THUNK(autocorr) LOAD_THUNK(welford)
LOAD_THUNK(pointset) LOAD_THUNK(pointset2d) LOAD_THUNK(spectrum2d)

static int t_io_peek(const adv_val *a) { return mcs_io_peek(a[0].z, a[1].p, a[2].p); }
static int t_io_crc32(const adv_val *a) { return mcs_io_crc32(a[0].z, a[1].p, a[2].p); }
static int t_io_kind_str(const adv_val *a)
{
    const char *s = mcs_io_kind_str(a[0].u32);
    int known = a[0].u32 >= MCS_IO_KIND_SPECTRUM && a[0].u32 <= MCS_IO_KIND_SPECTRUM2D;
    return s != NULL && known == (strcmp(s, "unknown") != 0) ? MCS_OK : ADV_BROKEN;
}
static int t_theory_spectrum_init(const adv_val *a) { return mcs_theory_spectrum_init(a[0].p, a[1].p); }
static int t_theory_spectrum_mean(const adv_val *a) { return mcs_theory_spectrum_mean(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_theory_spectrum_power(const adv_val *a) { return mcs_theory_spectrum_power(a[0].p, a[1].z, a[2].p); }
static int t_theory_power_spectrum(const adv_val *a) { return mcs_theory_power_spectrum(a[0].p, a[1].z, a[2].p); }
static int t_theory_spectrum_cross(const adv_val *a) { return mcs_theory_spectrum_cross(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_theory_spectrum_covariance(const adv_val *a) { return mcs_theory_spectrum_covariance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_theory_spectrum_estimator_mean(const adv_val *a) { return mcs_theory_spectrum_estimator_mean(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_theory_spectrum_variance(const adv_val *a) { return mcs_theory_spectrum_variance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_theory_spectrum_estimator_covariance(const adv_val *a)
{
    return mcs_theory_spectrum_estimator_covariance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p, a[5].p);
}

static const uint8_t pattern_vars[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8};

#define INFO_LEN {.op = L_CONST, .c = sizeof(mcs_io_info)}
#define CAP 16384u /* holds the record of every baseline object */
#define SAVE(sfx, T)                                                                       \
    FN(io_save_##sfx, EF_NONE, 1, 0, OBJ_IN("acc", T, 0), SZ_LEN("cap", CAP),              \
       AOUT("buf", E_U8, O_RAW, LEN(L_SLOT, 1), F_NULLOK), OUT("len", E_Z, O_RAW, 0))
#define LOAD(sfx, T)                                                                        \
    FN(io_load_##sfx, EF_NONE, 1, 0, OBJ_OUT("acc", T),                                     \
       {.name = "len", .kind = K_SIZE, .role = Z_REC, .type = T},                           \
       AIN("buf", E_U8, R_RECORD, LEN(L_REC, T), 0))
#define TS_IN OBJ_IN("ts", T_TSPEC, 0)
#define TS_SIZED OBJ_IN("ts", T_TSPEC, F_SIZED)
#define FREQ(nm, b) SZ_INDEX(nm, b, 0, BN - 1u, F_OKIN)
#define OUT_VAL(nm) OUT(nm, E_D, O_VAL, 0)
#define OUT_NN(nm) OUT(nm, E_D, O_NN, 0)
#define N_MATCH SZ_MATCH("n", BN, MCS_MAX_N)
#define K_MATCH SZ_MATCH("k", BK, SIZE_MAX)
#define F_OF(nm) AIN(nm, E_D, R_F, LEN(L_SLOT, 1), 0)

const adv_fn adv_fns_io[] = {
    SAVE(spectrum, T_SPECTRUM), SAVE(moment, T_MOMENT), SAVE(autocorr, T_AUTOCORR),
    SAVE(welford, T_WELFORD), SAVE(pointset, T_POINTSET), SAVE(pointset2d, T_POINTSET2D),
    SAVE(spectrum2d, T_SPECTRUM2D),
    LOAD(spectrum, T_SPECTRUM), LOAD(moment, T_MOMENT), LOAD(autocorr, T_AUTOCORR),
    LOAD(welford, T_WELFORD), LOAD(pointset, T_POINTSET), LOAD(pointset2d, T_POINTSET2D),
    LOAD(spectrum2d, T_SPECTRUM2D),
    FN(io_peek, EF_NONE, 1, 0, {.name = "len", .kind = K_SIZE, .role = Z_REC, .type = T_SPECTRUM},
       AIN("buf", E_U8, R_RECORD, LEN(L_REC, T_SPECTRUM), 0),
       AOUT("info", E_U8, O_RAW, INFO_LEN, 0)),
    FN(io_crc32, EF_NONE, 1, 0, {.name = "len", .kind = K_SIZE, .role = Z_LEN, .base = 64u, .hi = SIZE_MAX},
       AIN("data", E_U8, R_NONE, LEN(L_SLOT, 0), 0),
       OUT("crc", E_U32, O_RAW, 0)),
    FN(io_kind_str, EF_NONE, 1, 0, U32("kind", 1, 0, UINT32_MAX, F_FREE)),
    FNV(theory_spectrum_init, EF_NONE, pattern_vars, 1, OBJ_OUT("ts", T_TSPEC), OBJ_IN("pat", T_PAT, 0)),
    FN(theory_spectrum_mean, EF_NONE, 1, 0, TS_IN, FREQ("freq", 1), OUT_VAL("re"), OUT_VAL("im")),
    FN(theory_spectrum_power, EF_NONE, 1, 0, TS_IN, FREQ("freq", 1), OUT_NN("out")),
    FN(theory_power_spectrum, EF_NONE, 1, 0, TS_SIZED, N_MATCH,
       AOUT("power", E_D, O_NN, LEN(L_SLOT, 1), 0)),
    FN(theory_spectrum_cross, EF_NONE, 1, 0, TS_IN, FREQ("freq_k", 1), FREQ("freq_l", 2),
       OUT_VAL("re"), OUT_VAL("im")),
    FN(theory_spectrum_covariance, EF_NONE, 1, 0, TS_IN, FREQ("freq_k", 1), FREQ("freq_l", 2),
       OUT_VAL("re"), OUT_VAL("im")),
    FN(theory_spectrum_estimator_mean, EF_NONE, 1, 0, TS_SIZED, N_MATCH, K_MATCH, F_OF("f"),
       OUT_VAL("out")),
    FN(theory_spectrum_variance, EF_NONE, 1, 0, TS_SIZED, N_MATCH, K_MATCH, F_OF("f"),
       OUT_NN("out")),
    FN(theory_spectrum_estimator_covariance, EF_NONE, 1, 0, TS_SIZED, N_MATCH, K_MATCH,
       F_OF("f"), F_OF("g"), OUT_VAL("out")),
};
const size_t adv_fns_io_count = sizeof adv_fns_io / sizeof adv_fns_io[0];
