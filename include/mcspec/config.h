/* mcspec compile-time capacities. Override any of them with -D on the
 * command line (for the library and for every file that includes mcspec.h:
 * struct sizes depend on them). */
#ifndef MCSPEC_CONFIG_H
#define MCSPEC_CONFIG_H

/* mcspec-install: an installed copy records the library's capacities here. */

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

/* Link-time capacity check. Every file that includes this header references
 * a symbol named after its capacities; libmcspec defines only the one for the
 * capacities it was built with (src/version.c). Code built with other values
 * fails to link with "undefined reference to
 * mcs_config_requires_libmcspec_built_with_MCS_MAX_N_<N>_MCS_MAX_COV_N_<C>":
 * build it with the library's values (pkg-config --cflags mcspec, or the
 * mcspec::mcspec CMake target), or rebuild the library with yours. The
 * capacities must therefore be plain decimal numbers. `used` and `retain`
 * keep the reference through optimisation and --gc-sections (where the
 * toolchain supports retain). */
#define MCS_CONFIG_TAG_(n, c) mcs_config_requires_libmcspec_built_with_MCS_MAX_N_##n##_MCS_MAX_COV_N_##c
#define MCS_CONFIG_TAG(n, c) MCS_CONFIG_TAG_(n, c)
#define MCS_CONFIG_LINK_TAG MCS_CONFIG_TAG(MCS_MAX_N, MCS_MAX_COV_N)
#ifdef __cplusplus
extern "C" {
#endif
extern const char MCS_CONFIG_LINK_TAG[];
#ifdef __cplusplus
}
#endif
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wattributes"
static const char *const mcs_config_link_check_ __attribute__((used, retain)) = MCS_CONFIG_LINK_TAG;
#pragma GCC diagnostic pop
#endif

#endif /* MCSPEC_CONFIG_H */
