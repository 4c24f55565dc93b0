/* The adversarial table (test/test_adversarial.c): every public function is
 * described once by its argument slots; the engine derives the bad calls
 * from the slot kinds (NULL in each pointer, sizes 0, 1, max, max+1 and
 * SIZE_MAX, NaN, +-inf, negative, subnormal and huge values, zeroed,
 * 0xFF-filled and other-N objects, aliased arguments, self-merges), runs
 * each in a forked child with guard bytes around every buffer, and checks
 * the contract: an error changes no byte; a success writes only what it
 * documents, returns finite read-outs, moves counts by the right amount and
 * leaves every accumulator it touched readable and finite.
 *
 * Private to the test; hosted (POSIX fork, pipes) only. */
#ifndef ADV_H
#define ADV_H

#include <stddef.h>
#include <stdint.h>

#include "mcspec.h"

/* Object types a slot can hold. */
enum {
    T_NONE, T_RNG, T_IMP, T_PAT, T_SAMPLER, T_PAT2D, T_WELFORD, T_DFT, T_SPECTRUM,
    T_MOMENT, T_AUTOCORR, T_POINTSET, T_POINTSET2D, T_SPECTRUM2D, T_THEORY, T_TSPEC,
    /* adv_objects.c's measure, NUFFT and provenance section: */
    T_DISC,    /* mcs_discrepancy; its N is the dimension */
    T_SPACING, /* mcs_spacing; its N is the dimension */
    T_NUFFT,   /* mcs_nufft over a work buffer of the row's arena; its N is F */
    T_PROV,    /* mcs_io_provenance */
    T_RECORD,  /* a caller buffer of ADV_RECORD_CAP bytes holding a saved record */
    T_RECLEN,  /* the size_t holding that record's length (mcs_io_set_provenance) */
    T_INTEGRAND, /* mcs_integrand: a disk in 2D (variant 1: 1D; small: the other D; max: a Gaussian;
                    variants 2, 3: utk's Blinn-Phong, Gaussian mixture (small: 1D)) */
    T_INTEGRATE, /* mcs_integrate; its N is the dimension (max: another family) */
    T_PCF,     /* mcs_pcf over a buffer inside the object; its N is the dimension */
    T_COUNT
};

/* Bytes of a T_RECORD buffer: the record of the largest spectrum and the
 * largest provenance block, with room. */
#define ADV_RECORD_CAP (192u << 10)

/* Object states a row may substitute for the baseline object. */
enum {
    OV_BASE,  /* initialised, a few trials in */
    OV_EMPTY, /* initialised, no trials */
    OV_ZERO,  /* all bytes 0 */
    OV_FF,    /* all bytes 0xFF */
    OV_SMALL, /* initialised for another (smaller) N */
    OV_BIG,   /* initialised for the largest N the type accepts */
    OV_FULL,  /* trial count at UINT64_MAX (accumulators) */
    OV_BIGK,  /* a pattern whose K is SIZE_MAX (set as pattern_init allows it) */
    OV_COUNT
};

/* Slot kinds. */
enum {
    K_OBJ_IN,  /* const object */
    K_OBJ_IO,  /* object the call updates */
    K_OBJ_OUT, /* object the call initialises */
    K_ARR_IN,  /* const array */
    K_ARR_OUT, /* array written */
    K_OUT,     /* one value written */
    K_SIZE, K_DBL, K_U32, K_U64, K_LONG, K_ENUM, K_FN, K_CTX
};

/* Element types of arrays and outputs. */
enum { E_D, E_Z, E_U32, E_U64, E_U8 };

/* Contents of input arrays and scalars, and the checks on outputs. */
enum {
    R_NONE,   /* objects and scalars without a content role */
    R_WEIGHT, /* finite, >= 0 (a sample weight, a dense s_n) */
    R_IMPW,   /* finite, > 0 (importance weights) */
    R_F,      /* finite, any sign (an integrand, a signal) */
    R_POINT,  /* in [0, 1) */
    R_BINS,   /* size_t in [0, N) */
    R_RECORD, /* bytes: a saved record of the baseline object of type len.a (io.h) */
    O_VAL,    /* output: finite */
    O_NN,     /* output: finite and >= 0 (a power, a variance, a standard error) */
    O_U01,    /* output: in [0, 1) */
    O_BIN,    /* output: a bin in [0, N) */
    O_RAW,    /* output: any bits */
    R_RANGE   /* a double scalar valid in [dlo, dhi] (a tolerance; adv_refine_rows) */
};

