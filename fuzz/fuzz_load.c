/* libFuzzer target for the record loader (mk/fuzz.mk: make fuzz, make fuzz-ci).
 *
 * Every input is offered to the loader of every kind, each time into a
 * destination holding a known, different accumulator. The harness aborts
 * (a finding) unless, for each kind, either
 * - the load fails with one of the documented record statuses, agrees with
 *   mcs_io_peek on framing errors, and leaves the destination byte-identical; or
 * - the load succeeds, the loaded object saves back to exactly the input
 *   bytes (with the input's provenance block set again, for a version 2
 *   record: load keeps the statistics, not the block), and every read-out
 *   it offers is finite.
 * mcs_io_peek_provenance must agree with mcs_io_peek on every input, and a
 * provenance it reads must give the same block back.
 * Each input is checked twice: as given, and with its last four bytes
 * replaced by the right CRC-32, so that mutations get past the checksum and
 * reach the kind, shape and value checks (otherwise almost every mutant
 * stops at MCS_ERR_CHECKSUM). ASan and UBSan (the build flags) catch reads
 * past the input and undefined arithmetic on the way. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mcspec.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static mcs_spectrum spec, spec_pristine;
static mcs_moment mom, mom_pristine;
static mcs_autocorr ac, ac_pristine;
static mcs_welford wf, wf_pristine;
/* The objects over caller memory, each with a buffer for every shape a
 * record of the inputs' length (max_len, mk/fuzz.mk) holds but a few 2D
 * spectra of a long, thin grid, which the load refuses with MCS_ERR_SPACE
 * after all the record's checks (the harness asks mcs_io_load_size why). */
#define FZ_FREQ_1D 1024u
#define FZ_FREQ_2D 32u
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
/* The pcf over its buffer: bins up to what a record of max_len holds. */
#define FZ_PCF_BINS 1024u
typedef struct {
    mcs_pcf acc;
    _Alignas(64) unsigned char mem[MCS_PCF_SIZE(FZ_PCF_BINS)];
} fz_pcf;
static fz_pcf pcf_all, pcf_all_pristine;
static mcs_integrate integ, integ_pristine;
static mcs_discrepancy disc, disc_pristine;
static mcs_spacing spc, spc_pristine;
#define pcf (pcf_all.acc)
static double pcf_r[FZ_PCF_BINS], pcf_m[FZ_PCF_BINS], pcf_s[FZ_PCF_BINS];
static fz_pointset ps_all, ps_all_pristine;
static fz_pointset2d ps2_all, ps2_all_pristine;
static fz_spectrum2d sp2_all, sp2_all_pristine;
#define ps (ps_all.acc)
#define ps2 (ps2_all.acc)
#define sp2 (sp2_all.acc)
static mcs_dft plan;
static uint8_t saved[1u << 18]; /* above any record of the default capacities (85 KB) */
static mcs_io_provenance prov;   /* the input's, when peek_provenance reads one */
static double re[MCS_MAX_N], im[MCS_MAX_N];
static double mat_re[MCS_MAX_COV_N * MCS_MAX_COV_N], mat_im[MCS_MAX_COV_N * MCS_MAX_COV_N];

static void finding(const char *kind, const char *what)
{
    fprintf(stderr, "fuzz_load: %s: %s\n", kind, what);
    abort();
}

static void ok_or_die(mcs_status st, const char *kind, const char *what)
{
    if (st != MCS_OK) {
        fprintf(stderr, "fuzz_load: %s: %s returned %s\n", kind, what, mcs_status_str(st));
        abort();
    }
}

static void finite_or_die(double v, const char *kind, const char *what)
{
    if (!isfinite(v)) {
        fprintf(stderr, "fuzz_load: %s: %s is %g\n", kind, what, v);
        abort();
    }
}

/* Powers, variances and standard errors are never negative (every
 * accumulator clamps its rounding within a stated bound and refuses what lies
 * beyond it), so one below 0 from a loaded object is a record that lies. */
