// The run-time-degree evaluators MatrixFree's mapping set-up calls, for the kernels' SIMD lanes
// (fast_solver/simd.h, matrix_free_simd.cc), cells here and faces in
// matrix_free_simd_faces.cc: deal.II 9.4's two template files share one include guard. Degrees above 4 (a mapping of higher degree than any
// element offered) take deal.II's generic evaluator.
#include "fast_solver/simd.h"

#if defined(COMPLIANT_SIMD_WIDTH_BITS) && COMPLIANT_SIMD_WIDTH_BITS > 0
#  define FE_EVAL_FACTORY_DEGREE_MAX 4
#  include <deal.II/matrix_free/evaluation_template_factory.templates.h>

namespace dealii::internal
{
  using Lanes = compliant::fast_solver::SimdArray<double>;

  template void FEEvaluationFactory<2, Lanes>::evaluate(unsigned int, EvaluationFlags::EvaluationFlags,
                                                        const Lanes *, FEEvaluationData<2, Lanes, false> &);
  template void FEEvaluationFactory<3, Lanes>::evaluate(unsigned int, EvaluationFlags::EvaluationFlags,
                                                        const Lanes *, FEEvaluationData<3, Lanes, false> &);
} // namespace dealii::internal
#endif
