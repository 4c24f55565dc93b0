/* The exact expectations of the spacing statistics for independent uniform
 * points on the unit torus (spacing.h, mcs_spacing_exact_random).
 *
 * Average minimum distance. By translation invariance every point's nearest
 * distance R has the law of the distance from 0 to the nearest of K - 1
 * independent uniform points, P(R > r) = (1 - A(r))^(K-1), A(r) the area of
 * the toroidal disk of radius r (the disk cut by the square [-1/2, 1/2]^2),
 * so E R = int_0^rmax (1 - A(r))^(K-1) dr, and the mean over the K points
 * has the same expectation.
 *   1D: A = 2 r up to 1/2, E R = 1/(2K).
 *   2D: A = pi r^2 up to 1/2; beyond, up to rmax = sqrt(2)/2, the disk less
 *       four segments, A = pi r^2 - 4 (r^2 acos(1/(2r)) - sqrt(r^2 - 1/4)/2).
 *       int_0^{1/sqrt(pi)} (1 - pi r^2)^(K-1) dr = Gamma(K) / (2 Gamma(K + 1/2))
 *       (y = pi r^2: a complete beta function B(1/2, K) / (2 sqrt(pi))), so
 *       E R = Gamma(K) / (2 Gamma(K + 1/2))
 *             - int_{1/2}^{1/sqrt(pi)} (1 - pi r^2)^(K-1) dr
 *             + int_{1/2}^{rmax} (1 - A(r))^(K-1) dr,
 *       the last two, both below (1 - pi/4)^(K-1) / 4, by tanh-sinh
 *       quadrature (its nodes crowd at the ends, where (r - 1/2)^(3/2) and
 *       the corners make A not smooth).
 *   3D to 8D: the same with the ball, A = V_d r^d up to r = 1/2, gives
 *       E R = V_d^(-1/d) Gamma(1 + 1/d) Gamma(K) / Gamma(K + 1/d) + c, where
 *       c, the part past r = 1/2 (ball less torus), is at most
 *       (sqrt(d)/2 - 1/2) (1 - V_d / 2^d)^(K-1) in size. The ball cut by the
 *       cube has no short closed form, so the value is given only for K
 *       large enough that this bound is below 2^-53 of the value (K >= 52 in
 *       3D, 104 in 4D, 212, 450, 1007 and 2370 in 5D to 8D).
 * Minimum distance in 1D: the K gaps between neighbours on the circle are
 * Dirichlet(1, ..., 1); the least of them, which is the least toroidal
 * distance (it is at most 1/K <= 1/2), has E = 1/K^2.
 * Both are then divided by d_max (1/K in 1D, sqrt(2 / (sqrt(3) K)) in 2D),
 * as the accumulator's values are. */
#include "mcspec/spacing.h"
#include "measures_internal.h"

#include <math.h>
#include <stddef.h>

static const double pi = 3.14159265358979323846;

/* V_d, the volume of the unit ball, and Gamma(1 + 1/d), d = 1..8 (to 17
 * digits; no tgamma, which not every embedded libm has). */
static const double ball_volume[9] = {0.0, 2.0, 3.1415926535897932385, 4.1887902047863909846,
                                      4.9348022005446793094, 5.2637890139143245967,
                                      5.1677127800499700292, 4.7247659703314011696,
                                      4.0587121264167682182};
static const double gamma_1a[9] = {0.0, 1.0, 0.88622692545275801365, 0.89297951156924921122,
                                   0.90640247705547707798, 0.91816874239976061064,
                                   0.92771933363003920071, 0.93543756289254634824,
                                   0.94174269984970148809};

/* Stirling's series of ln Gamma less its leading terms: S(z) = 1/(12 z) -
 * 1/(360 z^3) + 1/(1260 z^5) - 1/(1680 z^7) (the next term, 1/(1188 z^9),
 * is below 1e-19 at z = 64). */
static double stirling_tail(double z)
{
    return 1.0 / (12.0 * z) - 1.0 / (360.0 * z * z * z) + 1.0 / (1260.0 * pow(z, 5.0)) -
           1.0 / (1680.0 * pow(z, 7.0));
}

/* Gamma(K) / Gamma(K + a) for a = 1/d: by the recurrence from Gamma(1) /
 * Gamma(1 + a) up to K = 64 (about 64 u of rounding), beyond by the
 * difference of Stirling's series, written so that nothing of size K ln K
 * cancels: ln ratio = -(K - 1/2) log1p(a/K) - a ln(K + a) + a + S(K) - S(K + a). */
