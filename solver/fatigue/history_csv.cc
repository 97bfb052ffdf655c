#include <fatigue/history_csv.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace fatigue
{
  namespace
  {
    std::string
    trim(const std::string &text)
    {
      const char *blanks = " \t\r\n";
      const auto  begin  = text.find_first_not_of(blanks);
      if (begin == std::string::npos)
        return "";
      const auto end = text.find_last_not_of(blanks);
      return text.substr(begin, end - begin + 1);
    }

    std::vector<std::string>
    split_fields(const std::string &line)
    {
      std::vector<std::string> fields;
      std::size_t              start = 0;
      while (true)
        {
          const std::size_t comma = line.find(',', start);
          fields.push_back(trim(line.substr(start, comma - start)));
          if (comma == std::string::npos)
            return fields;
          start = comma + 1;
        }
    }

    std::string
    unquote(const std::string &name)
    {
      if (name.size() >= 2 && name.front() == '"' && name.back() == '"')
        return trim(name.substr(1, name.size() - 2));
      return name;
    }

    [[noreturn]] void
    fail(const std::string &source, const std::size_t line, const std::string &what)
    {
      throw std::invalid_argument("file '" + source + "', line " + std::to_string(line) + ": " +
                                  what);
    }

    bool
    parse_number(const std::string &text, double &value)
    {
      if (text.empty())
        return false;
      char *end = nullptr;
      errno     = 0;
      value     = std::strtod(text.c_str(), &end);
      return errno == 0 && end == text.c_str() + text.size() && std::isfinite(value);
    }
  } // namespace

  HistoryTable
  read_history_csv(const std::string &path)
  {
    std::ifstream file(path);
    if (!file)
      throw std::invalid_argument("file '" + path +
                                  "': cannot be opened for reading (expected a CSV file with a "
                                  "header 'time,<hot spot 1>,<hot spot 2>,...')");
    return parse_history_csv(file, path);
  }

  HistoryTable
  parse_history_csv(std::istream &input, const std::string &source_name)
  {
    HistoryTable table;
    table.source = source_name;

    std::vector<std::string> names;
    std::string              line;
    std::size_t              line_number = 0, header_line = 0;
    while (std::getline(input, line))
      {
        ++line_number;
        const std::string content = trim(line);
        if (content.empty() || content.front() == '#')
          continue;
        const std::vector<std::string> fields = split_fields(content);

        if (names.empty()) // the header
          {
            header_line = line_number;
            std::set<std::string> seen;
            for (std::size_t c = 0; c < fields.size(); ++c)
              {
                const std::string name = unquote(fields[c]);
                double            number;
                if (name.empty())
                  fail(source_name, line_number,
                       "column " + std::to_string(c + 1) +
                           " of the header has no name (expected a header "
                           "'time,<hot spot 1>,<hot spot 2>,...')");
                if (parse_number(name, number))
                  fail(source_name, line_number,
                       "the header is missing: first line holds the number '" + name +
                           "' (expected column names 'time,<hot spot 1>,...')");
                if (!seen.insert(name).second)
                  fail(source_name, line_number,
                       "column name '" + name + "' appears twice (expected unique hot-spot names)");
                names.push_back(name);
              }
            if (names.size() < 2)
              fail(source_name, line_number,
                   "the header has " + std::to_string(names.size()) +
                       " column (expected a time/step column and at least one hot-spot column)");
            table.step_column = names[0];
            for (std::size_t c = 1; c < names.size(); ++c)
              table.hot_spots.push_back({names[c], {}});
            continue;
          }

        if (fields.size() != names.size())
          fail(source_name, line_number,
               "found " + std::to_string(fields.size()) + " values (expected " +
                   std::to_string(names.size()) + ", one per header column)");
        for (std::size_t c = 0; c < fields.size(); ++c)
          {
            double value;
            if (!parse_number(fields[c], value))
              fail(source_name, line_number,
                   "column '" + names[c] + "': '" + fields[c] + "' is not a finite number");
            if (c == 0)
              {
                if (!table.steps.empty() && !(value > table.steps.back()))
                  fail(source_name, line_number,
                       "column '" + names[0] + "': " + fields[c] +
                           " does not increase (expected strictly increasing time/step values)");
                table.steps.push_back(value);
              }
            else
              table.hot_spots[c - 1].values.push_back(value);
          }
      }

    if (names.empty())
      throw std::invalid_argument("file '" + source_name +
                                  "': no header found (expected a header "
                                  "'time,<hot spot 1>,<hot spot 2>,...' and data rows)");
    if (table.steps.size() < 2)
      fail(source_name, header_line,
           "found " + std::to_string(table.steps.size()) +
               " data row(s) below the header (expected at least 2 samples of the duty cycle)");
    return table;
  }

  HistoryTable
  select_columns(const HistoryTable &table, const std::vector<std::string> &names)
  {
    HistoryTable result = table;
    result.hot_spots.clear();
    for (const std::string &name : names)
      {
        bool found = false;
        for (const HotSpotHistory &h : table.hot_spots)
          if (h.name == name)
            {
              result.hot_spots.push_back(h);
              found = true;
              break;
            }
        if (!found)
          {
            std::string available;
            for (const HotSpotHistory &h : table.hot_spots)
              available += (available.empty() ? "'" : ", '") + h.name + "'";
            throw std::invalid_argument("file '" + table.source + "': column '" + name +
                                        "' not found (expected one of the hot-spot columns " +
                                        available + ")");
          }
      }
    return result;
  }
} // namespace fatigue