static void nonneg_or_die(double v, const char *kind, const char *what)
{
    finite_or_die(v, kind, what);
    if (v < 0.0) {
        fprintf(stderr, "fuzz_load: %s: %s is %g, below 0\n", kind, what, v);
        abort();
    }
}

static void setup_once(void)
{
    static int ready;
    if (ready)
        return;
    const size_t bins[3] = {1u, 4u, 4u};
    const double w[3] = {0.5, 2.0, 1.25};
    ok_or_die(mcs_spectrum_init(&spec_pristine, 9u), "setup", "spectrum init");
    ok_or_die(mcs_spectrum_add_bins(&spec_pristine, 3u, bins, w), "setup", "spectrum add");
    ok_or_die(mcs_moment_init(&mom_pristine, 6u), "setup", "moment init");
    ok_or_die(mcs_moment_add_bins(&mom_pristine, 3u, bins, w), "setup", "moment add");
    ok_or_die(mcs_autocorr_init(&ac_pristine, 11u), "setup", "autocorr init");
    ok_or_die(mcs_autocorr_add_bins(&ac_pristine, 3u, bins, w), "setup", "autocorr add");
    ok_or_die(mcs_welford_init(&wf_pristine), "setup", "welford init");
    ok_or_die(mcs_welford_add(&wf_pristine, 3.5), "setup", "welford add");
    const double pts[4] = {0.125, 0.5, 0.75, 0.375};
    fz_pointset *p1 = &ps_all_pristine;
    fz_pointset2d *p2 = &ps2_all_pristine;
    fz_spectrum2d *s2 = &sp2_all_pristine;
    ok_or_die(mcs_pointset_init(&p1->acc, 5u, 0u, p1->mem, sizeof p1->mem), "setup", "pointset init");
    ok_or_die(mcs_pointset_add(&p1->acc, 4u, pts), "setup", "pointset add");
    ok_or_die(mcs_pointset2d_init(&p2->acc, 3u, 0u, p2->mem, sizeof p2->mem), "setup",
              "pointset2d init");
    ok_or_die(mcs_pointset2d_add(&p2->acc, 2u, pts), "setup", "pointset2d add");
    ok_or_die(mcs_spectrum2d_init(&s2->acc, 3u, 4u, s2->mem, sizeof s2->mem), "setup",
              "spectrum2d init");
    ok_or_die(mcs_spectrum2d_add_points(&s2->acc, 2u, pts, NULL), "setup", "spectrum2d add");
    /* The measures: two sets of 2 points in 2D (the pcf's cutoff 0.5 / sqrt(2)). */
    static unsigned char work[MCS_DISCREPANCY_STAR_WORK_SIZE(2) + MCS_PCF_WORK_SIZE(2)];
    mcs_integrand f;
    mcs_rng rng;
    ok_or_die(mcs_rng_seed(&rng, 3u, 4u), "setup", "rng");
    ok_or_die(mcs_pcf_init(&pcf_all_pristine.acc, 2u, MCS_PCF_RDF, 3u, 0.5, 0.0,
                           pcf_all_pristine.mem, sizeof pcf_all_pristine.mem), "setup", "pcf init");
    ok_or_die(mcs_integrate_init(&integ_pristine, MCS_INTEGRAND_DISK, 2u), "setup", "integrate init");
    ok_or_die(mcs_integrand_draw(&f, MCS_INTEGRAND_DISK, 2u, &rng), "setup", "integrand");
    ok_or_die(mcs_discrepancy_init(&disc_pristine, 2u), "setup", "discrepancy init");
    ok_or_die(mcs_spacing_init(&spc_pristine, 2u), "setup", "spacing init");
    for (size_t t = 0; t < 2u; ++t) {
        ok_or_die(mcs_pcf_add(&pcf_all_pristine.acc, 2u, pts, work, sizeof work), "setup", "pcf add");
        ok_or_die(mcs_integrate_add(&integ_pristine, 1u, &f, 2u, pts, MCS_INTEGRATE_RANDOM, 0u, 0u),
                  "setup", "integrate add");
        ok_or_die(mcs_discrepancy_add(&disc_pristine, 2u, pts, work, sizeof work), "setup",
                  "discrepancy add");
        ok_or_die(mcs_spacing_add(&spc_pristine, 2u, pts, NULL, 0u), "setup", "spacing add");
    }
    ready = 1;
}

