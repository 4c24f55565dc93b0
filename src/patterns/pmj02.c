/* Progressive multi-jittered (0,2) sequences, pmj02 and pmj02bn
 * (Christensen, Kensler and Kilpatrick 2018), with the valid strata
 * enumerated as Pharr (2019) does (bluenoise.h, docs/samplers.md).
 *
 * Coordinates are 53-bit binary fractions X / 2^53, so the stratum of a
 * point at every level is exact integer arithmetic. After 2^t points every
 * elementary interval of shape 2^-a x 2^-(t-a), a = 0..t, holds one point;
 * the occupancy of the 2^t cells of every shape is kept as bits. A new point
 * goes into a given subquadrant, a cell of the 2^h x 2^h grid, h = ceil(t/2).
 * The shapes with a >= h (at least h x bits, at most h y bits) see the point's
 * y only through the subquadrant, so they constrain x alone; the shapes with
 * t - a >= h constrain y alone. The valid positions are therefore a product:
 * the finest x strata X (t bits, inside the subquadrant) whose cells are free
 * in every shape a = h..t, times the finest y strata whose cells are free in
 * every shape a = 0..t-h, each list found by descending the binary tree of
 * strata and pruning at the first occupied cell (Pharr's observation). The
 * point is uniform in a uniformly chosen valid (X, Y) pair. */
#include "blue_internal.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#define FRAC_BITS 53u
#define TWO_M53 (1.0 / 9007199254740992.0)

/* The levels: 2^levels >= k > 2^(levels - 1) (0 for k = 1). */
static unsigned levels_of(size_t k)
{
    unsigned m = 0u;
    while (((size_t)1u << m) < k)
        ++m;
    return m;
}

static size_t occ_words(unsigned levels)
{
    return ((((size_t)levels + 1u) << levels) + 63u) / 64u;
}

static size_t list_len(unsigned levels)
{
    return ((size_t)1u << ((levels + 1u) / 2u)) + 1u;
}

size_t mcs_pmj02_work_bytes_(size_t k)
{
    const unsigned levels = levels_of(k);
    const size_t side = mcs_blue_grid_side_(2u, k);
    return 2u * mcs_blue_carve_bytes_(k, 8u) + mcs_blue_carve_bytes_(occ_words(levels), 8u) +
           2u * mcs_blue_carve_bytes_(list_len(levels), 4u) +
           mcs_blue_carve_bytes_(side * side, 4u) + mcs_blue_carve_bytes_(k, 4u) +
           mcs_blue_carve_bytes_(2u * k, 8u);
}

typedef struct {
    uint64_t *x, *y;   /* the points as 53-bit fractions */
    uint64_t *occ;     /* bit a 2^t + cell: shape a's cell is occupied */
    uint32_t *xs, *ys; /* the valid strata of the point being placed */
    size_t nx, ny;
    unsigned t;        /* the current level: 2^t points when it is complete */
    uint32_t candidates; /* per point: 1 for pmj02 */
    mcs_rng *rng;
    mcs_blue_grid_ grid; /* the points as doubles, for best candidates */
} pmj_;

/* Shape a's cell of finest strata (X, Y) at level t: the a top bits of X and
 * the t - a top bits of Y. */
static size_t cell_bit(unsigned t, unsigned a, uint64_t X, uint64_t Y)
{
    const size_t cell = (size_t)((Y >> a) << a | (X >> (t - a)));
    return ((size_t)a << t) + cell;
}

static int occupied(const pmj_ *s, size_t bit)
{
    return (int)((s->occ[bit >> 6] >> (bit & 63u)) & 1u);
}

static void mark(pmj_ *s, size_t i)
{
    const unsigned t = s->t;
    const uint64_t X = s->x[i] >> (FRAC_BITS - t), Y = s->y[i] >> (FRAC_BITS - t);
    for (unsigned a = 0; a <= t; ++a) {
        const size_t bit = cell_bit(t, a, X, Y);
        s->occ[bit >> 6] |= (uint64_t)1u << (bit & 63u);
    }
}

