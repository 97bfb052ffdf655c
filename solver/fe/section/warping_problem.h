// Saint-Venant torsion of a prismatic bar reduced to its cross-section: the warping function
// omega(x, y), with the axial displacement w = theta' omega (Timoshenko and Goodier, Theory of
// Elasticity, 3rd ed., sec. 104):
//   Laplace(omega) = 0 in the section,  d omega/dn = y n_x - x n_y on its boundary,
// x, y measured from the centroid, and the mean of omega zero (omega is defined up to a constant).
// Serial: a cross-section mesh is small.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include "mesh/gmsh_geometry.h"

#include <memory>
#include <string>

namespace compliant::section
{
  class WarpingProblem
  {
  public:
    // Reads the 2D mesh text, refines it and picks FE_Q / FE_SimplexP of `degree` (1 to 3) by the
    // cell type. Throws std::invalid_argument naming `mesh_name` for a 3D or mixed mesh.
    WarpingProblem(const MeshedGeometry &geometry, unsigned int degree,
                   unsigned int refinements, const std::string &mesh_name);

    // Area and centroid, then the warping function about the centroid.
    void solve();

    // Point relative to the centroid (valid after solve()).
    dealii::Point<2> relative(const dealii::Point<2> &p) const { return p - centroid_offset; }

    dealii::Triangulation<2>                triangulation;
    dealii::DoFHandler<2>                   dof_handler;
    std::unique_ptr<dealii::FiniteElement<2>> fe;
    std::unique_ptr<dealii::Mapping<2>>     mapping;
    // Exact for every integrand of degree 2 * degree on affine cells (omega^2, x^2, ...).
    std::unique_ptr<dealii::Quadrature<2>>  quadrature;
    unsigned int                            degree;

    double                 area = 0;
    dealii::Point<2>       centroid;
    dealii::Vector<double> warping; // about the centroid, zero mean

  private:
    dealii::Tensor<1, 2> centroid_offset;

    void compute_area_and_centroid();
  };
} // namespace compliant::section
