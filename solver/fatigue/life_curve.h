// A power-law life curve in equivalent amplitude a (strain or stress, after the mean correction):
//   N(a) = N_ref (a / a_ref)^(-k),   equivalently a = a_ref (N / N_ref)^(-1/k)
// This is Basquin's law (O. H. Basquin, Proc. ASTM 10:625-630, 1910) written around a reference
// point instead of the fatigue-strength coefficient at one reversal, so that the parameter that
// carries the anchor (a_ref at N_ref) and the one that carries the slope (k) are separate. For a
// strain-life curve of an elastomer k = 1/c relates to the crack-growth power-law exponent F by
// k = 2F (Gent, Lindley and Thomas integration with strain energy density ~ strain^2; Mars and
// Fatemi, Int. J. Fatigue 24, 2002, section 3).
// Below an optional endurance amplitude the life is infinite; 0 means no endurance limit, the
// conservative choice (elementary Miner rule).
#ifndef FATIGUE_LIFE_CURVE_H
#define FATIGUE_LIFE_CURVE_H

#include <string>

namespace fatigue
{
  struct LifeCurve
  {
    std::string name;
    double      reference_amplitude = 0.0; // a_ref, equivalent amplitude at reference_cycles
    double      reference_cycles    = 0.0; // N_ref
    double      exponent            = 0.0; // k
    double      endurance_amplitude = 0.0; // no damage at or below this amplitude
    std::string source;                    // where a_ref, N_ref and k come from

    // Throws std::invalid_argument naming the first invalid parameter.
    void
    check() const;

    // 1 / N(a): the Miner damage of one cycle; 0 at or below the endurance amplitude and for a = 0.
    // Computed directly so that tiny amplitudes give 0 damage rather than 1 / infinity.
    double
    damage_per_cycle(double equivalent_amplitude) const;

    // N(a); +infinity where damage_per_cycle is 0.
    double
    cycles_to_failure(double equivalent_amplitude) const;

    // Inverse: the amplitude with life N (ignores the endurance amplitude).
    double
    amplitude_at(double cycles) const;

    // The same curve with reference and endurance amplitudes multiplied by factor > 0.
    LifeCurve
    scaled(double factor, const std::string &new_name) const;
  };
} // namespace fatigue

#endif