/* Level t begins: the shapes of 2^t points, the first `placed` marked. */
static void begin_level(pmj_ *s, unsigned t, size_t placed)
{
    s->t = t;
    const size_t words = occ_words(t);
    for (size_t w = 0; w < words; ++w)
        s->occ[w] = 0u;
    for (size_t i = 0; i < placed; ++i)
        mark(s, i);
}

/* The cell bit of the node (depth d below the subquadrant, prefix q) of
 * the x tree (y = 0: prefix of x, shape a = h + d, its y cell from
 * other, the subquadrant's h-bit y) or of the y tree (y = 1: prefix of y,
 * shape a = t - h - d, its x cell from other, the subquadrant's x). */
static size_t node_bit(const pmj_ *s, int y, unsigned h, unsigned d, uint64_t q, uint64_t other)
{
    const unsigned t = s->t;
    if (!y) {
        const unsigned a = h + d;
        return ((size_t)a << t) + (size_t)((other >> (h - (t - a))) << a | q);
    }
    const unsigned a = t - h - d;
    return ((size_t)a << t) + (size_t)(q << a | other >> (h - a));
}

/* The valid finest strata of one axis: a depth-first walk of the binary
 * tree of strata below the subquadrant (depth t - h), pruned at the first
 * occupied cell, leaves in increasing order; an explicit stack of at most
 * 2 (t - h) + 1 nodes. */
static size_t find_valid(const pmj_ *s, int y, unsigned h, uint64_t sx, uint64_t sy,
                         uint32_t *out)
{
    uint32_t stack_q[2u * 32u + 2u]; /* prefixes of at most t <= 24 bits */
    uint8_t stack_d[2u * 32u + 2u];
    size_t top = 0u, n = 0u;
    const unsigned depth = s->t - h;
    stack_q[top] = (uint32_t)(y ? sy : sx);
    stack_d[top++] = 0u;
    while (top > 0u) {
        --top;
        const uint32_t q = stack_q[top];
        const unsigned d = stack_d[top];
        if (occupied(s, node_bit(s, y, h, d, q, y ? sx : sy)))
            continue;
        if (d == depth) {
            out[n++] = (uint32_t)q;
            continue;
        }
        stack_q[top] = 2u * q + 1u; /* right below left: leaves come out in order */
        stack_d[top++] = (uint8_t)(d + 1u);
        stack_q[top] = 2u * q;
        stack_d[top++] = (uint8_t)(d + 1u);
    }
    return n;
}

/* Point i in subquadrant (sx, sy) of the 2^h grid: the best of `candidates`
 * uniform valid positions (farthest from the points so far; the first on a
 * tie), or the one position for candidates = 1. 0 if no stratum is valid. */
static int place(pmj_ *s, size_t i, unsigned h, uint64_t sx, uint64_t sy)
{
    const uint32_t candidates = s->candidates;
    mcs_rng *rng = s->rng;
    const unsigned t = s->t, low = FRAC_BITS - t;
    s->nx = find_valid(s, 0, h, sx, sy, s->xs);
    s->ny = find_valid(s, 1, h, sx, sy, s->ys);
    if (s->nx == 0u || s->ny == 0u)
        return 0;
    double best = -1.0;
    for (uint32_t c = 0; c < candidates; ++c) {
        const uint64_t X = s->xs[mcs_blue_bounded_(rng, (uint32_t)s->nx)];
        const uint64_t Y = s->ys[mcs_blue_bounded_(rng, (uint32_t)s->ny)];
        const uint64_t x = X << low | mcs_blue_bits_(rng, low);
        const uint64_t y = Y << low | mcs_blue_bits_(rng, low);
        double d2 = 0.0;
        if (candidates > 1u) {
            const double q[2] = {(double)x * TWO_M53, (double)y * TWO_M53};
            uint32_t near = MCS_BLUE_NONE;
            d2 = mcs_blue_grid_nearest_(&s->grid, q, &near);
        }
        if (d2 > best) {
            best = d2;
            s->x[i] = x;
            s->y[i] = y;
        }
    }
    mark(s, i);
    const double p[2] = {(double)s->x[i] * TWO_M53, (double)s->y[i] * TWO_M53};
    mcs_blue_grid_add_(&s->grid, p);
    return 1;
}

