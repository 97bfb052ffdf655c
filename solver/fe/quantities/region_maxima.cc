#include "quantities/region_maxima.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/fe/fe_values.h>

#include "elasticity/linear_elastic_problem.h"
#include "finite_strain/finite_strain_problem.h"
#include "input/spec_list.h"
#include "quantities/peak_sampling.h"

#include <limits>
#include <stdexcept>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    const char *axis_name[3] = {"x", "y", "z"};

    // Requested bodies as name -> material id; '*' stands for every body.
    std::map<std::string, int> requested_bodies(const CaseParameters             &p,
                                                const std::map<std::string, int> &bodies)
    {
      std::map<std::string, int> result;
      for (const auto &name : split(p.region_maxima, ','))
        {
          if (name.empty())
            continue;
          if (name == "*")
            {
              result.insert(bodies.begin(), bodies.end());
              continue;
            }
          const auto it = bodies.find(name);
          if (it == bodies.end())
            {
              std::string known;
              for (const auto &b : bodies)
                known += " '" + b.first + "'";
              throw std::invalid_argument("Quantities/Region maxima: unknown body '" + name +
                                          "'; the mesh's bodies are:" +
                                          (known.empty() ? " (none)" : known));
            }
          result.insert(*it);
        }
      return result;
    }

    // Largest principal strain: small strain, or lambda_1 - 1 from C = F^T F.
    template <int dim>
    double max_principal_strain(const Tensor<2, dim> &grad_u, const bool finite_strain)
    {
      if (!finite_strain)
        return eigenvalues(symmetrize(grad_u))[0];
      Tensor<2, dim> F = grad_u;
      for (unsigned int d = 0; d < dim; ++d)
        F[d][d] += 1;
      const double c1 = eigenvalues(symmetrize(transpose(F) * F))[0];
      return std::sqrt(std::max(c1, 0.0)) - 1;
    }
  } // namespace

  template <class Problem>
  void validate_region_maxima(const Problem &problem)
  {
    requested_bodies(problem.parameters, problem.geometry.material_ids);
  }

  template <class Problem>
  void add_region_maxima(const Problem &problem, Quantities &q)
  {
    constexpr int dim    = Problem::dimension;
    const auto    bodies = requested_bodies(problem.parameters, problem.geometry.material_ids);
    if (bodies.empty())
      return;
    MPI_Comm comm = problem.communicator;

    const Quadrature<dim> sample = peak_sample_points(*problem.quadrature, *problem.fe);
    const bool            has_pressure = problem.fe->n_components() > dim;
    const FEValuesExtractors::Vector u(0);
    const FEValuesExtractors::Scalar pressure(has_pressure ? dim : 0);
    FEValues<dim> values(*problem.mapping, *problem.fe, sample,
                         update_values | update_gradients | update_quadrature_points);
    std::vector<Tensor<2, dim>> grad(sample.size());
    std::vector<double>         p_values(sample.size(), 0.0);

    struct Peak
    {
      double     value = -std::numeric_limits<double>::max();
      Point<dim> where;
    };
    std::map<int, Peak> strain, stress; // by material id
    for (const auto &[name, id] : bodies)
      strain[id], stress[id];

    for (const auto &cell : problem.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() && strain.count(cell->material_id()))
        {
          const int       id       = cell->material_id();
          const Material &material = problem.materials.at(id);
          values.reinit(cell);
          values[u].get_function_gradients(problem.solution, grad);
          if (has_pressure)
            values[pressure].get_function_values(problem.solution, p_values);
          for (unsigned int k = 0; k < sample.size(); ++k)
            {
              const double e = max_principal_strain(grad[k], Problem::geometrically_nonlinear);
              if (e > strain[id].value)
                strain[id] = {e, values.quadrature_point(k)};
              double       sigma_zz;
              const auto   sigma = problem.cauchy_stress(grad[k], material, p_values[k], sigma_zz);
              const double vm    = problem.von_mises(sigma, sigma_zz);
              if (vm > stress[id].value)
                stress[id] = {vm, values.quadrature_point(k)};
            }
        }

    const auto reduce = [&](const Peak &local, const std::string &key) {
      const auto [value, where] = global_peak(local.value, local.where, comm);
      q[key] = value;
      for (unsigned int d = 0; d < dim; ++d)
        q[key + "_" + axis_name[d]] = where[d];
    };
    for (const auto &[name, id] : bodies)
      {
        reduce(strain[id], "max_principal_strain_in_" + name);
        reduce(stress[id], "max_von_mises_in_" + name);
      }
  }

  template void validate_region_maxima(const LinearElasticProblem<2> &);
  template void validate_region_maxima(const LinearElasticProblem<3> &);
  template void validate_region_maxima(const FiniteStrainProblem<2> &);
  template void validate_region_maxima(const FiniteStrainProblem<3> &);
  template void add_region_maxima(const LinearElasticProblem<2> &, Quantities &);
  template void add_region_maxima(const LinearElasticProblem<3> &, Quantities &);
  template void add_region_maxima(const FiniteStrainProblem<2> &, Quantities &);
  template void add_region_maxima(const FiniteStrainProblem<3> &, Quantities &);
} // namespace compliant
