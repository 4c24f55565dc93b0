/* One adversarial row: build its world, snapshot it, make the call and hold
 * the result to the contract (see adv.h). Aliased rows are compared with the
 * same call on separate buffers. */
#include "adv_world.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#if defined(__SANITIZE_ADDRESS__)
#define ADV_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define ADV_ASAN 1
#endif
#endif
#ifdef ADV_ASAN
#include <sanitizer/asan_interface.h>
#define POISON(p, n) __asan_poison_memory_region((p), (n))
#define UNPOISON(p, n) __asan_unpoison_memory_region((p), (n))
#else
#define POISON(p, n) ((void)(p), (void)(n))
#define UNPOISON(p, n) ((void)(p), (void)(n))
#endif

typedef struct {
    adv_val a[ADV_MAX_SLOTS];
    int reg[ADV_MAX_SLOTS]; /* region of each pointer slot, -1 if none */
    size_t len[ADV_MAX_SLOTS];
    int ov[ADV_MAX_SLOTS];
    size_t n_bins;
    uint64_t count[ADV_MAX_SLOTS];
} adv_call;

static const size_t elem_bytes[5] = {sizeof(double), sizeof(size_t), sizeof(uint32_t),
                                     sizeof(uint64_t), 1u};

static double cb_ok(double x, void *ctx) { (void)ctx; return 2.0 * x - 0.3; }
static double cb_nan(double x, void *ctx) { (void)ctx; (void)x; return NAN; }
static double cb_huge(double x, void *ctx) { (void)ctx; return 1e300 * (1.0 + x); }

/* The size an array follows: the row's value where the call must accept it
 * (so the caller's array really is that long), else the baseline's (the call
 * must refuse the value before it reads the array). */
static size_t slot_value(const adv_row *r, int i)
{
    const adv_slot *s = &r->fn->slot[i];
    if (s->role == Z_REC && !(r->slot == i && r->mk == MK_SIZE))
        return adv_record_size(s->type);
    if (r->slot != i || r->mk != MK_SIZE)
        return (size_t)s->base;
    const size_t z = r->zval;
    const int valid = s->role == Z_LEN || (s->role == Z_DEF && z >= s->lo && z <= s->hi);
    return valid && z <= (1u << 20) ? z : (size_t)s->base;
}

static size_t length_of(const adv_row *r, const adv_call *c, const adv_len *l)
{
    /* L_REC and L_CONST name no slot */
    const int t = l->op == L_OBJN || l->op == L_OBJNN ? r->fn->slot[l->a].type : T_NONE;
    switch (l->op) {
    case L_SLOT: return slot_value(r, l->a);
    case L_2SLOT: return 2u * slot_value(r, l->a);
    case L_SQ: return slot_value(r, l->a) * slot_value(r, l->a);
    case L_HALF: return slot_value(r, l->a) / 2u + 1u;
    case L_OBJN: return adv_state_n(t, c->ov[l->a]);
    case L_OBJNN: return adv_state_nn(t, c->ov[l->a], r->variant);
    case L_PROD: return slot_value(r, l->a) * slot_value(r, l->b);
    case L_PROD2: return 2u * slot_value(r, l->a) * slot_value(r, l->b);
    case L_CONST: return l->c;
    case L_REC: return adv_record_size(l->a);
    default: /* L_KDIM: k times the dimension of the sampler in slot b */
        return slot_value(r, l->a) *
               (adv_state_nn(T_SAMPLER, OV_BASE, r->variant) / adv_state_n(T_SAMPLER, OV_BASE));
    }
}

static void objects(const adv_row *r, adv_call *c)
{
    const adv_fn *fn = r->fn;
    for (int i = 0; i < fn->nslot; ++i) {
        const adv_slot *s = &fn->slot[i];
        c->reg[i] = -1;
        c->ov[i] = r->slot == i && r->mk == MK_OBJ ? r->mv : OV_BASE;
        if (s->kind > K_OBJ_OUT || (r->slot == i && r->mk == MK_NULL))
            continue;
        size_t bytes = adv_type_size(s->type);
        c->reg[i] = adv_nregs;
        void *p = adv_region_for(bytes, i, s->kind);
        c->a[i].p = p;
        c->len[i] = 1;
        if (p == NULL)
            return;
        if (s->kind == K_OBJ_OUT)
            memset(p, ADV_FILL_BYTE, bytes);
        else
            (void)adv_build(s->type, c->ov[i], r->variant, p);
        c->count[i] = adv_has_count(s->type) ? adv_count(s->type, p) : 0u;
    }
}

/* N of the call: bins are drawn below it and output bins checked against it. */
static size_t bins_limit(const adv_row *r, const adv_call *c)
{
    const int i = r->fn->nref;
    const adv_slot *s = &r->fn->slot[i];
    size_t n = s->kind <= K_OBJ_OUT ? adv_state_n(s->type, c->ov[i]) : slot_value(r, i);
    return n > 0u ? n : 1u;
}

