/* Adversarial table: moment, autocorr and theory. */
#include "adv_table.h"

static int t_moment_init(const adv_val *a) { return mcs_moment_init(a[0].p, a[1].z); }
static int t_moment_add_bins(const adv_val *a) { return mcs_moment_add_bins(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_moment_add_dense(const adv_val *a) { return mcs_moment_add_dense(a[0].p, a[1].z, a[2].p); }
static int t_moment_merge(const adv_val *a) { return mcs_moment_merge(a[0].p, a[1].p); }
static int t_moment_count(const adv_val *a) { return mcs_moment_count(a[0].p, a[1].p); }
static int t_moment_bin_mean(const adv_val *a) { return mcs_moment_bin_mean(a[0].p, a[1].z, a[2].p); }
static int t_moment_bin_second(const adv_val *a) { return mcs_moment_bin_second(a[0].p, a[1].z, a[2].z, a[3].p); }
static int t_moment_mean(const adv_val *a) { return mcs_moment_mean(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_moment_power(const adv_val *a) { return mcs_moment_power(a[0].p, a[1].z, a[2].p); }
static int t_moment_cross(const adv_val *a) { return mcs_moment_cross(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_moment_covariance(const adv_val *a) { return mcs_moment_covariance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_moment_cross_matrix(const adv_val *a) { return mcs_moment_cross_matrix(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_moment_covariance_matrix(const adv_val *a) { return mcs_moment_covariance_matrix(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_moment_estimator_mean(const adv_val *a) { return mcs_moment_estimator_mean(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_moment_variance(const adv_val *a) { return mcs_moment_variance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_moment_estimator_covariance(const adv_val *a)
{
    return mcs_moment_estimator_covariance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p, a[5].p);
}
static int t_autocorr_init(const adv_val *a) { return mcs_autocorr_init(a[0].p, a[1].z); }
static int t_autocorr_add_bins(const adv_val *a) { return mcs_autocorr_add_bins(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_autocorr_merge(const adv_val *a) { return mcs_autocorr_merge(a[0].p, a[1].p); }
static int t_autocorr_count(const adv_val *a) { return mcs_autocorr_count(a[0].p, a[1].p); }
static int t_autocorr_mean(const adv_val *a) { return mcs_autocorr_mean(a[0].p, a[1].p, a[2].z, a[3].p, a[4].p); }
static int t_autocorr_power(const adv_val *a) { return mcs_autocorr_power(a[0].p, a[1].p, a[2].z, a[3].p); }
static int t_theory_init(const adv_val *a) { return mcs_theory_init(a[0].p, a[1].p); }
static int t_theory_bin_mean(const adv_val *a) { return mcs_theory_bin_mean(a[0].p, a[1].z, a[2].p); }
static int t_theory_bin_second(const adv_val *a) { return mcs_theory_bin_second(a[0].p, a[1].z, a[2].z, a[3].p); }
static int t_theory_mean(const adv_val *a) { return mcs_theory_mean(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_theory_power(const adv_val *a) { return mcs_theory_power(a[0].p, a[1].z, a[2].p); }
static int t_theory_cross(const adv_val *a) { return mcs_theory_cross(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_theory_covariance(const adv_val *a) { return mcs_theory_covariance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_theory_cross_matrix(const adv_val *a) { return mcs_theory_cross_matrix(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_theory_covariance_matrix(const adv_val *a) { return mcs_theory_covariance_matrix(a[0].p, a[1].z, a[2].p, a[3].p); }
static int t_theory_estimator_mean(const adv_val *a) { return mcs_theory_estimator_mean(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_theory_variance(const adv_val *a) { return mcs_theory_variance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p); }
static int t_theory_estimator_covariance(const adv_val *a)
{
    return mcs_theory_estimator_covariance(a[0].p, a[1].z, a[2].z, a[3].p, a[4].p, a[5].p);
}

static const uint8_t pattern_vars[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8};

#define MOM_IN OBJ_IN("acc", T_MOMENT, 0)
#define MOM_SIZED OBJ_IN("acc", T_MOMENT, F_SIZED)
#define TH_IN OBJ_IN("th", T_THEORY, 0)
#define TH_SIZED OBJ_IN("th", T_THEORY, F_SIZED)
#define FREQ(nm, b) SZ_INDEX(nm, b, 0, BN - 1u, F_OKIN)
#define OUT_VAL(nm) OUT(nm, E_D, O_VAL, 0)
#define OUT_NN(nm) OUT(nm, E_D, O_NN, 0)
#define MATRIX(nm) AOUT(nm, E_D, O_VAL, LEN(L_SQ, 1), 0)
#define F_OF(nm, slot) AIN(nm, E_D, R_F, LEN(L_SLOT, slot), 0)
/* Read-outs of moment and theory take the same arguments. */
#define SECOND_READOUTS(pre, IN, SIZED, kslot)                                                  \
    FN(pre##_bin_mean, EF_NONE, 1, 0, IN, FREQ("bin", 1), OUT_VAL("out")),                      \
    FN(pre##_bin_second, EF_NONE, 1, 0, IN, FREQ("bin_m", 1), FREQ("bin_n", 2), OUT_VAL("out")), \
    FN(pre##_mean, EF_NONE, 1, 0, IN, FREQ("freq", 1), OUT_VAL("re"), OUT_VAL("im")),           \
    FN(pre##_power, EF_NONE, 1, 0, IN, FREQ("freq", 1), OUT_NN("out")),                          \
    FN(pre##_cross, EF_NONE, 1, 0, IN, FREQ("freq_k", 1), FREQ("freq_l", 2), OUT_VAL("re"),      \
       OUT_VAL("im")),                                                                           \
    FN(pre##_covariance, EF_NONE, 1, 0, IN, FREQ("freq_k", 1), FREQ("freq_l", 2), OUT_VAL("re"), \
       OUT_VAL("im")),                                                                           \
    FN(pre##_cross_matrix, EF_NONE, 1, 0, SIZED, SZ_MATCH("n", BN, MCS_MAX_COV_N), MATRIX("re"), \
       MATRIX("im")),                                                                            \
    FN(pre##_covariance_matrix, EF_NONE, 1, 0, SIZED, SZ_MATCH("n", BN, MCS_MAX_COV_N),          \
       MATRIX("re"), MATRIX("im")),                                                              \
    FN(pre##_estimator_mean, EF_NONE, 1, 0, SIZED, SZ_MATCH("n", BN, MCS_MAX_COV_N), kslot,     \
       F_OF("f", 1), OUT_VAL("out")),                                                            \
    FN(pre##_variance, EF_NONE, 1, 0, SIZED, SZ_MATCH("n", BN, MCS_MAX_COV_N), kslot,           \
       F_OF("f", 1), OUT_NN("out")),                                                             \
    FN(pre##_estimator_covariance, EF_NONE, 1, 0, SIZED, SZ_MATCH("n", BN, MCS_MAX_COV_N),      \
       kslot, F_OF("f", 1), F_OF("g", 1), OUT_VAL("out"))

const adv_fn adv_fns_stats[] = {
    FN(moment_init, EF_INIT, 1, 1, OBJ_OUT("acc", T_MOMENT),
       SZ_DEF("n", BN, 1, MCS_MAX_COV_N, F_OKIN)),
    FN(moment_add_bins, EF_ADD, 1, 0, OBJ_IO("acc", T_MOMENT, 0), SZ_LEN("k", BT),
       AIN("bins", E_Z, R_BINS, LEN(L_SLOT, 1), 0), AIN("weights", E_D, R_WEIGHT, LEN(L_SLOT, 1), 0)),
    FN(moment_add_dense, EF_ADD, 1, 0, OBJ_IO("acc", T_MOMENT, F_SIZED),
       SZ_MATCH("n", BN, MCS_MAX_COV_N), AIN("s", E_D, R_WEIGHT, LEN(L_SLOT, 1), 0)),
    FN(moment_merge, EF_MERGE, 1, 0, OBJ_IO("dst", T_MOMENT, 0), OBJ_IN("src", T_MOMENT, F_SIZED)),
    FN(moment_count, EF_NONE, 1, 0, MOM_IN, OUT("count", E_U64, O_RAW, 0)),
    SECOND_READOUTS(moment, MOM_IN, MOM_SIZED, SZ_NOMAX("k", BK)),
    FN(autocorr_init, EF_INIT, 1, 1, OBJ_OUT("acc", T_AUTOCORR), SZ_DEF("n", BN, 1, MCS_MAX_N, F_OKIN)),
    FN(autocorr_add_bins, EF_ADD, 1, 0, OBJ_IO("acc", T_AUTOCORR, 0), SZ_LEN("k", BT),
       AIN("bins", E_Z, R_BINS, LEN(L_SLOT, 1), 0), AIN("weights", E_D, R_WEIGHT, LEN(L_SLOT, 1), 0)),
    FN(autocorr_merge, EF_MERGE, 1, 0, OBJ_IO("dst", T_AUTOCORR, 0), OBJ_IN("src", T_AUTOCORR, F_SIZED)),
    FN(autocorr_count, EF_NONE, 1, 0, OBJ_IN("acc", T_AUTOCORR, 0), OUT("count", E_U64, O_RAW, 0)),
    FN(autocorr_mean, EF_NONE, 1, 0, OBJ_IN("acc", T_AUTOCORR, F_SIZED), OBJ_IO("plan", T_DFT, F_SIZED),
       SZ_MATCH("n", BN, MCS_MAX_N), AOUT("re", E_D, O_VAL, LEN(L_SLOT, 2), 0),
       AOUT("im", E_D, O_VAL, LEN(L_SLOT, 2), 0)),
    FN(autocorr_power, EF_NONE, 1, 0, OBJ_IN("acc", T_AUTOCORR, F_SIZED), OBJ_IO("plan", T_DFT, F_SIZED),
       SZ_MATCH("n", BN, MCS_MAX_N), AOUT("power", E_D, O_NN, LEN(L_SLOT, 2), 0)),
    FNV(theory_init, EF_NONE, pattern_vars, 1, OBJ_OUT("th", T_THEORY), OBJ_IN("pat", T_PAT, 0)),
    SECOND_READOUTS(theory, TH_IN, TH_SIZED, SZ_MATCH("k", BK, SIZE_MAX)),
};
const size_t adv_fns_stats_count = sizeof adv_fns_stats / sizeof adv_fns_stats[0];
