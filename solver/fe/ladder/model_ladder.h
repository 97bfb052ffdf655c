// The model ladder (Target/Relative error > 0): a linear static case climbs from the cheapest model
// until the estimated error of its quantities meets the target. Rungs: (a) a closed form named in
// Comparison answers a quantity when its own error bound meets the target; (b) a plane-stress model
// is checked against the 3D solid it stands for by an energy bound (quantities/out_of_plane_bound.h),
// printed with its verdict and written to the summary (out_of_plane_bound, ladder_dimension_check);
// with Target/Paired model (ladder/paired_model.h) the ladder climbs the plane-stress model first
// and goes on to the 3D part when the bound plus the discretization estimate cannot meet the target;
// (c) linear before finite strain: after the first linear rung the largest material rotation theta
// decides, the geometric error of a linear model being of order theta^2; (d) refinement at the
// case's degree, uniform or adaptive (Kelly indicator, hanging nodes), or first the degree (2, 3, 4
// on the case's mesh, then halved cells at the highest degree; the default on 3D hexahedra), until the Richardson estimate
// (observed order, mesh size h = N^(-1/dim) from the DoF count N; for a degree sequence this is
// the p-extension extrapolation of Szabo and Babuska) meets the target. Each rung is
// printed (model, DoFs, time, values, estimates, why it went on) and written to ladder.csv.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include "analyses/analysis.h"
#include "ladder/ladder_row.h"

#include <string>
#include <vector>

namespace compliant
{
  struct TargetSettings
  {
    double                   relative_error = 0; // fraction (the case gives percent)
    std::vector<std::string> quantities;
    unsigned int             max_refinements = 4;
    bool                     allow_finite_strain = true;
    bool                     adaptive = false;       // Refinement = adaptive
    bool                     degree   = false;       // Refinement = degree
    bool                     automatic = false;      // Refinement = auto: degree on 3D hexahedra, else uniform
    double                   refined_fraction = 0.3; // of the cells, per adaptive rung
    bool                     goal_oriented    = true; // dual-weighted indicators (else Kelly's)
    bool                     closed_forms = true;    // rung (a): a closed form with a bound may stop the climb
    std::string              paired_model; // Target/Paired model: the other dimension's model of the part

    // Set by the ladder for the climbs it starts itself across dimensions (paired_model.h):
    bool        stand_in_for_3d = false; // a plane-stress climb that gives way to the 3D part
    std::string dimension_note;          // why the 3D part is climbed: for its summary
    double      dimension_bound = -1;    // the plane-stress model's out-of-plane bound, if computed
    std::string pair_of;                 // the case whose target this climb answers, if another
    std::vector<LadderRow> earlier_rows; // rungs of the plane-stress model, before this climb's
    double                 earlier_seconds = 0; // their time, when not inside this climb's own
  };

  // What a plane-stress climb standing in for a 3D part found when it gave way to the 3D model.
  struct DimensionVerdict
  {
    std::string            reason;
    double                 bound = -1;
    std::vector<LadderRow> rows; // the plane-stress model's rungs
  };

  void           declare_target_settings(dealii::ParameterHandler &prm);
  TargetSettings read_target_settings(dealii::ParameterHandler &prm);

  // Returns the exit code: 0 target met, 4 not met. A plane-stress climb standing in for a 3D part
  // (target.stand_in_for_3d) returns needs_3d_model instead when its out-of-plane bound misses,
  // with the reason in *verdict.
  template <int dim>
  int run_model_ladder(const RunContext &context, const TargetSettings &target,
                       DimensionVerdict *verdict = nullptr);

  constexpr int needs_3d_model = 100;
} // namespace compliant
