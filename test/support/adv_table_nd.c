/* Adversarial table: the any-dimension samplers' calls and the projection
 * analysis (issue 26). The projections object is not an object type of the
 * engine yet: its thunks build one over static memory, call, and check
 * themselves that a refused call changed neither the object nor its buffer
 * (and that NULL and never-initialised objects are refused). */
#include "adv_table.h"

#include <string.h>

static int t_sampler_init_padded(const adv_val *a)
{
    return mcs_sampler_init_padded(a[0].p, (mcs_sampler_kind)a[1].e, a[2].z, a[3].z);
}
static int t_sampler_init_lattice(const adv_val *a)
{
    return mcs_sampler_init_lattice(a[0].p, a[1].z, a[2].z, a[3].u32);
}
/* A generator for every (k, dim) in range, 1 <= g < k (g = 1 at k <= 2 or
 * dim 1), coprime to k; 0 out of range. */
static int t_sampler_lattice_generator(const adv_val *a)
{
    const size_t k = a[0].z, dim = a[1].z;
    const uint32_t g = mcs_sampler_lattice_generator(k, dim);
    const int in = k >= 1u && (uint64_t)k - 1u <= UINT32_MAX && dim >= 1u && dim <= MCS_SAMPLER_MAX_DIM;
    if (!in)
        return g == 0u ? MCS_OK : ADV_BROKEN;
    if (k <= 2u || dim == 1u)
        return g == 1u ? MCS_OK : ADV_BROKEN;
    uint64_t x = g, y = k;
    while (y != 0u) {
        uint64_t t = x % y;
        x = y;
        y = t;
    }
    return g >= 2u && (uint64_t)g < (uint64_t)k && x == 1u ? MCS_OK : ADV_BROKEN;
}
static int t_sampler_base_is_exact(const adv_val *a)
{
    const int e = a[0].e, r = mcs_sampler_base_is_exact((mcs_sampler_kind)e);
    const int want = e == MCS_SAMPLER_VAN_DER_CORPUT || e == MCS_SAMPLER_HALTON ||
                     e == MCS_SAMPLER_HAMMERSLEY || e == MCS_SAMPLER_KRONECKER ||
                     e == MCS_SAMPLER_LATTICE;
    return r == want ? MCS_OK : ADV_BROKEN;
}

static int t_projections_size(const adv_val *a)
{
    return mcs_projections_size(a[0].z, a[1].z, a[2].z, a[3].p);
}

/* The baseline projections object: 3 dimensions, F = 4, R = 2, K <= 16. */
#define PJ_DIM 3u
#define PJ_F 4u
#define PJ_K 16u
#define PJ_MEM MCS_PROJECTIONS_SIZE(PJ_DIM, PJ_F, PJ_K)
static unsigned char pj_mem[PJ_MEM + 8u];
static double pj_points[PJ_DIM * PJ_K];

/* NULL and a never-initialised (zeroed) object are refused by every call. */
static int refuses_bad_objects(void)
{
    mcs_projections zero;
    mcs_projections_pair out;
    size_t c = 0;
    memset(&zero, 0, sizeof zero);
    return mcs_projections_add(NULL, 4u, pj_points) == MCS_ERR_NULL &&
           mcs_projections_add(&zero, 4u, pj_points) == MCS_ERR_UNINIT &&
           mcs_projections_pair_stats(&zero, 0u, 1u, &out) == MCS_ERR_UNINIT &&
           mcs_projections_flagged(&zero, &c) == MCS_ERR_UNINIT &&
           mcs_projections_flagged(NULL, &c) == MCS_ERR_NULL;
}

/* p initialised over pj_mem with `sets` sets of PJ_K points added. */
static int baseline(mcs_projections *p, int sets)
{
    if (mcs_projections_init(p, PJ_DIM, PJ_F, 2u, PJ_K, 1u, pj_mem, sizeof pj_mem) != MCS_OK)
        return 0;
    for (int s = 0; s < sets; ++s) {
        for (size_t q = 0; q < PJ_DIM * PJ_K; ++q)
            pj_points[q] = (double)((q * 7u + (size_t)s * 5u) % 97u) / 97.0;
        if (mcs_projections_add(p, PJ_K, pj_points) != MCS_OK)
            return 0;
    }
    return 1;
}

static int t_projections_init(const adv_val *a)
{
    mcs_projections p, before;
    memset(&p, 0xa5, sizeof p);
    before = p;
    if (mcs_projections_init(NULL, a[0].z, a[1].z, a[2].z, a[3].z, a[4].z, a[5].p, a[6].z) ==
        MCS_OK)
        return ADV_BROKEN;
    mcs_status st = mcs_projections_init(&p, a[0].z, a[1].z, a[2].z, a[3].z, a[4].z, a[5].p, a[6].z);
    if (st != MCS_OK && memcmp(&p, &before, sizeof p) != 0)
        return ADV_BROKEN;
    return st;
}