/* The statuses a record gives (and MCS_ERR_SPACE, a sound record whose
 * object is larger than this harness's buffer: checked where it occurs). */
static int is_record_status(mcs_status st)
{
    return st == MCS_ERR_MAGIC || st == MCS_ERR_TRUNCATED || st == MCS_ERR_VERSION ||
           st == MCS_ERR_FORMAT || st == MCS_ERR_CHECKSUM || st == MCS_ERR_KIND ||
           st == MCS_ERR_N_RANGE || st == MCS_ERR_FREQ_RANGE || st == MCS_ERR_NOT_FINITE ||
           st == MCS_ERR_INVARIANT || st == MCS_ERR_SPACE ||
           st == MCS_ERR_DOMAIN; /* a measure's shape word no init takes */
}

/* The common half of every kind's check: the status, the untouched
 * destination, and the save that must give the input back. */
static int loaded(const char *kind, mcs_status st, mcs_status peek_st, const void *dst,
                  const void *pristine, size_t obj_size)
{
    if (st != MCS_OK) {
        if (!is_record_status(st))
            finding(kind, "load failed with a status no record error gives");
        if (peek_st != MCS_OK && st != peek_st)
            finding(kind, "load and peek disagree on a framing error");
        if (memcmp(dst, pristine, obj_size) != 0)
            finding(kind, "failed load changed the destination");
        return 0;
    }
    if (peek_st != MCS_OK)
        finding(kind, "load accepted what peek refused");
    return 1;
}

static void same_bytes(const char *kind, size_t len, const uint8_t *data, size_t size)
{
    if (len != size || memcmp(saved, data, size) != 0)
        finding(kind, "saving the loaded object does not give the input back");
}

static void read_spectrum(void)
{
    uint64_t count = 0u, units = 0u;
    ok_or_die(mcs_spectrum_count(&spec, &count), "spectrum", "count");
    ok_or_die(mcs_spectrum_units(&spec, &units), "spectrum", "units");
    for (size_t f = 0; count >= 1u && f < spec.n; ++f) {
        double a, b;
        ok_or_die(mcs_spectrum_mean(&spec, f, &a, &b), "spectrum", "mean");
        finite_or_die(a, "spectrum", "mean re");
        finite_or_die(b, "spectrum", "mean im");
        ok_or_die(mcs_spectrum_power(&spec, f, &a), "spectrum", "power");
        nonneg_or_die(a, "spectrum", "power");
        if (units < 2u) /* standard errors rest on units, not trials */
            continue;
        ok_or_die(mcs_spectrum_mean_stderr(&spec, f, &a), "spectrum", "mean stderr");
        nonneg_or_die(a, "spectrum", "mean stderr");
        ok_or_die(mcs_spectrum_power_stderr(&spec, f, &a), "spectrum", "power stderr");
        nonneg_or_die(a, "spectrum", "power stderr");
    }
}

