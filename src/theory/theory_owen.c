/* The exact expected periodogram of Owen-scrambled point sets (owen.h;
 * docs/owen.md derives it): phi_b(l, k), the pair counts per level vector of
 * any set (from its unscrambled points) and of a (0,m,2)-net (from the net
 * property), and E P(k) = 1 + (2/K) sum_levels N(l) prod_d phi(l_d, k_d)
 * over unordered pairs. */
#include "core/internal.h"
#include "mcspec/owen.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define POW_LIMIT ((uint64_t)1 << 44) /* b^L <= 2^44: the digits kept */

static int base_ok(unsigned base) { return base >= 2u && base <= MCS_OWEN_MAX_BASE; }

/* 1 <= k <= MCS_OWEN_MAX_K, written so a 32-bit size_t raises no
 * always-false comparison. */
static int k_ok(size_t k) { return k >= 1u && (uint64_t)k - 1u < (uint64_t)MCS_OWEN_MAX_K; }

/* L of a base in range: the largest L with b^L <= 2^44. */
static unsigned digits_of(unsigned base)
{
    unsigned l = 0;
    for (uint64_t p = base; p <= POW_LIMIT; p *= base)
        ++l;
    return l;
}

mcs_status mcs_owen_digits(unsigned base, unsigned *digits)
{
    if (digits == NULL)
        return MCS_ERR_NULL;
    if (!base_ok(base))
        return MCS_ERR_DOMAIN;
    *digits = digits_of(base);
    return MCS_OK;
}

static size_t abs_freq(long f) { return f < 0 ? (size_t)(-(f + 1)) + 1u : (size_t)f; }

/* sinc^2(pi f / n), n = b^l >= 1 an exact integer: sin^2 has period n in f,
 * so the sine takes f mod n and stays accurate for large f. */
static double sinc2(size_t f, uint64_t n)
{
    if (f == 0u)
        return 1.0;
    const double s = sin(MCS_TWO_PI * 0.5 * (double)((uint64_t)f % n) / (double)n);
    const double a = MCS_TWO_PI * 0.5 * (double)f / (double)n;
    return (s * s) / (a * a);
}

/* phi_b(l, f) with n = b^l: x - y = (D + U - V) / b^(l+1), D the difference
 * of a uniform pair of distinct digits, U and V uniform: E e^{-2 pi i f D /
 * b^(l+1)} = (|sum_p z^p|^2 - b) / (b (b - 1)) and |E e^{-2 pi i f U / b^(l+1)}|^2
 * = sinc^2(pi f / b^(l+1)); their product simplifies to the difference below
 * (docs/owen.md), which has no 0/0. */
static double phi_at(unsigned base, uint64_t n, size_t f)
{
    const double b = (double)base;
    return (b * sinc2(f, n) - sinc2(f, n * base)) / (b - 1.0);
}

mcs_status mcs_owen_phi(unsigned base, size_t level, long freq, double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    if (!base_ok(base) || level >= digits_of(base))
        return MCS_ERR_DOMAIN;
    const size_t f = abs_freq(freq);
    if (f > (size_t)MCS_OWEN_MAX_FREQ)
        return MCS_ERR_FREQ_RANGE;
    uint64_t n = 1u;
    for (size_t l = 0; l < level; ++l)
        n *= base;
    *out = phi_at(base, n, f);
    return MCS_OK;
}

/* ---- counts of any set ---- */

mcs_status mcs_owen_len(size_t dims, const unsigned *bases, size_t *len)
{
    if (bases == NULL || len == NULL)
        return MCS_ERR_NULL;
    if (dims != 1u && dims != 2u)
        return MCS_ERR_DOMAIN;
    for (size_t d = 0; d < dims; ++d)
        if (!base_ok(bases[d]))
            return MCS_ERR_DOMAIN;
    const size_t lx = digits_of(bases[0]), ly = dims == 2u ? digits_of(bases[1]) : 0u;
    *len = (lx + 1u) * (ly + 1u) + (lx + 1u) + (dims == 2u ? ly + 1u : 0u);
    return MCS_OK;
}

/* The L-digit base-b integer nearest to x b^L (x in [0, 1)), pw_l = b^L. */
static uint64_t digits_int(double x, uint64_t pw_l)
{
    const uint64_t u = (uint64_t)(x * (double)pw_l + 0.5);
    return u < pw_l ? u : pw_l - 1u;
}

/* Bits of a nonzero x (its bit length). */
static unsigned bit_length(uint64_t x)
{
    unsigned n = 0;
    for (unsigned s = 32; s > 0u; s /= 2u)
        if (x >> s != 0u) {
            x >>= s;
            n += s;
        }
    return n + (x != 0u);
}

