// The common end of every field output: material id and partition per cell, patches
// (subdivided on hypercubes to show higher-order fields), fields.h5 + fields.xdmf written under
// temporary names and renamed when complete. Included by .cc files only (DataOut is heavy).
#pragma once

#include <deal.II/numerics/data_out.h>

#include <string>

namespace compliant
{
  // Problem: LinearElasticProblem<dim> or FiniteStrainProblem<dim>. Returns the .xdmf path.
  template <class Problem>
  std::string write_field_files(dealii::DataOut<Problem::dimension> &data_out,
                                const Problem &problem, const std::string &directory);
} // namespace compliant
