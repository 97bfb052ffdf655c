// The isoparametric mapping of triangles and tetrahedra of degree 2 with edges on the curved
// boundaries: deal.II 9.4's MappingFE places every edge midpoint on the straight chord, whatever
// manifold the edge has; this one asks the edge's manifold.
#pragma once

#include <deal.II/fe/mapping_fe.h>

#include <vector>

namespace compliant
{
  template <int dim>
  class CurvedSimplexMapping : public dealii::MappingFE<dim>
  {
  public:
    explicit CurvedSimplexMapping(unsigned int degree);

    std::unique_ptr<dealii::Mapping<dim>> clone() const override;

  protected:
    std::vector<dealii::Point<dim>>
    compute_mapping_support_points(const typename dealii::Triangulation<dim>::cell_iterator &cell) const override;
  };
} // namespace compliant
