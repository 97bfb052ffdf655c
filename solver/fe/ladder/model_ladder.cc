// The model ladder's entry and its order of steps: (a) closed forms, (b) the dimension, then the
// linear rungs with (c) the linear/finite-strain decision, and the finite-strain rungs (d).
#include "ladder/model_ladder.h"

#include "input/spec_list.h"
#include "ladder/ladder_climb.h"
#include "ladder/percent.h"
#include "quantities/comparison.h"

#include <algorithm>
#include <iostream>

namespace compliant
{
  namespace
  {
    std::vector<std::string> check_quantities(const std::string &checks)
    {
      std::vector<std::string> names; // once each, though several checks may name a quantity
      for (const auto &c : parse_checks(checks))
        if (std::find(names.begin(), names.end(), c.quantity) == names.end())
          names.push_back(c.quantity);
      return names;
    }
  } // namespace

  template <int dim>
  LadderClimb<dim>::LadderClimb(const RunContext &context, const TargetSettings &target, DimensionVerdict *verdict)
    : context(context)
    , p(context.parameters)
    , target(target)
    , verdict(verdict)
    , root(dealii::Utilities::MPI::this_mpi_process(context.communicator) == 0)
    , names(target.quantities.empty() ? check_quantities(context.parameters.checks) : target.quantities)
    , earlier_rows(target.earlier_rows)
    , planner(target.degree || (target.automatic && dim == 3), context.parameters.element_degree)
    , stop_rule(planner.degree_rungs())
    , out_of_plane(target.dimension_bound)
    , dimension_reason(target.dimension_note)
  {
    if (names.empty())
      throw InputError("case file '" + p.case_file + "', Target/Quantities: name the quantities the "
                       "target applies to (or give Comparison/Checks)");
    // (b) across dimensions: the other dimension's model of the same part, read (and checked)
    // before anything is solved.
    if (!target.paired_model.empty())
      paired = read_paired_model(p, context.geometry, target.paired_model, context.communicator);
    // A plane-stress climb standing for a 3D part: its out-of-plane bound takes its share of the
    // target, and the climb gives way to the 3D model when the bound alone misses it.
    stand_in = target.stand_in_for_3d || (dim == 2 && paired);
  }

  template <int dim>
  int LadderClimb<dim>::run()
  {
    if (root)
      {
        std::cout << "Model ladder" << (target.stand_in_for_3d ? " (plane-stress model of the 3D part)" : "")
                  << ": target " << percent(target.relative_error) << " on";
        for (const auto &n : names)
          std::cout << ' ' << n;
        std::cout << "\n";
      }
    if (const auto rc = answer_by_closed_forms())
      return *rc;
    if (const auto rc = plane_stress_model_first())
      return *rc;
    print_dimension_line();
    if (const auto rc = climb_linear())
      return *rc;
    if (stand_in && !met && !finite_strain)
      {
        // Estimate plus bound did not meet the target within the rungs allowed: the 3D part may.
        dimension_reason = "the plane-stress model did not meet the target (its estimate plus the "
                           "out-of-plane bound " + percent(out_of_plane) + ") within its rungs";
        return give_way_to_3d();
      }
    return finite_strain ? climb_finite_strain() : finish_linear();
  }

  template <int dim>
  TargetSettings LadderClimb<dim>::paired_target() const
  {
    TargetSettings t = target;
    t.paired_model.clear();
    t.quantities = names;
    t.pair_of    = p.case_file;
    return t;
  }

  template <int dim>
  std::optional<int> LadderClimb<dim>::plane_stress_model_first()
  {
    // (b) A plane-stress model is checked against the 3D solid it stands for on every rung (the
    // energy bound of quantities/out_of_plane_bound.h); the last rung's bound is reported.
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
    return std::nullopt;
  }

  template <int dim>
  void LadderClimb<dim>::print_dimension_line() const
  {
    if (!root)
      return;
    if (paired && context.check_only)
      std::cout << "  (b) paired model " << paired->parameters.case_file << " read and meshed: the same part\n";
    else if (dim == 3 && !dimension_reason.empty())
      std::cout << "  (b) 3D: " << dimension_reason << "\n";
    else if (p.model != Model::plane_stress)
      std::cout << "  (b) dimension as set by Model = " << to_string(p.model)
                << (p.model == Model::three_d ? "" : " (no out-of-plane bound for plane strain: it stands for a part "
                                           "long in z or held at its z faces)")
                << "\n";
  }

  template <int dim>
  std::vector<LadderRow> LadderClimb<dim>::all_rows() const
  {
    std::vector<LadderRow> rows = earlier_rows;
    for (const auto &rung : rungs)
      rows.push_back(ladder_row(rung, names, stand_in));
    return rows;
  }

  template <int dim>
  void LadderClimb<dim>::print(const Rung &rung) const
  {
    if (root)
      print_rung(std::cout, rung, earlier_rows.size() + rungs.size() + 1, target.adaptive && rung.model == "linear");
  }

  template <int dim>
  int LadderClimb<dim>::give_way_to_3d()
  {
    // Hand the climb to the 3D model, with this model's rungs for its ladder.csv.
    const std::vector<LadderRow> rows = all_rows();
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
  }

  template <int dim>
  int run_model_ladder(const RunContext &context, const TargetSettings &target, DimensionVerdict *verdict)
  {
    LadderClimb<dim> climb(context, target, verdict);
    return climb.run();
  }

  template class LadderClimb<2>;
  template class LadderClimb<3>;
  template int run_model_ladder<2>(const RunContext &, const TargetSettings &, DimensionVerdict *);
  template int run_model_ladder<3>(const RunContext &, const TargetSettings &, DimensionVerdict *);
} // namespace compliant
