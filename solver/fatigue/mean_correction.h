// Mean-stress and mean-strain corrections: each maps one counted cycle (its maximum and minimum) to
// an equivalent amplitude, the single number a life curve is entered with. The curve must be
// expressed in the same equivalent amplitude (see printed_tpu.h, which converts its anchor test
// through the same correction).
#ifndef FATIGUE_MEAN_CORRECTION_H
#define FATIGUE_MEAN_CORRECTION_H

#include <fatigue/rainflow.h>

#include <string>

namespace fatigue
{
  // Goodman: sigma_ar = sigma_a / (1 - sigma_m / sigma_u), the fully reversed (R = -1) amplitude of
  // equal life. Goodman (1899); in this form N. E. Dowling, Mechanical Behavior of Materials, 4th
  // ed., Pearson 2013, chapter 9 (mean stress equations). A compressive mean gets no credit
  // (sigma_ar = sigma_a), the usual conservative choice; a mean at or above sigma_u returns
  // +infinity (failure in the first cycle).
  double
  goodman_equivalent_amplitude(double amplitude, double mean, double ultimate_strength);

  // Smith-Watson-Topper: sigma_ar = sqrt(sigma_max sigma_a), sigma_max = sigma_m + sigma_a; a cycle
  // that never goes into tension (sigma_max <= 0) does no damage. K. N. Smith, P. Watson, T. H.
  // Topper, J. Materials 5(4):767-778, 1970; Dowling, chapter 9.
  double
  smith_watson_topper_equivalent_amplitude(double amplitude, double mean);

  // Strain-based parameter for elastomers: maximum principal strain with an R-ratio correction.
  // Mars and Fatemi (Int. J. Fatigue 24:949-961, 2002, section 2.1; Rubber Chem. Technol.
  // 77:391-412, 2004) survey the maximum principal strain as the crack-nucleation parameter of
  // rubber and report that (i) the compressive part of a cycle contributes little, cracks opening
  // only under tension, and (ii) a larger minimum strain shortens the life of non-strain-
  // crystallising elastomers but lengthens that of natural rubber. Both enter here in Walker form
  // referenced to fully relaxing loading (R = 0, the usual elastomer test):
  //   eps_max' = eps_max,  eps_min' = max(eps_min, 0)                     (compression ignored)
  //   eps_a'   = (eps_max' - eps_min') / 2,  R' = eps_min' / eps_max'
  //   eps_eq   = (eps_max' / 2)^(1 - gamma) * eps_a'^gamma = eps_a' (1 - R')^(gamma - 1)
  // so eps_eq = eps_a at R = 0 for every gamma. gamma = 1: amplitude only (no mean effect);
  // gamma < 1: mean strain harmful (gamma = 0.5 is the SWT-like choice); gamma > 1: mean strain
  // beneficial (strain-crystallising rubber). A cycle with eps_max <= 0 does no damage. The Walker
  // form is K. Walker, ASTM STP 462, 1970, applied here to strain; it is our parametrisation, not a
  // formula printed by Mars and Fatemi.
  double
  elastomer_equivalent_strain_amplitude(double maximum_strain, double minimum_strain,
                                        double walker_exponent);

  enum class MeanCorrection
  {
    none,                // equivalent amplitude = amplitude
    goodman,             // stress
    smith_watson_topper, // stress
    elastomer_walker     // maximum principal strain
  };

  struct MeanCorrectionSettings
  {
    MeanCorrection kind              = MeanCorrection::none;
    double         ultimate_strength = 0.0; // Goodman only, same unit as the history
    double         walker_exponent   = 0.5; // elastomer_walker only

    // Throws std::invalid_argument when a parameter the chosen correction needs is invalid.
    void
    check() const;
  };

  // Equivalent amplitude of one counted cycle under the chosen correction.
  double
  equivalent_amplitude(double maximum, double minimum, const MeanCorrectionSettings &settings);

  double
  equivalent_amplitude(const CountedCycle &cycle, const MeanCorrectionSettings &settings);

  // "none", "goodman", "swt", "elastomer-walker"; parse throws std::invalid_argument listing them.
  std::string
  to_string(MeanCorrection kind);
  MeanCorrection
  parse_mean_correction(const std::string &name);

  // One-line description with the formula, for reports.
  std::string
  describe(const MeanCorrectionSettings &settings);
} // namespace fatigue

#endif
