/* A renderer's check of its sampler's dimensions (issue 26): the projection
 * analysis of mcspec (projections.h) over every pair of dimensions of four
 * 8-dimensional samplers written here as renderers have them, and the list
 * of pairs it flags:
 *  - c-ray:        Owen-scrambled Sobol whose dimensions repeat after six
 *                  (dimension 6 is dimension 0 again, 7 is 1), as the C path
 *                  tracer c-ray's sampler does;
 *  - shared-seed:  padded Sobol pairs, each pair scrambled and permuted from
 *                  its own seed, except that pairs (2,3) and (4,5) are seeded
 *                  from the same value (a pixel hash that forgot the
 *                  dimension): the two pairs are the same points;
 *  - padded:       mcspec's padded sampler, every pair independent;
 *  - random:       independent uniform coordinates.
 * A unit test (test/measures/test_projections.c) asserts the same in the
 * library; test/sample_check.sh asserts this program's lines. Usage:
 * sampler_check [--k K] [--sets T] [--seed S]. */
#include "mcspec.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DIM 8u
#define FREQ 8u
#define RADIUS 3u
#define MAX_K 4096u

static double points[DIM * MAX_K];
static double pair[2u * MAX_K];
static unsigned char work[MCS_PROJECTIONS_SIZE(DIM, FREQ, MAX_K)];

typedef int (*draw_fn)(mcs_rng *rng, size_t k, double *x);

static int draw_cray(mcs_rng *rng, size_t k, double *x)
{
    static double six[6u * MAX_K];
    mcs_sampler s;
    if (mcs_sampler_init(&s, MCS_SAMPLER_SOBOL_ND, 6u, k) != MCS_OK ||
        mcs_sampler_draw(&s, rng, k, six) != MCS_OK)
        return -1;
    for (size_t j = 0; j < k; ++j)
        for (size_t a = 0; a < DIM; ++a)
            x[j * DIM + a] = six[j * 6u + a % 6u];
    return 0;
}

/* One padded pair from a seed: an Owen-scrambled Sobol pair in the order of
 * a permutation keyed by the seed, as a renderer pads. */
static int draw_pair(uint64_t seed, size_t k, size_t axis, double *x)
{
    mcs_sampler s;
    mcs_rng r;
    if (mcs_sampler_init(&s, MCS_SAMPLER_SOBOL, 2u, k) != MCS_OK ||
        mcs_rng_seed(&r, seed, 26u) != MCS_OK || mcs_sampler_draw(&s, &r, k, pair) != MCS_OK)
        return -1;
    uint32_t key = (uint32_t)(seed * 0x9e3779b97f4a7c15u >> 32);
    for (size_t j = 0; j < k; ++j) {
        uint32_t i = mcs_pattern2d_permute((uint32_t)j, (uint32_t)k, key);
        x[j * DIM + axis] = pair[2u * i];
        x[j * DIM + axis + 1u] = pair[2u * i + 1u];
    }
    return 0;
}

static int draw_shared_seed(mcs_rng *rng, size_t k, double *x)
{
    uint32_t seeds[4];
    for (int p = 0; p < 4; ++p)
        if (mcs_rng_u32(rng, &seeds[p]) != MCS_OK)
            return -1;
    seeds[2] = seeds[1]; /* the bug: pair 2's hash is pair 1's */
    for (size_t p = 0; p < 4u; ++p)
        if (draw_pair(seeds[p], k, 2u * p, x) != 0)
            return -1;
    return 0;
}

static int draw_padded(mcs_rng *rng, size_t k, double *x)
{
    mcs_sampler s;
    return mcs_sampler_init(&s, MCS_SAMPLER_PADDED, DIM, k) == MCS_OK &&
                   mcs_sampler_draw(&s, rng, k, x) == MCS_OK
               ? 0
               : -1;
}

static int draw_random(mcs_rng *rng, size_t k, double *x)
{
    for (size_t i = 0; i < k * DIM; ++i)
        if (mcs_rng_double(rng, &x[i]) != MCS_OK)
            return -1;
    return 0;
}

/* Runs the analysis of one sampler and prints its flagged pairs. */
static int check(const char *name, draw_fn draw, size_t k, size_t sets, uint64_t seed)
{
    mcs_projections p;
    mcs_rng rng;
    if (mcs_projections_init(&p, DIM, FREQ, RADIUS, k, 0u, work, sizeof work) != MCS_OK ||
        mcs_rng_seed(&rng, seed, 0u) != MCS_OK)
        return -1;
    for (size_t t = 0; t < sets; ++t)
        if (draw(&rng, k, points) != 0 || mcs_projections_add(&p, k, points) != MCS_OK)
            return -1;
    size_t flagged = 0;
    if (mcs_projections_flagged(&p, &flagged) != MCS_OK)
        return -1;
    printf("%-12s %2zu of %zu pairs flagged:", name, flagged, (size_t)(DIM * (DIM - 1u) / 2u));
    for (size_t i = 0; i < DIM; ++i)
        for (size_t j = i + 1u; j < DIM; ++j) {
            mcs_projections_pair r;
            if (mcs_projections_pair_stats(&p, i, j, &r) != MCS_OK)
                return -1;
            if (r.flagged)
                printf(" (%zu,%zu) peak %.0f", i, j, r.peak_max);
        }
    printf("%s\n", flagged == 0u ? " none" : "");
    return 0;
}

static int option(int argc, char **argv, int *i, const char *name, unsigned long long lo,
                  unsigned long long hi, unsigned long long *out)
{
    if (strcmp(argv[*i], name) != 0)
        return 0;
    char *end = NULL;
    unsigned long long v = *i + 1 < argc ? strtoull(argv[*i + 1], &end, 10) : 0u;
    if (end == NULL || *end != '\0' || v < lo || v > hi) {
        fprintf(stderr, "sampler_check: %s takes a whole number in %llu..%llu\n", name, lo, hi);
        exit(2);
    }
    *out = v;
    *i += 1;
    return 1;
}

int main(int argc, char **argv)
{
    unsigned long long k = 256u, sets = 32u, seed = 1u;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--help") == 0) {
            puts("usage: sampler_check [--k K] [--sets T] [--seed S]\n"
                 "Flags the correlated pairs of dimensions of four 8D samplers (see the source).");
            return 0;
        }
        if (!option(argc, argv, &i, "--k", 16u, MAX_K, &k) &&
            !option(argc, argv, &i, "--sets", 2u, 100000u, &sets) &&
            !option(argc, argv, &i, "--seed", 0u, UINT64_MAX, &seed)) {
            fprintf(stderr, "sampler_check: unknown option '%s' (see --help)\n", argv[i]);
            return 2;
        }
    }
    printf("projection analysis of 8D samplers: K = %llu, %llu sets, F = %u, R = %u\n", k, sets,
           FREQ, RADIUS);
    const struct {
        const char *name;
        draw_fn draw;
    } samplers[4] = {{"c-ray", draw_cray},
                     {"shared-seed", draw_shared_seed},
                     {"padded", draw_padded},
                     {"random", draw_random}};
    for (int s = 0; s < 4; ++s)
        if (check(samplers[s].name, samplers[s].draw, (size_t)k, (size_t)sets, seed) != 0) {
            fprintf(stderr, "sampler_check: %s failed\n", samplers[s].name);
            return 1;
        }
    return 0;
}
