// Life-curve ASSUMPTION for 3D-printed TPU (Semiflex class, Shore 98A). No Basquin or strain-life
// constants for printed TPU or Semiflex exist in the literature (../shared/reference/materials.md),
// so the curves below are named, documented assumptions with a factor-of-two band, not data.
//
// Anchor (the only published TPU fatigue number found): bulk TPU plate, tension-tension load
// control, R = 0.1, 5 Hz, fatigue limit 10.25 MPa (S. Wang, S. Tang, C. He, Q. Wang, Polymers
// 15(4):899, 2023). Read here as the maximum stress of the cycle (the usual meaning of a stress
// level in tension-tension tests) and placed at N_ref = 1e6 cycles (the paper's run-out count is
// not used; 1e6 is the conservative end of usual polymer fatigue-limit definitions).
//
// Strain model (default; flexures are displacement driven, so strain is the controlled quantity):
//   anchor strain eps_max = 10.25 MPa / 89.5 MPa (printed TPU low-strain modulus, Bates, Farrow,
//   Trask, Mater. Des. 2016) = 0.1145, eps_min = 0.1 eps_max; equivalent amplitude through the
//   elastomer Walker correction (mean_correction.h) -> a_anchor = 0.0543 for gamma = 0.5.
//   low:     a_ref = 0.5 a_anchor, k = 4  (printed knock-down: across-layer strength 12-24 MPa vs
//                                          22-36 MPa in plane, about 0.55, rounded down; F = 2)
//   nominal: a_ref = 1.0 a_anchor, k = 6  (F = 3)
//   high:    a_ref = 2.0 a_anchor, k = 8  (strain-controlled bending without the cyclic creep of a
//                                          stress-controlled test; printed TPU living hinges
//                                          survived > 2e6 folds, Balderrama-Armendariz et al., Int.
//                                          J. Adv. Manuf. Technol. 2019; F = 4)
//   with k = 2F and F the crack-growth exponent, about 2 (natural rubber) to 4 (SBR) per Mars and
//   Fatemi 2002. No endurance limit.
// Stress model (alternative; a stress-based curve is questionable at these strains):
//   a_anchor = the chosen stress correction applied to (10.25, 1.025) MPa (SWT: 6.88 MPa);
//   low 0.5 a_anchor, k = 8; nominal 0.75 a_anchor, k = 12; high 1.0 a_anchor, k = 16 (k typical
//   of the flat S-N curves of unfilled thermoplastics; assumption). No endurance limit.
//
// The seed flap's 717,727 cycles is a run-out (no failure), a lower bound on life at the strain the
// flexure saw: use run_out.h to check each curve against it and to lift curves that contradict it.
#ifndef FATIGUE_PRINTED_TPU_H
#define FATIGUE_PRINTED_TPU_H

#include <fatigue/fatigue_model.h>

namespace fatigue
{
  namespace printed_tpu
  {
    // Wang et al. 2023 anchor test.
    constexpr double anchor_maximum_stress = 10.25; // MPa
    constexpr double anchor_stress_ratio   = 0.1;
    constexpr double anchor_cycles         = 1.0e6; // assumed, see above
    // Bates et al. 2016, printed TPU, ASTM D412.
    constexpr double low_strain_modulus = 89.5; // MPa
    // Lower end of the in-plane tensile strength of printed TPU 95A-98A (materials.md).
    constexpr double default_ultimate_strength = 22.0; // MPa

    // Equivalent strain amplitude of the anchor under a strain correction (elastomer-walker or
    // none).
    double
    anchor_equivalent_strain_amplitude(const MeanCorrectionSettings &correction);

    // Equivalent stress amplitude of the anchor under a stress correction.
    double
    anchor_equivalent_stress_amplitude(const MeanCorrectionSettings &correction);

    // "printed-tpu-strain-v1": maximum principal strain, elastomer Walker correction with this
    // gamma.
    FatigueModel
    strain_model(double walker_exponent = 0.5);

    // The same with another strain correction (elastomer-walker or none); the anchor is converted
    // through it, so the curves are always expressed in the correction's equivalent amplitude.
    FatigueModel
    strain_model(const MeanCorrectionSettings &correction);

    // "printed-tpu-stress-v1": maximum principal stress in MPa; correction goodman, swt or none.
    FatigueModel
    stress_model(const MeanCorrectionSettings &correction);
  } // namespace printed_tpu
} // namespace fatigue

#endif
