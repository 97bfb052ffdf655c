// The shared discretization and the input it is built from, tested without running a case
// (issue 29, item 5): the DoF count of Q_p and mixed u-p elements on a refined structured mesh
// against the node count of the element, materials and boundary conditions resolved against the
// mesh's physical names, the refusals that name the case-file entry, and the list grammar every
// case-file list is written in.
#include <deal.II/base/mpi.h>
#include <deal.II/fe/mapping_q.h>

#include "discretization/discretization.h"
#include "input/spec_list.h"
#include "mesh/gmsh_geometry.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

using namespace compliant;

namespace
{
  // A 4 x 1 rectangle of nx x ny quadrilaterals with physical names left, right, top, body.
  MeshedGeometry rectangle(unsigned int nx, unsigned int ny)
  {
    const std::string file = "/tmp/compliant-discretization-check.geo";
    std::ofstream(file) << "Point(1) = {0, 0, 0}; Point(2) = {4, 0, 0}; Point(3) = {4, 1, 0}; "
                           "Point(4) = {0, 1, 0};\n"
                           "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                           "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                           "Transfinite Curve{1, 3} = " << nx + 1 << "; Transfinite Curve{2, 4} = " << ny + 1 << ";\n"
                           "Transfinite Surface{1}; Recombine Surface{1};\n"
                           "Physical Curve(\"left\") = {4}; Physical Curve(\"right\") = {2}; "
                           "Physical Curve(\"top\") = {3}; Physical Surface(\"body\") = {1};\n";
    MeshedGeometry geometry = mesh_geometry(file, {});
    std::remove(file.c_str());
    return geometry;
  }

  CaseParameters rectangle_case()
  {
    CaseParameters p;
    p.case_file          = "discretization_check.prm";
    p.mesh_file          = "rectangle.geo";
    p.dimension          = 2;
    p.model              = Model::plane_stress;
    p.element_degree     = 2;
    p.global_refinements = 1;
    p.thickness          = 2.5;
    p.unit_system        = UnitSystem::si;
    p.materials          = "*: steel";
    p.clamped            = "left";
    p.traction           = "right: 0 -1e3";
    p.displacement       = "top: y=0.001";
    return p;
  }

  // Every step of the set-up, in the order the problems run them.
  void build(Discretization<2> &d, bool with_pressure)
  {
    d.check_mesh_dimension();
    d.create_mesh();
    d.mixed = with_pressure;
    d.choose_element(with_pressure);
    d.assign_materials();
    d.resolve_boundary_conditions();
    d.distribute_dofs();
  }

