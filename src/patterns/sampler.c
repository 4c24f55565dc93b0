#include "mcspec/sampler.h"
#include "random/rng_inline.h"
#include "sampler_internal.h"

#include <stddef.h>
#include <stdint.h>

/* Sobol dimension 2 (primitive polynomial x + 1, m_1 = 1): direction number
 * v_b = v_{b-1} xor (v_{b-1} >> 1) from v_0 = 2^31, i.e. the rows of Pascal's
 * triangle mod 2. Dimension 1 has v_b = 2^(31-b): the van der Corput sequence.
 * (Row 2 of Joe and Kuo's table, mcs_sampler_sobol_v_, holds the same
 * numbers: a test checks it.) */
static const uint32_t sobol_dim2[32] = {
    0x80000000u, 0xc0000000u, 0xa0000000u, 0xf0000000u, 0x88000000u, 0xcc000000u,
    0xaa000000u, 0xff000000u, 0x80800000u, 0xc0c00000u, 0xa0a00000u, 0xf0f00000u,
    0x88880000u, 0xcccc0000u, 0xaaaa0000u, 0xffff0000u, 0x80008000u, 0xc000c000u,
    0xa000a000u, 0xf000f000u, 0x88008800u, 0xcc00cc00u, 0xaa00aa00u, 0xff00ff00u,
    0x80808080u, 0xc0c0c0c0u, 0xa0a0a0a0u, 0xf0f0f0f0u, 0x88888888u, 0xccccccccu,
    0xaaaaaaaau, 0xffffffffu};

#define TWO_M32 MCS_SMP_TWO_M32
#define KRONECKER_1D MCS_SMP_KRONECKER_1D
#define KRONECKER_R2_X MCS_SMP_KRONECKER_R2_X
#define KRONECKER_R2_Y MCS_SMP_KRONECKER_R2_Y
#define reverse_bits mcs_smp_reverse_bits_
#define owen_to_double mcs_smp_owen_to_double_
#define radical_inverse3 mcs_smp_radical_inverse3_
#define fraction64 mcs_smp_fraction64_
#define rotate mcs_smp_rotate_

const char *mcs_sampler_kind_str(mcs_sampler_kind kind)
{
    switch (kind) {
    case MCS_SAMPLER_VAN_DER_CORPUT: return "van-der-corput";
    case MCS_SAMPLER_HALTON: return "halton";
    case MCS_SAMPLER_HAMMERSLEY: return "hammersley";
    case MCS_SAMPLER_SOBOL: return "sobol-owen";
    case MCS_SAMPLER_KRONECKER: return "kronecker";
    case MCS_SAMPLER_SOBOL_ND: return "sobol-owen-nd";
    case MCS_SAMPLER_HALTON_PERMUTED: return "halton-permuted";
    case MCS_SAMPLER_PADDED: return "padded";
    case MCS_SAMPLER_HALTON_OWEN: return "halton-owen";
    case MCS_SAMPLER_LATTICE: return "lattice";
    }
    return "unknown";
}

int mcs_sampler_has_dim(mcs_sampler_kind kind, size_t dim)
{
    switch (kind) {
    case MCS_SAMPLER_VAN_DER_CORPUT: return dim == 1u;
    case MCS_SAMPLER_HALTON:
    case MCS_SAMPLER_HAMMERSLEY: return dim == 2u;
    case MCS_SAMPLER_SOBOL:
    case MCS_SAMPLER_KRONECKER: return dim == 1u || dim == 2u;
    case MCS_SAMPLER_SOBOL_ND:
    case MCS_SAMPLER_HALTON_PERMUTED:
    case MCS_SAMPLER_HALTON_OWEN:
    case MCS_SAMPLER_LATTICE: return dim >= 1u && dim <= MCS_SAMPLER_MAX_DIM;
    case MCS_SAMPLER_PADDED: return dim >= 2u && dim <= MCS_SAMPLER_MAX_DIM;
    }
    return 0;
}

