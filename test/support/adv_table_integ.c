/* Adversarial table: the integrand families and the integration-error
 * accumulator (integrand.h, integrate.h). The integrand arrays of
 * mcs_integrate_add and the predictions are one integrand object, so m is
 * tried at 0 and 1 only (F_BACKED): a larger m would read past the array,
 * which the call cannot see and ASan reports (make test SAN=1). */
#include "adv_table.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

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

/* After a successful update: every read-out finite and >= 0, or a
 * documented refusal of a state with too few sets. */
static int integrate_after(int st, const mcs_integrate *acc)
{
    if (st != MCS_OK || acc == NULL)
        return st;
    uint64_t n = 0;
    double v;
    if (mcs_integrate_count(acc, &n) != MCS_OK)
        return broken("count refused after a success");
    mcs_status r = mcs_integrate_mse(acc, &v);
    if (r == MCS_OK ? !(isfinite(v) && v >= 0.0) : !(r == MCS_ERR_EMPTY && n == 0u))
        return broken("mse %s %g after a success", mcs_status_str(r), v);
    r = mcs_integrate_mse_stderr(acc, &v);
    if (r == MCS_OK ? !(isfinite(v) && v >= 0.0) : !(r == MCS_ERR_EMPTY && n < 2u))
        return broken("mse_stderr %s %g after a success", mcs_status_str(r), v);
    r = mcs_integrate_exact(acc, &v);
    if (r == MCS_OK ? !(isfinite(v) && v >= 0.0) : r != MCS_ERR_EMPTY && r != MCS_ERR_DOMAIN)
        return broken("exact %s %g after a success", mcs_status_str(r), v);
    return MCS_OK;
}

static int t_integrand_family_str(const adv_val *a)
{
    const char *s = mcs_integrand_family_str((mcs_integrand_family)a[0].e);
    const int known = a[0].e >= 0 && a[0].e < MCS_INTEGRAND_FAMILIES;
    return s != NULL && known == (strcmp(s, "unknown") != 0) ? MCS_OK : ADV_BROKEN;
}
static int t_integrand_is_periodic(const adv_val *a)
{
    const int p = mcs_integrand_is_periodic((mcs_integrand_family)a[0].e);
    const int want = a[0].e == MCS_INTEGRAND_GAUSSIAN_PERIODIC || a[0].e == MCS_INTEGRAND_DISK ||
                     a[0].e == MCS_INTEGRAND_COSINE;
    return p == want ? MCS_OK : broken("is_periodic(%d) = %d", a[0].e, p);
}
static int t_integrand_has_dim(const adv_val *a)
{
    const int h = mcs_integrand_has_dim((mcs_integrand_family)a[0].e, a[1].z);
    const int want = a[0].e >= 0 && a[0].e < MCS_INTEGRAND_FAMILIES &&
                     (a[1].z == 2u || (a[1].z == 1u && a[0].e != MCS_INTEGRAND_BLINN_PHONG));
    return h == want ? MCS_OK : broken("has_dim(%d, %zu) = %d", a[0].e, a[1].z, h);
}
static int t_integrand_draw(const adv_val *a)
{
    const int st = mcs_integrand_draw(a[0].p, (mcs_integrand_family)a[1].e, a[2].z, a[3].p);
    double v;
    if (st == MCS_OK && mcs_integrand_integral(a[0].p, &v) != MCS_OK)
        return broken("a drawn integrand is refused");
    return st;
}
static int t_integrand_eval(const adv_val *a) { return mcs_integrand_eval(a[0].p, a[1].p, a[2].p); }
static int t_integrand_estimate(const adv_val *a)
{
    return mcs_integrand_estimate(a[0].p, a[1].z, a[2].p, a[3].p);
}
static int t_integrand_integral(const adv_val *a) { return mcs_integrand_integral(a[0].p, a[1].p); }
static int t_integrand_variance(const adv_val *a) { return mcs_integrand_variance(a[0].p, a[1].p); }
static int t_integrand_jittered_mse(const adv_val *a)
{
    return mcs_integrand_jittered_mse(a[0].p, a[1].z, a[2].z, a[3].p);
}
static int t_integrand_power(const adv_val *a) { return mcs_integrand_power(a[0].p, a[1].l, a[2].l, a[3].p); }
static int t_integrand_predict(const adv_val *a)
{
    return mcs_integrand_predict(a[0].p, a[1].z, a[2].p, a[3].z, a[4].p, a[5].p);
}
static int t_integrand_predict_1d(const adv_val *a)
{
    return mcs_integrand_predict_1d(a[0].p, a[1].z, a[2].p, a[3].z, a[4].p, a[5].p);
}
static int t_integrate_init(const adv_val *a)
{
    return integrate_after(mcs_integrate_init(a[0].p, (mcs_integrand_family)a[1].e, a[2].z), a[0].p);
}
static int t_integrate_add(const adv_val *a)
{
    return integrate_after(mcs_integrate_add(a[0].p, a[1].z, a[2].p, a[3].z, a[4].p,
                                             (mcs_integrate_reference)a[5].e, a[6].z, a[7].z),
                           a[0].p);
}
static int t_integrate_merge(const adv_val *a) { return integrate_after(mcs_integrate_merge(a[0].p, a[1].p), a[0].p); }
static int t_integrate_count(const adv_val *a) { return mcs_integrate_count(a[0].p, a[1].p); }
static int t_integrate_mse(const adv_val *a) { return mcs_integrate_mse(a[0].p, a[1].p); }
static int t_integrate_mse_stderr(const adv_val *a) { return mcs_integrate_mse_stderr(a[0].p, a[1].p); }
static int t_integrate_exact(const adv_val *a) { return mcs_integrate_exact(a[0].p, a[1].p); }

