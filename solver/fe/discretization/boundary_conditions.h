// Boundary conditions and loads of a case, resolved against the mesh's physical names.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include "input/case_file.h"

#include <map>
#include <string>
#include <vector>

namespace compliant
{
  template <int dim>
  struct PrescribedRotation
  {
    int                     boundary_id;
    std::string             boundary;
    double                  angle; // radians
    dealii::Point<3>        center;
    dealii::Tensor<1, 3>    axis; // unit vector
  };

  template <int dim>
  struct PrescribedDisplacement
  {
    int                  boundary_id;
    std::string          boundary;
    std::vector<bool>        mask;        // per component
    std::vector<double>      values;      // per component, when constant
    std::vector<std::string> expressions; // per component, muparser in x, y, z ("0" if free)
    bool                     is_constant = true;
  };

  // A boundary moving as a rigid body under a dead force and moment (Boundary conditions/Rigid).
  template <int dim>
  struct RigidBoundaryLoad
  {
    int                    boundary_id;
    std::string            boundary;
    dealii::Tensor<1, dim> force;
    dealii::Tensor<1, 3>   moment; // 2D: z only
    bool                   has_center = false;
    dealii::Point<3>       center;
  };

  template <int dim>
  struct BoundaryConditions
  {
    std::vector<std::pair<std::string, int>>     clamped;
    std::vector<PrescribedDisplacement<dim>>     displacements;
    std::vector<PrescribedRotation<dim>>         rotations;
    std::vector<RigidBoundaryLoad<dim>>          rigid;
    std::map<int, dealii::Tensor<1, dim>>        tractions;     // per boundary id
    // Tractions given as expressions of x, y, z and geometry parameters, per boundary id.
    std::map<int, std::vector<std::string>>      traction_fields;
    std::map<std::string, dealii::Tensor<1, dim>> total_forces; // by boundary name
    // Normal pressure (number or expression of x, y, z) per boundary id: t = -p n.
    std::map<int, std::string>                   pressures;
    dealii::Tensor<1, dim>                       body_force;
    dealii::Tensor<1, dim>                       gravity;
  };

  // Throws std::invalid_argument naming the entry for an unknown boundary or a malformed value.
  template <int dim>
  BoundaryConditions<dim> resolve_boundary_conditions(const CaseParameters             &p,
                                                      const std::map<std::string, int> &boundaries);

  // Looks a boundary name up; the message lists the names the mesh has.
  int boundary_id_of(const std::string &name, const std::map<std::string, int> &boundaries,
                     const std::string &where);

  template <int dim>
  dealii::Tensor<1, dim> parse_vector(const std::string &text, const std::string &where);
} // namespace compliant
