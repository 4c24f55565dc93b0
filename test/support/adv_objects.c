/* Objects of the adversarial table: the baseline of each type (N = 12 bins,
 * K = 6 samples, a few trials in), its bad states (zeroed, 0xFF, another N,
 * a full count), and the read-outs that must stay finite after a successful
 * update. */
#include "adv.h"
#include "adv_world.h" /* the arena: a plan's buffer, a provenance's slot */

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#define BASE_N 12u
#define BASE_K 6u

/* ---- measure accumulators, NUFFT plans, provenances and records ----
 * Their N: the dimension of an accumulator (1 small, 2 base, the largest it
 * accepts max), F of a plan (3 small, 8 base, and as max the largest F whose
 * buffer and output the row's arena holds, 16384 in 1D and 128 in 2D, where
 * nufft.h accepts 2^26 and 2^16), for a provenance another run (its N of 7
 * bins, small) or its list full (max), and the record of another spectrum.
 * OV_FULL of an accumulator is every count at MCS_MAX_COUNT, the most one
 * holds, so adds and merges must answer MCS_ERR_COUNT (a count of
 * UINT64_MAX is only a bad state, which the zeroed and 0xFF rows give). */

static double meas_frac(double x) { return x - floor(x); }

/* Set t of k points in dim coordinates, spread and in [0, 1). */
static void meas_points(int t, size_t k, size_t dim, double *p)
{
    for (size_t i = 0; i < k; ++i)
        for (size_t a = 0; a < dim; ++a)
            p[i * dim + a] = meas_frac(0.1 * t + 0.6180339887 * (double)i +
                                       0.7548776662 * (double)(i * a + a) + 0.05);
}

static size_t meas_dim(int type, int ov)
{
    const int disc = type == T_DISC;
    if (type == T_PCF)
        return ov == OV_SMALL ? 1u : 2u;
    return ov == OV_SMALL ? 1u
           : ov == OV_BIG ? (disc ? (size_t)MCS_DISCREPANCY_MAX_DIM : (size_t)MCS_SPACING_MAX_DIM)
                          : 2u;
}

static void disc_build(int ov, mcs_discrepancy *acc)
{
    static double pts[7u * MCS_DISCREPANCY_MAX_DIM];
    static unsigned char work[MCS_DISCREPANCY_STAR_WORK_SIZE(7)];
    const size_t dim = meas_dim(T_DISC, ov);
    (void)mcs_discrepancy_init(acc, dim);
    for (int t = 0; t < 3 && ov != OV_EMPTY; ++t) { /* 5, 6, 7 points: 1/K varies too */
        meas_points(t, 5u + (size_t)t, dim, pts);
        (void)mcs_discrepancy_add(acc, 5u + (size_t)t, pts, work, sizeof work);
    }
    if (ov == OV_FULL) {
        acc->inv_k.count = MCS_MAX_COUNT;
        for (int m = 0; m < MCS_DISCREPANCY_MEASURES; ++m)
            acc->d2[m].count = MCS_MAX_COUNT;
    }
}

static void spacing_build(int ov, mcs_spacing *acc)
{
    static double pts[64u * MCS_SPACING_MAX_DIM];
    static unsigned char work[MCS_SPACING_WORK_SIZE(64)];
    const size_t dim = meas_dim(T_SPACING, ov);
    (void)mcs_spacing_init(acc, dim);
    for (int t = 0; t < 3 && ov != OV_EMPTY; ++t) { /* 16, 40, 64 points: 64 takes the grid */
        const size_t k = t == 0 ? 16u : t == 1 ? 40u : 64u;
        meas_points(t, k, dim, pts);
        (void)mcs_spacing_add(acc, k, pts, work, sizeof work);
    }
    if (ov == OV_FULL)
        for (int s = 0; s < MCS_SPACING_STATISTICS; ++s)
            acc->stat[s].count = MCS_MAX_COUNT;
}

