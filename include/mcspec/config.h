/* mcspec compile-time capacities: every macro that sizes a public struct is
 * defined here and nowhere else. Override any of them with -D on the command
 * line, as a plain decimal number, for the library and for every file that
 * includes mcspec.h alike: the struct layouts depend on them, and the checks
 * below stop a build that mixes two sets of values. */
#ifndef MCSPEC_CONFIG_H
#define MCSPEC_CONFIG_H

/* mcspec-install: an installed copy records the library's capacities here. */

/* Largest number of bins N of the 1D binned objects: mcs_importance (24 B
 * per unit), mcs_dft (64 B), mcs_spectrum (about 100 B), mcs_autocorr. */
#ifndef MCS_MAX_N
#define MCS_MAX_N 4096
#endif

/* Largest N of the full N x N second-moment objects, mcs_moment and
 * mcs_theory (8 B x N^2 per matrix). */
#ifndef MCS_MAX_COV_N
#define MCS_MAX_COV_N 64
#endif

/* Largest per-axis cutoff F of the 2D point-set spectrum mcs_pointset2d
 * (about 64 (F + 1)^2 B). */
#ifndef MCS_MAX_FREQ
#define MCS_MAX_FREQ 32
#endif

/* Largest cutoff F of the 1D point-set spectrum mcs_pointset (about 34 B per
 * frequency). */
#ifndef MCS_MAX_FREQ_1D
#define MCS_MAX_FREQ_1D 1024
#endif

/* Largest N1 and N2 of the 2D binned spectrum mcs_spectrum2d (about 28 S^2 B
 * for S = MCS_MAX_SIDE). */
#ifndef MCS_MAX_SIDE
#define MCS_MAX_SIDE 64
#endif

#if MCS_MAX_N < 1
#error "MCS_MAX_N must be at least 1"
#endif
#if MCS_MAX_COV_N < 1 || MCS_MAX_COV_N > MCS_MAX_N
#error "MCS_MAX_COV_N must be in 1..MCS_MAX_N"
#endif
#if MCS_MAX_FREQ < 1
#error "MCS_MAX_FREQ must be at least 1"
#endif
#if MCS_MAX_FREQ_1D < 1
#error "MCS_MAX_FREQ_1D must be at least 1"
#endif
#if MCS_MAX_SIDE < 1
#error "MCS_MAX_SIDE must be at least 1"
#endif

/* Link-time capacity check. Every file that includes this header references
 * a symbol named after all five capacities; libmcspec defines only the one
 * for the capacities it was built with (src/version.c). Code built with
 * other values fails to link with "undefined reference to
 * mcs_config_requires_libmcspec_built_with_MCS_MAX_N_<N>_MCS_MAX_COV_N_<C>
 * _MCS_MAX_FREQ_<F>_MCS_MAX_FREQ_1D_<F1>_MCS_MAX_SIDE_<S>" (one name): build
 * it with the library's values (pkg-config --cflags mcspec, or the
 * mcspec::mcspec CMake target), or rebuild the library with yours. The
 * capacities must therefore be plain decimal numbers. `used` and `retain`
 * keep the reference through optimisation and --gc-sections (where the
 * toolchain supports retain). mk/install.mk reads the values back out of
 * this name, in this order. */
#define MCS_CONFIG_TAG_(n, c, f, f1, s)                                                  \
    mcs_config_requires_libmcspec_built_with_MCS_MAX_N_##n##_MCS_MAX_COV_N_##c## \
        _MCS_MAX_FREQ_##f##_MCS_MAX_FREQ_1D_##f1##_MCS_MAX_SIDE_##s
#define MCS_CONFIG_TAG(n, c, f, f1, s) MCS_CONFIG_TAG_(n, c, f, f1, s)
#define MCS_CONFIG_LINK_TAG \
    MCS_CONFIG_TAG(MCS_MAX_N, MCS_MAX_COV_N, MCS_MAX_FREQ, MCS_MAX_FREQ_1D, MCS_MAX_SIDE)
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
