// The long-edge coarse space (fast_solver/long_edge_space.h) and its Galerkin matrix:
// - its prolongation reproduces, to round-off, the degree-2 interpolant of every field quadratic
//   along the long direction and linear across it (Q(2,1,1) on cells long in x; Q(2,2,1) on plate
//   cells long in x and y), with a face held at zero; and it does not reproduce a field quadratic
//   across a cell (the check can fail);
// - the matrix the operator's kernel computes cell by cell equals P^T K P formed by PETSc from the
//   assembled degree-2 matrix, with full and with reduced integration;
// - cells long in x and z are long in a plate 1 thick and stay linear in a block 12 thick; a leaf
//   is thin across its thinner side; ghost cells of a distributed mesh take their owner's verdict;
// in 2D and 3D (the space) and 3D (the verdicts), on any rank count (ctest: 1 and 2 ranks).
#include <deal.II/base/function.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/numerics/vector_tools.h>

#include "fast_solver/elasticity_operator.h"
#include "fast_solver/long_cells.h"
#include "fast_solver/long_edge_space.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace dealii;

namespace
{
  using VectorType = LinearAlgebra::distributed::Vector<double>;

  // Cells 3 x 0.5 (x 0.5): long in x. plate: 3 x 3 x 0.5, long in x and y.
  template <int dim>
  void build_mesh(parallel::distributed::Triangulation<dim> &mesh, const bool plate)
  {
    std::vector<unsigned int> cells(dim, 2);
    cells[0] = 4;
    Point<dim> far;
    for (unsigned int d = 0; d < dim; ++d)
      far[d] = d == 0 ? 12. : 1.;
    if (plate)
      far[1] = 6.;
    GridGenerator::subdivided_hyper_rectangle(mesh, cells, Point<dim>(), far, true);
  }

  // Zero at x = 0. quadratic_across adds y^2 to the first component (not in the space).
  template <int dim>
  class Field : public Function<dim>
  {
  public:
    Field(const bool plate, const bool quadratic_across) : Function<dim>(dim), plate(plate), across(quadratic_across) {}
    double value(const Point<dim> &p, const unsigned int component) const override
    {
      const double x = p[0], y = p[1], z = dim == 3 ? p[2] : 0.5;
      switch (component)
        {
          case 0: return x * x + x * y * z + (across ? x * y * y : 0.) + (plate ? x * y * y : 0.);
          case 1: return x * x * y + 0.3 * x * z;
          default: return x * z + x * y - 0.2 * x * x * z;
        }
    }

  private:
    bool plate, across;
  };

  template <int dim>
  struct Model
  {
    parallel::distributed::Triangulation<dim> mesh{MPI_COMM_WORLD};
    FESystem<dim>                             fe{FE_Q<dim>(2), dim};
    DoFHandler<dim>                           dofs{mesh};
    AffineConstraints<double>                 constraints;
    compliant::fast_solver::LongEdgeSpace     space;