/* An integrand: a disk in 2D (base; variant 1: in 1D), in the other
 * dimension (small), a Gaussian (max). */
static void integrand_build(int ov, int v, mcs_integrand *f)
{
    mcs_rng rng;
    (void)mcs_rng_seed(&rng, 25u, 1u);
    if (v >= 2) { /* utk's: 2 a Blinn-Phong lobe (2D), 3 a clipped Gaussian mixture */
        const size_t d = v == 3 && ov == OV_SMALL ? 1u : 2u;
        (void)mcs_integrand_draw(f, v == 2 ? MCS_INTEGRAND_BLINN_PHONG : MCS_INTEGRAND_GAUSSIAN_MIXTURE,
                                 d, &rng);
        return;
    }
    const size_t dim = (v == 1) != (ov == OV_SMALL) ? 1u : 2u;
    (void)mcs_integrand_draw(f, ov == OV_BIG ? MCS_INTEGRAND_GAUSSIAN : MCS_INTEGRAND_DISK, dim,
                             &rng);
}

/* The integration error of disks (base, 2D; small: 1D), or of Heavisides
 * (max, 2D): three sets of 5, 6, 7 points with one integrand each. */
static void integrate_build(int ov, mcs_integrate *acc)
{
    static double pts[14];
    const size_t dim = ov == OV_SMALL ? 1u : 2u;
    const mcs_integrand_family fam = ov == OV_BIG ? MCS_INTEGRAND_HEAVISIDE : MCS_INTEGRAND_DISK;
    mcs_rng rng;
    (void)mcs_rng_seed(&rng, 26u, 1u);
    (void)mcs_integrate_init(acc, fam, dim);
    for (int t = 0; t < 3 && ov != OV_EMPTY; ++t) {
        mcs_integrand f;
        (void)mcs_integrand_draw(&f, fam, dim, &rng);
        meas_points(t, 5u + (size_t)t, dim, pts);
        (void)mcs_integrate_add(acc, 1u, &f, 5u + (size_t)t, pts, MCS_INTEGRATE_RANDOM, 0u, 0u);
    }
    if (ov == OV_FULL)
        acc->sq.count = acc->exact.count = MCS_MAX_COUNT;
}

/* A pair-correlation accumulator over a buffer inside the object (8 bins
 * of psa's RDF over [0, 1/2) mean spacings; 1D for OV_SMALL; no OV_BIG, as
 * 2D is the base), three sets of 64 points in (one K, so its radial power
 * reads out; 64 takes the cell grid). The header's pointers point
 * into the object's own buffer, so a copy is repointed (adv_copy_object). */
typedef struct {
    mcs_pcf acc;
    _Alignas(64) unsigned char mem[MCS_PCF_SIZE(8)];
} adv_pcf;

static void pcf_build(int ov, adv_pcf *o)
{
    static double pts[2u * 64u];
    static unsigned char work[MCS_PCF_WORK_SIZE(64)];
    const size_t dim = meas_dim(T_PCF, ov);
    (void)mcs_pcf_init(&o->acc, dim, MCS_PCF_RDF, 8u, 0.5, 0.0, o->mem, sizeof o->mem);
    for (int t = 0; t < 3 && ov != OV_EMPTY; ++t) {
        meas_points(t, 64u, dim, pts);
        (void)mcs_pcf_add(&o->acc, 64u, pts, work, sizeof work);
    }
    if (ov == OV_FULL)
        o->acc.count = MCS_MAX_COUNT;
}

/* Plan variants: the dimension as L_KDIM reads it (1 for v % 7 < 3), so
 * that points[k d] follow the plan, and a tolerance each (1e-15: the widest
 * kernel; 1e-14 in 2D: sigma 5/2; 1e-1: the narrowest). */
static const double nufft_tols[6] = {1e-9, 1e-15, 1e-1, 1e-6, 1e-14, 1e-1};
static const char *const nufft_names[6] = {"1d-tol1e-9", "1d-tol1e-15", "1d-tol1e-1",
                                           "2d-tol1e-6", "2d-tol1e-14", "2d-tol1e-1"};

