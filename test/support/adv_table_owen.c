/* Adversarial table: the exact theory of Owen-scrambled sets (owen.h). The
 * bases and axes of a projection are two scalars here (base_x, base_y; the
 * axes are 0 and 1 of the points), which the thunks put in arrays; the
 * read-outs read a fixed 2D set of BK points set up here (the table has no
 * object type for mcs_owen), as the rotation's rows do. */
#include "adv_table.h"

static int t_owen_digits(const adv_val *a) { return mcs_owen_digits(a[0].u32, a[1].p); }

static int t_owen_len(const adv_val *a)
{
    const unsigned bases[2] = {a[1].u32, a[2].u32};
    return mcs_owen_len(a[0].z, bases, a[3].p);
}

static int t_owen_init(const adv_val *a)
{
    const size_t axes[2] = {0u, 1u};
    const unsigned bases[2] = {a[4].u32, a[5].u32};
    return mcs_owen_init(a[0].p, a[1].z, a[2].z, a[3].p, a[6].z, axes, bases, a[7].p, a[8].z);
}

/* BK points of a 2D set, bases 2 and 3 (L = 44 and 27). */
static const mcs_owen *base_owen(void)
{
    static mcs_owen ow;
    static uint64_t work[MCS_OWEN_LEN_MAX];
    const double p[2u * BK] = {0.0, 0.0, 0.5, 1.0 / 3.0, 0.25, 2.0 / 3.0,
                               0.75, 1.0 / 9.0, 0.125, 4.0 / 9.0, 0.625, 7.0 / 9.0};
    const size_t axes[2] = {0u, 1u};
    const unsigned bases[2] = {2u, 3u};
    return mcs_owen_init(&ow, BK, 2u, p, 2u, axes, bases, work, MCS_OWEN_LEN_MAX) == MCS_OK ? &ow
                                                                                          : NULL;
}

static int t_owen_power(const adv_val *a) { return mcs_owen_power(base_owen(), a[0].l, a[1].l, a[2].p); }
static int t_owen_pair_count(const adv_val *a)
{
    return mcs_owen_pair_count(base_owen(), a[0].z, a[1].z, a[2].p);
}
static int t_owen_phi(const adv_val *a) { return mcs_owen_phi(a[0].u32, a[1].z, a[2].l, a[3].p); }
static int t_owen_net_pairs(const adv_val *a)
{
    return mcs_owen_net_pairs(a[0].u32, a[1].z, a[2].z, a[3].z, a[4].p);
}
static int t_owen_net_power(const adv_val *a)
{
    return mcs_owen_net_power(a[0].u32, a[1].z, a[2].l, a[3].l, a[4].p);
}
static int t_owen_theory_of(const adv_val *a)
{
    return mcs_owen_theory_of((mcs_sampler_kind)a[0].e, a[1].z, a[2].p);
}

#define BASE(nm, b, fl) U32(nm, b, 2, MCS_OWEN_MAX_BASE, fl)
#define FREQ(nm, b) LNG(nm, b, -MCS_OWEN_MAX_FREQ, MCS_OWEN_MAX_FREQ, F_OKIN)
#define OWEN_LEN {.op = L_CONST, .c = sizeof(mcs_owen)}
#define NET_M SZ_DEF("m", 5, 0, 32, 0)

const adv_fn adv_fns_owen[] = {
    FN(owen_digits, EF_NONE, 1, 0, BASE("base", 3, F_OKIN), OUT("digits", E_U32, O_RAW, 0)),
    FN(owen_len, EF_NONE, 1, 0, SZ_DEF("dims", 2, 1, 2, F_OKIN), BASE("base_x", 2, F_OKIN),
       BASE("base_y", 3, F_OKIN), OUT("len", E_Z, O_RAW, 0)),
    FN(owen_init, EF_NONE, 1, 1, AOUT("ow", E_U8, O_RAW, OWEN_LEN, 0), SZ_LEN("k", BK),
       SZ_DEF("dim", 2, 2, SIZE_MAX, F_NOMAX),
       AIN("points", E_D, R_POINT, LEN2(L_PROD, 1, 2), 0), BASE("base_x", 2, F_OKIN),
       BASE("base_y", 3, F_OKIN), SZ_DEF("dims", 2, 1, 2, F_OKIN),
       AOUT("work", E_U64, O_RAW, LEN(L_SLOT, 8), 0), SZ_LEN("len", MCS_OWEN_LEN_MAX)),
    FN(owen_power, EF_NONE, 1, 0, FREQ("freq_x", 3), FREQ("freq_y", -2), OUT("out", E_D, O_NN, 0)),
    FN(owen_pair_count, EF_NONE, 1, 0, SZ_INDEX("level_x", 1, 0, 44, F_OKIN),
       SZ_INDEX("level_y", 0, 0, 27, F_OKIN), OUT("out", E_U64, O_RAW, 0)),
    FN(owen_phi, EF_NONE, 1, 0, BASE("base", 3, 0), SZ_INDEX("level", 2, 0, 43, 0),
       FREQ("freq", 5), OUT("out", E_D, O_VAL, 0)),
    FN(owen_net_pairs, EF_NONE, 1, 0, BASE("base", 2, 0), NET_M, SZ_FREE("level_x", 1),
       SZ_FREE("level_y", 2), OUT("out", E_U64, O_RAW, 0)),
    FN(owen_net_power, EF_NONE, 1, 0, BASE("base", 2, 0), NET_M, FREQ("freq_x", 3),
       FREQ("freq_y", 1), OUT("out", E_D, O_NN, 0)),
    FN(owen_theory_of, EF_NONE, 1, 0, ENM("kind", MCS_SAMPLER_SOBOL, 0, MCS_SAMPLER_KIND_COUNT - 1, 0),
       SZ_DEF("dim", 2, 1, 2, 0), OUT("out", E_U32, O_RAW, 0)),
};
const size_t adv_fns_owen_count = sizeof adv_fns_owen / sizeof adv_fns_owen[0];
