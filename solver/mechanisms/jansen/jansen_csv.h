// CSV table of a crank turn: foot path, foot velocity and acceleration, link
// angles and rates, and all joint coordinates, one row per crank angle.
#pragma once

#include <mechanisms/jansen/jansen_crank_turn.h>

#include <ostream>
#include <vector>

namespace compliant
{
  namespace jansen
  {
    // Columns: theta2_deg, x_H, y_H, vx_H, vy_H, v_H, ax_H, ay_H, a_H,
    // theta3_deg .. theta8p_deg, omega3 .. omega8, alpha3 .. alpha8,
    // then x_A, y_A, ..., x_H, y_H (the foot columns repeat as joint H).
    // Lengths in mm, time in s, angles in degrees, rates in rad/s and rad/s^2.
    void write_crank_turn_csv(std::ostream &out, const std::vector<JansenState> &states);
  } // namespace jansen
} // namespace compliant
