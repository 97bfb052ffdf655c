// Names of the eight joints of the Jansen leg and a per-joint array of planar
// vectors (positions, velocities or accelerations).
#pragma once

#include <mechanisms/jansen/planar_vector.h>

#include <array>
#include <cstddef>

namespace compliant
{
  namespace jansen
  {
    enum class Joint : std::size_t
    {
      A = 0, // crank axle, fixed
      B,     // crank pin
      C,     // ternary CDE, joint with BC
      D,     // ternary CDE, joint with DF
      E,     // fixed pivot, origin of the frame
      F,     // ternary FGH, joint with DF
      G,     // ternary FGH, joint with BG and EG
      H      // foot
    };

    constexpr std::size_t n_joints = 8;

    constexpr std::array<Joint, n_joints> all_joints = {
      Joint::A, Joint::B, Joint::C, Joint::D, Joint::E, Joint::F, Joint::G, Joint::H};

    inline const char *joint_name(const Joint joint)
    {
      constexpr std::array<const char *, n_joints> names = {"A", "B", "C", "D", "E", "F", "G", "H"};
      return names[static_cast<std::size_t>(joint)];
    }

    struct JointVectors
    {
      std::array<PlanarVector, n_joints> values{};

      PlanarVector &operator[](const Joint joint)
      {
        return values[static_cast<std::size_t>(joint)];
      }

      const PlanarVector &operator[](const Joint joint) const
      {
        return values[static_cast<std::size_t>(joint)];
      }
    };
  } // namespace jansen
} // namespace compliant
