/* Compiles a kernel body twice (simd.h): includes the file MCS_SIMD_BODY
 * names once with KERNEL(name) = name_generic for the baseline ISA and, where
 * MCS_AVX2_CLONES, once more with KERNEL(name) = name_avx2 between
 * MCS_AVX2_BEGIN and MCS_AVX2_END. A file defines MCS_SIMD_BODY (a quoted
 * header name), includes this, and picks a copy per object at run time.
 * No include guard: each including file gets its own copies. */
#include "simd.h"

#define KERNEL(name) name##_generic
#include MCS_SIMD_BODY
#undef KERNEL

#if MCS_AVX2_CLONES
MCS_AVX2_BEGIN
#define KERNEL(name) name##_avx2
#include MCS_SIMD_BODY
#undef KERNEL
MCS_AVX2_END
#endif

#undef MCS_SIMD_BODY
