/* Adversarial table: sampler, pattern2d, pointset, pointset2d, spectrum2d. */
#include "adv_table.h"

#include <limits.h>
#include <math.h>
#include <string.h>

static int t_sampler_kind_str(const adv_val *a)
{
    const char *s = mcs_sampler_kind_str((mcs_sampler_kind)a[0].e);
    int known = a[0].e >= 0 && a[0].e < MCS_SAMPLER_KIND_COUNT;
    return s != NULL && known == (strcmp(s, "unknown") != 0) ? MCS_OK : ADV_BROKEN;
}
/* has_dim says 1 exactly where init accepts the kind in that dimension. */
static int t_sampler_has_dim(const adv_val *a)
{
    mcs_sampler s;
    int h = mcs_sampler_has_dim((mcs_sampler_kind)a[0].e, a[1].z);
    int ok = mcs_sampler_init(&s, (mcs_sampler_kind)a[0].e, a[1].z, 4u) == MCS_OK;
    return (h == 0 || h == 1) && h == ok ? MCS_OK : ADV_BROKEN;
}
static int t_sampler_init(const adv_val *a) { return mcs_sampler_init(a[0].p, (mcs_sampler_kind)a[1].e, a[2].z, a[3].z); }
static int t_sampler_draw(const adv_val *a) { return mcs_sampler_draw(a[0].p, a[1].p, a[2].z, a[3].p); }
static int t_sampler_base_points(const adv_val *a) { return mcs_sampler_base_points(a[0].p, a[1].z, a[2].p); }
/* The top m bits of the result depend only on the top m bits of x. */
static int t_sampler_owen_scramble(const adv_val *a)
{
    uint32_t x = a[0].u32, seed = a[1].u32, r = mcs_sampler_owen_scramble(x, seed);
    for (int m = 1; m < 32; m += 5) {
        uint32_t mask = ~(uint32_t)0 << (32 - m);
        if ((mcs_sampler_owen_scramble(x ^ ~mask, seed) & mask) != (r & mask))
            return ADV_BROKEN;
    }
    return MCS_OK;
}
static int t_pattern2d_kind_str(const adv_val *a)
{
    const char *s = mcs_pattern2d_kind_str((mcs_pattern2d_kind)a[0].e);
    int known = a[0].e >= 0 && a[0].e < MCS_PATTERN2D_KIND_COUNT;
    return s != NULL && known == (strcmp(s, "unknown") != 0) ? MCS_OK : ADV_BROKEN;
}
static int t_pattern2d_init(const adv_val *a)
{
    return mcs_pattern2d_init(a[0].p, (mcs_pattern2d_kind)a[1].e, a[2].z, a[3].z, a[4].z);
}
static int t_pattern2d_draw(const adv_val *a) { return mcs_pattern2d_draw(a[0].p, a[1].p, a[2].z, a[3].p); }
/* A permutation of [0, l) for l up to 4096 (every image distinct and in
 * range), and 0 outside it. */
static int t_pattern2d_permute(const adv_val *a)
{
    static unsigned char seen[4096];
    const uint32_t i = a[0].u32, l = a[1].u32, p = a[2].u32;
    if (l == 0u || i >= l)
        return mcs_pattern2d_permute(i, l, p) == 0u ? MCS_OK : ADV_BROKEN;
    if (l > 4096u)
        return mcs_pattern2d_permute(i, l, p) < l ? MCS_OK : ADV_BROKEN;
    memset(seen, 0, l);
    for (uint32_t j = 0; j < l; ++j) {
        uint32_t r = mcs_pattern2d_permute(j, l, p);
        if (r >= l || seen[r]++)
            return ADV_BROKEN;
    }
    return MCS_OK;
}
/* The planar float calls get float copies of both arrays (adv_floats_begin
 * narrows one array at a time), narrowed as it does: a double below 1
 * stays below 1.0f. */
