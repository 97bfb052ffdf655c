#include "analyses/nonlinear_static.h"

#include "analyses/buckling_parts.h"
#include "analyses/interruption.h"
#include "analyses/response_curve.h"

#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include "constraints/extra_constraints.h"
#include "contact/contact_obstacle.h"
#include "discretization/degree_transfer.h"
#include "finite_strain/finite_strain_load_path.h"
#include "finite_strain/finite_strain_problem.h"
#include "nonlinear/load_stepping.h"
#include "output/field_output.h"
#include "output/run_pictures.h"
#include "quantities/quantities.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

namespace compliant
{
  namespace
  {
    void declare(dealii::ParameterHandler &prm)
    {
      using namespace dealii;
      prm.enter_subsection("Finite strain");
      prm.declare_entry("Law", "neo-Hookean", Patterns::Selection(hyperelastic_law_selection()),
                        hyperelastic_law_documentation());
      prm.declare_entry("Mooney-Rivlin ratio", "0.2", Patterns::Double(0, 0.99),
                        "c2 / (c1 + c2) of the Mooney-Rivlin law (0 is neo-Hookean).");
      prm.declare_entry("Law constants", "", Patterns::Anything(), law_constants_documentation());
      prm.declare_entry("Formulation", "displacement", Patterns::Selection("displacement|mixed"),
                        "displacement: Q_p elements; mixed: Q_p displacement with discontinuous "
                        "P_(p-1) pressure, free of volumetric locking for nu -> 0.5.");
      prm.declare_entry("Follower pressure", "", Patterns::Anything(),
                        "Pressure acting on the deformed surface (follows its rotation): "
                        "'boundary: p' with p an expression of the reference coordinates x, y, z "
                        "and geometry parameters; positive pushes inward. Scaled by the load factor.");
      prm.declare_entry("Initial step", "0.1", Patterns::Double(1e-12, 1),
                        "First load-factor increment (the load factor runs from 0 to 1 and "
                        "scales loads, prescribed displacements and rotation angles).");
      prm.declare_entry("Minimum step", "1e-4", Patterns::Double(0, 1),
                        "Smallest increment before the run gives up.");
      prm.declare_entry("Maximum step", "0.25", Patterns::Double(1e-12, 1),
                        "Largest increment; steps grow by 1.5 after easy convergence.");
      prm.declare_entry("Path", "load steps", Patterns::Selection("load steps|arc length"),
                        "How the load path is followed. load steps: the load factor rises in "
                        "adaptive steps (with prescribed displacements: the drive); stops at a "
                        "limit point of the load. arc length: Crisfield's spherical arc-length "
                        "continuation, the load factor an unknown; follows loads (not prescribed "
                        "motion) through limit points and snap-backs to load factor 1, reports "
                        "every limit point and bifurcation (MUMPS; the step sizes above are "
                        "load-factor increments along the initial tangent).");
      prm.declare_entry("Arc length steps", "500", Patterns::Integer(1),
                        "Path = arc length: most steps before the run stops short of load factor 1.");
      prm.declare_entry("Newton iterations", "25", Patterns::Integer(1),
                        "Newton iterations per step before the step is cut back.");
      prm.declare_entry("Stability check", "true", Patterns::Bool(),
                        "After each step, count the negative eigenvalues of the tangent "
                        "stiffness (LDL^T inertia): when equilibrium turns unstable (limit point "
                        "or bifurcation passed) the run stops and reports the load, instead of "
                        "following an unstable path. Off automatically with follower pressure "
                        "and with rigid boundaries in 3D (non-symmetric tangent).");
      prm.declare_entry("Predictor", "secant", Patterns::Selection("secant|last state"),
                        "Where Newton starts each load step. secant: on the line through the "
                        "last two converged states, at the new load factor (fewer Newton "
                        "iterations on most paths; if Newton fails from there it starts again "
                        "from the last state, and the failed iterations count); last state: "
                        "from the last converged state. Not with contact (always the last state).");
      prm.declare_entry("Residual tolerance", "1e-9", Patterns::Double(0, 1),
                        "Newton converges when the residual is below this fraction of the "
                        "internal force norm.");
      prm.leave_subsection();
      declare_contact_parameters(prm);
    }