int mcs_sampler_base_is_exact(mcs_sampler_kind kind)
{
    switch (kind) {
    case MCS_SAMPLER_VAN_DER_CORPUT:
    case MCS_SAMPLER_HALTON:
    case MCS_SAMPLER_HAMMERSLEY:
    case MCS_SAMPLER_KRONECKER:
    case MCS_SAMPLER_LATTICE: return 1;
    default: return 0;
    }
}

/* K in 1..2^32; a padded sampler's permutations take K below 2^32. */
static int k_in_range_for(mcs_sampler_kind kind, size_t k)
{
    uint64_t top = kind == MCS_SAMPLER_PADDED ? (uint64_t)UINT32_MAX - 1u : (uint64_t)UINT32_MAX;
    return k >= 1u && (uint64_t)k - 1u <= top;
}

static int k_in_range(size_t k)
{
    return k_in_range_for(MCS_SAMPLER_VAN_DER_CORPUT, k);
}

static void set(mcs_sampler *s, mcs_sampler_kind kind, uint32_t pad, uint32_t g, size_t dim,
                size_t k)
{
    s->kind = kind;
    s->pad = pad;
    s->generator = g;
    s->dim = dim;
    s->k = k;
}

mcs_status mcs_sampler_init(mcs_sampler *s, mcs_sampler_kind kind, size_t dim, size_t k)
{
    if (s == NULL)
        return MCS_ERR_NULL;
    if (!mcs_sampler_has_dim(kind, dim))
        return MCS_ERR_KIND;
    if (!k_in_range_for(kind, k))
        return MCS_ERR_K_RANGE;
    uint32_t pad = kind == MCS_SAMPLER_PADDED ? (uint32_t)MCS_SAMPLER_SOBOL : 0u;
    uint32_t g = kind == MCS_SAMPLER_LATTICE ? mcs_sampler_lattice_generator(k, dim) : 0u;
    set(s, kind, pad, g, dim, k);
    return MCS_OK;
}

mcs_status mcs_sampler_init_padded(mcs_sampler *s, mcs_sampler_kind pad, size_t dim, size_t k)
{
    if (s == NULL)
        return MCS_ERR_NULL;
    if (!mcs_smp_is_pad_kind_((uint32_t)pad) || !mcs_sampler_has_dim(MCS_SAMPLER_PADDED, dim))
        return MCS_ERR_KIND;
    if (!k_in_range_for(MCS_SAMPLER_PADDED, k))
        return MCS_ERR_K_RANGE;
    set(s, MCS_SAMPLER_PADDED, (uint32_t)pad, 0u, dim, k);
    return MCS_OK;
}

mcs_status mcs_sampler_init_lattice(mcs_sampler *s, size_t dim, size_t k, uint32_t g)
{
    if (s == NULL)
        return MCS_ERR_NULL;
    if (!mcs_sampler_has_dim(MCS_SAMPLER_LATTICE, dim))
        return MCS_ERR_KIND;
    if (!k_in_range(k))
        return MCS_ERR_K_RANGE;
    if (!mcs_sampler_generator_ok_(k, g))
        return MCS_ERR_MISMATCH;
    set(s, MCS_SAMPLER_LATTICE, 0u, g, dim, k);
    return MCS_OK;
}

/* What init leaves: a kind defined in dim, K in range, the kind's own
 * fields set (and the others 0). */
static int is_valid(const mcs_sampler *s)
{
    if (!mcs_sampler_has_dim(s->kind, s->dim) || !k_in_range_for(s->kind, s->k))
        return 0;
    if (s->kind == MCS_SAMPLER_PADDED)
        return mcs_smp_is_pad_kind_(s->pad) && s->generator == 0u;
    if (s->kind == MCS_SAMPLER_LATTICE)
        return s->pad == 0u && mcs_sampler_generator_ok_(s->k, s->generator);
    return s->pad == 0u && s->generator == 0u;
}

/* The checks of a trial of k points into points: NULL, UNINIT (also for a
 * never-seeded rng, whose zeros would give every trial the same set; 1 when
 * none is drawn from), MISMATCH. */
static mcs_status check(const mcs_sampler *s, int rng_seeded, size_t k, const double *points)
{
    if (s == NULL || points == NULL)
        return MCS_ERR_NULL;
    if (!is_valid(s) || !rng_seeded)
        return MCS_ERR_UNINIT;
    if (k != s->k)
        return MCS_ERR_MISMATCH;
    return MCS_OK;
}

