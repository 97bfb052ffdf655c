#include <mechanisms/jansen/jansen_paper_values.h>

#include <cmath>

namespace compliant
{
  namespace jansen
  {
    PaperKinematics paper_ground_contact_kinematics()
    {
      PaperKinematics paper;
      paper.omega2 = 10.;
      auto set     = [&](const Quantity q, const double value, const int decimals) {
        paper.values[static_cast<std::size_t>(q)] = {value, decimals};
      };
      // Section III.A, angles from the horizontal.
      set(Quantity::theta2, 302.8, 1);
      set(Quantity::theta3, 123.21, 2);
      set(Quantity::theta4, 213.43, 2);
      set(Quantity::theta5, 243.15, 2);
      set(Quantity::theta5p, 149.42, 2);
      set(Quantity::theta6, 81.9, 1);
      set(Quantity::theta7, 267.53, 2);
      set(Quantity::theta8, 326.98, 2);
      set(Quantity::theta8p, 246.01, 2);
      // Section III.B and eqs. (9)-(11).
      set(Quantity::omega3, 2.99, 2);
      set(Quantity::omega4, 2.2, 1);
      set(Quantity::omega5, -0.03, 2);
      set(Quantity::omega6, 5.09, 2);
      set(Quantity::omega7, 5.36, 2);
      set(Quantity::omega8, -0.657, 3);
      set(Quantity::foot_velocity_x, 844.72, 2);
      set(Quantity::foot_velocity_y, -75.7, 1);
      set(Quantity::foot_speed, 848.11, 2);
      // Section III.C and eqs. (16)-(18).
      set(Quantity::alpha3, 12.35, 2);
      set(Quantity::alpha4, 6.4, 1);
      set(Quantity::alpha5, 29.3, 1);
      set(Quantity::alpha6, -13.01, 2);
      set(Quantity::alpha7, -10.42, 2);
      set(Quantity::alpha8, 30.6, 1);
      set(Quantity::foot_acceleration_x, 5081.45, 2);
      set(Quantity::foot_acceleration_y, -75.7, 1);
      set(Quantity::foot_acceleration_magnitude, 5081.47, 2);
      return paper;
    }

    LinkAngles paper_printed_angles()
    {
      const auto       paper  = paper_ground_contact_kinematics();
      const double     degree = M_PI / 180.;
      const auto       angle  = [&](const Quantity q) {
        return paper.values[static_cast<std::size_t>(q)].value * degree;
      };
      LinkAngles a;
      a.theta1  = 11.6 * degree;
      a.theta2  = angle(Quantity::theta2);
      a.theta3  = angle(Quantity::theta3);
      a.theta4  = angle(Quantity::theta4);
      a.theta5  = angle(Quantity::theta5);
      a.theta5p = angle(Quantity::theta5p);
      a.theta6  = angle(Quantity::theta6);
      a.theta7  = angle(Quantity::theta7);
      a.theta8  = angle(Quantity::theta8);
      a.theta8p = angle(Quantity::theta8p);
      return a;
    }
  } // namespace jansen
} // namespace compliant
