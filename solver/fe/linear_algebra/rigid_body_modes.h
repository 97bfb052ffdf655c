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
  template <int dim>
  class RigidBodyMode : public dealii::Function<dim>
  {
  public:
    static constexpr unsigned int n_modes = dim == 2 ? 3 : 6;

    explicit RigidBodyMode(unsigned int mode) : dealii::Function<dim>(dim), mode(mode) {}
    void vector_value(const dealii::Point<dim> &p, dealii::Vector<double> &v) const override
    {
      v = 0;
      if (mode < dim)
        v[mode] = 1;
      else if (dim == 2)
        v[0] = -p[1], v[1] = p[0];
      else
        {
          const unsigned int axis = mode - dim, a = (axis + 1) % 3, b = (axis + 2) % 3;
          v[a] = -p[b];
          v[b] = p[a];
        }
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
