#include "ladder/model_ladder.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/fe/fe_values.h>

#include "analyses/linear_static_model.h"
#include "analyses/nonlinear_static.h"
#include "input/spec_list.h"
#include "quantities/comparison.h"
#include "quantities/out_of_plane_bound.h"
#include "materials/material.h"
#include "input/expression.h"
#include <closed_forms/registry.h>
#include "ladder/adaptive_refinement.h"
#include "ladder/error_estimate.h"
#include "ladder/paired_model.h"
#include "mesh/memory_estimate.h"
#include "output/field_output.h"
#include "output/summary.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

namespace compliant
{
  void declare_target_settings(dealii::ParameterHandler &prm)
  {
    using namespace dealii;
    prm.enter_subsection("Target");
    prm.declare_entry("Relative error", "0", Patterns::Double(0, 100),
                      "Percent. 0: solve the model as set. > 0: the model ladder refines (Target/Refinement) "
                      "until the Richardson estimate of every target quantity's discretization "
                      "error is below this, and moves to finite strain when the rotations of the "
                      "linear answer make the geometric error (theta^2) larger (linear static only).");
    prm.declare_entry("Quantities", "", Patterns::Anything(),
                      "Reported quantities the target applies to, comma-separated, e.g. "
                      "'rotational_stiffness_drive, displacement_tip_y'. Empty: the quantities "
                      "named on the left of Comparison/Checks.");
    prm.declare_entry("Allow finite strain", "true", Patterns::Bool(),
                      "false: stay linear even when the rotations call for finite strain (a linear "
                      "benchmark); the ladder still prints the geometric estimate.");
    prm.declare_entry("Maximum refinements", "4", Patterns::Integer(1, 12),
                      "Rungs the ladder may add after the first, in each of the linear and the "
                      "finite-strain climbs: halvings of the mesh of Discretization/Global "
                      "refinements, adaptive cycles, or degree steps (degree rungs: 2 -> 3 -> 4 "
                      "count as two).");
    prm.declare_entry("Refinement", "auto", Patterns::Selection("auto|uniform|adaptive|degree"),
                      "auto: degree on hexahedral 3D models (a degree step costs about 3x the DoFs "
                      "where halving the cells costs 8x, and a uniform climb needs the rung after "
                      "the first that meets the target to observe an order), uniform otherwise "
                      "(2D, and tetrahedra after the first rung at degree 2). "
                      "uniform: every rung halves every cell. adaptive: every rung refines the cells "
                      "with the largest Kelly indicators (gradient jumps), leaving hanging nodes; "
                      "quadrilateral and hexahedral meshes only. degree: the rungs raise the "
                      "element degree on the case's mesh, 2, 3, 4 (only 2 on triangles and "
                      "tetrahedra), then halve every cell at the highest degree; the error is extrapolated in the DoF "
                      "count (p-extension); finite-strain rungs climb in degree too. A degree step "
                      "costs about 3x the DoFs in 3D where halving the cells costs 8x. "
                      "Discretization/Element degree is then not used. Finite-strain rungs climb "
                      "uniformly at Discretization/Element degree under auto, uniform and adaptive "
                      "(the tangent's assembly cost grows steeply with the degree).");
    prm.declare_entry("Closed forms", "true", Patterns::Bool(),
                      "Rung (a): true lets a closed form of Comparison/Checks answer a target "
                      "quantity without any FE model when its error bound (geometric "
                      "nonlinearity, shear, root restraint: see --help's closed forms) meets the "
                      "target for the case's Model and its arguments need no FE result. The case's "
                      "load and supports are taken to be the formula's. false: always climb.");
    prm.declare_entry("Refined cell fraction", "0.3", Patterns::Double(0.01, 1),
                      "Adaptive refinement: the fraction of cells refined per rung (largest "
                      "indicators first).");
    prm.declare_entry("Paired model", "", Patterns::Anything(),
                      "Rung (b) across dimensions: the case file of the same part in the other "
                      "dimension, 'case.prm[: Section/Entry=expression, ...]' (next to this case; "
                      "the expressions over this case's geometry parameters and thickness; "
                      "same-named geometry parameters and --set Material/Materials and Unit system "
                      "carry over). A 3D case names its plane-stress model: the ladder climbs it "
                      "first and stops there when its out-of-plane bound plus its discretization "
                      "estimate meet the target, else climbs the 3D case. A plane-stress case names "
                      "its 3D part: the ladder climbs the 3D case when the bound misses. Both must "
                      "report the target quantities under the same names and have the same materials "
                      "and volume (2D: area times Material/Thickness), checked; and the same loads and "
                      "supports, not checked. Read only with a target. Empty: the dimension stays as "
                      "Model sets it.");
    prm.leave_subsection();
  }

  TargetSettings read_target_settings(dealii::ParameterHandler &prm)
  {
    TargetSettings t;
    prm.enter_subsection("Target");
    t.relative_error  = prm.get_double("Relative error") / 100;
    t.max_refinements = prm.get_integer("Maximum refinements");
    t.allow_finite_strain = prm.get_bool("Allow finite strain");
    t.adaptive            = prm.get("Refinement") == "adaptive";
    t.degree              = prm.get("Refinement") == "degree";
    t.automatic           = prm.get("Refinement") == "auto";
    t.refined_fraction    = prm.get_double("Refined cell fraction");
    t.closed_forms        = prm.get_bool("Closed forms");
    t.paired_model        = prm.get("Paired model");
    for (const auto &item : split(prm.get("Quantities"), ','))
      if (const auto name = trim(item); !name.empty())
        t.quantities.push_back(name);
    prm.leave_subsection();
    return t;
  }

