#include <mechanisms/jansen/dense_linear_solve.h>
#include <mechanisms/jansen/jansen_motion_analysis.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace compliant
{
  namespace jansen
  {
    namespace
    {
      // Unknowns, in this order: omega (or alpha) of links 3, 4, 5, 6, 7, 8.
      // Rows: x and y of loop (1) E-A-B-C-E, loop (2) E-A-B-G-E, loop (3) G-E-D-F-G.
      constexpr std::size_t n_unknowns = 6;

      // Adds a link term r sigma(theta) (the coefficient of its rate) to the
      // two rows of one loop.
      void add_link_column(DenseMatrix<n_unknowns> &jacobian,
                           const std::size_t        loop,
                           const std::size_t        unknown,
                           const double             length,
                           const double             theta)
      {
        const PlanarVector column = length * normal_vector(theta);
        jacobian[2 * loop][unknown] += column.x;
        jacobian[2 * loop + 1][unknown] += column.y;
      }

      void add_to_loop(DenseVector<n_unknowns> &rhs, const std::size_t loop, const PlanarVector &v)
      {
        rhs[2 * loop] += v.x;
        rhs[2 * loop + 1] += v.y;
      }

      // Rate of change of a link vector r mu(theta): r omega sigma(theta).
      PlanarVector link_velocity(const double length, const double theta, const double omega)
      {
        return (length * omega) * normal_vector(theta);
      }

      // Second rate: r (alpha sigma(theta) - omega^2 mu(theta)).
      PlanarVector link_acceleration(const double length,
                                     const double theta,
                                     const double omega,
                                     const double alpha)
      {
        return length * (alpha * normal_vector(theta) - (omega * omega) * unit_vector(theta));
      }

      LinkRates to_link_rates(const DenseVector<n_unknowns> &x)
      {
        return {x[0], x[1], x[2], x[3], x[4], x[5]};
      }
    } // namespace

    JansenMotion solve_motion(const JansenLinkLengths &lengths,
                              const LinkAngles        &angles,
                              const double             omega2,
                              const double             alpha2)
    {
      validate(lengths);
      if (!std::isfinite(omega2) || !std::isfinite(alpha2))
        throw std::invalid_argument("solve_motion: crank speed omega2 and crank acceleration "
                                    "alpha2 must be finite");
      const LinkAngles &a = angles;

      DenseMatrix<n_unknowns> jacobian{};
      add_link_column(jacobian, 0, 0, lengths.bc, a.theta3);  // loop 1: r3 sigma3
      add_link_column(jacobian, 0, 2, lengths.ce, a.theta5);  // loop 1: r5 sigma5
      add_link_column(jacobian, 1, 1, lengths.bg, a.theta4);  // loop 2: r4 sigma4
      add_link_column(jacobian, 1, 3, lengths.eg, a.theta6);  // loop 2: r6 sigma6
      add_link_column(jacobian, 2, 3, lengths.eg, a.theta6);  // loop 3: r6 sigma6
      add_link_column(jacobian, 2, 2, lengths.de, a.theta5p); // loop 3: r5' sigma5'
      add_link_column(jacobian, 2, 4, lengths.df, a.theta7);  // loop 3: r7 sigma7
      add_link_column(jacobian, 2, 5, lengths.fg, a.theta8);  // loop 3: r8 sigma8

      const auto solve = [&](const DenseVector<n_unknowns> &rhs, const char *what) {
        const auto x = solve_dense<n_unknowns>(jacobian, rhs);
        if (!x)
          throw std::invalid_argument(
            std::string("solve_motion: singular loop Jacobian in the ") + what +
            " analysis at crank angle theta2 = " + std::to_string(a.theta2 * 180. / M_PI) +
            " deg (a dead point of the leg)");
        return to_link_rates(*x);
      };

      // Velocity: the crank term moves to the right-hand side.
      const PlanarVector crank_velocity = link_velocity(lengths.ab, a.theta2, omega2);
      DenseVector<n_unknowns> velocity_rhs{};
      add_to_loop(velocity_rhs, 0, -crank_velocity);
      add_to_loop(velocity_rhs, 1, -crank_velocity);

      JansenMotion motion;
      motion.angular_velocities = solve(velocity_rhs, "velocity");
      const LinkRates &w        = motion.angular_velocities;

      // Acceleration: the same Jacobian times alpha; everything that does not
      // multiply an unknown alpha (crank term, centripetal terms) goes right.
      const PlanarVector crank_acceleration =
        link_acceleration(lengths.ab, a.theta2, omega2, alpha2);
      const auto centripetal = [](const double length, const double theta, const double omega) {
        return link_acceleration(length, theta, omega, 0.);
      };
      DenseVector<n_unknowns> acceleration_rhs{};
      add_to_loop(acceleration_rhs,
                  0,
                  -(crank_acceleration + centripetal(lengths.bc, a.theta3, w.link3) +
                    centripetal(lengths.ce, a.theta5, w.link5)));
      add_to_loop(acceleration_rhs,
                  1,
                  -(crank_acceleration + centripetal(lengths.bg, a.theta4, w.link4) +
                    centripetal(lengths.eg, a.theta6, w.link6)));
      add_to_loop(acceleration_rhs,
                  2,
                  -(centripetal(lengths.eg, a.theta6, w.link6) +
                    centripetal(lengths.de, a.theta5p, w.link5) +
                    centripetal(lengths.df, a.theta7, w.link7) +
                    centripetal(lengths.fg, a.theta8, w.link8)));
      motion.angular_accelerations = solve(acceleration_rhs, "acceleration");
      const LinkRates &al          = motion.angular_accelerations;

      // Joint chains from the fixed pivots: B = A + r2, C = B + r3, G = E - r6,
      // D = E + r5', F = D + r7, H = G + r8'.
      JointVectors &v = motion.velocities;
      v[Joint::B]     = crank_velocity;
      v[Joint::C]     = v[Joint::B] + link_velocity(lengths.bc, a.theta3, w.link3);
      v[Joint::G]     = -link_velocity(lengths.eg, a.theta6, w.link6);
      v[Joint::D]     = link_velocity(lengths.de, a.theta5p, w.link5);
      v[Joint::F]     = v[Joint::D] + link_velocity(lengths.df, a.theta7, w.link7);
      v[Joint::H]     = v[Joint::G] + link_velocity(lengths.gh, a.theta8p, w.link8);

      JointVectors &acc = motion.accelerations;
      acc[Joint::B]     = crank_acceleration;
      acc[Joint::C] =
        acc[Joint::B] + link_acceleration(lengths.bc, a.theta3, w.link3, al.link3);
      acc[Joint::G] = -link_acceleration(lengths.eg, a.theta6, w.link6, al.link6);
      acc[Joint::D] = link_acceleration(lengths.de, a.theta5p, w.link5, al.link5);
      acc[Joint::F] =
        acc[Joint::D] + link_acceleration(lengths.df, a.theta7, w.link7, al.link7);
      acc[Joint::H] =
        acc[Joint::G] + link_acceleration(lengths.gh, a.theta8p, w.link8, al.link8);
      return motion;
    }
  } // namespace jansen
} // namespace compliant
