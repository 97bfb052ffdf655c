// The discretization every problem builds on: the mesh (shared or distributed), the finite element
// (Q_p or P_p vector field, optionally with a discontinuous P_(p-1) pressure), the mapping and
// quadratures, the DoFs with their index sets and hanging-node constraints, the materials and the
// boundary conditions resolved against the mesh. Linear, finite-strain and modal problems derive
// from it; constraint builders (pins, mirror ties, edge supports) take it, so they serve every
// problem. Building is split into steps because each problem checks its own restrictions between
// them (finite strain: hexahedra only; mixed: no plane stress) with its own messages.
#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include "discretization/boundary_conditions.h"
#include "discretization/geometry_imperfection.h"
#include "materials/material.h"
#include "input/case_file.h"
#include "mesh/gmsh_geometry.h"
#include "mesh/mesh_partition.h"

#include <map>
#include <memory>
#include <string>

namespace compliant
{
  template <int dim>
  class Discretization
  {
  public:
    static constexpr int dimension = dim;

    // The mesh is shared unless the analysis chose to distribute it (mesh/mesh_partition.h).
    Discretization(const CaseParameters &parameters, const MeshedGeometry &geometry, MPI_Comm communicator,
                   const MeshPartitionChoice &partition = {});
    virtual ~Discretization();

    // Steps of the set-up, in this order. Throw std::invalid_argument naming the case-file entry.
    void check_mesh_dimension() const;  // the mesh is dim-dimensional
    void create_mesh();                 // refinements of the case applied, manifolds attached
    // Q_p (quadrilaterals, hexahedra) or P_p (triangles, tetrahedra, p <= 2) vector field; with
    // `with_pressure` (hypercubes only) a discontinuous P_(p-1) pressure as the last component.
    void choose_element(bool with_pressure);
    void assign_materials(); // Materials against the mesh's material ids
    void resolve_boundary_conditions(); // every boundary name against the mesh
    void distribute_dofs();  // DoFs, locally owned/relevant sets, hanging-node constraints

    // Names usable in Derived and Checks expressions: geometry parameters, thickness, and E, nu,
    // G of the first body's material.
    std::map<std::string, double> expression_variables() const;

    const CaseParameters                                     &parameters;
    const MeshedGeometry                                     &geometry;
    MPI_Comm                                                  communicator;
    MeshPartitionChoice                                       mesh_partition;
    std::unique_ptr<dealii::parallel::TriangulationBase<dim>> triangulation_storage;
    dealii::parallel::TriangulationBase<dim>                 &triangulation;
    std::unique_ptr<dealii::FiniteElement<dim>>               fe;
    // Set before choose_element: the mapping becomes the perfect geometry's plus this shift.
    std::shared_ptr<const GeometryImperfection>               imperfection;
    struct ImperfectionField; // the shift's DoFs and vector, which the mapping refers to
    std::unique_ptr<ImperfectionField>                        imperfection_field;
    std::unique_ptr<dealii::Mapping<dim>>                     mapping;
    // Points named in the case file are material points of the perfect geometry: located with its
    // mapping, evaluated with the (imperfect) one.
    const dealii::Mapping<dim> &point_mapping() const
    {
      return perfect_mapping ? *perfect_mapping : *mapping;
    }
    std::unique_ptr<dealii::Mapping<dim>> perfect_mapping; // with an imperfection only
    std::unique_ptr<dealii::Quadrature<dim>>                  quadrature;
    std::unique_ptr<dealii::Quadrature<dim - 1>>              face_quadrature;
    dealii::DoFHandler<dim>                                   dof_handler;
    dealii::IndexSet                                          locally_owned_dofs, locally_relevant_dofs;
    dealii::AffineConstraints<double>                         hanging_node_constraints; // adaptive meshes only
    std::map<int, Material>                                   materials;
    BoundaryConditions<dim>                                   boundary_conditions;
    double                                                    thickness; // 2D models; 1 in 3D
    // u-p with a discontinuous pressure, the last component (set by the problem before choose_element).
    bool mixed = false;
    // Model = plane stress (2D): the out-of-plane stress vanishes.
    const bool plane_stress;
  };
} // namespace compliant