  namespace
  {
    // Largest rotation of material lines, |skew(grad u)| (radians, infinitesimal), over the
    // quadrature points of every cell: what makes a linear answer wrong at order theta^2.
    template <int dim>
    double largest_rotation(const LinearElasticProblem<dim> &problem)
    {
      using namespace dealii;
      FEValues<dim> fe_values(*problem.mapping, *problem.fe, *problem.quadrature, update_gradients);
      const FEValuesExtractors::Vector u(0);
      std::vector<Tensor<2, dim>>      grad(fe_values.n_quadrature_points);
      double                           largest = 0;
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[u].get_function_gradients(problem.solution, grad);
            for (const auto &g : grad)
              {
                const Tensor<2, dim> w = 0.5 * (g - transpose(g));
                largest = std::max(largest, std::sqrt(0.5 * scalar_product(w, w)));
              }
          }
      return Utilities::MPI::max(largest, problem.communicator);
    }

    std::vector<std::string> check_quantities(const std::string &checks)
    {
      std::vector<std::string> names; // once each, though several checks may name a quantity
      for (const auto &c : parse_checks(checks))
        if (std::find(names.begin(), names.end(), c.quantity) == names.end())
          names.push_back(c.quantity);
      return names;
    }

    std::string percent(double fraction)
    {
      std::ostringstream s;
      s << std::setprecision(2) << 100 * fraction << " %";
      return s.str();
    }
  } // namespace

  template <int dim>
  int run_model_ladder(const RunContext &context, const TargetSettings &target, DimensionVerdict *verdict)
  {
    const auto &p    = context.parameters;
    const bool  root = dealii::Utilities::MPI::this_mpi_process(context.communicator) == 0;
    auto        names = target.quantities.empty() ? check_quantities(p.checks) : target.quantities;
    if (names.empty())
      throw InputError("case file '" + p.case_file + "', Target/Quantities: name the quantities the "
                       "target applies to (or give Comparison/Checks)");
    dealii::Timer total;
    struct Rung
    {
      std::string  model = "linear";
      unsigned int degree, refinements, adaptive_cycles;
      double       dofs, seconds;
      std::map<std::string, double>        values;
      std::map<std::string, ErrorEstimate> estimates;
      // The estimate the stop rule reads: the Richardson one, times the safety factor while the
      // observed order is not steady (adaptive and degree rungs); negative when there is none.
      std::map<std::string, double>        stop_estimates;
      std::string                          decision;
    };
    std::vector<Rung>                  rungs;
    std::vector<LadderRow>             earlier_rows = target.earlier_rows; // of an abandoned plane-stress model
    std::map<std::string, std::vector<double>> history;
    std::vector<double>                mesh_sizes; // h = N^(-1/dim)
    std::uint64_t                      last_cells = 0;
    std::string                        too_large; // why the climb stopped short, if it did
    std::vector<std::vector<bool>>     adaptive_refinements;
    // Adaptive and degree rungs: the last observed order (0 if none), and why an estimate cannot
    // stop the climb yet.
    std::map<std::string, double>      orders;
    std::map<std::string, std::string> unsteady;
    // Degree rungs: 2, 3, 4 on hexahedra (degree 1 locks in bending and is far from the
    // asymptotic rate); FE_SimplexP stops at 2 here (known after the first rung built the mesh).
    constexpr unsigned int             lowest_degree  = 2;
    unsigned int                       highest_degree = 4;
    // Refinement = auto climbs in degree on 3D hexahedra (one degree step costs about 3x the DoFs
    // where halving the cells costs 8x, and a uniform climb pays for the rung after the first that
    // meets the target to observe an order: 5.5x the cheapest uniform mesh's whole process on the
    // torsion bar, against 1.26x in degree); tetrahedra go uniform at degree 2 after the first rung.
    bool                               degree_rungs = target.degree || (target.automatic && dim == 3);
    unsigned int                       uniform_degree = p.element_degree;
    // The safety factor on an estimate whose observed order is not steady (see the stop rule).
    const auto unsteady_safety = [&]() { return degree_rungs ? 8.0 : 10.0; };
    const auto unsteady_factor = [&]() { return std::to_string(static_cast<int>(unsteady_safety())); };
    // The estimate the stop rule reads for quantity n (negative without an observed order): the
    // Richardson one, times the safety factor while the observed order is not steady. Only an
    // observed order ends the climb: an assumed one is optimistic at singularities. Adaptive meshes
    // converge unevenly while the refinement finds the singular corners (Cook's membrane: observed
    // orders 2.8, 6.2, 3.9 on the first rungs, estimates 6x too small): there the order must also
    // hold steady over two successive triples (within a factor 1.5). Degree rungs likewise:
    // convergence in N speeds up with the degree on smooth problems and is algebraic at
    // singularities. The safety factor is 10 on adaptive rungs (the worst effectivity on such rungs
    // of Cook's membrane was 0.16), 8 on a triple of degrees (bare effectivities 0.32 on Cook, 0.23
    // on the torsion bar: the convergence in N slows from degree 3 to 4; 8 x puts them at 2.5 and
    // 1.8).
    const auto stop_estimate = [&](const std::string &n, const ErrorEstimate &e, const bool uneven) {
      bool steady = true;
      if (uneven)
        {
          const double previous = orders[n];
          steady = e.order_observed && previous > 0 &&
                   std::max(previous, e.observed_order) < 1.5 * std::min(previous, e.observed_order);
          orders[n] = e.order_observed ? e.observed_order : 0;
          if (!steady && e.available)
            unsteady[n] = previous > 0 && e.order_observed ?
                            "observed order not steady yet (" + std::to_string(previous).substr(0, 4) +
                              " then " + std::to_string(e.observed_order).substr(0, 4) + ")" :
                            "observed order not steady yet";
          else
            unsteady.erase(n);
        }
      return e.available && e.order_observed ? (steady ? 1 : unsteady_safety()) * e.relative : -1.0;
    };
    // Why a rung goes on: each quantity's missing or too large estimate.
    const auto why_go_on = [&](const Rung &rung) {
      std::string why;
      for (const auto &[n, e] : rung.estimates)
        if (!e.available)
          why += " " + n + " " + e.note + ";";
        else if (e.relative > target.relative_error)
          why += " " + n + " estimate " + percent(e.relative) + " > target;";
        else if (!e.order_observed)
          why += " " + n + " " + e.note + ", one more rung to observe it;";
        else if (unsteady.count(n))
          why += " " + n + " " + unsteady[n] + " and " + unsteady_factor() + " x estimate > target;";
      return why;
    };
    std::unique_ptr<CaseParameters>    chosen_parameters;
    LinearStaticModel<dim>             chosen;
    bool                               met = false, finite_strain = false;
    std::string                        geometric_reason;
    // One line per rung (before it joins `rungs`): model, mesh, cost, values, estimates, decision.
    const auto print_rung = [&](const Rung &rung) {
      if (!root)
        return;
      std::cout << "  (d) rung " << earlier_rows.size() + rungs.size() + 1 << ": " << rung.model << ", degree "
                << rung.degree << ", refinements " << rung.refinements;
      if (target.adaptive && rung.model == "linear")
        std::cout << " + " << rung.adaptive_cycles << " adaptive";
      std::cout << ", " << static_cast<long>(rung.dofs) << " DoFs, " << std::setprecision(3)
                << rung.seconds << " s;";
      for (const auto &[n, v] : rung.values)
        {
          const auto &e = rung.estimates.at(n);
          std::cout << ' ' << n << " = " << std::setprecision(8) << v << " (estimate "
                    << (e.available ? percent(e.relative) : std::string("-"));
          const auto stop = rung.stop_estimates.find(n);
          if (e.available && stop != rung.stop_estimates.end() && stop->second > e.relative)
            std::cout << ", untrusted: order not steady; bound used " << percent(stop->second);
          std::cout << ")";
        }
      std::cout << "; " << rung.decision << std::endl;
    };
    // (b) across dimensions: the other dimension's model of the same part, read (and checked)
    // before anything is solved.
    std::optional<PairedModel> paired;
    if (!target.paired_model.empty())
      paired = read_paired_model(p, context.geometry, target.paired_model, context.communicator);
    // A plane-stress climb standing for a 3D part: its out-of-plane bound takes its share of the
    // target, and the climb gives way to the 3D model when the bound alone misses it.
    const bool stand_in = target.stand_in_for_3d || (dim == 2 && paired);
    const auto paired_target = [&]() {
      TargetSettings t = target;
      t.paired_model.clear();
      t.quantities = names;
      t.pair_of    = p.case_file;
      return t;
    };
    if (root)
      std::cout << "Model ladder" << (target.stand_in_for_3d ? " (plane-stress model of the 3D part)" : "")
                << ": target " << percent(target.relative_error) << " on";
    for (const auto &n : names)
      if (root)
        std::cout << ' ' << n;
    if (root)
      std::cout << "\n";
    // (a) A closed form whose own error bound meets the target, for this Model, with arguments
    // known before any FE solve, answers the quantity. All target quantities answered: stop.
    {
      struct Answer
      {
        std::string formula, basis;
        double      value = 0, bound = 0;
      };
      std::map<std::string, Answer> answers;
      const auto materials = assign_materials(p.materials, context.geometry.material_ids, p.unit_system);
      const auto variables = expression_variables(p.geometry_parameters, materials.begin()->second,
                                                  dim == 2 ? p.thickness : 1.0);
      for (const auto &n : names)
        {
          std::string why = "no closed form in Comparison/Checks";
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
              // A plane-stress model paired with its 3D part answers for the part.
              const std::string part_model = dim == 2 && paired ? std::string("3d") : p.model;
              if (std::find(result.bound_models.begin(), result.bound_models.end(), part_model) ==
                  result.bound_models.end())
                {
                  why = check.formula + "'s bound does not hold for Model = " + part_model +
                        (part_model != p.model ? " (the 3D part this model stands for)" : "");
                  continue;
                }
              const Answer answer{check.formula, result.error_bound_basis, result.value, result.error_bound};
              if (answer.bound <= target.relative_error &&
                  (!answers.count(n) || answer.bound < answers[n].bound))
                answers[n] = answer;
              else if (answer.bound > target.relative_error && answer.bound < smallest_failed)
                {
                  smallest_failed = answer.bound; // report the closest miss
                  why = check.formula + ": bound " + percent(answer.bound) + " > target (" +
                        answer.basis + ")";
                }
            }
          if (root)
            {
              if (answers.count(n))
                std::cout << "  (a) " << n << " = " << std::setprecision(8) << answers[n].value << " by "
                          << answers[n].formula << ", bound " << percent(answers[n].bound)
                          << " <= target (" << answers[n].basis << ")" << std::endl;
              else
                std::cout << "  (a) " << n << ": " << why << std::endl;
            }
        }
      if (target.closed_forms && answers.size() == names.size())
        {
          if (root)
            std::cout << "  (a) every target quantity is answered by a closed form: stop, no FE model" << std::endl;
          check_output_directory(p, context.communicator);
          if (context.check_only)
            return 0;
          RunSummary summary;
          summary.case_file = p.case_file;
          summary.settings  = {{"analysis", p.analysis}, {"model", p.model},
                               {"ladder", "target met by closed forms (rung a)"}};
          summary.parameters = p.geometry_parameters;
          for (const auto &[n, a] : answers)
            {
              summary.quantities[n]                     = a.value;
              summary.quantities[n + "_error_estimate"] = a.bound;
              summary.settings.insert({n + "_closed_form", a.formula + ": " + a.basis});
            }
          summary.quantities["ladder_rungs"]          = 1;
          summary.quantities["ladder_total_seconds"]  = total.wall_time();
          summary.quantities["target_relative_error"] = target.relative_error;
          if (root)
            {
              std::filesystem::create_directories(p.output_directory);
              write_summary(summary, p.output_directory + "/summary.json");
              std::ofstream out(p.output_directory + "/ladder.csv.tmp");
              out << "rung,model,degree,refinements,adaptive_cycles,dofs,seconds,cumulative_seconds";
              for (const auto &n : names)
                out << ',' << n << ",estimate_" << n << ",stop_estimate_" << n;
              out << "\n1,closed form,0,0,0,0," << total.wall_time() << ',' << total.wall_time()
                  << std::setprecision(10);
              for (const auto &n : names)
                out << ',' << answers[n].value << ',' << answers[n].bound << ',' << answers[n].bound;
              out << "\n";
              out.close();
              std::filesystem::rename(p.output_directory + "/ladder.csv.tmp", p.output_directory + "/ladder.csv");
              std::cout << "\n" << format_table(summary) << "\nResults in " << p.output_directory
                        << "/ (summary.json, ladder.csv)" << std::endl;
            }
          return 0;
        }
      if (root && !target.closed_forms && !answers.empty())
        std::cout << "  (a) Target/Closed forms = false: climbing anyway" << std::endl;
    }
    // (b) A plane-stress model is checked against the 3D solid it stands for on every rung (the
    // energy bound of quantities/out_of_plane_bound.h); the last rung's bound is reported.
    double      out_of_plane = target.dimension_bound; // relative, < 0: not computed
    std::string dimension_reason = target.dimension_note;
    if constexpr (dim == 3)
      if (paired && !context.check_only)
        {
          // The plane-stress model first: it stops the climb when 2D is enough.
          if (root)
            std::cout << "  (b) the plane-stress model " << paired->parameters.case_file
                      << " first: it answers for this 3D part when its out-of-plane bound plus its "
                         "discretization estimate meet the target\n" << std::endl;
          TargetSettings t  = paired_target();
          t.stand_in_for_3d = true;
          t.closed_forms    = false; // rung (a) has been tried on the 3D part
          const RunContext plane{paired->parameters, *paired->prm, paired->geometry, false, context.communicator};
          DimensionVerdict found;
          const int        rc = run_model_ladder<2>(plane, t, &found);
          if (rc != needs_3d_model)
            return rc;
          dimension_reason = found.reason;
          out_of_plane     = found.bound;
          earlier_rows     = found.rows; // the 2D time is inside this climb's own
          if (root)
            std::cout << "\nModel ladder, back to the 3D part " << p.case_file << "\n";
        }
    if (paired && context.check_only && root)
      std::cout << "  (b) paired model " << paired->parameters.case_file << " read and meshed: the same part\n";
    else if (dim == 3 && !dimension_reason.empty() && root)
      std::cout << "  (b) 3D: " << dimension_reason << "\n";
    else if (p.model != "plane stress" && root)
      std::cout << "  (b) dimension as set by Model = " << p.model
                << (p.model == "3d" ? "" : " (no out-of-plane bound for plane strain: it stands for a part "
                                           "long in z or held at its z faces)")
                << "\n";

    // A rung's line of ladder.csv (without its number and cumulative time).
    const auto to_row = [&](const Rung &rung) {
      std::ostringstream head, tail;
      head << std::setprecision(10) << (stand_in ? "plane stress " : "") << rung.model << ',' << rung.degree
           << ',' << rung.refinements << ',' << rung.adaptive_cycles << ',' << rung.dofs << ',' << rung.seconds;
      tail << std::setprecision(10);
      for (const auto &n : names)
        {
          const auto &e = rung.estimates.at(n);
          tail << ',' << rung.values.at(n) << ',';
          if (e.available)
            tail << e.relative;
          tail << ',';
          const auto stop = rung.stop_estimates.find(n);
          if (e.available)
            tail << (stop != rung.stop_estimates.end() && stop->second >= 0 ? stop->second : e.relative);
        }
      return LadderRow{head.str(), rung.seconds, tail.str()};
    };
    // This plane-stress model cannot stand for its 3D part (dimension_reason says why): hand the
    // climb to the 3D model, with this model's rungs for its ladder.csv.
    const auto give_way_to_3d = [&]() -> int {
      std::vector<LadderRow> rows = earlier_rows;
      for (const auto &rung : rungs)
        rows.push_back(to_row(rung));
      if (target.stand_in_for_3d)
        {
          if (verdict != nullptr)
            *verdict = {dimension_reason, out_of_plane, rows};
          return needs_3d_model;
        }
      if constexpr (dim == 2)
        {
          // This case is the plane-stress model: its 3D part climbs now and writes the results.
          if (root)
            std::cout << "\nModel ladder, on to the 3D part " << paired->parameters.case_file << "\n";
          TargetSettings t  = paired_target();
          t.dimension_note  = dimension_reason;
          t.dimension_bound = out_of_plane;
          t.earlier_rows    = rows;
          t.earlier_seconds = total.wall_time();
          const RunContext solid{paired->parameters, *paired->prm, paired->geometry, false, context.communicator};
          return run_model_ladder<3>(solid, t);
        }
      return 4; // a 3D climb never stands in for another
    };
    for (unsigned int k = 0; k <= target.max_refinements && !met; ++k)
      {
        auto rung_parameters = std::make_unique<CaseParameters>(p);
        // Degree rungs: 2, 3, ... up to the highest degree on the case's mesh, then halve cells.
        const unsigned int h_steps = !degree_rungs                               ? k :
                                     k + lowest_degree > highest_degree ? k + lowest_degree - highest_degree :
                                                                          0;
        rung_parameters->element_degree =
          degree_rungs ? std::min(k + lowest_degree, highest_degree) : uniform_degree;
        // Kelly's refine flags are computed over the whole mesh: adaptive rungs share it.
        if (target.adaptive && p.mesh_partition == "distributed")
          throw InputError("case file '" + p.case_file + "': Discretization/Mesh partition = "
                           "distributed is not possible with Target/Refinement = adaptive (the "
                           "refine flags cover the whole mesh); use shared or auto");
        if (target.adaptive)
          rung_parameters->mesh_partition = "shared";
        if (target.adaptive)
          rung_parameters->adaptive_refinements = adaptive_refinements;
        else
          rung_parameters->global_refinements = p.global_refinements + h_steps;
        if (k > 0 && !target.adaptive)
          try
            {
              // The next rung (one more uniform refinement, or a higher degree, of the last
              // rung's mesh) must fit in memory.
              const bool refines = !degree_rungs || h_steps > 0;
              refuse_refinement_beyond_memory(last_cells, dim, refines ? 1 : 0,
                                              rung_parameters->element_degree,
                                              dealii::Utilities::MPI::n_mpi_processes(context.communicator));
            }
          catch (const ModelTooLarge &e)
            {
              too_large = e.what();
              rungs.back().decision = "target NOT met: the next rung would not fit in memory";
              if (root)
                std::cout << "  (d) no rung " << k + 1 << ": " << too_large << std::endl;
              break;
            }
        dealii::Timer rung_timer;
        auto model = solve_linear_static_model<dim>(context, *rung_parameters);
        last_cells = model.problem->triangulation.n_global_active_cells();
        if (model.stopped_for_check)
          return 0;
        if (target.adaptive && !model.problem->triangulation.all_reference_cells_are_hyper_cube())
          throw InputError("case file '" + p.case_file + "', Target/Refinement: adaptive refinement "
                           "needs a quadrilateral or hexahedral mesh (no hanging nodes on triangles or "
                           "tetrahedra); use uniform");
        if (k == 0 && !model.problem->triangulation.all_reference_cells_are_hyper_cube())
          {
            highest_degree = lowest_degree;
            if (target.automatic && degree_rungs)
              {
                degree_rungs   = false; // only halving is left: uniform rungs at degree 2
                uniform_degree = lowest_degree;
              }
          }
        Rung rung;
        rung.degree          = rung_parameters->element_degree;
        rung.refinements     = rung_parameters->global_refinements;
        rung.adaptive_cycles = rung_parameters->adaptive_refinements.size();
        rung.dofs            = model.quantities.at("n_dofs");
        // Uniform rungs halve h exactly; adaptive ones measure it by the DoF count.
        mesh_sizes.push_back(target.adaptive || degree_rungs ? std::pow(rung.dofs, -1.0 / dim) :
                                                                std::ldexp(1.0, -static_cast<int>(k)));
        met              = true;
        // Targets may name derived quantities (Quantities/Derived) as well as computed ones.
        auto rung_quantities = model.quantities;
        try
          {
            add_derived_quantities(p.derived, rung_quantities, model.problem->expression_variables());
          }
        catch (const std::invalid_argument &e)
          {
            throw InputError("case file '" + p.case_file + "': " + e.what());
          }
        for (const auto &n : names)
          {
            const auto found = rung_quantities.find(n);
            if (found == rung_quantities.end())
              throw InputError(target.pair_of.empty() ?
                                 "case file '" + p.case_file + "', Target/Quantities: '" + n +
                                   "' is not a reported quantity" :
                                 "case file '" + p.case_file + "': '" + n + "' is not a reported quantity, "
                                   "but case file '" + target.pair_of + "' targets it and names this case in "
                                   "Target/Paired model: both models must report it under that name");
            rung.values[n] = found->second;
            history[n].push_back(found->second);
            // Assumed order in h for a smooth quantity: degree + 1 (displacements at points).
            const auto e      = estimate_discretization_error(history[n], mesh_sizes, rung.degree + 1.0);
            rung.estimates[n] = e;
            rung.stop_estimates[n] = stop_estimate(n, e, target.adaptive || degree_rungs);
            met = met && rung.stop_estimates[n] >= 0 && rung.stop_estimates[n] <= target.relative_error;
          }
        std::string needs_3d; // why this plane-stress model cannot stand for its 3D part
        if constexpr (dim == 2)
          {
          if (p.model == "plane stress" && !model.problem->mixed)
            {
              const auto   bound  = plane_stress_out_of_plane_bound(*model.problem);
              const double energy = model.quantities.at("strain_energy");
              out_of_plane        = energy > 0 ? bound.energy_difference / energy :
                                                 std::numeric_limits<double>::infinity();
              std::ostringstream why;
              why << "plane stress against the 3D solid of thickness " << model.problem->thickness
                  << ": |U_3D - U| <= " << percent(out_of_plane)
                  << " of U (energy bound; it holds for the strain energy and the stiffness of a single "
                     "load or drive)";
              if (stand_in)
                why << (out_of_plane < target.relative_error ?
                          " < target: 2D stands for the 3D part while its discretization estimate stays "
                          "below the rest of the target, " + percent(target.relative_error - out_of_plane) :
                        out_of_plane < 2 * target.relative_error && k < 2 ?
                          " >= target on this mesh, < 2 x target: the bound tightens on finer meshes; "
                          "one more 2D rung" :
                          " >= target: the 3D part may differ from this 2D model by more than the "
                          "target; climbing the 3D model");
              else
                why << (out_of_plane <= target.relative_error ?
                          " <= target: 2D is enough" :
                          " > target: the 3D part may differ from this 2D model by more than the target; "
                          "model it in 3D (Model = 3d, or name it in Target/Paired model) to meet the "
                          "target against the solid");
              dimension_reason = why.str();
              if ((k == 0 || stand_in) && root)
                std::cout << "  (b) " << dimension_reason << "\n";
              // The bound tightens as the mesh resolves the out-of-plane field: a coarse rung gives
              // way only when the bound is twice the target (cantilever W = 1: 0.24 % on the first
              // rung, 0.13 % converged).
              if (stand_in && out_of_plane >= target.relative_error &&
                  (out_of_plane >= 2 * target.relative_error || k >= 2))
                needs_3d = "out-of-plane bound " + percent(out_of_plane) + " >= target";
              else if (stand_in)
                // The bound takes its share: estimate + bound must meet the target.
                for (const auto &n : names)
                  met = met && rung.stop_estimates[n] + out_of_plane <= target.relative_error;
            }
          else if (stand_in)
            needs_3d = dimension_reason = "no out-of-plane bound for the mixed formulation";
          }
        if (k == 0)
          {
            // (c) the geometric error of the linear answer, of order theta^2.
            const double theta = largest_rotation(*model.problem);
            const double geometric = theta * theta;
            std::ostringstream why;
            why << "largest rotation " << std::setprecision(3) << theta * 180 / M_PI << " deg: geometric error ~theta^2 = "
                << percent(geometric) << (geometric > target.relative_error ? " > " : " <= ") << "target";
            geometric_reason = why.str();
            finite_strain    = geometric > target.relative_error;
            if (finite_strain && !target.allow_finite_strain)
              geometric_reason += ": finite strain would be needed, but Target/Allow finite strain = false keeps it linear";
            else
              geometric_reason += finite_strain ? ": finite strain needed (its own rungs follow)" :
                                                  ": linear is enough";
            finite_strain = finite_strain && target.allow_finite_strain;
            if (root)
              std::cout << "  (c) " << geometric_reason << "\n";
            if (finite_strain && stand_in && needs_3d.empty())
              {
                // The out-of-plane bound is one of linear elasticity.
                needs_3d = dimension_reason = "finite strain needed, and the out-of-plane bound that "
                                              "justifies 2D holds for linear models only";
                finite_strain = false;
              }
          }
        if (!needs_3d.empty())
          {
            met           = false;
            rung.decision = "the plane-stress model cannot stand for the 3D part (" + needs_3d + ")";
            rung.seconds  = rung_timer.wall_time();
            print_rung(rung);
            rungs.push_back(rung);
            return give_way_to_3d();
          }
        if (finite_strain)
          {
            // The linear answer is off by its geometric error whatever the mesh: climb in
            // finite strain instead, from the case's own mesh.
            met           = false;
            rung.decision = "finite strain needed: the climb goes on in finite strain";
          }
        else if (met)
          rung.decision = "estimate meets the target: stop";
        else if (k == target.max_refinements)
          rung.decision = "target NOT met within Target/Maximum refinements";
        else
          {
            rung.decision = target.adaptive                                   ? "refine adaptively:" :
                            degree_rungs && k + lowest_degree < highest_degree ? "raise the degree:" :
                                                                      "refine:";
            rung.decision += why_go_on(rung);
            if (target.adaptive)
              adaptive_refinements.push_back(kelly_refine_flags(*model.problem, target.refined_fraction));
          }
        rung.seconds = rung_timer.wall_time();
        print_rung(rung);
        rungs.push_back(rung);
        chosen_parameters = std::move(rung_parameters);
        chosen            = std::move(model);
        if (finite_strain)
          break;
      }
    if (stand_in && !met && !finite_strain)
      {
        // Estimate plus bound did not meet the target within the rungs allowed: the 3D part may.
        dimension_reason = "the plane-stress model did not meet the target (its estimate plus the "
                           "out-of-plane bound " + percent(out_of_plane) + ") within its rungs";
        return give_way_to_3d();
      }

    // The chosen model's run: linear output as usual, or the finite-strain analysis on its mesh.
    RunContext chosen_context{*chosen_parameters, context.prm, context.geometry, context.check_only,
                              context.communicator};
    auto write_ladder = [&](const std::string &directory) {
      if (!root)
        return;
      std::filesystem::create_directories(directory);
      std::ofstream out(directory + "/ladder.csv.tmp");
      out << "rung,model,degree,refinements,adaptive_cycles,dofs,seconds,cumulative_seconds";
      for (const auto &n : names)
        out << ',' << n << ",estimate_" << n << ",stop_estimate_" << n;
      out << "\n" << std::setprecision(10);
      std::vector<LadderRow> rows = earlier_rows;
      for (const auto &rung : rungs)
        rows.push_back(to_row(rung));
      double cumulative = 0;
      for (std::size_t k = 0; k < rows.size(); ++k)
        {
          cumulative += rows[k].seconds;
          out << k + 1 << ',' << rows[k].head << ',' << cumulative << rows[k].tail << "\n";
        }
      out.close();
      std::filesystem::rename(directory + "/ladder.csv.tmp", directory + "/ladder.csv");
    };
    if (finite_strain)
      {
        // (d) in finite strain: from the case's own mesh, uniform refinement at the case's degree,
        // or degree rungs as in the linear climb when Refinement = degree asks for them (adaptive
        // refinement drives linear rungs only), until the estimate meets the target. Auto stays
        // uniform here: the tangent is assembled cell by cell, whose cost grows steeply with the
        // degree (3D roll-up, degrees 2, 3, 4: 2.9, 22, 130 s for 2.7k, 7.2k, 15k DoFs). Every
        // rung writes the output directory; what stays is the last rung's, with its estimates.
        chosen.problem.reset();
        const bool fs_degree_rungs = target.degree;
        orders.clear();
        unsteady.clear();
        const unsigned int first = p.global_refinements;
        std::map<std::string, std::vector<double>> fs_history;
        std::vector<double>                        fs_sizes;
        bool                                       fs_met = false;
        double                                     last_fs_cells = 0;
        for (unsigned int j = 0; j <= target.max_refinements && !fs_met; ++j)
          {
            const unsigned int h_steps = !fs_degree_rungs                               ? j :
                                         j + lowest_degree > highest_degree ? j + lowest_degree - highest_degree :
                                                                              0;
            const unsigned int r      = first + h_steps;
            const unsigned int degree = fs_degree_rungs ? std::min(j + lowest_degree, highest_degree) : uniform_degree;
            if (j > 0)
              try
                {
                  refuse_refinement_beyond_memory(static_cast<std::uint64_t>(last_fs_cells), dim,
                                                  !fs_degree_rungs || h_steps > 0 ? 1 : 0, degree,
                                                  dealii::Utilities::MPI::n_mpi_processes(context.communicator));
                }
              catch (const ModelTooLarge &e)
                {
                  too_large = e.what();
                  rungs.back().decision = "target NOT met: the next rung would not fit in memory";
                  if (root)
                    std::cout << "  (d) no finite-strain rung at degree " << degree << ", " << r
                              << " refinements: " << too_large << std::endl;
                  break;
                }
            CaseParameters nonlinear     = *chosen_parameters;
            nonlinear.analysis           = "nonlinear static";
            nonlinear.element_degree     = degree;
            nonlinear.global_refinements = r;
            RunContext nonlinear_context{nonlinear, context.prm, context.geometry, context.check_only,
                                         context.communicator};
            Rung          rung;
            rung.model           = "finite strain";
            rung.degree          = nonlinear.element_degree;
            rung.refinements     = r;
            rung.adaptive_cycles = 0;
            dealii::Timer rung_timer;
            const auto amend = [&](RunSummary &summary) {
              rung.dofs     = summary.quantities.at("n_dofs");
              last_fs_cells = summary.quantities.at("n_cells");
              fs_sizes.push_back(fs_degree_rungs ? std::pow(rung.dofs, -1.0 / dim) : std::ldexp(1.0, -static_cast<int>(j)));
              fs_met = true;
              for (const auto &n : names)
                {
                  const auto found = summary.quantities.find(n);
                  if (found == summary.quantities.end())
                    throw InputError("case file '" + p.case_file + "', Target/Quantities: '" + n +
                                     "' is not a reported quantity of the finite-strain analysis");
                  fs_history[n].push_back(found->second);
                  const auto e = estimate_discretization_error(fs_history[n], fs_sizes, degree + 1.0);
                  rung.values[n]         = found->second;
                  rung.estimates[n]      = e;
                  const double stop      = stop_estimate(n, e, fs_degree_rungs);
                  rung.stop_estimates[n] = stop;
                  fs_met = fs_met && stop >= 0 && stop <= target.relative_error;
                  if (e.available)
                    {
                      summary.quantities[n + "_error_estimate"] = std::max(stop, e.relative);
                      summary.quantities[n + "_observed_order"] = e.observed_order;
                      if (stop > e.relative)
                        {
                          summary.quantities[n + "_richardson_estimate"] = e.relative;
                          summary.settings.insert({n + "_error_estimate_basis",
                                                   "observed order not steady: " + unsteady_factor() +
                                                     " x the Richardson estimate"});
                        }
                    }
                  else
                    summary.settings.insert({n + "_error_estimate", e.note});
                }
              summary.settings.insert({"ladder", fs_met ? "target met" : "target not met"});
              summary.settings.insert({"ladder_geometric_check", geometric_reason});
              if (out_of_plane >= 0)
                {
                  summary.settings.insert({"ladder_dimension_check", dimension_reason + " (linear rung)"});
                  summary.quantities["out_of_plane_bound"] = out_of_plane;
                }
              summary.quantities["ladder_rungs"]          = rungs.size() + 1 + earlier_rows.size();
              summary.quantities["ladder_total_seconds"]  = total.wall_time() + target.earlier_seconds;
              summary.quantities["target_relative_error"] = target.relative_error;
            };
            const int rc = run_nonlinear_static<dim>(nonlinear_context, amend);
            rung.seconds = rung_timer.wall_time();
            if (rc != 0)
              {
                if (!rung.values.empty())
                  rungs.push_back(rung);
                write_ladder(nonlinear.output_directory);
                return rc;
              }
            if (fs_met)
              rung.decision = "estimate meets the target: stop";
            else if (j == target.max_refinements)
              rung.decision = "target NOT met within Target/Maximum refinements";
            else
              rung.decision = (fs_degree_rungs && j + lowest_degree < highest_degree ? "raise the degree:" : "refine:") +
                              why_go_on(rung);
            print_rung(rung);
            rungs.push_back(rung);
          }
        write_ladder(chosen_parameters->output_directory);
        return fs_met ? 0 : 4;
      }

    const auto &problem = *chosen.problem;
    RunSummary  summary =
      start_summary(chosen_context, problem.triangulation.all_reference_cells_are_hyper_cube());
    summary.settings.insert({"solver", problem.solver_method});
    summary.settings.insert({"ladder", met ? "target met" :
                                             too_large.empty() ? "target not met" :
                                                                 "target not met: " + too_large});
    summary.settings.insert({"ladder_geometric_check", geometric_reason});
    summary.quantities = chosen.quantities;
    if (out_of_plane >= 0)
      {
        summary.settings.insert({"ladder_dimension_check", dimension_reason});
        summary.quantities["out_of_plane_bound"] = out_of_plane;
      }
    summary.quantities["ladder_rungs"]         = rungs.size() + earlier_rows.size();
    summary.quantities["ladder_total_seconds"] = total.wall_time() + target.earlier_seconds;
    summary.quantities["target_relative_error"] = target.relative_error;
    for (const auto &[n, e] : rungs.back().estimates)
      if (e.available)
        {
          // What the stop rule read: the Richardson estimate, or its safety multiple while the
          // observed order is not steady (then the bare estimate is kept beside it).
          const auto   stop  = rungs.back().stop_estimates.find(n);
          const double bound = stop != rungs.back().stop_estimates.end() && stop->second >= 0 ? stop->second : e.relative;
          summary.quantities[n + "_error_estimate"] = bound;
          summary.quantities[n + "_observed_order"] = e.observed_order;
          // A plane-stress model standing for its 3D part: the error against the part.
          if (stand_in && out_of_plane >= 0)
            summary.quantities[n + "_error_estimate_against_3d"] = bound + out_of_plane;
          if (bound > e.relative)
            {
              summary.quantities[n + "_richardson_estimate"] = e.relative;
              summary.settings.insert({n + "_error_estimate_basis",
                                       "observed order not steady: " + unsteady_factor() +
                                         " x the Richardson estimate"});
            }
        }
      else
        summary.settings.insert({n + "_error_estimate", e.note});
    finish_run(chosen_context, summary, problem.expression_variables(), [&](const std::string &directory) {
      write_fields(problem, directory);
    });
    write_ladder(chosen_parameters->output_directory);
    return met ? 0 : 4;
  }

  template int run_model_ladder<2>(const RunContext &, const TargetSettings &, DimensionVerdict *);
  template int run_model_ladder<3>(const RunContext &, const TargetSettings &, DimensionVerdict *);
} // namespace compliant
