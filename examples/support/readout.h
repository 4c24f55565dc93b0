/* Shared by the section examples: values read back from the library and from
 * Welford accumulators for the tables, EX_NA where the read fails. A failed
 * library call changes nothing, so its output variable would hold a stale or
 * made-up value: these helpers put EX_NA (printed "-") there instead. */
#ifndef MCSPEC_EXAMPLE_READOUT_H
#define MCSPEC_EXAMPLE_READOUT_H

#include <stddef.h>

#include "mcspec.h"
#include "report.h"

/* *v if the call that filled it returned st == MCS_OK, else EX_NA. v is a
 * pointer so that *v is read after the call: in or_na(call(&v), v) the
 * arguments are unsequenced. */
double ex_or_na(mcs_status st, const double *v);
/* The same for a call with two outputs (re, im). */
ex_complex ex_complex_or_na(mcs_status st, const double *re, const double *im);

/* Mean and standard error of a Welford accumulator (EX_NA if too few values). */
double ex_mean(const mcs_welford *w, double *stderr_out);
/* Unbiased variance and its standard error (EX_NA if too few values). */
double ex_variance(const mcs_welford *w, double *stderr_out);

/* Measured <|S_freq|^2> of a spectrum accumulator, and its standard error
 * (stderr_out may be NULL); EX_NA where unavailable. */
double ex_spectrum_power(const mcs_spectrum *spectrum, size_t freq, double *stderr_out);

/* The signed frequency |k| of DFT index q over m bins: index q > m/2 is
 * frequency q - m. The note's N -> infinity forms are functions of the signed
 * frequency (the sinc^2 is even); taken literally at index q near m they
 * describe a frequency near m, which a pattern's spectrum (symmetric,
 * P_{m-q} = P_q) does not have. */
size_t ex_fold(size_t m, size_t q);

#endif /* MCSPEC_EXAMPLE_READOUT_H */