    void report_critical_points(const std::vector<CriticalPoint> &points, const bool root)
    {
      if (!root)
        return;
      for (const auto &point : points)
        {
          std::cout << to_string(point.kind) << " at load factor " << std::setprecision(8) << point.load_factor
                    << " (between steps at " << point.bracket_low << " and " << point.bracket_high
                    << "; negative tangent eigenvalues " << point.unstable_before << " -> "
                    << point.unstable_after << ")" << std::endl;
        }
    }

    // limit_point_1, limit_point_2, ..., bifurcation_1, ...: load factors in path order.
    void add_critical_points(const std::vector<CriticalPoint> &points, Quantities &quantities)
    {
      unsigned int limits = 0, bifurcations = 0;
      for (const auto &point : points)
        if (point.kind == CriticalPoint::Kind::limit_point)
          quantities["limit_point_" + std::to_string(++limits)] = point.load_factor;
        else
          quantities["bifurcation_" + std::to_string(++bifurcations)] = point.load_factor;
      if (!points.empty())
        {
          quantities["limit_points"] = limits;
          quantities["bifurcations"] = bifurcations;
        }
    }

    // What the stability stop advises depends on how the path is driven.
    template <int dim>
    std::string unstable_advice(const BoundaryConditions<dim> &bc)
    {
      if (bc.displacements.empty() && bc.rotations.empty())
        return "Load control cannot follow it: drive the structure by a prescribed displacement to follow it "
               "past a limit point (or use Finite strain/Path = arc length)";
      // a displacement drive passes limit points of the load: what stops it is a bifurcation
      return "The run is driven by prescribed displacements or rotations, so this is a bifurcation (or a "
             "limit of the drive itself): an imperfection (a geometry parameter) selects one branch to follow";
    }

    // Derived quantities split into those of every step and those of the path's critical points
    // (limit_point_1, ...), which exist only at the end.
    std::pair<std::string, std::string> split_derived(const std::string &derived)
    {
      std::string per_step, path;
      for (const auto &entry : dealii::Utilities::split_string_list(derived, ';'))
        (entry.find("limit_point_") == std::string::npos && entry.find("bifurcation") == std::string::npos ?
           per_step :
           path) += entry + ";";
      return {per_step, path};
    }

    void print_step(const unsigned int number, const double load_factor, const NewtonReport &report,
                    const Quantities &quantities)
    {
      std::cout << "step " << std::setw(3) << number << "  load factor " << std::setw(10) << std::setprecision(6)
                << load_factor << "  Newton " << std::setw(2) << report.iterations << "  residual "
                << std::scientific << std::setprecision(2) << report.residual << std::defaultfloat;
      if (report.line_search_cuts)
        std::cout << "  line search cuts " << report.line_search_cuts;
      if (const auto active = quantities.find("contact_active_nodes"); active != quantities.end())
        std::cout << "  contact nodes " << active->second;
      std::cout << std::endl;
    }

    // Contact forces and moments per obstacle, the active nodes and the deepest penetration, from
    // the residual at the converged state (the obstacles' forces are what it leaves on the nodes).
    template <int dim>
    void add_contact_quantities(const FiniteStrainProblem<dim> &problem, Quantities &q)
    {
      if (!problem.contact)
        return;
      auto residual = problem.reaction_forces();
      residual *= -1; // f_ext - f_int
      const auto  result = problem.contact->result(problem.solution, residual, problem.load_factor);
      const char *axes[] = {"x", "y", "z"};
      const auto  names  = problem.contact->names(); // the obstacles', then the pairs'
      for (unsigned int o = 0; o < result.obstacles.size(); ++o)
        {
          const std::string name = names[o];
          const auto       &r    = result.obstacles[o];
          for (unsigned int d = 0; d < dim; ++d)
            q["contact_force_" + name + "_" + axes[d]] = r.force[d];
          for (unsigned int d = (dim == 2 ? 2 : 0); d < 3; ++d)
            q["contact_moment_" + name + "_" + axes[d]] = r.moment[d];
          q["contact_nodes_" + name] = r.nodes;
          if (o < problem.contact->obstacles.size() && problem.contact->obstacles[o].friction > 0)
            q["contact_sticking_nodes_" + name] = r.sticking, q["contact_slipping_nodes_" + name] = r.slipping;
        }
      q["contact_active_nodes"]          = result.active_nodes;
      q["contact_max_penetration"]       = result.max_penetration;
      q["contact_penetration_tolerance"] = problem.contact->tolerance;
    }

