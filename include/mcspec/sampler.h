/* Low-discrepancy samplers as renderers use them, randomised
 * per trial from an mcs_rng so that each trial is an unbiased point set and
 * trials are independent:
 *
 *   kind            dim  point j (j = 0..K-1)                 per-trial randomisation
 *   van der Corput  1    phi_2(j)                             Cranley-Patterson rotation
 *   Halton          2    (phi_2(j), phi_3(j))                 Cranley-Patterson rotation
 *   Hammersley      2    (j/K, phi_2(j))                      Cranley-Patterson rotation
 *   Sobol           1,2  Sobol dimensions 1 (and 2)           hash-based Owen scrambling
 *   Kronecker       1,2  frac(j alpha)                        random shift (mod 1)
 *                        alpha = 1/golden (1D), or R2 (1/g, 1/g^2) with g^3 = g + 1 (2D)
 *
 * phi_b is the radical inverse in base b. Sobol points are in index order
 * (point j is the xor of the direction numbers of j's set bits, as in pbrt
 * and Burley), not Gray-code order: the first 2^m points are the same set. A Cranley-Patterson rotation adds
 * one uniform shift per axis, modulo 1. Owen scrambling (nested uniform
 * scrambling) flips each binary digit of a coordinate by an independent
 * fair coin per node of the digit tree (the digit's place and the digits
 * above it); here each coin is a bit of a 64-bit hash of the node and a key
 * mixed from a 64-bit seed per axis per trial (two rng outputs), and the
 * digits below 2^-32 come from the hash of the whole 32-digit prefix (what
 * scrambling to full double precision would give).
 *
 * Any dimension, 1..MCS_SAMPLER_MAX_DIM (docs/samplers-nd.md has the
 * definitions, data sources and references):
 *
 *   kind             dim      point j, coordinate a               per-trial randomisation
 *   sobol-owen-nd    1..64    Sobol dimension a + 1, Joe and Kuo's hash-based Owen scrambling,
 *                             new-joe-kuo-6.21201 direction       one seed per axis (the same
 *                             numbers                             draws as sobol-owen: its
 *                                                                 dims 1 and 2 bit for bit)
 *   halton-permuted  1..64    phi_b(j), b the (a+1)-th prime,     a random permutation of the
 *                             every digit to double precision     digits per base and digit
 *                                                                 position (pbrt-v4's
 *                                                                 DigitPermutation), one seed
 *                                                                 per axis
 *   halton-owen      1..64    phi_b(j) as above                   nested uniform scrambling in
 *                                                                 base b: each digit permuted
 *                                                                 by a function of the digits
 *                                                                 above it, one seed per axis
 *   lattice          1..64    frac(j z_a / K), z_a = g^a mod K    random shift (mod 1)
 *                             (Korobov), g from a search (below)
 *   padded           2..64    pair p = axes (2p, 2p+1): an        each pair drawn
 *                             independent 2D set of `pad` kind,   independently, its points
 *                             point order permuted per pair       permuted by a random
 *                             (an odd last axis: the first        permutation of [0, K)
 *                             coordinate of one more pair)        (as pbrt pads)
 *
 * The Halton digit permutations come from a hash of the node: uniform random
 * permutations (Fisher-Yates) in bases up to 13; above, a uniform affine map
 * after Kensler's hashed permutation, which sends every pair of distinct
 * digits to a uniform pair of distinct digits (the pair law of uniform
 * permutations, all a spectrum uses). The padded point orders are Kensler's
 * hashed permutations (mcs_pattern2d_permute).
 *
 * Points are written interleaved: points[dim * j + d] is coordinate d of
 * point j, every coordinate in [0, 1). K is at most 2^32 (32-bit indices).
 * sizeof(mcs_sampler) is 32 bytes on x86-64 (20 on 32-bit targets). */
#ifndef MCSPEC_SAMPLER_H
#define MCSPEC_SAMPLER_H

#include <stddef.h>
#include <stdint.h>
#include "status.h"
#include "rng.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    MCS_SAMPLER_VAN_DER_CORPUT = 0, /* 1D only */
    MCS_SAMPLER_HALTON = 1,         /* 2D only */
    MCS_SAMPLER_HAMMERSLEY = 2,     /* 2D only */
    MCS_SAMPLER_SOBOL = 3,          /* 1D or 2D */
    MCS_SAMPLER_KRONECKER = 4,      /* 1D or 2D */
    MCS_SAMPLER_SOBOL_ND = 5,       /* 1..MCS_SAMPLER_MAX_DIM */
    MCS_SAMPLER_HALTON_PERMUTED = 6, /* 1..MCS_SAMPLER_MAX_DIM */
    MCS_SAMPLER_PADDED = 7,         /* 2..MCS_SAMPLER_MAX_DIM */
    MCS_SAMPLER_HALTON_OWEN = 8,    /* 1..MCS_SAMPLER_MAX_DIM */
    MCS_SAMPLER_LATTICE = 9         /* 1..MCS_SAMPLER_MAX_DIM */
} mcs_sampler_kind;

#define MCS_SAMPLER_KIND_COUNT 10

/* Largest dimension of the any-dimension kinds: the Sobol table holds 64
 * dimensions and Halton the first 64 primes (2..311). */
#define MCS_SAMPLER_MAX_DIM 64