/* The subquadrant (h bits per axis) of point i. */
static uint64_t sub_x(const pmj_ *s, size_t i, unsigned h) { return s->x[i] >> (FRAC_BITS - h); }
static uint64_t sub_y(const pmj_ *s, size_t i, unsigned h) { return s->y[i] >> (FRAC_BITS - h); }

static void carve(pmj_ *s, size_t k, void *work)
{
    const unsigned levels = levels_of(k);
    const size_t side = mcs_blue_grid_side_(2u, k);
    mcs_blue_carver_ cv = {(unsigned char *)work, mcs_pmj02_work_bytes_(k)};
    s->x = mcs_blue_carve_(&cv, k, 8u);
    s->y = mcs_blue_carve_(&cv, k, 8u);
    s->occ = mcs_blue_carve_(&cv, occ_words(levels), 8u);
    s->xs = mcs_blue_carve_(&cv, list_len(levels), 4u);
    s->ys = mcs_blue_carve_(&cv, list_len(levels), 4u);
    s->grid.head = mcs_blue_carve_(&cv, side * side, 4u);
    s->grid.next = mcs_blue_carve_(&cv, k, 4u);
    s->grid.pts = mcs_blue_carve_(&cv, 2u * k, 8u);
    mcs_blue_grid_init_(&s->grid, 2u, k, k);
}

mcs_status mcs_pmj02_(size_t k, uint32_t candidates, mcs_rng *rng, void *work, double *points)
{
    pmj_ s;
    carve(&s, k, work);
    s.candidates = candidates;
    s.rng = rng;
    s.x[0] = mcs_blue_bits_(rng, FRAC_BITS);
    s.y[0] = mcs_blue_bits_(rng, FRAC_BITS);
    const double p0[2] = {(double)s.x[0] * TWO_M53, (double)s.y[0] * TWO_M53};
    mcs_blue_grid_add_(&s.grid, p0);
    size_t placed = 1u;
    int ok = 1;
    /* From n = 4^j points to 2n, then to 4n; the subquadrants are the cells
     * of the 2^(j+1) x 2^(j+1) grid at both steps. */
    for (unsigned j = 0; placed < k && ok; ++j) {
        const size_t n = (size_t)1u << (2u * j);
        const unsigned h = j + 1u;
        /* Even step: each point's diagonally opposite subquadrant, the
         * points visited in the order i xor r (a random xor shuffle). */
        begin_level(&s, 2u * j + 1u, placed);
        const size_t r = mcs_blue_bounded_(rng, (uint32_t)n);
        for (size_t i = 0; i < n && placed < k && ok; ++i, ++placed) {
            const size_t old = i ^ r;
            ok = place(&s, placed, h, sub_x(&s, old, h) ^ 1u, sub_y(&s, old, h) ^ 1u);
        }
        if (placed >= k || !ok)
            break;
        /* Odd step: each cell of the 2^j grid has two points in diagonal
         * subquadrants; one of the other two, chosen at random, gets point
         * 2n + i and the last one point 3n + i. */
        begin_level(&s, 2u * j + 2u, placed);
        const size_t r2 = mcs_blue_bounded_(rng, (uint32_t)n);
        for (size_t i = 0; i < n && placed < k && ok; ++i, ++placed) {
            const size_t old = i ^ r2;
            const int swap_x = mcs_blue_bounded_(rng, 2u) == 0u;
            ok = place(&s, placed, h, sub_x(&s, old, h) ^ (swap_x ? 1u : 0u),
                       sub_y(&s, old, h) ^ (swap_x ? 0u : 1u));
        }
        for (size_t i = 0; i < n && placed < k && ok; ++i, ++placed) {
            /* The fourth subquadrant of the cell of point 2n + i: diagonal to it. */
            const size_t third = 2u * n + i;
            ok = place(&s, placed, h, sub_x(&s, third, h) ^ 1u, sub_y(&s, third, h) ^ 1u);
        }
    }
    if (!ok)
        return MCS_ERR_INVARIANT;
    for (size_t i = 0; i < k; ++i) {
        points[2u * i] = (double)s.x[i] * TWO_M53;
        points[2u * i + 1u] = (double)s.y[i] * TWO_M53;
    }
    return MCS_OK;
}
