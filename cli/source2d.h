/* The named 2D point sources of the mcspec command: the 2D patterns
 * (mcs_pattern2d) and the 2D low-discrepancy samplers (mcs_sampler), their
 * exact periodogram where one exists, and their trial loop into the 2D
 * point-set spectrum (for `mcspec pattern KIND --dim 2`).
 *
 * Exact <P(k)>: the closed forms of mcs_pointset2d_exact_power for random,
 * jittered, grid, shifted-grid and n-rooks; for the rotated or shifted
 * samplers (halton, hammersley, kronecker) the periodogram of the
 * unrandomised set, which a Cranley-Patterson rotation or a shift changes by
 * a common phase only at integer wave vectors (mcs_sampler_base_points), so
 * every trial has it exactly; Owen's theory for the scrambled samplers
 * (docs/owen.md: Sobol, Owen-scrambled Halton); none for multi-jittered, cmj,
 * permuted Halton and padded pairs, which the report says. */
#ifndef MCSPEC_CLI_SOURCE2D_H
#define MCSPEC_CLI_SOURCE2D_H

#include <stddef.h>
#include <stdint.h>

#include "mcspec.h"
#include "output.h"
#include "progress.h"

/* "random, jittered, grid, shifted-grid, n-rooks, multi-jittered, cmj,
 * halton, hammersley, sobol-owen, kronecker": the names KIND takes. */
#define CLI_SOURCE2D_NAMES                                                                     \
    "random, jittered, grid, shifted-grid, n-rooks, multi-jittered, cmj, halton, hammersley, " \
    "sobol-owen, kronecker"

typedef struct {
    const char *name;      /* KIND as given */
    int is_sampler;
    mcs_pattern2d pattern; /* when !is_sampler */
    mcs_sampler sampler;   /* when is_sampler */
    size_t k;              /* points per trial */
    mcs_pointset2d *base;  /* rotated samplers: the unrandomised set's periodogram; else NULL */
    void *base_mem;        /* its buffer */
    /* Owen-scrambled samplers (mcs_owen_theory_of NESTED): the (0,m,2)-net
     * route for Sobol at K = 2^m (net_m = m + 1), else the pair counts of the
     * unscrambled points (owen, over owen_work) up to CLI_OWEN_MAX_K points */
    size_t net_m;
    mcs_owen *owen;
    uint64_t *owen_work;
} cli_source2d;

/* Most points whose pair counts the command forms for Owen's theory (O(K^2),
 * about 2 s at this K); above it only Sobol at K = 2^m has the exact column. */
#define CLI_OWEN_MAX_K 16384u

/* 1 if name is a 2D source, else 0. */
int cli_source2d_known(const char *name);

/* Sets up source name with k points (patterns with the most nearly square
 * strata) and, for the rotated samplers, the exact periodogram up to
 * cutoff freq. Returns 0, or an exit status after one line on stderr. */
int cli_source2d_init(const char *cmd, const char *name, size_t k, size_t freq,
                      cli_source2d *src);
void cli_source2d_free(cli_source2d *src);

/* 1 if src's points depend on its m x n strata (not random, n-rooks or a
 * sampler). */
int cli_source2d_uses_strata(const cli_source2d *src);

/* What the exact column holds for src: "closed form"
 * (mcs_pointset2d_exact_power), "unrandomised set", or "" where there is none. */
const char *cli_source2d_exact_source(const cli_source2d *src);

/* The exact <P(kx, ky)> and radial averages of src for a report, NaN where
 * there are none (|kx|, |ky|, r <= the freq given to init); scale K. */
void cli_source2d_exact(const cli_source2d *src, cli_exact2d *out);

/* Draws trials [first, last) of stream `stream` (PCG32 seeded (seed,
 * stream), as cli/streams.h) of src into acc, a mcs_pointset2d. Returns 0 or
 * CLI_EXIT_FAIL after a message. Fits cli_stream_job's run. */
int cli_source2d_run(const char *cmd, const void *src, uint64_t seed, uint64_t stream,
                     uint64_t first, uint64_t last, void *acc, cli_progress *progress);

#endif /* MCSPEC_CLI_SOURCE2D_H */
