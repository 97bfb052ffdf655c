#include "analyses/modal.h"

#include "analyses/error_estimates.h"

#include <deal.II/base/timer.h>

#include "constraints/extra_constraints.h"
#include "elasticity/global_constraints.h"
#include "analyses/modal_eigensolver.h"
#include "analyses/modal_fields.h"
#include "output/run_pictures.h"
#include "analyses/modal_mass_matrix.h"
#include "analyses/setup_without_supports.h"
#include "elasticity/linear_elastic_problem.h"
#include "input/spec_list.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>

namespace compliant
{
  namespace
  {
    const char *axis_name[3] = {"x", "y", "z"};

    // Auto shift: this fraction of max(K_ii / M_ii), an upper estimate of the largest
    // eigenvalue of the mesh. Far below any flexible mode of a reasonable mesh, large enough that
    // K - sigma M stays well conditioned (condition number about 1e9) for MUMPS.
    constexpr double auto_shift_fraction = 1e-9;

    struct ModalSettings
    {
      unsigned int n_modes;
      bool         auto_shift;
      double       shift_frequency; // Hz, when not auto
      double       tolerance;
      unsigned int max_iterations;
    };

    ModalSettings read_settings(const RunContext &context)
    {
      const auto   &prm = context.prm;
      ModalSettings s;
      s.n_modes        = prm.get_integer({"Modal"}, "Number of modes");
      s.tolerance      = prm.get_double({"Modal"}, "Tolerance");
      s.max_iterations = prm.get_integer({"Modal"}, "Maximum iterations");
      const std::string shift = trim(prm.get({"Modal"}, "Shift"));
      s.auto_shift            = shift == "auto";
      s.shift_frequency       = 0;
      if (!s.auto_shift)
        {
          const auto v = [&] {
            try
              {
                return parse_numbers(shift, "Modal/Shift");
              }
            catch (const std::invalid_argument &)
              {
                return std::vector<double>();
              }
          }();
          if (v.size() != 1)
            throw InputError("case file '" + context.parameters.case_file +
                             "': Modal/Shift: expected 'auto' or one frequency in Hz, got '" +
                             shift + "'");
          s.shift_frequency = v[0];
        }
      return s;
    }

    // max over unconstrained DoFs of K_ii / M_ii.
    double diagonal_ratio_bound(const dealii::PETScWrappers::MPI::SparseMatrix &stiffness,
                                const dealii::PETScWrappers::MPI::SparseMatrix &mass,
                                const dealii::IndexSet                         &owned,
                                const dealii::AffineConstraints<double>        &constraints,
                                MPI_Comm                                        comm)
    {
      double largest = 0;
      for (const auto i : owned)
        if (!constraints.is_constrained(i) && mass.diag_element(i) > 0)
          largest = std::max(largest, stiffness.diag_element(i) / mass.diag_element(i));
      return dealii::Utilities::MPI::max(largest, comm);
    }

    // Frequencies and effective modal masses (Chopra, Dynamics of Structures, sec. 13.2.5): with
    // x^T M x = 1, Gamma_d = x^T M r_d, m_eff = Gamma_d^2; over all modes it sums to r_d^T M r_d
    // (the mass that is not on supports). q holds total_mass already.
    template <int dim>
    void add_frequencies_and_effective_masses(const LinearElasticProblem<dim>                &problem,
                                              const dealii::PETScWrappers::MPI::SparseMatrix &mass,
                                              const EigenResult &result, std::map<std::string, double> &q)
    {
      const double two_pi = 2 * M_PI;
      std::vector<dealii::PETScWrappers::MPI::Vector> m_r;
      for (unsigned int d = 0; d < dim; ++d)
        {
          m_r.emplace_back(problem.locally_owned_dofs, problem.communicator);
          mass.vmult(m_r.back(), translation(problem, d));
        }
      std::vector<double> fraction_sum(dim, 0.);
      for (unsigned int n = 0; n < result.eigenvalues.size(); ++n)
        {
          const double lambda = result.eigenvalues[n];
          const std::string id = std::to_string(n + 1);
          // A rigid-body mode may come out slightly negative: keep the sign visible.
          q["frequency_" + id] = std::copysign(std::sqrt(std::abs(lambda)), lambda) / two_pi;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const double gamma = result.eigenvectors[n] * m_r[d];
              const double m_eff = gamma * gamma;
              q["effective_mass_" + std::string(axis_name[d]) + "_" + id]          = m_eff;
              q["effective_mass_fraction_" + std::string(axis_name[d]) + "_" + id] = m_eff / q["total_mass"];
              fraction_sum[d] += m_eff / q["total_mass"];
            }
        }
      for (unsigned int d = 0; d < dim; ++d)
        q["effective_mass_fraction_" + std::string(axis_name[d]) + "_sum"] = fraction_sum[d];
    }

