/* Rows of the adversarial table: from a function's slots, every bad (and
 * boundary) value each slot can take, with the outcome the contract demands
 * of it: MCS_ERR_NULL, some error, success, or either (then the success must
 * be sound and the error must change nothing). */
#include "adv.h"

#include <float.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>

static int obj_state_applies(int type, int ov)
{
    switch (ov) {
    case OV_EMPTY:
    case OV_FULL: return adv_has_count(type);
    case OV_SMALL:
    case OV_BIG: return type != T_RNG && type != T_WELFORD;
    case OV_BIGK: return type == T_PAT;
    default: return 1;
    }
}

static int expect_obj(const adv_fn *fn, int si, int ov, int v)
{
    const adv_slot *s = &fn->slot[si];
    switch (ov) {
    case OV_ZERO:
        if (s->type == T_RNG) /* an unseeded rng is detectable; some draws never use it */
            for (int j = 0; j < fn->nslot; ++j)
                if (fn->slot[j].kind <= K_OBJ_OUT && !adv_variant_draws(fn->slot[j].type, v))
                    return EX_ANY;
        return s->type == T_WELFORD ? EX_ANY : EX_ERR;
    case OV_FF:
        return s->type == T_WELFORD || s->type == T_RNG ? EX_ANY : EX_ERR;
    case OV_SMALL:
    case OV_BIG: return s->flags & F_SIZED ? EX_ERR : EX_ANY;
    case OV_FULL: /* the count cannot grow past UINT64_MAX */
        return fn->effect == EF_ADD || fn->effect == EF_MERGE ? EX_ERR : EX_ANY;
    default: return EX_ANY;
    }
}

static const char *const ov_names[OV_COUNT] = {"base", "empty", "zeroed", "0xFF-filled",
                                               "other-N(small)", "other-N(max)", "count=UINT64_MAX",
                                               "K=SIZE_MAX"};

static const struct {
    const char *name;
    int value;
} dbl_muts[] = {
    {"NaN", MV_NAN}, {"+inf", MV_PINF}, {"-inf", MV_NINF}, {"-1", MV_NEG},
    {"subnormal", MV_SUB}, {"1e300", MV_HUGE}, {"0", MV_ZERO}, {"1.0", MV_ONE},
    {"-0.0", MV_NZERO}, {"1-ulp", MV_BELOW1}, {"1.5e154", MV_SQRTMAX}, {"all DBL_MAX", MV_ALLMAX}};

/* Outcome of a double value (a scalar or one array element) of a role. */
static int expect_dbl(int role, int mv, int is_array)
{
    if (mv == MV_NAN || mv == MV_PINF || mv == MV_NINF)
        return EX_ERR;
    switch (role) {
    case R_POINT:
        if (mv == MV_NEG || mv == MV_ONE || mv == MV_HUGE || mv == MV_SQRTMAX)
            return EX_ERR;
        return mv == MV_NZERO ? EX_ANY : EX_OK;
    case R_WEIGHT:
        if (mv == MV_NEG)
            return EX_ERR;
        return mv == MV_HUGE || mv == MV_SQRTMAX || mv == MV_ALLMAX ? EX_ANY : EX_OK;
    case R_IMPW: /* 0 puts a bin outside the support; not every weight is mutated */
        if (mv == MV_NEG)
            return EX_ERR;
        if (mv == MV_ZERO)
            return EX_OK;
        return mv == MV_ONE || mv == MV_BELOW1 ? EX_OK : EX_ANY;
    default: /* R_F */
        (void)is_array;
        return mv == MV_HUGE || mv == MV_SQRTMAX || mv == MV_ALLMAX ? EX_ANY : EX_OK;
    }
}

static int dbl_mut_applies(int role, int mv, int is_array)
{
    if (mv == MV_ALLMAX)
        return is_array && role != R_POINT;
    if (mv == MV_SQRTMAX)
        return role != R_POINT;
    if (mv == MV_ONE || mv == MV_BELOW1 || mv == MV_NZERO)
        return role == R_POINT || role == R_IMPW;
    return 1;
}

typedef struct {
    adv_row *rows;
    size_t n, cap;
    const adv_fn *fn;
    int v;
} row_sink;

/* Appends a row (the last one is overwritten when the buffer is full: the
 * caller's capacity check fails the test then). */
static adv_row *add(row_sink *k, int slot, int mk, int mv, int expect, const char *what)
{
    adv_row *r = &k->rows[k->n < k->cap ? k->n++ : k->cap - 1u];
    memset(r, 0, sizeof *r);
    r->fn = k->fn;
    r->variant = k->v;
    r->slot = slot;
    r->slot2 = -1;
    r->mk = mk;
    r->mv = mv;
    r->expect = expect;
    const char *vn = "";
    for (int i = 0; i < k->fn->nslot && k->fn->nvar > 1; ++i)
        if (k->fn->slot[i].kind <= K_OBJ_OUT && adv_variant_name(k->fn->slot[i].type, k->v)[0])
            vn = adv_variant_name(k->fn->slot[i].type, k->v);
    snprintf(r->label, sizeof r->label, "%s%s%s%s%s", slot >= 0 ? k->fn->slot[slot].name : "",
             slot >= 0 ? "=" : "", what, vn[0] ? " @" : "", vn);
    return r;
}

