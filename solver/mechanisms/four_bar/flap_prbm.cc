// flap_prbm: kinematics, PRBM torques and the compliant/rigid torque ratio of the compliant flap
// four-bar (seed paper 000), printed as a table and written as CSV files for postproc/.
//
//   flap_prbm [parameter-file] [--set key=value]... [--output DIR] [--help]

#include <mechanisms/four_bar/branch_tracker.h>
#include <mechanisms/four_bar/cycle_dynamics.h>
#include <mechanisms/four_bar/flap_parameters.h>
#include <mechanisms/four_bar/grashof.h>
#include <mechanisms/four_bar/motor_ripple.h>
#include <mechanisms/four_bar/prbm_springs.h>
#include <mechanisms/four_bar/working_window.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace compliant::four_bar;

namespace
{
  constexpr double deg = M_PI / 180.;
  constexpr double rpm = 2. * M_PI / 60.;

  // The paper's headline figures (seed 000, sec. 3).
  constexpr double paper_torque_ratio     = 3.;
  constexpr double paper_speed_ripple_rpm = 0.001;

  void print_usage(std::ostream &out)
  {
    out << "usage: flap_prbm [parameter-file] [--set key=value]... [--output DIR] [--help]\n"
           "Parameter file: 'key = value' lines, '#' comments. Parameters and defaults:\n";
  }

  std::ofstream open_csv(const std::filesystem::path &path)
  {
    std::ofstream out(path);
    if (!out)
      throw std::runtime_error("cannot write " + path.string());
    out << std::setprecision(10);
    return out;
  }

  // The CSV files of one run, written under temporary names and renamed only when the whole run
  // succeeded: a run that fails leaves nothing (and removes the folder if it made it).
  class PendingOutput
  {
  public:
    explicit PendingOutput(const std::filesystem::path &directory)
      : directory(directory)
      , created(std::filesystem::create_directories(directory))
    {}
    PendingOutput(const PendingOutput &)            = delete;
    PendingOutput &operator=(const PendingOutput &) = delete;
    ~PendingOutput()
    {
      if (committed)
        return;
      std::error_code ignored;
      for (const auto &name : names)
        std::filesystem::remove(directory / (name + ".part"), ignored);
      if (created)
        std::filesystem::remove(directory, ignored); // only if empty
    }
    std::ofstream open(const std::string &name)
    {
      names.push_back(name);
      return open_csv(directory / (name + ".part"));
    }
    void commit()
    {
      for (const auto &name : names)
        std::filesystem::rename(directory / (name + ".part"), directory / name);
      committed = true;
    }

  private:
    std::filesystem::path    directory;
    bool                     created   = false;
    bool                     committed = false;
    std::vector<std::string> names;
  };

  FlapMechanism make_mechanism(const FlapParameters &p, const Pose &rest,
                               const double youngs_modulus, const double flexure_length)
  {
    const double K = flexural_pivot_stiffness(youngs_modulus, p.flexure_width, p.flexure_thickness,
                                              flexure_length);
    return {p.lengths, p.masses, {{K, K, K, K}, rest}, p.gravity, p.branch};
  }

  double ratio(const TorqueStatistics &numerator, const TorqueStatistics &denominator,
               const bool use_rms)
  {
    return use_rms ? numerator.rms / denominator.rms : numerator.peak / denominator.peak;
  }

  // Spring stiffness K (equal at A..D) that makes the compliant/reference torque ratio equal to
  // target: the spring torque is linear in K, so the ratio is continuous in K; bisection on a
  // logarithmic bracket.
  double stiffness_for_ratio(const std::vector<CycleSample> &unit_spring_cycle,
                             const TorqueComponent reference, const bool use_rms,
                             const double target)
  {
    const auto ratio_at = [&](const double K) {
      std::vector<CycleSample> scaled = unit_spring_cycle;
      for (auto &s : scaled)
        s.spring_torque *= K;
      const auto c = torque_statistics(scaled, TorqueComponent::compliant, TorqueReference::crank);
      const auto r = torque_statistics(scaled, reference, TorqueReference::crank);
      // Without gravity the reference is inertia only; the compliant signal then must not
      // include gravity either.
      if (reference == TorqueComponent::inertia)
        {
          for (auto &s : scaled)
            s.gravity_torque = 0.;
          const auto c0 =
            torque_statistics(scaled, TorqueComponent::compliant, TorqueReference::crank);
          return ratio(c0, r, use_rms);
        }
      return ratio(c, r, use_rms);
    };
    double lo = 1e-14, hi = 1e-14;
    while (ratio_at(hi) < target && hi < 1e6)
      {
        lo = hi;
        hi *= 2.;
      }
    for (unsigned int i = 0; i < 200 && hi / lo > 1. + 1e-12; ++i)
      {
        const double mid                   = std::sqrt(lo * hi);
        (ratio_at(mid) < target ? lo : hi) = mid;
      }
    return std::sqrt(lo * hi);
  }

