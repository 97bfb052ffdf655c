// Closed forms of stability: columns, flexures under axial load, bistable beams.
#include "bistable.h"
#include "formula_helpers.h"
#include "plates.h"

namespace closed_forms
{
  namespace internal
  {
    namespace
    {
      // Measured with the FE (cases/bistable/REPORT.md: one perfect cosine beam on its symmetric
      // path, plane stress, arc length, h/L = 0.02): F_top / F_bottom against the estimates -14 / -31 %
      // at Q = 4, -4 / -10.5 % at Q = 8, -1.7 / -6 % at Q = 16: they are the large-Q limits.
      constexpr double bistable_estimate_q = 10.0;
      constexpr double bistable_shallow_ratio = 0.1; // h/L: the shallow-beam (modal) model

      void check_bistable(Result &result, const Args &p)
      {
        const double Q = p.at("h") / p.at("t");
        warn_if(result, Q <= bistable_minimum_q,
                "Q = h/t = " + number(Q) + " <= 2.31: the beam is not bistable with its second mode held");
        warn_if(result, Q > bistable_minimum_q && Q < bistable_estimate_q,
                "Q = h/t = " + number(Q) + " < 10: the estimate is the large-Q limit and overestimates (FE: "
                "+16/+45 % at Q = 4, +4/+12 % at Q = 8 for top/bottom; the bottom one +6.5 % still at Q = 16)");
        warn_if(result, p.at("h") / p.at("L") > bistable_shallow_ratio,
                "h/L = " + number(p.at("h") / p.at("L")) + " > 0.1: not a shallow beam");
      }
    } // namespace