static int is_ptr(int kind)
{
    return kind <= K_OUT || kind == K_FN || kind == K_CTX;
}

static void null_rows(row_sink *k, int i, const adv_slot *s)
{
    int ex = s->flags & F_NULLOK ? EX_OK : s->flags & F_NULLERR ? EX_ERR : EX_NULL;
    add(k, i, MK_NULL, 0, ex, "NULL");
}

static void obj_rows(row_sink *k, int i, const adv_slot *s)
{
    if (s->kind == K_OBJ_OUT)
        return;
    for (int ov = OV_EMPTY; ov < OV_COUNT; ++ov)
        if (obj_state_applies(s->type, ov))
            add(k, i, MK_OBJ, ov, expect_obj(k->fn, i, ov, k->v), ov_names[ov]);
}

static void dbl_rows(row_sink *k, int i, const adv_slot *s, int is_array)
{
    char what[48];
    for (size_t m = 0; m < sizeof dbl_muts / sizeof dbl_muts[0]; ++m) {
        int mv = dbl_muts[m].value;
        if (!dbl_mut_applies(s->role, mv, is_array))
            continue;
        snprintf(what, sizeof what, "%s%s", is_array && mv != MV_ALLMAX ? "[last] " : "",
                 dbl_muts[m].name);
        add(k, i, MK_DBL, mv, expect_dbl(s->role, mv, is_array), what);
    }
}

static void record_rows(row_sink *k, int i)
{
    add(k, i, MK_BINS, 0, EX_ERR, "magic byte flipped");
    add(k, i, MK_BINS, 1, EX_ERR, "middle byte flipped");
    add(k, i, MK_BINS, 2, EX_ERR, "CRC byte flipped");
}

static void bins_rows(row_sink *k, int i)
{
    add(k, i, MK_BINS, 0, EX_ERR, "[last] N");
    add(k, i, MK_BINS, 1, EX_ERR, "[last] SIZE_MAX");
    add(k, i, MK_BINS, 2, EX_OK, "all N-1");
}

/* size_t values by role; the outcome from the valid range. */
static void size_rows(row_sink *k, int i, const adv_slot *s)
{
    size_t vals[8];
    int nv = 0;
    if (s->role == Z_REC) { /* a record's exact length: anything else is refused */
        const size_t n = adv_record_size(s->type);
        const size_t recs[5] = {0u, 1u, n - 1u, n + 1u, SIZE_MAX};
        char what[32];
        for (int a = 0; a < 5; ++a) {
            if (a == 4)
                snprintf(what, sizeof what, "SIZE_MAX");
            else
                snprintf(what, sizeof what, "%zu", recs[a]);
            add(k, i, MK_SIZE, 0, EX_ERR, what)->zval = recs[a];
        }
        return;
    }
    const int nomax = (s->flags & (F_NOMAX | F_BACKED)) != 0;
    vals[nv++] = 0u;
    vals[nv++] = 1u;
    if (s->role == Z_LEN) {
        vals[nv++] = ADV_LONG_LEN;
    } else if (s->role != Z_FREE) {
        if (!nomax) {
            vals[nv++] = s->hi;
            vals[nv++] = s->hi + 1u;
        }
        if (s->role == Z_MATCH) {
            vals[nv++] = (size_t)s->base - 1u;
            vals[nv++] = (size_t)s->base + 1u;
        }
    }
    if (s->role != Z_LEN && !(s->flags & F_BACKED)) /* a length without a maximum cannot be a
                                                         lie the call could see */
        vals[nv++] = SIZE_MAX;
    for (int a = 0; a < nv; ++a) {
        size_t z = vals[a];
        int dup = z == (size_t)s->base && s->role != Z_FREE;
        for (int b = 0; b < a; ++b)
            dup |= vals[b] == z;
        if (dup)
            continue;
        int in = s->role == Z_MATCH ? z == (size_t)s->base : z >= s->lo && z <= s->hi;
        int ex = s->role == Z_FREE ? EX_ANY : !in ? EX_ERR : s->flags & F_OKIN ? EX_OK : EX_ANY;
        char what[32];
        if (z == SIZE_MAX)
            snprintf(what, sizeof what, "SIZE_MAX");
        else
            snprintf(what, sizeof what, "%zu%s", z, z == s->hi && !nomax ? "(max)" : "");
        add(k, i, MK_SIZE, 0, ex, what)->zval = z;
    }
}