    struct PathOutcome
    {
      LoadPathResult             result;
      std::vector<CriticalPoint> critical_points;
    };

    using StepRecorder =
      std::function<void(unsigned int, double, const NewtonReport &, const std::vector<std::pair<std::string, double>> &)>;

    // Follows the path by load steps or arc length; record runs for every converged step.
    template <int dim>
    PathOutcome follow_path(FiniteStrainProblem<dim> &problem, const PathSettings &settings,
                            const StepRecorder &record, std::function<bool()> interruption, const bool root,
                            const std::string &case_file)
    {
      PathOutcome outcome;
      if (!settings.arc_length)
        {
          FiniteStrainLoadPath<dim> path(problem, std::move(interruption));
          outcome.result = follow_load_path(
            path, settings.stepping,
            [&](const AcceptedStep &accepted) { record(accepted.number, accepted.load_factor, accepted.newton, {}); },
            [&](const double target, const std::string &why, const double next_step) {
              if (root)
                std::cout << "step to load factor " << target << " failed: " << why << "; cutting the step to "
                          << next_step << std::endl;
            });
          return outcome;
        }
      ArcLengthResult arc;
      try
        {
          arc = problem.follow_arc_length(
            settings.continuation,
            [&](const ArcLengthStep &step) {
              record(step.number, step.load_factor, step.newton,
                     {{"arc_length", step.arc_length}, {"unstable_modes", step.unstable_modes}});
            },
            [&](const double from, const std::string &why, const double next) {
              if (root)
                std::cout << "arc-length step from load factor " << from << " failed: " << why
                          << "; cutting the step to " << next << std::endl;
            });
        }
      catch (const std::invalid_argument &e)
        {
          throw InputError("case file '" + case_file + "': " + e.what());
        }
      outcome.result.steps             = arc.steps;
      outcome.result.cutbacks          = arc.cutbacks;
      outcome.result.newton_iterations = arc.newton_iterations;
      outcome.result.failure           = arc.failure;
      if (!arc.warning.empty() && root)
        std::cout << "warning: " << arc.warning << std::endl;
      outcome.result.interrupted       = arc.interrupted;
      outcome.critical_points          = arc.critical_points;
      report_critical_points(outcome.critical_points, root);
      return outcome;
    }

    // The state of `from` (same case and mesh, a lower degree) carried to the problem, then Newton
    // at from's load factor: for a hyperelastic body the end of the same path. false, with the
    // problem unloaded again, where the state cannot be carried or Newton fails from it.
    template <int dim>
    bool solve_from_state(FiniteStrainProblem<dim> &problem, const FiniteStrainProblem<dim> &from,
                          const StepRecorder &record, const bool root, PathOutcome &outcome)
    {
      dealii::PETScWrappers::MPI::Vector carried;
      if (!interpolate_to_finer_degree<dim>(from, from.solution, problem, carried) ||
          problem.rigid_boundaries.size() != from.rigid_boundaries.size())
        return false;
      const dealii::PETScWrappers::MPI::Vector unloaded = problem.solution;
      problem.restore(carried, from.load_factor);
      for (unsigned int b = 0; b < problem.rigid_boundaries.size(); ++b)
        problem.rigid_boundaries[b].continue_rotation_from(from.rigid_boundaries[b]);
      try
        {
          const NewtonReport report = problem.solve_to(from.load_factor);
          outcome.result.steps             = 1;
          outcome.result.newton_iterations = report.iterations;
          record(1, problem.load_factor, report, {});
          return true;
        }
      catch (const RunInterrupted &)
        {
          // Stopped by a signal: reported as the path's interruption, not followed again.
          outcome.result.interrupted = true;
          return true;
        }
      catch (const StepFailure &e)
        {
          if (root)
            std::cout << "Newton from the carried state failed (" << e.what() << "); following the path"
                      << std::endl;
          // Back to rest, with nothing the failed Newton left: no held contact nodes, no
          // rotation to continue.
          problem.restore(unloaded, 0);
          for (auto &rigid : problem.rigid_boundaries)
            rigid.forget_rotation();
          if (problem.contact)
            problem.contact->release_all();
          return false;
        }
    }