  int run(int argc, char **argv)
  {
    FlapParameterSet      parameter_set;
    std::filesystem::path output = "flap_prbm_output";
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
          {
            print_usage(std::cout);
            parameter_set.print(std::cout);
            return 0;
          }
        else if (arg == "--set" && i + 1 < argc)
          parameter_set.set(argv[++i]);
        else if (arg == "--output" && i + 1 < argc)
          output = argv[++i];
        else if (!arg.empty() && arg[0] != '-')
          parameter_set.read_file(arg);
        else
          throw std::invalid_argument("unknown or incomplete argument '" + arg +
                                      "' (see flap_prbm --help)");
      }
    const FlapParameters p = parameter_set.parameters();
    std::cout << std::setprecision(4);

    std::cout << "flap_prbm: compliant flap four-bar (seed 000) - parameters\n";
    parameter_set.print(std::cout);

    // --- Grashof class and full-range kinematics -------------------------------------------
    const GrashofAnalysis grashof = classify_grashof(p.lengths);
    std::cout << "\nGrashof: " << to_string(grashof.class_)
              << " (s + l - p - q = " << grashof.condition / 1e-3 << " mm"
              << (grashof.class_ == GrashofClass::change_point ?
                    ", limit class " + to_string(grashof.grashof_limit_class) :
                    std::string())
              << "); crank turns fully: " << (grashof.crank_fully_rotates ? "yes" : "no") << "\n";

    // --- Working window (checked before any file is written) ----------------------------
    const double centre       = p.automatic_centre ?
                                  crank_angle_with_right_transmission(p.lengths, p.branch) :
                                  p.window_centre;
    const double crank_sweep  = p.sweep_link == SweepLink::crank ?
                                  p.sweep :
                                  crank_sweep_for_rocker_sweep(p.lengths, p.branch, centre, p.sweep);
    const double start        = centre - 0.5 * crank_sweep;
    const double rocker_sweep = rocker_sweep_over(p.lengths, p.branch, centre, crank_sweep);
    const bool   rotation     = p.motion == MotionKind::full_rotation;
    // A change-point linkage repeats its motion only every second crank turn.
    const unsigned int n_turns = rotation && grashof.class_ == GrashofClass::change_point ? 2 : 1;
    if (!rotation && min_collinearity_over(p.lengths, p.branch, start, start + crank_sweep) < 1e-3)
      throw std::domain_error("the working window contains a dead or change point; choose "
                              "another window_centre_deg or a smaller sweep");
    const Pose rest =
      solve_pose(p.lengths, p.rest_pose == RestPose::start ? start : centre, p.branch);
    const MotionLaw motion{rotation ? MotionKind::full_rotation : MotionKind::harmonic_oscillation,
                           start, crank_sweep};
    PendingOutput files(output);