static size_t nufft_dim(int v) { return v % 7 < 3 ? 1u : 2u; }

static size_t nufft_freq(int ov, int v)
{
    return ov == OV_SMALL ? 3u : ov != OV_BIG ? 8u : nufft_dim(v) == 1u ? 16384u : 128u;
}

/* The plan over a buffer of the row's arena (a dependency the call may
 * write, as a transform uses it as scratch), set up for another header and
 * copied in (copies share the buffer, nufft.h); the zeroed and 0xFF states
 * are the header's, over a real buffer. */
static void nufft_build(int ov, int v, mcs_nufft *plan)
{
    const size_t dim = nufft_dim(v % 6), freq = nufft_freq(ov, v % 6);
    const double tol = nufft_tols[v % 6];
    size_t bytes = 0;
    mcs_nufft made;
    memset(&made, 0, sizeof made);
    (void)mcs_nufft_size(dim, freq, tol, &bytes);
    void *mem = adv_region_for(bytes, -1, K_OBJ_IO);
    if (mem != NULL) { /* else the overflow flag fails the row */
        memset(mem, 0, bytes);
        (void)mcs_nufft_init(&made, dim, freq, tol, mem, bytes);
    }
    memcpy(plan, &made, sizeof made);
    if (ov == OV_ZERO || ov == OV_FF)
        memset(plan, ov == OV_ZERO ? 0 : 0xFF, sizeof *plan);
}

/* The slot of the arena region obj starts, -1 outside the arena. */
static int arena_slot(const void *obj)
{
    for (int g = 0; g < adv_nregs; ++g)
        if (adv_arena + adv_regs[g].off == (const unsigned char *)obj)
            return adv_regs[g].slot;
    return -1;
}

/* A provenance, variant v % 2: 0 a pattern run (one stream range), 1 point
 * sets (two input files). Slot s holds streams or inputs of its own, so a
 * merge of two baselines is one of disjoint pieces; the block of a record
 * (s < 0) its own too. */
static void prov_build(int ov, int v, int s, mcs_io_provenance *p)
{
    static const char *const names[2] = {"in/first.txt", "in/second.csv"};
    const uint64_t own = s < 0 ? 2u : (uint64_t)s;
    memset(p, 0, sizeof *p);
    if (v % 2 == 1 && ov != OV_SMALL) {
        p->source = MCS_IO_SOURCE_POINTS;
        p->ninputs = ov == OV_BIG ? MCS_IO_PROV_MAX_INPUTS : 2u;
        for (uint32_t i = 0; i < p->ninputs; ++i) {
            p->input[i].crc =
                ov == OV_BIG ? 0x20000u + 2u * i : (i + 1u) * 0x1000u + 16u * (uint32_t)own;
            p->input[i].bytes = 100u + i;
            memcpy(p->input[i].name, names[i % 2], strlen(names[i % 2]));
        }
        return;
    }
    p->source = MCS_IO_SOURCE_PATTERN;
    p->dim = 1u;
    memcpy(p->pattern, "stratified", 10);
    p->n = ov == OV_SMALL ? 7u : BASE_N;
    p->k = BASE_K;
    p->importance = 1u;
    p->importance_crc = 0xC0FFEEu;
    p->streams = 64u;
    p->trials = 643u;
    p->nranges = ov == OV_BIG ? MCS_IO_PROV_MAX_RANGES : 1u;
    for (uint32_t i = 0; i < p->nranges; ++i) {
        p->range[i].seed = ov == OV_BIG ? 100u + i : 42u;
        p->range[i].first = ov == OV_BIG ? 0u : 2u * own;
        p->range[i].end = ov == OV_BIG ? 1u : 2u * own + 1u;
    }
}

/* A record buffer, variant v % 4: a saved spectrum (N 12; 7 small, the
 * largest max) with the block of a pattern run (0), of point sets (1), or
 * none (version 1: 2, 3); zeros after it. Its length into *len. */
