/* The point sources of `mcspec sample` and `mcspec projections KIND`: one
 * table of kinds (name, the dimensions it has, set-up and draw), the 1D
 * patterns, the 2D patterns and the samplers of the library. A new kind is
 * one row in cli/cmd_sample.c's table (the blue-noise kinds are there too). */
#ifndef MCSPEC_CLI_SAMPLE_H
#define MCSPEC_CLI_SAMPLE_H

#include <stddef.h>
#include <stdint.h>

#include "mcspec.h"

typedef struct cli_sample_kind cli_sample_kind;

/* A set-up source: what its draw needs. */
typedef struct {
    const cli_sample_kind *kind;
    size_t dim, k, n;            /* dimension, points per set, bins of a 1D pattern */
    mcs_pattern pattern;         /* 1D patterns */
    mcs_pattern2d pattern2d;     /* 2D patterns */
    mcs_sampler sampler;         /* samplers */
    size_t *bins;                /* 1D patterns: bins[k], weights[k] (allocated) */
    double *weights;
    void *work;                  /* blue-noise kinds: their work memory (allocated) */
    size_t work_bytes;
} cli_sample_source;

struct cli_sample_kind {
    const char *name;
    size_t dim_min, dim_max; /* the dimensions it has */
    int arg;                 /* the library's kind enum of the row */
    /* MCS_OK, or a status the caller reports (K out of range, ...) */
    mcs_status (*init)(cli_sample_source *src);
    /* one set of src->k points into points[k * dim] */
    mcs_status (*draw)(const cli_sample_source *src, mcs_rng *rng, double *points);
};

/* "random, stratified, ...": every kind name, for messages and --help. */
void cli_sample_names(char *buf, size_t size);

/* Sets up kind `name` in dim dimensions with k points (n bins for the 1D
 * patterns). Returns 0, or an exit status after one line on stderr (an
 * unknown kind lists the kinds; a kind without that dimension says which it
 * has). */
int cli_sample_init(const char *cmd, const char *name, size_t dim, size_t k, size_t n,
                    cli_sample_source *src);
void cli_sample_free(cli_sample_source *src);

/* One set. Returns 0 or CLI_EXIT_FAIL after a message. */
int cli_sample_draw(const char *cmd, const cli_sample_source *src, mcs_rng *rng, double *points);

#endif /* MCSPEC_CLI_SAMPLE_H */
