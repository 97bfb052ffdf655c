#include <fatigue/hot_spot_assessment.h>
#include <fatigue/input_checks.h>

#include <algorithm>
#include <set>

namespace fatigue
{
  LifeBand
  make_life_band(const std::array<double, n_band_members> &lives)
  {
    return {*std::min_element(lives.begin(), lives.end()), lives[nominal_life],
            *std::max_element(lives.begin(), lives.end())};
  }

  LifeBand
  HotSpotResult::life() const
  {
    return make_life_band(repeats_to_failure);
  }

  LifeBand
  FatigueAssessment::life() const
  {
    std::array<double, n_band_members> lives{};
    for (std::size_t m = 0; m < n_band_members; ++m)
      lives[m] = hot_spots[critical_per_member[m]].repeats_to_failure[m];
    return make_life_band(lives);
  }

  bool
  FatigueAssessment::critical_location_is_robust() const
  {
    return std::all_of(critical_per_member.begin(), critical_per_member.end(),
                       [this](const std::size_t i) {
                         return i == critical;
                       });
  }

  std::vector<LoadingSpectrum>
  FatigueAssessment::spectra() const
  {
    std::vector<LoadingSpectrum> result;
    for (const HotSpotResult &h : hot_spots)
      result.push_back(h.spectrum);
    return result;
  }

  FatigueAssessment
  assess_fatigue(const std::vector<HotSpotHistory> &hot_spots, const FatigueModel &model,
                 const CountingSettings &counting)
  {
    model.check();
    internal::require_non_negative("gate", counting.gate);
    if (hot_spots.empty())
      throw std::invalid_argument("fatigue: parameter 'hot_spots' must hold at least one named "
                                  "history, got none");
    std::set<std::string> names;
    for (const HotSpotHistory &h : hot_spots)
      {
        if (h.name.empty())
          throw std::invalid_argument("fatigue: parameter 'hot_spots' must have non-empty names");
        if (!names.insert(h.name).second)
          throw std::invalid_argument("fatigue: parameter 'hot_spots' must have unique names, '" +
                                      h.name + "' appears twice");
      }

    FatigueAssessment assessment;
    assessment.model    = model;
    assessment.counting = counting;
    for (const HotSpotHistory &h : hot_spots)
      {
        HotSpotResult result;
        result.name = h.name;
        try
          {
            result.cycles = count_cycles(h.values, counting.kind, counting.gate);
          }
        catch (const std::invalid_argument &e)
          {
            throw std::invalid_argument("hot spot '" + h.name + "': " + e.what());
          }
        result.spectrum = equivalent_spectrum(result.cycles, model.correction);
        for (std::size_t m = 0; m < n_band_members; ++m)
          {
            result.damage_per_repeat[m]  = miner_damage(result.spectrum, model.curves[m]);
            result.repeats_to_failure[m] = repeats_to_failure(result.damage_per_repeat[m]);
          }
        assessment.hot_spots.push_back(std::move(result));
      }

    for (std::size_t m = 0; m < n_band_members; ++m)
      {
        std::size_t worst = 0;
        for (std::size_t i = 1; i < assessment.hot_spots.size(); ++i)
          if (assessment.hot_spots[i].damage_per_repeat[m] >
              assessment.hot_spots[worst].damage_per_repeat[m])
            worst = i;
        assessment.critical_per_member[m] = worst;
      }
    assessment.critical = assessment.critical_per_member[nominal_life];
    return assessment;
  }
} // namespace fatigue