static void scalars_and_arrays(const adv_row *r, adv_call *c)
{
    const adv_fn *fn = r->fn;
    c->n_bins = bins_limit(r, c);
    for (int i = 0; i < fn->nslot; ++i) {
        const adv_slot *s = &fn->slot[i];
        const int mut = r->slot == i;
        switch (s->kind) {
        case K_SIZE: c->a[i].z = mut && r->mk == MK_SIZE ? r->zval : slot_value(r, i); break;
        case K_DBL: c->a[i].d = adv_scalar_double(r, i); break;
        case K_U32: c->a[i].u32 = (uint32_t)(mut && r->mk == MK_INT ? (uint64_t)r->lval : s->base); break;
        case K_U64: c->a[i].u64 = mut && r->mk == MK_INT ? (uint64_t)r->lval : s->base; break;
        case K_LONG: c->a[i].l = mut && r->mk == MK_INT ? r->lval : (long)s->base; break;
        case K_ENUM: c->a[i].e = (int)(mut && r->mk == MK_INT ? r->lval : (long)s->base); break;
        case K_FN:
            c->a[i].fn = mut && r->mk == MK_NULL ? NULL
                         : mut && r->mk == MK_CB ? (r->mv == 1 ? cb_nan : cb_huge) : cb_ok;
            break;
        case K_CTX: c->a[i].p = adv_region_for(sizeof(double), i, K_ARR_IN); break;
        default: break;
        }
        if (s->kind != K_ARR_IN && s->kind != K_ARR_OUT && s->kind != K_OUT)
            continue;
        c->reg[i] = -1;
        c->a[i].p = NULL;
        if (mut && r->mk == MK_NULL)
            continue;
        c->len[i] = s->kind == K_OUT ? 1u : length_of(r, c, &s->len);
        c->reg[i] = adv_nregs;
        void *p = adv_region_for(c->len[i] * elem_bytes[s->type], i, s->kind);
        c->a[i].p = p;
        if (p == NULL)
            return;
        if (s->kind == K_ARR_IN)
            adv_fill_array(r, i, p, c->len[i], c->n_bins);
        else
            memset(p, ADV_FILL_BYTE, c->len[i] * elem_bytes[s->type]);
    }
}

/* Builds the world of row r. With alias set, slot and slot2 then share one
 * new buffer, long enough for both, holding what the input of the two (else
 * slot) holds; the reference build gives slot2 that content in its own buffer. */
static int source_slot(const adv_row *r)
{
    const adv_slot *a = &r->fn->slot[r->slot], *b = &r->fn->slot[r->slot2];
    return a->kind != K_ARR_IN && a->kind != K_OBJ_IN && b->kind == K_ARR_IN ? r->slot2 : r->slot;
}

static void share_content(const adv_row *r, adv_call *c, int src, void *dst, size_t elems)
{
    const adv_slot *s = &r->fn->slot[src];
    if (s->kind <= K_OBJ_OUT)
        adv_copy_object(s->type, dst, c->a[src].p);
    else if (s->kind == K_ARR_IN)
        adv_fill_array(r, src, dst, elems, c->n_bins);
    else
        memset(dst, ADV_FILL_BYTE, elems * elem_bytes[s->type]);
}

static size_t slot_bytes(const adv_row *r, const adv_call *c, int i)
{
    const adv_slot *s = &r->fn->slot[i];
    return s->kind <= K_OBJ_OUT ? adv_type_size(s->type) : c->len[i] * elem_bytes[s->type];
}

enum { BUILD_PLAIN, BUILD_REF, BUILD_ALIAS };

static int build(const adv_row *r, adv_call *c, int mode)
{
    adv_world_reset();
    memset(c, 0, sizeof *c);
    objects(r, c);
    scalars_and_arrays(r, c);
    if (mode != BUILD_PLAIN && !adv_overflow) {
        const int i = r->slot, j = r->slot2, src = source_slot(r), dst = src == i ? j : i;
        if (mode == BUILD_REF) {
            share_content(r, c, src, c->a[dst].p, c->len[dst]);
        } else {
            const adv_slot *s = &r->fn->slot[i];
            size_t elems = c->len[i] > c->len[j] ? c->len[i] : c->len[j];
            size_t bytes = s->kind <= K_OBJ_OUT ? adv_type_size(s->type) : elems * elem_bytes[s->type];
            int g = adv_nregs;
            void *p = adv_region_for(bytes, i, s->kind == K_ARR_IN || s->kind == K_OBJ_IN
                                                   ? r->fn->slot[j].kind : s->kind);
            if (p != NULL) {
                share_content(r, c, src, p, elems);
                c->a[i].p = c->a[j].p = p;
                c->reg[i] = c->reg[j] = g;
            }
        }
    }
    return !adv_overflow;
}

