// Precision positions generated from a known four-bar by the four-bar library: synthesis must find
// its two dyads again, and forward kinematics must pass the positions (an independent reference).
#pragma once

#include <mechanisms/burmester/dyad_synthesis.h>
#include <mechanisms/four_bar/position_analysis.h>

#include <array>
#include <complex>
#include <vector>

namespace known_linkage
{
  using compliant::burmester::Complex;
  using compliant::burmester::PrecisionPosition;
  namespace fb = compliant::four_bar;

  // Crank-rocker: ground 1.0, crank 0.35, coupler 0.9, rocker 0.8; coupler point 0.5 from B at
  // 30 degrees to BC; A at the origin, D at (1, 0).
  inline const fb::LinkLengths lengths{1.0, 0.35, 0.9, 0.8};
  inline const Complex         offset = std::polar(0.5, 0.5236);
  inline const std::array<double, 4> crank_angles{0.6, 1.1, 1.7, 2.4};

  inline fb::Pose pose(double crank) { return fb::solve_pose(lengths, crank, fb::AssemblyBranch::minus); }

  inline PrecisionPosition position_at(double crank)
  {
    const auto    p = pose(crank);
    const Complex b = std::polar(lengths.crank, crank);
    const Complex r = b + offset * std::polar(1.0, p.coupler_angle);
    return {r.real(), r.imag(), p.coupler_angle};
  }

  inline std::vector<PrecisionPosition> positions(const std::array<double, 4> &cranks = crank_angles)
  {
    std::vector<PrecisionPosition> result;
    for (const double c : cranks)
      result.push_back(position_at(c));
    return result;
  }
} // namespace known_linkage
