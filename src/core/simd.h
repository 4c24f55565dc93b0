/* Function multiversioning for the vectorisable kernels (dft_simd.h,
 * spectrum_simd.h): a file includes a kernel body once for the baseline ISA
 * and once between MCS_AVX2_BEGIN and MCS_AVX2_END, with KERNEL(name)
 * naming each copy, and picks a copy at run time by an object's simd flag
 * (set at init from mcs_cpu_avx2_()). Plain C11 everywhere else: on other
 * targets or compilers only the baseline copy exists.
 *
 * Both copies compute the same bits: their loops do the same IEEE
 * operations in the same order per lane, and ISO C mode (-std=c11) does not
 * contract a * b + c into an FMA (nor does the avx2 target enable FMA). */
#ifndef MCSPEC_SIMD_H
#define MCSPEC_SIMD_H

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(MCS_NO_AVX2)
#define MCS_AVX2_CLONES 1
#if defined(__clang__)
#define MCS_AVX2_BEGIN \
    _Pragma("clang attribute push(__attribute__((target(\"avx2\"))), apply_to = function)")
#define MCS_AVX2_END _Pragma("clang attribute pop")
#else
#define MCS_AVX2_BEGIN _Pragma("GCC push_options") _Pragma("GCC target(\"avx2\")")
#define MCS_AVX2_END _Pragma("GCC pop_options")
#endif
#else
#define MCS_AVX2_CLONES 0
#endif

/* Keeps a kernel out of its callers: an AVX2 function that inlines a
 * register-hungry kernel spills 32-byte values, for which the compiler
 * realigns the stack (a dynamic frame that make stack refuses). */
#if defined(__GNUC__) || defined(__clang__)
#define MCS_NOINLINE __attribute__((noinline))
#else
#define MCS_NOINLINE
#endif

/* 1 when this CPU and its OS run AVX2 code (cpuid and xgetbv, no library
 * call; x86-64 only, 0 elsewhere). Slow in a virtual machine (cpuid traps),
 * so it is asked once per object, at init. */
int mcs_cpu_avx2_(void);

#endif /* MCSPEC_SIMD_H */
