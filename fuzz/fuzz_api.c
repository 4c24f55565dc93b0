/* libFuzzer target for random sequences of API calls (issue 10; mk/fuzz.mk:
 * make fuzz, make fuzz-ci).
 *
 * The input is a program: each operation byte picks a public function, the
 * bytes after it its objects (two of each type, kept across the operations of
 * one input and corrupted on request: zeroed, 0xFF-filled, a header byte
 * flipped, a statistic overwritten), sizes, values (ordinary, boundary,
 * NaN, +-inf, subnormal, huge, raw bits) and arrays. After every call the
 * harness checks the contract and aborts (a finding) unless
 * - a failed call changed no byte of any object, input or output;
 * - a successful one wrote nothing past its outputs, left its inputs alone,
 *   returned finite read-outs (>= 0 for powers, variances, standard errors),
 *   moved a count by exactly one per add and to the sum on a merge.
 * ASan and UBSan (the build flags) catch the rest.
 *
 * Findings are tagged with the item of issue 10 whose rule they break (5:
 * a non-finite read-out, 7: a negative variance, 9: a count) or 0. Every one
 * is fatal; with FUZZ_API_KNOWN=skip the tagged ones are counted instead,
 * and FUZZ_API_KNOWN=<item> counts all but that one, for hunting past a
 * defect while it is open (none is today). */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mcspec.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAXLEN 4096 /* >= MCS_MAX_N and MCS_MAX_COV_N^2 at the default capacities */
#define GUARD 8     /* elements after each output that no call may write */
#define FILLBYTE 0xA5

/* ---- the input as a stream of arguments ---- */

static const uint8_t *in_p;
static size_t in_n;

static unsigned byte(void)
{
    if (in_n == 0u)
        return 0u;
    --in_n;
    return *in_p++;
}

static uint64_t word(int nbytes)
{
    uint64_t v = 0;
    for (int i = 0; i < nbytes; ++i)
        v = v << 8 | byte();
    return v;
}

static const double special[] = {
    0.0, -0.0, 1.0, -1.0, 0.5, 0.3, 2.5, 12.0, 1e9, 1e-10, 1e-300, 4.9406564584124654e-324,
    DBL_MIN, 1e100, 1.5e154, 1e200, 1e300, DBL_MAX, -DBL_MAX, 0x1.fffffffffffffp-1, (double)NAN,
    (double)INFINITY, -(double)INFINITY, -1e-300,
    /* large valid weights (issue 22: an importance weight 1/p_n reaches
     * 2^32 / N; 1e8 cancelled an open batch; the limits are 2^100 a trial
     * for spectrum and 2^220 for moment) */
    1e8, 1e10, 0x1p32, 0x1p99, 0x1p100, 0x1p200, 0x1p218};
#define NSPECIAL (sizeof special / sizeof special[0])

/* Mostly ordinary values in [0, 2), then the specials, then raw bits. */
static double dbl(void)
{
    unsigned b = byte();
    if (b < 128u)
        return (double)b / 64.0;
    if (b < 220u)
        return special[(b - 128u) % NSPECIAL];
    uint64_t u = word(8);
    double d;
    memcpy(&d, &u, sizeof d);
    return d;
}

static size_t size_any(void)
{
    unsigned b = byte();
    if (b < 192u)
        return b % 40u;
    const size_t edge[8] = {SIZE_MAX, MCS_MAX_N, MCS_MAX_N + 1u, MCS_MAX_COV_N, MCS_MAX_COV_N + 1u,
                            (size_t)1 << 32, 64u + byte(), (size_t)word(8)};
    return edge[b % 8u];
}

/* A length the caller's arrays really have. */
static size_t len_arg(void)
{
    size_t z = size_any();
    return z <= MAXLEN ? z : byte() % 40u;
}

/* ---- findings ---- */

static int skip_known, only_item;
static unsigned long known_seen;

#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
static void finding(int item, const char *fn, const char *fmt, ...)
{
    if (item != 0 && skip_known && item != only_item) {
        ++known_seen;
        return;
    }
    va_list ap;
    va_start(ap, fmt);
    if (item > 100)
        fprintf(stderr, "fuzz_api: [finding N%d] %s: ", item - 100, fn);
    else if (item > 0)
        fprintf(stderr, "fuzz_api: [issue 10 item %d] %s: ", item, fn);
    else
        fprintf(stderr, "fuzz_api: [new finding] %s: ", fn);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    abort();
}