static void record_build(int ov, int v, unsigned char *buf, size_t *len)
{
    static _Alignas(64) unsigned char acc[sizeof(mcs_spectrum)];
    mcs_io_provenance prov;
    memset(buf, 0, ADV_RECORD_CAP);
    *len = 0;
    (void)adv_build(T_SPECTRUM, ov == OV_SMALL || ov == OV_BIG ? ov : OV_BASE, 0, acc);
    (void)mcs_io_save_spectrum((const mcs_spectrum *)(const void *)acc, ADV_RECORD_CAP, buf, len);
    if (v % 4 < 2) {
        prov_build(OV_BASE, v % 4, -1, &prov);
        (void)mcs_io_set_provenance(&prov, ADV_RECORD_CAP, buf, len);
    }
}

/* The base record of variant v, and its length into *len. */
static const unsigned char *record_of(int v, size_t *len)
{
    static unsigned char buf[ADV_RECORD_CAP];
    record_build(OV_BASE, v, buf, len);
    return buf;
}

static size_t record_length(int v)
{
    size_t len = 0;
    (void)record_of(v, &len);
    return len;
}

/* Builds a type of this section (adv_build's contract). */
static int meas_build(int type, int ov, int v, void *obj)
{
    if ((ov == OV_EMPTY || ov == OV_FULL) && !adv_has_count(type))
        return 0;
    if (ov == OV_BIGK || (ov == OV_BIG && type == T_PCF))
        return 0;
    if ((ov == OV_ZERO || ov == OV_FF) && type != T_NUFFT) {
        memset(obj, ov == OV_ZERO ? 0 : 0xFF, adv_type_size(type));
        return 1;
    }
    memset(obj, 0x3C, adv_type_size(type)); /* padding bytes get a known value too */
    switch (type) {
    case T_DISC: disc_build(ov, obj); break;
    case T_SPACING: spacing_build(ov, obj); break;
    case T_INTEGRAND: integrand_build(ov, v, obj); break;
    case T_INTEGRATE: integrate_build(ov, obj); break;
    case T_PCF: pcf_build(ov, obj); break;
    case T_NUFFT: nufft_build(ov, v, obj); break;
    case T_PROV: prov_build(ov, v, arena_slot(obj), obj); break;
    case T_RECORD: {
        size_t len = 0;
        record_build(ov, v, obj, &len);
        break;
    }
    default: { /* T_RECLEN: the base record's length, or one byte short or over */
        const size_t len = record_length(v);
        *(size_t *)obj = ov == OV_SMALL ? len - 1u : ov == OV_BIG ? len + 1u : len;
        break;
    }
    }
    return 1;
}

static size_t meas_type_size(int type)
{
    switch (type) {
    case T_DISC: return sizeof(mcs_discrepancy);
    case T_SPACING: return sizeof(mcs_spacing);
    case T_PCF: return sizeof(adv_pcf);
    case T_NUFFT: return sizeof(mcs_nufft);
    case T_PROV: return sizeof(mcs_io_provenance);
    case T_RECORD: return ADV_RECORD_CAP;
    case T_INTEGRAND: return sizeof(mcs_integrand);
    case T_INTEGRATE: return sizeof(mcs_integrate);
    default: return sizeof(size_t);
    }
}

static const char *const meas_type_names[T_COUNT - T_DISC] = {
    "discrepancy", "spacing", "nufft", "provenance", "record", "record_len", "integrand",
    "integrate", "pcf"};

/* Variant names: a plan's dimension and tolerance, a provenance's source,
 * and (a record appears only in mcs_io_set_provenance's rows) the source
 * set on which record. */
static const char *meas_variant_name(int type, int v)
{
    static const char *const set_names[4] = {"pattern-on-pattern-block", "points-on-points-block",
                                             "pattern-on-version-1", "points-on-version-1"};
    switch (type) {
    case T_NUFFT: return nufft_names[v % 6];
    case T_PROV: return v % 2 ? "points" : "pattern";
    case T_RECORD: return set_names[v % 4];
    default: return "";
    }
}

