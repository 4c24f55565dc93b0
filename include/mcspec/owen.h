/* The exact expected periodogram of Owen-scrambled (nested uniform
 * scrambled) point sets, in 1D and in any 2D projection of a d-dimensional
 * set (docs/owen.md derives every formula here).
 *
 * Under nested uniform scrambling in base b (Owen 1995) two coordinates
 * whose unscrambled values share exactly l leading base-b digits become
 * x = (A + (p + U) / b) / b^l and y = (A + (q + V) / b) / b^l with A uniform
 * on 0..b^l - 1, (p, q) a uniform pair of distinct digits and U, V uniform on
 * [0, 1), all independent, and independent across coordinates. So for a
 * scrambled set of K points
 *     E P(k) = 1 + (1/K) sum_{j != j'} prod_d phi_b(l_d(j, j'), k_d),
 *     phi_b(l, k) = E e^{-2 pi i k (x - y)}
 *                 = (b sinc^2(pi k / b^l) - sinc^2(pi k / b^(l+1))) / (b - 1)
 * (sinc x = sin x / x; phi = 1 for equal coordinates), and only the number
 * N(l_x, l_y) of pairs per level vector is needed:
 *  - any set (mcs_owen_init): counted from the unscrambled points, O(K^2),
 *    into the caller's work array; then mcs_owen_power is O(L^2);
 *  - a (0,m,2)-net in base b (mcs_owen_net_power): the net property alone
 *    fixes N (docs/owen.md), O(m^2) per wave vector, no points needed.
 * In 1D a (0,m,1)-net (K = b^m points of a van der Corput set) gives
 * 1 - sinc^2(pi k / K), the stratified pattern's spectrum.
 *
 *     static uint64_t work[MCS_OWEN_LEN_MAX];
 *     mcs_owen ow;
 *     const size_t axes[2] = {0, 1};
 *     const unsigned bases[2] = {2, 3};
 *     mcs_owen_init(&ow, k, dim, points, 2, axes, bases, work, MCS_OWEN_LEN_MAX);
 *     mcs_owen_power(&ow, 3, -2, &p);     E P(3, -2) of the scrambled set
 *
 * Digits. Coordinate d in base b is read as its nearest L-digit base-b
 * fraction, L the largest with b^L <= 2^44 (44 digits in base 2, 27 in base
 * 3): exact for the double values of a digital set of up to L digits (within
 * 2^-44 b^L of such a fraction). Two coordinates equal in all L digits count
 * as equal (phi = 1): scrambling maps equal digits to equal values.
 *
 * Every call validates its inputs before writing: on error nothing changes.
 * Nothing allocates. */
#ifndef MCSPEC_OWEN_H
#define MCSPEC_OWEN_H

#include <stddef.h>
#include <stdint.h>
#include "status.h"
#include "sampler.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest base (bases are 2..MCS_OWEN_MAX_BASE), the digits kept in base 2
 * (the most of any base: b^L <= 2^44), the largest set (K^2 / 2 pairs stay
 * exact in a uint64), and the largest |frequency| of a read-out. */
#define MCS_OWEN_MAX_BASE 256u
#define MCS_OWEN_MAX_DIGITS 44u
#define MCS_OWEN_MAX_K 4294967295u
#define MCS_OWEN_MAX_FREQ 1073741824L /* 2^30 */

/* uint64 entries of work memory the largest projection needs (two base-2
 * axes): (L + 1)^2 pair counts and L + 1 powers of the base per axis. A
 * constant expression, for a static array; mcs_owen_len gives the exact
 * need of given bases. */
#define MCS_OWEN_LEN_MAX                                                              \
    (((size_t)MCS_OWEN_MAX_DIGITS + 1u) * ((size_t)MCS_OWEN_MAX_DIGITS + 1u) +         \
     2u * ((size_t)MCS_OWEN_MAX_DIGITS + 1u))

/* Set up by mcs_owen_init; read-only to the caller. */
typedef struct {
    size_t dims;         /* 1 or 2: the projection's axes (0: not set up) */
    size_t axis[2];      /* the coordinates of the points projected on (axis[1] = 0 in 1D) */
    unsigned base[2];    /* their bases (base[1] = 0 in 1D) */
    unsigned digits[2];  /* L per axis: digits kept (digits[1] = 0 in 1D) */
    size_t k;            /* points K, 1..MCS_OWEN_MAX_K */
    uint64_t *pairs;     /* N(l_x, l_y) at pairs[l_x (digits[1] + 1) + l_y], l_d = 0..L_d in the
                            caller's work array: unordered pairs whose coordinates share exactly l_d
                            leading digits (l_d = L_d: all, equal); they sum to K (K - 1) / 2 */
} mcs_owen;

/* Digits L kept in base base (the largest L with base^L <= 2^44) into
 * *digits. MCS_ERR_NULL, MCS_ERR_DOMAIN (base outside 2..MCS_OWEN_MAX_BASE).
 * *digits untouched on error. */
mcs_status mcs_owen_digits(unsigned base, unsigned *digits);

/* uint64 entries of work memory mcs_owen_init needs for a projection on
 * dims axes (1 or 2) of bases bases[dims]: (L_x + 1)(L_y + 1) counts (L_y =
 * 0 in 1D) and L_d + 1 powers per axis, into *len (at most
 * MCS_OWEN_LEN_MAX). MCS_ERR_NULL, MCS_ERR_DOMAIN (dims not 1 or 2, a base
 * outside 2..MCS_OWEN_MAX_BASE). *len untouched on error. */
mcs_status mcs_owen_len(size_t dims, const unsigned *bases, size_t *len);