static int t_projections_add(const adv_val *a)
{
    static unsigned char copy[sizeof pj_mem];
    mcs_projections p;
    if (!refuses_bad_objects() || !baseline(&p, 1))
        return ADV_BROKEN;
    const mcs_projections before = p;
    memcpy(copy, pj_mem, sizeof pj_mem);
    mcs_status st = mcs_projections_add(&p, a[0].z, a[1].p);
    if (st != MCS_OK && (memcmp(&p, &before, sizeof p) != 0 || memcmp(copy, pj_mem, sizeof copy) != 0))
        return ADV_BROKEN;
    return st;
}

static int t_projections_pair_stats(const adv_val *a)
{
    mcs_projections p;
    mcs_projections_pair out, before;
    if (!refuses_bad_objects() || !baseline(&p, 2))
        return ADV_BROKEN;
    memset(&out, 0x5a, sizeof out);
    before = out;
    if (mcs_projections_pair_stats(&p, a[0].z, a[1].z, NULL) == MCS_OK)
        return ADV_BROKEN;
    mcs_status st = mcs_projections_pair_stats(&p, a[0].z, a[1].z, &out);
    if (st != MCS_OK && memcmp(&out, &before, sizeof out) != 0)
        return ADV_BROKEN;
    return st;
}

static int t_projections_flagged(const adv_val *a)
{
    mcs_projections p;
    if (!refuses_bad_objects() || !baseline(&p, 2))
        return ADV_BROKEN;
    return mcs_projections_flagged(&p, a[0].p);
}

#define PTS_CONST {.op = L_CONST, .c = PJ_DIM * PJ_K}

const adv_fn adv_fns_nd[] = {
    FN(sampler_init_padded, EF_NONE, 1, 3, OBJ_OUT("s", T_SAMPLER), ENM("pad", 3, 1, 4, F_OKIN),
       SZ_DEF("dim", 4, 2, MCS_SAMPLER_MAX_DIM, F_OKIN),
       SZ_DEF("k", 8, 1, (size_t)UINT32_MAX, F_OKIN)),
    FN(sampler_init_lattice, EF_NONE, 1, 2, OBJ_OUT("s", T_SAMPLER),
       SZ_DEF("dim", 4, 1, MCS_SAMPLER_MAX_DIM, F_OKIN), SZ_DEF("k", 16, 1, (size_t)1 << 32, 0),
       U32("g", 5, 1, 15, 0)),
    FN(sampler_lattice_generator, EF_NONE, 1, 0, SZ_FREE("k", 16), SZ_FREE("dim", 3)),
    FN(sampler_base_is_exact, EF_NONE, 1, 0, ENM("kind", 0, 0, 9, F_FREE)),
    FN(projections_size, EF_NONE, 1, 0, SZ_DEF("dim", 4, 2, MCS_PROJECTIONS_MAX_DIM, F_OKIN),
       SZ_DEF("freq", 4, 1, MCS_PROJECTIONS_MAX_FREQ, F_OKIN),
       SZ_DEF("k_max", 16, 1, (size_t)1 << 31, F_OKIN), OUT("bytes", E_Z, O_RAW, 0)),
    FN(projections_init, EF_NONE, 1, 0, SZ_DEF("dim", PJ_DIM, 2, PJ_DIM, 0),
       SZ_DEF("freq", PJ_F, 1, PJ_F, 0), SZ_INDEX("radius", 2, 1, PJ_F, 0),
       SZ_DEF("k_max", PJ_K, 1, PJ_K, 0), SZ_FREE("disc_sets", 1), MEM(6),
       SZ_LEN("bytes", PJ_MEM)),
    FN(projections_add, EF_NONE, 1, 0, SZ_DEF("k", PJ_K, 1, PJ_K, F_OKIN),
       AIN("points", E_D, R_POINT, PTS_CONST, 0)),
    FN(projections_pair_stats, EF_NONE, 1, 0, SZ_INDEX("i", 0, 0, PJ_DIM - 1u, 0),
       SZ_INDEX("j", 2, 0, PJ_DIM - 1u, 0)),
    FN(projections_flagged, EF_NONE, 1, 0, OUT("count", E_Z, O_RAW, 0)),
};
const size_t adv_fns_nd_count = sizeof adv_fns_nd / sizeof adv_fns_nd[0];
