/* Objects of the adversarial table: the baseline of each type (N = 12 bins,
 * K = 6 samples, a few trials in), its bad states (zeroed, 0xFF, another N,
 * a full count), and the read-outs that must stay finite after a successful
 * update. */
#include "adv.h"

#include <math.h>
#include <string.h>

#define BASE_N 12u
#define BASE_K 6u

static const size_t type_sizes[T_COUNT] = {
    0, sizeof(mcs_rng), sizeof(mcs_importance), sizeof(mcs_pattern), sizeof(mcs_sampler),
    sizeof(mcs_pattern2d), sizeof(mcs_welford), sizeof(mcs_dft), sizeof(mcs_spectrum),
    sizeof(mcs_moment), sizeof(mcs_autocorr), sizeof(mcs_pointset), sizeof(mcs_pointset2d),
    sizeof(mcs_spectrum2d), sizeof(mcs_theory), sizeof(mcs_theory_spectrum)};

static const char *const type_names[T_COUNT] = {
    "-", "rng", "importance", "pattern", "sampler", "pattern2d", "welford", "dft",
    "spectrum", "moment", "autocorr", "pointset", "pointset2d", "spectrum2d", "theory",
    "theory_spectrum"};

size_t adv_type_size(int type) { return type_sizes[type]; }
const char *adv_type_name(int type) { return type_names[type]; }

/* ---- baseline variants ---- */

static const mcs_pattern_kind pat_kinds[9] = {
    MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED, MCS_PATTERN_HOMOGENIZED, MCS_PATTERN_UNIFORM,
    MCS_PATTERN_JITTER, MCS_PATTERN_RANDOM, MCS_PATTERN_STRATIFIED, MCS_PATTERN_UNIFORM,
    MCS_PATTERN_JITTER};
static const mcs_sampler_kind smp_kinds[7] = {
    MCS_SAMPLER_VAN_DER_CORPUT, MCS_SAMPLER_SOBOL, MCS_SAMPLER_KRONECKER, MCS_SAMPLER_HALTON,
    MCS_SAMPLER_HAMMERSLEY, MCS_SAMPLER_SOBOL, MCS_SAMPLER_KRONECKER};
static const char *const path_names[3] = {"auto", "sparse", "fft"};
static char variant_buf[48];

const char *adv_variant_name(int type, int v)
{
    switch (type) {
    case T_SPECTRUM: return path_names[v % 3];
    case T_PAT:
    case T_THEORY:
    case T_TSPEC:
        v %= 9;
        variant_buf[0] = '\0';
        strcat(variant_buf, mcs_pattern_kind_str(pat_kinds[v]));
        strcat(variant_buf, v >= 5 ? "+importance" : "");
        return variant_buf;
    case T_PAT2D: return mcs_pattern2d_kind_str((mcs_pattern2d_kind)(v % 7));
    case T_SAMPLER:
        variant_buf[0] = '\0';
        strcat(variant_buf, mcs_sampler_kind_str(smp_kinds[v % 7]));
        strcat(variant_buf, v % 7 < 3 ? "-1d" : "-2d");
        return variant_buf;
    default: return "";
    }
}

int adv_variant_draws(int type, int v)
{
    if (type == T_PAT)
        return pat_kinds[v % 9] != MCS_PATTERN_UNIFORM;
    return type != T_PAT2D || v % 7 != MCS_PATTERN2D_GRID;
}

/* ---- trial data: deterministic, valid, with a repeated bin ---- */

static void trial_bins(size_t n, int t, size_t *bins, double *w)
{
    for (size_t j = 0; j < 5u; ++j) {
        bins[j] = ((size_t)t * 3u + j * 5u) % n;
        w[j] = 0.5 + 0.25 * (double)j;
    }
    bins[1] = bins[0];
}

static double frac(double x) { return x - floor(x); }

static void trial_points(int t, size_t count, double *p)
{
    for (size_t j = 0; j < count; ++j)
        p[j] = frac(0.1 * t + 0.6180339887 * (double)j + 0.05);
}

static void imp_build(mcs_importance *imp, size_t n)
{
    static double w[MCS_MAX_N];
    for (size_t j = 0; j < n; ++j)
        w[j] = 1.0 + (double)(j % 4u);
    (void)mcs_importance_init(imp, n, w);
}

static void pat_build(mcs_pattern *pat, int v, size_t n)
{
    mcs_importance *imp = NULL;
    if (v % 9 >= 5) {
        imp = adv_dep_alloc(sizeof *imp);
        imp_build(imp, n);
    }
    (void)mcs_pattern_init(pat, pat_kinds[v % 9], n, BASE_K, imp);
}

