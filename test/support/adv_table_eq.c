/* Adversarial table: the closed forms of eq.h. */
#include "adv_table.h"

static int t_eq2_uncorrelated_variance(const adv_val *a) { return mcs_eq2_uncorrelated_variance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p, a[5].p); }
static int t_eq4_correlated_variance(const adv_val *a) { return mcs_eq4_correlated_variance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p, a[5].p); }
static int t_eq11_unbiased_mean(const adv_val *a) { return mcs_eq11_unbiased_mean(a[0].z, a[1].p, a[2].p); }
static int t_eq13_variance(const adv_val *a) { return mcs_eq13_variance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_eq14_variance(const adv_val *a) { return mcs_eq14_variance(a[0].z, a[1].z, a[2].p, a[3].p, a[4].p); }
static int t_eq23_random_power(const adv_val *a) { return mcs_eq23_random_power(a[0].z, a[1].z, a[2].z, a[3].p); }
static int t_eq24_random_variance(const adv_val *a) { return mcs_eq24_random_variance(a[0].z, a[1].z, a[2].p, a[3].p); }
static int t_eq25_random_variance(const adv_val *a) { return mcs_eq25_random_variance(a[0].z, a[1].z, a[2].p, a[3].p); }
static int t_eq30_stratified_delta_printed(const adv_val *a) { return mcs_eq30_stratified_delta_printed(a[0].z, a[1].z, a[2].z, a[3].z, a[4].p, a[5].p); }
static int t_eq30_stratified_delta_corrected(const adv_val *a) { return mcs_eq30_stratified_delta_corrected(a[0].z, a[1].z, a[2].z, a[3].z, a[4].p, a[5].p); }
static int t_eq30_stratified_cross(const adv_val *a) { return mcs_eq30_stratified_cross(a[0].z, a[1].z, a[2].z, a[3].z, a[4].p, a[5].p); }
static int t_eq31_stratified_delta_printed(const adv_val *a) { return mcs_eq31_stratified_delta_printed(a[0].z, a[1].z, a[2].z, a[3].p); }
static int t_eq32_stratified_delta(const adv_val *a) { return mcs_eq32_stratified_delta(a[0].z, a[1].z, a[2].z, a[3].p); }
static int t_eq33_stratified_power_exact(const adv_val *a) { return mcs_eq33_stratified_power_exact(a[0].z, a[1].z, a[2].z, a[3].p); }
static int t_eq33_stratified_power_limit(const adv_val *a) { return mcs_eq33_stratified_power_limit(a[0].z, a[1].z, a[2].z, a[3].p); }
static int t_eq34_uniform_spectrum(const adv_val *a) { return mcs_eq34_uniform_spectrum(a[0].z, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_eq35_jitter_mean(const adv_val *a) { return mcs_eq35_jitter_mean(a[0].z, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_eq37_jitter_power(const adv_val *a) { return mcs_eq37_jitter_power(a[0].z, a[1].z, a[2].z, a[3].p); }
static int t_eq41_importance_second(const adv_val *a) { return mcs_eq41_importance_second(a[0].p, a[1].z, a[2].z, a[3].z, a[4].p); }
static int t_eq43_importance_cross(const adv_val *a) { return mcs_eq43_importance_cross(a[0].p, a[1].z, a[2].z, a[3].z, a[4].p, a[5].p); }
static int t_eq45_importance_power(const adv_val *a) { return mcs_eq45_importance_power(a[0].p, a[1].z, a[2].z, a[3].p); }
static int t_eq46_importance_power0(const adv_val *a) { return mcs_eq46_importance_power0(a[0].p, a[1].z, a[2].p); }
static int t_eq49_importance_stratified_cross(const adv_val *a) { return mcs_eq49_importance_stratified_cross(a[0].p, a[1].z, a[2].z, a[3].z, a[4].p, a[5].p); }
static int t_eq50_importance_stratified_power(const adv_val *a) { return mcs_eq50_importance_stratified_power(a[0].p, a[1].z, a[2].z, a[3].p); }
static int t_eq52_variance_printed(const adv_val *a) { return mcs_eq52_variance_printed(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_eq52_variance_corrected(const adv_val *a) { return mcs_eq52_variance_corrected(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_eq55_variance_convolution(const adv_val *a) { return mcs_eq55_variance_convolution(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_eq58_bound_printed(const adv_val *a) { return mcs_eq58_bound_printed(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_eq58_bound_corrected(const adv_val *a) { return mcs_eq58_bound_corrected(a[0].p, a[1].z, a[2].p, a[3].p); }
/* The exact read-outs added beside the closed forms (theory.h). */
static int t_theory_bias(const adv_val *a) { return mcs_theory_bias(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_theory_spectrum_bias(const adv_val *a)
{
    return mcs_theory_spectrum_bias(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p);
}
static int t_theory_rotation_init(const adv_val *a)
{
    return mcs_theory_rotation_init(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p, a[5].z);
}
/* The read-outs of the rotation of a fixed set of BK points over BN bins
 * (set up here: the table has no object type for it). */
static const mcs_theory_rotation *base_rotation(void)
{
    static mcs_theory_rotation rot;
    static double work[BN];
    const double a[BK] = {0.0, 0.5, 0.25, 0.75, 0.3, 0.93};
    return mcs_theory_rotation_init(&rot, BN, BK, a, work, BN) == MCS_OK ? &rot : NULL;
}
static int t_theory_rotation_mean(const adv_val *a)
{
    return mcs_theory_rotation_mean(base_rotation(), a[0].z, a[1].p, a[2].p);
}
static int t_theory_rotation_power(const adv_val *a)
{
    return mcs_theory_rotation_power(base_rotation(), a[0].z, a[1].p);
}
static int t_theory_rotation_variance(const adv_val *a)
{
    return mcs_theory_rotation_variance(base_rotation(), a[0].z, a[1].z, a[2].p, a[3].p);
}
static int t_theory_spectrum_read_all(const adv_val *a)
{
    return mcs_theory_spectrum_read_all(a[0].p, a[1].z, a[2].p, a[3].p, a[4].p, a[5].p);
}

#define TH OBJ_IN("th", T_THEORY, F_SIZED)
#define ROT_LEN {.op = L_CONST, .c = sizeof(mcs_theory_rotation)}
#define N_MATCH SZ_MATCH("n", BN, MCS_MAX_COV_N)
#define K_MATCH SZ_MATCH("k", BK, SIZE_MAX)
#define N_ANY SZ_DEF("n", BN, 1, MCS_MAX_N, 0)
#define K_ANY SZ_NOMAX("k", BK)
#define FREQ1(nm, b) SZ_INDEX(nm, b, 1, BN - 1u, 0)
#define FREQ0(nm, b) SZ_INDEX(nm, b, 0, BN - 1u, 0)
#define F_N(nm, slot) AIN(nm, E_D, R_F, LEN(L_SLOT, slot), 0)
#define F_IMP(nm) AIN(nm, E_D, R_F, LEN(L_OBJN, 0), 0)
#define OUT_VAL(nm) OUT(nm, E_D, O_VAL, 0)
#define OUT_NN(nm) OUT(nm, E_D, O_NN, 0)
#define IMP OBJ_IN("imp", T_IMP, F_NULLERR)
/* Section 3 forms: (n, k, freq..., outputs). */
#define EQ_NKF(sfx, F, out) FN(sfx, EF_NONE, 1, 0, N_ANY, K_ANY, F("freq", 1), out)
#define EQ_NKFF(sfx, F)                                                                        \
    FN(sfx, EF_NONE, 1, 0, N_ANY, K_ANY, F("freq_k", 1), F("freq_l", 1), OUT_VAL("re"),         \
       OUT_VAL("im"))
#define EQ_IMP_F(sfx, out) FN(sfx, EF_NONE, 1, 0, IMP, K_ANY, F_IMP("f"), out)

const adv_fn adv_fns_eq[] = {
    FN(eq2_uncorrelated_variance, EF_NONE, 1, 0, TH, N_MATCH, K_MATCH, F_N("f", 1), F_N("g", 1),
       OUT_NN("out")),
    FN(eq4_correlated_variance, EF_NONE, 1, 0, TH, N_MATCH, K_MATCH, F_N("f", 1), F_N("g", 1),
       OUT_NN("out")),
    FN(eq11_unbiased_mean, EF_NONE, 1, 0, SZ_DEF("n", BN, 1, MCS_MAX_N, F_OKIN), F_N("f", 0),
       OUT_VAL("out")),
    FN(eq13_variance, EF_NONE, 1, 0, TH, N_MATCH, K_MATCH, F_N("f", 1), OUT_VAL("out")),
    FN(eq14_variance, EF_NONE, 1, 0, SZ_DEF("n", BN, 1, MCS_MAX_N, F_OKIN), K_ANY,
       F_N("f", 0), F_N("power", 0), OUT_VAL("out")),
    EQ_NKF(eq23_random_power, FREQ1, OUT_NN("out")),
    FN(eq24_random_variance, EF_NONE, 1, 0, N_ANY, K_ANY, F_N("f", 0), OUT_NN("out")),
    FN(eq25_random_variance, EF_NONE, 1, 0, N_ANY, K_ANY, F_N("f", 0), OUT_NN("out")),
    EQ_NKFF(eq30_stratified_delta_printed, FREQ1),
    EQ_NKFF(eq30_stratified_delta_corrected, FREQ0),
    EQ_NKFF(eq30_stratified_cross, FREQ0),
    EQ_NKF(eq31_stratified_delta_printed, FREQ1, OUT_VAL("out")),
    EQ_NKF(eq32_stratified_delta, FREQ1, OUT_VAL("out")),
    EQ_NKF(eq33_stratified_power_exact, FREQ1, OUT_NN("out")),
    EQ_NKF(eq33_stratified_power_limit, FREQ1, OUT_NN("out")),
    FN(eq34_uniform_spectrum, EF_NONE, 1, 0, N_ANY, K_ANY, FREQ0("freq", 1), OUT_VAL("re"),
       OUT_VAL("im")),
    FN(eq35_jitter_mean, EF_NONE, 1, 0, N_ANY, K_ANY, FREQ0("freq", 1), OUT_VAL("re"),
       OUT_VAL("im")),
    EQ_NKF(eq37_jitter_power, FREQ0, OUT_NN("out")),
    FN(eq41_importance_second, EF_NONE, 1, 0, IMP, K_ANY, FREQ0("bin_m", 1), FREQ0("bin_n", 2),
       OUT_NN("out")),
    FN(eq43_importance_cross, EF_NONE, 1, 0, IMP, K_ANY, FREQ0("freq_k", 1), FREQ0("freq_l", 2),
       OUT_VAL("re"), OUT_VAL("im")),
    FN(eq45_importance_power, EF_NONE, 1, 0, IMP, K_ANY, FREQ1("freq", 1), OUT_NN("out")),
    FN(eq46_importance_power0, EF_NONE, 1, 0, IMP, K_ANY, OUT_NN("out")),
    FN(eq49_importance_stratified_cross, EF_NONE, 1, 0, IMP, K_ANY, FREQ1("freq_k", 1),
       FREQ1("freq_l", 2), OUT_VAL("re"), OUT_VAL("im")),
    FN(eq50_importance_stratified_power, EF_NONE, 1, 0, IMP, K_ANY, FREQ1("freq", 1),
       OUT_VAL("out")),
    EQ_IMP_F(eq52_variance_printed, OUT_VAL("out")),
    EQ_IMP_F(eq52_variance_corrected, OUT_NN("out")),
    EQ_IMP_F(eq55_variance_convolution, OUT_VAL("out")),
    EQ_IMP_F(eq58_bound_printed, OUT_NN("out")),
    EQ_IMP_F(eq58_bound_corrected, OUT_NN("out")),
    FN(theory_spectrum_read_all, EF_NONE, 1, 0, OBJ_IN("ts", T_TSPEC, F_SIZED),
       SZ_MATCH("n_out", BN / 2u + 1u, MCS_MAX_N / 2u + 1u),
       AOUT("mean_re", E_D, O_VAL, LEN(L_SLOT, 1), F_NULLOK),
       AOUT("mean_im", E_D, O_VAL, LEN(L_SLOT, 1), F_NULLOK),
       AOUT("variance", E_D, O_NN, LEN(L_SLOT, 1), F_NULLOK),
       AOUT("power", E_D, O_NN, LEN(L_SLOT, 1), F_NULLOK)),
    FN(theory_bias, EF_NONE, 1, 0, TH, N_MATCH, K_MATCH, F_N("f", 1), OUT_VAL("out")),
    FN(theory_spectrum_bias, EF_NONE, 1, 0, OBJ_IN("ts", T_TSPEC, F_SIZED),
       SZ_MATCH("n", BN, MCS_MAX_N), K_MATCH, F_N("f", 1), OUT_VAL("out")),
    FN(theory_rotation_init, EF_NONE, 1, 1,
       AOUT("rot", E_U8, O_RAW, ROT_LEN, 0),
       SZ_DEF("n", BN, 1, MCS_MAX_N, 0), SZ_LEN("k", BK),
       AIN("points", E_D, R_POINT, LEN(L_SLOT, 2), 0), AOUT("work", E_D, O_NN, LEN(L_SLOT, 5), 0),
       SZ_LEN("len", BN)),
    FN(theory_rotation_mean, EF_NONE, 1, 0, SZ_INDEX("freq", 0, 0, BN - 1u, F_OKIN),
       OUT_VAL("re"), OUT_VAL("im")),
    FN(theory_rotation_power, EF_NONE, 1, 0, SZ_INDEX("freq", 1, 0, BN - 1u, F_OKIN),
       OUT_NN("out")),
    FN(theory_rotation_variance, EF_NONE, 1, 0, SZ_MATCH("n", BN, MCS_MAX_N),
       SZ_MATCH("k", BK, SIZE_MAX), F_N("f", 0), OUT_NN("out")),
};
const size_t adv_fns_eq_count = sizeof adv_fns_eq / sizeof adv_fns_eq[0];