/* ---- objects: two of each type ---- */

enum { RNG, IMP, PAT, SMP, P2D, WEL, DFT, SPEC, MOM, AC, PS, PS2, S2, TH, TS, NTYPES };
static mcs_rng o_rng[2];
static mcs_importance o_imp[2];
static mcs_pattern o_pat[2];
static mcs_sampler o_smp[2];
static mcs_pattern2d o_p2d[2];
static mcs_welford o_wel[2];
static mcs_dft o_dft[2];
static mcs_spectrum o_spec[2];
static mcs_moment o_mom[2];
static mcs_autocorr o_ac[2];
/* The objects over caller memory: the header and a buffer for the largest
 * shape kept here (a larger one is refused by init: MCS_ERR_SPACE). */
#define FZ_FREQ_1D 256u
#define FZ_FREQ_2D 40u
#define FZ_SIDE 64u
typedef struct {
    mcs_pointset acc;
    _Alignas(64) unsigned char mem[MCS_POINTSET_SIZE(FZ_FREQ_1D)];
} fz_pointset;
typedef struct {
    mcs_pointset2d acc;
    _Alignas(64) unsigned char mem[MCS_POINTSET2D_SIZE(FZ_FREQ_2D)];
} fz_pointset2d;
typedef struct {
    mcs_spectrum2d acc;
    _Alignas(64) unsigned char mem[MCS_SPECTRUM2D_SIZE(FZ_SIDE, FZ_SIDE)];
} fz_spectrum2d;
static fz_pointset o_ps[2];
static fz_pointset2d o_ps2[2];
static fz_spectrum2d o_s2[2];
static mcs_theory o_th[2];
static mcs_theory_spectrum o_ts[2];
static void *const objs[NTYPES] = {o_rng, o_imp, o_pat, o_smp, o_p2d, o_wel, o_dft, o_spec, o_mom,
                                   o_ac, o_ps, o_ps2, o_s2, o_th, o_ts};
static const size_t obj_size[NTYPES] = {
    sizeof(mcs_rng), sizeof(mcs_importance), sizeof(mcs_pattern), sizeof(mcs_sampler),
    sizeof(mcs_pattern2d), sizeof(mcs_welford), sizeof(mcs_dft), sizeof(mcs_spectrum),
    sizeof(mcs_moment), sizeof(mcs_autocorr), sizeof(fz_pointset), sizeof(fz_pointset2d),
    sizeof(fz_spectrum2d), sizeof(mcs_theory), sizeof(mcs_theory_spectrum)};
static unsigned dirty;

static void *obj(int type, unsigned i)
{
    dirty |= 1u << type;
    return (char *)objs[type] + (i & 1u) * obj_size[type];
}

/* The object, or NULL one time in 32. */
static void *obj_or_null(int type)
{
    unsigned b = byte();
    return b % 32u == 31u ? NULL : obj(type, b);
}

/* The trial count of an accumulator: its field, or for the objects over
 * caller memory (whose count is in their buffer, reached through a header
 * that may be corrupted) what their count call says, 0 if it refuses. */
static uint64_t count_of(int type, const void *o)
{
    uint64_t c = 0u;
    switch (type) {
    case WEL: return ((const mcs_welford *)o)->count;
    case SPEC: return ((const mcs_spectrum *)o)->count;
    case MOM: return ((const mcs_moment *)o)->count;
    case AC: return ((const mcs_autocorr *)o)->count;
    case PS: return mcs_pointset_count(o, &c) == MCS_OK ? c : 0u;
    case PS2: return mcs_pointset2d_count(o, &c) == MCS_OK ? c : 0u;
    case S2: return mcs_spectrum2d_count(o, &c) == MCS_OK ? c : 0u;
    default: return 0u;
    }
}

/* Bytes of an object over caller memory that hold its header and
 * statistics (its scratch, and the NUFFT's KissFFT state, follow: no C
 * library can validate a foreign struct, so corruption stays out of them);
 * 64 (the header's start) while its header does not pass its own check. */
static size_t stats_end(int type, const unsigned char *o, size_t bytes)
{
    uint64_t c = 0u;
    const void *v = o;
    const mcs_status st = type == PS    ? mcs_pointset_count(v, &c)
                          : type == PS2 ? mcs_pointset2d_count(v, &c)
                                        : mcs_spectrum2d_count(v, &c);
    if (st != MCS_OK)
        return 64u;
    const double *re = type == PS    ? ((const mcs_pointset *)v)->re
                       : type == PS2 ? ((const mcs_pointset2d *)v)->re
                                     : ((const mcs_spectrum2d *)v)->re;
    const uintptr_t at = (uintptr_t)(const void *)re - (uintptr_t)v;
    return at >= 64u && at <= bytes ? (size_t)at : 64u;
}

