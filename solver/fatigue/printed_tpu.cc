#include <fatigue/printed_tpu.h>

#include <sstream>
#include <stdexcept>

namespace fatigue
{
  namespace printed_tpu
  {
    namespace
    {
      LifeCurve
      make_curve(const std::string &name, const double reference_amplitude, const double exponent,
                 const std::string &source)
      {
        LifeCurve curve;
        curve.name                = name;
        curve.reference_amplitude = reference_amplitude;
        curve.reference_cycles    = anchor_cycles;
        curve.exponent            = exponent;
        curve.endurance_amplitude = 0.0;
        curve.source              = source;
        curve.check();
        return curve;
      }
    } // namespace

    double
    anchor_equivalent_strain_amplitude(const MeanCorrectionSettings &correction)
    {
      if (correction.kind != MeanCorrection::elastomer_walker &&
          correction.kind != MeanCorrection::none)
        throw std::invalid_argument(
            "fatigue: parameter 'correction' of the printed TPU strain model "
            "must be strain based (elastomer-walker or none), got '" +
            to_string(correction.kind) + "'");
      correction.check();
      const double maximum = anchor_maximum_stress / low_strain_modulus;
      return equivalent_amplitude(maximum, anchor_stress_ratio * maximum, correction);
    }

    double
    anchor_equivalent_stress_amplitude(const MeanCorrectionSettings &correction)
    {
      if (correction.kind == MeanCorrection::elastomer_walker)
        throw std::invalid_argument(
            "fatigue: parameter 'correction' of the printed TPU stress model "
            "must be stress based (none, goodman or swt), got "
            "'elastomer-walker'");
      correction.check();
      return equivalent_amplitude(anchor_maximum_stress,
                                  anchor_stress_ratio * anchor_maximum_stress, correction);
    }

    FatigueModel
    strain_model(const double walker_exponent)
    {
      MeanCorrectionSettings correction;
      correction.kind            = MeanCorrection::elastomer_walker;
      correction.walker_exponent = walker_exponent;
      return strain_model(correction);
    }

    FatigueModel
    strain_model(const MeanCorrectionSettings &correction)
    {
      FatigueModel model;
      model.name       = "printed-tpu-strain-v1";
      model.quantity   = Quantity::strain;
      model.unit       = ""; // dimensionless
      model.correction = correction;

      const double      anchor = anchor_equivalent_strain_amplitude(correction);
      const std::string origin =
          "anchor: Wang et al. 2023 bulk TPU fatigue limit 10.25 MPa at R = 0.1 over E = 89.5 MPa "
          "(Bates et al. 2016), placed at 1e6 cycles";
      model.curves[low_life] =
          make_curve("printed-tpu-strain-v1/low", 0.5 * anchor, 4.0,
                     origin + "; x0.5 printed across-layer knock-down; k = 2F, F = 2");
      model.curves[nominal_life] =
          make_curve("printed-tpu-strain-v1/nominal", anchor, 6.0, origin + "; k = 2F, F = 3");
      model.curves[high_life] = make_curve(
          "printed-tpu-strain-v1/high", 2.0 * anchor, 8.0,
          origin + "; x2 strain control without cyclic creep, printed TPU hinges > 2e6 folds; "
                   "k = 2F, F = 4");

      std::ostringstream assumption;
      assumption << "ASSUMED strain-life curve (no published constants for printed TPU): "
                 << "N = 1e6 (eps_eq / a_ref)^-k, eps_eq = maximum principal strain amplitude "
                 << "(" << to_string(correction.kind)
                 << "); a_ref = " << model.curves[low_life].reference_amplitude << " / "
                 << model.curves[nominal_life].reference_amplitude << " / "
                 << model.curves[high_life].reference_amplitude
                 << " and k = 4 / 6 / 8 (low / nominal / high)";
      model.assumption = assumption.str();
      model.check();
      return model;
    }

    FatigueModel
    stress_model(const MeanCorrectionSettings &correction)
    {
      FatigueModel model;
      model.name       = "printed-tpu-stress-v1";
      model.quantity   = Quantity::stress;
      model.unit       = "MPa";
      model.correction = correction;

      const double      anchor = anchor_equivalent_stress_amplitude(correction);
      const std::string origin = "anchor: Wang et al. 2023 bulk TPU fatigue limit 10.25 MPa at "
                                 "R = 0.1 through the " +
                                 to_string(correction.kind) + " correction, placed at 1e6 cycles";
      model.curves[low_life]     = make_curve("printed-tpu-stress-v1/low", 0.5 * anchor, 8.0,
                                              origin + "; x0.5 printed across-layer knock-down");
      model.curves[nominal_life] = make_curve("printed-tpu-stress-v1/nominal", 0.75 * anchor, 12.0,
                                              origin + "; x0.75 printed knock-down");
      model.curves[high_life] =
          make_curve("printed-tpu-stress-v1/high", anchor, 16.0, origin + "; bulk value");

      std::ostringstream assumption;
      assumption << "ASSUMED stress-life curve (no published constants for printed TPU): "
                 << "N = 1e6 (s_eq / a_ref)^-k in MPa; a_ref = "
                 << model.curves[low_life].reference_amplitude << " / "
                 << model.curves[nominal_life].reference_amplitude << " / "
                 << model.curves[high_life].reference_amplitude
                 << " and k = 8 / 12 / 16 (low / nominal / high)";
      model.assumption = assumption.str();
      model.check();
      return model;
    }
  } // namespace printed_tpu
} // namespace fatigue
