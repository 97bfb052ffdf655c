// The run-time-degree face evaluators MatrixFree's mapping set-up calls, for the kernels' SIMD
// lanes (see matrix_free_simd_evaluation.cc).
#include "fast_solver/simd.h"

#if defined(COMPLIANT_SIMD_WIDTH_BITS) && COMPLIANT_SIMD_WIDTH_BITS > 0
#  define FE_EVAL_FACTORY_DEGREE_MAX 4
#  include <deal.II/matrix_free/evaluation_template_face_factory.templates.h>

namespace dealii::internal
{
  using Lanes = compliant::fast_solver::SimdArray<double>;

  template void FEFaceEvaluationFactory<2, Lanes>::evaluate(unsigned int, EvaluationFlags::EvaluationFlags,
                                                            const Lanes *, FEEvaluationData<2, Lanes, true> &);
  template void FEFaceEvaluationFactory<3, Lanes>::evaluate(unsigned int, EvaluationFlags::EvaluationFlags,
                                                            const Lanes *, FEEvaluationData<3, Lanes, true> &);
} // namespace dealii::internal
#endif
