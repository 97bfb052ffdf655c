// Translations and infinitesimal rotations: the kernel of elasticity without supports, which
// algebraic multigrid needs as its near null space (deal.II 9.4 has no extract_rigid_body_modes).
#pragma once

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <vector>

namespace compliant
{
  // Component c of rigid-body mode m at position r (from the rotations' centre): translations
  // along x, y (, z), then rotations about z (2D) or x, y, z (3D), e_axis x r.
  template <int dim>
  double rigid_body_mode_value(const unsigned int mode, const unsigned int component, const dealii::Tensor<1, dim> &r)
  {
    if (mode < dim)
      return mode == component ? 1. : 0.;
    const unsigned int axis = dim == 2 ? 2 : mode - dim, a = (axis + 1) % 3, b = (axis + 2) % 3;
    const auto         at   = [&r](const unsigned int d) { return d < dim ? r[d] : 0.; };
    return component == a ? -at(b) : component == b ? at(a) : 0.;
  }

  template <int dim>
  class RigidBodyMode : public dealii::Function<dim>
  {
  public:
    static constexpr unsigned int n_modes = dim == 2 ? 3 : 6;

    explicit RigidBodyMode(unsigned int mode) : dealii::Function<dim>(dim), mode(mode) {}
    void vector_value(const dealii::Point<dim> &p, dealii::Vector<double> &v) const override
    {
      for (unsigned int c = 0; c < dim; ++c)
        v[c] = rigid_body_mode_value<dim>(mode, c, p);
    }

  private:
    unsigned int mode;
  };

  // The modes as distributed vectors on the DoFs of a vector-valued element of dim components.
  template <int dim>
  std::vector<dealii::PETScWrappers::MPI::Vector>
  rigid_body_modes(const dealii::Mapping<dim> &mapping, const dealii::DoFHandler<dim> &dof_handler,
                   MPI_Comm communicator)
  {
    std::vector<dealii::PETScWrappers::MPI::Vector> modes;
    for (unsigned int m = 0; m < RigidBodyMode<dim>::n_modes; ++m)
      {
        modes.emplace_back(dof_handler.locally_owned_dofs(), communicator);
        dealii::VectorTools::interpolate(mapping, dof_handler, RigidBodyMode<dim>(m), modes.back());
      }
    return modes;
  }
} // namespace compliant
