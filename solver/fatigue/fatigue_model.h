// A fatigue model: what is counted (strain or stress), how a cycle becomes an equivalent amplitude
// (mean correction) and the life curve as an uncertainty band of three parameter sets. The band is
// part of the model because for printed TPU no published curve exists (see printed_tpu.h).
#ifndef FATIGUE_FATIGUE_MODEL_H
#define FATIGUE_FATIGUE_MODEL_H

#include <fatigue/life_curve.h>
#include <fatigue/mean_correction.h>

#include <array>
#include <cstddef>
#include <string>

namespace fatigue
{
  enum class Quantity
  {
    strain, // maximum principal (engineering) strain, dimensionless
    stress  // maximum principal stress, in the unit of the curve (MPa for the built-in models)
  };

  std::string
  to_string(Quantity quantity);
  Quantity
  parse_quantity(const std::string &name); // "strain" or "stress"

  // Positions in FatigueModel::curves. "low" is the parameter set expected to give the shortest
  // life, "high" the longest; the reported band is nevertheless the min/max over all three (the
  // curves have different slopes and could cross far outside their intended range).
  enum BandMember : std::size_t
  {
    low_life     = 0,
    nominal_life = 1,
    high_life    = 2
  };
  constexpr std::size_t n_band_members = 3;

  std::string
  band_member_name(std::size_t member); // "low", "nominal", "high"

  struct FatigueModel
  {
    std::string                           name;
    Quantity                              quantity = Quantity::strain;
    std::string                           unit; // of the history and of the curves' amplitudes
    MeanCorrectionSettings                correction;
    std::array<LifeCurve, n_band_members> curves;
    std::string                           assumption; // the stated assumption behind the curves

    void
    check() const;
  };
} // namespace fatigue

#endif