/* The arrays of an object whose first N (or N^2) values its calls read: a
 * double picked anywhere in the body of a large object seldom lands among
 * them, so corruption picks one of these as often. Types not listed have no
 * such arrays (or keep them behind their plans). */
typedef struct {
    size_t offset;
    int square; /* N x N */
} live_array;

static const live_array live_mom[] = {
    {offsetof(mcs_moment, shift), 0},   {offsetof(mcs_moment, sum_d), 0},
    {offsetof(mcs_moment, sum_dd), 1},  {offsetof(mcs_moment, batch_s), 0},
    {offsetof(mcs_moment, batch_d), 0}, {offsetof(mcs_moment, batch_w), 1}};
static const live_array live_th[] = {{offsetof(mcs_theory, mean_s), 0},
                                     {offsetof(mcs_theory, second), 1}};
static const live_array live_ts[] = {
    {offsetof(mcs_theory_spectrum, mean_s), 0}, {offsetof(mcs_theory_spectrum, edge), 0},
    {offsetof(mcs_theory_spectrum, length), 0}, {offsetof(mcs_theory_spectrum, inv_p), 0}};

/* One double among the values in use of o (type MOM, TH or TS) set to v;
 * nothing for other types or an object whose N is out of range. */
static void corrupt_live(int type, unsigned char *o, size_t at, double v)
{
    const live_array *list = NULL;
    size_t len = 0u, n = 0u, cap = (size_t)MCS_MAX_COV_N;
    switch (type) {
    case MOM: list = live_mom, len = 6u, n = ((mcs_moment *)(void *)o)->n; break;
    case TH: list = live_th, len = 2u, n = ((mcs_theory *)(void *)o)->n; break;
    case TS:
        list = live_ts, len = 4u, n = ((mcs_theory_spectrum *)(void *)o)->n;
        cap = (size_t)MCS_MAX_N;
        break;
    default: return;
    }
    if (n == 0u || n > cap)
        return;
    const live_array *a = &list[at % len];
    const size_t count = a->square ? n * n : n;
    memcpy(o + a->offset + ((at / len) % count) * sizeof v, &v, sizeof v);
}

/* Corruption: zeroed, 0xFF, a flipped byte in the first 64 (the header:
 * sizes, counts, kinds, paths), one double of the body or one of the values
 * in use set to a special value. The pattern's importance pointer and the
 * plans' KissFFT state are left alone: no C library can validate a wild
 * pointer or a foreign struct. */
static void corrupt(void)
{
    int type = (int)(byte() % NTYPES);
    unsigned char *o = obj(type, byte());
    size_t bytes = obj_size[type], at = (size_t)word(2);
    switch (byte() % 5u) {
    case 4: corrupt_live(type, o, at, dbl()); break;
    case 0: memset(o, 0, bytes); break;
    case 1: memset(o, 0xFF, bytes); break;
    case 2:
        at %= bytes < 64u ? bytes : 64u;
        if (type == PAT && at >= offsetof(mcs_pattern, importance))
            break;
        o[at] ^= (unsigned char)(1u << (byte() % 8u));
        break;
    default: {
        size_t lo = type == DFT ? bytes : type == SPEC ? offsetof(mcs_spectrum, mean_re) : 64u;
        if (type == PS || type == PS2 || type == S2)
            bytes = stats_end(type, o, bytes);
        if (bytes < lo + sizeof(double))
            break;
        double v = dbl();
        memcpy(o + lo + (at % ((bytes - lo) / sizeof v)) * sizeof v, &v, sizeof v);
    }
    }
}

/* ---- arguments: arrays and outputs ---- */

static double din[3][MAXLEN];
static size_t zin[MAXLEN];
static double dout[2][MAXLEN + GUARD];
static size_t zout[MAXLEN + GUARD];
static uint64_t uout[1 + GUARD];

