// Grashof classification of a four-bar from its link lengths
// (Grashof 1883; classes as in Norton, Design of Machinery, 5th ed., sec. 2.12, and
// Barker's classification, Mech. Mach. Theory 20(6), 1985).
#pragma once

#include <mechanisms/four_bar/link_lengths.h>

#include <string>

namespace compliant
{
  namespace four_bar
  {
    // s, l: shortest and longest link; p, q: the other two.
    enum class GrashofClass
    {
      crank_rocker,  // s + l < p + q, shortest link is the crank (input fully rotates)
      rocker_crank,  // s + l < p + q, shortest link is the rocker (output fully rotates)
      double_crank,  // s + l < p + q, shortest link is the ground (drag link)
      double_rocker, // s + l < p + q, shortest link is the coupler (Grashof double rocker)
      change_point,  // s + l = p + q: links can become collinear; the branch may switch
      triple_rocker  // s + l > p + q: non-Grashof, no link turns fully relative to another
    };

    struct GrashofAnalysis
    {
      GrashofClass class_;
      // s + l - (p + q): negative Grashof, zero change point, positive non-Grashof.
      double condition;
      // For a change-point linkage, the class it would have with s + l slightly below
      // p + q (which link turns fully); equal to class_ otherwise.
      GrashofClass grashof_limit_class;
      // Whether the crank (resp. rocker) can turn through 360 degrees relative to ground.
      bool crank_fully_rotates;
      bool rocker_fully_rotates;
    };

    // relative_tolerance: |s + l - p - q| below this times the longest link counts as equality.
    GrashofAnalysis classify_grashof(const LinkLengths &lengths, double relative_tolerance = 1e-9);

    std::string to_string(GrashofClass grashof_class);
  } // namespace four_bar
} // namespace compliant
