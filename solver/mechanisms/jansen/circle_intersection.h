// Intersection of two circles: the position of the free joint of a dyad
// (two links pinned together, their far ends at known points).
#pragma once

#include <mechanisms/jansen/planar_vector.h>

#include <optional>

namespace compliant
{
  namespace jansen
  {
    // Which of the two intersection points to take, seen from the first centre
    // looking towards the second: the assembly branch of the dyad.
    enum class Side
    {
      left  = +1, // counter-clockwise of the directed line first -> second
      right = -1  // clockwise of it
    };

    // Point X with |X - first_centre| = first_radius and
    // |X - second_centre| = second_radius on the requested side; empty if the
    // circles do not meet (dyad cannot be assembled) or the centres coincide.
    // Law of cosines along the centre line, then the offset normal to it.
    std::optional<PlanarVector> intersect_circles(const PlanarVector &first_centre,
                                                  const double        first_radius,
                                                  const PlanarVector &second_centre,
                                                  const double        second_radius,
                                                  const Side          side);
  } // namespace jansen
} // namespace compliant