static void read_moment(void)
{
    if (mom.count == 0u)
        return;
    const size_t n = mom.n;
    for (size_t b = 0; b < n; ++b) {
        double a, c;
        ok_or_die(mcs_moment_bin_mean(&mom, b, &a), "moment", "bin mean");
        finite_or_die(a, "moment", "bin mean");
        ok_or_die(mcs_moment_mean(&mom, b, &a, &c), "moment", "mean");
        finite_or_die(a, "moment", "spectrum mean re");
        finite_or_die(c, "moment", "spectrum mean im");
        ok_or_die(mcs_moment_power(&mom, b, &a), "moment", "power");
        nonneg_or_die(a, "moment", "power");
        for (size_t c2 = 0; c2 < n; ++c2) {
            ok_or_die(mcs_moment_bin_second(&mom, b, c2, &a), "moment", "bin second");
            finite_or_die(a, "moment", "second");
        }
    }
    /* The loader refuses sums no trials give (issue 22 item 3), so the
     * covariance of a loaded object reads out as a built one's does: MCS_OK,
     * finite, with a diagonal (variances) >= 0. */
    ok_or_die(mcs_moment_covariance_matrix(&mom, n, mat_re, mat_im), "moment", "covariance");
    for (size_t j = 0; j < n * n; ++j) {
        finite_or_die(mat_re[j], "moment", "covariance re");
        finite_or_die(mat_im[j], "moment", "covariance im");
    }
    for (size_t j = 0; j < n; ++j)
        nonneg_or_die(mat_re[j * n + j], "moment", "variance (covariance diagonal)");
    ok_or_die(mcs_moment_cross_matrix(&mom, n, mat_re, mat_im), "moment", "cross");
    for (size_t j = 0; j < n * n; ++j) {
        finite_or_die(mat_re[j], "moment", "cross re");
        finite_or_die(mat_im[j], "moment", "cross im");
    }
    for (size_t j = 0; j < n; ++j)
        nonneg_or_die(mat_re[j * n + j], "moment", "power (cross diagonal)");
}

static void read_autocorr(void)
{
    if (ac.count == 0u)
        return;
    const size_t n = ac.n;
    ok_or_die(mcs_dft_init(&plan, n), "autocorr", "plan");
    ok_or_die(mcs_autocorr_mean(&ac, &plan, n, re, im), "autocorr", "mean");
    for (size_t f = 0; f < n; ++f) {
        finite_or_die(re[f], "autocorr", "mean re");
        finite_or_die(im[f], "autocorr", "mean im");
    }
    ok_or_die(mcs_autocorr_power(&ac, &plan, n, re), "autocorr", "power");
    for (size_t f = 0; f < n; ++f)
        nonneg_or_die(re[f], "autocorr", "power");
}

static void read_welford(void)
{
    double v;
    if (wf.count >= 1u) {
        ok_or_die(mcs_welford_mean(&wf, &v), "welford", "mean");
        finite_or_die(v, "welford", "mean");
    }
    if (wf.count >= 2u) {
        ok_or_die(mcs_welford_variance(&wf, &v), "welford", "variance");
        nonneg_or_die(v, "welford", "variance");
        ok_or_die(mcs_welford_stderr(&wf, &v), "welford", "stderr");
        nonneg_or_die(v, "welford", "stderr");
    }
    if (wf.count >= 4u) {
        ok_or_die(mcs_welford_variance_stderr(&wf, &v), "welford", "variance stderr");
        nonneg_or_die(v, "welford", "variance stderr");
    }
}

/* A read-out that succeeds must be finite (one that refuses is fine). v is a
 * pointer: the read-out writing it is another argument of the same call,
 * and C leaves the order in which arguments are evaluated open. */
static void finite_if_ok(mcs_status st, const double *v, const char *kind, const char *what)
{
    if (st == MCS_OK)
        finite_or_die(*v, kind, what);
}

static void read_pointset(void)
{
    for (long f = -(long)ps.freq_max; f <= (long)ps.freq_max; ++f) {
        double v = 0.0;
        finite_if_ok(mcs_pointset_power(&ps, f, &v), &v, "pointset", "power");
        finite_if_ok(mcs_pointset_power_stderr(&ps, f, &v), &v, "pointset", "power stderr");
    }
}

static void read_pointset2d(void)
{
    const long f = (long)ps2.freq_max;
    for (long fy = -f; fy <= f; ++fy)
        for (long fx = -f; fx <= f; ++fx) {
            double v = 0.0;
            finite_if_ok(mcs_pointset2d_power(&ps2, fx, fy, &v), &v, "pointset2d", "power");
            finite_if_ok(mcs_pointset2d_power_stderr(&ps2, fx, fy, &v), &v, "pointset2d",
                         "power stderr");
        }
    for (size_t r = 0; r <= ps2.freq_max; ++r) {
        double v = 0.0;
        finite_if_ok(mcs_pointset2d_radial(&ps2, r, &v), &v, "pointset2d", "radial");
        finite_if_ok(mcs_pointset2d_radial_stderr(&ps2, r, &v), &v, "pointset2d", "radial stderr");
        finite_if_ok(mcs_pointset2d_anisotropy(&ps2, r, &v), &v, "pointset2d", "anisotropy");
    }
}