/* N of a state, as adv_state_n (a plan: its F in 1D) and as adv_state_nn:
 * an accumulator's set of ADV_LONG_LEN points (the add rows' points[k d]),
 * a plan's output of 2 (2F + 1)^d doubles. */
static size_t meas_state_n(int type, int ov)
{
    if (type == T_NUFFT)
        return nufft_freq(ov, 0);
    if (type == T_INTEGRAND || type == T_INTEGRATE)
        return ov == OV_SMALL ? 1u : 2u;
    return type == T_DISC || type == T_SPACING || type == T_PCF ? meas_dim(type, ov) : 0u;
}

static size_t meas_state_nn(int type, int ov, int v)
{
    if (type == T_NUFFT) {
        const size_t side = 2u * nufft_freq(ov, v % 6) + 1u;
        return 2u * (nufft_dim(v % 6) == 1u ? side : side * side);
    }
    if (type == T_INTEGRAND || type == T_INTEGRATE)
        return (size_t)ADV_LONG_LEN * (ov == OV_SMALL ? 1u : 2u);
    return type == T_DISC || type == T_SPACING || type == T_PCF
               ? (size_t)ADV_LONG_LEN * meas_dim(type, ov)
               : 0u;
}

static const size_t type_sizes[T_COUNT] = {
    0, sizeof(mcs_rng), sizeof(mcs_importance), sizeof(mcs_pattern), sizeof(mcs_sampler),
    sizeof(mcs_pattern2d), sizeof(mcs_welford), sizeof(mcs_dft), sizeof(mcs_spectrum),
    sizeof(mcs_moment), sizeof(mcs_autocorr), sizeof(adv_pointset), sizeof(adv_pointset2d),
    sizeof(adv_spectrum2d), sizeof(mcs_theory), sizeof(mcs_theory_spectrum)};

static const char *const type_names[T_COUNT] = {
    "-", "rng", "importance", "pattern", "sampler", "pattern2d", "welford", "dft",
    "spectrum", "moment", "autocorr", "pointset", "pointset2d", "spectrum2d", "theory",
    "theory_spectrum"};

size_t adv_type_size(int type)
{
    if (type >= T_DISC)
        return meas_type_size(type);
    return type_sizes[type];
}

const char *adv_type_name(int type)
{
    if (type >= T_DISC)
        return meas_type_names[type - T_DISC];
    return type_names[type];
}

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
    if (type >= T_DISC)
        return meas_variant_name(type, v);
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
                                        MCS_MAX_N, MCS_MAX_COV_N, MCS_MAX_N, ADV_PS_BIG,
                                        ADV_PS2_BIG, ADV_S2_BIG, MCS_MAX_COV_N, MCS_MAX_N};
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
    case T_POINTSET: ((adv_pointset *)obj)->acc.state->count = c; break;
    case T_POINTSET2D: ((adv_pointset2d *)obj)->acc.state->count = c; break;
    case T_SPECTRUM2D: ((adv_spectrum2d *)obj)->acc.state->count = c; break;
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
    case T_POINTSET: {
        adv_pointset *o = obj;
        (void)mcs_pointset_init(&o->acc, n, 0u, o->mem, sizeof o->mem);
        break;
    }
    case T_POINTSET2D: {
        adv_pointset2d *o = obj;
        (void)mcs_pointset2d_init(&o->acc, n, 0u, o->mem, sizeof o->mem);
        break;
    }
    case T_SPECTRUM2D: {
        adv_spectrum2d *o = obj;
        (void)mcs_spectrum2d_init(&o->acc, n, n == 6u ? 4u : n == 3u ? 5u : n, o->mem,
                                  sizeof o->mem);
        break;
    }
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
    if (type >= T_DISC)
        return meas_build(type, ov, v, obj);
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
    case T_DISC: return ((const mcs_discrepancy *)obj)->dim;
    case T_SPACING: return ((const mcs_spacing *)obj)->dim;
    case T_INTEGRAND: return ((const mcs_integrand *)obj)->dim;
    case T_INTEGRATE: return ((const mcs_integrate *)obj)->dim;
    case T_PCF: return ((const mcs_pcf *)obj)->dim;
    case T_NUFFT: return ((const mcs_nufft *)obj)->freq;
    default: return 0;
    }
}

