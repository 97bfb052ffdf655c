#include "formula_table.h"

#include "formula_helpers.h"

#include "beams.h"
#include "cylinders.h"
#include "elastica.h"
#include "input_checks.h"
#include "prbm.h"
#include "torsion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace closed_forms
{
  namespace internal
  {
    namespace
    {
      // ---------------------------------------------------------------- beams
      void
      add_beam_formulas(std::vector<Formula> &table)
      {
        table.push_back(
          {"euler_bernoulli_cantilever_deflection",
           "tip deflection of a cantilever under a transverse tip load, P L^3/(3 E I) (length)",
           "Gere and Timoshenko, Mechanics of Materials; closed-forms.md",
           {load(), length_L(), modulus_E(), width_b(), depth_h()},
           [](const Args &p) {
             Result r{euler_bernoulli_cantilever_deflection(p.at("P"), p.at("L"), p.at("E"), p.at("b"),
                                                            p.at("h")),
                      {}};
             check_beam_slenderness(r, p.at("L"), p.at("h"));
             check_linear_deflection(r, r.value, p.at("L"));
             // nu is not an argument: the shear term at its largest, nu = 0.5
             bound_cantilever_deflection(r, p.at("P"), p.at("L"), p.at("E"), p.at("b"), p.at("h"),
                                         (4 + 5 * 0.5) / 8, "shear deformation omitted (4 + 5 nu)/8 (h/L)^2 at nu = 0.5");
             return r;
           }});

        table.push_back(
          {"timoshenko_cantilever_deflection",
           "tip deflection of a cantilever under a transverse tip load with shear, "
           "P L^3/(3 E I) + P L/(kappa G A) (length)",
           "Timoshenko and Gere, Mechanics of Materials; closed-forms.md",
           {load(), length_L(), modulus_E(), poisson_nu(), width_b(), depth_h(), kappa_arg()},
           [](const Args &p) {
             Result r{timoshenko_cantilever_deflection(p.at("P"), p.at("L"), p.at("E"), p.at("nu"),
                                                       p.at("b"), p.at("h"), p.at("kappa")),
                      {}};
             check_timoshenko_slenderness(r, p.at("L"), p.at("h"));
             check_linear_deflection(r, r.value, p.at("L"));
             {
               const double nu = p.at("nu");
               bound_cantilever_deflection(r, p.at("P"), p.at("L"), p.at("E"), p.at("b"), p.at("h"),
                                           std::abs((1 + nu) / (2 * p.at("kappa")) - (4 + 5 * nu) / 8),
                                           "shear term against Timoshenko-Goodier's");
             }
             return r;
           }});

        table.push_back(
          {"timoshenko_goodier_cantilever_deflection",
           "plane-stress elasticity: end deflection of a cantilever with parabolic end shear and the "
           "matching end restraint, P L^3/(3EI) + (4+5nu) P h^2 L/(24EI) (length)",
           "Timoshenko and Goodier, Theory of Elasticity, sec. 21; Augarde and Deeks 2008",
           {load(), length_L(), modulus_E(), poisson_nu(), width_b(), depth_h()},
           [](const Args &p) {
             Result r{timoshenko_goodier_cantilever_deflection(p.at("P"), p.at("L"), p.at("E"),
                                                               p.at("nu"), p.at("b"), p.at("h")),
                      {}};
             check_linear_deflection(r, r.value, p.at("L"));
             bound_cantilever_deflection(r, p.at("P"), p.at("L"), p.at("E"), p.at("b"), p.at("h"), 0,
                                         "shear (exact)");
             return r;
           }});

        table.push_back(
          {"euler_bernoulli_guided_stiffness",
           "transverse stiffness of a fixed-guided beam, 12 E I / L^3 (force/length)",
           "Gere and Timoshenko, Mechanics of Materials; Howell 2001 sec. 5.6",
           {length_L(), modulus_E(), width_b(), depth_h()},
           [](const Args &p) {
             Result r{euler_bernoulli_guided_stiffness(p.at("L"), p.at("E"), p.at("b"), p.at("h")), {}};
             check_beam_slenderness(r, p.at("L"), p.at("h"));
             return r;
           }});

        table.push_back(
          {"timoshenko_guided_stiffness",
           "transverse stiffness of a fixed-guided Timoshenko beam, 12 E I/(L^3 (1 + Phi)), "
           "Phi = 12 E I/(kappa G A L^2) (force/length)",
           "Timoshenko and Gere, Mechanics of Materials; closed-forms.md",
           {length_L(), modulus_E(), poisson_nu(), width_b(), depth_h(), kappa_arg()},
           [](const Args &p) {
             Result r{timoshenko_guided_stiffness(p.at("L"), p.at("E"), p.at("nu"), p.at("b"), p.at("h"),
                                                  p.at("kappa")),
                      {}};
             check_timoshenko_slenderness(r, p.at("L"), p.at("h"));
             return r;
           }});

        table.push_back(
          {"euler_bernoulli_cantilever_frequency",
           "n-th natural frequency of a cantilever, (beta_n L)^2 sqrt(E I/(rho A L^4)) / (2 pi) "
           "(cycles per time unit: Hz in SI or N-mm-t units)",
           "Blevins, Formulas for Natural Frequency and Mode Shape, table 8-1; beta_n L from "
           "1 + cos x cosh x = 0",
           {{"n", "mode number 1, 2, 3, ...", true, none, true}, length_L(), modulus_E(),
            positive("rho", "density"), width_b(), depth_h()},
           [](const Args &p) {
             const unsigned int n = mode_number(p.at("n"));
             Result r{euler_bernoulli_cantilever_frequency(n, p.at("L"), p.at("E"), p.at("rho"),
                                                           p.at("b"), p.at("h")),
                      {}};
             // Higher modes have shorter wavelengths: scale the slenderness by beta_1 / beta_n.
             const double equivalent_slenderness =
               p.at("L") / p.at("h") * cantilever_frequency_root(1) / cantilever_frequency_root(n);
             warn_if(r, equivalent_slenderness < min_beam_slenderness,
                     "(L/h)(beta_1/beta_n) = " + number(equivalent_slenderness) +
                       " < 10: shear and rotary inertia lower this mode noticeably");
             return r;
           }});
      }

      // ---------------------------------------------------------------- PRBM
      void
      add_prbm_formulas(std::vector<Formula> &table)
      {
        table.push_back(
          {"prbm_pivot_stiffness",
           "torsional spring of a small-length flexural pivot, K = E I / l (moment/rad)",
           "Howell, Compliant Mechanisms, Wiley 2001, sec. 5.2",
           {modulus_E(), width_b(), depth_h(), flexure_l(),
            {"link_length", "length of the rigid link the flexure carries (enables the l/L check)",
             false, none, true}},
           [](const Args &p) {
             const double l = p.at("l");
             Result r{prbm_pivot_stiffness(p.at("E"), p.at("b"), p.at("h"), l), {}};
             const double link_length = p.at("link_length");
             if (!std::isnan(link_length))
               warn_if(r, l / link_length > max_pivot_length_ratio,
                       "l/link_length = " + number(l / link_length) +
                         " > 0.1: not a small-length flexural pivot (tip error > ~0.4 % at 26 deg, "
                         "5 % for l = link_length)");
             warn_if(r, l / p.at("h") < min_beam_slenderness,
                     "l/h = " + number(l / p.at("h")) +
                       " < 10: short thick flexure; shear, stretch and Poisson effects are outside "
                       "the model (J. Mech. Des. 138(9):092302, 2016)");
             return r;
           }});

        table.push_back(
          {"prbm_cantilever_force_stiffness",
           "torsional spring of the PRBM cantilever with end force, K = gamma K_theta E I / l "
           "(moment/rad)",
           "Howell, Compliant Mechanisms, Wiley 2001, sec. 5.3",
           {modulus_E(), width_b(), depth_h(), flexure_l(), gamma_arg(), K_theta_arg()},
           [](const Args &p) {
             Result r{prbm_cantilever_force_stiffness(p.at("E"), p.at("b"), p.at("h"), p.at("l"),
                                                      p.at("gamma"), p.at("K_theta")),
                      {}};
             check_beam_slenderness(r, p.at("l"), p.at("h"));
             return r;
           }});

        table.push_back({"prbm_cantilever_tip_x",
                         "PRBM cantilever tip coordinate along the undeflected beam, "
                         "l (1 - gamma (1 - cos Theta)) (length)",
                         "Howell, Compliant Mechanisms, Wiley 2001, sec. 5.3",
                         {flexure_l(), angle_Theta(), gamma_arg()},
                         [](const Args &p) {
                           Result r{prbm_cantilever_tip_position(p.at("l"), p.at("Theta"),
                                                                 p.at("gamma"))
                                      .x,
                                    {}};
                           check_prbm_angle(r, p.at("Theta"));
                           return r;
                         }});

        table.push_back({"prbm_cantilever_tip_y",
                         "PRBM cantilever transverse tip coordinate, gamma l sin Theta (length)",
                         "Howell, Compliant Mechanisms, Wiley 2001, sec. 5.3",
                         {flexure_l(), angle_Theta(), gamma_arg()},
                         [](const Args &p) {
                           Result r{prbm_cantilever_tip_position(p.at("l"), p.at("Theta"),
                                                                 p.at("gamma"))
                                      .y,
                                    {}};
                           check_prbm_angle(r, p.at("Theta"));
                           return r;
                         }});

        table.push_back(
          {"prbm_cantilever_tip_force",
           "dead transverse tip force holding the PRBM cantilever at Theta, "
           "K Theta / (gamma l cos Theta) (force)",
           "Howell, Compliant Mechanisms, Wiley 2001, sec. 5.3",
           {modulus_E(), width_b(), depth_h(), flexure_l(), angle_Theta(), gamma_arg(), K_theta_arg()},
           [](const Args &p) {
             Result r{prbm_cantilever_tip_force(p.at("E"), p.at("b"), p.at("h"), p.at("l"),
                                                p.at("Theta"), p.at("gamma"), p.at("K_theta")),
                      {}};
             check_prbm_angle(r, p.at("Theta"));
             check_beam_slenderness(r, p.at("l"), p.at("h"));
             return r;
           }});
      }

      // ---------------------------------------------------------------- torsion
      void
      add_torsion_formulas(std::vector<Formula> &table)
      {
        const std::string saint_venant_source =
          "Timoshenko and Goodier, Theory of Elasticity, 3rd ed., sec. 109";
        table.push_back({"saint_venant_beta",
                         "torsion-constant factor beta of a rectangle, J = beta a b^3, a >= b "
                         "(dimensionless)",
                         saint_venant_source,
                         {side_a(), side_b()},
                         [](const Args &p) {
                           return Result{saint_venant_beta(p.at("a"), p.at("b")), {}};
                         }});
        table.push_back({"saint_venant_alpha",
                         "shear-stress factor alpha of a rectangle, tau_max = T/(alpha a b^2), a >= b "
                         "(dimensionless)",
                         saint_venant_source,
                         {side_a(), side_b()},
                         [](const Args &p) {
                           return Result{saint_venant_alpha(p.at("a"), p.at("b")), {}};
                         }});
        table.push_back({"torsion_constant",
                         "Saint-Venant torsion constant J = beta a b^3 (length^4)",
                         saint_venant_source,
                         {side_a(), side_b()},
                         [](const Args &p) {
                           return Result{torsion_constant(p.at("a"), p.at("b")), {}};
                         }});
        table.push_back({"saint_venant_max_shear_stress",
                         "maximum torsional shear stress, at the middle of the long side, "
                         "T/(alpha a b^2) (stress)",
                         saint_venant_source,
                         {signed_value("T", "torque"), side_a(), side_b()},
                         [](const Args &p) {
                           return Result{
                             saint_venant_max_shear_stress(p.at("T"), p.at("a"), p.at("b")), {}};
                         }});
        table.push_back(
          {"saint_venant_torsion_stiffness",
           "torsional stiffness with free warping, G J / L (moment/rad)",
           saint_venant_source,
           {side_a(), side_b(), bar_L(), modulus_E(), poisson_nu()},
           [](const Args &p) {
             Result r{saint_venant_torsion_stiffness(p.at("a"), p.at("b"), p.at("L"), p.at("E"),
                                                     p.at("nu")),
                      {}};
             const double long_side = std::max(p.at("a"), p.at("b"));
             warn_if(r, p.at("L") < min_saint_venant_length * long_side,
                     "Saint-Venant assumes free warping; bar shorter than ten widths (L/a = " +
                       number(p.at("L") / long_side) +
                       "): clamped ends make it stiffer, see vlasov_torsion_stiffness");
             return r;
           }});
        table.push_back({"warping_constant",
                         "warping constant Gamma = integral of omega^2 dA of the Saint-Venant warping "
                         "function (length^6)",
                         "series derived in solver/closed_forms/torsion.cc from Timoshenko and "
                         "Goodier sec. 109; checked by finite differences",
                         {side_a(), side_b()},
                         [](const Args &p) {
                           return Result{warping_constant(p.at("a"), p.at("b")), {}};
                         }});
        table.push_back(
          {"vlasov_torsion_stiffness",
           "torsional stiffness of a bar clamped at both ends with warping restrained, "
           "G J/[L - (2/lambda) tanh(lambda L/2)], lambda = sqrt(G J/(E Gamma)) (moment/rad)",
           "Vlasov, Thin-Walled Elastic Beams (1961); closed-forms.md",
           {side_a(), side_b(), bar_L(), modulus_E(), poisson_nu()},
           [](const Args &p) {
             Result r{vlasov_torsion_stiffness(p.at("a"), p.at("b"), p.at("L"), p.at("E"), p.at("nu")),
                      {}};
             const double long_side = std::max(p.at("a"), p.at("b"));
             warn_if(r, p.at("L") < long_side,
                     "L/a = " + number(p.at("L") / long_side) +
                       " < 1: bar shorter than its width; the one-dimensional Vlasov model "
                       "(no secondary warping shear) is only indicative, a 3D model decides");
             return r;
           }});
      }

      // ---------------------------------------------------------------- thick cylinder (Lame)
      void
      add_cylinder_formulas(std::vector<Formula> &table)
      {
        const std::string source = "Timoshenko and Goodier, Theory of Elasticity, sec. 28 (Lame)";
        const std::vector<Argument> radii{positive("r_i", "inner radius"), positive("r_o", "outer radius"),
                                          Argument{"p_i", "inner pressure (default 0)", false, 0.0, false},
                                          Argument{"p_o", "outer pressure (default 0)", false, 0.0, false},
                                          positive("r", "radius where the value is wanted")};
        std::vector<Argument> displacement_args = radii;
        displacement_args.push_back(modulus_E());
        displacement_args.push_back(poisson_nu());
        for (const bool plane_strain : {true, false})
          table.push_back(
            {plane_strain ? "lame_radial_displacement_plane_strain" :
                            "lame_radial_displacement_plane_stress",
             std::string("radial displacement of a thick-walled cylinder under inner and outer "
                         "pressure, ") +
               (plane_strain ? "long cylinder (plane strain)" : "thin ring (plane stress)") +
               " (length)",
             source, displacement_args, [plane_strain](const Args &p) {
               return Result{lame_radial_displacement(p.at("r_i"), p.at("r_o"), p.at("p_i"), p.at("p_o"),
                                                      p.at("E"), p.at("nu"), p.at("r"), plane_strain),
                             {}};
             }});
        table.push_back({"lame_hoop_stress",
                         "hoop stress sigma_theta of a thick-walled cylinder under inner and outer "
                         "pressure (stress; the same in plane stress and plane strain)",
                         source, radii, [](const Args &p) {
                           return Result{lame_hoop_stress(p.at("r_i"), p.at("r_o"), p.at("p_i"),
                                                          p.at("p_o"), p.at("r")),
                                         {}};
                         }});
        table.push_back({"lame_radial_stress",
                         "radial stress sigma_r of a thick-walled cylinder under inner and outer "
                         "pressure (stress)",
                         source, radii, [](const Args &p) {
                           return Result{lame_radial_stress(p.at("r_i"), p.at("r_o"), p.at("p_i"),
                                                            p.at("p_o"), p.at("r")),
                                         {}};
                         }});
      }

      // ---------------------------------------------------------------- elastica
      void
      add_elastica_formulas(std::vector<Formula> &table)
      {
        const Argument moment = signed_value("M", "end moment");
        const std::string moment_source =
          "circular arc of curvature M/(E I); Howell 2001 sec. 5.4; closed-forms.md";
        const std::string force_source =
          "Bisshopp and Drucker, Q. Appl. Math. 3:272 (1945), elliptic integrals (Carlson)";

        // Shared checks: inextensible, shear-rigid, linear moment-curvature.
        const auto end_moment = [](const Args &p, double CantileverTip::*component, double scale) {
          const double t = p.at("M") * p.at("L") / flexural_rigidity(p);
          Result r{end_moment_elastica(t).*component * scale, {}};
          check_beam_slenderness(r, p.at("L"), p.at("h"));
          check_bending_strain(r, t, p.at("L"), p.at("h"));
          warn_if(r, std::abs(t) > 2.0 * M_PI,
                  "ML/(EI) = " + number(t) + " > 2 pi: the beam winds past a full circle and "
                                             "would touch itself");
          return r;
        };
        const auto tip_force = [](const Args &p, double CantileverTip::*component, double scale) {
          const double L = p.at("L");
          const double alpha = p.at("P") * L * L / flexural_rigidity(p);
          const CantileverTip tip = tip_load_elastica(alpha);
          Result r{tip.*component * scale, {}};
          check_beam_slenderness(r, L, p.at("h"));
          // Largest curvature is at the clamp: M = P x_tip.
          check_bending_strain(r, alpha * (1.0 - tip.shortening), L, p.at("h"));
          return r;
        };

        const std::vector<Argument> moment_args{moment, length_L(), modulus_E(), width_b(), depth_h()};
        const std::vector<Argument> force_args{load(), length_L(), modulus_E(), width_b(), depth_h()};

        table.push_back({"elastica_end_moment_rotation", "tip rotation under an end moment (rad)",
                         moment_source, moment_args, [end_moment](const Args &p) {
                           return end_moment(p, &CantileverTip::rotation, 1.0);
                         }});
        table.push_back({"elastica_end_moment_deflection",
                         "transverse tip displacement under an end moment, L (1 - cos t)/t, "
                         "t = M L/(E I) (length)",
                         moment_source, moment_args, [end_moment](const Args &p) {
                           return end_moment(p, &CantileverTip::deflection, p.at("L"));
                         }});
        table.push_back({"elastica_end_moment_shortening",
                         "axial tip displacement towards the clamp under an end moment, "
                         "L (1 - sin t / t) (length)",
                         moment_source, moment_args, [end_moment](const Args &p) {
                           return end_moment(p, &CantileverTip::shortening, p.at("L"));
                         }});
        table.push_back({"elastica_tip_force_rotation",
                         "tip rotation under a dead transverse tip force (rad)", force_source,
                         force_args, [tip_force](const Args &p) {
                           return tip_force(p, &CantileverTip::rotation, 1.0);
                         }});
        table.push_back({"elastica_tip_force_deflection",
                         "transverse tip displacement under a dead transverse tip force (length)",
                         force_source, force_args, [tip_force](const Args &p) {
                           return tip_force(p, &CantileverTip::deflection, p.at("L"));
                         }});
        table.push_back({"elastica_tip_force_shortening",
                         "axial tip displacement towards the clamp under a dead transverse tip "
                         "force (length)",
                         force_source, force_args, [tip_force](const Args &p) {
                           return tip_force(p, &CantileverTip::shortening, p.at("L"));
                         }});
      }
    } // namespace

    std::vector<Formula>
    make_formula_table()
    {
      std::vector<Formula> table;
      add_beam_formulas(table);
      add_prbm_formulas(table);
      add_torsion_formulas(table);
      add_elastica_formulas(table);
      add_cylinder_formulas(table);
      add_stability_formulas(table);
      return table;
    }
  } // namespace internal
} // namespace closed_forms
