/* The binned 1D accumulator kinds of the record format (docs/format.md):
 * spectrum, moment, autocorr and welford (the point-set and 2D ones are in
 * io_points.c). For each, its layout (payload length and value rules for a
 * shape), the emit function that lists its values in payload order, and the
 * load that decodes them in the same order into a freshly initialised object.
 *
 * Adding a kind: a new mcs_io_kind number, a layout, an emit, a load and the
 * two public wrappers, as below; the framing, checksum and value checks of
 * io.c need no change, nor does the version. */
#include "io_internal.h"

#include <math.h>
#include <string.h>

/* One shape word N, 1 <= N <= max_n. */
static mcs_status layout_n(uint32_t kind, uint64_t n, uint64_t max_n, io_layout *lay)
{
    if (n == 0u || n > max_n)
        return MCS_ERR_N_RANGE;
    mcs_io_layout_start(lay, kind, 1u, &n);
    return MCS_OK;
}

/* ---- spectrum: counts, five half spectra k = 0..N/2, the open PAIR batch ----
 *
 * Payload: units, open_count, open_work (integers exact in a double: each is
 * at most the count, 2^53, or a sum of K (K + 1) / 2), then mean_re, mean_im,
 * m2_s, mean_pow, m2_pow over k = 0..N/2, then the open batch's open_sum[N]
 * and open_pairs[1 .. 2N) (entry 0 stands for a difference of -N, which no
 * pair has). With the open batch a loaded spectrum is the saved one: the same
 * read-outs, merges and later adds, to the bit. */

enum { SP_UNITS, SP_OPEN, SP_WORK, SP_SCALARS };

static mcs_status layout_spectrum(const uint64_t *shape, io_layout *lay)
{
    mcs_status st = layout_n(MCS_IO_KIND_SPECTRUM, shape[0], MCS_MAX_N, lay);
    if (st != MCS_OK)
        return st;
    const size_t n = (size_t)shape[0], h1 = n / 2u + 1u;
    mcs_io_add_range(lay, SP_SCALARS, IO_RULE_NONNEG);           /* units, open_count, open_work */
    mcs_io_add_range(lay, 2u * h1, 0u);                          /* mean_re, mean_im */
    mcs_io_add_range(lay, h1, IO_RULE_NONNEG | IO_RULE_SPREAD);  /* m2_s */
    mcs_io_add_range(lay, h1, IO_RULE_NONNEG);                   /* mean_pow */
    mcs_io_add_range(lay, h1, IO_RULE_NONNEG | IO_RULE_SPREAD);  /* m2_pow */
    mcs_io_add_range(lay, 3u * n - 1u, IO_RULE_NONNEG);          /* open_sum, open_pairs */
    return MCS_OK;
}

/* Payload value i of a spectrum, read from the object or from a payload. */
typedef double (*sp_get_fn)(const void *src, size_t n, size_t i);

static double sp_get_acc(const void *src, size_t n, size_t i)
{
    const mcs_spectrum *acc = (const mcs_spectrum *)src;
    const size_t h1 = n / 2u + 1u;
    if (i < SP_SCALARS)
        return i == SP_UNITS ? (double)acc->units
               : i == SP_OPEN ? (double)acc->open_count : acc->open_work;
    i -= SP_SCALARS;
    const double *const half[5] = {acc->mean_re, acc->mean_im, acc->m2_s, acc->mean_pow,
                                   acc->m2_pow};
    if (i < 5u * h1)
        return half[i / h1][i % h1];
    i -= 5u * h1;
    return i < n ? acc->open_sum[i] : acc->open_pairs[1u + i - n];
}

static double sp_get_payload(const void *src, size_t n, size_t i)
{
    (void)n;
    return mcs_io_get_f64((const uint8_t *)src, i);
}

static int sp_zero(sp_get_fn get, const void *src, size_t n, size_t first, size_t len)
{
    for (size_t i = first; i < first + len; ++i)
        if (get(src, n, i) != 0.0)
            return 0;
    return 1;
}

/* The spectrum's own invariants (spectrum.c, spectrum_check), beyond the
 * rules every kind shares: whole unit and open counts with
 * units <= count - open_count and units = 0 exactly when every trial is in
 * the open batch; an open batch's work at least one pair per trial, and no
 * open batch leaving its work and sums 0; the closed statistics 0 with no
 * unit and the M2s 0 with fewer than 2 (a spread needs 2 units, not 2
 * trials). Values are finite and >= 0 here (checked first). */