/* A double array: one value, a ramp, values from the input, or valid points. */
static double *darray(int which, size_t len)
{
    double *d = din[which];
    unsigned mode = byte() % 4u;
    double v = dbl(), step = (double)(byte() % 16u) / 16.0;
    for (size_t j = 0; j < len; ++j)
        d[j] = mode == 0   ? v
               : mode == 1 ? 0.25 + step * (double)(j % 7u)
               : mode == 2 ? (j < 12u ? dbl() : d[j % 12u])
                           : ((double)j + step) / (double)len;
    return d;
}

/* The values of d[len] as floats for the _f calls (beyond the float range:
 * an infinity of its sign, since that conversion is undefined in C). */
static float fin[2u * MAXLEN]; /* the 2D calls read 2 k values */
static float *as_floats(const double *d, size_t len)
{
    for (size_t j = 0; j < len; ++j)
        fin[j] = fabs(d[j]) <= (double)FLT_MAX ? (float)d[j]
                 : isnan(d[j])                 ? NAN
                 : d[j] > 0.0                  ? INFINITY
                                               : -INFINITY;
    return fin;
}

/* Bins below n (mostly), or any value. */
static size_t *zarray(size_t len, size_t n)
{
    unsigned mode = byte() % 4u, mul = 1u + byte() % 7u;
    size_t off = byte();
    for (size_t j = 0; j < len; ++j)
        zin[j] = mode == 3 ? size_any() : n > 0u ? (j * mul + off) % (n + (mode == 2 && n < SIZE_MAX)) : off;
    return zin;
}

/* ---- checked calls ---- */

typedef struct {
    const void *p;
    size_t bytes, keep; /* keep: leading bytes a successful call may write */
    size_t snap;        /* where its bytes before the call are kept */
} region;

static region regs[8];
static int nregs;
static size_t snap_used;
static unsigned char snap[8u << 20]; /* above eight of the largest object (about 600 KB) */
static const char *cur_fn;

static void begin(const char *fn)
{
    cur_fn = fn;
    nregs = 0;
    snap_used = 0;
}

/* An input (keep 0), an object the call may update (keep all), or an output
 * of len elements of esize bytes (filled first; GUARD more elements after it). */
static void *reg(const void *p, size_t bytes, size_t keep)
{
    if (p != NULL && nregs < 8 && snap_used + bytes <= sizeof snap) {
        regs[nregs] = (region){p, bytes, keep, snap_used};
        memcpy(snap + snap_used, p, bytes);
        snap_used += bytes;
        ++nregs;
    }
    return (void *)(uintptr_t)p;
}

static void *out(void *p, size_t len, size_t esize)
{
    if (p == NULL)
        return NULL;
    memset(p, FILLBYTE, (len + GUARD) * esize);
    return reg(p, (len + GUARD) * esize, len * esize);
}

static void *inout(int type, void *o) { return reg(o, o ? obj_size[type] : 0u, o ? obj_size[type] : 0u); }

static mcs_status end(mcs_status st)
{
    for (int i = 0; i < nregs; ++i) {
        const region *g = &regs[i];
        const unsigned char *tail = (const unsigned char *)g->p + g->keep;
        const int same = memcmp(g->p, snap + g->snap, g->bytes) == 0;
        if (st != MCS_OK) {
            if (!same)
                finding(0, cur_fn, "failed call (%s) changed argument %d", mcs_status_str(st), i);
        } else if (g->keep == 0u) {
            if (!same)
                finding(0, cur_fn, "MCS_OK but changed input %d", i);
        } else {
            for (size_t j = 0; j < g->bytes - g->keep; ++j)
                if (tail[j] != FILLBYTE)
                    finding(0, cur_fn, "MCS_OK but wrote past output %d (byte +%zu)", i, j);
        }
    }
    return st;
}

/* Read-outs of a successful call: finite, and >= 0 where nonneg. */
static void vals(mcs_status st, const double *v, size_t n, int nonneg)
{
    for (size_t j = 0; st == MCS_OK && j < n; ++j) {
        if (!isfinite(v[j]))
            finding(5, cur_fn, "MCS_OK with value[%zu] = %g", j, v[j]);
        if (nonneg && v[j] < 0.0)
            finding(7, cur_fn, "MCS_OK with a negative variance or power %g at [%zu]", v[j], j);
    }
}

/* Count after a successful add (delta 1) or merge (delta the source's). */
static void counted(mcs_status st, uint64_t before, uint64_t delta, uint64_t after)
{
    if (st == MCS_OK && (before + delta < before || after != before + delta))
        finding(9, cur_fn, "count %llu + %llu became %llu", (unsigned long long)before,
                (unsigned long long)delta, (unsigned long long)after);
}

