/* Integrand families with exact integrals, for the integration error of a
 * point set in [0,1)^d, d = 1 or 2 (docs/measures.md, "Integration error").
 * One integrand is drawn from a family with a seeded mcs_rng, so a family
 * of M integrands is reproducible from the seed; then it is evaluated, its
 * exact integral and variance read, the exact mean squared error of the
 * jittered grid computed, and, for the torus-periodic families, its Fourier
 * power |f^(k)|^2 and the error the point-set eq. 14 predicts from a
 * measured mean periodogram.
 *
 *   family             f(x)                                      random parameters
 *   gaussian           exp(-|x - c|^2 / (2 s^2)) on the square     c in [0,1)^d, s in [0.05, 0.25]
 *   gaussian_periodic  the same Gaussian periodised on the torus   as gaussian
 *                      (sum over the images c + n, n in Z^d)
 *   heaviside          2D: 1 where (x - p).u > 0 (a half-plane     p in [0,1)^2, u = (cos t, sin t),
 *                      across the square); 1D: 1 where x < p       t in [0, 2 pi); 1D: p in [0,1)
 *   disk               1 within toroidal distance r of c (a disk   c in [0,1)^d, r in [0.1, 0.4]
 *                      on the torus; 1D: an arc of length 2 r)
 *   cosine             prod_d (1 + a_d cos(2 pi m_d x_d + phi_d))  a_d in [0,1), m_d in 1..4,
 *                                                                  phi_d in [0, 2 pi)
 *   blinn_phong        utk's BlinnPhong (2D only): the estimate    p on the unit sphere, p_y <= -0.01;
 *                      S fr(o, l) cos(l) of the light a quad       o in the octant x, z >= 0, y <= 0;
 *                      sends to p, l(x) the direction that the     alpha in [10, 100]
 *                      area-preserving map of spherical
 *                      rectangles (Urena et al. 2013) gives x
 *   gaussian_mixture   utk's ClippedGaussianMixture: sum over      n boxes, n in 2d..2d^2; per box
 *                      boxes B_i of 1[x in B_i] exp(-(x - mu_i)^T  corners uniform, mu_i uniform in
 *                      A_i (x - mu_i) / 2)                         B_i, A_i^-1 of variances in
 *                                                                  [0.01, 1] on axes at a uniform angle
 *
 * Exact integrals (I) and integrals of f^2 (Q), per axis where separable:
 *   gaussian           I = prod s sqrt(pi/2) [erf((1 - c)/(s sqrt 2)) + erf(c/(s sqrt 2))],
 *                      Q = prod (s sqrt(pi) / 2) [erf((1 - c)/s) + erf(c/s)]
 *   gaussian_periodic  I = (s sqrt(2 pi))^d,
 *                      Q = prod s sqrt(pi) sum_n exp(-n^2 / (4 s^2))
 *   heaviside          I = Q = the area of the half-plane inside the square (clipped polygon)
 *   disk               I = Q = pi r^2 (2D), 2 r (1D) (r < 1/2: the disk never meets its images)
 *   cosine             I = 1, Q = prod (1 + a^2 / 2)
 *   blinn_phong        I, Q by nested adaptive Gauss-Kronrod (7, 15) over x_1 and x_2,
 *                      x_2 split where the light crosses the horizon (f has a kink)
 *   gaussian_mixture   1D: by erf; 2D: I = sum_i int_{B_i} g_i, Q = sum_{i,j} int_{B_i cap B_j}
 *                      g_i g_j (a product of Gaussians is one), each by erf over x_2 and
 *                      adaptive Gauss-Kronrod (7, 15) over x_1
 * Both quadratures stop when the sum over panels of |K15 - G7| is below 1e-13
 * of the result (a conservative estimate of the error for these smooth
 * panels; docs/measures.md gives the measured errors, below 1e-12 relative).
 * They run once, in mcs_integrand_draw, which keeps I and Q in the integrand.
 * Var[f(U)] = Q - I^2, so K independent uniform points integrate f with mean
 * squared error exactly (Q - I^2) / K.
 *
 * The jittered grid of m x n cells (one uniform point per cell, K = m n;
 * 1D: K = m cells): each cell C holds a point uniform in it, so
 *     MSE = (1/K^2) sum_C (K int_C f^2 - (K int_C f)^2),
 * exact from the integrals over each cell (not for blinn_phong and the 2D
 * gaussian_mixture, whose cells would each need a quadrature; the 1D
 * mixture's by erf per cell): per axis by erf for the
 * Gaussians (the periodised one over its images; a product of two images is
 * a Gaussian of width s / sqrt 2) and by sines for the cosines, where the
 * separable sum over cells factors into sums per axis (O(m + n)); the
 * clipped cell polygon for the Heaviside; the area of a disk over a
 * rectangle for the disk (its integral over the chord lengths, by pieces
 * between the points where the circle meets the rectangle's sides), summed
 * over the disk's images (O(K) cells for both).
 *
 * Fourier power on the torus, f^(k) = int f(x) e^{-2 pi i k.x} dx, defined
 * for the torus-periodic families only (gaussian_periodic, disk, cosine;
 * the others are not translation invariant on the torus, and eq. 14 does
 * not apply to them):
 *   gaussian_periodic  |f^(k)|^2 = (2 pi s^2)^d exp(-4 pi^2 s^2 |k|^2)
 *   disk               2D: (r J1(2 pi r |k|) / |k|)^2, (pi r^2)^2 at k = 0;
 *                      1D: (sin(2 pi k r) / (pi k))^2, (2 r)^2 at k = 0
 *   cosine             prod_d (1 at k_d = 0, a_d^2 / 4 at |k_d| = m_d, else 0)
 * J1 by its power series below x = 15 and its Hankel asymptotic series
 * above (absolute error below 1e-11). Evaluation of the periodised Gaussian
 * sums the images n = -3..3 per axis, the omitted ones below exp(-72) of the
 * peak.
 *
 * Prediction (the point-set form of eq. 14). For a family whose centre (or
 * phase) is uniform on the torus and drawn independently of the points,
 * the cross terms of E|sum_j f(x_j) - K I|^2 average out over the centre,
 * so for ANY point process (stationary or not, jittered too)
 *     E[err^2] = (1/K) sum_{k != 0} E|f^(k)|^2 <P(k)>,
 * P(k) = |sum_j e^{-2 pi i k.x_j}|^2 / K the periodogram. mcs_integrand_predict
 * sums it over the measured <P(k)> of a point-set accumulator for
 * 0 < |k|_inf <= F (truncated) and bounds what it leaves out: with p_tail a
 * bound on <P(k)> beyond F,
 *     tail = (p_tail / K) (Q - sum_{|k|_inf <= F} |f^(k)|^2)   (Parseval),
 * so the true E[err^2] lies in [predicted, predicted + tail]. p_tail is the
 * larger of 1 and the largest measured <P(k)> on the outermost shell
 * |k|_inf = F: exact for random points (<P> = 1) and the jittered grid
 * (<P> = 1 - sinc^2 sinc^2 <= 1), an assumption (stated, not proved) for
 * other patterns, whose <P> settles at 1 beyond their peak. The Parseval
 * difference carries rounding of about (number of terms) eps Q, which the
 * tail adds. */
