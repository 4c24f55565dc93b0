/* Low-discrepancy samplers in 1D and 2D as renderers use them, randomised
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
 * scrambling) flips each binary digit of a coordinate by a random function
 * of the digits above it; here the random functions are the hash of
 * Laine-Karras / Burley ("Practical hash-based Owen scrambling", JCGT 2020)
 * with N. Vegdahl's constants, one 32-bit seed per axis per trial, and the
 * digits below 2^-32 come from a second hash of the scrambled prefix and the
 * seed (what scrambling to full double precision would give).
 *
 * Points are written interleaved: points[dim * j + d] is coordinate d of
 * point j, every coordinate in [0, 1). K is at most 2^32 (32-bit indices).
 * sizeof(mcs_sampler) is 24 bytes on x86-64 (12 on 32-bit targets). */
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
    MCS_SAMPLER_KRONECKER = 4       /* 1D or 2D */
} mcs_sampler_kind;

#define MCS_SAMPLER_KIND_COUNT 5

typedef struct {
    mcs_sampler_kind kind;
    size_t dim; /* 1 or 2 */
    size_t k;   /* points per trial K, 1..2^32 */
} mcs_sampler;

/* Name of a kind ("van-der-corput", "halton", "hammersley", "sobol-owen",
 * "kronecker"), or "unknown". */
const char *mcs_sampler_kind_str(mcs_sampler_kind kind);

/* 1 if kind is defined in dimension dim (see the table above), else 0. */
int mcs_sampler_has_dim(mcs_sampler_kind kind, size_t dim);

/* Configures a sampler of K points in dim dimensions. MCS_ERR_NULL,
 * MCS_ERR_KIND (unknown kind, or kind not defined in dim; dim not 1 or 2),
 * MCS_ERR_K_RANGE (k = 0 or k > 2^32). *s untouched on error. */
mcs_status mcs_sampler_init(mcs_sampler *s, mcs_sampler_kind kind, size_t dim, size_t k);

/* One randomised trial: points[k * dim] written. k must equal s->k.
 * Draws dim values from rng per trial (a shift, or a scrambling seed).
 * MCS_ERR_NULL, MCS_ERR_UNINIT (s not from mcs_sampler_init, or rng never
 * seeded), MCS_ERR_MISMATCH (k != s->k).
 * On error nothing is written and rng is not advanced. */
mcs_status mcs_sampler_draw(const mcs_sampler *s, mcs_rng *rng, size_t k, double *points);

/* The same K points without randomisation (no rotation, no shift, Sobol
 * unscrambled): points[k * dim] written. A Cranley-Patterson rotation or a
 * shift changes each e^{-2 pi i f.x_j} by one common phase at integer f, so
 * these points give the exact (deterministic) periodogram of the randomised
 * kinds. Statuses as mcs_sampler_draw. */
mcs_status mcs_sampler_base_points(const mcs_sampler *s, size_t k, double *points);

/* Base-2 nested uniform (Owen) scrambling of a 32-bit binary fraction x (bit
 * 31 is the 1/2 digit) under seed: bit b of the result is bit b of x flipped
 * by a function of seed and the bits of x above b. So for every m, the top m
 * bits of the result depend only on the top m bits of x, and distinct top-m
 * prefixes stay distinct. */
uint32_t mcs_sampler_owen_scramble(uint32_t x, uint32_t seed);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_SAMPLER_H */
