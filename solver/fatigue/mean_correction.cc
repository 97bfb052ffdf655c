#include <fatigue/input_checks.h>
#include <fatigue/mean_correction.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace fatigue
{
  double
  goodman_equivalent_amplitude(const double amplitude, const double mean,
                               const double ultimate_strength)
  {
    internal::require_non_negative("amplitude", amplitude);
    internal::require_finite("mean", mean);
    internal::require_positive("ultimate_strength", ultimate_strength);
    if (mean <= 0.0)
      return amplitude;
    if (mean >= ultimate_strength)
      return std::numeric_limits<double>::infinity();
    return amplitude / (1.0 - mean / ultimate_strength);
  }

  double
  smith_watson_topper_equivalent_amplitude(const double amplitude, const double mean)
  {
    internal::require_non_negative("amplitude", amplitude);
    internal::require_finite("mean", mean);
    const double maximum = mean + amplitude;
    if (maximum <= 0.0)
      return 0.0;
    return std::sqrt(maximum * amplitude);
  }

  double
  elastomer_equivalent_strain_amplitude(const double maximum_strain, const double minimum_strain,
                                        const double walker_exponent)
  {
    internal::require_finite("maximum_strain", maximum_strain);
    internal::require_finite("minimum_strain", minimum_strain);
    internal::require_non_negative("walker_exponent", walker_exponent);
    if (minimum_strain > maximum_strain)
      throw std::invalid_argument("fatigue: parameter 'minimum_strain' must not exceed "
                                  "'maximum_strain', got " +
                                  internal::format_number(minimum_strain) + " > " +
                                  internal::format_number(maximum_strain));
    if (maximum_strain <= 0.0)
      return 0.0;
    const double tensile_minimum = std::max(minimum_strain, 0.0);
    const double amplitude       = 0.5 * (maximum_strain - tensile_minimum);
    if (amplitude == 0.0)
      return 0.0;
    return std::pow(0.5 * maximum_strain, 1.0 - walker_exponent) *
           std::pow(amplitude, walker_exponent);
  }

  void
  MeanCorrectionSettings::check() const
  {
    if (kind == MeanCorrection::goodman)
      internal::require_positive("ultimate_strength", ultimate_strength);
    if (kind == MeanCorrection::elastomer_walker)
      internal::require_non_negative("walker_exponent", walker_exponent);
  }

  double
  equivalent_amplitude(const double maximum, const double minimum,
                       const MeanCorrectionSettings &settings)
  {
    internal::require_finite("maximum", maximum);
    internal::require_finite("minimum", minimum);
    if (minimum > maximum)
      throw std::invalid_argument("fatigue: parameter 'minimum' must not exceed 'maximum', got " +
                                  internal::format_number(minimum) + " > " +
                                  internal::format_number(maximum));
    const double amplitude = 0.5 * (maximum - minimum);
    const double mean      = 0.5 * (maximum + minimum);
    switch (settings.kind)
      {
      case MeanCorrection::none:
        return amplitude;
      case MeanCorrection::goodman:
        return goodman_equivalent_amplitude(amplitude, mean, settings.ultimate_strength);
      case MeanCorrection::smith_watson_topper:
        return smith_watson_topper_equivalent_amplitude(amplitude, mean);
      case MeanCorrection::elastomer_walker:
        return elastomer_equivalent_strain_amplitude(maximum, minimum, settings.walker_exponent);
      }
    throw std::logic_error("fatigue: unknown mean correction");
  }

  double
  equivalent_amplitude(const CountedCycle &cycle, const MeanCorrectionSettings &settings)
  {
    return equivalent_amplitude(cycle.maximum(), cycle.minimum(), settings);
  }

  std::string
  to_string(const MeanCorrection kind)
  {
    switch (kind)
      {
      case MeanCorrection::none:
        return "none";
      case MeanCorrection::goodman:
        return "goodman";
      case MeanCorrection::smith_watson_topper:
        return "swt";
      case MeanCorrection::elastomer_walker:
        return "elastomer-walker";
      }
    throw std::logic_error("fatigue: unknown mean correction");
  }

  MeanCorrection
  parse_mean_correction(const std::string &name)
  {
    for (const MeanCorrection kind :
         {MeanCorrection::none, MeanCorrection::goodman, MeanCorrection::smith_watson_topper,
          MeanCorrection::elastomer_walker})
      if (name == to_string(kind))
        return kind;
    throw std::invalid_argument(
        "fatigue: parameter 'mean correction' must be one of none, goodman, "
        "swt, elastomer-walker, got '" +
        name + "'");
  }

  std::string
  describe(const MeanCorrectionSettings &settings)
  {
    std::ostringstream out;
    switch (settings.kind)
      {
      case MeanCorrection::none:
        out << "none (equivalent amplitude = range / 2)";
        break;
      case MeanCorrection::goodman:
        out << "Goodman: a_eq = a / (1 - m / " << settings.ultimate_strength
            << ") for m > 0, a for m <= 0";
        break;
      case MeanCorrection::smith_watson_topper:
        out << "Smith-Watson-Topper: a_eq = sqrt(max(x_max, 0) a)";
        break;
      case MeanCorrection::elastomer_walker:
        out << "elastomer max. principal strain, Walker form at R = 0: eps_eq = (eps_max/2)^"
            << 1.0 - settings.walker_exponent << " * eps_a'^" << settings.walker_exponent
            << ", eps_a' = (eps_max - max(eps_min, 0))/2, no damage if eps_max <= 0";
        break;
      }
    return out.str();
  }
} // namespace fatigue
