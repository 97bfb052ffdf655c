#include "ladder/model_ladder.h"

#include "input/spec_list.h"

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
                      "with the largest indicators (Refinement indicator), leaving hanging nodes; "
                      "quadrilateral and hexahedral meshes only; finite-strain rungs too, their duals "
                      "solved with the tangent at each rung's converged state. degree: the rungs raise the "
                      "element degree on the case's mesh, 2, 3, 4 (only 2 on triangles and "
                      "tetrahedra), then halve every cell at the highest degree; the error is extrapolated in the DoF "
                      "count (p-extension); finite-strain rungs climb in degree too. A degree step "
                      "costs about 3x the DoFs in 3D where halving the cells costs 8x. "
                      "Discretization/Element degree is then not used. Finite-strain rungs climb "
                      "at Discretization/Element degree under auto, uniform and adaptive "
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
    prm.declare_entry("Refinement indicator", "goal", Patterns::Selection("goal|kelly"),
                      "Adaptive refinement: goal: dual-weighted (goal-oriented) indicators, Kelly's "
                      "for the solution times Kelly's for the dual of each target quantity (one more "
                      "solve per target: point displacements, stresses at points, mean displacements, "
                      "reactions, moments and stiffnesses, and derived targets made of them, their "
                      "parts combined by the target's linearization; the strain energy uses the "
                      "solution itself); kelly: Kelly's gradient-jump indicator of the solution alone.");
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
    t.goal_oriented       = prm.get("Refinement indicator") == "goal";
    t.closed_forms        = prm.get_bool("Closed forms");
    t.paired_model        = prm.get("Paired model");
    for (const auto &item : split(prm.get("Quantities"), ','))
      if (const auto name = trim(item); !name.empty())
        t.quantities.push_back(name);
    prm.leave_subsection();
    return t;
  }
} // namespace compliant
