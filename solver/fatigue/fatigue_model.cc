#include <fatigue/fatigue_model.h>

#include <stdexcept>

namespace fatigue
{
  std::string
  to_string(const Quantity quantity)
  {
    return quantity == Quantity::strain ? "strain" : "stress";
  }

  Quantity
  parse_quantity(const std::string &name)
  {
    if (name == "strain")
      return Quantity::strain;
    if (name == "stress")
      return Quantity::stress;
    throw std::invalid_argument(
        "fatigue: parameter 'quantity' must be 'strain' or 'stress', got '" + name + "'");
  }

  std::string
  band_member_name(const std::size_t member)
  {
    switch (member)
      {
      case low_life:
        return "low";
      case nominal_life:
        return "nominal";
      case high_life:
        return "high";
      }
    throw std::invalid_argument("fatigue: parameter 'member' must be 0, 1 or 2, got " +
                                std::to_string(member));
  }

  void
  FatigueModel::check() const
  {
    correction.check();
    for (const LifeCurve &curve : curves)
      curve.check();
    const bool stress_correction = correction.kind == MeanCorrection::goodman ||
                                   correction.kind == MeanCorrection::smith_watson_topper;
    if (quantity == Quantity::strain && stress_correction)
      throw std::invalid_argument("fatigue: model '" + name + "': mean correction '" +
                                  to_string(correction.kind) +
                                  "' is stress based but the quantity is strain");
    if (quantity == Quantity::stress && correction.kind == MeanCorrection::elastomer_walker)
      throw std::invalid_argument("fatigue: model '" + name +
                                  "': mean correction 'elastomer-walker' is strain based but the "
                                  "quantity is stress");
  }
} // namespace fatigue