/* Leading digits u and v (L digits each) share: L minus the fewest trailing
 * digits whose removal makes them equal (a binary search over pw = b^0..b^L;
 * in base 2 the bit length of u ^ v). */
static unsigned shared_digits(uint64_t u, uint64_t v, unsigned base, unsigned l,
                              const uint64_t *pw)
{
    if (u == v)
        return l;
    if (base == 2u)
        return l - bit_length(u ^ v);
    unsigned lo = 1u, hi = l; /* u / b^L = v / b^L = 0 */
    while (lo < hi) {
        const unsigned mid = (lo + hi) / 2u;
        if (u / pw[mid] == v / pw[mid])
            hi = mid;
        else
            lo = mid + 1u;
    }
    return l - lo;
}

static mcs_status check_init(const mcs_owen *ow, size_t k, size_t dim, const double *points,
                             size_t dims, const size_t *axes, const unsigned *bases,
                             const uint64_t *work, size_t len)
{
    if (ow == NULL || points == NULL || axes == NULL || bases == NULL || work == NULL)
        return MCS_ERR_NULL;
    size_t need = 0;
    mcs_status st = mcs_owen_len(dims, bases, &need);
    if (st != MCS_OK)
        return st;
    if (!k_ok(k))
        return MCS_ERR_K_RANGE;
    if (dim == 0u || k > SIZE_MAX / dim || (dims == 2u && axes[0] == axes[1]))
        return MCS_ERR_DOMAIN;
    for (size_t d = 0; d < dims; ++d)
        if (axes[d] >= dim)
            return MCS_ERR_DOMAIN;
    if (len < need)
        return MCS_ERR_SPACE;
    const size_t wb = mcs_bytes_(len, sizeof *work), pb = mcs_bytes_(k * dim, sizeof *points);
    const size_t ab = dims * sizeof *axes, bb = dims * sizeof *bases;
    if (mcs_overlap_(work, wb, ow, sizeof *ow) || mcs_overlap_(work, wb, points, pb) ||
        mcs_overlap_(work, wb, axes, ab) || mcs_overlap_(work, wb, bases, bb) ||
        mcs_overlap_(ow, sizeof *ow, points, pb) || mcs_overlap_(ow, sizeof *ow, axes, ab) ||
        mcs_overlap_(ow, sizeof *ow, bases, bb))
        return MCS_ERR_ALIAS;
    for (size_t j = 0; j < k; ++j)
        for (size_t d = 0; d < dims; ++d) {
            const double x = points[dim * j + axes[d]];
            if (!(x >= 0.0 && x < 1.0))
                return MCS_ERR_POINT_RANGE;
        }
    return MCS_OK;
}

/* Per axis: its base, L, b^0..b^L (in work) and the coordinate's column. */
typedef struct {
    unsigned base, digits;
    const uint64_t *pw;
    size_t col;
} axis_digits;

static void count_pairs(size_t k, size_t dim, const double *points, size_t dims,
                        const axis_digits *ax, uint64_t *pairs)
{
    const size_t stride = dims == 2u ? (size_t)ax[1].digits + 1u : 1u;
    const uint64_t top0 = ax[0].pw[ax[0].digits], top1 = dims == 2u ? ax[1].pw[ax[1].digits] : 1u;
    for (size_t j = 0; j < k; ++j) {
        const uint64_t u0 = digits_int(points[dim * j + ax[0].col], top0);
        const uint64_t u1 = dims == 2u ? digits_int(points[dim * j + ax[1].col], top1) : 0u;
        for (size_t i = j + 1u; i < k; ++i) {
            const uint64_t v0 = digits_int(points[dim * i + ax[0].col], top0);
            size_t at = shared_digits(u0, v0, ax[0].base, ax[0].digits, ax[0].pw) * stride;
            if (dims == 2u)
                at += shared_digits(u1, digits_int(points[dim * i + ax[1].col], top1), ax[1].base,
                                    ax[1].digits, ax[1].pw);
            ++pairs[at];
        }
    }
}

mcs_status mcs_owen_init(mcs_owen *ow, size_t k, size_t dim, const double *points, size_t dims,
                         const size_t *axes, const unsigned *bases, uint64_t *work, size_t len)
{
    mcs_status st = check_init(ow, k, dim, points, dims, axes, bases, work, len);
    if (st != MCS_OK)
        return st;
    axis_digits ax[2] = {{2u, 0u, NULL, 0u}, {2u, 0u, NULL, 0u}};
    size_t cells = 1u;
    for (size_t d = 0; d < dims; ++d) {
        ax[d].base = bases[d];
        ax[d].digits = digits_of(bases[d]);
        ax[d].col = axes[d];
        cells *= (size_t)ax[d].digits + 1u;
    }
    uint64_t *pw = work + cells;
    for (size_t d = 0; d < dims; ++d) {
        ax[d].pw = pw;
        pw[0] = 1u;
        for (unsigned l = 1; l <= ax[d].digits; ++l)
            pw[l] = pw[l - 1u] * ax[d].base;
        pw += ax[d].digits + 1u;
    }
    memset(work, 0, cells * sizeof *work);
    count_pairs(k, dim, points, dims, ax, work);
    mcs_owen set;
    memset(&set, 0, sizeof set);
    set.dims = dims;
    set.k = k;
    set.pairs = work;
    for (size_t d = 0; d < dims; ++d) {
        set.axis[d] = axes[d];
        set.base[d] = bases[d];
        set.digits[d] = ax[d].digits;
    }
    *ow = set;
    return MCS_OK;
}