#ifndef MCSPEC_INTEGRAND_H
#define MCSPEC_INTEGRAND_H

#include <stddef.h>
#include <stdint.h>
#include "status.h"
#include "rng.h"
#include "pointset.h"
#include "pointset2d.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Largest dimension of an integrand. */
#define MCS_INTEGRAND_MAX_DIM 2

/* Ranges of the random parameters (the table above). */
#define MCS_INTEGRAND_GAUSSIAN_MIN_WIDTH 0.05
#define MCS_INTEGRAND_GAUSSIAN_MAX_WIDTH 0.25
#define MCS_INTEGRAND_DISK_MIN_RADIUS 0.1
#define MCS_INTEGRAND_DISK_MAX_RADIUS 0.4
#define MCS_INTEGRAND_COSINE_MAX_FREQ 4
#define MCS_INTEGRAND_BLINN_PHONG_MIN_EXPONENT 10.0
#define MCS_INTEGRAND_BLINN_PHONG_MAX_EXPONENT 100.0
#define MCS_INTEGRAND_BLINN_PHONG_MIN_DEPTH 0.01 /* -p_y, the point's distance to the light's plane */
#define MCS_INTEGRAND_MIXTURE_MIN_VARIANCE 0.01
#define MCS_INTEGRAND_MIXTURE_MAX_VARIANCE 1.0

