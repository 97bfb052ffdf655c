#include <mechanisms/four_bar/flap_parameters.h>
#include <text/text_utilities.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace compliant
{
  namespace four_bar
  {
    namespace
    {
      constexpr double mm  = 1e-3;
      constexpr double deg = M_PI / 180.;
      constexpr double rpm = 2. * M_PI / 60.;

      using text::trim;

      double to_number(const std::string &key, const std::string &text)
      {
        std::istringstream in(text);
        double             value;
        if (!(in >> value) || !(in >> std::ws).eof() || !std::isfinite(value))
          throw std::invalid_argument("flap parameter '" + key + "': expected a number, got '" +
                                      text + "'");
        return value;
      }

      double positive(const std::string &key, const std::string &text)
      {
        const double value = to_number(key, text);
        if (!(value > 0.))
          throw std::invalid_argument("flap parameter '" + key +
                                      "': expected a positive number, got " + text);
        return value;
      }

      double non_negative(const std::string &key, const std::string &text)
      {
        const double value = to_number(key, text);
        if (value < 0.)
          throw std::invalid_argument("flap parameter '" + key +
                                      "': expected a non-negative number, got " + text);
        return value;
      }

      std::vector<double> positive_list(const std::string &key, const std::string &text)
      {
        std::vector<double> values;
        std::istringstream  in(text);
        std::string         item;
        while (std::getline(in, item, ','))
          values.push_back(positive(key, trim(item)));
        if (values.empty())
          throw std::invalid_argument("flap parameter '" + key +
                                      "': expected a comma-separated list of positive numbers");
        return values;
      }

      std::string choice(const std::string &key, const std::string &text,
                         const std::vector<std::string> &allowed)
      {
        for (const auto &option : allowed)
          if (text == option)
            return text;
        std::string list;
        for (const auto &option : allowed)
          list += (list.empty() ? "" : " | ") + option;
        throw std::invalid_argument("flap parameter '" + key + "': expected one of " + list +
                                    ", got '" + text + "'");
      }
    } // namespace

    FlapParameterSet::FlapParameterSet()
    {
      // Geometry, Table 1 of the paper.
      declare("ground_length_mm", "60", "l1 = |AD| (paper Table 1)");
      declare("crank_length_mm", "10", "l2 = |AB|, driven link (paper Table 1)");
      declare("coupler_length_mm", "65", "l3 = |BC| (paper Table 1)");
      declare("rocker_length_mm", "15", "l4 = |CD|, carries the flap (paper Table 1)");
      // Masses and inertias, Table 1.
      declare("crank_mass_kg", "3.154e-4", "m2 (paper Table 1)");
      declare("coupler_mass_kg", "6.48e-5", "m3 (paper Table 1)");
      declare("rocker_mass_kg", "3.487e-5", "m4 (paper Table 1)");
      declare("crank_inertia_kgm2", "1.11e-9", "I2 about the centre of mass (paper Table 1)");
      declare("coupler_inertia_kgm2", "1.22e-9", "I3 about the centre of mass (paper Table 1)");
      declare("rocker_inertia_kgm2", "7.98e-9", "I4 about the centre of mass (paper Table 1)");
      declare("centre_of_mass_fraction", "0.5",
              "centre of mass of each link as a fraction of its length from its first joint "
              "(A, B, D); the paper gives none: mid-link");
      // Flexures.
      declare("youngs_modulus_mpa", "89.5",
              "Semiflex modulus (not in the paper): printed TPU 98A at low strain, Bates et "
              "al., Mater. Des. 2016; printed TPUs span 24-247 MPa");
      declare("flexure_width_mm", "1.5", "b (paper Table 1)");
      declare("flexure_thickness_mm", "3",
              "h, bending thickness: the paper uses I = b h^3 / 12 with h = 3 mm (Eq. 4)");
      declare("flexure_length_mm", "1",
              "l_k (not in the paper): 1 mm = l2/10, the longest flexure for which the "
              "small-length flexural pivot holds on the 10 mm crank (Howell 2001, l << L)");
      // Motion.
      declare("assembly_branch", "minus",
              "root of Eq. E13: minus = C above the ground line (0..116 deg rocker), plus = "
              "mirror image");
      declare("motion", "oscillation",
              "oscillation: the crank rocks harmonically, one out-and-back sweep per motor turn "
              "(ideal driver, as the paper's fatigue rig) | rotation: the crank turns fully at the "
              "motor speed (the paper's model; meaningful for the rigid linkage only)");
      declare("sweep_link", "rocker",
              "which link sweeps sweep_deg: rocker (the flap, 26 deg in paper sec. 2.1 and Fig. "
              "9) | crank (link AB, as the paper's sec. 2.2 words the fatigue test)");
      declare("sweep_deg", "26", "peak-to-peak sweep of sweep_link (paper: 26 deg)");
      declare("window_centre_deg", "auto",
              "crank angle at the middle of the sweep; auto = where the transmission angle is "
              "90 deg (the paper gives no working position)");
      declare("rest_pose", "start",
              "where the flexures are unloaded (the as-printed shape): start of the sweep (flap "
              "closed) | centre");
      declare("motor_speed_rpm", "60", "motor speed (paper: 60 rpm)");
      declare("gravity_ms2", "9.81", "gravity (paper Eq. E23); 0 switches it off");
      declare("gravity_direction_deg", "-90",
              "direction of gravity from the ground line AD (-90: AD horizontal, as E24-E26)");
      declare("samples_per_cycle", "720", "samples of the torque cycle");
      // Motor (only for the speed ripple; the paper gives no motor data).
      declare("motor_stall_torque_nm", "1.0",
              "stall torque of the 60 rpm gear motor (assumed: small 12 V gear motor class)");
      declare("motor_reflected_inertia_kgm2", "1e-3",
              "rotor and gearbox inertia at the output shaft (assumed; affects ripple little "
              "at 1 Hz as the motor time constant is milliseconds)");
      // Parameter study of the torque ratio.
      declare("study_youngs_moduli_mpa", "24, 50, 89.5, 150, 247",
              "moduli for the torque-ratio study (printed TPU range, materials.md)");
      declare("study_flexure_lengths_mm", "0.25, 0.5, 1, 2, 3, 5, 10",
              "flexure lengths for the torque-ratio study");
    }

    void FlapParameterSet::declare(const std::string &key, const std::string &default_value,
                                   const std::string &documentation)
    {
      entries[key] = {default_value, default_value, documentation};
      order.push_back(key);
    }

    void FlapParameterSet::assign(const std::string &key, const std::string &value,
                                  const std::string &where)
    {
      const auto entry = entries.find(key);
      if (entry == entries.end())
        throw std::invalid_argument(where + "unknown flap parameter '" + key +
                                    "' (flap_prbm --help lists them)");
      if (value.empty())
        throw std::invalid_argument(where + "flap parameter '" + key + "' has no value");
      entry->second.value = value;
    }

    void FlapParameterSet::read_file(const std::string &file_name)
    {
      std::ifstream in(file_name);
      if (!in)
        throw std::invalid_argument("cannot open flap parameter file '" + file_name + "'");
      std::string  line;
      unsigned int line_number = 0;
      while (std::getline(in, line))
        {
          ++line_number;
          const std::string where   = file_name + ":" + std::to_string(line_number) + ": ";
          const std::string content = trim(line.substr(0, line.find('#')));
          if (content.empty())
            continue;
          const auto equals = content.find('=');
          if (equals == std::string::npos)
            throw std::invalid_argument(where + "expected 'key = value', got '" + content + "'");
          assign(trim(content.substr(0, equals)), trim(content.substr(equals + 1)), where);
        }
    }

    void FlapParameterSet::set(const std::string &assignment)
    {
      const auto equals = assignment.find('=');
      if (equals == std::string::npos)
        throw std::invalid_argument("--set expects key=value, got '" + assignment + "'");
      assign(trim(assignment.substr(0, equals)), trim(assignment.substr(equals + 1)), "--set: ");
    }

    FlapParameters FlapParameterSet::parameters() const
    {
      const auto value = [this](const std::string &key) {
        return entries.at(key).value;
      };
      const auto pos = [&](const std::string &key) {
        return positive(key, value(key));
      };
      const auto nonneg = [&](const std::string &key) {
        return non_negative(key, value(key));
      };

      FlapParameters p;
      p.lengths             = {pos("ground_length_mm") * mm, pos("crank_length_mm") * mm,
                               pos("coupler_length_mm") * mm, pos("rocker_length_mm") * mm};
      const double fraction = nonneg("centre_of_mass_fraction");
      if (fraction > 1.)
        throw std::invalid_argument(
          "flap parameter 'centre_of_mass_fraction': expected a number in [0, 1], got " +
          value("centre_of_mass_fraction"));
      p.masses = {
        {nonneg("crank_mass_kg"), nonneg("crank_inertia_kgm2"), fraction * p.lengths.crank},
        {nonneg("coupler_mass_kg"), nonneg("coupler_inertia_kgm2"), fraction * p.lengths.coupler},
        {nonneg("rocker_mass_kg"), nonneg("rocker_inertia_kgm2"), fraction * p.lengths.rocker}};
      p.youngs_modulus    = pos("youngs_modulus_mpa") * 1e6;
      p.flexure_width     = pos("flexure_width_mm") * mm;
      p.flexure_thickness = pos("flexure_thickness_mm") * mm;
      p.flexure_length    = pos("flexure_length_mm") * mm;

      p.branch = choice("assembly_branch", value("assembly_branch"), {"plus", "minus"}) == "plus" ?
                   AssemblyBranch::plus :
                   AssemblyBranch::minus;
      p.motion = choice("motion", value("motion"), {"oscillation", "rotation"}) == "rotation" ?
                   MotionKind::full_rotation :
                   MotionKind::harmonic_oscillation;
      p.sweep_link = choice("sweep_link", value("sweep_link"), {"crank", "rocker"}) == "crank" ?
                       SweepLink::crank :
                       SweepLink::rocker;
      p.sweep      = pos("sweep_deg") * deg;
      if (p.sweep >= 2. * M_PI)
        throw std::invalid_argument("flap parameter 'sweep_deg': expected less than 360, got " +
                                    value("sweep_deg"));
      p.automatic_centre = value("window_centre_deg") == "auto";
      p.window_centre =
        p.automatic_centre ? 0. : to_number("window_centre_deg", value("window_centre_deg")) * deg;
      p.rest_pose    = choice("rest_pose", value("rest_pose"), {"start", "centre"}) == "start" ?
                         RestPose::start :
                         RestPose::centre;
      p.motor_speed  = pos("motor_speed_rpm") * rpm;
      const double g = nonneg("gravity_ms2");
      const double direction =
        to_number("gravity_direction_deg", value("gravity_direction_deg")) * deg;
      p.gravity            = {g * std::cos(direction), g * std::sin(direction)};
      const double samples = pos("samples_per_cycle");
      if (samples < 8 || samples != std::floor(samples) || samples > 1e7)
        throw std::invalid_argument(
          "flap parameter 'samples_per_cycle': expected an integer in [8, 1e7], got " +
          value("samples_per_cycle"));
      p.samples_per_cycle = static_cast<unsigned int>(samples);
      p.motor = {p.motor_speed, pos("motor_stall_torque_nm"), pos("motor_reflected_inertia_kgm2")};
      for (const double E :
           positive_list("study_youngs_moduli_mpa", value("study_youngs_moduli_mpa")))
        p.study_youngs_moduli.push_back(E * 1e6);
      for (const double l :
           positive_list("study_flexure_lengths_mm", value("study_flexure_lengths_mm")))
        p.study_flexure_lengths.push_back(l * mm);
      return p;
    }

    void FlapParameterSet::print(std::ostream &out) const
    {
      for (const auto &key : order)
        {
          const Entry &e = entries.at(key);
          out << "  " << key << " = " << e.value;
          if (e.value != e.default_value)
            out << "   (default " << e.default_value << ")";
          out << "\n      " << e.documentation << "\n";
        }
    }
  } // namespace four_bar
} // namespace compliant