    double max_residual = 0., max_rocker = -1e9, min_rocker = 1e9;
    {
      // Two crank turns from just past the fold, to show the branch continuation.
      auto csv = files.open("flap_kinematics.csv");
      csv << "crank_deg,coupler_deg,rocker_deg,branch,dth3_dth2,dth4_dth2,d2th3_dth2,d2th4_dth2,"
             "transmission_deg,closure_residual_m,relative_discriminant\n";
      const double  step = 0.5 * deg;
      BranchTracker tracker(p.lengths, 0.5 * step, p.branch);
      for (unsigned int i = 0; i < 1440; ++i)
        {
          const Pose  &pose     = i == 0 ? tracker.pose() : tracker.advance((i + 0.5) * step);
          const auto   h        = derivative_coefficients(p.lengths, pose);
          const auto   k        = freudenstein_coefficients(p.lengths, pose.crank_angle);
          const double residual = closure_residual(p.lengths, pose);
          max_residual          = std::max(max_residual, residual);
          if (i < 720)
            {
              max_rocker = std::max(max_rocker, pose.rocker_angle);
              min_rocker = std::min(min_rocker, pose.rocker_angle);
            }
          csv << pose.crank_angle / deg << ',' << pose.coupler_angle / deg << ','
              << pose.rocker_angle / deg << ',' << to_string(pose.branch) << ','
              << h.coupler_velocity << ',' << h.rocker_velocity << ',' << h.coupler_acceleration
              << ',' << h.rocker_acceleration << ',' << transmission_angle(pose) / deg << ','
              << residual << ',' << k.discriminant / (k.k1 * k.k1 + k.k2 * k.k2 + k.k3 * k.k3)
              << '\n';
        }
      std::cout << "Kinematics over two crank turns (0.5 deg steps): max closure residual "
                << max_residual << " m (" << max_residual / p.lengths.longest()
                << " of the longest link); rocker range over one turn " << min_rocker / deg
                << " .. " << max_rocker / deg
                << " deg; root-label switches at the fold: " << tracker.n_branch_switches() << "\n";
    }

    if (!rotation)
      {
        const Pose first = solve_pose(p.lengths, start, p.branch);
        const Pose last  = solve_pose(p.lengths, start + crank_sweep, p.branch);
        std::cout << "\nWorking window (" << to_string(p.branch) << " branch): crank "
                  << start / deg << " .. " << (start + crank_sweep) / deg << " deg (sweep "
                  << crank_sweep / deg << " deg), rocker " << first.rocker_angle / deg << " .. "
                  << last.rocker_angle / deg << " deg (sweep " << rocker_sweep / deg
                  << " deg); transmission angle " << transmission_angle(first) / deg << " .. "
                  << transmission_angle(last) / deg << " deg\n"
                  << "Motion: harmonic crank oscillation, one sweep out and back per motor turn "
                     "(ideal driver), motor "
                  << p.motor_speed / rpm << " rpm; flexures unloaded at crank "
                  << rest.crank_angle / deg << " deg\n";
      }
    else
      std::cout << "\nMotion: full crank rotation at " << p.motor_speed / rpm << " rpm from crank "
                << start / deg << " deg, period " << n_turns
                << " turn(s) (the change point swaps the branch each turn); the rocker swings "
                   "through its whole range, not the flap's 26 deg. The compliant rows below wind "
                   "flexure A through 360 deg per turn: not physical for a one-piece part, shown "
                   "only because the paper's model turns the crank fully.\n";

    // --- PRBM and dynamics over one cycle -------------------------------------------------
    const double        K         = flexural_pivot_stiffness(p.youngs_modulus, p.flexure_width,
                                                             p.flexure_thickness, p.flexure_length);
    const FlapMechanism mechanism = make_mechanism(p, rest, p.youngs_modulus, p.flexure_length);
    const auto          cycle =
      evaluate_cycle(mechanism, motion, p.motor_speed, p.samples_per_cycle, n_turns);
    std::cout << "PRBM spring K = E b h^3 / (12 l_k) = " << K
              << " N m/rad (E = " << p.youngs_modulus / 1e6
              << " MPa, b = " << p.flexure_width / 1e-3 << " mm, h = " << p.flexure_thickness / 1e-3
              << " mm, l_k = " << p.flexure_length / 1e-3 << " mm)\n";
    {
      auto csv = files.open("flap_torque_cycle.csv");
      csv << "time_s,motor_deg,crank_deg,coupler_deg,rocker_deg,crank_speed_rad_s,"
             "crank_accel_rad_s2,drive_ratio,T_inertia_Nm,T_gravity_Nm,T_spring_Nm,T_rigid_Nm,"
             "T_compliant_Nm,T_rigid_motor_Nm,T_compliant_motor_Nm,P_rigid_W,P_compliant_W,"
             "transmission_deg,kinetic_J,gravity_J,spring_J\n";
      for (const auto &s : cycle)
        csv << s.time << ',' << s.motor_angle / deg << ',' << s.pose.crank_angle / deg << ','
            << s.pose.coupler_angle / deg << ',' << s.pose.rocker_angle / deg << ','
            << s.crank.velocity << ',' << s.crank.acceleration << ',' << s.crank.drive_ratio << ','
            << s.inertia_torque << ',' << s.gravity_torque << ',' << s.spring_torque << ','
            << s.rigid_crank_torque() << ',' << s.compliant_crank_torque() << ','
            << s.rigid_crank_torque() * s.crank.drive_ratio << ','
            << s.compliant_crank_torque() * s.crank.drive_ratio << ','
            << s.rigid_crank_torque() * s.crank.velocity << ','
            << s.compliant_crank_torque() * s.crank.velocity << ',' << s.transmission_angle / deg
            << ',' << s.kinetic_energy << ',' << s.gravity_energy << ',' << s.spring_energy << '\n';
    }

