// The model ladder's climb (private to ladder/): the state one run_model_ladder call carries from
// rung to rung, and one member per step of the climb, each in its own file:
//   closed_form_rung.cc    (a) closed forms that answer the target without a model
//   model_ladder.cc        (b) the plane-stress model of a 3D part first, and the hand-over to 3D
//   linear_climb.cc        (b), (c) and (d) on linear rungs, and the linear result
//   finite_strain_climb.cc (d) on finite-strain rungs
// The decisions themselves are plain functions (stop_rule.h, rung_plan.h, model_checks.h).
#pragma once

#include <deal.II/base/timer.h>

#include "analyses/linear_static_model.h"
#include "ladder/ladder_table.h"
#include "ladder/model_ladder.h"
#include "ladder/paired_model.h"
#include "ladder/rung_plan.h"
#include "ladder/stop_rule.h"

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace compliant
{
  template <int dim>
  class FiniteStrainProblem;
  struct RunSummary;

  template <int dim>
  class LadderClimb
  {
  public:
    LadderClimb(const RunContext &context, const TargetSettings &target, DimensionVerdict *verdict);
    int run();

  private:
    // (a) every target quantity answered by a closed form within the target: the exit code.
    std::optional<int> answer_by_closed_forms();
    // (b) a 3D part with a paired plane-stress model climbs that first: its exit code if it answered.
    std::optional<int> plane_stress_model_first();
    void               print_dimension_line() const;
    // (d) linear rungs; an exit code if the climb ended there (a --check, or the hand-over to 3D).
    std::optional<int> climb_linear();
    // A linear rung's values, estimates and stop estimates; true if every one meets the target.
    bool estimate_rung(const LinearStaticModel<dim> &model, const CaseParameters &rung_parameters, Rung &rung,
                       std::map<std::string, std::vector<double>> &history, const std::vector<double> &mesh_sizes);
    // Refine flags for the next adaptive rung: goal-oriented (Target/Refinement indicator) or Kelly's.
    std::vector<bool> refine_flags(const LinearStaticModel<dim> &model);
    // (b) a plane-stress rung against its 3D solid; why it cannot stand for the 3D part ("" if it can).
    std::string check_plane_stress(const LinearStaticModel<dim> &model, const Rung &rung, unsigned int k);
    int                finish_linear();
    int                climb_finite_strain();
    // Refine flags for the next adaptive finite-strain rung, from the problem at its converged state.
    std::vector<bool> finite_strain_flags(FiniteStrainProblem<dim> &problem, const RunSummary &summary);
    // This plane-stress model cannot stand for its 3D part (dimension_reason says why).
    int            give_way_to_3d();
    TargetSettings paired_target() const;
    std::vector<LadderRow> all_rows() const;
    void                   print(const Rung &rung) const;
    void                   add_estimates_to_summary(RunSummary &summary, const Rung &rung) const;

    const RunContext       &context;
    const CaseParameters   &p;
    const TargetSettings   &target;
    DimensionVerdict       *verdict;
    const bool              root;
    dealii::Timer           total;
    std::vector<std::string> names;
    std::optional<PairedModel> paired;
    bool                       stand_in = false; // a plane-stress climb answering for a 3D part

    std::vector<Rung>              rungs;
    std::vector<LadderRow>         earlier_rows; // of an abandoned plane-stress model
    RungPlanner                    planner;
    StopRule                       stop_rule;
    std::uint64_t                  last_cells = 0;
    std::string                    too_large; // why the climb stopped short, if it did
    std::vector<std::vector<bool>> adaptive_refinements;

    std::unique_ptr<CaseParameters> chosen_parameters;
    LinearStaticModel<dim>          chosen;
    bool                            met = false, finite_strain = false;
    std::string                     geometric_reason;
    double                          out_of_plane; // relative, < 0: not computed
    std::string                     dimension_reason;
  };
} // namespace compliant