size_t adv_state_n(int type, int ov)
{
    if (type >= T_DISC)
        return meas_state_n(type, ov);
    return size_of_state(type, ov);
}

/* The same for the arrays over an object's whole index set (N1 N2 bins of a
 * 2D spectrum, K dim coordinates of a sampler). */
size_t adv_state_nn(int type, int ov, int v)
{
    if (type >= T_DISC)
        return meas_state_nn(type, ov, v);
    size_t n = size_of_state(type, ov);
    if (type == T_SPECTRUM2D)
        return n * (n == 6u ? 4u : n == 3u ? 5u : n);
    if (type == T_SAMPLER)
        return n * (v % 7 < 3 ? 1u : 2u);
    return n;
}

int adv_has_count(int type)
{
    if (type == T_DISC || type == T_SPACING || type == T_INTEGRATE || type == T_PCF)
        return 1;
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
    case T_DISC: return ((const mcs_discrepancy *)obj)->inv_k.count;
    case T_SPACING: return ((const mcs_spacing *)obj)->stat[0].count;
    case T_INTEGRATE: return ((const mcs_integrate *)obj)->sq.count;
    case T_PCF: return ((const mcs_pcf *)obj)->count;
    default: break;
    }
    /* Their count is in their buffer, read only through a header that
     * passes its own check (a zeroed one points nowhere). */
    uint64_t c = 0u;
    const mcs_status st = type == T_POINTSET     ? mcs_pointset_count(obj, &c)
                          : type == T_POINTSET2D ? mcs_pointset2d_count(obj, &c)
                          : type == T_SPECTRUM2D ? mcs_spectrum2d_count(obj, &c)
                                                 : MCS_ERR_KIND;
    return st == MCS_OK ? c : 0u;
}

void adv_copy_object(int type, void *dst, const void *src)
{
    switch (type) {
    case T_POINTSET: {
        adv_pointset *d = dst;
        memcpy(d, src, sizeof *d);
        (void)mcs_pointset_copy(&d->acc, d->mem, sizeof d->mem, src);
        break;
    }
    case T_POINTSET2D: {
        adv_pointset2d *d = dst;
        memcpy(d, src, sizeof *d);
        (void)mcs_pointset2d_copy(&d->acc, d->mem, sizeof d->mem, src);
        break;
    }
    case T_SPECTRUM2D: {
        adv_spectrum2d *d = dst;
        memcpy(d, src, sizeof *d);
        (void)mcs_spectrum2d_copy(&d->acc, d->mem, sizeof d->mem, src);
        break;
    }
    case T_PCF: { /* repoint what pointed into the source's own buffer */
        adv_pcf *d = dst;
        const adv_pcf *o = src;
        memcpy(d, o, sizeof *d);
        const uintptr_t lo = (uintptr_t)o->mem, hi = lo + sizeof o->mem;
        double **ptrs[3] = {&d->acc.mean, &d->acc.m2, &d->acc.value};
        for (int i = 0; i < 3; ++i)
            if ((uintptr_t)*ptrs[i] >= lo && (uintptr_t)*ptrs[i] < hi)
                *ptrs[i] = (double *)(void *)(d->mem + ((uintptr_t)*ptrs[i] - lo));
        if ((uintptr_t)o->acc.mem >= lo && (uintptr_t)o->acc.mem < hi)
            d->acc.mem = d->mem + ((uintptr_t)o->acc.mem - lo);
        break;
    }
    default: memcpy(dst, src, adv_type_size(type)); break;
    }
}

