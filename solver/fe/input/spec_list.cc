#include "input/spec_list.h"

#include <text/text_utilities.h>

#include <iomanip>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace compliant
{
  std::string trim(const std::string &s) { return text::trim(s); }

  std::string round_trip_text(const double value)
  {
    for (int digits = 6; digits < 17; ++digits)
      {
        std::ostringstream s;
        s << std::setprecision(digits) << value;
        if (std::stod(s.str()) == value)
          return s.str();
      }
    std::ostringstream s;
    s << std::setprecision(17) << value;
    return s.str();
  }

  std::vector<std::string> split(const std::string &s, char separator)
  {
    std::vector<std::string> parts;
    std::string              current;
    int                      depth = 0; // separators inside parentheses do not split
    for (char c : s)
      {
        if (c == '(')
          ++depth;
        if (c == ')')
          --depth;
        if (c == separator && depth == 0)
          {
            parts.push_back(trim(current));
            current.clear();
          }
        else
          current += c;
      }
    parts.push_back(trim(current));
    return parts;
  }

  std::string SpecItem::get(const std::string &key) const
  {
    for (const auto &f : fields)
      if (f.key == key)
        return f.value;
    return "";
  }

  bool SpecItem::has(const std::string &key) const
  {
    for (const auto &f : fields)
      if (f.key == key)
        return true;
    return false;
  }

  std::vector<SpecItem> parse_spec_list(const std::string &text, const std::string &where)
  {
    std::vector<SpecItem> items;
    if (trim(text).empty())
      return items;
    for (const auto &raw_item : split(text, ';'))
      {
        if (raw_item.empty())
          continue;
        SpecItem   item;
        const auto colon = raw_item.find(':');
        item.name        = trim(raw_item.substr(0, colon));
        if (item.name.empty())
          throw std::invalid_argument(where + ": an item '" + raw_item +
                                      "' has no name before ':'");
        if (colon != std::string::npos)
          for (const auto &raw_field : split(raw_item.substr(colon + 1), ','))
            {
              if (raw_field.empty())
                throw std::invalid_argument(where + ": empty field in item '" + raw_item + "'");
              SpecField  field;
              const auto eq = raw_field.find('=');
              if (eq == std::string::npos)
                field.value = raw_field;
              else
                {
                  field.key   = trim(raw_field.substr(0, eq));
                  field.value = trim(raw_field.substr(eq + 1));
                  if (field.key.empty() || field.value.empty())
                    throw std::invalid_argument(where + ": malformed 'key=value' field '" +
                                                raw_field + "'");
                }
              item.fields.push_back(field);
            }
        items.push_back(item);
      }
    return items;
  }

  std::vector<double> parse_numbers(const std::string &text, const std::string &where)
  {
    std::string cleaned = text;
    for (char &c : cleaned)
      if (c == ',' || c == '(' || c == ')')
        c = ' ';
    std::istringstream  in(cleaned);
    std::vector<double> values;
    std::string         token;
    while (in >> token)
      {
        std::size_t used = 0;
        double      v    = 0;
        try
          {
            v = std::stod(token, &used);
          }
        catch (...)
          {
            used = 0;
          }
        if (used != token.size())
          throw std::invalid_argument(where + ": expected a number, got '" + token + "'");
        if (!std::isfinite(v))
          throw std::invalid_argument(where + ": expected a finite number, got '" + token + "'");
        values.push_back(v);
      }
    return values;
  }
} // namespace compliant