static const char *slot_name(const adv_row *r, int reg)
{
    int s = adv_regs[reg].slot;
    return s < 0 ? "a dependency" : r->fn->slot[s].name;
}

static int region_changed(int g, size_t from, size_t to, size_t *at)
{
    for (size_t b = from; b < to; ++b)
        if (adv_arena[b] != adv_snap[b]) {
            *at = b - adv_regs[g].off;
            return 1;
        }
    return 0;
}

static void guards(int poison)
{
    for (int g = 0; g < adv_nregs; ++g) {
        unsigned char *p = adv_arena + adv_regs[g].off;
        if (poison) {
            POISON(p - ADV_GUARD, ADV_GUARD);
            POISON(p + adv_regs[g].bytes, ADV_GUARD);
        } else {
            UNPOISON(p - ADV_GUARD, ADV_GUARD);
            UNPOISON(p + adv_regs[g].bytes, ADV_GUARD);
        }
    }
}

static int call_once(const adv_row *r, adv_call *c, long *calls)
{
    memcpy(adv_snap, adv_arena, adv_used);
    guards(1);
    int st = r->fn->call(c->a);
    guards(0);
    ++*calls;
    return st;
}

/* ---- checks ---- */

char adv_note[160];
static char *msg;
static long *ncalls;

#if defined(__GNUC__)
__attribute__((format(printf, 1, 2)))
#endif
static int fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, 200, fmt, ap);
    va_end(ap);
    return 1;
}

/* A failed call: every byte of the world as it was. */
static int unchanged(const adv_row *r, int st)
{
    for (int g = 0; g < adv_nregs; ++g) {
        size_t at = 0, lo = adv_regs[g].off - ADV_GUARD;
        size_t hi = adv_regs[g].off + adv_regs[g].bytes + ADV_GUARD;
        if (region_changed(g, lo, hi, &at))
            return fail("failed call (%s) changed %s at byte %zu",
                        mcs_status_str((mcs_status)st), slot_name(r, g), at);
    }
    return 0;
}

static int out_values_bad(const adv_row *r, const adv_call *c, int i)
{
    const adv_slot *s = &r->fn->slot[i];
    const void *p = c->a[i].p;
    if (p == NULL || s->role == O_RAW)
        return 0;
    for (size_t j = 0; j < c->len[i]; ++j) {
        double v = s->type == E_D ? ((const double *)p)[j] : 0.0;
        int ok = s->role == O_VAL   ? isfinite(v)
                 : s->role == O_NN  ? isfinite(v) && v >= 0.0
                 : s->role == O_U01 ? v >= 0.0 && v < 1.0
                 : s->role == O_BIN ? ((const size_t *)p)[j] < c->n_bins : 1;
        if (!ok)
            return fail("MCS_OK with %s[%zu] = %.17g", s->name, j, v);
    }
    return 0;
}

/* The counted object a call updates (dst) and the one it merges in (src). */
static void counted(const adv_row *r, const adv_call *c, int *dst, int *src)
{
    const adv_fn *fn = r->fn;
    *dst = *src = -1;
    for (int i = 0; i < fn->nslot; ++i) {
        const adv_slot *s = &fn->slot[i];
        if (s->kind > K_OBJ_OUT || !adv_has_count(s->type) || c->a[i].p == NULL)
            continue;
        if (*dst < 0 && s->kind != K_OBJ_IN)
            *dst = i;
        else if (*src < 0 && s->kind == K_OBJ_IN)
            *src = i;
    }
}

static int count_bad(const adv_row *r, const adv_call *c)
{
    int dst, src;
    counted(r, c, &dst, &src);
    if (dst < 0 || r->fn->effect == EF_NONE)
        return 0;
    const unsigned long long before = c->count[dst];
    const unsigned long long after = adv_count(r->fn->slot[dst].type, c->a[dst].p);
    if (r->fn->effect == EF_INIT && after != 0u)
        return fail("init left the count at %llu", after);
    if (r->fn->effect == EF_ADD && (before == UINT64_MAX || after != before + 1u))
        return fail("MCS_OK moved the count %llu -> %llu (one add)", before, after);
    if (r->fn->effect == EF_MERGE && src >= 0) {
        const unsigned long long other = c->a[src].p == c->a[dst].p ? before : c->count[src];
        if (before + other < before || after != before + other)
            return fail("MCS_OK merged counts %llu + %llu into %llu", before, other, after);
    }
    return 0;
}