static int spectrum_ok(sp_get_fn get, const void *src, size_t n, uint64_t count)
{
    const size_t h1 = n / 2u + 1u;
    const double units = get(src, n, SP_UNITS), open = get(src, n, SP_OPEN);
    const double work = get(src, n, SP_WORK);
    if (units != floor(units) || open != floor(open) || open > (double)count)
        return 0;
    const double closed = (double)count - open; /* exact: both at most 2^53 */
    if (units > closed || (units == 0.0) != (closed == 0.0))
        return 0;
    if (open == 0.0 ? (work != 0.0 || !sp_zero(get, src, n, SP_SCALARS + 5u * h1, 3u * n - 1u))
                    : work < open)
        return 0;
    if (units == 0.0 && !sp_zero(get, src, n, SP_SCALARS, 5u * h1))
        return 0;
    return units >= 2.0 || (sp_zero(get, src, n, SP_SCALARS + 2u * h1, h1) &&
                            sp_zero(get, src, n, SP_SCALARS + 4u * h1, h1));
}

static void emit_spectrum(const void *obj, io_sink *sink)
{
    const mcs_spectrum *acc = (const mcs_spectrum *)obj;
    const size_t n = acc->n, h1 = n / 2u + 1u;
    mcs_io_sink_put(sink, (double)acc->units);
    mcs_io_sink_put(sink, (double)acc->open_count);
    mcs_io_sink_put(sink, acc->open_work);
    mcs_io_put_array(sink, acc->mean_re, h1);
    mcs_io_put_array(sink, acc->mean_im, h1);
    mcs_io_put_array(sink, acc->m2_s, h1);
    mcs_io_put_array(sink, acc->mean_pow, h1);
    mcs_io_put_array(sink, acc->m2_pow, h1);
    mcs_io_put_array(sink, acc->open_sum, n);
    mcs_io_put_array(sink, acc->open_pairs + 1, 2u * n - 1u);
}