    // The run's counts and timings, its critical points and the derived quantities that use them.
    template <int dim>
    void add_path_quantities(RunSummary &summary, const FiniteStrainProblem<dim> &problem,
                             const PathOutcome &outcome, const std::string &path_derived,
                             const std::string &case_file)
    {
      const auto &result = outcome.result;
      auto       &q      = summary.quantities;
      q["load_factor"]       = problem.load_factor;
      q["load_steps"]        = result.steps;
      q["step_cutbacks"]     = result.cutbacks;
      q["newton_iterations"] = result.newton_iterations;
      if (result.last_stable_load_factor >= 0)
        q["last_stable_load_factor"] = result.last_stable_load_factor;
      add_critical_points(outcome.critical_points, q);
      try
        {
          add_derived_quantities(path_derived, q, problem.expression_variables());
        }
      catch (const std::invalid_argument &e)
        {
          throw InputError("case file '" + case_file + "': " + e.what() + " (this run found " +
                           std::to_string(outcome.critical_points.size()) + " limit points and bifurcations)");
        }
      q["time_tangent_assembly"] = problem.tangent_assembly_seconds;
      q["time_linear_solves"]    = problem.linear_solve_seconds;
      if (problem.contact)
        q["time_contact_active_set"] = problem.contact_seconds;
      q["linear_solves"]         = problem.total_linear_solves;
      if (problem.preconditioner_setup_seconds > 0)
        q["time_preconditioner_setup"] = problem.preconditioner_setup_seconds;
      if (problem.preconditioner_builds > 0)
        q["preconditioner_builds"] = problem.preconditioner_builds;
      if (problem.total_linear_iterations > 0)
        q["linear_iterations"] = problem.total_linear_iterations;
    }
  } // namespace

  PathSettings read_path_settings(dealii::ParameterHandler &prm, const CaseParameters &p, const int dim)
  {
    PathSettings s;
    s.finite_strain.extra   = read_extra_constraints(prm);
    s.finite_strain.contact = read_contact_settings(prm);
    prm.enter_subsection("Finite strain");
    s.finite_strain.law                   = prm.get("Law");
    s.finite_strain.mooney_rivlin_ratio   = prm.get_double("Mooney-Rivlin ratio");
    s.finite_strain.law_constants         = prm.get("Law constants");
    try // bad constants are bad input (exit 2), refused before the mesh is made
      {
        parse_law_constants(s.finite_strain.law, s.finite_strain.law_constants);
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError("case file '" + p.case_file + "': " + e.what());
      }
    s.finite_strain.mixed                 = prm.get("Formulation") == "mixed";
    s.finite_strain.follower_pressure     = prm.get("Follower pressure");
    s.finite_strain.max_newton_iterations = prm.get_integer("Newton iterations");
    s.finite_strain.residual_tolerance    = prm.get_double("Residual tolerance");
    s.finite_strain.secant_predictor      = prm.get("Predictor") == "secant";
    // A moment on a rigid boundary in 3D makes the tangent unsymmetric too (a space-fixed
    // moment is not conservative under finite rotations).
    s.stepping.stability_check = prm.get_bool("Stability check") && s.finite_strain.follower_pressure.empty() &&
                                 !(dim == 3 && !dealii::Utilities::trim(p.rigid).empty());
    s.stepping.initial_step           = prm.get_double("Initial step");
    s.stepping.minimum_step           = prm.get_double("Minimum step");
    s.stepping.maximum_step           = prm.get_double("Maximum step");
    s.arc_length                      = prm.get("Path") == "arc length";
    s.continuation.initial_step       = s.stepping.initial_step;
    s.continuation.minimum_step       = s.stepping.minimum_step;
    s.continuation.maximum_step       = s.stepping.maximum_step;
    s.continuation.max_iterations     = s.finite_strain.max_newton_iterations;
    s.continuation.residual_tolerance = s.finite_strain.residual_tolerance;
    s.continuation.max_steps          = prm.get_integer("Arc length steps");
    prm.leave_subsection();
    return s;
  }


