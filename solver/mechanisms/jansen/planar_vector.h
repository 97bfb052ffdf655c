// A point or free vector in the plane of the mechanism, with the two unit
// vectors of planar loop-closure kinematics:
//   mu(theta)    = ( cos theta, sin theta)   direction of a link,
//   sigma(theta) = (-sin theta, cos theta)   d mu / d theta (mu turned +90 deg),
// the notation of the seed paper (Kartal & Kavlak, eqs. 1-8) and of
// E. Soylemez, Makine Teorisi-I Mekanizma Teknigi, Birsen, 2010.
#pragma once

#include <cmath>

namespace compliant
{
  namespace jansen
  {
    struct PlanarVector
    {
      double x = 0.;
      double y = 0.;
    };

    inline PlanarVector operator+(const PlanarVector &a, const PlanarVector &b)
    {
      return {a.x + b.x, a.y + b.y};
    }

    inline PlanarVector operator-(const PlanarVector &a, const PlanarVector &b)
    {
      return {a.x - b.x, a.y - b.y};
    }

    inline PlanarVector operator-(const PlanarVector &a)
    {
      return {-a.x, -a.y};
    }

    inline PlanarVector operator*(const double s, const PlanarVector &a)
    {
      return {s * a.x, s * a.y};
    }

    inline double dot(const PlanarVector &a, const PlanarVector &b)
    {
      return a.x * b.x + a.y * b.y;
    }

    // z-component of the 3D cross product: > 0 when b lies counter-clockwise of a.
    inline double cross(const PlanarVector &a, const PlanarVector &b)
    {
      return a.x * b.y - a.y * b.x;
    }

    inline double norm(const PlanarVector &a)
    {
      return std::hypot(a.x, a.y);
    }

    inline PlanarVector unit_vector(const double theta)
    {
      return {std::cos(theta), std::sin(theta)};
    }

    inline PlanarVector normal_vector(const double theta)
    {
      return {-std::sin(theta), std::cos(theta)};
    }

    // Angle of a vector from the +x axis, counter-clockwise, in [0, 2 pi).
    inline double direction_angle(const PlanarVector &a)
    {
      const double two_pi = 2. * M_PI;
      const double angle  = std::atan2(a.y, a.x);
      return angle < 0. ? angle + two_pi : angle;
    }
  } // namespace jansen
} // namespace compliant