static void read_spectrum2d(void)
{
    for (size_t k2 = 0; k2 < sp2.n_y; ++k2)
        for (size_t k1 = 0; k1 < sp2.n_x; ++k1) {
            double a = 0.0, b = 0.0;
            const mcs_status st = mcs_spectrum2d_mean(&sp2, k1, k2, &a, &b);
            finite_if_ok(st, &a, "spectrum2d", "mean re");
            finite_if_ok(st, &b, "spectrum2d", "mean im");
            finite_if_ok(mcs_spectrum2d_power(&sp2, k1, k2, &a), &a, "spectrum2d", "power");
            finite_if_ok(mcs_spectrum2d_power_stderr(&sp2, k1, k2, &a), &a, "spectrum2d",
                         "power stderr");
            finite_if_ok(mcs_spectrum2d_mean_stderr(&sp2, k1, k2, &a), &a, "spectrum2d",
                         "mean stderr");
        }
}

/* The measures: every read-out that succeeds is finite, and the spreads and
 * exact values >= 0. */
static void nonneg_if_ok(mcs_status st, const double *v, const char *kind, const char *what)
{
    if (st == MCS_OK)
        nonneg_or_die(*v, kind, what);
}

static void read_pcf(void)
{
    const size_t b = pcf.bins;
    const mcs_status st = mcs_pcf_read_all(&pcf, b, pcf_r, pcf_m, NULL);
    for (size_t i = 0; st == MCS_OK && i < b; ++i)
        nonneg_or_die(pcf_m[i], "pcf", "mean");
    if (mcs_pcf_read_all(&pcf, b, NULL, NULL, pcf_s) == MCS_OK)
        for (size_t i = 0; i < b; ++i)
            nonneg_or_die(pcf_s[i], "pcf", "stderr");
    for (size_t i = 0; i < b && i < 64u; ++i) {
        double v = 0.0;
        nonneg_if_ok(mcs_pcf_exact(&pcf, NULL, i, &v), &v, "pcf", "exact");
    }
    double v = 0.0;
    finite_if_ok(mcs_pcf_power(&pcf, 1.0, &v), &v, "pcf", "power");
}

static void read_integrate(void)
{
    double v = 0.0;
    nonneg_if_ok(mcs_integrate_mse(&integ, &v), &v, "integrate", "mse");
    nonneg_if_ok(mcs_integrate_mse_stderr(&integ, &v), &v, "integrate", "mse stderr");
    nonneg_if_ok(mcs_integrate_exact(&integ, &v), &v, "integrate", "exact");
}

static void read_discrepancy(void)
{
    for (int m = 0; m < MCS_DISCREPANCY_MEASURES; ++m) {
        double v = 0.0;
        const mcs_discrepancy_measure d = (mcs_discrepancy_measure)m;
        finite_if_ok(mcs_discrepancy_mean(&disc, d, &v), &v, "discrepancy", "mean");
        nonneg_if_ok(mcs_discrepancy_stderr(&disc, d, &v), &v, "discrepancy", "stderr");
        nonneg_if_ok(mcs_discrepancy_exact_random(&disc, d, &v), &v, "discrepancy", "exact");
    }
}

static void read_spacing(void)
{
    for (int m = 0; m < MCS_SPACING_STATISTICS; ++m) {
        double v = 0.0;
        const mcs_spacing_statistic d = (mcs_spacing_statistic)m;
        nonneg_if_ok(mcs_spacing_mean(&spc, d, &v), &v, "spacing", "mean");
        nonneg_if_ok(mcs_spacing_stderr(&spc, d, &v), &v, "spacing", "stderr");
    }
}

/* Each kind's load and save through one signature (a call through a cast
 * function pointer would be undefined, and UBSan's -fsanitize=function says so). */