/* A set-up object: its fields as init leaves them (else UNINIT) and counts
 * summing to K (K - 1) / 2 (else INVARIANT). O(L^2). */
static mcs_status check_set(const mcs_owen *ow, const void *out)
{
    if (ow == NULL || out == NULL)
        return MCS_ERR_NULL;
    if ((ow->dims != 1u && ow->dims != 2u) || !k_ok(ow->k) || ow->pairs == NULL)
        return MCS_ERR_UNINIT;
    for (size_t d = 0; d < 2u; ++d) {
        const int on = d < ow->dims;
        if (on ? !base_ok(ow->base[d]) || ow->digits[d] != digits_of(ow->base[d])
               : ow->base[d] != 0u || ow->digits[d] != 0u)
            return MCS_ERR_UNINIT;
    }
    const size_t cells = ((size_t)ow->digits[0] + 1u) * ((size_t)ow->digits[1] + 1u);
    const uint64_t kk = ow->k, total = kk * (kk - 1u) / 2u;
    uint64_t sum = 0;
    for (size_t c = 0; c < cells; ++c) {
        if (ow->pairs[c] > total - sum)
            return MCS_ERR_INVARIANT;
        sum += ow->pairs[c];
    }
    return sum == total ? MCS_OK : MCS_ERR_INVARIANT;
}

/* E P = 1 + 2 sum / K cannot be negative; the sum's rounding (K^2 / 2 pair
 * terms of magnitude <= 1, a relative 1e-16 each) can take an exact zero
 * (a net at low frequencies: P = 1 - sinc^2 ~ 1e-9 and below) a few K eps
 * under it, which reads 0. */
static double nonneg(double v, double k)
{
    return v < 0.0 && v > -64.0 * k * DBL_EPSILON ? 0.0 : v;
}

/* phi[l] = phi_b(l, f) for l < L, and phi[L] = 1 (equal coordinates). */
static void phi_row(unsigned base, unsigned digits, size_t f, double *phi)
{
    uint64_t n = 1u;
    for (unsigned l = 0; l < digits; ++l, n *= base)
        phi[l] = phi_at(base, n, f);
    phi[digits] = 1.0;
}

mcs_status mcs_owen_power(const mcs_owen *ow, long freq_x, long freq_y, double *out)
{
    mcs_status st = check_set(ow, out);
    if (st != MCS_OK)
        return st;
    const size_t fx = abs_freq(freq_x), fy = abs_freq(freq_y);
    if (fx > (size_t)MCS_OWEN_MAX_FREQ || fy > (size_t)MCS_OWEN_MAX_FREQ ||
        (ow->dims == 1u && fy != 0u))
        return MCS_ERR_FREQ_RANGE;
    if (fx == 0u && fy == 0u)
        return mcs_set_(out, (double)ow->k);
    double px[MCS_OWEN_MAX_DIGITS + 1u];
    phi_row(ow->base[0], ow->digits[0], fx, px);
    const size_t ly = ow->digits[1];
    double sum = 0.0;
    uint64_t n = 1u;
    for (size_t c = 0; c <= ly; ++c, n *= ow->dims == 2u ? ow->base[1] : 1u) {
        double row = 0.0;
        for (size_t a = 0; a <= ow->digits[0]; ++a)
            row += (double)ow->pairs[a * (ly + 1u) + c] * px[a];
        sum += row * (c == ly ? 1.0 : phi_at(ow->base[1], n, fy));
    }
    return mcs_set_(out, nonneg(1.0 + 2.0 * sum / (double)ow->k, (double)ow->k));
}

mcs_status mcs_owen_pair_count(const mcs_owen *ow, size_t level_x, size_t level_y, uint64_t *out)
{
    mcs_status st = check_set(ow, out);
    if (st != MCS_OK)
        return st;
    if (level_x > ow->digits[0] || level_y > ow->digits[1])
        return MCS_ERR_DOMAIN;
    *out = ow->pairs[level_x * ((size_t)ow->digits[1] + 1u) + level_y];
    return MCS_OK;
}
