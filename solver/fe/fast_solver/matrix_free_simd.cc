// MatrixFree for the kernels' SIMD lanes (fast_solver/simd.h): libdeal.ii instantiates it for its
// own width (one lane) only, so the wider one is instantiated here from deal.II's templates.
#include "fast_solver/simd.h"

#if defined(COMPLIANT_SIMD_WIDTH_BITS) && COMPLIANT_SIMD_WIDTH_BITS > 0
#  include <deal.II/matrix_free/evaluation_template_factory_hanging_nodes.templates.h>
#  include <deal.II/matrix_free/mapping_info.templates.h>
#  include <deal.II/matrix_free/matrix_free.templates.h>
#  include <deal.II/matrix_free/shape_info.templates.h>

namespace dealii
{
  using Lanes = compliant::fast_solver::SimdArray<double>;

  template class MatrixFree<2, double, Lanes>;
  template class MatrixFree<3, double, Lanes>;
  template void MatrixFree<2, double, Lanes>::internal_reinit<double, 2>(
    const std::shared_ptr<hp::MappingCollection<2>> &, const std::vector<const DoFHandler<2, 2> *> &,
    const std::vector<const AffineConstraints<double> *> &, const std::vector<IndexSet> &,
    const std::vector<hp::QCollection<2>> &, const AdditionalData &);
  template void MatrixFree<3, double, Lanes>::internal_reinit<double, 3>(
    const std::shared_ptr<hp::MappingCollection<3>> &, const std::vector<const DoFHandler<3, 3> *> &,
    const std::vector<const AffineConstraints<double> *> &, const std::vector<IndexSet> &,
    const std::vector<hp::QCollection<3>> &, const AdditionalData &);

  template struct internal::MatrixFreeFunctions::ShapeInfo<Lanes>;
  template void internal::MatrixFreeFunctions::ShapeInfo<Lanes>::reinit<2, 2, 2>(const Quadrature<2> &,
                                                                              const FiniteElement<2, 2> &,
                                                                              unsigned int);
  template void internal::MatrixFreeFunctions::ShapeInfo<Lanes>::reinit<3, 3, 3>(const Quadrature<3> &,
                                                                              const FiniteElement<3, 3> &,
                                                                              unsigned int);
  template struct internal::MatrixFreeFunctions::MappingInfo<2, double, Lanes>;
  template struct internal::MatrixFreeFunctions::MappingInfo<3, double, Lanes>;
  template struct internal::FEEvaluationHangingNodesFactory<2, double, Lanes>;
  template struct internal::FEEvaluationHangingNodesFactory<3, double, Lanes>;
} // namespace dealii
#endif
