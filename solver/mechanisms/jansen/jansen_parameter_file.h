// Reads the leg's dimensions from a small text file in the syntax of deal.II
// ParameterHandler files (so it looks like the project's case files), e.g.
//   # the seed paper's leg
//   set EA = 193.96
//   set theta1 = 11.6      # degrees
// Every key EA AB BC BG CE DE CD EG DF FG GH FH theta1 must appear exactly once.
#pragma once

#include <mechanisms/jansen/jansen_link_lengths.h>

#include <istream>
#include <string>

namespace compliant
{
  namespace jansen
  {
    // Throws std::invalid_argument naming the source (file name) and line for
    // a malformed line, an unknown or repeated key, a value that is not a
    // number; naming the key for a missing one; then validate()s the lengths.
    JansenLinkLengths read_link_lengths(std::istream &in, const std::string &source_name);

    JansenLinkLengths read_link_lengths_file(const std::string &file_name);
  } // namespace jansen
} // namespace compliant
