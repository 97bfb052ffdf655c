// The p-multigrid's own level transfer (fast_solver/level_transfer.h) against deal.II's
// MGTwoLevelTransfer on the same two levels: prolongation and restriction of random vectors agree
// to round-off in 2D and 3D, from degree 1 to 2 up to 3 to 4, with a boundary held at zero, on a
// curved (smoothly transformed) mesh, on one mesh and across twin meshes (the error estimates'
// enriched model over the model's own levels), on any rank count (the ctest runs it on 1 and on 2
// ranks). On a mesh with hanging nodes the own transfer steps aside and deal.II's serves.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/matrix_free/matrix_free.h>
#include <deal.II/numerics/vector_tools.h>

#include "fast_solver/level_transfer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace dealii;

namespace
{
  using VectorType = LinearAlgebra::distributed::Vector<double>;

  struct Comparison
  {
    double       prolongation = 0, restriction = 0; // largest difference / largest entry
    double       smallest_entry_scale = 0;          // of the two reference results (not vacuous)
    unsigned int own_levels   = 0;
  };

  // Random owned entries, zero where held (the state the V-cycle keeps them in).
  void fill_random(VectorType &v, const AffineConstraints<double> &constraints, std::mt19937 &random)
  {
    std::uniform_real_distribution<double> value(-1., 1.);
    for (const auto i : v.locally_owned_elements())
      v(i) = constraints.is_constrained(i) ? 0. : value(random);
  }

  double relative_difference(const VectorType &a, const VectorType &b)
  {
    VectorType difference = a;
    difference -= b;
    return difference.linfty_norm() / std::max(b.linfty_norm(), 1e-300);
  }

  template <int dim>
  void build_mesh(parallel::distributed::Triangulation<dim> &mesh, const bool hanging)
  {
    std::vector<unsigned int> cells(dim, 2);
    cells[0] = 4;
    Point<dim> far;
    for (unsigned int d = 0; d < dim; ++d)
      far[d] = d == 0 ? 4. : 2.;
    GridGenerator::subdivided_hyper_rectangle(mesh, cells, Point<dim>(), far, true);
    if (hanging)
      {
        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->is_locally_owned() && cell->center()[0] < 1.)
            cell->set_refine_flag();
        mesh.execute_coarsening_and_refinement();
      }
    GridTools::transform(
      [](const Point<dim> &p) {
        Point<dim> q = p;
        q[0] += 0.15 * std::sin(p[1]);
        q[1] += 0.1 * std::sin(0.7 * p[0]);
        return q;
      },
      mesh);
  }

  // twin: the coarse DoFs on a second mesh built the same way.
  template <int dim>
  Comparison compare(const unsigned int fine_degree, const bool hanging, const bool twin = false)
  {
    const MPI_Comm                            comm = MPI_COMM_WORLD;
    parallel::distributed::Triangulation<dim> mesh(comm), twin_mesh(comm);
    build_mesh(mesh, hanging);
    if (twin)
      build_mesh(twin_mesh, hanging);

    const FESystem<dim> fine_fe(FE_Q<dim>(fine_degree), dim), coarse_fe(FE_Q<dim>(fine_degree - 1), dim);
    DoFHandler<dim>     fine_dofs(mesh), coarse_dofs(twin ? twin_mesh : mesh);
    fine_dofs.distribute_dofs(fine_fe);
    coarse_dofs.distribute_dofs(coarse_fe);
    MGLevelObject<const DoFHandler<dim> *>    dofs(0, 1);
    MGLevelObject<AffineConstraints<double>> constraints(0, 1);
    dofs[0] = &coarse_dofs, dofs[1] = &fine_dofs;
    const MappingQ1<dim>                   mapping;
    MGLevelObject<MatrixFree<dim, double>> layouts(0, 1);
    for (unsigned int level = 0; level <= 1; ++level)
      {
        IndexSet relevant;
        DoFTools::extract_locally_relevant_dofs(*dofs[level], relevant);
        constraints[level].reinit(relevant);
        DoFTools::make_hanging_node_constraints(*dofs[level], constraints[level]);
        VectorTools::interpolate_boundary_values(mapping, *dofs[level], 0, Functions::ZeroFunction<dim>(dim),
                                                 constraints[level]);
        constraints[level].close();
        layouts[level].reinit(mapping, *dofs[level], constraints[level], QGauss<1>(fine_degree + 1));
      }
    const auto initialize = [&](const unsigned int level, VectorType &v) { layouts[level].initialize_dof_vector(v); };

    compliant::fast_solver::LevelTransfer<dim> own(dofs, constraints, initialize);
    MGTwoLevelTransfer<dim, VectorType>        reference;
    reference.reinit_polynomial_transfer(fine_dofs, coarse_dofs, constraints[1], constraints[0]);

    std::mt19937 random(7 + Utilities::MPI::this_mpi_process(comm));
    VectorType   coarse, fine, own_result, reference_result;
    initialize(0, coarse);
    initialize(1, fine);
    Comparison result;
    result.own_levels = own.n_own_levels();

    fill_random(coarse, constraints[0], random);
    initialize(1, own_result);
    initialize(1, reference_result);
    own.prolongate(1, own_result, coarse);
    reference.prolongate_and_add(reference_result, coarse);
    result.prolongation = relative_difference(own_result, reference_result);
    result.smallest_entry_scale = reference_result.linfty_norm();

    fill_random(fine, constraints[1], random);
    initialize(0, own_result);
    initialize(0, reference_result);
    own.restrict_and_add(1, own_result, fine);
    reference.restrict_and_add(reference_result, fine);
    result.restriction = relative_difference(own_result, reference_result);
    result.smallest_entry_scale = std::min(result.smallest_entry_scale, reference_result.linfty_norm());
    return result;
  }
} // namespace