  std::string resolve_error(const CaseParameters &p, const MeshedGeometry &g)
  {
    try
      {
        resolve_boundary_conditions<2>(p, g.boundary_ids);
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    return "";
  }
} // namespace

TEST(Discretization, QuadraticElementDofsMatchTheNodeCount)
{
  const MeshedGeometry geometry = rectangle(8, 2);
  ASSERT_EQ(geometry.n_cells, 16u);
  const CaseParameters p = rectangle_case();
  Discretization<2>    d(p, geometry, MPI_COMM_WORLD);
  build(d, false);
  // One global refinement: 16 x 4 cells; Q2 has (2 nx + 1)(2 ny + 1) nodes of 2 components.
  EXPECT_EQ(d.triangulation.n_global_active_cells(), 64u);
  EXPECT_EQ(d.fe->degree, 2u);
  EXPECT_EQ(d.fe->n_components(), 2u);
  EXPECT_EQ(d.dof_handler.n_dofs(), 2u * 33u * 9u);
  EXPECT_EQ(d.locally_owned_dofs.size(), d.dof_handler.n_dofs());
  EXPECT_EQ(d.hanging_node_constraints.n_constraints(), 0u); // uniform mesh: none
  EXPECT_NE(dynamic_cast<const dealii::MappingQ<2> *>(d.mapping.get()), nullptr);
  EXPECT_TRUE(d.plane_stress);
  EXPECT_DOUBLE_EQ(d.thickness, 2.5);
}

TEST(Discretization, MixedElementAddsADiscontinuousLinearPressure)
{
  const MeshedGeometry geometry = rectangle(8, 2);
  CaseParameters       p        = rectangle_case();
  p.model                       = Model::plane_strain; // mixed refuses plane stress
  Discretization<2> d(p, geometry, MPI_COMM_WORLD);
  build(d, true);
  // Q2 displacement plus a discontinuous P1 pressure: 3 pressure DoFs per cell.
  EXPECT_EQ(d.fe->n_components(), 3u);
  EXPECT_EQ(d.dof_handler.n_dofs(), 2u * 33u * 9u + 3u * 64u);
}

TEST(Discretization, MaterialsAndBoundaryConditionsResolvedAgainstTheMesh)
{
  const MeshedGeometry geometry = rectangle(4, 1);
  const CaseParameters p        = rectangle_case();
  Discretization<2>    d(p, geometry, MPI_COMM_WORLD);
  build(d, false);
  ASSERT_EQ(d.materials.size(), 1u);
  const Material &steel = d.materials.begin()->second;
  EXPECT_DOUBLE_EQ(steel.youngs_modulus, 200e9); // the library's steel, SI
  EXPECT_DOUBLE_EQ(steel.poissons_ratio, 0.3);
  const auto variables = d.expression_variables();
  EXPECT_DOUBLE_EQ(variables.at("E"), 200e9);
  EXPECT_DOUBLE_EQ(variables.at("G"), 200e9 / 2.6);
  EXPECT_DOUBLE_EQ(variables.at("thickness"), 2.5);

  const auto &bc = d.boundary_conditions;
  ASSERT_EQ(bc.clamped.size(), 1u);
  EXPECT_EQ(bc.clamped[0].second, geometry.boundary_ids.at("left"));
  ASSERT_EQ(bc.tractions.count(geometry.boundary_ids.at("right")), 1u);
  EXPECT_DOUBLE_EQ(bc.tractions.at(geometry.boundary_ids.at("right"))[1], -1e3);
  ASSERT_EQ(bc.displacements.size(), 1u);
  EXPECT_EQ(bc.displacements[0].mask, std::vector<bool>({false, true}));
  EXPECT_TRUE(bc.displacements[0].is_constant);
  EXPECT_DOUBLE_EQ(bc.displacements[0].values[1], 0.001);
}

TEST(Discretization, RefusalsNameTheEntryAndWhatWasExpected)
{
  const MeshedGeometry geometry = rectangle(4, 1);
  CaseParameters       p        = rectangle_case();
  p.clamped                     = "left, bottom";
  const std::string unknown     = resolve_error(p, geometry);
  EXPECT_NE(unknown.find("Boundary conditions/Clamped: unknown boundary 'bottom'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("'left' 'right' 'top'"), std::string::npos) << unknown; // the names it has

  p              = rectangle_case();
  p.displacement = "left: x=0";
  EXPECT_NE(resolve_error(p, geometry).find("boundary 'left' appears in both Boundary conditions/Clamped and "
                                            "Boundary conditions/Displacement"),
            std::string::npos);

  p          = rectangle_case();
  p.rotation = "right: angle=0.1, degrees=5";
  EXPECT_NE(resolve_error(p, geometry).find("needs exactly one of angle=<radians> or degrees=<deg>"),
            std::string::npos);

  p          = rectangle_case();
  p.traction = "right: 1 2 3";
  EXPECT_NE(resolve_error(p, geometry).find("Loads/Traction: 'right' needs 2 space-separated numbers or "
                                            "expressions"),
            std::string::npos);

  // An expression per component is kept as text, not refused.
  p          = rectangle_case();
  p.traction = "right: 0 -(1-y^2)";
  const auto bc = resolve_boundary_conditions<2>(p, geometry.boundary_ids);
  EXPECT_EQ(bc.traction_fields.at(geometry.boundary_ids.at("right"))[1], "-(1-y^2)");
}

TEST(SpecList, ItemsFieldsAndNumbers)
{
  const auto items = parse_spec_list("right: angle=0.01, center=100 5 0; left ; tip: 0 -1", "Test/Entry");
  ASSERT_EQ(items.size(), 3u);
  EXPECT_EQ(items[0].name, "right");
  EXPECT_EQ(items[0].get("angle"), "0.01");
  EXPECT_EQ(items[0].get("center"), "100 5 0");
  EXPECT_FALSE(items[0].has("axis"));
  EXPECT_EQ(items[1].name, "left");
  EXPECT_TRUE(items[1].fields.empty());
  ASSERT_EQ(items[2].fields.size(), 1u);
  EXPECT_TRUE(items[2].fields[0].key.empty()); // positional
  EXPECT_EQ(parse_numbers(items[2].fields[0].value, "Test/Entry"), std::vector<double>({0, -1}));
  EXPECT_EQ(parse_numbers("1e-3, 2", "Test/Entry"), std::vector<double>({1e-3, 2}));
  EXPECT_EQ(round_trip_text(0.1), "0.1");
  EXPECT_EQ(std::stod(round_trip_text(1.0 / 3)), 1.0 / 3);
}

TEST(SpecList, MalformedTextNamesTheEntry)
{
  for (const std::string text : {"1 x 2", "1 nan", "1 inf", ""})
    {
      if (text.empty())
        {
          EXPECT_TRUE(parse_numbers(text, "Test/Entry").empty());
          continue;
        }
      try
        {
          parse_numbers(text, "Test/Entry");
          ADD_FAILURE() << "'" << text << "' accepted";
        }
      catch (const std::invalid_argument &e)
        {
          EXPECT_NE(std::string(e.what()).find("Test/Entry"), std::string::npos) << e.what();
        }
    }
  for (const std::string text : {": x=1", "a: =1", "a: x=1,, y=2"})
    try
      {
        parse_spec_list(text, "Test/List");
        ADD_FAILURE() << "'" << text << "' accepted";
      }
    catch (const std::invalid_argument &e)
      {
        EXPECT_NE(std::string(e.what()).find("Test/List"), std::string::npos) << e.what();
      }
}
