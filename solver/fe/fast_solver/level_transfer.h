// The transfers between the p-multigrid's levels: degree k and k + 1 on one mesh, or on twin
// meshes whose cells come in the same order (the error estimates' degree-(p+1) model over the
// degree-p model's own levels). Cells are matched by level, index and ownership only: callers
// make sure twin meshes are the same mesh (PMultigridSolver compares their cells' centres).
//
// Where no constraint couples DoFs (supports held at zero, no hanging nodes, no periodicity) a
// cell-wise interpolation of our own, set up in one pass over the cells: each fine DoF is written
// by one cell that owns it, and the restriction is the exact transpose. deal.II's
// MGTwoLevelTransfer::reinit_polynomial_transfer matches cells by a consensus over their ids even
// on one mesh: 0.077 s of a 0.17 s multigrid set-up for 263k Q2 DoFs on one rank. Elsewhere (an
// adapted mesh) deal.II's transfer, per level.
#pragma once

#include <deal.II/base/mg_level_object.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/multigrid/mg_base.h>
#include <deal.II/multigrid/mg_transfer_global_coarsening.h>

#include <functional>
#include <memory>

namespace compliant::fast_solver
{
  template <int dim>
  class LevelTransfer : public dealii::MGTransferBase<dealii::LinearAlgebra::distributed::Vector<double>>
  {
  public:
    using VectorType       = dealii::LinearAlgebra::distributed::Vector<double>;
    using InitializeVector = std::function<void(unsigned int, VectorType &)>;

    // Level l (> min) transfers between dofs[l - 1] and dofs[l]; constraints: each level's
    // homogeneous ones; initialize: a level's vector layout (its operator's). The DoFHandlers
    // and constraints must outlive this object. own_transfer = false: deal.II's on every level.
    LevelTransfer(const dealii::MGLevelObject<const dealii::DoFHandler<dim> *>    &dofs,
                  const dealii::MGLevelObject<dealii::AffineConstraints<double>> &constraints,
                  const InitializeVector &initialize, bool own_transfer = true);
    ~LevelTransfer() override;

    void prolongate(unsigned int to_level, VectorType &dst, const VectorType &src) const override;
    void prolongate_and_add(unsigned int to_level, VectorType &dst, const VectorType &src) const override;
    void restrict_and_add(unsigned int from_level, VectorType &dst, const VectorType &src) const override;

    // As MGTransferGlobalCoarsening: PreconditionMG's copies between the fine vector and the levels.
    template <class InVector>
    void copy_to_mg(const dealii::DoFHandler<dim> &, dealii::MGLevelObject<VectorType> &dst, const InVector &src) const
    {
      for (unsigned int level = dst.min_level(); level <= dst.max_level(); ++level)
        {
          initialize(level, dst[level]);
          if (level == dst.max_level())
            dst[level].copy_locally_owned_data_from(src);
          else
            dst[level] = 0.;
        }
    }
    template <class OutVector>
    void copy_from_mg(const dealii::DoFHandler<dim> &, OutVector &dst, const dealii::MGLevelObject<VectorType> &src) const
    {
      dst.copy_locally_owned_data_from(src[src.max_level()]);
    }
    template <class OutVector>
    void copy_from_mg_add(const dealii::DoFHandler<dim> &, OutVector &dst,
                          const dealii::MGLevelObject<VectorType> &src) const
    {
      dst += src[src.max_level()];
    }

    // Levels served by the cell-wise transfer (the others by deal.II's).
    unsigned int n_own_levels() const;

  private:
    struct CellWise;
    dealii::MGLevelObject<std::unique_ptr<CellWise>>                        own;
    dealii::MGLevelObject<dealii::MGTwoLevelTransfer<dim, VectorType>>      dealii_transfers;
    InitializeVector                                                        initialize;
  };
} // namespace compliant::fast_solver
