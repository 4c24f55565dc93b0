/* Adversarial table: status, version, rng, importance, pattern, estimate,
 * welford, dft and spectrum. */
#include "adv_table.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* ---- float points ----
 * The engine fills and mutates double arrays. A row of a _f call narrows
 * its points to floats at the same address (so the aliasing rows still
 * alias), rounding toward zero, which keeps a value in [0,1) inside and one
 * outside outside (NaN stays NaN, beyond the float range an infinity): the
 * double row's expected outcome holds. After the call the doubles go back
 * byte for byte, except where the call itself wrote (an output aliasing the
 * points), so the engine's byte checks see what the call did. */

static double floats_saved[2u * ADV_LONG_LEN];
static float floats_written[2u * ADV_LONG_LEN];

static float toward_zero(double d)
{
    if (isnan(d))
        return NAN;
    if (!(fabs(d) <= (double)FLT_MAX))
        return d > 0.0 ? INFINITY : -INFINITY;
    float f = (float)d;
    return fabs((double)f) > fabs(d) ? nextafterf(f, 0.0f) : f;
}

const float *adv_floats_begin(void *points, size_t len)
{
    if (points == NULL || len > sizeof floats_saved / sizeof floats_saved[0])
        return NULL; /* NULL rows; a longer array is a table error the rows show */
    memcpy(floats_saved, points, len * sizeof(double));
    for (size_t j = 0; j < len; ++j)
        floats_written[j] = toward_zero(floats_saved[j]);
    memcpy(points, floats_written, len * sizeof(float));
    return points;
}

void adv_floats_end(void *points, size_t len)
{
    if (points == NULL || len > sizeof floats_saved / sizeof floats_saved[0])
        return;
    /* The floats cover the first len / 2 doubles (and half of one more). */
    for (size_t i = 0; 2u * i < len; ++i) {
        unsigned char *slot = (unsigned char *)points + i * sizeof(double);
        const size_t bytes = 2u * i + 1u < len ? sizeof(double) : sizeof(float);
        if (memcmp(slot, &floats_written[2u * i], bytes) == 0)
            memcpy(slot, &floats_saved[i], sizeof(double));
    }
}

/* ---- thunks ---- */