mcs_status mcs_io_save_spectrum(const mcs_spectrum *acc, size_t cap, void *buf, size_t *len)
{
    uint64_t count;
    io_layout lay;
    size_t size;
    if (acc == NULL || len == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_spectrum_count(acc, &count); /* MCS_ERR_UNINIT */
    if (st != MCS_OK)
        return st;
    const uint64_t n = acc->n;
    (void)layout_spectrum(&n, &lay); /* cannot fail: acc->n is in range */
    const io_source src = {acc, emit_spectrum, count};
    st = mcs_io_save_record(&lay, &src, 0u, NULL, &size); /* the shared rules first */
    if (st != MCS_OK)
        return st;
    if (!spectrum_ok(sp_get_acc, acc, acc->n, count))
        return MCS_ERR_INVARIANT;
    return mcs_io_save_record(&lay, &src, cap, buf, len);
}

static const io_kind kind_spectrum = {MCS_IO_KIND_SPECTRUM, 1u, layout_spectrum};

mcs_status mcs_io_load_spectrum(mcs_spectrum *acc, size_t len, const void *buf)
{
    io_record rec;
    if (acc == NULL || buf == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_io_load_check(&kind_spectrum, len, buf, &rec);
    if (st != MCS_OK)
        return st;
    const uint8_t *pl = rec.payload;
    const size_t n = (size_t)rec.lay.shape[0], h1 = n / 2u + 1u;
    if (!spectrum_ok(sp_get_payload, pl, n, rec.count))
        return MCS_ERR_INVARIANT;
    st = mcs_spectrum_init(acc, n); /* leaves acc as it was on error */
    if (st != MCS_OK)
        return st;
    acc->count = rec.count;
    acc->units = (uint64_t)mcs_io_get_f64(pl, SP_UNITS);
    acc->open_count = (uint64_t)mcs_io_get_f64(pl, SP_OPEN);
    acc->open_work = mcs_io_get_f64(pl, SP_WORK);
    double *const half[5] = {acc->mean_re, acc->mean_im, acc->m2_s, acc->mean_pow, acc->m2_pow};
    for (size_t a = 0; a < 5u; ++a)
        mcs_io_get_array(half[a], pl, SP_SCALARS + a * h1, h1);
    mcs_io_get_array(acc->open_sum, pl, SP_SCALARS + 5u * h1, n);
    mcs_io_get_array(acc->open_pairs + 1, pl, SP_SCALARS + 5u * h1 + n, 2u * n - 1u);
    return MCS_OK;
}

/* ---- moment: shift[N], then sum_d[N], lo_d[N] and the upper triangles of
 * sum_dd and lo_dd row by row (moment.h: sums of d = s - c, c the first
 * trial, with their Kahan compensations, so a loaded object is the saved one
 * and merges bit for bit like it) ---- */

static mcs_status layout_moment(const uint64_t *shape, io_layout *lay)
{
    mcs_status st = layout_n(MCS_IO_KIND_MOMENT, shape[0], MCS_MAX_COV_N, lay);
    if (st != MCS_OK)
        return st;
    const size_t n = (size_t)shape[0];
    /* c is a trial's s (weights >= 0); the sums of d are 0 before 2 trials. */
    mcs_io_add_range(lay, n, IO_RULE_NONNEG);
    mcs_io_add_range(lay, 2u * n + n * (n + 1u), IO_RULE_SPREAD);
    return MCS_OK;
}

/* The upper triangle of an N x N array, row by row. */
static void put_upper(io_sink *sink, const double *a, size_t n)
{
    for (size_t m = 0; m < n; ++m)
        mcs_io_put_array(sink, a + m * n + m, n - m);
}

/* Back from payload[at ..), mirrored into the lower triangle (both are
 * stored, exactly symmetric); returns the index after it. */
static size_t get_upper(double *a, const uint8_t *pl, size_t at, size_t n)
{
    for (size_t m = 0; m < n; ++m) {
        mcs_io_get_array(a + m * n + m, pl, at, n - m);
        for (size_t c = m + 1u; c < n; ++c)
            a[c * n + m] = a[m * n + c];
        at += n - m;
    }
    return at;
}

static void emit_moment(const void *obj, io_sink *sink)
{
    const mcs_moment *acc = (const mcs_moment *)obj;
    const size_t n = acc->n;
    mcs_io_put_array(sink, acc->shift, n);
    mcs_io_put_array(sink, acc->sum_d, n);
    mcs_io_put_array(sink, acc->lo_d, n);
    put_upper(sink, acc->sum_dd, n);
    put_upper(sink, acc->lo_dd, n);
}

mcs_status mcs_io_save_moment(const mcs_moment *acc, size_t cap, void *buf, size_t *len)
{
    uint64_t count;
    io_layout lay;
    if (acc == NULL || len == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_moment_count(acc, &count);
    if (st != MCS_OK)
        return st;
    const uint64_t n = acc->n;
    (void)layout_moment(&n, &lay);
    const io_source src = {acc, emit_moment, count};
    return mcs_io_save_record(&lay, &src, cap, buf, len);
}

static const io_kind kind_moment = {MCS_IO_KIND_MOMENT, 1u, layout_moment};

mcs_status mcs_io_load_moment(mcs_moment *acc, size_t len, const void *buf)
{
    io_record rec;
    if (acc == NULL || buf == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_io_load_check(&kind_moment, len, buf, &rec);
    if (st != MCS_OK)
        return st;
    const uint8_t *pl = rec.payload;
    const size_t n = (size_t)rec.lay.shape[0];
    st = mcs_moment_init(acc, n);
    if (st != MCS_OK)
        return st;
    mcs_io_get_array(acc->shift, pl, 0u, n);
    mcs_io_get_array(acc->sum_d, pl, n, n);
    mcs_io_get_array(acc->lo_d, pl, 2u * n, n);
    (void)get_upper(acc->lo_dd, pl, get_upper(acc->sum_dd, pl, 3u * n, n), n);
    acc->count = rec.count;
    return MCS_OK;
}

/* ---- autocorr: sum_s[N] and sum_dc, then lo_s[N], sum_lag and lo_lag for
 * the lags 0..N/2, and lo_dc (autocorr.h: sum_lag holds centred lag sums
 * for trials of K >= N, which may be negative; the lo_ are the Kahan
 * compensations, so a loaded object is the saved one) ---- */

static mcs_status layout_autocorr(const uint64_t *shape, io_layout *lay)
{
    mcs_status st = layout_n(MCS_IO_KIND_AUTOCORR, shape[0], MCS_MAX_N, lay);
    if (st != MCS_OK)
        return st;
    const size_t n = (size_t)shape[0], h1 = n / 2u + 1u;
    mcs_io_add_range(lay, n + 1u, IO_RULE_NONNEG);
    mcs_io_add_range(lay, n + 2u * h1 + 1u, 0u);
    return MCS_OK;
}

static void emit_autocorr(const void *obj, io_sink *sink)
{
    const mcs_autocorr *acc = (const mcs_autocorr *)obj;
    const size_t n = acc->n, h1 = n / 2u + 1u;
    mcs_io_put_array(sink, acc->sum_s, n);
    mcs_io_sink_put(sink, acc->sum_dc);
    mcs_io_put_array(sink, acc->lo_s, n);
    mcs_io_put_array(sink, acc->sum_lag, h1);
    mcs_io_put_array(sink, acc->lo_lag, h1);
    mcs_io_sink_put(sink, acc->lo_dc);
}

mcs_status mcs_io_save_autocorr(const mcs_autocorr *acc, size_t cap, void *buf, size_t *len)
{
    uint64_t count;
    io_layout lay;
    if (acc == NULL || len == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_autocorr_count(acc, &count);
    if (st != MCS_OK)
        return st;
    const uint64_t n = acc->n;
    (void)layout_autocorr(&n, &lay);
    const io_source src = {acc, emit_autocorr, count};
    return mcs_io_save_record(&lay, &src, cap, buf, len);
}

static const io_kind kind_autocorr = {MCS_IO_KIND_AUTOCORR, 1u, layout_autocorr};

mcs_status mcs_io_load_autocorr(mcs_autocorr *acc, size_t len, const void *buf)
{
    io_record rec;
    if (acc == NULL || buf == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_io_load_check(&kind_autocorr, len, buf, &rec);
    if (st != MCS_OK)
        return st;
    const uint8_t *pl = rec.payload;
    const size_t n = (size_t)rec.lay.shape[0];
    st = mcs_autocorr_init(acc, n);
    if (st != MCS_OK)
        return st;
    const size_t h1 = n / 2u + 1u;
    mcs_io_get_array(acc->sum_s, pl, 0u, n);
    acc->sum_dc = mcs_io_get_f64(pl, n);
    mcs_io_get_array(acc->lo_s, pl, n + 1u, n);
    mcs_io_get_array(acc->sum_lag, pl, 2u * n + 1u, h1);
    mcs_io_get_array(acc->lo_lag, pl, 2u * n + 1u + h1, h1);
    acc->lo_dc = mcs_io_get_f64(pl, 2u * n + 1u + 2u * h1);
    acc->count = rec.count;
    return MCS_OK;
}

/* ---- welford: mean, m2, m3, m4; no shape ---- */

static mcs_status layout_welford(const uint64_t *shape, io_layout *lay)
{
    mcs_io_layout_start(lay, MCS_IO_KIND_WELFORD, 0u, shape);
    mcs_io_add_range(lay, 1u, 0u);                               /* mean */
    mcs_io_add_range(lay, 1u, IO_RULE_NONNEG | IO_RULE_SPREAD);  /* m2 */
    mcs_io_add_range(lay, 1u, IO_RULE_SPREAD);                   /* m3 */
    mcs_io_add_range(lay, 1u, IO_RULE_NONNEG | IO_RULE_SPREAD);  /* m4 */
    return MCS_OK;
}

static void emit_welford(const void *obj, io_sink *sink)
{
    const mcs_welford *acc = (const mcs_welford *)obj;
    mcs_io_sink_put(sink, acc->mean);
    mcs_io_sink_put(sink, acc->m2);
    mcs_io_sink_put(sink, acc->m3);
    mcs_io_sink_put(sink, acc->m4);
}

mcs_status mcs_io_save_welford(const mcs_welford *acc, size_t cap, void *buf, size_t *len)
{
    io_layout lay;
    if (acc == NULL || len == NULL)
        return MCS_ERR_NULL;
    (void)layout_welford(NULL, &lay);
    const io_source src = {acc, emit_welford, acc->count};
    return mcs_io_save_record(&lay, &src, cap, buf, len);
}

static const io_kind kind_welford = {MCS_IO_KIND_WELFORD, 0u, layout_welford};

mcs_status mcs_io_load_welford(mcs_welford *acc, size_t len, const void *buf)
{
    io_record rec;
    if (acc == NULL || buf == NULL)
        return MCS_ERR_NULL;
    mcs_status st = mcs_io_load_check(&kind_welford, len, buf, &rec);
    if (st != MCS_OK)
        return st;
    const uint8_t *pl = rec.payload;
    acc->count = rec.count;
    acc->mean = mcs_io_get_f64(pl, 0u);
    acc->m2 = mcs_io_get_f64(pl, 1u);
    acc->m3 = mcs_io_get_f64(pl, 2u);
    acc->m4 = mcs_io_get_f64(pl, 3u);
    return MCS_OK;
}
