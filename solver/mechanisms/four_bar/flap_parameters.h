// Named, documented parameters of the flap PRBM study with their defaults and sources, read from
// a "key = value" file and "--set key=value" overrides. The defaults are the flap paper's
// (seed 000, Table 1) where it gives a value, and documented choices where it does not.
#pragma once

#include <mechanisms/four_bar/generalized_inertia.h>
#include <mechanisms/four_bar/link_lengths.h>
#include <mechanisms/four_bar/motion_law.h>
#include <mechanisms/four_bar/motor_ripple.h>
#include <mechanisms/four_bar/position_analysis.h>

#include <array>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace compliant
{
  namespace four_bar
  {
    enum class SweepLink
    {
      crank, // the sweep angle is the crank's (the paper's "26 deg of link AB", sec. 2.2)
      rocker // the sweep angle is the rocker's, i.e. the flap's (sec. 2.1, Fig. 9)
    };

    enum class RestPose
    {
      start, // flexures unloaded at the start of the sweep (printed with the flap closed)
      centre // flexures unloaded at the middle of the sweep
    };

    // Typed values in SI units (lengths in m, angles in rad).
    struct FlapParameters
    {
      LinkLengths           lengths;
      MovingLinkMasses      masses;
      double                youngs_modulus;
      double                flexure_width;     // b
      double                flexure_thickness; // h, in the bending direction
      double                flexure_length;    // l_k
      AssemblyBranch        branch;
      MotionKind            motion;
      SweepLink             sweep_link;
      double                sweep;
      bool                  automatic_centre;
      double                window_centre;
      RestPose              rest_pose;
      double                motor_speed;
      std::array<double, 2> gravity;
      unsigned int          samples_per_cycle;
      DcMotor               motor;
      std::vector<double>   study_youngs_moduli;   // [Pa]
      std::vector<double>   study_flexure_lengths; // [m]
    };

    class FlapParameterSet
    {
    public:
      // All keys with their defaults.
      FlapParameterSet();

      // Reads "key = value" lines; '#' starts a comment. Throws std::invalid_argument naming the
      // file and line for a malformed line or an unknown key.
      void read_file(const std::string &file_name);

      // "key=value". Throws std::invalid_argument for an unknown key or a missing '='.
      void set(const std::string &assignment);

      // Converts and checks every value; throws std::invalid_argument naming the key and what
      // was expected.
      FlapParameters parameters() const;

      // Every key with its documentation, default and current value.
      void print(std::ostream &out) const;

    private:
      struct Entry
      {
        std::string value;
        std::string default_value;
        std::string documentation;
      };
      std::map<std::string, Entry> entries;
      std::vector<std::string>     order;

      void declare(const std::string &key, const std::string &default_value,
                   const std::string &documentation);
      void assign(const std::string &key, const std::string &value, const std::string &where);
    };
  } // namespace four_bar
} // namespace compliant
