// Samples a solution for a picture: each owned cell (2D) or outer face (3D) cut into sub-cells of
// the element's degree, so that quadratic cells show their curvature, with the displacement and a
// value at each corner; the 2D boundary as segments. Collective; the result is complete on rank 0
// (the other ranks get an empty geometry).
#pragma once

#include <deal.II/lac/petsc_vector.h>

#include "discretization/discretization.h"
#include "output/picture_geometry.h"

#include <functional>

namespace compliant
{
  // The colouring value at a point from the displacement, its gradient, the pressure (mixed
  // formulation; 0 otherwise) and the cell's material.
  template <int dim>
  using PictureValue = std::function<double(const dealii::Tensor<1, dim> &u, const dealii::Tensor<2, dim> &grad_u,
                                            double pressure, const Material &material)>;

  // `ghosted`: a vector with the locally relevant DoFs.
  template <int dim>
  PictureGeometry sample_picture(const Discretization<dim> &discretization,
                                 const dealii::PETScWrappers::MPI::Vector &ghosted,
                                 const PictureValue<dim> &value);

  // The converged state coloured by von Mises (Cauchy stress).
  // Problem: LinearElasticProblem<dim> or FiniteStrainProblem<dim>.
  template <class Problem>
  PictureGeometry sample_von_mises(const Problem &problem);
} // namespace compliant
