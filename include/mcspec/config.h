/* mcspec compile-time capacities. Override any of them with -D on the
 * command line (for the library and for every file that includes mcspec.h:
 * struct sizes depend on them). */
#ifndef MCSPEC_CONFIG_H
#define MCSPEC_CONFIG_H

/* Largest number of bins N any object accepts (importance, spectrum, dft). */
#ifndef MCS_MAX_N
#define MCS_MAX_N 4096
#endif

/* Largest N for the full N x N second-moment objects (moment, theory). */
#ifndef MCS_MAX_COV_N
#define MCS_MAX_COV_N 64
#endif

#if MCS_MAX_N < 1
#error "MCS_MAX_N must be at least 1"
#endif
#if MCS_MAX_COV_N < 1 || MCS_MAX_COV_N > MCS_MAX_N
#error "MCS_MAX_COV_N must be in 1..MCS_MAX_N"
#endif

#endif /* MCSPEC_CONFIG_H */