/* ---- accumulators: init, add, merge, count ---- */

static const int acc_types[7] = {WEL, SPEC, MOM, AC, PS, PS2, S2};

static mcs_status init_acc(int type, void *o, size_t n, size_t n2)
{
    switch (type) {
    case WEL: return mcs_welford_init(o);
    case SPEC: return mcs_spectrum_init(o, n);
    case MOM: return mcs_moment_init(o, n);
    case AC: return mcs_autocorr_init(o, n);
    /* the objects over caller memory: over their own buffer (none for NULL) */
    case PS: return mcs_pointset_init(o, n, 0u, o ? ((fz_pointset *)o)->mem : NULL, sizeof o_ps[0].mem);
    case PS2:
        return mcs_pointset2d_init(o, n, 0u, o ? ((fz_pointset2d *)o)->mem : NULL,
                                   sizeof o_ps2[0].mem);
    default:
        return mcs_spectrum2d_init(o, n, n2, o ? ((fz_spectrum2d *)o)->mem : NULL,
                                   sizeof o_s2[0].mem);
    }
}

static mcs_status merge_acc(int type, void *d, const void *s)
{
    switch (type) {
    case WEL: return mcs_welford_merge(d, s);
    case SPEC: return mcs_spectrum_merge(d, s);
    case MOM: return mcs_moment_merge(d, s);
    case AC: return mcs_autocorr_merge(d, s);
    case PS: return mcs_pointset_merge(d, s);
    case PS2: return mcs_pointset2d_merge(d, s);
    default: return mcs_spectrum2d_merge(d, s);
    }
}

static mcs_status count_acc(int type, const void *o, uint64_t *c)
{
    switch (type) {
    case WEL: *c = ((const mcs_welford *)o)->count; return MCS_OK;
    case SPEC: return mcs_spectrum_count(o, c);
    case MOM: return mcs_moment_count(o, c);
    case AC: return mcs_autocorr_count(o, c);
    case PS: return mcs_pointset_count(o, c);
    case PS2: return mcs_pointset2d_count(o, c);
    default: return mcs_spectrum2d_count(o, c);
    }
}

static void op_acc_init_merge_count(unsigned which)
{
    const int type = acc_types[byte() % 7u];
    void *o = obj_or_null(type);
    begin(which == 0 ? "init" : which == 1 ? "merge" : "count");
    if (which == 0) {
        size_t n = size_any(), n2 = size_any();
        mcs_status st = end(init_acc(type, inout(type, o), n, n2));
        if (st == MCS_OK && count_of(type, o) != 0u)
            finding(0, cur_fn, "init left the count at %llu", (unsigned long long)count_of(type, o));
    } else if (which == 1) {
        const void *src = obj_or_null(type); /* the same object half of the time: a self-merge */
        uint64_t d = o ? count_of(type, o) : 0u, sc = src ? count_of(type, src) : 0u;
        if (src != o)
            reg(src, src ? obj_size[type] : 0u, 0u);
        mcs_status st = end(merge_acc(type, inout(type, o), src));
        if (o != NULL)
            counted(st, d, sc, count_of(type, o));
    } else if (type != WEL) {
        uint64_t *c = out(uout, 1, 8);
        reg(o, o ? obj_size[type] : 0u, 0u);
        mcs_status st = end(count_acc(type, o, c));
        if (st == MCS_OK && *c != count_of(type, o))
            finding(0, cur_fn, "count read-out %llu, field %llu", (unsigned long long)*c,
                    (unsigned long long)count_of(type, o));
    }
}

/* After a successful add of k finite samples: does some bin's s_n = the sum
 * of its weights overflow? Then no spectrum of the trial exists, and MCS_OK
 * means a stale or poisoned one (item 1 on the FFT path, 5 elsewhere). */
static int bin_sum_overflows(size_t n, size_t k, const size_t *bins, const double *pts,
                             const double *w)
{
    static double sum[MAXLEN];
    if (n == 0u || n > MAXLEN)
        return 0;
    memset(sum, 0, n * sizeof sum[0]);
    int bad = 0;
    for (size_t j = 0; j < k; ++j) {
        size_t b = bins != NULL ? bins[j] : (size_t)(pts[j] * (double)n);
        if (b < n) {
            sum[b] += w != NULL ? w[j] : 1.0;
            bad |= !isfinite(sum[b]);
        }
    }
    return bad;
}

