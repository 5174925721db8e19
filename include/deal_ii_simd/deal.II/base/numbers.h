// SIMD width of deal.II's VectorizedArray for wetbed's own code (doc/developer_guide.md,
// "SIMD width"). Debian's deal.II 9.4 is configured for generic x86-64 with
// DEAL_II_VECTORIZATION_WIDTH_IN_BITS = 0, so VectorizedArray<double> has one lane and
// the matrix-free kernels run one cell at a time. deal.II's config.h defines that width
// and then includes this header (deal.II/base/numbers.h), which is found here first when
// CMake's WETBED_SIMD is on: the width is raised to what the compiler's target
// (-march=native) offers before numbers.h and vectorization.h are read, in every
// translation unit alike. The MatrixFree classes for that width, which the library does
// not hold, are instantiated at the end of source/solvers/matrix_free_flow_operator.cc.
#ifndef wetbed_deal_ii_simd_numbers_h
#define wetbed_deal_ii_simd_numbers_h

#if DEAL_II_VECTORIZATION_WIDTH_IN_BITS == 0
#define WETBED_LIBRARY_VECTORIZATION_WIDTH_IN_BITS 0
#elif DEAL_II_VECTORIZATION_WIDTH_IN_BITS == 128
#define WETBED_LIBRARY_VECTORIZATION_WIDTH_IN_BITS 128
#elif DEAL_II_VECTORIZATION_WIDTH_IN_BITS == 256
#define WETBED_LIBRARY_VECTORIZATION_WIDTH_IN_BITS 256
#else
#define WETBED_LIBRARY_VECTORIZATION_WIDTH_IN_BITS 512
#endif

#ifndef WETBED_SIMD_MAX_BITS
#define WETBED_SIMD_MAX_BITS 512
#endif
#undef DEAL_II_VECTORIZATION_WIDTH_IN_BITS
#undef DEAL_II_COMPILER_VECTORIZATION_LEVEL
#if defined(__AVX512F__) && WETBED_SIMD_MAX_BITS >= 512
#define DEAL_II_VECTORIZATION_WIDTH_IN_BITS 512
#define DEAL_II_COMPILER_VECTORIZATION_LEVEL 3
#elif defined(__AVX__) && WETBED_SIMD_MAX_BITS >= 256
#define DEAL_II_VECTORIZATION_WIDTH_IN_BITS 256
#define DEAL_II_COMPILER_VECTORIZATION_LEVEL 2
#elif defined(__SSE2__) && WETBED_SIMD_MAX_BITS >= 128
#define DEAL_II_VECTORIZATION_WIDTH_IN_BITS 128
#define DEAL_II_COMPILER_VECTORIZATION_LEVEL 1
#else
#define DEAL_II_VECTORIZATION_WIDTH_IN_BITS 0
#define DEAL_II_COMPILER_VECTORIZATION_LEVEL 0
#endif
#endif

#include_next <deal.II/base/numbers.h>