    explicit Model(const bool plate)
    {
      build_mesh(mesh, plate);
      dofs.distribute_dofs(fe);
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dofs, relevant);
      constraints.reinit(relevant);
      DoFTools::make_zero_boundary_constraints(dofs, 0, constraints);
      constraints.close();
      compliant::fast_solver::build_long_edge_space(dofs, constraints, compliant::fast_solver::find_long_cells(mesh, 3., 2.), space);
    }
  };

  // max |P (I U) - U| / max |U| over the unconstrained DoFs, U the field's degree-2 interpolant
  // and I the injection at the coarse DoFs.
  template <int dim>
  double reproduction_error(const bool plate, const bool quadratic_across)
  {
    Model<dim>     model(plate);
    const auto    &owned = model.dofs.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(model.dofs, relevant);
    VectorType     field(owned, relevant, MPI_COMM_WORLD); // interpolate writes every DoF of owned cells
    VectorTools::interpolate(MappingQ1<dim>(), model.dofs, Field<dim>(plate, quadratic_across), field);

    Vec coarse, fine;
    MatCreateVecs(model.space.prolongation, &coarse, &fine);
    PetscScalar *values;
    VecGetArray(coarse, &values);
    for (std::size_t i = 0; i < model.space.owned_coarse_dofs.size(); ++i)
      values[i] = field(model.space.owned_coarse_dofs[i]);
    VecRestoreArray(coarse, &values);
    MatMult(model.space.prolongation, coarse, fine);
    double largest_difference = 0, largest = 0;
    VecGetArray(fine, &values);
    unsigned int row = 0;
    for (const auto i : owned)
      {
        if (!model.constraints.is_constrained(i))
          {
            largest_difference = std::max(largest_difference, std::abs(values[row] - field(i)));
            largest            = std::max(largest, std::abs(field(i)));
          }
        ++row;
      }
    VecRestoreArray(fine, &values);
    VecDestroy(&coarse);
    VecDestroy(&fine);
    return Utilities::MPI::max(largest_difference, MPI_COMM_WORLD) / Utilities::MPI::max(largest, MPI_COMM_WORLD);
  }

  // |A_kernel - P^T K P|_F / |P^T K P|_F.
  template <int dim>
  double galerkin_difference(const bool plate, const double hourglass)
  {
    Model<dim>                                         model(plate);
    const MappingQ1<dim>                               mapping;
    compliant::fast_solver::ElasticityOperator<dim, double> op;
    op.reinit(mapping, model.dofs, model.constraints,
              [](types::material_id) { return std::make_pair(1.5, 1.0); }, hourglass);
    PETScWrappers::MPI::SparseMatrix fine_matrix;
    op.compute_matrix(fine_matrix, MPI_COMM_WORLD);
    Mat reference, kernel;
    MatPtAP(fine_matrix, model.space.prolongation, MAT_INITIAL_MATRIX, 2.0, &reference);

    const PetscInt n = model.space.n_owned_coarse;
    MatCreate(MPI_COMM_WORLD, &kernel);
    MatSetType(kernel, MATMPIAIJ);
    MatSetSizes(kernel, n, n, PETSC_DETERMINE, PETSC_DETERMINE);
    MatMPIAIJSetPreallocation(kernel, 200, nullptr, 200, nullptr);
    MatSetOption(kernel, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE);
    // Through the interface the multigrid uses (the operators override it privately).
    static_cast<const compliant::fast_solver::MatrixFreeOperatorBase<dim, double> &>(op).add_kernel_subspace_matrix(model.space, kernel);
    MatAssemblyBegin(kernel, MAT_FINAL_ASSEMBLY);
    MatAssemblyEnd(kernel, MAT_FINAL_ASSEMBLY);
    PetscReal scale, difference;
    MatNorm(reference, NORM_FROBENIUS, &scale);
    MatAXPY(kernel, -1., reference, DIFFERENT_NONZERO_PATTERN);
    MatNorm(kernel, NORM_FROBENIUS, &difference);
    MatDestroy(&reference);
    MatDestroy(&kernel);
    EXPECT_GT(scale, 1.);
    return difference / scale;
  }
} // namespace

TEST(LongEdgeSpace, ReproducesFieldsQuadraticAlongLongEdges)
{
  EXPECT_LT(reproduction_error<2>(false, false), 1e-13);
  EXPECT_LT(reproduction_error<3>(false, false), 1e-13);
  EXPECT_LT(reproduction_error<3>(true, false), 1e-13);
}

// The same x y^2 term the plate reproduces (y is long there) is quadratic across the bar's cells.
TEST(LongEdgeSpace, DoesNotReproduceFieldsQuadraticAcross)
{
  EXPECT_GT(reproduction_error<2>(false, true), 1e-3);
  EXPECT_GT(reproduction_error<3>(false, true), 1e-3);
}

TEST(LongEdgeSpace, GalerkinMatrixFromTheKernel)
{
  EXPECT_LT(galerkin_difference<2>(false, -1.), 1e-12);
  EXPECT_LT(galerkin_difference<3>(false, -1.), 1e-12);
  EXPECT_LT(galerkin_difference<3>(true, -1.), 1e-12);
  EXPECT_LT(galerkin_difference<3>(false, 0.02), 1e-12); // reduced integration, two rules
}