/* One trial into an accumulator: sparse bins, dense s, or points. */
static void op_add(void)
{
    const int type = acc_types[byte() % 7u];
    void *o = obj_or_null(type);
    /* Every accumulator but welford starts with its size_t N (or F, or N1). */
    const size_t k = len_arg(), nb = o != NULL && type != WEL ? *(const size_t *)o : 16u;
    /* One byte picks the input form and whether points go in as float. */
    const unsigned how_byte = byte(), how = how_byte % 3u, as_float = how_byte / 3u % 2u;
    uint64_t before = o ? count_of(type, o) : 0u;
    begin("add");
    const double *w = byte() % 8u == 0u ? NULL : reg(darray(0, k), k * 8, 0);
    const double *pts = reg(darray(1, 2u * k), 2u * k * 8, 0);
    const float *ptf = as_float ? reg(as_floats(pts, 2u * k), 2u * k * 4, 0) : NULL;
    inout(type, o);
    mcs_status st;
    switch (type) {
    case WEL: st = mcs_welford_add(o, dbl()); break;
    case SPEC:
        st = how == 0 ? mcs_spectrum_add_bins(o, k, reg(zarray(k, nb), k * sizeof(size_t), 0), w)
             : how == 1 ? mcs_spectrum_add_dense(o, k, w)
             : as_float ? mcs_spectrum_add_points_f(o, k, ptf, w)
                        : mcs_spectrum_add_points(o, k, pts, w);
        break;
    case MOM:
        st = how == 0 ? mcs_moment_add_bins(o, k, reg(zarray(k, nb), k * sizeof(size_t), 0), w)
                      : mcs_moment_add_dense(o, k, w);
        break;
    case AC: st = mcs_autocorr_add_bins(o, k, reg(zarray(k, nb), k * sizeof(size_t), 0), w); break;
    case PS: st = as_float ? mcs_pointset_add_f(o, k, ptf) : mcs_pointset_add(o, k, pts); break;
    case PS2:
        st = as_float ? mcs_pointset2d_add_f(o, k, ptf) : mcs_pointset2d_add(o, k, pts);
        break;
    default:
        st = as_float ? mcs_spectrum2d_add_points_f(o, k, ptf, w)
                      : mcs_spectrum2d_add_points(o, k, pts, w);
        break;
    }
    end(st);
    if (o != NULL)
        counted(st, before, 1u, count_of(type, o));
    const int sparse = type == AC || (type == MOM && how == 0) || (type == SPEC && how != 1);
    if (st == MCS_OK && sparse && bin_sum_overflows(nb, k, type == SPEC && how == 2 ? NULL : zin, pts, w))
        finding(type == SPEC ? 1 : 5, cur_fn, "MCS_OK for a trial whose bin sum overflows");
}

/* The read-outs and the operations on generators, plans, theory, closed
 * forms and 2D objects: a second file of this one translation unit (a
 * libFuzzer target is built from one source, mk/fuzz.mk). */
#include "fuzz_api_ops.h"

/* ---- the program ---- */

static void reset_objects(void)
{
    for (int t = 0; t < NTYPES; ++t)
        if (dirty & (1u << t))
            memset(objs[t], 0, 2u * obj_size[t]);
    dirty = 0u;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static int ready;
    if (!ready) {
        const char *k = getenv("FUZZ_API_KNOWN");
        skip_known = k != NULL && (strcmp(k, "skip") == 0 || atoi(k) > 0);
        only_item = k != NULL ? atoi(k) : 0;
        ready = 1;
    }
    reset_objects();
    in_p = data;
    in_n = size;
    for (int ops = 0; in_n > 0u && ops < 64; ++ops) {
        const unsigned op = byte() % 25u;
        if (op < 7u)
            op_readout(op);
        else if (op < 10u)
            op_acc_init_merge_count(op - 7u);
        else if (op < 13u)
            op_add();
        else
            switch (op) {
            case 13: op_welford_readout(); break;
            case 14: op_rng(); break;
            case 15: op_importance(); break;
            case 16: op_pattern(); break;
            case 17: op_estimate(); break;
            case 18: op_sampler_pattern2d(); break;
            case 19: op_dft_autocorr(); break;
            case 20: op_theory_init(); break;
            case 21: byte() % 2u ? op_eq_plain() : op_eq_importance(); break;
            case 22: byte() % 2u ? op_2d() : op_misc(); break;
            case 23: op_save_load(); break;
            default: corrupt(); break;
            }
    }
    return 0;
}