/* N of each sized type in the states OV_BASE, OV_SMALL, OV_BIG. */
static size_t size_of_state(int type, int ov)
{
    static const size_t base[T_COUNT] = {0, 0, 12, 12, 8, 6, 0, 12, 12, 12, 12, 8, 4, 6, 12, 12};
    static const size_t small[T_COUNT] = {0, 0, 7, 7, 4, 4, 0, 7, 7, 7, 7, 3, 2, 3, 7, 7};
    static const size_t big[T_COUNT] = {0, 0, MCS_MAX_N, MCS_MAX_N, 64, 64, 0, MCS_MAX_N,
                                        MCS_MAX_N, MCS_MAX_COV_N, MCS_MAX_N, MCS_MAX_FREQ_1D,
                                        MCS_MAX_FREQ, MCS_MAX_SIDE, MCS_MAX_COV_N, MCS_MAX_N};
    return ov == OV_SMALL ? small[type] : ov == OV_BIG ? big[type] : base[type];
}

static void fill_trials(int type, void *obj, int trials)
{
    size_t bins[5];
    double w[5], pts[2 * BASE_K];
    const size_t n = adv_obj_n(type, obj);
    for (int t = 0; t < trials; ++t) {
        if (n > 0u)
            trial_bins(n, t, bins, w);
        trial_points(t, 2 * BASE_K, pts);
        switch (type) {
        case T_WELFORD: (void)mcs_welford_add(obj, 1.0 + 0.3 * t * t); break;
        case T_SPECTRUM: /* batch 1: every trial a unit, so 3 trials have standard errors */
            (void)mcs_spectrum_set_batch(obj, 1u);
            (void)mcs_spectrum_add_bins(obj, 5u, bins, w);
            break;
        case T_MOMENT: (void)mcs_moment_add_bins(obj, 5u, bins, w); break;
        case T_AUTOCORR: (void)mcs_autocorr_add_bins(obj, 5u, bins, w); break;
        case T_POINTSET: (void)mcs_pointset_add(obj, BASE_K, pts); break;
        case T_POINTSET2D: (void)mcs_pointset2d_add(obj, BASE_K, pts); break;
        case T_SPECTRUM2D: (void)mcs_spectrum2d_add_points(obj, BASE_K, pts, NULL); break;
        default: break;
        }
    }
}

static void set_count(int type, void *obj, uint64_t c)
{
    switch (type) {
    case T_WELFORD: ((mcs_welford *)obj)->count = c; break;
    case T_SPECTRUM: ((mcs_spectrum *)obj)->count = c; break;
    case T_MOMENT: ((mcs_moment *)obj)->count = c; break;
    case T_AUTOCORR: ((mcs_autocorr *)obj)->count = c; break;
    case T_POINTSET: ((mcs_pointset *)obj)->count = c; break;
    case T_POINTSET2D: ((mcs_pointset2d *)obj)->count = c; break;
    case T_SPECTRUM2D: ((mcs_spectrum2d *)obj)->count = c; break;
    default: break;
    }
}

/* Initialises obj of a sized type for N = n (no trials). */
static void init_sized(int type, int v, size_t n, void *obj)
{
    switch (type) {
    case T_RNG: (void)mcs_rng_seed(obj, 42u, 54u); break;
    case T_IMP: imp_build(obj, n); break;
    case T_PAT: pat_build(obj, v, n); break;
    case T_SAMPLER: (void)mcs_sampler_init(obj, smp_kinds[v % 7], v % 7 < 3 ? 1u : 2u, n); break;
    case T_PAT2D: {
        size_t sx = n == 6u ? 3u : (size_t)sqrt((double)n);
        (void)mcs_pattern2d_init(obj, (mcs_pattern2d_kind)(v % 7), n, sx, n / sx);
        break;
    }
    case T_WELFORD: (void)mcs_welford_init(obj); break;
    case T_DFT: (void)mcs_dft_init(obj, n); break;
    case T_SPECTRUM:
        (void)mcs_spectrum_init(obj, n);
        (void)mcs_spectrum_set_path(obj, (mcs_spectrum_path)(v % 3));
        break;
    case T_MOMENT: (void)mcs_moment_init(obj, n); break;
    case T_AUTOCORR: (void)mcs_autocorr_init(obj, n); break;
    case T_POINTSET: (void)mcs_pointset_init(obj, n); break;
    case T_POINTSET2D: (void)mcs_pointset2d_init(obj, n); break;
    case T_SPECTRUM2D: (void)mcs_spectrum2d_init(obj, n, n == 6u ? 4u : n == 3u ? 5u : n); break;
    case T_THEORY:
    case T_TSPEC: {
        mcs_pattern *pat = adv_dep_alloc(sizeof *pat);
        pat_build(pat, v, n);
        (void)(type == T_THEORY ? mcs_theory_init(obj, pat) : mcs_theory_spectrum_init(obj, pat));
        break;
    }
    default: break;
    }
}

