// The prolongation to a once-refined twin mesh (discretization/refinement_transfer.h), which the
// error estimates' two-level solve on triangles and tetrahedra stands on: P2 on the coarse mesh
// lies in P2 on the refined one, so P applied to the coarse interpolant of a quadratic field must
// give the fine interpolant of the same field to round-off, on every child of every cell.
#include <deal.II/base/function.h>
#include <deal.II/numerics/vector_tools.h>

#include "discretization/discretization.h"
#include "discretization/refinement_transfer.h"
#include "mesh/gmsh_geometry.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

using namespace compliant;

namespace
{
  // A 2 x 1 rectangle (or 2 x 1 x 1 box) of triangles (tetrahedra), physical names left and body.
  MeshedGeometry simplex_block(const int dim)
  {
    const std::string file = "/tmp/compliant-refinement-transfer-check.geo";
    if (dim == 2)
      std::ofstream(file) << "Point(1) = {0, 0, 0, 0.4}; Point(2) = {2, 0, 0, 0.4}; Point(3) = {2, 1, 0, 0.4}; "
                             "Point(4) = {0, 1, 0, 0.4};\n"
                             "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                             "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                             "Physical Curve(\"left\") = {4}; Physical Surface(\"body\") = {1};\n";
    else
      std::ofstream(file) << "SetFactory(\"OpenCASCADE\"); Box(1) = {0, 0, 0, 2, 1, 1};\n"
                             "Mesh.CharacteristicLengthMax = 0.5;\n"
                             "Physical Surface(\"left\") = {1}; Physical Volume(\"body\") = {1};\n";
    MeshedGeometry geometry = mesh_geometry(file, {});
    std::remove(file.c_str());
    return geometry;
  }

  CaseParameters simplex_case(const int dim, const unsigned int refinements)
  {
    CaseParameters p;
    p.case_file          = "refinement_transfer_check.prm";
    p.mesh_file          = "block.geo";
    p.dimension          = dim;
    p.model              = dim == 2 ? Model::plane_stress : Model::three_d;
    p.element_degree     = 2;
    p.global_refinements = refinements;
    p.unit_system        = UnitSystem::si;
    p.materials          = "*: steel";
    p.clamped            = "left";
    return p;
  }

  template <int dim>
  void build(Discretization<dim> &d)
  {
    d.check_mesh_dimension();
    d.create_mesh();
    d.choose_element(false);
    d.assign_materials();
    d.resolve_boundary_conditions();
    d.distribute_dofs();
  }

  // A quadratic field with every monomial of degree 2 present.
  template <int dim>
  class Quadratic : public dealii::Function<dim>
  {
  public:
    Quadratic() : dealii::Function<dim>(dim) {}
    double value(const dealii::Point<dim> &x, const unsigned int c) const override
    {
      const double z = dim == 3 ? x[dim - 1] : 0.3;
      return (c + 1) * x[0] * x[0] - 0.7 * x[0] * x[1] + 0.4 * x[1] * x[1] + z * (x[0] - 2 * z) + 0.1 * c;
    }
  };

  template <int dim>
  void check_quadratic_carried_exactly()
  {
    const MeshedGeometry      geometry = simplex_block(dim);
    const CaseParameters      pc = simplex_case(dim, 0), pf = simplex_case(dim, 1);
    Discretization<dim>       coarse(pc, geometry, MPI_COMM_WORLD), fine(pf, geometry, MPI_COMM_WORLD);
    build(coarse);
    build(fine);
    ASSERT_FALSE(coarse.triangulation.all_reference_cells_are_hyper_cube());
    dealii::AffineConstraints<double> none;
    none.close();
    dealii::PETScWrappers::MPI::SparseMatrix prolongation;
    ASSERT_TRUE(build_refinement_prolongation<dim>(coarse, fine, none, prolongation));

    dealii::PETScWrappers::MPI::Vector u_coarse(coarse.locally_owned_dofs, MPI_COMM_WORLD),
      u_fine(fine.locally_owned_dofs, MPI_COMM_WORLD), carried(fine.locally_owned_dofs, MPI_COMM_WORLD);
    // Interpolation at the support points of the reference cell (no mapping: the straight block).
    dealii::VectorTools::interpolate(*coarse.mapping, coarse.dof_handler, Quadratic<dim>(), u_coarse);
    dealii::VectorTools::interpolate(*fine.mapping, fine.dof_handler, Quadratic<dim>(), u_fine);
    prolongation.vmult(carried, u_coarse);
    carried -= u_fine;
    EXPECT_LT(carried.linfty_norm(), 1e-12 * u_fine.linfty_norm()) << dim << "D";
    EXPECT_GT(u_fine.linfty_norm(), 1.);

    // Not a twin: the mesh refined twice is refused, P untouched.
    const CaseParameters p2 = simplex_case(dim, 2);
    Discretization<dim>  twice(p2, geometry, MPI_COMM_WORLD);
    build(twice);
    dealii::PETScWrappers::MPI::SparseMatrix other;
    EXPECT_FALSE(build_refinement_prolongation<dim>(coarse, twice, none, other));
  }
} // namespace

TEST(RefinementTransfer, TrianglesCarryAQuadraticExactly)
{
  check_quadratic_carried_exactly<2>();
}

TEST(RefinementTransfer, TetrahedraCarryAQuadraticExactly)
{
  check_quadratic_carried_exactly<3>();
}