#define CONST_LEN(n) {.op = L_CONST, .c = n}
#define OUT_VAL(nm) OUT(nm, E_D, O_VAL, 0)
#define OUT_NN(nm) OUT(nm, E_D, O_NN, 0)
#define F_IN OBJ_IN("f", T_INTEGRAND, 0)
#define FS_IN OBJ_IN("fs", T_INTEGRAND, F_SIZED)
#define ONE_M SZ_DEF("m", 1, 1, 1, F_OKIN | F_BACKED)
#define FAMILY ENM("family", MCS_INTEGRAND_DISK, 0, MCS_INTEGRAND_FAMILIES - 1, F_OKIN)
#define DIM SZ_DEF("dim", 2, 1, 2, F_OKIN)
#define ACC_IN OBJ_IN("acc", T_INTEGRATE, 0)
#define K_LEN(nm, b, lo_, fl) \
    {.name = nm, .kind = K_SIZE, .role = Z_LEN, .base = b, .lo = lo_, .hi = SIZE_MAX, .flags = fl}
#define K_ANY(nm, b, lo_, fl) \
    {.name = nm, .kind = K_SIZE, .role = Z_DEF, .base = b, .lo = lo_, .hi = SIZE_MAX, .flags = F_NOMAX | (fl)}
#define FREQ(nm, b) LNG(nm, b, -(long)MCS_POINTSET_MAX_FREQ, (long)MCS_POINTSET_MAX_FREQ, 0)
#define STRATA(nm, b) SZ_DEF(nm, b, 1, MCS_INTEGRAND_JITTERED_MAX_K, 0)

/* The 1D integrand (adv_objects.c's variant 1); the disk and utk's two
 * (variants 2 and 3). */
static const uint8_t one_d[1] = {1};
static const uint8_t with_utk[3] = {0, 2, 3};

const adv_fn adv_fns_integ[] = {
    FN(integrand_family_str, EF_NONE, 1, 0, ENM("family", 0, 0, MCS_INTEGRAND_FAMILIES - 1, F_FREE)),
    FN(integrand_is_periodic, EF_NONE, 1, 0, ENM("family", 0, 0, MCS_INTEGRAND_FAMILIES - 1, F_FREE)),
    FN(integrand_has_dim, EF_NONE, 1, 0,
       ENM("family", MCS_INTEGRAND_BLINN_PHONG, 0, MCS_INTEGRAND_FAMILIES - 1, F_FREE),
       SZ_FREE("dim", 2)),
    FN(integrand_draw, EF_NONE, 1, 0, OBJ_OUT("f", T_INTEGRAND), FAMILY, DIM,
       OBJ_IO("rng", T_RNG, 0)),
    FNV(integrand_eval, EF_NONE, with_utk, 0, F_IN, AIN("x", E_D, R_POINT, CONST_LEN(2), 0),
       OUT_VAL("out")),
    FNV(integrand_estimate, EF_NONE, with_utk, 0, F_IN, K_LEN("k", BK, 1, F_OKIN),
       AIN("points", E_D, R_POINT, LEN(L_2SLOT, 1), 0), OUT_VAL("out")),
    FNV(integrand_integral, EF_NONE, with_utk, 0, F_IN, OUT_NN("out")),
    FNV(integrand_variance, EF_NONE, with_utk, 0, F_IN, OUT_NN("out")),
    FN(integrand_jittered_mse, EF_NONE, 1, 0, F_IN, STRATA("strata_x", 4), STRATA("strata_y", 3),
       OUT_NN("out")),
    FN(integrand_power, EF_NONE, 1, 0, F_IN, FREQ("freq_x", 2), FREQ("freq_y", 0), OUT_NN("out")),
    FN(integrand_predict, EF_NONE, 1, 0, FS_IN, ONE_M, OBJ_IN("ps", T_POINTSET2D, 0),
       K_ANY("k", BK, 1, F_OKIN), OUT_NN("predicted"), OUT_NN("tail")),
    FNV(integrand_predict_1d, EF_NONE, one_d, 0, FS_IN, ONE_M,
       OBJ_IN("ps", T_POINTSET, 0), K_ANY("k", BK, 1, F_OKIN), OUT_NN("predicted"), OUT_NN("tail")),

    FN(integrate_init, EF_INIT, 1, 0, OBJ_OUT("acc", T_INTEGRATE), FAMILY, DIM),
    FN(integrate_add, EF_ADD, 1, 0, OBJ_IO("acc", T_INTEGRATE, 0), ONE_M, FS_IN,
       K_LEN("k", ADV_LONG_LEN, 1, F_OKIN), AIN("points", E_D, R_POINT, LEN(L_OBJNN, 0), 0),
       ENM("reference", 1, 0, 2, 0), SZ_FREE("strata_x", 40), SZ_FREE("strata_y", 25)),
    FN(integrate_merge, EF_MERGE, 1, 0, OBJ_IO("dst", T_INTEGRATE, 0), OBJ_IN("src", T_INTEGRATE, F_SIZED)),
    FN(integrate_count, EF_NONE, 1, 0, ACC_IN, OUT("count", E_U64, O_RAW, 0)),
    FN(integrate_mse, EF_NONE, 1, 0, ACC_IN, OUT_NN("out")),
    FN(integrate_mse_stderr, EF_NONE, 1, 0, ACC_IN, OUT_NN("out")),
    FN(integrate_exact, EF_NONE, 1, 0, ACC_IN, OUT_NN("out")),
};
const size_t adv_fns_integ_count = sizeof adv_fns_integ / sizeof adv_fns_integ[0];
