#include <mechanisms/four_bar/prbm_springs.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace compliant
{
  namespace four_bar
  {
    namespace
    {
      void require_positive(const char *name, const double value)
      {
        if (!(std::isfinite(value) && value > 0.))
          throw std::invalid_argument(std::string("four_bar: ") + name +
                                      " must be positive and finite, got " + std::to_string(value));
      }
    } // namespace

    double flexural_pivot_stiffness(const double youngs_modulus, const double width,
                                    const double thickness, const double flexure_length)
    {
      require_positive("Young's modulus E", youngs_modulus);
      require_positive("flexure width b", width);
      require_positive("flexure thickness h", thickness);
      require_positive("flexure length l_k", flexure_length);
      const double second_moment = width * thickness * thickness * thickness / 12.;
      return youngs_modulus * second_moment / flexure_length;
    }

    std::array<double, 4> flexure_rotations(const PrbmSprings &springs, const Pose &pose)
    {
      const double d2 = pose.crank_angle - springs.rest.crank_angle;
      const double d3 = pose.coupler_angle - springs.rest.coupler_angle;
      const double d4 = pose.rocker_angle - springs.rest.rocker_angle;
      return {d2, d3 - d2, d4 - d3, d4};
    }

    std::array<double, 4> spring_moments(const PrbmSprings &springs, const Pose &pose)
    {
      const auto            rotation = flexure_rotations(springs, pose);
      std::array<double, 4> moments;
      for (unsigned int i = 0; i < 4; ++i)
        moments[i] = -springs.stiffness[i] * rotation[i]; // Eq. 5-8
      return moments;
    }

    double spring_energy(const PrbmSprings &springs, const Pose &pose)
    {
      const auto rotation = flexure_rotations(springs, pose);
      double     energy   = 0.;
      for (unsigned int i = 0; i < 4; ++i)
        energy += 0.5 * springs.stiffness[i] * rotation[i] * rotation[i];
      return energy;
    }

    double input_torque_virtual_work(const PrbmSprings &springs, const Pose &pose,
                                     const DerivativeCoefficients &h)
    {
      const auto  r = flexure_rotations(springs, pose);
      const auto &K = springs.stiffness;
      // Eq. 12: the rate of each flexure rotation with th2 multiplies its spring moment.
      return K[0] * r[0] + K[1] * r[1] * (h.coupler_velocity - 1.) +
             K[2] * r[2] * (h.rocker_velocity - h.coupler_velocity) +
             K[3] * r[3] * h.rocker_velocity;
    }
  } // namespace four_bar
} // namespace compliant