#define IO_CALLS(name, type)                                                              \
    static mcs_status load_##name(void *obj, size_t len, const void *buf)                 \
    {                                                                                     \
        return mcs_io_load_##name((type *)obj, len, buf);                                 \
    }                                                                                     \
    static mcs_status save_##name(const void *obj, size_t cap, void *buf, size_t *len)    \
    {                                                                                     \
        return mcs_io_save_##name((const type *)obj, cap, buf, len);                      \
    }
IO_CALLS(spectrum, mcs_spectrum)
IO_CALLS(moment, mcs_moment)
IO_CALLS(autocorr, mcs_autocorr)
IO_CALLS(welford, mcs_welford)
IO_CALLS(integrate, mcs_integrate)
IO_CALLS(discrepancy, mcs_discrepancy)
IO_CALLS(spacing, mcs_spacing)

/* The objects over caller memory load over their own buffer; MCS_ERR_SPACE
 * must be what mcs_io_load_size says of the record. */
static mcs_status space_checked(mcs_status st, size_t len, const void *buf, size_t bytes)
{
    size_t need = 0u;
    if (st == MCS_ERR_SPACE && !(mcs_io_load_size(len, buf, 0u, &need) == MCS_OK && need > bytes))
        finding("load", "MCS_ERR_SPACE for a record whose object fits the buffer");
    return st;
}
static mcs_status load_pointset(void *obj, size_t len, const void *buf)
{
    fz_pointset *o = obj;
    return space_checked(mcs_io_load_pointset(&o->acc, 0u, o->mem, sizeof o->mem, len, buf), len,
                         buf, sizeof o->mem);
}
static mcs_status load_pointset2d(void *obj, size_t len, const void *buf)
{
    fz_pointset2d *o = obj;
    return space_checked(mcs_io_load_pointset2d(&o->acc, 0u, o->mem, sizeof o->mem, len, buf),
                         len, buf, sizeof o->mem);
}
static mcs_status load_spectrum2d(void *obj, size_t len, const void *buf)
{
    fz_spectrum2d *o = obj;
    return space_checked(mcs_io_load_spectrum2d(&o->acc, o->mem, sizeof o->mem, len, buf), len,
                         buf, sizeof o->mem);
}
static mcs_status load_pcf(void *obj, size_t len, const void *buf)
{
    fz_pcf *o = obj;
    return space_checked(mcs_io_load_pcf(&o->acc, o->mem, sizeof o->mem, len, buf), len, buf,
                         sizeof o->mem);
}
static mcs_status save_pcf(const void *obj, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save_pcf(obj, cap, buf, len);
}
static mcs_status save_pointset(const void *obj, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save_pointset(obj, cap, buf, len);
}
static mcs_status save_pointset2d(const void *obj, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save_pointset2d(obj, cap, buf, len);
}
static mcs_status save_spectrum2d(const void *obj, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save_spectrum2d(obj, cap, buf, len);
}

/* A kind: its destination and the pristine copy it is reset to, its load
 * and save, and the read-outs of a loaded object. */
/* A loaded object merged into itself is the object of twice its trials: the
 * merge may refuse only counts or sums past its limits (MCS_ERR_COUNT,
 * MCS_ERR_MAGNITUDE); when it
 * succeeds the result saves and reads out as a built object does (an
 * autocorr record with a compensation of 1e-300 on a zero sum once loaded,
 * merged and left an object save refused). */
static mcs_status merge_spectrum(void *obj) { return mcs_spectrum_merge(obj, obj); }
static mcs_status merge_moment(void *obj) { return mcs_moment_merge(obj, obj); }
static mcs_status merge_autocorr(void *obj) { return mcs_autocorr_merge(obj, obj); }
static mcs_status merge_welford(void *obj) { return mcs_welford_merge(obj, obj); }
static mcs_status merge_pcf(void *obj) { return mcs_pcf_merge(obj, obj); }
static mcs_status merge_integrate(void *obj) { return mcs_integrate_merge(obj, obj); }
static mcs_status merge_discrepancy(void *obj) { return mcs_discrepancy_merge(obj, obj); }
static mcs_status merge_spacing(void *obj) { return mcs_spacing_merge(obj, obj); }

