/* Adversarial table: the blue-noise samplers (bluenoise.h). The draws run
 * with the default parameters (params NULL); mcs_bluenoise_params_resolve's
 * rows mutate the radius. */
#include "adv_table.h"

#include <string.h>

static int t_bluenoise_kind_str(const adv_val *a)
{
    const char *s = mcs_bluenoise_kind_str((mcs_bluenoise_kind)a[0].e);
    const int known = a[0].e >= 0 && a[0].e < MCS_BLUENOISE_KIND_COUNT;
    return s != NULL && known == (strcmp(s, "unknown") != 0) ? MCS_OK : ADV_BROKEN;
}
/* has_dim says exactly which (kind, dim) the size query accepts. */
static int t_bluenoise_has_dim(const adv_val *a)
{
    size_t bytes = 0;
    const int h = mcs_bluenoise_has_dim((mcs_bluenoise_kind)a[0].e, a[1].z);
    const int ok = mcs_bluenoise_work_size((mcs_bluenoise_kind)a[0].e, a[1].z, 8u, &bytes) == MCS_OK;
    return h == ok ? MCS_OK : ADV_BROKEN;
}
/* A resolved radius is the one given, or the default, inside the range. */
static int t_bluenoise_params_resolve(const adv_val *a)
{
    const mcs_bluenoise_params p = {a[2].d, 0u, 0u, 0u, 0u};
    mcs_bluenoise_params *out = a[3].p;
    int st = mcs_bluenoise_params_resolve((mcs_bluenoise_kind)a[0].e, a[1].z, &p, out);
    if (st == MCS_OK && out != NULL && a[0].e <= (int)MCS_BLUENOISE_POISSON_DISK &&
        !(out->radius >= MCS_BLUENOISE_MIN_RADIUS && out->radius <= MCS_BLUENOISE_MAX_RADIUS &&
          (p.radius == 0.0 || out->radius == p.radius)))
        return ADV_BROKEN;
    return st;
}
static int t_bluenoise_work_size(const adv_val *a)
{
    int st = mcs_bluenoise_work_size((mcs_bluenoise_kind)a[0].e, a[1].z, a[2].z, a[3].p);
    return st == MCS_OK && *(size_t *)a[3].p > MCS_BLUENOISE_WORK_SIZE(a[1].z, a[2].z) ? ADV_BROKEN : st;
}
static int t_bluenoise_draw(const adv_val *a)
{
    return mcs_bluenoise_draw((mcs_bluenoise_kind)a[0].e, a[1].z, a[2].z, NULL, a[3].p, a[4].p,
                              a[5].z, a[6].p);
}
/* A maximal set's count is at most its cap, its points in [0, 1) (the
 * rest of the array is not written: the engine sees it as raw). */
static int t_bluenoise_maximal(const adv_val *a)
{
    int st = mcs_bluenoise_maximal((mcs_bluenoise_kind)a[0].e, a[1].z, a[2].z, NULL, a[3].p, a[4].p,
                                   a[5].z, a[6].z, a[7].p, a[8].p);
    if (st != MCS_OK)
        return st;
    const size_t n = *(size_t *)a[8].p;
    const double *p = a[7].p;
    if (n < 1u || n > a[6].z)
        return ADV_BROKEN;
    for (size_t j = 0; j < n * a[1].z; ++j)
        if (!(p[j] >= 0.0 && p[j] < 1.0))
            return ADV_BROKEN;
    return st;
}

#define BK_K 64u
#define BK_WORK MCS_BLUENOISE_WORK_SIZE(3, BK_K)
#define BK_CAP (8u * BK_K + 2u)
#define BK_KIND(fl) ENM("kind", 0, 0, MCS_BLUENOISE_KIND_COUNT - 1, fl)
#define BK_DIM(fl) SZ_DEF("dim", 2, 1, MCS_BLUENOISE_MAX_DIM, fl)
#define BK_KS(fl) SZ_DEF("k", BK_K, 1, MCS_BLUENOISE_MAX_K, fl)
#define BK_LEN(nm, b) {.name = nm, .kind = K_SIZE, .role = Z_LEN, .base = b, .lo = 1, .hi = SIZE_MAX}
#define BK_PARAMS_LEN {.op = L_CONST, .c = sizeof(mcs_bluenoise_params)}
#define BK_RADIUS                                                                       \
    {.name = "radius", .kind = K_DBL, .role = R_RANGE, .dbase = 0.75, .dlo = 0.0,       \
     .dhi = MCS_BLUENOISE_MAX_RADIUS, .flags = 0}

const adv_fn adv_fns_blue[] = {
    FN(bluenoise_kind_str, EF_NONE, 1, 0, BK_KIND(F_FREE)),
    FN(bluenoise_has_dim, EF_NONE, 1, 0, BK_KIND(F_FREE), SZ_FREE("dim", 2)),
    FN(bluenoise_params_resolve, EF_NONE, 1, 0, BK_KIND(0), BK_DIM(F_OKIN), BK_RADIUS,
       AOUT("out", E_U8, O_RAW, BK_PARAMS_LEN, 0)),
    FN(bluenoise_work_size, EF_NONE, 1, 0, BK_KIND(F_OKIN), BK_DIM(F_OKIN), BK_KS(F_OKIN),
       OUT("bytes", E_Z, O_RAW, 0)),
    FN(bluenoise_draw, EF_NONE, 1, 0, BK_KIND(0), BK_DIM(0), BK_KS(0), OBJ_IO("rng", T_RNG, 0),
       AOUT("work", E_U8, O_RAW, LEN(L_SLOT, 5), 0), BK_LEN("work_bytes", BK_WORK),
       AOUT("points", E_D, O_U01, LEN2(L_PROD, 2, 1), 0)),
    FN(bluenoise_maximal, EF_NONE, 1, 0, BK_KIND(0), BK_DIM(0), BK_KS(0), OBJ_IO("rng", T_RNG, 0),
       AOUT("work", E_U8, O_RAW, LEN(L_SLOT, 5), 0), BK_LEN("work_bytes", BK_WORK),
       BK_LEN("cap", BK_CAP), AOUT("points", E_D, O_RAW, LEN2(L_PROD, 6, 1), 0),
       OUT("count", E_Z, O_RAW, 0)),
};
const size_t adv_fns_blue_count = sizeof adv_fns_blue / sizeof adv_fns_blue[0];