uint32_t mcs_sampler_owen_scramble(uint32_t x, uint32_t seed)
{
    return mcs_smp_owen_scramble_(x, seed);
}

static uint32_t sobol_bits(uint32_t j, size_t axis)
{
    if (axis == 0u)
        return reverse_bits(j);
    uint32_t v = 0u;
    for (unsigned b = 0; j != 0u; ++b, j >>= 1)
        if (j & 1u)
            v ^= sobol_dim2[b];
    return v;
}

/* Coordinate `axis` of unrandomised point j of a rotated kind. */
static double base_coordinate(const mcs_sampler *s, uint32_t j, size_t axis)
{
    switch (s->kind) {
    case MCS_SAMPLER_HALTON:
        return axis == 0u ? (double)reverse_bits(j) * TWO_M32 : radical_inverse3(j);
    case MCS_SAMPLER_HAMMERSLEY:
        return axis == 0u ? (double)j / (double)s->k : (double)reverse_bits(j) * TWO_M32;
    case MCS_SAMPLER_SOBOL:
        return (double)sobol_bits(j, axis) * TWO_M32;
    default: /* van der Corput */
        return (double)reverse_bits(j) * TWO_M32;
    }
}

static uint64_t kronecker_step(size_t dim, size_t axis)
{
    if (dim == 1u)
        return KRONECKER_1D;
    return axis == 0u ? KRONECKER_R2_X : KRONECKER_R2_Y;
}

mcs_status mcs_sampler_base_points(const mcs_sampler *s, size_t k, double *points)
{
    mcs_status st = check(s, 1, k, points);
    if (st != MCS_OK)
        return st;
    if (s->kind == MCS_SAMPLER_PADDED) {
        mcs_sampler_base_padded_(s, points);
        return MCS_OK;
    }
    if (mcs_smp_kind_is_nd_(s->kind)) {
        mcs_sampler_base_nd_(s, points);
        return MCS_OK;
    }
    const size_t dim = s->dim;
    for (size_t j = 0; j < k; ++j)
        for (size_t a = 0; a < dim; ++a)
            points[dim * j + a] =
                s->kind == MCS_SAMPLER_KRONECKER
                    ? fraction64((uint64_t)j * kronecker_step(dim, a))
                    : base_coordinate(s, (uint32_t)j, a);
    return MCS_OK;
}

mcs_status mcs_sampler_draw(const mcs_sampler *s, mcs_rng *rng, size_t k, double *points)
{
    mcs_status st = rng == NULL ? MCS_ERR_NULL : check(s, mcs_rng_is_seeded_(rng), k, points);
    if (st != MCS_OK)
        return st;
    if (s->kind == MCS_SAMPLER_PADDED) {
        mcs_sampler_draw_padded_(s, rng, points);
        return MCS_OK;
    }
    if (mcs_smp_kind_is_nd_(s->kind)) {
        mcs_sampler_draw_nd_(s, rng, points);
        return MCS_OK;
    }
    const size_t dim = s->dim;
    for (size_t a = 0; a < dim; ++a) {
        if (s->kind == MCS_SAMPLER_SOBOL) {
            const uint64_t key = mcs_smp_draw_key_(rng);
            for (size_t j = 0; j < k; ++j)
                points[dim * j + a] = owen_to_double(sobol_bits((uint32_t)j, a), key);
        } else if (s->kind == MCS_SAMPLER_KRONECKER) {
            /* A 64-bit fixed-point shift keeps j alpha + shift exact mod 1. */
            uint64_t shift = (uint64_t)mcs_rng_next_(rng) << 32;
            shift |= mcs_rng_next_(rng);
            uint64_t step = kronecker_step(dim, a);
            for (size_t j = 0; j < k; ++j)
                points[dim * j + a] = fraction64((uint64_t)j * step + shift);
        } else {
            double shift = mcs_rng_double_(rng);
            for (size_t j = 0; j < k; ++j)
                points[dim * j + a] = rotate(base_coordinate(s, (uint32_t)j, a), shift);
        }
    }
    return MCS_OK;
}