typedef struct {
    const char *name;
    void *dst;
    const void *pristine;
    size_t size;
    mcs_status (*load)(void *obj, size_t len, const void *buf);
    mcs_status (*save)(const void *obj, size_t cap, void *buf, size_t *len);
    void (*read_outs)(void);
    mcs_status (*self_merge)(void *obj); /* NULL: not checked */
} kind_case;

#define KIND(name, obj, merge)                                                              \
    {#name, &obj, &obj##_pristine, sizeof obj, load_##name, save_##name, read_##name, merge}

static const kind_case kinds[] = {
    KIND(spectrum, spec, merge_spectrum), KIND(moment, mom, merge_moment),
    KIND(autocorr, ac, merge_autocorr),   KIND(welford, wf, merge_welford),
    KIND(pointset, ps_all, NULL),         KIND(pointset2d, ps2_all, NULL),
    KIND(spectrum2d, sp2_all, NULL),
    KIND(pcf, pcf_all, merge_pcf),        KIND(integrate, integ, merge_integrate),
    KIND(discrepancy, disc, merge_discrepancy), KIND(spacing, spc, merge_spacing),
};

/* The load into a destination holding another accumulator; when it
 * succeeds, the save that must give the input back, then the read-outs. */
static void check_kind(const kind_case *k, const uint8_t *data, size_t size, mcs_status peek_st)
{
    size_t len = 0u;
    memcpy(k->dst, k->pristine, k->size);
    const mcs_status st = k->load(k->dst, size, data);
    if (!loaded(k->name, st, peek_st, k->dst, k->pristine, k->size))
        return;
    ok_or_die(k->save(k->dst, sizeof saved, saved, &len), k->name, "save");
    if (prov.source != MCS_IO_SOURCE_NONE)
        ok_or_die(mcs_io_set_provenance(&prov, sizeof saved, saved, &len), k->name,
                  "set provenance");
    same_bytes(k->name, len, data, size);
    k->read_outs();
    if (k->self_merge == NULL)
        return;
    const mcs_status m = k->self_merge(k->dst);
    if (m == MCS_ERR_COUNT || m == MCS_ERR_MAGNITUDE) /* past a limit: refused, fine */
        return;
    ok_or_die(m, k->name, "self-merge of the loaded object");
    ok_or_die(k->save(k->dst, sizeof saved, saved, &len), k->name, "save after self-merge");
    k->read_outs();
}

static void check_all(const uint8_t *data, size_t size)
{
    mcs_io_info info;
    const mcs_status peek_st = mcs_io_peek(size, data, &info);
    if (peek_st == MCS_OK && info.size != size)
        finding("peek", "record size is not the input size");
    memset(&prov, 0, sizeof prov);
    if (mcs_io_peek_provenance(size, data, &prov) != peek_st)
        finding("peek", "peek and peek_provenance disagree");
    if (peek_st == MCS_OK && (prov.source != MCS_IO_SOURCE_NONE) != (info.version == 2u))
        finding("peek", "a provenance without version 2, or version 2 without one");
    for (size_t i = 0; i < sizeof kinds / sizeof kinds[0]; ++i)
        check_kind(&kinds[i], data, size, peek_st);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const uint8_t empty[1];
    static uint8_t fixed[1u << 16];
    setup_once();
    if (data == NULL) /* libFuzzer may pass NULL with size 0; the API wants a buffer */
        data = empty;
    check_all(data, size);
    if (size >= (size_t)MCS_IO_HEADER_BYTES + MCS_IO_CRC_BYTES && size <= sizeof fixed) {
        uint32_t crc = 0u;
        memcpy(fixed, data, size);
        ok_or_die(mcs_io_crc32(size - 4u, fixed, &crc), "harness", "crc32");
        for (size_t i = 0; i < 4u; ++i)
            fixed[size - 4u + i] = (uint8_t)(crc >> (8u * i));
        check_all(fixed, size);
    }
    return 0;
}
