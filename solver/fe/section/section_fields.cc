#include "section/section_fields.h"

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace compliant::section
{
  using namespace dealii;

  namespace
  {
    class ShearStressPostprocessor : public DataPostprocessor<2>
    {
    public:
      ShearStressPostprocessor(const WarpingProblem &problem, const SectionProperties &section,
                               double shear_modulus, double torque)
        : problem(problem)
        , shift(section.shear_centre - section.centroid)
        , shear_modulus(shear_modulus)
        , stress_per_factor(torque / section.torsion_constant)
      {}

      void evaluate_scalar_field(const DataPostprocessorInputs::Scalar<2> &inputs,
                                 std::vector<Vector<double>> &computed) const override
      {
        for (unsigned int k = 0; k < inputs.solution_values.size(); ++k)
          {
            const Point<2>     p   = problem.relative(inputs.evaluation_points[k]);
            const Tensor<1, 2> tau = shear_per_unit_twist(inputs.solution_gradients[k], p);
            // omega_S = omega - y_s x + x_s y (section_properties.h)
            computed[k][0] = inputs.solution_values[k] - shift[1] * p[0] + shift[0] * p[1];
            computed[k][1] = shear_modulus * tau[0];
            computed[k][2] = shear_modulus * tau[1];
            computed[k][3] = stress_per_factor * tau[0];
            computed[k][4] = stress_per_factor * tau[1];
            computed[k][5] = stress_per_factor * tau.norm();
          }
      }

      std::vector<std::string> get_names() const override
      {
        return {"warping_about_shear_centre", "shear_stress_per_unit_twist",
                "shear_stress_per_unit_twist", "shear_stress", "shear_stress",
                "shear_stress_magnitude"};
      }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        using namespace DataComponentInterpretation;
        return {component_is_scalar,         component_is_part_of_vector,
                component_is_part_of_vector, component_is_part_of_vector,
                component_is_part_of_vector, component_is_scalar};
      }

      UpdateFlags get_needed_update_flags() const override
      {
        return update_values | update_gradients | update_quadrature_points;
      }

    private:
      const WarpingProblem &problem;
      const Tensor<1, 2>    shift;
      const double          shear_modulus, stress_per_factor;
    };
  } // namespace

  std::string write_section_fields(const WarpingProblem &problem, const SectionProperties &section,
                                   const double shear_modulus, const double torque,
                                   const std::string &directory)
  {
    DataOut<2> data_out;
    data_out.attach_dof_handler(problem.dof_handler);
    data_out.add_data_vector(problem.warping, "warping");
    ShearStressPostprocessor stress(problem, section, shear_modulus, torque);
    data_out.add_data_vector(problem.warping, stress);
    // Subdivided patches show the higher-order field; deal.II 9.4 supports them on hypercubes only.
    const bool hypercube = problem.triangulation.all_reference_cells_are_hyper_cube();
    data_out.build_patches(*problem.mapping, hypercube ? problem.degree : 1);

    const std::string file    = directory + "/section.vtu";
    const std::string partial = file + ".partial";
    {
      std::ofstream out(partial);
      data_out.write_vtu(out);
      if (!out)
        throw std::runtime_error("cannot write fields '" + partial + "'");
    }
    if (std::rename(partial.c_str(), file.c_str()) != 0)
      throw std::runtime_error("cannot rename '" + partial + "' to '" + file + "'");
    return file;
  }
} // namespace compliant::section