static const float *planar_floats(const double *x, size_t len, float *out)
{
    if (x == NULL || len > 4096u)
        return NULL;
    for (size_t j = 0; j < len; ++j) {
        float f = (float)x[j];
        out[j] = x[j] < 1.0 && f >= 1.0f ? nextafterf(1.0f, 0.0f) : f;
    }
    return out;
}
static float planar_x[4096], planar_y[4096];

static int t_pointset_size(const adv_val *a) { return mcs_pointset_size(a[0].z, a[1].u32, a[2].p); }
static int t_pointset_init(const adv_val *a) { return mcs_pointset_init(a[0].p, a[1].z, a[2].u32, a[3].p, a[4].z); }
static int t_pointset_copy(const adv_val *a) { return mcs_pointset_copy(a[0].p, a[1].p, a[2].z, a[3].p); }
static int t_pointset_set_path(const adv_val *a) { return mcs_pointset_set_path(a[0].p, (mcs_pointset_path)a[1].e); }
static int t_pointset_path_for(const adv_val *a)
{
    mcs_pointset_path p = MCS_POINTSET_PATH_AUTO;
    int st = mcs_pointset_path_for(a[0].p, a[1].z, a[2].p != NULL ? &p : NULL);
    if (st == MCS_OK && p != MCS_POINTSET_PATH_DIRECT && p != MCS_POINTSET_PATH_NUFFT)
        return ADV_BROKEN;
    if (st == MCS_OK)
        memcpy(a[2].p, &p, sizeof p);
    return st;
}
static int t_pointset_set_wrap(const adv_val *a) { return mcs_pointset_set_wrap(a[0].p, a[1].e); }
static int t_pointset_add(const adv_val *a) { return mcs_pointset_add(a[0].p, a[1].z, a[2].p); }
static int t_pointset_add_f(const adv_val *a)
{
    const float *x = adv_floats_begin(a[2].p, a[1].z);
    int st = mcs_pointset_add_f(a[0].p, a[1].z, x);
    adv_floats_end(a[2].p, a[1].z);
    return st;
}
static int t_pointset_merge(const adv_val *a) { return mcs_pointset_merge(a[0].p, a[1].p); }
static int t_pointset_count(const adv_val *a) { return mcs_pointset_count(a[0].p, a[1].p); }
static int t_pointset_power(const adv_val *a) { return mcs_pointset_power(a[0].p, a[1].l, a[2].p); }
static int t_pointset_power_stderr(const adv_val *a) { return mcs_pointset_power_stderr(a[0].p, a[1].l, a[2].p); }
static int t_pointset_exact_power(const adv_val *a) { return mcs_pointset_exact_power((mcs_pattern_kind)a[0].e, a[1].z, a[2].l, a[3].p); }
static int t_pointset2d_size(const adv_val *a) { return mcs_pointset2d_size(a[0].z, a[1].u32, a[2].p); }
static int t_pointset2d_init(const adv_val *a) { return mcs_pointset2d_init(a[0].p, a[1].z, a[2].u32, a[3].p, a[4].z); }
static int t_pointset2d_copy(const adv_val *a) { return mcs_pointset2d_copy(a[0].p, a[1].p, a[2].z, a[3].p); }
static int t_pointset2d_set_path(const adv_val *a) { return mcs_pointset2d_set_path(a[0].p, (mcs_pointset_path)a[1].e); }
static int t_pointset2d_path_for(const adv_val *a)
{
    mcs_pointset_path p = MCS_POINTSET_PATH_AUTO;
    int st = mcs_pointset2d_path_for(a[0].p, a[1].z, a[2].p != NULL ? &p : NULL);
    if (st == MCS_OK && p != MCS_POINTSET_PATH_DIRECT && p != MCS_POINTSET_PATH_NUFFT)
        return ADV_BROKEN;
    if (st == MCS_OK)
        memcpy(a[2].p, &p, sizeof p);
    return st;
}
static int t_pointset2d_set_wrap(const adv_val *a) { return mcs_pointset2d_set_wrap(a[0].p, a[1].e); }
static int t_pointset2d_add_planar(const adv_val *a) { return mcs_pointset2d_add_planar(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_pointset2d_add_planar_f(const adv_val *a)
{
    return mcs_pointset2d_add_planar_f(a[0].p, a[1].z, planar_floats(a[2].p, a[1].z, planar_x),
                                       planar_floats(a[3].p, a[1].z, planar_y));
}
static int t_pointset2d_add(const adv_val *a) { return mcs_pointset2d_add(a[0].p, a[1].z, a[2].p); }
static int t_pointset2d_add_f(const adv_val *a)
{
    const size_t len = a[1].z <= SIZE_MAX / 2u ? 2u * a[1].z : SIZE_MAX;
    const float *x = adv_floats_begin(a[2].p, len);
    int st = mcs_pointset2d_add_f(a[0].p, a[1].z, x);
    adv_floats_end(a[2].p, len);
    return st;
}
static int t_pointset2d_merge(const adv_val *a) { return mcs_pointset2d_merge(a[0].p, a[1].p); }
static int t_pointset2d_count(const adv_val *a) { return mcs_pointset2d_count(a[0].p, a[1].p); }
static int t_pointset2d_power(const adv_val *a) { return mcs_pointset2d_power(a[0].p, a[1].l, a[2].l, a[3].p); }
static int t_pointset2d_power_stderr(const adv_val *a) { return mcs_pointset2d_power_stderr(a[0].p, a[1].l, a[2].l, a[3].p); }
static int t_pointset2d_radial(const adv_val *a) { return mcs_pointset2d_radial(a[0].p, a[1].z, a[2].p); }
static int t_pointset2d_radial_stderr(const adv_val *a) { return mcs_pointset2d_radial_stderr(a[0].p, a[1].z, a[2].p); }
static int t_pointset2d_anisotropy(const adv_val *a) { return mcs_pointset2d_anisotropy(a[0].p, a[1].z, a[2].p); }
static int t_pointset2d_ring_size(const adv_val *a) { return mcs_pointset2d_ring_size(a[0].z, a[1].p); }
static int t_pointset2d_exact_power(const adv_val *a) { return mcs_pointset2d_exact_power(a[0].p, a[1].l, a[2].l, a[3].p); }
static int t_pointset2d_exact_radial(const adv_val *a) { return mcs_pointset2d_exact_radial(a[0].p, a[1].z, a[2].p); }
static int t_pointset2d_exact_anisotropy(const adv_val *a) { return mcs_pointset2d_exact_anisotropy(a[0].p, a[1].z, a[2].p); }
static int t_spectrum2d_size(const adv_val *a) { return mcs_spectrum2d_size(a[0].z, a[1].z, a[2].p); }
static int t_spectrum2d_init(const adv_val *a) { return mcs_spectrum2d_init(a[0].p, a[1].z, a[2].z, a[3].p, a[4].z); }
static int t_spectrum2d_copy(const adv_val *a) { return mcs_spectrum2d_copy(a[0].p, a[1].p, a[2].z, a[3].p); }
static int t_spectrum2d_set_wrap(const adv_val *a) { return mcs_spectrum2d_set_wrap(a[0].p, a[1].e); }
static int t_spectrum2d_add_points_planar(const adv_val *a)
{
    return mcs_spectrum2d_add_points_planar(a[0].p, a[1].z, a[2].p, a[3].p, a[4].p);
}
static int t_spectrum2d_add_points_planar_f(const adv_val *a)
{
    return mcs_spectrum2d_add_points_planar_f(a[0].p, a[1].z, planar_floats(a[2].p, a[1].z, planar_x),
                                              planar_floats(a[3].p, a[1].z, planar_y), a[4].p);
}
static int t_spectrum2d_add_points(const adv_val *a) { return mcs_spectrum2d_add_points(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_spectrum2d_add_points_f(const adv_val *a)
{
    const size_t len = a[1].z <= SIZE_MAX / 2u ? 2u * a[1].z : SIZE_MAX;
    const float *x = adv_floats_begin(a[2].p, len);
    int st = mcs_spectrum2d_add_points_f(a[0].p, a[1].z, x, a[3].p);
    adv_floats_end(a[2].p, len);
    return st;
}
static int t_spectrum2d_merge(const adv_val *a) { return mcs_spectrum2d_merge(a[0].p, a[1].p); }
static int t_spectrum2d_count(const adv_val *a) { return mcs_spectrum2d_count(a[0].p, a[1].p); }
static int t_spectrum2d_mean(const adv_val *a) { return mcs_spectrum2d_mean(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_spectrum2d_power(const adv_val *a) { return mcs_spectrum2d_power(a[0].p, a[1].z, a[2].z, a[3].p); }
static int t_spectrum2d_power_stderr(const adv_val *a) { return mcs_spectrum2d_power_stderr(a[0].p, a[1].z, a[2].z, a[3].p); }
static int t_spectrum2d_mean_stderr(const adv_val *a) { return mcs_spectrum2d_mean_stderr(a[0].p, a[1].z, a[2].z, a[3].p); }
static int t_spectrum2d_transform(const adv_val *a) { return mcs_spectrum2d_transform(a[0].p, a[1].p, a[2].p, a[3].p); }
static int t_spectrum2d_variance14(const adv_val *a) { return mcs_spectrum2d_variance14(a[0].p, a[1].z, a[2].p, a[3].p, a[4].p); }
static int t_spectrum2d_exact_mean(const adv_val *a) { return mcs_spectrum2d_exact_mean(a[0].p, a[1].z, a[2].z, a[3].z, a[4].z, a[5].p, a[6].p); }
static int t_spectrum2d_exact_power(const adv_val *a) { return mcs_spectrum2d_exact_power(a[0].p, a[1].z, a[2].z, a[3].z, a[4].z, a[5].p); }
static int t_spectrum2d_exact_covariance(const adv_val *a)
{
    return mcs_spectrum2d_exact_covariance(a[0].p, a[1].z, a[2].z, a[3].z, a[4].z, a[5].z, a[6].z,
                                           a[7].p, a[8].p);
}
static int t_spectrum2d_exact_variance(const adv_val *a) { return mcs_spectrum2d_exact_variance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p, a[5].p); }
static int t_spectrum2d_exact_variance14(const adv_val *a) { return mcs_spectrum2d_exact_variance14(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p, a[5].p); }

static const uint8_t sampler_vars[7] = {0, 1, 2, 3, 4, 5, 6};
static const uint8_t p2d_vars[7] = {0, 1, 2, 3, 4, 5, 6};
static const uint8_t p2d_exact_vars[5] = {0, 1, 2, 3, 4};   /* closed forms exist */
static const uint8_t p2d_aniso_vars[3] = {1, 2, 3};        /* not exactly isotropic */
static const uint8_t p2d_binned_vars[3] = {0, 1, 3};       /* random, jittered, shifted grid */

#define OUT_VAL(nm) OUT(nm, E_D, O_VAL, 0)
#define OUT_NN(nm) OUT(nm, E_D, O_NN, 0)
#define PS_IN OBJ_IN("acc", T_POINTSET, 0)
#define P2_IN OBJ_IN("acc", T_POINTSET2D, 0)
#define S2_IN OBJ_IN("acc", T_SPECTRUM2D, 0)
#define PAT2 OBJ_IN("pat", T_PAT2D, 0)
#define F1(nm) LNG(nm, 1, -8, 8, F_OKIN)
#define F2(nm, b) LNG(nm, b, -4, 4, F_OKIN)
#define S2_FREQ SZ_INDEX("freq_k", 1, 0, 5, F_OKIN), SZ_INDEX("freq_l", 1, 0, 3, F_OKIN)
#define S2_PLANE(nm, role_) AIN(nm, E_D, role_, LEN(L_OBJNN, 0), 0)
#define SIDES SZ_DEF("n_x", 6, 1, MCS_SPECTRUM2D_MAX_SIDE, 0), \
              SZ_DEF("n_y", 4, 1, MCS_SPECTRUM2D_MAX_SIDE, 0)
#define PATH_OUT OUT("path", E_U32, O_RAW, 0)
#define BIN_FREQ SZ_INDEX("freq_k", 1, 0, 5, 0), SZ_INDEX("freq_l", 1, 0, 3, 0)
#define EXACT_PLANE(nm) AIN(nm, E_D, R_F, LEN2(L_PROD, 1, 2), 0)

const adv_fn adv_fns_2d[] = {
    FN(sampler_kind_str, EF_NONE, 1, 0, ENM("kind", 0, 0, 9, F_FREE)),
    FN(sampler_has_dim, EF_NONE, 1, 0, ENM("kind", 0, 0, 9, F_FREE), SZ_FREE("dim", 1)),
    FN(sampler_init, EF_NONE, 1, 3, OBJ_OUT("s", T_SAMPLER), ENM("kind", 3, 0, 9, 0),
       SZ_DEF("dim", 2, 1, 2, F_OKIN), SZ_DEF("k", 8, 1, (size_t)1 << 32, F_OKIN)),
    FNV(sampler_draw, EF_NONE, sampler_vars, 0, OBJ_IN("s", T_SAMPLER, F_SIZED),
        OBJ_IO("rng", T_RNG, 0), SZ_MATCH("k", 8, (size_t)1 << 32),
        AOUT("points", E_D, O_U01, LEN2(L_KDIM, 2, 0), 0)),
    FNV(sampler_base_points, EF_NONE, sampler_vars, 0, OBJ_IN("s", T_SAMPLER, F_SIZED),
        SZ_MATCH("k", 8, (size_t)1 << 32), AOUT("points", E_D, O_U01, LEN2(L_KDIM, 1, 0), 0)),
    FN(sampler_owen_scramble, EF_NONE, 1, 0, U32("x", 0x9E3779B9u, 0, UINT32_MAX, F_FREE),
       U32("seed", 12345u, 0, UINT32_MAX, F_FREE)),
    FN(pattern2d_kind_str, EF_NONE, 1, 0, ENM("kind", 0, 0, 6, F_FREE)),
    FN(pattern2d_init, EF_NONE, 1, 2, OBJ_OUT("pat", T_PAT2D), ENM("kind", 1, 0, 6, F_OKIN),
       SZ_DEF("k", 6, 1, MCS_PATTERN2D_MAX_K, 0), SZ_FREE("strata_x", 3), SZ_FREE("strata_y", 2)),
    FNV(pattern2d_draw, EF_NONE, p2d_vars, 0, OBJ_IN("pat", T_PAT2D, F_SIZED), OBJ_IO("rng", T_RNG, 0),
        SZ_MATCH("k", 6, MCS_PATTERN2D_MAX_K), AOUT("points", E_D, O_U01, LEN(L_2SLOT, 2), 0)),
    FN(pattern2d_permute, EF_NONE, 1, 0, U32("i", 3, 0, UINT32_MAX, F_FREE),
       U32("l", 10, 0, UINT32_MAX, F_FREE), U32("p", 7, 0, UINT32_MAX, F_FREE)),
    FN(pointset_size, EF_NONE, 1, 0, SZ_DEF("freq_max", 8, 1, MCS_POINTSET_MAX_FREQ, F_OKIN),
       FLAGS, OUT("bytes", E_Z, O_RAW, 0)),
    FN(pointset_init, EF_INIT, 1, 1, OBJ_OUT("acc", T_POINTSET),
       SZ_DEF("freq_max", 8, 1, MCS_POINTSET_MAX_FREQ, 0), FLAGS, MEM(4), SZ_LEN("bytes", PS_MEM)),
    FN(pointset_copy, EF_NONE, 1, 0, OBJ_OUT("dst", T_POINTSET), MEM(2), SZ_LEN("bytes", PS_MEM),
       OBJ_IN("src", T_POINTSET, 0)),
    FN(pointset_set_path, EF_NONE, 1, 0, OBJ_IO("acc", T_POINTSET, 0), ENM("path", 2, 0, 2, F_OKIN)),
    FN(pointset_path_for, EF_NONE, 1, 0, PS_IN, SZ_NOMAX("k", 6), PATH_OUT),
    FN(pointset_set_wrap, EF_NONE, 1, 0, OBJ_IO("acc", T_POINTSET, 0), ENM("wrap", 1, 0, 1, F_OKIN)),
    FN(pointset_add, EF_ADD, 1, 1, OBJ_IO("acc", T_POINTSET, 0), SZ_LEN("k", 6),
       AIN("points", E_D, R_POINT, LEN(L_SLOT, 1), 0)),
    FN(pointset_add_f, EF_ADD, 1, 1, OBJ_IO("acc", T_POINTSET, 0), SZ_LEN("k", 6),
       AIN("points", E_D, R_POINT, LEN(L_SLOT, 1), 0)),
    FN(pointset_merge, EF_MERGE, 1, 0, OBJ_IO("dst", T_POINTSET, 0), OBJ_IN("src", T_POINTSET, F_SIZED)),
    FN(pointset_count, EF_NONE, 1, 0, PS_IN, OUT("count", E_U64, O_RAW, 0)),
    FN(pointset_power, EF_NONE, 1, 0, PS_IN, F1("freq"), OUT_NN("out")),
    FN(pointset_power_stderr, EF_NONE, 1, 0, PS_IN, F1("freq"), OUT_NN("out")),
    FN(pointset_exact_power, EF_NONE, 1, 1, ENM("kind", 1, 0, 4, 0), SZ_NOMAX("k", 6),
       LNG("freq", 1, LONG_MIN, LONG_MAX, F_FREE), OUT_NN("out")),
    FN(pointset2d_size, EF_NONE, 1, 0, SZ_DEF("freq_max", 4, 1, MCS_POINTSET2D_MAX_FREQ, F_OKIN),
       FLAGS, OUT("bytes", E_Z, O_RAW, 0)),
    FN(pointset2d_init, EF_INIT, 1, 1, OBJ_OUT("acc", T_POINTSET2D),
       SZ_DEF("freq_max", 4, 1, MCS_POINTSET2D_MAX_FREQ, 0), FLAGS, MEM(4), SZ_LEN("bytes", P2_MEM)),
    FN(pointset2d_copy, EF_NONE, 1, 0, OBJ_OUT("dst", T_POINTSET2D), MEM(2),
       SZ_LEN("bytes", P2_MEM), OBJ_IN("src", T_POINTSET2D, 0)),
    FN(pointset2d_set_path, EF_NONE, 1, 0, OBJ_IO("acc", T_POINTSET2D, 0),
       ENM("path", 2, 0, 2, F_OKIN)),
    FN(pointset2d_path_for, EF_NONE, 1, 0, P2_IN, SZ_NOMAX("k", 6), PATH_OUT),
    FN(pointset2d_set_wrap, EF_NONE, 1, 0, OBJ_IO("acc", T_POINTSET2D, 0),
       ENM("wrap", 1, 0, 1, F_OKIN)),
    FN(pointset2d_add_planar, EF_ADD, 1, 1, OBJ_IO("acc", T_POINTSET2D, 0), SZ_LEN("k", 6),
       AIN("x", E_D, R_POINT, LEN(L_SLOT, 1), 0), AIN("y", E_D, R_POINT, LEN(L_SLOT, 1), 0)),
    FN(pointset2d_add_planar_f, EF_ADD, 1, 1, OBJ_IO("acc", T_POINTSET2D, 0), SZ_LEN("k", 6),
       AIN("x", E_D, R_POINT, LEN(L_SLOT, 1), 0), AIN("y", E_D, R_POINT, LEN(L_SLOT, 1), 0)),
    FN(pointset2d_add, EF_ADD, 1, 1, OBJ_IO("acc", T_POINTSET2D, 0), SZ_LEN("k", 6),
       AIN("points", E_D, R_POINT, LEN(L_2SLOT, 1), 0)),
    FN(pointset2d_add_f, EF_ADD, 1, 1, OBJ_IO("acc", T_POINTSET2D, 0), SZ_LEN("k", 6),
       AIN("points", E_D, R_POINT, LEN(L_2SLOT, 1), 0)),
    FN(pointset2d_merge, EF_MERGE, 1, 0, OBJ_IO("dst", T_POINTSET2D, 0),
       OBJ_IN("src", T_POINTSET2D, F_SIZED)),
    FN(pointset2d_count, EF_NONE, 1, 0, P2_IN, OUT("count", E_U64, O_RAW, 0)),
    FN(pointset2d_power, EF_NONE, 1, 0, P2_IN, F2("freq_x", 1), F2("freq_y", 2), OUT_NN("out")),
    FN(pointset2d_power_stderr, EF_NONE, 1, 0, P2_IN, F2("freq_x", 1), F2("freq_y", 2),
       OUT_NN("out")),
    FN(pointset2d_radial, EF_NONE, 1, 0, P2_IN, SZ_INDEX("radius", 1, 0, 4, F_OKIN), OUT_NN("out")),
    FN(pointset2d_radial_stderr, EF_NONE, 1, 0, P2_IN, SZ_INDEX("radius", 1, 0, 4, F_OKIN),
       OUT_NN("out")),
    FN(pointset2d_anisotropy, EF_NONE, 1, 0, P2_IN, SZ_INDEX("radius", 2, 1, 4, 0), OUT_VAL("out")),
    FN(pointset2d_ring_size, EF_NONE, 1, 0, SZ_FREE("radius", 3), OUT("out", E_Z, O_RAW, 0)),
    FNV(pointset2d_exact_power, EF_NONE, p2d_exact_vars, 0, PAT2, LNG("freq_x", 1, LONG_MIN, LONG_MAX, F_FREE),
        LNG("freq_y", 2, LONG_MIN, LONG_MAX, F_FREE), OUT_NN("out")),
    FNV(pointset2d_exact_radial, EF_NONE, p2d_exact_vars, 0, PAT2, SZ_FREE("radius", 2), OUT_NN("out")),
    FNV(pointset2d_exact_anisotropy, EF_NONE, p2d_aniso_vars, 0, PAT2, SZ_FREE("radius", 2),
        OUT_VAL("out")),
    FN(spectrum2d_size, EF_NONE, 1, 0, SZ_DEF("n_x", 6, 1, MCS_SPECTRUM2D_MAX_SIDE, F_OKIN),
       SZ_DEF("n_y", 4, 1, MCS_SPECTRUM2D_MAX_SIDE, F_OKIN), OUT("bytes", E_Z, O_RAW, 0)),
    FN(spectrum2d_init, EF_INIT, 1, 1, OBJ_OUT("acc", T_SPECTRUM2D),
       SZ_DEF("n_x", 6, 1, MCS_SPECTRUM2D_MAX_SIDE, 0), SZ_DEF("n_y", 4, 1, MCS_SPECTRUM2D_MAX_SIDE, 0),
       MEM(4), SZ_LEN("bytes", S2_MEM)),
    FN(spectrum2d_copy, EF_NONE, 1, 0, OBJ_OUT("dst", T_SPECTRUM2D), MEM(2),
       SZ_LEN("bytes", S2_MEM), OBJ_IN("src", T_SPECTRUM2D, 0)),
    FN(spectrum2d_set_wrap, EF_NONE, 1, 0, OBJ_IO("acc", T_SPECTRUM2D, 0),
       ENM("wrap", 1, 0, 1, F_OKIN)),
    FN(spectrum2d_add_points_planar, EF_ADD, 1, 1, OBJ_IO("acc", T_SPECTRUM2D, 0), SZ_LEN("k", 6),
       AIN("x", E_D, R_POINT, LEN(L_SLOT, 1), 0), AIN("y", E_D, R_POINT, LEN(L_SLOT, 1), 0),
       AIN("weights", E_D, R_WEIGHT, LEN(L_SLOT, 1), F_NULLOK)),
    FN(spectrum2d_add_points_planar_f, EF_ADD, 1, 1, OBJ_IO("acc", T_SPECTRUM2D, 0), SZ_LEN("k", 6),
       AIN("x", E_D, R_POINT, LEN(L_SLOT, 1), 0), AIN("y", E_D, R_POINT, LEN(L_SLOT, 1), 0),
       AIN("weights", E_D, R_WEIGHT, LEN(L_SLOT, 1), F_NULLOK)),
    FN(spectrum2d_add_points, EF_ADD, 1, 1, OBJ_IO("acc", T_SPECTRUM2D, 0), SZ_LEN("k", 6),
       AIN("points", E_D, R_POINT, LEN(L_2SLOT, 1), 0),
       AIN("weights", E_D, R_WEIGHT, LEN(L_SLOT, 1), F_NULLOK)),
    FN(spectrum2d_add_points_f, EF_ADD, 1, 1, OBJ_IO("acc", T_SPECTRUM2D, 0), SZ_LEN("k", 6),
       AIN("points", E_D, R_POINT, LEN(L_2SLOT, 1), 0),
       AIN("weights", E_D, R_WEIGHT, LEN(L_SLOT, 1), F_NULLOK)),
    FN(spectrum2d_merge, EF_MERGE, 1, 0, OBJ_IO("dst", T_SPECTRUM2D, 0),
       OBJ_IN("src", T_SPECTRUM2D, F_SIZED)),
    FN(spectrum2d_count, EF_NONE, 1, 0, S2_IN, OUT("count", E_U64, O_RAW, 0)),
    FN(spectrum2d_mean, EF_NONE, 1, 0, S2_IN, S2_FREQ, OUT_VAL("re"), OUT_VAL("im")),
    FN(spectrum2d_power, EF_NONE, 1, 0, S2_IN, S2_FREQ, OUT_NN("out")),
    FN(spectrum2d_power_stderr, EF_NONE, 1, 0, S2_IN, S2_FREQ, OUT_NN("out")),
    FN(spectrum2d_mean_stderr, EF_NONE, 1, 0, S2_IN, S2_FREQ, OUT_NN("out")),
    FN(spectrum2d_transform, EF_NONE, 1, 0, S2_IN, S2_PLANE("s", R_F),
       AOUT("re", E_D, O_VAL, LEN(L_OBJNN, 0), 0), AOUT("im", E_D, O_VAL, LEN(L_OBJNN, 0), 0)),
    FN(spectrum2d_variance14, EF_NONE, 1, 0, S2_IN, SZ_NOMAX("k", 6), S2_PLANE("f_re", R_F),
       S2_PLANE("f_im", R_F), OUT_NN("out")),
    FNV(spectrum2d_exact_mean, EF_NONE, p2d_binned_vars, 0, PAT2, SIDES, BIN_FREQ, OUT_VAL("re"),
        OUT_VAL("im")),
    FNV(spectrum2d_exact_power, EF_NONE, p2d_binned_vars, 0, PAT2, SIDES, BIN_FREQ, OUT_NN("out")),
    FNV(spectrum2d_exact_covariance, EF_NONE, p2d_binned_vars, 0, PAT2, SIDES,
        SZ_INDEX("k1", 1, 0, 5, 0), SZ_INDEX("k2", 1, 0, 3, 0), SZ_INDEX("l1", 1, 0, 5, 0),
        SZ_INDEX("l2", 1, 0, 3, 0), OUT_VAL("re"), OUT_VAL("im")),
    FNV(spectrum2d_exact_variance, EF_NONE, p2d_binned_vars, 0, PAT2, SIDES, EXACT_PLANE("f_re"),
        EXACT_PLANE("f_im"), OUT_NN("out")),
    FNV(spectrum2d_exact_variance14, EF_NONE, p2d_binned_vars, 0, PAT2, SIDES, EXACT_PLANE("f_re"),
        EXACT_PLANE("f_im"), OUT_NN("out")),
};
const size_t adv_fns_2d_count = sizeof adv_fns_2d / sizeof adv_fns_2d[0];
