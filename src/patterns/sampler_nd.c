/* The any-dimension samplers but padded (sampler.h): Owen-scrambled Sobol
 * with Joe and Kuo's direction numbers, Halton with permuted digits and
 * with nested uniform (Owen) scrambling in base b, and Korobov's rank-1
 * lattice with a random shift, whose generator is picked here. */
#include "sampler_internal.h"
#include "mcspec/pattern2d.h"
#include "random/rng_inline.h"

#include <stddef.h>
#include <stdint.h>

/* The first 64 primes: the Halton base of axis a is primes[a]. */
static const uint32_t primes[MCS_SAMPLER_MAX_DIM] = {
    2,   3,   5,   7,   11,  13,  17,  19,  23,  29,  31,  37,  41,  43,  47,  53,
    59,  61,  67,  71,  73,  79,  83,  89,  97,  101, 103, 107, 109, 113, 127, 131,
    137, 139, 149, 151, 157, 163, 167, 173, 179, 181, 191, 193, 197, 199, 211, 223,
    227, 229, 233, 239, 241, 251, 257, 263, 269, 271, 277, 281, 283, 293, 307, 311};

/* How a Halton axis randomises its digits. */
typedef enum { DIGITS_PLAIN, DIGITS_PERMUTED, DIGITS_OWEN } digit_mode;

/* Number of base-b digits n with b^n >= 2^53 (every digit a double holds),
 * and b^n: below 311 * 2^53 < 2^62. */
static unsigned digit_count(uint32_t b, uint64_t *bn)
{
    uint64_t p = 1u;
    unsigned n = 0u;
    while (p < (UINT64_C(1) << 53)) {
        p *= b;
        ++n;
    }
    *bn = p;
    return n;
}

/* Image of d under a uniform random permutation of [0, b), b <= 13: Fisher
 * and Yates' shuffle driven by the mixed-radix digits of r (uniform to within
 * b! / 2^64 < 2^-31). Called with constant b (fisher_yates_small), so that
 * the loop unrolls and its divisions become multiplications. */
static inline uint32_t fisher_yates(uint32_t d, uint64_t r, uint32_t b)
{
    unsigned char p[13];
    for (uint32_t e = 0; e < 13u; ++e)
        p[e] = (unsigned char)e;
    for (uint32_t i = b - 1u; i > 0u; --i) {
        const uint32_t j = (uint32_t)(r % (i + 1u));
        r /= i + 1u;
        const unsigned char t = p[i];
        p[i] = p[j];
        p[j] = t;
    }
    return p[d];
}

static uint32_t fisher_yates_small(uint32_t d, uint64_t r, uint32_t b)
{
    switch (b) {
    case 2u: return d ^ (uint32_t)(r & 1u);
    case 3u: return fisher_yates(d, r, 3u);
    case 5u: return fisher_yates(d, r, 5u);
    case 7u: return fisher_yates(d, r, 7u);
    case 11u: return fisher_yates(d, r, 11u);
    default: return fisher_yates(d, r, 13u);
    }
}

/* The permutation of digit i (0 = the 1/b digit) of an axis of key `key`,
 * from a hash h of the node: per axis and digit position (as pbrt-v4's
 * DigitPermutation), and for Owen also the digits above (prefix = j mod b^i,
 * below 2^32).
 * Bases up to 13: a uniform random permutation (Fisher-Yates from h).
 * Larger bases: a uniform affine map d -> (alpha d + beta) mod b,
 * 1 <= alpha < b (from h's halves by multiply-shift: uniform to within
 * b / 2^32), after Kensler's hashed permutation sigma. b is prime, so the
 * affine maps send any two distinct digits sigma(d), sigma(d') to a uniform
 * pair of distinct digits (the affine group is sharply 2-transitive): each
 * digit uniform, and the law of a pair of points (what spectra and Owen's
 * theory use) exactly that of uniform random permutations; sigma breaks up
 * the arithmetic progressions an affine map alone would leave, but triples
 * are only close to uniform. (Kensler's permutation alone, used before, sent
 * digits 0 and 1 of base 7 to a pair 32 standard units off uniform.) */
