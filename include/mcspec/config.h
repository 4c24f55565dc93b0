/* mcspec compile-time capacities: every macro that sizes a public struct is
 * defined here and nowhere else (the objects sized at run time give their
 * caps in their own headers). Override any of them with -D on the command
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

/* MCS_MAX_FREQ, MCS_MAX_FREQ_1D and MCS_MAX_SIDE sized mcs_pointset2d,
 * mcs_pointset and mcs_spectrum2d until those took their size at run time,
 * over caller memory (issue 24: pointset.h, pointset2d.h, spectrum2d.h give
 * their sizes and caps, MCS_POINTSET_MAX_FREQ, MCS_POINTSET2D_MAX_FREQ and
 * MCS_SPECTRUM2D_MAX_SIDE, which no -D changes). They size nothing now and
 * no call reads them; they keep their old defaults and their place in the
 * link tag below only because the installed package's checks (pkg-config,
 * CMake, mk/install.mk) still name them, and go when those do. */
#ifndef MCS_MAX_FREQ
#define MCS_MAX_FREQ 32
#endif
#ifndef MCS_MAX_FREQ_1D
#define MCS_MAX_FREQ_1D 1024
#endif
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

/* Not a capacity but a feature switch: 1 (the default) builds the type-1
 * NUFFT (nufft.h) and the point-set accumulators' NUFFT path; 0 leaves them
 * out, for firmware that never has the large sets the NUFFT is for (about
 * 12 KiB of flash on Cortex-M: docs/embedded.md). With 0 the accumulators
 * behave as if every object had MCS_POINTSET_DIRECT_ONLY (size queries give
 * the direct path's bytes, AUTO takes the direct sum, whose results keep
 * their bits), mcs_pointset_set_path and mcs_pointset2d_set_path refuse the
 * NUFFT path with MCS_ERR_DOMAIN, and every mcs_nufft_ call returns
 * MCS_ERR_DOMAIN. Set it with -DMCS_CONFIG_NUFFT=0 for the library (make
 * NUFFT=0, CMake -DMCSPEC_NUFFT=OFF; an installed copy records 0 above).
 * Code that includes mcspec.h may see either value: no struct depends on
 * it, and MCS_POINTSET_SIZE and MCS_POINTSET2D_SIZE only shrink to the
 * direct sizes with 0 (a buffer that small is refused with MCS_ERR_SPACE
 * by a library with the NUFFT, never overrun). */
#ifndef MCS_CONFIG_NUFFT
#define MCS_CONFIG_NUFFT 1
#endif
#if MCS_CONFIG_NUFFT != 0 && MCS_CONFIG_NUFFT != 1
#error "MCS_CONFIG_NUFFT must be 0 or 1"
#endif

/* Not a capacity (it sizes nothing and is not overridable): the largest
 * count (trials, or values for a welford) any accumulator holds, 2^53, the
 * last count a double represents exactly -- every read-out divides by it and
 * every merge weighs by it. An add or merge that would pass it returns
 * MCS_ERR_COUNT and changes nothing. */
#define MCS_MAX_COUNT 9007199254740992u

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
