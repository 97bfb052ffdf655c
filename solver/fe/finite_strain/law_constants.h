// The constants of a hyperelastic law given in the case file ('Finite strain/Law constants'), and
// the Drucker stability check they must pass. Plain C++ (no deal.II): the parsing and the check are
// unit-tested alone, and postproc/fit_material.py applies the same check to what it fits.
#pragma once

#include <string>
#include <vector>

namespace compliant
{
  struct LawConstants
  {
    bool                given = false; // false: from the material's E and nu
    std::vector<double> mu, alpha;     // Ogden: mu_p, alpha_p (1 to 3 pairs)
    std::vector<double> c;             // Yeoh: C10, C20, C30; neo-Hookean: C10; Mooney-Rivlin: C10, C01
    double              bulk_modulus = 0; // kappa; 0: from the material's nu and the shear modulus

    // Small-strain shear modulus: sum mu_p (Ogden), 2 C10 (Yeoh, neo-Hookean), 2 (C10 + C01).
    double shear_modulus(const std::string &law) const;
  };

  // The --help text of 'Finite strain/Law constants'.
  std::string law_constants_documentation();

  // Parses 'key=value, key=value' for the law (a name of hyperelastic_laws()): Ogden mu1, alpha1
  // [, mu2, alpha2 [, mu3, alpha3]]; Yeoh C10, C20, C30; neo-Hookean C10; Mooney-Rivlin C10, C01;
  // each may add kappa. Empty text: given = false (refused for Ogden and Yeoh, which have no
  // constants in E and nu alone). Bad input (unknown or missing keys, wrong count, a non-number,
  // non-positive moduli, a law that is not Drucker-stable) throws std::invalid_argument naming
  // 'Finite strain/Law constants' and what was expected.
  LawConstants parse_law_constants(const std::string &law, const std::string &text);

  // Drucker stability of the incompressible law (d tau : d eps > 0 for every isochoric log-strain
  // increment, tau the Kirchhoff stress) along uniaxial, equibiaxial and planar stretch lambda in
  // [0.1, 10] (the range Abaqus checks). Returns "" when stable, else where it fails.
  std::string drucker_violation(const std::string &law, const LawConstants &constants);
} // namespace compliant
