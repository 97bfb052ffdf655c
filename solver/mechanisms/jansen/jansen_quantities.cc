#include <mechanisms/jansen/jansen_quantities.h>

#include <cmath>

namespace compliant
{
  namespace jansen
  {
    namespace
    {
      constexpr std::array<const char *, n_quantities> labels = {
        "theta2 (crank)", "theta3", "theta4", "theta5", "theta5'", "theta6", "theta7",
        "theta8", "theta8'", "omega3", "omega4", "omega5 (= omega5')", "omega6", "omega7",
        "omega8 (= omega8')", "V_Hx", "V_Hy", "|V_H|", "alpha3", "alpha4",
        "alpha5 (= alpha5')", "alpha6", "alpha7", "alpha8 (= alpha8')", "a_Hx", "a_Hy",
        "|a_H|"};

      double degrees(const double radians)
      {
        const double d = radians * 180. / M_PI;
        return d - 360. * std::floor(d / 360.);
      }

      void fill_angles(const LinkAngles &a, QuantityValues &q)
      {
        q[0] = degrees(a.theta2);
        q[1] = degrees(a.theta3);
        q[2] = degrees(a.theta4);
        q[3] = degrees(a.theta5);
        q[4] = degrees(a.theta5p);
        q[5] = degrees(a.theta6);
        q[6] = degrees(a.theta7);
        q[7] = degrees(a.theta8);
        q[8] = degrees(a.theta8p);
      }

      void fill_rates(const LinkRates &w,
                      const LinkRates &al,
                      const PlanarVector &v,
                      const PlanarVector &acc,
                      QuantityValues &q)
      {
        const std::array<double, 6> omega = {w.link3, w.link4, w.link5, w.link6, w.link7, w.link8};
        const std::array<double, 6> alpha = {al.link3, al.link4, al.link5, al.link6, al.link7, al.link8};
        for (std::size_t k = 0; k < 6; ++k)
          {
            q[static_cast<std::size_t>(Quantity::omega3) + k] = omega[k];
            q[static_cast<std::size_t>(Quantity::alpha3) + k] = alpha[k];
          }
        q[static_cast<std::size_t>(Quantity::foot_velocity_x)]             = v.x;
        q[static_cast<std::size_t>(Quantity::foot_velocity_y)]             = v.y;
        q[static_cast<std::size_t>(Quantity::foot_speed)]                  = norm(v);
        q[static_cast<std::size_t>(Quantity::foot_acceleration_x)]         = acc.x;
        q[static_cast<std::size_t>(Quantity::foot_acceleration_y)]         = acc.y;
        q[static_cast<std::size_t>(Quantity::foot_acceleration_magnitude)] = norm(acc);
      }
    } // namespace

    std::string quantity_label(const Quantity quantity)
    {
      return labels[static_cast<std::size_t>(quantity)];
    }

    bool is_angle(const Quantity quantity)
    {
      return static_cast<std::size_t>(quantity) <= static_cast<std::size_t>(Quantity::theta8p);
    }

    std::string quantity_unit(const Quantity quantity)
    {
      const auto q = static_cast<std::size_t>(quantity);
      if (is_angle(quantity))
        return "deg";
      if (q <= static_cast<std::size_t>(Quantity::omega8))
        return "rad/s";
      if (q <= static_cast<std::size_t>(Quantity::foot_speed))
        return "mm/s";
      if (q <= static_cast<std::size_t>(Quantity::alpha8))
        return "rad/s^2";
      return "mm/s^2";
    }

    QuantityValues tabulate(const LinkAngles &angles, const JansenMotion &motion)
    {
      QuantityValues q{};
      fill_angles(angles, q);
      fill_rates(motion.angular_velocities,
                 motion.angular_accelerations,
                 motion.velocities[Joint::H],
                 motion.accelerations[Joint::H],
                 q);
      return q;
    }

    QuantityValues tabulate(const LinkAngles &angles, const FiniteDifferenceMotion &motion)
    {
      QuantityValues q{};
      fill_angles(angles, q);
      fill_rates(motion.angular_velocities,
                 motion.angular_accelerations,
                 motion.foot_velocity,
                 motion.foot_acceleration,
                 q);
      return q;
    }
  } // namespace jansen
} // namespace compliant