// Cells 3 x 0.5 x 3 stacked 2 deep make a plate 1 thick (each is long in x and z), stacked 24 deep
// a block 12 thick, 4 times their length (none is: linear, 6 : 1). On the solver's mesh type, whose
// every rank sees every cell, so that each walk through the stack is whole.
TEST(LongEdgeSpace, SlabsOfAThickBlockStayLinear)
{
  for (const unsigned int layers : {2u, 24u})
    {
      parallel::shared::Triangulation<3> mesh(MPI_COMM_WORLD, Triangulation<3>::none, false,
                                              parallel::shared::Triangulation<3>::partition_metis);
      GridGenerator::subdivided_hyper_rectangle(mesh, {2, layers, 2}, Point<3>(), Point<3>(6., 0.5 * layers, 6.));
      const auto   cells     = compliant::fast_solver::find_long_cells(mesh, 3., 2.);
      unsigned int long_ones = 0, owned = 0;
      for (const auto &cell : mesh.active_cell_iterators())
        if (cell->is_locally_owned())
          long_ones += cells.mask[cell->active_cell_index()] == 0b101, ++owned;
      EXPECT_EQ(Utilities::MPI::sum(owned, MPI_COMM_WORLD), 4 * layers);
      EXPECT_EQ(Utilities::MPI::sum(long_ones, MPI_COMM_WORLD), layers == 2 ? 8u : 0u);
      EXPECT_NEAR(cells.largest_linear_aspect_ratio, layers == 2 ? 1. : 6., 1e-12);
    }
}

// A leaf 12 wide and 1 thick in cells 3 x 0.5 x 0.5: across y the part is 12 thick, across z 1;
// the thinner side decides, and every cell is long in x.
TEST(LongEdgeSpace, ALeafIsThinAcrossItsThinnerSide)
{
  parallel::shared::Triangulation<3> mesh(MPI_COMM_WORLD, Triangulation<3>::none, false,
                                          parallel::shared::Triangulation<3>::partition_metis);
  GridGenerator::subdivided_hyper_rectangle(mesh, {4, 24, 2}, Point<3>(), Point<3>(12., 12., 1.));
  const auto   cells     = compliant::fast_solver::find_long_cells(mesh, 3., 2.);
  unsigned int long_ones = 0;
  for (const auto &cell : mesh.active_cell_iterators())
    if (cell->is_locally_owned())
      long_ones += cells.mask[cell->active_cell_index()] == 0b001;
  EXPECT_EQ(Utilities::MPI::sum(long_ones, MPI_COMM_WORLD), 4u * 24 * 2);
}

// Cells 3, 3, 0.5, 0.5, 1.5, 3 long in x along a bar 1 x 1 (long, long, cubes, cubes, 3:1, long) on
// p4est's mesh, whose ranks hold artificial cells: each cell this rank sees has the verdict the
// whole mesh gives on one rank (the ghosts get theirs from the owner).
TEST(LongEdgeSpace, GhostCellsTakeTheirOwnersVerdict)
{
  const std::vector<std::vector<double>> steps{{3., 3., 0.5, 0.5, 1.5, 3.}, {0.5, 0.5}, {0.5, 0.5}};
  const Point<3>                          far(11.5, 1., 1.);
  parallel::distributed::Triangulation<3> mesh(MPI_COMM_WORLD);
  Triangulation<3>                        whole;
  GridGenerator::subdivided_hyper_rectangle(mesh, steps, Point<3>(), far);
  GridGenerator::subdivided_hyper_rectangle(whole, steps, Point<3>(), far);
  const auto here = compliant::fast_solver::find_long_cells(mesh, 3., 2.);
  const auto all  = compliant::fast_solver::find_long_cells(whole, 3., 2.);
  std::map<long, unsigned int> by_column; // the verdict by the cell centre's x (in 1/100)
  for (const auto &cell : whole.active_cell_iterators())
    by_column[std::lround(100 * cell->center()[0])] = all.mask[cell->active_cell_index()];
  unsigned int seen = 0, long_ones = 0;
  for (const auto &cell : mesh.active_cell_iterators())
    if (!cell->is_artificial())
      {
        EXPECT_EQ(here.mask[cell->active_cell_index()], by_column.at(std::lround(100 * cell->center()[0])));
        ++seen, long_ones += here.mask[cell->active_cell_index()] == 0b001;
      }
  EXPECT_EQ(by_column.size(), 6u);
  EXPECT_GT(seen, long_ones);
  EXPECT_GT(long_ones, 0u);
  EXPECT_FALSE(here.thick_long_cells);
}
