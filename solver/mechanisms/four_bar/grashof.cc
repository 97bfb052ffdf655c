#include <mechanisms/four_bar/grashof.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace compliant
{
  namespace four_bar
  {
    GrashofAnalysis classify_grashof(const LinkLengths &lengths, const double relative_tolerance)
    {
      check_link_lengths(lengths);
      auto sorted = lengths.as_array();
      std::sort(sorted.begin(), sorted.end());
      const double condition = (sorted[0] + sorted[3]) - (sorted[1] + sorted[2]);

      GrashofAnalysis result;
      result.condition       = condition;
      const double tolerance = relative_tolerance * sorted[3];
      if (std::abs(condition) <= tolerance)
        result.class_ = GrashofClass::change_point;
      else if (condition > 0.)
        result.class_ = GrashofClass::triple_rocker;

      // In a Grashof or change-point chain a shortest link turns fully relative to both of its
      // neighbours (Norton sec. 2.12): a grounded link turns fully if it or the ground is a
      // shortest link. Equal shortest links (parallelogram, deltoid) all turn.
      const bool   grashof_or_change_point = condition <= tolerance;
      const double shortest                = sorted[0];
      const auto   is_shortest             = [&](const double length) {
        return length - shortest <= tolerance;
      };
      result.crank_fully_rotates =
        grashof_or_change_point && (is_shortest(lengths.crank) || is_shortest(lengths.ground));
      result.rocker_fully_rotates =
        grashof_or_change_point && (is_shortest(lengths.rocker) || is_shortest(lengths.ground));

      if (!grashof_or_change_point)
        result.grashof_limit_class = GrashofClass::triple_rocker;
      else if (result.crank_fully_rotates && result.rocker_fully_rotates)
        result.grashof_limit_class = GrashofClass::double_crank;
      else if (result.crank_fully_rotates)
        result.grashof_limit_class = GrashofClass::crank_rocker;
      else if (result.rocker_fully_rotates)
        result.grashof_limit_class = GrashofClass::rocker_crank;
      else
        result.grashof_limit_class = GrashofClass::double_rocker; // coupler shortest
      if (condition < -tolerance)
        result.class_ = result.grashof_limit_class;
      return result;
    }

    std::string to_string(const GrashofClass grashof_class)
    {
      switch (grashof_class)
        {
          case GrashofClass::crank_rocker:
            return "crank-rocker";
          case GrashofClass::rocker_crank:
            return "rocker-crank";
          case GrashofClass::double_crank:
            return "double-crank";
          case GrashofClass::double_rocker:
            return "double-rocker";
          case GrashofClass::change_point:
            return "change-point";
          case GrashofClass::triple_rocker:
            return "triple-rocker (non-Grashof)";
        }
      return "unknown";
    }
  } // namespace four_bar
} // namespace compliant
