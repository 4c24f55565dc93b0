/* Private to the blue-noise samplers (blue*.c, pmj02.c): a uniform grid of
 * linked cells over the torus for the distance queries, the toroidal
 * distance, and carving the caller's work buffer. */
#ifndef MCSPEC_BLUE_INTERNAL_H
#define MCSPEC_BLUE_INTERNAL_H

#include <stddef.h>
#include <stdint.h>
#include "mcspec/bluenoise.h"
#include "mcspec/rng.h"

/* An empty cell or the end of a cell's list. */
#define MCS_BLUE_NONE UINT32_MAX

/* Points in [0,1)^dim, dim <= 3, sorted into m^dim cells of side 1/m: cell c
 * holds head[c], next[head[c]], ... . pts[dim i + a] is coordinate a of
 * point i (the points in the order added), cap points at most. */
typedef struct {
    size_t dim, m, cells, count, cap;
    uint32_t *head, *next;
    double *pts;
} mcs_blue_grid_;

/* The caller's work, carved front to back. */
typedef struct {
    unsigned char *at;
    size_t left;
} mcs_blue_carver_;

/* Cells per axis of a grid for about k points: the largest m with
 * m^dim <= k, at least 1. */
size_t mcs_blue_grid_side_(size_t dim, size_t k);

/* Bytes that carving n items of size elem (aligned to 8) takes at most. */
size_t mcs_blue_carve_bytes_(size_t n, size_t elem);

/* The next n items of size elem, 8-aligned, from c (the caller sized the
 * buffer with mcs_blue_carve_bytes_, so there is room). */
void *mcs_blue_carve_(mcs_blue_carver_ *c, size_t n, size_t elem);

/* An empty grid of side mcs_blue_grid_side_(dim, k) over the caller's
 * g->head[cells], g->next[cap] and g->pts[cap dim], set before the call
 * (at most six arguments per call keeps every frame static: stack.sh). */
void mcs_blue_grid_init_(mcs_blue_grid_ *g, size_t dim, size_t k, size_t cap);

/* Empties the cells (the points stay in pts, count is 0). */
void mcs_blue_grid_clear_(mcs_blue_grid_ *g);

/* Appends p (dim coordinates in [0,1)) as point count; count < cap. p may be
 * the slot it is copied to. */
void mcs_blue_grid_add_(mcs_blue_grid_ *g, const double *p);

/* 1 if some point of g is at toroidal distance below r from p (squared
 * distances compared, r^2 against the sum of squares in axis order). */
int mcs_blue_grid_conflict_(const mcs_blue_grid_ *g, const double *p, double r);

/* The squared toroidal distance from p to the nearest point of g, its index
 * to *index (HUGE_VAL and MCS_BLUE_NONE when g is empty). */
double mcs_blue_grid_nearest_(const mcs_blue_grid_ *g, const double *p, uint32_t *index);

/* The toroidal squared distance of a and b in dim dimensions, summed in axis
 * order (the tests sum the same way). */
double mcs_blue_torus_d2_(size_t dim, const double *a, const double *b);

/* d_max of k points in dim (1..3) dimensions (spacing.h's table). */
double mcs_blue_packing_distance_(size_t dim, size_t k);

/* x mod 1 in [0, 1) (x - floor(x) rounding up to 1 gives 0). */
double mcs_blue_wrap_(double x);

/* The draws of the samplers, unchecked: rng seeded. */
double mcs_blue_uniform_(mcs_rng *rng);
uint32_t mcs_blue_bounded_(mcs_rng *rng, uint32_t bound);
uint64_t mcs_blue_bits_(mcs_rng *rng, unsigned bits); /* bits <= 64 uniform bits */

/* The samplers behind mcs_bluenoise_draw and _maximal, after every check:
 * the work's bytes are at least their *_work_bytes_ for (dim, k), rng is
 * seeded and may be advanced even on failure (the caller restores it), and
 * p holds the resolved parameters. Each writes points only on MCS_OK. */
typedef struct {
    mcs_bluenoise_kind kind;
    size_t dim, k;
    mcs_bluenoise_params p; /* resolved */
    mcs_rng *rng;
    void *work;
    int maximal;   /* mcs_bluenoise_maximal: all n points, n to *count */
    double *points;
    size_t *count; /* maximal only */
} mcs_blue_job_;
size_t mcs_blue_poisson_work_bytes_(size_t dim, size_t k);
mcs_status mcs_blue_poisson_(const mcs_blue_job_ *job);
size_t mcs_blue_lloyd_work_bytes_(size_t k);
mcs_status mcs_blue_lloyd_(size_t k, const mcs_bluenoise_params *p, mcs_rng *rng, void *work,
                           double *points);
size_t mcs_pmj02_work_bytes_(size_t k);
mcs_status mcs_pmj02_(size_t k, uint32_t candidates, mcs_rng *rng, void *work, double *points);

#endif /* MCSPEC_BLUE_INTERNAL_H */
