// Fatigue assessment of several named locations (hot spots), each with the history of one duty
// cycle: rainflow count, mean correction, Miner damage per repeat for each band member of the
// model, life in repeats of the duty cycle, and the critical location (largest damage).
#ifndef FATIGUE_HOT_SPOT_ASSESSMENT_H
#define FATIGUE_HOT_SPOT_ASSESSMENT_H

#include <fatigue/fatigue_model.h>
#include <fatigue/miner_damage.h>
#include <fatigue/rainflow.h>

#include <array>
#include <string>
#include <vector>

namespace fatigue
{
  struct HotSpotHistory
  {
    std::string         name;
    std::vector<double> values; // one duty cycle, in the model's quantity and unit
  };

  struct CountingSettings
  {
    HistoryKind kind = HistoryKind::repeating; // a mechanism repeats its duty cycle
    double      gate = 0.0;                    // hysteresis filter, same unit as the history
  };

  // Shortest, nominal and longest life over the model's band members.
  struct LifeBand
  {
    double low;
    double nominal;
    double high;
  };

  LifeBand
  make_life_band(const std::array<double, n_band_members> &lives);

  struct HotSpotResult
  {
    std::string                        name;
    std::vector<CountedCycle>          cycles;
    LoadingSpectrum                    spectrum; // equivalent amplitudes of `cycles`
    std::array<double, n_band_members> damage_per_repeat;
    std::array<double, n_band_members> repeats_to_failure;

    LifeBand
    life() const;
  };

  struct FatigueAssessment
  {
    FatigueModel               model;
    CountingSettings           counting;
    std::vector<HotSpotResult> hot_spots;
    // Per band member: index of the hot spot with the largest damage (the first one on ties).
    std::array<std::size_t, n_band_members> critical_per_member;
    std::size_t                             critical; // = critical_per_member[nominal_life]

    // Life of the part (the critical hot spot of each member) as a band.
    LifeBand
    life() const;

    // True when all band members agree on the critical location.
    bool
    critical_location_is_robust() const;

    std::vector<LoadingSpectrum>
    spectra() const;
  };

  // Throws std::invalid_argument when there is no hot spot, a name is empty or repeated, or a
  // history is empty or not finite.
  FatigueAssessment
  assess_fatigue(const std::vector<HotSpotHistory> &hot_spots, const FatigueModel &model,
                 const CountingSettings &counting = {});
} // namespace fatigue

#endif