    const TorqueComponent components[4]      = {TorqueComponent::inertia, TorqueComponent::rigid,
                                                TorqueComponent::springs, TorqueComponent::compliant};
    const char           *component_names[4] = {"rigid, inertia only", "rigid, inertia + gravity",
                                                "springs alone", "compliant (all)"};
    TorqueStatistics      crank_stats[4], motor_stats[4];
    std::cout << "\nTorque over one cycle                peak |T| crank   RMS T crank   peak |T| "
                 "motor   RMS T motor   peak |P|      RMS P\n"
              << "                                     [N m]            [N m]         [N m]     "
                 "       [N m]         [W]           [W]\n";
    for (unsigned int c = 0; c < 4; ++c)
      {
        crank_stats[c] = torque_statistics(cycle, components[c], TorqueReference::crank);
        motor_stats[c] = torque_statistics(cycle, components[c], TorqueReference::motor);
        std::cout << "  " << std::left << std::setw(35) << component_names[c] << std::right
                  << std::scientific << std::setw(14) << crank_stats[c].peak << std::setw(14)
                  << crank_stats[c].rms << std::setw(17) << motor_stats[c].peak << std::setw(14)
                  << motor_stats[c].rms << std::setw(14) << crank_stats[c].peak_power
                  << std::setw(14) << crank_stats[c].rms_power << std::defaultfloat << "\n";
      }
    // Compliant without gravity, to pair with the inertia-only rigid mechanism.
    auto cycle_no_gravity = cycle;
    for (auto &s : cycle_no_gravity)
      s.gravity_torque = 0.;
    const auto compliant_no_g =
      torque_statistics(cycle_no_gravity, TorqueComponent::compliant, TorqueReference::crank);
    const auto compliant_no_g_motor =
      torque_statistics(cycle_no_gravity, TorqueComponent::compliant, TorqueReference::motor);
    std::cout << "\nCompliant/rigid torque ratio (paper: about " << paper_torque_ratio << ")\n"
              << "  with gravity    : peak " << crank_stats[3].peak / crank_stats[1].peak
              << " (crank), " << motor_stats[3].peak / motor_stats[1].peak << " (motor); RMS "
              << crank_stats[3].rms / crank_stats[1].rms << " (crank), "
              << motor_stats[3].rms / motor_stats[1].rms << " (motor); peak power "
              << crank_stats[3].peak_power / crank_stats[1].peak_power << "\n"
              << "  without gravity : peak " << compliant_no_g.peak / crank_stats[0].peak
              << " (crank), " << compliant_no_g_motor.peak / motor_stats[0].peak << " (motor); RMS "
              << compliant_no_g.rms / crank_stats[0].rms << " (crank), "
              << compliant_no_g_motor.rms / motor_stats[0].rms << " (motor)\n";

    // --- What the paper's ratio of 3 requires --------------------------------------------
    {
      const FlapMechanism unit = {
        p.lengths, p.masses, {{1., 1., 1., 1.}, rest}, p.gravity, p.branch};
      const auto unit_cycle =
        evaluate_cycle(unit, motion, p.motor_speed, p.samples_per_cycle, n_turns);
      const double I = p.flexure_width * std::pow(p.flexure_thickness, 3) / 12.;
      std::cout << "\nSpring stiffness K (all four equal) that gives the paper's ratio of "
                << paper_torque_ratio << ", and what it implies:\n";
      for (const bool with_gravity : {true, false})
        for (const bool use_rms : {false, true})
          {
            const double K3 = stiffness_for_ratio(
              unit_cycle, with_gravity ? TorqueComponent::rigid : TorqueComponent::inertia, use_rms,
              paper_torque_ratio);
            std::cout << "  " << (with_gravity ? "with gravity,    " : "without gravity, ")
                      << (use_rms ? "RMS : " : "peak: ") << "K = " << K3 << " N m/rad = K_prbm / "
                      << K / K3 << "; E = " << K3 * p.flexure_length / I / 1e6
                      << " MPa at l_k = " << p.flexure_length / 1e-3
                      << " mm, or l_k = " << p.youngs_modulus * I / K3
                      << " m at E = " << p.youngs_modulus / 1e6 << " MPa\n";
          }
    }