/* Counts the pairs of the k points points[k * dim] (interleaved: coordinate
 * c of point j is points[dim j + c]; unscrambled, as the digital
 * construction gives them) per level vector of their projection on the dims
 * axes axes[dims] (each < dim, distinct: coordinates of one point are not
 * scrambled independently), coordinate axes[d] in base bases[d]; into
 * work[len], len at least what mcs_owen_len reports (that many entries
 * written; the first (L_x + 1)(L_y + 1) are the counts the read-outs use,
 * and they must stay as init left them). Only the projected coordinates are
 * read (each in [0, 1)); points is not kept. O(K^2 dims) (about 0.1 s at
 * K = 4096 in base 2). MCS_ERR_NULL, MCS_ERR_K_RANGE (k = 0 or above
 * MCS_OWEN_MAX_K), MCS_ERR_DOMAIN (dims not 1 or 2, dim = 0 or k dim
 * overflowing, an axis >= dim or two axes equal, a base outside
 * 2..MCS_OWEN_MAX_BASE), MCS_ERR_SPACE (len too small), MCS_ERR_POINT_RANGE
 * (a projected coordinate outside [0, 1) or NaN), MCS_ERR_ALIAS (*ow or work
 * overlapping each other or points, axes or bases). On error neither *ow nor
 * work changes. */
mcs_status mcs_owen_init(mcs_owen *ow, size_t k, size_t dim, const double *points, size_t dims,
                         const size_t *axes, const unsigned *bases, uint64_t *work, size_t len);

/* The read-outs of a set-up object: MCS_ERR_NULL, MCS_ERR_UNINIT (ow not set
 * up by mcs_owen_init), MCS_ERR_INVARIANT (the counts no longer sum to
 * K (K - 1) / 2: the work array was written since), as stated; outputs
 * untouched on error. */

/* E P(freq_x, freq_y) of the scrambled set (above; in 1D freq_y must be 0).
 * P(0) = K exactly. O(L_x L_y). MCS_ERR_FREQ_RANGE (|freq| above
 * MCS_OWEN_MAX_FREQ, or freq_y != 0 in 1D). */
mcs_status mcs_owen_power(const mcs_owen *ow, long freq_x, long freq_y, double *out);

/* N(level_x, level_y) of the set (level_y = 0 in 1D): unordered pairs whose
 * coordinates share exactly level_d leading digits (level_d = L_d: equal).
 * MCS_ERR_DOMAIN (a level above its axis's L). */
mcs_status mcs_owen_pair_count(const mcs_owen *ow, size_t level_x, size_t level_y, uint64_t *out);

/* phi_b(level, freq) (above) into *out: the characteristic function at
 * integer freq of x - y for two scrambled coordinates sharing exactly level
 * leading digits in base base. Exact to rounding (sin^2 takes freq mod
 * b^l). MCS_ERR_NULL, MCS_ERR_DOMAIN (base outside 2..MCS_OWEN_MAX_BASE, or
 * level >= L of the base), MCS_ERR_FREQ_RANGE (|freq| > MCS_OWEN_MAX_FREQ). */
mcs_status mcs_owen_phi(unsigned base, size_t level, long freq, double *out);

/* N(level_x, level_y) of any (0,m,2)-net in base base (K = b^m points), from
 * the net property alone: the ordered pairs sharing at least a digits in x
 * and c in y are K (b^(m-a-c) - 1) for a + c <= m and 0 beyond, and N is
 * their second difference (docs/owen.md); nonzero only for
 * level_x + level_y < m. Unordered pairs into *out. MCS_ERR_NULL,
 * MCS_ERR_DOMAIN (base outside 2..MCS_OWEN_MAX_BASE), MCS_ERR_K_RANGE
 * (base^m above MCS_OWEN_MAX_K). Any levels are accepted. */
mcs_status mcs_owen_net_pairs(unsigned base, size_t m, size_t level_x, size_t level_y,
                              uint64_t *out);

/* E P(freq_x, freq_y) of an Owen-scrambled (0,m,2)-net in base base from
 * those counts, O(m^2), no points needed (freq_y = 0: its 1D projection, a
 * (0,m,1)-net, 1 - sinc^2(pi freq_x / b^m)); P(0) = K. Statuses as
 * mcs_owen_net_pairs, and MCS_ERR_FREQ_RANGE (|freq| > MCS_OWEN_MAX_FREQ). */
mcs_status mcs_owen_net_power(unsigned base, size_t m, long freq_x, long freq_y, double *out);

/* Which exact theory gives a sampler's expected periodogram. */
typedef enum {
    MCS_OWEN_THEORY_NONE = 0,   /* none known: the command prints "no exact theory" */
    MCS_OWEN_THEORY_PHASE = 1,  /* randomised by one phase per axis (a rotation or a shift):
                                   the periodogram of mcs_sampler_base_points is exact */
    MCS_OWEN_THEORY_NESTED = 2  /* nested uniform scrambling: mcs_owen_init on the
                                   base points (any K), or mcs_owen_net_power at K = 2^m */
} mcs_owen_theory;

/* The exact theory of sampler kind in dim dimensions into *out: Sobol (2D
 * and any-dimension) and Owen-scrambled Halton are NESTED (bases 2, 2 and 2,
 * 3, ... per axis); van der Corput, Halton, Hammersley, Kronecker and the
 * lattice PHASE; permuted Halton and padded NONE (permuted digits are not
 * nested; a padded set's pairs are independent Sobol pairs). MCS_ERR_NULL, MCS_ERR_KIND (unknown kind, or kind
 * not defined in dim, as mcs_sampler_init). *out untouched on error. */
mcs_status mcs_owen_theory_of(mcs_sampler_kind kind, size_t dim, mcs_owen_theory *out);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_OWEN_H */
