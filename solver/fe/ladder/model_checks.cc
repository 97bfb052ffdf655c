#include "ladder/model_checks.h"

#include "ladder/percent.h"

#include <cmath>
#include <iomanip>
#include <sstream>

namespace compliant
{
  GeometricVerdict geometric_verdict(const double theta, const double target, const bool allow_finite_strain)
  {
    const double       geometric = theta * theta;
    const bool         needed    = geometric > target;
    std::ostringstream why;
    why << "largest rotation " << std::setprecision(3) << theta * 180 / M_PI
        << " deg: geometric error ~theta^2 = " << percent(geometric) << (needed ? " > " : " <= ") << "target";
    if (needed && !allow_finite_strain)
      why << ": finite strain would be needed, but Target/Allow finite strain = false keeps it linear";
    else
      why << (needed ? ": finite strain needed (its own rungs follow)" : ": linear is enough");
    return {needed && allow_finite_strain, why.str()};
  }

  OutOfPlaneVerdict out_of_plane_verdict(const double bound, const double thickness, const double target,
                                         const bool stand_in, const unsigned int k)
  {
    OutOfPlaneVerdict  verdict;
    std::ostringstream why;
    why << "plane stress against the 3D solid of thickness " << thickness << ": |U_3D - U| <= " << percent(bound)
        << " of U (energy bound; it holds for the strain energy and the stiffness of a single load or drive)";
    if (stand_in)
      why << (bound < target ? " < target: 2D stands for the 3D part while its discretization estimate stays "
                               "below the rest of the target, " + percent(target - bound) :
              bound < 2 * target && k < 2 ?
                               " >= target on this mesh, < 2 x target: the bound tightens on finer meshes; "
                               "one more 2D rung" :
                               " >= target: the 3D part may differ from this 2D model by more than the "
                               "target; climbing the 3D model");
    else
      why << (bound <= target ? " <= target: 2D is enough" :
                                " > target: the 3D part may differ from this 2D model by more than the target; "
                                "model it in 3D (Model = 3d, or name it in Target/Paired model) to meet the "
                                "target against the solid");
    verdict.reason = why.str();
    if (stand_in && bound >= target && (bound >= 2 * target || k >= 2))
      verdict.needs_3d = "out-of-plane bound " + percent(bound) + " >= target";
    else
      verdict.bound_shares_target = stand_in;
    return verdict;
  }
} // namespace compliant
