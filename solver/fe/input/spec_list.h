// Parser for the small list grammar used by case-file entries such as
//   "right: angle=0.01, center=100 5 0; left"
// item  := name [':' field (',' field)*]      items separated by ';'
// field := key '=' value | value              value: words or numbers separated by spaces
#pragma once

#include <map>
#include <string>
#include <vector>

namespace compliant
{
  struct SpecField
  {
    std::string key;   // empty for a positional field
    std::string value; // raw text, trimmed
  };

  struct SpecItem
  {
    std::string            name;
    std::vector<SpecField> fields;

    // Value of a keyed field, or an empty string.
    std::string get(const std::string &key) const;
    bool        has(const std::string &key) const;
  };

  // Splits an entry into items; throws std::invalid_argument naming `where` on malformed text.
  std::vector<SpecItem> parse_spec_list(const std::string &text, const std::string &where);

  // Parses "1 2 3" (spaces or commas) into numbers; throws naming `where` if a token is not a number.
  std::vector<double> parse_numbers(const std::string &text, const std::string &where);

  std::string trim(const std::string &s);
  // Shortest text that reads back as the same double.
  std::string round_trip_text(double value);
  std::vector<std::string> split(const std::string &s, char separator);
} // namespace compliant
