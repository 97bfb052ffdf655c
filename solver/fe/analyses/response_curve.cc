#include "analyses/response_curve.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace compliant
{
  ResponseCurve::ResponseCurve(std::string file, const bool root)
    : file(std::move(file))
    , root(root)
  {}

  void ResponseCurve::add(const unsigned int step, const double load_factor, const unsigned int newton_iterations,
                          const std::vector<std::pair<std::string, double>> &path_columns,
                          const std::map<std::string, double>                &quantities)
  {
    if (!root)
      return;
    if (!started)
      {
        text = "step,load_factor,newton_iterations";
        for (const auto &[name, value] : path_columns)
          text += "," + name;
        for (const auto &[name, value] : quantities)
          if (name.rfind("time_", 0) != 0)
            {
              columns.push_back(name);
              text += "," + name;
            }
        text += "\n";
        started = true;
      }
    std::ostringstream line;
    line << step << "," << std::setprecision(12) << load_factor << "," << newton_iterations;
    for (const auto &[name, value] : path_columns)
      line << "," << value;
    for (const auto &name : columns)
      {
        const auto it = quantities.find(name);
        line << "," << (it != quantities.end() ? it->second : 0.);
      }
    text += line.str() + "\n";
    write();
  }

  void ResponseCurve::finish()
  {
    if (root && !started)
      {
        text = "step,load_factor,newton_iterations\n";
        write();
      }
  }

  void ResponseCurve::write() const
  {
    std::ofstream(file + ".tmp") << text;
    std::filesystem::rename(file + ".tmp", file);
  }
} // namespace compliant