static uint32_t permute_digit(uint32_t d, uint32_t b, uint64_t key, unsigned i, uint64_t prefix,
                              digit_mode mode)
{
    const uint64_t node = (uint64_t)(i + 1u) << 40 | (mode == DIGITS_OWEN ? prefix : 0u);
    const uint64_t h = mcs_smp_mix64_(key ^ node);
    if (b <= 13u)
        return fisher_yates_small(d, h, b);
    const uint64_t alpha = 1u + ((h >> 32) * (b - 1u) >> 32);
    const uint64_t beta = (h & 0xffffffffu) * b >> 32;
    const uint32_t sigma = mcs_pattern2d_permute(d, b, (uint32_t)(mcs_smp_mix64_(h) >> 32));
    return (uint32_t)((alpha * sigma + beta) % b);
}

/* phi_b(j) with each of its n digits (the zeros beyond j's last digit too)
 * put through its permutation: R = sum_i d'_i b^(n-1-i) < b^n < 2^62 is
 * exact, and R / b^n is rounded once; the largest R can round up to 1,
 * which becomes the largest double below 1. */
static double halton_coordinate(uint32_t j, uint32_t b, uint64_t key, digit_mode mode)
{
    uint64_t bn = 0u;
    const unsigned n = digit_count(b, &bn);
    uint64_t r = 0u, rest = j, prefix = 0u, place = 1u;
    for (unsigned i = 0; i < n; ++i) {
        uint32_t d = (uint32_t)(rest % b);
        uint32_t e = d;
        if (mode != DIGITS_PLAIN)
            e = permute_digit(d, b, key, i, prefix, mode);
        r = r * b + e;
        if (rest != 0u) {
            prefix += (uint64_t)d * place;
            place *= b;
            rest /= b;
        }
    }
    double x = (double)r / (double)bn;
    return x < 1.0 ? x : 1.0 - MCS_SMP_TWO_M53;
}

static digit_mode mode_of(mcs_sampler_kind kind)
{
    return kind == MCS_SAMPLER_HALTON_OWEN ? DIGITS_OWEN : DIGITS_PERMUTED;
}

/* (j z mod K) / K: j < 2^32 and z < 2^32, so the product fits 64 bits. */
static double lattice_coordinate(uint32_t j, uint64_t z, uint64_t k)
{
    return (double)(((uint64_t)j * z) % k) / (double)k;
}

/* Column a of a trial: key or shift as drawn for that axis. */
static void fill_axis(const mcs_sampler *s, size_t a, uint64_t key, double shift, uint64_t z,
                      double *points)
{
    const size_t dim = s->dim, k = s->k;
    for (size_t j = 0; j < k; ++j) {
        double x;
        switch (s->kind) {
        case MCS_SAMPLER_SOBOL_ND:
            x = mcs_smp_owen_to_double_(mcs_smp_sobol_bits_((uint32_t)j, a), key);
            break;
        case MCS_SAMPLER_LATTICE:
            x = mcs_smp_rotate_(lattice_coordinate((uint32_t)j, z, k), shift);
            break;
        default:
            x = halton_coordinate((uint32_t)j, primes[a], key, mode_of(s->kind));
            break;
        }
        points[dim * j + a] = x;
    }
}

void mcs_sampler_draw_nd_(const mcs_sampler *s, mcs_rng *rng, double *points)
{
    uint64_t z = 1u;
    for (size_t a = 0; a < s->dim; ++a) {
        uint64_t key = 0u;
        double shift = 0.0;
        if (s->kind == MCS_SAMPLER_LATTICE)
            shift = mcs_rng_double_(rng);
        else
            key = mcs_smp_draw_key_(rng);
        fill_axis(s, a, key, shift, z, points);
        z = z * s->generator % (s->k > 0u ? (uint64_t)s->k : 1u); /* k >= 1 (checked) */
    }
}