/* Roles of size_t scalars. */
enum {
    Z_DEF,   /* defines a size: valid in [lo, hi] */
    Z_MATCH, /* must equal the object's own size (base) */
    Z_INDEX, /* an index: valid in [lo, hi] */
    Z_LEN,   /* an array length without a maximum: >= lo, arrays follow it */
    Z_FREE,  /* any value is meaningful */
    Z_REC    /* must equal the size of the record of object type `type` (io.h) */
};

/* Slot flags. */
enum {
    F_NULLOK = 1,  /* NULL is allowed (the call must succeed) */
    F_NULLERR = 2, /* NULL is an error, not necessarily MCS_ERR_NULL */
    F_SIZED = 4,   /* an object of another N (or shape) must be refused */
    F_OKIN = 8,    /* every in-range size must succeed */
    F_NOMAX = 16,  /* Z_DEF without a documented maximum (hi = SIZE_MAX) */
    F_FREE = 32,   /* every value is meaningful (no status to check) */
    F_ZEROOK = 64, /* the zeroed object is a valid state (adv_refine_rows) */
    F_BACKED = 128 /* Z_DEF counting elements of an object the row holds one of: no rows
                      above hi (a larger count would read past the caller's array, which
                      no call can see) */
};

/* Array length: op over slot values. */
enum { L_SLOT, L_2SLOT, L_SQ, L_HALF, L_OBJN, L_OBJNN, L_KDIM, L_PROD, L_CONST, L_REC,
       L_PROD2 /* 2 a b: a sets of b interleaved 2D points (adv_table_abi.c) */ };

typedef struct {
    uint8_t op, a, b; /* L_REC: a is the record's object type */
    size_t c;         /* L_CONST */
} adv_len;

typedef struct {
    const char *name;
    uint8_t kind, type, role, flags; /* type: object type or element type */
    size_t lo, hi;                   /* sizes; long and enum ranges below */
    long llo, lhi;
    double dbase;
    uint64_t base; /* baseline scalar */
    adv_len len;
    double dlo, dhi; /* R_RANGE */
} adv_slot;

/* What a successful call does to the count of its first object slot. */
enum { EF_NONE, EF_ADD, EF_MERGE, EF_INIT };

typedef union {
    void *p;
    size_t z;
    double d;
    uint32_t u32;
    uint64_t u64;
    long l;
    int e;
    mcs_estimate_integrand fn;
} adv_val;

/* A thunk returns the status, or ADV_BROKEN when a function without a
 * status broke its own documented invariant. */
#define ADV_BROKEN 12345
/* What broke, filled by a thunk before it returns ADV_BROKEN (optional). */
extern char adv_note[160];
typedef int (*adv_thunk)(const adv_val *a);

#define ADV_MAX_SLOTS 10

typedef struct {
    const char *name;
    adv_thunk call;
    uint8_t effect;
    uint8_t nvar;  /* baseline variants (pattern kinds, spectrum paths, ...) */
    uint8_t nslot;
    uint8_t nref;  /* slot whose N bounds bins and indices (object or size) */
    adv_slot slot[ADV_MAX_SLOTS];
    const uint8_t *vars; /* the object variants of the baselines, NULL: 0 .. nvar-1 */
} adv_fn;

/* Mutations. */
enum { MK_NONE, MK_NULL, MK_OBJ, MK_DBL, MK_BINS, MK_SIZE, MK_INT, MK_CB, MK_ALIAS };
/* Double values (MK_DBL). */
enum {
    MV_NAN, MV_PINF, MV_NINF, MV_NEG, MV_SUB, MV_HUGE, MV_ZERO, MV_ONE, MV_NZERO, MV_BELOW1,
    MV_SQRTMAX, MV_ALLMAX
};
/* Length of an array whose size slot has no maximum, in its "long" row. */
#define ADV_LONG_LEN 1000u

/* A row: one function, one variant, one mutation of one slot (or an alias
 * of slot and slot2). */
typedef struct {
    const adv_fn *fn;
    int variant, slot, slot2;
    int mk, mv;     /* mutation kind and value (MV_*, OV_*, bins case, callback) */
    size_t zval;    /* MK_SIZE value */
    long lval;      /* MK_INT value */
    int expect;
    int item; /* issue-10 item of a known open defect, 0 if none */
    char label[112];
} adv_row;

enum { EX_OK, EX_ERR, EX_NULL, EX_ANY };

/* The function tables (adv_table_*.c). */
extern const adv_fn adv_fns_core[];
extern const size_t adv_fns_core_count;
extern const adv_fn adv_fns_stats[];
extern const size_t adv_fns_stats_count;
extern const adv_fn adv_fns_eq[];
extern const size_t adv_fns_eq_count;
extern const adv_fn adv_fns_2d[];
extern const size_t adv_fns_2d_count;
extern const adv_fn adv_fns_io[];
extern const size_t adv_fns_io_count;
extern const adv_fn adv_fns_measures[];
extern const size_t adv_fns_measures_count;
extern const adv_fn adv_fns_owen[];
extern const size_t adv_fns_owen_count;
extern const adv_fn adv_fns_nd[];
extern const size_t adv_fns_nd_count;
extern const adv_fn adv_fns_blue[];
extern const size_t adv_fns_blue_count;
extern const adv_fn adv_fns_integ[];
extern const size_t adv_fns_integ_count;
extern const adv_fn adv_fns_pcf[];
extern const size_t adv_fns_pcf_count;