static int t_status_str(const adv_val *a)
{
    const char *s = mcs_status_str((mcs_status)a[0].e);
    return s != NULL && strncmp(s, "MCS_", 4) == 0 ? MCS_OK : ADV_BROKEN;
}
static int t_version(const adv_val *a)
{
    (void)a;
    return strcmp(mcs_version(), MCS_VERSION_STRING) == 0 ? MCS_OK : ADV_BROKEN;
}
static int t_rng_seed(const adv_val *a)
{
    int st = mcs_rng_seed(a[0].p, a[1].u64, a[2].u64);
    return st == MCS_OK && !(((mcs_rng *)a[0].p)->inc & 1u) ? ADV_BROKEN : st;
}
static int t_rng_u32(const adv_val *a) { return mcs_rng_u32(a[0].p, a[1].p); }
static int t_rng_bounded(const adv_val *a)
{
    int st = mcs_rng_bounded(a[0].p, a[1].u32, a[2].p);
    return st == MCS_OK && *(uint32_t *)a[2].p >= a[1].u32 ? ADV_BROKEN : st;
}
static int t_rng_double(const adv_val *a) { return mcs_rng_double(a[0].p, a[1].p); }
static int t_importance_init(const adv_val *a) { return mcs_importance_init(a[0].p, a[1].z, a[2].p); }
static int t_importance_warp(const adv_val *a) { return mcs_importance_warp(a[0].p, a[1].d, a[2].p, a[3].p); }
static int t_importance_q(const adv_val *a) { return mcs_importance_q(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_pattern_kind_str(const adv_val *a)
{
    const char *s = mcs_pattern_kind_str((mcs_pattern_kind)a[0].e);
    int known = a[0].e >= 0 && a[0].e < MCS_PATTERN_KIND_COUNT;
    return s != NULL && known == (strcmp(s, "unknown") != 0) ? MCS_OK : ADV_BROKEN;
}
static int t_pattern_init(const adv_val *a)
{
    return mcs_pattern_init(a[0].p, (mcs_pattern_kind)a[1].e, a[2].z, a[3].z, a[4].p);
}
static int t_pattern_draw(const adv_val *a) { return mcs_pattern_draw(a[0].p, a[1].p, a[2].z, a[3].p, a[4].p, a[5].p); }
static int t_pattern_bin_points(const adv_val *a)
{
    return mcs_pattern_bin_points(a[0].z, a[1].z, a[2].p, a[3].p, a[4].p, a[5].p);
}
static int t_pattern_dense(const adv_val *a) { return mcs_pattern_dense(a[0].z, a[1].z, a[2].p, a[3].p, a[4].p); }
static int t_estimate_bins(const adv_val *a)
{
    return mcs_estimate_bins(a[0].z, a[1].z, a[2].p, a[3].p, a[4].p, a[5].p);
}
static int t_estimate_points(const adv_val *a)
{
    return mcs_estimate_points(a[0].z, a[1].fn, a[2].p, a[3].p, a[4].p, a[5].p);
}
static int t_pattern_bin_points_f(const adv_val *a)
{
    const float *x = adv_floats_begin(a[3].p, a[1].z);
    int st = mcs_pattern_bin_points_f(a[0].z, a[1].z, a[2].p, x, a[4].p, a[5].p);
    adv_floats_end(a[3].p, a[1].z);
    return st;
}
static int t_estimate_points_f(const adv_val *a)
{
    const float *x = adv_floats_begin(a[3].p, a[0].z);
    int st = mcs_estimate_points_f(a[0].z, a[1].fn, a[2].p, x, a[4].p, a[5].p);
    adv_floats_end(a[3].p, a[0].z);
    return st;
}
static int t_welford_init(const adv_val *a) { return mcs_welford_init(a[0].p); }
static int t_welford_add(const adv_val *a) { return mcs_welford_add(a[0].p, a[1].d); }
static int t_welford_merge(const adv_val *a) { return mcs_welford_merge(a[0].p, a[1].p); }
static int t_welford_mean(const adv_val *a) { return mcs_welford_mean(a[0].p, a[1].p); }
static int t_welford_variance(const adv_val *a) { return mcs_welford_variance(a[0].p, a[1].p); }
static int t_welford_stderr(const adv_val *a) { return mcs_welford_stderr(a[0].p, a[1].p); }
static int t_welford_variance_stderr(const adv_val *a) { return mcs_welford_variance_stderr(a[0].p, a[1].p); }
static int t_dft_init(const adv_val *a) { return mcs_dft_init(a[0].p, a[1].z); }
static int t_dft_check(const adv_val *a) { return mcs_dft_check(a[0].p, a[1].z); }
static int t_dft_real(const adv_val *a) { return mcs_dft_real(a[0].p, a[1].z, a[2].p, a[3].p, a[4].p); }
static int t_dft_real_half(const adv_val *a) { return mcs_dft_real_half(a[0].p, a[1].z, a[2].p, a[3].p, a[4].p); }
static int t_spectrum_init(const adv_val *a) { return mcs_spectrum_init(a[0].p, a[1].z); }
static int t_spectrum_set_path(const adv_val *a) { return mcs_spectrum_set_path(a[0].p, (mcs_spectrum_path)a[1].e); }
static int t_spectrum_add_bins(const adv_val *a) { return mcs_spectrum_add_bins(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_spectrum_add_dense(const adv_val *a) { return mcs_spectrum_add_dense(a[0].p, a[1].z, a[2].p); }
static int t_spectrum_add_points(const adv_val *a) { return mcs_spectrum_add_points(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_spectrum_add_points_f(const adv_val *a)
{
    const float *x = adv_floats_begin(a[2].p, a[1].z);
    int st = mcs_spectrum_add_points_f(a[0].p, a[1].z, x, a[3].p);
    adv_floats_end(a[2].p, a[1].z);
    return st;
}
static int t_spectrum_merge(const adv_val *a) { return mcs_spectrum_merge(a[0].p, a[1].p); }
static int t_spectrum_count(const adv_val *a) { return mcs_spectrum_count(a[0].p, a[1].p); }
static int t_spectrum_units(const adv_val *a) { return mcs_spectrum_units(a[0].p, a[1].p); }
static int t_spectrum_set_batch(const adv_val *a) { return mcs_spectrum_set_batch(a[0].p, a[1].u64); }
static int t_spectrum_flush(const adv_val *a) { return mcs_spectrum_flush(a[0].p); }
static int t_dft_backend(const adv_val *a)
{
    (void)a;
    const char *b = mcs_dft_backend();
    return b != NULL && (strcmp(b, "kissfft") == 0 || strcmp(b, "fftw3") == 0) ? MCS_OK : ADV_BROKEN;
}
static int t_spectrum_mean(const adv_val *a) { return mcs_spectrum_mean(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_spectrum_mean_stderr(const adv_val *a) { return mcs_spectrum_mean_stderr(a[0].p, a[1].z, a[2].p); }
static int t_spectrum_power(const adv_val *a) { return mcs_spectrum_power(a[0].p, a[1].z, a[2].p); }
static int t_spectrum_power_stderr(const adv_val *a) { return mcs_spectrum_power_stderr(a[0].p, a[1].z, a[2].p); }
static int t_spectrum_read_all(const adv_val *a)
{
    return mcs_spectrum_read_all(a[0].p, a[1].z, a[2].p, a[3].p, a[4].p, a[5].p, a[6].p);
}

/* ---- descriptors ---- */

#ifdef MCS_MAX_K
#define PAT_K SZ_DEF("k", BK, 1, MCS_MAX_K, 0)
#else
#define PAT_K SZ_NOMAX("k", BK)
#endif

static const uint8_t pattern_vars[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8};
static const uint8_t path_vars[3] = {0, 1, 2};

#define RNG_IO OBJ_IO("rng", T_RNG, 0)
#define SPEC_IN OBJ_IN("acc", T_SPECTRUM, 0)
#define FREQ SZ_INDEX("freq", 1, 0, BN - 1u, F_OKIN)
/* n_out of the array read-outs: the stored frequencies k = 0..N/2 */
#define HALF_MATCH SZ_MATCH("n_out", BN / 2u + 1u, MCS_MAX_N / 2u + 1u)

const adv_fn adv_fns_core[] = {
    FN(status_str, EF_NONE, 1, 0, ENM("status", 0, -15, 0, F_FREE)),
    {"mcs_version", t_version, EF_NONE, 1, 0, 0, {{0}}, NULL},
    FN(rng_seed, EF_NONE, 1, 0, OBJ_OUT("rng", T_RNG), U64("initstate", 42), U64("initseq", 54)),
    FN(rng_u32, EF_NONE, 1, 0, RNG_IO, OUT("out", E_U32, O_RAW, 0)),
    FN(rng_bounded, EF_NONE, 1, 0, RNG_IO, U32("bound", 10, 1, UINT32_MAX, F_OKIN),
       OUT("out", E_U32, O_RAW, 0)),
    FN(rng_double, EF_NONE, 1, 0, RNG_IO, OUT("out", E_D, O_U01, 0)),
    FN(importance_init, EF_INIT, 1, 1, OBJ_OUT("imp", T_IMP), SZ_DEF("n", BN, 1, MCS_MAX_N, F_OKIN),
       AIN("weights", E_D, R_IMPW, LEN(L_SLOT, 1), 0)),
    FN(importance_warp, EF_NONE, 1, 0, OBJ_IN("imp", T_IMP, 0), DBL("u", R_POINT, 0.3),
       OUT("x", E_D, O_U01, F_NULLOK), OUT("bin", E_Z, O_BIN, F_NULLOK)),
    FN(importance_q, EF_NONE, 1, 0, OBJ_IN("imp", T_IMP, 0), FREQ, OUT("re", E_D, O_VAL, 0),
       OUT("im", E_D, O_VAL, 0)),
    FN(pattern_kind_str, EF_NONE, 1, 0, ENM("kind", 0, 0, 4, F_FREE)),
    FN(pattern_init, EF_NONE, 1, 2, OBJ_OUT("pat", T_PAT), ENM("kind", 0, 0, 4, 0),
       SZ_DEF("n", BN, 1, MCS_MAX_N, 0), PAT_K, OBJ_IN("importance", T_IMP, F_NULLOK | F_SIZED)),
    FNV(pattern_draw, EF_NONE, pattern_vars, 0, OBJ_IN("pat", T_PAT, 0), RNG_IO,
        SZ_MATCH("k", BK, SIZE_MAX), AOUT("bins", E_Z, O_BIN, LEN(L_SLOT, 2), 0),
        AOUT("weights", E_D, O_NN, LEN(L_SLOT, 2), 0),
        AOUT("points", E_D, O_U01, LEN(L_SLOT, 2), F_NULLOK)),
    FN(pattern_bin_points, EF_NONE, 1, 0, SZ_DEF("n", BN, 1, MCS_MAX_N, 0), SZ_LEN("k", BK),
       OBJ_IN("importance", T_IMP, F_NULLOK | F_SIZED), AIN("points", E_D, R_POINT, LEN(L_SLOT, 1), 0),
       AOUT("bins", E_Z, O_BIN, LEN(L_SLOT, 1), 0), AOUT("weights", E_D, O_NN, LEN(L_SLOT, 1), 0)),
    FN(pattern_bin_points_f, EF_NONE, 1, 0, SZ_DEF("n", BN, 1, MCS_MAX_N, 0), SZ_LEN("k", BK),
       OBJ_IN("importance", T_IMP, F_NULLOK | F_SIZED), AIN("points", E_D, R_POINT, LEN(L_SLOT, 1), 0),
       AOUT("bins", E_Z, O_BIN, LEN(L_SLOT, 1), 0), AOUT("weights", E_D, O_NN, LEN(L_SLOT, 1), 0)),
    FN(pattern_dense, EF_NONE, 1, 0, SZ_DEF("n", BN, 1, MCS_MAX_N, 0), SZ_LEN("k", BT),
       AIN("bins", E_Z, R_BINS, LEN(L_SLOT, 1), 0), AIN("weights", E_D, R_WEIGHT, LEN(L_SLOT, 1), 0),
       AOUT("s", E_D, O_NN, LEN(L_SLOT, 0), 0)),
    FN(estimate_bins, EF_NONE, 1, 0, SZ_LEN("n", BN), SZ_LEN("k", BT),
       AIN("f", E_D, R_F, LEN(L_SLOT, 0), 0), AIN("bins", E_Z, R_BINS, LEN(L_SLOT, 1), 0),
       AIN("weights", E_D, R_WEIGHT, LEN(L_SLOT, 1), 0), OUT("out", E_D, O_VAL, 0)),
    FN(estimate_points, EF_NONE, 1, 0, SZ_LEN("k", BK), FNP("f"), CTX("ctx"),
       AIN("points", E_D, R_POINT, LEN(L_SLOT, 0), 0),
       AIN("weights", E_D, R_WEIGHT, LEN(L_SLOT, 0), F_NULLOK), OUT("out", E_D, O_VAL, 0)),
    FN(estimate_points_f, EF_NONE, 1, 0, SZ_LEN("k", BK), FNP("f"), CTX("ctx"),
       AIN("points", E_D, R_POINT, LEN(L_SLOT, 0), 0),
       AIN("weights", E_D, R_WEIGHT, LEN(L_SLOT, 0), F_NULLOK), OUT("out", E_D, O_VAL, 0)),
    FN(welford_init, EF_INIT, 1, 0, OBJ_OUT("acc", T_WELFORD)),
    FN(welford_add, EF_ADD, 1, 0, OBJ_IO("acc", T_WELFORD, 0), DBL("x", R_F, 1.5)),
    FN(welford_merge, EF_MERGE, 1, 0, OBJ_IO("dst", T_WELFORD, 0), OBJ_IN("src", T_WELFORD, 0)),
    FN(welford_mean, EF_NONE, 1, 0, OBJ_IN("acc", T_WELFORD, 0), OUT("mean", E_D, O_VAL, 0)),
    FN(welford_variance, EF_NONE, 1, 0, OBJ_IN("acc", T_WELFORD, 0), OUT("variance", E_D, O_NN, 0)),
    FN(welford_stderr, EF_NONE, 1, 0, OBJ_IN("acc", T_WELFORD, 0), OUT("stderr", E_D, O_NN, 0)),
    FN(welford_variance_stderr, EF_NONE, 1, 0, OBJ_IN("acc", T_WELFORD, 0),
       OUT("stderr", E_D, O_NN, 0)),
    FN(dft_init, EF_NONE, 1, 1, OBJ_OUT("plan", T_DFT), SZ_DEF("n", BN, 1, MCS_MAX_N, F_OKIN)),
    FN(dft_check, EF_NONE, 1, 0, OBJ_IN("plan", T_DFT, F_SIZED), SZ_MATCH("n", BN, MCS_MAX_N)),
    FN(dft_real, EF_NONE, 1, 0, OBJ_IO("plan", T_DFT, F_SIZED), SZ_MATCH("n", BN, MCS_MAX_N),
       AIN("s", E_D, R_F, LEN(L_SLOT, 1), 0), AOUT("re", E_D, O_VAL, LEN(L_SLOT, 1), 0),
       AOUT("im", E_D, O_VAL, LEN(L_SLOT, 1), F_NULLOK)),
    FN(dft_real_half, EF_NONE, 1, 0, OBJ_IO("plan", T_DFT, F_SIZED), SZ_MATCH("n", BN, MCS_MAX_N),
       AIN("s", E_D, R_F, LEN(L_SLOT, 1), 0), AOUT("re", E_D, O_VAL, LEN(L_HALF, 1), 0),
       AOUT("im", E_D, O_VAL, LEN(L_HALF, 1), F_NULLOK)),
    FN(spectrum_init, EF_INIT, 1, 1, OBJ_OUT("acc", T_SPECTRUM), SZ_DEF("n", BN, 1, MCS_MAX_N, F_OKIN)),
    FN(spectrum_set_path, EF_NONE, 1, 0, OBJ_IO("acc", T_SPECTRUM, 0), ENM("path", 2, 0, 3, F_OKIN)),
    FNV(spectrum_add_bins, EF_ADD, path_vars, 0, OBJ_IO("acc", T_SPECTRUM, 0), SZ_LEN("k", BT),
        AIN("bins", E_Z, R_BINS, LEN(L_SLOT, 1), 0), AIN("weights", E_D, R_WEIGHT, LEN(L_SLOT, 1), 0)),
    FN(spectrum_add_dense, EF_ADD, 1, 0, OBJ_IO("acc", T_SPECTRUM, F_SIZED),
       SZ_MATCH("n", BN, MCS_MAX_N), AIN("s", E_D, R_WEIGHT, LEN(L_SLOT, 1), 0)),
    FNV(spectrum_add_points, EF_ADD, path_vars, 0, OBJ_IO("acc", T_SPECTRUM, 0), SZ_LEN("k", BT),
        AIN("points", E_D, R_POINT, LEN(L_SLOT, 1), 0),
        AIN("weights", E_D, R_WEIGHT, LEN(L_SLOT, 1), F_NULLOK)),
    FNV(spectrum_add_points_f, EF_ADD, path_vars, 0, OBJ_IO("acc", T_SPECTRUM, 0), SZ_LEN("k", BT),
        AIN("points", E_D, R_POINT, LEN(L_SLOT, 1), 0),
        AIN("weights", E_D, R_WEIGHT, LEN(L_SLOT, 1), F_NULLOK)),
    FN(spectrum_merge, EF_MERGE, 1, 0, OBJ_IO("dst", T_SPECTRUM, 0), OBJ_IN("src", T_SPECTRUM, F_SIZED)),
    FN(spectrum_count, EF_NONE, 1, 0, SPEC_IN, OUT("count", E_U64, O_RAW, 0)),
    FN(spectrum_units, EF_NONE, 1, 0, SPEC_IN, OUT("units", E_U64, O_RAW, 0)),
    FN(spectrum_set_batch, EF_NONE, 1, 0, OBJ_IO("acc", T_SPECTRUM, 0),
       U64_MAX_("batch", 16, MCS_SPECTRUM_BATCH_LIMIT)),
    FN(spectrum_flush, EF_NONE, 1, 0, OBJ_IO("acc", T_SPECTRUM, 0)),
    {"mcs_dft_backend", t_dft_backend, EF_NONE, 1, 0, 0, {{0}}, NULL},
    FN(spectrum_mean, EF_NONE, 1, 0, SPEC_IN, FREQ, OUT("re", E_D, O_VAL, 0), OUT("im", E_D, O_VAL, 0)),
    FN(spectrum_mean_stderr, EF_NONE, 1, 0, SPEC_IN, FREQ, OUT("stderr", E_D, O_NN, 0)),
    FN(spectrum_power, EF_NONE, 1, 0, SPEC_IN, FREQ, OUT("power", E_D, O_NN, 0)),
    FN(spectrum_power_stderr, EF_NONE, 1, 0, SPEC_IN, FREQ, OUT("stderr", E_D, O_NN, 0)),
    FN(spectrum_read_all, EF_NONE, 1, 0, OBJ_IN("acc", T_SPECTRUM, F_SIZED), HALF_MATCH,
       AOUT("mean_re", E_D, O_VAL, LEN(L_SLOT, 1), F_NULLOK),
       AOUT("mean_im", E_D, O_VAL, LEN(L_SLOT, 1), F_NULLOK),
       AOUT("mean_stderr", E_D, O_NN, LEN(L_SLOT, 1), F_NULLOK),
       AOUT("power", E_D, O_NN, LEN(L_SLOT, 1), F_NULLOK),
       AOUT("power_stderr", E_D, O_NN, LEN(L_SLOT, 1), F_NULLOK)),
};
const size_t adv_fns_core_count = sizeof adv_fns_core / sizeof adv_fns_core[0];