TEST(LevelTransfer, AgreesWithDealIIs)
{
  for (unsigned int degree = 2; degree <= 4; ++degree)
    {
      const auto plane = compare<2>(degree, false);
      EXPECT_EQ(plane.own_levels, 1u) << "2D, degree " << degree;
      EXPECT_LT(plane.prolongation, 1e-13) << "2D, degree " << degree;
      EXPECT_LT(plane.restriction, 1e-13) << "2D, degree " << degree;
      EXPECT_GT(plane.smallest_entry_scale, 0.1) << "2D, degree " << degree;
      const auto solid = compare<3>(degree, false);
      EXPECT_EQ(solid.own_levels, 1u) << "3D, degree " << degree;
      EXPECT_LT(solid.prolongation, 1e-13) << "3D, degree " << degree;
      EXPECT_LT(solid.restriction, 1e-13) << "3D, degree " << degree;
      EXPECT_GT(solid.smallest_entry_scale, 0.1) << "3D, degree " << degree;
    }
}

TEST(LevelTransfer, AcrossTwinMeshes)
{
  const auto plane = compare<2>(2, false, true);
  EXPECT_EQ(plane.own_levels, 1u);
  EXPECT_LT(plane.prolongation, 1e-13);
  EXPECT_LT(plane.restriction, 1e-13);
  const auto solid = compare<3>(2, false, true);
  EXPECT_EQ(solid.own_levels, 1u);
  EXPECT_LT(solid.prolongation, 1e-13);
  EXPECT_LT(solid.restriction, 1e-13);
}

TEST(LevelTransfer, HangingNodesTakeDealIIs)
{
  const auto plane = compare<2>(2, true);
  EXPECT_EQ(plane.own_levels, 0u);
  EXPECT_LT(plane.prolongation, 1e-15);
  EXPECT_LT(plane.restriction, 1e-15);
  const auto solid = compare<3>(3, true);
  EXPECT_EQ(solid.own_levels, 0u);
}
