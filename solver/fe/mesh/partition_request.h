// What 'Discretization/Mesh partition' asks for, parsed once from the case file (light: no
// deal.II, so the typed case parameters can hold it).
#pragma once

#include <string>

namespace compliant
{
  // What 'Discretization/Mesh partition' asks for: a partition, or 'auto' (the run decides).
  enum class PartitionRequest
  {
    automatic,
    shared,
    distributed
  };
  // "auto", "shared" or "distributed"; std::invalid_argument for anything else.
  PartitionRequest partition_request_from_string(const std::string &text);

} // namespace compliant
