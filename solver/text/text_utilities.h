// The one home of the small text helpers every input reader needs (case files, parameter files,
// Abaqus meshes, command lines): plain C++, header-only, below everything else.
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace compliant::text
{
  // s without leading and trailing blanks (space, tab, carriage return, newline).
  inline std::string trim(const std::string &s)
  {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string::npos)
      return "";
    const auto last = s.find_last_not_of(" \t\r\n");
    return s.substr(first, last - first + 1);
  }

  // The fields between separators, as written (a trailing separator gives a last empty field;
  // the empty text gives none).
  inline std::vector<std::string> split(const std::string &s, const char separator)
  {
    std::vector<std::string> parts;
    std::string              part;
    std::istringstream       stream(s);
    while (std::getline(stream, part, separator))
      parts.push_back(part);
    if (!s.empty() && s.back() == separator)
      parts.push_back("");
    return parts;
  }

  // The same, each field trimmed.
  inline std::vector<std::string> split_trimmed(const std::string &s, const char separator)
  {
    auto parts = split(s, separator);
    for (auto &p : parts)
      p = trim(p);
    return parts;
  }
} // namespace compliant::text