/* long, enum, u32 and u64 scalars: the range edges and the type's extremes. */
static void int_rows(row_sink *k, int i, const adv_slot *s)
{
    long vals[10];
    int nv = 0;
    if (s->kind == K_U64) {
        vals[nv++] = 0;
        vals[nv++] = 1;
        vals[nv++] = -1; /* UINT64_MAX */
        if (s->lhi > 0) { /* a bounded u64: its edge */
            vals[nv++] = s->lhi;
            vals[nv++] = s->lhi + 1;
        }
    } else if (s->kind == K_U32) {
        vals[nv++] = 0;
        vals[nv++] = 1;
        vals[nv++] = 3;
        vals[nv++] = (long)0x80000000u;
        vals[nv++] = (long)UINT32_MAX;
    } else {
        long lo = s->llo, hi = s->lhi;
        long cand[8] = {lo > LONG_MIN ? lo - 1 : lo, lo, hi, hi < LONG_MAX ? hi + 1 : hi, 0,
                        s->kind == K_LONG ? LONG_MIN : INT_MIN,
                        s->kind == K_LONG ? LONG_MAX : INT_MAX, lo / 2 + hi / 2};
        for (int c = 0; c < 8; ++c)
            vals[nv++] = cand[c];
    }
    for (int a = 0; a < nv; ++a) {
        int dup = 0;
        for (int b = 0; b < a; ++b)
            dup |= vals[b] == vals[a];
        if (dup)
            continue;
        long x = vals[a];
        int in = s->kind == K_U64 ? s->lhi <= 0 || (uint64_t)x <= (uint64_t)s->lhi
                                  : x >= s->llo && x <= s->lhi;
        int ex = s->flags & F_FREE ? EX_ANY : !in ? EX_ERR : s->flags & F_OKIN ? EX_OK : EX_ANY;
        char what[32];
        snprintf(what, sizeof what, "%ld", x);
        add(k, i, MK_INT, 0, ex, what)->lval = x;
    }
}

static void fn_rows(row_sink *k, int i)
{
    add(k, i, MK_CB, 1, EX_ERR, "f returns NaN");
    add(k, i, MK_CB, 2, EX_ANY, "f returns 1e300");
}

static int elem_of(const adv_slot *s)
{
    if (s->kind <= K_OBJ_OUT)
        return 100 + s->type;
    return s->kind == K_ARR_IN || s->kind == K_ARR_OUT || s->kind == K_OUT ? s->type : -1;
}

static int writable(int kind)
{
    return kind == K_OBJ_IO || kind == K_OBJ_OUT || kind == K_ARR_OUT || kind == K_OUT;
}

/* Two pointers to the same buffer: the call must either refuse or give what
 * it gives with separate buffers (input buffers excepted). */
static void alias_rows(row_sink *k)
{
    const adv_fn *fn = k->fn;
    char what[48];
    for (int i = 0; i < fn->nslot; ++i)
        for (int j = i + 1; j < fn->nslot; ++j) {
            const adv_slot *a = &fn->slot[i], *b = &fn->slot[j];
            if (elem_of(a) < 0 || elem_of(a) != elem_of(b) || !(writable(a->kind) || writable(b->kind)))
                continue;
            snprintf(what, sizeof what, "alias %s==%s", a->name, b->name);
            adv_row *r = add(k, -1, MK_ALIAS, 0, EX_ANY, what);
            r->slot = i;
            r->slot2 = j;
        }
}

size_t adv_rows(const adv_fn *fn, adv_row *rows, size_t cap)
{
    row_sink k = {rows, 0, cap, fn, 0};
    for (int v = 0; v < (fn->nvar ? fn->nvar : 1); ++v) {
        k.v = fn->vars != NULL ? fn->vars[v] : v;
        add(&k, -1, MK_NONE, 0, EX_OK, "baseline");
        for (int i = 0; i < fn->nslot; ++i) {
            const adv_slot *s = &fn->slot[i];
            if (is_ptr(s->kind) && s->kind != K_CTX)
                null_rows(&k, i, s);
            if (s->kind <= K_OBJ_OUT)
                obj_rows(&k, i, s);
            else if (s->kind == K_ARR_IN && s->type == E_D)
                dbl_rows(&k, i, s, 1);
            else if (s->kind == K_ARR_IN && s->role == R_BINS)
                bins_rows(&k, i);
            else if (s->kind == K_ARR_IN && s->role == R_RECORD)
                record_rows(&k, i);
            else if (s->kind == K_DBL)
                dbl_rows(&k, i, s, 0);
            else if (s->kind == K_SIZE)
                size_rows(&k, i, s);
            else if (s->kind == K_U32 || s->kind == K_U64 || s->kind == K_LONG || s->kind == K_ENUM)
                int_rows(&k, i, s);
            else if (s->kind == K_FN)
                fn_rows(&k, i);
        }
        alias_rows(&k);
    }
    return k.n;
}