static double gamma_ratio(size_t k, size_t dim)
{
    const double a = 1.0 / (double)dim;
    if (k <= 64u) {
        double r = 1.0 / gamma_1a[dim];
        for (size_t j = 1; j < k; ++j)
            r *= (double)j / ((double)j + a);
        return r;
    }
    const double z = (double)k, y = z + a;
    return exp(-(z - 0.5) * log1p(a / z) - a * log(y) + a + (stirling_tail(z) - stirling_tail(y)));
}

/* 1 - A(r) of the 2D toroidal disk, r in [1/2, sqrt(2)/2] (never below 0). */
static double uncovered(double r)
{
    const double s = r * r - 0.25, seg = r * r * acos(0.5 / r) - 0.5 * sqrt(s > 0.0 ? s : 0.0);
    const double a = 1.0 - (pi * r * r - 4.0 * seg);
    return a > 0.0 ? a : 0.0;
}

/* (1 - A)^(K-1) or (1 - pi r^2)^(K-1) at r. */
static double tail_integrand(int disk_only, double r, double km1)
{
    const double base = disk_only ? 1.0 - pi * r * r : uncovered(r);
    return base > 0.0 ? pow(base, km1) : 0.0;
}

/* int_a^b by tanh-sinh: r = c + h tanh(pi/2 sinh t), t = j / 32, |t| <= 4;
 * the distance to the near end, h (1 - tanh), is formed without
 * cancellation, so nodes reach the ends' singularities. */
static double tanh_sinh(int disk_only, double a, double b, double km1)
{
    const double c = 0.5 * (a + b), h = 0.5 * (b - a), step = 1.0 / 32.0;
    double sum = 0.5 * pi * tail_integrand(disk_only, c, km1);
    for (int j = 1; j <= 128; ++j) {
        const double t = step * (double)j, u = 0.5 * pi * sinh(t), e = exp(-2.0 * u);
        const double gap = h * 2.0 * e / (1.0 + e); /* h (1 - tanh u) */
        const double ch = cosh(u), w = 0.5 * pi * cosh(t) / (ch * ch);
        sum += w * (tail_integrand(disk_only, a + gap, km1) + tail_integrand(disk_only, b - gap, km1));
    }
    return sum * h * step;
}

/* The ball's part of E R, V_d^(-1/d) Gamma(1 + 1/d) Gamma(K) / Gamma(K + 1/d). */
static double nearest_ball(size_t dim, size_t k)
{
    return pow(ball_volume[dim], -1.0 / (double)dim) * gamma_1a[dim] * gamma_ratio(k, dim);
}

/* E R in 2D (the header's formula). */
static double nearest_2d(size_t k)
{
    const double km1 = (double)(k - 1u), main = nearest_ball(2u, k);
    const double disk = tanh_sinh(1, 0.5, 1.0 / sqrt(pi), km1);
    const double torus = tanh_sinh(0, 0.5, sqrt(0.5), km1);
    return main - disk + torus;
}

/* The bound on the part of E R past r = 1/2 in dim >= 3 dimensions. */
static double past_half_bound(size_t dim, size_t k)
{
    const double cap = 1.0 - ball_volume[dim] / ldexp(1.0, (int)dim);
    return (0.5 * sqrt((double)dim) - 0.5) * pow(cap, (double)(k - 1u));
}

mcs_status mcs_spacing_exact_random(mcs_spacing_statistic statistic, size_t dim, size_t k,
                                    double *out)
{
    if (out == NULL)
        return MCS_ERR_NULL;
    if ((unsigned)statistic >= (unsigned)MCS_SPACING_STATISTICS)
        return MCS_ERR_KIND;
    if (dim < 1u || dim > (size_t)MCS_SPACING_MAX_DIM)
        return MCS_ERR_DOMAIN;
    if (k < 2u)
        return MCS_ERR_K_RANGE;
    const int avg = statistic == MCS_SPACING_AVG_MIN_DISTANCE;
    if (dim >= 2u && !avg)
        return MCS_ERR_DOMAIN;
    const double ball = dim >= 3u ? nearest_ball(dim, k) : 0.0;
    if (dim >= 3u && !(past_half_bound(dim, k) <= 0x1p-53 * ball))
        return MCS_ERR_DOMAIN;
    double dmax = 0.0;
    mcs_status st = mcs_spacing_packing_distance(dim, k, &dmax);
    if (st != MCS_OK)
        return st;
    const double kk = (double)k;
    const double e = dim == 1u ? (avg ? 0.5 / kk : 1.0 / (kk * kk)) : dim == 2u ? nearest_2d(k) : ball;
    *out = e / dmax;
    return MCS_OK;
}
