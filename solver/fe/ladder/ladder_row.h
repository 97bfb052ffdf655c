#pragma once

#include <string>

namespace compliant
{
  // One rung's line of ladder.csv without its number and cumulative time: the columns before
  // (model ... seconds) and after (values and estimates) them.
  struct LadderRow
  {
    std::string head;
    double      seconds = 0;
    std::string tail;
  };
} // namespace compliant