static int success_bad(const adv_row *r, const adv_call *c)
{
    for (int g = 0; g < adv_nregs; ++g) {
        size_t at = 0, off = adv_regs[g].off, end = off + adv_regs[g].bytes;
        const int kind = adv_regs[g].kind;
        if (region_changed(g, off - ADV_GUARD, off, &at) ||
            region_changed(g, end, end + ADV_GUARD, &at))
            return fail("MCS_OK but wrote outside %s (guard byte %zu)", slot_name(r, g), at);
        if ((kind == K_ARR_IN || kind == K_OBJ_IN) && region_changed(g, off, end, &at))
            return fail("MCS_OK but changed the input %s at byte %zu", slot_name(r, g), at);
    }
    for (int i = 0; i < r->fn->nslot; ++i) {
        const adv_slot *s = &r->fn->slot[i];
        if ((s->kind == K_ARR_OUT || s->kind == K_OUT) && out_values_bad(r, c, i))
            return 1;
        if ((s->kind == K_OBJ_IO || s->kind == K_OBJ_OUT) && c->a[i].p != NULL) {
            const char *h = adv_health(s->type, c->a[i].p, ncalls);
            if (h != NULL)
                return fail("after MCS_OK, %s: %s", s->name, h);
        }
    }
    return count_bad(r, c);
}

static int expect_bad(const adv_row *r, int st)
{
    const char *name = mcs_status_str((mcs_status)st);
    if (st == ADV_BROKEN)
        return fail("broke its documented invariant%s%s", adv_note[0] ? ": " : "", adv_note);
    if (strcmp(name, "MCS_ERR_UNKNOWN") == 0)
        return fail("returned %d, not a status", st);
    switch (r->expect) {
    case EX_OK: return st != MCS_OK ? fail("expected MCS_OK, got %s", name) : 0;
    case EX_ERR: return st == MCS_OK ? fail("expected an error, got MCS_OK") : 0;
    case EX_NULL: return st != MCS_ERR_NULL ? fail("expected MCS_ERR_NULL, got %s", name) : 0;
    default: return 0;
    }
}

/* ---- rows ---- */

static _Alignas(64) unsigned char ref_out[2][1u << 20], got_out[1u << 20];
static size_t ref_bytes[2];

/* The aliased call against the same call on separate buffers: every output
 * of the two slots must hold what it would have held alone. */
static int alias_bad(const adv_row *r, adv_call *c, int st)
{
    adv_call ref;
    const int pair[2] = {r->slot, r->slot2};
    if (!build(r, &ref, BUILD_REF))
        return fail("world too large");
    int ref_st = call_once(r, &ref, ncalls);
    for (int q = 0; q < 2; ++q) {
        const adv_slot *s = &r->fn->slot[pair[q]];
        if (s->kind <= K_OBJ_OUT) { /* what it holds, wherever it is */
            ref_bytes[q] = adv_canonical(s->type, ref.a[pair[q]].p, ref_out[q], sizeof ref_out[q]);
        } else {
            ref_bytes[q] = slot_bytes(r, &ref, pair[q]);
            memcpy(ref_out[q], ref.a[pair[q]].p, ref_bytes[q]);
        }
    }
    if (!build(r, c, BUILD_ALIAS))
        return fail("world too large");
    st = call_once(r, c, ncalls);
    if (expect_bad(r, st))
        return 1;
    if (st != MCS_OK)
        return unchanged(r, st);
    if (ref_st != MCS_OK)
        return fail("aliased call gave MCS_OK where separate buffers gave %s",
                    mcs_status_str((mcs_status)ref_st));
    for (int q = 0; q < 2; ++q) {
        const int kind = r->fn->slot[pair[q]].kind;
        if (kind == K_ARR_IN || kind == K_OBJ_IN)
            continue;
        const adv_slot *s = &r->fn->slot[pair[q]];
        const unsigned char *got = c->a[pair[q]].p;
        size_t got_bytes = ref_bytes[q];
        if (s->kind <= K_OBJ_OUT) {
            got_bytes = adv_canonical(s->type, got, got_out, sizeof got_out);
            got = got_out;
        }
        if (got_bytes != ref_bytes[q] || memcmp(got, ref_out[q], ref_bytes[q]) != 0)
            return fail("aliased call gave MCS_OK with %s unlike separate buffers",
                        r->fn->slot[pair[q]].name);
    }
    return success_bad(r, c);
}

int adv_run_row(const adv_row *r, char *why, long *calls)
{
    static adv_call c;
    msg = why;
    ncalls = calls;
    why[0] = '\0';
    adv_note[0] = '\0';
    if (r->mk == MK_ALIAS)
        return alias_bad(r, &c, 0);
    if (!build(r, &c, BUILD_PLAIN))
        return fail("world too large");
    int st = call_once(r, &c, calls);
    if (expect_bad(r, st))
        return 1;
    return st != MCS_OK ? unchanged(r, st) : success_bad(r, &c);
}
