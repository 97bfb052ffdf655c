// Rung (a): a closed form of Comparison/Checks whose own error bound meets the target, for this
// Model, with arguments known before any FE solve, answers the quantity. All target quantities
// answered: the ladder stops with no FE model.
#include <closed_forms/registry.h>

#include "input/expression.h"
#include "input/spec_list.h"
#include "ladder/ladder_climb.h"
#include "ladder/percent.h"
#include "materials/material.h"
#include "quantities/comparison.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>

namespace compliant
{
  namespace
  {
    struct Answer
    {
      std::string formula, basis;
      double      value = 0, bound = 0;
    };

    void write_closed_form_results(const CaseParameters &p, const std::vector<std::string> &names,
                                   std::map<std::string, Answer> &answers, const double target_error,
                                   const double seconds)
    {
      RunSummary summary;
      summary.case_file  = p.case_file;
      summary.settings   = {{"analysis", p.analysis}, {"model", to_string(p.model)},
                            {"ladder", "target met by closed forms (rung a)"}};
      summary.parameters = p.geometry_parameters;
      for (const auto &[n, a] : answers)
        {
          summary.quantities[n]                     = a.value;
          summary.quantities[n + "_error_estimate"] = a.bound;
          summary.settings.insert({n + "_closed_form", a.formula + ": " + a.basis});
        }
      summary.quantities["ladder_rungs"]          = 1;
      summary.quantities["ladder_total_seconds"]  = seconds;
      summary.quantities["target_relative_error"] = target_error;
      std::filesystem::create_directories(p.output_directory);
      write_summary(summary, p.output_directory + "/summary.json");
      std::ofstream out(p.output_directory + "/ladder.csv.tmp");
      out << "rung,model,degree,refinements,adaptive_cycles,dofs,seconds,cumulative_seconds";
      for (const auto &n : names)
        out << ',' << n << ",estimate_" << n << ",stop_estimate_" << n;
      out << "\n1,closed form,0,0,0,0," << seconds << ',' << seconds << std::setprecision(10);
      for (const auto &n : names)
        out << ',' << answers[n].value << ',' << answers[n].bound << ',' << answers[n].bound;
      out << "\n";
      out.close();
      std::filesystem::rename(p.output_directory + "/ladder.csv.tmp", p.output_directory + "/ladder.csv");
      std::cout << "\n" << format_table(summary) << "\nResults in " << p.output_directory
                << "/ (summary.json, ladder.csv)" << std::endl;
    }
  } // namespace

  template <int dim>
  std::optional<int> LadderClimb<dim>::answer_by_closed_forms()
  {
    std::map<std::string, Answer> answers;
    const auto materials = assign_materials(p.materials, context.geometry.material_ids, p.unit_system);
    const auto variables = expression_variables(p.geometry_parameters, materials.begin()->second,
                                                dim == 2 ? p.thickness : 1.0);
    // A plane-stress model paired with its 3D part answers for the part.
    const std::string part_model = to_string(dim == 2 && paired ? Model::three_d : p.model);
    for (const auto &n : names)
      {
        std::string why             = "no closed form in Comparison/Checks";
        double      smallest_failed = std::numeric_limits<double>::infinity();
        for (const auto &check : parse_checks(p.checks))
          {
            if (check.quantity != n)
              continue;
            std::map<std::string, double> arguments;
            try
              {
                for (const auto &[argument, expression] : check.arguments)
                  arguments[argument] = evaluate_expression(expression, variables, "Comparison/Checks");
              }
            catch (const std::invalid_argument &)
              {
                why = check.formula + " needs FE results in its arguments";
                continue;
              }
            closed_forms::Result result;
            try
              {
                result = closed_forms::evaluate(check.formula, arguments);
              }
            catch (const std::exception &e)
              {
                throw InputError("case file '" + p.case_file + "', Comparison/Checks '" + n + " ~ " +
                                 check.formula + "': " + e.what());
              }
            if (!std::isfinite(result.error_bound))
              {
                why = check.formula + " has no error bound";
                continue;
              }
            if (std::find(result.bound_models.begin(), result.bound_models.end(), part_model) ==
                result.bound_models.end())
              {
                why = check.formula + "'s bound does not hold for Model = " + part_model +
                      (part_model != to_string(p.model) ? " (the 3D part this model stands for)" : "");
                continue;
              }
            const Answer answer{check.formula, result.error_bound_basis, result.value, result.error_bound};
            if (answer.bound <= target.relative_error && (!answers.count(n) || answer.bound < answers[n].bound))
              answers[n] = answer;
            else if (answer.bound > target.relative_error && answer.bound < smallest_failed)
              {
                smallest_failed = answer.bound; // report the closest miss
                why = check.formula + ": bound " + percent(answer.bound) + " > target (" + answer.basis + ")";
              }
          }
        if (root && answers.count(n))
          std::cout << "  (a) " << n << " = " << std::setprecision(8) << answers[n].value << " by "
                    << answers[n].formula << ", bound " << percent(answers[n].bound) << " <= target ("
                    << answers[n].basis << ")" << std::endl;
        else if (root)
          std::cout << "  (a) " << n << ": " << why << std::endl;
      }
    if (target.closed_forms && answers.size() == names.size())
      {
        if (root)
          std::cout << "  (a) every target quantity is answered by a closed form: stop, no FE model" << std::endl;
        check_output_directory(p, context.communicator);
        if (context.check_only)
          return 0;
        if (root)
          write_closed_form_results(p, names, answers, target.relative_error, total.wall_time());
        return 0;
      }
    if (root && !target.closed_forms && !answers.empty())
      std::cout << "  (a) Target/Closed forms = false: climbing anyway" << std::endl;
    return std::nullopt;
  }

  template std::optional<int> LadderClimb<2>::answer_by_closed_forms();
  template std::optional<int> LadderClimb<3>::answer_by_closed_forms();
} // namespace compliant