/* The outcomes adv_rows does not derive, for the slots of R_RANGE and
 * F_ZEROOK (adv_table_measures.c): run on the rows of every function. */
void adv_refine_rows(adv_row *rows, size_t nrows);

/* Checks of the measure, NUFFT and provenance calls that a row cannot
 * express (adv_table_measures.c), run as scenarios: MCS_OK or ADV_BROKEN. */
int measures_work_of_exactly_the_queried_size_at_any_alignment_is_enough(const adv_val *a);
int measures_overlapping_buffers_are_refused_unchanged(const adv_val *a);
int nufft_edited_plan_headers_are_refused_unchanged(const adv_val *a);
int nufft_size_accepts_the_edges_of_tol_and_freq_and_no_more(const adv_val *a);
int io_provenances_breaking_a_rule_are_refused_unchanged(const adv_val *a);

/* The objects that keep their arrays in caller memory (pointset.h,
 * pointset2d.h, spectrum2d.h) live in the table as their header followed by
 * a buffer for the largest shape the table builds (OV_BIG); the calls get
 * the header, which points into the buffer. Their bytes depend on where
 * they are, so copies and comparisons go through adv_copy_object and
 * adv_canonical. */
#define ADV_PS_BIG 256u
#define ADV_PS2_BIG 32u
#define ADV_S2_BIG 64u
typedef struct {
    mcs_pointset acc;
    _Alignas(64) unsigned char mem[MCS_POINTSET_SIZE(ADV_PS_BIG)];
} adv_pointset;
typedef struct {
    mcs_pointset2d acc;
    _Alignas(64) unsigned char mem[MCS_POINTSET2D_SIZE(ADV_PS2_BIG)];
} adv_pointset2d;
typedef struct {
    mcs_spectrum2d acc;
    _Alignas(64) unsigned char mem[MCS_SPECTRUM2D_SIZE(ADV_S2_BIG, ADV_S2_BIG)];
} adv_spectrum2d;

/* Objects (adv_objects.c). */
size_t adv_type_size(int type);
/* A copy of src (type) into dst that is a whole object where it is: memcpy,
 * or the object's copy call for the types above. */
void adv_copy_object(int type, void *dst, const void *src);
/* What obj holds, in bytes that do not depend on where it is (for every
 * type but those above, its bytes), into out[cap]; returns the length. */
size_t adv_canonical(int type, const void *obj, unsigned char *out, size_t cap);
const char *adv_type_name(int type);
/* Builds object type in state ov for baseline variant v into obj (all of
 * adv_type_size bytes written); deps are allocated with adv_dep_alloc.
 * Returns 0 if the state does not apply to the type. */
int adv_build(int type, int ov, int v, void *obj);
/* N of an object as the length of its arrays (0 if it has none). */
size_t adv_obj_n(int type, const void *obj);
/* The same from the state a row asks for (zeroed and 0xFF objects: the base N). */
size_t adv_state_n(int type, int ov);
size_t adv_state_nn(int type, int ov, int v);
int adv_has_count(int type);
/* Bytes of the record of the baseline object of an accumulator type (io.h),
 * and the record itself into buf (which holds that many). */
size_t adv_record_size(int type);
void adv_record(int type, void *buf);
uint64_t adv_count(int type, const void *obj);
const char *adv_variant_name(int type, int v);
/* 0 if an object of this type and variant never draws from its rng. */
int adv_variant_draws(int type, int v);
/* Read-outs of a successfully updated object: NULL if every one either
 * fails or is finite (and >= 0 where it is a variance, a power or a standard
 * error), else what broke. *calls counts the calls made. */
const char *adv_health(int type, const void *obj, long *calls);
void *adv_dep_alloc(size_t bytes);

/* Engine (adv_engine.c): one row in this process; 0 if it passes, else why. */
int adv_run_row(const adv_row *r, char *why, long *calls);
size_t adv_rows(const adv_fn *fn, adv_row *rows, size_t cap);
/* Runs rows in forked children (a per-row timeout); result[i] is 0 for a
 * pass, else msg[i] says why. */
void adv_run(const adv_row *rows, size_t nrows, int *result, char (*msg)[200], long *calls);
extern int adv_timeout_ms;

#endif /* ADV_H */
