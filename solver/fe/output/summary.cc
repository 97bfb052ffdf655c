#include "output/summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace compliant
{
  namespace
  {
    std::string quoted(const std::string &s)
    {
      std::string out = "\"";
      for (char c : s)
        {
          if (c == '"' || c == '\\')
            out += '\\';
          if (c == '\n')
            {
              out += "\\n";
              continue;
            }
          out += c;
        }
      return out + "\"";
    }

    std::string number(double v)
    {
      if (!std::isfinite(v))
        return "null";
      std::ostringstream s;
      s << std::setprecision(12) << v;
      return s.str();
    }

    template <typename Map, typename Format>
    std::string object(const Map &map, Format format, const std::string &indent)
    {
      std::string out = "{";
      bool        first = true;
      for (const auto &[k, v] : map)
        {
          out += (first ? "\n" : ",\n") + indent + "  " + quoted(k) + ": " + format(v);
          first = false;
        }
      return out + (first ? "}" : "\n" + indent + "}");
    }
  } // namespace

  std::string to_json(const RunSummary &s)
  {
    std::ostringstream out;
    out << "{\n  \"case\": " << quoted(s.case_file) << ",\n";
    out << "  \"settings\": " << object(s.settings, quoted, "  ") << ",\n";
    out << "  \"parameters\": " << object(s.parameters, number, "  ") << ",\n";
    out << "  \"quantities\": " << object(s.quantities, number, "  ") << ",\n";
    out << "  \"comparisons\": [";
    for (unsigned int i = 0; i < s.comparisons.size(); ++i)
      {
        const auto &c = s.comparisons[i];
        out << (i ? ",\n" : "\n") << "    {\"quantity\": " << quoted(c.quantity)
            << ", \"closed_form\": " << quoted(c.formula) << ", \"computed\": " << number(c.computed)
            << ", \"reference\": " << number(c.reference)
            << ", \"relative_difference\": " << number(c.relative_difference) << ", \"warnings\": [";
        for (unsigned int w = 0; w < c.warnings.size(); ++w)
          out << (w ? ", " : "") << quoted(c.warnings[w]);
        out << "]}";
      }
    out << (s.comparisons.empty() ? "]\n" : "\n  ]\n") << "}\n";
    return out.str();
  }

  void write_summary(const RunSummary &summary, const std::string &file)
  {
    const std::string partial = file + ".partial";
    {
      std::ofstream out(partial);
      out << to_json(summary);
      if (!out)
        throw std::runtime_error("cannot write summary '" + partial + "'");
    }
    if (std::rename(partial.c_str(), file.c_str()) != 0)
      throw std::runtime_error("cannot rename '" + partial + "' to '" + file + "'");
  }

  std::string format_table(const RunSummary &s)
  {
    std::ostringstream out;
    out << "Quantities of interest\n";
    std::size_t width = 44; // one column for the values, however long a name
    for (const auto &q : s.quantities)
      width = std::max(width, q.first.size() + 2);
    // An estimate stands beside its quantity (summary.json keeps it under its own name).
    const auto shown_beside = [&](const std::string &k) {
      for (const std::string suffix : {"_error_estimate", "_error_estimate_absolute"})
        if (k.size() > suffix.size() && k.compare(k.size() - suffix.size(), suffix.size(), suffix) == 0 &&
            s.quantities.count(k.substr(0, k.size() - suffix.size())) > 0)
          return true;
      return false;
    };
    for (const auto &[k, v] : s.quantities)
      {
        if (shown_beside(k))
          continue;
        std::ostringstream value;
        value << std::setprecision(8) << v;
        out << "  " << std::left << std::setw(width) << k << value.str();
        const auto e        = s.quantities.find(k + "_error_estimate");
        const auto absolute = s.quantities.find(k + "_error_estimate_absolute");
        if (e != s.quantities.end() || absolute != s.quantities.end())
          {
            // Relative to a value near zero (a reaction in a direction nothing loads) says
            // nothing: the absolute estimate then.
            std::ostringstream estimate;
            estimate << std::setprecision(2);
            if (e != s.quantities.end() && (e->second < 1 || absolute == s.quantities.end()))
              estimate << 100 * e->second << " %";
            else
              estimate << absolute->second << " (absolute)";
            out << std::string(value.str().size() < 16 ? 16 - value.str().size() : 1, ' ') << "error "
                << estimate.str() << " (estimated)";
          }
        out << "\n";
      }
    if (!s.comparisons.empty())
      {
        out << "\nComparison with closed forms\n  " << std::left << std::setw(34) << "quantity"
            << std::setw(44) << "closed form" << std::setw(16) << "FE" << std::setw(16)
            << "closed form" << "rel. diff\n";
        for (const auto &c : s.comparisons)
          {
            out << "  " << std::left << std::setw(34) << c.quantity << std::setw(44) << c.formula
                << std::setw(16) << std::setprecision(8) << c.computed << std::setw(16)
                << c.reference << std::showpos << std::fixed << std::setprecision(3)
                << 100 * c.relative_difference << " %" << std::noshowpos << std::defaultfloat
                << "\n";
            for (const auto &w : c.warnings)
              out << "    WARNING (" << c.formula << "): " << w << "\n";
          }
      }
    return out.str();
  }
} // namespace compliant
