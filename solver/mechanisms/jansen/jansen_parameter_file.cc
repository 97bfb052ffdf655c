#include <mechanisms/jansen/jansen_parameter_file.h>
#include <text/text_utilities.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace compliant
{
  namespace jansen
  {
    namespace
    {
      std::string trimmed(const std::string &s) { return text::trim(s); }

      double *field(JansenLinkLengths &l, const std::string &key, double &theta1_degrees)
      {
        const std::map<std::string, double *> fields = {
          {"EA", &l.ea}, {"AB", &l.ab}, {"BC", &l.bc}, {"BG", &l.bg}, {"CE", &l.ce},
          {"DE", &l.de}, {"CD", &l.cd}, {"EG", &l.eg}, {"DF", &l.df}, {"FG", &l.fg},
          {"GH", &l.gh}, {"FH", &l.fh}, {"theta1", &theta1_degrees}};
        const auto it = fields.find(key);
        return it == fields.end() ? nullptr : it->second;
      }
    } // namespace

    JansenLinkLengths read_link_lengths(std::istream &in, const std::string &source_name)
    {
      JansenLinkLengths                 lengths;
      double                            theta1_degrees = 0.;
      std::map<std::string, unsigned>   seen;
      std::string                       line;
      unsigned int                      line_number = 0;
      const auto error = [&](const std::string &what) {
        return std::invalid_argument(source_name + ":" + std::to_string(line_number) + ": " +
                                     what);
      };

      while (std::getline(in, line))
        {
          ++line_number;
          const std::string text = trimmed(line.substr(0, line.find('#')));
          if (text.empty())
            continue;
          if (text.rfind("set ", 0) != 0 || text.find('=') == std::string::npos)
            throw error("expected 'set <name> = <value>', got '" + text + "'");
          const auto        equals = text.find('=');
          const std::string key    = trimmed(text.substr(4, equals - 4));
          const std::string value  = trimmed(text.substr(equals + 1));
          double           *target = field(lengths, key, theta1_degrees);
          if (target == nullptr)
            throw error("unknown parameter '" + key +
                        "' (expected one of EA AB BC BG CE DE CD EG DF FG GH FH theta1)");
          if (seen.count(key) != 0)
            throw error("parameter '" + key + "' repeated (first set on line " +
                        std::to_string(seen[key]) + ")");
          std::size_t used = 0;
          try
            {
              *target = std::stod(value, &used);
            }
          catch (const std::exception &)
            {
              used = 0;
            }
          if (used == 0 || used != value.size() || !std::isfinite(*target))
            throw error("value of '" + key + "' must be a number, got '" + value + "'");
          seen[key] = line_number;
        }

      for (const char *key :
           {"EA", "AB", "BC", "BG", "CE", "DE", "CD", "EG", "DF", "FG", "GH", "FH", "theta1"})
        if (seen.count(key) == 0)
          throw std::invalid_argument(source_name + ": parameter '" + key + "' is missing");
      lengths.ground_angle = theta1_degrees * M_PI / 180.;
      try
        {
          validate(lengths);
        }
      catch (const std::invalid_argument &e)
        {
          throw std::invalid_argument(source_name + ": " + e.what());
        }
      return lengths;
    }

    JansenLinkLengths read_link_lengths_file(const std::string &file_name)
    {
      std::ifstream in(file_name);
      if (!in)
        throw std::invalid_argument("read_link_lengths_file: cannot open '" + file_name + "'");
      return read_link_lengths(in, file_name);
    }
  } // namespace jansen
} // namespace compliant
