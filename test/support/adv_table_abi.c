/* Adversarial table: abi (struct sizes for bindings) and the point-set
 * batches of pointset_batch.c (pointset.h, pointset2d.h). */
#include "adv_table.h"

#include <stdint.h>

static int t_abi_sizeof(const adv_val *a) { return mcs_abi_sizeof((mcs_abi_type)a[0].e, a[1].p, a[2].p); }
static int t_pointset_add_sets(const adv_val *a) { return mcs_pointset_add_sets(a[0].p, a[1].z, a[2].z, a[3].p); }
static int t_pointset_add_sets_f(const adv_val *a)
{
    const size_t len = a[2].z != 0u && a[1].z > SIZE_MAX / a[2].z ? SIZE_MAX : a[1].z * a[2].z;
    const float *x = adv_floats_begin(a[3].p, len);
    int st = mcs_pointset_add_sets_f(a[0].p, a[1].z, a[2].z, x);
    adv_floats_end(a[3].p, len);
    return st;
}
static int t_pointset_read_all(const adv_val *a) { return mcs_pointset_read_all(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_pointset2d_add_sets(const adv_val *a) { return mcs_pointset2d_add_sets(a[0].p, a[1].z, a[2].z, a[3].p); }
static int t_pointset2d_add_sets_f(const adv_val *a)
{
    const size_t len = a[2].z != 0u && a[1].z > SIZE_MAX / 2u / a[2].z ? SIZE_MAX : 2u * a[1].z * a[2].z;
    const float *x = adv_floats_begin(a[3].p, len);
    int st = mcs_pointset2d_add_sets_f(a[0].p, a[1].z, a[2].z, x);
    adv_floats_end(a[3].p, len);
    return st;
}
static int t_pointset2d_read_all(const adv_val *a) { return mcs_pointset2d_read_all(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_pointset2d_radial_all(const adv_val *a)
{
    return mcs_pointset2d_radial_all(a[0].p, a[1].z, a[2].p, a[3].p, a[4].p);
}

/* The baselines' F: 8 in 1D, 4 in 2D (adv_objects.c). */
#define PS_OUT(nm, role_) AOUT(nm, E_D, role_, LEN(L_SLOT, 1), F_NULLOK)

const adv_fn adv_fns_abi[] = {
    FN(abi_sizeof, EF_NONE, 1, 0, ENM("type", 7, 0, MCS_ABI_TYPE_COUNT - 1, F_OKIN),
       OUT("size", E_Z, O_RAW, F_NULLOK), OUT("align", E_Z, O_RAW, F_NULLOK)),
    FN(pointset_add_sets, EF_NONE, 1, 2, OBJ_IO("acc", T_POINTSET, 0), SZ_LEN("sets", 3),
       SZ_LEN("k", 6), AIN("points", E_D, R_POINT, LEN2(L_PROD, 1, 2), 0)),
    FN(pointset_add_sets_f, EF_NONE, 1, 2, OBJ_IO("acc", T_POINTSET, 0), SZ_LEN("sets", 3),
       SZ_LEN("k", 6), AIN("points", E_D, R_POINT, LEN2(L_PROD, 1, 2), 0)),
    FN(pointset_read_all, EF_NONE, 1, 0, OBJ_IN("acc", T_POINTSET, 0), SZ_MATCH("n_out", 9, 9),
       PS_OUT("power", O_NN), PS_OUT("power_stderr", O_NN)),
    FN(pointset2d_add_sets, EF_NONE, 1, 2, OBJ_IO("acc", T_POINTSET2D, 0), SZ_LEN("sets", 3),
       SZ_LEN("k", 6), AIN("points", E_D, R_POINT, LEN2(L_PROD2, 1, 2), 0)),
    FN(pointset2d_add_sets_f, EF_NONE, 1, 2, OBJ_IO("acc", T_POINTSET2D, 0), SZ_LEN("sets", 3),
       SZ_LEN("k", 6), AIN("points", E_D, R_POINT, LEN2(L_PROD2, 1, 2), 0)),
    FN(pointset2d_read_all, EF_NONE, 1, 0, OBJ_IN("acc", T_POINTSET2D, 0), SZ_MATCH("side", 9, 9),
       AOUT("power", E_D, O_NN, LEN(L_SQ, 1), F_NULLOK),
       AOUT("power_stderr", E_D, O_NN, LEN(L_SQ, 1), F_NULLOK)),
    FN(pointset2d_radial_all, EF_NONE, 1, 0, OBJ_IN("acc", T_POINTSET2D, 0), SZ_MATCH("n_out", 5, 5),
       PS_OUT("radial", O_NN), PS_OUT("radial_stderr", O_NN), PS_OUT("anisotropy_db", O_RAW)),
};
const size_t adv_fns_abi_count = sizeof adv_fns_abi / sizeof adv_fns_abi[0];