  template <int dim>
  int run_nonlinear_static(const RunContext &context, const SummaryAmendment<dim> &amend_summary,
                           const FiniteStrainProblem<dim> *start_from)
  {
    const auto &p    = context.parameters;
    MPI_Comm    comm = context.communicator;
    const bool  root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    PathSettings settings = read_path_settings(const_cast<dealii::ParameterHandler &>(context.prm), p, dim);

    dealii::Timer timer;
    const auto    partition = choose_mesh_partition(
      context, p, settings.finite_strain.extra.empty() ? "" : "Extra constraints (ties between any two bodies)");
    const auto    set_up    = [&](const std::shared_ptr<const GeometryImperfection> &imperfection) {
      auto problem = std::make_unique<FiniteStrainProblem<dim>>(p, settings.finite_strain, context.geometry, comm,
                                                                partition);
      problem->imperfection = imperfection;
      try
        {
          parse_checks(p.checks);
          problem->setup();
          const auto &bc = problem->boundary_conditions;
          if (bc.clamped.empty() && bc.displacements.empty() && bc.rotations.empty())
            throw std::invalid_argument("Boundary conditions: nothing is clamped, displaced or rotated; "
                                        "a static solve needs the rigid-body motion constrained (a "
                                        "Rigid boundary moves with the body, it does not hold it)");
          if (!problem->contact)
            problem->require_rigid_motion_held("a static solve");
          validate_quantity_requests(*problem);
          if (settings.arc_length)
            problem->require_load_driven();
          if (settings.arc_length && problem->contact)
            problem->contact->require_fixed_frictionless(
              "Finite strain/Path = arc length follows loads, where the load factor may turn back");
        }
      catch (const std::invalid_argument &e)
        {
          throw InputError("case file '" + p.case_file + "': " + e.what());
        }
      return problem;
    };
    // Geometry/Imperfection: the case is checked on the perfect geometry first, then the perfect
    // geometry's buckling modes shift the mesh of the problem that is solved.
    auto       problem_storage = set_up(nullptr);
    Quantities imperfection_quantities;
    if (!p.imperfection.empty() && !context.check_only)
      {
        problem_storage.reset();
        problem_storage = set_up(buckling_mode_imperfection<dim>(context, imperfection_quantities));
      }
    auto &problem = *problem_storage;
    settings.stepping.unstable_advice = unstable_advice(problem.boundary_conditions);
    const auto &law = settings.finite_strain;
    if (report_mesh_and_stop_if_check(context, problem.triangulation.n_global_active_cells(),
                                      problem.dof_handler.n_dofs(),
                                      ", " + law.law + (law.mixed ? ", mixed u-p" : ", displacement") +
                                        (problem.mesh_partition.partition == MeshPartition::distributed ?
                                           ", mesh distributed" :
                                           "")))
      return 0;

    // The response curve is written step by step: a run that stops keeps its converged steps.
    if (root)
      std::filesystem::create_directories(p.output_directory);
    ResponseCurve     curve(p.output_directory + "/curve.csv", root);
    InterruptionGuard interruption;
    problem.stop_requested = [&]() { return interruption.requested(comm); };

    Quantities quantities;
    const auto [per_step_derived, path_derived] = split_derived(p.derived);
    const auto record = [&](const unsigned int number, const double load_factor, const NewtonReport &report,
                            const std::vector<std::pair<std::string, double>> &path_columns) {
      quantities = compute_quantities(problem);
      add_contact_quantities(problem, quantities);
      // Derived quantities per step too, so curves can hold e.g. a link angle.
      try
        {
          add_derived_quantities(per_step_derived, quantities, problem.expression_variables());
        }
      catch (const std::invalid_argument &e)
        {
          throw InputError("case file '" + p.case_file + "': " + e.what());
        }
      if (root)
        print_step(number, load_factor, report, quantities);
      curve.add(number, load_factor, report.iterations, path_columns, quantities);
    };
    PathOutcome outcome;
    const bool  from_state = start_from && solve_from_state(problem, *start_from, record, root, outcome);
    if (!from_state)
      outcome =
        follow_path(problem, settings, record, [&]() { return interruption.requested(comm); }, root, p.case_file);
    std::string failure = outcome.result.failure;
    if (outcome.result.interrupted)
      {
        std::ostringstream message;
        message << "interrupted by " << interruption.signal_name(comm) << " at load factor " << problem.load_factor
                << " (last converged step, " << outcome.result.steps << " steps)";
        failure = message.str();
      }
    curve.finish();
    if (problem.contact)
      {
        auto residual = problem.reaction_forces();
        residual *= -1;
        problem.contact->write_csv(p.output_directory + "/contact.csv", problem.solution, residual, problem.load_factor);
      }

    RunSummary summary = start_summary(context, problem.triangulation.all_reference_cells_are_hyper_cube());
    summary.settings.insert({"law", law.law});
    summary.settings.insert({"formulation", law.mixed ? "mixed" : "displacement"});
    summary.settings.insert({"solver", problem.linear_solver_description()});
    summary.settings.insert({"solver_requested", to_string(context.parameters.solver_method)});
    summary.settings.insert({"mesh_partition", to_string(problem.mesh_partition.partition)});
    summary.settings.insert({"status", failure.empty() ? "completed" : failure});
    summary.settings.insert({"curve", curve.file});
    if (from_state)
      summary.settings.insert({"path", "Newton at the end load from a lower degree's state (not followed)"});
    summary.quantities = quantities;
    summary.quantities.insert(imperfection_quantities.begin(), imperfection_quantities.end());
    add_path_quantities(summary, problem, outcome, path_derived, p.case_file);
    summary.quantities["time_total"] = timer.wall_time();
    if (amend_summary)
      amend_summary(summary, problem);
    finish_run(context, summary, problem.expression_variables(),
               [&](const std::string &directory) { write_fields(problem, directory); },
               [&](const RunSummary &finished) { return static_pictures(problem, finished, curve.file); });
    if (!failure.empty())
      {
        if (root)
          std::cerr << "error: " << failure << "; converged steps are in " << curve.file << std::endl;
        return outcome.result.interrupted ? interruption.exit_code(comm) : 3;
      }
    return 0;
  }

  template int run_nonlinear_static<2>(const RunContext &, const SummaryAmendment<2> &, const FiniteStrainProblem<2> *);
  template int run_nonlinear_static<3>(const RunContext &, const SummaryAmendment<3> &, const FiniteStrainProblem<3> *);

  Analysis nonlinear_static_analysis()
  {
    return {{"nonlinear static",
            "total-Lagrangian finite strain, Newton-Raphson with adaptive load steps (see "
            "subsection Finite strain)",
            declare},
            [](const RunContext &context) {
              return context.parameters.dimension == 2 ? run_nonlinear_static_with_estimates<2>(context) :
                                                         run_nonlinear_static_with_estimates<3>(context);
            }};
  }
} // namespace compliant