    void add_stability_formulas(std::vector<Formula> &table)
    {
      const Argument ends = positive("K", "effective-length factor of the ends: 2 fixed-free, 1 pinned-pinned, "
                                          "0.6992 fixed-pinned, 0.5 fixed-fixed");
      table.push_back(
        {"euler_column_load",
         "buckling load of a column, pi^2 E I / (K L)^2, h the depth in the buckling direction (force)",
         "Timoshenko and Gere, Theory of Elastic Stability, sec. 2.1-2.3",
         {length_L(), modulus_E(), width_b(), depth_h(), ends},
         [](const Args &p) {
           Result r{euler_column_load(p.at("L"), p.at("E"), p.at("b"), p.at("h"), p.at("K")), {}};
           check_beam_slenderness(r, p.at("K") * p.at("L"), p.at("h"));
           return r;
         }});
      table.push_back(
        {"engesser_column_load",
         "buckling load of a column with shear, P_E / (1 + P_E / (kappa G A)) (force)",
         "Timoshenko and Gere, Theory of Elastic Stability, sec. 2.18 (Engesser)",
         {length_L(), modulus_E(), poisson_nu(), width_b(), depth_h(), ends, kappa_arg()},
         [](const Args &p) {
           Result r{engesser_column_load(p.at("L"), p.at("E"), p.at("nu"), p.at("b"), p.at("h"), p.at("K"),
                                         p.at("kappa")),
                    {}};
           check_timoshenko_slenderness(r, p.at("K") * p.at("L"), p.at("h"));
           return r;
         }});

      table.push_back(
        {"beam_column_end_moment_stiffness",
         "end-moment stiffness M/theta of a cantilever under an axial end force P (P > 0 "
         "compressive, keeping its direction): (EI/L) kL/tan kL, in tension kL/tanh kL (moment/rad)",
         "Timoshenko and Gere, Theory of Elastic Stability, sec. 1.5",
         {length_L(), modulus_E(), width_b(), depth_h(),
          signed_value("P", "axial end force, positive in compression")},
         [](const Args &p) {
           Result r{beam_column_end_moment_stiffness(p.at("L"), p.at("E"), p.at("b"), p.at("h"), p.at("P")), {}};
           check_beam_slenderness(r, p.at("L"), p.at("h"));
           const double critical = euler_column_load(p.at("L"), p.at("E"), p.at("b"), p.at("h"), 2.0);
           warn_if(r, p.at("P") >= critical,
                   "P = " + number(p.at("P") / critical) + " P_cr: at or beyond the buckling load the "
                   "straight cantilever is unstable (stiffness <= 0)");
           return r;
         }});

      const std::vector<Argument> guided_args = {length_L(), modulus_E(), width_b(), depth_h(),
                                                 signed_value("P", "axial force, positive in compression")};
      const auto guided_checks = [](Result &r, const Args &p) {
        check_beam_slenderness(r, p.at("L"), p.at("h"));
        const double critical = euler_column_load(p.at("L"), p.at("E"), p.at("b"), p.at("h"), 1.0);
        warn_if(r, p.at("P") >= critical, "P = " + number(p.at("P") / critical) + " P_cr: at or beyond the "
                                          "sway buckling load the guided blade is unstable (stiffness <= 0)");
      };
      table.push_back(
        {"guided_beam_column_stiffness",
         "transverse stiffness F/delta of a fixed-guided blade (parallel-guided flexure) under an axial force "
         "P (P > 0 compressive): exact beam-column, 12 E I / L^3 at P = 0, zero at pi^2 E I / L^2 (force/length)",
         "Timoshenko and Gere, Theory of Elastic Stability, sec. 1.11-1.12",
         guided_args,
         [guided_checks](const Args &p) {
           Result r{guided_beam_column_stiffness(p.at("L"), p.at("E"), p.at("b"), p.at("h"), p.at("P")), {}};
           guided_checks(r, p);
           return r;
         }});
      table.push_back(
        {"bcm_guided_stiffness",
         "the same by the beam constraint model, (E I / L^3)(12 + 6/5 p - p^2/700), p = -P L^2 / E I "
         "(force/length)",
         "Awtar, Slocum and Sevincer, J. Mech. Des. 129:625 (2007)",
         guided_args,
         [guided_checks](const Args &p) {
           Result r{bcm_guided_stiffness(p.at("L"), p.at("E"), p.at("b"), p.at("h"), p.at("P")), {}};
           guided_checks(r, p);
           const double EI = p.at("E") * second_moment_of_area(p.at("b"), p.at("h"));
           const double pn = std::abs(p.at("P")) * p.at("L") * p.at("L") / EI;
           // Against the exact stiffness: 3e-5 at |p| = 2.5, 1e-4 (tension) and 3.5e-4 (compression) at
           // |p| = 5, 3.9e-3 at p = -8 (unit.closed_forms.Beams.BeamConstraintModel...).
           warn_if(r, pn > 5, "|p| = P L^2 / E I = " + number(pn) + " > 5: the second-order series departs from the "
                                "exact beam-column stiffness by more than 0.035 % (0.4 % at 8 in compression; "
                                "guided_beam_column_stiffness is exact)");
           return r;
         }});
      table.push_back(
        {"lateral_torsional_buckling_moment",
         "uniform moment that buckles a narrow strip sideways and twisted, fork ends, (pi/L) sqrt(E I_y G J) "
         "(moment)",
         "Timoshenko and Gere, Theory of Elastic Stability, sec. 6.2",
         {length_L(), modulus_E(), poisson_nu(), depth_h(), positive("b", "width of the strip, b < h")},
         [](const Args &p) {
           Result r{lateral_torsional_buckling_moment(p.at("L"), p.at("E"), p.at("nu"), p.at("h"), p.at("b")), {}};
           check_beam_slenderness(r, p.at("L"), p.at("h"));
           const double ratio = p.at("b") / p.at("h");
           warn_if(r, ratio > 0.3, "b/h = " + number(ratio) + " > 0.3: not a narrow strip; the curvature before "
                                     "buckling raises M_cr by " + number(100 * (1 / std::sqrt(1 - ratio * ratio) - 1)) +
                                     " % or more");
           return r;
         }});

      const std::vector<Argument> plate_args = {
        positive("a", "plate length along the load"), positive("b", "plate width across the load"),
        positive("t", "plate thickness"), modulus_E(), poisson_nu(),
        optional_positive("m", "half-waves along the load", 1), optional_positive("n", "half-waves across it", 1)};
      std::vector<Argument> plate_mindlin_args = plate_args;
      plate_mindlin_args.push_back(optional_positive("kappa", "shear correction factor", 5.0 / 6.0));
      table.push_back(
        {"plate_buckling_stress",
         "uniform compressive stress along a that buckles a rectangular plate simply supported on all four "
         "edges into m half-waves along a and n across b, (pi^2 D / (b^2 t)) (m b/a + n^2 a/(m b))^2, "
         "D = E t^3 / 12 (1 - nu^2) (stress)",
         "Timoshenko and Gere, Theory of Elastic Stability, sec. 9.2",
         plate_args,
         [](const Args &p) {
           const double a = p.at("a"), b = p.at("b"), t = p.at("t"), m = p.at("m"), n = p.at("n");
           Result r{plate_buckling_stress(a, b, t, p.at("E"), p.at("nu"), m, n), {}};
           const double shear = plate_buckling_shear_share(a, b, t, p.at("E"), p.at("nu"), m, n);
           warn_if(r, shear > 0.01, "transverse shear lowers this mode's stress by " +
                                      number(100 * shear / (1 + shear)) + " % (Mindlin): a thick plate for it");
           warn_if(r, std::min(a, b) / t < 20, "min(a, b)/t = " + number(std::min(a, b) / t) +
                                                 " < 20: not a thin plate");
           return r;
         }});

      table.push_back(
        {"plate_buckling_stress_mindlin",
         "the same with transverse shear (Mindlin's simply supported plate): the Kirchhoff stress / (1 + "
         "pi^2 D ((m/a)^2 + (n/b)^2) / (kappa G t)) (stress)",
         "Timoshenko and Gere, sec. 9.2; shear: Mindlin, J. Appl. Mech. 18:31 (1951), simply supported case",
         plate_mindlin_args,
         [](const Args &p) {
           const double a = p.at("a"), b = p.at("b"), t = p.at("t"), m = p.at("m"), n = p.at("n");
           const double shear = plate_buckling_shear_share(a, b, t, p.at("E"), p.at("nu"), m, n, p.at("kappa"));
           Result r{plate_buckling_stress(a, b, t, p.at("E"), p.at("nu"), m, n) / (1 + shear), {}};
           warn_if(r, std::min(a / m, b / n) / t < 5,
                   "a half-wave shorter than 5 thicknesses: beyond plate theory");
           return r;
         }});

      const std::vector<Argument> bistable_args = {
        positive("L", "span of the beam"), modulus_E(), positive("b", "out-of-plane width"),
        positive("t", "in-plane thickness"), positive("h", "apex height of the centre line (cosine shape)")};
      table.push_back({"bistable_switching_force_top",
                       "force at the centre that snaps a cosine clamped-clamped beam with its second mode "
                       "held (double beam, tied centre) forward, ~740 E I h / L^3 per beam (force)",
                       "Qiu, Lang and Slocum, J. MEMS 13:137 (2004)", bistable_args, [](const Args &p) {
                         Result r{bistable_switching_force_top(p.at("L"), p.at("E"), p.at("b"), p.at("t"), p.at("h")),
                                  {}};
                         check_bistable(r, p);
                         return r;
                       }});
      table.push_back({"bistable_switching_force_bottom",
                       "force at the centre that pulls the same beam back from its second stable position, "
                       "~370 E I h / L^3 per beam (force)",
                       "Qiu, Lang and Slocum, J. MEMS 13:137 (2004)", bistable_args, [](const Args &p) {
                         Result r{bistable_switching_force_bottom(p.at("L"), p.at("E"), p.at("b"), p.at("t"),
                                                                  p.at("h")),
                                  {}};
                         check_bistable(r, p);
                         return r;
                       }});
    }
  } // namespace internal
} // namespace closed_forms
