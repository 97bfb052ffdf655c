#include <mechanisms/four_bar/link_lengths.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace compliant
{
  namespace four_bar
  {
    double LinkLengths::longest() const
    {
      const auto all = as_array();
      return *std::max_element(all.begin(), all.end());
    }

    void check_link_lengths(const LinkLengths &lengths)
    {
      const char *names[4] = {"ground length l1", "crank length l2", "coupler length l3",
                              "rocker length l4"};
      const auto  values   = lengths.as_array();
      for (unsigned int i = 0; i < 4; ++i)
        if (!(std::isfinite(values[i]) && values[i] > 0.))
          throw std::invalid_argument(std::string("four_bar: ") + names[i] +
                                      " must be positive and finite, got " +
                                      std::to_string(values[i]));
    }
  } // namespace four_bar
} // namespace compliant
