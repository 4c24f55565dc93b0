/* Slot and function descriptors of the adversarial table (adv_table_*.c).
 * Every public function is one thunk (its arguments from an adv_val array)
 * and one FN line of slots in argument order. */
#ifndef ADV_TABLE_H
#define ADV_TABLE_H

#include "adv.h"

#include <stdint.h>

/* Objects: const input, updated, initialised. */
#define OBJ_IN(nm, t, fl) {.name = nm, .kind = K_OBJ_IN, .type = t, .flags = fl}
#define OBJ_IO(nm, t, fl) {.name = nm, .kind = K_OBJ_IO, .type = t, .flags = fl}
#define OBJ_OUT(nm, t) {.name = nm, .kind = K_OBJ_OUT, .type = t}
/* size_t scalars: a defined size in [lo, hi], a size that must equal the
 * object's (b), an index in [lo, hi], an array length (>= lo), a free value. */
#define SZ_DEF(nm, b, lo_, hi_, fl) \
    {.name = nm, .kind = K_SIZE, .role = Z_DEF, .base = b, .lo = lo_, .hi = hi_, .flags = fl}
#define SZ_NOMAX(nm, b) \
    {.name = nm, .kind = K_SIZE, .role = Z_DEF, .base = b, .lo = 1, .hi = SIZE_MAX, .flags = F_NOMAX}
#define SZ_MATCH(nm, b, hi_) \
    {.name = nm, .kind = K_SIZE, .role = Z_MATCH, .base = b, .lo = b, .hi = hi_}
#define SZ_INDEX(nm, b, lo_, hi_, fl) \
    {.name = nm, .kind = K_SIZE, .role = Z_INDEX, .base = b, .lo = lo_, .hi = hi_, .flags = fl}
#define SZ_LEN(nm, b) {.name = nm, .kind = K_SIZE, .role = Z_LEN, .base = b, .lo = 1, .hi = SIZE_MAX}
#define SZ_FREE(nm, b) {.name = nm, .kind = K_SIZE, .role = Z_FREE, .base = b, .hi = SIZE_MAX}
/* Other scalars. */
#define DBL(nm, role_, b) {.name = nm, .kind = K_DBL, .role = role_, .dbase = b}
#define U32(nm, b, lo_, hi_, fl) \
    {.name = nm, .kind = K_U32, .base = b, .llo = lo_, .lhi = hi_, .flags = fl}
#define U64(nm, b) {.name = nm, .kind = K_U64, .base = b, .flags = F_OKIN}
/* A u64 that must be at most hi_ (> 0): rows at hi_ and hi_ + 1 too. */
#define U64_MAX_(nm, b, hi_) {.name = nm, .kind = K_U64, .base = b, .lhi = (long)(hi_), .flags = F_OKIN}
#define LNG(nm, b, lo_, hi_, fl) \
    {.name = nm, .kind = K_LONG, .base = (uint64_t)(b), .llo = lo_, .lhi = hi_, .flags = fl}
#define ENM(nm, b, lo_, hi_, fl) \
    {.name = nm, .kind = K_ENUM, .base = b, .llo = lo_, .lhi = hi_, .flags = fl}
#define FNP(nm) {.name = nm, .kind = K_FN}
#define CTX(nm) {.name = nm, .kind = K_CTX, .flags = F_NULLOK}
/* Arrays: element type, content role (input) or check (output), length. */
#define LEN(op_, a_) {.op = op_, .a = a_}
#define LEN2(op_, a_, b_) {.op = op_, .a = a_, .b = b_}
#define AIN(nm, et, role_, len_, fl) \
    {.name = nm, .kind = K_ARR_IN, .type = et, .role = role_, .len = len_, .flags = fl}
#define AOUT(nm, et, role_, len_, fl) \
    {.name = nm, .kind = K_ARR_OUT, .type = et, .role = role_, .len = len_, .flags = fl}
#define OUT(nm, et, role_, fl) {.name = nm, .kind = K_OUT, .type = et, .role = role_, .flags = fl}

#define NSLOTS(...) ((uint8_t)(sizeof((adv_slot[]){__VA_ARGS__}) / sizeof(adv_slot)))
/* FN(suffix of mcs_<suffix>, effect, variants, N slot, slots...) */
#define FN(sfx, eff, nv, ref, ...) \
    {"mcs_" #sfx, t_##sfx, eff, nv, NSLOTS(__VA_ARGS__), ref, {__VA_ARGS__}, NULL}
#define FNV(sfx, eff, vars_, ref, ...)                                                   \
    {"mcs_" #sfx, t_##sfx, eff, (uint8_t)sizeof(vars_), NSLOTS(__VA_ARGS__), ref, {__VA_ARGS__}, \
     vars_}

/* The baselines: N = 12 bins, K = 6 samples per pattern trial, sparse trials
 * of 5 samples (with a repeated bin), frequency and bin indices inside. */
#define BN 12u
#define BK 6u
#define BT 5u

/* The caller's buffer of an init, copy or load of the objects over caller
 * memory: bytes for the baseline shape (F = 8 in 1D, 4 in 2D, 6 x 4 bins),
 * the array as long as the bytes slot (at) says; their flags. */
#define PS_MEM MCS_POINTSET_SIZE(8u)
#define P2_MEM MCS_POINTSET2D_SIZE(4u)
#define S2_MEM MCS_SPECTRUM2D_SIZE(6u, 4u)
#define MEM(at) AOUT("mem", E_U8, O_RAW, LEN(L_SLOT, at), 0)
#define FLAGS U32("flags", 0, 0, MCS_POINTSET_DIRECT_ONLY, F_OKIN)

/* The _f calls' rows reuse the double rows' arrays: adv_floats_begin
 * narrows points[len] to floats in place (adv_table_core.c says how), and
 * adv_floats_end puts the doubles back after the call. */
const float *adv_floats_begin(void *points, size_t len);
void adv_floats_end(void *points, size_t len);

/* adv_table_abi.c: the abi query and the point-set batches. */
extern const adv_fn adv_fns_abi[];
extern const size_t adv_fns_abi_count;

#endif /* ADV_TABLE_H */
