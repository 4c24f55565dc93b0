/* Stand-in <math.h> for compiling mcspec with a toolchain that ships no C
 * library (riscv64-unknown-elf-gcc here; make cross-rv). It declares only the
 * functions of tools/alloc_allowlist.txt, with their C99 prototypes, so a
 * library source that used anything else fails to compile. */
#ifndef MCS_FREESTANDING_MATH_H
#define MCS_FREESTANDING_MATH_H

#define HUGE_VAL (__builtin_huge_val())
#define INFINITY (__builtin_inff())
#define NAN (__builtin_nanf(""))
#define isfinite(x) __builtin_isfinite(x)
#define isinf(x) __builtin_isinf(x)
#define isnan(x) __builtin_isnan(x)
#define signbit(x) __builtin_signbit(x)
#define fpclassify(x) __builtin_fpclassify(FP_NAN, FP_INFINITE, FP_NORMAL, FP_SUBNORMAL, FP_ZERO, x)
#define FP_NAN 0
#define FP_INFINITE 1
#define FP_ZERO 2
#define FP_SUBNORMAL 3
#define FP_NORMAL 4

double acos(double), asin(double), atan(double), atan2(double, double), cbrt(double);
double ceil(double), copysign(double, double), cos(double), cosh(double), erf(double);
double erfc(double), exp(double), exp2(double), expm1(double), fabs(double), floor(double);
double fma(double, double, double), fmax(double, double), fmin(double, double);
double fmod(double, double), frexp(double, int *), hypot(double, double), ldexp(double, int);
double lgamma(double), log(double), log10(double), log1p(double), log2(double);
double modf(double, double *), nearbyint(double), nextafter(double, double);
double pow(double, double), remainder(double, double), rint(double), round(double);
double scalbn(double, int), sin(double), sinh(double), sqrt(double), tan(double);
double tanh(double), tgamma(double), trunc(double);
long lrint(double), lround(double);
long long llrint(double), llround(double);
void sincos(double, double *, double *);

#endif