/* Most boxes of a gaussian_mixture (2 d^2 in 2D). */
#define MCS_INTEGRAND_MAX_BOXES 8

/* Most cells of mcs_integrand_jittered_mse (2^22: its O(K) loops over the
 * cells of the indicators stay under a second). */
#define MCS_INTEGRAND_JITTERED_MAX_K 4194304u

typedef enum {
    MCS_INTEGRAND_GAUSSIAN = 0,      /* a Gaussian bump on the square (not periodic) */
    MCS_INTEGRAND_GAUSSIAN_PERIODIC, /* the same bump periodised on the torus */
    MCS_INTEGRAND_HEAVISIDE,         /* a half-plane across the square (a step in 1D) */
    MCS_INTEGRAND_DISK,              /* a disk on the torus (an arc in 1D) */
    MCS_INTEGRAND_COSINE,            /* a product of 1 + a cos(2 pi m x + phi), integral 1 */
    MCS_INTEGRAND_BLINN_PHONG,       /* utk's Blinn-Phong lobe lit by a quad (2D only) */
    MCS_INTEGRAND_GAUSSIAN_MIXTURE,  /* utk's clipped mixture of Gaussians */
    MCS_INTEGRAND_FAMILIES           /* how many there are */
} mcs_integrand_family;

/* One integrand: transparent, fixed size, no pointers. Fields a family does
 * not use are 0. blinn_phong's frame and the utk families' integral, square
 * and error are computed by mcs_integrand_draw from the parameters: an
 * integrand whose parameters are changed by hand keeps stale values (the
 * frame is checked against p, the others only for range). */
typedef struct {
    mcs_integrand_family family;
    size_t dim;       /* 1 or 2; 0 before mcs_integrand_draw */
    double centre[2]; /* gaussians, disk: c; heaviside: the point p on the line (1D: the step) */
    double width;     /* gaussians: s; disk: r */
    double normal[2]; /* heaviside 2D: the unit normal u */
    double amp[2];    /* cosine: a_d */
    double phase[2];  /* cosine: phi_d */
    long freq[2];     /* cosine: m_d */
    double shading[3]; /* blinn_phong: p, the shading point */
    double view[3];    /* blinn_phong: o, the unit view direction */
    double exponent;   /* blinn_phong: alpha */
    double frame[7];   /* blinn_phong: the quad seen from p (solid angle, ...), from p */
    size_t boxes;      /* gaussian_mixture: n */
    double box_lo[MCS_INTEGRAND_MAX_BOXES][2], box_hi[MCS_INTEGRAND_MAX_BOXES][2];
    double mean[MCS_INTEGRAND_MAX_BOXES][2];      /* gaussian_mixture: mu_i */
    double precision[MCS_INTEGRAND_MAX_BOXES][3]; /* A_i = [[a, b], [b, c]] as (a, b, c); 1D: a */
    double integral;  /* blinn_phong, gaussian_mixture: I, by the draw */
    double square;    /* blinn_phong, gaussian_mixture: Q, by the draw */
    double error;     /* blinn_phong, gaussian_mixture: the quadrature's relative error
                         estimate for I and Q (0: by erf alone) */
} mcs_integrand;

/* Name of a family as the command prints it ("gaussian",
 * "gaussian_periodic", "heaviside", "disk", "cosine", "blinn_phong",
 * "gaussian_mixture"), or "unknown"; never NULL. */
const char *mcs_integrand_family_str(mcs_integrand_family family);

/* 1 if the family is periodic on the torus and translation invariant (its
 * Fourier power and prediction exist: gaussian_periodic, disk, cosine),
 * else 0 (an unknown family too). */
int mcs_integrand_is_periodic(mcs_integrand_family family);

/* 1 if family has integrands in dim dimensions (every family in 1 and 2,
 * but blinn_phong in 2 only), else 0 (an unknown family too). */
int mcs_integrand_has_dim(mcs_integrand_family family, size_t dim);