    // --- Ratio against E and l_k -----------------------------------------------------------
    {
      auto csv = files.open("flap_ratio_study.csv");
      csv << "youngs_modulus_mpa,flexure_length_mm,stiffness_Nm_rad,peak_ratio_gravity,"
             "rms_ratio_gravity,peak_ratio_no_gravity,rms_ratio_no_gravity,peak_compliant_Nm\n";
      std::cout << "\nPeak compliant/rigid torque ratio at the crank (with gravity) against E and "
                   "l_k\n  l_k [mm] \\ E [MPa]";
      for (const double E : p.study_youngs_moduli)
        std::cout << std::setw(12) << E / 1e6;
      std::cout << "\n";
      for (const double l : p.study_flexure_lengths)
        {
          std::cout << "  " << std::setw(18) << std::left << l / 1e-3 << std::right;
          for (const double E : p.study_youngs_moduli)
            {
              const auto study = evaluate_cycle(make_mechanism(p, rest, E, l), motion,
                                                p.motor_speed, p.samples_per_cycle, n_turns);
              auto       no_g  = study;
              for (auto &s : no_g)
                s.gravity_torque = 0.;
              const auto c =
                torque_statistics(study, TorqueComponent::compliant, TorqueReference::crank);
              const auto c0 =
                torque_statistics(no_g, TorqueComponent::compliant, TorqueReference::crank);
              csv << E / 1e6 << ',' << l / 1e-3 << ','
                  << flexural_pivot_stiffness(E, p.flexure_width, p.flexure_thickness, l) << ','
                  << c.peak / crank_stats[1].peak << ',' << c.rms / crank_stats[1].rms << ','
                  << c0.peak / crank_stats[0].peak << ',' << c0.rms / crank_stats[0].rms << ','
                  << c.peak << '\n';
              std::cout << std::setw(12) << std::setprecision(3) << std::scientific
                        << c.peak / crank_stats[1].peak << std::defaultfloat
                        << std::setprecision(4);
            }
          std::cout << "\n";
        }
    }

    // --- Speed ripple under an assumed motor ------------------------------------------------
    if (!rotation)
      {
        std::cout << "\nMotor speed ripple (assumed linear motor: stall " << p.motor.stall_torque
                  << " N m, no-load " << p.motor.no_load_speed / rpm << " rpm, reflected inertia "
                  << p.motor.reflected_inertia << " kg m^2; paper: about " << paper_speed_ripple_rpm
                  << " rpm)\n";
        for (const bool springs : {false, true})
          {
            const auto load = [&](const double phi) {
              const ReflectedLoad L = reflected_load(mechanism, motion, phi, springs);
              return MotorLoad{L.inertia, L.inertia_derivative, L.generalized_force};
            };
            try
              {
                const RippleResult r = simulate_motor_ripple(p.motor, load, 2. * M_PI);
                std::cout << "  " << (springs ? "compliant" : "rigid    ") << ": ripple "
                          << r.ripple / rpm << " rpm (RK4), " << r.quasi_static_ripple / rpm
                          << " rpm (quasi-static, mechanism inertia neglected), mean speed "
                          << r.mean_speed / rpm << " rpm\n";
              }
            catch (const std::domain_error &error)
              {
                std::cout << "  " << (springs ? "compliant" : "rigid    ") << ": " << error.what()
                          << "\n";
              }
          }
      }
    else
      std::cout << "\nMotor speed ripple: computed for the oscillating drive only.\n";

    files.commit();
    std::cout << "\nCSV files written to " << output.string()
              << ": flap_kinematics.csv, flap_torque_cycle.csv, flap_ratio_study.csv\n";
    return 0;
  }
} // namespace

int main(int argc, char **argv)
{
  try
    {
      return run(argc, argv);
    }
  catch (const std::exception &error)
    {
      std::cerr << "flap_prbm: error: " << error.what() << "\n";
      return 1;
    }
}