typedef struct {
    mcs_sampler_kind kind;
    uint32_t pad;        /* padded: the 2D kind of each pair (an mcs_sampler_kind); else 0 */
    uint32_t generator;  /* lattice: Korobov's g (z_a = g^a mod K); else 0 */
    size_t dim;          /* 1..MCS_SAMPLER_MAX_DIM as the kind allows */
    size_t k;            /* points per trial K, 1..2^32 */
} mcs_sampler;

/* Name of a kind ("van-der-corput", "halton", "hammersley", "sobol-owen",
 * "kronecker", "sobol-owen-nd", "halton-permuted", "padded", "halton-owen",
 * "lattice"), or "unknown". */
const char *mcs_sampler_kind_str(mcs_sampler_kind kind);

/* 1 if kind is defined in dimension dim (see the table above), else 0. */
int mcs_sampler_has_dim(mcs_sampler_kind kind, size_t dim);

/* Configures a sampler of K points in dim dimensions. padded pads with
 * sobol-owen pairs; lattice takes mcs_sampler_lattice_generator(k, dim).
 * MCS_ERR_NULL, MCS_ERR_KIND (unknown kind, or kind not defined in dim),
 * MCS_ERR_K_RANGE (k = 0 or k > 2^32; padded: k > 2^32 - 1). *s untouched
 * on error. */
mcs_status mcs_sampler_init(mcs_sampler *s, mcs_sampler_kind kind, size_t dim, size_t k);

/* A padded sampler whose pairs are 2D sets of kind pad (halton, hammersley,
 * sobol-owen or kronecker), dim 2..MCS_SAMPLER_MAX_DIM, K 1..2^32 - 1.
 * MCS_ERR_NULL, MCS_ERR_KIND (pad not one of those, or dim out of range),
 * MCS_ERR_K_RANGE. *s untouched on error. */
mcs_status mcs_sampler_init_padded(mcs_sampler *s, mcs_sampler_kind pad, size_t dim, size_t k);

/* A Korobov lattice sampler with the caller's generator g (1 <= g < K, or
 * g = 1 when K = 1): z_a = g^a mod K. MCS_ERR_NULL, MCS_ERR_KIND (dim out of
 * range), MCS_ERR_K_RANGE, MCS_ERR_MISMATCH (g out of range). *s untouched
 * on error. */
mcs_status mcs_sampler_init_lattice(mcs_sampler *s, size_t dim, size_t k, uint32_t g);

/* Korobov's generator for K points in dim dimensions as mcs_sampler_init
 * picks it: of the 256 candidates g_c = the first integer >= max(2, round(K
 * frac(c / golden))) coprime to K (c = 1..256), the one whose worst 2D
 * projection is best: the largest min over lags l = 1..dim-1 of the
 * shortest nonzero dual vector |h| (h_0 + h_1 g^l = 0 mod K) of the 2D
 * lattice (1, g^l) / K, the spectral test. Pair (a, a + l) of the lattice
 * is the point set of (1, g^l) (g^a is a unit mod K), so this is the worst
 * pair of dimensions. 1 for K <= 2 or dim = 1. 0 when k or dim is out of
 * range. */
uint32_t mcs_sampler_lattice_generator(size_t k, size_t dim);

/* One randomised trial: points[k * dim] written. k must equal s->k.
 * Draws from rng per axis per trial a shift or a 64-bit scrambling seed, two
 * outputs each (a padded sampler one more per pair, for its point order).
 * MCS_ERR_NULL, MCS_ERR_UNINIT (s not from mcs_sampler_init, or rng never
 * seeded), MCS_ERR_MISMATCH (k != s->k).
 * On error nothing is written and rng is not advanced. */
mcs_status mcs_sampler_draw(const mcs_sampler *s, mcs_rng *rng, size_t k, double *points);

/* The same K points without randomisation (no rotation, no shift, Sobol
 * unscrambled, Halton digits unpermuted, padded pairs unscrambled and in
 * index order): points[k * dim] written. A Cranley-Patterson rotation or a
 * shift changes each e^{-2 pi i f.x_j} by one common phase at integer f, so
 * for the rotated and shifted kinds (van der Corput, halton, hammersley,
 * kronecker, lattice: mcs_sampler_base_is_exact) these points give the
 * exact (deterministic) periodogram. Statuses as mcs_sampler_draw. */
mcs_status mcs_sampler_base_points(const mcs_sampler *s, size_t k, double *points);

/* Base-2 nested uniform (Owen) scrambling of a 32-bit binary fraction x (bit
 * 31 is the 1/2 digit) under seed: bit b of the result is bit b of x flipped
 * by a coin of the node (b, the bits of x above b): a bit of a 64-bit hash
 * of the node and of a key mixed from seed, so the coins of all nodes are
 * independent fair coins as far as tests over seeds tell. So for every m, the
 * top m bits of the result depend only on the top m bits of x, and distinct
 * top-m prefixes stay distinct. */
uint32_t mcs_sampler_owen_scramble(uint32_t x, uint32_t seed);

/* 1 if kind's randomisation is a rotation or shift mod 1 (van der Corput,
 * halton, hammersley, kronecker, lattice), so that mcs_sampler_base_points
 * gives every trial's periodogram exactly; else 0. */
int mcs_sampler_base_is_exact(mcs_sampler_kind kind);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_SAMPLER_H */
