/* The linked-cell grid of the blue-noise samplers over the torus, the
 * toroidal distance, d_max, and their draws (blue_internal.h). */
#include "blue_internal.h"
#include "random/rng_inline.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>

/* A search stops when the best squared distance is within this fraction
 * below the ring bound (R / m)^2: a point's cell, floor(x m), can be off by
 * one where x m rounds across a whole number (as in spacing.c). */
#define REACH_MARGIN 1e-9

/* Centre densities of the densest packings in 1..3 dimensions (spacing.h):
 * 1/2, 1/(2 sqrt 3), 1/(4 sqrt 2). */
static const double centre_density[3] = {0.5, 0.28867513459481288225, 0.17677669529663688110};

double mcs_blue_packing_distance_(size_t dim, size_t k)
{
    return 2.0 * pow(centre_density[dim - 1u] / (double)k, 1.0 / (double)dim);
}

double mcs_blue_wrap_(double x)
{
    const double w = x - floor(x);
    return w < 1.0 ? w : 0.0;
}

double mcs_blue_torus_d2_(size_t dim, const double *a, const double *b)
{
    double s = 0.0;
    for (size_t c = 0; c < dim; ++c) {
        double d = fabs(a[c] - b[c]);
        d = d > 0.5 ? 1.0 - d : d;
        s += d * d;
    }
    return s;
}

double mcs_blue_uniform_(mcs_rng *rng) { return mcs_rng_double_(rng); }

uint32_t mcs_blue_bounded_(mcs_rng *rng, uint32_t bound) { return mcs_rng_bounded_(rng, bound); }

uint64_t mcs_blue_bits_(mcs_rng *rng, unsigned bits)
{
    if (bits == 0u)
        return 0u;
    const uint64_t hi = mcs_rng_next_(rng), lo = mcs_rng_next_(rng);
    const uint64_t v = hi << 32 | lo;
    return bits >= 64u ? v : v >> (64u - bits);
}

size_t mcs_blue_grid_side_(size_t dim, size_t k)
{
    size_t m = (size_t)pow((double)k, 1.0 / (double)dim);
    for (;;) { /* correct pow's rounding either way */
        size_t p = 1u;
        for (size_t c = 0; c < dim; ++c)
            p *= m + 1u;
        if (p > k)
            break;
        ++m;
    }
    for (;;) {
        size_t p = 1u;
        for (size_t c = 0; c < dim; ++c)
            p *= m;
        if (m <= 1u || p <= k)
            break;
        --m;
    }
    return m < 1u ? 1u : m;
}

size_t mcs_blue_carve_bytes_(size_t n, size_t elem)
{
    return n * elem + 8u;
}

void *mcs_blue_carve_(mcs_blue_carver_ *c, size_t n, size_t elem)
{
    const size_t pad = (8u - (size_t)((uintptr_t)c->at & 7u)) & 7u;
    unsigned char *p = c->at + pad;
    c->at = p + n * elem;
    c->left -= pad + n * elem;
    return p;
}

void mcs_blue_grid_init_(mcs_blue_grid_ *g, size_t dim, size_t k, size_t cap)
{
    g->dim = dim;
    g->m = mcs_blue_grid_side_(dim, k);
    g->cells = 1u;
    for (size_t c = 0; c < dim; ++c)
        g->cells *= g->m;
    g->cap = cap;
    mcs_blue_grid_clear_(g);
}

void mcs_blue_grid_clear_(mcs_blue_grid_ *g)
{
    for (size_t c = 0; c < g->cells; ++c)
        g->head[c] = MCS_BLUE_NONE;
    g->count = 0u;
}

static size_t axis_cell(const mcs_blue_grid_ *g, double x)
{
    const size_t c = (size_t)(x * (double)g->m);
    return c < g->m ? c : g->m - 1u;
}

static size_t cell_of(const mcs_blue_grid_ *g, const double *p)
{
    size_t cell = 0u;
    for (size_t c = g->dim; c-- > 0;)
        cell = cell * g->m + axis_cell(g, p[c]);
    return cell;
}

void mcs_blue_grid_add_(mcs_blue_grid_ *g, const double *p)
{
    const size_t i = g->count++;
    double *slot = g->pts + i * g->dim;
    for (size_t c = 0; c < g->dim; ++c)
        slot[c] = p[c];
    const size_t cell = cell_of(g, slot);
    g->next[i] = g->head[cell];
    g->head[cell] = (uint32_t)i;
}

/* The cells of the box of Chebyshev radius reach around p's cell, each once
 * (an axis the box wraps over is scanned whole): per axis a first cell and a
 * span. */
typedef struct {
    size_t first[3], span[3];
} box_;

static box_ box_of(const mcs_blue_grid_ *g, const double *p, size_t reach, int *whole)
{
    box_ b = {{0u, 0u, 0u}, {1u, 1u, 1u}};
    *whole = 1;
    for (size_t c = 0; c < g->dim; ++c) {
        if (2u * reach + 1u >= g->m) {
            b.first[c] = 0u;
            b.span[c] = g->m;
        } else {
            b.first[c] = (axis_cell(g, p[c]) + g->m - reach) % g->m;
            b.span[c] = 2u * reach + 1u;
            *whole = 0;
        }
    }
    return b;
}

/* Visits the points of box b: returns 1 as soon as one is closer than
 * sqrt(stop2) (conflict search), else keeps the nearest in *best2, *index. */
static int scan_box(const mcs_blue_grid_ *g, const box_ *b, const double *p, double stop2,
                    double *best2, uint32_t *index)
{
    size_t off[3] = {0u, 0u, 0u};
    for (;;) {
        size_t cell = 0u;
        for (size_t c = g->dim; c-- > 0;)
            cell = cell * g->m + (b->first[c] + off[c]) % g->m;
        for (uint32_t i = g->head[cell]; i != MCS_BLUE_NONE; i = g->next[i]) {
            const double d2 = mcs_blue_torus_d2_(g->dim, p, g->pts + (size_t)i * g->dim);
            if (d2 < stop2)
                return 1;
            if (d2 < *best2) {
                *best2 = d2;
                *index = i;
            }
        }
        size_t c = 0u;
        while (c < g->dim && ++off[c] == b->span[c])
            off[c++] = 0u;
        if (c == g->dim)
            return 0;
    }
}

int mcs_blue_grid_conflict_(const mcs_blue_grid_ *g, const double *p, double r)
{
    /* Every point within r is within reach cells on each axis: reach / m >= r
     * with room for the rounding of floor(x m). */
    const size_t reach = (size_t)(r * (double)g->m * (1.0 + REACH_MARGIN)) + 1u;
    int whole = 0;
    const box_ b = box_of(g, p, reach, &whole);
    double best2 = HUGE_VAL;
    uint32_t index = MCS_BLUE_NONE;
    return scan_box(g, &b, p, r * r, &best2, &index);
}

double mcs_blue_grid_nearest_(const mcs_blue_grid_ *g, const double *p, uint32_t *index)
{
    double best2 = HUGE_VAL;
    *index = MCS_BLUE_NONE;
    if (g->count == 0u)
        return best2;
    for (size_t reach = 0;; ++reach) {
        int whole = 0;
        const box_ b = box_of(g, p, reach, &whole);
        (void)scan_box(g, &b, p, -1.0, &best2, index);
        /* A point outside the box is at least reach / m away. */
        const double bound = (double)reach / (double)g->m;
        if (whole || best2 <= bound * bound * (1.0 - REACH_MARGIN))
            return best2;
    }
}