/* Draws one integrand of family in dim dimensions from rng (a fixed number
 * of doubles per family and dim, so M draws from one seed are reproducible;
 * blinn_phong and gaussian_mixture then integrate it, about a millisecond).
 * MCS_ERR_NULL, MCS_ERR_KIND (not a family), MCS_ERR_DOMAIN (dim not 1 or
 * 2, or not one of the family's: mcs_integrand_has_dim), MCS_ERR_UNINIT (rng never seeded), MCS_ERR_ALIAS (f overlapping rng).
 * *f and rng untouched on error. */
mcs_status mcs_integrand_draw(mcs_integrand *f, mcs_integrand_family family, size_t dim,
                              mcs_rng *rng);

/* Every call below returns MCS_ERR_NULL for a NULL argument and
 * MCS_ERR_UNINIT for an integrand no draw produces (unknown family, dim not
 * 1 or 2, a parameter outside its range or not finite, a normal not of unit
 * length), changing nothing. */

/* f at one point x[dim] in [0,1)^dim. MCS_ERR_POINT_RANGE (a coordinate
 * outside [0, 1) or NaN). *out untouched on error. */
mcs_status mcs_integrand_eval(const mcs_integrand *f, const double *x, double *out);

/* The estimate (1/k) sum_j f(x_j) of k points, points[k * dim] interleaved.
 * MCS_ERR_K_RANGE (k = 0), MCS_ERR_POINT_RANGE (a coordinate outside [0, 1)
 * or NaN, or k * dim past SIZE_MAX). *out untouched on error. */
mcs_status mcs_integrand_estimate(const mcs_integrand *f, size_t k, const double *points,
                                  double *out);

/* The exact integral I of f over [0,1)^dim (the table above). */
mcs_status mcs_integrand_integral(const mcs_integrand *f, double *out);

/* The exact variance Q - I^2 of f at one uniform point (random points: the
 * mean squared error times K). */
mcs_status mcs_integrand_variance(const mcs_integrand *f, double *out);

/* The exact mean squared error of the jittered grid of strata_x x strata_y
 * cells (1D: strata_x cells, strata_y = 1). MCS_ERR_DOMAIN (blinn_phong
 * and the 2D gaussian_mixture: not known), MCS_ERR_K_RANGE (a strata count
 * 0, strata_y not 1 in 1D, or strata_x strata_y above
 * MCS_INTEGRAND_JITTERED_MAX_K).
 * *out untouched on error. */
mcs_status mcs_integrand_jittered_mse(const mcs_integrand *f, size_t strata_x, size_t strata_y,
                                      double *out);

/* |f^(k)|^2 at wave vector (freq_x, freq_y) (1D: freq_y must be 0).
 * MCS_ERR_DOMAIN (a family that is not periodic), MCS_ERR_FREQ_RANGE
 * (freq_y not 0 in 1D, or |freq| above MCS_POINTSET_MAX_FREQ). */
mcs_status mcs_integrand_power(const mcs_integrand *f, long freq_x, long freq_y, double *out);

/* The predicted mean squared error, the mean over the m integrands fs[m]
 * (one family, dim 2) of (1/k) sum_{0 < |q|_inf <= F} |f^(q)|^2 <P(q)>, with
 * <P> read from ps (F its cutoff; sets of k points), into *predicted, and
 * the mean of their tail bounds (above) into *tail. O(m F^2).
 * MCS_ERR_K_RANGE (m or k 0), MCS_ERR_DOMAIN (a family that is not
 * periodic), MCS_ERR_MISMATCH (integrands of different families, or not
 * dim 2), MCS_ERR_UNINIT (ps not initialised), MCS_ERR_EMPTY (ps has no
 * trials), MCS_ERR_ALIAS (the outputs overlapping each other). Outputs
 * untouched on error. */
mcs_status mcs_integrand_predict(const mcs_integrand *fs, size_t m, const mcs_pointset2d *ps,
                                 size_t k, double *predicted, double *tail);

/* The same in 1D over a 1D point-set accumulator (integrands of dim 1). */
mcs_status mcs_integrand_predict_1d(const mcs_integrand *fs, size_t m, const mcs_pointset *ps,
                                    size_t k, double *predicted, double *tail);

#ifdef __cplusplus
}
#endif

#endif /* MCSPEC_INTEGRAND_H */
