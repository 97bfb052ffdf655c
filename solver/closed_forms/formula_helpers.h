// Helpers of the closed-form table (internal): argument declarations, validity limits and the
// warnings they raise. Shared by the table's translation units.
#ifndef CLOSED_FORMS_FORMULA_HELPERS_H
#define CLOSED_FORMS_FORMULA_HELPERS_H

#include "beams.h"
#include "elastica.h"
#include "input_checks.h"
#include "prbm.h"
#include "registry.h"
#include "torsion.h"

#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace closed_forms
{
  namespace internal
  {
    // Validity limits (project choices, each explained where it is used).
    constexpr double min_beam_slenderness = 10.0;       // L/h for shear-free beam theory
    constexpr double min_timoshenko_slenderness = 2.0;  // L/h: clamp end zone ~ h dominates below
    constexpr double max_linear_deflection = 0.1;       // v/L: elastica differs by > ~1 % above
    constexpr double max_pivot_length_ratio = 0.1;      // l/L of the small-length flexural pivot
    constexpr double min_saint_venant_length = 10.0;    // L/a: warping restraint < 5 % beyond
    constexpr double max_bending_strain = 0.01;         // linear moment-curvature law

    using Args = std::map<std::string, double>;
    constexpr double none = std::numeric_limits<double>::quiet_NaN();

    inline Argument
    positive(const std::string &name, const std::string &description)
    {
      return {name, description, true, none, true};
    }

    inline Argument
    signed_value(const std::string &name, const std::string &description)
    {
      return {name, description, true, none, false};
    }

    inline Argument
    optional_positive(const std::string &name, const std::string &description,
                      const double default_value)
    {
      return {name, description, false, default_value, true};
    }

    inline Argument load() { return signed_value("P", "transverse tip load (force; sign gives the direction)"); }
    inline Argument length_L() { return positive("L", "beam length"); }
    inline Argument modulus_E() { return positive("E", "Young's modulus"); }
    inline Argument poisson_nu() { return signed_value("nu", "Poisson's ratio, -1 < nu < 0.5"); }
    inline Argument width_b() { return positive("b", "section width, out of the bending plane"); }
    inline Argument depth_h() { return positive("h", "section depth in the bending direction"); }
    inline Argument kappa_arg() { return optional_positive("kappa", "shear correction factor",
                                                 rectangle_shear_coefficient); }
    inline Argument flexure_l() { return positive("l", "flexure length"); }
    inline Argument gamma_arg() { return optional_positive("gamma", "PRBM characteristic radius factor",
                                                 prbm_characteristic_radius_factor); }
    inline Argument K_theta_arg() { return optional_positive("K_theta", "PRBM stiffness coefficient",
                                                   prbm_stiffness_coefficient); }
    inline Argument angle_Theta() { return signed_value("Theta", "pseudo-rigid-body angle (rad)"); }
    inline Argument side_a() { return positive("a", "one side of the rectangle (sorted internally)"); }
    inline Argument side_b() { return positive("b", "other side of the rectangle (sorted internally)"); }
    inline Argument bar_L() { return positive("L", "bar length"); }

    inline std::string
    number(const double value)
    {
      std::ostringstream out;
      out.precision(4);
      out << value;
      return out.str();
    }

    inline void
    warn_if(Result &result, const bool condition, const std::string &message)
    {
      if (condition)
        result.warnings.push_back(message);
    }

    inline void
    check_beam_slenderness(Result &result, const double L, const double h)
    {
      warn_if(result, L / h < min_beam_slenderness,
              "L/h = " + number(L / h) +
                " < 10: shear deformation is not negligible (use the Timoshenko formula)");
    }

    inline void
    check_timoshenko_slenderness(Result &result, const double L, const double h)
    {
      warn_if(result, L / h < min_timoshenko_slenderness,
              "L/h = " + number(L / h) +
                " < 2: the clamped end zone (about one depth long) is not a beam; 2D/3D effects dominate");
    }

    inline void
    check_linear_deflection(Result &result, const double deflection, const double L)
    {
      warn_if(result, std::abs(deflection) / L > max_linear_deflection,
              "|v|/L = " + number(std::abs(deflection) / L) +
                " > 0.1: geometric nonlinearity matters (error > ~1 %); use elastica_tip_force_*");
    }

    // A bound on a linear cantilever formula's error against plane-stress elasticity of an
    // end-loaded cantilever (model ladder, rung (a)). Three parts: the geometric nonlinearity
    // (the elastica's tip deflection at alpha = P L^2 / E I against the linear alpha / 3); the
    // shear term, shear_coefficient (h/L)^2, the formula's departure from Timoshenko and
    // Goodier's elasticity solution; and (h/L)^2 for a root restrained otherwise than theirs
    // (fully clamped: measured 0.6-0.9 (h/L)^2 at L/h = 10-40, cases/verification/cantilever_2d.prm).
    inline void
    bound_cantilever_deflection(Result &result, const double P, const double L, const double E,
                                const double b, const double h, const double shear_coefficient,
                                const std::string &shear_text)
    {
      const double alpha = P * L * L / (E * second_moment_of_area(b, h));
      const double geometric =
        alpha == 0 ? 0 : std::abs((alpha / 3) / tip_load_elastica(alpha).deflection - 1);
      const double slenderness = (h / L) * (h / L);
      result.error_bound = geometric + shear_coefficient * slenderness + slenderness;
      result.error_bound_basis = "geometric nonlinearity (elastica) " + number(geometric) + ", " +
                                 shear_text + " " + number(shear_coefficient * slenderness) +
                                 ", root restraint (h/L)^2 = " + number(slenderness) +
                                 "; assumes the case's load and clamp are the formula's";
      result.bound_models = {"plane stress"};
    }

    inline void
    check_prbm_angle(Result &result, const double Theta)
    {
      warn_if(result, std::abs(Theta) > prbm_max_angle,
              "|Theta| = " + number(std::abs(Theta) * 180.0 / M_PI) +
                " deg > 64 deg: outside the range of Howell's PRBM fit");
    }

    inline void
    check_bending_strain(Result &result, const double curvature_times_L, const double L,
                         const double h)
    {
      const double strain = std::abs(curvature_times_L) * h / (2.0 * L);
      warn_if(result, strain > max_bending_strain,
              "peak bending strain " + number(strain) +
                " > 1 %: the linear moment-curvature law of the elastica is doubtful");
    }

    inline unsigned int
    mode_number(const double n)
    {
      if (!(n >= 1.0 && n <= 1e6 && n == std::floor(n)))
        throw std::invalid_argument(
          "closed_forms: argument 'n' (mode number) must be an integer >= 1, got " +
          format_number(n));
      return static_cast<unsigned int>(n);
    }

    inline double
    flexural_rigidity(const Args &p)
    {
      return p.at("E") * second_moment_of_area(p.at("b"), p.at("h"));
    }

    // Columns, beam-columns, bistable beams (formula_table_stability.cc).
    void add_stability_formulas(std::vector<Formula> &table);
  } // namespace internal
} // namespace closed_forms

#endif