/* The record of an object over caller memory (its statistics and count,
 * wherever they are), then its settings; the raw bytes if it has none. */
size_t adv_canonical(int type, const void *obj, unsigned char *out, size_t cap)
{
    size_t len = 0u;
    mcs_status st = MCS_ERR_KIND;
    int settings[4] = {0, 0, 0, 0};
    switch (type) {
    case T_POINTSET: {
        const mcs_pointset *a = obj;
        st = mcs_io_save_pointset(a, cap - sizeof settings, out, &len);
        settings[0] = (int)a->flags, settings[1] = (int)a->path, settings[2] = a->wrap;
        break;
    }
    case T_POINTSET2D: {
        const mcs_pointset2d *a = obj;
        st = mcs_io_save_pointset2d(a, cap - sizeof settings, out, &len);
        settings[0] = (int)a->flags, settings[1] = (int)a->path, settings[2] = a->wrap;
        break;
    }
    case T_SPECTRUM2D: {
        const mcs_spectrum2d *a = obj;
        st = mcs_io_save_spectrum2d(a, cap - sizeof settings, out, &len);
        settings[2] = a->wrap;
        break;
    }
    case T_PCF: { /* the fields and the statistics, wherever the buffer is */
        const mcs_pcf *a = obj;
        const double fields[8] = {(double)a->dim, (double)a->estimator, (double)a->bins, a->radius,
                                  a->sigma, (double)a->count, (double)a->k_min, (double)a->k_max};
        if (sizeof fields > cap)
            break;
        memcpy(out, fields, sizeof fields);
        len = sizeof fields;
        const int mine = a->bins <= 8u && a->mean == (const double *)(const void *)((const adv_pcf *)obj)->mem &&
                         a->m2 == a->mean + a->bins;
        if (mine && len + 2u * a->bins * sizeof(double) <= cap) {
            memcpy(out + len, a->mean, 2u * a->bins * sizeof(double));
            len += 2u * a->bins * sizeof(double);
        }
        return len;
    }
    default: break;
    }
    if (st != MCS_OK) {
        len = adv_type_size(type) < cap ? adv_type_size(type) : cap;
        memcpy(out, obj, len);
        return len;
    }
    memcpy(out + len, settings, sizeof settings);
    return len + sizeof settings;
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
    case T_PCF: return mcs_io_save_pcf(o, cap, buf, len);
    case T_INTEGRATE: return mcs_io_save_integrate(o, cap, buf, len);
    case T_DISC: return mcs_io_save_discrepancy(o, cap, buf, len);
    case T_SPACING: return mcs_io_save_spacing(o, cap, buf, len);
    default: return mcs_io_save_spectrum2d(o, cap, buf, len);
    }
}

/* The baseline object is built in a buffer of its own (records are of
 * accumulators, which have no dependencies in the arena). */
static const void *record_source(int type)
{
#define MAX2_(a, b) ((a) > (b) ? (a) : (b))
    static _Alignas(64) unsigned char obj[MAX2_(MAX2_(sizeof(mcs_spectrum), sizeof(adv_pointset)),
                                                MAX2_(sizeof(adv_pointset2d), sizeof(adv_spectrum2d)))];
#undef MAX2_
    (void)adv_build(type, OV_BASE, 0, obj);
    return obj;
}

size_t adv_record_size(int type)
{
    size_t len = 0;
    if (type == T_RECORD) /* the baseline record with a pattern run's block */
        return record_length(0);
    (void)save(type, record_source(type), 0u, NULL, &len);
    return len;
}

void adv_record(int type, void *buf)
{
    size_t len = 0;
    if (type == T_RECORD) {
        const unsigned char *rec = record_of(0, &len);
        memcpy(buf, rec, len);
        return;
    }
    (void)save(type, record_source(type), adv_record_size(type), buf, &len);
}