    // One modal model built and solved: what run() reports, and what the error estimates solve
    // again one degree up.
    template <int dim>
    struct ModalModel
    {
      std::unique_ptr<LinearElasticProblem<dim>> problem;
      std::unique_ptr<dealii::PETScWrappers::MPI::SparseMatrix> mass; // not movable itself
      EigenResult                                 result;
      EigenSettings                               eigen;
      Quantities                                  q;
      bool                                        supported = false, stopped_for_check = false;
    };

    template <int dim>
    ModalModel<dim> solve_modal_model(const RunContext &context, const CaseParameters &p, const ModalSettings &settings)
    {
      MPI_Comm               comm = context.communicator;
      dealii::Timer          timer;
      ModalModel<dim>        model;
      const ExtraConstraints extra = read_extra_constraints(context.prm);
      model.supported = has_supports(p) || !extra.edge_supports.empty() || !extra.mirror_ties.empty();
      model.problem   = std::make_unique<LinearElasticProblem<dim>>(
        p, context.geometry, comm, choose_mesh_partition(context, p, "the modal analysis (constraints gathered on every rank)"));
      auto &problem = *model.problem;
      // Supports hold still in a vibration: the constraints without their prescribed values.
      dealii::AffineConstraints<double> constraints;
      try
        {
          parse_checks(p.checks);
          if (has_supports(p))
            problem.setup();
          else
            setup_without_supports(problem);
          constraints = gather_constraints(problem, true);
          add_extra_constraints(problem, extra, constraints);
        }
      catch (const std::invalid_argument &e)
        {
          throw InputError("case file '" + p.case_file + "': " + e.what());
        }
      if (settings.n_modes > problem.dof_handler.n_dofs() / 2)
        throw InputError("case file '" + p.case_file + "': Modal/Number of modes = " +
                         std::to_string(settings.n_modes) + " is too many for " +
                         std::to_string(problem.dof_handler.n_dofs()) + " DoFs");
      const RunContext model_context{p, context.prm, context.geometry, context.check_only, comm};
      if (report_mesh_and_stop_if_check(model_context, problem.triangulation.n_global_active_cells(),
                                        problem.dof_handler.n_dofs(), model.supported ? "" : ", no supports (free)"))
        {
          model.stopped_for_check = true;
          return model;
        }

      const auto sparsity = install_constraints(problem, std::move(constraints));
      problem.assemble(); // the stiffness; the load vector is not used
      dealii::Timer mass_timer;
      model.mass = std::make_unique<dealii::PETScWrappers::MPI::SparseMatrix>();
      assemble_mass_matrix(problem, sparsity, *model.mass);
      const double mass_seconds = mass_timer.wall_time();

      auto &eigen          = model.eigen;
      eigen.n_modes        = settings.n_modes;
      eigen.tolerance      = settings.tolerance;
      eigen.max_iterations = settings.max_iterations;
      eigen.petsc_options  = p.petsc_options;
      const double two_pi  = 2 * M_PI;
      if (settings.auto_shift)
        eigen.shift = -auto_shift_fraction * diagonal_ratio_bound(problem.system_matrix, *model.mass,
                                                                  problem.locally_owned_dofs,
                                                                  problem.constraints, comm);
      else
        eigen.shift = std::copysign(std::pow(two_pi * settings.shift_frequency, 2),
                                    settings.shift_frequency);
      dealii::Timer eigen_timer;
      model.result = solve_eigenproblem(problem.system_matrix, *model.mass, problem.locally_owned_dofs, eigen);
      const double eigen_seconds = eigen_timer.wall_time();

      auto &q            = model.q;
      q["n_dofs"]        = problem.dof_handler.n_dofs();
      q["n_cells"]       = problem.triangulation.n_global_active_cells();
      q["n_ranks"]       = dealii::Utilities::MPI::n_mpi_processes(comm);
      q["total_mass"]    = total_mass(problem);
      q["eigen_shift"]   = eigen.shift;
      q["eigensolver_iterations"] = model.result.iterations;
      double worst_error          = 0;
      for (const double e : model.result.backward_errors)
        worst_error = std::max(worst_error, e);
      q["eigen_backward_error_max"] = worst_error;

      add_frequencies_and_effective_masses(problem, *model.mass, model.result, q);
      q["time_setup"]      = problem.statistics.setup_seconds;
      q["time_assembly"]   = problem.statistics.assembly_seconds + mass_seconds;
      q["time_eigensolve"] = eigen_seconds;
      q["time_total"]      = timer.wall_time();
      return model;
    }

    template <int dim>
    void print_modes(const ModalModel<dim> &model)
    {
      const auto &q = model.q;
      std::cout << "Eigensolver: " << model.result.n_converged << " pairs converged, " << model.result.iterations
                << " restarts, shift " << model.eigen.shift << ", " << q.at("time_eigensolve")
                << " s\n  mode  frequency (Hz)  effective mass fraction";
      for (unsigned int d = 0; d < dim; ++d)
        std::cout << "  " << axis_name[d];
      std::cout << "\n";
      for (unsigned int n = 0; n < model.result.eigenvalues.size(); ++n)
        {
          const std::string id = std::to_string(n + 1);
          std::cout << "  " << std::setw(4) << n + 1 << "  " << std::setw(14) << std::setprecision(8)
                    << q.at("frequency_" + id) << "  ";
          for (unsigned int d = 0; d < dim; ++d)
            std::cout << std::setw(10) << std::setprecision(4)
                      << q.at("effective_mass_fraction_" + std::string(axis_name[d]) + "_" + id);
          std::cout << "\n";
        }
      std::cout << std::flush;
    }