int adv_build(int type, int ov, int v, void *obj)
{
    const size_t bytes = type_sizes[type];
    const int acc = adv_has_count(type);
    switch (ov) {
    case OV_ZERO: memset(obj, 0, bytes); return 1;
    case OV_FF: memset(obj, 0xFF, bytes); return 1;
    case OV_EMPTY:
    case OV_FULL:
        if (!acc)
            return 0;
        break;
    case OV_SMALL:
    case OV_BIG:
        if (size_of_state(type, ov) == 0u)
            return 0;
        break;
    case OV_BIGK:
        if (type != T_PAT)
            return 0;
        break;
    default: break;
    }
    memset(obj, 0x3C, bytes); /* padding bytes get a known value too */
    init_sized(type, v, size_of_state(type, ov), obj);
    if (ov != OV_EMPTY && acc)
        fill_trials(type, obj, type == T_WELFORD ? 5 : 3);
    if (ov == OV_FULL)
        set_count(type, obj, UINT64_MAX);
    if (ov == OV_BIGK)
        ((mcs_pattern *)obj)->k = SIZE_MAX;
    return 1;
}

size_t adv_obj_n(int type, const void *obj)
{
    switch (type) {
    case T_IMP: return ((const mcs_importance *)obj)->n;
    case T_PAT: return ((const mcs_pattern *)obj)->n;
    case T_SAMPLER: return ((const mcs_sampler *)obj)->k;
    case T_PAT2D: return ((const mcs_pattern2d *)obj)->k;
    case T_DFT: return ((const mcs_dft *)obj)->n;
    case T_SPECTRUM: return ((const mcs_spectrum *)obj)->n;
    case T_MOMENT: return ((const mcs_moment *)obj)->n;
    case T_AUTOCORR: return ((const mcs_autocorr *)obj)->n;
    case T_POINTSET: return ((const mcs_pointset *)obj)->freq_max;
    case T_POINTSET2D: return ((const mcs_pointset2d *)obj)->freq_max;
    case T_SPECTRUM2D: return ((const mcs_spectrum2d *)obj)->n_x;
    case T_THEORY: return ((const mcs_theory *)obj)->n;
    case T_TSPEC: return ((const mcs_theory_spectrum *)obj)->n;
    default: return 0;
    }
}

size_t adv_state_n(int type, int ov)
{
    return size_of_state(type, ov);
}

/* The same for the arrays over an object's whole index set (N1 N2 bins of a
 * 2D spectrum, K dim coordinates of a sampler). */
size_t adv_state_nn(int type, int ov, int v)
{
    size_t n = size_of_state(type, ov);
    if (type == T_SPECTRUM2D)
        return n * (n == 6u ? 4u : n == 3u ? 5u : n);
    if (type == T_SAMPLER)
        return n * (v % 7 < 3 ? 1u : 2u);
    return n;
}

int adv_has_count(int type)
{
    return type == T_WELFORD || type == T_SPECTRUM || type == T_MOMENT || type == T_AUTOCORR ||
           type == T_POINTSET || type == T_POINTSET2D || type == T_SPECTRUM2D;
}

uint64_t adv_count(int type, const void *obj)
{
    switch (type) {
    case T_WELFORD: return ((const mcs_welford *)obj)->count;
    case T_SPECTRUM: return ((const mcs_spectrum *)obj)->count;
    case T_MOMENT: return ((const mcs_moment *)obj)->count;
    case T_AUTOCORR: return ((const mcs_autocorr *)obj)->count;
    case T_POINTSET: return ((const mcs_pointset *)obj)->count;
    case T_POINTSET2D: return ((const mcs_pointset2d *)obj)->count;
    case T_SPECTRUM2D: return ((const mcs_spectrum2d *)obj)->count;
    default: return 0;
    }
}

/* ---- records (io.h) ---- */

static mcs_status save(int type, const void *o, size_t cap, void *buf, size_t *len)
{
    switch (type) {
    case T_WELFORD: return mcs_io_save_welford(o, cap, buf, len);
    case T_SPECTRUM: return mcs_io_save_spectrum(o, cap, buf, len);
    case T_MOMENT: return mcs_io_save_moment(o, cap, buf, len);
    case T_AUTOCORR: return mcs_io_save_autocorr(o, cap, buf, len);
    case T_POINTSET: return mcs_io_save_pointset(o, cap, buf, len);
    case T_POINTSET2D: return mcs_io_save_pointset2d(o, cap, buf, len);
    default: return mcs_io_save_spectrum2d(o, cap, buf, len);
    }
}

/* The baseline object is built in a buffer of its own (records are of
 * accumulators, which have no dependencies in the arena). */
static const void *record_source(int type)
{
    static _Alignas(64) unsigned char obj[sizeof(mcs_spectrum)];
    (void)adv_build(type, OV_BASE, 0, obj);
    return obj;
}

size_t adv_record_size(int type)
{
    size_t len = 0;
    (void)save(type, record_source(type), 0u, NULL, &len);
    return len;
}

void adv_record(int type, void *buf)
{
    size_t len = 0;
    (void)save(type, record_source(type), adv_record_size(type), buf, &len);
}