void mcs_sampler_base_nd_(const mcs_sampler *s, double *points)
{
    const size_t dim = s->dim, k = s->k;
    uint64_t z = 1u;
    for (size_t a = 0; a < dim; ++a) {
        for (size_t j = 0; j < k; ++j) {
            double x;
            if (s->kind == MCS_SAMPLER_SOBOL_ND)
                x = (double)mcs_smp_sobol_bits_((uint32_t)j, a) * MCS_SMP_TWO_M32;
            else if (s->kind == MCS_SAMPLER_LATTICE)
                x = lattice_coordinate((uint32_t)j, z, k);
            else
                x = halton_coordinate((uint32_t)j, primes[a], 0u, DIGITS_PLAIN);
            points[dim * j + a] = x;
        }
        z = z * s->generator % (k > 0u ? (uint64_t)k : 1u); /* k >= 1 (checked) */
    }
}

/* ---- Korobov's generator -------------------------------------------------- */

int mcs_sampler_generator_ok_(size_t k, uint32_t g)
{
    return k == 1u ? g == 1u : g >= 1u && (uint64_t)g < (uint64_t)k;
}

static uint64_t gcd64(uint64_t a, uint64_t b)
{
    while (b != 0u) {
        uint64_t t = a % b;
        a = b;
        b = t;
    }
    return a;
}

/* Squared length of the shortest nonzero h with h_0 + h_1 y = 0 mod K: the
 * dual lattice of (1, y) / K, basis (K, 0) and (-y, 1), Lagrange-Gauss
 * reduced. Coordinates stay integers below 2^33; the dot products are taken
 * in double (exact enough to pick the quotient; a few iterations cap it). */
static double shortest_dual(uint64_t k, uint64_t y)
{
    int64_t u0 = (int64_t)k, u1 = 0, v0 = -(int64_t)y, v1 = 1;
    for (int it = 0; it < 256; ++it) {
        const double uu = (double)u0 * (double)u0 + (double)u1 * (double)u1;
        double vv = (double)v0 * (double)v0 + (double)v1 * (double)v1;
        if (vv > uu) {
            int64_t t0 = u0, t1 = u1;
            u0 = v0;
            u1 = v1;
            v0 = t0;
            v1 = t1;
            vv = uu;
        }
        /* now |v| <= |u|: reduce u by v */
        double mu = ((double)u0 * (double)v0 + (double)u1 * (double)v1) / vv;
        int64_t m = (int64_t)(mu < 0.0 ? mu - 0.5 : mu + 0.5);
        if (m == 0)
            return vv;
        u0 -= m * v0;
        u1 -= m * v1;
    }
    double a = (double)u0 * (double)u0 + (double)u1 * (double)u1;
    double b = (double)v0 * (double)v0 + (double)v1 * (double)v1;
    return a < b ? a : b;
}

/* The worst pair of dimensions of generator g: min over lags. */
static double merit(uint64_t k, uint64_t g, size_t dim)
{
    double worst = 0.0;
    uint64_t y = 1u;
    for (size_t l = 1; l < dim; ++l) {
        y = y * g % k;
        double h = shortest_dual(k, y);
        if (l == 1u || h < worst)
            worst = h;
    }
    return worst;
}

uint32_t mcs_sampler_lattice_generator(size_t k, size_t dim)
{
    if (k < 1u || (uint64_t)k - 1u > (uint64_t)UINT32_MAX || dim < 1u ||
        dim > MCS_SAMPLER_MAX_DIM)
        return 0u;
    if (k <= 2u || dim == 1u)
        return 1u;
    const uint64_t kk = (uint64_t)k;
    uint64_t best = 1u;
    double best_merit = -1.0;
    for (unsigned c = 1; c <= 256u; ++c) {
        double f = (double)c * 0.61803398874989484820;
        f -= (double)(uint64_t)f;
        uint64_t g = (uint64_t)((double)kk * f + 0.5);
        if (g < 2u)
            g = 2u;
        while (g < kk && gcd64(g, kk) != 1u)
            ++g;
        if (g >= kk)
            continue;
        double m = merit(kk, g, dim);
        if (m > best_merit) {
            best_merit = m;
            best = g;
        }
    }
    return (uint32_t)best;
}