    template <int dim>
    int run(const RunContext &context)
    {
      const auto         &p    = context.parameters;
      const bool          root = dealii::Utilities::MPI::this_mpi_process(context.communicator) == 0;
      const ModalSettings settings = read_settings(context);
      // Static quantities have no meaning for a mode: say so rather than drop them silently.
      std::string ignored;
      for (const auto &[name, value] :
           {std::pair<std::string, std::string>{"Points", p.points}, {"Reactions", p.reactions},
            {"Mean displacements", p.mean_displacements}, {"Rotations", p.rotations},
            {"Region maxima", p.region_maxima}})
        if (!value.empty())
          ignored += (ignored.empty() ? "" : ", ") + ("Quantities/" + name);
      if (root && !ignored.empty())
        std::cout << "note: a modal analysis reports frequencies, effective masses and Derived "
                     "quantities; ignored here: "
                  << ignored << "\n";
      auto model = solve_modal_model<dim>(context, p, settings);
      if (model.stopped_for_check)
        return 0;
      auto &problem = *model.problem;
      if (root)
        print_modes(model);

      RunSummary summary =
        start_summary(context, problem.triangulation.all_reference_cells_are_hyper_cube());
      summary.settings.insert({"eigensolver", "SLEPc Krylov-Schur, shift-and-invert, MUMPS"});
      summary.settings.insert({"mass_matrix", "consistent"});
      summary.settings.insert({"supports", model.supported ? "Dirichlet boundaries held fixed" : "none (free)"});
      if (!ignored.empty())
        summary.settings.insert({"ignored_quantities", ignored});
      summary.quantities = model.q;
      if (p.error_estimates)
        {
          // Frequencies one degree up (the eigenvalue's dual is its own mode): the same modes in
          // the same order, ascending.
          Quantities frequencies{{"n_cells", model.q.at("n_cells")}}; // for the memory check
          for (const auto &[name, value] : model.q)
            if (name.rfind("frequency_", 0) == 0)
              frequencies[name] = value;
          const auto estimates = estimate_quantity_errors<dim>(
            context, p, frequencies, problem.triangulation.all_reference_cells_are_hyper_cube(),
            [&](const RunContext &enriched_context, const CaseParameters &enriched) {
              const auto plus = solve_modal_model<dim>(enriched_context, enriched, settings);
              return std::make_pair(plus.q, static_cast<std::size_t>(plus.problem->dof_handler.n_dofs()));
            });
          add_error_estimates(summary, estimates);
        }

      for (auto &x : model.result.eigenvectors)
        problem.constraints.distribute(x);
      auto variables   = problem.expression_variables();
      variables["rho"] = problem.materials.begin()->second.density;
      finish_run(context, summary, variables, [&](const std::string &directory) {
        write_mode_shapes(problem, model.result.eigenvectors, directory);
      }, [&](const RunSummary &finished) { return mode_pictures<dim>(problem, model.result.eigenvectors, finished); });
      return 0;
    }
  } // namespace

  Analysis modal_analysis()
  {
    return {{"modal",
            "natural frequencies and mode shapes (consistent mass, SLEPc shift-and-invert); "
            "supports held fixed, loads ignored; settings in the Modal subsection",
            [](dealii::ParameterHandler &prm) {
              declare_extra_constraints(prm);
              prm.enter_subsection("Modal");
              prm.declare_entry("Number of modes", "6", dealii::Patterns::Integer(1, 1000),
                                "How many of the lowest natural frequencies (nearest the shift) "
                                "to compute; rigid-body modes of a free structure count (3 in "
                                "2D, 6 in 3D).");
              prm.declare_entry("Shift", "auto", dealii::Patterns::Anything(),
                                "'auto': a small negative spectral shift (1e-9 max K_ii/M_ii "
                                "below zero) so that the lowest modes are found, supported or "
                                "free. Or a frequency f in Hz: the modes nearest f, shift "
                                "(2 pi f)^2 (f < 0 gives -(2 pi f)^2; f = 0 fails for a free "
                                "structure, whose K is singular).");
              prm.declare_entry("Tolerance", "1e-10", dealii::Patterns::Double(0, 1),
                                "Relative convergence tolerance of the eigenpairs (SLEPc).");
              prm.declare_entry("Maximum iterations", "1000", dealii::Patterns::Integer(1),
                                "Krylov-Schur restarts before giving up.");
              prm.leave_subsection();
            }},
            [](const RunContext &context) {
              return context.parameters.dimension == 2 ? run<2>(context) : run<3>(context);
            }};
  }
} // namespace compliant
