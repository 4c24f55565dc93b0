/* The record kind of the pair correlation (docs/format.md, kind 8):
 * mcs_pcf, whose header is the caller's struct and whose arrays are in the
 * caller's buffer, loaded over a buffer as the point sets are (io_mem.c). */
#include "io_internal.h"
#include "measures/pcf_internal.h"

#include <math.h>
#include <string.h>

/* ---- pcf: shape [dim, estimator, B, radius, sigma] (the last two as the
 * bits of their doubles), payload k_min, k_max, then mean[B] and M2[B]: the
 * header is the caller's struct and the arrays are in its buffer, so the
 * walker's object is the header and the arrays are reached through its
 * pointers (IO_AS_POINTED) ---- */

enum { PC_BINS = 1 };

static double double_of(uint64_t bits)
{
    double v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

static uint64_t bits_of(double v)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    return bits;
}

/* The header a shape describes, without a buffer (for the checks). */
static mcs_pcf pcf_of_shape(const uint64_t *shape)
{
    mcs_pcf h;
    memset(&h, 0, sizeof h);
    h.dim = (size_t)shape[0];
    h.estimator = shape[1] == 1u ? MCS_PCF_GAUSSIAN : MCS_PCF_RDF;
    h.bins = (size_t)shape[2];
    h.radius = double_of(shape[3]);
    h.sigma = double_of(shape[4]);
    return h;
}

static int positive_finite(double x)
{
    return isfinite(x) && x > 0.0;
}

/* A shape mcs_pcf_init takes and leaves as it is: sigma exactly +0 for the
 * RDF (init stores 0), positive and finite for the kernel. */
static mcs_status sizes_pcf(const uint64_t *shape, size_t *size)
{
    if ((shape[0] != 1u && shape[0] != 2u) || shape[1] > 1u)
        return MCS_ERR_DOMAIN;
    if (shape[2] == 0u || shape[2] > (uint64_t)MCS_PCF_MAX_BINS)
        return MCS_ERR_N_RANGE;
    const double radius = double_of(shape[3]), sigma = double_of(shape[4]);
    if (!positive_finite(radius) || (shape[1] == 1u ? !positive_finite(sigma) : shape[4] != 0u))
        return MCS_ERR_DOMAIN;
    size[PC_BINS] = (size_t)shape[2];
    return MCS_OK;
}

static void shape_pcf(const void *obj, uint64_t *shape)
{
    const mcs_pcf *acc = (const mcs_pcf *)obj;
    shape[0] = acc->dim;
    shape[1] = acc->estimator == MCS_PCF_GAUSSIAN ? 1u : 0u;
    shape[2] = acc->bins;
    shape[3] = bits_of(acc->radius);
    shape[4] = bits_of(acc->sigma);
}

static mcs_status count_pcf(const void *obj, uint64_t *count)
{
    return mcs_pcf_count((const mcs_pcf *)obj, count);
}

/* The largest g one set of k points can give in bin b: every pair in the
 * bin (RDF), or every pair at the kernel's peak (Gaussian); it grows with
 * k, so the one of k_max bounds the mean over the sets. */
static double pcf_bound(const mcs_pcf *h, size_t k, size_t b)
{
    const double s = mcs_pcf_spacing_(h->dim, k), width = h->radius / (double)h->bins * s;
    if (h->estimator == MCS_PCF_RDF)
        return 1.0 / mcs_pcf_ring_(h->dim, (double)b * width, (double)(b + 1u) * width);
    const double r = ((double)b + 0.5) * width, sigma = h->sigma * s;
    const double peak = 1.0 / (sigma * sqrt(2.0 * 3.14159265358979323846));
    return peak / (h->dim == 1u ? 2.0 : 2.0 * 3.14159265358979323846 * r);
}

/* The invariants of pcf.h's state check (pcf.c, mcs_pcf_check_) on the
 * values, and what the adds imply: 2 <= k_min <= k_max with the cutoff at
 * k_min within 1/2 (mcs_pcf_add refuses other sets); the means >= 0 (the
 * rule) and at most pcf_bound at k_max. */
static int pcf_ok(const io_values *values, uint64_t count)
{
    const double k_min = mcs_io_value(values, 0u), k_max = mcs_io_value(values, 1u);
    if (count == 0u)
        return 1; /* every value 0: the rules */
    if (!(k_min >= 2.0 && k_min <= k_max))
        return 0;
    const mcs_pcf h = pcf_of_shape(values->shape);
    size_t side = 0u, need = 0u;
    if (mcs_pcf_set_check_(&h, (size_t)k_min, &side, &need) != MCS_OK ||
        mcs_pcf_set_check_(&h, (size_t)k_max, &side, &need) != MCS_OK)
        return 0;
    const double slack = 1.0 + 0x1p-20;
    for (size_t b = 0; b < h.bins; ++b)
        if (!(mcs_io_value(values, 2u + b) <= pcf_bound(&h, (size_t)k_max, b) * slack))
            return 0;
    return 1;
}

static const io_kind kind_pcf = {
    .kind = MCS_IO_KIND_PCF,
    .shape_len = 5u,
    .sizes = sizes_pcf,
    .count = count_pcf,
    .init = mcs_io_init_checked,
    .count_at = offsetof(mcs_pcf, count),
    .valid = pcf_ok,
    .nfields = 4u,
    .fields = {IO_SIZE(mcs_pcf, k_min, IO_RULE_NONNEG), IO_SIZE(mcs_pcf, k_max, IO_RULE_NONNEG),
               IO_POINTED(mcs_pcf, mean, PC_BINS, IO_RULE_NONNEG),
               IO_POINTED(mcs_pcf, m2, PC_BINS, IO_RULE_M2)},
    .shape_of = shape_pcf};

/* The table (its init the dry walk's: io_mem.c sets the other), and pcf.h's
 * size query and init for a shape. */
static void table_pcf(io_kind *k, const void *acc)
{
    (void)acc; /* the header's offsets are fixed: its arrays are reached by pointer */
    *k = kind_pcf;
}
static mcs_status size_pcf(const uint64_t *shape, unsigned flags, size_t *need)
{
    (void)flags;
    return mcs_pcf_size((size_t)shape[2], need);
}
static mcs_status init_pcf(void *acc, const uint64_t *shape, unsigned flags, void *mem,
                           size_t bytes)
{
    const mcs_pcf h = pcf_of_shape(shape);
    (void)flags;
    return mcs_pcf_init(acc, h.dim, h.estimator, h.bins, h.radius, h.sigma, mem, bytes);
}

static const io_mem_kind mem_pcf = {table_pcf,          NULL,     sizeof(mcs_pcf),
                                   offsetof(mcs_pcf, mem), offsetof(mcs_pcf, bytes),
                                   count_pcf,          size_pcf, init_pcf};

mcs_status mcs_io_save_pcf(const mcs_pcf *acc, size_t cap, void *buf, size_t *len)
{
    return mcs_io_save_mem(&mem_pcf, acc, cap, buf, len);
}

mcs_status mcs_io_load_pcf(mcs_pcf *acc, void *mem, size_t bytes, size_t len, const void *buf)
{
    const io_mem_arg arg = {mem, bytes, 0u};
    return mcs_io_load_mem(&mem_pcf, acc, &arg, len, buf);
}

mcs_status mcs_io_pcf_need(const uint64_t *shape, size_t *need)
{
    size_t size[IO_MAX_DIMS];
    mcs_status st = sizes_pcf(shape, size);
    return st != MCS_OK ? st : mcs_pcf_size(size[PC_BINS], need);
}
