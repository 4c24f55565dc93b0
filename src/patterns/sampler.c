#include "mcspec/sampler.h"
#include "random/rng_inline.h"

#include <stddef.h>
#include <stdint.h>

/* 2^-32 and 2^-53: a 32-bit binary fraction and a 53-bit one to double. */
#define TWO_M32 (1.0 / 4294967296.0)
#define TWO_M53 (1.0 / 9007199254740992.0)

/* Sobol dimension 2 (primitive polynomial x + 1, m_1 = 1): direction number
 * v_b = v_{b-1} xor (v_{b-1} >> 1) from v_0 = 2^31, i.e. the rows of Pascal's
 * triangle mod 2. Dimension 1 has v_b = 2^(31-b): the van der Corput sequence. */
static const uint32_t sobol_dim2[32] = {
    0x80000000u, 0xc0000000u, 0xa0000000u, 0xf0000000u, 0x88000000u, 0xcc000000u,
    0xaa000000u, 0xff000000u, 0x80800000u, 0xc0c00000u, 0xa0a00000u, 0xf0f00000u,
    0x88880000u, 0xcccc0000u, 0xaaaa0000u, 0xffff0000u, 0x80008000u, 0xc000c000u,
    0xa000a000u, 0xf000f000u, 0x88008800u, 0xcc00cc00u, 0xaa00aa00u, 0xff00ff00u,
    0x80808080u, 0xc0c0c0c0u, 0xa0a0a0a0u, 0xf0f0f0f0u, 0x88888888u, 0xccccccccu,
    0xaaaaaaaau, 0xffffffffu};

/* Kronecker steps as 64-bit fixed-point fractions, round(alpha 2^64): j alpha
 * mod 1 is then exact integer arithmetic mod 2^64 for every j (a double
 * product j * alpha would lose log2(j) bits of the fraction).
 * 1D: 1/golden = 0.6180339887...; 2D (R2, Roberts 2018): 1/g and 1/g^2 with g
 * the plastic number, g^3 = g + 1: 0.7548776662..., 0.5698402909... */
#define KRONECKER_1D UINT64_C(0x9e3779b97f4a7c16)
#define KRONECKER_R2_X UINT64_C(0xc13fa9a902a6328f)
#define KRONECKER_R2_Y UINT64_C(0x91e10da5c79e7b1d)

const char *mcs_sampler_kind_str(mcs_sampler_kind kind)
{
    switch (kind) {
    case MCS_SAMPLER_VAN_DER_CORPUT: return "van-der-corput";
    case MCS_SAMPLER_HALTON: return "halton";
    case MCS_SAMPLER_HAMMERSLEY: return "hammersley";
    case MCS_SAMPLER_SOBOL: return "sobol-owen";
    case MCS_SAMPLER_KRONECKER: return "kronecker";
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
    }
    return 0;
}

static int k_in_range(size_t k)
{
    return k >= 1u && (uint64_t)k - 1u <= (uint64_t)UINT32_MAX;
}

mcs_status mcs_sampler_init(mcs_sampler *s, mcs_sampler_kind kind, size_t dim, size_t k)
{
    if (s == NULL)
        return MCS_ERR_NULL;
    if (!mcs_sampler_has_dim(kind, dim))
        return MCS_ERR_KIND;
    if (!k_in_range(k))
        return MCS_ERR_K_RANGE;
    s->kind = kind;
    s->dim = dim;
    s->k = k;
    return MCS_OK;
}

/* The checks of a trial of k points into points: NULL, UNINIT (also for a
 * never-seeded rng, whose zeros would give every trial the same set; 1 when
 * none is drawn from), MISMATCH. */
static mcs_status check(const mcs_sampler *s, int rng_seeded, size_t k, const double *points)
{
    if (s == NULL || points == NULL)
        return MCS_ERR_NULL;
    if (!mcs_sampler_has_dim(s->kind, s->dim) || !k_in_range(s->k) || !rng_seeded)
        return MCS_ERR_UNINIT;
    if (k != s->k)
        return MCS_ERR_MISMATCH;
    return MCS_OK;
}

static uint32_t reverse_bits(uint32_t x)
{
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
}

uint32_t mcs_sampler_owen_scramble(uint32_t x, uint32_t seed)
{
    /* Bit-reversed, the 1/2 digit is bit 0. Each step changes bit b only by
     * bits below b: x ^= x * even (the product's bit b uses bits < b), adding
     * a constant and multiplying by an odd number (carries move upwards). So
     * reversed back, each digit is flipped by a function of the digits above
     * it: nested scrambling. Constants: Vegdahl's improved Laine-Karras hash. */
    x = reverse_bits(x);
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return reverse_bits(x);
}

/* A 32-bit integer mixer (Wellons' lowbias32): supplies the digits below
 * 2^-32 of a scrambled coordinate from its 32-bit prefix and the seed. */
static uint32_t mix32(uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

static double owen_to_double(uint32_t bits, uint32_t seed)
{
    uint32_t scrambled = mcs_sampler_owen_scramble(bits, seed);
    uint32_t low = mix32(scrambled ^ mix32(seed ^ 0x9e3779b9u)) >> 11; /* 21 more digits */
    return ((double)scrambled * 2097152.0 + (double)low) * TWO_M53;
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

/* phi_3(j) = (digits of j in base 3, reversed) / 3^d: the reversed digits
 * form an integer below 3^21 < 2^53, so one division rounds it correctly. */
static double radical_inverse3(uint32_t j)
{
    uint64_t rev = 0u, scale = 1u;
    while (j != 0u) {
        rev = rev * 3u + j % 3u;
        scale *= 3u;
        j /= 3u;
    }
    return (double)rev / (double)scale;
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

/* Top 53 bits of a 64-bit fraction: a double in [0, 1). */
static double fraction64(uint64_t x)
{
    return (double)(x >> 11) * TWO_M53;
}

/* u + shift mod 1 for u, shift in [0,1): if u + shift >= 1 the subtraction
 * is exact; if the sum rounds up to exactly 1 it becomes 0. */
static double rotate(double u, double shift)
{
    double x = u + shift;
    return x >= 1.0 ? x - 1.0 : x;
}

mcs_status mcs_sampler_base_points(const mcs_sampler *s, size_t k, double *points)
{
    mcs_status st = check(s, 1, k, points);
    if (st != MCS_OK)
        return st;
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
    const size_t dim = s->dim;
    for (size_t a = 0; a < dim; ++a) {
        if (s->kind == MCS_SAMPLER_SOBOL) {
            uint32_t seed = mcs_rng_next_(rng);
            for (size_t j = 0; j < k; ++j)
                points[dim * j + a] = owen_to_double(sobol_bits((uint32_t)j, a), seed);
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
