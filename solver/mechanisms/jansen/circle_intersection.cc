#include <mechanisms/jansen/circle_intersection.h>

#include <cmath>

namespace compliant
{
  namespace jansen
  {
    std::optional<PlanarVector> intersect_circles(const PlanarVector &first_centre,
                                                  const double        first_radius,
                                                  const PlanarVector &second_centre,
                                                  const double        second_radius,
                                                  const Side          side)
    {
      const PlanarVector centre_line = second_centre - first_centre;
      const double       distance    = norm(centre_line);
      if (distance == 0.)
        return std::nullopt;

      // Foot of the perpendicular from X on the centre line, measured from the
      // first centre (law of cosines), and the half-chord height.
      const double along =
        (first_radius * first_radius - second_radius * second_radius + distance * distance) /
        (2. * distance);
      const double height_squared = first_radius * first_radius - along * along;
      if (height_squared < 0.)
        return std::nullopt;

      const PlanarVector along_unit  = (1. / distance) * centre_line;
      const PlanarVector normal_unit = {-along_unit.y, along_unit.x}; // +90 deg: the left side
      const double       height      = static_cast<int>(side) * std::sqrt(height_squared);
      return first_centre + along * along_unit + height * normal_unit;
    }
  } // namespace jansen
} // namespace compliant
