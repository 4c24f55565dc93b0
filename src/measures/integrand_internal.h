/* Helpers the integrand files share (integrand.c, integrand_cells.c,
 * integrand_fourier.c, integrate.c); private header. */
#ifndef MCSPEC_INTEGRAND_INTERNAL_H
#define MCSPEC_INTEGRAND_INTERNAL_H

#include <stddef.h>

#include "mcspec/integrand.h"
#include "mcspec/rng.h"

#define MCS_INTEG_PI 3.14159265358979323846
#define MCS_INTEG_TWO_PI 6.28318530717958647693

/* Images n = -IMAGES..IMAGES per axis of the periodised Gaussian. */
#define MCS_INTEG_IMAGES 3

/* The adaptive Gauss-Kronrod quadrature (integrand_quad.c): MCS_INTEG_QUAD_N
 * integrals at once of fn(ctx, x, out[MCS_INTEG_QUAD_N]) over [a, b] into
 * out[], their error estimates (QUADPACK's) into err[]: bisected until
 * each panel's estimate is within its share of the larger of rel times a
 * first estimate of the integral and floors[n] (+inf: that component never
 * asks for a bisection), or at its rounding floor. */
#define MCS_INTEG_QUAD_N 4
typedef void (*mcs_integ_quad_fn)(void *ctx, double x, double *out);
void mcs_integ_quad_(mcs_integ_quad_fn fn, void *ctx, double a, double b, double rel,
                     const double *floors, double *out, double *err);

/* The families from utk (integrand_utk.c): blinn_phong and
 * gaussian_mixture. 1 if family is one of them. */
int mcs_integ_is_utk_(mcs_integrand_family family);

/* 1 if f (of a utk family, family and dim valid) is one the draw produces. */
int mcs_integ_utk_valid_(const mcs_integrand *f);

/* Fills g (family and dim set, the rest 0) from rng and computes its I and Q. */
void mcs_integ_utk_draw_(mcs_integrand *g, mcs_rng *rng);

/* A 1D gaussian_mixture's int f and int f^2 over [x0, x1], by erf. */
void mcs_integ_mixture_cell_(const mcs_integrand *f, double x0, double x1, double *i1,
                             double *square);

/* f at x (valid f of a utk family): no checks. */
double mcs_integ_utk_eval_(const mcs_integrand *f, const double *x);

/* 1 if f is an integrand some draw produces (integrand.h), else 0. */
int mcs_integ_valid_(const mcs_integrand *f);

/* f at x (valid f, x in [0,1)^dim): no checks. */
double mcs_integ_eval_(const mcs_integrand *f, const double *x);

/* The exact I and Q = int f^2 of a valid f. */
void mcs_integ_moments_(const mcs_integrand *f, double *integral, double *square);

/* The area of the 2D Heaviside's half-plane inside [x0,x1] x [y0,y1]
 * (the rectangle clipped by the line, Sutherland-Hodgman, then the shoelace
 * formula); 1D (the step x < p): the length of [x0, x1] below p. */
double mcs_integ_halfplane_area_(const mcs_integrand *f, double x0, double x1, double y0,
                                 double y1);

/* 1 if the exact jittered-grid MSE of a valid f is known (not for
 * blinn_phong and the 2D gaussian_mixture). */
int mcs_integ_has_jittered_(const mcs_integrand *f);

/* The exact jittered-grid MSE of a valid f over mx x my cells (my = 1 in
 * 1D), mx my <= MCS_INTEGRAND_JITTERED_MAX_K. */
double mcs_integ_jittered_(const mcs_integrand *f, size_t mx, size_t my);

/* |f^(k)|^2 of a valid periodic f (k_y = 0 in 1D). */
double mcs_integ_power_(const mcs_integrand *f, long kx, long ky);

#endif /* MCSPEC_INTEGRAND_INTERNAL_H */
