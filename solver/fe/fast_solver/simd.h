// SIMD lanes for the matrix-free kernels. Debian's deal.II 9.4 is configured without
// vectorization (DEAL_II_VECTORIZATION_WIDTH_IN_BITS 0), so its default VectorizedArray<double>
// holds one number and every sum-factorization kernel runs scalar. Where the build machine runs
// AVX2 (solver/fe/CMakeLists.txt checks, COMPLIANT_SIMD_WIDTH_BITS = 256), this header - put
// first into every translation unit of the library by the compiler's -include - lets
// vectorization.h define its AVX classes (VectorizedArray<double, 4>), while the default width
// stays the library's 1: numbers.h fixes the default before the switch, so every class compiled
// into libdeal.ii keeps its layout. The kernels then take SimdArray<Number> explicitly, and
// MatrixFree is instantiated for them (fast_solver/matrix_free_simd*.cc). After vectorization.h
// the macro is 0 again: the two matrix-free headers that read it later then take their per-lane
// loops, right for any width. (Its SIMDComparison enum gets AVX's values here and 0-5 in the
// library; it only appears as a template argument, so the symbols differ and never meet.)
// Measured: README, Speed (cases/benchmarks/simd_speed.py).
#pragma once

#include <deal.II/base/config.h>

#include <deal.II/base/numbers.h> // the default width, fixed at the library's

#if defined(COMPLIANT_SIMD_WIDTH_BITS) && COMPLIANT_SIMD_WIDTH_BITS > 0
#  ifdef dealii_vectorization_h
#    error "fast_solver/simd.h must be included before any deal.II header that includes vectorization.h"
#  endif
#  undef DEAL_II_VECTORIZATION_WIDTH_IN_BITS
#  define DEAL_II_VECTORIZATION_WIDTH_IN_BITS COMPLIANT_SIMD_WIDTH_BITS
#  include <deal.II/base/vectorization.h>
#  undef DEAL_II_VECTORIZATION_WIDTH_IN_BITS
#  define DEAL_II_VECTORIZATION_WIDTH_IN_BITS 0
#else
#  include <deal.II/base/vectorization.h>
#endif

#include <cstddef>

namespace compliant::fast_solver
{
#if defined(COMPLIANT_SIMD_WIDTH_BITS) && COMPLIANT_SIMD_WIDTH_BITS > 0
  template <typename Number>
  inline constexpr std::size_t simd_lanes = COMPLIANT_SIMD_WIDTH_BITS / (8 * sizeof(Number));
#else
  template <typename Number>
  inline constexpr std::size_t simd_lanes = 1;
#endif

  // The lanes every matrix-free kernel works on: cells processed together.
  template <typename Number>
  using SimdArray = dealii::VectorizedArray<Number, simd_lanes<Number>>;
} // namespace compliant::fast_solver
